"""Render the registry's derivations as Markdown documents (one per part of the paper).

A document is a sequence of named blocks, each between ``<!-- begin NAME -->`` and
``<!-- end NAME -->`` lines, so that a check can regenerate the cheap blocks (statements,
steps, identities) and compare them with a committed file whose expensive blocks (tables
computed with the full solver, figures) it leaves alone. Imports SymPy and mpmath when
called; ``import asymptotics`` does not import this module.

Measured figures (the fast-against-precise differences and the identities' residuals) depend
on the machine: a float64 difference at rounding level moves with the CPU's libm and SIMD paths
(numpy's AVX-512 paths against its baseline moved them by up to 3.4e-16 here, e.g. 3e-16 to 5e-16).
The rendered text marks each (``measured``); ``agrees`` compares a committed document with a
rendered one exactly except there, where both figures must meet the tolerance the figure is
checked against, and ``text_of`` removes the marks for writing. So a document is current on
any machine whose figures pass, and a rerun does not rewrite it for a last digit.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import mpmath
import numpy as np

from .derivation import Derivation
from .registry import PARTS, part

__all__ = ["identity_residual", "fast_precise_difference", "render_part", "join", "blocks_of", "Block", "measured",
           "text_of", "agrees"]

Block = tuple[str, str]  # (name, Markdown body)

_BLOCK = re.compile(r"<!-- begin (?P<name>[^ ]+) -->\n(?P<body>.*?)<!-- end (?P=name) -->\n", re.S)
_MARK, _BOUND = "\ue000", "\ue001"  # a measured figure: MARK text BOUND value BOUND tolerance BOUND centre MARK
# (private-use characters: not whitespace, so rstrip and split leave them alone)
_FIGURE = r"(-?\d+(?:\.\d+)?(?:e[-+]\d+)?)"  # a number as _sig and the reports write it (e-notation or fixed)


def _once(f):
    """Memoise on the identity of the (frozen, long-lived) registry object: each check is run
    once per process, whether the tests or the documents ask first."""
    results: dict[int, float] = {}

    def wrapper(obj) -> float:
        if id(obj) not in results:
            results[id(obj)] = f(obj)
        return results[id(obj)]

    wrapper.__doc__ = f.__doc__
    return wrapper


@_once
def identity_residual(identity) -> float:
    """Largest |left - right| of an Identity over its points, at its working precision."""
    with mpmath.workdps(identity.dps):
        return max(float(abs(identity.residual(*point))) for point in identity.points)


@_once
def fast_precise_difference(d: Derivation) -> float:
    """Largest relative difference between ``d.fast`` and ``d.precise`` at the comparison points
    (elementwise for results with several components; absolute where the exact value is 0)."""
    worst = 0.0
    with mpmath.workdps(30):
        for point in d.comparison.points:
            exact = d.precise(*point)
            exact = np.array([float(v) for v in (exact if isinstance(exact, (list, tuple)) else [exact])])
            value = np.atleast_1d(np.asarray(d.fast(*point), dtype=float))
            scale = np.where(exact == 0.0, 1.0, np.abs(exact))
            worst = max(worst, float(np.max(np.abs(value - exact) / scale)))
    return worst


def _latex(expr) -> str:
    import sympy

    return expr if isinstance(expr, str) else sympy.latex(expr)


def _math(expr) -> str:
    return f"$$\n{_latex(expr)}\n$$"


def _sig(value: float) -> str:
    return "0" if value == 0.0 else f"{value:.0e}"


def measured(value: float, tolerance: float, text: str | None = None, centre: float = 0.0) -> str:
    """A machine-dependent figure, written as ``text`` (default ``_sig``, one digit in e-notation), marked with the
    claim it is checked against: within ``tolerance`` of ``centre`` (0 for an error or a difference; for a
    computed value its reference, or the value itself with the accuracy it is known to)."""
    return f"{_MARK}{_sig(value) if text is None else text}{_BOUND}{value!r}{_BOUND}{tolerance!r}{_BOUND}{centre!r}{_MARK}"


def text_of(rendered: str) -> str:
    """The Markdown of a rendered document: the marks of its measured figures removed."""
    return re.sub(f"{_BOUND}[^{_MARK}]*{_MARK}", "", rendered).replace(_MARK, "")  # keep each figure's text


def agrees(committed: str, rendered: str) -> bool:
    """Whether ``committed`` is ``text_of(rendered)`` but for measured figures, each of which meets its claim
    (within its tolerance of its centre) in both (the rendered ones are also checked by the tests)."""
    parts = rendered.split(_MARK)  # fixed text at even positions, "text BOUND value BOUND tolerance BOUND centre" at odd
    pattern = "".join(re.escape(part) if k % 2 == 0 else _FIGURE for k, part in enumerate(parts))
    found = re.fullmatch(pattern, committed, re.S)
    if found is None:
        return False
    for old, figure in zip(found.groups(), parts[1::2]):
        _, value, tolerance, centre = (float(v) if k else v for k, v in enumerate(figure.split(_BOUND)))
        if not (abs(float(old) - centre) <= tolerance + _half_unit(old) and abs(value - centre) <= tolerance):
            return False
    return True


def _half_unit(figure: str) -> float:
    """Half a unit in the last printed digit of ``figure`` (the rounding of a committed figure)."""
    mantissa, _, exponent = figure.partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def _summary(entries: tuple[Derivation, ...]) -> str:
    rows = ["| result | what | agrees with the paper | identities checked numerically | fast vs precise |",
            "|---|---|---|---|---|"]
    for d in entries:
        agree = "(not in the paper)" if d.printed is None else ("yes" if d.agrees else "no, see note")
        ids = ", ".join(f"{i.name} ({measured(identity_residual(i), i.tol)})" for i in d.identities) or "none"
        cmp_ = measured(fast_precise_difference(d), d.comparison.rtol) if d.comparison else "-"
        rows.append(f"| {d.label} | {d.title} | {agree} | {ids} | {cmp_} |")
    return "\n".join(rows)


def _name(f) -> str:
    """`module.function` for a public function; "in the registry" for a wrapper made in a derivation."""
    public = not f.__module__.startswith("asymptotics.derive") and f.__name__.isidentifier() and f.__name__[0] != "_"
    return f"`{f.__module__}.{f.__name__}`" if public else "(a wrapper in the derivation module)"


def _entry(d: Derivation) -> str:
    lines = [f"## {d.label} {d.title}", "", "Derived:", "", _math(d.derived), ""]
    if d.printed is not None:
        verdict = "agrees" if d.agrees else "**differs** (see the note)"
        lines += ["As printed in the paper (transcribed), which the derivation " + verdict + ":", "", _math(d.printed), ""]
    if d.steps:
        lines += ["Steps (SymPy):", ""]
        for k, step in enumerate(d.steps, 1):
            lines += [f"{k}. {step.text}", "", _math(step.expr), ""]
    if d.identities:
        lines += ["Steps SymPy cannot do, checked numerically with mpmath:", "",
                  "| identity | statement | points | digits | max abs residual | tolerance |", "|---|---|---|---|---|---|"]
        for i in d.identities:
            lines.append(f"| {i.name} | ${i.statement}$ | {len(i.points)} | {i.dps} | {measured(identity_residual(i), i.tol)} | {_sig(i.tol)} |")
        lines.append("")
    if d.fast is not None:
        lines.append(f"Numeric functions of ({', '.join(d.arguments)}): fast (numpy) {_name(d.fast)}"
                     + (f", precise (mpmath) {_name(d.precise)}" if d.precise else "") + ".")
        if d.comparison:
            lines.append(f"Largest relative difference at {len(d.comparison.points)} points: "
                         f"{measured(fast_precise_difference(d), d.comparison.rtol)} "
                         f"(tolerance {_sig(d.comparison.rtol)}).")
        lines.append("")
    if d.note:
        lines += [f"Note: {d.note}", ""]
    return "\n".join(lines).rstrip() + "\n"


def render_part(name: str, extra: Mapping[str, str] | None = None) -> list[Block]:
    """The blocks of the document of one part: header, summary, one per derivation, then ``extra``."""
    title, _ = PARTS[name]
    entries = part(name)
    blocks: list[Block] = [
        ("header", f"# {title}\n\nGenerated by `python derivations/regenerate.py` from `asymptotics.registry`; "
                   "do not edit. [S75] = D. A. Spence, *J. Elasticity* 5 (1975) 297–319.\n"),
        ("summary", _summary(entries) + "\n"),
    ]
    blocks += [(f"derivation{d.label}", _entry(d)) for d in entries]
    blocks += list((extra or {}).items())
    return blocks


def join(blocks: list[Block]) -> str:
    """The Markdown text of a document made of ``blocks``."""
    return "\n".join(f"<!-- begin {name.replace(' ', '_')} -->\n{body.rstrip()}\n<!-- end {name.replace(' ', '_')} -->\n"
                     for name, body in blocks)


def blocks_of(text: str) -> dict[str, str]:
    """The blocks of a committed document, name -> body (inverse of ``join``)."""
    return {m["name"]: m["body"] for m in _BLOCK.finditer(text)}
