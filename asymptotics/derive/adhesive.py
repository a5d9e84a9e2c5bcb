"""SymPy derivations of [S75] Appendix B with (4.10) and (4.18): the fully adhesive punch.

Entries (labels): "(4.10)" kappa, p0(0), q0'(0) and the gamma-series of P0*; "(B3)" the
stresses from (B2) by differentiation and integration by parts; "(B4)" P0* = atanh(gamma)/gamma;
"(B4)-series" its gamma-series and the numbers quoted after (2.36); "(B6)" the centre of the
adhesive sphere's pressure; "(4.18)" A, C and Psi1.

Notation: C_h = cosh(pi kappa/2), theta(w) = atanh(w) = (1/2) log((1+w)/(1-w)),
kappa = (2/pi) atanh(gamma). Abel integrals int_0^x f(w) dw / sqrt(x^2 - w^2) are written as
int_0^(pi/2) f(x sin phi) dphi, which SymPy differentiates under the integral sign and
expands in x. Unknown shapes are SymPy undefined functions where the argument holds for
any function. Where SymPy cannot evaluate an integral or a series (int_0^oo sin(kappa t)/sinh t dt,
the digamma sum of Psi1, the stresses of (B1), A of (4.18)) the step is an :class:`Identity`
checked in mpmath at 30-40 digits.

The numeric functions are those of ``asymptotics.adhesive``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from functools import cache

import mpmath
import numpy as np
import sympy as sp
from sympy import (Eq, Function, I, Integral, O, Rational, S, Symbol, Tuple, atanh, beta, cos, cosh,
                   coth, diff, digamma, expand_func, gamma, gammasimp, integrate, limit, log, oo,
                   pi, simplify, sin, sinh, sqrt, symbols, tanh)

from ..adhesive import (central_pressure_adhesive, compliance_adhesive, pressure_adhesive,
                        pressure_adhesive_mp, psi1, psi1_mp, shear_adhesive, shear_adhesive_mp,
                        shear_slope_adhesive, sphere_A_adhesive, sphere_C_adhesive,
                        sphere_central_pressure_adhesive, sphere_pressure_slope_adhesive)
from ..derivation import Comparison, Derivation, Identity, Step, rounding_bound
from .precision import at_precision, exact

__all__ = ["derivations"]

PART = "B"

x, w, y, phi, th, v = symbols("x w y phi theta v", positive=True)
g, k, nu_ = symbols("gamma kappa nu", positive=True)
m_ = Symbol("m", positive=True)  # gamma = 1/(1 + m) keeps 0 < gamma < 1 for SymPy
Ch = cosh(pi * k / 2)
KAPPA = 2 * atanh(g) / pi  # (4.10)
P00 = Symbol("p_0(0)", positive=True)
Sf, Cf, F = Function("S"), Function("C"), Function("F")

_ORDER = 6  # series orders in x and gamma


def _mp_kappa(gamma_):
    return 2 * mpmath.atanh(gamma_) / mpmath.pi


def _mp_centre(gamma_):
    """p0(0) = (kappa/gamma) cosh(pi kappa/2) (4.10) in mpmath."""
    kappa = _mp_kappa(gamma_)
    return (kappa / gamma_ if gamma_ else 2 / mpmath.pi) * mpmath.cosh(mpmath.pi * kappa / 2)




_Z, _U = Symbol("z"), Symbol("u")


def _taylor(expr, order: int):
    """Taylor polynomial in z of ``expr`` up to z^(order-1).

    atanh(z) is replaced by its Taylor polynomial u(z), each sin or cos of kappa u expanded in u
    first and 1/(1 - z^2) by its geometric series (SymPy's ``series`` of the composite is
    several times slower); anything else is left to ``series``.
    """
    u_poly = sp.series(atanh(_Z), _Z, 0, order).removeO()
    replaced = expr.replace(lambda e: isinstance(e, (sin, cos)) and e.has(atanh(_Z)),
                            lambda e: sp.series(e.func(e.args[0].subs(atanh(_Z), _U)), _U, 0, order).removeO())
    geometric = sum(_Z ** (2 * j) for j in range(order))  # 1/(1 - z^2)
    rest = sp.expand(replaced.subs(_U, u_poly).subs(1 / (1 - _Z**2), geometric))
    if not rest.is_polynomial(_Z):
        rest = sp.series(rest, _Z, 0, order).removeO()
    poly = sp.Poly(sp.expand(rest), _Z)
    return sum(c * _Z**j for (j,), c in poly.terms() if j < order)


def _abel_phi(shape, order: int):
    """(2/pi) int_0^(pi/2) shape(x sin phi) dphi expanded in x to ``order``.

    shape(z) is expanded in z and each z^j integrated with Wallis' integral
    int_0^(pi/2) sin^j phi dphi = sqrt(pi) Gamma((j+1)/2) / (2 Gamma(j/2 + 1)).
    """
    expansion = sp.Poly(_taylor(shape(_Z), order), _Z)
    total = sum(c * x**j * sqrt(pi) * gamma(Rational(j + 1, 2)) / (2 * gamma(Rational(j, 2) + 1))
                for (j,), c in expansion.terms())
    return sp.expand(2 / pi * total)


# ----------------------------------------------------------------------------- (4.10)
def _centre_identity(c2) -> Identity:
    """(B3) by quadrature at tiny x against p0(0)(1 + c2 x^2) and (kappa/2) p0(0) x (c2 from the series)."""
    c2_mp = sp.lambdify(k, c2, "mpmath")

    def residual(x_, gamma_):
        kappa = _mp_kappa(gamma_)
        centre = _mp_centre(gamma_)
        c2_value = c2_mp(kappa)
        p_err = pressure_adhesive_mp(x_, gamma_, dps=40) - centre * (1 + c2_value * x_**2)
        q_err = shear_adhesive_mp(x_, gamma_, dps=40) - kappa * centre / 2 * x_
        return max(abs(p_err), abs(q_err)) / centre

    return Identity(
        name="(B3) quadrature near x = 0",
        statement=r"p_0(x) = p_0(0)(1 + c_2x^2) + O(x^4),\ q_0(x) = \tfrac12\kappa p_0(0)x + O(x^3)",
        residual=exact(residual),
        points=((1e-9, 0.5), (1e-9, 0.2), (1e-9, 1 / 3)),
        tol=1e-26,  # O(x^3) = 1e-27 remainder of q0
    )


def _d410() -> Derivation:
    steps = []
    kappa_ok = simplify(sp.expand_log((KAPPA - log((1 + g) / (1 - g)) / pi).rewrite(log), force=True)) == 0
    steps.append(Step("kappa = (1/pi) log((1+gamma)/(1-gamma)) = (2/pi) atanh(gamma)", Eq(k, KAPPA)))
    # p0(0) from (B2), p-row: x p0 = (2/(pi gamma)) C_h d/dx int_0^x w sin(kappa theta) dw / sqrt(x^2 - w^2).
    inner = _abel_phi(lambda z: z * sin(k * atanh(z)), _ORDER) * pi / 2
    x_p0 = 2 / (pi * g) * Ch * diff(inner, x)
    centre = sp.simplify(limit(x_p0 / x, x, 0))
    steps.append(Step("(B2), p-row, w = x sin(phi), expanded in x: x p0(x) =", Eq(x * Symbol("p_0(x)"), sp.expand(x_p0))))
    steps.append(Step("p0(0)", Eq(P00, centre)))
    # p0(x)/p0(0) and q0(x) from (B3) (its derivation is entry (B3)).
    p_ratio = _abel_phi(lambda z: cos(k * atanh(z)) / (1 - z**2), _ORDER)
    q_ratio = _abel_phi(lambda z: z * sin(k * atanh(z)) / (1 - z**2), _ORDER + 1) / x
    steps.append(Step("(B3), p-row, w = x sin(phi): p0(x)/p0(0) =", p_ratio + O(x**_ORDER)))
    steps.append(Step("(B3), q-row: q0(x)/p0(0) =", sp.expand(q_ratio) + O(x**_ORDER)))
    slope = sp.expand(q_ratio).coeff(x, 1)
    c2 = p_ratio.coeff(x, 2)
    compliance = sp.series(atanh(g) / g, g, 0, _ORDER)
    steps.append(Step("P0* = pi kappa/(2 gamma) = atanh(gamma)/gamma (B4), expanded", compliance))
    derived = Tuple(Eq(k, KAPPA), Eq(P00, centre), Eq(Symbol("q_0'(0)"), slope * P00),
                    Eq(Symbol("P_0^*"), compliance))
    printed = Tuple(Eq(k, log((1 + g) / (1 - g)) / pi), Eq(P00, k / g * Ch), Eq(Symbol("q_0'(0)"), k * P00 / 2),
                    Eq(Symbol("P_0^*"), 1 + nu_**2 / 3 + O(nu_**4)))
    parts_ok = kappa_ok and simplify(centre - k / g * Ch) == 0 and simplify(slope - k / 2) == 0
    series_as_printed = sp.expand(compliance.removeO()).coeff(g, 2) == Rational(1, 3)
    return Derivation(
        label="(4.10)",
        part=PART,
        title="Adhesive flat punch at the centre: kappa, p0(0) = (kappa/gamma) cosh(pi kappa/2), q0/x -> kappa p0(0)/2, P0* series",
        derived=derived,
        printed=printed,
        agrees=False,
        steps=tuple(steps),
        identities=(_centre_identity(c2),),
        fast=lambda gamma_: np.array([central_pressure_adhesive(gamma_), shear_slope_adhesive(gamma_)]),
        precise=at_precision(lambda gamma_: [_mp_centre(gamma_), _mp_kappa(gamma_) * _mp_centre(gamma_) / 2]),
        arguments=("gamma",),
        comparison=Comparison(points=((1e-6,), (0.2,), (1 / 3,), (3 / 7,), (0.5,), (0.7,)), rtol=4e-15),
        note=(f"Slip: the paper prints P* = pi kappa/(2 gamma) = 1 + nu^2/3 + ...; the derivation gives "
              f"1 + gamma^2/3 + gamma^4/5 + ... (errata 1; cf. (2.36)). Everything else agrees "
              f"(kappa, p0(0), q0'(0): {parts_ok}; gamma^2 coefficient 1/3: {series_as_printed}). "
              "p0(0) is derived from (B2); the paper says the limits follow from '(A3)' = (B3) and calls "
              "them '(2.10)' = (4.10). fast/precise give (p0(0), lim q0/x)."),
        extra={"parts_agree": bool(parts_ok and series_as_printed), "c2": c2},
    )


# ----------------------------------------------------------------------------- (B3)
def _b1_abel(x_, gamma_, component: int):
    """int_x^1 (w cos(kappa theta), sin(kappa theta)) dw / sqrt(w^2 - x^2), with w = tanh(tau0 + u^2)."""
    kappa = _mp_kappa(gamma_)
    tau0 = mpmath.atanh(x_)

    def integrand(u):
        if u == 0:
            ratio = 1
        else:
            ratio = mpmath.sqrt(u * u / mpmath.sinh(u * u))
        tau = tau0 + u * u
        root = mpmath.sqrt((mpmath.tanh(tau) + x_) / (mpmath.cosh(tau) * mpmath.cosh(tau0)))
        shape = mpmath.tanh(tau) * mpmath.cos(kappa * tau) if component == 0 else mpmath.sin(kappa * tau)
        return 2 * ratio * shape / (mpmath.cosh(tau) ** 2 * root)

    return mpmath.quad(integrand, [0, 1, 3, mpmath.inf])


def _b1_identity() -> Identity:
    """(B1) by numerical x-derivative of its Abel integrals, against (B3) by quadrature."""

    def residual(x_, gamma_):
        scale = -2 / mpmath.pi * mpmath.cosh(mpmath.pi * _mp_kappa(gamma_) / 2)
        p_b1 = scale * mpmath.diff(lambda z: _b1_abel(z, gamma_, 0), x_) / x_
        q_b1 = scale * mpmath.diff(lambda z: _b1_abel(z, gamma_, 1), x_)
        return max(abs(p_b1 - pressure_adhesive_mp(x_, gamma_, dps=mpmath.mp.dps)),
                   abs(q_b1 - shear_adhesive_mp(x_, gamma_, dps=mpmath.mp.dps)))

    return Identity(
        name="(B1) = (B3)",
        statement=(r"-\tfrac{2}{\pi}C_h\tfrac{d}{dx}\int_x^1\binom{w\cos\kappa\theta}{\sin\kappa\theta}\tfrac{dw}{\sqrt{w^2-x^2}}"
                   r" = \binom{x p_0}{q_0}\ \text{of (B3)}"),
        residual=exact(residual),
        points=((0.3, 0.5), (0.8, 0.5), (0.5, 0.2)),
        dps=30,
        tol=1e-20,  # numerical differentiation of a quadrature
    )


def _db3() -> Derivation:
    steps = []
    # p-row of (B2) with S(w) = sin(kappa theta), S(0) = 0.
    inner = Integral(x * sin(phi) * Sf(x * sin(phi)), (phi, 0, pi / 2))
    differentiated = diff(inner, x)
    target = Integral(x * diff(Sf(x * sin(phi)), x) / sin(phi), (phi, 0, pi / 2))  # x S'(x sin phi)
    gap = simplify(differentiated.function - target.function + diff(cos(phi) * Sf(x * sin(phi)), phi))
    boundary = (cos(phi) * Sf(x * sin(phi))).subs(phi, pi / 2) - (cos(phi) * Sf(x * sin(phi))).subs(phi, 0)
    p_ok = gap == 0 and boundary.subs(Sf(0), 0) == 0
    steps.append(Step("(B2), p-row: x p0 = (2/(pi gamma)) C_h d/dx int_0^(pi/2) x sin(phi) S(x sin phi) dphi, "
                      "S = sin(kappa theta); differentiated under the integral", differentiated))
    steps.append(Step("integrand minus x S'(x sin phi) is -d/dphi[cos(phi) S(x sin phi)] (difference simplifies to 0); "
                      "integrated: [cos(phi) S(x sin phi)] from 0 to pi/2 = -S(0) = 0", gap))
    s_prime = simplify(diff(sin(k * atanh(w)), w))
    steps.append(Step("so p0 = (2/(pi gamma)) C_h int_0^x S'(w) dw/sqrt(x^2-w^2), with S'(w)", Eq(Symbol("S'(w)"), s_prime)))
    p_form = P00 * 2 / pi * Integral(cos(k * atanh(w)) / ((1 - w**2) * sqrt(x**2 - w**2)), (w, 0, x))
    p_ok = p_ok and simplify(s_prime - k * cos(k * atanh(w)) / (1 - w**2)) == 0
    steps.append(Step("with p0(0) = (kappa/gamma) C_h (4.10): (B3), p-row", Eq(Symbol("p_0(x)"), p_form)))
    # q-row of (B2) (lost in the transcript): q0 = -(2/(pi gamma)) C_h d/dx int_0^x cos(kappa theta) dw / sqrt(x^2-w^2).
    q_inner = Integral(Cf(x * sin(phi)), (phi, 0, pi / 2))
    q_diff = diff(q_inner, x)
    c_prime = simplify(diff(cos(k * atanh(w)), w))
    q_ok = simplify(c_prime + k * sin(k * atanh(w)) / (1 - w**2)) == 0
    steps.append(Step("(B2), q-row (reconstructed): q0 = -(2/(pi gamma)) C_h d/dx int_0^(pi/2) C(x sin phi) dphi, "
                      "C = cos(kappa theta); differentiated", q_diff))
    steps.append(Step("with C'(w); sin(phi) = w/x", Eq(Symbol("C'(w)"), c_prime)))
    q_form = P00 * 2 / pi * Integral(w / x * sin(k * atanh(w)) / ((1 - w**2) * sqrt(x**2 - w**2)), (w, 0, x))
    steps.append(Step("(B3), q-row", Eq(Symbol("q_0(x)"), q_form)))
    derived = Tuple(Eq(Symbol("p_0(x)"), p_form), Eq(Symbol("q_0(x)"), q_form))
    return Derivation(
        label="(B3)",
        part=PART,
        title="Adhesive flat punch stresses as Abel integrals over (0, x), from (B2)",
        derived=derived,
        printed=derived,
        agrees=bool(p_ok and q_ok),
        steps=tuple(steps),
        identities=(_b1_identity(),),
        fast=lambda x_, gamma_: np.array([pressure_adhesive(x_, gamma_), shear_adhesive(x_, gamma_)]),
        precise=lambda x_, gamma_: [pressure_adhesive_mp(x_, gamma_, dps=40), shear_adhesive_mp(x_, gamma_, dps=40)],
        arguments=("x", "gamma"),
        comparison=Comparison(points=((0.0, 0.5), (0.3, 0.5), (0.9, 0.5), (0.999, 0.5), (0.5, 0.2), (0.99, 1 / 3)),
                              rtol=1e-13),
        note=("The transcript keeps only the p-entry (-w sin kappa theta) of the vector in (B2); the q-entry must be "
              "cos(kappa theta) for (B3) to follow (it needs differentiation only, the p-row also an integration by "
              "parts, using sin(kappa theta(0)) = 0). (B1) reads (w cos kappa theta, sin kappa theta) (errata 7); "
              "its agreement with (B3) is checked numerically (Identity). App. B's '(A1)', '(A3)' mean (B1), (B3)."),
    )


# ----------------------------------------------------------------------------- (B4)
def _cos_integral_identity() -> Identity:
    def residual(kappa):
        value = mpmath.quad(lambda t_: mpmath.cos(kappa * t_) / mpmath.cosh(t_) ** 2, [0, mpmath.inf])
        a = mpmath.pi * kappa / 2
        return value - a / mpmath.sinh(a)

    return Identity(
        name="int_0^1 cos(kappa theta) dw",
        statement=r"\int_0^1\cos\kappa\theta\,dw = \int_0^\infty\frac{\cos\kappa\tau}{\cosh^2\tau}d\tau = \frac{\pi\kappa/2}{\sinh(\pi\kappa/2)}",
        residual=exact(residual),
        points=((0.1,), (0.35,), (1,), (3,)),
        tol=1e-30,
    )


def _db4() -> Derivation:
    steps = []
    by_abel = integrate(diff(F(x), x), (x, 0, 1))
    steps.append(Step("(2.4) with (B1): (pi/2) int_0^1 x p0 dx = -C_h int_0^1 F'(x) dx, F(x) = int_x^1 w cos(kappa theta) dw/sqrt(w^2-x^2)",
                      -Ch * by_abel))
    steps.append(Step("F(1) = 0 and F(0) = int_0^1 cos(kappa theta) dw", Eq(Symbol("P_0^*"), Ch * Integral(cos(k * atanh(w)), (w, 0, 1)))))
    a = Symbol("a", positive=True)
    # cos(kappa theta) = Re ((1+w)/(1-w))^(i kappa/2), even in w; w = 2v - 1 gives a Beta integral.
    body = ((1 + w) / (1 - w)) ** (I * a)
    in_v = sp.powsimp(sp.expand_power_base(body.subs(w, 2 * v - 1) * 2, force=True), force=True)
    beta_form = Integral(v ** (I * a) * (1 - v) ** (-I * a), (v, 0, 1))
    value = simplify(gammasimp(beta(1 + I * a, 1 - I * a).rewrite(gamma)))
    steps.append(Step("int_0^1 cos(kappa theta) dw = (1/2) Re int_(-1)^1 ((1+w)/(1-w))^(i a) dw, a = kappa/2; w = 2v - 1",
                      Eq(Symbol("integrand"), in_v)))
    steps.append(Step("Euler's Beta integral B(1 + i a, 1 - i a) = Gamma(1 + ia) Gamma(1 - ia)", Eq(beta_form, value)))
    compliance = simplify((Ch * value.subs(a, k / 2)))
    steps.append(Step("P0* = C_h (pi kappa/2)/sinh(pi kappa/2)", Eq(Symbol("P_0^*"), compliance)))
    closed = simplify(compliance.subs(k, KAPPA).rewrite(tanh))
    coth_ok = simplify(coth(atanh(g)) - 1 / g) == 0
    closed = simplify(sp.expand_trig(closed))
    steps.append(Step("kappa = (2/pi) atanh(gamma), coth(atanh gamma) = 1/gamma", Eq(Symbol("P_0^*"), closed)))
    agrees = coth_ok and simplify(compliance - pi * k / 2 * coth(pi * k / 2)) == 0 and simplify(
        (pi * k / 2 * coth(pi * k / 2)).subs(k, KAPPA) - atanh(g) / g) == 0
    return Derivation(
        label="(B4)",
        part=PART,
        title="Adhesive compliance P0* = C_h int_0^1 cos(kappa theta) dw = pi kappa/(2 gamma) = atanh(gamma)/gamma",
        derived=Eq(Symbol("P_0^*"), atanh(g) / g),
        printed=Eq(Symbol("P_0^*"), pi * k / (2 * g)),
        agrees=bool(agrees and simplify(pi * KAPPA / (2 * g) - atanh(g) / g) == 0),
        steps=tuple(steps),
        identities=(_cos_integral_identity(),),
        fast=compliance_adhesive,
        precise=at_precision(lambda gamma_: mpmath.atanh(gamma_) / gamma_ if gamma_ else mpmath.mpf(1)),
        arguments=("gamma",),
        # atanh(gamma)/gamma: one call, one division
        comparison=Comparison(points=((1e-8,), (0.1,), (1 / 3,), (0.5,), (0.74,), (0.75,)), rtol=rounding_bound(1, 1)),
        note="Agrees. The upper bound of P* in §2.1 (Shield & Anderson). App. B's '(1.27)' means (2.4).",
    )


def _db4_series() -> Derivation:
    expansion = sp.series(atanh(g) / g, g, 0, 10)
    printed = 1 + g**2 / 3 + O(g**4)
    two_term = Rational(13, 12)
    exact = log(3)
    agrees = sp.expand(expansion.removeO() - (1 + g**2 / 3)).coeff(g, 2) == 0 and expansion.removeO().coeff(g, 0) == 1
    steps = (
        Step("atanh(gamma)/gamma expanded", expansion),
        Step("(2.36) keeps 1 + gamma^2/3; at gamma = 1/2", Eq(Symbol("P_2"), two_term)),
        Step("exact at gamma = 1/2: atanh(1/2)/(1/2) = log 3", Eq(Symbol("P_0^*"), exact)),
    )
    return Derivation(
        label="(B4)-series",
        part=PART,
        title="P0* = 1 + gamma^2/3 + gamma^4/5 + ...; (2.36) at gamma = 1/2: 1.0833 against log 3 = 1.098612",
        derived=expansion,
        printed=printed,
        agrees=bool(agrees),
        steps=steps,
        note=("The series is sum gamma^(2j)/(2j+1). (2.36) agrees to O(gamma^4). After (2.36) the paper quotes "
              "1.0833 (correct: 13/12 = 1.08333) 'compared with the exact value 1.0988'; the exact value is "
              "log 3 = 1.098612 (errata 8). (4.10) prints nu^2/3 for gamma^2/3 (errata 1)."),
        extra={"gamma": 0.5, "two_term": float(two_term), "exact": float(exact), "paper_exact": 1.0988,
               "paper_two_term": 1.0833},
    )


# ----------------------------------------------------------------------------- (B6)
def _sinh_identity() -> Identity:
    def residual(kappa):
        value = mpmath.quad(lambda t_: mpmath.sin(kappa * t_) / mpmath.sinh(t_) if t_ else kappa, [0, mpmath.inf])
        return value - mpmath.pi / 2 * mpmath.tanh(mpmath.pi * kappa / 2)

    return Identity(
        name="int_0^oo sin(kappa t)/sinh t dt",
        statement=r"\int_0^\infty\frac{\sin\kappa t}{\sinh t}dt = \frac{\pi}{2}\tanh\frac{\pi\kappa}{2}",
        residual=exact(residual),
        points=((0.1,), (0.35,), (1,), (2.5,)),
        tol=1e-30,
    )


def _db6() -> Derivation:
    steps = []
    steps.append(Step("(B5) = (3.13) with n = 2", Eq(Symbol("p(x)"), 2 * x * Integral(Function("p_0")(y) / y**2, (y, x, 1)))))
    # p0 even and smooth: p0(y) = p0(0) + y^2 h(y).
    constant_part = sp.simplify(2 * x * integrate(P00 / y**2, (y, x, 1)))
    steps.append(Step("p0 = p0(0) + y^2 h(y): the p0(0) part gives", constant_part))
    steps.append(Step("and 2x int_x^1 h dy = 2x int_0^1 h dy + O(x^2), so p'(0) = 2 FP with "
                      "FP = int_0^1 (p0(y) - p0(0))/y^2 dy - p0(0)", Eq(Symbol("p'(0)"), sp.diff(constant_part, x) + 2 * Symbol("H"))))
    # Swap with (B3): int_w^1 dy / (y^2 sqrt(y^2 - w^2)) = sqrt(1 - w^2)/w^2.
    anti = sqrt(y**2 - w**2) / (w**2 * y)
    anti_ok = simplify(diff(anti, y) - 1 / (y**2 * sqrt(y**2 - w**2))) == 0
    steps.append(Step("p0 - p0(0) = p0(0)(2/pi) int_0^y (cos(kappa theta)/(1-w^2) - 1) dw/sqrt(y^2-w^2) by (B3); "
                      "swap, inner antiderivative (checked by differentiation)", Eq(Symbol("F"), anti)))
    pieces = simplify((sqrt(1 - w**2) - 1 / sqrt(1 - w**2)) / w**2)
    minus_half_pi = integrate(pieces, (w, 0, 1))
    steps.append(Step("-p0(0) = p0(0)(2/pi) int_0^1 [sqrt(1-w^2) - 1/sqrt(1-w^2)]/w^2 dw, since the integral is",
                      minus_half_pi))
    fp_w = Integral((cos(k * atanh(w)) - 1) / (w**2 * sqrt(1 - w**2)), (w, 0, 1))
    steps.append(Step("FP = p0(0)(2/pi) times", fp_w))
    # theta = atanh(w) by definition; 1/(w^2 sqrt(1 - w^2)) dw/dtheta with w = tanh(theta), in exponentials.
    weight = (1 / (w**2 * sqrt(1 - w**2))).subs(w, tanh(th)) * diff(tanh(th), th)
    weight = sp.powsimp(sp.factor(weight.rewrite(sp.exp)), force=True)
    theta_ok = simplify(weight - (cosh(th) / sinh(th) ** 2).rewrite(sp.exp)) == 0
    theta_target = (cos(k * th) - 1) * cosh(th) / sinh(th) ** 2
    steps.append(Step("w = tanh(theta)", Eq(Symbol("integrand"), theta_target)))
    lower = limit((cos(k * th) - 1) / sinh(th), th, 0)
    upper = limit((cos(k * th) - 1) / sinh(th), th, oo)
    by_parts_ok = lower == 0 and upper == 0 and simplify(diff(-1 / sinh(th), th) - cosh(th) / sinh(th) ** 2) == 0
    steps.append(Step("by parts with d/dtheta(-1/sinh theta) = cosh/sinh^2; boundary terms (cos - 1)/sinh at 0 and oo",
                      Tuple(lower, upper)))
    steps.append(Step("so the integral is -kappa int_0^oo sin(kappa theta)/sinh(theta) dtheta = -kappa (pi/2) tanh(pi kappa/2) "
                      "(Identity)", -k * pi / 2 * tanh(pi * k / 2)))
    tanh_ok = simplify(tanh(pi * KAPPA / 2) - g) == 0
    slope = sp.simplify(2 * P00 * 2 / pi * (-k * pi / 2 * g))
    steps.append(Step("tanh(pi kappa/2) = gamma; p'(0) = 2 FP", Eq(Symbol("p'(0)"), slope)))
    derived = Eq(Symbol("p(x)"), 2 * P00 * (1 - k * g * x) + O(x**2))
    return Derivation(
        label="(B6)",
        part=PART,
        title="Adhesive sphere near the centre: p(x) = 2 p0(0)[1 - kappa gamma x + ...]",
        derived=derived,
        printed=derived,
        agrees=bool(anti_ok and theta_ok and by_parts_ok and tanh_ok and minus_half_pi == -pi / 2
                    and simplify(slope + 2 * P00 * k * g) == 0 and constant_part.subs(x, 0) == 2 * P00),
        steps=tuple(steps),
        identities=(_sinh_identity(),),
        fast=lambda gamma_: np.array([sphere_central_pressure_adhesive(gamma_), sphere_pressure_slope_adhesive(gamma_)]),
        precise=at_precision(lambda gamma_: [2 * _mp_centre(gamma_), -2 * _mp_centre(gamma_) * _mp_kappa(gamma_) * gamma_]),
        arguments=("gamma",),
        comparison=Comparison(points=((1e-6,), (0.2,), (1 / 3,), (0.5,), (0.7,)), rtol=4e-15),
        note=("Agrees. At nu = 0: p(0) = 1.615192, p'(0) = -0.282415 as quoted in §4.2. p'(0) is twice the "
              "Hadamard finite part of int_0^1 p0(y) y^-2 dy. fast/precise give (p(0), p'(0))."),
    )


# ----------------------------------------------------------------------------- (4.18)
def _m_kernel_mp(w_):
    """M(w) = int_0^w K'(s) ds / sqrt(w^2 - s^2), K(s) = (1 - r)/(1 + r), r = sqrt(1 - s^2), by quadrature."""
    def k_prime(s_):
        r = mpmath.sqrt((1 - s_) * (1 + s_))
        return 2 * s_ / (r * (1 + r) ** 2)

    return mpmath.quad(lambda p_: k_prime(w_ * mpmath.sin(p_)), [0, mpmath.pi / 2])


