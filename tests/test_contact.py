"""Physical units (numeric.app.contact) against the classical closed forms and the paper's scalings.

References: Hertz (sphere), Boussinesq (flat punch) and Sneddon (cone) frictionless solutions
written out here from the textbook formulas, CONTACT's combin_mater (Kalker's (1.44)) and
Dundurs' beta in its kappa form, typed in independently of numeric.app.contact.
"""

import math
import warnings

import numpy as np
import pytest

from asymptotics.adhesive import compliance_adhesive
from asymptotics.materials import gamma_dissimilar, gamma_from_nu
from numeric import flat_punch, power_law
from numeric.app.contact import (SMALL_STRAIN, Elastic, FlatPunch, MaterialPair, PowerLaw, SmallStrainWarning, elastic,
                                 indent)

GLASS = dict(E=70e9, nu=0.22)
STEEL = dict(E=210e9, nu=0.3)

# The closed forms below involve only cube roots, square roots and products: rounding is a few
# ulp, and the frictionless dimensionless inputs (P* = 2/3, A = 1 to 1e-16, p = (4/pi) sqrt(1 - x^2))
# are exact or rounding-level, so 1e-12 relative leaves a margin of ~1000 ulp.
EXACT = 1e-12


def e_star(*bodies):
    """Hertz's reduced modulus 1/sum((1 - nu^2)/E) (textbook form, rigid bodies omitted)."""
    return 1.0 / sum((1.0 - b["nu"] ** 2) / b["E"] for b in bodies)


@pytest.fixture(scope="module")
def glass_sphere():
    """Rigid 5 mm sphere, 100 N on glass, mu = 0.3: the issue's example."""
    return indent(PowerLaw.sphere(0.005), elastic(**GLASS), mu=0.3, load=100.0)


# --- frictionless limits: exact closed forms -----------------------------------------------------

@pytest.mark.parametrize("indenter", [None, STEEL])
def test_hertz_sphere_frictionless_given_load(indenter):
    R, P = 0.005, 100.0
    s = indent(PowerLaw.sphere(R), elastic(**GLASS), mu=0.0, load=P,
               indenter=None if indenter is None else elastic(**indenter))
    Es = e_star(GLASS) if indenter is None else e_star(GLASS, indenter)
    a = (3.0 * P * R / (4.0 * Es)) ** (1.0 / 3.0)  # Hertz
    assert s.contact_radius == pytest.approx(a, rel=EXACT)
    assert s.approach == pytest.approx(a * a / R, rel=EXACT)
    assert s.max_pressure == pytest.approx(3.0 * P / (2.0 * math.pi * a * a), rel=EXACT)
    assert s.max_pressure_radius == 0.0
    assert s.stiffness == pytest.approx(2.0 * Es * a, rel=EXACT)  # S = 2 E* a
    assert s.materials.reduced_modulus == pytest.approx(Es, rel=EXACT)
    assert s.max_shear == 0.0 and s.max_shear_radius is None and s.stick_radius == 0.0
    r = np.array([0.0, 0.3, 0.7, 0.99]) * a
    p0 = 3.0 * P / (2.0 * math.pi * a * a)
    # p = p0 sqrt(1 - r^2/a^2); absolute tolerance at the level of p0 (the root amplifies rounding near the edge)
    np.testing.assert_allclose(s.pressure(r), p0 * np.sqrt(1.0 - (r / a) ** 2), rtol=0, atol=EXACT * p0)
    assert s.pressure(s.contact_radius) == 0.0 and s.pressure(1.5 * a) == 0.0  # (3.7)


def test_hertz_sphere_frictionless_given_approach():
    R, delta = 0.01, 2e-6
    s = indent(PowerLaw.sphere(R), elastic(**GLASS), mu=0.0, approach=delta)
    Es = e_star(GLASS)
    a = math.sqrt(R * delta)
    assert s.contact_radius == pytest.approx(a, rel=EXACT)
    assert s.load == pytest.approx(4.0 * Es * a**3 / (3.0 * R), rel=EXACT)  # P = (4/3) E* a^3 / R


