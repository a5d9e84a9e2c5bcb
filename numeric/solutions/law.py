"""The asymptotic route of ``numeric.flat_punch``: the friction law of [S75] (2.28), alone or with
its gamma^2 correction (``asymptotics.second_order``), with error bounds measured against the
full solution, and the first-order stresses (2.26), (2.31) that go with it.

Used where the caller's ``rtol`` allows it (``LawRoute.offers``), and below the solver's reach,
c < 1e-5 (``LawRoute.last_resort``), where it is matched to the table at c = 1e-5 (``hand_over_ratio``) so that
mu(c) is continuous and increasing across the hand-over. The bounds are envelopes of measured errors (the
Chebyshev table and level-2 solves, see the comments); they are not proofs.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

import numpy as np

from asymptotics import second_order
from asymptotics.adhesive import compliance_adhesive
from asymptotics.first_order import frictionless_pressure, mu_over_gamma, shear_ratio_first_order, stick_radius_first_order

from numeric.core.table import table_least_c, table_least_mu
from numeric.solutions.limits import ADHESIVE_EDGE_BREAKPOINTS
from numeric.solutions.solution import FlatPunchSolution, Offer, meets, warn_unmet

# The asymptotic route: mu/gamma = f0(c) (first order, (2.28)) or f0(c) (1 + R(c) gamma^2),
# R = f2/f0 (asymptotics.second_order), with error bounds measured against the full solution.

#: The asymptotic route is offered for c <= ASYMPTOTIC_C_MAX only (its error grows without bound
#: toward c_max).
ASYMPTOTIC_C_MAX = 0.9
#: Envelopes in gamma of |mu/mu_law - 1| for 0 < c <= 0.9: the value at the first breakpoint >= gamma.
#: Measured maxima over c in [1e-3, 0.9] (always at c = 0.9; every maximum grows with gamma): the
#: Chebyshev table (1e-10) at gamma = 0.05 ... 2/3 on 90 values of c, level-2 solves at gamma = 0.7,
#: 0.75 (error estimates <= 1.3e-7); first order / gamma^2 = 0.86, 0.92, 1.02, 1.21, 1.56, 2.04, 2.62,
#: 4.26, second order / gamma^4 = 1.04, 1.08, 1.15, 1.29, 1.59, 2.01, 2.60, 4.16 at the breakpoints.
#: Below c = 1e-3 (level 1-2 solves at c = 1e-3, 1e-4, 1e-5, gamma = 0.2 ... 0.7) they are smaller:
#: 0.48 ... 0.72 and 0.32 ... 0.50 (f4/f0 ~ 0.3 + 0.4 gamma^2). Each bound is 10 % above the maximum.
GAMMA_BREAKS = (0.2, 0.3, 0.4, 0.5, 0.6, 2.0 / 3.0, 0.7, 0.75)
K2_BOUNDS = (0.95, 1.02, 1.13, 1.33, 1.72, 2.24, 2.89, 4.69)
K4_BOUNDS = (1.15, 1.19, 1.27, 1.43, 1.75, 2.22, 2.87, 4.58)
#: |P* - law| / (gamma^4 f0(c)) (first order, 1 + gamma^2 P2) and / (gamma^6 f0(c)) (second order,
#: + gamma^4 P4): P* - 1 vanishes with f0 as c -> 0. Measured maxima (same data, c = 1e-3 ... 0.9):
#: 0.18 ... 0.26 and 0.12 ... 0.19 at gamma = 0.05 ... 2/3 (at c ~ 0.67), 0.30 and 0.22 at gamma = 0.75
#: (c = 0.5); 15 % above.
KP2_BOUND, KP4_BOUND = 0.35, 0.26
#: Below c = 1e-3 the laws' errors are smaller than at c = 0.9: measured |mu/mu_law - 1| / gamma^2 =
#: 0.48 ... 0.72 (first order) and / gamma^4 = 0.32 ... 0.50 (second order, with the quadrature's f2)
#: at c = 1e-3, 1e-4, 1e-5, gamma = 0.2 ... 0.7 (level 1-2 solves; they grow slowly as c decreases
#: and with gamma: 0.78 and 0.43 at gamma = 0.75, c = 1e-3); bounds about 30 % above.
K2_SMALL_C, K4_SMALL_C = 1.0, 0.7
#: P2/f0 as c -> 0: 0.36338 at c = 1e-100 and at 1e-300 (compliance_p2 / mu_over_gamma); used where c underflows.
P2_OVER_F0_AT_ZERO = 0.36338


def envelope(bounds: tuple[float, ...], gamma: float) -> float:
    for g, k in zip(GAMMA_BREAKS, bounds, strict=True):
        if gamma <= g:
            return k
    return math.inf  # gamma > 3/4 (dissimilar bodies): not measured


def law_bound(c: float, gamma: float, order: int) -> float:
    """Bound of |mu/mu_law - 1| at stick radius c for the law of this order (0: (2.28), 2: with f2)."""
    if gamma > GAMMA_BREAKS[-1]:
        return math.inf  # not measured
    if c < second_order.C_MIN:
        return K2_SMALL_C * gamma**2 if order == 0 else K4_SMALL_C * gamma**4 + second_order.F2_SMALL_C_ERROR * gamma**2
    return envelope(K2_BOUNDS if order == 0 else K4_BOUNDS, gamma) * gamma ** (2 + order)


def law_stick_radius(mu: float, gamma: float, order: int) -> float:
    """c with mu = gamma f0(c) (order 0: the inverse of (2.28)) or mu = gamma f0(c) (1 + R(c) gamma^2)
    (order 2), both inverted in ``asymptotics``; 0 where c underflows."""
    if order == 0:
        return float(stick_radius_first_order(mu, gamma=gamma))
    return float(second_order.stick_radius_second_order(mu, gamma=gamma))


def law_friction_coefficient(c: float, gamma: float, order: int) -> float:
    """mu = gamma f0(c) ((2.28), order 0) or gamma f0(c) (1 + R(c) gamma^2) (order 2)."""
    f0 = float(mu_over_gamma(c))
    return gamma * f0 * (1.0 + second_order.correction_ratio(c) * gamma**2 if order == 2 else 1.0)


def hand_over_ratio(gamma: float) -> float:
    """mu/mu_law (second order) at the table's least stick radius C_MIN = 1e-5, where the solver's reach ends too: below
    it the last-resort law is this multiple of the second-order law, so that mu(c) meets the table there and keeps
    increasing across (1 where the table does not reach). Measured against level-2 solves below the hand-over (the
    solver run beyond its reach, ``tests/test_rtol.py``): |mu_matched/mu - 1| = 4.6e-4, 8.8e-4, 1.7e-3 at c = 3e-6,
    1e-6, 1e-7 for nu = -0.999 (the unmatched law 0.12 throughout), 2.8e-5, 5.5e-5 at c = 3e-6, 1e-6 for nu = 0.3
    (unmatched 2.1e-3): it grows about linearly in log(1e-5/c). Its stated bound is ``matched_bound``'s."""
    c0, mu0 = table_least_c(), table_least_mu(gamma)
    if not (math.isfinite(c0) and math.isfinite(mu0)):
        return 1.0
    law = law_friction_coefficient(c0, gamma, 2)
    if min(mu0, law) < sys.float_info.min:  # subnormal mu (gamma below ~1e-306): a ratio of roundings (0/0 at
        return 1.0                           # gamma = 5e-324), where the law is exact to rounding anyway
    return mu0 / law


