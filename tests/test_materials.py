"""Material parameters (2.2), (4.10) and the dissimilar-bodies gamma of the §2.1 footnote."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asymptotics.materials import (
    check_c,
    check_gamma,
    check_mu,
    check_n,
    gamma_dissimilar,
    gamma_from_nu,
    kappa_from_gamma,
    resolve_gamma,
)
from numeric import flat_punch, largest_stick_radius


def test_gamma_exact_values():
    # (2.2) by hand: nu = 0 -> 1/2, nu = 0.3 -> 2/7 (the paper's steel example), nu = 1/2 -> 0.
    assert gamma_from_nu(0.0) == 0.5
    assert gamma_from_nu(0.3) == pytest.approx(2 / 7, abs=1e-16)
    assert gamma_from_nu(0.5) == 0.0
    assert np.allclose(gamma_from_nu([0.0, 0.25]), [0.5, 1 / 3], rtol=0, atol=1e-16)


def test_kappa_matches_log_form_of_4_18():
    # kappa = (1/pi) log(3 - 4 nu) for one body (4.18); our atanh form must agree to rounding.
    for nu in (-0.9, 0.0, 0.25, 0.49):
        assert kappa_from_gamma(gamma_from_nu(nu)) == pytest.approx(math.log(3 - 4 * nu) / math.pi, rel=1e-14)
    # errata table, 12 digits
    assert kappa_from_gamma(0.5) == pytest.approx(0.349699152566, abs=1e-12)
    assert kappa_from_gamma(0.2) == pytest.approx(0.129063552413, abs=1e-12)


def test_kappa_keeps_relative_accuracy_for_tiny_gamma():
    # log((1+g)/(1-g)) would lose all digits at g = 1e-17; atanh gives 2 g / pi exactly.
    assert kappa_from_gamma(1e-17) == pytest.approx(2e-17 / math.pi, rel=1e-15)


def test_gamma_dissimilar_limits():
    # rigid second body: the single-body gamma; identical bodies: 0 (no relative slip forcing).
    for nu in (0.0, 0.3):
        assert gamma_dissimilar(2.0, nu, math.inf, 0.1) == pytest.approx(gamma_from_nu(nu), rel=1e-15)
    assert gamma_dissimilar(3.0, 0.2, 3.0, 0.2) == 0.0
    # by hand: G1 = 1, nu1 = 0, G2 = 1, nu2 = 1/2 -> (1/2 - 0) / (1 + 1/2) = 1/3
    assert gamma_dissimilar(1.0, 0.0, 1.0, 0.5) == pytest.approx(1 / 3, rel=1e-15)


@pytest.mark.parametrize("nu", [-1.0, 0.51, float("nan"), 2.0])
def test_bad_nu_is_rejected(nu):
    with pytest.raises(ValueError, match="nu"):
        gamma_from_nu(nu)


@pytest.mark.parametrize(
    "call, name",
    [
        (lambda: gamma_dissimilar(0.0, 0.3, 1.0, 0.3), "G1"),
        (lambda: gamma_dissimilar(1.0, 0.3, -1.0, 0.3), "G2"),
        (lambda: gamma_dissimilar(1.0, 0.7, 1.0, 0.3), "nu"),
        (lambda: kappa_from_gamma(1.0), "gamma"),
        (lambda: check_mu(-0.1), "mu"),
        (lambda: check_mu(float("nan")), "mu"),
        (lambda: check_c(0.0), "c"),
        (lambda: check_c(1.5), "c"),
        (lambda: check_n(0.0), "n"),
        (lambda: check_n(float("nan")), "n"),
        (lambda: resolve_gamma(0.3, 0.2), "exactly one"),
        (lambda: resolve_gamma(None, None), "exactly one"),
    ],
)
def test_bad_inputs_name_the_argument(call, name):
    with pytest.raises(ValueError, match=name):
        call()


NU = st.floats(-1.0, 0.5, exclude_min=True)
MODULUS = st.floats(1e-300, 1e300)


@given(nu1=NU, nu2=NU, G1=MODULUS, G2=st.one_of(MODULUS, st.just(math.inf)))
def test_no_pair_of_materials_reaches_three_quarters(nu1, nu2, G1, G2):
    # |gamma_bar| <= max_i gamma_from_nu(nu_i) < 3/4 (proof in gamma_dissimilar): checked against the bound itself,
    # which rounding may put at 3/4 only as nu -> -1 (gamma_from_nu(-1 + 1e-16) rounds to 0.75)
    g = gamma_dissimilar(G1, nu1, G2, nu2)
    assert abs(g) <= max(gamma_from_nu(nu1), gamma_from_nu(nu2)) * (1 + 4 * np.finfo(float).eps)
    assert abs(g) <= 0.75
    check_gamma(abs(g))  # so every material pair's |gamma_bar| is accepted


@pytest.mark.parametrize("gamma", [0.7500000000000001, 0.9, 1.0 - 1e-16])
def test_gamma_beyond_three_quarters_is_rejected(gamma):
    # no material reaches it: ValueError naming gamma, from the checks and from the solvers that take gamma
    for call in (check_gamma, kappa_from_gamma, lambda g: flat_punch(gamma=g, mu=0.3),
                 lambda g: largest_stick_radius(gamma=g)):
        with pytest.raises(ValueError, match=r"^gamma must lie in \[0, 3/4\]"):
            call(gamma)
    assert float(check_gamma(0.75)) == 0.75  # the limit nu -> -1, where the tables end, is accepted
