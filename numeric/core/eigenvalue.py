"""The eigenvalue relation of [S75] §2.2 on the singular basis: theta for given c, c for given theta.

theta = atan(mu gamma) = pi alpha runs over [0, pi/2] as mu runs over [0, inf]; the system
D(theta) z = b of ``numeric.core.operators`` is analytic in theta, and the eigenvalue
condition G = l(theta) . z = 0 (phi(c-) = 0) picks the friction.

Given c: Newton in theta on G with an LU per step (z and the adjoint of l from one
factorisation); the basis carries alpha = theta / pi of the previous step, and the outer
loop stops when theta moves by less than 1e-9 relative (the computed theta changes by ~1e-9
per unit change of the basis exponent, measured, so the last outer step changes nothing).

Given theta (alpha known exactly), from a close guess of c and of d theta / d xi (the tables'):
given-c solves at xi = log(c / (1 - c)) stepped by (theta - theta(xi)) / slope, the slope then
from the last two solves (``solve_given_theta_guided``); the tables' c is good to 1e-13 ... 1e-9, so
the first solve, or the second, lands within rounding: a stick radius costs one or two given-c
solves. Without a guess
(or at theta = pi/2, the limit mu -> inf, whose root is the largest stick radius c_max and where
theta(xi) does not exist beyond it): the secant method in xi on G, each step a new layout
(``solve_given_theta``).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple, Protocol, TypeVar

import numpy as np
from scipy import optimize

from numeric.core.charts import Layout, Resolution, layout
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.operators import AbelOperators, CollocationSystem, collocation_system

__all__ = ["Eigensolution", "GuidedSolution", "operators_at", "NewtonRoot", "newton_theta", "guided_steps", "solve_given_c",
           "solve_on_operators", "solve_given_theta", "solve_given_theta_guided", "EigenSystem", "STEP_TOLERANCE",
           "TANGENT_REACH", "carried_along_tangent"]

HALF_PI = 0.5 * math.pi
#: The basis exponent is settled when it moves mu gamma = tan(theta) by less than this, relative. (A tolerance
#: relative to theta, as before, left the exponent 1.5e-9 off at nu = 0.3, 1 - c = 1.01 (1 - c_max), mu gamma = 154:
#: mu scattered over degrees 11 ... 16 by 2.5e-11 and p at x = c by 2.6e-9, against 5.5e-13 and 4e-11 settled.)
ALPHA_TOLERANCE = 1e-9


@dataclass(frozen=True, slots=True, eq=False)
class Eigensolution:
    """theta and the coefficients z of the solution on ``system`` (D(theta) z = b, l . z = 0)."""

    system: CollocationSystem
    theta: float
    coefficients: np.ndarray
    newton_step: float  # size of the last Newton step in theta (0 when theta was given)
    tangent: np.ndarray | None = None  # dz/dtheta on this system within the last step, where Newton formed it

    @property
    def layout(self) -> Layout:
        return self.system.layout


@lru_cache(maxsize=4)
def operators_at(c: float, gap: float, res: Resolution) -> AbelOperators:
    """The Abel integrals of the layout for c = 1 - gap at resolution res: they depend on the discretisation only,
    not on gamma or mu, so a sweep over nu at one c (the paper's tables) forms them once (the last few kept)."""
    return AbelOperators(layout(c, gap, res))


class EigenSystem(Protocol):
    """What Newton in theta needs of a system D(theta) z = b with eigen functional G = l(theta) . z: the axisymmetric
    ``CollocationSystem`` at a fixed basis exponent, and the plane ``LinearisedPlaneSystem``."""

    rhs: np.ndarray

    def matrix(self, theta: float) -> np.ndarray: ...

    def functional(self, theta: float) -> np.ndarray: ...

    def functional_derivative(self, theta: float) -> np.ndarray: ...

    def derivative_times(self, theta: float, z: np.ndarray) -> np.ndarray: ...


class NewtonRoot(NamedTuple):
    """``newton_theta``'s result: the root, z there, the last step, and the last step's LU, dG/dtheta and dz/dtheta
    (all at the last theta but one, within the last step of the root: its conditioning and slopes are the root's)."""

    theta: float
    coefficients: np.ndarray
    last_step: float
    lu: EquilibratedLU
    slope: float
    tangent: np.ndarray


def newton_theta(system: EigenSystem, theta: float, tol: float = 1e-15, max_steps: int = 30,
                 conditioning: bool = False, noise: float = 0.0) -> NewtonRoot:
    """Root of G(theta) = l(theta) . D(theta)^-1 b on (0, pi/2] from theta, basis fixed.

    Returns a ``NewtonRoot`` (``EquilibratedLU.condition`` of its LU if ``conditioning``). Stops when a step is below tol relative, or once the
    steps stop shrinking (at least fourfold) while below 1e-8 relative: Newton has reached the
    rounding floor of G, and the last step measures it; or when a step is below ``noise`` (absolute: the caller's
    known rounding scatter of theta, which at small theta can exceed 1e-8 relative), the step then taken and z
    carried along it to first order, as after a first step below 1e-9 relative."""
    previous = math.inf
    for _ in range(max_steps):
        lu = EquilibratedLU(system.matrix(theta), conditioning)
        z = lu.solve_refined(system.rhs)
        l = system.functional(theta)
        y = lu.solve_transposed(l)
        dD_z = system.derivative_times(theta, z)
        dG = system.functional_derivative(theta) @ z - y @ dD_z
        step = (l @ z) / dG
        new = theta - step
        if new >= HALF_PI:  # beyond mu = inf: the root, if any, is at or below pi/2
            if theta == HALF_PI:  # the caller brackets instead (c >= c_max is refused before, by the closed form)
                raise SolverError("Newton in theta left (0, pi/2]")
            new = HALF_PI
        elif new <= 0.0:
            new = 0.5 * theta
        size = abs(new - theta)
        if (size <= 1e-9 * theta and previous == math.inf) or size <= noise:  # a close guess (the next step is
            dz = -lu.solve(dD_z)                                                  # ~1e-18), or a step within noise
            return NewtonRoot(new, z + (new - theta) * dz, size, lu, float(dG), dz)
        if size <= tol * theta or (size <= 1e-8 * theta and size >= 0.25 * previous):
            return NewtonRoot(new, z, size, lu, float(dG), -lu.solve(dD_z))
        if size > 0.5 * previous and size > 1e-6 * theta:
            raise SolverError(f"Newton in theta is not converging (step {step:.3g})")
        previous = size
        theta = new
    raise SolverError(f"Newton in theta did not converge (last step {step:.3g})")


def _functional_at(ops: AbelOperators, gamma: float, theta: float) -> float:
    """G(theta) with the basis carrying alpha = theta / pi."""
    system = collocation_system(ops, gamma, theta / math.pi)
    lu = EquilibratedLU(system.matrix(theta))
    return float(system.functional(theta) @ lu.solve_refined(system.rhs))


def _bracket_theta(ops: AbelOperators, gamma: float, theta: float) -> float:
    """Root of G by Brent's method (scipy) on a bracket found by stepping out from theta.

    G < 0 below the eigenvalue and > 0 above it, but it is not monotone and the discrete
    system is singular at isolated theta far from the root (poles of G, where |G| is huge), so
    Newton from a poor guess can run away and a sign change alone is not a root: the bracket
    is grown in steps of 1.3 in mu from the guess, and a sign change is accepted when Brent's
    root has |G| below the values at its ends (a pole has it above)."""
    mu0 = math.tan(theta)
    points = [math.atan(mu0 * 1.3 ** k) for k in range(-40, 41)]
    points = sorted(set(p for p in points if 0.0 < p < HALF_PI) | {theta, HALF_PI})
    start = points.index(theta)
    values = {theta: _functional_at(ops, gamma, theta)}
    for radius in range(1, len(points)):
        for j in (start - radius, start + radius):
            if not 0 <= j < len(points):
                continue
            for a, b in ((points[j], points[j + 1]) if j + 1 < len(points) else (None, None),
                         (points[j - 1], points[j]) if j > 0 else (None, None)):
                if a is None:
                    continue
                for t in (a, b):
                    if t not in values:
                        values[t] = _functional_at(ops, gamma, t)
                if values[a] * values[b] < 0.0:
                    root = optimize.brentq(lambda t: _functional_at(ops, gamma, t), a, b, xtol=1e-14, rtol=1e-12)
                    if abs(_functional_at(ops, gamma, root)) < min(abs(values[a]), abs(values[b])):
                        return root
    raise NoEigenvalueError("no friction coefficient gives this stick radius (no root of the eigenvalue condition)")


def solve_given_c(c: float, gap: float, gamma: float, theta_guess: float, res: Resolution,
                  max_outer: int = 8) -> Eigensolution:
    """theta = atan(mu gamma) for stick radius c = 1 - gap, from a guess.

    Newton with the basis exponent from the guess (fast path); if it fails to converge,
    Brent's method on a bracket, then Newton again from its root. The basis exponent is taken from the root
    again until it moves mu gamma = tan theta by less than ALPHA_TOLERANCE relative, or, once its change no longer
    shrinks (rounding of theta next to pi/2), by less than ALPHA_TOLERANCE in theta."""
    return solve_on_operators(operators_at(c, gap, res), gamma, theta_guess, max_outer)


def solve_on_operators(ops: AbelOperators, gamma: float, theta_guess: float, max_outer: int = 8) -> Eigensolution:
    """``solve_given_c`` on the Abel integrals of a given layout (``operators_at``'s, or a mapped layout's:
    ``numeric.core.layout_map``)."""
    theta = theta_guess
    bracketed = False
    outer = 0
    previous = math.inf
    while outer < max_outer:
        outer += 1
        system = collocation_system(ops, gamma, theta / math.pi)
        try:
            root = newton_theta(system, theta)
        except SolverError:
            if bracketed:
                raise
            theta, bracketed = _bracket_theta(ops, gamma, theta), True
            continue
        change = abs(root.theta - theta)
        done = change <= ALPHA_TOLERANCE * math.sin(root.theta) * math.cos(root.theta) or \
            (change <= ALPHA_TOLERANCE * root.theta and change >= 0.25 * previous)
        theta, previous = root.theta, change
        if done:
            return Eigensolution(system, theta, root.coefficients, root.last_step, root.tangent)
    raise SolverError(f"the basis exponent did not settle for c = {ops.layout.c}, gamma = {gamma}")


def _residual(c_logit: float, theta: float, gamma: float, res: Resolution):
    c = 1.0 / (1.0 + math.exp(-c_logit))
    gap = 1.0 / (1.0 + math.exp(c_logit))
    system = collocation_system(operators_at(c, gap, res), gamma, theta / math.pi)
    z = EquilibratedLU(system.matrix(theta)).solve_refined(system.rhs)
    return system.functional(theta) @ z, system, z


def solve_given_theta(theta: float, gamma: float, c_logit_guess: float, res: Resolution, *, step: float = 1e-3,
                      tol: float = 1e-14, max_steps: int = 40) -> Eigensolution:
    """Stick radius for theta = atan(mu gamma) (pi/2: mu = inf, c = c_max) by the secant method in
    xi = log(c / (1 - c)) from a guess.

    G(xi) is smooth up to the small jumps where the layout changes (an element boundary moves
    with c; they are of the size of the discretisation error), so the iteration also stops when
    its steps, below 1e-8, stop shrinking; the returned ``newton_step`` is the last step in xi."""
    x0, x1 = c_logit_guess, c_logit_guess + step
    g0, _, _ = _residual(x0, theta, gamma, res)
    g1, system, z = _residual(x1, theta, gamma, res)
    previous = math.inf
    for _ in range(max_steps):
        if g1 == g0:
            return Eigensolution(system, theta, z, abs(x1 - x0))
        x2 = x1 - g1 * (x1 - x0) / (g1 - g0)
        x0, g0 = x1, g1
        x1 = x2
        g1, system, z = _residual(x1, theta, gamma, res)
        size = abs(x1 - x0)
        if size <= tol * max(1.0, abs(x1)) or (size <= 1e-8 and size >= 0.25 * previous):
            return Eigensolution(system, theta, z, size)
        previous = size
    raise SolverError(f"the secant iteration in c did not converge for theta = {theta}, gamma = {gamma}")


@dataclass(frozen=True, slots=True, eq=False)
class GuidedSolution:
    """The last given-c solve of ``solve_given_theta_guided``, d theta / d xi there (the caller's, or the secant of
    the last two solves), and the step in xi = logit c it did not take (below STEP_TOLERANCE): the c of theta lies
    that far from the solution's."""

    solution: Eigensolution
    slope: float
    remaining_step: float


#: The guided iteration in logit c stops below this step (relative to max(1, |logit c|)): c would move by less than
#: 1e-12 (1 - c) relative, the size of the level's own discretisation error (the step not taken is reported and
#: enters the error estimate). The tables' c is good to 1e-13 ... 1e-9, so one solve is often enough.
STEP_TOLERANCE = 1e-12


def _logit_parts(xi: float) -> tuple[float, float]:
    """c and 1 - c of xi = log(c / (1 - c)), each without cancellation."""
    return 1.0 / (1.0 + math.exp(-xi)), 1.0 / (1.0 + math.exp(xi))


#: ``_at_theta`` carries z along Newton's tangent where theta and Newton's last step are both within this fraction of
#: the distance to pi/2 (z's theta-derivatives grow like powers of 1/(pi/2 - theta)): the second-order remainder is
#: then ~1e-16 of z, far below the rounding of a fresh solve.
TANGENT_REACH = 1e-8


def carried_along_tangent(z: np.ndarray, theta_from: float, theta: float, tangent: np.ndarray | None,
                          last_step: float) -> np.ndarray | None:
    """z, a root's coefficients at theta_from, moved to theta to first order along Newton's dz/dtheta (``tangent``),
    where the move and Newton's last step are both within ``TANGENT_REACH`` of the distance to pi/2 (the second-order
    remainder is then ~1e-16 of z); None where they are not (or there is no tangent): the caller solves at theta."""
    reach = TANGENT_REACH * (HALF_PI - theta)
    if tangent is None or abs(theta - theta_from) > reach or last_step > reach:
        return None
    return z + (theta - theta_from) * tangent


def _at_theta(sol: Eigensolution, theta: float) -> Eigensolution:
    """The solution on the same system at theta itself, where the friction it implies, tan(theta)/gamma, would
    differ from the one asked for by more than 1e-14 relative: d log mu / d theta = 1/(sin cos) is mu gamma near
    pi/2, so Newton's theta, within rounding of the root (~1e-16), missed mu by 6e-10 at mu gamma = 3600. The
    eigenvalue condition there is off by the last step in c (below rounding in mu's terms).

    z moves to theta to first order along Newton's dz/dtheta where the move is small (``TANGENT_REACH``), else by a
    new solve. The guided solves start Newton at theta itself, so where its first step was its last the move undoes
    that step and gives the LU's own solution at theta, a new solve without the LU. Measured over 78 given-mu solves
    (nu from -0.9 to 0.45, 1 - c from 1.0001 to 100 (1 - c_max)): the two ways give P*, p and q within 1.1e-10 of
    each other, as close as two new solves one unit in the last place of theta apart (1.2e-10: the rounding of the
    solve next to c_max). Given mu next to c_max, 4.5 -> 3.9 ms a solve (the LU of up to 450 unknowns saved)."""
    miss = abs(theta - sol.theta) / (math.sin(theta) * math.cos(theta)) if theta < HALF_PI else 0.0
    if miss <= 1e-14:
        return sol
    system = sol.system
    z = carried_along_tangent(sol.coefficients, sol.theta, theta, sol.tangent, sol.newton_step)
    if z is not None:
        return Eigensolution(system, theta, z, abs(theta - sol.theta), sol.tangent)
    z = EquilibratedLU(system.matrix(theta)).solve_refined(system.rhs)
    return Eigensolution(system, theta, z, abs(theta - sol.theta))


Solved = TypeVar("Solved")


def guided_steps(theta: float, c: float, gap: float, slope: float, solve: Callable[[float, float], Solved],
                 theta_of: Callable[[Solved], float], max_steps: int = 8,
                 theta_noise: float = 0.0) -> tuple[Solved, float, float]:
    """Given-c solves ``solve(c, gap)`` at xi_k = logit c_k, stepped by xi_{k+1} = xi_k + (theta - theta(xi_k)) / slope
    (slope = d theta / d xi, the caller's first, then from the last two solves) until the next step would be below
    STEP_TOLERANCE in xi, or the solve's theta is within ``theta_noise`` (absolute) of theta (a step smaller than
    the scatter of the given-c solve's theta moves c by noise), or once steps below 1e-8 stop shrinking (the small
    jumps of theta(xi) where the layout changes, of the size of the discretisation error). Returns the last solve,
    the slope and the step not taken. Raises SolverError if it does not settle."""
    xi = math.log(c) - math.log(gap)
    previous: tuple[float, float] | None = None
    last_step = math.inf
    for _ in range(max_steps):
        sol = solve(c, gap)
        found = theta_of(sol)
        if previous is not None and found != previous[1] and xi != previous[0]:
            slope = (found - previous[1]) / (xi - previous[0])
        step = (theta - found) / slope
        if (abs(step) <= STEP_TOLERANCE * max(1.0, abs(xi)) or abs(theta - found) <= theta_noise
                or (abs(step) <= 1e-8 and abs(step) >= 0.25 * last_step)):
            return sol, slope, abs(step)
        previous, last_step = (xi, found), abs(step)
        xi += step
        c, gap = _logit_parts(xi)
    raise SolverError(f"the stick radius for theta = {theta} did not settle from the guide (last step {step:.3g} in logit c)")


def solve_given_theta_guided(theta: float, gamma: float, c: float, gap: float, slope: float, res: Resolution,
                             max_steps: int = 8) -> GuidedSolution:
    """Stick radius for theta = atan(mu gamma) < pi/2 from a close guess c = 1 - gap and slope = d theta / d xi.

    ``guided_steps`` over given-c solves (Newton in theta at fixed c, the basis carrying alpha = theta / pi); the
    last solve is then taken at theta itself (``_at_theta``). Raises SolverError if it does not settle.
    """
    sol, slope, remaining = guided_steps(theta, c, gap, slope, lambda c, gap: solve_given_c(c, gap, gamma, theta, res),
                                         lambda sol: sol.theta, max_steps)
    return GuidedSolution(_at_theta(sol, theta), slope, remaining)
