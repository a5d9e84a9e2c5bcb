"""The eigenvalue problem of [S75] §2.2 on the hp discretisation: mu for given c.

Collocation ([S75] (2.2), (2.7)-(2.8)): (2.2a) with w* = 1 at every node and (2.2b) with
u* = 0 at the stick nodes; in the slip zone Q = mu P / t (q = mu p, (2.6b)) is
substituted, so the system is D(mu) z = b with D(mu) = D0 + mu D1 and
z = (P_stick, Q_stick, P_slip).

Eigenvalue condition: F(mu) = mu p(c-) - q(c-), the excess friction phi = p - q/mu of
(2.11) at the stick side of x = c, must vanish (equivalent to chi(c) = 0 (2.13) and to
q/(mu p) -> 1 (§4.1); reformulation.md). For mu != mu_c the discrete solution tries to
represent the (c - x)^(-1/2 - alpha) singularity, so F is large but smooth in mu.

Root finding: one LU of D(mu0) at the small-gamma eigenvalue (2.28); then Arnoldi on
K = D(mu0)^-1 D1 gives a shifted (FOM) model of z(mu) for every mu at O(n^2) per step,
whose real roots come from a small generalized eigenproblem and are accepted only with a
certified residual below 1e-13 and p > 0, mu p - q >= 0 on the stick nodes. A root more
than 5 % from the LU centre is refined by a second LU at the root (a far model root was
measured off by up to 1e-6 when mu gamma > 1). If no root is certified, F at the LU
centre brackets the root and the centre moves (Illinois regula falsi, or geometric
steps), with a new LU.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from asymptotics.arrays import read_only
from asymptotics.first_order import mu_over_gamma

from numeric.core.mesh import (
    Discretisation,
    Elements,
    Resolution,
    abel_matrices,
    adhesive_discretisation,
    discretise,
    gauss_rule,
    legendre_values,
)

__all__ = ["FlatField", "solve_mu", "solve_adhesive", "NoEigenvalueError", "SolverError"]


class NoEigenvalueError(RuntimeError):
    """No friction coefficient mu >= 0 gives the stick radius asked for."""


class SolverError(RuntimeError):
    """The solver did not converge at this resolution (e.g. c below ~1e-4 at fine levels)."""


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


def _system(d: Discretisation, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """D0, D1 and b with D(mu) = D0 + mu D1; unknowns (P_stick, Q_stick, P_slip);
    rows (2.2a) at stick nodes, (2.2b) at stick nodes, (2.2a) at slip nodes."""
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


class _Factor:
    """LU of a row- and column-equilibrated matrix."""

    def __init__(self, D: np.ndarray) -> None:
        self.cs = 1.0 / np.max(np.abs(D), axis=0)
        scaled = D * self.cs[None, :]
        self.rs = 1.0 / np.max(np.abs(scaled), axis=1)
        scaled *= self.rs[:, None]
        self.lu = sla.lu_factor(scaled, overwrite_a=True, check_finite=False)

    def solve(self, y: np.ndarray) -> np.ndarray:
        return sla.lu_solve(self.lu, y * self.rs, check_finite=False) * self.cs


def _end_value_row(elements: Elements) -> np.ndarray:
    """Row vector giving a nodal field's value at the upper end of the last element."""
    k = int(elements.degree[-1])
    row = np.zeros(elements.start[-1])
    row[elements.start[-2] :] = np.polynomial.legendre.legvander(np.array([1.0]), k)[0] @ gauss_rule(k)[2]
    return row


