"""Power-law indenters z ~ r^n from the flat-punch solution, [S75] §3.

A body of shape z = r^n/(n b^(n-1)) (n = 2 sphere, n = 1 cone) pressed in monotonically
has the same stick radius c as the flat punch, and its surface stresses follow from the
flat-punch stresses p0, q0 by the quadrature (3.13),

    p(x) = n x^(n-1) int_x^1 t^(-n) p0(t) dt,   q(x) = n x^(n-1) int_x^1 t^(-n) q0(t) dt.

The indentation constant A (delta = A a^n / b^(n-1), (3.2)) comes from (3.5a) at x = 1,
where the Abel term vanishes because p(1) = 0 (3.7):

    A* = 1 + gamma int_0^1 q(t) (1 - (1 - t^2)^(-1/2)) dt
       = 1 + gamma int_0^1 q0(s) s^(-n) W_n(s) ds,                              (*)
    W_n(s) = int_0^s n t^(n-1) (1 - (1 - t^2)^(-1/2)) dt = s^n - (n/2) B(s^2; n/2, 1/2),

(the second line by (3.13) and a swap of the order of integration), with
A = B(n/2, 1/2) / (2 A*) from (3.5). ``indentation_constant_316`` takes the paper's route
(3.16) instead; the two are compared in the tests.

(3.16) as printed is correct for every mu: multiplying (3.5a) by (2/pi)(1 - x^2)^(-1/2)
and integrating, the gamma terms give gamma (int q - int q) = 0, since
(2/pi) int_0^1 (1 - x^2)^(-1/2) dx = 1 and (2/pi) int_t^1 x dx / sqrt((1 - x^2)(x^2 - t^2)) = 1.
The right-hand side is 1 - A* B((n+1)/2, 1/2)/pi = 1 - 1/(n A). Frictionless checks:
A = 1 for the sphere and A = pi/2 for the cone (A* = 1).

The displacement constant C (u = C x^n in the stick zone, (3.4)) is (3.5b) at a point
0 < x < c: C* x^n = x int_x^1 q dt / sqrt(t^2 - x^2) - gamma int_0^x t p dt / sqrt(x^2 - t^2),
C* = Gamma((n+3)/2) Gamma(1/2) / Gamma(1 + n/2) C.

Numerical method
----------------
All integrals are composite Gauss-Legendre (30 nodes, ``numeric.core.quadrature``) on the
flat solution's breakpoints, with every piece [a, b], a > 0, split geometrically so that b <= 2a (this
resolves t^(-n) and keeps each piece well inside the region of analyticity). Values of
int_x^1 t^(-n) f dt at many points are obtained at once: the points are merged into the
breakpoints, every piece is integrated, and reverse cumulative sums are taken.

Two details matter near the edge x = 1, where p0, q0 ~ (1 - x)^(alpha - 1/2):

* Near 1 a double t resolves 1 - t only to 1.1e-16 absolutely, so Gauss nodes would be
  displaced by up to 5e-4 relative to 1 - t at 1 - t = 1e-13. Pieces with a >= 1/2 are
  therefore built in s = 1 - t: each node is rounded to a double t, its exact
  s = 1 - t (Sterbenz) is recovered, and interpolatory weights are solved for the rounded
  nodes.
* The flat solution is sampled only on [0, x_e], x_e = 1 - s_e with s_e in [1e-13, 4e-13)
  (``EDGE_GAP``; the last breakpoint that far from 1, graded further by factors of 4 if
  needed). On (x_e, 1) the local edge form is fitted to the samples at s_e and 4 s_e and
  integrated exactly: K s^(alpha - 1/2), tan(pi alpha) = mu gamma, in the slip annulus, or
  s^(-1/2) Re[K s^(i kappa/2)] (log-periodic) when the edge sticks (1 - c < s_e: c = 1, mu = inf;
  not the slip limit mu = inf, c = c_max, whose annulus keeps alpha = 1/2)
  (reformulation.md, structure of the solution). The neglected next order is O(s_e)
  absolutely, about 1e-13.
* Near x = c, for large mu gamma, the fields carry a layer of s^beta (beta = 1 - 2 alpha)
  narrower than one unit in the last place of c; the flat solution returns at a node that rounds
  onto c the value at the nearest double (``numeric.core.fields``), not the spike q(c) = mu p(c)
  of that layer, which made A and C drift like 1e-16 mu gamma (nan at mu gamma > 1e16).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike
from scipy import special

from asymptotics.arrays import scalar_or_array
from asymptotics.materials import GAMMA_MAX, check_n, check_x

from numeric.core.graded_mesh import LEVELS
from numeric.core.quadrature import (COMPOSITE_NODES, composite_rule, gauss_legendre, grade_to_zero, integration_matrices,
                                     split_geometric)
from numeric.core.errors import SolverError
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.limits import closed_form
from numeric.solutions.solution import AccuracyWarning, FlatPunchSolution
from numeric.solutions.solver import LEVEL_TYPICAL_ERROR

__all__ = [
    "PowerLawSolution",
    "power_law",
    "FlatStresses",
    "EDGE_GAP",
    "C_RTOL",
    "N_RANGE",
    "SUBNORMAL_N",
    "power_law_pressure",
    "power_law_shear",
    "indentation_constant",
    "indentation_constant_316",
    "displacement_constant",
    "power_law_compliance",
    "w_n_scaled",
]

EDGE_GAP = 1e-13
"""Smallest distance 1 - x at which the flat solution is sampled; beyond, the edge form is used."""

N_RANGE = (1e-300, 100.0)
"""The exponents ``power_law`` takes. Above 100 the quadratures of (3.13) lose digits (the frictionless pressure is
4e-13 from its closed form at n = 100, 2e-9 at 150, 5e-2 at 1000), and the indenter is a flat punch to that
accuracy; below 1e-300 A ~ 1/n overflows."""

SUBNORMAL_N = 1.05
"""Below this n the stresses at a subnormal x (< 2.2e-308) are refused; above, they are the centre values, from
which they differ by x^(n - 1) < 4.6e-16 relative."""
_TINY = float(np.finfo(float).tiny)

C_RTOL = 1e-6
"""Relative error of ``PowerLawSolution.C`` above which it warns: five digits lost against the flat solution's
~1e-11 (reached near n = 10 for c ~ 0.3, n = 14 for c ~ 0.9)."""

_SERIES_TERMS = 30  # terms of the small-s series of W_n (0.25^30 < 1e-18)


@runtime_checkable
class FlatStresses(Protocol):
    """What the power-law transformation needs from a flat-punch solution ([S75] §2).

    ``numeric.FlatPunchSolution`` satisfies it; so does any object with
    these attributes. p0 and q0 must be smooth (analytic) inside each breakpoint
    interval; the breakpoints are graded geometrically toward c and 1.
    """

    gamma: float  # coupling constant (2.2)
    mu: float  # friction coefficient, inf when fully adhesive
    c: float  # stick radius, 1 when fully adhesive
    compliance: float  # P0* = (pi/2) int x p0 dx, (2.4)
    breakpoints: np.ndarray  # 0 = b_0 < ... < b_m = 1

    def pressure(self, x: np.ndarray) -> np.ndarray: ...  # p0(x), 0 <= x < 1

    def shear(self, x: np.ndarray) -> np.ndarray: ...  # q0(x), 0 <= x < 1


# ------------------------------------------------------------------ flat solution
@dataclass(frozen=True, slots=True)
class _EdgeModel:
    """Local form of f near x = 1 and its integral over (1 - s, 1)."""

    kind: str  # "power" or "log-periodic"
    exponent: float  # alpha - 1/2 (power) or kappa/2 (log-periodic)
    a: float
    b: float
    s_ref: float

    @classmethod
    def fit(cls, values: np.ndarray, s_e: float, mu: float, gamma: float, adhesive: bool) -> _EdgeModel:
        """The local form fitted to f at s = s_e and 4 s_e: K s^(alpha - 1/2), tan(pi alpha) = mu gamma,
        or s^(-1/2) Re[K s^(i kappa/2)] when the edge sticks (``adhesive``: no slip annulus outside 1 - s_e;
        mu = inf and c = 1, or the adhesive stresses of ``numeric.solutions.solver.nearly_adhesive``). The
        slip limit (mu = inf, c = c_max < 1, ``numeric.slip_limit``) keeps its annulus: alpha = 1/2."""
        if adhesive:  # adhesive edge: s^(-1/2) Re[K s^(i kappa/2)]
            omega = math.atanh(gamma) / math.pi  # kappa/2
            g1, g2 = values * np.sqrt(np.array([s_e, 4.0 * s_e]))
            ell = math.log(4.0)
            sinc = ell * np.sinc(omega * ell / np.pi)
            return cls("log-periodic", omega, float(g1), float((g2 - g1 * math.cos(omega * ell)) / sinc), s_e)
        beta = math.atan(mu * gamma) / math.pi - 0.5  # (1 - x)^(alpha - 1/2)
        return cls("power", beta, float(values[0] / s_e**beta), 0.0, s_e)

    def integral(self, s: np.ndarray) -> np.ndarray:
        """int_{1-s}^1 f dt for 0 <= s <= s_e (t^(-n) = 1 + O(s) is dropped: O(s^(3/2)))."""
        s = np.asarray(s, dtype=float)
        if self.kind == "power":
            beta = self.exponent
            return self.a * s ** (beta + 1.0) / (beta + 1.0)
        omega = self.exponent
        ell = np.log(np.where(s > 0.0, s, self.s_ref) / self.s_ref)
        sinc = ell * np.sinc(omega * ell / np.pi)  # sin(omega ell)/omega
        cos = np.cos(omega * ell)
        denom = 0.25 + omega**2
        # Re[(a - i b/omega) sqrt(s) e^{i omega ell} / (1/2 + i omega)]
        re_part = self.a * (0.5 * cos + omega**2 * sinc) / denom
        im_part = self.b * (0.5 * sinc - cos) / denom
        return np.where(s > 0.0, np.sqrt(np.maximum(s, 0.0)) * (re_part + im_part), 0.0)


def _checked_constants(flat: FlatStresses) -> tuple[float, float, float]:
    """gamma, mu and c of ``flat``, with a ValueError naming what it lacks or what is out of range."""
    for name in ("gamma", "mu", "c", "compliance", "breakpoints", "pressure", "shear"):
        if not hasattr(flat, name):
            raise ValueError(f"flat must provide '{name}' (see FlatStresses)")
    gamma, mu, c = float(flat.gamma), float(flat.mu), float(flat.c)
    if not 0.0 <= gamma <= GAMMA_MAX:
        raise ValueError(f"flat.gamma must lie in [0, 3/4], got {flat.gamma!r}")
    if not mu >= 0.0:
        raise ValueError(f"flat.mu must be >= 0 (inf when adhesive), got {flat.mu!r}")
    if not 0.0 <= c <= 1.0:
        raise ValueError(f"flat.c must lie in [0, 1], got {flat.c!r}")
    return gamma, mu, c


def _sampled_knots(breakpoints: np.ndarray) -> np.ndarray:
    """Knots 0 ... x_e: the breakpoints at least EDGE_GAP from 1, graded further toward 1 by factors
    of 4 if they stop early (x_e = 1 - s_e, s_e in [EDGE_GAP, 4 EDGE_GAP))."""
    bps = np.asarray(breakpoints, dtype=float)
    if (bps.ndim != 1 or bps.size < 2 or bps[0] != 0.0 or bps[-1] != 1.0
            or not np.all(np.diff(bps) > 0.0)):
        raise ValueError("flat.breakpoints must increase strictly from 0 to 1")
    inner = bps[(bps < 1.0) & (1.0 - bps >= EDGE_GAP)]
    extra = []
    s = 1.0 - inner[-1]
    while s >= 4.0 * EDGE_GAP:  # grade toward 1 if the given breakpoints stop early
        s /= 4.0
        extra.append(1.0 - s)
    return np.concatenate([inner, extra]) if extra else inner


class _Flat:
    """A validated flat solution with its sampled region [0, x_e] and edge models."""

    def __init__(self, flat: FlatStresses):
        self.flat = flat
        self.gamma, self.mu, self.c = _checked_constants(flat)
        self.knots = _sampled_knots(flat.breakpoints)  # 0 ... x_e
        self.x_e = float(self.knots[-1])
        self.s_e = 1.0 - self.x_e
        self.p_centre = float(np.asarray(flat.pressure(np.zeros(1)), dtype=float).ravel()[0])
        probe = np.array([self.x_e, 1.0 - 4.0 * self.s_e])
        adhesive = 1.0 - self.c < self.s_e  # the stick zone reaches into the edge piece (mu = inf is not enough)
        self.edge_p = _EdgeModel.fit(np.asarray(flat.pressure(probe), dtype=float), self.s_e, self.mu, self.gamma,
                                     adhesive)
        self.edge_q = _EdgeModel.fit(np.asarray(flat.shear(probe), dtype=float), self.s_e, self.mu, self.gamma,
                                     adhesive)

    def rule_knots(self, *, grade_zero: bool = False, extra: tuple[float, ...] = (),
                   n: float = 1.0) -> np.ndarray:
        """Knots 0 ... x_e of the composite rule (optionally graded toward 0, extra points
        inserted), split so that every piece [a, b], a > 0, has b <= 2a."""
        knots = np.union1d(self.knots, [e for e in extra if 0.0 < e < self.x_e])
        if grade_zero:
            levels = int(min(64, 500.0 / (n * math.log(2.0))))  # keep t^(-n) < 1e217
            knots = np.union1d(knots, grade_to_zero(float(knots[1]), levels))
        return split_geometric(knots)

    def rule(self) -> tuple[np.ndarray, np.ndarray]:
        """Composite Gauss rule on [0, x_e]: flattened nodes and weights."""
        knots = self.rule_knots()
        nodes, weights = composite_rule(knots[:-1], knots[1:])
        return nodes.ravel(), weights.ravel()

    def tail_integrals(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        s = 1.0 - x
        return self.edge_p.integral(s), self.edge_q.integral(s)

    def _piece_sums(self, lo: np.ndarray, hi: np.ndarray, n: float):
        """Gauss rule on pieces, p0 and q0 at the nodes and int over each piece of t^(-n) f."""
        nodes, weights = composite_rule(lo, hi)
        flat_nodes = nodes.ravel()
        p0 = np.asarray(self.flat.pressure(flat_nodes), float).reshape(nodes.shape)
        q0 = np.asarray(self.flat.shear(flat_nodes), float).reshape(nodes.shape)
        scale = nodes ** (-n)
        return nodes, weights, scale * p0, scale * q0

    def _from_edge(self, piece_p: np.ndarray, piece_q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """int from each knot to 1: reverse cumulative sums plus the edge piece beyond x_e."""
        tail_p, tail_q = self.tail_integrals(np.array([self.x_e]))
        cum_p = np.concatenate([np.cumsum(piece_p[::-1])[::-1], [0.0]]) + tail_p[0]
        cum_q = np.concatenate([np.cumsum(piece_q[::-1])[::-1], [0.0]]) + tail_q[0]
        return cum_p, cum_q

    def weighted_integrals(self, x: np.ndarray, n: float) -> tuple[np.ndarray, np.ndarray]:
        """x^n F_p(x), F_p(x) = int_x^1 t^(-n) p0 dt, and likewise for q0; 0 < x < 1.

        The points are merged into the knots K_i (each costs one piece of 30 evaluations).
        The scaled sums U_i = K_i^n int_{K_i}^1 t^(-n) f dt obey
        U_i = int_{K_i}^{K_(i+1)} (K_i/t)^n f dt + (K_i/K_(i+1))^n U_(i+1), which stays
        finite for x down to the smallest doubles (t^(-n) alone overflows).
        """
        x = np.asarray(x, dtype=float)
        up, uq = np.empty(x.shape), np.empty(x.shape)
        edge = x >= self.x_e
        tail_p, tail_q = self.tail_integrals(x[edge])
        up[edge], uq[edge] = x[edge] ** n * tail_p, x[edge] ** n * tail_q
        inside = ~edge
        if np.any(inside):
            pts, inverse = np.unique(x[inside], return_inverse=True)
            knots = split_geometric(np.union1d(pts, self.knots[self.knots > pts[0]]))
            lo, hi = knots[:-1], knots[1:]
            nodes, weights = composite_rule(lo, hi)
            flat_nodes = nodes.ravel()
            scale = weights * (lo[:, None] / nodes) ** n
            piece_p = (scale * np.asarray(self.flat.pressure(flat_nodes), float).reshape(nodes.shape)).sum(axis=1)
            piece_q = (scale * np.asarray(self.flat.shear(flat_nodes), float).reshape(nodes.shape)).sum(axis=1)
            ratio = (lo / hi) ** n
            edge_p, edge_q = self.tail_integrals(np.array([self.x_e]))
            scaled_p = np.empty(knots.shape)
            scaled_q = np.empty(knots.shape)
            scaled_p[-1], scaled_q[-1] = self.x_e**n * edge_p[0], self.x_e**n * edge_q[0]
            for i in range(lo.size - 1, -1, -1):  # the recurrence above
                scaled_p[i] = piece_p[i] + ratio[i] * scaled_p[i + 1]
                scaled_q[i] = piece_q[i] + ratio[i] * scaled_q[i + 1]
            where = np.searchsorted(knots, pts)
            up[inside] = scaled_p[where][inverse]
            uq[inside] = scaled_q[where][inverse]
        return up, uq

    def stresses_on_rule(self, knots: np.ndarray, n: float):
        """Nodes, weights and p, q of (3.13) at the Gauss nodes of the pieces of ``knots``.

        ``knots`` must end at x_e. Inside a piece, int_node^b t^(-n) f dt comes from the
        spectral integration matrix of the same nodes, so no further evaluations of p0, q0
        are needed.
        """
        lo, hi = knots[:-1], knots[1:]
        nodes, weights, gp, gq = self._piece_sums(lo, hi, n)
        cum_p, cum_q = self._from_edge((weights * gp).sum(axis=1), (weights * gq).sum(axis=1))
        mats = integration_matrices(nodes, lo, hi)
        fp = np.einsum("pij,pj->pi", mats, gp) + cum_p[1:, None]
        fq = np.einsum("pij,pj->pi", mats, gq) + cum_q[1:, None]
        factor = n * nodes ** (n - 1.0)
        return nodes.ravel(), weights.ravel(), (factor * fp).ravel(), (factor * fq).ravel()

    def stresses(self, x: np.ndarray, n: float) -> tuple[np.ndarray, np.ndarray]:
        """p(x), q(x) of (3.13) for 0 < x <= 1."""
        up, uq = self.weighted_integrals(x, n)
        return n * up / x, n * uq / x  # (3.13): n x^(n-1) F = n (x^n F)/x


def _evaluate(flat: FlatStresses, n: float, x: ArrayLike, component: int) -> np.ndarray | float:
    n = check_n(n)
    xs = check_x(x)
    prepared = _Flat(flat)
    values = xs.ravel()
    subnormal = (values > 0.0) & (values < _TINY)
    if np.any(subnormal):
        if n < SUBNORMAL_N:
            raise ValueError(f"x must be 0 or a normal double (>= {_TINY:g}) for n = {n!r} < {SUBNORMAL_N}: p and q go "
                             f"like x^(n - 1) near the centre, not resolved at a subnormal x, got {x!r}")
        values = np.where(subnormal, 0.0, values)  # |p(x) - p(0)| ~ x^(n - 1) < 5e-16 p(0) there
    out = np.zeros(values.shape)
    positive = values > 0.0
    if np.any(positive):
        out[positive] = prepared.stresses(values[positive], n)[component]
    if np.any(~positive):
        out[~positive] = _centre_value(prepared, n, component)
    return scalar_or_array(out.reshape(xs.shape))


def _centre_value(prepared: _Flat, n: float, component: int) -> float:
    """p(0), q(0): (3.18) for n > 1, divergent or finite limits otherwise."""
    if component == 0:
        if n > 1.0:
            return n / (n - 1.0) * prepared.p_centre  # (3.18)
        return math.inf
    if n > 1.0:
        return 0.0
    # q(0) = lim n x^(n-1) int_x^1 t^(-n) q0 dt, with int_0^1 t^(-n) q0 dt finite for n < 2.
    tiny = float(prepared.knots[1]) * 1e-30
    total = float(prepared.weighted_integrals(np.array([tiny]), n)[1][0]) / tiny**n
    if n == 1.0:
        return total
    return 0.0 if total == 0.0 else math.copysign(math.inf, total)


# ------------------------------------------------------------------ public API
def power_law_pressure(flat: FlatStresses, n: float, x: ArrayLike) -> np.ndarray | float:
    """Contact pressure p(x) under a power-law indenter z ~ r^n, [S75] (3.13).

    p(x) = n x^(n-1) int_x^1 t^(-n) p0(t) dt with p0 the flat-punch pressure of ``flat``.

    Parameters
    ----------
    flat : FlatStresses
        Flat-punch solution (same mu, gamma; the stick radius c carries over, §3.2).
    n : float
        Exponent of the indenter shape, n > 0 (2 sphere, 1 cone).
    x : array_like
        Radius over contact radius, 0 <= x <= 1.

    Returns
    -------
    p : float or ndarray
        p(1) = 0 (3.7). At x = 0, p(0) = n p0(0)/(n - 1) for n > 1 (3.18); for n <= 1 the
        pressure diverges at the apex (logarithmically for the cone) and inf is returned.

    Examples
    --------
    >>> from asymptotics.first_order import frictionless_pressure
    >>> class Smooth:
    ...     gamma, mu, c, compliance = 0.5, 0.0, 0.0, 1.0
    ...     breakpoints = np.concatenate([[0.0, 0.5], 1 - 0.5 * 0.25 ** np.arange(1, 26), [1.0]])
    ...     pressure = staticmethod(frictionless_pressure)
    ...     shear = staticmethod(np.zeros_like)
    >>> p = power_law_pressure(Smooth(), 2, 0.6)            # (3.19): (4/pi) sqrt(1 - x^2)
    >>> bool(abs(p - 4 / np.pi * 0.8) < 1e-13)
    True
    """
    return _evaluate(flat, n, x, 0)


def power_law_shear(flat: FlatStresses, n: float, x: ArrayLike) -> np.ndarray | float:
    """Shear traction q(x) under a power-law indenter z ~ r^n, [S75] (3.13).

    q(x) = n x^(n-1) int_x^1 t^(-n) q0(t) dt. q(1) = 0 (3.7). At x = 0: q(0) = 0 for n > 1,
    int_0^1 q0(t)/t dt for the cone n = 1, and +-inf for n < 1 (unless q0 = 0).

    Parameters
    ----------
    flat : FlatStresses
        Flat-punch solution.
    n : float
        Exponent of the indenter shape, n > 0.
    x : array_like
        Radius over contact radius, 0 <= x <= 1.
    """
    return _evaluate(flat, n, x, 1)


def w_n_scaled(n: float, s: ArrayLike) -> np.ndarray | float:
    """s^(-n) W_n(s), W_n(s) = int_0^s n t^(n-1) (1 - (1 - t^2)^(-1/2)) dt, for 0 <= s <= 1.

    The kernel of the A-identity (*) in the module docstring. For s <= 1/2 the series
    -n sum_{k>=1} binom(2k, k) 4^-k s^(2k)/(n + 2k) avoids the cancellation in the closed
    form 1 - (n/2) s^(-n) B(s^2; n/2, 1/2) used for s > 1/2. s^(-2) W_2 = -(1 - r)/(1 + r),
    r = sqrt(1 - s^2).

    Examples
    --------
    >>> round(float(w_n_scaled(2.0, 1.0)), 15)   # -(1 - 0)/(1 + 0)
    -1.0
    """
    n = check_n(n)
    s = np.asarray(s, dtype=float)
    if np.any(np.isnan(s)) or np.any((s < 0.0) | (s > 1.0)):
        raise ValueError(f"s must lie in [0, 1], got {s!r}")
    out = np.empty(s.shape)
    small = s <= 0.5
    k = np.arange(1, _SERIES_TERMS + 1, dtype=float)
    coeff = np.exp(special.gammaln(2 * k + 1) - 2 * special.gammaln(k + 1) - 2 * k * np.log(2.0)) / (n + 2 * k)
    s2 = s[small][..., None] ** 2
    out[small] = -n * np.sum(coeff * s2**k, axis=-1)
    big = s[~small]
    incomplete = special.betainc(0.5 * n, 0.5, big**2) * special.beta(0.5 * n, 0.5)
    out[~small] = 1.0 - 0.5 * n * incomplete / big**n
    return scalar_or_array(out)


def _a_star(prepared: _Flat, n: float) -> float:
    """A* = 1 + gamma int_0^1 q0(s) s^(-n) W_n(s) ds, the identity (*) of the module docstring."""
    nodes, weights = prepared.rule()
    integral = float(np.sum(weights * np.asarray(prepared.flat.shear(nodes), float) * w_n_scaled(n, nodes)))
    # Edge piece: q0 ~ s^(-1/2) and s^(-n) W_n = W(1) + O(sqrt(s)); evaluating at 1 - s_e/4
    # makes the (1 - s)^(-1/2) case exact to the next order.
    integral += float(w_n_scaled(n, 1.0 - 0.25 * prepared.s_e)) * float(prepared.edge_q.integral(np.array(prepared.s_e)))
    return 1.0 + prepared.gamma * integral


#: Below this 1 - c the stick-slip layer next to x = 1 is thinner than the composite rule in x resolves (its nodes are
#: doubles near 1, spaced 1.1e-16). Measured for the sphere at gamma = 0.05, 0.124, 0.17: A - A_adhesive falls like
#: (1 - c)^0.9 (-1.1e-11 ... -2.5e-10 at 1 - c = 1e-9) and C - C_adhesive like -(0.013 ... 0.046)(1 - c), while the
#: computed C leaves that trend by 1e-11 at 1 - c = 1e-10, 3e-11 at 1e-11, 2e-10 at 3e-12 and 2e-8 at 1e-13
#: (A by 3e-12, 2e-11, 2e-9 at 1e-11, 3e-12, 1e-13). Below it A and C are the adhesive solution's (App. B, c = 1),
#: within 1e-12 of the frictional ones there.
ADHESIVE_CONSTANTS_GAP = 1e-11


def _for_constants(flat: FlatStresses) -> FlatStresses:
    """The flat solution A and C are computed from: ``flat``, or the adhesive one where 1 - c < ADHESIVE_CONSTANTS_GAP."""
    gap = float(getattr(flat, "gap", 1.0 - float(flat.c)))
    if 0.0 < gap < ADHESIVE_CONSTANTS_GAP and float(flat.gamma) > 0.0:
        return closed_form(None, float(flat.gamma), math.inf, 1.0, True,
                           f"adhesive: 1 - c = {gap:.3g} is below what the constants' quadrature resolves")
    return flat


def indentation_constant(flat: FlatStresses, n: float) -> float:
    """Indentation constant A, delta = A a^n / b^(n-1), [S75] (3.2), (3.5).

    From (3.5a) at x = 1 with p(1) = 0 (3.7) and (3.13) with the order of integration
    swapped, A* = 1 + gamma int_0^1 q0(s) s^(-n) W_n(s) ds (``w_n_scaled``), and
    A = Gamma(n/2) Gamma(1/2) / (2 A* Gamma((n+1)/2)) = B(n/2, 1/2)/(2 A*) by (3.5).
    Frictionless (q0 = 0): A = 1 for the sphere, pi/2 for the cone.

    Parameters
    ----------
    flat : FlatStresses
        Flat-punch solution; its shear q0 enters (*).
    n : float
        Exponent of the indenter shape, n > 0.
    """
    n = check_n(n)
    return float(special.beta(0.5 * n, 0.5) / (2.0 * _a_star(_Flat(_for_constants(flat)), n)))  # (3.5)


def indentation_constant_316(flat: FlatStresses, n: float) -> float:
    """Indentation constant A by the paper's route (3.16), 1 - 1/(nA) = (2/pi) int_0^1 t K(t) p(t) dt.

    K(t) is the complete elliptic integral of modulus t (``ellipkm1((1 - t)(1 + t))``,
    exact near t = 1) and p the power-law pressure (3.13). (3.16) is correct as printed,
    with or without friction (module docstring). The part of the integral beyond x_e,
    O(s_e^(3/2) log s_e) ~ 1e-18, is dropped.

    Parameters
    ----------
    flat : FlatStresses
        Flat-punch solution; its pressure p0 enters through (3.13).
    n : float
        Exponent of the indenter shape, n > 0.
    """
    n = check_n(n)
    prepared = _Flat(flat)
    nodes, weights, p, _ = prepared.stresses_on_rule(prepared.rule_knots(grade_zero=True, n=n), n)
    kernel = nodes * special.ellipkm1((1.0 - nodes) * (1.0 + nodes))
    integral = (2.0 / np.pi) * float(np.sum(weights * kernel * p))  # (3.16)
    return 1.0 / (n * (1.0 - integral))


def displacement_constant(flat: FlatStresses, n: float, *, x: float | None = None) -> float:
    """Stick-zone displacement constant C, u(x) = C x^n on (0, c), [S75] (3.4), (3.5b).

    C* x^n = x int_x^1 q(t) dt / sqrt(t^2 - x^2) - gamma int_0^x t p(t) dt / sqrt(x^2 - t^2),
    C* = Gamma((n+3)/2) Gamma(1/2) / Gamma(1 + n/2) C, evaluated at one point x of the stick
    zone with p, q from (3.13). Near t = x the substitutions t = x + s^2 (on (x, 2x)) and
    t = x - s^2 (on (x/2, x)) remove the inverse square roots; elsewhere the composite rule
    is used directly. The part beyond x_e, O(s_e^(3/2)), is dropped. The result does not
    depend on x if (p0, q0) solve the flat-punch problem (the tests check this).

    Parameters
    ----------
    flat : FlatStresses
        Flat-punch solution with a stick zone, c > 0.
    n : float
        Exponent of the indenter shape, n > 0.
    x : float, optional
        Point of the stick zone, 0 < x < c; default c/2.
    """
    n = check_n(n)
    if not float(flat.c) > 0.0:
        raise ValueError("flat.c must be > 0: C is defined on the stick zone 0 < x < c")
    prepared = _Flat(_for_constants(flat))
    c = prepared.c
    x = 0.5 * c if x is None else float(x)
    if not 0.0 < x < c or x >= prepared.x_e:
        raise ValueError(f"x must lie in the stick zone (0, c) = (0, {c!r}), got {x!r}")
    xi, w = gauss_legendre(COMPOSITE_NODES)

    def sqrt_rule(lo: float, hi: float, sign: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Nodes t = x + sign s^2 for t between lo and hi (one of them x), weights in s."""
        ts = prepared.knots[(prepared.knots > lo) & (prepared.knots < hi)]
        s_knots = np.sqrt(np.abs(np.concatenate([[lo], ts, [hi]]) - x))
        s_knots = np.sort(s_knots)
        a, b = s_knots[:-1], s_knots[1:]
        s = (0.5 * (a + b))[:, None] + (0.5 * (b - a))[:, None] * xi
        ws = (0.5 * (b - a))[:, None] * w
        return (x + sign * s**2).ravel(), s.ravel(), ws.ravel()

    # Direct parts on the composite rule: (0, x/2) and (2x, x_e).
    knots = prepared.rule_knots(grade_zero=True, extra=(0.5 * x, 2.0 * x), n=n)
    nodes, weights, p_rule, q_rule = prepared.stresses_on_rule(knots, n)
    low, high = nodes < 0.5 * x, nodes > 2.0 * x
    # Parts next to x, with t = x + s^2 on (x, 2x) and t = x - s^2 on (x/2, x).
    t1, s1, w1 = sqrt_rule(x, min(2.0 * x, prepared.x_e), 1.0)
    t3, s3, w3 = sqrt_rule(0.5 * x, x, -1.0)
    p_near, q_near = prepared.stresses(np.concatenate([t1, t3]), n)
    q1, p3 = q_near[: t1.size], p_near[t1.size:]
    t2, w2, q2 = nodes[high], weights[high], q_rule[high]
    t4, w4, p4 = nodes[low], weights[low], p_rule[low]
    term1 = x * (np.sum(w1 * 2.0 * q1 / np.sqrt(2.0 * x + s1**2))  # t = x + s^2
                 + np.sum(w2 * q2 / np.sqrt((t2 - x) * (t2 + x))))
    term2 = (np.sum(w3 * 2.0 * t3 * p3 / np.sqrt(2.0 * x - s3**2))  # t = x - s^2
             + np.sum(w4 * t4 * p4 / np.sqrt((x - t4) * (x + t4))))
    c_star = (term1 - prepared.gamma * term2) / x**n  # (3.5b)
    return float(c_star * math.exp(special.gammaln(1.0 + 0.5 * n) - special.gammaln(0.5 * n + 1.5)) / math.sqrt(math.pi))


