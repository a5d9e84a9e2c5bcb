"""SymPy derivations of [S75] §3: power-law indenters and the transformation to the flat punch.

Entries (labels): "(3.5)" A* and C* from the Abel integrals of x^n; "(3.10)" the
commutation rule D L = L D~; "(3.13)" the quadrature solving D~ p = p0, p(1) = 0;
"(3.15)" the radial displacement; "(3.16)" the quadrature for A, with its companion
"(3.16)-edge" ((3.5a) at x = 1); "(3.17)" P* = n P0*/(n+1); "(3.18)" p(0) = n p0(0)/(n-1);
"(3.19)", "(3.20)" the smooth sphere and cone; "frictionless-n" (beyond the paper) the
smooth power-law pressure and A for every n in closed form.

Conventions. Every Abel operator of (2.2) is written in the scaled variable t = x s, so
that it reads x^k int K(s) f(x s) ds over fixed limits or limits (1, 1/x); then x d/dx acts
on f(x s) as (t f'(t)) at t = x s, and SymPy differentiates under the integral sign with
Leibniz's rule for the limit 1/x (whose term carries f(1), zero by (3.7)). Unknown stresses
are SymPy undefined functions, so the manipulations hold for every p, q, p0, q0.
Euler's Beta integral int_0^1 v^(a-1) (1-v)^(b-1) dv = B(a, b) (the definition of B) and
Euler's transformation of 2F1 are used as known; each is also an :class:`Identity`
checked in mpmath at 40 digits. SymPy's ``integrate`` is avoided where it is slow (several
seconds for a Beta integral with symbolic exponents): antiderivatives are stated and
checked by differentiation instead.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

import mpmath
import numpy as np
import sympy as sp
from sympy import (Eq, Function, Integral, Rational, S, Symbol, Tuple, atanh, beta, diff,
                   elliptic_k, expand_func, gamma, gammasimp, hyper, hyperexpand, log, pi,
                   simplify, sqrt, symbols)

from ..derivation import Comparison, Derivation, Identity, Step, rounding_bound
from .precision import at_precision, exact
from ..similarity import (a_star_factor, c_star_factor, central_pressure_ratio, compliance_ratio,
                         frictionless_pressure_power_law)

__all__ = ["derivations"]

PART = "3"

x, t, s, v, sigma = symbols("x t s v sigma", positive=True)
gap = Symbol("g", positive=True)  # 1 - x^2 or 1 - t^2, where a positive symbol lets SymPy take square roots
n, A, C, gam = symbols("n A C gamma", positive=True)
a_len, b_len, delta, r_rad = symbols("a b delta r", positive=True)
p, q, p0, q0, f, u, u0 = (Function(name) for name in ("p", "q", "p_0", "q_0", "f", "u", "u_0"))


# ----------------------------------------------------------------------------- helpers
def _is_zero(expr) -> bool:
    """True if SymPy reduces ``expr`` to 0 (gamma functions expanded first)."""
    return sp.simplify(gammasimp(expand_func(expr))) == 0


def _tidy(expr):
    """Cheap simplification: factor, then split and recombine powers (all symbols are positive)."""
    return sp.powsimp(sp.expand_power_base(sp.factor(expr), force=True), force=True)


def _integrals_vanish(expr, boundary: dict) -> tuple[bool, object, object]:
    """Split ``expr`` (a sum of Integrals over one range plus boundary terms) and simplify both parts.

    Returns (both zero, integrand part, boundary part after ``boundary`` substitution).
    """
    expr = sp.expand(expr)
    integrals = expr.atoms(Integral)
    if len({i.limits for i in integrals}) > 1:
        raise ValueError("integrals over different ranges")
    marker = sp.Dummy("M")
    body = sp.expand(expr.xreplace({i: i.function * marker for i in integrals}))
    inner = simplify(body.coeff(marker))
    outer = simplify(body.subs(marker, 0).subs(boundary))
    return inner == 0 and outer == 0, inner, outer


def _substitute(integral: Integral, new, var, lo, hi) -> Integral:
    """``integral`` (one variable) with its variable replaced by ``new`` (a function of ``var``)
    on the range (lo, hi) of ``var``: the integrand times d new / d var, simplified."""
    (old, _, _), = integral.limits
    body = integral.function.subs(old, new) * diff(new, var)
    return Integral(_tidy(body), (var, lo, hi))


def _euler_beta_identity() -> Identity:
    """int_0^1 v^(a-1) (1-v)^(b-1) dv = B(a, b), checked by tanh-sinh quadrature."""

    def residual(a, b):  # v = sin^2(phi) keeps 1 - v accurate near v = 1
        integrand = lambda p_: 2 * mpmath.sin(p_) ** (2 * a - 1) * mpmath.cos(p_) ** (2 * b - 1)
        return mpmath.quad(integrand, [0, mpmath.pi / 2]) - mpmath.beta(a, b)

    return Identity(
        name="Euler's Beta integral",
        statement=r"\int_0^1 v^{a-1}(1-v)^{b-1}\,dv = B(a,b)",
        residual=exact(residual),
        points=((1.25, 0.5), (2, 0.5), (0.75, 0.5), (3.5, 0.5), (1, 0.5)),
        dps=40,
        tol=1e-30,
    )


def _abel_power(m) -> tuple[object, tuple[Step, ...]]:
    """int_0^x t^m dt / sqrt(x^2 - t^2) = x^m B((m+1)/2, 1/2)/2, with the substitution steps."""
    start = Integral(t**m / sqrt(x**2 - t**2), (t, 0, x))
    scaled = _substitute(start, x * s, s, 0, 1)
    in_v = _substitute(scaled, sqrt(v), v, 0, 1)
    value = x**m * beta((m + 1) / 2, S.Half) / 2
    steps = (
        Step(f"Abel integral of t^{sp.sstr(m)}: substitute t = x s", Eq(start, scaled)),
        Step("s = sqrt(v): an Euler Beta integral", Eq(scaled, in_v)),
        Step("Euler's integral B(a, b)", Eq(start, value)),
    )
    return value, steps




def _frictionless_p_mp(x_, n_):
    """(3.13) with (2.26) in closed form, (2n/pi) sqrt(z) 2F1(1, 1 - n/2; 3/2; z), z = 1 - x^2.

    Extra digits make z = (1 - x)(1 + x) carry x^2 to the working precision.
    """
    if x_ == 0:
        return 2 * n_ / ((n_ - 1) * mpmath.pi) if n_ > 1 else mpmath.inf
    extra = 10 + int(4 * max(0, -mpmath.log10(x_)))
    with mpmath.workdps(mpmath.mp.dps + extra):
        z = (1 - x_) * (1 + x_)
        value = 2 * n_ / mpmath.pi * mpmath.sqrt(z) * mpmath.hyp2f1(1, 1 - n_ / 2, 1.5, z)
    return +value


def _frictionless_p_quad(x_, n_):
    """n x^(n-1) int_x^1 t^(-n) (2/pi)(1-t^2)^(-1/2) dt by tanh-sinh, with t = 1 - w^2."""
    body = mpmath.quad(lambda w: 2 * (1 - w * w) ** (-n_) / mpmath.sqrt(2 - w * w), [0, mpmath.sqrt(1 - x_)])
    return n_ * x_ ** (n_ - 1) * 2 / mpmath.pi * body


# ----------------------------------------------------------------------------- (3.5)
def _d35() -> Derivation:
    steps = []
    w = 1 - x**n * a_len**n / (n * b_len ** (n - 1) * delta)
    w_self_similar = w.subs(delta, A * a_len**n / b_len ** (n - 1))
    steps.append(Step("(3.1) with delta = A a^n / b^(n-1) (3.2)", Eq(Symbol("w"), sp.simplify(w_self_similar))))
    i_w, st = _abel_power(n + 1)
    steps.extend(st)
    w_star = diff(x - i_w / (n * A), x)  # d/dx int_0^x t w dt / sqrt(x^2 - t^2), int t/sqrt = x
    a_star = sp.simplify((1 - w_star) / x**n)
    steps.append(Step("w* = d/dx int_0^x t w(t) dt / sqrt(x^2 - t^2) = 1 - A* x^n", Eq(Symbol("A^*"), a_star)))
    i_u, st = _abel_power(n)
    steps.extend(st)
    u_star = (n + 1) * C * i_u  # (t u)' = C (n+1) t^n
    c_star = sp.simplify(u_star / x**n)
    steps.append(Step("u* = int_0^x (t u)' dt / sqrt(x^2 - t^2) with u = C x^n: u* = C* x^n", Eq(Symbol("C^*"), c_star)))
    printed_a = gamma(n / 2) * gamma(S.Half) / (2 * A * gamma((n + 1) / 2))
    printed_c = gamma((n + 3) / 2) * gamma(S.Half) / gamma(1 + n / 2) * C
    agrees = _is_zero(a_star.rewrite(gamma) - printed_a) and _is_zero(c_star.rewrite(gamma) - printed_c)

    def fast(n_):
        return np.array([a_star_factor(n_), c_star_factor(n_)])

    factor_a = sp.lambdify(n, (a_star * A).rewrite(gamma), "mpmath")
    factor_c = sp.lambdify(n, (c_star / C).rewrite(gamma), "mpmath")
    return Derivation(
        label="(3.5)",
        part=PART,
        title="A* and C*: the Abel integrals of w = 1 - x^n/(nA) and u = C x^n",
        derived=Tuple(Eq(Symbol("A^*"), a_star), Eq(Symbol("C^*"), c_star)),
        printed=Tuple(Eq(Symbol("A^*"), printed_a), Eq(Symbol("C^*"), printed_c)),
        agrees=agrees,
        steps=tuple(steps),
        identities=(_euler_beta_identity(),),
        fast=fast,
        precise=at_precision(lambda n_: [factor_a(n_), factor_c(n_)]),
        arguments=("n",),
        comparison=Comparison(points=((0.25,), (0.5,), (1.0,), (2.0,), (3.0,), (7.5,), (40.0,)), rtol=4e-15),
        note=("fast returns (A A*, C*/C) = (a_star_factor(n), c_star_factor(n)). The text's later "
              "reference (1.15) means (3.5) (errata)."),
    )


# ----------------------------------------------------------------------------- (3.10)
def _operator_pieces() -> dict[str, tuple[Callable, object]]:
    """The five Abel pieces of L in (2.2), scaled (t = x s), with their original form."""
    return {
        "int_x^1 t p dt / sqrt(t^2 - x^2)  [L11]": (
            lambda F: x * Integral(s * F(s) / sqrt(s**2 - 1), (s, 1, 1 / x)),
            Integral(t * f(t) / sqrt(t**2 - x**2), (t, x, 1))),
        "int_0^1 q dt  [L12, first term]": (
            lambda F: x * Integral(F(s), (s, 0, 1 / x)),
            Integral(f(t), (t, 0, 1))),
        "x int_0^x q dt / sqrt(x^2 - t^2)  [L12, second term]": (
            lambda F: x * Integral(F(s) / sqrt(1 - s**2), (s, 0, 1)),
            x * Integral(f(t) / sqrt(x**2 - t**2), (t, 0, x))),
        "int_0^x t p dt / sqrt(x^2 - t^2)  [L21]": (
            lambda F: x * Integral(s * F(s) / sqrt(1 - s**2), (s, 0, 1)),
            Integral(t * f(t) / sqrt(x**2 - t**2), (t, 0, x))),
        "x int_x^1 q dt / sqrt(t^2 - x^2)  [L22]": (
            lambda F: x * Integral(F(s) / sqrt(s**2 - 1), (s, 1, 1 / x)),
            x * Integral(f(t) / sqrt(t**2 - x**2), (t, x, 1))),
    }


def _same_after_scaling(original, scaled) -> bool:
    """``original`` (c * Integral in t) equals ``scaled`` (c' * Integral in s) under t = x s."""
    (integral,) = original.atoms(Integral)
    (_, lo, hi), = integral.limits
    moved = _substitute(integral, x * s, s, lo / x, hi / x)
    (target,) = scaled.atoms(Integral)
    same_limits = moved.limits == target.limits
    left = (original / integral) * moved.function
    right = (scaled / target) * target.function
    return same_limits and simplify(left - right) == 0


def _commutation(op: Callable, shift) -> tuple[bool, object, object]:
    """D (op f) - op(D f - shift f) with D = 1 - (x/n) d/dx: (vanishes, integrand part, boundary part)."""
    plain = op(lambda s_: f(x * s_))
    transformed = op(lambda s_: (1 - shift) * f(x * s_) - x / n * diff(f(x * s_), x))  # t f'(t) = x d/dx f(xs)
    residual = plain - x / n * diff(plain, x) - transformed
    return _integrals_vanish(residual, {f(1): 0})


def _d310() -> Derivation:
    steps = []
    all_zero = True
    for name, (op, original) in _operator_pieces().items():
        scaled = op(lambda s_: f(x * s_))
        all_zero = all_zero and _same_after_scaling(original, scaled)
        steps.append(Step(f"{name}: t = x s gives x * (integral over fixed or (1, 1/x) limits)", Eq(original, scaled)))
        ok, inner, outer = _commutation(op, 1 / n)
        all_zero = all_zero and ok
        steps.append(Step(f"{name}: D(op f) - op(D~ f), integrand part and boundary part with f(1) = 0 (3.7)",
                          Tuple(inner, outer)))
    D, L, Dt = symbols(r"D L \tilde{D}", commutative=False)
    statement = Eq(D * L, L * Dt)
    return Derivation(
        label="(3.10)",
        part=PART,
        title="The commutation rule D L = L D~, D = 1 - (x/n) d/dx, D~ = D - 1/n",
        derived=statement,
        printed=statement,
        agrees=all_zero,
        steps=tuple(steps),
        note=("Proved for each of the five Abel pieces of L with p, q undefined functions: every piece "
              "is x * (integral of K(s) f(xs)), homogeneous of degree 1, so x d/dx commutes with it up to "
              "the term L f, and the Leibniz terms at s = 1/x carry f(1) = 0 (3.7). The constant "
              "int_0^1 q dt is x int_0^(1/x) q(xs) ds. The paper's 'apply D to both sides of (1.15)' "
              "means (3.5)."),
    )


# ----------------------------------------------------------------------------- (3.13)
def _d313() -> Derivation:
    tilde = (1 - 1 / n) * p(x) - x / n * diff(p(x), x)
    ode = Eq(tilde, p0(x))
    factor = x ** (1 - n)
    exact = diff(factor * p(x), x) - (-n * x ** (-n)) * tilde
    solution = n * x ** (n - 1) * Integral(t ** (-n) * p0(t), (t, x, 1))
    check = simplify(((1 - 1 / n) * solution - x / n * diff(solution, x) - p0(x)))
    boundary = solution.subs(x, 1).doit()
    steps = (
        Step("(3.11): D~ p = p0 with D~ = 1 - 1/n - (x/n) d/dx", ode),
        Step("integrating factor: d/dx(x^(1-n) p) = -n x^(-n) D~ p (difference simplifies to 0)", simplify(exact)),
        Step("integrate from x to 1 with p(1) = 0 (3.7)", Eq(p(x), solution)),
        Step("substituted back into D~ p - p0 (Leibniz rule)", check),
        Step("value at x = 1", boundary),
    )
    printed = Eq(p(x), n * x ** (n - 1) * Integral(t ** (-n) * p0(t), (t, x, 1)))
    return Derivation(
        label="(3.13)",
        part=PART,
        title="p(x) = n x^(n-1) int_x^1 t^(-n) p0(t) dt (same for q): the solution of D~ p = p0, p(1) = 0",
        derived=Eq(p(x), solution),
        printed=printed,
        agrees=bool(simplify(exact) == 0 and check == 0 and boundary == 0 and printed.rhs == solution),
        steps=steps,
        note=("The general solution adds K x^(n-1), excluded by p(1) = 0. App. B's reference (1.23) means "
              "(3.13) (errata). Numerical evaluation for a computed flat punch: numeric.solutions.power_law."),
    )


# ----------------------------------------------------------------------------- (3.15)
def _d315() -> Derivation:
    steps = []
    a0 = lambda F: Integral(F(s) / sqrt(1 - s**2), (s, 0, 1))  # int_0^x g dt / sqrt(x^2 - t^2)
    ok_a0, inner, outer = _commutation(a0, 0)
    steps.append(Step("u* = A0 (t u)', A0 g = int_0^x g dt/sqrt(x^2 - t^2) = int_0^1 g(xs) ds/sqrt(1 - s^2): "
                      "degree 0, so D A0 g - A0 D g = 0 (integrand part, boundary part)", Tuple(inner, outer)))
    steps.append(Step("u0* = D u* and A0 one-to-one give D (x u)' = (x u0)'",
                      Eq(diff(x * u(x), x) - x / n * diff(x * u(x), x, 2), diff(x * u0(x), x))))
    candidate = x**n * (C - n * Integral(t ** (-n - 1) * u0(t), (t, 0, x)))
    g = diff(x * candidate, x)
    residual = simplify(g - x / n * diff(g, x) - diff(x * u0(x), x))
    steps.append(Step("u = x^n [C - n int_0^x t^(-n-1) u0 dt] substituted: residual", residual))
    steps.append(Step("homogeneous solutions: (x u)' = K x^n, i.e. u = K x^n/(n+1) + K'/x; regularity at 0 "
                      "drops K'/x and u = C x^n on the stick zone (u0 = 0 there) fixes K", Eq(u(x), candidate)))
    u_r = (A * a_len**n / b_len ** (n - 1)) * candidate.subs(x, r_rad / a_len)  # u_r = delta u(r/a)
    printed = (A * r_rad**n / b_len ** (n - 1)) * (C - n * Integral(t ** (-n - 1) * u0(t), (t, 0, r_rad / a_len)))
    steps.append(Step("u_r = delta u(r/a) with delta = A a^n / b^(n-1) (3.2)",
                      Eq(Symbol("u_r"), sp.powsimp(sp.expand_power_base(u_r, force=True), force=True))))
    rate = simplify(diff(printed, a_len))
    expected_rate = n * A * (a_len / b_len) ** (n - 1) * u0(r_rad / a_len)
    steps.append(Step("d u_r / d a (Leibniz): n A (a/b)^(n-1) u0(r/a), zero on the stick zone", Eq(Symbol("du_r/da"), rate)))
    agrees = ok_a0 and residual == 0 and _is_zero(u_r - printed) and _is_zero(rate - expected_rate)
    return Derivation(
        label="(3.15)",
        part=PART,
        title="Radial displacement u_r(r, a) of the power-law indenter and its rate d u_r/d a",
        derived=Eq(Symbol("u_r"), u_r),
        printed=Eq(Symbol("u_r"), printed),
        agrees=bool(agrees),
        steps=tuple(steps),
        note="Printed u_r and its a-derivative agree with the derivation.",
    )


# ----------------------------------------------------------------------------- (3.16)
def _antiderivative_step(text: str, integrand, antiderivative, var) -> tuple[Step, bool]:
    ok = simplify(diff(antiderivative, var) - integrand) == 0
    return Step(f"{text} (F' - integrand simplifies to 0)", Eq(Symbol("F"), antiderivative)), ok


def _elliptic_kernel_identity() -> Identity:
    def residual(t_):
        # x = t (1 - u^2) removes the inverse square root at x = t: dx / sqrt(t^2 - x^2) = 2 du / sqrt(2 - u^2).
        inner = mpmath.quad(lambda u_: 2 / (mpmath.sqrt(1 - (t_ * (1 - u_ * u_)) ** 2) * mpmath.sqrt(2 - u_ * u_)),
                            [0, mpmath.sqrt(1 - t_), 1])
        return inner - mpmath.ellipk(t_ * t_)

    return Identity(
        name="Abel kernel of (3.16) is K(t)",
        statement=r"\int_0^t \frac{dx}{\sqrt{(1-x^2)(t^2-x^2)}} = K(t)",
        residual=exact(residual),
        points=((0.1,), (0.5,), (0.9,), (0.999,)),
        tol=1e-30,
    )


def _a316_frictionless_identity() -> Identity:
    def residual(n_):
        integral = mpmath.quad(lambda t_: t_ * mpmath.ellipk(t_ * t_) * _frictionless_p_mp(t_, n_), [0, 0.5, 1])
        a_value = mpmath.beta(n_ / 2, mpmath.mpf(1) / 2) / 2
        return 2 / mpmath.pi * integral - (1 - 1 / (n_ * a_value))

    return Identity(
        name="(3.16) for smooth indenters (A = B(n/2, 1/2)/2, p of 'frictionless-n')",
        statement=r"1 - \frac{1}{nA} = \frac{2}{\pi}\int_0^1 t K(t) p(t)\,dt",
        residual=exact(residual),
        points=((0.5,), (2,), (3,)),
        dps=30,
        tol=1e-25,
    )


def _d316() -> tuple[Derivation, Derivation]:
    steps = []
    ok = True
    # Left side, L11 term: swap the order, kernel int_0^t dx / sqrt((1-x^2)(t^2-x^2)).
    kernel = Integral(1 / sqrt((1 - x**2) * (t**2 - x**2)), (x, 0, t))
    legendre = _substitute(kernel, t * sigma, sigma, 0, 1)
    ok = ok and simplify(legendre.function - 1 / sqrt((1 - sigma**2) * (1 - t**2 * sigma**2))) == 0
    steps.append(Step("L11 term: (2/pi) int_0^1 (1-x^2)^(-1/2) int_x^1 t p dt/sqrt(t^2-x^2) dx, order swapped; "
                      "the kernel with x = t sigma is Legendre's form of K(t) (SymPy's elliptic_k takes m = t^2)",
                      Eq(kernel, legendre)))
    steps.append(Step("so the L11 term is", (2 / pi) * Integral(t * elliptic_k(t**2) * p(t), (t, 0, 1))))
    # gamma terms: (2/pi) int (1-x^2)^(-1/2) dx = 1 and (2/pi) int_t^1 x dx / sqrt((1-x^2)(x^2-t^2)) = 1.
    first = sp.integrate(2 / pi / sqrt(1 - x**2), (x, 0, 1))
    weight = Integral(x / sqrt((1 - x**2) * (x**2 - t**2)), (x, t, 1))
    in_sigma = _substitute(weight.subs(t, sqrt(1 - gap)), sqrt(1 - gap + gap * sigma), sigma, 0, 1)  # gap = 1 - t^2
    second = simplify((2 / pi * beta(S.Half, S.Half) / 2).rewrite(gamma))
    ok = ok and simplify(in_sigma.function - 1 / (2 * sqrt(sigma * (1 - sigma)))) == 0 and first == 1 and second == 1
    steps.append(Step("gamma term int_0^1 q dt: weight (2/pi) int_0^1 (1-x^2)^(-1/2) dx", first))
    steps.append(Step("gamma term x int_0^x q/sqrt(x^2-t^2): weight (2/pi) int_t^1 x dx/sqrt((1-x^2)(x^2-t^2)); "
                      "x^2 = t^2 + (1 - t^2) sigma gives (1/pi) B(1/2, 1/2)", Eq(weight, in_sigma)))
    steps.append(Step("so the second weight is", second))
    steps.append(Step("the gamma terms cancel: gamma (1 - 1) int_0^1 q dt", gam * (first - second)))
    # Right side: (2/pi) int_0^1 (1 - A* x^n)/sqrt(1 - x^2) dx.
    moment, st = _abel_power(n)
    moment = moment.subs(x, 1)
    steps.extend(st)
    a_star = gamma(n / 2) * gamma(S.Half) / (2 * A * gamma((n + 1) / 2))  # (3.5)
    right = 1 - a_star * 2 / pi * moment
    right_simple = sp.simplify(gammasimp(expand_func(right.rewrite(gamma))))
    steps.append(Step("right side (2/pi) int_0^1 (1 - A* x^n) dx / sqrt(1 - x^2) with A* of (3.5)", Eq(Symbol("RHS"), right_simple)))
    ok = ok and _is_zero(right.rewrite(gamma) - (1 - 1 / (n * A)))
    derived = Eq(1 - 1 / (n * A), 2 / pi * Integral(t * elliptic_k(t**2) * p(t), (t, 0, 1)))
    main = Derivation(
        label="(3.16)",
        part=PART,
        title="A by quadrature: 1 - 1/(nA) = (2/pi) int_0^1 t K(t) p(t) dt",
        derived=derived,
        printed=derived,
        agrees=bool(ok),
        steps=tuple(steps),
        identities=(_elliptic_kernel_identity(), _a316_frictionless_identity(), _euler_beta_identity()),
        note=("Correct as printed, with or without friction: the gamma terms cancel for every q. K(t) is "
              "the complete elliptic integral of modulus t (parameter m = t^2). For a computed flat punch "
              "see numeric.solutions.power_law.indentation_constant_316."),
    )
    # Companion: (3.5a) at x = 1, where the L11 term vanishes.
    edge_steps = [Step("(3.5a) at x = 1: int_1^1 ... = 0, the gamma terms give",
                       Eq(1 - Symbol("A^*"), -gam * Integral(q(t) * (1 - 1 / sqrt(1 - t**2)), (t, 0, 1))))]
    edge_steps.append(Step("(3.13) for q and the order swapped: A* = 1 + gamma int_0^1 q0(s) s^(-n) W_n(s) ds",
                           Eq(Symbol("W_n(s)"), Integral(n * t ** (n - 1) * (1 - 1 / sqrt(1 - t**2)), (t, 0, s)))))
    w2 = sp.integrate(2 * t * (1 - 1 / sqrt(1 - t**2)), (t, 0, s))
    kernel2 = simplify(w2 / s**2)
    target = -(1 - sqrt(1 - s**2)) / (1 + sqrt(1 - s**2))
    edge_ok = simplify(kernel2 - target) == 0 and a_star.subs(n, 2) * A == 1
    edge_steps.append(Step("n = 2: s^(-2) W_2(s)", Eq(Symbol("s^{-2}W_2"), kernel2)))
    edge_steps.append(Step("n = 2: A* = 1/A by (3.5)", Eq(Symbol("A^*"), a_star.subs(n, 2))))
    edge_derived = Eq(1 / A, 1 - gam * Integral(q0(s) * (1 - sqrt(1 - s**2)) / (1 + sqrt(1 - s**2)), (s, 0, 1)))
    edge = Derivation(
        label="(3.16)-edge",
        part=PART,
        title="Sphere: 1/A = 1 - gamma int_0^1 q0(s) (1 - sqrt(1-s^2))/(1 + sqrt(1-s^2)) ds, from (3.5a) at x = 1",
        derived=edge_derived,
        printed=None,
        agrees=bool(edge_ok),
        steps=tuple(edge_steps),
        note=("Not in the paper: a companion of (3.16) needing only the flat punch's shear q0. For general n, "
              "W_n(s) = s^n - (n/2) B(s^2; n/2, 1/2). With the adhesive q0 of (B3) it reproduces A of (4.18) "
              "(tests/test_derive_similarity.py)."),
    )
    return main, edge


# ----------------------------------------------------------------------------- (3.17), (3.18)
def _d317() -> Derivation:
    pressure = n * x ** (n - 1) * Integral(t ** (-n) * p0(t), (t, x, 1))
    start = pi / 2 * Integral(x * pressure, (x, 0, 1))
    weight = sp.integrate(n * x**n, (x, 0, t), conds="none")
    swapped = pi / 2 * Integral(t ** (-n) * p0(t) * weight, (t, 0, 1))
    kernel = sp.powsimp(sp.expand(t ** (-n) * weight), force=True)
    result = pi / 2 * Integral(kernel * p0(t), (t, 0, 1))
    ratio = sp.simplify(kernel / t)
    steps = (
        Step("(2.4) with p from (3.13)", Eq(Symbol("P^*"), start)),
        Step("order swapped: inner weight int_0^t n x^n dx", Eq(Symbol("P^*"), swapped)),
        Step("t^(-n) n t^(n+1)/(n+1) = n t/(n+1)", Eq(Symbol("P^*"), result)),
    )
    return Derivation(
        label="(3.17)",
        part=PART,
        title="Compliance P* = n P0*/(n+1)",
        derived=Eq(Symbol("P^*"), ratio * Symbol("P_0^*")),
        printed=Eq(Symbol("P^*"), n / (n + 1) * Symbol("P_0^*")),
        agrees=bool(sp.simplify(ratio - n / (n + 1)) == 0),
        steps=steps,
        fast=compliance_ratio,
        precise=at_precision(lambda n_: n_ / (n_ + 1)),
        arguments=("n",),
        comparison=Comparison(points=((0.5,), (1.0,), (2.0,), (3.0,)), rtol=rounding_bound(2)),  # n/(n + 1)
        note=("Swapping the order is the integration by parts of the paper. fast/precise give P*/P0*. "
              "Section 4.2's reference (1.28) means (3.17) (errata)."),
    )


def _d318() -> Derivation:
    numerator = Integral(t ** (-n) * p0(t), (t, x, 1))
    ratio = simplify(diff(numerator, x) / diff(x ** (1 - n), x))
    centre = n * ratio.subs(x, 0)
    via_311 = sp.solve(Eq((1 - 1 / n) * Symbol("p(0)"), p0(0)), Symbol("p(0)"))[0]
    steps = (
        Step("(3.13): p = n (int_x^1 t^(-n) p0 dt) / x^(1-n), both -> inf as x -> 0 for n > 1; l'Hopital ratio",
             ratio),
        Step("x -> 0", Eq(Symbol("p(0)"), centre)),
        Step("the same from (3.11) at x = 0, where x p'(x) -> 0: (1 - 1/n) p(0) = p0(0)", Eq(Symbol("p(0)"), via_311)),
    )
    printed = n / (n - 1) * p0(0)
    return Derivation(
        label="(3.18)",
        part=PART,
        title="Central pressure p(0) = n p0(0)/(n-1), n > 1",
        derived=Eq(Symbol("p(0)"), centre),
        printed=Eq(Symbol("p(0)"), printed),
        agrees=bool(simplify(centre - printed) == 0 and simplify(via_311 - printed) == 0),
        steps=steps,
        fast=central_pressure_ratio,
        precise=at_precision(lambda n_: n_ / (n_ - 1)),
        arguments=("n",),
        comparison=Comparison(points=((1.5,), (2.0,), (3.0,), (10.0,)), rtol=rounding_bound(2)),  # n/(n - 1)
        note="fast/precise give p(0)/p0(0). For n <= 1 p is unbounded at x = 0.",
    )


# ----------------------------------------------------------------------------- (3.19), (3.20)
def _boussinesq() -> object:
    return 2 / pi / sqrt(1 - t**2)  # (2.26)


def _d319() -> Derivation:
    integrand = t**-2 * _boussinesq()
    anti = -2 / pi * sqrt(1 - t**2) / t
    step, ok = _antiderivative_step("int t^(-2) (2/pi)(1-t^2)^(-1/2) dt", integrand, anti, t)
    pressure = simplify(2 * x * (anti.subs(t, 1) - anti.subs(t, x)))
    # A = 1: (3.5a) without gamma for this p; t^2 = x^2 + (1 - x^2) sigma.
    abel = Integral(t * pressure.subs(x, t) / sqrt(t**2 - x**2), (t, x, 1))
    in_sigma = _substitute(abel.subs(x, sqrt(1 - gap)), sqrt(1 - gap + gap * sigma), sigma, 0, 1)
    body_ok = simplify(in_sigma.function - 2 * gap / pi * sqrt((1 - sigma) / sigma)) == 0
    value = (2 * gap / pi * beta(S.Half, Rational(3, 2))).rewrite(gamma).subs(gap, 1 - x**2)
    printed = 4 / pi * (1 - x**2) ** S.Half
    steps = (
        Step("(3.13), n = 2, p0 = (2/pi)(1 - t^2)^(-1/2) (2.26)", Eq(p(x), 2 * x * Integral(integrand, (t, x, 1)))),
        step,
        Step("p(x)", Eq(p(x), pressure)),
        Step("(3.5a), gamma = 0: int_x^1 t p dt / sqrt(t^2 - x^2), t^2 = x^2 + g sigma, g = 1 - x^2", Eq(abel, in_sigma)),
        Step("= (2 g/pi) B(1/2, 3/2)", Eq(abel, value)),
        Step("= 1 - A* x^2 with A* = 1, so A = B(1, 1/2)/2 = 1 by (3.5)", beta(1, S.Half) / 2),
    )
    return Derivation(
        label="(3.19)",
        part=PART,
        title="Smooth sphere: p(x) = (4/pi)(1 - x^2)^(1/2), A = 1",
        derived=Eq(p(x), pressure),
        printed=Eq(p(x), printed),
        agrees=bool(ok and body_ok and simplify(pressure - printed) == 0 and simplify(value - (1 - x**2)) == 0),
        steps=steps,
        fast=lambda x_: frictionless_pressure_power_law(x_, 2.0),
        precise=at_precision(lambda x_: 4 / mpmath.pi * mpmath.sqrt((1 - x_) * (1 + x_))),
        arguments=("x",),
        # the costlier branch (x^2 < 1/2): x^(n-1), beta, hyp2f1 and 8 operations, no cancellation at n = 2
        comparison=Comparison(points=((0.0,), (1e-9,), (0.3,), (0.7,), (0.9,), (1 - 1e-12,), (1.0,)),
                              rtol=rounding_bound(8, 3)),
        note="The classical Hertz pressure; A = 1 as the paper says.",
    )


def _d320() -> Derivation:
    integrand = t**-1 * _boussinesq()
    anti = -2 / pi * atanh(sqrt(1 - t**2))
    step, ok = _antiderivative_step("int t^(-1) (2/pi)(1-t^2)^(-1/2) dt", integrand, anti, t)
    pressure = simplify(anti.subs(t, 1) - anti.subs(t, x))
    printed = 2 / pi * log((1 + sqrt(1 - x**2)) / x)
    # atanh(r) = log((1+r)/x) with r = sqrt(1 - x^2): compare exp(2 atanh r) = (1+r)/(1-r) with ((1+r)/x)^2.
    r = Symbol("r", positive=True)
    same = simplify((1 + r) / (1 - r) - ((1 + r) / sqrt(1 - r**2)) ** 2) == 0
    steps = (
        Step("(3.13), n = 1, p0 = (2/pi)(1 - t^2)^(-1/2) (2.26)", Eq(p(x), Integral(integrand, (t, x, 1)))),
        step,
        Step("p(x)", Eq(p(x), pressure)),
        Step("(2/pi) atanh(r) = (2/pi) log((1+r)/x), r = sqrt(1-x^2): (1+r)/(1-r) - ((1+r)/x)^2 simplifies to 0",
             Eq(pressure, printed)),
    )
    return Derivation(
        label="(3.20)",
        part=PART,
        title="Smooth cone (n = 1): p(x) = (2/pi) log[(1 + sqrt(1 - x^2))/x]",
        derived=Eq(p(x), pressure),
        printed=Eq(p(x), printed),
        agrees=bool(ok and same),
        steps=steps,
        fast=lambda x_: frictionless_pressure_power_law(x_, 1.0),
        precise=at_precision(lambda x_: 2 / mpmath.pi * mpmath.log((1 + mpmath.sqrt((1 - x_) * (1 + x_))) / x_)),
        arguments=("x",),
        # log1p(sqrt((1 - x)(1 + x))) - log(x): 2 calls, 7 operations, a sum of positive terms (log x < 0)
        comparison=Comparison(points=((1e-300,), (1e-9,), (0.3,), (0.7,), (0.9,), (1 - 1e-12,), (1.0,)),
                              rtol=rounding_bound(7, 2)),
        note="A = pi/2 for the smooth cone (A* = 1 in (3.5)); p diverges logarithmically at the apex.",
    )


# ----------------------------------------------------------------------------- frictionless-n
def _euler_transformation_identity() -> Identity:
    def residual(n_, z):
        lhs = mpmath.hyp2f1(mpmath.mpf(1) / 2, (n_ + 1) / 2, mpmath.mpf(3) / 2, z)
        rhs = (1 - z) ** ((1 - n_) / 2) * mpmath.hyp2f1(1, 1 - n_ / 2, mpmath.mpf(3) / 2, z)
        return lhs - rhs

    return Identity(
        name="Euler's transformation of 2F1",
        statement=r"{}_2F_1(\tfrac12,\tfrac{n+1}2;\tfrac32;z) = (1-z)^{(1-n)/2}\,{}_2F_1(1,1-\tfrac n2;\tfrac32;z)",
        residual=exact(residual),
        points=((0.5, 0.3), (1.5, 0.9), (2.5, 0.5), (3, 0.99), (7.5, 0.2)),
        tol=1e-28,
    )


def _quadrature_identity() -> Identity:
    def residual(n_, x_):
        return _frictionless_p_quad(x_, n_) - _frictionless_p_mp(x_, n_)

    return Identity(
        name="closed form against quadrature of (3.13)",
        statement=r"n x^{n-1}\int_x^1 t^{-n}\tfrac{2}{\pi}(1-t^2)^{-1/2}dt = \tfrac{2n}{\pi}\sqrt{1-x^2}\,{}_2F_1(1,1-\tfrac n2;\tfrac32;1-x^2)",
        residual=exact(residual),
        points=((0.5, 0.1), (0.5, 0.9), (1.5, 0.01), (2.5, 0.5), (3, 0.3), (4, 0.999), (7.5, 0.6)),
        tol=1e-28,
    )


def _dfrictionless() -> Derivation:
    b = (n + 1) / 2
    k = Symbol("k", integer=True, nonnegative=True)
    z = Symbol("z", positive=True)
    steps = [Step("(3.13) with p0 = (2/pi)(1 - t^2)^(-1/2) (2.26)",
                  Eq(p(x), n * x ** (n - 1) * Integral(t ** (-n) * _boussinesq(), (t, x, 1))))]
    moved = Integral(t ** (-n) / sqrt(1 - t**2), (t, x, 1)).transform(t, (sqrt(1 - v), v))
    steps.append(Step("t = sqrt(1 - v): (1/2) int_0^(1-x^2) v^(-1/2) (1 - v)^(-(n+1)/2) dv", moved))
    # Termwise: (1 - v)^(-b) = sum (b)_k v^k / k!; int_0^z v^(k-1/2) dv = z^(k+1/2)/(k+1/2).
    term = sp.rf(b, k) / sp.factorial(k) / (k + S.Half) / 2
    hyper_term = sp.rf(S.Half, k) * sp.rf(b, k) / (sp.rf(Rational(3, 2), k) * sp.factorial(k))
    termwise_ok = sp.simplify(gammasimp((term / hyper_term).rewrite(gamma))) == 1
    steps.append(Step("termwise: coefficient of z^(k+1/2) over that of 2F1(1/2, (n+1)/2; 3/2; z)",
                      sp.simplify(gammasimp((term / hyper_term).rewrite(gamma)))))
    incomplete = sqrt(z) * hyper((S.Half, b), (Rational(3, 2),), z)
    steps.append(Step("so the integral is", Eq(Symbol("I"), incomplete)))
    closed_z = sqrt(z) * (1 - z) ** ((1 - n) / 2) * hyper((1, 1 - n / 2), (Rational(3, 2),), z)
    steps.append(Step("Euler's transformation (Identity), z = 1 - x^2, (1 - z)^((1-n)/2) = x^(1-n)", closed_z))
    pressure = 2 * n / pi * sqrt(1 - x**2) * hyper((1, 1 - n / 2), (Rational(3, 2),), 1 - x**2)
    steps.append(Step("p(x) = n x^(n-1) (2/pi) I", Eq(p(x), pressure)))
    sphere = hyperexpand(pressure.subs(n, 2))
    cone = hyperexpand(pressure.subs(n, 1))
    cone_target = 2 / pi * atanh(sqrt(1 - x**2))
    special_ok = simplify(sphere - 4 / pi * sqrt(1 - x**2)) == 0 and simplify(cone - cone_target) == 0
    steps.append(Step("n = 2: (3.19)", Eq(p(x), sphere)))
    steps.append(Step("n = 1: (2/pi) atanh(sqrt(1-x^2)), which is (3.20)", Eq(p(x), cone)))
    gauss = hyperexpand(hyper((1, 1 - n / 2), (Rational(3, 2),), 1))
    centre = simplify(gammasimp(expand_func(2 * n / pi * gauss)))
    steps.append(Step("x = 0, Gauss's sum (n > 1): p(0) = (2/pi) n/(n-1), (3.18)", Eq(Symbol("p(0)"), centre)))
    a_value = gamma(n / 2) * gamma(S.Half) / (2 * gamma((n + 1) / 2))
    steps.append(Step("A from (3.5) with A* = 1 (gamma = 0 makes (3.5a) the frictionless Abel equation)",
                      Eq(A, a_value)))
    a_ok = simplify(a_value.subs(n, 2) - 1) == 0 and simplify(a_value.subs(n, 1) - pi / 2) == 0
    centre_ok = simplify(centre - 2 * n / (pi * (n - 1))) == 0
    return Derivation(
        label="frictionless-n",
        part=PART,
        title="Smooth power-law indenter: p(x) = (2n/pi) sqrt(1-x^2) 2F1(1, 1-n/2; 3/2; 1-x^2), A = sqrt(pi) Gamma(n/2)/(2 Gamma((n+1)/2))",
        derived=Tuple(Eq(p(x), pressure), Eq(A, a_value)),
        printed=None,
        agrees=bool(termwise_ok and special_ok and a_ok and centre_ok),
        steps=tuple(steps),
        identities=(_euler_transformation_identity(), _quadrature_identity()),
        fast=frictionless_pressure_power_law,
        precise=at_precision(_frictionless_p_mp),
        arguments=("x", "n"),
        comparison=Comparison(
            points=tuple((x_, n_) for n_ in (0.3, 0.9, 1.0, 1.5, 2.0, 2.5, 3.0, 3.02, 4.0, 7.5, 20.0)
                         for x_ in (1e-12, 1e-4, 0.3, 0.7, 0.71, 0.9, 0.999, 1 - 1e-12)),
            rtol=1e-14,
        ),
        note=("Beyond the paper; the classical smooth solution (A for general n is the known "
              "Sneddon/Galin result). `agrees` means the n = 1, 2 cases reduce to (3.19), (3.20), the centre "
              "to (3.18) and A to 1 and pi/2. The Euler transformation is an Identity. For n < 1 the pressure "
              "is unbounded like x^(n-1) at the apex."),
    )


# ----------------------------------------------------------------------------- collection
@cache
def derivations() -> tuple[Derivation, ...]:
    """The §3 derivations, in the paper's order (cached: SymPy work is done once)."""
    d316, edge = _d316()
    return (_d35(), _d310(), _d313(), _d315(), d316, edge, _d317(), _d318(), _d319(), _d320(), _dfrictionless())
