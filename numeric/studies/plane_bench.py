"""Plane strain (issue 14) in the benchmark: the strip punch's tasks timed in the same run as the axisymmetric ones.

``plane_side_by_side`` times, per call and with the layout's transforms cleared before each call (a problem not
solved before, as ``numeric.studies.bench.side_by_side`` does for the axisymmetric solver):

* the plane counterpart of the paper's scheme (``numeric.baseline.plane_scheme``) at the paper's resolution
  h = 0.02, nu = 0.25, c = 0.5: mu for given c, the yardstick of the ratio column;
* the full solution (mu or c, p, q, u at four points) of ``strip_punch`` at the default level for given c and for
  given mu, at c <= 0.95 and near c_max (nu = 0: c_max = 0.99626; nu = -1/2: 0.94110; nu = 0.3: 1 - 1.6e-6), without
  and with its error estimate (a second solve one degree lower, formed when read): the same task labels as the
  axisymmetric side-by-side rows, so that the report can set each beside its axisymmetric counterpart;
* below the solver's smallest c (1e-5) the law route (``numeric.solutions.plane_law``) for given c, its first call
  per nu (the fit: three solver solves) and later calls.

References: ``reference_mu``, the median of four finer resolutions, for the solver's rows and the scheme; for the law route the solver's own iteration run directly at c = 1e-6 at level 3
(``plane_given_c``; the public route does not, 0.1-0.7 s a solve), as in ``derivations/plane_strain.md``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction", J. Elasticity 5 (1975) 297-319, §4.1.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Callable
from functools import lru_cache

import numpy as np

from asymptotics.materials import gamma_from_nu

from numeric.baseline.plane_scheme import plane_solve_friction
from numeric.core.plane_charts import PlaneResolution
from numeric.core.plane_eigenvalue import plane_given_c, plane_operators_at
from numeric.core.plane_fields import PlaneField
from numeric.solutions.plane_law import law_fit
from numeric.solutions.plane_punch import strip_punch
from numeric.solutions.plane_solver import PLANE_LEVELS
from numeric.studies.timing import SideBySide, Yardstick

__all__ = ["INSIDE", "NEAR", "SCHEME_H", "SCHEME_TASK", "REFERENCE", "REFERENCE_RESOLUTIONS", "reference_mu",
           "plane_side_by_side"]

#: (nu, c) inside c <= 0.95 (as the axisymmetric side by side) and near the plane c_max of each nu.
INSIDE = ((0.0, 0.1), (0.0, 0.5), (0.25, 0.5), (0.25, 0.9), (0.45, 0.5), (-0.5, 0.5))
NEAR = ((0.0, 0.99), (0.0, 0.995), (-0.5, 0.9), (-0.5, 0.93), (0.3, 0.9999))
#: The paper's friction mesh (§4.1), at which the plane scheme gets 3 places.
SCHEME_H = 0.02
SCHEME_TASK = "plane scheme (numeric.baseline.plane_scheme), h = 0.02, nu = 0.25, c = 0.5 (mu)"
#: Stick widths and nu of the law route's rows.
LAW_POINTS = ((0.3, 1e-6), (0.0, 1e-6))


#: The reference resolutions: degrees 26 and 28, the layout's c_fraction 0.1 and 0.25.
REFERENCE_RESOLUTIONS = tuple(PlaneResolution(d, 2, c_fraction=f) for d in (26, 28) for f in (0.1, 0.25))
REFERENCE = "median of degrees 26, 28 (two layouts)"


@lru_cache(maxsize=None)
def reference_mu(nu: float, c: float) -> float:
    """mu for stick width c: the median over ``REFERENCE_RESOLUTIONS`` of the careful iteration started 1e-6 off the
    default level's theta (started on it, Newton may stop at once and return the default level's own root). Level 4
    (degree 24) is not used: at nu = 0.25 it lies 5e-10 from this median (its estimate says 5e-10), where levels 2
    and 3 lie within 1e-11; the four values here spread by 1e-11 relative, up to 8e-10 at theta = 0.003 (nu = 0.45,
    c = 0.05), where mu = tan(theta)/gamma carries G's absolute rounding in theta over theta."""
    g = float(gamma_from_nu(nu))
    start = math.atan(strip_punch(nu=nu, c=c).mu * g) * (1.0 + 1e-6)
    return statistics.median(PlaneField(plane_given_c(c, 1.0 - c, g, start, res)).mu for res in REFERENCE_RESOLUTIONS)


