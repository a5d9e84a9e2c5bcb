"""The paper's own numerical scheme, [S75] §4 - the baseline, implemented faithfully.

Method ([S75] §4, §4.1, §4.2)
-----------------------------
* p(t) and t^-1 q(t) are piecewise constant on N intervals h_j = (t_{j-1}, t_j) of (0, 1)
  (4.1); the stick radius is a node, c = t_M (4.2).
* (2.2) is collocated at the midpoints x_i with the Abel integrals done exactly
  (``numeric.baseline.abel``), giving the partitioned system (4.3).
* In the slip annulus q = mu p (4.5) eliminates the shear unknowns j > M; the remaining
  N + M unknowns solve D p = e (4.6), (4.8). D is derived here from (4.3) and (4.5) (the
  transcript of (4.7) has lost signs): with L the 2N x 2N matrix of (4.3),

      rows i = 1..N  (normal):   D_ij = A_ij                                  j <= M
                                 D_ij = A_ij + mu gamma (x_i B_ij / x_j - |h_j|)   j > M
                                 D_i,N+j = gamma (x_i B_ij - x_j |h_j|)       j <= M
      rows N+i, i = 1..M (stick): D_N+i,j = -gamma B_ij                       j <= M
                                 D_N+i,j = -gamma B_ij + mu x_i A_ij / x_j    j > M
                                 D_N+i,N+j = x_i A_ij                         j <= M

  i.e. D(mu) = D0 + mu D1. The transcript's second block has the opposite overall sign
  (+gamma B_ij); that only flips the sign of the right-hand side u* of those rows.
* Compliance by the midpoint sum (4.9); the slip displacement u from (4.12).
* The eigenvalue: for fixed c, q/p at the last three stick midpoints is extrapolated to
  x = c by the quadratic through them ("Gaussian extrapolation") to give mu*(mu), and
  mu*(mu) = mu is solved by regula falsi to 1e-5 (§4.1). Plain regula falsi keeps one end
  of the bracket and needs up to 100 steps here; the paper reports "approximately five",
  so the Illinois form of regula falsi (halve the function value at an end kept twice) is
  used: the same bracketing method, 5-10 steps.
* The sphere (n = 2): (3.13) evaluated by the quadratic-interpolation quadrature
  (4.13)-(4.15), and A, C by least-squares fits of D p^(2) to 1 - x^2/A and 3 pi C x^2 / 4
  (4.16)-(4.17).

Meshes: the four of §4 (``paper_mesh("i")`` ... ``("iv")``), uniform meshes of any N, and
the friction mesh of §4.1 (widths 0.02, halved within 0.08 of c; ``friction_mesh``),
which refines uniformly with its coarse width ``h``.

This module is the yardstick for ``numeric``'s high-accuracy solver: do not improve it.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from asymptotics.arrays import read_only
from asymptotics.first_order import mu_over_gamma
from asymptotics.materials import check_c, resolve_gamma

from numeric.baseline.abel import lower_abel_weights, upper_abel_weights

__all__ = [
    "Mesh",
    "SchemeSolution",
    "SphereFit",
    "uniform_mesh",
    "paper_mesh",
    "friction_mesh",
    "collocation_matrix",
    "solve_at_mu",
    "solve_adhesive",
    "solve_friction",
    "sphere_from_flat",
]


@dataclass(frozen=True, slots=True)
class Mesh:
    """Nodes 0 = t_0 < ... < t_N = 1 of §4, with the stick radius at node ``stick_index`` (4.2)."""

    nodes: np.ndarray
    stick_index: int

    def __post_init__(self) -> None:
        nodes = read_only(self.nodes)
        if nodes.ndim != 1 or nodes.size < 4 or nodes[0] != 0.0 or nodes[-1] != 1.0:
            raise ValueError("nodes must be a 1-d array from 0 to 1 with at least 3 intervals")
        if np.any(np.diff(nodes) <= 0.0):
            raise ValueError("nodes must increase strictly")
        if not 3 <= self.stick_index <= nodes.size - 1:
            raise ValueError(f"stick_index must lie in [3, N], got {self.stick_index}")
        object.__setattr__(self, "nodes", nodes)

    @property
    def size(self) -> int:
        """Number of intervals N."""
        return self.nodes.size - 1

    @property
    def c(self) -> float:
        """Stick radius t_M."""
        return float(self.nodes[self.stick_index])

    @property
    def midpoints(self) -> np.ndarray:
        """Collocation points x_i = (t_{i-1} + t_i)/2."""
        return 0.5 * (self.nodes[1:] + self.nodes[:-1])

    @property
    def widths(self) -> np.ndarray:
        """Interval lengths |h_i|."""
        return np.diff(self.nodes)


def _mesh_from_widths(widths: list[tuple[int, float]], stick_index: int | None = None) -> Mesh:
    steps = np.concatenate([np.full(count, width) for count, width in widths])
    nodes = np.concatenate([[0.0], np.cumsum(steps)])
    nodes[-1] = 1.0
    return Mesh(nodes, nodes.size - 1 if stick_index is None else stick_index)


def uniform_mesh(n_intervals: int) -> Mesh:
    """N equal intervals, c = 1 (the fully adhesive case); meshes (i), (ii) of §4 are N = 25, 50."""
    if int(n_intervals) != n_intervals or n_intervals < 3:
        raise ValueError(f"n_intervals must be an integer >= 3, got {n_intervals!r}")
    return _mesh_from_widths([(int(n_intervals), 1.0 / n_intervals)])


_PAPER_MESHES = {
    "i": [(25, 0.04)],
    "ii": [(50, 0.02)],
    "iii": [(45, 0.02), (10, 0.01)],
    "iv": [(40, 0.02), (20, 0.01)],
}


def paper_mesh(label: str) -> Mesh:
    """One of the four adhesive test meshes (i)-(iv) of [S75] §4 (N = 25, 50, 55, 60), c = 1."""
    try:
        return _mesh_from_widths(_PAPER_MESHES[label])
    except KeyError:
        raise ValueError(f"label must be one of {sorted(_PAPER_MESHES)}, got {label!r}") from None


def _split(start: float, stop: float, width: float) -> np.ndarray:
    """Interior nodes plus ``stop`` for the fewest equal intervals no wider than ``width``."""
    count = max(1, math.ceil((stop - start) / width - 1e-9))
    return np.linspace(start, stop, count + 1)[1:]


def friction_mesh(c: float, h: float = 0.02, band: float = 0.08) -> Mesh:
    """The friction mesh of [S75] §4.1: widths h, halved within ``band`` of c = t_M.

    With the defaults and c a multiple of 0.02 this is exactly the paper's mesh
    (|h_i| = .02 except .01 for i = M-7 .. M+8). Near c = 0 or 1 the band is cut at the
    end of the interval ("modified slightly when c is close to 0 or 1"); elsewhere each
    piece gets the fewest equal intervals no wider than h (or h/2), so c stays a node.
    Halving ``h`` halves every width.
    """
    c = float(check_c(c))
    if not 0.0 < h <= 0.1:
        raise ValueError(f"h (coarse interval width) must lie in (0, 0.1], got {h!r}")
    fine = 0.5 * h
    lower = max(0.0, c - band)
    upper = min(1.0, c + band)
    if lower < 4 * fine:  # too short for coarse intervals: the band reaches 0
        lower = 0.0
    if 1.0 - upper < 4 * fine:
        upper = 1.0
    pieces = [np.array([0.0])]
    if lower > 0.0:
        pieces.append(_split(0.0, lower, h))
    pieces.append(_split(lower, c, fine))
    stick_index = sum(p.size for p in pieces) - 1
    if c < 1.0:
        pieces.append(_split(c, upper, fine))
        if upper < 1.0:
            pieces.append(_split(upper, 1.0, h))
    nodes = np.concatenate(pieces)
    nodes[stick_index] = c
    nodes[-1] = 1.0
    if stick_index < 3:
        raise ValueError(f"c = {c} is too small for the mesh width h = {h}: fewer than 3 stick intervals")
    return Mesh(nodes, stick_index)


@lru_cache(maxsize=64)
def collocation_matrix(nodes_key: bytes, gamma: float) -> np.ndarray:
    """The 2N x 2N matrix L of (4.3), acting on (p_1..p_N, s_1..s_N), s = q/t, for the mesh whose
    nodes are ``np.frombuffer(nodes_key)`` (cached per mesh and gamma; read-only)."""
    nodes = np.frombuffer(nodes_key)
    x = 0.5 * (nodes[1:] + nodes[:-1])
    widths = np.diff(nodes)
    A = upper_abel_weights(nodes, x)
    B = lower_abel_weights(nodes, x)
    top = np.hstack([A, gamma * (x[:, None] * B - (x * widths)[None, :])])  # (4.3a)
    bottom = np.hstack([-gamma * B, x[:, None] * A])  # (4.3b)
    L = np.vstack([top, bottom])
    L.setflags(write=False)
    return L


def _system(mesh: Mesh, gamma: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """D0, D1 with D(mu) = D0 + mu D1 of (4.6)-(4.7), and the full L of (4.3)."""
    n, m = mesh.size, mesh.stick_index
    L = collocation_matrix(mesh.nodes.tobytes(), gamma)
    rows = np.r_[0:n, n : n + m]
    D0 = np.hstack([L[rows, :n], L[rows, n : n + m]])
    D1 = np.zeros_like(D0)
    x_slip = mesh.midpoints[m:]
    D1[:, m:n] = L[rows, n + m :] / x_slip[None, :]  # (4.5): s_j = mu p_j / x_j, j > M
    return D0, D1, L


@dataclass(frozen=True, slots=True)
class SchemeSolution:
    """A flat-punch solution of the paper's scheme (values at the midpoints x_i).

    Attributes
    ----------
    mesh : Mesh
    gamma, mu, c : float
        Coupling constant, friction coefficient, stick radius t_M.
    pressure, shear : ndarray
        p_i and q_i = x_i s_i on each interval (4.1).
    shear_density : ndarray
        s_i = q_i / x_i, the paper's unknowns p_{i+N}.
    slip : ndarray
        u(x_i) by (4.12) in the slip annulus, 0 in the stick zone.
    compliance : float
        P* by the midpoint sum (4.9).
    central_pressure : float
        p(0), the value p_1 of the piecewise-constant pressure on the first interval.
    mu_star : float
        q/p extrapolated to x = c from the last three stick midpoints (§4.1); equals mu
        to within ``tol`` at the eigenvalue (nan when c = 1).
    iterations : int
        Regula falsi steps (0 when mu was given).
    converged : bool
    message : str
    """

    mesh: Mesh
    gamma: float
    mu: float
    c: float
    pressure: np.ndarray
    shear: np.ndarray
    shear_density: np.ndarray
    slip: np.ndarray
    compliance: float
    central_pressure: float
    mu_star: float
    iterations: int = 0
    converged: bool = True
    message: str = "solved at the given mu"


def _extrapolate_to_c(mesh: Mesh, ratio: np.ndarray) -> float:
    """Quadratic through the last three stick midpoints, evaluated at c (§4.1)."""
    m = mesh.stick_index
    xs = mesh.midpoints[m - 3 : m]
    return float(np.polyval(np.polyfit(xs, ratio[m - 3 : m], 2), mesh.c))


def _solve_vector(mesh: Mesh, gamma: float, mu: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Solve (4.6); return p (N), s = q/t (N) and L."""
    n, m = mesh.size, mesh.stick_index
    D0, D1, L = _system(mesh, gamma)
    rhs = np.r_[np.ones(n), np.zeros(m)]  # (4.8)
    sol = np.linalg.solve(D0 + mu * D1 if m < n else D0, rhs)
    p = sol[:n]
    s = np.empty(n)
    s[:m] = sol[n:]
    s[m:] = mu * p[m:] / mesh.midpoints[m:]  # (4.5)
    return p, s, L


