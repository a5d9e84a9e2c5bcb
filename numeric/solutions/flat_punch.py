"""The frictional flat punch: stick radius, friction, compliance and stresses ([S75] §2).

Method, and why: piecewise polynomials in u = t^2 on an hp mesh graded geometrically
toward the stick-slip boundary and the edge, collocation of (2.2) with every Abel integral
done exactly, and the eigenvalue condition phi(c-) = 0 solved by a Krylov model of the
linear system (``numeric.core``). The solution has power-type singularities at x = c and
x = 1 whose exponents depend on mu (tan pi alpha = mu gamma), so a fixed singular basis would
have to change during the eigenvalue iteration; geometric grading with low degree near those
points and high degree away from them resolves any such exponent with exponential
convergence in the number of unknowns, and keeps the matrices for a given mesh reusable
(cached) across mu and gamma.

Routes (``route`` of the result names the one taken), each in its module: closed forms in the
limits (``numeric.solutions.limits``); the asymptotic law mu/gamma = f0(c) (2.28) or
f0 + gamma^2 f2 with error bounds measured against the solver (``numeric.solutions.law``); the
solver at its resolution levels (``numeric.solutions.solver``), with a bracket for given mu
beyond what it reaches near the largest stick radius c_max = 1 - 8 exp(-pi/kappa). The route
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

from asymptotics.materials import check_c, check_mu, check_nu, resolve_gamma

from numeric.core.errors import SolverError
from numeric.core.graded_mesh import LEVELS
from numeric.solutions.law import LawRoute
from numeric.solutions.limits import closed_form_given_c, closed_form_given_mu
from numeric.solutions.solver import C_ASYMPTOTIC, DEFAULT_LEVEL, LEVEL_C_MIN, SolverRoute
from numeric.solutions.solution import FlatPunchSolution, first_meeting

__all__ = ["flat_punch", "check_rtol", "level_and_rtol"]


def check_rtol(rtol) -> float:
    """``rtol`` as a float, raising ValueError naming it unless positive and finite."""
    value = float(rtol)
    if not (math.isfinite(value) and value > 0.0):
        raise ValueError(f"rtol must be a positive finite number, got {rtol!r}")
    return value


def _check_level(level) -> int:
    try:
        ok = 1 <= int(level) < len(LEVELS) and int(level) == level
    except (TypeError, ValueError, OverflowError):
        ok = False
    if not ok:
        raise ValueError(f"level must be an integer in [1, {len(LEVELS) - 1}], got {level!r}")
    return int(level)


def level_and_rtol(level, rtol) -> tuple[int, float | None]:
    """The checked level (default ``DEFAULT_LEVEL``) and rtol; not both may be given."""
    if level is not None and rtol is not None:
        raise ValueError("give level or rtol, not both (rtol chooses the route and the level)")
    return (DEFAULT_LEVEL if level is None else _check_level(level)), (None if rtol is None else check_rtol(rtol))


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
        Resolution level 1..4 of ``numeric.core.graded_mesh.LEVELS`` (the next coarser one gives
        the error estimate); 2 (the default) reaches ~1e-10. Not together with ``rtol``.
    rtol : float, optional
        Relative accuracy wanted in the returned c (given mu) or mu (given c): the cheapest
        route whose error meets ``error <= rtol * value`` is taken. A closed form in the
        limits; else the asymptotic law for c <= 0.9 (first order (2.28) where its measured
        bound K2(gamma) gamma^2 meets rtol, else second order (2.28) + gamma^2 f2 where
        K4(gamma) gamma^4 does; ``numeric.solutions.law.K2_BOUNDS``, ``K4_BOUNDS``); else the solver at the first
        level whose typical accuracy meets rtol (1: 1e-8, 2: 1e-10, 3: 1e-12, else 4), and
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
        If c exceeds the largest stick radius, estimated as c_max = 1 - 8 exp(-pi/kappa),
        kappa = (2/pi) atanh(gamma) (large gamma): at once above 1 - 7.5 exp(-pi/kappa), and
        wherever the solver fails within 16 exp(-pi/kappa) of 1.
    SolverError
        If even level 1 does not converge. A level is not tried below the smallest c it
        reaches (``numeric.solutions.solver.LEVEL_C_MIN``: 5e-6, 5e-5, 5e-4, 1e-2); the next coarser one is used and
        ``route`` says so. Below c = 1e-5 (``C_ASYMPTOTIC``; given mu: where the asymptotic
        law puts c there) the asymptotic route (second order) is taken.

    Notes
    -----
    Given mu, c lies below c_max for every finite mu, but mu(c) ~ 1/(c_max - c): the search
    stops at c_top = 1 - 10 exp(-pi/kappa) (or 1 - 1e-9 where that is larger, small gamma). For
    mu > mu(c_top) the result is a bracket: c = the midpoint of (c_top, min(1, 1 - 7.5
    exp(-pi/kappa))], P* the midpoint of (P*(c_top), P*_adhesive (B4)], the half-widths as
    ``error``; the stresses are those of the adhesive solution (App. B) at small gamma and of
    the solution at c_top otherwise, as ``route`` says.

    Examples
    --------
    >>> s = flat_punch(nu=0.0, c=0.5)
    >>> round(s.mu, 10), round(s.compliance, 10), s.error < 1e-9
    (0.298714616, 1.0522119983, True)
    >>> flat_punch(nu=0.25, mu=1e-4).route.startswith("asymptotic, second order")   # c ~ 1e-130
    True
    """
    g = resolve_gamma(nu, gamma)
    nu_value = None if nu is None else float(check_nu(nu))
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick radius)")
    level_value, rtol_value = level_and_rtol(level, rtol)
    if c is not None:
        return _given_c(nu_value, g, float(check_c(c)), level_value, rtol_value)
    return _given_mu(nu_value, g, float(check_mu(mu)), level_value, rtol_value)


