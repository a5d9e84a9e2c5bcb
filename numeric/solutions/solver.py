"""The solver route of ``numeric.flat_punch``: the singular-basis solver of ``numeric.core`` at its levels.

Each level is a ``numeric.core.charts.Resolution`` (``RESOLUTIONS``); ``error`` is twice the difference between
the level and the same problem at the next level up (levels 0-3; level 4: the difference from the partner one
polynomial degree lower, ``numeric.core.charts.partner``; ``estimate_resolution``, ``ESTIMATE_SAFETY``), at least
``ERROR_FLOOR`` times the value (the rounding level of the eigenvalue condition, flat in c down to c = 1e-5 since the
rows of (2.2a) are differenced and the solves refined, ``numeric.core.operators.collocation_system``), given c at
least theta's rounding scatter in mu (``THETA_FLOOR``: next to c_max, where mu gamma = tan theta is large, it
decides) and, given c within 1e-6 (1 - c_max) of c_max, at least the shift of mu from the level's c_max
(``NEAR_C_MAX``; within rounding of c_max the answer is the slip limit, mu = inf). Where the next level's error is
at most half the level's, the estimate lies between 1 and 3 times the true error. Measured against level 4 over 72
(nu, c) (``ESTIMATE_SAFETY``: 1 - c from 1.001 to 100 (1 - c_max), nu from -1/2 to 0.4, and c = 0.1, 0.5, 0.9): the
default level's estimate 1.0 ... 3.14 times its true error (or the rounding floor), never below it; the partner one
degree lower had been up to 829 times pessimistic there. Levels 2, 3 and 4 against degree 21 over 79 such (nu, c):
never below, 1.0 ... 2.06 times the larger of the true error and the stated floor. The estimate is a second solve, somewhat costlier than the first, so it is formed
when first read (``numeric.solutions.solution.DeferredError``), or at once where rtol asks for it.

Given c: Newton in theta = atan(mu gamma) from a guess (the Chebyshev table, else the
second-order law). Given mu: where the table reaches, given-c solves from its c, stepped in
logit(c) by (theta - theta(c)) over its slope d theta / d logit c (one or two solves: the table's
c is good to 1e-13 ... 1e-9, and a step from it lands within rounding); elsewhere the secant method in logit(c)
from the law's guess (or the largest stick radius when the law's c exceeds it); no bracket is
needed near full stick, where mu -> inf is the regular limit theta -> pi/2. Below ``C_ASYMPTOTIC`` the solver is
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
from dataclasses import replace

import numpy as np

from asymptotics.adhesive import compliance_adhesive
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.first_order import mu_over_gamma
from asymptotics.second_order import C_MAX, correction_ratio, stick_radius_second_order

from numeric.core.charts import RESOLUTIONS, Resolution, partner
from numeric.core.eigenvalue import solve_given_c as core_given_c
from numeric.core.eigenvalue import solve_given_theta, solve_given_theta_guided
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.fields import SingularField
from numeric.core.table import TableValues, table_available, table_friction_coefficient, table_given_mu
from numeric.solutions.limits import ADHESIVE_EDGE_BREAKPOINTS, ClosedForm, closed_form, no_eigenvalue
from numeric.solutions.solution import DeferredError, FlatPunchSolution, Offer, warn_unmet

__all__ = ["DEFAULT_LEVEL", "C_ASYMPTOTIC", "GAP_ADHESIVE", "LAW_MU_GAMMA_MAX", "ERROR_FLOOR", "LEVEL_TYPICAL_ERROR", "LEVEL_SECONDS",
           "ESTIMATE_SAFETY", "FINER_ESTIMATE_BELOW", "THETA_FLOOR", "estimate_resolution", "estimate_safety", "NEAR_C_MAX", "ROUNDING_ULPS", "rounding_floor", "SolverRoute", "solve_given_c", "solve_given_mu", "solve_limit", "from_field",
           "nearly_adhesive"]

DEFAULT_LEVEL = 2
HALF_PI = 0.5 * math.pi
#: Below this stick radius the asymptotic law replaces the solver (the layout needs ~40 elements at 1e-5).
C_ASYMPTOTIC = 1e-5
#: Given mu, below this 1 - c the answer is the adhesive solution with the law's c (see the module docstring).
GAP_ADHESIVE = 1e-13
#: Above this mu gamma the law is not consulted for a guess (it overflows; c is near c_max or 1 anyway).
LAW_MU_GAMMA_MAX = 1e6
#: Relative floor of the error estimate: below it two levels agree only to rounding and to the Abel
#: rules' 1e-13. Measured: at nu = -0.999 ... -0.9, c = 0.9 (mu ~ 2.5) levels 2 and 4 scatter by 3.9e-13 ... 4e-13
#: relative (both converged: degrees 11 ... 19 of the layout scatter likewise), elsewhere below 2e-13.
ERROR_FLOOR = 5e-13
#: Given c with (1 - c) - (1 - c_max) below this fraction of 1 - c_max (or ROUNDING_ULPS units in the last place
#: of c), the level's own c_max (the limit problem, fine and partner) is solved first to tell c from c_max.
NEAR_C_MAX = 1e-6
#: c within this many units in the last place of c_max (or within twice the distance of the level's c_max from
#: the closed form, if larger) is c_max to rounding: the answer is the slip limit, mu = inf.
ROUNDING_ULPS = 4.0
#: Levels below this estimate their error from the next level up (``estimate_resolution``), level 4 (none above it)
#: from the partner one degree lower (``numeric.core.charts.partner``). Level 3 did so too until it was checked
#: against degree 21 (level 4's layout rule): next to c_max its partner's difference fell below its error (1 - c =
#: 1.001 (1 - c_max), nu = 0.35: 5e-13 against 6.9e-12 in mu, the reference's own spread to degree 23 3.4e-13).
FINER_ESTIMATE_BELOW = 4
#: The error estimate of each level is its difference from ``estimate_resolution``'s solve times this factor. From the
#: next level up, twice the difference: where that level's own error is at most half of this one's, the difference lies
#: between half and 1.5 times this level's error, so the estimate between 1 and 3 times it. Measured against level 4
#: (max of mu and P*, above the rounding floor) over 72 (nu, c), nu from -1/2 to 0.4, 1 - c from 1.001 to 100 (1 - c_max)
#: and c = 0.1, 0.5, 0.9: level 0 1.95 ... 2.02 times its true error, level 1 1.0 ... 1.98, level 2 1.0 ... 3.14 (the
#: partner one degree lower had given level 2 1.0 ... 829 there, 829 at nu = 0.3 next to c_max, where its plain degree
#: 10 converges poorly and level 2's own error happens to be small; and level 0 up to 6.4 times short of its error).
ESTIMATE_SAFETY = (2.0, 2.0, 2.0, 2.0, 1.0)
#: Absolute rounding scatter of a given-c solve's theta: mu's error is at least mu THETA_FLOOR / (sin(theta) cos(theta))
#: (mu gamma = tan theta), which next to c_max (mu gamma ~ 1e3) is above ERROR_FLOOR. Measured: the spread of theta
#: over 12 starts (the route's guess and 1e-12 ... 1e-6 relative off it) at levels 0-4, nu in {-1/2, 0, 0.2, 0.3,
#: 0.35, 0.4}, 1 - c = 1.001, 1.003, 1.01, 1.1, 2, 10 (1 - c_max): at most 2.5e-14 at level 1, 7.3e-15, 1.3e-14 and
#: 1.4e-14 at levels 2, 3, 4 (mu relative 1.5e-11 at nu = 0.35, 1.001 (1 - c_max), level 3); 3.6e-13 at level 0, whose
#: difference from level 1 is far larger there.
THETA_FLOOR = 3e-14


def estimate_resolution(level: int) -> Resolution:
    """The resolution whose solve gives the level's error estimate: the next level up below ``FINER_ESTIMATE_BELOW``,
    else the partner one degree lower."""
    return RESOLUTIONS[level + 1] if level < FINER_ESTIMATE_BELOW else partner(RESOLUTIONS[level])


def estimate_safety(level: int) -> float:
    """The factor on the difference from ``estimate_resolution``'s solve at this level (``ESTIMATE_SAFETY``)."""
    return ESTIMATE_SAFETY[level]


