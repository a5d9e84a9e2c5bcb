"""[S75] §2.3: the SymPy derivations (2.26)-(2.36) and the first-order flat-punch functions.

Oracles: mpmath at 30-60 digits (independent formulas: a direct quadrature of (2.14), a root
finder for the inverse of (2.28), the convergent K' series), exact closed forms ((B4),
atanh(gamma)/gamma), substitution back into (2.33), and the full solver at small gamma.
"""

import math
import time

import mpmath
import numpy as np
import pytest

from asymptotics import first_order as fp
from asymptotics import stick_radius
from asymptotics.materials import gamma_from_nu

LABELS = ("(2.26)", "(2.27)", "(2.28)", "(2.29)", "(2.30)", "(2.31)", "(2.33)", "(2.34)", "(2.35)", "(2.36)")


@pytest.fixture(scope="module")
def entries():
    from asymptotics.derive.first_order import derivations

    start = time.perf_counter()
    result = {d.label: d for d in derivations()}
    print(f"derivations() took {time.perf_counter() - start:.1f} s")
    return result


def test_labels_and_part(entries):
    assert tuple(entries) == LABELS
    assert all(d.part == "2.3" for d in entries.values())




def test_the_parameter_reading_of_heuman_fails(entries):
    # errata 6: reading Lambda0's second argument as a parameter misses (2.14) by ~1e-2
    extra = entries["(2.30)"].extra
    assert extra["modulus_reading_gap"] < 1e-18 and extra["parameter_reading_gap"] > 1e-3


@pytest.mark.parametrize("x, c", [(0.2, 0.3), (1e-4, 0.7), (0.69, 0.7), (0.95, 0.999)])
def test_psi_against_direct_quadrature_of_2_14(x, c):
    from asymptotics.derive.first_order import phi_direct_mp

    with mpmath.workdps(25):
        direct = phi_direct_mp(x, c) * mpmath.sqrt(1 - mpmath.mpf(x) ** 2) * mpmath.pi / 2
    # fast psi: rounding of the elliptic integrals (1e-15) times a few
    assert abs(float(fp.psi(x, c)) - float(direct)) <= 1e-14 * max(1.0, abs(float(direct)))
    assert abs(float(fp.shear_ratio_first_order(x, c)) - float(1 - direct)) <= 1e-14 * abs(float(1 - direct)) + 1e-16


def test_psi_end_values_and_vectorisation():
    c = np.array([0.1, 0.5, 0.9])
    assert np.all(fp.psi(0.0, c) == 1.0) and np.all(fp.psi(c, c) == 0.0)
    x = np.linspace(0.0, 0.5, 11)
    values = fp.psi(x, 0.5)
    assert values.shape == (11,)
    assert np.all(np.isfinite(values))
    assert fp.shear_ratio_first_order(0.7, 0.5) == 1.0
    assert fp.shear_ratio_first_order(0.0, 0.5) == 0.0


def test_shear_ratio_keeps_relative_accuracy_near_the_centre():
    # 1 - psi ~ x: the addition-theorem form keeps 1e-14 relative down to x = 1e-12 (mpmath at 50+ digits)
    for x in (1e-12, 1e-8, 1e-4):
        exact = fp.shear_ratio_first_order_mp(x, 0.5)
        assert abs(float(fp.shear_ratio_first_order(x, 0.5)) / float(exact) - 1) < 1e-14


def test_monotonicity_claims_after_2_31(entries):
    extra = entries["(2.30)"].extra
    assert extra["monotone_in_x"] is True and extra["decreasing_in_c"] is True
    # spot check of the second claim off the grid
    assert float(fp.shear_ratio_first_order(0.3, 0.4)) > float(fp.shear_ratio_first_order(0.3, 0.8))


# ---------------------------------------------------------------------------------------
# (2.28) and its inverse

@pytest.mark.parametrize("ratio", [1e-3, 0.01, 0.05, 0.1, 0.3, 1.0, 2.0, 5.0, 12.5, 1e3])
def test_stick_radius_against_mpmath_root(ratio):
    gamma = 0.25
    c = float(fp.stick_radius_first_order(ratio * gamma, gamma=gamma))
    with mpmath.workdps(60):
        exact = fp.stick_radius_first_order_mp(ratio, dps=40)
        if exact < mpmath.mpf(2) ** -1022:  # below the normal doubles (ratio = 1e-3: c = 2e-434)
            assert c == 0.0
            return
        # conditioning: a relative 1e-16 in mu/gamma (or in log f0) moves c by log(4/c) 1e-16;
        # a few ulps of log f0 (elliptic K', logs) allowed
        tol_c = 4e-16 * (1 + float(mpmath.log(4 / exact)))
        assert abs(c / float(exact) - 1) <= tol_c
        complement = 1 - exact
        if complement > 1e-10:
            # 1 - c is limited by the spacing 1.1e-16 of doubles below 1
            assert abs((1 - c) - float(complement)) <= 1.2e-16 + 1e-14 * float(complement)


