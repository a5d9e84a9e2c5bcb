"""Gauss-Legendre quadrature: the one home of the rules used by the solver and the power-law transforms.

Element rules of the hp discretisation (``numeric.core.graded_mesh``): ``gauss_rule(k)`` gives the
k + 1 nodes and weights on [-1, 1] with the inverse Legendre-Vandermonde matrix that turns
nodal values into Legendre coefficients; ``padded_inverse_vandermonde`` stacks them for all
degrees up to kmax; ``legendre_values`` evaluates P_0 ... P_k by the three-term recurrence.

Composite rules for integrals of a flat-punch solution over [0, x_e] (``numeric.solutions.
power_law``, [S75] (3.13)): ``composite_rule`` puts COMPOSITE_NODES Gauss-Legendre nodes on
each piece [lo, hi]. Near t = 1 a double t resolves 1 - t only to 1.1e-16 absolutely, so
pieces with lo >= 1/2 are built in s = 1 - t: each node is rounded to a double t, its exact
s = 1 - t (Sterbenz) is recovered, and interpolatory weights are solved for the rounded nodes.
``integration_matrices`` integrate the interpolant from each node to the piece's end;
``split_geometric`` and ``grade_to_zero`` place knots for integrands with power behaviour at 0
(every piece [a, b], a > 0, gets b <= 2a).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

__all__ = [
    "COMPOSITE_NODES",
    "graded_rule",
    "gauss_legendre",
    "christoffel_gauss01",
    "gauss_rule",
    "padded_inverse_vandermonde",
    "legendre_values",
    "composite_rule",
    "integration_matrices",
    "split_geometric",
    "grade_to_zero",
    "tanh_sinh01",
]

COMPOSITE_NODES = 30
"""Gauss-Legendre nodes per piece of a composite rule."""


@lru_cache(maxsize=None)
def gauss_legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss-Legendre nodes and weights on [-1, 1] (cached, read-only; the one call of ``leggauss``)."""
    x, w = np.polynomial.legendre.leggauss(n)
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


@lru_cache(maxsize=None)
def christoffel_gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss-Legendre nodes s on [0, 1] with the weights as the Christoffel function, w_i = 1 / sum_(m < n)
    (2 m + 1) P_m(2 s_i - 1)^2 (cached, read-only): a sum of positive terms at the rounded node, so the weights are
    good to a few ulp, where ``leggauss``'s are off by up to 7e-13 relative at n = 40 (against mpmath; the rule then
    integrates 16 s^15 over [0, 1] to 2.4e-14 instead of 4e-16). For rules of many nodes whose every weight counts."""
    x, _ = gauss_legendre(n)
    s = 0.5 * (x + 1.0)
    p = legendre_values(x, n - 1)
    w = 1.0 / ((2.0 * np.arange(n) + 1.0)[:, None] * p * p).sum(axis=0)
    s.setflags(write=False)
    w.setflags(write=False)
    return s, w


@lru_cache(maxsize=None)
def gauss_rule(k: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(k+1)-point Gauss-Legendre nodes, weights on [-1, 1] and the inverse Legendre-Vandermonde
    (nodal values at the nodes -> Legendre coefficients of the degree-k interpolant)."""
    x, w = gauss_legendre(k + 1)
    return x, w, np.linalg.inv(np.polynomial.legendre.legvander(x, k))


@lru_cache(maxsize=None)
def padded_inverse_vandermonde(kmax: int) -> np.ndarray:
    """Inverse Vandermonde of every degree k <= kmax, zero-padded: [k, legendre, node]."""
    out = np.zeros((kmax + 1, kmax + 1, kmax + 1))
    for k in range(kmax + 1):
        out[k, : k + 1, : k + 1] = gauss_rule(k)[2]
    return out


