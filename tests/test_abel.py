"""Exact Abel weights of piecewise-constant densities (4.3), errata item 4."""

import mpmath
import numpy as np

from numeric.baseline.abel import lower_abel_weights, upper_abel_weights


def _reference(nodes, x):
    """A_ij, B_ij by tanh-sinh quadrature of the kernels of (2.2) at 40 digits."""
    n = len(nodes) - 1
    A = np.zeros((len(x), n))
    B = np.zeros((len(x), n))
    with mpmath.workdps(40):
        for i, xi in enumerate(map(mpmath.mpf, x)):
            for j in range(n):
                a, b = mpmath.mpf(nodes[j]), mpmath.mpf(nodes[j + 1])
                if b > xi:
                    lo = max(a, xi)
                    # t = lo + s^2 removes the inverse square root at t = x
                    A[i, j] = mpmath.quad(
                        lambda s: 2 * s * (lo + s * s) / mpmath.sqrt((lo - xi + s * s) * (lo + xi + s * s)),
                        [0, mpmath.sqrt(b - lo)])
                if a < xi:
                    hi = min(b, xi)
                    B[i, j] = mpmath.quad(
                        lambda s: 2 * s * (hi - s * s) / mpmath.sqrt((xi - hi + s * s) * (xi + hi - s * s)),
                        [0, mpmath.sqrt(hi - a)])
    return A, B


def test_weights_against_quadrature_on_a_graded_mesh():
    # Elements down to 1e-12 next to x = 1 and to 1e-9 around an interior point: the
    # cancellation-free differences must keep ~1e-15 relative accuracy (rounding only).
    nodes = np.array([0.0, 0.1, 0.3, 0.5 - 1e-9, 0.5, 0.5 + 1e-9, 0.7, 1 - 1e-6, 1 - 1e-12, 1.0])
    x = 0.5 * (nodes[1:] + nodes[:-1])
    A_ref, B_ref = _reference(nodes, x)
    A, B = upper_abel_weights(nodes, x), lower_abel_weights(nodes, x)
    scale = np.maximum(np.abs(A_ref), 1e-300)
    assert np.max(np.abs(A - A_ref) / scale) < 1e-13
    scale = np.maximum(np.abs(B_ref), 1e-300)
    assert np.max(np.abs(B - B_ref) / scale) < 1e-13
    # triangular structure stated after (4.3): A_ij = 0 for j < i, B_ij = 0 for j > i
    assert np.all(np.tril(A, -1) == 0) and np.all(np.triu(B, 1) == 0)


def test_weights_sum_to_the_whole_abel_integral():
    # Summing over j integrates a constant density: int_x^1 t dt / sqrt(t^2 - x^2) = sqrt(1 - x^2)
    # and int_0^x t dt / sqrt(x^2 - t^2) = x. Exact closed forms, so only rounding (1e-14) remains.
    nodes = np.linspace(0.0, 1.0, 41) ** 0.7
    x = np.array([0.05, 0.33, 0.61, 0.97])
    assert np.allclose(upper_abel_weights(nodes, x).sum(axis=1), np.sqrt(1 - x**2), rtol=0, atol=1e-14)
    assert np.allclose(lower_abel_weights(nodes, x).sum(axis=1), x, rtol=0, atol=1e-14)
