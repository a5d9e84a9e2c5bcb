"""The tabulated fields (``numeric.core.field_table``) and their mapped layouts (``numeric.core.layout_map``).

References: level-4 solves of the singular-basis solver (an independent discretisation of higher degree, ~1e-10
in the fields) and the mapped layout's own level-0 solve at the same (c, gamma) (what the table interpolates).
"""

import importlib.util
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import numeric.core.field_table_data as data
from numeric import flat_punch
from numeric.core.charts import EDGE, RESOLUTIONS, STICK_END, layout
from numeric.core.eigenvalue import solve_given_c, solve_on_operators
from numeric.core.field_table import (GAMMA_MIN, field_table_errors, field_table_pieces, piece_reference, tabulated_field,
                                      use_field_table_data)
from numeric.core.fields import SingularField, TabulatedField
from numeric.core.layout_map import mapped_layout
from numeric.core.operators import AbelOperators
from numeric.core.table import table_given_c
from numeric.solutions.solver import solve_given_c as solver_given_c
from numeric.solutions.table_route import FIELD_ERROR, TABLE_RTOL

ROOT = Path(__file__).resolve().parents[1]
RES = RESOLUTIONS[0]
# new held-out points may be somewhat worse than the build's worst (random points, corners and edge midpoints): 3x;
# plus the level-4 reference's own error in the fields, ~1e-10 (tests/test_singular_solver.py)
MARGIN, REFERENCE = 3.0, 1e-9


def u_ends(lay) -> tuple[np.ndarray, np.ndarray]:
    """Each element's [u_lo, u_hi] (the stick end's chart runs down from c^2, the edge's down from 1)."""
    anchor = np.where(lay.anchor == 0, lay.c2, 1.0)
    lo = np.where(lay.kind == EDGE, 1.0 - lay.hi, np.where(lay.kind == STICK_END, lay.c2 - lay.hi, anchor + lay.lo))
    hi = np.where(lay.kind == EDGE, 1.0 - lay.lo, np.where(lay.kind == STICK_END, lay.c2 - lay.lo, anchor + lay.hi))
    return lo, hi


@pytest.mark.parametrize("c_ref, c", [(0.05, 0.09), (0.4, 0.7), (0.4, 0.4), (0.9, 0.72), (0.9, 0.9)])
def test_a_mapped_layout_covers_0_to_1_in_order_and_is_the_reference_at_c_ref(c_ref, c):
    ref = layout(c_ref, 1.0 - c_ref, RES)
    lay = mapped_layout(c, 1.0 - c, ref, RES)
    lo, hi = u_ends(lay)
    assert lo[0] == 0.0 and hi[-1] == 1.0
    assert np.all(hi > lo)
    # contiguous (the two elements at c^2 share it): neighbouring ends are formed as c^2 + a or 1 - (w - a) from the
    # same map, each within a few units in the last place of u <= 1; 8 ulps of 1 (1.8e-15) leaves room for exp/log
    # rounding on any SIMD path, and a wrong map moves ends by >= 1e-3
    tol = 8 * np.finfo(float).eps
    joined = np.ones(lo.size - 1, dtype=bool)
    joined[lay.stick_end] = False
    assert np.max(np.abs(lo[1:] - hi[:-1])[joined]) <= tol
    assert hi[lay.stick_end] == pytest.approx(c * c, abs=tol) and lo[lay.stick_end + 1] == hi[lay.stick_end]
    if c == c_ref:  # the maps are the identity at c_ref, to the rounding of the round trip through log/logit and exp:
        # relative ~eps |log a| for the smallest offsets (|log a| <= 15 here), so 1e-14
        assert np.allclose(lay.lo, ref.lo, rtol=1e-14, atol=0.0) and np.allclose(lay.hi, ref.hi, rtol=1e-14, atol=0.0)


def test_a_mapped_layout_refuses_to_cross_one_over_root_two():
    ref = layout(0.4, 0.6, RES)
    with pytest.raises(ValueError, match="either side"):
        mapped_layout(0.75, 0.25, ref, RES)


