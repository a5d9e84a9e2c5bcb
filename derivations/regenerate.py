"""Regenerate the committed documents of ``derivations/`` from the code.

Computes: ``paper_tables.md``, the tables of [S75] §4 and §4.2 recomputed with the paper's
scheme beside the exact values (``numeric.paper_tables``). Run time: about 1 s.

Run from the repository root::

    python derivations/regenerate.py

The output is deterministic (no timestamps), so a re-run leaves ``git diff`` empty;
``tests/test_derivations.py`` fails when the committed files are out of date.
"""

from __future__ import annotations

from pathlib import Path

from numeric.paper_tables import render

HERE = Path(__file__).resolve().parent

DOCUMENTS = {"paper_tables.md": render}


def main() -> None:
    for name, make in DOCUMENTS.items():
        (HERE / name).write_text(make() + "\n", encoding="utf-8")
        print(f"wrote derivations/{name}")


if __name__ == "__main__":
    main()
