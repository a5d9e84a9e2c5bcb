"""Property-based stress tests of the solver ([S75] §2) and the smoke test of numeric.studies.stability.

Hypothesis draws (nu, mu) or (nu, c) from the admissible domain where the solver is
documented to work (c in [0.05, 0.95], nu in [-0.5, 0.45]: gamma from 2/3 to 0.09) and checks
the physics: monotonicity of c in mu and nu, the constraints (2.8)-(2.9), continuity at
x = c, the stick radius shared by the flat punch and power-law indenters (§3.2), round
trips, and 1 <= P* <= atanh(gamma)/gamma (B4) increasing in mu. Example counts are small
(the profile of tests/conftest.py supplies derandomisation and deadline); the
``slow``-marked twins run more examples. Every tolerance is the solution's own error
estimate (its ``error``, or the difference of two levels for pointwise values), or says why not.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asymptotics.materials import gamma_from_nu
from numeric import flat_punch, friction_coefficient, power_law, stick_radius
from numeric.core import table_data
from numeric.app.cli import main
from numeric.studies.stability import HonestyCheck, SweepPoint, sweep

NU = st.floats(-0.5, 0.45)
C = st.floats(0.05, 0.95)
# strictly inside the table's c range: at c = C_MAX exactly the inversion's end test can fail by
# rounding and stick_radius falls back to the solver (measured: c = 0.95 returns 0.95 + 4.0e-12,
# within the level-2 solver's error but not the table's)
C_TABLE = st.floats(table_data.C_MIN * (1 + 1e-9), table_data.C_MAX * (1 - 1e-9))
NU_TABLE = st.floats(-0.5, 0.5, exclude_max=True)
FAST = settings(max_examples=4)
SLOW = settings(max_examples=40)


# ----------------------------------------------------------------------------- monotonicity
def _c_increases_in_mu(nu: float, mu: float, factor: float) -> None:
    lo, hi = stick_radius(mu, nu), stick_radius(mu * factor, nu)
    # the table's c carries <= 5e-10 relative error (MU_RELATIVE_ERROR 5.2e-11 in mu at worst, d log mu/d log c
    # > 0.1 for c >= 1e-3; ~1e-11 in the interior): a strict increase is required beyond 1e-11
    assert hi > lo * (1 + 1e-11), (nu, mu, lo, hi)


@FAST
@given(nu=st.floats(-0.5, 0.2), mu=st.floats(0.15, 0.3), factor=st.floats(1.01, 1.5))
def test_stick_radius_increases_with_mu(nu, mu, factor):
    """§2.1: more friction, larger stick zone (here inside the table's domain; the slow twin
    also reaches the solver route, c > 0.95 or c < 1e-3)."""
    _c_increases_in_mu(nu, mu, factor)


@pytest.mark.slow
@SLOW
@given(nu=st.floats(-0.5, 0.49), c=st.floats(1e-3, 0.97), factor=st.floats(1.001, 3.0))
def test_stick_radius_increases_with_mu_many(nu, c, factor):
    # mu drawn through c, so that c(mu) stays above the solver's documented floor (c ~ 1e-5;
    # nu = 0, mu = 0.0625 gives c ~ 4e-8 and SolverError); mu * factor may reach the solver
    # route (c > 0.95) or the bracketed one (c within 1e-9 of 1)
    _c_increases_in_mu(nu, float(friction_coefficient(c, nu)), factor)


def _c_increases_in_nu(nu: float, dnu: float, c: float) -> None:
    # Direction: at fixed c the friction needed grows with gamma, mu = gamma f0(c) (1 + O(gamma^2))
    # with f2 > 0 ((2.28) and tests/test_flat_punch.py), and gamma = (1-2nu)/(2-2nu) decreases
    # with nu (2.2); so at fixed mu the stick radius increases with nu. Checked in that form:
    # mu_c(c) decreases in nu, beyond the table's relative error 7e-12.
    mu_lo_nu, mu_hi_nu = friction_coefficient(c, nu), friction_coefficient(c, min(nu + dnu, 0.4999))
    assert mu_hi_nu < mu_lo_nu * (1 - 1e-11), (nu, dnu, c)
    # and directly in c at the first mu
    assert stick_radius(mu_lo_nu, min(nu + dnu, 0.4999)) > c


@FAST
@given(nu=st.floats(-0.5, 0.45), dnu=st.floats(0.01, 0.1), c=st.floats(0.01, 0.6))
def test_stick_radius_increases_with_nu(nu, dnu, c):
    _c_increases_in_nu(nu, dnu, c)


@pytest.mark.slow
@SLOW
@given(nu=st.floats(-0.5, 0.49), dnu=st.floats(0.001, 0.5), c=st.floats(0.002, 0.94))
def test_stick_radius_increases_with_nu_many(nu, dnu, c):
    _c_increases_in_nu(nu, dnu, c)


def test_nu_direction_against_the_solver():
    """The same direction from the solver alone (no table): c(mu = 0.3) at nu = 0, 0.25 (level 1)."""
    a, b = flat_punch(nu=0.0, mu=0.3, level=1), flat_punch(nu=0.25, mu=0.3, level=1)
    assert b.c - a.c > a.error + b.error  # 0.826 vs 0.503, errors ~1e-8


# ----------------------------------------------------------------------------- (2.8)-(2.9), continuity
def _constraints_and_continuity(nu: float, c: float) -> None:
    coarse, fine = flat_punch(nu=nu, c=c, level=1), flat_punch(nu=nu, c=c, level=2)
    mu = fine.mu
    # pointwise error of the level-2 field: its difference from level 1 (levels converge
    # exponentially, so the coarser one's distance bounds the finer one's error)
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
    # continuity at x = c: the discrete p and q jump at c by the unresolved singular term
    # (c - x)^(1/2 - alpha), tan(pi alpha) = mu gamma, next to c. The jump does not shrink
    # steadily with the level (measured: nu = 0, c = 0.0039: 5.8e-7 at level 1, 2.0e-6 at level 3;
    # nu = 0.47, c = 0.25: 9.2e-9, 1.1e-8), so no level-to-level rate is asserted. Tolerance:
    # 1e-3 p(c), the accuracy the solver itself accepts for mu p - q at the node next to c
    # (numeric.core.graded_eigen._admissible); measured worst 5e-5 p(c) at nu = -0.5, c = 0.85 (alpha = 0.23)
    below = np.nextafter(c, 0.0)
    for f in (fine.pressure, fine.shear):
        jump = abs(float(f(below)) - float(f(c)))
        assert jump <= 1e-3 * float(fine.pressure(c)), (nu, c, jump)


@FAST
@given(nu=NU, c=C)
def test_constraints_and_continuity(nu, c):
    """(2.8): mu p - q >= 0 on (0, c); (2.9): q = mu p, u <= 0 on (c, 1); p, q continuous at c."""
    _constraints_and_continuity(nu, c)


@pytest.mark.slow
@settings(max_examples=20)
@given(nu=st.floats(-0.6, 0.49), c=st.floats(1e-3, 0.95))
def test_constraints_and_continuity_many(nu, c):
    _constraints_and_continuity(nu, c)


# ----------------------------------------------------------------------------- power law, round trips, P*
@settings(max_examples=2)
@given(nu=NU, mu=st.floats(0.1, 0.6))
def test_power_law_has_the_flat_punch_stick_radius(nu, mu):
    """§3.2: c depends on mu and nu only, not on the indenter's shape n (same level, same c)."""
    flat = flat_punch(nu=nu, mu=mu, level=1)
    for n in (1, 2, 3):
        h = power_law(n, nu=nu, mu=mu, level=1)
        assert h.c == flat.c and h.error == flat.error
        assert math.isfinite(h.A) and h.A > 0 and math.isfinite(h.C)
        assert h.compliance == pytest.approx(n * flat.compliance / (n + 1), rel=1e-15)  # (3.17), exact arithmetic


