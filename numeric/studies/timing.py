"""Timing of the benchmarks: the median time of a call, the caches a new problem would not find, the record
of one task timed beside a yardstick (``numeric.studies.bench``, ``numeric.studies.plane_bench``), and the time a
method would need for an error, along the power law of its (time, error) points."""

from __future__ import annotations

import math
import statistics
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["SideBySide", "Yardstick", "median_time", "clear_caches", "power_law_time"]


@dataclass(frozen=True, slots=True)
class SideBySide:
    """One task timed in the same run as a yardstick (the paper's scheme at h = 0.01, or for the plane tasks the
    axisymmetric solver's same task): ``seconds`` (median; per call), ``ratio`` = seconds / the yardstick's, ``error``
    the worst relative error over ``points`` points against ``reference``."""

    task: str
    seconds: float
    ratio: float
    error: float
    points: int
    reference: str


def median_time(call: Callable[[], object], *, before: Callable[[], object] | None = None, budget: float = 0.5,
                max_runs: int = 5, warm: bool = False) -> float:
    """Median seconds per call of ``call()`` over runs until ``budget`` seconds or ``max_runs`` runs
    (at least one run).

    The first call calibrates: calls shorter than 1 ms are repeated within a run so that a
    run lasts about 2 ms (not with ``before``). It counts as a run only if ``warm`` (the
    caller has made a warm-up call already) and it is not repeated. ``before`` (untimed)
    runs before each call, e.g. to clear a cache.
    """
    if before is not None:
        before()
    t0 = time.perf_counter()
    call()
    first = time.perf_counter() - t0
    inner = 1 if before is not None or first >= 1e-3 else max(1, int(2e-3 / max(first, 1e-7)))
    times: list[float] = [first] if warm and inner == 1 else []
    total = sum(times)
    while not times or (len(times) < max_runs and total < budget):
        if before is not None:
            before()
        t0 = time.perf_counter()
        for _ in range(inner):
            call()
        elapsed = time.perf_counter() - t0
        times.append(elapsed / inner)
        total += elapsed
    return statistics.median(times)


class Yardstick:
    """A call that tasks are timed against, timed again before each of their cases (``case``): its time
    (``seconds``) is the median of all those runs, so that the ratios do not carry the drift of a shared machine's
    load over the seconds the tasks take (single medians of the paper's scheme were seen 5.2 ... 7.6 ms apart)."""

    def __init__(self, call: Callable[[], object], *, before: Callable[[], object] | None = None, budget: float = 0.5,
                 max_runs: int = 5) -> None:
        self._call, self._before, self.budget, self.max_runs = call, before, budget, max_runs
        self._times: list[float] = []

    def run(self) -> None:
        """Time the yardstick once more (a median over its runs)."""
        self._times.append(median_time(self._call, before=self._before, budget=self.budget, max_runs=self.max_runs))

    @property
    def timings(self) -> tuple[float, ...]:
        """Its timings so far, seconds per call (one per ``run``)."""
        return tuple(self._times)

    @property
    def seconds(self) -> float:
        """The median of its timings so far (one is made if there is none)."""
        if not self._times:
            self.run()
        return statistics.median(self._times)

    def case(self, call: Callable[[], object], *, before: Callable[[], object] | None = None,
             warm: bool = False) -> float:
        """``median_time`` of one case of a task, with the same budget and runs, after timing the yardstick again."""
        self.run()
        return median_time(call, before=before, budget=self.budget, max_runs=self.max_runs, warm=warm)

    def rows(self, own: tuple[str, float, int, str],
             tasks: Sequence[tuple[str, float, float, int, str]]) -> list[SideBySide]:
        """The yardstick's own row (task, error, points, reference) and the tasks' (task, seconds, error, points,
        reference), each with its ratio to ``seconds``."""
        t = self.seconds
        task, error, points, reference = own
        return [SideBySide(task, t, 1.0, error, points, reference)] + [
            SideBySide(name, seconds, seconds / t, err, n, ref) for name, seconds, err, n, ref in tasks]


def clear_caches() -> tuple[str, ...]:
    """Clear every ``functools`` cache in the loaded ``numeric`` and ``asymptotics`` modules.

    Returns the qualified names of the caches cleared (sorted)."""
    names = []
    for name, module in sorted(sys.modules.items()):
        if module is None or not (name.startswith("numeric.") or name.startswith("asymptotics.")):
            continue
        for attr, obj in vars(module).items():
            if callable(getattr(obj, "cache_clear", None)) and getattr(obj, "__module__", None) == name:
                obj.cache_clear()
                names.append(f"{name}.{attr}")
    return tuple(sorted(names))


def power_law_time(points: Sequence[tuple[float, float]], target: float) -> tuple[float, float]:
    """Slope s of the least-squares line log(error) = a - s log(time) through (time, error) points, and the time where
    it reaches ``target`` (meaningful for s > 0: the error falls with the time)."""
    log_t, log_e = np.log([t for t, _ in points]), np.log([e for _, e in points])
    minus_s, a = np.polyfit(log_t, log_e, 1)
    return float(-minus_s), float(np.exp((math.log(target) - a) / minus_s))
