"""The collocation system of [S75] (2.2), (2.7)-(2.8) on the singular basis.

Unknowns: the coefficients of P = p and Q = q/x on the stick elements, and of R on the slip
elements, where p = R cos(theta) and q = R sin(theta)/gamma, theta = pi alpha = atan(mu gamma):
q = mu p (2.6b) holds by construction, and both stay bounded for every mu in [0, inf] (mu = inf
is p = 0, q = R/gamma: the limit problem of the largest stick radius).

Rows: (2.2a) with w* = 1 at every collocation point, then (2.2b) with u* = 0 at the stick
points, so the matrix is D(theta) = [S | cos(theta) A + sin(theta)/gamma B].

The Abel integrals (``numeric.core.abel_rules``) that do not depend on alpha (every plain
element, the regular family of the elements touching c^2) are formed once per layout;
the families that carry alpha are contracted per alpha from cached nodes.

The eigenvalue condition is phi(c-) = 0, phi = p - q/mu (2.11), the same as chi(c) = 0
(2.13) and q/(mu p) -> 1 at c (§4.1). In the basis phi = a + h_beta(0) b at c- (a: the
regular part, b: the singular family's), and the functional returned is phi(c-) cos(theta)
for beta > 1/2 and beta phi(c-) cos(theta) = beta a - b otherwise: smooth in beta down to
beta = 0 (mu = inf), where it says that the logarithm of p at c- vanishes.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from numeric.core.abel_rules import (NEAR_OUTSIDE, gauss01, plain_inside_rule, plain_outside_rule, plain_self_rule,
                         sqrt_inside_rule, sqrt_near_outside_rule, sqrt_outside_kernel, sqrt_outside_nodes, sqrt_self_rule)
from numeric.core.charts import (AT_C2, EDGE, PLAIN, SLIP, SLIP_END, STICK, Layout, collocation, family_factors, shifted_legendre)

__all__ = ["AbelOperators", "CollocationSystem", "collocation_system", "normal_factor"]

EXTRA_NODES = 6
"""Gauss points beyond the degree + 1 that are exact for a plain element: they cover the smooth factor 1/x."""


@dataclass(slots=True)
class _Term:
    """Rows ``rows`` of one operator block of a singular element: sum_q W[r, q] phi_j(S[.., q])."""

    rows: np.ndarray | None
    W: np.ndarray
    S: np.ndarray
    P: np.ndarray
    shared: bool  # S, P are one node set (q,) for every row
    regular: np.ndarray | None = None  # the alpha-free regular family, contracted once (elements at c)


@lru_cache(maxsize=None)
def plain_legendre(nq: int, degree: int) -> np.ndarray:
    """Shifted Legendre values at the nq Gauss points of [0, 1]."""
    return shifted_legendre(degree, gauss01(nq)[0])


def _factors(kind: int, S: np.ndarray, alpha: float, displacement: bool, cache: dict):
    """family_factors at the nodes S, computed once per node set within one ``matrices`` call."""
    key = ("f", id(S))
    if key not in cache:
        cache[key] = family_factors(kind, S, alpha, displacement)
    return cache[key]


def _contract(kind: int, term: _Term, alpha: float, sdeg: int, cache: dict, displacement: bool = False) -> np.ndarray:
    """sum_q W phi_j(S) for the basis of a singular element at exponent alpha."""
    regular, singular = _factors(kind, term.S, alpha, displacement, cache)
    if term.regular is not None and not displacement:  # element at c: only the singular family carries alpha
        if term.shared:
            key = ("h", id(term.S))
            if key not in cache:
                cache[key] = singular[:, None] * term.P[:, : sdeg + 1]
            return np.concatenate([term.regular, term.W @ cache[key]], axis=1)
        return np.concatenate([term.regular, np.einsum("iq,iqj->ij", term.W * singular, term.P[..., : sdeg + 1])], axis=1)
    if term.shared:
        key = ("b", id(term.S))
        if key not in cache:
            head = term.P if regular is None else regular[:, None] * term.P
            cache[key] = np.concatenate([head, singular[:, None] * term.P[:, : sdeg + 1]], axis=1)
        return term.W @ cache[key]
    Wr = term.W if regular is None else term.W * regular
    return np.concatenate([np.einsum("iq,iqj->ij", Wr, term.P),
                           np.einsum("iq,iqj->ij", term.W * singular, term.P[..., : sdeg + 1])], axis=1)


class AbelOperators:
    """The Abel integrals of every basis function of a layout at given points.

    For element e, ``matrices(alpha)[e]`` maps "upper", "lower" (and for slip elements
    "upper/x", "lower/x": of phi/x) to (points, n_basis[e]) arrays and "integral" (and
    "integral/x") to the (n_basis[e],) integrals over the element in u. Points default to the
    collocation points (whose rules on their own element are cached); ``names`` and
    ``elements`` restrict what is formed.
    """

    def __init__(self, lay: Layout, points: tuple[np.ndarray, np.ndarray] | None = None,
                 names: tuple[str, ...] = ("upper", "lower"), elements: np.ndarray | None = None) -> None:
        self.layout = lay
        collocated = points is None
        anchor, offset = collocation(lay)[:2] if collocated else points
        self.x = np.sqrt(np.where(anchor == AT_C2, lay.c2, 1.0) + offset)
        self._fixed: dict[int, dict[str, np.ndarray]] = {}
        self._terms: dict[int, dict[str, list[_Term]]] = {}
        self.elements = np.arange(len(lay)) if elements is None else np.asarray(elements)
        rel_all = {}
        own_all = {}
        for e in self.elements:
            ae = lay.anchor[e]
            rel_all[e] = np.where(anchor == ae, 0.0, lay.w if ae != AT_C2 else -lay.w) - offset  # A_e - v
            own = np.zeros(self.x.size, bool)
            if collocated:
                own[lay.starts[e]: lay.starts[e + 1]] = True
            own_all[e] = own
        plain = [int(e) for e in self.elements if lay.kind[e] == PLAIN]
        if plain:
            self._fixed.update(self._plain(plain, np.stack([rel_all[e] for e in plain], axis=1),
                                           np.stack([own_all[e] for e in plain], axis=1), names, collocated))
        for e in self.elements:
            if lay.kind[e] != PLAIN:
                self._terms[e] = self._singular(e, rel_all[e], own_all[e], names)

    def _plain(self, elements: list[int], rel: np.ndarray, own: np.ndarray, names, collocated: bool
               ) -> dict[int, dict[str, np.ndarray]]:
        """All plain elements at once (they share degree and rules): rel, own are (points, elements)."""
        lay = self.layout
        E = np.array(elements)
        deg = int(lay.degree[E[0]])
        m = deg + 1
        nq = deg + 1 + EXTRA_NODES
        N = self.x.size
        L = lay.hi[E] - lay.lo[E]
        lo = lay.lo[E]
        A = np.where(lay.anchor[E] == AT_C2, lay.c2, 1.0)
        slip = lay.zone[E] == SLIP
        xq, wq = gauss01(nq)
        Pq = plain_legendre(nq, deg)
        inv_x = 1.0 / np.sqrt(A[:, None] + lo[:, None] + L[:, None] * xq[None, :])  # (E, nq), used on slip elements
        d_lo, d_hi = rel + lo[None, :], rel + (lo + L)[None, :]
        inside = ~own & (d_lo <= 0.0) & (d_hi >= 0.0)
        out: dict[int, dict[str, np.ndarray]] = {int(e): {} for e in E}
        for upper in (True, False):
            name = "upper" if upper else "lower"
            if name not in names:
                continue
            M = np.zeros((N, E.size, m))
            Mx = np.zeros((N, E.size, m))
            if collocated:  # own points: the same rule on every element, scaled by sqrt(L)
                S, W, P = plain_self_rule(m, nq, upper, deg)
                own_block = np.einsum("iq,iqj->ij", W, P)
                u_own = A[:, None, None] + lo[:, None, None] + L[:, None, None] * S[None]  # (E, m, nq)
                own_x = np.einsum("eiq,iqj->eij", W[None] / np.sqrt(u_own), P)
                for k, e in enumerate(E):
                    rows = slice(int(lay.starts[e]), int(lay.starts[e + 1]))
                    M[rows, k] = math.sqrt(L[k]) * own_block
                    Mx[rows, k] = math.sqrt(L[k]) * own_x[k]
            side = ~own & ~inside & ((d_lo > 0.0) if upper else (d_hi < 0.0))
            distance = d_lo if upper else -d_hi
            near = side & (distance < L[None, :])
            pairs = np.nonzero(inside | near)
            if pairs[0].size:
                i, k = pairs
                in_pair = inside[i, k]
                S = np.empty((i.size, nq)); W = np.empty((i.size, nq))
                if np.any(in_pair):
                    Si, Wi = plain_inside_rule(np.clip(-d_lo[i, k][in_pair] / L[k][in_pair], 0.0, 1.0), nq, upper)
                    S[in_pair], W[in_pair] = Si, Wi * np.sqrt(L[k][in_pair])[:, None]
                if np.any(~in_pair):
                    So, Wo = plain_outside_rule(L[k][~in_pair], d_lo[i, k][~in_pair], d_hi[i, k][~in_pair], upper, nq)
                    S[~in_pair], W[~in_pair] = So, Wo
                P = shifted_legendre(deg, S)
                M[i, k] = np.einsum("iq,iqj->ij", W, P)
                Mx[i, k] = np.einsum("iq,iqj->ij", W / np.sqrt(A[k][:, None] + lo[k][:, None] + L[k][:, None] * S), P)
            far = side & ~near
            if np.any(far):  # the kernel is smooth on the element: one Gauss rule (Bernstein rho >= 5.8)
                diff = np.where(far[:, :, None], d_lo[:, :, None] + L[None, :, None] * xq[None, None, :], 1.0)
                Kf = np.where(far[:, :, None], (0.5 * L[:, None] * wq[None, :])[None] / np.sqrt(np.abs(diff)), 0.0)
                M += np.einsum("ieq,qj->iej", Kf, Pq)
                Mx += np.einsum("ieq,qj->iej", Kf * inv_x[None], Pq)
            for k, e in enumerate(E):
                out[int(e)][name] = M[:, k]
                if slip[k]:
                    out[int(e)][name + "/x"] = Mx[:, k]
        integral = L[:, None] * (wq @ Pq)[None, :]
        integral_x = L[:, None] * ((wq[None, :] * inv_x) @ Pq)
        for k, e in enumerate(E):
            out[int(e)]["integral"] = integral[k]
            if slip[k]:
                out[int(e)]["integral/x"] = integral_x[k]
        return out

    def _singular(self, e: int, rel: np.ndarray, own: np.ndarray, names) -> dict[str, list[_Term]]:
        lay = self.layout
        L, m, deg = lay.length(e), int(lay.n_basis[e]), int(lay.degree[e])
        slip = lay.zone[e] == SLIP
        A = lay.anchor_value(e)
        sign = 1.0 if lay.kind[e] == SLIP_END else -1.0  # u = A + sign L s^2
        rL = math.sqrt(L)
        d = -sign * rel / L  # s_v^2 of every point
        inside = ~own & (d > 0.0) & (d < 1.0)
        So, Wo, one_minus, Po = sqrt_outside_nodes(deg)
        u_o = A + sign * L * So * So
        out: dict[str, list[_Term]] = {}
        for away in (True, False):
            upper = away == (sign > 0.0)  # slip end: u > v is s > s_v
            name = "upper" if upper else "lower"
            if name not in names:
                continue
            terms = []
            if np.any(own):
                S, W, P = sqrt_self_rule(int(lay.kind[e]), m, away, deg)
                terms.append(_Term(np.flatnonzero(own), rL * W, S, P, False))
            if np.any(inside):
                S, W = sqrt_inside_rule(np.sqrt(d[inside]), away, deg)
                terms.append(_Term(np.flatnonzero(inside), rL * W, S, shifted_legendre(deg, S), False))
            side = ~own & ~inside & ((d <= 0.0) if away else (d >= 1.0))
            near = side & ((-d < NEAR_OUTSIDE) if away else (d - 1.0 < NEAR_OUTSIDE))
            rows = np.flatnonzero(side & ~near)
            if rows.size:
                terms.append(_Term(rows, rL * Wo[None, :] * sqrt_outside_kernel(So, one_minus, d[rows]), So, Po, True))
            if np.any(near):
                S, W = sqrt_near_outside_rule(d[near], deg)
                terms.append(_Term(np.flatnonzero(near), rL * W, S, shifted_legendre(deg, S), False))
            out[name] = terms
            if slip:
                out[name + "/x"] = [_Term(t.rows, t.W / np.sqrt(u_o if t.shared else A + sign * L * t.S * t.S), t.S, t.P,
                                          t.shared) for t in terms]
        wi = 2.0 * L * So * Wo  # du = 2 L s ds
        out["integral"] = [_Term(None, wi[None, :], So, Po, True)]
        if slip:
            out["integral/x"] = [_Term(None, (wi / np.sqrt(u_o))[None, :], So, Po, True)]
        if lay.kind[e] != EDGE:  # the regular family of the elements at c does not depend on alpha
            for terms in out.values():
                for t in terms:
                    t.regular = t.W @ t.P if t.shared else np.einsum("iq,iqj->ij", t.W, t.P)
        return out

    def matrices(self, alpha: float, displacement: bool = False) -> dict[int, dict[str, np.ndarray]]:
        """Per element: name -> matrix; ``displacement`` uses the families of u* (``family_factors``)."""
        lay = self.layout
        result = dict(self._fixed)
        for e, blocks in self._terms.items():
            cache: dict = {}
            kind, sdeg, m = int(lay.kind[e]), int(lay.singular_degree[e]), int(lay.n_basis[e])
            mats = {}
            for name, terms in blocks.items():
                if terms and terms[0].rows is None:
                    mats[name] = _contract(kind, terms[0], alpha, sdeg, cache, displacement)[0]
                    continue
                M = np.zeros((self.x.size, m))
                for term in terms:
                    M[term.rows] = _contract(kind, term, alpha, sdeg, cache, displacement)
                mats[name] = M
            result[e] = mats
        return result


@dataclass(frozen=True, slots=True, eq=False)
class CollocationSystem:
    """D(theta) = [stick | cos(theta) normal + sin(theta)/gamma shear], right side, eigen functional."""

    layout: Layout
    gamma: float
    alpha: float            # the exponent the basis carries
    stick: np.ndarray       # (n, 2 ns): columns of P and Q on the stick elements
    normal: np.ndarray      # (n, nl): slip columns multiplying p = R cos(theta)
    shear: np.ndarray       # (n, nl): slip columns multiplying q = R sin(theta)/gamma
    rhs: np.ndarray
    end_row: np.ndarray     # (ns,): value at c- of a stick field (with the beta scaling of the functional)
    integral: np.ndarray    # (ns + nl,): int P du over each element's basis (stick, then slip)
    x: np.ndarray           # collocation points
    u_star_stick: np.ndarray   # (nl, 2 ns): u* of (2.2b) at the slip points from the stick unknowns
    u_star_normal: np.ndarray  # (nl, nl): ... from the slip unknowns, times cos(theta)
    u_star_shear: np.ndarray   # (nl, nl): ... times sin(theta)/gamma

    def u_star(self, theta: float, z: np.ndarray) -> np.ndarray:
        """u* = x int_x^1 q / sqrt(t^2 - x^2) - gamma int_0^x t p / sqrt(x^2 - t^2) (2.2b) at the slip points."""
        ns = self.n_stick
        slip = z[2 * ns:]
        return (self.u_star_stick @ z[: 2 * ns] + normal_factor(theta) * (self.u_star_normal @ slip)
                + _shear_factor(theta, self.gamma) * (self.u_star_shear @ slip))

    @property
    def n_stick(self) -> int:
        return self.end_row.size

    def matrix(self, theta: float) -> np.ndarray:
        return np.concatenate([self.stick, normal_factor(theta) * self.normal + _shear_factor(theta, self.gamma) * self.shear],
                              axis=1)

    def matrix_derivative(self, theta: float) -> np.ndarray:
        """d D / d theta (zero on the stick columns)."""
        n, ns = self.rhs.size, self.n_stick
        out = np.zeros((n, n))
        out[:, 2 * ns:] = -math.sin(theta) * self.normal + (normal_factor(theta) / self.gamma) * self.shear
        return out

    def functional(self, theta: float) -> np.ndarray:
        """l with l . z = phi(c-) cos(theta) (times beta for beta <= 1/2): sin(theta)/gamma p(c-) - cos(theta) q(c-)."""
        ns = self.n_stick
        out = np.zeros(self.rhs.size)
        out[:ns] = _shear_factor(theta, self.gamma) * self.end_row
        out[ns: 2 * ns] = -normal_factor(theta) * self.layout.c * self.end_row
        return out

    def functional_derivative(self, theta: float) -> np.ndarray:
        ns = self.n_stick
        out = np.zeros(self.rhs.size)
        out[:ns] = (normal_factor(theta) / self.gamma) * self.end_row
        out[ns: 2 * ns] = math.sin(theta) * self.layout.c * self.end_row
        return out


def normal_factor(theta: float) -> float:
    """cos(theta), exactly 0 at theta = pi/2 (mu = inf: no pressure on the slip annulus)."""
    return 0.0 if theta >= 0.5 * math.pi else math.cos(theta)


def _shear_factor(theta: float, gamma: float) -> float:
    """sin(theta)/gamma = mu cos(theta)."""
    return math.sin(theta) / gamma


def collocation_system(ops: AbelOperators, gamma: float, alpha: float) -> CollocationSystem:
    """Assemble [S75] (2.2a) at every point and (2.2b) at the stick points for basis exponent alpha."""
    lay = ops.layout
    x = ops.x
    mats = ops.matrices(alpha)
    ns = lay.n_stick
    N = x.size
    nl = N - ns
    n = 2 * ns + nl
    stick = np.zeros((n, 2 * ns))
    normal = np.zeros((n, nl))
    shear = np.zeros((n, nl))
    us_stick = np.zeros((nl, 2 * ns))
    us_normal = np.zeros((nl, nl))
    us_shear = np.zeros((nl, nl))
    xl = x[ns:]
    integral = np.zeros(N)
    xs = x[:ns]
    for e in range(len(lay)):
        M = mats[e]
        cols = slice(int(lay.starts[e]), int(lay.starts[e + 1]))
        integral[cols] = M["integral"] if "integral" in M else 0.0
        if lay.zone[e] == STICK:
            qcols = slice(ns + cols.start, ns + cols.stop)
            stick[:N, cols] = M["upper"]                                                    # (2.2a): int_x^1 t p
            stick[:N, qcols] = -gamma * (0.5 * M["integral"][None, :] - x[:, None] * M["lower"])  # -gamma {int q - x int_0^x}
            stick[N:, qcols] = xs[:, None] * M["upper"][:ns]                                # (2.2b): x int_x^1 q
            stick[N:, cols] = -gamma * M["lower"][:ns]                                      # - gamma int_0^x t p
            us_stick[:, cols] = -gamma * M["lower"][ns:]  # (2.2b) at slip points: the stick q is below them
        else:
            lcols = slice(cols.start - ns, cols.stop - ns)
            normal[:N, lcols] = M["upper"]
            shear[:N, lcols] = -gamma * (0.5 * M["integral/x"][None, :] - x[:, None] * M["lower/x"])
            shear[N:, lcols] = xs[:, None] * M["upper/x"][:ns]
            us_normal[:, lcols] = -gamma * M["lower"][ns:]
            us_shear[:, lcols] = xl[:, None] * M["upper/x"][ns:]
    rhs = np.zeros(n)
    rhs[:N] = 1.0
    e = lay.stick_end
    deg, sdeg = int(lay.degree[e]), int(lay.singular_degree[e])
    at_c = shifted_legendre(deg, np.zeros(1))[0]  # P_k(-1) = (-1)^k
    beta = 1.0 - 2.0 * alpha
    scale_regular, scale_singular = (1.0, 0.0) if beta > 0.5 else (beta, -1.0)
    end_row = np.zeros(ns)
    end_row[int(lay.starts[e]): int(lay.starts[e + 1])] = np.concatenate(
        [scale_regular * at_c, scale_singular * at_c[: sdeg + 1]])
    return CollocationSystem(lay, gamma, alpha, stick, normal, shear, rhs, end_row, integral, x, us_stick, us_normal,
                             us_shear)
