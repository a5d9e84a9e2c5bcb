"""The frictional flat punch: stick radius, friction, compliance and stresses ([S75] §2).

Method, and why: piecewise polynomials in u = t^2 on an hp mesh graded geometrically
toward the stick-slip boundary and the edge, collocation of (2.2) with every Abel integral
done exactly, and the eigenvalue condition phi(c-) = 0 solved by a Krylov model of the
linear system (``numeric.discretize``, ``numeric.eigen``). The solution has power-type
singularities at x = c and x = 1 whose exponents depend on mu (tan pi alpha = mu gamma),
so a fixed singular basis would have to change during the eigenvalue iteration; geometric
grading with low degree near those points and high degree away from them resolves any
such exponent with exponential convergence in the number of unknowns, and keeps the
matrices for a given mesh reusable (cached) across mu and gamma.

The limits use closed forms: mu = 0 is frictionless (2.26) with c = 0; gamma = 0 (an
incompressible solid) has no shear coupling, q = 0 and c = 1 for any mu > 0; mu = inf or
c = 1 is the fully adhesive solution of Appendix B.

``error`` is the difference between two resolution levels (the one returned and the next
coarser), an upper estimate of the returned level's error because the levels converge
exponentially (tests check it against a finer level). Where mu gamma > 1 the singularity
at c becomes nearly a jump (exponent 1/2 - alpha -> 0) and convergence can stall; then a
third level is solved and the larger difference is reported if they do not shrink tenfold.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike
from scipy import optimize

from asymptotics.adhesive import compliance_adhesive, pressure_adhesive, shear_adhesive
from asymptotics.arrays import scalar_or_array
from asymptotics.flat_punch import frictionless_pressure, mu_over_gamma
from asymptotics.materials import check_c, check_mu, check_nu, check_x, gamma_from_nu, resolve_gamma

from .discretize import LEVELS
from .eigen import FlatField, NoEigenvalueError, SolverError, solve_mu
from .eigen_table import table_available, table_friction_coefficient, table_stick_radius

__all__ = ["FlatPunchSolution", "flat_punch", "stick_radius", "friction_coefficient", "NoEigenvalueError", "SolverError"]

DEFAULT_LEVEL = 2
ADHESIVE_EDGE_BREAKPOINTS = np.concatenate([[0.0, 0.5], 1.0 - 0.5 * 0.25 ** np.arange(1, 26), [1.0]])
ADHESIVE_EDGE_BREAKPOINTS.setflags(write=False)  # smooth pieces of the closed forms, graded toward x = 1


@dataclass(frozen=True, slots=True)
class _ClosedForm:
    """Frictionless (c = 0 or gamma = 0) or fully adhesive (c = 1) stresses in closed form."""

    gamma: float
    adhesive: bool

    def pressure(self, x: np.ndarray) -> np.ndarray:
        if self.adhesive and self.gamma > 0.0:
            return pressure_adhesive(x, self.gamma)  # (B3)
        return frictionless_pressure(x)  # (2.26)

    def shear(self, x: np.ndarray) -> np.ndarray:
        if self.adhesive and self.gamma > 0.0:
            return shear_adhesive(x, self.gamma)  # (B3)
        return np.zeros(np.shape(x))

    def slip(self, x: np.ndarray) -> np.ndarray:
        return np.zeros(np.shape(x))


@dataclass(frozen=True, slots=True)
class FlatPunchSolution:
    """A flat punch pressed into a half-space with friction, [S75] §2.

    Attributes
    ----------
    nu : float or None
        Poisson's ratio (None when gamma was given directly).
    gamma : float
        Coupling constant (2.2).
    mu : float
        Friction coefficient (inf for the adhesive limit).
    c : float
        Stick radius over contact radius.
    compliance : float
        P* = (pi/2) int_0^1 x p dx (2.4); the load is P = 4 G a P* delta / (1 - nu).
    error : float
        Estimated absolute error of c, mu and compliance (0 for closed forms).
    route : str
        "closed form (...)" or "solver level L, n unknowns".
    breakpoints : ndarray
        Points in [0, 1] between which p and q are smooth (graded toward c and 1).

    Methods pressure(x), shear(x), slip(x) give p, q of (2.1) and u of (2.10) at
    0 <= x <= 1 (vectorised); at the punch edge x = 1 the flat-punch stresses are infinite
    ((1 - x)^(alpha - 1/2), alpha < 1/2; q is 0 without friction), and u is 0 in the stick zone.
    """

    nu: float | None
    gamma: float
    mu: float
    c: float
    compliance: float
    error: float
    route: str
    breakpoints: np.ndarray
    _field: FlatField | _ClosedForm

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """Contact pressure p(x), [S75] (2.1)."""
        return self._at(x, self._field.pressure, edge=self._edge_value())

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """Shear traction q(x), [S75] (2.1); q = mu p in the slip annulus."""
        return self._at(x, self._field.shear, edge=self._edge_value(shear=True))

    def slip(self, x: ArrayLike) -> np.ndarray | float:
        """Radial displacement rate u(x) = d u_r / d delta of (2.10); 0 on the stick zone."""
        return self._at(x, self._field.slip, edge=None)

    def _edge_value(self, shear: bool = False) -> float:
        if isinstance(self._field, _ClosedForm):
            return 0.0 if shear and not (self._field.adhesive and self.gamma > 0) else math.inf
        return math.inf  # (1 - x)^(alpha - 1/2), alpha < 1/2

    def _at(self, x: ArrayLike, f, edge: float | None) -> np.ndarray | float:
        xs = check_x(x)
        flat = xs.ravel()
        out = np.empty(flat.shape)
        interior = flat < 1.0
        out[interior] = f(flat[interior])
        if edge is None:
            out[~interior] = f(np.nextafter(1.0, 0.0) * np.ones((~interior).sum())) if np.any(~interior) else 0.0
        else:
            out[~interior] = edge
        return scalar_or_array(out.reshape(xs.shape))


def _closed_form(nu, gamma: float, mu: float, c: float, adhesive: bool, why: str) -> FlatPunchSolution:
    compliance = float(compliance_adhesive(gamma)) if adhesive else 1.0  # (B4) or frictionless
    return FlatPunchSolution(nu, gamma, mu, c, compliance, 0.0, f"closed form ({why})", ADHESIVE_EDGE_BREAKPOINTS,
                             _ClosedForm(gamma, adhesive))


def _from_field(nu, fine: FlatField, level: int, error: float) -> FlatPunchSolution:
    return FlatPunchSolution(
        nu=nu,
        gamma=fine.gamma,
        mu=fine.mu,
        c=fine.c,
        compliance=fine.compliance,
        error=error,
        route=f"solver level {level}, {fine.n_unknowns} unknowns",
        breakpoints=fine.breakpoints,
        _field=fine,
    )


def _error_estimate(fields: list[FlatField]) -> float:
    """Difference of the two finest levels, or, where it has not shrunk tenfold from the
    next pair (convergence stalling as alpha -> 1/2, mu gamma large), the larger of the two."""
    diffs = [max(abs(a.mu - b.mu), abs(a.compliance - b.compliance)) for a, b in zip(fields, fields[1:])]
    if len(diffs) == 2 and diffs[0] > 0.1 * diffs[1]:
        return max(diffs)
    return diffs[0]


#: Largest stick radius the solver is asked for; beyond it the answer is bracketed (flat_punch).
C_TOP = 1.0 - 1e-9


def _first_order_stick_radius(mu: float, gamma: float) -> float:
    """Invert the small-gamma law (2.28), mu/gamma = atanh(c)/(c K'(c)), for c (capped at C_TOP)."""
    target = mu / gamma
    g = lambda s: math.log(float(mu_over_gamma(_expit(s)))) - math.log(target)  # noqa: E731
    top = _logit(C_TOP)
    if g(top) <= 0.0:
        return C_TOP
    return _expit(optimize.brentq(g, -60.0, top, xtol=1e-12))


class _AboveTop(Exception):
    """mu exceeds mu_c(C_TOP): the stick radius lies in (C_TOP, 1]."""


def _logit(c: float) -> float:
    return math.log(c / (1.0 - c))


def _expit(s: float) -> float:
    return 1.0 / (1.0 + math.exp(-s))


def _invert_coarse(mu: float, gamma: float, level: int, c_guess: float) -> tuple[FlatField, float]:
    """Stick radius with mu_c(c) = mu at one level by Brent in s = logit(c) on log mu.

    Returns the solution and d(log mu)/ds at the root (from the two nearest evaluations)."""
    evaluations: dict[float, FlatField] = {}

    def g(s: float) -> float:
        c = min(_expit(s), C_TOP)
        try:
            field = solve_mu(c, gamma, LEVELS[level], mu_guess=mu)
        except NoEigenvalueError:
            return math.inf  # beyond the largest stick radius: mu is unbounded there
        evaluations[s] = field
        return math.log(field.mu) - math.log(mu)

    s0 = _logit(c_guess)
    step = 0.05
    lo, hi = s0 - step, s0 + step
    g_lo, g_hi = g(lo), g(hi)
    while g_lo > 0.0:
        lo, hi, g_hi = lo - 2 * step, lo, g_lo
        step *= 2
        g_lo = g(lo)
        if lo < -40:
            raise NoEigenvalueError(f"no stick radius above 1e-17 for mu = {mu}, gamma = {gamma:.6g}")
    while g_hi < 0.0:
        lo, g_lo, hi = hi, g_hi, hi + 2 * step
        step *= 2
        g_hi = g(hi)
        if hi >= _logit(C_TOP):
            raise _AboveTop()
    root = optimize.brentq(g, lo, hi, xtol=1e-11)
    field = evaluations.get(root) or solve_mu(_expit(root), gamma, LEVELS[level], mu_guess=mu)
    # slope from the nearest evaluation at a different c (s beyond C_TOP is clamped to it)
    near = min((s for s in evaluations if evaluations[s].c != field.c), key=lambda s: abs(s - root))
    slope = (math.log(evaluations[near].mu) - math.log(field.mu)) / (_logit(evaluations[near].c) - _logit(field.c))
    return field, slope


def _table_start(mu: float, gamma: float) -> tuple[float, float] | None:
    """c from the Chebyshev table and d(log mu)/d(logit c) there, or None outside its domain."""
    if not table_available():
        return None
    c = float(table_stick_radius(mu, gamma))
    if math.isnan(c):
        return None
    s = _logit(c)
    pair = table_friction_coefficient(1.0 / (1.0 + np.exp(-np.array([s - 1e-4, s + 1e-4]))), np.array(gamma))
    if np.any(np.isnan(pair)):
        return None
    return c, float(np.log(pair[1] / pair[0]) / 2e-4)


def _invert(mu: float, gamma: float, level: int) -> tuple[FlatField, float]:
    """The fine solution with mu_c(c) = mu and the error of its c.

    The start is the Chebyshev table's c (``numeric.eigen_table``) or, outside the table,
    Brent on the coarse level. Then secant steps in logit(c) on the fine level until the
    fine mu matches to 1e-11 relative (usually 1-2 solves, the start being that close), c
    stops moving in double precision (near c = 1), or 8 steps are spent: at very small c,
    mu(c) at fixed resolution jitters by ~1e-10 relative (measured at c = 4e-5). The best
    iterate is returned; the error of c adds its remaining mismatch in mu to the coarse
    level's mismatch (or the coarse c's distance), both converted to c by the slope.
    """
    start = _table_start(mu, gamma)
    coarse = None
    if start is None:
        coarse, slope = _invert_coarse(mu, gamma, level - 1, _first_order_stick_radius(mu, gamma))
        c_start = coarse.c
    else:
        c_start, slope = start
    s_old, field = _logit(c_start), solve_mu(c_start, gamma, LEVELS[level], mu_guess=mu)
    g_old = math.log(field.mu) - math.log(mu)
    best, g_best = field, g_old
    for _ in range(8):
        if abs(g_old) < 1e-11:
            break
        step = -g_old / slope
        while True:
            s_new = s_old + step
            try:
                if _expit(s_new) > C_TOP:
                    if solve_mu(C_TOP, gamma, LEVELS[level], mu_guess=mu).mu < mu:
                        raise _AboveTop()  # mu increases with c: the stick radius is above C_TOP
                    raise NoEigenvalueError("step beyond C_TOP")
                new = solve_mu(_expit(s_new), gamma, LEVELS[level], mu_guess=mu)
                break
            except NoEigenvalueError:
                step /= 4.0  # overshot beyond the largest stick radius: shorten the step
        g_new = math.log(new.mu) - math.log(mu)
        if abs(g_new) < abs(g_best):
            best, g_best = new, g_new
        if abs(new.c - field.c) <= 4 * np.spacing(new.c):  # c cannot move further in doubles
            break
        if g_new != g_old:
            slope = (g_new - g_old) / (s_new - s_old)
        s_old, g_old, field = s_new, g_new, new
    to_c = best.c * (1.0 - best.c) / abs(slope)  # d c = c (1 - c) d logit(c), d log mu = slope d logit(c)
    residual = abs(g_best) * to_c
    if coarse is None:
        check = solve_mu(best.c, gamma, LEVELS[level - 1], mu_guess=mu)
        return best, residual + max(abs(math.log(check.mu / mu)) * to_c, abs(check.compliance - best.compliance))
    return best, residual + max(abs(best.c - coarse.c), abs(best.compliance - coarse.compliance))


def flat_punch(
    nu: float | None = None,
    mu: float | None = None,
    c: float | None = None,
    *,
    gamma: float | None = None,
    level: int = DEFAULT_LEVEL,
) -> FlatPunchSolution:
    """Solve the flat-punch problem (2.7)-(2.9) for given friction or given stick radius.

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 1/2 (or give ``gamma`` for dissimilar bodies).
    mu : float, optional
        Friction coefficient, 0 <= mu <= inf. Exactly one of ``mu`` and ``c``.
    c : float, optional
        Stick radius over contact radius, 0 < c <= 1; the friction coefficient that
        produces it is returned.
    gamma : float, optional
        Coupling constant (2.2) instead of ``nu``.
    level : int
        Resolution level 1..4 of ``numeric.discretize.LEVELS`` (the next coarser one gives
        the error estimate); 2 reaches ~1e-10.

    Returns
    -------
    FlatPunchSolution

    Raises
    ------
    NoEigenvalueError
        If no friction coefficient gives the requested c (large gamma, c near 1).
    SolverError
        If even level 1 does not converge. Where the requested level fails (stick radii
        below ~1e-4, mu well below gamma / log(4e4), (2.29)) the next coarser level is used
        and ``route`` says so.

    Examples
    --------
    >>> s = flat_punch(nu=0.0, c=0.5)
    >>> round(s.mu, 10), round(s.compliance, 10), s.error < 1e-9
    (0.298714616, 1.0522119983, True)
    """
    g = resolve_gamma(nu, gamma)
    nu_value = None if nu is None else float(check_nu(nu))
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick radius)")
    if not 1 <= int(level) < len(LEVELS) or int(level) != level:
        raise ValueError(f"level must be an integer in [1, {len(LEVELS) - 1}], got {level!r}")
    if c is not None:
        c_value = float(check_c(c))
        if c_value == 1.0:
            return _closed_form(nu_value, g, math.inf, 1.0, True, "adhesive, App. B")
        if g == 0.0:
            return _closed_form(nu_value, g, 0.0, c_value, False, "gamma = 0: no coupling, mu = 0 (2.28)")
        return _with_fallback(lambda lv: _solve_given_c(nu_value, c_value, g, lv), level)
    mu_value = float(check_mu(mu))
    if mu_value == 0.0:
        return _closed_form(nu_value, g, 0.0, 0.0, False, "frictionless, (2.26)")
    if mu_value == math.inf:
        return _closed_form(nu_value, g, math.inf, 1.0, True, "adhesive, App. B")
    if g == 0.0:
        return _closed_form(nu_value, g, mu_value, 1.0, False, "gamma = 0: no coupling, no slip")
    return _with_fallback(lambda lv: _solve_given_mu(nu_value, mu_value, g, lv), level)


