"""The whole-plane tables: mu, c, P*, p(0) and the sphere's and cone's A and C as Chebyshev interpolants.

Built from level-3 solutions by ``derivations/build_tables.py`` (``numeric/core/table_data.py``),
over regions of the (c, gamma) plane, each a rectangle in coordinates in which the stored
functions are smooth (analytic beyond the rectangle, so that Chebyshev series converge
geometrically), cut into pieces along the first coordinate and into bands of gamma:

- S: c from C_MIN to the box edge 1 - box_gap(gamma), in u = logit(c) and gamma^2. Stored: log(mu/gamma)
  (the first-order law (2.28) is the gamma -> 0 limit), P*, p(0), A and c^(n-1) C/gamma for n = 2, 1
  (C is odd in gamma and grows like 1/c for the sphere).
- N (near full stick, small gamma): 1 - c from GAP_MIN to box_gap(gamma), in u = log(1 - c) and gamma^2,
  stored as in S (c itself has lost the digits of 1 - c there).
- L (near the largest stick radius, gamma >= its lower band edge): c from the box edge to c_max(gamma),
  in w = log((1 - c)/(1 - c_max)) in [0, log(box_gap/(1 - c_max))] (closed form,
  ``asymptotics.largest_stick_radius``) and gamma. Stored: w mu gamma (finite at mu = inf, w = 0, where
  1 - c - (1 - c_max) ~ A/(mu gamma), the approach), P*, p(0), A and C.

The box edge box_gap(gamma) = GAP_BOX + GAP_BOX_RISE (gamma / GAMMA_MAX)^4 keeps S a safe distance from
c_max(gamma), which comes down to 0.95 at gamma = 3/4 (mu(c) is singular there): an even polynomial in
gamma, so the regions stay analytic in gamma^2. mu has poles in w at +-2 pi i (where 1 - c = 1 - c_max
again), so the L regions are cut into pieces of width about 2 pi. The regions, their bands and pieces
are data of the build (``table_data.REGIONS``).

Evaluation is a tensor product of Chebyshev polynomials per point, T(x) A T(y); no special functions.
c for given mu comes from a vectorised Newton iteration on the interpolant, safeguarded by
bisection (mu increases with c, §2.1). Below c = C_MIN the asymptotic law answers
(``numeric.solutions.law``); at gamma below the L bands and 1 - c < GAP_MIN the adhesive solution does
(``numeric.solutions.solver.GAP_ADHESIVE``). Inside, every quantity is given to the worst error
measured at held-out points by the build (``table_errors``).

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
from pathlib import Path

import numpy as np
from numpy.polynomial import chebyshev

from asymptotics.largest_stick_radius import largest_stick_radius_gap

from numeric.core.generated_data import GeneratedData

__all__ = ["QUANTITIES", "Region", "Constants", "regions", "box_gap", "u_range", "to_unit", "gap_and_c", "stored_eigen",
           "stored_quantity", "chebyshev_matrix", "coefficients_of", "use_table_data", "table_available", "table_errors", "TableValues",
           "table_given_c", "table_given_mu", "table_least_c", "table_least_mu", "table_friction_coefficient", "table_stick_radius",
           "table_compliance"]

QUANTITIES = ("compliance", "central_pressure", "sphere_A", "sphere_C", "cone_A", "cone_C")
"""What the table holds besides the eigenvalue relation (P*, p(0), A and C of n = 2 and n = 1)."""

_C_POWER = {"sphere_C": 1.0, "cone_C": 0.0}  # C stored as c^(n - 1) C / gamma in S and N
_COORDINATES = ("logit_c", "log_gap", "log_gap_ratio")


@dataclass(frozen=True)
class Region:
    """One rectangle of the table: its coordinate u (``coordinate``: "logit_c", "log_gap" or "log_gap_ratio"),
    its band of gamma, and the breakpoints in x = [-1, 1] of its pieces."""

    name: str
    coordinate: str
    gamma_range: tuple[float, float]
    gamma_squared: bool  # the gamma coordinate is gamma^2 (S, N: the functions are even in gamma) or gamma
    pieces: tuple[float, ...] = (-1.0, 1.0)


@dataclass(frozen=True)
class Constants:
    """The edges of the table's domain (``table_data``)."""

    c_min: float
    gap_min: float
    gap_box: float
    gap_box_rise: float
    gamma_max: float


