"""Physical units for the plane-strain contacts: a cylinder (line contact) and a rigid strip punch, with friction.

Give the load per unit length P (N/m), the elastic constants (``numeric.app.contact.MaterialPair``: a half-space
and an optional elastic indenter, gamma_bar of [S75]'s footnote) and the friction coefficient; get the contact
half-width a, the stick half-width c a, the surface tractions in Pa with their maxima, the slip, and Hertz's values.

Scaling (``numeric.solutions.plane_power_law``): tractions sigma = (P/a) p(x), q likewise; with M = 1/((1 - nu1)/G1 +
(1 - nu2)/G2) = E*/2, the cylinder of radius R carries P = M a^2/(K R), so a = sqrt(K R P / M); Hertz (K0 = 2/pi):
a = sqrt(4 R P/(pi E*)), p_max = 2 P/(pi a). Slip: the tangential surface displacement of the half-space relative to
the indenter, (P/M) u(x) for the strip; for the cylinder each load increment dP is a strip punch of the current
width, so the slip rate in the slip zones is du/dP = u_strip(x)/M (m per N/m). The indentation depth of a
half-plane is not defined (logarithmic), so no approach or stiffness is reported. gamma_bar < 0 (the indenter the
more compressible): the mirror solution, shear and slip change sign.

References
----------
[S73] D. A. Spence, "An eigenvalue problem for elastic contact with finite friction",
      Proc. Camb. Phil. Soc. 73 (1973) 249-268.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from numeric.app.contact import Elastic, MaterialPair, json_ready, positive
from numeric.core.plane_fields import FieldCombination
from numeric.solutions.plane_law import FullSlipField
from numeric.solutions.plane_power_law import plane_power_law
from numeric.solutions.plane_punch import strip_punch
from numeric.solutions.plane_solver import DEFAULT_LEVEL

__all__ = ["LineContact", "press_cylinder", "press_strip"]


@dataclass(frozen=True, slots=True)
class LineContact:
    """A plane-strain contact in SI units (lengths m, tractions Pa, load per length N/m).

    ``frictionless_*`` are the values without friction (Hertz's cylinder; Sadowsky's strip, whose a is the same).
    ``slip_edge``: the slip at x = a (strip: m; cylinder: rate du/dP at x = a, m per N/m); ``max_slip``: the largest
    slip (m, at ``max_slip_at``): the strip's at its edges, the cylinder's accumulated over the loading, largest
    inside the slip zones (``PlanePowerLawSolution.slip``). The strip's pressure and
    shear are infinite at its edges: ``max_pressure`` and ``max_shear`` are inf there. Below the solver's smallest stick
    half-width (c < 1e-5, small mu: ``numeric.solutions.plane_law``) the values that depend on the neighbourhood of
    the stick zone (the cylinder's maxima and centre pressure, the strip's centre pressure) and the slip are None."""

    shape: str
    size: float
    materials: MaterialPair
    mu: float
    load: float
    gamma: float
    c: float
    half_width: float
    stick_half_width: float
    max_pressure: float | None
    max_pressure_at: float | None
    centre_pressure: float | None
    max_shear: float | None
    max_shear_at: float | None
    slip_edge: float | None
    max_slip: float | None
    max_slip_at: float | None
    frictionless_half_width: float
    frictionless_max_pressure: float
    frictionless_centre_pressure: float
    error: float
    route: str

    def to_dict(self) -> dict:
        """JSON-ready (SI units; infinities as None)."""
        out = {}
        for name in self.__slots__:
            value = getattr(self, name)
            if name == "materials":
                value = {"half_space": {"G": value.half_space.G, "nu": value.half_space.nu},
                         "indenter": None if value.indenter is None else {"G": value.indenter.G, "nu": value.indenter.nu},
                         "reduced_modulus": value.reduced_modulus}
            out[name] = value
        return json_ready(out)


def _pair(half_space: Elastic, indenter: Elastic | None) -> tuple[MaterialPair, float, float]:
    pair = MaterialPair(half_space, indenter)
    g = pair.gamma
    return pair, abs(g), -1.0 if g < 0.0 else 1.0


def _maximum(f, c: float) -> tuple[float, float]:
    """max of f on [0, 1) from a grid refined toward c and 1 (the kinks and the edge), and where."""
    x = np.unique(np.concatenate([np.linspace(0.0, 0.999, 1000), c + np.linspace(-0.02, 0.02, 81),
                                  1.0 - np.geomspace(1e-2, 1e-6, 40)]))
    x = x[(x >= 0.0) & (x < 1.0)]
    values = np.asarray(f(x))
    k = int(np.argmax(values))
    return float(values[k]), float(x[k])


def _half_width(K: float, R: float, P: float, M: float) -> float:
    """a = sqrt(K R P / M) (m), in logarithms where the product leaves the normal doubles (E = 1.8e308 made
    pi M overflow and Hertz's a zero: ZeroDivisionError); ValueError where a itself is not a finite double."""
    direct = K * R * P / M
    if math.isfinite(direct) and direct >= sys.float_info.min:
        return math.sqrt(direct)
    log_a = 0.5 * (math.log(K) + math.log(R) + math.log(P) - math.log(M))
    if not -708.0 < log_a < 709.0:
        raise ValueError(f"the contact half-width sqrt(K R P / M) = exp({log_a:.4g}) m is not a finite double: radius "
                         f"{R!r} m, load {P!r} N/m and the modulus M = {M!r} Pa are out of scale")
    return math.exp(log_a)


def press_cylinder(radius: float, half_space: Elastic, *, mu: float, load: float, indenter: Elastic | None = None,
                   level: int = DEFAULT_LEVEL) -> LineContact:
    """A cylinder of radius R (m) pressed with load per unit length P (N/m): the plane-strain Hertz contact with friction."""
    R = positive(radius, "radius", "cylinder radius, m")
    P = positive(load, "load", "load per unit length, N/m")
    pair, g, sign = _pair(half_space, indenter)
    h = plane_power_law(2, gamma=g, mu=mu, level=level)
    M = pair.modulus
    a = _half_width(h.load_factor, R, P, M)
    a_h = _half_width(2.0 / math.pi, R, P, M)
    scale = P / a
    p_h = 2.0 * P / (math.pi * a_h)
    if isinstance(h.flat.field, FullSlipField):  # the maxima lie in the unresolved neighbourhood of the stick zone
        return LineContact("cylinder", R, pair, float(mu), P, pair.gamma, h.c, a, h.c * a, None, None, None, None, None,
                           None, None, None, a_h, p_h, p_h, h.flat.error, h.flat.route)
    pmax, pmax_at = _maximum(h.pressure, h.c)
    qmax, qmax_at = _maximum(lambda x: np.asarray(h.shear(x)), h.c)
    slip = float(h.flat.slip(1.0)) / M
    umax, umax_at = _largest_slip(h)
    return LineContact("cylinder", R, pair, float(mu), P, pair.gamma, h.c, a, h.c * a, scale * pmax, pmax_at * a,
                       scale * float(h.pressure(0.0)), sign * scale * qmax, qmax_at * a, sign * slip,
                       sign * umax * P / M, umax_at * a, a_h, p_h, p_h, h.flat.error, h.flat.route)


def _largest_slip(h) -> tuple[float, float]:
    """The cylinder's largest accumulated slip (u <= 0, inward, on 0 < x < 1) and where: |u| = |C| x^n grows over the
    stick zone and falls to 0 at the edge, so its largest value lies on [c, 1] (bounded scalar search, to 1e-9 in x;
    from the resolved side where the field leaves the neighbourhood of c unresolved)."""
    lo = h.c
    if isinstance(h.flat.field, FieldCombination) and h.flat.field.unresolved is not None:
        lo = h.flat.field.unresolved[1]
    if h.c >= 1.0 or lo >= 1.0:
        return 0.0, 1.0
    found = optimize.minimize_scalar(lambda x: float(h.slip(x)), bounds=(lo, 1.0), method="bounded",
                                     options={"xatol": 1e-9})
    at_lo = float(h.slip(lo))
    return (float(found.fun), float(found.x)) if found.fun <= at_lo else (at_lo, lo)


def press_strip(half_width: float, half_space: Elastic, *, mu: float, load: float, indenter: Elastic | None = None,
                level: int = DEFAULT_LEVEL) -> LineContact:
    """A rigid flat strip punch of half-width a (m) pressed with load per unit length P (N/m), with friction."""
    a = positive(half_width, "half_width", "strip half-width, m")
    P = positive(load, "load", "load per unit length, N/m")
    pair, g, sign = _pair(half_space, indenter)
    s = strip_punch(gamma=g, mu=mu, level=level)
    scale = P / a
    if isinstance(s.field, FullSlipField):  # p(0) and the slip are not resolved (c < 1e-5)
        centre, slip = None, None
    else:
        centre, slip = scale * float(s.pressure(0.0)), sign * float(s.slip(1.0)) * P / pair.modulus
    return LineContact("strip", a, pair, float(mu), P, pair.gamma, s.c, a, s.c * a, math.inf, a, centre, math.inf, a,
                       slip, slip, None if slip is None else a, a, math.inf, P / (math.pi * a), s.error, s.route)
