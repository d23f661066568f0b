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
    _add_tradeoff_parser(sub)
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
        return _run_tradeoff(args)
    return 0


def _floats(text: str) -> list[float]:
    return [float(x) for x in text.replace(",", " ").split()]


def _names(text: str) -> list[str]:
    return [x for x in text.replace(",", " ").split() if x]


def _add_tradeoff_parser(sub: "argparse._SubParsersAction[argparse.ArgumentParser]") -> None:
    p = sub.add_parser(
        "tradeoff",
        help="measure speed against accuracy of every method and step on a problem file; recommend the cheapest",
        description="Run each method at each step on PROBLEM (a TOML file or a shipped example: "
        "t_handle, fast_top, satellite_torque, projectile), compare with the exact solution or a "
        "refined reference, print the table and the recommendation, and write "
        "tradeoff.csv/.json/.png/.svg to --out.",
    )
    p.add_argument("problem", help="problem .toml path or example name")
    p.add_argument("--methods", type=_names, help="comma-separated method names (default: the file's, else all)")
    p.add_argument("--dts", type=_floats, help="comma-separated steps [s] (default: the file's)")
    p.add_argument("--horizon", type=float, help="time span [s] (default: the file's)")
    p.add_argument("--tolerance", type=float, help="tolerance on --measure for the recommendation")
    p.add_argument("--measure", help="error measure (default: the file's, else final_attitude_error)")
    p.add_argument("--cost", choices=("time", "evaluations"), default="time", help="cost to minimise")
    p.add_argument("--out", help="folder for tradeoff.csv, tradeoff.json, tradeoff.png, tradeoff.svg")
    p.add_argument("--no-progress", action="store_true",
                   help="no cost estimate and no progress bar on stderr (the bar shows only on a terminal)")


def _show_warning(message: Warning | str, category: type[Warning], filename: str, lineno: int,
                  file: TextIO | None = None, line: str | None = None) -> None:
    """Warnings on the command line: `rigiddyn: <Category>: <message>`, without a source line."""
    print(f"rigiddyn: {category.__name__}: {message}", file=sys.stderr if file is None else file)


def _run_tradeoff(args: argparse.Namespace) -> int:
    from pathlib import Path

    from rigiddyn.tradeoff import tradeoff

    try:
        with warnings.catch_warnings():  # restores the previous warning display afterwards
            warnings.showwarning = _show_warning
            result = tradeoff(args.problem, methods=args.methods, dts=args.dts, horizon=args.horizon,
                              tolerance=args.tolerance, measure=args.measure, cost=args.cost,
                              progress=not args.no_progress)
    except (ValueError, TypeError) as e:
        print(f"rigiddyn tradeoff: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("rigiddyn tradeoff: interrupted", file=sys.stderr)
        return 130
    print(result.to_table())
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        written = [out / "tradeoff.csv", out / "tradeoff.json"]
        result.to_csv(written[0])
        result.to_json(written[1])
        try:
            written += result.plot(out / "tradeoff")
        except ImportError as e:
            print(f"rigiddyn tradeoff: no plot: {e}", file=sys.stderr)
        print("wrote " + ", ".join(str(w) for w in written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
