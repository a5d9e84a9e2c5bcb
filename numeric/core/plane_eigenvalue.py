"""The eigenvalue relation of the strip punch on the plane singular basis: theta for given c, c for given theta.

theta = atan(mu gamma) = pi alpha runs over [0, pi/2] as mu runs over [0, inf]; the system
D(theta) z = b of ``numeric.core.plane_operators`` is analytic in theta, and the eigenvalue
condition G = l(theta) . z = 0 (phi(c-) = 0) picks the friction.

Given c: Newton in theta on G with one LU a step (z and the adjoint of l from one factorisation,
dG/dtheta = l' . z - y . D' z with D^T y = l), the basis exponent alpha = theta / pi following theta at
every step, safeguarded by bisection once the root is bracketed.

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

import numpy as np

from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.plane_charts import PlaneLayout, PlaneResolution, plane_layout
from numeric.core.plane_operators import PlaneCollocationSystem, PlaneOperators, plane_collocation_system

__all__ = ["PlaneEigensolution", "plane_given_c", "plane_given_theta", "partner_shift_theta", "partner_shift_xi",
           "ALPHA_TOLERANCE", "CHORD_BELOW", "CLOSE", "THETA_MAX"]

HALF_PI = 0.5 * math.pi
THETA_MAX = HALF_PI - 1e-9
"""Largest theta Newton visits (mu gamma = 1e9): at pi/2 itself the generic mode degenerates (``MODE_BETA_MIN``)."""
ALPHA_TOLERANCE = 1e-12
"""Newton in theta stops when a step is below this, relative."""


@dataclass(frozen=True, slots=True, eq=False)
class PlaneEigensolution:
    """theta and the coefficients z on ``system`` (D(theta) z = b, l . z = 0), with the operators that built it."""

    system: PlaneCollocationSystem
    operators: PlaneOperators
    theta: float
    coefficients: np.ndarray
    last_step: float  # the last Newton step in theta, or secant step in logit c
    slope: float = math.nan  # dG/dtheta (given c) or dG/dxi (given theta) at the solution

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
    system = plane_collocation_system(ops, gamma, alpha)
    D = system.matrix(theta)
    lu = EquilibratedLU(D)
    z = lu.solve(system.rhs)
    l = system.functional(theta)
    if not derivative:
        return system, z, float(l @ z), math.nan
    y = lu.solve_transposed(l)
    shifted = plane_collocation_system(ops, gamma, alpha + ALPHA_STEP)
    dD = system.matrix_derivative(theta) + (shifted.matrix(theta) - D) / (math.pi * ALPHA_STEP)
    dG = system.functional_derivative(theta) @ z - y @ (dD @ z)
    return system, z, float(l @ z), float(dG)


#: A Newton step below this (relative) from a close guess is the last: its successor is below ~1e-14.
CLOSE = 1e-7

#: Newton keeps its last derivative (a chord step) while its steps are below this, relative: the derivative is then
#: good to ~1e-4 and the chord step's error ~1e-4 of the step, far below the step itself.
CHORD_BELOW = 1e-4


def plane_given_c(c: float, gap: float, gamma: float, theta_guess: float, res: PlaneResolution,
                  max_steps: int = 40, close: bool = False) -> PlaneEigensolution:
    """theta = atan(mu gamma) for stick half-width c = 1 - gap: Newton in theta from a guess, the basis exponent
    following theta at every step, safeguarded by bisection (in log mu) once the root is bracketed.

    G(theta) (the mode's amplitude) is smooth and decreasing in theta over (0, pi/2] (it changes sign once at
    the eigenvalue); the iteration stops when a step is below ``ALPHA_TOLERANCE`` relative, or when the steps
    stop shrinking below 1e-10 relative (the rounding floor of G). The derivative is formed again only while the
    steps exceed ``CHORD_BELOW`` relative (or after a bisection). ``close``: the guess is a coarser resolution's
    root; one Newton step is taken and accepted if it is below ``CLOSE`` relative (the coefficients are those at the
    guess: the stresses move by the step times their derivative in theta, ~1e-12)."""
    ops = PlaneOperators(plane_layout(c, gap, res))
    theta = theta_guess
    theta = min(theta, THETA_MAX)
    lo, hi = 0.0, THETA_MAX  # bracket: G > 0 at lo, G < 0 at hi
    previous = math.inf
    dG = math.nan
    if close:  # one Newton step from a guess within ~1e-7: the next would be ~1e-14, below the rounding floor
        system, z, G, dG = _evaluate(ops, gamma, theta)
        new = theta - G / dG
        if abs(new - theta) <= CLOSE * theta and new < THETA_MAX:
            return PlaneEigensolution(system, ops, new, z, abs(new - theta), dG)
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
    ops = PlaneOperators(plane_layout(c, gap, res))
    G = _evaluate(ops, gamma, solution.theta, derivative=False)[2]
    return -G / solution.slope


def _residual(xi: float, theta: float, gamma: float, res: PlaneResolution):
    c = 1.0 / (1.0 + math.exp(-xi))
    gap = 1.0 / (1.0 + math.exp(xi))
    ops = PlaneOperators(plane_layout(c, gap, res))
    system = plane_collocation_system(ops, gamma, theta / math.pi)
    z = EquilibratedLU(system.matrix(theta)).solve(system.rhs)
    return float(system.functional(theta) @ z), system, ops, z


def plane_given_theta(theta: float, gamma: float, xi_guess: float, res: PlaneResolution, *, step: float = 1e-3,
                      tol: float = 1e-14, max_steps: int = 40) -> PlaneEigensolution:
    """Stick half-width for theta = atan(mu gamma) (pi/2: mu = inf, c = c_max) by the secant method in
    xi = log(c / (1 - c)) from a guess; the last step in xi is returned as ``last_step``."""
    x0, x1 = xi_guess, xi_guess + step
    g0 = _residual(x0, theta, gamma, res)[0]
    g1, system, ops, z = _residual(x1, theta, gamma, res)
    previous = math.inf
    for _ in range(max_steps):
        if g1 == g0:
            return PlaneEigensolution(system, ops, theta, z, abs(x1 - x0))
        x2 = x1 - g1 * (x1 - x0) / (g1 - g0)
        x0, g0 = x1, g1
        x1 = x2
        g1, system, ops, z = _residual(x1, theta, gamma, res)
        size = abs(x1 - x0)
        if size <= tol * max(1.0, abs(x1)) or (size <= 1e-9 and size >= 0.25 * previous):
            return PlaneEigensolution(system, ops, theta, z, size, (g1 - g0) / (x1 - x0))
        previous = size
    raise SolverError(f"the secant iteration in c did not converge for theta = {theta}, gamma = {gamma}")


def partner_shift_xi(theta: float, gamma: float, solution: PlaneEigensolution, res: PlaneResolution) -> float:
    """xi_partner - xi (xi = logit c) for the resolution ``res`` at fixed theta: one evaluation of its G at the
    solution's c over the solution's secant slope dG/dxi."""
    lay = solution.layout
    xi = math.log(lay.c) - math.log(lay.gap)
    return -_residual(xi, theta, gamma, res)[0] / solution.slope
