"""Finite Hilbert transforms of the plane solver's element functions (the Cauchy kernel of plane strain).

The plane-strain surface relations (``asymptotics.plane``) carry H f(x) = (1/pi) PV int f(t) dt / (t - x).
On an element t = a + sigma L s, s in [0, 1], with x = a + sigma L y, dt / (t - x) = ds / (s - y) for
either orientation sigma, so all that is needed is

    I_j(y) = PV int_0^1 w(s) P_j(2 s - 1) ds / (s - y),        j = 0 .. K,

for the three weights of the basis (``Family``):

- ``PLAIN``, w = 1: I_j(y) = -2 Q_j(2 y - 1) (Neumann's integral), with Q_j the Legendre function of the
  second kind (Ferrers' on the cut). ``legendre_q01``: forward recurrence on the cut and just off it,
  where the dominant solution P_j grows slowly (rho^(2K) <= FORWARD_GROWTH, rho = |eta| + sqrt(eta^2 - 1));
  elsewhere Miller's backward recurrence of the ratios Q_j / Q_(j-1) (the continued fraction of the
  minimal solution), started far enough above K that the truncation error rho^(-2m) is below 1e-17.
- ``HBETA``, w = h_beta(s) = (s^beta - 1)/beta, 0 <= beta <= 1/2 (log s at beta = 0): the singular family at
  the stick-slip point, written so that it stays a well-conditioned basis function as beta -> 0 (mu -> inf).
- ``POWER``, w = s^lam, -1 < lam <= 0: the edge family (1 - x)^(alpha - 1/2).

For the weighted families: points inside the element, I_j = int w D_j ds + P_j(y) V_w(y) with the divided
difference D_j = (P_j(s) - P_j(y))/(s - y) (a polynomial, by its own recurrence) and V_w(y) = PV int_0^1 w/(s - y)
in closed form (``power_cauchy``, ``hbeta_cauchy``); points outside but within ``FAR`` of the element,
a fixed composite rule graded toward the near end (pieces of ratio 1/2, so a pole at distance d from an
end is at least three half-lengths from the centre of every piece longer than d: Gauss error 5.83^-(2n));
points beyond ``FAR``, the family's product rule of degree + ``FAR_NODES`` nodes.

Every rule against the weight w is a product rule (``product_rule``): fixed Gauss-Legendre nodes, weights from
the moments of w against P_m in closed form (``power_moments``, ``hbeta_moments``), so nothing but a few weights
depends on the exponent (no Gauss-Jacobi eigenproblem per exponent).

Accuracy (``tests/test_plane.py``, ``test_element_transforms_against_mpmath``, against 30-digit mpmath): within
2e-14 of max(1, |I_j|) at points from 1e-9 of an element end to 30 element lengths away, for K <= 18 and beta, lam
over their range (measured worst 2e-14, in the Legendre recurrences at degree 18).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import special

from numeric.core.charts import h_beta
from numeric.core.quadrature import christoffel_gauss01, gauss_legendre

__all__ = ["PLAIN", "HBETA", "POWER", "Family", "FAR", "FAR_NODES", "FORWARD_GROWTH", "legendre_q01",
           "legendre01", "power_moments", "hbeta_moments", "product_rule", "power_cauchy", "hbeta_cauchy",
           "family_weight", "CauchyGeometry", "cauchy_geometry", "family_cauchy", "family_integrals", "family_values",
           "mode_cauchy"]

PLAIN, HBETA, POWER = 0, 1, 2
"""Weights of a family: 1, h_beta(s), s^lam."""

FAR = 0.5
"""Points farther than this (in element lengths) from an element: the family's lean rule (``FAR_NODES``)."""
FAR_NODES = 34
"""Nodes of the lean rule beyond the degree: for |y - [0, 1]| >= FAR the pole of P_j(2s - 1)/(s - y) is at
rho >= 2 + sqrt 3, and the product rule of degree + FAR_NODES - 1 leaves P_j(y) rho^-(degree + FAR_NODES) <= 3.73^-34
= 4e-20."""
FORWARD_GROWTH = 30.0
"""Forward recurrence of Q_j off the cut while rho^(2K) stays below this (a relative loss of 30 ulp at worst)."""
_PIECES = 60  # graded pieces toward an end: poles down to 2^-60 ~ 1e-18 of the element length
_PIECE_NODES = 10  # Gauss nodes per graded piece: 5.83^-20 = 5e-16
_HBETA_PIECES = 66  # h_beta at 0: the innermost piece [0, 2^-66] is dropped (|int| < 1e-18)
_SERIES_TERMS = 60  # |y| <= 1/2: tails sum y^k to 2^-60
_SMALL = 0.05  # below, the cot/csc remainders by their zeta series
_ZETA_EVEN = np.array([special.zeta(2 * k) for k in range(1, 14)])


