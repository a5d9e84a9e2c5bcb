"""Run time against error of every method for the flat punch and the sphere ([S75] §2, §3, §4).

Measures, for the cases nu in {0, 0.25, 0.45} x c in {0.1, 0.5, 0.9} plus the fully
adhesive case c = 1 for each nu, and near the largest stick radius (nu = 0: c = 0.99, 0.998;
nu = -0.5: c = 0.95, 0.98), every method at every resolution it offers:

* the paper's scheme ``numeric.baseline.scheme`` ([S75] §4): ``solve_friction`` on the friction
  mesh of §4.1 with coarse width h = 0.04 ... 0.0025 (N ~ 30 ... 460 intervals; h = 0.02 is
  the paper's), ``solve_adhesive`` on uniform meshes N = 25 ... 800 (N = 50 is the paper's
  mesh (ii)) and on the graded meshes (iii), (iv); the sphere's A by ``sphere_from_flat``
  ((4.13)-(4.17));
* our solver ``numeric.flat_punch`` at levels 0-4 (mu, P*, p(0) for given c; c for given
  mu), at c = 1 the discrete adhesive solver ``numeric.core.graded_collocation.solve_adhesive`` (``flat_punch``
  itself returns the closed form there, also listed); A by ``indentation_constant`` on the
  flat solution (what ``power_law(2, ...).A`` computes);
* the Chebyshev table route (``friction_coefficient``, ``stick_radius``,
  ``numeric.core.table.table_compliance``);
* the asymptotic formulas of ``asymptotics.first_order``: (2.28) and its inverse, the
  first-order compliance (2.34), the first-order central pressure (2.32)-(2.33), (2.36) at
  c = 1, and the second-order law of ``asymptotics.second_order``.

Errors are relative, |value - reference| / |reference|. References: the closed forms of
App. B at c = 1 ((B4), (4.10), (4.18)); for 0 < c < 1 our solver's finest level 4, whose
own error is bounded by its distance to level 3 and cross-checked against the paper's
scheme Aitken-extrapolated in h (an independent discretisation). The stick radius for
given mu is asked for at mu = mu_ref(c), so its reference is the case's c.

Run time: the median over repeated runs (until ``budget`` seconds or ``max_runs`` runs;
calls under 1 ms are looped so that one run lasts about 2 ms), after one untimed warm-up
call. The setup cost is measured separately: the first call with every ``functools`` cache
of ``numeric`` and ``asymptotics`` cleared, against later calls. The paper's scheme caches
its collocation matrix per (mesh, gamma), i.e. per case; that cache is cleared before each
timed run, so its run time is that of a case not solved before, as it is for our solver,
whose caches (reference meshes and Abel blocks per level, Gauss rules, the table) do not
depend on c or gamma.

    hertz-friction bench            # writes derivations/benchmark.md and .png (minutes)
    hertz-friction bench --quick    # nu = 0.25, c = 0.5 and 1, coarser meshes; prints only

``side_by_side`` times the tasks of the whole-plane issue in the same run as the paper's scheme at
h = 0.01: the full solution for given c and for given mu, inside c <= 0.95 and near c_max, at the
default level and through the rtol = 1e-4 route, and ``stick_radius`` over 1000 random points;
``numeric.studies.plane_bench`` the strip punch's same tasks in the same run (plane strain).

This module measures; ``numeric.studies.bench_report`` renders the Markdown and the plot.

On a shared machine set ``OPENBLAS_NUM_THREADS=1``: threaded BLAS under load was measured
3-6 times slower.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import os
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field

import numpy as np

from asymptotics import first_order, second_order
from asymptotics.adhesive import central_pressure_adhesive, compliance_adhesive, sphere_A_adhesive
from asymptotics.materials import gamma_from_nu

from numeric.baseline import scheme
from numeric.core import graded_collocation
from numeric.core.eigenvalue import operators_at
from numeric.core.graded_mesh import LEVELS
from numeric.core.table import table_compliance
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.power_law import indentation_constant, power_law
from numeric.solutions.sweep import friction_coefficient, stick_radius
from numeric.studies.equal_accuracy import PUBLISHED_H, EqualAccuracy, equal_accuracy, scheme_tolerance
from numeric.studies.plane_bench import plane_side_by_side
from numeric.studies.timing import SideBySide, Yardstick, clear_caches, median_time, power_law_time

__all__ = [
    "Case",
    "Config",
    "Row",
    "Reference",
    "Setup",
    "CrossCheck",
    "Headline",
    "Benchmark",
    "side_by_side",
    "FULL",
    "QUICK",
    "reference",
    "measure_case",
    "run",
    "time_to_reach",
    "best_error_within",
    "aitken",
    "headline",
]

# method names (also the legend of the plot)
SCHEME = "paper's scheme (§4)"
SCHEME_GRADED = "paper's scheme, graded meshes (iii), (iv)"
SOLVER = "our solver"
CLOSED_FORM = "flat_punch at c = 1 (closed form)"
TABLE = "Chebyshev table"
ASYMPTOTIC = "asymptotic formulas"
METHODS = (SCHEME, SCHEME_GRADED, SOLVER, CLOSED_FORM, TABLE, ASYMPTOTIC)

QUANTITIES = ("mu", "c", "P*", "p(0)", "A")
QUANTITY_TEXT = {
    "mu": "mu for given c",
    "c": "c for given mu (mu = reference mu of the case)",
    "P*": "compliance P* (2.4)",
    "p(0)": "central pressure p(0)",
    "A": "sphere's A (3.2)",
}

#: Cleared before each timed solve: the solver keeps the Abel integrals of the last few layouts (one per c and
#: level), which a repeated call of the same problem would find; a new problem would not.
PER_PROBLEM = operators_at.cache_clear
PUBLISHED_N = 50  # the paper's uniform adhesive mesh (ii) (§4)
TARGET = 1e-10  # accuracy asked of our solver in the headline


@dataclass(frozen=True, slots=True)
class Case:
    """Poisson's ratio and stick radius (c = 1: fully adhesive)."""

    nu: float
    c: float

    @property
    def gamma(self) -> float:
        return float(gamma_from_nu(self.nu))

    @property
    def adhesive(self) -> bool:
        return self.c == 1.0

    @property
    def label(self) -> str:
        return f"nu={self.nu:g}, c={self.c:g}"


