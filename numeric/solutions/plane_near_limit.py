"""The strip punch at friction beyond the solver's reach toward mu -> inf (mu gamma > ``LIMIT_MU_GAMMA[1]``).

There theta = atan(mu gamma) lies within 1e-6 of pi/2, where the basis exponent 1/2 - alpha and the generic mode
degenerate (the solver stopped converging from mu gamma ~ 1e10 and gave p(c) = -3017 at nu = -0.9). The solution is
smooth in eps = 1/(mu gamma) down to eps = 0 (the limit problem of ``numeric.solutions.plane_solver.solve_limit``):
1 - c = (1 - c_max) + A eps + O(eps^2), and likewise p, q, u away from the stick-slip point. So c, q, u here are
linear in eps through the limit's two solves at mu gamma = 1e5, 1e6 (an extrapolation by at most eps_2 = 1e-6, whose
neglected term is the limit's own, ~(gap_1 - gap_2)^2/(1 - c_max)), and p = q/mu on the slip zones (Coulomb's law,
exact). Within ``NEAR_ZONE`` times c - c(mu gamma = 1e5) of x = c the two solves see different zones and are not
combined: stresses and slip there raise ValueError. The cylinder's integrals of p and q (``plane_power_law``) are
linear in the fields and are combined the same way.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction", J. Elasticity 5 (1975) 297-319, §2.4 (the limit
      mu -> inf of the axisymmetric problem; the plane one is the same construction).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from numeric.core.plane_fields import PlaneField, Weight, weighted_tail_integrals

__all__ = ["NEAR_ZONE", "NearLimitField", "near_limit_field"]

#: Half-width of the zone about x = c left unresolved, in units of c - c(mu gamma = 1e5) (~1.4e-5 (1 - c_max)).
NEAR_ZONE = 10.0


@dataclass(frozen=True, slots=True, eq=False)
class NearLimitField:
    """w_1 F_1 + w_2 F_2 of the limit's two solves (weights summing to 1) at friction ``mu``; stick-slip point ``c``."""

    fields: tuple[PlaneField, PlaneField]
    weights: tuple[float, float]
    mu: float
    c: float
    gap: float

    @property
    def unresolved(self) -> tuple[float, float]:
        """The interval of |x| about c where the stresses and the slip are not resolved."""
        c_first = min(f.c for f in self.fields)
        width = NEAR_ZONE * (self.c - c_first)
        return c_first - width, self.c + width

    def check(self, ax: np.ndarray) -> None:
        """ValueError if a point |x| lies in ``unresolved``."""
        lo, hi = self.unresolved
        inside = (ax > lo) & (ax < hi)
        if np.any(inside):
            raise ValueError(f"x = {float(ax[inside][0])!r} lies within {hi - self.c:.2g} of the stick-slip point "
                             f"c = {self.c!r}, where the solution at mu = {self.mu:g} (mu gamma beyond 1e6) is not "
                             f"resolved: the stresses are linear in 1/(mu gamma) only away from it")

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p and q at -1 <= x <= 1: q combined, p combined on the stick zone and q/mu (Coulomb) on the slip zones."""
        x = np.asarray(x, dtype=float)
        self.check(np.abs(x).ravel())
        (f1, f2), (w1, w2) = self.fields, self.weights
        (p1, q1), (p2, q2) = f1.pressure_shear(x), f2.pressure_shear(x)
        p, q = w1 * p1 + w2 * p2, w1 * q1 + w2 * q2
        slipping = np.abs(x) > self.c
        p = np.where(slipping, np.abs(q) / self.mu, p)
        return p, q

    def slip(self, x: np.ndarray) -> np.ndarray:
        """u at -1 <= x <= 1, combined (0 on the stick zone)."""
        x = np.asarray(x, dtype=float)
        self.check(np.abs(x).ravel())
        (f1, f2), (w1, w2) = self.fields, self.weights
        return w1 * f1.slip(x) + w2 * f2.slip(x)

    def tail_integrals(self, x: np.ndarray, weight: Weight) -> tuple[np.ndarray, np.ndarray]:
        """``weighted_tail_integrals`` of the combination (linear in the field)."""
        (f1, f2), (w1, w2) = self.fields, self.weights
        (p1, q1), (p2, q2) = weighted_tail_integrals(f1, x, weight), weighted_tail_integrals(f2, x, weight)
        return w1 * p1 + w2 * p2, w1 * q1 + w2 * q2


def near_limit_field(mu: float, gamma: float, near: tuple[tuple[float, float, PlaneField], ...]) -> NearLimitField:
    """The field at friction mu from the limit's solves ``near`` ((mu gamma, 1 - c, field) at two mu gamma): weights
    linear in 1/(mu gamma)."""
    (m1, gap1, f1), (m2, gap2, f2) = near
    eps, e1, e2 = 1.0 / (mu * gamma), 1.0 / m1, 1.0 / m2
    w1 = (eps - e2) / (e1 - e2)
    w2 = 1.0 - w1
    gap = w1 * gap1 + w2 * gap2  # the line through both, which meets eps = 0 at gap_limit
    return NearLimitField((f1, f2), (w1, w2), mu, 1.0 - gap, gap)
