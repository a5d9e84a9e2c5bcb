"""The Abel rules of the singular basis (``numeric.core.abel_rules``) against mpmath.

Every basis function of every element kind, at points inside the element (near and far from its
singular end), just outside either end (down to 1e-12 of the element) and far away, in both
directions, for alpha from 0.01 to 0.49 (beta = 1 - 2 alpha from 0.98 to 0.02, the edge weight
s^(2 alpha - 1) from s^-0.98 to s^-0.02). The reference is tanh-sinh quadrature at 30 digits with
break points at the singular end, at the point and graded toward a nearby outside point.
Tolerance 1e-12 relative to max(1, |value|): measured worst 2.3e-11 before the inner pieces of
the graded rules kept enough nodes, 1.3e-11 since, that one at a point 1.8e-11 beyond a plain
element, where the test's own double-rounded geometry (c^2 + (1 - c^2) != 1 by 1e-17) shifts the
distance by 1e-6 relative; elsewhere <= 2e-13. So points closer than 1e-10 of an element are
checked at 1e-10.
"""

import mpmath
import numpy as np
import pytest

from numeric.core.charts import AT_C2, AT_ONE, PLAIN, SLIP_END, STICK_END, Resolution, layout
from numeric.core.abel_rules import gauss01
from numeric.core.charts import shifted_legendre
from numeric.core.operators import EXTRA_NODES, AbelOperators, near_plain

LAY = layout(0.6, 0.4, Resolution(degree=12, singular_degree=3, edge_singular_degree=1))


def _basis_mp(e: int, j: int, s, alpha):
    kind, K = int(LAY.kind[e]), int(LAY.degree[e])
    k = j if j <= K else j - K - 1
    P = mpmath.legendre(k, 2 * s - 1)
    if kind == PLAIN or j <= K and kind in (STICK_END, SLIP_END):
        return P
    if kind in (STICK_END, SLIP_END):
        b = 1 - 2 * mpmath.mpf(alpha)
        return ((s**b - s) / (b - 1) if b > 0.5 else (s**b - 1) / b) * P
    w = s ** (2 * mpmath.mpf(alpha) - 1)
    return w * P if j <= K else w * s**2 * mpmath.log(s) * P


def _exact(e: int, j: int, v, upper: bool, alpha: float):
    kind = int(LAY.kind[e])
    A = mpmath.mpf(LAY.c2 if LAY.anchor[e] == AT_C2 else 1.0)
    lo, hi = mpmath.mpf(LAY.lo[e]), mpmath.mpf(LAY.hi[e])
    L = hi - lo

    def u_of(s):
        if kind == PLAIN:
            return A + lo + L * s
        return A + L * s * s if kind == SLIP_END else A - L * s * s

    def integrand(s):
        d = u_of(s) - v
        if (upper and d <= 0) or (not upper and d >= 0):
            return mpmath.mpf(0)
        jacobian = L if kind == PLAIN else 2 * L * s
        return _basis_mp(e, j, s, alpha) * jacobian / (2 * mpmath.sqrt(abs(d)))

    points = [mpmath.mpf(0), mpmath.mpf(1)]
    if kind == PLAIN:
        position = (v - A - lo) / L
        if 0 < position < 1:
            points.insert(1, position)
        for distance, end in ((-position, 0), (position - 1, 1)):
            if 0 < distance < 1:
                points += [abs(end - distance * 10**k) for k in range(40) if distance * 10**k < 1]
    else:
        s2 = (v - A) / L if kind == SLIP_END else (A - v) / L
        if 0 < s2 < 1:
            points.insert(1, mpmath.sqrt(s2))
        elif s2 < 0:
            points += [mpmath.sqrt(-s2) * mpmath.mpf(10)**k for k in range(-3, 40) if mpmath.sqrt(-s2) * 10**k < 1]
        elif s2 - 1 < 1:
            points += [1 - (s2 - 1) * mpmath.mpf(10)**k for k in range(40) if (s2 - 1) * 10**k < 1]
    return mpmath.quad(integrand, sorted(set(points)))


