"""The solver route of ``numeric.flat_punch``: the singular-basis solver of ``numeric.core`` at its levels.

Each level is a ``numeric.core.charts.Resolution`` (``RESOLUTIONS``); ``error`` is the
difference between the level and the same problem one polynomial degree lower
(``numeric.core.charts.partner``), at least ``ERROR_FLOOR`` times the value (the rounding
level of the eigenvalue condition). Measured against level 4 (``tests/test_singular_solver.py``,
``derivations/benchmark.md``) the true error lies below this estimate and within a factor 10
of it.

Given c: Newton in theta = atan(mu gamma) from a guess (the Chebyshev table, else the
second-order law). Given mu: the secant method in logit(c) from a guess (the table, else the
law, or the largest stick radius when the law's c exceeds it); no bracket is needed near full
stick, where mu -> inf is the regular limit theta -> pi/2. Below ``C_ASYMPTOTIC`` the solver is
not offered (the law is the answer, ``numeric.solutions.law``). Given mu, where the law puts
1 - c below ``GAP_ADHESIVE`` (mu of order gamma log(1/gap)/pi at small gamma) the slip annulus
is thinner than 1e-13 of the radius and P* and the stresses at 1 - x > 1e-12 differ from the
adhesive ones by less than the level's error (measured: P* - P*_adhesive ~ 0.3 gap^0.87): the
result is the adhesive solution (App. B) with that c, and ``route`` says so.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.special import logit

from asymptotics.adhesive import compliance_adhesive
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.first_order import mu_over_gamma
from asymptotics.second_order import C_MAX, correction_ratio, stick_radius_second_order

from numeric.core.charts import RESOLUTIONS, Resolution, partner
from numeric.core.eigenvalue import solve_given_c as core_given_c
from numeric.core.eigenvalue import solve_given_theta
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.fields import SingularField
from numeric.core.table import table_available, table_friction_coefficient, table_stick_radius
from numeric.solutions.limits import ADHESIVE_EDGE_BREAKPOINTS, ClosedForm, no_eigenvalue
from numeric.solutions.solution import FlatPunchSolution, Offer, warn_unmet

__all__ = ["DEFAULT_LEVEL", "C_ASYMPTOTIC", "GAP_ADHESIVE", "LAW_MU_GAMMA_MAX", "ERROR_FLOOR", "LEVEL_TYPICAL_ERROR", "LEVEL_SECONDS",
           "SolverRoute", "solve_given_c", "solve_given_mu", "from_field"]

DEFAULT_LEVEL = 2
#: Below this stick radius the asymptotic law replaces the solver (the layout needs ~40 elements at 1e-5).
C_ASYMPTOTIC = 1e-5
#: Given mu, below this 1 - c the answer is the adhesive solution with the law's c (see the module docstring).
GAP_ADHESIVE = 1e-13
#: Above this mu gamma the law is not consulted for a guess (it overflows; c is near c_max or 1 anyway).
LAW_MU_GAMMA_MAX = 1e6
#: Relative floor of the error estimate: below it two levels agree only to rounding and to the Abel
#: rules' 1e-13 (measured: levels 3 and 4 differ by up to 6e-13 relative where both converged).
ERROR_FLOOR = 2e-13
#: Typical relative accuracy of each level (the worst measured, ``RESOLUTIONS``); rtol picks the first that meets it.
LEVEL_TYPICAL_ERROR = {0: 1e-8, 1: 1e-9, 2: 1e-11, 3: 1e-12, 4: 1e-13}
#: Rough run time in seconds of a solve with its error estimate (derivations/benchmark.md), for ordering routes.
LEVEL_SECONDS = {0: 0.008, 1: 0.010, 2: 0.016, 3: 0.025, 4: 0.04}


def from_field(nu: float | None, field: SingularField, level: int, error: float, mu: float | None = None
               ) -> FlatPunchSolution:
    """The solver's solution as a ``FlatPunchSolution`` (``mu``: the friction asked for, given mu)."""
    return FlatPunchSolution(
        nu=nu,
        gamma=field.gamma,
        mu=field.mu if mu is None else mu,
        c=field.c,
        compliance=field.compliance,
        error=error,
        route=f"solver level {level}, {field.n_unknowns} unknowns",
        breakpoints=field.breakpoints,
        _field=field,
    )


