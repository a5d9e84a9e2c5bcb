"""Quadrature rules for the Abel integrals of the singular basis ([S75] (2.2)).

With u = t^2 the integrals of (2.2) are, for a basis function phi on an element,

    upper:  int_{u > v} phi(u) du / (2 sqrt(u - v)) = int_x^1 t p dt / sqrt(t^2 - x^2),
    lower:  int_{u < v} phi(u) du / (2 sqrt(v - u)) = int_0^x t p dt / sqrt(x^2 - t^2),   v = x^2.

Each rule returns chart nodes S and weights W with integral = sum_q W[q] phi(S[q]); weights
include the kernel and the Jacobian, but not the factor sqrt(L) of the element length L,
which the caller applies. Cases:

- plain element (polynomial in u): |u - v| = t^2 makes the integrand a polynomial in t,
  so K + 1 Gauss points in t are exact for every v (the substitution of
  ``numeric.core.mesh``); a few more cover a smooth extra factor 1/x.
- sqrt chart u = A +/- L s^2, point v inside (s_v in (0, 1)): on the side of s_v away from
  the singular end, s = sqrt(s_v^2 + t^2) removes the kernel singularity (|u - v| = L t^2)
  and leaves an integrand analytic in t but for t = +/- i s_v, so the t rule is graded toward
  0; on the side toward the singular end, s = s_v sin(theta) (|u - v| = L s_v^2 cos^2) leaves
  the singular family at theta = 0, so that rule is graded toward 0.
- sqrt chart, point outside: the kernel s / sqrt(s^2 + e^2) (before the singular end) or
  s / sqrt(s_v^2 - s^2) (beyond the far end) on one fixed node set graded toward both ends,
  so the block is a matrix product; points well away from the element (``FAR_BEFORE``,
  ``FAR_BEYOND``) have the kernel interpolated at 32 Chebyshev points instead, and the
  integrals of the Lagrange polynomials against the basis on the fixed nodes
  (``outside_projector``) are formed once per element and exponent.

The number of graded pieces and nodes was chosen by ``tests/test_abel_rules.py``: every rule
agrees with a 30-digit mpmath quadrature to 1e-15 relative on the basis functions.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from numeric.core.charts import collocation_chart, shifted_legendre
from numeric.core.quadrature import gauss_legendre, graded_rule

__all__ = ["TOWARD", "AWAY", "WHOLE", "FAR_END", "sqrt_inside_rule", "sqrt_self_rule", "sqrt_outside_nodes", "sqrt_outside_kernel", "sqrt_outside_kernel_change", "sqrt_near_outside_rule", "NEAR_OUTSIDE",
           "FAR_BEFORE", "FAR_BEYOND", "INTERPOLATION_POINTS", "chebyshev_points01", "outside_projector",
           "plain_inside_rule", "plain_self_rule", "plain_outside_rule", "gauss01"]

#: Graded rules (layers, ratio, extra, nmin, dn): toward the singular family (theta), toward the
#: complex kernel point i s_v (t), whole element from outside toward 0, and toward the far end;
#: the outermost piece has degree + extra nodes, each further piece dn fewer, at least nmin.
TOWARD = (28, 0.2, 8, 4, 1)
NEAR = (24, 0.2, 6, 6, 0)
AWAY = (12, 0.2, 6, 6, 0)
WHOLE = (28, 0.2, 8, 4, 1)
FAR_END = (10, 0.2, 6, 6, 2)


def _graded(spec: tuple, degree: int) -> tuple[np.ndarray, np.ndarray]:
    layers, ratio, extra, nmin, dn = spec
    return graded_rule(layers, ratio, degree + extra, nmin, dn)


@lru_cache(maxsize=None)
def gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss-Legendre nodes and weights on [0, 1]."""
    x, w = gauss_legendre(n)
    return 0.5 * (x + 1.0), 0.5 * w


