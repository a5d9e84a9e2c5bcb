"""The collocation system of [S75] (2.2), (2.7)-(2.8) on the singular basis.

Unknowns: the coefficients of P = p and Q = q/x on the stick elements, and of R on the slip
elements, where p = R cos(theta) and q = R sin(theta)/gamma, theta = pi alpha = atan(mu gamma):
q = mu p (2.6b) holds by construction, and both stay bounded for every mu in [0, inf] (mu = inf
is p = 0, q = R/gamma: the limit problem of the largest stick radius).

Rows: (2.2a) with w* = 1 at every collocation point, then (2.2b) with u* = 0 at the stick
points, so the matrix is D(theta) = [S | cos(theta) A + sin(theta)/gamma B].

The Abel integrals (``numeric.core.abel_rules``) that do not depend on alpha (every plain
element, the regular family of the elements touching c^2) are formed once per layout, all
points and elements of a kind at once, into matrices over the whole basis (``AbelMatrices``);
the families that carry alpha are contracted per alpha from cached nodes.

The eigenvalue condition is phi(c-) = 0, phi = p - q/mu (2.11), the same as chi(c) = 0
(2.13) and q/(mu p) -> 1 at c (§4.1). The stick pressure has no singular family
(``numeric.core.stick_pressure_pins``: for beta <= 1/2 its coefficients are pinned to 0, above h_beta(0) = 0), so
p(c-) = a_P, the regular part, and q(c-) = c (a_Q + h_beta(0) b_Q) with h_beta(0) = -1/beta for
beta <= 1/2 (0 above). The functional returned is
mu cos(theta) phi(c-) = sin(theta)/gamma a_P - c cos(theta) a_Q + c (cos(theta)/beta) b_Q:
smooth down to beta = 0 (mu = inf), where cos(theta)/beta tends to pi/2 on the diagonal theta = pi (1 - beta)/2
and the condition becomes a_P/gamma + (pi/2) c b_Q = 0 (the limit problem of the largest stick radius).

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

from numeric.core.abel_rules import (FAR_BEFORE, FAR_BEYOND, INTERPOLATION_POINTS, NEAR_OUTSIDE, chebyshev_points01, gauss01,
                                     outside_projector,
                                     plain_inside_rule, plain_outside_rule, plain_self_rule, sqrt_inside_rule,
                                     sqrt_near_outside_rule, sqrt_outside_kernel, sqrt_outside_kernel_change,
                                     sqrt_outside_nodes, sqrt_self_rule)
from numeric.core.charts import (AT_C2, EDGE, PLAIN, SLIP, SLIP_END, STICK, STICK_END, Layout, chart_logarithm,
                                 collocation, collocation_chart, family_factors,
                                 shifted_legendre)
from numeric.core.linear_algebra import pin_to_zero
from numeric.core.stick_pressure_pins import pinned_rows, pins_stick_pressure

__all__ = ["AbelMatrices", "AbelOperators", "VaryingColumns", "CollocationSystem", "collocation_system", "near_plain",
           "normal_factor", "partner_near_rule", "projected_outside_legendre", "self_legendre_block", "stick_end_rows"]

EXTRA_NODES = 6
"""Gauss points beyond the degree + 1 that are exact for a plain element: they cover the smooth factor 1/x."""



def near_plain(degree: int) -> float:
    """Distance from a plain element, in element lengths, below which a point gets the exact rule in t = sqrt|u - v|.

    Beyond it the degree + 1 + EXTRA_NODES Gauss points integrate P_k(u)/sqrt|u - v| to rounding: the kernel's
    branch point at distance delta gives the Bernstein ellipse rho = (sqrt(delta) + sqrt(1 + delta))^2, and the
    rule's error falls like rho^-(2 nq - degree); this distance puts that at e^-35 = 6e-16. Measured against
    mpmath at the distance for degrees 6 ... 18 (``tests/test_abel_rules.py``): <= 2.1e-15 relative (1.7e-15 is the
    rounding of the degree-18 sums at any distance).
    """
    rho = math.exp(35.0 / (2 * (degree + 1 + EXTRA_NODES) - degree))
    return (0.5 * (math.sqrt(rho) - 1.0 / math.sqrt(rho))) ** 2

NAMES = ("upper", "lower")
"""The two Abel integrals: over u > v and over u < v (``numeric.core.abel_rules``)."""

REFERENCE = 0
"""The collocation point (the first, the one nearest the centre) whose row of [S75] (2.2a) the others are differenced
against (``collocation_system``)."""

CHANGE = "change"
"""The key of ``AbelMatrices.change``: the upper integral less its row at ``REFERENCE``."""

CANCELLATION_FREE_BELOW = 0.2
"""Stick radii below which ``AbelMatrices.change`` is formed without cancellation; above, by subtracting the rows
(the loss there is the componentwise condition of theta, which grows like 1/c: 2e2 at c = 0.1, 35 differenced).
Measured at level 2 over nu in {-0.5, 0, 0.3, 0.45}: for c = 0.2 ... 0.95 the two ways agree within 1.3e-15 in mu,
4.4e-16 in P* and 2.8e-11 in p, q, u (relative to max(1, |p|), at x = 0, c/2, c and its neighbouring doubles,
(1 + c)/2, 1 - 1e-5), with the same error against level 4; at c = 0.05 subtracting left p 9.6e-12 off level 4 where
the cancellation-free change has 1.7e-12. The cancellation-free terms cost ~0.45 ms of a 3 ms layout."""


@lru_cache(maxsize=None)
def plain_legendre(nq: int, degree: int) -> np.ndarray:
    """Shifted Legendre values at the nq Gauss points of [0, 1]."""
    return shifted_legendre(degree, gauss01(nq)[0])


@lru_cache(maxsize=None)
def partner_near_rule(partner_kind: int, partner_n: int, degree: int
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The near-outside rule of an element touching c^2 at its partner's collocation points (the element on the other
    side of c^2, of the same length): which of the partner's points (chart order) lie within NEAR_OUTSIDE of the shared
    end, d = -s^2 there (s the partner's chart points), S, W, P of ``sqrt_near_outside_rule`` and their block of the
    Legendre family, sum_q W P (read-only).

    Both ends have length c_fraction * min(c^2, 1 - c^2) and their charts are anchored at c^2, so these points, their
    rule and its Legendre values are the same for every c: formed once per degree, not per layout. (Formed from the
    offsets, d differs from -s^2 by the rounding of L s^2 / L.)"""
    s = collocation_chart(partner_kind, partner_n)
    d = -(s * s)
    take = np.flatnonzero(-d < NEAR_OUTSIDE)
    S, W = sqrt_near_outside_rule(d[take], degree)
    P = shifted_legendre(degree, S)
    out = (take, S, W, P, _weighted_sum(W, P))
    for a in out:
        a.setflags(write=False)
    return out