#: Typical relative accuracy of each level (the worst measured, ``RESOLUTIONS``); rtol picks the first that meets it.
LEVEL_TYPICAL_ERROR = {0: 1e-7, 1: 1e-9, 2: 1e-11, 3: 1e-12, 4: 1e-13}
#: Rough run time in seconds of a solve with its error estimate (derivations/benchmark.md: a solve and, below
#: ``FINER_ESTIMATE_BELOW``, one at the next level up), for ordering routes.
LEVEL_SECONDS = {0: 0.009, 1: 0.013, 2: 0.021, 3: 0.025, 4: 0.04}


def from_field(nu: float | None, field: SingularField, level: int, error: float | DeferredError,
               mu: float | None = None) -> FlatPunchSolution:
    """The solver's solution as a ``FlatPunchSolution`` (``mu``: the friction asked for, given mu) with its error
    estimate (the level's ``estimate_safety`` times the difference from ``estimate_resolution``'s solve, at least the
    rounding floor)."""
    if mu is not None:  # solved at theta = atan(mu gamma): cos(theta) from mu itself (``SingularField.with_friction``)
        field = field.with_friction(mu)
    return FlatPunchSolution(
        nu=nu,
        gamma=field.gamma,
        mu=field.mu,
        c=field.c,
        compliance=field.compliance,
        _error=error,
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


#: First secant step in logit(c) from a guess of the table (good to ~1e-10) and from the law's
TABLE_STEP, LAW_STEP = 1e-6, 1e-3


def _logit_guess(mu: float, gamma: float, found: TableValues | None = None) -> tuple[float, float]:
    """logit(c) from the table (``found``, if the caller has read it already), else the second-order law,
    kept below the largest stick radius; and the first secant step that suits the guess."""
    if found is None:
        found = table_given_mu(mu, gamma, quantities=())  # nan outside the table (or without it)
    c, gap = float(found.c[0]), float(found.gap[0])
    if 0.0 < c < 1.0:
        return math.log(c) - math.log(gap), TABLE_STEP
    if mu * gamma < LAW_MU_GAMMA_MAX:
        c = float(stick_radius_second_order(mu, gamma=gamma))
    if not 0.0 < c < 1.0:
        c = 1.0
    gap_max = float(largest_stick_radius_gap(gamma))
    gap = max(1.0 - c, 1.5 * gap_max, 1e-300)
    if c <= 0.0:
        c = C_ASYMPTOTIC
    return (math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)), LAW_STEP


