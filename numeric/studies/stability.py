"""Stress tests of numerical stability: parameter sweep, honesty of ``error``, round-off.

Three studies of the high-accuracy solver ([S75] §2, ``numeric.flat_punch``):

1. ``sweep``: every public entry point (``flat_punch`` given mu or c, ``stick_radius``,
   ``friction_coefficient``, ``power_law``) over nu in [-0.99, 0.4999] (gamma from 0.749 to
   2e-4), mu in [1e-4, 1e4] and c in [1e-12, 1]; each call's value, ``error``, ``route`` or
   raised exception is recorded, and each value is checked to be finite and admissible
   (0 < c <= 1, mu >= 0, 1 <= P* <= atanh(gamma)/gamma of (B4)). ``check_honesty`` compares a
   sample with the finest level (``LEVELS[4]``): |value - reference| <= error must hold.
2. ``plateau_study``, ``adhesive_plateau``: the error of mu and P* (2.4) as the resolution
   grows past convergence, with the condition number of the collocation matrix
   D(mu) = D0 + mu D1 of ``numeric.core.graded_eigen`` (raw and after the row/column equilibration the
   solver factors); at c = 1 the reference is the exact P0* = atanh(gamma)/gamma (B4).
3. ``mpmath_crosscheck``: the level-0 system D(mu) z = b solved in mpmath at 30 digits
   (same double matrix, so the difference is the round-off of the double solve) and one
   Newton step of the eigenvalue condition phi(c-) = mu p(c-) - q(c-) = 0 (2.11) in mpmath;
   ``adhesive_mp_check``: the adhesive solution (c = 1) against (B3), (B4), (4.10) at 30 digits.

Run ``hertz-friction stability [--quick]``; it writes ``derivations/stability.md``
(``numeric.studies.stability_report``; full run measured at 442 s of CPU, 16 min wall on the
shared 2-core machine; ``--quick`` ~3 s of CPU).
The hand-over to asymptotic forms where c or 1 - c is exponentially small (2.29) is not
part of this module.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import mpmath
import numpy as np
import scipy.linalg as sla
from scipy.sparse.linalg import LinearOperator, onenormest

from asymptotics.adhesive import central_pressure_adhesive, pressure_adhesive_mp, shear_adhesive_mp
from asymptotics.materials import gamma_from_nu

from numeric.core import table_data
from numeric.core.linear_algebra import EquilibratedLU, equilibrate
from numeric.core.graded_collocation import adhesive_system, end_value_row, solve_adhesive, system
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.graded_eigen import solve_mu
from numeric.core.graded_mesh import LEVELS, Resolution, discretise
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.power_law import power_law
from numeric.solutions.sweep import friction_coefficient, stick_radius

__all__ = [
    "SweepPoint",
    "HonestyCheck",
    "PlateauRow",
    "MpCheck",
    "StabilityReport",
    "FULL_GRID",
    "QUICK_GRID",
    "FINE_RESOLUTIONS",
    "sweep",
    "check_honesty",
    "plateau_study",
    "adhesive_plateau",
    "mpmath_crosscheck",
    "adhesive_mp_check",
    "run",
]

#: (nus, mus, cs) of the full sweep; nu = -0.99 gives gamma = 0.749, nu = 0.4999 gamma = 2e-4 (2.2)
FULL_GRID: tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]] = (
    (-0.99, -0.5, 0.0, 0.25, 0.45, 0.4999),
    (1e-4, 1e-2, 0.1, 0.3, 1.0, 10.0, 1e4),
    (1e-12, 1e-6, 1e-4, 1e-2, 0.3, 0.7, 0.95, 0.99, 0.999, 1.0 - 1e-6, 1.0 - 1e-12, 1.0),
)
QUICK_GRID: tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]] = (
    (0.0, 0.45),
    (0.0, 0.3),
    (0.5, 1.0),
)

#: Resolutions beyond LEVELS[4] for the plateau study: higher degree; finer ratio and more layers;
#: finer still (the last one's eigenvalue is not certified at c = 0.5: SolverError, recorded as such)
FINE_RESOLUTIONS: tuple[Resolution, ...] = (
    Resolution(sigma=0.18, layers_c=20, layers_edge=26, kmax=32, slope=2.0, layers_adhesive=44, kmax_adhesive=40,
               slope_adhesive=2.0),
    Resolution(sigma=0.15, layers_c=24, layers_edge=30, kmax=30, slope=1.5, layers_adhesive=48, kmax_adhesive=40,
               slope_adhesive=2.0),
    Resolution(sigma=0.12, layers_c=28, layers_edge=34, kmax=34, slope=2.0, layers_adhesive=56, kmax_adhesive=44,
               slope_adhesive=2.5),
)


@dataclass(frozen=True, slots=True)
class SweepPoint:
    """One call of the sweep.

    ``function`` names the call ("flat_punch(mu)", "flat_punch(c)", "stick_radius",
    "friction_coefficient", "power_law(2)"); ``argument`` is its mu or c. ``c``, ``mu``,
    ``compliance`` are the returned values (NaN when the call raised, or not returned by that
    function); ``raised`` is "" or "ExceptionType: message"; ``admissible`` says the values are
    finite and in range (0 < c <= 1, mu >= 0, 1 - error <= P* <= atanh(gamma)/gamma + error);
    ``seconds`` is CPU time.
    """

    function: str
    nu: float
    gamma: float
    argument: float
    c: float
    mu: float
    compliance: float
    error: float
    route: str
    raised: str
    admissible: bool
    seconds: float

    @property
    def region(self) -> str:
        """Region of the parameter space: by c for c-given calls, by the returned c otherwise."""
        c = self.argument if self.function in ("flat_punch(c)", "friction_coefficient") else self.c
        if math.isnan(c):
            return "mu <= 1e-2" if self.argument <= 1e-2 else ("mu >= 10" if self.argument >= 10 else "raised, 1e-2 < mu < 10")
        if c == 0.0:
            return "c = 0"
        if c < 1e-5:
            return "0 < c < 1e-5"
        if c < 0.99:
            return "1e-5 <= c < 0.99"
        return "0.99 <= c < 1" if c < 1.0 else "c = 1"


@dataclass(frozen=True, slots=True)
class HonestyCheck:
    """|value - reference| against the returned ``error`` (``bound``); reference at level 4."""

    function: str
    nu: float
    argument: float
    quantity: str
    value: float
    reference: float
    bound: float
    reference_error: float

    @property
    def difference(self) -> float:
        return abs(self.value - self.reference)

    @property
    def honest(self) -> bool:
        return self.difference <= self.bound


@dataclass(frozen=True, slots=True)
class PlateauRow:
    """One resolution of the plateau study: errors against the finest resolution (or exact)."""

    label: str
    n_unknowns: int
    mu: float
    compliance: float
    mu_error: float
    compliance_error: float
    condition: float
    condition_equilibrated: float
    seconds: float


@dataclass(frozen=True, slots=True)
class MpCheck:
    """A double-precision value against a 30-digit mpmath value of the same quantity."""

    label: str
    double: float
    mp: float

    @property
    def difference(self) -> float:
        return abs(self.double - self.mp)


@dataclass(frozen=True, slots=True)
class StabilityReport:
    """Everything ``main`` writes: the sweep, the honesty checks, the plateau and mpmath studies."""

    quick: bool
    points: tuple[SweepPoint, ...]
    honesty: tuple[HonestyCheck, ...]
    plateau: tuple[PlateauRow, ...]
    adhesive: tuple[PlateauRow, ...]
    mp_system: tuple[MpCheck, ...]
    mp_adhesive: tuple[MpCheck, ...]
    seconds: tuple[tuple[str, float], ...]  # (study, CPU seconds)


# ----------------------------------------------------------------------------- sweep
def _admissible(gamma: float, c: float, mu: float, compliance: float, error: float) -> bool:
    """Finite (mu may be inf) and in range; NaN marks a value the function does not return."""
    if any(math.isinf(v) for v in (c, compliance, error)):
        return False
    top = math.atanh(gamma) / gamma if gamma > 0 else 1.0  # (B4): the adhesive P* bounds P* above
    slack = 0.0 if math.isnan(error) else error
    return ((math.isnan(c) or 0.0 <= c <= 1.0) and (math.isnan(mu) or mu >= 0.0)
            and (math.isnan(compliance) or 1.0 - slack <= compliance <= top + slack))


def _call(function: str, nu: float, argument: float, f: Callable[[], object]) -> SweepPoint:
    gamma = float(gamma_from_nu(nu))
    start = time.process_time()
    c = mu = compliance = error = math.nan
    route = raised = ""
    try:
        out = f()
    except (ValueError, SolverError, NoEigenvalueError, ArithmeticError, RuntimeError) as exc:
        raised = f"{type(exc).__name__}: {exc}"
    else:
        if isinstance(out, float | np.floating):
            if function == "stick_radius":
                c = float(out)
            else:
                mu = float(out)
        else:
            c, mu, compliance, error = float(out.c), float(out.mu), float(out.compliance), float(out.error)
            route = getattr(out, "route", "") or getattr(out.flat, "route", "")
            if function.startswith("power_law"):
                compliance = float(out.flat.compliance)
                extra = (float(out.A), float(out.C))
                if not all(math.isfinite(v) for v in extra):
                    route += f" [A, C not finite: {extra}]"
                    error = math.inf
    seconds = time.process_time() - start
    ok = raised != "" or _admissible(gamma, c, mu, compliance, error)
    return SweepPoint(function, nu, gamma, argument, c, mu, compliance, error, route, raised, ok, seconds)


def sweep(nus: Sequence[float], mus: Sequence[float], cs: Sequence[float], *,
          power_law_nus: Sequence[float] | None = None,
          power_law_mus: Sequence[float] | None = None) -> tuple[SweepPoint, ...]:
    """Call every public entry point on the grid; record value, error, route or exception.

    ``power_law(2, nu=, mu=)`` runs on the sub-grid ``power_law_nus`` x ``power_law_mus``
    (default: the whole grid).
    """
    points = []
    for nu in nus:
        for mu in mus:
            points.append(_call("flat_punch(mu)", nu, mu, lambda: flat_punch(nu=nu, mu=mu)))
            points.append(_call("stick_radius", nu, mu, lambda: float(stick_radius(mu, nu))))
        for c in cs:
            points.append(_call("flat_punch(c)", nu, c, lambda: flat_punch(nu=nu, c=c)))
            points.append(_call("friction_coefficient", nu, c, lambda: float(friction_coefficient(c, nu))))
    for nu in nus if power_law_nus is None else power_law_nus:
        for mu in mus if power_law_mus is None else power_law_mus:
            points.append(_call("power_law(2)", nu, mu, lambda: power_law(2, nu=nu, mu=mu)))
    return tuple(points)


def _table_c_bound(c: float, gamma: float) -> float:
    """Error bound on a tabulated c: the recorded relative error of mu over d(log mu)/dc."""
    h = 1e-5 * min(c, 1.0 - c)
    pair = np.asarray(friction_coefficient(np.array([c - h, c + h]), _nu_of_gamma(gamma)), dtype=float)
    return table_data.MU_RELATIVE_ERROR / abs(math.log(pair[1] / pair[0]) / (2 * h))


def _nu_of_gamma(gamma: float) -> float:
    return (1.0 - 2.0 * gamma) / (2.0 - 2.0 * gamma)  # inverse of (2.2)


def check_honesty(points: Sequence[SweepPoint], *, max_checks: int | None = None) -> tuple[HonestyCheck, ...]:
    """Compare returned values with ``flat_punch(..., level=4)``: |value - reference| <= error.

    Checked: solver routes of ``flat_punch`` (c, mu, P*), and the table values of
    ``stick_radius`` / ``friction_coefficient`` inside the table's domain against its
    recorded error. Points whose level-4 reference raises are skipped.
    """
    checks: list[HonestyCheck] = []
    candidates = [p for p in points if not p.raised and (
        (p.function.startswith("flat_punch") and p.route.startswith("solver"))
        or (p.function in ("stick_radius", "friction_coefficient") and _in_table(p)))]
    if max_checks is not None and len(candidates) > max_checks:
        candidates = [candidates[i] for i in np.linspace(0, len(candidates) - 1, max_checks).round().astype(int)]
    for p in candidates:
        try:
            if p.function in ("flat_punch(c)", "friction_coefficient"):
                ref = flat_punch(nu=p.nu, c=p.argument, level=4)
            else:
                ref = flat_punch(nu=p.nu, mu=p.argument, level=4)
        except (SolverError, NoEigenvalueError):
            continue
        if p.function == "flat_punch(c)":
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "mu", p.mu, ref.mu, p.error, ref.error))
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "P*", p.compliance, ref.compliance, p.error,
                                       ref.error))
        elif p.function == "flat_punch(mu)":
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "c", p.c, ref.c, p.error, ref.error))
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "P*", p.compliance, ref.compliance, p.error,
                                       ref.error))
        elif p.function == "friction_coefficient":
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "mu", p.mu, ref.mu,
                                       table_data.MU_RELATIVE_ERROR * ref.mu, ref.error))
        else:
            checks.append(HonestyCheck(p.function, p.nu, p.argument, "c", p.c, ref.c,
                                       _table_c_bound(p.c, p.gamma), ref.error))
    return tuple(checks)


def _in_table(p: SweepPoint) -> bool:
    c = p.argument if p.function == "friction_coefficient" else p.c
    return (table_data.C_MIN <= c <= table_data.C_MAX) and p.gamma <= table_data.GAMMA_MAX


# ----------------------------------------------------------------------------- plateau
def _conditions(D: np.ndarray, exact: bool) -> tuple[float, float]:
    """Condition of D and of its equilibrated form (``numeric.core.graded_collocation.equilibrate``, what the
    solver factors): 2-norm by SVD when ``exact``, else the 1-norm estimate of Hager-Higham."""
    scaled = equilibrate(D)[0]
    out = []
    for M in (D, scaled):
        if exact:
            out.append(float(np.linalg.cond(M)))
        else:
            lu = sla.lu_factor(M, check_finite=False)
            n = M.shape[0]
            inv = LinearOperator((n, n), matvec=lambda y, lu=lu: sla.lu_solve(lu, y),
                                 rmatvec=lambda y, lu=lu: sla.lu_solve(lu, y, trans=1), dtype=float)
            out.append(float(np.linalg.norm(M, 1) * onenormest(inv)))
    return out[0], out[1]


def _resolutions(finest_level: int, extra: bool) -> list[tuple[str, Resolution]]:
    out = [(f"level {i}", LEVELS[i]) for i in range(finest_level + 1)]
    if extra:
        out += [(f"custom {i + 1}", r) for i, r in enumerate(FINE_RESOLUTIONS)]
    return out


def plateau_study(c: float, nu: float, *, finest_level: int = 4, extra: bool = True,
                  exact_condition_below: int = 1000) -> tuple[PlateauRow, ...]:
    """mu(c) and P* at resolutions past convergence; errors against the finest converged one.

    The condition number is that of D(mu) at the converged mu of each resolution; the 2-norm
    (SVD) below ``exact_condition_below`` unknowns, the 1-norm estimate above.
    """
    gamma = float(gamma_from_nu(nu))
    fields = []
    for label, res in _resolutions(finest_level, extra):
        start = time.process_time()
        try:
            field = solve_mu(c, gamma, res)
        except SolverError:
            fields.append((f"{label} (SolverError: no certified eigenvalue)", None, (math.nan, math.nan),
                           time.process_time() - start))
            continue
        seconds = time.process_time() - start
        D0, D1, _ = system(discretise(c, res), gamma)
        cond = _conditions(D0 + field.mu * D1, D0.shape[0] < exact_condition_below)
        fields.append((label, field, cond, seconds))
    finest = [f for _, f, _, _ in fields if f is not None][-1]
    rows = []
    for label, field, cond, seconds in fields:
        if field is None:
            rows.append(PlateauRow(label, 0, math.nan, math.nan, math.nan, math.nan, *cond, seconds))
            continue
        rows.append(PlateauRow(label, field.n_unknowns, field.mu, field.compliance, abs(field.mu - finest.mu),
                               abs(field.compliance - finest.compliance), *cond, seconds))
    return tuple(rows)


def adhesive_plateau(gamma: float, *, finest_level: int = 4, extra: bool = True,
                     exact_condition_below: int = 1000) -> tuple[PlateauRow, ...]:
    """The c = 1 solver's P* and p(0) against the exact (B4), (4.10) at each resolution.

    ``mu_error`` holds the error of p(0) (mu is infinite here).
    """
    with mpmath.workdps(30):
        g = mpmath.mpf(gamma)
        exact_p = float(mpmath.atanh(g) / g)  # (B4)
    exact_p0 = float(central_pressure_adhesive(gamma))  # (4.10)
    rows = []
    for label, res in _resolutions(finest_level, extra):
        start = time.process_time()
        field = solve_adhesive(gamma, res)
        seconds = time.process_time() - start
        D = adhesive_system(gamma, res)[0]
        cond = _conditions(D, D.shape[0] < exact_condition_below)
        p0 = float(field.pressure(np.array([0.0]))[0])
        rows.append(PlateauRow(label, field.n_unknowns, math.inf, field.compliance, abs(p0 - exact_p0),
                               abs(field.compliance - exact_p), *cond, seconds))
    return tuple(rows)


# ----------------------------------------------------------------------------- mpmath
def mpmath_crosscheck(c: float, nu: float, *, level: int = 0, dps: int = 30) -> tuple[MpCheck, ...]:
    """The level-``level`` system D(mu) z = b at the double-precision root, solved in mpmath.

    D, b are the double matrices of ``numeric.core.graded_collocation.system``; mpmath solves them at ``dps``
    digits, so the differences are the round-off of the double LU solve (the solver's own
    equilibrated LU) and of the eigenvalue iteration. One Newton step of
    F(mu) = mu p(c-) - c Q(c-) (2.11) in mpmath, with dz/dmu = -D^-1 D1 z, gives the root of
    the discrete problem to 30 digits (the step is ~1e-14, its square negligible).
    """
    gamma = float(gamma_from_nu(nu))
    res = LEVELS[level]
    field = solve_mu(c, gamma, res)
    d = discretise(c, res)
    D0, D1, b = system(d, gamma)
    ms = d.x_stick.size
    end = end_value_row(d.stick)
    D = D0 + field.mu * D1
    z_double = EquilibratedLU(D).solve(b)  # as the solver solves
    with mpmath.workdps(dps):
        LU, perm = mpmath.mp.LU_decomp(mpmath.matrix(D.tolist()))  # once: O(n^3) in mpmath

        def solve(rhs):
            return mpmath.mp.U_solve(LU, mpmath.mp.L_solve(LU, rhs.copy(), perm))

        z = solve(mpmath.matrix(b.tolist()))
        dz = solve(-(mpmath.matrix(D1.tolist()) * z))
        mu = mpmath.mpf(field.mu)
        e = [mpmath.mpf(v) for v in end]
        p_end = mpmath.fsum(e[i] * z[i] for i in range(ms))
        q_end = mpmath.fsum(e[i] * z[ms + i] for i in range(ms))
        dp_end = mpmath.fsum(e[i] * dz[i] for i in range(ms))
        dq_end = mpmath.fsum(e[i] * dz[ms + i] for i in range(ms))
        F = mu * p_end - c * q_end  # (2.11) at x = c-
        mu_root = mu - F / (p_end + mu * dp_end - c * dq_end)
        z_mp = np.array([float(v) for v in z])
        w = np.concatenate([d.w_stick, np.zeros(ms), d.w_slip])
        P_mp = float(mpmath.pi / 4 * mpmath.fsum(mpmath.mpf(w[i]) * z[i] for i in range(len(w))))  # (2.4)
        F_scaled = float(F / (mu * abs(p_end)))
    scale = float(np.max(np.abs(z_mp)))
    return (
        MpCheck(f"z (max-norm relative), level {level}, n = {b.size}", float(np.max(np.abs(z_double - z_mp)) / scale), 0.0),
        MpCheck("P* of the discrete solution at the double mu", field.compliance, P_mp),
        MpCheck("F(mu_double) / (mu p(c-)) in mpmath", F_scaled, 0.0),
        MpCheck("mu: double root vs 30-digit Newton root", field.mu, float(mu_root)),
    )


def adhesive_mp_check(gamma: float, xs: Sequence[float] = (0.0, 0.5, 0.9, 0.999), *, level: int = 4, dps: int = 30) -> tuple[MpCheck, ...]:
    """c = 1: the API's closed forms and the solver at ``level`` against 30-digit (B3), (B4).

    P0* = atanh(gamma)/gamma (B4) and p0, q0 at ``xs`` by mpmath quadrature of (B3)
    (``asymptotics.adhesive.*_mp``).
    """
    nu = _nu_of_gamma(gamma)
    api = flat_punch(nu=nu, c=1.0)
    solver = solve_adhesive(gamma, LEVELS[level])
    with mpmath.workdps(dps):
        P = float(mpmath.atanh(mpmath.mpf(gamma)) / mpmath.mpf(gamma))
    out = [MpCheck("P* closed form (B4)", api.compliance, P), MpCheck(f"P* solver level {level}", solver.compliance, P)]
    for x in xs:
        p = float(pressure_adhesive_mp(x, gamma, dps))
        q = float(shear_adhesive_mp(x, gamma, dps))
        xa = np.array([x])
        out += [
            MpCheck(f"p0({x}) closed form (B3)", float(api.pressure(x)), p),
            MpCheck(f"p0({x}) solver level {level}", float(solver.pressure(xa)[0]), p),
            MpCheck(f"q0({x}) closed form (B3)", float(api.shear(x)), q),
            MpCheck(f"q0({x}) solver level {level}", float(solver.shear(xa)[0]), q),
        ]
    return tuple(out)


# ----------------------------------------------------------------------------- driver
def run(quick: bool = False) -> StabilityReport:
    """All studies; ``quick`` shrinks every one of them (a few seconds)."""
    seconds = []
    t = time.process_time()
    if quick:
        nus, mus, cs = QUICK_GRID
        points = sweep(nus, mus, cs, power_law_nus=nus[:1], power_law_mus=mus[1:])
    else:
        nus, mus, cs = FULL_GRID
        points = sweep(nus, mus, cs, power_law_nus=(-0.99, 0.0, 0.4999), power_law_mus=(1e-4, 0.1, 1.0, 1e4))
    seconds.append(("sweep", time.process_time() - t))
    t = time.process_time()
    honesty = check_honesty(points, max_checks=2 if quick else 40)
    seconds.append(("honesty", time.process_time() - t))
    t = time.process_time()
    plateau = plateau_study(0.5, 0.25, finest_level=2 if quick else 4, extra=not quick)
    adhesive = adhesive_plateau(1 / 3, finest_level=2 if quick else 4, extra=not quick)
    seconds.append(("plateau", time.process_time() - t))
    t = time.process_time()
    mp_system = () if quick else mpmath_crosscheck(0.5, 0.25, level=0)
    mp_adhesive = adhesive_mp_check(1 / 3, xs=(0.5,) if quick else (0.0, 0.5, 0.9, 0.999), level=2 if quick else 4)
    seconds.append(("mpmath", time.process_time() - t))
    return StabilityReport(quick, points, honesty, plateau, adhesive, mp_system, mp_adhesive, tuple(seconds))
