"""Stress tests of numerical stability over the whole (mu, nu) plane: sweep, honesty of ``error``, round-off.

Studies of the public entry points and of the singular-basis solver behind them ([S75] §2;
``numeric.solutions.solver`` on ``numeric.core.charts``, ``operators``, ``eigenvalue``):

1. ``sweep``: ``flat_punch`` given mu and given c, ``stick_radius``, ``friction_coefficient``,
   ``power_law(2)``, ``largest_stick_radius``, ``slip_limit`` and ``stick_radius_approach``
   over nu in {-0.999, ..., 0.4999, 1/2} (gamma from 0.7499 to 0 (2.2)), mu from 1e-8 to 1e300
   and inf, c from 1e-12 to 1 and next to the largest stick radius c_max(nu) (1 - c = k (1 - c_max),
   k = 10, 1.01, 1, 0.99). Each call's value, ``error``, route, warnings or raised exception
   is recorded, and each value is checked: finite, 0 <= c <= c_max (c = 1 only for mu = inf or
   gamma = 0, as documented), mu >= 0, 1 <= P* <= atanh(gamma)/gamma (B4), c increasing in mu and
   mu, P* increasing in c; the documented exceptions (``NoEigenvalueError`` for c >= c_max,
   ``ValueError`` for a slip limit at gamma = 0) are not findings, anything else is.
   ``power_law_limit``: A and C of the sphere (3.2), (3.4) as mu -> inf, where the approach
   (1 - c) - (1 - c_max) ~ A/(mu gamma) makes successive differences shrink like 1/mu.
2. ``check_honesty``: the returned ``error`` against the true error, |value - reference|/error,
   with three references: the same route at level 4, the independent hp-graded solver
   (``numeric.core.graded_*``, levels 4 and 3 for its own error) where it reaches, and the closed
   form c_max (K'/K = kappa, ``asymptotics.largest_stick_radius``) where mu gamma >= 1e16 (the
   approach A/(mu gamma) < 1e-16 there). The ratio must not exceed 1 and should exceed 0.1.
3. ``plateau_study``: mu (or 1 - c at mu = inf) and P* (2.4) as the degree grows past
   convergence, with the condition numbers of the collocation matrix D(theta) of
   ``numeric.core.operators`` (raw and equilibrated, as ``EquilibratedLU`` factors it);
   ``slip_limit_plateau`` at theta = pi/2 against the closed-form c_max; ``adhesive_plateau``: the
   only discretised c = 1 system (the graded solver's; ``flat_punch(mu=inf)`` is the closed form)
   against the exact P0* = atanh(gamma)/gamma (B4) and p0(0) (4.10).
4. ``system_mpmath_check``: the new level-0 system D(theta) z = b solved in mpmath at 30 digits
   (the same double matrix, so the difference is the round-off of the double solve), with one
   Newton step of the eigenvalue condition G(theta) = l(theta) . z = 0 (phi(c-) = 0, (2.11)) in
   mpmath; ``adhesive_mp_check``: the adhesive closed forms and the graded c = 1 solver against
   (B3), (B4), (4.10) at 30 digits.

Run ``hertz-friction stability [--quick]``: it writes ``derivations/stability.md``
(``numeric.studies.stability_report``); the full run was measured at 443 s of CPU, 7.7 min wall on
the shared 2-core machine (sweep 130 s, honesty 135 s, plateau 35 s, mpmath 142 s), ``--quick`` at
~10 s. The values at c <= 1e-4 depend on the solver's start at the 1e-11 level (round-off, see the
report), so a re-run can change their last digits. Every call runs under an address-space cap of
``MEMORY_CAP`` bytes above the process's current size, so that an entry point that tries to
allocate without bound fails with ``MemoryError`` (recorded as a finding) instead of taking the
machine (``resource.RLIMIT_AS``; no cap where ``resource`` or ``/proc`` is missing).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import time
import warnings
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, replace

import mpmath
import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import LinearOperator, onenormest

from asymptotics.adhesive import central_pressure_adhesive, pressure_adhesive_mp, shear_adhesive_mp
from asymptotics.derivation import rounding_bound
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu

from numeric import (NoEigenvalueError, SolverError, flat_punch, friction_coefficient, largest_stick_radius,
                     power_law, slip_limit, stick_radius, stick_radius_approach)
from numeric.core import table_data
from numeric.core.charts import RESOLUTIONS, Resolution, partner
from numeric.core.eigenvalue import Eigensolution, solve_given_c, solve_given_theta
from numeric.core.fields import SingularField
from numeric.core.graded_collocation import adhesive_system, solve_adhesive
from numeric.core.graded_eigen import solve_mu as graded_solve_mu
from numeric.core.graded_mesh import LEVELS as GRADED_LEVELS
from numeric.core.linear_algebra import EquilibratedLU, equilibrate
from numeric.core.operators import normal_factor
from numeric.core.table import table_available, table_errors
from numeric.solutions.solver import GAP_ADHESIVE, rounding_floor

__all__ = [
    "Grid",
    "SweepPoint",
    "LimitRow",
    "HonestyCheck",
    "PlateauRow",
    "PlateauStudy",
    "MpCheck",
    "MpStudy",
    "StabilityReport",
    "FULL_GRID",
    "QUICK_GRID",
    "EXTRA_RESOLUTIONS",
    "MEMORY_CAP",
    "memory_cap",
    "sweep",
    "power_law_limit",
    "check_honesty",
    "plateau_study",
    "slip_limit_plateau",
    "adhesive_plateau",
    "system_mpmath_check",
    "adhesive_mp_check",
    "run",
]

HALF_PI = 0.5 * math.pi
EPS = float(np.finfo(float).eps)
#: Bytes a single call may add to the process's address space (see the module docstring): five times what
#: the largest call of the study was measured to use (0.4 GB peak resident size of a full run).
MEMORY_CAP = 2 * 2**30
#: Degrees beyond level 4 (degree 18) for the plateau study, with level 4's singular degree.
EXTRA_RESOLUTIONS: tuple[Resolution, ...] = (Resolution(degree=21, singular_degree=3),
                                             Resolution(degree=24, singular_degree=3),
                                             Resolution(degree=28, singular_degree=3))
#: Where the graded solver is a reference: its eigenvalue search stops at mu = 1e4
#: (``numeric.core.graded_eigen.solve_mu``), and below c ~ 1e-3 it needs more layers than level 4 has.
GRADED_MU_MAX = 1e3
GRADED_C_MIN = 1e-3
#: mu gamma above which the approach A/(mu gamma) (A < 0.06, ``stick_radius_approach``) is below
#: the rounding of c: c_max in closed form is then the reference for c.
CLOSED_FORM_MU_GAMMA = 1e16


@dataclass(frozen=True, slots=True)
class Grid:
    """The sweep's inputs: nus; mus; cs; factors k of 1 - c = k (1 - c_max(nu)) added to cs per nu;
    the mus of ``power_law(2)``; the nus and mu gamma values of ``power_law_limit``."""

    nus: tuple[float, ...]
    mus: tuple[float, ...]
    cs: tuple[float, ...]
    gap_factors: tuple[float, ...]
    power_law_mus: tuple[float, ...]
    limit_nus: tuple[float, ...]
    limit_mu_gammas: tuple[float, ...]


#: mu log-spaced from 1e-8 to 1e300, denser where c moves (1e-3 to 1e4), and mu = inf; c from 1e-12 to 1
FULL_GRID = Grid(
    nus=(-0.999, -0.99, -0.9, -0.5, 0.0, 0.3, 0.45, 0.4999, 0.5),
    mus=(1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 100.0, 1e4, 1e8, 1e16, 1e50, 1e100, 1e300,
         math.inf),
    cs=(1e-12, 1e-8, table_data.C_MIN, 1e-4, 1e-3, 1e-2, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95, 0.99, 0.999, 1.0 - 1e-6,
        1.0 - 1e-9, 1.0 - 1e-12, 1.0),
    gap_factors=(10.0, 1.01, 1.0, 0.99),
    power_law_mus=(1e-4, 0.3, 10.0, 1e8, 1e16, 1e300, math.inf),
    limit_nus=(-0.999, -0.5, 0.0, 0.3),
    limit_mu_gammas=(1e2, 1e4, 1e6, 1e8, 1e10, 1e12, 1e14, 1e16),
)
QUICK_GRID = Grid(nus=(0.0, 0.3), mus=(1e-4, 0.3, 1e300, math.inf), cs=(0.5, 1.0), gap_factors=(1.01,),
                  power_law_mus=(0.3,), limit_nus=(0.0,), limit_mu_gammas=(1e2, 1e4, 1e6))


# ----------------------------------------------------------------------------- results
@dataclass(frozen=True, slots=True)
class SweepPoint:
    """One call of the sweep.

    ``function`` names the call ("flat_punch(mu)", "flat_punch(c)", "stick_radius",
    "friction_coefficient", "power_law(2)", "largest_stick_radius", "slip_limit",
    "stick_radius_approach"); ``argument`` is its mu or c (NaN for the functions of nu alone).
    ``c``, ``mu``, ``compliance`` (P*, of the flat punch also for ``power_law``), ``error``,
    ``A``, ``C`` are the returned values (NaN when the call raised or does not return them;
    ``stick_radius_approach`` returns its A in ``A``). ``raised`` is "" or "Type: message";
    ``expected`` says a raised exception is the documented one; ``warned`` lists the warnings;
    ``problems`` the failed checks (empty: admissible); ``seconds`` is CPU time.
    """

    function: str
    nu: float
    gamma: float
    argument: float
    c: float
    mu: float
    compliance: float
    error: float
    A: float
    C: float
    route: str
    raised: str
    expected: bool
    warned: str
    problems: tuple[str, ...]
    seconds: float

    @property
    def admissible(self) -> bool:
        return not self.problems

    @property
    def route_kind(self) -> str:
        """The route's first words, or the exception type."""
        if self.raised:
            return self.raised.split(":")[0] + (" (documented)" if self.expected else "")
        for kind in ("closed form", "asymptotic", "solver level", "adhesive stresses", "limit mu -> inf", "bracketed"):
            if self.route.startswith(kind):
                return kind
        return self.route.split(",")[0] if self.route else "value"


