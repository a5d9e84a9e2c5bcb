"""The eigenvalue problem of [S75] §2.2 on the hp discretisation: mu for given c, and c for given mu.

The collocated system D(mu) z = b, D(mu) = D0 + mu D1, is ``numeric.core.graded_collocation.system``.
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
steps), with a new LU: the bracketing is interleaved with the refactorisation, so it is
written out here rather than handed to scipy.

Given mu (``solve_c``), c with mu_c(c) = mu is found in logit(c): from the table's c, or by
Brent on a coarse resolution, then secant steps on the fine one.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.linalg as sla
from scipy import optimize
from scipy.special import expit, logit

from asymptotics.first_order import mu_over_gamma

from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.graded_collocation import FlatField, end_value_row, flat_field, system
from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.graded_mesh import Discretisation, Resolution, discretise
from numeric.core.table import table_available, table_friction_coefficient, table_stick_radius

__all__ = ["solve_mu", "solve_c", "AboveTopError"]

#: A model root is certified when its residual is below this (relative to the right-hand side).
CERTIFIED = 1e-13


def _arnoldi_step(factor: EquilibratedLU, D1_slip: np.ndarray, V: np.ndarray, H: np.ndarray, m: int,
                  ms: int) -> np.ndarray:
    """Column m - 1 of H and the unnormalised next vector of the Krylov basis of D(mu0)^-1 D1."""
    w = factor.solve(D1_slip @ V[2 * ms :, m - 1])
    for _ in range(2):  # classical Gram-Schmidt, twice
        h = V[:, :m].T @ w
        w -= V[:, :m] @ h
        H[:m, m - 1] += h
    H[m, m - 1] = np.linalg.norm(w)
    return w


def _model_root_guess(Hm: np.ndarray, h_next: float, a_p: np.ndarray, a_q: np.ndarray, beta: float, mu0: float,
                      c: float, fallback: float) -> float | None:
    """The shift delta = mu - mu0 of the reduced model's best real root (certified first, then the
    smallest residual), or None if the model is singular at every candidate."""
    m = Hm.shape[0]
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
        ev = np.array([fallback])
    candidates = []
    for delta in ev:
        try:
            zz = np.linalg.solve(eye + delta * Hm, e1)
        except np.linalg.LinAlgError:  # the model is singular at this delta: no root there
            continue
        with np.errstate(over="ignore", invalid="ignore"):
            residual = abs(delta) * h_next * abs(zz[-1]) / beta
        if math.isfinite(residual):  # an overflowing model solution is no root
            candidates.append((residual, abs(delta), delta))
    if not candidates:
        return None
    candidates.sort(key=lambda t: (t[0] > CERTIFIED, t[1] if t[0] <= CERTIFIED else t[0]))
    return candidates[0][2]


def _polish(delta: float, Hm: np.ndarray, a_p: np.ndarray, a_q: np.ndarray, beta: float, mu0: float,
            c: float) -> tuple[float, np.ndarray] | None:
    """Three Newton steps on the reduced model from ``delta``; (delta, model solution), or None
    where the model is singular or overflows there (then delta is no root)."""
    m = Hm.shape[0]
    e1 = np.zeros(m)
    e1[0] = beta
    eye = np.eye(m)
    try:
        # a nearly singular model (c within 1e-9 of 1 at large gamma) can overflow here:
        # such a delta is not a root, and is skipped instead of raising
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            for _ in range(3):
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
        return None
    if not (math.isfinite(delta) and np.all(np.isfinite(zz))):
        return None
    return delta, zz


def _krylov_root(factor: EquilibratedLU, D1_slip: np.ndarray, b: np.ndarray, ms: int, c: float, mu0: float,
                 l_p: np.ndarray, l_q: np.ndarray, m_max: int = 32, tol: float = 1e-14):
    """Arnoldi on K = D(mu0)^-1 D1 from D(mu0)^-1 b; FOM model of F(mu) = mu p(c-) - c Q(c-).

    Returns (mu, z, certified residual). (A step at which the model has no usable root leaves
    that basis vector unset, which ends the iteration at the next step.)"""
    n = b.size
    r0 = factor.solve(b)
    beta = np.linalg.norm(r0)
    V = np.zeros((n, m_max + 1))
    H = np.zeros((m_max + 1, m_max))
    V[:, 0] = r0 / beta
    mu, res, z = mu0, math.inf, np.array([beta])
    for m in range(1, m_max + 1):
        w = _arnoldi_step(factor, D1_slip, V, H, m, ms)
        if m >= 3 and (m % 2 == 0 or m == m_max):
            Hm = H[:m, :m]
            a_p, a_q = l_p @ V[:, :m], l_q @ V[:, :m]
            delta = _model_root_guess(Hm, H[m, m - 1], a_p, a_q, beta, mu0, c, mu - mu0)
            polished = None if delta is None else _polish(delta, Hm, a_p, a_q, beta, mu0, c)
            if polished is None:
                continue
            delta, zz = polished
            res_new = abs(delta) * H[m, m - 1] * abs(zz[-1]) / beta
            converged = abs(mu0 + delta - mu) < tol * max(1.0, mu0 + delta) and res_new < CERTIFIED
            mu, res, z = mu0 + delta, res_new, zz
            if converged:
                break
        if H[m, m - 1] < 1e-300:
            break
        V[:, m] = w / H[m, m - 1]
    return mu, V[:, : z.size] @ z, res


class _Illinois:
    """The bracket (mu, F) with F(lo) < 0 < F(hi) of the outer iteration, and its next LU centre:
    Illinois regula falsi once both ends are known, geometric steps of 1.6 before."""

    def __init__(self) -> None:
        self.lo: tuple[float, float] | None = None
        self.hi: tuple[float, float] | None = None
        self.side = 0

    def contains(self, mu: float) -> bool:
        return (self.lo is None or mu > self.lo[0]) and (self.hi is None or mu < self.hi[0])

    def next_centre(self, centre: float, F: float) -> float:
        lo, hi, side = self.lo, self.hi, self.side
        if F < 0:
            if side == -1 and hi is not None:
                hi = (hi[0], hi[1] / 2)  # Illinois
            lo, side = (centre, F), -1
        else:
            if side == 1 and lo is not None:
                lo = (lo[0], lo[1] / 2)
            hi, side = (centre, F), 1
        self.lo, self.hi, self.side = lo, hi, side
        if lo is not None and hi is not None:
            return (lo[0] * hi[1] - hi[0] * lo[1]) / (hi[1] - lo[1])
        if lo is not None:
            return centre * 1.6
        return centre / 1.6


def _stick_end_functionals(d: Discretisation, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Rows l_p, l_q with l_p z = P(c-) and l_q z = Q(c-) for z = (P_stick, Q_stick, P_slip)."""
    ms = d.x_stick.size
    end = end_value_row(d.stick)
    l_p = np.zeros(n)
    l_p[:ms] = end
    l_q = np.zeros(n)
    l_q[ms : 2 * ms] = end
    return l_p, l_q


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
    D0, D1, b = system(d, gamma)
    ms = d.x_stick.size
    l_p, l_q = _stick_end_functionals(d, b.size)
    D1_slip = D1[:, 2 * ms :]
    centre = gamma * float(mu_over_gamma(c)) if mu_guess is None else mu_guess  # (2.28)
    bracket = _Illinois()
    for _ in range(max_outer):
        factor = EquilibratedLU(D0 + centre * D1)
        mu, z, residual = _krylov_root(factor, D1_slip, b, ms, c, centre, l_p, l_q)
        if residual < CERTIFIED and mu > 0 and bracket.contains(mu) and _admissible(z, mu, d):
            if abs(mu - centre) <= 0.05 * mu:
                break
            # A model root far from the LU centre can be off by up to 1e-6 relative (seen for
            # mu gamma > 1, where (2.28) starts far below mu_c): factor again at the root.
            centre = mu
            continue
        r0 = factor.solve(b)
        centre = bracket.next_centre(centre, centre * (l_p @ r0) - c * (l_q @ r0))
        if centre > mu_max:
            raise NoEigenvalueError(
                f"no friction coefficient mu <= {mu_max:g} gives stick radius c = {c} at gamma = {gamma:.6g}: "
                "for large gamma the stick radius has an upper bound below 1"
            )
    else:
        raise SolverError(f"eigenvalue iteration did not converge for c = {c}, gamma = {gamma:.6g} at this level")
    return flat_field(d, gamma, mu, z)


