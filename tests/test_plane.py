"""The plane-strain strip punch and cylinder with friction (``asymptotics.plane``, ``numeric.plane``).

Each check names its independent source: mpmath quadrature at 30 digits, SymPy, the closed
limits, convergence between resolution levels, the first-order law's measured order.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy import special

from asymptotics import plane as closed
from numeric import plane
from numeric.core.plane_cauchy import element_cauchy
from numeric.core.plane_system import PLANE_RESOLUTIONS, solve_plane_given_c


def _cauchy_mp(lam, k, y):
    with mpmath.workdps(30):
        lam, y = mpmath.mpf(lam), mpmath.mpf(y)
        f = lambda s: s**lam * mpmath.legendre(k, 2 * s - 1)  # noqa: E731
        if 0 < y < 1:
            g = lambda s: (f(s) - f(y)) / (s - y) if s != y else mpmath.diff(f, y)  # noqa: E731
            return mpmath.quad(g, [0, y, 1]) + f(y) * mpmath.log((1 - y) / y)
        return mpmath.quad(lambda s: f(s) / (s - y), [0, 1])


@pytest.mark.parametrize("lam", [0.0, 0.3, -0.3, 0.002, -0.4999])
def test_element_cauchy_transforms_against_mpmath(lam):
    # 30-digit quadrature; 2e-12 of max(1, |I|): the subtracted rule loses up to 3 digits to P_k(y) ~ 1.56^k
    # just outside the element (measured worst 5e-13 over these exponents and points)
    y = np.array([-3.0, -0.04, 1e-9, 0.3, 0.51, 0.999999, 1.03, 3.0])
    got = element_cauchy(lam, 12, y)
    for i, yi in enumerate(y):
        for k in (0, 5, 12):
            ref = float(_cauchy_mp(lam, k, yi))
            assert abs(got[i, k] - ref) <= 2e-12 * max(1.0, abs(ref)), (lam, yi, k)


def test_local_exponent_at_the_stick_slip_point():
    # amplitudes a (q - mu p, stick side), b (p, stick), d (p, slip) of |x - c|^lam; C = cot(pi lam), S = 1/sin(pi lam)
    g, m, C, S = sp.symbols("gamma mu C S")
    M = sp.Matrix([[g, C + g * m, -S], [0, S, g * m - C], [C, m * C - g, -m * S]])
    det = sp.expand(M.det()).subs(S**2, 1 + C**2)
    assert sp.factor(sp.expand(det)) == sp.factor(-(C - g * m) * (g - 1) * (g + 1))  # cot(pi lam) = mu gamma


def test_bonded_index_is_abramovs():
    nu = sp.symbols("nu")
    gamma = (1 - 2 * nu) / (2 - 2 * nu)
    assert sp.simplify((1 + gamma) / (1 - gamma) - (3 - 4 * nu)) == 0
    assert closed.bonded_index(0.5) == pytest.approx(math.log(3.0) / (2 * math.pi), rel=1e-15)


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
    assert 1 - closed.stick_width_first_order(4.0, 0.5) == pytest.approx(closed.gap_large_mu_plane(4.0, 0.5), rel=1e-10)


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


@pytest.fixture(scope="module")
def punch():
    return plane.flat_punch(nu=0.3, c=0.5)


def test_levels_converge(punch):
    # level 3 is the reference: the default (level 2) agrees to 3e-10 relative (measured 6.6e-10 ... 7e-11 over
    # nu = 0, 0.3, 0.45 and c = 0.3, 0.5, 0.8 in the study that chose the levels)
    fine = solve_plane_given_c(0.5, punch.gamma, punch.mu, PLANE_RESOLUTIONS[3])
    assert abs(fine.mu - punch.mu) <= 1e-9 * punch.mu
    assert punch.error <= 1e-8


def test_given_mu_inverts_given_c(punch):
    back = plane.flat_punch(nu=0.3, mu=punch.mu)
    assert back.c == pytest.approx(0.5, abs=1e-8)


def test_the_solution_satisfies_the_friction_conditions(punch):
    x = np.linspace(0.0, 0.5, 41)[1:-1]
    p, q = punch.pressure(x), punch.shear(x)
    assert np.all(q < punch.mu * p) and np.all(p > 0)  # stick: |q| < mu p
    assert punch.shear(0.5) == pytest.approx(punch.mu * punch.pressure(0.5), rel=1e-6)  # q -> mu p at c
    xs = np.array([0.6, 0.8, 0.95])
    assert np.all(punch.slip(xs) < 0) and np.all(punch.slip(-xs) > 0)  # slip inward
    assert np.all(punch.slip(x) == 0.0)
    assert punch.shear(-0.3) == -punch.shear(0.3) and punch.pressure(-0.3) == punch.pressure(0.3)


def test_first_order_law_error_is_order_gamma_squared():
    # (mu / mu_first - 1) / gamma^2 is the same at two small gamma (measured 0.70 at nu = 0.45, c = 0.5)
    ratios = []
    for nu in (0.45, 0.48):
        g = (1 - 2 * nu) / (2 - 2 * nu)
        mu = plane.flat_punch(nu=nu, c=0.5).mu
        ratios.append((mu / (g * float(closed.mu_over_gamma_plane(0.5))) - 1) / g**2)
    assert ratios[0] == pytest.approx(ratios[1], rel=0.05)


def test_frictionless_limits_are_exact():
    s = plane.flat_punch(nu=0.3, mu=0.0)
    x = np.array([0.0, 0.5, 0.99])
    assert np.allclose(s.pressure(x), 1 / (np.pi * np.sqrt(1 - x**2)), rtol=1e-15, atol=0.0)  # rounding only
    h = plane.power_law(2, nu=0.3, mu=0.0)
    # the (3.13) quadrature drops the tanh-sinh nodes that round onto x = 1: ~2 sqrt(1e-16) of the edge mass
    assert np.allclose(h.pressure(x[:2]), 2 / np.pi * np.sqrt(1 - x[:2] ** 2), atol=2e-8)
    assert h.load_ratio == 1.0


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="exactly one of mu"):
        plane.flat_punch(nu=0.3)
    with pytest.raises(ValueError, match="nu"):
        plane.flat_punch(nu=0.7, c=0.5)
    with pytest.raises(ValueError, match="c "):
        plane.flat_punch(nu=0.3, c=1.5)
    with pytest.raises(TypeError, match="x must be"):
        plane.flat_punch(nu=0.3, mu=0.0).pressure("a")
    with pytest.raises(ValueError, match="x "):
        plane.flat_punch(nu=0.3, mu=0.0).pressure(1.5)
