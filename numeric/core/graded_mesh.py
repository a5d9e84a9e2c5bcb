"""hp discretisation of (2.2): graded meshes in u = t^2 and exact Abel integrals.

The unknowns are P(u) = p(t) and Q(u) = q(t)/t with u = t^2 ([S75] §2.1; p even, q odd,
so both are smooth functions of u at the centre). On each element they are polynomials of
degree k with a nodal basis at the k + 1 Gauss-Legendre points.

Meshes are geometric (ratio ``sigma``) toward the stick-slip boundary u = c^2 from both
sides and toward the edge u = 1, where the solution behaves like a power of the distance
(reformulation.md: (1-x)^(alpha-1/2) at the edge, (c-x)^(1/2-alpha) at c); the degree
grows linearly with the distance in layers from each of these points (an hp mesh), which
gives exponential convergence in the number of unknowns. Element end points are stored as
an *anchor* (c^2 or 1) plus an offset, so elements of width 1e-20 next to c^2 or 1 carry
no cancellation; every u - v is formed from offsets.

Abel integrals of polynomials are exact: with s = sqrt|u - v|,
    int_{u > v} P(u) du / (2 sqrt(u - v)) = int P(v + s^2) ds,
    int_{u < v} P(u) du / (2 sqrt(v - u)) = int P(v - s^2) ds,
polynomials in s integrated by Gauss-Legendre. For t = sqrt(u) these are
int_x^1 t p dt / sqrt(t^2 - x^2) and int_0^x t p dt / sqrt(x^2 - t^2) of (2.2). Pairs of an
element and a point far from it (Bernstein-ellipse estimate at 1e-17) use the element's own
Gauss rule instead.

The meshes for a given c are images of c-independent reference meshes under
u = c^2 u~ (stick) and u = c^2 + (1 - c^2) u~ (slip), so the stick-stick and slip-slip
blocks are cached reference blocks times c or sqrt(1 - c^2); only the two cross blocks
depend on c.

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

from numeric.core.quadrature import gauss_rule, legendre_values, padded_inverse_vandermonde

__all__ = ["Resolution", "LEVELS", "Elements", "Discretisation", "discretise", "adhesive_discretisation", "abel_matrices"]

_FAR_DIGITS = 40.0  # log(1e17): a far pair's Gauss rule is exact to 1e-17 relative


@dataclass(frozen=True, slots=True)
class Resolution:
    """Parameters of the graded hp mesh.

    sigma: geometric ratio of the layers; layers_c: layers toward c^2 on each side;
    layers_edge: layers toward u = 1 in the slip zone; layers_adhesive: toward u = 1 when
    c = 1; kmin, kmax, slope: degree kmin + floor(slope * layer) capped at kmax;
    split: fraction of the slip zone graded toward c^2 (the rest toward 1).
    """

    sigma: float = 0.2
    layers_c: int = 15
    layers_edge: int = 20
    kmin: int = 2
    kmax: int = 16
    slope: float = 1.0
    split: float = 0.5
    layers_adhesive: int = 30
    kmax_adhesive: int = 24
    slope_adhesive: float = 1.5


#: Resolution levels 0-4, coarse to fine (about 210, 380, 750, 1300, 1600 unknowns at
#: 0 < c < 1). Level 2 is the default (~1e-10 in mu and P*), level 3 reaches ~1e-12; the
#: adhesive meshes of levels 3 and 4 reach 3e-12 in P*, p(0) and q'(0) (tests/test_flat_punch.py).
LEVELS: tuple[Resolution, ...] = (
    Resolution(layers_c=8, layers_edge=10, kmax=10, slope=0.7, layers_adhesive=20, kmax_adhesive=12, slope_adhesive=0.7),
    Resolution(layers_c=12, layers_edge=14, kmax=14, slope=0.7, layers_adhesive=24, kmax_adhesive=16, slope_adhesive=1.0),
    Resolution(layers_c=15, layers_edge=20, kmax=16, slope=1.0),
    Resolution(layers_c=18, layers_edge=24, kmax=22, slope=1.5, layers_adhesive=30, kmax_adhesive=32, slope_adhesive=2.0),
    Resolution(sigma=0.18, layers_c=20, layers_edge=26, kmax=26, slope=1.5, layers_adhesive=40, kmax_adhesive=36,
               slope_adhesive=2.0),
)


@dataclass(frozen=True, slots=True)
class Elements:
    """Elements [anchor + lo, anchor + hi] in u with polynomial degree ``degree``."""

    anchor: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    degree: np.ndarray

    def __len__(self) -> int:
        return self.anchor.size

    @property
    def start(self) -> np.ndarray:
        """Index of each element's first node, and the total number of nodes last."""
        return np.concatenate([[0], np.cumsum(self.degree + 1)])

    def nodes(self) -> tuple[np.ndarray, np.ndarray]:
        """Anchors and offsets of all Gauss nodes, element by element."""
        offsets = [lo + (hi - lo) * (gauss_rule(k)[0] + 1) / 2 for lo, hi, k in zip(self.lo, self.hi, self.degree)]
        return np.repeat(self.anchor, self.degree + 1), np.concatenate(offsets)

    def weights(self) -> np.ndarray:
        """Gauss weights in u of all nodes (int f du = weights @ f(nodes))."""
        return np.concatenate([0.5 * (hi - lo) * gauss_rule(k)[1] for lo, hi, k in zip(self.lo, self.hi, self.degree)])

    def scaled(self, anchor: np.ndarray, factor: float) -> Elements:
        return Elements(anchor, factor * self.lo, factor * self.hi, self.degree)


