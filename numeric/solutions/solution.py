"""The result of a flat-punch solve ([S75] §2), whichever route produced it.

``FlatPunchSolution`` carries the numbers (mu, c, P*, their error, the route taken) and a
stress field: the closed forms of the limits (``numeric.solutions.limits``), the first-order
fields of the asymptotic law (``numeric.solutions.law``) or the discrete solution of the solver
(``numeric.core.graded_collocation.FlatField``). Every route builds it; the route choice
(``numeric.solutions.flat_punch``) compares them by ``error`` with ``meets``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import scalar_or_array
from asymptotics.materials import check_x

__all__ = ["AccuracyWarning", "Deferred", "DeferredError", "StressField", "FlatPunchSolution", "Offer", "first_meeting",
           "meets", "warn_unmet"]


class AccuracyWarning(UserWarning):
    """The requested ``rtol`` could not be met; the most accurate result available was returned."""


class Deferred:
    """A value formed on first use (``value()``) and kept; pickled (to another process) with it, formed then: the
    computation behind it does not travel."""

    __slots__ = ("_compute", "_value")

    def __init__(self, compute: Callable[[], object]) -> None:
        self._compute: Callable[[], object] | None = compute
        self._value: object | None = None

    def value(self) -> object:
        if self._value is None:
            assert self._compute is not None
            self._value = self._compute()
            self._compute = None
        return self._value

    def __repr__(self) -> str:
        return "<formed on first use>" if self._value is None else repr(self._value)

    def __reduce__(self):
        return (_known, (type(self), self.value()))


def _known(kind: type, value: object) -> Deferred:
    known = kind(lambda: value)
    known.value()
    return known


class DeferredError(Deferred):
    """An error estimate formed on first use.

    The solver's estimate is a second solve one polynomial degree lower (``numeric.solutions.solver``), as
    costly as the solution itself: a caller who reads neither ``error`` nor asks for ``rtol`` does not pay
    for it. The value, once formed, is kept.
    """

    __slots__ = ()

    def __init__(self, compute: Callable[[], float]) -> None:
        super().__init__(lambda: float(compute()))


class StressField(Protocol):
    """What a route hands the solution: p, q of (2.1) and u of (2.10) on 0 <= x < 1, and the
    value of p (``shear=False``) or q at the edge x = 1."""

    def pressure(self, x: np.ndarray) -> np.ndarray: ...

    def shear(self, x: np.ndarray) -> np.ndarray: ...

    def slip(self, x: np.ndarray) -> np.ndarray: ...

    def edge_value(self, shear: bool) -> float: ...


@dataclass(frozen=True, slots=True)
class FlatPunchSolution:
    """A flat punch pressed into a half-space with friction, [S75] §2.

    Attributes
    ----------
    nu : float or None
        Poisson's ratio (None when gamma was given directly).
    gamma : float
        Coupling constant (2.2).
    mu : float
        Friction coefficient (inf for the adhesive limit).
    c : float
        Stick radius over contact radius.
    compliance : float
        P* = (pi/2) int_0^1 x p dx (2.4); the load is P = 4 G a P* delta / (1 - nu).
    error : float
        Estimated absolute error of c, mu and compliance (0 for closed forms); on the solver route it is
        formed when first read (a second solve, at the next level up for levels 0-2, ``DeferredError``).
    route : str
        "closed form (...)" or "solver level L, n unknowns".
    breakpoints : ndarray
        Points in [0, 1] between which p and q are smooth (graded toward c and 1).

    Methods pressure(x), shear(x), slip(x) give p, q of (2.1) and u of (2.10) at
    0 <= x <= 1 (vectorised); at the punch edge x = 1 the flat-punch stresses are infinite
    ((1 - x)^(alpha - 1/2), alpha < 1/2; q is 0 without friction), and u is 0 in the stick zone.
    """

    nu: float | None
    gamma: float
    mu: float
    c: float
    compliance: float
    _error: float | DeferredError
    route: str
    breakpoints: np.ndarray
    _field: StressField

    @property
    def error(self) -> float:
        """Estimated absolute error of c, mu and compliance (formed on first use on the solver route)."""
        return self._error.value() if isinstance(self._error, DeferredError) else self._error

    @property
    def gap(self) -> float:
        """1 - c, without the cancellation of forming it from c (near c_max it is 1e-3 ... 1e-12)."""
        return float(getattr(self._field, "gap", 1.0 - self.c))

    def pressure(self, x: ArrayLike) -> np.ndarray | float:
        """Contact pressure p(x), [S75] (2.1)."""
        return self._at(x, self._field.pressure, edge=self._field.edge_value(shear=False))

    def shear(self, x: ArrayLike) -> np.ndarray | float:
        """Shear traction q(x), [S75] (2.1); q = mu p in the slip annulus."""
        return self._at(x, self._field.shear, edge=self._field.edge_value(shear=True))

    def slip(self, x: ArrayLike) -> np.ndarray | float:
        """Radial displacement rate u(x) = d u_r / d delta of (2.10); 0 on the stick zone."""
        return self._at(x, self._field.slip, edge=None)

    def _at(self, x: ArrayLike, f, edge: float | None) -> np.ndarray | float:
        xs = check_x(x)
        flat = xs.ravel()
        out = np.empty(flat.shape)
        interior = flat < 1.0
        out[interior] = f(flat[interior])
        if edge is None:
            out[~interior] = f(np.nextafter(1.0, 0.0) * np.ones((~interior).sum())) if np.any(~interior) else 0.0
        else:
            out[~interior] = edge
        return scalar_or_array(out.reshape(xs.shape))


@dataclass(frozen=True, slots=True)
class Offer:
    """A route's answer to "can you meet rtol, and at what cost?".

    ``cost`` is a rough run time in seconds (the route choice tries offers cheapest first);
    ``promises()`` says, before running, whether the route's error bound meets rtol;
    ``run()`` computes the solution, whose ``error`` then decides.
    """

    cost: float
    promises: Callable[[], bool]
    run: Callable[[], FlatPunchSolution]


def first_meeting(offers: list[Offer], rtol: float,
                  value: Callable[[FlatPunchSolution], float]) -> FlatPunchSolution | None:
    """Run the offers that promise rtol, cheapest first; the first result that meets rtol in
    ``value`` (mu given c, c given mu), or None."""
    for offer in sorted(offers, key=lambda o: o.cost):
        if offer.promises():
            sol = offer.run()
            if meets(sol, rtol, value(sol)):
                return sol
    return None


def meets(sol: FlatPunchSolution, rtol: float, value: float) -> bool:
    """Whether ``sol.error`` is within ``rtol`` of ``value`` (mu given c, c given mu)."""
    return sol.error <= rtol * value


def warn_unmet(sol: FlatPunchSolution, rtol: float, value: float) -> None:
    """Issue the ``AccuracyWarning`` for a best result that misses ``rtol``."""
    warnings.warn(AccuracyWarning(
        f"rtol = {rtol:g} not met: the best route available ({sol.route}) has error {sol.error:.3g}, "
        f"{sol.error / value if value > 0 else math.inf:.3g} relative"), stacklevel=3)
