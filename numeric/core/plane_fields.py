"""Stresses and slip of a strip-punch solution on the plane singular basis.

p and q are evaluated from the basis, so their behaviour at x = c and x = 1 is exact: there is no
interpolation between nodes and no loss at x = c itself or at 1 - x = 1e-5. The generic mode is left
out: its amplitude is the eigen residual (below 1e-12 at a converged solution) and its function is
singular at c.

The slip: with u = u_x G / ((1 - nu) P) (u_x the tangential surface displacement, P the load per
unit length), du/dx = H q - gamma p (the tangential surface relation, ``asymptotics.plane``), which
vanishes on the stick zone, so u(x) = int_c^x (H q - gamma p) dt on the slip zone (the strain interpolated at the
slip elements' collocation points, where the system holds H q: in their bases before the edge element, and on it as its
singular part, known from the coefficients, and a polynomial: ``PlaneField.strain``); the integrand
behaves like (t - c)^beta (and its logarithmic limit) at c and (1 - t)^(alpha - 1/2) at 1, and is integrated
by a composite Gauss rule graded toward both ends of [c, x] (pieces of ratio 1/2) whose innermost piece is
taken in s = h v^8, where those end behaviours become v^7 times a smooth function of v.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from numeric.core.charts import h_beta
from numeric.core.plane_cauchy import family_values, legendre01
from numeric.core.plane_charts import AT_ONE, EDGE, PointSet, element_families, locate
from numeric.core.plane_eigenvalue import PlaneEigensolution
from numeric.core.plane_operators import PlaneOperators, normal_factor
from numeric.core.quadrature import christoffel_gauss01, gauss_legendre

__all__ = ["PlaneField", "FieldCombination", "SLIP_PIECES", "SLIP_NODES", "INNER_POWER", "INNER_NODES", "NODE_CLEARANCE",
           "CLEARANCE_FRACTION", "graded_both_ends",
           "graded_toward", "pieces_toward", "weighted_tail_integrals", "Weight"]

#: A weight of the tail integrals: weight(t, 1 - t), the second argument exact next to the edge.
Weight = Callable[[np.ndarray, np.ndarray], np.ndarray]

SLIP_PIECES = 50
"""Graded pieces toward each end of [0, 1] in ``graded_both_ends`` (down to 2^-50 of its length), and the most
``pieces_toward`` gives."""
SLIP_NODES = 12
"""Gauss nodes per piece (the pieces see the end singularities at >= 3 half-lengths: 5.83^-24)."""
INNER_POWER = 16
"""The innermost piece [0, h] of a graded half is integrated in v, s = h v^INNER_POWER: an end behaviour s^lam times a
smooth function (lam >= -1/2: the strain's (1 - t)^(alpha - 1/2) at the edge, (t - c)^beta at c; also its logarithms)
becomes v^(16 lam + 15) times a smooth function of v, at worst v^7."""
INNER_NODES = 40
"""Gauss nodes of the innermost piece in v: v^7 to 40^-16 (a Gauss error n^-(2 lam' + 2) for v^lam'); a pole a distance
d >= h beyond s = 0 lies at v = (d/h)^(1/16) e^(i pi/16), rho >= 1.85 (1.85^-80 = 4e-22), the far end of the rule (s = 1,
h <= 1/4) at v >= 4^(1/16), rho >= 1.81 (2.5e-21). (With v^8 and 24 nodes (1 - s)^-0.4 came out 9e-14 off.) The
weights are ``christoffel_gauss01``'s: with ``leggauss``'s the rule integrated 1 to 1.2e-14."""
NODE_CLEARANCE = 1e-13
"""Least distance of a slip-integral node from an element end inside the slip zone (see ``PlaneField.slip``), at most
``CLEARANCE_FRACTION`` of the slip zone 1 - c."""
CLEARANCE_FRACTION = 1e-10


class PlaneField:
    """p, q, the slip u and the load of a ``PlaneEigensolution`` (theta = atan(mu gamma))."""

    def __init__(self, solution: PlaneEigensolution) -> None:
        self.solution = solution
        sys = solution.system
        self.layout = sys.layout
        self.gamma = sys.gamma
        self.theta = solution.theta
        self.alpha = sys.alpha
        self.c = self.layout.c
        self.gap = self.layout.gap
        self.n_unknowns = solution.coefficients.size
        ns = sys.n_stick
        z = solution.coefficients
        self.residual = float(z[-1])  # the generic mode's amplitude
        n = int(solution.operators.starts[-1])
        self._p = np.zeros(n)  # coefficients of p and q over the whole basis (layout order)
        self._q = np.zeros(n)
        self._p[sys.stick_columns] = z[:ns]
        self._q[sys.stick_columns] = z[ns:2 * ns]
        R = z[2 * ns:-1]
        self._p[sys.slip_columns] = normal_factor(self.theta) * R
        self._q[sys.slip_columns] = (math.sin(self.theta) / self.gamma) * R
        self._starts = solution.operators.starts
        self._last_points: tuple | None = None  # (points, (p, q)) of the last ``pressure_shear``

    @property
    def mu(self) -> float:
        return math.inf if self.theta >= 0.5 * math.pi else math.tan(self.theta) / self.gamma

    @cached_property
    def load(self) -> float:
        """int_{-1}^{1} p dx (1 by the normalisation row, to rounding)."""
        return float(2.0 * self.solution.system.integrals @ self._p)

    def _basis_values(self, x: np.ndarray, side: np.ndarray | None = None) -> np.ndarray:
        """Every basis function at points 0 <= x <= 1 (rows), 0 off its element."""
        return self._basis_at(locate(self.layout, x, side))

    def _basis_at(self, pts: PointSet) -> np.ndarray:
        """Every basis function at located points (rows), 0 off its element."""
        lay = self.layout
        out = np.zeros((pts.size, int(self._starts[-1])))
        legendre = legendre01(lay.degree, pts.s)  # every family's polynomials, at once
        for e in np.unique(pts.owner):
            mine = pts.owner == e
            col = int(self._starts[e])
            for fam in element_families(lay, int(e), self.alpha):
                with np.errstate(divide="ignore", invalid="ignore"):  # the edge weight at x = 1 (set by the caller)
                    block = family_values(fam, pts.s[mine], legendre[mine])
                out[np.ix_(mine, np.arange(col, col + fam.degree + 1))] = block
                col += fam.degree + 1
        return out

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p(x) and q(x) for -1 <= x <= 1 (p even, q odd; x = c is the stick side's value, continuous there). The
        last points' values are kept: a caller asking for p and then q at the same x (as the solution's ``pressure``
        and ``shear`` do) evaluates the basis once."""
        x = np.asarray(x, dtype=float)
        key = (x.shape, x.tobytes())
        if self._last_points is not None and self._last_points[0] == key:
            p, q = self._last_points[1]
            return p.copy(), q.copy()
        p, q = self._pressure_shear(x)
        self._last_points = (key, (p.copy(), q.copy()))
        return p, q

    def _pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ax = np.abs(x).ravel()
        B = self._basis_values(ax)
        with np.errstate(invalid="ignore"):
            p = B @ self._p
            q = B @ self._q
        edge = ax == 1.0
        if np.any(edge):  # (1 - x)^(alpha - 1/2): infinite for mu < inf; at mu = inf p = 0 and q is finite
            p[edge] = 0.0 if self.theta >= 0.5 * math.pi else math.inf
            if self.theta < 0.5 * math.pi:
                q[edge] = math.inf
        return p.reshape(x.shape), (np.sign(x).ravel() * q).reshape(x.shape)

    @cached_property
    def _strain_at_slip_points(self) -> tuple[PointSet, np.ndarray]:
        """The slip elements' collocation points and H q - gamma p there, H q from the system
        (``PlaneCollocationSystem.slip_odd``)."""
        ops = self.solution.operators
        points = _subset(ops.points, ops.slip_rows)
        return points, self.solution.system.slip_odd @ self._q - self.gamma * (self._basis_at(points) @ self._p)

    @cached_property
    def _strain_coefficients(self) -> np.ndarray:
        """The strain H q - gamma p on the slip elements before the edge one in their own bases (layout columns; 0
        elsewhere), interpolated at their collocation points (``_strain_at_slip_points``). There the strain has the
        local behaviour of p and q (smooth, and |x - c|^(1/2 - alpha) at c), which the bases carry: fitted by least
        squares on 40 points of each such element, its transforms left a residual of at most 1.8e-14 of the largest
        strain (nu = -1/2 ... 0.45, c = 0.3 ... 0.9). Measured: the interpolant within 1.1e-13 of max(1, |strain|) of
        the transforms at interior points (7 (nu, c), nu = -0.9 ... 0.499); within 1e-6 of an element end the
        transforms of the discrete solution carry its small jumps there times a logarithm (up to 3e-9 at nu = 0,
        c = 0.99), which the interpolant does not, and the slip, their integral, is the same to 5e-15 of max(1, |u|)
        over 42 (nu, c) from c = 1e-4 to 0.9999 (the cylinder's 3e-15), at a quarter of the time (one point at
        c = 1/2: 5.8 ms against 1.8 ms)."""
        points, strain = self._strain_at_slip_points
        B = self._basis_at(points)
        out = np.zeros(self._p.size)
        for e in np.unique(points.owner):
            if self.layout.kind[e] == EDGE:
                continue
            mine = np.flatnonzero(points.owner == e)
            cols = slice(int(self._starts[e]), int(self._starts[e + 1]))
            out[cols] = np.linalg.solve(B[mine, cols], strain[mine])
        return out

    def _edge_singular_strain(self, pts: PointSet, legendre: np.ndarray) -> np.ndarray:
        """The part of the strain on the edge element that is not a polynomial in its chart s (points on it).

        On the edge element q = s^lam Q(s), lam = alpha - 1/2, Q a polynomial (the element's coefficients), and
        PV int_0^1 s^lam P_j ds/(s - y) = -pi cot(pi lam) y^lam P_j(y) + a function analytic on [0, 1)
        (``numeric.core.plane_cauchy.power_cauchy``: V_lam, and the divided differences of P_j): so H q has
        -sigma cot(pi lam) y^lam Q(y) (sigma the chart's orientation) beside an analytic part. With
        y^lam = 1 + lam h_lam(y) the polynomial -sigma cot(pi lam) Q goes to the analytic part, and what is left,
        -sigma lam cot(pi lam) h_lam(y) Q(y), stays finite as lam -> 0 (mu -> inf: log y Q / pi). With -gamma p
        (s^lam times a polynomial) it is this part. ``legendre``: ``legendre01`` of the layout's degree at the points."""
        lay, e = self.layout, self._edge
        lam = self.alpha - 0.5
        lam_cot = 1.0 / math.pi if lam == 0.0 else lam / math.tan(math.pi * lam)
        cols = slice(int(self._starts[e]), int(self._starts[e + 1]))
        with np.errstate(divide="ignore", invalid="ignore"):  # at x = 1 itself (the caller's)
            p = family_values(element_families(lay, e, self.alpha)[0], pts.s, legendre) @ self._p[cols]
            return -lay.sigma[e] * lam_cot * h_beta(lam, pts.s) * (legendre @ self._q[cols]) - self.gamma * p

    @cached_property
    def _edge(self) -> int:
        return int(np.flatnonzero(self.layout.kind == EDGE)[0])

    @cached_property
    def _edge_strain_coefficients(self) -> np.ndarray:
        """The strain on the edge element less ``_edge_singular_strain``, analytic there, interpolated in Legendre
        polynomials of its chart (degree + 1 of them) at its collocation points. Measured against the transforms of
        every basis function at 58 points of the edge element (chart 0.001 ... 0.999 and 1 - x down to 1e-8 of its
        length), 14 (nu, c), nu = -0.9 ... 0.499, c = 1e-3 ... 0.9999: within 6.3e-13 of max(1, |strain|) (the strain
        there up to 1.4e4; 5.2e-14 where 1 - c >= 0.01), and at theta = pi/2 (lam = 0, nu = 0, -1/2) 7.9e-14; a fit in
        the edge basis alone was 1e-5 off. The slip from it is the same as from the transforms at every node to
        1.1e-16 of max(1, |u|) (58 cases: 33 (nu, c) given c, 25 (nu, mu) given mu up to 1e8; the cylinder's 4e-17)."""
        points, strain = self._strain_at_slip_points
        mine = np.flatnonzero(points.owner == self._edge)
        edge = _subset(points, mine)
        legendre = legendre01(self.layout.degree, edge.s)
        return np.linalg.solve(legendre, strain[mine] - self._edge_singular_strain(edge, legendre))

    def strain(self, t: np.ndarray, offset_from_one: np.ndarray | None = None) -> np.ndarray:
        """du/dx = H q - gamma p at points c < t < 1 of the slip zone; ``offset_from_one``: t - 1 exactly, if known.

        Interpolated at the slip elements' collocation points: before the edge element in their bases
        (``_strain_coefficients``), on it as its non-polynomial part and a polynomial
        (``_edge_strain_coefficients``)."""
        t = np.asarray(t, dtype=float).ravel()
        lay = self.layout
        pts = locate(lay, t, offset_from_one=offset_from_one)
        edge = lay.kind[pts.owner] == EDGE
        out = np.empty(t.shape)
        if not np.all(edge):
            inner = _subset(pts, ~edge)
            out[~edge] = self._basis_at(inner) @ self._strain_coefficients
        if np.any(edge):
            on_edge = _subset(pts, edge)
            legendre = legendre01(lay.degree, on_edge.s)
            out[edge] = self._edge_singular_strain(on_edge, legendre) + legendre @ self._edge_strain_coefficients
        return out

    def transformed_strain(self, pts: PointSet) -> np.ndarray:
        """H q - gamma p at located points from the transforms of every basis function there (``PlaneOperators`` at
        the points; at element ends single basis functions' transforms are logarithmic, so the points lie off them):
        what ``strain`` interpolates, formed directly (the tests' reference; a few ms a call)."""
        T = PlaneOperators(self.layout, pts).transforms(self.alpha, modes=False)
        return T.odd @ self._q - self.gamma * (T.values @ self._p)

    def slip(self, x: np.ndarray) -> np.ndarray:
        """u(x) = int_c^|x| (H q - gamma p) dt sgn(x) for -1 <= x <= 1 (0 on the stick zone)."""
        x = np.asarray(x, dtype=float)
        ax = np.abs(x).ravel()
        out = np.zeros(ax.shape)
        outer = np.flatnonzero(ax > self.c)
        # the strain is singular at c, at 1 and (through q's odd reflection) at -c: graded toward c as far as -c is
        # near, toward x as far as x is near 1
        length = ax[outer] - self.c
        at_c = pieces_toward(2.0 * self.c / length)
        to_edge = (1.0 - ax[outer]) / length
        at_x = pieces_toward(to_edge)
        # the strain is singular at c itself, but at x only through the edge: where that is at least the innermost
        # piece's length beyond x, the piece is plain Gauss (12 nodes, not 40), and where it is half the interval
        # away or more, one piece covers the whole half at x
        regular = to_edge >= 0.5 ** (at_x + 1.0)
        at_x = np.where(regular & (to_edge >= 0.5), 0, at_x)
        for kc, kx, smooth in set(zip(at_c.tolist(), at_x.tolist(), regular.tolist())):
            group = outer[(at_c == kc) & (at_x == kx) & (regular == smooth)]
            lo = np.full(group.size, self.c)
            out[group] = self._strain_integral(lo, ax[group], ax[group] - 1.0, graded_toward(kc, kx, smooth))
        return (np.sign(x).ravel() * out).reshape(x.shape)

    def tail_strain_integrals(self, lo: np.ndarray, weight: Weight) -> np.ndarray:
        """int_lo^1 weight(t) (H q - gamma p)(t) dt for c <= lo <= 1 (weight(t) smooth on [lo, 1]; 0 at lo = 1): graded
        toward 1 (the strain's (1 - t)^(alpha - 1/2), one piece and the innermost) and toward lo as far as lo is near c
        (or, at lo = c, as far as t = 0 is near: the weight may be singular there, and the strain is at -c)."""
        lo = np.asarray(lo, dtype=float).ravel()
        out = np.zeros(lo.shape)
        below = lo < 1.0
        length = np.where(below, 1.0 - lo, 1.0)
        pieces = pieces_toward(np.where(lo == self.c, self.c, lo - self.c) / length)
        for k in np.unique(pieces[below]):
            group = np.flatnonzero(below & (pieces == k))
            out[group] = self._strain_integral(lo[group], np.ones(group.size), np.zeros(group.size),
                                               graded_toward(int(k), 1), weight)
        return out

    def _strain_integral(self, lo: np.ndarray, hi: np.ndarray, hi_minus_one: np.ndarray,
                         rule: tuple[np.ndarray, np.ndarray, np.ndarray], weight: Weight | None = None) -> np.ndarray:
        """int_lo^hi weight(t) (H q - gamma p) dt for c <= lo < hi <= 1 (hi - 1 given exactly) by the rule
        (s, 1 - s, w) on [0, 1] mapped onto each [lo, hi]; weight 1 if None."""
        s, one_minus_s, w = rule
        length = hi - lo
        nodes = lo[:, None] + length[:, None] * s[None, :]
        # t - 1 = (hi - 1) - length (1 - s): exact next to the edge, where t itself rounds to 1
        from_one = hi_minus_one[:, None] - length[:, None] * one_minus_s[None, :]
        # nodes that round to c go to its slip side (as doubles; t - 1, exact, is kept); nodes next to an element end
        # inside the slip zone (single basis functions' transforms are logarithmic there, and where the chart's anchor
        # changes from c to 1 the chart value of a node a few ulp off the end rounds to the end itself: u came out NaN
        # at x = (1 + c)/2 and at other ends) move to the clearance from the end on their own side, t - 1 with them
        # (the strain is smooth across such an end, so the integral moves by ~1e-13 times its weight there)
        lay = self.layout
        nodes = np.where(nodes == self.c, np.nextafter(self.c, 2.0), nodes)  # (t - 1 keeps the node where it is)
        from_one = np.where(from_one <= -lay.gap, -lay.gap * (1.0 - CLEARANCE_FRACTION), from_one)
        # the ends as t - 1, exact from the layout's offsets (the doubles t round by 1.1e-16 next to the edge, where a
        # slip zone of 1e-14 holds several ends: compared as doubles, every node moved by the clearance, beyond t = 1,
        # and u was NaN for 1 - c <= 1e-13); the clearance at most CLEARANCE_FRACTION of the slip zone
        base = np.where(lay.anchor == AT_ONE, 0.0, -lay.gap)
        ends = np.unique(np.concatenate([base + lay.origin, base + lay.origin + lay.sigma * lay.length]))
        ends = ends[(ends > -lay.gap) & (ends < 0.0)]
        clearance = min(NODE_CLEARANCE, CLEARANCE_FRACTION * lay.gap)
        if ends.size:
            nearest = ends[np.abs(from_one[..., None] - ends).argmin(axis=-1)]
            shift = np.where(from_one >= nearest, clearance, -clearance) - (from_one - nearest)
            shift = np.where(np.abs(from_one - nearest) < clearance, shift, 0.0)
            nodes, from_one = nodes + shift, from_one + shift
        values = self.strain(nodes.ravel(), from_one.ravel()).reshape(nodes.shape)
        if weight is not None:
            values = values * weight(nodes, -from_one)
        return (values @ w) * length


def _subset(pts: PointSet, where: np.ndarray) -> PointSet:
    """The points of a ``PointSet`` at an index (mask, indices or slice)."""
    return PointSet(pts.anchor[where], pts.offset[where], pts.x[where], pts.owner[where], pts.s[where])


def graded_both_ends() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Composite Gauss on [0, 1]: pieces [2^-(j+1), 2^-j] toward 0 and toward 1 (j < SLIP_PIECES), the innermost
    piece in v, s = h v^INNER_POWER (end behaviours s^lam, lam > -1, become smooth).

    Returns nodes s, their complements 1 - s (exact: next to 1 a double s would round 1 - s) and weights."""
    return graded_toward(SLIP_PIECES, SLIP_PIECES)


def _half(pieces: int, regular: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """Nodes s in [0, 1/2] and weights: ``pieces`` pieces [lo, 2 lo], lo = 2^-2 ... 2^-(pieces + 1), and the innermost
    [0, 2^-(pieces + 1)] in v, s = h v^INNER_POWER (``INNER_NODES``), or, where the integrand is ``regular`` at s = 0
    (its singularity at least the innermost piece's length beyond it), in s with SLIP_NODES like the other pieces."""
    x, w = gauss_legendre(SLIP_NODES)
    lo = 0.5 ** np.arange(2, pieces + 2, dtype=float)  # pieces [lo, 2 lo] within [0, 1/2]
    s_half = ((1.5 * lo)[:, None] + (0.5 * lo)[:, None] * x[None, :]).ravel()
    w_half = ((0.5 * lo)[:, None] * w[None, :]).ravel()
    h = 0.5 ** (pieces + 1)
    if regular:
        return np.concatenate([0.5 * h * (x + 1.0), s_half]), np.concatenate([0.5 * h * w, w_half])
    v, wv = christoffel_gauss01(INNER_NODES)
    m = INNER_POWER
    return np.concatenate([h * v**m, s_half]), np.concatenate([m * h * v ** (m - 1) * wv, w_half])


@lru_cache(maxsize=None)
def graded_toward(at_zero: int, at_one: int, regular_one: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """As ``graded_both_ends`` with ``at_zero`` pieces toward 0 and ``at_one`` toward 1 (read-only arrays);
    ``regular_one``: the integrand is regular at s = 1, its singularity at least 2^-(at_one + 1) beyond it
    (``pieces_toward`` unclipped; ``at_one`` = 0 where it is 1/2 or more beyond), and the innermost piece there is
    plain Gauss (``_half``)."""
    s0, w0 = _half(at_zero)
    s1, w1 = _half(at_one, regular_one)
    s = np.concatenate([s0, 1.0 - s1[::-1]])
    one_minus = np.concatenate([1.0 - s0, s1[::-1]])
    wt = np.concatenate([w0, w1[::-1]])
    for a in (s, one_minus, wt):
        a.setflags(write=False)
    return s, one_minus, wt


def pieces_toward(distance: np.ndarray) -> np.ndarray:
    """Pieces toward the end s = 1 of a rule on [0, 1] whose integrand is singular at 1 + ``distance`` (>= 0): until
    the innermost piece, 2^-(j + 1) long, is no longer than that distance (every piece then sees the singularity at
    >= 3 half-lengths, as ``SLIP_NODES`` assumes), at least 1 and at most SLIP_PIECES."""
    with np.errstate(divide="ignore"):
        needed = np.ceil(-np.log2(np.asarray(distance, dtype=float))) - 1.0
    return np.clip(np.nan_to_num(needed, posinf=SLIP_PIECES), 1, SLIP_PIECES).astype(int)


def weighted_tail_integrals(field: PlaneField, x: np.ndarray, weight: Weight) -> tuple[np.ndarray, np.ndarray]:
    """int_x^1 weight(t) p(t) dt and int_x^1 weight(t) q(t) dt for 0 < x <= 1 (weight(t, 1 - t) smooth on (0, 1), e.g.
    t^-n, or with a logarithm at t = 1, which it evaluates from the exact 1 - t it is given).

    Element by element in its chart: whole elements above x by one rule each (formed once per call), the
    element holding x on its part [x, end] with the rule graded toward both ends (``graded_both_ends``: the
    singular families at an end of the piece, and t^-n near x = 0, are resolved by the grading)."""
    lay = field.layout
    x = np.asarray(x, dtype=float)
    s_rule, _, w_rule = graded_both_ends()
    starts = field._starts
    n_el = len(lay)
    whole_p, whole_q = np.zeros(n_el), np.zeros(n_el)
    lo = np.array([lay.x_range(e)[0] for e in range(n_el)])
    hi = np.array([lay.x_range(e)[1] for e in range(n_el)])

    def piece(e: int, s_a: float, s_b: float) -> tuple[float, float]:
        """int over chart [s_a, s_b] of element e of weight(t) (p, q)(t) |dt|."""
        s = s_a + (s_b - s_a) * s_rule
        step = lay.sigma[e] * lay.length[e] * s
        t = (lay.anchor_value(lay.anchor[e]) + lay.origin[e]) + step  # exact next to 0 (the first element starts at 0)
        offset = lay.origin[e] + step
        one_minus_t = -offset if lay.anchor[e] == AT_ONE else lay.gap - offset  # exact next to the edge
        col = int(starts[e])
        values = []
        for fam in element_families(lay, e, field.alpha):
            values.append(family_values(fam, s))
        B = np.concatenate(values, axis=1)
        cols = slice(col, col + B.shape[1])
        g = weight(t, one_minus_t) * w_rule * (s_b - s_a) * lay.length[e]
        return float(g @ (B @ field._p[cols])), float(g @ (B @ field._q[cols]))

    for e in range(n_el):
        if lo[e] > 0.0:
            whole_p[e], whole_q[e] = piece(e, 0.0, 1.0)
    out_p, out_q = np.zeros(x.shape), np.zeros(x.shape)
    for i, xi in enumerate(x.ravel()):
        above = lo >= xi
        tp, tq = whole_p[above].sum(), whole_q[above].sum()
        e = int(np.flatnonzero((lo < xi) & (hi >= xi))[0]) if np.any((lo < xi) & (hi >= xi)) else -1
        if e >= 0 and xi < hi[e]:
            # the chart value of x, and which side of it lies above x
            s_x = float(np.clip((xi - (lay.anchor_value(lay.anchor[e]) + lay.origin[e])) / (lay.sigma[e] * lay.length[e]),
                                0.0, 1.0))
            a, b = (s_x, 1.0) if lay.sigma[e] > 0 else (0.0, s_x)
            pp, qq = piece(e, a, b)
            tp, tq = tp + pp, tq + qq
        out_p.flat[i], out_q.flat[i] = tp, tq
    return out_p, out_q


@dataclass(frozen=True, slots=True, eq=False)
class FieldCombination:
    """p = sum_i weights[i] p_i, q = sum_i weights[i] q_i and u = sum_i weights[i] u_i of solver fields, with Coulomb's
    law exact on the slip zones |x| > c: p = |q|/mu there from the combined q. Where the fields are linear in a
    parameter (1/(mu gamma) near the limit mu -> inf, ``numeric.solutions.plane_near_limit``) this is their
    interpolation. ``unresolved``: an interval of |x| about c where the combination does not hold (the fields'
    stick-slip points differ), refused with ValueError (``reason`` says why), or None. The weighted integrals of p and
    q (the cylinder's, ``tail_integrals``) are linear too."""

    fields: tuple[PlaneField, ...]
    weights: tuple[float, ...]
    mu: float
    c: float
    gap: float
    unresolved: tuple[float, float] | None = None
    reason: str = ""

    def check(self, ax: np.ndarray) -> None:
        """ValueError if a point |x| lies in ``unresolved``."""
        if self.unresolved is None:
            return
        lo, hi = self.unresolved
        inside = (ax > lo) & (ax < hi)
        if np.any(inside):
            raise ValueError(f"x = {float(ax[inside][0])!r} lies within {hi - self.c:.2g} of the stick-slip point "
                             f"c = {self.c!r}, {self.reason}")

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p and q at -1 <= x <= 1, combined, and Coulomb's law on the slip zones."""
        x = np.asarray(x, dtype=float)
        self.check(np.abs(x).ravel())
        p, q = np.zeros(x.shape), np.zeros(x.shape)
        edge = np.abs(x) == 1.0  # (1 - x)^(alpha - 1/2): every field (mu < inf) is infinite there, weights of both signs
        inner = np.where(edge, 0.0, x)
        for f, w in zip(self.fields, self.weights):
            pf, qf = f.pressure_shear(inner)
            p, q = p + w * pf, q + w * qf
        p, q = np.where(edge, math.inf, p), np.where(edge, np.copysign(math.inf, x), q)
        return np.where(np.abs(x) > self.c, np.abs(q) / self.mu, p), q

    def slip(self, x: np.ndarray) -> np.ndarray:
        """u at -1 <= x <= 1, combined (0 on the stick zone)."""
        x = np.asarray(x, dtype=float)
        self.check(np.abs(x).ravel())
        return sum(w * f.slip(x) for f, w in zip(self.fields, self.weights))

    def tail_integrals(self, x: np.ndarray, weight: Weight) -> tuple[np.ndarray, np.ndarray]:
        """``weighted_tail_integrals`` of the combination (linear in the fields; on the slip zones the fields' own q,
        which the combination matches to its accuracy)."""
        tp, tq = 0.0, 0.0
        for f, w in zip(self.fields, self.weights):
            fp, fq = weighted_tail_integrals(f, x, weight)
            tp, tq = tp + w * fp, tq + w * fq
        return tp, tq
