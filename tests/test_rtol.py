"""rtol routes of numeric.flat_punch, the asymptotic hand-over at small c, and the regressions of the
stability sweep (derivations/stability.md): bugs 1-5 of issue 5's stress tests.

References are independent of the route under test: the solver at level 3 (its own error estimate
~1e-12, checked against level 4 in tests/test_flat_punch.py) for asymptotic and table routes, and
closed forms where the route is asymptotic in a limit (c = 4 exp(-1/f0) when c underflows K').
"""

import math
import time
import warnings
from functools import lru_cache

import numpy as np
import pytest

from asymptotics.first_order import compliance_first_order, frictionless_pressure, mu_over_gamma, shear_ratio_first_order
from asymptotics.materials import gamma_from_nu, kappa_from_gamma
from asymptotics.second_order import F2_SMALL_C_FIT as R_SMALL_C
from numeric import NoEigenvalueError, power_law
from numeric.solutions.law import hand_over_ratio, law_bracket as _law_bracket
from numeric import AccuracyWarning, flat_punch, friction_coefficient, stick_radius
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from numeric.solutions.solver import C_ASYMPTOTIC, solve_given_c
from numeric.core.table import table_errors, table_least_mu
from numeric.solutions.sweep import TABLE_MARGIN, table_meets


@lru_cache(maxsize=None)
def _reference(nu: float, **given):
    # level 3: error estimate ~1e-12 (each returned .error is checked below)
    return flat_punch(nu=nu, level=3, **given)


def _ref_c(nu, c):
    return _reference(nu, c=c)


def _ref_mu(nu, mu):
    return _reference(nu, mu=mu)


# ----------------------------------------------------------------------------- arguments
@pytest.mark.parametrize("call", [
    lambda: flat_punch(nu=0.25, c=0.5, level=2, rtol=1e-6),
    lambda: stick_radius(0.2, 0.25, level=2, rtol=1e-6),
    lambda: friction_coefficient(0.5, 0.25, level=2, rtol=1e-6),
    lambda: power_law(2, nu=0.25, c=0.5, level=2, rtol=1e-6),
])
def test_level_and_rtol_together_raise(call):
    with pytest.raises(ValueError, match="rtol"):
        call()


@pytest.mark.parametrize("rtol", [0.0, -1e-3, math.nan, math.inf])
def test_bad_rtol_raises_naming_it(rtol):
    with pytest.raises(ValueError, match="rtol"):
        flat_punch(nu=0.25, c=0.5, rtol=rtol)


# ----------------------------------------------------------------------------- route choice, given c
# (nu, c, rtol, expected route). gamma = 0.0196 (nu = .49), 0.0909 (.45), 1/3 (.25). The first-order bound
# is K2 gamma^2 with K2 = 0.95 (gamma <= 0.2), 1.13 (<= 0.4); second order K4 gamma^4, K4 = 1.15, 1.27:
# nu = .49: 3.6e-4 and 1.7e-7; nu = .45: 7.9e-3 and 7.9e-5; nu = .25: 0.126 and 0.016.
NEAR_C_MAX_025 = 1.0 - 1.5 * float(largest_stick_radius_gap(gamma_from_nu(0.25)))  # 1 - c = 1.5 (1 - c_max)
GIVEN_C_ROUTES = [
    (0.49, 0.5, 1e-2, "asymptotic, first order"),
    (0.49, 0.5, 1e-6, "asymptotic, second order"),
    (0.49, 0.5, 1e-9, "solver level"),
    (0.45, 0.5, 1e-2, "asymptotic, first order"),
    (0.45, 0.5, 1e-4, "table"),  # the table (cost 2e-4 s) before the second-order law (1e-3 s), both meet 1e-4
    (0.45, 0.5, 1e-6, "solver level 0"),
    (0.25, 0.5, 1e-2, "table"),
    (0.25, 0.5, 1e-7, "solver level 0"),  # level 0's error estimate (twice its difference from level 1) meets 1e-7
    (0.25, 0.5, 1e-8, "solver level 1"),  # the first level whose typical accuracy (1e-9) meets 1e-8
    # next to c_max level 0's estimate meets it too (2.5e-9 mu, twice its difference from level 1; its distance from
    # level 4 1.3e-9 mu); ten times its difference from the partner one degree lower, 1.4e-6 mu, had not
    (0.25, NEAR_C_MAX_025, 1e-7, "solver level 0"),
    (0.25, 0.5, 1e-10, "solver level 2"),  # the first level whose typical accuracy (1e-11) meets 1e-10
]


