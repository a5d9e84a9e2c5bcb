"""The measured checks of the plane-strain solution, rendered for ``derivations/plane_strain.md``.

Computes (about 20 s): the largest stick width c_max from the limit problem mu -> inf; the first-order law's error
against the solver, (mu/mu_1 - 1)/gamma^2, and its observed order in gamma; the solver's levels and their error
estimates against the median of degrees 26 and 28; the independent piecewise-constant scheme
(``numeric.baseline.plane_scheme``) at the paper's resolution and Richardson-extrapolated; the cylinder's load,
central pressure and peak shear against Hertz; the law below the solver's smallest c against the solver's iteration
run below it. Deterministic (no timings); the figures at the rounding level (errors, estimates, the law's fit) move
with the BLAS threads and the CPU and are written as measured figures with the claim each is checked against
(``asymptotics.document.measured``), so a re-run on another machine leaves ``git diff`` empty.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from asymptotics.document import measured
from asymptotics.materials import gamma_from_nu
from asymptotics.plane import mu_over_gamma_plane

from numeric.baseline.plane_scheme import extrapolated_mu, plane_solve_friction
from numeric.core.plane_charts import PlaneResolution
from numeric.core.plane_eigenvalue import plane_given_c
from numeric.core.plane_fields import PlaneField
from numeric.solutions.plane_law import law_fit, law_friction_coefficient
from numeric.solutions.plane_power_law import plane_power_law
from numeric.solutions.plane_punch import plane_slip_limit, strip_punch
from numeric.solutions.plane_solver import DEFAULT_LEVEL, PLANE_LEVELS
from numeric.studies.plane_bench import reference_mu

__all__ = ["plane_checks_markdown"]


def _c_max_table() -> list[str]:
    rows = ["| nu | gamma | 1 - c_max | estimated error | K'(c_max)/K(c_max) / eps (eps = atanh(gamma)/pi) |",
            "|---|---|---|---|---|"]
    for nu in (0.2, 0.1, 0.0, -0.25, -0.5):
        g = float(gamma_from_nu(nu))
        s = plane_slip_limit(nu)
        ratio = float(special.ellipkm1(s.c * s.c) / special.ellipkm1(s.gap * (1.0 + s.c))) / (math.atanh(g) / math.pi)
        # 1 - c_max known to its estimate; the estimate (a difference at the rounding level) claimed below 1e-10
        rows.append(f"| {nu:g} | {g:.6f} | {measured(s.gap, s.error, f'{s.gap:.10e}', s.gap)} | "
                    f"{measured(s.error, 1e-10, f'{s.error:.1e}')} | {ratio:.6f} |")
    return rows


def _first_order_table() -> list[str]:
    rows = ["| c | nu = 0.49 | 0.45 | 0.4 | 0.3 | 0 | observed order (0.49, 0.45) |", "|---|---|---|---|---|---|---|"]
    for c in (0.3, 0.5, 0.8):
        values, gammas = [], []
        for nu in (0.49, 0.45, 0.4, 0.3, 0.0):
            g = float(gamma_from_nu(nu))
            mu = strip_punch(nu=nu, c=c).mu
            values.append(mu / (g * float(mu_over_gamma_plane(c))) - 1.0)
            gammas.append(g)
        order = math.log(values[0] / values[1]) / math.log(gammas[0] / gammas[1])
        rows.append(f"| {c:g} | " + " | ".join(f"{v / g**2:.4f}" for v, g in zip(values, gammas)) + f" | {order:.3f} |")
    return rows


def _levels_table() -> list[str]:
    rows = ["| nu | c | mu (reference) | level: error, estimate | | | | |", "|---|---|---|---|---|---|---|---|"]
    for nu, c in ((0.3, 0.5), (0.0, 0.9), (-0.5, 0.9), (0.3, 0.05)):
        mu_ref = reference_mu(nu, c)
        cells = []
        for level in range(len(PLANE_LEVELS)):
            s = strip_punch(nu=nu, c=c, level=level)
            error, estimate = abs(s.mu - mu_ref) / mu_ref, s.error / s.mu
            # the error is claimed below the estimate; the estimate, where it is the 1e-10 floor, is that floor
            cells.append(f"{level}: {measured(error, estimate, f'{error:.1e}')}, {estimate:.1e}")
        # the reference's own scatter (BLAS threads, starts): 1e-11 relative, plus theta's absolute rounding ~1e-12
        # over theta (mu = tan(theta)/gamma; at nu = 0.3, c = 0.05, theta = 0.031, one and two threads gave mu 1.9e-11
        # apart)
        theta = math.atan(mu_ref * float(gamma_from_nu(nu)))
        tolerance = (1e-11 + 1e-12 / theta) * mu_ref
        rows.append(f"| {nu:g} | {c:g} | {measured(mu_ref, tolerance, f'{mu_ref:.12f}', mu_ref)} | "
                    + " | ".join(cells) + " |")
    return rows


def _scheme_table() -> list[str]:
    rows = ["| nu | c | mu (solver) | paper's mesh (h = 0.02) | difference | extrapolated (h = 0.005 ... 0.00125) | "
            "difference | observed order |", "|---|---|---|---|---|---|---|---|"]
    for nu, c in ((0.3, 0.5), (0.25, 0.3), (0.0, 0.24), (0.0, 0.5), (0.375, 0.8)):
        mu = strip_punch(nu=nu, c=c).mu
        paper = plane_solve_friction(c, nu, h=0.02).mu
        e = extrapolated_mu(c, nu, h=0.005)
        rows.append(f"| {nu:g} | {c:g} | {mu:.10f} | {paper:.5f} | {paper - mu:+.1e} | {e.extrapolated:.8f} | "
                    f"{e.extrapolated - mu:+.1e} | {e.order:.3f} |")
    return rows


def _cylinder_table() -> list[str]:
    rows = ["| nu | mu | c | P / P_Hertz at the same a | p(0) / p_Hertz(0) | max q / max p | at x |",
            "|---|---|---|---|---|---|---|"]
    x = np.linspace(0.0, 1.0, 401)[1:-1]
    for nu in (0.0, 0.3):
        for mu in (0.1, 0.3, 1.0):
            h = plane_power_law(2, nu=nu, mu=mu)
            q = np.asarray(h.shear(x))
            k = int(np.argmax(q))
            rows.append(f"| {nu:g} | {mu:g} | {h.c:.8f} | {h.load_ratio:.8f} | "
                        f"{float(h.pressure(0.0)) / (2 / math.pi):.8f} | {q[k] / float(h.pressure(0.0)):.5f} | {x[k]:.4f} |")
    return rows


def _small_c_table() -> list[str]:
    rows = ["| nu | gamma | a | b | error bound (relative) | mu law / mu solver - 1 at c = 1e-6 | at 1e-7 |",
            "|---|---|---|---|---|---|---|"]
    for nu in (0.45, 0.3, 0.0, -0.5, -0.9):
        g = float(gamma_from_nu(nu))
        fit = law_fit(g, DEFAULT_LEVEL)
        cells = []
        for c in (1e-6, 1e-7):
            mu = law_friction_coefficient(c, g, DEFAULT_LEVEL)[0]
            solved = plane_given_c(c, 1.0 - c, g, math.atan(mu * g), PLANE_LEVELS[3])
            difference = mu / PlaneField(solved).mu - 1.0
            cells.append(measured(difference, fit.relative_error, f"{difference:.1e}"))  # claimed within the bound
        # a and b from two solver solves at c = 1e-4, 1e-5 (round-off ~1e-13/c each): known to the law's bound over
        # gamma^2 (a) and that times L^2 = log(4e5)^2 (b); the bound (a difference of two fits) to itself
        bound, a_tol = fit.relative_error, fit.relative_error / g**2
        rows.append(f"| {nu:g} | {g:.6f} | {measured(fit.a, a_tol, f'{fit.a:.8f}', fit.a)} | "
                    f"{measured(fit.b, a_tol * math.log(4e5) ** 2, f'{fit.b:.6f}', fit.b)} | "
                    f"{measured(bound, bound, f'{bound:.1e}', bound)} | {cells[0]} | {cells[1]} |")
    return rows


def plane_checks_markdown() -> str:
    """The measured block of ``plane_strain.md``."""
    lines = ["## Measured: the full solution and its checks", "",
             "Largest stick width (the limit problem mu -> inf, slip zones without pressure, level 2). K'/K at c_max "
             "is not a fixed multiple of eps (nor of gamma, asin gamma, atan gamma; nor for the moduli c^2, sqrt(c) "
             "or Landen's): no closed form of the 3-D kind K'(c_max)/K(c_max) = kappa was found.", "",
             *_c_max_table(), "",
             "First-order law mu/gamma = K(c)/K'(c) against the solver: (mu/mu_1 - 1)/gamma^2 tends to a constant as "
             "gamma -> 0 (order 2).", "", *_first_order_table(), "",
             "The solver's levels (degree 12, 15, 18, 21, 24): relative error of mu against the median of degrees 26 "
             "and 28 in two layouts (``numeric.studies.plane_bench.reference_mu``) and the estimated error (partner "
             "one degree lower, at least 1e-10 relative).", "", *_levels_table(), "",
             "The independent discretisation (piecewise constants, the paper's eigen condition): first order; at the "
             "paper's resolution three places, not the four [S75] §4.1 claims for the 2-D calculations.", "",
             *_scheme_table(), "",
             "The cylinder (n = 2), from the strip punch by (3.13) and the outside slope: load at the same contact "
             "half-width over Hertz's pi a^2 E*/(4 R), central pressure over (2/pi) P/a, the peak shear traction.", "",
             *_cylinder_table(), "",
             "Below the solver's smallest c (1e-5): mu = mu_1 (1 + gamma^2 (a + b/L^2)), L = log(4/c), a and b fitted "
             "to the solver at c = 1e-4 and 1e-5 (``numeric.solutions.plane_law``), against the solver's iteration "
             "run directly at c = 1e-6 and 1e-7 (level 3), which the public route does not do (0.1-0.7 s a solve).", "",
             *_small_c_table()]
    return "\n".join(lines) + "\n"
