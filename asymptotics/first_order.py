"""The flat punch at first order in gamma: [S75] §2.3, (2.26)-(2.36).

Putting gamma = 0 in (2.2a) gives the frictionless pressure p^(0) = (2/pi)(1 - x^2)^(-1/2)
(2.26); with it, (2.12) and chi(c) = 0 (2.13) give the first-order friction law

    mu/gamma = f0(c) = atanh(c) / (c K'(c)),   K'(c) = K(sqrt(1 - c^2)),      (2.28)

and (2.14) the shear q^(0) = mu p^(0) (1 - psi(x, c)) on the stick zone (2.30), (2.31).
Everything here is the leading term of an expansion in gamma at fixed c (mu = O(gamma)):
exact as gamma -> 0, an approximation for real materials (gamma = 2/7 for nu = 0.3).

Functions (numpy, vectorised; the ``*_mp`` twins evaluate the same result in mpmath):

    frictionless_pressure      p^(0)(x)                                        (2.26)
    chi0                       the first-order excess friction chi^(0)(x)      (2.27)
    mu_over_gamma              f0(c)                                           (2.28)
    stick_radius_first_order   c for given mu, gamma: the inverse of (2.28)
    c_small_mu, c_large_mu     its limits (2.29) with correction terms
    psi, shear_ratio_first_order   psi(x, c) and q^(0)/(mu p^(0)) = 1 - psi   (2.30), (2.31)
    pressure_correction        P1 with p = p^(0) + gamma^2 P1 + ..., from (2.33)
    compliance_first_order     P* = 1 + gamma int (1 - sqrt(1 - t^2)) q^(0) dt  (2.34)

Elliptic integrals use SciPy's and mpmath's parameter m = k^2: K'(c) = ``ellipkm1(c**2)``,
exact for tiny c. The SymPy derivations of these results are in
``asymptotics.derive.first_order`` (registry entries "(2.26)" ... "(2.36)").

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
from scipy import special

from .arrays import scalar_or_array
from .materials import check_c, check_gamma, check_mu, check_x, resolve_gamma

__all__ = [
    "frictionless_pressure",
    "chi0",
    "mu_over_gamma",
    "mu_over_gamma_mp",
    "mu_over_gamma_log_slope",
    "stick_radius_first_order",
    "stick_radius_first_order_mp",
    "c_small_mu",
    "c_large_mu",
    "one_minus_c_large_mu",
    "SMALL_MU_COEFFICIENTS",
    "LARGE_MU_COEFFICIENTS",
    "psi",
    "psi_mp",
    "shear_ratio_first_order",
    "shear_ratio_first_order_mp",
    "pressure_correction",
    "pressure_correction_mp",
    "compliance_first_order",
    "compliance_first_order_mp",
    "shear_moment_first_order",
    "tanh_sinh_rule",
]


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

    Exact in the limit gamma -> 0 at fixed c; inf at c = 1. Below c = 1e-150, where c^2
    underflows, K'(c) = log(4/c) (error below c^2 log(1/c)).

    Examples
    --------
    >>> round(float(mu_over_gamma(0.5)), 12)
    0.509438589023
    """
    cs = check_c(c)
    with np.errstate(divide="ignore"):
        ratio = np.arctanh(cs) / (cs * _k_prime(cs))  # (2.28)
    return ratio[()] if ratio.ndim == 0 else ratio


def mu_over_gamma_mp(c, dps: int = 30):
    """f0(c) = atanh(c)/(c K'(c)) of (2.28) in mpmath at ``dps`` digits (inf at c = 1)."""
    extra = max(0, int(-2 * mpmath.log10(mpmath.mpf(c)))) if c > 0 else 0  # 1 - c^2 must keep c^2
    with mpmath.workdps(dps + extra):
        c = mpmath.mpf(c)
        if c == 1:
            return mpmath.inf
        return mpmath.atanh(c) / (c * mpmath.ellipk(1 - c * c))  # (2.28)


def chi0(x: ArrayLike, mu_over_gamma_value: float) -> np.ndarray | float:
    """First-order excess-friction function chi^(0)(x) of [S75] (2.27).

    chi^(0)(x) = (2/pi) [x K'(x) - (gamma/mu) atanh(x)],  K'(x) = K(sqrt(1 - x^2)),

    i.e. chi of (2.12) with the frictionless pressure (2.26); its root in (0, 1) is the
    first-order stick radius of (2.28). chi^(0)(0) = 0 (x K'(x) ~ x log(4/x)).

    Parameters
    ----------
    x : array_like
        0 <= x < 1.
    mu_over_gamma_value : float
        mu/gamma > 0.

    Examples
    --------
    >>> abs(float(chi0(0.5, 0.5094385890229398))) < 1e-14   # the root c = 0.5 of (2.28): O(1) terms cancel
    True
    """
    xs = np.asarray(x, dtype=float)
    if np.any(np.isnan(xs)) or np.any((xs < 0.0) | (xs >= 1.0)):
        raise ValueError(f"x must lie in [0, 1), got {x!r}")
    ratio = float(mu_over_gamma_value)
    if not ratio > 0.0 or math.isinf(ratio):
        raise ValueError(f"mu_over_gamma_value must be finite and > 0, got {mu_over_gamma_value!r}")
    x_k = np.zeros(xs.shape)
    inside = xs > 0.0
    x_k[inside] = xs[inside] * special.ellipkm1(xs[inside] ** 2)  # x K'(x), K'(x) = K(m = 1 - x^2)
    return scalar_or_array((2.0 / np.pi) * (x_k - np.arctanh(xs) / ratio))  # (2.27)


# ---------------------------------------------------------------------------------------
# Elliptic helpers (parameter m = k^2)