def _m_closed(w_):
    """-1/w - log(1 - w^2)/w^3 = sum_(j>=2) w^(2j-3)/j; the series below w = 1/2 (no cancellation)."""
    if w_ >= 0.5:
        return -1 / w_ - mpmath.log1p(-w_ * w_) / w_**3
    return mpmath.nsum(lambda j: w_ ** (2 * j - 3) / j, [2, mpmath.inf])


def _m_identity() -> Identity:
    return Identity(
        name="kernel M(w) in closed form",
        statement=r"\int_0^w\frac{K'(s)\,ds}{\sqrt{w^2-s^2}} = -\frac1w - \frac{\log(1-w^2)}{w^3},\ K = \frac{1-\sqrt{1-s^2}}{1+\sqrt{1-s^2}}",
        residual=exact(lambda w_: _m_kernel_mp(w_) - _m_closed(w_)),
        points=((0.05,), (0.3,), (0.7,), (0.95,)),
        tol=1e-30,
    )


def _a_identity() -> Identity:
    """1/A of (4.18) against the companion of (3.16): 1/A = 1 - gamma int_0^1 q0 K ds with q0 of (B1)."""

    def residual(gamma_):
        kappa = _mp_kappa(gamma_)
        scale = 2 / mpmath.pi * mpmath.cosh(mpmath.pi * kappa / 2)

        def integrand(tau):  # w = tanh(tau); log(1 - w^2) = -2 log cosh(tau) stays finite for large tau
            w_ = mpmath.tanh(tau)
            m_value = _m_closed(w_) if w_ < 0.5 else -1 / w_ + 2 * mpmath.log(mpmath.cosh(tau)) / w_**3
            return mpmath.sin(kappa * tau) * m_value / mpmath.cosh(tau) ** 2

        integral = mpmath.quad(integrand, [0, 1, 4, mpmath.inf])
        inverse_a = 1 - gamma_ * scale * integral
        return inverse_a - (1 - kappa**2 * psi1_mp(kappa, dps=mpmath.mp.dps))

    return Identity(
        name="A of (4.18) from (3.16)-edge with the adhesive shear",
        statement=(r"1 - \gamma\tfrac{2}{\pi}C_h\int_0^1\sin\kappa\theta(w)\,M(w)\,dw = 1 - \kappa^2\Psi_1(\kappa)"),
        residual=exact(residual),
        points=((0.5,), (1 / 3,), (0.2,), (3 / 7,)),
        tol=1e-28,
    )


