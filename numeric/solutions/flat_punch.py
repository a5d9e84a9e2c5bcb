"""The frictional flat punch: stick radius, friction, compliance and stresses ([S75] §2).

Method, and why: piecewise polynomials in u = t^2 on an hp mesh graded geometrically
toward the stick-slip boundary and the edge, collocation of (2.2) with every Abel integral
done exactly, and the eigenvalue condition phi(c-) = 0 solved by a Krylov model of the
linear system (``numeric.core.mesh``, ``numeric.core.eigen``). The solution has power-type
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

Routes (``route`` of the result names the one taken): closed forms in the limits; the solver;
the asymptotic law mu/gamma = f0(c) (2.28) or f0 + gamma^2 f2 (``asymptotics.second_order``)
below c = 1e-5, where the solver does not converge, and wherever ``rtol`` allows it
(c <= 0.9), with error bounds measured against the solver (``numeric.solutions.law.K2_BOUNDS``, ``K4_BOUNDS``,
``KP2_BOUND``, ``KP4_BOUND``; first-order stresses, O(gamma^2)); a bracket for given mu
beyond what the solver reaches near the largest stick radius c_max = 1 - 8 exp(-pi/kappa).
``rtol`` takes the cheapest route that meets it and warns (``AccuracyWarning``) where none does.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import sys
import time
import warnings
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike
from scipy import optimize
from scipy.special import expit, logit

from asymptotics.adhesive import compliance_adhesive, pressure_adhesive, shear_adhesive
from asymptotics.arrays import scalar_or_array
from asymptotics.first_order import frictionless_pressure, mu_over_gamma, mu_over_gamma_log_slope
from asymptotics.second_order import correction_ratio
from asymptotics.materials import check_c, check_mu, check_nu, check_x, gamma_from_nu, kappa_from_gamma, resolve_gamma

from numeric.core.collocation import FlatField
from numeric.core.eigen import NoEigenvalueError, SolverError, solve_mu
from numeric.core.mesh import LEVELS
from numeric.core.table import table_available, table_friction_coefficient, table_stick_radius
from numeric.solutions.law import (ASYMPTOTIC_C_MAX, Bracket, FirstOrderField,
                                   law_bound, law_bracket, law_compliance, route_text)

__all__ = ["AccuracyWarning", "FlatPunchSolution", "flat_punch", "stick_radius", "friction_coefficient", "NoEigenvalueError",
           "SolverError"]

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


class AccuracyWarning(UserWarning):
    """The requested ``rtol`` could not be met; the most accurate result available was returned."""


#: Largest stick radius the solver is asked for at small gamma; beyond it the answer is bracketed.
C_TOP = 1.0 - 1e-9

# ---------------------------------------------------------------------------------------
# The largest stick radius (derivations/section_2_3.md, "Largest stick radius"): mu(c) of the
# full problem grows like 1/(c_max - c) with 1 - c_max = 8 exp(-pi/kappa), kappa = (2/pi) atanh(gamma);
# measured (1 - c_max) exp(pi/kappa) = 7.994 at gamma = 2/7 ... 0.5 and 7.926 at gamma = 2/3.

#: 1 - c_max ~ C_MAX_COEFFICIENT exp(-pi/kappa): the estimate quoted in messages.
C_MAX_COEFFICIENT = 8.0
#: c_max < 1 - C_MAX_UPPER_COEFFICIENT exp(-pi/kappa): 5 % below the smallest measured coefficient, 7.926.
C_MAX_UPPER_COEFFICIENT = 7.5
#: The given-mu search stops at c_top = 1 - C_SEARCH_COEFFICIENT exp(-pi/kappa), about 5 % of 1 - c_max
#: below c_max; there mu ~ 40 ... 100 (measured at gamma = 2/3 ... 1/3 in derivations/section_2_3.md,
#: level-2 error estimates 3e-5 ... 4e-2 of mu: the solver's error grows as c -> c_max).
C_SEARCH_COEFFICIENT = 8.4


def _gap_scale(gamma: float) -> float:
    """exp(-pi/kappa), kappa = (2/pi) atanh(gamma) ([S75] (4.10)): 1 - c_max is about 8 times this."""
    return math.exp(-math.pi / float(kappa_from_gamma(gamma)))


def _c_search_top(gamma: float) -> float:
    """Largest stick radius the given-mu search asks the solver for."""
    return min(C_TOP, 1.0 - C_SEARCH_COEFFICIENT * _gap_scale(gamma))


def _no_eigenvalue(c: float, gamma: float, detail: str = "") -> NoEigenvalueError:
    c_max = 1.0 - C_MAX_COEFFICIENT * _gap_scale(gamma)
    return NoEigenvalueError(
        f"no friction coefficient gives stick radius c = {c!r} at gamma = {gamma:.6g}: the largest stick radius is "
        f"estimated as c_max = 1 - 8 exp(-pi/kappa) = {c_max:.6g} (kappa = (2/pi) atanh(gamma); mu -> inf as "
        f"c -> c_max; derivations/section_2_3.md){detail}")


# ---------------------------------------------------------------------------------------
# Reach of the solver and accuracy of its levels

#: Smallest stick radius at which each level's eigenvalue iteration converges. Measured with
#: ``numeric.core.eigen.solve_mu`` at gamma = 0.1, 0.3, 0.5, 0.75: level 1 converged at 2e-6 and 5e-6;
#: level 2 failed at 2e-5 (gamma = 0.3) and 3e-5 (0.1, 0.3), converged at 5e-5; level 3 failed at
#: 2e-4, 3e-4, converged at 5e-4; level 4 failed at 1e-3 ... 5e-3, converged at 1e-2. A failing
#: iteration spends 5-25 s before SolverError, so a level is not tried below its floor.
LEVEL_C_MIN = {1: 5e-6, 2: 5e-5, 3: 5e-4, 4: 1e-2}
#: Below this stick radius the asymptotic law replaces the solver (twice level 1's floor).
C_ASYMPTOTIC = 1e-5
#: Typical relative accuracy of each level (numeric.core.mesh.LEVELS); rtol picks the first that meets it.
LEVEL_TYPICAL_ERROR = {1: 1e-8, 2: 1e-10, 3: 1e-12}
#: Relative error of mu from the Chebyshev table (numeric.core.table): MU_RELATIVE_ERROR = 5.2e-11, the
#: worst of its build checks (at the corner c = 0.95, gamma = 2/3); about twice that.
TABLE_MU_RTOL = 1e-10

def _graded_breakpoints(c: float) -> np.ndarray:
    """Breakpoints graded toward x = c (both sides) and toward the edge."""
    if c <= 0.0:
        return ADHESIVE_EDGE_BREAKPOINTS
    k = 0.25 ** np.arange(1, 26)
    points = np.unique(np.concatenate([ADHESIVE_EDGE_BREAKPOINTS, [c], c * (1.0 - k), c + (1.0 - c) * k]))
    points.setflags(write=False)
    return points


def _asymptotic_given_c(nu, c: float, gamma: float, order: int, why: str) -> FlatPunchSolution:
    f0 = float(mu_over_gamma(c))
    mu = gamma * f0 * (1.0 + correction_ratio(c) * gamma**2 if order == 2 else 1.0)
    bound = law_bound(c, gamma, order)
    compliance, bound_p = law_compliance(c, gamma, order, f0)
    return FlatPunchSolution(nu, gamma, mu, c, compliance, max(bound * mu, bound_p),
                             route_text(order, bound, bound_p, why), _graded_breakpoints(c),
                             FirstOrderField(c, mu))


def _asymptotic_given_mu(nu, mu: float, gamma: float, order: int, bracket: Bracket, why: str) -> FlatPunchSolution:
    """The law's c for given mu; error of c from the bracket, of P* its bound plus its change over the bracket."""
    ratio = 1.0 + (correction_ratio(bracket.c) * gamma**2 if order == 2 else 0.0)
    values = [(float(compliance_adhesive(gamma)), 0.0) if c > 0.999 else  # P* <= P0* (B4), P* increases with c
              law_compliance(c, gamma, order, float(mu_over_gamma(c)) if c > 0.0 else mu / (gamma * ratio))
              for c in (bracket.c, bracket.lo, bracket.hi)]
    compliance, bound_p = values[0]
    error_p = bound_p + max(abs(v[0] - compliance) for v in values[1:])
    error_c = max(bracket.hi - bracket.c, bracket.c - bracket.lo)
    return FlatPunchSolution(nu, gamma, mu, bracket.c, compliance, max(error_c, error_p),
                             route_text(order, bracket.bound, bound_p,
                                               f"so {bracket.lo:.6g} <= c <= {bracket.hi:.6g}; {why}"),
                             _graded_breakpoints(bracket.c),
                             FirstOrderField(bracket.c, mu))