def _k_prime(c: np.ndarray) -> np.ndarray:
    """K'(c) = K(m = 1 - c^2) for 0 < c < 1; log(4/c) where c^2 would underflow (error < c^2 log)."""
    tiny = c < 1e-150
    safe = np.where(tiny, 0.5, c)
    with np.errstate(divide="ignore"):  # c = 1: K(0) is finite, c = 0 is excluded by the callers
        return np.where(tiny, np.log(4.0) - np.log(np.where(tiny, c, 1.0)), special.ellipkm1(safe**2))


# (K(m) - E(m))/m = (pi/2) sum_{n>=1} ((1/2)_n/n!)^2 (2n/(2n-1)) m^(n-1), for m <= 1/2
# (the direct difference cancels as m -> 0); 60 terms reach 2^-60 < 1e-18.
@lru_cache(maxsize=1)
def _k_minus_e_coefficients() -> np.ndarray:
    coeffs, a = [], 1.0
    for n in range(1, 61):
        a *= ((n - 0.5) / n) ** 2
        coeffs.append(0.5 * np.pi * a * 2 * n / (2 * n - 1))
    return np.array(coeffs)


def _k_minus_e_over_m(m: np.ndarray, k_of_m: np.ndarray) -> np.ndarray:
    """(K(m) - E(m))/m for 0 < m < 1, given K(m) (from ``_k_prime``, accurate as m -> 1):
    a series as m -> 0, where the difference cancels."""
    small = m <= 0.5
    series = np.polynomial.polynomial.polyval(np.where(small, m, 0.0), _k_minus_e_coefficients())
    big = np.where(small, 0.75, m)
    direct = (np.where(small, 2.0, k_of_m) - special.ellipe(big)) / big
    return np.where(small, series, direct)


# ---------------------------------------------------------------------------------------
# (2.29): the limits of the inverse of (2.28), with the next terms

#: c = 4 exp(-E) (1 + sum_j a_j(E) z^j), E = gamma/mu, z = exp(-2E); a_j as polynomial
#: coefficients in E (lowest first). Derived in asymptotics.derive.first_order "(2.29)".
SMALL_MU_COEFFICIENTS: tuple[tuple[float, ...], ...] = (
    (-4.0, -4.0 / 3.0),
    (14.0, 84.0 / 5.0, 40.0 / 9.0),
    (-40.0, -10648.0 / 105.0, -1232.0 / 15.0, -1568.0 / 81.0),
)

#: 1 - c = 2 w (1 + sum_j b_j(M) w^j), M = mu/gamma, w = exp(-pi M); b_j as polynomial
#: coefficients in pi M (lowest first). Derived in asymptotics.derive.first_order "(2.29)".
LARGE_MU_COEFFICIENTS: tuple[tuple[float, ...], ...] = (
    (-1.0, 1.0),
    (1.0, -9.0 / 4.0, 3.0 / 2.0),
    (-1.0, 15.0 / 4.0, -5.0, 8.0 / 3.0),
)


def _check_terms(terms: int) -> int:
    if terms not in (1, 2, 3, 4):
        raise ValueError(f"terms must be 1, 2, 3 or 4 (leading term plus up to 3 corrections), got {terms!r}")
    return terms


def _ratio(mu: ArrayLike, gamma: float) -> np.ndarray:
    mus = check_mu(mu)
    g = float(check_gamma(gamma))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # mu/gamma beyond the doubles is inf: c = 1
        return np.where(mus == 0.0, 0.0, mus / g) if g > 0.0 else np.where(mus == 0.0, 0.0, np.inf)


def _small_mu_series(e: np.ndarray, terms: int) -> np.ndarray:
    """c from E = gamma/mu by the small-mu expansion; 0 where E is infinite or c underflows (E > 800:
    4 exp(-E) < 1e-347, while the correction polynomials would overflow)."""
    finite = np.isfinite(e) & (e <= 800.0)
    ef = np.where(finite, e, 1.0)
    z = np.exp(-2.0 * ef)
    factor = np.ones_like(ef)
    for j, coeffs in enumerate(SMALL_MU_COEFFICIENTS[: terms - 1], start=1):
        factor += np.polynomial.polynomial.polyval(ef, coeffs) * z**j
    return np.where(finite, np.exp(np.log(4.0) - ef) * factor, 0.0)  # (2.29)


def one_minus_c_large_mu(ratio: np.ndarray, terms: int) -> np.ndarray:
    """1 - c from M = mu/gamma (an array) by the large-mu expansion (2.29) with ``terms`` terms; 0 where M
    is infinite or so large that exp(-pi M) underflows (pi M > 800), where the correction polynomials would
    overflow. The complement itself, free of the rounding of c = 1 - (1 - c) (``c_large_mu``)."""
    live = np.isfinite(ratio) & (np.pi * np.where(np.isfinite(ratio), ratio, 0.0) <= 800.0)
    pm = np.pi * np.where(live, ratio, 1.0)
    w = np.exp(-pm)
    factor = np.ones_like(pm)
    for j, coeffs in enumerate(LARGE_MU_COEFFICIENTS[: terms - 1], start=1):
        factor += np.polynomial.polynomial.polyval(pm, coeffs) * w**j
    return np.where(live, 2.0 * w * factor, 0.0)  # (2.29)


