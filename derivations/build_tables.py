"""Build the whole-plane tables of ``numeric.core.table`` (writes ``numeric/core/table_data.py``).

Samples level-3 solutions (``numeric.solutions.solver``, ~1e-13) with the sphere's and cone's A
and C (``numeric.solutions.power_law``) at Chebyshev points of the first kind on every piece of
the regions of ``numeric.core.table`` (``REGION_SPECS``: S, N and the bands L0, L1, L2 near the
largest stick radius), turns the stored functions into Chebyshev coefficients, and checks the
interpolants at held-out random points of each region and at its corners and edge midpoints
against fresh level-3 solves, both ways (mu for given c, c for given mu). The worst error of each
quantity is recorded in the generated module (``ERRORS``: relative for mu, c (region S) and 1 - c
(``gap``, regions N and L); relative to max(1, |value|) for P*, p(0), A and C) and checked by
``tests/test_tables.py``.

Run time: 30-45 minutes on 2 cores (46 on a loaded machine) (two processes; single-threaded BLAS, or the threads of the
two processes fight over the cores), with a progress bar per region on a terminal:

    OPENBLAS_NUM_THREADS=1 python derivations/build_tables.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from numeric import slip_limit
from numeric.core import table
from numeric.solutions.power_law import displacement_constant, indentation_constant
from numeric.solutions.progress import tracked
from numeric.solutions.solver import solve_given_c

ROOT = Path(__file__).resolve().parents[1]
C_MIN, GAP_MIN, GAP_BOX, GAP_BOX_RISE, GAMMA_MAX = 1e-5, 1e-13, 0.1, 0.2, 0.75
#: name -> (coordinate, gamma band, gamma^2 coordinate, piece breakpoints in x); see numeric.core.table. Pieces:
#: S and N four each (log mu is singular at c_max beyond S's top, at 1 - c = 2 beyond N's); L0 eight, so
#: that each piece is at most ~6 wide in w at gamma = 0.1 (W = 46 there; mu has poles at w = +-2 pi i).
REGION_SPECS = {
    "S": ("logit_c", (0.0, GAMMA_MAX), True, (-1.0, -0.5, 0.0, 0.5, 1.0)),
    "N": ("log_gap", (0.0, 0.1), True, (-1.0, -0.5, 0.0, 0.5, 1.0)),
    "L0": ("log_gap_ratio", (0.1, 0.3), False, tuple(np.linspace(-1.0, 1.0, 9))),
    "L1": ("log_gap_ratio", (0.3, 0.5), False, (-1.0, -0.5, 0.0, 1.0)),
    "L2": ("log_gap_ratio", (0.5, GAMMA_MAX), False, (-1.0, 0.0, 1.0)),
}
#: Chebyshev points (x, gamma) of each piece of a region
SIZES = {"S": (28, 24), "N": (28, 16), "L0": (24, 24), "L1": (24, 20), "L2": (24, 20)}
QUICK = {"S": (6, 5), "N": (6, 4), "L0": (5, 4), "L1": (5, 4), "L2": (5, 4)}
N_CHECK = {"S": 48, "N": 24, "L0": 32, "L1": 24, "L2": 24}
LEVEL = 3
REGIONS = table.regions(REGION_SPECS)
CONSTANTS = table.Constants(C_MIN, GAP_MIN, GAP_BOX, GAP_BOX_RISE, GAMMA_MAX)


def chebyshev_points(n: int) -> np.ndarray:
    return np.cos(np.pi * (np.arange(n) + 0.5) / n)


def coefficients(values: np.ndarray) -> np.ndarray:
    """2-D Chebyshev coefficients from values at first-kind points (discrete cosine transforms)."""
    mats = []
    for n in values.shape:
        T = np.cos(np.outer(np.arange(n), np.pi * (np.arange(n) + 0.5) / n)) * 2.0 / n
        T[0] /= 2.0
        mats.append(T)
    return mats[0] @ values @ mats[1].T


def gamma_at(region: table.Region, y: np.ndarray) -> np.ndarray:
    g0, g1 = region.gamma_range
    t = 0.5 * (np.asarray(y) + 1.0)
    return np.sqrt(g0 * g0 + t * (g1 * g1 - g0 * g0)) if region.gamma_squared else g0 + t * (g1 - g0)


def u_at(region: table.Region, x: float, gamma: float) -> float:
    lo, hi = table.u_range(region, np.array(gamma), CONSTANTS)
    return float(lo + 0.5 * (x + 1.0) * (hi - lo))


def solve(name: str, u: float, gamma: float, theta_guess: float | None = None):
    """The level-3 solution at u of region ``name`` (c and 1 - c exact; the slip limit at w = 0)."""
    region = REGIONS[name]
    gap, c = (float(v) for v in table.gap_and_c(region, np.array(u), np.array(gamma)))
    if region.coordinate == "log_gap_ratio" and u == 0.0:
        return slip_limit(gamma=gamma, level=LEVEL)
    return solve_given_c(None, c, gamma, LEVEL, gap=gap, theta_guess=theta_guess)


def quantities(sol) -> dict[str, float]:
    """P*, p(0), A and C of the sphere (n = 2) and the cone (n = 1) of one flat-punch solution."""
    return {"compliance": sol.compliance, "central_pressure": float(sol.pressure(0.0)),
            "sphere_A": indentation_constant(sol, 2.0), "sphere_C": displacement_constant(sol, 2.0),
            "cone_A": indentation_constant(sol, 1.0), "cone_C": displacement_constant(sol, 1.0)}


def sample(point: tuple[str, float, float], theta_guess: float | None = None) -> dict[str, float]:
    """The stored functions of region ``name`` at (u, gamma), and the solution's mu, c, 1 - c, quantities."""
    name, u, gamma = point
    region = REGIONS[name]
    sol = solve(name, u, gamma, theta_guess)
    q = quantities(sol)
    gap, c = (float(v) for v in table.gap_and_c(region, np.array(u), np.array(gamma)))
    stored = {"eigen": float(table.stored_eigen(region, np.array(u), np.array(gamma), np.array(sol.mu)))}
    stored.update({k: float(table.stored_quantity(region, k, np.array(v), np.array(c), np.array(gamma))) for k, v in q.items()})
    return {"stored": stored, "quantities": q, "mu": sol.mu, "c": c, "gap": gap}


