"""Speed against accuracy on the user's own problem: a work-precision sweep over methods and steps.

For each method x dt, `tradeoff` runs the C++ `simulate` over the problem's horizon, measures the
cost (wall time of the C++ loop per step; derivative evaluations per step from `methods()`), and
compares every recorded state with a reference at the same times:

- ``"exact"`` when the problem has a closed form: torque-free rotation (`TorqueFreeSolution`,
  Euler-Poinsot) and a centre of mass under gravity and world-fixed piecewise-constant forces
  (p = p0 + v0 t + a t^2/2 on each piece);
- ``"richardson"`` otherwise: the highest-order method at dt/2^j, refined (j = 1, 2, ...) until its
  Richardson estimate |y_{h/2} - y_h| / (2^p - 1) is below a tenth of the errors it referees.

Error measures (the SciML work-precision convention, shared/notes/free-rigid-body.md), "final_"
at the horizon and "max_" over the recorded states:
  attitude_error  geodesic angle |log(q_ref^-1 q)| [rad]
  momentum_error  |I (w_B - w_ref)| / |I w_ref| (body angular momentum relative to G)
  position_error  |p_W - p_ref| [m];  velocity_error |v_W - v_ref| [m/s]
  state_error     max of attitude, momentum, position / L_p and velocity / L_v (dimensionless;
                  L_p = max(radius of gyration, distance travelled), L_v = max(speed, L_p / horizon))
  energy_drift    max_t |T - T_ref| / max_t T_ref (kinetic energy)
  momentum_drift  max_t ||I w| - |I w_ref|| / max_t |I w_ref| (|L| drift)
  quaternion_norm_error  max_t ||q| - 1|
observed_order: slope of log(measure) against log(dt) from the next larger dt of the same method;
  nan (not applicable) for a method that is exact on the problem (order 0, or exact_torque_free on a
  torque-free problem: its error is round-off at every dt) and where either error is round-off
  (below ROUND_OFF_PER_STEP x steps), whose slope says nothing about the truncation error.
"""

from __future__ import annotations

import csv
import io
import json
import math
import sys
import warnings
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from . import _core
from .problem import Problem, load_problem
from .stability import StabilityWarning, stability_message

__all__ = ["COLUMNS", "MEASURES", "Recommendation", "TradeoffResult", "reference_states", "tradeoff"]

_QUANTITIES = ("state_error", "attitude_error", "momentum_error", "position_error", "velocity_error")
MEASURES = tuple(f"{w}_{q}" for q in _QUANTITIES for w in ("final", "max")) + (
    "energy_drift", "momentum_drift", "quaternion_norm_error")
COLUMNS = ("method", "dt", "steps", "order", "evaluations_per_step", "time_per_step", "total_time",
           "total_evaluations") + MEASURES + ("observed_order", "reference", "reference_error", "diverged",
                                              "stability")
_COSTS = {"time": "total_time", "evaluations": "total_evaluations"}
SAMPLES = 200  # states compared per run (every k-th step)
ROUND_OFF_PER_STEP = 100 * np.finfo(float).eps  # errors below this x steps are round-off
MIN_TIMED_SECONDS = 2e-2  # time each run at least twice, up to 5 times until this much; keep the fastest


# ---------------------------------------------------------------------------------------------
# states and references at given times


@dataclass
class States:
    """States at n times: t (n,), p_W (n, 3), q_WB (n, 4) (x, y, z, w), v_W (n, 3), w_B (n, 3)."""

    t: np.ndarray
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray


def _states(result: Any) -> States:
    return States(np.asarray(result.t), np.asarray(result.p_W), np.asarray(result.q_WB),
                  np.asarray(result.v_W), np.asarray(result.w_B))


