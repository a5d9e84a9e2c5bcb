"""The registry of derived results, keyed by the paper's equation numbers.

``registry()`` imports the derivation modules (and so SymPy) on first use, runs their
derivations once and returns a read-only mapping label -> :class:`Derivation`; ``get`` picks
one. Tests and the documents in ``derivations/`` iterate over it.

>>> from asymptotics.registry import get
>>> get("(2.28)").part
'2.3'

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from functools import cache
from types import MappingProxyType

from .derivation import Derivation

__all__ = ["PARTS", "registry", "get", "part"]

# part -> (document title, derivation modules contributing to it)
PARTS: Mapping[str, tuple[str, tuple[str, ...]]] = MappingProxyType({
    "2.3": ("§2.3 Solution by successive approximations", ("asymptotics.derive.first_order", "asymptotics.derive.second_order",
                                                            "asymptotics.derive.largest_stick_radius")),
    "3": ("§3 The Hertzian indentor: power-law transforms", ("asymptotics.derive.similarity",)),
    "B": ("Appendix B, (4.10), (4.18): the adhesive solution", ("asymptotics.derive.adhesive",)),
    "P": ("Plane strain: the strip punch and the cylinder with friction (issue 14)", ("asymptotics.derive.plane",)),
})


@cache
def registry() -> Mapping[str, Derivation]:
    """All derivations, label -> Derivation, in the order of the parts and the paper."""
    entries: dict[str, Derivation] = {}
    for _, modules in PARTS.values():
        for name in modules:
            for d in importlib.import_module(name).derivations():
                if d.label in entries:
                    raise RuntimeError(f"label {d.label} derived twice ({name})")
                entries[d.label] = d
    return MappingProxyType(entries)


def get(label: str) -> Derivation:
    """The derivation of one result, e.g. ``get("(2.28)")``."""
    try:
        return registry()[label]
    except KeyError:
        raise KeyError(f"no derivation {label!r}; known: {', '.join(registry())}") from None


def part(name: str) -> tuple[Derivation, ...]:
    """The derivations that go into the document of one part ("2.3", "3" or "B")."""
    if name not in PARTS:
        raise ValueError(f"part must be one of {', '.join(PARTS)}, got {name!r}")
    return tuple(d for d in registry().values() if d.part == name)
