"""The fully adhesive punch: closed forms of [S75] Appendix B, (4.10) and (4.18).

With c = 1 no point of the contact slips and the problem has an exact solution
(Spence 1968, Keer 1967). Everything here depends on gamma only (through
kappa = (2/pi) atanh gamma); each function takes ``gamma``, so it serves dissimilar
bodies as well (``materials.gamma_dissimilar``).

Flat punch
    compliance_adhesive        P0* = pi kappa / (2 gamma) = atanh(gamma)/gamma   (B4)
    central_pressure_adhesive  p0(0) = (kappa/gamma) cosh(pi kappa / 2)         (4.10)
    shear_slope_adhesive       lim q0(x)/x = kappa p0(0) / 2                    (4.10)
    pressure_adhesive,         p0(x), q0(x) by quadrature of (B3)
    shear_adhesive
Sphere (n = 2)
    sphere_central_pressure_adhesive  p(0) = 2 p0(0)                            (B6)
    sphere_pressure_slope_adhesive    p'(0) = -2 p0(0) kappa gamma              (B6)
    psi1                              Psi1(kappa) = sum (-1)^n (kappa/2)^(2n) eta(2n+1)
    sphere_A_adhesive, sphere_C_adhesive  A, C of (4.18)

Each has a numpy evaluator; the ``*_mp`` functions are independent mpmath evaluations
(direct series or direct quadrature of (B3)) used as oracles in the tests.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import numpy as np
from numpy.typing import ArrayLike
from scipy import special

from .arrays import scalar_or_array
from .materials import check_gamma, kappa_from_gamma

__all__ = [
    "compliance_adhesive",
    "central_pressure_adhesive",
    "shear_slope_adhesive",
    "pressure_adhesive",
    "shear_adhesive",
    "pressure_adhesive_mp",
    "shear_adhesive_mp",
    "sphere_central_pressure_adhesive",
    "sphere_pressure_slope_adhesive",
    "psi1",
    "psi1_mp",
    "sphere_A_adhesive",
    "sphere_C_adhesive",
]


def _atanh_over(gamma: np.ndarray) -> np.ndarray:
    """atanh(gamma)/gamma with its limit 1 at gamma = 0."""
    safe = np.where(gamma == 0.0, 0.5, gamma)
    return np.where(gamma == 0.0, 1.0, np.arctanh(safe) / safe)


def compliance_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Compliance factor of the adhesive flat punch, P0* = pi kappa/(2 gamma), [S75] (B4).

    Equal to atanh(gamma)/gamma = (1/(2 gamma)) log((1+gamma)/(1-gamma)), the upper end
    of the range 1 <= P* <= P0* of Shield & Anderson (§2.1).

    Examples
    --------
    >>> round(float(compliance_adhesive(0.5)), 11)   # log 3
    1.09861228867
    """
    g = check_gamma(gamma)
    return scalar_or_array(_atanh_over(g))  # (B4)


def central_pressure_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Central pressure of the adhesive flat punch, p0(0) = (kappa/gamma) cosh(pi kappa/2), (4.10).

    Tends to the frictionless 2/pi as gamma -> 0.

    Examples
    --------
    >>> round(float(central_pressure_adhesive(0.5)), 12)
    0.807595599478
    """
    g = check_gamma(gamma)
    kappa = np.asarray(kappa_from_gamma(g))
    return scalar_or_array((2.0 / np.pi) * _atanh_over(g) * np.cosh(0.5 * np.pi * kappa))  # (4.10)


def shear_slope_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Limit of q0(x)/x at the centre of the adhesive flat punch, kappa p0(0)/2, [S75] (4.10)."""
    g = check_gamma(gamma)
    kappa = np.asarray(kappa_from_gamma(g))
    return scalar_or_array(0.5 * kappa * np.asarray(central_pressure_adhesive(g)))  # (4.10)


# Gauss-Legendre rule on (0, pi/2) for the (B3) integrals; 160 nodes reach 1e-14
# relative for 0 <= x <= 1 - 1e-15 (tests/test_adhesive.py checks against mpmath).
@lru_cache(maxsize=1)
def _psi_rule() -> tuple[np.ndarray, np.ndarray]:
    nodes, weights = np.polynomial.legendre.leggauss(160)
    return 0.25 * np.pi * (nodes + 1.0), 0.25 * np.pi * weights


