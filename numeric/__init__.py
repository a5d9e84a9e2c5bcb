"""Numerical solutions of the Hertz contact problem with finite friction (Spence 1975).

High-accuracy solver: ``flat_punch``, ``stick_radius``, ``friction_coefficient``
(``numeric.flat_punch``) and ``power_law`` (``numeric.power_law``). The paper's own scheme,
the baseline, is ``numeric.spence1975``.
"""

from .flat_punch import (AccuracyWarning, FlatPunchSolution, NoEigenvalueError, SolverError, flat_punch,
                         friction_coefficient, stick_radius)
from .power_law import PowerLawSolution, power_law

__all__ = [
    "AccuracyWarning",
    "FlatPunchSolution",
    "NoEigenvalueError",
    "PowerLawSolution",
    "SolverError",
    "flat_punch",
    "friction_coefficient",
    "power_law",
    "stick_radius",
]
