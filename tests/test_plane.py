"""The plane-strain strip punch and cylinder with friction (``asymptotics.plane``, ``numeric.plane``).

Each check names its independent source: mpmath at 20-30 digits, SymPy, the closed limits, the same problem
at a much higher resolution (degree 28), the first-order law's measured order.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp

from asymptotics import plane as closed
from numeric import plane
from numeric.core.errors import NoEigenvalueError
from numeric.core.linear_algebra import equilibrate
from numeric.core.plane_cauchy import (HBETA, PLAIN, POWER, Family, family_cauchy, hbeta_moments, mode_cauchy, power_moments,
                                       product_rule)
from numeric.core.plane_charts import PlaneResolution
from numeric.core.plane_eigenvalue import plane_given_c, plane_given_c_linearised
from numeric.core.plane_fields import PlaneField, graded_both_ends

GAMMA_03 = 0.4 / 1.4  # nu = 0.3
#: mu(c = 0.5, nu = 0.3): degree 20, 24, 28 of the solver with c_fraction 0.25 and 0.1 (six values) lie within
#: 0.2374025971507 ... 0.2374025971518; their mean, with that spread as its uncertainty.
MU_REF_05 = 0.23740259715125
MU_REF_SPREAD = 1.1e-12


def _weight_mp(kind, parameter, s):
    if kind == PLAIN:
        return mpmath.mpf(1)
    if kind == POWER:
        return s ** parameter
    b = mpmath.mpf(parameter)
    return mpmath.log(s) if b == 0 else (s**b - 1) / b


def _cauchy_mp(kind, parameter, j, y):
    """PV int_0^1 w(s) P_j(2s - 1) ds / (s - y) at 30 digits (singularity subtracted inside; breakpoints graded to
    the scale of the distance from the nearer end; the subtraction cancels |w(y) log y| ~ 1e6 at y = 1e-9 for
    s^(-1/2), so 20 digits would leave 1e-14)."""
    with mpmath.workdps(30):
        y = mpmath.mpf(y)
        f = lambda s: _weight_mp(kind, parameter, s) * mpmath.legendre(j, 2 * s - 1)  # noqa: E731
        if 0 < y < 1:
            g = lambda s: (f(s) - f(y)) / (s - y) if s != y else mpmath.diff(f, y)  # noqa: E731
            near = [y * mpmath.mpf(2) ** -k for k in range(30 if kind == POWER else 6, 0, -1)]  # s^lam at 0: finer
            return mpmath.quad(g, [0] + near + [y, 1]) + f(y) * mpmath.log((1 - y) / y)
        d = y - 1 if y > 1 else -y
        toward = [mpmath.mpf(2) ** -k for k in range(1, int(-mpmath.log(d, 2)) + 3)] if d < 0.5 else []
        points = ([0, 0.5] + [1 - t for t in toward] + [1]) if y > 1 else ([0] + toward[::-1] + [1])
        return mpmath.quad(lambda s: f(s) / (s - y), sorted(set(points)))


@pytest.mark.parametrize("family", [Family(PLAIN, 0.0, 16), Family(POWER, -0.5, 12), Family(POWER, -0.1, 12),
                                    Family(HBETA, 0.45, 2), Family(HBETA, 1e-4, 2), Family(HBETA, 0.0, 2)])
def test_element_transforms_against_mpmath(family):
    # 30-digit quadrature at points inside, just outside (1e-9 ... 0.4 of the element) and far away; bound 2e-14 of
    # max(1, |I|) (measured worst over these: 1e-14; the Legendre recurrences and the subtraction cost a few ulp)
    y = np.array([-30.0, -0.4, -1e-9, 1e-9, 0.3, 0.97, 1.0 + 1e-9, 1.3])
    got = family_cauchy(family, y)
    for i, yi in enumerate(y):
        for j in sorted({0, family.degree}):
            ref = float(_cauchy_mp(family.kind, family.parameter, j, yi))
            assert abs(got[i, j] - ref) <= 2e-14 * max(1.0, abs(ref)), (family, yi, j)


def test_moments_and_product_rule_against_mpmath():
    # int_0^1 w P_m(2s - 1) for s^lam and h_beta, m < 52, by 30-digit quadrature: each moment is a product of m + 1
    # rounded ratios, so within (2 m + 4) ulp relative: 2.6e-14 at m = 51 (bound 3e-14)
    with mpmath.workdps(30):
        for kind, parameter in ((POWER, -0.5), (POWER, -0.1), (POWER, 0.3), (HBETA, 0.5), (HBETA, 1e-4), (HBETA, 0.0)):
            got = (power_moments if kind == POWER else hbeta_moments)(parameter, 52)
            for m in (0, 1, 2, 7, 30, 51):
                ref = mpmath.quad(lambda s: _weight_mp(kind, parameter, s) * mpmath.legendre(m, 2 * s - 1),
                                  [0] + [mpmath.mpf(2) ** -k for k in range(40, 0, -1)] + [1])
                assert abs(got[m] - float(ref)) <= 3e-14 * abs(float(ref)), (kind, parameter, m)
        # the product rule: exact on w times a polynomial of degree n - 1 (P_35 here: to the rounding of 36 terms,
        # 36 ulp x sum |w_i P_35(s_i)| <= 36 x 1.1e-16 x 2 = 8e-15; measured 2.2e-15), and int s^(-1/2) / (s + 0.6)
        # (pole at rho = 4.16: 4.16^-36 = 6e-23) to the rounding of the weights (1.2e-15 relative measured with the
        # Christoffel weights, 3e-14 with leggauss's; bound 4e-15)
        s, w = product_rule(power_moments(-0.5, 36))
        ref = mpmath.quad(lambda t: t ** -0.5 * mpmath.legendre(35, 2 * t - 1), [0, 1e-12, 1e-6, 1e-2, 0.5, 1])
        assert abs(w @ np.polynomial.legendre.legval(2 * s - 1, [0] * 35 + [1]) - float(ref)) <= 8e-15
        ref = mpmath.quad(lambda t: t ** -0.5 / (t + mpmath.mpf("0.6")), [0, 1e-12, 1e-6, 1e-2, 0.5, 1])
        assert abs(w @ (1.0 / (s + 0.6)) - float(ref)) <= 4e-15 * abs(float(ref))


def test_mode_transform_against_hypergeometric_closed_form():
    # beta PV int_0^1 s^(beta - 1) ds/(s - y) = -(1/y) 2F1(1, beta; beta + 1; 1/y) (continued to 0 < y < 1 by the real
    # part of the boundary value), mpmath at 30 digits; and the delta function's -1/y at beta = 0
    with mpmath.workdps(30):
        for beta in (0.5, 0.3, 1e-3):
            for y in (-3.0, -0.3, 1e-6, 0.3, 0.7, 1.2):
                ref = float(mpmath.re(-1 / mpmath.mpf(y) * mpmath.hyp2f1(1, beta, beta + 1, 1 / mpmath.mpf(y) + 1e-40j)))
                assert abs(float(mode_cauchy(beta, np.array([y]))[0]) - ref) <= 2e-15 * max(1.0, abs(ref))
    y = np.array([-3.0, -0.3, 0.3, 3.0])
    assert np.allclose(mode_cauchy(0.0, y), -1.0 / y, rtol=1e-15, atol=0.0)


def test_local_exponent_at_the_stick_slip_point():
    # Mellin symbols of H on one-sided powers: H[x_+^l] = -C x_+^l - S x_-^l, H[x_-^l] = S x_+^l + C x_-^l
    # (C = cot(pi l), S = 1/sin(pi l)); amplitudes a (q, stick side x < 0), b (p, stick), d (p, slip, q = mu p):
    # rows (N) on x > 0, (N) on x < 0, (T) on x < 0. det = (gamma mu - C)(1 - gamma^2): cot(pi l) = mu gamma only.
    g, m, C, S = sp.symbols("gamma mu C S")
    M = sp.Matrix([[0, S, g * m - C], [g, C, -S], [C, -g, -m * S]])
    det = sp.expand(M.det()).subs(S**2, 1 + C**2)
    assert sp.factor(sp.expand(det)) == sp.factor((g * m - C) * (1 - g**2))
    # the generic mode l = -1/2 - alpha has no p on the stick side and d = gamma a sin(pi l) = -gamma cos(pi alpha) a
    a = sp.symbols("a")
    null = M.subs(C, g * m) * sp.Matrix([a, 0, g * a / S])
    assert sp.simplify(null.subs(S**2, 1 + g**2 * m**2)) == sp.zeros(3, 1)


def test_bonded_index_is_abramovs():
    nu = sp.symbols("nu")
    gamma = (1 - 2 * nu) / (2 - 2 * nu)
    assert sp.simplify((1 + gamma) / (1 - gamma) - (3 - 4 * nu)) == 0
    assert closed.bonded_index(0.5) == pytest.approx(math.log(3.0) / (2 * math.pi), rel=1e-15)


def test_abramov_bonded_solution_satisfies_stick_everywhere():
    # H w = i gamma w at x = 0.3 by 30-digit quadrature of the principal value (singularity subtracted)
    gamma = mpmath.mpf("0.4")
    eps = mpmath.atanh(gamma) / mpmath.pi
    with mpmath.workdps(30):
        w = lambda t: mpmath.cosh(mpmath.pi * eps) / mpmath.pi * (1 - t) ** (-0.5 - 1j * eps) * (1 + t) ** (-0.5 + 1j * eps)  # noqa: E731
        x = mpmath.mpf("0.3")
        pv = mpmath.quad(lambda t: (w(t) - w(x)) / (t - x), [-1, x, 1]) + w(x) * mpmath.log((1 - x) / (1 + x))
        assert abs(pv / mpmath.pi - 1j * gamma * w(x)) < 1e-12
        assert abs(mpmath.quad(lambda t: w(t).real, [-1, 0, 1]) - 1) < 1e-12
    assert complex(closed.bonded_traction(0.3, 0.4)) == pytest.approx(complex(w(x)), rel=1e-14)


def test_first_order_law_steps_and_inverse():
    c = mpmath.mpf("0.6")
    with mpmath.workdps(30):
        # int_{-c}^{c} p0 / sqrt(c^2 - t^2) = (2/pi) K(c) and int_{c<|s|<1} p0 / sqrt(s^2 - c^2) = (2/pi) K'(c)
        left = 2 * mpmath.quad(lambda t: 1 / (mpmath.pi * mpmath.sqrt((1 - t * t) * (c * c - t * t))), [0, c])
        right = 2 * mpmath.quad(lambda s: 1 / (mpmath.pi * mpmath.sqrt((1 - s * s) * (s * s - c * c))), [c, 1])
        # tanh-sinh with 1/sqrt singularities at both ends of each range: measured 8e-18 at 30 digits
        assert abs(left - 2 / mpmath.pi * mpmath.ellipk(c * c)) < 1e-15
        assert abs(right - 2 / mpmath.pi * mpmath.ellipk(1 - c * c)) < 1e-15
    for cv in (1e-6, 0.3, 0.5, 0.9, 1 - 1e-9):
        assert closed.mu_over_gamma_plane(cv) == pytest.approx(float(closed.mu_over_gamma_plane_mp(cv)), rel=4e-15)
        mu = 0.4 * float(closed.mu_over_gamma_plane(cv))
        assert closed.stick_width_first_order(mu, 0.4) == pytest.approx(cv, rel=1e-13)  # the theta-function inverse
    assert closed.c_small_mu_plane(0.02, 0.5) == pytest.approx(closed.stick_width_first_order(0.02, 0.5), rel=1e-15)
    # the law's d mu / d logit c against mpmath's derivative of K/K' (50 digits) in logit c: measured within 2.3e-16;
    # bound 1e-14 (ellipkm1 is good to a few ulp, and 1 - c = gap is passed exactly)
    with mpmath.workdps(50):
        def law(xi):
            k = 1 / (1 + mpmath.exp(-xi))
            return mpmath.ellipk(k * k) / mpmath.ellipk(1 - k * k)
        for cv, gap in ((1e-3, 1 - 1e-3), (0.5, 0.5), (1 - 2.0**-30, 2.0**-30)):
            xi = mpmath.log(mpmath.mpf(cv) / mpmath.mpf(gap))
            assert closed.friction_slope_first_order(cv, gap, 0.3) == pytest.approx(0.3 * float(mpmath.diff(law, xi)),
                                                                                    rel=1e-14)
    assert 1 - closed.stick_width_first_order(4.0, 0.5) == pytest.approx(closed.gap_large_mu_plane(4.0, 0.5), rel=1e-10)


@pytest.fixture(scope="module")
def punch():
    return plane.flat_punch(nu=0.3, c=0.5)


def test_default_level_against_the_converged_value(punch):
    # MU_REF_05: degrees 20-28, two layouts (see its comment); the default level (degree 18) and its estimate
    assert abs(punch.mu - MU_REF_05) <= 3e-12 + MU_REF_SPREAD
    assert punch.error >= abs(punch.mu - MU_REF_05) - MU_REF_SPREAD
    assert punch.error <= 1e-10 * punch.mu


def test_the_system_is_not_singular(punch):
    # the equilibrated matrix at the default level: smallest singular value 4e-12 of the largest (measured; the
    # enriched basis h_beta P_k, k <= 2, next to degree-18 Legendre series is redundant to ~1e-9 on its element).
    # Before the fix: 1e-16 (singular families of degree 4-6, polynomial to rounding) and, with one collocation
    # point fewer on the edge, a spurious edge oscillation.
    sol = punch.field.solution
    sv = np.linalg.svd(equilibrate(sol.system.matrix(sol.theta))[0], compute_uv=False)
    assert sv[-1] / sv[0] > 1e-13


def test_given_mu_inverts_given_c(punch):
    back = plane.flat_punch(nu=0.3, mu=punch.mu)
    # the steps in logit c stop once theta is within THETA_SCATTER (5e-11 relative) of atan(mu gamma): c within
    # that over d theta / d c (~1 here), and within the estimated error (which counts the step not taken)
    assert abs(back.c - 0.5) <= back.error < 1e-10


def test_the_solution_satisfies_the_friction_conditions(punch):
    x = np.linspace(0.0, 0.5, 41)[1:-1]
    p, q = punch.pressure(x), punch.shear(x)
    assert np.all(q < punch.mu * p) and np.all(p > 0)  # stick: |q| < mu p
    # q/(mu p) -> 1 at c: the eigenvalue condition phi(c-) = 0 holds to the discretisation error of the stresses at c
    # (the end of the singular element; measured 2.8e-10 at the default level), the stress target being 1e-9
    assert punch.shear(0.5) == pytest.approx(punch.mu * punch.pressure(0.5), rel=1e-9)
    xs = np.array([0.6, 0.8, 0.95])
    assert np.all(punch.slip(xs) < 0) and np.all(punch.slip(-xs) > 0)  # slip inward
    assert np.all(punch.slip(x) == 0.0)
    assert punch.shear(-0.3) == -punch.shear(0.3) and punch.pressure(-0.3) == punch.pressure(0.3)
    assert punch.field.load == pytest.approx(1.0, abs=1e-13)  # the load row, to the LU's rounding (n eps ~ 3e-14)


def test_the_stresses_converge_at_c_and_next_to_the_edge(punch):
    # the default level against degree 24 at x = 0, c and 1 - 1e-5, relative to max(1, |p|)
    fine = PlaneField(plane_given_c(0.5, 0.5, GAMMA_03, punch.field.theta, PlaneResolution(24, 2)))
    x = np.array([0.0, 0.25, 0.5, 0.75, 1 - 1e-5])
    p, q = punch.field.pressure_shear(x)
    pf, qf = fine.pressure_shear(x)
    scale = np.maximum(1.0, np.abs(pf))
    assert np.all(np.abs(p - pf) <= 1e-9 * scale) and np.all(np.abs(q - qf) <= 1e-9 * scale)


@pytest.mark.parametrize("nu, c", [(0.0, 0.99), (0.0, 0.995), (-0.5, 0.93)])
def test_the_stresses_at_c_converge_next_to_the_largest_stick_width(nu, c):
    # alpha = 0.33 ... 0.48: the default level against degree 24 at x = c, the doubles next to it and within 1e-9 of it
    # (relative to c, 1 - c), p relative to max(1, |p|), q to max(1, |q|). Measured 5e-10, 6.6e-10, 7.6e-10; with the
    # stick pressure's singular family free (before it was pinned, from alpha = 1/4 and now 0.04 on) 6.7e-9, 5e-8,
    # 1.5e-6. Bound
    # 2e-9, the stress target (1e-9) with room for rounding
    from numeric.solutions.plane_solver import DEFAULT_LEVEL, PLANE_LEVELS
    g = (1 - 2 * nu) / (2 - 2 * nu)
    theta = math.atan(plane.flat_punch(nu=nu, c=c).mu * g)
    x = np.array([c * (1 - 1e-9), np.nextafter(c, 0.0), c, np.nextafter(c, 2.0), c + 1e-9 * (1 - c)])
    p, q = PlaneField(plane_given_c(c, 1 - c, g, theta, PLANE_LEVELS[DEFAULT_LEVEL])).pressure_shear(x)
    pf, qf = PlaneField(plane_given_c(c, 1 - c, g, theta, PlaneResolution(24, 2))).pressure_shear(x)
    assert np.all(np.abs(p - pf) <= 2e-9 * np.maximum(1.0, np.abs(pf))), (p - pf)
    assert np.all(np.abs(q - qf) <= 2e-9 * np.maximum(1.0, np.abs(qf))), (q - qf)


@pytest.mark.parametrize("nu, c", [(0.3, 0.999), (0.0, 0.97)])
def test_the_stresses_at_c_converge_where_the_stick_pressure_family_is_pinned_below_a_quarter(nu, c):
    # alpha = 0.10, 0.23: between PLANE_PIN_FROM = 0.04 and 1/4, where p's singular family on the stick end was left
    # free before. The default level against degree 28 at x = 0, c/2, within 1e-9 of c, the doubles next to it, c
    # itself and (1 + c)/2, p relative to max(1, |p|), q to max(1, |q|). Measured 1.5e-10, 3.1e-10 (free: 1.7e-9,
    # 2.9e-9). Bound 1e-9, the stress target
    from numeric.solutions.plane_solver import DEFAULT_LEVEL, PLANE_LEVELS
    g = (1 - 2 * nu) / (2 - 2 * nu)
    theta = math.atan(plane.flat_punch(nu=nu, c=c).mu * g)
    x = np.array([0.0, 0.5 * c, c * (1 - 1e-9), np.nextafter(c, 0.0), c, np.nextafter(c, 2.0), c + 1e-9 * (1 - c),
                  0.5 * (1 + c)])
    p, q = PlaneField(plane_given_c(c, 1 - c, g, theta, PLANE_LEVELS[DEFAULT_LEVEL])).pressure_shear(x)
    pf, qf = PlaneField(plane_given_c(c, 1 - c, g, theta, PlaneResolution(28, 2))).pressure_shear(x)
    assert np.all(np.abs(p - pf) <= 1e-9 * np.maximum(1.0, np.abs(pf))), (p - pf)
    assert np.all(np.abs(q - qf) <= 1e-9 * np.maximum(1.0, np.abs(qf))), (q - qf)


def test_slip_integral_rule():
    # the composite rules of the slip integral (innermost pieces in s = h v^16, Christoffel weights): the strain's end
    # behaviours s^lam, lam >= -1/2 ((1 - t)^(alpha - 1/2) at the edge, (t - c)^beta at c), log s and log^2 s, to
    # rounding, on the fully graded rule and on the one with a single piece at each end (the slip at x = (1 + c)/2):
    # measured <= 1.2e-15 relative; the sum of <= 1300 positive terms of a few ulp each, the weights a few ulp: 1e-14
    from numeric.core.plane_fields import graded_toward, pieces_toward
    for s, om, w in (graded_both_ends(), graded_toward(1, 1)):
        for lam in (-0.5, -0.48, -0.25, 0.0, 0.3, 0.5):
            assert abs((w * s**lam).sum() * (lam + 1) - 1.0) < 1e-14
            assert abs((w * om**lam).sum() * (lam + 1) - 1.0) < 1e-14
        assert abs((w * np.log(s)).sum() + 1.0) < 1e-14 and abs((w * np.log(om) ** 2).sum() - 2.0) < 1e-14
    # a pole of order 2 a distance d beyond s = 0 (the weight t^-n at t = 0 behind lo = c, the strain's -c), graded as
    # far as pieces_toward(d) says, times s^0.3: against 30-digit mpmath, measured 4.4e-16
    with mpmath.workdps(30):
        for d in (1e-2, 1e-5, 1e-9):
            s, _, w = graded_toward(int(pieces_toward(np.array([d]))[0]), 1)
            dm = mpmath.mpf(d)
            ref = mpmath.quad(lambda t: t ** mpmath.mpf("0.3") / (t + dm) ** 2,
                              [0] + [dm * mpmath.mpf(2) ** k for k in range(-6, 31) if dm * 2**k < 1] + [1])
            assert abs((w * s**0.3 / (s + d) ** 2).sum() / float(ref) - 1.0) < 1e-14
    # the same pole a distance d beyond s = 1 (the edge's singularity behind x, the slip's upper limit), the end at 1
    # regular: the innermost piece there plain Gauss (``regular_one``), s^0.3 at 0 as the strain's at c, one piece
    # for the whole half where d >= 1/2; measured <= 4.4e-16 (two pieces fewer: 1e-10 ... 1e-9)
    with mpmath.workdps(30):
        for d in (1.0, 0.3, 1e-2, 1e-5, 1e-9):
            k = 0 if d >= 0.5 else int(pieces_toward(np.array([d]))[0])  # as ``PlaneField.slip`` chooses
            s, om, w = graded_toward(1, k, True)
            assert d >= 0.5 ** (k + 1)  # the condition under which the slip takes the plain innermost piece
            dm = mpmath.mpf(d)
            ref = mpmath.quad(lambda t: t ** mpmath.mpf("0.3") / (1 + dm - t) ** 2,
                              [0, 0.5] + sorted(1 - dm * mpmath.mpf(2) ** j for j in range(-6, 31) if dm * 2**j < 0.5) + [1])
            assert abs((w * s**0.3 / (om + d) ** 2).sum() / float(ref) - 1.0) < 1e-14


def test_first_order_law_error_is_order_gamma_squared():
    # (mu / mu_first - 1) / gamma^2 is the same at two small gamma (measured 0.70 at nu = 0.45, c = 0.5)
    ratios = []
    for nu in (0.45, 0.48):
        g = (1 - 2 * nu) / (2 - 2 * nu)
        mu = plane.flat_punch(nu=nu, c=0.5).mu
        ratios.append((mu / (g * float(closed.mu_over_gamma_plane(0.5))) - 1) / g**2)
    assert ratios[0] == pytest.approx(ratios[1], rel=0.05)


def test_frictionless_and_bonded_limits_are_exact():
    s = plane.flat_punch(nu=0.3, mu=0.0)
    x = np.array([0.0, 0.5, 0.99])
    assert np.allclose(s.pressure(x), 1 / (np.pi * np.sqrt(1 - x**2)), rtol=1e-15, atol=0.0)  # rounding only
    h = plane.power_law(2, nu=0.3, mu=0.0)
    x = np.array([0.0, 1e-8, 1e-3, 0.6, 0.999, 1 - 1e-12, 1.0])
    # (3.13) on the closed form by the graded rule in u = sqrt(1 - t): Hertz to rounding (measured 2e-16)
    assert np.allclose(h.pressure(x), 2 / np.pi * np.sqrt((1 - x) * (1 + x)), rtol=0, atol=2e-15)
    assert h.load_factor == pytest.approx(2 / math.pi, rel=1e-13) and h.load_ratio == pytest.approx(1.0, rel=1e-13)
    b = plane.flat_punch(nu=0.3, c=1.0)
    assert b.mu == math.inf and b.route == "full stick (Abramov)"
    w = closed.bonded_traction(np.array([0.2, 0.7]), GAMMA_03)
    assert np.all(b.pressure([0.2, 0.7]) == w.real) and np.all(b.shear([0.2, 0.7]) == w.imag)


def test_cylinder_with_friction():
    h = plane.power_law(2, nu=0.3, c=0.5)
    # (3.18): p(0) = 2 p0(0)
    assert float(h.pressure(0.0)) == pytest.approx(2 * float(h.flat.pressure(0.0)), rel=1e-15)
    # unit load: int p over [0, c] and [c, 1] by the graded rule (p_n has |x - c|^(beta + 1) at c), 1e-12
    s, _, w = graded_both_ends()
    total = 2 * (0.5 * np.sum(w * h.pressure(0.5 * s)) + 0.5 * np.sum(w * h.pressure(0.5 + 0.5 * s)))
    assert total == pytest.approx(1.0, abs=1e-12)
    # friction raises the load at a given width: P/P_Hertz > 1
    assert h.load_ratio > 1.0
    q = h.shear(np.array([0.25, 0.5, 0.75]))
    assert q[1] == pytest.approx(h.mu * float(h.pressure(0.5)), rel=1e-9)  # q = mu p from c outward, (3.14)


def test_above_the_largest_stick_width_there_is_no_friction_coefficient():
    with pytest.raises(NoEigenvalueError):
        plane.flat_punch(nu=0.0, c=0.999)  # c_max(nu = 0) = 0.99626 (the limit problem)


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="exactly one of mu"):
        plane.flat_punch(nu=0.3)
    with pytest.raises(ValueError, match="nu"):
        plane.flat_punch(nu=0.7, c=0.5)
    with pytest.raises(ValueError, match="c "):
        plane.flat_punch(nu=0.3, c=1.5)
    with pytest.raises(ValueError, match="mu"):
        plane.flat_punch(nu=0.3, mu=-1.0)
    with pytest.raises(ValueError, match="level"):
        plane.flat_punch(nu=0.3, c=0.5, level=7)
    with pytest.raises(TypeError, match="x must be"):
        plane.flat_punch(nu=0.3, mu=0.0).pressure("a")
    with pytest.raises(ValueError, match="x "):
        plane.flat_punch(nu=0.3, mu=0.0).pressure(1.5)
    with pytest.raises(ValueError, match="n "):
        plane.power_law(-1, nu=0.3, mu=0.0)
    # the strip punch solves one problem: longer arrays are refused by name (numpy's "only 0-dimensional arrays"
    # message before), one-element arrays accepted as numeric.flat_punch accepts them
    for kwargs, name in ((dict(mu=np.array([0.2, 0.3])), "mu"), (dict(c=np.array([0.2, 0.3])), "c")):
        with pytest.raises(TypeError, match=f"{name} must be a single number"):
            plane.flat_punch(nu=0.3, **kwargs)
    assert plane.flat_punch(nu=np.array([[0.3]]), mu=np.array([0.0])).c == 0.0


#: (nu, c) over the plane: small and moderate c, each region of the guess table (S: c <= 0.8; N: gamma <= 0.16,
#: nu = 0.45; L: near c_max, 1 - c_max = 1.6e-6, 3.7e-3, 5.9e-2 at nu = 0.3, 0, -0.5)
SPREAD = [(0.3, 0.5), (0.3, 0.05), (0.45, 0.3), (0.45, 0.999), (0.0, 0.9), (-0.5, 0.9), (0.3, 0.99999), (0.0, 0.996),
          (-0.5, 0.94)]


def test_the_guess_table_starts_newton_one_round_from_the_root():
    # the generated table (derivations/build_plane_guess.py) recorded its worst error in mu at held-out points of each
    # region; here fresh points against the careful iteration at the default level (an independent route: Newton
    # with both assemblies at every step, from the first-order law): within the recorded error (x 2: these are other
    # points), and below OUTER_TOLERANCE, so that the linearised iteration accepts its first round
    from numeric.core import plane_guess, plane_guess_data
    from numeric.core.plane_eigenvalue import OUTER_TOLERANCE
    from numeric.solutions.plane_solver import PLANE_LEVELS
    assert max(plane_guess_data.ERRORS.values()) < 1e-7
    for nu, c in SPREAD:
        g = (1 - 2 * nu) / (2 - 2 * nu)
        start = math.atan(g * g / plane_guess.elliptic_ratio(c, 1 - c))
        theta = plane_given_c(c, 1 - c, g, start, PLANE_LEVELS[2]).theta
        guess = plane_guess.theta_guess(c, 1 - c, g)
        region = plane_guess.region_of(c, 1 - c, g).name
        assert abs(math.tan(guess.theta) / math.tan(theta) - 1) < 2 * plane_guess_data.ERRORS[region], (nu, c)
        assert abs(guess.theta / theta - 1) < OUTER_TOLERANCE, (nu, c)


def test_the_table_inverts_itself_and_its_slope_is_the_solvers():
    # stick_width_guess(theta) is the c whose theta_guess is theta (to rounding), and its d theta / d logit c agrees
    # with a central difference of level-2 solves 1e-4 apart in logit c (the table's own error, 1e-8, over the step)
    from numeric.core import plane_guess
    from numeric.solutions.plane_solver import PLANE_LEVELS
    for nu, c in ((0.3, 0.5), (0.45, 0.999), (-0.5, 0.94)):
        g = (1 - 2 * nu) / (2 - 2 * nu)
        guess = plane_guess.theta_guess(c, 1 - c, g)
        c2, gap2, back = plane_guess.stick_width_guess(guess.theta, g)
        assert abs(math.log(c2 / gap2) - math.log(c / (1 - c))) < 1e-12 and back.theta == pytest.approx(guess.theta, rel=1e-14)
        xi = math.log(c / (1 - c))
        thetas = []
        for x in (xi - 1e-4, xi + 1e-4):
            cc, gg = 1 / (1 + math.exp(-x)), 1 / (1 + math.exp(x))
            thetas.append(plane_given_c(cc, gg, g, guess.theta, PLANE_LEVELS[2]).theta)
        assert guess.slope == pytest.approx((thetas[1] - thetas[0]) / 2e-4, rel=1e-4), (nu, c)


@pytest.mark.parametrize("nu, c", SPREAD)
def test_the_linearised_iteration_agrees_with_the_careful_one(nu, c):
    # the fast path (one round of two assemblies from the table) against the careful iteration (both assemblies at
    # every step) at the default level: theta to THETA_SCATTER relative (the rounding floor of G: the careful iteration
    # itself ends anywhere within 2e-11 ... 3e-11 of theta depending on its start and on the BLAS threads, measured),
    # i.e. mu to that times theta / (sin cos) (1 at small mu, ~100 near c_max), below the level's accuracy; the
    # stresses, relative to max(1, |p|), to the level's own error there (the careful iteration against degree 24,
    # twice) or 5e-9: two roots within G's rounding floor differ in the stresses by that
    # floor times their derivative in theta, large near c_max, where the level's own error is 2e-7 ... 5e-6 (measured
    # at nu = 0 and -1/2; 1e-10 at nu = 0.3, c = 0.5), and the stresses at c itself are ill-conditioned: at nu = 0,
    # c = 0.9 the linearised arrays, 7e-15 relative from a fresh assembly at alpha = theta/pi, give p(c) 1.9e-9 and
    # q(c) 2.6e-9 from its solution (measured), the basis being nearly redundant on the elements at c. At x = c itself
    # the bound is the level's documented accuracy there, 1e-7 of the larger of |p|, |q| (README: levels 2 and 3 lie
    # within 6e-8 and 8e-8 of level 4 at x = c near c_max): with a multithreaded BLAS the two routes' q(c) came out
    # 3e-7 apart at nu = 0.3, c = 0.99999 (mu = 4, |q| = 129: 2.4e-9) and 2.4e-8 at nu = 0.45, c = 0.999 (|q| = 1.9)
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_solver import PLANE_LEVELS, THETA_SCATTER
    g = (1 - 2 * nu) / (2 - 2 * nu)
    fast = plane.flat_punch(nu=nu, c=c)
    careful = plane_given_c(c, 1 - c, g, math.atan(g * g / elliptic_ratio(c, 1 - c)), PLANE_LEVELS[2])
    assert fast.field.solution.linearised is not None  # it was the fast path
    t = careful.theta
    assert abs(fast.mu / (math.tan(t) / g) - 1) < THETA_SCATTER * t / (math.sin(t) * math.cos(t))
    x = np.array([0.0, 0.5 * c, c, 0.5 * (1 + c), 1 - 1e-5])
    fine = PlaneField(plane_given_c(c, 1 - c, g, careful.theta, PlaneResolution(24, 2)))
    (p, q), (pc, qc), (pf, qf) = (f.pressure_shear(x) for f in (fast.field, PlaneField(careful), fine))
    at_c = x == c
    scale = np.maximum(1.0, np.maximum(np.abs(pf), np.abs(qf)))
    for a, b, f in ((p, pc, pf), (q, qc, qf)):
        away = np.abs(a - b)[~at_c] / scale[~at_c]
        assert np.max(away) <= max(5e-9, 2 * np.max(np.abs(b - f)[~at_c] / scale[~at_c])), (nu, c)
        assert np.max(np.abs(a - b)[at_c] / scale[at_c]) <= 1e-7, (nu, c)


@pytest.mark.parametrize("nu, c", [(-0.5, 0.93), (0.0, 0.99)])
def test_the_rate_in_alpha_is_the_quotient_of_two_whole_assemblies(nu, c):
    # the linearised system's second assembly forms only the columns that depend on alpha (h_beta at c, the edge
    # element, the generic mode): against the difference quotient of two whole assemblies, where both have the same pins
    # and no balance (alpha >= BALANCE_ALPHA_MAX, the reflection being chosen per assembly below it), the quotient is 0
    # to the last bit in every other column (the same operations on the same numbers: what the restriction rests on),
    # and in those columns it is the rate to the quotient's own rounding: a few eps of the terms that make each entry
    # (|stick|, cos|normal| + sin|shear|, |mode| of both assemblies) over the step; 4 eps, the rate and the quotient
    # rounding their sums in a different order
    from dataclasses import replace
    from numeric.core.plane_eigenvalue import plane_operators_at
    from numeric.core.plane_operators import BALANCE_ALPHA_MAX, linearised_system, plane_collocation_system
    from numeric.solutions.plane_solver import PLANE_LEVELS
    g = (1 - 2 * nu) / (2 - 2 * nu)
    theta = math.atan(plane.flat_punch(nu=nu, c=c).mu * g)
    alpha, step = theta / math.pi, 1e-7 * theta / math.pi
    assert alpha >= BALANCE_ALPHA_MAX
    ops = plane_operators_at(c, 1 - c, PLANE_LEVELS[2])
    base, other = plane_collocation_system(ops, g, alpha), plane_collocation_system(ops, g, alpha + step)
    assert base.pinned == other.pinned and base.balance is None and other.balance is None
    quotient = (other.matrix(theta) - base.matrix(theta)) / step
    linear = linearised_system(ops, g, alpha, step)
    rate = np.zeros_like(quotient)
    linear.rate.add_to_matrix(rate, theta, 1.0, base.n_stick)
    varying = np.zeros(quotient.shape[1], dtype=bool)
    varying[linear.rate.stick_columns] = True
    varying[2 * base.n_stick + linear.rate.slip_columns] = True
    assert 0 < np.count_nonzero(varying) < varying.size / 4
    assert np.all(quotient[:, ~varying] == 0.0) and np.all(rate[:, ~varying] == 0.0)
    def terms(s):
        return replace(s, stick=np.abs(s.stick), normal=np.abs(s.normal), shear=np.abs(s.shear),
                       mode_stick=np.abs(s.mode_stick)).matrix(theta)

    bound = 4 * np.finfo(float).eps * (terms(base) + terms(other)) / step
    assert np.all(np.abs(rate - quotient) <= bound)
    assert np.max(np.abs(quotient)) > 1e3 * np.max(bound)  # the rate is resolved, not rounding
    assert np.array_equal(linear.matrix(theta), base.matrix(theta))  # delta = 0 at theta = pi alpha


@pytest.mark.parametrize("c", [0.01, 0.5])
def test_the_error_estimate_covers_the_rounding_of_theta_as_nu_tends_to_a_half(c):
    # as nu -> 1/2 theta ~ gamma^2 K/K' is small, and on the plain system G's rounding, absolute in theta, dominated
    # mu's relative error: the independent measure is the scatter of the root itself over starts 1e-9 ... 1e-7 off
    # (each its own linearisation, so its own rounding). Measured at nu = 0.488, level 2: 3.3e-9 (c = 0.01), 1.5e-10
    # (c = 0.5) on the plain system, where the estimate was 8.2e-10 and 1e-10 before it counted theta_rounding; on
    # the balanced system the scatter is 6.8e-11 and 5.1e-12, the estimate 4.8e-10 and 1e-10
    from numeric.solutions.plane_solver import GUESS_SPREAD, PLANE_LEVELS
    nu = 0.488
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = plane.flat_punch(nu=nu, c=c)
    theta = math.atan(s.mu * g)
    roots = [plane_given_c_linearised(c, 1 - c, g, theta * (1 + k), PLANE_LEVELS[2], GUESS_SPREAD).theta
             for k in (-3e-8, -1e-8, -1e-9, 1e-9, 1e-8, 3e-8, 1e-7)]
    mus = np.tan(roots) / g
    assert (mus.max() - mus.min()) <= s.error


@pytest.mark.parametrize("nu", [0.46, 0.48, 0.489])
@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
def test_mu_to_1e_10_as_nu_tends_to_a_half(nu, c):
    # balanced, the normal rows' near-null combination is replaced by a tangential row: the plain system's
    # mu was up to 3.4e-9 off at nu = 0.489, c = 0.05 (its estimate 3e-8, theta's absolute rounding over theta ~
    # gamma^2). Against the small-gamma series through level-3 solves at gamma = 0.06 ... 0.16 (another route: an
    # interpolation in gamma^2, extrapolated below 0.06), measured at these points: 4.7e-11 ... 8.7e-11 (c = 0.05),
    # 1e-13 ... 2.2e-11 (c = 0.5, 0.97). Bound 2e-10: the target 1e-10 plus the series' own error (~1e-10 at
    # gamma = 0.02, ``plane_small_gamma``). The estimate: 4e-10 (c = 0.05) and the floor 1e-10 (was 1e-9 ... 3e-8).
    from numeric.solutions.plane_small_gamma import gamma_series
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = plane.flat_punch(nu=nu, c=c)
    assert s.route.startswith("solver")
    series = g * gamma_series(c, 1 - c, 3).mu_over_gamma(g)
    assert abs(s.mu / series - 1) <= 2e-10
    assert s.error <= 1e-9 * s.mu


@pytest.mark.parametrize("c, gap", [(0.5, 0.5), (1 - 1e-9, 1e-9)])
def test_the_balanced_solver_keeps_the_stresses_as_gamma_tends_to_zero(c, gap):
    # gamma = 1e-8 (nu = 0.5 - 5e-9): on the plain system the stick-shear near-null mode (singular value ~ gamma) put
    # q/(mu p) = 1.1e4 in the stick zone at c = 0.5, q(0.1) < 0 and u(0.75)/gamma = -1319 (the limit is -0.0385).
    # Balanced, levels 2 and 3 against level 4 (a convergence study), measured: p, q/gamma, u/gamma within 3e-12,
    # 1e-11, 1e-13 (level 2, c = 0.5) and 4e-11, 2e-11, 2e-16 (1 - c = 1e-9, where the small-gamma series does not
    # reach) of their largest value; bound 1e-9, the accuracy of the stresses
    from numeric.solutions.plane_solver import solve_given_c
    g = 1e-8
    x = np.array([0.0, 0.3 * c, c * (1 - 1e-3), c, c + 1e-3 * gap, 0.5 * (1 + c), 1 - 0.01 * gap, -0.5 * c])
    ref = solve_given_c(c, gap, g, 4).field
    p_ref, q_ref = ref.pressure_shear(x)
    u_ref = ref.slip(x)
    for level in (2, 3):
        f = solve_given_c(c, gap, g, level).field
        p, q = f.pressure_shear(x)
        for got, want in ((p, p_ref), (q / g, q_ref / g), (f.slip(x) / g, u_ref / g)):
            assert np.max(np.abs(got - want)) <= 1e-9 * np.max(np.abs(want)), level
    f = solve_given_c(c, gap, g, 2).field
    stick = np.linspace(0.01, 0.99, 50) * c
    p, q = f.pressure_shear(stick)
    assert np.all(np.abs(q) <= f.mu * p) and np.all(q > 0.0)  # Coulomb, the shear outward
    assert np.all(f.slip(c + gap * np.array([0.1, 0.5, 0.9])) < 0.0)  # slipping inward


@pytest.mark.parametrize("nu, c", [(-0.5, 1e-4), (0.0, 1e-3), (0.3, 1e-4), (0.3, 0.5), (0.45, 0.01), (0.499, 0.9)])
def test_theta_rounding_covers_the_scatter_of_the_root(nu, c):
    # theta_rounding (the lesser of 5e-13 c^-0.4 and 3e-11 theta c^-0.6) floors the error estimate and stops Newton:
    # the scatter of the root over starts 1e-9 ... 1e-7 off (each its own linearisation, so its own rounding) must lie
    # below it. Measured at level 2 (spread / theta): 6.6e-13 (nu = -1/2, c = 1e-4), 3.3e-12, 2.3e-10 (nu = 0.3,
    # c = 1e-4), 1.3e-12, 3.4e-11, 5.4e-12; the envelope there 2.3e-10, 1.4e-10, 1.6e-9, 9.7e-12, 4.8e-10, 3.2e-11:
    # 6x ... 350x above, not tighter (the scatter grows with the level, to 7e-10 at level 4, nu = 0.3, c = 1e-4)
    from numeric.core.plane_eigenvalue import theta_rounding
    from numeric.solutions.plane_solver import GUESS_SPREAD, PLANE_LEVELS
    g = (1 - 2 * nu) / (2 - 2 * nu)
    theta = math.atan(plane.flat_punch(nu=nu, c=c).mu * g)
    roots = [plane_given_c_linearised(c, 1 - c, g, theta * (1 + k), PLANE_LEVELS[2], GUESS_SPREAD).theta
             for k in (-1e-7, -1e-8, -1e-9, 1e-9, 1e-8, 1e-7)]
    assert max(roots) - min(roots) <= theta_rounding(c, theta)


@pytest.mark.parametrize("nu, c", [(0.499, 0.01), (0.499, 0.1), (0.495, 1e-4)])
def test_the_linearised_iteration_settles_at_its_rounding_near_nu_a_half(nu, c):
    # on the plain system theta's rounding scatter there was 1e-7 ... 4e-6 relative, above the iteration's relative
    # tolerances: before they were absolute as well (theta_rounding), starts at the root itself or 1e-8 ... 1e-7 off
    # raised SolverError at these points (the route then fell back on the careful iteration); now each settles,
    # within the solver's estimate (on the balanced system 1.9e-11, 1.4e-11, 5.5e-10 from it, the estimate 4.8e-10,
    # 1.2e-10, 1.3e-8 relative)
    from numeric.solutions.plane_solver import GUESS_SPREAD, PLANE_LEVELS, solve_given_c
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = solve_given_c(c, 1 - c, g, 2)
    theta, error = math.atan(s.field.mu * g), s.error.value()
    for k in (0.0, -3e-8, 1e-8, 1e-7):
        root = plane_given_c_linearised(c, 1 - c, g, theta * (1 + k), PLANE_LEVELS[2], GUESS_SPREAD).theta
        assert abs(math.tan(root) / g - s.field.mu) <= error


@pytest.fixture
def linearised_rounds(monkeypatch):
    """The arguments of every linearised round (``numeric.core.plane_eigenvalue.linearised_system``) from here on: a
    given-c solve from a close start is one round."""
    from numeric.core import plane_eigenvalue
    rounds = []
    original = plane_eigenvalue.linearised_system
    monkeypatch.setattr(plane_eigenvalue, "linearised_system", lambda *a: rounds.append(a) or original(*a))
    return rounds


def test_one_round_given_c_and_one_solve_given_mu(linearised_rounds):
    # what the table buys: given c, one linearised round (two assemblies); given mu, one given-c solve at the table's c,
    # whose theta already lies within the solve's own scatter THETA_SCATTER of atan(mu gamma) (with the coarser table
    # of 5.2e-10 ... 3.7e-8 it took a second solve, one step in logit c, here and at 42 of 70 points), one round; the
    # error estimate only when read; c within its estimated error
    from numeric.solutions.solution import DeferredError
    rounds = linearised_rounds
    s = plane.flat_punch(nu=0.0, c=0.9)
    assert len(rounds) == 1 and isinstance(s._error, DeferredError)
    rounds.clear()
    back = plane.flat_punch(nu=0.0, mu=s.mu)
    assert len(rounds) == 1 and abs(back.c - 0.9) <= back.error


@pytest.mark.parametrize("nu, c", [(0.0, 0.99), (-0.5, 0.93), (0.3, 0.9999), (-0.5, 0.5)])
def test_given_mu_takes_one_solve_near_c_max_too(nu, c, linearised_rounds):
    # next to c_max (region L of the guess table) as inside: the table's c lands within the given-c solve's own scatter
    # of theta, so given mu is one given-c solve (two or three there with the table before its 1 - c_max series and its
    # nodes were refined, numeric.core.plane_guess), and c is within its estimated error of the case's c (mu from a
    # level-3 solve at c: level 3's own error is far below level 2's estimate)
    rounds = linearised_rounds
    mu = plane.flat_punch(nu=nu, c=c, level=3).mu
    rounds.clear()
    s = plane.flat_punch(nu=nu, mu=mu)
    assert len(rounds) == 1 and abs(s.gap - (1.0 - c)) <= s.error


@pytest.mark.parametrize("nu, c", [(0.25, 0.5), (0.0, 0.995), (-0.9, 0.3)])
def test_given_mu_carries_the_solution_along_newtons_tangent(nu, c, monkeypatch):
    # given mu, the last given-c solve's z is carried to theta = atan(mu gamma) along Newton's dz/dtheta
    # (``plane_at_theta``, ``numeric.core.eigenvalue.TANGENT_REACH``), as on the axisymmetric side, instead of a new LU
    # at theta: the guided solves start Newton at theta, so the carried z is that LU's own solution up to the rounding
    # of adding and removing Newton's last step. Against a new solve at theta on the same system the load, p, q and u
    # (relative to max(1, |p|)) agree to 0 at these points (measured; 6e-12 at nu = 0, c = 0.05, 3.7e-10 at nu = 0.49,
    # c = 0.3 where both lie ~2e-9 from level 3); bound 1e-11, below the level's 1e-9, and no LU is formed for it
    import dataclasses

    from asymptotics.materials import gamma_from_nu
    from numeric.core import plane_eigenvalue
    from numeric.core.linear_algebra import EquilibratedLU
    mu = plane.friction_coefficient(c, nu)
    factored = []
    original = plane_eigenvalue.EquilibratedLU
    monkeypatch.setattr(plane_eigenvalue, "EquilibratedLU", lambda *a, **k: factored.append(a) or original(*a, **k))
    s = plane.flat_punch(nu=nu, mu=mu)
    carried = s.field.solution
    assert carried.theta == math.atan(mu * float(gamma_from_nu(nu))) and carried.tangent is not None
    assert not factored  # the given-c solves factor through newton_theta; plane_at_theta added none
    system = carried.linearised
    fresh = PlaneField(dataclasses.replace(carried, coefficients=EquilibratedLU(system.matrix(carried.theta)).solve_refined(
        system.rhs)))
    x = np.array([0.0, 0.5 * s.c, s.c, np.nextafter(s.c, 2.0), 0.5 * (1 + s.c), 1 - 1e-5 * (1 - s.c)])
    (p, q), (pf, qf) = s.field.pressure_shear(x), fresh.pressure_shear(x)
    scale = np.maximum(1.0, np.abs(pf))
    assert s.field.load == pytest.approx(fresh.load, rel=1e-11)
    assert np.all(np.abs(p - pf) <= 1e-11 * scale) and np.all(np.abs(q - qf) <= 1e-11 * np.maximum(1.0, np.abs(qf)))
    assert np.all(np.abs(s.field.slip(x) - fresh.slip(x)) <= 1e-11 * scale)


def test_a_badly_conditioned_layout_gives_way_to_the_alternate(monkeypatch):
    # at nu = 0, c = 0.05 (alpha = 0.033, below PLANE_PIN_FROM: p's singular family on the stick end is free) gamma^2
    # times the plain system's condition number at the root exceeded CONDITION_LIMIT and the route took the alternate
    # layout, the default one being 9.9e-12 off the median of four finer solves (``reference_mu``). Balanced, the
    # default layout is 1.5e-12 off there (measured) and well conditioned (gamma^2 x 2.1e11): no second solve; bound
    # 1e-11, the level's accuracy. The mechanism itself, forced (CONDITION_LIMIT 0): the alternate layout is solved and
    # kept only if CONDITION_GAIN times better conditioned (never here: 5.5e11 against 8.4e11), and where it is kept
    # (CONDITION_GAIN 0) the route says so and mu is as good
    import numeric.solutions.plane_solver as plane_solver
    from numeric.solutions.plane_solver import ALTERNATE_C_FRACTION, CONDITION_LIMIT
    from numeric.studies.plane_bench import reference_mu
    nu, c = 0.0, 0.05
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = plane.flat_punch(nu=nu, c=c)
    assert "alternate" not in s.route and g * g * s.field.solution.conditioning < CONDITION_LIMIT
    assert abs(s.mu / reference_mu(nu, c) - 1) < 1e-11
    assert s.error >= abs(s.mu - reference_mu(nu, c))
    monkeypatch.setattr(plane_solver, "CONDITION_LIMIT", 0.0)
    assert plane.flat_punch(nu=nu, c=c).mu == s.mu  # tried, not better by CONDITION_GAIN: the default kept
    monkeypatch.setattr(plane_solver, "CONDITION_GAIN", 0.0)
    alternate = plane.flat_punch(nu=nu, c=c)
    assert alternate.field.layout.resolution.c_fraction == ALTERNATE_C_FRACTION and "alternate layout" in alternate.route
    assert abs(alternate.mu / reference_mu(nu, c) - 1) < 1e-11


@pytest.mark.parametrize("nu, c", [(-0.5, 0.9117), (-0.5, 0.925), (-0.008, 0.17)])
def test_the_poles_were_the_free_stick_pressure_family(nu, c):
    # at these (nu, c) (alpha = 0.41, 0.44 next to c_max; 0.048) the default layout was nearly singular at the root
    # (conditioning 1.8e15, 4e13; mu off by 4e-8, 1.5e-9, 2.5e-10): p's singular family on the stick end, free, made a
    # near-null vector concentrated at c. Pinned to 0 (from alpha = 1/4 on for the first two, from 0.04 on for the
    # third, ``numeric.core.stick_pressure_pins.PLANE_PIN_FROM``) the default layout keeps its conditioning (gamma^2 x
    # conditioning below CONDITION_LIMIT, 6.3e10 at the third, so the route stays in it, one solve instead of two) and
    # the route's mu is within 2.5e-13, 3.8e-13, 4.6e-13 of the median of four finer solves (measured; the default
    # layout's own iteration from the reference, 7e-16 at the first); bound 1e-11, the level's accuracy away from poles
    from numeric.solutions.plane_solver import ALTERNATE_C_FRACTION, CONDITION_LIMIT
    from numeric.studies.plane_bench import reference_mu
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = plane.flat_punch(nu=nu, c=c)
    assert s.field.layout.resolution.c_fraction != ALTERNATE_C_FRACTION
    assert g * g * s.field.solution.conditioning < CONDITION_LIMIT
    assert abs(s.mu / reference_mu(nu, c) - 1) < 1e-11


def test_rtol_chooses_the_coarsest_level_that_meets_it():
    # as the axisymmetric flat_punch: the coarsest level whose typical accuracy meets rtol, finer while error >
    # rtol x mu (given c) or c (given mu). Against the median of four finer solves (``reference_mu``): at nu = 0.3,
    # c = 0.5 level 0 is 2.5e-9 off (its estimate 6.5e-9) and level 1 2.3e-11 (estimate 1.4e-10), measured
    from numeric.solutions.solution import AccuracyWarning
    from numeric.studies.plane_bench import reference_mu
    ref = reference_mu(0.3, 0.5)
    for rtol, level in ((1e-6, 0), (1e-8, 1), (1e-10, 2)):
        s = plane.flat_punch(nu=0.3, c=0.5, rtol=rtol)
        assert s.route.startswith(f"solver level {level}") and s.error <= rtol * s.mu
        assert abs(s.mu - ref) <= rtol * ref
    back = plane.flat_punch(nu=0.3, mu=ref, rtol=1e-6)
    assert back.error <= 1e-6 * back.c and abs(back.c - 0.5) <= 1e-6 * 0.5
    assert plane.power_law(2, nu=0.3, c=0.5, rtol=1e-6).flat.route.startswith("solver level 0")
    # the elementwise functions pass it on (level 0 within 1e-6 of the reference, as above)
    assert abs(plane.friction_coefficient(0.5, 0.3, rtol=1e-6) / ref - 1) <= 1e-6
    assert abs(plane.stick_radius(ref, 0.3, rtol=1e-6) / 0.5 - 1) <= 1e-6
    with pytest.warns(AccuracyWarning, match="rtol = 1e-12 not met"):
        plane.flat_punch(nu=0.3, c=0.5, rtol=1e-12)  # below the estimate's floor, 1e-10
    assert plane.flat_punch(nu=0.3, mu=0.0, rtol=1e-14).error == 0.0  # a closed form meets any rtol
    with pytest.raises(ValueError, match="not both"):
        plane.flat_punch(nu=0.3, c=0.5, level=2, rtol=1e-6)
    for bad in (0.0, -1e-6, math.nan, math.inf):
        with pytest.raises(ValueError, match="rtol"):
            plane.flat_punch(nu=0.3, c=0.5, rtol=bad)


def test_the_error_is_formed_on_demand_and_pickled_with_its_value():
    import pickle
    s = plane.flat_punch(nu=0.3, c=0.5)
    assert repr(s._error) == "<formed on first use>"
    copy = pickle.loads(pickle.dumps(s))
    assert copy.error == s.error and copy.mu == s.mu


@pytest.mark.slow
def test_the_guess_table_is_reproduced_by_its_script():
    # regenerating the committed table gives the same file (deterministic: fixed nodes and seed); the script runs in
    # its own process (its worker pool needs its functions importable), about three minutes on two cores
    import os
    import subprocess
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    target = root / "numeric" / "core" / "plane_guess_data.py"
    committed = target.read_text()
    try:
        subprocess.run([sys.executable, str(root / "derivations" / "build_plane_guess.py")], check=True, cwd=root,
                       env={**os.environ, "OPENBLAS_NUM_THREADS": "1"}, capture_output=True)
        assert target.read_text() == committed
    finally:
        target.write_text(committed)


def test_the_stick_width_saturates_below_the_edge():
    # c_max(nu = 0): the limit mu -> inf extrapolated from mu gamma = 1e5, 1e6 against the limit problem solved at
    # theta = pi/2 itself (a different route, degree 20): 2e-13 absolute in 1 - c_max (bound 1e-12)
    from numeric.core.plane_eigenvalue import plane_given_theta
    s = plane.slip_limit(0.0)
    direct = plane_given_theta(math.pi / 2, 0.5, math.log(0.99626 / 0.00374), PlaneResolution(20, 2), step=0.01)
    assert abs(s.gap - direct.layout.gap) < 1e-12
    assert s.error < 1e-12 and s.mu == math.inf
    # c(mu) approaches it from below like 1/mu: (1 - c) - (1 - c_max) = A/(mu gamma), A/(1 - c_max) ~ 1.43 (measured)
    near = plane.flat_punch(nu=0.0, mu=2000.0)
    assert near.c < s.c
    assert 1.2 < (near.gap - s.gap) * 2000.0 * 0.5 / s.gap < 1.7
    # the first-order law would close the slip zone: 8 exp(-pi mu/gamma) is 0 to double precision at mu = 2000
    assert closed.gap_large_mu_plane(2000.0, 0.5) == 0.0


@pytest.mark.parametrize("nu, c", [(0.3, 0.5), (-0.5, 0.9), (0.25, 0.5)])
def test_the_slip_converges(nu, c):
    # the slip u at the default level against degree 26 (layout c_fraction 0.1) inside the slip zone, at the element
    # ends of both layouts (where the chart's anchor changes, (1 + c)/2, the integral's last nodes rounded onto the
    # end: u was NaN there), next to c and at the edge: measured 1e-14 ... 1e-12 with numpy's default and baseline
    # SIMD paths (the strain integral's rule is exact to rounding, tests above; what remains is the solution's error).
    # Not degree 24 in the default layout: at nu = 0.25 it is itself 2e-12 ... 2.3e-11 off, depending on the SIMD path
    # (its mu 1.5e-10 from the other resolutions', see numeric.studies.plane_bench.reference_mu)
    g = (1 - 2 * nu) / (2 - 2 * nu)
    s = plane.flat_punch(nu=nu, c=c)
    fine = PlaneField(plane_given_c(c, 1 - c, g, s.field.theta, PlaneResolution(26, 2, c_fraction=0.1)))
    ends = np.concatenate([f.layout.x_range(e) for f in (s.field, fine) for e in range(len(f.layout))])
    x = np.concatenate([ends[(ends > c) & (ends <= 1.0)],
                        [c + 0.3 * (1 - c), 0.5 * (1 + c), c + 0.7 * (1 - c), 1 - 1e-5, 1.0, np.nextafter(c, 2.0)]])
    got = s.field.slip(x)
    assert np.all(np.isfinite(got)) and np.max(np.abs(got - fine.slip(x))) < 1e-11


def _transformed_strain(field, x):
    """H q - gamma p at x from the transforms of every basis function there: the reference of the interpolated strain."""
    from numeric.core.plane_charts import locate
    return field.transformed_strain(locate(field.layout, x))


def _edge_points(field):
    """50 points across the edge element (chart 0.001 ... 0.999) and 8 toward x = 1 (1 - x down to 1e-8 of its length)."""
    from numeric.core.plane_charts import EDGE
    lay = field.layout
    e = int(np.flatnonzero(lay.kind == EDGE)[0])
    start = 1.0 + lay.origin[e] + lay.sigma[e] * lay.length[e]
    return np.concatenate([start + (1 - start) * np.linspace(0.001, 0.999, 50), 1 - (1 - start) * np.logspace(-8, -1, 8)])


@pytest.mark.parametrize("nu, c", [(-0.5, 0.9), (0.0, 0.99), (0.3, 0.05), (0.499, 0.3), (0.3, 0.9999), (-0.9, 0.86)])
def test_the_interpolated_strain_matches_the_transforms_on_the_slip_elements(nu, c):
    # the strain is interpolated at the slip elements' collocation points (PlaneField.strain): before the edge element
    # in their bases, on it as its singular part from the coefficients and a polynomial. Against H q - gamma p from the
    # transforms of every basis function, relative to max(1, |strain|): at 30 interior points of each element before
    # the edge (chart 0.05 ... 0.95) measured at most 6.4e-13 (nu = 0.3, c = 0.9999; 1.6e-13 elsewhere), on the edge
    # element (``_edge_points``; the strain there up to 1.4e4) 6.3e-13 (nu = 0.45, c = 0.999; 5.2e-14 for 1 - c >=
    # 0.01), over these and eight more (nu, c): the interpolation's conditioning times the rounding of H q where the
    # slip zone is small; bound 3e-12. (Within 1e-6 of an element end before the edge the transforms of the discrete solution carry
    # its small jumps there times a logarithm, up to 3e-9 at nu = 0, c = 0.99; the interpolant has none, and the slip,
    # the integral, is the same to 5e-15: measured over 42 (nu, c) against the transforms at every node;
    # test_the_slip_converges above.)
    from numeric.core.plane_charts import EDGE, SLIP
    field = plane.flat_punch(nu=nu, c=c).field
    lay = field.layout
    inner = [e for e in lay.elements(SLIP) if lay.kind[e] != EDGE]
    assert inner
    for x in [lay.anchor_value(lay.anchor[e]) + lay.origin[e] + lay.sigma[e] * lay.length[e] * np.linspace(0.05, 0.95, 30)
              for e in inner] + [_edge_points(field)]:
        exact = _transformed_strain(field, x)
        assert np.max(np.abs(field.strain(x) - exact) / np.maximum(1.0, np.abs(exact))) < 3e-12


@pytest.mark.parametrize("nu", [0.0, -0.5])
def test_the_edge_strain_at_mu_inf_has_the_logarithm(nu):
    # at theta = pi/2 (the limit problem solved for c_max) the edge exponent alpha - 1/2 is 0: p = 0 there and the
    # singular part of H q is log(s) Q(s) / pi (PlaneField._edge_singular_strain's limit); against the transforms as
    # above: measured 7.9e-14 (nu = 0) and 1.9e-14 of max(1, |strain|), bound 3e-12 as above
    from asymptotics.materials import gamma_from_nu
    from numeric.core.plane_eigenvalue import plane_given_theta
    from numeric.core.plane_guess import gap_max
    from numeric.solutions.plane_solver import PLANE_LEVELS
    g = float(gamma_from_nu(nu))
    gap = gap_max(g)  # the guess table's 1 - c_max: the secant's start
    field = PlaneField(plane_given_theta(0.5 * math.pi, g, math.log((1 - gap) / gap), PLANE_LEVELS[2]))
    assert field.alpha == 0.5
    x = _edge_points(field)
    exact = _transformed_strain(field, x)
    assert np.max(np.abs(field.strain(x) - exact) / np.maximum(1.0, np.abs(exact))) < 3e-12


@pytest.mark.parametrize("nu, c", [(0.45, 0.05), (0.0, 0.99), (-0.9, 0.5)])
def test_the_slip_rule_graded_where_the_strain_is_singular_agrees_with_full_grading(nu, c):
    # the slip integral grades toward c as far as -c is near and toward x only as far as x is near the edge
    # (pieces_toward); against the rule graded fully toward both ends (SLIP_PIECES each) on the same solution: the
    # strain is smooth away from c and 1, so the two agree to rounding (measured 1e-15 of u ~ 0.03-0.17; the sum of
    # ~1000 terms of size |u| at a few ulp each bounds it by 1e-13)
    from numeric.core.plane_fields import pieces_toward
    field = plane.flat_punch(nu=nu, c=c).field
    x = c + (1 - c) * np.array([1e-9, 1e-5, 0.01, 0.3, 0.9, 0.999, 1 - 1e-9, 1.0])
    assert list(pieces_toward((1 - x) / (x - c))[[0, 3, 7]]) == [1, 1, 50]
    s, one_minus_s, w = graded_both_ends()
    length = x - c
    # (nodes that round onto c taken on its slip side, as the slip integral does)
    full = [field.strain(np.maximum(c + d * s, np.nextafter(c, 2.0)), (v - 1.0) - d * one_minus_s) @ w * d
            for v, d in zip(x, length)]
    assert np.max(np.abs(field.slip(x) - np.array(full))) < 1e-13


@pytest.mark.parametrize("nu", [0.0, -0.9])
def test_beyond_mu_gamma_1e6_the_solution_is_linear_in_one_over_mu_gamma(nu):
    # above mu gamma = 1e6 c, q, u come from the limit's two solves (mu gamma = 1e5, 1e6), linear in 1/(mu gamma);
    # against the solver run directly at mu gamma = 1e7 (a different route, which still converges there): measured c
    # 1.6e-12 (nu = 0), 1.5e-12 (-0.9); p, q 1.2e-9, 1.3e-10 of max(1, |.|) next to the edge; u 5e-12, 2e-13. Bounds:
    # c 1e-10 (the level's own accuracy near c_max, README), stresses 5e-9 and u 1e-10 (the direct solve's own error
    # at x = 1 - 1e-5 near c_max: 1e-9)
    from numeric.solutions.plane_solver import solve_given_mu
    g = (1 - 2 * nu) / (2 - 2 * nu)
    mu = 1e7 / g
    s = plane.flat_punch(nu=nu, mu=mu)
    assert s.route.startswith("near the limit")
    direct = solve_given_mu(mu, g, 2).field
    assert abs(s.c - direct.c) < 1e-10
    x = np.array([0.0, 0.5 * s.c, 0.9 * s.c, s.c + 0.1 * s.gap, 0.5 * (1 + s.c), 1 - 1e-5])
    (p, q), (pd, qd) = (s.pressure(x), s.shear(x)), direct.pressure_shear(x)
    assert np.max(np.abs(p - pd) / np.maximum(1.0, np.abs(pd))) < 5e-9
    assert np.max(np.abs(q - qd) / np.maximum(1.0, np.abs(qd))) < 5e-9
    assert np.max(np.abs(s.slip(x) - direct.slip(x))) < 1e-10
    # Coulomb's law on the slip zones exactly (p = |q|/mu, then mu p: two correctly rounded operations, at most 2 ulp
    # = 4.4e-16 on any CPU, bound 1e-15); the stick-slip neighbourhood is refused, not guessed
    assert np.all(np.abs(q[3:]) == pytest.approx(mu * p[3:], rel=1e-15))
    with pytest.raises(ValueError, match="stick-slip point"):
        s.pressure(s.c)


def test_friction_up_to_1e300_reaches_c_max_and_the_cylinder_follows():
    # mu = 1e16 and 1e300: c within the limit's error of c_max (slip_limit), which the solver could not reach (it
    # raised SolverError or gave p(c) = -3017 there); the cylinder on the same field has a finite load
    limit = plane.slip_limit(0.3)
    for mu in (1e16, 1e300):
        s = plane.flat_punch(nu=0.3, mu=mu)
        assert abs(s.gap - limit.gap) <= 2 * limit.error + limit.gap * 1e-9  # the A/(mu gamma) term: 1e-16 of 1 - c
        h = plane.power_law(2, nu=0.3, mu=mu)
        assert math.isfinite(h.load_ratio) and h.load_ratio > 1.0


def test_a_stick_width_above_c_max_is_refused_as_such():
    # nu = -0.9: c_max = 0.866 (plane_strain.md); c = 0.999999 made Newton fail with SolverError
    with pytest.raises(NoEigenvalueError, match="above the largest"):
        plane.flat_punch(nu=-0.9, c=0.999999)


def test_full_stick_to_double_precision_at_small_gamma():
    # nu = 0.45 (gamma = 1/11), mu = 3: 1 - c ~ 1e-40 by the first-order law, far below what c can show; the solver
    # failed (SolverError). Above the friction at 1 - c = 2^-40 = 9.1e-13 the bonded punch is returned, c = 1 - 2^-41
    # +- 2^-41: its stresses against the solver's at 1 - c = 1e-12 were measured within 3.3e-12 (p), 3.8e-12 (q)
    from numeric.solutions.plane_solver import FULL_STICK_GAP, full_stick_friction
    g = 1 / 11
    s = plane.flat_punch(nu=0.45, mu=3.0)
    assert s.route.startswith("full stick") and 0 < s.gap <= s.error and s.gap + s.error <= FULL_STICK_GAP
    edge = plane.flat_punch(nu=0.45, c=1 - FULL_STICK_GAP)
    # the public route and the threshold's own solve start differently: within the estimated error (9e-11 apart)
    assert abs(edge.mu - full_stick_friction(g)) <= edge.error and edge.mu < 3.0
    x = np.array([0.0, 0.5, 0.9, 0.99])
    assert np.max(np.abs(s.pressure(x) - edge.pressure(x))) < 1e-10
    assert np.max(np.abs(s.shear(x) - edge.shear(x))) < 1e-10
    with pytest.raises(ValueError, match="bonded punch"):
        s.pressure(1.0)


def test_between_the_table_and_full_stick_the_secant_starts_near_the_root():
    # nu = 0.45, mu = 0.9: beyond the guess table (1 - c < 1e-8) and below the full-stick friction; log(1 - c) from
    # the table's end and the full-stick solve, linear in log mu, is within 7 % of the solved 1 - c (measured; the
    # first-order law's start was 3 orders off and the secant took 16 solves instead of 8); bound 25 %. The answer
    # satisfies the eigenvalue condition at mu: the given-c solve at that 1 - c (passed exactly: c itself rounds 1 - c
    # by 1e-6 relative here, which moves mu by 4e-8) returns mu within its error.
    from numeric.solutions.plane_solver import FULL_STICK_GAP, full_stick_friction, near_full_stick_gap, solve_given_c
    g = 1 / 11
    s = plane.flat_punch(nu=0.45, mu=0.9)
    start = near_full_stick_gap(0.9, g, full_stick_friction(g), FULL_STICK_GAP)
    assert s.gap < 1e-8 and abs(start / s.gap - 1) < 0.25
    back = solve_given_c(s.c, s.gap, g, 2)
    assert abs(back.field.mu - 0.9) <= back.error.value()


def test_the_cylinder_slip_frictionless_against_mpmath():
    # mu = 0: u = n x^n int_x^1 t^(-n-1) u0(t) dt with Sadowsky's u0 = -(gamma/pi) asin t, by mpmath at 30 digits:
    # measured 7e-18 (bound 1e-15: the edge rule's rounding on values ~0.05)
    h = plane.power_law(2, nu=0.3, mu=0.0)
    x = np.array([1e-6, 0.1, 0.5, 0.9, 0.999, 1.0])
    with mpmath.workdps(30):
        ref = [float(2 * mpmath.mpf(v) ** 2 * mpmath.quad(lambda t: t**-3 * (-GAMMA_03 / mpmath.pi) * mpmath.asin(t),
                                                           [v, 1])) for v in x]
    assert np.max(np.abs(h.slip(x) - np.array(ref))) < 1e-15
    assert np.all(h.slip(-x) == -h.slip(x))


def test_the_cylinder_slip_with_friction():
    # the accumulated slip u = n x^n int_x'^1 t^(-n-1) u0 dt is computed by parts on the strain; independently,
    # d(u/x^n)/dx = -n u0(x)/x^(n+1) on the slip zone, u0 the strip punch's slip at that one point: central
    # differences of steps 1e-3 and 5e-4, Richardson-extrapolated (error O(h^4): measured 2.6e-11 at x = 0.8 and
    # 2.8e-10 at 0.95, whose u0 bends toward the edge; rounding 1e-17 of u ~ 5e-3 over 2h: 1e-14; bound 1e-9); the
    # stick zone keeps u = C x^n ([S75] (3.4)); the point at the edge has just come into contact (u = 0)
    h = plane.power_law(2, nu=0.3, mu=0.3)

    def central(x, step):
        up, down = h.slip(np.array([x + step, x - step]))
        return (up / (x + step) ** 2 - down / (x - step) ** 2) / (2 * step)

    for x in (0.8, 0.95):
        derivative = (4 * central(x, 5e-4) - central(x, 1e-3)) / 3
        assert derivative == pytest.approx(-2 * float(h.flat.slip(x)) / x**3, rel=1e-9)
    u = h.slip(np.array([0.1, 0.3, 0.8]))
    assert u[0] / 0.1**2 == pytest.approx(u[1] / 0.3**2, rel=1e-12) and np.all(u < 0)
    assert h.slip(1.0) == 0.0
    with pytest.raises(NotImplementedError):
        plane.power_law(2, nu=0.3, mu=0.01).slip(0.5)  # the law route below c = 1e-5 does not compute the slip


def test_the_slip_limit_beyond_the_solvers_reach_is_the_small_gamma_form():
    # Where 1 - c_max < 2^-40 (gamma < ~0.157) the limit problem is not solved: largest_stick_radius(0.45) took 30 s,
    # 0.47 149 s and 1.6 GB, 0.49 > 900 s, and 0.499 raised "math domain error" (1 - c_max underflowed in the start).
    # Now the closed form: c = 1 - (1 - c_max) with 1 - c_max from the limit problem's small-gamma form
    # (numeric.core.plane_guess.gap_max_small_gamma) and its error bound, the bonded punch's stresses, no layout.
    from numeric.core.plane_guess import gap_max_small_gamma
    from numeric.solutions.plane_solver import FULL_STICK_GAP
    for nu in (0.41, 0.45, 0.47, 0.49, 0.499, 0.4999999, 0.5):
        s = plane.slip_limit(nu)
        assert s.route.startswith("limit mu -> inf") and not hasattr(s.field, "n_unknowns")
        assert s.gap == gap_max_small_gamma(s.gamma) < FULL_STICK_GAP and s.c == 1.0 - s.gap and s.mu == math.inf
        assert 0.0 <= s.error <= 3e-3 * s.gap and plane.largest_stick_radius(nu) == s.c  # expm1(2e-5/atanh(gamma))
    assert plane.largest_stick_radius(0.499) == 1.0 and plane.slip_limit(0.4999999).c == 1.0


def test_the_small_gamma_form_of_c_max_meets_the_solver_and_the_table():
    # The hand-over: at gamma = 0.157 (1 - c_max = 9.2e-13, just above 2^-40) the limit problem is solved (1720
    # unknowns at level 2, the most the route meets: the count grows as 1 - c_max falls, bounded here by the switch);
    # the form there within its stated error of the solve (measured 3.2e-9 relative, stated 1.3e-4), so no jump where
    # the closed form takes over, just below. The table's series (level-2 solves, 0.16 ... 0.75, built separately) is
    # met within the form's error at 0.16, 0.2 and 0.3 (measured 2.4e-9, 5.8e-8, 1.5e-8 relative; stated
    # 1.2e-4 ... 6.5e-5).
    from numeric.core.plane_guess import gap_max, gap_max_relative_error, gap_max_small_gamma
    solved = plane.slip_limit(gamma=0.157)
    assert solved.route.startswith("limit mu -> inf (slip zones") and solved.field.n_unknowns <= 1720
    form = gap_max_small_gamma(0.157)
    assert abs(form - solved.gap) <= form * gap_max_relative_error(0.157) + solved.error
    below = plane.slip_limit(gamma=0.1565)
    assert below.route.startswith("limit mu -> inf: 1 - c_max") and below.gap < solved.gap
    for g in (0.16, 0.2, 0.3):
        assert abs(gap_max_small_gamma(g) / gap_max(g) - 1.0) <= gap_max_relative_error(g)


@pytest.mark.slow
@pytest.mark.parametrize("g", [0.13, 0.14, 0.15])
def test_the_small_gamma_form_of_c_max_meets_the_limit_problem_below_the_table(g):
    # The form against the limit problem solved at level 3 below the table's band (three of the 13 gamma it was fitted
    # to; 4-6 s each): measured within 3.4e-8 relative in 1 - c_max; bound: the form's stated error (1.3e-4 ... 1.5e-4)
    from numeric.core.plane_guess import gap_max_relative_error, gap_max_small_gamma
    from numeric.solutions.plane_solver import solve_limit
    solved = solve_limit(g, 3)
    assert abs(gap_max_small_gamma(g) / solved.gap_limit - 1.0) <= gap_max_relative_error(g)


def test_a_stick_width_at_c_max_to_rounding_is_the_slip_limit():
    # nu = 0.49, c = 1 - 2^-53: c_max = 1 - 1.7e-108 is 1 to rounding, and c lies within 4 ulp of it: the answer is
    # the slip limit, mu = inf, as the axisymmetric numeric.flat_punch gives (it took 14 s and raised
    # NoEigenvalueError "at gamma = 0.14", a gamma of the small-gamma series' nodes, not 0.0196)
    import numeric
    c = 0.9999999999999999
    for nu in (0.49, 0.4898, 0.499, 0.4999999, 0.5 - 1e-12):
        s = plane.flat_punch(nu=nu, c=c)
        assert s.mu == math.inf and s.route.startswith(f"c = {c!r} is c_max to rounding")
        assert s.c == plane.slip_limit(nu).c
    assert numeric.flat_punch(nu=0.49, c=c).mu == math.inf
    # farther from c_max than rounding: a finite mu (the solver at gamma itself, see test_plane_small_gamma)
    assert math.isfinite(plane.flat_punch(nu=0.49, c=1 - 1e-15).mu)
    # above c_max, the error names the problem's gamma
    with pytest.raises(NoEigenvalueError, match="gamma = 0.15:"):
        plane.flat_punch(gamma=0.15, c=1 - 1e-14)  # 1 - c_max = 2.1e-13 there


def test_level_is_validated_as_the_axisymmetric_api_does():
    # level=3.0 and np.int64(3) were refused ("must be an integer from 0 to 4, got np.int64(3)"); the plane API takes
    # the axisymmetric check (numeric.solutions.flat_punch.check_level), over the same number of levels
    from numeric.core.charts import RESOLUTIONS
    from numeric.solutions.plane_solver import PLANE_LEVELS
    assert len(PLANE_LEVELS) == len(RESOLUTIONS)
    ref = plane.flat_punch(nu=0.3, mu=0.3, level=3).c
    assert plane.flat_punch(nu=0.3, mu=0.3, level=3.0).c == ref
    assert plane.stick_radius(0.3, 0.3, level=np.int64(3)) == ref
    assert plane.slip_limit(0.3, level=np.int64(2)).c == plane.slip_limit(0.3).c
    with pytest.raises(ValueError, match="level"):
        plane.flat_punch(nu=0.3, mu=0.3, level=2.5)
    with pytest.raises(TypeError, match="level"):
        plane.flat_punch(nu=0.3, mu=0.3, level="2")


def test_nu_and_gamma_and_x_are_validated_as_flat_punch_does():
    # stick_radius(mu, nu, gamma=...) silently took gamma; gamma="0.2" was taken; stick_radius(0.3) said "nu must be a
    # real number ..., got None"; pressure(True) was inf where the axisymmetric solution raises TypeError
    with pytest.raises(ValueError, match="exactly one of nu"):
        plane.stick_radius(0.3, 0.3, gamma=0.2)
    with pytest.raises(ValueError, match="exactly one of nu"):
        plane.stick_radius(0.3)
    with pytest.raises(ValueError, match="exactly one of nu"):
        plane.friction_coefficient(0.5)
    with pytest.raises(TypeError, match="gamma"):
        plane.stick_radius(0.3, gamma="0.2")
    with pytest.raises(ValueError, match="gamma"):
        plane.stick_radius(0.3, gamma=0.8)
    s = plane.flat_punch(nu=0.3, mu=0.3)
    for f in (s.pressure, s.shear, s.slip, plane.power_law(2, nu=0.3, mu=0.3).pressure):
        with pytest.raises(TypeError, match="x must be"):
            f(True)
        with pytest.raises(TypeError, match="x must be"):
            f([True, False])


def test_the_law_routes_refusal_at_the_centre_says_what_it_gives():
    # flat_punch(nu=0.3, mu=1e-300).pressure(0) said "x = 0 lies within 100 c ... c = 0 ... at |x| >= 0 only"
    s = plane.flat_punch(nu=0.3, mu=1e-300)
    assert s.c == 0.0
    with pytest.raises(ValueError, match=r"x != 0 only \(c underflows to 0") as raised:
        s.pressure(0.0)
    assert "|x| >= 0" not in str(raised.value)
    small = plane.flat_punch(nu=0.3, mu=0.01)
    with pytest.raises(ValueError, match=r"\|x\| >= .* \(100 c\) only"):
        small.pressure(0.5 * small.c)


@pytest.mark.parametrize("n", [1e-3, 0.5, 1.0, 1.5, 2.0, 3.0, 10.0, 100.0])
def test_power_law_stresses_are_right_down_to_the_centre(n):
    # (3.13) on Sadowsky's punch against mpmath (30 digits, in s = log(t/x): p = n int_0^log(1/x) e^((1-n)s) p0(x e^s)
    # ds, smooth but for the edge's square root at the top, a tanh-sinh end; split at log(1/x) - 1): the quadrature's
    # weight t^-n overflowed below x = exp(-709/n) (NaN at x = 1e-3 for n = 100) and the rule did not resolve x below
    # ~1e-16 (p(1e-100) = 2e-35 for n = 2, against 0.6366); now the weights as (x_ref/t)^n and, below x = 1e-12, the
    # values there carried to x by the centre's behaviour (PlanePowerLawSolution._near_centre). Measured 1e-16 ...
    # 2e-13 relative (n = 100: the weight's exp(n log(x_ref/t)) rounding); bound 1e-12
    def reference(x):
        with mpmath.workdps(30):
            x = mpmath.mpf(x)
            top = -mpmath.log(x)

            def integrand(v):
                t = x * mpmath.exp(v)
                return mpmath.exp((1 - n) * v) / (mpmath.pi * mpmath.sqrt((1 - t) * (1 + t)))
            return float(n * mpmath.quad(integrand, [0, max(top - 1, 0), top]))
    h = plane.power_law(n, nu=0.3, mu=0.0)
    x = np.array([1e-300, 1e-100, 1e-20, 1e-12 * (1 - 1e-9), 1e-12, 1e-8, 1e-2, 0.6])
    got = h.pressure(x)
    want = np.array([reference(v) for v in x])
    assert np.all(np.abs(got / want - 1.0) <= 1e-12)
    # with friction (the solver's field): finite, continuous where the centre's form takes over
    f = plane.power_law(n, nu=0.3, mu=0.3)
    below, at = f.pressure(np.array([np.nextafter(1e-12, 0.0), 1e-12]))
    assert np.all(np.isfinite(f.pressure(x))) and np.all(np.isfinite(f.shear(x))) and abs(below / at - 1) < 1e-12


def test_power_law_exponent_range_is_the_axisymmetric_one():
    # n = 1000 gave pressure NaN; n = 1e300 with mu = inf a load ratio of -1.24: refused beyond numeric.power_law's
    # N_RANGE (1e-300 ... 100), with the same reason
    from numeric.solutions.power_law import N_RANGE
    for n in (100.0000001, 1000, 1e300):
        with pytest.raises(ValueError, match="n \\(power-law exponent\\) must lie in"):
            plane.power_law(n, nu=0.3, mu=0.3)
    for n in N_RANGE:
        h = plane.power_law(n, nu=0.3, mu=math.inf)
        assert math.isfinite(h.load_ratio) and h.load_ratio > 0.0


@pytest.mark.parametrize("gap", [1e-13, 1e-14, 1e-15])
def test_the_slip_is_finite_on_a_slip_zone_of_a_few_ulp(gap):
    # nu = 0.45, 1 - c <= 1e-13 (c_max = 1 - 1e-22 there): u was NaN. The slip zone holds elements of ~20 ulp of x; the
    # nodes next to their ends were moved by 1e-13 (beyond x = 1) and the owner of a node was found from the rounded
    # x. Now from x - 1 (exact). Against the same strain integrated by the rule graded fully toward both ends
    # (SLIP_PIECES each), the nodes placed by their exact offsets: measured 3e-16 ... 5.6e-14 relative; bound 1e-12 (the
    # graded rules' own agreement at ordinary c is 1e-13 of |u|, test above, here on a |u| of 1e-9); and u(1)
    # inward, |u(1)|/sqrt(1 - c) = 0.041, 0.045, 0.050 continuing the trend of 1 - c = 1e-10 ... 1e-12 (0.034, 0.036,
    # 0.038: +0.003 ... +0.005 a decade), checked loosely: between 0.03 and 0.06
    s = plane.flat_punch(nu=0.45, c=1 - gap)
    f = s.field
    fracs = (1.0, 0.3, 0.7)  # not at element ends (0.25, 0.5, 0.75 of the zone), where the reference would need them
    x = np.array([f.c + frac * f.gap if frac < 1.0 else 1.0 for frac in fracs])
    u = s.slip(x)
    assert np.all(np.isfinite(u)) and np.all(u < 0.0)
    nodes, one_minus, w = graded_both_ends()
    full = []
    for v in x:  # x as the double it is (it rounds by up to 1e-3 of a 1e-13 zone): x - c and x - 1 are exact
        length = v - f.c
        from_one = (v - 1.0) - length * one_minus
        t = np.maximum(f.c + length * nodes, np.nextafter(f.c, 2.0))
        full.append(f.strain(t, from_one) @ w * length)
    assert np.max(np.abs(u - np.array(full)) / np.abs(u)) <= 1e-12
    assert 0.03 < -u[0] / math.sqrt(f.gap) < 0.06
