"""Build the plane solver's guess table (``numeric.core.plane_guess``): theta(c, gamma) of the strip punch.

1. 1 - c_max(gamma) at N_GAP_MAX Chebyshev points of gamma over region L's band, from the limit problem at level 2
   (``numeric.solutions.plane_solver.solve_limit``), as the series of h = atanh(gamma) log(8 / (1 - c_max)). Region L's
   coordinate is log(1 - c) less log(1 - c_max), so near c_max its stored function is off by the series' relative error
   over that distance: with 16 points the series was 2e-10 ... 8e-10 off fresh limit solves between its nodes (its last
   coefficient 1.5e-9), with 28 within 6e-13.
2. At Chebyshev points of the first kind of each region (S, N, L: ``REGION_SPECS``), the careful given-c solve at
   level 2 (``numeric.core.plane_eigenvalue.plane_given_c``) from the first-order law, not from the table being
   rebuilt (the result then does not depend on it), polished by the linearised Newton (``careful_theta``); along each
   gamma of region L from the largest 1 - c down towards c_max, each solve started from the previous two (1/(mu gamma)
   extrapolated linearly in 1 - c).
3. The stored functions' Chebyshev coefficients (discrete cosine transforms), written to
   ``numeric/core/plane_guess_data.py`` with the worst relative error in mu of the guess at held-out points of each
   region (random ones, fixed seed, and a grid near its ends), measured against fresh level-2 solves (``ERRORS``).

Deterministic: a re-run writes the same file. (The limit solves of step 1 start from the file's own 1 - c_max, so a
run from another file moves the series at rounding, 4e-11 in h, and L's coefficients by up to 1.7e-8 of 1.6 with it;
run again, it reproduces itself.) Run time: about three minutes on two cores (two processes; set
OPENBLAS_NUM_THREADS=1, or the BLAS threads of the two fight over the cores):

    OPENBLAS_NUM_THREADS=1 python derivations/build_plane_guess.py
"""

from __future__ import annotations

import importlib
import math
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from numeric.core import plane_guess, plane_guess_data
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.plane_eigenvalue import plane_given_c, plane_given_c_linearised
from numeric.solutions.plane_solver import PLANE_LEVELS, solve_limit

ROOT = Path(__file__).resolve().parents[1]
TARGET = ROOT / "numeric" / "core" / "plane_guess_data.py"
LEVEL = 2
C_MIN, GAP_S, GAP_N, GAMMA_N, GAMMA_MAX = 1e-5, 0.2, 1e-8, 0.16, 0.75
#: name -> (coordinate, gamma band, gamma^2 coordinate); see numeric.core.plane_guess
REGION_SPECS = {"S": ("logit_c", (0.0, GAMMA_MAX), True), "N": ("log_gap", (0.0, GAMMA_N), True),
                "L": ("log_gap_ratio", (GAMMA_N, GAMMA_MAX), False)}
#: Chebyshev points (u, gamma) of each region, and of the series of 1 - c_max in gamma
SIZES = {"S": (44, 18), "N": (24, 11), "L": (52, 24)}
N_GAP_MAX = 28
N_CHECK = {"S": 24, "N": 12, "L": 24}
#: Held-out points near the ends of each region too (its unit coordinates, x in u and y in gamma), besides the random
#: ones: an interpolant at first-kind points is least accurate beyond its outermost nodes. Next to c_max (region L,
#: x = -0.999) the guess was up to 6e-8 off where the random points' worst was 2.9e-10, and a fresh point at
#: nu = -1/2, c = 0.94 (x = -0.95) 6.9e-10.
EDGE_X = (-0.999, -0.99, -0.95, 0.95, 0.99, 0.999)
EDGE_Y = (-0.999, -0.5, 0.0, 0.5, 0.999)
SEED = 20261127


def coefficients(values: np.ndarray) -> np.ndarray:
    """Chebyshev coefficients (1-D or 2-D) from values at first-kind points (discrete cosine transforms)."""
    out = values
    for axis, n in enumerate(values.shape):
        T = np.cos(np.outer(np.arange(n), math.pi * (np.arange(n) + 0.5) / n)) * 2.0 / n
        T[0] /= 2.0
        out = np.moveaxis(np.tensordot(T, out, axes=(1, axis)), 0, axis)
    return out


def gamma_at(region: plane_guess.GuessRegion, y: float) -> float:
    g0, g1 = region.gamma_range
    t = 0.5 * (y + 1.0)
    return math.sqrt(g0 * g0 + t * (g1 * g1 - g0 * g0)) if region.gamma_squared else g0 + t * (g1 - g0)


def u_at(region: plane_guess.GuessRegion, x: float, gamma: float) -> float:
    lo, hi = plane_guess.u_range(region, gamma)
    return lo + 0.5 * (x + 1.0) * (hi - lo)


def limit_gap(gamma: float) -> float:
    return solve_limit(gamma, LEVEL).gap_limit


