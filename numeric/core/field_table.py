"""Tabulated fields: the level-0 stresses and slip of the flat punch as Chebyshev interpolants in (c, gamma).

The engineer's route (``numeric.solutions.table_route``, rtol >= 1e-4) takes mu, c and P* from the whole-plane
table (``numeric.core.table``); its stresses p, q and slip u were a level-0 solve (one assembly, one LU, ~2 ms).
Here they are read instead: on a mapped layout (``numeric.core.layout_map``: the elements of one reference
layout, moved smoothly with c) the coefficients of the level-0 eigensolution (P, Q, R), theta, the basis
exponent and u* at the slip collocation points are analytic in (logit c, gamma), so a tensor product of
Chebyshev polynomials holds them (``stored_vector``).
A point costs the mapped layout, two short Chebyshev vectors and one contraction; the fields are then evaluated
on the basis as the solver's are (``numeric.core.fields.TabulatedField``), their singular behaviour at x = c and
x = 1 exact.

Pieces of c, each a rectangle [c_lo, c_hi] x [0, gamma_max] in (logit c, gamma), lie on one side of
1/sqrt(2) (``layout_map``) and below mu gamma = 1, where the stick pressure's singular family is pinned
(``numeric.core.stick_pressure_pins``: the discretisation changes there, and its coefficients jump); outside
them the route solves at level 0 as before. Built by ``derivations/build_field_table.py``, which records the
worst error at held-out points both of the interpolation (against the mapped layout's own solve there) and of the
fields (against level 4): ``field_table_errors``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from numeric.core.charts import RESOLUTIONS, Layout, layout
from numeric.core.fields import TabulatedField
from numeric.core.generated_data import GeneratedData
from numeric.core.layout_map import mapped_layout
from numeric.core.table import chebyshev_matrix

__all__ = ["GAMMA_MIN", "FieldPiece", "field_table_available", "field_table_errors", "field_table_holds",
           "field_table_pieces", "piece_reference", "piece_coordinates", "piece_stick_radius", "stored_vector",
           "tabulated_field", "use_field_table_data"]


@dataclass(frozen=True, slots=True)
class FieldPiece:
    """One rectangle of the field table: c in [c_lo, c_hi] (reference layout at c_ref), gamma in [0, gamma_max] (read
    from ``GAMMA_MIN`` up); Chebyshev sizes (n_c, n_gamma); the level of the reference layout. The stored vector is
    ``stored_vector``'s."""

    c_lo: float
    c_hi: float
    c_ref: float
    gamma_max: float
    n_c: int
    n_gamma: int
    level: int

    def holds(self, c: float, gamma: float) -> bool:
        return self.c_lo <= c <= self.c_hi and GAMMA_MIN <= gamma <= self.gamma_max


def piece_reference(piece: FieldPiece) -> Layout:
    """The reference layout of a piece: ``charts.layout`` at c_ref at the piece's level."""
    return _reference(piece.c_ref, piece.level)


@lru_cache(maxsize=None)
def _reference(c_ref: float, level: int) -> Layout:
    return layout(c_ref, 1.0 - c_ref, RESOLUTIONS[level])


def _logit_range(piece: FieldPiece) -> tuple[float, float]:
    return math.log(piece.c_lo) - math.log1p(-piece.c_lo), math.log(piece.c_hi) - math.log1p(-piece.c_hi)


def piece_coordinates(piece: FieldPiece, c: float, gap: float, gamma: float) -> tuple[float, float]:
    """(t, v) in [-1, 1]^2: t linear in logit c = log c - log(1 - c), v linear in gamma."""
    lo, hi = _logit_range(piece)
    t = 2.0 * (math.log(c) - math.log(gap) - lo) / (hi - lo) - 1.0
    return t, 2.0 * gamma / piece.gamma_max - 1.0


def piece_stick_radius(piece: FieldPiece, t: float) -> tuple[float, float]:
    """c and 1 - c at t in [-1, 1] (``piece_coordinates``' t), each formed without cancellation."""
    lo, hi = _logit_range(piece)
    u = lo + 0.5 * (t + 1.0) * (hi - lo)
    return 1.0 / (1.0 + math.exp(-u)), 1.0 / (1.0 + math.exp(u))


#: Below this gamma the field table is not read (the caller solves): as gamma -> 0 the basis exponent alpha ~ gamma^2
#: tends to 0 and the edge's family of u*, s^(2 alpha), to the constant (at gamma = 1e-8, c = 0.05 the u* interpolation
#: matrix of the edge element was singular). The rtol = 1e-4 route does not come here below gamma ~ 0.008, where
#: the asymptotic law meets 1e-4 first (``numeric.solutions.law``).
GAMMA_MIN = 1e-3

