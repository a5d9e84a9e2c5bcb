"""The collocation system of the strip punch on the plane singular basis.

Equations (``asymptotics.plane``; x over the half-width a, p even, q odd, H the finite Hilbert transform
on (-1, 1)):

    (N)  H p + gamma q = 0          at every collocation point    (flat punch: du_z/dx = 0)
    (T)  H q - gamma p = 0          at the stick points           (stick: du_x/dx = 0)
    (P)  int_{-1}^{1} p dx = 1                                     (the load)

with q = mu p on the slip zone c < x < 1. Unknowns: the coefficients of p and q on the stick elements
and of R on the slip elements, where p = R cos(theta), q = R sin(theta)/gamma, theta = pi alpha =
atan(mu gamma): q = mu p holds by construction and both stay bounded for every mu in [0, inf] (at
mu = inf, p = 0 on the slip zone: the limit problem of the largest stick width). So the matrix is
D(theta) = S + cos(theta) N + sin(theta) T, with S the stick columns and N, T the slip columns'
normal and shear parts, as in ``numeric.core.operators``.

The basis functions live on [0, 1]; p is their even and q their odd reflection, so at x >= 0
H p(x) = H b(x) - H b(-x) and H q(x) = H b(x) + H b(-x) for a basis function b
(``numeric.core.plane_cauchy`` gives H b at x and at -x).

What does not depend on alpha (every Legendre family: the plain elements and the regular families of
the elements at c) is formed once per layout and point set (``PlaneOperators``); the h_beta family at
c and the edge family s^(alpha - 1/2) are formed per alpha, on their rules' parameter-free geometry
(``numeric.core.plane_cauchy.CauchyGeometry``), formed at the first alpha and kept for the next.

The eigenvalue condition is phi(c-) = 0, phi = p - q/mu, the two-dimensional (2.13): without it the
stick side carries (c - x)^(-1/2 - alpha). In the basis phi = a + h_beta(0) b at c- (a: the regular part,
b: the singular family's, h_beta(0) = -1/beta), and the functional is beta phi(c-) cos(theta) =
beta a - b, smooth down to beta = 0 (mu = inf), where it says that the logarithm of p at c- vanishes.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla

from numeric.core.linear_algebra import pin_to_zero
from numeric.core.plane_cauchy import (PLAIN as PLAIN_WEIGHT, CauchyGeometry, Family, cauchy_geometry, family_cauchy,
                                      family_integrals, family_values, legendre01, mode_cauchy)
from numeric.core.plane_charts import (AT_C, EDGE, PLAIN, SLIP, STICK, PlaneLayout, PointSet, collocation_points,
                                       element_families, locate)
from numeric.core.quadrature import gauss_legendre
from numeric.core.stick_pressure_pins import pinned_rows, pins_stick_pressure

MODE_BETA_MIN = 1e-9
"""The generic mode carries the exponent beta - 1 with beta = 1/2 - alpha, but at least this. In the scaling
beta s^(beta - 1) its parts tend to delta functions at c from either side that cancel in q (and p carries
cos(theta) ~ pi beta), so at beta = 0 (mu = inf exactly) the column degenerates; below mu gamma ~ 1e9 it follows the
true exponent (with beta held at 1e-3 instead, the functional near c_max at nu = 0.3 was erratic: a mode of the wrong
exponent). The eigenvalue does not depend on the mode's column (at the root its amplitude is 0), only the smoothness
of G near the root does; the limit mu -> inf is taken by extrapolation (``numeric.solutions.plane_solver``)."""

BALANCE_ALPHA_MAX = 0.25
"""The system is balanced below this basis exponent (mu gamma < 1; ``plane_collocation_system``): beyond, next to
c_max, balancing changed nothing measurable (nu = -1/2, c = 0.9, alpha = 0.39: mu 2e-13 and 1e-13 off degree 28, p and
q at and next to x = c 1e-9 either way; nu = 0, c = 0.97, alpha = 0.23: 3e-14 and 1e-14, 5e-10 and 3e-10), and its LU
of the p block costs ~1 ms a solve at 500-700 unknowns."""
BALANCE_POINT = 1e-3
"""The balancing (T) row's point lies this fraction of the stick end's length before c."""
NEAR_NULL_STEPS = 4
"""Inverse-iteration steps for the normal rows' near-null combination (each gains ~1e-2, the ratio of the two least
singular values of their p block)."""

__all__ = ["MODE_BETA_MIN", "BALANCE_ALPHA_MAX", "BALANCE_POINT", "NEAR_NULL_STEPS", "PlaneOperators", "Transforms",
           "Balance", "near_null_balance", "PlaneCollocationSystem", "plane_collocation_system", "normal_factor",
           "LinearisedPlaneSystem", "PlaneRate", "linearised_system"]


@dataclass(frozen=True, slots=True, eq=False)
class Transforms:
    """Every basis function (columns, layout order, families in order) at the points (rows): H of its even
    reflection, H of its odd reflection, its value (0 off its element), and int_0^1 of each function; and
    the same of the generic mode m = beta s^(beta - 1) on the stick end (``mode_stick``: even, odd, values)
    and on the slip end (``mode_slip``), with its integral over the slip end (``mode_integral``); the mode's parts are
    None where they were not asked for (``PlaneOperators.transforms(alpha, modes=False)``). Its columns are every
    basis function's, or with ``transforms(alpha, varying_only=True)`` those of ``PlaneOperators.varying_columns``."""

    even: np.ndarray
    odd: np.ndarray
    values: np.ndarray
    integrals: np.ndarray
    mode_stick: tuple[np.ndarray, np.ndarray, np.ndarray] | None
    mode_slip: tuple[np.ndarray, np.ndarray, np.ndarray] | None
    mode_integral: float


