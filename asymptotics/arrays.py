"""Small array helpers shared by both packages (results are read-only; 0-d becomes a scalar)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["read_only", "scalar_or_array"]


def read_only(values: ArrayLike) -> np.ndarray:
    """A float copy of ``values`` that cannot be written (for frozen result objects)."""
    arr = np.array(values, dtype=float)
    arr.setflags(write=False)
    return arr


def scalar_or_array(arr: np.ndarray) -> np.ndarray | float:
    """Unwrap a 0-d array to a numpy scalar, so scalar input gives scalar output."""
    return arr[()] if arr.ndim == 0 else arr
