"""The engineer's route (``numeric.solutions.table_route``): for rtol >= 1e-4 ``flat_punch`` answers from
the whole-plane table, with level-0 stresses computed on first use.

References: level-3 and level-4 solves of the singular-basis solver (an independent discretisation of
higher degree: their difference from level 0 is level 0's error, to ~1e-10) at the same stick radius.
"""

import math

import numpy as np
import pytest

import numeric.core.table_data as data
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu
from numeric import flat_punch
from numeric.solutions.table_route import FIELD_ERROR, GAP_FACTOR, TABLE_RTOL

# the table's scalars against a level-3 solve: 3x its worst held-out error (tests/test_tables.py) plus the
# level-3 solution's own ~1e-12
MARGIN, SOLVER = 3.0, 2e-12

CASES = [dict(nu=0.0, c=0.5), dict(nu=-0.5, c=0.98), dict(nu=0.3, mu=0.8), dict(nu=0.45, mu=0.7),
         dict(nu=-0.9, mu=5.0), dict(nu=0.2, c=0.3)]


@pytest.mark.parametrize("case", CASES)
def test_route_is_the_table_and_its_scalars_are_the_solvers(case):
    sol = flat_punch(**case, rtol=TABLE_RTOL)
    assert sol.route.startswith("table")
    ref = flat_punch(**case, level=3)
    if "c" in case:
        assert sol.mu == pytest.approx(ref.mu, rel=MARGIN * data.ERRORS["mu"] + SOLVER)
    else:
        rel = MARGIN * max(data.ERRORS["c"], data.ERRORS["gap"]) + SOLVER
        assert sol.gap == pytest.approx(ref.gap, rel=rel) or sol.c == pytest.approx(ref.c, rel=rel)
    assert sol.compliance == pytest.approx(ref.compliance, rel=MARGIN * data.ERRORS["compliance"] + SOLVER)
    assert abs(sol.mu - ref.mu) <= sol.error or abs(sol.c - ref.c) <= sol.error  # the estimate is not optimistic


@pytest.mark.parametrize("case", CASES)
def test_stresses_meet_the_field_error_at_every_x(case):
    sol = flat_punch(**case, rtol=TABLE_RTOL)
    ref = flat_punch(nu=case["nu"], c=sol.c, level=4)
    c = sol.c
    x = np.array([0.0, 0.5 * c, c * (1 - 1e-6), c, c + 1e-6 * (1 - c), 0.5 * (1 + c), 1 - 1e-5])
    scale = np.maximum(1.0, np.abs(ref.pressure(x)))
    assert np.max(np.abs(sol.pressure(x) - ref.pressure(x)) / scale) <= FIELD_ERROR
    assert np.max(np.abs(sol.shear(x) - ref.shear(x)) / scale) <= FIELD_ERROR


def test_no_table_route_below_its_rtol_or_next_to_c_max():
    assert not flat_punch(nu=0.0, c=0.5, rtol=1e-6).route.startswith("table")
    gamma = gamma_from_nu(-0.5)
    gap = 1.05 * float(largest_stick_radius_gap(gamma))  # inside GAP_FACTOR (1 - c_max)
    assert gap < GAP_FACTOR * float(largest_stick_radius_gap(gamma))
    sol = flat_punch(nu=-0.5, c=1.0 - gap, rtol=TABLE_RTOL)
    assert not sol.route.startswith("table") and math.isfinite(sol.mu)
