"""Closed forms of [S75] §3 for power-law indenters z = r^n / (n b^(n-1)).

The transformation of §3.2 turns the power-law problem into the flat-punch one: the
right-hand sides of (2.2) for w = 1 - x^n/(nA) and u = C x^n are (3.5)

    w* = 1 - A* x^n,   u* = C* x^n,
    A* = a_star_factor(n) / A,        a_star_factor(n) = Gamma(n/2) Gamma(1/2) / (2 Gamma((n+1)/2)),
    C* = c_star_factor(n) C,          c_star_factor(n) = Gamma((n+3)/2) Gamma(1/2) / Gamma(1 + n/2),

and the stresses follow from the flat-punch ones by (3.13),
p(x) = n x^(n-1) int_x^1 t^(-n) p0(t) dt. Hence P* = n P0*/(n+1) (3.17) and
p(0) = n p0(0)/(n-1) for n > 1 (3.18).

Without friction p0 = (2/pi)(1 - t^2)^(-1/2) (2.26) and (3.13) has the closed form
(derived in ``asymptotics.derive.similarity``, entry "frictionless-n")

    p(x) = (2n/pi) sqrt(1 - x^2) 2F1(1, 1 - n/2; 3/2; 1 - x^2),

which is (4/pi) sqrt(1 - x^2) for the sphere (3.19) and (2/pi) log((1 + sqrt(1 - x^2))/x)
for the cone (3.20); A* = 1 gives the classical indentation constant A = a_star_factor(n)
(1 for the sphere, pi/2 for the cone).

Nomenclature: x radius over contact radius, n exponent of the indenter (2 sphere, 1 cone),
A indentation constant (delta = A a^n / b^(n-1), (3.2)), C stick-zone displacement
constant (u = C x^n, (3.4)), P* compliance factor (2.4).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike
from scipy import special

from .arrays import scalar_or_array
from .materials import check_n, check_x

__all__ = [
    "a_star_factor",
    "c_star_factor",
    "frictionless_indentation_constant",
    "compliance_ratio",
    "central_pressure_ratio",
    "frictionless_pressure_power_law",
]


def a_star_factor(n: float) -> float:
    """Gamma(n/2) Gamma(1/2) / (2 Gamma((n+1)/2)) = B(n/2, 1/2)/2, with A* = a_star_factor(n)/A, [S75] (3.5).

    Parameters
    ----------
    n : float
        Exponent of the indenter, n > 0.

    Examples
    --------
    >>> round(a_star_factor(2.0), 14), round(a_star_factor(1.0), 14)   # 1 and pi/2
    (1.0, 1.5707963267949)
    """
    n = check_n(n)
    return float(0.5 * special.beta(0.5 * n, 0.5))  # (3.5)


def c_star_factor(n: float) -> float:
    """Gamma((n+3)/2) Gamma(1/2) / Gamma(1 + n/2) = ((n+1)/2) B((n+1)/2, 1/2), with C* = c_star_factor(n) C, [S75] (3.5).

    Examples
    --------
    >>> round(c_star_factor(2.0), 14)   # 3 pi / 4, the factor of (4.17)
    2.35619449019234
    """
    n = check_n(n)
    return float(0.5 * (n + 1.0) * special.beta(0.5 * (n + 1.0), 0.5))  # (3.5)


def frictionless_indentation_constant(n: float) -> float:
    """Indentation constant A of a smooth power-law indenter, delta = A a^n / b^(n-1), [S75] (3.2), (3.5).

    Without friction (3.5a) holds with A* = 1, so A = a_star_factor(n) =
    sqrt(pi) Gamma(n/2) / (2 Gamma((n+1)/2)): 1 for the sphere (Hertz, after (3.19)),
    pi/2 for the cone.

    Examples
    --------
    >>> round(frictionless_indentation_constant(2.0), 14)
    1.0
    """
    return a_star_factor(n)  # A* = 1 in (3.5)


def compliance_ratio(n: float) -> float:
    """P*/P0* = n/(n+1): compliance of the power-law indenter over the flat punch's, [S75] (3.17).

    Holds for every friction coefficient (same mu, nu). Without friction P0* = 1.

    Examples
    --------
    >>> compliance_ratio(2.0)
    0.6666666666666666
    """
    n = check_n(n)
    return n / (n + 1.0)  # (3.17)


def central_pressure_ratio(n: float) -> float:
    """p(0)/p0(0) = n/(n-1): central pressure over the flat punch's, [S75] (3.18), for n > 1.

    For n <= 1 the power-law pressure is unbounded at the apex and ``ValueError`` is raised.

    Examples
    --------
    >>> central_pressure_ratio(2.0)
    2.0
    """
    n = check_n(n)
    if not n > 1.0:
        raise ValueError(f"n must be > 1 for a finite central pressure (3.18), got {n!r}")
    return n / (n - 1.0)  # (3.18)


# Below x^2 = 1/2 the argument z = 1 - x^2 of the 2F1 form would lose x^2 to rounding;
# there each n gets a form in x^2 instead (module docstring of the derivation, entry
# "frictionless-n"). The x^2-form has poles at odd n >= 3 that cancel between its terms;
# within _ODD_GAP of them the z-form is used, whose error there is 2e-15
# (tests/test_derive_similarity.py checks both against mpmath).
_ODD_GAP = 0.05


def _pressure_z_form(x: np.ndarray, n: float) -> np.ndarray:
    z = (1.0 - x) * (1.0 + x)  # exact near x = 1
    return (2.0 * n / np.pi) * np.sqrt(z) * special.hyp2f1(1.0, 1.0 - 0.5 * n, 1.5, z)


def _pressure_small_x(x: np.ndarray, n: float) -> np.ndarray:
    """p(x) for 0 < x < 1/sqrt(2)."""
    a = 0.5 * (1.0 - n)
    if n < 1.0:  # int_x^1 t^-n (1-t^2)^-1/2 dt = (1/2) B(a, 1/2) I_{1-x^2}(1/2, a), complement in x^2
        return (n / np.pi) * x ** (n - 1.0) * special.beta(a, 0.5) * special.betaincc(a, 0.5, x * x)
    if n == 1.0:  # (3.20)
        return (2.0 / np.pi) * (np.log1p(np.sqrt((1.0 - x) * (1.0 + x))) - np.log(x))
    odd = 2.0 * round(0.5 * (n - 1.0)) + 1.0
    if odd >= 3.0 and abs(n - odd) < _ODD_GAP:
        return _pressure_z_form(x, n)
    # n > 1: (1/2)[B(a, 1/2) - B_{x^2}(a, 1/2)] with B_z(a, b) = z^a 2F1(a, 1-b; a+1; z)/a.
    return (n / np.pi) * (x ** (n - 1.0) * special.beta(a, 0.5) - special.hyp2f1(a, 0.5, a + 1.0, x * x) / a)


def frictionless_pressure_power_law(x: ArrayLike, n: float) -> np.ndarray | float:
    """Pressure under a smooth power-law indenter z ~ r^n, [S75] (3.13) with (2.26).

    p(x) = n x^(n-1) int_x^1 t^(-n) (2/pi)(1 - t^2)^(-1/2) dt
         = (2n/pi) sqrt(1 - x^2) 2F1(1, 1 - n/2; 3/2; 1 - x^2),
    (4/pi) sqrt(1 - x^2) for the sphere (3.19), (2/pi) log((1 + sqrt(1 - x^2))/x) for the
    cone (3.20). Normalised as in (2.1) (by G delta / ((1 - nu) a)); the shear is zero.

    Parameters
    ----------
    x : array_like
        Radius over contact radius, 0 <= x <= 1.
    n : float
        Exponent of the indenter, n > 0.

    Returns
    -------
    p : float or ndarray
        p(1) = 0 (3.7); p(0) = 2n/((n-1) pi) for n > 1 (3.18) and inf for n <= 1
        (the apex of a cone or a cusp carries an unbounded pressure).

    Notes
    -----
    Relative accuracy about 1e-15 (measured against mpmath at 80 digits), except for
    1 < n < 1.01 and x < 0.7, where the two terms of the x^2-form cancel to
    leave about 4e-16/(n - 1).

    Examples
    --------
    >>> round(float(frictionless_pressure_power_law(0.6, 2.0)), 15)   # (4/pi) 0.8
    1.01859163578813
    >>> float(frictionless_pressure_power_law(0.0, 3.0)) == 3.0 / np.pi   # (3.18): (3/2)(2/pi)
    True
    """
    n = check_n(n)
    xs = check_x(x)
    flat = xs.ravel()
    out = np.empty(flat.shape)
    centre = flat == 0.0
    out[centre] = 2.0 * n / ((n - 1.0) * math.pi) if n > 1.0 else math.inf  # (3.18)
    outer = flat * flat >= 0.5
    out[outer] = _pressure_z_form(flat[outer], n)
    inner = ~outer & ~centre
    if np.any(inner):
        out[inner] = _pressure_small_x(flat[inner], n)
    return scalar_or_array(out.reshape(xs.shape))
