"""Regenerate the committed documents and figures of ``derivations/`` from the code.

Computes ``paper_tables.md`` (the tables of [S75] §4 and §4.2 recomputed with the paper's
scheme), ``section_2_3.md``, ``section_3.md``, ``appendix_b.md`` (one document per part of
the paper from ``asymptotics.registry``, and in §2.3 every expansion against the full
solution) and ``figures/`` (the paper's figures 2-6 redrawn, and figures the paper lacks).
The work is ``numeric.studies.documents.regenerate``; this script runs it on this folder, as
``hertz-friction derivations`` does. Run from the repository root::

    python derivations/regenerate.py            # everything (a few minutes)
    python derivations/regenerate.py --fast     # skip what needs the full solver
    python derivations/regenerate.py --check    # compare with the committed files, write nothing

``--fast`` leaves the solver-computed blocks of the documents and the figures as committed
(a test runs ``--fast --check``; the full check is a slow test). The output is
deterministic (no timestamps), so a re-run leaves ``git diff`` empty. The full run pins the BLAS to
one thread, as the committed files were made (a threaded BLAS moves the tenth digits of the
solver's figures); where the environment does not, it runs in a child process that does.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from numeric.app import cli

HERE = Path(__file__).resolve().parent


def main(argv: list[str] | None = None) -> int:
    """``hertz-friction derivations --directory derivations/ [--fast] [--check]``; returns the exit code."""
    parser = argparse.ArgumentParser(prog="python derivations/regenerate.py",
                                     description="Regenerate the documents and figures of this folder "
                                                 "(as hertz-friction derivations --directory derivations/).")
    parser.add_argument("--fast", action="store_true", help="leave the solver-computed blocks and figures as committed")
    parser.add_argument("--check", action="store_true", help="name the stale documents, write nothing (exit code 1)")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2), printed by argparse
        return exc.code if isinstance(exc.code, int) else 2
    return cli.main(["derivations", "--directory", str(HERE)] + ["--fast"] * args.fast + ["--check"] * args.check)


if __name__ == "__main__":
    raise SystemExit(main())