def _ballistic(problem: Problem, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """p_W, v_W (n, 3) of the centre of mass under gravity and world-fixed piecewise-constant forces:
    on each piece p = p0 + v0 s + a s^2/2, v = v0 + a s."""
    breaks = sorted({b for load in problem.loads for b in (load.t_start, load.t_end) if 0.0 < b < t.max()})
    edges = [0.0] + breaks + [math.inf]
    p0, v0 = problem.p_W.astype(float), problem.v_W.astype(float)
    p, v = np.empty((t.size, 3)), np.empty((t.size, 3))
    for start, end in zip(edges[:-1], edges[1:]):
        a = problem.gravity + sum((load.force for load in problem.loads if load.t_start <= start < load.t_end),
                                  np.zeros(3)) / problem.mass
        inside = (t >= start) & (t < end)
        s = (t[inside] - start)[:, None]
        p[inside], v[inside] = p0 + v0 * s + 0.5 * a * s**2, v0 + a * s
        if math.isfinite(end):
            span = end - start
            p0, v0 = p0 + v0 * span + 0.5 * a * span**2, v0 + a * span
    return p, v


def reference_states(problem: Problem, t: np.ndarray) -> States:
    """The exact states of `problem` at times t (n,) [s]; ValueError if it has no closed form."""
    if not problem.has_exact_solution:
        raise ValueError("problem: expected torque-free rotation and world-fixed forces (a closed form), got "
                         "body torques or body-frame forces")
    t = np.asarray(t, float)
    q, w = _core.TorqueFreeSolution(problem.inertia_com, problem.q_WB, problem.w_B).state_at(t)
    p, v = _ballistic(problem, t)
    return States(t, p, np.asarray(q), v, np.asarray(w))


# ---------------------------------------------------------------------------------------------
# error measures


def _attitude_angle(q_ref: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Geodesic angle 2 atan2(|vec(q_ref^-1 q)|, |scalar|) [rad], rows (x, y, z, w)."""
    a_v, a_w, b_v, b_w = q_ref[:, :3], q_ref[:, 3:], q[:, :3], q[:, 3:]
    vec = a_w * b_v - b_w * a_v - np.cross(a_v, b_v)
    scalar = np.abs(a_w[:, 0] * b_w[:, 0] + np.sum(a_v * b_v, axis=1))
    return np.asarray(2.0 * np.arctan2(np.linalg.norm(vec, axis=1), scalar))


def _measures(problem: Problem, run: States, ref: States, quaternion_norm_error: np.ndarray) -> dict[str, float]:
    inertia, mass = problem.inertia_com, problem.mass
    h, h_ref = run.w_B @ inertia.T, ref.w_B @ inertia.T
    g_ref = np.linalg.norm(h_ref, axis=1)
    g_scale = np.maximum(g_ref, np.finfo(float).tiny)
    radius = math.sqrt(np.trace(inertia) / (2.0 * mass))  # radius of gyration about a mean axis [m]
    length = max(radius, float(np.max(np.linalg.norm(ref.p_W - ref.p_W[0], axis=1))))
    speed = max(float(np.max(np.linalg.norm(ref.v_W, axis=1))), length / problem.horizon)
    series = {
        "attitude_error": _attitude_angle(ref.q_WB, run.q_WB),
        "momentum_error": np.linalg.norm(h - h_ref, axis=1) / g_scale,
        "position_error": np.linalg.norm(run.p_W - ref.p_W, axis=1),
        "velocity_error": np.linalg.norm(run.v_W - ref.v_W, axis=1),
    }
    series["state_error"] = np.max([series["attitude_error"], series["momentum_error"],
                                    series["position_error"] / length, series["velocity_error"] / speed], axis=0)
    out = {}
    for name, values in series.items():
        out[f"final_{name}"], out[f"max_{name}"] = float(values[-1]), float(np.max(values))

    def kinetic(s: States) -> np.ndarray:
        return np.asarray(0.5 * mass * np.sum(s.v_W**2, axis=1) + 0.5 * np.sum(s.w_B * (s.w_B @ inertia.T), axis=1))

    t_ref = kinetic(ref)
    out["energy_drift"] = float(np.max(np.abs(kinetic(run) - t_ref)) / max(np.max(t_ref), np.finfo(float).tiny))
    out["momentum_drift"] = float(np.max(np.abs(np.linalg.norm(h, axis=1) - g_ref)) / np.max(g_scale))
    out["quaternion_norm_error"] = float(np.max(np.abs(quaternion_norm_error)))
    return out


# ---------------------------------------------------------------------------------------------
# runs


@dataclass
class _Run:
    states: States
    quaternion_norm_error: np.ndarray
    diverged: bool
    time_per_step: float


def _simulate(problem: Problem, method: str, dt: float, steps: int, record_every: int, timed: bool) -> _Run:
    body, initial, loads = problem.body(), problem.initial_state(), problem.applied_loads()
    best, spent = math.inf, 0.0
    for repeat in range(5 if timed else 1):
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="simulate: the state became non-finite", category=RuntimeWarning)
            result = _core.simulate(body, initial, dt, steps, method, record_every=record_every, loads=loads,
                                    gravity=problem.gravity)
        best, spent = min(best, result.elapsed_seconds / max(steps, 1)), spent + result.elapsed_seconds
        if result.diverged or (repeat >= 1 and spent >= MIN_TIMED_SECONDS):
            break
    return _Run(_states(result), np.asarray(result.quaternion_norm_error), bool(result.diverged), best)


def _reference_method(methods_info: dict[str, dict[str, Any]]) -> str:
    """The highest-order method; ties go to one that keeps SO(3) exactly."""
    return str(max(methods_info.values(), key=lambda m: (m["order"], "SO(3)" in m["conserves"]))["name"])


def _richardson_reference(problem: Problem, method: str, order: int, dt: float, steps: int, record_every: int,
                          runs: Sequence[_Run], max_steps: int) -> tuple[States, dict[str, float]]:
    """(reference States, estimate of its error per measure): `method` at dt/2^j, j = 1, 2, ..., until
    the Richardson estimate of max_state_error is below a tenth of every run's error, hits round-off,
    or the next refinement would exceed max_steps."""
    zeros = np.zeros(1)
    sub = 2
    coarse = _simulate(problem, method, dt / sub, steps * sub, record_every * sub, timed=False)
    while True:
        fine = _simulate(problem, method, dt / (2 * sub), steps * 2 * sub, record_every * 2 * sub, timed=False)
        sub *= 2
        if fine.diverged or coarse.diverged:
            coarse = fine
            if steps * 2 * sub > max_steps:
                raise RuntimeError(f"reference: {method} diverged even at dt = {dt / sub:.3g} s")
            continue
        estimate = {k: v / (2**order - 1) for k, v in _measures(problem, fine.states, coarse.states, zeros).items()}
        errors = [_measures(problem, r.states, fine.states, zeros)["max_state_error"] for r in runs if not r.diverged]
        target = 0.1 * min(errors, default=0.0)
        if estimate["max_state_error"] <= max(target, 1e-14) or steps * 2 * sub > max_steps:
            return fine.states, estimate
        coarse = fine


def _fmt(x: Any) -> str:
    if isinstance(x, float):
        return f"{x:.3g}" if math.isfinite(x) else str(x)
    return str(x)


# ---------------------------------------------------------------------------------------------
# results


@dataclass
class Recommendation:
    """The cheapest (method, dt) whose `measure` is <= tolerance (row is None if none is)."""

    measure: str
    tolerance: float
    cost: str
    row: dict[str, Any] | None
    best: dict[str, Any] | None  # the most accurate run, for "none meets it"

    @property
    def met(self) -> bool:
        return self.row is not None

    def __str__(self) -> str:
        if self.row is not None:
            r = self.row
            return (f"recommendation: {r['method']} with dt = {_fmt(r['dt'])} s ({r['steps']} steps): "
                    f"{self.measure} = {_fmt(r[self.measure])} <= tolerance {_fmt(self.tolerance)}, "
                    f"cost {_fmt(r['total_time'])} s ({_fmt(r['time_per_step'] * 1e9)} ns/step), "
                    f"{r['total_evaluations']} derivative evaluations; reference ({r['reference']}) error "
                    f"{_fmt(r['reference_error'])}")
        if self.best is None:
            return f"recommendation: none; every run diverged ({self.measure}, tolerance {_fmt(self.tolerance)})"
        b = self.best
        return (f"recommendation: none meets {self.measure} <= {_fmt(self.tolerance)}; best is {b['method']} "
                f"with dt = {_fmt(b['dt'])} s: {self.measure} = {_fmt(b[self.measure])} at {_fmt(b['total_time'])} s; "
                f"try smaller steps or a higher-order method")


@dataclass
class TradeoffResult:
    """Rows (one per method x dt, keys COLUMNS) and the recommendation for the sweep's tolerance."""

    problem: str
    horizon: float
    measure: str
    tolerance: float | None
    rows: list[dict[str, Any]]
    cost: str = "time"
    recommendation: Recommendation | None = field(default=None)

    def __post_init__(self) -> None:
        if self.recommendation is None and self.tolerance is not None:
            self.recommendation = self.recommend(self.tolerance, self.measure, self.cost)

    def recommend(self, tolerance: float, measure: str | None = None, cost: str = "time") -> Recommendation:
        """The cheapest run (cost 'time': total wall time; 'evaluations': derivative evaluations) whose
        `measure` is <= tolerance, diverged runs excluded."""
        measure = measure or self.measure
        _check_measure(measure)
        if cost not in _COSTS:
            raise ValueError(f"cost: expected one of {', '.join(_COSTS)}, got {cost!r}")
        usable = [r for r in self.rows if not r["diverged"] and math.isfinite(r[measure])]
        meeting = [r for r in usable if r[measure] <= tolerance]
        row = min(meeting, key=lambda r: (r[_COSTS[cost]], r[measure])) if meeting else None
        best = min(usable, key=lambda r: (r[measure], r[_COSTS[cost]])) if usable else None
        return Recommendation(measure, float(tolerance), cost, row, best)

    def methods(self) -> list[str]:
        return list(dict.fromkeys(r["method"] for r in self.rows))

    # -- text
    def to_table(self, columns: Sequence[str] = ("method", "dt", "steps", "time_per_step", "total_evaluations",
                                                  "final_state_error", "max_state_error", "max_attitude_error",
                                                  "energy_drift", "momentum_drift", "quaternion_norm_error",
                                                  "observed_order", "stability")) -> str:
        """A fixed-width text table of `columns` (time_per_step shown in ns)."""
        headers = [("ns/step" if c == "time_per_step" else c) for c in columns]
        cells = []
        for r in self.rows:
            line = []
            for c in columns:
                v = r[c]
                if c == "time_per_step":
                    v = v * 1e9
                if c == "stability":
                    v = "beyond limit" if v else ""
                if c == "method" and r["diverged"]:
                    v = f"{v} (diverged)"
                line.append(_fmt(v))
            cells.append(line)
        widths = [max(len(h), *(len(line[i]) for line in cells)) if cells else len(h) for i, h in enumerate(headers)]
        out = [f"{self.problem}: horizon {_fmt(self.horizon)} s, measure {self.measure}",
               "  ".join(h.ljust(w) for h, w in zip(headers, widths)),
               "  ".join("-" * w for w in widths)]
        out += ["  ".join(v.ljust(w) for v, w in zip(line, widths)) for line in cells]
        if self.recommendation is not None:
            out.append(str(self.recommendation))
        return "\n".join(out)

    def __str__(self) -> str:
        return self.to_table()

    # -- CSV / JSON
    def to_csv(self, path: str | Path | None = None) -> str:
        """All COLUMNS as CSV (floats with 17 significant digits); written to `path` if given."""
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        for r in self.rows:
            writer.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in r.items()})
        text = buf.getvalue()
        if path is not None:
            Path(path).write_text(text)
        return text

    @staticmethod
    def read_csv(path_or_text: str | Path, problem: str = "", horizon: float = math.nan,
                 measure: str = "final_attitude_error", tolerance: float | None = None) -> TradeoffResult:
        text = Path(path_or_text).read_text() if _is_file(path_or_text) else str(path_or_text)
        rows = [_typed_row(r) for r in csv.DictReader(io.StringIO(text))]
        return TradeoffResult(problem, horizon, measure, tolerance, rows)

    def to_dict(self) -> dict[str, Any]:
        rec = self.recommendation
        return {"problem": self.problem, "horizon": self.horizon, "measure": self.measure,
                "tolerance": self.tolerance, "cost": self.cost, "rows": self.rows,
                "recommendation": None if rec is None else {"met": rec.met, "text": str(rec), "row": rec.row,
                                                            "best": rec.best}}

    def to_json(self, path: str | Path | None = None) -> str:
        """JSON with the sweep's settings, rows and recommendation (inf/nan as JSON strings)."""
        text = json.dumps(_json_safe(self.to_dict()), indent=1)
        if path is not None:
            Path(path).write_text(text)
        return text

    @staticmethod
    def read_json(path_or_text: str | Path) -> TradeoffResult:
        text = Path(path_or_text).read_text() if _is_file(path_or_text) else str(path_or_text)
        d = _json_restore(json.loads(text))
        return TradeoffResult(d["problem"], d["horizon"], d["measure"], d["tolerance"], d["rows"], d.get("cost", "time"))

    # -- plot
    def plot(self, path: str | Path, formats: Sequence[str] = ("png", "svg"),
             measure: str | None = None) -> list[Path]:
        """Work-precision plot (log-log; `measure` against wall time and against derivative
        evaluations, one line per method, the tolerance as a dashed line, the recommendation
        circled); written as path.<format> for each format. Needs matplotlib (pip install
        'rigiddyn[plot]'). Returns the files written."""
        try:
            import matplotlib

            matplotlib.use("Agg") if "matplotlib.pyplot" not in sys.modules else None
            import matplotlib.pyplot as plt
        except ImportError:
            raise ImportError("plot: expected matplotlib (pip install 'rigiddyn[plot]' or pip install matplotlib)") from None
        measure = measure or self.measure
        _check_measure(measure)
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
        for ax, cost, label in ((axes[0], "total_time", "wall time of the run [s]"),
                                (axes[1], "total_evaluations", "derivative evaluations")):
            for method in self.methods():
                rows = [r for r in self.rows if r["method"] == method and not r["diverged"]
                        and r[measure] > 0 and math.isfinite(r[measure])]
                if rows:
                    ax.loglog([r[cost] for r in rows], [r[measure] for r in rows], "o-", label=method)
            if self.tolerance is not None:
                ax.axhline(self.tolerance, color="gray", linestyle="--", linewidth=1, label="tolerance")
            rec = self.recommendation
            if rec is not None and rec.row is not None and rec.row[measure] > 0:
                ax.loglog([rec.row[cost]], [rec.row[measure]], "o", markersize=14, markerfacecolor="none",
                          markeredgecolor="black", label="recommended")
            ax.set_xlabel(label)
            ax.set_ylabel(measure)
            ax.grid(True, which="both", alpha=0.3)
        axes[0].legend(fontsize=8)
        fig.suptitle(f"{self.problem}: work-precision over {_fmt(self.horizon)} s")
        written = []
        for fmt in formats:
            out = Path(f"{path}.{fmt}")
            fig.savefig(out)
            written.append(out)
        plt.close(fig)
        return written


