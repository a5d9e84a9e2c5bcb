"""Numerical solutions of the Hertz contact problem with finite friction (Spence 1975).

The public API: ``flat_punch`` (``numeric.solutions.flat_punch``), ``stick_radius`` and
``friction_coefficient`` (``numeric.solutions.sweep``), ``power_law``
(``numeric.solutions.power_law``), and the limit mu -> inf: ``largest_stick_radius``,
``slip_limit``, ``stick_radius_approach`` (``numeric.solutions.slip_limit``), with their result
types and errors. This is the only module of ``numeric`` that re-exports.

The folders are the layers, and imports only go down (``tests/test_layers.py`` checks it):
``app`` (SI calculator, command line) -> ``studies`` (tables, benchmark, stability,
expansion checks, figures) -> ``solutions`` (the problems and their routes) and
``baseline`` (the paper's own scheme of §4, independent of ``core`` on purpose) -> ``core``
(quadrature, mesh, collocation, eigenvalue, table) -> ``asymptotics`` -> numpy, scipy, mpmath.
"""

from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.power_law import PowerLawSolution, power_law
from numeric.solutions.slip_limit import largest_stick_radius, slip_limit, stick_radius_approach
from numeric.solutions.solution import AccuracyWarning, FlatPunchSolution
from numeric.solutions.sweep import friction_coefficient, stick_radius

__all__ = [
    "AccuracyWarning",
    "FlatPunchSolution",
    "NoEigenvalueError",
    "PowerLawSolution",
    "SolverError",
    "flat_punch",
    "friction_coefficient",
    "largest_stick_radius",
    "power_law",
    "slip_limit",
    "stick_radius",
    "stick_radius_approach",
]
