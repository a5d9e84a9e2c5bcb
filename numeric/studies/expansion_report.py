"""The checks of ``numeric.studies.expansion_checks`` rendered: Markdown tables and the error figure.

``render_markdown(study)`` gives deterministic Markdown (fixed formats, errors to 2 significant
digits, rows sorted, no timestamps) for ``derivations/section_2_3.md``; ``expansion_tables(fast)``
runs the study and renders it; ``plot_expansion_errors`` draws the log-log figure "error against
gamma" (matplotlib, imported when called).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import numpy as np

from asymptotics.document import measured

from numeric.studies.expansion_checks import ExpansionStudy, OrderRow, expansion_errors, expansion_study, observed_orders

__all__ = ["render_markdown", "expansion_tables", "plot_expansion_errors"]


def _e(v: float) -> str:
    """An error to 2 significant digits."""
    return f"{v:.1e}"


def _matrix(rows, value: str, title: str, orders: tuple[OrderRow, ...] | None = None) -> list[str]:
    """Rows c, columns gamma (nu), cells row.<value>; the first two slopes at the right."""
    gammas = sorted({(r.gamma, r.nu) for r in rows})
    cells = {(r.c, r.gamma): getattr(r, value) for r in rows}
    head = "| c | " + " | ".join(f"γ = {g:.4f} (ν = {nu:g})" for g, nu in gammas) + " |"
    if orders:
        head += " order (γ₁, γ₂) | order (γ₂, γ₃) |"
    lines = [f"**{title}**", "", head, "|" + "---|" * (len(gammas) + 1 + (2 if orders else 0))]
    slope = {o.c: o.slopes for o in orders or ()}
    for c in sorted({r.c for r in rows}):
        line = f"| {c:g} | " + " | ".join(_e(cells[(c, g)]) if (c, g) in cells else "" for g, _ in gammas) + " |"
        if orders:
            line += f" {slope[c][0]:.2f} | {slope[c][1]:.2f} |"
        lines.append(line)
    return lines + [""]


def _error_and_order(rows, error: str, quantity: str, title: str, scaled_title: str) -> list[str]:
    """The table of an error, then the table of the error scaled by its expected power of gamma with
    the observed orders."""
    return _matrix(rows, error, title) + _matrix(rows, "scaled", scaled_title, observed_orders(rows, error, quantity))


def render_markdown(study: ExpansionStudy) -> str:
    """Deterministic Markdown tables of an ``ExpansionStudy`` (errors to 2 significant digits)."""
    mode = "fast mode (table μ and P*, level-2 stresses)" if study.fast else "full mode (level-3 solutions)"
    out = [f"### Checks of the expansions of §2.3 against the full solution ({mode})", ""]
    law = study.friction_law
    out += _error_and_order(law, "relative_error", "(2.28)", "(2.28): relative error (γ f0(c) − μ)/μ of the first-order law",
                            "(2.28): relative error / γ², with the observed order in γ")
    if law[0].scaled_second is not None:
        out += _matrix(law, "scaled_second", "second order μ/γ = f0 + γ² f2: relative error / γ⁴, with the observed order",
                       observed_orders(law, "relative_error_second", "second order"))
    out += ["**(2.29), μ → 0: c from the full μ(c)**", "",
            "| γ | c | μ (full) | 4 exp(−γ/μ)/c − 1 | c_small_mu(4 terms)/c − 1 | μ log(4/c)/γ − 1 | same / γ² |",
            "|---|---|---|---|---|---|---|"]
    out += [f"| {r.gamma:.4f} | {r.c:.0e} | {r.mu:.6g} | {_e(r.relative_error_leading)} | "
            f"{_e(r.relative_error_series)} | {_e(r.exponent_defect)} | {r.exponent_defect / r.gamma**2:.3f} |"
            for r in study.small_mu] + [""]
    out += ["**(2.29), μ → ∞: 1 − c from the full μ(c)**", "",
            "| γ | 1 − c | μ (full) | 2 exp(−πμ/γ)/(1 − c) − 1 | c_large_mu(4 terms): same | "
            "πμ/(γ log(2/(1 − c))) − 1 | (μ − γf0)/(μ (γf0)²) | (P* − 1)/γ² (→ 1/3 at c = 1) |",
            "|---|---|---|---|---|---|---|---|"]
    out += [f"| {r.gamma:.4f} | {r.one_minus_c:.0e} | {r.mu:.6g} | {_e(r.relative_error_leading)} | "
            f"{_e(r.relative_error_series)} | {_e(r.exponent_defect)} | {r.law_scaled:.3f} | {r.compliance_coefficient:.5f} |"
            for r in study.large_mu] + [""]
    if study.largest_stick:
        out += ["**Largest stick radius: μ(c) of the full solution (level 2) as c → c_max(γ)**", "",
                "| γ | 1 − c | μ | 1/μ | solver error of μ |", "|---|---|---|---|---|"]
        # the solver's error estimate is a difference of two levels near c_max: its digits move with the CPU's
        # rounding; the check holds it to 1e-8 relative (measured at most 2e-10, gamma = 3/4, mu = 33)
        out += [f"| {r.gamma:.4f} | {r.one_minus_c:.3e} | {r.mu:.5g} | {1.0 / r.mu:.4g} | "
                f"{measured(r.error, 1e-8 * max(1.0, r.mu), _e(r.error))} |" for r in study.largest_stick] + [""]
        out += ["**c_max(γ) from the limit problem μ → ∞ (`numeric.slip_limit`) against K′(c_max)/K(c_max) = κ**", "",
                "| γ | κ = (2/π) atanh γ | 1 − c_max (limit problem) | relative difference from the closed form | "
                "(1 − c_max) exp(π/κ) | A/(1 − c_max) |", "|---|---|---|---|---|---|"]
        # the limit problem's 1 - c_max and its difference from the closed form are held to the 1e-10 relative the
        # tests claim (measured 1e-13 ... 6e-11), A to the 1e-6 of its difference quotient (slip_limit.APPROACH_STEP)
        out += [f"| {r.gamma:.4f} | {r.kappa:.6f} | "
                f"{measured(r.one_minus_c_max, 1e-10 * gap, f'{r.one_minus_c_max:.10e}', gap)} | "
                f"{measured(r.closed_form_difference, 1e-10, _e(r.closed_form_difference))} | {r.ratio:.6f} | "
                f"{measured(r.approach, 1e-6 * r.approach, f'{r.approach:.5f}', r.approach)} |"
                for r, gap in ((r, r.one_minus_c_max / (1.0 + r.closed_form_difference))
                               for r in study.largest_stick_estimates)] + [""]
    else:
        out += ["(The largest stick radius c_max(γ) is studied in full mode only.)", ""]
    out += _error_and_order(study.stick_shear, "max_difference", "(2.31)",
                            "(2.31): max over the stick zone of |q/(μp) − (1 − ψ)|",
                            "(2.31): that maximum / γ², with the observed order")
    comp = study.compliance
    out += _error_and_order(comp, "error", "(2.34)", "(2.34): error P*₁ − P* of the first-order compliance",
                            "(2.34): error / γ⁴, with the observed order")
    if comp[0].scaled_second is not None:
        out += _matrix(comp, "scaled_second", "P* = 1 + γ² P2 + γ⁴ P4: error / γ⁶, with the observed order",
                       observed_orders(comp, "error_second", "second order"))
    out += ["**(2.36): 1 + γ²/3 against the adhesive atanh(γ)/γ (B4)**", "",
            "| γ | atanh(γ)/γ | error | error / γ⁴ (→ −1/5) |", "|---|---|---|---|"]
    out += [f"| {r.gamma:.4f} | {r.exact:.10f} | {_e(r.error)} | {r.scaled:.4f} |" for r in study.adhesive_compliance]
    return "\n".join(out) + "\n"


def expansion_tables(fast: bool) -> str:
    """Markdown of every check of §2.3 (``expansion_study`` then ``render_markdown``).

    ``fast=True`` takes seconds, ``fast=False`` minutes (level-3 solves, the c_max study).
    """
    return render_markdown(expansion_study(fast))


def plot_expansion_errors(path: str, study: ExpansionStudy | None = None, *, fast: bool = True) -> None:
    """Log-log figure of ``expansion_errors`` against gamma, with gamma^2 and gamma^4 guides."""
    import matplotlib
    import matplotlib.ticker

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    e = expansion_errors(study if study is not None else expansion_study(fast))
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.loglog(e.gamma, e.friction_law, "o-", label="(2.28) μ = γ f0(c): relative error")
    ax.loglog(e.stick_gamma, e.stick_shear, "s-", label="(2.31) q/(μp) = 1 − ψ: max difference")
    if e.friction_law_second is not None:
        ax.loglog(e.gamma, e.friction_law_second, "^-", label="μ = γ(f0 + γ² f2): relative error")
        ax.loglog(e.gamma, e.compliance_second, "x-", label="P* = 1 + γ² P2 + γ⁴ P4: error")
    ax.loglog(e.gamma, e.compliance, "d-", label="(2.34) P* first order: error")
    ax.loglog(e.gamma, e.adhesive_compliance, "v-", label="(2.36) 1 + γ²/3 vs atanh(γ)/γ")
    g = np.geomspace(e.gamma[0], e.gamma[-1], 50)
    guides = ((2, e.stick_shear[0] / 3.0), (4, e.compliance[0] / 3.0))
    if e.compliance_second is not None:
        guides += ((6, e.compliance_second[0] / 3.0),)
    for n, below in guides:  # slope guides a factor 3 below the first point of a curve of that order
        ax.loglog(g, below * (g / g[0]) ** n, "k:", lw=1)
        ax.annotate("γ" + "⁰¹²³⁴⁵⁶"[n], (g[-1], below * (g[-1] / g[0]) ** n), fontsize=8, ha="left", va="center")
    ax.xaxis.set_major_locator(matplotlib.ticker.FixedLocator([0.02, 0.05, 0.1, 0.2, 0.5]))
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("γ = (1 − 2ν)/(2 − 2ν)")
    ax.set_ylabel("worst |error| over c")
    ax.set_title("Expansions of [S75] §2.3 against the full solution")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
