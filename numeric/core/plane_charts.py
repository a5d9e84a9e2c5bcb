"""The singular basis of the plane (strip-punch) solver: elements, charts, local exponents, collocation points.

The stresses of the frictional strip punch (``asymptotics.plane``; x over the half-width, p even,
q odd) are analytic in x except at the stick-slip point x = c and the edge x = 1, where the local
analysis of the half-plane relations (``asymptotics.derive.plane``) gives

- at x = c, on both sides: p, q = A(x) + |x - c|^beta B(x) (with B = 0 for p on the stick side: the local solutions
  have no pressure there, ``asymptotics.derive.plane``), beta = 1/2 - alpha, tan(pi alpha) = mu gamma,
  with A, B analytic: the Mellin symbol of the Cauchy kernel has the roots cot(pi lam) = mu gamma only
  (lam = 1/2 - alpha + n), and the regular solutions (lam = 0, 1, ...) are the ones analytic across c
  (the 2 x 2 Riemann-Hilbert problem's local exponents differ by 1/2 - alpha, not an integer: no
  logarithms). For mu other than the eigenvalue the stick side also carries (c - x)^(-1/2 - alpha).
- at x = 1: p = (1 - x)^(alpha - 1/2) E(x), E analytic (the edge of the slip zone, q = mu p).

So the elements touching c ("stick end", "slip end") carry Legendre polynomials plus h_beta(s) times
polynomials of degree ``singular_degree`` (p's on the stick end pinned to 0 from alpha = 0.04 on,
``numeric.core.stick_pressure_pins.PLANE_PIN_FROM``: the local solutions have no pressure on the stick side, ``numeric.core.plane_operators.plane_collocation_system``) (h_beta = (s^beta - 1)/beta, ``numeric.core.charts.h_beta``:
the same span as s^beta but well conditioned as beta -> 0, mu -> inf, where it is log s); the element
touching 1 ("edge") carries s^(alpha - 1/2) times polynomials; every other element ("plain") is a
polynomial. The chart of an element is linear, t = a + sigma L s, s in [0, 1], with s = 0 at the
singular end. Plain elements are graded geometrically toward c and 1 only so far as to separate
the scales (each no longer than (grading - 1) times its distance to c, nor than its distance to 1
over grading), not to resolve the singularities, which the basis carries.

Points and element ends are stored as an anchor (c or 1) plus an offset, and 1 - c is taken as given
(``gap``), so elements of width 1e-12 next to c or 1 lose no digits.

Near-redundancy: h_beta(s) s^k is approximated by polynomials of degree K to about K^(-2(beta + k)), so a
singular family of high degree next to a Legendre series of degree K makes the basis (and the system)
numerically rank deficient (the previous layout's 4-6 singular functions: smallest singular value of the
equilibrated matrix 1e-16 of the largest). ``singular_degree`` stays at 2-3 here, as in the axisymmetric
solver, and ``tests/test_plane.py`` (``test_the_system_is_not_singular``) checks the condition of the system.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from numeric.core.plane_cauchy import HBETA, PLAIN as PLAIN_WEIGHT, POWER, Family
from numeric.core.quadrature import gauss_legendre

__all__ = ["PLAIN", "STICK_END", "SLIP_END", "EDGE", "STICK", "SLIP", "AT_C", "AT_ONE", "PlaneResolution",
           "plane_partner", "PlaneLayout", "plane_layout", "element_families",
           "COLLOCATION_POWER", "collocation_chart", "PointSet", "collocation_points", "locate"]

PLAIN, STICK_END, SLIP_END, EDGE = 0, 1, 2, 3
"""Element kinds."""
STICK, SLIP = 0, 1
"""Zones."""
AT_C, AT_ONE = 0, 1
"""Anchors: offsets are measured from c or from 1."""


@dataclass(frozen=True, slots=True)
class PlaneResolution:
    """degree: Legendre degree of every element; singular_degree: of the polynomial multiplying h_beta at c;
    c_fraction: the two elements touching c have length c_fraction min(c, 1 - c); edge_fraction: the edge
    element has length edge_fraction (1 - c); grading: ratio of successive plain elements."""

    degree: int = 12
    singular_degree: int = 2
    c_fraction: float = 0.25
    edge_fraction: float = 0.25
    grading: float = 2.0


def plane_partner(res: PlaneResolution) -> PlaneResolution:
    """The resolution one degree lower: its difference from ``res`` is the error estimate."""
    return replace(res, degree=res.degree - 1)


@dataclass(frozen=True, slots=True, eq=False)
class PlaneLayout:
    """Elements on [0, 1] for one stick half-width c = 1 - gap.

    Element e is t = anchor + origin[e] + sigma[e] length[e] s, s in [0, 1] (anchor c or 1 by ``anchor[e]``);
    ``zone`` says whether it carries (p, q) (stick) or p with q = mu p (slip). ``starts[e]`` is the first
    column of element e within its zone's block; ``resolution`` is the one it was laid out at."""

    c: float
    gap: float
    kind: np.ndarray
    zone: np.ndarray
    anchor: np.ndarray
    origin: np.ndarray
    sigma: np.ndarray
    length: np.ndarray
    degree: int
    singular_degree: int
    resolution: PlaneResolution

    def __len__(self) -> int:
        return self.kind.size

    def anchor_value(self, code: np.ndarray | int) -> np.ndarray:
        return np.where(np.asarray(code) == AT_C, self.c, 1.0)

    def n_basis(self, e: int) -> int:
        kind = int(self.kind[e])
        return self.degree + 1 + (self.singular_degree + 1 if kind in (STICK_END, SLIP_END) else 0)

    def n_points(self, e: int) -> int:
        """Collocation points of element e: as many as its basis functions.

        The count balances: the rows are (N) at every point, (T) at the stick points and the load (P),
        the unknowns p, q on the stick elements, R on the slip elements and the amplitude of the generic
        mode (``numeric.core.plane_operators``). (With one point fewer on the edge and one more elsewhere,
        as the index of the edge might suggest, the edge element carries a spurious oscillation: residual
        of (N) 5e-3 of max p at nu = -1/2, c = 0.9, against 3e-13 with its full count.)"""
        return self.n_basis(e)

    def elements(self, zone: int) -> np.ndarray:
        return np.flatnonzero(self.zone == zone)

    @property
    def stick_end(self) -> int:
        return int(np.flatnonzero(self.kind == STICK_END)[0])

    def x_range(self, e: int) -> tuple[float, float]:
        """[lo, hi] of element e in x (floats)."""
        a = float(self.anchor_value(self.anchor[e])) + self.origin[e]
        b = a + self.sigma[e] * self.length[e]
        return (a, b) if a < b else (b, a)


