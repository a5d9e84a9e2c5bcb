"""The plane-strain calculator and command line: ``numeric.app.plane_contact``, ``hertz-friction cylinder|strip``."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from numeric import plane
from numeric.app import cli
from numeric.app.contact import elastic
from numeric.app.plane_contact import press_cylinder, press_strip

GLASS = elastic(E=70e9, nu=0.22)


def test_frictionless_cylinder_is_hertz():
    # a = sqrt(4 R P/(pi E*)), p_max = 2 P/(pi a) (plane-strain Hertz), to rounding (K0 = 2/pi to 5e-14)
    c = press_cylinder(0.005, GLASS, mu=0.0, load=1e5)
    e_star = 2.0 * GLASS.G / (1.0 - GLASS.nu)
    a = math.sqrt(4 * 0.005 * 1e5 / (math.pi * e_star))
    assert c.half_width == pytest.approx(a, rel=1e-13) and c.frictionless_half_width == pytest.approx(a, rel=1e-15)
    assert c.max_pressure == pytest.approx(2e5 / (math.pi * a), rel=1e-13) and c.max_shear == 0.0


def test_cylinder_with_friction_scales_the_dimensionless_solution():
    c = press_cylinder(0.005, GLASS, mu=0.3, load=1e5)
    h = plane.power_law(2, nu=0.22, mu=0.3)
    assert c.c == h.c and c.stick_half_width == pytest.approx(h.c * c.half_width, rel=1e-15)
    # P = M a^2/(K R): the load-width relation with the strip punch's load factor (numeric.solutions.plane_power_law)
    M = GLASS.G / (1.0 - GLASS.nu)
    assert M * c.half_width**2 / (h.load_factor * 0.005) == pytest.approx(1e5, rel=1e-13)
    assert c.centre_pressure == pytest.approx(1e5 / c.half_width * float(h.pressure(0.0)), rel=1e-13)
    assert c.half_width < c.frictionless_half_width  # friction stiffens the contact: smaller a at the same load
    # the largest accumulated slip (bounded search to 1e-9 in x) against grids: 21 points over the slip zone (none
    # beyond it) and 41 points 1e-3 apart about it (equal within the grid's resolution: the slip is flat at its
    # extremum, (0.5e-3)^2 u''/u ~ 1e-6 relative)
    import numpy as np
    at = c.max_slip_at / c.half_width
    assert h.c < at < 1.0
    coarse = np.asarray(h.slip(np.linspace(h.c, 1.0, 21))) * 1e5 / M
    fine = np.asarray(h.slip(np.clip(at + 1e-3 * np.arange(-20, 21), h.c, 1.0))) * 1e5 / M
    lowest = min(coarse.min(), fine.min())  # the fine grid holds the optimum itself: the same value to rounding
    assert c.max_slip <= lowest + 1e-12 * abs(lowest) and lowest < 0.0
    assert c.max_slip == pytest.approx(fine.min(), rel=1e-5)


def test_strip_slip_and_sadowsky():
    s = press_strip(0.001, GLASS, mu=0.0, load=1e5)
    M = GLASS.G / (1.0 - GLASS.nu)
    g = (1 - 2 * 0.22) / (2 - 2 * 0.22)
    assert s.centre_pressure == pytest.approx(1e5 / (math.pi * 0.001), rel=1e-15)
    assert s.slip_edge == pytest.approx(-(g / 2) * 1e5 / M, rel=1e-14)  # u = -(gamma/pi) asin(x) at x = 1
    f = press_strip(0.001, GLASS, mu=0.3, load=1e5)
    assert -(g / 2) * 1e5 / M < f.slip_edge < 0.0  # friction reduces the inward slip
    assert math.isinf(f.max_pressure)


def test_command_line(capsys):
    assert cli.main(["cylinder", "--radius", "0.005", "--load-per-length", "1e5", "--E", "70e9", "--nu", "0.22",
                     "--mu", "0.3", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["c"] == pytest.approx(plane.power_law(2, nu=0.22, mu=0.3).c, rel=1e-12)
    assert cli.main(["strip", "--half-width", "0.001", "--load-per-length", "1e5", "--G", "3e10", "--nu", "0.3",
                     "--mu", "0.5", "--indenter-E", "2e11", "--indenter-nu", "0.3"]) == 0
    assert "strip punch, half-width 1 mm" in capsys.readouterr().out
    assert cli.main(["cylinder", "--radius", "0.005", "--load-per-length", "-1", "--E", "70e9", "--nu", "0.22",
                     "--mu", "0.3"]) == 2
    assert "load" in capsys.readouterr().err


def test_extreme_moduli_give_a_finite_answer_or_a_clear_error():
    # E = 1.8e308 made pi M overflow and Hertz's half-width 0 (ZeroDivisionError; the CLI printed a traceback): the
    # half-widths now from logarithms where the product leaves the doubles, checked against the plane-strain Hertz
    # a = sqrt(4 R P/(pi E*)) formed in logarithms by hand (to 1e-13: exp/log rounding over |log a| = 352)
    huge = elastic(E=1.7976931348623157e308, nu=0.3)
    c = press_cylinder(0.005, huge, mu=0.3, load=1e5)
    e_star = 2.0 * huge.G / (1.0 - huge.nu)
    a_hertz = math.exp(0.5 * (math.log(4 * 0.005 * 1e5) - math.log(math.pi) - math.log(e_star)))
    assert c.frictionless_half_width == pytest.approx(a_hertz, rel=1e-13)
    assert math.isfinite(c.half_width) and c.half_width > 0.0 and math.isfinite(c.max_pressure)
    assert cli.main(["cylinder", "--radius", "0.005", "--load-per-length", "1e5", "--E", "1.7976931348623157e308",
                     "--nu", "0.3", "--mu", "0.3"]) == 0
    with pytest.raises(ValueError, match="half-width"):
        press_cylinder(1e300, elastic(E=1e-300, nu=0.3), mu=0.3, load=1e300)
    # gamma_bar = 2.9e-28 (a soft indenter on nu -> -1): full stick at once (it took 8 s, then SolverError)
    soft = press_cylinder(0.005, elastic(E=70e9, nu=-0.9999999), mu=0.3, load=1e5,
                          indenter=elastic(E=1e-10, nu=0.5))
    assert soft.route.startswith("full stick") and soft.c > 1 - 1e-12


def test_next_to_full_stick_at_tiny_gamma_the_calculator_gives_the_stresses():
    # nu = 0.49999 (gamma = 2e-5, below FIRST_ORDER_GAMMA = 3e-5), mu = 1.6e-4: 1 - c = 9.7e-11, below the small-gamma
    # series' reach, where mu and c are the first-order law's. The strip punch's stresses were not computed there
    # (NotImplementedError: the strip's centre pressure and slip None, the cylinder a ValueError); now they are the
    # solver's at c (within 7.8e-10 of level 4 down to gamma = 1e-100, ``numeric.solutions.plane_small_gamma``).
    # Checked: the strip's centre pressure against Abramov's bonded punch (a closed form), which slip zones of 1e-10
    # change at x = 0 by far less than the bound 1e-10 (measured 1.3e-15 relative here, 8e-15 at gamma = 1e-6), and the
    # cylinder's half-width against Hertz's, which the coupling changes by O(gamma^2) (measured -0.37 gamma^2; bound
    # 10 gamma^2, as the strip punch's p(0) test at small gamma)
    from asymptotics.plane import bonded_traction
    body = elastic(E=70e9, nu=0.49999)
    strip = press_strip(0.005, body, mu=1.6e-4, load=1e5)
    g = strip.gamma
    assert strip.route.startswith("near full stick") and "first-order law" in strip.route
    bonded = float(np.real(bonded_traction(np.array([0.0]), g))[0]) * 1e5 / 0.005
    assert abs(strip.centre_pressure / bonded - 1.0) < 1e-10 and strip.slip_edge < 0.0
    cylinder = press_cylinder(0.005, body, mu=1.6e-4, load=1e5)
    assert abs(cylinder.half_width / cylinder.frictionless_half_width - 1.0) < 10 * g * g


