"""The §3 derivations (asymptotics.derive.similarity) and the fast functions of asymptotics.similarity.

Oracles: the SymPy derivations themselves (agrees), mpmath at 30-40 digits (Identities,
``precise``), and quadratures written here independently of the code under test.
"""

import math

import mpmath
import numpy as np
import pytest
from scipy import integrate

from asymptotics.adhesive import shear_adhesive, sphere_A_adhesive
from asymptotics.derive.similarity import derivations
from asymptotics.similarity import (a_star_factor, c_star_factor, central_pressure_ratio, compliance_ratio,
                                   frictionless_indentation_constant, frictionless_pressure_power_law)

LABELS = ("(3.5)", "(3.10)", "(3.13)", "(3.15)", "(3.16)", "(3.16)-edge", "(3.17)", "(3.18)", "(3.19)",
          "(3.20)", "frictionless-n")


@pytest.fixture(scope="module")
def entries():
    return {d.label: d for d in derivations()}


def test_all_labels_in_part_3_and_cached(entries):
    assert tuple(entries) == LABELS
    assert all(d.part == "3" for d in entries.values())
    assert derivations() is derivations()  # functools.cache


def test_cross_reference_slips_are_recorded(entries):
    assert "(1.15)" in entries["(3.10)"].note
    assert "(1.23)" in entries["(3.13)"].note
    assert "(1.28)" in entries["(3.17)"].note


# ------------------------------------------------------------------ fast functions, independent checks
def _pressure_quad_mp(x, n):
    """n x^(n-1) int_x^1 t^-n (2/pi)(1-t^2)^-1/2 dt at 20 digits: on (x, 1/2) in t with breakpoints
    x 2^k (t^-n varies on the scale t), on (1/2, 1) with t = 1 - w^2 (removes the edge root)."""
    with mpmath.workdps(20):
        x, n = mpmath.mpf(x), mpmath.mpf(n)
        inner = 0
        if x < 0.5:
            points = [x * 2**k for k in range(80) if x * 2**k < 0.5] + [mpmath.mpf(1) / 2]
            inner = mpmath.quad(lambda t: t ** (-n) / mpmath.sqrt(1 - t * t), points)
        top = mpmath.sqrt(1 - max(x, mpmath.mpf(1) / 2))
        outer = mpmath.quad(lambda w: 2 * (1 - w * w) ** (-n) / mpmath.sqrt(2 - w * w), [0, top])
        return float(n * x ** (n - 1) * 2 / mpmath.pi * (inner + outer))


@pytest.mark.parametrize("n", [0.2, 0.999, 1.0, 1.001, 1.3, 2.0, 2.97, 3.0, 3.03, 5.0, 9.5])
def test_frictionless_pressure_against_quadrature(n):
    # Accuracy 1e-15 relative except 1 < n < 1.01 (about 4e-16/(n-1), docstring): 1e-13 covers n = 1.001,
    # the 20-digit quadrature is good to ~1e-18.
    xs = np.array([1e-10, 1e-4, 0.4, 0.7072, 0.95, 1 - 1e-13])
    fast = frictionless_pressure_power_law(xs, n)
    exact = np.array([_pressure_quad_mp(x, n) for x in xs])
    np.testing.assert_allclose(fast, exact, rtol=1e-13, atol=0)


def test_frictionless_pressure_special_cases_and_shapes():
    xs = np.linspace(0.0, 1.0, 11)
    np.testing.assert_allclose(frictionless_pressure_power_law(xs, 2), 4 / np.pi * np.sqrt(1 - xs**2), rtol=1e-15, atol=1e-16)
    assert frictionless_pressure_power_law(1.0, 3.7) == 0.0  # (3.7)
    assert math.isinf(frictionless_pressure_power_law(0.0, 1.0))  # cone apex
    assert math.isinf(frictionless_pressure_power_law(0.0, 0.5))
    assert frictionless_pressure_power_law(0.0, 3.0) == pytest.approx(3 / np.pi, rel=1e-15)  # (3.18)
    assert np.shape(frictionless_pressure_power_law(np.zeros((2, 3)) + 0.5, 2.5)) == (2, 3)
    assert np.isscalar(frictionless_pressure_power_law(0.5, 2.5))


@pytest.mark.parametrize("n", [0.5, 1.0, 2.0, 3.0, 6.0])
def test_frictionless_compliance_and_indentation(n):
    # (3.17) with P0* = 1 by quadrature of the fast pressure; (3.5a) without friction, whose right side
    # 1 - x^n/(nA) gives A* = 1, i.e. A = frictionless_indentation_constant(n), checked at x = 1/2 by
    # quadrature of int_x^1 t p dt / sqrt(t^2 - x^2) (t = sqrt(x^2 + (1 - x^2) s^2)); scipy quad: 1e-10.
    compliance = np.pi / 2 * integrate.quad(lambda x: x * frictionless_pressure_power_law(x, n), 0, 1, limit=200)[0]
    assert compliance == pytest.approx(compliance_ratio(n), rel=1e-9)
    x = 0.5
    g = 1 - x * x  # t dt / sqrt(t^2 - x^2) = sqrt(g) ds
    abel = integrate.quad(lambda s: frictionless_pressure_power_law(math.sqrt(x * x + g * s * s), n) * math.sqrt(g),
                          0, 1, limit=200)[0]
    assert abel == pytest.approx(1 - x**n, rel=1e-9)  # A* = 1: A = frictionless_indentation_constant(n)


