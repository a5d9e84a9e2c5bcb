"""The figures of ``numeric.studies.figures`` drawn with matplotlib, and the writer of the committed set.

Each plot function (``plot_fig2_chi0``, ...) draws a ``FigureData``. matplotlib is imported
inside the plot functions only (``matplotlib.figure.Figure`` with the Agg canvas, no pyplot
and no global backend switch), so importing this module stays light.

``write_figures(directory)`` computes, writes ``<name>.csv`` and then ``<name>.png`` (or
other formats) for every figure in ``FIGURES``, plus ``index.md`` with the captions when
all figures are written. Regenerate the committed set (about 60 s CPU, 70 s wall on 2 cores)
with ``hertz-friction figures --output derivations/figures`` or ``python derivations/regenerate.py``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from numeric.solutions.progress import Progress, progress_bar
from numeric.studies.figures import COMPUTE, Curve, FigureData

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

__all__ = [
    "FIGURES",
    "IMAGE_FORMATS",
    "plot_fig2_chi0",
    "plot_fig3_stick_radius",
    "plot_fig4_compliance",
    "plot_fig5_flat_punch_stresses",
    "plot_fig6_sphere_stresses",
    "plot_stick_radius_asymptotes",
    "plot_slip_displacement",
    "plot_sphere_indentation",
    "write_figures",
]

IMAGE_FORMATS = ("png", "pdf", "svg")

_STYLE = {
    "font.size": 9,
    "axes.labelsize": 9,
    "axes.titlesize": 9,
    "legend.fontsize": 7.5,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "lines.linewidth": 1.3,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "legend.frameon": False,
    "mathtext.fontset": "dejavuserif",
    "svg.hashsalt": "hertz-friction",
}
_SAVE_METADATA = {"png": {"Software": None}, "pdf": {"CreationDate": None, "Producer": None}, "svg": {"Date": None}}
_DPI = 200
_LS = {"solver": "-", "(2.28)": "--", "(2.29)": ":"}


def _nu_colour(nu: float):
    from matplotlib import colormaps

    return colormaps["viridis"](0.9 * nu / 0.5)


def _c_colour(c: float):
    from matplotlib import colormaps

    return colormaps["plasma"](0.05 + 0.8 * c)


def _new_figure(width: float, height: float) -> Figure:
    from matplotlib.figure import Figure

    return Figure(figsize=(width, height), layout="constrained")


def _letter(ax: Axes, letter: str) -> None:
    ax.text(-0.02, 1.02, f"({letter})", transform=ax.transAxes, ha="right", va="bottom", fontweight="bold")


def _styled(plot: Callable[[FigureData], Figure]) -> Callable[[FigureData], Figure]:
    """Run a plot function under the house style (rcParams), returning its Figure."""

    @functools.wraps(plot)
    def wrapped(data: FigureData) -> Figure:
        import matplotlib

        with matplotlib.rc_context(_STYLE):
            return plot(data)

    return wrapped


def _label_right(ax: Axes, y: float, text: str, colour) -> None:
    """A direct label just right of the axes at height y (data coordinates)."""
    ax.annotate(text, xy=(1.0, y), xycoords=("axes fraction", "data"), xytext=(3, 0), textcoords="offset points",
                va="center", ha="left", color=colour, fontsize=8)


def _style_legend(ax: Axes, entries: Sequence[tuple[dict, str]], loc: str) -> None:
    """Legend of line styles only (colours are labelled directly): (Line2D kwargs, label)."""
    from matplotlib.lines import Line2D

    ax.legend(handles=[Line2D([], [], **kw, label=label) for kw, label in entries], loc=loc)


def _nu_legend(ax: Axes, curves: Sequence[Curve], loc: str, extra: Sequence[tuple[dict, str]] = ()) -> None:
    """Legend: one colour per nu, then grey entries for the styles, (Line2D kwargs, label)."""
    from matplotlib.lines import Line2D

    nus = sorted({cv.param("nu") for cv in curves if "nu" in dict(cv.params)})
    handles = [Line2D([], [], color=_nu_colour(nu), label=rf"$\nu = {nu:g}$") for nu in nus]
    handles += [Line2D([], [], color="0.3", **kw, label=label) for kw, label in extra]
    ax.legend(handles=handles, loc=loc)


def _against_mu(ax: Axes, curves: Sequence[Curve]) -> None:
    """A family of curves against mu, coloured by nu: the paper's values as open circles, the full
    solution solid, the first-order law dashed, a limit dotted with its nu written at the right."""
    for cv in curves:
        colour = _nu_colour(cv.param("nu"))
        if cv.model == "paper":
            ax.plot(cv.x, cv.y, "o", mfc="none", color=colour, ms=5)
        elif cv.model == "solver":
            ax.plot(cv.x, cv.y, color=colour, lw=1.4)
        elif cv.model in _LS:
            ax.plot(cv.x, cv.y, color=colour, ls=_LS[cv.model], lw=1.0)
        else:
            ax.plot(cv.x, cv.y, color=colour, ls=":", lw=1.0)
            _label_right(ax, cv.y[-1], rf"$\nu = {cv.param('nu'):g}$", colour)


@_styled
def plot_fig2_chi0(data: FigureData) -> Figure:
    """chi^(0)(x) (2.27) with its roots marked (paper's figure 2)."""
    fig = _new_figure(4.2, 3.0)
    ax = fig.add_subplot()
    for cv, ls in zip(data.select("chi0(x)"), ("-", "--", "-.", ":")):
        r, c = cv.param("mu_over_gamma"), cv.param("c")
        ax.plot(cv.x, cv.y, color="k", ls=ls, label=rf"$\mu/\gamma = {r:g}$  ($c = {c:.3f}$)")
        ax.plot([c], [0.0], "o", color="k", ms=4)
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(-0.6, 0.45)
    ax.set_xlabel(r"$x = r/a$")
    ax.set_ylabel(r"$\chi^{(0)}(x)$")
    ax.legend(loc="lower left")
    return fig


@_styled
def plot_fig3_stick_radius(data: FigureData) -> Figure:
    """c against mu: full solution, (2.28), paper's values (paper's figure 3)."""
    fig = _new_figure(4.6, 3.4)
    ax = fig.add_subplot()
    _against_mu(ax, data.select("c(mu)"))
    ax.set_xlim(0.0, 1.5)
    ax.set_ylim(0.0, 1.0)
    ax.set_xlabel(r"friction coefficient $\mu$")
    ax.set_ylabel(r"stick radius $c$")
    _nu_legend(ax, data.curves, "lower right", extra=(
        ({"ls": "-"}, "full solution"), ({"ls": "--", "lw": 1.0}, "first order (2.28)"),
        ({"marker": "o", "mfc": "none", "ls": "none"}, "paper, §4.2 table")))
    return fig


@_styled
def plot_fig4_compliance(data: FigureData) -> Figure:
    """P* against mu with the adhesive limits (paper's figure 4)."""
    fig = _new_figure(4.6, 3.4)
    ax = fig.add_subplot()
    _against_mu(ax, data.select("P*(mu)"))
    ax.set_xlim(0.0, 2.0)
    ax.set_ylim(0.995, 1.105)
    ax.set_xlabel(r"friction coefficient $\mu$")
    ax.set_ylabel(r"compliance factor $P^* = (1-\nu)P\,/\,(4Ga\delta)$")
    _style_legend(ax, (({"color": "0.3"}, "full solution"),
                       ({"color": "0.3", "ls": ":", "lw": 1.0}, r"adhesive limit $\tanh^{-1}\gamma\,/\gamma$ (B4)")),
                  "lower right")
    return fig


def _c_legend_label(cv: Curve) -> str:
    mu, c = cv.param("mu"), cv.param("c")
    if math.isinf(mu):
        return r"$\mu = \infty$ (adhesive)"
    if mu == 0.0:
        return r"$\mu = 0$ (Hertz, (3.19))" if cv.model.startswith("Hertz") else r"$\mu = 0$ (frictionless)"
    return rf"$\mu = {mu:.4f}$, $c = {c:g}$"


def _stress_axes(ax: Axes, curves: Sequence[Curve]) -> list:
    """Draw solver curves (coloured by c) and the limits mu = 0 (dashed), inf (dotted);
    return the limits' line handles."""
    limits = []
    for cv in curves:
        if cv.model == "solver":
            ax.plot(cv.x, cv.y, color=_c_colour(cv.param("c")), label=_c_legend_label(cv))
        else:
            ls = ":" if math.isinf(cv.param("mu")) else "--"
            limits += ax.plot(cv.x, cv.y, color="k", ls=ls, lw=1.0, label=_c_legend_label(cv))
    return limits


@_styled
def plot_fig5_flat_punch_stresses(data: FigureData) -> Figure:
    """q/(mu p) in the stick zone, p and q of the flat punch (paper's figure 5)."""
    fig = _new_figure(7.2, 2.8)
    axes = fig.subplots(1, 3)
    nu = data.curves[0].param("nu")
    ax = axes[0]
    for cv in data.select("q/(mu p)(x)", "solver"):
        ax.plot(cv.x, cv.y, color=_c_colour(cv.param("c")), label=_c_legend_label(cv))
        ax.plot([cv.param("c")], [1.0], "o", color=_c_colour(cv.param("c")), ms=3)
    for cv in data.select("q/(mu p)(x)", "(2.31)"):
        ax.plot(cv.x, cv.y, color="k", ls="--", lw=0.8)
    ax.set_xlim(0.0, 1.0)
    ax.set_ylim(0.0, 1.05)
    ax.set_xlabel(r"$x = r/a$")
    ax.set_ylabel(r"$q/\mu p$ in the stick zone $x < c$")
    _style_legend(ax, (({"color": "0.3"}, "full solution"), ({"color": "k", "ls": "--", "lw": 0.8},
                                                                "first order (2.31)")), "lower right")
    limits = []
    for ax, panel, label, ylim in ((axes[1], "p(x)", r"pressure $p$", (0.0, 3.0)),
                                   (axes[2], "q(x)", r"shear $q$", (0.0, 1.2))):
        limits.append(_stress_axes(ax, data.select(panel)))
        ax.set_xlim(0.0, 1.0)
        ax.set_ylim(*ylim)
        ax.set_xlabel(r"$x = r/a$")
        ax.set_ylabel(label)
    axes[1].legend(handles=[ln for ln in axes[1].get_lines() if ln not in limits[0]] + limits[0], loc="upper left",
                   title=rf"flat punch, $\nu = {nu:g}$", alignment="left")
    for ax, letter in zip(axes, "abc"):
        _letter(ax, letter)
    return fig


@_styled
def plot_fig6_sphere_stresses(data: FigureData) -> Figure:
    """Sphere pressure and shear with the Hertz curve (paper's figure 6)."""
    fig = _new_figure(6.4, 2.9)
    axes = fig.subplots(1, 2)
    nu = data.curves[0].param("nu")
    for ax, panel, label in ((axes[0], "p(x)", r"pressure $p$"), (axes[1], "q(x)", r"shear $q$")):
        _stress_axes(ax, data.select(panel))
        ax.set_xlim(0.0, 1.0)
        ax.set_ylim(bottom=0.0)
        ax.set_xlabel(r"$x = r/a$")
        ax.set_ylabel(label)
    axes[0].legend(loc="lower left", title=rf"sphere, $\nu = {nu:g}$", alignment="left")
    for ax, letter in zip(axes, "ab"):
        _letter(ax, letter)
    return fig


@_styled
def plot_stick_radius_asymptotes(data: FigureData) -> Figure:
    """log c against gamma/mu and log(1 - c) against mu/gamma with (2.28), (2.29)."""
    fig = _new_figure(7.0, 3.0)
    axes = fig.subplots(1, 2)
    for ax, panel, xlabel, ylabel, xlim, ylim in (
            (axes[0], "c(gamma/mu)", r"$\gamma/\mu$", r"stick radius $c$", (0.0, 8.0), (1e-3, 1.0)),
            (axes[1], "1-c(mu/gamma)", r"$\mu/\gamma$", r"slip-annulus width $1 - c$", (0.0, 8.0), (1e-6, 1.0))):
        for cv in data.select(panel):
            colour = _nu_colour(cv.param("nu")) if cv.model == "solver" else "k"
            ax.plot(cv.x, cv.y, color=colour, ls=_LS[cv.model], lw=1.4 if cv.model == "solver" else 1.0)
        ax.set_yscale("log")
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
    _nu_legend(axes[0], data.select("c(gamma/mu)"), "lower left")
    _style_legend(axes[1], (({"color": "0.3"}, "full solution"), ({"color": "k", "ls": "--", "lw": 1.0},
                                                                    "first order (2.28)"),
                            ({"color": "k", "ls": ":", "lw": 1.0}, "asymptote (2.29)")), "lower left")
    for ax, letter in zip(axes, "ab"):
        _letter(ax, letter)
    return fig


@_styled
def plot_slip_displacement(data: FigureData) -> Figure:
    """u(x) in the slip annulus."""
    fig = _new_figure(4.2, 3.0)
    ax = fig.add_subplot()
    nu = data.curves[0].param("nu")
    for cv in data.select("u(x)"):
        ax.plot(cv.x, cv.y, color=_c_colour(cv.param("c")), label=_c_legend_label(cv))
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlim(0.0, 1.0)
    ax.set_xlabel(r"$x = r/a$")
    ax.set_ylabel(r"slip $u = \partial u_r/\partial\delta$")
    ax.legend(loc="lower left", title=rf"flat punch, $\nu = {nu:g}$", alignment="left")
    return fig


@_styled
def plot_sphere_indentation(data: FigureData) -> Figure:
    """1/A against mu for the sphere."""
    fig = _new_figure(4.6, 3.4)
    ax = fig.add_subplot()
    _against_mu(ax, data.select("1/A(mu)"))
    ax.set_xlim(0.0, 2.0)
    ax.set_xlabel(r"friction coefficient $\mu$")
    ax.set_ylabel(r"sphere: $1/A = a^2/(R\delta)$")
    _style_legend(ax, (({"color": "0.3"}, "full solution"), ({"color": "0.3", "ls": ":", "lw": 1.0}, "adhesive (4.18)"),
                       ({"color": "0.3", "marker": "o", "mfc": "none", "ls": "none"}, "paper, §4.2 table")),
                  "center right")
    return fig


# ---------------------------------------------------------------------------------------
# registry and writer

#: name -> (compute, plot), in the order the figures are written.
FIGURES: dict[str, tuple[Callable[[], FigureData], Callable[[FigureData], Figure]]] = {
    name: (compute, plot) for (name, compute), plot in zip(COMPUTE.items(), (
        plot_fig2_chi0, plot_fig3_stick_radius, plot_fig4_compliance, plot_fig5_flat_punch_stresses,
        plot_fig6_sphere_stresses, plot_stick_radius_asymptotes, plot_slip_displacement, plot_sphere_indentation),
        strict=True)
}


def write_figures(directory: str | Path, *, formats: Sequence[str] = ("png",),
                  names: Iterable[str] | None = None, progress: Progress = False) -> list[Path]:
    """Compute, write ``<name>.csv`` and then ``<name>.<format>`` for each figure.

    Parameters
    ----------
    directory : str or Path
        Output directory (created if missing).
    formats : sequence of str
        Image formats, any of "png", "pdf", "svg" (metadata without dates, so re-runs
        give identical files with the same matplotlib and fonts).
    names : iterable of str, optional
        Keys of ``FIGURES``; all by default, in which case ``index.md`` (captions and
        links) is written too.
    progress : "auto", bool
        A bar over the figures on stderr (``numeric.solutions.progress``; the command line's default is "auto").

    Returns
    -------
    list of Path
        The files written, in order.
    """
    formats = tuple(formats)
    bad = [f for f in formats if f not in IMAGE_FORMATS]
    if bad or not formats:
        raise ValueError(f"formats must be a non-empty subset of {IMAGE_FORMATS}, got {formats!r}")
    selected = tuple(FIGURES) if names is None else tuple(names)
    unknown = [n for n in selected if n not in FIGURES]
    if unknown or not selected:
        raise ValueError(f"names must be a non-empty subset of {tuple(FIGURES)}, got {selected!r}")
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    index = ["# Figures", "", "Generated by `numeric.studies.figure_plots.write_figures`; do not edit. Data: the CSV beside "
             "each image (long format, one row per point).", ""]
    with progress_bar(len(selected), "figures", progress, unit="figure") as bar:
        for name in selected:
            compute, plot = FIGURES[name]
            data = compute()
            csv = out / f"{name}.csv"
            csv.write_text(data.to_csv())
            written.append(csv)
            fig = plot(data)
            import matplotlib

            with matplotlib.rc_context(_STYLE):
                for fmt in formats:
                    path = out / f"{name}.{fmt}"
                    fig.savefig(path, format=fmt, dpi=_DPI, metadata=_SAVE_METADATA[fmt])
                    written.append(path)
            index += [f"## {name}", "", f"![{name}]({name}.{formats[0]})", "", data.caption, ""]
            bar.update()
    if names is None:
        path = out / "index.md"
        path.write_text("\n".join(index))
        written.append(path)
    return written
