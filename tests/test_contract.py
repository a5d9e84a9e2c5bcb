"""Every input gets an answer or a clear error (issue 13), by property.

For each public function (``numeric.__all__``, ``asymptotics.__all__``, the SI calculator of
``numeric.app.contact``) hypothesis draws each argument over the whole float range (0, -0, subnormals,
1e300, +-inf, NaN), as numpy scalars, one-element and empty arrays, arrays holding NaN or inf,
arrays of mismatched shapes, and wrong types (None, strings, booleans, complex numbers, objects). The
outcome must be one of

* a result with no NaN, and no inf except where documented (mu = inf for c = 1 or the slip limit, the
  stresses at the edge x = 1 of a flat punch, the pressure at the apex of an n <= 1 indenter);
* a ``ValueError`` or ``TypeError`` whose message names the argument;
* a documented exception of valid input: ``NoEigenvalueError`` where no friction coefficient gives c (c at
  or above c_max, or c < 1 at gamma = 0), the ``ValueError`` of ``stick_radius_approach`` where the slip
  annulus is below what the solver resolves;

and no warning may leak except the documented ``AccuracyWarning`` and ``SmallStrainWarning``.
The command line is held to the same contract: exit 0, or 1 with one line on stderr (no solution or a
numerical failure), or 2 with one line (or argparse's usage), never a traceback.

The profile of ``tests/conftest.py`` is derandomised and bounded (30 examples a test).
"""

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import asymptotics
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu
from numeric import (AccuracyWarning, NoEigenvalueError, flat_punch, friction_coefficient, largest_stick_radius,
                     power_law, slip_limit, stick_radius, stick_radius_approach)
from numeric.app.cli import main
from numeric.app.contact import FlatPunch, PowerLaw, SmallStrainWarning, elastic, indent

FLOATS = st.floats(allow_nan=True, allow_infinity=True)  # the whole range: +-0, subnormals, 1e308, +-inf, nan
WRONG = st.sampled_from([None, "0.3", "", True, False, 0.3 + 0.1j, object(), [0.1, "x"], {"mu": 0.3}])
SCALARS = st.one_of(FLOATS, st.integers(-3, 3), FLOATS.map(np.float64), FLOATS.map(lambda v: np.array([v])), WRONG)
ARRAYS = st.one_of(
    SCALARS,
    st.lists(FLOATS, max_size=3).map(np.array),  # empty arrays, NaN and inf inside
    st.lists(st.lists(FLOATS, min_size=2, max_size=2), min_size=1, max_size=2).map(np.array),  # 2-d
    st.integers(0, 4).map(lambda n: np.linspace(0.1, 0.9, n)),  # shapes that may not broadcast
)
DOCUMENTED_WARNINGS = (AccuracyWarning, SmallStrainWarning)


def either(valid: st.SearchStrategy) -> st.SearchStrategy:
    """Half the draws from the valid range (so that results are checked too), the rest from anything."""
    return st.one_of(valid, SCALARS)


NU = either(st.floats(-0.999, 0.5))
GAMMA = either(st.floats(0.0, 0.75))
MATERIAL = st.one_of(st.tuples(st.just("nu"), NU), st.tuples(st.just("gamma"), GAMMA))
VALID_MATERIAL = st.one_of(st.tuples(st.just("nu"), st.floats(-0.999, 0.5)), st.tuples(st.just("gamma"), st.floats(0.0, 0.75)))


def cases(valid: st.SearchStrategy, wild: st.SearchStrategy) -> st.SearchStrategy:
    """Half the cases with every argument valid (so that results are checked), half with any argument wild."""
    return st.one_of(valid, wild)