@lru_cache(maxsize=None)
def projected_outside_legendre(degree: int) -> np.ndarray:
    """The Legendre values on the outside nodes projected onto the Chebyshev points (``outside_projector`` @ P): the
    far points' block of the Legendre family is their kernel's weights times this (read-only)."""
    out = outside_projector(degree) @ sqrt_outside_nodes(degree)[3]
    out.setflags(write=False)
    return out


@lru_cache(maxsize=None)
def self_legendre_block(kind: int, n: int, away: bool, degree: int) -> np.ndarray:
    """sum_q W[r, q] P_j(S[r, q]) of ``sqrt_self_rule`` (its own points' block of the Legendre family, without the
    factor sqrt(L)); the same for every element of this kind (read-only)."""
    S, W, P = sqrt_self_rule(kind, n, away, degree)
    out = _weighted_sum(W, P)
    out.setflags(write=False)
    return out


def _weighted_sum(W: np.ndarray, P: np.ndarray) -> np.ndarray:
    """sum_q W[i, q] P[i, q, j] for every row i (a batched product, BLAS)."""
    return np.matmul(W[:, None, :], P)[:, 0, :]


@dataclass(frozen=True, slots=True, eq=False)
class AbelMatrices:
    """The Abel integrals of every basis function (columns, in ``Layout.starts`` order) at the points (rows).

    ``upper``/``lower``: int_{u > v} and int_{u < v} of phi(u) du / (2 sqrt|u - v|); ``upper_x``/``lower_x``:
    the same of phi(u)/sqrt(u) (filled in the slip columns only, where q = R sin(theta)/gamma is not divided
    by x); ``integral``, ``integral_x``: int phi du and int phi/sqrt(u) du over each element. Columns of
    elements not asked for are 0; what was not formed (a name not asked for, the divided integrals without
    ``AbelOperators``' ``divided``) is empty.

    ``change``: ``upper`` less its row at the collocation point ``REFERENCE``, formed without cancellation where a point
    and the reference see an element through the same outside rule (far from it, where the kernel barely changes), as
    the difference of the two rows elsewhere (there it loses nothing); formed on the collocation points only.
    """

    upper: np.ndarray
    lower: np.ndarray
    upper_x: np.ndarray
    lower_x: np.ndarray
    integral: np.ndarray
    integral_x: np.ndarray
    change: np.ndarray

    def of(self, name: str) -> np.ndarray:
        """The matrix or vector called ``name`` ("upper", "lower/x", "integral", ...)."""
        return getattr(self, name.replace("/", "_"))


@dataclass(frozen=True, slots=True)
class _Term:
    """Rows ``rows`` (None: the element integral) of one block of a singular element: sum_q W[r, q] phi_j(S[.., q]).

    ``shared``: S and P are one node set (q,) for every row; with a ``projector`` (r, q), W is (rows, r) and the
    block is W @ projector @ phi(S) (kernels interpolated at r Chebyshev points, ``abel_rules.outside_projector``)."""

    rows: np.ndarray | None
    W: np.ndarray
    S: np.ndarray
    P: np.ndarray
    shared: bool
    projector: np.ndarray | None = None
    regular: np.ndarray | None = None  # the Legendre family's block, where it comes from a cached product

    def contract(self, basis: np.ndarray) -> np.ndarray:
        """The block for a basis tabulated on the shared nodes, basis (q, columns)."""
        return self.W @ (basis if self.projector is None else self.projector @ basis)

    def legendre_block(self, degree: int) -> np.ndarray:
        """The block of the Legendre family P_0 .. P_degree (the regular family of the elements at c): the cached
        product where there is one (``regular``; the projected nodes' ``projected_outside_legendre``)."""
        if self.regular is not None:
            return self.regular
        if self.projector is not None:
            return self.W @ projected_outside_legendre(degree)
        return self.W @ self.P if self.shared else _weighted_sum(self.W, self.P)


