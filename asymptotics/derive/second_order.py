"""SymPy derivation of the second order of the small-gamma expansion (beyond [S75] §2.3).

Two entries, part "2.3":

* ``"f2"``: mu/gamma = f0(c) + gamma^2 f2(c) + O(gamma^4), f0 the law (2.28);
* ``"P*-second-order"``: P* = 1 + gamma^2 P2(c) + gamma^4 P4(c) + O(gamma^6), P2 the term of (2.34).

The steps are SymPy expressions; the integrals SymPy cannot do (Abel integrals giving
elliptic functions, the exact compliance identity, int_0^1 atanh^2 = pi^2/12) are
:class:`Identity` objects checked with mpmath quadrature at 30 digits. The final integrals
are evaluated numerically (``asymptotics.second_order``: nested adaptive quadrature, frozen
into Chebyshev tables); how, and how they were checked, is in each entry's ``note``.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

from functools import cache

import mpmath
import sympy as sp

from .. import second_order as so
from ..derivation import Comparison, Derivation, Identity, Step

__all__ = ["derivations"]

PART = "2.3"

x, t, s, y, u, c = sp.symbols("x t s y u c", positive=True)
gamma, mu = sp.symbols("gamma mu", positive=True)
p, q, g, h, g2, h1, h3 = (sp.Function(n) for n in ("p", "q", "g", "h", "g2", "h1", "h3"))
f0, f2, P2, P4 = (sp.Function(n)(c) for n in ("f0", "f2", "P2", "P4"))
Hg2, Hh1, gt2, He = (sp.Function(n) for n in ("Hg2", "Hh1", "gtilde2", "He"))  # H g2, H h1, g~2, H[e]
B, B2, g2p = (sp.Function(n) for n in ("B", "B2", "g2prime"))


def K_prime(arg):
    """K'(k) = K(sqrt(1 - k^2)) in SymPy's parameter convention."""
    return sp.elliptic_k(1 - arg**2)


def E_prime(arg):
    return sp.elliptic_e(1 - arg**2)


# ---------------------------------------------------------------------------------------
# identities checked in mpmath (residual = left - right)

def _mp_kp(k):
    return mpmath.ellipk(1 - k**2)


def _n_p0_residual(c_):
    """int_0^c t p0(t) dt/sqrt(c^2 - t^2) - (2/pi) atanh c, p0 = (2/pi)(1-t^2)^(-1/2); t = c sin(theta)."""
    c_ = mpmath.mpf(c_)
    val = mpmath.quad(lambda th: c_ * mpmath.sin(th) / mpmath.sqrt(1 - (c_ * mpmath.sin(th)) ** 2), [0, mpmath.pi / 2])
    return 2 / mpmath.pi * (val - mpmath.atanh(c_))


def _d_p0_residual(c_):
    """c int_c^1 p0 dt/sqrt(t^2 - c^2) - (2/pi) c K'(c); t = sqrt(c^2 + (1-c^2) sin^2)."""
    c_ = mpmath.mpf(c_)
    k2 = 1 - c_**2
    val = mpmath.quad(lambda th: 1 / mpmath.sqrt(c_**2 + k2 * mpmath.sin(th) ** 2), [0, mpmath.pi / 2])
    return 2 / mpmath.pi * c_ * (val - _mp_kp(c_))


def _b_stick_residual(x_, c_):
    """int_0^x s ds/sqrt((c^2-s^2)(x^2-s^2)) - atanh(x/c), x < c; s = x sin(theta)."""
    x_, c_ = mpmath.mpf(x_), mpmath.mpf(c_)
    val = mpmath.quad(lambda th: x_ * mpmath.sin(th) / mpmath.sqrt(c_**2 - (x_ * mpmath.sin(th)) ** 2), [0, mpmath.pi / 2])
    return val - mpmath.atanh(x_ / c_)


def _b_slip_residual(x_, c_):
    """int_0^c s ds/sqrt((c^2-s^2)(x^2-s^2)) - atanh(c/x), x > c."""
    return _b_stick_residual(c_, x_)


def _abel_k_residual(y_, x_):
    """int_y^x ds/sqrt((x^2-s^2)(s^2-y^2)) - K'(y/x)/x, y < x; s^2 = y^2 + (x^2-y^2) sin^2."""
    y_, x_ = mpmath.mpf(y_), mpmath.mpf(x_)
    val = mpmath.quad(lambda th: 1 / mpmath.sqrt(y_**2 + (x_**2 - y_**2) * mpmath.sin(th) ** 2), [0, mpmath.pi / 2])
    return val - _mp_kp(y_ / x_) / x_


def _h1_slope_residual(s_):
    """d/ds (s K'(s)) - R_D(0, s^2, 1)/3."""
    s_ = mpmath.mpf(s_)
    return mpmath.diff(lambda z: z * _mp_kp(z), s_) - mpmath.elliprd(0, s_**2, 1) / 3