class AboveTopError(Exception):
    """mu exceeds mu_c at the search's largest stick radius c_top: the stick radius lies above it."""


def _coarse_root(mu: float, gamma: float, res: Resolution, c_guess: float, c_top: float) -> tuple[FlatField, float]:
    """Stick radius with mu_c(c) = mu at one resolution by Brent in s = logit(c) on log mu, c <= c_top.

    Returns the solution and d(log mu)/ds at the root (from the two nearest evaluations)."""
    evaluations: dict[float, FlatField] = {}
    top = logit(c_top)

    def g(s: float) -> float:
        c = min(expit(s), c_top)
        try:
            field = solve_mu(c, gamma, res, mu_guess=mu)
        except NoEigenvalueError:
            return math.inf  # beyond the largest stick radius: mu is unbounded there
        evaluations[s] = field
        return math.log(field.mu) - math.log(mu)

    step = 0.05
    s0 = min(logit(c_guess), top - step)
    lo, hi = s0 - step, s0 + step
    g_lo, g_hi = g(lo), g(hi)
    while g_lo > 0.0:
        lo, hi, g_hi = lo - 2 * step, lo, g_lo
        step *= 2
        g_lo = g(lo)
        if lo < -40:
            raise NoEigenvalueError(f"no stick radius above 1e-17 for mu = {mu}, gamma = {gamma:.6g}")
    while g_hi < 0.0:
        if hi >= top:
            raise AboveTopError()
        lo, g_lo, hi = hi, g_hi, min(hi + 2 * step, top)
        step *= 2
        g_hi = g(hi)
    root = optimize.brentq(g, lo, hi, xtol=1e-11)
    field = evaluations.get(root) or solve_mu(expit(root), gamma, res, mu_guess=mu)
    # slope from the nearest evaluation at a different c (s beyond c_top is clamped to it)
    near = min((s for s in evaluations if evaluations[s].c != field.c), key=lambda s: abs(s - root))
    slope = (math.log(evaluations[near].mu) - math.log(field.mu)) / (logit(evaluations[near].c) - logit(field.c))
    return field, slope


