"""The tables of [S75] §4 and §4.2, recomputed with the paper's scheme beside the exact values.

Each table lists the paper's printed number, ours (``numeric.baseline.scheme`` on the paper's
mesh), the exact value where a closed form exists (Appendix B, (4.18)) and the errors.
The printed numbers are transcribed from ``shared/spec/spence1975.md`` with the layout of
the last table taken from errata item 3; they are data to compare with, never inputs.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np

from asymptotics.adhesive import (
    central_pressure_adhesive,
    compliance_adhesive,
    sphere_A_adhesive,
    sphere_C_adhesive,
    sphere_central_pressure_adhesive,
    sphere_pressure_slope_adhesive,
)
from asymptotics.materials import gamma_from_nu

from numeric.baseline.scheme import paper_mesh, solve_adhesive, solve_friction, sphere_from_flat
from numeric.solutions.progress import Progress, progress_bar

__all__ = ["PAPER", "render"]

#: Numbers as printed in [S75] (transcribed; see errata items 3 and 8 for the layout).
PAPER = {
    "mesh": {  # §4, nu = 0, c = 1: label -> (N, P*, p(0))
        "i": (25, 1.09652, 0.80926),
        "ii": (50, 1.09769, 0.80881),
        "iii": (55, 1.09834, 0.80778),
        "iv": (60, 1.09826, 0.80784),
    },
    "nu": {0.0: 1.09834, 0.125: 1.06884, 0.25: 1.03964, 0.375: 1.01366},  # §4, P* at N = 55
    "alpha": {"alpha0": 0.99437, "alpha1": 0.91345, "alpha2": 0.32167},  # §4.2, nu = 0, c = 1
    "central_fit": (1.615725, -0.2801, -0.781),  # §4.2, p^(2) = a0 + a1 x + a2 x^2
    "sphere_force": 2.91840,  # §4.2 "direct quadrature of the p^(2) distribution" = 4 P*
    "mu_inverse_A": {  # §4.2 last table: (nu, c) -> (mu, 1/A); mu is None at c = 1
        (0.0, 0.24): (0.2063, 0.9684),
        (0.0, 0.5): (0.2986, 0.9578),
        (0.0, 0.7): (0.4013, 0.9479),
        (0.0, 0.8): (0.4862, 0.9417),
        (0.0, 1.0): (None, 0.9190),
        (0.25, 0.3): (0.1387, 0.9827),
        (0.25, 0.5): (0.1801, 0.9794),
        (0.25, 0.8): (0.2843, 0.9728),
        (0.25, 1.0): (None, 0.9635),
    },
}


def _fmt(value: float | None, digits: int = 5) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    return f"{value:.{digits}f}"


def _err(value: float, exact: float | None) -> str:
    return "-" if exact is None else f"{value - exact:+.1e}"


def _table(header: list[str], rows: list[list[str]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return lines + [""]


def mesh_table() -> list[str]:
    """P* and p(0) of the adhesive flat punch at nu = 0 on meshes (i)-(iv) of §4."""
    exact_p, exact_c = float(compliance_adhesive(0.5)), float(central_pressure_adhesive(0.5))
    rows = []
    for label, (n, paper_c, paper_p) in PAPER["mesh"].items():
        sol = solve_adhesive(paper_mesh(label), 0.0)
        rows.append(
            [f"({label}) {n}", _fmt(paper_c), _fmt(sol.compliance, 6), _fmt(exact_p, 6), _err(paper_c, exact_p),
             _err(sol.compliance, exact_p), _fmt(paper_p), _fmt(sol.central_pressure, 6), _fmt(exact_c, 6),
             _err(paper_p, exact_c), _err(sol.central_pressure, exact_c)]
        )
    header = ["mesh N", "P* paper", "P* ours", "P* exact (B4)", "err paper", "err ours",
              "p(0) paper", "p(0) ours", "p(0) exact (4.10)", "err paper", "err ours"]
    return ["## Adhesive flat punch, nu = 0: the mesh table of §4", ""] + _table(header, rows)


def nu_table() -> list[str]:
    """P* of the adhesive flat punch on mesh (iii), N = 55, for four Poisson ratios."""
    rows = []
    for nu, paper in PAPER["nu"].items():
        sol = solve_adhesive(paper_mesh("iii"), nu)
        exact = float(compliance_adhesive(gamma_from_nu(nu)))
        rows.append([f"{nu:g}", _fmt(paper), _fmt(sol.compliance, 6), _fmt(exact, 6), _err(paper, exact),
                     _err(sol.compliance, exact)])
    header = ["nu", "P* paper", "P* ours", "P* exact (B4)", "err paper", "err ours"]
    return ["## Adhesive flat punch, N = 55: the nu table of §4", ""] + _table(header, rows)


def sphere_table() -> list[str]:
    """The adhesive sphere test of §4.2 at nu = 0 (friction mesh at c = 1, N = 54)."""
    gamma = 0.5
    fit = sphere_from_flat(solve_friction(1.0, 0.0))
    A, C = float(sphere_A_adhesive(gamma)), float(sphere_C_adhesive(gamma))
    exact = {"alpha0": 1.0, "alpha1": 1.0 / A, "alpha2": -3.0 * np.pi * C / 4.0}
    rows = [[name, _fmt(PAPER["alpha"][name]), _fmt(getattr(fit, name), 6), _fmt(exact[name], 6),
             _err(PAPER["alpha"][name], exact[name]), _err(getattr(fit, name), exact[name])]
            for name in ("alpha0", "alpha1", "alpha2")]
    central_exact = (float(sphere_central_pressure_adhesive(gamma)), float(sphere_pressure_slope_adhesive(gamma)), None)
    for k, name in enumerate(("p(0)", "p'(0)", "p''(0)/2")):
        rows.append([f"{name} (quadratic fit)", _fmt(PAPER["central_fit"][k]), _fmt(fit.central_fit[k], 6),
                     _fmt(central_exact[k], 6), _err(PAPER["central_fit"][k], central_exact[k]),
                     _err(fit.central_fit[k], central_exact[k])])
    force_exact = 4.0 * 2.0 / 3.0 * float(compliance_adhesive(gamma))
    rows.append(["4 P* direct quadrature", _fmt(PAPER["sphere_force"]), _fmt(4 * fit.compliance_direct, 6),
                 _fmt(force_exact, 6), _err(PAPER["sphere_force"], force_exact),
                 _err(4 * fit.compliance_direct, force_exact)])
    header = ["quantity", "paper", "ours", "exact", "err paper", "err ours"]
    notes = [
        "alpha0, alpha1, alpha2: least-squares fits (4.16)-(4.17); exact 1, 1/A and -3 pi C/4 of (4.18).",
        "p(0), p'(0): (B6). 4 P*: the paper's 2.91840 is 2 pi int x p dx = 4 P* (errata item 2);"
        " exact 4 (2/3) log 3 by (3.17), (B4).",
        "",
    ]
    return ["## Adhesive sphere, nu = 0: the test of §4.2", ""] + _table(header, rows) + notes


def mu_table() -> list[str]:
    """mu(c) and 1/A = alpha1 on the friction mesh of §4.1, the last table of §4.2."""
    rows = []
    for (nu, c), (paper_mu, paper_inv_a) in PAPER["mu_inverse_A"].items():
        sol = solve_friction(c, nu)
        fit = sphere_from_flat(sol)
        exact = 1.0 / float(sphere_A_adhesive(gamma_from_nu(nu))) if c == 1.0 else None
        rows.append([f"{nu:g}", f"{c:g}", _fmt(paper_mu, 4), _fmt(None if c == 1.0 else sol.mu, 5),
                     _fmt(paper_inv_a, 4), _fmt(fit.alpha1, 5), _fmt(exact, 5), _err(fit.alpha1, exact)])
    header = ["nu", "c", "mu paper", "mu ours", "1/A paper", "1/A ours (alpha1)", "1/A exact (4.18)", "err ours"]
    return ["## Friction coefficient and sphere constant: the last table of §4.2", ""] + _table(header, rows)


def render(progress: Progress = False) -> str:
    """All four tables as Markdown; ``progress`` as for the sweeps (``numeric.solutions.progress``: a bar per table
    on stderr)."""
    lines = ["# The tables of Spence (1975) recomputed with the paper's own scheme", "",
             "Generated by `hertz-friction tables`; do not edit.", ""]
    parts = (mesh_table, nu_table, sphere_table, mu_table)
    with progress_bar(len(parts), "tables", progress, unit="table") as bar:
        for part in parts:
            lines += part()
            bar.update()
    return "\n".join(lines)
