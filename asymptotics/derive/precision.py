"""mpmath wrappers shared by the derivation modules: arguments as mpf, a working precision."""

from __future__ import annotations

from collections.abc import Callable

import mpmath

__all__ = ["exact", "at_precision"]


def exact(residual: Callable) -> Callable:
    """Convert the arguments of an Identity residual to mpf at the caller's precision."""

    def wrapped(*args):
        return residual(*(mpmath.mpf(a) for a in args))

    return wrapped


def at_precision(func: Callable, dps: int = 40) -> Callable:
    """Evaluate ``func`` with mpmath at ``dps`` digits (arguments converted to mpf)."""

    def wrapped(*args):
        with mpmath.workdps(dps):
            return func(*(mpmath.mpf(a) for a in args))

    return wrapped