def sample_row(points: list[tuple[str, float, float]]) -> list[dict[str, float]]:
    """``sample`` along one gamma of a region near c_max, from the box edge towards c_max (points in order of
    decreasing 1 - c), each solve started from the previous ones: 1/(mu gamma) extrapolated linearly in
    1 - c (it falls like (1 - c) - (1 - c_max) near c_max). Without it the solver falls back to a secant
    search that takes 10-30 s a point at 1 - c_max < 1e-15."""
    out: list[dict[str, float]] = []
    gamma = points[0][2]
    for point in points:
        guess = None
        if len(out) >= 2:
            (g1, e1), (g2, e2) = ((r["gap"], 1.0 / (r["mu"] * gamma)) for r in out[-2:])
            gap = float(table.gap_and_c(REGIONS[point[0]], np.array(point[1]), np.array(gamma))[0])
            eps = e2 + (e1 - e2) * (gap - g2) / (g1 - g2) if g1 != g2 else e2
            guess = math.atan2(1.0, max(eps, 0.5 * e2 * gap / g2))
        out.append(sample(point, guess))
    return out


def build_region(pool, name: str, size: tuple[int, int]) -> dict[str, list[np.ndarray]]:
    """The Chebyshev coefficients of each stored function on each piece of region ``name``."""
    region = REGIONS[name]
    n_x, n_y = size
    ys = chebyshev_points(n_y)
    out: dict[str, list[np.ndarray]] = {k: [] for k in ("eigen",) + table.QUANTITIES}
    edges = list(zip(region.pieces[:-1], region.pieces[1:]))[::-1]  # the last piece first: x descending
    xs = np.concatenate([lo + 0.5 * (chebyshev_points(n_x) + 1.0) * (hi - lo) for lo, hi in edges])
    rows = [[(name, u_at(region, x, g), float(g)) for x in xs] for g in gamma_at(region, ys)]
    if region.coordinate == "log_gap_ratio":  # x descending is 1 - c decreasing: continue along each row
        results = [r for row in tracked(pool.map(sample_row, rows), len(rows), f"region {name}", unit="row")
                   for r in row]
    else:
        results = list(tracked(pool.map(sample, [p for row in rows for p in row], chunksize=2), len(rows) * len(xs),
                               f"region {name}", unit="solve"))
    table_ = np.array([[r["stored"][k] for r in results] for k in out]).reshape(len(out), n_y, len(edges), n_x)
    for i, k in enumerate(out):
        out[k] = [coefficients(table_[i, :, j, :].T) for j in reversed(range(len(edges)))]
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a small grid (tests of the script itself)")
    parser.add_argument("--output", type=Path, default=ROOT / "numeric" / "core" / "table_data.py")
    parser.add_argument("--check-only", action="store_true",
                        help="re-check the tables in OUTPUT at new held-out points and rewrite only their ERRORS")
    args = parser.parse_args()
    if args.check_only:
        recheck(args.output)
        return
    sizes = QUICK if args.quick else SIZES
    t0 = time.perf_counter()
    rng = np.random.default_rng(20261125)
    coefs = {}
    with ProcessPoolExecutor(max_workers=2) as pool:
        for name in REGIONS:
            coefs[name] = build_region(pool, name, sizes[name])
            solves = np.prod(sizes[name]) * (len(REGIONS[name].pieces) - 1)
            print(f"region {name}: {solves} solves, {time.perf_counter() - t0:.0f} s", file=sys.stderr)
        write(args.output, coefs, errors=None)
        errors = check(pool, rng, args.output, {k: (v if not args.quick else 4) for k, v in N_CHECK.items()})
    write(args.output, coefs, errors)
    print(f"errors: {errors}; {time.perf_counter() - t0:.0f} s", file=sys.stderr)