@pytest.mark.parametrize("nu, c, rtol, route", GIVEN_C_ROUTES)
def test_given_c_route_and_accuracy(nu, c, rtol, route):
    s = flat_punch(nu=nu, c=c, rtol=rtol)
    ref = _ref_c(nu, c)
    assert s.route.startswith(route), s.route
    # the promise: within rtol of the value, and within the stated error (plus the reference's own)
    assert abs(s.mu - ref.mu) <= rtol * ref.mu + ref.error, (s.mu, ref.mu)
    assert abs(s.mu - ref.mu) <= s.error + ref.error
    assert abs(s.compliance - ref.compliance) <= s.error + ref.error


GIVEN_MU_ROUTES = [
    (0.49, 0.01, 1e-2, "asymptotic, first order"),
    (0.49, 0.01, 1e-6, "asymptotic, second order"),
    (0.49, 0.01, 1e-4, "table"),  # cheaper than the second-order law, which also meets 1e-4
    (0.45, 0.05, 1e-2, "table"),  # first order: c bound 1.5e-2 > rtol
    (0.45, 0.05, 1e-6, "solver level 0"),
    (0.25, 0.2, 1e-2, "table"),
    (0.25, 0.2, 1e-10, "solver level 2"),
]


@pytest.mark.parametrize("nu, mu, rtol, route", GIVEN_MU_ROUTES)
def test_given_mu_route_and_accuracy(nu, mu, rtol, route):
    s = flat_punch(nu=nu, mu=mu, rtol=rtol)
    ref = _ref_mu(nu, mu)
    assert s.route.startswith(route), s.route
    assert abs(s.c - ref.c) <= rtol * ref.c + ref.error, (s.c, ref.c)
    assert abs(s.c - ref.c) <= s.error + ref.error
    assert abs(s.compliance - ref.compliance) <= s.error + ref.error


def test_default_route_is_unchanged():
    assert flat_punch(nu=0.25, c=0.5).route.startswith("solver level 2")
    assert flat_punch(nu=0.49, c=0.5).route.startswith("solver level 2")  # no rtol: no asymptotic route at c = .5


# ----------------------------------------------------------------------------- sweeps
def test_sweep_routes_meet_rtol():
    # friction_coefficient: table (1e-10 in mu) for rtol >= 1e-10; asymptotic where the law suffices
    ref = _ref_c(0.25, 0.5)
    for rtol in (1e-2, 1e-6, 1e-10, 1e-11):
        mu = friction_coefficient(0.5, 0.25, rtol=rtol)
        assert abs(mu - ref.mu) <= rtol * ref.mu + ref.error, rtol
    ref = _ref_mu(0.25, 0.2)
    for rtol in (1e-2, 1e-6, 1e-9):
        c = stick_radius(0.2, 0.25, rtol=rtol)
        assert abs(c - ref.c) <= rtol * ref.c + ref.error, rtol
    ref = _ref_c(0.49, 0.5)
    mu = friction_coefficient(np.array([0.5, 0.5]), np.array([0.49, 0.49]), rtol=1e-2)
    assert np.all(np.abs(mu - ref.mu) <= 1e-2 * ref.mu)


def test_table_bound_is_the_recorded_error_with_its_margin():
    # the sweeps trust the table to TABLE_MARGIN times the worst error its build measured at held-out points
    # (tests/test_tables.py checks the record itself against fresh solves)
    errors = table_errors()
    bound_mu, bound_c = TABLE_MARGIN * errors["mu"], TABLE_MARGIN * max(errors["c"], errors["gap"])
    assert table_meets("mu", np.array([0.2]), bound_mu)[0] and not table_meets("mu", np.array([0.2]), 0.9 * bound_mu)[0]
    assert table_meets("c", np.array([0.5]), bound_c)[0] and not table_meets("c", np.array([0.5]), 0.9 * bound_c)[0]