def _full(s) -> tuple:
    """What "the full solution" returns: mu, c, and p, q, u at four points."""
    x = np.array([0.0, 0.5 * s.c, s.c, 0.5 * (1 + s.c)])
    return s.mu, s.c, s.pressure(x), s.shear(x), s.slip(x)


def _with_error(s) -> tuple:
    return _full(s) + (s.error,)


def plane_side_by_side(budget: float, max_runs: int) -> list[SideBySide]:
    """The plane tasks, each timed (median per call over runs within ``budget`` seconds or ``max_runs`` runs) with its
    worst relative error; ``ratio`` is to the plane scheme at h = 0.02 timed here, again before each case of each task
    (``Yardstick``: its time is the median of all those runs)."""
    clear = plane_operators_at.cache_clear
    scheme = plane_solve_friction(0.5, 0.25, h=SCHEME_H)
    yardstick = Yardstick(lambda: plane_solve_friction(0.5, 0.25, h=SCHEME_H), budget=budget, max_runs=max_runs)
    measured: list[tuple[str, float, float, int, str]] = []  # task, seconds, error, points, reference

    def task(label: str, calls: list[tuple[Callable[[], object], Callable[[object], float]]], reference: str,
             returns: Callable[[object], tuple] = _full, before: Callable[[], object] = clear) -> None:
        times, errors = [], []
        for call, error in calls:
            before()
            errors.append(error(call()))
            times.append(yardstick.case(lambda call=call: returns(call()), before=before))
        measured.append((label, statistics.median(times), max(errors), len(calls), reference))

    def given_c(nu: float, c: float):
        mu = reference_mu(nu, c)
        return lambda: strip_punch(nu=nu, c=c), lambda s: abs(s.mu / mu - 1)

    def given_mu(nu: float, c: float):
        mu = reference_mu(nu, c)
        return lambda: strip_punch(nu=nu, mu=mu), lambda s: abs(s.gap / (1.0 - c) - 1)

    task("full solution for given c <= 0.95 (level 2)", [given_c(*p) for p in INSIDE], REFERENCE)
    task("full solution for given c near c_max (level 2)", [given_c(*p) for p in NEAR], REFERENCE)
    task("full solution for given mu, c <= 0.95 (level 2)", [given_mu(*p) for p in INSIDE], REFERENCE)
    task("full solution for given mu near c_max (level 2)", [given_mu(*p) for p in NEAR], REFERENCE)
    task("the same with its error estimate: given c <= 0.95", [given_c(*p) for p in INSIDE], REFERENCE, _with_error)
    task("the same with its error estimate: given mu, c <= 0.95", [given_mu(*p) for p in INSIDE], REFERENCE,
         _with_error)

    def law(nu: float, c: float):
        g = float(gamma_from_nu(nu))
        direct = PlaneField(plane_given_c(c, 1.0 - c, g, math.atan(strip_punch(nu=nu, c=c).mu * g), PLANE_LEVELS[3]))
        return lambda: strip_punch(nu=nu, c=c), lambda s: abs(s.mu / direct.mu - 1)

    laws = [law(*p) for p in LAW_POINTS]
    reference = "the solver's iteration at c itself (level 3)"
    task("plane law route, c = 1e-6, first call per nu (the fit)", laws, reference, lambda s: (s.mu,), law_fit.cache_clear)
    task("plane law route, c = 1e-6, later calls", laws, reference, lambda s: (s.mu,), lambda: None)
    return yardstick.rows((SCHEME_TASK, abs(scheme.mu / reference_mu(0.25, 0.5) - 1), 1, REFERENCE), measured)
