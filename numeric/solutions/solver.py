"""The solver route of ``numeric.flat_punch``: the singular-basis solver of ``numeric.core`` at its levels.

Each level is a ``numeric.core.charts.Resolution`` (``RESOLUTIONS``); ``error`` is the
difference between the level and the same problem one polynomial degree lower
(``numeric.core.charts.partner``; at level 0, and at level 1 within 10 (1 - c_max) of c_max, ten times it,
``estimate_safety``), at least ``ERROR_FLOOR`` times
the value (the rounding level of the eigenvalue condition, flat in c down to c = 1e-5 since the rows of (2.2a) are
differenced and the solves refined, ``numeric.core.operators.collocation_system``) and, given c within 1e-6 (1 - c_max) of c_max, at least the shift of mu from the
level's c_max (``NEAR_C_MAX``; within rounding of c_max the answer is the slip limit, mu = inf). Measured against
level 4 and the graded solver (``derivations/stability.md``, ``tests/test_singular_solver.py``) the true error of
the default level lies below this estimate everywhere checked; the default level is at the rounding floor at most
points, and where it is not and level 4 resolves it the estimate is within a factor 10 at 7 of 8 points (the eighth
700x pessimistic next to c_max at nu = 0.3, where the partner's plain degree 10 converges poorly). The estimate is
a second solve as costly as the first, so it is formed when first read
(``numeric.solutions.solution.DeferredError``), or at once where rtol asks for it.

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
           "ESTIMATE_SAFETY", "NEAR_ESTIMATE_SAFETY", "NEAR_SAFETY_GAPS", "estimate_safety", "NEAR_C_MAX", "ROUNDING_ULPS", "rounding_floor", "SolverRoute", "solve_given_c", "solve_given_mu", "solve_limit", "from_field",
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
#: The error estimate of each level is its difference from the partner one degree lower times this factor. Level 0
#: converges erratically next to c_max: over 80 (nu, c) (``numeric.core.charts.RESOLUTIONS``) its true error was up
#: to 6.4 times the difference (nu = 0, 1 - c = 1.5 (1 - c_max)), at two points above it; at levels 1-3 never (level 4
#: is the reference).
ESTIMATE_SAFETY = (10.0, 1.0, 1.0, 1.0, 1.0)
#: Level 1 too where 1 - c < NEAR_SAFETY_GAPS (1 - c_max): over 500 random (nu, c) (half with 1 - c from 1.01 to 1000
#: (1 - c_max)) against level 4 its true error exceeded the difference at 4 of the 65 measurable points there (up to
#: 1.42 times, nu = 0.04 ... 0.13, 1 - c = 2.5 ... 7 (1 - c_max)), and a fuzz campaign found 4.2 times at nu = 0.095,
#: 1 - c = 3.1 (1 - c_max); farther out at most 0.42 of it (73 points), and level 2 at most 0.35 of its own anywhere.
NEAR_SAFETY_GAPS = 10.0
NEAR_ESTIMATE_SAFETY = (10.0, 10.0, 1.0, 1.0, 1.0)


def estimate_safety(level: int, gap: float, gamma: float) -> float:
    """The factor on the partner difference at this level and 1 - c (``ESTIMATE_SAFETY``, ``NEAR_ESTIMATE_SAFETY``)."""
    if gamma > 0.0 and gap < NEAR_SAFETY_GAPS * float(largest_stick_radius_gap(gamma)):
        return NEAR_ESTIMATE_SAFETY[level]
    return ESTIMATE_SAFETY[level]
#: Typical relative accuracy of each level (the worst measured, ``RESOLUTIONS``); rtol picks the first that meets it.
LEVEL_TYPICAL_ERROR = {0: 1e-7, 1: 1e-9, 2: 1e-11, 3: 1e-12, 4: 1e-13}
#: Rough run time in seconds of a solve with its error estimate (derivations/benchmark.md), for ordering routes.
LEVEL_SECONDS = {0: 0.008, 1: 0.010, 2: 0.016, 3: 0.025, 4: 0.04}


def from_field(nu: float | None, field: SingularField, level: int, error: float | DeferredError,
               mu: float | None = None) -> FlatPunchSolution:
    """The solver's solution as a ``FlatPunchSolution`` (``mu``: the friction asked for, given mu); ``error`` is
    the partner difference, times the level's ``estimate_safety``."""
    factor = estimate_safety(level, field.gap, field.gamma)
    if mu is not None:  # solved at theta = atan(mu gamma): cos(theta) from mu itself (``SingularField.with_friction``)
        field = field.with_friction(mu)
    if factor != 1.0:
        error = factor * error if isinstance(error, float) else DeferredError(lambda e=error: factor * e.value())
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


