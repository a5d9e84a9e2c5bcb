"""The whole-plane tables (``numeric.core.table``) against fresh solves.

The build (``derivations/build_tables.py``) records its worst errors at held-out points; these
tests check the record against the issue's target (1e-10) and the tables against new points of
their own (level-3 solves, ~1e-12), in each region (S: c <= 0.9; N: 1 - c down to 1e-13 at small
gamma; L: up to the largest stick radius), both ways (mu given c, c given mu) and at the ends:
mu = inf (c_max, closed form), below the table (the law, c underflowing to 0), outside (nan).
"""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import numeric.core.table_data as data
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu
from numeric import flat_punch, friction_coefficient, stick_radius
from numeric.core.table import QUANTITIES, table_given_c, table_given_mu
from numeric.solutions.power_law import displacement_constant, indentation_constant
from numeric.solutions.solver import solve_given_c

ROOT = Path(__file__).resolve().parents[1]
# New points may be somewhat worse than the build's worst held-out point (random points and the
# corners of each region): 3x; plus the level-3 reference's own error, ~1e-12 relative (LEVEL_TYPICAL_ERROR).
MARGIN, SOLVER = 3.0, 2e-12


#: What README.md states for the tables (the build's record, rounded up). The issue asked for 1e-10: met by every
#: quantity down to C_MIN = 1e-5 (until the solver's small-c round-off was removed, the level-3 references between
#: 1e-5 and 1e-3 carried ~2e-13 (2e-3/c) absolute in mu, and the record there was mu 3.4e-10, c 4.3e-9, p(0) 7.8e-9).
CLAIMS = {"mu": 1e-11, "c": 1e-12, "gap": 1e-12, "compliance": 1e-14, "central_pressure": 1e-12,
          "sphere_A": 2e-12, "sphere_C": 2e-11, "cone_A": 1e-12, "cone_C": 1e-11}
CLAIMS_ABOVE_SMALL_C = 1e-10


def test_recorded_errors_meet_the_stated_accuracy():
    # mu, c, 1 - c relative; the rest relative to max(1, |value|)
    for name in ("mu", "c", "gap") + QUANTITIES:
        assert data.ERRORS[name] <= CLAIMS[name], (name, data.ERRORS[name])
        assert data.ERRORS_ABOVE_SMALL_C[name] <= CLAIMS_ABOVE_SMALL_C, (name, data.ERRORS_ABOVE_SMALL_C[name])


def _check_quantities(tv, sol, extra: float = 0.0) -> None:
    ref = {"compliance": sol.compliance, "central_pressure": float(sol.pressure(0.0)),
           "sphere_A": indentation_constant(sol, 2.0), "sphere_C": displacement_constant(sol, 2.0),
           "cone_A": indentation_constant(sol, 1.0), "cone_C": displacement_constant(sol, 1.0)}
    for name in QUANTITIES:
        scale = max(1.0, abs(ref[name]))
        assert abs(tv.values[name][0] - ref[name]) <= (MARGIN * data.ERRORS[name] + SOLVER + extra) * scale, name


@pytest.mark.parametrize("c, gamma", [(2e-5, 0.7), (0.0123, 0.61), (0.377, 0.05), (0.71, 0.42), (0.89, 0.27)])
def test_region_s_against_fresh_solves(c, gamma):
    sol = flat_punch(gamma=gamma, c=c, level=3)
    tv = table_given_c(c, gamma)
    assert tv.mu[0] == pytest.approx(sol.mu, rel=MARGIN * data.ERRORS["mu"] + SOLVER)
    _check_quantities(tv, sol)
    back = table_given_mu(sol.mu, gamma)
    assert back.c[0] == pytest.approx(c, rel=MARGIN * data.ERRORS["c"] + SOLVER)


