"""The strip punch as nu -> 1/2: the solver at small gamma, and the small-gamma series (mu/gamma in gamma^2,
``numeric.solutions.plane_small_gamma``) that the law below the solver's smallest c takes r from.

The series is checked against the solver where both are good (gamma = 0.03, level 3), against itself through nodes
solved at another level (a convergence study: level 3 against level 2) and through other nodes. The solver's route
below SMALL_GAMMA: mu within 1e-10 of the series, given c and given mu inverse to each other, its stresses against the
solver's limit gamma -> 0 from solves at gamma = 0.02 ... 0.04. Near c = 1 and for tiny gamma given mu: the first-order law (a closed form) with its measured
O(gamma^2) bound, and the hand-overs at c = 1e-5 and 1 - c = SERIES_GAP_MIN.
"""

import math

import numpy as np
import pytest

from numeric import plane
from numeric.solutions.plane_small_gamma import NODES, SMALL_GAMMA, gamma_series
from numeric.solutions.plane_solver import C_SMALLEST, solve_given_c

CHECK_NODES = (0.07, 0.09, 0.11, 0.13, 0.15, 0.18)  # other nodes: other truncation, other rounding


def _series(c: float, g: float, level: int) -> tuple[float, float]:
    """mu from the series through NODES at ``level``, and 3x its distance from the one through CHECK_NODES."""
    mu = g * gamma_series(c, 1 - c, level, NODES).mu_over_gamma(g)
    other = g * gamma_series(c, 1 - c, level, CHECK_NODES).mu_over_gamma(g)
    return mu, 3.0 * abs(mu - other)


@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
def test_the_series_meets_the_solver_where_the_solver_is_good(c):
    # at gamma = 0.03 (nu = 0.485) the series (through gamma = 0.06 ... 0.16, extrapolated below them) and level 3
    # differ by 4.6e-12 ... 1.5e-10 relative (measured); bound: the solver's estimate and the series' together
    g = 0.03
    mu, error = _series(c, g, 2)
    direct = solve_given_c(c, 1 - c, g, 3)
    assert abs(direct.field.mu - mu) <= error + direct.error.value()


@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
@pytest.mark.parametrize("g", [0.002, 0.005, 0.019])
def test_the_series_converges_with_the_solvers_level(c, g):
    # the series through level-3 solves at its nodes against the one through level 2: 8.4e-14 ... 1.3e-10 relative at
    # these (c, gamma), 0 ... 0.54 of the level-2 series' estimate (measured); bound: that estimate
    mu, error = _series(c, g, 2)
    assert abs(g * gamma_series(c, 1 - c, 3).mu_over_gamma(g) - mu) <= max(error, 1e-10 * mu)
    assert error <= 5e-10 * mu  # the estimate itself: up to 2.4e-10 relative at these points (measured)


def test_the_series_leading_coefficient_is_the_solvers_slope_at_small_gamma():
    # r = (mu/gamma - F0)/gamma^2 from level-3 solves at gamma = 0.01 and 0.02 (not nodes of the series) is 0.55013 and
    # 0.55031 at c = 1/2; the series' r there agrees to 1.4e-6 and 1.3e-7 (measured, before the system was balanced);
    # bound: the solver's error in r plus 1e-6
    from asymptotics.plane import mu_over_gamma_plane
    f0 = float(mu_over_gamma_plane(0.5))
    s = gamma_series(0.5, 0.5, 2)
    for g in (0.01, 0.02):
        direct = solve_given_c(0.5, 0.5, g, 3)
        r_direct = (direct.field.mu / g - f0) / g**2
        r_series = (s.mu_over_gamma(g) - f0) / g**2
        assert abs(r_series - r_direct) <= direct.error.value() / g**3 + 1e-6


