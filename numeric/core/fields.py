"""Stresses, slip and compliance of a flat-punch solution on the singular basis ([S75] (2.1), (2.4), (2.10)).

p and q are evaluated from the basis, so their singular behaviour at x = c and x = 1 is
exact: there is no interpolation between nodes and no loss at x = c itself or at 1 - x = 1e-5.
At x = c itself, where the layer of s^beta at c is resolved, p is taken from the stick side (its value there is
the regular part alone; on the slip side two terms of ~1/beta cancel) and q = mu p.

The slip u of (2.10) is (2/(pi x)) times the lower Abel integral of u* over (c, x); u* is
known at the slip collocation points from (2.2b) and interpolated in the slip elements'
basis, which carries the behaviour of u* at both ends (one Abel order smoother than p).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from functools import cached_property, lru_cache

import numpy as np

from numeric.core.charts import (AT_C2, AT_ONE, EDGE, PLAIN, SLIP, SLIP_END, STICK, STICK_END, Layout, basis_values,
                                 chart_of_offset, collocation_chart, shifted_legendre)
from numeric.core.eigenvalue import Eigensolution
from numeric.core.operators import AbelOperators, normal_factor, stick_end_rows

__all__ = ["SingularField", "TabulatedField", "point_offsets"]


def point_offsets(lay: Layout, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Anchor codes and offsets of points x in [0, 1]: from c^2 up to the middle of the slip zone, else from 1."""
    x = np.asarray(x, dtype=float)
    to_one = x > 0.5 * (lay.c + 1.0)
    anchor = np.where(to_one, AT_ONE, AT_C2)
    offset = np.where(to_one, -(1.0 - x) * (1.0 + x), (x - lay.c) * (x + lay.c))
    return anchor, offset


#: ``SingularField.slip`` leaves out the slip elements that start more than this above the largest point in u = x^2
#: (their integrals over t < x are 0; the margin keeps any element that rounding of u could put on the other side).
SLIP_MARGIN = 1e-12

#: ``SingularField`` keeps the basis at the last point set of each zone only up to this many points (a plot's or a
#: quadrature's many points would hold n_basis values each).
KEPT_POINTS = 1024


@lru_cache(maxsize=None)
def _collocation_legendre(kind: int, n: int, degree: int) -> np.ndarray:
    """Shifted Legendre values at the n collocation points of an element of this kind, (n, degree + 1)."""
    values = shifted_legendre(degree, collocation_chart(kind, n))
    values.setflags(write=False)
    return values


