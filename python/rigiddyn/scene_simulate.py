"""``python -m rigiddyn simulate SCENE``: the simulate command for scene files (rigiddyn.scene_file).

The `simulate` command (rigiddyn.__main__) hands a scene file (a .toml with [[body]] tables, or a shipped scene's
name, rigiddyn.scene_file.example_scenes()) to run_scene_simulate, a problem file to
simulate_command.run_simulate. The scene's [run] gives the defaults
of --method, --dt, --duration and --record-every; the command-line options override them. A scene with a
[controller] runs under it (rigiddyn.Controller: its law sampled every period, run.json's "controller" records it;
no --tolerance).

Writes to --out (default: simulate-<name>, as for a problem): trajectory.csv, trajectory.npz,
trajectory.parquet (when pyarrow is installed), run.json and trajectory.png (unless --no-plot). The
tables are WIDE, one row per record, the columns of rigiddyn.scene_result (what
SceneResult.to_dataframe gives): ``t [s]``, then per body ``<name>:p_W_x [m]`` .. ``<name>:q_WB_x`` ..
``<name>:v_W_x [m/s]`` .. ``<name>:w_B_x [rad/s]``, ``<name>:pivot_reaction_W_x [N]`` ..,
``<name>:angular_momentum_O_W_x [kg m^2/s]`` .., ``<name>:mass [kg]``, then the energies, momenta, and
each element's ``work[i] <Class> [J]`` and ``power[i] <Class> [W]`` (in a moving frame, the fictitious
terms' too: CentrifugalForce, CoriolisForce, ...). One file rather than one per body: the scene-wide
columns (energy, momenta, work) belong to a record, and ``df.filter(like="sat:")`` selects a body. The
plot overlays the bodies (rigiddyn.trajectory_plot.scene_figure: positions, the angular velocity and
attitude of the bodies that have one, energies and work, |H|, the masses when they change);
--animate (one body's axes) is refused. --units gives the tables and the plot in the user's units, as for a
problem (rigiddyn.output_units; run.json records them under "units").

The summary line says what matters for the scene: the energy drift when every element is conservative
(the Jacobi integral in a frame turning at a constant rate); the energy balance T(t) - T(0) - W(t) (W
the work of every element) when one is not (damping, drag, scheduled loads, a force in Python); the
mass burnt by each body with a mass flow (whose energy is not conserved: the thrust works); the range
of each pivot's reaction. The files are written all at once after the run, as simulate_command's.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import warnings
from pathlib import Path
from typing import Any, cast

import numpy as np

from . import _core
from ._names import require_method
from .out_folder import EXIT_EXISTS, OutFolder, OutputExists
from .scene_file import SceneFile, read_scene

__all__ = ["SCENE_OUTPUTS", "is_scene_file", "run_scene_simulate"]

SCENE_OUTPUTS = ("trajectory.csv", "trajectory.npz", "trajectory.parquet", "run.json", "trajectory.png")
MAX_DEFAULT_RECORDS = 10_000  # as simulate_command: without --record-every or [run] record_every


def is_scene_file(path_or_name: str) -> bool:
    """True for a shipped scene's name or a readable .toml file with [[body]] or [[cluster]] tables (a
    problem file has one [body] table): scene_file.is_scene_toml."""
    from .scene_file import example_scenes, is_scene_toml

    try:
        if not Path(path_or_name).is_file():
            return path_or_name in example_scenes()
    except (OSError, ValueError):
        return False  # load_problem names what is wrong with it
    return is_scene_toml(path_or_name)


class _ScenePlan:
    """The checked settings of one `simulate` of a scene file."""

    def __init__(self, args: argparse.Namespace) -> None:
        from .simulate_command import command_units, default_out, step_count
        from .trajectory_plot import check_attitude

        try:
            self.file: SceneFile = read_scene(args.problem)
        except ValueError as e:
            raise ValueError(f"PROBLEM: {e}") from None
        self.source = str(args.problem)
        run = self.file.run
        duration = args.duration if args.duration is not None else run.duration
        self.tolerance: float | None = args.tolerance
        self.measure: str | None = args.measure
        self.max_steps: int | None = args.max_steps
        if self.tolerance is None:
            for given, name in ((args.measure, "--measure"), (args.max_steps, "--max-steps")):
                if given is not None:
                    raise ValueError(f"{name}: expected nothing without --tolerance, got {given!r}")
        if self.tolerance is not None:  # the method (unless --method) and dt are chosen by simulate
            if args.dt is not None:
                raise ValueError(f"--dt: expected nothing with --tolerance (exactly one of them), got {args.dt!r}")
            if args.steps is not None:
                raise ValueError(f"--steps: expected nothing with --tolerance (the steps follow from the chosen dt; "
                                 f"give --duration), got {args.steps!r}")
            if duration is None:
                raise ValueError("--duration: expected a time span [s] (or duration in the scene's [run]) with "
                                 "--tolerance, got nothing")
            if args.no_error:
                raise ValueError("--no-error: expected nothing with --tolerance (the global error estimate "
                                 "certifies the run), got --no-error")
            self.method_given: str | None = None if args.method is None else require_method(args.method, "--method")
            self.method: str = self.method_given or "chosen"
            self.duration: float = duration
            self.dt: float = math.nan  # the run's choice, set after it
            self.steps = 0
            self.record_every: int = args.record_every if args.record_every is not None else 1
        else:
            self.method = require_method(args.method if args.method is not None else run.method, "--method")
            dt = args.dt if args.dt is not None else run.dt
            if dt is None:
                raise ValueError("--dt: expected a time step [s] > 0 (or dt in the scene's [run]), got nothing")
            self.dt = dt
            if args.steps is None and duration is None:
                raise ValueError("--duration: expected a time span [s] (or --steps, or duration in the scene's "
                                 "[run]), got nothing")
            self.steps = step_count(args.steps, duration, self.dt)
            self.record_every = (args.record_every if args.record_every is not None else
                                 max(run.record_every, -(-self.steps // MAX_DEFAULT_RECORDS)))
        if args.animate:
            raise ValueError(f"--animate: expected a problem file (scene files have no animation yet), "
                             f"got the scene {args.problem!r}")
        self.attitude = check_attitude(args.attitude)
        self.units = command_units(args.units)
        self.plot = not args.no_plot and _matplotlib()
        self.kinds = [type(body).__name__ for body in self.file.scene.bodies]
        self.out = OutFolder(args.out if args.out is not None else default_out(args.problem), self.outputs(),
                             args.force, SCENE_OUTPUTS)
        self.progress = not args.no_progress and self.tolerance is None  # the steps are not known before the run
        self.error = not args.no_error

    def outputs(self) -> list[str]:
        """The files this run writes."""
        from .simulate_command import table_outputs

        return table_outputs() + (["trajectory.png"] if self.plot else [])


def _matplotlib() -> bool:
    """True if matplotlib is installed (set to draw files only); else False, with a note on stderr."""
    try:
        import matplotlib

        matplotlib.use("Agg")  # files only, never a window
    except ImportError:
        print("rigiddyn simulate: no plot: matplotlib is not installed (pip install 'rigiddyn[plot]')", file=sys.stderr)
        return False
    return True


def _run_record(plan: _ScenePlan, result: Any, columns: list[str]) -> dict[str, Any]:
    """run.json: what was run and what came out (numbers, null for not-a-number)."""
    from . import __version__
    from .output_units import units_record
    from .simulate_command import error_report

    def number(x: float) -> float | None:
        return float(x) if math.isfinite(x) else None

    return {
        "rigiddyn": __version__,
        "scene": plan.file.name,
        "source": plan.source,
        "method": plan.method,
        "dt [s]": plan.dt,
        "steps": plan.steps,
        "record_every": plan.record_every,
        "records": int(len(result.t)),
        "t_end [s]": number(result.t[-1]),
        "bodies": list(result.body_names),
        "elements": list(result.elements),
        "diverged": bool(result.diverged),
        "unconverged_steps": int(result.unconverged_steps),
        "elapsed_seconds [s]": result.elapsed_seconds,
        "global error": error_report(result.error),
        "controller": _controller_record(plan.file),
        "units": units_record(plan.units),
        "columns": columns,
        "quaternion order": "x, y, z, w",
        **_choice_record(result),
    }


def _controller_record(file: SceneFile) -> dict[str, Any] | None:
    """run.json's account of the file's [controller] (its table, in SI; None without one)."""
    from ._controller_table import controller_table
    from .scene_file import _body_names

    controller = file.run.controller
    return None if controller is None else controller_table(controller, file.scene, _body_names(file.scene))


def _choice_record(result: Any) -> dict[str, Any]:
    """run.json's account of a run to a tolerance (result.choice), {} for a run at a given dt."""
    c = result.choice
    if c is None:
        return {}
    return {"tolerance": c.tolerance, "measure": c.measure, "certified_error": c.certified_error,
            "predicted_error": c.predicted_error, "refinements": c.refinements, "choice": c.reason}