def _graded_side(length: float, layers: int, sigma: float, kmin: int, kmax: int, slope: float):
    """Distances [far, near] of elements from a singular point, biggest first, and degrees."""
    d = np.concatenate([length * sigma ** np.arange(layers + 1), [0.0]])
    layer = np.arange(layers + 1)[::-1]  # counted from the singular point
    degree = np.minimum(kmax, kmin + np.floor(slope * layer + 1e-9).astype(int))
    return d[:-1], d[1:], degree


def _reference_meshes(res: Resolution, extra_layers: int) -> tuple[Elements, Elements]:
    """Stick mesh on u~ in (0, 1) graded toward 1 (anchor 1); slip mesh graded toward 0 and 1.

    ``extra_layers`` more layers toward u~ = 0 on the slip side resolve the scale c^2 of the
    stick-slip boundary when c is small (the stick side is scaled by c^2 already)."""
    far, near, degree = _graded_side(1.0, res.layers_c, res.sigma, res.kmin, res.kmax, res.slope)
    stick = Elements(np.ones(degree.size), -far, -near, degree)
    a_far, a_near, a_deg = _graded_side(res.split, res.layers_c + extra_layers, res.sigma, res.kmin, res.kmax, res.slope)
    b_far, b_near, b_deg = _graded_side(1 - res.split, res.layers_edge, res.sigma, res.kmin, res.kmax, res.slope)
    slip = Elements(
        np.concatenate([np.zeros(a_deg.size), np.ones(b_deg.size)]),
        np.concatenate([a_near[::-1], -b_far]),
        np.concatenate([a_far[::-1], -b_near]),
        np.concatenate([a_deg[::-1], b_deg]),
    )
    return stick, slip


def abel_matrices(el: Elements, anchor: np.ndarray, offset: np.ndarray, *, upper: bool = True, lower: bool = True):
    """Exact Abel integrals of the nodal basis of ``el`` at points v = anchor + offset.

    Returns (U, Lo) with U[i, n] = int_{u > v_i} L_n(u) du / (2 sqrt(u - v_i)) and
    Lo[i, n] = int_{u < v_i} L_n(u) du / (2 sqrt(v_i - u)); either may be None.
    """
    start = el.start
    degree, width = el.degree, el.hi - el.lo
    kmax = int(degree.max())
    element_of = np.repeat(np.arange(len(el)), degree + 1)
    _, node_offset = el.nodes()
    same = anchor[:, None] == el.anchor[None, :]
    da = np.where(same, 0.0, el.anchor[None, :] - anchor[:, None])
    d_lo = da + (el.lo[None, :] - offset[:, None])  # u_lo - v
    d_hi = da + (el.hi[None, :] - offset[:, None])  # u_hi - v
    threshold = (np.cosh(_FAR_DIGITS / (2 * degree + 2)) - 1) / 2
    far_up = d_lo > threshold * width
    far_lo = -d_hi > threshold * width
    quarter_weights = el.weights() / 2  # h w / 4: Gauss weight in u over the 2 of (2 sqrt)
    diff = da[:, element_of] + (node_offset[None, :] - offset[:, None])  # u_n - v
    base = quarter_weights[None, :] / np.sqrt(np.where(diff == 0.0, 1.0, np.abs(diff)))
    U = np.where(far_up[:, element_of], base, 0.0) if upper else None
    Lo = np.where(far_lo[:, element_of], base, 0.0) if lower else None
    xg, wg, _ = gauss_rule(kmax)
    vinv = padded_inverse_vandermonde(kmax)
    local = np.arange(kmax + 1)

    def near(rows: np.ndarray, elems: np.ndarray, is_upper: bool, out: np.ndarray) -> None:
        if rows.size == 0:
            return
        h = width[elems]
        if is_upper:
            dl, dh = d_lo[rows, elems], d_hi[rows, elems]
            inside = dl > 0  # the element lies wholly above v
            s_lo = np.sqrt(np.where(inside, dl, 0.0))
            s_hi = np.sqrt(dh)
            ds = np.where(inside, h / (s_hi + s_lo), s_hi)
            step = ds[:, None] * ((xg + 1) / 2)[None, :]  # s - s_lo, formed directly
            u_minus_lo = np.where(inside[:, None], step * (2 * s_lo[:, None] + step), step * step - dl[:, None])
        else:
            dl, dh = -d_lo[rows, elems], -d_hi[rows, elems]  # v - u_lo > 0, v - u_hi
            inside = dh > 0
            s_hi = np.sqrt(dl)
            s_lo = np.sqrt(np.where(inside, dh, 0.0))
            ds = np.where(inside, h / (s_hi + s_lo), s_hi)
            step = ds[:, None] * ((1 - xg) / 2)[None, :]  # s_hi - s
            u_minus_lo = step * (2 * s_hi[:, None] - step)
        xi = -1.0 + 2.0 * u_minus_lo / h[:, None]
        moments = (legendre_values(xi, kmax) @ wg).T * (ds / 2)[:, None]
        values = np.einsum("pk,pkn->pn", moments, vinv[degree[elems]])
        mask = local[None, :] <= degree[elems][:, None]
        out[np.broadcast_to(rows[:, None], mask.shape)[mask], (start[elems][:, None] + local[None, :])[mask]] = values[mask]

    if upper:
        near(*np.nonzero((d_hi > 0) & ~far_up), True, U)
    if lower:
        near(*np.nonzero((d_lo < 0) & ~far_lo), False, Lo)
    return U, Lo