@dataclass(frozen=True, slots=True)
class Config:
    """What to measure: cases, resolutions, method families and the timing budget."""

    cases: tuple[Case, ...]
    scheme_h: tuple[float, ...] = (0.04, 0.02, 0.01, 0.005, 0.0025)
    scheme_n: tuple[int, ...] = (25, 50, 100, 200, 400, 800)
    graded_meshes: tuple[str, ...] = ("iii", "iv")
    levels: tuple[int, ...] = (0, 1, 2, 3, 4)
    methods: frozenset[str] = frozenset({"scheme", "solver", "table", "asymptotic"})
    setup: bool = True
    budget: float = 0.5
    max_runs: int = 5
    #: runs per case of the side-by-side (``side_by_side``), within ``side_budget`` seconds: the ratios there are the
    #: point of it, and single calls on a shared machine scatter by 1.5x (medians of 5 runs were seen 5.5 ... 8.8 ms
    #: apart for one case)
    side_runs: int = 21
    side_budget: float = 1.0


#: nu in {0, 0.25, 0.45} x c in {0.1, 0.5, 0.9, 1}, and near the largest stick radius: nu = 0 (c_max = 0.998997),
#: c = 0.99, 0.998; nu = -0.5 (c_max = 0.982778), c = 0.95, 0.98.
FULL = Config(cases=tuple(Case(nu, c) for nu in (0.0, 0.25, 0.45) for c in (0.1, 0.5, 0.9, 1.0))
              + (Case(0.0, 0.99), Case(0.0, 0.998), Case(-0.5, 0.95), Case(-0.5, 0.98)))
QUICK = Config(
    cases=(Case(0.25, 0.5), Case(0.25, 1.0)),
    scheme_h=(0.04, 0.02, 0.01, 0.005),
    scheme_n=(25, 50, 100, 200),
    graded_meshes=(),
    budget=0.2,
    max_runs=3,
    side_runs=3,
    side_budget=0.2,
)