def _nodes_u(t: _Term, u_outside: np.ndarray, u_chebyshev: np.ndarray, anchor: float, scale: float) -> np.ndarray:
    """u at the points where a term's weights sit: its own nodes, the shared outside nodes, or the Chebyshev points."""
    if not t.shared:
        return anchor + scale * t.S * t.S
    return u_outside if t.projector is None else u_chebyshev


class AbelOperators:
    """The Abel integrals of every basis function of a layout at given points.

    ``matrices(alpha)`` gives them as an ``AbelMatrices``. Points default to the collocation points (whose rules
    on their own element are cached); ``names`` ("upper", "lower") and ``elements`` restrict what is formed, and
    ``divided=False`` leaves out the integrals of phi/sqrt(u) (``AbelMatrices.upper_x`` ... empty).
    What does not depend on alpha (every plain element, the regular family of the elements touching c^2) is
    formed here, once per layout and point set; the families that carry alpha are kept as quadrature terms
    (weights, nodes, Legendre values) and contracted per alpha.
    """

    def __init__(self, lay: Layout, points: tuple[np.ndarray, np.ndarray] | None = None,
                 names: tuple[str, ...] = NAMES, elements: np.ndarray | None = None, divided: bool = True) -> None:
        self.layout = lay
        collocated = points is None
        anchor, offset = collocation(lay)[:2] if collocated else points
        self.x = np.sqrt(np.where(anchor == AT_C2, lay.c2, 1.0) + offset)
        N, nb = self.x.size, int(lay.starts[-1])
        self.names = tuple(n for n in NAMES if n in names)
        self.divided = divided
        elements = np.arange(len(lay)) if elements is None else np.asarray(elements)
        # A_e - v for every (point, element): offsets from the element's anchor
        ae = lay.anchor[elements]
        rel = np.where(anchor[:, None] == ae[None, :], 0.0, np.where(ae == AT_C2, -lay.w, lay.w)[None, :]) - offset[:, None]
        owner = np.repeat(np.arange(len(lay)), lay.n_basis) if collocated else np.full(N, -1)
        own = owner[:, None] == elements[None, :]
        self._fixed = {key: np.zeros((N, nb)) for key in self.names + (tuple(n + "/x" for n in self.names) if divided else ())}
        # v - v_ref of every point, from the offsets (the anchors c^2 and 1 are w = 1 - c^2 apart): the rows of the upper
        # integral differenced against the reference point's (``AbelMatrices.change``), on the collocation points
        # (formed without cancellation only below CANCELLATION_FREE_BELOW, where ``_rise`` is set; above, by subtraction)
        self._rise = None
        if collocated and "upper" in self.names:
            if lay.c < CANCELLATION_FREE_BELOW:
                ref_anchor = anchor[REFERENCE]
                shift = np.where(anchor == ref_anchor, 0.0, lay.w if ref_anchor == AT_C2 else -lay.w)
                self._rise = shift + (offset - offset[REFERENCE])
            self._fixed[CHANGE] = np.full((N, nb), np.nan)
        self._fixed["integral"] = np.zeros(nb)
        if divided:
            self._fixed["integral/x"] = np.zeros(nb)
        is_plain = lay.kind[elements] == PLAIN
        if np.any(is_plain):
            self._plain(elements[is_plain], rel[:, is_plain], own[:, is_plain], collocated)
        self._terms: dict[int, dict[str, list[_Term]]] = {}
        for k in np.flatnonzero(~is_plain):
            e = int(elements[k])
            self._terms[e] = self._singular(e, rel[:, k], own[:, k], owner)
            if lay.kind[e] != EDGE:  # the regular family of the elements at c does not depend on alpha
                cols = slice(int(lay.starts[e]), int(lay.starts[e]) + int(lay.degree[e]) + 1)
                for key, terms in self._terms[e].items():
                    target = self._fixed[key]
                    for t in terms:
                        block = t.legendre_block(int(lay.degree[e]))
                        if t.rows is None:
                            target[cols] = block[0]
                        else:
                            target[t.rows, cols] = block
        if CHANGE in self._fixed:  # the rest of the change by difference (all of it from CANCELLATION_FREE_BELOW up)
            upper, change = self._fixed["upper"], self._fixed[CHANGE]
            np.subtract(upper, upper[REFERENCE], out=change, where=np.isnan(change))
        self._nodes = _node_sets(lay, self._terms)
        self._logs = {family: chart_logarithm(flat) for family, (flat, _) in self._nodes.items()}

    def _plain(self, E: np.ndarray, rel: np.ndarray, own: np.ndarray, collocated: bool) -> None:
        """All plain elements E at once (they share degree and rules): rel, own are (points, elements)."""
        lay = self.layout
        deg = int(lay.degree[E[0]])
        m = deg + 1
        nq = m + EXTRA_NODES
        N = self.x.size
        L = lay.hi[E] - lay.lo[E]
        lo = lay.lo[E]
        A = np.where(lay.anchor[E] == AT_C2, lay.c2, 1.0)
        xq, wq = gauss01(nq)
        Pq = plain_legendre(nq, deg)
        inv_x = 1.0 / np.sqrt(A[:, None] + lo[:, None] + L[:, None] * xq[None, :])  # (E, nq), the slip columns' 1/x
        d_lo, d_hi = rel + lo[None, :], rel + (lo + L)[None, :]
        inside = ~own & (d_lo <= 0.0) & (d_hi >= 0.0)
        cols = (lay.starts[E][:, None] + np.arange(m)[None, :]).ravel()
        slip = (lay.zone[E] == SLIP) & self.divided  # the elements whose integrals of phi/sqrt(u) are formed
        slip_k = np.flatnonzero(slip)
        slip_index = np.cumsum(slip) - 1  # k -> its place among slip_k
        slip_cols = (lay.starts[E[slip_k]][:, None] + np.arange(m)[None, :]).ravel()
        rL = np.sqrt(L)
        for name in self.names:
            upper = name == "upper"
            M = np.zeros((N, E.size, m))
            Mx = np.zeros((N, slip_k.size, m))
            if collocated:  # own points: the same rule on every element, scaled by sqrt(L)
                S, W, P = plain_self_rule(m, nq, upper, deg)
                rows = (lay.starts[E][:, None] + np.arange(m)[None, :]).ravel()
                M[rows, np.repeat(np.arange(E.size), m)] = (rL[:, None, None] * _weighted_sum(W, P)[None]).reshape(-1, m)
                if slip_k.size:
                    u_own = (A + lo)[slip_k, None, None] + L[slip_k, None, None] * S[None]  # (slip elements, m, nq)
                    Wx = (W[None] / np.sqrt(u_own))[:, :, None, :]
                    Mx[slip_cols, np.repeat(np.arange(slip_k.size), m)] = (
                        rL[slip_k, None, None] * np.matmul(Wx, P[None])[:, :, 0, :]).reshape(-1, m)
            side = ~own & ~inside & ((d_lo > 0.0) if upper else (d_hi < 0.0))
            distance = d_lo if upper else -d_hi
            near = side & (distance < near_plain(deg) * L[None, :])
            i, k = np.nonzero(inside | near)
            if i.size:
                in_pair = inside[i, k]
                S = np.empty((i.size, nq))
                W = np.empty((i.size, nq))
                if np.any(in_pair):
                    Si, Wi = plain_inside_rule(np.clip(-d_lo[i, k][in_pair] / L[k][in_pair], 0.0, 1.0), nq, upper)
                    S[in_pair], W[in_pair] = Si, Wi * rL[k][in_pair][:, None]
                if np.any(~in_pair):
                    S[~in_pair], W[~in_pair] = plain_outside_rule(L[k][~in_pair], d_lo[i, k][~in_pair],
                                                                  d_hi[i, k][~in_pair], upper, nq)
                P = shifted_legendre(deg, S)
                M[i, k] = _weighted_sum(W, P)
                on = slip[k]
                if np.any(on):
                    ks = k[on]
                    Mx[i[on], slip_index[ks]] = _weighted_sum(W[on] / np.sqrt((A + lo)[ks][:, None] + L[ks][:, None] * S[on]),
                                                              P[on])
            smooth = side & ~near
            i, k = np.nonzero(smooth)
            if i.size:  # the kernel is smooth on the element: one Gauss rule
                Kf = (0.5 * L[k][:, None] * wq[None, :]) / np.sqrt(np.abs(d_lo[i, k][:, None] + L[k][:, None] * xq[None, :]))
                M[i, k] = Kf @ Pq
                on = slip[k]
                if np.any(on):
                    Mx[i[on], slip_index[k[on]]] = (Kf[on] * inv_x[k[on]]) @ Pq
            if upper and self._rise is not None:
                self._fixed[CHANGE][:, cols] = self._plain_change(smooth, d_lo, L, xq, wq, Pq).reshape(N, -1)
            self._fixed[name][:, cols] = M.reshape(N, -1)
            if slip_k.size:
                self._fixed[name + "/x"][:, slip_cols] = Mx.reshape(N, -1)
        self._fixed["integral"][cols] = (L[:, None] * (wq @ Pq)[None, :]).ravel()
        if slip_k.size:
            self._fixed["integral/x"][slip_cols] = (L[slip_k, None] * ((wq[None, :] * inv_x[slip_k]) @ Pq)).ravel()

    def _plain_change(self, smooth: np.ndarray, d_lo: np.ndarray, L: np.ndarray, xq: np.ndarray, wq: np.ndarray,
                      Pq: np.ndarray) -> np.ndarray:
        """``AbelMatrices.change`` on the plain elements, (points, elements, degree + 1): where a point and the reference
        both see an element through the one Gauss rule (``smooth``), 1/sqrt(u - v) - 1/sqrt(u - v_ref) =
        (v - v_ref) / (sqrt(u - v) sqrt(u - v_ref) (sqrt(u - v) + sqrt(u - v_ref))) on its nodes; nan elsewhere."""
        out = np.full(smooth.shape + (Pq.shape[1],), np.nan)
        seen = smooth[REFERENCE]
        i, k = np.nonzero(smooth & seen[None, :])
        keep = i != REFERENCE
        i, k = i[keep], k[keep]
        if i.size:
            step = L[k][:, None] * xq[None, :]
            a, a_ref = np.sqrt(d_lo[i, k][:, None] + step), np.sqrt(d_lo[REFERENCE, k][:, None] + step)
            out[i, k] = ((0.5 * L[k][:, None] * wq[None, :]) * self._rise[i][:, None] / (a * a_ref * (a + a_ref))) @ Pq
        return out

    def _singular(self, e: int, rel: np.ndarray, own: np.ndarray, owner: np.ndarray) -> dict[str, list[_Term]]:
        """The quadrature terms of singular element e for every point (``owner``: each point's element, -1 off the
        collocation points), per name. The near rule at the points of the partner end across c^2 is
        ``partner_near_rule``'s."""
        lay = self.layout
        L, m, deg = lay.length(e), int(lay.n_basis[e]), int(lay.degree[e])
        slip = lay.zone[e] == SLIP and self.divided  # the integrals of phi/sqrt(u) too
        A = lay.anchor_value(e)
        sign = 1.0 if lay.kind[e] == SLIP_END else -1.0  # u = A + sign L s^2
        rL = math.sqrt(L)
        d = -sign * rel / L  # s_v^2 of every point
        inside = ~own & (d > 0.0) & (d < 1.0)
        inside_any = bool(inside.any())
        So, Wo, one_minus, Po = sqrt_outside_nodes(deg)
        Sc, one_minus_c = chebyshev_points01()
        projector = outside_projector(deg)
        if slip:
            u_o = A + sign * L * So * So
            u_c = A + sign * L * Sc * Sc
        out: dict[str, list[_Term]] = {}
        own_rows = np.flatnonzero(own)
        partner_rows = None  # the partner end's points that ``partner_near_rule`` covers
        if lay.kind[e] in (STICK_END, SLIP_END):
            partner = e + 1 if lay.kind[e] == STICK_END else e - 1
            if lay.length(partner) == L:
                rows_of_partner = np.flatnonzero(owner == partner)
                if rows_of_partner.size == lay.n_basis[partner]:
                    take = partner_near_rule(int(lay.kind[partner]), int(lay.n_basis[partner]), deg)[0]
                    partner_rows = rows_of_partner[take]
        for away in (True, False):
            upper = away == (sign > 0.0)  # slip end: u > v is s > s_v
            name = "upper" if upper else "lower"
            if name not in self.names:
                continue
            terms = []
            if own_rows.size:
                S, W, P = sqrt_self_rule(int(lay.kind[e]), m, away, deg)
                regular = None if lay.kind[e] == EDGE else rL * self_legendre_block(int(lay.kind[e]), m, away, deg)
                terms.append(_Term(own_rows, rL * W, S, P, False, regular=regular))
            if inside_any:
                S, W = sqrt_inside_rule(np.sqrt(d[inside]), away, deg)
                terms.append(_Term(np.flatnonzero(inside), rL * W, S, shifted_legendre(deg, S), False))
            side = ~own & ~inside & ((d <= 0.0) if away else (d >= 1.0))
            near = side & ((-d < NEAR_OUTSIDE) if away else (d - 1.0 < NEAR_OUTSIDE))
            far = side & ((d <= FAR_BEFORE) if away else (d >= FAR_BEYOND))
            if np.count_nonzero(far) < INTERPOLATION_POINTS:  # a few points: the direct sum costs less than the projection
                far[:] = False
            changes = []
            rows = np.flatnonzero(side & ~near & ~far)
            if rows.size:
                terms.append(_Term(rows, rL * Wo[None, :] * sqrt_outside_kernel(So, one_minus, d[rows], away), So, Po, True))
                changes.append((rows, So, one_minus, Wo, None))
            rows = np.flatnonzero(far)
            if rows.size:
                terms.append(_Term(rows, rL * sqrt_outside_kernel(Sc, one_minus_c, d[rows], away), So, Po, True, projector))
                changes.append((rows, Sc, one_minus_c, None, projector))
            if upper and self._rise is not None:  # ``AbelMatrices.change`` where the reference is in the same group
                for rows, nodes, one_less, weights, project in changes:
                    if REFERENCE in rows:
                        rows = rows[rows != REFERENCE]
                        K = sqrt_outside_kernel_change(nodes, one_less, d[rows], float(d[REFERENCE]),
                                                       (sign / L) * self._rise[rows], away)
                        W = rL * (K if weights is None else weights[None, :] * K)
                        out.setdefault(CHANGE, []).append(_Term(rows, W, So, Po, True, project))
            if near.any():
                rows = np.flatnonzero(near)
                if partner_rows is not None and away and np.array_equal(rows, partner_rows):
                    _, S, W, P, block = partner_near_rule(int(lay.kind[partner]), int(lay.n_basis[partner]), deg)
                    terms.append(_Term(rows, rL * W, S, P, False, regular=rL * block))
                else:
                    S, W = sqrt_near_outside_rule(d[near], deg)
                    terms.append(_Term(rows, rL * W, S, shifted_legendre(deg, S), False))
            out[name] = terms
            if slip:
                out[name + "/x"] = [_Term(t.rows, t.W / np.sqrt(_nodes_u(t, u_o, u_c, A, sign * L)), t.S, t.P, t.shared,
                                          t.projector) for t in terms]
        wi = 2.0 * L * So * Wo  # du = 2 L s ds
        out["integral"] = [_Term(None, wi[None, :], So, Po, True)]
        if slip:
            out["integral/x"] = [_Term(None, (wi / np.sqrt(u_o))[None, :], So, Po, True)]
        return out

    @property
    def fixed(self) -> AbelMatrices:
        """The integrals that do not depend on alpha, with the columns that do (``varying(alpha)``) 0: read-only views
        of the arrays every alpha shares. (``varying(alpha, displacement=True)`` also replaces the regular family of the
        elements at c, which here is the stresses'.)"""
        return _abel_matrices({key: _read_only(value) for key, value in self._fixed.items()}, self.x.size)

    def varying(self, alpha: float, displacement: bool = False) -> VaryingColumns:
        """The columns that depend on basis exponent alpha (``displacement``: the families of u*, ``family_factors``):
        the singular families of the elements at c (with displacement their whole columns) and the edge element's."""
        lay = self.layout
        ranges = {}
        for e in self._terms:
            start, head = int(lay.starts[e]), int(lay.degree[e]) + 1
            only_singular = int(lay.kind[e]) != EDGE and not displacement  # the regular family is in the fixed part
            ranges[e] = (start + head if only_singular else start, int(lay.starts[e + 1]), only_singular)
        columns = np.concatenate([np.arange(lo, hi) for lo, hi, _ in ranges.values()]) if ranges else np.zeros(0, int)
        k = columns.size
        out = {key: np.zeros((self.x.size, k) if value.ndim == 2 else k) for key, value in self._fixed.items()}
        # the family factors at every node of a family (the two ends share theirs), one call each
        values = {family: family_factors(family, flat, alpha, displacement, self._logs[family])
                  for family, (flat, _) in self._nodes.items()}
        bases: dict = {}  # tabulated and projected bases per (family, node set, columns)
        first = 0
        for e, blocks in self._terms.items():
            kind, sdeg = int(lay.kind[e]), int(lay.singular_degree[e])
            family = _family(kind)
            flat_regular, flat_singular = values[family]
            where = self._nodes[family][1]
            lo, hi, only_singular = ranges[e]
            cols = slice(first, first + hi - lo)
            first += hi - lo

            def block_of(t: _Term) -> np.ndarray:
                part = where[id(t.S)]
                singular = flat_singular[part].reshape(t.S.shape)
                regular = None if flat_regular is None else flat_regular[part].reshape(t.S.shape)
                if t.shared:
                    key_basis = (family, id(t.S), sdeg, only_singular)
                    if key_basis not in bases:
                        basis = singular[:, None] * t.P[:, : sdeg + 1]
                        if not only_singular:
                            basis = np.concatenate([t.P if regular is None else regular[:, None] * t.P, basis], axis=1)
                        bases[key_basis] = basis
                    basis = bases[key_basis]
                    if t.projector is None:
                        return t.W @ basis
                    key_projected = key_basis + (id(t.projector),)
                    if key_projected not in bases:
                        bases[key_projected] = t.projector @ basis
                    return t.W @ bases[key_projected]
                block = _weighted_sum(t.W * singular, t.P[..., : sdeg + 1])
                if only_singular:
                    return block
                return np.concatenate([_weighted_sum(t.W if regular is None else t.W * regular, t.P), block], axis=1)

            for key, terms in blocks.items():
                if key == CHANGE:
                    continue
                target = out[key]
                for t in terms:
                    if t.rows is None:
                        target[cols] = block_of(t)[0]
                    else:
                        target[t.rows, cols] = block_of(t)
            if CHANGE in out:  # by difference, then without cancellation where the reference shares a rule
                upper = out["upper"][:, cols]
                out[CHANGE][:, cols] = upper - upper[REFERENCE]
                for t in blocks.get(CHANGE, ()):
                    out[CHANGE][t.rows, cols] = block_of(t)
        columns.setflags(write=False)
        return VaryingColumns(columns, _abel_matrices(out, self.x.size))

    def matrices(self, alpha: float, displacement: bool = False) -> AbelMatrices:
        """The Abel integrals at basis exponent alpha (``displacement``: the families of u*): the fixed ones with the
        ``varying`` columns set."""
        varying = self.varying(alpha, displacement)
        out = {key: value.copy() for key, value in self._fixed.items()}
        for key, value in out.items():
            value[..., varying.columns] = varying.matrices.of(key)
        return _abel_matrices(out, self.x.size)