# ----------------------------------------------------------------------------- unreachable rtol
def test_unreachable_rtol_warns_and_returns_the_best():
    # c = 1e-4: no level reaches 1e-15 relative (the error floor is 1e-14, ERROR_FLOOR): the finest is returned
    with pytest.warns(AccuracyWarning, match="not met"):
        s = flat_punch(nu=0.25, c=1e-4, rtol=1e-15)
    assert s.route.startswith("solver level 4")
    # below the solver's reach only the asymptotic law is left
    with pytest.warns(AccuracyWarning, match="not met"):
        s = flat_punch(nu=0.25, c=1e-7, rtol=1e-6)
    assert s.route.startswith("asymptotic, second order")


def test_no_warning_when_rtol_is_met():
    with warnings.catch_warnings():
        warnings.simplefilter("error", AccuracyWarning)
        flat_punch(nu=0.25, c=0.5, rtol=1e-6)
        flat_punch(nu=0.25, c=1e-7, rtol=0.05)  # asymptotic bound 0.017 mu, P* 3.7e-4


# ----------------------------------------------------------------------------- the hand-over at c = 1e-5
# Below c = C_MIN = 1e-5 (the table's least stick radius and the solver's reach) the second-order law is matched to the
# table there (``numeric.solutions.law.hand_over_ratio``): mu(c) is continuous and increasing across, where the law
# alone was 2.1e-3 (nu = 0.3) ... 0.14 (nu = -0.999) off and c(mu) jumped (c = 2.5e-5 from the law at mu just below
# mu(1e-5), nu = -0.5).
@pytest.mark.parametrize("gamma", [0.2, 0.5, 0.75])
def test_handover_given_c_is_continuous(gamma):
    # the two sides differ by the table's error at C_MIN (1e-10-ish in mu, ``table_errors``) and the law's change over
    # 1e-12 relative in c (1e-13); 1e-9 relative leaves room for the solver's own error there (<= 1e-11)
    solver = flat_punch(gamma=gamma, c=C_ASYMPTOTIC)
    law = flat_punch(gamma=gamma, c=C_ASYMPTOTIC * (1 - 1e-12))
    assert solver.route.startswith("solver level 2") and law.route.startswith("asymptotic, second order")
    assert "matched" in law.route
    assert abs(solver.mu - law.mu) <= 1e-9 * solver.mu
    assert abs(solver.compliance - law.compliance) <= law.error + solver.error


@pytest.mark.parametrize("gamma", [0.2, 0.75])
def test_handover_given_mu_is_continuous_and_within_the_stated_range(gamma):
    # the hand-over is at the table's mu(c = C_MIN): just above it the solver, just below the matched law; 2e-9 in mu
    # moves c by 2e-9 d log c/d log mu ~ 2.6e-8 relative at c = 1e-5 (d log mu/d log c ~ 1/log(4/c) = 0.077), the
    # table's error at C_MIN (~1e-10 in mu) by 1.3e-9: tested at 1e-7
    mu = table_least_mu(gamma)
    solver = flat_punch(gamma=gamma, mu=mu * (1 + 1e-9))
    law = flat_punch(gamma=gamma, mu=mu * (1 - 1e-9))
    assert solver.route.startswith("solver level 2") and law.route.startswith("asymptotic")
    assert solver.c == pytest.approx(C_ASYMPTOTIC, rel=1e-6)  # 1e-9 in mu moves c by ~1e-8 relative
    assert law.c < solver.c and law.c == pytest.approx(solver.c, rel=1e-7)
    bracket = _law_bracket(mu * (1 - 1e-9), gamma, 2, hand_over_ratio(gamma))
    assert bracket.lo - solver.error <= solver.c <= bracket.hi + solver.error
    assert abs(solver.compliance - law.compliance) <= law.error + solver.error


@pytest.mark.parametrize("nu", [-0.999, -0.5, 0.0, 0.45])
def test_stick_radius_increases_with_mu_across_the_handover(nu):
    m = friction_coefficient(C_ASYMPTOTIC, nu)
    mus = m * np.array([0.5, 0.9, 0.999, 1 - 1e-6, 1 - 1e-9, 1.0, 1 + 1e-9, 1 + 1e-6, 1.001])
    vector = stick_radius(mus, nu)
    scalar = np.array([flat_punch(nu=nu, mu=v).c for v in mus])
    assert np.all(np.diff(vector) > 0.0) and np.all(np.diff(scalar) > 0.0)
    # the vector reads the table where the scalar solves (mu within 1e-10): c within ~1e-10 d log c/d log mu ~ 1e-8
    np.testing.assert_allclose(vector, scalar, rtol=5e-8, atol=0.0)