def _frozen(values, dtype) -> np.ndarray:
    a = np.array(values, dtype=dtype)
    a.setflags(write=False)
    return a


def plane_layout(c: float, gap: float, res: PlaneResolution) -> PlaneLayout:
    """The elements for stick half-width c = 1 - gap (0 < c < 1; gap is used for 1 - c)."""
    Lc = res.c_fraction * min(c, gap)
    Le = res.edge_fraction * gap
    q = res.grading
    els = []  # (kind, zone, anchor, origin, sigma, length)
    d = Lc  # plain stick elements down to 0, each no longer than (q - 1) x its distance to c; the last, [0, c - d],
    # no longer than d / 2: p is even, so its polynomial is one on [-(c - d), c - d] with singularities at +-c
    while c - d > 0.5 * d:
        step = min(d * (q - 1.0), c - d)
        nd = c if c - (d + step) < 0.2 * step else d + step
        els.append((PLAIN, STICK, AT_C, -nd, 1.0, nd - d))
        d = nd
    if d < c:
        els.append((PLAIN, STICK, AT_C, -c, 1.0, c - d))
    els.reverse()
    els.append((STICK_END, STICK, AT_C, 0.0, -1.0, Lc))
    els.append((SLIP_END, SLIP, AT_C, 0.0, 1.0, Lc))
    a, top = Lc, gap - Le  # offsets from c: no longer than (q - 1) x the distance to c, nor the distance to 1 / q
    while a < top * (1.0 - 1e-15):
        step = min(a * (q - 1.0), (gap - a) / q)
        b = top if top - (a + step) < 0.2 * step else a + step
        if a < 0.5 * gap:
            els.append((PLAIN, SLIP, AT_C, a, 1.0, b - a))
        else:
            els.append((PLAIN, SLIP, AT_ONE, a - gap, 1.0, b - a))
        a = b
    els.append((EDGE, SLIP, AT_ONE, 0.0, -1.0, Le))
    kind, zone, anchor, origin, sigma, length = zip(*els)
    return PlaneLayout(c, gap, _frozen(kind, int), _frozen(zone, int), _frozen(anchor, int), _frozen(origin, float),
                       _frozen(sigma, float), _frozen(length, float), res.degree, res.singular_degree, res)


def element_families(lay: PlaneLayout, e: int, alpha: float) -> tuple[Family, ...]:
    """The weighted families of element e at basis exponent alpha (``numeric.core.plane_cauchy``)."""
    kind = int(lay.kind[e])
    if kind == PLAIN:
        return (Family(PLAIN_WEIGHT, 0.0, lay.degree),)
    if kind == EDGE:
        return (Family(POWER, alpha - 0.5, lay.degree),)
    return Family(PLAIN_WEIGHT, 0.0, lay.degree), Family(HBETA, 0.5 - alpha, lay.singular_degree)