def regions(specs: dict[str, tuple]) -> dict[str, Region]:
    """Regions from their specifications name -> (coordinate, (gamma_lo, gamma_hi), gamma_squared, pieces)."""
    return {name: Region(name, coordinate, tuple(band), squared, tuple(pieces))
            for name, (coordinate, band, squared, pieces) in specs.items()}


def box_gap(gamma: np.ndarray, k: Constants) -> np.ndarray:
    """1 - c at the edge between S (or N) and L: GAP_BOX + GAP_BOX_RISE (gamma / GAMMA_MAX)^4."""
    g = np.asarray(gamma, dtype=float) / k.gamma_max
    return k.gap_box + k.gap_box_rise * (g * g) * (g * g)


def u_range(region: Region, gamma: np.ndarray, k: Constants) -> tuple[np.ndarray, np.ndarray]:
    """The ends of u in region at gamma (arrays)."""
    gamma = np.asarray(gamma, dtype=float)
    edge = box_gap(gamma, k)
    if region.coordinate == "logit_c":
        lo, hi = math.log(k.c_min) - math.log1p(-k.c_min), np.log1p(-edge) - np.log(edge)
    elif region.coordinate == "log_gap":
        lo, hi = math.log(k.gap_min), np.log(edge)
    else:
        lo, hi = 0.0, np.log(edge) - np.log(largest_stick_radius_gap(gamma))
    return np.broadcast_to(np.asarray(lo, dtype=float), gamma.shape), np.broadcast_to(np.asarray(hi, dtype=float), gamma.shape)