def legendre_values(xi: np.ndarray, k: int) -> np.ndarray:
    """Legendre polynomials P_0..P_k at xi, stacked on the first axis (three-term recurrence)."""
    out = np.empty((k + 1,) + np.shape(xi))
    out[0] = 1.0
    if k >= 1:
        out[1] = xi
    scratch = np.empty(np.shape(xi))
    for n in range(1, k):  # ((2 n + 1) xi P_n - n P_(n-1)) / (n + 1), in place: the same operations, no temporaries
        following = out[n + 1]
        np.multiply(2 * n + 1, xi, out=following)
        following *= out[n]
        np.multiply(n, out[n - 1], out=scratch)
        following -= scratch
        following /= n + 1
    return out


def composite_rule(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights, shape (len(lo), COMPOSITE_NODES), of Gauss-Legendre on each [lo, hi].

    Pieces with lo >= 1/2 are mapped in s = 1 - t and get interpolatory weights for the
    rounded nodes (see the module docstring), so that 1 - t is exact at every node.
    """
    xi, w = gauss_legendre(COMPOSITE_NODES)
    half = 0.5 * (hi - lo)
    nodes = (0.5 * (hi + lo))[:, None] + half[:, None] * xi
    weights = half[:, None] * w
    near = lo >= 0.5
    if np.any(near):
        s_lo, s_hi = 1.0 - hi[near], 1.0 - lo[near]  # exact (Sterbenz)
        hs, ms = 0.5 * (s_hi - s_lo), 0.5 * (s_hi + s_lo)
        t = 1.0 - (ms[:, None] + hs[:, None] * xi)
        s = 1.0 - t  # exact
        hs_safe = np.where(hs > 0.0, hs, 1.0)
        xi_true = np.clip((s - ms[:, None]) / hs_safe[:, None], -1.0, 1.0)
        vander = np.polynomial.legendre.legvander(xi_true, COMPOSITE_NODES - 1)  # (M, N, N)
        rhs = np.zeros(COMPOSITE_NODES)
        rhs[0] = 2.0
        # Rounded nodes of very short pieces may coincide; keep plain Gauss weights there.
        distinct = np.all(np.diff(np.sort(xi_true, axis=1), axis=1) > 1e-3 / COMPOSITE_NODES**2, axis=1)
        w_true = np.broadcast_to(w, xi_true.shape).copy()
        if np.any(distinct):
            mats = np.swapaxes(vander[distinct], 1, 2)
            w_true[distinct] = np.linalg.solve(mats, np.broadcast_to(rhs, (mats.shape[0], COMPOSITE_NODES))[..., None])[..., 0]
        nodes[near] = t
        weights[near] = hs[:, None] * w_true
    return nodes, weights


def integration_matrices(nodes: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """M with (M f)_i = int_{t_i}^{hi} of the interpolant of f at the nodes of each piece.

    With xi the local coordinate, int_xi^1 P_k = (P_{k-1}(xi) - P_{k+1}(xi))/(2k + 1)
    (k >= 1) and 1 - xi (k = 0); M = W V^-1 (times the half-length). Shape (pieces, N, N).
    """
    near = lo >= 0.5
    xi = np.empty(nodes.shape)
    half = 0.5 * (hi - lo)
    half_safe = np.where(half > 0.0, half, 1.0)
    xi[~near] = (nodes[~near] - (0.5 * (hi + lo))[~near, None]) / half_safe[~near, None]
    s, s_lo, s_hi = 1.0 - nodes[near], 1.0 - hi[near], 1.0 - lo[near]
    xi[near] = -(s - 0.5 * (s_hi + s_lo)[:, None]) / half_safe[near, None]
    xi = np.clip(xi, -1.0, 1.0)
    # rounded nodes of very short pieces may coincide (as in composite_rule): use the ideal ones there
    distinct = np.all(np.diff(np.sort(xi, axis=1), axis=1) > 1e-3 / COMPOSITE_NODES**2, axis=1)
    xi[~distinct] = gauss_legendre(COMPOSITE_NODES)[0]
    vander = np.polynomial.legendre.legvander(xi, COMPOSITE_NODES)  # P_0 .. P_N
    k = np.arange(1, COMPOSITE_NODES)
    integ = np.empty(xi.shape + (COMPOSITE_NODES,))
    integ[..., 0] = 1.0 - xi
    integ[..., 1:] = (vander[..., k - 1] - vander[..., k + 1]) / (2 * k + 1)
    basis = vander[..., :COMPOSITE_NODES]
    # M = integ @ inv(basis)  ->  solve basis^T M^T = integ^T
    mats = np.swapaxes(np.linalg.solve(np.swapaxes(basis, 1, 2), np.swapaxes(integ, 1, 2)), 1, 2)
    return mats * half[:, None, None]


def split_geometric(knots: np.ndarray) -> np.ndarray:
    """Insert points so that every piece [a, b] with a > 0 has b <= 2a (sorted, unique)."""
    lo, hi = knots[:-1], knots[1:]
    ratio = np.divide(hi, lo, out=np.ones_like(hi), where=lo > 0.0)
    count = np.where(lo > 0.0, np.ceil(np.log2(np.maximum(ratio, 1.0)) - 1e-12), 1.0).astype(int)
    count = np.maximum(count, 1)
    if np.all(count == 1):
        return knots
    parts = [knots[:1]]
    for a, b, k in zip(lo, hi, count):
        if k == 1:
            parts.append(np.array([b]))
        else:
            parts.append(a * (b / a) ** (np.arange(1, k + 1) / k))
            parts[-1][-1] = b
    return np.concatenate(parts)


def grade_to_zero(b1: float, levels: int = 64) -> np.ndarray:
    """Knots b1 2^-levels, ..., b1/2 (for integrands like t^n at t = 0)."""
    return b1 * 2.0 ** -np.arange(levels, 0, -1, dtype=float)


@lru_cache(maxsize=None)
def graded_rule(layers: int, ratio: float, nmax: int, nmin: int, dn: int) -> tuple[np.ndarray, np.ndarray]:
    """Composite Gauss-Legendre on [0, 1] graded geometrically toward 0 (sorted nodes, weights; read-only).

    Pieces [ratio^(j+1), ratio^j], j = 0 .. layers - 1, and [0, ratio^layers]; the piece j gets
    max(nmin, nmax - dn j) nodes (an hp rule: integrands with an algebraic or logarithmic
    singularity at 0 converge geometrically in the number of pieces).
    """
    xs, ws = [], []
    hi = 1.0
    for j in range(layers + 1):
        lo = ratio * hi if j < layers else 0.0
        x, w = gauss_legendre(max(nmin, nmax - dn * j))
        xs.append(lo + 0.5 * (hi - lo) * (x + 1.0))
        ws.append(0.5 * (hi - lo) * w)
        hi = lo
    x, w = np.concatenate(xs), np.concatenate(ws)
    order = np.argsort(x)
    x, w = x[order], w[order]
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


@lru_cache(maxsize=None)
def tanh_sinh01(step: float = 1.0 / 16.0, span: float = 3.2) -> tuple[np.ndarray, np.ndarray]:
    """Tanh-sinh (double-exponential) nodes and weights on (0, 1), read-only.

    v = (1 + tanh((pi/2) sinh(t))) / 2 for t = -span .. span in ``step``: integrands with algebraic
    singularities at either end (the plane solver's (1 - x)^(alpha - 1/2), |x - c|^(1/2 - alpha)) converge
    double-exponentially; nodes that round to 0 or 1 are dropped.
    """
    t = np.arange(-span, span + 0.5 * step, step)
    u = 0.5 * np.pi * np.sinh(t)
    v = 0.5 * (1.0 + np.tanh(u))
    w = 0.25 * np.pi * step * np.cosh(t) / np.cosh(u) ** 2
    keep = (v > 0.0) & (v < 1.0)
    v, w = v[keep], w[keep]
    v.setflags(write=False)
    w.setflags(write=False)
    return v, w
