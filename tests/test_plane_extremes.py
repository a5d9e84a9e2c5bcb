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