@dataclass(frozen=True, slots=True)
class Family:
    """Weight w(s) (``PLAIN``, ``HBETA`` with parameter beta, ``POWER`` with parameter lam) times P_0..P_degree."""

    kind: int
    parameter: float
    degree: int


def legendre01(k: int, s: np.ndarray) -> np.ndarray:
    """P_0 .. P_k (2 s - 1), stacked on the last axis."""
    x = 2.0 * np.asarray(s, dtype=float) - 1.0
    out = np.empty(x.shape + (k + 1,))
    out[..., 0] = 1.0
    if k >= 1:
        out[..., 1] = x
    for n in range(1, k):
        out[..., n + 1] = ((2 * n + 1) * x * out[..., n] - n * out[..., n - 1]) / (n + 1)
    return out


def legendre_q01(y: np.ndarray, k: int) -> np.ndarray:
    """Q_0 .. Q_k(2 y - 1) for real y != 0, 1, stacked on the last axis: Ferrers' functions for 0 < y < 1,
    the second-kind functions outside (Q_j ~ rho^-(j+1)). Q_0 = log|y / (y - 1)| / 2 is formed from y (not
    from eta = 2 y - 1, whose rounding would cost |log| digits next to the ends)."""
    y = np.asarray(y, dtype=float)
    out = np.empty(y.shape + (k + 1,))
    inside = (y > 0.0) & (y < 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        log_one_minus = np.where(y < 0.5, np.log1p(-np.where(y < 0.5, y, 0.0)), np.log(np.abs(1.0 - y)))
        out[..., 0] = 0.5 * (np.log(np.abs(y)) - log_one_minus)
        a = np.abs(2.0 * y - 1.0)
        rho = np.where(inside, 1.0, a + 2.0 * np.sqrt(np.abs(y * (y - 1.0))))
    forward = inside | (2 * k * np.log(rho) <= math.log(FORWARD_GROWTH))
    if k >= 1:
        x = 2.0 * y[forward] - 1.0
        q = np.empty(x.shape + (k + 1,))
        q[..., 0] = out[forward][..., 0]
        q[..., 1] = x * q[..., 0] - 1.0
        for n in range(1, k):
            q[..., n + 1] = ((2 * n + 1) * x * q[..., n] - n * q[..., n - 1]) / (n + 1)
        out[forward] = q
        miller = ~forward
        if np.any(miller):
            # one backward pass for all points, started as far above k as the point nearest the cut needs (the
            # loop's cost is per step, not per point, at these sizes; more steps only shrink a point's truncation)
            idx = np.flatnonzero(miller.ravel())
            steps = int(np.ceil(20.0 / np.log(rho.ravel()[idx].min()))) + 2
            flat = out.reshape(-1, k + 1)
            flat[idx] = _miller(2.0 * y.ravel()[idx] - 1.0, k, min(steps, 4096), flat[idx, 0])
    return out


def _miller(eta: np.ndarray, k: int, m: int, q0: np.ndarray) -> np.ndarray:
    """Q_0..Q_k outside the cut from the ratios r_n = Q_n/Q_(n-1) = n / ((2n + 1) eta - (n + 1) r_(n+1)), r_(k+m+1) = 0."""
    r = np.zeros(eta.shape)
    ratios = np.empty(eta.shape + (k + 1,))
    for n in range(k + m, 0, -1):
        r = n / ((2 * n + 1) * eta - (n + 1) * r)
        if n <= k:
            ratios[..., n] = r
    ratios[..., 0] = q0
    return np.cumprod(ratios, axis=-1)


def power_moments(lam: float, n: int) -> np.ndarray:
    """int_0^1 s^lam P_m(2 s - 1) ds, m < n (lam > -1): Gamma(lam + 1)^2 / (Gamma(lam + m + 2) Gamma(lam + 1 - m)),
    by the ratio (lam - m + 1)/(lam + m + 1) of successive moments (a rounding each)."""
    ratios = np.ones(n)
    m = np.arange(1, n, dtype=float)
    ratios[1:] = (lam - m + 1.0) / (lam + m + 1.0)
    return np.cumprod(ratios) / (lam + 1.0)


def hbeta_moments(beta: float, n: int) -> np.ndarray:
    """int_0^1 h_beta(s) P_m(2 s - 1) ds, m < n (0 <= beta <= 1/2): -1/(beta + 1), then ``power_moments`` / beta with
    its factor beta cancelled, 1/((beta + 1)(beta + 2)) prod_(2 <= k <= m) (beta - k + 1)/(beta + k + 1): smooth down to
    beta = 0 (the moments of log s)."""
    ratios = np.ones(n)
    ratios[0] = -1.0 / (beta + 1.0)
    if n > 1:
        ratios[1] = -1.0 / (beta + 2.0)
        m = np.arange(2, n, dtype=float)
        ratios[2:] = (beta - m + 1.0) / (beta + m + 1.0)
    return np.cumprod(ratios)


@lru_cache(maxsize=None)
def _projector(n: int) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss-Legendre nodes s on [0, 1] and A[i, m] = w_i (2 m + 1) P_m(2 s_i - 1), m < n (read-only; A[:, 0]
    are the weights). The weights are ``christoffel_gauss01``'s (``leggauss``'s are off by 4e-13 at the end nodes, which
    a weight singular there multiplies: 7e-14 in int s^(-1/2)/(s + 0.6) with 36 nodes, against 9e-16)."""
    s, w = christoffel_gauss01(n)
    a = w[:, None] * (2.0 * np.arange(n) + 1.0)[None, :] * legendre01(n - 1, s)
    a.setflags(write=False)
    return s, a


def product_rule(moments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights of int_0^1 w(s) f(s) ds ~ sum W_i f(s_i), exact for polynomials f of degree < n, from the n
    moments int w P_m(2 s - 1) (``power_moments``, ``hbeta_moments``): the n Gauss-Legendre nodes, whatever w (so a
    kernel at them does not depend on the weight's exponent), W = A @ moments (the Legendre coefficients of the degree
    n - 1 interpolant of f, (2 m + 1) sum_i w_i f(s_i) P_m, are exact). Error for f analytic in the Bernstein ellipse
    rho: ~rho^-n (Gauss-Jacobi's rho^-2n with half the nodes; the nodes are cheaper than an eigenproblem per weight)."""
    s, a = _projector(moments.size)
    return s, a @ moments


