"""SymPy derivations of the plane-strain strip punch and cylinder with friction (issue 14, [S75] §5's counterpart).

Entries (part "P", document ``derivations/plane_strain.md``):

- "2D-formulation": the half-plane surface relations with friction, H p + gamma q = 0 (flat punch), H q - gamma p = 0
  (stick), q = mu sgn(x) p (slip), in complex form H w = i gamma w on the stick zone (w = p + i q); the fully
  stuck punch (Abramov) w = (cosh(pi eps)/pi) (1 - x)^(-1/2 - i eps) (1 + x)^(-1/2 + i eps), eps = atanh(gamma)/pi
  = log(3 - 4 nu)/(2 pi), checked by 30-digit quadrature of H w - i gamma w.
- "2D-exponents": the local exponents from the Mellin symbols of H on one-sided powers: at the stick-slip point
  cot(pi lam) = mu gamma (lam = 1/2 - alpha, and the generic mode -1/2 - alpha), at the edge cot(pi lam) = -mu gamma
  (lam = alpha - 1/2), tan(pi alpha) = mu gamma: the same alpha as [S75] (2.15).
- "2D-(2.28)": the first-order law mu/gamma = K(c)/K'(c), from the solvability of the stick-zone equation for q
  with weight (c^2 - x^2)^(-1/2) (Sadowsky's pressure); its inverse by Jacobi's nome.
- "2D-(2.29)": its limits c ~ 4 exp(-pi gamma/(2 mu)) (mu -> 0) and 1 - c ~ 8 exp(-pi mu/gamma) (mu -> inf).
- "2D-(3.13)": the cylinder: Hertz's p = (2/pi) sqrt(1 - x^2) from Sadowsky's by (3.13), the load factor
  K0 = 2/pi, and P = pi a^2 E*/(4 R).

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from functools import cache

import mpmath
import sympy as sp

from ..derivation import Comparison, Derivation, Identity, Step
from ..plane import (mu_over_gamma_plane, mu_over_gamma_plane_mp, stick_width_first_order,
                     stick_width_first_order_mp)
from .precision import exact

__all__ = ["derivations"]

PART = "P"



def _abramov_identity() -> Identity:
    def residual(gamma_, x):
        eps = mpmath.atanh(gamma_) / mpmath.pi
        w = lambda t: mpmath.cosh(mpmath.pi * eps) / mpmath.pi * (1 - t) ** (-0.5 - 1j * eps) * (1 + t) ** (-0.5 + 1j * eps)  # noqa: E731
        pv = mpmath.quad(lambda t: (w(t) - w(x)) / (t - x), [-1, x, 1]) + w(x) * mpmath.log((1 - x) / (1 + x))
        return abs(pv / mpmath.pi - 1j * gamma_ * w(x))

    return Identity(
        name="Abramov's w solves H w = i gamma w on (-1, 1)",
        statement=r"\frac{1}{\pi}\,\mathrm{PV}\!\int_{-1}^{1}\frac{w(t)\,dt}{t-x} = i\gamma\,w(x)",
        residual=exact(residual), points=((0.5, 0.3), (0.2, -0.7), (0.7, 0.9)), dps=30,
        tol=1e-16)  # tanh-sinh of the singularity-subtracted PV at 30 digits: measured 4e-18


def _d_formulation() -> Derivation:
    nu, g, eps = sp.symbols("nu gamma epsilon", real=True)
    gamma_nu = (1 - 2 * nu) / (2 - 2 * nu)
    ratio = sp.simplify((1 + gamma_nu) / (1 - gamma_nu))
    p, q, Hp, Hq = sp.symbols("p q Hp Hq")
    stick = sp.Eq(sp.Symbol("Hw"), sp.expand(Hp + sp.I * Hq).subs({Hp: -g * q, Hq: g * p}))
    steps = (
        Step("surface relations of plane strain, x over the half-width, p, q over P/a (int p = 1): du_z/dx and du_x/dx "
             "over (1 - nu) P/(G a)", sp.Eq(sp.Symbol("u_z'"), Hp + g * q)),
        Step("tangential: stick zone du_x/dx = 0", sp.Eq(sp.Symbol("u_x'"), Hq - g * p)),
        Step("on the stick zone both vanish: with w = p + i q, H w = i gamma w", stick),
        Step("the bonded index: (1 + gamma)/(1 - gamma) = 3 - 4 nu", sp.Eq(sp.Symbol("(1+gamma)/(1-gamma)"), ratio)),
        Step("eps = atanh(gamma)/pi = log(3 - 4 nu)/(2 pi)", sp.Eq(eps, sp.log(ratio) / (2 * sp.pi))),
    )
    derived = sp.Eq(sp.Symbol("w"), sp.cosh(sp.pi * eps) / sp.pi * (1 - sp.Symbol("x")) ** (-sp.Rational(1, 2) - sp.I * eps)
                    * (1 + sp.Symbol("x")) ** (-sp.Rational(1, 2) + sp.I * eps))
    return Derivation(
        label="2D-formulation", part=PART,
        title="half-plane relations with friction; full stick: Abramov's w, eps = log(3 - 4 nu)/(2 pi)",
        derived=derived, printed=None, agrees=bool(sp.simplify(ratio - (3 - 4 * nu)) == 0),
        steps=steps, identities=(_abramov_identity(),),
        note="p is the pressure, q the shear traction on the half-plane in +x (outward for x > 0); the slip zones "
             "slip inward, so friction on the half-plane acts outward: q = mu sgn(x) p there. Plane stress: nu -> "
             "nu/(1 + nu), gamma = (1 - nu)/2 (asymptotics.plane.gamma_plane_stress). Dissimilar bodies: gamma of "
             "[S75]'s footnote (asymptotics.materials.gamma_dissimilar).")


def _d_exponents() -> Derivation:
    g, m, C, S, a = sp.symbols("gamma mu C S a")
    # amplitudes: a (q, stick side x < 0), b (p, stick side), d (p, slip side, q = mu p); rows (N) x > 0, (N) x < 0,
    # (T) x < 0, with H[x_+^l] = -C x_+^l - S x_-^l, H[x_-^l] = S x_+^l + C x_-^l (C = cot(pi l), S = 1/sin(pi l))
    M = sp.Matrix([[0, S, g * m - C], [g, C, -S], [C, -g, -m * S]])
    det = sp.factor(sp.expand(M.det()).subs(S**2, 1 + C**2))
    mode = sp.simplify((M.subs(C, g * m) * sp.Matrix([a, 0, g * a / S])).subs(S**2, 1 + g**2 * m**2))
    edge = sp.solve(sp.Eq(C + g * m, 0), C)[0]
    steps = (
        Step("Mellin symbols of H on one-sided powers |x|^lam near the stick-slip point; the amplitudes (a, b, d) of "
             "q (stick), p (stick), p (slip) solve M (a, b, d) = 0", sp.Eq(sp.Symbol("M"), M)),
        Step("det M (S^2 = 1 + C^2): nonzero roots only where cot(pi lam) = mu gamma", sp.Eq(sp.Symbol("det"), det)),
        Step("the generic mode lam = -1/2 - alpha: no p on the stick side, d = gamma a sin(pi lam); M depends on lam "
             "through C and S only and v solves it for every S, so the admissible lam = 1/2 - alpha (and every lam with "
             "cot(pi lam) = mu gamma) has no p on the stick side either (the solvers pin that family to 0)",
             sp.Eq(sp.Symbol("M v"), mode)),
        Step("at the edge (p on x < 1 only, q = mu p): H p + gamma mu p = 0 gives C + mu gamma = 0",
             sp.Eq(C, edge)),
    )
    return Derivation(
        label="2D-exponents", part=PART,
        title="local exponents: (x - c)^(1/2 - alpha) on either side of the stick-slip point, (1 - x)^(alpha - 1/2) at the edge",
        derived=sp.Eq(sp.cot(sp.pi * sp.Symbol("lambda")), g * m), printed=None,
        agrees=bool(sp.simplify(det - (g * m - C) * (1 - g**2)) == 0 and mode == sp.zeros(3, 1)),
        steps=steps,
        note="tan(pi alpha) = mu gamma as in [S75] (2.15). The regular solutions (integer exponents) are analytic "
             "across c with q = mu p, so the fields are A(x) + |x - c|^(1/2 - alpha) B(x) on both sides, A, B analytic "
             "(the 2 x 2 Riemann-Hilbert problem's exponents 0 and 1/2 - alpha differ by a non-integer: no logarithms); "
             "the solver's basis carries exactly these (numeric.core.plane_charts).")


def _kk_identities() -> tuple[Identity, Identity]:
    def stick(c):
        return 2 * mpmath.quad(lambda t: 1 / (mpmath.pi * mpmath.sqrt((1 - t * t) * (c * c - t * t))), [0, c]) \
            - 2 / mpmath.pi * mpmath.ellipk(c * c)

    def slip(c):
        return 2 * mpmath.quad(lambda s: 1 / (mpmath.pi * mpmath.sqrt((1 - s * s) * (s * s - c * c))), [c, 1]) \
            - 2 / mpmath.pi * mpmath.ellipk(1 - c * c)

    points = ((0.1,), (0.6,), (0.95,))
    return (Identity("int_{-c}^{c} p0 (c^2 - t^2)^(-1/2) = (2/pi) K(c)",
                     r"\int_{-c}^{c}\frac{dt}{\pi\sqrt{(1-t^2)(c^2-t^2)}} = \frac{2}{\pi}K(c)", exact(stick), points,
                     dps=30, tol=1e-15),  # tanh-sinh with square-root singularities at both ends: measured 2e-17
            Identity("int_{c<|s|<1} p0 (s^2 - c^2)^(-1/2) = (2/pi) K'(c)",
                     r"\int_{c<|s|<1}\frac{ds}{\pi\sqrt{(1-s^2)(s^2-c^2)}} = \frac{2}{\pi}K'(c)", exact(slip), points,
                     dps=30, tol=1e-15))  # as above: measured 3e-17


def _d228() -> Derivation:
    c, mu, g = sp.symbols("c mu gamma", positive=True)
    K, Kp = sp.Function("K")(c), sp.Function("K'")(c)
    steps = (
        Step("gamma = 0: Sadowsky's p0 = 1/(pi sqrt(1 - x^2)); first order: H q = gamma p0 on (-c, c), q = mu sgn(x) p0 "
             "outside", sp.Eq(sp.Symbol("Hq"), g / (sp.pi * sp.sqrt(1 - sp.Symbol("x") ** 2)))),
        Step("q bounded at +-c (the eigenvalue condition) requires int_{-c}^{c} (gamma p0 - H q_slip) (c^2 - x^2)^(-1/2) dx "
             "= 0, and int_{-c}^{c} dx/((t - x) sqrt(c^2 - x^2)) = pi sgn(t)/sqrt(t^2 - c^2) for |t| > c",
             sp.Eq(g * sp.Symbol("I_stick"), mu * sp.Symbol("I_slip"))),
        Step("the two integrals are (2/pi) K(c) and (2/pi) K'(c) (checked below)", sp.Eq(g * K, mu * Kp)),
    )
    return Derivation(
        label="2D-(2.28)", part=PART, title="first-order law of the strip punch: mu/gamma = K(c)/K'(c)",
        derived=sp.Eq(mu / g, K / Kp), printed=None, agrees=True, steps=steps, identities=_kk_identities(),
        fast=mu_over_gamma_plane, precise=mu_over_gamma_plane_mp, arguments=("c",),
        comparison=Comparison(points=((1e-9,), (1e-3,), (0.3,), (0.5,), (0.9,), (1 - 1e-9,)), rtol=4e-15),
        note="The 2-D counterpart of [S75] (2.28), where log((1+c)/(1-c))/(2c) stands for K(c): in the plane the "
             "Abel kernels become Cauchy kernels and both weighted integrals are complete elliptic integrals. The full "
             "solution differs by O(gamma^2) (measured below and in tests/test_plane.py).")


def _nome_identity() -> Identity:
    def residual(ratio):
        q = mpmath.exp(-mpmath.pi * ratio)
        k = mpmath.jtheta(2, 0, q) ** 2 / mpmath.jtheta(3, 0, q) ** 2
        return mpmath.ellipk(1 - k * k) / mpmath.ellipk(k * k) - ratio

    return Identity("Jacobi: k = theta_2^2/theta_3^2 at q = exp(-pi r) has K'(k)/K(k) = r",
                    r"k = \frac{\vartheta_2(q)^2}{\vartheta_3(q)^2},\ q = e^{-\pi r} \Rightarrow \frac{K'(k)}{K(k)} = r",
                    exact(residual), ((0.3,), (1.0,), (2.5,)), dps=40, tol=1e-30)


def _d229() -> Derivation:
    q, qp = sp.symbols("q q'", positive=True)
    n = range(1, 8)
    theta2 = 2 * q ** sp.Rational(1, 4) * sum(q ** (j * (j + 1)) for j in range(0, 7))
    theta3 = 1 + 2 * sum(q ** (j * j) for j in n)
    theta3p = 1 + 2 * sum(qp ** (j * j) for j in n)
    theta4p = 1 + 2 * sum((-1) ** j * qp ** (j * j) for j in n)
    small = sp.series(theta2**2 / theta3**2, q, 0, 2)
    large = sp.series(1 - theta4p**2 / theta3p**2, qp, 0, 3)
    steps = (
        Step("K'(c)/K(c) = gamma/mu: the nome q = exp(-pi gamma/mu) gives c = theta_2(q)^2/theta_3(q)^2",
             sp.Eq(sp.Symbol("c"), small)),
        Step("mu -> inf: the complementary nome q' = exp(-pi mu/gamma), c = theta_4(q')^2/theta_3(q')^2",
             sp.Eq(1 - sp.Symbol("c"), large)),
    )
    derived = sp.Eq(sp.Symbol("c"), 4 * sp.exp(-sp.pi * sp.Symbol("gamma") / (2 * sp.Symbol("mu"))))
    return Derivation(
        label="2D-(2.29)", part=PART,
        title="limits of the first-order law: c ~ 4 exp(-pi gamma/(2 mu)), 1 - c ~ 8 exp(-pi mu/gamma)",
        derived=derived, printed=None,
        agrees=bool(sp.limit(small.removeO() / sp.sqrt(q), q, 0) == 4 and large.removeO().coeff(qp, 1) == 8),
        steps=steps, identities=(_nome_identity(),),
        fast=stick_width_first_order, precise=stick_width_first_order_mp, arguments=("mu", "gamma"),
        comparison=Comparison(points=((0.05, 0.5), (0.3, 0.5), (1.0, 0.4), (3.0, 0.2)), rtol=1e-13),
        note="As [S75] (2.29) for the axisymmetric law, c -> 1 as mu -> inf is a property of the first-order law only: "
             "the full solution saturates at c_max < 1 (measured below; no closed form found).")


def _d313() -> Derivation:
    x, t, v = sp.symbols("x t v", positive=True)
    p0 = 1 / (sp.pi * sp.sqrt(1 - t**2))
    # antiderivatives (SymPy's definite integrals return Piecewise branches here): checked by differentiation
    F = -sp.sqrt(1 - t**2) / (sp.pi * t)
    assert sp.simplify(sp.diff(F, t) - p0 / t**2) == 0
    hertz = sp.simplify(2 * x * (F.subs(t, 1) - F.subs(t, x)))
    Fw = -sp.log(1 - t**2 * v**2) / t**2
    assert sp.simplify(sp.diff(Fw, v) - 2 * v / (1 - t**2 * v**2)) == 0
    w2 = Fw.subs(v, 1) - Fw.subs(v, 0)
    E, a, R, G, nu = sp.symbols("E^* a R G nu", positive=True)
    K0 = 2 / sp.pi
    load = sp.simplify((G * a**2 / ((1 - nu) * K0 * R)).subs(G, E * (1 - nu) / 2))
    steps = (
        Step("(3.13) with n = 2 on Sadowsky's pressure: d/dt(-sqrt(1 - t^2)/(pi t)) = p0/t^2", sp.Eq(sp.Symbol("p"), hertz)),
        Step("outside slope of unit strip punches of half-width b: W_2(t) = int_0^1 2 v dv/(1 - t^2 v^2) "
             "= [-log(1 - t^2 v^2)/t^2]_0^1",
             sp.Eq(sp.Symbol("W_2"), w2)),
        Step("K = (2/pi) int_0^1 p0 W_2 dt = 2/pi frictionless (checked below); P = G a^2/((1 - nu) K R), E* = 2 G/(1 - nu)",
             sp.Eq(sp.Symbol("P"), load)),
    )

    def k0(_):
        return (2 / mpmath.pi) * mpmath.quad(lambda s: -mpmath.log(1 - s * s) / (s * s * mpmath.pi * mpmath.sqrt(1 - s * s)),
                                             [0, 1]) - 2 / mpmath.pi

    return Derivation(
        label="2D-(3.13)", part=PART, title="the cylinder: Hertz's pressure (2/pi) sqrt(1 - x^2) and P = pi a^2 E*/(4 R)",
        derived=sp.Eq(sp.Symbol("p"), hertz), printed=None,
        agrees=bool(sp.simplify(hertz - 2 / sp.pi * sp.sqrt(1 - x**2)) == 0 and sp.simplify(load - sp.pi * a**2 * E / (4 * R)) == 0),
        steps=steps,
        identities=(Identity("K0 = (2/pi) int_0^1 p0 W_2 = 2/pi", r"\frac{2}{\pi}\int_0^1\frac{-\log(1-t^2)}{\pi t^2\sqrt{1-t^2}}dt = \frac{2}{\pi}",
                             exact(k0), ((0,),), dps=30, tol=1e-14),),  # log and square root at t = 1: measured 2e-16
        note="The indentation depth of a half-plane is not defined (the displacement grows like the logarithm of the "
             "distance), so the load-width relation P(a) replaces the compliance: with friction, P = G a^2/((1 - nu) K R) "
             "with K from the strip punch (numeric.solutions.plane_power_law); every load increment is a strip punch "
             "of the current width, so c is that of the strip punch for every n, as in [S75] §3.")


@cache
def derivations() -> tuple[Derivation, ...]:
    """The plane-strain results, derived (runs once; a few seconds)."""
    return (_d_formulation(), _d_exponents(), _d228(), _d229(), _d313())