def first_order(c: float, gap: float, gamma: float) -> float:
    """theta of the first-order law, tan(theta) = gamma^2 K(c)/K'(c)."""
    return math.atan(gamma * gamma / plane_guess.elliptic_ratio(c, gap))


def careful_theta(name: str, c: float, gap: float, gamma: float, previous: list[tuple[float, float, float, float]]
                  ) -> float:
    """theta at (c, gamma) of region ``name``: ``careful_root``, polished by the linearised Newton from it (from a start
    that close its one step leaves theta at its rounding). The careful iteration stops once its steps or its bracket are
    within 1e-12 ... 1e-10 of theta, which next to pi/2 is loose in mu (d log mu / d theta ~ mu gamma): at the node of
    region L nearest c_max (1 - c ~ 1.0006 (1 - c_max), mu gamma ~ 2e3) it had left mu 2.5e-7 ... 4e-7 from the
    linearised solve there, which agreed to 4e-10 with the careful iteration from the first-order law. Where the polish
    does not converge the careful root is kept."""
    theta = careful_root(name, c, gap, gamma, previous)
    try:
        return plane_given_c_linearised(c, gap, gamma, theta, PLANE_LEVELS[LEVEL]).theta
    except SolverError:
        return theta


def careful_root(name: str, c: float, gap: float, gamma: float, previous: list[tuple[float, float, float, float]]
                 ) -> float:
    """theta at (c, gamma) of region ``name`` by the careful given-c solve at LEVEL: from the first-order law, or
    (region L, near c_max) from the previous two solves of the row, 1/(mu gamma) extrapolated linearly in 1 - c, else
    from the larger of the first-order law and the approach mu gamma = 1.4 (1 - c_max) / (c_max - c) (both fall
    short), else from the approach alone: the careful solver, started too far from the root next to c_max, can step
    to mu gamma ~ 1e9, where the generic mode degenerates, and give up, or take the sign change of G there for the
    root (a result above 100 times the larger of the approach and the first-order law is refused); last, the linearised iteration (the careful Newton can
    also end jittering at its rounding floor, steps of 1e-12)."""
    starts = [first_order(c, gap, gamma)]
    largest = math.inf
    if plane_guess.REGIONS[name].coordinate == "log_gap_ratio":
        gap_max = plane_guess.gap_max(gamma)
        largest = 100.0 * max(1.4 * gap_max / (gap - gap_max), math.tan(starts[0]))
        approach = math.atan(1.4 * gap_max / (gap - gap_max))
        starts = [max(starts[0], approach), approach]
        if len(previous) >= 2:
            (_, g1, _, t1), (_, g2, _, t2) = previous[-2:]
            e1, e2 = 1.0 / math.tan(t1), 1.0 / math.tan(t2)
            eps = e2 + (e1 - e2) * (gap - g2) / (g1 - g2)
            starts.insert(0, math.atan2(1.0, max(eps, 0.5 * e2 * gap / g2)))
    for start in starts:
        try:
            theta = plane_given_c(c, gap, gamma, start, PLANE_LEVELS[LEVEL]).theta
        except (NoEigenvalueError, SolverError):
            continue
        if math.tan(theta) <= largest:
            return theta
    try:
        return plane_given_c_linearised(c, gap, gamma, starts[0], PLANE_LEVELS[LEVEL], 1e-3, 12).theta
    except SolverError as e:
        raise SolverError(f"no careful solve at region {name}, c = {c!r}, 1 - c = {gap!r}, gamma = {gamma!r}, starts "
                          f"{starts}: {e}") from e


def solve_row(points: list[tuple[str, float, float]]) -> list[tuple[float, float, float, float]]:
    """(c, 1 - c, gamma, theta) along one gamma of a region, in the order given (region L: 1 - c decreasing towards
    c_max), by ``careful_theta``."""
    out: list[tuple[float, float, float, float]] = []
    for name, u, gamma in points:
        gap, c = plane_guess.gap_and_c(plane_guess.REGIONS[name], u, gamma)
        out.append((c, gap, gamma, careful_theta(name, c, gap, gamma, out)))
    return out


def build_region(pool, name: str) -> np.ndarray:
    """The coefficients (nu, ny) of region ``name``'s stored function."""
    region = plane_guess.REGIONS[name]
    n_u, n_y = SIZES[name]
    xs = plane_guess.chebyshev_nodes(n_u)  # descending: the largest u first (region L: the largest 1 - c first)
    if region.coordinate == "log_gap":
        xs = xs[::-1]
    rows = [[(name, u_at(region, float(x), g), g) for x in xs] for g in (gamma_at(region, y) for y in plane_guess.chebyshev_nodes(n_y))]
    values = np.empty((n_u, n_y))
    for j, row in enumerate(pool.map(solve_row, rows)):
        for i, (c, gap, gamma, theta) in enumerate(row):
            k = i if region.coordinate != "log_gap" else n_u - 1 - i
            values[k, j] = plane_guess.stored_value(region, c, gap, gamma, theta)
    return coefficients(values)