def _pi_cot(lam: float) -> float:
    """pi cot(pi lam) for -1 < lam < 1, lam != 0; exactly 0 at lam = -1/2 (as -pi tan(pi (lam + 1/2)))."""
    if lam < -0.25:
        return -math.pi * math.tan(math.pi * (lam + 0.5))
    return math.pi / math.tan(math.pi * lam)


def _cot_remainder(lam: float) -> float:
    """1/lam - pi cot(pi lam), exact to rounding as lam -> 0."""
    if abs(lam) < _SMALL:
        return float(2.0 * np.sum(_ZETA_EVEN * lam ** (2 * np.arange(1, _ZETA_EVEN.size + 1) - 1)))
    return 1.0 / lam - _pi_cot(lam)


def _csc_remainder(lam: float) -> float:
    """1/lam - pi / sin(pi lam), exact to rounding as lam -> 0."""
    if abs(lam) < _SMALL:
        k = np.arange(1, _ZETA_EVEN.size + 1)
        return float(-2.0 * np.sum((1.0 - 2.0 ** (1 - 2 * k)) * _ZETA_EVEN * lam ** (2 * k - 1)))
    return 1.0 / lam - math.pi / math.sin(math.pi * lam)


def _cot_remainder_over(beta: float) -> float:
    """(1/beta - pi cot(pi beta)) / beta, pi^2/3 at beta = 0."""
    if abs(beta) < _SMALL:
        return float(2.0 * np.sum(_ZETA_EVEN * beta ** (2 * np.arange(1, _ZETA_EVEN.size + 1) - 2)))
    return _cot_remainder(beta) / beta


def _csc_remainder_over(beta: float) -> float:
    """(1/beta - pi / sin(pi beta)) / beta, -pi^2/6 at beta = 0."""
    if abs(beta) < _SMALL:
        k = np.arange(1, _ZETA_EVEN.size + 1)
        return float(-2.0 * np.sum((1.0 - 2.0 ** (1 - 2 * k)) * _ZETA_EVEN * beta ** (2 * k - 2)))
    return _csc_remainder(beta) / beta


def _second_remainder(z: np.ndarray) -> np.ndarray:
    """(e^z - 1 - z)/z^2 (1/2 at z = 0), without cancellation."""
    z = np.asarray(z, dtype=float)
    small = np.abs(z) < 0.5
    out = np.empty(z.shape)
    zs = z[small]
    term, total = np.full(zs.shape, 0.5), np.full(zs.shape, 0.5)
    for n in range(3, 22):
        term = term * zs / n
        total = total + term
    out[small] = total
    zl = z[~small]
    out[~small] = (np.expm1(zl) - zl) / (zl * zl)
    return out