def rounding_floor(scale: float) -> float:
    """The rounding level of the eigenvalue condition, ERROR_FLOOR * scale, at every c.

    Small c once needed more (a floor growing like 1/c below c = 2e-3: levels 2, 3, 4 scattered by 1.6e-11 in mu at
    c = 1e-5): the rows of (2.2a) are now differenced against one point and the solves refined
    (``numeric.core.operators.collocation_system``, ``numeric.core.linear_algebra.EquilibratedLU.solve_refined``), and
    over nu in {-0.5, 0, 0.3, 0.45} the three levels agree within 1.5e-14 in mu and P* at c = 1e-5, 3e-5, 1e-4, 3e-4,
    1e-3 and 3e-3 (measured)."""
    return ERROR_FLOOR * scale


def _error(fine: SingularField, other: SingularField, value: Callable[[SingularField], float], level: int) -> float:
    """The level's error estimate from ``estimate_resolution``'s solve ``other``: ``estimate_safety`` times the larger
    difference of ``value`` and P*, at least the rounding floor."""
    scale = max(abs(value(fine)), abs(fine.compliance))
    difference = max(abs(value(fine) - value(other)), abs(fine.compliance - other.compliance))
    return max(estimate_safety(level) * difference, rounding_floor(scale))


def solve_given_c(nu: float | None, c: float, gamma: float, level: int, gap: float | None = None,
                  theta_guess: float | None = None) -> FlatPunchSolution:
    """mu for stick radius c at ``level``; ``estimate_resolution``'s solve gives the error estimate. ``gap``: 1 - c
    exactly, where c near 1 has rounded it (the tables' nodes); ``theta_guess``: atan(mu gamma) from a
    neighbouring solution (else the table's, or the law's)."""
    given_gap = gap
    rounding = ROUNDING_ULPS * (math.ulp(c) if gap is None else math.ulp(gap))
    gap = 1.0 - c if gap is None else gap
    gap_max = float(largest_stick_radius_gap(gamma))
    excess = gap - gap_max  # (1 - c) - (1 - c_max); mu gamma ~ A / excess, A ~ 1.2 ... 1.5 (1 - c_max)
    bias = 0.0
    if excess <= max(NEAR_C_MAX * gap_max, 2.0 * rounding):
        # Near c_max the friction is A/(gamma excess): a shift of the level's c_max (measured against the closed
        # form at level 2: 1.8e-13 at nu = -0.999, 9e-16 at nu = -0.9, 1.5e-16 at nu = 0) moves mu by
        # mu shift/excess, and c within rounding of c_max has no finite mu to tell.
        limit, partner_gap = solve_limit(nu, gamma, level)
        # and one unit in the last place of 1 - c for the rounding of the eigenvalue condition (measured: the
        # level-4 mu at nu = -0.999, 6 ulp below c_max, is 5% off the approach A/(gamma excess))
        bias = max(abs(limit.gap - gap_max), abs(partner_gap - gap_max)) + rounding / ROUNDING_ULPS
        resolution = max(rounding, 2.0 * bias)
        if excess < -resolution:
            raise no_eigenvalue(c, gamma)
        if rounding < abs(excess) <= resolution and level < len(RESOLUTIONS) - 1:  # a finer level's c_max may tell
            return solve_given_c(nu, c, gamma, level + 1, given_gap, theta_guess)
        if excess <= resolution:
            return replace(limit, route=f"c = {c!r} is c_max to rounding (|(1 - c) - (1 - c_max)| = {abs(excess):.2g} "
                                        f"<= {resolution:.2g}): {limit.route}")
    res = RESOLUTIONS[level]
    guess = _theta_guess(c, gamma) if theta_guess is None else theta_guess
    try:
        fine = SingularField(core_given_c(c, gap, gamma, guess, res))
    except (SolverError, NoEigenvalueError):
        fine = SingularField(core_given_c(c, gap, gamma, _theta_near_c_max(gap, gamma, res), res))

    def estimate() -> float:
        other = SingularField(core_given_c(c, gap, gamma, fine.theta, estimate_resolution(level)))
        error = max(_error(fine, other, lambda f: f.mu, level), fine.mu * THETA_FLOOR / (0.5 * math.sin(2.0 * fine.theta)))
        if bias > 0.0:  # the level's c_max off the closed form by bias: mu off by up to mu bias / (excess - bias)
            error = max(error, fine.mu * bias / (excess - bias))
        return error

    return from_field(nu, fine, level, DeferredError(estimate))