def to_unit(region: Region, u: np.ndarray, gamma: np.ndarray, ends: tuple[np.ndarray, np.ndarray]
            ) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) in [-1, 1]^2 for u and gamma."""
    lo, hi = ends
    g0, g1 = region.gamma_range
    g = np.asarray(gamma, dtype=float)
    y = 2.0 * (g * g - g0 * g0) / (g1 * g1 - g0 * g0) - 1.0 if region.gamma_squared else 2.0 * (g - g0) / (g1 - g0) - 1.0
    return 2.0 * (u - lo) / (hi - lo) - 1.0, y


def gap_and_c(region: Region, u: np.ndarray, gamma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """1 - c and c (each without cancellation) at u."""
    if region.coordinate == "logit_c":
        return 1.0 / (1.0 + np.exp(u)), 1.0 / (1.0 + np.exp(-u))
    gap = np.exp(u) if region.coordinate == "log_gap" else largest_stick_radius_gap(gamma) * np.exp(u)
    return gap, 1.0 - gap


def stored_eigen(region: Region, u: np.ndarray, gamma: np.ndarray, mu: np.ndarray) -> np.ndarray:
    """The stored eigenvalue function at u for friction mu: log(mu/gamma) in S and N, w mu gamma in L."""
    if region.coordinate == "log_gap_ratio":
        return u * mu * gamma
    return np.log(mu) - np.log(gamma)


def _log_mu(region: Region, u: np.ndarray, gamma: np.ndarray, stored: np.ndarray, stored_slope: np.ndarray
            ) -> tuple[np.ndarray, np.ndarray]:
    """log mu and d log mu/du from the stored eigenvalue function F and dF/du."""
    if region.coordinate == "log_gap_ratio":  # F = w mu gamma
        with np.errstate(divide="ignore"):
            return np.log(stored) - np.log(u) - np.log(gamma), stored_slope / stored - 1.0 / u
    return np.log(gamma) + stored, stored_slope


def stored_quantity(region: Region, name: str, value: np.ndarray, c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """A quantity as stored (C scaled in S and N); ``_physical`` undoes it."""
    if name in _C_POWER and region.gamma_squared:
        return value * c ** _C_POWER[name] / gamma
    return value


def _physical(region: Region, name: str, stored: np.ndarray, c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    if name in _C_POWER and region.gamma_squared:
        return stored * gamma / c ** _C_POWER[name]
    return stored


#: Up to this many points the Chebyshev recurrence runs on Python floats (numpy's per-call overhead dominates).
_FEW = 8


def chebyshev_matrix(x: np.ndarray, n: int) -> np.ndarray:
    """T_0 .. T_(n-1) at points x: shape (len(x), n) (the three-term recurrence)."""
    x = np.asarray(x, dtype=float)
    if x.size > _FEW:
        return chebyshev.chebvander(x, n - 1)
    rows = []
    for t in x.tolist():
        row = [1.0, t][:n]
        for _ in range(n - 2):
            row.append(2.0 * t * row[-1] - row[-2])
        rows.append(row)
    return np.array(rows, dtype=float).reshape(x.size, n)


def use_table_data(module) -> None:
    """Evaluate the tables of ``module`` (a freshly built table_data) instead of the committed ones (None: those)."""
    _TABLES.use(module)


@dataclass(frozen=True)
class _Tables:
    module: object
    constants: Constants
    regions: dict[str, Region]
    coefficients: dict[str, dict[str, list[np.ndarray]]]  # region -> key -> per piece (nx, ny)
    derivatives: dict[str, dict[str, list[np.ndarray]]]   # d/dx of "eigen" and "compliance"


def coefficients_of(data) -> dict[str, dict[str, list[np.ndarray]]]:
    """region -> stored function -> per piece the (nx, ny) Chebyshev coefficients of a table_data module (read from
    the .npy array beside it)."""
    values = np.load(Path(data.__file__).with_suffix(".npy"), allow_pickle=False)
    return {name: {key: [values[o: o + nx * ny].reshape(nx, ny) for o, nx, ny in spans] for key, spans in keys.items()}
            for name, keys in data.SERIES.items()}


def _tables_of(data) -> _Tables:
    constants = Constants(data.C_MIN, data.GAP_MIN, data.GAP_BOX, data.GAP_BOX_RISE, data.GAMMA_MAX)
    found = regions(data.REGIONS)
    coefficients = coefficients_of(data)
    derivatives = {name: {k: [chebyshev.chebder(a, axis=0) for a in coefficients[name][k]] for k in ("eigen", "compliance")}
                   for name in found}
    return _Tables(data, constants, found, coefficients, derivatives)


#: numeric.core.table_data (generated; imported on first use only), or a module given to ``use_table_data``
_TABLES = GeneratedData("numeric.core.table_data", _tables_of)


def _data() -> _Tables:
    return _TABLES.get()


def table_available() -> bool:
    """Whether the generated table module is present (and of this format)."""
    return _TABLES.available()


def table_errors() -> dict[str, float]:
    """The worst errors the build measured at held-out points (empty without a table): relative for
    mu, c, 1 - c (``gap``) and A; relative to max(1, |value|) for P*, p(0) and C."""
    return dict(_data().module.ERRORS or {}) if table_available() else {}


@dataclass(frozen=True)
class TableValues:
    """mu, c, 1 - c, the QUANTITIES, and d log mu / d logit c and d P* / d logit c at a set of points (nan where
    the table does not reach, and for what was not asked for)."""

    mu: np.ndarray
    c: np.ndarray
    gap: np.ndarray
    values: dict[str, np.ndarray]
    log_mu_slope: np.ndarray
    compliance_slope: np.ndarray


def _empty(n: int) -> TableValues:
    nan = np.full(n, np.nan)
    return TableValues(nan.copy(), nan.copy(), nan.copy(), {k: nan.copy() for k in QUANTITIES}, nan.copy(), nan.copy())


class _Slice:
    """Region ``name`` at a set of gamma: per piece, the Chebyshev series in x of the stored functions at each
    point's gamma, summed over gamma on first use (only what the caller asks for)."""

    def __init__(self, name: str, gamma: np.ndarray) -> None:
        tables = _data()
        self.region, self.gamma = tables.regions[name], gamma
        self.ends = u_range(self.region, gamma, tables.constants)
        self.y = to_unit(self.region, self.ends[0], gamma, self.ends)[1]
        self._coefficients, self._derivatives = tables.coefficients[name], tables.derivatives[name]
        self._ty: np.ndarray | None = None
        self._series: dict[tuple[str, bool], list[np.ndarray]] = {}

    def series(self, key: str, derivative: bool = False) -> np.ndarray:
        """(pieces, points, nx): the coefficients in x of ``key`` (or of its x-derivative) at each point's gamma."""
        if (key, derivative) not in self._series:
            source = (self._derivatives if derivative else self._coefficients)[key]
            if self._ty is None:
                self._ty = chebyshev_matrix(self.y, self._coefficients[key][0].shape[1])
            self._series[key, derivative] = np.stack([self._ty[:, : a.shape[1]] @ a.T for a in source])
        return self._series[key, derivative]

    def subset(self, keep: np.ndarray) -> "_Slice":
        """The slice at the points ``keep`` (a boolean mask), sharing what was summed so far."""
        part = object.__new__(_Slice)
        part.region, part.gamma, part.y = self.region, self.gamma[keep], self.y[keep]
        part.ends = (self.ends[0][keep], self.ends[1][keep])
        part._coefficients, part._derivatives = self._coefficients, self._derivatives
        part._ty = None if self._ty is None else self._ty[keep]
        part._series = {k: v[:, keep] for k, v in self._series.items()}
        return part

    def x_of(self, u: np.ndarray) -> np.ndarray:
        return to_unit(self.region, u, self.gamma, self.ends)[0]

    def u_of(self, x: np.ndarray) -> np.ndarray:
        lo, hi = self.ends
        return lo + 0.5 * (x + 1.0) * (hi - lo)

    def value(self, key: str, x: np.ndarray, derivative: bool = False) -> np.ndarray:
        """The stored function ``key`` at x (or its derivative in u), each point in its own piece."""
        return self.values(key, x, (derivative,))[0]

    def values(self, key: str, x: np.ndarray, derivatives: tuple[bool, ...]) -> list[np.ndarray]:
        """``value`` for each of ``derivatives`` at once: the pieces located and the Chebyshev polynomials formed
        once (Newton on log mu in ``table_given_mu`` reads the value and its slope at every step)."""
        edges = np.asarray(self.region.pieces)
        j = np.minimum(np.maximum(np.searchsorted(edges, x, side="right") - 1, 0), edges.size - 2)
        lo, hi = edges[j], edges[j + 1]
        t = (2.0 * x - lo - hi) / (hi - lo)
        own = np.arange(x.size)
        series = [self.series(key, derivative)[j, own] for derivative in derivatives]  # each point's own piece
        T = chebyshev_matrix(t, max(b.shape[1] for b in series))
        out = []
        for b, derivative in zip(series, derivatives):
            value = np.einsum("pk,pk->p", b, T[:, : b.shape[1]])
            if derivative:  # d/du = d/dt dt/dx dx/du
                value *= (2.0 / (hi - lo)) * (2.0 / (self.ends[1] - self.ends[0]))
            out.append(value)
        return out

    def log_mu(self, x: np.ndarray, slope: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
        """log mu at x and (if asked) d log mu/du."""
        u = self.u_of(x)
        if slope:
            stored, stored_slope = self.values("eigen", x, (False, True))
        else:
            stored, stored_slope = self.value("eigen", x), np.zeros_like(x)
        value, derivative = _log_mu(self.region, u, self.gamma, stored, stored_slope)
        return value, (derivative if slope else None)

    def fill(self, out: TableValues, rows: np.ndarray, x: np.ndarray, mu: np.ndarray | None,
             quantities: tuple[str, ...], slopes: bool) -> None:
        u = self.u_of(x)
        gap, c = gap_and_c(self.region, u, self.gamma)
        out.gap[rows], out.c[rows] = gap, c
        if mu is None or slopes:
            log_mu, log_slope = self.log_mu(x, slopes)
            out.mu[rows] = np.exp(log_mu) if mu is None else mu
        else:
            out.mu[rows] = mu
        if slopes:  # d/d logit c: du/d logit c is 1 for u = logit c, -c for u = log(1 - c) (+ a constant in gamma)
            du = 1.0 if self.region.coordinate == "logit_c" else -c
            out.log_mu_slope[rows] = du * log_slope
            out.compliance_slope[rows] = du * self.value("compliance", x, derivative=True)
        for name in quantities:
            out.values[name][rows] = _physical(self.region, name, self.value(name, x), c, self.gamma)


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
                  quantities: tuple[str, ...] = QUANTITIES, slopes: bool = False) -> TableValues:
    """The tabulated values for stick radius c (nan outside the table's domain, and for the QUANTITIES not
    asked for; the slopes only with ``slopes``); ``gap``: 1 - c where c has rounded it (near c = 1 the relative
    error of 1 - c is 1e-16/(1 - c), and mu's is that over log(2/(1 - c)))."""
    c, gamma = _flat(c, gamma)
    out = _empty(c.size)
    if not table_available():
        return out
    tables = _data()
    k = tables.constants
    gap = 1.0 - c if gap is None else np.broadcast_to(np.asarray(gap, dtype=float).ravel(), c.shape)
    edge = box_gap(gamma, k)
    taken = np.zeros(c.size, dtype=bool)
    for name, region in tables.regions.items():
        if taken.all():  # every point answered (a scalar call in S: the other regions' masks not formed)
            break
        rows = np.flatnonzero(_gamma_in(region, gamma) & ~taken)
        if rows.size == 0:
            continue
        if region.coordinate == "logit_c":
            rows = rows[(c[rows] >= k.c_min) & (gap[rows] >= edge[rows])]
        elif region.coordinate == "log_gap":
            rows = rows[(gap[rows] < edge[rows]) & (gap[rows] >= k.gap_min)]
        else:
            gap_max = np.asarray(largest_stick_radius_gap(gamma[rows]), dtype=float)
            keep = (gap[rows] < edge[rows]) & (gap[rows] > gap_max)
            rows, gap_max = rows[keep], gap_max[keep]
        if rows.size == 0:
            continue
        taken[rows] = True
        piece = _Slice(name, gamma[rows])
        if region.coordinate == "logit_c":
            u = np.log(c[rows]) - np.log(gap[rows])
        else:
            u = np.log(gap[rows]) if region.coordinate == "log_gap" else np.log(gap[rows] / gap_max)
        piece.fill(out, rows, piece.x_of(u), None, quantities, slopes)
        out.c[rows], out.gap[rows] = c[rows], gap[rows]
    return out