@pytest.mark.parametrize("nu, measured", [(-0.999, 8.8e-4), (0.3, 5.5e-5)])
def test_matched_law_against_the_solver_below_its_reach(nu, measured):
    # the solver run at c = 1e-6, below the reach the routes give it (its levels 1 and 2 agree to 1.3e-9 there): the
    # matched law is within 1.5x the measured (the unmatched law 0.12 and 2.1e-3 off), and within its stated error
    gamma = float(gamma_from_nu(nu))
    reference = solve_given_c(nu, 1e-6, gamma, 2)
    law = flat_punch(nu=nu, c=1e-6)
    assert "matched" in law.route
    assert abs(law.mu / reference.mu - 1.0) <= 1.5 * measured
    assert abs(law.mu - reference.mu) <= law.error


# ----------------------------------------------------------------------------- asymptotic fields
def test_asymptotic_fields_are_first_order_and_close_to_the_solver():
    s = flat_punch(nu=0.45, c=0.5, rtol=1e-2)
    g = s.gamma
    x = np.array([0.0, 0.2, 0.45, 0.6, 0.9])
    assert np.array_equal(s.pressure(x), frictionless_pressure(x))
    assert np.allclose(s.shear(x), s.mu * frictionless_pressure(x) * shear_ratio_first_order(x, 0.5), rtol=1e-15)
    with pytest.raises(NotImplementedError, match="slip"):
        s.slip(0.7)
    ref = _ref_c(0.45, 0.5)
    # O(gamma^2) relative (derivations/section_2_3.md: max |q/(mu p) - (1 - psi)| = 0.12 gamma^2 at c = .5);
    # gamma^2 = 8.3e-3, checked at 1 gamma^2
    assert np.all(np.abs(s.pressure(x) / ref.pressure(x) - 1) <= g**2)
    # q/mu: the shear ratio (2.31) (0.12 gamma^2 at c = .5) times p (measured 0.63 gamma^2 off at x = .6);
    # checked at 1 gamma^2 p. q itself also carries the law's error of mu, which the route's error covers
    assert np.all(np.abs(s.shear(x[1:]) / s.mu - ref.shear(x[1:]) / ref.mu) <= g**2 * ref.pressure(x[1:]))
    assert abs(s.mu - ref.mu) <= s.error


# ----------------------------------------------------------------------------- regressions 1-5
@pytest.mark.parametrize("nu, mu", [(-0.99, 1e-4), (-0.5, 1e-4), (0.0, 1e-4), (0.25, 1e-4), (0.45, 1e-4),
                                    (-0.99, 0.01), (-0.5, 0.01), (0.0, 0.01)])
def test_bug1_2_tiny_mu_returns_the_asymptotic_law_fast(nu, mu):
    # was: scipy ValueError from brentq (bug 1), or 67 s then SolverError (bug 2, nu = 0, mu = .01)
    start = time.perf_counter()
    s = flat_punch(nu=nu, mu=mu)
    assert time.perf_counter() - start < 1.0  # measured 3-15 ms
    assert s.route.startswith("asymptotic, second order") and math.isfinite(s.error)
    g = gamma_from_nu(nu)
    # independent of the inversion: for c < 1e-150 K'(c) = log(4/c) exactly in doubles and
    # atanh(c)/c = 1, so mu/gamma = (1 + R g^2)/log(4/c) gives c = 4 exp(-g (1 + R g^2)/mu)
    if s.c < 1e-150:
        r = R_SMALL_C[0] - R_SMALL_C[1] / math.log(4 / s.c) if s.c > 0 else R_SMALL_C[0]
        assert s.c == pytest.approx(4 * math.exp(-g * (1 + r * g**2) / mu), rel=1e-10, abs=1e-320)
    # P* - 1 = gamma^2 P2(c) with P2 -> rho f0 as c -> 0, rho from (2.34) as implemented independently
    # (asymptotics.first_order.compliance_first_order, tanh-sinh) at c = 1e-300, and f0 = mu/(gamma (1 + R gamma^2))
    c_rho = max(s.c, 1e-300)
    rho = (compliance_first_order(c_rho, 0.5) - 1.0) / (0.25 * float(mu_over_gamma(c_rho)))  # (2.34) ~ gamma^2
    r = R_SMALL_C[0] - R_SMALL_C[1] / math.log(4 / c_rho)
    assert abs(s.compliance - 1.0 - g * rho * mu / (1 + r * g**2)) <= s.error
    assert s.shear(0.5) == pytest.approx(mu * float(frictionless_pressure(0.5)), rel=1e-12) or s.c > 0.5