@pytest.mark.parametrize("gap, gamma", [(0.05, 0.1), (1e-6, 0.08), (1e-11, 0.03)])
def test_region_n_against_fresh_solves(gap, gamma):
    # 1 - c given exactly (c = 1 - gap rounds it): the solver and the table both take it
    sol = solve_given_c(None, 1.0 - gap, gamma, 3, gap=gap)
    tv = table_given_c(1.0 - gap, gamma)
    # the table forms 1 - c from the rounded c: relative change of gap up to 1.1e-16/gap, times d log mu/d log gap
    # (<= 1/log(2/gap) < 1)
    rounding = 1.2e-16 / gap
    assert tv.mu[0] == pytest.approx(sol.mu, rel=MARGIN * data.ERRORS["mu"] + SOLVER + rounding)
    _check_quantities(tv, sol)
    back = table_given_mu(sol.mu, gamma)
    assert back.gap[0] == pytest.approx(gap, rel=MARGIN * data.ERRORS["gap"] + SOLVER)


@pytest.mark.parametrize("mu, gamma", [(3.0, 0.7), (40.0, 0.5), (1e4, 0.62), (200.0, 0.3), (2.0, 0.13)])
def test_region_l_against_fresh_solves(mu, gamma):
    sol = flat_punch(gamma=gamma, mu=mu, level=3)
    tv = table_given_mu(mu, gamma)
    assert tv.gap[0] == pytest.approx(sol.gap, rel=MARGIN * data.ERRORS["gap"] + SOLVER)
    _check_quantities(tv, sol)


def test_mu_inf_is_the_closed_form_c_max():
    # w = 0 is a node line of region L's interpolant in x: c_max itself comes from the closed form
    # (asymptotics.largest_stick_radius, checked against the limit problem to 1e-10 in tests/test_slip_limit.py)
    for gamma in (0.2, 0.5, 0.74):
        tv = table_given_mu(math.inf, gamma)
        assert tv.gap[0] == pytest.approx(float(largest_stick_radius_gap(gamma)), rel=1e-14)
        assert np.isfinite(tv.values["compliance"][0])


def test_outside_the_table_is_nan_and_the_api_answers():
    assert np.isnan(table_given_c(1e-7, 0.5).mu).all()  # below C_MIN: the law's
    assert np.isnan(table_given_c(1.0 - 1e-14, 0.05).mu).all()  # beyond GAP_MIN at small gamma: the adhesive limit's
    gap_max = float(largest_stick_radius_gap(0.5))
    assert np.isnan(table_given_c(1.0 - 0.5 * gap_max, 0.5).mu).all()  # beyond c_max: no eigenvalue
    assert np.isnan(table_given_mu(1e-4, 0.5).c).all()


@pytest.mark.parametrize("mu, nu", [(1e-3, -0.5), (1e-3, -0.9), (1e-200, 0.3)])
def test_underflowing_stick_radius_is_zero_with_the_law(mu, nu):
    # c ~ 4 exp(-gamma/mu) (2.29) is below 1e-300 here: 0.0, by the asymptotic law, no exception
    assert 4.0 * math.exp(-gamma_from_nu(nu) / mu * 0.9) < 1e-250
    assert stick_radius(mu, nu) == 0.0
    sol = flat_punch(nu=nu, mu=mu)
    assert sol.c == 0.0 and sol.route.startswith("asymptotic")


def test_sweeps_use_the_table_and_broadcast():
    out = stick_radius(np.array([[0.1], [2.0]]), np.array([0.0, 0.25, -0.5]))
    assert out.shape == (2, 3) and np.all((out > 0) & (out < 1))
    assert isinstance(stick_radius(0.2, 0.25), float)
    assert np.all(np.diff(stick_radius(np.linspace(0.1, 5.0, 50), 0.3)) > 0)  # c increases with mu
    mu = friction_coefficient(np.array([0.5, 0.99]), np.array([0.0, -0.3]))
    assert mu[0] == pytest.approx(flat_punch(nu=0.0, c=0.5).mu, rel=MARGIN * data.ERRORS["mu"] + SOLVER)
    assert mu[1] == pytest.approx(flat_punch(nu=-0.3, c=0.99).mu, rel=MARGIN * data.ERRORS["mu"] + SOLVER)


