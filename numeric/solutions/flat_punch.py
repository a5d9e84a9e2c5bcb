"""The frictional flat punch: stick radius, friction, compliance and stresses ([S75] §2).

Method, and why: the stresses have power-type singularities at x = c and x = 1 whose exponents
are known from tan(pi alpha) = mu gamma (``numeric.core.charts``). The basis carries them:
elements touching c and 1 hold the singular families in a square-root chart, the rest are
polynomials in u = x^2 graded only to separate the scales; (2.2) is collocated with the Abel
integrals done by rules that integrate the singular families exactly to rounding
(``numeric.core.abel_rules``), and the eigenvalue condition phi(c-) = 0 is solved in
theta = atan(mu gamma), which runs over [0, pi/2] as mu runs over [0, inf] (``numeric.core.
eigenvalue``). About 150-300 unknowns give mu, P* and the stresses to ~1e-12.

Routes (``route`` of the result names the one taken), each in its module: closed forms in the
limits (``numeric.solutions.limits``); the asymptotic law mu/gamma = f0(c) (2.28) or
f0 + gamma^2 f2 with error bounds measured against the solver (``numeric.solutions.law``); the
solver at its resolution levels (``numeric.solutions.solver``), up to the largest stick radius
c_max(gamma) (``asymptotics.largest_stick_radius``), which mu -> inf approaches. The route
choice here asks each route once what it offers for ``rtol`` (whether its bound meets it, and
at what cost) and takes the cheapest offer whose result meets it, warning
(``AccuracyWarning``) where none does; without ``rtol`` the solver runs at ``level``. Below
c = 1e-5, where the solver does not converge, the second-order law is the answer.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import check_c, check_gamma, check_mu, check_nu, real_number, resolve_gamma

from numeric.core.charts import RESOLUTIONS
from numeric.core.errors import SolverError
from numeric.core.table import table_given_mu, table_least_mu
from numeric.solutions.law import LawRoute
from numeric.solutions.limits import closed_form, closed_form_given_c, closed_form_given_mu
from numeric.solutions.solver import C_ASYMPTOTIC, DEFAULT_LEVEL, LAW_MU_GAMMA_MAX, NEAR_C_MAX, SolverRoute
from numeric.solutions.solution import FlatPunchSolution, Offer, first_meeting
from numeric.solutions.table_route import TABLE_RTOL, TableRoute

__all__ = ["flat_punch", "check_level", "check_rtol", "level_and_rtol", "GAMMA_LAW_EXACT"]

GAMMA_LAW_EXACT = 1e-100
"""Below this gamma the law answers, whatever ``level`` or ``rtol``: its error (K4 gamma^4 relative, second
order) is far below rounding there, while the solver's kernels lose gamma^2 to underflow (measured: right to
6e-13 in c at gamma = 1e-150, c = 6.5e-49 for 0.485 and OverflowError at 1e-200)."""


def check_rtol(rtol) -> float:
    """``rtol`` as a float, raising ValueError naming it unless positive and finite (TypeError unless a number)."""
    value = real_number(rtol, "rtol")
    if not (math.isfinite(value) and value > 0.0):
        raise ValueError(f"rtol must be a positive finite number, got {rtol!r}")
    return value


def check_level(level) -> int:
    """``level`` as an int, raising ValueError naming it unless one of the resolution levels (TypeError unless a number)."""
    value = real_number(level, "level")
    if not (0.0 <= value < len(RESOLUTIONS) and value == math.floor(value)):
        raise ValueError(f"level must be an integer in [0, {len(RESOLUTIONS) - 1}], got {level!r}")
    return int(value)


def level_and_rtol(level, rtol) -> tuple[int, float | None]:
    """The checked level (default ``DEFAULT_LEVEL``) and rtol; not both may be given."""
    if level is not None and rtol is not None:
        raise ValueError("give level or rtol, not both (rtol chooses the route and the level)")
    return (DEFAULT_LEVEL if level is None else check_level(level)), (None if rtol is None else check_rtol(rtol))


def flat_punch(
    nu: float | None = None,
    mu: float | None = None,
    c: float | None = None,
    *,
    gamma: float | None = None,
    level: int | None = None,
    rtol: float | None = None,
) -> FlatPunchSolution:
    """Solve the flat-punch problem (2.7)-(2.9) for given friction or given stick radius.

    Parameters
    ----------
    nu : float
        Poisson's ratio, -1 < nu <= 1/2 (or give ``gamma`` for dissimilar bodies).
    mu : float, optional
        Friction coefficient, 0 <= mu <= inf. Exactly one of ``mu`` and ``c``.
    c : float, optional
        Stick radius over contact radius, 0 < c <= 1; the friction coefficient that
        produces it is returned.
    gamma : float, optional
        Coupling constant (2.2) instead of ``nu``.
    level : int, optional
        Resolution level 0..4 of ``numeric.core.charts.RESOLUTIONS`` (the same resolution one degree
        lower gives the error estimate); 2 (the default) reaches ~1e-11. Not together with ``rtol``.
    rtol : float, optional
        Relative accuracy wanted in the returned c (given mu) or mu (given c): the cheapest
        route whose error meets ``error <= rtol * value`` is taken. A closed form in the
        limits; else the asymptotic law for c <= 0.9 (first order (2.28) where its measured
        bound K2(gamma) gamma^2 meets rtol, else second order (2.28) + gamma^2 f2 where
        K4(gamma) gamma^4 does; ``numeric.solutions.law.K2_BOUNDS``, ``K4_BOUNDS``); for rtol >= 1e-4 the
        whole-plane tables with level-0 stresses formed on first use (tabulated for 0.05 <= c <= 0.9)
        (``numeric.solutions.table_route``: mu, c, P* to the tables' recorded errors, p and q to
        ``FIELD_ERROR`` = 5e-5 of max(1, |p|)); else the solver at the first
        level whose typical accuracy meets rtol (0: 1e-8, 1: 1e-9, 2: 1e-11, 3: 1e-12, else 4), and
        finer levels while its ``error`` exceeds ``rtol * value``. If no route meets rtol,
        the most accurate result is returned with an ``AccuracyWarning``.

    Returns
    -------
    FlatPunchSolution
        ``route`` names the route. On the asymptotic route ``error`` is the measured bound of
        the law (mu, P*; for given mu the c range it implies), the stresses are the
        first-order fields p^(0) (2.26) and q = mu p^(0) (1 - psi) (2.31) with relative error
        O(gamma^2), and ``slip`` raises NotImplementedError.

    Raises
    ------
    NoEigenvalueError
        If c is above the largest stick radius c_max(gamma) (``numeric.largest_stick_radius``) by more than
        rounding, or if gamma = 0 (nu = 1/2) and c < 1: without coupling every mu > 0 gives c = 1 and mu = 0
        gives c = 0 (``numeric.solutions.limits``). Within rounding of c_max (4 units in the last place of c, or twice the distance of the
        level's c_max from the closed form) the result is the slip limit (``numeric.slip_limit``: mu = inf,
        c = c_max, ``route`` says so); just below, mu is finite with the shift of the level's c_max in ``error``.
    SolverError
        If the iteration does not converge. Below c = 1e-5 (``C_ASYMPTOTIC``; given mu: where the
        asymptotic law puts c there) the asymptotic route (second order) is taken.

    Notes
    -----
    Given mu, c lies below c_max for every finite mu and tends to it like 1/mu; mu = inf is the
    fully adhesive solution (App. B), not the limit of the frictional one (``numeric.slip_limit``).
    Where the law puts 1 - c below 1e-13 (small gamma, large mu) the adhesive stresses are returned
    with that c (``numeric.solutions.solver.GAP_ADHESIVE``).

    Examples
    --------
    >>> s = flat_punch(nu=0.0, c=0.5)
    >>> round(s.mu, 10), round(s.compliance, 10), s.error < 1e-9
    (0.298714616, 1.0522119983, True)
    >>> flat_punch(nu=0.25, mu=1e-4).route.startswith("asymptotic, second order")   # c ~ 1e-130
    True
    """
    nu_value = None if nu is None else _scalar(check_nu(nu), "nu")
    g = resolve_gamma(nu_value, None if gamma is None else _scalar(check_gamma(gamma), "gamma"))
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick radius)")
    level_value, rtol_value = level_and_rtol(level, rtol)
    if c is not None:
        return _given_c(nu_value, g, _scalar(check_c(c), "c"), level_value, rtol_value)
    return _given_mu(nu_value, g, _scalar(check_mu(mu), "mu"), level_value, rtol_value)


def _scalar(value: ArrayLike, name: str) -> float:
    """A checked argument as a float; flat_punch solves one problem (arrays: stick_radius, friction_coefficient)."""
    arr = np.asarray(value, dtype=float)
    if arr.size != 1:
        raise TypeError(f"{name} must be a single number for flat_punch, got shape {arr.shape}; "
                        "stick_radius and friction_coefficient take arrays")
    return float(arr.reshape(()))


def _given_c(nu: float | None, gamma: float, c: float, level: int, rtol: float | None) -> FlatPunchSolution:
    if 0.0 < gamma and c < 1.0 and 1.0 - c <= float(largest_stick_radius_gap(gamma)) * (1.0 + NEAR_C_MAX):
        # at c_max to rounding (the slip limit) or beyond it (NoEigenvalueError): the solver tells which
        solver = SolverRoute(nu, gamma, c, None, c)
        return solver.at_level(level) if rtol is None else (first_meeting(solver.offers(rtol), rtol, lambda s: s.mu)
                                                             or solver.best_effort(rtol))
    closed = closed_form_given_c(nu, gamma, c)
    if closed is not None:
        return closed
    law = LawRoute(nu, gamma, c, None)
    if gamma < GAMMA_LAW_EXACT:
        return law.last_resort(None, f"gamma < {GAMMA_LAW_EXACT:g}, where the law is exact to rounding")
    solver = SolverRoute(nu, gamma, c, None, c)
    return _cheapest(law, _table(nu, gamma, c, None, rtol), solver, level, rtol, lambda sol: sol.mu,
                     f"c < {C_ASYMPTOTIC:g}")


def _given_mu(nu: float | None, gamma: float, mu: float, level: int, rtol: float | None) -> FlatPunchSolution:
    closed = closed_form_given_mu(nu, gamma, mu)
    if closed is not None:
        return closed
    law = LawRoute(nu, gamma, None, mu)
    if gamma < GAMMA_LAW_EXACT:
        why = f"gamma < {GAMMA_LAW_EXACT:g}, where the law is exact to rounding"
        if law.bracket.c == 1.0:  # 1 - c below the doubles' spacing: the adhesive stresses, exactly as well
            return closed_form(nu, gamma, mu, 1.0, True, f"adhesive stresses (App. B): {why}, and 1 - c < 1e-16")
        return law.last_resort(None, why)
    gap_max = float(largest_stick_radius_gap(gamma))
    if mu * gamma >= LAW_MU_GAMMA_MAX:  # far beyond the law: c is c_max to rounding, or 1 to within gap_max
        solver = SolverRoute(nu, gamma, None, mu, 1.0, gap_max)
        return solver.at_level(level) if rtol is None else (first_meeting(solver.offers(rtol), rtol, lambda s: s.c)
                                                             or solver.best_effort(rtol))
    # where the table reaches, its c and 1 - c (~1e-9) decide the route: the law's 1 - c misses the
    # saturation at c_max (at gamma = 0.13, mu = 2 it puts 1 - c at 1e-21, the table at 6.5e-12)
    found = table_given_mu(mu, gamma, quantities=(), slopes=True)
    if math.isfinite(found.gap[0]):
        solver = SolverRoute(nu, gamma, None, mu, float(found.c[0]), float(found.gap[0]), found)
    elif mu < table_least_mu(gamma):  # c < C_MIN: below the solver's reach, whatever the law's estimate
        solver = SolverRoute(nu, gamma, None, mu, 0.0)
    else:
        solver = SolverRoute(nu, gamma, None, mu, law.bracket.c, max(law.gap, gap_max))
    try:
        return _cheapest(law, _table(nu, gamma, None, mu, rtol), solver, level, rtol, lambda sol: sol.c,
                         f"the law's c < {C_ASYMPTOTIC:g}")
    except SolverError:
        if law.bracket.lo >= C_ASYMPTOTIC:
            raise
        # the law's c is above C_ASYMPTOTIC but the true one below the solver's reach
        return law.last_resort(rtol, "the solver did not converge at this small c")


def _table(nu: float | None, gamma: float, c: float | None, mu: float | None, rtol: float | None) -> list[Offer]:
    """The table route's offers (none unless rtol >= TABLE_RTOL: the table is not consulted otherwise)."""
    if rtol is None or rtol < TABLE_RTOL:
        return []
    return TableRoute(nu, gamma, c, mu).offers(rtol)


def _cheapest(law: LawRoute, table: list[Offer], solver: SolverRoute, level: int, rtol: float | None,
              value: Callable[[FlatPunchSolution], float], below: str) -> FlatPunchSolution:
    """Ask the law, the table and the solver once what they offer for rtol; run the offers cheapest first and
    return the first result that meets rtol in ``value``; else the solver's best (or, below its
    reach, the second-order law), with an ``AccuracyWarning``. Without rtol the solver runs at
    ``level``."""
    if rtol is not None:
        sol = first_meeting(law.offers(rtol) + table + (solver.offers(rtol) if solver.reaches else []), rtol, value)
        if sol is not None:
            return sol
    if not solver.reaches:
        return law.last_resort(rtol, f"{below}, below the solver's reach")
    return solver.at_level(level) if rtol is None else solver.best_effort(rtol)
