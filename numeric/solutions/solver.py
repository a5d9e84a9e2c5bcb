"""The solver route of ``numeric.flat_punch``: the hp solver of ``numeric.core`` at its resolution levels.

``error`` is the difference between two resolution levels (the one returned and the next
coarser), an upper estimate of the returned level's error because the levels converge
exponentially (tests check it against a finer level). Where mu gamma > 1 the singularity
at c becomes nearly a jump (exponent 1/2 - alpha -> 0) and convergence can stall; then a
third level is solved and the larger difference is reported if they do not shrink tenfold.

Each level converges only above a smallest stick radius (``LEVEL_C_MIN``); below, the next
coarser level is used and ``route`` says so; below ``C_ASYMPTOTIC`` the solver is not offered.
Given mu, beyond what the solver reaches near the largest stick radius the answer is a bracket
(``near_full_stick``).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

from asymptotics.adhesive import compliance_adhesive

from numeric.core.graded_collocation import FlatField
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.graded_eigen import AboveTopError, solve_c, solve_mu
from numeric.core.graded_mesh import LEVELS
from numeric.core.table import table_available, table_friction_coefficient
from numeric.solutions.limits import (ADHESIVE_EDGE_BREAKPOINTS, C_MAX_COEFFICIENT, C_MAX_UPPER_COEFFICIENT, C_TOP,
                                      ClosedForm, c_search_top, gap_scale, no_eigenvalue)
from numeric.solutions.solution import FlatPunchSolution, Offer, warn_unmet

__all__ = ["DEFAULT_LEVEL", "LEVEL_C_MIN", "C_ASYMPTOTIC", "LEVEL_TYPICAL_ERROR", "LEVEL_SECONDS", "SolverRoute",
           "solve_given_c", "solve_given_mu", "near_full_stick"]

DEFAULT_LEVEL = 2
#: Smallest stick radius at which each level's eigenvalue iteration converges. Measured with
#: ``numeric.core.graded_eigen.solve_mu`` at gamma = 0.1, 0.3, 0.5, 0.75: level 1 converged at 2e-6 and 5e-6;
#: level 2 failed at 2e-5 (gamma = 0.3) and 3e-5 (0.1, 0.3), converged at 5e-5; level 3 failed at
#: 2e-4, 3e-4, converged at 5e-4; level 4 failed at 1e-3 ... 5e-3, converged at 1e-2. A failing
#: iteration spends 5-25 s before SolverError, so a level is not tried below its floor.
LEVEL_C_MIN = {1: 5e-6, 2: 5e-5, 3: 5e-4, 4: 1e-2}
#: Below this stick radius the asymptotic law replaces the solver (twice level 1's floor).
C_ASYMPTOTIC = 1e-5
#: Typical relative accuracy of each level (numeric.core.graded_mesh.LEVELS); rtol picks the first that meets it.
LEVEL_TYPICAL_ERROR = {1: 1e-8, 2: 1e-10, 3: 1e-12}
#: Rough run time in seconds of a solve at each level with its error estimate (derivations/benchmark.md),
#: for ordering the routes.
LEVEL_SECONDS = {1: 0.02, 2: 0.04, 3: 0.15, 4: 0.5}


def from_field(nu: float | None, fine: FlatField, level: int, error: float) -> FlatPunchSolution:
    """The solver's discrete solution as a ``FlatPunchSolution``."""
    return FlatPunchSolution(
        nu=nu,
        gamma=fine.gamma,
        mu=fine.mu,
        c=fine.c,
        compliance=fine.compliance,
        error=error,
        route=f"solver level {level}, {fine.n_unknowns} unknowns",
        breakpoints=fine.breakpoints,
        _field=fine,
    )


def error_estimate(fields: list[FlatField]) -> float:
    """Difference of the two finest levels, or, where it has not shrunk tenfold from the
    next pair (convergence stalling as alpha -> 1/2, mu gamma large), the larger of the two."""
    diffs = [max(abs(a.mu - b.mu), abs(a.compliance - b.compliance)) for a, b in zip(fields, fields[1:])]
    if len(diffs) == 2 and diffs[0] > 0.1 * diffs[1]:
        return max(diffs)
    return diffs[0]


def solve_given_c(nu: float | None, c: float, gamma: float, level: int) -> FlatPunchSolution:
    """mu for stick radius c at ``level``, the next coarser level giving the error estimate."""
    # the table's mu (7e-12, recorded at build) centres the LU: the Krylov root is then local, no second LU
    guess = float(table_friction_coefficient(c, gamma)[0]) if table_available() else math.nan
    guess = None if math.isnan(guess) else guess
    try:
        fields = [solve_mu(c, gamma, LEVELS[lv], mu_guess=guess) for lv in (level, level - 1)]
        if fields[0].mu * gamma > 1.0 and level >= 2:  # alpha > 1/4: convergence can stall, look one level further
            fields.append(solve_mu(c, gamma, LEVELS[level - 2], mu_guess=guess))
    except (SolverError, NoEigenvalueError) as exc:
        if c > 1.0 - 2.0 * C_MAX_COEFFICIENT * gap_scale(gamma):  # within twice 1 - c_max of 1
            raise no_eigenvalue(c, gamma, f"; the solver: {exc}") from None
        raise
    return from_field(nu, fields[0], level, error_estimate(fields))


def solve_given_mu(nu: float | None, mu: float, gamma: float, level: int, c_guess: float) -> FlatPunchSolution:
    """The stick radius for friction mu at ``level`` (``numeric.core.graded_eigen.solve_c``), or the bracket
    near full stick where mu exceeds what the search reaches."""
    try:
        fine, error = solve_c(mu, gamma, LEVELS[level], LEVELS[level - 1], c_guess=c_guess,
                              c_top=c_search_top(gamma))
    except AboveTopError:
        return near_full_stick(nu, gamma, mu, level)
    return from_field(nu, fine, level, error)


