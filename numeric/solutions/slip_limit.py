"""The limit mu -> inf of the frictional flat punch, and the largest stick radius (beyond [S75]).

As mu grows the stick radius does not reach 1 (as (2.29), the first-order law, says) but c_max(gamma)
< 1: in theta = atan(mu gamma) the eigenvalue relation is regular at theta = pi/2, where the slip
annulus carries shear q = R/gamma but no pressure (p = q/mu = 0), and the pressure at the stick
edge has no logarithm (``numeric.core.operators``). ``slip_limit`` solves that limit problem;
its stick radius is c_max, which satisfies K'(c_max)/K(c_max) = kappa
(``asymptotics.largest_stick_radius``, found from it; agreement 1e-12 in 1 - c_max, tested).

This is not the fully adhesive punch (App. B; ``flat_punch(mu=inf)``): there the whole contact
sticks and the stresses oscillate at the edge like (1 - x)^(-1/2 +- i kappa/2); here an annulus
of width 1 - c_max (1e-3 at nu = 0, 1.7e-2 at nu = -1/2, 4e-7 at nu = 0.3) still slides, and p, q
are bounded there. A user who wants "very high friction" wants this one for the stick radius and
the stresses near the edge; P* and the stresses away from the edge differ from the adhesive ones
by about (1 - c_max)^0.9.

The approach: (1 - c) - (1 - c_max) = A / (mu gamma) + O(mu^-2). ``stick_radius_approach`` gives A
from the limit problem (a one-sided difference in 1/(mu gamma), second order).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import scalar_or_array
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import check_gamma, check_nu, gamma_from_nu, real_number, resolve_gamma

from numeric.core.charts import RESOLUTIONS
from numeric.core.eigenvalue import solve_given_theta
from numeric.core.fields import SingularField
from numeric.solutions.flat_punch import check_level
from numeric.solutions.solution import FlatPunchSolution
from numeric.solutions.solver import DEFAULT_LEVEL, GAP_ADHESIVE, solve_limit

__all__ = ["largest_stick_radius", "slip_limit", "stick_radius_approach"]

HALF_PI = 0.5 * math.pi
APPROACH_STEP = 1e-3
"""Step in 1/(mu gamma) of the difference giving A (second order: error ~1e-6 A, measured)."""


def largest_stick_radius(nu: ArrayLike = None, *, gamma: ArrayLike = None) -> np.ndarray | float:
    """c_max(nu): the stick radius as mu -> inf, K'(c_max)/K(c_max) = (2/pi) atanh(gamma) (closed form).

    Vectorised over nu (or gamma). For nu above ~0.47 (gamma < 0.06) 1 - c_max underflows and c_max = 1.

    Examples
    --------
    >>> round(float(largest_stick_radius(0.0)), 12), round(float(largest_stick_radius(-0.5)), 10)
    (0.998997001458, 0.9827777946)
    """
    if (nu is None) == (gamma is None):
        raise ValueError("give exactly one of nu and gamma")
    g = gamma_from_nu(check_nu(nu)) if gamma is None else check_gamma(gamma)
    return scalar_or_array(1.0 - np.asarray(largest_stick_radius_gap(g), dtype=float))


def _limit(gamma: float, level: int, theta: float = HALF_PI) -> SingularField:
    gap = float(largest_stick_radius_gap(gamma))
    start = math.log1p(-gap) - math.log(gap)
    return SingularField(solve_given_theta(theta, gamma, start, RESOLUTIONS[level]))


def slip_limit(nu: float | None = None, *, gamma: float | None = None, level: int = DEFAULT_LEVEL) -> FlatPunchSolution:
    """The frictional flat punch in the limit mu -> inf: c = c_max, no pressure on the slip annulus.

    The limit problem (theta = pi/2) at ``level``; ``error`` is the difference from one degree lower.
    ``mu`` is inf and ``route`` says "limit mu -> inf". Not the adhesive solution (see the module).
    Where 1 - c_max < 1e-13 (``GAP_ADHESIVE``; nu above ~0.41) the annulus is below what the stresses
    resolve and the result is the adhesive solution with c = 1 - (1 - c_max) (closed form), its error
    max(1 - c_max, 0.3 (1 - c_max)^0.87) (``numeric.solutions.solver.nearly_adhesive``); at gamma = 0
    (nu = 1/2) it is the closed form c = 1 (no coupling).
    """
    g = resolve_gamma(nu, gamma)
    return solve_limit(None if nu is None else float(check_nu(real_number(nu, "nu"))), g, check_level(level))[0]


def stick_radius_approach(nu: float | None = None, *, gamma: float | None = None, level: int = DEFAULT_LEVEL) -> float:
    """A in (1 - c) - (1 - c_max) = A/(mu gamma) + O(mu^-2) as mu -> inf, from the limit problem.

    (-3 g(0) + 4 g(h) - g(2h)) / (2h) with g the 1 - c at 1/(mu gamma) = 0, h, 2h (h = APPROACH_STEP).

    Raises
    ------
    ValueError
        Where 1 - c_max < 1e-13 (``GAP_ADHESIVE``: nu above ~0.41, gamma below ~0.15): the annulus, and A
        (~1.2 ... 1.5 (1 - c_max)), are below what the solver resolves, and at nu = 1/2 there is none.
    """
    g = resolve_gamma(nu, gamma)
    level = check_level(level)
    gap_max = float(largest_stick_radius_gap(g))
    if not gap_max >= GAP_ADHESIVE:
        raise ValueError(f"stick_radius_approach: at gamma = {g:.6g} (nu = {nu}) the slip annulus of the limit, "
                         f"1 - c_max = {gap_max:.3g}, is thinner than {GAP_ADHESIVE:g}, below what the solver "
                         "resolves (A ~ 1.2 ... 1.5 (1 - c_max) would be as small)")
    gaps = [_limit(g, level, math.atan2(1.0, k * APPROACH_STEP)).layout.gap for k in (0, 1, 2)]
    return (-3.0 * gaps[0] + 4.0 * gaps[1] - gaps[2]) / (2.0 * APPROACH_STEP)
