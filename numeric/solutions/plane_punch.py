"""The strip punch and power-law profiles in plane strain with friction: solutions, limits, API.

``strip_punch`` (one of mu, c), ``plane_power_law`` (|x|^n, the cylinder n = 2),
``plane_stick_width`` and ``plane_friction_coefficient``: the singular-basis solver of
``numeric.core.plane_system`` at two levels (their difference is ``error``), or the closed
forms of ``asymptotics.plane`` in the limits mu = 0 (Sadowsky, Hertz) and c = 1 (Abramov).

Dimensionless fields (``asymptotics.plane``): x = X/a, p = sigma_zz a/P, q = sigma_xz a/P
(the traction on the half-plane, + outward for x > 0), int_{-1}^{1} p = 1; the slip
u(x) = u_x G / ((1 - nu) P), negative (inward) for c < x < 1.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import scalar_or_array
from asymptotics.materials import check_c, check_mu, check_n, check_x, resolve_gamma
from asymptotics.plane import (bonded_traction, mu_over_gamma_plane, pressure_sadowsky,
                               stick_width_first_order)
from numeric.core.errors import NoEigenvalueError
from numeric.core.plane_system import (PLANE_RESOLUTIONS, PlaneSolution, legendre_block_values,
                                       solve_plane_given_c, solve_plane_given_mu, transforms_at)
from numeric.core.quadrature import tanh_sinh01

__all__ = ["StripPunchSolution", "PlanePowerLawSolution", "strip_punch", "plane_power_law", "plane_stick_width",
           "plane_friction_coefficient", "DEFAULT_LEVEL"]

DEFAULT_LEVEL = 2
"""Resolution level of the answer; the level below gives the error estimate."""


class _Field:
    """p, q, slip of a discrete ``PlaneSolution``."""

    def __init__(self, solution: PlaneSolution) -> None:
        self.solution = solution
        self.system = solution.system
        self.parts = self.system.split(solution.coefficients)

    def _values(self, x: np.ndarray, field_name: str) -> np.ndarray:
        return legendre_block_values(self.system, x, field_name) @ self.parts[field_name]

    def pq(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ax = np.abs(x)
        c = self.system.layout.c
        stick = ax <= c  # x = c: the stick end's value (p, q are continuous there)
        p, q = np.empty(ax.shape), np.empty(ax.shape)
        p[stick] = self._values(ax[stick], "P")
        q[stick] = self._values(ax[stick], "Q")
        p[~stick] = self._values(ax[~stick], "p")
        q[~stick] = self.system.mu * p[~stick]  # (S): q = mu p on the slip zone, to the last bit
        return p, np.sign(x) * q

    def tangential_strain(self, x: np.ndarray) -> np.ndarray:
        """H q - gamma p at points of the slip zone (du_x/dx over (1 - nu) P / (G a))."""
        sys = self.system
        Ho = {f: transforms_at(sys, x, f)[1] for f in ("Q", "p")}
        p = self._values(x, "p")
        return Ho["Q"] @ self.parts["Q"] + sys.mu * (Ho["p"] @ self.parts["p"]) - sys.gamma * p

    def slip(self, x: np.ndarray) -> np.ndarray:
        """u(x) = int_c^|x| (H q - gamma p) dt, odd in x, 0 on the stick zone (tanh-sinh rule per point)."""
        ax = np.abs(x)
        c = self.system.layout.c
        out = np.zeros(ax.shape)
        outer = ax > c
        if np.any(outer):
            nodes, weights = tanh_sinh01()
            xs = ax[outer]
            t = c + (xs[:, None] - c) * nodes[None, :]
            t = np.where(np.isin(t, self.system.layout_ends), np.nextafter(t, 2.0), t)  # H is log-singular at element ends
            strain = self.tangential_strain(t.ravel()).reshape(t.shape)
            out[outer] = (strain * weights[None, :]).sum(axis=1) * (xs - c)
        return np.sign(x) * out


@dataclass(frozen=True, slots=True)
class StripPunchSolution:
    """A rigid flat strip punch, half-width a, pressed into an elastic half-plane with Coulomb friction.

    Attributes
    ----------
    gamma, mu, c : float
        Coupling constant, friction coefficient (inf: bonded), stick half-width over a.
    nu : float or None
        Poisson's ratio when given.
    error : float
        Estimated absolute error of mu (given c) or c (given mu): the difference from the level below.
    route : str
        "frictionless (Sadowsky)", "bonded (Abramov)" or "solver level k, n unknowns".
    """

    gamma: float
    mu: float
    c: float
    nu: float | None
    error: float
    route: str
    _field: object = field(repr=False, compare=False)

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """p(x) = sigma_zz a / P, -1 < x < 1 (even)."""
        return scalar_or_array(self._pq(x)[0])

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """q(x) = sigma_xz a / P on the half-plane, + outward (odd)."""
        return scalar_or_array(self._pq(x)[1])

    def slip(self, x: ArrayLike) -> np.ndarray | float:
        """u(x) = u_x G / ((1 - nu) P): 0 on |x| <= c, inward (sign opposite to x) on the slip zones."""
        x_arr = _points(x)
        if isinstance(self._field, _Field):
            return scalar_or_array(self._field.slip(x_arr))
        return scalar_or_array(np.zeros(x_arr.shape) if self.mu == math.inf else np.full(x_arr.shape, np.nan))

    def _pq(self, x: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        x_arr = _points(x)
        if isinstance(self._field, _Field):
            return self._field.pq(x_arr)
        if self.mu == 0.0:
            return np.asarray(pressure_sadowsky(x_arr), dtype=float), np.zeros(x_arr.shape)
        w = np.asarray(bonded_traction(x_arr, self.gamma))
        return w.real, w.imag


def _points(x: ArrayLike) -> np.ndarray:
    """x over the half-width: -1 <= x <= 1 (ValueError naming x otherwise)."""
    raw = np.asarray(x) if x is not None else None
    if raw is None or raw.dtype.kind not in "biuf":
        raise TypeError(f"x must be a real number or an array of real numbers, got {x!r}")
    check_x(np.abs(raw))
    return raw.astype(float)


def _solve_level(gamma: float, mu: float | None, c: float | None, level: int, guess: float) -> PlaneSolution:
    res = PLANE_RESOLUTIONS[level]
    if c is not None:
        return solve_plane_given_c(c, gamma, guess, res)
    return solve_plane_given_mu(mu, gamma, guess, res)


def strip_punch(*, nu: float | None = None, gamma: float | None = None, mu: float | None = None,
                c: float | None = None, level: int = DEFAULT_LEVEL) -> StripPunchSolution:
    """The flat strip punch with friction: give exactly one of ``mu`` and ``c``, and ``nu`` or ``gamma``.

    mu = 0 is Sadowsky's frictionless punch, mu = inf or c = 1 Abramov's bonded one (closed forms);
    otherwise the singular-basis solver at ``level`` (0-3), with the level below as error estimate.

    Examples
    --------
    >>> s = strip_punch(nu=0.3, c=0.5)
    >>> round(s.mu, 8), s.error < 1e-8
    (0.2374026, True)
    """
    g = resolve_gamma(nu, gamma)
    if (mu is None) == (c is None):
        raise ValueError("give exactly one of mu (friction coefficient) or c (stick half-width / a)")
    if not isinstance(level, int) or not 1 <= level < len(PLANE_RESOLUTIONS):
        raise ValueError(f"level must be an integer from 1 to {len(PLANE_RESOLUTIONS) - 1}, got {level!r}")
    if c is not None:
        c = float(check_c(c))
        if c == 1.0:
            return StripPunchSolution(g, math.inf, 1.0, nu, 0.0, "bonded (Abramov)", None)
        if g == 0.0:
            raise NoEigenvalueError("gamma = 0: shear and pressure decouple and every mu > 0 gives c = 1")
        guess = g * float(mu_over_gamma_plane(c))
        coarse = _solve_level(g, None, c, level - 1, guess)
        fine = _solve_level(g, None, c, level, coarse.mu)
        return StripPunchSolution(g, fine.mu, c, nu, abs(fine.mu - coarse.mu),
                                  f"solver level {level}, {fine.system.n_unknowns} unknowns", _Field(fine))
    mu = float(check_mu(mu))
    if mu == 0.0:
        return StripPunchSolution(g, 0.0, 0.0, nu, 0.0, "frictionless (Sadowsky)", None)
    if mu == math.inf:
        return StripPunchSolution(g, math.inf, 1.0, nu, 0.0, "bonded (Abramov)", None)
    if g == 0.0:
        return StripPunchSolution(g, mu, 1.0, nu, 0.0, "bonded (Abramov)", None)
    guess = min(max(float(stick_width_first_order(mu, g)), 1e-3), 0.99)
    coarse = _solve_level(g, mu, None, level - 1, guess)
    fine = _solve_level(g, mu, None, level, coarse.c)
    return StripPunchSolution(g, mu, fine.c, nu, abs(fine.c - coarse.c),
                              f"solver level {level}, {fine.system.n_unknowns} unknowns", _Field(fine))


@dataclass(frozen=True, slots=True)
class PlanePowerLawSolution:
    """A profile z = |X|^n / (n b^(n-1)) (the cylinder: n = 2, b = R), the flat-punch solution transformed by (3.13).

    ``load_ratio`` is P over the frictionless P at the same a (Hertz: P = pi a^2 E*/(4 R) for n = 2).
    """

    n: float
    flat: StripPunchSolution
    _rule: tuple = field(repr=False, compare=False)

    @property
    def c(self) -> float:
        return self.flat.c

    @property
    def mu(self) -> float:
        return self.flat.mu

    def _transform(self, x: ArrayLike, shear: bool) -> np.ndarray:
        x_arr = _points(x)
        ax = np.atleast_1d(np.abs(x_arr))
        nodes, weights = self._rule
        t = ax[:, None] + (1.0 - ax[:, None]) * nodes[None, :]
        inside = t < 1.0  # nodes that round onto the edge carry no weight worth keeping
        f = np.zeros(t.shape)
        flat = self.flat.shear if shear else self.flat.pressure
        f[inside] = np.asarray(flat(t[inside])) * t[inside] ** (-self.n)
        out = np.zeros(ax.shape)
        pos = ax > 0.0
        out[pos] = self.n * ax[pos] ** (self.n - 1.0) * (f[pos] @ weights) * (1.0 - ax[pos])  # (3.13)
        if not shear and self.n > 1.0:
            out[~pos] = self.n / (self.n - 1.0) * float(self.flat.pressure(0.0))  # (3.18): the limit x -> 0
        out = out.reshape(np.shape(x_arr))
        return np.sign(x_arr) * out if shear else out

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """p(x) = n x^(n-1) int_x^1 t^-n p0(t) dt ([S75] (3.13) in the plane), int p = 1."""
        return scalar_or_array(self._transform(x, False))

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """q(x) = n x^(n-1) int_x^1 t^-n q0(t) dt."""
        return scalar_or_array(self._transform(x, True))

    @property
    def load_ratio(self) -> float:
        """P(a) with friction over P(a) without (n = 2: over Hertz's pi a^2 E*/(4 R))."""
        return load_ratio(self.flat, self.n, self._rule)


def load_ratio(flat: StripPunchSolution, n: float, rule) -> float:
    """P / P_frictionless at the same contact width for the profile |X|^n.

    The increments are flat punches of the current width b, whose slope outside |x| < 1 is
    s0(y) = H p0(y) (q0 = 0 there), so du_z/dX = -(|X|/b)^(n-1)... gives
    P = k a^n / n with k int_1^inf s0(y) y^-n dy = -(G/(1 - nu)) / b^(n-1); the ratio is
    S_frictionless / S with S = int_0^1 p0(t) W_n(t) dt, W_n(t) = int_1^inf (y^-n/(y - t) + y^-n/(y + t)) dy.
    """
    nodes, weights = rule
    t = nodes
    p0 = np.asarray(flat.pressure(t))
    w = _weight(n, t)
    ours = float((p0 * w * weights).sum())
    frictionless = float((np.asarray(pressure_sadowsky(t)) * w * weights).sum())
    return frictionless / ours


def _weight(n: float, t: np.ndarray) -> np.ndarray:
    """W_n(t) = int_1^inf y^-n (1/(y - t) + 1/(y + t)) dy, by a Gauss-Laguerre-free substitution y = 1/v."""
    nodes, weights = tanh_sinh01()
    v = nodes[None, :]
    integrand = v ** (n - 1.0) * (1.0 / (1.0 - t[:, None] * v) + 1.0 / (1.0 + t[:, None] * v))
    return (integrand * weights[None, :]).sum(axis=1)


def plane_power_law(n: float, *, nu: float | None = None, gamma: float | None = None, mu: float | None = None,
                    c: float | None = None, level: int = DEFAULT_LEVEL) -> PlanePowerLawSolution:
    """Power-law profile |X|^n (n = 2: the cylinder) with friction: the same c as the strip punch.

    >>> h = plane_power_law(2, nu=0.3, c=0.5)
    >>> round(float(h.pressure(0.0)), 6) > round(2 / 3.141592653589793, 6)   # friction raises p(0)
    True
    """
    n = check_n(n)
    return PlanePowerLawSolution(n, strip_punch(nu=nu, gamma=gamma, mu=mu, c=c, level=level), tanh_sinh01())


def plane_stick_width(mu: ArrayLike, nu: float | None = None, *, gamma: float | None = None,
                      level: int = DEFAULT_LEVEL) -> np.ndarray | float:
    """c(mu, nu) of the strip punch (and of every power law), elementwise."""
    mu_arr = np.asarray(check_mu(mu), dtype=float)
    out = np.array([strip_punch(nu=nu, gamma=gamma, mu=float(m), level=level).c for m in mu_arr.ravel()])
    return scalar_or_array(out.reshape(mu_arr.shape))


def plane_friction_coefficient(c: ArrayLike, nu: float | None = None, *, gamma: float | None = None,
                               level: int = DEFAULT_LEVEL) -> np.ndarray | float:
    """mu(c, nu) of the strip punch, elementwise."""
    c_arr = np.asarray(check_c(c), dtype=float)
    out = np.array([strip_punch(nu=nu, gamma=gamma, c=float(v), level=level).mu for v in c_arr.ravel()])
    return scalar_or_array(out.reshape(c_arr.shape))
