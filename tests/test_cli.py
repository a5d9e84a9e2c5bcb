"""The ``hertz-friction`` command line: output, JSON contract and exit codes (via ``main(argv)``)."""

import csv
import io
import json
import math
import sys

import pytest

import numeric
from numeric import SolverError, flat_punch, stick_radius
from numeric.app.cli import main

EXAMPLE = ["sphere", "--radius", "0.005", "--load", "100", "--E", "70e9", "--nu", "0.22", "--mu", "0.3", "--json"]
KEYS = {"contact_radius", "stick_radius", "approach", "max_pressure", "max_shear", "stiffness"}


def run(capsys, argv):
    code = main(argv)
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(scope="module")
def example_json():
    """The issue's call; run once (module scope cannot use capsys, so redirect by hand)."""
    import contextlib

    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        code = main(EXAMPLE)
    assert code == 0
    text = buffer.getvalue()
    assert text.count("\n") == 1  # one JSON object on one line
    return json.loads(text)


def test_issue_example_keys(example_json):
    d = example_json
    assert KEYS <= set(d) and KEYS <= set(d["frictionless"])
    assert all(isinstance(d[k], float) and math.isfinite(d[k]) for k in KEYS)


def test_issue_example_frictionless_block_is_classical_hertz(example_json):
    f = example_json["frictionless"]
    E_star = 70e9 / (1.0 - 0.22**2)
    a = (3.0 * 100.0 * 0.005 / (4.0 * E_star)) ** (1.0 / 3.0)
    # closed forms, rounding only (see tests/test_contact.py)
    assert f["contact_radius"] == pytest.approx(a, rel=1e-12)
    assert f["approach"] == pytest.approx(a * a / 0.005, rel=1e-12)
    assert f["max_pressure"] == pytest.approx(3.0 * 100.0 / (2.0 * math.pi * a * a), rel=1e-12)
    assert f["stiffness"] == pytest.approx(2.0 * E_star * a, rel=1e-12)
    assert f["stick_radius"] == 0.0 and f["max_shear"] == 0.0


def test_issue_example_values(example_json):
    d = example_json
    # stick fraction from the Chebyshev table (an independent route: 7e-12 in mu)
    c = float(stick_radius(0.3, 0.22))
    assert d["stick_radius"] / d["contact_radius"] == pytest.approx(c, rel=1e-9)
    # (2.4), (3.2), (3.17): P = 4 M a P* delta with M = G/(1 - nu), P* = (2/3) P0*
    P0 = flat_punch(nu=0.22, mu=0.3).compliance
    M = 70e9 / (2.0 * 1.22) / 0.78
    assert 4.0 * M * d["contact_radius"] * (2.0 / 3.0) * P0 * d["approach"] == pytest.approx(100.0, rel=1e-13)
    assert d["stiffness"] == pytest.approx(4.0 * M * d["contact_radius"] * P0, rel=1e-13)
    # friction: less approach, more stiffness, some shear (Shield & Anderson, (2.4) ff.)
    assert d["approach"] < d["frictionless"]["approach"] and d["stiffness"] > d["frictionless"]["stiffness"]
    assert 0.0 < d["max_shear"] <= 0.3 * d["max_pressure"]
    assert d["units"]["stress"] == "Pa" and d["materials"]["indenter"] is None


def test_elastic_sphere(capsys):
    code, out, _ = run(capsys, EXAMPLE + ["--indenter-E", "210e9", "--indenter-nu", "0.3", "--mu", "0"])
    d = json.loads(out)
    E_star = 1.0 / ((1 - 0.22**2) / 70e9 + (1 - 0.3**2) / 210e9)
    a = (3.0 * 100.0 * 0.005 / (4.0 * E_star)) ** (1.0 / 3.0)
    assert code == 0 and d["contact_radius"] == pytest.approx(a, rel=1e-12)
    assert d["materials"]["reduced_modulus"] == pytest.approx(E_star, rel=1e-15)


def test_human_readable_has_units(capsys):
    code, out, _ = run(capsys, ["punch", "--radius", "1e-3", "--approach", "1e-6", "--G", "30e9", "--nu", "0.3",
                                "--mu", "0"])
    assert code == 0
    assert "contact radius a" in out and " mm" in out and "N/m" in out and "infinite at r = 1 mm" in out