def test_boussinesq_flat_punch():
    a, P, G, nu = 1e-3, 50.0, 30e9, 0.3
    s = indent(FlatPunch(a), elastic(G=G, nu=nu), mu=0.0, load=P)
    assert s.approach == pytest.approx(P * (1.0 - nu) / (4.0 * G * a), rel=EXACT)  # P = 4 G a delta/(1 - nu)
    assert s.stiffness == pytest.approx(4.0 * G * a / (1.0 - nu), rel=EXACT)
    r = np.array([0.0, 0.5, 0.9]) * a
    np.testing.assert_allclose(s.pressure(r), P / (2.0 * math.pi * a * np.sqrt(a * a - r * r)), rtol=EXACT)
    assert math.isinf(s.max_pressure) and s.max_pressure_radius == a
    assert s.to_dict()["max_pressure"] is None  # JSON has no infinity


def test_sneddon_cone_frictionless():
    theta, delta = math.radians(70.3), 1e-6
    with pytest.warns(SmallStrainWarning):  # delta/a = (pi/2) cot(70.3 deg) = 0.56
        s = indent(PowerLaw.cone(70.3), elastic(**GLASS), mu=0.0, approach=delta)
    Es = e_star(GLASS)
    a = 2.0 * delta * math.tan(theta) / math.pi  # Sneddon: delta = (pi/2) a cot(theta)
    # A = pi/2 comes from the power-law quadrature, accurate to ~1e-14 on closed-form flat
    # solutions (numeric.solutions.power_law); 1e-11 leaves a margin
    assert s.contact_radius == pytest.approx(a, rel=1e-11)
    assert s.load == pytest.approx(2.0 / math.pi * Es * delta**2 * math.tan(theta), rel=1e-11)
    r = np.array([0.1, 0.5, 0.9]) * a
    np.testing.assert_allclose(s.pressure(r), 0.5 * Es / math.tan(theta) * np.arccosh(a / r), rtol=1e-11)  # (3.20)
    assert math.isinf(s.max_pressure) and s.max_pressure_radius == 0.0


# --- two elastic bodies and the parameters of other codes ------------------------------------------

def test_material_pair_parameters_match_other_codes():
    hs, ind = elastic(**GLASS), elastic(**STEEL)
    pair = MaterialPair(hs, ind)
    G1, n1, G2, n2 = hs.G, hs.nu, ind.G, ind.nu
    # CONTACT's combin_mater (src/m_hierarch_data.f90, Kalker's (1.44)), typed in
    G = 2.0 / (1.0 / G1 + 1.0 / G2)
    nu = G * (n1 / G1 + n2 / G2) / 2.0
    K = (G / 4.0) * ((1.0 - 2.0 * n1) / G1 - (1.0 - 2.0 * n2) / G2)
    k = pair.kalker
    assert (k.G, k.nu, k.K) == pytest.approx((G, nu, K), rel=1e-15)
    # rounding only: gamma_bar = K/(1 - nu) is an algebraic identity
    assert pair.gamma == pytest.approx(K / (1.0 - nu), rel=1e-14)
    assert pair.gamma == pytest.approx(gamma_dissimilar(G1, n1, G2, n2), rel=1e-15)
    # Dundurs' beta in the kappa form, body a = indenter, body b = half-space
    ka, kb = 3.0 - 4.0 * n2, 3.0 - 4.0 * n1
    beta = (G2 * (kb - 1.0) - G1 * (ka - 1.0)) / (G2 * (kb + 1.0) + G1 * (ka + 1.0))
    assert pair.dundurs_beta == pytest.approx(beta, rel=1e-14)
    assert pair.reduced_modulus == pytest.approx(e_star(GLASS, STEEL), rel=1e-15)
    # rigid counterpart: K = (1 - 2 nu)/2, gamma = K/(1 - nu) = (2.2)
    rigid = MaterialPair(hs)
    assert rigid.kalker.K == pytest.approx((1.0 - 2.0 * n1) / 2.0, rel=1e-15)
    assert rigid.gamma == pytest.approx(float(gamma_from_nu(n1)), rel=1e-15)
    assert rigid.modulus == pytest.approx(G1 / (1.0 - n1), rel=1e-15)
    # a very stiff indenter approaches the rigid one (relative difference ~ G1/G2 = 1e-9)
    stiff = MaterialPair(hs, Elastic(G1 * 1e9, 0.3))
    assert stiff.gamma == pytest.approx(rigid.gamma, rel=1e-8)
    assert stiff.modulus == pytest.approx(rigid.modulus, rel=1e-8)


