"""Regenerate the committed documents and figures of ``derivations/`` from the code.

Computes:
- ``paper_tables.md``: the tables of [S75] §4 and §4.2 recomputed with the paper's scheme
  beside the exact values (``numeric.studies.paper_tables``), about 1 s;
- ``section_2_3.md``, ``section_3.md``, ``appendix_b.md``: one document per part of the
  paper, from ``asymptotics.registry`` (statements, SymPy steps, identities checked with
  mpmath, fast against precise evaluations), and in §2.3 the check of every expansion
  against the full solution (``numeric.studies.expansion_checks``);
- ``figures/``: the paper's figures 2-6 redrawn from our solutions and figures the paper
  lacks (``numeric.studies.figures``), PNG with the plotted data as CSV beside each.

Run from the repository root::

    python derivations/regenerate.py            # everything (a few minutes)
    python derivations/regenerate.py --fast     # skip what needs the full solver
    python derivations/regenerate.py --check    # compare with the committed files, write nothing

``--fast`` leaves the solver-computed blocks of the documents and the figures as committed
(a test runs ``--fast --check``; the full check is a slow test). The output is
deterministic (no timestamps), so a re-run leaves ``git diff`` empty.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent
FIGURES = HERE / "figures"

# part of the registry -> (document, figures shown in it)
PART_DOCUMENTS = {
    "2.3": ("section_2_3.md", ("fig2_chi0", "fig3_stick_radius", "stick_radius_asymptotes", "fig4_compliance",
                               "fig5_flat_punch_stresses", "slip_displacement", "expansion_errors")),
    "3": ("section_3.md", ("fig6_sphere_stresses", "sphere_indentation")),
    "B": ("appendix_b.md", ()),
}


def _figure_block(names: tuple[str, ...]) -> str:
    lines = ["## Figures", ""]
    lines += [f"![{name}](figures/{name}.png)" for name in names]
    return "\n".join(lines) + "\n"


def part_blocks(name: str, study=None) -> list[tuple[str, str | None]]:
    """Blocks of a part's document; with ``study`` None (fast mode) the solver-computed block is
    (name, None), kept as committed."""
    from asymptotics.document import render_part

    _, figures = PART_DOCUMENTS[name]
    extra: dict[str, str | None] = {}
    if name == "2.3":
        from numeric.studies.expansion_checks import render_markdown

        extra["expansion-checks"] = None if study is None else render_markdown(study)
    if figures:
        extra["figures"] = _figure_block(figures)
    return render_part(name, extra)


def _merge(blocks: list[tuple[str, str | None]], committed: str) -> str:
    from asymptotics.document import blocks_of, join

    kept = blocks_of(committed)
    return join([(n, kept.get(n.replace(" ", "_"), "") if body is None else body) for n, body in blocks])


def documents(study) -> dict[str, Callable[[str], str]]:
    """File name -> function of the committed text giving the regenerated text."""
    from numeric.studies.paper_tables import render

    docs: dict[str, Callable[[str], str]] = {"paper_tables.md": lambda _: render() + "\n"}
    for name, (file, _) in PART_DOCUMENTS.items():
        docs[file] = lambda committed, name=name: _merge(part_blocks(name, study), committed)
    return docs


def write_figures(study) -> list[Path]:
    from numeric.studies.expansion_checks import plot_expansion_errors
    from numeric.studies.figures import write_figures as write

    FIGURES.mkdir(exist_ok=True)
    paths = write(FIGURES)
    plot_expansion_errors(str(FIGURES / "expansion_errors.png"), study)
    return [*paths, FIGURES / "expansion_errors.png"]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fast", action="store_true", help="skip the blocks and figures that need the full solver")
    parser.add_argument("--check", action="store_true", help="compare with the committed files instead of writing")
    args = parser.parse_args(argv)
    study = None
    if not args.fast:
        from numeric.studies.expansion_checks import expansion_study

        study = expansion_study(fast=False)
    stale = []
    for file, make in documents(study).items():
        path = HERE / file
        committed = path.read_text(encoding="utf-8") if path.exists() else ""
        fresh = make(committed)
        if args.check:
            if fresh != committed:
                stale.append(file)
        else:
            path.write_text(fresh, encoding="utf-8")
            print(f"wrote derivations/{file}")
    if not args.fast and not args.check:
        for path in write_figures(study):
            print(f"wrote {path.relative_to(HERE.parent)}")
    if stale:
        print("out of date (run python derivations/regenerate.py): " + ", ".join(stale), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
