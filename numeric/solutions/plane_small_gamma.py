"""The strip punch as nu -> 1/2 (gamma -> 0): mu, the stresses and the slip as series in gamma^2 through solves at
larger gamma.

As gamma -> 0 theta = atan(mu gamma) ~ gamma^2 K(c)/K'(c) and the solver's theta carries an absolute rounding (its
system's condition grows like 1/gamma: at gamma = 0 the normal and the tangential problems decouple), so mu's relative
error grows like 1/gamma^2 (level 3, c = 0.5: 2e-9 at gamma = 0.02, 3.4e-8 at 0.005, 2e-7 at 0.002). The shear and
the slip fare worse: the equilibrated system has a near-null stick-shear mode whose singular value is proportional to
gamma, and rounding in the tangential rows reaches q through it amplified by 1/gamma (measured at c = 0.5 against the
limit of the solver at gamma = 0.01, 0.02, 0.03: q/gamma off by 2.5e-7 at gamma = 0.005, 3.4e-5 at 1e-3, 0.1 at
1e-6 and 175 at 1e-8, where the stick zone's q/(mu p) was 1.1e4 and the slip had the wrong sign; p stays within
2e-11). At fixed c, mu/gamma, p, q/gamma and u/gamma are even in gamma and analytic in gamma^2 (mu, q and u are odd in
gamma), mu/gamma with the first-order law as its limit:

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
5.6e-10 (c = 0.05, 0.5, 0.97). A three-node series (gamma = 0.04, 0.08, 0.16) was good to ~1e-10 only below 0.005.

The stresses and the slip are the same interpolation of the nodes' fields (``small_gamma_field``: p, q/gamma and
u/gamma in gamma^2, Coulomb's q = mu p on the slip zones for the series' mu): no solve at gamma itself. Against the
limit gamma -> 0 of level-3 solves at gamma = 0.02, 0.03, 0.04 (quadratic in gamma^2; a route independent of the
nodes), at x = 0, 0.3 c, c (1 - 1e-3), c, c + 1e-3 (1 - c), (1 + c)/2, 1 - 0.01 (1 - c), -c/2 and gamma = 1e-9: p,
q/gamma and u/gamma within 5e-11, 9.3e-9, 2.7e-10 of their largest value at c = 0.5; 1.2e-9 ... 3.4e-9, 2e-9 ...
6.6e-9, 1.1e-9 ... 3.1e-9 at c = 0.95, 0.97, 0.99 (largest at x = c); toward c = 1 the two part further (q/gamma
1.4e-7 at 1 - c = 1e-4 and 1e-6, 5e-7 at 1e-8; u/gamma 6.9e-7, 3.3e-6 at 1e-6, 1e-8), where the reference's own
truncation grows (r's curvature in gamma^2, below); against the limit through 0.005, 0.01, 0.015 the near-one nodes
give q/gamma within 1.1e-8 and 2.6e-8 at 1 - c = 1e-6 and 1e-8. In the stick zone |q| < mu p everywhere checked.
(The solver at gamma = 1e-9 itself had q/(mu p) = 1.1e4 there.)

Toward c = 1 the nodes' own largest stick width c_max(gamma_node) comes near (1 - c_max = 5.3e-11 at gamma = 0.18):
there mu is not analytic in gamma^2 at the nodes (the approach to c_max, ~exp(-4.7/gamma)), the series through
``NODES`` degraded (mu/gamma's limit off by 1.1e-5 at 1 - c = 1e-6, 4e-4 at 1e-8) and above c_max(0.18) did not exist.
Below 1 - c = ``NEAR_ONE_GAP`` the nodes are scaled by ``NEAR_ONE_SCALE`` (gamma = 0.021 ... 0.056, where
1 - c_max < 1e-37): at 1 - c = 1e-6, 1e-8, 1e-10 the limit of mu/gamma is within 6.4e-10, 3.9e-9, 3e-8 and q/gamma
within 2e-9, 2.6e-8, 4.4e-7 (u/gamma 1.1e-9, 6.3e-9, 2.3e-8) of the solver's limit. Below 1 - c = ``SERIES_GAP_MIN``
(1e-8: each node a solve of 1200-2200 unknowns, ~1 s) the series is not formed (``near_one``).

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

from asymptotics.plane import slip_width_first_order, stick_width_first_order

from numeric.core.plane_fields import FieldCombination, PlaneField
from numeric.core.plane_guess import elliptic_ratio
from numeric.solutions.plane_solver import ROUNDING_FLOOR, solve_given_c

__all__ = ["SMALL_GAMMA", "NODES", "CHECK_NODES", "NEAR_ONE_GAP", "NEAR_ONE_SCALE", "SERIES_GAP_MIN",
           "DIRECT_FIELDS_GAMMA", "ERROR_FACTOR", "GammaSeries", "UnresolvedField", "series_nodes", "node_fields", "gamma_series", "small_gamma_friction", "small_gamma_field",
           "small_gamma_stick_width", "friction_slope"]

#: Below this gamma (nu > 0.4898) mu comes from the series: there the series is good to ~1e-10 relative (its estimate
#: 2.4e-10 at most, measured) and the solver's own mu to 7.9e-10 ... 1.3e-8 (level 3's estimate at gamma = 0.019).
SMALL_GAMMA = 0.02
#: gamma of the solver solves the series goes through, and of the second series its error is taken from.
NODES = (0.06, 0.08, 0.1, 0.12, 0.14, 0.16)
CHECK_NODES = (0.07, 0.09, 0.11, 0.13, 0.15, 0.18)
#: Below this 1 - c the nodes are scaled by ``NEAR_ONE_SCALE`` (see the module docstring; at 1 - c = 1e-4 the two node
#: sets give mu/gamma's limit within 2e-7 (``NODES``) and 1.1e-9 (scaled) of the solver's).
NEAR_ONE_GAP = 1e-4
NEAR_ONE_SCALE = 0.35
#: Below this 1 - c the series is not formed (``near_one``).
SERIES_GAP_MIN = 1e-8
#: Below 1 - c = SERIES_GAP_MIN the stresses are those of the solver at gamma itself from this gamma on, and not
#: computed below it: there the solver's q/gamma carries a rounding of up to ~3e-11/gamma^2 relative (measured at
#: c = 0.5 next to x = c: 3.4e-5 at gamma = 1e-3; 1e-13/gamma^2 elsewhere).
DIRECT_FIELDS_GAMMA = 1e-3
#: The error bound over the two series' difference.
ERROR_FACTOR = 3.0
#: Newton steps in logit c of ``small_gamma_stick_width`` (from the first-order law it takes 2 or 3).
MAX_STEPS = 8


def series_nodes(gap: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The nodes and check nodes for 1 - c = gap (``NEAR_ONE_GAP``)."""
    if gap >= NEAR_ONE_GAP:
        return NODES, CHECK_NODES
    return tuple(NEAR_ONE_SCALE * g for g in NODES), tuple(NEAR_ONE_SCALE * g for g in CHECK_NODES)