@dataclass(frozen=True, slots=True)
class LimitRow:
    """A and C of ``power_law(2)`` at one mu gamma; ``step_A``, ``step_C``: change from the previous row.

    The approach to mu = inf is ~1/(mu gamma), so each step of 100x in mu gamma must shrink the change
    ~100x; ``settles`` is false where the change grows instead (beyond 1e-12, the rounding of A and
    C): that is lost digits, not physics."""

    nu: float
    mu_gamma: float
    c: float
    A: float
    C: float
    step_A: float
    step_C: float
    settles: bool
    raised: str
    warned: str


@dataclass(frozen=True, slots=True)
class HonestyCheck:
    """|value - reference| against the returned error bound of one quantity at one sweep point.

    ``reference_kind``: "level 4", "graded (levels 4, 3)", "closed form c_max" or "table (level 4)";
    ``reference_error``: the reference's own error estimate; ``at_floor``: the bound is the solver's
    rounding floor (``rounding_floor``: ERROR_FLOOR * max(|value|, P*)), where the true error
    lies below what any level resolves.
    """

    function: str
    nu: float
    argument: float
    reference_kind: str
    quantity: str
    value: float
    reference: float
    bound: float
    reference_error: float
    at_floor: bool

    @property
    def difference(self) -> float:
        return abs(self.value - self.reference)

    @property
    def ratio(self) -> float:
        return self.difference / self.bound if self.bound > 0 else math.inf

    @property
    def resolved(self) -> bool:
        """The reference is ten times more accurate than the bound: the ratio measures the estimate."""
        return self.reference_error <= 0.1 * self.bound

    @property
    def status(self) -> str:
        """"honest" (difference <= bound), "optimistic" (beyond bound + the reference's error), else
        "inconclusive"."""
        if self.difference <= self.bound:
            return "honest"
        return "optimistic" if self.difference > self.bound + self.reference_error else "inconclusive"


@dataclass(frozen=True, slots=True)
class PlateauRow:
    """One resolution: the value (mu, or 1 - c at mu = inf, or p(0) at c = 1) and P* with their errors
    against the reference, the resolution's own estimate |row - partner| (NaN where none), and the
    2-norm condition numbers of the system matrix, raw and equilibrated."""

    label: str
    n_unknowns: int
    value: float
    value_error: float
    compliance: float
    compliance_error: float
    estimate: float
    condition: float
    condition_equilibrated: float


@dataclass(frozen=True, slots=True)
class PlateauStudy:
    """A plateau table: what is solved, which value, and against what."""

    title: str
    quantity: str
    reference: str
    rows: tuple[PlateauRow, ...]


