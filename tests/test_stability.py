"""Property-based stress tests of the flat-punch solution ([S75] §2) and tests of numeric.studies.stability.

Hypothesis draws (nu, mu) or (nu, c) over the whole domain nu in (-1, 1/2) (gamma from 0.75 to 0)
and c from the table's C_MIN up to next to the largest stick radius c_max(nu), and checks the
physics: c increasing in mu and nu, the constraints (2.8)-(2.9), continuity at x = c, the stick
radius shared by the flat punch and the power laws (§3.2), round trips, and 1 <= P* <=
atanh(gamma)/gamma (B4) increasing in c. Example counts are small (the profile of
tests/conftest.py supplies derandomisation and deadline); the ``slow``-marked twins run more.
The study's own checks compare with independent references: the hp-graded solver, the closed-form
largest stick radius and adhesive solution (B3), (B4), (4.10), mpmath at 30 digits, and convergence.
Each tolerance says where it comes from.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu
from numeric import flat_punch, friction_coefficient, power_law, stick_radius
from numeric.app.cli import main
from numeric.core import table_data
from numeric.core.table import table_available, table_errors
from numeric.solutions.solver import ERROR_FLOOR
from numeric.solutions.sweep import TABLE_MARGIN
from numeric.studies.stability import (Grid, HonestyCheck, adhesive_mp_check, adhesive_plateau, check_honesty,
                                       memory_cap, plateau_study, slip_limit_plateau, sweep, system_mpmath_check)

FAST = settings(max_examples=4)
SLOW = settings(max_examples=40)
#: nu over (-1, 1/2) short of the ends, where gamma -> 3/4 and gamma -> 0 (the ends are swept by the study)
NU = st.floats(-0.99, 0.49)


def _gamma(nu: float) -> float:
    return float(gamma_from_nu(nu))


def _c_top(nu: float) -> float:
    """A stick radius safely below c_max(nu): 1 - c = 10 (1 - c_max), or 1 - 1e-9 where c_max rounds to 1."""
    gap_max = float(largest_stick_radius_gap(_gamma(nu)))
    return 1.0 - max(10.0 * gap_max, 1e-9)


def _c_of(nu: float, fraction: float) -> float:
    """c from 2 C_MIN to _c_top(nu), uniform in logit(c). (At C_MIN itself, 1e-5, the hand-over to the law is
    decided by the table's mu(C_MIN), to its error: a round trip from c = C_MIN may land on the law's side.)"""
    c_lo = 2.0 * table_data.C_MIN
    lo, hi = math.log(c_lo / (1 - c_lo)), math.log(_c_top(nu) / (1 - _c_top(nu)))
    s = lo + fraction * (hi - lo)
    return 1.0 / (1.0 + math.exp(-s))


# ----------------------------------------------------------------------------- monotonicity
def _c_increases_in_mu(nu: float, fraction: float, factor: float) -> None:
    mu = flat_punch(nu=nu, c=_c_of(nu, fraction), level=1).mu
    a, b = flat_punch(nu=nu, mu=mu, level=1), flat_punch(nu=nu, mu=factor * mu, level=1)
    # both c carry their own error estimate (never optimistic in derivations/stability.md); the increase must
    # exceed both. Measured (b.c - a.c)/(errors) >= 5 for factor 1.01 over nu in [-0.99, 0.49] and c up to
    # _c_of(nu, 0.95); beyond, 1 - c < 1e-8 at small gamma, the increase falls below the level-1 errors
    assert b.c - a.c > a.error + b.error, (nu, mu, factor, a.c, b.c)


@FAST
@given(nu=NU, fraction=st.floats(0.0, 0.9), factor=st.floats(1.05, 3.0))
def test_stick_radius_increases_with_mu(nu, fraction, factor):
    """§2.1: more friction, larger stick zone, from c = 1e-5 up to next to c_max (mu gamma up to ~1e6)."""
    _c_increases_in_mu(nu, fraction, factor)


@pytest.mark.slow
@SLOW
@given(nu=NU, fraction=st.floats(0.0, 0.95), factor=st.floats(1.01, 3.0))
def test_stick_radius_increases_with_mu_many(nu, fraction, factor):
    _c_increases_in_mu(nu, fraction, factor)


def _c_increases_in_nu(nu: float, dnu: float, fraction: float) -> None:
    # Direction: at fixed c the friction needed grows with gamma, mu = gamma f0(c) (1 + O(gamma^2)) with
    # f2 > 0 ((2.28)), and gamma = (1 - 2nu)/(2 - 2nu) decreases with nu (2.2); so mu_c(c) decreases with nu,
    # and at fixed mu the stick radius increases with nu. Both at level 1 with their errors.
    nu2 = min(nu + dnu, 0.49)
    c = _c_of(nu, fraction)
    a = flat_punch(nu=nu, c=c, level=1)
    b = flat_punch(nu=nu2, c=c, level=1)
    assert b.mu < a.mu - a.error - b.error, (nu, nu2, c)
    assert flat_punch(nu=nu2, mu=a.mu, level=1).c > c


@FAST
@given(nu=st.floats(-0.99, 0.45), dnu=st.floats(0.01, 0.1), fraction=st.floats(0.0, 0.9))
def test_stick_radius_increases_with_nu(nu, dnu, fraction):
    _c_increases_in_nu(nu, dnu, fraction)


@pytest.mark.slow
@SLOW
@given(nu=st.floats(-0.99, 0.48), dnu=st.floats(0.001, 0.5), fraction=st.floats(0.0, 1.0))
def test_stick_radius_increases_with_nu_many(nu, dnu, fraction):
    _c_increases_in_nu(nu, dnu, fraction)


# ----------------------------------------------------------------------------- (2.8)-(2.9), continuity
def _constraints_and_continuity(nu: float, c: float) -> None:
    coarse, fine = flat_punch(nu=nu, c=c, level=1), flat_punch(nu=nu, c=c, level=2)
    mu = fine.mu
    # pointwise error of the level-2 field: its difference from level 1 (levels converge exponentially,
    # so the coarser one's distance bounds the finer one's error)
    x_stick = c * (1.0 - np.logspace(-9, 0, 40, endpoint=False))
    phi = mu * fine.pressure(x_stick) - fine.shear(x_stick)  # (2.8) excess friction
    phi_err = np.abs(phi - (coarse.mu * coarse.pressure(x_stick) - coarse.shear(x_stick)))
    assert np.all(phi >= -phi_err), (nu, c)
    assert np.all(fine.slip(x_stick) == 0.0)  # u = 0 in the stick zone (2.7)
    x_slip = c + (1.0 - c) * np.logspace(-9, -1e-9, 40)
    assert np.array_equal(fine.shear(x_slip), mu * fine.pressure(x_slip))  # q = mu p (2.9), exact by construction
    u = fine.slip(x_slip)
    assert np.all(u <= np.abs(u - coarse.slip(x_slip))), (nu, c)  # slip inward, u <= 0 (2.9)
    assert np.all(fine.pressure(np.concatenate([x_stick, x_slip])) > 0.0)
    # continuity at x = c: p and q are continuous but only Hoelder there, A + s^beta B with beta = 1 - 2 alpha,
    # tan(pi alpha) = mu gamma, s^2 = |x^2 - c^2| / min(c^2, 1 - c^2) (numeric.core.charts: the scale of the
    # elements at c), so across one rounding step delta of x they change by ~ s^beta = (2 c delta /
    # min(c^2, 1 - c^2))^(1/2 - alpha) times their size, plus the discretisation error on each side (level 2
    # against level 1). Measured coefficient of the first term <= 0.71 (1.8 at c = 1e-5, where the second
    # dominates) over nu in [-0.99, 0.49], c from 1e-5 to 1 - 10 (1 - c_max); bound 10. A wrong eigenvalue
    # would leave a (c - x)^(-1/2 - alpha) jump instead.
    below = np.nextafter(c, 0.0)
    alpha = math.atan(mu * fine.gamma) / math.pi
    local = 10.0 * (2.0 * c * (c - below) / min(c * c, (1.0 - c) * (1.0 + c))) ** (0.5 - alpha)
    for f, g in ((fine.pressure, coarse.pressure), (fine.shear, coarse.shear)):
        jump = abs(float(f(below)) - float(f(c)))
        discretisation = abs(float(f(below)) - float(g(below))) + abs(float(f(c)) - float(g(c)))
        scale = max(abs(float(fine.pressure(c))), abs(float(fine.shear(c))))
        assert jump <= local * scale + discretisation, (nu, c, jump, local * scale, discretisation)


@FAST
@given(nu=NU, fraction=st.floats(0.1, 0.9))
def test_constraints_and_continuity(nu, fraction):
    """(2.8): mu p - q >= 0 on (0, c); (2.9): q = mu p, u <= 0 on (c, 1); p, q continuous at c."""
    _constraints_and_continuity(nu, _c_of(nu, fraction))


@pytest.mark.slow
@settings(max_examples=20)
@given(nu=NU, fraction=st.floats(0.0, 1.0))
def test_constraints_and_continuity_many(nu, fraction):
    _constraints_and_continuity(nu, _c_of(nu, fraction))


# ----------------------------------------------------------------------------- power law, round trips, P*
@settings(max_examples=2)
@given(nu=NU, fraction=st.floats(0.2, 0.9))
def test_power_law_has_the_flat_punch_stick_radius(nu, fraction):
    """§3.2: c depends on mu and nu only, not on the indenter's shape n (same level, same c)."""
    mu = flat_punch(nu=nu, c=_c_of(nu, fraction), level=1).mu
    flat = flat_punch(nu=nu, mu=mu, level=1)
    for n in (1, 2):
        h = power_law(n, nu=nu, mu=mu, level=1)
        assert h.c == flat.c and h.error == flat.error
        assert math.isfinite(h.A) and h.A > 0 and math.isfinite(h.C)
        assert h.compliance == pytest.approx(n * flat.compliance / (n + 1), rel=1e-15)  # (3.17), exact arithmetic


