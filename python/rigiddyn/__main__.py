"""Command line: ``python -m rigiddyn COMMAND``."""

from __future__ import annotations

import argparse
import sys


def main(argv: list[str] | None = None) -> int:
    """Run the rigiddyn command line; returns the process exit code."""
    parser = argparse.ArgumentParser(prog="rigiddyn", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("version", help="print the library version")
    args = parser.parse_args(argv)
    if args.command == "version":
        import rigiddyn

        print(rigiddyn.__version__)
    return 0


if __name__ == "__main__":
    sys.exit(main())