def outcome(call):
    """(value, the ValueError/TypeError or None, the warnings) of ``call()``; other exceptions propagate."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            value, error = call(), None
        except (ValueError, TypeError) as exc:
            value, error = None, exc
    leaked = [w for w in caught if not issubclass(w.category, DOCUMENTED_WARNINGS)]
    assert not leaked, [f"{w.category.__name__}: {w.message}" for w in leaked]
    return value, error


def names_one_of(error: Exception, *names: str) -> bool:
    return any(name in str(error) for name in names)


def no_nan(*values) -> bool:
    return all(not np.any(np.isnan(np.asarray(v, dtype=float))) for v in values)


def _no_eigenvalue_is_documented(exc: NoEigenvalueError, c: float, gamma: float) -> bool:
    # c at or above c_max (to the solver's rounding near it), or c < 1 without coupling
    return gamma == 0.0 or 1.0 - c <= 2.0 * float(largest_stick_radius_gap(gamma)) + 1e-15


# ----------------------------------------------------------------------------- asymptotics.__all__
@given(c=ARRAYS)
def test_mu_over_gamma(c):
    value, error = outcome(lambda: asymptotics.mu_over_gamma(c))
    if error is not None:
        assert names_one_of(error, "c "), error
    else:  # (2.28): finite on (0, 1), inf at c = 1 only
        arr = np.asarray(value, dtype=float)
        assert no_nan(arr) and np.all(arr >= 0.0)
        assert np.all(np.isfinite(arr) | (np.asarray(c, dtype=float) == 1.0))


@given(x=ARRAYS, c=ARRAYS)
def test_psi(x, c):
    value, error = outcome(lambda: asymptotics.psi(x, c))
    if error is not None:
        assert names_one_of(error, "x", "c ", "shape", "broadcast"), error
    else:  # 0 <= psi <= 1 on the stick zone (psi(0) = 1, psi(c) = 0)
        arr = np.asarray(value, dtype=float)
        assert no_nan(arr) and np.all((arr >= -1e-15) & (arr <= 1.0 + 1e-15))


@given(mu=st.one_of(st.floats(0.0, 10.0), ARRAYS), material_m=MATERIAL, order=either(st.sampled_from([0, 2])))
def test_asymptotic_stick_radius(mu, material_m, order):
    material, m = material_m
    value, error = outcome(lambda: asymptotics.stick_radius(mu, **{material: m}, order=order))
    if error is not None:
        assert names_one_of(error, "mu", material, "order", "exactly one", "shape", "broadcast"), error
    else:
        arr = np.asarray(value, dtype=float)
        assert no_nan(arr) and np.all((arr >= 0.0) & (arr <= 1.0))


# ----------------------------------------------------------------------------- numeric.__all__
OPTION = st.sampled_from([{}, {"level": 0}, {"rtol": 1e-4}])
VALID_GIVEN = st.one_of(st.tuples(st.just("mu"), st.floats(0.0, 1e3)), st.tuples(st.just("c"), st.floats(1e-6, 1.0)))
GIVEN = st.one_of(st.tuples(st.just("mu"), either(st.floats(0.0, 1e3))), st.tuples(st.just("c"), either(st.floats(1e-6, 1.0))))


@given(case=cases(st.tuples(VALID_MATERIAL, VALID_GIVEN, OPTION, st.none()),
                  st.tuples(MATERIAL, GIVEN, OPTION, st.one_of(st.none(), SCALARS))))
def test_flat_punch(case):
    (material, m), (given_, v), option, bad_option = case
    kwargs = {material: m, given_: v, **option}
    if bad_option is not None:  # a drawn value for the option instead
        kwargs[next(iter(option), "level")] = bad_option
    try:
        sol, error = outcome(lambda: flat_punch(**kwargs))
    except NoEigenvalueError as exc:
        gamma = float(m) if material == "gamma" else float(gamma_from_nu(m))
        assert given_ == "c" and _no_eigenvalue_is_documented(exc, float(np.asarray(v)), gamma), exc
        return
    if error is not None:
        assert names_one_of(error, material, given_, "level", "rtol", "exactly one"), error
        return
    assert 0.0 <= sol.c <= 1.0 and sol.mu >= 0.0 and math.isfinite(sol.compliance) and math.isfinite(sol.error)
    assert math.isfinite(sol.mu) or sol.c == 1.0 or "c_max to rounding" in sol.route  # documented mu = inf
    x = np.array([0.0, 0.5, 0.999])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.all(np.isfinite(sol.pressure(x))) and np.all(np.isfinite(sol.shear(x)))


@given(first=ARRAYS, nu=ARRAYS, inverse=st.booleans())
def test_sweeps_over_arrays(first, nu, inverse):
    # use_table=False would solve every point; the table answers inside its domain, flat_punch the rest
    call = friction_coefficient if inverse else stick_radius
    try:
        value, error = outcome(lambda: call(first, nu, progress=False))
    except NoEigenvalueError as exc:
        assert inverse and ("largest stick radius" in str(exc) or "gamma = 0" in str(exc)), exc
        return
    if error is not None:
        assert names_one_of(error, "c " if inverse else "mu", "nu", "shape", "broadcast"), error
        return
    arr = np.asarray(value, dtype=float)
    assert arr.shape == np.broadcast_shapes(np.shape(first), np.shape(nu))
    assert no_nan(arr)
    if inverse:  # mu = inf only at c = 1 (or at c_max to rounding)
        assert np.all(np.isfinite(arr) | (np.broadcast_to(np.asarray(first, dtype=float), arr.shape) >= 0.99))
    else:
        assert np.all((arr >= 0.0) & (arr <= 1.0))


@given(n=either(st.floats(0.5, 8.0)), mu=either(st.sampled_from([0.0, 0.3, math.inf])))
def test_power_law(n, mu):
    value, error = outcome(lambda: power_law(n, nu=0.3, mu=mu))
    if error is not None:
        assert names_one_of(error, "n ", "mu"), error
        return
    C, _ = outcome(lambda: value.C)  # an AccuracyWarning where C lost digits (documented)
    assert math.isfinite(value.A) and math.isfinite(value.compliance) and no_nan(C)
    assert math.isfinite(C) or (0.5 * value.c) ** value.n < np.finfo(float).tiny  # documented: |C| ~ c^-n
    x = np.array([0.1, 0.5, 1.0])
    assert np.all(np.isfinite(value.pressure(x))) and np.all(np.isfinite(value.shear(x)))


@given(material=st.sampled_from(["nu", "gamma"]), m=st.one_of(st.floats(-0.999, 0.5), ARRAYS))
def test_largest_stick_radius(material, m):
    value, error = outcome(lambda: largest_stick_radius(**{material: m}))
    if error is not None:
        assert names_one_of(error, material, "exactly one"), error
    else:
        arr = np.asarray(value, dtype=float)
        assert no_nan(arr) and np.all((arr > 0.9) & (arr <= 1.0))  # c_max > 0.98 for every gamma <= 3/4


@given(material_m=MATERIAL, level=either(st.sampled_from([0, 1])))
def test_slip_limit_and_its_approach(material_m, level):
    material, m = material_m
    value, error = outcome(lambda: slip_limit(**{material: m}, level=level))
    if error is not None:
        assert names_one_of(error, material, "level", "exactly one"), error
        return
    assert math.isinf(value.mu) and 0.9 < value.c <= 1.0 and math.isfinite(value.compliance)
    approach, error = outcome(lambda: stick_radius_approach(**{material: m}, level=level))
    if error is not None:  # documented: the annulus is thinner than the solver resolves
        assert "below what the solver resolves" in str(error), error
    else:
        assert math.isfinite(approach) and approach > 0.0


# ----------------------------------------------------------------------------- the SI calculator
SHAPES = st.sampled_from(["sphere", "cone", "punch", "power", "length"])
LOADING = st.sampled_from(["load", "approach"])


@given(case=cases(st.tuples(SHAPES, st.floats(1e-4, 80.0), st.floats(1e3, 1e12), st.floats(-0.999, 0.5),
                            st.sampled_from([0.0, 0.3, 1.0]), LOADING, st.floats(1e-9, 1e3)),
                  st.tuples(SHAPES, either(st.floats(1e-4, 80.0)), either(st.floats(1e3, 1e12)), NU,
                            either(st.sampled_from([0.0, 0.3])), LOADING, either(st.floats(1e-9, 1e3)))))
def test_indent(case):
    shape, size, E, nu, mu, given_, amount = case

    def make():
        body = elastic(E=E, nu=nu)
        indenter = {"sphere": lambda: PowerLaw.sphere(size), "cone": lambda: PowerLaw.cone(size),
                    "punch": lambda: FlatPunch(size), "power": lambda: PowerLaw(size, 1.0),
                    "length": lambda: PowerLaw.from_length(2.0, size)}[shape]()
        return indent(indenter, body, mu=mu, **{given_: amount})

    contact, error = outcome(make)
    if error is not None:
        assert names_one_of(error, "radius", "semi_angle_deg", "n ", "b ", "E ", "G ", "nu", "mu", given_), error
        return
    scalars = [contact.contact_radius, contact.approach, contact.load, contact.stiffness, contact.mean_pressure,
               contact.strain, contact.c, contact.compliance, contact.error]
    assert all(math.isfinite(v) and v >= 0.0 for v in scalars), scalars
    # documented infinities: the flat punch's edge (pressure, and shear with friction) and an n <= 1 apex
    singular = shape == "punch" or (shape == "power" and float(np.asarray(size)) <= 1.0) or shape == "cone"
    assert singular or (math.isfinite(contact.max_pressure) and math.isfinite(contact.max_shear))
    r = np.array([0.0, 0.5, 2.0]) * contact.contact_radius
    assert no_nan(contact.pressure(r), contact.shear(r))
    if contact.route.startswith("asymptotic"):  # documented: the law (c < 1e-5) has no slip displacement
        with pytest.raises(NotImplementedError, match="slip displacement"):
            contact.slip_rate(r)
    else:
        assert no_nan(contact.slip_rate(r))


@given(r=ARRAYS, other=ARRAYS)
def test_contact_methods(glass_contact, r, other):
    for method, name in ((glass_contact.pressure, "r"), (glass_contact.shear, "r"), (glass_contact.slip_rate, "r"),
                         (glass_contact.load_at, "approach"), (glass_contact.approach_at, "load")):
        value, error = outcome(lambda: method(r))
        if error is not None:
            assert names_one_of(error, name), error
        else:
            assert no_nan(value) and np.all(np.isfinite(np.asarray(value, dtype=float)))
    grid, error = outcome(lambda: glass_contact.on_grid(r, other))
    if error is not None:
        assert names_one_of(error, "x", "y", "shape", "broadcast"), error
    else:
        assert no_nan(grid.pressure, grid.shear_x, grid.shear_y, grid.slip_rate)


@pytest.fixture(scope="module")
def glass_contact():
    return indent(PowerLaw.sphere(0.005), elastic(E=70e9, nu=0.22), mu=0.3, load=100.0)


# ----------------------------------------------------------------------------- the command line
# capsys is read out after every example, so sharing it between examples is safe
CAPTURED = settings(suppress_health_check=[HealthCheck.function_scoped_fixture])
NUMBER_TEXT = st.one_of(FLOATS.map(repr), st.sampled_from(["1e309", "-0", "0x10", "1,2", "", " ", "abc", "--", "1:2:3"]))
PHYSICAL = {
    "sphere": ["--radius"], "punch": ["--radius"], "cone": ["--semi-angle-deg"], "power-law": ["--n", "--k"],
}


@CAPTURED
@given(command=st.sampled_from(sorted(PHYSICAL)), values=st.lists(NUMBER_TEXT, min_size=6, max_size=6),
       given_=st.sampled_from(["--load", "--approach"]), modulus=st.sampled_from(["--E", "--G"]),
       extra=st.sampled_from([[], ["--json"], ["--indenter-E", "200e9", "--indenter-nu", "0.3"], ["--level", "7"]]))
def test_command_line_physical(capsys, command, values, given_, modulus, extra):
    options = PHYSICAL[command] + [given_, modulus, "--nu", "--mu"]
    argv = [command] + [token for option, value in zip(options, values) for token in (option, value)] + extra
    _one_line_or_success(capsys, argv)


@CAPTURED
@given(material=st.sampled_from(["--nu", "--gamma"]), m=NUMBER_TEXT, which=st.sampled_from(["--mu", "--c"]),
       v=NUMBER_TEXT, n=st.one_of(st.none(), NUMBER_TEXT), json_=st.booleans())
def test_command_line_solve(capsys, material, m, which, v, n, json_):
    argv = ["solve", material, m, which, v] + ([] if n is None else ["--n", n]) + (["--json"] if json_ else [])
    _one_line_or_success(capsys, argv)


@CAPTURED
@given(mu=st.one_of(NUMBER_TEXT, st.sampled_from(["0.1:0.3:2", "0.3:0.1:0", "0.1,nan", "1:2:1e9x"])),
       nu=st.one_of(NUMBER_TEXT, st.sampled_from(["0,0.25", "-0.9:0.49:2", "0.5"])),
       options=st.sampled_from([[], ["--format", "json"], ["--sphere"], ["--level", "1"], ["--quiet"]]))
def test_command_line_table(capsys, mu, nu, options):
    _one_line_or_success(capsys, ["table", "--mu", mu, "--nu", nu, *options], rows_may_fail=True)


@pytest.mark.parametrize("argv", [
    ["figures", "--format", "bmp"], ["figures", "--only", "no-such-figure", "--output", "/nonexistent/x"],
    ["bench", "--output"], ["stability", "--quick", "--output"], ["derivations", "--directory"],
    ["tables", "--fast"], ["table", "--mu", "0.3"], ["solve", "--nu", "0.3"], ["sphere", "--radius", "1"],
    ["cone", "--semi-angle-deg", "1.2", "--load", "1", "--E", "1e9", "--nu", "0.3", "--mu", "0.3"],
])
def test_command_line_bad_usage_of_every_subcommand(capsys, argv):
    code, _, err = _one_line_or_success(capsys, argv)
    assert code == 2 and err


def _one_line_or_success(capsys, argv, rows_may_fail=False):
    code = main(argv)
    out, err = capsys.readouterr()
    assert "Traceback" not in err and "Traceback" not in out, (argv, err)
    if code == 0:
        assert out and (not err or "%|" in err), (argv, err)  # a progress bar at most
    elif code == 1:
        kinds = ("no solution:", "numerical failure:") + (("rows failed",) if rows_may_fail else ())
        assert any(k in err for k in kinds) and err.count("\n") <= 1 + rows_may_fail, (argv, err)
    else:
        assert code == 2, (argv, code, err)
        assert err.startswith("usage:") or (err.startswith(f"hertz-friction {argv[0]}: error: ") and err.count("\n") == 1), \
            (argv, err)
    return code, out, err


# ----------------------------------------------------------------------------- what the properties found
def test_what_the_property_tests_found_answers_now():
    # each case returned NaN, raised something unnamed or warned before. 1 - psi at x = 1e-20 against mpmath's
    # psi_mp at 60 digits, within the fast form's rounding (about 20 operations and 4 elliptic-integral calls:
    # rounding_bound(20, 4) = 5.9e-15); c = 1 in double where mu/gamma exceeds 12 (2.29), and at gamma = 0
    import mpmath

    from asymptotics.derivation import rounding_bound
    from asymptotics.first_order import psi_mp, shear_ratio_first_order

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert float(asymptotics.psi(5e-324, 0.5)) == 1.0
        with mpmath.workdps(80):
            exact = float(1 - psi_mp(1e-20, 0.5, dps=60))
        assert float(shear_ratio_first_order(1e-20, 0.5)) == pytest.approx(exact, rel=rounding_bound(20, 4))
        assert float(asymptotics.stick_radius(1e300, nu=0.3)) == 1.0
        assert float(asymptotics.stick_radius(0.3, gamma=1e-300)) == 1.0
        assert float(asymptotics.stick_radius(1.0, gamma=0.0, order=2)) == 1.0
        assert float(largest_stick_radius(gamma=5e-324)) == 1.0
        assert 0.0 < float(friction_coefficient(5e-324, 0.3, progress=False)) < 1e-3
    for call, name in ((lambda: power_law("2", nu=0.3, mu=0.3), "n"), (lambda: flat_punch(nu=0.3, mu=True), "mu"),
                       (lambda: flat_punch(nu=0.3, mu=0.3, rtol="1e-3"), "rtol"),
                       (lambda: slip_limit(nu=np.array([0.0])), None), (lambda: slip_limit(nu=0.0, level=0.5), "level"),
                       (lambda: PowerLaw.sphere("0.005"), "radius")):
        value, error = outcome(call)
        assert (error is None) if name is None else (error is not None and str(error).startswith(name)), (name, error)
    with pytest.raises(ValueError, match="^load = 5e-324 N: .* overflow or underflow"):
        indent(PowerLaw.sphere(0.005), elastic(E=70e9, nu=0.22), mu=0.3, load=5e-324)
