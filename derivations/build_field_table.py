"""Build the tabulated fields of ``numeric.core.field_table`` (writes ``numeric/core/field_table_data.py`` and .npy).

On each piece of c (``PIECES``) the level-0 eigensolution on the mapped layout (``numeric.core.layout_map``) is
solved at Chebyshev points of the first kind in (logit c, gamma), gamma in (0, gamma_max) (Newton in theta
from the whole-plane table's theta), and its stored vector (theta, the basis exponent, the coefficients of P, Q,
R and u* at the slip collocation points, ``numeric.core.field_table.stored_vector``) is turned into Chebyshev
coefficients. The interpolant is then checked at held-out random points of each piece (gamma from
``numeric.core.field_table.GAMMA_MIN`` up, where the table is read) and at its corners and edge midpoints (the edges
themselves: every point of the rectangle is read): p, q relative to max(1, |p|)
and u absolute at ten x from 0 to 1 - 1e-5 (x = c included), against the mapped layout's own solve there
("interpolation") and against level 4 ("fields"). The worst of each is recorded in the generated module
(``ERRORS``) and checked by ``tests/test_field_table.py``.

Run time: about 30 s on one core:

    OPENBLAS_NUM_THREADS=1 python derivations/build_field_table.py [--quick] [--output PATH]
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import sys
import time
from pathlib import Path

import numpy as np
from numpy.polynomial import chebyshev

from numeric.core import field_table
from numeric.core.charts import RESOLUTIONS
from numeric.core.eigenvalue import solve_on_operators
from numeric.core.fields import SingularField
from numeric.core.layout_map import mapped_layout
from numeric.core.operators import AbelOperators
from numeric.core.table import table_given_c
from numeric.solutions.progress import tracked
from numeric.solutions.solver import solve_given_c

ROOT = Path(__file__).resolve().parents[1]
LEVEL = 0
#: (c_lo, c_hi, c_ref, gamma_max, n_c, n_gamma): below 1/sqrt(2) the reference is the piece's smallest c, above its
#: largest (``numeric.core.layout_map``); each piece a factor of 2 in c below 0.4 (two more slip elements at its small
#: end than the mapped layout needs at its large end); the sliver (0.7071, 0.70711) around 1/sqrt(2) left out; every
#: piece below mu gamma = 1 (from c = 0.82 at gamma = 3/4 up, the stick pressure's singular family is pinned: the
#: discretisation changes there, and a piece across it converged to 1e-2 only), hence gamma <= 0.65 above c = 0.8
#: (mu gamma = 0.82 at c = 0.9, gamma = 0.65). Sizes (10, 16): the interpolation then stays below ~4e-7, far
#: below level 0's own error ((8, 12) reached 1e-5); 24 points in gamma on (0.70711, 0.8), whose corner c = 0.8,
#: gamma = 3/4 (mu gamma = 0.945) lies next to mu gamma = 1 (2e-6 there with 16).
PIECES = (
    (0.05, 0.1, 0.05, 0.75, 10, 16),
    (0.1, 0.2, 0.1, 0.75, 10, 16),
    (0.2, 0.4, 0.2, 0.75, 10, 16),
    (0.4, 0.7071, 0.4, 0.75, 10, 16),
    (0.70711, 0.8, 0.8, 0.75, 10, 24),
    (0.8, 0.9, 0.9, 0.65, 10, 16),
)
QUICK_SIZES = (4, 5)
N_CHECK = 24


def chebyshev_points(n: int) -> np.ndarray:
    return np.cos(np.pi * (np.arange(n) + 0.5) / n)


def node_field(piece: field_table.FieldPiece, c: float, gap: float, gamma: float) -> SingularField:
    """The level-0 eigensolution on the piece's mapped layout at (c, gamma), Newton from the table's theta."""
    lay = mapped_layout(c, gap, field_table.piece_reference(piece), RESOLUTIONS[piece.level])
    mu = float(table_given_c(c, gamma, gap=gap, quantities=()).mu[0])
    return SingularField(solve_on_operators(AbelOperators(lay), gamma, math.atan(mu * gamma)))


def stored(field: SingularField) -> np.ndarray:
    """The stored vector (``numeric.core.field_table.stored_vector``)."""
    sol = field.solution
    return field_table.stored_vector(field.gamma, sol.theta, sol.system.alpha, sol.coefficients, field.u_star_values,
                                     field.layout.n_stick)


def build_piece(piece: field_table.FieldPiece) -> np.ndarray:
    """Chebyshev coefficients (n_c, n_gamma, stored) of the piece's stored vector."""
    tc, tg = chebyshev_points(piece.n_c), chebyshev_points(piece.n_gamma)
    values = []
    for t in tracked(tc, tc.size, f"piece c in [{piece.c_lo}, {piece.c_hi}]", unit="row"):
        c, gap = field_table.piece_stick_radius(piece, float(t))
        values.append([stored(node_field(piece, c, gap, 0.5 * (float(v) + 1.0) * piece.gamma_max)) for v in tg])
    values = np.array(values)  # (n_c, n_gamma, stored)
    inv_c = np.linalg.inv(chebyshev.chebvander(tc, piece.n_c - 1))
    inv_g = np.linalg.inv(chebyshev.chebvander(tg, piece.n_gamma - 1))
    return np.einsum("ai,ijk,bj->abk", inv_c, values, inv_g)


