"""The benchmark (``numeric.studies.bench``): its rows carry the right errors, and the headline logic.

The full benchmark takes minutes and its timings are not reproducible; here it runs in a
tiny configuration (the adhesive case nu = 0, the paper's scheme on its mesh (ii) and the
asymptotic formula (2.36)) whose errors are checked against values computed here
independently: the closed forms of App. B written out with ``math``, and the paper's own
printed P* for mesh (ii). The headline ratios are checked on synthetic rows.
"""

import math
import statistics
import time

import pytest

from numeric.app.cli import main
from numeric.baseline import scheme
from numeric.studies import bench, bench_report
from numeric.studies.bench import (
    FULL,
    SCHEME,
    SOLVER,
    TABLE,
    Benchmark,
    Case,
    Config,
    Row,
    best_error_within,
    headline,
    time_to_reach,
)
from numeric.studies.timing import Yardstick, clear_caches, median_time

TINY = Config(cases=(Case(0.0, 1.0),), scheme_h=(), scheme_n=(50,), graded_meshes=(), levels=(),
              methods=frozenset({"scheme", "asymptotic"}), setup=False, budget=0.0, max_runs=1)

# nu = 0: gamma = 1/2, kappa = (2/pi) atanh(1/2) (4.10), written out here
GAMMA = 0.5
KAPPA = 2.0 / math.pi * math.atanh(GAMMA)
P_EXACT = math.log(3.0)  # (B4): atanh(1/2)/(1/2) = log 3
P0_EXACT = KAPPA / GAMMA * math.cosh(math.pi * KAPPA / 2.0)  # (4.10)
INVERSE_A_EXACT = 0.918498211  # (4.18), the errata's table of exact values (9 digits)
P_PAPER_MESH_II = 1.09769  # [S75] §4, mesh table: P* on mesh (ii), N = 50, printed to 5 decimals


@pytest.fixture(scope="module")
def tiny():
    return bench.run(TINY)


def _row(rows, method, quantity):
    (row,) = [r for r in rows if r.method == method and r.quantity == quantity]
    return row


def test_tiny_run_has_one_row_per_method_and_quantity(tiny):
    keys = sorted((r.method, r.resolution, r.quantity) for r in tiny.rows)
    assert keys == sorted([(SCHEME, "N = 50", "P*"), (SCHEME, "N = 50", "p(0)"), (SCHEME, "N = 50", "A"),
                           (bench.ASYMPTOTIC, "(2.36)", "P*")])
    assert all(math.isfinite(r.seconds) and r.seconds > 0.0 for r in tiny.rows)
    assert _row(tiny.rows, SCHEME, "P*").published  # N = 50 is the paper's mesh (ii)


def test_references_are_the_closed_forms(tiny):
    row = _row(tiny.rows, SCHEME, "P*")
    assert abs(row.reference - P_EXACT) < 4e-16  # the same double up to one rounding
    assert abs(_row(tiny.rows, SCHEME, "p(0)").reference - P0_EXACT) < 1e-15  # rounding of cosh, atanh
    assert abs(1.0 / _row(tiny.rows, SCHEME, "A").reference - INVERSE_A_EXACT) < 1e-9  # table printed to 9 digits


def test_paper_scheme_error_at_mesh_ii_matches_the_paper(tiny):
    # The paper prints P* = 1.09769 on mesh (ii) against the exact log 3 = 1.098612: an
    # absolute error of 9.2e-4, relative 8.4e-4. Our row must show that error to within the
    # print's half unit 5e-6 plus 5e-6 for the reproduction (README: our run of the scheme
    # agrees with every printed P* to the 5 decimals), i.e. 1e-5 absolute.
    row = _row(tiny.rows, SCHEME, "P*")
    assert abs(row.error * P_EXACT - abs(P_PAPER_MESH_II - P_EXACT)) < 1e-5
    assert 9.1e-4 < row.error * P_EXACT < 9.3e-4
    # and the row's value is what the scheme returns (relative error of that value, here)
    direct = scheme.solve_adhesive(scheme.uniform_mesh(50), 0.0).compliance
    assert row.value == direct
    assert row.error == pytest.approx(abs(direct - P_EXACT) / P_EXACT, rel=1e-12)


