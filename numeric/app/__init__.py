"""The applications: the SI calculator (``numeric.app.contact``) and the ``hertz-friction``
command line (``numeric.app.cli``). Modules are imported by their full name; this file
re-exports nothing.
"""
