"""``python -m rigiddyn simulate``: run a problem file with one method and save what it records.

Writes to --out (default: simulate-<name> in the current folder, <name> the example's or the file's):
trajectory.csv, trajectory.npz, trajectory.parquet (when pyarrow is installed), run.json (the run's
settings and outcome), trajectory.png (ω, attitude, energy and |L| over t) and, with --animate,
axes.mp4 or axes.gif (the body's axes turning). The columns are those of rigiddyn.trajectory, in SI or in
the units of --units (``--units length=km,angle=deg,time=h``: rigiddyn.output_units; the tables and the plot
use them, run.json records them under "units" while its own settings stay SI). Every
argument and --out are checked before the run starts; the files are written all at once after it
(rigiddyn.out_folder: nothing half-written, earlier outputs replaced only with --force). The exit codes
are rigiddyn.out_folder's.

The time loop stays in C++: the progress bar is fed by simulate's `progress` callback, which the
core calls from its loop at most every 0.05 s (SimulationOptions::monitor), not per step; a run with
the bar is therefore the same computation as one without (tests/python/test_trajectory_cli.py).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TextIO, cast

import numpy as np

from . import _core
from ._names import require_method
from .out_folder import (EXIT_BAD_INPUT, EXIT_CODES_HELP, EXIT_DIVERGED, EXIT_EXISTS, EXIT_INTERRUPTED, EXIT_OK,
                         EXIT_UNWRITABLE, OutFolder, OutputError, OutputExists)
from .problem import Problem, load_problem
from .stability import warn_if_unstable

# every file the command may write to --out (trajectory.parquet with pyarrow, trajectory.png unless
# --no-plot, axes.mp4 or axes.gif with --animate)
OUTPUTS = ("trajectory.csv", "trajectory.npz", "trajectory.parquet", "run.json", "trajectory.png", "axes.mp4",
           "axes.gif")

__all__ = ["MAX_DEFAULT_RECORDS", "MAX_STEPS", "add_simulate_parser", "command_units", "default_out", "energy_balance",
           "error_report", "fail", "progress_bar", "run_and_report", "run_simulate", "simulate_problem", "step_count",
           "table_outputs"]

# without --record-every a run records every k-th step, k the least giving at most this many records
# (+ the last): a table a plot and a spreadsheet still take whole
MAX_DEFAULT_RECORDS = 10_000
MAX_STEPS = 2**53  # steps of one run at most (every step count below it is exact in a float)


def _positive(kind: type, what: str) -> Callable[[str], Any]:
    """An argparse type: `kind` (float or int) > 0, finite, else "expected <what>, got <text>"."""
    def parse(text: str) -> Any:
        try:
            value = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}") from None
        if not math.isfinite(value) or value <= 0:
            raise argparse.ArgumentTypeError(f"expected {what}, got {text!r}")
        return value

    return parse


def add_simulate_parser(sub: "argparse._SubParsersAction[argparse.ArgumentParser]") -> None:
    """Add the `simulate` subcommand to the command line's subparsers."""
    from .problem import example_problems
    from .trajectory_plot import ATTITUDE_HELP

    methods = ", ".join(m["name"] for m in _core.methods())
    p = sub.add_parser(
        "simulate",
        help="run a problem file with one method; save the recorded states (CSV, npz, Parquet) and plot them",
        description="Run PROBLEM (a TOML file or a shipped example: " + ", ".join(example_problems()) + ") with "
        "--method at fixed step --dt, and write to --out: trajectory.csv, trajectory.npz, trajectory.parquet "
        "(when pyarrow is installed), run.json and trajectory.png (w_B, attitude, energy, |L| over time); "
        "--animate adds an animation of the body's axes. Columns carry their units, e.g. 'w_B_x [rad/s]' "
        "('w_B_x [deg/s]' with --units angle=deg). "
        "With --tolerance instead of --dt (scene files) the method and dt are chosen to meet it.",
        epilog=EXIT_CODES_HELP,
    )
    p.add_argument("problem", help="problem .toml path or example name, or a scene file ([[body]] tables, "
                                   "rigiddyn.scene_simulate) or shipped scene name")
    p.add_argument("--method", help=f"integration method, one of: {methods} (required for a problem file; a scene "
                                    "file's [run] gives the default)")
    p.add_argument("--dt", type=_positive(float, "a time step [s] > 0"),
                   help="time step [s] (required for a problem file; a scene file's [run] gives the default)")
    span = p.add_mutually_exclusive_group()
    span.add_argument("--duration", type=_positive(float, "a time span [s] > 0"),
                      help="time span [s] (default: the problem's horizon); runs round(duration / dt) steps")
    span.add_argument("--steps", type=_positive(int, "an integer number of steps >= 1"), help="number of steps")
    p.add_argument("--tolerance", type=_positive(float, "a tolerance > 0 in the unit of --measure"),
                   help="instead of --dt: the largest error the run may have (absolute, in the unit of --measure); the "
                        "method (unless --method is given) and dt are chosen, the run certified by its global error "
                        "estimate and refined if needed (rigiddyn.simulate's tolerance=); the horizon is "
                        "--duration or the file's; a scene file's [run] dt and method are then not used")
    p.add_argument("--measure", choices=("attitude", "angular_velocity", "position", "velocity", "energy",
                                         "angular_momentum"),
                   help="the quantity --tolerance bounds, in rad, rad/s, m, m/s, J or kg m^2/s (default: position for "
                        "a scene of particles, else attitude)")
    p.add_argument("--max-steps", type=_positive(int, "an integer >= 4"),
                   help="with --tolerance: the most steps the run may take (default 10000000); more fails naming "
                        "the steps needed")
    p.add_argument("--record-every", type=_positive(int, "an integer >= 1"),
                   help=f"record every k-th step and the last (default: the least k giving at most "
                        f"{MAX_DEFAULT_RECORDS} records)")
    p.add_argument("--out", help="folder for the files (created if missing; default: simulate-<name> in the current "
                                 "folder, <name> the example's or the file's name without .toml)")
    p.add_argument("--force", action="store_true",
                   help="replace the files of an earlier run in --out (and symbolic links in their place: the "
                        "link, not what it points to); without it they are refused, naming the file")
    p.add_argument("--attitude", default="euler:ZYX", help=f"attitude in the plot: {ATTITUDE_HELP} (default euler:ZYX)")
    p.add_argument("--animate", nargs="?", const="auto", choices=("auto", "mp4", "gif"),
                   help="also write an animation of the body's axes: mp4 (needs ffmpeg), gif (needs Pillow) or "
                        "auto (mp4 if ffmpeg is present, else gif)")
    p.add_argument("--frames", type=_positive(int, "an integer >= 1"), default=100,
                   help="frames of the animation, evenly spaced over the records (default 100, at 25 per second)")
    p.add_argument("--units", metavar="DIMENSION=UNIT,...",
                   help="units of the tables and the plot instead of SI: comma-separated dimension=unit pairs, the "
                        "dimensions among length, angle, time, mass, energy, power, force (e.g. "
                        "length=km,angle=deg,time=h gives 'p_W_x [km]', 'w_B_x [deg/h]', 't [h]'); a compound unit "
                        "follows its parts (rad/s: angle and time); the quaternion stays as it is; run.json records "
                        "the units")
    p.add_argument("--no-plot", action="store_true", help="write the tables only, no trajectory.png")
    p.add_argument("--no-progress", action="store_true",
                   help="no progress bar on stderr (shown only on a terminal and when tqdm is installed)")
    p.add_argument("--no-error", action="store_true",
                   help="no global error estimate (by default two more runs at 2 dt and 4 dt, +0.75x the cost, "
                        "estimate the error of every record: printed, and in run.json)")


