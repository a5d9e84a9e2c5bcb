"""Plane strain: the strip punch and power-law profiles (the cylinder) with friction, the 2-D counterpart of ``numeric``.

``stick_radius(mu, nu)`` (the stick half-width c over a), ``friction_coefficient(c, nu)``,
``flat_punch(nu=..., mu=... | c=...)`` (the strip punch) and ``power_law(n, nu=..., mu=...)``
(|x|^n; n = 2 the cylinder), each with ``.c``, ``.mu``, ``.pressure(x)``, ``.shear(x)`` and (the
punch) ``.slip(x)``, x the distance from the centre over the half-width a; the limit mu -> inf:
``slip_limit(nu)`` and ``largest_stick_radius(nu)`` (c_max < 1). The closed forms are in
``asymptotics.plane``. Like ``numeric/__init__.py`` this package only re-exports: it is a second
API module of the same layer.

>>> from numeric import plane
>>> s = plane.flat_punch(nu=0.3, c=0.5)
>>> round(s.mu, 10)
0.2374025972
>>> abs(float(plane.power_law(2, nu=0.3, mu=0.0).pressure(0.6)) - 1.6 / 3.141592653589793) < 1e-15   # Hertz
True
"""

from numeric.core.errors import NoEigenvalueError
from numeric.solutions.plane_power_law import PlanePowerLawSolution
from numeric.solutions.plane_power_law import plane_power_law as power_law
from numeric.solutions.plane_punch import StripPunchSolution
from numeric.solutions.plane_punch import plane_friction_coefficient as friction_coefficient
from numeric.solutions.plane_punch import plane_largest_stick_width as largest_stick_radius
from numeric.solutions.plane_punch import plane_slip_limit as slip_limit
from numeric.solutions.plane_punch import plane_stick_width as stick_radius
from numeric.solutions.plane_punch import strip_punch as flat_punch

__all__ = ["NoEigenvalueError", "PlanePowerLawSolution", "StripPunchSolution", "flat_punch", "friction_coefficient",
           "largest_stick_radius", "power_law", "slip_limit", "stick_radius"]