def recheck(path: Path) -> None:
    """The check of ``main`` on the tables already in ``path`` (their coefficients unchanged)."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("built_table_data", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    coefs = table.coefficients_of(module)
    t0 = time.perf_counter()
    with ProcessPoolExecutor(max_workers=2) as pool:
        errors = check(pool, np.random.default_rng(20261125), path, N_CHECK)
    write(path, coefs, errors)
    print(f"errors: {errors}; {time.perf_counter() - t0:.0f} s", file=sys.stderr)


#: The errors at c >= SMALL_C are also recorded apart (``ERRORS_ABOVE_SMALL_C``): below it the level-3 references
#: once carried the solver's round-off (~2e-13 (2e-3/c) absolute in mu, before (2.2a) was differenced and the solves
#: refined, ``numeric.core.operators.collocation_system``); the two records now agree but in c (1.2e-13 against 4.3e-14).
SMALL_C = 1e-3


def check(pool, rng, path: Path, n_check: dict[str, int]) -> tuple[dict[str, float], dict[str, float]]:
    """Worst errors of the written table at held-out random points (fresh level-3 solves): everywhere, and at
    c >= SMALL_C."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("fresh_table_data", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    table.use_table_data(module)
    points = []
    for name in REGIONS:
        region = REGIONS[name]
        for _ in range(n_check[name]):
            g = float(gamma_at(region, rng.uniform(-1.0, 1.0)))
            points.append((name, u_at(region, float(rng.uniform(-1.0, 1.0)), g), g))
        # the corners and edge midpoints, where interpolants are weakest (gamma = 0 and, in L0, L1, mu = inf
        # at x = -1 are limits, approached to 1e-3 of the edge)
        for x in (-0.999, 0.0, 1.0):
            for y in (-0.999, 0.0, 1.0):
                g = float(gamma_at(region, y))
                points.append((name, u_at(region, x, g), g))
    errors = {name: 0.0 for name in ("mu", "c", "gap") + table.QUANTITIES}
    above = dict(errors)
    worst: dict[str, tuple] = {}

    def record(name: str, value: float, where: tuple) -> None:
        value = value if math.isfinite(value) else math.inf  # a nan counts as the worst
        if not value <= errors[name]:
            errors[name] = value
            worst[name] = where
        if where[1] >= SMALL_C and not value <= above[name]:
            above[name] = value
    for point, ref in zip(points, tracked(pool.map(sample, points), len(points), "check", unit="solve")):
        name, _, g = point
        where = (name, ref["c"], ref["gap"], g)
        tv = table.table_given_c(ref["c"], g, gap=ref["gap"])
        record("mu", abs(tv.mu[0] / ref["mu"] - 1.0), where)
        for q in table.QUANTITIES:
            record(q, abs(tv.values[q][0] - ref["quantities"][q]) / max(1.0, abs(ref["quantities"][q])), where)
        back = table.table_given_mu(ref["mu"], g)
        if REGIONS[name].coordinate == "logit_c":
            record("c", abs(back.c[0] / ref["c"] - 1.0), where)
        else:
            record("gap", abs(back.gap[0] / ref["gap"] - 1.0), where)
    table.use_table_data(None)
    print(f"worst points: {worst}", file=sys.stderr)
    return {k: float(f"{v:.3g}") for k, v in errors.items()}, {k: float(f"{v:.3g}") for k, v in above.items()}


