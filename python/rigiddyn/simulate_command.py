"""``python -m rigiddyn simulate``: run a problem file with one method and save what it records.

Writes to --out: trajectory.csv, trajectory.npz, trajectory.parquet (when pyarrow is installed),
run.json (the run's settings and outcome), trajectory.png (ω, attitude, energy and |L| over t) and,
with --animate, axes.mp4 or axes.gif (the body's axes turning). The columns are those of
rigiddyn.trajectory. Every argument and --out are checked before the run starts.

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
from typing import Any, TextIO

import numpy as np

from . import _core
from .out_folder import check_out_folder
from .problem import Problem, load_problem
from .stability import warn_if_unstable

# written to --out (trajectory.parquet with pyarrow; axes.mp4 or axes.gif with --animate)
OUTPUTS = ("trajectory.csv", "trajectory.npz", "trajectory.parquet", "run.json", "trajectory.png")

__all__ = ["MAX_DEFAULT_RECORDS", "add_simulate_parser", "progress_bar", "run_simulate", "simulate_problem"]

# without --record-every a run records every k-th step, k the least giving at most this many records
# (+ the last): a table a plot and a spreadsheet still take whole
MAX_DEFAULT_RECORDS = 10_000


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
        "--animate adds an animation of the body's axes. Columns carry their units, e.g. 'w_B_x [rad/s]'.",
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
    p.add_argument("--record-every", type=_positive(int, "an integer >= 1"),
                   help=f"record every k-th step and the last (default: the least k giving at most "
                        f"{MAX_DEFAULT_RECORDS} records)")
    p.add_argument("--out", required=True, help="folder for the files (created if missing)")
    p.add_argument("--attitude", default="euler:ZYX", help=f"attitude in the plot: {ATTITUDE_HELP} (default euler:ZYX)")
    p.add_argument("--animate", nargs="?", const="auto", choices=("auto", "mp4", "gif"),
                   help="also write an animation of the body's axes: mp4 (needs ffmpeg), gif (needs Pillow) or "
                        "auto (mp4 if ffmpeg is present, else gif)")
    p.add_argument("--frames", type=_positive(int, "an integer >= 1"), default=100,
                   help="frames of the animation, evenly spaced over the records (default 100, at 25 per second)")
    p.add_argument("--no-plot", action="store_true", help="write the tables only, no trajectory.png")
    p.add_argument("--no-progress", action="store_true",
                   help="no progress bar on stderr (shown only on a terminal and when tqdm is installed)")


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
                     progress: Callable[[int], None] | None = None) -> Any:
    """rigiddyn.simulate of `problem` from its initial state at t = 0 over `steps` steps of `dt` [s] with
    `method`, recording every `record_every`-th step (and the last), after a StabilityWarning when dt
    is beyond the method's linear stability limit (rigiddyn.stability). `progress(steps_done)` is
    simulate's callback (about every 0.05 s of the run). Returns the SimulationResult."""
    warn_if_unstable(method, dt, steps, problem.inertia_com, problem.w_B, problem.torque_free, stacklevel=2)
    return _core.simulate(problem.body(), problem.initial_state(), dt, steps, method, record_every=record_every,
                          loads=problem.applied_loads(), gravity=problem.gravity, progress=progress)


