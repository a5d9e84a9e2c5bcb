"""The limits of the flat punch in closed form, and the largest stick radius ([S75] §2, App. B).

mu = 0 is frictionless (2.26) with c = 0; gamma = 0 (an incompressible solid) has no shear
coupling, q = 0 and c = 1 for any mu > 0 (mu = 0 for any c); mu = inf or c = 1 is the fully
adhesive solution of Appendix B. ``closed_form_given_c`` and ``closed_form_given_mu`` answer
first whether the problem is one of these (exactly, at no cost); the first refuses a stick
radius above the largest one.

The largest stick radius (derivations/section_2_3.md, "Largest stick radius"): mu(c) of the
full problem grows like 1/(c_max - c) with 1 - c_max = 8 exp(-pi/kappa), kappa = (2/pi)
atanh(gamma); measured (1 - c_max) exp(pi/kappa) = 7.994 at gamma = 2/7 ... 0.5 and 7.926 at
gamma = 2/3. ``gap_scale`` is exp(-pi/kappa); the constants below place the estimate, a safe
upper bound and the top of the given-mu search.

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
from asymptotics.materials import kappa_from_gamma

from numeric.core.errors import NoEigenvalueError
from numeric.solutions.solution import FlatPunchSolution

__all__ = [
    "ADHESIVE_EDGE_BREAKPOINTS",
    "C_TOP",
    "C_MAX_COEFFICIENT",
    "C_MAX_UPPER_COEFFICIENT",
    "C_SEARCH_COEFFICIENT",
    "ClosedForm",
    "closed_form",
    "closed_form_given_c",
    "closed_form_given_mu",
    "gap_scale",
    "c_search_top",
    "no_eigenvalue",
]

ADHESIVE_EDGE_BREAKPOINTS = np.concatenate([[0.0, 0.5], 1.0 - 0.5 * 0.25 ** np.arange(1, 26), [1.0]])
ADHESIVE_EDGE_BREAKPOINTS.setflags(write=False)  # smooth pieces of the closed forms, graded toward x = 1

#: Largest stick radius the solver is asked for at small gamma; beyond it the answer is bracketed.
C_TOP = 1.0 - 1e-9
#: 1 - c_max ~ C_MAX_COEFFICIENT exp(-pi/kappa): the estimate quoted in messages.
C_MAX_COEFFICIENT = 8.0
#: c_max < 1 - C_MAX_UPPER_COEFFICIENT exp(-pi/kappa): 5 % below the smallest measured coefficient, 7.926.
C_MAX_UPPER_COEFFICIENT = 7.5
#: The given-mu search stops at c_top = 1 - C_SEARCH_COEFFICIENT exp(-pi/kappa), about 5 % of 1 - c_max
#: below c_max; there mu ~ 40 ... 100 (measured at gamma = 2/3 ... 1/3 in derivations/section_2_3.md,
#: level-2 error estimates 3e-5 ... 4e-2 of mu: the solver's error grows as c -> c_max).
C_SEARCH_COEFFICIENT = 8.4


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
    """The closed form if stick radius c is a limit (c = 1, or gamma = 0), else None.

    Raises
    ------
    NoEigenvalueError
        If c is above the largest stick radius (at once above 1 - 7.5 exp(-pi/kappa)).
    """
    if c == 1.0:
        return closed_form(nu, gamma, math.inf, 1.0, True, "adhesive, App. B")
    if gamma == 0.0:
        return closed_form(nu, gamma, 0.0, c, False, "gamma = 0: no coupling, mu = 0 (2.28)")
    if c > 1.0 - C_MAX_UPPER_COEFFICIENT * gap_scale(gamma):
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


def gap_scale(gamma: float) -> float:
    """exp(-pi/kappa), kappa = (2/pi) atanh(gamma) ([S75] (4.10)): 1 - c_max is about 8 times this."""
    return math.exp(-math.pi / float(kappa_from_gamma(gamma)))


def c_search_top(gamma: float) -> float:
    """Largest stick radius the given-mu search asks the solver for."""
    return min(C_TOP, 1.0 - C_SEARCH_COEFFICIENT * gap_scale(gamma))


def no_eigenvalue(c: float, gamma: float, detail: str = "") -> NoEigenvalueError:
    """The error for a stick radius above the largest one, naming the estimate of c_max."""
    c_max = 1.0 - C_MAX_COEFFICIENT * gap_scale(gamma)
    return NoEigenvalueError(
        f"no friction coefficient gives stick radius c = {c!r} at gamma = {gamma:.6g}: the largest stick radius is "
        f"estimated as c_max = 1 - 8 exp(-pi/kappa) = {c_max:.6g} (kappa = (2/pi) atanh(gamma); mu -> inf as "
        f"c -> c_max; derivations/section_2_3.md){detail}")