def _round_trip_table(nu: float, fraction: float) -> None:
    # from just above C_MIN (at C_MIN a rounding below hands over to the law) to the box edge at small gamma,
    # 1 - GAP_BOX (beyond, region N or L); nu = 1/2 (gamma = 0, mu = 0 for every c) has no round trip
    c = 1.001 * table_data.C_MIN + fraction * (1.0 - table_data.GAP_BOX - 1.001 * table_data.C_MIN)
    back = stick_radius(friction_coefficient(c, nu), nu)
    # both directions read the same Chebyshev series; the inversion is Newton to 1e-15 in the unit
    # coordinate (numeric.core.table), about 1e-14 in logit c over the box, so c returns to ~1e-14
    # relative; 1e-12 leaves 100x for the rounding of the series
    assert back == pytest.approx(c, rel=1e-12)


@pytest.mark.skipif(not table_available(), reason="the Chebyshev table is not built")
@settings(max_examples=25)
@given(nu=st.floats(-0.999, 0.49), fraction=st.floats(0.0, 1.0))
def test_round_trip_table(nu, fraction):
    _round_trip_table(nu, fraction)


@pytest.mark.slow
@pytest.mark.skipif(not table_available(), reason="the Chebyshev table is not built")
@settings(max_examples=300)
@given(nu=st.floats(-0.999, 0.49), fraction=st.floats(0.0, 1.0))
def test_round_trip_table_many(nu, fraction):
    _round_trip_table(nu, fraction)


