"""The largest stick radius c_max and the limit mu -> inf (beyond [S75]).

Independent sources: the limit problem (theta = pi/2 of the singular-basis solver) against the
closed form K'(c_max)/K(c_max) = kappa (theta functions in numpy; the elliptic-integral relation
in mpmath), the solver at large but finite mu, a boundary-element solution quoted in the issue
(nu = -0.5), and the series of 1 - c_max in the nome.
"""

import math

import mpmath
import numpy as np
import pytest

from asymptotics.largest_stick_radius import largest_stick_radius_gap, largest_stick_radius_gap_mp, nome
from numeric import flat_punch, largest_stick_radius, slip_limit, stick_radius_approach


@pytest.mark.parametrize("gamma", [0.3, 0.5, 2 / 3, 0.75])
def test_limit_problem_gives_the_closed_form(gamma):
    # the limit problem's root against K'(c)/K(c) = (2/pi) atanh(gamma): 1e-10 relative in 1 - c_max is the
    # issue's target; measured 6.4e-13, 1.6e-13, 1.7e-14, 3.6e-12 against the closed form at 40 digits (gamma = .3,
    # .5, 2/3, .75; 8.7e-11 at .3 before the stick pressure's singular family was pinned to 0)
    s = slip_limit(gamma=gamma)
    gap = 1.0 - s.c
    with mpmath.workdps(40):
        c = 1 - mpmath.mpf(gap)
        ratio = mpmath.ellipk(mpmath.mpf(gap) * (2 - gap)) / mpmath.ellipk(c * c)
        kappa = 2 * mpmath.atanh(gamma) / mpmath.pi
        # d(K'/K)/d(gap) is of order 1/gap, so the relation holds to kappa's precision times ~1e-10
        assert abs(float(ratio - kappa)) < 1e-10 * float(kappa)
    assert gap == pytest.approx(float(largest_stick_radius_gap(gamma)), rel=1e-10)
    assert s.error < 1e-10


def test_closed_form_fast_against_mpmath_and_its_series():
    for g in (0.1, 0.2, 2 / 7, 0.5, 0.75):
        assert float(largest_stick_radius_gap(g)) == pytest.approx(float(largest_stick_radius_gap_mp(g)), rel=1e-13)
    # 1 - c_max = 8q - 32q^2 + 96q^3 - ... (SymPy, asymptotics.derive.largest_stick_radius): the first term is
    # the 8 exp(-pi/kappa) measured before; at gamma = .5, q = 1.25e-4, the three terms leave O(q^4) = 4e-16
    q = float(nome(0.5))
    assert float(largest_stick_radius_gap(0.5)) == pytest.approx(8 * q - 32 * q**2 + 96 * q**3, rel=1e-11)
    assert float(largest_stick_radius(0.0)) == 1.0 - float(largest_stick_radius_gap(0.5))


def test_saturation_matches_the_boundary_element_solution():
    # issue 11: an independent BEM solution at nu = -0.5 gives c ~ 0.946, 0.974, 0.980, 0.982 at mu = 2, 5,
    # 13.6, 50 (three digits) with the annulus pressure falling toward 0
    cs, peak = [], []
    for mu, bem in ((2.0, 0.946), (5.0, 0.974), (13.6, 0.980), (50.0, 0.982)):
        s = flat_punch(nu=-0.5, mu=mu)
        assert abs(s.c - bem) < 1e-3
        cs.append(s.c)
        x = np.linspace(s.c, 1.0, 200)[1:-1]
        peak.append(np.max(s.pressure(x)))
    assert np.all(np.diff(cs) > 0) and np.all(np.diff(peak) < 0)
    assert cs[-1] < float(largest_stick_radius(-0.5)) < 0.983


def test_approach_is_linear_in_one_over_mu():
    # (1 - c) - (1 - c_max) = A/(mu gamma) + O(mu^-2): at mu gamma = 1e3, 1e4 the scaled difference matches
    # A to 1e-3, 1e-4 (the O(1/mu) correction; measured 1.2e-3, 1.2e-4 relative), at nu = 0
    g = 0.5
    A = stick_radius_approach(gamma=g)
    gap_max = float(largest_stick_radius_gap(g))
    assert A / gap_max == pytest.approx(1.4293650, rel=1e-6)  # measured; the regression value of A (nu = 0)
    for mu_gamma, tol in ((1e3, 3e-3), (1e4, 3e-4)):
        s = flat_punch(gamma=g, mu=mu_gamma / g)
        assert ((1 - s.c) - gap_max) * mu_gamma == pytest.approx(A, rel=tol)


def test_the_limit_is_not_the_adhesive_solution():
    s, adhesive = slip_limit(nu=0.0), flat_punch(nu=0.0, mu=math.inf)
    assert adhesive.c == 1.0 and s.c < 1.0 and s.mu == math.inf
    x = np.linspace(s.c, 1.0, 50)[1:-1]
    assert np.all(s.pressure(x) == 0.0)  # p = q/mu = 0 on the annulus
    assert np.all(np.isfinite(s.shear(x))) and np.all(s.shear(x) > 0.0)
    # P* below the adhesive value by about (1 - c_max)^0.9 (measured 5.5e-4 at nu = 0, 1 - c_max = 1e-3)
    assert 0.0 < adhesive.compliance - s.compliance < 10 * (1 - s.c) ** 0.9