def test_swapping_bodies_mirrors_the_shear():
    """gamma_bar -> -gamma_bar: same c, a, delta, P; shear and slip change sign (module docstring)."""
    P, R = 20.0, 0.01
    one = indent(PowerLaw.sphere(R), elastic(**GLASS), mu=0.2, load=P, indenter=elastic(**STEEL),
                 with_frictionless=False)
    two = indent(PowerLaw.sphere(R), elastic(**STEEL), mu=0.2, load=P, indenter=elastic(**GLASS),
                 with_frictionless=False)
    assert one.gamma > 0 > two.gamma and two.gamma == pytest.approx(-one.gamma, rel=1e-14)
    # the same dimensionless problem (|gamma_bar| equal to rounding) and M summed in another order:
    # the results agree to rounding (1e-12 leaves room for an ulp of gamma_bar through the solver)
    for name in ("c", "contact_radius", "approach", "stiffness", "max_pressure", "max_shear"):
        assert getattr(two, name) == pytest.approx(getattr(one, name), rel=1e-12)
    r = np.array([0.2, 0.5, 0.9, 0.99]) * one.contact_radius
    assert np.all(one.shear(r) > 0) and np.all(two.shear(r) < 0)
    np.testing.assert_allclose(two.shear(r), -one.shear(r), rtol=1e-12)
    annulus = 0.5 * (one.c + 1.0) * one.contact_radius
    assert one.slip_rate(annulus) < 0 < two.slip_rate(annulus)


def test_similar_materials_have_no_friction_effect():
    s = indent(PowerLaw.sphere(0.01), elastic(**STEEL), mu=0.5, load=10.0, indenter=elastic(**STEEL))
    assert s.gamma == 0.0 and s.max_shear == 0.0
    assert s.contact_radius == pytest.approx(s.frictionless.contact_radius, rel=EXACT)


# --- friction: the paper's scalings and physical properties ----------------------------------------

def test_issue_example_against_the_dimensionless_solver(glass_sphere):
    s = glass_sphere
    flat = flat_punch(nu=0.22, mu=0.3)
    gamma = float(gamma_from_nu(0.22))
    M = 70e9 / (2 * 1.22) / 0.78  # G/(1 - nu)
    assert s.c == pytest.approx(flat.c, rel=1e-14) and s.gamma == pytest.approx(gamma, rel=1e-15)
    # (3.2), (2.4), (3.17) by hand from A and P0*
    a = (100.0 / (4 * M * (2 / 3) * flat.compliance * 2 * (1 / 0.01) * s.A)) ** (1 / 3)
    assert s.contact_radius == pytest.approx(a, rel=1e-13)
    assert s.approach == pytest.approx(s.A * a * a / 0.005, rel=1e-13)
    assert s.stick_radius == pytest.approx(flat.c * a, rel=1e-13)
    assert s.stiffness == pytest.approx(1.5 * s.load / s.approach, rel=1e-13)  # ((n+1)/n) P/delta
    # Shield & Anderson ((2.4) ff.): a rough punch penetrates less; 1 <= P0* <= atanh(gamma)/gamma
    assert s.ratios["approach"] < 1.0 and s.ratios["load"] == 1.0
    assert 1.0 < s.ratios["stiffness"] < float(compliance_adhesive(gamma))
    # S = 4 M a P0* (module docstring) against 2 E* a0 = 4 M a0 at the same load
    assert s.ratios["stiffness"] == pytest.approx(flat.compliance * s.ratios["contact_radius"], rel=1e-13)