def _displacement_constant_checked(flat: FlatPunchSolution, n: float) -> tuple[float, float]:
    """C at x = c/2 and its relative change at x = c/4 (its error estimate), warning or raising as
    ``PowerLawSolution.C`` says."""
    if flat.c == 0.0 or flat.gamma == 0.0:  # frictionless or uncoupled: u = 0 in the stick zone
        return 0.0, 0.0
    with np.errstate(over="ignore", invalid="ignore"):  # t^(-n) overflows at small c and large n: raised below
        value = displacement_constant(flat, n)
        other = displacement_constant(flat, n, x=0.25 * flat.c)
    if math.isinf(value) and (0.5 * flat.c) ** n < _TINY:  # documented: |C| ~ c^-n is beyond the doubles
        return value, 0.0
    if not (math.isfinite(value) and math.isfinite(other)):
        raise SolverError(f"C (3.4) of the power law n = {n!r} at c = {flat.c!r} cannot be evaluated: u = C x^n is a "
                          "difference of two stick-zone integrals whose rounding grows with n (x^n underflows here)")
    error = abs(other - value) / abs(value) if value != 0.0 else (0.0 if other == 0.0 else math.inf)
    if error > C_RTOL:
        warnings.warn(AccuracyWarning(
            f"C (3.4) of the power law n = {n!r} at c = {flat.c!r} is good to {error:.1e} relative only (two points "
            f"of the stick zone give {value!r} and {other!r}): its rounding grows with n"), stacklevel=3)
    return value, error