class _Plan:
    """The checked settings of one `simulate` command."""

    def __init__(self, args: argparse.Namespace) -> None:
        from .trajectory_plot import check_attitude

        try:
            self.problem = load_problem(args.problem)
        except ValueError as e:  # the command line calls load_problem's argument PROBLEM
            raise ValueError(str(e).replace("path_or_name: ", "PROBLEM: ", 1)) from None
        names = [m["name"] for m in _core.methods()]
        if args.dt is None:  # a scene file's [run] may give it; a problem file has none
            raise ValueError("--dt: expected a time step [s] > 0 for a problem file, got nothing")
        if args.method not in names:
            raise ValueError(f"--method: expected one of {', '.join(names)}, got {args.method!r}")
        self.method: str = args.method
        self.dt: float = args.dt
        if args.steps is not None:
            self.steps: int = args.steps
        else:
            duration = self.problem.horizon if args.duration is None else args.duration
            self.steps = round(duration / self.dt)
            if self.steps < 1:
                raise ValueError(f"--duration: expected a time span >= dt = {self.dt!r} s, got {duration!r}")
        self.record_every: int = (args.record_every if args.record_every is not None
                                  else max(1, -(-self.steps // MAX_DEFAULT_RECORDS)))
        self.attitude = check_attitude(args.attitude)
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
        self.out = check_out_folder(args.out, OUTPUTS)
        self.progress = not args.no_progress


def _run_record(plan: _Plan, result: Any) -> dict[str, Any]:
    """run.json: what was run and what came out (numbers, null for not-a-number)."""
    from . import __version__
    from .trajectory import column_names

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
        "columns": column_names(),
        "quaternion order": "x, y, z, w",
    }


def _summary(result: Any) -> str:
    T, L = np.asarray(result.total_energy), np.asarray(result.angular_momentum_norm)

    def drift(x: np.ndarray) -> str:
        return f"{(x[-1] - x[0]) / abs(x[0]):+.2e}" if x[0] != 0 else f"{x[-1] - x[0]:+.2e} (absolute)"

    return (f"{len(result.t)} records to t = {result.t[-1]:.6g} s in {result.elapsed_seconds:.3g} s; "
            f"relative drift: total energy {drift(T)}, |L| {drift(L)}")


def _write(plan: _Plan, result: Any) -> list[Path]:
    from .trajectory import write_csv, write_npz, write_parquet

    record = _run_record(plan, result)
    written = [write_csv(result, plan.out / "trajectory.csv"), write_npz(result, plan.out / "trajectory.npz")]
    try:
        written.append(write_parquet(result, plan.out / "trajectory.parquet", metadata=record))
    except ImportError as e:
        print(f"rigiddyn simulate: no Parquet file: {e}", file=sys.stderr)
    (plan.out / "run.json").write_text(json.dumps(record, indent=2) + "\n")
    written.append(plan.out / "run.json")
    title = f"{plan.problem.name}: {plan.method}, dt = {plan.dt:g} s"
    if plan.plot:
        from .trajectory_plot import plot_trajectory

        written.append(plot_trajectory(result, plan.out / "trajectory.png", plan.attitude, title))
    if plan.writer is not None:
        from .trajectory_plot import animate_axes

        written.append(animate_axes(result, plan.out / "axes", "mp4" if plan.writer[1] == ".mp4" else "gif",
                                    frames=plan.frames, title=plan.method))
    return written


def run_simulate(args: argparse.Namespace) -> int:
    """The `simulate` command: check everything, run, write; returns the exit code (0: done, 1: the
    state became non-finite (the records up to there are written), 2: bad input, 130: interrupted)."""
    from .scene_simulate import is_scene_file, run_scene_simulate

    if is_scene_file(args.problem):  # [[body]] tables: a scene (wide per-body tables, no plot)
        return run_scene_simulate(args)
    try:
        plan = _Plan(args)
    except (ValueError, TypeError) as e:
        print(f"rigiddyn simulate: {e}", file=sys.stderr)
        return 2
    return run_and_report(plan.steps, plan.progress,
                          lambda update: simulate_problem(plan.problem, plan.method, plan.dt, plan.steps,
                                                          plan.record_every, update),
                          _summary, lambda result: _write(plan, result))


def run_and_report(steps: int, progress: bool, run: Callable[[Callable[[int], None] | None], Any],
                   summary: Callable[[Any], str], write: Callable[[Any], list[Path]]) -> int:
    """`run(update)` (update: the progress bar's callback, None without one) over `steps` steps, then its
    summary and the files `write` made printed; returns the exit code (0: done, 1: the state became
    non-finite (the records up to there are written), 2: bad input, 130: interrupted). Shared by the
    problem and the scene forms of the `simulate` command."""
    update, close = progress_bar(steps) if progress else (None, lambda: None)
    try:
        result = run(update)
        if update is not None and not result.diverged:
            update(steps)
    except KeyboardInterrupt:
        print("rigiddyn simulate: interrupted", file=sys.stderr)
        return 130
    except (ValueError, TypeError) as e:
        print(f"rigiddyn simulate: {e}", file=sys.stderr)
        return 2
    finally:
        close()
    print(summary(result))
    written = write(result)
    print("wrote " + ", ".join(str(w) for w in written))
    return 1 if result.diverged else 0
