"""The rigid strip punch in plane strain with friction: the solution type, its routes and the public functions.

``strip_punch`` (exactly one of mu and c), ``plane_stick_width`` and ``plane_friction_coefficient``
(vectorised), ``plane_slip_limit`` and ``plane_largest_stick_width`` (mu -> inf): the singular-basis solver
(``numeric.solutions.plane_solver``) or the closed forms of ``asymptotics.plane`` in the limits mu = 0
(Sadowsky) and mu = inf with full stick, c = 1 (Abramov; as ``numeric.flat_punch(mu=inf)`` gives App. B's
adhesive punch). The limit mu -> inf of the frictional punch is not the bonded one: its stick width
saturates at c_max < 1 (``plane_largest_stick_width``).

Dimensionless fields (``asymptotics.plane``): x = X/a, p = sigma_zz a/P, q = sigma_xz a/P (the traction on
the half-plane, + outward for x > 0), int_{-1}^{1} p = 1; the slip u(x) = u_x G / ((1 - nu) P), negative
(inward) for c < x < 1 and 0 on the stick zone. (Plane stress: nu -> nu/(1 + nu), ``gamma_plane_stress``.)

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import scalar_or_array
from asymptotics.materials import check_c, check_gamma, check_mu, check_nu, real_number, resolve_gamma
from asymptotics.plane import (bonded_traction, friction_slope_first_order, pressure_sadowsky, slip_width_first_order,
                               stick_width_first_order)

from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.plane_fields import PlaneField
from numeric.core.plane_guess import elliptic_ratio, gap_max, gap_max_relative_error
from numeric.solutions.plane_law import FullSlipField, law_friction_coefficient, law_stick_width
from numeric.solutions.plane_near_limit import near_limit_field
from numeric.solutions.plane_small_gamma import SERIES_GAP_MIN, SMALL_GAMMA
from numeric.solutions.flat_punch import check_level, check_rtol
from numeric.solutions.plane_solver import (C_SMALLEST, DEFAULT_LEVEL, FIRST_ORDER_GAMMA, FIRST_ORDER_R_MAX,
                                            FULL_STICK_GAP, LIMIT_MU_GAMMA, PLANE_LEVELS, ROUNDING_FLOOR,
                                            beyond_table_toward_full_stick, full_stick_friction, limit_resolved,
                                            solve_given_c, solve_given_mu, solve_limit)
from numeric.solutions.solution import Deferred, DeferredError, meets, warn_unmet

__all__ = ["StripPunchSolution", "strip_punch", "plane_stick_width", "plane_friction_coefficient", "plane_slip_limit",
           "plane_largest_stick_width", "points", "ABOVE_C_MAX", "GAMMA_FLOOR", "ROUNDING_ULPS", "RTOL_START"]

EPS = float(np.finfo(float).eps)


def points(x: ArrayLike) -> np.ndarray:
    """x over the half-width: -1 <= x <= 1 (TypeError for non-numbers and booleans, as the axisymmetric solution's
    stresses, ValueError naming x otherwise)."""
    raw = np.asarray(x) if x is not None else None
    if raw is None or raw.dtype.kind not in "iuf":
        raise TypeError(f"x must be a real number or an array of real numbers, got {x!r}")
    arr = raw.astype(float)
    if not np.all(np.isfinite(arr)) or np.any(np.abs(arr) > 1.0):
        raise ValueError(f"x (distance from the centre over the half-width a) must lie in [-1, 1], got {x!r}")
    return arr


class _Sadowsky:
    """mu = 0: p = 1/(pi sqrt(1 - x^2)), q = 0, u = -(gamma/pi) asin(x) (du/dx = -gamma p, u(0) = 0)."""

    def __init__(self, gamma: float) -> None:
        self.gamma = gamma

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return np.asarray(pressure_sadowsky(x), dtype=float), np.zeros(x.shape)

    def slip(self, x: np.ndarray) -> np.ndarray:
        return -(self.gamma / math.pi) * np.arcsin(x)

    def edge_pressure_shear(self, u: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p, q at t = 1 - u^2, formed from u (1 - t would round next to the edge)."""
        return 1.0 / (math.pi * u * np.sqrt(2.0 - u * u)), np.zeros(u.shape)


