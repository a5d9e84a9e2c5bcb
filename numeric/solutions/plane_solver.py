"""The solver route of ``numeric.plane``: the plane singular-basis solver at its levels, with an error estimate.

Each level is a ``PlaneResolution`` (``PLANE_LEVELS``); ``error`` is the difference between the level and
the same problem one polynomial degree lower (``plane_partner``; its root from one evaluation of its eigen
functional at the level's root, over the level's slope), at least ``ROUNDING_FLOOR`` times the
value (the scatter of mu between degrees 20 ... 28, where the discretisation error is far below it,
measured: 1e-12 ... 7e-11 relative over nu in [-1/2, 0.3], c in [0.05, 0.99]).

Given c: Newton in theta = atan(mu gamma) (``numeric.core.plane_eigenvalue``) from the guess table
(``numeric.core.plane_guess``; the first-order law mu/gamma = K(c)/K'(c) of ``asymptotics.plane`` where it does
not reach). Given mu: the secant method in logit(c) at theta = atan(mu gamma), from the table's inverse (kept
below the largest stick width). mu -> inf: the limit problem theta = pi/2, whose root is the largest stick
width c_max.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


from numeric.core.errors import NoEigenvalueError
from numeric.core.plane_charts import PlaneResolution, plane_partner
from numeric.core.plane_eigenvalue import partner_shift_theta, partner_shift_xi, plane_given_c, plane_given_theta
from numeric.core.plane_fields import PlaneField
from numeric.core.plane_guess import gap_fit, stick_width_guess
from numeric.core.plane_guess import theta_guess as theta_guess_table

__all__ = ["PLANE_LEVELS", "DEFAULT_LEVEL", "ROUNDING_FLOOR", "PlaneSolve", "solve_given_c", "solve_given_mu",
           "solve_limit", "C_SMALLEST", "LIMIT_MU_GAMMA"]

#: Levels 0-4 (degree 12, 15, 18, 21, 24; h_beta times quadratics at c). Measured against degree 28
#: (``tests/test_plane_solver.py``): mu to about 1e-8, 1e-9, 3e-11, 1e-11, 1e-11 (the last two at the rounding floor).
PLANE_LEVELS: tuple[PlaneResolution, ...] = tuple(PlaneResolution(degree=d, singular_degree=2) for d in (12, 15, 18, 21, 24))
DEFAULT_LEVEL = 2
#: Relative floor of the error estimate: the rounding level of the eigenvalue (see the module docstring).
ROUNDING_FLOOR = 1e-10
HALF_PI = 0.5 * math.pi


@dataclass(frozen=True, slots=True)
class PlaneSolve:
    """A solver result: the level's field and the estimated absolute error of mu (given c) or c (given mu, or of
    1 - c_max at mu = inf)."""

    field: PlaneField
    error: float
    level: int
    gap_limit: float = math.nan  # 1 - c_max where the limit mu -> inf was extrapolated


def _mu(theta: float, gamma: float) -> float:
    return math.inf if theta >= HALF_PI else math.tan(theta) / gamma


def solve_given_c(c: float, gap: float, gamma: float, level: int, theta_guess: float | None = None) -> PlaneSolve:
    """mu for stick half-width c = 1 - gap at ``level``; the error is the shift of mu to the partner resolution (one
    degree lower), from one evaluation of its eigen functional (``partner_shift_theta``). ValueError below
    ``C_SMALLEST``."""
    if c < C_SMALLEST:
        raise ValueError(f"c = {c!r} is below {C_SMALLEST:g}, outside the solver's range (first-order law: "
                         "mu/gamma = K(c)/K'(c))")
    res = PLANE_LEVELS[level]
    close = theta_guess is not None
    if theta_guess is None:  # the guess table (``numeric.core.plane_guess``, ~4e-3), Newton at the level from there
        theta_guess = theta_guess_table(c, gamma)
    solution = plane_given_c(c, gap, gamma, theta_guess, res, close=close)
    fine = PlaneField(solution)
    shift = partner_shift_theta(c, gap, gamma, solution, plane_partner(res))
    error = max(abs(_mu(fine.theta + shift, gamma) - fine.mu), ROUNDING_FLOOR * fine.mu)
    return PlaneSolve(fine, error, level)


#: mu gamma of the two solves the limit mu -> inf is extrapolated from: 1 - c = (1 - c_max) + A/(mu gamma) + O(mu^-2),
#: A ~ 1.4 (1 - c_max) (measured), so linear extrapolation from 1e5 and 1e6 leaves ~1e-11 (1 - c_max)
LIMIT_MU_GAMMA = (1e5, 1e6)


def solve_limit(gamma: float, level: int) -> PlaneSolve:
    """The limit mu -> inf (slip zones without pressure) at ``level``: c = c_max, extrapolated linearly in 1/(mu gamma)
    from ``LIMIT_MU_GAMMA`` (at mu = inf itself the generic mode degenerates); error in 1 - c_max: the partner's
    shift at the larger mu gamma, or the extrapolation's neglected O(mu^-2) term if larger. Against the limit problem
    solved at theta = pi/2 where that works (nu = 0, -1/2): 2e-13, 1e-13 absolute in 1 - c_max."""
    res = PLANE_LEVELS[level]
    gap = gap_fit(gamma)
    xi = math.log1p(-gap) - math.log(gap)
    gaps, fields = [], []
    for mg in LIMIT_MU_GAMMA:
        solution = plane_given_theta(math.atan(mg), gamma, xi, res, step=0.01)
        xi = math.log(solution.layout.c) - math.log(solution.layout.gap)
        fields.append(PlaneField(solution))
        gaps.append(solution.layout.gap)
    m1, m2 = LIMIT_MU_GAMMA
    gap_max = gaps[1] - (gaps[0] - gaps[1]) * m1 / (m2 - m1)
    fine = fields[1]
    partner = _gap_error(fine, partner_shift_xi(math.atan(m2), gamma, solution, plane_partner(res)))
    # the neglected B/(m1 m2) of the extrapolation: B ~ A^2/(1 - c_max), i.e. ~ (gaps[0] - gaps[1])^2/(1 - c_max)
    return PlaneSolve(fine, max(partner, (gaps[0] - gaps[1]) ** 2 / gap_max), level, gap_max)


def _gap_error(fine: PlaneField, shift: float) -> float:
    """|change of 1 - c| for a change ``shift`` of logit c (d(1 - c) = -c (1 - c) d xi), at least the rounding floor."""
    return max(abs(fine.c * fine.gap * shift), ROUNDING_FLOOR * min(fine.c, fine.gap))


#: Stick widths below this are not solved for (the layout needs ~40 elements at 1e-5, and round-off grows like 1/c).
C_SMALLEST = 1e-5


def solve_given_mu(mu: float, gamma: float, level: int) -> PlaneSolve:
    """The stick half-width for friction mu at ``level`` (secant in logit c); error from the partner as for c_max.
    ValueError where the guess puts c below ``C_SMALLEST``."""
    res = PLANE_LEVELS[level]
    theta = math.atan(mu * gamma)
    c = stick_width_guess(theta, gamma)  # the guess table's inverse (~1e-3 in c), else the first-order law's
    if c < C_SMALLEST:
        raise ValueError(f"mu = {mu:.6g} is too small at gamma = {gamma:.6g}: the stick half-width c ~ {c:.2g} lies "
                         f"below {C_SMALLEST:g}, outside the solver's range (first-order law: c ~ 4 exp(-pi gamma/(2 mu)))")
    gap_max = gap_fit(gamma)
    gap = max(1.0 - c, 2.0 * gap_max)
    c = min(c, 1.0 - gap)
    xi = math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)
    solution = plane_given_theta(theta, gamma, xi, res, step=1e-3)
    fine = PlaneField(solution)
    if not 0.0 < fine.c < 1.0:
        raise NoEigenvalueError(f"no stick width found for mu = {mu}, gamma = {gamma}")
    return PlaneSolve(fine, _gap_error(fine, partner_shift_xi(theta, gamma, solution, plane_partner(res))), level)
