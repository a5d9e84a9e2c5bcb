"""The strip punch below the solver's smallest stick width (``numeric.solutions.plane_law``).

Independent sources: mpmath (the full-slip pressure's normalisation and Carleman equation), the plane solver run
directly below the public route's reach (c = 1e-6: the core iteration at level 3, which the public route does not
use there because of its cost, 0.1-0.5 s), and the solver at c = 1e-5 for the stresses.
"""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest

from asymptotics.plane import pressure_full_slip
from numeric import plane
from numeric.app.cli import main
from numeric.core.plane_eigenvalue import plane_given_c, theta_rounding
from numeric.core.plane_fields import PlaneField
from numeric.solutions.plane_law import OUTER_FACTOR, FullSlipField, law_fit
from numeric.solutions.plane_power_law import PlanePowerLawSolution
from numeric.solutions.plane_punch import StripPunchSolution
from numeric.solutions.plane_solver import C_SMALLEST, PLANE_LEVELS, ROUNDING_FLOOR


def _gamma(nu: float) -> float:
    return (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)


@pytest.mark.parametrize("alpha", [0.01, 0.05, 0.2, 0.45])
def test_full_slip_pressure_solves_the_carleman_equation(alpha):
    """mpmath at 30 digits: int p = 1 and H p + tan(pi alpha) sgn(x) p = 0 off x = 0, to 1e-15 (p even, so
    H p(x) = (1/pi) PV int_0^1 p(t) 2x/(t^2 - x^2) dt; t = s^k, k = 1/(1 - 2 alpha), removes t^(-2 alpha) at 0, and
    tanh-sinh then leaves ~1e-20; a wrong formula would miss by O(alpha)); the double-precision function agrees with
    the formula to a few ulps of its three powers (bound 1e-14 relative)."""
    with mpmath.workdps(30):
        a = mpmath.mpf(alpha)
        k = 1 / (1 - 2 * a)

        def p(t):
            return mpmath.cos(mpmath.pi * a) / mpmath.pi * (1 - t * t) ** (a - 0.5) * t ** (-2 * a)

        def over_s(f, breaks):  # int_0^1 f(t) dt with t = s^k
            return mpmath.quad(lambda v: f(v**k) * k * v ** (k - 1), breaks)

        assert abs(2 * over_s(p, [0, 1]) - 1) < 1e-15
        for x in (mpmath.mpf("0.3"), mpmath.mpf("0.8"), mpmath.mpf("0.01")):
            kernel = lambda t: (p(t) - p(x)) * 2 * x / (t * t - x * x)  # noqa: E731
            hilbert = (over_s(kernel, [0, x ** (1 / k), 1]) + p(x) * mpmath.log((1 - x) / (1 + x))) / mpmath.pi
            assert abs(hilbert + mpmath.tan(mpmath.pi * a) * p(x)) < 1e-15 * p(x)
            for sign in (1, -1):
                assert float(pressure_full_slip(sign * float(x), alpha)) == pytest.approx(float(p(x)), rel=1e-14)


@pytest.mark.parametrize("nu", [0.45, 0.0, -0.9])
def test_law_against_the_solver_below_its_reach(nu):
    """mu at c = 1e-6 from the law against the core solver at level 3 run there directly: within the law's error
    bound, and the bound not more than 100 times the actual difference or the solver's own rounding scatter there,
    whichever is larger (``theta_rounding`` in theta, times d mu / d theta = sec^2(theta) / gamma). Measured: at
    nu = 0 and -0.9 the bound is 12 and 75 times the difference; at nu = 0.45 (theta = 8.6e-4) the solver's mu at
    c = 1e-6 scatters between levels 2, 3 and 4 by 5.5e-9 relative (its theta_rounding: 1.2e-7), the law's bound is
    4.1e-8 relative, and the difference to level 3 alone came out 1.7e-10 (numpy 2.4.6, scipy 1.17.1), which made the
    bound 250 times it: there the difference measures the solver's rounding, not the law."""
    g = _gamma(nu)
    c = 1e-6
    s = plane.flat_punch(nu=nu, c=c)
    assert s.route.startswith("law")
    theta = math.atan(s.mu * g)
    solved = PlaneField(plane_given_c(c, 1.0 - c, g, theta, PLANE_LEVELS[3])).mu
    difference = abs(s.mu - solved)
    rounding = theta_rounding(c, theta) / (g * math.cos(theta) ** 2)
    assert difference <= s.error
    assert s.error <= 100.0 * max(difference, ROUNDING_FLOOR * solved, rounding)