def _given_c(nu: float | None, gamma: float, c: float, level: int, rtol: float | None) -> FlatPunchSolution:
    closed = closed_form_given_c(nu, gamma, c)
    if closed is not None:
        return closed
    law = LawRoute(nu, gamma, c, None)
    solver = SolverRoute(nu, gamma, c, None, c, c)
    return _cheapest(law, solver, level, rtol, lambda sol: sol.mu, f"c < {C_ASYMPTOTIC:g}")


def _given_mu(nu: float | None, gamma: float, mu: float, level: int, rtol: float | None) -> FlatPunchSolution:
    closed = closed_form_given_mu(nu, gamma, mu)
    if closed is not None:
        return closed
    law = LawRoute(nu, gamma, None, mu)
    solver = SolverRoute(nu, gamma, None, mu, law.bracket.lo, law.bracket.c)
    try:
        return _cheapest(law, solver, level, rtol, lambda sol: sol.c, f"the law's c < {C_ASYMPTOTIC:g}")
    except SolverError:
        if law.bracket.lo >= LEVEL_C_MIN[1]:
            raise
        # the law's c is above C_ASYMPTOTIC but the true one below the solver's reach
        return law.last_resort(rtol, "the solver did not converge at this small c")


def _cheapest(law: LawRoute, solver: SolverRoute, level: int, rtol: float | None,
              value: Callable[[FlatPunchSolution], float], below: str) -> FlatPunchSolution:
    """Ask the law and the solver once what they offer for rtol; run the offers cheapest first and
    return the first result that meets rtol in ``value``; else the solver's best (or, below its
    reach, the second-order law), with an ``AccuracyWarning``. Without rtol the solver runs at
    ``level``."""
    if rtol is not None:
        sol = first_meeting(law.offers(rtol) + (solver.offers(rtol) if solver.reaches else []), rtol, value)
        if sol is not None:
            return sol
    if not solver.reaches:
        return law.last_resort(rtol, f"{below}, below the solver's reach")
    return solver.at_level(level) if rtol is None else solver.best_effort(rtol)