@pytest.mark.parametrize("c", [0.05, 0.5, 0.97])
def test_below_small_gamma_the_solver_answers_and_inverts_itself(c):
    # the solver at gamma itself (balanced): mu within 1e-10 of the series (measured 1.5e-12 ... 6.7e-11 at gamma =
    # 0.01; bound: the target 1e-10 plus the series' own estimate), its estimate 4e-10 at most; given that mu, c back to
    # within the route's error (its estimate of c, and the given-c error carried by d mu/d c)
    g = 0.5 * SMALL_GAMMA
    s = plane.flat_punch(gamma=g, c=c)
    assert s.route.startswith("solver") and s.error <= 5e-10 * s.mu
    mu, error = _series(c, g, 3)
    assert abs(s.mu - mu) <= 1e-10 * mu + error
    back = plane.flat_punch(gamma=g, mu=s.mu)
    assert back.route.startswith("solver")
    h = 1e-6 * min(c, 1 - c)
    slope = (plane.flat_punch(gamma=g, c=c + h).mu - plane.flat_punch(gamma=g, c=c - h).mu) / (2 * h)
    assert abs(back.c - c) <= back.error + s.error / slope


def _solver_trend(c: float, x: np.ndarray) -> np.ndarray:
    """p, q/gamma, u/gamma at x as quadratics in gamma^2 (rows: coefficients) through level-3 solves at gamma = 0.02,
    0.03, 0.04."""
    gs = (0.02, 0.03, 0.04)
    rows = []
    for g in gs:
        f = solve_given_c(c, 1 - c, g, 3).field
        p, q = f.pressure_shear(x)
        rows.append(np.concatenate([p, q / g, f.slip(x) / g]))
    return np.linalg.solve(np.vander([g * g for g in gs], 3, increasing=True), np.array(rows))


@pytest.mark.parametrize("nu, c", [(0.499999999, 0.5), (0.5 - 1e-12, 0.9)])
def test_the_stresses_stay_right_as_gamma_goes_to_zero(nu, c):
    # The plain system at gamma itself put q/(mu p) = 1.1e4 in the stick zone at nu = 0.499999999, c = 0.5 (Coulomb
    # needs <= 1), q(0.1) < 0 and u(0.75)/gamma = -1319 (-0.0385 at nu = 0.49999), with mu's error 1.6e-19; at
    # nu = 0.5 - 1e-12, c = 0.9 u(0.99) > 0 and q(0.9) < 0. The route's p, q/gamma, u/gamma (the balanced solver at
    # gamma itself) against the solver's limit gamma -> 0 (_solver_trend, from solves at larger gamma): measured within
    # 3.6e-11, 2.1e-10, 3.9e-11 (c = 0.5) and 6.2e-10, 3.6e-10, 3.1e-10 (c = 0.9) of the largest value (the series
    # through the nodes' fields, the route before, 1.1e-10, 5.6e-10, 4.9e-11 and 6.2e-10, 1.1e-8, 6.8e-10); bound 5e-8,
    # the reference's own uncertainty next to x = c (the limits through gamma = 0.01 ... 0.03 and 0.02 ... 0.04
    # differ there by 1.2e-7 at c = 0.5), not tighter
    s = plane.flat_punch(nu=nu, c=c)
    g = s.gamma
    assert s.route.startswith("solver")
    x = np.array([0.0, 0.3 * c, c * (1 - 1e-3), c, c + 1e-3 * (1 - c), 0.5 * (1 + c), 1 - 0.01 * (1 - c), -0.5 * c])
    got = np.concatenate([s.pressure(x), s.shear(x) / g, s.slip(x) / g])
    ref = _solver_trend(c, x)[0]
    n = x.size
    for k in range(3):
        part = slice(k * n, (k + 1) * n)
        assert np.max(np.abs(got[part] - ref[part])) <= 5e-8 * np.max(np.abs(ref[part]))
    # Coulomb in the stick zone, the signs: shear outward for x > 0, slip inward
    stick = np.linspace(0.01, 0.99, 50) * c
    assert np.all(np.abs(s.shear(stick)) <= s.mu * s.pressure(stick))
    assert np.all(s.shear(stick) > 0.0)
    slipping = c + (1 - c) * np.array([0.1, 0.5, 0.9, 0.99])
    assert np.all(s.slip(slipping) < 0.0) and np.all(np.diff(s.slip(slipping)) < 0.0)


