"""The plane flat punch with friction on a singular basis: layout, collocation system, eigenvalue.

Equations (``asymptotics.plane``; x over the half-width a, p even, q odd, load int p = 1):

    (N)  H p + gamma q = 0           on (-1, 1)   (flat punch: du_z/dx = 0)
    (T)  H q - gamma p = 0           on (-c, c)   (stick: du_x/dx = 0)
    (S)  q = mu sgn(x) p             on c < |x| < 1 (slip inward, friction outward)

and the eigenvalue condition (q - mu p)(c-) = 0: without it the stick side carries
(c - x)^(-1/2 - alpha), tan(pi alpha) = mu gamma.

Local exponents (``asymptotics.derive.plane``): at x = c on both sides p, q = A(x) + |x - c|^beta B(x),
beta = 1/2 - alpha; at the edge p = (1 - x)^(alpha - 1/2) E(x); A, B, E analytic. The basis
carries them: on [0, 1] the elements are a "stick end" [c - L, c] and a "slip end" [c, c + L]
(Legendre polynomials plus |x - c|^beta times polynomials of degree ``singular_degree``), the
"edge" [1 - L_e, 1] ((1 - x)^(alpha - 1/2) times polynomials), and plain polynomial elements
graded geometrically so that each is no longer than its distance to c or 1. p and q on
(-1, 0) are the even and odd reflections, so H of a basis function b at x is
H b(x) -+ H b(-x) (``numeric.core.plane_cauchy``).

Unknowns: P, Q on the stick elements, p on the slip elements (q = mu p there). Rows: (N) at
every collocation point, (T) at the stick points, and int_{-1}^{1} p = 1; the edge element
has one collocation point fewer than functions (the index of the edge, as in Gauss-Jacobi
collocation).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy import optimize

from numeric.core.errors import SolverError
from numeric.core.linear_algebra import EquilibratedLU
from numeric.core.plane_cauchy import element_cauchy, element_integrals, legendre01
from numeric.core.quadrature import gauss_legendre

__all__ = ["PLAIN", "STICK_END", "SLIP_END", "EDGE", "PlaneResolution", "PLANE_RESOLUTIONS", "PlaneLayout",
           "plane_layout", "families", "PlaneSystem", "PlaneSolution", "solve_plane_given_c", "solve_plane_given_mu",
           "owners", "transforms_at", "legendre_block_values"]

PLAIN, STICK_END, SLIP_END, EDGE = 0, 1, 2, 3


@dataclass(frozen=True, slots=True)
class PlaneResolution:
    """degree: Legendre degree of every element; singular_degree: of the |x - c|^beta family;
    c_fraction, edge_fraction: lengths of the elements at c (times min(c, 1 - c)) and at 1
    (times 1 - c); grading: ratio of successive plain elements."""

    degree: int = 12
    singular_degree: int = 4
    c_fraction: float = 0.25
    edge_fraction: float = 0.25
    grading: float = 2.0


#: Levels 0-3, coarse to fine (level 1 the default; ``tests/test_plane_solver.py`` measures them).
PLANE_RESOLUTIONS: tuple[PlaneResolution, ...] = (
    PlaneResolution(degree=8, singular_degree=3),
    PlaneResolution(degree=12, singular_degree=4),
    PlaneResolution(degree=16, singular_degree=5),
    PlaneResolution(degree=20, singular_degree=6),
)


@dataclass(frozen=True, slots=True, eq=False)
class PlaneLayout:
    """Elements on [0, 1]: kind, singular end a, orientation sigma (t = a + sigma L s), length L."""

    c: float
    kind: np.ndarray
    end: np.ndarray
    sigma: np.ndarray
    length: np.ndarray
    degree: int
    singular_degree: int

    def __len__(self) -> int:
        return self.kind.size

    @property
    def stick(self) -> np.ndarray:
        return (self.kind == STICK_END) | ((self.kind == PLAIN) & (self.end < self.c))

    def n_basis(self, e: int) -> int:
        extra = self.singular_degree + 2 if self.kind[e] in (STICK_END, SLIP_END) else 0
        return self.degree + 1 + extra

    def n_points(self, e: int) -> int:
        return self.n_basis(e) - (1 if self.kind[e] == EDGE else 0)

    def lo_hi(self, e: int) -> tuple[float, float]:
        a, b = self.end[e], self.end[e] + self.sigma[e] * self.length[e]
        return (a, b) if a < b else (b, a)


def _frozen(values, dtype) -> np.ndarray:
    out = np.array(values, dtype=dtype)
    out.setflags(write=False)
    return out


def plane_layout(c: float, res: PlaneResolution) -> PlaneLayout:
    """The elements for stick half-width c (0 < c < 1)."""
    gap = 1.0 - c
    Lc = res.c_fraction * min(c, gap)
    Le = res.edge_fraction * gap
    els = [(STICK_END, c, -1.0, Lc), (SLIP_END, c, 1.0, Lc), (EDGE, 1.0, -1.0, Le)]
    d = Lc  # plain stick elements down to 0, each no longer than (grading - 1) x its distance to c
    while d < c * (1.0 - 1e-15):
        step = d * (res.grading - 1.0)
        nd = c if d + step > c - 0.5 * step else d + step
        els.append((PLAIN, c - nd, 1.0, nd - d))
        d = nd
    a, top = c + Lc, 1.0 - Le  # plain slip elements: no longer than the distance to c, nor to 1 / grading
    while a < top * (1.0 - 1e-15):
        step = min((a - c) * (res.grading - 1.0), (1.0 - a) / res.grading)
        b = top if a + step > top - 0.5 * step else a + step
        els.append((PLAIN, a, 1.0, b - a))
        a = b
    els.sort(key=lambda el: el[1] + 0.5 * el[2] * el[3])
    kind, end, sigma, length = zip(*els)
    return PlaneLayout(c, _frozen(kind, int), _frozen(end, float), _frozen(sigma, float), _frozen(length, float),
                       res.degree, res.singular_degree)


def families(lay: PlaneLayout, e: int, field: str, alpha: float) -> tuple[tuple[float, int], ...]:
    """(exponent, degree) of the families s^lam P_0..P_degree of element e for ``field`` "P", "Q" (stick) or "p" (slip).

    At c the generic solution (mu not the eigenvalue) has (c - x)^(-1/2 - alpha) in q on the stick side and
    (x - c)^(-1/2 - alpha) in p on the slip side, none in p on the stick side (``asymptotics.derive.plane``):
    those families start at -1/2 - alpha (and so contain |x - c|^(1/2 - alpha) too); p on the stick side
    starts at 1/2 - alpha. The eigenvalue is where the amplitude of (c - x)^(-1/2 - alpha) in q vanishes.
    """
    kind, d, sd = lay.kind[e], lay.degree, lay.singular_degree
    if kind == PLAIN:
        return ((0.0, d),)
    if kind == EDGE:
        return ((alpha - 0.5, d),)
    if kind == STICK_END and field == "P":
        return ((0.0, d), (0.5 - alpha, sd))
    if kind == STICK_END:
        return ((0.0, d), (-0.5 - alpha, sd))
    return ((0.0, d), (-0.5 - alpha, sd + 1))


def _size(fams) -> int:
    return sum(deg + 1 for _, deg in fams)


def _chart_points(n: int, kind: int) -> np.ndarray:
    r = 0.5 * (gauss_legendre(n)[0] + 1.0)
    return r if kind == PLAIN else r**1.25


@dataclass(frozen=True, slots=True, eq=False)
class Block:
    """The basis of one field over its elements: H of its even and odd reflections at the points, its values
    at the points (0 off each function's element), int_0^1 of each function, and where each element starts."""

    elements: np.ndarray
    starts: np.ndarray
    even: np.ndarray
    odd: np.ndarray
    values: np.ndarray
    integrals: np.ndarray


def _block(lay: PlaneLayout, elements, field: str, alpha: float, x: np.ndarray, owner: np.ndarray,
           transforms: bool = True) -> Block:
    sizes = [_size(families(lay, e, field, alpha)) for e in elements]
    starts = np.concatenate([[0], np.cumsum(sizes)]).astype(int)
    n = int(starts[-1])
    shape = (x.size, n) if transforms else (0, n)
    He, Ho, V, integrals = np.zeros(shape), np.zeros(shape), np.zeros((x.size, n)), np.zeros(n)
    for k, e in enumerate(elements):
        a, sg, L = lay.end[e], lay.sigma[e], lay.length[e]
        col = int(starts[k])
        y_plus = (x - a) / (sg * L)
        mine = owner == e
        s = np.clip(y_plus[mine], 0.0, 1.0)
        for lam, deg in families(lay, e, field, alpha):
            cols = slice(col, col + deg + 1)
            if transforms:
                # t = a + sigma L s: dt / (t - x) = ds / (s - y), and s runs against t where sigma = -1
                plus = (sg / math.pi) * element_cauchy(lam, deg, y_plus)
                minus = (sg / math.pi) * element_cauchy(lam, deg, (-x - a) / (sg * L))
                He[:, cols] = plus - minus  # H of the even reflection: H b(x) - H b(-x)
                Ho[:, cols] = plus + minus  # odd reflection
            V[mine, cols] = legendre01(deg, s) * _power(s, lam, kind=int(lay.kind[e]))[:, None]
            integrals[cols] = L * element_integrals(lam, deg)
            col += deg + 1
    return Block(np.asarray(elements), starts, He, Ho, V, integrals)


def _power(s: np.ndarray, lam: float, kind: int) -> np.ndarray:
    """s^lam; at s = 0 with lam < 0: inf at the edge (p there is infinite), 0 at c (there the family's
    amplitude is the eigen residual, ~0, and the next term vanishes: the field's value at c is the regular part)."""
    if lam == 0.0:
        return np.ones(s.shape)
    at_zero = s == 0.0
    out = np.where(at_zero, 1.0, s) ** lam
    if lam < 0.0:
        out[at_zero] = np.inf if kind == EDGE else 0.0
    return out


def owners(lay: PlaneLayout, x: np.ndarray) -> np.ndarray:
    """The element holding each point 0 <= x <= 1 (x = c goes to the stick end, x = 1 to the edge)."""
    lo = np.array([lay.lo_hi(e)[0] for e in range(len(lay))])
    order = np.argsort(lo)
    k = np.clip(np.searchsorted(lo[order], x, side="right") - 1, 0, len(lay) - 1)
    out = order[k]
    at_c = x == lay.c
    out[at_c] = int(np.flatnonzero(lay.kind == STICK_END)[0])
    return out


class PlaneSystem:
    """The collocation system for one layout and one mu; ``solve`` returns the coefficients z = [P, Q, p]."""

    def __init__(self, lay: PlaneLayout, gamma: float, mu: float) -> None:
        self.layout, self.gamma, self.mu = lay, gamma, mu
        self.alpha = math.atan(mu * gamma) / math.pi
        points, owner = [], []
        for e in range(len(lay)):
            n = _size(families(lay, e, "P" if lay.stick[e] else "p", self.alpha)) - (lay.kind[e] == EDGE)
            s = _chart_points(n, int(lay.kind[e]))
            points.append(lay.end[e] + lay.sigma[e] * lay.length[e] * s)
            owner.append(np.full(s.size, e))
        order = np.argsort(np.concatenate(points))
        self.x = np.concatenate(points)[order]
        self.owner = np.concatenate(owner)[order]
        self.stick_point = self.x < lay.c
        stick = np.flatnonzero(lay.stick)
        slip = np.flatnonzero(~lay.stick)
        self.blocks = {f: _block(lay, els, f, self.alpha, self.x, self.owner)
                       for f, els in (("P", stick), ("Q", stick), ("p", slip))}

    @property
    def layout_ends(self) -> np.ndarray:
        """Every element end: H of a single element is log-singular there, so fields are not evaluated on them."""
        lay = self.layout
        return np.unique(np.concatenate([lay.lo_hi(e) for e in range(len(lay))]))

    def block_at(self, x: np.ndarray, field: str, transforms: bool = True) -> Block:
        """The basis of ``field`` at other points 0 <= x <= 1 (values, and the transforms unless not asked for)."""
        x = np.asarray(x, dtype=float)
        return _block(self.layout, self.blocks[field].elements, field, self.alpha, x, owners(self.layout, x), transforms)

    @property
    def n_unknowns(self) -> int:
        return sum(b.starts[-1] for b in self.blocks.values())

    def matrix(self) -> tuple[np.ndarray, np.ndarray]:
        """D z = b: (N) at every point, (T) at the stick points, int_{-1}^{1} p = 1."""
        g, mu = self.gamma, self.mu
        P, Q, p = self.blocks["P"], self.blocks["Q"], self.blocks["p"]
        sp = self.stick_point
        N = self.x.size
        nP, nQ = int(P.starts[-1]), int(Q.starts[-1])
        D = np.zeros((N + int(sp.sum()) + 1, self.n_unknowns))
        cP, cQ, cp = slice(0, nP), slice(nP, nP + nQ), slice(nP + nQ, None)
        D[:N, cP] = P.even                           # (N): H p (stick part)
        D[:N, cQ] = g * Q.values                     #      + gamma q at stick points
        D[:N, cp] = p.even + (g * mu) * p.values     #      + H p (slip part) + gamma mu p at slip points
        D[N:-1, cQ] = Q.odd[sp]                      # (T): H q (stick part)
        D[N:-1, cp] = mu * p.odd[sp]                 #      + H (mu p) (slip part)
        D[N:-1, cP] = -g * P.values[sp]              #      - gamma p
        D[-1, cP] = 2.0 * P.integrals                # int_{-1}^{1} p = 1
        D[-1, cp] = 2.0 * p.integrals
        rhs = np.zeros(D.shape[0])
        rhs[-1] = 1.0
        if D.shape[0] != D.shape[1]:
            raise SolverError(f"plane system is {D.shape}, not square")
        return D, rhs

    def split(self, z: np.ndarray) -> dict[str, np.ndarray]:
        nP, nQ = int(self.blocks["P"].starts[-1]), int(self.blocks["Q"].starts[-1])
        return {"P": z[:nP], "Q": z[nP:nP + nQ], "p": z[nP + nQ:]}

    def end_values(self, z: np.ndarray) -> tuple[float, float, float]:
        """At c- (stick-end element, s = 0): p, the regular part of q, and the amplitude of (c - x)^(-1/2 - alpha) in q."""
        lay = self.layout
        e = int(np.flatnonzero(lay.kind == STICK_END)[0])
        parts = self.split(z)
        out = []
        for f in ("P", "Q"):
            block = self.blocks[f]
            k = int(np.flatnonzero(block.elements == e)[0])
            col = int(block.starts[k])
            values = []
            for lam, deg in families(lay, e, f, self.alpha):
                values.append(float(((-1.0) ** np.arange(deg + 1)) @ parts[f][col:col + deg + 1]))
                col += deg + 1
            out.append(values)
        return out[0][0], out[1][0], out[1][1]

    def solve(self) -> np.ndarray:
        D, b = self.matrix()
        return EquilibratedLU(D).solve(b)

    def eigen_residual(self, z: np.ndarray) -> float:
        """Amplitude of (c - x)^(-1/2 - alpha) in q - mu p on the stick side over mu p(c-): 0 at the eigenvalue."""
        p, _, amplitude = self.end_values(z)
        return amplitude / (self.mu * p)


@dataclass(frozen=True, slots=True, eq=False)
class PlaneSolution:
    """mu, c and the coefficients on ``system`` (its layout, gamma and basis exponent)."""

    system: PlaneSystem
    coefficients: np.ndarray
    residual: float

    @property
    def mu(self) -> float:
        return self.system.mu

    @property
    def c(self) -> float:
        return self.system.layout.c


def _residual_in_theta(lay: PlaneLayout, gamma: float, theta: float) -> tuple[float, PlaneSystem, np.ndarray]:
    system = PlaneSystem(lay, gamma, math.tan(theta) / gamma)
    z = system.solve()
    return system.eigen_residual(z), system, z


def solve_plane_given_c(c: float, gamma: float, mu_guess: float, res: PlaneResolution, *, tol: float = 1e-14,
                        max_steps: int = 40) -> PlaneSolution:
    """mu for stick half-width c: the secant method in theta = atan(mu gamma) on the eigen residual."""
    lay = plane_layout(c, res)
    t0 = math.atan(mu_guess * gamma)
    t1 = t0 * (1.0 + 1e-4)
    g0, _, _ = _residual_in_theta(lay, gamma, t0)
    g1, system, z = _residual_in_theta(lay, gamma, t1)
    previous = math.inf
    for _ in range(max_steps):
        if g1 == g0:
            break
        t2 = t1 - g1 * (t1 - t0) / (g1 - g0)
        if not 0.0 < t2 < 0.5 * math.pi:
            t2 = min(max(t2, 0.5 * t1), 0.5 * (t1 + 0.5 * math.pi))
        t0, g0 = t1, g1
        t1 = t2
        g1, system, z = _residual_in_theta(lay, gamma, t1)
        size = abs(t1 - t0)
        if size <= tol * t1 or (size <= 1e-9 * t1 and size >= 0.25 * previous):
            return PlaneSolution(system, z, g1)
        previous = size
    if abs(t1 - t0) <= 1e-9 * t1:
        return PlaneSolution(system, z, g1)
    raise SolverError(f"the secant iteration in theta did not converge for c = {c}, gamma = {gamma}")


def solve_plane_given_mu(mu: float, gamma: float, c_guess: float, res: PlaneResolution, *, tol: float = 1e-14,
                         max_steps: int = 40) -> PlaneSolution:
    """c for friction mu: the secant method in logit c on the eigen residual."""

    def residual(xi: float):
        c = 1.0 / (1.0 + math.exp(-xi))
        system = PlaneSystem(plane_layout(c, res), gamma, mu)
        z = system.solve()
        return system.eigen_residual(z), system, z

    x0 = math.log(c_guess / (1.0 - c_guess))
    x1 = x0 + 1e-3
    g0, _, _ = residual(x0)
    g1, system, z = residual(x1)
    previous = math.inf
    for _ in range(max_steps):
        if g1 == g0:
            return PlaneSolution(system, z, g1)
        x2 = x1 - g1 * (x1 - x0) / (g1 - g0)
        x0, g0 = x1, g1
        x1 = x2
        g1, system, z = residual(x1)
        size = abs(x1 - x0)
        if size <= tol * max(1.0, abs(x1)) or (size <= 1e-9 and size >= 0.25 * previous):
            return PlaneSolution(system, z, g1)
        previous = size
    raise SolverError(f"the secant iteration in c did not converge for mu = {mu}, gamma = {gamma}")


def transforms_at(system: PlaneSystem, x: np.ndarray, field: str) -> tuple[np.ndarray, np.ndarray]:
    """H of the even and odd reflections of ``field``'s basis at points x."""
    block = system.block_at(x, field)
    return block.even, block.odd


def legendre_block_values(system: PlaneSystem, x: np.ndarray, field: str) -> np.ndarray:
    """Values of ``field``'s basis at points x (each on its own element; x on the field's zone)."""
    return system.block_at(x, field, transforms=False).values