def power_cauchy(lam: float, y: np.ndarray) -> np.ndarray:
    """V_lam(y) = PV int_0^1 s^lam ds / (s - y) for lam > -1 and real y not 0 or 1.

    |y| <= 1/2: V = A(y) - sum_k y^k / (k - lam) (the tail int_1^inf s^lam / (s - y), continued
    analytically in lam), A = -pi cot(pi lam) y^lam (y > 0) or -pi |y|^lam / sin(pi lam) (y < 0),
    the k = 0 term combined with A so that lam -> 0 (log|y| in the limit) loses nothing.
    y > 1/2: [0, 1/4] by the product rule of s^lam (30 nodes, pole at rho >= 5.83: 5.83^-30 = 1e-23), [1/4, 1] as
    int (s^lam - y^lam)/(s - y) + y^lam log|(1 - y)/(1/4 - y)|.
    y < -1/2: the product rule on [0, 1] (40 nodes; the pole is >= 1/2 away, rho >= 3.73: 3.73^-40 = 1e-23).
    """
    y = np.asarray(y, dtype=float)
    if lam == 0.0:
        return np.log(np.abs((1.0 - y) / y))
    out = np.empty(y.shape)
    small = np.abs(y) <= 0.5
    if np.any(small):
        ys = y[small]
        log_ay = np.log(np.abs(ys))
        remainder = np.where(ys > 0.0, _cot_remainder(lam), _csc_remainder(lam))
        power = np.exp(lam * log_ay)
        # A(y) + 1/lam: as remainder y^lam - (y^lam - 1)/lam where lam log|y| is small (lam -> 0), else directly
        # (where y^lam is large the two terms of the first form cancel)
        direct = np.abs(lam * log_ay) > 1.0
        factor = np.where(ys > 0.0, _pi_cot(lam), math.pi / math.sin(math.pi * lam))
        head = np.where(direct, 1.0 / lam - factor * power, remainder * power - special.expm1(lam * log_ay) / lam)
        out[small] = head - _tail(ys, 1.0 / (np.arange(1, _SERIES_TERMS) - lam))
    right = y > 0.5
    if np.any(right):
        yr = y[right]
        out[right] = _power_near_zero(lam, yr) + _quarter_difference(lam, lam, yr) + yr**lam * _quarter_log(yr)
    left = y < -0.5
    if np.any(left):
        out[left] = _by_product_rule(power_moments(lam, 40), y[left])
    return out


def _power_near_zero(lam: float, yr: np.ndarray) -> np.ndarray:
    """int_0^(1/4) s^lam ds/(s - y) for y > 1/2: the product rule of s^lam (30 nodes), scaled to [0, 1/4]."""
    s1, w1 = product_rule(power_moments(lam, 30))
    return (0.25 ** (lam + 1.0)) * ((w1[None, :] / (0.25 * s1[None, :] - yr[:, None])).sum(axis=1))


def _quarter_difference(exponent: float, factor: float, yr: np.ndarray) -> np.ndarray:
    """factor int_(1/4)^1 (s^b - y^b) / (b (s - y)) ds, b = ``exponent``, for y > 1/2: the divided difference as
    y^b log(s/y) exprel(b log(s/y)) / (s - y) (nothing cancels as b -> 0; y^(b - 1) at s = y), on 40 Gauss nodes."""
    s2, w2 = _quarter_to_one()
    log_ratio = np.log(s2[None, :] / yr[:, None])
    dd = yr[:, None] ** exponent * factor * log_ratio * special.exprel(exponent * log_ratio) / (s2[None, :] - yr[:, None])
    dd = np.where(s2[None, :] == yr[:, None], factor * yr[:, None] ** (exponent - 1.0), dd)
    return dd @ w2


def _quarter_log(yr: np.ndarray) -> np.ndarray:
    """int_(1/4)^1 ds/(s - y) = log|(1 - y)/(1/4 - y)| for y > 1/2."""
    return np.log(np.abs((1.0 - yr) / (0.25 - yr)))


def _by_product_rule(moments: np.ndarray, y: np.ndarray) -> np.ndarray:
    """int_0^1 w(s) ds/(s - y) by the product rule of the weight whose Legendre moments are given (y off [0, 1])."""
    s, w = product_rule(moments)
    return (w[None, :] / (s[None, :] - y[:, None])).sum(axis=1)