def _b3_integrals(x: np.ndarray, kappa: float) -> tuple[np.ndarray, np.ndarray]:
    """I_p(x), I_q(x) with p0 = p0(0)(2/pi) I_p, q0 = p0(0)(2/pi) I_q, for 0 < x < 1.

    (B3) with w = tanh(tau) becomes int_0^theta_x (cos kappa tau, (tanh tau / x) sin kappa tau)
    dtau / sqrt(x^2 - tanh^2 tau), theta_x = atanh x. With tau = theta_x sin(psi) the
    inverse-square-root end point is removed, and
    x^2 - tanh^2 tau = sinh(theta_x - tau)(x + tanh tau)/(cosh theta_x cosh tau),
    theta_x - tau = theta_x cos^2 psi / (1 + sin psi), is free of cancellation.
    """
    psi, weights = _psi_rule()
    theta_x = np.arctanh(x)[:, None]
    sin_psi, cos_psi = np.sin(psi), np.cos(psi)
    tau = theta_x * sin_psi
    gap = theta_x * cos_psi**2 / (1.0 + sin_psi)
    xx = x[:, None]
    root = np.sqrt(np.sinh(gap) * (xx + np.tanh(tau)) / (np.cosh(theta_x) * np.cosh(tau)))
    jac = theta_x * cos_psi / root
    i_p = (jac * np.cos(kappa * tau)) @ weights
    i_q = (jac * np.tanh(tau) / xx * np.sin(kappa * tau)) @ weights
    return i_p, i_q


def _b3(x: ArrayLike, gamma: float) -> tuple[np.ndarray, np.ndarray]:
    g = float(check_gamma(gamma))
    xs = np.asarray(x, dtype=float)
    if np.any(np.isnan(xs)) or np.any((xs < 0.0) | (xs >= 1.0)):
        raise ValueError(f"x must lie in [0, 1) (the stresses are singular at x = 1), got {x!r}")
    kappa = float(kappa_from_gamma(g))
    p_centre = float(central_pressure_adhesive(g))
    flat = xs.ravel()
    p = np.full(flat.shape, p_centre)
    q = np.zeros(flat.shape)
    inner = flat > 0.0
    if np.any(inner):
        i_p, i_q = _b3_integrals(flat[inner], kappa)
        p[inner] = p_centre * (2.0 / np.pi) * i_p  # (B3)
        q[inner] = p_centre * (2.0 / np.pi) * i_q  # (B3)
    return p.reshape(xs.shape), q.reshape(xs.shape)


def pressure_adhesive(x: ArrayLike, gamma: float) -> np.ndarray | float:
    """Contact pressure p0(x) of the adhesive flat punch, [S75] (B3).

    Parameters
    ----------
    x : array_like
        Radius over contact radius, 0 <= x < 1.
    gamma : float
        Coupling constant, 0 <= gamma <= 3/4.

    Examples
    --------
    >>> round(float(pressure_adhesive(0.0, 0.5)), 12)
    0.807595599478
    """
    return scalar_or_array(_b3(x, gamma)[0])


def shear_adhesive(x: ArrayLike, gamma: float) -> np.ndarray | float:
    """Shear traction q0(x) of the adhesive flat punch, [S75] (B3); q0(0) = 0."""
    return scalar_or_array(_b3(x, gamma)[1])


def _b3_mp(x, gamma, component: int, dps: int):
    """(B3) in mpmath. With w = x - u^2 the inverse square root at w = x goes; the pole of
    1/(1 - w^2) at distance 1 - x from the end is resolved by breakpoints u = sqrt(1-x) 4^k."""
    with mpmath.workdps(dps):
        x = mpmath.mpf(x)
        gamma = mpmath.mpf(gamma)
        kappa = 2 * mpmath.atanh(gamma) / mpmath.pi
        p_centre = (kappa / gamma if gamma else 2 / mpmath.pi) * mpmath.cosh(mpmath.pi * kappa / 2)
        if x == 0:
            return p_centre if component == 0 else mpmath.mpf(0)

        def integrand(u):
            w = x - u * u
            theta = mpmath.atanh(w)
            shape = mpmath.cos(kappa * theta) if component == 0 else w / x * mpmath.sin(kappa * theta)
            return 2 * shape / ((1 - x + u * u) * (1 + w) * mpmath.sqrt(x + w))

        top = mpmath.sqrt(x)
        scale = mpmath.sqrt(1 - x)
        points = [mpmath.mpf(0)] + [scale * 4**k for k in range(60) if scale * 4**k < top] + [top]
        return p_centre * 2 / mpmath.pi * mpmath.quad(integrand, points)