def write(path: Path, pieces: tuple, blocks: list[np.ndarray], errors: dict | None) -> None:
    flat, series, offset = [], [], 0
    for block in blocks:
        series.append((offset, block.shape))
        flat.append(block.ravel())
        offset += block.size
    np.save(path.with_suffix(".npy"), np.concatenate(flat), allow_pickle=False)
    lines = [
        '"""Tabulated fields of numeric.core.field_table: generated by derivations/build_field_table.py, do not edit.',
        "The Chebyshev coefficients are in field_table_data.npy beside this module (``SERIES`` says where).",
        '"""',
        f"LEVEL = {LEVEL}",
        "#: (c_lo, c_hi, c_ref, gamma_max, n_c, n_gamma) per piece",
        f"PIECES = {tuple(pieces)!r}",
        "#: per piece (offset, shape (n_c, n_gamma, stored)) of its coefficients in the array",
        f"SERIES = {tuple((o, tuple(int(n) for n in s)) for o, s in series)!r}",
        "#: worst errors at held-out points of every piece (p, q relative to max(1, |p|), u absolute, at ten x from 0",
        "#: to 1 - 1e-5): of the interpolation against the mapped layout's own solve, and of the fields against level 4",
        f"ERRORS = {errors!r}",
        "",
    ]
    path.write_text("\n".join(lines))


def load(path: Path):
    spec = importlib.util.spec_from_file_location("fresh_field_table_data", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def check_points(c: float, gap: float) -> np.ndarray:
    """The x at which the fields are compared: the centre, the stick zone, c itself, the annulus, next to the edge."""
    return np.array([0.0, 0.3 * c, 0.7 * c, 0.95 * c, c, c + 0.01 * gap, c + 0.3 * gap, c + 0.7 * gap,
                     1.0 - 1e-3 * gap, 1.0 - 1e-5])


def difference(a, b, x: np.ndarray) -> float:
    """max of |p - p'| and |q - q'| over max(1, |p'|), and of |u - u'| (b the reference)."""
    scale = np.maximum(1.0, np.abs(b.pressure(x)))
    return float(max(np.max(np.abs(a.pressure(x) - b.pressure(x)) / scale),
                     np.max(np.abs(a.shear(x) - b.shear(x)) / scale), np.max(np.abs(a.slip(x) - b.slip(x)))))


def check(pieces: list[field_table.FieldPiece], n_check: int, rng: np.random.Generator) -> dict:
    """Worst interpolation and field errors at held-out points of every piece (the table in use)."""
    errors = {"interpolation": 0.0, "fields": 0.0}
    where: dict[str, tuple] = {}
    edge = (-1.0, 0.0, 1.0)
    points = [(p, float(t), float(v)) for p in pieces for t, v in rng.uniform(-1.0, 1.0, (n_check, 2))]
    points += [(p, t, v) for p in pieces for t in edge for v in edge]
    for piece, t, v in tracked(points, len(points), "check", unit="point"):
        c, gap = field_table.piece_stick_radius(piece, t)
        # gamma over [GAMMA_MIN, gamma_max], where the table is read
        gamma = field_table.GAMMA_MIN + 0.5 * (v + 1.0) * (piece.gamma_max - field_table.GAMMA_MIN)
        x = check_points(c, gap)
        read = field_table.tabulated_field(c, gap, gamma, math.nan)
        if read is None:
            raise RuntimeError(f"the table does not hold c = {c}, gamma = {gamma}")
        for name, value in (("interpolation", difference(read, node_field(piece, c, gap, gamma), x)),
                            ("fields", difference(read, solve_given_c(None, c, gamma, 4, gap=gap), x))):
            value = value if math.isfinite(value) else math.inf
            if not value <= errors[name]:
                errors[name], where[name] = value, (c, gamma)
    print(f"worst at (c, gamma): {where}", file=sys.stderr)
    return {k: float(f"{v:.3g}") for k, v in errors.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a small grid (tests of the script itself)")
    parser.add_argument("--output", type=Path, default=ROOT / "numeric" / "core" / "field_table_data.py")
    args = parser.parse_args()
    t0 = time.perf_counter()
    specs = tuple(spec[:4] + (QUICK_SIZES if args.quick else spec[4:]) for spec in PIECES)
    pieces = [field_table.FieldPiece(*spec, LEVEL) for spec in specs]
    blocks = [build_piece(piece) for piece in pieces]
    write(args.output, specs, blocks, None)
    field_table.use_field_table_data(load(args.output))
    try:
        errors = check(pieces, 2 if args.quick else N_CHECK, np.random.default_rng(20261127))
    finally:
        field_table.use_field_table_data(None)
    write(args.output, specs, blocks, errors)
    print(f"errors: {errors}; {time.perf_counter() - t0:.0f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
