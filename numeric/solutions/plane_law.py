"""The strip punch below the solver's smallest stick width: the second-order law in 1/log(4/c) and full slip.

Below c = ``C_SMALLEST`` (1e-5; small mu, mu/gamma below ~0.12) the plane solver is not run. There, with
L = log(4/c) and the first-order law mu_1 = gamma K(c)/K'(c) (= gamma pi/(2 L) to a relative c^2/(4 L)),

    mu = mu_1 (1 + gamma^2 r),    r(c, gamma) = a(gamma) + b(gamma)/L^2 + ...

The form was found from the solver (``derivations/plane_strain.md``, ``tests/test_plane_law.py``): r changes by halves per decade of c as c -> 0,
and its change follows 1/L^2 (fitted through c = 1e-3 and 1e-4 it predicts the solver's r at 1e-5 to 2e-7 ...
5e-5, at 1e-6 and 1e-7, solved directly, to 2e-7 ... 2e-5). a and b are fitted here through the solver at
``LAW_NODES[1:]`` = 1e-4, 1e-5 (the law is continuous with the solver at 1e-5), once per gamma and level; below
``SMALL_GAMMA`` through the small-gamma series' r at those c (``numeric.solutions.plane_small_gamma``: r without the
cancellation of mu/mu_1 - 1 ~ gamma^2 r, which at tiny gamma falls below the solver's rounding).
Its error: the same fit through ``LAW_NODES[:2]`` = 1e-3, 1e-4 moves the limit a by da; the relative error of
mu is taken as ``LAW_ERROR_FACTOR`` gamma^2 |da| (measured, against the solver at c = 1e-6 and 1e-7: the actual
error is 1/3 ... 1/240 of this bound, ``derivations/plane_strain.md``), plus the solver's rounding floor.

The stresses: as c -> 0 the stick zone shrinks to a point and away from it the punch slips inward everywhere,
p = (cos(pi alpha)/pi) (1 - x^2)^(alpha - 1/2) |x|^(-2 alpha), q = mu sgn(x) p (``asymptotics.plane.
pressure_full_slip``). Against the solver at c = 1e-5 ... 1e-4 the relative difference at |x| >= 100 c is
0.5 alpha (c/x)^2 (measured, nu from -0.99 to 0.49), so ``FullSlipField`` answers at |x| >= ``OUTER_FACTOR`` c to
alpha (c/x)^2 plus the effect of mu's error through alpha; nearer the stick zone (the stick zone itself, where p is
flat and q turns over) it raises ValueError, and the slip is not computed here.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy import optimize

from asymptotics.plane import mu_over_gamma_plane, pressure_full_slip

from numeric.solutions.plane_small_gamma import SMALL_GAMMA, gamma_series
from numeric.solutions.plane_solver import C_SMALLEST, ROUNDING_FLOOR, solve_given_c

__all__ = ["LAW_NODES", "LAW_ERROR_FACTOR", "OUTER_FACTOR", "LawFit", "law_fit", "law_friction_coefficient",
           "law_stick_width", "FullSlipField"]

#: Stick widths of the solver solves the law is fitted through (the last is the solver's smallest, ``C_SMALLEST``).
LAW_NODES = (1e-3, 1e-4, C_SMALLEST)
#: Bound of the relative error of mu over gamma^2 |da| (see the module docstring; measured margin 3 ... 240).
LAW_ERROR_FACTOR = 3.0
#: The stresses are given at |x| >= OUTER_FACTOR c (relative error there below alpha/OUTER_FACTOR^2).
OUTER_FACTOR = 100.0


def _log_ratio(c: float) -> float:
    """L = log(4/c)."""
    return math.log(4.0) - math.log(c)


@dataclass(frozen=True, slots=True)
class LawFit:
    """r = a + b/L^2 (mu = mu_1 (1 + gamma^2 r)) for one gamma, and the relative error bound of mu it gives."""

    gamma: float
    a: float
    b: float
    relative_error: float

    def r(self, c: float) -> float:
        return self.a + self.b / _log_ratio(c) ** 2


def _ratio(c: float, gamma: float, level: int) -> float:
    """r = (mu/mu_1 - 1)/gamma^2 from the solver at c; below ``SMALL_GAMMA`` from the small-gamma series, whose
    correction term it is over F0 (formed without the cancellation of mu/mu_1 - 1: the solver's own mu there carries
    a rounding that grows like 1/gamma^2, and r took it times 1/gamma^2 more: the law was 5 % off at nu = 0.4999999
    and its stick width not bracketed at nu = 0.499999999999)."""
    if gamma < SMALL_GAMMA:
        series = gamma_series(c, 1.0 - c, level)
        return series.correction(gamma) / series.first_order
    mu = solve_given_c(c, 1.0 - c, gamma, level).field.mu
    return (mu / (gamma * float(mu_over_gamma_plane(c))) - 1.0) / gamma**2


def _through(c1: float, r1: float, c2: float, r2: float) -> tuple[float, float]:
    """a, b of r = a + b/L^2 through two points."""
    s1, s2 = _log_ratio(c1) ** -2, _log_ratio(c2) ** -2
    b = (r1 - r2) / (s1 - s2)
    return r2 - b * s2, b


@lru_cache(maxsize=64)
def law_fit(gamma: float, level: int) -> LawFit:
    """The law's a, b for gamma from three solver solves at ``LAW_NODES`` (kept per gamma and level)."""
    c0, c1, c2 = LAW_NODES
    r0, r1, r2 = (_ratio(c, gamma, level) for c in LAW_NODES)
    a, b = _through(c1, r1, c2, r2)
    a_coarse, _ = _through(c0, r0, c1, r1)
    return LawFit(gamma, a, b, LAW_ERROR_FACTOR * gamma**2 * abs(a - a_coarse) + ROUNDING_FLOOR)