def solve_limit(nu: float | None, gamma: float, level: int) -> tuple[FlatPunchSolution, float]:
    """The limit mu -> inf (theta = pi/2: c = c_max, no pressure on the slip annulus) at ``level``, and the
    1 - c_max of ``estimate_resolution``'s solve.

    ``error`` is the difference from that solve (c, P*, times ``estimate_safety``), at least ERROR_FLOOR P*. Where 1 - c_max is below
    GAP_ADHESIVE (nu above ~0.41, gamma below ~0.15) the annulus is thinner than the stresses resolve (and a
    layout down to it would need ~1e4 elements at nu = 0.4999, where 1 - c_max underflows: 1.3 GiB): the
    adhesive solution (App. B) with c = 1 - (1 - c_max) of the closed form, as ``nearly_adhesive``; at
    gamma = 0 the closed form c = 1.
    """
    if gamma == 0.0:
        sol = closed_form(nu, gamma, math.inf, 1.0, True, "limit mu -> inf at gamma = 0: no coupling, c = 1")
        return sol, 0.0
    gap_max = float(largest_stick_radius_gap(gamma))
    if gap_max < GAP_ADHESIVE:
        near = nearly_adhesive(nu, gamma, math.inf, gap_max)
        route = (f"limit mu -> inf: adhesive stresses (App. B), 1 - c_max = {gap_max:.3g} < {GAP_ADHESIVE:g} "
                 "(closed form) is below what the stresses resolve")
        return replace(near, route=route), gap_max
    res = RESOLUTIONS[level]
    start = math.log1p(-gap_max) - math.log(gap_max)
    fine = SingularField(solve_given_theta(HALF_PI, gamma, start, res))
    other = SingularField(solve_given_theta(HALF_PI, gamma, math.log(fine.c) - math.log(fine.gap),
                                            estimate_resolution(level)))
    error = max(estimate_safety(level) * max(abs(fine.gap - other.gap), abs(fine.compliance - other.compliance)),
                ERROR_FLOOR * fine.compliance)
    sol = from_field(nu, fine, level, error, math.inf)
    return replace(sol, route=f"limit mu -> inf (annulus without pressure), {sol.route}"), other.gap


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