@pytest.mark.parametrize("nu, gap_factor", [(0.0, None), (-0.9, 10.0)])
def test_round_trip_solver(nu, gap_factor):
    """Given c, then given the mu found: c again within the two errors (the mu error converted to c by
    the slope d mu/dc, from two level-1 solves; near c_max mu grows like 1/(c_max - c)). At c = 0.97, and
    at 1 - c = 10 (1 - c_max)."""
    c = 0.97 if gap_factor is None else 1.0 - gap_factor * float(largest_stick_radius_gap(_gamma(nu)))
    given_c = flat_punch(nu=nu, c=c)
    back = flat_punch(nu=nu, mu=given_c.mu)
    h = 1e-4 * min(c, 1.0 - c)
    slope = (flat_punch(nu=nu, c=c + h, level=1).mu - flat_punch(nu=nu, c=c - h, level=1).mu) / (2 * h)
    assert abs(back.c - c) <= back.error + given_c.error / slope


def _compliance_bounds(nu: float, fraction: float, step: float) -> None:
    c = _c_of(nu, fraction)
    c2 = _c_of(nu, min(fraction + step, 1.0))
    a, b = flat_punch(nu=nu, c=c, level=1), flat_punch(nu=nu, c=c2, level=1)
    gamma = _gamma(nu)
    top = math.atanh(gamma) / gamma  # (B4): the fully adhesive compliance bounds P* from above
    for s in (a, b):
        assert 1.0 - s.error < s.compliance < top + s.error  # frictionless P* = 1 from below
    assert b.mu > a.mu  # larger c needs larger mu
    assert b.compliance - a.compliance > -(a.error + b.error)  # P* increases with mu (and c)