def _points(e: int) -> list[tuple[float, float]]:
    """(v, distance from the element relative to its length; 0 inside)."""
    kind, L = int(LAY.kind[e]), LAY.length(e)
    A = LAY.c2 if LAY.anchor[e] == AT_C2 else 1.0
    if kind == PLAIN:
        u_lo, u_hi = A + LAY.lo[e], A + LAY.hi[e]
        out = [(u_lo + L * t, 0.0) for t in (1e-9, 0.3, 0.999999)]
        out += [(u_lo - L * t, t) for t in (1e-10, 0.5)] + [(u_hi + L * t, t) for t in (1e-10, 2.0)]
    elif kind == SLIP_END:
        out = [(A + L * s * s, 0.0) for s in (1e-4, 0.02, 0.5, 0.99)]
        out += [(A - L * t, t) for t in (1e-12, 1e-5, 0.2, 0.5)] + [(A + L * (1 + t), t) for t in (1e-10, 0.1, 1.0, 1.5)]
    else:
        out = [(A - L * s * s, 0.0) for s in (1e-4, 0.02, 0.5, 0.99)]
        out += [(A + L * t, t) for t in (1e-12, 1e-5, 0.2, 0.5)] + [(A - L * (1 + t), t) for t in (1e-10, 0.1, 1.0, 1.5)]
    return [(v, t) for v, t in out if 0.0 < v < 1.0]


SINGULAR_ELEMENTS = [int(e) for e in np.flatnonzero(LAY.kind != PLAIN)] + [int(np.flatnonzero(LAY.kind == PLAIN)[-1])]


@pytest.mark.parametrize("e", SINGULAR_ELEMENTS)
def test_rules_match_mpmath(e):
    """The three singular elements and a plain one at alpha = 0.01, the hardest for the edge weight."""
    _check(e, 0.01)


@pytest.mark.slow
@pytest.mark.parametrize("alpha", [0.01, 0.3, 0.49])
@pytest.mark.parametrize("e", range(len(LAY)))
def test_rules_match_mpmath_everywhere(e, alpha):
    _check(e, alpha)


def _check(e: int, alpha: float) -> None:
    pts = _points(e)
    vs = np.array([v for v, _ in pts])
    anchor = np.array([AT_C2 if abs(v - LAY.c2) < abs(v - 1.0) else AT_ONE for v in vs])
    offset = vs - np.where(anchor == AT_C2, LAY.c2, 1.0)
    mats = AbelOperators(LAY, (anchor, offset), elements=np.array([e])).matrices(alpha)
    cols = slice(int(LAY.starts[e]), int(LAY.starts[e + 1]))
    K, m = int(LAY.degree[e]), int(LAY.n_basis[e])
    columns = [0, K] + ([K + 1, m - 1] if LAY.kind[e] != PLAIN else [])
    with mpmath.workdps(30):
        for upper in (True, False):
            M = mats.of("upper" if upper else "lower")[:, cols]
            for i, (v, distance) in enumerate(pts):
                tol = 1e-10 if 0.0 < distance < 1e-9 else 1e-12
                for j in columns:
                    exact = float(_exact(e, j, mpmath.mpf(v), upper, alpha))
                    assert abs(M[i, j] - exact) <= tol * max(1.0, abs(exact)), (e, v, upper, j, M[i, j], exact)


@pytest.mark.parametrize("degree", [6, 7, 8, 9, 11, 12, 14, 15, 17, 18])  # every level's degree and its partner's
def test_plain_gauss_rule_resolves_the_kernel_beyond_the_near_distance(degree):
    # at the distance where plain elements switch from the exact t-rule to plain Gauss points, the Gauss rule
    # integrates P_k(2t - 1)/sqrt|u - v| to rounding on either side of the element. Its own error there is
    # e^-35 = 6e-16 (``near_plain``); rounding adds the three-term recurrence's ~k eps (k <= 18: 4e-15) and the sum
    # of deg + 7 terms' ~(deg + 7) eps relative to the largest integral: bound 1e-14 (measured 1.8e-15 with
    # numpy 2.4, 3.9e-15 with numpy 1.24, whose Gauss nodes and recurrence round differently)
    xq, wq = gauss01(degree + 1 + EXTRA_NODES)
    P = shifted_legendre(degree, xq)
    delta = near_plain(degree)
    for kernel, kernel_mp in ((lambda t: 1 / np.sqrt(t + delta), lambda t: 1 / mpmath.sqrt(t + delta)),
                              (lambda t: 1 / np.sqrt(1 + delta - t), lambda t: 1 / mpmath.sqrt(1 + delta - t))):
        approx = (wq * kernel(xq)) @ P
        with mpmath.workdps(30):
            exact = np.array([float(mpmath.quad(lambda t: mpmath.legendre(j, 2 * t - 1) * kernel_mp(t), [0, 1]))
                              for j in range(degree + 1)])
        assert np.max(np.abs(approx - exact)) <= 1e-14 * np.max(np.abs(exact))


