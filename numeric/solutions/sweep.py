"""Sweeps over arrays: ``stick_radius`` and ``friction_coefficient`` of the flat punch ([S75] §2.2).

All points at once through the Chebyshev table of ``numeric.core.table`` inside its domain
(microseconds a point); the others one by one through ``flat_punch``, serially or mapped over
an executor (``concurrent.futures``, a Dask client's ``get_executor()``), with a progress bar
on stderr (``numeric.solutions.progress``). With ``rtol`` each point takes the cheapest route that meets it: the asymptotic law
(``numeric.solutions.law``), the table where its recorded error does, else ``flat_punch``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.materials import check_c, check_mu, check_nu, gamma_from_nu

from numeric.core.table import (table_available, table_errors, table_friction_coefficient, table_given_c,
                                table_least_c, table_stick_radius)
from numeric.solutions.flat_punch import check_rtol, flat_punch, level_and_rtol
from numeric.solutions.law import LawRoute, hand_over_ratio, law_stick_radius
from numeric.solutions.progress import Progress, check_progress, progress_bar
from numeric.solutions.solution import first_meeting

__all__ = ["Executor", "TABLE_MARGIN", "table_meets", "stick_radius", "friction_coefficient"]

#: The table's relative error is taken as twice the worst its build measured at held-out points
#: (``numeric.core.table_data.ERRORS``: mu, and c, directly, both ways through the interpolant).
TABLE_MARGIN = 2.0


class Executor(Protocol):
    """What a sweep can be handed to: ``concurrent.futures`` executors (threads or
    processes) and ``dask.distributed.Client.get_executor()`` all provide this ``map``."""

    def map(self, fn: Callable, *iterables: Iterable) -> Iterable: ...


def _solved_c(mu: float, nu: float, level: int | None, rtol: float | None) -> float:
    return flat_punch(nu=nu, mu=mu, level=level, rtol=rtol).c


def _below_table(kind: str, a: np.ndarray, g: np.ndarray, missing: np.ndarray) -> np.ndarray:
    """Of the points ``missing``, those below the table's least stick radius (C_MIN = 1e-5), where flat_punch
    answers by the second-order law matched to the table there: their c from that law directly, without the
    bracket and the P* it also computes (nan elsewhere). The tables' least mu is read for all of them at once."""
    out = np.full(missing.size, np.nan)
    if kind != "c" or not missing.size or not table_available():
        return out
    least = table_given_c(np.full(missing.size, table_least_c()), g[missing], quantities=()).mu
    for k in np.flatnonzero((a[missing] > 0.0) & (a[missing] < least)):
        gamma = float(g[missing[k]])
        # the ratio as flat_punch forms it (one table read per point), so that both give the same c to the last bit
        out[k] = law_stick_radius(float(a[missing[k]]) / hand_over_ratio(gamma), gamma, 2)
    return out


def _solved_mu(c: float, nu: float, level: int | None, rtol: float | None) -> float:
    return flat_punch(nu=nu, c=c, level=level, rtol=rtol).mu


def table_meets(kind: str, values: np.ndarray, rtol: float) -> np.ndarray:
    """Where the table's value meets rtol: its recorded error of mu or c (``table_errors``) times TABLE_MARGIN."""
    errors = table_errors()
    bound = TABLE_MARGIN * max(errors.get(kind, math.inf), errors.get("gap", 0.0) if kind == "c" else 0.0)
    return ~np.isnan(values) & (bound <= rtol)


