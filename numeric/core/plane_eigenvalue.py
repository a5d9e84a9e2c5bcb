"""The eigenvalue relation of the strip punch on the plane singular basis: theta for given c, c for given theta.

theta = atan(mu gamma) = pi alpha runs over [0, pi/2] as mu runs over [0, inf]; the system
D(theta) z = b of ``numeric.core.plane_operators`` is analytic in theta, and the eigenvalue
condition G = l(theta) . z = 0 (phi(c-) = 0) picks the friction.

Given c, from a close guess (the table of ``numeric.core.plane_guess``): ``plane_given_c_linearised``, Newton in
theta (``numeric.core.eigenvalue.newton_theta``, the axisymmetric solver's) on the system linearised in the basis
exponent about the guess (``LinearisedPlaneSystem``: two assemblies, then an LU a step); G depends on the basis exponent
nearly as much as on theta, so the exponent cannot be held fixed as in the axisymmetric solver, but to first order it
can follow theta at no cost. Otherwise (no table there, or the linearised iteration does not settle): the careful
``plane_given_c``, Newton with both assemblies at every step (dG/dtheta = l' . z - y . D' z with D^T y = l, the basis
exponent alpha = theta / pi following theta), safeguarded by bisection once the root is bracketed.

Given theta (alpha known exactly): the secant method in xi = log(c / (1 - c)) on G, each step a new
layout. theta = pi/2 is the limit mu -> inf: its root is the largest stick width c_max.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from numeric.core.eigenvalue import carried_along_tangent, newton_theta
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.plane_charts import PlaneLayout, PlaneResolution, plane_layout
from numeric.core.plane_operators import (LinearisedPlaneSystem, PlaneCollocationSystem, PlaneOperators, linearised_system,
                                          plane_collocation_system)

__all__ = ["PlaneEigensolution", "plane_operators_at", "plane_given_c", "plane_given_c_linearised", "plane_at_theta",
           "plane_given_theta", "partner_shift_theta", "partner_shift_xi", "ALPHA_TOLERANCE",
           "CHORD_BELOW", "EXPONENT_STEP", "OUTER_TOLERANCE", "THETA_MAX", "THETA_ROUNDING", "THETA_ROUNDING_ABSOLUTE",
           "theta_rounding"]

HALF_PI = 0.5 * math.pi
THETA_MAX = HALF_PI - 1e-9
"""Largest theta Newton visits (mu gamma = 1e9): at pi/2 itself the generic mode degenerates (``MODE_BETA_MIN``)."""
ALPHA_TOLERANCE = 1e-12
"""Newton in theta stops when a step is below this, relative."""
THETA_ROUNDING = 3e-11
"""Scale of ``theta_rounding``'s relative part (times theta)."""
THETA_ROUNDING_ABSOLUTE = 5e-13
"""Scale of ``theta_rounding``'s absolute part."""


def theta_rounding(c: float, theta: float) -> float:
    """The rounding scatter of a given-c solve's theta: the lesser of ``THETA_ROUNDING_ABSOLUTE`` c^-0.4 and
    ``THETA_ROUNDING`` theta c^-0.6 (theta the solve's, or its guess).

    Measured: the spread (max - min) of theta over seven starts 1e-9 ... 1e-7 off, at levels 0-4, c in {1e-4, 1e-3,
    3e-3, 0.01, 0.1, 0.5, 0.9, 0.99}, nu in {-1/2, 0, 0.3, 0.45, 0.47, 0.488, 0.495, 0.499} (312 points): absolute
    at most 8.6e-12 (nu = 0.3, c = 1e-4, level 4), below the absolute part everywhere (2e-11 there); relative to
    theta below 1e-11 at c >= 0.1 for nu <= 0.3 and up to 3e-11 as nu -> 1/2, up to 2e-10 at c = 0.01, 1e-9 at 1e-3,
    2e-9 at 1e-4 (growing with the level and toward small c, not as gamma -> 0: at c = 0.5 2e-12 ... 3e-11 from
    nu = 0.45 to 0.499), below the relative part everywhere. The absolute part decides where theta is not small (it
    is the plain system's envelope, which next to c_max, where the system is not balanced, still holds), the relative
    one as nu -> 1/2: with the relative part alone the estimate at nu = 0.3, c = 3.4e-4 (mu = 0.05) was 3.6e-8 in c,
    where the scatter is ~1e-9, and ``stick_radius(..., rtol=1e-8)`` warned.

    Before the system was balanced (``numeric.core.plane_operators.plane_collocation_system``) the scatter was absolute
    in theta (1e-14 ... 3.6e-12, growing like c^-0.4): as nu -> 1/2 (gamma -> 0, theta ~ gamma^2 K(c)/K'(c)) the
    system's condition grew like 1/gamma and mu's relative error like 1/gamma^2 (2.6e-10 ... 1.3e-7 at nu = 0.47 ...
    0.499, where the spread / theta is now 2e-12 ... 3e-11 at c = 0.5).

    It floors the error estimate, and Newton on the linearised system stops at a step below it (taking that step: the
    root is then within the step's square, not within the envelope)."""
    return min(THETA_ROUNDING_ABSOLUTE * c**-0.4, THETA_ROUNDING * theta * c**-0.6)