@pytest.mark.parametrize("gamma", [1e-16, 1e-20, 1e-28, 1e-100, 1.9999557565557572e-12])  # the last nu = 0.499999999999
def test_tiny_gamma_given_mu_is_full_stick_at_once(gamma):
    # mu = 0.3 at gamma -> 0: the first-order law tan(theta) = gamma^2 K(c)/K'(c) puts 1 - c = 8 exp(-pi mu/gamma) = 0
    # (closed form), below FULL_STICK_GAP: full stick, as numeric.flat_punch(gamma=1e-20, mu=0.3) answers c = 1. The
    # solver at gamma itself raised SolverError after 5-9 s (gamma = 1e-16, 1e-28, 1e-100) or NoEigenvalueError after
    # 13 s (1e-20): now no solve at all (the threshold mu at 1 - c = 2^-40 is the first-order law's below
    # FIRST_ORDER_GAMMA)
    from asymptotics.plane import slip_width_first_order
    from numeric.solutions.plane_solver import FULL_STICK_GAP
    for mu in (0.3, 1e-8):
        s = plane.flat_punch(gamma=gamma, mu=mu)
        assert slip_width_first_order(mu, gamma) < FULL_STICK_GAP
        assert s.route.startswith("full stick") and s.gap <= s.error and 1.0 - s.c < FULL_STICK_GAP
        assert not hasattr(s.field, "n_unknowns")  # the bonded punch's closed form, no layout


def test_tiny_gamma_small_mu_is_the_first_order_law():
    # nu = 0.499999999999 (gamma = 2e-12), mu = 2e-13: c ~ 6e-7, below the solver's smallest; the law's fit used the
    # solver at gamma itself, whose r = (mu/mu_1 - 1)/gamma^2 was rounding over gamma^2 (~1e11), and brentq found no
    # bracket (ValueError "f(a) and f(b) must have different signs"). Now r from the series: at gamma = 2e-12 the law
    # is the first-order law to gamma^2 r ~ 1e-24, so c is the inverse of K(c)/K'(c) = mu/gamma (the closed form)
    # to rounding (bound 1e-12 relative); its stated error is the floor of mu's, 1e-10, times L = log(4/c) = 15.7
    from asymptotics.plane import stick_width_first_order
    s = plane.flat_punch(nu=0.499999999999, mu=2e-13)
    assert s.route.startswith("law")
    assert s.c == pytest.approx(float(stick_width_first_order(2e-13, s.gamma)), rel=1e-12)
    assert s.error <= 1e-10 * math.log(4 / s.c) * s.c * (1 + 1e-6)


def test_near_full_stick_at_small_gamma():
    # 1 - c below SERIES_GAP_MIN at gamma < SMALL_GAMMA: nu = 0.49, c = 1 - 1e-14 took 8 s and raised
    # NoEigenvalueError naming a node's gamma (0.16: c lies above that gamma's c_max); now the solver at gamma itself,
    # and at nu = 0.4999999 (gamma = 2e-7 < FIRST_ORDER_GAMMA) the first-order law, whose relative error in mu is at
    # most FIRST_ORDER_R_MAX gamma^2 (r = 40.3 at 1 - c = 1e-14, measured with the solver). Checked: the solver's mu
    # against the first-order law (a closed form) within that bound, and the law's mu is the closed form itself
    from asymptotics.plane import bonded_traction
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_solver import FIRST_ORDER_R_MAX
    c = 1 - 1e-14
    gap = 1 - c  # exact
    s = plane.flat_punch(nu=0.49, c=c)
    first = s.gamma / elliptic_ratio(c, gap)
    assert s.route.startswith("near full stick") and "solver level 2" in s.route
    assert 0.0 < s.mu / first - 1.0 <= FIRST_ORDER_R_MAX * s.gamma**2
    # the solver's estimate counts theta's rounding scatter, which depends on the BLAS path (measured 6.7e-10 relative
    # with one BLAS thread, 1.5e-9 with the default threads): 1e-8 says the solver answered (the first-order law's
    # bound, FIRST_ORDER_R_MAX gamma^2, is 2.3e-2 here) with room above that scatter
    assert s.error <= 1e-8 * s.mu
    assert np.isfinite(s.shear(0.999)) and s.slip(1.0) < 0.0
    tiny = plane.flat_punch(nu=0.4999999, c=c)
    assert tiny.mu == tiny.gamma / elliptic_ratio(c, gap)
    assert tiny.error == pytest.approx(FIRST_ORDER_R_MAX * tiny.gamma**2 * tiny.mu, rel=1e-15)
    # its stresses (not computed until measured, ``numeric.solutions.plane_small_gamma``): a solve at c, which away from
    # the slip zones of 1e-14 is the bonded punch's (Abramov, a closed form; measured 1.6e-10 of max(1, |p|) in q and
    # 8e-15 in p at gamma = 1e-6, 1 - c = 1e-9, q's difference falling like gamma (1 - c)/(1 - x); bound 1e-9)
    x = np.array([0.0, 0.3, 0.6, 0.9, 0.99])
    bonded = np.asarray(bonded_traction(x, tiny.gamma))
    assert np.max(np.abs(tiny.pressure(x) - bonded.real)) < 1e-9 and np.max(np.abs(tiny.shear(x) - bonded.imag)) < 1e-9
    back = plane.flat_punch(nu=0.4999999, mu=tiny.mu)
    assert abs(back.c - tiny.c) <= back.error