def matched_bound(bound: float, ratio: float) -> float:
    """Bound of |mu/(ratio mu_law) - 1| and |ratio mu_law/mu - 1| from ``bound`` of |mu/mu_law - 1| (= eps): the
    matched law's error is (ratio - 1 - eps)/(1 + eps) relative to mu, and (1 + eps - ratio)/ratio relative to itself."""
    if ratio == 1.0:
        return bound
    return (abs(ratio - 1.0) + bound) / min(ratio, 1.0 - bound) if bound < 1.0 else math.inf


def law_compliance(c: float, gamma: float, order: int, f0: float) -> tuple[float, float]:
    """P* = 1 + gamma^2 P2 (+ gamma^4 P4 for order 2 and c >= 1e-3) and the bound of its error (f0 = f0(c))."""
    if gamma * gamma * max(1.0, f0) < 1e-17:  # P2 < f0 (P2/f0 = 0.07 ... 0.364 for c = 1 - 1e-6 ... 0): 1 + gamma^2 P2 rounds to 1
        return 1.0, KP2_BOUND * gamma**4 * f0
    p2 = P2_OVER_F0_AT_ZERO * f0 if c < 1e-100 else float(second_order.compliance_p2(c))
    if order == 2 and c >= second_order.C_MIN:
        return 1.0 + gamma**2 * p2 + gamma**4 * float(second_order.compliance_p4(c)), KP4_BOUND * gamma**6 * f0
    return 1.0 + gamma**2 * p2, KP2_BOUND * gamma**4 * f0