@dataclass(frozen=True, slots=True, eq=False)
class PlaneEigensolution:
    """theta and the coefficients z on ``system`` (D(theta) z = b, l . z = 0), with the operators that built it."""

    system: PlaneCollocationSystem
    operators: PlaneOperators
    theta: float
    coefficients: np.ndarray
    last_step: float  # the last Newton step in theta, or secant step in logit c
    slope: float = math.nan  # dG/dtheta (given c) or dG/dxi (given theta) at the solution, where the iteration had it
    linearised: LinearisedPlaneSystem | None = None  # the linearised system that gave it (for the system at another theta)
    conditioning: float = math.nan  # 1-norm condition number of the equilibrated D at the root, where Newton had it
    tangent: np.ndarray | None = None  # dz/dtheta on ``linearised`` within Newton's last step, where Newton formed it

    @property
    def layout(self) -> PlaneLayout:
        return self.system.layout


ALPHA_STEP = 1e-7
"""Step in the basis exponent of the difference quotient dD/dalpha (error ~1e-7 relative in dG, rounding ~1e-9)."""


def _evaluate(ops: PlaneOperators, gamma: float, theta: float, derivative: bool = True
              ) -> tuple[PlaneCollocationSystem, np.ndarray, float, float]:
    """The system with the basis exponent alpha = theta/pi, its solution z, G = a and (if asked) dG/dtheta along
    alpha = theta/pi: dG = l' . z - y . (dD/dtheta + dD/dalpha / pi) z with D^T y = l, dD/dalpha by a difference
    quotient (the basis exponent moves the singular families; at fixed basis G's slope can have the wrong sign)."""
    alpha = theta / math.pi
    linear = linearised_system(ops, gamma, alpha, ALPHA_STEP) if derivative else None
    system = plane_collocation_system(ops, gamma, alpha) if linear is None else linear.base
    lu = EquilibratedLU(system.matrix(theta))
    z = lu.solve_refined(system.rhs)
    l = system.functional(theta)
    if linear is None:
        return system, z, float(l @ z), math.nan
    y = lu.solve_transposed(l)
    dG = system.functional_derivative(theta) @ z - y @ linear.derivative_times(theta, z)  # at theta = pi alpha
    return system, z, float(l @ z), float(dG)


#: Newton keeps its last derivative (a chord step) while its steps are below this, relative: the derivative is then
#: good to ~1e-4 and the chord step's error ~1e-4 of the step, far below the step itself.
CHORD_BELOW = 1e-4


@lru_cache(maxsize=4)
def plane_operators_at(c: float, gap: float, res: PlaneResolution) -> PlaneOperators:
    """The alpha-independent transforms of the layout for c = 1 - gap at res (they depend on the discretisation only,
    not on gamma or mu: a sweep over nu at one c forms them once; the last few kept)."""
    return PlaneOperators(plane_layout(c, gap, res))


#: Step of the difference quotient dD/dalpha of ``LinearisedPlaneSystem``, relative to alpha. Measured at nu = 0.3,
#: c = 0.5 against the converged root: from guesses 1e-7 off it leaves 1.4e-12 relative in theta (the rounding floor
#: of G, ~1e-12; a step of 1e-9 leaves 4e-12 from rounding, one of 1e-6 5e-12 from the curvature).
EXPONENT_STEP = 1e-7
#: The linearised iteration is done when Newton moved theta by less than this, relative: the first-order model's
#: error is then below ~1e-12 (measured, see ``EXPONENT_STEP``); else it starts again about the new theta.
OUTER_TOLERANCE = 1e-7
#: Linearised iterations before the careful iteration takes over.
MAX_OUTER = 3


