"""The extremes of the stability study: mu gamma up to 1e300, c at c_max to rounding, tiny gamma, small c.

Independent references: the slip limit (theta = pi/2 exactly, no mu in the problem) with the approach
A/(mu gamma) for c; the closed form of 1 - c_max (``asymptotics.largest_stick_radius``); the adhesive
closed form (App. B); solves at level 4 for the error estimate at small c.
"""

import math
import resource

import numpy as np
import pytest

from asymptotics.adhesive import compliance_adhesive
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu
from numeric import (NoEigenvalueError, flat_punch, largest_stick_radius, power_law, slip_limit,
                     stick_radius_approach)
from numeric.core.charts import RESOLUTIONS
from numeric.core.eigenvalue import solve_given_theta
from numeric.core.fields import SingularField
from numeric.solutions.power_law import displacement_constant, indentation_constant
from numeric.solutions.solver import GAP_ADHESIVE, rounding_floor, solve_given_c


# ---------------------------------------------------------------- 1. large mu gamma
@pytest.mark.parametrize("nu", [-0.5, 0.0, 0.3])
def test_power_law_constants_settle_to_the_slip_limit(nu):
    # A, C at mu gamma = 1e8 ... 1e300 against the slip limit's (theta = pi/2 exactly: no mu gamma to round)
    # plus the slope in eps = 1/(mu gamma) from mu gamma = 1e4 (O(eps^2) at 1e8 and above: < 1e-15). Before the
    # fix A drifted like 1e-16 mu gamma (1e-5 at 1e10, nan at 1e16); measured after: |A - ref|, |C - ref| below
    # 2e-13 at nu = -0.5, 0 and 1e-13 at 0.3, so 1e-11 (the solver's accuracy, level 2) is the bound.
    g = float(gamma_from_nu(nu))
    limit = slip_limit(nu)
    a_lim, c_lim = indentation_constant(limit, 2), displacement_constant(limit, 2)
    near = power_law(2, nu=nu, mu=1e4 / g)
    slope_a, slope_c = (near.A - a_lim) * 1e4, (near.C - c_lim) * 1e4
    slope_p = (near.flat.compliance - limit.compliance) * 1e4
    for mu_gamma in (1e8, 1e16, 1e300):
        s = power_law(2, nu=nu, mu=mu_gamma / g)
        eps = 1.0 / mu_gamma
        assert abs(s.A - (a_lim + slope_a * eps)) < 1e-11
        assert abs(s.C - (c_lim + slope_c * eps)) < 1e-11
        # c against the closed form c_max and the approach A/(mu gamma); P* against the limit's
        approach = stick_radius_approach(nu) * eps
        assert abs(s.flat.gap - (float(largest_stick_radius_gap(g)) + approach)) < 1e-11 * max(s.flat.gap, 1e-3)
        assert abs(s.flat.compliance - (limit.compliance + slope_p * eps)) <= max(s.error, limit.error)
        assert s.error < 1e-10


def test_fields_at_the_stick_slip_boundary_are_finite_for_huge_mu():
    # at mu gamma >= 1e16 theta rounds to pi/2: h_beta(0) = -inf made p(c), q(c) nan; the value at x = c is the
    # one at the nearest double (the s^beta layer is thinner than an ulp), the limit over the doubles
    s = flat_punch(nu=0.0, mu=1e300)
    x = np.array([np.nextafter(s.c, 0.0), s.c, np.nextafter(s.c, 2.0)])
    p, q = s.pressure(x), s.shear(x)
    assert np.all(np.isfinite(p)) and np.all(np.isfinite(q))
    assert q[1] == pytest.approx(q[2], rel=1e-6)
    # the slip side: p = q/mu (~1e-298), q = mu p as the product to rounding
    assert p[1] == p[2] and np.allclose(1e300 * p[1:], q[1:], rtol=4e-16, atol=0.0)


@pytest.mark.parametrize("nu", [0.0, -0.5])
def test_annulus_pressure_keeps_its_relative_accuracy_at_huge_mu(nu):
    # p = R cos(theta) on the slip annulus, cos(theta) = 1/hypot(1, mu gamma) from mu (``SingularField.with_friction``):
    # from theta = atan(mu gamma) it carried theta's rounding over pi/2 - theta (relative 1e-16 mu gamma: 1e-6 at
    # mu = 1e10; from mu gamma = 1e16 on p was 0 while q was not). Against the slip limit (mu = inf, q = R/gamma on the
    # annulus), mu p agrees with its q to 1e-9 at mu = 1e10 (the approach c_max - c ~ A/(mu gamma) and level 2's error
    # next to c_max: measured 3.7e-10) and from mu = 1e17 on (1/(mu gamma) ~ 1e-17) to the rounding of two solves of
    # the same limit problem on two paths: kappa eps with kappa ~ 1e3 ... 1e4 (equilibrated, next to c_max), 1e-12
    # (measured 0 ... 1 ulp, 7.8e-15 with numpy's SIMD limited to x86-64-v2)
    limit = slip_limit(nu)
    x = np.array([0.5 * (1.0 + limit.c), 1.0 - 0.3 * (1.0 - limit.c), 1.0 - 1e-3 * (1.0 - limit.c)])
    for mu, rtol in ((1e10, 1e-9), (1e17, 1e-12), (1e300, 1e-12)):
        s = flat_punch(nu=nu, mu=mu)
        np.testing.assert_allclose(mu * s.pressure(x), limit.shear(x), rtol=rtol, atol=0.0)
        np.testing.assert_allclose(s.shear(x), mu * s.pressure(x), rtol=4e-16, atol=0.0)


