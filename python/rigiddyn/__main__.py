"""Command line: ``python -m rigiddyn COMMAND``."""

from __future__ import annotations

import argparse
import sys
import warnings
from typing import TextIO


def main(argv: list[str] | None = None) -> int:
    """Run the rigiddyn command line; returns the process exit code."""
    parser = argparse.ArgumentParser(prog="rigiddyn", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("version", help="print the library version")
    sub.add_parser(
        "worked-example",
        help="compute the shaft-and-disk example of K. Craig's \"Rigid Body Dynamics\" slides with the library and "
        "print it beside the slides' answer",
    )
    from rigiddyn.tradeoff_command import add_tradeoff_parser

    add_tradeoff_parser(sub)
    from rigiddyn.simulate_command import add_simulate_parser

    add_simulate_parser(sub)
    args = parser.parse_args(argv)
    if args.command == "version":
        import rigiddyn

        print(rigiddyn.__version__)
    elif args.command == "worked-example":
        from rigiddyn.worked_example import format_worked_example, textbook_worked_example

        result = textbook_worked_example()
        print(format_worked_example(result))
        return 0 if result["max_error"] <= 1e-12 else 1
    elif args.command == "tradeoff":
        from rigiddyn.tradeoff_command import run_tradeoff

        with warnings.catch_warnings():  # restores the previous warning display afterwards
            warnings.showwarning = _show_warning
            return run_tradeoff(args)
    elif args.command == "simulate":
        from rigiddyn.scene_simulate import is_scene_file, run_scene_simulate
        from rigiddyn.simulate_command import run_simulate

        with warnings.catch_warnings():  # restores the previous warning display afterwards
            warnings.showwarning = _show_warning
            if is_scene_file(args.problem):  # [[body]] tables: a scene (wide per-body tables)
                return run_scene_simulate(args)
            return run_simulate(args)
    return 0


def _show_warning(message: Warning | str, category: type[Warning], filename: str, lineno: int,
                  file: TextIO | None = None, line: str | None = None) -> None:
    """Warnings on the command line: `rigiddyn: <Category>: <message>`, without a source line."""
    print(f"rigiddyn: {category.__name__}: {message}", file=sys.stderr if file is None else file)


if __name__ == "__main__":
    sys.exit(main())
