"""The engineer's route of ``numeric.flat_punch``: the whole-plane table, with fields on demand.

For rtol >= ``TABLE_RTOL`` the table (``numeric.core.table``) answers c, mu and P* at once (to its
recorded held-out errors, ~1e-10), and the stresses p, q and the slip u are level 0's
(``numeric.core.charts.RESOLUTIONS[0]``), formed only when first asked for: read from the field table
(``numeric.core.field_table``: the level-0 eigensolution on a layout that moves smoothly with c, tabulated in
(c, gamma) for 0.05 <= c <= 0.9 below mu gamma = 1; ~0.1 ms) where it holds the point, else solved from
the table's theta = atan(mu gamma) (one assembly and one or two LU factorisations, ~2 ms: Newton in theta from a
guess good to 1e-10 stops after its first step). Either is level 0's discrete eigensolution, not
the table's theta with level 0's basis: off the discrete eigenvalue the basis carries a spurious
(c - x)^(-1/2 - alpha) component at x = c. Measured against level 4 (``tests/test_table_route.py``,
``tests/test_field_table.py``) p and q are within ``FIELD_ERROR`` of max(1, |p|) at every x, x = c and
1 - x = 1e-5 included.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from asymptotics.largest_stick_radius import largest_stick_radius_gap

from numeric.core.charts import RESOLUTIONS
from numeric.core.eigenvalue import solve_given_c
from numeric.core.field_table import field_table_holds, tabulated_field
from numeric.core.fields import SingularField
from numeric.core.table import TableValues, table_errors, table_given_c, table_given_mu
from numeric.solutions.law import graded_breakpoints
from numeric.solutions.solution import FlatPunchSolution, Offer

__all__ = ["TABLE_RTOL", "FIELD_ERROR", "GAP_FACTOR", "TABLE_SECONDS", "DeferredField", "TableRoute"]

#: The least rtol the route is offered for: the level-0 fields' accuracy, with a margin of 5.
TABLE_RTOL = 1e-4
#: Bound of the level-0 fields' error against level 4 (p, q relative to max(1, |p|)): measured worst
#: 1.7e-5 over nu in {-0.95, -0.5, 0, 0.3, 0.45} and c from 0.01 up to 1 - 1.1 (1 - c_max), at x = c (3.1e-5 before the
#: grading was held for every element)
#: (``tests/test_table_route.py`` checks a sample), with a margin.
FIELD_ERROR = 5e-5
#: The route stops at 1 - c = GAP_FACTOR (1 - c_max): closer to the largest stick radius (mu gamma above
#: ~10 A) the level-0 stresses at x = c lose digits (measured 1e-4 ... 1e-2 at 1.001 (1 - c_max)).
GAP_FACTOR = 1.1
#: Rough run time of the route without the fields, in seconds (for ordering routes).
TABLE_SECONDS = 2e-4


class DeferredField:
    """The level-0 fields at stick radius c = 1 - gap, read from the field table or solved when p, q or u are first
    asked for."""

    def __init__(self, c: float, gap: float, gamma: float, theta: float, compliance: float) -> None:
        self.c, self.gap, self.gamma, self.theta_guess, self.compliance = c, gap, gamma, theta, compliance

    @cached_property
    def solved(self) -> SingularField:
        """The tabulated level-0 field where the field table holds (c, gamma), else the level-0 solve (Newton in
        theta from the table's theta)."""
        read = tabulated_field(self.c, self.gap, self.gamma, self.compliance)
        if read is not None:
            return read
        return SingularField(solve_given_c(self.c, self.gap, self.gamma, self.theta_guess, RESOLUTIONS[0]))

    def pressure(self, x: np.ndarray) -> np.ndarray:
        return self.solved.pressure(x)

    def shear(self, x: np.ndarray) -> np.ndarray:
        return self.solved.shear(x)

    def slip(self, x: np.ndarray) -> np.ndarray:
        return self.solved.slip(x)

    def edge_value(self, shear: bool) -> float:
        return self.solved.edge_value(shear)


class TableRoute:
    """The table for one problem (exactly one of c and mu given): an offer for rtol >= TABLE_RTOL where the
    table reaches the point and its recorded errors meet rtol."""

    def __init__(self, nu: float | None, gamma: float, c: float | None, mu: float | None) -> None:
        self.nu, self.gamma, self.given_c = nu, gamma, c is not None
        wanted = ("compliance",)  # the route reports mu, c and P*; the sphere's and cone's constants are not read
        self._values: TableValues = (table_given_c(c, gamma, quantities=wanted) if c is not None
                                     else table_given_mu(mu, gamma, quantities=wanted))
        self.errors = table_errors()

    @property
    def reaches(self) -> bool:
        v = self._values
        if not (np.isfinite(v.c[0]) and np.isfinite(v.mu[0]) and self.errors):
            return False
        return bool(v.gap[0] >= GAP_FACTOR * float(largest_stick_radius_gap(self.gamma)))

    def error(self) -> float:
        """Absolute error bound of the returned value (mu given c, c given mu) and P*, from the recorded errors."""
        v = self._values
        if self.given_c:
            value_error = self.errors["mu"] * v.mu[0]
        else:
            value_error = max(self.errors["c"] * v.c[0], self.errors["gap"] * v.gap[0])
        return max(value_error, self.errors["compliance"] * v.values["compliance"][0])

    def offers(self, rtol: float) -> list[Offer]:
        if not self.reaches or rtol < TABLE_RTOL:
            return []
        return [Offer(TABLE_SECONDS, lambda: True, self.solution)]

    def solution(self) -> FlatPunchSolution:
        v = self._values
        mu, c, gap = float(v.mu[0]), float(v.c[0]), float(v.gap[0])
        theta = 0.5 * math.pi if math.isinf(mu) else math.atan(mu * self.gamma)
        compliance = float(v.values["compliance"][0])
        fields = "tabulated" if field_table_holds(c, self.gamma) else "computed"
        return FlatPunchSolution(
            nu=self.nu, gamma=self.gamma, mu=mu, c=c, compliance=compliance, _error=self.error(),
            route=f"table (mu, c, P* to {self.error():.1g}) with level-0 stresses (to {FIELD_ERROR:g} of max(1, p)) "
                  f"{fields} on first use",
            breakpoints=graded_breakpoints(c), _field=DeferredField(c, gap, self.gamma, theta, compliance))