def solve_at_mu(mesh: Mesh, mu: float, nu: float | None = None, *, gamma: float | None = None) -> SchemeSolution:
    """Solve the flat-punch system (4.6) on ``mesh`` for a given mu (no eigenvalue iteration).

    For mu other than the eigenvalue mu_c(c) the solution violates (2.8) or (2.9) near
    x = c (§4.1); use ``solve_friction`` for the physical solution.
    """
    g = resolve_gamma(nu, gamma)
    if not (mu >= 0.0 and math.isfinite(mu)):
        raise ValueError(f"mu (friction coefficient) must be finite and >= 0, got {mu!r}")
    p, s, L = _solve_vector(mesh, g, mu)
    n, m = mesh.size, mesh.stick_index
    x = mesh.midpoints
    u_star = L[n:, :n] @ p + L[n:, n:] @ s  # lower rows of (4.3)
    u_star[:m] = 0.0  # stick zone, where (4.3b) is imposed
    slip = (2.0 / np.pi) * (lower_abel_weights(mesh.nodes, x) @ u_star) / x  # (4.12)
    ratio = x * s / p
    return SchemeSolution(
        mesh=mesh,
        gamma=g,
        mu=float(mu),
        c=mesh.c,
        pressure=read_only(p),
        shear=read_only(x * s),
        shear_density=read_only(s),
        slip=read_only(slip),
        compliance=float(0.5 * np.pi * np.sum(mesh.widths * x * p)),  # (4.9)
        central_pressure=float(p[0]),
        mu_star=_extrapolate_to_c(mesh, ratio) if m < n else math.nan,
    )