def law_friction_coefficient(c: float, gamma: float, level: int) -> tuple[float, float]:
    """mu for stick width 0 < c < C_SMALLEST and its absolute error bound."""
    fit = law_fit(gamma, level)
    mu = gamma * float(mu_over_gamma_plane(c)) * (1.0 + gamma**2 * fit.r(c))
    return mu, fit.relative_error * mu


def law_stick_width(mu: float, gamma: float, level: int) -> tuple[float, float]:
    """c for friction mu by the law (0.0 where it underflows) and its absolute error bound.

    Solves (pi/2) y (1 + gamma^2 (a + b y^2)) = mu/gamma for y = 1/L (K/K' = pi/(2 L) to c^2/(4 L) relative at
    these c), c = 4 exp(-1/y); a relative error e of mu moves L by about e L, so c by e L c. Only called where the
    answer lies below C_SMALLEST (the caller checks ``mu < law_friction_coefficient(C_SMALLEST)``)."""
    fit = law_fit(gamma, level)
    target = mu / gamma

    def excess(y: float) -> float:
        return 0.5 * math.pi * y * (1.0 + gamma**2 * (fit.a + fit.b * y * y)) - target

    y_top = 1.0 / _log_ratio(C_SMALLEST)
    if excess(y_top) <= 0.0:
        # mu is the law's at C_SMALLEST to within K/K' = pi/(2 L)'s relative c^2/(4 L) (2e-12 there) or rounding: the
        # hand-over point itself (brentq found no bracket: the round trip of c = 1e-5 failed at nu = 0.2, 0.44)
        return C_SMALLEST, fit.relative_error * _log_ratio(C_SMALLEST) * C_SMALLEST
    y = optimize.brentq(excess, 0.0, y_top, xtol=1e-300, rtol=4.0 * np.finfo(float).eps)
    if y == 0.0:  # mu/gamma at the bottom of the doubles (mu = 5e-324): L beyond them, c = 0 (it raised ZeroDivisionError)
        return 0.0, 0.0
    big_l = 1.0 / y
    c = 4.0 * math.exp(-big_l)
    return c, fit.relative_error * big_l * c


class FullSlipField:
    """The stresses of the law route: full inward slip at |x| >= OUTER_FACTOR c (``pressure_full_slip``)."""

    def __init__(self, gamma: float, mu: float, c: float) -> None:
        self.gamma, self.mu, self.c = gamma, mu, c
        self.alpha = math.atan(mu * gamma) / math.pi

    def check(self, ax: np.ndarray) -> None:
        """ValueError naming x where |x| < OUTER_FACTOR c (the stick zone and its neighbourhood) or x = 0."""
        near = (ax < OUTER_FACTOR * self.c) | (ax == 0.0)
        if np.any(near):
            where = (f"|x| >= {OUTER_FACTOR * self.c:.3g} ({OUTER_FACTOR:g} c) only" if self.c > 0.0 else
                     "x != 0 only (c underflows to 0; the full-slip pressure is singular at the centre)")
            raise ValueError(
                f"x = {float(ax[near][0]):.3g} is not resolved: the stick half-width c = {self.c:.3g} is below the "
                f"solver's smallest ({C_SMALLEST:g}), and this route (full slip away from the stick zone) gives the "
                f"stresses at {where}")

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ax = np.abs(x)
        self.check(ax)
        p = np.asarray(pressure_full_slip(ax, self.alpha), dtype=float)
        return p, self.mu * np.sign(x) * p

    def edge_pressure_shear(self, u: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p, q at t = 1 - u^2 > 0 (both given: 1 - t^2 = u^2 (2 - u^2) formed from u, t^(-2 alpha) from t). Used by
        integrals over t, where the neighbourhood of the stick zone has a share of order c (no check)."""
        p = (math.cos(math.pi * self.alpha) / math.pi) * (u * u * (2.0 - u * u)) ** (self.alpha - 0.5) * t ** (
            -2.0 * self.alpha)
        return p, self.mu * p

    def slip(self, x: np.ndarray) -> np.ndarray:
        raise NotImplementedError(
            f"the slip displacement is not computed below the solver's smallest stick width (c = {self.c:.3g} < "
            f"{C_SMALLEST:g})")