def _compliance_residual():
    """int_0^1 (1 - sqrt(1-t^2)) q dt - (2/pi) int_0^1 h atanh, for q = t: h = x sqrt(1 - x^2)."""
    rhs = 2 / mpmath.pi * mpmath.quad(lambda z: z * mpmath.sqrt(1 - z**2) * mpmath.atanh(z), [0, 1])
    return mpmath.mpf(1) / 6 - rhs


def _atanh_square_residual():
    """int_0^1 atanh(x)^2 dx - pi^2/12 (so P2 -> 1/3 as c -> 1, (2.36))."""
    return mpmath.quad(lambda z: mpmath.atanh(z) ** 2, [0, 1]) - mpmath.pi**2 / 12


def _identities_f2() -> tuple[Identity, ...]:
    at_c = ((mpmath.mpf("0.1"),), (mpmath.mpf("0.5"),), (mpmath.mpf("0.9"),))
    pairs = ((mpmath.mpf("0.2"), mpmath.mpf("0.5")), (mpmath.mpf("0.45"), mpmath.mpf("0.5")), (mpmath.mpf("0.7"), mpmath.mpf("0.9")))
    return (
        Identity("N[p0]", r"\int_0^c \frac{t\,p^{(0)}(t)\,dt}{\sqrt{c^2-t^2}} = \frac{2}{\pi}\operatorname{atanh} c",
                 _n_p0_residual, at_c, dps=30, tol=1e-25),
        Identity("D[p0]", r"c\int_c^1 \frac{p^{(0)}(t)\,dt}{\sqrt{t^2-c^2}} = \frac{2}{\pi} c K'(c)",
                 _d_p0_residual, at_c, dps=30, tol=1e-25),
        Identity("B stick", r"\int_0^x \frac{s\,ds}{\sqrt{(c^2-s^2)(x^2-s^2)}} = \operatorname{atanh}(x/c),\ x<c",
                 _b_stick_residual, pairs, dps=30, tol=1e-25),
        Identity("B slip", r"\int_0^c \frac{s\,ds}{\sqrt{(c^2-s^2)(x^2-s^2)}} = \operatorname{atanh}(c/x),\ x>c",
                 _b_slip_residual, tuple((b, a) for a, b in pairs), dps=30, tol=1e-25),
        Identity("Abel K'", r"\int_y^x \frac{ds}{\sqrt{(x^2-s^2)(s^2-y^2)}} = K'(y/x)/x",
                 _abel_k_residual, pairs, dps=30, tol=1e-25),
        Identity("h1 slope", r"\frac{d}{ds}\,s K'(s) = \frac{K'(s)-E'(s)}{1-s^2} = \tfrac13 R_D(0, s^2, 1)",
                 _h1_slope_residual, at_c, dps=30, tol=1e-22),
    )


# ---------------------------------------------------------------------------------------

