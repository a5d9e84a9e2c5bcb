"""Power-law indenters from the real frictional flat-punch solution (§3), 0 < c < 1.

tests/test_power_law.py checks the transforms on closed-form flat solutions; here the flat
solution is the solver's, and the checks are the structural identities of §3 and the
paper's numbers.
"""

import math

import numpy as np
import pytest

from numeric import flat_punch, power_law
from numeric.studies.paper_tables import PAPER
from numeric.solutions.power_law import displacement_constant, indentation_constant_316
from numeric.baseline.scheme import solve_friction, sphere_from_flat


@pytest.fixture(scope="module")
def sphere():
    return power_law(2, nu=0.0, c=0.5)


def test_stick_radius_and_compliance_3_17(sphere):
    flat = flat_punch(nu=0.0, c=0.5)
    assert sphere.c == flat.c and sphere.mu == flat.mu  # §3.2: same c for every n
    assert sphere.compliance == pytest.approx(2 / 3 * flat.compliance, rel=1e-15)  # (3.17)


def test_edge_stresses_vanish_3_7(sphere):
    # p(1) = q(1) = 0 (3.7); just inside, p ~ (1 - x)^(alpha + 1/2) -> 0.
    assert sphere.pressure(1.0) == 0.0 and sphere.shear(1.0) == 0.0
    assert sphere.pressure(1 - 1e-10) < 1e-4


def test_centre_pressure_3_18(sphere):
    # (3.18): p(0) = n/(n-1) p0(0) = 2 p0(0) for the sphere; the quadrature near x = 0 must
    # approach it (p(x) - p(0) = O(x), so 1e-7 at x = 1e-8 with margin).
    p0 = sphere.flat.pressure(0.0)
    assert sphere.pressure(0.0) == pytest.approx(2 * p0, rel=1e-15)
    assert sphere.pressure(1e-8) == pytest.approx(2 * p0, rel=1e-7)


def test_friction_inequality_3_14(sphere):
    # (3.14): mu p - q > 0 on (0, c) and = 0 on (c, 1) (to rounding of O(1) values).
    x = np.linspace(0.0, 1.0, 401)
    excess = sphere.mu * sphere.pressure(x) - sphere.shear(x)
    stick, slip = x < sphere.c - 1e-3, x > sphere.c
    assert np.all(excess[stick] > 0.0)
    assert np.max(np.abs(excess[slip])) < 1e-13


def test_two_routes_to_A_and_two_points_for_C(sphere):
    # A from the (3.5a)-at-x=1 identity and from (3.16) differ by the flat solution's
    # error (~1e-10 at level 2; measured 7e-11); C from (3.5b) at two stick points likewise.
    assert indentation_constant_316(sphere.flat, 2) == pytest.approx(sphere.A, abs=5e-10)
    c1 = displacement_constant(sphere.flat, 2, x=0.1 * sphere.c)
    c2 = displacement_constant(sphere.flat, 2, x=0.8 * sphere.c)
    assert c1 == pytest.approx(c2, abs=5e-10)
    assert c1 == pytest.approx(sphere.C, abs=5e-10)


def test_A_between_hertz_and_adhesive():
    # Friction stiffens the contact: 1/A falls from 1 (Hertz, (3.19)) toward the adhesive
    # 1/A of (4.18) as c grows (delta = A a^2/R at fixed a needs more load with friction).
    inv_a = [1 / power_law(2, nu=0.0, c=c, level=1).A for c in (0.2, 0.5, 0.8)]
    assert 1.0 > inv_a[0] > inv_a[1] > inv_a[2] > 1 / power_law(2, nu=0.0, mu=math.inf).A


@pytest.mark.parametrize("key", [k for k in PAPER["mu_inverse_A"] if k[1] < 1.0])
def test_inverse_A_against_the_paper(key):
    # The paper rates its alpha1 estimate of 1/A as accurate to "about half a percent";
    # our exact 1/A must lie within 0.6 % of its table. The paper's scheme run by us gives
    # alpha1 within 3e-4 of our exact value (measured), so the table's 0.4 % offset is the
    # paper's, not the scheme's.
    nu, c = key
    inv_a = 1 / power_law(2, nu=nu, c=c, level=1).A
    assert inv_a == pytest.approx(PAPER["mu_inverse_A"][key][1], rel=6e-3)
    alpha1 = sphere_from_flat(solve_friction(c, nu)).alpha1
    assert alpha1 == pytest.approx(inv_a, abs=1e-3)


def test_A_and_C_are_computed_on_first_access_and_kept(monkeypatch):
    from numeric.solutions import power_law as pl

    calls = []
    real = pl.indentation_constant
    monkeypatch.setattr(pl, "indentation_constant", lambda flat, n: calls.append(n) or real(flat, n))
    h = pl.power_law(2, nu=0.25, c=0.5, level=1)
    assert calls == []  # not computed when only c, mu, compliance are wanted
    first = h.A
    assert h.A == first and calls == [2.0]  # computed once, then reused


def test_C_at_the_finest_level_survives_pieces_shorter_than_the_node_spacing():
    # level 4 grades the mesh toward c = 0.5 until Gauss nodes of the shortest pieces coincide in
    # doubles (this raised LinAlgError); C must still converge: levels 3 and 4 agree to the level-3
    # accuracy (~1e-11, README).
    fine = power_law(2, nu=0.25, c=0.5, level=4)
    assert abs(fine.C - power_law(2, nu=0.25, c=0.5, level=3).C) < 1e-10