@pytest.mark.parametrize("argv, name", [
    (["sphere", "--radius", "0.005", "--load", "-100", "--E", "70e9", "--nu", "0.22", "--mu", "0.3"], "load"),
    (["sphere", "--radius", "0", "--load", "100", "--E", "70e9", "--nu", "0.22", "--mu", "0.3"], "radius"),
    (["sphere", "--radius", "0.005", "--load", "100", "--E", "nan", "--nu", "0.22", "--mu", "0.3"], "E"),
    (["sphere", "--radius", "0.005", "--load", "100", "--E", "70e9", "--nu", "0.5001", "--mu", "0.3"], "nu"),
    (["sphere", "--radius", "0.005", "--load", "100", "--E", "70e9", "--nu", "0.2", "--mu", "-0.3"], "mu"),
    (["sphere", "--radius", "0.005", "--load", "100", "--E", "70", "--nu", "0.2", "--mu", "0.3"], "units"),
    (["sphere", "--radius", "0.005", "--load", "100", "--E", "70e9", "--nu", "0.2", "--mu", "0.3",
      "--indenter-E", "200e9"], "indenter_nu"),
    (["power-law", "--n", "0", "--k", "1", "--load", "1", "--G", "1e9", "--nu", "0.2", "--mu", "0.3"], "n "),
    (["cone", "--semi-angle", "95", "--load", "1", "--G", "1e9", "--nu", "0.2", "--mu", "0.3"], "semi_angle"),
    (["solve", "--nu", "0.7", "--mu", "0.3"], "nu"),
    (["table", "--mu", "0.1:0.2:x", "--nu", "0.3"], "mu"),
])
def test_bad_input_exit_2_and_names_it(capsys, argv, name):
    code, out, err = run(capsys, argv)
    assert code == 2 and out == ""
    assert name in err and "Traceback" not in err


@pytest.mark.parametrize("argv", [
    ["sphere", "--radius", "0.005", "--load", "1", "--approach", "1e-6", "--E", "1e9", "--nu", "0.2", "--mu", "0"],
    ["sphere", "--radius", "0.005", "--load", "1", "--nu", "0.2", "--mu", "0"],  # neither E nor G
    ["sphere", "--radius", "0.005", "--load", "abc", "--E", "1e9", "--nu", "0.2", "--mu", "0"],
    ["nonsense"],
    [],
])
def test_usage_errors_exit_2(capsys, argv):
    code, out, err = run(capsys, argv)
    assert code == 2 and out == "" and "usage:" in err


@pytest.mark.parametrize("command", ["sphere", "punch", "cone", "power-law", "solve", "table", "figures", "tables"])
def test_help_exit_0(capsys, command):
    code, out, _ = run(capsys, [command, "--help"])
    assert code == 0 and "usage: hertz-friction" in out


def test_numerical_failure_exit_1(capsys, monkeypatch):
    def fail(*args, **kwargs):
        raise SolverError("did not converge")

    monkeypatch.setattr(numeric, "flat_punch", fail)
    code, out, err = run(capsys, ["solve", "--nu", "0.3", "--mu", "0.3"])
    assert code == 1 and out == "" and "numerical failure: did not converge" in err


def test_solve(capsys):
    code, out, _ = run(capsys, ["solve", "--nu", "0.0", "--c", "0.5", "--json"])
    d = json.loads(out)
    # README: mu(c = 0.5, nu = 0) = 0.298714616 (level 2, error < 1e-9; paper .2986)
    assert code == 0 and d["c"] == 0.5 and d["mu"] == pytest.approx(0.298714616, abs=1e-9)
    code, out, _ = run(capsys, ["solve", "--gamma", "0.5", "--mu", str(d["mu"]), "--n", "2"])
    assert code == 0 and "c = 0.5" in out and "A = 1.0401615" in out  # README: A = 1.04016157