@lru_cache(maxsize=32)
def node_fields(c: float, gap: float, level: int, nodes: tuple[float, ...]) -> tuple[PlaneField, ...]:
    """The solver's fields for stick half-width c = 1 - gap at each gamma of ``nodes`` (detached from their systems,
    kept per c, level and nodes). ValueError for 1 - c below ``SERIES_GAP_MIN``."""
    if not gap >= SERIES_GAP_MIN:
        raise ValueError(f"1 - c = {gap!r} is below {SERIES_GAP_MIN:g}: the small-gamma series is not formed there")
    return tuple(solve_given_c(c, gap, g, level).field.detached() for g in nodes)


@dataclass(frozen=True, slots=True)
class GammaSeries:
    """mu/gamma = first_order + gamma^2 r(gamma), r = sum_k coefficients[k] gamma^(2k), at one c (``gamma_series``);
    first_order = F0(c) = K(c)/K'(c)."""

    c: float
    first_order: float
    coefficients: tuple[float, ...]

    def correction(self, gamma: float) -> float:
        """r(gamma) = (mu/gamma - F0)/gamma^2."""
        return float(np.polynomial.polynomial.polyval(gamma * gamma, self.coefficients))

    def mu_over_gamma(self, gamma: float) -> float:
        return self.first_order + gamma * gamma * self.correction(gamma)


