"""Power-law profiles in plane strain with friction: the cylinder (n = 2) and |X|^n, from the strip punch.

A profile z = |X|^n / (n b^(n-1)) (the cylinder of radius R: n = 2, b = R) pressed monotonically: every
load increment is a strip punch of the current half-width, so the stick half-width c is that of the strip
punch for every n (the problem is linear in the load at fixed width; [S75] §3's self-similarity in the
plane), and with unit total load

    p(x) = n x^(n-1) int_x^1 t^-n p0(t) dt,      q(x) = n x^(n-1) int_x^1 t^-n q0(t) dt        ([S75] (3.13))

(a superposition of unit strip punches of half-width b with weight n b^(n-1) db). The load-width relation
follows from the slope of the surface outside each strip punch, s0(y) = H p0(y) for |y| > 1:

    (H p + gamma q)(x) = -K sgn(x) |x|^(n-1),   K = (n/pi) int_0^1 p0(t) W_n(t) dt,
    W_n(t) = int_1^inf 2 y^(1-n) dy / (y^2 - t^2) = int_0^1 2 v^(n-1) dv / (1 - t^2 v^2)   (-log(1 - t^2)/t^2 at n = 2),

and the indenter's slope -sgn(X) |X|^(n-1)/b^(n-1) gives P = G a^n / ((1 - nu) K b^(n-1)); frictionless,
K0 = 2/pi at n = 2 (Hertz: P = pi a^2 E* / (4 R), E* = 2 G/(1 - nu)). The indentation depth of a half-plane
is not defined (the displacement grows like log of the distance), so P(a) is the relation reported.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import scalar_or_array
from asymptotics.materials import check_n

from numeric.core.plane_fields import FieldCombination, PlaneField, graded_both_ends, weighted_tail_integrals
from numeric.solutions.plane_law import FullSlipField
from numeric.solutions.plane_punch import StripPunchSolution, points, strip_punch
from numeric.solutions.power_law import N_RANGE

__all__ = ["PlanePowerLawSolution", "plane_power_law", "load_weight", "load_factor_frictionless", "GROUP_SPREAD",
           "X_SMALL", "scale_groups", "power_ratio"]


def load_weight(n: float, t: np.ndarray, u: np.ndarray | None = None) -> np.ndarray:
    """W_n(t) = int_1^inf 2 y^(1-n) dy / (y^2 - t^2) = int_0^1 2 v^(n-1) dv / (1 - t^2 v^2) for 0 <= t < 1.

    W_2 = -log(1 - t^2)/t^2 (1 at t = 0), with 1 - t^2 = u^2 (2 - u^2) from u = sqrt(1 - t) where given (next to
    the edge t would round it); other n: W_2 + int_0^1 2 (v^(n-1) - v) dv/(1 - t^2 v^2), whose integrand is
    bounded at v = t = 1 (the rule graded toward both ends resolves v^(n-1) at 0)."""
    t = np.asarray(t, dtype=float)
    t2 = t * t
    one_minus_t2 = (1.0 - t) * (1.0 + t) if u is None else u * u * (2.0 - u * u)
    with np.errstate(divide="ignore", invalid="ignore"):
        w2 = np.where(t2 > 1e-8, -np.log(one_minus_t2) / np.where(t2 > 1e-8, t2, 1.0), 1.0 + 0.5 * t2)
    if n == 2.0:
        return w2
    v, one_minus_v, wv = graded_both_ends()
    # 1 - t^2 v^2 = (1 - t^2) + t^2 (1 - v)(1 + v), without cancellation at t, v -> 1
    denominator = one_minus_t2[..., None] + t2[..., None] * (one_minus_v * (1.0 + v))[None, :]
    remainder = (2.0 * wv * (v ** (n - 1.0) - v)) / denominator
    return w2 + remainder.sum(axis=-1)


#: Below this x the stresses of (3.13) are taken from their values here and the flat punch's behaviour at the centre
#: (``PlanePowerLawSolution._near_centre``; exact to O(X_SMALL^2) relative): the quadrature resolves x to ~1e-16.
X_SMALL = 1e-12

#: Largest spread (x_max/x_min)^n within one of ``scale_groups``: (x_ref/t)^n then underflows only where (x/t)^n is
#: below 1e-208 (against terms of order 1), and (x/x_ref)^n stays finite.
GROUP_SPREAD = 1e100


def scale_groups(x: np.ndarray, n: float) -> list[tuple[np.ndarray, float]]:
    """Indices of the points 0 < x <= 1 in groups over which (x/x_ref)^n <= GROUP_SPREAD, with x_ref each group's
    smallest x: the weights t^-n of the integrals of (3.13) are taken as (x_ref/t)^n <= 1 (no overflow)."""
    logs = np.log(x)
    bins = np.floor(n * (logs - logs.min()) / math.log(GROUP_SPREAD)).astype(int)
    return [(np.flatnonzero(bins == b), float(x[bins == b].min())) for b in np.unique(bins)]


def power_ratio(a: np.ndarray | float, b: np.ndarray | float, n: float) -> np.ndarray:
    """(a/b)^n: a^n / b^n where both are normal doubles (to a few ulp), else exp(n (log a - log b)) (to |n log(a/b)|
    ulp), its exponent capped at 700 (a <= b inside the integrals; elsewhere the value is not used)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    log_a, log_b = np.log(a), np.log(b)
    direct = (np.abs(n * log_a) < 700.0) & (np.abs(n * log_b) < 700.0)
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        return np.where(direct, a**n / b**n, np.exp(np.minimum(n * (log_a - log_b), 700.0)))