def _gap(gamma):
    return math.exp(-math.pi / float(kappa_from_gamma(gamma)))


def test_bug3_5_large_mu_at_large_gamma_is_solved_quickly():
    # was: SolverError naming c = 0.99999999895 (bug 3); RuntimeWarning overflow and 30-60 s (bug 5); then a
    # bracket beyond mu(c_top). mu -> inf is the regular limit theta -> pi/2 of the eigenvalue relation, so
    # every mu is solved: c rises toward c_max(gamma) (asymptotics.largest_stick_radius), never reaching it
    start = time.perf_counter()
    for gamma, mu in ((0.749, 10.0), (0.749, 1e4), (2 / 3, 1000.0)):
        s = flat_punch(gamma=gamma, mu=mu)
        assert s.route.startswith("solver level 2") and s.mu == mu
        gap_max = float(largest_stick_radius_gap(gamma))
        assert 0.0 < (1.0 - s.c) - gap_max
        assert abs(s.c - flat_punch(gamma=gamma, mu=mu, level=3).c) <= s.error
    assert time.perf_counter() - start < 15.0  # measured 1.5 s for the three


@pytest.mark.parametrize("gamma, c", [(0.749, 0.96), (0.749, 0.99), (0.749, 1 - 1e-6), (2 / 3, 0.985),
                                      (2 / 3, 0.983), (0.5, 0.9995)])
def test_bug4_above_c_max_raises_no_eigenvalue_error_naming_c_max(gamma, c):
    # c_max = 0.9511, 0.9827778, 0.9989970 (asymptotics.largest_stick_radius): refused at once
    start = time.perf_counter()
    with pytest.raises(NoEigenvalueError, match="c_max"):
        flat_punch(gamma=gamma, c=c)
    assert time.perf_counter() - start < 10.0


def test_power_law_passes_rtol_through_but_not_to_the_law():
    # the law's first-order stresses would give C off by 4.6e-3 at nu = 0.4 (far above the law's error
    # in mu), so power_law takes the solver even where flat_punch alone would take the law
    assert flat_punch(nu=0.45, c=0.5, rtol=1e-2).route.startswith("asymptotic")
    h = power_law(2, nu=0.45, c=0.5, rtol=1e-2)
    assert h.flat.route.startswith("solver level 0")
    reference = power_law(2, nu=0.45, c=0.5, level=3)
    # the requested rtol is the contract (level 3 is ~1e-12, far inside it); the law route missed it for C at nu = 0.45
    assert abs(h.C - reference.C) <= 1e-2 * abs(reference.C) and abs(h.A - reference.A) <= 1e-2 * reference.A
    fine = power_law(2, nu=0.25, c=0.5, rtol=1e-11).flat  # rtol reaches the solver's levels and is met there
    assert fine.route.startswith("solver level") and fine.error <= 1e-11 * fine.mu


def test_below_the_handover_vector_and_scalar_agree_to_the_bit():
    # below mu(1e-5) both the vectorised stick_radius and flat_punch use the law matched at c = 1e-5, its ratio formed
    # the same way (one table read per point): the same c to the last bit (a fuzz campaign found 1e-13 relative where
    # the vector read the table for all points at once; c's sensitivity to mu is ~log(1/c) at c ~ 1e-29 ... 1e-293)
    points = [(0.00578371717279551, 0.2194592072141267), (0.0016316614813357663, -0.5938427629850858),
              (0.0002487196301686297, 0.4007771063412401), (0.03, 0.0)]
    for mu, nu in points:
        assert stick_radius(np.array([mu]), nu)[0] == flat_punch(nu=nu, mu=mu).c
