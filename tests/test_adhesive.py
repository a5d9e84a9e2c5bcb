"""Adhesive closed forms (App. B, (4.10), (4.18)) against independent mpmath/scipy evaluations."""

import math

import mpmath
import numpy as np
import pytest
from scipy import integrate

from asymptotics.adhesive import (
    central_pressure_adhesive,
    compliance_adhesive,
    pressure_adhesive,
    pressure_adhesive_mp,
    psi1,
    psi1_mp,
    shear_adhesive,
    shear_adhesive_mp,
    shear_slope_adhesive,
    sphere_A_adhesive,
    sphere_C_adhesive,
    sphere_central_pressure_adhesive,
    sphere_pressure_slope_adhesive,
)
from asymptotics.materials import gamma_from_nu, kappa_from_gamma

GAMMAS = [0.5, 3 / 7, 1 / 3, 0.2, 1e-3, 0.74]
POINTS = [1e-9, 1e-3, 0.1, 0.5, 0.9, 0.999, 1 - 1e-8, 1 - 1e-13]


@pytest.mark.parametrize("gamma", GAMMAS)
def test_b3_quadrature_against_mpmath(gamma):
    # Gauss-Legendre (160 nodes, after the tau/psi substitutions) against tanh-sinh at 30 digits
    # on the untransformed (B3). Tolerance from the operation count: 160 terms summed, each rounded to
    # eps = 2.2e-16, amplified ~3x by the substitution where p ~ (1-x)^(-1/2) (x = 1 - 1e-13): 1.1e-13.
    # Measured worst 4e-14 here and 5.4e-14 on a CPU with AVX-512 summation (a 5e-14 bound failed there).
    x = np.array(POINTS)
    p, q = pressure_adhesive(x, gamma), shear_adhesive(x, gamma)
    p_ref = np.array([float(pressure_adhesive_mp(xi, gamma)) for xi in x])
    q_ref = np.array([float(shear_adhesive_mp(xi, gamma)) for xi in x])
    tol = 160 * 2.2e-16 * 3
    assert np.max(np.abs(p / p_ref - 1)) < tol
    assert np.max(np.abs(q / q_ref - 1)) < tol


def test_b3_limits_at_the_centre():
    # (4.10): p(x) = p(0) + O(x^2), q(x)/x = kappa p(0)/2 + O(x^2); at x = 1e-4 the O(x^2)
    # terms are ~1e-8 relative, so 1e-7 separates a right limit from a wrong one.
    for gamma in (0.5, 0.2):
        assert pressure_adhesive(1e-4, gamma) == pytest.approx(central_pressure_adhesive(gamma), rel=1e-7)
        assert shear_adhesive(1e-4, gamma) / 1e-4 == pytest.approx(shear_slope_adhesive(gamma), rel=1e-7)
    assert pressure_adhesive(0.0, 0.5) == central_pressure_adhesive(0.5)
    assert shear_adhesive(0.0, 0.5) == 0.0


def _residuals_of_2_2(gamma: float, x: float) -> tuple[float, float]:
    """(2.2a) - 1 and (2.2b) for the (B3) stresses, all integrals by mpmath tanh-sinh.

    t = x + s^2 (upper) and t = x - s^2 (lower) remove the inverse square roots; the upper
    range is split geometrically towards t = 1, where p, q ~ (1-t)^(-1/2) oscillate.
    """
    p = lambda t: float(pressure_adhesive(float(t), gamma))  # noqa: E731
    q = lambda t: float(shear_adhesive(float(t), gamma))  # noqa: E731
    s_top = math.sqrt(1 - 1e-15 - x)
    splits = [0.0] + [math.sqrt((1 - x) * (1 - 4.0**-k)) for k in range(1, 12)] + [s_top]
    up = lambda f: mpmath.quad(lambda s: 2 * f(x + s * s) / mpmath.sqrt(2 * x + s * s), splits)  # noqa: E731
    down = lambda f: mpmath.quad(lambda s: 2 * f(x - s * s) / mpmath.sqrt(2 * x - s * s), [0, math.sqrt(x)])  # noqa: E731
    upper_p = up(lambda t: t * p(t))
    upper_q = up(q)
    lower_p = down(lambda t: t * p(t))
    lower_q = down(q)
    total_q = mpmath.quad(q, [0, x]) + mpmath.quad(lambda s: 2 * s * q(x + s * s), splits)
    a = upper_p - gamma * (total_q - x * lower_q) - 1
    b = x * upper_q - gamma * lower_p
    return float(a), float(b)


@pytest.mark.parametrize("gamma, x", [(0.5, 0.3), (0.2, 0.8)])
def test_b3_solves_the_governing_equations(gamma, x):
    # The adhesive stresses must satisfy (2.2) with w* = 1 and u* = 0 everywhere (c = 1).
    # The integrals stop at 1 - eps, eps = 1e-15 (p(1 - eps) is the last double below 1);
    # as p, q ~ amplitude (1-t)^(-1/2), the part cut off is at most
    # 2 sqrt(eps) amplitude / sqrt(1 - x^2) per integral, ~3e-8: the tolerance is twice that.
    eps = 1e-15
    edge = np.array([1 - 1e-6, 1 - 1e-9, 1 - 1e-12])
    amplitude = np.max(np.sqrt(1 - edge) * np.maximum(pressure_adhesive(edge, gamma), np.abs(shear_adhesive(edge, gamma))))
    cut = 2 * math.sqrt(eps) * amplitude / math.sqrt(1 - x * x) * (1 + gamma)
    a, b = _residuals_of_2_2(gamma, x)
    assert abs(a) < 2 * cut
    assert abs(b) < 2 * cut