def _shown(text: str) -> str:
    """`text` quoted, or its length and start when it is long."""
    return repr(text) if len(text) <= 80 else f"a path of {len(text)} characters, {text[:30]!r}..."


def default_out(problem: str) -> str:
    """The default --out of `simulate PROBLEM`: simulate-<name>, <name> the shipped example's or scene's
    name, or the file's name without its suffix."""
    return f"simulate-{Path(problem).stem or problem}"


def step_count(steps: int | None, duration: float | None, dt: float) -> int:
    """The steps of a run: `steps` (--steps) if given, else round(duration / dt) for `duration` [s] at `dt`
    [s]; ValueError naming --steps or --duration when that is below 1 or beyond MAX_STEPS (a quotient
    that overflows to inf included)."""
    if steps is not None:
        if not 1 <= steps <= MAX_STEPS:
            raise ValueError(f"--steps: expected an integer number of steps from 1 to 2**53, got {steps}")
        return steps
    assert duration is not None, "a duration where --steps is not given"
    ratio = duration / dt
    if not ratio <= MAX_STEPS:  # also inf (1e300 / 1e-300) and nan
        raise ValueError(f"--duration: expected a run of at most 2**53 steps of dt = {dt!r} s, got {duration!r} s "
                         f"(duration / dt = {ratio:.3g} steps)")
    steps = round(ratio)
    if steps < 1:
        raise ValueError(f"--duration: expected a time span >= dt = {dt!r} s, got {duration!r}")
    return steps