@dataclass(frozen=True, slots=True)
class MpCheck:
    """A double-precision value against a 30-digit mpmath value of the same quantity."""

    label: str
    double: float
    mp: float

    @property
    def difference(self) -> float:
        return abs(self.double - self.mp)

    @property
    def relative(self) -> float:
        return self.difference / abs(self.mp) if self.mp != 0 else self.difference


@dataclass(frozen=True, slots=True)
class MpStudy:
    """mpmath checks at one point; ``condition`` is that of the equilibrated double matrix (NaN if none)."""

    title: str
    n_unknowns: int
    condition: float
    checks: tuple[MpCheck, ...]


@dataclass(frozen=True, slots=True)
class StabilityReport:
    """Everything ``run`` measured."""

    quick: bool
    table: bool  # whether the Chebyshev table was available (stick_radius, friction_coefficient use it)
    points: tuple[SweepPoint, ...]
    limit: tuple[LimitRow, ...]
    honesty: tuple[HonestyCheck, ...]
    skipped: tuple[str, ...]  # honesty references that could not be computed, and why
    plateaus: tuple[PlateauStudy, ...]
    mp: tuple[MpStudy, ...]
    seconds: tuple[tuple[str, float], ...]  # (study, CPU seconds)


# ----------------------------------------------------------------------------- helpers
def _gamma(nu: float) -> float:
    return float(gamma_from_nu(nu))


def _gap_max(gamma: float) -> float:
    """1 - c_max(gamma), closed form (underflows to 0 for gamma < ~0.06)."""
    return float(largest_stick_radius_gap(gamma)) if gamma > 0.0 else 0.0


def _adhesive_compliance(gamma: float) -> float:
    """atanh(gamma)/gamma (B4), correctly rounded: the bound the API's closed form is checked against."""
    if gamma == 0.0:
        return 1.0
    with mpmath.workdps(30):
        return float(mpmath.atanh(gamma) / gamma)  # (B4)


@contextlib.contextmanager
def memory_cap(extra: int = MEMORY_CAP) -> Iterator[None]:
    """Cap the address space at its current size plus ``extra`` bytes (restored afterwards); does nothing
    where ``resource`` or ``/proc/self/statm`` is missing or a tighter cap is already set."""
    try:
        import resource

        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        with open("/proc/self/statm") as f:
            used = int(f.read().split()[0]) * resource.getpagesize()
    except (ImportError, OSError, ValueError):
        yield
        return
    cap = used + extra
    if hard != resource.RLIM_INFINITY:
        cap = min(cap, hard)
    if soft != resource.RLIM_INFINITY and soft <= cap:
        yield
        return
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


@dataclass(frozen=True, slots=True)
class _Outcome:
    value: object
    raised: str
    exception: type | None
    warned: tuple[str, ...]
    runtime_warning: bool
    seconds: float


def _attempt(f: Callable[[], object]) -> _Outcome:
    """Call f under the memory cap, recording its warnings and any exception (a stress test records
    every failure, so every exception is caught)."""
    start = time.process_time()
    value, raised, kind = None, "", None
    with warnings.catch_warnings(record=True) as caught, memory_cap():
        warnings.simplefilter("always")
        try:
            value = f()
        except Exception as exc:  # noqa: BLE001 - recorded, not handled
            raised, kind = f"{type(exc).__name__}: {exc}", type(exc)
    seconds = time.process_time() - start
    seen = tuple(dict.fromkeys(f"{w.category.__name__}: {w.message}" for w in caught))
    runtime = any(issubclass(w.category, RuntimeWarning) for w in caught)
    return _Outcome(value, raised, kind, seen, runtime, seconds)


def _solution_problems(s, gamma: float, given: str, argument: float) -> list[str]:
    """Range checks of a solution's c, mu, P*, error (``given``: "mu", "c" or "" for the slip limit)."""
    out = []
    c, mu, P, err = float(s.c), float(s.mu), float(s.compliance), float(s.error)
    if not (math.isfinite(err) and err >= 0.0):
        out.append(f"error = {err!r} is not a finite non-negative number")
    slack = err if math.isfinite(err) else 0.0
    if not (math.isfinite(c) and 0.0 <= c <= 1.0):
        out.append(f"c = {c!r} is not in [0, 1]")
    else:
        full = c == 1.0 and (math.isinf(mu) or gamma == 0.0)  # documented: adhesive, or no coupling
        c_max = 1.0 - _gap_max(gamma)
        if not full and c > c_max + slack + 4 * EPS:
            out.append(f"c = {c!r} exceeds c_max = {c_max!r} by more than its error")
        if c == 0.0 and mu > 0.0 and gamma > 0.0 and not s.route.startswith("asymptotic"):
            out.append("c = 0 for mu > 0 on a route other than the law's (where c underflows)")
    if given == "mu" and mu != argument:
        out.append(f"returned mu = {mu!r} is not the mu given")
    if given == "c":
        # documented: c within rounding of c_max returns the slip limit, mu = inf, at that level's own c_max
        at_c_max = math.isinf(mu) and "c_max to rounding" in s.route and abs(c - argument) <= slack + 4 * EPS
        if c != argument and not at_c_max:
            out.append(f"returned c = {c!r} is not the c given")
        if math.isnan(mu) or mu < 0.0:
            out.append(f"mu = {mu!r} is not >= 0")
        elif math.isinf(mu) and c < 1.0 and not at_c_max:
            out.append("mu = inf at c < 1 (documented only for the adhesive c = 1 and for c_max to rounding)")
    top = _adhesive_compliance(gamma)
    rounding = rounding_bound(1, 1) * top  # the closed form np.arctanh(gamma)/gamma: one call, one division
    if not (math.isfinite(P) and 1.0 - slack - rounding <= P <= top + slack + rounding):
        out.append(f"P* = {P!r} outside [1, atanh(gamma)/gamma = {top!r}] (B4)")
    return out


