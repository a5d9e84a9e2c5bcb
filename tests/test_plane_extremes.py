"""The plane API over the whole parameter range: every call gives a finite answer, or the documented exception.

A sweep over nu in [-0.999, 1/2], mu in [0, 1e300] and inf, c in [1e-300, 1], for the strip punch (given mu and
given c), the cylinder and stick_radius / friction_coefficient, with p, q, u at x = 0, c/2, c, the next double above
c, (1 + c)/2, 1 - 1e-9, 1, -1/2 and -c. Run first (by hand) it found SolverError at mu gamma beyond ~1e10, at
nu = 0.45, mu = 3 and for c above c_max at nu = -0.9; p(c) = -3017 and NaN at mu = 1e10 ... 1e16; the cylinder without
a slip; NaN with a warning from the bonded punch at x = 1. Accepted: ValueError (a point where the route does not
resolve the field, or an input outside the domain), NoEigenvalueError (c above c_max, or gamma = 0 with c < 1),
NotImplementedError (the slip below the solver's smallest c). About 20 s: slow.
"""

import math
import warnings

import numpy as np
import pytest

from numeric import plane
from numeric.core.errors import NoEigenvalueError

NUS = (-0.999, -0.9, -0.5, 0.0, 0.3, 0.45, 0.499, 0.5)
MUS = (0.0, 1e-300, 1e-8, 1e-4, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 100.0, 1e4, 1e8, 1e16, 1e300, math.inf)
CS = (1e-300, 1e-12, 1e-6, 1e-5, 1e-4, 0.01, 0.5, 0.9, 0.99, 0.999999, 1.0)


def _fields_are_finite_or_refused(solution) -> list[str]:
    c = solution.c
    x = np.array([0.0, 0.5 * c, c, np.nextafter(c, 2.0), 0.5 * (1 + c), 1 - 1e-9, 1.0, -0.5, -c])
    x = x[np.abs(x) <= 1.0]
    problems = []
    for name in ("pressure", "shear", "slip"):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                values = np.asarray(getattr(solution, name)(x), dtype=float)
        except (ValueError, NotImplementedError):
            continue
        if np.any(np.isnan(values)):
            problems.append(f"{name} NaN at {x[np.isnan(values)].tolist()}")
    return problems


def _call(f):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            return f()
        except (ValueError, NoEigenvalueError):
            return None


@pytest.mark.slow
@pytest.mark.parametrize("nu", NUS)
def test_every_friction_and_stick_width_is_answered(nu):
    problems = []
    for mu in MUS:
        for make in (lambda: plane.flat_punch(nu=nu, mu=mu), lambda: plane.power_law(2, nu=nu, mu=mu)):
            s = _call(make)
            if s is not None:
                assert not math.isnan(s.c) and (s.c == 0.0 or 0.0 < s.c <= 1.0), (nu, mu, s.c)
                problems += [f"mu = {mu}: {p}" for p in _fields_are_finite_or_refused(s)]
        _call(lambda: plane.stick_radius(mu, nu))
    for c in CS:
        s = _call(lambda: plane.flat_punch(nu=nu, c=c))
        if s is not None:
            assert not math.isnan(s.mu) and s.mu >= 0.0, (nu, c, s.mu)
            problems += [f"c = {c}: {p}" for p in _fields_are_finite_or_refused(s)]
        _call(lambda: plane.friction_coefficient(c, nu))
    assert not problems, problems


@pytest.mark.parametrize("gamma", [1e-160, 1e-310, 5e-324])
def test_below_the_solvers_smallest_coupling_the_law_and_the_uncoupled_punch_answer(gamma):
    # the solver's theta ~ gamma^2 K/K' underflows below gamma ~ 1e-155 (it gave mu = 0 at c = 1/2 and c = 0.4999 for
    # mu = 0.7817 gamma at gamma = 1e-160) and its blocks overflow below ~5e-309 (NaN stresses at 1e-308); below
    # GAMMA_FLOOR = 1e-150 mu and c are the first-order law's (its error 60 gamma^2 relative, below rounding) and the
    # stresses those of the punch without coupling (O(gamma) of max(1, |p|) off). Checked against the closed forms:
    # the law (the same expression: to the bit), Sadowsky's and Abramov's punches (to the bit, the same fields), and
    # every field finite; just above the floor the solver agrees with the law within its own error (measured 2.4e-13
    # at c = 1/2, gamma = 2e-150; bound 1e-12)
    from asymptotics.plane import bonded_traction, pressure_sadowsky, stick_width_first_order
    from numeric.core.plane_guess import elliptic_ratio
    from numeric.solutions.plane_punch import GAMMA_FLOOR
    assert gamma < GAMMA_FLOOR
    x = np.array([0.0, 0.3, 0.9, 0.99])
    half = plane.flat_punch(gamma=gamma, c=0.5)
    assert half.mu == gamma / elliptic_ratio(0.5, 0.5) and "below" in half.route
    assert np.array_equal(half.pressure(x), pressure_sadowsky(x)) and not np.any(half.shear(x))
    near = plane.flat_punch(gamma=gamma, c=1.0 - 1e-12)
    bonded = np.asarray(bonded_traction(x, gamma))
    assert np.array_equal(near.pressure(x), bonded.real) and np.array_equal(near.shear(x), bonded.imag)
    given = plane.flat_punch(gamma=gamma, mu=gamma)
    assert given.c == float(stick_width_first_order(gamma, gamma))
    for s in (half, near, given, plane.power_law(2, gamma=gamma, mu=3.0 * gamma)):
        assert not _fields_are_finite_or_refused(s)
    above = plane.flat_punch(gamma=2e-150, c=0.5)
    assert "solver" in above.route and abs(above.mu / (2e-150 / elliptic_ratio(0.5, 0.5)) - 1.0) < 1e-12
