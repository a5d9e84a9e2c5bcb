"""The solvers' failures, shared by the singular-basis solver and the graded one.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

__all__ = ["NoEigenvalueError", "SolverError"]


class NoEigenvalueError(RuntimeError):
    """No friction coefficient mu >= 0 gives the stick radius asked for (it lies above c_max)."""


class SolverError(RuntimeError):
    """The solver did not converge."""