def _error(fine: SingularField, coarse: SingularField, value: Callable[[SingularField], float]) -> float:
    scale = max(abs(value(fine)), abs(fine.compliance))
    return max(abs(value(fine) - value(coarse)), abs(fine.compliance - coarse.compliance),
               rounding_floor(scale))


def solve_given_c(nu: float | None, c: float, gamma: float, level: int, gap: float | None = None,
                  theta_guess: float | None = None) -> FlatPunchSolution:
    """mu for stick radius c at ``level``; the partner resolution gives the error estimate. ``gap``: 1 - c
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
        coarse = SingularField(core_given_c(c, gap, gamma, fine.theta, partner(res)))
        error = _error(fine, coarse, lambda f: f.mu)
        if bias > 0.0:  # the level's c_max off the closed form by bias: mu off by up to mu bias / (excess - bias)
            error = max(error, fine.mu * bias / (excess - bias))
        return error

    return from_field(nu, fine, level, DeferredError(estimate))


def solve_limit(nu: float | None, gamma: float, level: int) -> tuple[FlatPunchSolution, float]:
    """The limit mu -> inf (theta = pi/2: c = c_max, no pressure on the slip annulus) at ``level``, and the
    partner resolution's 1 - c_max.

    ``error`` is the difference from the partner (c, P*), at least ERROR_FLOOR P*. Where 1 - c_max is below
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
    coarse = SingularField(solve_given_theta(HALF_PI, gamma, math.log(fine.c) - math.log(fine.gap), partner(res)))
    error = max(abs(fine.gap - coarse.gap), abs(fine.compliance - coarse.compliance), ERROR_FLOOR * fine.compliance)
    sol = from_field(nu, fine, level, error, math.inf)
    return replace(sol, route=f"limit mu -> inf (annulus without pressure), {sol.route}"), coarse.gap


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
    c and d theta / d logit c; the error estimate is the partner resolution's theta at the same c, turned into
    c by that slope (and P* by the table's d P* / d logit c). Elsewhere: the secant in logit c at
    theta = atan(mu gamma) from the law's guess, the partner likewise."""
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
            coarse = SingularField(core_given_c(fine.c, fine.gap, gamma, fine.theta, partner(res)))
            # the partner's logit c for this theta, less ours, and the step in logit c the iteration did not take
            shift = abs(guided.solution.theta - coarse.theta) / abs(guided.slope) + guided.remaining_step
            scale = max(fine.c, fine.compliance)
            return max(fine.c * fine.gap * shift, abs(fine.compliance - coarse.compliance) + compliance_slope * shift,
                       rounding_floor(scale))

        return from_field(nu, fine, level, DeferredError(estimate), mu)
    start, step = _logit_guess(mu, gamma, found)
    fine = SingularField(solve_given_theta(theta, gamma, start, res, step=step))

    def estimate_secant() -> float:
        # the partner's c differs from the fine one's by the discretisation error (< 1e-6)
        coarse = SingularField(solve_given_theta(theta, gamma, math.log(fine.c) - math.log(fine.layout.gap),
                                                 partner(res), step=TABLE_STEP))
        return _error(fine, coarse, lambda f: f.c)

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
