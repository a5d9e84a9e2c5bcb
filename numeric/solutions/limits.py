"""The limits of the flat punch in closed form, and the largest stick radius ([S75] §2, App. B).

mu = 0 is frictionless (2.26) with c = 0; gamma = 0 (an incompressible solid, or elastically
similar bodies) has no shear coupling: q = 0 and nothing slips, so c = 1 for every mu > 0, and no
friction coefficient gives a stick radius 0 < c < 1 (mu = 0, frictionless, is the degenerate c = 0;
the law mu = gamma f0(c) (2.28) tends to it as gamma -> 0, but at gamma = 0 itself that mu gives
c = 0, not c); mu = inf or c = 1 is the fully adhesive solution of Appendix B. ``closed_form_given_c`` and ``closed_form_given_mu`` answer
first whether the problem is one of these (exactly, at no cost); the first refuses a stick
radius above the largest one.

The largest stick radius c_max(gamma) < 1 (``asymptotics.largest_stick_radius``: K'/K = kappa,
found from the limit problem mu -> inf): a stick radius at or above it has no friction
coefficient.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asymptotics.adhesive import compliance_adhesive, pressure_adhesive, shear_adhesive
from asymptotics.first_order import frictionless_pressure
from asymptotics.largest_stick_radius import largest_stick_radius_gap

from numeric.core.errors import NoEigenvalueError
from numeric.solutions.solution import FlatPunchSolution

__all__ = [
    "ADHESIVE_EDGE_BREAKPOINTS",
    "ClosedForm",
    "closed_form",
    "closed_form_given_c",
    "closed_form_given_mu",
    "no_eigenvalue",
]

ADHESIVE_EDGE_BREAKPOINTS = np.concatenate([[0.0, 0.5], 1.0 - 0.5 * 0.25 ** np.arange(1, 26), [1.0]])
ADHESIVE_EDGE_BREAKPOINTS.setflags(write=False)  # smooth pieces of the closed forms, graded toward x = 1

@dataclass(frozen=True, slots=True)
class ClosedForm:
    """Frictionless (c = 0 or gamma = 0) or fully adhesive (c = 1) stresses in closed form."""

    gamma: float
    adhesive: bool

    def pressure(self, x: np.ndarray) -> np.ndarray:
        if self.adhesive and self.gamma > 0.0:
            return pressure_adhesive(x, self.gamma)  # (B3)
        return frictionless_pressure(x)  # (2.26)

    def shear(self, x: np.ndarray) -> np.ndarray:
        if self.adhesive and self.gamma > 0.0:
            return shear_adhesive(x, self.gamma)  # (B3)
        return np.zeros(np.shape(x))

    def slip(self, x: np.ndarray) -> np.ndarray:
        return np.zeros(np.shape(x))

    def edge_value(self, shear: bool) -> float:
        """p at x = 1 is infinite; q too when adhesive (B3), else 0 (no shear)."""
        return 0.0 if shear and not (self.adhesive and self.gamma > 0) else math.inf


def closed_form(nu: float | None, gamma: float, mu: float, c: float, adhesive: bool, why: str) -> FlatPunchSolution:
    """The frictionless or fully adhesive solution as a ``FlatPunchSolution`` (error 0)."""
    compliance = float(compliance_adhesive(gamma)) if adhesive else 1.0  # (B4) or frictionless
    return FlatPunchSolution(nu, gamma, mu, c, compliance, 0.0, f"closed form ({why})", ADHESIVE_EDGE_BREAKPOINTS,
                             ClosedForm(gamma, adhesive))


def closed_form_given_c(nu: float | None, gamma: float, c: float) -> FlatPunchSolution | None:
    """The closed form if stick radius c is a limit (c = 1), else None.

    Raises
    ------
    NoEigenvalueError
        If c is at or above the largest stick radius c_max(gamma), or if gamma = 0 and c < 1 (without
        coupling every mu > 0 gives c = 1, and mu = 0 gives c = 0).
    """
    if c == 1.0:
        return closed_form(nu, gamma, math.inf, 1.0, True, "adhesive, App. B")
    if gamma == 0.0:
        raise NoEigenvalueError(
            f"no friction coefficient gives stick radius c = {c!r} at gamma = 0 (nu = 1/2, or elastically similar "
            "bodies): without coupling there is no shear and nothing slips, so c = 1 for every mu > 0 (c = 0 only "
            "for the frictionless mu = 0)")
    if 1.0 - c <= float(largest_stick_radius_gap(gamma)):
        raise no_eigenvalue(c, gamma)
    return None


def closed_form_given_mu(nu: float | None, gamma: float, mu: float) -> FlatPunchSolution | None:
    """The closed form if friction mu is a limit (mu = 0, mu = inf, or gamma = 0), else None."""
    if mu == 0.0:
        return closed_form(nu, gamma, 0.0, 0.0, False, "frictionless, (2.26)")
    if mu == math.inf:
        return closed_form(nu, gamma, math.inf, 1.0, True, "adhesive, App. B")
    if gamma == 0.0:
        return closed_form(nu, gamma, mu, 1.0, False, "gamma = 0: no coupling, no slip")
    return None


def no_eigenvalue(c: float, gamma: float, detail: str = "") -> NoEigenvalueError:
    """The error for a stick radius above the largest one, naming c_max (``asymptotics.largest_stick_radius``)."""
    gap = float(largest_stick_radius_gap(gamma))
    return NoEigenvalueError(
        f"no friction coefficient gives stick radius c = {c!r} at gamma = {gamma:.6g}: the largest stick radius is "
        f"c_max = 1 - {gap:.10g} (K'(c_max)/K(c_max) = kappa = (2/pi) atanh(gamma); mu -> inf as c -> c_max){detail}")