def _with_fallback(solve, level: int) -> FlatPunchSolution:
    """``solve(level)``, or, where the level does not converge (very small c), the next coarser
    level with the route saying so; the error estimate is then that level's own."""
    try:
        return solve(level)
    except SolverError:
        if level <= 1:
            raise
        sol = _with_fallback(solve, level - 1)
        return replace(sol, route=f"{sol.route} (level {level} did not converge)")


def _solve_given_c(nu, c: float, gamma: float, level: int) -> FlatPunchSolution:
    # the table's mu (7e-12, recorded at build) centres the LU: the Krylov root is then local, no second LU
    guess = float(table_friction_coefficient(c, gamma)[0]) if table_available() else math.nan
    guess = None if math.isnan(guess) else guess
    fields = [solve_mu(c, gamma, LEVELS[lv], mu_guess=guess) for lv in (level, level - 1)]
    if fields[0].mu * gamma > 1.0 and level >= 2:  # alpha > 1/4: convergence can stall, look one level further
        fields.append(solve_mu(c, gamma, LEVELS[level - 2], mu_guess=guess))
    return _from_field(nu, fields[0], level, _error_estimate(fields))


def _solve_given_mu(nu, mu: float, gamma: float, level: int) -> FlatPunchSolution:
    try:
        fine, error = _invert(mu, gamma, level)
    except _AboveTop:
        return _near_full_stick(nu, gamma, mu, level)
    return _from_field(nu, fine, level, error)