@dataclass(frozen=True, slots=True)
class Row:
    """One measured value: a method at one resolution, for one case and quantity."""

    nu: float
    c: float
    quantity: str
    method: str
    resolution: str
    size: int  # intervals N of the paper's scheme, unknowns of our solver, 0 otherwise
    rank: float  # orders the resolutions of a method, coarse to fine
    value: float
    reference: float
    seconds: float
    published: bool = False  # the paper's own resolution (h = 0.02, N = 50)
    is_reference: bool = False  # the row is the reference itself (our level 4 at 0 < c < 1)

    @property
    def error(self) -> float:
        """Relative error |value - reference| / |reference|."""
        return abs(self.value - self.reference) / abs(self.reference)


@dataclass(frozen=True, slots=True)
class Reference:
    """Reference values of one case and what they rest on.

    ``spread`` is the largest relative difference between our levels 4 and 3 over mu, P*,
    p(0), A (0 for the closed forms): an upper estimate of the level-4 error, the levels
    converging exponentially.
    """

    case: Case
    mu: float
    compliance: float
    central_pressure: float
    A: float
    basis: str
    spread: float

    def value(self, quantity: str) -> float:
        return {"mu": self.mu, "c": self.case.c, "P*": self.compliance, "p(0)": self.central_pressure,
                "A": self.A}[quantity]


@dataclass(frozen=True, slots=True)
class Setup:
    """First call with every cache cleared against later calls of the same case."""

    case: Case
    method: str
    resolution: str
    first: float
    repeat: float


@dataclass(frozen=True, slots=True)
class CrossCheck:
    """The paper's scheme Aitken-extrapolated in h against the level-4 reference."""

    case: Case
    quantity: str
    extrapolated: float
    uncertainty: float  # change of the extrapolant when the finest h is dropped
    order: float  # observed order log2 of the ratio of successive differences
    reference: float


@dataclass(frozen=True, slots=True)
class Headline:
    """Our solver at ``target`` against the paper's scheme at its published resolution.

    Times are medians over the cases, errors the worst over the cases; ``ratio`` is the
    median over the cases of (our time)/(paper's time). ``paper_error_in_our_time``: the
    best error of the paper's scheme among its resolutions that run within our time;
    ``our_error_in_paper_time``: the same for our solver within the paper's time (None
    when no level runs that fast); ``table_*``: the table route (None where not offered);
    ``paper_slope``: median over the cases of the least-squares slope s of log(error) against
    log(time) of the paper's scheme (error ~ time^-s), and ``paper_extrapolated_seconds``
    the median time at which that line reaches ``target`` (an extrapolation, not a run).
    """

    quantity: str
    cases: int
    target: float
    our_seconds: float
    our_levels: tuple[str, ...]
    paper_seconds: float
    paper_error: float
    ratio: float
    ratio_range: tuple[float, float]
    paper_error_in_our_time: float | None
    our_error_in_paper_time: float | None
    our_fastest_seconds: float
    table_seconds: float | None
    table_error: float | None
    paper_slope: float
    paper_extrapolated_seconds: float


@dataclass(frozen=True, slots=True)
class Benchmark:
    config: Config
    references: tuple[Reference, ...]
    rows: tuple[Row, ...]
    setups: tuple[Setup, ...]
    checks: tuple[CrossCheck, ...]
    seconds: float
    machine: dict = field(default_factory=dict)
    side_by_side: tuple[SideBySide, ...] = ()
    plane: tuple[SideBySide, ...] = ()  # numeric.studies.plane_bench, same run
    equal_accuracy: tuple[EqualAccuracy, ...] = ()  # numeric.studies.equal_accuracy, same run


def _timed(call: Callable[[], object], config: Config, before: Callable[[], object] | None = None,
           value: object = None):
    """The value of one warm-up call (unless ``value`` is known already) and the median time of later ones."""
    if value is None:
        if before is not None:
            before()
        value = call()
    return value, median_time(call, before=before, budget=config.budget, max_runs=config.max_runs, warm=True)


# ----------------------------------------------------------------------------- references
def reference(case: Case) -> Reference:
    """Reference values of ``case``: App. B closed forms at c = 1, else our level 4 (see module doc)."""
    return _reference_and_solutions(case)[0]


