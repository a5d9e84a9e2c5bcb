"""The asymptotic expansions of [S75] §2.3 checked against the full solution, with observed orders.

Each check compares a closed form of ``asymptotics.first_order`` (or
``asymptotics.second_order``, ``asymptotics.adhesive``) with the full solution of
``numeric.flat_punch`` over Poisson's ratios from nu = 0.49 (gamma = 0.0196) to nu = -1/2
(gamma = 2/3), and fits the order in gamma from log-log slopes between neighbouring gammas
(``observed_orders``). The fields of ``ExpansionStudy``, each a tuple of frozen rows:

    friction_law          mu/gamma = f0(c)                      (2.28)   expect O(gamma^2)
                          mu/gamma = f0 + gamma^2 f2            (beyond) expect O(gamma^4)
    small_mu              c ~ 4 exp(-gamma/mu)                  (2.29)   mu -> 0
    large_mu              1 - c ~ 2 exp(-pi mu/gamma)           (2.29)   mu -> inf
    largest_stick(_estimates)  mu(c) near the largest stick radius c_max(gamma) < 1
    stick_shear           q/(mu p) = 1 - psi(x, c) on (0, c)    (2.31)   expect O(gamma^2)
    compliance            P* = 1 + gamma int (1 - sqrt(1-t^2)) q^(0)   (2.34)  expect O(gamma^4)
    adhesive_compliance   P* = 1 + gamma^2/3                    (2.36)   expect O(gamma^4)

The second-order columns (``asymptotics.second_order``) are filled only once that module's
generated table exists (its quadratures take seconds a point); until then they are None.

``expansion_study(fast)`` runs them all and ``expansion_errors`` reduces them to the worst
error at each gamma; ``numeric.studies.expansion_report`` renders them as deterministic
Markdown for ``derivations/section_2_3.md`` and as the log-log figure "error against gamma". ``fast=True`` uses
the Chebyshev table (``numeric.core.table``, mu to 7e-12 relative, P* to 5e-14) for mu and
P*, level-2 solutions for the stresses and no solves near c_max (seconds); ``fast=False``
solves everything at level 3 (1e-11) and adds c = 1e-4, 1 - c down to 1e-6 and the c_max
study (minutes).

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from asymptotics.adhesive import compliance_adhesive
from asymptotics.arrays import read_only
from asymptotics.first_order import (
    c_large_mu,
    c_small_mu,
    compliance_first_order,
    mu_over_gamma,
    shear_ratio_first_order,
)
from asymptotics.largest_stick_radius import largest_stick_radius_gap
from asymptotics.materials import gamma_from_nu, kappa_from_gamma
from asymptotics.second_order import compliance_second_order, mu_over_gamma_second_order

from numeric.core.table import table_compliance
from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.slip_limit import slip_limit, stick_radius_approach
from numeric.solutions.solution import FlatPunchSolution
from numeric.solutions.sweep import friction_coefficient

__all__ = [
    "NUS",
    "C_VALUES",
    "FrictionLawRow",
    "SmallMuRow",
    "LargeMuRow",
    "LargestStickRow",
    "LargestStickEstimate",
    "largest_stick_rows",
    "StickShearRow",
    "ComplianceRow",
    "AdhesiveComplianceRow",
    "OrderRow",
    "ExpansionStudy",
    "ExpansionErrors",
    "expansion_study",
    "observed_orders",
    "expansion_errors",
]

#: Poisson's ratios of the study: gamma = (1 - 2 nu)/(2 - 2 nu) from 0.0196 to 2/3 (2.2)
NUS = (0.49, 0.45, 0.4, 0.3, 0.2, 0.1, 0.0, -0.25, -0.5)
#: stick radii of the study
C_VALUES = (0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95)
_STRESS_NUS_FAST = (0.49, 0.45, 0.4, 0.0)
_STRESS_CS_FAST = (0.3, 0.7)
_SMALL_MU_NUS = (0.49, 0.45, 0.3, 0.0, -0.5)
_LARGE_MU_NUS = (0.49, 0.45, 0.4, 0.3)
# 1 - c_max(gamma) measured once with flat_punch(gamma=..., mu=1000) at level 2 (1.7e-2,
# 1.0e-3, 7.0e-5, 5.3e-6, 4.1e-7 for gamma = 2/3, 1/2, 0.4, 1/3, 2/7): only used to place the
# the largest stick radius: gammas of the limit problem, and 1 - c = (1 - c_max) * _CMAX_FACTORS for mu(c)
_CMAX_GAMMAS = (0.75, 2.0 / 3.0, 0.5, 0.4, 1.0 / 3.0, 2.0 / 7.0)
_CMAX_FACTORS = (2.0, 1.5, 1.2, 1.1, 1.05)


@dataclass(frozen=True, slots=True)
class OrderRow:
    """Observed order of one approximation at fixed c: log-log slopes of |error| against gamma.

    ``slopes[k]`` is the slope between the k-th and (k+1)-th smallest gamma of ``gammas``.
    """

    quantity: str
    c: float
    gammas: tuple[float, ...]
    slopes: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class FrictionLawRow:
    """(2.28) at one (nu, c): full mu against gamma f0(c) and gamma (f0 + gamma^2 f2).

    ``relative_error`` = (gamma f0 - mu)/mu, ``scaled`` = that / gamma^2;
    ``relative_error_second`` = (gamma (f0 + gamma^2 f2) - mu)/mu, ``scaled_second`` = / gamma^4
    (None while ``asymptotics.second_order`` has no generated table).
    """

    nu: float
    gamma: float
    c: float
    mu: float
    relative_error: float
    scaled: float
    relative_error_second: float | None
    scaled_second: float | None


@dataclass(frozen=True, slots=True)
class SmallMuRow:
    """(2.29), mu -> 0, at one (nu, c): c from 4 exp(-gamma/mu), from ``c_small_mu`` (three
    correction terms, i.e. the inverse of the first-order law (2.28)), and the exponent.

    ``relative_error_leading`` = c_(2.29)/c - 1 with mu the full solution's friction;
    ``relative_error_series`` the same for ``c_small_mu(mu, gamma, terms=4)``;
    ``exponent_defect`` = mu log(4/c)/gamma - 1 (0 if c = 4 exp(-gamma/mu) held exactly).
    """

    nu: float
    gamma: float
    c: float
    mu: float
    relative_error_leading: float
    relative_error_series: float
    exponent_defect: float


@dataclass(frozen=True, slots=True)
class LargeMuRow:
    """(2.29), mu -> inf, at one (nu, c): 1 - c from 2 exp(-pi mu/gamma) and from ``c_large_mu``.

    ``relative_error_leading`` = (1 - c)_(2.29)/(1 - c) - 1; ``relative_error_series`` the same
    for ``c_large_mu(mu, gamma, terms=4)``; ``exponent_defect`` = pi mu/(gamma log(2/(1 - c))) - 1;
    ``law_scaled`` = (mu - gamma f0(c))/(mu (gamma f0(c))^2), the error of (2.28) over the square of
    its own mu: the gamma^2 term of (2.28) grows like f0^2 as c -> 1, not like a constant;
    ``compliance_coefficient`` = (P* - 1)/gamma^2 of the full solution, to set beside 1/3 (2.36).
    """

    nu: float
    gamma: float
    one_minus_c: float
    mu: float
    relative_error_leading: float
    relative_error_series: float
    exponent_defect: float
    law_scaled: float
    compliance_coefficient: float


@dataclass(frozen=True, slots=True)
class LargestStickRow:
    """mu(c) of the full solution close to the largest stick radius, at one (gamma, c)."""

    gamma: float
    one_minus_c: float
    mu: float
    error: float


@dataclass(frozen=True, slots=True)
class LargestStickEstimate:
    """c_max(gamma) from the limit problem mu -> inf (``numeric.slip_limit``) against the closed form
    K'(c_max)/K(c_max) = kappa (``asymptotics.largest_stick_radius``); ``ratio`` = (1 - c_max) exp(pi/kappa)
    (-> 8 as gamma -> 0); ``approach`` = A/(1 - c_max), (1 - c) - (1 - c_max) ~ A/(mu gamma)."""

    gamma: float
    kappa: float
    one_minus_c_max: float
    closed_form_difference: float  # relative, in 1 - c_max
    ratio: float
    approach: float


@dataclass(frozen=True, slots=True)
class StickShearRow:
    """(2.31) at one (nu, c): max over the stick zone of |q/(mu p) - (1 - psi)|, and where."""

    nu: float
    gamma: float
    c: float
    max_difference: float
    x_at_max: float
    scaled: float


@dataclass(frozen=True, slots=True)
class ComplianceRow:
    """(2.34) at one (nu, c): error of the first-order P* (and of the second-order one).

    ``error`` = P*_(2.34) - P*, ``scaled`` = error/gamma^4, ``coefficient`` = (P* - 1)/gamma^2;
    ``error_second`` = 1 + gamma^2 P2 + gamma^4 P4 - P*, ``scaled_second`` = that / gamma^6
    (None while ``asymptotics.second_order`` has no generated table).
    """

    nu: float
    gamma: float
    c: float
    compliance: float
    error: float
    scaled: float
    coefficient: float
    error_second: float | None
    scaled_second: float | None


@dataclass(frozen=True, slots=True)
class AdhesiveComplianceRow:
    """(2.36) at one nu: 1 + gamma^2/3 against atanh(gamma)/gamma (B4); error/gamma^4 -> 1/5."""

    nu: float
    gamma: float
    exact: float
    error: float
    scaled: float


@dataclass(frozen=True, slots=True)
class ExpansionStudy:
    """All checks of §2.3; ``fast`` says which mode produced it."""

    fast: bool
    friction_law: tuple[FrictionLawRow, ...]
    small_mu: tuple[SmallMuRow, ...]
    large_mu: tuple[LargeMuRow, ...]
    largest_stick: tuple[LargestStickRow, ...]
    largest_stick_estimates: tuple[LargestStickEstimate, ...]
    stick_shear: tuple[StickShearRow, ...]
    compliance: tuple[ComplianceRow, ...]
    adhesive_compliance: tuple[AdhesiveComplianceRow, ...]


@dataclass(frozen=True, slots=True)
class ExpansionErrors:
    """Worst |error| over the stick radii at each gamma, per approximation (for the figure);
    ``friction_law_second`` and ``compliance_second`` are None without the second-order table."""

    gamma: np.ndarray
    friction_law: np.ndarray
    friction_law_second: np.ndarray | None
    compliance: np.ndarray
    compliance_second: np.ndarray | None
    adhesive_compliance: np.ndarray
    stick_gamma: np.ndarray
    stick_shear: np.ndarray


@lru_cache(maxsize=1)
def _second_order_available() -> bool:
    """Whether ``asymptotics.second_order`` has its generated table (else seconds a point)."""
    try:
        mu_over_gamma_second_order(0.5, 0.1)
    except ImportError:
        return False
    return True


# ----------------------------------------------------------------------------------------
# the full solutions


def _solve(nu: float, c: float, level: int) -> FlatPunchSolution:
    return flat_punch(nu=nu, c=c, level=level)


def _full_mu_and_compliance(nus, cs, fast: bool, solutions: dict) -> dict:
    """mu and P* at each (nu, c): the table (fast) or level-3 solutions (kept in ``solutions``)."""
    out = {}
    for nu in nus:
        g = float(gamma_from_nu(nu))
        if fast:
            mus = np.asarray(friction_coefficient(np.array(cs), nu))
            pstars = table_compliance(np.array(cs), np.full(len(cs), g))
            out.update({(nu, c): (float(m), float(p)) for c, m, p in zip(cs, mus, pstars)})
        else:
            for c in cs:
                s = solutions.setdefault((nu, c), _solve(nu, c, 3))
                out[(nu, c)] = (s.mu, s.compliance)
    return out


# ----------------------------------------------------------------------------------------
# (2.28), (2.34), (2.36)


def _friction_law(values: dict) -> tuple[FrictionLawRow, ...]:
    rows = []
    for (nu, c), (mu, _) in values.items():
        g = float(gamma_from_nu(nu))
        first = g * float(mu_over_gamma(c))  # (2.28)
        rel = (first - mu) / mu
        rel2 = (g * float(mu_over_gamma_second_order(c, g)) - mu) / mu if _second_order_available() else None
        rows.append(FrictionLawRow(nu, g, c, mu, rel, rel / g**2, rel2, None if rel2 is None else rel2 / g**4))
    return tuple(sorted(rows, key=lambda r: (r.c, r.gamma)))


def _compliance(values: dict) -> tuple[ComplianceRow, ...]:
    rows = []
    for (nu, c), (_, pstar) in values.items():
        g = float(gamma_from_nu(nu))
        err = float(compliance_first_order(c, g)) - pstar  # (2.34)
        err2 = float(compliance_second_order(c, g)) - pstar if _second_order_available() else None
        rows.append(ComplianceRow(nu, g, c, pstar, err, err / g**4, (pstar - 1.0) / g**2,
                                  err2, None if err2 is None else err2 / g**6))
    return tuple(sorted(rows, key=lambda r: (r.c, r.gamma)))


def _adhesive_compliance() -> tuple[AdhesiveComplianceRow, ...]:
    rows = []
    for nu in NUS:
        g = float(gamma_from_nu(nu))
        exact = float(compliance_adhesive(g))  # (B4)
        err = 1.0 + g * g / 3.0 - exact  # (2.36)
        rows.append(AdhesiveComplianceRow(nu, g, exact, err, err / g**4))
    return tuple(sorted(rows, key=lambda r: r.gamma))


# ----------------------------------------------------------------------------------------
# (2.29) and the largest stick radius


def _small_mu(fast: bool) -> tuple[SmallMuRow, ...]:
    cs = (1e-2, 1e-3) if fast else (1e-2, 1e-3, 1e-4)
    rows = []
    for nu in _SMALL_MU_NUS:
        g = float(gamma_from_nu(nu))
        for c in cs:
            mu = float(friction_coefficient(c, nu, level=2))  # table for c >= 1e-3, else solver
            leading = 4.0 * math.exp(-g / mu)  # (2.29)
            series = float(c_small_mu(mu, g, terms=4))
            rows.append(SmallMuRow(nu, g, c, mu, leading / c - 1.0, series / c - 1.0, mu * math.log(4.0 / c) / g - 1.0))
    return tuple(sorted(rows, key=lambda r: (r.gamma, -r.c)))


def _large_mu(fast: bool) -> tuple[LargeMuRow, ...]:
    gaps = (5e-2, 1e-2) if fast else (5e-2, 1e-2, 1e-3, 1e-4, 1e-6)
    rows = []
    for nu in _LARGE_MU_NUS[:2] if fast else _LARGE_MU_NUS:
        g = float(gamma_from_nu(nu))
        for gap in gaps:
            s = flat_punch(nu=nu, c=1.0 - gap, level=2)
            mu = s.mu
            leading = 2.0 * math.exp(-math.pi * mu / g)  # (2.29)
            series = 1.0 - float(c_large_mu(mu, g, terms=4))
            first = g * float(mu_over_gamma(1.0 - gap))  # (2.28)
            rows.append(LargeMuRow(nu, g, gap, mu, leading / gap - 1.0, series / gap - 1.0,
                                   math.pi * mu / (g * math.log(2.0 / gap)) - 1.0, (mu - first) / (mu * first**2),
                                   (s.compliance - 1.0) / g**2))
    return tuple(sorted(rows, key=lambda r: (r.gamma, -r.one_minus_c)))


def largest_stick_rows(fast: bool) -> tuple[tuple[LargestStickRow, ...], tuple[LargestStickEstimate, ...]]:
    """mu(c) of the full solution at 1 - c = factor (1 - c_max) for the study's gammas and factors, and c_max from
    the limit problem (``slip_limit``) against the closed form K'(c_max)/K(c_max) = kappa; both empty when ``fast``."""
    if fast:
        return (), ()
    rows, estimates = [], []
    for g in _CMAX_GAMMAS:
        gap_max = float(largest_stick_radius_gap(g))
        limit = slip_limit(gamma=g)
        kappa = float(kappa_from_gamma(g))
        one_minus = 1.0 - limit.c
        estimates.append(LargestStickEstimate(g, kappa, one_minus, one_minus / gap_max - 1.0,
                                              one_minus * math.exp(math.pi / kappa),
                                              stick_radius_approach(gamma=g) / one_minus))
        for factor in _CMAX_FACTORS:
            s = flat_punch(gamma=g, c=1.0 - factor * gap_max, level=2)
            rows.append(LargestStickRow(g, factor * gap_max, s.mu, s.error))
    return (tuple(sorted(rows, key=lambda r: (r.gamma, -r.one_minus_c))),
            tuple(sorted(estimates, key=lambda r: r.gamma)))