@pytest.mark.parametrize("n", [0.5, 1.0, 2.0, 3.0, 7.0])
def test_star_factors_against_abel_quadrature(n):
    # w = 1 - x^n/(nA): d/dx int_0^x t w dt/sqrt(x^2-t^2) = 1 - A* x^n; u = C x^n: u* = C* x^n (3.5).
    # Moments int_0^1 s^m ds/sqrt(1-s^2) by mpmath (s = sin phi), 30 digits.
    with mpmath.workdps(30):
        moment = lambda m: mpmath.quad(lambda p: mpmath.sin(p) ** m, [0, mpmath.pi / 2])
        a_star_times_a = (n + 1) / n * moment(n + 1)
        c_star_over_c = (n + 1) * moment(n)
    assert a_star_factor(n) == pytest.approx(float(a_star_times_a), rel=4e-15)
    assert c_star_factor(n) == pytest.approx(float(c_star_over_c), rel=4e-15)
    assert frictionless_indentation_constant(n) == a_star_factor(n)


def test_ratios():
    assert compliance_ratio(2) == pytest.approx(2 / 3, rel=1e-16)
    assert central_pressure_ratio(2) == 2.0
    assert frictionless_indentation_constant(1.0) == pytest.approx(math.pi / 2, rel=2e-15)


def test_edge_companion_gives_adhesive_A():
    # (3.16)-edge with the adhesive q0 of (B3) must give 1/A of (4.18) (the Identity of (4.18) checks
    # this to 28 digits in mpmath; here the numpy evaluator of (B3) is used). q0 ~ (1-s)^(-1/2) times a
    # log-periodic factor: with s = 1 - u^2 the integrand 2 u q0 K is bounded (|.| < 1.2 here) and
    # oscillates in log u, so a 40-point Gauss rule per decade u in (1e-6, 1) resolves it. The
    # part u < 1e-6 (1 - s < 1e-12, where doubles no longer resolve 1 - s) is dropped: at most
    # gamma * 1.2e-6, hence rel=1e-6.
    nodes, weights = np.polynomial.legendre.leggauss(40)
    edges = 10.0 ** -np.arange(7.0)
    lo, hi = edges[1:], edges[:-1]
    u = (0.5 * (hi + lo))[:, None] + (0.5 * (hi - lo))[:, None] * nodes
    w = (0.5 * (hi - lo))[:, None] * weights
    s = 1.0 - u * u
    r = u * np.sqrt(2.0 - u * u)  # sqrt(1 - s^2)
    for gamma in (0.5, 0.2):
        q0 = np.asarray(shear_adhesive(s.ravel(), gamma)).reshape(s.shape)
        integrand = q0 * (1 - r) / (1 + r) * 2 * u
        assert np.max(np.abs(integrand)) < 1.2
        integral = np.sum(w * integrand)
        assert 1 - gamma * integral == pytest.approx(1 / float(sphere_A_adhesive(gamma)), rel=1e-6)


@pytest.mark.parametrize(("call", "name"), [
    (lambda: a_star_factor(0.0), "n"),
    (lambda: c_star_factor(float("nan")), "n"),
    (lambda: compliance_ratio(-1.0), "n"),
    (lambda: central_pressure_ratio(1.0), "n"),
    (lambda: frictionless_pressure_power_law(1.5, 2.0), "x"),
    (lambda: frictionless_pressure_power_law(float("nan"), 2.0), "x"),
    (lambda: frictionless_pressure_power_law(0.5, float("inf")), "n"),
])
def test_bad_inputs_raise_naming_the_argument(call, name):
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        call()


def test_commutation_check_can_fail():
    # Negative control for (3.10) and (3.15): the degree-1 pieces of L do not commute with D itself,
    # and the degree-0 Abel operator of u* does not commute with D~ = D - 1/n.
    from sympy import Integral, sqrt

    from asymptotics.derive import similarity as pl

    l11 = next(iter(pl._operator_pieces().values()))[0]
    assert not pl._commutation(l11, 0)[0]
    assert pl._commutation(l11, 1 / pl.n)[0]
    a0 = lambda F: Integral(F(pl.s) / sqrt(1 - pl.s**2), (pl.s, 0, 1))  # noqa: E731
    assert not pl._commutation(a0, 1 / pl.n)[0]


def test_every_expression_prints_as_latex(entries):
    # The documents of derivations/ show each step with sympy.latex.
    import sympy

    for d in entries.values():
        for expr in (d.derived, d.printed, *(step.expr for step in d.steps)):
            if expr is not None:
                assert sympy.latex(expr)