@pytest.mark.parametrize("n", [12, 40, 60])
def test_christoffel_weights_integrate_monomials_to_rounding(n):
    # christoffel_gauss01 (numeric.core.quadrature): exact for s^k, k < 2n, in exact arithmetic; in double the node's
    # rounding (1/2 ulp relative) enters s^k k-fold and each weight carries a few ulp, so the relative error is at
    # most (k + 8) x 2.2e-16 (measured 1.1e-14 at n = 40, k = 79, where leggauss's weights give 1.3e-13)
    from numeric.core.quadrature import christoffel_gauss01
    s, w = christoffel_gauss01(n)
    k = np.arange(2 * n)
    got = (w[None, :] * s[None, :] ** k[:, None]).sum(axis=1) * (k + 1.0)
    assert np.all(np.abs(got - 1.0) <= (k + 8) * 2.2e-16)
    # against mpmath's weights 2 / ((1 - x^2) P_n'(x)^2) at the same (double) nodes, 40 digits: ~eps / (1 - x) at the
    # end nodes, where the weight's own slope turns the node's rounding into that (measured 4e-15 at n = 40)
    with mpmath.workdps(40):
        x = [mpmath.mpf(2) * mpmath.mpf(float(v)) - 1 for v in s]
        ref = [1 / ((1 - t * t) * (n * (t * mpmath.legendre(n, t) - mpmath.legendre(n - 1, t)) / (t * t - 1)) ** 2)
               for t in x]
    ref = np.array([float(r) for r in ref])
    assert np.all(np.abs(w / ref - 1.0) <= 4.4e-16 / np.minimum(s, 1.0 - s) + 1e-15)


@pytest.mark.parametrize("c, level", [(0.05, 2), (0.5, 0), (0.97, 4), (0.3, 2)])
def test_the_cached_blocks_of_the_elements_at_c_are_the_rules_at_the_points(c, level):
    # at the collocation points, the blocks of the two elements touching c^2 come partly from products formed once per
    # degree: their own points' Legendre block (``self_legendre_block``), the near rule at the other end's first points
    # (``partner_near_rule``, at d = -s^2 of the other end's chart) and the projected Legendre values of the far points
    # (``projected_outside_legendre``). The same points given explicitly take the generic rules (the inside rule, the
    # near rule at d formed from the offsets; checked against mpmath above), contracted there. Every row of both
    # elements' columns agrees to 1.0e-15 of the block's largest entry (measured; 0 at c = 1/2, level 0); bound 4e-15,
    # the rounding of sums of ~250 terms in a different order
    from numeric.core.charts import RESOLUTIONS, collocation
    from numeric.core.operators import partner_near_rule
    lay = layout(c, 1.0 - c, RESOLUTIONS[level])
    before = partner_near_rule.cache_info()
    cached = AbelOperators(lay).matrices(0.2)
    after = partner_near_rule.cache_info()
    assert after.hits + after.misses >= before.hits + before.misses + 4  # both ends' "upper"/"lower" took it
    anchor, offset, _ = collocation(lay)
    generic = AbelOperators(lay, (anchor, offset)).matrices(0.2)
    e = lay.stick_end
    for name in ("upper", "lower", "upper/x", "lower/x"):
        for element in (e, e + 1):
            cols = slice(int(lay.starts[element]), int(lay.starts[element + 1]))
            a, b = cached.of(name)[:, cols], generic.of(name)[:, cols]
            if np.any(b):
                assert np.max(np.abs(a - b)) <= 4e-15 * np.max(np.abs(b)), (name, element)


