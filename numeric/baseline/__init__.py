"""The paper's own numerical scheme ([S75] §4), kept as the yardstick.

Independent of ``numeric.core`` and ``numeric.solutions`` on purpose: it imports only
``asymptotics`` and numpy, so that comparing it with the solver compares two discretisations.
Modules are imported by their full name; this file re-exports nothing.
"""