#: Collocation points on a singular element are r^POWER at the Gauss points r of [0, 1]: clustered toward the
#: singular end, where the enriched space is otherwise badly determined (as in ``numeric.core.charts``).
COLLOCATION_POWER = {PLAIN: 1.0, STICK_END: 1.25, SLIP_END: 1.25, EDGE: 1.25}


def collocation_chart(kind: int, n: int) -> np.ndarray:
    """The n collocation points of an element of this kind, in its chart (sorted, in (0, 1))."""
    r = 0.5 * (gauss_legendre(n)[0] + 1.0)
    power = COLLOCATION_POWER[kind]
    return r if power == 1.0 else r**power


@dataclass(frozen=True, slots=True, eq=False)
class PointSet:
    """Points 0 <= x <= 1 as anchor + offset, their x, the element holding each and its chart value s there."""

    anchor: np.ndarray
    offset: np.ndarray
    x: np.ndarray
    owner: np.ndarray
    s: np.ndarray

    @property
    def size(self) -> int:
        return self.x.size


def collocation_points(lay: PlaneLayout) -> PointSet:
    """Collocation points element by element (stick elements first, in layout order)."""
    anchors, offsets, owners, charts = [], [], [], []
    for e in range(len(lay)):
        s = collocation_chart(int(lay.kind[e]), lay.n_points(e))
        anchors.append(np.full(s.size, lay.anchor[e]))
        offsets.append(lay.origin[e] + lay.sigma[e] * lay.length[e] * s)
        owners.append(np.full(s.size, e))
        charts.append(s)
    anchor, offset = np.concatenate(anchors), np.concatenate(offsets)
    x = lay.anchor_value(anchor) + offset
    return PointSet(anchor, offset, x, np.concatenate(owners), np.concatenate(charts))


def locate(lay: PlaneLayout, x: np.ndarray, side: np.ndarray | None = None, offset_from_one: np.ndarray | None = None
           ) -> PointSet:
    """Points 0 <= x <= 1 as a ``PointSet``: anchored at 1 beyond the middle of the slip zone, else at c.

    x = c belongs to the stick end (``side`` = SLIP moves it to the slip end), x = 1 to the edge element.
    ``offset_from_one``: x - 1 exactly, where the caller has it (next to the edge a double x rounds it)."""
    x = np.asarray(x, dtype=float)
    to_one = x > lay.c + 0.5 * lay.gap
    anchor = np.where(to_one, AT_ONE, AT_C)
    if offset_from_one is None:
        offset = np.where(to_one, x - 1.0, x - lay.c)
        lo = np.array([lay.x_range(e)[0] for e in range(len(lay))])
        key = x
    else:  # the owner and both offsets from x - 1 itself: next to the edge x rounds by 1.1e-16, a slip zone of 1e-14
        # holds elements of ~20 ulp, and the owner by x was off by one at their ends (its chart value clipped to 0)
        from_one = np.asarray(offset_from_one, dtype=float)
        # a point above c as a double is on the slip side, whatever rounding put its offset at or below c
        from_one = np.where(x > lay.c, np.maximum(from_one, np.nextafter(-lay.gap, 0.0)), from_one)
        offset = np.where(to_one, from_one, from_one + lay.gap)
        lo = np.where(lay.anchor == AT_ONE, 0.0, -lay.gap) + np.minimum(lay.origin, lay.origin + lay.sigma * lay.length)
        key = from_one
    order = np.argsort(lo)
    owner = order[np.clip(np.searchsorted(lo[order], key, side="right") - 1, 0, len(lay) - 1)]
    at_c = x == lay.c if offset_from_one is None else from_one == -lay.gap
    if np.any(at_c):
        slip_side = np.zeros(x.shape, dtype=bool) if side is None else np.broadcast_to(np.asarray(side) == SLIP, x.shape)
        owner[at_c] = np.where(slip_side[at_c], lay.stick_end + 1, lay.stick_end)
    owner[(x >= 1.0) if offset_from_one is None else (from_one >= 0.0)] = len(lay) - 1
    # chart value in the owner: offsets from the owner's anchor
    a_own = lay.anchor[owner]
    rel = offset + np.where(anchor == a_own, 0.0, np.where(a_own == AT_C, lay.gap, -lay.gap))
    s = np.clip((rel - lay.origin[owner]) / (lay.sigma[owner] * lay.length[owner]), 0.0, 1.0)
    return PointSet(anchor, offset, x, owner, s)