def _with_balance_point(lay: PlaneLayout, points: PointSet) -> PointSet:
    """``points`` and, after them, the balancing (T) row's point ``BALANCE_POINT`` of the stick end's length before c
    (its offsets formed from 1 - x: next to c = 1 a double x rounds onto c)."""
    before = BALANCE_POINT * float(lay.length[lay.stick_end])
    extra = locate(lay, np.array([lay.c - before]), offset_from_one=np.array([-(lay.gap + before)]))
    return PointSet(*(np.concatenate([getattr(points, name), getattr(extra, name)])
                      for name in ("anchor", "offset", "x", "owner", "s")))


class PlaneOperators:
    """Transforms of every basis function of a layout at a point set (default: the collocation points, and after them
    the balancing (T) row's point, ``BALANCE_POINT`` before c: ``n_collocation`` counts the first).

    ``transforms(alpha)`` fills in the alpha-dependent families; ``columns(e)`` is element e's slice.
    """

    def __init__(self, lay: PlaneLayout, points: PointSet | None = None) -> None:
        self.layout = lay
        if points is None:
            points = collocation_points(lay)
            self.n_collocation = points.size
            points = _with_balance_point(lay, points)
        else:
            self.n_collocation = points.size
        self.points = points
        pts = self.points
        sizes = np.array([lay.n_basis(e) for e in range(len(lay))])
        self.starts = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
        n = int(self.starts[-1])
        N = pts.size
        E = len(lay)
        # chart coordinates y of every point and of its mirror -x with respect to every element
        rel = pts.offset[:, None] - lay.origin[None, :] + np.where(
            pts.anchor[:, None] == lay.anchor[None, :], 0.0, np.where(lay.anchor[None, :] == AT_C, lay.gap, -lay.gap))
        scale = (lay.sigma * lay.length)[None, :]
        self._y = rel / scale
        a = lay.anchor_value(lay.anchor) + lay.origin
        self._y_mirror = -(pts.x[:, None] + a[None, :]) / scale
        self._fixed_even = np.zeros((N, n))
        self._fixed_odd = np.zeros((N, n))
        self._fixed_values = np.zeros((N, n))
        self.integrals_fixed = np.zeros(n)
        # the Legendre family of every element (plain ones whole, the ends' regular part), all elements at once
        d = lay.degree
        has_plain = lay.kind != EDGE
        E_plain = np.flatnonzero(has_plain)
        both = np.concatenate([self._y[:, E_plain], self._y_mirror[:, E_plain]], axis=0)
        I = _legendre_cauchy(both, d)  # (2N, E', d + 1)
        sig = lay.sigma[E_plain][None, :, None] / math.pi
        plus, minus = sig * I[:N], sig * I[N:]
        cols = (self.starts[E_plain][:, None] + np.arange(d + 1)[None, :]).ravel()
        self._fixed_even[:, cols] = (plus - minus).reshape(N, -1)
        self._fixed_odd[:, cols] = (plus + minus).reshape(N, -1)
        fam = element_families(lay, int(E_plain[0]), 0.0)[0]
        self.integrals_fixed[cols] = (lay.length[E_plain][:, None] * family_integrals(fam)[None, :]).ravel()
        owned = np.flatnonzero(np.isin(pts.owner, E_plain))  # every point of a Legendre family, at once
        self._fixed_values[owned[:, None], self.starts[pts.owner[owned]][:, None] + np.arange(d + 1)[None, :]] = \
            family_values(fam, pts.s[owned])
        self._singular = np.flatnonzero(lay.kind != PLAIN)
        # per group of singular elements that carry one family (``transforms``), formed at the first exponent
        self._geometry: dict[tuple[int, ...], CauchyGeometry] = {}

    @cached_property
    def slip_rows(self) -> slice:
        """The points (rows) of the slip elements, the edge one included, one block (the points go element by element
        in layout order): where ``PlaneCollocationSystem.slip_odd`` holds the strain's transforms
        (``numeric.core.plane_fields``)."""
        lay = self.layout
        rows = np.flatnonzero(np.isin(self.points.owner[: self.n_collocation], lay.elements(SLIP)))
        if rows.size == 0:
            return slice(0, 0)
        if not np.array_equal(rows, np.arange(rows[0], rows[-1] + 1)):
            raise ValueError("the slip elements' points are not one block")
        return slice(int(rows[0]), int(rows[-1]) + 1)

    def _chart_points(self, elements: list[int] | tuple[int, ...]) -> np.ndarray:
        """Every point and its mirror in the chart of each element, element after element (2 N values each)."""
        return np.concatenate([np.concatenate([self._y[:, e], self._y_mirror[:, e]]) for e in elements])

    def columns(self, e: int) -> slice:
        return slice(int(self.starts[e]), int(self.starts[e + 1]))

    @cached_property
    def zone_columns(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The basis columns of the stick zone and of the slip zone (layout order), and the stick elements' collocation
        points (read-only: every assembly of this layout takes them)."""
        lay = self.layout
        stick_el, slip_el = lay.elements(STICK), lay.elements(SLIP)
        sc = np.concatenate([np.arange(self.starts[e], self.starts[e + 1]) for e in stick_el])
        lc = np.concatenate([np.arange(self.starts[e], self.starts[e + 1]) for e in slip_el])
        out = (sc, lc, np.flatnonzero(np.isin(self.points.owner[: self.n_collocation], stick_el)))
        for a in out:
            a.setflags(write=False)
        return out

    @cached_property
    def varying_columns(self) -> np.ndarray:
        """The basis columns that depend on the basis exponent (layout order): the h_beta families of the two ends at c
        and the whole edge element; every other column is a Legendre family, the same at every alpha."""
        return np.concatenate([np.arange(self._family_start(int(e)), int(self.starts[e + 1])) for e in self._singular])

    def _family_start(self, e: int) -> int:
        """The first column of singular element e's alpha-dependent family (after the ends' Legendre part)."""
        return int(self.starts[e]) + (0 if self.layout.kind[e] == EDGE else self.layout.degree + 1)

    def transforms(self, alpha: float, modes: bool = True, varying_only: bool = False) -> Transforms:
        """All transforms with the alpha-dependent families (h_beta at c, the edge weight) at exponent alpha; the generic
        mode's only if ``modes`` (the fields leave the mode out); only the columns that depend on alpha
        (``varying_columns``) if ``varying_only`` (the second assembly of a difference quotient in alpha)."""
        lay, pts = self.layout, self.points
        N = pts.size
        held = self.varying_columns if varying_only else None
        if varying_only:
            even, odd, values = np.zeros((N, held.size)), np.zeros((N, held.size)), np.zeros((N, held.size))
            integrals = np.zeros(held.size)
        else:
            even, odd = self._fixed_even.copy(), self._fixed_odd.copy()
            values, integrals = self._fixed_values.copy(), self.integrals_fixed.copy()
        # the singular elements that carry one family (the stick and slip ends share h_beta) in one call of the
        # transforms on all their points and mirrors: its cost is mostly per call, not per point
        groups: dict[Family, list[int]] = {}
        for e in self._singular:
            groups.setdefault(element_families(lay, int(e), alpha)[-1], []).append(int(e))
        for fam, elements in groups.items():
            key = tuple(elements)
            if key not in self._geometry:
                self._geometry[key] = cauchy_geometry(fam.kind, fam.degree, self._chart_points(elements))
            I_all = family_cauchy(fam, self._geometry[key].y, self._geometry[key])
            moments = family_integrals(fam)
            for i, e in enumerate(elements):
                I = I_all[2 * N * i: 2 * N * (i + 1)]
                col = self._family_start(e)
                if held is not None:  # its place among the held columns (each family's columns are consecutive there)
                    col = int(np.searchsorted(held, col))
                sig = lay.sigma[e] / math.pi
                plus, minus = sig * I[:N], sig * I[N:]
                cols = slice(col, col + fam.degree + 1)
                even[:, cols] = plus - minus
                odd[:, cols] = plus + minus
                mine = pts.owner == e
                if np.any(mine):
                    values[mine, cols] = family_values(fam, pts.s[mine])
                integrals[cols] = lay.length[e] * moments
        length = float(lay.length[lay.stick_end + 1])
        if not modes:
            return Transforms(even, odd, values, integrals, None, None, length)
        beta = max(0.5 - alpha, MODE_BETA_MIN)
        ends = (lay.stick_end, lay.stick_end + 1)
        I_all = mode_cauchy(beta, self._chart_points(ends))
        parts = []
        for i, e in enumerate(ends):
            I = I_all[2 * N * i: 2 * N * (i + 1)]
            sig = lay.sigma[e] / math.pi
            plus, minus = sig * I[:N], sig * I[N:]
            mine = pts.owner == e
            value = np.zeros(N)
            value[mine] = beta * pts.s[mine] ** (beta - 1.0)
            parts.append((plus - minus, plus + minus, value))
        return Transforms(even, odd, values, integrals, parts[0], parts[1], length)


#: Point-element pairs farther than this (in element lengths) from the element take Gauss-Legendre: the pole at
#: eta = 2 y - 1 >= 4 gives rho >= 7.9, and (degree/2 + 10) nodes integrate P_k/(s - y) to rho^-20 = 9e-19.
GAUSS_DISTANCE = 1.5


def _legendre_cauchy(y: np.ndarray, degree: int) -> np.ndarray:
    """int_0^1 P_k(2s - 1) ds/(s - y), k <= degree, for an array of y: -2 Q_k(2y - 1) (``plane_cauchy.legendre_q01``)
    where y is within GAUSS_DISTANCE of [0, 1], one Gauss-Legendre rule (a batched product) beyond."""
    s, w = gauss_legendre(degree // 2 + 10)
    s, w = 0.5 * (s + 1.0), 0.5 * w
    out = np.empty(y.shape + (degree + 1,))
    near = (y > -GAUSS_DISTANCE) & (y < 1.0 + GAUSS_DISTANCE)
    out[~near] = (w / (s - y[~near][:, None])) @ legendre01(degree, s)
    if np.any(near):
        out[near] = family_cauchy(Family(PLAIN_WEIGHT, 0.0, degree), y[near])
    return out


def normal_factor(theta: float) -> float:
    """cos(theta), exactly 0 at theta = pi/2 (mu = inf: no pressure on the slip zone)."""
    return 0.0 if theta >= 0.5 * math.pi else math.cos(theta)


@dataclass(frozen=True, slots=True, eq=False)
class Balance:
    """The reflection of the normal rows (N) that isolates their near-null combination, and where it lands.

    ``w``: the unit Householder vector over the N rows (0 at the pins'), I - 2 w w^T taking the near-null combination
    u of those rows (u^T [their p columns] ~ 0) to one row, ``row``, which then holds the balancing (T) equation
    instead (``plane_collocation_system``)."""

    w: np.ndarray
    row: int


def near_null_balance(p_block: np.ndarray, rows: np.ndarray, n_rows: int) -> Balance:
    """The ``Balance`` of the normal rows ``rows`` (of ``n_rows``) from their p columns ``p_block`` (square: the pins'
    rows and columns left out): u by inverse iteration (``NEAR_NULL_STEPS`` steps on the LU of the column-scaled
    block; column scaling does not move a left null vector), the reflection about its largest component."""
    scaled = p_block / np.maximum(p_block.max(axis=0), -p_block.min(axis=0))
    lu = sla.lu_factor(scaled, check_finite=False)
    u = np.ones(rows.size)
    for _ in range(NEAR_NULL_STEPS):
        u = sla.lu_solve(lu, u, trans=1, check_finite=False)
        u /= np.linalg.norm(u)
    k = int(np.argmax(np.abs(u)))
    u[k] += math.copysign(1.0, u[k])
    w = np.zeros(n_rows)
    w[rows] = u / np.linalg.norm(u)
    return Balance(w, int(rows[k]))


def _reflect(arrays: tuple[np.ndarray, ...], balance: Balance) -> None:
    """Apply the balance's reflection to the first rows (the (N) rows) of each array, in place."""
    w = balance.w
    for a in arrays:
        part = a[: w.size]
        part -= np.multiply.outer(2.0 * w, w @ part)


@dataclass(frozen=True, slots=True, eq=False)
class PlaneCollocationSystem:
    """D(theta) = [stick | cos(theta) normal + sin(theta) shear] (+ the mode's stick part in the last column).

    Unknowns z = [p on the stick elements, q on the stick elements, R on the slip elements, a], a the amplitude
    of the generic mode, which is the eigen functional: G(theta) = a."""

    layout: PlaneLayout
    gamma: float
    alpha: float            # the exponent the basis carries
    stick: np.ndarray       # (n, 2 ns): columns of p and q on the stick elements
    normal: np.ndarray      # (n, nl + 1): slip columns (and the mode's slip part) multiplying cos(theta)
    shear: np.ndarray       # (n, nl + 1): ... multiplying sin(theta)
    mode_stick: np.ndarray  # (n,): the mode's stick part (q = m on the stick end)
    rhs: np.ndarray
    stick_columns: np.ndarray  # basis columns (of ``PlaneOperators``) of the stick zone, then of the slip zone
    slip_columns: np.ndarray
    integrals: np.ndarray   # int_0^1 of every basis function (layout order)
    pinned: bool            # whether p's singular family on the stick end is pinned to 0 (``plane_collocation_system``)
    slip_odd: np.ndarray    # H of every basis function's odd reflection (columns, layout order) at the points of
    #                         the slip elements (``PlaneOperators.slip_rows``): the slip's strain
    balance: Balance | None = None  # the normal rows' near-null combination replaced (``plane_collocation_system``)

    @property
    def n_stick(self) -> int:
        return self.stick_columns.size

    def matrix(self, theta: float) -> np.ndarray:
        out = np.concatenate([self.stick, normal_factor(theta) * self.normal + math.sin(theta) * self.shear], axis=1)
        out[:, -1] += self.mode_stick
        return out

    def matrix_derivative(self, theta: float) -> np.ndarray:
        """d D / d theta (zero on the stick columns)."""
        n, ns = self.rhs.size, self.n_stick
        out = np.zeros((n, n))
        out[:, 2 * ns:] = -math.sin(theta) * self.normal + normal_factor(theta) * self.shear
        return out

    def times(self, theta: float, z: np.ndarray) -> np.ndarray:
        """D(theta) z, without forming the matrix."""
        ns2 = 2 * self.n_stick
        slip = z[ns2:]
        return (self.stick @ z[:ns2] + normal_factor(theta) * (self.normal @ slip) + math.sin(theta) * (self.shear @ slip)
                + self.mode_stick * z[-1])

    def derivative_times(self, theta: float, z: np.ndarray) -> np.ndarray:
        """(d D / d theta) z, without forming the matrix."""
        slip = z[2 * self.n_stick:]
        return -math.sin(theta) * (self.normal @ slip) + normal_factor(theta) * (self.shear @ slip)

    def functional(self, theta: float) -> np.ndarray:
        """l with l . z = a, the generic mode's amplitude (0 at the eigenvalue)."""
        out = np.zeros(self.rhs.size)
        out[-1] = 1.0
        return out

    def functional_derivative(self, theta: float) -> np.ndarray:
        return np.zeros(self.rhs.size)


def plane_collocation_system(ops: PlaneOperators, gamma: float, alpha: float) -> PlaneCollocationSystem:
    """Assemble (N) at every collocation point, (T) at the stick points and (P), for basis exponent alpha.

    The generic mode (``asymptotics.derive.plane``: the local solution (c - x)^(-1/2 - alpha) has no p on the
    stick side and p = -gamma cos(pi alpha) q on the slip side) enters as q = m on the stick end and
    R = -gamma m on the slip end (p = R cos(theta)), m = beta s^(beta - 1) (unit integral; the delta function
    at c for mu = inf).

    Nor has the admissible local solution (c - x)^(1/2 - alpha), or any with cot(pi lam) = mu gamma, p on the stick
    side: from alpha = 0.04 on (``numeric.core.stick_pressure_pins.PLANE_PIN_FROM``; the second assembly of a difference
    quotient in alpha takes the first's choice, ``linearised_system``) p's coefficients
    of h_beta on the stick end are pinned to 0 in (N) rows at the stick end's points
    ``numeric.core.stick_pressure_pins.pinned_rows``, as in the axisymmetric system. Left free, they made a near-null
    vector concentrated at c: at nu = 0, c = 0.99 (mu = 3.5, degree 18) the equilibrated
    system's least singular value rose from 2.2e-11 to 7.9e-9 with the pins, mu moved from 2e-12 to 1e-13 of the
    degree-24 solution and p at x = c from 7e-9 to 8e-12 (nu = -1/2, c = 0.93: 3e-10 to 3e-13 in mu, 9e-7 to 1e-11 in
    p). Below alpha = 0.04 they stay free: pinned there, mu between degrees 18 and 24 differed 50 times more at
    nu = 0.45 (2.2e-10 against 4.8e-12 at c = 0.5); between 0.04 and 1/4 (free until this was measured) pinned p at
    x = c came from up to 2.9e-9 to 3.1e-10 of degree 28.

    The system is balanced below ``BALANCE_ALPHA_MAX``. The rows count N (N) + (T) + (P), but the p block of (N) is square
    and nearly singular (H p = 0 has the punch's own solution (1 - x^2)^(-1/2) in the continuum, fixed by (P)): its
    least singular value is ~2e-10 (equilibrated), its left singular vector u a combination of (N) rows that in the
    discrete system only constrains q, through gamma q. As gamma -> 0 that made a near-null vector of the whole system
    (least singular value 3e-11, 7e-12, 4.5e-13 at gamma = 0.29, 0.04, 0.002, c = 1/2; concentrated on the stick shear)
    and the rounding of G absolute in theta, so that mu's relative error grew like 1/gamma^2 (3.4e-9 at nu = 0.489). So
    the (N) rows (less the pins) are reflected (Householder, ``near_null_balance``: u by inverse iteration on the p
    block) to put u's combination in one row, which becomes (T) at one more stick point (``BALANCE_POINT`` of the stick
    end before c; its transforms are the operators' last row): at gamma = 0 the system then falls into two square
    blocks, p from (N) and (P), q and the mode from (T). Measured: the rounding scatter of theta is relative
    (``numeric.core.plane_eigenvalue.theta_rounding``); mu at nu = 0.45 ... 0.489 comes within 1e-10 of the small-gamma
    series (8.7e-11 at c = 0.05); the stresses stay right down to gamma = 1e-8 (levels 2 and 4 within 4e-11 of the
    largest value). Over 22 x 12 (nu, c) in [-0.6, 0.45] x [0.05, 0.6] level 2 lies within 6.4e-11 of the median of
    degrees 26 and 28 in two layouts (the plain system: 5.6e-10 at nu = 0.4, c = 0.05, and 3 points beyond 1e-10), the
    equilibrated condition number's median 5.5e9 (plain 5.9e10). The extra row's place mattered while it lay far from c
    (mu 2.6e-11 off at 0.77 c, 7.5e-13 at 0.1 c, nu = 0.3, c = 1/2; 3e-10 ... 5e-10 at c = 0.05, nu = 0.46, 0.48
    anywhere below 0.6 c): next to c, 5e-11 ... 1e-10 there. The two assemblies of a difference
    quotient share one ``balance`` (the reflection is not smooth in alpha)."""
    lay = ops.layout
    N = ops.n_collocation
    T = ops.transforms(alpha)
    sc, lc, stick_pts = ops.zone_columns
    ns, nl = sc.size, lc.size
    n = N + stick_pts.size + 1
    if n != 2 * ns + nl + 1:
        raise ValueError(f"plane system is {n} x {2 * ns + nl + 1}, not square")
    stick, normal, shear, mode_stick = _blocks(T, gamma, N, stick_pts, sc, lc)
    rhs = np.zeros(n)
    rhs[-1] = 1.0
    pin = pins_stick_pressure(alpha, plane=True)
    slots = pin_rows = np.zeros(0, dtype=int)
    if pin:
        slots, pin_rows = _pins(ops, sc)
        pin_to_zero(stick, slots, pin_rows, (normal, shear, mode_stick, rhs))
    if alpha < BALANCE_ALPHA_MAX:
        rows = np.setdiff1d(np.arange(N), pin_rows)
        p_columns = np.setdiff1d(np.arange(ns), slots)
        p_block = np.concatenate([stick[np.ix_(rows, p_columns)], normal[rows, :nl]], axis=1)
        balance = near_null_balance(p_block, rows, N)
    else:
        balance = None
    if balance is not None:
        _balanced((stick, normal, shear, mode_stick), balance, T, gamma, N, sc, lc, slots)
    return PlaneCollocationSystem(lay, gamma, alpha, stick, normal, shear, mode_stick, rhs, sc, lc, T.integrals, pin,
                                  T.odd[ops.slip_rows], balance)


def _pins(ops: PlaneOperators, sc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The pinned unknowns (p's h_beta columns on the stick end, as places among the stick columns ``sc``) and the (N)
    rows that carry the pins (``plane_collocation_system``)."""
    lay = ops.layout
    e = lay.stick_end
    slots = np.flatnonzero((sc >= ops.starts[e] + lay.degree + 1) & (sc < ops.starts[e + 1]))
    own = np.flatnonzero(ops.points.owner[: ops.n_collocation] == e)  # the stick end's points, from c on
    return slots, own[pinned_rows(own.size, slots.size)]


def _blocks(T: Transforms, gamma: float, N: int, stick_pts: np.ndarray, sc: np.ndarray, lc: np.ndarray
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The stick, normal and shear blocks and the mode's stick column of (N), (T), (P) (``plane_collocation_system``)
    for the basis columns sc (stick zone) and lc (slip zone) of T's arrays, before pins and balance."""
    ns, nl = sc.size, lc.size
    n = N + stick_pts.size + 1
    stick = np.zeros((n, 2 * ns))
    stick[:N, :ns] = T.even[:N, sc]                          # (N): H p (stick part)
    stick[:N, ns:] = gamma * T.values[:N, sc]                #      + gamma q at the stick points
    stick[N:-1, ns:] = T.odd[np.ix_(stick_pts, sc)]         # (T): H q (stick part)
    stick[N:-1, :ns] = -gamma * T.values[np.ix_(stick_pts, sc)]  # - gamma p
    stick[-1, :ns] = 2.0 * T.integrals[sc]                  # (P): int_{-1}^{1} p
    normal = np.zeros((n, nl + 1))
    normal[:N, :nl] = T.even[:N, lc]                         # (N): H p (slip part), p = R cos(theta)
    normal[-1, :nl] = 2.0 * T.integrals[lc]
    shear = np.zeros((n, nl + 1))
    shear[:N, :nl] = T.values[:N, lc]                        # (N): gamma q = R sin(theta) at the slip points
    shear[N:-1, :nl] = T.odd[np.ix_(stick_pts, lc)] / gamma  # (T): H q (slip part), q = R sin(theta)/gamma
    even_l, odd_l, value_l = T.mode_slip                    # the mode on the slip end: R = -gamma m
    normal[:N, -1] = -gamma * even_l[:N]
    normal[-1, -1] = -2.0 * gamma * T.mode_integral
    shear[:N, -1] = -gamma * value_l[:N]
    shear[N:-1, -1] = -odd_l[stick_pts]
    even_s, odd_s, value_s = T.mode_stick                   # on the stick end: q = m
    mode_stick = np.zeros(n)
    mode_stick[:N] = gamma * value_s[:N]
    mode_stick[N:-1] = odd_s[stick_pts]
    return stick, normal, shear, mode_stick


def _balanced(blocks: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray], balance: Balance, T: Transforms,
              gamma: float, N: int, sc: np.ndarray, lc: np.ndarray, slots: np.ndarray) -> None:
    """Apply the balance to the blocks of ``_blocks`` in place: the reflection of the (N) rows (rhs is 0 there), then
    (T) at the balance point (the transforms' row N) in the row it freed; sc, lc: T's columns of the blocks' unknowns,
    ``slots``: the pinned places among sc."""
    stick, normal, shear, mode_stick = blocks
    _reflect(blocks, balance)
    r, ns, nl = balance.row, sc.size, lc.size
    stick[r, :ns] = -gamma * T.values[N, sc]
    stick[r, ns:] = T.odd[N, sc]
    stick[r, slots] = 0.0
    normal[r] = 0.0
    shear[r, :nl] = T.odd[N, lc] / gamma
    shear[r, -1] = -T.mode_slip[1][N]
    mode_stick[r] = T.mode_stick[1][N]


@dataclass(frozen=True, slots=True, eq=False)
class PlaneRate:
    """d/dalpha of a ``PlaneCollocationSystem``'s arrays (a difference quotient of two assemblies), held on the
    columns that depend on alpha (``PlaneOperators.varying_columns``; in every other column the two assemblies are the
    same to the last bit, so their quotient is 0 there): ``stick_columns`` their places in the stick block (p's, then
    q's), ``slip_columns`` in the slip block (the generic mode's, the last, among them), ``basis_columns`` the basis
    columns themselves (of ``integrals`` and ``slip_odd``)."""

    stick_columns: np.ndarray
    slip_columns: np.ndarray
    basis_columns: np.ndarray
    stick: np.ndarray
    normal: np.ndarray
    shear: np.ndarray
    mode_stick: np.ndarray
    integrals: np.ndarray
    slip_odd: np.ndarray

    def times(self, theta: float, z: np.ndarray, n_stick: int) -> np.ndarray:
        """The rate's D(theta) z (``PlaneCollocationSystem.times``) for the unknowns z of a system of ``n_stick``
        stick columns."""
        slip = z[2 * n_stick + self.slip_columns]
        return (self.stick @ z[self.stick_columns] + normal_factor(theta) * (self.normal @ slip)
                + math.sin(theta) * (self.shear @ slip) + self.mode_stick * z[-1])

    def derivative_times(self, theta: float, z: np.ndarray, n_stick: int) -> np.ndarray:
        """The rate's (d D / d theta) z (``PlaneCollocationSystem.derivative_times``)."""
        slip = z[2 * n_stick + self.slip_columns]
        return -math.sin(theta) * (self.normal @ slip) + normal_factor(theta) * (self.shear @ slip)

    def add_to_matrix(self, D: np.ndarray, theta: float, delta: float, n_stick: int) -> None:
        """D += delta x the rate's D(theta) (``PlaneCollocationSystem.matrix``), in place."""
        D[:, self.stick_columns] += delta * self.stick
        D[:, 2 * n_stick + self.slip_columns] += delta * (normal_factor(theta) * self.normal + math.sin(theta) * self.shear)
        D[:, -1] += delta * self.mode_stick


def _combined(base: PlaneCollocationSystem, rate: PlaneRate, delta: float) -> PlaneCollocationSystem:
    """The system whose arrays are base's + delta x rate's (the basis exponent base.alpha + delta, to first order)."""
    stick, normal, shear = base.stick.copy(), base.normal.copy(), base.shear.copy()
    integrals, slip_odd = base.integrals.copy(), base.slip_odd.copy()
    stick[:, rate.stick_columns] += delta * rate.stick
    normal[:, rate.slip_columns] += delta * rate.normal
    shear[:, rate.slip_columns] += delta * rate.shear
    integrals[rate.basis_columns] += delta * rate.integrals
    slip_odd[:, rate.basis_columns] += delta * rate.slip_odd
    return PlaneCollocationSystem(base.layout, base.gamma, base.alpha + delta, stick, normal, shear,
                                  base.mode_stick + delta * rate.mode_stick, base.rhs, base.stick_columns,
                                  base.slip_columns, integrals, base.pinned, slip_odd, base.balance)


@dataclass(frozen=True, slots=True, eq=False)
class LinearisedPlaneSystem:
    """The plane system with its basis exponent following theta, alpha = theta / pi, to first order about alpha0:
    D(theta) = D(theta; alpha0) + (theta/pi - alpha0) dD/dalpha(theta), dD/dalpha a difference quotient of two
    assemblies (``rate``, on the columns that depend on alpha).

    The eigen functional G = a (the generic mode's amplitude) depends on the basis exponent nearly as strongly as on
    theta: at the root, dG/dalpha / pi = -1.005 dG/dtheta at nu = 0.3, c = 0.5 (measured), so Newton at a fixed basis
    lands on a theta that follows the basis, not the eigenvalue. Along alpha = theta/pi, with the first-order term,
    the root of this system is that of the careful iteration to (theta/pi - alpha0) x (the step in alpha) x 44/alpha
    relative (measured at nu = 0.3, c = 0.5), besides rounding. It offers what ``numeric.core.eigenvalue.newton_theta``
    needs (matrix, functional, functional_derivative, derivative_times, rhs), and ``at(theta)``, the system at
    alpha = theta/pi as a ``PlaneCollocationSystem`` (its arrays to first order), for the fields."""

    base: PlaneCollocationSystem
    rate: PlaneRate

    @property
    def rhs(self) -> np.ndarray:
        return self.base.rhs

    def at(self, theta: float) -> PlaneCollocationSystem:
        return _combined(self.base, self.rate, theta / math.pi - self.base.alpha)

    def matrix(self, theta: float) -> np.ndarray:
        """D(theta) at alpha = theta/pi: the base's and delta x the rate's (``at(theta).matrix(theta)``, without the
        combined arrays)."""
        D = self.base.matrix(theta)
        self.rate.add_to_matrix(D, theta, theta / math.pi - self.base.alpha, self.base.n_stick)
        return D

    def derivative_times(self, theta: float, z: np.ndarray) -> np.ndarray:
        """d/dtheta [D(theta; alpha0 + delta) z], delta = theta/pi - alpha0: the theta-derivative at the combined arrays
        and the rate's D z / pi."""
        base, rate, ns = self.base, self.rate, self.base.n_stick
        delta = theta / math.pi - base.alpha
        return (base.derivative_times(theta, z) + delta * rate.derivative_times(theta, z, ns)
                + rate.times(theta, z, ns) / math.pi)

    def functional(self, theta: float) -> np.ndarray:
        return self.base.functional(theta)

    def functional_derivative(self, theta: float) -> np.ndarray:
        return self.base.functional_derivative(theta)


def linearised_system(ops: PlaneOperators, gamma: float, alpha: float, step: float) -> LinearisedPlaneSystem:
    """``LinearisedPlaneSystem`` about alpha from assemblies at alpha and alpha + step, the second only of the columns
    that depend on alpha (``PlaneOperators.varying_columns``), with the first's pins and balance."""
    base = plane_collocation_system(ops, gamma, alpha)
    N = ops.n_collocation
    T = ops.transforms(alpha + step, varying_only=True)
    held = ops.varying_columns
    sc, lc, stick_pts = ops.zone_columns
    p_places, l_places = np.flatnonzero(np.isin(sc, held)), np.flatnonzero(np.isin(lc, held))
    p_held, l_held = np.searchsorted(held, sc[p_places]), np.searchsorted(held, lc[l_places])  # their columns in T
    stick, normal, shear, mode_stick = _blocks(T, gamma, N, stick_pts, p_held, l_held)
    slots = np.zeros(0, dtype=int)
    if base.pinned:  # the first's pins: the same unit rows and columns, so 0 in the quotient
        slots, pin_rows = _pins(ops, sc)
        slots = np.searchsorted(p_places, slots)  # the pinned unknowns are alpha-dependent (h_beta columns)
        pin_to_zero(stick, slots, pin_rows, (normal, shear, mode_stick))
    if base.balance is not None:
        _balanced((stick, normal, shear, mode_stick), base.balance, T, gamma, N, p_held, l_held, slots)
    ns, nl = sc.size, lc.size
    stick_columns = np.concatenate([p_places, ns + p_places])
    slip_columns = np.append(l_places, nl)
    rate = PlaneRate(stick_columns, slip_columns, held, (stick - base.stick[:, stick_columns]) / step,
                     (normal - base.normal[:, slip_columns]) / step, (shear - base.shear[:, slip_columns]) / step,
                     (mode_stick - base.mode_stick) / step, (T.integrals - base.integrals[held]) / step,
                     (T.odd[ops.slip_rows] - base.slip_odd[:, held]) / step)
    return LinearisedPlaneSystem(base, rate)