@FAST
@given(nu=NU, fraction=st.floats(0.0, 0.95), step=st.floats(0.01, 0.3))
def test_compliance_between_limits_and_increasing(nu, fraction, step):
    _compliance_bounds(nu, fraction, step)


@pytest.mark.slow
@SLOW
@given(nu=NU, fraction=st.floats(0.0, 1.0), step=st.floats(1e-3, 0.3))
def test_compliance_between_limits_and_increasing_many(nu, fraction, step):
    _compliance_bounds(nu, fraction, step)


# ----------------------------------------------------------------------------- the stability module
TINY = Grid(nus=(-0.999,), mus=(0.3,), cs=(0.5, 0.99, 1.0), gap_factors=(), power_law_mus=(), limit_nus=(),
            limit_mu_gammas=())


def test_sweep_records_values_and_the_documented_exception():
    pts = sweep(TINY)
    by = {(p.function, p.argument): p for p in pts}
    s = by[("flat_punch(c)", 0.5)]
    assert s.admissible and not s.raised and s.route.startswith("solver level 2")
    # friction_coefficient reads the table: its recorded error, with the sweeps' margin, besides the solver's
    table_bound = TABLE_MARGIN * table_errors()["mu"] * s.mu
    assert by[("friction_coefficient", 0.5)].mu == pytest.approx(s.mu, abs=s.error + table_bound)
    # c = 0.99 is above c_max(-0.999) = 0.951: NoEigenvalueError, as documented, is not a finding
    above = by[("flat_punch(c)", 0.99)]
    assert above.raised.startswith("NoEigenvalueError") and above.expected and above.admissible
    adhesive = by[("flat_punch(c)", 1.0)]
    assert adhesive.mu == math.inf and adhesive.admissible  # documented: c = 1 is the adhesive solution
    # the largest stick radius against its definition K'(c)/K(c) = (2/pi) atanh(gamma), and the slip limit
    c_max = next(p for p in pts if p.function == "largest_stick_radius")
    assert c_max.admissible and c_max.c == pytest.approx(0.9511455292845629, abs=1e-15)
    limit = next(p for p in pts if p.function == "slip_limit")
    assert abs(limit.c - c_max.c) <= limit.error and math.isinf(limit.mu)


def test_memory_cap_turns_a_runaway_allocation_into_a_memory_error():
    pytest.importorskip("resource")
    with pytest.raises(MemoryError), memory_cap(2**28):
        np.ones(2**30)  # 8 GiB
    np.ones(2**20)  # the cap is lifted afterwards