def test_stick_radius_round_trip():
    c = np.concatenate([np.logspace(-12, -1, 23), np.linspace(0.1, 0.99, 90), 1 - np.logspace(-2, -9, 8)])
    back = fp.stick_radius_first_order(fp.mu_over_gamma(c) * 0.3, gamma=0.3)
    small = c < 0.5
    # relative in c: conditioning log(4/c) times a few ulps of f0
    assert np.all(np.abs(back[small] / c[small] - 1) <= 8e-16 * (1 + np.log(4 / c[small])))
    # relative in 1 - c: the spacing of doubles below 1 (1.1e-16) over 1 - c, plus a few ulps
    near = ~small
    assert np.all(np.abs((1 - back[near]) / (1 - c[near]) - 1) <= 2.3e-16 / (1 - c[near]) + 1e-14)
    # the other way round, up to mu/gamma = 2 (1 - c = 3.8e-3): f0 is then resolved to ~1e-14
    ratio = np.logspace(-2, np.log10(2.0), 50)
    c2 = fp.stick_radius_first_order(ratio * 0.2, gamma=0.2)
    assert np.all(np.abs(fp.mu_over_gamma(c2) / ratio - 1) <= 1e-14)


def test_stick_radius_edge_cases_and_nu():
    assert fp.stick_radius_first_order(0.0, gamma=0.3) == 0.0
    assert fp.stick_radius_first_order(np.inf, gamma=0.3) == 1.0
    assert list(fp.stick_radius_first_order([0.0, 0.1, np.inf], gamma=0.0)) == [0.0, 1.0, 1.0]
    assert fp.stick_radius_first_order(0.2, 0.3) == fp.stick_radius_first_order(0.2, gamma=float(gamma_from_nu(0.3)))
    assert np.all(np.diff(fp.stick_radius_first_order(np.linspace(0.0, 2.0, 101), gamma=0.5)) >= 0.0)


@pytest.mark.parametrize("call", [
    lambda: fp.stick_radius_first_order(-0.1, gamma=0.3),
    lambda: fp.stick_radius_first_order(float("nan"), gamma=0.3),
    lambda: fp.stick_radius_first_order(0.1, 0.3, gamma=0.3),
    lambda: fp.stick_radius_first_order(0.1),
    lambda: stick_radius(0.1, gamma=0.3, order=1),
    lambda: stick_radius(-0.1, gamma=0.3, order=1),
    lambda: fp.stick_radius_first_order(0.1, gamma=1.0),
    lambda: fp.c_small_mu(0.1, 0.3, terms=0),
    lambda: fp.c_large_mu(0.1, 0.3, terms=5),
    lambda: fp.psi(0.6, 0.5),
    lambda: fp.psi(0.2, 1.0),
    lambda: fp.psi(-0.1, 0.5),
    lambda: fp.shear_ratio_first_order(1.0, 0.5),
    lambda: fp.pressure_correction(1.0, 0.5),
    lambda: fp.pressure_correction(0.5, 1.0),
    lambda: fp.compliance_first_order(0.0, 0.3),
    lambda: fp.compliance_first_order(0.5, -0.1),
    lambda: fp.mu_over_gamma(0.0),
])
def test_bad_input_raises_value_error(call):
    with pytest.raises(ValueError):
        call()


def test_stick_radius_order_two():
    from asymptotics import second_order

    try:
        second_order.f2(0.5)
    except ImportError as exc:  # the generated table of the other module is not there yet
        with pytest.raises(NotImplementedError):
            stick_radius(0.1, gamma=0.2, order=2)
        pytest.skip(f"asymptotics.second_order.f2 unavailable: {exc}")
    gamma = 0.2
    ratio = np.array([0.3, 0.5, 1.0])
    c = stick_radius(ratio * gamma, gamma=gamma, order=2)
    assert np.array_equal(c, second_order.stick_radius_second_order(ratio * gamma, gamma=gamma))
    # the secant stops at 1e-14 in log(atanh c); f2 itself is a ~1e-12 table
    assert np.allclose(fp.mu_over_gamma(c) + gamma**2 * second_order.f2(c), ratio, rtol=1e-12)


# ---------------------------------------------------------------------------------------
# (2.29)

def test_frozen_asymptotic_coefficients_are_the_derived_ones(entries):
    extra = entries["(2.29)"].extra
    for frozen, derived in ((fp.SMALL_MU_COEFFICIENTS, extra["small_mu_coefficients"]),
                            (fp.LARGE_MU_COEFFICIENTS, extra["large_mu_coefficients"])):
        assert len(frozen) == len(derived)
        for a, b in zip(frozen, derived):
            assert np.allclose(a, b, rtol=1e-15, atol=0.0)


def test_leading_terms_are_the_papers_2_29():
    mu, gamma = 0.02, 0.5
    assert float(fp.c_small_mu(mu, gamma, terms=1)) == pytest.approx(4 * math.exp(-gamma / mu), rel=1e-15)
    mu = 2.0
    assert float(fp.c_large_mu(mu, gamma, terms=1)) == pytest.approx(1 - 2 * math.exp(-math.pi * mu / gamma), rel=1e-15)