@dataclass(frozen=True, slots=True)
class _Reference:
    stick: Elements
    slip: Elements
    stick_nodes: tuple[np.ndarray, np.ndarray]
    slip_nodes: tuple[np.ndarray, np.ndarray]
    U_stick: np.ndarray
    Lo_stick: np.ndarray
    U_slip: np.ndarray
    Lo_slip: np.ndarray


@lru_cache(maxsize=16)
def _reference(res: Resolution, extra_layers: int) -> _Reference:
    stick, slip = _reference_meshes(res, extra_layers)
    sn, ln = stick.nodes(), slip.nodes()
    U_s, Lo_s = abel_matrices(stick, *sn)
    U_l, Lo_l = abel_matrices(slip, *ln)
    return _Reference(stick, slip, sn, ln, U_s, Lo_s, U_l, Lo_l)


@dataclass(frozen=True, slots=True)
class Discretisation:
    """The mesh for one stick radius c: stick elements on (0, c^2), slip elements on (c^2, 1).

    Matrices are Abel integrals of the nodal bases at the nodes: U_ss, Lo_ss (stick rows and
    columns), U_ll, Lo_ll (slip), U_sl (stick rows, slip columns, upper) and Lo_ls (slip rows,
    stick columns, lower); the other two cross blocks vanish.
    """

    c: float
    resolution: Resolution
    stick: Elements
    slip: Elements
    x_stick: np.ndarray
    x_slip: np.ndarray
    w_stick: np.ndarray
    w_slip: np.ndarray
    U_ss: np.ndarray
    Lo_ss: np.ndarray
    U_ll: np.ndarray
    Lo_ll: np.ndarray
    U_sl: np.ndarray
    Lo_ls: np.ndarray
    slip_nodes: tuple[np.ndarray, np.ndarray]


def discretise(c: float, res: Resolution) -> Discretisation:
    """The discretisation for 0 < c < 1 from the cached reference meshes and blocks."""
    c2 = c * c
    # grade the slip side toward c^2 as finely as the stick side (smallest elements
    # split sigma^L and c^2 sigma^L): log(c^2 / split) / log(sigma) extra layers for small c
    ref = _reference(res, max(0, math.floor(math.log(c2 / res.split) / math.log(res.sigma))))
    w = (1.0 - c) * (1.0 + c)
    stick = ref.stick.scaled(np.full(len(ref.stick), c2), c2)
    slip = ref.slip.scaled(np.where(ref.slip.anchor == 0.0, c2, 1.0), w)
    stick_nodes = (np.full(ref.stick_nodes[0].size, c2), c2 * ref.stick_nodes[1])
    slip_nodes = (np.where(ref.slip_nodes[0] == 0.0, c2, 1.0), w * ref.slip_nodes[1])
    U_sl, _ = abel_matrices(slip, *stick_nodes, lower=False)
    _, Lo_ls = abel_matrices(stick, *slip_nodes, upper=False)
    root_w = math.sqrt(w)
    return Discretisation(
        c=c,
        resolution=res,
        stick=stick,
        slip=slip,
        x_stick=np.sqrt(stick_nodes[0] + stick_nodes[1]),
        x_slip=np.sqrt(slip_nodes[0] + slip_nodes[1]),
        w_stick=c2 * ref.stick.weights(),
        w_slip=w * ref.slip.weights(),
        U_ss=c * ref.U_stick,
        Lo_ss=c * ref.Lo_stick,
        U_ll=root_w * ref.U_slip,
        Lo_ll=root_w * ref.Lo_slip,
        U_sl=U_sl,
        Lo_ls=Lo_ls,
        slip_nodes=slip_nodes,
    )


@lru_cache(maxsize=8)
def adhesive_discretisation(res: Resolution) -> tuple[Elements, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The c = 1 mesh graded toward u = 1: elements, node x, weights in u, U and Lo."""
    far, near, degree = _graded_side(1.0, res.layers_adhesive, res.sigma, res.kmin, res.kmax_adhesive, res.slope_adhesive)
    el = Elements(np.ones(degree.size), -far, -near, degree)
    anchor, offset = el.nodes()
    U, Lo = abel_matrices(el, anchor, offset)
    return el, np.sqrt(anchor + offset), el.weights(), U, Lo