@pytest.mark.parametrize("nu", [0.3, -0.5])
def test_law_meets_the_solver_at_its_smallest_c_and_inverts_itself(nu):
    """The law is fitted through the solver at C_SMALLEST: just below it the law's mu is the solver's at C_SMALLEST
    to the solver's error (the change of mu over 1e-9 relative in c is ~1e-10 relative: d log mu/d log c ~ 1/L);
    given the law's mu, the law returns c to the rounding of solving for 1/log(4/c) (relative ~L eps)."""
    below = plane.flat_punch(nu=nu, c=C_SMALLEST * (1.0 - 1e-9))
    at = plane.flat_punch(nu=nu, c=C_SMALLEST)
    assert below.route.startswith("law") and at.route.startswith("solver")
    assert abs(below.mu / at.mu - 1.0) < 1e-9 + at.error / at.mu
    for c in (3e-6, 1e-9, 1e-100):
        s = plane.flat_punch(nu=nu, c=c)
        back = plane.flat_punch(nu=nu, mu=s.mu)
        assert back.route.startswith("law")
        assert back.c == pytest.approx(c, rel=300 * math.log(4 / c) * np.finfo(float).eps)
        assert back.error == pytest.approx(law_fit(_gamma(nu), 2).relative_error * math.log(4 / c) * c, rel=1e-6)


def test_tiny_friction_underflows_to_zero():
    """mu = 1e-3 at nu = 0.3: log(4/c) ~ pi gamma/(2 mu) = 449 > 745 - log 4? no: ~449, c ~ 1e-195; mu = 1e-4:
    log(4/c) ~ 4490, c underflows to 0.0, said in the route."""
    s = plane.flat_punch(nu=0.3, mu=1e-3)
    assert 0.0 < s.c < 1e-150
    zero = plane.flat_punch(nu=0.3, mu=1e-4)
    assert zero.c == 0.0 and "underflows" in zero.route
    assert plane.stick_radius(1e-4, 0.3) == 0.0


@pytest.mark.parametrize("nu", [0.3, -0.9])
def test_full_slip_stresses_against_the_solver(nu):
    """The law route's stresses (full slip) against the solver's at c = 1e-5 with the same mu: within
    alpha (c/x)^2 relative at |x| >= 100 c (measured 0.5 alpha (c/x)^2) plus the solver's own spread at c = 1e-5
    (levels 2, 3, 4 at nu = 0.3: up to 5e-11 relative at 1 - x = 1e-6 and 5e-12 at x <= 0.9, measured; a rounding
    change in the element transforms moved the default level's p there by 1e-12 and its mu by 4e-10, the
    conditioning at c = 1e-5: floor 1e-10), and the cylinder's load factor (3.13) within 1e-9 (measured 1e-11 ...
    1e-10: the stick zone's share is of order c)."""
    c = C_SMALLEST
    s = plane.flat_punch(nu=nu, c=c)
    field = FullSlipField(s.gamma, s.mu, c)
    x = np.concatenate([c * np.geomspace(OUTER_FACTOR, 1e4, 7), [0.3, 0.9, 1 - 1e-6], -c * np.geomspace(100, 1e3, 3)])
    p, q = field.pressure_shear(x)
    bound = field.alpha * (c / x) ** 2 + 1e-10
    assert np.all(np.abs(p / s.pressure(x) - 1.0) <= bound)
    assert np.all(np.abs(q / s.shear(x) - 1.0) <= bound)
    law = StripPunchSolution(s.nu, s.gamma, s.mu, c, 1.0 - c, 0.0, "test", 0.0, field)
    assert PlanePowerLawSolution(2.0, law).load_factor == pytest.approx(plane.power_law(2, nu=nu, c=c).load_factor,
                                                                       rel=1e-9)


def test_what_the_law_route_does_not_resolve():
    """Near the stick zone (|x| < 100 c, x = 0) a ValueError naming x; the slip: NotImplementedError; the CLI
    reports those values as null, the rest as numbers."""
    s = plane.flat_punch(nu=0.3, mu=0.01)
    with pytest.raises(ValueError, match="x = "):
        s.pressure(0.0)
    with pytest.raises(ValueError, match="x = "):
        plane.power_law(2, nu=0.3, mu=0.01).pressure([0.5, 0.0])
    with pytest.raises(NotImplementedError, match="slip"):
        s.slip(0.5)
    assert float(s.pressure(0.5)) == pytest.approx(float(pressure_full_slip(0.5, math.atan(s.mu * s.gamma) / math.pi)))


def test_cylinder_cli_with_small_friction(capsys):
    """hertz-friction cylinder at mu = 0.01: the half-width from the law route's load factor, the maxima null."""
    assert main(["cylinder", "--radius", "0.01", "--load-per-length", "1e5", "--E", "210e9", "--nu", "0.3",
                 "--mu", "0.01", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["max_pressure"] is None and out["centre_pressure"] is None and out["slip_edge"] is None
    h = plane.power_law(2, nu=0.3, mu=0.01)
    modulus = 210e9 / (2.0 * (1.0 - 0.3**2))
    assert out["half_width"] == pytest.approx(math.sqrt(h.load_factor * 0.01 * 1e5 / modulus), rel=1e-12)