class _Abramov:
    """Full stick (c = 1): p + i q = (cosh(pi eps)/pi) (1 - x)^(-1/2 - i eps) (1 + x)^(-1/2 + i eps), u = 0."""

    def __init__(self, gamma: float) -> None:
        self.gamma = gamma

    def pressure_shear(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        w = np.asarray(bonded_traction(x, self.gamma))
        return w.real, w.imag

    def slip(self, x: np.ndarray) -> np.ndarray:
        return np.zeros(x.shape)

    def edge_pressure_shear(self, u: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """p, q at t = 1 - u^2, formed from u: 1 - t = u^2, 1 + t = 2 - u^2."""
        eps = math.atanh(self.gamma) / math.pi
        w = (math.cosh(math.pi * eps) / math.pi) / (u * np.sqrt(2.0 - u * u)) * np.exp(
            1j * eps * (np.log(2.0 - u * u) - 2.0 * np.log(u)))
        return w.real, w.imag


@dataclass(frozen=True, slots=True)
class StripPunchSolution:
    """A rigid flat strip punch of half-width a pressed into an elastic half-plane with Coulomb friction.

    Attributes
    ----------
    nu : float or None
        Poisson's ratio (None when gamma was given).
    gamma : float
        Coupling constant (1 - 2 nu)/(2 - 2 nu).
    mu : float
        Friction coefficient (inf: full stick, or the limit mu -> inf).
    c, gap : float
        Stick half-width over a, and 1 - c (without the cancellation of forming it from c).
    error : float
        Estimated absolute error of mu (given c) or c (given mu; of 1 - c_max in the limit mu -> inf):
        the difference from the resolution one degree lower, at least the rounding floor; 0 for closed forms. On
        the solver route it is formed when first read (a solve at the lower resolution, ``DeferredError``).
    route : str
        "frictionless (Sadowsky)", "full stick (Abramov)", "solver level L, n unknowns" (or "solver level L (alternate
        layout), ...": the level's layout was near a pole of the eigen functional, ``numeric.solutions.plane_solver.
        CONDITION_LIMIT``), "limit mu -> inf ...",
        "law below the solver's smallest c ..." (c < 1e-5), "near the limit mu -> inf ..." (mu gamma > 1e6),
        "full stick to within ..." (1 - c < 2^-40 at small gamma), "near full stick at small gamma ..." (gamma < 0.02,
        1 - c < 1e-8: the solver with its stresses, or below gamma = 3e-5 and where rtol is met by its bound the
        first-order law, the stresses then a solve at c when first read), "gamma = ... below 1e-150 ..." (the law and
        the uncoupled punch's stresses, ``GAMMA_FLOOR``) or
        "c = ... is c_max to rounding: ..." (given c within 4 ulp of c_max: the slip limit).
    residual : float
        The eigen residual (the generic mode's amplitude; 0 for closed forms).

    Methods pressure(x), shear(x), slip(x) give p, q and u at -1 <= x <= 1 (vectorised): p even, q odd,
    q = mu p on the slip zones; at x = +-1 the flat-punch stresses are infinite ((1 - x)^(alpha - 1/2)).
    """

    nu: float | None
    gamma: float
    mu: float
    c: float
    gap: float
    _error: float | DeferredError
    route: str
    residual: float = 0.0
    _field: object = field(default=None, repr=False, compare=False)

    @property
    def error(self) -> float:
        """Estimated absolute error of mu (given c) or c (given mu): see the class docstring."""
        return self._error.value() if isinstance(self._error, DeferredError) else self._error

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """p(x) = sigma_zz a / P (even)."""
        return scalar_or_array(self.field.pressure_shear(points(x))[0])

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """q(x) = sigma_xz a / P on the half-plane, + outward (odd)."""
        return scalar_or_array(self.field.pressure_shear(points(x))[1])

    def slip(self, x: ArrayLike) -> np.ndarray | float:
        """u(x) = u_x G / ((1 - nu) P): 0 on |x| <= c, inward (sign opposite to x) on the slip zones."""
        return scalar_or_array(self.field.slip(points(x)))

    @property
    def field(self) -> object:
        """The stress field (``PlaneField`` for the solver, a closed form otherwise)."""
        return self._field.value() if isinstance(self._field, Deferred) else self._field


#: The typical relative accuracy of mu at levels 0-4 (``numeric.solutions.plane_solver.PLANE_LEVELS``, measured up to
#: 7e-7, 1e-9, 1e-11, 6e-12, 5e-10 at five (nu, c); the estimate is floored at ``ROUNDING_FLOOR``, 1e-10): rtol
#: starts at the first level listed at or below it.
RTOL_START = (1e-6, 1e-8, ROUNDING_FLOOR)


def _meeting(rtol: float, run: Callable[[int], StripPunchSolution], value: Callable[[StripPunchSolution], float]
             ) -> StripPunchSolution:
    """The first level from ``RTOL_START`` on whose ``error`` is within rtol of ``value``; else the most accurate, with
    an ``AccuracyWarning``. Below the estimate's floor only the default level runs (no level can show more); a
    route that is not the solver's (closed forms, the small-c law, full stick, near the limit) runs once."""
    start = next((lv for lv, typical in enumerate(RTOL_START) if typical <= rtol), DEFAULT_LEVEL)
    levels = range(start, len(PLANE_LEVELS)) if rtol >= ROUNDING_FLOOR else (DEFAULT_LEVEL,)
    best = None
    for lv in levels:
        s = run(lv)
        if meets(s, rtol, value(s)):
            return s
        if best is None or s.error < best.error:
            best = s
        if not s.route.startswith("solver"):
            break
    warn_unmet(best, rtol, value(best))
    return best


def _from_field(nu: float | None, fine: PlaneField, error: float | DeferredError, level: int, mu: float | None = None
                ) -> StripPunchSolution:
    alternate = fine.layout.resolution.c_fraction != PLANE_LEVELS[level].c_fraction
    route = f"solver level {level}{' (alternate layout)' if alternate else ''}, {fine.n_unknowns} unknowns"
    return StripPunchSolution(nu, fine.gamma, fine.mu if mu is None else mu, fine.c, fine.gap, error, route,
                              fine.residual, fine)


def _near_one(nu: float | None, gamma: float, mu: float, c: float, gap: float, error: float | DeferredError,
              solved: PlaneField | None, level: int) -> StripPunchSolution:
    """Small gamma (< ``SMALL_GAMMA``) and 1 - c < ``SERIES_GAP_MIN``: ``solved`` the solver's field at gamma
    itself (mu and c with its error), else the first-order law (below ``FIRST_ORDER_GAMMA``, where rtol is met by its
    bound, or given mu where the solver's secant in c did not converge); the stresses of the solve where there is one,
    else of a given-c solve at c formed when first read (``Deferred``): the solver's stresses hold where its mu does not
    (``numeric.solutions.plane_small_gamma``)."""
    how = (f"solver level {level} at gamma itself" if solved is not None else
           f"the first-order law mu/gamma = K(c)/K'(c) (error {FIRST_ORDER_R_MAX:g} gamma^2 relative in mu)")
    route = f"near full stick at small gamma (1 - c < {SERIES_GAP_MIN:g}, gamma < {SMALL_GAMMA:g}): mu and c from {how}"
    if solved is not None:
        return StripPunchSolution(nu, gamma, mu, c, gap, error, route + "; its stresses", solved.residual, solved)
    return StripPunchSolution(nu, gamma, mu, c, gap, error,
                              route + f"; the stresses of solver level {level} at c, formed when first read", 0.0,
                              Deferred(lambda: solve_given_c(c, gap, gamma, level).field))


def _floor_bound(gamma: float) -> float:
    """The first-order law's relative error bound in mu below ``GAMMA_FLOOR``: its bound or the rounding of K/K'
    (8 ulp), whichever is larger."""
    return max(_law_mu_bound(gamma), 8.0 * EPS)


def _below_floor(nu: float | None, gamma: float, mu: float, c: float, gap: float, error: float) -> StripPunchSolution:
    """gamma below ``GAMMA_FLOOR``: mu and c of the first-order law with their ``error`` (from ``_floor_bound``); the
    stresses of the bonded punch next to full stick (1 - c below ``SERIES_GAP_MIN``), else of the frictionless one."""
    bonded = gap < SERIES_GAP_MIN
    route = (f"gamma = {gamma:.3g} below {GAMMA_FLOOR:g}, where the solver's blocks overflow: mu and c from the "
             f"first-order law mu/gamma = K(c)/K'(c) (error {_floor_bound(gamma):.2g} relative in mu); the stresses "
             f"of the {'bonded punch (Abramov)' if bonded else 'frictionless punch (Sadowsky)'}, within O(gamma) of "
             "max(1, |p|)")
    return StripPunchSolution(nu, gamma, mu, c, gap, error, route, 0.0, _Abramov(gamma) if bonded else _Sadowsky(gamma))


def _law_answers(gamma: float, rtol: float | None, bound: Callable[[], float]) -> bool:
    """Whether the first-order law answers next to full stick at small gamma: below ``FIRST_ORDER_GAMMA``, or where
    ``bound()``, its relative error bound on the value rtol is on (mu given c, c given mu), meets rtol."""
    return gamma < FIRST_ORDER_GAMMA or (rtol is not None and bound() <= rtol)


def _law_mu_bound(gamma: float) -> float:
    """The first-order law's relative error bound in mu, ``FIRST_ORDER_R_MAX`` gamma^2."""
    return FIRST_ORDER_R_MAX * gamma * gamma


def _law_stick_width(mu: float, gamma: float, bound: float | None = None) -> tuple[float, float, float]:
    """c, 1 - c and the bound on the error of c of the first-order law for mu: mu's relative ``bound`` (default
    ``_law_mu_bound``) turned into a shift of logit c by the law's slope d mu / d logit c, and that into c as
    c (1 - c) expm1(shift) (next to full stick the shift is not small: 0.48 at nu = 0.49, mu = 0.16, where the true
    1 - c is the law's times up to exp(shift)); inf where the slope is 0 (c = 0). mu and the slope are both ~gamma:
    their ratio is formed from mu/gamma (gamma may be subnormal, the slope 0)."""
    c, gap = float(stick_width_first_order(mu, gamma)), float(slip_width_first_order(mu, gamma))
    slope = friction_slope_first_order(c, gap, 1.0)  # d (mu/gamma) / d logit c
    bound = _law_mu_bound(gamma) if bound is None else bound
    return c, gap, (c * gap * math.expm1(bound * (mu / gamma) / slope) if slope > 0.0 else math.inf)


def _law_c_bound(mu: float, gamma: float) -> float:
    """The first-order law's relative error bound in c for mu (``_law_stick_width``)."""
    c, _, error = _law_stick_width(mu, gamma)
    return error / c if c > 0.0 else math.inf


def _near_one_given_c(nu: float | None, gamma: float, c: float, level: int, law: bool) -> StripPunchSolution:
    """Given c at gamma < SMALL_GAMMA and 1 - c < SERIES_GAP_MIN (``_near_one``); ``law``: ``_law_answers``."""
    gap = 1.0 - c
    if law:
        mu = gamma / elliptic_ratio(c, gap)
        return _near_one(nu, gamma, mu, c, gap, _law_mu_bound(gamma) * mu, None, level)
    solve = solve_given_c(c, gap, gamma, level)
    return _near_one(nu, gamma, solve.field.mu, c, gap, solve.error, solve.field, level)


def _near_one_given_mu(nu: float | None, gamma: float, mu: float, level: int, law: bool) -> StripPunchSolution:
    """Given mu at gamma < SMALL_GAMMA where the first-order law puts 1 - c below SERIES_GAP_MIN (``_near_one``)."""
    if not law:
        try:
            solve = solve_given_mu(mu, gamma, level)
            return _near_one(nu, gamma, mu, solve.field.c, solve.field.gap, solve.error, solve.field, level)
        except SolverError:  # the secant in c near c = 1 at small gamma (gamma = 2e-4, 1 - c = 5e-10): the law below
            pass
    c, gap, error = _law_stick_width(mu, gamma)
    return _near_one(nu, gamma, mu, c, gap, error, None, level)


#: Given c within this many units in the last place of c_max (``gap_max``), c is c_max to rounding: the answer is the
#: slip limit, mu = inf (the axisymmetric ``numeric.solutions.solver.ROUNDING_ULPS``).
ROUNDING_ULPS = 4.0

#: Given c, 1 - c below 1 - c_max of the guess table by more than this (relative) is refused at once (the table's
#: 1 - c_max is good to ~1e-8 relative; nearer, the solver decides): Newton in theta failed to converge there before.
ABOVE_C_MAX = 1e-6

#: Below this gamma the solver leaves the doubles: theta = atan(mu gamma) ~ gamma^2 K(c)/K'(c) underflows (measured at
#: c = 0.05, 0.5, 0.9: its mu within 2.4e-13 of the first-order law at gamma = 1e-20 ... 1e-155, 0 at 1e-160, and given
#: mu = 0.7817 gamma its c 0.4999 for 0.5; its blocks overflow below ~5e-309, q = R sin(theta)/gamma), while nothing it
#: adds is above rounding: the first-order law's error in mu, 60 gamma^2 relative, is below 1e-298, and the stresses
#: differ from those of the punch without coupling (Sadowsky's; the bonded one's next to full stick) by O(gamma) of
#: max(1, |p|) (q and u ~ gamma, p by O(gamma^2)).
GAMMA_FLOOR = 1e-150

#: Given mu, the law is asked whether c < C_SMALLEST where the first-order c is below this: the true c is below the
#: first-order one (mu/mu_1 - 1 > 0), by a factor exp(-L gamma^2 r) >= exp(-0.5 L), so from here on it is above 1e-5.
FIRST_ORDER_CHECK = 1e-2


def _below_solver(mu: float, gamma: float, level: int) -> bool:
    """Whether the stick width for mu lies below the solver's smallest (``C_SMALLEST``)."""
    first_order = float(stick_width_first_order(mu, gamma))
    if first_order >= FIRST_ORDER_CHECK:
        return False
    return first_order < C_SMALLEST or mu < law_friction_coefficient(C_SMALLEST, gamma, level)[0]


def _full_stick(mu: float, gamma: float, level: int, law: bool) -> bool:
    """Whether 1 - c < FULL_STICK_GAP for mu: only where c_max lies above 1 - FULL_STICK_GAP (``limit_resolved``
    false), for mu gamma beyond LIMIT_MU_GAMMA[1] (1 - c within 1.4e-6 (1 - c_max) of 1 - c_max) or mu beyond the
    guess table toward full stick and at least the friction at 1 - c = FULL_STICK_GAP (the first-order law's where
    ``law``, ``_law_answers``)."""
    if limit_resolved(gamma):
        return False
    return mu * gamma > LIMIT_MU_GAMMA[1] or (beyond_table_toward_full_stick(mu, gamma)
                                              and mu >= full_stick_friction(gamma, level, law))


def _from_law(nu: float | None, gamma: float, mu: float, c: float, error: float) -> StripPunchSolution:
    route = (f"law below the solver's smallest c ({C_SMALLEST:g}): mu = mu_1 (1 + gamma^2 (a + b/log(4/c)^2)) fitted "
             f"to the solver; stresses of full slip at |x| >= 100 c; slip not computed"
             + ("; c underflows to 0.0" if c == 0.0 else ""))
    return StripPunchSolution(nu, gamma, mu, c, 1.0 - c, error, route, 0.0, FullSlipField(gamma, mu, c))


def strip_punch(*, nu: float | None = None, gamma: float | None = None, mu: float | None = None,
                c: float | None = None, level: int | None = None, rtol: float | None = None) -> StripPunchSolution:
    """The flat strip punch with friction: give exactly one of ``mu`` and ``c``, and ``nu`` or ``gamma``.

    mu = 0 is Sadowsky's frictionless punch, mu = inf or c = 1 Abramov's fully stuck one (closed forms);
    otherwise the singular-basis solver at ``level`` (0-4, default 2, validated as ``numeric.flat_punch`` does), with
    the level one degree lower as error estimate. c above the largest stick width c_max(gamma) raises
    ``NoEigenvalueError``; c within 4 ulp of it is the slip limit (mu = inf, ``plane_slip_limit``).

    ``rtol`` (instead of ``level``): the coarsest level whose typical accuracy meets it (``RTOL_START``), then finer
    ones while ``error`` exceeds rtol times mu (given c) or c (given mu); if none does (the estimate's floor is 1e-10
    relative), the most accurate result with an ``AccuracyWarning``. Reading ``error`` costs a second solve. Next to
    full stick at small gamma (1 - c < 1e-8, gamma < 0.02), where a solve costs 0.3 ... 3 s, the first-order law
    answers at once wherever its bound meets rtol: 60 gamma^2 relative in mu given c, that bound turned into c by the
    law's slope given mu (below 1e-10 relative over most of the band: c is within 1e-8 of 1); the stresses then come
    from a solve at c, formed when first read. Without rtol the solver answers, from gamma = 3e-5 up
    (``FIRST_ORDER_GAMMA``; below, the law).

    Examples
    --------
    >>> s = strip_punch(nu=0.3, c=0.5)
    >>> round(s.mu, 10), s.error < 1e-10
    (0.2374025972, True)
    """
    if rtol is not None:
        if level is not None:
            raise ValueError("give level or rtol, not both (rtol chooses the level)")
        rtol = check_rtol(rtol)
        value = (lambda s: s.mu) if c is not None else (lambda s: s.c)
        return _meeting(rtol, lambda lv: _strip_punch(nu, gamma, mu, c, lv, rtol), value)
    return _strip_punch(nu, gamma, mu, c, DEFAULT_LEVEL if level is None else check_level(level), None)


def _strip_punch(nu: float | None, gamma: float | None, mu: float | None, c: float | None, level: int,
                 rtol: float | None) -> StripPunchSolution:
    """``strip_punch`` at ``level``; ``rtol`` (the caller's, or None) only decides whether the first-order law answers
    next to full stick at small gamma (``_law_answers``)."""
    nu = None if nu is None else real_number(check_nu(nu), "nu")
    g = resolve_gamma(nu, gamma)
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick half-width / a)")
    if c is not None:
        c = real_number(check_c(c), "c")
        if c == 1.0:
            return StripPunchSolution(nu, g, math.inf, 1.0, 0.0, 0.0, "full stick (Abramov)", 0.0, _Abramov(g))
        if g == 0.0:
            raise NoEigenvalueError("gamma = 0: shear and pressure decouple and every mu > 0 gives c = 1")
        if c < C_SMALLEST:
            mu, error = law_friction_coefficient(c, g, level)
            return _from_law(nu, g, mu, c, error)
        largest = gap_max(g)  # 1 - c_max: the guess table's series, or below its band the small-gamma form
        if abs((1.0 - c) - largest) <= ROUNDING_ULPS * math.ulp(c):
            # c is c_max to rounding: the slip limit, mu = inf (as the axisymmetric numeric.flat_punch answers)
            limit = plane_slip_limit(nu, gamma=gamma, level=level)
            return replace(limit, route=f"c = {c!r} is c_max to rounding (|(1 - c) - (1 - c_max)| = "
                                        f"{abs((1.0 - c) - largest):.2g} <= {ROUNDING_ULPS:g} ulp of c): {limit.route}")
        if 1.0 - c < (1.0 - ABOVE_C_MAX) * largest:
            raise NoEigenvalueError(f"no friction coefficient gives stick half-width c = {c!r} at gamma = {g:.6g}: it "
                                    f"lies above the largest, c_max = {1.0 - largest:.10g} (mu -> inf)")
        if g < GAMMA_FLOOR:
            mu = g / elliptic_ratio(c, 1.0 - c)
            return _below_floor(nu, g, mu, c, 1.0 - c, _floor_bound(g) * mu)
        if g < SMALL_GAMMA and 1.0 - c < SERIES_GAP_MIN:
            return _near_one_given_c(nu, g, c, level, _law_answers(g, rtol, lambda: _law_mu_bound(g)))
        solve = solve_given_c(c, 1.0 - c, g, level)
        return _from_field(nu, solve.field, solve.error, level)
    mu = real_number(check_mu(mu), "mu")
    if mu == 0.0:
        return StripPunchSolution(nu, g, 0.0, 0.0, 1.0, 0.0, "frictionless (Sadowsky)", 0.0, _Sadowsky(g))
    if mu == math.inf or g == 0.0:
        return StripPunchSolution(nu, g, mu, 1.0, 0.0, 0.0, "full stick (Abramov)", 0.0, _Abramov(g))
    if _below_solver(mu, g, level):
        c, error = law_stick_width(mu, g, level)
        return _from_law(nu, g, mu, c, error)
    law = g < SMALL_GAMMA and _law_answers(g, rtol, lambda: _law_c_bound(mu, g))
    if _full_stick(mu, g, level, law):
        threshold = full_stick_friction(g, level, law)
        how = "the first-order law's, raised by its bound" if law else f"solver level {level}"
        route = (f"full stick to within {FULL_STICK_GAP:.2g}: mu >= {threshold:.10g}, the friction "
                 f"at 1 - c = {FULL_STICK_GAP:.2g} ({how}); c = 1 - {FULL_STICK_GAP / 2:.2g} +- "
                 f"{FULL_STICK_GAP / 2:.2g}, stresses of the bonded punch (Abramov), no slip")
        return StripPunchSolution(nu, g, mu, 1.0 - 0.5 * FULL_STICK_GAP, 0.5 * FULL_STICK_GAP, 0.5 * FULL_STICK_GAP,
                                  route, 0.0, _Abramov(g))
    if mu * g > LIMIT_MU_GAMMA[1]:
        limit = solve_limit(g, level)
        f = near_limit_field(mu, g, limit.near)
        route = (f"near the limit mu -> inf (mu gamma > {LIMIT_MU_GAMMA[1]:g}): c, q, u linear in 1/(mu gamma) through "
                 f"the solves at mu gamma = {LIMIT_MU_GAMMA[0]:g}, {LIMIT_MU_GAMMA[1]:g} (solver level {level}), "
                 f"p = q/mu on the slip zones; not resolved within {f.unresolved[1] - f.c:.2g} of x = c")
        return StripPunchSolution(nu, g, mu, f.c, f.gap, limit.error, route, 0.0, f)
    if g < GAMMA_FLOOR:
        return _below_floor(nu, g, mu, *_law_stick_width(mu, g, _floor_bound(g)))
    if g < SMALL_GAMMA and float(slip_width_first_order(mu, g)) < SERIES_GAP_MIN:
        return _near_one_given_mu(nu, g, mu, level, law)
    solve = solve_given_mu(mu, g, level)
    return _from_field(nu, solve.field, solve.error, level, mu)


def plane_slip_limit(nu: float | None = None, *, gamma: float | None = None, level: int = DEFAULT_LEVEL
                     ) -> StripPunchSolution:
    """The frictional strip punch in the limit mu -> inf: c = c_max < 1, no pressure on the slip zones (q = R/gamma
    there); not the fully stuck punch (``strip_punch(mu=inf)``). ``error`` is that of 1 - c_max.

    Where 1 - c_max < 2^-40 = 9.1e-13 (gamma below ~0.157, nu above ~0.407; ``numeric.solutions.plane_solver.
    limit_resolved``) the slip zones are below what the solver resolves: c = 1 - (1 - c_max) (1.0 to double precision
    below 1.1e-16), ``gap`` = 1 - c_max from the limit problem's small-gamma form (``numeric.core.plane_guess.gap_max``)
    and ``error`` its error bound, with the stresses of the bonded punch (Abramov; as ``strip_punch`` gives them where
    1 - c < 2^-40). At gamma = 0 (nu = 1/2) c = 1: no coupling."""
    nu = None if nu is None else real_number(check_nu(nu), "nu")
    g = resolve_gamma(nu, gamma)
    level = check_level(level)
    if not limit_resolved(g):
        gap = gap_max(g)
        error = gap * gap_max_relative_error(g) if gap > 0.0 else 0.0  # 0: 1 - c_max underflows (gamma < 0.007)
        route = (f"limit mu -> inf: 1 - c_max = {gap:.3g} +- {error:.2g} (the limit problem's small-gamma form) is below "
                 f"{FULL_STICK_GAP:.2g}, which the solver does not resolve; stresses of the bonded punch (Abramov), no "
                 "slip" if g > 0.0 else "limit mu -> inf at gamma = 0: no coupling, c = 1")
        return StripPunchSolution(nu, g, math.inf, 1.0 - gap, gap, error, route, 0.0, _Abramov(g))
    solve = solve_limit(g, level)
    f = solve.field
    return StripPunchSolution(nu, g, math.inf, 1.0 - solve.gap_limit, solve.gap_limit,
                              solve.error, f"limit mu -> inf (slip zones without pressure; c extrapolated from mu gamma "
                              f"= 1e5, 1e6, the stresses at 1e6), solver level {level}, {f.n_unknowns} unknowns",
                              f.residual, f)


def plane_largest_stick_width(nu: float | None = None, *, gamma: float | None = None,
                              level: int = DEFAULT_LEVEL) -> float:
    """c_max(nu): the stick half-width as mu -> inf, from the limit problem (no closed form is known)."""
    return plane_slip_limit(nu, gamma=gamma, level=level).c


def _elementwise(values: np.ndarray, nu: ArrayLike, gamma: ArrayLike, solve) -> np.ndarray | float:
    """solve(value, nu, gamma) at each pair of ``values`` and nu (or gamma), broadcast, as an array of their shape;
    exactly one of nu and gamma (ValueError, as ``strip_punch``), each checked (``check_nu``, ``check_gamma``)."""
    if (nu is None) == (gamma is None):
        raise ValueError("give exactly one of nu (Poisson's ratio) or gamma (coupling constant)")
    other = check_nu(nu) if gamma is None else check_gamma(gamma)
    v, o = np.broadcast_arrays(values, other)
    out = np.array([solve(float(a), None if gamma is not None else float(b), None if gamma is None else float(b))
                    for a, b in zip(v.ravel(), o.ravel())])
    return scalar_or_array(out.reshape(v.shape))


def plane_stick_width(mu: ArrayLike, nu: ArrayLike = None, *, gamma: ArrayLike = None, level: int | None = None,
                      rtol: float | None = None) -> np.ndarray | float:
    """c(mu, nu) of the strip punch (and of every power law |x|^n), elementwise over broadcast arrays; ``level`` or
    ``rtol`` as ``strip_punch`` takes them."""
    return _elementwise(np.asarray(check_mu(mu), dtype=float), nu, gamma,
                        lambda m, n, g: strip_punch(nu=n, gamma=g, mu=m, level=level, rtol=rtol).c)


def plane_friction_coefficient(c: ArrayLike, nu: ArrayLike = None, *, gamma: ArrayLike = None,
                               level: int | None = None, rtol: float | None = None) -> np.ndarray | float:
    """mu(c, nu) of the strip punch, elementwise over broadcast arrays (NoEigenvalueError above c_max); ``level`` or
    ``rtol`` as ``strip_punch`` takes them."""
    return _elementwise(np.asarray(check_c(c), dtype=float), nu, gamma,
                        lambda cc, n, g: strip_punch(nu=n, gamma=g, c=cc, level=level, rtol=rtol).mu)
