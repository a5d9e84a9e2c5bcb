"""A table-free-of-solves first guess of the strip punch's friction for a given stick half-width (the Newton start).

The first-order law tan(theta) = gamma^2 K(c)/K'(c) (``asymptotics.plane``) is off by up to a factor 3 at
gamma = 1/2 near the largest stick width, where the true mu grows without bound. The ratio

    R(c, gamma) = gamma^2 cot(theta) / (K'(c)/K(c)),      theta = atan(mu gamma),

is smooth: 1 - O(gamma^2) as c -> 0 and falling to 0 at c_max. It is stored (``plane_guess_data``, written by
``derivations/build_plane_guess.py`` from level-1 solves) as a Chebyshev product in v = w_top / w, w = K'(c)/K(c)
(w -> inf as c -> 0, so v -> 0 like 1/log(1/c)) and gamma, for w >= w_top = w(c_top(gamma)),
c_top = 1 - 2 (1 - c_max) - 2e-3 with 1 - c_max from a fit (``gap_fit``). Outside (gamma below the table, c above c_top)
the guess is the first-order law's, or the approach to c_max. The table's accuracy is tested at held-out points
(``tests/test_plane_solver.py``): it is a starting point, not a result.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize, special

from asymptotics.plane import stick_width_first_order

from numeric.core import plane_guess_data as data

__all__ = ["gap_fit", "elliptic_ratio", "top_of_table", "ratio_nodes", "theta_guess", "stick_width_guess", "chebyshev_nodes"]


def gap_fit(gamma: float) -> float:
    """1 - c_max(gamma), roughly: 8 exp(-pi/(k eps)), eps = atanh(gamma)/pi, k = 1.87 + 0.97 gamma (a fit to the limit
    problem at nu = 0.1 ... -0.75, 3 % in 1 - c_max)."""
    eps = math.atanh(gamma) / math.pi
    return 8.0 * math.exp(-math.pi / ((1.87 + 0.97 * gamma) * eps))


def elliptic_ratio(c: float) -> float:
    """K'(c)/K(c) (modulus c), without the cancellation of 1 - c^2."""
    return float(special.ellipkm1(c * c) / special.ellipkm1((1.0 - c) * (1.0 + c)))


def top_of_table(gamma: float) -> float:
    """c_top = 1 - 2 (1 - c_max) - 2e-3 by ``gap_fit`` (smooth in gamma): the table stops there."""
    return 1.0 - 2.0 * gap_fit(gamma) - 2e-3


def chebyshev_nodes(n: int, lo: float, hi: float) -> np.ndarray:
    """n Chebyshev points of the first kind on [lo, hi]."""
    k = np.arange(n)
    return 0.5 * (lo + hi) + 0.5 * (hi - lo) * np.cos((2 * k + 1) * math.pi / (2 * n))


def ratio_nodes() -> tuple[np.ndarray, np.ndarray]:
    """The table's nodes: v (over [V_MIN, 1]) and gamma (over [GAMMA_MIN, GAMMA_MAX])."""
    return (chebyshev_nodes(data.N_V, data.V_MIN, 1.0), chebyshev_nodes(data.N_GAMMA, data.GAMMA_MIN, data.GAMMA_MAX))


def _barycentric(nodes: np.ndarray, x: float) -> np.ndarray:
    """Weights w_k with f(x) = sum_k w_k f(nodes_k) for the interpolant at Chebyshev points of the first kind."""
    n = nodes.size
    k = np.arange(n)
    bary = (-1.0) ** k * np.sin((2 * k + 1) * math.pi / (2 * n))
    diff = x - nodes
    if np.any(diff == 0.0):
        return (diff == 0.0).astype(float)
    terms = bary / diff
    return terms / terms.sum()


def theta_guess(c: float, gamma: float) -> float:
    """atan(mu gamma) for stick half-width c: the table's ratio where it reaches, else the first-order law."""
    w = elliptic_ratio(c)
    first_order = math.atan(gamma * gamma / w)
    if not data.GAMMA_MIN <= gamma <= data.GAMMA_MAX:
        return first_order
    c_top = top_of_table(gamma)
    if c > c_top:
        return first_order
    v = elliptic_ratio(c_top) / w
    if v < data.V_MIN:
        return first_order
    v_nodes, g_nodes = ratio_nodes()
    ratio = float(_barycentric(v_nodes, v) @ np.asarray(data.RATIO) @ _barycentric(g_nodes, gamma))
    return math.atan(gamma * gamma / (w * ratio))


def stick_width_guess(theta: float, gamma: float) -> float:
    """The c whose guessed theta (``theta_guess``) is theta, where the table reaches (a root on [c(V_MIN), c_top] by
    scipy's brentq), else the first-order law's inverse (theta functions, ``asymptotics.plane``)."""
    first_order = float(stick_width_first_order(math.tan(theta) / gamma, gamma))
    if not data.GAMMA_MIN <= gamma <= data.GAMMA_MAX:
        return first_order
    c_top = top_of_table(gamma)
    c_low = float(stick_width_first_order(data.V_MIN * 0.5 / elliptic_ratio(c_top), 0.5))  # w = w_top / V_MIN
    f_low, f_top = theta_guess(c_low, gamma) - theta, theta_guess(c_top, gamma) - theta
    if f_low * f_top > 0.0:
        return first_order
    return float(optimize.brentq(lambda c: theta_guess(c, gamma) - theta, c_low, c_top, xtol=1e-14, rtol=1e-12))
