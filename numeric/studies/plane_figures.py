"""The plane-strain figures: the stick half-width against friction, and the stresses of the strip punch and cylinder.

``plane_stick_width_data`` / ``plane_stresses_data`` compute (``FigureData`` of ``numeric.studies.figures``: the CSV is
what tests compare), ``plot_plane_figure`` draws with matplotlib (Agg, imported inside), and ``write_plane_figures``
writes ``<name>.csv`` then ``<name>.png`` into a directory (``derivations/figures`` via ``regenerate.py``; the
``plane-figures`` subcommand of the command line). About 10 s.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from asymptotics.materials import gamma_from_nu
from asymptotics.plane import stick_width_first_order

from numeric.solutions.plane_power_law import plane_power_law
from numeric.solutions.plane_punch import plane_slip_limit, strip_punch
from numeric.studies.figures import Curve, FigureData

__all__ = ["PLANE_FIGURES", "plane_stick_width_data", "plane_stresses_data", "plot_plane_figure", "write_plane_figures"]

NUS = (0.3, 0.0, -0.5)
MUS = (0.1, 0.3, 1.0)


def _curve(panel: str, model: str, x, y, **params: float) -> Curve:
    xs, ys = np.array(x, dtype=float), np.array(y, dtype=float)
    xs.setflags(write=False)
    ys.setflags(write=False)
    return Curve(panel, model, tuple(sorted(params.items())), xs, ys)


def plane_stick_width_data() -> FigureData:
    """c(mu) of the strip punch (every power law) for nu = 0.3, 0, -1/2: the full solution (below c = 1e-5 the law
    fitted to the solver, ``numeric.solutions.plane_law``), the first-order law, c_max."""
    curves = []
    mus = np.geomspace(0.1, 30.0, 25)
    for nu in NUS:
        g = float(gamma_from_nu(nu))
        c_max = plane_slip_limit(nu).c
        solved = [strip_punch(nu=nu, mu=float(m)).c for m in mus]  # below c = 1e-5 the law fitted to the solver
        curves.append(_curve("c(mu)", "full solution", mus, solved, nu=nu))
        curves.append(_curve("c(mu)", "first order", mus, np.asarray(stick_width_first_order(mus, g)), nu=nu))
        curves.append(_curve("c(mu)", "c_max", [mus[0], mus[-1]], [c_max, c_max], nu=nu))
    return FigureData("plane_stick_width", "Stick half-width c/a of the strip punch and the cylinder against mu: the "
                      "full solution, the first-order law mu/gamma = K(c)/K'(c), and the largest stick width c_max "
                      "(the limit mu -> inf)", (("c(mu)", "mu", "c/a"),), tuple(curves))


def plane_stresses_data() -> FigureData:
    """p and q of the strip punch and the cylinder at nu = 0.3 for mu = 0.1, 0.3, 1, and the frictionless ones."""
    x = np.concatenate([np.linspace(0.0, 0.98, 99), 1.0 - np.geomspace(1e-2, 1e-4, 9)])
    curves = []
    for mu in (0.0, *MUS):
        s = strip_punch(nu=0.3, mu=mu)
        h = plane_power_law(2, nu=0.3, mu=mu)
        curves += [_curve("strip p(x)", "solver", x, s.pressure(x), mu=mu),
                   _curve("strip q(x)", "solver", x, s.shear(x), mu=mu),
                   _curve("cylinder p(x)", "solver", x, h.pressure(x), mu=mu),
                   _curve("cylinder q(x)", "solver", x, h.shear(x), mu=mu)]
    return FigureData("plane_stresses", "Pressure p and shear q (over P/a; P the load per unit length) under the strip "
                      "punch and the cylinder at nu = 0.3 for mu = 0, 0.1, 0.3, 1; q = mu p outside the stick zone",
                      (("strip p(x)", "x/a", "p a/P"), ("strip q(x)", "x/a", "q a/P"), ("cylinder p(x)", "x/a", "p a/P"),
                       ("cylinder q(x)", "x/a", "q a/P")), tuple(curves))


PLANE_FIGURES = {"plane_stick_width": plane_stick_width_data, "plane_stresses": plane_stresses_data}


def plot_plane_figure(data: FigureData):
    """The figure of ``data`` (matplotlib Figure with the Agg canvas)."""
    from matplotlib import colormaps
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    panels = data.panels
    fig = Figure(figsize=(6.4 if len(panels) == 1 else 9.0, 4.2 if len(panels) == 1 else 6.4))
    FigureCanvasAgg(fig)
    axes = [fig.add_subplot(1, 1, 1)] if len(panels) == 1 else [fig.add_subplot(2, 2, k + 1) for k in range(len(panels))]
    colours = colormaps["viridis"]
    for ax, (panel, xq, yq) in zip(axes, panels):
        for cv in data.select(panel=panel):
            key = dict(cv.params)
            value = key.get("nu", key.get("mu", 0.0))
            index = (NUS.index(value) if "nu" in key else (0, *MUS).index(value))
            colour = colours(index / 3.0)
            style = {"solver": "-", "full solution": "-", "first order": "--", "c_max": ":"}[cv.model]
            label = f"{'nu' if 'nu' in key else 'mu'} = {value:g}" if style == "-" else None
            ax.plot(cv.x, cv.y, style, color=colour, label=label, lw=1.2)
        ax.set_xlabel(xq)
        ax.set_ylabel(yq)
        if panel == "c(mu)":
            ax.set_xscale("log")
            ax.set_title("solid: full solution; dashed: first-order law; dotted: c_max", fontsize=9)
        if "p(x)" in panel:
            ax.set_ylim(0.0, 1.5 if "strip" in panel else 1.0)
        if panel == "strip q(x)":  # q = mu p is infinite at the edge, like p
            ax.set_ylim(-0.02, 0.8)
        ax.set_title(panel if panel != "c(mu)" else ax.get_title(), fontsize=9)
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def write_plane_figures(directory: str | Path) -> list[Path]:
    """Compute, write ``<name>.csv`` and then ``<name>.png`` for each plane figure; returns the files written."""
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name, compute in PLANE_FIGURES.items():
        data = compute()
        csv = out / f"{name}.csv"
        csv.write_text(data.to_csv())
        fig = plot_plane_figure(data)
        png = out / f"{name}.png"
        fig.savefig(png, format="png", dpi=150, metadata={"Software": None})
        written += [csv, png]
    return written