@pytest.mark.parametrize("gamma, gap", [(5e-5, 1e-10), (3e-4, 1e-10), (1e-3, 1e-12)])
def test_the_stresses_next_to_full_stick_at_small_gamma_converge(gamma, gap):
    # 1 - c below SERIES_GAP_MIN at FIRST_ORDER_GAMMA <= gamma < 1e-3, where the stresses were not given before they
    # were measured (below gamma = 1.7e-4 until the rtol route could choose the law): the route's p, q (default level)
    # against level 4 within the stated 1e-9 of max(1, |p|), on the stick zone, next to c and across the slip zones
    # (measured 3.0e-10 and 7.8e-11, at most 8.7e-10 over 16 such cases at gamma >= 1.7e-4 and 20 below, inside the
    # slip zones, where p ~ (1 - x)^(alpha - 1/2) is largest); and p(0) against Sadowsky's 1/pi of the frictionless
    # punch, which the coupling changes by O(gamma^2) (measured 0.5 gamma^2: 4.5e-8 and 5e-7; bound 10 gamma^2)
    c = 1.0 - gap
    s = plane.flat_punch(gamma=gamma, c=c)
    ref = plane.flat_punch(gamma=gamma, c=c, level=4)
    assert "its stresses" in s.route
    x = np.array([0.0, 0.3, 0.9, 0.999999, c - 10 * gap, c + 0.01 * gap, c + 0.5 * gap, c + 0.99 * gap])
    scale = np.maximum(1.0, np.abs(ref.pressure(x)))
    assert np.max(np.abs(s.pressure(x) - ref.pressure(x)) / scale) < 1e-9
    assert np.max(np.abs(s.shear(x) - ref.shear(x)) / scale) < 1e-9
    assert abs(math.pi * float(s.pressure(0.0)) - 1.0) < 10.0 * gamma**2


def test_the_solver_answers_next_to_full_stick_down_to_first_order_gamma():
    # the route took the first-order law below gamma = 1.7e-4 for speed, its mu up to 1.5e-6 off; now the solver from
    # FIRST_ORDER_GAMMA = 3e-5 up: at 1 - c = 1e-12 the route's r = (mu/mu_1 - 1)/gamma^2 (mu_1 the first-order law, a
    # closed form; the law itself has r = 0 and the bound 60) at gamma = 5e-5 against r at gamma = 1e-3 (r changes like
    # gamma^2 between them: measured 30.3124 against 30.3136); bound 0.05, 1.25e-10 in mu
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_solver import FIRST_ORDER_GAMMA
    c = 1.0 - 1e-12
    gap = 1.0 - c  # exact (Sterbenz), as the route forms it
    routes = {gamma: plane.flat_punch(gamma=gamma, c=c) for gamma in (5e-5, 1e-3)}
    r = {gamma: (s.mu / (gamma / elliptic_ratio(c, gap)) - 1.0) / gamma**2 for gamma, s in routes.items()}
    assert FIRST_ORDER_GAMMA <= 5e-5 and all("solver level 2 at gamma itself" in s.route for s in routes.values())
    assert abs(r[5e-5] - r[1e-3]) < 0.05


