"""Where the stick pressure's singular family at x = c is pinned to 0, and in which rows: the rule of the
axisymmetric (``numeric.core.operators``) and the plane (``numeric.core.plane_operators``) collocation systems.

The local solutions at the stick-slip point carry no pressure on the stick side (``asymptotics.derive.plane``), so
the stick pressure's coefficients of h_beta are 0 in the solution; where the family tends to log s, left free, they
made a near-null vector of the system (measured in ``numeric.core.charts``). The equations z = 0 replace rows of the
normal equation (``numeric.core.linear_algebra.pin_to_zero``).
"""

from __future__ import annotations

import numpy as np

__all__ = ["pins_stick_pressure", "pinned_rows", "AXISYMMETRIC_PIN_FROM", "PLANE_PIN_FROM"]

#: The axisymmetric system pins from alpha = 1/4 on (mu gamma >= 1, beta = 1 - 2 alpha <= 1/2), where the family tends
#: to log s and, left free, made a near-null vector (``numeric.core.charts``). Below, h_beta(0) = 0 and the free family
#: does no harm; pinned from alpha = 0.04 on, mu scattered over degrees 12 ... 20 by up to 1.1e-12 against 3.2e-13
#: (nu = -0.9, c = 0.01; 12 (nu, c) with alpha in [0.04, 1/4)), for p and q within 6.8e-10 of level 4 against 8.6e-10
#: (27 (nu, c) with alpha in [0.02, 0.26)): both within the stress target, so the rule stays.
AXISYMMETRIC_PIN_FROM = 0.25

#: The plane system pins from alpha = 0.04 on (1/2 - alpha <= 0.46 there): between 0.04 and 1/4 the free family left
#: p and q at and next to x = c up to 2.9e-9 off degree 28 (nu = 0, c = 0.97; 1.7e-9 at nu = 0.3, c = 0.999),
#: pinned 3.1e-10 (13 (nu, c) with alpha in [0.04, 1/4)), and mu's spread over degrees 16 ... 24 fell from up to
#: 2.8e-11 to below 1e-12. Below 0.04 (nu >= 0.4 at these c) pinning did not help: both ways scatter by 1e-9 ... 7e-8
#: at x = c, the system's conditioning growing like 1/gamma; pinned there, mu between degrees 18 and 24 differed 50
#: times more at nu = 0.45 (2.2e-10 against 4.8e-12 at c = 0.5).
PLANE_PIN_FROM = 0.04


def pins_stick_pressure(alpha: float, plane: bool = False) -> bool:
    """Whether the stick pressure's singular family at c is pinned to 0 at basis exponent alpha: from
    ``AXISYMMETRIC_PIN_FROM`` on in the axisymmetric system, from ``PLANE_PIN_FROM`` on in the plane one (``plane``)."""
    return alpha >= (PLANE_PIN_FROM if plane else AXISYMMETRIC_PIN_FROM)


def pinned_rows(n: int, k: int) -> np.ndarray:
    """The k of the stick end's n collocation points (counted from c) whose rows of the normal equation ((2.2a); (N)
    in the plane solver) pin the stick pressure's singular coefficients to 0: every (n // k)-th from the second on.

    Without those coefficients the system has k more equations than unknowns, and the k dropped must be of the normal
    equation, which determines p: as gamma -> 0 the tangential one alone determines q (dropping k of its rows left q
    undetermined at gamma = 1e-30). Which k of the points matters: measured on the axisymmetric system at nu = 0,
    c = 0.9988 (mu = 16.8) and c = 0.99895, degrees 12 ... 22, the spread choice keeps mu within 1e-12 of the degree-18
    solution and p at x = c within 1e-9 (the k points farthest from c put mu 1e-10 off, the k nearest 7e-7 in p, the
    k in the middle 1e-9 in mu at c = 1e-3)."""
    return 1 + (n // k) * np.arange(k)