def pressure_adhesive_mp(x, gamma, dps: int = 30):
    """p0(x) of (B3) by tanh-sinh quadrature in mpmath at ``dps`` digits (an oracle)."""
    return _b3_mp(x, gamma, 0, dps)


def shear_adhesive_mp(x, gamma, dps: int = 30):
    """q0(x) of (B3) by tanh-sinh quadrature in mpmath at ``dps`` digits (an oracle)."""
    return _b3_mp(x, gamma, 1, dps)


def sphere_central_pressure_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Central pressure of the adhesive sphere (n = 2), p(0) = 2 p0(0), [S75] (B6), (3.18)."""
    return scalar_or_array(2.0 * np.asarray(central_pressure_adhesive(gamma)))  # (B6)


def sphere_pressure_slope_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Slope p'(0) = -2 p0(0) kappa gamma of the adhesive sphere's pressure, [S75] (B6).

    Examples
    --------
    >>> round(float(sphere_pressure_slope_adhesive(0.5)), 6)   # the paper's -.282415
    -0.282415
    """
    g = check_gamma(gamma)
    kappa = np.asarray(kappa_from_gamma(g))
    return scalar_or_array(-2.0 * np.asarray(central_pressure_adhesive(g)) * kappa * g)  # (B6)


def psi1(kappa: ArrayLike) -> np.ndarray | float:
    """Psi1(kappa) = sum_n (-1)^n (kappa/2)^(2n) eta(2n+1) of [S75] (4.18), by digamma.

    Expanding eta and summing the geometric series in n gives
    Psi1 = sum_k (-1)^(k-1) k / (k^2 + kappa^2/4)
         = Re[digamma(1 + i kappa/4) - digamma(1/2 + i kappa/4)] / 2,
    valid for all real kappa (the eta series itself needs |kappa| < 2).
    ``psi1_mp`` sums the eta series directly; the tests compare the two.

    Examples
    --------
    >>> round(float(psi1(0.0)), 15)   # log 2
    0.693147180559945
    """
    k = np.asarray(kappa, dtype=float)
    if np.any(np.isnan(k)):
        raise ValueError(f"kappa must not be NaN, got {kappa!r}")
    z = 0.25j * k
    value = 0.5 * (special.psi(1.0 + z) - special.psi(0.5 + z)).real
    return scalar_or_array(value)


def psi1_mp(kappa, dps: int = 30):
    """Psi1(kappa) of (4.18) by direct summation of the eta series in mpmath (|kappa| < 2)."""
    with mpmath.workdps(dps):
        half_sq = (mpmath.mpf(kappa) / 2) ** 2
        return mpmath.nsum(lambda n: (-half_sq) ** n * mpmath.altzeta(2 * n + 1), [0, mpmath.inf])


def sphere_A_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Indentation constant A = 1/(1 - kappa^2 Psi1(kappa)) of the adhesive sphere, [S75] (4.18).

    delta = A a^2 / R (3.2); A = 1 without friction (Hertz).

    Examples
    --------
    >>> round(1.0 / float(sphere_A_adhesive(0.5)), 9)   # errata table: 0.918498211
    0.918498211
    """
    g = check_gamma(gamma)
    kappa = np.asarray(kappa_from_gamma(g))
    return scalar_or_array(1.0 / (1.0 - kappa**2 * np.asarray(psi1(kappa))))  # (4.18)


def sphere_C_adhesive(gamma: ArrayLike) -> np.ndarray | float:
    """Stick-zone displacement constant C of the adhesive sphere, u = C x^2, [S75] (4.18).

    C = -(2/3) kappa^2 sqrt(3 - 4 nu)/(1 - 2 nu), written with 3 - 4 nu = (1+gamma)/(1-gamma)
    and 1 - 2 nu = gamma/(1 - gamma) as C = -(2/3)(kappa^2/gamma) sqrt(1 - gamma^2),
    which is 0 at gamma = 0.
    """
    g = check_gamma(gamma)
    kappa = np.asarray(kappa_from_gamma(g))
    kappa_sq_over = (2.0 / np.pi) * kappa * _atanh_over(g)  # kappa^2/gamma
    return scalar_or_array(-(2.0 / 3.0) * kappa_sq_over * np.sqrt(1.0 - g**2))  # (4.18)