def test_honesty_check_statuses():
    honest = HonestyCheck("flat_punch(c)", 0.0, 0.5, "level 4", "mu", 1.0, 1.0 + 5e-11, 1e-10, 1e-12, False)
    optimistic = HonestyCheck("flat_punch(c)", 0.0, 0.5, "level 4", "mu", 1.0, 1.0 + 2e-10, 1e-10, 1e-12, False)
    inconclusive = HonestyCheck("flat_punch(c)", 0.0, 0.5, "level 4", "mu", 1.0, 1.0 + 2e-10, 1e-10, 5e-10, False)
    assert (honest.status, optimistic.status, inconclusive.status) == ("honest", "optimistic", "inconclusive")
    assert honest.resolved and not inconclusive.resolved and honest.ratio == pytest.approx(0.5)


def test_error_estimate_is_honest_against_level_4_and_the_graded_solver():
    """At nu = -0.5, c = 0.9: |value - reference| <= error against level 4 and against the independent graded
    solver (levels 4 and 3, ~1e-12 relative). Level 2's true error there (2e-15 relative, against level 4) is below
    the rounding floor, which is the estimate ('floor')."""
    grid = Grid(nus=(-0.5,), mus=(), cs=(0.9,), gap_factors=(), power_law_mus=(), limit_nus=(), limit_mu_gammas=())
    pts = [p for p in sweep(grid) if p.function == "flat_punch(c)"]
    checks, skipped = check_honesty(pts, max_graded=1)
    assert not skipped
    kinds = {x.reference_kind for x in checks}
    assert kinds == {"level 4", "graded (levels 4, 3)"}
    for x in checks:
        assert x.status == "honest", x
    assert all(x.at_floor for x in checks)


def test_error_estimate_is_within_tenfold_where_level_4_resolves_it():
    """Next to c_max (nu = -0.5, 1 - c = 1.1 (1 - c_max), mu = 21) level 2's error (4.6e-11 absolute in mu) is
    above the rounding floor (1e-11): the estimate, twice |level 2 - level 3| (9.3e-11), bounds it and lies within 3x
    of it (measured ratio 0.49; with level 4's own error, 1.05e-11 (its floor), the true ratio lies in 0.38 ... 0.61).
    Level 4 is 8.9 times more accurate than that estimate (it was 10 times for the partner one degree lower's 3.7e-10,
    ratio 0.13): bound 5 times."""
    grid = Grid(nus=(-0.5,), mus=(), cs=(), gap_factors=(1.1,), power_law_mus=(), limit_nus=(), limit_mu_gammas=())
    pts = [p for p in sweep(grid) if p.function == "flat_punch(c)"]
    checks, skipped = check_honesty(pts, max_graded=0)
    assert not skipped and checks
    for x in checks:
        assert x.status == "honest", x
    level4 = [x for x in checks if x.reference_kind == "level 4"]
    assert level4 and all(x.reference_error <= 0.2 * x.bound and not x.at_floor for x in level4)
    assert 1.0 / 3.0 <= max(x.ratio for x in level4) <= 1.0


def test_plateau_of_the_new_system_converges_to_the_graded_solver():
    """mu(c = 0.5, nu = 0): exponential convergence over levels 0-3, then agreement with the graded
    solver's level 4 (an independent discretisation, ~1e-12: tests/test_singular_solver.py)."""
    from numeric.core.graded_eigen import solve_mu
    from numeric.core.graded_mesh import LEVELS

    study = plateau_study(0.0, 0.5, finest_level=3, extra=False)
    errors = [r.value_error for r in study.rows]
    # measured 4.7e-11, 1.2e-12, 2.0e-14 against level 3: at least 30x per level until the floor
    assert errors[1] <= errors[0] / 30 and errors[2] <= max(errors[1] / 30, 1e-14)
    for r in study.rows:
        assert r.condition_equilibrated <= r.condition  # equilibration does not hurt (measured 9-13x better)
    graded = solve_mu(0.5, 0.5, LEVELS[4])
    assert study.rows[-1].value == pytest.approx(graded.mu, rel=1e-11)
    assert study.rows[-1].compliance == pytest.approx(graded.compliance, rel=1e-11)