def _digamma_identity() -> Identity:
    def residual(kappa):
        direct = mpmath.nsum(lambda j: (-1) ** (j - 1) * j / (j * j + kappa**2 / 4), [1, mpmath.inf])
        z = mpmath.mpc(0, kappa / 4)
        closed = (mpmath.digamma(1 + z) - mpmath.digamma(mpmath.mpf(1) / 2 + z)).real / 2
        return direct - closed

    return Identity(
        name="alternating sum as digamma",
        statement=r"\sum_{k\ge1}\frac{(-1)^{k-1}k}{k^2+\kappa^2/4} = \tfrac12\,\mathrm{Re}\left[\psi(1+\tfrac{i\kappa}4)-\psi(\tfrac12+\tfrac{i\kappa}4)\right]",
        residual=exact(residual),
        points=((0.1,), (0.35,), (1,), (1.9,), (5,)),
        tol=1e-30,
    )


def _d418() -> Derivation:
    steps = []
    j, n_ = symbols("k n", integer=True, positive=True)
    a = k / 2
    ratio = -((a / j) ** 2)  # sum over n of ratio^n / k, a geometric series for kappa < 2k
    geometric = simplify(1 / (j * (1 - ratio)))
    sum_ok = simplify(geometric - j / (j**2 + a**2)) == 0
    steps.append(Step("eta(2n+1) = sum_k (-1)^(k-1) k^-(2n+1); summed over n first (|kappa| < 2k)", Eq(Symbol("term_k"), geometric)))
    closed = (digamma(1 + I * k / 4) - digamma(S.Half + I * k / 4)) / 2
    steps.append(Step("Psi1 = sum_k (-1)^(k-1) k/(k^2 + kappa^2/4) = Re of the digamma form (Identity), valid for all kappa",
                      Eq(Symbol("Psi_1"), sp.re(closed))))
    at_zero = simplify(expand_func(closed.subs(k, 0)))
    steps.append(Step("Psi1(0)", at_zero))
    # C: the nu-form of (4.18) against the gamma-form, gamma = 1/(1+m) with m > 0.
    nu_of_g = (1 - 2 * g) / (2 - 2 * g)
    c_nu = -Rational(2, 3) * k**2 * sqrt(3 - 4 * nu_) / (1 - 2 * nu_)
    c_g = -Rational(2, 3) * k**2 * sqrt(1 - g**2) / g
    c_diff = simplify((c_nu.subs(nu_, nu_of_g) - c_g).subs(g, 1 / (1 + m_)))
    kappa_nu = simplify((log(3 - 4 * nu_) / pi).subs(nu_, nu_of_g) - log((1 + g) / (1 - g)) / pi)
    steps.append(Step("C: 3 - 4 nu = (1+gamma)/(1-gamma), 1 - 2 nu = gamma/(1-gamma); nu-form minus gamma-form", c_diff))
    steps.append(Step("kappa = (1/pi) log(3 - 4 nu) minus (1/pi) log((1+gamma)/(1-gamma))", kappa_nu))
    # M(w) of the A-identity: series of the closed form against termwise integration.
    # K(s) = (1 - r)/(1 + r) = (1 - r)^2/s^2, r = sqrt(1 - s^2), as a Taylor polynomial.
    r_poly = sp.series(sqrt(1 - _Z**2), _Z, 0, 12).removeO()
    k_poly = _taylor(sp.expand(sp.expand((1 - r_poly) ** 2) / _Z**2), 11)
    termwise = _abel_phi(lambda z: diff(k_poly, _Z).subs(_Z, z), 9) * pi / 2
    closed_m = sp.series(-1 / x - log(1 - x**2) / x**3, x, 0, 9).removeO()
    m_ok = simplify(sp.expand(termwise - closed_m)) == 0
    steps.append(Step("A: (3.16)-edge, 1/A = 1 - gamma int_0^1 q0 K ds, K = (1-r)/(1+r); with q0 of (B1), by parts and "
                      "swapped: 1/A = 1 - gamma (2/pi) C_h int_0^1 sin(kappa theta(w)) M(w) dw, where "
                      "M(w) = int_0^w K'(s) ds/sqrt(w^2-s^2) = -1/w - log(1-w^2)/w^3 (series agree to w^8; Identity)",
                      Eq(Symbol("M(w)"), -1 / w - log(1 - w**2) / w**3)))
    psi = Symbol("Psi_1(kappa)")
    derived = Tuple(Eq(Symbol("A"), 1 / (1 - k**2 * psi)), Eq(psi, sp.re(closed)), Eq(Symbol("C"), c_g))
    printed = Tuple(Eq(Symbol("A"), 1 / (1 - k**2 * psi)),
                    Eq(psi, sp.Sum((-1) ** n_ * (k / 2) ** (2 * n_) * sp.dirichlet_eta(2 * n_ + 1), (n_, 0, oo))),
                    Eq(Symbol("C"), c_nu))
    agrees = sum_ok and at_zero == log(2) and c_diff == 0 and kappa_nu == 0 and m_ok

    def fast(gamma_):
        return np.array([sphere_A_adhesive(gamma_), sphere_C_adhesive(gamma_)])

    def precise(gamma_):
        kappa = _mp_kappa(gamma_)
        a_value = 1 / (1 - kappa**2 * psi1_mp(kappa, dps=mpmath.mp.dps))
        return [a_value, -mpmath.mpf(2) / 3 * kappa**2 * mpmath.sqrt(1 - gamma_**2) / gamma_]

    return Derivation(
        label="(4.18)",
        part=PART,
        title="Adhesive sphere: A = 1/(1 - kappa^2 Psi1(kappa)), C = -(2/3) kappa^2 sqrt(3-4nu)/(1-2nu), Psi1 as digamma",
        derived=derived,
        printed=printed,
        agrees=bool(agrees),
        steps=tuple(steps),
        identities=(_digamma_identity(), _m_identity(), _a_identity()),
        fast=fast,
        precise=at_precision(precise),
        arguments=("gamma",),
        comparison=Comparison(points=((0.05,), (0.2,), (1 / 3,), (3 / 7,), (0.5,), (0.7,)), rtol=4e-15),
        note=("A and C are quoted from Spence (1968) (4.12). Here Psi1 is summed in closed form "
              "(digamma), the nu- and gamma-forms of C and kappa are shown equal, and A is confirmed "
              "independently: the paper's own §3 (the (3.16)-edge companion) with the adhesive shear of (B1) "
              "gives 1/A = 1 - kappa^2 Psi1 to 28 digits (Identity). C is not re-derived (only its two forms "
              "compared). Psi1(0) = log 2 as printed. fast/precise give (A, C); psi1 is asymptotics.adhesive.psi1."),
        extra={"psi1": psi1},
    )


# ----------------------------------------------------------------------------- collection
@cache
def derivations() -> tuple[Derivation, ...]:
    """Appendix B, (4.10) and (4.18) derivations (cached: SymPy work is done once)."""
    return (_d410(), _db3(), _db4(), _db4_series(), _db6(), _d418())
