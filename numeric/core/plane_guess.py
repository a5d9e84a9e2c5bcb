"""The plane solver's starting guess: theta = atan(mu gamma) of the strip punch over the (c, gamma) plane.

The stored functions are Chebyshev series (``plane_guess_data``, written by ``derivations/build_plane_guess.py`` from
level-2 solves) over three regions, each a rectangle in coordinates in which they are smooth:

- S: c from C_MIN to 1 - GAP_S, in u = logit c and gamma^2 (mu is even in the sign of gamma). Stored: the ratio to
  the first-order law, R = gamma^2 cot(theta) / w, w = K'(c)/K(c) (``asymptotics.plane``: tan(theta) = gamma^2 / w),
  1 - O(gamma^2) as c -> 0 and smooth through the largest stick width c_max(gamma), where it vanishes.
- N (small gamma, up to GAMMA_N, where c_max lies far above): 1 - c from GAP_N to GAP_S, in u = log(1 - c) and
  gamma^2. Stored: R.
- L (near c_max, gamma from GAMMA_N): 1 - c from 1 - c_max to GAP_S, in u = log(1 + x), x = log((1 - c)/(1 - c_max))
  (the approach to c_max, 1 - c - (1 - c_max) ~ A/(mu gamma), spread out), and gamma. Stored: x tan(theta), finite at
  c_max. 1 - c_max(gamma) is itself a series in gamma, of h = atanh(gamma) log(8/(1 - c_max)) (smooth: 1 - c_max
  falls like exp(-pi/(k eps)), eps = atanh(gamma)/pi), from the limit problem (``numeric.solutions.plane_solver``).
  Below the band (where 1 - c_max < 1.7e-12) ``gap_max`` continues it by the limit problem's small-gamma form
  h = pi^2/2 - 2 log 2 gamma - b1 gamma^3 - ... (``gap_max_small_gamma``, fitted to the solves at gamma = 0.13 ... 0.3).

Outside them (c below C_MIN, gamma below GAMMA_N with 1 - c below GAP_N, c above the tabulated c_max) ``theta_guess``
returns None and the caller starts from the first-order law or the approach to c_max. The worst relative error in mu
at held-out points (random ones and a grid near each region's ends), measured by the build against fresh level-2 solves,
is ``plane_guess_data.ERRORS``: 6.1e-9 in S (44 x 18 nodes; 7.2e-11 at the random points, the worst at its end c =
C_MIN, gamma = 0.017), 1.2e-10 in N (24 x 11) and 5.7e-8 in L (52 x 24; 2.9e-10 at the random points, the worst next
to c_max, x = -0.999 in L's unit coordinate, gamma = 0.75, beyond the outermost node). On a 9 x 13 grid over L the guess
is within 1e-9 for x >= -0.95, 5e-10 ... 4e-9 at x = -0.99 and 8e-9 ... 6e-8 at x = -0.999 (1 - c within 0.1 % of
1 - c_max; in theta, where mu gamma ~ 1e3, ~1e-11).

Before (32 x 14, 24 x 8 and 36 x 24 nodes, random held-out points only: 5.2e-10, 6.9e-9, 3.7e-8) L was up to 3e-7 off
on that grid next to c_max and along gamma = 0.16: L's coordinate divides by x = log((1 - c)/(1 - c_max)), and the
series of 1 - c_max (16 nodes) was 2e-10 ... 8e-10 off fresh limit solves (28 nodes: 6e-13); and the build's careful
solves stopped at a tolerance in theta that is loose in mu next to pi/2 (now polished, ``careful_theta``). Given mu,
one given-c solve suffices where the guess lies within the solve's own scatter of theta (``THETA_SCATTER`` of
``numeric.solutions.plane_solver``, 5e-11): at 69 of 70 points now, 28 before (the benchmark's 11 cases and 59 random
(nu, c), nu in [-0.9, 0.45], c in [0.02, 0.97]), near c_max included.

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
from numpy.polynomial import chebyshev
from scipy import special

from numeric.core import plane_guess_data as data

__all__ = ["SMALL_GAMMA_GAP_MAX", "SMALL_GAMMA_GAP_MAX_H_ERROR", "gap_max_small_gamma", "gap_max_relative_error",
           "elliptic_ratio", "GuessRegion", "REGIONS", "region_of", "coordinate", "gap_and_c",
           "stored_value", "theta_from_stored", "u_range", "gap_max", "gap_max_stored", "GAP_MAX_RANGE", "chebyshev_nodes",
           "Guess", "theta_guess", "stick_width_guess"]


#: h(gamma) = atanh(gamma) log(8 / (1 - c_max)) as gamma -> 0: pi^2/2 - gamma (2 log 2 + b1 gamma^2 + b2 gamma^4 +
#: b3 gamma^6); these are (2 log 2, b1, b2, b3). Fitted (least squares, b1 ... b3 only) to the limit problem solved at
#: level 3 (``numeric.solutions.plane_solver.solve_limit``) at 13 gamma from 0.13 to 0.3: residuals in h below 2.2e-8
#: (level 2 gives the same h to 3.3e-9), 1.4e-8 at gamma = 0.2 left out of the fit; it meets the table's series at
#: gamma = 0.16 to 2.4e-9 relative in 1 - c_max. pi^2/2 and 2 log 2 are what the solves give, not a proof: a
#: polynomial in gamma fitted freely (degree 5 and 6, gamma <= 0.25 or 0.3) has h(0) - pi^2/2 = -1.4e-5 ... 4.0e-6,
#: h'(0) + 2 log 2 = -1.4e-4 ... 4.8e-4 and h''(0) = -6.7e-3 ... 2.0e-3 (h - pi^2/2 is odd in gamma); with h(0) =
#: pi^2/2 held, the odd fit's h'(0) is -2 log 2 to 3e-8 (gamma <= 0.25) and 4e-7 (<= 0.3). (The axisymmetric relation
#: has h = pi^2/2 exactly, ``asymptotics.largest_stick_radius``; in the plane 1 - c_max -> 32 exp(-pi^2/(2 atanh
#: gamma)) as gamma -> 0.)
SMALL_GAMMA_GAP_MAX = (2.0 * math.log(2.0), 0.21850366, 0.09788115, 0.05657238)
#: Bound of |h - h_true| for the small-gamma form below the table's band: the free fits' scatter of h(0) about pi^2/2
#: (1.4e-5 at most), not the residuals (2.2e-8): the relative error of 1 - c_max is taken as expm1(it / atanh(gamma)),
#: 1.3e-4 where 1 - c_max = 2^-40 (gamma = 0.157), growing to 3e-3 where it underflows (gamma = 0.007).
SMALL_GAMMA_GAP_MAX_H_ERROR = 2e-5


def gap_max_small_gamma(gamma: float) -> float:
    """1 - c_max(gamma) = 8 exp(-h(gamma)/atanh(gamma)), h = pi^2/2 - gamma (2 log 2 + b1 gamma^2 + ...)
    (``SMALL_GAMMA_GAP_MAX``): the limit problem's form as gamma -> 0 (0 at gamma = 0; it underflows to 0 below
    gamma ~ 0.007, where 1 - c_max < 1e-308)."""
    if gamma == 0.0:
        return 0.0
    h = 0.5 * math.pi**2 - gamma * float(np.polynomial.polynomial.polyval(gamma * gamma, SMALL_GAMMA_GAP_MAX))
    return 8.0 * math.exp(-h / math.atanh(gamma))


def gap_max_relative_error(gamma: float) -> float:
    """The relative error bound of ``gap_max`` below the table's band (the small-gamma form): expm1 of
    ``SMALL_GAMMA_GAP_MAX_H_ERROR`` / atanh(gamma) (inf at gamma = 0, where 1 - c_max = 0)."""
    exponent = math.inf if gamma == 0.0 else SMALL_GAMMA_GAP_MAX_H_ERROR / math.atanh(gamma)
    return math.expm1(exponent) if exponent < 700.0 else math.inf  # (1 - c_max underflows long before)


def elliptic_ratio(c: float, gap: float) -> float:
    """w = K'(c)/K(c) (modulus c) for c = 1 - gap, without the cancellation of 1 - c^2 = gap (1 + c)."""
    return float(special.ellipkm1(c * c) / special.ellipkm1(gap * (1.0 + c)))