class SingularField:
    """p, q, u and P* of an ``Eigensolution`` (theta = atan(mu gamma))."""

    def __init__(self, solution: Eigensolution) -> None:
        self.solution = solution
        sys = solution.system
        self._adopt(sys.layout, sys.gamma, solution.theta, sys.alpha, solution.coefficients, sys.end_row)
        ns = sys.n_stick
        self.compliance = float(0.25 * math.pi * (sys.integral[:ns] @ self._P
                                                 + normal_factor(self.theta) * (sys.integral[ns:] @ self._R)))  # (2.4)

    def _adopt(self, layout: Layout, gamma: float, theta: float, alpha: float, coefficients: np.ndarray,
               end_row: np.ndarray) -> None:
        self.layout = layout
        self.gamma = gamma
        self.theta = theta
        self.alpha = alpha
        self.c = layout.c
        self.gap = layout.gap  # 1 - c, formed without cancellation
        self.n_unknowns = coefficients.size
        self._kept: dict[int, tuple[bytes, list]] = {}  # the last points' basis per zone (``_basis_at``)
        ns = layout.n_stick
        self._P, self._Q, self._R = coefficients[:ns], coefficients[ns:2 * ns], coefficients[2 * ns:]
        self._end_row = end_row
        self._friction: float | None = None  # mu where it is known better than tan(theta)/gamma (``with_friction``)
        self._normal = normal_factor(theta)  # cos(theta): p = R cos(theta) on the slip annulus

    @property
    def mu(self) -> float:
        if self._friction is not None:
            return self._friction
        return math.inf if self.theta >= 0.5 * math.pi else math.tan(self.theta) / self.gamma

    def with_friction(self, mu: float) -> "SingularField":
        """The same solution for the friction mu it was solved at (theta = atan(mu gamma)), with cos(theta) =
        1/hypot(1, mu gamma) from mu itself: from theta it carries theta's rounding over pi/2 - theta, relative 1e-16
        mu gamma (1e-6 at mu gamma = 1e10; at mu gamma >= 1e16 theta is pi/2 and p on the annulus was 0 where q was
        not). The stresses on the slip annulus use it; nothing else changes."""
        out = object.__new__(type(self))
        out.__dict__.update(self.__dict__)
        out._kept = {}
        out._friction = mu
        out._normal = 1.0 / math.hypot(1.0, mu * self.gamma)
        return out

    @cached_property
    def breakpoints(self) -> np.ndarray:
        """Element ends in x, with points graded geometrically (ratio 1/4) toward c and 1 between which
        p and q are smooth enough for composite quadrature (the power-law transforms)."""
        lay = self.layout
        c = lay.c
        k = 0.25 ** np.arange(1, 26)
        sign = np.where((lay.kind == PLAIN) | (lay.kind == SLIP_END), 1.0, -1.0)
        anchor = np.where(lay.anchor == AT_C2, lay.c2, 1.0)
        ends = np.sqrt(np.clip(anchor[:, None] + sign[:, None] * np.stack([lay.lo, lay.hi], axis=1), 0.0, None)).ravel()
        points = np.concatenate([ends, [0.0, c, 1.0], c * (1.0 - k), c + lay.gap * k, 1.0 - lay.gap * k])
        points = np.unique(np.clip(points, 0.0, 1.0))
        points.setflags(write=False)
        return points

    def edge_value(self, shear: bool) -> float:
        """p and q at x = 1: infinite, (1 - x)^(alpha - 1/2); at mu = inf p = 0 there and q is bounded."""
        return math.inf

    def _evaluate(self, x: np.ndarray, zone: int, coefficients: np.ndarray) -> np.ndarray:
        """Sum of the basis of the elements of ``zone`` at points x (which must lie in that zone)."""
        out = np.zeros(x.shape)
        base = 0 if zone == STICK else self.layout.n_stick
        for rows, first, last, values in self._basis_at(x, zone):
            out[rows] = values @ coefficients[first - base: last - base]
        return out

    def _basis_at(self, x: np.ndarray, zone: int) -> list[tuple[np.ndarray, int, int, np.ndarray]]:
        """Per element of ``zone`` holding some of the points x: their rows, the element's unknowns (first, last)
        and its basis there. The last point set of each zone is kept: p and q at the same points (``pressure``,
        ``shear``) tabulate the basis once."""
        key = x.tobytes() if x.size <= KEPT_POINTS else None
        kept = self._kept.get(zone)
        if key is not None and kept is not None and kept[0] == key:
            return kept[1]
        lay = self.layout
        parts = []
        if x.size:
            anchor, offset = point_offsets(lay, x)
            elements = np.flatnonzero(lay.zone == zone)
            ae = lay.anchor[elements]
            off = offset[:, None] + np.where(anchor[:, None] == ae[None, :], 0.0,
                                             np.where(ae == AT_C2, lay.w, -lay.w)[None, :])  # offsets from each A_e
            kind = lay.kind[elements]
            lo = np.where(kind == PLAIN, lay.lo[elements], np.where(kind == SLIP_END, 0.0, -lay.hi[elements]))
            hi = np.where(kind == PLAIN, lay.hi[elements], np.where(kind == SLIP_END, lay.hi[elements], 0.0))
            which = np.argmax((off >= lo[None, :]) & (off <= hi[None, :]), axis=1)  # the first element holding the point
            for k in np.unique(which):
                e = int(elements[k])
                rows = np.flatnonzero(which == k)
                s = chart_of_offset(lay, e, off[rows, k])
                if lay.kind[e] == SLIP_END or lay.kind[e] == STICK_END:
                    s = self._off_the_layer(e, s)
                parts.append((rows, int(lay.starts[e]), int(lay.starts[e + 1]), basis_values(lay, e, s, self.alpha)))
        if key is not None:
            self._kept[zone] = (key, parts)
        return parts

    def _off_the_layer(self, e: int, s: np.ndarray) -> np.ndarray:
        """Chart points s of an element at c, with s = 0 (x = c itself) moved to the nearest double x on the
        element's side when the layer of s^beta at c is thinner than that distance.

        Near c the fields are A(s) + s^beta B(s) (``numeric.core.charts``), in the basis a + b h_beta(s): at
        s = 0 exactly, h_beta = -1/beta, while at the nearest double x != c (s_near ~ 1e-8 ... 1e-4) it is
        still ~log s_near as long as s_near^beta is near 1. For such beta (mu gamma above ~20 at the largest
        s_near) s^beta falls from ~1 to 0 in a layer narrower than one unit in the last place of c: the value
        at c is a spike of height ~b/beta that no other double sees (q(c) = mu p(c), 1e300 at mu = 1e300;
        -inf - inf = nan at beta = 0), computed with the rounding of b amplified by 1/beta. A quadrature node
        that rounds onto c stands for its neighbourhood, not for the spike (it made the power-law constants
        drift like 1e-16 mu gamma, ``numeric.solutions.power_law``), so there the value at the nearest double
        is returned: the one-sided limit over the doubles. Where the layer is resolved (s_near^beta < 1/2)
        the value at c is kept.
        """
        at_c = s == 0.0
        if not np.any(at_c):
            return s
        lay = self.layout
        beta = 1.0 - 2.0 * self.alpha
        near = np.nextafter(lay.c, 2.0 if lay.kind[e] == SLIP_END else 0.0)
        s_near = float(chart_of_offset(lay, e, np.array((near - lay.c) * (near + lay.c))))
        if not (s_near > 0.0 and beta * math.log(s_near) >= -math.log(2.0)):
            return s
        return np.where(at_c, s_near, s)

    @cached_property
    def _pressure_at_c(self) -> float | None:
        """p(c) from the stick side, where the slip side's layer at c is resolved (``_off_the_layer`` keeps the value
        at c), else None.

        There p is continuous at c (A(s) + s^beta B(s) on either side, beta > 0) and its value is the stick pressure's
        regular part at s = 0, while on the slip side it is a_R + h_beta(0) b_R with h_beta(0) = -1/beta: two terms
        of ~1/beta that cancel, their rounding amplified by 1/beta. Measured against level 4 at 1 - c = 1.001 ... 100
        (1 - c_max), nu in {-0.9, -1/2, 0, 0.3}: level 2's p and q at c were off by up to 1.2e-9 from the slip side
        (nu = 0.3, 1 - c = 1.2 (1 - c_max)), 3.0e-10 from the stick side where the layer is resolved."""
        e = self.layout.stick_end + 1  # the slip end
        if self._off_the_layer(e, np.zeros(1))[0] != 0.0:
            return None
        return float(self._end_row @ self._P)  # P(c-), the eigenvalue condition's own

    def pressure(self, x: np.ndarray) -> np.ndarray:
        """p(x), 0 <= x < 1 (infinite at x = 1 for 0 <= mu < inf)."""
        x = np.asarray(x, dtype=float)
        stick = x < self.layout.c
        out = np.empty(x.shape)
        out[stick] = self._evaluate(x[stick], STICK, self._P)
        out[~stick] = self._normal * self._evaluate(x[~stick], SLIP, self._R)
        at_c = x == self.c
        if at_c.any() and self._pressure_at_c is not None:
            out[at_c] = self._pressure_at_c
        return out

    def shear(self, x: np.ndarray) -> np.ndarray:
        """q(x) = x Q in the stick zone, mu p = R sin(theta)/gamma in the slip annulus."""
        x = np.asarray(x, dtype=float)
        stick = x < self.layout.c
        out = np.empty(x.shape)
        out[stick] = x[stick] * self._evaluate(x[stick], STICK, self._Q)
        slip = self._evaluate(x[~stick], SLIP, self._R)
        # q = mu p (2.6b) as the product, so that it holds to the last bit; R/gamma at mu = inf
        out[~stick] = (self.mu * (self._normal * slip) if self.mu < math.inf
                       else slip / self.gamma)
        at_c = x == self.c
        if at_c.any() and self._pressure_at_c is not None:  # q(c) = mu p(c), p(c) from the stick side
            out[at_c] = self.mu * self._pressure_at_c
        return out

    @cached_property
    def u_star_values(self) -> np.ndarray:
        """u* of (2.2b) at the slip collocation points (the slip's source)."""
        return self.solution.system.u_star(self.theta, self.solution.coefficients)

    @cached_property
    def u_star_coefficients(self) -> np.ndarray:
        """u* interpolated at the slip collocation points in each slip element's basis."""
        lay = self.layout
        values = self.u_star_values
        ns = lay.n_stick
        out = np.empty(values.size)
        slip = np.flatnonzero(lay.zone == SLIP)
        plain = slip[lay.kind[slip] == PLAIN]
        if plain.size:  # one interpolation matrix for every plain element (Legendre values at the Gauss points)
            m = int(lay.n_basis[plain[0]])
            rows = (lay.starts[plain][:, None] - ns + np.arange(m)[None, :])
            out[rows] = np.linalg.solve(_collocation_legendre(PLAIN, m, int(lay.degree[plain[0]])), values[rows].T).T
        for e in slip[lay.kind[slip] != PLAIN]:
            kind, m = int(lay.kind[e]), int(lay.n_basis[e])
            rows = slice(int(lay.starts[e]) - ns, int(lay.starts[e + 1]) - ns)
            B = basis_values(lay, e, collocation_chart(kind, m), self.alpha,
                             legendre=_collocation_legendre(kind, m, int(lay.degree[e])), displacement=True)
            out[rows] = np.linalg.solve(B, values[rows])
        return out

    def slip(self, x: np.ndarray) -> np.ndarray:
        """u(x) = (2/(pi x)) int_c^x t u*(t) dt / sqrt(x^2 - t^2) (2.10): 0 on the stick zone, < 0 in the annulus."""
        x = np.asarray(x, dtype=float)
        out = np.zeros(x.shape)
        outer = x > self.layout.c
        if not np.any(outer):
            return out
        lay = self.layout
        xs = x[outer]
        # the integral runs over c < t < x: the slip elements starting above the largest point (by more than
        # SLIP_MARGIN, far beyond the rounding of u) give 0 and are left out
        start = np.where(lay.anchor == AT_C2, lay.c2, 1.0) + np.where(lay.kind == EDGE, -lay.hi, lay.lo)
        ops = AbelOperators(lay, point_offsets(lay, xs), names=("lower",),
                            elements=np.flatnonzero((lay.zone == SLIP) & (start < xs.max() ** 2 + SLIP_MARGIN)),
                            divided=False)
        total = ops.matrices(self.alpha, displacement=True).lower[:, lay.n_stick:] @ self.u_star_coefficients
        out[outer] = (2.0 / math.pi) * total / xs
        return out


class TabulatedField(SingularField):
    """The fields of stored values (``numeric.core.field_table``): a layout, theta, the basis exponent alpha,
    the coefficients of P, Q and R, u* (the slip's source) at the slip collocation points and P* given; no system
    is formed."""

    def __init__(self, layout: Layout, gamma: float, theta: float, alpha: float, coefficients: np.ndarray,
                 u_star_values: np.ndarray, compliance: float) -> None:
        self.solution = None
        self._adopt(layout, gamma, theta, alpha, coefficients, stick_end_rows(layout)[0])
        self.u_star_values = u_star_values
        self.compliance = compliance
