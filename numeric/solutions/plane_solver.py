"""The solver route of ``numeric.plane``: the plane singular-basis solver at its levels, with an error estimate.

Each level is a ``PlaneResolution`` (``PLANE_LEVELS``); ``error`` is the difference between the level and
the same problem one polynomial degree lower (``plane_partner``; its root from one evaluation of its eigen
functional at the level's root, over the level's slope), at least ``ROUNDING_FLOOR`` times the
value (the scatter of mu between degrees 20 ... 28, where the discretisation error is far below it,
measured: 1e-12 ... 7e-11 relative over nu in [-1/2, 0.3], c in [0.05, 0.99]), and at least theta's
rounding scatter ``theta_rounding`` turned into mu or c. On the plain system that scatter was absolute in theta, and
as nu -> 1/2 (theta ~ gamma^2) it limited mu's relative accuracy (2.6e-10 ... 1.3e-7 at nu = 0.47 ... 0.499); on the
balanced system (``numeric.core.plane_operators.plane_collocation_system``) it is relative: measured against the
small-gamma series through level-3 nodes (``numeric.solutions.plane_small_gamma``, an independent route from solves
at gamma >= 0.06) at nu = 0.45 ... 0.489, c = 0.05, 0.3, 0.5, 0.9, 0.97, level 2 is within 9.7e-11 (c = 0.05) and
2.2e-11 (c >= 0.3), where the plain system was up to 3.4e-9 off (nu = 0.489, c = 0.05).

The estimate is a solve at the partner resolution, so it is formed when ``error`` is first read
(``numeric.solutions.solution.DeferredError``).

Given c: Newton in theta = atan(mu gamma) on the system linearised in the basis exponent
(``numeric.core.plane_eigenvalue.plane_given_c_linearised``) from the guess table (``numeric.core.plane_guess``,
~1e-9: one round of two assemblies and an LU or two); where the table does not reach, or that does not settle, the
careful Newton of ``plane_given_c`` from the table's guess or the first-order law mu/gamma = K(c)/K'(c) of
``asymptotics.plane``. Given mu, where the table reaches: given-c solves from its c, stepped in logit c by its
d theta / d logit c (``numeric.core.eigenvalue.guided_steps``, the axisymmetric solver's; two solves, the table's c
being good to ~1e-9); elsewhere the secant method in logit(c) at theta = atan(mu gamma) from the first-order law's c
(kept below the largest stick width). mu -> inf: the limit problem theta = pi/2, whose root is the largest stick
width c_max, solved where 1 - c_max >= 2^-40 (``limit_resolved``; below, the callers take 1 - c_max from the limit
problem's small-gamma form, ``numeric.core.plane_guess.gap_max``). Next to c = 1 toward gamma = 0 the first-order
law, to ``FIRST_ORDER_R_MAX`` gamma^2 relative, answers below ``FIRST_ORDER_GAMMA`` (the solver's mu is not measured to
hold there) and, from the callers, wherever that bound meets the caller's rtol.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

from asymptotics.plane import stick_width_first_order

from numeric.core.eigenvalue import guided_steps
from numeric.core.errors import NoEigenvalueError, SolverError
from numeric.core.plane_charts import PlaneResolution, plane_partner
from numeric.core.plane_eigenvalue import (PlaneEigensolution, partner_shift_theta, partner_shift_xi, plane_at_theta,
                                           plane_given_c, plane_given_c_linearised, plane_given_theta, theta_rounding)
from numeric.core.plane_fields import PlaneField
from numeric.core.plane_guess import elliptic_ratio, gap_max, gap_max_small_gamma, stick_width_guess, theta_guess
from numeric.core.plane_guess_data import ERRORS as GUESS_ERRORS, GAMMA_N, GAP_N as GUESS_GAP_N
from numeric.solutions.solution import DeferredError

__all__ = ["PLANE_LEVELS", "DEFAULT_LEVEL", "ROUNDING_FLOOR", "PlaneSolve", "solve_given_c", "solve_given_mu",
           "near_full_stick_gap", "FULL_STICK_GAP", "full_stick_friction", "beyond_table_toward_full_stick",
           "solve_limit", "limit_resolved", "FIRST_ORDER_R_MAX", "FIRST_ORDER_GAMMA", "C_SMALLEST", "C_SMALLEST_SLACK",
           "LIMIT_MU_GAMMA", "LIMIT_APPROACH", "THETA_SCATTER"]

#: Levels 0-4 (degree 12, 15, 18, 21, 24; h_beta times quadratics at c). Measured at five (nu, c) (nu = 0.25, 0.3,
#: 0.45; c = 0.05 ... 0.65) against the median of degrees 26 and 28 in two layouts (``numeric.studies.plane_bench``):
#: mu to 2e-9 ... 7e-7, 7e-11 ... 1e-9, 8e-14 ... 1e-11, 1e-13 ... 6e-12 and 6e-13 ... 5e-10 relative; level 4's layout
#: meets a pole of G near the root at nu = 0.25 (5e-10, its estimate 5e-10), where the route now takes the alternate
#: layout (``CONDITION_LIMIT``; 4e-13). ``tests/test_plane.py`` checks the default
#: level against six solves of degrees 20-28 and the levels' table is in ``derivations/plane_strain.md``.
PLANE_LEVELS: tuple[PlaneResolution, ...] = tuple(PlaneResolution(degree=d, singular_degree=2) for d in (12, 15, 18, 21, 24))
DEFAULT_LEVEL = 2
#: Relative floor of the error estimate: the rounding level of the eigenvalue (see the module docstring).
ROUNDING_FLOOR = 1e-10
HALF_PI = 0.5 * math.pi


@dataclass(frozen=True, slots=True)
class PlaneSolve:
    """A solver result: the level's field and the estimated absolute error of mu (given c) or c (given mu, or of
    1 - c_max at mu = inf)."""

    field: PlaneField
    error: float | DeferredError
    level: int
    gap_limit: float = math.nan  # 1 - c_max where the limit mu -> inf was extrapolated
    near: tuple[tuple[float, float, PlaneField], ...] = ()  # the limit's solves: (mu gamma, 1 - c, field)


def _mu(theta: float, gamma: float) -> float:
    return math.inf if theta >= HALF_PI else math.tan(theta) / gamma


#: The guess table's accuracy in theta, relative (its worst held-out error in mu, at least 1e-9): the linearised
#: iteration's first difference step spans it.
GUESS_SPREAD = max(1e-9, *(GUESS_ERRORS or {"": 1e-3}).values())


#: A layout whose system is ill-conditioned at its root beyond this (gamma^2 times the 1-norm condition number of the
#: equilibrated D, ``PlaneEigensolution.conditioning``) where c >= ``CONDITION_CHECK_C`` and 1 - c >=
#: ``CONDITION_CHECK_GAP`` is solved again in the layout with ``ALTERNATE_C_FRACTION``, and the better conditioned of
#: the two kept (if better by ``CONDITION_GAIN``). The discrete system is singular at isolated theta (poles of G);
#: where one lies near the root the root loses digits. Conditioning also grows like gamma^-2 as the coupling weakens
#: (8e10, 1.1e12, 2.6e12, 5.5e12 at c = 0.5, nu = -1/2, 0, 1/4, 0.45, all good to 1e-11), hence the factor. Measured
#: at level 2 over 75 random (nu, c) with 1e-3 < c < c_max and at nu = -1/2, 0.9 <= c <= 0.935: gamma^2 x conditioning
#: up to 7e11 where mu is within 2e-11 of the median of four finer solves; 1.5e12 ... 8e14 where it is off by 3e-10
#: ... 4e-8 (nu = -1/2, c = 0.91 ... 0.935; nu = -0.008, c = 0.17), where the layout with c_fraction 0.1 is 5 ... 25
#: times better conditioned and brings mu within 6e-12. Below 1 - c = 1e-3 conditioning grows for every layout (1e13
#: ... 1e16 at 1 - c = 1e-4 ... 1e-9), and below c = 1e-2 too (1e12 ... 1e14 at c = 3e-3 ... 1e-3, the round-off
#: that grows like 1/c): there it is not a signal. The poles at nu = -1/2, c = 0.91 ... 0.935 (alpha = 0.41 ... 0.48)
#: were the stick pressure's free singular family: pinned from alpha = 0.04 on (``numeric.core.plane_operators``) the
#: default layout is within 1e-15 of the reference there. Below the family stays free and such poles remain; over
#: 19 x 23 (nu, c) in [-0.6, 0.3] x [0.05, 0.6] the route took the alternate at 1 (nu = 0, c = 0.05; at 3 while the
#: family was free up to alpha = 1/4, nu = -0.008, c = 0.17 among them). These figures are the plain system's: balanced
#: (``numeric.core.plane_operators.plane_collocation_system``) the condition number no longer grows like gamma^-2
#: (median 5.5e9 against 5.9e10 over 22 x 12 (nu, c) in [-0.6, 0.45] x [0.05, 0.6], gamma^2 x conditioning at most
#: 9.5e11, mu within 6.4e-11 of the finer solves everywhere there) and the route took the alternate nowhere on that grid;
#: the check stays, for poles elsewhere.
CONDITION_LIMIT = 1e12
CONDITION_CHECK_GAP = 1e-3
CONDITION_CHECK_C = 1e-2
ALTERNATE_C_FRACTION = 0.1
CONDITION_GAIN = 3.0


def _given_c(c: float, gap: float, gamma: float, res: PlaneResolution, theta: float | None = None
             ) -> PlaneEigensolution:
    """The given-c solve from ``theta`` (else the table's guess) in the layout of ``res``, or, where that one is near a
    pole of G (``CONDITION_LIMIT``), in the alternate layout if it is better conditioned; the solution's layout says
    which (``layout.resolution``)."""
    solution = _solve_in(c, gap, gamma, res, theta)
    if (res.c_fraction != ALTERNATE_C_FRACTION and c >= CONDITION_CHECK_C and gap >= CONDITION_CHECK_GAP
            and gamma * gamma * solution.conditioning > CONDITION_LIMIT):
        other = _solve_in(c, gap, gamma, replace(res, c_fraction=ALTERNATE_C_FRACTION), solution.theta)
        if other.conditioning * CONDITION_GAIN < solution.conditioning:
            return other
    return solution


def _solve_in(c: float, gap: float, gamma: float, res: PlaneResolution, theta: float | None) -> PlaneEigensolution:
    """The given-c solve at ``res`` from ``theta`` (else the table's guess): linearised Newton, else the careful
    iteration from that start, else from the first-order law (the careful Newton started within ~1e-12 of the root can
    end jittering at its rounding floor without settling)."""
    # just below the table's smallest c (C_SMALLEST_SLACK), its theta there: the first-order law is 3 % off at
    # gamma = 0.18, c = 1e-5, and Newton from it did not settle
    guess = theta_guess(c, gap, gamma) if c >= C_SMALLEST else theta_guess(C_SMALLEST, 1.0 - C_SMALLEST, gamma)
    if theta is None and guess is not None:
        theta = guess.theta
    first_order = math.atan(gamma * gamma / elliptic_ratio(c, gap))
    if theta is not None:
        try:
            return plane_given_c_linearised(c, gap, gamma, theta, res, GUESS_SPREAD)
        except SolverError:
            try:
                return plane_given_c(c, gap, gamma, theta, res)
            except SolverError:
                pass
    return plane_given_c(c, gap, gamma, first_order, res)


def solve_given_c(c: float, gap: float, gamma: float, level: int) -> PlaneSolve:
    """mu for stick half-width c = 1 - gap at ``level``; the error (formed when first read) is the shift of mu to the
    partner resolution (one degree lower), from one evaluation of its eigen functional (``partner_shift_theta``).
    ValueError below ``C_SMALLEST`` (less ``C_SMALLEST_SLACK``)."""
    if c < C_SOLVED_MIN:
        raise ValueError(f"c = {c!r} is below {C_SMALLEST:g}, outside the solver's range (first-order law: "
                         "mu/gamma = K(c)/K'(c))")
    res = PLANE_LEVELS[level]
    solution = _given_c(c, gap, gamma, res)
    fine = PlaneField(solution)

    def estimate() -> float:
        shift = partner_shift_theta(c, gap, gamma, solution, plane_partner(solution.layout.resolution))
        t = fine.theta
        rounding = fine.mu * theta_rounding(c, t) / (math.sin(t) * math.cos(t))  # d mu / mu = d theta / (sin cos)
        return max(abs(_mu(t + shift, gamma) - fine.mu), ROUNDING_FLOOR * fine.mu, rounding)

    return PlaneSolve(fine, DeferredError(estimate), level)


#: A/(1 - c_max) of the approach to c_max, 1 - c = (1 - c_max) (1 + A/(mu gamma)) (measured ~1.4, ``LIMIT_MU_GAMMA``):
#: the start of the secant in c where mu lies beyond the guess table and c_max within reach.
LIMIT_APPROACH = 1.4

#: mu gamma of the two solves the limit mu -> inf is extrapolated from: 1 - c = (1 - c_max) + A/(mu gamma) + O(mu^-2),
#: A ~ 1.4 (1 - c_max) (measured), so linear extrapolation from 1e5 and 1e6 leaves ~1e-11 (1 - c_max)
LIMIT_MU_GAMMA = (1e5, 1e6)


def limit_resolved(gamma: float) -> bool:
    """Whether the limit mu -> inf is solved (``solve_limit``): its slip zones, 1 - c_max (``gap_max``), are at least
    ``FULL_STICK_GAP`` wide (gamma above ~0.157, nu below ~0.407). Below, the layout down to them costs without
    bound (at nu = 0.45, 1 - c_max = 1e-20: 30 s; at 0.47, 1e-29: 150 s and 1.6 GB; at 0.499 1 - c_max underflows),
    c_max is 1 to within 9.1e-13 and the bonded punch's stresses are within the solver's accuracy of the limit's (as
    ``full_stick_friction`` measured): the answer is the closed form with 1 - c_max from ``gap_max``."""
    return gap_max(gamma) >= FULL_STICK_GAP


@lru_cache(maxsize=16)
def solve_limit(gamma: float, level: int) -> PlaneSolve:
    """The limit mu -> inf (slip zones without pressure) at ``level``: c = c_max, extrapolated linearly in 1/(mu gamma)
    from ``LIMIT_MU_GAMMA`` (at mu = inf itself the generic mode degenerates); error in 1 - c_max: the partner's
    shift at the larger mu gamma, or the extrapolation's neglected O(mu^-2) term if larger. Against the limit problem
    solved at theta = pi/2 where that works (nu = 0, -1/2): 2e-13, 1e-13 absolute in 1 - c_max. The two solves are
    kept (``near``) for friction beyond ``LIMIT_MU_GAMMA[1]``; the result is cached per gamma and level. The public
    routes call it only where ``limit_resolved``: below, its cost grows without bound (10-15 s at gamma = 0.13 ...
    0.15, where it still converges; SolverError at 0.12)."""
    res = PLANE_LEVELS[level]
    gap = gap_max_small_gamma(gamma)  # the start: not the guess table's series, which the table's build computes here
    xi = math.log1p(-gap) - math.log(gap)
    gaps, fields = [], []
    for mg in LIMIT_MU_GAMMA:
        solution = plane_given_theta(math.atan(mg), gamma, xi, res, step=0.01)
        xi = math.log(solution.layout.c) - math.log(solution.layout.gap)
        fields.append(PlaneField(solution))
        gaps.append(solution.layout.gap)
    m1, m2 = LIMIT_MU_GAMMA
    gap_limit = gaps[1] - (gaps[0] - gaps[1]) * m1 / (m2 - m1)
    fine = fields[1]
    partner = _gap_error(fine, partner_shift_xi(math.atan(m2), gamma, solution, plane_partner(res)))
    # the neglected B/(m1 m2) of the extrapolation: B ~ A^2/(1 - c_max), i.e. ~ (gaps[0] - gaps[1])^2/(1 - c_max)
    return PlaneSolve(fine, max(partner, (gaps[0] - gaps[1]) ** 2 / gap_limit), level, gap_limit,
                      tuple(zip(LIMIT_MU_GAMMA, gaps, fields)))


def near_full_stick_gap(mu: float, gamma: float, mu_full: float, gap_full: float) -> float | None:
    """1 - c for mu between the guess table's end toward full stick (1 - c = GAP_N, small gamma) and a solve at
    (mu_full, gap_full) nearer full stick: log(1 - c) interpolated linearly in log mu (near full stick 1 - c falls
    like a power of mu: at nu = 0.45 log10(1 - c) = -7.17, -9.18, -10.83, -12.04 at mu = 0.6, 0.8, 1.0, 1.18, slopes
    -6.9, -7.5, -7.4 in log10 mu); None where mu is not between them or the table gives no end value."""
    guess = theta_guess(1.0 - GUESS_GAP_N, GUESS_GAP_N, gamma)
    if guess is None:
        return None
    mu_end = math.tan(guess.theta) / gamma
    if not mu_end < mu < mu_full:
        return None
    t = (math.log(mu) - math.log(mu_end)) / (math.log(mu_full) - math.log(mu_end))
    return math.exp(math.log(GUESS_GAP_N) + t * (math.log(gap_full) - math.log(GUESS_GAP_N)))


def _gap_error(fine: PlaneField, shift: float) -> float:
    """|change of 1 - c| for a change ``shift`` of logit c (d(1 - c) = -c (1 - c) d xi), at least the rounding floor."""
    return max(abs(fine.c * fine.gap * shift), ROUNDING_FLOOR * min(fine.c, fine.gap))


#: Relative scatter of a given-c solve's theta (its rounding floor): measured 2e-11 ... 3e-11 over starts 1e-8 ... 1e-3
#: away and one or two BLAS threads (nu = 0.45, c = 0.999; 5e-12 at nu = 0.3, c = 0.5), with a margin of 2. Given mu,
#: the steps in logit c stop once theta is within it: a smaller step would move c by noise.
THETA_SCATTER = 5e-11

#: Stick widths below this are not solved for (the layout needs ~40 elements at 1e-5, and round-off grows like 1/c).
C_SMALLEST = 1e-5
#: Given mu at the hand-over to the law below C_SMALLEST (mu at least the law's, i.e. the solver's, mu at C_SMALLEST),
#: the given-c solves may land below C_SMALLEST by the rounding of the steps toward it (6e-9 relative measured at
#: nu = 0.49): they are solved down to C_SMALLEST (1 - C_SMALLEST_SLACK).
C_SMALLEST_SLACK = 1e-6
#: The least stick half-width solved for: C_SMALLEST less its slack.
C_SOLVED_MIN = (1.0 - C_SMALLEST_SLACK) * C_SMALLEST


#: Given mu, 1 - c below this (2^-40 = 9.1e-13: c = 1 - 2^-40 is a double and gives this gap back exactly) is
#: answered as full stick (the stresses of the bonded punch were measured within 3.3e-12 (p) and 3.8e-12 (q) of the
#: solver's at 1 - c = 1e-12, nu = 0.45; the solver itself took seconds below it and failed further down, where c is
#: 1 to double precision).
FULL_STICK_GAP = 2.0**-40


#: |r| = |mu/mu_1 - 1|/gamma^2 (mu_1 = gamma K(c)/K'(c), the first-order law) is below this for every c from 1e-5 to
#: 1 - 2^-53 at gamma <= 0.01: measured with the solver at gamma = 0.002, 0.005, 0.01, r = 2.0, 4.8, 9.0, 14.7, 21.8,
#: 30.3, 40.3, 49.6 at 1 - c = 1e-2, 1e-4, ..., 1e-14, 2.2e-16 (r grows like log(1/(1 - c))^2 toward c = 1; 0.55 at
#: c = 0.5; it changes by 3000 gamma^2 at 1 - c = 2.2e-16), so the first-order law's relative error in mu is at most
#: FIRST_ORDER_R_MAX gamma^2.
FIRST_ORDER_R_MAX = 60.0
#: Below this gamma the first-order law's mu (error FIRST_ORDER_R_MAX gamma^2, relative: 5.4e-8 here) is taken next to
#: c = 1, whatever the level or rtol: the solver's mu there is not measured to hold. Measured with the system as it is
#: now (balanced below alpha = 1/4, the stick pressure pinned from alpha = 0.04), at gamma = 3e-5, 5e-5, 1e-4, 1.5e-4
#: and 1 - c = 1e-9, 1e-10, 1e-12, 1e-14, 1e-16 levels 2 and 3 lie within 3.1e-11 of level 4 in mu, and r = (mu/mu_1 -
#: 1)/gamma^2 of levels 2 and 3 within 1e-2 of its value at larger gamma (30.3124 at 1 - c = 1e-12: mu within ~1e-12);
#: at gamma = 1e-5 level 4 loses it (r 33.6 against 30.33). From here up the solver answers (0.3 ... 0.6 s given c,
#: 1 ... 2 s given mu: 1400-2000 unknowns), unless rtol is met by the law's bound (``numeric.solutions.plane_punch``).
#: (Until the rtol route could choose the law this limit stood at 1.7e-4, for speed; a measurement on the earlier
#: balanced system, r of levels 1-3 against 30.31, had the solver's mu 2.7e-9 ... 6.4e-7 off at gamma = 3e-4 ... 1e-5.)
FIRST_ORDER_GAMMA = 3e-5


@lru_cache(maxsize=64)
def full_stick_friction(gamma: float, level: int = DEFAULT_LEVEL, law: bool = False) -> float:
    """mu at 1 - c = ``FULL_STICK_GAP`` (a given-c solve, 0.5-1.5 s, kept per gamma and level): from there on the stick
    zone fills the contact to within 9.1e-13. With ``law`` or below ``FIRST_ORDER_GAMMA`` the first-order law's mu
    there raised by its bound, (1 + ``FIRST_ORDER_R_MAX`` gamma^2) times it: mu/mu_1 - 1 = r gamma^2 with 0 < r <= 60,
    so beyond it the stick zone surely fills the contact (the law's own mu there was 1.2 % below the solver's at
    nu = 0.49, and friction between the two had been called full stick with 1 - c up to 1.24e-12). Only where c_max
    lies above 1 - ``FULL_STICK_GAP`` (the limit is not resolved, ``limit_resolved``; else ValueError: no friction
    reaches it)."""
    if not 0.0 < gamma or limit_resolved(gamma):
        raise ValueError(f"gamma = {gamma!r}: the full-stick friction is defined only where 1 - c_max < "
                         f"{FULL_STICK_GAP:.3g} (gamma below ~0.157)")
    if law or gamma < FIRST_ORDER_GAMMA:
        return gamma / elliptic_ratio(1.0 - FULL_STICK_GAP, FULL_STICK_GAP) * (1.0 + FIRST_ORDER_R_MAX * gamma * gamma)
    return solve_given_c(1.0 - FULL_STICK_GAP, FULL_STICK_GAP, gamma, level).field.mu


def beyond_table_toward_full_stick(mu: float, gamma: float) -> bool:
    """Whether mu lies beyond the guess table toward full stick (small gamma only)."""
    if gamma >= GAMMA_N or float(stick_width_first_order(mu, gamma)) < 0.5:
        return False
    return stick_width_guess(math.atan(mu * gamma), gamma) is None


def solve_given_mu(mu: float, gamma: float, level: int) -> PlaneSolve:
    """The stick half-width for friction mu at ``level``: where the table reaches, given-c solves from its c
    (``guided_steps``; the error: the partner's theta at the last c, turned into c by the slope, plus the step not
    taken), else the secant in logit c (the error: the partner's G over the secant's slope); formed when first read.
    Between the table's end toward full stick and ``full_stick_friction`` (small gamma) the secant starts from
    ``near_full_stick_gap``. ValueError where the guess puts c below ``C_SMALLEST``."""
    res = PLANE_LEVELS[level]
    theta = math.atan(mu * gamma)
    found = stick_width_guess(theta, gamma)
    if found is not None and found[0] >= C_SOLVED_MIN:
        c, gap, guess = found
        layout = [res]  # the steps stay in the layout the first solve chose (a pole of G near one step is near all)

        def step(c: float, gap: float) -> PlaneEigensolution:
            solution = _given_c(c, gap, gamma, layout[0], theta)
            layout[0] = solution.layout.resolution
            return solution

        try:
            last, slope, remaining = guided_steps(theta, c, gap, guess.slope, step, lambda s: s.theta,
                                                  theta_noise=max(THETA_SCATTER * theta, theta_rounding(c, theta)))
        except SolverError:
            last = None
        if last is not None:
            solution = plane_at_theta(last, theta)
            fine = PlaneField(solution)

            def estimate() -> float:
                lay = solution.layout
                shift = partner_shift_theta(lay.c, lay.gap, gamma, last, plane_partner(lay.resolution))
                return _gap_error(fine, (abs(shift) + theta_rounding(lay.c, theta)) / abs(slope) + remaining)

            return PlaneSolve(fine, DeferredError(estimate), level)
    c = float(stick_width_first_order(mu, gamma)) if found is None else found[0]
    if c < C_SOLVED_MIN:
        raise ValueError(f"mu = {mu:.6g} is too small at gamma = {gamma:.6g}: the stick half-width c ~ {c:.2g} lies "
                         f"below {C_SMALLEST:g}, outside the solver's range (first-order law: c ~ 4 exp(-pi gamma/(2 mu)))")
    largest = gap_max(gamma)
    gap = max(1.0 - c, 2.0 * largest)
    if found is None and beyond_table_toward_full_stick(mu, gamma):
        if limit_resolved(gamma):  # c_max is within reach (gamma just below GAMMA_N): start from the approach to it
            gap = max(1.0 - c, largest * (1.0 + LIMIT_APPROACH / (mu * gamma)))
        else:
            between = near_full_stick_gap(mu, gamma, full_stick_friction(gamma, level), FULL_STICK_GAP)
            gap = gap if between is None else between
    c = min(c, 1.0 - gap)
    xi = math.log(c) - math.log(gap) if c < 0.5 else math.log1p(-gap) - math.log(gap)
    solution = plane_given_theta(theta, gamma, xi, res, step=1e-3)
    fine = PlaneField(solution)
    if not 0.0 < fine.c < 1.0:
        raise NoEigenvalueError(f"no stick width found for mu = {mu}, gamma = {gamma}")
    return PlaneSolve(fine, DeferredError(lambda: _gap_error(fine, partner_shift_xi(theta, gamma, solution,
                                                                                      plane_partner(res)))), level)