def plane_given_c_linearised(c: float, gap: float, gamma: float, theta_guess: float, res: PlaneResolution,
                             spread: float = EXPONENT_STEP, max_outer: int = MAX_OUTER) -> PlaneEigensolution:
    """theta for stick half-width c = 1 - gap from a close guess: Newton (``numeric.core.eigenvalue.newton_theta``) on
    the system linearised in the basis exponent about the guess (``LinearisedPlaneSystem``), its difference step the
    larger of ``EXPONENT_STEP`` and ``spread`` (the guess's expected relative error: the secant then spans the root);
    again about the result while Newton moved theta by more than ``OUTER_TOLERANCE`` (relative) and ``theta_rounding``
    (absolute: as nu -> 1/2 theta's rounding scatter exceeds 1e-7 relative, and rounds would chase it). Raises SolverError if that takes
    more than ``max_outer`` rounds or Newton does not converge (the caller falls back to ``plane_given_c``)."""
    ops = plane_operators_at(c, gap, res)
    theta = min(theta_guess, THETA_MAX)
    step = max(EXPONENT_STEP, spread)
    noise = theta_rounding(c, theta)
    for _ in range(max_outer):
        system = linearised_system(ops, gamma, theta / math.pi, step * theta / math.pi)
        root = newton_theta(system, theta, conditioning=True, noise=noise)
        new = root.theta
        moved = abs(new - theta)
        if not 0.0 < new < THETA_MAX:
            break
        if moved <= max(OUTER_TOLERANCE * new, noise):
            return PlaneEigensolution(system.at(new), ops, new, root.coefficients, root.last_step, root.slope, system,
                                      root.lu.condition(), root.tangent)
        theta, step = new, max(EXPONENT_STEP, moved / new)
    raise SolverError(f"the linearised iteration did not settle for c = {c}, gamma = {gamma}")


def plane_at_theta(solution: PlaneEigensolution, theta: float) -> PlaneEigensolution:
    """The solution on the same (linearised) system at theta itself: given mu, the last given-c solve's theta differs
    from atan(mu gamma) by its remaining step in c (below 1e-12 in logit c), and the stresses are taken at mu.

    As the axisymmetric ``numeric.core.eigenvalue`` does, z moves to theta along Newton's dz/dtheta where theta and
    Newton's last step are both near enough (``carried_along_tangent``), else by a new solve. The guided solves start
    Newton at theta itself, so where its first step was its last the move undoes that step and gives the LU's own solution at theta. Measured over 51 given-mu solves (nu from -0.9
    to 0.49, c from 0.02 to 0.97) against a new solve at theta: p, q, u at 14 points and the load identical at 49, within
    6e-12 of max(1, |p|) at nu = 0, c = 0.05, and 3.7e-10 at nu = 0.49, c = 0.3, where both lie ~2e-9 from level 3
    (the new solve the farther: q 2.7e-9 against 2.3e-9). One LU of up to 730 unknowns saved a given-mu solve."""
    system = solution.linearised
    if system is None or theta == solution.theta:
        return solution
    z = carried_along_tangent(solution.coefficients, solution.theta, theta, solution.tangent, solution.last_step)
    if z is None:
        z = EquilibratedLU(system.matrix(theta)).solve_refined(system.rhs)
    return PlaneEigensolution(system.at(theta), solution.operators, theta, z, abs(theta - solution.theta),
                              solution.slope, system, solution.conditioning, solution.tangent)


def plane_given_c(c: float, gap: float, gamma: float, theta_guess: float, res: PlaneResolution,
                  max_steps: int = 40) -> PlaneEigensolution:
    """theta = atan(mu gamma) for stick half-width c = 1 - gap: Newton in theta from a guess, the basis exponent
    following theta at every step, safeguarded by bisection (in log mu) once the root is bracketed.

    G(theta) (the mode's amplitude) is smooth and decreasing in theta over (0, pi/2] (it changes sign once at
    the eigenvalue); the iteration stops when a step is below ``ALPHA_TOLERANCE`` relative, or when the steps
    stop shrinking below 1e-10 relative (the rounding floor of G). The derivative is formed again only while the
    steps exceed ``CHORD_BELOW`` relative (or after a bisection)."""
    ops = plane_operators_at(c, gap, res)
    theta = theta_guess
    theta = min(theta, THETA_MAX)
    lo, hi = 0.0, THETA_MAX  # bracket: G > 0 at lo, G < 0 at hi
    previous = math.inf
    dG = math.nan
    for _ in range(max_steps):
        fresh = not (previous <= CHORD_BELOW * theta)
        system, z, G, slope = _evaluate(ops, gamma, theta, derivative=fresh)
        dG = slope if fresh else dG
        if G > 0.0:
            lo = max(lo, theta)
        elif G < 0.0:
            hi = min(hi, theta)
        if G > 0.0 and theta >= THETA_MAX:
            raise NoEigenvalueError(f"no friction coefficient gives stick half-width c = {c!r} at gamma = {gamma:.6g}: "
                                    "the eigen functional keeps its sign up to mu = inf (c is above the largest "
                                    "stick width c_max)")
        new = theta - G / dG if dG != 0.0 else math.nan
        if not (lo < new < hi or (new == hi == THETA_MAX)) or not math.isfinite(new):  # bisect in log mu
            if lo == 0.0:
                new = 0.5 * theta
            elif hi == THETA_MAX:
                new = THETA_MAX if math.tan(theta) > 1e3 else math.atan(4.0 * math.tan(theta))
            else:
                new = math.atan(math.sqrt(math.tan(lo) * math.tan(hi)))
            change = abs(new - theta)
            if change <= 1e-10 * theta or hi - lo <= 1e-10 * theta:  # Newton left a bracket already at rounding
                return PlaneEigensolution(system, ops, theta, z, max(change, hi - lo), dG)
            previous = math.inf  # a fresh derivative at the next point
        else:
            change = abs(new - theta)
            if change <= ALPHA_TOLERANCE * theta or (change <= 1e-10 * theta and change >= 0.25 * previous):
                return PlaneEigensolution(system, ops, theta, z, change, dG)
            previous = change
        theta = new
    raise SolverError(f"Newton in theta did not converge for c = {c}, gamma = {gamma} (last step {change:.3g})")


