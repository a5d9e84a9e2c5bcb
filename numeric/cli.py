"""The ``hertz-friction`` command line."""

from __future__ import annotations

import argparse
import sys


def main(argv: list[str] | None = None) -> int:
    """Entry point of the ``hertz-friction`` console script."""
    parser = argparse.ArgumentParser(prog="hertz-friction", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("tables", help="print the tables of Spence (1975) beside our recomputation and the exact values")
    args = parser.parse_args(argv)
    if args.command == "tables":
        from .paper_tables import render

        sys.stdout.write(render() + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
