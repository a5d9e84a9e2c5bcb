"""Closed forms for the flat punch: frictionless solution and the first-order mu-c law.

[S75] §2.3: p^(0)(x) = (2/pi)(1 - x^2)^(-1/2) (2.26) is the exact frictionless pressure
(and the gamma -> 0 limit); setting chi^(0)(c) = 0 in (2.27) gives the small-gamma
relation between friction and stick radius,

    mu/gamma = atanh(c) / (c K'(c)),   K'(c) = K(sqrt(1 - c^2)),          (2.28)

with the limits (2.29). Elliptic integrals use SciPy's parameter convention m = k^2;
K'(c) is evaluated as ``ellipkm1(c**2)`` = K(m = 1 - c^2), exact for tiny c.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike
from scipy import special

from .materials import check_c

__all__ = ["frictionless_pressure", "mu_over_gamma"]


def frictionless_pressure(x: ArrayLike) -> np.ndarray | float:
    """Boussinesq pressure under a smooth flat punch, p = (2/pi)(1 - x^2)^(-1/2), [S75] (2.26).

    Examples
    --------
    >>> round(float(frictionless_pressure(0.0)), 15)
    0.636619772367581
    """
    xs = np.asarray(x, dtype=float)
    if np.any(np.isnan(xs)) or np.any((xs < 0.0) | (xs >= 1.0)):
        raise ValueError(f"x must lie in [0, 1), got {x!r}")
    p = (2.0 / np.pi) / np.sqrt((1.0 - xs) * (1.0 + xs))  # (2.26)
    return p[()] if p.ndim == 0 else p


def mu_over_gamma(c: ArrayLike) -> np.ndarray | float:
    """First-order friction law mu/gamma = atanh(c)/(c K'(c)), [S75] (2.28).

    Exact in the limit gamma -> 0 at fixed c; inf at c = 1.

    Examples
    --------
    >>> round(float(mu_over_gamma(0.5)), 12)
    0.509438589023
    """
    cs = check_c(c)
    with np.errstate(divide="ignore"):
        ratio = np.arctanh(cs) / (cs * special.ellipkm1(cs**2))  # (2.28)
    return ratio[()] if ratio.ndim == 0 else ratio
