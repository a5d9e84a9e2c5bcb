"""Physical units: the frictional Hertz problem for engineers ([S75] §2.1, (2.1), (2.4), §3).

Give an indenter shape, the elastic constants, the friction coefficient and either the load
P or the approach delta (SI units: N, m, Pa); get the contact radius a, the stick radius
c a, the approach, the load, the loading stiffness dP/d delta, the surface tractions in Pa
with their maxima, the slip rate in the annulus, and the same quantities without friction.

Scaling ([S75] (2.1), (2.4), (3.2), (3.17))
-------------------------------------------
The dimensionless solution (p, q, u, P*, A of ``numeric.flat_punch`` / ``numeric.power_law``)
is turned into physical quantities by

    pressure  -sigma_zz(r) = M (delta/a) p(r/a),   shear  -sigma_rz(r) = M (delta/a) q(r/a)   (2.1)
    load      P = 4 M a P* delta                                                          (2.4)
    shape     z = k r^n:  delta = n k A a^n                                               (3.2)

with M = G/(1 - nu) for a rigid indenter. Spence writes the profile as z = r^n/(n b^(n-1)),
i.e. k = 1/(n b^(n-1)), so (3.2) reads delta = A a^n / b^(n-1); the form z = k r^n is used
here because with n = 1 Spence's form fixes the cone's slope to 1, whereas a cone of
semi-angle theta at the apex is z = r cot(theta) (k = cot theta). Sphere of radius R:
n = 2, k = 1/(2R) (b = R).

Given the load P of a power-law indenter, P = 4 M P* n k A a^(n+1), so
a = (P / (4 M P* n k A))^(1/(n+1)); given delta, a = (delta/(n k A))^(1/n). A flat punch has
a fixed radius a and delta = P/(4 M a P*).

Stiffness. For a power law P is proportional to a^(n+1) and delta to a^n at fixed mu (the
stick radius c, P* and A depend only on mu and nu, §3.2), so P ~ delta^((n+1)/n) and

    dP/d delta = ((n+1)/n) P/delta = 4 M a ((n+1)/n) P* = 4 M a P0*      by (3.17),

the stiffness of a flat punch of the current contact radius with the same friction. Without
friction (P0* = 1) this is the familiar S = 2 E* a; friction raises it by the factor P0*
(1 <= P0* <= atanh(gamma)/gamma, (2.4)). For the flat punch, dP/d delta = 4 M a P* at fixed
a. This is the stiffness under increasing load, which is all the theory covers; on unloading
the slip reverses and Spence's monotonic-loading solution no longer applies.

Slip. Spence's u is the radial displacement per unit approach, u = d u_r / d delta, for the
flat punch (a fixed, u_r = delta u(x), (2.1)). For a power law (3.15) gives
d u_r/da = n A (a/b)^(n-1) u0(r/a) in the annulus and d delta/da = n A (a/b)^(n-1), so
d u_r / d delta = u0(r/a) as well: the slip rate per unit approach is the flat punch's u0 for
every power law. It is zero in the stick zone and negative (inward) in the annulus (2.9).

Two elastic bodies (footnote to [S75] §2.1)
-------------------------------------------
Spence's analysis is for a rigid indenter, but his footnote to §2.1 (citing Spence [15])
notes that it carries over to two elastic bodies (shear moduli G1, G2, Poisson's ratios
nu1, nu2): the boundary conditions then hold for the sums w1 + w2 of the normal
displacements and for the relative radial displacement u1 - u2, and (2.2) keeps its form
with gamma replaced by

    gamma_bar = ((1 - 2 nu1)/(2 G1) - (1 - 2 nu2)/(2 G2)) / ((1 - nu1)/G1 + (1 - nu2)/G2)

(``asymptotics.materials.gamma_dissimilar``), body 1 being the half-space and body 2 the
indenter. Dividing (2.2) through by the denominator is what makes the scale factor of
(2.1) the composite

    M = 1 / ((1 - nu1)/G1 + (1 - nu2)/G2),     E* = 2 M,

and E* = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) is the classical Hertz reduced modulus, since
(1 - nu^2)/E = (1 - nu)/(2G). Both bodies are treated as half-spaces, the usual Hertz
assumption (a much smaller than the indenter's radius), and the theory is linear (small
strains; checked below). The second body's terms enter gamma_bar with a minus sign: the
coupling comes from the mismatch of the two surfaces' radial displacements. If
gamma_bar < 0 (the indenter the more compressible body) the solution is the mirror image of
the one for |gamma_bar|: (2.2) and (2.8)-(2.9) are unchanged under gamma -> -gamma,
q -> -q, u -> -u. So the solver is run with |gamma_bar|, and the shear traction and slip
carry the sign of gamma_bar: inward shear on the half-space and outward relative slip when
gamma_bar < 0. Elastically similar bodies (gamma_bar = 0) have no coupling: no shear, full
stick, frictionless Hertz values.

Conventions
-----------
``pressure`` is -sigma_zz >= 0 on the half-space surface; ``shear`` is the radial shear
traction acting on the half-space (body 1), -sigma_rz, positive pointing away from the axis
(outward, as friction acts on the half-space under a rigid indenter, (2.6b)); ``slip_rate``
is d(u_r1 - u_r2)/d delta, negative inward.

Other codes' parameters
-----------------------
* Dundurs' beta: in the form (1/2)[(1 - 2 nu1)/G1 - (1 - 2 nu2)/G2] / [(1 - nu1)/G1 + (1 - nu2)/G2]
  with body 1 the half-space it is gamma_bar itself; Dundurs' own expression
  beta = [G_a(kappa_b - 1) - G_b(kappa_a - 1)] / [G_a(kappa_b + 1) + G_b(kappa_a + 1)],
  kappa = 3 - 4 nu, equals gamma_bar with body a the indenter and body b the half-space
  (swapping the bodies flips the sign; |beta| = |gamma_bar| always).
* Kalker's CONTACT: combined modulus G = 2/(1/G1 + 1/G2), combined Poisson's ratio
  nu = (G/2)(nu1/G1 + nu2/G2), difference parameter K = (G/4)((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2)
  (Kalker's (1.44), as computed in CONTACT's ``combin_mater``, src/m_hierarch_data.f90 of
  github.com/eve70a/CONTACT). Then, for any pair, the denominator of gamma_bar is
  2(1 - nu)/G and its numerator 2K/G, so gamma_bar = K/(1 - nu) exactly, and M = G/(2(1 - nu)).
  For a rigid counterpart G = 2 G1, nu = nu1, K = (1 - 2 nu1)/2 and gamma = K/(1 - nu) is
  (2.2). CONTACT's tractions are those on its body 1: make the half-space CONTACT's body 1.

Input checks
------------
Loads, approaches, lengths and moduli must be finite and > 0, -1 < nu <= 1/2, mu >= 0 (inf
allowed: full stick), n > 0, exactly one of load and approach, exactly one of E and G; the
cone's semi-angle is in degrees, in (45, 90). Units are not guessed from magnitudes (soft gels
have E ~ 1 kPa, so no bound on E alone is safe); instead the result must be within the linear
half-space theory. Its strain measure ``Contact.strain`` = max(delta/a, surface slope at the
contact edge, mean pressure / E*) (for a sphere the slope is a/R, and delta/a = a/R too):

* above ``STRAIN_LIMIT`` = 1 the input is rejected, a ``ValueError`` naming the load (or
  approach) and suggesting to check the units. A modulus given in GPa or MPa by mistake
  (E = 70 for 70 GPa) trips this check; not every slip can be caught (a radius given in mm
  makes the contact milder, not impossible);
* above ``SMALL_STRAIN`` = 0.1 the result comes with a ``SmallStrainWarning``: Hertz theory
  treats both bodies as linear elastic half-spaces with small surface slopes, and its error
  grows in proportion to the strain measure (Johnson, *Contact Mechanics*, §4.2: a << R). A 5 mm
  ball at 1.5 MN on glass has a/R = 0.83: a number, but not a physical answer. A cone's
  strain does not depend on the load but on its angle (delta/a = A cot theta, A ~ pi/2: 0.56 at
  the Berkovich-equivalent 70.3 deg), so cones sharper than about 86 deg always warn.

References
----------
[S75] D. A. Spence, "The Hertz contact problem with finite friction",
      J. Elasticity 5 (1975) 297-319.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike

from asymptotics.arrays import read_only, scalar_or_array
from asymptotics.materials import check_mu, check_n, check_nu, finite_array, gamma_dissimilar, real_number

from numeric.solutions.flat_punch import flat_punch
from numeric.solutions.power_law import PowerLawSolution, power_law
from numeric.solutions.solution import FlatPunchSolution
from numeric.solutions.solver import DEFAULT_LEVEL

__all__ = [
    "Elastic",
    "elastic",
    "positive",
    "MaterialPair",
    "KalkerParameters",
    "FlatPunch",
    "PowerLaw",
    "Contact",
    "GridSolution",
    "indent",
    "small_strain_message",
    "SmallStrainWarning",
    "SMALL_STRAIN",
    "STRAIN_LIMIT",
]

STRAIN_LIMIT = 1.0  # strain measure (delta/a, edge slope, mean pressure/E*) above which input is rejected
SMALL_STRAIN = 0.1  # ... above which Hertz theory no longer applies (a/R < 0.1 for a sphere): a warning


class SmallStrainWarning(UserWarning):
    """The contact's strain measure (``Contact.strain``: a/R for a sphere) exceeds ``SMALL_STRAIN``: the result is
    that of the linear half-space theory, whose error grows like the strain."""
_GRID = np.linspace(0.0, 1.0, 257)  # search grid in x = r/a for the maxima, then zoomed
_ZOOMS = 4


def positive(value: float, name: str, what: str) -> float:
    """``value`` as a float, raising ValueError naming it unless finite and > 0 (TypeError unless a number)."""
    v = real_number(value, name)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name} ({what}) must be finite and > 0, got {value!r}")
    return v


@dataclass(frozen=True, slots=True)
class Elastic:
    """An isotropic linearly elastic body.

    Attributes
    ----------
    G : float
        Shear modulus, Pa.
    nu : float
        Poisson's ratio, -1 < nu <= 1/2.
    """

    G: float
    nu: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "G", positive(self.G, "G", "shear modulus, Pa"))
        object.__setattr__(self, "nu", float(check_nu(real_number(self.nu, "nu"))))

    @property
    def E(self) -> float:
        """Young's modulus E = 2 G (1 + nu), Pa."""
        return 2.0 * self.G * (1.0 + self.nu)