def near_full_stick(nu: float | None, gamma: float, mu: float, level: int) -> FlatPunchSolution:
    """mu > mu_c(c_top), c_top = ``c_search_top``: by monotonicity in mu (c and P* increase, §2.1),
    c_top < c <= c_hi and P*(c_top) < P* <= P0*, c_hi = 1 at small gamma (c_top = 1 - 1e-9), else
    1 - 7.5 exp(-pi/kappa) (above c_max); return the midpoints with half-widths (plus the solver's
    error at c_top) as the error. Stresses: the adhesive closed form (App. B) at small gamma (exact
    outside the slip annulus of width < 1e-9 only in the limit), else the solution at c_top."""
    top_c = c_search_top(gamma)
    edge = solve_mu(top_c, gamma, LEVELS[level], mu_guess=mu)
    edge_coarse = solve_mu(top_c, gamma, LEVELS[level - 1], mu_guess=mu)
    if edge.mu > mu:  # the coarse search overshot: not in the near-full-stick regime after all
        raise SolverError(f"stick radius for mu = {mu}, gamma = {gamma:.6g} not bracketed below {top_c}")
    adhesive = float(compliance_adhesive(gamma))
    solver_error = abs(edge.compliance - edge_coarse.compliance)
    c_hi = min(1.0, 1.0 - C_MAX_UPPER_COEFFICIENT * gap_scale(gamma))
    small_gamma = top_c == C_TOP
    if small_gamma:
        what, field, breakpoints = "adhesive stresses (App. B)", ClosedForm(gamma, True), ADHESIVE_EDGE_BREAKPOINTS
    else:
        what = f"c_max ~ 1 - 8 exp(-pi/kappa); stresses of the solution at c = {top_c:.6g} (mu = {edge.mu:.6g})"
        field, breakpoints = edge, edge.breakpoints
    return FlatPunchSolution(
        nu=nu,
        gamma=gamma,
        mu=mu,
        c=0.5 * (top_c + c_hi),
        compliance=0.5 * (adhesive + edge.compliance),
        error=max(0.5 * (c_hi - top_c), 0.5 * abs(adhesive - edge.compliance) + solver_error),
        route=f"bracketed: mu > mu_c({top_c:.12g}) = {edge.mu:.6g}, so {top_c:.12g} < c <= {c_hi:.12g}; {what}",
        breakpoints=breakpoints,
        _field=field,
    )


class SolverRoute:
    """The solver for one problem (exactly one of c and mu given) at the levels that reach ``c_low``.

    ``c_low`` is the stick radius, or a lower bound of it (the law's bracket, given mu); a
    level is never run below its floor ``LEVEL_C_MIN``. ``reaches`` is false below
    ``C_ASYMPTOTIC``. ``offers(rtol)`` are the levels whose typical accuracy meets rtol,
    ``best_effort`` the most accurate of them (or the finest level reached) when none did,
    and ``at_level(level)`` the result without rtol.
    """

    def __init__(self, nu: float | None, gamma: float, c: float | None, mu: float | None, c_low: float,
                 c_estimate: float):
        self.reaches = c_estimate >= C_ASYMPTOTIC
        self.top = max([lv for lv in LEVEL_C_MIN if LEVEL_C_MIN[lv] <= c_low] + [1])
        self._value: Callable[[FlatPunchSolution], float]
        if c is not None:
            self._solve = lambda level: solve_given_c(nu, c, gamma, level)
            self._value = lambda sol: sol.mu
        else:
            self._solve = lambda level: solve_given_mu(nu, mu, gamma, level, c_estimate)
            self._value = lambda sol: sol.c
        self._results: list[FlatPunchSolution] = []

    def _with_fallback(self, level: int) -> FlatPunchSolution:
        """The solve at ``level``, or, where it does not converge (very small c), the next coarser
        level with the route saying so; the error estimate is then that level's own."""
        try:
            return self._solve(level)
        except SolverError:
            if level <= 1:
                raise
            sol = self._with_fallback(level - 1)
            return replace(sol, route=f"{sol.route} (level {level} did not converge)")

    def at_level(self, level: int) -> FlatPunchSolution:
        """The solution at ``level`` (no rtol), or at the finest level below it that reaches c."""
        sol = self._with_fallback(min(level, self.top))
        if self.top < level:
            sol = replace(sol, route=f"{sol.route} (level {level} does not reach c < {LEVEL_C_MIN[level]:g})")
        return sol

    def _start(self, rtol: float) -> int:
        return next((lv for lv, e in LEVEL_TYPICAL_ERROR.items() if e <= rtol), 4)

    def offers(self, rtol: float) -> list[Offer]:
        """One offer per level from the first whose typical accuracy meets rtol to the finest reached."""
        return [Offer(LEVEL_SECONDS[lv], lambda: True, lambda lv=lv: self._run(lv))
                for lv in range(self._start(rtol), self.top + 1)]

    def _run(self, level: int) -> FlatPunchSolution:
        sol = self._with_fallback(level)
        self._results.append(sol)
        return sol

    def best_effort(self, rtol: float) -> FlatPunchSolution:
        """The most accurate level run (the finest reached, if rtol asked for more), with an
        ``AccuracyWarning``."""
        if not self._results:
            self._run(self.top)
        best = min(self._results, key=lambda sol: sol.error)
        if self.top < 4:
            best = replace(best, route=f"{best.route} (level {self.top + 1} does not reach c < "
                                       f"{LEVEL_C_MIN[self.top + 1]:g})")
        warn_unmet(best, rtol, self._value(best))
        return best
