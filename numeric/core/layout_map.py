"""Layouts of fixed topology whose element ends move smoothly with c (the discretisation of the tabulated fields).

``numeric.core.charts.layout`` builds the elements for each c by rules (geometric grading, a last element that
absorbs a remainder, a centre element halved) whose outcome changes in jumps: the number of elements and the
branch a rule takes switch at many c, so a solution's coefficients are only piecewise smooth in c. A mapped
layout keeps the elements of one reference layout (at c_ref) and moves their ends with c by maps smooth in c,
so that the coefficients of the discrete eigensolution are analytic in (c, gamma) over a piece of c and can be
tabulated (``numeric.core.field_table``):

- the two elements touching c^2 have length L_c = c_fraction min(c^2, 1 - c^2) and the edge element
  L_e = edge_fraction (1 - c^2), as in ``charts.layout``;
- a plain stick element's ends, at distance d from c^2, keep their place in log d between log L_c and log c^2
  (where L_c is proportional to c^2, c^2 <= 1/2, this is the scaling u -> (c / c_ref)^2 u);
- a plain slip element's ends, at offset a from c^2 in (0, w), w = 1 - c^2, keep their place in
  xi = log(a / (w - a)) between xi(L_c) and xi(w - L_e) = log 3, the edge element's end (where L_c is
  proportional to w, c^2 >= 1/2, the same scaling of the slip zone).

So no map crosses c^2 = 1/2, where L_c switches between its two forms: a piece lies on one side. Toward the
reference's side of the piece its elements are stretched (there the graded steps of ``charts.layout`` would be
longest): the reference is the piece's smallest c below 1/sqrt(2) (most slip elements) and its largest above
(most stick elements), so that elsewhere in the piece the grading is finer than the reference's.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np

from numeric.core.charts import AT_C2, EDGE, PLAIN, SLIP, STICK, STICK_END, Layout, Resolution

__all__ = ["mapped_layout"]

_EDGE_LOGIT = math.log(3.0)  # xi at the edge element's end, a = w - L_e = (3/4) w (edge_fraction 1/4)


def _read_only(a: np.ndarray) -> np.ndarray:
    a.setflags(write=False)
    return a


def mapped_layout(c: float, gap: float, reference: Layout, res: Resolution) -> Layout:
    """The elements of ``reference`` (``charts.layout`` at c_ref, resolution res) moved to stick radius c = 1 - gap.

    c and c_ref must lie on the same side of 1/sqrt(2) (L_c's form), and res.edge_fraction must be 1/4.
    """
    if res.edge_fraction != 0.25:
        raise ValueError(f"mapped layouts take edge_fraction 1/4, got {res.edge_fraction}")
    c2, w = c * c, gap * (2.0 - gap)
    if (c2 <= w) != (reference.c2 <= reference.w):
        raise ValueError(f"c = {c} and the reference's c = {reference.c} lie on either side of 1/sqrt(2)")
    Lc, Le = res.c_fraction * min(c2, w), res.edge_fraction * w
    Lc0 = float(reference.hi[reference.stick_end])
    kind, zone = reference.kind, reference.zone
    lo, hi = np.array(reference.lo), np.array(reference.hi)
    at_c = kind == STICK_END
    at_c |= np.roll(at_c, 1)  # and the slip end after it
    lo[at_c], hi[at_c] = 0.0, Lc
    lo[kind == EDGE], hi[kind == EDGE] = 0.0, Le

    stick = np.flatnonzero((kind == PLAIN) & (zone == STICK))  # from the centre outward: [-d_far, -d_near]
    scale = (math.log(c2) - math.log(Lc)) / (math.log(reference.c2) - math.log(Lc0))

    def distance(d0: np.ndarray) -> np.ndarray:  # log d affine: log Lc0 -> log Lc, log c_ref^2 -> log c^2
        return Lc * np.exp((np.log(d0) - math.log(Lc0)) * scale)

    far, near = distance(-reference.lo[stick]), distance(-reference.hi[stick])
    far[0] = c2  # the centre element reaches u = 0
    lo[stick], hi[stick] = -far, -near

    slip = np.flatnonzero((kind == PLAIN) & (zone == SLIP))
    w0 = reference.w
    start0 = math.log(Lc0 / (w0 - Lc0))
    start = math.log(Lc / (w - Lc))
    stretch = (_EDGE_LOGIT - start) / (_EDGE_LOGIT - start0)

    def offsets(lo0: np.ndarray, anchor: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(a, w - a) of the moved ends: xi affine, log 3 fixed and start0 -> start (each side without cancellation)."""
        a0 = np.where(anchor == AT_C2, lo0, w0 + lo0)
        rest0 = np.where(anchor == AT_C2, w0 - lo0, -lo0)
        xi = _EDGE_LOGIT + (np.log(a0) - np.log(rest0) - _EDGE_LOGIT) * stretch
        return w / (1.0 + np.exp(-xi)), w / (1.0 + np.exp(xi))

    anchor = reference.anchor[slip]
    a_lo, rest_lo = offsets(reference.lo[slip], anchor)
    a_hi, rest_hi = offsets(reference.hi[slip], anchor)
    a_lo[0], rest_lo[0] = Lc, w - Lc                 # the first starts at the slip end
    a_hi[-1], rest_hi[-1] = w - Le, Le               # the last ends at the edge element
    lo[slip] = np.where(anchor == AT_C2, a_lo, -rest_lo)
    hi[slip] = np.where(anchor == AT_C2, a_hi, -rest_hi)
    return Layout(c, gap, c2, w, kind, zone, reference.anchor, _read_only(lo), _read_only(hi), reference.degree,
                  reference.singular_degree, reference.n_basis, reference.starts)
