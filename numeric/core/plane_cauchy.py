"""Finite Hilbert transforms of the plane solver's element functions (the Cauchy kernel of plane strain).

The plane-strain surface relations (``asymptotics.plane``) carry the finite Hilbert transform
H f(x) = (1/pi) PV int f(t) dt / (t - x). On an element mapped to s in [0, 1], with its
singular end at s = 0, the solver's functions are s^lam P_k(2 s - 1) (lam = 0: a plain
element; lam = 1/2 - alpha at the stick-slip point, alpha - 1/2 at the edge), and

    I_k(y) = PV int_0^1 s^lam P_k(2 s - 1) ds / (s - y)

is all that is needed: t = a + sigma L s, x = a + sigma L y gives H = I_k(y) / pi for either
orientation sigma = +-1.

- Points well away from the element (y outside [-NEAR, 1 + NEAR]): Gauss-Jacobi with weight
  s^lam, FAR_NODES nodes (the pole is at least NEAR from the interval: error below 1e-16).
- Near or inside: I_k(y) = int s^lam D_k(s, y) ds + P_k(y) V_lam(y), with the divided difference
  D_k = (P_k(s) - P_k(y)) / (s - y) (a polynomial, by a recurrence without cancellation) and
  V_lam(y) = PV int_0^1 s^lam ds / (s - y) in closed form (``power_cauchy``).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy import special

from numeric.core.quadrature import gauss_legendre

__all__ = ["NEAR", "FAR_NODES", "gauss_jacobi01", "power_cauchy", "element_cauchy", "element_integrals",
           "legendre01"]

NEAR = 0.05
"""Points with y in [-NEAR, 1 + NEAR] take the subtracted rule (P_k(y) grows like 1.56^k there)."""
FAR_NODES = 50
"""Gauss-Jacobi nodes for points beyond NEAR: the integrand's pole is >= NEAR away, error ~ 1.56^-(2n - k)."""
_SERIES_TERMS = 60  # |y| <= 1/2: the tail sum of V_lam to 2^-60
_SMALL_LAMBDA = 0.05  # below, 1/lam - pi cot(pi lam) and 1/lam - pi/sin(pi lam) by their Taylor series
_ZETA_EVEN = np.array([special.zeta(2 * k) for k in range(1, 12)])