def _krylov_root(factor: _Factor, D1_slip: np.ndarray, b: np.ndarray, ms: int, c: float, mu0: float,
                 l_p: np.ndarray, l_q: np.ndarray, m_max: int = 32, tol: float = 1e-14):
    """Arnoldi on K = D(mu0)^-1 D1 from D(mu0)^-1 b; FOM model of F(mu) = mu p(c-) - c Q(c-).

    Returns (mu, z, certified residual)."""
    n = b.size
    r0 = factor.solve(b)
    beta = np.linalg.norm(r0)
    V = np.zeros((n, m_max + 1))
    H = np.zeros((m_max + 1, m_max))
    V[:, 0] = r0 / beta
    mu, res, z = mu0, math.inf, np.array([beta])
    for m in range(1, m_max + 1):
        w = factor.solve(D1_slip @ V[2 * ms :, m - 1])
        for _ in range(2):  # classical Gram-Schmidt, twice
            h = V[:, :m].T @ w
            w -= V[:, :m] @ h
            H[:m, m - 1] += h
        H[m, m - 1] = np.linalg.norm(w)
        if m >= 3 and (m % 2 == 0 or m == m_max):
            Hm = H[:m, :m]
            a_p, a_q = l_p @ V[:, :m], l_q @ V[:, :m]
            e1 = np.zeros(m)
            e1[0] = beta
            eye = np.eye(m)
            # roots delta of the reduced model: [[I + delta H, e1], [(mu0 + delta) a_p - c a_q, 0]] singular
            A = np.zeros((m + 1, m + 1))
            B = np.zeros((m + 1, m + 1))
            A[:m, :m], A[:m, m], A[m, :m] = eye, e1, mu0 * a_p - c * a_q
            B[:m, :m], B[m, :m] = Hm, a_p
            ev = sla.eigvals(A, -B)
            ev = ev[np.isfinite(ev)]
            ev = ev[(np.abs(ev.imag) <= 1e-8 * np.abs(ev)) & (ev.real > -mu0) & (ev.real < 10 * mu0 + 10)].real
            if ev.size == 0:
                ev = np.array([mu - mu0])
            candidates = []
            for delta in ev:
                try:
                    zz = np.linalg.solve(eye + delta * Hm, e1)
                except np.linalg.LinAlgError:  # the model is singular at this delta: no root there
                    continue
                with np.errstate(over="ignore", invalid="ignore"):
                    residual = abs(delta) * H[m, m - 1] * abs(zz[-1]) / beta
                if math.isfinite(residual):  # an overflowing model solution is no root
                    candidates.append((residual, abs(delta), delta))
            if not candidates:
                continue
            candidates.sort(key=lambda t: (t[0] > 1e-13, t[1] if t[0] <= 1e-13 else t[0]))
            delta = candidates[0][2]
            try:
                # a nearly singular model (c within 1e-9 of 1 at large gamma) can overflow here:
                # such a delta is not a root, and is skipped below instead of raising
                with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                    for _ in range(3):  # Newton polish on the model
                        M = eye + delta * Hm
                        zz = np.linalg.solve(M, e1)
                        dz = -np.linalg.solve(M, Hm @ zz)
                        F = (mu0 + delta) * (a_p @ zz) - c * (a_q @ zz)
                        dF = a_p @ zz + (mu0 + delta) * (a_p @ dz) - c * (a_q @ dz)
                        if dF == 0.0 or not math.isfinite(F / dF):
                            break
                        delta -= F / dF
                    zz = np.linalg.solve(eye + delta * Hm, e1)
            except np.linalg.LinAlgError:
                continue
            if not (math.isfinite(delta) and np.all(np.isfinite(zz))):
                continue
            res_new = abs(delta) * H[m, m - 1] * abs(zz[-1]) / beta
            converged = abs(mu0 + delta - mu) < tol * max(1.0, mu0 + delta) and res_new < 1e-13
            mu, res, z = mu0 + delta, res_new, zz
            if converged:
                break
        if H[m, m - 1] < 1e-300:
            break
        V[:, m] = w / H[m, m - 1]
    return mu, V[:, : z.size] @ z, res


