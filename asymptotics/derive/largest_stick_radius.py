"""SymPy derivation of the largest stick radius c_max (beyond [S75] (2.29)).

Entry "c_max": the limit problem mu -> inf (``numeric.solutions.slip_limit``) has its root where
K'(c)/K(c) = kappa = (2/pi) atanh(gamma), found numerically by this project (agreement 1e-12 in
1 - c_max over gamma in [0.3, 0.75], ``tests/test_largest_stick_radius.py``; not proved). By
Jacobi's nome identities, with q = exp(-pi K'/K) = exp(-pi/kappa) the complementary modulus is
k' = theta_4(q)^2 / theta_3(q)^2, so c_max = k'; SymPy expands 1 - c_max in q. The nome identity
is checked in mpmath (an :class:`Identity`); the relation itself is an observation, recorded
as such in the note.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import mpmath
import sympy as sp

from ..derivation import Comparison, Derivation, Identity, Step
from ..largest_stick_radius import largest_stick_radius_gap, largest_stick_radius_gap_mp
from .precision import exact

__all__ = ["derivations"]

PART = "2.3"
_TERMS = 6  # theta series terms and the order of the q-series


def _nome_identity() -> Identity:
    def residual(gamma_):
        kappa = 2 * mpmath.atanh(gamma_) / mpmath.pi
        q = mpmath.exp(-mpmath.pi / kappa)
        k_prime = mpmath.jtheta(4, 0, q) ** 2 / mpmath.jtheta(3, 0, q) ** 2
        gap = 1 - k_prime
        return mpmath.ellipk(gap * (2 - gap)) / mpmath.ellipk(k_prime**2) - kappa

    return Identity(
        name="Jacobi: K'(k')/K(k') with k' = theta_4^2/theta_3^2 at q = exp(-pi/kappa) is kappa",
        statement=r"k' = \frac{\vartheta_4(q)^2}{\vartheta_3(q)^2},\ q = e^{-\pi/\kappa} \;\Rightarrow\; "
                  r"\frac{K(\sqrt{1-k'^2})}{K(k')} = \kappa",
        residual=exact(residual),
        points=((0.2,), (0.3,), (0.5,), (2 / 3,), (0.75,)),
        dps=40,
        tol=1e-30,
    )


def _dcmax() -> Derivation:
    q, kappa, g = sp.symbols("q kappa gamma", positive=True)
    n = range(1, _TERMS)
    theta3 = 1 + 2 * sum(q ** (j * j) for j in n)
    theta4 = 1 + 2 * sum((-1) ** j * q ** (j * j) for j in n)
    gap = 1 - theta4**2 / theta3**2
    series = sp.series(gap, q, 0, _TERMS + 1)
    leading = series.removeO().coeff(q, 1)
    derived = sp.Eq(sp.Symbol("1 - c_max"), series)
    steps = (
        Step("the limit problem's root (observed): K'(c_max)/K(c_max) = kappa, kappa = (2/pi) atanh(gamma)",
             sp.Eq(kappa, 2 * sp.atanh(g) / sp.pi)),
        Step("nome q = exp(-pi K'/K) = exp(-pi/kappa); c_max = k' = theta_4(q)^2/theta_3(q)^2",
             sp.Eq(sp.Symbol("c_max"), theta4**2 / theta3**2)),
        Step("1 - c_max expanded in q", derived),
        Step("leading term: 8 exp(-pi/kappa), the coefficient measured before from the solver", sp.Eq(sp.Symbol("a_1"), leading)),
    )
    return Derivation(
        label="c_max", part=PART,
        title="largest stick radius: K'(c_max)/K(c_max) = kappa, 1 - c_max = 8q - 32q^2 + 96q^3 - ..., q = exp(-pi/kappa)",
        derived=derived, printed=None, agrees=bool(leading == 8),
        steps=steps, identities=(_nome_identity(),),
        fast=largest_stick_radius_gap, precise=largest_stick_radius_gap_mp, arguments=("gamma",),
        comparison=Comparison(points=((0.1,), (0.2,), (2 / 7,), (0.5,), (2 / 3,), (0.75,)), rtol=5e-14),
        note="Not in the paper, whose (2.29) says c -> 1 as mu -> inf (the limit of the first-order law, gamma -> 0 "
             "first). The relation K'/K = kappa is what the limit problem of the full solution gives (1e-12 relative "
             "in 1 - c_max, tests/test_largest_stick_radius.py); a proof is not given here. The fast function sums "
             "the theta series in numpy, the precise one uses mpmath's jtheta.",
    )


def derivations() -> tuple[Derivation, ...]:
    return (_dcmax(),)