def _edge_rule(x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes t, u = sqrt(1 - t) and weights g (rows: one rule per x) for int_x^1 f(t) dt with f ~ (1 - t)^(-1/2):
    t = 1 - u^2 = (1 - u)(1 + u), u in [0, sqrt(1 - x)], dt = 2 u du, by the rule graded toward both ends
    (``numeric.core.plane_fields.graded_both_ends``: the oscillation (1 - t)^(i eps) of the full-stick punch at
    u = 0, t^-n near x = 0 at the other end)."""
    s, one_minus_s, w = graded_both_ends()
    top = np.sqrt(1.0 - x)
    u = top[:, None] * s[None, :]
    one_minus_u = (x / (1.0 + top))[:, None] + top[:, None] * one_minus_s[None, :]  # 1 - top = x / (1 + top)
    return one_minus_u * (1.0 + u), u, 2.0 * u * w[None, :] * top[:, None]


def load_factor_frictionless(n: float) -> float:
    """K0 = (n/pi) int_0^1 p_S(t) W_n(t) dt for Sadowsky's p_S = 1/(pi sqrt(1 - t^2)) (2/pi at n = 2)."""
    t, u, g = _edge_rule(np.zeros(1))
    return float((n / math.pi) * np.sum(g / (math.pi * u * np.sqrt(2.0 - u * u)) * load_weight(n, t, u)))


@dataclass(frozen=True, slots=True)
class PlanePowerLawSolution:
    """A profile |X|^n / (n b^(n-1)) (n = 2: the cylinder, b = R) with friction, from the strip punch ``flat``.

    ``pressure``, ``shear``: (3.13) in the plane, unit load; ``load_factor`` K with P = G a^n / ((1 - nu) K b^(n-1));
    ``load_ratio`` = K0/K, the load over the frictionless one at the same half-width a.
    """

    n: float
    flat: StripPunchSolution
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def c(self) -> float:
        return self.flat.c

    @property
    def mu(self) -> float:
        return self.flat.mu

    @property
    def gamma(self) -> float:
        return self.flat.gamma

    def _scaled_tails(self, ax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """n x^(n-1) int_x^1 t^-n (p0, q0) dt at 0 < x < 1, as (n/x) (x/x_ref)^n int_x^1 (x_ref/t)^n (p0, q0) dt over
        ``scale_groups`` (t^-n itself overflowed below x = exp(-709/n): NaN at x = 1e-3 for n = 100)."""
        f = self.flat.field
        n = self.n
        p, q = np.zeros(ax.shape), np.zeros(ax.shape)
        for group, ref in scale_groups(ax, n):
            def weight(t: np.ndarray, one_minus_t: np.ndarray, ref: float = ref) -> np.ndarray:
                return power_ratio(ref, t, n)
            if isinstance(f, PlaneField):
                tp, tq = weighted_tail_integrals(f, ax[group], weight)
            elif isinstance(f, FieldCombination):
                tp, tq = f.tail_integrals(ax[group], weight)
            else:
                t, u, g = _edge_rule(ax[group])  # closed-form flat punch: t = 1 - u^2 on [x, 1]
                pe, qe = f.edge_pressure_shear(u, t)
                g = g * weight(t, u * u)
                tp, tq = (g * pe).sum(axis=1), (g * qe).sum(axis=1)
            scale = (n / ax[group]) * power_ratio(ax[group], ref, n)
            p[group], q[group] = scale * tp, scale * tq
        return p, q

    def _near_centre(self, ax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p and q at 0 < x < X_SMALL from their values at x_s = X_SMALL: there the flat punch's f0 (p0 or q0) is
        f0(x_s) (t/x_s)^lam to O(x_s^2) (lam = 0 for p0, 1 for q0, even and odd and analytic at 0; -2 alpha for both on
        the full-slip route, ``FullSlipField``), so f(x) = f(x_s) r^(n-1) + n f0(x_s) r^lam (1 - r^m)/m, r = x/x_s,
        m = n - 1 - lam (-log r at m = 0). The quadrature of (3.13) resolves x down to ~1e-16 only (at x = 1e-20 it
        was 1e-5 ... 2e-3 off for n = 2 ... 10, and 0 at x = 1e-300)."""
        n = self.n
        xs = np.array([X_SMALL])
        ps, qs = self._scaled_tails(xs)
        f = self.flat.field
        slip_everywhere = isinstance(f, FullSlipField)
        p0, q0 = f.pressure_shear(xs)
        log_r = np.log(ax / X_SMALL)
        out = []
        for value, flat, lam in ((ps[0], p0[0], -2.0 * f.alpha if slip_everywhere else 0.0),
                                 (qs[0], q0[0], -2.0 * f.alpha if slip_everywhere else 1.0)):
            m = n - 1.0 - lam
            if m == 0.0:
                term = -log_r * np.exp(lam * log_r)
            else:  # r^lam (1 - r^m)/m; where r^m would overflow (n < 1), (r^lam - r^(n-1))/m has no cancellation
                e = m * log_r
                term = np.where(e < 700.0, -np.expm1(np.minimum(e, 700.0)) / m * np.exp(lam * log_r),
                                (np.exp(lam * log_r) - np.exp(np.minimum((n - 1.0) * log_r, 700.0))) / m)
            out.append(value * np.exp((n - 1.0) * log_r) + n * flat * term)
        return out[0], out[1]

    def _fields(self, x: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        x_arr = points(x)
        ax = np.abs(x_arr).ravel()
        n = self.n
        if isinstance(self.flat.field, FullSlipField):  # below the solver's smallest c: |x| >= 100 c only
            self.flat.field.check(ax)
        p, q = np.zeros(ax.shape), np.zeros(ax.shape)
        inside = (ax >= X_SMALL) & (ax < 1.0)
        if np.any(inside):
            p[inside], q[inside] = self._scaled_tails(ax[inside])
        small = (ax > 0.0) & (ax < X_SMALL)
        if np.any(small):
            p[small], q[small] = self._near_centre(ax[small])
        centre = ax == 0.0
        if np.any(centre):  # x -> 0: n x^(n-1) int_x^1 t^-n p0 -> n p0(0)/(n - 1) (n > 1), [S75] (3.18)
            p0 = float(np.asarray(self.flat.pressure(0.0)))
            p[centre] = n / (n - 1.0) * p0 if n > 1.0 else math.inf
        return p.reshape(x_arr.shape), (np.sign(x_arr).ravel() * q).reshape(x_arr.shape)

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """p(x) = n x^(n-1) int_x^1 t^-n p0(t) dt, int p = 1 (0 at the edges for n > 0)."""
        return scalar_or_array(self._fields(x)[0])

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """q(x) = n x^(n-1) int_x^1 t^-n q0(t) dt (odd, + outward on the half-plane)."""
        return scalar_or_array(self._fields(x)[1])

    def slip(self, x: ArrayLike) -> np.ndarray | float:
        """u(x) = u_x G / ((1 - nu) P), P the present load, accumulated over the loading (odd, inward): each point
        slipped while the stick-slip point grew past it, so the stick zone keeps u = C x^n ([S75] (3.4), (3.15) in
        the plane): u = n x^n int_max(c, x)^1 t^(-n-1) u0(t) dt, u0 the strip punch's slip. On the solver's field by
        parts, x^n [(x'^-n - 1) u0(x') + int_x'^1 (t^-n - 1) u0'(t) dt], x' = max(c, |x|), so that the strain u0' is
        integrated once; on the closed forms (Sadowsky's u0 = -(gamma/pi) asin t, Abramov's 0) directly."""
        x_arr = points(x)
        ax = np.abs(x_arr).ravel()
        f = self.flat.field
        if isinstance(f, FullSlipField):
            f.slip(ax)  # raises: not computed below the solver's smallest c
        out = np.zeros(ax.shape)
        inside = ax > 0.0
        if np.any(inside):
            if isinstance(f, FieldCombination):
                f.check(ax)
                out[inside] = sum(w * self._accumulated(g, ax[inside]) for g, w in zip(f.fields, f.weights))
            elif isinstance(f, PlaneField):
                out[inside] = self._accumulated(f, ax[inside])
            else:
                t, _, g = _edge_rule(ax[inside])
                t = np.minimum(t, 1.0)  # (1 - u)(1 + u) may round a few ulp above 1 where u -> 0
                weight = power_ratio(ax[inside][:, None], t, self.n) / t  # x^n t^(-n-1), as (x/t)^n / t
                out[inside] = self.n * (g * weight * f.slip(t)).sum(axis=1)
        return scalar_or_array((np.sign(x_arr).ravel() * out).reshape(x_arr.shape))

    def _accumulated(self, f: PlaneField, ax: np.ndarray) -> np.ndarray:
        """n |x|^n int_x'^1 t^(-n-1) u0 dt on the solver's field, by parts (see ``slip``): x^n (t^-n - 1) as
        (x/x_ref)^n ((x_ref/t)^n - x_ref^n) over ``scale_groups`` of x' = max(x, c), which t^-n overflowed."""
        n = self.n
        lo = np.maximum(ax, f.c)
        out = np.zeros(ax.shape)
        for group, ref in scale_groups(lo, n):
            def weight(t: np.ndarray, one_minus_t: np.ndarray, ref: float = ref) -> np.ndarray:
                return power_ratio(ref, t, n) - ref**n
            tail = f.tail_strain_integrals(lo[group], weight)
            at_lo = power_ratio(ax[group], lo[group], n) - ax[group] ** n
            out[group] = at_lo * f.slip(lo[group]) + power_ratio(ax[group], ref, n) * tail
        return out

    @property
    def load_factor(self) -> float:
        """K = (n/pi) int_0^1 p0 W_n: P = G a^n / ((1 - nu) K b^(n-1)) (2/pi frictionless at n = 2)."""
        if "K" not in self._cache:
            self._cache["K"] = self._load_factor()
        return self._cache["K"]

    def _load_factor(self) -> float:
        f = self.flat.field
        if isinstance(f, (PlaneField, FieldCombination)):
            tails = weighted_tail_integrals if isinstance(f, PlaneField) else type(f).tail_integrals
            tail, _ = tails(f, np.array([1e-300]), lambda t, one_minus_t: load_weight(self.n, t, np.sqrt(one_minus_t)))
            return float(self.n / math.pi * tail[0])
        t, u, g = _edge_rule(np.zeros(1))
        p, _ = f.edge_pressure_shear(u, t)
        return float(self.n / math.pi * np.sum(g * p * load_weight(self.n, t, u)))

    @property
    def load_ratio(self) -> float:
        """P with friction over P frictionless at the same half-width (K0/K)."""
        return load_factor_frictionless(self.n) / self.load_factor


def plane_power_law(n: float, *, nu: float | None = None, gamma: float | None = None, mu: float | None = None,
                    c: float | None = None, level: int | None = None, rtol: float | None = None
                    ) -> PlanePowerLawSolution:
    """Profile |X|^n (n = 2: the cylinder) with friction: the same c as the strip punch (exactly one of mu, c), whose
    ``level`` (default 2) or ``rtol`` (on mu or c, ``strip_punch``) it takes; 1e-300 <= n <= 100, the axisymmetric
    ``numeric.power_law``'s range (``numeric.solutions.power_law.N_RANGE``: ValueError outside; n = 1000 gave NaN
    here, n = 1e300 a negative load ratio).

    >>> h = plane_power_law(2, nu=0.3, mu=0.0)
    >>> round(float(h.pressure(0.6)), 12) == round(1.6 / math.pi, 12)   # Hertz: (2/pi) sqrt(1 - x^2)
    True
    """
    n_value = check_n(n)
    if not N_RANGE[0] <= n_value <= N_RANGE[1]:
        raise ValueError(f"n (power-law exponent) must lie in [{N_RANGE[0]:g}, {N_RANGE[1]:g}] (the axisymmetric "
                         "power_law's N_RANGE: beyond 100 the indenter is a flat punch, use flat_punch), got "
                         f"{n!r}")
    return PlanePowerLawSolution(n_value, strip_punch(nu=nu, gamma=gamma, mu=mu, c=c, level=level, rtol=rtol))
