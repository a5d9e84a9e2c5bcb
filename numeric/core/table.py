"""The whole-plane tables: mu, c, P*, p(0) and the sphere's and cone's A and C as Chebyshev interpolants.

Built from level-3 solutions by ``derivations/build_tables.py`` (``numeric/core/table_data.py``),
in three regions of the (c, gamma) plane, each a rectangle in coordinates in which the stored
functions are smooth (analytic beyond the rectangle, so that Chebyshev series converge
geometrically):

- S (the box): c in [C_MIN, C_BOX], gamma in [0, GAMMA_MAX], in u = logit(c) and gamma^2.
  Stored: log(mu/(gamma f0(c))) (f0 the first-order law (2.28)), P*, p(0), A and
  c^(n-1) C/gamma for n = 2, 1 (C is odd in gamma and grows like 1/c for the sphere).
- N (near full stick, small gamma): 1 - c in [GAP_MIN, 1 - C_BOX], gamma in [0, GAMMA_L], in
  u = log(1 - c) and gamma^2. Stored as in S with f0 replaced by its limit log(2/(1 - c))/pi,
  which is exact in 1 - c (c itself has lost the digits of 1 - c there).
- L0, L1 (near the largest stick radius): gamma in [GAMMA_L, GAMMA_SPLIT] and [GAMMA_SPLIT, GAMMA_MAX],
  c from C_BOX to c_max(gamma), in w = log((1 - c)/(1 - c_max)) in [0, W_B(gamma)]
  (W_B = log((1 - C_BOX)/(1 - c_max)), closed form, ``asymptotics.largest_stick_radius``) and gamma.
  Stored: w mu gamma (finite at mu = inf, w = 0, where 1 - c - (1 - c_max) ~ A/(mu gamma), the
  approach), P*, p(0), A and C. mu = inf is the regular end w = 0 of these regions.

Each region may be cut into pieces along its x = [-1, 1] (``Region.pieces``), each with its own
series: mu has poles in w at +-2 pi i (where 1 - c = 1 - c_max again), and W_B reaches 39 at
gamma = GAMMA_L, so one series over [0, W_B] would converge like 1.4^-n; the gamma bands keep the
essential singularity at gamma = 0 (1 - c_max ~ 8 exp(-pi/kappa)) and the one at gamma = 1 far away.

Below c = C_MIN the asymptotic law answers (``numeric.solutions.law``); at gamma < GAMMA_L and
1 - c < GAP_MIN the adhesive solution does (``numeric.solutions.solver.GAP_ADHESIVE``). Inside,
every quantity is given to the worst error measured at held-out points by the build
(``table_errors``). c for given mu comes from a vectorised Newton iteration on the interpolant,
safeguarded by bisection (mu increases with c, §2.1).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.polynomial import chebyshev
from scipy import special

from asymptotics.first_order import mu_over_gamma, mu_over_gamma_log_slope
from asymptotics.largest_stick_radius import largest_stick_radius_gap

__all__ = ["QUANTITIES", "REGIONS", "Region", "make_regions", "u_range", "to_unit", "gap_and_c",
           "stored_eigen", "stored_quantity", "use_table_data", "table_available", "table_errors", "TableValues",
           "table_given_c", "table_given_mu", "table_least_mu", "table_friction_coefficient", "table_stick_radius", "table_compliance"]

QUANTITIES = ("compliance", "central_pressure", "sphere_A", "sphere_C", "cone_A", "cone_C")
"""What the table holds besides the eigenvalue relation (P*, p(0), A and C of n = 2 and n = 1)."""

_C_POWER = {"sphere_C": 1.0, "cone_C": 0.0}  # C stored as c^(n - 1) C / gamma in S and N


@dataclass(frozen=True)
class Region:
    """One rectangle of the table: its physical coordinate u (``coordinate``), the ends of gamma, and the
    breakpoints in x = [-1, 1] of its pieces."""

    name: str
    coordinate: str  # "logit_c", "log_gap" or "log_gap_ratio"
    gamma_range: tuple[float, float]
    gamma_squared: bool  # the gamma coordinate is gamma^2 (S, N: the functions are even in gamma) or gamma
    pieces: tuple[float, ...] = (-1.0, 1.0)


def make_regions(gamma_l: float, gamma_split: float, gamma_max: float) -> dict[str, Region]:
    """The regions of the table, S, N, L0 and L1, for its gamma constants (``table_data``)."""
    return {"S": Region("S", "logit_c", (0.0, gamma_max), True, (-1.0, 0.0, 1.0)),
            "N": Region("N", "log_gap", (0.0, gamma_l), True),
            "L0": Region("L0", "log_gap_ratio", (gamma_l, gamma_split), False, (-1.0, -0.5, 1.0)),
            "L1": Region("L1", "log_gap_ratio", (gamma_split, gamma_max), False, (-1.0, -0.5, 1.0))}


REGIONS = ("S", "N", "L0", "L1")


def piece_of(region: Region, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For x in [-1, 1]: the index of its piece, the local coordinate in [-1, 1] of that piece, and
    d(local)/dx."""
    edges = np.asarray(region.pieces)
    j = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, edges.size - 2)
    lo, hi = edges[j], edges[j + 1]
    return j, (2.0 * x - lo - hi) / (hi - lo), 2.0 / (hi - lo)