def chebyshev_nodes(n: int) -> np.ndarray:
    """n Chebyshev points of the first kind on [-1, 1] (descending)."""
    return np.cos(math.pi * (np.arange(n) + 0.5) / n)


@dataclass(frozen=True, slots=True)
class GuessRegion:
    """One rectangle of the table: its coordinate u ("logit_c", "log_gap", "log_gap_ratio"), its band of gamma and
    whether the gamma coordinate is gamma^2."""

    name: str
    coordinate: str
    gamma_range: tuple[float, float]
    gamma_squared: bool


REGIONS: dict[str, GuessRegion] = {name: GuessRegion(name, coordinate, tuple(band), squared)
                                   for name, (coordinate, band, squared) in data.REGIONS.items()}
#: The band of gamma of the series of 1 - c_max (that of region L).
GAP_MAX_RANGE = REGIONS["L"].gamma_range


def gap_max_stored(gamma: float, gap_max_value: float) -> float:
    """The stored function of 1 - c_max: h = atanh(gamma) log(8 / (1 - c_max))."""
    return math.atanh(gamma) * (math.log(8.0) - math.log(gap_max_value))


def _series(coefficients: np.ndarray, t: float) -> float:
    """The Chebyshev series at t (nan for an empty one: the table being built)."""
    return float(chebyshev.chebval(t, coefficients)) if len(coefficients) else math.nan