def test_differenced_upper_rows_are_formed_without_cancellation():
    # (2.2a) is solved as its row at the first collocation point and every other row less that one
    # (``numeric.core.operators.collocation_system``). Far from an element the kernel 1/(2 sqrt(u - v)) barely changes
    # between two points with small v, so the difference of two rows keeps only their rounding: at c = 1e-3 the change
    # is ~1e-6 of the entries, and subtracting the rows would leave it ~1e-10 relative off. ``AbelMatrices.change``
    # forms it from the difference kernel on the same nodes: against the 30-digit difference of the two integrals
    # (tanh-sinh on the element, the points exact in mpmath) within 1e-13 of the element block's largest entry:
    # measured 4.3e-16, where the difference of the two rows is 6.1e-10 off (the kernel is smooth on these elements,
    # where the Gauss rule is at rounding; 1e-13 leaves room for a sum of ~20 terms in any order)
    from numeric.core.charts import EDGE, RESOLUTIONS, collocation
    from numeric.core.operators import REFERENCE
    c, alpha = 1e-3, 0.3
    lay = layout(c, 1.0 - c, RESOLUTIONS[2])
    anchor, offset, x = collocation(lay)
    M = AbelOperators(lay).matrices(alpha)
    ns = lay.n_stick
    rows = [ns - 1, ns + 2, ns + 40]  # the stick point nearest c, slip points just above c and farther out
    far_plain = [e for e in range(len(lay)) if lay.kind[e] == PLAIN and lay.lo[e] + lay.anchor_value(e) > 0.1]
    elements = far_plain[:1] + far_plain[-1:] + [int(np.flatnonzero(lay.kind == EDGE)[0])]

    def point(i):
        return mpmath.mpf(lay.c2 if anchor[i] == AT_C2 else 1.0) + mpmath.mpf(offset[i])

    with mpmath.workdps(30):
        v0 = point(REFERENCE)
        for e in elements:
            A = mpmath.mpf(lay.anchor_value(e))
            lo, L = mpmath.mpf(lay.lo[e]), mpmath.mpf(lay.hi[e] - lay.lo[e])
            K, m = int(lay.degree[e]), int(lay.n_basis[e])
            edge = lay.kind[e] == EDGE
            cols = [0, K] + ([K + 1, m - 1] if edge else [])

            def basis(j, s):
                if not edge:
                    return mpmath.legendre(j, 2 * s - 1)
                k = j if j <= K else j - K - 1
                w = s ** (2 * mpmath.mpf(alpha) - 1) * mpmath.legendre(k, 2 * s - 1)
                return w if j <= K else w * s**2 * mpmath.log(s)

            def u_of(s):
                return A - L * s * s if edge else A + lo + L * s

            jacobian = (lambda s: 2 * L * s) if edge else (lambda s: L)
            for i in rows:
                v = point(i)
                block = M.change[i, int(lay.starts[e]): int(lay.starts[e + 1])]
                for j in cols:
                    exact = mpmath.quad(lambda s: basis(j, s) * jacobian(s) * (
                        1 / (2 * mpmath.sqrt(u_of(s) - v)) - 1 / (2 * mpmath.sqrt(u_of(s) - v0))), [0, 1])
                    assert abs(block[j] - float(exact)) <= 1e-13 * np.max(np.abs(block)), (e, i, j, block[j], exact)


@pytest.mark.parametrize("c, level", [(1e-3, 2), (0.5, 0), (0.5, 2), (0.97, 4)])
def test_the_system_is_assembled_from_the_fixed_integrals_and_the_varying_columns(c, level):
    # ``collocation_system`` reads the integrals that do not depend on alpha where they lie (``AbelOperators.fixed``)
    # and puts the assembled columns that do (``varying``) in their places, instead of assembling a copy of the whole
    # integrals (``matrices``). That is exact if the fixed integrals are 0 in the varying columns, ``matrices`` is the
    # two together, and every column of the system depends on its own basis column only, the same at every alpha
    # outside the varying ones: checked to the last bit (no tolerance: the same operations on the same numbers)
    from numeric.core.charts import RESOLUTIONS
    from numeric.core.operators import collocation_system
    ops = AbelOperators(layout(c, 1.0 - c, RESOLUTIONS[level]))
    fixed = ops.fixed
    ns = ops.layout.n_stick
    systems = {}
    for alpha in (0.3, 0.4):  # both above AXISYMMETRIC_PIN_FROM: the same rows pinned
        varying = ops.varying(alpha)
        whole = ops.matrices(alpha)
        outside = np.setdiff1d(np.arange(int(ops.layout.starts[-1])), varying.columns)
        for name in ("upper", "lower", "upper/x", "lower/x", "change", "integral", "integral/x"):
            assert not np.any(fixed.of(name)[..., varying.columns])
            assert np.array_equal(whole.of(name)[..., varying.columns], varying.matrices.of(name))
            assert np.array_equal(whole.of(name)[..., outside], fixed.of(name)[..., outside])
        systems[alpha] = collocation_system(ops, 0.4, alpha)
    cs, cl = varying.columns[varying.columns < ns], varying.columns[varying.columns >= ns] - ns
    keep_stick = np.setdiff1d(np.arange(2 * ns), np.concatenate([cs, ns + cs]))
    keep_slip = np.setdiff1d(np.arange(ops.x.size - ns), cl)
    a, b = systems[0.3], systems[0.4]
    assert np.array_equal(a.stick[:, keep_stick], b.stick[:, keep_stick])
    assert np.array_equal(a.normal[:, keep_slip], b.normal[:, keep_slip])
    assert np.array_equal(a.shear[:, keep_slip], b.shear[:, keep_slip])
    assert not np.array_equal(a.normal[:, cl], b.normal[:, cl])