def _reference_and_solutions(case: Case) -> tuple[Reference, dict]:
    """The reference and the flat solutions of levels 4 and 3 it was computed from (none at c = 1)."""
    g = case.gamma
    if case.adhesive:
        return Reference(case, math.inf, float(compliance_adhesive(g)), float(central_pressure_adhesive(g)),
                         float(sphere_A_adhesive(g)), "closed forms (B4), (4.10), (4.18)", 0.0), {}
    fine, coarse = (flat_punch(nu=case.nu, c=case.c, level=level) for level in (4, 3))

    def values(s) -> np.ndarray:
        return np.array([s.mu, s.compliance, float(s.pressure(0.0)), indentation_constant(s, 2)])

    v4, v3 = values(fine), values(coarse)
    spread = float(np.max(np.abs(v4 - v3) / np.abs(v4)))
    return Reference(case, *map(float, v4), "our solver, level 4", spread), {4: fine, 3: coarse}


# ---------------------------------------------------------------------------- measurement
def _rows(case: Case, ref: Reference, method: str, resolution: str, size: int, rank: float,
          values: dict[str, tuple[float, float]], published: bool = False, is_reference: bool = False) -> list[Row]:
    return [Row(case.nu, case.c, q, method, resolution, size, rank, float(v), ref.value(q), t, published,
                is_reference and q != "c") for q, (v, t) in values.items()]


def _measure_scheme(case: Case, ref: Reference, config: Config) -> list[Row]:
    clear = scheme.collocation_matrix.cache_clear  # per (mesh, gamma), i.e. per case: a new case builds it
    rows = []

    def add(method: str, resolution: str, call, rank: float, published: bool) -> None:
        sol, t = _timed(call, config, clear)
        _, t_sphere = _timed(lambda: scheme.sphere_from_flat(sol), config)
        values = {"P*": (sol.compliance, t), "p(0)": (sol.central_pressure, t),
                  "A": (scheme.sphere_from_flat(sol).A, t + t_sphere)}
        if not case.adhesive:
            values = {"mu": (sol.mu, t), **values}
        rows.extend(_rows(case, ref, method, resolution, sol.mesh.size, rank, values, published))

    if case.adhesive:
        for n in config.scheme_n:
            add(SCHEME, f"N = {n}", lambda n=n: scheme.solve_adhesive(scheme.uniform_mesh(n), case.nu), n, n == PUBLISHED_N)
        for label in config.graded_meshes:
            mesh = scheme.paper_mesh(label)
            add(SCHEME_GRADED, f"mesh ({label}), N = {mesh.size}", lambda mesh=mesh: scheme.solve_adhesive(mesh, case.nu),
                mesh.size, False)
    else:
        for h in config.scheme_h:
            add(SCHEME, f"h = {h:g}", lambda h=h: scheme.solve_friction(case.c, case.nu, h=h, tol=scheme_tolerance(h)), 1.0 / h,
                h == PUBLISHED_H)
    return rows


def _measure_solver(case: Case, ref: Reference, config: Config, solved: dict | None = None) -> list[Row]:
    rows = []
    solved = solved or {}
    for level in config.levels:
        if case.adhesive:
            field_, t = _timed(lambda level=level: graded_collocation.solve_adhesive(case.gamma, LEVELS[level]), config)
            size = field_.n_unknowns
            values = {"P*": (field_.compliance, t), "p(0)": (float(field_.pressure(np.array([0.0]))[0]), t)}
            flat = field_
        else:
            flat, t = _timed(lambda level=level: flat_punch(nu=case.nu, c=case.c, level=level), config,
                             before=PER_PROBLEM, value=solved.get(level))
            size = int(flat.route.split(", ")[1].split()[0])
            inverse, t_inv = _timed(lambda level=level: flat_punch(nu=case.nu, mu=ref.mu, level=level), config,
                                    before=PER_PROBLEM)
            values = {"mu": (flat.mu, t), "c": (inverse.c, t_inv), "P*": (flat.compliance, t),
                      "p(0)": (float(flat.pressure(0.0)), t)}
        A, t_A = _timed(lambda flat=flat: indentation_constant(flat, 2), config)
        values["A"] = (A, t + t_A)
        rows.extend(_rows(case, ref, SOLVER, f"level {level}", size, level, values,
                          is_reference=level == 4 and not case.adhesive))
    if case.adhesive:
        closed, t = _timed(lambda: flat_punch(nu=case.nu, c=1.0), config)
        sphere, t_A = _timed(lambda: power_law(2, nu=case.nu, c=1.0), config)
        values = {"P*": (closed.compliance, t), "p(0)": (float(closed.pressure(0.0)), t), "A": (sphere.A, t_A)}
        rows.extend(_rows(case, ref, CLOSED_FORM, "App. B", 0, 0, values))
    return rows