@lru_cache(maxsize=256)
def gauss_jacobi01(n: int, lam: float) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss rule on [0, 1] for the weight s^lam (lam > -1): nodes, weights (read-only)."""
    if lam == 0.0:
        x, w = gauss_legendre(n)
        s, ws = 0.5 * (x + 1.0), 0.5 * w
    else:
        x, w = special.roots_jacobi(n, 0.0, lam)
        s, ws = 0.5 * (x + 1.0), w * 2.0 ** (-lam - 1.0)
    s, ws = np.array(s), np.array(ws)
    s.setflags(write=False)
    ws.setflags(write=False)
    return s, ws


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


def _divided_differences(k: int, s: np.ndarray, y: np.ndarray, Py: np.ndarray) -> np.ndarray:
    """D_j(s, y) = (P_j(2s-1) - P_j(2y-1)) / (s - y), j = 0..k, shape s.shape + (k+1,) (s, y broadcast).

    From the three-term recurrence: D_{j+1} = ((2j+1)(x_s D_j + 2 P_j(y)) - j D_{j-1}) / (j + 1), D_0 = 0, D_1 = 2.
    """
    xs = 2.0 * s - 1.0
    out = np.zeros(np.broadcast(s, y).shape + (k + 1,))
    if k >= 1:
        out[..., 1] = 2.0
    for j in range(1, k):
        out[..., j + 1] = ((2 * j + 1) * (xs * out[..., j] + 2.0 * Py[..., j]) - j * out[..., j - 1]) / (j + 1)
    return out


def _cot_remainder(lam: float) -> float:
    """1/lam - pi cot(pi lam), exact to rounding as lam -> 0."""
    if abs(lam) < _SMALL_LAMBDA:
        powers = lam ** (2 * np.arange(1, _ZETA_EVEN.size + 1) - 1)
        return float(2.0 * np.sum(_ZETA_EVEN * powers))
    return 1.0 / lam - math.pi / math.tan(math.pi * lam)


def _csc_remainder(lam: float) -> float:
    """1/lam - pi / sin(pi lam), exact to rounding as lam -> 0."""
    if abs(lam) < _SMALL_LAMBDA:
        k = np.arange(1, _ZETA_EVEN.size + 1)
        powers = lam ** (2 * k - 1)
        return float(-2.0 * np.sum((1.0 - 2.0 ** (1 - 2 * k)) * _ZETA_EVEN * powers))
    return 1.0 / lam - math.pi / math.sin(math.pi * lam)


def power_cauchy(lam: float, y: np.ndarray) -> np.ndarray:
    """V_lam(y) = PV int_0^1 s^lam ds / (s - y) for lam > -1 and real y not 0 or 1.

    |y| <= 1/2: V = A(y) - sum_k y^k / (k - lam) (the tail int_1^inf s^lam / (s - y), continued
    analytically in lam), A = -pi cot(pi lam) y^lam (y > 0) or -pi |y|^lam / sin(pi lam) (y < 0),
    the k = 0 term combined with A so that lam -> 0 (log|y| in the limit) loses nothing.
    y > 1/2: [0, 1/4] by Gauss-Jacobi, [1/4, 1] as int (s^lam - y^lam)/(s - y) + y^lam log|(1 - y)/(1/4 - y)|.
    y < -1/2: Gauss-Jacobi on [0, 1] (the pole is >= 1/2 away).
    """
    y = np.asarray(y, dtype=float)
    if lam == 0.0:
        return np.log(np.abs((1.0 - y) / y))
    out = np.empty(y.shape)
    small = np.abs(y) <= 0.5
    if np.any(small):
        ys = y[small]
        ay = np.abs(ys)
        log_ay = np.log(ay)
        remainder = np.where(ys > 0.0, _cot_remainder(lam), _csc_remainder(lam))
        head = remainder * np.exp(lam * log_ay) - special.expm1(lam * log_ay) / lam  # A(y) + 1/lam
        k = np.arange(1, _SERIES_TERMS)
        tail = (ys[:, None] ** k[None, :]) @ (1.0 / (k - lam))
        out[small] = head - tail
    right = y > 0.5
    if np.any(right):
        yr = y[right]
        s1, w1 = gauss_jacobi01(30, lam)
        part1 = (0.25 ** (lam + 1.0)) * ((w1[None, :] / (0.25 * s1[None, :] - yr[:, None])).sum(axis=1))
        x2, w2 = gauss_legendre(40)
        s2 = 0.25 + 0.375 * (x2 + 1.0)
        ratio = (s2[None, :] - yr[:, None]) / yr[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            dd = np.where(ratio != 0.0, np.exp(lam * np.log(yr))[:, None] * special.expm1(lam * np.log1p(ratio))
                          / (s2[None, :] - yr[:, None]), lam * yr[:, None] ** (lam - 1.0))
        part2 = 0.375 * (dd @ w2)
        out[right] = part1 + part2 + yr**lam * np.log(np.abs((1.0 - yr) / (0.25 - yr)))
    left = y < -0.5
    if np.any(left):
        s, w = gauss_jacobi01(40, lam)
        out[left] = (w[None, :] / (s[None, :] - y[left][:, None])).sum(axis=1)
    return out


def element_cauchy(lam: float, k: int, y: np.ndarray) -> np.ndarray:
    """I_j(y) = PV int_0^1 s^lam P_j(2s - 1) ds / (s - y), j = 0..k: shape y.shape + (k + 1,)."""
    y = np.asarray(y, dtype=float)
    out = np.empty(y.shape + (k + 1,))
    near = (y >= -NEAR) & (y <= 1.0 + NEAR)
    if np.any(~near):
        s, w = gauss_jacobi01(FAR_NODES, lam)
        P = legendre01(k, s)
        out[~near] = (w[None, :] / (s[None, :] - y[~near][:, None])) @ P
    if np.any(near):
        yn = y[near]
        n = k // 2 + 2  # D_j has degree j - 1: exact
        s, w = gauss_jacobi01(n, lam)
        Py = legendre01(k, yn)
        D = _divided_differences(k, s[None, :], yn[:, None], Py[:, None, :])  # (points, n, k+1)
        out[near] = np.einsum("n,pnk->pk", w, D) + Py * power_cauchy(lam, yn)[:, None]
    return out


def element_integrals(lam: float, k: int) -> np.ndarray:
    """int_0^1 s^lam P_j(2 s - 1) ds, j = 0..k."""
    s, w = gauss_jacobi01(k // 2 + 1, lam)
    return w @ legendre01(k, s)