# QUADPACK flags "roundoff" on the log-periodic oscillation at the edge; the asserted error
# estimate and the comparison with the exact value are the checks.
@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@pytest.mark.parametrize("gamma", [0.5, 1 / 3, 0.05])
def test_b4_against_direct_quadrature_of_b3(gamma):
    # (B4) P0* = pi kappa/(2 gamma) against (pi/2) int_0^1 x p0(x) dx of the (B3) pressure.
    # x = 1 - s^2 removes the inverse square root; 1e-10 is scipy quad's reached accuracy here.
    def integrand(s):
        x = 1.0 - s * s
        return 2.0 * s * x * pressure_adhesive(x, gamma) if x < 1.0 else 0.0

    value, err = integrate.quad(integrand, 0.0, 1.0, limit=200, epsabs=1e-13, epsrel=1e-13)
    assert err < 1e-11
    assert 0.5 * math.pi * value == pytest.approx(compliance_adhesive(gamma), abs=1e-10)
    assert compliance_adhesive(gamma) == pytest.approx(math.pi * kappa_from_gamma(gamma) / (2 * gamma), rel=1e-14)


def test_b4_errata_table():
    # P* and p0(0) against the 12-digit table of errata.md (computed there from the closed forms).
    table = {0.0: (1.09861228867, 0.807595599478), 0.125: (1.06900585385, 0.753231113033),
             0.25: (1.03972077084, 0.702058180676), 0.375: (1.01366277027, 0.658624682925)}
    for nu, (p_star, p0) in table.items():
        g = gamma_from_nu(nu)
        assert compliance_adhesive(g) == pytest.approx(p_star, abs=1e-11)
        assert central_pressure_adhesive(g) == pytest.approx(p0, abs=1e-12)


def test_frictionless_limit_gamma_zero():
    # gamma -> 0: P* -> 1, p0(0) -> 2/pi, and p0(x) -> (2/pi)(1 - x^2)^(-1/2) (2.26).
    assert compliance_adhesive(0.0) == 1.0
    assert central_pressure_adhesive(0.0) == pytest.approx(2 / math.pi, rel=1e-16)
    x = np.array([0.2, 0.7, 0.99])
    assert np.allclose(pressure_adhesive(x, 0.0), 2 / np.pi / np.sqrt(1 - x**2), rtol=1e-14, atol=0)
    assert np.all(shear_adhesive(x, 0.0) == 0.0)


@pytest.mark.parametrize("kappa", [0.0, 0.1, 0.349699152566, 0.6, 1.5])
def test_psi1_digamma_form_against_eta_series(kappa):
    # Digamma closed form against direct summation of sum (-1)^n (kappa/2)^(2n) eta(2n+1) at 30 digits.
    assert psi1(kappa) == pytest.approx(float(psi1_mp(kappa)), rel=2e-15)
    assert psi1(0.0) == pytest.approx(math.log(2), rel=1e-15)  # Psi1(0) = log 2 (4.18)


def test_sphere_constants_4_18():
    # 1/A against the errata table (9 digits) and C in the paper's nu form.
    for nu, inv_a in {0.0: 0.918498211, 0.125: 0.942629687, 0.25: 0.966784733, 0.375: 0.988516228}.items():
        g = gamma_from_nu(nu)
        assert 1 / sphere_A_adhesive(g) == pytest.approx(inv_a, abs=1e-9)
        kappa = math.log(3 - 4 * nu) / math.pi
        c_paper_form = -(2 / 3) * kappa**2 * math.sqrt(3 - 4 * nu) / (1 - 2 * nu)  # (4.18) as printed
        assert sphere_C_adhesive(g) == pytest.approx(c_paper_form, rel=1e-13)
    assert sphere_A_adhesive(0.0) == 1.0 and sphere_C_adhesive(0.0) == 0.0  # Hertz: A = 1, no slip


@pytest.mark.filterwarnings("ignore::scipy.integrate.IntegrationWarning")
@pytest.mark.parametrize("gamma", [0.5, 0.25])
def test_b6_against_the_quadrature_3_13(gamma):
    # (3.13) with n = 2: p(x) = 2 x int_x^1 t^-2 p0(t) dt, so p(0) = 2 p0(0) and
    # p'(0) = -2 [p0(0) - int_0^1 (p0(t) - p0(0)) / t^2 dt]. Compare (B6) with that
    # quadrature of the (B3) pressure (1e-9: scipy quad on the t = 1 - s^2 form).
    p_centre = central_pressure_adhesive(gamma)

    def integrand(s):
        t = 1.0 - s * s
        return 2.0 * s * (pressure_adhesive(t, gamma) - p_centre) / t**2 if t < 1.0 else 0.0

    value, err = integrate.quad(integrand, 0.0, 1.0, limit=200, epsabs=1e-12, epsrel=1e-12)
    assert err < 1e-10
    assert sphere_pressure_slope_adhesive(gamma) == pytest.approx(-2.0 * (p_centre - value), abs=1e-9)
    assert sphere_central_pressure_adhesive(gamma) == 2.0 * p_centre


def test_paper_values_of_b6():
    # §4.2 quotes p(0) = 1.615192 and p'(0) = -.282415 at nu = 0 (6 digits).
    assert sphere_central_pressure_adhesive(0.5) == pytest.approx(1.615192, abs=1e-6)
    assert sphere_pressure_slope_adhesive(0.5) == pytest.approx(-0.282415, abs=1e-6)


@pytest.mark.parametrize("x", [1.0, -0.1, float("nan")])
def test_stresses_reject_x_outside_the_contact(x):
    with pytest.raises(ValueError, match="x"):
        pressure_adhesive(x, 0.5)