def _measure_table(case: Case, ref: Reference, config: Config) -> list[Row]:
    if case.adhesive:
        return []  # c = 1 lies outside the table (it ends at 1 - c = 1e-13, or at c_max)
    mu, t_mu = _timed(lambda: friction_coefficient(case.c, case.nu), config)
    c, t_c = _timed(lambda: stick_radius(ref.mu, case.nu), config)
    p, t_p = _timed(lambda: float(table_compliance(case.c, case.gamma)[0]), config)
    return _rows(case, ref, TABLE, "level-3 fit", 0, 0, {"mu": (mu, t_mu), "c": (c, t_c), "P*": (p, t_p)})


def _measure_asymptotic(case: Case, ref: Reference, config: Config) -> list[Row]:
    g = case.gamma
    if case.adhesive:
        p, t = _timed(lambda: float(first_order.compliance_first_order(1.0, g)), config)  # (2.36)
        return _rows(case, ref, ASYMPTOTIC, "(2.36)", 0, 1, {"P*": (p, t)})
    values = {
        "mu": _timed(lambda: g * float(first_order.mu_over_gamma(case.c)), config),  # (2.28)
        "c": _timed(lambda: float(first_order.stick_radius_first_order(ref.mu, gamma=g)), config),  # (2.28) inverted
        "P*": _timed(lambda: float(first_order.compliance_first_order(case.c, g)), config),  # (2.34)
        "p(0)": _timed(lambda: 2.0 / math.pi + g * g * float(first_order.pressure_correction(0.0, case.c)),
                       config),  # (2.32)-(2.33)
    }
    rows = _rows(case, ref, ASYMPTOTIC, "first order", 0, 1, values)
    values = {
        "mu": _timed(lambda: g * float(second_order.mu_over_gamma_second_order(case.c, g)), config),
        "c": _timed(lambda: float(second_order.stick_radius_second_order(ref.mu, gamma=g)), config),
    }
    return rows + _rows(case, ref, ASYMPTOTIC, "second order", 0, 2, values)


_MEASURES = {"scheme": _measure_scheme, "solver": _measure_solver, "table": _measure_table,
             "asymptotic": _measure_asymptotic}


def measure_case(case: Case, config: Config) -> tuple[Reference, list[Row]]:
    """Reference and rows of every selected method for one case."""
    ref, solved = _reference_and_solutions(case)
    rows = []
    for family in ("scheme", "solver", "table", "asymptotic"):
        if family in config.methods:
            measure = _MEASURES[family]
            rows += measure(case, ref, config, solved) if family == "solver" else measure(case, ref, config)
    return ref, rows