@dataclass(frozen=True, slots=True, eq=False)
class VaryingColumns:
    """The columns of the Abel integrals that depend on the basis exponent (``AbelOperators.varying``): their basis
    indices (increasing: the stick zone's first) and their integrals, an ``AbelMatrices`` of those columns only."""

    columns: np.ndarray
    matrices: AbelMatrices


def _read_only(a: np.ndarray) -> np.ndarray:
    view = a.view()
    view.setflags(write=False)
    return view


def _abel_matrices(out: dict[str, np.ndarray], n_points: int) -> AbelMatrices:
    """``AbelMatrices`` of the arrays by name; empty where a name was not formed."""
    empty = np.zeros((n_points, 0))
    return AbelMatrices(out.get("upper", empty), out.get("lower", empty), out.get("upper/x", empty),
                        out.get("lower/x", empty), out["integral"], out.get("integral/x", np.zeros(0)),
                        out.get(CHANGE, empty))


def _family(kind: int) -> int:
    """The kind whose families an element of this kind carries: the stick and slip ends share h_beta."""
    return EDGE if kind == EDGE else SLIP_END


def _node_sets(lay: Layout, terms: dict[int, dict[str, list[_Term]]]) -> dict[int, tuple[np.ndarray, dict]]:
    """Every distinct node set of the singular elements' terms, per family (``_family``): all nodes in one flat
    array, and the slice of each node set (by identity) in it, so that ``matrices`` forms each family's factors
    in one call."""
    out: dict[int, tuple[list, dict]] = {}
    for e, blocks in terms.items():
        chunks, where = out.setdefault(_family(int(lay.kind[e])), ([], {}))
        for t in (t for ts in blocks.values() for t in ts):
            if id(t.S) not in where:
                start = where[id(chunks[-1])].stop if chunks else 0
                where[id(t.S)] = slice(start, start + t.S.size)
                chunks.append(t.S)
    return {family: (np.concatenate([c.ravel() for c in chunks]), where) for family, (chunks, where) in out.items()}


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
    end_row: np.ndarray     # (ns,): a, the regular part of a stick field at c-: all of P(c-) (module docstring)
    end_singular: np.ndarray  # (ns,): b, the singular family's coefficient at c-: Q(c-) = a_Q + h_beta(0) b_Q
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

    def derivative_times(self, theta: float, z: np.ndarray) -> np.ndarray:
        """(d D / d theta) z, without forming the matrix."""
        slip = z[2 * self.n_stick:]
        return -math.sin(theta) * (self.normal @ slip) + (normal_factor(theta) / self.gamma) * (self.shear @ slip)

    def functional(self, theta: float) -> np.ndarray:
        """l with l . z = mu cos(theta) phi(c-) = sin(theta)/gamma p(c-) - cos(theta) q(c-) (module docstring)."""
        ns, c = self.n_stick, self.layout.c
        out = np.zeros(self.rhs.size)
        out[:ns] = _shear_factor(theta, self.gamma) * self.end_row
        weight = _singular_weight(theta, self.alpha)[0]
        out[ns: 2 * ns] = c * (weight * self.end_singular - normal_factor(theta) * self.end_row)
        return out

    def functional_derivative(self, theta: float) -> np.ndarray:
        ns, c = self.n_stick, self.layout.c
        out = np.zeros(self.rhs.size)
        out[:ns] = (normal_factor(theta) / self.gamma) * self.end_row
        slope = _singular_weight(theta, self.alpha)[1]
        out[ns: 2 * ns] = c * (slope * self.end_singular + math.sin(theta) * self.end_row)
        return out


