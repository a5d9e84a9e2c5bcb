"""The committed documents in derivations/ are what the code regenerates, and the CLI runs."""

import importlib.metadata
import shutil
import subprocess
from pathlib import Path

import pytest

from numeric.paper_tables import render

ROOT = Path(__file__).resolve().parents[1]


def test_paper_tables_document_is_current():
    committed = (ROOT / "derivations" / "paper_tables.md").read_text(encoding="utf-8")
    assert committed == render() + "\n", "run: python derivations/regenerate.py"


def test_console_script_prints_the_tables():
    exe = shutil.which("hertz-friction")
    if exe is None:
        pytest.skip("package not installed (pip install -e .[test]) - the console script is absent")
    out = subprocess.run([exe, "tables"], capture_output=True, text=True, check=True).stdout
    assert out == render() + "\n"


def test_no_other_distribution_provides_our_packages():
    # PyPI has an unrelated 'asymptotics'; installed beside us it would shadow one package.
    providers = importlib.metadata.packages_distributions()
    for package in ("asymptotics", "numeric"):
        assert set(providers.get(package, ["hertz-friction"])) == {"hertz-friction"}, providers.get(package)
