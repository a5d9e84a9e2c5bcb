"""SymPy derivations of [S75]; imported by ``asymptotics.registry`` only (they import SymPy)."""