def solve_adhesive(mesh: Mesh, nu: float | None = None, *, gamma: float | None = None) -> SchemeSolution:
    """The fully adhesive flat punch (c = 1, M = N) on a mesh of §4, e.g. ``paper_mesh("iii")``."""
    if mesh.stick_index != mesh.size:
        raise ValueError("the adhesive case needs a mesh with the stick radius at t_N = 1")
    sol = solve_at_mu(mesh, 0.0, nu, gamma=gamma)
    return replace(sol, mu=math.inf, message="fully adhesive, c = 1")


def solve_friction(
    c: float,
    nu: float | None = None,
    *,
    gamma: float | None = None,
    h: float = 0.02,
    tol: float = 1e-5,
    max_iterations: int = 100,
) -> SchemeSolution:
    """Friction coefficient mu_c(c) and the flat-punch stresses by the paper's iteration, §4.1.

    Parameters
    ----------
    c : float
        Stick radius, 0 < c <= 1 (c = 1 gives the adhesive solution).
    nu, gamma : float
        Exactly one: Poisson's ratio, or the coupling constant directly.
    h : float
        Coarse width of the friction mesh (``friction_mesh``); 0.02 is the paper's.
    tol : float
        Regula falsi stops when |mu*(mu) - mu| < tol (the paper's 1e-5).

    Returns
    -------
    SchemeSolution
        At mu = mu_c, with |mu*(mu_c) - mu_c| < tol.

    Raises
    ------
    RuntimeError
        If no bracket of mu_c on which regula falsi converges is found: at large gamma
        and c near 1 the coarse scheme's q/p extrapolation can fail (e.g. nu = -0.9,
        c = 0.95 at h = 0.02).
    """
    g = resolve_gamma(nu, gamma)
    mesh = friction_mesh(c, h)
    if mesh.stick_index == mesh.size:
        return solve_adhesive(mesh, gamma=g)
    if g == 0.0:  # q = 0 in the stick zone for every mu: the eigenvalue is mu = 0 (2.28)
        return replace(solve_at_mu(mesh, 0.0, gamma=g), message="gamma = 0: mu_c = 0")

    def excess(mu: float) -> tuple[float, SchemeSolution]:
        sol = solve_at_mu(mesh, mu, gamma=g)
        return sol.mu_star - mu, sol

    guess = g * float(mu_over_gamma(mesh.c))
    sol, last_failure = _bracketed_root(excess, guess, tol, max_iterations)
    if sol is not None:
        return sol
    raise RuntimeError(
        f"the paper's scheme finds no eigenvalue on this mesh (c = {c}, gamma = {g:.6g}, h = {h}) "
        f"for mu within a factor 1.2**40 of {guess:.3g}: {last_failure}"
    )