def elastic(*, nu: float, E: float | None = None, G: float | None = None, prefix: str = "") -> Elastic:
    """An elastic body from Poisson's ratio and exactly one of Young's modulus E or shear modulus G (Pa).

    ``prefix`` (e.g. "indenter_") is put in front of the argument names in error messages.

    Examples
    --------
    >>> elastic(E=70e9, nu=0.25).G
    28000000000.0
    """
    if (E is None) == (G is None):
        raise ValueError(f"give exactly one of {prefix}E (Young's modulus) or {prefix}G (shear modulus)")
    try:
        nu_value = float(check_nu(real_number(nu, "nu")))
    except (ValueError, TypeError) as err:
        raise type(err)(f"{prefix}{err}") from None
    if G is None:
        G = positive(E, f"{prefix}E", "Young's modulus, Pa") / (2.0 * (1.0 + nu_value))
    return Elastic(positive(G, f"{prefix}G", "shear modulus, Pa"), nu_value)


@dataclass(frozen=True, slots=True)
class KalkerParameters:
    """The material parameters of Kalker's CONTACT (Kalker's (1.44)).

    Attributes
    ----------
    G : float
        Combined modulus of rigidity 2/(1/G1 + 1/G2), Pa (CONTACT works in N/mm^2 = MPa).
    nu : float
        Combined Poisson's ratio (G/2)(nu1/G1 + nu2/G2).
    K : float
        Difference parameter (G/4)((1 - 2 nu1)/G1 - (1 - 2 nu2)/G2); gamma_bar = K/(1 - nu).
    """

    G: float
    nu: float
    K: float