def _meets(sol: FlatPunchSolution, rtol: float, value: float) -> bool:
    return sol.error <= rtol * value


# ---------------------------------------------------------------------------------------
# The solver route


class _AboveTop(Exception):
    """mu exceeds mu_c at the search's largest stick radius."""


def _invert_coarse(mu: float, gamma: float, level: int, c_guess: float, top_c: float) -> tuple[FlatField, float]:
    """Stick radius with mu_c(c) = mu at one level by Brent in s = logit(c) on log mu, c <= top_c.

    Returns the solution and d(log mu)/ds at the root (from the two nearest evaluations)."""
    evaluations: dict[float, FlatField] = {}
    top = logit(top_c)

    def g(s: float) -> float:
        c = min(expit(s), top_c)
        try:
            field = solve_mu(c, gamma, LEVELS[level], mu_guess=mu)
        except NoEigenvalueError:
            return math.inf  # beyond the largest stick radius: mu is unbounded there
        evaluations[s] = field
        return math.log(field.mu) - math.log(mu)

    step = 0.05
    s0 = min(logit(c_guess), top - step)
    lo, hi = s0 - step, s0 + step
    g_lo, g_hi = g(lo), g(hi)
    while g_lo > 0.0:
        lo, hi, g_hi = lo - 2 * step, lo, g_lo
        step *= 2
        g_lo = g(lo)
        if lo < -40:
            raise NoEigenvalueError(f"no stick radius above 1e-17 for mu = {mu}, gamma = {gamma:.6g}")
    while g_hi < 0.0:
        if hi >= top:
            raise _AboveTop()
        lo, g_lo, hi = hi, g_hi, min(hi + 2 * step, top)
        step *= 2
        g_hi = g(hi)
    root = optimize.brentq(g, lo, hi, xtol=1e-11)
    field = evaluations.get(root) or solve_mu(expit(root), gamma, LEVELS[level], mu_guess=mu)
    # slope from the nearest evaluation at a different c (s beyond top_c is clamped to it)
    near = min((s for s in evaluations if evaluations[s].c != field.c), key=lambda s: abs(s - root))
    slope = (math.log(evaluations[near].mu) - math.log(field.mu)) / (logit(evaluations[near].c) - logit(field.c))
    return field, slope