def test_stiffness_is_the_derivative_of_the_load(glass_sphere):
    """dP/d delta by central differences in delta at fixed mu; O(h^2) = 1e-8 truncation, so 1e-7."""
    h = 1e-4
    up, down = (indent(PowerLaw.sphere(0.005), elastic(**GLASS), mu=0.3, approach=glass_sphere.approach * f,
                       with_frictionless=False) for f in (1 + h, 1 - h))
    fd = (up.load - down.load) / (2 * h * glass_sphere.approach)
    assert glass_sphere.stiffness == pytest.approx(fd, rel=1e-7)


def test_tractions_obey_coulomb(glass_sphere):
    s = glass_sphere
    a, c = s.contact_radius, s.c
    stick = np.linspace(0.0, 0.98 * c, 25) * a
    slip = np.linspace(c + 0.02 * (1 - c), 0.99, 25) * a
    # mu p - q >= 0 in the stick zone (2.8); q = mu p in the annulus to the solver's ~1e-8
    assert np.all(s.mu * s.pressure(stick) - s.shear(stick) >= 0.0)
    np.testing.assert_allclose(s.shear(slip), s.mu * s.pressure(slip), rtol=1e-7)
    assert s.shear(0.0) == 0.0 and s.pressure(1.01 * a) == 0.0 and s.shear(2 * a) == 0.0
    assert np.all(s.slip_rate(stick) == 0.0) and np.all(s.slip_rate(slip) < 0.0)  # (2.9)
    # the maxima bound a dense sample and are attained where reported
    r = np.linspace(0.0, a, 2001)
    assert s.max_pressure >= s.pressure(r).max() and s.max_shear >= s.shear(r).max()
    # a few ulp: the radius goes through r = x a and back to x = r / a
    assert float(s.shear(s.max_shear_radius)) == pytest.approx(s.max_shear, rel=1e-14)
    assert float(s.pressure(s.max_pressure_radius)) == pytest.approx(s.max_pressure, rel=1e-14)


def test_on_grid(glass_sphere):
    s = glass_sphere
    a = s.contact_radius
    x = np.array([[0.0, 0.3 * a], [-0.5 * a, 2 * a]])
    y = np.array([[0.0, 0.4 * a], [0.1 * a, 0.0]])
    g = s.on_grid(x, y)
    r = np.hypot(x, y)
    np.testing.assert_array_equal(g.radius, r)
    np.testing.assert_array_equal(g.pressure, s.pressure(r))
    np.testing.assert_allclose(np.hypot(g.shear_x, g.shear_y), np.abs(g.shear), rtol=1e-15)
    assert g.shear_x[0, 0] == 0.0 and g.shear_x[1, 0] < 0.0  # outward shear at x < 0 points to -x
    assert (g.stick_radius, g.approach, g.load) == (s.stick_radius, s.approach, s.load)
    assert not g.pressure.flags.writeable


@pytest.mark.parametrize("shape", [FlatPunch(2e-3), PowerLaw.sphere(0.02), PowerLaw(1.5, 1.0)])  # strains 7e-5, 0.01, 0.02
def test_round_trip_load_approach_load(shape):
    """Closed-form inversions of (2.4), (3.2) on the same dimensionless solution: rounding only."""
    first = indent(shape, elastic(**GLASS), mu=0.2, load=40.0, with_frictionless=False)
    back = indent(shape, elastic(**GLASS), mu=0.2, approach=first.approach, with_frictionless=False)
    assert back.load == pytest.approx(40.0, rel=1e-13)
    assert back.contact_radius == pytest.approx(first.contact_radius, rel=1e-13)
    # the load-approach relation of the path against a fresh solve at another approach
    other = indent(shape, elastic(**GLASS), mu=0.2, approach=0.5 * first.approach, with_frictionless=False)
    assert float(first.load_at(0.5 * first.approach)) == pytest.approx(other.load, rel=1e-13)
    assert float(first.approach_at(other.load)) == pytest.approx(other.approach, rel=1e-13)