# ---------------------------------------------------------------- 2. c at c_max
@pytest.mark.parametrize("nu", [-0.9, -0.5, 0.0, 0.3])
def test_c_max_to_rounding_is_the_slip_limit(nu):
    c_max = float(largest_stick_radius(nu))
    s = flat_punch(nu=nu, c=c_max)
    assert s.mu == math.inf and "c_max to rounding" in s.route and "limit mu -> inf" in s.route
    assert np.isfinite(s.error) and s.error < 1e-10
    assert abs(s.gap - float(largest_stick_radius_gap(float(gamma_from_nu(nu))))) < 1e-12
    with pytest.raises(NoEigenvalueError):  # beyond c_max by more than rounding
        flat_punch(nu=nu, c=c_max + 64 * math.ulp(c_max))


@pytest.mark.parametrize("nu, k", [(0.0, 6), (0.0, 64), (-0.9, 16), (0.3, 8)])
def test_just_below_c_max_mu_is_finite_and_its_error_honest(nu, k):
    # k ulp below c_max: mu gamma = A/excess (the approach, A from the limit problem, excess from the closed
    # form); its error from A's second order (~1e-6) and O(eps) is far below the solver's here, which comes from
    # the shift of the level's c_max (measured ratio |mu - approach| / error 0.006 ... 0.6)
    g = float(gamma_from_nu(nu))
    c_max = float(largest_stick_radius(nu))
    c = c_max - k * math.ulp(c_max)
    s = flat_punch(nu=nu, c=c)
    expected = stick_radius_approach(nu) / (((1.0 - c) - float(largest_stick_radius_gap(g))) * g)
    assert math.isfinite(s.mu) and 0.0 < s.error < s.mu
    assert abs(s.mu - expected) <= s.error


# ---------------------------------------------------------------- 3. tiny gamma
@pytest.mark.parametrize("nu", [0.4999, 0.5])
def test_slip_limit_at_tiny_gamma_is_adhesive_without_gigabytes(nu):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    s = slip_limit(nu)
    g = float(gamma_from_nu(nu))
    assert s.mu == math.inf and s.c == 1.0
    assert s.compliance == (float(compliance_adhesive(g)) if g > 0 else 1.0)
    assert "adhesive" in s.route or "closed form" in s.route
    with pytest.raises(ValueError, match="gamma"):
        stick_radius_approach(nu)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before < 200_000  # kB: no 1.3 GiB layout


def test_nearly_adhesive_slip_limit_error_covers_the_solved_limit():
    # nu = 0.415: 1 - c_max = 1.8e-14 < GAP_ADHESIVE; the limit problem solved anyway (a layout down to 1e-14
    # is still small) gives P* within the stated error of the adhesive P*, and the closed-form c_max
    nu = 0.415
    g = float(gamma_from_nu(nu))
    gap = float(largest_stick_radius_gap(g))
    assert gap < GAP_ADHESIVE
    s = slip_limit(nu)
    solved = SingularField(solve_given_theta(0.5 * math.pi, g, math.log1p(-gap) - math.log(gap), RESOLUTIONS[2]))
    assert abs(solved.compliance - s.compliance) <= s.error
    assert abs(solved.gap - gap) < 1e-3 * gap
    assert s.error < 1e-11