@lru_cache(maxsize=256)
def _log_mu_ends(name: str, gamma: float) -> tuple[float, float]:
    """log mu at the ends of region ``name`` at gamma where it is least and greatest (x = -1, 1 in S; 1, -1 in N
    and L, where log mu falls with x)."""
    sign = 1.0 if _data().regions[name].coordinate == "logit_c" else -1.0
    piece = _Slice(name, np.array([gamma]))
    return (float(piece.log_mu(np.array([-sign]), slope=False)[0][0]),
            float(piece.log_mu(np.array([sign]), slope=False)[0][0]))


def table_given_mu(mu: np.ndarray, gamma: np.ndarray, quantities: tuple[str, ...] = QUANTITIES,
                   slopes: bool = False) -> TableValues:
    """The tabulated values for friction mu (nan outside the table's domain, and for the QUANTITIES not asked
    for; the slopes only with ``slopes``; mu = inf: c = c_max)."""
    mu, gamma = _flat(mu, gamma)
    out = _empty(mu.size)
    if not table_available():
        return out
    tables = _data()
    with np.errstate(divide="ignore", invalid="ignore"):
        target = np.log(mu)
    candidate = (mu > 0.0) & (gamma > 0.0)
    for name, region in tables.regions.items():  # S first; N and L take what lies above mu at the box edge
        if not candidate.any():  # every point answered or below the table
            break
        rows = np.flatnonzero(candidate & _gamma_in(region, gamma))
        if region.coordinate == "log_gap_ratio":
            ends = rows[np.isinf(mu[rows])]
            if ends.size:
                _Slice(name, gamma[ends]).fill(out, ends, np.full(ends.size, -1.0), mu[ends], quantities, False)
                candidate[ends] = False
            rows = rows[np.isfinite(mu[rows])]
        if rows.size == 0:
            continue
        # log mu increases with x in S (u = logit c) and decreases in N and L (u = log 1 - c)
        sign = 1.0 if region.coordinate == "logit_c" else -1.0
        piece = _Slice(name, gamma[rows])
        if rows.size == 1:  # a scalar call: the region's ends in mu depend on gamma only (kept)
            least, greatest = (np.array([v]) for v in _log_mu_ends(name, float(gamma[rows[0]])))
        else:
            least = piece.log_mu(np.full(rows.size, -sign), slope=False)[0]
            greatest = piece.log_mu(np.full(rows.size, sign), slope=False)[0]
        low, high = least > target[rows], greatest < target[rows]  # below the region's least mu, above its greatest
        candidate[rows[~high]] = False  # answered here, or below the table (mu < mu(C_MIN): the law's)
        # only S has a lower end in mu; in N and L a mu a rounding below the end is the end's
        keep = ~(low | high) if region.coordinate == "logit_c" else ~high
        rows = rows[keep]
        if rows.size == 0:
            continue
        piece, goal = piece.subset(keep), target[rows]
        scale = 0.5 * (piece.ends[1] - piece.ends[0])
        with np.errstate(divide="ignore", invalid="ignore"):  # start where log mu, linear between the ends, meets it
            start = sign * (2.0 * (goal - least[keep]) / (greatest[keep] - least[keep]) - 1.0)
        start = np.where(np.isfinite(start), np.clip(start, -0.999, 0.999), 0.0)
        if region.coordinate == "log_gap_ratio":
            # mu = F/(gamma w) with F (stored) smooth and finite at c_max (w = 0): w ~ F(c_max)/(gamma mu) starts
            # Newton within F's variation of the root (it took 8-11 steps from the linear start near c_max)
            stored_at_c_max = piece.value("eigen", np.full(rows.size, -1.0))
            near = piece.x_of(stored_at_c_max / (piece.gamma * mu[rows]))
            start = np.where(np.isfinite(near), np.clip(near, -0.999, 0.999), start)

        def f(x, piece=piece, goal=goal, sign=sign, scale=scale):
            value, slope = piece.log_mu(x)
            return sign * (value - goal), sign * slope * scale

        piece.fill(out, rows, _newton(f, start), mu[rows], quantities, slopes)
    return out


def table_least_c() -> float:
    """The table's least stick radius C_MIN (nan without the table): below it the asymptotic law answers."""
    return _data().constants.c_min if table_available() else math.nan


def table_least_mu(gamma: float) -> float:
    """mu at the table's least stick radius C_MIN (nan without the table): below it c < C_MIN."""
    if not table_available() or not 0.0 < gamma <= _data().constants.gamma_max:
        return math.nan
    return float(table_given_c(_data().constants.c_min, gamma, quantities=()).mu[0])


def table_friction_coefficient(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """mu(c, gamma) from the table (nan outside its domain)."""
    return table_given_c(c, gamma, quantities=()).mu


def table_compliance(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """P*(c, gamma) from the table (nan outside its domain)."""
    return table_given_c(c, gamma, quantities=("compliance",)).values["compliance"]


def table_stick_radius(mu: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """c(mu, gamma) from the table (nan outside its domain)."""
    return table_given_mu(mu, gamma, quantities=()).c