def power_law_compliance(flat: FlatStresses, n: float) -> float:
    """Compliance factor P* = n P0* / (n + 1) of the power-law indenter, [S75] (3.17).

    Examples
    --------
    >>> class Flat:
    ...     compliance = 1.0
    >>> power_law_compliance(Flat(), 2)
    0.6666666666666666
    """
    n = check_n(n)
    compliance = float(flat.compliance)
    if not compliance > 0.0:
        raise ValueError(f"flat.compliance must be > 0, got {flat.compliance!r}")
    return n / (n + 1.0) * compliance  # (3.17)


@dataclass(frozen=True, slots=True)
class PowerLawSolution:
    """A power-law indenter z = r^n / (n b^(n-1)) pressed into a half-space with friction, [S75] §3.

    Attributes
    ----------
    n : float
        Exponent of the profile (2: sphere, 1: cone).
    compliance : float
        P* = n P0* / (n + 1) (3.17).
    flat : FlatPunchSolution
        The flat-punch solution the stresses are computed from (3.13).
    nu, gamma, mu, c, error : float
        The flat punch's (c is the same for every power law, §3.2; ``error`` estimates c, mu, P0*).
    A : float
        Indentation constant, delta = A a^n / b^(n-1) (3.2), by the identity (*) above;
        computed on first access (a quadrature of the flat shear), then kept.
    C : float
        Stick-zone displacement constant, u = C x^n on (0, c) (3.4); computed on first
        access, then kept. It is a difference of two stick-zone integrals divided by x^n, so its
        rounding grows with n (measured at x = c/2: ~1e-13 at n = 2, 1e-8 at n = 8, 1e-5 at
        n = 12, and lost beyond n ~ 14); ``C_error`` is its estimated relative error, the change
        when the same C is evaluated at x = c/4 (the true C does not depend on x). Where that
        exceeds ``C_RTOL`` an ``AccuracyWarning`` says so. Where (c/2)^n underflows, |C|, which grows
        like c^-n, is beyond the doubles and C is -inf (or +inf); where C cannot be evaluated otherwise
        a ``SolverError`` is raised.
    C_error : float
        Estimated relative error of ``C`` (0 where C = 0 exactly).
    """

    n: float
    compliance: float
    flat: FlatPunchSolution
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def nu(self) -> float | None:
        return self.flat.nu

    @property
    def gamma(self) -> float:
        return self.flat.gamma

    @property
    def mu(self) -> float:
        return self.flat.mu

    @property
    def c(self) -> float:
        return self.flat.c

    @property
    def error(self) -> float:
        return self.flat.error

    @property
    def A(self) -> float:
        if "A" not in self._cache:
            self._cache["A"] = indentation_constant(self.flat, self.n)
        return self._cache["A"]

    @property
    def C(self) -> float:
        if "C" not in self._cache:
            self._cache["C"], self._cache["C_error"] = _displacement_constant_checked(self.flat, self.n)
        return self._cache["C"]

    @property
    def C_error(self) -> float:
        self.C  # noqa: B018 - computes both on first access
        return self._cache["C_error"]

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """Contact pressure p(x) by (3.13); p(1) = 0 (3.7)."""
        return power_law_pressure(self.flat, self.n, x)

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """Shear traction q(x) by (3.13); q(1) = 0 (3.7)."""
        return power_law_shear(self.flat, self.n, x)


