"""Progress of long work: a tqdm bar on stderr, shown by default only where someone watches.

Sweeps (``stick_radius``, ``friction_coefficient``), the command line's ``table``, the figures
and the table build report how far they are with an estimated time to go. ``progress`` is
``"auto"`` (the default: a bar when stderr is a terminal, nothing in a pipe, a log file or a test),
``True`` (always) or ``False`` (never; the command line's ``--quiet``).
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from typing import Literal, TypeVar

from tqdm import tqdm

__all__ = ["Progress", "check_progress", "shows_progress", "progress_bar", "tracked"]

Progress = bool | Literal["auto"]
T = TypeVar("T")


def check_progress(progress: object) -> Progress:
    """``progress`` itself if it is "auto", True or False, else a TypeError or ValueError naming it."""
    if isinstance(progress, bool) or progress == "auto":
        return progress  # type: ignore[return-value]
    if isinstance(progress, str):
        raise ValueError(f"progress must be 'auto', True or False, got {progress!r}")
    raise TypeError(f"progress must be 'auto', True or False, got {progress!r}")


def shows_progress(progress: Progress) -> bool:
    """Whether a bar is drawn: always for True, never for False, for "auto" when stderr is a terminal."""
    if check_progress(progress) == "auto":
        isatty = getattr(sys.stderr, "isatty", None)
        return bool(isatty is not None and isatty())
    return bool(progress)


def progress_bar(total: int, description: str, progress: Progress = "auto", unit: str = "point") -> tqdm:
    """A tqdm bar over ``total`` steps on stderr (disabled, drawing nothing, unless ``shows_progress``)."""
    return tqdm(total=total, desc=description, unit=unit, file=sys.stderr, disable=not shows_progress(progress),
                dynamic_ncols=True, leave=True)


def tracked(items: Iterable[T], total: int, description: str, progress: Progress = "auto",
            unit: str = "point") -> Iterator[T]:
    """The items of ``items`` (e.g. an executor's ``map``), counted on a ``progress_bar`` as they arrive."""
    with progress_bar(total, description, progress, unit) as bar:
        for item in items:
            yield item
            bar.update()