def sqrt_inside_rule(s: np.ndarray, away: bool, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """Rule for points with chart value s in (0, 1) inside a sqrt-chart element: S, W of shape (len(s), q).

    ``away``: the part s' > s (away from the singular end), else s' < s."""
    if away:
        t, wt = _graded(AWAY, degree)
        T = np.sqrt((1.0 - s) * (1.0 + s))
        tt = T[:, None] * t[None, :]
        return np.sqrt(s[:, None] ** 2 + tt * tt), T[:, None] * wt[None, :]
    th, wt = _graded(TOWARD, degree)
    th = 0.5 * math.pi * th
    return s[:, None] * np.sin(th)[None, :], s[:, None] * (0.5 * math.pi * np.sin(th) * wt)[None, :]


@lru_cache(maxsize=None)
def sqrt_self_rule(kind: int, n: int, away: bool, degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``sqrt_inside_rule`` at the n collocation points of an element of this kind, with the shifted
    Legendre values at the nodes, (n, q, degree + 1) (cached: the same for every such element)."""
    S, W = sqrt_inside_rule(collocation_chart(kind, n), away, degree)
    return S, W, shifted_legendre(degree, S)


@lru_cache(maxsize=None)
def sqrt_outside_nodes(degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Fixed nodes on [0, 1] for points outside a sqrt-chart element: [0, 1/2] graded toward 0,
    [1/2, 1] graded toward 1. Returns S, weights, 1 - S (exact) and the shifted Legendre values."""
    xw, ww = _graded(WHOLE, degree)
    xf, wf = _graded(FAR_END, degree)
    S = np.concatenate([0.5 * xw, 1.0 - 0.5 * xf])
    one_minus = np.concatenate([1.0 - 0.5 * xw, 0.5 * xf])
    W = np.concatenate([0.5 * ww, 0.5 * wf])
    return S, W, one_minus, shifted_legendre(degree, S)


#: Points outside a sqrt-chart element closer than this (in s^2 from its singular end, or from
#: its far end) get a rule of their own: the shared nodes resolve the kernel only down to here.
NEAR_OUTSIDE = 1e-3


#: Points outside a sqrt-chart element beyond its singular end by at least -FAR_BEFORE (in s^2), or beyond its far
#: end with s_v^2 >= FAR_BEYOND, see a kernel s / sqrt|s^2 - s_v^2| (times the smooth 1/x) that INTERPOLATION_POINTS
#: Chebyshev points in s resolve to rounding (interpolation error at the thresholds, measured: 8.7e-16 and 4.4e-16
#: of the kernel's maximum; the singularities are at s = +-i 0.5 and s = 1.41). Their integrals are then
#: kernel(Chebyshev points) @ ``outside_projector`` @ basis(outside nodes): INTERPOLATION_POINTS kernel values a
#: point instead of one per outside node.
FAR_BEFORE, FAR_BEYOND = -0.25, 2.0
INTERPOLATION_POINTS = 32


@lru_cache(maxsize=None)
def chebyshev_points01(r: int = INTERPOLATION_POINTS) -> tuple[np.ndarray, np.ndarray]:
    """Chebyshev points of the second kind on [0, 1] (both ends included) and 1 - s at them (exact)."""
    k = np.arange(r)
    s = 0.5 * (1.0 - np.cos(np.pi * k / (r - 1)))
    one_minus = 0.5 * (1.0 + np.cos(np.pi * k / (r - 1)))
    return s, one_minus


@lru_cache(maxsize=None)
def outside_projector(degree: int) -> np.ndarray:
    """(r, q): row k is the outside nodes' weights times the Lagrange polynomial of Chebyshev point k at the
    nodes (barycentric form), so that projector @ f(nodes) = int_0^1 l_k(s) f(s) ds by the outside rule."""
    S, W, _, _ = sqrt_outside_nodes(degree)
    xk, _ = chebyshev_points01()
    r = xk.size
    bary = np.where(np.arange(r) % 2 == 0, 1.0, -1.0)
    bary[0] *= 0.5
    bary[-1] *= 0.5
    diff = S[:, None] - xk[None, :]
    terms = bary[None, :] / diff  # no outside node is a Chebyshev point (graded Gauss nodes are irrational)
    lagrange = terms / terms.sum(axis=1, keepdims=True)  # (q, r)
    out = (W[:, None] * lagrange).T
    out.setflags(write=False)
    return out


def sqrt_near_outside_rule(d: np.ndarray, degree: int) -> tuple[np.ndarray, np.ndarray]:
    """Rules S, W (rows, q) for points outside a sqrt-chart element near one of its ends.

    d = s_v^2 <= 0 (beyond the singular end, e^2 = -d): w^2 = s^2 + e^2 turns the kernel
    s ds / sqrt(s^2 + e^2) into dw, w in [e, sqrt(1 + e^2)], graded toward w = e (s = 0, and the
    branch point w = -e of s(w), so every piece keeps its nodes). d >= 1 (beyond the far end):
    on [0, 1/2] the kernel s / sqrt(d - s^2) is smooth and the rule is graded toward the
    singular family at s = 0; on [1/2, 1], w^2 = d - s^2 turns s ds / sqrt(d - s^2) into dw.
    """
    before = d <= 0.0
    x, wx = _graded(NEAR, degree)
    S = np.zeros((d.size, x.size))  # rows beyond the far end are overwritten below, and their spare columns must
    W = np.zeros((d.size, x.size))  # hold nodes (zeros), not leftover memory: a weight 0 times a NaN node is NaN
    if np.any(before):
        e = np.sqrt(-d[before])
        top = np.sqrt(1.0 - d[before])
        width = 1.0 / (top + e)  # top - e without cancellation
        t = width[:, None] * x[None, :]  # w - e
        S[before] = np.sqrt(t * (t + 2.0 * e[:, None]))
        W[before] = width[:, None] * wx[None, :]
    if np.any(~before):
        dv = d[~before]
        xs, ws = _graded(TOWARD, degree)
        xg, wg = gauss01(degree + 6)
        # [0, 1/2] in s: kernel s / sqrt(d - s^2), smooth there (d - s^2 >= 3/4); graded toward s = 0
        s1 = 0.5 * xs
        k1 = (0.5 * ws * s1)[None, :] / np.sqrt(dv[:, None] - s1[None, :] ** 2)
        # [1/2, 1] by w^2 = d - s^2: w from sqrt(d - 1) to sqrt(d - 1/4), integrand phi(s(w)) dw
        lo_w, hi_w = np.sqrt(dv - 1.0), np.sqrt(dv - 0.25)
        width = 0.75 / (lo_w + hi_w)
        w = lo_w[:, None] + width[:, None] * xg[None, :]
        s2 = np.sqrt((1.0 - (w - lo_w[:, None]) * (w + lo_w[:, None])))  # s^2 = d - w^2 = 1 - (w^2 - (d - 1))
        n1, n2 = xs.size, xg.size
        S_after = np.concatenate([np.broadcast_to(s1, (dv.size, n1)), s2], axis=1)
        W_after = np.concatenate([k1, width[:, None] * wg[None, :]], axis=1)
        S_full = np.zeros((d.size, max(S.shape[1], n1 + n2)))
        W_full = np.zeros_like(S_full)
        S_full[:, : S.shape[1]] = S
        W_full[:, : W.shape[1]] = W
        S_full[~before, : n1 + n2] = S_after
        W_full[~before, : n1 + n2] = W_after
        W_full[~before, n1 + n2:] = 0.0
        S, W = S_full, W_full
    return np.minimum(S, 1.0), W


def sqrt_outside_kernel(S: np.ndarray, one_minus: np.ndarray, d: np.ndarray, before: bool) -> np.ndarray:
    """Kernel factor (rows, q) for points with s_v^2 = d outside [0, 1], all on one side.

    ``before`` (d <= 0, the points beyond the singular end, at distance e^2 = -d): s / sqrt(s^2 + e^2);
    else (d >= 1, beyond the far end): s / sqrt(d - s^2), with d - s^2 = (d - 1) + (1 - s)(1 + s).
    """
    if before:
        return S[None, :] / np.sqrt(S[None, :] ** 2 - d[:, None])
    return S[None, :] / np.sqrt((d - 1.0)[:, None] + (one_minus * (1.0 + S))[None, :])


def sqrt_outside_kernel_change(S: np.ndarray, one_minus: np.ndarray, d: np.ndarray, d_ref: float, change: np.ndarray,
                               before: bool) -> np.ndarray:
    """``sqrt_outside_kernel`` at s_v^2 = d less its value at d_ref, (rows, q), formed without cancellation.

    ``change`` is d - d_ref, formed by the caller from the points' offsets (not from d). With A = s^2 - d (``before``)
    or B = d - s^2, 1/sqrt(A) - 1/sqrt(A_ref) = (A_ref - A) / (sqrt(A) sqrt(A_ref) (sqrt(A) + sqrt(A_ref))): far from the
    element the kernel barely changes between two points, and the difference of its two values would keep only the
    rounding of either (the rows of [S75] (2.2a) differenced against a reference point, ``numeric.core.operators``).
    """
    if before:
        a, a_ref, gain = S[None, :] ** 2 - d[:, None], S ** 2 - d_ref, change
    else:
        a, a_ref = (d - 1.0)[:, None] + (one_minus * (1.0 + S))[None, :], (d_ref - 1.0) + one_minus * (1.0 + S)
        gain = -change
    ra, rr = np.sqrt(a), np.sqrt(a_ref)[None, :]
    return S[None, :] * gain[:, None] / (ra * rr * (ra + rr))


def plain_inside_rule(xi_v: np.ndarray, nq: int, upper: bool) -> tuple[np.ndarray, np.ndarray]:
    """w-rule of a plain element for points xi_v in [0, 1] inside it: S, W (len(xi_v), nq)."""
    x, wq = gauss01(nq)
    T = np.sqrt(1.0 - xi_v) if upper else np.sqrt(xi_v)
    t = T[:, None] * x[None, :]
    S = np.clip(xi_v[:, None] + t * t if upper else xi_v[:, None] - t * t, 0.0, 1.0)
    return S, T[:, None] * wq[None, :]


@lru_cache(maxsize=None)
def plain_self_rule(n: int, nq: int, upper: bool, degree: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``plain_inside_rule`` at the n collocation points, with the Legendre values (cached)."""
    S, W = plain_inside_rule(gauss01(n)[0], nq, upper)
    return S, W, shifted_legendre(degree, S)


def plain_outside_rule(L, d_lo: np.ndarray, d_hi: np.ndarray, upper: bool, nq: int) -> tuple[np.ndarray, np.ndarray]:
    """w-rule of plain elements of length L (scalar or per point) for points wholly below (upper) or
    above (lower) them.

    d_lo = u_lo - v, d_hi = u_hi - v. Nodes xi in [0, 1] and weights, both (rows, nq), formed
    without cancellation: the t-interval has length L / (t_a + t_b)."""
    x, wq = gauss01(nq)
    L = np.broadcast_to(np.asarray(L, dtype=float), d_lo.shape)
    if upper:
        ta, tb = np.sqrt(d_lo), np.sqrt(d_hi)
        width = L / (ta + tb)
        step = width[:, None] * x[None, :]
        xi = step * (2.0 * ta[:, None] + step) / L[:, None]
    else:
        ta, tb = np.sqrt(-d_hi), np.sqrt(-d_lo)
        width = L / (ta + tb)
        step = width[:, None] * x[None, :]
        xi = step * (2.0 * tb[:, None] - step) / L[:, None]
    return np.clip(xi, 0.0, 1.0), width[:, None] * wq[None, :]
