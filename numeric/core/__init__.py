"""The solver core: quadrature, graded meshes with exact Abel matrices, collocation, the eigenvalue.

Discretisation and linear algebra only; no routes, no physical units. Imports ``asymptotics``
(the small-gamma law as a starting guess) and numpy/scipy, nothing above. Modules are imported
by their full name; this file re-exports nothing.
"""