def _unit(value: float, lo: float, hi: float) -> float:
    return 2.0 * (value - lo) / (hi - lo) - 1.0


def gap_max(gamma: float) -> float:
    """1 - c_max(gamma) for 0 <= gamma <= GAMMA_MAX: the table's series in its band (GAMMA_N ... GAMMA_MAX, from
    level-2 solves of the limit problem), the small-gamma form ``gap_max_small_gamma`` below it (and while the table
    is being built)."""
    g0, g1 = GAP_MAX_RANGE
    if g0 <= gamma <= g1 and len(data.GAP_MAX_SERIES):
        h = _series(np.asarray(data.GAP_MAX_SERIES), _unit(gamma, g0, g1))
        return 8.0 * math.exp(-h / math.atanh(gamma))
    return gap_max_small_gamma(gamma)


def u_range(region: GuessRegion, gamma: float) -> tuple[float, float]:
    """The ends of u in region at gamma."""
    if region.coordinate == "logit_c":
        return math.log(data.C_MIN) - math.log1p(-data.C_MIN), math.log1p(-data.GAP_S) - math.log(data.GAP_S)
    if region.coordinate == "log_gap":
        return math.log(data.GAP_N), math.log(data.GAP_S)
    return 0.0, math.log1p(math.log(data.GAP_S / gap_max(gamma)))


def coordinate(region: GuessRegion, c: float, gap: float, gamma: float) -> float:
    """u of region at c = 1 - gap (see the module docstring)."""
    if region.coordinate == "logit_c":
        return math.log(c) - math.log(gap)
    if region.coordinate == "log_gap":
        return math.log(gap)
    return math.log1p(math.log(gap / gap_max(gamma)))


def gap_and_c(region: GuessRegion, u: float, gamma: float) -> tuple[float, float]:
    """1 - c and c at u of region (each without cancellation)."""
    if region.coordinate == "logit_c":
        return 1.0 / (1.0 + math.exp(u)), 1.0 / (1.0 + math.exp(-u))
    gap = math.exp(u) if region.coordinate == "log_gap" else gap_max(gamma) * math.exp(math.expm1(u))
    return gap, 1.0 - gap


def stored_value(region: GuessRegion, c: float, gap: float, gamma: float, theta: float) -> float:
    """The stored function at (c, gamma) for theta: R = gamma^2 cot(theta) / w (S, N), x tan(theta) (L)."""
    if region.coordinate == "log_gap_ratio":
        return math.log(gap / gap_max(gamma)) * math.tan(theta)
    return gamma * gamma / (math.tan(theta) * elliptic_ratio(c, gap))


def theta_from_stored(region: GuessRegion, c: float, gap: float, gamma: float, value: float) -> float:
    """The inverse of ``stored_value``."""
    if region.coordinate == "log_gap_ratio":
        return math.atan(value / math.log(gap / gap_max(gamma)))
    return math.atan(gamma * gamma / (value * elliptic_ratio(c, gap)))


def region_of(c: float, gap: float, gamma: float) -> GuessRegion | None:
    """The region holding (c, gamma), or None."""
    if c < data.C_MIN or not 0.0 < gamma <= data.GAMMA_MAX or not data.COEFFICIENTS:
        return None
    if gap >= data.GAP_S:
        return REGIONS["S"]
    if gamma <= data.GAMMA_N:
        return REGIONS["N"] if gap >= data.GAP_N else None
    return REGIONS["L"] if gap > gap_max(gamma) else None


@lru_cache(maxsize=64)
def _x_series(name: str, gamma: float) -> np.ndarray:
    """Region ``name``'s series in x at this gamma (the gamma direction summed once)."""
    region = REGIONS[name]
    g0, g1 = region.gamma_range
    y = _unit(gamma * gamma, g0 * g0, g1 * g1) if region.gamma_squared else _unit(gamma, g0, g1)
    a = np.asarray(data.COEFFICIENTS[name])  # (nx, ny)
    return a @ chebyshev.chebvander(np.array([y]), a.shape[1] - 1)[0]