def test_slip_limit_reaches_the_closed_form_largest_stick_radius():
    """mu = inf on the new system against K'(c_max)/K(c_max) = kappa in closed form: 1 - c to 1e-12
    relative at level 3 (the agreement numeric.slip_limit documents; measured 0 at level 3, 1.5e-13 at 2)."""
    study = slip_limit_plateau(0.0, finest_level=3, extra=False)
    gap_max = float(largest_stick_radius_gap(0.5))
    assert study.rows[-1].value_error <= 1e-12 * gap_max
    assert study.rows[0].value_error > study.rows[-1].value_error  # and it converges there


def test_adhesive_system_against_the_exact_solution():
    """c = 1 (graded adhesive mesh) against P0* = atanh(gamma)/gamma (B4) and p0(0) (4.10), exact: level 2
    measured 2e-15 in P*, 8.7e-12 in p0(0); bounds 10x those (the level's convergence, not rounding)."""
    study = adhesive_plateau(0.0, finest_level=2)
    assert study.rows[-1].compliance_error <= 2e-14
    assert study.rows[-1].value_error <= 1e-10
    assert study.rows[0].value_error > study.rows[-1].value_error


def test_double_solve_of_the_level_0_system_against_mpmath():
    """The same double matrix solved at 30 digits: the double root mu differs from the 30-digit root by
    the round-off of the double LU and Newton; the solver assumes it below its floor ERROR_FLOOR (5e-13
    relative; measured 3e-15 here). P* is a sum of ~100 terms of size ~1 with relative rounding eps each:
    1e-14 (measured 2e-16)."""
    study = system_mpmath_check(0.0, 0.5)
    checks = {x.label.split(":")[0]: x for x in study.checks}
    assert checks["mu"].relative <= ERROR_FLOOR
    assert checks["P* of z at the double theta (2.4)"].relative <= 1e-14


@pytest.mark.parametrize("nu", [-0.999, 0.4999])
def test_adhesive_closed_forms_against_mpmath(nu):
    """(B3), (B4), (4.10) as the API evaluates them against 30-digit mpmath quadrature, at both ends of
    gamma: relative 1e-13 (closed forms of a few special functions, and a Gauss rule of (B3) converged to
    rounding; measured <= 2e-15)."""
    study = adhesive_mp_check(nu, xs=(0.0, 0.5, 0.99), graded_level=None)
    for x in study.checks:
        assert x.difference <= 1e-13 * max(1.0, abs(x.mp)), x


def test_quick_report(tmp_path):
    out = tmp_path / "stability.md"
    assert main(["stability", "--quick", "--output", str(out)]) == 0
    text = out.read_text()
    for section in ("## Summary", "## Findings", "## Sweep by function and route", "## Honesty of the error estimate",
                    "## Plateau past convergence", "## mpmath at 30 digits", "## Every call"):
        assert section in text


KNOWN_FINDINGS = {
    # measured by the full study (derivations/stability.md), in code outside this module: the power law's
    # A and C lose digits like mu gamma (NaN or A < 0 at mu gamma >= 1e15); at c = c_max as a double the
    # given-c solve returns error = inf (and mu = inf at nu = 0); the limit mu -> inf at gamma -> 0
    # allocates beyond the memory cap
    "power_law(2)", "flat_punch(c)", "friction_coefficient", "slip_limit", "stick_radius_approach",
}


@pytest.mark.slow  # the whole sweep of derivations/stability.md: ~2 min CPU
def test_full_sweep_has_no_new_kind_of_finding():
    from numeric.studies.stability import FULL_GRID

    points = sweep(FULL_GRID)
    bad = [p for p in points if p.problems]
    for p in bad:
        assert p.function in KNOWN_FINDINGS, p
        if p.function in ("flat_punch(c)", "friction_coefficient"):  # only at c = c_max itself
            assert p.argument == 1.0 - float(largest_stick_radius_gap(p.gamma)), p
        if p.function == "power_law(2)":
            assert p.mu * p.gamma >= 1e15, p
        if p.function in ("slip_limit", "stick_radius_approach"):
            assert p.raised.startswith("MemoryError") and p.gamma < 1e-3, p