def _point(function: str, nu: float, argument: float, outcome: _Outcome, problems: list[str],
           expected: bool = False) -> SweepPoint:
    v = outcome.value
    nan = math.nan
    c = mu = P = err = A = C = nan
    route = ""
    if v is not None:
        if isinstance(v, float | int | np.floating | np.ndarray):
            x = float(np.asarray(v))
            if function in ("stick_radius", "largest_stick_radius"):
                c = x
            elif function == "friction_coefficient":
                mu = x
            else:
                A = x
        else:
            flat = getattr(v, "flat", v)
            c, mu, err = float(flat.c), float(flat.mu), float(flat.error)
            P = float(flat.compliance)
            route = flat.route
            if function.startswith("power_law"):
                A, C = float(v.A), float(v.C)
    if outcome.raised and not expected:
        problems = [f"raised {outcome.raised}"] + problems
    if outcome.runtime_warning:
        problems = problems + ["warned " + "; ".join(outcome.warned)]
    return SweepPoint(function, nu, _gamma(nu), argument, c, mu, P, err, A, C, route, outcome.raised,
                      bool(outcome.raised) and expected, "; ".join(outcome.warned), tuple(problems), outcome.seconds)


def _with_constants(h):
    """Force the power law's A and C (computed on first access) inside the timed, guarded call."""
    _ = h.A, h.C
    return h


def _c_grid(grid: Grid, gamma: float) -> list[float]:
    """grid.cs and 1 - k (1 - c_max) for the gap factors k (those below 1 dropped when they round to 1)."""
    gap_max = _gap_max(gamma)
    near = [1.0 - k * gap_max for k in grid.gap_factors if gap_max > 0.0]
    return sorted({c for c in (*grid.cs, *near) if 0.0 < c <= 1.0})


def _table_c_bound(c: float) -> float:
    errors = table_errors()
    return max(errors.get("c", 0.0) * c, errors.get("gap", 0.0) * (1.0 - c))


# ----------------------------------------------------------------------------- sweep
def sweep(grid: Grid) -> tuple[SweepPoint, ...]:
    """Call every public entry point on ``grid``; record value, error, route, warnings or exception,
    and the failed checks (see the module docstring)."""
    points: list[SweepPoint] = []
    for nu in grid.nus:
        gamma = _gamma(nu)
        c_max = 1.0 - _gap_max(gamma)
        # largest stick radius, the slip limit and its approach
        o = _attempt(lambda nu=nu: largest_stick_radius(nu))
        probs = [] if o.raised else ([] if 0.0 < float(o.value) <= 1.0 and float(o.value) == c_max else
                                     [f"c_max = {float(o.value)!r}: not in (0, 1] or not the closed form {c_max!r}"])
        points.append(_point("largest_stick_radius", nu, math.nan, o, probs))
        o = _attempt(lambda nu=nu: slip_limit(nu))
        expected = o.exception is ValueError and gamma == 0.0  # documented: no slip annulus at gamma = 0
        probs = [] if o.value is None else _solution_problems(o.value, gamma, "", math.nan)
        points.append(_point("slip_limit", nu, math.nan, o, probs, expected))
        o = _attempt(lambda nu=nu: stick_radius_approach(nu))
        probs = [] if o.value is None or (math.isfinite(float(o.value)) and float(o.value) >= 0.0) else \
            [f"A = {float(o.value)!r} is not finite and >= 0"]
        # documented: no approach where the limit's annulus is below what the solver resolves
        thin = o.exception is ValueError and _gap_max(gamma) < GAP_ADHESIVE
        points.append(_point("stick_radius_approach", nu, math.nan, o, probs, thin))
        # given mu
        by_mu = []
        for mu in grid.mus:
            o = _attempt(lambda nu=nu, mu=mu: flat_punch(nu=nu, mu=mu))
            flat = o.value
            probs = [] if flat is None else _solution_problems(flat, gamma, "mu", mu)
            by_mu.append(_point("flat_punch(mu)", nu, mu, o, probs))
            o = _attempt(lambda nu=nu, mu=mu: stick_radius(mu, nu))
            probs = []
            if o.value is not None:
                c = float(o.value)
                tol = (flat.error if flat is not None and math.isfinite(flat.error) else 0.0) + \
                    (_table_c_bound(c) if table_available() else 0.0) + 4 * EPS
                if not (math.isfinite(c) and 0.0 <= c <= 1.0 and (c <= c_max + tol or (c == 1.0 and math.isinf(mu)))):
                    probs.append(f"c = {c!r} not in [0, c_max = {c_max!r}]")
            if (o.value is None) != (flat is None):
                probs.append("flat_punch(mu) and stick_radius disagree on whether this point has a solution")
            points.append(_point("stick_radius", nu, mu, o, probs))
        points += _monotone(by_mu, "c")
        # given c
        by_c = []
        for c in _c_grid(grid, gamma):
            o = _attempt(lambda nu=nu, c=c: flat_punch(nu=nu, c=c))
            flat = o.value
            # documented: c at or above c_max, or any c < 1 at gamma = 0 (no friction coefficient gives a slip annulus)
            expected = o.exception is NoEigenvalueError and (c >= c_max or gamma == 0.0)
            probs = [] if flat is None else _solution_problems(flat, gamma, "c", c)
            by_c.append(_point("flat_punch(c)", nu, c, o, probs, expected))
            o = _attempt(lambda nu=nu, c=c: float(friction_coefficient(c, nu)))
            probs = []
            if o.value is not None:
                mu = float(o.value)
                at_c_max = abs((1.0 - c) - _gap_max(gamma)) <= 4 * EPS  # documented: the slip limit's mu = inf
                if math.isnan(mu) or mu < 0.0 or (math.isinf(mu) and c < 1.0 and not at_c_max):
                    probs.append(f"mu = {mu!r} (must be >= 0, inf only at c = 1 or c_max to rounding)")
            if (o.value is None) != (flat is None):
                probs.append("flat_punch(c) and friction_coefficient disagree on whether this point has a solution")
            points.append(_point("friction_coefficient", nu, c, o,
                                 probs, o.exception is NoEigenvalueError and (c >= c_max or gamma == 0.0)))
        points += _monotone(by_c, "mu")
        for mu in grid.power_law_mus:
            o = _attempt(lambda nu=nu, mu=mu: _with_constants(power_law(2, nu=nu, mu=mu)))
            probs = []
            if o.value is not None:
                h = o.value
                probs = _solution_problems(h.flat, gamma, "mu", mu)
                if not (math.isfinite(h.A) and h.A > 0.0 and math.isfinite(h.C)):
                    probs.append(f"A = {h.A!r}, C = {h.C!r}: A must be finite and positive, C finite")
                if abs(h.compliance - 2.0 * h.flat.compliance / 3.0) > 4 * EPS * h.compliance:  # (3.17)
                    probs.append(f"P* = {h.compliance!r} is not 2/3 of the flat punch's (3.17)")
            points.append(_point("power_law(2)", nu, mu, o, probs))
    return tuple(points)


