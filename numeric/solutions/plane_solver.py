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
           "solve_limit"]

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


def _mu(theta: float, gamma: float) -> float:
    return math.inf if theta >= HALF_PI else math.tan(theta) / gamma


def solve_given_c(c: float, gap: float, gamma: float, level: int, theta_guess: float | None = None) -> PlaneSolve:
    """mu for stick half-width c = 1 - gap at ``level``; the error is the shift of mu to the partner resolution (one
    degree lower), from one evaluation of its eigen functional (``partner_shift_theta``)."""
    res = PLANE_LEVELS[level]
    close = theta_guess is not None
    if theta_guess is None:  # the guess table (``numeric.core.plane_guess``, ~4e-3), Newton at the level from there
        theta_guess = theta_guess_table(c, gamma)
    solution = plane_given_c(c, gap, gamma, theta_guess, res, close=close)
    fine = PlaneField(solution)
    shift = partner_shift_theta(c, gap, gamma, solution, plane_partner(res))
    error = max(abs(_mu(fine.theta + shift, gamma) - fine.mu), ROUNDING_FLOOR * fine.mu)
    return PlaneSolve(fine, error, level)


def solve_limit(gamma: float, level: int) -> PlaneSolve:
    """The limit mu -> inf (theta = pi/2: no pressure on the slip zone) at ``level``: c = c_max; error in 1 - c."""
    res = PLANE_LEVELS[level]
    gap = gap_fit(gamma)
    solution = plane_given_theta(HALF_PI, gamma, math.log1p(-gap) - math.log(gap), res, step=0.01)
    fine = PlaneField(solution)
    return PlaneSolve(fine, _gap_error(fine, partner_shift_xi(HALF_PI, gamma, solution, plane_partner(res))), level)


def _gap_error(fine: PlaneField, shift: float) -> float:
    """|change of 1 - c| for a change ``shift`` of logit c (d(1 - c) = -c (1 - c) d xi), at least the rounding floor."""
    return max(abs(fine.c * fine.gap * shift), ROUNDING_FLOOR * min(fine.c, fine.gap))


def solve_given_mu(mu: float, gamma: float, level: int) -> PlaneSolve:
    """The stick half-width for friction mu at ``level`` (secant in logit c); error from the partner as for c_max."""
    res = PLANE_LEVELS[level]
    theta = math.atan(mu * gamma)
    c = stick_width_guess(theta, gamma)  # the guess table's inverse (~1e-3 in c), else the first-order law's
    gap_max = gap_fit(gamma)
    gap = max(1.0 - c, 2.0 * gap_max)
    c = min(c, 1.0 - gap)
    xi = math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)
    solution = plane_given_theta(theta, gamma, xi, res, step=1e-3)
    fine = PlaneField(solution)
    if not 0.0 < fine.c < 1.0:
        raise NoEigenvalueError(f"no stick width found for mu = {mu}, gamma = {gamma}")
    return PlaneSolve(fine, _gap_error(fine, partner_shift_xi(theta, gamma, solution, plane_partner(res))), level)