def power_law(n: float, nu: float | None = None, mu: float | None = None, c: float | None = None, *,
              gamma: float | None = None, level: int | None = None, rtol: float | None = None) -> PowerLawSolution:
    """Solve the frictional contact of a power-law indenter z ~ r^n, [S75] §3.

    Parameters are those of ``numeric.flat_punch`` plus the exponent n, 1e-300 <= n <= 100 (``N_RANGE``). With ``rtol``
    the asymptotic route of ``flat_punch`` is not used (A and C need the full stresses) except
    below the solver's reach, c < 1e-5.

    Examples
    --------
    >>> h = power_law(2, nu=0.25, mu=0.0)       # Hertz: A = 1, p = (4/pi) sqrt(1 - x^2)
    >>> round(h.A, 12), round(float(h.pressure(0.6)), 12)
    (1.0, 1.018591635788)
    """
    n_value = check_n(n)
    if not N_RANGE[0] <= n_value <= N_RANGE[1]:
        raise ValueError(f"n (power-law exponent) must lie in [{N_RANGE[0]:g}, {N_RANGE[1]:g}] (N_RANGE: beyond 100 the "
                         f"indenter is a flat punch, use flat_punch), got {n!r}")
    flat = flat_punch(nu=nu, mu=mu, c=c, gamma=gamma, level=level, rtol=rtol)
    if rtol is not None and flat.route.startswith("asymptotic"):
        # A and C need the full stresses: from the law's first-order fields they are off by far more
        # than the law's error in mu (measured at nu = 0.4, c = 0.5, rtol = 1e-3: C by 4.6e-3 against a
        # stated 7.6e-5), so the cheapest route meeting rtol here is the solver at the level whose typical
        # accuracy meets it; below the solver's reach (c < 1e-5) flat_punch itself returns the law again.
        chosen = min((lv for lv, e in LEVEL_TYPICAL_ERROR.items() if e <= rtol), default=len(LEVELS) - 1)
        flat = flat_punch(nu=nu, mu=mu, c=c, gamma=gamma, level=chosen)
    return PowerLawSolution(n=n_value, compliance=power_law_compliance(flat, n_value), flat=flat)