def _monotone(points: list[SweepPoint], value: str) -> list[SweepPoint]:
    """Add a problem where c (given mu) or mu (given c), or P*, decreases by more than the two errors
    along the sorted argument: c increases with mu, mu and P* with c (§2.1, (B4))."""
    solved = [p for p in points if not p.raised and math.isfinite(getattr(p, value))]
    worse: dict[int, list[str]] = {}
    for a, b in itertools.pairwise(solved):
        slack = (a.error if math.isfinite(a.error) else 0.0) + (b.error if math.isfinite(b.error) else 0.0)
        for name in (value, "compliance"):
            va, vb = getattr(a, name), getattr(b, name)
            if vb < va - slack - 4 * EPS * abs(va):
                label = "P*" if name == "compliance" else name
                worse.setdefault(id(b), []).append(
                    f"{label} = {vb!r} decreases from {va!r} at argument {a.argument!r} (errors {slack:.2g})")
    return [replace(p, problems=p.problems + tuple(worse.get(id(p), ()))) for p in points]


def power_law_limit(nus: Sequence[float], mu_gammas: Sequence[float]) -> tuple[LimitRow, ...]:
    """A and C of ``power_law(2, nu, mu)`` at mu = mu_gamma / gamma, mu_gamma increasing: as mu -> inf
    c -> c_max with (1 - c) - (1 - c_max) ~ A_approach/(mu gamma), so A and C settle like 1/mu."""
    rows = []
    for nu in nus:
        gamma = _gamma(nu)
        previous: tuple[float, float] | None = None
        last_step = (math.inf, math.inf)
        for mg in mu_gammas:
            o = _attempt(lambda nu=nu, mu=mg / gamma: _with_constants(power_law(2, nu=nu, mu=mu)))
            warned = "; ".join(o.warned)
            if o.value is None:
                rows.append(LimitRow(nu, mg, math.nan, math.nan, math.nan, math.nan, math.nan, False, o.raised, warned))
                continue
            h = o.value
            A, C = float(h.A), float(h.C)
            step = (math.nan, math.nan) if previous is None else (A - previous[0], C - previous[1])
            finite = math.isfinite(A) and math.isfinite(C)
            grows = previous is not None and any(abs(s) > abs(t) + 1e-12 or math.isnan(s)
                                                  for s, t in zip(step, last_step))
            rows.append(LimitRow(nu, mg, float(h.c), A, C, *step, finite and not grows, "", warned))
            previous = (A, C)
            if not math.isnan(step[0]):
                last_step = step
    return tuple(rows)


# ----------------------------------------------------------------------------- honesty
def _spread(items: list, limit: int | None) -> list:
    """At most ``limit`` items, evenly spread over the list."""
    if limit is None or len(items) <= limit:
        return items
    if limit <= 0:
        return []
    return [items[i] for i in sorted(set(np.linspace(0, len(items) - 1, limit).round().astype(int)))]


def _floor(p: SweepPoint, bound: float, *values: float) -> bool:
    """Whether ``bound`` is the solver's rounding floor at p (``numeric.solutions.solver.rounding_floor``)."""
    return bound <= rounding_floor(max(abs(v) for v in values)) * (1.0 + 1e-9)


def _level4_checks(p: SweepPoint) -> list[HonestyCheck]:
    given_c = p.function == "flat_punch(c)"
    ref = flat_punch(nu=p.nu, c=p.argument, level=4) if given_c else flat_punch(nu=p.nu, mu=p.argument, level=4)
    name, value, reference = ("mu", p.mu, ref.mu) if given_c else ("c", p.c, ref.c)
    floor = _floor(p, p.error, value, p.compliance)
    return [HonestyCheck(p.function, p.nu, p.argument, "level 4", name, value, reference, p.error, ref.error, floor),
            HonestyCheck(p.function, p.nu, p.argument, "level 4", "P*", p.compliance, ref.compliance, p.error,
                         ref.error, floor)]


def _graded_checks(p: SweepPoint, levels: tuple[int, int]) -> list[HonestyCheck]:
    """Against the graded solver at levels (fine, coarse): given c directly; given mu, the graded
    mu(c) at the returned c converted to c by the slope d mu/dc (and P* by dP*/dc) of the new solver
    at level 0 (a relative slope error e changes the reference c by e |c - c_ref|, negligible)."""
    fine, coarse = (graded_solve_mu(p.c, p.gamma, GRADED_LEVELS[k], mu_guess=p.mu) for k in levels)
    floor = _floor(p, p.error, p.mu if p.function == "flat_punch(c)" else p.c, p.compliance)
    kind = f"graded (levels {levels[0]}, {levels[1]})"
    if p.function == "flat_punch(c)":
        return [HonestyCheck(p.function, p.nu, p.argument, kind, "mu", p.mu, fine.mu, p.error,
                             abs(fine.mu - coarse.mu), floor),
                HonestyCheck(p.function, p.nu, p.argument, kind, "P*", p.compliance, fine.compliance, p.error,
                             abs(fine.compliance - coarse.compliance), floor)]
    h = 1e-3 * min(p.c, 1.0 - p.c - _gap_max(p.gamma))
    lo, hi = (flat_punch(nu=p.nu, c=p.c + s * h, level=0) for s in (-1.0, 1.0))
    dmu, dP = (hi.mu - lo.mu) / (2 * h), (hi.compliance - lo.compliance) / (2 * h)
    c_ref = p.c + (p.mu - fine.mu) / dmu
    c_err = abs(fine.mu - coarse.mu) / dmu
    P_ref = fine.compliance + dP * (c_ref - p.c)
    return [HonestyCheck(p.function, p.nu, p.argument, kind, "c", p.c, c_ref, p.error, c_err, floor),
            HonestyCheck(p.function, p.nu, p.argument, kind, "P*", p.compliance, P_ref, p.error,
                         abs(fine.compliance - coarse.compliance) + abs(dP) * c_err, floor)]


