"""Where the stick pressure's singular family at x = c is pinned to 0, and in which rows: one rule for the
axisymmetric (``numeric.core.operators``) and the plane (``numeric.core.plane_operators``) collocation systems.

The local solutions at the stick-slip point carry no pressure on the stick side (``asymptotics.derive.plane``), so
the stick pressure's coefficients of h_beta are 0 in the solution; where the family tends to log s, left free, they
made a near-null vector of the system (measured in ``numeric.core.charts``). The equations z = 0 replace rows of the
normal equation (``numeric.core.linear_algebra.pin_to_zero``).
"""

from __future__ import annotations

import numpy as np

__all__ = ["pins_stick_pressure", "pinned_rows"]


def pins_stick_pressure(alpha: float) -> bool:
    """Whether the stick pressure's singular family at c is pinned to 0 at basis exponent alpha: from alpha = 1/4 on
    (mu gamma >= 1; beta = 1 - 2 alpha <= 1/2 here, 1/2 - alpha <= 1/4 in the plane solver), where the family tends to
    log s and, left free, made a near-null vector of the system (``numeric.core.charts``). The same rule in both
    geometries."""
    return alpha >= 0.25


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
