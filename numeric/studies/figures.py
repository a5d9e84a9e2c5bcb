"""The data of the figures of [S75] (figures 2-6), redrawn from our solutions, and of figures the paper lacks.

This module computes; ``numeric.studies.figure_plots`` draws. For each figure a compute
function (``fig2_chi0``, ...) returns a ``FigureData``: the plotted curves as read-only arrays,
each with the parameters held fixed along it. ``FigureData.to_csv`` writes them in long format
(one row a point, ``%.10g``, rows in a fixed order), which is what tests and ``git diff``
compare. ``COMPUTE`` lists them by file name, in the order they are written.

Dimensionless quantities ((2.1), (2.4), (3.2)): x = r/a; p = -sigma_zz (1 - nu) a / (G delta),
q = -sigma_rz (1 - nu) a / (G delta); u = d u_r / d delta in the slip annulus (2.10);
P* = (1 - nu) P / (4 G a delta); the sphere's delta = A a^2 / R.

Sources of the data: the high-accuracy solver at its default level 2 (``numeric.flat_punch``,
errors ~1e-10 in mu and P*, ~1e-8 pointwise in the stresses), its Chebyshev table for
sweeps over c (``numeric.core.table``, 7e-12), the power-law quadrature (3.13)
(``numeric.solutions.power_law``) and the closed forms of ``asymptotics`` (chi^(0) of (2.27) is
``asymptotics.first_order.chi0``). Sweeps toward c = 1 (solver
points at 1 - c from 0.034 down to 1.1e-6) stop after the first point beyond mu/gamma = 8
(off every plot), or where the solver's error estimate exceeds 1e-4 of mu or it finds no
friction coefficient (for gamma >= ~0.4 it reports a largest stick radius below 1, README).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike
from scipy import optimize, special

from asymptotics.adhesive import compliance_adhesive, sphere_A_adhesive
from asymptotics.arrays import read_only
from asymptotics.first_order import chi0, mu_over_gamma, shear_ratio_first_order
from asymptotics.materials import check_c, check_nu, gamma_from_nu

from numeric.core.errors import NoEigenvalueError
from numeric.core.table import table_compliance
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.power_law import indentation_constant, power_law, power_law_pressure, power_law_shear
from numeric.solutions.solution import FlatPunchSolution
from numeric.solutions.sweep import friction_coefficient, stick_radius
from numeric.studies.paper_tables import PAPER

__all__ = [
    "Curve",
    "FigureData",
    "COMPUTE",
    "fig2_chi0",
    "fig3_stick_radius",
    "fig4_compliance",
    "fig5_flat_punch_stresses",
    "fig6_sphere_stresses",
    "stick_radius_asymptotes",
    "slip_displacement",
    "sphere_indentation",
]

#: Poisson's ratios of the curve families (the paper's four and one near 1/2).
NU_VALUES = (0.0, 0.125, 0.25, 0.375, 0.45)
#: Stick radii of the stress figures: the paper's nu = 0 runs of §4.2 (errata item 3).
C_VALUES = (0.24, 0.5, 0.7, 0.8)
#: mu/gamma of the two chi^(0) curves (roots c = 0.49 and 0.90 by (2.28)).
MU_OVER_GAMMA_VALUES = (0.5, 1.0)
#: Sweeps toward c = 1 stop when the solver's error estimate exceeds this fraction of mu.
SWEEP_RTOL = 1e-4
#: ... and after the first point beyond mu/gamma = 8 (mu = 4 at nu = 0), the largest plotted.
MU_OVER_GAMMA_MAX = 8.0
CSV_FORMAT = "%.10g"
X_MAX_FLAT = 0.995  # the flat-punch stresses are infinite at x = 1: data stop here

# ---------------------------------------------------------------------------------------
# data


@dataclass(frozen=True, slots=True)
class Curve:
    """One plotted line or set of markers.

    Attributes
    ----------
    panel : str
        Which axes it belongs to, named ``"y(x)"`` (e.g. ``"c(mu)"``).
    model : str
        What produced it: ``"solver"``, ``"(2.28)"``, ``"paper"``, ``"frictionless"``, ...
    params : tuple of (str, float)
        Parameters held fixed along the curve (e.g. ``(("nu", 0.0),)``).
    x, y : ndarray
        The points, read-only.
    """

    panel: str
    model: str
    params: tuple[tuple[str, float], ...]
    x: np.ndarray
    y: np.ndarray

    def param(self, name: str) -> float:
        """The value of parameter ``name`` (``KeyError`` if the curve has none)."""
        return dict(self.params)[name]


@dataclass(frozen=True, slots=True)
class FigureData:
    """The data of one figure: its curves, and what its panels' axes mean.

    Attributes
    ----------
    name : str
        File stem, a key of ``FIGURES``.
    caption : str
        Caption for documents (also the CSV's leading comment).
    panels : tuple of (str, str, str)
        (panel, x quantity, y quantity), in drawing order.
    curves : tuple of Curve
    """

    name: str
    caption: str
    panels: tuple[tuple[str, str, str], ...]
    curves: tuple[Curve, ...]

    def select(self, panel: str | None = None, model: str | None = None, **params: float) -> tuple[Curve, ...]:
        """Curves of ``panel`` and ``model`` (None: any) whose parameters match ``params``."""
        return tuple(cv for cv in self.curves
                     if (panel is None or cv.panel == panel) and (model is None or cv.model == model)
                     and all(dict(cv.params).get(k) == v for k, v in params.items()))

    def to_csv(self) -> str:
        """Long-format CSV: comment lines (caption, panel axes), header, one row per point."""
        names: list[str] = []
        for cv in self.curves:
            names += [k for k, _ in cv.params if k not in names]
        lines = [f"# {self.name}: {self.caption}"]
        lines += [f"# panel {p}: x = {xq}, y = {yq}" for p, xq, yq in self.panels]
        lines.append(",".join(["panel", "model", *names, "x", "y"]))
        for cv in self.curves:
            fixed = dict(cv.params)
            head = [cv.panel, cv.model] + [_fmt(fixed[k]) if k in fixed else "" for k in names]
            lines += [",".join(head + [_fmt(a), _fmt(b)]) for a, b in zip(cv.x, cv.y)]
        return "\n".join(lines) + "\n"


def _fmt(value: float) -> str:
    return CSV_FORMAT % value


def _curve(panel: str, model: str, x: ArrayLike, y: ArrayLike, **params: float) -> Curve:
    xs, ys = read_only(x), read_only(y)
    if xs.shape != ys.shape or xs.ndim != 1:
        raise ValueError(f"x and y of a curve must be 1-d of equal length, got {xs.shape} and {ys.shape}")
    if np.any(np.isnan(xs)) or np.any(np.isnan(ys)):
        raise ValueError(f"NaN in curve {panel} {model} {params}")
    return Curve(panel, model, tuple((k, float(v)) for k, v in params.items()), xs, ys)


# ---------------------------------------------------------------------------------------
# roots and sampling


def _chi0_root(ratio: float) -> float:
    """The root of chi^(0) in (0, 1), by bracketing chi0 itself (not via (2.28))."""
    lo = 0.5
    while chi0(lo, ratio) <= 0.0:
        lo *= 0.5
    hi = 0.5
    while chi0(hi, ratio) >= 0.0:
        hi = 0.5 * (1.0 + hi)
    return optimize.brentq(lambda t: float(chi0(t, ratio)), lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)


def _samples(lo: float, hi: float, breakpoints: ArrayLike = (), n: int = 300, finest: float = 1e-5) -> np.ndarray:
    """A uniform grid on [lo, hi] merged with the solution's breakpoints inside it.

    The breakpoints are graded geometrically toward c and 1, so merging them puts points
    densely where the stresses vary fastest; points closer than ``finest`` to an earlier
    one are dropped (invisible on a plot)."""
    b = np.asarray(breakpoints, dtype=float)
    pts = np.unique(np.concatenate([np.linspace(lo, hi, n), b[(b >= lo) & (b <= hi)]]))
    keep = [pts[0]]
    for t in pts[1:]:
        if t - keep[-1] >= finest or t == hi:
            keep.append(t)
    return np.array(keep)


def _logit_grid(c_lo: float, c_hi: float, n: int) -> np.ndarray:
    return special.expit(np.linspace(special.logit(c_lo), special.logit(c_hi), n))


# ---------------------------------------------------------------------------------------
# cached solutions (pure functions of their arguments; results are read-only)


@dataclass(frozen=True, slots=True)
class _Sweep:
    """mu(c) and P*(c) for one nu: table for 1e-3 <= c <= 0.95, solver for c toward 1."""

    nu: float
    gamma: float
    c: np.ndarray
    one_minus_c: np.ndarray  # exact complement of c, for the c -> 1 plots
    mu: np.ndarray
    compliance: np.ndarray


#: 1 - c of the solver points toward c = 1: dense enough for linear axes, then
#: geometric down to 1.1e-6 for the log plot (the sweep may stop earlier, see ``_sweep``).
TAIL_ONE_MINUS_C = tuple(0.05 * 10.0 ** (-k / 6.0) for k in range(1, 10)) + tuple(
    0.05 * 10.0 ** (-k / 3.0) for k in range(6, 15))


@functools.lru_cache(maxsize=None)
def _sweep(nu: float) -> _Sweep:
    gamma = float(gamma_from_nu(nu))
    mid = np.clip(_logit_grid(1e-3, 0.95, 90), 1e-3, 0.95)  # inside the Chebyshev table
    rows = list(zip(mid, 1.0 - mid, np.asarray(friction_coefficient(mid, nu), dtype=float),
                    np.asarray(table_compliance(mid, np.full(mid.shape, gamma)), dtype=float)))  # (c, 1 - c, mu, P*)
    for om in TAIL_ONE_MINUS_C:  # solver
        try:
            s = _flat(nu, 1.0 - om)
        except NoEigenvalueError:
            break  # beyond the solver's largest stick radius (large gamma)
        if s.error > SWEEP_RTOL * s.mu:
            break
        rows.append((1.0 - om, om, s.mu, s.compliance))
        if s.mu > MU_OVER_GAMMA_MAX * gamma:
            break  # the curve has left every plot
    c, one_minus_c, mu, compliance = (read_only(col) for col in zip(*rows))
    return _Sweep(nu, gamma, c, one_minus_c, mu, compliance)


@functools.lru_cache(maxsize=None)
def _flat(nu: float, c: float) -> FlatPunchSolution:
    return flat_punch(nu=nu, c=c)  # level 2


@functools.lru_cache(maxsize=None)
def _flat_mu(nu: float, mu: float) -> FlatPunchSolution:
    return flat_punch(nu=nu, mu=mu)  # closed forms at mu = 0 and mu = inf


# ---------------------------------------------------------------------------------------
# compute functions


def fig2_chi0(ratios: Sequence[float] = MU_OVER_GAMMA_VALUES) -> FigureData:
    """chi^(0)(x) of [S75] (2.27) for several mu/gamma (the paper's figure 2).

    Each curve's x grid contains its root c (where chi^(0)(c) = 0, the first-order law
    (2.28)); the root is the curve parameter ``c``.
    """
    curves = []
    for r in ratios:
        root = _chi0_root(float(r))
        x = np.unique(np.concatenate([[0.0], np.geomspace(1e-6, 1e-2, 40), np.linspace(0.0, 0.999, 400), [root]]))
        curves.append(_curve("chi0(x)", "(2.27)", x, chi0(x, r), mu_over_gamma=r, c=root))
    caption = ("First-order excess friction chi^(0)(x) (2.27), p = frictionless pressure (2.26), for two values "
               "of mu/gamma; its root is the first-order stick radius c of (2.28) (chi^(0) >= 0 on the stick "
               "zone x <= c). chi^(0) -> -inf at x = 1.")
    return FigureData("fig2_chi0", caption, (("chi0(x)", "x", "chi^(0)"),), tuple(curves))


def fig3_stick_radius(nus: Sequence[float] = NU_VALUES) -> FigureData:
    """Stick radius c against friction mu: full solution and first-order law (2.28) (paper's figure 3).

    The full curve is parametrised by c (mu from ``friction_coefficient``, starting at the
    frictionless point c = 0, mu = 0); the first-order curve is mu = gamma atanh(c)/(c K'(c)).
    The paper's printed mu(c) of §4.2 are added as model ``"paper"``.
    """
    curves = []
    c_first = _logit_grid(1e-6, 1 - 1e-9, 400)
    for nu in nus:
        sw = _sweep(float(nu))
        curves.append(_curve("c(mu)", "solver", np.r_[0.0, sw.mu], np.r_[0.0, sw.c], nu=nu))
        curves.append(_curve("c(mu)", "(2.28)", np.r_[0.0, sw.gamma * mu_over_gamma(c_first)], np.r_[0.0, c_first],
                             nu=nu))
    for nu in nus:
        table = [(mu, c) for (n, c), (mu, _) in PAPER["mu_inverse_A"].items() if n == nu and mu is not None]
        if table:
            curves.append(_curve("c(mu)", "paper", [m for m, _ in table], [c for _, c in table], nu=nu))
    caption = ("Stick radius c (radius of the no-slip zone over the contact radius) against the friction "
               "coefficient mu for several Poisson's ratios nu: full solution (solid; the same for a flat punch "
               "and any power-law indenter, §3.2) and the first-order law (2.28) (dashed), exact as gamma -> 0; "
               "markers: the paper's values (§4.2 table; its mu = .1801 at nu = .25, c = .5 is a misprint of .1810).")
    return FigureData("fig3_stick_radius", caption, (("c(mu)", "mu", "c"),), tuple(curves))


def fig4_compliance(nus: Sequence[float] = NU_VALUES, mu_max: float = 3.0) -> FigureData:
    """Compliance factor P* against mu, with the adhesive limit atanh(gamma)/gamma (paper's figure 4).

    P* = (pi/2) int_0^1 x p dx (2.4), P = 4 G a P* delta / (1 - nu); P* = 1 at mu = 0 and
    tends to the fully adhesive (B4) value as mu -> inf.
    """
    curves = []
    for nu in nus:
        sw = _sweep(float(nu))
        curves.append(_curve("P*(mu)", "solver", np.r_[0.0, sw.mu], np.r_[1.0, sw.compliance], nu=nu))
        adhesive = float(compliance_adhesive(sw.gamma))
        curves.append(_curve("P*(mu)", "adhesive (B4)", [0.0, mu_max], [adhesive, adhesive], nu=nu))
    caption = ("Compliance factor P* = (1 - nu) P / (4 G a delta) (2.4) of the flat punch against mu for several "
               "nu (solid): it rises from the frictionless 1 toward the fully adhesive atanh(gamma)/gamma (B4) "
               "(dotted), as Shield and Anderson's bounds require.")
    return FigureData("fig4_compliance", caption, (("P*(mu)", "mu", "P*"),), tuple(curves))


def fig5_flat_punch_stresses(nu: float = 0.0, cs: Sequence[float] = C_VALUES) -> FigureData:
    """Flat punch stresses for several mu: q/(mu p) on the stick zone, p and q (paper's figure 5).

    Panels ``q/(mu p)(x)`` on 0 <= x <= c (0 at the centre, 1 at c), ``p(x)`` and ``q(x)``
    on 0 <= x <= 0.995 (both infinite at x = 1); references: frictionless (2.26) and fully
    adhesive (B3).
    """
    check_nu(nu)
    curves = []
    for c in cs:
        s = _flat(float(nu), float(check_c(c)))
        x_stick = _samples(0.0, s.c, s.breakpoints, n=200)
        p, q = s.pressure(x_stick), s.shear(x_stick)
        curves.append(_curve("q/(mu p)(x)", "solver", x_stick, q / (s.mu * p), nu=nu, mu=s.mu, c=s.c))
        curves.append(_curve("q/(mu p)(x)", "(2.31)", x_stick, shear_ratio_first_order(x_stick, s.c), c=s.c))
    for c in cs:
        s = _flat(float(nu), float(c))
        x = _samples(0.0, X_MAX_FLAT, s.breakpoints, n=300)
        curves.append(_curve("p(x)", "solver", x, s.pressure(x), nu=nu, mu=s.mu, c=s.c))
        curves.append(_curve("q(x)", "solver", x, s.shear(x), nu=nu, mu=s.mu, c=s.c))
    for model, mu in (("frictionless (2.26)", 0.0), ("adhesive (B3)", math.inf)):
        s = _flat_mu(float(nu), mu)
        x = _samples(0.0, X_MAX_FLAT, 1.0 - np.geomspace(0.5, 1.0 - X_MAX_FLAT, 30), n=300)
        curves.append(_curve("p(x)", model, x, s.pressure(x), nu=nu, mu=mu, c=s.c))
        if mu > 0:
            curves.append(_curve("q(x)", model, x, s.shear(x), nu=nu, mu=mu, c=s.c))
    caption = (f"Flat punch, nu = {nu:g}, for several friction coefficients mu (stick radius c): "
               "(a) q/(mu p) in the stick zone 0 <= x <= c (the paper's figure 5), reaching 1 at x = c, with the "
               "first-order (2.31) at the same c (dashed; up to 0.06 off at nu = 0, not \"indistinguishable\"); "
               "(b) pressure p and (c) shear q, p = -sigma_zz (1 - nu) a / (G delta) (2.1), q likewise from "
               "sigma_rz, with the frictionless (2.26) and fully adhesive (B3) limits. Stresses are infinite at "
               "the edge x = 1 (like (1 - x)^(alpha - 1/2), tan(pi alpha) = mu gamma); data stop at x = 0.995.")
    panels = (("q/(mu p)(x)", "x", "q/(mu p)"), ("p(x)", "x", "p"), ("q(x)", "x", "q"))
    return FigureData("fig5_flat_punch_stresses", caption, panels, tuple(curves))


def fig6_sphere_stresses(nu: float = 0.0, cs: Sequence[float] = C_VALUES) -> FigureData:
    """Sphere (n = 2) pressure and shear for several mu, with Hertz (3.19) (paper's figure 6).

    Stresses by the quadrature (3.13) of the flat punch ones; the frictionless curve
    (model ``"Hertz (3.19)"``) is ``power_law(2, mu=0)``, p = (4/pi) sqrt(1 - x^2).
    """
    check_nu(nu)
    curves = []
    flats = [_flat(float(nu), float(check_c(c))) for c in cs] + [_flat_mu(float(nu), math.inf)]
    for s in flats:
        model = "adhesive (B3), (3.13)" if math.isinf(s.mu) else "solver"
        x = _samples(0.0, 1.0, s.breakpoints if not math.isinf(s.mu) else (), n=200 if math.isinf(s.mu) else 300)
        curves.append(_curve("p(x)", model, x, power_law_pressure(s, 2, x), nu=nu, mu=s.mu, c=s.c))
        curves.append(_curve("q(x)", model, x, power_law_shear(s, 2, x), nu=nu, mu=s.mu, c=s.c))
    hertz = power_law(2, nu=nu, mu=0.0)
    x = np.linspace(0.0, 1.0, 201)
    curves.append(_curve("p(x)", "Hertz (3.19)", x, hertz.pressure(x), nu=nu, mu=0.0, c=0.0))
    caption = (f"Sphere (Hertz indentation, n = 2), nu = {nu:g}: (a) pressure p and (b) shear q for several mu "
               "(stick radius c as for the flat punch, §3.2), from the flat-punch stresses by (3.13); "
               "p = -sigma_zz (1 - nu) a / (G delta) with delta = A a^2 / R (3.2). Frictionless: Hertz "
               "(4/pi) sqrt(1 - x^2) (3.19); mu = inf: fully adhesive. Both vanish at the edge (3.7).")
    return FigureData("fig6_sphere_stresses", caption, (("p(x)", "x", "p"), ("q(x)", "x", "q")), tuple(curves))


def stick_radius_asymptotes(nus: Sequence[float] = NU_VALUES) -> FigureData:
    """c against mu/gamma on scales that show both limits (2.29).

    Panel ``c(gamma/mu)`` (log c against gamma/mu) shows c ~ 4 exp(-gamma/mu) as mu -> 0 as a
    straight line; panel ``1-c(mu/gamma)`` (log(1 - c) against mu/gamma) shows
    1 - c ~ 2 exp(-pi mu/gamma) as mu -> inf. In these variables the first-order law (2.28)
    and (2.29) do not depend on gamma; the full solution does.
    """
    curves = []
    for nu in nus:
        sw = _sweep(float(nu))
        small = sw.c <= 0.6
        curves.append(_curve("c(gamma/mu)", "solver", sw.gamma / sw.mu[small], sw.c[small], nu=nu))
        large = sw.c >= 0.4
        curves.append(_curve("1-c(mu/gamma)", "solver", sw.mu[large] / sw.gamma, sw.one_minus_c[large], nu=nu))
    small_c = np.geomspace(1e-4, 0.6, 300)
    curves.append(_curve("c(gamma/mu)", "(2.28)", 1.0 / mu_over_gamma(small_c), small_c))
    g_over_mu = np.linspace(0.0, 8.0, 81)
    curves.append(_curve("c(gamma/mu)", "(2.29)", g_over_mu, 4.0 * np.exp(-g_over_mu)))
    om = np.geomspace(1e-8, 0.6, 300)  # 1 - c, without cancellation
    curves.append(_curve("1-c(mu/gamma)", "(2.28)", mu_over_gamma(1.0 - om), om))
    m_over_g = np.linspace(0.0, 8.0, 81)
    curves.append(_curve("1-c(mu/gamma)", "(2.29)", m_over_g, 2.0 * np.exp(-np.pi * m_over_g)))
    caption = ("Stick radius against mu/gamma on scales that show both limits of (2.29): (a) log c against "
               "gamma/mu, where c ~ 4 exp(-gamma/mu) (mu -> 0) is a straight line; (b) log(1 - c) against "
               "mu/gamma, where 1 - c ~ 2 exp(-pi mu/gamma) (mu -> inf) is one. Full solution for several nu "
               "(solid), first-order law (2.28) (dashed, the gamma -> 0 limit), asymptotes (2.29) (dotted; in (a) "
               "it coincides with (2.28)). At small c the full solution keeps the exponent of (2.29) with a "
               "gamma-dependent factor; toward c = 1 it leaves (2.29) for nu <= 0.375 (gamma >= 0.2), 1 - c "
               "decaying far more slowly. Full curves stop at 1 - c = 1.1e-6 (nu = 0.375, 0.45).")
    panels = (("c(gamma/mu)", "gamma/mu", "c"), ("1-c(mu/gamma)", "mu/gamma", "1 - c"))
    return FigureData("stick_radius_asymptotes", caption, panels, tuple(curves))


def slip_displacement(nu: float = 0.0, cs: Sequence[float] = C_VALUES) -> FigureData:
    """Radial slip u(x) = d u_r / d delta in the annulus c < x <= 1 for several mu ((2.10))."""
    check_nu(nu)
    curves = []
    for c in cs:
        s = _flat(float(nu), float(check_c(c)))
        x = _samples(s.c, 1.0, s.breakpoints, n=200)
        curves.append(_curve("u(x)", "solver", x, s.slip(x), nu=nu, mu=s.mu, c=s.c))
    caption = (f"Flat punch, nu = {nu:g}: radial surface displacement per unit indentation, u = d u_r / d delta "
               "(2.10), in the slip annulus c < x <= 1 for several mu; u = 0 on the stick zone and u < 0 "
               "(inward slip, (2.9)) in the annulus.")
    return FigureData("slip_displacement", caption, (("u(x)", "x", "u"),), tuple(curves))


def sphere_indentation(nus: Sequence[float] = (0.0, 0.25, 0.45), points: int = 12) -> FigureData:
    """Sphere: 1/A against mu (delta = A a^2 / R, (3.2)), with the adhesive limit (4.18).

    A by ``indentation_constant`` ((3.5a) at x = 1) from the flat solution at ``points``
    friction coefficients evenly spaced up to mu(c = 0.95) and at the solver points of the
    c -> 1 sweep; A = 1 without friction; the paper's 1/A of §4.2 as model ``"paper"``.
    """
    curves = []
    mu_end = 3.0
    for nu in nus:
        sweep = _sweep(float(nu))
        mus = np.linspace(0.0, float(friction_coefficient(0.95, nu)), points + 1)[1:]
        cs = np.atleast_1d(stick_radius(mus, nu))  # the Chebyshev table
        flats = [_flat(float(nu), float(c)) for c in (*cs, *sweep.c[sweep.c > 0.95])]
        inv_a = [1.0 / indentation_constant(s, 2) for s in flats]
        curves.append(_curve("1/A(mu)", "solver", [0.0] + [s.mu for s in flats], [1.0] + inv_a, nu=nu))
        adhesive = 1.0 / float(sphere_A_adhesive(gamma_from_nu(nu)))
        curves.append(_curve("1/A(mu)", "adhesive (4.18)", [0.0, mu_end], [adhesive, adhesive], nu=nu))
    for nu in nus:
        table = [(mu, a) for (n, c), (mu, a) in PAPER["mu_inverse_A"].items() if n == nu and mu is not None]
        if table:
            curves.append(_curve("1/A(mu)", "paper", [m for m, _ in table], [a for _, a in table], nu=nu))
    caption = ("Sphere: a^2/(R delta) = 1/A (3.2) against mu for several nu (solid), from 1 (Hertz, frictionless) "
               "toward the fully adhesive value (4.18) (dotted); friction makes the sphere sink less for a given "
               "contact radius. Markers: the paper's 1/A (§4.2 table, from its fit (4.17)), 0.3-0.5 % low.")
    return FigureData("sphere_indentation", caption, (("1/A(mu)", "mu", "1/A"),), tuple(curves))


#: name -> compute function, in the order the figures are written.
COMPUTE: dict[str, Callable[[], FigureData]] = {
    "fig2_chi0": fig2_chi0,
    "fig3_stick_radius": fig3_stick_radius,
    "fig4_compliance": fig4_compliance,
    "fig5_flat_punch_stresses": fig5_flat_punch_stresses,
    "fig6_sphere_stresses": fig6_sphere_stresses,
    "stick_radius_asymptotes": stick_radius_asymptotes,
    "slip_displacement": slip_displacement,
    "sphere_indentation": sphere_indentation,
}
