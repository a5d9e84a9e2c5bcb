"""Plane strain: closed forms of the strip punch and the cylinder with friction (the 2-D counterpart of [S75]).

Formulation (derived in ``asymptotics.derive.plane``). A rigid punch is pressed monotonically
into the half-plane z > 0 over |X| < a; p(x) is the pressure and q(x) the shear traction on
the half-plane in the +X direction, x = X/a, both over P/a (P the load per unit length), so
that int_{-1}^{1} p dx = 1. The surface relations of plane strain (Johnson, Contact
Mechanics, (2.25)) read, with H f(x) = (1/pi) PV int_{-1}^{1} f(t) dt / (t - x),

    (G a / ((1 - nu) P)) du_z/dX = H p + gamma q,
    (G a / ((1 - nu) P)) du_x/dX = H q - gamma p,      gamma = (1 - 2 nu) / (2 - 2 nu),

the same gamma as [S75] (2.2) (plane stress: nu -> nu / (1 + nu), gamma = (1 - nu)/2). The flat
punch: H p + gamma q = 0 on (-1, 1); stick |x| < c: H q - gamma p = 0; slip c < |x| < 1, inward:
q = mu sgn(x) p (friction on the half-plane acts outward). For every load the same c (the
problem is linear in P); for a profile |X|^n the increments are flat punches of the current
width, so c is the same for every n and p = n x^(n-1) int_x^1 t^-n p0(t) dt ([S75] (3.13)).

Closed forms here:
- first order in gamma: mu / gamma = K(c) / K'(c) (the 2-D (2.28)), its inverse
  c = theta_2(q)^2 / theta_3(q)^2 with the nome q = exp(-pi gamma / mu), and its limits
  c ~ 4 exp(-pi gamma / (2 mu)) (mu -> 0), 1 - c ~ 8 exp(-pi mu / gamma) (mu -> inf);
- full inward slip (the limit c -> 0 away from the stick zone): p = (cos(pi alpha)/pi) (1 - x^2)^(alpha - 1/2) |x|^(-2 alpha),
  q = mu sgn(x) p, tan(pi alpha) = mu gamma;
- frictionless: Sadowsky's punch p = 1 / (pi sqrt(1 - x^2)), Hertz's cylinder p = (2/pi) sqrt(1 - x^2),
  P = pi a^2 E* / (4 R);
- fully bonded (Abramov): p + i q = (cosh(pi eps)/pi) (1 - x)^(-1/2 - i eps) (1 + x)^(-1/2 + i eps),
  eps = atanh(gamma)/pi = log(3 - 4 nu)/(2 pi).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
from numpy.typing import ArrayLike
from scipy import special

from .arrays import scalar_or_array
from .materials import check_c, check_gamma, check_mu, check_nu, check_x

__all__ = ["gamma_plane_stress", "bonded_index", "mu_over_gamma_plane", "mu_over_gamma_plane_mp",
           "friction_slope_first_order", "stick_width_first_order", "slip_width_first_order",
           "stick_width_first_order_mp", "c_small_mu_plane", "gap_large_mu_plane",
           "pressure_sadowsky", "pressure_full_slip", "pressure_hertz_cylinder", "hertz_cylinder_load", "bonded_traction", "EXACT_RELATION"]

_THETA_TERMS = 12

#: The closing note on the exact eigen-relation (rendered in ``derivations/plane_strain.md``).
EXACT_RELATION = """## The exact relation: what it was reduced to, and why no closed form is given here