def partner_shift_theta(c: float, gap: float, gamma: float, solution: PlaneEigensolution, res: PlaneResolution
                        ) -> float:
    """theta_partner - theta for the resolution ``res`` (one evaluation of its G at the solution's theta, over the
    solution's slope: the two resolutions' G differ by the discretisation error, their slopes by far less)."""
    ops = plane_operators_at(c, gap, res)
    G = _evaluate(ops, gamma, solution.theta, derivative=False)[2]
    return -G / solution.slope


def _residual(xi: float, theta: float, gamma: float, res: PlaneResolution):
    c = 1.0 / (1.0 + math.exp(-xi))
    gap = 1.0 / (1.0 + math.exp(xi))
    ops = plane_operators_at(c, gap, res)
    system = plane_collocation_system(ops, gamma, theta / math.pi)
    z = EquilibratedLU(system.matrix(theta)).solve_refined(system.rhs)
    return float(system.functional(theta) @ z), system, ops, z


def plane_given_theta(theta: float, gamma: float, xi_guess: float, res: PlaneResolution, *, step: float = 1e-3,
                      tol: float = 1e-14, max_steps: int = 40) -> PlaneEigensolution:
    """Stick half-width for theta = atan(mu gamma) (pi/2: mu = inf, c = c_max) by the secant method in
    xi = log(c / (1 - c)) from a guess; the last step in xi is returned as ``last_step``."""
    x0, x1 = xi_guess, xi_guess + step
    g0 = _residual(x0, theta, gamma, res)[0]
    g1, system, ops, z = _residual(x1, theta, gamma, res)
    previous = math.inf
    slope = math.nan
    for _ in range(max_steps):
        if g1 == g0:  # G equal to the last bit at two points: the slope the last step was taken with (if any)
            return PlaneEigensolution(system, ops, theta, z, abs(x1 - x0), slope)
        slope = (g1 - g0) / (x1 - x0)
        x2 = x1 - g1 / slope
        x0, g0 = x1, g1
        x1 = x2
        g1, system, ops, z = _residual(x1, theta, gamma, res)
        size = abs(x1 - x0)
        if size <= tol * max(1.0, abs(x1)) or (size <= 1e-9 and size >= 0.25 * previous):
            # the slope of the last two points, or (a step of zero: G was 0 to the last bit; or G the same to the last bit
            # at both, as at nu = -0.9, theta = pi/2 with numpy's SIMD limited to x86-64-v2) the one it was taken with
            last = (g1 - g0) / (x1 - x0) if size > 0.0 else 0.0
            return PlaneEigensolution(system, ops, theta, z, size, last if last != 0.0 else slope)
        previous = size
    raise SolverError(f"the secant iteration in c did not converge for theta = {theta}, gamma = {gamma}")


def partner_shift_xi(theta: float, gamma: float, solution: PlaneEigensolution, res: PlaneResolution) -> float:
    """xi_partner - xi (xi = logit c) for the resolution ``res`` at fixed theta: one evaluation of its G at the
    solution's c over the solution's secant slope dG/dxi."""
    lay = solution.layout
    xi = math.log(lay.c) - math.log(lay.gap)
    return -_residual(xi, theta, gamma, res)[0] / solution.slope
