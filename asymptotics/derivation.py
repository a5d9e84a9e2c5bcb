"""What a derivation of the paper's analysis records: the vocabulary of the registry.

A :class:`Derivation` holds one numbered result of [S75]: the statement as derived by SymPy,
the statement as printed in the paper, the steps that lead from one to the other (each a
SymPy expression shown in LaTeX), the identities SymPy cannot prove (checked numerically
with mpmath instead, each an :class:`Identity`) and the numeric functions that evaluate the
result (``fast``: numpy, vectorised; ``precise``: mpmath). The derivation modules in
``asymptotics.derive`` build these; ``asymptotics.registry`` collects them by equation
number. This module itself needs neither SymPy nor mpmath.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

__all__ = ["Step", "Identity", "Comparison", "Derivation", "EPS", "LIBM_ULP", "rounding_bound"]

EPS = 2.0**-52
"""Machine epsilon of float64: one unit in the last place of 1."""

LIBM_ULP = 4
"""Units in the last place allowed for one call of a transcendental function (log, atanh, hyp2f1, ...). numpy's
own accuracy tests hold its float64 SIMD paths to 1 ulp (``umath-validation-set-*.csv``), but where it falls back
to the platform's libm, or calls scipy's special functions, nothing promises correct rounding; 4 covers what the
common libms are measured at, so a bound built on it holds on any x86-64 or ARM machine, not only this one."""


def rounding_bound(operations: int, calls: int = 0, condition: float = 1.0) -> float:
    """Relative error bound of a float64 evaluation against an exact reference, to first order in EPS.

    Half a unit in the last place for each basic operation (+, -, *, /, sqrt: correctly rounded by IEEE 754) and
    for rounding the reference, ``LIBM_ULP`` for each call of a transcendental function, all times the condition
    number of the formula (1 where no subtraction cancels). A unit in the last place of x is at most EPS |x|.

    >>> round(rounding_bound(1, 1) / EPS, 2)   # atanh(g)/g: one call, one division, the reference's rounding
    5.0
    """
    return (0.5 * (operations + 1) + LIBM_ULP * calls) * condition * EPS


@dataclass(frozen=True, slots=True)
class Step:
    """One step of a derivation: what was done (in words) and what it gave (SymPy)."""

    text: str
    expr: Any  # a SymPy expression or Eq; shown with sympy.latex


@dataclass(frozen=True, slots=True)
class Identity:
    """A step SymPy cannot do, checked numerically instead.

    ``residual(*point)`` evaluates left minus right side in mpmath at ``dps`` digits;
    the identity is accepted where ``abs(residual) <= tol`` at every point of ``points``
    (``tol`` a few digits above the working precision, i.e. rounding).
    """

    name: str
    statement: str  # LaTeX
    residual: Callable[..., Any]
    points: tuple[tuple[Any, ...], ...]
    dps: int = 40
    tol: float = 1e-30


@dataclass(frozen=True, slots=True)
class Comparison:
    """``fast`` against ``precise`` at ``points``: max relative difference <= ``rtol``.

    Where ``fast`` is a short closed form, ``rtol`` is ``rounding_bound`` of its operations (a tolerance at the
    last digit this machine happens to produce would fail on another CPU).
    """

    points: tuple[tuple[Any, ...], ...]
    rtol: float


@dataclass(frozen=True, slots=True)
class Derivation:
    """One numbered result of [S75], derived.

    Attributes
    ----------
    label : str
        The equation number, e.g. "(2.28)"; results beyond the paper use a label of their
        own ("f2", "P4", ...).
    part : str
        "2.3", "3" or "B" (appendix B with (4.10), (4.18)): which document it goes into.
    title : str
        A line saying what the result is.
    derived : SymPy expression or Eq
        The result as our derivation gives it.
    printed : SymPy expression, Eq or None
        The paper's statement transcribed (None where the paper states nothing to compare).
    agrees : bool
        Whether ``derived`` equals ``printed`` (decided in the derivation, symbolically where
        SymPy can, else numerically; see ``note``).
    steps : tuple of Step
    identities : tuple of Identity
    fast, precise : callables or None
        numpy (vectorised) and mpmath evaluations of the result, same arguments.
    arguments : tuple of str
        Names of the arguments of ``fast`` and ``precise``.
    comparison : Comparison or None
        Where ``fast`` is checked against ``precise``.
    note : str
        Slips found in the paper, conventions, what was checked numerically and why.
    """

    label: str
    part: str
    title: str
    derived: Any
    printed: Any
    agrees: bool
    steps: tuple[Step, ...] = ()
    identities: tuple[Identity, ...] = ()
    fast: Callable[..., Any] | None = None
    precise: Callable[..., Any] | None = None
    arguments: tuple[str, ...] = ()
    comparison: Comparison | None = None
    note: str = ""
    extra: dict[str, Any] = field(default_factory=dict)  # free-form, e.g. tables for the document