def solve_given_mu(nu: float | None, mu: float, gamma: float, level: int, found: TableValues | None = None
                   ) -> FlatPunchSolution:
    """The stick radius for friction mu at ``level``, started from the table (``found``: its values at mu, if
    already read).

    Where the table reaches: one or two given-c solves (``numeric.core.eigenvalue.solve_given_theta_guided``) from its
    c and d theta / d logit c; the error estimate is ``estimate_resolution``'s theta at the same c, turned into
    c by that slope (and P* by the table's d P* / d logit c). Elsewhere: the secant in logit c at
    theta = atan(mu gamma) from the law's guess, ``estimate_resolution``'s likewise."""
    theta = math.atan(mu * gamma)
    res: Resolution = RESOLUTIONS[level]
    if found is None:
        found = table_given_mu(mu, gamma, quantities=(), slopes=True)
    c, gap, log_slope = float(found.c[0]), float(found.gap[0]), float(found.log_mu_slope[0])
    if 0.0 < c < 1.0 and math.isfinite(log_slope) and theta < HALF_PI:
        guided = solve_given_theta_guided(theta, gamma, c, gap, math.sin(theta) * math.cos(theta) * log_slope, res)
        fine = SingularField(guided.solution)
        compliance_slope = abs(float(found.compliance_slope[0]))

        def estimate() -> float:
            other = SingularField(core_given_c(fine.c, fine.gap, gamma, fine.theta, estimate_resolution(level)))
            # the other resolution's logit c for this theta, less ours, and the step in logit c the iteration did not take
            shift = abs(guided.solution.theta - other.theta) / abs(guided.slope) + guided.remaining_step
            scale = max(fine.c, fine.compliance)
            difference = max(fine.c * fine.gap * shift, abs(fine.compliance - other.compliance) + compliance_slope * shift)
            return max(estimate_safety(level) * difference, rounding_floor(scale))

        return from_field(nu, fine, level, DeferredError(estimate), mu)
    start, step = _logit_guess(mu, gamma, found)
    fine = SingularField(solve_given_theta(theta, gamma, start, res, step=step))

    def estimate_secant() -> float:
        # the other resolution's c differs from the fine one's by the discretisation error (< 1e-6)
        other = SingularField(solve_given_theta(theta, gamma, math.log(fine.c) - math.log(fine.layout.gap),
                                                estimate_resolution(level), step=TABLE_STEP))
        return _error(fine, other, lambda f: f.c, level)

    return from_field(nu, fine, level, DeferredError(estimate_secant), mu)


def nearly_adhesive(nu: float | None, gamma: float, mu: float, gap: float) -> FlatPunchSolution:
    """mu so large for this gamma that 1 - c < GAP_ADHESIVE: the adhesive solution with c = 1 - gap (its P* and
    stresses at 1 - x > 1e-12 within 0.3 gap^0.87 of the frictional ones, measured)."""
    adhesive = float(compliance_adhesive(gamma))
    return FlatPunchSolution(
        nu=nu, gamma=gamma, mu=mu, c=1.0 - gap, compliance=adhesive,
        _error=max(gap, 0.3 * gap**0.87),
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
                 gap_estimate: float = 1.0, found: TableValues | None = None):
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
            self._solve = lambda level: solve_given_mu(nu, mu, gamma, level, found)
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