def _near_full_stick(nu, gamma: float, mu: float, level: int) -> FlatPunchSolution:
    """mu > mu_c(C_TOP): by monotonicity in mu (c and P* increase, §2.1), C_TOP < c <= 1 and
    P*(C_TOP) < P* <= P0*; return the midpoints with half-widths (plus the solver's error
    at C_TOP) as the error, and the adhesive closed-form stresses (exact outside the slip
    annulus of width < 1 - C_TOP only in the limit)."""
    edge = solve_mu(C_TOP, gamma, LEVELS[level], mu_guess=mu)
    edge_coarse = solve_mu(C_TOP, gamma, LEVELS[level - 1], mu_guess=mu)
    if edge.mu > mu:  # the coarse search overshot: not in the near-full-stick regime after all
        raise SolverError(f"stick radius for mu = {mu}, gamma = {gamma:.6g} not bracketed below {C_TOP}")
    adhesive = float(compliance_adhesive(gamma))
    solver_error = abs(edge.compliance - edge_coarse.compliance)
    return FlatPunchSolution(
        nu=nu,
        gamma=gamma,
        mu=mu,
        c=0.5 * (1.0 + C_TOP),
        compliance=0.5 * (adhesive + edge.compliance),
        error=max(0.5 * (1.0 - C_TOP), 0.5 * abs(adhesive - edge.compliance) + solver_error),
        route=f"bracketed: mu > mu_c({C_TOP}) = {edge.mu:.6g}, so {C_TOP} < c <= 1; adhesive stresses (App. B)",
        breakpoints=ADHESIVE_EDGE_BREAKPOINTS,
        _field=_ClosedForm(gamma, True),
    )