def write(gap_max_series: np.ndarray, coefs: dict[str, np.ndarray], errors: dict[str, float] | None) -> None:
    def literal(a: np.ndarray) -> str:
        if a.ndim == 1:
            return "(" + ", ".join(repr(float(v)) for v in a) + ",)"
        return "(\n        " + ",\n        ".join(literal(row) for row in a) + ",\n    )"

    lines = ['"""Generated by derivations/build_plane_guess.py - do not edit.', "",
             "The guess table of ``numeric.core.plane_guess``: Chebyshev coefficients COEFFICIENTS[region][i][j] of the",
             "stored function in u (i) and gamma or gamma^2 (j), and of h(gamma) = atanh(gamma) log(8 / (1 - c_max)).",
             '"""', "",
             f"C_MIN, GAP_S, GAP_N, GAMMA_N, GAMMA_MAX = {C_MIN!r}, {GAP_S!r}, {GAP_N!r}, {GAMMA_N!r}, {GAMMA_MAX!r}",
             f"LEVEL = {LEVEL}",
             "#: name -> (coordinate, gamma band, gamma^2 coordinate)",
             "REGIONS = {" + ", ".join(f"{k!r}: ({c!r}, {tuple(b)!r}, {sq!r})" for k, (c, b, sq) in REGION_SPECS.items()) + "}",
             f"#: worst relative error of the guess in mu at held-out points of each region (random, seed {SEED}, and near its",
             f"#: ends, EDGE_X x EDGE_Y), against level-{LEVEL} solves",
             f"ERRORS = {errors!r}",
             f"GAP_MAX_SERIES = {literal(gap_max_series)}",
             "COEFFICIENTS = {"]
    for name, a in coefs.items():
        lines.append(f"    {name!r}: {literal(a)},")
    lines += ["}", ""]
    TARGET.write_text("\n".join(lines), encoding="utf-8")
    importlib.reload(plane_guess_data)
    importlib.reload(plane_guess)


def check_point(point: tuple[str, float, float]) -> float:
    """|mu_guess / mu - 1| at a held-out point, against a fresh level-2 solve (``careful_theta``, not from the guess)."""
    name, u, gamma = point
    gap, c = plane_guess.gap_and_c(plane_guess.REGIONS[name], u, gamma)
    guess = plane_guess.theta_guess(c, gap, gamma)
    theta = careful_theta(name, c, gap, gamma, [])
    return abs(math.tan(guess.theta) / math.tan(theta) - 1.0)


def main() -> None:
    t0 = time.perf_counter()
    band = REGION_SPECS["L"][1]
    gammas = [band[0] + 0.5 * (y + 1.0) * (band[1] - band[0]) for y in plane_guess.chebyshev_nodes(N_GAP_MAX)]
    with ProcessPoolExecutor(max_workers=2) as pool:
        gaps = list(pool.map(limit_gap, gammas))
    h = coefficients(np.array([plane_guess.gap_max_stored(g, gap) for g, gap in zip(gammas, gaps)]))
    write(h, {}, None)
    print(f"1 - c_max: {N_GAP_MAX} limit solves, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    coefs = {}
    with ProcessPoolExecutor(max_workers=2, initializer=_reload) as pool:
        for name in REGION_SPECS:
            coefs[name] = build_region(pool, name)
            print(f"region {name}: {np.prod(SIZES[name])} solves, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
    write(h, coefs, None)
    rng = np.random.default_rng(SEED)
    points = []
    for name, n in N_CHECK.items():
        region = plane_guess.REGIONS[name]
        for _ in range(n):
            g = gamma_at(region, float(rng.uniform(-1.0, 1.0)))
            points.append((name, u_at(region, float(rng.uniform(-1.0, 1.0)), g), g))
    for name in N_CHECK:
        region = plane_guess.REGIONS[name]
        points += [(name, u_at(region, x, g), g) for g in (gamma_at(region, y) for y in EDGE_Y) for x in EDGE_X]
    with ProcessPoolExecutor(max_workers=2, initializer=_reload) as pool:
        found = list(pool.map(check_point, points))
    errors = {name: float(f"{max(e for (n, _, _), e in zip(points, found) if n == name):.2g}") for name in N_CHECK}
    worst = {name: max(((e, p) for p, e in zip(points, found) if p[0] == name)) for name in N_CHECK}
    print(f"worst points (error, (region, u, gamma)): {worst}", file=sys.stderr)
    write(h, coefs, errors)
    print(f"wrote {TARGET}; worst relative error of the guess in mu at held-out points: {errors}; "
          f"{time.perf_counter() - t0:.0f} s", file=sys.stderr)


def _reload() -> None:
    """A worker sees the data module as written so far (it may have been forked before the last write)."""
    importlib.reload(plane_guess_data)
    importlib.reload(plane_guess)


if __name__ == "__main__":
    main()
