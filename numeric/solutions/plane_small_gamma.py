"""The strip punch as nu -> 1/2 (gamma -> 0): mu/gamma as a series in gamma^2 through solves at larger gamma.

As gamma -> 0 theta = atan(mu gamma) ~ gamma^2 K(c)/K'(c) and the solver's theta carries an absolute rounding (its
system's condition grows like 1/gamma: at gamma = 0 the normal and the tangential problems decouple), so mu's relative
error grows like 1/gamma^2 (level 3, c = 0.5: 2e-9 at gamma = 0.02, 3.4e-8 at 0.005, 2e-7 at 0.002). mu/gamma is even
in gamma and analytic in gamma^2 (mu is odd in gamma), with the first-order law as its limit:

    mu/gamma = F0(c) + gamma^2 r(c, gamma),   F0 = K(c)/K'(c) (``asymptotics.plane.mu_over_gamma_plane``),
    r = F1(c) + F2(c) gamma^2 + F3(c) gamma^4 + ...

(measured: r at c = 0.5 is 0.55013, 0.55031, 0.55101, 0.55384 at gamma = 0.01, 0.02, 0.04, 0.08, its changes growing
fourfold per doubling of gamma). Below ``SMALL_GAMMA`` (nu > 0.4898) mu/gamma is taken from r interpolated in gamma^2
(degree 5) through the solver's r at the six ``NODES`` (gamma = 0.06 ... 0.16, where the solver's mu is good to ~1e-11
and r to ~3e-9), extrapolated to gamma; its error is ``ERROR_FACTOR`` times the difference from the same series through
``CHECK_NODES`` (other truncation, other rounding), at least the solver's rounding floor. Measured at c = 0.05, 0.3,
0.5, 0.9, 0.97, 0.99 (level 2 nodes): the two series differ by 6e-15 ... 1e-12 (relative) at gamma = 0.002, 2e-13 ...
3e-11 at 0.01, 1e-12 ... 9e-11 at 0.02, and the series through level-3 nodes by 3e-14 ... 2e-12, 6e-12 ... 4e-11,
3e-12 ... 1e-10; at gamma = 0.019 level 3's own estimate is 7.9e-10 ... 1.3e-8 and it meets the series to 8e-12 ...
5.6e-10 (c = 0.05, 0.5, 0.97).
A three-node series (gamma = 0.04, 0.08, 0.16) was good to ~1e-10 only below gamma = 0.005.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import special

from asymptotics.plane import mu_over_gamma_plane

from numeric.solutions.plane_solver import ROUNDING_FLOOR, solve_given_c

__all__ = ["SMALL_GAMMA", "NODES", "CHECK_NODES", "ERROR_FACTOR", "GammaSeries", "gamma_series",
           "small_gamma_friction", "small_gamma_stick_width_step"]

#: Below this gamma (nu > 0.4898) mu comes from the series: there the series is good to ~1e-10 relative (its estimate
#: 2.4e-10 at most, measured) and the solver's own mu to 7.9e-10 ... 1.3e-8 (level 3's estimate at gamma = 0.019).
SMALL_GAMMA = 0.02
#: gamma of the solver solves the series goes through, and of the second series its error is taken from.
NODES = (0.06, 0.08, 0.1, 0.12, 0.14, 0.16)
CHECK_NODES = (0.07, 0.09, 0.11, 0.13, 0.15, 0.18)
#: The error bound over the two series' difference.
ERROR_FACTOR = 3.0


@dataclass(frozen=True, slots=True)
class GammaSeries:
    """mu/gamma = first_order + gamma^2 r(gamma), r = sum_k coefficients[k] gamma^(2k), at one c (``gamma_series``);
    first_order = F0(c) = K(c)/K'(c)."""

    c: float
    first_order: float
    coefficients: tuple[float, ...]

    def mu_over_gamma(self, gamma: float) -> float:
        t = gamma * gamma
        return self.first_order + t * float(np.polynomial.polynomial.polyval(t, self.coefficients))


@lru_cache(maxsize=64)
def gamma_series(c: float, gap: float, level: int, nodes: tuple[float, ...] = NODES) -> GammaSeries:
    """The series through the solver's r = (mu/gamma - F0)/gamma^2 at ``nodes`` (kept per c, level and nodes)."""
    f0 = float(mu_over_gamma_plane(c))
    t = np.array([g * g for g in nodes])
    r = np.array([(solve_given_c(c, gap, g, level).field.mu / g - f0) / (g * g) for g in nodes])
    return GammaSeries(c, f0, tuple(float(v) for v in np.linalg.solve(np.vander(t, t.size, increasing=True), r)))


def small_gamma_friction(c: float, gap: float, gamma: float, level: int) -> tuple[float, float]:
    """mu for stick half-width c at gamma < SMALL_GAMMA from the series, and its error (module docstring)."""
    mu = gamma * gamma_series(c, gap, level).mu_over_gamma(gamma)
    other = gamma * gamma_series(c, gap, level, CHECK_NODES).mu_over_gamma(gamma)
    return mu, max(ERROR_FACTOR * abs(mu - other), ROUNDING_FLOOR * mu)


def small_gamma_stick_width_step(c: float, gap: float, gamma: float, mu: float, level: int) -> tuple[float, float]:
    """1 - c moved from the solver's stick half-width c (for friction mu) to the series' by one Newton step with
    d mu / d c = gamma dF0/dc = gamma pi / (2 c k'^2 K'^2) (Legendre's relation; k'^2 = 1 - c^2, K' = K(k')), exact to
    O(gamma^2) relative, and the step is ~1e-7 relative; and the error of 1 - c: the series' error in mu over the slope."""
    series_mu, error = small_gamma_friction(c, gap, gamma, level)
    k_prime = float(special.ellipkm1(c * c))  # K(m = 1 - c^2)
    slope = gamma * math.pi / (2.0 * c * gap * (1.0 + c) * k_prime * k_prime)
    return gap + (series_mu - mu) / slope, error / slope