def test_a_tabulated_field_of_a_solution_s_own_values_is_that_solution_s_field():
    # the subclass's end row (p at c) and u* interpolation against the solver's: the same numbers
    c, gamma = 0.5, 0.3
    lay = layout(c, 1.0 - c, RES)
    theta = math.atan(float(table_given_c(c, gamma, quantities=()).mu[0]) * gamma)
    solved = SingularField(solve_on_operators(AbelOperators(lay), gamma, theta))
    read = TabulatedField(lay, gamma, solved.theta, solved.alpha, solved.solution.coefficients, solved.u_star_values,
                          solved.compliance)
    x = np.array([0.0, 0.3, c, 0.6, 0.9, 1.0 - 1e-5])
    for name in ("pressure", "shear", "slip"):
        assert np.array_equal(getattr(read, name)(x), getattr(solved, name)(x))


def test_the_build_s_recorded_errors_are_below_the_route_s_field_error():
    errors = field_table_errors()
    assert errors == data.ERRORS
    # the route's bound on the level-0 fields holds with a margin of ten, the interpolation included
    assert errors["fields"] <= FIELD_ERROR / 10 and errors["interpolation"] <= FIELD_ERROR / 10


def check_points(c: float) -> np.ndarray:
    gap = 1.0 - c
    return np.array([0.0, 0.5 * c, c * (1 - 1e-6), c, c + 1e-6 * gap, 0.5 * (1 + c), 1.0 - 1e-5])


@pytest.mark.parametrize("k", range(6))
def test_new_points_of_each_piece_meet_the_recorded_error_against_level_4(k):
    piece = field_table_pieces()[k]
    rng = np.random.default_rng(100 + k)  # not the build's seed
    for _ in range(2):
        c = float(np.exp(rng.uniform(np.log(piece.c_lo), np.log(piece.c_hi))))
        gamma = float(rng.uniform(GAMMA_MIN, piece.gamma_max))
        read = tabulated_field(c, 1.0 - c, gamma, math.nan)
        ref = solver_given_c(None, c, gamma, 4)
        x = check_points(c)
        scale = np.maximum(1.0, np.abs(ref.pressure(x)))
        bound = MARGIN * data.ERRORS["fields"] + REFERENCE
        assert np.max(np.abs(read.pressure(x) - ref.pressure(x)) / scale) <= bound, (c, gamma)
        assert np.max(np.abs(read.shear(x) - ref.shear(x)) / scale) <= bound, (c, gamma)
        assert np.max(np.abs(read.slip(x) - ref.slip(x))) <= bound, (c, gamma)
        # theta is the mapped layout's discrete eigenvalue, level 0's: its mu within level 0's typical error (1e-7,
        # solver.LEVEL_TYPICAL_ERROR[0]) of the table's (measured at the pieces' corners: 1.2e-8 at most)
        assert read.mu == pytest.approx(float(table_given_c(c, gamma, quantities=()).mu[0]), rel=1e-7)


def test_small_gamma_keeps_the_relative_accuracy_of_theta_the_shear_and_the_slip():
    # theta ~ gamma^2 mu/gamma, the stick shear and u* ~ gamma are stored scaled (stored as they were, theta was 38 %
    # off at gamma = 1e-4): q and u relative to their own size, against the mapped layout's solve, at the least gamma
    # the table is read at. Measured: theta 8.8e-10, q 1.9e-8, u 7.8e-9 relative; unscaled, theta and q were 1.6e-3 off
    # here. Bounds about 30 times the measured (the interpolation's error moves with the build, ~3e-7 recorded)
    c, gamma = 0.5, GAMMA_MIN
    piece = next(p for p in field_table_pieces() if p.holds(c, gamma))
    read = tabulated_field(c, 1.0 - c, gamma, math.nan)
    lay = mapped_layout(c, 1.0 - c, piece_reference(piece), RES)
    theta = math.atan(float(table_given_c(c, gamma, quantities=()).mu[0]) * gamma)
    solved = SingularField(solve_on_operators(AbelOperators(lay), gamma, theta))
    assert read.theta == pytest.approx(solved.theta, rel=3e-8)
    x = np.array([0.2, 0.45, 0.7, 0.95])
    q = solved.shear(x)
    assert np.max(np.abs(read.shear(x) - q) / np.abs(q)) <= 5e-7
    u = solved.slip(np.array([0.7, 0.95]))
    assert np.max(np.abs(read.slip(np.array([0.7, 0.95])) - u) / np.abs(u)) <= 3e-7