# ---------------------------------------------------------------- 4. error floor at small c
@pytest.mark.parametrize("nu, c", [(0.0, 1e-5), (0.3, 1e-4), (0.45, 3e-5)])
def test_small_c_is_at_the_flat_rounding_floor(nu, c):
    # Round-off once grew like 1/c here (levels 2 and 4 8.9e-12 apart at nu = 0, c = 1e-5, and a floor 2e-3/c times
    # ERROR_FLOOR to cover it); with (2.2a) differenced against one point and the solves refined it does not
    # (``numeric.core.operators.collocation_system``): over nu in {-0.5, 0, 0.3, 0.45}, c from 1e-5 to 3e-3, levels 2,
    # 3, 4 agree within 1.5e-14 in mu and P* (measured). So the estimate is the flat floor ERROR_FLOOR max(mu, P*), and
    # the levels lie within a tenth of it (5e-14: 3x the measured scatter, room for other BLAS/SIMD summation orders;
    # 8.9e-12 before would fail)
    g = float(gamma_from_nu(nu))
    s2, s4 = solve_given_c(nu, c, g, 2), solve_given_c(nu, c, g, 4)
    assert s2.error == rounding_floor(max(s2.mu, s2.compliance))
    assert abs(s2.mu - s4.mu) <= 0.1 * s2.error and abs(s2.compliance - s4.compliance) <= 0.1 * s2.error


@pytest.mark.slow
@pytest.mark.parametrize("nu", [-0.5, 0.0, 0.3, 0.45])
def test_error_covers_the_round_off_at_small_c_everywhere(nu):
    # at small c every level sits at the solver's round-off, level 4 included: the difference of two levels is
    # bounded by the sum of their estimates, not by the coarser one's alone (at nu = -1/2, c = 1e-3 level 2 is 4.5e-13
    # from level 4, its own estimate 4.1e-13 and level 4's 4.4e-13: the reference is no better than the level)
    g = float(gamma_from_nu(nu))
    for c in (1e-5, 3e-5, 1e-4, 3e-4, 1e-3):
        s4 = solve_given_c(nu, c, g, 4)
        for level in (2, 3):
            s = solve_given_c(nu, c, g, level)
            assert abs(s.mu - s4.mu) <= s.error + s4.error


@pytest.mark.parametrize("ratio", [0.5, 1.0, 3.0])
def test_vanishing_gamma_takes_the_law_and_agrees_with_the_solver(ratio):
    # below gamma = 1e-100 the solver's kernels lose gamma^2 to underflow (it returned c = 6.5e-49 for 0.485 at
    # gamma = 1e-300, mu/gamma = 1/2, and overflowed at 1e-200); the law, exact to O(gamma^2), answers there. The
    # solver at gamma = 1e-30 (its level-2 error ~1e-12, an independent discretisation) gives the same c.
    solver = flat_punch(gamma=1e-30, mu=ratio * 1e-30)
    assert solver.route.startswith("solver")
    for g in (1e-120, 1e-300, 1e-310):
        law = flat_punch(gamma=g, mu=ratio * g)
        assert law.route.startswith("asymptotic") and "exact to rounding" in law.route
        assert law.c == pytest.approx(solver.c, rel=0, abs=solver.error + 1e-15)
        back = flat_punch(gamma=g, c=law.c)
        assert back.mu == pytest.approx(ratio * g, rel=1e-14)  # the law inverted both ways: rounding of f0 (~10 ops)


@pytest.mark.parametrize("gamma", [5e-324, 1e-320])
def test_subnormal_gamma_below_the_tables_least_c_is_answered(gamma):
    # at gamma = 5e-324, c = 1e-6 the hand-over ratio to the table (``law.hand_over_ratio``) was 0/0: the table's and
    # the law's mu at c = 1e-5 both underflow (ZeroDivisionError). There the law is exact to rounding: mu is gamma
    # times its value at gamma = 1e-300 (a normal double, the same law) to the subnormals' rounding (two of their ulps)
    normal = flat_punch(gamma=1e-300, c=1e-6).mu / 1e-300
    s = flat_punch(gamma=gamma, c=1e-6)
    assert s.mu >= 0.0 and abs(s.mu - normal * gamma) <= 2 * 5e-324


@pytest.mark.parametrize("nu", [0.0, -0.9999999999999999])
def test_slip_where_theta_rounds_to_half_pi(nu):
    # at mu gamma = 7.5e19 theta = atan(mu gamma) is pi/2 in double, alpha = 1/2, and u*'s edge family s^(2 alpha) is
    # s, a polynomial: the family (s^t - 1 - t (s - 1))/(t (1 - t)), t = 2 alpha, is s - 1 - s log s there (with
    # (s^t - 1)/t alone the interpolation of u* was singular: LinAlgError). Levels 2 and 4 agree to 1e-10 relative
    # (level 2's slip next to c_max; measured 5e-12, 9e-12)
    s = flat_punch(nu=nu, mu=1e20)
    x = np.array([0.5 * (1.0 + s.c), 1.0 - 0.01 * (1.0 - s.c), 1.0])  # on the slip annulus
    u2, u4 = s.slip(x), flat_punch(nu=nu, mu=1e20, level=4).slip(x)
    assert np.all(u2 < 0.0)
    np.testing.assert_allclose(u2, u4, rtol=1e-10, atol=0.0)