@dataclass(frozen=True, slots=True)
class MaterialPair:
    """An elastic half-space (body 1) and an indenter (body 2; None = rigid).

    See the module docstring for how the rigid-indenter theory is extended to two elastic
    bodies (footnote to [S75] §2.1).
    """

    half_space: Elastic
    indenter: Elastic | None = None

    def _compliances(self) -> tuple[float, float]:
        """((1 - nu1)/G1 + (1 - nu2)/G2, (1 - 2 nu1)/(2 G1) - (1 - 2 nu2)/(2 G2))."""
        b1 = self.half_space
        total = (1.0 - b1.nu) / b1.G
        mismatch = (1.0 - 2.0 * b1.nu) / (2.0 * b1.G)
        if self.indenter is not None:
            b2 = self.indenter
            total += (1.0 - b2.nu) / b2.G
            mismatch -= (1.0 - 2.0 * b2.nu) / (2.0 * b2.G)
        return total, mismatch

    @property
    def modulus(self) -> float:
        """M = 1/((1 - nu1)/G1 + (1 - nu2)/G2), Pa: G/(1 - nu) of (2.1) for a rigid indenter."""
        return 1.0 / self._compliances()[0]

    @property
    def reduced_modulus(self) -> float:
        """Hertz's E* = 2 M = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2), Pa."""
        return 2.0 * self.modulus

    @property
    def gamma(self) -> float:
        """Signed gamma_bar of the footnote to [S75] §2.1; gamma (2.2) of the half-space if rigid."""
        if self.indenter is None:
            return (1.0 - 2.0 * self.half_space.nu) / (2.0 - 2.0 * self.half_space.nu)  # (2.2)
        return gamma_dissimilar(self.half_space.G, self.half_space.nu, self.indenter.G, self.indenter.nu)

    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta with the indenter as body a, the half-space as body b: equal to gamma_bar."""
        return self.gamma

    @property
    def kalker(self) -> KalkerParameters:
        """CONTACT's G, nu, K with the half-space as CONTACT's body 1; gamma_bar = K/(1 - nu)."""
        G1, nu1 = self.half_space.G, self.half_space.nu
        if self.indenter is None:
            return KalkerParameters(2.0 * G1, nu1, 0.5 * (1.0 - 2.0 * nu1))
        G2, nu2 = self.indenter.G, self.indenter.nu
        G = 2.0 / (1.0 / G1 + 1.0 / G2)
        return KalkerParameters(G, 0.5 * G * (nu1 / G1 + nu2 / G2),
                                0.25 * G * ((1.0 - 2.0 * nu1) / G1 - (1.0 - 2.0 * nu2) / G2))


@dataclass(frozen=True, slots=True)
class FlatPunch:
    """A rigid flat-ended cylindrical punch of radius ``radius`` (m), [S75] §2."""

    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", positive(self.radius, "radius", "punch radius, m"))

    @property
    def description(self) -> str:
        return f"flat punch, radius {self.radius:.6g} m"


@dataclass(frozen=True, slots=True)
class PowerLaw:
    """An axisymmetric indenter z = k r^n (z and r in m, k in m^(1-n)), [S75] §3.

    Spence's z = r^n/(n b^(n-1)) is ``PowerLaw.from_length(n, b)``; ``sphere`` and ``cone``
    give the classical shapes.
    """

    n: float
    k: float
    description: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "n", check_n(self.n))
        object.__setattr__(self, "k", positive(self.k, "k", "profile coefficient of z = k r^n, m^(1-n)"))
        if not self.description:
            object.__setattr__(self, "description", f"power law z = {self.k:.6g} r^{self.n:g}")

    @classmethod
    def sphere(cls, radius: float) -> PowerLaw:
        """A sphere of radius R (m) in the Hertz approximation z = r^2/(2R): n = 2, b = R."""
        R = positive(radius, "radius", "sphere radius, m")
        return cls(2.0, 0.5 / R, f"sphere, radius {R:.6g} m")

    @classmethod
    def cone(cls, semi_angle_deg: float) -> PowerLaw:
        """A cone of semi-angle theta at the apex, in degrees, z = r cot(theta): n = 1.

        Degrees, as on the command line (``--semi-angle-deg``) and as indenters are specified. The
        half-space theory needs a small surface slope, theta close to 90 deg ([S75] after (3.19));
        45 < theta < 90 is accepted (e.g. 70.3, the Berkovich-equivalent cone, whose strain measure
        delta/a = 0.56 is above ``SMALL_STRAIN``, so ``indent`` warns). An angle in radians falls
        below 45 and is refused, not misread.
        """
        theta = real_number(semi_angle_deg, "semi_angle_deg")
        if not 45.0 < theta < 90.0:
            hint = " (radians? the angle is in degrees)" if 0.0 < theta <= 0.5 * math.pi else ""
            raise ValueError(f"semi_angle_deg (cone semi-angle at the apex) must lie in (45, 90) degrees, got "
                             f"{semi_angle_deg!r}{hint}")
        return cls(1.0, 1.0 / math.tan(math.radians(theta)), f"cone, semi-angle {theta:.6g} deg")

    @classmethod
    def from_length(cls, n: float, b: float) -> PowerLaw:
        """Spence's z = r^n/(n b^(n-1)) ([S75] §3.1), b a body length in m: k = 1/(n b^(n-1))."""
        n_value = check_n(n)
        b_value = positive(b, "b", "body length of z = r^n/(n b^(n-1)), m")
        return cls(n_value, 1.0 / (n_value * b_value ** (n_value - 1.0)),
                   f"power law z = r^{n_value:g}/({n_value:g} b^{n_value - 1.0:g}), b = {b_value:.6g} m")


