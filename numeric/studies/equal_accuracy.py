"""The paper's scheme run to the accuracy of the engineer's route (rtol = 1e-4), side by side with that route.

The benchmark's side-by-side table (``numeric.studies.bench.side_by_side``) holds the paper's scheme at its published
kind of resolution, h = 0.01, where it gives mu and P* to ~2e-4. An engineer who asks for rtol = 1e-4 wants 1e-4 in
everything the full solution returns. Here, per case of the rtol = 1e-4 task (given c), the scheme ([S75] §4,
``numeric.baseline.scheme``) runs on finer friction meshes (``H``) until its full solution is within ``TARGET`` of
level 4: mu, P* (4.9) and p, q, u (4.12) at its collocation points nearest x = 0, c/2 and (1 + c)/2 (relative to
max(1, |p|), as the route's fields; the scheme has no value at x = c itself). The time to reach ``TARGET`` is
interpolated in log-log between the first mesh that reaches it and the one before, else the least-squares line through
log(error) against log(time) over the meshes run is extrapolated (marked so). The route is timed on the same cases,
its error taken the same way (and at x = c).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from numeric.baseline import scheme
from numeric.core.eigenvalue import operators_at
from numeric.solutions.flat_punch import flat_punch
from numeric.studies.timing import median_time, power_law_time

__all__ = ["TARGET", "H", "PUBLISHED_H", "scheme_tolerance", "EqualAccuracy", "time_to_target", "equal_accuracy",
           "summary"]

#: The engineer's accuracy: the rtol of the route.
TARGET = 1e-4
#: Coarse widths of the friction mesh tried, coarse to fine (the paper's is 0.02; the side-by-side's 0.01).
H = (0.02, 0.014, 0.01, 0.007, 0.005, 0.0035, 0.0025)
#: The paper's friction mesh (§4.1).
PUBLISHED_H = 0.02


def scheme_tolerance(h: float) -> float:
    """Regula falsi tolerance of the paper's scheme: its 1e-5 at h = 0.02, scaled like h^3 so that it stays below the
    discretisation error (order ~1.2 in h) on every finer mesh."""
    return 1e-5 * (h / PUBLISHED_H) ** 3


@dataclass(frozen=True, slots=True)
class EqualAccuracy:
    """One case: the route's time and worst error, the scheme's (h, seconds, worst error) per mesh run, and its time
    to ``TARGET`` (``extrapolated`` if no mesh reached it; None where its error did not fall with the time, or no two
    meshes ran; ``failure`` then names the mesh on which the scheme found no eigenvalue, if it did not run)."""

    nu: float
    c: float
    route_seconds: float
    route_error: float
    scheme: tuple[tuple[float, float, float], ...]
    scheme_seconds: float | None
    extrapolated: bool
    failure: str = ""

    @property
    def ratio(self) -> float | None:
        """The scheme's time to ``TARGET`` over the route's."""
        return None if self.scheme_seconds is None else self.scheme_seconds / self.route_seconds


def _field_error(values: Sequence[np.ndarray], reference: Sequence[np.ndarray]) -> float:
    """Worst error of p, q, u relative to max(1, |p|) (the reference's p)."""
    scale = np.maximum(1.0, np.abs(reference[0]))
    return max(float(np.max(np.abs(v - r) / scale)) for v, r in zip(values, reference))


def _scheme_error(sol: scheme.SchemeSolution, ref) -> float:
    """The scheme's worst error over mu, P* and p, q, u at its points nearest 0, c/2 and (1 + c)/2."""
    xm = sol.mesh.midpoints
    idx = np.unique([int(np.argmin(np.abs(xm - x))) for x in (0.0, 0.5 * ref.c, 0.5 * (1.0 + ref.c))])
    x = xm[idx]
    fields = _field_error((sol.pressure[idx], sol.shear[idx], sol.slip[idx]),
                          (ref.pressure(x), ref.shear(x), ref.slip(x)))
    return max(abs(sol.mu / ref.mu - 1.0), abs(sol.compliance / ref.compliance - 1.0), fields)


def time_to_target(points: Sequence[tuple[float, float]]) -> tuple[float | None, bool]:
    """The scheme's time to TARGET from its (seconds, error) points, coarse to fine: where a mesh reaches it, the
    log-log interpolation between that mesh and the one before (the time at which the error crosses TARGET; the
    first mesh's time if it reaches it already); else the least-squares line through all points, extrapolated (True),
    if the error falls with the time. None otherwise."""
    for k, (t, e) in enumerate(points):
        if e <= TARGET:
            if k == 0:
                return t, False
            (t0, e0), (t1, e1) = points[k - 1], (t, e)
            if not e0 > e1:
                return t1, False
            w = math.log(e0 / TARGET) / math.log(e0 / e1)
            return math.exp(math.log(t0) + w * math.log(t1 / t0)), False
    if len(points) < 2:
        return None, False
    slope, seconds = power_law_time(points, TARGET)
    if slope <= 0.0:  # the error does not fall with the time: no extrapolation
        return None, False
    return seconds, True


def equal_accuracy(cases: Sequence[tuple[float, float]], budget: float, max_runs: int) -> list[EqualAccuracy]:
    """Per (nu, c): the rtol = 1e-4 route's full solution and the scheme refined to ``TARGET`` (module docstring)."""
    out = []
    for nu, c in cases:
        ref = flat_punch(nu=nu, c=c, level=4)
        x = np.array([0.0, 0.5 * c, c, 0.5 * (1.0 + c)])
        reference = (ref.pressure(x), ref.shear(x), ref.slip(x))

        def route():
            s = flat_punch(nu=nu, c=c, rtol=TARGET)
            return s, (s.pressure(x), s.shear(x), s.slip(x))

        s, fields = route()
        route_error = max(abs(s.mu / ref.mu - 1.0), abs(s.compliance / ref.compliance - 1.0),
                          _field_error(fields, reference))
        route_seconds = median_time(route, before=operators_at.cache_clear, budget=budget, max_runs=max_runs)
        runs, failure = [], ""
        for h in H:
            try:
                sol = scheme.solve_friction(c, nu, h=h, tol=scheme_tolerance(h))
            except RuntimeError:  # no bracket of the eigenvalue on this mesh (``scheme.solve_friction``)
                failure = f"finds no eigenvalue at h = {h:g}"
                break
            seconds = median_time(lambda h=h: scheme.solve_friction(c, nu, h=h, tol=scheme_tolerance(h)),
                                  before=scheme.collocation_matrix.cache_clear, budget=budget, max_runs=max_runs)
            runs.append((h, seconds, _scheme_error(sol, ref)))
            if runs[-1][2] <= TARGET:
                break
        seconds, extrapolated = time_to_target([(t, e) for _, t, e in runs])
        out.append(EqualAccuracy(nu, c, route_seconds, route_error, tuple(runs), seconds, extrapolated,
                                 failure if seconds is None else ""))
    return out


def summary(rows: Sequence[EqualAccuracy]) -> tuple[float, float, float, int] | None:
    """Median, least and largest ratio (scheme at TARGET over the route) over the cases that have one, and their
    number; None if none."""
    ratios = [r.ratio for r in rows if r.ratio is not None]
    if not ratios:
        return None
    return statistics.median(ratios), min(ratios), max(ratios), len(ratios)