def _theta_guess(c: float, gamma: float) -> float:
    """atan(mu gamma) from the table (7e-12); else the second-order law (its gamma^2 f2/f0 held at c = 0.999
    above), or, within 50 (1 - c_max) of c_max, the approach mu gamma ~ 1.3 (1 - c_max)/(c_max - c)
    (``numeric.solutions.slip_limit``: A/(1 - c_max) = 1.19 ... 1.52 for gamma = 0.75 ... 0.3)."""
    mu = float(np.ravel(table_friction_coefficient(np.array([c]), np.array([gamma])))[0]) if table_available() else math.nan
    if not math.isnan(mu):
        return math.atan(mu * gamma)
    gap, gap_max = 1.0 - c, float(largest_stick_radius_gap(gamma))
    if gap < 50.0 * gap_max:
        return math.atan(1.3 * gap_max / (gap - gap_max))
    ratio = correction_ratio(min(c, C_MAX))
    return math.atan(gamma * gamma * float(mu_over_gamma(c)) * (1.0 + ratio * gamma**2))


def _logit_guess(mu: float, gamma: float) -> float:
    """logit(c) from the table, else the second-order law, kept below the largest stick radius."""
    c = float(np.ravel(table_stick_radius(np.array([mu]), np.array([gamma])))[0]) if table_available() else math.nan
    if not 0.0 < c < 1.0 and mu * gamma < LAW_MU_GAMMA_MAX:
        c = float(stick_radius_second_order(mu, gamma=gamma))
    if not 0.0 < c < 1.0:
        c = 1.0
    gap_max = float(largest_stick_radius_gap(gamma))
    gap = max(1.0 - c, 1.5 * gap_max, 1e-300)
    if c <= 0.0:
        c = C_ASYMPTOTIC
    return math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)


def _error(fine: SingularField, coarse: SingularField, value: Callable[[SingularField], float]) -> float:
    scale = max(abs(value(fine)), abs(fine.compliance))
    return max(abs(value(fine) - value(coarse)), abs(fine.compliance - coarse.compliance), ERROR_FLOOR * scale)


def solve_given_c(nu: float | None, c: float, gamma: float, level: int) -> FlatPunchSolution:
    """mu for stick radius c at ``level``; the partner resolution gives the error estimate."""
    gap = 1.0 - c
    if gap <= float(largest_stick_radius_gap(gamma)):
        raise no_eigenvalue(c, gamma)
    res = RESOLUTIONS[level]
    try:
        fine = SingularField(core_given_c(c, gap, gamma, _theta_guess(c, gamma), res))
    except (SolverError, NoEigenvalueError):
        fine = SingularField(core_given_c(c, gap, gamma, _theta_near_c_max(gap, gamma, res), res))
    coarse = SingularField(core_given_c(c, gap, gamma, fine.theta, partner(res)))
    return from_field(nu, fine, level, _error(fine, coarse, lambda f: f.mu))


def _theta_near_c_max(gap: float, gamma: float, res: Resolution, tol: float = 1e-6) -> float:
    """theta for 1 - c = gap by the secant method in eps = cot(theta) = 1/(mu gamma) on the given-theta
    solver: 1 - c is smooth in eps down to eps = 0 (c_max), where G(theta) at fixed c is not (poles of the
    discrete system lie near pi/2). From eps = (gap - gap_max)/(1.3 gap_max), the approach; to tol relative."""
    gap_max = float(largest_stick_radius_gap(gamma))
    start = math.log1p(-gap) - math.log(gap)

    def residual(eps: float) -> float:
        field = solve_given_theta(math.atan2(1.0, eps), gamma, start, res)
        return math.log(field.layout.gap) - math.log(gap)

    e0 = max((gap - gap_max) / (1.3 * gap_max), 1e-12)
    e1 = 1.1 * e0
    r0, r1 = residual(e0), residual(e1)
    for _ in range(30):
        if r1 == r0:
            break
        e0, e1 = e1, max(e1 - r1 * (e1 - e0) / (r1 - r0), 0.5 * e1)
        r0, r1 = r1, residual(e1)
        if abs(e1 - e0) <= tol * e1:
            break
    return math.atan2(1.0, e1)


