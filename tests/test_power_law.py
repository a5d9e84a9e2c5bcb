"""Tests of numeric.solutions.power_law ([S75] §3): closed forms, (4.18), mpmath oracles.

Reference flat solutions are built from the closed forms: the Boussinesq pressure (2.26)
and the adhesive solution of Appendix B (asymptotics.adhesive, accurate to ~1e-14
relative for x < 1 - 1e-13). Tolerances are a few hundred ulps of O(1) quantities
unless stated; the measured errors are quoted next to each.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from asymptotics import adhesive
from asymptotics.first_order import frictionless_pressure
from numeric.solutions import power_law as pl

BREAKPOINTS = np.concatenate([[0.0, 0.5], 1.0 - 0.5 * 0.25 ** np.arange(1, 26), [1.0]])


class AdhesiveFlat:
    """Fully adhesive flat punch (App. B) in the FlatStresses protocol.

    p0 and q0 come from one (B3) quadrature; the last call is memoised because the
    module always asks for both at the same nodes.
    """

    def __init__(self, gamma: float):
        self.gamma = gamma
        self.mu = math.inf
        self.c = 1.0
        self.compliance = float(adhesive.compliance_adhesive(gamma))
        self.breakpoints = BREAKPOINTS
        self._memo: tuple[bytes | None, tuple | None] = (None, None)

    def _both(self, x):
        x = np.asarray(x, dtype=float)
        key = x.tobytes() + bytes(str(x.shape), "ascii")
        if self._memo[0] != key:
            p = np.asarray(adhesive.pressure_adhesive(x, self.gamma))
            q = np.asarray(adhesive.shear_adhesive(x, self.gamma))
            self._memo = (key, (p, q))
        return self._memo[1]

    def pressure(self, x):
        return self._both(x)[0]

    def shear(self, x):
        return self._both(x)[1]


class SmoothFlat:
    """Frictionless flat punch, p0 = (2/pi)(1 - x^2)^(-1/2) (2.26), q0 = 0."""

    gamma = 0.5
    mu = 0.0
    c = 0.0
    compliance = 1.0
    breakpoints = BREAKPOINTS

    def pressure(self, x):
        return np.asarray(frictionless_pressure(x))

    def shear(self, x):
        return np.zeros_like(np.asarray(x, dtype=float))


@pytest.fixture(scope="module")
def adhesive_half():
    return AdhesiveFlat(0.5)  # nu = 0


def test_protocol():
    assert isinstance(SmoothFlat(), pl.FlatStresses)
    assert isinstance(AdhesiveFlat(0.2), pl.FlatStresses)


# ---------------------------------------------------------------- frictionless
X = np.array([1e-300, 1e-8, 1e-3, 0.1, 0.5, 0.9, 0.99, 1 - 1e-6, 1 - 1e-10, 1 - 1e-13, 1 - 1e-15, 1.0])


def test_sphere_frictionless_319():
    # (3.19). Measured max error 9e-16; 1e-14 allows for the edge model (O(s_e) = 1e-13
    # relative to a (1 - x)^(1/2) that is itself 1e-7 there).
    x = np.concatenate([[0.0], X])
    p = pl.power_law_pressure(SmoothFlat(), 2, x)
    np.testing.assert_allclose(p, 4 / np.pi * np.sqrt((1 - x) * (1 + x)), rtol=0, atol=1e-14)
    assert pl.power_law_pressure(SmoothFlat(), 2, 0.0) == pytest.approx(4 / np.pi, rel=1e-15)  # (3.18)
    np.testing.assert_array_equal(pl.power_law_shear(SmoothFlat(), 2, x), 0.0)


def test_cone_frictionless_320():
    # (3.20), p = (2/pi) log((1 + sqrt(1 - x^2))/x). Measured 2e-15 relative at x = 1e-300
    # (p = 440, a sum over ~1000 geometric pieces) and <= 2e-16 absolute elsewhere.
    p = pl.power_law_pressure(SmoothFlat(), 1, X)
    exact = 2 / np.pi * np.log((1 + np.sqrt((1 - X) * (1 + X))) / X)
    np.testing.assert_allclose(p, exact, rtol=1e-14, atol=1e-14)
    assert pl.power_law_pressure(SmoothFlat(), 1, 0.0) == math.inf  # log divergence


@pytest.mark.parametrize("n", [0.5, 1.5, 3.7])
def test_general_n_frictionless_hyp2f1(n):
    # p = (2/pi) n x^(n-1) sqrt(1 - x^2) 2F1((n+1)/2, 1/2; 3/2; 1 - x^2): (3.13) with v = t^2,
    # then v = 1 - w (n = 2, 1 give (3.19), (3.20)). mpmath at 30 digits.
    x = np.array([1e-6, 0.01, 0.3, 0.7, 0.95, 1 - 1e-9])
    p = pl.power_law_pressure(SmoothFlat(), n, x)
    with mpmath.workdps(30):
        exact = [float(2 / mpmath.pi * n * mpmath.mpf(xi) ** (n - 1) * mpmath.sqrt(1 - mpmath.mpf(xi) ** 2)
                       * mpmath.hyp2f1((n + 1) / mpmath.mpf(2), 0.5, 1.5, 1 - mpmath.mpf(xi) ** 2)) for xi in x]
    np.testing.assert_allclose(p, exact, rtol=2e-14)  # measured <= 4e-15


@pytest.mark.parametrize(("n", "A"), [(2.0, 1.0), (1.0, math.pi / 2), (3.7, None), (0.4, None)])
def test_indentation_constant_frictionless(n, A):
    # A* = 1 without shear, so A = B(n/2, 1/2)/2 by (3.5): 1 (Hertz) and pi/2 (cone).
    # Route (3.16) is a genuine quadrature of (2/pi) t K(t) p(t): measured 2e-16.
    exact = A if A is not None else 0.5 * math.gamma(n / 2) * math.sqrt(math.pi) / math.gamma((n + 1) / 2)
    assert pl.indentation_constant(SmoothFlat(), n) == pytest.approx(exact, rel=1e-15)
    assert pl.indentation_constant_316(SmoothFlat(), n) == pytest.approx(exact, rel=1e-13)


def test_w_n_series_and_closed_form_agree():
    # The hand-over at s = 1/2 between the series and the incomplete-beta form: no jump
    # beyond the betainc rounding (measured 4e-17); n = 2 closed form -(1 - r)/(1 + r).
    for n in (0.3, 1.0, 2.0, 5.5):
        below, above = pl.w_n_scaled(n, np.nextafter(0.5, 0.0)), pl.w_n_scaled(n, np.nextafter(0.5, 1.0))
        assert below == pytest.approx(above, rel=1e-13)
    s = np.array([1e-8, 0.1, 0.5, 0.8, 1.0])
    r = np.sqrt(1 - s**2)
    np.testing.assert_allclose(pl.w_n_scaled(2.0, s), -(s**2 / (1 + r) ** 2), rtol=1e-14)


# ---------------------------------------------------------------- adhesive sphere
@pytest.mark.parametrize("gamma", [0.5, 0.2])
def test_adhesive_sphere_constants_418(gamma):
    # (4.18) for A and C; measured |1/A - exact| <= 1.2e-14, |C - exact| <= 1.7e-14.
    # The 1e-12 tolerances cover the App. B quadrature (1e-14) and the edge model (1e-13).
    flat = AdhesiveFlat(gamma)
    assert 1 / pl.indentation_constant(flat, 2) == pytest.approx(1 / adhesive.sphere_A_adhesive(gamma), abs=1e-12)
    assert pl.indentation_constant_316(flat, 2) == pytest.approx(pl.indentation_constant(flat, 2), abs=1e-12)
    for x in (0.3, 0.7):
        assert pl.displacement_constant(flat, 2, x=x) == pytest.approx(adhesive.sphere_C_adhesive(gamma), abs=1e-12)


@pytest.mark.parametrize("n", [0.5, 1.0, 3.3])
def test_adhesive_routes_agree_general_n(adhesive_half, n):
    # The A identity and (3.16) are independent quadratures; C must not depend on x.
    # Measured differences <= 2e-14 (A) and 7e-15 (C).
    assert pl.indentation_constant_316(adhesive_half, n) == pytest.approx(
        pl.indentation_constant(adhesive_half, n), abs=1e-12)
    c1, c2 = (pl.displacement_constant(adhesive_half, n, x=x) for x in (0.2, 0.6))
    assert c1 == pytest.approx(c2, abs=1e-12)
    assert c1 < 0.0  # inward displacement of the stuck surface (sign of (4.18))


def test_adhesive_gamma_zero_is_frictionless():
    # gamma = 0: q0 = 0 and C = 0 exactly, A = 1 (kappa = 0 in (4.18)).
    flat = AdhesiveFlat(0.0)
    assert pl.displacement_constant(flat, 2) == pytest.approx(0.0, abs=1e-15)
    assert pl.indentation_constant(flat, 2) == pytest.approx(1.0, rel=1e-15)


def test_adhesive_sphere_centre_b6(adhesive_half):
    # (3.18)/(B6): p(0) = 2 p0(0) exactly; p'(0) = -2 p0(0) kappa gamma. p is a polynomial
    # in x to O(x^3) near 0 (p0 even), so two Richardson steps on h = 1e-3 leave O(h^3)
    # = 1e-9 (times p''' ~ 1) and 1e-13 of rounding. Measured error 1.4e-9.
    g = 0.5
    assert pl.power_law_pressure(adhesive_half, 2, 0.0) == adhesive.sphere_central_pressure_adhesive(g)
    h = 1e-3
    p = pl.power_law_pressure(adhesive_half, 2, np.array([0.0, h, 2 * h, 4 * h]))
    d1, d2, d4 = ((p[k] - p[0]) / (hk) for k, hk in ((1, h), (2, 2 * h), (3, 4 * h)))
    r1, r2 = 2 * d1 - d2, 2 * d2 - d4
    slope = (4 * r1 - r2) / 3
    assert slope == pytest.approx(adhesive.sphere_pressure_slope_adhesive(g), abs=1e-8)


def test_edge_values_vanish(adhesive_half):
    # (3.7): p(1) = q(1) = 0 exactly; just inside, p, q ~ (1 - x)^(1/2).
    x = np.array([1.0, 1 - 1e-14])
    p = pl.power_law_pressure(adhesive_half, 2, x)
    q = pl.power_law_shear(adhesive_half, 2, x)
    assert p[0] == 0.0 and q[0] == 0.0
    assert 0.0 < p[1] < 1e-6 and abs(q[1]) < 1e-6


def test_compliance_317(adhesive_half):
    # (3.17) against direct quadrature (pi/2) int x p dx of the computed p (the quadrature
    # misses O(s_e^(3/2)) beyond x_e); measured 4e-16.
    n = 2.0
    prepared = pl._Flat(adhesive_half)
    nodes, weights, p, _ = prepared.stresses_on_rule(prepared.rule_knots(), n)
    direct = 0.5 * np.pi * np.sum(weights * nodes * p)
    assert pl.power_law_compliance(adhesive_half, n) == pytest.approx(direct, rel=1e-13)
    assert pl.power_law_compliance(adhesive_half, n) == pytest.approx(2 / 3 * math.log(3), rel=1e-15)


def _sphere_oracle(x: float, gamma: float, dps: int = 20) -> tuple[float, float]:
    """p(x), q(x) for n = 2 by (B3) in (3.13) with the order swapped, in mpmath.

    p = (4/pi) p0(0) x int_0^1 cos(kappa theta) J(w) dw/(1 - w^2),
    J = int_max(x,w)^1 dt/(t^2 sqrt(t^2 - w^2)) = (1 - x^2)/(x (x r + sqrt(x^2 - w^2))) (w < x),
        r/w^2 (w > x), r = sqrt(1 - w^2);
    q likewise with w sin(kappa theta) and J3 = int dt/(t^3 sqrt(t^2 - w^2))
        = [phi + sin phi cos phi]/(2 w^3) between phi = acos(w/max(x, w)) and acos(w).
    """
    with mpmath.workdps(dps + 40):
        x = mpmath.mpf(x)
        g = mpmath.mpf(gamma)
        kappa = 2 * mpmath.atanh(g) / mpmath.pi
        p_centre = kappa / g * mpmath.cosh(mpmath.pi * kappa / 2)

        def j2(w):
            r = mpmath.sqrt(1 - w * w)
            if w < x:
                return (1 - x * x) / (x * (x * r + mpmath.sqrt(x * x - w * w)))
            return r / (w * w)

        def j3(w):
            def big_g(phi):
                return phi + mpmath.sin(phi) * mpmath.cos(phi)
            return (big_g(mpmath.acos(w)) - big_g(mpmath.acos(w / max(x, w)))) / (2 * w**3)

        def fp(w):
            if w >= 1:
                return mpmath.mpf(0)  # tanh-sinh node rounded onto the integrable end point
            return mpmath.cos(kappa * mpmath.atanh(w)) * j2(w) / (1 - w * w)

        def fq(w):
            if w == 0 or w >= 1:
                return mpmath.mpf(0)  # O(w^2) at 0; integrable end point at 1
            return w * mpmath.sin(kappa * mpmath.atanh(w)) * j3(w) / (1 - w * w)

        pts = [0, x, (1 + x) / 2, 1]
        p = 4 / mpmath.pi * p_centre * x * mpmath.quad(fp, pts)
        q = 4 / mpmath.pi * p_centre * x * mpmath.quad(fq, pts)
        return float(p), float(q)


def test_adhesive_sphere_pointwise_mpmath(adhesive_half):
    # Independent oracle (swapped order, closed-form inner integrals, 20 digits).
    # Measured relative errors <= 2e-15 (p, q at x = 0.05 ... 1 - 1e-6).
    x = np.array([0.05, 0.5, 0.95, 1 - 1e-6])
    p = pl.power_law_pressure(adhesive_half, 2, x)
    q = pl.power_law_shear(adhesive_half, 2, x)
    for xi, pi_, qi in zip(x, p, q):
        p_ref, q_ref = _sphere_oracle(float(xi), 0.5)
        assert pi_ == pytest.approx(p_ref, rel=1e-13)
        assert qi == pytest.approx(q_ref, rel=1e-13)


# ---------------------------------------------------------------- bad inputs
def test_bad_inputs_raise():
    flat = SmoothFlat()
    for n in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="n"):
            pl.power_law_pressure(flat, n, 0.5)
    for x in (-0.1, 1.1, math.nan):
        with pytest.raises(ValueError, match="x"):
            pl.power_law_shear(flat, 2, x)
    with pytest.raises(ValueError, match="c"):
        pl.displacement_constant(flat, 2)  # no stick zone
    with pytest.raises(ValueError, match="x"):
        pl.displacement_constant(AdhesiveFlat(0.5), 2, x=1.0)

    class Broken(SmoothFlat):
        breakpoints = np.array([0.0, 0.6, 0.5, 1.0])

    with pytest.raises(ValueError, match="breakpoints"):
        pl.indentation_constant(Broken(), 2)


def test_constants_next_to_full_stick_are_the_adhesive_ones():
    # below 1 - c = 1e-11 the composite rule in x cannot resolve the stick-slip layer, and A, C come from the adhesive
    # solution (App. B): equal to its closed forms (4.18) to the quadrature's 1e-14; above, the frictional constants
    # approach them like -(1 - c)^0.9 (A) and -0.03 (1 - c) (C, measured at gamma = 0.124), so at 1 - c = 1e-9 they
    # differ by 1e-10 and 4e-11: less than 1e-9, and more than zero (the quadrature resolves them there)
    from asymptotics.adhesive import sphere_A_adhesive, sphere_C_adhesive
    from numeric.solutions.power_law import ADHESIVE_CONSTANTS_GAP, displacement_constant, indentation_constant
    from numeric.solutions.solver import solve_given_c

    gamma = 0.124
    A_ad, C_ad = float(sphere_A_adhesive(gamma)), float(sphere_C_adhesive(gamma))
    for gap in (0.5 * ADHESIVE_CONSTANTS_GAP, 1e-13):
        flat = solve_given_c(None, 1.0 - gap, gamma, 2, gap=gap)
        assert indentation_constant(flat, 2.0) == pytest.approx(A_ad, rel=1e-14)
        assert displacement_constant(flat, 2.0) == pytest.approx(C_ad, rel=1e-13)
    flat = solve_given_c(None, 1.0 - 1e-9, gamma, 2, gap=1e-9)
    assert 1e-12 < abs(indentation_constant(flat, 2.0) - A_ad) < 1e-9
    assert 1e-12 < abs(displacement_constant(flat, 2.0) - C_ad) < 1e-9


def test_C_says_how_good_it_is_and_warns_where_n_has_eaten_its_digits():
    # u = C x^n on the stick zone is a difference of two integrals over x^n: at nu = 0.3, mu = 0.3 (c = 0.896) it
    # was -0.1145 at n = 14 and -1894 at n = 16, silently. C_error is the change of C between x = c/2 and c/4
    # (the true C does not depend on x): small at n = 2, and above C_RTOL, with an AccuracyWarning, at n = 16
    good = pl.power_law(2, nu=0.3, mu=0.3)
    assert good.C_error < 1e-11 and good.C == pytest.approx(pl.displacement_constant(good.flat, 2, x=0.7 * good.c),
                                                          rel=1e-11)
    bad = pl.power_law(16, nu=0.3, mu=0.3)
    with pytest.warns(pl.AccuracyWarning, match="good to .* relative only"):
        bad.C
    assert bad.C_error > pl.C_RTOL


@pytest.mark.parametrize("n", [0.0, 5e-324, 150.0, 1e6])
def test_exponents_outside_the_validated_range_are_refused(n):
    # above n = 100 the quadratures lose digits (the frictionless pressure 5 % off at n = 1000), below 1e-300
    # A ~ 1/n overflows
    with pytest.raises(ValueError, match="^n "):
        pl.power_law(n, nu=0.3, mu=0.3)


def test_subnormal_radii():
    # for n >= 1.05 the centre value, from which p(x) differs by x^(n-1) < 5e-16; below, refused (p ~ x^(n-1))
    h = pl.power_law(2, nu=0.3, mu=0.3)
    assert float(h.pressure(5e-324)) == float(h.pressure(0.0))
    with pytest.raises(ValueError, match="^x must be 0 or a normal double"):
        pl.power_law(1.0, nu=0.3, mu=0.3).pressure(5e-324)