def normal_factor(theta: float) -> float:
    """cos(theta), exactly 0 at theta = pi/2 (mu = inf: no pressure on the slip annulus)."""
    return 0.0 if theta >= 0.5 * math.pi else math.cos(theta)


def _shear_factor(theta: float, gamma: float) -> float:
    """sin(theta)/gamma = mu cos(theta)."""
    return math.sin(theta) / gamma


def _singular_weight(theta: float, alpha: float) -> tuple[float, float]:
    """cos(theta)/beta, beta = 1 - 2 alpha (-cos(theta) h_beta(0): the singular family's weight in cos(theta) q(c-)),
    and its theta-derivative -sin(theta)/beta, at basis exponent alpha. Both 0 for beta > 1/2 (h_beta(0) = 0); at
    beta = 0 (mu = inf) the weight's limit pi/2 on the diagonal theta = pi alpha, and slope 0 (theta stays at pi/2)."""
    beta = 1.0 - 2.0 * alpha
    if beta > 0.5:
        return 0.0, 0.0
    if beta == 0.0:
        return 0.5 * math.pi, 0.0
    return normal_factor(theta) / beta, -math.sin(theta) / beta


def stick_end_rows(lay: Layout) -> tuple[np.ndarray, np.ndarray]:
    """(a, b) over the stick unknowns: a stick field's regular part at c- and its singular family's coefficient there
    (``CollocationSystem.end_row``, ``end_singular``): the stick end's Legendre values at s = 0, P_k(-1) = (-1)^k."""
    e = lay.stick_end
    deg, sdeg, first = int(lay.degree[e]), int(lay.singular_degree[e]), int(lay.starts[e])
    at_c = shifted_legendre(deg, np.zeros(1))[0]
    regular, singular = np.zeros(lay.n_stick), np.zeros(lay.n_stick)
    regular[first: first + deg + 1] = at_c
    singular[first + deg + 1: int(lay.starts[e + 1])] = at_c[: sdeg + 1]
    return regular, singular