def write(path: Path, coefs: dict, errors: tuple[dict, dict] | None) -> None:
    """The generated module at ``path`` (constants, regions, errors and where each series lies) and its coefficients,
    one float64 array in ``path`` with suffix .npy (a Python source of 80 000 floats took 1.3 s to compile on first
    use; the array loads in a millisecond). Both are deterministic: no timestamps."""
    layout, arrays, offset = {}, [], 0
    for name, region_coefs in coefs.items():
        layout[name] = {}
        for key, pieces in region_coefs.items():
            spans = []
            for a in pieces:
                a = np.asarray(a, dtype=float)
                spans.append((offset, a.shape[0], a.shape[1]))
                arrays.append(a.ravel())
                offset += a.size
            layout[name][key] = spans
    np.save(path.with_suffix(".npy"), np.concatenate(arrays), allow_pickle=False)
    lines = ['"""Whole-plane tables of numeric.core.table: generated by derivations/build_tables.py, do not edit.', "",
             f"The coefficients are in {path.with_suffix('.npy').name} beside this module (``SERIES`` says where).", '"""', "",
             f"C_MIN, GAP_MIN, GAP_BOX, GAP_BOX_RISE, GAMMA_MAX = {C_MIN!r}, {GAP_MIN!r}, {GAP_BOX!r}, {GAP_BOX_RISE!r}, "
             f"{GAMMA_MAX!r}",
             f"LEVEL = {LEVEL}",
             "#: name -> (coordinate, gamma band, gamma^2 coordinate, piece breakpoints in x)",
             "REGIONS = {" + ", ".join(f"{k!r}: ({c!r}, {tuple(b)!r}, {sq!r}, {tuple(float(v) for v in p)!r})"
                                      for k, (c, b, sq, p) in REGION_SPECS.items()) + "}",
             "#: worst errors at held-out points against fresh level-3 solves: relative for mu, c (region S) and",
             "#: 1 - c (gap, regions N and L); relative to max(1, |value|) for P*, p(0), A and C; everywhere, and at",
             f"#: c >= {SMALL_C:g} (below, the references carry the solver's round-off)",
             # an unusable quantity stays visible
             "ERRORS = " + repr(None if errors is None else errors[0]).replace("inf", "float('inf')"),
             "ERRORS_ABOVE_SMALL_C = " + repr(None if errors is None else errors[1]).replace("inf", "float('inf')"),
             "#: region -> stored function -> per piece (offset, nx, ny) of its Chebyshev coefficients in the array",
             "SERIES = {"]
    for name, keys in layout.items():
        lines.append(f"    {name!r}: {{")
        lines += [f"        {k!r}: {spans!r}," for k, spans in keys.items()]
        lines.append("    },")
    lines += ["}", ""]
    path.write_text("\n".join(lines), encoding="utf-8")


if __name__ == "__main__":
    main()
