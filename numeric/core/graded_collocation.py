"""Collocation of [S75] (2.2) on the hp discretisation: the linear systems, their LU, the discrete fields.

(2.2a) is collocated with w* = 1 at every node and (2.2b) with u* = 0 at the stick nodes;
in the slip zone Q = mu P / t (q = mu p, (2.6b)) is substituted, so for 0 < c < 1 the system
is D(mu) z = b with D(mu) = D0 + mu D1 and z = (P_stick, Q_stick, P_slip) (``system``); at
c = 1 there is no slip zone and the system is linear (``adhesive_system``, ``solve_adhesive``).
Matrices are factored after row and column equilibration (``numeric.core.linear_algebra``).
``FlatField`` is the discrete solution as piecewise Legendre series in u = t^2, with p, q and
the slip u of (2.10); ``numeric.core.graded_eigen`` finds the mu at which it is the physical one.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asymptotics.arrays import read_only

from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.graded_mesh import Discretisation, Elements, Resolution, abel_matrices, adhesive_discretisation
from numeric.core.quadrature import gauss_rule, legendre_values

__all__ = ["FlatField", "system", "adhesive_system", "end_value_row", "flat_field",
           "solve_adhesive"]


@dataclass(frozen=True, slots=True)
class _Piecewise:
    """Piecewise Legendre series on elements; evaluation at x = sqrt(u)."""

    elements: Elements
    coefficients: np.ndarray  # (E, kmax + 1), zero-padded

    @classmethod
    def from_nodal(cls, elements: Elements, values: np.ndarray) -> _Piecewise:
        kmax = int(elements.degree.max())
        coef = np.zeros((len(elements), kmax + 1))
        for e, (s, k) in enumerate(zip(elements.start[:-1], elements.degree)):
            coef[e, : k + 1] = gauss_rule(int(k))[2] @ values[s : s + k + 1]
        coef.setflags(write=False)
        return cls(elements, coef)

    def __call__(self, x: np.ndarray) -> np.ndarray:
        el = self.elements
        roots = np.sqrt(el.anchor)  # c or 1
        offsets = (x[:, None] - roots[None, :]) * (x[:, None] + roots[None, :])  # u - anchor
        inside = (offsets >= el.lo[None, :]) & (offsets <= el.hi[None, :])
        e = np.argmax(inside, axis=1)
        off = offsets[np.arange(x.size), e]
        xi = np.clip(-1.0 + 2.0 * (off - el.lo[e]) / (el.hi[e] - el.lo[e]), -1.0, 1.0)
        basis = legendre_values(xi, self.coefficients.shape[1] - 1)
        return np.einsum("kp,pk->p", basis, self.coefficients[e])


@dataclass(frozen=True, slots=True)
class FlatField:
    """The discrete flat-punch solution on one mesh.

    pressure(x), shear(x): p and q at 0 <= x < 1 (vectorised); slip(x): u of (2.10).
    ``breakpoints`` are the element ends in x (graded toward c and 1).
    """

    c: float
    gamma: float
    mu: float
    compliance: float
    n_unknowns: int
    breakpoints: np.ndarray
    _stick_p: _Piecewise
    _stick_q: _Piecewise
    _slip_p: _Piecewise | None
    _slip_u_star: tuple[Elements, np.ndarray] | None

    def pressure(self, x: np.ndarray) -> np.ndarray:
        """p(x), [S75] (2.1)."""
        x = np.asarray(x, dtype=float)
        out = np.empty(x.shape)
        stick = x < self.c
        out[stick] = self._stick_p(x[stick])
        if self._slip_p is not None:
            out[~stick] = self._slip_p(x[~stick])
        return out

    def shear(self, x: np.ndarray) -> np.ndarray:
        """q(x) = x Q(x^2) in the stick zone, mu p(x) in the slip annulus (2.6b)."""
        x = np.asarray(x, dtype=float)
        out = np.empty(x.shape)
        stick = x < self.c
        out[stick] = x[stick] * self._stick_q(x[stick])
        if self._slip_p is not None:
            out[~stick] = self.mu * self._slip_p(x[~stick])
        return out

    def slip(self, x: np.ndarray) -> np.ndarray:
        """Radial surface displacement rate u(x) of (2.10); 0 in the stick zone, < 0 in the slip annulus."""
        x = np.asarray(x, dtype=float)
        out = np.zeros(x.shape)
        outer = x > self.c
        if self._slip_u_star is None or not np.any(outer):
            return out
        elements, u_star = self._slip_u_star
        xs = x[outer]
        anchor = np.where(np.abs(xs - self.c) <= np.abs(1.0 - xs), self.c**2, 1.0)
        offset = (xs - np.sqrt(anchor)) * (xs + np.sqrt(anchor))
        _, Lo = abel_matrices(elements, anchor, offset, upper=False)
        out[outer] = (2.0 / np.pi) * (Lo @ u_star) / xs  # (2.10)
        return out

    def edge_value(self, shear: bool) -> float:
        """p and q at x = 1: infinite, (1 - x)^(alpha - 1/2) with alpha < 1/2."""
        return math.inf


def system(d: Discretisation, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """D0, D1 and b of the collocated (2.2) for 0 < c < 1, with D(mu) = D0 + mu D1.

    Unknowns (P_stick, Q_stick, P_slip); rows (2.2a) at stick nodes, (2.2b) at stick nodes,
    (2.2a) at slip nodes.
    """
    ms, ml = d.x_stick.size, d.x_slip.size
    n = 2 * ms + ml
    D0 = np.zeros((n, n))
    D1 = np.zeros((n, n))
    xs, xl = d.x_stick, d.x_slip
    Ps, Qs, Pl = slice(0, ms), slice(ms, 2 * ms), slice(2 * ms, n)
    ra, rb, rl = slice(0, ms), slice(ms, 2 * ms), slice(2 * ms, n)
    # (2.2a): int_x^1 t p / sqrt - gamma (int_0^1 q dt - x int_0^x q / sqrt) = 1, int_0^1 q dt = (1/2) int Q du
    D0[ra, Ps] = d.U_ss
    D0[ra, Pl] = d.U_sl
    D0[ra, Qs] = -gamma * (0.5 * d.w_stick[None, :] - xs[:, None] * d.Lo_ss)
    D1[ra, Pl] = -gamma * 0.5 * (d.w_slip / xl)[None, :]
    D0[rl, Pl] = d.U_ll
    D0[rl, Qs] = -gamma * (0.5 * d.w_stick[None, :] - xl[:, None] * d.Lo_ls)
    D1[rl, Pl] = -gamma * (0.5 * d.w_slip[None, :] - xl[:, None] * d.Lo_ll) / xl[None, :]
    # (2.2b) in the stick zone: x int_x^1 q / sqrt - gamma int_0^x t p / sqrt = 0
    D0[rb, Qs] = xs[:, None] * d.U_ss
    D0[rb, Ps] = -gamma * d.Lo_ss
    D1[rb, Pl] = xs[:, None] * d.U_sl / xl[None, :]
    b = np.zeros(n)
    b[ra] = 1.0
    b[rl] = 1.0
    return D0, D1, b


def end_value_row(elements: Elements) -> np.ndarray:
    """Row vector giving a nodal field's value at the upper end of the last element (x = c- on the stick mesh)."""
    k = int(elements.degree[-1])
    row = np.zeros(elements.start[-1])
    row[elements.start[-2] :] = np.polynomial.legendre.legvander(np.array([1.0]), k)[0] @ gauss_rule(k)[2]
    return row