With w = p + i q and F(z) = (1/(2 pi i)) int_{-1}^{1} w(t) dt/(t - z), the conditions are, on the stick zone |x| < c,
F+ = -((1 + gamma)/(1 - gamma)) F- (H w = i gamma w); on the slip zones c < |x| < 1 two real conditions,
Im[(1 - i mu sgn x)(F+ - F-)] = 0 (q = mu sgn(x) p) and -Im(F+ + F-) + gamma mu sgn(x) Re(F+ - F-) = 0 (flat punch);
F+ = F- outside. For the vector (F, F*), F*(z) = conj F(conj z), these are a 2 x 2 matrix Riemann-Hilbert problem with
piecewise constant jumps: diagonal on the stick zone, non-diagonal on each slip zone, and the jump matrices of the two
kinds do not commute, so it does not reduce to scalar problems (the flat-punch symmetry F(-z) = F*(z) folds it onto
zeta = z^2 with singular points 0, c^2, 1 and infinity, but the jumps still do not commute). Its solution is that of a
Fuchsian system with four singular points whose monodromy is given (local exponents 0 and 1/2 - alpha at c, alpha - 1/2
at 1, 2-D-exponents below), a connection problem of Heun / Painleve VI type with no elementary solution in general; the
eigenvalue condition is that the exponent at c is 1/2 - alpha and not -1/2 - alpha. [S73] is reported (in [S75] §2.2,
§4.1) to have solved the 2-D problem analytically, by a Wiener-Hopf technique, and to have shown the Fredholm kernel of
the reduction analogous to [S75] (2.24) positive; that paper was not available here and its relation was not
reproduced. In one more attempt the reduction of [S75] §2.2 was followed in the plane: phi = p - q/mu vanishes on the
slip zones, the normal relation becomes a Carleman equation tan(pi alpha) sgn(x) p + H p = tan(pi alpha) sgn(x) phi on
(-1, 1), solvable in closed form (its fundamental solution (1 - x^2)^(alpha - 1/2) |x|^(-2 alpha), the |x|^(-2 alpha)
term excluded as in [S75] (2.20)), and the stick relation then gives a regular equation for phi on (-c, c); its kernel
was not brought to closed form within the time set for this. What is given instead: the first-order law
mu/gamma = K(c)/K'(c) in closed form with its limits and its measured O(gamma^2) error (below), the largest stick width
from the limit problem, and the full solution to 1e-10.
"""



def gamma_plane_stress(nu: ArrayLike) -> np.ndarray | float:
    """gamma for plane stress: (1 - 2 nu')/(2 - 2 nu') with nu' = nu/(1 + nu), i.e. (1 - nu)/2.

    >>> float(gamma_plane_stress(0.0)), float(gamma_plane_stress(0.5))
    (0.5, 0.25)
    """
    return scalar_or_array(0.5 * (1.0 - check_nu(nu)))


def bonded_index(gamma: ArrayLike) -> np.ndarray | float:
    """eps = atanh(gamma)/pi = log((1 + gamma)/(1 - gamma))/(2 pi) = log(3 - 4 nu)/(2 pi) (Abramov's index).

    >>> round(float(bonded_index(0.5)), 12)   # nu = 0: log(3)/(2 pi)
    0.174849576283
    """
    return scalar_or_array(np.arctanh(check_gamma(gamma)) / math.pi)


def mu_over_gamma_plane(c: ArrayLike) -> np.ndarray | float:
    """First-order friction law of the strip punch: mu/gamma = K(c)/K'(c) (modulus c).

    Both through ``ellipkm1`` (K(c) = ellipkm1((1 - c)(1 + c)), K'(c) = ellipkm1(c^2)) so that neither loses
    digits to a rounded 1 - c^2 as c -> 1 or c -> 0.

    >>> round(float(mu_over_gamma_plane(0.5)), 12)
    0.781700961348
    """
    c_arr = check_c(c)
    with np.errstate(divide="ignore"):
        out = special.ellipkm1((1.0 - c_arr) * (1.0 + c_arr)) / special.ellipkm1(c_arr * c_arr)
    return scalar_or_array(out)


def mu_over_gamma_plane_mp(c, dps: int = 30):
    """``mu_over_gamma_plane`` in mpmath."""
    with mpmath.workdps(dps):
        c = mpmath.mpf(c)
        return mpmath.ellipk(c * c) / mpmath.ellipk(1 - c * c)


def friction_slope_first_order(c: float, gap: float, gamma: float) -> float:
    """d mu / d logit c of the first-order law mu = gamma K(c)/K'(c) at c = 1 - gap: gamma pi / (2 (1 + c) K'(c)^2)
    (Legendre's relation gives d(K/K')/dc = pi / (2 c k'^2 K'^2), k'^2 = 1 - c^2 = gap (1 + c), and d c / d logit c =
    c gap); K'(c) through ``ellipkm1`` (m = 1 - c^2 = 1 - (1 - gap)^2 is not formed).

    >>> round(friction_slope_first_order(0.5, 0.5, 1.0), 12)   # pi / (3 K(m = 3/4)^2)
    0.225176669092
    """
    k_prime = float(special.ellipkm1(c * c))  # K(m = 1 - c^2)
    return gamma * math.pi / (2.0 * (1.0 + c) * k_prime * k_prime)


def _modulus_of_nome(log_nome: np.ndarray) -> np.ndarray:
    """k = theta_2(q)^2 / theta_3(q)^2 for q = exp(log_nome) <= exp(-pi): 4 sqrt(q) (sum q^(n(n+1)))^2 / theta_3^2,
    the factor 4 sqrt(q) taken as an exponential so that it does not underflow before k does."""
    n = np.arange(0, _THETA_TERMS)
    q = np.exp(log_nome)[..., None]
    reduced = np.sum(q ** (n * (n + 1)), axis=-1)  # theta_2 / (2 q^(1/4))
    theta3 = 1.0 + 2.0 * np.sum(q ** (n[1:] ** 2), axis=-1)
    return 4.0 * np.exp(0.5 * log_nome) * (reduced / theta3) ** 2


def stick_width_first_order(mu: ArrayLike, gamma: ArrayLike) -> np.ndarray | float:
    """Inverse of K(c)/K'(c) = mu/gamma: c = theta_2(q)^2/theta_3(q)^2, q = exp(-pi gamma/mu) (Jacobi's nome).

    Uses the nome of the complementary modulus where q > exp(-pi) (large mu/gamma) so that the
    theta series converge fast either way: c = theta_4(q')^2/theta_3(q')^2, q' = exp(-pi mu/gamma).

    >>> round(float(stick_width_first_order(0.5 * 0.781700961348, 0.5)), 9)
    0.5
    """
    mu_arr = check_mu(mu)
    g = check_gamma(gamma)
    with np.errstate(over="ignore"):  # mu subnormal: K'/K beyond the doubles, c = 0
        ratio = np.divide(g, mu_arr, out=np.full(np.broadcast(mu_arr, g).shape, np.inf), where=mu_arr > 0.0)  # K'/K
    out = np.empty(ratio.shape)
    direct = ratio >= 1.0
    with np.errstate(over="ignore", under="ignore"):
        out[direct] = _modulus_of_nome(-math.pi * ratio[direct])
        inv = ~direct
        qp = np.exp(-math.pi / ratio[inv])
        n = np.arange(1, _THETA_TERMS)
        theta3 = 1.0 + 2.0 * np.sum(qp[..., None] ** (n**2), axis=-1)
        theta4 = 1.0 + 2.0 * np.sum((-1.0) ** n * qp[..., None] ** (n**2), axis=-1)
        out[inv] = (theta4 / theta3) ** 2
    return scalar_or_array(out)


def slip_width_first_order(mu: ArrayLike, gamma: ArrayLike) -> np.ndarray | float:
    """1 - c of ``stick_width_first_order``, without the cancellation of forming it from c as c -> 1: where
    mu/gamma > 1, (theta_3^2 - theta_4^2)/theta_3^2 at q' = exp(-pi mu/gamma), with theta_3 - theta_4 =
    4 (q' + q'^9 + ...) and theta_3 + theta_4 = 2 (1 + 2 q'^4 + 2 q'^16 + ...); 8 exp(-pi mu/gamma) to leading order
    (``gap_large_mu_plane``), 0 where that underflows.

    >>> f"{float(slip_width_first_order(10.0, 0.5)):.6e}"   # 8 q' (1 - 4 q' + ...), q' = exp(-20 pi)
    '4.126320e-27'
    """
    mu_arr = check_mu(mu)
    g = check_gamma(gamma)
    with np.errstate(over="ignore"):  # gamma subnormal: K/K' beyond the doubles, 1 - c = 0
        ratio = np.divide(mu_arr, g, out=np.full(np.broadcast(mu_arr, g).shape, np.inf), where=g > 0.0)  # K/K'
    out = np.empty(ratio.shape)
    near = ratio > 1.0
    with np.errstate(over="ignore", under="ignore"):
        out[~near] = 1.0 - np.asarray(stick_width_first_order(np.broadcast_to(mu_arr, ratio.shape)[~near],
                                                              np.broadcast_to(g, ratio.shape)[~near]), dtype=float)
        qp = np.exp(-math.pi * ratio[near])[..., None]
        n = np.arange(1, _THETA_TERMS)
        odd, even = n[n % 2 == 1], n[n % 2 == 0]
        difference = 4.0 * np.sum(qp ** (odd**2), axis=-1)
        total = 2.0 + 4.0 * np.sum(qp ** (even**2), axis=-1)
        theta3 = 1.0 + 2.0 * np.sum(qp ** (n**2), axis=-1)
        out[near] = difference * total / theta3**2
    return scalar_or_array(out)


def stick_width_first_order_mp(mu, gamma, dps: int = 30):
    """``stick_width_first_order`` in mpmath (jtheta)."""
    with mpmath.workdps(dps):
        q = mpmath.exp(-mpmath.pi * mpmath.mpf(gamma) / mpmath.mpf(mu))
        return mpmath.jtheta(2, 0, q) ** 2 / mpmath.jtheta(3, 0, q) ** 2


def c_small_mu_plane(mu: ArrayLike, gamma: ArrayLike) -> np.ndarray | float:
    """mu -> 0 at fixed gamma: c ~ 4 exp(-pi gamma / (2 mu)) (leading term of theta_2^2/theta_3^2)."""
    return scalar_or_array(4.0 * np.exp(-math.pi * check_gamma(gamma) / (2.0 * check_mu(mu))))


def gap_large_mu_plane(mu: ArrayLike, gamma: ArrayLike) -> np.ndarray | float:
    """mu -> inf at first order in gamma: 1 - c ~ 8 exp(-pi mu / gamma) (the full solution saturates instead)."""
    return scalar_or_array(8.0 * np.exp(-math.pi * check_mu(mu) / check_gamma(gamma)))


def pressure_sadowsky(x: ArrayLike) -> np.ndarray | float:
    """Frictionless flat punch: p = 1/(pi sqrt(1 - x^2)), int_{-1}^{1} p = 1."""
    x_arr = np.abs(check_x(np.abs(x)))
    with np.errstate(divide="ignore"):
        return scalar_or_array(1.0 / (math.pi * np.sqrt((1.0 - x_arr) * (1.0 + x_arr))))


def pressure_full_slip(x: ArrayLike, alpha: float) -> np.ndarray | float:
    """Flat punch slipping inward at every x != 0: p = (cos(pi alpha)/pi) (1 - x^2)^(alpha - 1/2) |x|^(-2 alpha).

    With q = mu sgn(x) p the normal relation H p + gamma q = 0 becomes the Carleman equation
    H p + tan(pi alpha) sgn(x) p = 0 (tan(pi alpha) = mu gamma, 0 <= alpha < 1/2); this is its solution
    bounded by |x|^(-2 alpha) at x = 0, normalised by int_{-1}^{1} p = B(1/2 - alpha, 1/2 + alpha) cos(pi alpha)/pi = 1.
    It is the strip punch's pressure away from a stick zone that has shrunk to a point (c -> 0, small mu):
    ``numeric.plane`` uses it below the solver's smallest c. alpha = 0: Sadowsky's punch.

    >>> round(float(pressure_full_slip(0.5, 0.0)), 15) == round(float(pressure_sadowsky(0.5)), 15)
    True
    """
    if not 0.0 <= alpha < 0.5:
        raise ValueError(f"alpha (atan(mu gamma)/pi) must lie in [0, 1/2), got {alpha!r}")
    x_arr = np.abs(check_x(np.abs(x)))
    with np.errstate(divide="ignore"):
        return scalar_or_array((math.cos(math.pi * alpha) / math.pi) * ((1.0 - x_arr) * (1.0 + x_arr)) ** (alpha - 0.5)
                               * x_arr ** (-2.0 * alpha))


def pressure_hertz_cylinder(x: ArrayLike) -> np.ndarray | float:
    """Frictionless cylinder (Hertz): p = (2/pi) sqrt(1 - x^2), i.e. sigma = (2P/(pi a^2)) sqrt(a^2 - X^2)."""
    x_arr = np.abs(check_x(np.abs(x)))
    return scalar_or_array((2.0 / math.pi) * np.sqrt((1.0 - x_arr) * (1.0 + x_arr)))


def hertz_cylinder_load(a: float, radius: float, reduced_modulus: float) -> float:
    """Load per unit length of the frictionless cylinder: P = pi a^2 E* / (4 R)."""
    return math.pi * a * a * reduced_modulus / (4.0 * radius)


def bonded_traction(x: ArrayLike, gamma: float) -> np.ndarray | complex:
    """Fully bonded flat punch (Abramov): p + i q = (cosh(pi eps)/pi) (1 - x)^(-1/2 - i eps) (1 + x)^(-1/2 + i eps).

    Solves H w = i gamma w on (-1, 1) (stick everywhere) with int p = 1; q > 0 near x = 1-, the
    outward traction, and p changes sign infinitely often as x -> 1. At x = +-1 the traction has no value (its
    modulus grows without bound while its phase turns without end): ValueError there (it was NaN with a warning).

    >>> w = bonded_traction(0.0, 0.5)
    >>> round(float(w.real), 12), float(w.imag)
    (0.367552596948, 0.0)
    """
    x_arr = check_x(np.abs(x)) * np.sign(x)
    if np.any(np.abs(x_arr) == 1.0):
        raise ValueError("x must lie strictly inside (-1, 1) for the bonded punch: at the edges its traction "
                         "oscillates in sign with unbounded modulus and has no value")
    eps = float(bonded_index(gamma))
    log_ratio = 2.0 * np.arctanh(x_arr)  # log((1 + x)/(1 - x))
    out = (math.cosh(math.pi * eps) / math.pi) / np.sqrt((1.0 - x_arr) * (1.0 + x_arr)) * np.exp(1j * eps * log_ratio)
    return out[()] if out.ndim == 0 else out