def _sweep(name: str, kind: str, table, solve, first: ArrayLike, nu: ArrayLike, use_table: bool, level: int | None,
           rtol: float | None, executor: Executor | None, progress: Progress) -> np.ndarray | float:
    """Evaluate ``table`` on all points at once; solve the points outside its domain, one by
    one or through ``executor``, with a progress bar on stderr (``progress``). With ``rtol``, points
    where the asymptotic law meets it take that first, and the table only where it meets rtol."""
    a, n = np.broadcast_arrays(np.asarray(first, dtype=float), np.asarray(nu, dtype=float))
    shape = a.shape
    a, n = a.ravel(), n.ravel()
    g = np.asarray(gamma_from_nu(n), dtype=float)
    out = np.full(a.shape, np.nan)
    if rtol is not None:
        for i in range(a.size):
            if 0.0 < a[i] < (1.0 if kind == "mu" else math.inf) and g[i] > 0.0:
                given = (float(a[i]), None) if kind == "mu" else (None, float(a[i]))
                law = LawRoute(None, float(g[i]), *given)
                sol = first_meeting(law.offers(rtol), rtol, lambda s: getattr(s, kind))
                if sol is not None:
                    out[i] = getattr(sol, kind)
    rest = np.isnan(out)
    if use_table and table_available() and np.any(rest):
        values = np.array(table(a[rest], g[rest]), dtype=float)
        if rtol is not None:
            values = np.where(table_meets(kind, values, rtol), values, np.nan)
        out[rest] = values
    missing = np.flatnonzero(np.isnan(out))
    if rtol is None and use_table:
        out[missing] = _below_table(kind, a, g, missing)
        missing = np.flatnonzero(np.isnan(out))
    if missing.size:
        args = (a[missing], n[missing], [level] * missing.size, [rtol] * missing.size)
        results = executor.map(solve, *args) if executor is not None else map(solve, *args)
        with progress_bar(missing.size, name, progress) as bar:
            for index, value in zip(missing, results):
                out[index] = value
                bar.update()
    out = out.reshape(shape)
    return float(out) if out.ndim == 0 else out


def stick_radius(mu: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int | None = None,
                 rtol: float | None = None, executor: Executor | None = None,
                 progress: Progress = "auto") -> np.ndarray | float:
    """Stick radius c(mu, nu) of [S75] §2.2, broadcasting over arrays.

    Inside the table's domain (``numeric.core.table``: c >= 1e-5 up to the largest stick radius, every
    nu in (-1, 1/2]; for gamma <= 0.1, nu >= 0.44, up to 1 - c = 1e-13) c comes from the Chebyshev
    tables (about 6 ms for 1000 points at once, errors ``numeric.core.table_data.ERRORS``); below c = 1e-5 from the second-order law; elsewhere, or with
    ``use_table=False``, from ``flat_punch`` at ``level``: one by one, or mapped over
    ``executor`` (any ``concurrent.futures`` executor, or a Dask client's ``get_executor()``),
    with a progress bar and time to go on stderr: ``progress`` "auto" (the default) draws it when
    stderr is a terminal, True always, False never.

    With ``rtol`` (not together with ``level``) the cheapest route meeting it for each point:
    the asymptotic law (see ``flat_punch``), else the table where its recorded error (times
    ``TABLE_MARGIN``) meets rtol, else ``flat_punch(rtol=rtol)``. An
    ``AccuracyWarning`` from points solved through ``executor`` is raised in the workers.

    Examples
    --------
    >>> round(float(stick_radius(0.298714615962, 0.0)), 9)
    0.5
    """
    check_mu(mu)
    check_nu(nu)
    level_and_rtol(level, rtol)
    return _sweep("stick_radius", "c", table_stick_radius, _solved_c, mu, nu, use_table, level,
                  None if rtol is None else check_rtol(rtol), executor, check_progress(progress))


def friction_coefficient(c: ArrayLike, nu: ArrayLike, *, use_table: bool = True, level: int | None = None,
                         rtol: float | None = None, executor: Executor | None = None,
                         progress: Progress = "auto") -> np.ndarray | float:
    """Friction coefficient mu(c, nu) that produces stick radius c, broadcasting over arrays.

    From the Chebyshev table inside its domain, else from ``flat_punch`` (see ``stick_radius``,
    also for ``rtol``).
    """
    check_c(c)
    check_nu(nu)
    level_and_rtol(level, rtol)
    return _sweep("friction_coefficient", "mu", table_friction_coefficient, _solved_mu, c, nu, use_table, level,
                  None if rtol is None else check_rtol(rtol), executor, check_progress(progress))
