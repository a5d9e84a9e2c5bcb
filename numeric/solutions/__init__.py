"""The problems of [S75]: the flat punch (§2) and power-law indenters (§3), with their routes.

Closed forms in the limits, the asymptotic law with measured bounds, the table and the solver
of ``numeric.core``; sweeps over arrays. Modules are imported by their full name; this file
re-exports nothing (the public API is ``numeric``).
"""