def test_each_further_term_improves_the_order(entries):
    extra = entries["(2.29)"].extra
    for table in (extra["small_mu_errors"], extra["large_mu_errors"]):
        for ratio, *errors in table:
            for worse, better in zip(errors[:-1], errors[1:]):
                assert better < worse or worse < 1e-15, (ratio, errors)
    # the order: error(terms = k) ~ (E z)^k, so halving E z divides it by ~2^k; compare the
    # rows mu/gamma = 0.25 and 0.2 (E z = 0.027 and 0.00023): ratios grow with k
    rows = {row[0]: row[1:] for row in extra["small_mu_errors"]}
    gains = [a / b for a, b in zip(rows[0.25], rows[0.2])]
    assert gains[0] < gains[1] < gains[2] < gains[3]


def test_asymptotic_forms_meet_the_exact_inverse():
    # terms = 4 is exact to rounding for mu/gamma <= 0.1 (error ~ (E z)^4 < 1e-30)
    for ratio in (0.02, 0.05, 0.1):
        assert float(fp.c_small_mu(ratio * 0.5, 0.5, terms=4)) == pytest.approx(float(fp.stick_radius_first_order_mp(ratio)), rel=2e-15)


# ---------------------------------------------------------------------------------------
# (2.33), (2.34): pressure correction and compliance

@pytest.mark.slow  # ~2 s a point; the derivation itself checks c = 0.5, x = 0.5
@pytest.mark.parametrize("c, xs", [(0.9, (0.3,)), (0.2, (0.95,))])
def test_pressure_correction_satisfies_2_33(c, xs):
    from asymptotics.derive.first_order import substitution_residual

    # SciPy quad of a log-singular integrand: ~1e-9
    assert substitution_residual(c, xs) < 1e-8


def test_pressure_correction_against_the_solver():
    numeric = pytest.importorskip("numeric")
    c = 0.5
    x = np.array([0.0, 0.3, 0.6, 0.8, 0.95])
    p1 = fp.pressure_correction(x, c)
    p0 = fp.frictionless_pressure(x)
    remainders = []
    for gamma in (0.1, 0.05):
        s = numeric.flat_punch(c=c, gamma=gamma, level=2)
        remainders.append(np.max(np.abs((s.pressure(x) - p0) / gamma**2 - p1)))
    # p = p0 + gamma^2 P1 + O(gamma^4): the remainder / gamma^2 falls ~4x as gamma halves
    # (measured 6e-3 -> 1.5e-3; the solver's 1e-10 is far below)
    assert remainders[0] < 1e-2
    assert 3.5 < remainders[0] / remainders[1] < 4.5


def test_compliance_first_order_against_solver_and_limits():
    numeric = pytest.importorskip("numeric")
    c = 0.5
    errors = []
    for gamma in (0.2, 0.1):
        s = numeric.flat_punch(c=c, gamma=gamma, level=2)
        errors.append(abs(s.compliance - float(fp.compliance_first_order(c, gamma))))
    # O(gamma^4): halving gamma divides the error by ~16 (measured 0.0900 gamma^4)
    assert 13 < errors[0] / errors[1] < 19
    # c = 1 is (2.36); approached like 1/log(1/(1-c))
    assert fp.compliance_first_order(1.0, 0.5) == 1 + 0.25 / 3
    assert float(fp.compliance_first_order(1 - 1e-12, 0.5)) == pytest.approx(1 + 0.25 / 3, abs=1e-10)
    assert np.all(np.diff(fp.compliance_first_order(np.linspace(0.05, 0.99, 20), 0.3)) > 0)


def test_compliance_identity_is_exact_on_the_adhesive_solution(entries):
    # (2.34) with the exact adhesive shear (B3) gives (B4): SciPy quad of the (B3) values, ~1e-10
    assert entries["(2.34)"].extra["adhesive_gap"] < 1e-9


# ---------------------------------------------------------------------------------------
# (2.35), (2.36)

def test_adhesive_limit_matches_b3_like_gamma_squared(entries):
    (g1, gap1), (g2, gap2) = entries["(2.35)"].extra["b3_gap"]
    assert gap1 < 1e-3 and 0.5e-2 < gap2 / gap1 < 2e-2  # (g2/g1)^2 = 1e-2
    heuman = dict(entries["(2.35)"].extra["heuman_term"])
    assert heuman[32] < heuman[16] < heuman[8] < heuman[4] and heuman[32] < 1e-29


def test_2_36_numbers_and_the_slip(entries):
    extra = entries["(2.36)"].extra
    assert extra["first_order_at_half"] == pytest.approx(13 / 12, rel=1e-15)
    assert extra["exact_at_half"] == pytest.approx(math.log(3), rel=1e-15)
    assert round(extra["first_order_at_half"], 4) == extra["paper_first_order"]
    assert round(extra["exact_at_half"], 4) != extra["paper_exact"]  # errata 8: 1.0988 should be 1.0986
    assert "slip" in entries["(2.36)"].note