def check_honesty(points: Sequence[SweepPoint], *, max_level4: int | None = None, max_graded: int | None = 24,
                  graded_levels: tuple[int, int] = (4, 3)) -> tuple[tuple[HonestyCheck, ...], tuple[str, ...]]:
    """The returned ``error`` against references at solver-route points of the sweep.

    Level 4 (at most ``max_level4`` points, evenly spread); the graded solver at ``graded_levels``
    (at most ``max_graded`` points where mu <= GRADED_MU_MAX and c >= GRADED_C_MIN); the closed form
    c_max where mu gamma >= CLOSED_FORM_MU_GAMMA and for ``slip_limit``; and, with the table, the
    values of ``stick_radius`` and ``friction_coefficient`` against level 4 with the table's recorded
    error (``table_errors``) as the bound. Returns the checks and the references skipped (why).
    """
    solver = [p for p in points if p.function in ("flat_punch(c)", "flat_punch(mu)") and not p.raised
              and p.route.startswith("solver level") and math.isfinite(p.error)]
    checks: list[HonestyCheck] = []
    skipped: list[str] = []
    level4: dict[tuple[str, float, float], list[HonestyCheck]] = {}
    for p in _spread(solver, max_level4):
        try:
            level4[(p.function, p.nu, p.argument)] = found = _level4_checks(p)
        except (SolverError, NoEigenvalueError, ValueError) as exc:
            skipped.append(f"level 4 at {p.function}, nu = {p.nu}, argument = {p.argument!r}: "
                           f"{type(exc).__name__}: {exc}")
            continue
        checks += found
    reach = [p for p in solver if p.gamma > 0.0 and p.mu <= GRADED_MU_MAX and p.c >= GRADED_C_MIN]
    for p in _spread(reach, max_graded):
        try:
            checks += _graded_checks(p, graded_levels)
        except (SolverError, NoEigenvalueError, ValueError) as exc:
            skipped.append(f"graded at {p.function}, nu = {p.nu}, argument = {p.argument!r}: "
                           f"{type(exc).__name__}: {exc}")
    for p in points:
        if p.raised or not math.isfinite(p.error):
            continue
        limit = p.function == "slip_limit" or (p.function == "flat_punch(mu)" and p.route.startswith("solver level")
                                               and p.mu * p.gamma >= CLOSED_FORM_MU_GAMMA)
        if limit and p.gamma > 0.0:
            c_max = 1.0 - _gap_max(p.gamma)  # the approach A/(mu gamma) < 1e-16 is below c's rounding
            floor = _floor(p, p.error, p.c, p.compliance)
            kind = "closed form c_max (P*: level 4)"
            try:  # the returned error bounds c and P* together: P* against level 4
                ref = slip_limit(p.nu, level=4) if p.function == "slip_limit" else \
                    flat_punch(nu=p.nu, mu=p.argument, level=4)
            except (SolverError, NoEigenvalueError, ValueError) as exc:
                skipped.append(f"level 4 P* at {p.function}, nu = {p.nu}: {type(exc).__name__}: {exc}")
                continue
            checks += [HonestyCheck(p.function, p.nu, p.argument, kind, "c", p.c, c_max, p.error, EPS, floor),
                       HonestyCheck(p.function, p.nu, p.argument, kind, "P*", p.compliance, ref.compliance, p.error,
                                    ref.error, floor)]
    if table_available():
        checks += _table_checks(points, level4)
    return tuple(checks), tuple(skipped)


def _table_checks(points: Sequence[SweepPoint], level4: dict) -> list[HonestyCheck]:
    """stick_radius and friction_coefficient where they differ from flat_punch's level-2 value (that is,
    came from the table) against level 4, bounded by the table's recorded error."""
    errors = table_errors()
    flat = {(p.function, p.nu, p.argument): p for p in points if p.function.startswith("flat_punch")}
    out = []
    for p in points:
        if p.raised or p.function not in ("stick_radius", "friction_coefficient"):
            continue
        twin = flat.get(("flat_punch(mu)" if p.function == "stick_radius" else "flat_punch(c)", p.nu, p.argument))
        if twin is None or (twin.function, twin.nu, twin.argument) not in level4:
            continue
        ref = level4[(twin.function, twin.nu, twin.argument)][0]
        if p.function == "stick_radius":
            if p.c == twin.c:
                continue  # not from the table
            out.append(HonestyCheck(p.function, p.nu, p.argument, "table (level 4)", "c", p.c, ref.reference,
                                    _table_c_bound(p.c), ref.reference_error, False))
        else:
            if p.mu == twin.mu:
                continue
            out.append(HonestyCheck(p.function, p.nu, p.argument, "table (level 4)", "mu", p.mu, ref.reference,
                                    errors.get("mu", 0.0) * p.mu, ref.reference_error, False))
    return out


# ----------------------------------------------------------------------------- plateau
def _conditions(D: np.ndarray, exact_below: int = 2000) -> tuple[float, float]:
    """Condition of D and of ``equilibrate(D)`` (what ``EquilibratedLU`` factors): the 2-norm by SVD
    below ``exact_below`` unknowns, else the 1-norm estimate of Hager-Higham (``onenormest``)."""
    out = []
    for M in (D, equilibrate(D)[0]):
        if M.shape[0] < exact_below:
            out.append(float(np.linalg.cond(M)))
            continue
        lu = sla.lu_factor(M, check_finite=False)
        n = M.shape[0]
        inv = LinearOperator((n, n), matvec=lambda y, lu=lu: sla.lu_solve(lu, y),
                             rmatvec=lambda y, lu=lu: sla.lu_solve(lu, y, trans=1), dtype=float)
        out.append(float(np.linalg.norm(M, 1) * onenormest(inv)))
    return out[0], out[1]


def _resolutions(finest_level: int, extra: bool) -> list[tuple[str, Resolution]]:
    out = [(f"level {k} (degree {RESOLUTIONS[k].degree})", RESOLUTIONS[k]) for k in range(finest_level + 1)]
    if extra:
        out += [(f"degree {r.degree}", r) for r in EXTRA_RESOLUTIONS]
    return out


def _plateau(rows_in: list[tuple[str, SingularField | None, float, float, float, tuple[float, float]]],
             reference_value: float | None) -> tuple[PlateauRow, ...]:
    """Rows against the finest solved row (or ``reference_value`` for the value)."""
    solved = [r for r in rows_in if r[1] is not None]
    finest_value, finest_P = solved[-1][2], solved[-1][3]
    ref = finest_value if reference_value is None else reference_value
    out = []
    for label, field, value, P, estimate, cond in rows_in:
        if field is None:
            out.append(PlateauRow(label, 0, math.nan, math.nan, math.nan, math.nan, math.nan, math.nan, math.nan))
            continue
        out.append(PlateauRow(label, field.n_unknowns, value, abs(value - ref), P, abs(P - finest_P), estimate, *cond))
    return tuple(out)