def _bracketed_root(excess, guess: float, tol: float, max_iterations: int) -> tuple[SchemeSolution | None, str]:
    """The eigenvalue from the first bracket on which regula falsi converges, or (None, why not).

    mu*(mu) has poles (a midpoint pressure crossing zero) besides the root, so brackets are
    sought outward from the small-gamma eigenvalue (2.28) on a grid of ratio 1.2 and each
    fall of mu*(mu) - mu through zero is tried in turn; only a bracket on which regula
    falsi reaches |mu* - mu| < tol is accepted, so a pole cannot pass for the root.
    """
    grid: dict[int, float] = {}
    last_failure = "no fall of mu*(mu) - mu through zero"
    for step in range(41):
        for k in sorted({step, -step}, reverse=True):
            grid[k] = excess(guess * 1.2**k)[0]
            for left in (k - 1, k):
                if left in grid and left + 1 in grid and grid[left] > 0.0 > grid[left + 1]:
                    lo, hi = guess * 1.2**left, guess * 1.2**(left + 1)
                    sol = _regula_falsi(excess, lo, grid[left], hi, grid[left + 1], tol, max_iterations)
                    if sol.converged:
                        return sol, ""
                    last_failure = sol.message
    return None, last_failure


def _regula_falsi(excess, lo: float, f_lo: float, hi: float, f_hi: float, tol: float, max_iterations: int) -> SchemeSolution:
    """Illinois regula falsi on mu*(mu) - mu = 0 from a bracket with f_lo > 0 > f_hi (§4.1)."""
    side = 0
    for iteration in range(1, max_iterations + 1):
        mu = hi - f_hi * (hi - lo) / (f_hi - f_lo)  # regula falsi
        f_mu, sol = excess(mu)
        if not math.isfinite(f_mu):  # a midpoint pressure exactly 0 there: a pole, not this bracket's root
            return replace(sol, iterations=iteration, converged=False,
                           message=f"mu*(mu) is not finite at mu = {mu!r} (a pole inside the bracket)")
        if abs(f_mu) < tol:
            return replace(sol, iterations=iteration, converged=True, message="regula falsi converged")
        if f_mu > 0.0:
            lo, f_lo = mu, f_mu
            if side == 1:  # Illinois step: halve the value kept twice at the other end
                f_hi *= 0.5
            side = 1
        else:
            hi, f_hi = mu, f_mu
            if side == -1:
                f_lo *= 0.5
            side = -1
    message = f"regula falsi did not reach |mu* - mu| < {tol} in {max_iterations} steps"
    return replace(sol, iterations=max_iterations, converged=False, message=message)


