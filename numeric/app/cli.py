"""The ``hertz-friction`` command line.

Subcommands: ``sphere``, ``punch``, ``cone``, ``power-law`` (a contact in SI units,
``numeric.app.contact``), ``cylinder`` and ``strip`` (plane strain, load per unit length,
``numeric.app.plane_contact``), ``solve`` (one dimensionless case), ``table`` (a sweep over mu and nu),
and the studies: ``figures``, ``bench``, ``stability``, ``derivations`` (the committed documents)
and ``tables`` (the paper's tables). ``hertz-friction CMD --help`` describes each.

Exit codes: 0 success; 2 bad usage or bad input (argparse's convention; the message, naming
the input, goes to stderr without a traceback); 1 numerical failure (``SolverError``) or no
solution (``NoEigenvalueError``: no friction coefficient gives the stick radius asked for); for
``table``, any failed row, the others still being written.
"""

from __future__ import annotations

import argparse
import csv
import io
import itertools
import json
import math
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

_PREFIXES = {-12: "p", -9: "n", -6: "u", -3: "m", 0: "", 3: "k", 6: "M", 9: "G", 12: "T"}
_PHYSICAL = ("sphere", "punch", "cone", "power-law")


def _si(value: float | None, unit: str) -> str:
    """``value`` with an SI prefix and 6 significant digits, e.g. 1.7e-4 m -> '170 um'."""
    if value is None or not math.isfinite(value):
        return "infinite" if value is not None else "-"
    if value == 0.0:
        return f"0 {unit}"
    exponent = max(-12, min(12, 3 * math.floor(math.log10(abs(value)) / 3)))
    return f"{value / 10.0**exponent:.6g} {_PREFIXES[exponent]}{unit}"


def _material_args(parser: argparse.ArgumentParser) -> None:
    given = parser.add_mutually_exclusive_group(required=True)
    given.add_argument("--load", type=float, metavar="P", help="normal force P, N")
    given.add_argument("--approach", type=float, metavar="DELTA", help="approach delta of the two bodies, m")
    modulus = parser.add_mutually_exclusive_group(required=True)
    modulus.add_argument("--E", type=float, help="Young's modulus of the half-space, Pa")
    modulus.add_argument("--G", type=float, help="shear modulus of the half-space, Pa")
    parser.add_argument("--nu", type=float, required=True, help="Poisson's ratio of the half-space, in (-1, 1/2]")
    parser.add_argument("--mu", type=float, required=True, help="Coulomb friction coefficient, >= 0 (inf: full stick)")
    indenter = parser.add_mutually_exclusive_group()
    indenter.add_argument("--indenter-E", type=float, metavar="E", help="Young's modulus of the indenter, Pa "
                          "(default: rigid)")
    indenter.add_argument("--indenter-G", type=float, metavar="G", help="shear modulus of the indenter, Pa")
    parser.add_argument("--indenter-nu", type=float, metavar="NU", help="Poisson's ratio of the indenter "
                        "(required with --indenter-E/--indenter-G)")
    parser.add_argument("--level", type=int, default=2, choices=(1, 2, 3, 4),
                        help="solver resolution level (default 2, ~1e-10; 3: ~1e-12, slower)")
    parser.add_argument("--json", action="store_true", help="print one JSON object (SI units) instead of text")


def _build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="hertz-friction",
        description="Hertz contact with finite friction (D. A. Spence, J. Elasticity 5 (1975) 297-319).",
        epilog="Exit codes: 0 ok, 1 numerical failure or no solution, 2 bad usage or input.",
    )
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    _physical_parsers(commands)
    _line_contact_parsers(commands)
    _solve_parser(commands)
    _table_parser(commands)
    _study_parsers(commands)
    return parser