def _table_start(mu: float, gamma: float) -> tuple[float, float] | None:
    """c from the Chebyshev table and d(log mu)/d(logit c) there, or None outside its domain."""
    if not table_available():
        return None
    c = float(table_stick_radius(mu, gamma))
    if math.isnan(c):
        return None
    s = logit(c)
    pair = table_friction_coefficient(expit(np.array([s - 1e-4, s + 1e-4])), np.array(gamma))
    if np.any(np.isnan(pair)):
        return None
    return c, float(np.log(pair[1] / pair[0]) / 2e-4)


def solve_c(mu: float, gamma: float, fine: Resolution, coarse: Resolution, *, c_guess: float,
            c_top: float) -> tuple[FlatField, float]:
    """The stick radius for given mu: the ``fine`` solution with mu_c(c) = mu and the error of its c.

    The start is the Chebyshev table's c (``numeric.core.table``) or, outside the table,
    Brent on the ``coarse`` resolution from ``c_guess`` (the asymptotic law), up to ``c_top``.
    Then secant steps in logit(c) on the fine level until the
    fine mu matches to 1e-11 relative (usually 1-2 solves, the start being that close), c
    stops moving in double precision (near c = 1), or 8 steps are spent: at very small c,
    mu(c) at fixed resolution jitters by ~1e-10 relative (measured at c = 4e-5). The best
    iterate is returned; the error of c adds its remaining mismatch in mu to the coarse
    level's mismatch (or the coarse c's distance), both converted to c by the slope.

    Raises
    ------
    AboveTopError
        If mu exceeds mu_c(c_top): the stick radius lies between c_top and the largest one.
    """
    start = _table_start(mu, gamma)
    coarse_field = None
    if start is None:
        coarse_field, slope = _coarse_root(mu, gamma, coarse, min(c_guess, c_top), c_top)
        c_start = coarse_field.c
    else:
        c_start, slope = start
    s_old, field = logit(c_start), solve_mu(c_start, gamma, fine, mu_guess=mu)
    g_old = math.log(field.mu) - math.log(mu)
    best, g_best = field, g_old
    for _ in range(8):
        if abs(g_old) < 1e-11:
            break
        s_new, new = _fine_step(mu, gamma, fine, s_old, -g_old / slope, c_top)
        g_new = math.log(new.mu) - math.log(mu)
        if abs(g_new) < abs(g_best):
            best, g_best = new, g_new
        if abs(new.c - field.c) <= 4 * np.spacing(new.c):  # c cannot move further in doubles
            break
        if g_new != g_old:
            slope = (g_new - g_old) / (s_new - s_old)
        s_old, g_old, field = s_new, g_new, new
    to_c = best.c * (1.0 - best.c) / abs(slope)  # d c = c (1 - c) d logit(c), d log mu = slope d logit(c)
    residual = abs(g_best) * to_c
    if coarse_field is None:
        check = solve_mu(best.c, gamma, coarse, mu_guess=mu)
        return best, residual + max(abs(math.log(check.mu / mu)) * to_c, abs(check.compliance - best.compliance))
    return best, residual + max(abs(best.c - coarse_field.c), abs(best.compliance - coarse_field.compliance))


def _fine_step(mu: float, gamma: float, fine: Resolution, s_old: float, step: float,
               c_top: float) -> tuple[float, FlatField]:
    """The fine solution at logit(c) = s_old + step, the step shortened fourfold while it overshoots
    the largest stick radius."""
    while True:
        s_new = s_old + step
        try:
            if expit(s_new) > c_top:
                if solve_mu(c_top, gamma, fine, mu_guess=mu).mu < mu:
                    raise AboveTopError()  # mu increases with c: the stick radius is above c_top
                raise NoEigenvalueError("step beyond the search's largest stick radius")
            return s_new, solve_mu(expit(s_new), gamma, fine, mu_guess=mu)
        except NoEigenvalueError:
            step /= 4.0  # overshot beyond the largest stick radius: shorten the step


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