def test_the_solver_is_not_needed_for_random_points_of_the_whole_plane():
    # the batch (mu in [0.05, 2], nu in [-0.5, 0.49]) and a wider one (mu up to 1e6, nu to -0.999): the
    # table answers each point, or the point lies beyond it, where a closed route answers (the law below
    # c = C_MIN, the adhesive limit below 1 - c = GAP_MIN); the time is measured in derivations/benchmark.md
    rng = np.random.default_rng(1)
    for mu_hi, nu_lo in ((2.0, -0.5), (1e6, -0.999)):
        mu = np.exp(rng.uniform(math.log(0.05), math.log(mu_hi), 1000))
        nu = rng.uniform(nu_lo, 0.49, 1000)
        found = table_given_mu(mu, gamma_from_nu(nu))
        inside = (found.c > 0.0) & (found.gap > 0.0)
        assert inside.mean() > 0.9
        for m, n in zip(mu[~inside], nu[~inside]):
            assert not flat_punch(nu=float(n), mu=float(m)).route.startswith("solver"), (m, n)


@pytest.mark.slow
def test_build_script_runs(tmp_path):
    # the quick build (a small grid, ~1 minute) writes a module (its coefficients in a .npy beside it, ``SERIES``
    # saying where) that evaluates: mu at c = 0.5, gamma = 0.25 within the quick build's own recorded error of the
    # committed table's value (its grid is 4 x 4 a piece; its recorded worst 1.8e-3 over the plane)
    import importlib.util
    from numeric.core.table import use_table_data
    out = tmp_path / "table_quick.py"
    subprocess.run([sys.executable, str(ROOT / "derivations" / "build_tables.py"), "--quick", "--output", str(out)],
                   check=True)
    assert out.with_suffix(".npy").exists()
    spec = importlib.util.spec_from_file_location("table_quick", out)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    reference = table_given_c(np.array([0.5]), np.array([0.25]), quantities=()).mu[0]
    use_table_data(module)
    try:
        quick = table_given_c(np.array([0.5]), np.array([0.25]), quantities=()).mu[0]
    finally:
        use_table_data(None)
    # (and it is the quick table that answered: its coarse grid is 3e-4 off there, measured)
    assert 1e-8 < abs(quick / reference - 1) <= module.ERRORS["mu"]


@pytest.mark.slow
def test_a_built_wheel_carries_the_table_coefficients(tmp_path):
    # the coefficients live in numeric/core/table_data.npy, package data: a non-editable install must have them
    import zipfile

    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path),
                    str(ROOT)], check=True)
    (wheel,) = tmp_path.glob("hertz_friction-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    assert "numeric/core/table_data.npy" in names and "numeric/core/table_data.py" in names
    assert "numeric/core/field_table_data.npy" in names and "numeric/core/field_table_data.py" in names


def test_threads_that_first_read_the_tables_together_load_them_once(monkeypatch):
    # a sweep's threads (a thread pool, a Dask worker's threads) reading the tables first at the same moment: one
    # loads them, the others wait (concurrent loads did it four times here, and numpy's .npy header parse in two
    # threads at once raised SystemError on CPython 3.11.7, python/cpython#106905). The counting load sleeps 50 ms so
    # that the four threads, released together by the barrier, overlap in it; without the lock this counts 4.
    import threading
    import time
    from concurrent.futures import ThreadPoolExecutor

    from numeric.core import table
    loads = []
    real = table.coefficients_of

    def counting(data):
        loads.append(threading.get_ident())
        time.sleep(0.05)
        return real(data)

    monkeypatch.setattr(table, "coefficients_of", counting)
    table.use_table_data(None)  # the committed tables, not yet loaded
    barrier = threading.Barrier(4)

    def read(_):
        barrier.wait()
        return table.table_available()

    try:
        with ThreadPoolExecutor(4) as pool:
            assert all(pool.map(read, range(4)))
        assert len(loads) == 1
    finally:
        table.use_table_data(None)
