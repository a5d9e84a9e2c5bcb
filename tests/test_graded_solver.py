"""The hp-graded solver (``numeric.core.graded_*``): the independent discretisation.

The singular-basis solver behind ``numeric.flat_punch`` is checked against this one; these tests
check the graded solver itself against closed forms (App. B, (4.10)) and its own convergence.
They are the tests the graded solver had when it was the public one.
"""


import mpmath
import numpy as np
import pytest

from asymptotics.adhesive import pressure_adhesive_mp, shear_adhesive_mp
from numeric.core.graded_collocation import solve_adhesive
from numeric.core.graded_eigen import solve_mu
from numeric.core.graded_mesh import LEVELS


def _gamma(nu: float) -> float:
    return (1.0 - 2.0 * nu) / (2.0 - 2.0 * nu)


def _adhesive_exact(gamma: float) -> tuple[float, float, float]:
    """P* (B4), p0(0) and lim q0/x (4.10) of the adhesive punch, in mpmath at 30 digits."""
    with mpmath.workdps(30):
        g = mpmath.mpf(gamma)
        kappa = 2 * mpmath.atanh(g) / mpmath.pi
        p0 = kappa / g * mpmath.cosh(mpmath.pi * kappa / 2)
        return float(mpmath.atanh(g) / g), float(p0), float(kappa * p0 / 2)


ADHESIVE_GAMMAS = [0.5, 1 / 3, 0.74]  # nu = 0, 1/4, -0.92


@pytest.mark.parametrize("level", [3, 4])
@pytest.mark.parametrize("gamma", ADHESIVE_GAMMAS)
def test_adhesive_solver_against_closed_forms(gamma, level):
    # The solver's own c = 1 mesh (not the closed form): P* (B4) and p(0) (4.10) from
    # mpmath. 1e-11 is the accuracy levels 3-4 are meant to reach; measured worst 7.3e-12
    # (p(0), gamma = .74, level 3), otherwise <= 1.8e-12.
    field = solve_adhesive(gamma, LEVELS[level])
    compliance, p0, _ = _adhesive_exact(gamma)
    assert abs(field.compliance - compliance) < 1e-11
    assert abs(field.pressure(np.array([0.0]))[0] - p0) < 1e-11
    # the whole profile against (B3) by mpmath quadrature, same 1e-11 relative budget
    # (measured worst 1.4e-12, q at x = .3, gamma = .5, level 3).
    x = np.array([0.3, 0.7, 0.95, 0.999])
    np.testing.assert_allclose(field.pressure(x), [float(pressure_adhesive_mp(v, gamma)) for v in x], rtol=1e-11)
    np.testing.assert_allclose(field.shear(x), [float(shear_adhesive_mp(v, gamma)) for v in x], rtol=1e-11)


@pytest.mark.parametrize(
    "gamma, level",
    [
        (0.5, 3),
        (0.5, 4),
        (1 / 3, 3),
        (1 / 3, 4),
        (0.74, 3),
        (0.74, 4),
    ],
)
def test_adhesive_solver_shear_slope(gamma, level):
    # q'(0) = kappa p0(0)/2 (4.10) from mpmath, read as q(x)/x at x = 1e-7 (q = x Q(x^2),
    # so the O(x^2) correction is 1e-14 relative). Target 1e-11 absolute. The first
    # adhesive meshes missed it (1.8e-11 at gamma = 1/3, 1.4e-10 at .74, level 3); with
    # degree 32 (level 3) and 36 (level 4) P*, p(0), q'(0) measure <= 3.1e-12 for gamma
    # in {.1, 1/3, .5, 2/3, .74}.
    field = solve_adhesive(gamma, LEVELS[level])
    q_slope = _adhesive_exact(gamma)[2]
    assert abs(field.shear(np.array([1e-7]))[0] / 1e-7 - q_slope) < 1e-11



ROUNDING = 1e-13  # ~100 eps of quantities of order 1-10: differences below this are noise

SELF_CONVERGENCE_POINTS = [(0.05, 0.49), (0.05, -0.5), (0.5, 0.0), (0.98, 0.49), (0.98, -0.5)]


@pytest.mark.parametrize("c, nu", SELF_CONVERGENCE_POINTS)
def test_graded_levels_converge(c, nu):
    g = _gamma(nu)
    fields = [solve_mu(c, g, LEVELS[k]) for k in range(5)]
    mus = np.array([f.mu for f in fields])
    ps = np.array([f.compliance for f in fields])
    dist = np.maximum(np.abs(mus - mus[4]), np.abs(ps - ps[4]))
    # exponential convergence: each level at least 10x closer to level 4 than the one before,
    # until rounding (measured: factors 25-1000 over these points)
    for k in range(2):
        assert dist[k + 1] <= max(dist[k] / 10, ROUNDING), dist


@pytest.mark.parametrize("nu, c", [(0.25, 0.5), (0.0, 0.8), (-0.5, 0.3), (0.45, 0.1)])
def test_graded_pointwise_stresses_converge(nu, c):
    # The target: stresses to 1e-8 pointwise away from x = c and x = 1. Against level 4:
    # level 3 measured <= 9e-11 at all seven points (tolerance 1e-9); level 2 <= 2.1e-9 up to
    # the middle of the slip annulus (tolerance 1e-8), but 3.4e-8 at x = c + 0.9 (1 - c), next
    # to the edge singularity, so the default level meets the target only away from the edge.
    g = _gamma(nu)
    ref, fine, default = (solve_mu(c, g, LEVELS[k]) for k in (4, 3, 2))
    x = np.array([0.0, 0.2 * c, 0.6 * c, 0.9 * c, c + 0.1 * (1 - c), c + 0.5 * (1 - c), c + 0.9 * (1 - c)])
    for f in ("pressure", "shear"):
        exact = getattr(ref, f)(x)
        assert np.max(np.abs(getattr(fine, f)(x) - exact)) < 1e-9
        assert np.max(np.abs(getattr(default, f)(x[:-1]) - exact[:-1])) < 1e-8