def solve_given_mu(nu: float | None, mu: float, gamma: float, level: int, c_guess: float | None = None
                   ) -> FlatPunchSolution:
    """The stick radius for friction mu at ``level`` (secant in logit c at theta = atan(mu gamma))."""
    theta = math.atan(mu * gamma)
    start = _logit_guess(mu, gamma) if c_guess is None else float(logit(c_guess))
    res: Resolution = RESOLUTIONS[level]
    fine = SingularField(solve_given_theta(theta, gamma, start, res))
    coarse = SingularField(solve_given_theta(theta, gamma, math.log(fine.c) - math.log(fine.layout.gap), partner(res)))
    return from_field(nu, fine, level, _error(fine, coarse, lambda f: f.c), mu)


def nearly_adhesive(nu: float | None, gamma: float, mu: float, gap: float) -> FlatPunchSolution:
    """mu so large for this gamma that 1 - c < GAP_ADHESIVE: the adhesive solution with c = 1 - gap."""
    adhesive = float(compliance_adhesive(gamma))
    return FlatPunchSolution(
        nu=nu, gamma=gamma, mu=mu, c=1.0 - gap, compliance=adhesive,
        error=max(gap, 0.3 * gap**0.87),
        route=f"adhesive stresses (App. B): the law puts 1 - c = {gap:.3g} < {GAP_ADHESIVE:g}, below what the "
              "stresses resolve",
        breakpoints=ADHESIVE_EDGE_BREAKPOINTS, _field=ClosedForm(gamma, True))


class SolverRoute:
    """The solver for one problem (exactly one of c and mu given) at its levels.

    ``reaches`` is false where the stick radius (or, given mu, the law's estimate of it) is
    below ``C_ASYMPTOTIC``. ``offers(rtol)`` are the levels whose typical accuracy meets rtol,
    ``best_effort`` the most accurate result run (or level 4) when none did, and
    ``at_level(level)`` the result without rtol.
    """

    def __init__(self, nu: float | None, gamma: float, c: float | None, mu: float | None, c_estimate: float,
                 gap_estimate: float = 1.0):
        self.reaches = c_estimate >= C_ASYMPTOTIC
        self.top = len(RESOLUTIONS) - 1
        self._value: Callable[[FlatPunchSolution], float]
        if c is not None:
            self._solve = lambda level: solve_given_c(nu, c, gamma, level)
            self._value = lambda sol: sol.mu
        elif gap_estimate < GAP_ADHESIVE:
            self._solve = lambda level: nearly_adhesive(nu, gamma, mu, gap_estimate)
            self._value = lambda sol: sol.c
        else:
            self._solve = lambda level: solve_given_mu(nu, mu, gamma, level)
            self._value = lambda sol: sol.c
        self._results: list[FlatPunchSolution] = []

    def at_level(self, level: int) -> FlatPunchSolution:
        """The solution at ``level`` (no rtol)."""
        return self._solve(level)

    def _start(self, rtol: float) -> int:
        return next((lv for lv, e in LEVEL_TYPICAL_ERROR.items() if e <= rtol), self.top)

    def offers(self, rtol: float) -> list[Offer]:
        """One offer per level from the first whose typical accuracy meets rtol to the finest."""
        return [Offer(LEVEL_SECONDS[lv], lambda: True, lambda lv=lv: self._run(lv))
                for lv in range(self._start(rtol), self.top + 1)]

    def _run(self, level: int) -> FlatPunchSolution:
        sol = self._solve(level)
        self._results.append(sol)
        return sol

    def best_effort(self, rtol: float) -> FlatPunchSolution:
        """The most accurate level run (the finest, if rtol asked for more), with an ``AccuracyWarning``."""
        if not self._results:
            self._run(self.top)
        best = min(self._results, key=lambda sol: sol.error)
        warn_unmet(best, rtol, self._value(best))
        return best
