"""derivations/plane_strain.md and the plane figures are what the code regenerates (``python derivations/regenerate.py``)."""

from pathlib import Path

import pytest

from asymptotics.document import agrees
from numeric.studies.documents import documents

ROOT = Path(__file__).resolve().parents[1]
DOCUMENT = ROOT / "derivations" / "plane_strain.md"


def test_plane_document_cheap_blocks_are_current():
    # statements, SymPy steps, mpmath identities, fast-vs-precise and the note on the exact relation are regenerated;
    # the measured block (the full solver, ~10 s) is kept as committed (the slow test checks it)
    committed = DOCUMENT.read_text(encoding="utf-8")
    # (measured figures within their tolerance, as for the other documents: ``asymptotics.document.agrees``)
    assert agrees(committed, documents(None)["plane_strain.md"](committed)), "run: python derivations/regenerate.py"
    for block in ("derivation2D-(2.28)", "exact-relation", "plane-checks", "figures"):
        assert f"<!-- begin {block} -->" in committed


@pytest.mark.slow
def test_plane_document_and_figures_are_current(tmp_path):
    from numeric.studies.plane_figures import write_plane_figures
    committed = DOCUMENT.read_text(encoding="utf-8")
    assert agrees(committed, documents(object())["plane_strain.md"](committed))
    for path in write_plane_figures(tmp_path):
        if path.suffix == ".csv":
            assert path.read_text() == (ROOT / "derivations" / "figures" / path.name).read_text()
