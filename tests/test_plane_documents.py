"""derivations/plane_strain.md and the plane figures are what the code regenerates (``python derivations/regenerate.py``)."""

import subprocess
import sys
from pathlib import Path

import pytest

from asymptotics.document import agrees
from numeric.app.cli import one_blas_thread_environment
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


#: The measured block regenerated in a child process with one BLAS thread, as ``regenerate.py`` makes it: its
#: 10-digit figures follow the BLAS's summation order (with the default threads mu at nu = 0.3, c = 0.05 moved by
#: 2e-11), and a process's BLAS threads cannot be changed once it is loaded.
_CHECK_IN_ONE_THREAD = """
import sys
from pathlib import Path
from asymptotics.document import agrees
from numeric.app.cli import one_blas_thread_environment
from numeric.studies.documents import documents
committed = Path(sys.argv[1]).read_text(encoding="utf-8")
sys.exit(0 if agrees(committed, documents(object())["plane_strain.md"](committed)) else 1)
"""


@pytest.mark.slow
def test_plane_document_and_figures_are_current(tmp_path):
    from numeric.studies.plane_figures import write_plane_figures
    check = subprocess.run([sys.executable, "-c", _CHECK_IN_ONE_THREAD, str(DOCUMENT)], env=one_blas_thread_environment(),
                           check=False)
    assert check.returncode == 0, "run: python derivations/regenerate.py"
    for path in write_plane_figures(tmp_path):
        if path.suffix == ".csv":
            _same_table(path.read_text(), (ROOT / "derivations" / "figures" / path.name).read_text())


def _same_table(fresh: str, committed: str) -> None:
    """The same text cell by cell, numbers within 1e-9 relative: the plotted values are solutions good to ~1e-10 and
    move at the 1e-12 level with the BLAS threads (a last printed digit of ten changed with two threads)."""
    fresh_rows, committed_rows = fresh.splitlines(), committed.splitlines()
    assert len(fresh_rows) == len(committed_rows)
    for a, b in zip(fresh_rows, committed_rows):
        cells_a, cells_b = a.split(","), b.split(",")
        assert len(cells_a) == len(cells_b), (a, b)
        for x, y in zip(cells_a, cells_b):
            try:
                u, v = float(x), float(y)
            except ValueError:
                assert x == y, (a, b)
                continue
            assert u == pytest.approx(v, rel=1e-9, abs=1e-300), (a, b)