def _table_start(mu: float, gamma: float) -> tuple[float, float] | None:
    """c from the Chebyshev table and d(log mu)/d(logit c) there, or None outside its domain."""
    if not table_available():
        return None
    c = float(table_stick_radius(mu, gamma))
    if math.isnan(c):
        return None
    s = logit(c)
    pair = table_friction_coefficient(expit(np.array([s - 1e-4, s + 1e-4])), np.array(gamma))
    if np.any(np.isnan(pair)):
        return None
    return c, float(np.log(pair[1] / pair[0]) / 2e-4)


def _invert(mu: float, gamma: float, level: int, c_guess: float) -> tuple[FlatField, float]:
    """The fine solution with mu_c(c) = mu and the error of its c.

    The start is the Chebyshev table's c (``numeric.core.table``) or, outside the table,
    Brent on the coarse level from ``c_guess`` (the asymptotic law), up to ``_c_search_top``.
    Then secant steps in logit(c) on the fine level until the
    fine mu matches to 1e-11 relative (usually 1-2 solves, the start being that close), c
    stops moving in double precision (near c = 1), or 8 steps are spent: at very small c,
    mu(c) at fixed resolution jitters by ~1e-10 relative (measured at c = 4e-5). The best
    iterate is returned; the error of c adds its remaining mismatch in mu to the coarse
    level's mismatch (or the coarse c's distance), both converted to c by the slope.
    """
    top_c = _c_search_top(gamma)
    start = _table_start(mu, gamma)
    coarse = None
    if start is None:
        coarse, slope = _invert_coarse(mu, gamma, level - 1, min(c_guess, top_c), top_c)
        c_start = coarse.c
    else:
        c_start, slope = start
    s_old, field = logit(c_start), solve_mu(c_start, gamma, LEVELS[level], mu_guess=mu)
    g_old = math.log(field.mu) - math.log(mu)
    best, g_best = field, g_old
    for _ in range(8):
        if abs(g_old) < 1e-11:
            break
        step = -g_old / slope
        while True:
            s_new = s_old + step
            try:
                if expit(s_new) > top_c:
                    if solve_mu(top_c, gamma, LEVELS[level], mu_guess=mu).mu < mu:
                        raise _AboveTop()  # mu increases with c: the stick radius is above top_c
                    raise NoEigenvalueError("step beyond the search's largest stick radius")
                new = solve_mu(expit(s_new), gamma, LEVELS[level], mu_guess=mu)
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


