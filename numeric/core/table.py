"""The eigenvalue relation mu(c, gamma) and the compliance P*(c, gamma) as a Chebyshev table.

For sweeps and for ``stick_radius`` the full solver (tens of ms a point, several points for
the inverse) is replaced by a two-dimensional Chebyshev interpolant built once from
level-3 solutions (``derivations/build_eigen_table.py`` writes ``numeric/core/table_data.py``):
in xi = logit(c) on [C_MIN, C_MAX] and eta = gamma^2 on [0, GAMMA_MAX^2] it interpolates

    log( mu / (gamma f0(c)) ),   f0(c) = atanh(c) / (c K'(c))   (2.28),

which vanishes as gamma -> 0 (the small-gamma law is exact there), and P*. The build
checks the table at random points that are not grid points against fresh solves; the
measured worst errors are ``MU_RELATIVE_ERROR`` and ``COMPLIANCE_ERROR``. Outside the
domain the functions return nan and callers fall back to the solver.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numpy.polynomial import chebyshev
from scipy import special
from scipy.optimize import elementwise

from asymptotics.first_order import mu_over_gamma

__all__ = ["table_available", "in_domain", "interpolate", "table_friction_coefficient", "table_compliance",
           "table_stick_radius"]


@lru_cache(maxsize=1)
def _data():
    from numeric.core import table_data as data  # generated; imported on first use only

    return (np.array(data.LOG_RATIO_COEFFICIENTS), np.array(data.COMPLIANCE_COEFFICIENTS), data)


def table_available() -> bool:
    """Whether the generated table module is present."""
    try:
        _data()
    except ImportError:
        return False
    return True


def _xi(c: np.ndarray, c_min: float, c_max: float) -> np.ndarray:
    s_lo, s_hi = math.log(c_min / (1 - c_min)), math.log(c_max / (1 - c_max))
    return 2.0 * (special.logit(c) - s_lo) / (s_hi - s_lo) - 1.0


def interpolate(c: np.ndarray, gamma: np.ndarray, coef_mu: np.ndarray, coef_p: np.ndarray, c_min: float, c_max: float,
                gamma_max: float) -> tuple[np.ndarray, np.ndarray]:
    """log(mu/(gamma f0)) and P* at points (c, gamma) inside the domain, from the Chebyshev coefficients
    ``coef_mu``, ``coef_p`` in (xi, eta) (the committed ones, or a fresh build's)."""
    v1 = chebyshev.chebvander(_xi(c, c_min, c_max), coef_mu.shape[0] - 1)
    v2 = chebyshev.chebvander(2.0 * (gamma / gamma_max) ** 2 - 1.0, coef_mu.shape[1] - 1)
    return np.einsum("mi,ij,mj->m", v1, coef_mu, v2), np.einsum("mi,ij,mj->m", v1, coef_p, v2)


def in_domain(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """True where C_MIN <= c <= C_MAX and 0 < gamma <= GAMMA_MAX."""
    data = _data()[2]
    return (c >= data.C_MIN) & (c <= data.C_MAX) & (gamma > 0.0) & (gamma <= data.GAMMA_MAX)


def _at(c: np.ndarray, gamma: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    coef_mu, coef_p, data = _data()
    log_ratio = np.full(c.shape, np.nan)
    compliance = np.full(c.shape, np.nan)
    inside = in_domain(c, gamma)
    if np.any(inside):
        log_ratio[inside], compliance[inside] = interpolate(
            c[inside], gamma[inside], coef_mu, coef_p, data.C_MIN, data.C_MAX, data.GAMMA_MAX)
    return log_ratio, compliance


def table_friction_coefficient(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """mu(c, gamma) from the table (nan outside its domain)."""
    c, gamma = np.broadcast_arrays(np.atleast_1d(np.asarray(c, dtype=float)), np.asarray(gamma, dtype=float))
    log_ratio, _ = _at(c, gamma)
    return gamma * np.asarray(mu_over_gamma(np.clip(c, 1e-300, 1.0))) * np.exp(log_ratio)  # (2.28) x ratio


def table_compliance(c: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """P*(c, gamma) from the table (nan outside its domain)."""
    c, gamma = np.broadcast_arrays(np.atleast_1d(np.asarray(c, dtype=float)), np.asarray(gamma, dtype=float))
    return _at(c, gamma)[1]


def table_stick_radius(mu: np.ndarray, gamma: np.ndarray) -> np.ndarray:
    """c with mu(c, gamma) = mu from the table by root finding in logit(c) (nan outside its domain).

    mu(c) increases with c (§2.1): on [-1, 1] in the scaled logit(c) the bracketing root finder
    of scipy (``scipy.optimize.elementwise.find_root``, Chandrupatla's method) solves all points
    at once, to 1e-15 in the scaled logit. The gamma direction is contracted once per point;
    each step evaluates a one-dimensional Chebyshev series (``chebval``) and f0 of (2.28) for
    the points not yet converged.
    """
    mu, gamma = np.broadcast_arrays(np.asarray(mu, dtype=float), np.asarray(gamma, dtype=float))
    shape = mu.shape
    mu, gamma = mu.ravel(), gamma.ravel()
    coef_mu, _, data = _data()
    ok = (gamma > 0.0) & (gamma <= data.GAMMA_MAX) & (mu > 0.0)
    g = np.where(ok, gamma, data.GAMMA_MAX)
    eta = chebyshev.chebvander(2.0 * (g / data.GAMMA_MAX) ** 2 - 1.0, coef_mu.shape[1] - 1)
    series = (eta @ coef_mu.T).T  # (xi order, points): log ratio as a series in xi
    target = np.log(np.where(ok, mu, 1.0) / g)  # log(mu / gamma) = log f0(c) + log ratio

    def excess(xi: np.ndarray, point: np.ndarray) -> np.ndarray:  # increasing in xi
        c = _c_of_xi(xi, data.C_MIN, data.C_MAX)
        f0 = np.arctanh(c) / (c * special.ellipkm1(c * c))  # (2.28), as mu_over_gamma without checks
        return np.log(f0) + chebyshev.chebval(xi, series[:, point], tensor=False) - target[point]

    points = np.arange(mu.size)
    lo, hi = np.full(mu.shape, -1.0), np.full(mu.shape, 1.0)
    ok &= (excess(lo, points) <= 0.0) & (excess(hi, points) >= 0.0)  # elsewhere find_root flags the bracket
    root = elementwise.find_root(excess, (lo, hi), args=(points,),
                                 tolerances={"xatol": 1e-15, "xrtol": 0.0, "fatol": 1e-15, "frtol": 0.0})
    c = _c_of_xi(root.x, data.C_MIN, data.C_MAX)
    return np.where(ok, c, np.nan).reshape(shape)


def _c_of_xi(xi: np.ndarray, c_min: float, c_max: float) -> np.ndarray:
    s_lo, s_hi = math.log(c_min / (1 - c_min)), math.log(c_max / (1 - c_max))
    return special.expit(s_lo + (s_hi - s_lo) * (xi + 1.0) / 2.0)