def collocation_system(ops: AbelOperators, gamma: float, alpha: float) -> CollocationSystem:
    """Assemble [S75] (2.2a) at every point and (2.2b) at the stick points for basis exponent alpha: the blocks of the
    integrals that do not depend on alpha (``AbelOperators.fixed``, read where they lie), then those of the columns
    that do (``AbelOperators.varying``) put in their places. Every column of a block depends only on the same basis
    column, so this is the assembly of the whole integrals (``AbelOperators.matrices``) to the last bit (checked over
    1485 systems: levels 0-4, c from 1e-5 to 1 - 1e-9, alpha from 0 to 1/2), without their copy: measured at level 2,
    the copy took 0.34 ms at c = 1/2 (136 points), and without it the page faults of a full solution for given c (the
    heap's top, freed and given back between solves, faulted in again) fell from 185 ... 290 to 0 at c = 1/2, 0.9 and
    from 925 to 261 at c = 0.1; the full solution's median over the benchmark's six cases from 4.75 to 4.39 ms (six
    alternating pairs of processes)."""
    lay = ops.layout
    x = ops.x
    ns = lay.n_stick
    N = x.size
    nl = N - ns
    n = 2 * ns + nl
    ref = REFERENCE
    fixed = ops.fixed
    stick, normal, shear, us_stick_p, us_normal, us_shear = _assembled(fixed, x, ns, gamma, ns)
    varying = ops.varying(alpha)
    width = int(np.count_nonzero(varying.columns < ns))
    cs, cl = varying.columns[:width], varying.columns[width:] - ns
    v_stick, v_normal, v_shear, v_us_stick, v_us_normal, v_us_shear = _assembled(varying.matrices, x, ns, gamma, width)
    stick[:, cs], stick[:, ns + cs] = v_stick[:, :width], v_stick[:, width:]
    normal[:, cl], shear[:, cl] = v_normal, v_shear
    us_stick = np.zeros((nl, 2 * ns))
    us_stick[:, :ns] = us_stick_p  # (2.2b) at slip points: the stick q is below them
    us_stick[:, cs], us_normal[:, cl], us_shear[:, cl] = v_us_stick, v_us_normal, v_us_shear
    integral = fixed.integral.copy()
    integral[varying.columns] = varying.matrices.integral
    rhs = np.zeros(n)
    rhs[ref] = 1.0
    e = lay.stick_end
    deg = int(lay.degree[e])
    singular_slots = np.arange(int(lay.starts[e]) + deg + 1, int(lay.starts[e + 1]))
    if pins_stick_pressure(alpha):
        # P has no singular family on the stick end (``numeric.core.charts``): for beta <= 1/2 its coefficients there are
        # pinned to 0, in the rows of (2.2a) at sdeg + 1 of the stick end's points spread over it (``pinned_rows``);
        # above, h_beta(0) = 0 and the free family does no harm
        rows = int(lay.starts[e]) + pinned_rows(int(lay.n_basis[e]), singular_slots.size)
        pin_to_zero(stick, singular_slots, rows, (normal, shear, rhs), (us_stick,))
    regular, singular = stick_end_rows(lay)
    return CollocationSystem(lay, gamma, alpha, stick, normal, shear, rhs, regular, singular, integral, x, us_stick,
                             us_normal, us_shear)