def _physical_parsers(commands) -> None:
    phys = "Press {what} into an elastic half-space with friction; SI units in and out (N, m, Pa)."
    p = commands.add_parser("sphere", help="a sphere of radius R (Hertz)", description=phys.format(what="a sphere"))
    p.add_argument("--radius", type=float, required=True, help="sphere radius R, m")
    _material_args(p)
    p = commands.add_parser("punch", help="a flat-ended punch of radius a",
                            description=phys.format(what="a rigid flat punch"))
    p.add_argument("--radius", type=float, required=True, help="punch radius a, m")
    _material_args(p)
    p = commands.add_parser("cone", help="a cone z = r cot(theta)", description=phys.format(what="a cone"))
    p.add_argument("--semi-angle-deg", "--semi-angle", type=float, required=True, metavar="DEG", dest="semi_angle_deg",
                   help="semi-angle theta at the apex, degrees, in (45, 90) (e.g. 70.3: Berkovich-equivalent); "
                        "the same unit as PowerLaw.cone")
    _material_args(p)
    p = commands.add_parser("power-law", help="a body z = k r^n or z = r^n/(n b^(n-1))",
                            description=phys.format(what="a power-law body z = k r^n"))
    p.add_argument("--n", type=float, required=True, help="exponent n > 0 (2: sphere, 1: cone)")
    shape = p.add_mutually_exclusive_group(required=True)
    shape.add_argument("--b", type=float, help="Spence's body length b, m: z = r^n/(n b^(n-1))")
    shape.add_argument("--k", type=float, help="coefficient k, m^(1-n): z = k r^n")
    _material_args(p)


def _solve_parser(commands) -> None:
    p = commands.add_parser("solve", help="one dimensionless case: c, mu, P* (and A, C for z ~ r^n)",
                            description="Solve the dimensionless problem of [S75] §2 (and §3 with --n).")
    material = p.add_mutually_exclusive_group(required=True)
    material.add_argument("--nu", type=float, help="Poisson's ratio, in (-1, 1/2]")
    material.add_argument("--gamma", type=float, help="coupling constant (2.2) instead of nu (dissimilar bodies)")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--mu", type=float, help="friction coefficient: find the stick radius c")
    which.add_argument("--c", type=float, help="stick radius / contact radius: find mu")
    p.add_argument("--n", type=float, help="also the power-law indenter z ~ r^n (2: sphere)")
    p.add_argument("--level", type=int, default=2, choices=(1, 2, 3, 4), help="solver level (default 2)")
    p.add_argument("--json", action="store_true", help="print one JSON object")


def _table_parser(commands) -> None:
    p = commands.add_parser(
        "table", help="c and P* over ranges of mu and nu (CSV or JSON)",
        description="Tabulate the stick radius c and the flat-punch compliance P0* (optionally the sphere's A) "
                    "over mu and nu. A range is START:STOP:COUNT (inclusive, evenly spaced) or a comma list. "
                    "Rows whose solve fails are written with an error status and the exit code is 1.")
    p.add_argument("--mu", required=True, metavar="RANGE", help="friction coefficients, e.g. 0.1:1:10 or 0.1,0.3")
    p.add_argument("--nu", required=True, metavar="RANGE", help="Poisson's ratios, e.g. 0,0.25,0.49")
    p.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default csv)")
    p.add_argument("--output", metavar="FILE", help="write to FILE instead of stdout")
    p.add_argument("--sphere", action="store_true", help="add the sphere's A (3.2), C (3.4) and P* (3.17)")
    p.add_argument("--level", type=int, default=2, choices=(1, 2, 3, 4), help="solver level (default 2)")
    p.add_argument("--progress", choices=("auto", "always", "never"), default="auto",
                   help="progress bar with time to go on stderr (auto: when stderr is a terminal)")
    _quiet_arg(p)