LAW_NAMES = {0: "first order (2.28)", 2: "second order (2.28) + gamma^2 f2"}


@dataclass(frozen=True, slots=True)
class FirstOrderField:
    """Stresses at first order in gamma: p = p^(0) (2.26), q = mu p^(0) (1 - psi) (2.31) on the stick
    zone and mu p^(0) on the slip annulus; relative error O(gamma^2) (measured max |q/(mu p) - (1 - psi)|
    = 0.06 ... 0.5 gamma^2 for c = 0.1 ... 0.9, derivations/section_2_3.md)."""

    c: float
    mu: float

    def pressure(self, x: np.ndarray) -> np.ndarray:
        return np.asarray(frictionless_pressure(x), dtype=float)  # (2.26)

    def shear(self, x: np.ndarray) -> np.ndarray:
        p = np.asarray(frictionless_pressure(x), dtype=float)
        if self.c == 0.0:  # c underflowed: slip everywhere
            return self.mu * p
        return self.mu * p * np.asarray(shear_ratio_first_order(x, self.c), dtype=float)  # (2.31)

    def slip(self, x: np.ndarray) -> np.ndarray:
        raise NotImplementedError(
            "the slip displacement (2.10) is not computed on the asymptotic route; use the solver "
            "(give level=, or an rtol below this route's error bound; the solver needs c >= 1e-5)")

    def edge_value(self, shear: bool) -> float:
        """p^(0) and q at x = 1: infinite ((2.26), q = mu p^(0) on the slip annulus)."""
        return math.inf


def route_text(order: int, bound: float, bound_p: float, why: str, matched: bool = False) -> str:
    source = ("the measured bound of the law with its offset from the table at c = 1e-5, to which it is matched"
              if matched else f"measured bound, c <= {ASYMPTOTIC_C_MAX}")
    return (f"asymptotic, {LAW_NAMES[order]}: relative error of mu <= {bound:.2g} ({source}), of P* <= "
            f"{bound_p:.2g}; stresses at first order (2.26), (2.31), relative error O(gamma^2); slip displacement not "
            f"computed ({why})")


@dataclass(frozen=True, slots=True)
class Bracket:
    """The law's stick radius for given mu and the range the true one lies in (mu/mu_law within the bound)."""

    c: float
    lo: float
    hi: float
    bound: float