def gamma_series(c: float, gap: float, level: int, nodes: tuple[float, ...] = NODES) -> GammaSeries:
    """The series through the solver's r = (mu/gamma - F0)/gamma^2 at ``nodes`` (``node_fields``)."""
    f0 = 1.0 / elliptic_ratio(c, gap)
    t = np.array([g * g for g in nodes])
    r = np.array([(f.mu / g - f0) / (g * g) for g, f in zip(nodes, node_fields(c, gap, level, nodes))])
    return GammaSeries(c, f0, tuple(float(v) for v in np.linalg.solve(np.vander(t, t.size, increasing=True), r)))


def small_gamma_friction(c: float, gap: float, gamma: float, level: int) -> tuple[float, float]:
    """mu for stick half-width c at gamma < SMALL_GAMMA from the series, and its error (module docstring)."""
    nodes, check = series_nodes(gap)
    mu = gamma * gamma_series(c, gap, level, nodes).mu_over_gamma(gamma)
    other = gamma * gamma_series(c, gap, level, check).mu_over_gamma(gamma)
    return mu, max(ERROR_FACTOR * abs(mu - other), ROUNDING_FLOOR * mu)


def small_gamma_field(c: float, gap: float, gamma: float, mu: float, level: int) -> FieldCombination:
    """p, q and u at gamma < SMALL_GAMMA for stick half-width c = 1 - gap: the nodes' fields interpolated in gamma^2
    (Lagrange weights w_i at gamma^2: p = sum w_i p_i, q = gamma sum w_i q_i/gamma_i, likewise u), q = mu sgn(x) p on
    the slip zones for ``mu`` (the series')."""
    nodes = series_nodes(gap)[0]
    t = np.array([g * g for g in nodes])
    w = [float(np.prod([(gamma * gamma - t[j]) / (t[i] - t[j]) for j in range(t.size) if j != i]))
         for i in range(t.size)]
    return FieldCombination(node_fields(c, gap, level, nodes), tuple(w),
                            tuple(wi * gamma / g for wi, g in zip(w, nodes)), mu, c, gap, "q")


def friction_slope(c: float, gap: float, gamma: float) -> float:
    """d mu / d logit c of the first-order law: gamma pi / (2 (1 + c) K'(c)^2) (Legendre's relation; d mu/dc = gamma
    pi / (2 c k'^2 K'^2), k'^2 = 1 - c^2 = (1 - c)(1 + c)), exact to O(gamma^2) relative."""
    k_prime = float(special.ellipkm1(c * c))  # K(m = 1 - c^2)
    return gamma * math.pi / (2.0 * (1.0 + c) * k_prime * k_prime)


def small_gamma_stick_width(mu: float, gamma: float, level: int) -> tuple[float, float, float] | None:
    """c, 1 - c and the error of c for friction mu at gamma < SMALL_GAMMA: Newton in logit c on the series' mu from
    the first-order law's c, with the first-order slope (``friction_slope``), until the series' mu at c is mu to
    ROUNDING_FLOOR / 10; the error is the series' error in mu over the slope, plus the residual step. None where
    1 - c falls below ``SERIES_GAP_MIN`` (the series does not reach)."""
    c = float(stick_width_first_order(mu, gamma))
    gap = float(slip_width_first_order(mu, gamma)) if c >= 0.5 else 1.0 - c
    for _ in range(MAX_STEPS):
        if gap < SERIES_GAP_MIN:
            return None
        series_mu = gamma * gamma_series(c, gap, level, series_nodes(gap)[0]).mu_over_gamma(gamma)
        slope = friction_slope(c, gap, gamma)
        step = (mu - series_mu) / slope
        if abs(mu - series_mu) <= 0.1 * ROUNDING_FLOOR * mu:
            break
        xi = (math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)) + step
        c, gap = 1.0 / (1.0 + math.exp(-xi)), 1.0 / (1.0 + math.exp(xi))
    error = small_gamma_friction(c, gap, gamma, level)[1]
    return c, gap, c * gap * (error + abs(mu - series_mu)) / slope


class UnresolvedField:
    """The field of a route that gives mu and c only: p, q and the slip raise NotImplementedError saying why."""

    def __init__(self, reason: str) -> None:
        self.reason = reason

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError(self.reason)

    def edge_pressure_shear(self, u: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError(self.reason)

    def slip(self, x: np.ndarray) -> np.ndarray:
        raise NotImplementedError(self.reason)
