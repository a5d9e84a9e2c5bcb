"""Abel integrals of piecewise-constant densities ([S75] §4, (4.3)-(4.4)).

For nodes 0 = t_0 < t_1 < ... < t_N = 1 and collocation points x_i, the integrals in
(2.2) of a density that is 1 on h_j = (t_{j-1}, t_j) and 0 elsewhere are

    A_ij = int_{h_j, t > x_i} t dt / sqrt(t^2 - x_i^2)
         = sqrt(t_j^2 - x_i^2) - sqrt(max(t_{j-1}, x_i)^2 - x_i^2)      (j >= i, else 0)
    B_ij = int_{h_j, t < x_i} t dt / sqrt(x_i^2 - t^2)
         = sqrt(x_i^2 - t_{j-1}^2) - sqrt(x_i^2 - min(t_j, x_i)^2)      (j <= i, else 0)

(errata item 4; the antiderivatives are -/+ sqrt(|t^2 - x^2|)). Each difference of
square roots is evaluated as (b - a)/(sqrt b + sqrt a), with t^2 - x^2 = (t - x)(t + x),
so tiny elements of a graded mesh lose no digits (reformulation.md).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import numpy as np

__all__ = ["upper_abel_weights", "lower_abel_weights"]


def _root_difference(hi_sq: np.ndarray, lo_sq: np.ndarray) -> np.ndarray:
    """sqrt(hi_sq) - sqrt(lo_sq) for 0 <= lo_sq <= hi_sq without cancellation."""
    denom = np.sqrt(hi_sq) + np.sqrt(lo_sq)
    return np.divide(hi_sq - lo_sq, denom, out=np.zeros_like(denom), where=denom > 0.0)


def upper_abel_weights(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Matrix A_ij = int over h_j of t dt / sqrt(t^2 - x_i^2), restricted to t > x_i (4.3)."""
    x_col = x[:, None]
    lo = np.maximum(nodes[None, :-1], x_col)
    hi = np.maximum(nodes[None, 1:], x_col)
    return _root_difference((hi - x_col) * (hi + x_col), (lo - x_col) * (lo + x_col))


def lower_abel_weights(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Matrix B_ij = int over h_j of t dt / sqrt(x_i^2 - t^2), restricted to t < x_i (4.3)."""
    x_col = x[:, None]
    lo = np.minimum(nodes[None, :-1], x_col)
    hi = np.minimum(nodes[None, 1:], x_col)
    return _root_difference((x_col - lo) * (x_col + lo), (x_col - hi) * (x_col + hi))
