"""The small-gamma friction law of [S75] §2.3 inverted at either order: the stick radius for given mu.

``stick_radius(mu, nu, order=0)`` solves mu/gamma = f0(c) (2.28)
(``asymptotics.first_order.stick_radius_first_order``); ``order=2`` solves
mu/gamma = f0(c) + gamma^2 f2(c) (``asymptotics.second_order.stick_radius_second_order``, beyond
the paper). This is ``asymptotics.stick_radius``; the full problem's stick radius is
``numeric.stick_radius``. The dispatch lives here, above both orders, so that neither module
imports the other's caller (first_order <- second_order <- friction_law).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .first_order import stick_radius_first_order
from .second_order import stick_radius_second_order

__all__ = ["stick_radius"]


def stick_radius(mu: ArrayLike, nu: float | None = None, *, gamma: float | None = None,
                 order: int = 0) -> np.ndarray | float:
    """Stick radius c for friction mu by the small-gamma law of order 0 ((2.28)) or 2 (+ gamma^2 f2).

    Parameters
    ----------
    mu : array_like
        Friction coefficient, >= 0 (inf allowed).
    nu, gamma : float
        Exactly one: Poisson's ratio, or the coupling constant (2.2).
    order : {0, 2}
        Order in gamma of the law inverted.

    Examples
    --------
    >>> round(float(stick_radius(0.18104, nu=0.25)), 4), round(float(stick_radius(0.18104, nu=0.25, order=2)), 4)
    (0.5506, 0.5042)
    """
    if order == 0:
        return stick_radius_first_order(mu, nu, gamma=gamma)
    if order == 2:
        return stick_radius_second_order(mu, nu, gamma=gamma)
    stick_radius_first_order(mu, nu, gamma=gamma)  # a bad mu or nu is named before the order
    raise ValueError(f"order must be 0 or 2, got {order!r}")