# ----------------------------------------------------------------------------------------
# (2.31)


def _stick_grid(c: float) -> np.ndarray:
    """Points of (0, c): uniform, plus graded toward c where both ratios approach 1 like sqrt."""
    return np.unique(np.concatenate([np.linspace(0.0, c, 401)[1:-1], c * (1.0 - np.logspace(-7.0, -1.0, 61))]))


def _stick_shear(fast: bool, solutions: dict) -> tuple[StickShearRow, ...]:
    nus = _STRESS_NUS_FAST if fast else NUS
    cs = _STRESS_CS_FAST if fast else (0.1, 0.3, 0.5, 0.7, 0.9)
    rows = []
    for nu in nus:
        g = float(gamma_from_nu(nu))
        for c in cs:
            s = solutions[(nu, c)] if (nu, c) in solutions else _solve(nu, c, 2 if fast else 3)
            x = _stick_grid(s.c)
            diff = np.abs(np.asarray(s.shear(x)) / (s.mu * np.asarray(s.pressure(x))) - shear_ratio_first_order(x, c))
            k = int(np.argmax(diff))  # (2.31)
            rows.append(StickShearRow(nu, g, c, float(diff[k]), float(x[k]), float(diff[k]) / g**2))
    return tuple(sorted(rows, key=lambda r: (r.c, r.gamma)))


