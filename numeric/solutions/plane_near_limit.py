"""The strip punch at friction beyond the solver's reach toward mu -> inf (mu gamma > ``LIMIT_MU_GAMMA[1]``).

There theta = atan(mu gamma) lies within 1e-6 of pi/2, where the basis exponent 1/2 - alpha and the generic mode
degenerate (the solver stopped converging from mu gamma ~ 1e10 and gave p(c) = -3017 at nu = -0.9). The solution is
smooth in eps = 1/(mu gamma) down to eps = 0 (the limit problem of ``numeric.solutions.plane_solver.solve_limit``):
1 - c = (1 - c_max) + A eps + O(eps^2), and likewise p, q, u away from the stick-slip point. So c, q, u here are
linear in eps through the limit's two solves at mu gamma = 1e5, 1e6 (an extrapolation by at most eps_2 = 1e-6, whose
neglected term is the limit's own, ~(gap_1 - gap_2)^2/(1 - c_max)), and p = q/mu on the slip zones (Coulomb's law,
exact). Within ``NEAR_ZONE`` times c - c(mu gamma = 1e5) of x = c the two solves see different zones and are not
combined: stresses and slip there raise ValueError. The cylinder's integrals of p and q (``plane_power_law``) are
linear in the fields and are combined the same way (``numeric.core.plane_fields.FieldCombination``).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction", J. Elasticity 5 (1975) 297-319, §2.4 (the limit
      mu -> inf of the axisymmetric problem; the plane one is the same construction).
"""

from __future__ import annotations

from numeric.core.plane_fields import FieldCombination, PlaneField

__all__ = ["NEAR_ZONE", "near_limit_field"]

#: Half-width of the zone about x = c left unresolved, in units of c - c(mu gamma = 1e5) (~1.4e-5 (1 - c_max)).
NEAR_ZONE = 10.0


def near_limit_field(mu: float, gamma: float, near: tuple[tuple[float, float, PlaneField], ...]) -> FieldCombination:
    """The field at friction mu from the limit's solves ``near`` ((mu gamma, 1 - c, field) at two mu gamma): weights
    linear in 1/(mu gamma), the same for p and q, p = |q|/mu on the slip zones; unresolved within ``NEAR_ZONE`` times
    c - c(mu gamma = 1e5) of x = c."""
    (m1, gap1, f1), (m2, gap2, f2) = near
    eps, e1, e2 = 1.0 / (mu * gamma), 1.0 / m1, 1.0 / m2
    w1 = (eps - e2) / (e1 - e2)
    w2 = 1.0 - w1
    gap = w1 * gap1 + w2 * gap2  # the line through both, which meets eps = 0 at gap_limit
    c = 1.0 - gap
    c_first = min(f1.c, f2.c)
    width = NEAR_ZONE * (c - c_first)
    reason = (f"where the solution at mu = {mu:g} (mu gamma beyond 1e6) is not resolved: the stresses are linear in "
              "1/(mu gamma) only away from it")
    return FieldCombination((f1, f2), (w1, w2), mu, c, gap, (c_first - width, c + width), reason)