def u_range(region: Region, gamma: np.ndarray, c_min: float, c_box: float, gap_min: float) -> tuple[np.ndarray, np.ndarray]:
    """The ends of u in region at gamma (arrays)."""
    gamma = np.asarray(gamma, dtype=float)
    if region.coordinate == "logit_c":
        lo, hi = special.logit(c_min), special.logit(c_box)
    elif region.coordinate == "log_gap":
        lo, hi = math.log(gap_min), math.log1p(-c_box)
    else:
        lo, hi = 0.0, math.log1p(-c_box) - np.log(largest_stick_radius_gap(gamma))
    return np.broadcast_to(np.asarray(lo, dtype=float), gamma.shape), np.broadcast_to(np.asarray(hi, dtype=float), gamma.shape)


def to_unit(region: Region, u: np.ndarray, gamma: np.ndarray, ends: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) in [-1, 1]^2 for u and gamma."""
    lo, hi = ends
    g0, g1 = region.gamma_range
    g = np.asarray(gamma, dtype=float)
    y = 2.0 * (g * g - g0 * g0) / (g1 * g1 - g0 * g0) - 1.0 if region.gamma_squared else 2.0 * (g - g0) / (g1 - g0) - 1.0
    return 2.0 * (u - lo) / (hi - lo) - 1.0, y


def gap_and_c(region: Region, u: np.ndarray, gamma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """1 - c and c (each without cancellation) at u."""
    if region.coordinate == "logit_c":
        return special.expit(-u), special.expit(u)
    gap = np.exp(u) if region.coordinate == "log_gap" else largest_stick_radius_gap(gamma) * np.exp(u)
    return gap, 1.0 - gap


def log_mu_and_slope(region: Region, u: np.ndarray, gamma: np.ndarray, stored: np.ndarray, stored_slope: np.ndarray
                     ) -> tuple[np.ndarray, np.ndarray]:
    """log mu and d log mu/du from the stored eigenvalue function F and dF/du (see the module docstring)."""
    if region.coordinate == "log_gap_ratio":  # F = w mu gamma
        with np.errstate(divide="ignore"):
            return np.log(stored) - np.log(u) - np.log(gamma), stored_slope / stored - 1.0 / u
    gap, c = gap_and_c(region, u, gamma)
    if region.coordinate == "logit_c":  # F = log(mu/(gamma f0(c)))
        log_law = np.log(np.asarray(mu_over_gamma(c), dtype=float))
        law_slope = np.asarray(mu_over_gamma_log_slope(c), dtype=float) * gap  # d log f0/d logit c
    else:  # F = log(mu/(gamma l(1 - c))), l = log(2/(1 - c))/pi
        log_law = np.log((math.log(2.0) - u) / math.pi)
        law_slope = -1.0 / (math.log(2.0) - u)
    return np.log(gamma) + log_law + stored, law_slope + stored_slope


def stored_eigen(region: Region, u: np.ndarray, gamma: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """The stored eigenvalue function F at u for friction mu (the build's side of ``log_mu_and_slope``)."""
    if region.coordinate == "log_gap_ratio":
        return u * mu * gamma
    return np.log(mu) - log_mu_and_slope(region, u, gamma, np.zeros_like(u), np.zeros_like(u))[0]


def stored_quantity(region: Region, name: str, value: np.ndarray, c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """A quantity as stored (C scaled in S and N); ``physical_quantity`` undoes it."""
    if name in _C_POWER and region.gamma_squared:
        return value * c ** _C_POWER[name] / gamma
    return value


def physical_quantity(region: Region, name: str, stored: np.ndarray, c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """A quantity from its stored form."""
    if name in _C_POWER and region.gamma_squared:
        return stored * gamma / c ** _C_POWER[name]
    return stored


_SOURCE: list = []  # the data module in use: numeric.core.table_data, or one given to ``use_table_data``


def use_table_data(module) -> None:
    """Evaluate the tables of ``module`` (a freshly built table_data) instead of the committed ones (None: those)."""
    _SOURCE[:] = [] if module is None else [module]
    _data.cache_clear()


@lru_cache(maxsize=1)
def _data():
    if _SOURCE:
        data = _SOURCE[0]
    else:
        from numeric.core import table_data as data  # generated; imported on first use only
    constants = (data.C_MIN, data.C_BOX, data.GAP_MIN)
    found = make_regions(data.GAMMA_L, data.GAMMA_SPLIT, data.GAMMA_MAX)
    coefficients = {name: {k: [np.array(piece) for piece in v] for k, v in data.COEFFICIENTS[name].items()}
                    for name in REGIONS}
    return data, constants, found, coefficients


def table_available() -> bool:
    """Whether the generated table module is present (and of this format)."""
    try:
        _data()
    except (ImportError, AttributeError, KeyError):
        return False
    return True


def table_errors() -> dict[str, float]:
    """The worst errors the build measured at held-out points (empty without a table): relative for
    mu, c, 1 - c (``gap``) and A; absolute for P*, p(0) and C."""
    return dict(_data()[0].ERRORS or {}) if table_available() else {}


@dataclass(frozen=True)
class TableValues:
    """mu, c, 1 - c and the QUANTITIES at a set of points (nan where the table does not reach)."""

    mu: np.ndarray
    c: np.ndarray
    gap: np.ndarray
    values: dict[str, np.ndarray]


def _empty(n: int) -> TableValues:
    return TableValues(np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan), {k: np.full(n, np.nan) for k in QUANTITIES})


class _Slice:
    """Region ``name`` at a set of gamma: the Chebyshev series in x of each stored function, per point."""

    def __init__(self, name: str, gamma: np.ndarray) -> None:
        data, constants, found, coefficients = _data()
        self.region, self.gamma = found[name], gamma
        self.ends = u_range(self.region, gamma, *constants)
        self.y = to_unit(self.region, self.ends[0], gamma, self.ends)[1]
        self.coefficients = coefficients[name]
        self._series: dict[str, list[np.ndarray]] = {}

    def series(self, key: str) -> list[np.ndarray]:
        """Per piece: the coefficients in x of stored function ``key`` at each point's gamma, shape
        (points, degree in x + 1); summed over gamma on first use only (what the caller asks for)."""
        if key not in self._series:
            self._series[key] = [chebyshev.chebval(self.y, a.T, tensor=True).T for a in self.coefficients[key]]
        return self._series[key]

    def subset(self, keep: np.ndarray) -> "_Slice":
        """The slice at the points ``keep`` (a boolean mask), sharing the series summed so far."""
        part = object.__new__(_Slice)
        part.region, part.gamma, part.y, part.coefficients = self.region, self.gamma[keep], self.y[keep], self.coefficients
        part.ends = (self.ends[0][keep], self.ends[1][keep])
        part._series = {k: [a[keep] for a in v] for k, v in self._series.items()}
        return part

    def x_of(self, u: np.ndarray) -> np.ndarray:
        return to_unit(self.region, u, self.gamma, self.ends)[0]

    def u_of(self, x: np.ndarray) -> np.ndarray:
        lo, hi = self.ends
        return lo + 0.5 * (x + 1.0) * (hi - lo)

    def value(self, key: str, x: np.ndarray, derivative: bool = False) -> np.ndarray:
        """The stored function ``key`` at x (or its derivative in u), each point in its own piece."""
        j, t, dt_dx = piece_of(self.region, x)
        out = np.empty(x.shape)
        for k, a in enumerate(self.series(key)):
            rows = np.flatnonzero(j == k)
            if rows.size == 0:
                continue
            b = a[rows]
            if derivative:  # d/du = d/dt dt/dx dx/du
                b = chebyshev.chebder(b, axis=1) * (dt_dx[rows] * 2.0 / (self.ends[1][rows] - self.ends[0][rows]))[:, None]
            out[rows] = np.einsum("pk,pk->p", b, chebyshev.chebvander(t[rows], b.shape[1] - 1))
        return out

    def log_mu(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = self.u_of(x)
        return log_mu_and_slope(self.region, u, self.gamma, self.value("eigen", x), self.value("eigen", x, True))

    def fill(self, out: TableValues, rows: np.ndarray, x: np.ndarray, mu: np.ndarray | None,
             quantities: tuple[str, ...] = QUANTITIES) -> None:
        u = self.u_of(x)
        gap, c = gap_and_c(self.region, u, self.gamma)
        out.gap[rows], out.c[rows] = gap, c
        out.mu[rows] = np.exp(self.log_mu(x)[0]) if mu is None else mu
        for name in quantities:
            out.values[name][rows] = physical_quantity(self.region, name, self.value(name, x), c, self.gamma)


def _newton(f: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]], x: np.ndarray, steps: int = 60,
            tol: float = 1e-15, ftol: float = 1e-14) -> np.ndarray:
    """Roots in [-1, 1] of increasing f (value, derivative) = f(x), vectorised: Newton steps kept in the
    bracket (bisection where a step would leave it), the bracket narrowed by the sign of f; a point is done
    when its step is below tol or |f| below ftol (f = log mu - its goal: 1e-14 relative in mu, far below
    the table's own error; without it points whose last steps wander by rounding ran all 60 steps)."""
    lo, hi = np.full(x.shape, -1.0), np.ones(x.shape)
    active = np.ones(x.shape, dtype=bool)
    for _ in range(steps):
        value, slope = f(x)
        lo = np.where(value < 0.0, x, lo)
        hi = np.where(value > 0.0, x, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            new = x - value / slope
        outside = ~((new >= lo) & (new <= hi)) | ~np.isfinite(new)
        new = np.where(outside, 0.5 * (lo + hi), new)
        active &= ~((np.abs(new - x) <= tol) | (np.abs(value) <= ftol))
        x = np.where(active, new, x)  # a converged point stays (a bisection step would throw it off)
        if not active.any():
            break
    return x


def _gamma_in(region: Region, gamma: np.ndarray) -> np.ndarray:
    g0, g1 = region.gamma_range
    return (gamma > 0.0) & (gamma >= g0) & (gamma <= g1)


def _flat(a, b) -> tuple[np.ndarray, np.ndarray]:
    a, b = np.broadcast_arrays(np.atleast_1d(np.asarray(a, dtype=float)), np.atleast_1d(np.asarray(b, dtype=float)))
    return a.ravel(), b.ravel()


def table_given_c(c: np.ndarray, gamma: np.ndarray, gap: np.ndarray | None = None,
                  quantities: tuple[str, ...] = QUANTITIES) -> TableValues:
    """The tabulated values for stick radius c (nan outside the table's domain, and for the QUANTITIES not
    asked for); ``gap``: 1 - c where c has rounded it (near c = 1 the relative error of 1 - c is
    1e-16/(1 - c), and mu's is that over log(2/(1 - c)))."""
    c, gamma = _flat(c, gamma)
    out = _empty(c.size)
    if not table_available():
        return out
    _, (c_min, c_box, gap_min), found, _ = _data()
    gap = 1.0 - c if gap is None else np.broadcast_to(np.asarray(gap, dtype=float).ravel(), c.shape)
    gap_max = np.asarray(largest_stick_radius_gap(np.clip(gamma, 0.0, 1.0)), dtype=float)
    by_coordinate = {"logit_c": (c >= c_min) & (c <= c_box),
                     "log_gap": (c > c_box) & (gap >= gap_min),
                     "log_gap_ratio": (c > c_box) & (gap > gap_max)}
    where = {name: by_coordinate[found[name].coordinate] for name in REGIONS}
    taken = np.zeros(c.size, dtype=bool)
    for name in REGIONS:
        region = found[name]
        rows = np.flatnonzero(where[name] & _gamma_in(region, gamma) & ~taken)
        if rows.size == 0:
            continue
        taken[rows] = True
        piece = _Slice(name, gamma[rows])
        if region.coordinate == "logit_c":
            u = special.logit(c[rows])
        else:
            u = np.log(gap[rows]) if region.coordinate == "log_gap" else np.log(gap[rows] / gap_max[rows])
        piece.fill(out, rows, piece.x_of(u), None, quantities)
        out.c[rows], out.gap[rows] = c[rows], gap[rows]
    return out


def table_given_mu(mu: np.ndarray, gamma: np.ndarray, quantities: tuple[str, ...] = QUANTITIES) -> TableValues:
    """The tabulated values for friction mu (nan outside the table's domain, and for the QUANTITIES not asked
    for; mu = inf: c = c_max)."""
    mu, gamma = _flat(mu, gamma)
    out = _empty(mu.size)
    if not table_available():
        return out
    _, _, found, _ = _data()
    with np.errstate(divide="ignore", invalid="ignore"):
        target = np.log(mu)
    candidate = (mu > 0.0) & (gamma > 0.0)
    for name in REGIONS:  # S first; N, L0 and L1 take what lies above mu(C_BOX)
        region = found[name]
        rows = np.flatnonzero(candidate & _gamma_in(region, gamma))
        if region.coordinate == "log_gap_ratio":
            ends = rows[np.isinf(mu[rows])]
            if ends.size:
                _Slice(name, gamma[ends]).fill(out, ends, np.full(ends.size, -1.0), mu[ends], quantities)
                candidate[ends] = False
            rows = rows[np.isfinite(mu[rows])]
        if rows.size == 0:
            continue
        # log mu increases with x in S (u = logit c) and decreases in N and L (u = log 1 - c)
        sign = 1.0 if region.coordinate == "logit_c" else -1.0
        piece = _Slice(name, gamma[rows])
        low = piece.log_mu(np.full(rows.size, -sign))[0] > target[rows]  # mu below the region's least
        high = piece.log_mu(np.full(rows.size, sign))[0] < target[rows]  # mu above its greatest
        candidate[rows[~high]] = False  # answered here, or below the table (mu < mu(C_MIN): the law's)
        # only S has a lower end in mu; in N and L a mu a rounding below the end is the end's
        keep = ~(low | high) if region.coordinate == "logit_c" else ~high
        rows = rows[keep]
        if rows.size == 0:
            continue
        piece, goal = piece.subset(keep), target[rows]
        scale = 0.5 * (piece.ends[1] - piece.ends[0])

        def f(x, piece=piece, goal=goal, sign=sign, scale=scale):
            value, slope = piece.log_mu(x)
            return sign * (value - goal), sign * slope * scale

        piece.fill(out, rows, _newton(f, np.zeros(rows.size)), mu[rows], quantities)
    return out


def table_least_mu(gamma: float) -> float:
    """mu at the table's least stick radius C_MIN (nan without the table): below it c < C_MIN."""
    if not table_available() or not 0.0 < gamma <= _data()[2]["S"].gamma_range[1]:
        return math.nan
    return float(table_given_c(_data()[1][0], gamma, quantities=()).mu[0])


def table_friction_coefficient(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """mu(c, gamma) from the table (nan outside its domain)."""
    return table_given_c(c, gamma, quantities=()).mu


def table_compliance(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """P*(c, gamma) from the table (nan outside its domain)."""
    return table_given_c(c, gamma, quantities=("compliance",)).values["compliance"]


def table_stick_radius(mu: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """c(mu, gamma) from the table (nan outside its domain)."""
    return table_given_mu(mu, gamma, quantities=()).c