class Executor(Protocol):
    """What a sweep can be handed to: ``concurrent.futures`` executors (threads or
    processes) and ``dask.distributed.Client.get_executor()`` all provide this ``map``."""

    def map(self, fn: Callable, *iterables: Iterable) -> Iterable: ...


def _solved_c(mu: float, nu: float, level: int) -> float:
    return flat_punch(nu=nu, mu=mu, level=level).c


def _solved_mu(c: float, nu: float, level: int) -> float:
    return flat_punch(nu=nu, c=c, level=level).mu


def _report(name: str, done: int, total: int, started: float) -> None:
    rate = done / max(time.perf_counter() - started, 1e-9)
    end = "\n" if done == total else ""
    sys.stderr.write(f"\r{name}: {done}/{total} points solved, {rate:.3g} points/s{end}")
    sys.stderr.flush()


def _sweep(name: str, table, solve, first: ArrayLike, nu: ArrayLike, use_table: bool, level: int,
           executor: Executor | None, progress: bool) -> np.ndarray | float:
    """Evaluate ``table`` on all points at once; solve the points outside its domain, one by
    one or through ``executor``, reporting progress on stderr when asked."""
    a, n = np.broadcast_arrays(np.asarray(first, dtype=float), np.asarray(nu, dtype=float))
    shape = a.shape
    a, n = a.ravel(), n.ravel()
    g = np.asarray(gamma_from_nu(n), dtype=float)
    out = np.array(table(a, g), dtype=float) if use_table and table_available() else np.full(a.shape, np.nan)
    missing = np.flatnonzero(np.isnan(out))
    if missing.size:
        args = (a[missing], n[missing], [level] * missing.size)
        results = executor.map(solve, *args) if executor is not None else map(solve, *args)
        started = time.perf_counter()
        for k, (index, value) in enumerate(zip(missing, results), 1):
            out[index] = value
            if progress:
                _report(name, k, missing.size, started)
    out = out.reshape(shape)
    return float(out) if out.ndim == 0 else out