def _check_rtol(rtol) -> float:
    value = float(rtol)
    if not (math.isfinite(value) and value > 0.0):
        raise ValueError(f"rtol must be a positive finite number, got {rtol!r}")
    return value


def _check_level(level) -> int:
    try:
        ok = 1 <= int(level) < len(LEVELS) and int(level) == level
    except (TypeError, ValueError, OverflowError):
        ok = False
    if not ok:
        raise ValueError(f"level must be an integer in [1, {len(LEVELS) - 1}], got {level!r}")
    return int(level)


def _level_and_rtol(level, rtol) -> tuple[int, float | None]:
    if level is not None and rtol is not None:
        raise ValueError("give level or rtol, not both (rtol chooses the route and the level)")
    return (DEFAULT_LEVEL if level is None else _check_level(level)), (None if rtol is None else _check_rtol(rtol))


def flat_punch(
    nu: float | None = None,
    mu: float | None = None,
    c: float | None = None,
    *,
    gamma: float | None = None,
    level: int | None = None,
    rtol: float | None = None,
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
    level : int, optional
        Resolution level 1..4 of ``numeric.core.mesh.LEVELS`` (the next coarser one gives
        the error estimate); 2 (the default) reaches ~1e-10. Not together with ``rtol``.
    rtol : float, optional
        Relative accuracy wanted in the returned c (given mu) or mu (given c): the cheapest
        route whose error meets ``error <= rtol * value`` is taken. A closed form in the
        limits; else the asymptotic law for c <= 0.9 (first order (2.28) where its measured
        bound K2(gamma) gamma^2 meets rtol, else second order (2.28) + gamma^2 f2 where
        K4(gamma) gamma^4 does; ``numeric.solutions.law.K2_BOUNDS``, ``K4_BOUNDS``); else the solver at the first
        level whose typical accuracy meets rtol (1: 1e-8, 2: 1e-10, 3: 1e-12, else 4), and
        finer levels while its ``error`` exceeds ``rtol * value``. If no route meets rtol,
        the most accurate result is returned with an ``AccuracyWarning``.

    Returns
    -------
    FlatPunchSolution
        ``route`` names the route. On the asymptotic route ``error`` is the measured bound of
        the law (mu, P*; for given mu the c range it implies), the stresses are the
        first-order fields p^(0) (2.26) and q = mu p^(0) (1 - psi) (2.31) with relative error
        O(gamma^2), and ``slip`` raises NotImplementedError.

    Raises
    ------
    NoEigenvalueError
        If c exceeds the largest stick radius, estimated as c_max = 1 - 8 exp(-pi/kappa),
        kappa = (2/pi) atanh(gamma) (large gamma): at once above 1 - 7.5 exp(-pi/kappa), and
        wherever the solver fails within 16 exp(-pi/kappa) of 1.
    SolverError
        If even level 1 does not converge. A level is not tried below the smallest c it
        reaches (``LEVEL_C_MIN``: 5e-6, 5e-5, 5e-4, 1e-2); the next coarser one is used and
        ``route`` says so. Below c = 1e-5 (``C_ASYMPTOTIC``; given mu: where the asymptotic
        law puts c there) the asymptotic route (second order) is taken.

    Notes
    -----
    Given mu, c lies below c_max for every finite mu, but mu(c) ~ 1/(c_max - c): the search
    stops at c_top = 1 - 10 exp(-pi/kappa) (or 1 - 1e-9 where that is larger, small gamma). For
    mu > mu(c_top) the result is a bracket: c = the midpoint of (c_top, min(1, 1 - 7.5
    exp(-pi/kappa))], P* the midpoint of (P*(c_top), P*_adhesive (B4)], the half-widths as
    ``error``; the stresses are those of the adhesive solution (App. B) at small gamma and of
    the solution at c_top otherwise, as ``route`` says.

    Examples
    --------
    >>> s = flat_punch(nu=0.0, c=0.5)
    >>> round(s.mu, 10), round(s.compliance, 10), s.error < 1e-9
    (0.298714616, 1.0522119983, True)
    >>> flat_punch(nu=0.25, mu=1e-4).route.startswith("asymptotic, second order")   # c ~ 1e-130
    True
    """
    g = resolve_gamma(nu, gamma)
    nu_value = None if nu is None else float(check_nu(nu))
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick radius)")
    level_value, rtol_value = _level_and_rtol(level, rtol)
    if c is not None:
        c_value = float(check_c(c))
        if c_value == 1.0:
            return _closed_form(nu_value, g, math.inf, 1.0, True, "adhesive, App. B")
        if g == 0.0:
            return _closed_form(nu_value, g, 0.0, c_value, False, "gamma = 0: no coupling, mu = 0 (2.28)")
        if c_value > 1.0 - C_MAX_UPPER_COEFFICIENT * _gap_scale(g):
            raise _no_eigenvalue(c_value, g)
        return _given_c(nu_value, c_value, g, level_value, rtol_value)
    mu_value = float(check_mu(mu))
    if mu_value == 0.0:
        return _closed_form(nu_value, g, 0.0, 0.0, False, "frictionless, (2.26)")
    if mu_value == math.inf:
        return _closed_form(nu_value, g, math.inf, 1.0, True, "adhesive, App. B")
    if g == 0.0:
        return _closed_form(nu_value, g, mu_value, 1.0, False, "gamma = 0: no coupling, no slip")
    return _given_mu(nu_value, mu_value, g, level_value, rtol_value)


def _cheap_asymptotic(nu, gamma: float, rtol: float, *, c: float | None = None, mu: float | None = None,
                      bracket: Bracket | None = None) -> FlatPunchSolution | None:
    """The lowest-order asymptotic solution meeting rtol (c <= ASYMPTOTIC_C_MAX), or None."""
    for order in (0, 2):
        if c is not None:
            if c > ASYMPTOTIC_C_MAX or law_bound(c, gamma, order) > rtol:
                continue
            sol = _asymptotic_given_c(nu, c, gamma, order, f"meets rtol = {rtol:g}")
            if _meets(sol, rtol, sol.mu):
                return sol
        else:
            if min(law_bound(0.0, gamma, order), law_bound(0.5, gamma, order)) > 4.0 * rtol:
                continue  # c's relative error is mu's over d log mu/d log c (2.7 at c = 0.9 for f0): cannot meet rtol
            b = bracket if order == 2 and bracket is not None else law_bracket(mu, gamma, order)
            if b.hi > ASYMPTOTIC_C_MAX or b.c == 0.0:
                continue
            if max(b.hi - b.c, b.c - b.lo) > rtol * b.c:
                continue
            sol = _asymptotic_given_mu(nu, mu, gamma, order, b, f"meets rtol = {rtol:g}")
            if _meets(sol, rtol, sol.c):
                return sol
    return None


def _warn_unmet(sol: FlatPunchSolution, rtol: float, value: float) -> None:
    warnings.warn(AccuracyWarning(
        f"rtol = {rtol:g} not met: the best route available ({sol.route}) has error {sol.error:.3g}, "
        f"{sol.error / value if value > 0 else math.inf:.3g} relative"), stacklevel=3)


def _given_c(nu, c: float, gamma: float, level: int, rtol: float | None) -> FlatPunchSolution:
    if rtol is not None:
        sol = _cheap_asymptotic(nu, gamma, rtol, c=c)
        if sol is not None:
            return sol
    if c < C_ASYMPTOTIC:
        sol = _asymptotic_given_c(nu, c, gamma, 2, f"c < {C_ASYMPTOTIC:g}, below the solver's reach")
        if rtol is not None and not _meets(sol, rtol, sol.mu):
            _warn_unmet(sol, rtol, sol.mu)
        return sol
    return _by_level(lambda lv: _solve_given_c(nu, c, gamma, lv), c, level, rtol, lambda s: s.mu)


def _given_mu(nu, mu: float, gamma: float, level: int, rtol: float | None) -> FlatPunchSolution:
    bracket = law_bracket(mu, gamma, 2)
    if rtol is not None:
        sol = _cheap_asymptotic(nu, gamma, rtol, mu=mu, bracket=bracket)
        if sol is not None:
            return sol
    if bracket.c < C_ASYMPTOTIC:
        sol = _asymptotic_given_mu(nu, mu, gamma, 2, bracket,
                                   f"the law's c < {C_ASYMPTOTIC:g}, below the solver's reach")
        if rtol is not None and not (_meets(sol, rtol, sol.c) or (sol.c == 0.0 and bracket.hi == 0.0)):
            _warn_unmet(sol, rtol, sol.c)
        return sol
    try:
        return _by_level(lambda lv: _solve_given_mu(nu, mu, gamma, lv, bracket.c), bracket.lo, level, rtol,
                         lambda s: s.c)
    except SolverError:
        if bracket.lo >= LEVEL_C_MIN[1]:
            raise
        # the law's c is above C_ASYMPTOTIC but the true one below the solver's reach
        sol = _asymptotic_given_mu(nu, mu, gamma, 2, bracket, "the solver did not converge at this small c")
        if rtol is not None and not _meets(sol, rtol, sol.c):
            _warn_unmet(sol, rtol, sol.c)
        return sol


def _by_level(solve, c_low: float, level: int, rtol: float | None, value) -> FlatPunchSolution:
    """The solver at ``level`` (no rtol) or at the levels rtol asks for, never below a level's
    floor ``LEVEL_C_MIN`` (``c_low``: the stick radius, or a lower bound of it)."""
    top = max([lv for lv in LEVEL_C_MIN if LEVEL_C_MIN[lv] <= c_low] + [1])
    if rtol is None:
        sol = _with_fallback(solve, min(level, top))
        if top < level:
            sol = replace(sol, route=f"{sol.route} (level {level} does not reach c < {LEVEL_C_MIN[level]:g})")
        return sol
    start = next((lv for lv, e in LEVEL_TYPICAL_ERROR.items() if e <= rtol), 4)
    best = None
    for lv in range(min(start, top), top + 1):
        sol = _with_fallback(solve, lv)
        if best is None or sol.error < best.error:
            best = sol
        if _meets(sol, rtol, value(sol)):
            return sol
    if top < 4:
        best = replace(best, route=f"{best.route} (level {top + 1} does not reach c < {LEVEL_C_MIN[top + 1]:g})")
    _warn_unmet(best, rtol, value(best))
    return best


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
    try:
        fields = [solve_mu(c, gamma, LEVELS[lv], mu_guess=guess) for lv in (level, level - 1)]
        if fields[0].mu * gamma > 1.0 and level >= 2:  # alpha > 1/4: convergence can stall, look one level further
            fields.append(solve_mu(c, gamma, LEVELS[level - 2], mu_guess=guess))
    except (SolverError, NoEigenvalueError) as exc:
        if c > 1.0 - 2.0 * C_MAX_COEFFICIENT * _gap_scale(gamma):  # within twice 1 - c_max of 1
            raise _no_eigenvalue(c, gamma, f"; the solver: {exc}") from None
        raise
    return _from_field(nu, fields[0], level, _error_estimate(fields))


def _solve_given_mu(nu, mu: float, gamma: float, level: int, c_guess: float) -> FlatPunchSolution:
    try:
        fine, error = _invert(mu, gamma, level, c_guess)
    except _AboveTop:
        return _near_full_stick(nu, gamma, mu, level)
    return _from_field(nu, fine, level, error)


def _near_full_stick(nu, gamma: float, mu: float, level: int) -> FlatPunchSolution:
    """mu > mu_c(c_top), c_top = ``_c_search_top``: by monotonicity in mu (c and P* increase, §2.1),
    c_top < c <= c_hi and P*(c_top) < P* <= P0*, c_hi = 1 at small gamma (c_top = 1 - 1e-9), else
    1 - 7.5 exp(-pi/kappa) (above c_max); return the midpoints with half-widths (plus the solver's
    error at c_top) as the error. Stresses: the adhesive closed form (App. B) at small gamma (exact
    outside the slip annulus of width < 1e-9 only in the limit), else the solution at c_top."""
    top_c = _c_search_top(gamma)
    edge = solve_mu(top_c, gamma, LEVELS[level], mu_guess=mu)
    edge_coarse = solve_mu(top_c, gamma, LEVELS[level - 1], mu_guess=mu)
    if edge.mu > mu:  # the coarse search overshot: not in the near-full-stick regime after all
        raise SolverError(f"stick radius for mu = {mu}, gamma = {gamma:.6g} not bracketed below {top_c}")
    adhesive = float(compliance_adhesive(gamma))
    solver_error = abs(edge.compliance - edge_coarse.compliance)
    c_hi = min(1.0, 1.0 - C_MAX_UPPER_COEFFICIENT * _gap_scale(gamma))
    small_gamma = top_c == C_TOP
    if small_gamma:
        what, field, breakpoints = "adhesive stresses (App. B)", _ClosedForm(gamma, True), ADHESIVE_EDGE_BREAKPOINTS
    else:
        what = f"c_max ~ 1 - 8 exp(-pi/kappa); stresses of the solution at c = {top_c:.6g} (mu = {edge.mu:.6g})"
        field, breakpoints = edge, edge.breakpoints
    return FlatPunchSolution(
        nu=nu,
        gamma=gamma,
        mu=mu,
        c=0.5 * (top_c + c_hi),
        compliance=0.5 * (adhesive + edge.compliance),
        error=max(0.5 * (c_hi - top_c), 0.5 * abs(adhesive - edge.compliance) + solver_error),
        route=f"bracketed: mu > mu_c({top_c:.12g}) = {edge.mu:.6g}, so {top_c:.12g} < c <= {c_hi:.12g}; {what}",
        breakpoints=breakpoints,
        _field=field,
    )


class Executor(Protocol):
    """What a sweep can be handed to: ``concurrent.futures`` executors (threads or
    processes) and ``dask.distributed.Client.get_executor()`` all provide this ``map``."""

    def map(self, fn: Callable, *iterables: Iterable) -> Iterable: ...


def _solved_c(mu: float, nu: float, level: int | None, rtol: float | None) -> float:
    return flat_punch(nu=nu, mu=mu, level=level, rtol=rtol).c


def _solved_mu(c: float, nu: float, level: int | None, rtol: float | None) -> float:
    return flat_punch(nu=nu, c=c, level=level, rtol=rtol).mu


def _report(name: str, done: int, total: int, started: float) -> None:
    rate = done / max(time.perf_counter() - started, 1e-9)
    end = "\n" if done == total else ""
    sys.stderr.write(f"\r{name}: {done}/{total} points solved, {rate:.3g} points/s{end}")
    sys.stderr.flush()


def _table_meets(kind: str, values: np.ndarray, rtol: float) -> np.ndarray:
    """Where the table's value meets rtol: mu to TABLE_MU_RTOL; c to TABLE_MU_RTOL over d log mu/d log c,
    which is at least the first-order slope d log f0/d log c (f2/f0 and f4/f0 increase with c, measured)."""
    ok = ~np.isnan(values)
    if kind == "mu":
        return ok & (TABLE_MU_RTOL <= rtol)
    slope = np.ones(values.shape)
    slope[ok] = mu_over_gamma_log_slope(values[ok])
    return ok & (TABLE_MU_RTOL / slope <= rtol)


def _sweep(name: str, kind: str, table, solve, first: ArrayLike, nu: ArrayLike, use_table: bool, level: int | None,
           rtol: float | None, executor: Executor | None, progress: bool) -> np.ndarray | float:
    """Evaluate ``table`` on all points at once; solve the points outside its domain, one by
    one or through ``executor``, reporting progress on stderr when asked. With ``rtol``, points
    where the asymptotic law meets it take that first, and the table only where it meets rtol."""
    a, n = np.broadcast_arrays(np.asarray(first, dtype=float), np.asarray(nu, dtype=float))
    shape = a.shape
    a, n = a.ravel(), n.ravel()
    g = np.asarray(gamma_from_nu(n), dtype=float)
    out = np.full(a.shape, np.nan)
    if rtol is not None:
        for i in range(a.size):
            if 0.0 < a[i] < (1.0 if kind == "mu" else math.inf) and g[i] > 0.0:
                given = {"c": a[i]} if kind == "mu" else {"mu": a[i]}
                sol = _cheap_asymptotic(None, float(g[i]), rtol, **given)
                if sol is not None:
                    out[i] = getattr(sol, kind)
    rest = np.isnan(out)
    if use_table and table_available() and np.any(rest):
        values = np.array(table(a[rest], g[rest]), dtype=float)
        if rtol is not None:
            values = np.where(_table_meets(kind, values, rtol), values, np.nan)
        out[rest] = values
    missing = np.flatnonzero(np.isnan(out))
    if missing.size:
        args = (a[missing], n[missing], [level] * missing.size, [rtol] * missing.size)
        results = executor.map(solve, *args) if executor is not None else map(solve, *args)
        started = time.perf_counter()
        for k, (index, value) in enumerate(zip(missing, results), 1):
            out[index] = value
            if progress:
                _report(name, k, missing.size, started)
    out = out.reshape(shape)
    return float(out) if out.ndim == 0 else out


def stick_radius(mu: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int | None = None,
                 rtol: float | None = None, executor: Executor | None = None,
                 progress: bool = False) -> np.ndarray | float:
    """Stick radius c(mu, nu) of [S75] §2.2, broadcasting over arrays.

    Inside the table's domain (``numeric.core.table``: 1e-3 <= c <= 0.95, nu >= -1/2) c
    comes from the Chebyshev table of the eigenvalue relation (microseconds a point, error
    ``numeric.core.table_data.MU_RELATIVE_ERROR`` in mu); elsewhere, or with
    ``use_table=False``, from ``flat_punch`` at ``level``: one by one, or mapped over
    ``executor`` (any ``concurrent.futures`` executor, or a Dask client's ``get_executor()``),
    with a progress line on stderr when ``progress`` is true.

    With ``rtol`` (not together with ``level``) the cheapest route meeting it for each point:
    the asymptotic law (see ``flat_punch``), else the table where its error (``TABLE_MU_RTOL``
    in mu, over d log mu/d log c in c) meets rtol, else ``flat_punch(rtol=rtol)``. An
    ``AccuracyWarning`` from points solved through ``executor`` is raised in the workers.

    Examples
    --------
    >>> round(float(stick_radius(0.298714615962, 0.0)), 9)
    0.5
    """
    check_mu(mu)
    check_nu(nu)
    _level_and_rtol(level, rtol)
    return _sweep("stick_radius", "c", table_stick_radius, _solved_c, mu, nu, use_table, level,
                  None if rtol is None else _check_rtol(rtol), executor, progress)


def friction_coefficient(c: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int | None = None,
                         rtol: float | None = None, executor: Executor | None = None,
                         progress: bool = False) -> np.ndarray | float:
    """Friction coefficient mu(c, nu) that produces stick radius c, broadcasting over arrays.

    From the Chebyshev table inside its domain, else from ``flat_punch`` (see ``stick_radius``,
    also for ``rtol``).
    """
    check_c(c)
    check_nu(nu)
    _level_and_rtol(level, rtol)
    return _sweep("friction_coefficient", "mu", table_friction_coefficient, _solved_mu, c, nu, use_table, level,
                  None if rtol is None else _check_rtol(rtol), executor, progress)