def solve_mu(c: float, gamma: float, res: Resolution, *, mu_guess: float | None = None, mu_max: float = 1e4,
             max_outer: int = 40) -> FlatField:
    """Friction coefficient mu_c(c, gamma) and the flat-punch solution, 0 < c < 1, gamma > 0.

    ``mu_guess`` centres the LU (default: the small-gamma eigenvalue (2.28)).

    Raises
    ------
    NoEigenvalueError
        If no mu <= mu_max gives this c (for large gamma there is a largest stick radius).
    """
    d = discretise(c, res)
    D0, D1, b = _system(d, gamma)
    ms = d.x_stick.size
    n = b.size
    end = _end_value_row(d.stick)
    l_p = np.zeros(n)
    l_p[:ms] = end
    l_q = np.zeros(n)
    l_q[ms : 2 * ms] = end
    D1_slip = D1[:, 2 * ms :]
    centre = gamma * float(mu_over_gamma(c)) if mu_guess is None else mu_guess  # (2.28)
    lo = hi = None  # (mu, F) with F(lo) < 0 < F(hi)
    side = 0
    for _ in range(max_outer):
        factor = _Factor(D0 + centre * D1)
        mu, z, residual = _krylov_root(factor, D1_slip, b, ms, c, centre, l_p, l_q)
        if (residual < 1e-13 and mu > 0 and (lo is None or mu > lo[0]) and (hi is None or mu < hi[0])
                and _admissible(z, mu, d)):
            if abs(mu - centre) <= 0.05 * mu:
                break
            # A model root far from the LU centre can be off by up to 1e-6 relative (seen for
            # mu gamma > 1, where (2.28) starts far below mu_c): factor again at the root.
            centre = mu
            continue
        r0 = factor.solve(b)
        F = centre * (l_p @ r0) - c * (l_q @ r0)
        if F < 0:
            if side == -1 and hi is not None:
                hi = (hi[0], hi[1] / 2)  # Illinois
            lo, side = (centre, F), -1
        else:
            if side == 1 and lo is not None:
                lo = (lo[0], lo[1] / 2)
            hi, side = (centre, F), 1
        if lo is not None and hi is not None:
            centre = (lo[0] * hi[1] - hi[0] * lo[1]) / (hi[1] - lo[1])
        elif lo is not None:
            centre *= 1.6
        else:
            centre /= 1.6
        if centre > mu_max:
            raise NoEigenvalueError(
                f"no friction coefficient mu <= {mu_max:g} gives stick radius c = {c} at gamma = {gamma:.6g}: "
                "for large gamma the stick radius has an upper bound below 1"
            )
    else:
        raise SolverError(f"eigenvalue iteration did not converge for c = {c}, gamma = {gamma:.6g} at this level")
    P_st, Q_st, P_sl = z[:ms], z[ms : 2 * ms], z[2 * ms :]
    compliance = 0.25 * math.pi * (d.w_stick @ P_st + d.w_slip @ P_sl)  # (2.4): (pi/2) int x p dx = (pi/4) int P du
    Q_sl = mu * P_sl / d.x_slip
    u_star = d.x_slip * (d.U_ll @ Q_sl) - gamma * (d.Lo_ls @ P_st + d.Lo_ll @ P_sl)  # (2.2b) in the slip zone
    return FlatField(
        c=c,
        gamma=gamma,
        mu=float(mu),
        compliance=float(compliance),
        n_unknowns=n,
        breakpoints=_breakpoints([d.stick, d.slip]),
        _stick_p=_Piecewise.from_nodal(d.stick, P_st),
        _stick_q=_Piecewise.from_nodal(d.stick, Q_st),
        _slip_p=_Piecewise.from_nodal(d.slip, P_sl),
        _slip_u_star=(d.slip, read_only(u_star)),
    )


def _admissible(z: np.ndarray, mu: float, d: Discretisation) -> bool:
    """The root is the physical eigenvalue only if p > 0 and mu p - q >= 0 on the stick nodes (2.8).

    A root of the reduced model can be spurious (a mu where the discrete system is nearly
    singular, with mu p - q ~ -1e3 and p < 0); the constraint rejects it. The tolerance,
    1e-3 of mu max p, passes the discretisation error of mu p - q at the node next to c,
    where the exact mu p - q vanishes like (c - x)^(1/2 - alpha) (measured down to -2e-6).
    """
    ms = d.x_stick.size
    p, q = z[:ms], d.x_stick * z[ms : 2 * ms]
    return bool(np.all(p > 0.0) and np.all(mu * p - q >= -1e-3 * mu * np.max(p)))


def _breakpoints(groups: list[Elements]) -> np.ndarray:
    ends = np.concatenate([np.sqrt(g.anchor + g.lo) for g in groups] + [[1.0]])
    return read_only(np.unique(np.clip(ends, 0.0, 1.0)))


def solve_adhesive(gamma: float, res: Resolution) -> FlatField:
    """The fully adhesive flat punch (c = 1) on the mesh graded toward the edge."""
    el, x, w, U, Lo = adhesive_discretisation(res)
    n = x.size
    D = np.zeros((2 * n, 2 * n))
    D[:n, :n] = U
    D[:n, n:] = -gamma * (0.5 * w[None, :] - x[:, None] * Lo)  # (2.2a)
    D[n:, :n] = -gamma * Lo  # (2.2b), u* = 0
    D[n:, n:] = x[:, None] * U
    b = np.zeros(2 * n)
    b[:n] = 1.0
    z = _Factor(D).solve(b)
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
