"""The largest stick radius c_max(gamma): the limit mu -> inf of the stick radius (beyond [S75]).

[S75] (2.29) says c -> 1 as mu -> inf; that is the first-order law's limit (gamma -> 0 first).
At finite gamma the slip annulus never closes: c increases to c_max(gamma) < 1, where the
annulus carries shear but no pressure (p = q/mu -> 0) and the pressure at the stick edge has
no logarithm (the limit problem, ``numeric.core.eigenvalue`` at theta = pi/2).

Found by this project, from the limit problem: c_max is the modulus whose complete elliptic
integrals have the ratio kappa of the adhesive solution,

    K'(c_max) / K(c_max) = kappa = (2/pi) atanh(gamma) = (1/pi) log(3 - 4 nu),

i.e. c_max is the complementary modulus of the nome q = exp(-pi/kappa):

    c_max = theta_4(q)^2 / theta_3(q)^2,
    1 - c_max = 8 q - 32 q^2 + 96 q^3 - 256 q^4 + ...         (q = exp(-pi/kappa)).

The relation is not proved here; it is what the limit problem gives, to 1e-12 relative in
1 - c_max for gamma from 0.2 to 0.75 (``tests/test_largest_stick_radius.py``). The first term
is the 8 exp(-pi/kappa) measured before; 8 exp(-pi/kappa) is four times the distance from the
edge of the first zero of the adhesive g = cos(kappa atanh x) (App. B).

The approach as mu -> inf is linear in 1/mu: (1 - c) - (1 - c_max) = A(gamma) / (mu gamma) + O(mu^-2),
with A measured by the limit problem (``numeric.solutions.limits``).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from functools import lru_cache

import mpmath
import numpy as np
from numpy.typing import ArrayLike

from .arrays import scalar_or_array
from .materials import check_gamma

__all__ = ["nome", "largest_stick_radius_gap", "largest_stick_radius", "largest_stick_radius_mp",
           "largest_stick_radius_gap_mp"]

_TERMS = 6  # theta series terms: q^(n^2) with n <= 6; q <= exp(-pi/kappa(3/4)) = 6.3e-3 so q^36 < 1e-79


def nome(gamma: ArrayLike) -> np.ndarray | float:
    """q = exp(-pi/kappa), kappa = (2/pi) atanh(gamma) (0 at gamma = 0)."""
    g = np.asarray(check_gamma(gamma), dtype=float)
    with np.errstate(divide="ignore", over="ignore"):  # pi/kappa beyond the doubles (subnormal gamma): q = 0
        out = np.where(g > 0.0, np.exp(-math.pi / np.where(g > 0.0, (2.0 / math.pi) * np.arctanh(g), 1.0)), 0.0)
    return scalar_or_array(out)


def largest_stick_radius_gap(gamma: ArrayLike) -> np.ndarray | float:
    """1 - c_max(gamma) = (theta_3^2 - theta_4^2)/theta_3^2 at q = exp(-pi/kappa), formed without cancellation.

    theta_3 - theta_4 = 4 (q + q^9 + q^25 + ...), theta_3 + theta_4 = 2 (1 + 2 q^4 + 2 q^16 + ...).
    Underflows to 0 for gamma below about 0.06 (1 - c_max < 1e-300).

    Examples
    --------
    >>> f"{float(largest_stick_radius_gap(0.5)):.12e}"   # nu = 0
    '1.002998542160e-03'
    """
    if isinstance(gamma, (float, np.floating)):
        return _gap_scalar(float(gamma))  # a solve asks for it several times at one gamma
    return _gap(gamma)


@lru_cache(maxsize=64)
def _gap_scalar(gamma: float) -> float:
    return _gap(gamma)


def _gap(gamma: ArrayLike) -> np.ndarray | float:
    q = np.asarray(nome(gamma), dtype=float)
    n = np.arange(1, _TERMS + 1)
    odd, even = n[n % 2 == 1], n[n % 2 == 0]
    qq = q[..., None]
    difference = 4.0 * np.sum(qq ** (odd**2), axis=-1)
    total = 2.0 + 4.0 * np.sum(qq ** (even**2), axis=-1)
    theta3 = 1.0 + 2.0 * np.sum(qq ** (n**2), axis=-1)
    return scalar_or_array(difference * total / theta3**2)


def largest_stick_radius(gamma: ArrayLike) -> np.ndarray | float:
    """c_max(gamma) = theta_4(q)^2 / theta_3(q)^2, q = exp(-pi/kappa): K'(c_max)/K(c_max) = kappa."""
    return scalar_or_array(1.0 - np.asarray(largest_stick_radius_gap(gamma), dtype=float))


def largest_stick_radius_gap_mp(gamma, dps: int = 30):
    """1 - c_max by mpmath: 1 - theta_4(q)^2/theta_3(q)^2 at q = exp(-pi/kappa), at enough digits
    that the difference keeps ``dps`` (1 - c_max ~ 8 q)."""
    g = mpmath.mpf(gamma)
    if g == 0:
        return mpmath.mpf(0)
    with mpmath.workdps(dps):
        kappa = 2 * mpmath.atanh(g) / mpmath.pi
        q = mpmath.exp(-mpmath.pi / kappa)
    extra = int(-mpmath.log10(q)) + 10 if q > 0 else 10
    with mpmath.workdps(dps + extra):
        kappa = 2 * mpmath.atanh(g) / mpmath.pi
        q = mpmath.exp(-mpmath.pi / kappa)
        return +(1 - mpmath.jtheta(4, 0, q) ** 2 / mpmath.jtheta(3, 0, q) ** 2)


def largest_stick_radius_mp(gamma, dps: int = 30):
    """c_max by mpmath (see ``largest_stick_radius_gap_mp``)."""
    with mpmath.workdps(dps):
        return 1 - largest_stick_radius_gap_mp(gamma, dps)