def _run(plan: _ScenePlan, update: Any) -> Any:
    """simulate of the scene under the file's [controller], if it has one: at the plan's dt, or to its tolerance
    (then the plan takes the chosen method, dt and steps)."""
    if plan.tolerance is None:
        return _core.simulate(plan.file.scene, plan.file.initial, dt=plan.dt, steps=plan.steps,
                              method=cast(Any, plan.method), record_every=plan.record_every,  # checked
                              progress=update, error=plan.error, controller=plan.file.run.controller)
    result = _core.simulate(plan.file.scene, plan.file.initial, duration=plan.duration, tolerance=plan.tolerance,
                            measure=plan.measure, max_steps=plan.max_steps, method=cast(Any, plan.method_given),
                            record_every=plan.record_every, progress=update, controller=plan.file.run.controller)
    plan.method, plan.dt, plan.steps = result.choice.method, result.choice.dt, result.choice.steps
    return result


def _write(plan: _ScenePlan, result: Any, folder: Path) -> list[Path]:
    """The files of the run, written to `folder`; returns their paths."""
    from .scene_result import column_names
    from .trajectory import write_csv, write_npz, write_parquet

    record = _run_record(plan, result, column_names(result, units=plan.units))
    written = [write_csv(result, folder / "trajectory.csv", units=plan.units),
               write_npz(result, folder / "trajectory.npz", units=plan.units)]
    if "trajectory.parquet" in plan.out.outputs:
        written.append(write_parquet(result, folder / "trajectory.parquet", metadata=record, units=plan.units))
    else:
        print("rigiddyn simulate: no Parquet file: it needs pyarrow (pip install 'rigiddyn[parquet]')", file=sys.stderr)
    (folder / "run.json").write_text(json.dumps(record, indent=2) + "\n")
    written.append(folder / "run.json")
    if plan.plot:
        from .trajectory_plot import plot_scene

        title = f"{plan.file.name}: {plan.method}, dt = {plan.dt:g} s"
        written.append(plot_scene(result, plan.kinds, folder / "trajectory.png", plan.attitude, title,
                                  units=plan.units))
    return written


