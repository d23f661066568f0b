"""The command ``python -m rigiddyn tradeoff PROBLEM``: the work-precision report of rigiddyn.tradeoff.

PROBLEM is a problem file or example, or a scene file or shipped scene (a file whose `body` is an array
of tables, [[body]], is a scene; rigiddyn.scene_precision). With --out, the files are written all at once
after the sweep (rigiddyn.out_folder: nothing half-written; earlier files replaced only with --force);
the exit codes are rigiddyn.out_folder's."""

from __future__ import annotations

import argparse
import sys
import textwrap
from pathlib import Path
from typing import TYPE_CHECKING

from .out_folder import (EXIT_BAD_INPUT, EXIT_CODES_HELP, EXIT_EXISTS, EXIT_INTERRUPTED, EXIT_OK, EXIT_UNWRITABLE,
                         OutFolder, OutputError, OutputExists)

if TYPE_CHECKING:
    from .work_precision import TradeoffResult

# written to --out (the plot with matplotlib)
OUTPUTS = ("tradeoff.csv", "tradeoff.json", "tradeoff.png", "tradeoff.svg")


def _floats(text: str) -> list[float]:
    return [float(x) for x in text.replace(",", " ").split()]


def _names(text: str) -> list[str]:
    return [x for x in text.replace(",", " ").split() if x]


def _examples() -> list[str]:
    """The shipped problem examples and scenes, by name."""
    from rigiddyn.problem import example_problems
    from rigiddyn.scene_file import example_scenes

    return example_problems() + example_scenes()


def _epilog() -> str:
    """The methods (from the core's method table) and the error measures, for --help."""
    from rigiddyn import _core
    from rigiddyn._measures import measure_help

    def item(text: str) -> str:
        return textwrap.fill(text, 100, initial_indent="  ", subsequent_indent="      ")

    methods = [item(f"{m['name']}: order {m['order']}, {m['evaluations']} derivative evaluations per step"
                    + (" (closed form: torque-free bodies only)" if m["order"] == 0 else ""))
               for m in _core.methods()]
    measures = [item(line) for line in measure_help()]
    return "\n".join(["methods (--methods):", *methods,
                      "measures (--measure; final_: at the horizon, max_: the largest over the run):", *measures,
                      textwrap.fill(EXIT_CODES_HELP, 100)])


def add_tradeoff_parser(sub: "argparse._SubParsersAction[argparse.ArgumentParser]") -> None:
    """The `tradeoff` subcommand's arguments."""
    p = sub.add_parser(
        "tradeoff",
        help="measure speed against accuracy of every method and step on a problem or scene file; recommend the "
             "cheapest",
        description=textwrap.fill(
            "Run each method at each step on PROBLEM (a TOML file or a shipped example: "
            + ", ".join(_examples()) + "), compare with the exact solution or a refined reference, print a "
            "table 100 columns wide and the recommendation (without a tolerance: the Pareto front), and "
            "write every column to tradeoff.csv/.json and the plot to tradeoff.png/.svg in --out. A scene "
            "file ([[body]] tables) is swept the same way: errors over its bodies, a method it refuses shown "
            "'not applicable' with the reason, compile warnings as notes.", 100),
        epilog=_epilog(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("problem", help="problem or scene .toml path, or example or shipped scene name")
    p.add_argument("--methods", type=_names, help="comma-separated method names (default: the file's, else all)")
    p.add_argument("--dts", type=_floats, help="comma-separated steps [s] (default: the file's)")
    p.add_argument("--horizon", type=float, help="time span [s] (default: the file's)")
    p.add_argument("--tolerance", type=float,
                   help="tolerance on --measure for the recommendation (default: the file's; none: the Pareto front)")
    p.add_argument("--measure", help="error measure (default: the file's, else final_attitude_error; "
                                     "final_state_error for a scene)")
    p.add_argument("--cost", choices=("time", "evaluations"), default="time", help="cost to minimise")
    p.add_argument("--out", help="folder for " + ", ".join(OUTPUTS) + " (checked before the sweep; default: no files)")
    p.add_argument("--force", action="store_true",
                   help="replace the files of an earlier sweep in --out (and symbolic links in their place: the "
                        "link, not what it points to); without it they are refused, naming the file")
    p.add_argument("--no-progress", action="store_true",
                   help="no cost estimate and no progress bar on stderr (the bar shows only on a terminal)")


def _outputs() -> list[str]:
    """The files a sweep writes to --out: the plot only with matplotlib."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return list(OUTPUTS[:2])
    return list(OUTPUTS)


def _write(result: TradeoffResult, folder: Path) -> list[Path]:
    """The sweep's files, written to `folder`; returns their paths."""
    written = [folder / "tradeoff.csv", folder / "tradeoff.json"]
    result.to_csv(written[0])
    result.to_json(written[1])
    try:
        written += result.plot(folder / "tradeoff")
    except ImportError as e:
        print(f"rigiddyn tradeoff: no plot: {e}", file=sys.stderr)
    return written


def run_tradeoff(args: argparse.Namespace) -> int:
    """Check --out, run the sweep, print the report and write the files; the exit code
    (rigiddyn.out_folder's: 0 done, 2 bad input, 3 the files could not be written, 4 earlier files in --out
    without --force, 130 interrupted)."""
    from rigiddyn.simulate_command import fail
    from rigiddyn.work_precision import tradeoff

    try:
        out = OutFolder(args.out, _outputs(), args.force, OUTPUTS) if args.out is not None else None
        result = tradeoff(args.problem, methods=args.methods, dts=args.dts, horizon=args.horizon,
                          tolerance=args.tolerance, measure=args.measure, cost=args.cost,
                          progress=not args.no_progress)
    except (ValueError, TypeError, OSError, Warning) as e:
        return fail(e, EXIT_BAD_INPUT, "tradeoff")
    except OutputExists as e:
        return fail(e, EXIT_EXISTS, "tradeoff")
    except KeyboardInterrupt:
        return fail(KeyboardInterrupt("interrupted"), EXIT_INTERRUPTED, "tradeoff")
    print(result.to_table())
    if out is None:
        return EXIT_OK
    try:
        written = out.write(lambda folder: _write(result, folder))
    except OutputError as e:
        return fail(e, EXIT_UNWRITABLE, "tradeoff")
    except OutputExists as e:
        return fail(e, EXIT_EXISTS, "tradeoff")
    except KeyboardInterrupt:
        return fail(KeyboardInterrupt("interrupted; nothing written"), EXIT_INTERRUPTED, "tradeoff")
    print(f"wrote {', '.join(w.name for w in written)} to {out.path}")
    return EXIT_OK