def test_asymptotic_row_is_2_36(tiny):
    # (2.36): P* = 1 + gamma^2/3 = 13/12 at gamma = 1/2; error against log 3 worked out here
    row = _row(tiny.rows, bench.ASYMPTOTIC, "P*")
    assert row.value == pytest.approx(13.0 / 12.0, rel=1e-15)
    assert row.error == pytest.approx((P_EXACT - 13.0 / 12.0) / P_EXACT, rel=1e-12)


def test_render(tiny):
    text = bench_report.render(tiny)
    assert "| paper's scheme (§4) | N = 50 (paper's) | 50 | 8.4e-04 |" in text  # 9.2e-4 / log 3
    assert text == bench_report.render(tiny)  # deterministic for given measurements


def test_main_writes_table_and_plot(tmp_path, monkeypatch, capsys):
    # the command end to end on the tiny configuration (the plot takes most of this test's time)
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(bench, "QUICK", TINY)
    assert main(["bench", "--quick", "--output", str(tmp_path)]) == 0
    assert (tmp_path / "benchmark.md").read_text(encoding="utf-8") == capsys.readouterr().out
    assert (tmp_path / "benchmark.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


# ------------------------------------------------------------------- timing and caches
def test_median_time_runs_the_hook_before_each_call_and_respects_max_runs():
    calls = []
    seconds = median_time(lambda: calls.append("call"), before=lambda: calls.append("before"), budget=10.0,
                          max_runs=3)
    assert calls == ["before", "call"] * 4  # one warm-up call, then 3 timed runs, each after the hook
    assert 0.0 < seconds < 0.1  # two list appends: microseconds; 0.1 s only guards against a unit slip


def test_median_time_counts_the_first_call_when_warm():
    calls = []
    median_time(lambda: calls.append(time.sleep(2e-3)), budget=10.0, max_runs=3, warm=True)
    assert len(calls) == 3  # a call over 1 ms after the caller's warm-up: the first call is a run


def test_median_time_loops_fast_calls():
    count = [0]

    def call():
        count[0] += 1

    median_time(call, budget=0.0, max_runs=5)  # budget 0: exactly one run
    assert count[0] > 10  # a microsecond call is repeated within the run (~2 ms)


def test_the_yardstick_is_timed_again_before_each_case_and_its_time_is_the_median_of_those_runs():
    order = []
    yardstick = Yardstick(lambda: order.append(time.sleep(2e-3) or "yardstick"), budget=10.0, max_runs=1)
    for _ in range(3):
        yardstick.case(lambda: order.append(time.sleep(4e-3) or "case"))
    # each case: the yardstick (a warm-up and one timed run), then the case (a warm-up and one timed run)
    assert order == (["yardstick"] * 2 + ["case"] * 2) * 3
    assert len(yardstick.timings) == 3
    assert yardstick.seconds == statistics.median(yardstick.timings)
    assert 2e-3 <= yardstick.seconds < 1.0  # a 2 ms sleep: at least that; 1 s guards against a unit slip


def test_clear_caches_empties_the_solver_caches():
    scheme.solve_adhesive(scheme.uniform_mesh(10), 0.0)
    assert scheme.collocation_matrix.cache_info().currsize > 0
    names = clear_caches()
    assert "numeric.baseline.scheme.collocation_matrix" in names
    assert "numeric.core.graded_mesh._reference" in names
    assert scheme.collocation_matrix.cache_info().currsize == 0


def test_aitken_recovers_the_limit_of_a_power_law_sequence():
    # values at h, h/2, h/4, h/8 of 1 + 0.3 h^1.2: Aitken's delta^2 is exact for this form
    values = [1.0 + 0.3 * 2.0 ** (-1.2 * k) for k in range(4)]
    limit, order = bench.aitken(values)
    assert abs(limit - 1.0) < 1e-14  # rounding of the differences (~1e-16 / 0.1)
    assert order == pytest.approx(1.2, abs=1e-12)


# --------------------------------------------------------------------- headline logic
def _synthetic(nu, c, method, resolution, seconds, error, **kw):
    """A row whose relative error is ``error`` exactly (reference 1)."""
    return Row(nu, c, "mu", method, resolution, 0, 0, 1.0 + error, 1.0, seconds, **kw)


def _case(nu, paper_time):
    return [
        _synthetic(nu, 0.5, SCHEME, "h = 0.04", paper_time / 2, 1e-3),
        _synthetic(nu, 0.5, SCHEME, "h = 0.02", paper_time, 3e-4, published=True),
        _synthetic(nu, 0.5, SCHEME, "h = 0.01", 0.02, 1e-4),
        _synthetic(nu, 0.5, SCHEME, "h = 0.005", 0.3, 3e-5),
        _synthetic(nu, 0.5, SOLVER, "level 1", 0.05, 1e-9),
        _synthetic(nu, 0.5, SOLVER, "level 2", 0.1, 1e-11),
        _synthetic(nu, 0.5, SOLVER, "level 3", 0.4, 1e-13),
        _synthetic(nu, 0.5, SOLVER, "level 4", 0.001, 0.0, is_reference=True),  # must be ignored
        _synthetic(nu, 0.5, TABLE, "level-3 fit", 0.002, 1e-12),
    ]


def test_time_to_reach_and_best_error_within():
    points = [(0.05, 1e-9), (0.1, 1e-11), (0.4, 1e-13)]
    assert time_to_reach(points, 1e-10) == 0.1
    assert time_to_reach(points, 1e-14) is None
    assert best_error_within(points, 0.2) == 1e-11
    assert best_error_within(points, 0.01) is None


def test_headline_on_synthetic_rows():
    rows = _case(0.0, 0.005) + _case(0.25, 0.01)
    h = headline(rows, "mu", target=1e-10)
    assert h.cases == 2
    assert h.our_seconds == 0.1 and h.our_levels == ("level 2",)  # level 1 misses 1e-10; level 4 is the reference
    assert h.paper_seconds == pytest.approx(0.0075)  # median of 0.005 and 0.01
    assert h.paper_error == pytest.approx(3e-4)
    assert h.ratio == pytest.approx(15.0)  # median of 0.1/0.005 = 20 and 0.1/0.01 = 10
    assert h.ratio_range == pytest.approx((10.0, 20.0))
    assert h.paper_error_in_our_time == pytest.approx(1e-4)  # h = 0.01 (0.02 s) fits in 0.1 s, h = 0.005 does not
    assert h.our_error_in_paper_time is None  # no level runs in 5-10 ms
    assert h.our_fastest_seconds == 0.05
    assert h.table_seconds == 0.002 and h.table_error == pytest.approx(1e-12)


def test_headline_extrapolates_the_paper_along_a_power_law():
    # error = 1e-3 / t exactly: slope 1, and 1e-10 is reached at t = 1e7 s
    rows = [_synthetic(0.0, 0.5, SCHEME, f"h{k}", t, 1e-3 / t, published=k == 0) for k, t in enumerate((0.5, 2.0, 8.0))]
    rows.append(_synthetic(0.0, 0.5, SOLVER, "level 2", 0.1, 1e-11))
    h = headline(rows, "mu", target=1e-10)
    assert h.paper_slope == pytest.approx(1.0, rel=1e-9)
    assert h.paper_extrapolated_seconds == pytest.approx(1e7, rel=1e-9)
    assert h.our_error_in_paper_time == pytest.approx(1e-11)  # level 2 (0.1 s) runs within the paper's 0.5 s


def test_headline_is_none_without_a_level_reaching_the_target():
    rows = [r for r in _case(0.0, 0.005) if r.resolution in ("h = 0.02", "level 1")]
    assert headline(rows, "mu", target=1e-10) is None


def test_headline_renders_when_our_solver_is_faster_than_every_mesh_of_the_paper():
    # our level 2 (0.1 s) before the scheme's coarsest mesh (0.5 s): nothing of the paper runs in our time, and the
    # rendered line says so (it formatted None and the benchmark stopped)
    from numeric.studies.bench_report import render

    rows = [_synthetic(0.0, 0.5, SCHEME, f"h{k}", t, 1e-3 / t, published=k == 0) for k, t in enumerate((0.5, 2.0, 8.0))]
    rows.append(_synthetic(0.0, 0.5, SOLVER, "level 2", 0.1, 1e-11))
    h = headline(rows, "mu", target=1e-10)
    assert h.paper_error_in_our_time is None and h.ratio == pytest.approx(0.2)
    bench = Benchmark(FULL, (), tuple(rows), (), (), 1.0)
    assert "the paper's scheme reaches nothing" in render(bench)


def test_plane_rows_render_beside_their_axisymmetric_task():
    # the plane table's second ratio is to the axisymmetric row of the same task (2 ms against 8 ms: 4), blank where
    # the axisymmetric table has no such task
    from numeric.studies.bench_report import render
    from numeric.studies.timing import SideBySide

    axisymmetric = (SideBySide("full solution for given c <= 0.95 (level 2)", 2e-3, 1.0, 1e-13, 6, "level 4"),)
    plane = (SideBySide("full solution for given c <= 0.95 (level 2)", 8e-3, 2.0, 1e-11, 6, "median"),
             SideBySide("plane law route, c = 1e-6, later calls", 3e-5, 0.01, 5e-7, 2, "solver"))
    text = render(Benchmark(FULL, (), (), (), (), 1.0, {}, axisymmetric, plane))
    assert "| full solution for given c <= 0.95 (level 2) | 8 | 2 | 4 |" in text
    assert "| plane law route, c = 1e-6, later calls | 0.03 | 0.01 |  |" in text


def test_the_plane_reference_is_the_converged_value():
    # the plane benchmark's reference at nu = 0.3, c = 0.5 against test_plane's MU_REF_05 (six solves, degrees 20-28,
    # spread 1.1e-12 = 4.6e-12 relative): within that spread plus the reference's own (four solves, ~1e-11 relative at
    # this theta = 0.068, see reference_mu); measured 2.1e-12
    from numeric.studies.plane_bench import reference_mu

    assert abs(reference_mu(0.3, 0.5) / 0.23740259715125 - 1) < 1.5e-11


def test_the_schemes_time_to_the_target_is_interpolated_between_its_meshes():
    # error 1e-3 * (t / 1 ms)^-1: 2e-4 at 5 ms, 5e-5 at 20 ms; 1e-4 is crossed at 10 ms exactly (log-log line)
    from numeric.studies.equal_accuracy import TARGET, time_to_target
    points = [(t, 1e-3 * (t / 1e-3) ** -1) for t in (1e-3, 5e-3, 2e-2)]
    seconds, extrapolated = time_to_target(points)
    assert seconds == pytest.approx(1e-2, rel=1e-12) and not extrapolated
    # none within 1e-4: the line through all three is extrapolated to it (the same 10 ms)
    seconds, extrapolated = time_to_target(points[:2])
    assert seconds == pytest.approx(1e-2, rel=1e-12) and extrapolated and TARGET == 1e-4
    # an error that grows with the time is not extrapolated; the first mesh within the target is its own time
    assert time_to_target([(1e-3, 2e-4), (2e-3, 3e-4)]) == (None, False)
    assert time_to_target([(1e-3, 5e-5), (2e-3, 1e-5)]) == (1e-3, False)


def test_equal_accuracy_rows_render_with_their_ratio():
    from numeric.studies.bench_report import render
    from numeric.studies.equal_accuracy import EqualAccuracy
    rows = (EqualAccuracy(0.25, 0.5, 2e-3, 1e-7, ((0.01, 2e-3, 2e-4), (0.005, 1e-2, 8e-5)), 8e-3, False),
            EqualAccuracy(0.0, 0.99, 2e-3, 1e-7, ((0.01, 5e-3, 1e-2),), 1e9, True),
            EqualAccuracy(-0.5, 0.5, 2e-3, 1e-7, (), None, False, "finds no eigenvalue at h = 0.0035"))
    text = render(Benchmark(FULL, (), (), (), (), 1.0, {}, (), (), rows))
    assert "| 0.25 | 0.5 | 2 | 1.0e-07 | 8.0e-05 (0.005) | 8 | 4 |" in text
    assert "| 0 | 0.99 | 2 | 1.0e-07 | 1.0e-02 (0.01) | > 1 h (extrapolated) | > 1e5 |" in text
    assert "| not reached | the scheme finds no eigenvalue at h = 0.0035 |" in text
    assert "Over the 2 cases with a ratio: median 2.5e+11, least 4." in text