@dataclass(frozen=True, slots=True)
class SphereFit:
    """The sphere (n = 2) from a flat-punch solution by the paper's quadrature, §4.2.

    Attributes
    ----------
    pressure, shear : ndarray
        p^(2)(x_i) and q^(2)(x_i) = x_i p^(2)_{i+N} by (4.14)-(4.15).
    alpha0, alpha1 : float
        Least-squares fit alpha0 - alpha1 x^2 to the normal rows of D p^(2) (4.16)-(4.17);
        exact values 1 and 1/A.
    alpha2 : float
        Fit -alpha2 x^2 to the stick rows, i.e. alpha2 = -3 pi C / 4 (the paper's sign:
        its printed exact value .33271 is positive while C of (4.18) is negative).
    A, C : float
        1/alpha1 and -4 alpha2 / (3 pi), the paper's estimates of the constants of (3.2), (3.4).
    compliance : float
        (2/3) P0* by (3.17), the route the paper recommends.
    compliance_direct : float
        (pi/2) sum |h_j| x_j p^(2)_j, the direct quadrature; the paper quotes 4 times this
        (2.91840 against 4 (2/3) log 3 = 2.92963 at nu = 0; errata item 2).
    central_fit : tuple of float
        Coefficients (a0, a1, a2) of the quadratic a0 + a1 x + a2 x^2 through the first
        three p^(2)_i, the paper's check against (B6).
    """

    pressure: np.ndarray
    shear: np.ndarray
    alpha0: float
    alpha1: float
    alpha2: float
    A: float
    C: float
    compliance: float
    compliance_direct: float
    central_fit: tuple[float, float, float]