def _round_trip(nu: float, c: float) -> None:
    back = stick_radius(friction_coefficient(c, nu), nu)
    # both directions read the same Chebyshev table; the inversion stops at |log mu residual|
    # < 1e-15 and d log mu / d log c > 0.1 on the table's domain, so c returns to ~1e-14
    # relative; 1e-12 leaves room for the rounding of the series (~1e-15 in log mu)
    assert back == pytest.approx(c, rel=1e-12)


@settings(max_examples=25)
@given(nu=NU_TABLE, c=C_TABLE)
def test_round_trip_table(nu, c):
    _round_trip(nu, c)


@pytest.mark.slow
@settings(max_examples=300)
@given(nu=NU_TABLE, c=C_TABLE)
def test_round_trip_table_many(nu, c):
    _round_trip(nu, c)


def test_round_trip_solver():
    """Outside the table (c = 0.97) both directions go through the solver: within its error."""
    mu = friction_coefficient(0.97, 0.0)
    s = flat_punch(nu=0.0, mu=mu)
    assert abs(s.c - 0.97) <= s.error


def _compliance_bounds(nu: float, c: float, dc: float) -> None:
    a, b = flat_punch(nu=nu, c=c, level=1), flat_punch(nu=nu, c=min(c + dc, 0.95), level=1)
    gamma = float(gamma_from_nu(nu))
    top = math.atanh(gamma) / gamma  # (B4): the fully adhesive compliance bounds P* from above
    for s in (a, b):
        assert 1.0 - s.error < s.compliance < top + s.error  # frictionless P* = 1 from below
    assert b.mu > a.mu  # larger c needs larger mu
    assert b.compliance - a.compliance > -(a.error + b.error)  # P* increases with mu (and c)