def _measure_setup(config: Config) -> list[Setup]:
    """Cold first call (every cache cleared) and warm repeats, for one frictional and one adhesive case."""
    frictional = next((c for c in config.cases if c == Case(0.25, 0.5)), None) or next(
        (c for c in config.cases if not c.adhesive), None)
    adhesive = next((c for c in config.cases if c.adhesive), None)
    calls: list[tuple[Case, str, str, Callable[[], object]]] = []
    if frictional is not None:
        nu, c = frictional.nu, frictional.c
        if "scheme" in config.methods:
            calls += [(frictional, SCHEME, f"h = {h:g}", lambda h=h: scheme.solve_friction(c, nu, h=h, tol=scheme_tolerance(h)))
                      for h in config.scheme_h]
        if "solver" in config.methods:
            calls += [(frictional, SOLVER, f"level {lv}", lambda lv=lv: flat_punch(nu=nu, c=c, level=lv))
                      for lv in config.levels]
        if "table" in config.methods:
            calls.append((frictional, TABLE, "level-3 fit", lambda: friction_coefficient(c, nu)))
    if adhesive is not None:
        nu, g = adhesive.nu, adhesive.gamma
        if "scheme" in config.methods:
            calls += [(adhesive, SCHEME, f"N = {n}", lambda n=n: scheme.solve_adhesive(scheme.uniform_mesh(n), nu))
                      for n in config.scheme_n]
        if "solver" in config.methods:
            calls += [(adhesive, SOLVER, f"level {lv}", lambda lv=lv: graded_collocation.solve_adhesive(g, LEVELS[lv]))
                      for lv in config.levels]
    out = []
    for case, method, resolution, call in calls:
        clear_caches()
        t0 = time.perf_counter()
        call()
        first = time.perf_counter() - t0
        repeat = median_time(call, budget=config.budget, max_runs=config.max_runs, warm=True)
        out.append(Setup(case, method, resolution, first, repeat))
    return out


def aitken(values: Sequence[float]) -> tuple[float, float]:
    """Limit and observed order of the last three terms of a sequence at h, h/2, h/4 (Aitken's delta^2)."""
    d1, d2 = values[-2] - values[-3], values[-1] - values[-2]
    ratio = d1 / d2
    return values[-1] + d2 / (ratio - 1.0), math.log2(abs(ratio))


def _cross_checks(rows: Sequence[Row], references: Sequence[Reference]) -> list[CrossCheck]:
    out = []
    for ref in references:
        if ref.case.adhesive:
            continue
        for quantity in ("mu", "P*"):
            series = sorted((r for r in rows if r.method == SCHEME and r.quantity == quantity
                             and (r.nu, r.c) == (ref.case.nu, ref.case.c)), key=lambda r: r.rank)
            halving = [r for r in series if r.rank >= 1 / PUBLISHED_H - 1e-9]  # h = .02 and finer, halving
            if len(halving) < 4:
                continue
            values = [r.value for r in halving]
            ext, order = aitken(values)
            coarse, _ = aitken(values[:-1])
            out.append(CrossCheck(ref.case, quantity, ext, abs(ext - coarse), order, ref.value(quantity)))
    return out


def run(config: Config = FULL, progress: Callable[[str], object] | None = None) -> Benchmark:
    """Measure everything ``config`` asks for (the setup pass first, while the caches are cold)."""
    start = time.perf_counter()
    note = progress or (lambda message: None)
    setups = []
    if config.setup:
        note("setup: first calls with caches cleared")
        setups = _measure_setup(config)
    references, rows = [], []
    for case in config.cases:
        note(f"case {case.label}")
        ref, case_rows = measure_case(case, config)
        references.append(ref)
        rows += case_rows
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    machine = {"cores": os.cpu_count(), "blas_threads": os.environ.get("OPENBLAS_NUM_THREADS", "unset"),
               "load": load}
    note("side by side with the paper's scheme at h = 0.01")
    both = "scheme" in config.methods and "solver" in config.methods
    sides = side_by_side(config) if both else ()
    note("the paper's scheme refined to the rtol = 1e-4 route's accuracy")
    equal = equal_accuracy(INSIDE + NEAR, config.budget, config.max_runs) if both else ()
    note("plane strain: the strip punch's tasks, the plane scheme at h = 0.02")
    plane = plane_side_by_side(config.side_budget, config.side_runs) if both else ()
    return Benchmark(config, tuple(references), tuple(rows), tuple(setups), tuple(_cross_checks(rows, references)),
                     time.perf_counter() - start, machine, tuple(sides), tuple(plane), tuple(equal))


# --------------------------------------------------------------------------- side by side
SIDE_H = 0.01
BATCH = 1000
#: The side-by-side's (nu, c): inside c <= 0.95, and near c_max (nu = 0: 0.998997; nu = -1/2: 0.982778;
#: nu = 0.3: 1 - 4.1e-7).
INSIDE = ((0.0, 0.1), (0.0, 0.5), (0.25, 0.5), (0.25, 0.9), (0.45, 0.5), (-0.5, 0.5))
NEAR = ((0.0, 0.99), (0.0, 0.998), (-0.5, 0.95), (-0.5, 0.98), (0.3, 0.9999))