@dataclass(frozen=True)
class _Tables:
    module: object
    pieces: tuple[FieldPiece, ...]
    coefficients: tuple[np.ndarray, ...]  # per piece (n_c, n_gamma, stored)


def _tables_of(data) -> _Tables:
    values = np.load(Path(data.__file__).with_suffix(".npy"), allow_pickle=False)
    pieces, arrays = [], []
    for spec, (offset, shape) in zip(data.PIECES, data.SERIES):
        pieces.append(FieldPiece(*spec, data.LEVEL))
        block = values[offset: offset + int(np.prod(shape))].reshape(shape)
        block.setflags(write=False)
        arrays.append(block)
    return _Tables(data, tuple(pieces), tuple(arrays))


#: numeric.core.field_table_data (generated; imported on first use only), or a module given to
#: ``use_field_table_data``
_TABLES = GeneratedData("numeric.core.field_table_data", _tables_of)


def use_field_table_data(module) -> None:
    """Evaluate the tables of ``module`` (a freshly built field_table_data) instead of the committed ones (None:
    those)."""
    _TABLES.use(module)


def _data() -> _Tables:
    return _TABLES.get()


def field_table_available() -> bool:
    """Whether the generated field table is present (and of this format)."""
    return _TABLES.available()


def field_table_pieces() -> tuple[FieldPiece, ...]:
    """The pieces of the field table (none without it)."""
    return _data().pieces if field_table_available() else ()


def field_table_errors() -> dict[str, float]:
    """The worst errors the build measured at held-out points (empty without a table): "interpolation" (p, q relative
    to max(1, |p|) and u absolute, against the mapped layout's own solve) and "fields" (the same against level 4)."""
    return dict(_data().module.ERRORS or {}) if field_table_available() else {}


def stored_vector(gamma: float, theta: float, alpha: float, coefficients: np.ndarray, u_star: np.ndarray,
                  n_stick: int) -> np.ndarray:
    """[theta/gamma^2, alpha/gamma^2, P, Q/gamma, R, u*/gamma at the slip collocation points]: each analytic in gamma
    and of its own size as gamma -> 0, where theta = atan(mu gamma) ~ gamma^2 mu/gamma and the stick shear and u*
    (the slip's source) vanish like gamma (stored as they are, theta was 38 % off at gamma = 1e-4, q and u 1e-3 and
    5e-4 of their size at 1e-6, the interpolant's error being absolute)."""
    z = np.array(coefficients, dtype=float)
    z[n_stick: 2 * n_stick] /= gamma
    return np.concatenate([[theta / gamma**2, alpha / gamma**2], z, np.asarray(u_star) / gamma])


def _holding(c: float, gamma: float) -> tuple[FieldPiece, np.ndarray] | None:
    """The first piece holding (c, gamma) and its coefficients (None: none, or no table)."""
    if not field_table_available():
        return None
    tables = _data()
    return next(((p, a) for p, a in zip(tables.pieces, tables.coefficients) if p.holds(c, gamma)), None)


def field_table_holds(c: float, gamma: float) -> bool:
    """Whether ``tabulated_field`` answers at (c, gamma)."""
    return _holding(c, gamma) is not None


def tabulated_field(c: float, gap: float, gamma: float, compliance: float) -> TabulatedField | None:
    """The tabulated level-0 fields at stick radius c = 1 - gap (None outside the pieces, below ``GAMMA_MIN``, or
    without the table); ``compliance``: P* to report (the caller's, e.g. the whole-plane table's)."""
    held = _holding(c, gamma)
    if held is None:
        return None
    piece, coefficients = held
    t, v = piece_coordinates(piece, c, gap, gamma)
    n_c, n_gamma, stored = coefficients.shape
    row = chebyshev_matrix(np.array([t]), n_c)[0] @ coefficients.reshape(n_c, -1)
    values = chebyshev_matrix(np.array([v]), n_gamma)[0] @ row.reshape(n_gamma, stored)
    lay = mapped_layout(c, gap, piece_reference(piece), RESOLUTIONS[piece.level])
    ns = lay.n_stick
    n = ns + int(lay.starts[-1])
    z = values[2: 2 + n]
    z[ns: 2 * ns] *= gamma
    g2 = gamma * gamma
    return TabulatedField(lay, gamma, float(values[0]) * g2, float(values[1]) * g2, z, values[2 + n:] * gamma,
                          compliance)