def law_bracket(mu: float, gamma: float, order: int, ratio: float = 1.0) -> Bracket:
    """The law's c for given mu (times ``ratio``: ``hand_over_ratio``'s, below the hand-over at c = 1e-5, where the
    true c lies below it too) and the range the true c lies in."""
    c = law_stick_radius(mu / ratio, gamma, order)
    # the true c solves ratio mu_law(c) (1 + e) = mu with |e| <= bound, and mu_law increases with c;
    # the bound is the small-c one only if the whole range lies below 1e-3
    for at in (c, 1.0):
        bound = matched_bound(law_bound(at, gamma, order), ratio)
        lo = law_stick_radius(mu / (ratio * (1.0 + bound)), gamma, order)
        hi = law_stick_radius(mu / (ratio * (1.0 - bound)), gamma, order) if bound < 1.0 else 1.0
        if ratio != 1.0:
            hi = min(hi, table_least_c())
        if hi < second_order.C_MIN or at == 1.0:
            return Bracket(c, lo, hi, bound)
    raise AssertionError  # pragma: no cover


def graded_breakpoints(c: float) -> np.ndarray:
    """Breakpoints graded toward x = c (both sides) and toward the edge."""
    if c <= 0.0:
        return ADHESIVE_EDGE_BREAKPOINTS
    k = 0.25 ** np.arange(1, 26)
    points = np.unique(np.concatenate([ADHESIVE_EDGE_BREAKPOINTS, [c], c * (1.0 - k), c + (1.0 - c) * k]))
    points.setflags(write=False)
    return points


def asymptotic_given_c(nu: float | None, c: float, gamma: float, order: int, why: str,
                       ratio: float = 1.0) -> FlatPunchSolution:
    """The law's mu for given c (times ``ratio``: ``hand_over_ratio``'s below the hand-over), with its measured
    bound as the error (of mu; of P* its own bound)."""
    mu = ratio * law_friction_coefficient(c, gamma, order)
    bound = matched_bound(law_bound(c, gamma, order), ratio)
    compliance, bound_p = law_compliance(c, gamma, order, float(mu_over_gamma(c)))
    return FlatPunchSolution(nu, gamma, mu, c, compliance, max(bound * mu, bound_p),
                             route_text(order, bound, bound_p, why, ratio != 1.0), graded_breakpoints(c),
                             FirstOrderField(c, mu))


def asymptotic_given_mu(nu: float | None, mu: float, gamma: float, order: int, bracket: Bracket,
                        why: str, ratio: float = 1.0) -> FlatPunchSolution:
    """The law's c for given mu (``bracket``, matched by ``ratio`` below the hand-over); error of c from the bracket,
    of P* its bound plus its change over the bracket."""
    f2 = 1.0 + (second_order.correction_ratio(bracket.c) * gamma**2 if order == 2 else 0.0)
    values = [(float(compliance_adhesive(gamma)), 0.0) if c > 0.999 else  # P* <= P0* (B4), P* increases with c
              law_compliance(c, gamma, order, float(mu_over_gamma(c)) if c > 0.0 else mu / (gamma * f2 * ratio))
              for c in (bracket.c, bracket.lo, bracket.hi)]
    compliance, bound_p = values[0]
    error_p = bound_p + max(abs(v[0] - compliance) for v in values[1:])
    error_c = max(bracket.hi - bracket.c, bracket.c - bracket.lo)
    return FlatPunchSolution(nu, gamma, mu, bracket.c, compliance, max(error_c, error_p),
                             route_text(order, bracket.bound, bound_p,
                                        f"so {bracket.lo:.6g} <= c <= {bracket.hi:.6g}; {why}", ratio != 1.0),
                             graded_breakpoints(bracket.c),
                             FirstOrderField(bracket.c, mu))


#: Rough run time in seconds of the law of each order (for ordering the routes against the solver's levels).
LAW_SECONDS = {0: 1e-4, 2: 1e-3}