def flat_field(d: Discretisation, gamma: float, mu: float, z: np.ndarray) -> FlatField:
    """The discrete solution for 0 < c < 1 from the eigenvalue mu and the solution z of
    D(mu) z = b (``system``): compliance (2.4), the nodal fields as Legendre series, and u* of
    (2.2b) in the slip zone for the slip (2.10)."""
    ms = d.x_stick.size
    P_st, Q_st, P_sl = z[:ms], z[ms : 2 * ms], z[2 * ms :]
    compliance = 0.25 * math.pi * (d.w_stick @ P_st + d.w_slip @ P_sl)  # (2.4): (pi/2) int x p dx = (pi/4) int P du
    Q_sl = mu * P_sl / d.x_slip
    u_star = d.x_slip * (d.U_ll @ Q_sl) - gamma * (d.Lo_ls @ P_st + d.Lo_ll @ P_sl)  # (2.2b) in the slip zone
    return FlatField(
        c=d.c,
        gamma=gamma,
        mu=float(mu),
        compliance=float(compliance),
        n_unknowns=z.size,
        breakpoints=_breakpoints([d.stick, d.slip]),
        _stick_p=_Piecewise.from_nodal(d.stick, P_st),
        _stick_q=_Piecewise.from_nodal(d.stick, Q_st),
        _slip_p=_Piecewise.from_nodal(d.slip, P_sl),
        _slip_u_star=(d.slip, read_only(u_star)),
    )


def _breakpoints(groups: list[Elements]) -> np.ndarray:
    ends = np.concatenate([np.sqrt(g.anchor + g.lo) for g in groups] + [[1.0]])
    return read_only(np.unique(np.clip(ends, 0.0, 1.0)))




def adhesive_system(gamma: float, res: Resolution) -> tuple[np.ndarray, np.ndarray]:
    """D and b of the fully adhesive problem (c = 1) on ``adhesive_discretisation(res)``: unknowns
    (P, Q) at its nodes, rows (2.2a) and (2.2b) with u* = 0 everywhere."""
    _, x, w, U, Lo = adhesive_discretisation(res)
    n = x.size
    D = np.zeros((2 * n, 2 * n))
    D[:n, :n] = U
    D[:n, n:] = -gamma * (0.5 * w[None, :] - x[:, None] * Lo)  # (2.2a)
    D[n:, :n] = -gamma * Lo  # (2.2b), u* = 0
    D[n:, n:] = x[:, None] * U
    b = np.zeros(2 * n)
    b[:n] = 1.0
    return D, b


def solve_adhesive(gamma: float, res: Resolution) -> FlatField:
    """The fully adhesive flat punch (c = 1) on the mesh graded toward the edge (a linear solve)."""
    el, x, w, _, _ = adhesive_discretisation(res)
    n = x.size
    D, b = adhesive_system(gamma, res)
    z = EquilibratedLU(D).solve(b)
    P, Q = z[:n], z[n:]
    return FlatField(
        c=1.0,
        gamma=gamma,
        mu=math.inf,
        compliance=float(0.25 * math.pi * (w @ P)),
        n_unknowns=2 * n,
        breakpoints=_breakpoints([el]),
        _stick_p=_Piecewise.from_nodal(el, P),
        _stick_q=_Piecewise.from_nodal(el, Q),
        _slip_p=None,
        _slip_u_star=None,
    )