def plateau_study(nu: float, c: float, *, gap: float | None = None, finest_level: int = 4,
                  extra: bool = True) -> PlateauStudy:
    """mu(c) and P* (2.4) of the new solver at levels 0..``finest_level`` and the ``EXTRA_RESOLUTIONS``;
    errors against the finest; each row's estimate |row - partner| (the solver's error without its
    floor); the condition of D(theta) at the root. ``gap``: 1 - c exactly (next to c_max)."""
    gamma = _gamma(nu)
    gap = 1.0 - c if gap is None else gap
    theta = math.atan(flat_punch(nu=nu, c=c).mu * gamma)  # the guess: the default level's root
    rows = []
    for label, res in _resolutions(finest_level, extra):
        try:
            es = solve_given_c(c, gap, gamma, theta, res)
            coarse = SingularField(solve_given_c(c, gap, gamma, es.theta, partner(res)))
        except (SolverError, NoEigenvalueError) as exc:
            rows.append((f"{label} ({type(exc).__name__})", None, math.nan, math.nan, math.nan, (math.nan, math.nan)))
            continue
        field = SingularField(es)
        estimate = max(abs(field.mu - coarse.mu), abs(field.compliance - coarse.compliance))
        rows.append((label, field, field.mu, field.compliance, estimate, _conditions(es.system.matrix(es.theta))))
    return PlateauStudy(f"mu at nu = {nu}, c = {c!r} (1 - c = {gap:.4g}, gamma = {gamma:.4g})", "mu",
                        "the finest row", _plateau(rows, None))


def slip_limit_plateau(nu: float, *, finest_level: int = 4, extra: bool = True) -> PlateauStudy:
    """The limit problem theta = pi/2 (mu = inf, ``slip_limit``): 1 - c against the closed form
    1 - c_max (K'/K = kappa, ``asymptotics.largest_stick_radius``), P* against the finest row."""
    gamma = _gamma(nu)
    gap_max = _gap_max(gamma)
    start = math.log1p(-gap_max) - math.log(gap_max)
    rows = []
    for label, res in _resolutions(finest_level, extra):
        try:
            es = solve_given_theta(HALF_PI, gamma, start, res)
            field = SingularField(es)
            coarse = SingularField(solve_given_theta(HALF_PI, gamma, math.log(field.c) - math.log(field.gap),
                                                     partner(res)))
        except (SolverError, NoEigenvalueError) as exc:
            rows.append((f"{label} ({type(exc).__name__})", None, math.nan, math.nan, math.nan, (math.nan, math.nan)))
            continue
        estimate = max(abs(field.gap - coarse.gap), abs(field.compliance - coarse.compliance))
        rows.append((label, field, field.gap, field.compliance, estimate, _conditions(es.system.matrix(es.theta))))
    return PlateauStudy(f"1 - c at mu = inf (slip limit), nu = {nu} (gamma = {gamma:.4g})", "1 - c",
                        f"closed form 1 - c_max = {gap_max!r}; P* against the finest row", _plateau(rows, gap_max))


def adhesive_plateau(nu: float, *, finest_level: int = 4) -> PlateauStudy:
    """c = 1 on the graded solver's adhesive mesh (a linear solve): p0(0) against (4.10) and P* against
    (B4), exact; no estimate (the solver has no partner here)."""
    gamma = _gamma(nu)
    with mpmath.workdps(30):
        g = mpmath.mpf(gamma)
        exact_P = float(mpmath.atanh(g) / g)  # (B4)
    exact_p0 = float(central_pressure_adhesive(gamma))  # (4.10)
    rows = []
    for k in range(finest_level + 1):
        field = solve_adhesive(gamma, GRADED_LEVELS[k])
        p0 = float(field.pressure(np.array([0.0]))[0])
        cond = _conditions(adhesive_system(gamma, GRADED_LEVELS[k])[0])
        rows.append(PlateauRow(f"graded level {k}", field.n_unknowns, p0, abs(p0 - exact_p0), field.compliance,
                               abs(field.compliance - exact_P), math.nan, *cond))
    return PlateauStudy(f"p0(0) at c = 1 (adhesive), nu = {nu} (gamma = {gamma:.4g}), graded solver", "p0(0)",
                        f"exact: p0(0) = {exact_p0!r} (4.10), P0* = {exact_P!r} (B4)", tuple(rows))


# ----------------------------------------------------------------------------- mpmath
def _level_solution(nu: float, c: float, gap: float, level: int) -> Eigensolution:
    gamma = _gamma(nu)
    theta = math.atan(flat_punch(nu=nu, c=c, level=level).mu * gamma)
    return solve_given_c(c, gap, gamma, theta, RESOLUTIONS[level])


def system_mpmath_check(nu: float, c: float, *, gap: float | None = None, level: int = 0, dps: int = 30) -> MpStudy:
    """The level-``level`` system D(theta) z = b at the double root theta, solved in mpmath.

    D, b are the double arrays of ``numeric.core.operators.CollocationSystem`` (basis exponent
    alpha of the solver's last outer step); mpmath solves them at ``dps`` digits, so the
    differences are the round-off of the double equilibrated LU solve. One Newton step of
    G(theta) = l(theta) . z(theta) in mpmath, with dz/dtheta = -D^-1 (dD/dtheta) z, gives the root of
    the discrete condition to ~30 digits (the step is ~1e-15, its square negligible); its mu =
    tan(theta)/gamma is compared with the double root.
    """
    gamma = _gamma(nu)
    gap = 1.0 - c if gap is None else gap
    es = _level_solution(nu, c, gap, level)
    system, theta = es.system, es.theta
    field = SingularField(es)
    D, b = system.matrix(theta), system.rhs
    z_double = EquilibratedLU(D).solve_refined(b)  # as the solver solves
    Dp, l, lp = system.matrix_derivative(theta), system.functional(theta), system.functional_derivative(theta)
    ns = system.n_stick
    with mpmath.workdps(dps):
        LU, perm = mpmath.mp.LU_decomp(mpmath.matrix(D.tolist()))  # once: O(n^3) in mpmath

        def solve(rhs):
            return mpmath.mp.U_solve(LU, mpmath.mp.L_solve(LU, rhs.copy(), perm))

        z = solve(mpmath.matrix(b.tolist()))
        dz = solve(-(mpmath.matrix(Dp.tolist()) * z))
        n = b.size
        G = mpmath.fsum(mpmath.mpf(l[i]) * z[i] for i in range(n))
        dG = mpmath.fsum(mpmath.mpf(lp[i]) * z[i] + mpmath.mpf(l[i]) * dz[i] for i in range(n))
        theta_root = mpmath.mpf(theta) - G / dG
        mu_root = float(mpmath.tan(theta_root) / mpmath.mpf(gamma))
        scale = mpmath.fsum(abs(mpmath.mpf(l[i]) * z[i]) for i in range(n))
        w = system.integral
        P_mp = float(mpmath.pi / 4 * (mpmath.fsum(mpmath.mpf(w[i]) * z[i] for i in range(ns))
                                      + mpmath.mpf(normal_factor(theta))
                                      * mpmath.fsum(mpmath.mpf(w[i]) * z[ns + i] for i in range(ns, w.size))))  # (2.4)
        z_mp = np.array([float(v) for v in z])
        G_scaled = float(G / scale)
    P_double = float(0.25 * math.pi * (w[:ns] @ z_double[:ns] + normal_factor(theta) * (w[ns:] @ z_double[2 * ns:])))
    checks = (
        MpCheck("z: max |z_double - z_mp| / max |z_mp|", float(np.max(np.abs(z_double - z_mp)) / np.max(np.abs(z_mp))),
                0.0),
        MpCheck("P* of z at the double theta (2.4)", P_double, P_mp),
        MpCheck("G(theta_double) / sum |l_i z_i| in mpmath", G_scaled, 0.0),
        MpCheck("mu: double root against the 30-digit Newton root", field.mu, mu_root),
    )
    return MpStudy(f"level-{level} system at nu = {nu}, c = {c!r} (1 - c = {gap:.4g}, gamma = {gamma:.4g})", b.size,
                   _conditions(D)[1], checks)