@dataclass(frozen=True, slots=True)
class Guess:
    """theta at (c, gamma) from the table and d theta / d logit c there."""

    theta: float
    slope: float


def _theta_at(region: GuessRegion, u: float, gamma: float, bounds: tuple[float, float]) -> tuple[float, float, float]:
    """theta, c and 1 - c at u of region (``bounds``: its u range at this gamma)."""
    lo, hi = bounds
    gap, c = gap_and_c(region, u, gamma)
    value = _series(_x_series(region.name, gamma), _unit(u, lo, hi))
    return theta_from_stored(region, c, gap, gamma, value), c, gap


#: Step in u (relative to the region's range) of the central difference that gives d theta / du.
SLOPE_STEP = 1e-5


def _evaluate(region: GuessRegion, u: float, gamma: float) -> tuple[float, float, float, float]:
    """theta, d theta / du (a central difference of the series, ~1e-10 relative), c and 1 - c at u of region."""
    bounds = u_range(region, gamma)
    h = SLOPE_STEP * (bounds[1] - bounds[0])
    theta, c, gap = _theta_at(region, u, gamma, bounds)
    slope = (_theta_at(region, u + h, gamma, bounds)[0] - _theta_at(region, u - h, gamma, bounds)[0]) / (2.0 * h)
    return theta, slope, c, gap


def _du_dxi(region: GuessRegion, u: float, c: float) -> float:
    """d u / d logit c: 1 (S), -c (N: d log(1 - c) = -c d logit c), -c exp(-u) (L: u = log(1 + x), dx = -c d logit c)."""
    if region.coordinate == "logit_c":
        return 1.0
    if region.coordinate == "log_gap":
        return -c
    return -c * math.exp(-u)


def theta_guess(c: float, gap: float, gamma: float) -> Guess | None:
    """theta = atan(mu gamma) and d theta / d logit c for stick half-width c = 1 - gap, or None outside the table."""
    region = region_of(c, gap, gamma)
    if region is None:
        return None
    u = coordinate(region, c, gap, gamma)
    theta, slope, _, _ = _evaluate(region, u, gamma)
    return Guess(theta, slope * _du_dxi(region, u, c))


def stick_width_guess(theta: float, gamma: float) -> tuple[float, float, Guess] | None:
    """c, 1 - c and the table's theta and d theta / d logit c there, where the table's theta is ``theta`` (Newton in
    u on the series, kept in the region's range by bisection); None where the table does not reach."""
    if not 0.0 < gamma <= data.GAMMA_MAX or not 0.0 < theta < 0.5 * math.pi:
        return None
    names = ("S", "N") if gamma <= data.GAMMA_N else ("S", "L")
    for slack in (0.0, END_SLACK):  # within a region; else within END_SLACK beyond an end, taken at that end
        for name in names:
            found = _in_region(REGIONS[name], theta, gamma, slack)
            if found is not None:
                return found
    return None


#: theta up to this far (relative) beyond an end of the table is taken at that end: a theta from the solver's mu at the
#: table's smallest c (the hand-over to the law below c = 1e-5) lies beyond the table's own by its error (5e-10),
#: where the secant in c from the first-order law (3 % off there) did not converge (nu = 0.4).
END_SLACK = 1e-6


def _in_region(region: GuessRegion, theta: float, gamma: float, slack: float) -> tuple[float, float, Guess] | None:
    """``stick_width_guess`` in one region; theta within ``slack`` (relative) beyond an end is taken at the end."""
    lo, hi = u_range(region, gamma)
    if region.coordinate == "log_gap_ratio":
        lo = 1e-12 * hi  # u = 0 is c_max, the limit mu -> inf
    a, b = (lo, hi) if region.coordinate == "logit_c" else (hi, lo)  # theta increases from a to b
    ta, tb = _evaluate(region, a, gamma)[0], _evaluate(region, b, gamma)[0]
    if not ta * (1.0 - slack) <= theta <= tb * (1.0 + slack):
        return None
    theta = min(max(theta, ta), tb)
    u = a + (b - a) * (theta - ta) / (tb - ta)
    for _ in range(60):
        value, slope = _evaluate(region, u, gamma)[:2]
        if value < theta:
            a = u
        else:
            b = u
        new = u + (theta - value) / slope if slope != 0.0 else math.nan
        if not min(a, b) <= new <= max(a, b):
            new = 0.5 * (a + b)
        done = abs(new - u) <= 1e-14 * max(1.0, abs(u))
        u = new
        if done:
            break
    value, slope, c, gap = _evaluate(region, u, gamma)
    return c, gap, Guess(value, slope * _du_dxi(region, u, c))
