"""Studies of the solutions: the paper's tables, the benchmark, the stability study, the expansion
checks and the figures. Each measures in one module and renders (Markdown, plots) in another.
Modules are imported by their full name; this file re-exports nothing.
"""
