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


@pytest.mark.parametrize("command, shown", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_command_prints_what_the_readme_shows(command, shown, capsys):
    # printed to 6 significant digits from a level-2 solution (error ~1e-10): machine-independent
    assert main(shlex.split(command)[1:]) == 0
    assert capsys.readouterr().out == shown


def test_the_table_excerpt_is_what_tables_prints():
    # the rows under "A table." are lines of `hertz-friction tables` (numeric.studies.paper_tables.render)
    excerpt = README.split("**A table.**")[1].split("\n\n")[1]
    printed = render().splitlines()
    rows = excerpt.splitlines()
    assert len(rows) >= 3 and all(row in printed for row in rows), [row for row in rows if row not in printed]
