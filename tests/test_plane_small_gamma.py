"""The strip punch as nu -> 1/2: mu/gamma as a series in gamma^2 (``numeric.solutions.plane_small_gamma``).

The series is checked against the solver where the solver is good (gamma = 0.03, level 3), against itself through
nodes solved at another level (a convergence study: level 3 against level 2), and in the route: taken below
SMALL_GAMMA only, inverted given mu, its stresses those of the solver at c.
"""

import math

import numpy as np
import pytest

from numeric import plane
from numeric.solutions.plane_small_gamma import SMALL_GAMMA, gamma_series, small_gamma_friction
from numeric.solutions.plane_solver import solve_given_c


@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
def test_the_series_meets_the_solver_where_the_solver_is_good(c):
    # at gamma = 0.03 (nu = 0.485) level 3 is good to 3.2e-10 ... 5.1e-9 (its estimate) and the series (through
    # gamma = 0.06 ... 0.16, extrapolated below them) to 1e-10 ... 4.7e-10 (its estimate): they differ by 4.6e-12 ...
    # 1.5e-10 relative, 0.01 ... 0.05 of the two estimates together (measured); bound: the two estimates together
    g = 0.03
    mu, error = small_gamma_friction(c, 1 - c, g, 2)
    direct = solve_given_c(c, 1 - c, g, 3)
    assert abs(direct.field.mu - mu) <= error + direct.error.value()


@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
@pytest.mark.parametrize("g", [0.002, 0.005, 0.019])
def test_the_series_converges_with_the_solvers_level(c, g):
    # the series through level-3 solves at its nodes against the one through level 2: 8.4e-14 ... 1.3e-10 relative at
    # these (c, gamma), 0 ... 0.54 of the level-2 series' estimate (measured); bound: that estimate. Where the solver
    # itself is 7e-8 ... 1.2e-6 off (gamma = 0.002, level 3's own estimate)
    mu, error = small_gamma_friction(c, 1 - c, g, 2)
    assert abs(g * gamma_series(c, 1 - c, 3).mu_over_gamma(g) - mu) <= error
    assert error <= 5e-10 * mu  # the estimate itself: 1e-10 ... 2.4e-10 relative at these points (measured)


def test_the_series_leading_coefficient_is_the_solvers_slope_at_small_gamma():
    # r = (mu/gamma - F0)/gamma^2 from level-3 solves at gamma = 0.01 and 0.02 (not nodes of the series) is 0.55013 and
    # 0.55031 at c = 1/2 (their own errors 7e-5 and 4e-6 in r: the solver's relative error over gamma^2); the series'
    # r there agrees to 1.4e-6 and 1.3e-7 (measured); bound: the solver's error in r plus 1e-6
    from asymptotics.plane import mu_over_gamma_plane
    f0 = float(mu_over_gamma_plane(0.5))
    s = gamma_series(0.5, 0.5, 2)
    for g in (0.01, 0.02):
        direct = solve_given_c(0.5, 0.5, g, 3)
        r_direct = (direct.field.mu / g - f0) / g**2
        r_series = (s.mu_over_gamma(g) - f0) / g**2
        assert abs(r_series - r_direct) <= direct.error.value() / g**3 + 1e-6


def test_the_route_is_taken_below_small_gamma_only_and_inverts_itself():
    # given c below SMALL_GAMMA: the series' mu, its error 1e-10 relative (the floor) here; given that mu, c back to
    # within the route's error of c (a Newton step from the solver's c); above SMALL_GAMMA the solver's route
    g = 0.5 * SMALL_GAMMA
    s = plane.flat_punch(gamma=g, c=0.5)
    assert s.route.startswith("small-gamma series") and s.error <= 2e-10 * s.mu
    back = plane.flat_punch(gamma=g, mu=s.mu)
    assert back.route.startswith("small-gamma series")
    assert abs(back.c - 0.5) <= back.error + s.error / (g * 0.9)  # d mu/dc = gamma dF0/dc, dF0/dc = 0.90 at c = 1/2
    assert plane.flat_punch(gamma=1.2 * SMALL_GAMMA, c=0.5).route.startswith("solver")


def test_the_routes_stresses_are_the_solvers_at_c():
    # the stresses are those of the solver's solve at c, at its own eigenvalue (off it the generic mode would enter
    # at x = c): p everywhere and q on the stick zone as the solver has them, and on the slip zones q = mu p for the
    # series' mu to the last bit (the solver's own q/p is its own mu, within its error of the series')
    g = 0.5 * SMALL_GAMMA
    c = 0.5
    s = plane.flat_punch(gamma=g, c=c)
    direct = solve_given_c(c, 1 - c, g, 2).field
    x = np.array([0.0, 0.5 * c, c, 0.5 * (1 + c), 1 - 1e-5])
    p, q = s.pressure(x), s.shear(x)
    pd, qd = direct.pressure_shear(x)
    assert np.array_equal(p, pd) and np.array_equal(q[:3], qd[:3])
    assert np.all(q[3:] == s.mu * p[3:])
    assert abs(qd[3] / pd[3] - s.mu) <= solve_given_c(c, 1 - c, g, 2).error.value() + s.error
    assert math.isfinite(float(s.slip(0.75)))