@dataclass(frozen=True, slots=True)
class GridSolution:
    """The reference solution on a user's grid (for grid codes such as CONTACT or FE).

    Arrays have the shape of the grid and are read-only; SI units.

    Attributes
    ----------
    x, y, radius : ndarray
        Grid points and r = hypot(x, y), m.
    pressure : ndarray
        -sigma_zz, Pa (0 outside the contact; inf at the edge of a flat punch).
    shear : ndarray
        Radial shear traction on the half-space, Pa, positive outward.
    shear_x, shear_y : ndarray
        Its Cartesian components, shear * (x, y)/r (0 at r = 0).
    slip_rate : ndarray
        d(u_r1 - u_r2)/d delta, dimensionless; 0 in the stick zone and outside the contact.
    contact_radius, stick_radius, approach, load : float
        a (m), c a (m), delta (m), P (N).
    """

    x: np.ndarray
    y: np.ndarray
    radius: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    shear_x: np.ndarray
    shear_y: np.ndarray
    slip_rate: np.ndarray
    contact_radius: float
    stick_radius: float
    approach: float
    load: float


@dataclass(frozen=True, slots=True)
class Contact:
    """A frictional contact in SI units, [S75] (2.1), (2.4), (3.2), (3.17).

    Attributes
    ----------
    shape : FlatPunch or PowerLaw
        The indenter's profile.
    materials : MaterialPair
        The half-space and the indenter (None = rigid).
    mu : float
        Friction coefficient.
    c : float
        Stick radius over contact radius (depends on mu and gamma only).
    gamma : float
        Signed gamma_bar (footnote to §2.1); the solver runs with |gamma|.
    compliance : float
        P* of (2.4) for this shape ((3.17) for a power law).
    flat_compliance : float
        P0*, the flat punch's (equal to ``compliance`` for a flat punch).
    A : float or None
        Indentation constant of (3.2) (None for the flat punch).
    contact_radius : float
        a, m.
    stick_radius : float
        c a, m.
    approach : float
        delta, m (the approach of distant points of the two bodies).
    load : float
        P, N.
    stiffness : float
        dP/d delta under increasing load, N/m (module docstring).
    mean_pressure : float
        P / (pi a^2), Pa.
    max_pressure, max_pressure_radius : float
        Largest pressure (Pa) and where (m); inf for a flat punch (at r = a) and for n <= 1 (at r = 0).
    max_shear : float
        Largest magnitude of the shear traction, Pa (0 without friction or coupling; inf for a flat punch
        with friction, at r = a, like the pressure). For a
        cone (n = 1) (3.13) gives q(0) = int_0^1 q0(t)/t dt > 0: the radial shear jumps at the
        apex (like the logarithmic pressure (3.20)), and for n < 1 it is infinite there.
    max_shear_radius : float or None
        Where it occurs, m (None when the shear vanishes everywhere). Locations are
        found to ~1e-7 a by zooming a grid (the maxima are flat, so the values are exact
        to the solver's accuracy).
    strain : float
        max(delta/a, surface slope at r = a, mean pressure/E*): a/R for a sphere. Rejected above
        ``STRAIN_LIMIT``, warned above ``SMALL_STRAIN`` (module docstring).
    error : float
        The dimensionless solver's estimated absolute error in c, mu, P0* (0 for closed forms);
        the relative errors of a, delta, P and the stiffness are of the same order.
    route : str
        How the dimensionless problem was solved.
    frictionless : Contact or None
        The same indenter, materials and load (or approach) with mu = 0; None if mu = 0
        (the contact is its own frictionless reference) or with ``with_frictionless=False``.
    """

    shape: FlatPunch | PowerLaw
    materials: MaterialPair
    mu: float
    c: float
    gamma: float
    compliance: float
    flat_compliance: float
    A: float | None
    contact_radius: float
    stick_radius: float
    approach: float
    load: float
    stiffness: float
    mean_pressure: float
    max_pressure: float
    max_pressure_radius: float
    max_shear: float
    max_shear_radius: float | None
    strain: float
    error: float
    route: str
    frictionless: Contact | None = field(repr=False)
    _solution: FlatPunchSolution | PowerLawSolution = field(repr=False)

    @property
    def _scale(self) -> float:
        return self.materials.modulus * self.approach / self.contact_radius  # M delta / a of (2.1)

    def _dimensionless(self, r: ArrayLike, f, name: str) -> np.ndarray | float:
        rs = finite_array(r, name)
        if np.any(rs < 0.0):
            raise ValueError(f"{name} (radius, m) must be >= 0 and not NaN, got {r!r}")
        with np.errstate(over="ignore"):  # a radius beyond the doubles' range over a is outside the contact
            x = rs / self.contact_radius
        inside = x <= 1.0
        out = np.zeros(rs.shape)
        out[inside] = f(x[inside])
        return scalar_or_array(out)

    def pressure(self, r: ArrayLike) -> np.ndarray | float:
        """Contact pressure -sigma_zz(r) = M (delta/a) p(r/a), Pa, [S75] (2.1); 0 for r > a."""
        return self._scale * self._dimensionless(r, self._solution.pressure, "r")

    def shear(self, r: ArrayLike) -> np.ndarray | float:
        """Radial shear traction on the half-space, sign(gamma_bar) M (delta/a) q(r/a), Pa, [S75] (2.1)."""
        sign = -1.0 if self.gamma < 0.0 else 1.0  # mirror solution for gamma_bar < 0 (module docstring)
        return sign * self._scale * self._dimensionless(r, self._solution.shear, "r")

    def slip_rate(self, r: ArrayLike) -> np.ndarray | float:
        """Slip per unit approach d(u_r1 - u_r2)/d delta = sign(gamma_bar) u0(r/a), dimensionless, (2.10), (3.15).

        Zero in the stick zone r < c a and outside the contact; negative (inward) in the
        annulus for gamma_bar > 0. Per unit load divide by ``stiffness``. Raises
        ``NotImplementedError`` where the dimensionless solution is the asymptotic law's (c < 1e-5,
        ``route`` says so), which has no slip displacement.
        """
        flat = self._solution.flat if isinstance(self._solution, PowerLawSolution) else self._solution
        sign = -1.0 if self.gamma < 0.0 else 1.0
        return sign * self._dimensionless(r, flat.slip, "r")

    @property
    def _exponent(self) -> float:
        """P ~ delta^e along the loading path: e = (n + 1)/n (power law), 1 (flat punch)."""
        return 1.0 if isinstance(self.shape, FlatPunch) else (self.shape.n + 1.0) / self.shape.n

    def load_at(self, approach: ArrayLike) -> np.ndarray | float:
        """The load-approach relation of this loading path: P(delta) in N for delta in m.

        P = P1 (delta/delta1)^((n+1)/n) for a power law ((2.4) with (3.2): P ~ a^(n+1),
        delta ~ a^n at fixed mu), P = P1 delta/delta1 for the flat punch; (P1, delta1) are
        this contact's load and approach. Increasing load only (§2.1).
        """
        d = finite_array(approach, "approach")
        if np.any(~np.isfinite(d)) or np.any(d <= 0.0):
            raise ValueError(f"approach (m) must be finite and > 0, got {approach!r}")
        with np.errstate(over="ignore", under="ignore"):
            return _representable(self.load * (d / self.approach) ** self._exponent, "approach", "load")

    def approach_at(self, load: ArrayLike) -> np.ndarray | float:
        """The inverse of ``load_at``: delta(P) in m for P in N."""
        P = finite_array(load, "load")
        if np.any(~np.isfinite(P)) or np.any(P <= 0.0):
            raise ValueError(f"load (N) must be finite and > 0, got {load!r}")
        with np.errstate(over="ignore", under="ignore"):
            return _representable(self.approach * (P / self.load) ** (1.0 / self._exponent), "load", "approach")

    def on_grid(self, x: ArrayLike, y: ArrayLike = 0.0) -> GridSolution:
        """The tractions, slip rate, stick radius and approach at grid points (x, y) in m.

        Pass radii as ``x`` (y = 0) for an axisymmetric grid.

        Examples
        --------
        >>> s = indent(PowerLaw.sphere(0.01), elastic(E=1e9, nu=0.5), mu=0.0, approach=5e-5)
        >>> g = s.on_grid([0.0, 3e-4], [0.0, 4e-4])     # r = 0 and r = 5e-4 m = a/sqrt(2)
        >>> [round(float(v) / 1e6, 6) for v in g.pressure]   # (2/pi) E* (a/R) sqrt(1 - r^2/a^2), MPa
        [60.021088, 42.441318]
        """
        return _on_grid(self, x, y)

    @property
    def ratios(self) -> dict[str, float | None]:
        """Ratios to the frictionless values at the same load (or approach): the correction
        factors for contact_radius, approach, load, stiffness, max_pressure (all 1.0 if mu = 0;
        None where both values are infinite, e.g. the flat punch's edge pressure).

        Raises ``ValueError`` if the contact was computed with ``with_frictionless=False``.
        """
        keys = ("contact_radius", "approach", "load", "stiffness", "max_pressure")
        if self.mu == 0.0:
            return {k: 1.0 for k in keys}
        if self.frictionless is None:
            raise ValueError("ratios need the frictionless solution: call indent(..., with_frictionless=True)")
        return {k: _ratio(getattr(self, k), getattr(self.frictionless, k)) for k in keys}

    def to_dict(self) -> dict:
        """The results as a JSON-ready dict (SI units; infinite values become None)."""
        return _contact_dict(self)