# ----------------------------------------------------------------------------------------
# orders, the study, the worst errors


def observed_orders(rows, value: str, quantity: str) -> tuple[OrderRow, ...]:
    """Log-log slopes of |row.<value>| against gamma at each c of ``rows`` (sorted by gamma).

    Examples
    --------
    >>> r = [AdhesiveComplianceRow(0.0, g, 0.0, g**4, 1.0) for g in (0.1, 0.2)]
    >>> round(observed_orders(r, "error", "(2.36)")[0].slopes[0], 12)
    4.0
    """
    by_c: dict[float, list] = {}
    for r in rows:
        by_c.setdefault(getattr(r, "c", math.nan), []).append(r)
    out = []
    for c, group in sorted(by_c.items()):
        group = sorted(group, key=lambda r: r.gamma)
        g = np.array([r.gamma for r in group])
        e = np.abs(np.array([getattr(r, value) for r in group]))
        slopes = np.diff(np.log(e)) / np.diff(np.log(g))
        out.append(OrderRow(quantity, c, tuple(float(v) for v in g), tuple(float(v) for v in slopes)))
    return tuple(out)


def expansion_study(fast: bool) -> ExpansionStudy:
    """Run every check of §2.3 (see the module docstring); ``fast`` picks the mode."""
    if not isinstance(fast, bool):
        raise ValueError(f"fast must be True or False, got {fast!r}")
    solutions: dict = {}
    values = _full_mu_and_compliance(NUS, C_VALUES, fast, solutions)
    largest_rows, largest_estimates = largest_stick_rows(fast)
    return ExpansionStudy(
        fast=fast,
        friction_law=_friction_law(values),
        small_mu=_small_mu(fast),
        large_mu=_large_mu(fast),
        largest_stick=largest_rows,
        largest_stick_estimates=largest_estimates,
        stick_shear=_stick_shear(fast, solutions),
        compliance=_compliance(values),
        adhesive_compliance=_adhesive_compliance(),
    )


def expansion_errors(study: ExpansionStudy) -> ExpansionErrors:
    """Worst |error| over the stick radii of the study at each gamma, per approximation."""

    def worst(rows, value):
        gs = sorted({r.gamma for r in rows})
        return read_only(gs), read_only([max(abs(getattr(r, value)) for r in rows if r.gamma == g) for g in gs])

    gamma, law = worst(study.friction_law, "relative_error")
    second = study.friction_law[0].scaled_second is not None
    law2 = worst(study.friction_law, "relative_error_second")[1] if second else None
    _, comp = worst(study.compliance, "error")
    comp2 = worst(study.compliance, "error_second")[1] if second else None
    _, adhesive = worst(study.adhesive_compliance, "error")
    stick_gamma, stick = worst(study.stick_shear, "max_difference")
    return ExpansionErrors(gamma, law, law2, comp, comp2, adhesive, stick_gamma, stick)