def conservative(scene: Any) -> bool:
    """True if every element of `scene` derives from a potential and depends on neither the velocities
    nor the time (CompiledScene.element_traits; a SpringDamper only without damping): its total energy
    (in a moving frame, the Jacobi integral) is then conserved, else its elements do work that the energy
    balance accounts for. The frame's fictitious terms are not asked: they are the frame's, not work done."""
    if scene is None or not scene.elements:
        return True
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        traits = scene.compile("rk4").element_traits[:len(scene.elements)]
    return all(t["has_potential"] and not t["velocity_dependent"] and not t["time_dependent"] for t in traits)


def _summary(result: Any, scene: Any = None, controlled: bool = False) -> str:
    """One line: records, bodies, time; the energy drift (or, with mass flows, the mass burnt; under a
    controller, whose commands change the elements, the energy balance); the range of each pivot's reaction
    force."""
    n = len(result.body_names)
    head = (f"{len(result.t)} records of {n} {'body' if n == 1 else 'bodies'} to t = {result.t[-1]:.6g} s in "
            f"{result.elapsed_seconds:.3g} s")
    flows = [i for i, f in enumerate(getattr(scene, "mass_flows", None) or []) if f is not None]
    parts = [head]
    if flows:
        mass = np.asarray(result.mass)
        parts += [f"{result.body_names[i]}: mass {mass[0, i]:.6g} -> {mass[-1, i]:.6g} kg "
                  f"({mass[0, i] - mass[-1, i]:.6g} kg burnt)" for i in flows]
        parts.append("total energy not conserved (the thrust works)")
    elif controlled or not conservative(scene):  # damping, drag, loads, commands: every element's work against T's
        from .simulate_command import energy_balance

        work = np.sum(np.asarray(result.work).reshape(len(result.t), -1), axis=1)
        parts.append(energy_balance(result.kinetic_energy, work, "every element"))
    else:
        E = np.asarray(result.total_energy)
        drift = f"{(E[-1] - E[0]) / abs(E[0]):+.2e}" if E[0] != 0 else f"{E[-1] - E[0]:+.2e} J (absolute)"
        jacobi = " (the Jacobi integral)" if getattr(scene, "frame", None) is not None else ""
        parts.append(f"relative drift of the total energy{jacobi} {drift}")
    pinned = [i for i, b in enumerate(getattr(scene, "bodies", [])) if type(b).__name__.startswith("Pivoted")]
    if pinned:
        reaction = np.linalg.norm(np.asarray(result.pivot_reaction_W), axis=2)
        parts += [f"{result.body_names[i]}: pivot reaction |R| {reaction[:, i].min():.4g} to "
                  f"{reaction[:, i].max():.4g} N" for i in pinned]
    if getattr(result, "choice", None) is not None:
        parts.append(f"tolerance {result.choice.tolerance:g} ({result.choice.measure}): {result.choice.reason}")
    return "; ".join(parts)


def run_scene_simulate(args: argparse.Namespace) -> int:
    """The `simulate` command of a scene file: check everything, run, write; returns the exit code
    (rigiddyn.out_folder's, as simulate_command.run_simulate)."""
    from .simulate_command import fail, run_and_report

    try:
        plan = _ScenePlan(args)
    except (ValueError, TypeError, OSError, Warning) as e:
        return fail(e)
    except OutputExists as e:
        return fail(e, EXIT_EXISTS)
    return run_and_report(plan.steps, plan.progress, lambda update: _run(plan, update),
                          lambda result: _summary(result, plan.file.scene, plan.file.run.controller is not None),
                          plan.out,
                          lambda result, folder: _write(plan, result, folder))
