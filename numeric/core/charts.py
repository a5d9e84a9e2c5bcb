"""The singular basis of the flat-punch solver: elements, charts and the local exponents ([S75] §2).

The stresses of the frictional flat punch are analytic in u = x^2 except at the stick-slip
boundary u = c^2 and at the edge u = 1, where their behaviour is known
(``shared/spec/reformulation.md``, checked here by fits to independent solutions):

- at x = c, q/x on the stick side and p (q = mu p) on the slip side are A(s) + s^beta B(s) with
  A, B analytic in s = sqrt|u - c^2| (half-integer powers of |x - c| come from the Abel integrals),
  beta = 1 - 2 alpha, tan(pi alpha) = mu gamma ([S75] (2.15)); p on the stick side is A(s) alone:
  near c the problem is locally plane, and the plane local solutions (every exponent lam with
  cot(pi lam) = mu gamma, ``asymptotics.derive.plane``) carry no pressure on the stick side;
- at x = 1, p = t^(alpha - 1/2) [A(t) + t log t B(t)], t = 1 - u: the exponent of the
  frictional edge and, because every alpha - 1/2 + k is again a local exponent, a
  resonant logarithm one order higher.

So the basis carries them: elements touching c^2 ("stick end", "slip end") use the chart
u = c^2 -/+ L s^2 with Legendre polynomials in s and the singular family h_beta(s) times
low-degree polynomials; the element touching 1 ("edge") uses u = 1 - L s^2 with the weight
s^(2 alpha - 1) (= t^(alpha - 1/2)) times polynomials in s, and s^2 log s times the same
weight; all other elements ("plain") are polynomials in u. Elements are graded
geometrically toward c^2 and 1 only so far as to separate the scales (each plain element
is no longer than its distance to c^2 or 1), not to resolve the singularities, which the
basis carries: about 150 unknowns give mu to 1e-11 (``derivations/benchmark.md``).

h_beta(s) = (s^beta - s)/(beta - 1) for beta > 1/2 and (s^beta - 1)/beta for beta <= 1/2
spans, with the polynomials, the same functions as s^beta, but stays a well-conditioned
basis function as beta -> 1 (mu gamma -> 0, where it tends to s log s) and as beta -> 0
(mu -> inf, log s: the limit problem of the largest stick radius).

The stick pressure P shares the stick end's basis with the shear Q, but for beta <= 1/2 (mu gamma >= 1) its
coefficients of the singular family are pinned to 0 (``numeric.core.stick_pressure_pins``). Left free
there, they were undetermined (noise along one direction, of either sign between degrees) and made a
near-null vector of the system concentrated at x = c, as h_beta tends to log s: at nu = 0, c = 0.9988
(mu = 16.8, degree 12) the equilibrated system's least singular value was 2.4e-13 (the next 1.6e-9) and
p, q within 1e-9 (1 - c) of c moved by 1e-7 when the system was perturbed by 1e-16. Solved without them in
least squares, the same system leaves a residual at rounding (4.8e-15: the solution has no such
component); pinned, its least singular value is 1.3e-10 and the same perturbation moves p by 8e-11. For
beta > 1/2 the free family does no harm (h_beta(0) = 0; least singular value 4.6e-10 at nu = 0, c = 0.3),
and pinning it there made mu scatter between degrees 12 ... 26 by ten times more at small c (4e-12 against
3.7e-13 at nu = 0, c = 1e-3), so it stays. mu at level 2 stays within 1e-12 of the previous basis's level
4 (11 (nu, c) from c = 0.01 to 1 - c = 1.05 (1 - c_max)), and next to c_max p at x = c now converges with
the degree (``tests/test_singular_solver.py``).

Points are stored as an anchor (c^2 or 1) plus an offset, so elements of width 1e-12 next
to c^2 or 1 lose no digits, and 1 - c is taken as given (``gap``) rather than formed.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from numeric.core.quadrature import gauss_legendre, legendre_values

__all__ = [
    "PLAIN", "STICK_END", "SLIP_END", "EDGE", "STICK", "SLIP", "AT_C2", "AT_ONE",
    "Resolution", "RESOLUTIONS", "partner", "Layout", "SLIVER", "CENTRE_RATIO", "layout", "chart_logarithm", "h_beta", "family_factors", "basis_values",
    "FEW_POINTS", "shifted_legendre", "chart_offset", "chart_of_offset", "COLLOCATION_POWER", "collocation_chart", "collocation",
]

PLAIN, STICK_END, SLIP_END, EDGE = 0, 1, 2, 3
"""Element kinds: polynomial in u; touching c^2 from the stick side; from the slip side; touching u = 1."""
STICK, SLIP = 0, 1
"""Zones."""
AT_C2, AT_ONE = 0, 1
"""Anchors: offsets are measured from c^2 or from 1."""


@dataclass(frozen=True, slots=True)
class Resolution:
    """Degrees and layout of the singular basis.

    degree: Legendre degree on the singular elements; singular_degree: degree of the
    polynomial multiplying the singular family at c (edge_singular_degree: the logarithmic
    family at the edge; higher degrees are nearly polynomials, which only spoils the
    conditioning: coefficients of 5e5 with 3 at the edge against 2e3 with 1); plain_degree: degree on plain elements
    (default: ``degree``); c_fraction: the two elements touching c^2 have length
    c_fraction * min(c^2, 1 - c^2); grading: ratio of successive plain elements; edge_fraction:
    the edge element has length edge_fraction * (1 - c^2); edge_grading: a plain slip element is at most its
    distance to u = 1 over this long (default: ``grading``; ``EDGE_GRADING``).
    """

    degree: int = 12
    singular_degree: int = 3
    edge_singular_degree: int = 1
    plain_degree: int | None = None
    c_fraction: float = 0.25
    grading: float = 2.0
    edge_fraction: float = 0.25
    edge_grading: float | None = None

    @property
    def toward_edge(self) -> float:
        return self.grading if self.edge_grading is None else self.edge_grading

    @property
    def plain(self) -> int:
        return self.degree if self.plain_degree is None else self.plain_degree


#: Resolution levels 0-4, coarse to fine; level 2 is the default. Levels 1 and 2 hold the plain elements below the
#: singular ones (degree 9 against 10, 11 against 13): there the plain elements set the error of mu, which then shrinks
#: regularly with the degree, so the partner one degree lower (``partner``) bounds it. Measured (before EDGE_GRADING)
#: over 80 (nu, c), nu in [-0.999, 0.4999], 1 - c from 0.999 down to 1.01 (1 - c_max), against degree 24 (mu and P*,
#: relative): level 1 worst 2.6e-9, level 2 worst 4.9e-11 (median 3e-15; 262 unknowns on average), level 3 8e-13, the estimate above the true
#: error at all 80 for levels 1 and 2. With every element at degree 12 (274 unknowns) level 2 was worst 1.3e-11 but
#: at nu = 0.3, 1 - c = 1.1 (1 - c_max) 1.2 times above its estimate: the degree-11 partner was the more accurate (even
#: plain degrees converge worse there; plain 12 under singular 13 fell 1.03 times short at the same point). The
#: singular elements at 13 rather than 12 (4 more unknowns) brought p and q at x = c next to c_max from 1.8e-9 to 1.1e-9
#: of level 4 (3e-10 since p(c) is read from the stick side, ``numeric.core.fields``). Level 0 (all at degree 7) is erratic next to c_max (up to 6.4 times its partner difference,
#: ``numeric.solutions.solver.ESTIMATE_SAFETY``); lower plain degrees were worse.
#: Levels 2-4 grade their plain slip elements toward the edge by EDGE_GRADING: at the grading's 2 the element where
#: the anchors meet (mid-annulus) was as long as its distance to u = 1, where p ~ (1 - x)^(alpha - 1/2) is largest, and
#: level 2's p there was up to 2.05e-9 of max(1, |p|) off level 4 (nu = 0.45, c = 0.4, x = 0.69; over c = 0.05 ... 0.9,
#: nu in {-0.5, 0, 0.3, 0.45}, 42 points across the annulus; level 3 within 1.9e-12 of level 4). At 3 it is at most
#: half that distance: 3.5e-12 there, for one plain element more (178 -> 190 unknowns). Levels 0 and 1 keep the
#: grading (the field table is stored on level-0 layouts; level 1's estimate factors were measured on its layout).
EDGE_GRADING = 3.0
RESOLUTIONS: tuple[Resolution, ...] = (
    Resolution(degree=7, singular_degree=2),
    Resolution(degree=10, singular_degree=3, plain_degree=9),
    Resolution(degree=13, singular_degree=3, plain_degree=11, edge_grading=EDGE_GRADING),
    Resolution(degree=15, singular_degree=3, edge_grading=EDGE_GRADING),
    Resolution(degree=18, singular_degree=3, edge_grading=EDGE_GRADING),
)


def partner(res: Resolution) -> Resolution:
    """The resolution one degree lower: its difference from ``res`` is the error estimate."""
    return Resolution(res.degree - 1, res.singular_degree, res.edge_singular_degree,
                      None if res.plain_degree is None else res.plain_degree - 1, res.c_fraction, res.grading,
                      res.edge_fraction, res.edge_grading)


@dataclass(frozen=True, slots=True, eq=False)
class Layout:
    """Elements for one stick radius: kind, zone, anchor and offsets [lo, hi] from the anchor."""

    c: float
    gap: float        # 1 - c
    c2: float         # c^2
    w: float          # 1 - c^2, formed from gap
    kind: np.ndarray
    zone: np.ndarray
    anchor: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    degree: np.ndarray
    singular_degree: np.ndarray
    n_basis: np.ndarray
    starts: np.ndarray  # first basis index of each element, total last

    def __len__(self) -> int:
        return self.kind.size

    def length(self, e: int) -> float:
        return float(self.hi[e] - self.lo[e])

    def anchor_value(self, e: int) -> float:
        return self.c2 if self.anchor[e] == AT_C2 else 1.0

    @property
    def n_stick(self) -> int:
        """Basis functions (= collocation points) in the stick zone."""
        return int(self.n_basis[self.zone == STICK].sum())

    @property
    def stick_end(self) -> int:
        return int(np.flatnonzero(self.kind == STICK_END)[0])


def _frozen(values, dtype) -> np.ndarray:
    a = np.array(values, dtype=dtype)
    a.setflags(write=False)
    return a


#: The last plain element toward u = 0 and the last before the edge element absorb a remainder shorter than this
#: fraction of a graded step (no sliver), and no more: merging up to half a step (1.5 times the grading's length)
#: limited level 2 to 2e-9 in p in the slip annulus (near x = c + 0.7 (1 - c)) and, where the merge fell near
#: x = 0, to 9e-9 in p(0) at nu = 0.3, 1 - c = 1.2e-5; holding the grading gave 3e-11 there with the plain elements
#: at degree 12 (at the levels' plain degrees, ``RESOLUTIONS``, level 2 reaches 9.6e-10 mid-annulus).
SLIVER = 0.1

#: The element touching u = 0 is at most this fraction of its distance to u = 1 long (the edge's singularity; the stick
#: pressure is regular at c^2), else it is halved: p(0) is its value at an end no neighbour shares, reached by
#: extrapolation. Level 2 against level 4 over nu in {-0.9, -1/2, 0, 0.3, 0.45}, 19 values of 1 - c from 0.3 down to
#: 1.05 (1 - c_max) each: p(0) up to 2.4e-9 off unsplit (where the element was as long as its distance to c^2 and c
#: near 1), 1.9e-10 with this rule (4.9e-10 with 0.75), at 2.4 % more unknowns on average; below c = 1/sqrt(2) the
#: element is at most a third of that distance and p(0) was within 4.5e-11 (56 (nu, c)).
CENTRE_RATIO = 0.6


def layout(c: float, gap: float, res: Resolution) -> Layout:
    """The elements for stick radius c = 1 - gap (0 < c < 1); gap is used for 1 - c^2."""
    c2 = c * c
    w = gap * (2.0 - gap)
    Lc = res.c_fraction * min(c2, w)
    q = res.grading
    els = []  # (kind, zone, anchor, lo, hi, degree, singular degree)
    d = Lc
    stick = []
    while d < c2 * (1.0 - 1e-15):  # plain stick elements, each no longer than (q - 1) x its distance to c^2
        step = d * (q - 1.0)
        nd = c2 if d + step > c2 - SLIVER * step else d + step
        if nd == c2 and c2 - d > CENTRE_RATIO * (d + w):
            nd = d + 0.5 * (c2 - d)
        stick.append((PLAIN, STICK, AT_C2, -nd, -d, res.plain, 0))
        d = nd
    els += stick[::-1]
    els.append((STICK_END, STICK, AT_C2, 0.0, Lc, res.degree, res.singular_degree))
    els.append((SLIP_END, SLIP, AT_C2, 0.0, Lc, res.degree, res.singular_degree))
    Le = min(res.edge_fraction * w, w - Lc)
    top = w - Le
    a = Lc  # offset from c^2
    # no longer than (q - 1) x the distance to c^2, nor the distance to 1 over the edge grading
    while a < top * (1.0 - 1e-15):
        step = min(a * (q - 1.0), (w - a) / res.toward_edge)
        b = top if a + step > top - SLIVER * step else a + step
        if a < 0.5 * w:
            els.append((PLAIN, SLIP, AT_C2, a, b, res.plain, 0))
        else:
            els.append((PLAIN, SLIP, AT_ONE, a - w, b - w, res.plain, 0))
        a = b
    els.append((EDGE, SLIP, AT_ONE, 0.0, Le, res.degree, res.edge_singular_degree))
    kind, zone, anchor, lo, hi, deg, sdeg = zip(*els)
    kind = np.array(kind)
    nb = np.array(deg) + 1 + np.where(kind == PLAIN, 0, np.array(sdeg) + 1)
    return Layout(c, gap, c2, w, _frozen(kind, int), _frozen(zone, int), _frozen(anchor, int), _frozen(lo, float),
                  _frozen(hi, float), _frozen(deg, int), _frozen(sdeg, int), _frozen(nb, int),
                  _frozen(np.concatenate([[0], np.cumsum(nb)]), int))


def chart_logarithm(s: np.ndarray) -> np.ndarray:
    """log s where s > 0, 0 elsewhere: what ``h_beta`` and ``family_factors`` take the powers of s from. Nodes that
    serve many alpha (``numeric.core.operators.AbelOperators``) form it once: per alpha only the exponentials remain
    (the logarithm was a third of the family factors' time)."""
    s = np.asarray(s, dtype=float)
    return np.log(np.where(s > 0.0, s, 1.0))


def h_beta(beta: float, s: np.ndarray, log_s: np.ndarray | None = None) -> np.ndarray:
    """The singular family at c: (s^beta - s)/(beta - 1) (beta > 1/2) or (s^beta - 1)/beta (beta <= 1/2).

    Stable as beta -> 1 (-> s log s) and beta -> 0 (-> log s); at s = 0 it is 0 (beta > 1/2),
    -1/beta (0 < beta <= 1/2) or -inf (beta = 0). ``log_s``: ``chart_logarithm(s)``, if the caller has it.
    """
    s = np.asarray(s, dtype=float)
    pos = s > 0.0
    ls = chart_logarithm(s) if log_s is None else log_s
    if beta > 0.5:
        d = beta - 1.0
        out = s * (ls if d == 0.0 else np.expm1(d * ls) / d)
        at_zero = 0.0
    else:
        out = ls if beta == 0.0 else np.expm1(beta * ls) / beta
        at_zero = -np.inf if beta == 0.0 else -1.0 / beta
    return np.where(pos, out, at_zero)


def family_factors(kind: int, s: np.ndarray, alpha: float, displacement: bool = False, log_s: np.ndarray | None = None
                   ) -> tuple[np.ndarray | None, np.ndarray]:
    """Factors of the two families on a singular element at chart points s (``log_s``: ``chart_logarithm(s)``, if the
    caller has it).

    Stick/slip end: (None, h_beta(s)), beta = 1 - 2 alpha; edge: (s^(2 alpha - 1), s^(2 alpha + 1) log s).
    ``displacement``: the families of u* = x int_x^1 q - gamma int_0^x t p (one Abel order
    smoother): at c, where u* vanishes from the slip side like s^2 and s^(1 + beta), (s^2, s h_beta);
    at the edge, where u* is A(s) + s^t B(s), t = 2 alpha, (None, (s^t - 1 - t (s - 1))/(t (1 - t))): the same space
    for 0 < t < 1, but the family stays apart from A's Legendre polynomials at both ends, where s^t itself falls onto
    them (1 at t = 0, s at t = 1): log s - (s - 1) at t = 0 (mu = 0), s - 1 - s log s at t = 1 (mu = inf). With s^t,
    at mu gamma ~ 1e-9 the interpolation of u* lost 6 digits near the edge and below ~1e-15 it was singular; with
    (s^t - 1)/t alone it was singular at mu = inf.
    """
    if kind in (STICK_END, SLIP_END):
        if displacement:  # u* = 0 at c with no linear term: s^2 A(s) + s^(1 + beta) B(s)
            beta = 1.0 - 2.0 * alpha
            # s h_beta is (s^(1+beta) - s^2)/(beta - 1) for beta > 1/2; below, h_beta carries a constant, which
            # would put a linear term into u*: there s^(1+beta) itself (s log s in the limit beta = 0)
            singular = s * (h_beta(beta, s, log_s) if beta > 0.5 or beta == 0.0 else s**beta)
            return s * s, singular
        return None, h_beta(1.0 - 2.0 * alpha, s, log_s)
    pos = s > 1e-300  # below, the weights of every rule are 0 (and s^(2 alpha - 1) could overflow)
    sp = np.where(pos, s, 1.0)
    ls = np.log(sp) if log_s is None else np.where(pos, log_s, 0.0)
    if displacement:
        t = 2.0 * alpha
        if t <= 0.5:  # (s^t - 1)/t - (s - 1), over 1 - t
            family = ls - (sp - 1.0) if t == 0.0 else (np.expm1(t * ls) / t - (sp - 1.0)) / (1.0 - t)
        else:  # s (s^(t - 1) - 1)/(t (1 - t)) + (s - 1)/t, the same without the cancellation near t = 1
            family = (sp - 1.0) - sp * ls if t >= 1.0 else sp * np.expm1((t - 1.0) * ls) / (t * (1.0 - t)) + (sp - 1.0) / t
        return None, np.where(pos, family, 0.0)
    weight = np.where(pos, np.exp((2.0 * alpha - 1.0) * ls), 0.0)
    return weight, weight * (sp * sp * ls)


#: Up to this many points the recurrence runs on Python floats (the same operations in the same order, so the same
#: values): numpy's per-call overhead made P_0 .. P_12 at two points cost 30 microseconds against 4.
FEW_POINTS = 16


def shifted_legendre(k: int, s: np.ndarray) -> np.ndarray:
    """P_0 .. P_k (2 s - 1), stacked on the last axis."""
    s = np.asarray(s, dtype=float)
    if s.size > FEW_POINTS:
        return np.moveaxis(legendre_values(2.0 * s - 1.0, k), 0, -1)
    rows = []
    for x in (2.0 * s.ravel() - 1.0).tolist():
        p = [1.0, x][: k + 1]
        for n in range(1, k):
            p.append(((2 * n + 1) * x * p[n] - n * p[n - 1]) / (n + 1))
        rows.append(p)
    return np.array(rows, dtype=float).reshape(s.shape + (k + 1,))


def basis_values(lay: Layout, e: int, s: np.ndarray, alpha: float, legendre: np.ndarray | None = None,
                 displacement: bool = False) -> np.ndarray:
    """The basis functions of element e at chart points s: shape s.shape + (n_basis[e],).

    ``legendre`` may pass shifted_legendre(degree, s) when it is cached; ``displacement`` selects
    the families of u* (see ``family_factors``).
    """
    P = shifted_legendre(int(lay.degree[e]), s) if legendre is None else legendre
    kind = int(lay.kind[e])
    if kind == PLAIN:
        return P
    regular, singular = family_factors(kind, np.asarray(s, dtype=float), alpha, displacement)
    head = P if regular is None else regular[..., None] * P
    return np.concatenate([head, singular[..., None] * P[..., : int(lay.singular_degree[e]) + 1]], axis=-1)


def chart_offset(lay: Layout, e: int, s: np.ndarray) -> np.ndarray:
    """Offset from the element's anchor of chart points s."""
    kind = int(lay.kind[e])
    L = lay.length(e)
    if kind == PLAIN:
        return lay.lo[e] + L * s
    if kind == SLIP_END:
        return L * s * s
    return -L * s * s  # stick end (anchor c^2), edge (anchor 1)


def chart_of_offset(lay: Layout, e: int, offset: np.ndarray) -> np.ndarray:
    """Chart points of offsets (from the element's anchor) inside element e (inverse of chart_offset)."""
    kind = int(lay.kind[e])
    L = lay.length(e)
    if kind == PLAIN:
        return np.clip((offset - lay.lo[e]) / L, 0.0, 1.0)
    sign = 1.0 if kind == SLIP_END else -1.0
    return np.sqrt(np.clip(sign * offset / L, 0.0, 1.0))


#: Collocation points on a singular element are r^POWER at the Gauss points r of [0, 1]: the enriched
#: space is badly determined by Gauss points in s (interpolation of A(s) + s^beta B(s) at K = 15,
#: 5 singular functions: 1e-9 ... 5e-7), well by points clustered toward the singular end
#: (r^2: 1e-13 ... 4e-13 at the stick-slip boundary; r^1.5: 3e-15 at the edge). On the slip side of c the
#: points cluster harder: near the largest stick radius (beta = 1 - 2 alpha ~ 0.02) the family there is
#: nearly log s and its amplitude, seen only from s >= 1e-3 at r^1.25, was extrapolated to the slip side's
#: s ~ 1e-5 at x within a few ulp of c: q there drifted by 1e-6 relative between degrees 12 ... 26
#: (nu = 0.3, 1 - c = 1.05 (1 - c_max)). At r^1.5 degrees 12 ... 28 agree within 3e-9 there
#: (``tests/test_singular_solver.py``); r^1.75 did better at x = c (9e-10) but lost mu at degrees 24 and 28 near
#: c_max (1.8e-9 at degree 28, nu = 0, 1 - c = 1.01 (1 - c_max), where r^1.5 keeps every degree within 4e-12).
COLLOCATION_POWER = {PLAIN: 1.0, STICK_END: 1.25, SLIP_END: 1.5, EDGE: 1.25}


def collocation_chart(kind: int, n: int) -> np.ndarray:
    """The n collocation points of an element of this kind, in its chart (sorted, in (0, 1))."""
    r = 0.5 * (gauss_legendre(n)[0] + 1.0)
    power = COLLOCATION_POWER[kind]
    return r if power == 1.0 else r ** power


def collocation(lay: Layout) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Collocation points, element by element: anchor codes, offsets, and x = sqrt(u).

    The offsets are ``chart_offset``'s, the plain elements' (which share one chart) formed together."""
    anchor = np.repeat(lay.anchor, lay.n_basis)
    offset = np.empty(anchor.size)
    plain = np.flatnonzero(lay.kind == PLAIN)
    if plain.size:  # lo + L s, as chart_offset
        s = collocation_chart(PLAIN, int(lay.n_basis[plain[0]]))
        rows = lay.starts[plain][:, None] + np.arange(s.size)[None, :]
        offset[rows] = lay.lo[plain][:, None] + (lay.hi[plain] - lay.lo[plain])[:, None] * s[None, :]
    for e in np.flatnonzero(lay.kind != PLAIN):
        offset[int(lay.starts[e]): int(lay.starts[e + 1])] = chart_offset(
            lay, int(e), collocation_chart(int(lay.kind[e]), int(lay.n_basis[e])))
    return anchor, offset, np.sqrt(np.where(anchor == AT_C2, lay.c2, 1.0) + offset)