def test_rtol_takes_the_law_next_to_full_stick_where_its_bound_meets_it():
    # gamma = 1e-4, 1 - c = 1e-10: the solve costs ~0.3 s (given c) and ~2 s (given mu); at rtol = 1e-4 the first-order
    # law's bound, 60 gamma^2 = 6e-7 relative, meets rtol: mu is the law's closed form, its stated error that bound,
    # and the solver's level-2 mu (an independent route, within 1e-10 of level 4 here) lies within it (measured 2.2e-7
    # relative: r = 22); the stresses are a level-0 solve at c on first read, against level 2 within rtol of
    # max(1, |p|) (measured 8.3e-9, 1.2e-11). At rtol = 1e-10 the bound does not meet it and the solver answers, its
    # error within rtol (the estimate's floor). Given mu at rtol = 1e-4: the law's c, whose stated error covers the
    # solver's c (measured 5.5e-16 against 1.5e-15)
    import pickle
    import warnings
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_solver import FIRST_ORDER_R_MAX
    gamma, c = 1e-4, 1.0 - 1e-10
    gap = 1.0 - c
    solver = plane.flat_punch(gamma=gamma, c=c)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        loose = plane.flat_punch(gamma=gamma, c=c, rtol=1e-4)
        tight = plane.flat_punch(gamma=gamma, c=c, rtol=1e-10)
        back = plane.flat_punch(gamma=gamma, mu=solver.mu, rtol=1e-4)
    assert "first-order law" in loose.route and loose.mu == gamma / elliptic_ratio(c, gap)
    assert loose.error == pytest.approx(FIRST_ORDER_R_MAX * gamma**2 * loose.mu, rel=1e-15)
    assert abs(loose.mu - solver.mu) <= loose.error <= 1e-4 * loose.mu
    x = np.array([0.0, 0.3, 0.9, 0.999999, c - 10 * gap, c + 0.01 * gap, c + 0.5 * gap, c + 0.99 * gap])
    scale = np.maximum(1.0, np.abs(solver.pressure(x)))
    assert np.max(np.abs(loose.pressure(x) - solver.pressure(x)) / scale) < 1e-4
    assert np.max(np.abs(loose.shear(x) - solver.shear(x)) / scale) < 1e-4
    copy = pickle.loads(pickle.dumps(loose))  # with its field, formed (the solve behind it does not travel)
    assert np.array_equal(copy.pressure(x), loose.pressure(x))
    assert "solver level 2 at gamma itself" in tight.route and tight.error <= 1e-10 * tight.mu
    assert "first-order law" in back.route and abs(back.c - c) <= back.error


@pytest.mark.parametrize("nu, mu", [(0.49, 0.16), (0.499, 0.016)])
def test_rtol_given_mu_takes_the_law_next_to_full_stick_where_its_bound_on_c_meets_it(nu, mu):
    # rubber-like nu and friction (1 - c = 7.3e-11 and 9.3e-11): the default route's secant in c takes ~1 s; rtol given
    # mu is on c, and the first-order law's bound on mu (60 gamma^2: 2.3e-2, 2.4e-4 relative) turned into c by its
    # slope (c (1 - c) expm1 of the shift in logit c) is 4.7e-11 and 5.6e-13 of c, so rtol = 1e-10 takes the law at
    # once (measured 1.2 ms). Against the solver's c (the default route, within ~1e-20 of its own estimate): within
    # the law's stated error (measured 1.5e-11 against 4.7e-11, 2.0e-13 against 5.6e-13). The stresses are a solve at
    # the law's c, first read: away from the slip zones (x <= 0.99) the solver's at its own c within 1e-9 of
    # max(1, |p|) (measured 4.5e-12 and 6.9e-14: the bonded punch's there, which slip zones moved by 1.5e-11 change
    # by ~gamma 1e-11 / (1 - x))
    import warnings
    solver = plane.flat_punch(nu=nu, mu=mu)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        law = plane.flat_punch(nu=nu, mu=mu, rtol=1e-10)
    assert "first-order law" in law.route and "solver" in solver.route
    assert abs(law.c - solver.c) <= law.error <= 1e-10 * law.c
    x = np.array([0.0, 0.3, 0.9, 0.99])
    scale = np.maximum(1.0, np.abs(solver.pressure(x)))
    assert np.max(np.abs(law.pressure(x) - solver.pressure(x)) / scale) < 1e-9
    assert np.max(np.abs(law.shear(x) - solver.shear(x)) / scale) < 1e-9