def _is_file(x: str | Path) -> bool:
    try:
        return Path(x).is_file()
    except (OSError, ValueError):
        return False


_INT_COLUMNS = {"steps", "order", "evaluations_per_step", "total_evaluations"}
_STR_COLUMNS = {"method", "reference", "stability"}


def _typed_row(r: dict[str, str]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in r.items():
        if k in _INT_COLUMNS:
            out[k] = int(v)
        elif k in _STR_COLUMNS:
            out[k] = v
        elif k == "diverged":
            out[k] = v == "True"
        else:
            out[k] = float(v)
    return out


def _json_safe(x: Any) -> Any:
    if isinstance(x, float) and not math.isfinite(x):
        return str(x)
    if isinstance(x, dict):
        return {k: _json_safe(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_json_safe(v) for v in x]
    return x


def _json_restore(x: Any) -> Any:
    if isinstance(x, str) and x in ("inf", "-inf", "nan"):
        return float(x)
    if isinstance(x, dict):
        return {k: _json_restore(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_json_restore(v) for v in x]
    return x


def _check_measure(measure: str) -> None:
    if measure not in MEASURES:
        raise ValueError(f"measure: expected one of {', '.join(MEASURES)}, got {measure!r}")


class _Progress:
    """tqdm if installed, else a counter on stderr."""

    def __init__(self, total: int, enabled: bool) -> None:
        self.total, self.done, self.bar = total, 0, None
        self.enabled = enabled
        if enabled:
            try:
                from tqdm import tqdm

                self.bar = tqdm(total=total, desc="tradeoff", unit="run", file=sys.stderr)
            except ImportError:
                pass

    def update(self, label: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.set_postfix_str(label)
            self.bar.update(1)
        else:
            print(f"\rtradeoff: {self.done}/{self.total} {label:<40}", end="", file=sys.stderr, flush=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.enabled:
            print(file=sys.stderr)


def _default_dts(problem: Problem) -> list[float]:
    """Eight halvings from dt*rho = 1, rho = the fastest rate of the spin (or the horizon / 16)."""
    rho = max(float(np.linalg.norm(problem.w_B)), 1e-300)
    dt0 = min(1.0 / rho, problem.horizon / 16)
    return [dt0 / 2**j for j in range(8)]


def _exact_on(problem: Problem, info: dict[str, Any]) -> bool:
    """True if the method has no truncation error on `problem` (order 0, or exact on torque-free bodies)."""
    return info["order"] == 0 or (info["exact_torque_free"] and problem.torque_free)


def _observed_orders(rows: list[dict[str, Any]], measure: str, exact_methods: set[str]) -> None:
    for method in dict.fromkeys(r["method"] for r in rows):
        mine = sorted((r for r in rows if r["method"] == method), key=lambda r: -r["dt"])
        mine[0]["observed_order"] = math.nan
        for coarse, fine in zip(mine[:-1], mine[1:]):
            e0, e1 = coarse[measure], fine[measure]
            above_round_off = min(e0 / coarse["steps"], e1 / fine["steps"]) > ROUND_OFF_PER_STEP
            ok = (method not in exact_methods and above_round_off and math.isfinite(e0) and math.isfinite(e1)
                  and coarse["dt"] != fine["dt"])
            fine["observed_order"] = math.log(e0 / e1) / math.log(coarse["dt"] / fine["dt"]) if ok else math.nan


def tradeoff(problem: Problem | str | Path, methods: Iterable[str] | None = None,
             dts: Iterable[float] | None = None, horizon: float | None = None,
             tolerance: float | None = None, measure: str | None = None, progress: bool = True,
             cost: str = "time", samples: int = SAMPLES, max_reference_steps: int = 4_000_000) -> TradeoffResult:
    """Run every method x dt on `problem` (a Problem, a TOML path or an example name) and measure
    cost and error against a reference (see the module docstring).

    methods: names from methods() (default: the file's [tradeoff] list, else all that can run the problem:
    `exact` only for a torque-free body); dts [s]
    (default: the file's, else eight halvings from dt |w| = 1); each dt is adjusted to
    horizon / round(horizon / dt) so that every run ends exactly at the horizon [s] (default:
    the problem's). tolerance/measure: the recommendation's criterion (measure in MEASURES,
    default final_attitude_error). cost: 'time' or 'evaluations' for the recommendation.
    samples: states compared per run. Emits one StabilityWarning listing the runs whose dt is
    beyond the method's linear stability limit (rigiddyn.stability); diverged runs get inf errors.
    """
    if not isinstance(problem, Problem):
        problem = load_problem(problem)
    if horizon is not None:
        problem = problem.with_horizon(horizon)
    defaults = problem.tradeoff
    info = {m["name"]: m for m in _core.methods()}
    # by default every method that can run the problem: the exact flow (order 0) is for torque-free bodies only
    runnable = [name for name, m in info.items() if m["order"] != 0 or problem.torque_free]
    methods = list(methods if methods is not None else defaults.get("methods", runnable))
    for name in methods:
        if name not in info:
            raise ValueError(f"methods: expected names from {', '.join(info)}, got {name!r}")
    dts = [float(d) for d in (dts if dts is not None else defaults.get("dts", _default_dts(problem)))]
    if not dts or not all(math.isfinite(d) and d > 0 for d in dts):
        raise ValueError(f"dts: expected a non-empty list of finite steps > 0 [s], got {dts!r}")
    measure = measure or defaults.get("measure", "final_attitude_error")
    _check_measure(measure)
    tolerance = tolerance if tolerance is not None else defaults.get("tolerance")
    if tolerance is not None and not (math.isfinite(tolerance) and tolerance > 0):
        raise ValueError(f"tolerance: expected a finite number > 0, got {tolerance!r}")
    if cost not in _COSTS:
        raise ValueError(f"cost: expected one of {', '.join(_COSTS)}, got {cost!r}")

    exact = problem.has_exact_solution
    ref_method = _reference_method(info)
    grid = sorted({max(1, round(problem.horizon / d)) for d in dts})
    bar = _Progress(len(grid) * len(methods), progress)
    rows: list[dict[str, Any]] = []
    unstable: list[str] = []
    try:
        for steps in grid:
            dt = problem.horizon / steps
            every = max(1, steps // samples)
            runs = []
            for method in methods:
                runs.append(_simulate(problem, method, dt, steps, every, timed=True))
                bar.update(f"{method} dt={dt:.3g}")
            if exact:
                ref_error = 0.0
            else:
                ref, estimate = _richardson_reference(problem, ref_method, info[ref_method]["order"], dt, steps,
                                                      every, runs, max_reference_steps)
                ref_error = estimate[measure]
            for method, run in zip(methods, runs):
                m = info[method]
                row: dict[str, Any] = {"method": method, "dt": dt, "steps": steps, "order": m["order"],
                                       "evaluations_per_step": m["evaluations"], "time_per_step": run.time_per_step,
                                       "total_time": run.time_per_step * steps,
                                       "total_evaluations": m["evaluations"] * steps}
                if run.diverged:
                    row.update({k: math.inf for k in MEASURES})
                else:
                    if exact:
                        ref = reference_states(problem, run.states.t)
                    row.update(_measures(problem, run.states, ref, run.quaternion_norm_error))
                message = stability_message(method, dt, steps, problem.inertia_com, problem.w_B, problem.torque_free)
                if message:
                    unstable.append(message)
                row.update({"observed_order": math.nan, "reference": "exact" if exact else f"richardson({ref_method})",
                            "reference_error": ref_error, "diverged": run.diverged, "stability": message or ""})
                rows.append(row)
    finally:
        bar.close()
    _observed_orders(rows, measure, {m for m in methods if _exact_on(problem, info[m])})
    rows.sort(key=lambda r: (methods.index(r["method"]), -r["dt"]))
    if unstable:
        warnings.warn("tradeoff: some steps are beyond the method's stability limit:\n  " + "\n  ".join(unstable),
                      StabilityWarning, stacklevel=2)
    return TradeoffResult(problem.name, problem.horizon, measure, tolerance, rows, cost)