def test_table_csv_and_json(capsys, tmp_path):
    code, out, err = run(capsys, ["table", "--mu", "0.2:0.4:2", "--nu", "0.25", "--progress", "always"])
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0 and [float(r["mu"]) for r in rows] == [0.2, 0.4]
    for r in rows:  # the Chebyshev table is an independent route (7e-12 in mu)
        assert float(r["c"]) == pytest.approx(float(stick_radius(float(r["mu"]), 0.25)), rel=1e-9)
        assert r["status"] == "ok"
    assert "table: 100%" in err and "2/2" in err  # a tqdm bar
    target = tmp_path / "t.json"
    code, out, err = run(capsys, ["table", "--mu", "0.2", "--nu", "0.25", "--format", "json", "--output", str(target)])
    data = json.loads(target.read_text())
    assert code == 0 and out == "" and err == ""  # progress "auto": stderr is not a terminal here
    assert data[0]["c"] == pytest.approx(float(rows[0]["c"]), rel=1e-15)


def test_table_csv_cells_are_numbers(capsys):
    # numpy 2 prints its scalars as np.float64(...): every numeric cell must parse as a float
    code, out, _ = run(capsys, ["table", "--mu", "0.3:1e4:2", "--nu", "0:0.3:2", "--sphere"])
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0 and len(rows) == 4
    for r in rows:
        for key, value in r.items():
            if key not in ("route", "status") and value != "":
                float(value)


def test_negative_values_reach_the_checks(capsys):
    # argparse alone reads "-1e9" and "-0.9:0.49:3" as options ("expected one argument")
    code, _, err = run(capsys, ["sphere", "--radius", "0.005", "--load", "100", "--E", "-1e9", "--nu", "0.22", "--mu", "0.3"])
    assert code == 2 and "E (Young's modulus, Pa) must be finite and > 0" in err
    code, out, _ = run(capsys, ["table", "--mu", "0.3", "--nu", "-0.9:0.49:3"])
    assert code == 0 and [float(r["nu"]) for r in csv.DictReader(io.StringIO(out))] == [-0.9, -0.205, 0.49]


def test_table_failed_row_exit_1(capsys, monkeypatch):
    real = numeric.flat_punch

    def flaky(nu=None, mu=None, **kwargs):
        if mu > 0.3:
            raise SolverError("no convergence")
        return real(nu=nu, mu=mu, **kwargs)

    monkeypatch.setattr(numeric, "flat_punch", flaky)
    code, out, err = run(capsys, ["table", "--mu", "0.2,0.4", "--nu", "0.25"])
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 1 and len(rows) == 2 and rows[0]["status"] == "ok"
    assert rows[1]["status"].startswith("failed") and rows[1]["c"] == ""
    assert "1 of 2 rows failed" in err


def test_figures_subcommand(capsys, tmp_path):
    """Wired to numeric.studies.figure_plots.write_figures; fig2 is closed-form (2.27), so cheap."""
    code, out, _ = run(capsys, ["figures", "--only", "fig2_chi0", "--format", "svg", "--output", str(tmp_path)])
    assert code == 0 and out.split() == [str(tmp_path / "fig2_chi0.csv"), str(tmp_path / "fig2_chi0.svg")]
    assert (tmp_path / "fig2_chi0.svg").stat().st_size > 0
    code, _, err = run(capsys, ["figures", "--only", "no_such_figure", "--output", str(tmp_path)])
    assert code == 2 and "names" in err


def test_bench_subcommand_passes_arguments_on(capsys):
    code, out, _ = run(capsys, ["bench", "--help"])
    assert code == 0 and "usage: hertz-friction bench" in out and "--quick" in out
    code, _, err = run(capsys, ["bench", "--no-such-option"])
    assert code == 2 and "unrecognized arguments" in err


def test_derivations_subcommand_runs_the_repository_generator(capsys):
    assert main(["derivations", "--help"]) == 0
    assert "--check" in capsys.readouterr().out
    assert main(["derivations", "--no-such-flag"]) == 2


def test_every_subcommand_describes_itself(capsys):
    # --help prints a description, not just the usage line (issue 13: `tables --help` was empty)
    for command in ("tables", "table", "derivations", "bench", "stability", "figures", "sphere", "solve"):
        code, out, _ = run(capsys, [command, "--help"])
        assert code == 0 and len(out.split("options:")[0].strip().splitlines()) >= 3, command