def progress_bar(total: int, stream: TextIO | None = None) -> tuple[Callable[[int], None] | None, Callable[[], None]]:
    """(callback(steps_done) for simulate's `progress`, close()) drawing a tqdm bar of `total` steps on
    `stream` (default stderr) when tqdm is installed and the stream is a terminal; else (None, a no-op).
    Call the callback with `total` after a complete run (simulate's last call comes before its end)."""
    stream = sys.stderr if stream is None else stream
    try:
        from tqdm import tqdm
    except ImportError:
        return None, lambda: None
    if not stream.isatty():
        return None, lambda: None
    bar = tqdm(total=total, desc="simulate", unit="step", unit_scale=True, file=stream)

    def update(steps_done: int) -> None:
        bar.update(steps_done - bar.n)

    return update, bar.close


def simulate_problem(problem: Problem, method: str, dt: float, steps: int, record_every: int = 1,
                     progress: Callable[[int], None] | None = None, error: bool = True) -> Any:
    """rigiddyn.simulate of `problem` from its initial state at t = 0 over `steps` steps of `dt` [s] with
    `method`, recording every `record_every`-th step (and the last), after a StabilityWarning when dt
    is beyond the method's linear stability limit (rigiddyn.stability). `progress(steps_done)` is
    simulate's callback (about every 0.05 s of the run); `error`: simulate's global error estimate.
    Returns the SceneResult (one body: ``result.body(0)``)."""
    warn_if_unstable(method, dt, steps, problem.inertia_com, problem.w_B, problem.torque_free, stacklevel=2)
    # method: a str of methods() (mypy knows their literal names), checked by the core
    return _core.simulate(problem.body(), problem.initial_state(), dt, steps, cast(Any, method), record_every=record_every,
                          loads=list(problem.loads), gravity=problem.gravity, progress=progress, error=error)