def _assembled(M: AbelMatrices, x: np.ndarray, ns: int, gamma: float, width: int
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``collocation_system``'s blocks from the Abel integrals M of some basis columns, the first ``width`` of them on
    the stick zone and the rest on the slip zone: (stick: p's columns then q's, normal, shear, and u* at the slip
    points from p on the stick, from the slip columns' normal and shear parts); ``ns`` stick points among x."""
    N = x.size
    n = N + ns
    S, L = slice(None, width), slice(width, None)
    xs, xl = x[:ns], x[ns:]
    # (2.2a) at the reference point, and at every other point less its value at the reference (``REFERENCE``): w* = 1
    # there and 0 here. The upper integrals' differences are formed without cancellation (``AbelMatrices.change``):
    # far from an element the kernel 1/sqrt(t^2 - x^2) barely changes from point to point, so the rows themselves hold
    # the solution only through differences of their rounding (the componentwise condition of theta grew like 1/c,
    # 2e4 at c = 1e-3 at nu = 0.45; differenced, 35, flat in c), and the integrals int q, the same in every row, drop
    # out.
    ref = REFERENCE
    lower, lower_x = x[:, None] * M.lower[:, S], x[:, None] * M.lower_x[:, L]
    stick = np.empty((n, 2 * width))
    stick[:N, :width] = M.change[:, S]                                           # (2.2a): int_x^1 t p
    stick[ref, :width] = M.upper[ref, S]
    stick[:N, width:] = gamma * (lower - lower[ref])                             # -gamma {int q - x int_0^x q}
    stick[ref, width:] = -gamma * (0.5 * M.integral[S] - lower[ref])
    stick[N:, width:] = xs[:, None] * M.upper[:ns, S]                             # (2.2b): x int_x^1 q
    stick[N:, :width] = -gamma * M.lower[:ns, S]                                  # - gamma int_0^x t p
    normal = np.zeros((n, M.lower.shape[1] - width))
    normal[:N] = M.change[:, L]
    normal[ref] = M.upper[ref, L]
    shear = np.empty((n, normal.shape[1]))
    shear[:N] = gamma * (lower_x - lower_x[ref])
    shear[ref] = -gamma * (0.5 * M.integral_x[L] - lower_x[ref])
    shear[N:] = xs[:, None] * M.upper_x[:ns, L]
    return stick, normal, shear, -gamma * M.lower[ns:, S], -gamma * M.lower[ns:, L], xl[:, None] * M.upper_x[ns:, L]