def c_small_mu(mu: ArrayLike, gamma: float, terms: int = 3) -> np.ndarray | float:
    """Stick radius for small mu/gamma: c ~ 4 exp(-gamma/mu) (1 + ...), [S75] (2.29).

    A limit of the FIRST-ORDER law (2.28) (gamma -> 0 at fixed c), not of the full problem.
    With E = gamma/mu and z = exp(-2E),

        c = 4 exp(-E) [1 - (4E/3 + 4) z + (40E^2/9 + 84E/5 + 14) z^2
                       - (1568E^3/81 + 1232E^2/15 + 10648E/105 + 40) z^3 + ...];

    ``terms`` = 1 is the paper's leading term, each further term adds one power of z.
    Relative error against the exact inverse of (2.28): O(E^terms z^terms)
    (tests/test_derive_first_order.py measures it).

    Examples
    --------
    >>> import math
    >>> round(float(c_small_mu(0.025, 0.5, terms=1)) / (4 * math.exp(-20)), 12)   # mu/gamma = 1/20
    1.0
    """
    ratio = _ratio(mu, gamma)
    with np.errstate(divide="ignore"):
        e = np.where(ratio == 0.0, np.inf, 1.0 / np.where(ratio == 0.0, 1.0, ratio))
    return scalar_or_array(_small_mu_series(e, _check_terms(terms)))


def c_large_mu(mu: ArrayLike, gamma: float, terms: int = 3) -> np.ndarray | float:
    """Stick radius for large mu/gamma: 1 - c ~ 2 exp(-pi mu/gamma) (1 + ...), [S75] (2.29).

    A limit of the FIRST-ORDER law (2.28) (gamma -> 0 at fixed c), not of the full problem
    (the full solution may have a largest stick radius below 1 for larger gamma; see the
    README). With M = mu/gamma and w = exp(-pi M),

        1 - c = 2 w [1 + (pi M - 1) w + (3 (pi M)^2/2 - 9 pi M/4 + 1) w^2
                     + (8 (pi M)^3/3 - 5 (pi M)^2 + 15 pi M/4 - 1) w^3 + ...].

    ``terms`` = 1 is the paper's leading term. Returns c; 1 - c below 1e-16 is lost in
    rounding (use the formula above for the complement itself).

    Examples
    --------
    >>> import math
    >>> float(c_large_mu(1.0, 0.5, terms=1)) == 1 - 2 * math.exp(-2 * math.pi)   # mu/gamma = 2
    True
    """
    ratio = _ratio(mu, gamma)
    return scalar_or_array(1.0 - one_minus_c_large_mu(ratio, _check_terms(terms)))


