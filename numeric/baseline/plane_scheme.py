"""The paper's piecewise-constant scheme for the strip punch ([S75] §5, "on identical lines" to §4) - the plane baseline.

Method (the two-dimensional counterpart of ``numeric.baseline.scheme``, kept independent of ``numeric.core``):

* p and q are constant on the intervals h_j = (t_(j-1), t_j) of a mesh of (0, 1) (``numeric.baseline.scheme.Mesh``;
  p even, q odd), c = t_M a node; in the slip intervals q_j = mu p_j.
* The surface relations are collocated at the midpoints in their integrated (logarithmic-potential) form, where
  a piecewise constant has exact integrals, F(u) = u log|u| - u:

      (N)  -(1/pi) int_{-1}^{1} p(t) log|x - t| dt + gamma int_0^x q dt = C      (every midpoint; C unknown:
           the indentation of a half-plane is not defined, only its gradient, H p + gamma q = 0)
      (T)  -(1/pi) int_{-1}^{1} q(t) log|x - t| dt - gamma int_0^x p dt = 0      (stick midpoints; odd, so no constant)
      (P)  int_{-1}^{1} p dt = 1,

  N + M + 1 equations for N values of p, M of q on the stick intervals and C.
* The eigenvalue, as in §4.1: q/(mu p) at the last three stick midpoints is extrapolated to x = c by the quadratic
  through them, mu* (mu) = mu (q/(mu p))(c), and mu* (mu) = mu is solved by a bracketing root finder (scipy's
  brentq, to 1e-12: the paper's regula falsi stopped at 1e-5) on the first fall through zero above the first-order
  law's mu on a grid of ratio 1.05.

Meshes: ``numeric.baseline.scheme.friction_mesh`` (widths h, halved within 0.08 of c: the paper's mesh at
h = 0.02), refined by halving h. The scheme is first order (p has |x - c|^(1/2 - alpha) and (1 - x)^(alpha - 1/2)
singularities); ``extrapolated_mu`` combines three meshes by Richardson extrapolation in h with the orders
measured from them (Aitken's estimate).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from asymptotics.materials import resolve_gamma
from asymptotics.plane import mu_over_gamma_plane

from numeric.baseline.scheme import Mesh, friction_mesh

__all__ = ["PlaneSchemeSolution", "plane_system", "plane_solve_at_mu", "plane_solve_friction", "PlaneExtrapolation",
           "extrapolated_mu"]


def _log_integral(a: np.ndarray, b: np.ndarray, x: np.ndarray) -> np.ndarray:
    """int_a^b log|x - t| dt = F(b - x) - F(a - x), F(u) = u log|u| - u (F(0) = 0)."""
    def F(u):
        au = np.abs(u)
        return np.where(au > 0.0, u * np.log(np.where(au > 0.0, au, 1.0)) - u, 0.0)
    return F(b[None, :] - x[:, None]) - F(a[None, :] - x[:, None])


def plane_system(mesh: Mesh, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Blocks of the integrated relations at the midpoints: E (log potential of the even extension of each
    interval), O (odd extension), J (int_0^x of each interval), w (widths)."""
    t, x = mesh.nodes, mesh.midpoints
    a, b = t[:-1], t[1:]
    right = _log_integral(a, b, x)
    left = _log_integral(-b, -a, x)
    J = np.clip(x[:, None] - a[None, :], 0.0, (b - a)[None, :])
    return right + left, right - left, J, b - a


@dataclass(frozen=True, slots=True)
class PlaneSchemeSolution:
    """p, q at the midpoints (q = mu p on the slip intervals), C, the extrapolated q/(mu p) at c and mu* = mu times it."""

    mesh: Mesh
    gamma: float
    mu: float
    p: np.ndarray
    q: np.ndarray
    constant: float
    ratio_at_c: float

    @property
    def mu_star(self) -> float:
        return self.mu * self.ratio_at_c


