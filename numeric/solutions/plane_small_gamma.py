"""The strip punch as nu -> 1/2 (gamma -> 0): mu/gamma as a series in gamma^2 through solves at larger gamma, for the
law below the solver's smallest stick width (``numeric.solutions.plane_law``), and what the routes do next to c = 1.

At fixed c, mu/gamma, p, q/gamma and u/gamma are even in gamma and analytic in gamma^2 (mu, q and u are odd in
gamma), mu/gamma with the first-order law as its limit:

    mu/gamma = F0(c) + gamma^2 r(c, gamma),   F0 = K(c)/K'(c) (``asymptotics.plane.mu_over_gamma_plane``),
    r = F1(c) + F2(c) gamma^2 + F3(c) gamma^4 + ...

(measured: r at c = 0.5 is 0.55013, 0.55031, 0.55101, 0.55384 at gamma = 0.01, 0.02, 0.04, 0.08, its changes growing
fourfold per doubling of gamma). ``gamma_series`` interpolates r in gamma^2 (degree 5) through the solver's r at the
six ``NODES`` (gamma = 0.06 ... 0.16) and extrapolates it to gamma: r without the cancellation of mu/mu_1 - 1, which
the law's fit needs at tiny gamma (there mu/mu_1 - 1 ~ gamma^2 r is below the solver's rounding). Measured at
c = 0.05, 0.3, 0.5, 0.9, 0.97, 0.99 (level 2 nodes): the series and the same through ``CHECK_NODES`` differ by
6e-15 ... 1e-12 (relative, in mu) at gamma = 0.002, 1e-12 ... 9e-11 at 0.02.

Until the solver's system was balanced (``numeric.core.plane_operators.plane_collocation_system``) this series was
also the route for mu and the stresses below gamma = 0.02 (nu > 0.4898): the plain system's theta carried an absolute
rounding and its stick shear a near-null mode, so that mu's relative error grew like 1/gamma^2 and q/(mu p) reached
1.1e4 at gamma = 1e-8. Balanced, the solver at gamma itself is the better route (at c = 0.05, gamma = 1e-3 ... 1e-8
the series' p and q/gamma were 2e-9 and 8e-9 off level 4 at x = c, the solver's level 2 1e-9 and 2e-9 at 1e-3 and
1e-12 at 1e-8), and the series serves the law and the tests as an independent route.

Next to c = 1 (1 - c < ``SERIES_GAP_MIN``) at gamma < ``SMALL_GAMMA`` the routes (``numeric.solutions.plane_punch``)
take the solver at gamma itself with its stresses (a solve costs 0.1 ... 2 s there), or the first-order law for mu and
c: below ``numeric.solutions.plane_solver.FIRST_ORDER_GAMMA`` (3e-5; its docstring), and wherever the caller's rtol is
met by its bound; the stresses then come from a given-c solve at c, formed when first read
(``numeric.solutions.solution.Deferred``). Measured with the system as it is now (balanced below alpha = 1/4, the stick
pressure pinned from alpha = 0.04), levels 2 and 3 against level 4 at gamma = 1.7e-4, 3e-4, 5e-4, 1e-3 and 1 - c =
1e-9, 1e-10, 1e-12, 1e-14 (16 cases; x = 0, 0.3, 0.6, 0.9, 0.99, 1 - 1e-6, next to c on either side, c, and three
points across the slip zones): mu within 4.5e-12, q within 5.9e-12 of max(1, |p|) (6e-11 of its own largest value),
the slip within 1e-8 of its own value (which is 1e-10 ... 1e-30: the zones are 1e-9 ... 1e-14 wide), p within 1.0e-9
of max(1, |p|) inside the slip zones, where p ~ (1 - x)^(alpha - 1/2) is largest (level 2: 8.7e-10), and 1.5e-13
elsewhere; at gamma = 3e-5, 5e-5, 1e-4, 1.5e-4 (1 - c down to 1e-16 for mu, 1e-14 for the stresses, 20 cases) the
solver's mu within 3.1e-11, p within 8.6e-10 and q within 9.4e-13 of max(1, |p|). Below, at gamma = 1e-5, 3e-6, 1e-6,
1e-7, 1e-8, 1e-10, 1e-16, 1e-30, 1e-100 and 1 - c = 1e-9, 1e-12, 1e-14 (27 cases, the same points), the solver's mu
is not kept (r = (mu/mu_1 - 1)/gamma^2 of levels 2-4 scatters by ~3 at gamma = 1e-5 and from -2400 to 12000 at
1e-6: its rounding over gamma^2) but its stresses are: level 2 within 7.8e-10 of level 4 in p and 9.8e-12 in q, of
max(1, |p|); and away from the slip zones they are the bonded punch's (Abramov's closed form, ``asymptotics.plane``)
to the slip zones' influence: at x = 0.3 ... 1 - 1e-6, 1 - c = 1e-9, p within 4.2e-10 and q within 1.6e-7 of
max(1, |p|) at gamma = 1e-3, within 8e-15 and 1.6e-10 at gamma = 1e-6 (q's difference ~ gamma (1 - c)/(1 - x)).
(The first measurement, before the pins and the balance's present form, had q/gamma up to 7e-8 and mu 1e-8 off at
gamma = 2e-4 ... 5e-4, and the stresses were not given below gamma = 1e-3; until this measurement they were not
given below gamma = 3e-5.)

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

from numeric.core.plane_guess import elliptic_ratio
from numeric.solutions.plane_solver import solve_given_c

__all__ = ["SMALL_GAMMA", "NODES", "SERIES_GAP_MIN", "GammaSeries",
           "node_friction", "gamma_series"]

#: Below this gamma (nu > 0.4898) the law takes r from the series (``numeric.solutions.plane_law``), and next to c = 1
#: (``SERIES_GAP_MIN``) the routes hand over as the module docstring says.
SMALL_GAMMA = 0.02
#: gamma of the solver solves the series goes through.
NODES = (0.06, 0.08, 0.1, 0.12, 0.14, 0.16)
#: Below this 1 - c (at gamma < SMALL_GAMMA) the routes' near-one handling; the series is not formed there.
SERIES_GAP_MIN = 1e-8


@lru_cache(maxsize=32)
def node_friction(c: float, gap: float, level: int, nodes: tuple[float, ...]) -> tuple[float, ...]:
    """The solver's mu for stick half-width c = 1 - gap at each gamma of ``nodes`` (kept per c, level and nodes).
    ValueError for 1 - c below ``SERIES_GAP_MIN``."""
    if not gap >= SERIES_GAP_MIN:
        raise ValueError(f"1 - c = {gap!r} is below {SERIES_GAP_MIN:g}: the small-gamma series is not formed there")
    return tuple(solve_given_c(c, gap, g, level).field.mu for g in nodes)


@dataclass(frozen=True, slots=True)
class GammaSeries:
    """mu/gamma = first_order + gamma^2 r(gamma), r = sum_k coefficients[k] gamma^(2k), at one c (``gamma_series``);
    first_order = F0(c) = K(c)/K'(c)."""

    c: float
    first_order: float
    coefficients: tuple[float, ...]

    def correction(self, gamma: float) -> float:
        """r(gamma) = (mu/gamma - F0)/gamma^2."""
        return float(np.polynomial.polynomial.polyval(gamma * gamma, self.coefficients))

    def mu_over_gamma(self, gamma: float) -> float:
        return self.first_order + gamma * gamma * self.correction(gamma)


def gamma_series(c: float, gap: float, level: int, nodes: tuple[float, ...] = NODES) -> GammaSeries:
    """The series through the solver's r = (mu/gamma - F0)/gamma^2 at ``nodes`` (``node_friction``)."""
    f0 = 1.0 / elliptic_ratio(c, gap)
    t = np.array([g * g for g in nodes])
    r = np.array([(mu / g - f0) / (g * g) for g, mu in zip(nodes, node_friction(c, gap, level, nodes))])
    return GammaSeries(c, f0, tuple(float(v) for v in np.linalg.solve(np.vander(t, t.size, increasing=True), r)))