def side_by_side(config: Config) -> list[SideBySide]:
    """The tasks of issue 11 timed in one run against the paper's scheme at h = 0.01 (nu = 0.25, c = 0.5), which is
    timed again before each case of each task (its time: the median of all those runs).

    References: level 4 for the single solves (its error is ~1e-13), level 2 at 40 of the 1000
    random points of the batch (the table's error bound is 1e-10-ish, level 2's ~1e-11)."""
    budget, runs = config.side_budget, config.side_runs
    clear = scheme.collocation_matrix.cache_clear
    ref_mid = flat_punch(nu=0.25, c=0.5, level=4)
    sch = scheme.solve_friction(0.5, 0.25, h=SIDE_H, tol=scheme_tolerance(SIDE_H))
    yardstick = Yardstick(lambda: scheme.solve_friction(0.5, 0.25, h=SIDE_H, tol=scheme_tolerance(SIDE_H)),
                          before=clear, budget=budget, max_runs=runs)
    measured: list[tuple[str, float, float, int, str]] = []  # task, seconds, error, points, reference

    def full(s) -> tuple:  # what "the full solution" returns: mu or c, P*, p, q, u at a few points
        x = np.array([0.0, 0.5 * s.c, s.c, 0.5 * (1 + s.c)])
        return s.mu, s.c, s.compliance, s.pressure(x), s.shear(x), s.slip(x)

    def with_error(s) -> tuple:  # the same and its error estimate (on the solver route a second solve)
        return full(s) + (s.error,)

    def task(label: str, calls: list[tuple[Callable[[], object], Callable[[object], float]]], reference_: str,
             returns: Callable[[object], tuple] = full) -> None:
        times, errors = [], []
        for call, error in calls:
            value = call()
            times.append(yardstick.case(lambda call=call: returns(call()), before=PER_PROBLEM))
            errors.append(error(value))
        measured.append((label, statistics.median(times), max(errors), len(calls), reference_))

    def given_c(nu: float, c: float, **kw):
        ref = flat_punch(nu=nu, c=c, level=4)
        return (lambda: flat_punch(nu=nu, c=c, **kw),
                lambda s: max(abs(s.mu / ref.mu - 1), abs(s.compliance / ref.compliance - 1)))

    def given_mu(nu: float, c: float, **kw):
        ref = flat_punch(nu=nu, c=c, level=4)
        return (lambda: flat_punch(nu=nu, mu=ref.mu, **kw),
                lambda s: max(abs(s.gap / ref.gap - 1), abs(s.compliance / ref.compliance - 1)))

    inside, near = list(INSIDE), list(NEAR)
    task("full solution for given c <= 0.95 (level 2)", [given_c(nu, c) for nu, c in inside], "level 4")
    task("full solution for given c near c_max (level 2)", [given_c(nu, c) for nu, c in near], "level 4")
    task("full solution for given mu, c <= 0.95 (level 2)", [given_mu(nu, c) for nu, c in inside], "level 4")
    task("full solution for given mu near c_max (level 2)", [given_mu(nu, c) for nu, c in near], "level 4")
    task("the same with its error estimate: given c <= 0.95", [given_c(nu, c) for nu, c in inside], "level 4", with_error)
    task("the same with its error estimate: given c near c_max", [given_c(nu, c) for nu, c in near], "level 4",
         with_error)
    task("the same with its error estimate: given mu, c <= 0.95", [given_mu(nu, c) for nu, c in inside], "level 4",
         with_error)
    task("the same with its error estimate: given mu near c_max", [given_mu(nu, c) for nu, c in near], "level 4",
         with_error)
    task("full solution for given c, rtol = 1e-4", [given_c(nu, c, rtol=1e-4) for nu, c in inside + near], "level 4")
    task("full solution for given mu, rtol = 1e-4", [given_mu(nu, c, rtol=1e-4) for nu, c in inside + near], "level 4")
    rng = np.random.default_rng(11)
    mus, nus = rng.uniform(0.05, 2.0, BATCH), rng.uniform(-0.5, 0.49, BATCH)
    batch = stick_radius(mus, nus)
    t_batch = yardstick.case(lambda: stick_radius(mus, nus), warm=True)
    check = [(m, n, c) for m, n, c in zip(mus[:40], nus[:40], batch[:40])]
    err = max(abs(c / flat_punch(nu=n, mu=m).c - 1) for m, n, c in check)
    measured.append((f"stick_radius of {BATCH} random (mu, nu), mu in [0.05, 2], nu in [-0.5, 0.49] (one call)",
                     t_batch, err, 40, "level 2 at 40 of the points"))
    scheme_error = max(abs(sch.mu / ref_mid.mu - 1), abs(sch.compliance / ref_mid.compliance - 1))
    return yardstick.rows(("paper's scheme, h = 0.01, nu = 0.25, c = 0.5 (mu, P*)", scheme_error, 1, "level 4"), measured)


