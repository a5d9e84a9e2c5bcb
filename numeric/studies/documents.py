"""The committed documents and figures of ``derivations/``, regenerated from the code.

Computes:
- ``paper_tables.md``: the tables of [S75] §4 and §4.2 recomputed with the paper's scheme
  beside the exact values (``numeric.studies.paper_tables``), about 1 s;
- ``section_2_3.md``, ``section_3.md``, ``appendix_b.md``: one document per part of the
  paper, from ``asymptotics.registry`` (statements, SymPy steps, identities checked with
  mpmath, fast against precise evaluations), and in §2.3 the check of every expansion
  against the full solution (``numeric.studies.expansion_checks``);
- ``figures/``: the paper's figures 2-6 redrawn from our solutions and figures the paper
  lacks (``numeric.studies.figure_plots``), PNG with the plotted data as CSV beside each;
- ``plane_strain.md``: the plane-strain strip punch and cylinder (part "P" of the registry) with the
  measured checks of ``numeric.studies.plane_checks``, and its figures (``numeric.studies.plane_figures``).

``regenerate(directory, fast=, check=)`` writes them (or, with ``check``, names the stale
ones); ``fast`` leaves the solver-computed blocks of the documents and the figures as
committed. The output is deterministic (no timestamps), and a document whose only changes are
measured rounding-level figures that still meet their tolerances is current
(``asymptotics.document.agrees``) and not rewritten, so a re-run leaves ``git diff`` empty on
any machine. ``hertz-friction derivations`` and ``python derivations/regenerate.py`` run it.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from asymptotics.document import agrees, blocks_of, join, render_part, text_of
from asymptotics.plane import EXACT_RELATION

from numeric.studies.expansion_checks import ExpansionStudy, expansion_study
from numeric.studies.expansion_report import plot_expansion_errors, render_markdown
from numeric.studies.figure_plots import write_figures
from numeric.studies.paper_tables import render
from numeric.studies.plane_checks import plane_checks_markdown
from numeric.studies.plane_figures import write_plane_figures

__all__ = ["PART_DOCUMENTS", "source_derivations", "part_blocks", "documents", "regenerate"]

# part of the registry -> (document, figures shown in it)
PART_DOCUMENTS = {
    "2.3": ("section_2_3.md", ("fig2_chi0", "fig3_stick_radius", "stick_radius_asymptotes", "fig4_compliance",
                               "fig5_flat_punch_stresses", "slip_displacement", "expansion_errors")),
    "3": ("section_3.md", ("fig6_sphere_stresses", "sphere_indentation")),
    "B": ("appendix_b.md", ()),
    "P": ("plane_strain.md", ("plane_stick_width", "plane_stresses")),
}


def source_derivations() -> Path | None:
    """``derivations/`` of the source checkout this package runs from (an editable install), else None."""
    candidate = Path(__file__).resolve().parents[2] / "derivations"
    return candidate if candidate.is_dir() else None


def _figure_block(names: tuple[str, ...]) -> str:
    lines = ["## Figures", ""]
    lines += [f"![{name}](figures/{name}.png)" for name in names]
    return "\n".join(lines) + "\n"


def part_blocks(name: str, study: ExpansionStudy | None = None) -> list[tuple[str, str | None]]:
    """Blocks of a part's document; with ``study`` None (fast mode) the solver-computed block is
    (name, None), kept as committed."""
    _, figures = PART_DOCUMENTS[name]
    extra: dict[str, str | None] = {}
    if name == "2.3":
        extra["expansion-checks"] = None if study is None else render_markdown(study)
    if name == "P":  # the plane-strain measurements, computed whenever the solver runs (study given)
        extra["exact-relation"] = EXACT_RELATION
        extra["plane-checks"] = None if study is None else plane_checks_markdown()
    if figures:
        extra["figures"] = _figure_block(figures)
    return render_part(name, extra)


def _merge(blocks: list[tuple[str, str | None]], committed: str) -> str:
    kept = blocks_of(committed)
    return join([(n, kept.get(n.replace(" ", "_"), "") if body is None else body) for n, body in blocks])


def documents(study: ExpansionStudy | None) -> dict[str, Callable[[str], str]]:
    """File name -> function of the committed text giving the regenerated text (its measured figures marked:
    ``asymptotics.document.text_of`` gives the Markdown)."""
    docs: dict[str, Callable[[str], str]] = {"paper_tables.md": lambda _: render() + "\n"}
    for name, (file, _) in PART_DOCUMENTS.items():
        docs[file] = lambda committed, name=name: _merge(part_blocks(name, study), committed)
    return docs


def _write_figures(directory: Path, study: ExpansionStudy) -> list[Path]:
    figures = directory / "figures"
    figures.mkdir(exist_ok=True)
    plane = write_plane_figures(figures)
    paths = write_figures(figures)
    plot_expansion_errors(str(figures / "expansion_errors.png"), study)
    return [*plane, *paths, figures / "expansion_errors.png"]


def regenerate(directory: Path, *, fast: bool, check: bool,
               report: Callable[[str], object] = lambda message: None) -> list[str]:
    """Rewrite the documents in ``directory`` (and, unless ``fast``, the figures), or with ``check``
    compare instead of writing; returns the names of the stale documents. ``report`` is told each
    file written."""
    study = None if fast else expansion_study(fast=False)
    stale = []
    for file, make in documents(study).items():
        path = directory / file
        committed = path.read_text(encoding="utf-8") if path.exists() else ""
        fresh = make(committed)
        if agrees(committed, fresh):
            report(f"{path} is current")
            continue
        if check:
            stale.append(file)
        else:
            path.write_text(text_of(fresh), encoding="utf-8")
            report(f"wrote {path}")
    if study is not None and not check:
        for path in _write_figures(directory, study):
            report(f"wrote {path}")
    return stale