def _steps_f2() -> tuple[Step, ...]:
    pt = p(t)
    F = sp.Integral(t * pt / sp.sqrt(c**2 - t**2), (t, 0, c)) / (c * sp.Integral(pt / sp.sqrt(t**2 - c**2), (t, c, 1)))
    p0 = 2 / sp.pi / sp.sqrt(1 - t**2)
    f0_expr = sp.atanh(c) / (c * K_prime(c))
    h1_expr = sp.Piecewise((2 / sp.pi * sp.atanh(x), x < c), (2 / sp.pi * f0 * x * K_prime(x), True))
    a_expr = sp.Piecewise((t / sp.sqrt(c**2 - t**2), t < c), (-f0 * c / sp.sqrt(t**2 - c**2), True))
    B_expr = sp.Piecewise((sp.atanh(x / c), x < c), (sp.atanh(c / x) - f0 * c / x * K_prime(c / x), True))
    slope = sp.diff(x * K_prime(x), x)
    stick_h = sp.apart(2 * x / ((1 - s**2) * (s**2 - x**2)), s)
    return (
        Step("Stick zone (2.2b) with u* = 0 and q = mu (p - phi), phi = 0 on (c, 1): chi(c) = 0 (2.13) holds "
             "exactly, so (2.12) at x = c gives mu/gamma as a functional F[p] of the pressure alone",
             sp.Eq(mu / gamma, F)),
        Step("With p = p^(0) (2.26) the two Abel integrals are (2/pi) atanh c and (2/pi) c K'(c) "
             "(identities N[p0], D[p0]): F[p^(0)] = f0, the law (2.28)",
             sp.Eq(F.subs(p(t), p0), f0_expr)),
        Step("(2.2) is invariant under gamma -> -gamma, q -> -q, mu -> -mu, so mu/gamma is even in gamma",
             sp.Eq(mu / gamma, f0 + gamma**2 * f2 + sp.O(gamma**4))),
        Step("Abel transforms g = int_x^1 t p/sqrt(t^2-x^2), h = x int_x^1 q/sqrt(t^2-x^2) turn (2.2) into "
             "g - gamma H h = 1, h + gamma H g = u* (H the finite Hilbert transform on (-1, 1)); "
             "expand g = 1 + gamma^2 g2, h = gamma h1 + gamma^3 h3",
             sp.Eq(g2(x), Hh1(x))),
        Step("Stick zone: h = -gamma H g = gamma (2/pi) atanh x + O(gamma^3); slip zone: q = mu p, so "
             "h = mu g~ = gamma f0 (2/pi) x K'(x) + O(gamma^3): h1 in closed form (no psi of (2.30) needed)",
             sp.Eq(h1(x), h1_expr)),
        Step("F[p] = -Hg(c)/g~(c) with g~(x) = x int_x^1 p/sqrt(t^2-x^2); its gamma^2 term, g~0(c) = (2/pi) c K'(c)",
             sp.Eq(f2, (-Hg2(c) - f0 * gt2(c)) / (2 / sp.pi * c * K_prime(c)))),
        Step("The numerator is int_0^1 a(t) p2(t) dt with the weight a below; moving the Abel operator onto a "
             "(A* b = a, b = (2/pi) B' with B(x) = int_0^x a(s)/sqrt(x^2-s^2) ds; identities B stick, "
             "B slip, Abel K')",
             sp.Eq(sp.Function("a")(t), a_expr)),
        Step("The adjoint kernel; B(0) = 0 and B(1) = atanh c - f0 c K'(c) = 0 by (2.28); B jumps by "
             "-f0 pi/2 at c, which cancels the point mass -f0 delta(x - c) in b",
             sp.Eq(B(x), B_expr)),
        Step("Integrating by parts (boundary terms vanish as B(0) = B(1) = 0; g2 ~ -(f0/pi) log(1-x) at 1)",
             sp.Eq(f2, -sp.Integral(B(x) * g2p(x), (x, 0, 1)) / (c * K_prime(c)))),
        Step("d/dx H f = H f' - (1/pi)[f(1)/(1-x) + f(-1)/(1+x)] with h1(+-1) = +-f0",
             sp.Eq(g2p(x), sp.Function("H")(sp.Derivative(h1(x), x)) - 2 * f0 / sp.pi * x / (1 - x**2))),
        Step("h1' on the slip zone: (2/pi) f0 d/dx (x K'(x)) (identity h1 slope); SymPy's derivative:",
             sp.Eq(sp.Derivative(x * K_prime(x), x), slope)),
        Step("h1' on the stick zone is (2/pi)/(1-s^2); its Hilbert transform over (0, c) follows from the "
             "partial fractions (elementary): H = (2/pi^2) [log|(c-x)/(c+x)| + 2x atanh c]/(1-x^2)",
             sp.Eq(2 * x / ((1 - s**2) * (s**2 - x**2)), stick_h)),
    )


def _steps_p4() -> tuple[Step, ...]:
    h_ = h(x)
    e_expr = sp.Piecewise((sp.atanh(x), x < c), (0, True))
    B2_expr = sp.Integral(y / x * sp.atanh(y) * K_prime(y / x), (y, c, x))
    return (
        Step("P* = int_0^1 g dx ((2.4) by Abel) and g = 1 + gamma H h with int_0^1 H h = (2/pi) int_0^1 h atanh "
             "(H skew-adjoint, H[1] = -(2/pi) atanh): exact, equal to (2.34)'s right side (identity P* exact)",
             sp.Eq(sp.Symbol("P^*"), 1 + gamma * 2 / sp.pi * sp.Integral(h_ * sp.atanh(x), (x, 0, 1)))),
        Step("gamma^2 term with h1: the paper's (2.34) with q^(0) of (2.31), a single quadrature; -> 1/3 as c -> 1 "
             "(identity int atanh^2)",
             sp.Eq(P2, 4 / sp.pi**2 * (sp.Integral(sp.atanh(x)**2, (x, 0, c))
                                       + f0 * sp.Integral(x * K_prime(x) * sp.atanh(x), (x, c, 1))))),
        Step("gamma^3 term of h: stick zone h3 = -H g2; slip zone h = mu g~ gives h3 = f0 g~2 + f2 g~0",
             sp.Eq(h3(x), sp.Piecewise((-Hg2(x), x < c), (f0 * gt2(x) + f2 * 2 / sp.pi * x * K_prime(x), True)))),
        Step("H moved onto e = atanh on (0, c) (odd extension), the Abel operators of g~2 onto the weight "
             "int_c^t x atanh x/sqrt(t^2-x^2) dx, whose adjoint kernel is B2 (identity Abel K')",
             sp.Eq(sp.Function("e")(x), e_expr)),
        Step("P4: a triple integral (g2 = H h1, H[e] and B2' are inner quadratures)",
             sp.Eq(P4, 2 / sp.pi * (sp.Integral(g2(x) * He(x), (x, 0, 1))
                                    + f0 * 2 / sp.pi * sp.Integral(sp.Derivative(B2(x), x) * g2(x), (x, c, 1))
                                    + f2 * sp.Integral(sp.atanh(x) * 2 / sp.pi * x * K_prime(x), (x, c, 1))))),
        Step("the kernel B2", sp.Eq(B2(x), B2_expr)),
    )