def _quiet_arg(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--quiet", action="store_true", help="no progress on stderr (shown by default on a terminal)")


def _progress(args) -> bool | str:
    """The ``progress`` of numeric.solutions.progress for the options given: --quiet, else --progress, else auto."""
    if args.quiet:
        return False
    return {"auto": "auto", "always": True, "never": False}[getattr(args, "progress", "auto")]


def _study_parsers(commands) -> None:
    p = commands.add_parser("figures", help="write the figures (PNG/SVG)", description="Write the figures.")
    p.add_argument("--output", default="figures", metavar="DIR", help="directory (default ./figures)")
    p.add_argument("--format", action="append", choices=("png", "svg", "pdf"), dest="formats",
                   help="file format, repeatable (default png)")
    p.add_argument("--only", action="append", metavar="NAME", dest="names",
                   help="only this figure (a key of numeric.studies.figure_plots.FIGURES), repeatable")
    _quiet_arg(p)
    p = commands.add_parser("bench", help="the benchmark: error against run time of every method",
                            description="Run time against error of every method for the flat punch and the sphere "
                                        "(numeric.studies.bench); writes benchmark.md and benchmark.png.")
    p.add_argument("--quick", action="store_true", help="nu = 0.25, c = 0.5 and 1 only, coarser meshes (~1 min)")
    p.add_argument("--output", type=Path, default=None,
                   help="directory for benchmark.md and benchmark.png (default: derivations/ for the full run; "
                        "the quick run only prints unless given)")
    p.add_argument("--no-plot", action="store_true", help="do not draw benchmark.png")
    _quiet_arg(p)
    p = commands.add_parser("stability", help="the stability study: parameter sweep, honesty of error, round-off",
                            description="Stress tests of numerical stability (numeric.studies.stability); writes "
                                        "stability.md.")
    p.add_argument("--quick", action="store_true", help="small grid and coarse levels (a few seconds)")
    p.add_argument("--output", type=Path, default=None,
                   help="the report (default: derivations/stability.md of the source checkout)")
    p = commands.add_parser("derivations", help="regenerate derivations/ (documents, figures) in a source checkout",
                            description="Regenerate the committed documents and figures of derivations/ "
                                        "(numeric.studies.documents).")
    p.add_argument("--fast", action="store_true", help="skip the blocks and figures that need the full solver")
    p.add_argument("--check", action="store_true", help="compare with the committed files instead of writing")
    p.add_argument("--directory", type=Path, default=None,
                   help="the derivations folder (default: derivations/ of the source checkout)")
    p = commands.add_parser(
        "tables", help="print the tables of Spence (1975) beside our recomputation and the exact values",
        description="Print the paper's tables (the mesh and nu tables of §4, mu(c) of §4.2, 1/A of the sphere) "
                    "beside the paper's own scheme rerun and the full solution (numeric.studies.paper_tables; "
                    "the same as derivations/paper_tables.md). Takes about half a minute.")
    _quiet_arg(p)


def _elastic_bodies(args):
    from numeric.app.contact import elastic

    half = elastic(E=args.E, G=args.G, nu=args.nu)
    if args.indenter_E is None and args.indenter_G is None:
        if args.indenter_nu is not None:
            raise ValueError("indenter_nu needs --indenter-E or --indenter-G (the indenter is rigid by default)")
        return half, None
    if args.indenter_nu is None:
        raise ValueError("indenter_nu (Poisson's ratio of the indenter) is required with --indenter-E/--indenter-G")
    return half, elastic(E=args.indenter_E, G=args.indenter_G, nu=args.indenter_nu, prefix="indenter_")


def _shape(args):
    from numeric.app.contact import FlatPunch, PowerLaw

    if args.command == "sphere":
        return PowerLaw.sphere(args.radius)
    if args.command == "punch":
        return FlatPunch(args.radius)
    if args.command == "cone":
        return PowerLaw.cone(args.semi_angle_deg)
    if args.b is not None:
        return PowerLaw.from_length(args.n, args.b)
    return PowerLaw(args.n, args.k)


def _run_physical(args) -> int:
    from numeric.app.contact import SmallStrainWarning, indent

    half, indenter = _elastic_bodies(args)
    with warnings.catch_warnings():  # said in the output instead (text: a last line; JSON: "warning")
        warnings.simplefilter("ignore", SmallStrainWarning)
        contact = indent(_shape(args), half, mu=args.mu, load=args.load, approach=args.approach, indenter=indenter,
                         level=args.level)
    return _write(contact, args.json, _describe)


def _describe(s) -> str:
    """The contact as a human-readable table with units."""
    from numeric.app.contact import SMALL_STRAIN, small_strain_message

    pair = s.materials
    hs = pair.half_space
    body = "rigid" if pair.indenter is None else \
        f"elastic (E = {_si(pair.indenter.E, 'Pa')}, nu = {pair.indenter.nu:g})"
    lines = [
        f"{s.shape.description}, {body}, on a half-space E = {_si(hs.E, 'Pa')}, nu = {hs.nu:g}; mu = {s.mu:g}",
        f"reduced modulus E* = {_si(pair.reduced_modulus, 'Pa')}, gamma = {pair.gamma:.6g} (= Dundurs beta; "
        f"CONTACT: G = {_si(pair.kalker.G, 'Pa')}, nu = {pair.kalker.nu:.6g}, K = {pair.kalker.K:.6g})",
        "",
    ]
    ref = s.frictionless if s.frictionless is not None else s
    ratios = s.ratios

    def at(value, where):
        if where is None or value == 0.0:
            return _si(value, "Pa")
        return f"{_si(value, 'Pa')} at r = {_si(where, 'm')}"

    rows = [
        ("contact radius a", _si(s.contact_radius, "m"), _si(ref.contact_radius, "m"), ratios["contact_radius"]),
        ("stick radius c a", _si(s.stick_radius, "m"), _si(ref.stick_radius, "m"), None),
        ("approach delta", _si(s.approach, "m"), _si(ref.approach, "m"), ratios["approach"]),
        ("load P", _si(s.load, "N"), _si(ref.load, "N"), ratios["load"]),
        ("stiffness dP/d delta", _si(s.stiffness, "N/m"), _si(ref.stiffness, "N/m"), ratios["stiffness"]),
        ("mean pressure", _si(s.mean_pressure, "Pa"), _si(ref.mean_pressure, "Pa"), None),
        ("max pressure", at(s.max_pressure, s.max_pressure_radius), at(ref.max_pressure, ref.max_pressure_radius),
         ratios["max_pressure"]),
        ("max shear", at(s.max_shear, s.max_shear_radius), at(ref.max_shear, ref.max_shear_radius), None),
    ]
    width = max(len(r[1]) for r in rows) + 3
    lines.append(f"{'':24}{'with friction':{width}}{'frictionless':{width}}ratio")
    for name, value, reference, ratio in rows:
        lines.append(f"{name:24}{value:{width}}{reference:{width}}{'' if ratio is None else f'{ratio:.6g}'}")
    lines += ["", f"stick fraction c = {s.c:.9g}, P* = {s.compliance:.9g} (flat punch P0* = {s.flat_compliance:.9g})"
              + ("" if s.A is None else f", A = {s.A:.9g}"),
              f"route: {s.route}; estimated absolute error of c and P*: {s.error:.1e}"]
    if s.strain > SMALL_STRAIN:
        lines.append(f"warning: {small_strain_message(s.strain)}")
    return "\n".join(lines) + "\n"


def _run_solve(args) -> int:
    from numeric import flat_punch, power_law

    if args.n is None:
        sol, law = flat_punch(nu=args.nu, gamma=args.gamma, mu=args.mu, c=args.c, level=args.level), None
    else:
        law = power_law(args.n, nu=args.nu, gamma=args.gamma, mu=args.mu, c=args.c, level=args.level)
        sol = law.flat
    result = {"nu": sol.nu, "gamma": sol.gamma, "mu": sol.mu, "c": sol.c, "compliance": sol.compliance,
              "error": sol.error, "route": sol.route}
    if law is not None:
        result.update({"n": law.n, "A": law.A, "C": law.C, "power_law_compliance": law.compliance})
    if args.json:
        from numeric.app.contact import json_ready
        sys.stdout.write(json.dumps(json_ready(result), allow_nan=False) + "\n")
        return 0
    material = f"nu = {sol.nu:g} (gamma = {sol.gamma:.9g})" if sol.nu is not None else f"gamma = {sol.gamma:.9g}"
    out = [f"{material}, mu = {sol.mu:.9g}",
           f"stick radius / contact radius c = {sol.c:.9g}",
           f"flat-punch compliance P0* = {sol.compliance:.9g}   (P = 4 G a P* delta / (1 - nu), (2.4))"]
    if law is not None:
        out += [f"power law n = {law.n:g}: A = {law.A:.9g} (delta = A a^n / b^(n-1), (3.2)), C = {law.C:.9g} (3.4), "
                f"P* = {law.compliance:.9g} (3.17)"]
    found = "mu" if args.c is not None else "c"
    out.append(f"route: {sol.route}; estimated absolute error of {found} and P*: {sol.error:.1e}")
    sys.stdout.write("\n".join(out) + "\n")
    return 0


def _parse_range(text: str, name: str) -> list[float]:
    """START:STOP:COUNT (inclusive, evenly spaced) or a comma-separated list."""
    try:
        if ":" in text:
            start, stop, count = text.split(":")
            n = int(count)
            if n < 1:
                raise ValueError
            a, b = float(start), float(stop)
            # 12 significant digits: 0.1:0.5:3 gives 0.3, not 0.30000000000000004
            return [a] if n == 1 else [float(f"{a + (b - a) * i / (n - 1):.12g}") for i in range(n)]
        return [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise ValueError(f"{name} must be START:STOP:COUNT or a comma list of numbers, got {text!r}") from None


def _run_table(args) -> int:
    from asymptotics.materials import check_mu, check_nu

    from numeric import NoEigenvalueError, SolverError, flat_punch, power_law
    from numeric.solutions.progress import progress_bar

    mus = _parse_range(args.mu, "mu")
    nus = _parse_range(args.nu, "nu")
    if not mus or not nus:
        raise ValueError("mu and nu need at least one value each")
    for m in mus:
        check_mu(m)
    for v in nus:
        check_nu(v)
    total = len(mus) * len(nus)
    rows, failed = [], 0
    with progress_bar(total, "table", _progress(args), unit="row") as bar:
        for nu, mu in itertools.product(nus, mus):
            row = {"nu": nu, "gamma": None, "mu": mu, "c": None, "compliance": None, "error": None, "route": None}
            if args.sphere:
                row.update({"sphere_A": None, "sphere_C": None, "sphere_compliance": None})
            try:
                if args.sphere:
                    law = power_law(2, nu=nu, mu=mu, level=args.level)
                    sol = law.flat
                    row.update({"sphere_A": law.A, "sphere_C": law.C, "sphere_compliance": law.compliance})
                else:
                    sol = flat_punch(nu=nu, mu=mu, level=args.level)
                row.update({"gamma": sol.gamma, "c": sol.c, "compliance": sol.compliance, "error": sol.error,
                            "route": sol.route})
                row["status"] = "ok"
            except (SolverError, NoEigenvalueError) as err:
                failed += 1
                row["status"] = f"failed: {err}"
            rows.append(row)
            bar.update()
    text = _format_rows(rows, args.format)
    if args.output:
        with open(args.output, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    if failed:
        sys.stderr.write(f"hertz-friction table: {failed} of {total} rows failed (status column)\n")
        return 1
    return 0


def _format_rows(rows: list[dict], fmt: str) -> str:
    if fmt == "json":
        from numeric.app.contact import json_ready
        return json.dumps(json_ready(list(rows)), indent=1, allow_nan=False) + "\n"
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    for r in rows:
        # repr of a plain float (numpy 2 writes np.float64(...) for its own scalars): shortest round-trip digits
        writer.writerow({k: "" if v is None else (repr(float(v)) if isinstance(v, float) else v) for k, v in r.items()})
    return buffer.getvalue()


def _run_figures(args) -> int:
    from numeric.studies.figure_plots import write_figures

    paths = write_figures(args.output, formats=tuple(args.formats or ("png",)), names=args.names,
                          progress=_progress(args))
    for path in paths:
        sys.stdout.write(f"{path}\n")
    return 0


def _checkout_path(given: Path | None, command: str, file: str = "") -> Path | None:
    """``given``, or ``file`` in the source checkout's derivations/ (None, with a message, if there is none)."""
    from numeric.studies.documents import source_derivations

    if given is not None:
        return given
    found = source_derivations()
    if found is None:
        sys.stderr.write(f"hertz-friction {command}: error: needs a source checkout installed with pip install -e "
                         "(no derivations/ beside the package), or an explicit path\n")
        return None
    return found / file if file else found


def _run_bench(args) -> int:
    from numeric.studies import bench
    from numeric.studies.bench_report import plot, render
    from numeric.studies.documents import source_derivations

    output = args.output if args.output is not None or args.quick else source_derivations()
    report = (lambda message: None) if args.quiet else (lambda message: print(message, file=sys.stderr))
    result = bench.run(bench.QUICK if args.quick else bench.FULL, progress=report)
    text = render(result)
    if output is not None:
        output.mkdir(parents=True, exist_ok=True)
        (output / "benchmark.md").write_text(text, encoding="utf-8")
        if not args.no_plot:
            plot(result, output / "benchmark.png")
    sys.stdout.write(text)
    return 0


def _run_stability(args) -> int:
    from numeric.studies.stability import run
    from numeric.studies.stability_report import write_report

    output = _checkout_path(args.output, "stability", "stability.md")
    if output is None:
        return 2
    report = run(quick=args.quick)
    write_report(report, output)
    sys.stdout.write(f"wrote {output} ({len(report.points)} calls, {sum(v for _, v in report.seconds):.0f} s CPU)\n")
    return 0


#: The environment variables that pin the BLAS to one thread (OpenBLAS, the numpy and scipy wheels' BLAS; MKL; OpenMP).
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")


def one_blas_thread_environment() -> dict[str, str]:
    """This process's environment with the BLAS pinned to one thread (``BLAS_THREAD_VARIABLES``), for a child process
    that must compute as the committed documents were computed."""
    return dict(os.environ, **{name: "1" for name in BLAS_THREAD_VARIABLES})


def _run_derivations(args) -> int:
    from numeric.studies.documents import regenerate

    directory = _checkout_path(args.directory, "derivations")
    if directory is None:
        return 2
    if not args.fast and os.environ.get("OPENBLAS_NUM_THREADS") != "1":
        # the solver's figures are written to 10 digits and their last ones follow the BLAS's summation order: a
        # threaded OpenBLAS moved plane_strain.md's mu(nu = 0.3, c = 0.05) by 2e-11 and the slip figure's u by 5e-10
        # of tiny values. The committed files are one thread's; a process whose BLAS is already loaded cannot be
        # changed, so the run goes to a child process with the BLAS pinned (numpy's SIMD paths left these files alone)
        command = [sys.executable, "-m", "numeric.app.cli", "derivations", "--directory", str(directory)]
        return subprocess.run(command + ["--check"] * args.check, env=one_blas_thread_environment(),
                              check=False).returncode
    stale = regenerate(directory, fast=args.fast, check=args.check, report=lambda m: sys.stdout.write(m + "\n"))
    if stale:
        sys.stderr.write("out of date (run python derivations/regenerate.py): " + ", ".join(stale) + "\n")
        return 1
    return 0


def _run_tables(args) -> int:
    from numeric.studies.paper_tables import render

    sys.stdout.write(render(progress=_progress(args)) + "\n")
    return 0


_RUN = {"solve": _run_solve, "table": _run_table, "figures": _run_figures, "bench": _run_bench,
        "stability": _run_stability, "derivations": _run_derivations, "tables": _run_tables,
        "cylinder": lambda args: _run_line_contact(args), "strip": lambda args: _run_line_contact(args)}


def _line_contact_parsers(commands) -> None:
    """``cylinder`` and ``strip``: plane strain (issue 14), load per unit length."""
    text = ("Press {what} into an elastic half-space in plane strain (a line contact) with friction; SI units in and "
            "out (N/m, m, Pa). The indentation depth of a half-plane is not defined: the load-width relation, the "
            "tractions and the slip are reported instead.")
    for name, size, helptext in (("cylinder", "--radius", "cylinder radius R, m"),
                                 ("strip", "--half-width", "half-width a of the rigid flat strip punch, m")):
        p = commands.add_parser(name, help="a cylinder of radius R (line contact)" if name == "cylinder" else
                                "a rigid flat strip punch of half-width a (line contact)",
                                description=text.format(what="a cylinder" if name == "cylinder" else "a rigid strip punch"))
        p.add_argument(size, type=float, required=True, help=helptext)
        p.add_argument("--load-per-length", type=float, required=True, metavar="P", help="load per unit length P, N/m")
        modulus = p.add_mutually_exclusive_group(required=True)
        modulus.add_argument("--E", type=float, help="Young's modulus of the half-space, Pa")
        modulus.add_argument("--G", type=float, help="shear modulus of the half-space, Pa")
        p.add_argument("--nu", type=float, required=True, help="Poisson's ratio of the half-space, in (-1, 1/2] "
                       "(plane stress: give nu/(1 + nu))")
        p.add_argument("--mu", type=float, required=True, help="Coulomb friction coefficient, >= 0 (inf: full stick)")
        indenter = p.add_mutually_exclusive_group()
        indenter.add_argument("--indenter-E", type=float, metavar="E", help="Young's modulus of the indenter, Pa "
                              "(default: rigid)")
        indenter.add_argument("--indenter-G", type=float, metavar="G", help="shear modulus of the indenter, Pa")
        p.add_argument("--indenter-nu", type=float, metavar="NU", help="Poisson's ratio of the indenter "
                       "(required with --indenter-E/--indenter-G)")
        p.add_argument("--level", type=int, default=2, choices=(1, 2, 3, 4),
                       help="solver resolution level (default 2, ~1e-10)")
        p.add_argument("--json", action="store_true", help="print one JSON object (SI units) instead of text")


def _run_line_contact(args) -> int:
    from numeric.app.plane_contact import press_cylinder, press_strip

    half, indenter = _elastic_bodies(args)
    press = press_cylinder if args.command == "cylinder" else press_strip
    size = args.radius if args.command == "cylinder" else args.half_width
    contact = press(size, half, mu=args.mu, load=args.load_per_length, indenter=indenter, level=args.level)
    return _write(contact, args.json, _describe_line)


def _write(contact, as_json: bool, describe) -> int:
    """The contact on standard output, as JSON (SI, ``to_dict``) or as ``describe``'s table; exit code 0."""
    sys.stdout.write(json.dumps(contact.to_dict(), allow_nan=False) + "\n" if as_json else describe(contact))
    return 0


def _describe_line(s) -> str:
    """A line contact as a human-readable table with units."""
    pair = s.materials
    hs = pair.half_space
    body = "rigid" if pair.indenter is None else f"elastic (E = {_si(pair.indenter.E, 'Pa')}, nu = {pair.indenter.nu:g})"
    what = f"cylinder, radius {_si(s.size, 'm')}" if s.shape == "cylinder" else f"strip punch, half-width {_si(s.size, 'm')}"
    reference = "Hertz" if s.shape == "cylinder" else "frictionless (Sadowsky)"

    unresolved = "not resolved (c < 1e-5)"

    def at(value, where):
        if value is None:
            return unresolved
        return "infinite (at the edges)" if not math.isfinite(value) else f"{_si(value, 'Pa')} at x = {_si(where, 'm')}"

    def ratio(a, b):
        return f"{a / b:.6g}" if a is not None and math.isfinite(a) and math.isfinite(b) and b != 0.0 else ""

    def slip(value):
        if value is None:
            return unresolved
        return _si(value, "m") if s.shape == "strip" else f"{value:.6g} m/(N/m)"
    rows = [
        ("contact half-width a", _si(s.half_width, "m"), _si(s.frictionless_half_width, "m"),
         ratio(s.half_width, s.frictionless_half_width)),
        ("stick half-width c a", _si(s.stick_half_width, "m"), "0 m", ""),
        ("centre pressure", at(s.centre_pressure, 0.0).split(" at x")[0], _si(s.frictionless_centre_pressure, "Pa"),
         ratio(s.centre_pressure, s.frictionless_centre_pressure)),
        ("max pressure", at(s.max_pressure, s.max_pressure_at), at(s.frictionless_max_pressure, 0.0),
         ratio(s.max_pressure, s.frictionless_max_pressure)),
        ("max shear", at(s.max_shear, s.max_shear_at), "0 Pa", ""),
        ("slip at x = a" if s.shape == "strip" else "slip rate du/dP at x = a",
         slip(s.slip_edge), "", ""),
    ]
    if s.shape == "cylinder":  # the slip accumulated over the loading (the strip's largest is the one at x = a)
        rows.append(("max slip (accumulated)", unresolved if s.max_slip is None else
                     f"{_si(s.max_slip, 'm')} at x = {_si(s.max_slip_at, 'm')}", "0 m", ""))
    width = max(len(r[1]) for r in rows) + 3
    lines = [f"{what}, {body}, on a half-space E = {_si(hs.E, 'Pa')}, nu = {hs.nu:g} (plane strain); mu = {s.mu:g}; "
             f"load {_si(s.load, 'N/m')}",
             f"reduced modulus E* = {_si(pair.reduced_modulus, 'Pa')}, gamma = {s.gamma:.6g}", "",
             f"{'':26}{'with friction':{width}}{reference:{max(width, len(reference) + 3)}}ratio"]
    for name, value, ref, r in rows:
        lines.append(f"{name:26}{value:{width}}{ref:{max(width, len(reference) + 3)}}{r}")
    lines += ["", f"stick fraction c = {s.c:.10g}; route: {s.route}; estimated error of c or mu: {s.error:.1e}"]
    return "\n".join(lines) + "\n"


def _attach_negative_values(argv: list[str]) -> list[str]:
    """``--opt -1e9`` as ``--opt=-1e9``: argparse takes a value that starts with '-' for an option unless it
    looks like a plain negative number, which ``-1e9`` or a range ``-0.9:0.49:10`` does not."""
    out: list[str] = []
    i = 0
    while i < len(argv):
        token = argv[i]
        if (token.startswith("--") and "=" not in token and i + 1 < len(argv)
                and re.match(r"-(\d|\.\d|inf|nan)", argv[i + 1], re.IGNORECASE)):
            out.append(f"{token}={argv[i + 1]}")
            i += 2
        else:
            out.append(token)
            i += 1
    return out


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``hertz-friction`` console script; returns the exit code."""
    from numeric import NoEigenvalueError, SolverError

    parser = _build_parser()
    try:
        args = parser.parse_args(_attach_negative_values(list(sys.argv[1:] if argv is None else argv)))
    except SystemExit as exc:  # --help (0) or a usage error (2); argparse has printed the message
        return exc.code if isinstance(exc.code, int) else 2
    run = _RUN.get(args.command, _run_physical)
    try:
        return run(args)
    except (ValueError, TypeError) as err:
        sys.stderr.write(f"hertz-friction {args.command}: error: {err}\n")
        return 2
    except OSError as err:  # an --output that cannot be written
        sys.stderr.write(f"hertz-friction {args.command}: error: cannot write {err.filename or ''}: {err.strerror or err}\n")
        return 2
    except ImportError as err:  # the plot extra is not installed
        sys.stderr.write(f"hertz-friction {args.command}: error: {err.name or err} is needed here; "
                         "install it with pip install -e \".[plot]\"\n")
        return 2
    except NoEigenvalueError as err:  # the input has no solution (c above c_max, or c < 1 at gamma = 0)
        sys.stderr.write(f"hertz-friction {args.command}: no solution: {err}\n")
        return 1
    except SolverError as err:
        sys.stderr.write(f"hertz-friction {args.command}: numerical failure: {err}\n")
        return 1


if __name__ == "__main__":
    raise SystemExit(main())