@FAST
@given(nu=NU, c=C, dc=st.floats(0.005, 0.3))
def test_compliance_between_limits_and_increasing(nu, c, dc):
    _compliance_bounds(nu, c, dc)


@pytest.mark.slow
@SLOW
@given(nu=st.floats(-0.6, 0.49), c=st.floats(0.01, 0.94), dc=st.floats(1e-3, 0.3))
def test_compliance_between_limits_and_increasing_many(nu, c, dc):
    _compliance_bounds(nu, c, dc)


# ----------------------------------------------------------------------------- the stability module
def test_sweep_records_values_and_exceptions():
    pts = sweep((0.25,), (0.3,), (0.5, 1.0), power_law_nus=(), power_law_mus=())
    assert all(isinstance(p, SweepPoint) for p in pts) and len(pts) == 6
    by = {(p.function, p.argument): p for p in pts}
    s = by[("flat_punch(c)", 0.5)]
    assert s.admissible and not s.raised and s.route.startswith("solver level 2")
    assert by[("friction_coefficient", 0.5)].mu == pytest.approx(s.mu, abs=s.error)
    assert by[("flat_punch(c)", 1.0)].region == "c = 1"


def test_honesty_check_flags_a_violation():
    bad = HonestyCheck("flat_punch(c)", 0.0, 0.5, "mu", 1.0, 1.0 + 2e-10, 1e-10, 1e-15)
    good = HonestyCheck("flat_punch(c)", 0.0, 0.5, "mu", 1.0, 1.0 + 5e-11, 1e-10, 1e-15)
    assert not bad.honest and good.honest


def test_quick_report(tmp_path):
    out = tmp_path / "stability.md"
    assert main(["stability", "--quick", "--output", str(out)]) == 0
    text = out.read_text()
    assert "## Sweep summary" in text and "## Plateau past convergence" in text
    assert "Calls returning a non-finite or out-of-range value: 0." in text
    assert ", 0 with |value - reference| > error." in text


@pytest.mark.slow  # the whole sweep of derivations/stability.md: ~30 s CPU
def test_full_sweep_has_no_silent_failures():
    from numeric.studies.stability import FULL_GRID

    nus, mus, cs = FULL_GRID
    points = sweep(nus, mus, cs, power_law_nus=(-0.99, 0.0, 0.4999), power_law_mus=(1e-4, 0.1, 1.0, 1e4))
    assert all(p.admissible for p in points if not p.raised)  # finite, in range
    # the only failure allowed: a stick radius above the largest one, said as such
    assert all(p.raised.startswith("NoEigenvalueError") and "c_max" in p.raised for p in points if p.raised)