class _Plan:
    """The checked settings of one `simulate` command."""

    def __init__(self, args: argparse.Namespace) -> None:
        from .trajectory_plot import check_attitude

        try:
            self.problem = load_problem(args.problem)
        except ValueError as e:  # the command line calls load_problem's argument PROBLEM
            raise ValueError(str(e).replace("path_or_name: ", "PROBLEM: ", 1)) from None
        except OSError as e:  # a path the system refuses (too long, ...)
            raise ValueError(f"PROBLEM: expected a problem file or example name, got {_shown(args.problem)} "
                             f"({e.strerror or e})") from None
        if args.tolerance is not None:
            raise ValueError("--tolerance: expected a scene file (a problem file runs at a given --dt), got the "
                             f"problem {_shown(args.problem)}")
        if args.dt is None:  # a scene file's [run] may give it; a problem file has none
            raise ValueError("--dt: expected a time step [s] > 0 for a problem file, got nothing")
        self.method: str = require_method(args.method, "--method")
        self.dt: float = args.dt
        self.steps = step_count(args.steps, self.problem.horizon if args.duration is None else args.duration, self.dt)
        self.record_every: int = (args.record_every if args.record_every is not None
                                  else max(1, -(-self.steps // MAX_DEFAULT_RECORDS)))
        self.attitude = check_attitude(args.attitude)
        self.units = command_units(args.units)
        self.plot = not args.no_plot
        self.animate: str | None = args.animate
        self.frames: int = args.frames
        self.writer: tuple[str, str] | None = None
        if self.plot or self.animate:
            try:
                import matplotlib

                matplotlib.use("Agg")  # files only, never a window
            except ImportError:
                if self.animate:
                    raise ValueError("--animate: expected matplotlib installed (pip install 'rigiddyn[plot]'), "
                                     "got none") from None
                print("rigiddyn simulate: no plot: matplotlib is not installed (pip install 'rigiddyn[plot]')",
                      file=sys.stderr)
                self.plot = False
        if self.animate:
            from .trajectory_plot import animation_writer

            try:
                self.writer = animation_writer(self.animate)
            except RuntimeError as e:
                raise ValueError(f"--animate: {e}") from None
        self.out = OutFolder(args.out if args.out is not None else default_out(args.problem), self.outputs(),
                             args.force, OUTPUTS)
        self.progress = not args.no_progress
        self.error = not args.no_error

    def outputs(self) -> list[str]:
        """The files this run writes."""
        return (table_outputs() + (["trajectory.png"] if self.plot else []) +
                ([f"axes{self.writer[1]}"] if self.writer is not None else []))


def command_units(text: str | None) -> dict[str, str]:
    """The checked --units of the command ({} without it): rigiddyn.output_units.parse_units_option."""
    from .output_units import parse_units_option

    return {} if text is None else parse_units_option(text)


def table_outputs() -> list[str]:
    """The tables and run.json that `simulate` writes: trajectory.parquet only when pyarrow is installed."""
    try:
        import pyarrow  # noqa: F401
    except ImportError:
        return ["trajectory.csv", "trajectory.npz", "run.json"]
    return ["trajectory.csv", "trajectory.npz", "trajectory.parquet", "run.json"]


def _run_record(plan: _Plan, result: Any) -> dict[str, Any]:
    """run.json: what was run and what came out (numbers, null for not-a-number)."""
    from . import __version__
    from .output_units import units_record
    from .scene_result import column_names

    def number(x: float) -> float | None:
        return float(x) if math.isfinite(x) else None

    return {
        "rigiddyn": __version__,
        "problem": plan.problem.name,
        "source": plan.problem.source,
        "method": plan.method,
        "dt [s]": plan.dt,
        "steps": plan.steps,
        "record_every": plan.record_every,
        "records": int(len(result.t)),
        "t_end [s]": number(result.t[-1]),
        "diverged": bool(result.diverged),
        "unconverged_steps": int(result.unconverged_steps),
        "elapsed_seconds [s]": result.elapsed_seconds,
        "global error": error_report(result.error),
        "units": units_record(plan.units),
        "columns": column_names(result, units=plan.units),
        "quaternion order": "x, y, z, w",
    }


# the units of a GlobalError's quantities, in the order of GlobalError.max()
_ERROR_UNITS = {"attitude": "rad", "angular_velocity": "rad/s", "position": "m", "velocity": "m/s", "energy": "J",
                "angular_momentum": "kg m^2/s"}


def error_report(error: Any) -> dict[str, Any] | None:
    """run.json's "global error": the estimate's order, how many records it calls reliable, and how many each
    quantity is reliable at on its own (GlobalError.reliable_for), its largest value of each quantity ("attitude
    [rad]": ..., null where none) and the first verdict that is not "reliable" with its time (null when every record
    is); None for a run without an estimate (--no-error)."""
    if error is None:
        return None
    verdict = list(error.verdict)
    other = next((i for i, v in enumerate(verdict) if v != "reliable"), None)
    largest = {f"{name} [{_ERROR_UNITS[name]}]": (float(value) if math.isfinite(value) else None)
               for name, value in error.max().items()}
    return {"order": int(error.order), "records": len(verdict), "reliable records": int(np.sum(error.reliable)),
            "reliable records by quantity": {name: int(np.sum(error.reliable_for(name))) for name in _ERROR_UNITS},
            "largest estimates": largest,
            "first verdict not reliable": None if other is None else {"record": other, "verdict": verdict[other]}}


def _drift(x: np.ndarray) -> str:
    """The change of x over the run relative to its initial value (absolute if that is 0)."""
    return f"{(x[-1] - x[0]) / abs(x[0]):+.2e}" if x[0] != 0 else f"{x[-1] - x[0]:+.2e} (absolute)"


def energy_balance(kinetic_energy: Any, work: Any, what: str) -> str:
    """The work-energy balance of a run whose forces do work, T(t) - T(0) - W(t) at the end [J], zero for
    the exact motion (the kinetic energy theorem: the change of kinetic energy T is the work W of every
    force and couple; `what` says whose work W is), also relative to the energy scale max_t max(T, |W|)."""
    T, W = np.asarray(kinetic_energy, dtype=np.float64), np.asarray(work, dtype=np.float64)
    residual = float(T[-1] - T[0] - W[-1])
    scale = float(max(np.max(np.abs(T)), np.max(np.abs(W))))
    relative = f"{residual / scale:+.2e} of max(T, |W|) = {scale:.4g} J; " if scale > 0 else ""
    return f"energy balance T(t) - T(0) - W(t) = {residual:+.2e} J ({relative}W the work of {what})"


def _summary(problem: Problem, result: Any) -> str:
    """One line: records, time; without loads the relative drift of the total energy and |L|, with loads
    (they do work) the energy balance and the change of |L|."""
    head = f"{len(result.t)} records to t = {result.t[-1]:.6g} s in {result.elapsed_seconds:.3g} s"
    L = np.asarray(result.body(0).angular_momentum_norm)
    if any(np.any(load.force) or np.any(load.torque) for load in problem.loads):
        balance = energy_balance(result.kinetic_energy, np.sum(result.work, axis=1), "the loads and gravity")
        return f"{head}; {balance}; relative change of |L| {_drift(L)} (the loads' couples change it)"
    return f"{head}; relative drift: total energy {_drift(np.asarray(result.total_energy))}, |L| {_drift(L)}"


def _write(plan: _Plan, result: Any, folder: Path) -> list[Path]:
    """The files of the run, written to `folder`; returns their paths."""
    from .trajectory import write_csv, write_npz, write_parquet

    record = _run_record(plan, result)
    written = [write_csv(result, folder / "trajectory.csv", units=plan.units),
               write_npz(result, folder / "trajectory.npz", units=plan.units)]
    if "trajectory.parquet" in plan.out.outputs:
        written.append(write_parquet(result, folder / "trajectory.parquet", metadata=record, units=plan.units))
    else:
        print("rigiddyn simulate: no Parquet file: it needs pyarrow (pip install 'rigiddyn[parquet]')", file=sys.stderr)
    (folder / "run.json").write_text(json.dumps(record, indent=2) + "\n")
    written.append(folder / "run.json")
    title = f"{plan.problem.name}: {plan.method}, dt = {plan.dt:g} s"
    if plan.plot:
        from .trajectory_plot import plot_trajectory

        written.append(plot_trajectory(result, folder / "trajectory.png", plan.attitude, title, units=plan.units))
    if plan.writer is not None:
        from .trajectory_plot import animate_axes

        written.append(animate_axes(result, folder / "axes", "mp4" if plan.writer[1] == ".mp4" else "gif",
                                    frames=plan.frames, title=plan.method))
    return written


def run_simulate(args: argparse.Namespace) -> int:
    """The `simulate` command on a problem file: check everything, run, write; returns the exit code
    (rigiddyn.out_folder: 0 done, 1 the state became non-finite (the records up to there are written), 2 bad
    input, 3 the files could not be written, 4 earlier files in --out without --force, 130 interrupted). A
    scene file goes to rigiddyn.scene_simulate.run_scene_simulate instead (the command's dispatch, in
    rigiddyn.__main__)."""
    try:
        plan = _Plan(args)
    except (ValueError, TypeError, OSError, Warning) as e:
        return fail(e)
    except OutputExists as e:
        return fail(e, EXIT_EXISTS)
    return run_and_report(plan.steps, plan.progress,
                          lambda update: simulate_problem(plan.problem, plan.method, plan.dt, plan.steps,
                                                          plan.record_every, update, plan.error),
                          lambda result: _summary(plan.problem, result), plan.out,
                          lambda result, folder: _write(plan, result, folder))


def fail(error: BaseException, code: int = EXIT_BAD_INPUT, command: str = "simulate") -> int:
    """Print `error` as one line on stderr, "rigiddyn <command>: <message>" (a warning turned into an error
    by python -W error named by its category); returns `code`."""
    text = str(error)
    if isinstance(error, Warning):
        text = f"{type(error).__name__}: {text} (a warning, raised as an error)"
    print(f"rigiddyn {command}: {text}", file=sys.stderr)
    return code


def run_and_report(steps: int, progress: bool, run: Callable[[Callable[[int], None] | None], Any],
                   summary: Callable[[Any], str], out: OutFolder, write: Callable[[Any, Path], list[Path]]) -> int:
    """`run(update)` (update: the progress bar's callback, None without one) over `steps` steps, then its
    summary printed and its files written by `write(result, folder)` to `out` (all at once, see
    OutFolder.write) and named; returns the exit code (rigiddyn.out_folder's). Shared by the problem and
    the scene forms of the `simulate` command."""
    update, close = progress_bar(steps) if progress else (None, lambda: None)
    try:
        result = run(update)
        if update is not None and not result.diverged:
            update(steps)
    except KeyboardInterrupt:
        return fail(KeyboardInterrupt("interrupted"), EXIT_INTERRUPTED)
    except (ValueError, TypeError, Warning) as e:
        return fail(e)
    finally:
        close()
    print(summary(result))
    if getattr(result, "error", None) is not None:
        print(f"global error estimate: {result.error.summary()}")
    try:
        written = out.write(lambda folder: write(result, folder))
    except KeyboardInterrupt:
        return fail(KeyboardInterrupt("interrupted; nothing written"), EXIT_INTERRUPTED)
    except OutputError as e:
        return fail(e, EXIT_UNWRITABLE)
    except OutputExists as e:
        return fail(e, EXIT_EXISTS)
    print(f"wrote {', '.join(w.name for w in written)} to {out.path}")
    return EXIT_DIVERGED if result.diverged else EXIT_OK