@pytest.mark.parametrize("nu", [0.2, 0.3, 0.4, 0.44, 0.45, 0.49, 0.4999999])
def test_mu_increases_through_the_hand_over_to_the_law(nu):
    # at c = 1e-5 the law (below) hands over to the solver (above): friction_coefficient([9.99999e-6, 1e-5], 0.4999999)
    # was [2.4501e-8, 2.4355e-8] (the law's fit from the plain solver at gamma = 2e-7 itself, 5 % off) and the round
    # trip stick_radius(friction_coefficient(1e-5)) 64 % off; at nu = 0.49 mu(1e-5) given back raised "c =
    # 9.99999994e-06 is below 1e-05", and at nu = 0.2, 0.44 (0.4) mu(1e-5) given back found no bracket in the law.
    # Now mu(c) increases across the hand-over (at h = 1e-6) like the first-order law: mu(1e-5) - mu(1e-5 (1 - h)) =
    # h mu / L (d log F0 / d log c = 1/L, L = log(4/c) = 12.9), at h = 1e-4 to its O(gamma^2) part (measured 0.012 ...
    # 0.015 gamma^2: r's slope in log c) and the values' errors over their difference (the solver's at c = 1e-5 is
    # ~3e-9 relative, its estimate 3e-8: measured 4.3e-4 of the slope at nu = 0.49); bound 0.02 gamma^2 plus twice the
    # route's relative estimate over h / L; and the round trip holds to the stated error of c
    c = C_SMALLEST
    g = (1 - 2 * nu) / (2 - 2 * nu)
    below, at = plane.friction_coefficient([c * (1 - 1e-6), c], nu)
    assert below < at
    h = 1e-4
    below, at = plane.friction_coefficient([c * (1 - h), c], nu)
    solved = plane.flat_punch(nu=nu, c=c)
    slope_error = 2 * solved.error / solved.mu / (h / math.log(4 / c))
    assert abs((at - below) / at / (h / math.log(4 / c)) - 1.0) <= 0.02 * g * g + slope_error
    back = plane.flat_punch(nu=nu, mu=at)
    assert abs(back.c - c) <= back.error + solved.error / (at / (c * math.log(4 / c)))


def test_the_smallest_friction_gives_no_stick_zone():
    # mu = 5e-324 (the smallest double): the law's 1/log(4/c) underflowed to 0 and c = 4 exp(-1/y) raised
    # ZeroDivisionError; c = 4 exp(-pi gamma/(2 mu)) is 0 in doubles (closed form), and so is its error
    for nu in (-0.999, 0.3, 0.499):
        s = plane.flat_punch(nu=nu, mu=5e-324)
        assert s.c == 0.0 and s.error == 0.0 and s.route.startswith("law")


@pytest.mark.parametrize("factor", [1.001, 1.01])
def test_rtol_given_mu_next_to_the_full_stick_friction_states_an_error_that_covers_c(factor):
    # with rtol the full-stick threshold (mu at 1 - c = 2^-40) is the first-order law's; at nu = 0.49 that is 1.2 %
    # below the solver's (r = 30.9), and friction between the two was answered "full stick" with c = 1 - 2^-41 +- 2^-41
    # while the solver's 1 - c there is 1.24e-12 and 9.6e-13 (factor 1.001, 1.01 above the law's threshold): c was up to
    # 7.9e-13 off against a stated 4.5e-13. The threshold is now the law's raised by its bound (1 + 60 gamma^2; r > 0),
    # so these go to the law's c with its bound; checked against the solver's c (the default route; error ~1e-20)
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_solver import FULL_STICK_GAP
    nu = 0.49
    gamma = (1 - 2 * nu) / (2 - 2 * nu)
    mu = factor * gamma / elliptic_ratio(1.0 - FULL_STICK_GAP, FULL_STICK_GAP)
    fast = plane.flat_punch(nu=nu, mu=mu, rtol=1e-4)
    solver = plane.flat_punch(nu=nu, mu=mu)
    assert "solver" in solver.route and solver.gap > FULL_STICK_GAP
    assert abs(fast.c - solver.c) <= fast.error