def _log_f0_and_slope(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """log f0(c) and d log f0 / du at c = tanh(theta), theta = exp(u).

    log f0 = log(theta/c) - log K'(c); d/du = 1 - theta (K' - E')/(c K'), K' - E' = K(k) - E(k),
    k^2 = 1 - c^2 = sech^2(theta) (no cancellation near c = 1, where theta is large).
    """
    theta = np.exp(u)
    c = np.tanh(theta)
    m = 1.0 / np.cosh(theta) ** 2  # k^2 = 1 - c^2
    kp = _k_prime(c)
    k_minus_e = m * _k_minus_e_over_m(m, kp)
    # log f0 = log(theta/tanh theta) - log K'(c): no cancellation between u and log c
    log_theta_over_c = np.where(theta < 1e-8, theta * theta / 3.0, np.log(theta / np.where(theta < 1e-8, 1.0, c)))
    return log_theta_over_c - np.log(kp), 1.0 - theta * k_minus_e / (c * kp)


def mu_over_gamma_log_slope(c: ArrayLike) -> np.ndarray | float:
    """d log f0 / d log c of (2.28) for 0 < c < 1: a relative error e of mu moves c by e over this.

    Analytic: d log f0/du = 1 - theta (K' - E')/(c K') at u = log(theta), theta = atanh(c), and
    du/d log c = c / (theta (1 - c^2)). It rises from about 1/log(4/c) at small c (f0 ~ 1/log(4/c))
    without bound as c -> 1 (f0 ~ (2/pi) atanh(c)).

    Examples
    --------
    >>> round(float(mu_over_gamma_log_slope(0.5)), 12)
    0.629092283773
    """
    cs = check_c(c)
    if np.any(cs >= 1.0):
        raise ValueError(f"c (stick radius / contact radius) must lie in (0, 1), got {c!r}")
    theta = np.arctanh(cs)
    slope_u = _log_f0_and_slope(np.log(theta))[1]
    return scalar_or_array(slope_u * cs / (theta * (1.0 - cs) * (1.0 + cs)))


def _stick_radius_order0(ratio: np.ndarray) -> np.ndarray:
    """Invert (2.28) elementwise: Newton in u = log(atanh c), started from (2.29).

    E = 1/ratio > 24: the small-mu series with 4 terms is exact to rounding (its next term
    is below E^4 exp(-8E) < 1e-60 relative); ratio > 12: 1 - c < 1e-16, so c = 1 in double
    precision. In between Newton on the monotone log f0(u) converges in a few steps.
    """
    c = np.empty_like(ratio)
    small = ratio < 1.0 / 24.0
    large = ratio > 12.0
    with np.errstate(divide="ignore"):
        c[small] = _small_mu_series(np.where(ratio[small] == 0.0, np.inf, 1.0 / np.maximum(ratio[small], 1e-300)), 4)
    c[large] = 1.0 - one_minus_c_large_mu(ratio[large], 4)
    mid = ~(small | large)
    if np.any(mid):
        r = ratio[mid]
        guess_small = _small_mu_series(1.0 / r, 4)
        guess_large = 1.0 - one_minus_c_large_mu(r, 4)
        # theta from the better asymptote; atanh(c) of the large-mu guess via the complement
        theta_small = np.arctanh(np.clip(guess_small, 1e-300, 0.5))  # used where r < 1/2 only
        eta = np.maximum(1.0 - guess_large, 1e-300)
        theta_large = 0.5 * np.log((2.0 - eta) / eta)
        u = np.log(np.where(r < 0.5, theta_small, theta_large))
        target = np.log(r)
        for _ in range(50):
            value, slope = _log_f0_and_slope(u)
            step = (value - target) / slope
            u = u - step
            if np.all(np.abs(step) <= 1e-14 * np.maximum(1.0, np.abs(u))):
                break
        else:  # pragma: no cover - the iteration is monotone and quadratic
            raise RuntimeError("stick_radius_first_order: Newton iteration did not converge")
        c[mid] = np.tanh(np.exp(u))
    return c


def stick_radius_first_order(mu: ArrayLike, nu: float | None = None, *, gamma: float | None = None) -> np.ndarray | float:
    """Stick radius c for friction mu: the inverse of the first-order law (2.28), [S75].

    Solves mu/gamma = f0(c) = atanh(c)/(c K'(c)) for c, the gamma -> 0 limit at fixed
    mu/gamma (``asymptotics.second_order.stick_radius_second_order`` adds gamma^2 f2;
    ``asymptotics.stick_radius`` takes the order as an argument). For the full problem use
    ``numeric.stick_radius``.

    Parameters
    ----------
    mu : array_like
        Friction coefficient, >= 0 (inf allowed).
    nu : float, optional
        Poisson's ratio; give exactly one of ``nu`` and ``gamma``.
    gamma : float, optional
        Coupling constant (2.2), 0 <= gamma <= 3/4.

    Returns
    -------
    c : float or ndarray
        c(0) = 0, c(inf) = 1 (also for gamma = 0 and mu > 0). Relative accuracy ~1e-15 in
        c (c small) and in 1 - c (c near 1, down to the 1e-16 spacing of doubles below 1;
        c = 1.0 once mu/gamma > 12). For mu/gamma < 1/24 the series (2.29) with three
        correction terms is used (exact to rounding there); c underflows to 0 below
        mu/gamma ~ 1/744.

    Examples
    --------
    >>> round(float(stick_radius_first_order(0.509438589023 / 2, gamma=0.5)), 10)
    0.5

    The inversion is conditioned by log(4/c): a relative change of 1e-16 in mu/gamma moves
    c by log(4/c) 1e-16 relative.
    """
    return scalar_or_array(_stick_radius_order0(_ratio(mu, resolve_gamma(nu, gamma))))


def stick_radius_first_order_mp(mu_over_gamma_value, dps: int = 30):
    """The inverse of (2.28) in mpmath: c with f0(c) = mu/gamma, by a bracketing root finder.

    Solves log theta - log(tanh(theta) K(sech^2 theta)) = log(mu/gamma) for
    u = log(theta), theta = atanh(c), bracketed by the crude bounds
    theta in [0.1 * 4 exp(-gamma/mu), pi mu/(2 gamma) + 10] (independent of the fast code).
    """
    r0 = float(mu_over_gamma_value)
    extra = int(0.9 / r0) if r0 > 0 else 0  # 1 - c^2 must keep c^2 ~ 16 exp(-2 gamma/mu)
    with mpmath.workdps(dps + 10 + extra):
        r = mpmath.mpf(mu_over_gamma_value)
        if r == 0:
            return mpmath.mpf(0)
        if mpmath.isinf(r):
            return mpmath.mpf(1)

        def f(u):
            theta = mpmath.exp(u)
            return u - mpmath.log(mpmath.tanh(theta) * mpmath.ellipk(mpmath.sech(theta) ** 2)) - mpmath.log(r)

        lo = mpmath.log(mpmath.mpf("0.4") * mpmath.exp(-1 / r))
        hi = mpmath.log(mpmath.pi * r / 2 + 10)
        u = mpmath.findroot(f, (lo, hi), solver="anderson", tol=mpmath.mpf(10) ** (-2 * dps), verify=False)
        if abs(f(u)) > mpmath.mpf(10) ** (-dps - 5):
            raise ValueError(f"stick_radius_first_order_mp: no convergence for mu/gamma = {mu_over_gamma_value!r}")
        return +mpmath.tanh(mpmath.exp(u))


# ---------------------------------------------------------------------------------------
# (2.30), (2.31): psi(x, c) with Heuman's Lambda function

def _check_psi_args(x: ArrayLike, c: ArrayLike, *, whole: bool) -> tuple[np.ndarray, np.ndarray]:
    xs = check_x(x)
    cs = check_c(c)
    if np.any(cs >= 1.0):
        raise ValueError(f"c must lie in (0, 1) here (at c = 1, mu/gamma is infinite), got {c!r}")
    xs, cs = np.broadcast_arrays(xs, cs)
    if not whole and np.any(xs > cs):
        raise ValueError(f"x must lie in [0, c] (psi is defined on the stick zone), got x={x!r}, c={c!r}")
    if whole and np.any(xs >= 1.0):
        raise ValueError(f"x must lie in [0, 1), got {x!r}")
    return np.array(xs, dtype=float), np.array(cs, dtype=float)


def _atanh_over(y: np.ndarray) -> np.ndarray:
    """atanh(y)/y for 0 <= y < 1, 1 at y = 0."""
    small = y < 1e-8
    ys = np.where(small, 0.5, y)
    return np.where(small, 1.0 + y * y / 3.0, np.arctanh(ys) / ys)


def _atanh_minus_identity(y: np.ndarray) -> np.ndarray:
    """atanh(y) - y for 0 <= y < 1 without cancellation (series y^3/3 + y^5/5 + ... below 0.1)."""
    small = y < 0.1
    ys = np.where(small, y, 0.0)
    y2 = ys * ys
    series = ys * y2 * np.polynomial.polynomial.polyval(y2, [1.0 / (2 * j + 3) for j in range(14)])
    big = np.where(small, 0.5, y)
    return np.where(small, series, np.arctanh(big) - big)


def _psi_pair(x: np.ndarray, c: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(psi, 1 - psi) for 0 < x < c < 1, each without cancellation.

    psi = Lambda0(phi, k) - T, sin(phi) = omega/c, k = sqrt(1 - c^2) (a modulus: errata 6),
    Lambda0(phi, k) = (2/pi)[E(k) F(phi, c) + K(k) (E(phi, c) - F(phi, c))]  (B&F 150.01,
    k' = c), T = (2 c K'(c)/(pi x)) [omega/c - atanh(omega)/atanh(c)].
    Everything is written with xi = x/c and varpi = omega/c (O(1) as c -> 0):
    varpi^2 = (1 - xi^2)/(1 - x^2), 1 - varpi^2 = xi^2 (1 - c^2)/(1 - x^2).
    Near x = 0 (phi -> pi/2) the addition theorem F(phi) + F(beta) = K, E(phi) + E(beta) =
    E + c^2 sin(phi) sin(beta) with sin(beta) = xi gives
    1 - Lambda0 = (2/pi)[K(k)(E(beta, c) - omega x) - (K(k) - E(k)) F(beta, c)], and
    T = (2 K'(c)/(pi xi)) [atanh(delta)/atanh(c) - (1 - varpi)], delta = (c - omega)/(1 - c omega)
    (the ratio atanh(delta)/atanh(c) taken as (delta/c) (atanh(delta)/delta)/(atanh(c)/c))
    (atanh(c) - atanh(omega) = atanh(delta)); near x = c,
    T = (2 K'(c)/(pi xi)) [varpi (atanh c - c) - (atanh omega - omega)]/atanh(c).
    The incomplete integrals of parameter c^2 are taken in Carlson's form
    F = sin R_F(cos^2, Delta^2, 1), E - F = -(c^2/3) sin^3 R_D(cos^2, Delta^2, 1), whose
    arguments are exact differences (c^2 near 1 would cost digits in F(phi, c^2)).
    """
    one_m = (1.0 - c) * (1.0 + c)        # k^2 = 1 - c^2
    kk = _k_prime(c)                     # K(k) = K'(c)
    ek = special.ellipe(one_m)           # E(k)
    k_minus_e = one_m * _k_minus_e_over_m(one_m, kk)
    one_mx2 = (1.0 - x) * (1.0 + x)
    xi = x / c
    one_minus_xi = (c - x) / c
    varpi = np.sqrt(one_minus_xi * (1.0 + xi) / one_mx2)   # omega/c
    omega = c * varpi
    one_minus_varpi_over_xi = xi * one_m / (one_mx2 * (1.0 + varpi))  # not (xi^2 ...)/xi: xi may be subnormal
    one_minus_varpi = xi * one_minus_varpi_over_xi
    atanh_c = np.arctanh(c)
    psi_value, one_minus = np.empty_like(x), np.empty_like(x)
    near_centre = x < omega  # each form only where it is used: the direct one divides by xi
    d = ~near_centre
    if np.any(d):
        # direct form (x >= omega): sin(phi) = varpi, cos^2(phi) = xi^2 (1-c^2)/(1-x^2), Delta^2 = (1-c^2)/(1-x^2)
        sin_phi = np.minimum(varpi[d], 1.0)
        cos2_phi = xi[d] * xi[d] * one_m[d] / one_mx2[d]
        delta2_phi = one_m[d] / one_mx2[d]
        f_phi = sin_phi * special.elliprf(cos2_phi, delta2_phi, 1.0)
        e_minus_f_phi = -(c[d] * c[d] / 3.0) * sin_phi**3 * special.elliprd(cos2_phi, delta2_phi, 1.0)
        lam = (2.0 / np.pi) * (ek[d] * f_phi + kk[d] * e_minus_f_phi)  # B&F 150.01
        t_far = ((2.0 * kk[d] / (np.pi * xi[d])) * (varpi[d] * _atanh_minus_identity(c[d])
                                                    - _atanh_minus_identity(omega[d])) / atanh_c[d])
        psi_value[d] = lam - t_far  # (2.30)
        one_minus[d] = 1.0 - psi_value[d]
    n = near_centre
    if np.any(n):
        # complement form (x < omega): sin(beta) = xi, cos^2(beta) = 1 - xi^2, Delta^2 = 1 - x^2
        sin_beta = np.minimum(xi[n], 1.0)
        cos2_beta = one_minus_xi[n] * (1.0 + xi[n])
        f_beta = sin_beta * special.elliprf(cos2_beta, one_mx2[n], 1.0)
        e_beta = f_beta - (c[n] * c[n] / 3.0) * sin_beta**3 * special.elliprd(cos2_beta, one_mx2[n], 1.0)
        one_minus_lam = (2.0 / np.pi) * (kk[n] * (e_beta - omega[n] * x[n]) - k_minus_e[n] * f_beta)
        one_minus_c_omega = one_m[n] * (1.0 + c[n] * c[n] - x[n] * x[n]) / (one_mx2[n] * (1.0 + c[n] * omega[n]))
        delta_over_c = one_minus_varpi[n] / one_minus_c_omega
        # atanh(delta)/(atanh(c) (1 - varpi))
        ratio = _atanh_over(c[n] * delta_over_c) / (_atanh_over(c[n]) * one_minus_c_omega)
        one_minus[n] = one_minus_lam + (2.0 * kk[n] / np.pi) * one_minus_varpi_over_xi[n] * (ratio - 1.0)
        psi_value[n] = 1.0 - one_minus[n]
    return psi_value, one_minus


def _psi_both(xs: np.ndarray, cs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """_psi_pair with the end points x = 0 (psi = 1) and x >= c (psi = 0) set exactly."""
    value = np.where(xs <= 0.0, 1.0, 0.0)
    complement = np.where(xs <= 0.0, 0.0, 1.0)
    inner = (xs > 0.0) & (xs < cs)
    if np.any(inner):
        value[inner], complement[inner] = _psi_pair(xs[inner], cs[inner])
    return value, complement


def psi(x: ArrayLike, c: ArrayLike) -> np.ndarray | float:
    """psi(x, c) of [S75] (2.30): phi^(0) = (2/pi)(1 - x^2)^(-1/2) psi on the stick zone.

    psi = Lambda0(asin(omega/c), sqrt(1 - c^2))
          - (2c/(pi x)) K'(c) [omega/c - atanh(omega)/atanh(c)],
    omega = sqrt((c^2 - x^2)/(1 - x^2)), Lambda0 Heuman's function with its second argument
    a MODULUS (Byrd & Friedman 150.01; errata 6: this reading, not the parameter one,
    equals a direct evaluation of (2.14)). psi(0, c) = 1, psi(c, c) = 0.

    Parameters
    ----------
    x : array_like
        0 <= x <= c (broadcast against c).
    c : array_like
        Stick radius, 0 < c < 1.

    Examples
    --------
    >>> round(float(psi(0.3, 0.5)), 12)
    0.639722500786
    """
    xs, cs = _check_psi_args(x, c, whole=False)
    return scalar_or_array(_psi_both(xs, cs)[0])


def shear_ratio_first_order(x: ArrayLike, c: ArrayLike) -> np.ndarray | float:
    """q^(0)/(mu p^(0)) = 1 - psi(x, c) on the stick zone, 1 on the slip annulus, [S75] (2.31).

    The fraction of limiting friction mobilised at radius x at first order in gamma:
    0 at the centre, increasing to 1 at x = c. Accurate relative to its own size also
    near x = 0 (where it vanishes like x).

    Parameters
    ----------
    x : array_like
        0 <= x < 1.
    c : array_like
        Stick radius, 0 < c < 1.

    Examples
    --------
    >>> round(float(shear_ratio_first_order(0.3, 0.5)), 12), float(shear_ratio_first_order(0.7, 0.5))
    (0.360277499214, 1.0)
    """
    xs, cs = _check_psi_args(x, c, whole=True)
    return scalar_or_array(_psi_both(xs, cs)[1])


def psi_mp(x, c, dps: int = 30):
    """psi(x, c) of (2.30) in mpmath (Heuman form, B&F 150.01, evaluated at dps + 20 digits,
    plus 2 |log10 c| for tiny c, where 1 - c^2 must keep c^2)."""
    extra = max(0, int(-2 * mpmath.log10(mpmath.mpf(c)))) if c > 0 else 0
    with mpmath.workdps(dps + 20 + extra):
        x, c = mpmath.mpf(x), mpmath.mpf(c)
        if not (0 <= x <= c < 1):
            raise ValueError(f"need 0 <= x <= c < 1, got x={x}, c={c}")
        if x == 0:
            return mpmath.mpf(1)
        if x == c:
            return mpmath.mpf(0)
        omega = mpmath.sqrt((c * c - x * x) / (1 - x * x))
        phi = mpmath.asin(omega / c)
        m = 1 - c * c
        kk, ek = mpmath.ellipk(m), mpmath.ellipe(m)
        f_phi = mpmath.ellipf(phi, c * c)
        lam = 2 / mpmath.pi * (ek * f_phi + kk * mpmath.ellipe(phi, c * c) - kk * f_phi)  # B&F 150.01
        value = lam - 2 * c * kk / (mpmath.pi * x) * (omega / c - mpmath.atanh(omega) / mpmath.atanh(c))  # (2.30)
    return +value


def shear_ratio_first_order_mp(x, c, dps: int = 30):
    """1 - psi(x, c) in mpmath on [0, c] and 1 on (c, 1), (2.31)."""
    extra = max(0, int(-2 * mpmath.log10(mpmath.mpf(x)))) if x > 0 else 0  # 1 - psi ~ x
    with mpmath.workdps(dps + 20 + extra):
        x, c = mpmath.mpf(x), mpmath.mpf(c)
        value = mpmath.mpf(1) if x >= c else 1 - psi_mp(x, c, dps + 20 + extra)
    return +value


# ---------------------------------------------------------------------------------------
# Quadrature: tanh-sinh (double exponential) rules, robust to the algebraic and
# logarithmic end-point singularities met below; nodes carry their distances to both ends.

@lru_cache(maxsize=4)
def _tanh_sinh(level: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes on (0, 1) as (distance to 0, distance to 1, weight); step h = 2^-level."""
    h = 2.0**-level
    k = np.arange(-int(4.0 / h), int(4.0 / h) + 1)
    v = 0.5 * np.pi * np.sinh(k * h)
    cosh_v = np.cosh(v)
    left = 0.5 * np.exp(v) / cosh_v     # (1 + tanh v)/2
    right = 0.5 * np.exp(-v) / cosh_v   # (1 - tanh v)/2
    weight = 0.25 * np.pi * h * np.cosh(k * h) / cosh_v**2
    keep = (left > 0.0) & (right > 0.0) & (weight > 1e-300)
    return left[keep], right[keep], weight[keep]


def tanh_sinh_rule(a: float, b: float, level: int = 6) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Tanh-sinh nodes t in (a, b) with t - a, b - t (accurate) and weights; step 2^-level."""
    left, right, weight = _tanh_sinh(level)
    length = b - a
    return a + length * left, length * left, length * right, length * weight


# ---------------------------------------------------------------------------------------
# (2.34): the compliance at first order

def shear_moment_first_order(c: float, level: int = 6) -> float:
    """The moment of (2.34): int_0^1 (1 - sqrt(1 - t^2)) q^(0)/mu dt, q^(0)/mu = p^(0) (1 - psi) on (0, c), p^(0) on (c, 1)."""
    t, _, dist_c, w = tanh_sinh_rule(0.0, c, level)
    t = np.minimum(t, c - dist_c) if c < 1 else t
    shear = _psi_both(t, np.full_like(t, c))[1]
    one_minus_t2 = (1.0 - t) * (1.0 + t)
    kernel = t * t / (1.0 + np.sqrt(one_minus_t2)) / np.sqrt(one_minus_t2)  # (1 - sqrt(1-t^2))/sqrt(1-t^2)
    stick = (2.0 / np.pi) * float(np.dot(w, kernel * shear))
    # slip annulus: (2/pi) int_c^1 (1/sqrt(1-t^2) - 1) dt = (2/pi)(acos c - (1 - c))
    slip = (2.0 / np.pi) * (np.arccos(c) - (1.0 - c))
    return stick + slip


def compliance_first_order(c: ArrayLike, gamma: float) -> np.ndarray | float:
    """First-order compliance P* = 1 + gamma int_0^1 (1 - sqrt(1 - t^2)) q^(0)(t) dt, [S75] (2.34).

    With q^(0) = mu p^(0) (1 - psi) (2.31) and mu = gamma f0(c) (2.28) this is
    1 + gamma^2 f0(c) I(c), I(c) = int_0^1 (1 - sqrt(1 - t^2)) q^(0)/mu dt, evaluated by a
    tanh-sinh rule on (0, c) (to ~1e-14; the slip part is closed form). At c = 1 the limit
    (2.36) 1 + gamma^2/3 is returned. The identity (2.34) itself is exact; the first-order
    shear q^(0) is what makes this an approximation (error O(gamma^4) at fixed c).

    Parameters
    ----------
    c : array_like
        Stick radius, 0 < c <= 1.
    gamma : float
        Coupling constant, 0 <= gamma <= 3/4.

    Examples
    --------
    >>> round(float(compliance_first_order(1.0, 0.5)), 12)   # (2.36): 1 + 1/12
    1.083333333333
    """
    cs = check_c(c)
    g = float(check_gamma(gamma))
    flat = cs.ravel()
    out = np.empty_like(flat)
    for i, ci in enumerate(flat):
        if ci == 1.0:
            out[i] = 1.0 + g * g / 3.0  # (2.36)
        else:
            out[i] = 1.0 + g * g * float(mu_over_gamma(ci)) * shear_moment_first_order(float(ci))  # (2.34)
    return scalar_or_array(out.reshape(cs.shape))


def compliance_first_order_mp(c, gamma, dps: int = 20):
    """(2.34) at first order in mpmath: 1 + gamma^2 f0(c) int (1 - sqrt(1-t^2)) p^(0) (1 - psi) dt."""
    with mpmath.workdps(dps + 5):
        c, gamma = mpmath.mpf(c), mpmath.mpf(gamma)
        if c == 1:
            return 1 + gamma**2 / 3

        def stick(t):
            return (1 - mpmath.sqrt(1 - t * t)) * 2 / (mpmath.pi * mpmath.sqrt(1 - t * t)) * (1 - psi_mp(t, c, dps))

        slip = 2 / mpmath.pi * (mpmath.acos(c) - (1 - c))  # int_c^1 (1 - sqrt(1-t^2)) p^(0) dt
        moment = mpmath.quad(stick, [0, c]) + slip
        value = 1 + gamma**2 * mu_over_gamma_mp(c, dps + 5) * moment  # (2.34)
    return +value


# ---------------------------------------------------------------------------------------
# (2.33): the pressure correction

def _abel_log_kernel(s_minus_x: np.ndarray, s: np.ndarray, x: float, one_minus_s2: np.ndarray) -> np.ndarray:
    """P(s, x) = PV int_0^(1-x^2) u^(-1/2) du/(s^2 - x^2 - u), a = 1 - x^2, b = s^2 - x^2:
    (2/sqrt(b)) atanh(sqrt(b/a)) for b > 0, -(2/sqrt(-b)) atan(sqrt(a/-b)) for b < 0
    (the latter as arctan2(1, y), y = sqrt(-b/a)).

    atanh(y) = (1/2) log((1 + y)^2 a/(1 - s^2)) keeps the log singularity at s = 1 accurate;
    atanh(y)/y -> 1 as b -> 0+ (y < 1e-8: 1 + y^2/3).
    """
    a = (1.0 - x) * (1.0 + x)
    b = s_minus_x * (s + x)
    above = b > 0.0
    y = np.sqrt(np.abs(b) / a)
    tiny = y < 1e-8
    y_safe = np.where(tiny | ~above, 0.5, y)
    atanh_over = np.where(tiny, 1.0 + y * y / 3.0,
                          0.5 * np.log((1.0 + y_safe) ** 2 * a / np.where(above, one_minus_s2, 1.0)) / y_safe)
    pos = (2.0 / np.sqrt(a)) * atanh_over
    neg = -(2.0 / np.sqrt(np.where(above, 1.0, -b))) * np.arctan2(1.0, y)  # atan(1/y), exact as y -> 0
    return np.where(above, pos, neg)


def _pressure_correction_one(x: float, c: float, f0: float, level: int) -> float:
    """f0 * p1hat(x): see ``pressure_correction``."""
    breaks = sorted({0.0, c, x, 1.0})
    log_moment = 0.0
    kernel_integral = 0.0
    for a, b in zip(breaks[:-1], breaks[1:]):
        s, da, db, w = tanh_sinh_rule(a, b, level)
        one_minus_s2 = db * (1.0 + s) if b == 1.0 else (1.0 - s) * (1.0 + s)
        if b <= c:  # d/ds of h^(0)/mu: stick zone (2/pi) atanh(s)/f0, slip annulus (2/pi) s K'(s)
            slope = (2.0 / np.pi) / (f0 * one_minus_s2)
        else:
            slope = (2.0 / np.pi) * _k_minus_e_over_m(one_minus_s2, _k_prime(s))
        s_minus_x = da if a == x else (-db if b == x else s - x)
        log_moment += float(np.dot(w, slope * np.log(one_minus_s2)))
        kernel_integral += float(np.dot(w, slope * _abel_log_kernel(s_minus_x, s, x, one_minus_s2)))
    if x == 0.0:
        # P(s, x) ~ -pi/sqrt(x^2 - s^2) on (0, x) carries -(pi^2/2) h'(0) into the limit x -> 0+
        kernel_integral -= 0.5 * np.pi**2 * (2.0 / np.pi) / f0
    one_minus_x2 = (1.0 - x) * (1.0 + x)
    p1hat = (2.0 / np.pi**2) * ((np.log(4.0 * one_minus_x2) - log_moment) / np.sqrt(one_minus_x2) - kernel_integral)
    return f0 * p1hat  # (2.32), (2.33)


def pressure_correction(x: ArrayLike, c: float) -> np.ndarray | float:
    """First-order pressure correction P1(x; c): p = p^(0) + gamma^2 P1 + ..., from [S75] (2.33).

    (2.32) writes p = p^(0) + gamma p^(1), p^(1) solving the Abel equation (2.33) with the
    first-order shear q^(0) on the right. Since q^(0) = mu p^(0) (1 - psi) is itself
    proportional to mu = gamma f0(c) (2.28), gamma p^(1) = gamma^2 P1 with
    P1 = p^(1)/gamma = f0(c) p1hat, p1hat the solution of (2.33) with q^(0)/mu in place of
    q^(0). The paper says it "could be found numerically"; here the right side of (2.33)
    is the Hilbert transform of h^(0)/mu = x int_x^1 (q^(0)/mu) dt/sqrt(t^2 - x^2)
    (closed form: (2/pi) atanh(x)/f0(c) on (0, c), (2/pi) x K'(x) on (c, 1)), and
    Abel-inverting the logarithmic kernel in closed form leaves

        p1hat(x) = (2/pi^2) [ (log(4(1 - x^2)) - int_0^1 h'(s) log(1 - s^2) ds)/sqrt(1 - x^2)
                              - int_0^1 h'(s) P(s, x) ds ],

    h = h^(0)/mu, P(s, x) = PV int_0^(1-x^2) u^(-1/2) du/(s^2 - x^2 - u) (elementary), two
    single integrals done by tanh-sinh rules split at x and c. At x = 0 the value is the
    limit x -> 0+ (P ~ -pi/sqrt(x^2 - s^2) on (0, x) leaves -(pi^2/2) h'(0) behind). P1 ~ log(1-x)/sqrt(1-x) at the
    edge; it is checked by substitution into (2.33) and against the solver at small gamma
    in tests/test_derive_first_order.py.

    Parameters
    ----------
    x : array_like
        0 <= x < 1.
    c : float
        Stick radius, 0 < c < 1.

    Examples
    --------
    >>> p = pressure_correction([0.0, 1e-3], 0.5)        # even in x: P1(x) - P1(0) ~ 0.262 x^2
    >>> round(float(p[0]), 10), round(float(p[1] - p[0]) / 1e-6, 3)
    (0.5834637359, 0.262)
    """
    xs = check_x(x)
    if np.any(xs >= 1.0):
        raise ValueError(f"x must lie in [0, 1) (the pressure is singular at x = 1), got {x!r}")
    cs = float(check_c(c))
    if cs >= 1.0:
        raise ValueError(f"c must lie in (0, 1), got {c!r}")
    f0 = float(mu_over_gamma(cs))
    flat = xs.ravel()
    out = np.array([_pressure_correction_one(float(xi), cs, f0, 4) for xi in flat])  # level 4: converged to 3e-16
    return scalar_or_array(out.reshape(xs.shape))


def pressure_correction_mp(x, c, dps: int = 20):
    """P1(x; c) of ``pressure_correction`` by mpmath quadrature of the same formula."""
    with mpmath.workdps(dps + 5):
        x, c = mpmath.mpf(x), mpmath.mpf(c)
        f0 = mu_over_gamma_mp(c, dps + 5)
        pi = mpmath.pi

        def slope(s):
            m = 1 - s * s
            if s < c:
                return 2 / (pi * f0 * m)
            return 2 / pi * (mpmath.ellipk(m) - mpmath.ellipe(m)) / m if m > 0 else mpmath.mpf(1) / 2

        def log_term(s):
            m = 1 - s * s
            return slope(s) * mpmath.log(m) if m > 0 else mpmath.mpf(0)  # a node rounded onto s = 1

        def kernel(s):
            a, b = 1 - x * x, s * s - x * x
            if b >= a or b == 0:
                return mpmath.mpf(0)  # a node rounded onto s = 1 or s = x (integrable singularity)
            if b > 0:
                return 2 / mpmath.sqrt(b) * mpmath.atanh(mpmath.sqrt(b / a))
            return -2 / mpmath.sqrt(-b) * mpmath.atan(mpmath.sqrt(a / -b))

        points = sorted({mpmath.mpf(0), c, x, mpmath.mpf(1)})
        log_moment = mpmath.quad(log_term, points)
        kernel_integral = mpmath.quad(lambda s: slope(s) * kernel(s), points)
        if x == 0:  # the limit x -> 0+ (see _pressure_correction_one)
            kernel_integral -= pi**2 / 2 * slope(mpmath.mpf(0))
        p1hat = 2 / pi**2 * ((mpmath.log(4 * (1 - x * x)) - log_moment) / mpmath.sqrt(1 - x * x) - kernel_integral)
        value = f0 * p1hat
    return +value
