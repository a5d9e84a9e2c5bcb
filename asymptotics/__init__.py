"""The analysis of Spence (1975): closed forms, expansions and their SymPy derivations.

The paper's small-gamma friction law and its inverse, and the first-order shear ratio, at the
top level: ``mu_over_gamma`` (2.28), ``stick_radius`` (its inverse; ``order=2`` adds the
gamma^2 f2 correction), ``psi`` (2.30). Modules: ``materials``, ``first_order`` (§2.3),
``second_order`` (beyond the paper), ``friction_law`` (the law inverted at either order),
``similarity`` (§3, power-law indenters), ``adhesive`` (App. B), ``registry`` (every derived
result by equation number; imports SymPy on first use). Imports go one way: materials, arrays
<- first_order <- second_order <- friction_law; ``derive`` (SymPy) is imported by ``registry`` only.

>>> import asymptotics
>>> round(float(asymptotics.mu_over_gamma(0.5)), 12), round(float(asymptotics.stick_radius(0.2, nu=0.25)), 6)
(0.509438589023, 0.626788)
>>> round(float(asymptotics.psi(0.3, 0.5)), 12)
0.639722500786
"""

from .first_order import mu_over_gamma, psi
from .friction_law import stick_radius

__all__ = ["mu_over_gamma", "psi", "stick_radius"]