def hbeta_cauchy(beta: float, y: np.ndarray) -> np.ndarray:
    """W_beta(y) = PV int_0^1 h_beta(s) ds / (s - y), h_beta = (s^beta - 1)/beta (log s at beta = 0), 0 <= beta <= 1/2.

    (V_beta - V_0)/beta of ``power_cauchy``, arranged so that nothing cancels as beta -> 0:
    0 < |y| <= 1/2: W = g y^beta - log(y)^2 E(beta log|y|) - sum_k y^k / (k (k - beta)), with
    g = (1/beta - pi cot(pi beta))/beta (y > 0) or (1/beta - pi/sin(pi beta))/beta (y < 0) and
    E(z) = (e^z - 1 - z)/z^2; y > 1/2: [0, 1/4] by the product rule of h_beta (30 nodes, as in ``power_cauchy``),
    [1/4, 1] by subtracting h_beta(y) (the divided difference y^beta log(s/y) exprel(beta log(s/y)) / (s - y));
    y < -1/2: the product rule (40 nodes).
    """
    y = np.asarray(y, dtype=float)
    out = np.empty(y.shape)
    small = np.abs(y) <= 0.5
    if np.any(small):
        ys = y[small]
        log_ay = np.log(np.abs(ys))
        g = np.where(ys > 0.0, _cot_remainder_over(beta), _csc_remainder_over(beta))
        k = np.arange(1, _SERIES_TERMS)
        out[small] = g * np.exp(beta * log_ay) - log_ay**2 * _second_remainder(beta * log_ay) - _tail(ys, 1.0 / (k * (k - beta)))
    right = y > 0.5
    if np.any(right):
        yr = y[right]
        u, wh = product_rule(hbeta_moments(beta, 30))  # h_beta(u/4) = 4^-beta h_beta(u) + h_beta(1/4)
        w1 = 0.25 * (0.25**beta * wh + float(h_beta(beta, np.array(0.25))) * _projector(30)[1][:, 0])
        part1 = w1[None, :] @ (1.0 / (0.25 * u[:, None] - yr[None, :]))
        out[right] = part1[0] + _quarter_difference(beta, 1.0, yr) + h_beta(beta, yr) * _quarter_log(yr)
    left = y < -0.5
    if np.any(left):
        out[left] = _by_product_rule(hbeta_moments(beta, 40), y[left])
    return out


def mode_cauchy(beta: float, y: np.ndarray) -> np.ndarray:
    """PV int_0^1 m(s) ds / (s - y) for the generic mode m(s) = beta s^(beta - 1), 0 <= beta <= 1/2, y != 0, 1.

    m has unit integral and tends to the delta function at s = 0 as beta -> 0 (then the value is -1/y).
    |y| <= 1/2: beta V_(beta-1)(y) from the series of ``power_cauchy``, with pi beta cot(pi beta) (y > 0) or
    pi beta / sin(pi beta) (y < 0) as factors; otherwise, on [0, a] (a = 1/4 for y > 1/2, 1 for y < -1/2),
    int m/(s - y) = (beta/y) int_0^a s^beta ds/(s - y) - a^beta / y (no weight singular at beta -> 0), and
    for y > 1/2 the rest [1/4, 1] by subtracting m(y).
    """
    y = np.asarray(y, dtype=float)
    out = np.empty(y.shape)
    small = np.abs(y) <= 0.5
    if np.any(small):
        ys = y[small]
        ay = np.abs(ys)
        pb = math.pi * beta
        # y > 0: -pi beta cot(pi beta) y^(beta - 1) (the cotangent as tan(pi (1/2 - beta)), exact 0 at beta = 1/2);
        # y < 0: +pi beta |y|^(beta - 1) / sin(pi beta); both factors 1 at beta = 0
        cot_factor = 1.0 if beta == 0.0 else (pb * math.tan(math.pi * (0.5 - beta)) if beta > 0.25 else pb / math.tan(pb))
        csc_factor = 1.0 if beta == 0.0 else pb / math.sin(pb)
        k = np.arange(1, _SERIES_TERMS)
        head = np.where(ys > 0.0, -cot_factor, csc_factor) * ay ** (beta - 1.0)
        out[small] = head + beta / (beta - 1.0) - beta * _tail(ys, 1.0 / (k + 1.0 - beta))
    right = y > 0.5
    if np.any(right):
        yr = y[right]
        part1 = (beta / yr) * _power_near_zero(beta, yr) - 0.25**beta / yr
        lam = beta - 1.0
        out[right] = part1 + beta * (_quarter_difference(lam, lam, yr) + yr**lam * _quarter_log(yr))
    left = y < -0.5
    if np.any(left):
        yl = y[left]
        out[left] = (beta / yl) * _by_product_rule(power_moments(beta, 40), yl) - 1.0 / yl
    return out