def test_error_line_says_of_what(capsys):
    # issue 13: "estimated error" did not say of what; given mu the error bounds c and P*, given c mu and P*
    _, out, _ = run(capsys, ["solve", "--nu", "0.25", "--mu", "0.3"])
    assert "estimated absolute error of c and P*:" in out
    _, out, _ = run(capsys, ["solve", "--nu", "0.25", "--c", "0.5"])
    assert "estimated absolute error of mu and P*:" in out
    # the asymptotic route computes no slip displacement, and says so (not "no slip", which reads as stick)
    _, out, _ = run(capsys, ["solve", "--nu", "0.45", "--mu", "1e-3"])
    assert "slip displacement not computed" in out and "no slip" not in out


def test_unwritable_output_and_missing_matplotlib_are_one_line_errors(capsys, monkeypatch, tmp_path):
    code, out, err = run(capsys, ["table", "--mu", "0.3", "--nu", "0.2", "--output", str(tmp_path / "no" / "x.csv")])
    assert code == 2 and err.startswith("hertz-friction table: error: cannot write") and len(err.splitlines()) == 1
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib now raises ImportError
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    code, out, err = run(capsys, ["figures", "--only", "fig2_chi0", "--output", str(tmp_path)])
    assert code == 2 and "pip install -e \".[plot]\"" in err and len(err.splitlines()) == 1



def test_a_large_ball_contact_says_hertz_theory_no_longer_applies(capsys):
    # the issue's 5 mm ball at 1.5 MN on glass: a/R = 0.83 (numeric.app.contact.SMALL_STRAIN = 0.1), in the
    # text as a last line and in the JSON as "warning", exit 0 (a result, with its caveat); 100 N says nothing
    argv = ["sphere", "--radius", "0.005", "--load", "1.5e6", "--E", "70e9", "--nu", "0.22", "--mu", "0.3"]
    code, out, err = run(capsys, argv)
    assert code == 0 and err == ""
    assert out.splitlines()[-1].startswith("warning: strain measure 0.854 (a/R for a sphere")
    code, out, err = run(capsys, argv + ["--json"])
    assert code == 0 and err == "" and "Hertz theory assumes small strains" in json.loads(out)["warning"]
    code, out, _ = run(capsys, argv[:4] + ["100"] + argv[5:])
    assert code == 0 and "warning" not in out


def test_the_cone_angle_is_in_degrees_everywhere(capsys):
    # --semi-angle-deg (and the old --semi-angle, which was degrees too) is what PowerLaw.cone takes
    from numeric.app.contact import PowerLaw

    base = ["--load", "1e-3", "--E", "70e9", "--nu", "0.22", "--mu", "0.3", "--json"]
    outs = [run(capsys, ["cone", option, "70.3", *base]) for option in ("--semi-angle-deg", "--semi-angle")]
    assert [code for code, _, _ in outs] == [0, 0] and outs[0][1] == outs[1][1]
    indenter = json.loads(outs[0][1])["indenter"]
    assert indenter["k"] == PowerLaw.cone(70.3).k == 1.0 / math.tan(math.radians(70.3))
    assert indenter["description"] == "cone, semi-angle 70.3 deg"
    code, out, err = run(capsys, ["cone", "--semi-angle-deg", "1.227", *base])  # 70.3 deg in radians
    assert code == 2 and out == "" and "semi_angle_deg" in err and "radians?" in err


def test_no_solution_is_said_as_such(capsys):
    code, out, err = run(capsys, ["solve", "--nu", "0.5", "--c", "0.5"])
    assert code == 1 and out == ""
    assert err.startswith("hertz-friction solve: no solution: no friction coefficient gives stick radius c = 0.5 at "
                          "gamma = 0") and err.count("\n") == 1


@pytest.mark.parametrize("argv", [["table", "--mu", "0.2", "--nu", "0.25", "--progress", "always", "--quiet"],
                                  ["tables", "--quiet"]])
def test_quiet_draws_no_progress_even_on_a_terminal(capsys, monkeypatch, argv):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    code, out, err = run(capsys, argv)
    assert code == 0 and out and err == ""