# ------------------------------------------------------------------------------ headline
def time_to_reach(points: Iterable[tuple[float, float]], target: float) -> float | None:
    """Shortest time among (seconds, error) points whose error is at most ``target`` (None if none)."""
    times = [t for t, e in points if e <= target]
    return min(times) if times else None


def best_error_within(points: Iterable[tuple[float, float]], seconds: float) -> float | None:
    """Smallest error among (seconds, error) points that run within ``seconds`` (None if none)."""
    errors = [e for t, e in points if t <= seconds]
    return min(errors) if errors else None


def headline(rows: Sequence[Row], quantity: str, target: float = TARGET) -> Headline | None:
    """Our solver's time to ``target`` against the paper's scheme at its published resolution.

    Per case: our time = the shortest level reaching ``target``; the paper's = its published
    resolution. Cases where no level reaches the target are left out, and rows that are
    the reference itself are not used. None when no case has both.
    """
    per_case = []
    cases = sorted({(r.nu, r.c) for r in rows if r.quantity == quantity})
    for key in cases:
        mine = [r for r in rows if (r.nu, r.c) == key and r.quantity == quantity and not r.is_reference]
        ours = [(r.seconds, r.error) for r in mine if r.method == SOLVER]
        paper = [(r.seconds, r.error) for r in mine if r.method == SCHEME]
        published = [r for r in mine if r.method == SCHEME and r.published]
        t_ours = time_to_reach(ours, target)
        if t_ours is None or not published:
            continue
        level = next(r.resolution for r in mine if r.method == SOLVER and r.seconds == t_ours)
        table = [(r.seconds, r.error) for r in mine if r.method == TABLE]
        slope, t_extrapolated = power_law_time(paper, target)
        per_case.append((t_ours, level, published[0], best_error_within(paper, t_ours),
                         best_error_within(ours, published[0].seconds), min(t for t, _ in ours), table,
                         slope, t_extrapolated))
    if not per_case:
        return None
    ratios = [t / pub.seconds for t, _, pub, *_ in per_case]
    in_paper_time = [x[4] for x in per_case]
    tables = [x[6][0] for x in per_case if x[6]]
    return Headline(
        quantity=quantity,
        cases=len(per_case),
        target=target,
        our_seconds=statistics.median(x[0] for x in per_case),
        our_levels=tuple(sorted({x[1] for x in per_case})),
        paper_seconds=statistics.median(x[2].seconds for x in per_case),
        paper_error=max(x[2].error for x in per_case),
        ratio=statistics.median(ratios),
        ratio_range=(min(ratios), max(ratios)),
        paper_error_in_our_time=None if any(x[3] is None for x in per_case) else max(x[3] for x in per_case),
        our_error_in_paper_time=None if any(e is None for e in in_paper_time) else max(in_paper_time),
        our_fastest_seconds=statistics.median(x[5] for x in per_case),
        table_seconds=statistics.median(t for t, _ in tables) if tables else None,
        table_error=max(e for _, e in tables) if tables else None,
        paper_slope=statistics.median(x[7] for x in per_case),
        paper_extrapolated_seconds=statistics.median(x[8] for x in per_case),
    )