def test_spence_length_form_of_the_profile():
    """z = r^n/(n b^(n-1)) with b = R is the sphere (§3.1)."""
    assert PowerLaw.from_length(2, 0.005).k == pytest.approx(PowerLaw.sphere(0.005).k, rel=1e-15)


# --- input errors -----------------------------------------------------------------------------

SPHERE = PowerLaw.sphere(0.005)
BODY = elastic(**GLASS)


@pytest.mark.parametrize("call, name", [
    (lambda: indent(SPHERE, BODY, mu=0.3, load=-1.0), "load"),
    (lambda: indent(SPHERE, BODY, mu=0.3, load=0.0), "load"),
    (lambda: indent(SPHERE, BODY, mu=0.3, load=math.nan), "load"),
    (lambda: indent(SPHERE, BODY, mu=0.3, approach=-1e-6), "approach"),
    (lambda: indent(SPHERE, BODY, mu=0.3, load=1.0, approach=1e-6), "exactly one of load"),
    (lambda: indent(SPHERE, BODY, mu=0.3), "exactly one of load"),
    (lambda: indent(SPHERE, BODY, mu=-0.1, load=1.0), "mu"),
    (lambda: indent(SPHERE, BODY, mu=math.nan, load=1.0), "mu"),
    (lambda: PowerLaw.sphere(0.0), "radius"),
    (lambda: PowerLaw.sphere(math.inf), "radius"),
    (lambda: FlatPunch(-1e-3), "radius"),
    (lambda: PowerLaw(0.0, 1.0), "n "),
    (lambda: PowerLaw(-2.0, 1.0), "n "),
    (lambda: PowerLaw(2.0, 0.0), "k "),
    (lambda: PowerLaw.cone(30.0), "semi_angle_deg"),
    (lambda: PowerLaw.cone(math.radians(70.3)), r"semi_angle_deg .* got 1.22\d+ \(radians\? the angle is in degrees\)"),
    (lambda: elastic(E=-70e9, nu=0.2), "E "),
    (lambda: elastic(E=math.nan, nu=0.2), "E "),
    (lambda: elastic(G=0.0, nu=0.2), "G "),
    (lambda: elastic(E=70e9, G=30e9, nu=0.2), "exactly one of E"),
    (lambda: elastic(E=70e9, nu=0.6), "nu"),
    (lambda: elastic(E=70e9, nu=-1.0), "nu"),
    (lambda: elastic(E=70e9, nu=0.6, prefix="indenter_"), "indenter_nu"),
    # unit slip: E in GPa (70 instead of 70e9) gives a contact wider than the sphere
    (lambda: indent(SPHERE, elastic(E=70.0, nu=0.2), mu=0.3, load=100.0), "load = 100 N.*units"),
    (lambda: indent(FlatPunch(1e-3), BODY, mu=0.0, approach=2e-3), "approach"),
])
def test_bad_input_names_the_argument(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_ratios_need_the_frictionless_solution():
    s = indent(FlatPunch(1e-3), BODY, mu=0.3, load=10.0, with_frictionless=False)
    with pytest.raises(ValueError, match="with_frictionless"):
        s.ratios
    with pytest.raises(ValueError, match="r "):
        s.pressure(-1.0)
    with pytest.raises(ValueError, match="approach"):
        s.load_at(-1e-6)
    with pytest.raises(ValueError, match="load"):
        s.approach_at(0.0)


# --- the small-strain range of Hertz theory -------------------------------------------------------

@pytest.mark.parametrize("load, warns", [(100.0, False), (1.5e6, True)])
def test_small_strain_limit_warns(load, warns):
    # a 5 mm ball on glass: frictionless Hertz a = (3PR/4E*)^(1/3), delta = a^2/R, so delta/a = a/R is the
    # strain measure (the mean pressure/E* = 4a/(3 pi R) is smaller); closed forms of cube roots and products: 1e-12
    R = 0.005
    a = (3.0 * load * R / (4.0 * e_star(GLASS))) ** (1.0 / 3.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        s = indent(PowerLaw.sphere(R), elastic(**GLASS), mu=0.0, load=load)
    assert s.strain == pytest.approx(a / R, rel=EXACT)
    assert [w.category for w in caught] == ([SmallStrainWarning] if warns else [])
    assert (s.strain > SMALL_STRAIN) == warns
    if warns:  # the issue's 1.5 MN: a/R = 0.83; the message says what and why, once (not again for the reference)
        assert a / R == pytest.approx(0.849, abs=1e-3)  # 0.83 with mu = 0.3
        assert "a/R for a sphere" in str(caught[0].message) and "Hertz theory assumes small strains" in str(caught[0].message)
        assert s.to_dict()["warning"] == str(caught[0].message)
    else:
        assert "warning" not in s.to_dict()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        indent(PowerLaw.sphere(R), elastic(**GLASS), mu=0.3, load=load)  # with its frictionless reference
    assert len(caught) == int(warns)


@pytest.mark.parametrize("nu", [0.22, 0.45])
def test_stresses_shown_at_high_friction_are_that_friction_s(nu):
    # the issue read the stresses at mu = 1e4 as another mu's: they are this mu's solution (q = mu p on the slip
    # annulus; at nu = 0.45, 1 - c ~ 1e-23 is below what the stresses resolve and the route says they are the
    # adhesive ones), and the maxima shown are at least those of a scan (1001 points plus the annulus), to the
    # zoom's 1e-14; they agree with mu = inf to 6 digits because the stick zone saturates (c_max, 1 - c = 1.6e-5)
    s = indent(PowerLaw.sphere(0.005), elastic(**GLASS | {"nu": nu}), mu=1e4, load=100.0)
    h = power_law(2, nu=nu, mu=1e4)
    assert s.c == h.c
    x = np.unique(np.concatenate([np.linspace(0.0, 1.0, 1001), h.c + (1.0 - h.c) * np.linspace(0.0, 1.0, 21)]))
    scale = s.materials.modulus * s.approach / s.contact_radius  # (2.1)
    assert s.max_shear >= scale * np.max(np.abs(h.shear(x))) * (1 - 1e-14)
    assert s.max_pressure >= scale * np.max(h.pressure(x)) * (1 - 1e-14)
    if h.flat.route.startswith("solver"):
        annulus = h.c + (1.0 - h.c) * np.array([0.25, 0.5, 0.75])
        np.testing.assert_allclose(h.flat.shear(annulus), 1e4 * h.flat.pressure(annulus), rtol=1e-12)  # (2.8)
    else:
        assert h.flat.route.startswith("adhesive stresses")


def test_to_dict_is_strict_json_where_a_modulus_overflows():
    # E = 1.8e308 with nu != 0 makes the reduced modulus (and the indenter's E from G) inf; to_dict promises None for
    # infinities at every depth, so that --json can write strict JSON (it failed: "Out of range float values")
    import json

    from numeric.app.plane_contact import press_cylinder, press_strip

    huge = elastic(E=1.7976931348623157e308, nu=0.3)
    results = [press_strip(0.005, huge, mu=0.3, load=1e5), press_cylinder(0.005, huge, mu=0.3, load=1e5),
               indent(FlatPunch(0.005), elastic(E=1e300, nu=0.0), mu=0.3, approach=1e-300, indenter=huge)]
    for r in results:
        d = r.to_dict()
        json.dumps(d, allow_nan=False)
    assert results[0].to_dict()["materials"]["reduced_modulus"] is None
    assert results[2].to_dict()["materials"]["indenter"]["E"] is None