def _representable(values: np.ndarray, given: str, result: str) -> np.ndarray | float:
    """``values`` (of ``result``, computed from ``given``) unless one overflows to inf or underflows to 0."""
    if not np.all(np.isfinite(values) & (values > 0.0)):
        raise ValueError(f"{given}: the {result} it gives overflows or underflows double precision")
    return scalar_or_array(values)


def _on_grid(contact: Contact, x: ArrayLike, y: ArrayLike) -> GridSolution:
    """``Contact.on_grid``: the fields at (x, y), the shear split into its Cartesian components."""
    xs, ys = np.broadcast_arrays(finite_array(x, "x"), finite_array(y, "y"))
    if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(ys))):
        raise ValueError("x and y (grid coordinates, m) must be finite")
    with np.errstate(over="ignore"):  # beyond the doubles: outside the contact
        r = np.hypot(xs, ys)
    tau = np.asarray(contact.shear(r), dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_t = np.where(r > 0.0, xs / np.where(r > 0.0, r, 1.0), 0.0)
        sin_t = np.where(r > 0.0, ys / np.where(r > 0.0, r, 1.0), 0.0)
    return GridSolution(
        x=read_only(xs), y=read_only(ys), radius=read_only(r),
        pressure=read_only(contact.pressure(r)), shear=read_only(tau),
        shear_x=read_only(tau * cos_t), shear_y=read_only(tau * sin_t),
        slip_rate=read_only(contact.slip_rate(r)),
        contact_radius=contact.contact_radius, stick_radius=contact.stick_radius,
        approach=contact.approach, load=contact.load,
    )


def _contact_dict(contact: Contact) -> dict:
    """``Contact.to_dict``: the scalar results, the frictionless ones and the ratios, then the
    materials, the indenter, the error, the route and the units."""
    out = {
        "contact_radius": contact.contact_radius,
        "stick_radius": contact.stick_radius,
        "stick_fraction": contact.c,
        "approach": contact.approach,
        "load": contact.load,
        "stiffness": contact.stiffness,
        "mean_pressure": contact.mean_pressure,
        "max_pressure": contact.max_pressure,
        "max_pressure_radius": contact.max_pressure_radius,
        "max_shear": contact.max_shear,
        "max_shear_radius": contact.max_shear_radius,
        "mu": contact.mu,
        "compliance": contact.compliance,
        "flat_compliance": contact.flat_compliance,
        "indentation_constant": contact.A,
        "strain": contact.strain,
    }
    if contact.strain > SMALL_STRAIN:
        out["warning"] = small_strain_message(contact.strain)
    if contact.mu == 0.0:
        out["frictionless"] = dict(out)
    elif contact.frictionless is not None:
        out["frictionless"] = {k: v for k, v in contact.frictionless.to_dict().items() if k in out}
    if "frictionless" in out:
        out["ratios"] = dict(contact.ratios)
    out["materials"] = _materials_dict(contact.materials)
    out["indenter"] = _shape_dict(contact.shape)
    out["error"] = contact.error
    out["route"] = contact.route
    out["units"] = {"length": "m", "force": "N", "stress": "Pa", "stiffness": "N/m"}
    return json_ready(out)


def _materials_dict(pair: MaterialPair) -> dict:
    kal = pair.kalker
    return {
        "half_space": {"E": pair.half_space.E, "G": pair.half_space.G, "nu": pair.half_space.nu},
        "indenter": None if pair.indenter is None else
        {"E": pair.indenter.E, "G": pair.indenter.G, "nu": pair.indenter.nu},
        "reduced_modulus": pair.reduced_modulus,
        "gamma": pair.gamma,
        "dundurs_beta": pair.dundurs_beta,
        "kalker": {"G": kal.G, "nu": kal.nu, "K": kal.K},
    }


def _ratio(value: float, reference: float) -> float | None:
    if math.isinf(value) and math.isinf(reference):
        return None  # both infinite (flat-punch edge, cone apex): no ratio
    return value / reference


def json_ready(value: object) -> object:
    """``value`` with every non-finite float, at any depth of dicts, lists and tuples, as None (JSON has no inf or
    nan: a modulus of 1.8e308 made the reduced modulus inf, and the CLI's --json output failed)."""
    if isinstance(value, dict):
        return {k: json_ready(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return type(value)(json_ready(v) for v in value)
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _shape_dict(shape: FlatPunch | PowerLaw) -> dict:
    if isinstance(shape, FlatPunch):
        return {"shape": "flat punch", "radius": shape.radius, "description": shape.description}
    return {"shape": "power law", "n": shape.n, "k": shape.k, "description": shape.description}


def _maximum(f, breakpoints: np.ndarray) -> tuple[float, float | None]:
    """Largest |f| on [0, 1] and where: a grid (uniform plus the solution's breakpoints, which
    cluster at c and 1), then ``_ZOOMS`` vectorised zooms by a factor 16 around the best point
    (the bracket shrinks to 2/256/16^4 ~ 1e-7; f is smooth or has a kink at a maximum, where
    the value is then exact to rounding and the location to the final spacing)."""
    x = np.unique(np.concatenate([_GRID, breakpoints[(breakpoints >= 0.0) & (breakpoints <= 1.0)]]))
    values = np.abs(np.asarray(f(x), dtype=float))
    if np.any(np.isinf(values)):
        i = int(np.argmax(np.isinf(values)))
        return math.inf, float(x[i])
    i = int(np.argmax(values))
    best_x, best = float(x[i]), float(values[i])
    if best == 0.0:
        return 0.0, None
    lo, hi = x[max(i - 1, 0)], x[min(i + 1, len(x) - 1)]
    for _ in range(_ZOOMS):
        t = np.linspace(lo, hi, 33)
        v = np.abs(np.asarray(f(t), dtype=float))
        j = int(np.argmax(v))
        if v[j] > best * (1.0 + 1e-14):  # a rounding-level gain is not a better location
            best_x, best = float(t[j]), float(v[j])
        j = int(np.argmin(np.abs(t - best_x)))
        lo, hi = t[max(j - 1, 0)], t[min(j + 1, len(t) - 1)]
    return best, best_x


def small_strain_message(strain: float) -> str:
    """Why a contact with this strain measure (above ``SMALL_STRAIN``) is outside Hertz theory."""
    return (f"strain measure {strain:.3g} (a/R for a sphere; approach/radius, edge slope or mean pressure/E*) exceeds "
            f"{SMALL_STRAIN:g}: Hertz theory assumes small strains and slopes on two linear elastic half-spaces, so "
            "this result is the linear theory's, with an error of the order of the strain measure")


def _check_strain(measure: float, given: str, value: float) -> None:
    if not measure < STRAIN_LIMIT:
        raise ValueError(
            f"{given} = {value:.6g} {'N' if given == 'load' else 'm'} gives a strain measure {measure:.3g} >= "
            f"{STRAIN_LIMIT:g} (approach/radius, edge slope or mean pressure/E*): outside the linear half-space "
            f"theory; check the units "
            f"(SI: N, m, Pa) of {given}, the indenter's size and the elastic moduli")


def indent(
    shape: FlatPunch | PowerLaw,
    half_space: Elastic,
    *,
    mu: float,
    load: float | None = None,
    approach: float | None = None,
    indenter: Elastic | None = None,
    level: int = DEFAULT_LEVEL,
    with_frictionless: bool = True,
) -> Contact:
    """Press ``shape`` into ``half_space`` with friction ``mu`` to ``load`` P (N) or ``approach`` delta (m).

    Parameters
    ----------
    shape : FlatPunch or PowerLaw
        The indenter's profile (``PowerLaw.sphere(R)``, ``PowerLaw.cone(theta)``, ...).
    half_space : Elastic
        The elastic half-space (``elastic(E=..., nu=...)``).
    mu : float
        Coulomb friction coefficient, >= 0 (inf: full stick).
    load, approach : float
        Exactly one: the normal force P > 0 (N) or the approach delta > 0 (m).
    indenter : Elastic, optional
        The indenter's elastic constants; rigid if omitted (footnote to [S75] §2.1).
    level : int
        Resolution level of the dimensionless solver (``numeric.flat_punch``).
    with_frictionless : bool
        Also compute the mu = 0 solution for ``frictionless`` and ``ratios``.

    Returns
    -------
    Contact

    Warns
    -----
    SmallStrainWarning
        If the strain measure ``Contact.strain`` (a/R for a sphere) exceeds ``SMALL_STRAIN`` = 0.1.

    Raises
    ------
    ValueError
        Bad input, naming it (see the module docstring), or a result outside the linear theory.
    numeric.SolverError, numeric.NoEigenvalueError
        The dimensionless problem could not be solved.

    Examples
    --------
    Frictionless Hertz: a^3 = 3PR/(4E*), p_max = 3P/(2 pi a^2):

    >>> s = indent(PowerLaw.sphere(0.005), elastic(E=70e9, nu=0.22), mu=0.0, load=100.0)
    >>> E_star = 70e9 / (1 - 0.22**2)
    >>> a = (3 * 100.0 * 0.005 / (4 * E_star)) ** (1 / 3)
    >>> abs(s.contact_radius / a - 1) < 1e-12, abs(s.max_pressure / (3 * 100 / (2 * math.pi * a**2)) - 1) < 1e-12
    (True, True)
    """
    mu_value, given, value = _checked(shape, half_space, indenter, mu, load, approach)
    contact = _indent(shape, MaterialPair(half_space, indenter), mu_value, given, value, level, with_frictionless)
    if contact.strain > SMALL_STRAIN:
        warnings.warn(SmallStrainWarning(small_strain_message(contact.strain)), stacklevel=2)
    return contact


def _indent(shape: FlatPunch | PowerLaw, pair: MaterialPair, mu: float, given: str, value: float, level: int,
            with_frictionless: bool) -> Contact:
    """``indent`` on checked input, without the warning (given once, for the contact asked for)."""
    sol = _dimensionless(shape, mu, pair.gamma, level)
    try:
        scaled = _scaled(shape, sol, pair.modulus, given, value)
        a, delta, P = scaled.contact_radius, scaled.approach, scaled.load
        area = math.pi * a * a
        if not all(0.0 < v < math.inf for v in (a, delta, P, area)):
            raise OverflowError
    except (OverflowError, ZeroDivisionError):  # Python floats raise where the contact leaves the doubles
        raise ValueError(f"{given} = {value!r} {'N' if given == 'load' else 'm'}: the contact radius, approach, load "
                         "or contact area of this indenter overflow or underflow double precision; check the units "
                         "(SI: N, m, Pa)") from None
    strain = max(delta / a, scaled.edge_slope, P / area / pair.reduced_modulus)
    _check_strain(strain, given, value)
    frictionless = None
    if with_frictionless and mu != 0.0:
        frictionless = _indent(shape, pair, 0.0, given, value, level, False)
    return _contact(shape, pair, mu, sol, scaled, strain, frictionless)


def _checked(shape, half_space, indenter, mu, load, approach) -> tuple[float, str, float]:
    """The inputs of ``indent`` checked: mu, and which of load and approach was given, with its value."""
    if not isinstance(shape, (FlatPunch, PowerLaw)):
        raise ValueError(f"shape must be a FlatPunch or a PowerLaw, got {shape!r}")
    if not isinstance(half_space, Elastic) or not (indenter is None or isinstance(indenter, Elastic)):
        raise ValueError("half_space and indenter must be Elastic (use elastic(E=..., nu=...))")
    if (load is None) == (approach is None):
        raise ValueError("give exactly one of load (N) or approach (m)")
    mu_value = float(check_mu(real_number(mu, "mu")))
    if load is not None:
        return mu_value, "load", positive(load, "load", "normal force, N")
    return mu_value, "approach", positive(approach, "approach", "approach of the bodies, m")


def _dimensionless(shape: FlatPunch | PowerLaw, mu: float, gamma: float,
                   level: int) -> FlatPunchSolution | PowerLawSolution:
    """The dimensionless solution for |gamma_bar| (the mirror image for gamma_bar < 0, module docstring)."""
    if isinstance(shape, FlatPunch):
        return flat_punch(mu=mu, gamma=abs(gamma), level=level)
    return power_law(shape.n, mu=mu, gamma=abs(gamma), level=level)


@dataclass(frozen=True, slots=True)
class _Scaled:
    """The dimensionless solution at one load or approach: a, delta, P and the profile's slope at r = a."""

    contact_radius: float
    approach: float
    load: float
    edge_slope: float


def _scaled(shape: FlatPunch | PowerLaw, sol: FlatPunchSolution | PowerLawSolution, M: float, given: str,
            value: float) -> _Scaled:
    """a, delta and P from the given load or approach, by (2.4) and, for a power law, (3.2)."""
    if isinstance(shape, FlatPunch):
        a, P_star = shape.radius, sol.compliance
        if given == "load":
            P, delta = value, value / (4.0 * M * a * P_star)  # (2.4)
        else:
            delta, P = value, 4.0 * M * a * P_star * value  # (2.4)
        return _Scaled(a, delta, P, 0.0)
    n, k, P_star, A = shape.n, shape.k, sol.compliance, sol.A  # (3.17)
    if given == "load":
        P = value
        a = (P / (4.0 * M * P_star * n * k * A)) ** (1.0 / (n + 1.0))  # (2.4) with (3.2)
        delta = n * k * A * a**n  # (3.2)
    else:
        delta = value
        a = (delta / (n * k * A)) ** (1.0 / n)  # (3.2)
        P = 4.0 * M * a * P_star * delta  # (2.4)
    return _Scaled(a, delta, P, n * k * a ** (n - 1.0))  # dz/dr at r = a


def _contact(shape: FlatPunch | PowerLaw, pair: MaterialPair, mu: float, sol: FlatPunchSolution | PowerLawSolution,
             scaled: _Scaled, strain: float, frictionless: Contact | None) -> Contact:
    """The ``Contact``: stiffness, the maxima of the tractions in Pa, and the solver's error and route."""
    flat = sol.flat if isinstance(sol, PowerLawSolution) else sol
    a, delta, P = scaled.contact_radius, scaled.approach, scaled.load
    M = pair.modulus
    stiffness = 4.0 * M * a * flat.compliance  # = ((n+1)/n) P/delta by (3.17); flat punch: P/delta
    scale = M * delta / a  # (2.1)
    p_max, p_at = _maximum(sol.pressure, flat.breakpoints)
    q_max, q_at = _maximum(sol.shear, flat.breakpoints)
    return Contact(
        shape=shape, materials=pair, mu=mu, c=sol.c, gamma=pair.gamma, compliance=sol.compliance,
        flat_compliance=flat.compliance, A=sol.A if isinstance(sol, PowerLawSolution) else None, contact_radius=a,
        stick_radius=sol.c * a, approach=delta, load=P, stiffness=stiffness, mean_pressure=P / (math.pi * a * a),
        max_pressure=scale * p_max, max_pressure_radius=p_at * a,
        max_shear=scale * q_max, max_shear_radius=None if q_at is None else q_at * a, strain=strain,
        error=flat.error, route=flat.route, frictionless=frictionless, _solution=sol,
    )