def _local_quadratics(x: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Coefficients (a, b, c) of a t^2 + b t + c through the three midpoints nearest each interval (4.15)."""
    n = x.size
    centre = np.clip(np.arange(n), 1, n - 2)
    idx = centre[:, None] + np.array([-1, 0, 1])[None, :]
    xs = x[idx]
    vander = np.stack([xs**2, xs, np.ones_like(xs)], axis=-1)
    return np.linalg.solve(vander, values[idx][..., None])[..., 0]


def _power_integrals(lo: np.ndarray, hi: np.ndarray, power: int) -> np.ndarray:
    """int_lo^hi t^power dt, elementwise (power = -1 gives the logarithm)."""
    if power == -1:
        return np.log(hi / lo)
    return (hi ** (power + 1) - lo ** (power + 1)) / (power + 1)


def _tail_integrals(mesh: Mesh, coeffs: np.ndarray, shift: int) -> np.ndarray:
    """int_{x_i}^1 t^(k - shift) (a t^2 + b t + c) dt with the interval-wise quadratics."""
    x, nodes = mesh.midpoints, mesh.nodes

    def piece(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
        return sum(coeffs[:, 2 - k] * _power_integrals(lo, hi, k - shift) for k in range(3))

    full = piece(nodes[:-1].clip(min=x[0]), nodes[1:])
    after = np.concatenate([np.cumsum(full[::-1])[::-1][1:], [0.0]])
    return piece(x, nodes[1:]) + after


def sphere_from_flat(flat: SchemeSolution) -> SphereFit:
    """Sphere stresses, A and C from a flat-punch solution by the quadrature of [S75] §4.2.

    (4.14): p^(2)_i = 2 x_i int_{x_i}^1 t^-2 p^(0) dt and p^(2)_{i+N} = 2 int_{x_i}^1 t^-1 s^(0) dt,
    with p^(0), s^(0) replaced interval by interval by the quadratic through the three
    nearest midpoint values (4.15) and integrated exactly. Then (4.16)-(4.17).
    """
    mesh = flat.mesh
    n, m = mesh.size, mesh.stick_index
    x = mesh.midpoints
    pressure = 2.0 * x * _tail_integrals(mesh, _local_quadratics(x, flat.pressure), 2)  # (4.14)
    density = 2.0 * _tail_integrals(mesh, _local_quadratics(x, flat.shear_density), 1)  # (4.14)
    D0, D1, _ = _system(mesh, flat.gamma)
    D = D0 + flat.mu * D1 if m < n else D0
    e = D @ np.r_[pressure, density[:m]]  # (4.16)
    (alpha0, minus_alpha1), *_ = np.linalg.lstsq(np.column_stack([np.ones(n), -(x**2)]), e[:n], rcond=None)
    alpha1 = float(minus_alpha1)
    x_stick = x[:m]
    alpha2 = float(-(e[n:] @ x_stick**2) / np.sum(x_stick**4))  # (4.17), paper's sign
    central = np.polyfit(x[:3], pressure[:3], 2)[::-1]
    return SphereFit(
        pressure=read_only(pressure),
        shear=read_only(x * density),
        alpha0=float(alpha0),
        alpha1=alpha1,
        alpha2=alpha2,
        A=1.0 / alpha1,
        C=-4.0 * alpha2 / (3.0 * np.pi),
        compliance=2.0 / 3.0 * flat.compliance,  # (3.17)
        compliance_direct=float(0.5 * np.pi * np.sum(mesh.widths * x * pressure)),
        central_fit=tuple(float(v) for v in central),
    )
