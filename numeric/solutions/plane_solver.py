"""The solver route of ``numeric.plane``: the plane singular-basis solver at its levels, with an error estimate.

Each level is a ``PlaneResolution`` (``PLANE_LEVELS``); ``error`` is the difference between the level and
the same problem one polynomial degree lower (``plane_partner``), at least ``ROUNDING_FLOOR`` times the
value (the scatter of mu between degrees 20 ... 28, where the discretisation error is far below it,
measured: 1e-12 ... 7e-11 relative over nu in [-1/2, 0.3], c in [0.05, 0.99]).

Given c: Newton in theta = atan(mu gamma) (``numeric.core.plane_eigenvalue``), the partner first from the
first-order law mu/gamma = K(c)/K'(c) (``asymptotics.plane``), the level from the partner's theta (one or
two steps). Given mu: the secant method in logit(c) at theta = atan(mu gamma), from the first-order
law's inverse (kept below the largest stick width), the partner from the level's c. mu -> inf: the limit
problem theta = pi/2, whose root is the largest stick width c_max (``largest_stick_width``).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from asymptotics.plane import mu_over_gamma_plane, stick_width_first_order

from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.plane_charts import PlaneResolution, plane_partner
from numeric.core.plane_eigenvalue import plane_given_c, plane_given_theta
from numeric.core.plane_fields import PlaneField

__all__ = ["PLANE_LEVELS", "DEFAULT_LEVEL", "ROUNDING_FLOOR", "PlaneSolve", "solve_given_c", "solve_given_mu",
           "solve_limit", "c_max_guess"]

#: Levels 0-4 (degree 12, 15, 18, 21, 24; h_beta times quadratics at c). Measured against degree 28
#: (``tests/test_plane_solver.py``): mu to about 1e-8, 1e-9, 3e-11, 1e-11, 1e-11 (the last two at the rounding floor).
PLANE_LEVELS: tuple[PlaneResolution, ...] = tuple(PlaneResolution(degree=d, singular_degree=2) for d in (12, 15, 18, 21, 24))
DEFAULT_LEVEL = 2
#: Relative floor of the error estimate: the rounding level of the eigenvalue (see the module docstring).
ROUNDING_FLOOR = 1e-10
HALF_PI = 0.5 * math.pi


@dataclass(frozen=True, slots=True)
class PlaneSolve:
    """A solver result: the level's field, the partner's, and the estimated absolute error of mu (given c)
    or c (given mu, or of c_max at mu = inf)."""

    field: PlaneField
    partner: PlaneField
    error: float
    level: int


def _mu(theta: float, gamma: float) -> float:
    return math.inf if theta >= HALF_PI else math.tan(theta) / gamma


def solve_given_c(c: float, gap: float, gamma: float, level: int, theta_guess: float | None = None) -> PlaneSolve:
    """mu for stick half-width c = 1 - gap at ``level``, with the partner's difference as error."""
    res = PLANE_LEVELS[level]
    if theta_guess is None:
        theta_guess = math.atan(gamma * gamma * float(mu_over_gamma_plane(c)))
    partner = PlaneField(plane_given_c(c, gap, gamma, theta_guess, plane_partner(res)))
    fine = PlaneField(plane_given_c(c, gap, gamma, partner.theta, res))
    error = max(abs(fine.mu - partner.mu), ROUNDING_FLOOR * fine.mu)
    return PlaneSolve(fine, partner, error, level)


def c_max_guess(gamma: float) -> float:
    """1 - c_max(gamma), roughly: 8 exp(-pi/(k eps)), eps = atanh(gamma)/pi, k = 1.87 + 0.97 gamma (a fit to the
    limit problem at nu = 0.1 ... -0.75, good to 3 % in 1 - c_max: a starting point, not a result)."""
    eps = math.atanh(gamma) / math.pi
    return 8.0 * math.exp(-math.pi / ((1.87 + 0.97 * gamma) * eps))


def solve_limit(gamma: float, level: int) -> PlaneSolve:
    """The limit mu -> inf (theta = pi/2: no pressure on the slip zone) at ``level``: c = c_max; error in 1 - c."""
    res = PLANE_LEVELS[level]
    gap = c_max_guess(gamma)
    fine = PlaneField(plane_given_theta(HALF_PI, gamma, math.log1p(-gap) - math.log(gap), res, step=0.01))
    partner = PlaneField(plane_given_theta(HALF_PI, gamma, math.log(fine.c) - math.log(fine.gap), plane_partner(res),
                                           step=1e-6))
    error = max(abs(fine.gap - partner.gap), ROUNDING_FLOOR * fine.gap)
    return PlaneSolve(fine, partner, error, level)


def solve_given_mu(mu: float, gamma: float, level: int) -> PlaneSolve:
    """The stick half-width for friction mu at ``level`` (secant in logit c), with the partner's difference as error."""
    res = PLANE_LEVELS[level]
    theta = math.atan(mu * gamma)
    c = float(stick_width_first_order(mu, gamma))
    gap_max = c_max_guess(gamma)
    gap = max(1.0 - c, 2.0 * gap_max)
    c = min(c, 1.0 - gap)
    xi = math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)
    try:
        fine = PlaneField(plane_given_theta(theta, gamma, xi, res, step=0.01))
    except SolverError:
        raise
    if not 0.0 < fine.c < 1.0:
        raise NoEigenvalueError(f"no stick width found for mu = {mu}, gamma = {gamma}")
    partner = PlaneField(plane_given_theta(theta, gamma, math.log(fine.c) - math.log(fine.gap), plane_partner(res),
                                           step=1e-6))
    error = max(abs(fine.c - partner.c), ROUNDING_FLOOR * min(fine.c, fine.gap))
    return PlaneSolve(fine, partner, error, level)
