"""The committed documents in derivations/ are what the code regenerates, and the CLI runs."""

import importlib.metadata
import importlib.util
import shutil
import subprocess
from pathlib import Path

import pytest

from asymptotics.document import agrees, measured, text_of
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


def test_measured_figures_are_compared_against_their_tolerance():
    # a fast-vs-precise difference at rounding level moves with the CPU's libm and SIMD paths (3e-16 -> 5e-16
    # with numpy's AVX-512 paths on or off): the document stays current while both figures meet the tolerance
    # they are checked against, and not otherwise; all other text, numbers included, must be identical
    rendered = f"| (B4) | {measured(3e-16, 1e-15)} |\nLargest relative difference: {measured(0.0, 1e-15)} (tolerance 1e-15)\n"
    committed = text_of(rendered)
    assert committed == "| (B4) | 3e-16 |\nLargest relative difference: 0 (tolerance 1e-15)\n"
    assert agrees(committed, rendered)
    assert agrees(committed.replace("3e-16", "5e-16"), rendered)
    assert not agrees(committed.replace("3e-16", "2e-15"), rendered)  # the committed figure fails its tolerance
    assert not agrees(committed, rendered.replace("3e-16", "2e-15"))  # the fresh one does
    assert not agrees(committed.replace("tolerance 1e-15", "tolerance 4e-15"), rendered)  # fixed numbers are exact
    assert not agrees(committed.replace("(B4)", "(B3)"), rendered)
    # a computed value is held to the accuracy it is known to, around a reference (here itself) or its exact value
    value = f"A = {measured(1.52708, 2e-5, '1.52708', 1.52708)}, gap = {measured(-3.6e-12, 1e-10, '-3.6e-12')}"
    assert text_of(value) == "A = 1.52708, gap = -3.6e-12"
    assert agrees("A = 1.52709, gap = 4.1e-11", value)
    assert not agrees("A = 1.52711, gap = 4.1e-11", value) and not agrees("A = 1.52708, gap = -2e-10", value)


def test_regeneration_keeps_a_document_whose_figures_moved_within_tolerance(tmp_path):
    from numeric.studies.documents import regenerate

    for file in ("paper_tables.md", "section_2_3.md", "section_3.md", "appendix_b.md", "plane_strain.md"):
        shutil.copy(ROOT / "derivations" / file, tmp_path / file)
    # the (B4) row's fast-vs-precise figure as another machine might have measured it (tolerance 1e-15 or more)
    path = tmp_path / "appendix_b.md"
    text = path.read_text(encoding="utf-8")
    row = next(line for line in text.splitlines() if line.startswith("| (B4) |"))
    moved = row.rsplit("|", 2)[0] + "| 7e-16 |"
    path.write_text(text.replace(row, moved), encoding="utf-8")
    assert regenerate(tmp_path, fast=True, check=True) == []
    regenerate(tmp_path, fast=True, check=False)
    assert moved in path.read_text(encoding="utf-8")  # not rewritten for a last digit
    path.write_text(text.replace(row, row.rsplit("|", 2)[0] + "| 3e-13 |"), encoding="utf-8")
    assert regenerate(tmp_path, fast=True, check=True) == ["appendix_b.md"]


def test_the_script_states_its_own_usage(capsys):
    # python derivations/regenerate.py --help used to print the usage of hertz-friction derivations (with a
    # --directory the script fills in itself)
    assert _regenerate().main(["--help"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: python derivations/regenerate.py [-h] [--fast] [--check]\n")
    assert _regenerate().main(["--directory", "x"]) == 2