def stick_radius(mu: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int = DEFAULT_LEVEL,
                 executor: Executor | None = None, progress: bool = False) -> np.ndarray | float:
    """Stick radius c(mu, nu) of [S75] §2.2, broadcasting over arrays.

    Inside the table's domain (``numeric.eigen_table``: 1e-3 <= c <= 0.95, nu >= -1/2) c
    comes from the Chebyshev table of the eigenvalue relation (microseconds a point, error
    ``numeric._eigen_table.MU_RELATIVE_ERROR`` in mu); elsewhere, or with
    ``use_table=False``, from ``flat_punch`` at ``level``: one by one, or mapped over
    ``executor`` (any ``concurrent.futures`` executor, or a Dask client's ``get_executor()``),
    with a progress line on stderr when ``progress`` is true.

    Examples
    --------
    >>> round(float(stick_radius(0.298714615962, 0.0)), 9)
    0.5
    """
    check_mu(mu)
    check_nu(nu)
    return _sweep("stick_radius", table_stick_radius, _solved_c, mu, nu, use_table, level, executor, progress)


def friction_coefficient(c: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int = DEFAULT_LEVEL,
                         executor: Executor | None = None, progress: bool = False) -> np.ndarray | float:
    """Friction coefficient mu(c, nu) that produces stick radius c, broadcasting over arrays.

    From the Chebyshev table inside its domain, else from ``flat_punch`` (see ``stick_radius``).
    """
    check_c(c)
    check_nu(nu)
    return _sweep("friction_coefficient", table_friction_coefficient, _solved_mu, c, nu, use_table, level, executor,
                  progress)
