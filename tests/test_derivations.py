"""The committed documents in derivations/ are what the code regenerates, and the CLI runs."""

import importlib.metadata
import importlib.util
import shutil
import subprocess
from pathlib import Path

import pytest

from numeric.studies.paper_tables import render

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


def _regenerate():
    spec = importlib.util.spec_from_file_location("regenerate", ROOT / "derivations" / "regenerate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_derivation_documents_are_current_fast_mode(capsys):
    # fast mode: statements, steps, identities and fast-vs-precise of every part are regenerated
    # (in this process, so the registry's checks are shared with tests/test_registry.py); the
    # blocks computed with the full solver are kept as committed (the slow test checks those).
    assert _regenerate().main(["--fast", "--check"]) == 0, capsys.readouterr().err


@pytest.mark.slow
def test_derivation_documents_are_current_full():
    assert _regenerate().main(["--check"]) == 0
