"""Material parameters of the frictional contact problem ([S75] §2.1, (2.2), (4.10)).

Nomenclature (used throughout both packages)
--------------------------------------------
nu     Poisson's ratio, in (-1, 1/2].
gamma  (1 - 2 nu) / (2 - 2 nu), the coupling constant of (2.2); in [0, 3/4) for every material, and
       |gamma_bar| < 3/4 for every pair (``gamma_dissimilar``); inputs may take the closed end 3/4,
       the limit nu -> -1.
kappa  (1/pi) log((1 + gamma)/(1 - gamma)), the oscillation index of the adhesive
       solution (4.10), (B1).
mu     Coulomb friction coefficient, in [0, inf].
c      stick radius as a fraction of the contact radius, in (0, 1].

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "GAMMA_MAX",
    "gamma_from_nu",
    "gamma_dissimilar",
    "kappa_from_gamma",
    "check_nu",
    "check_gamma",
    "check_mu",
    "check_c",
    "check_n",
    "check_x",
    "real_number",
    "finite_array",
    "resolve_gamma",
]


GAMMA_MAX = 0.75
"""gamma at nu = -1, the supremum of gamma_from_nu over (-1, 1/2] and of |gamma_dissimilar| over all pairs."""


def finite_array(value: ArrayLike, name: str) -> np.ndarray:
    """``value`` as a float array: real numbers only (no None, strings, booleans, complex or objects: TypeError
    naming ``name``), and no NaN (ValueError)."""
    raw = np.asarray(value) if value is not None else None
    if raw is None or raw.dtype.kind not in "iuf":
        raise TypeError(f"{name} must be a real number or an array of real numbers, got {value!r}")
    arr = raw.astype(float)
    if np.any(np.isnan(arr)):
        raise ValueError(f"{name} must not be NaN, got {value!r}")
    return arr


def check_nu(nu: ArrayLike) -> np.ndarray:
    """Return ``nu`` as a float array, raising ``ValueError`` unless -1 < nu <= 1/2."""
    arr = finite_array(nu, "nu")
    if np.any((arr <= -1.0) | (arr > 0.5)):
        raise ValueError(f"nu (Poisson's ratio) must lie in (-1, 1/2], got {nu!r}")
    return arr


def check_gamma(gamma: ArrayLike) -> np.ndarray:
    """Return ``gamma`` as a float array, raising ``ValueError`` unless 0 <= gamma <= 3/4.

    No material reaches gamma = 3/4: gamma_from_nu(nu) < 3/4 for nu > -1, and |gamma_bar| < 3/4 for
    every pair of bodies (``gamma_dissimilar``). The closed end 3/4, the limit nu -> -1, is accepted:
    the problem is regular there (kappa = (2/pi) atanh(3/4)), and the tables are built up to it.
    """
    arr = finite_array(gamma, "gamma")
    if np.any((arr < 0.0) | (arr > GAMMA_MAX)):
        raise ValueError(f"gamma must lie in [0, 3/4] (no pair of materials with nu in (-1, 1/2] reaches |gamma| = 3/4), "
                         f"got {gamma!r}")
    return arr


def check_mu(mu: ArrayLike) -> np.ndarray:
    """Return ``mu`` as a float array, raising ``ValueError`` unless 0 <= mu <= inf."""
    arr = finite_array(mu, "mu")
    if np.any(arr < 0.0):
        raise ValueError(f"mu (friction coefficient) must be >= 0, got {mu!r}")
    return arr


def check_c(c: ArrayLike) -> np.ndarray:
    """Return ``c`` as a float array, raising ``ValueError`` unless 0 < c <= 1."""
    arr = finite_array(c, "c")
    if np.any((arr <= 0.0) | (arr > 1.0)):
        raise ValueError(f"c (stick radius / contact radius) must lie in (0, 1], got {c!r}")
    return arr


def real_number(value: object, name: str) -> float:
    """``value`` as a float if it is one real number (a Python or numpy int or float, or a one-element array of
    one); else a TypeError naming ``name`` (None, strings, booleans, complex numbers, objects, longer arrays)
    or, for NaN, a ValueError."""
    arr = finite_array(value, name)
    if arr.size != 1:
        raise TypeError(f"{name} must be a single number, got shape {arr.shape}")
    return float(arr.reshape(()))


def check_n(n: float) -> float:
    """Return the power-law exponent ``n`` as a float, raising ``ValueError`` unless n > 0 (TypeError unless a
    real number)."""
    value = real_number(n, "n")
    if not value > 0.0 or math.isinf(value):
        raise ValueError(f"n (power-law exponent of the indenter) must be finite and > 0, got {n!r}")
    return value


def check_x(x: ArrayLike) -> np.ndarray:
    """Return ``x`` as a float array, raising ``ValueError`` unless 0 <= x <= 1 (radius over contact radius)."""
    arr = finite_array(x, "x")
    if np.any((arr < 0.0) | (arr > 1.0)):
        raise ValueError(f"x (radius over contact radius) must lie in [0, 1], got {x!r}")
    return arr


def gamma_from_nu(nu: ArrayLike) -> np.ndarray | float:
    """Coupling constant gamma = (1 - 2 nu) / (2 - 2 nu), [S75] (2.2).

    Parameters
    ----------
    nu : array_like
        Poisson's ratio, -1 < nu <= 1/2.

    Returns
    -------
    gamma : float or ndarray
        In [0, 3/4); 0 for an incompressible solid.

    Examples
    --------
    >>> float(gamma_from_nu(0.0)), round(float(gamma_from_nu(0.3)), 15)   # 1/2 and 2/7
    (0.5, 0.285714285714286)
    """
    nu_arr = check_nu(nu)
    gamma = (1.0 - 2.0 * nu_arr) / (2.0 - 2.0 * nu_arr)  # (2.2)
    return gamma[()] if gamma.ndim == 0 else gamma


def kappa_from_gamma(gamma: ArrayLike) -> np.ndarray | float:
    """Oscillation index kappa = (1/pi) log((1 + gamma)/(1 - gamma)), [S75] (4.10).

    Written as (2/pi) atanh(gamma), which keeps full relative accuracy as gamma -> 0.
    For a single body kappa = (1/pi) log(3 - 4 nu) ((4.18)).

    Examples
    --------
    >>> round(float(kappa_from_gamma(0.5)), 12)
    0.349699152566
    """
    gamma_arr = check_gamma(gamma)
    kappa = (2.0 / np.pi) * np.arctanh(gamma_arr)  # (4.10)
    return kappa[()] if kappa.ndim == 0 else kappa


def gamma_dissimilar(G1: float, nu1: float, G2: float, nu2: float) -> float:
    """Modified coupling constant for two elastic bodies, footnote to [S75] §2.1.

    gamma_bar = ((1 - 2 nu1)/(2 G1) - (1 - 2 nu2)/(2 G2)) / ((1 - nu1)/G1 + (1 - nu2)/G2).

    The contact problem keeps its form with gamma replaced by |gamma_bar| (the sign only
    says which body's surface moves inward relative to the other). A rigid indenter is
    the limit G2 -> inf, where gamma_bar -> gamma_from_nu(nu1).

    |gamma_bar| < 3/4 always: with t_i = 1/G_i >= 0, gamma_bar = (a1 t1 - a2 t2)/(b1 t1 + b2 t2) with
    a_i = (1 - 2 nu_i)/2 >= 0 and b_i = 1 - nu_i > 0, so |gamma_bar| <= (a1 t1 + a2 t2)/(b1 t1 + b2 t2)
    <= max_i a_i/b_i = max_i gamma_from_nu(nu_i) < 3/4.

    Parameters
    ----------
    G1, G2 : float
        Shear moduli, > 0 (``G2 = inf`` for a rigid indenter).
    nu1, nu2 : float
        Poisson's ratios, in (-1, 1/2].

    Examples
    --------
    >>> gamma_dissimilar(1.0, 0.0, float("inf"), 0.3)
    0.5
    >>> gamma_dissimilar(2.0, 0.3, 2.0, 0.3)
    0.0
    """
    for name, g in (("G1", G1), ("G2", G2)):
        if not float(g) > 0.0:
            raise ValueError(f"{name} (shear modulus) must be > 0, got {g!r}")
    check_nu(nu1)
    check_nu(nu2)
    if math.isinf(G1):
        raise ValueError("G1 (shear modulus of the elastic half-space) must be finite")
    second = 0.0 if math.isinf(G2) else 1.0 / G2
    numerator = (1.0 - 2.0 * nu1) / (2.0 * G1) - (1.0 - 2.0 * nu2) * second / 2.0
    denominator = (1.0 - nu1) / G1 + (1.0 - nu2) * second
    return numerator / denominator


def resolve_gamma(nu: float | None, gamma: float | None) -> float:
    """Return gamma from exactly one of ``nu`` (a single body) or ``gamma`` (e.g. dissimilar bodies)."""
    if (nu is None) == (gamma is None):
        raise ValueError("give exactly one of nu (Poisson's ratio) or gamma (coupling constant)")
    if gamma is None:
        return float(gamma_from_nu(real_number(nu, "nu")))
    return float(check_gamma(real_number(gamma, "gamma")))