_NOTE_F2 = (
    "Beyond the paper (it calls this step prohibitive). f2 is the double integral of the last steps, "
    "evaluated by nested adaptive quadrature (scipy quad, inner principal values by subtraction, "
    "(K'-E')/(1-s^2) as R_D(0, s^2, 1)/3): asymptotics.second_order.f2_quadrature, 1e-14 relative "
    "(an mpmath tanh-sinh evaluation of the same integral at 20 digits gave "
    "0.27668037071434837681 at c = 0.5 and 0.82165719287404183083 at c = 0.9). The fast f2 is a "
    "piecewise Chebyshev table in logit(c) on [1e-3, 0.999] (derivations/build_second_order.py); "
    "'precise' here is the quadrature. Independent check: the full solver (numeric.flat_punch, level 3) "
    "at gamma = 0.02 ... 0.16: (mu/gamma - f0)/gamma^2 - f2 = f4 gamma^2 + ..., e.g. f4(0.5) = 0.230; "
    "the error of f0 + gamma^2 f2 falls like gamma^4 for c = 0.1 ... 0.9, no gamma^2 log gamma term. "
    "The local exponents (tan pi alpha = mu gamma) only produce exponentially small non-uniformities. "
    "Observed ends (not proven): f2/f0 = 0.468, 0.472, 0.479 at c = 1e-3, 1e-4, 1e-6 (the quadrature is "
    "not verified below 1e-3); f2/f0^3 = 0.42, 0.39 at c = 0.999, 0.9999, decreasing, as a local argument "
    "near the edge (mu = tan(gamma f0)/gamma-like) suggests f2 ~ f0^3/3."
)

_NOTE_P4 = (
    "P2 is the paper's (2.34) with q^(0) (2.31); P4 is new. P4 is the triple integral of the steps "
    "(asymptotics.second_order.compliance_p4_quadrature, tolerance 1e-11), tabulated like f2. "
    "Independent check: the solver's compliance at gamma = 0.02 ... 0.16 gives (P* - 1 - gamma^2 P2)/gamma^4 "
    "- P4 = P6 gamma^2 + ..., e.g. P6(0.5) = 0.061; the error of 1 + gamma^2 P2 + gamma^4 P4 falls like gamma^6."
)


@cache
def derivations() -> tuple[Derivation, ...]:
    """The entries "f2" and "P*-second-order" (the gamma^4 term P4) of part 2.3 (cached; ~1 s, SymPy)."""
    f2_entry = Derivation(
        label="f2",
        part=PART,
        title="second-order friction law mu/gamma = f0(c) + gamma^2 f2(c) + O(gamma^4)",
        derived=sp.Eq(f2, -sp.Integral(B(x) * g2p(x), (x, 0, 1)) / (c * K_prime(c))),
        printed=None,
        agrees=False,
        steps=_steps_f2(),
        identities=_identities_f2(),
        fast=so.f2,
        precise=so.f2_quadrature,
        arguments=("c",),
        comparison=Comparison(points=((0.37,), (0.83,)), rtol=1e-11),
        note=_NOTE_F2,
    )
    p4_entry = Derivation(
        label="P*-second-order",
        part=PART,
        title="compliance to gamma^4: P* = 1 + gamma^2 P2(c) + gamma^4 P4(c) + O(gamma^6)",
        derived=_steps_p4()[4].expr,
        printed=None,
        agrees=False,
        steps=_steps_p4(),
        identities=(
            Identity("P* exact", r"\int_0^1 (1-\sqrt{1-t^2})\,t\,dt = \frac{2}{\pi}\int_0^1 x\sqrt{1-x^2}\operatorname{atanh}x\,dx",
                     _compliance_residual, ((),), dps=30, tol=1e-25),
            Identity("int atanh^2", r"\int_0^1 \operatorname{atanh}^2 x\,dx = \pi^2/12",
                     _atanh_square_residual, ((),), dps=30, tol=1e-25),
        ),
        fast=so.compliance_p4,
        precise=so.compliance_p4_quadrature,
        arguments=("c",),
        comparison=Comparison(points=((0.61,),), rtol=1e-9),
        note=_NOTE_P4,
    )
    return (f2_entry, p4_entry)
