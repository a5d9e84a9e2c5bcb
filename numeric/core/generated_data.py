"""Generated data modules (a build script's .py beside its .npy), loaded once, on first use, under a lock.

The whole-plane tables (``numeric.core.table``) and the field table (``numeric.core.field_table``) read their
committed data this way; a build script hands a freshly written module to ``GeneratedData.use`` to check it.

Threads of a sweep (``numeric.solutions.sweep``, a thread pool or a Dask worker's threads) that first read the
tables at the same moment load them one after the other: concurrent loads did the work twice, and numpy's reading of
the .npy header (``ast.literal_eval``) in two threads at once raised "SystemError: AST constructor recursion depth
mismatch" on CPython 3.11.7 (python/cpython#106905, fixed in 3.11.8) in ``tests/test_dask.py``, 2 of 8 suite runs.
"""

from __future__ import annotations

import importlib
import threading
from collections.abc import Callable
from types import ModuleType
from typing import Generic, TypeVar

__all__ = ["GeneratedData", "LOAD_ERRORS"]

T = TypeVar("T")

#: What loading a missing or stale generated module raises (``GeneratedData.available`` is False then).
LOAD_ERRORS = (ImportError, AttributeError, KeyError, OSError, ValueError, TypeError)


class GeneratedData(Generic[T]):
    """The data of the generated module ``default`` (a dotted name, imported on first use) or of one given to
    ``use``, turned into a T by ``load`` once."""

    def __init__(self, default: str, load: Callable[[ModuleType], T]) -> None:
        self._default, self._load = default, load
        self._module: ModuleType | None = None
        self._value: T | None = None
        self._lock = threading.Lock()

    def use(self, module: ModuleType | None) -> None:
        """Read ``module`` (a freshly built one) instead of the committed one (None: that one again)."""
        with self._lock:
            self._module, self._value = module, None

    def get(self) -> T:
        with self._lock:
            if self._value is None:
                module = self._module if self._module is not None else importlib.import_module(self._default)
                self._value = self._load(module)
            return self._value

    def available(self) -> bool:
        """Whether the module is present and of this format."""
        try:
            self.get()
        except LOAD_ERRORS:
            return False
        return True
