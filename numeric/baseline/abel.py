"""Abel integrals of piecewise-constant densities ([S75] §4, (4.3)-(4.4)).

For nodes 0 = t_0 < t_1 < ... < t_N = 1 and collocation points x_i, the integrals in
(2.2) of a density that is 1 on h_j = (t_{j-1}, t_j) and 0 elsewhere are

    A_ij = int_{h_j, t > x_i} t dt / sqrt(t^2 - x_i^2)
         = sqrt(t_j^2 - x_i^2) - sqrt(max(t_{j-1}, x_i)^2 - x_i^2)      (j >= i, else 0)
    B_ij = int_{h_j, t < x_i} t dt / sqrt(x_i^2 - t^2)
         = sqrt(x_i^2 - t_{j-1}^2) - sqrt(x_i^2 - min(t_j, x_i)^2)      (j <= i, else 0)

(errata item 4; the antiderivatives are +/- sqrt(|t^2 - x^2|)). Each difference of
square roots is evaluated as (hi - lo)(hi + lo)/(sqrt|hi^2 - x^2| + sqrt|lo^2 - x^2|), the
radicands as (t - x)(t + x), so tiny elements of a graded mesh lose no digits.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import numpy as np

__all__ = ["upper_abel_weights", "lower_abel_weights"]


def _root_difference(lo: np.ndarray, hi: np.ndarray, x: np.ndarray, sign: float) -> np.ndarray:
    """sqrt(sign (hi^2 - x^2)) - sqrt(sign (lo^2 - x^2)) up to the overall sign, free of cancellation.

    The difference of the radicands is (hi - lo)(hi + lo) for both kernels; each radicand
    is formed as a product (t - x)(t + x). With sign = +1 this is the A weight (t >= x),
    with sign = -1 the B weight (t <= x), both returned non-negative.
    """
    root_hi = np.sqrt(sign * (hi - x) * (hi + x))
    root_lo = np.sqrt(sign * (lo - x) * (lo + x))
    denom = root_hi + root_lo
    numer = (hi - lo) * (hi + lo)
    return np.divide(numer, denom, out=np.zeros_like(denom), where=denom > 0.0)


def upper_abel_weights(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Matrix A_ij = int over h_j of t dt / sqrt(t^2 - x_i^2), restricted to t > x_i (4.3)."""
    x_col = x[:, None]
    lo = np.maximum(nodes[None, :-1], x_col)
    hi = np.maximum(nodes[None, 1:], x_col)
    return _root_difference(lo, hi, x_col, 1.0)


def lower_abel_weights(nodes: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Matrix B_ij = int over h_j of t dt / sqrt(x_i^2 - t^2), restricted to t < x_i (4.3)."""
    x_col = x[:, None]
    lo = np.minimum(nodes[None, :-1], x_col)
    hi = np.minimum(nodes[None, 1:], x_col)
    return _root_difference(lo, hi, x_col, -1.0)