def _tail(y: np.ndarray, coefficients: np.ndarray) -> np.ndarray:
    """sum_{k >= 1} coefficients[k - 1] y^k (|y| <= 1/2): the powers by a cumulative product, one matrix product."""
    powers = np.cumprod(np.broadcast_to(y[:, None], (y.size, coefficients.size)), axis=1)
    return powers @ coefficients


@lru_cache(maxsize=None)
def _quarter_to_one() -> tuple[np.ndarray, np.ndarray]:
    """40-point Gauss-Legendre on [1/4, 1]: the divided differences there are analytic but at s = 0 (rho = 3)."""
    x, w = gauss_legendre(40)
    return 0.25 + 0.375 * (x + 1.0), 0.375 * w


@lru_cache(maxsize=None)
def _graded_toward_zero(pieces: int, nodes: int = _PIECE_NODES, extra: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre on [2^-(j+1), 2^-j], j < pieces (the piece [0, 2^-pieces] left out), with nodes + max(0, extra - j)
    nodes on piece j (a polynomial factor of degree 2 extra is integrated on the long pieces too): read-only."""
    xs, ws = [], []
    for j in range(pieces):
        x, w = gauss_legendre(nodes + max(0, extra - j))
        lo = 2.0 ** -(j + 1)
        xs.append(lo + 0.5 * lo * (x + 1.0))  # half-length lo / 2
        ws.append(0.5 * lo * w)
    s, w = np.concatenate(xs), np.concatenate(ws)
    s.setflags(write=False)
    w.setflags(write=False)
    return s, w


def family_weight(family: Family, s: np.ndarray) -> np.ndarray:
    """w(s) of the family (0 at s = 0 for lam < 0 is not used: rules never put a node there)."""
    if family.kind == PLAIN:
        return np.ones(np.shape(s))
    if family.kind == HBETA:
        return h_beta(family.parameter, s)
    return np.asarray(s, dtype=float) ** family.parameter


def family_values(family: Family, s: np.ndarray, legendre: np.ndarray | None = None) -> np.ndarray:
    """w(s) P_j(2 s - 1), j = 0 .. degree: shape s.shape + (degree + 1,). ``legendre``: ``legendre01`` at s to this
    degree or a higher one (its leading columns are the lower degrees' own, bit for bit), where the caller has it."""
    P = legendre01(family.degree, s) if legendre is None else legendre[..., : family.degree + 1]
    return family_weight(family, s)[..., None] * P


def _family_moments(family: Family, n: int) -> np.ndarray:
    """int_0^1 w(s) P_m(2 s - 1) ds, m < n (closed forms)."""
    if family.kind == POWER:
        return power_moments(family.parameter, n)
    if family.kind == HBETA:
        return hbeta_moments(family.parameter, n)
    out = np.zeros(n)
    out[0] = 1.0
    return out


def _lean_rule(family: Family) -> tuple[np.ndarray, np.ndarray]:
    """Nodes (Gauss-Legendre, whatever the family's parameter) and weights (w folded in) that integrate w(s) x
    polynomials of degree < degree + FAR_NODES exactly (``product_rule``)."""
    return product_rule(_family_moments(family, family.degree + FAR_NODES))


@lru_cache(maxsize=None)
def _lean_legendre(degree: int) -> np.ndarray:
    """P_0..P_degree at the lean rule's nodes (read-only)."""
    return _frozen(legendre01(degree, _projector(degree + FAR_NODES)[0]))


@lru_cache(maxsize=None)
def _outside_nodes(kind: int, degree: int, toward_one: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The nodes of ``_outside_rule`` (they do not depend on the family's parameter): s, their distance d from the near
    end (exact), the weights without w (0 on the nodes whose weight ``_outside_rule`` forms whole) and the Legendre
    values (read-only)."""
    if not toward_one:
        s, ws = _graded_toward_zero(_PIECES if kind != HBETA else _HBETA_PIECES, extra=degree // 2 + 1)
        if kind == POWER:
            u = _projector(2 * _PIECE_NODES)[0]
            s, ws = np.concatenate([2.0 ** -_PIECES * u, s]), np.concatenate([np.zeros(u.size), ws])
        d = s
    else:
        s0 = 0.5 * _projector(degree + FAR_NODES)[0]
        t, wt = _graded_toward_zero(_PIECES, extra=degree // 2 + 2)
        keep = t < 0.5  # pieces [2^-(j+1), 2^-j] for j >= 1, mapped to 1 - t
        s = np.concatenate([s0, 1.0 - t[keep]])
        d = np.concatenate([1.0 - s0, t[keep]])
        ws = np.concatenate([np.zeros(s0.size), wt[keep]])
    return _frozen(s), _frozen(d), _frozen(ws), _frozen(legendre01(degree, s))


def _outside_rule(family: Family, toward_one: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Fixed nodes s, their distance d from the near end (exact), weights (w folded in) and the Legendre values,
    for points outside the element within FAR of an end.

    Toward 0 (the weight's end): pieces [2^-(j+1), 2^-j] (j < 66 for h_beta, 60 otherwise), and for ``POWER``
    the innermost [0, h], h = 2^-60, by the product rule of s^lam (20 nodes: a pole at least h away, rho >= 5.83,
    5.83^-20 = 5e-16 of that piece; ``HBETA``'s innermost piece is ``_innermost_hbeta``). Toward 1: the family's lean
    rule on [0, 1/2] (the pole is >= 1/2 away: rho >= 5.83 in u = 2 s; w(u/2) is 2^-lam u^lam, or 2^-beta h_beta(u) +
    h_beta(1/2)) and pieces [1 - 2^-j, 1 - 2^-(j+1)], j >= 1, their distance 2^-(j+1) ... 2^-j from 1 kept exact (a
    double s next to 1 would round it)."""
    s, d, ws, P = _outside_nodes(family.kind, family.degree, toward_one)
    ws = ws * family_weight(family, s)
    lam = family.parameter
    if not toward_one:
        if family.kind == POWER:
            n = 2 * _PIECE_NODES
            ws[:n] = 2.0 ** (-_PIECES * (lam + 1.0)) * product_rule(power_moments(lam, n))[1]
    else:
        n = family.degree + FAR_NODES
        if family.kind == HBETA:
            ws[:n] = 0.5 * (0.5**lam * _lean_rule(family)[1] + float(h_beta(lam, np.array(0.5))) * _projector(n)[1][:, 0])
        else:
            ws[:n] = _lean_rule(family)[1] * 0.5 ** ((lam if family.kind == POWER else 0.0) + 1.0)
    return s, d, ws, P


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a)
    a.setflags(write=False)
    return a


def _innermost_hbeta(beta: float, k: int, y: np.ndarray) -> np.ndarray:
    """int_0^h h_beta(s) P_j(2s - 1) ds / (s - y), h = 2^-66, for y < -2h: P_j(2s - 1) = (-1)^j there (to h j^2),
    1/(s - y) = -sum_n s^n / y^(n+1), and int_0^h h_beta s^n = h^(n+1) (h_beta(h)/(beta + n + 1) - 1/((n + 1)(beta + n + 1)))."""
    h = 2.0 ** -_HBETA_PIECES
    n = np.arange(8)
    moments = h ** (n + 1.0) * (float(h_beta(beta, np.array(h))) / (beta + n + 1) - 1.0 / ((n + 1) * (beta + n + 1)))
    total = -(moments[None, :] * (1.0 / y[:, None]) ** (n[None, :] + 1)).sum(axis=1)
    return total[:, None] * (-1.0) ** np.arange(k + 1)[None, :]


def _divided_differences(k: int, s: np.ndarray, y: np.ndarray, Py: np.ndarray) -> np.ndarray:
    """D_j(s, y) = (P_j(2s-1) - P_j(2y-1)) / (s - y), j = 0..k, shape broadcast(s, y) + (k+1,).

    From the three-term recurrence: D_{j+1} = ((2j+1)(x_s D_j + 2 P_j(y)) - j D_{j-1}) / (j + 1), D_0 = 0, D_1 = 2.
    """
    xs = 2.0 * s - 1.0
    out = np.zeros(np.broadcast(s, y).shape + (k + 1,))
    if k >= 1:
        out[..., 1] = 2.0
    for j in range(1, k):
        out[..., j + 1] = ((2 * j + 1) * (xs * out[..., j] + 2.0 * Py[..., j]) - j * out[..., j - 1]) / (j + 1)
    return out


@dataclass(frozen=True, slots=True, eq=False)
class CauchyGeometry:
    """What ``family_cauchy`` needs at points y that does not depend on the family's parameter (the exponent alpha of
    the solver's singular families): which rule each point takes, and the rules' kernels at the points. Formed once
    per point set by ``cauchy_geometry``, it serves every exponent (the solver assembles two for each c).

    inside: mask, P_j(y) and the divided differences D_j(s_n, y) at the product rule's nodes; far: mask and the
    kernel 1/(s_n - y) at the lean rule's nodes; near (toward 0, toward 1): masks, the kernels at the outside
    rule's nodes, and for the rule toward 1 log(1 + 2^-60/gap) (the piece it leaves out)."""

    kind: int
    degree: int
    y: np.ndarray
    inside: np.ndarray
    legendre_inside: np.ndarray
    differences: np.ndarray
    far: np.ndarray
    far_kernel: np.ndarray
    near: tuple[np.ndarray, np.ndarray]
    near_kernels: tuple[np.ndarray, np.ndarray]
    left_out: np.ndarray


def cauchy_geometry(kind: int, degree: int, y: np.ndarray) -> CauchyGeometry:
    """The parameter-free part of ``family_cauchy`` for a weighted family (``HBETA`` or ``POWER``) of this degree."""
    y = np.asarray(y, dtype=float)
    k = degree
    inside = (y > 0.0) & (y < 1.0)
    far = (y < -FAR) | (y > 1.0 + FAR)
    yi = y[inside]
    Py = legendre01(k, yi)
    s = _projector(k + 1)[0]  # the product rule's nodes (D_j has degree j - 1: exact)
    D = _divided_differences(k, s[None, :], yi[:, None], Py[:, None, :])
    far_kernel = 1.0 / (_projector(k + FAR_NODES)[0][None, :] - y[far][:, None])
    masks, kernels = [], []
    left_out = np.zeros(0)
    for toward_one in (False, True):
        near = ~inside & ~far & ((y > 1.0) if toward_one else (y < 0.0))
        d = _outside_nodes(kind, k, toward_one)[1]
        gap = (y[near] - 1.0) if toward_one else -y[near]  # distance from the end, exact (Sterbenz)
        kernels.append(1.0 / (-(d[None, :] + gap[:, None]) if toward_one else (d[None, :] + gap[:, None])))
        masks.append(near)
        if toward_one:
            left_out = np.log1p(2.0 ** -_PIECES / gap)
    return CauchyGeometry(kind, k, y, inside, Py, D, far, far_kernel, (masks[0], masks[1]), (kernels[0], kernels[1]),
                          left_out)


def family_cauchy(family: Family, y: np.ndarray, geometry: CauchyGeometry | None = None) -> np.ndarray:
    """I_j(y) = PV int_0^1 w(s) P_j(2s - 1) ds / (s - y), j = 0 .. degree, for y not 0 or 1: shape y.shape + (degree + 1,).

    ``geometry``: ``cauchy_geometry`` of the family's kind and degree at these y, if formed already."""
    y = np.asarray(y, dtype=float)
    k = family.degree
    if family.kind == PLAIN:
        return -2.0 * legendre_q01(y, k)
    g = cauchy_geometry(family.kind, k, y) if geometry is None else geometry
    out = np.empty(y.shape + (k + 1,))
    if np.any(g.far):
        ws = _lean_rule(family)[1]
        out[g.far] = g.far_kernel @ (ws[:, None] * _lean_legendre(k))
    if np.any(g.inside):
        ws = product_rule(_family_moments(family, k + 1))[1]
        yi = y[g.inside]
        V = power_cauchy(family.parameter, yi) if family.kind == POWER else hbeta_cauchy(family.parameter, yi)
        out[g.inside] = np.einsum("n,pnk->pk", ws, g.differences) + g.legendre_inside * V[:, None]
    for toward_one, near, kernel in zip((False, True), g.near, g.near_kernels):
        if np.any(near):
            _, _, ws, P = _outside_rule(family, toward_one)
            out[near] = kernel @ (ws[:, None] * P)
            if toward_one:  # the piece [1 - 2^-60, 1] left out: w(1) P_j(1) int ds/(s - y) = -w(1) log(1 + h/gap)
                out[near] -= float(family_weight(family, np.array(1.0))) * g.left_out[:, None]
            if family.kind == HBETA and not toward_one:
                out[near] += _innermost_hbeta(family.parameter, k, y[near])
    return out


def family_integrals(family: Family) -> np.ndarray:
    """int_0^1 w(s) P_j(2 s - 1) ds, j = 0 .. degree (closed forms: ``power_moments``, ``hbeta_moments``)."""
    return _family_moments(family, family.degree + 1)