class LawRoute:
    """The asymptotic route for one problem: exactly one of c (then mu is the answer) and mu (c) is given.

    ``offers(rtol)`` answers for each order whether its measured bound meets rtol (c <= 0.9);
    ``last_resort`` is the second-order law where nothing else can be had (below the solver's
    reach). For given mu the second-order bracket is computed once, on first use.
    """

    def __init__(self, nu: float | None, gamma: float, c: float | None, mu: float | None):
        self.nu, self.gamma, self.c, self.mu = nu, gamma, c, mu
        self._bracket: Bracket | None = None

    @property
    def bracket(self) -> Bracket:
        """The second-order law's c for the given mu and the range the true c lies in."""
        if self._bracket is None:
            self._bracket = law_bracket(self.mu, self.gamma, 2)
        return self._bracket

    @property
    def gap(self) -> float:
        """The second-order law's 1 - c for the given mu, formed without cancellation near c = 1:
        (2.29) 1 - c = 2 exp(-pi mu/gamma') with gamma' = gamma (1 + gamma^2 f2/f0 at c = 0.999)."""
        c = self.bracket.c
        if c < 0.999:
            return 1.0 - c
        ratio = second_order.correction_ratio(second_order.C_MAX)
        return 2.0 * math.exp(-math.pi * self.mu / (self.gamma * (1.0 + ratio * self.gamma**2)))

    def offers(self, rtol: float) -> list[Offer]:
        """One offer per order (0: (2.28), 2: + gamma^2 f2)."""
        return [Offer(LAW_SECONDS[order], lambda order=order: self._promises(order, rtol),
                      lambda order=order: self._solve(order, f"meets rtol = {rtol:g}")) for order in (0, 2)]

    def _promises(self, order: int, rtol: float) -> bool:
        g = self.gamma
        if self.c is not None:
            return self.c <= ASYMPTOTIC_C_MAX and law_bound(self.c, g, order) <= rtol
        if min(law_bound(0.0, g, order), law_bound(0.5, g, order)) > 4.0 * rtol:
            return False  # c's relative error is mu's over d log mu/d log c (2.7 at c = 0.9 for f0): cannot meet rtol
        b = self._order_bracket(order)
        return b.hi <= ASYMPTOTIC_C_MAX and b.c != 0.0 and max(b.hi - b.c, b.c - b.lo) <= rtol * b.c

    def _order_bracket(self, order: int) -> Bracket:
        return self.bracket if order == 2 else law_bracket(self.mu, self.gamma, order)

    def _solve(self, order: int, why: str) -> FlatPunchSolution:
        if self.c is not None:
            return asymptotic_given_c(self.nu, self.c, self.gamma, order, why)
        return asymptotic_given_mu(self.nu, self.mu, self.gamma, order, self._order_bracket(order), why)

    def meets(self, sol: FlatPunchSolution, rtol: float, bracket: Bracket | None = None) -> bool:
        """Whether the law's answer (mu given c, c given mu) meets rtol; an underflowed c whose whole
        bracket (the second-order one unless given) underflowed too counts as met."""
        if self.c is not None:
            return meets(sol, rtol, sol.mu)
        return meets(sol, rtol, sol.c) or (sol.c == 0.0 and (bracket or self.bracket).hi == 0.0)

    def last_resort(self, rtol: float | None, why: str) -> FlatPunchSolution:
        """The second-order law, with an ``AccuracyWarning`` if it misses rtol; below the hand-over to the table and
        the solver at c = 1e-5 matched to the table there (``hand_over_ratio``)."""
        if self.c is not None:
            below = self.c < table_least_c()
        else:
            below = self.mu < table_least_mu(self.gamma)
        ratio = hand_over_ratio(self.gamma) if below else 1.0
        matched = None
        if ratio == 1.0:
            sol = self._solve(2, why)
        elif self.c is not None:
            sol = asymptotic_given_c(self.nu, self.c, self.gamma, 2, why, ratio)
        else:
            matched = law_bracket(self.mu, self.gamma, 2, ratio)
            sol = asymptotic_given_mu(self.nu, self.mu, self.gamma, 2, matched,
                                      why, ratio)
        if rtol is not None and not self.meets(sol, rtol, matched):
            warn_unmet(sol, rtol, sol.mu if self.c is not None else sol.c)
        return sol
