"""The README's command-line examples print what the README shows (its Python examples run as
doctests, see pyproject's testpaths)."""

import re
import shlex
from pathlib import Path

import pytest

from numeric.app.cli import main
from numeric.studies.paper_tables import render

README = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
EXAMPLES = re.findall(r"```console\n\$ (hertz-friction [^\n]*)\n(.*?)```", README, re.S)


def test_the_readme_has_command_line_examples():
    assert EXAMPLES


ESTIMATE = re.compile(r"(estimated error of c or mu: )([0-9.e+-]+)")


@pytest.mark.parametrize("command, shown", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_command_prints_what_the_readme_shows(command, shown, capsys):
    # printed to 6 (c: 10) significant digits from a level-2 solution (error ~1e-10): machine-independent, except the
    # printed error estimate: the difference of two solutions a degree apart plus the guided step not taken (bounded
    # by the theta scatter, THETA_SCATTER), both within a few rounding units of 1e-10, so its digits move with the BLAS
    # and the CPU (measured 5.5e-11 ... 9.9e-11 for the cylinder example): it must lie within a factor 3 of the shown one
    assert main(shlex.split(command)[1:]) == 0
    out = capsys.readouterr().out
    assert ESTIMATE.sub(r"\1<estimate>", out) == ESTIMATE.sub(r"\1<estimate>", shown)
    for printed, expected in zip(ESTIMATE.findall(out), ESTIMATE.findall(shown)):
        assert float(expected[1]) / 3 <= float(printed[1]) <= 3 * float(expected[1]), (printed, expected)


def test_the_table_excerpt_is_what_tables_prints():
    # the rows under "A table." are lines of `hertz-friction tables` (numeric.studies.paper_tables.render)
    excerpt = README.split("**A table.**")[1].split("\n\n")[1]
    printed = render().splitlines()
    rows = excerpt.splitlines()
    assert len(rows) >= 3 and all(row in printed for row in rows), [row for row in rows if row not in printed]