def plane_solve_at_mu(mesh: Mesh, mu: float, gamma: float) -> PlaneSchemeSolution:
    """The piecewise-constant solution for friction mu on ``mesh`` (c = its stick node)."""
    n, m = mesh.size, mesh.stick_index
    E, O, J, w = plane_system(mesh, gamma)
    size = n + m + 1
    slip = (np.arange(n) >= m)[None, :]
    D = np.zeros((size, size))  # unknowns p (n), q on the stick intervals (m), C; rows (N) n, (T) m, (P) 1
    D[:n, :n] = -E / math.pi + gamma * mu * J * slip  # (N), with q = mu p on the slip intervals in int_0^x q
    D[:n, n:n + m] = gamma * J[:, :m]
    D[:n, -1] = -1.0
    D[n:n + m, :n] = -gamma * J[:m, :] - (mu / math.pi) * O[:m, :] * slip  # (T), slip q = mu p in the potential
    D[n:n + m, n:n + m] = -O[:m, :m] / math.pi
    D[n + m, :n] = 2.0 * w  # (P)
    rhs = np.zeros(size)
    rhs[n + m] = 1.0
    z = np.linalg.solve(D, rhs)
    p = z[:n]
    q = np.empty(n)
    q[:m] = z[n:n + m]
    q[m:] = mu * p[m:]
    xs = mesh.midpoints[m - 3:m]
    ratio = float(np.polyval(np.polyfit(xs, q[m - 3:m] / (mu * p[m - 3:m]), 2), mesh.c))  # §4.1's extrapolation
    return PlaneSchemeSolution(mesh, gamma, mu, p, q, float(z[-1]), ratio)


def plane_solve_friction(c: float, nu: float | None = None, *, gamma: float | None = None, h: float = 0.02,
                         tol: float = 1e-12, start: float | None = None) -> PlaneSchemeSolution:
    """mu for stick half-width c on the friction mesh of width h: the root of mu*(mu) - mu (scipy brentq), the first
    fall through zero on a grid of ratio 1.05 from 0.6 times the first-order law's mu, or from 0.98 ``start`` (a
    coarser mesh's root)."""
    g = resolve_gamma(nu, gamma)
    mesh = friction_mesh(c, h)
    guess = g * float(mu_over_gamma_plane(c)) if start is None else start

    def excess(mu: float) -> float:
        return plane_solve_at_mu(mesh, mu, g).ratio_at_c - 1.0

    # the first fall of mu*(mu) - mu through zero above the first-order value (friction raises mu above it), on a grid
    # of ratio 1.05: the extrapolated q/(mu p) also has poles (p at a last stick midpoint through 0) and rises again
    # past the root at fine meshes, so a bracket found by expanding outward can hold the wrong root
    grid = guess * (1.05 ** np.arange(-10, 120) if start is None else 0.98 * 1.05 ** np.arange(0, 120))
    values = [excess(grid[0])]
    for k in range(1, grid.size):
        values.append(excess(grid[k]))
        if values[-2] > 0.0 > values[-1] and values[-2] - values[-1] < 20.0:  # a fall, not a pole
            lo, hi = grid[k - 1], grid[k]
            break
    else:
        raise RuntimeError(f"no bracket of mu*(mu) = mu found for c = {c}, gamma = {g}")
    mu = optimize.brentq(excess, lo, hi, xtol=tol * guess, rtol=1e-15)
    return plane_solve_at_mu(mesh, mu, g)


@dataclass(frozen=True, slots=True)
class PlaneExtrapolation:
    """mu on meshes h, h/2, h/4, the observed order log2 of the ratio of successive differences, and the
    Richardson-extrapolated mu with that order (Aitken); ``error`` is the last correction's size."""

    h: float
    mu: tuple[float, float, float]
    order: float
    extrapolated: float
    error: float


def extrapolated_mu(c: float, nu: float | None = None, *, gamma: float | None = None, h: float = 0.02
                    ) -> PlaneExtrapolation:
    """Aitken/Richardson extrapolation of the scheme's mu from the friction meshes of widths h, h/2, h/4."""
    values: list[float] = []
    for k in range(3):
        values.append(plane_solve_friction(c, nu, gamma=gamma, h=h / 2**k, start=values[-1] if values else None).mu)
    d1, d2 = values[1] - values[0], values[2] - values[1]
    order = math.log2(d1 / d2) if d1 * d2 > 0.0 else math.nan
    correction = d2 / (2.0**order - 1.0) if math.isfinite(order) else math.nan
    return PlaneExtrapolation(h, tuple(values), order, values[2] + correction, abs(correction))