def test_outside_the_pieces_the_route_solves_at_level_0():
    assert tabulated_field(0.02, 0.98, 0.3, 1.0) is None and tabulated_field(0.95, 0.05, 0.3, 1.0) is None
    assert tabulated_field(0.85, 0.15, 0.7, 1.0) is None  # above the piece's gamma_max (mu gamma = 1 near)
    assert tabulated_field(0.5, 0.5, 0.5 * GAMMA_MIN, 1.0) is None
    inside, outside = flat_punch(nu=0.2, c=0.5, rtol=TABLE_RTOL), flat_punch(nu=0.2, c=0.95, rtol=TABLE_RTOL)
    assert "tabulated" in inside.route and "computed" in outside.route
    theta = math.atan(outside.mu * outside.gamma)
    level0 = SingularField(solve_given_c(outside.c, outside.gap, outside.gamma, theta, RES))
    x = np.array([0.3, 0.95, 0.97])
    assert np.array_equal(outside.pressure(x), level0.pressure(x))


def test_the_build_script_runs_and_its_table_is_the_one_read(tmp_path):
    out = tmp_path / "field_quick.py"
    script = ROOT / "derivations" / "build_field_table.py"
    subprocess.run([sys.executable, str(script), "--quick", "--output", str(out)], check=True, capture_output=True)
    spec = importlib.util.spec_from_file_location("field_quick", out)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    x = np.array([0.25, 0.75])
    committed = tabulated_field(0.5, 0.5, 0.3, 1.0).pressure(x)
    use_field_table_data(module)
    try:
        quick = tabulated_field(0.5, 0.5, 0.3, 1.0).pressure(x)
    finally:
        use_field_table_data(None)
    # the quick grid (4 x 5 points) is coarser than the committed one: it is the quick table that answered
    assert 0.0 < np.max(np.abs(quick - committed)) <= module.ERRORS["interpolation"]


@pytest.mark.slow
def test_the_committed_field_table_is_what_the_build_makes_today(tmp_path):
    # rebuilt from the current solver and layout map, the fields agree with the committed table's. Not the stored
    # coefficients: at some nodes of the first two pieces (c < 0.2, high gamma) the level-0 system is ill-conditioned
    # along a direction the fields hardly see (a singular-family coefficient of the stick shear moved by 1.7e-5
    # between one and two BLAS threads, the fields at 120 points by 2.8e-10). 1e-8 leaves a margin over that and
    # still catches a change of the discretisation, which moves level-0 fields by its error (1e-8 ... 1e-5).
    out = tmp_path / "field_fresh.py"
    script = ROOT / "derivations" / "build_field_table.py"
    subprocess.run([sys.executable, str(script), "--output", str(out)], check=True, capture_output=True)
    spec = importlib.util.spec_from_file_location("field_fresh", out)
    fresh = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(fresh)
    assert (fresh.LEVEL, fresh.PIECES, fresh.SERIES) == (data.LEVEL, data.PIECES, data.SERIES)
    assert fresh.ERRORS == pytest.approx(data.ERRORS, rel=0.05)
    rng = np.random.default_rng(7)
    points = [(float(np.exp(rng.uniform(np.log(p.c_lo), np.log(p.c_hi)))), float(rng.uniform(GAMMA_MIN, p.gamma_max)))
              for p in field_table_pieces() for _ in range(5)]

    def fields() -> np.ndarray:
        out = []
        for c, gamma in points:
            read, x = tabulated_field(c, 1.0 - c, gamma, 1.0), check_points(c)
            out.append(np.concatenate([read.pressure(x), read.shear(x), read.slip(x)]))
        return np.array(out)
    committed = fields()
    use_field_table_data(fresh)
    try:
        rebuilt = fields()
    finally:
        use_field_table_data(None)
    assert np.max(np.abs(rebuilt - committed) / np.maximum(1.0, np.abs(committed))) <= 1e-8