def adhesive_mp_check(nu: float, xs: Sequence[float] = (0.0, 0.5, 0.9, 0.999, 1.0 - 1e-6), *,
                      graded_level: int | None = 4, dps: int = 30) -> MpStudy:
    """c = 1: the API's closed forms (``flat_punch(mu=inf)``: (B3), (B4)), (4.10) and the graded c = 1
    solver at ``graded_level`` against P0* = atanh(gamma)/gamma (B4) and p0, q0 of (B3) by mpmath
    quadrature at ``dps`` digits (``asymptotics.adhesive.*_mp``)."""
    gamma = _gamma(nu)
    api = flat_punch(nu=nu, mu=math.inf)
    with mpmath.workdps(dps):
        P = float(mpmath.atanh(mpmath.mpf(gamma)) / mpmath.mpf(gamma))
    out = [MpCheck("P0* closed form (B4)", api.compliance, P),
           MpCheck("p0(0) closed form (4.10)", float(central_pressure_adhesive(gamma)),
                   float(pressure_adhesive_mp(0.0, gamma, dps)))]
    solver = None if graded_level is None else solve_adhesive(gamma, GRADED_LEVELS[graded_level])
    if solver is not None:
        out.append(MpCheck(f"P0* graded level {graded_level}", solver.compliance, P))
    for x in xs:
        p, q = float(pressure_adhesive_mp(x, gamma, dps)), float(shear_adhesive_mp(x, gamma, dps))
        out += [MpCheck(f"p0({x!r}) closed form (B3)", float(api.pressure(x)), p),
                MpCheck(f"q0({x!r}) closed form (B3)", float(api.shear(x)), q)]
        if solver is not None:
            xa = np.array([x])
            out += [MpCheck(f"p0({x!r}) graded level {graded_level}", float(solver.pressure(xa)[0]), p),
                    MpCheck(f"q0({x!r}) graded level {graded_level}", float(solver.shear(xa)[0]), q)]
    return MpStudy(f"adhesive c = 1, nu = {nu} (gamma = {gamma:.4g})", 0 if solver is None else solver.n_unknowns,
                   math.nan, tuple(out))


# ----------------------------------------------------------------------------- driver
def _near_c_max(nu: float, factor: float = 1.01) -> tuple[float, float]:
    """(c, 1 - c) with 1 - c = factor (1 - c_max(nu))."""
    gap = factor * _gap_max(_gamma(nu))
    return 1.0 - gap, gap


def run(quick: bool = False) -> StabilityReport:
    """All studies; ``quick`` shrinks each of them (seconds, for a smoke test)."""
    seconds = []
    t = time.process_time()
    grid = QUICK_GRID if quick else FULL_GRID
    points = sweep(grid)
    limit = power_law_limit(grid.limit_nus, grid.limit_mu_gammas)
    seconds.append(("sweep", time.process_time() - t))
    t = time.process_time()
    if quick:
        honesty, skipped = check_honesty(points, max_level4=2, max_graded=1, graded_levels=(1, 0))
    else:
        honesty, skipped = check_honesty(points, max_level4=None, max_graded=24)
    seconds.append(("honesty", time.process_time() - t))
    t = time.process_time()
    if quick:
        plateaus = (plateau_study(0.0, 0.5, finest_level=2, extra=False),
                    slip_limit_plateau(0.0, finest_level=2, extra=False),
                    adhesive_plateau(0.0, finest_level=1))
    else:
        c_near, gap_near = _near_c_max(0.0)
        c_near3, gap_near3 = _near_c_max(-0.999)
        plateaus = (plateau_study(0.0, 0.5), plateau_study(-0.999, 0.9), plateau_study(0.4999, 0.5),
                    plateau_study(0.3, 1e-4), plateau_study(0.0, c_near, gap=gap_near),
                    plateau_study(-0.999, c_near3, gap=gap_near3),
                    slip_limit_plateau(0.0), slip_limit_plateau(-0.999), slip_limit_plateau(0.3),
                    adhesive_plateau(0.0), adhesive_plateau(-0.999))
    seconds.append(("plateau", time.process_time() - t))
    t = time.process_time()
    if quick:
        mp = (adhesive_mp_check(0.0, xs=(0.5,), graded_level=1),)
    else:
        c_near, gap_near = _near_c_max(0.0)
        mp = (system_mpmath_check(0.0, 0.5), system_mpmath_check(0.4999, 0.5), system_mpmath_check(0.3, 1e-4),
              system_mpmath_check(0.0, c_near, gap=gap_near),
              adhesive_mp_check(-0.999), adhesive_mp_check(0.0), adhesive_mp_check(0.4999, graded_level=None))
    seconds.append(("mpmath", time.process_time() - t))
    return StabilityReport(quick, table_available(), points, limit, honesty, skipped, plateaus, mp, tuple(seconds))
