"""Speed against accuracy on the user's own problem: a work-precision sweep over methods and steps.

The sweep is the function `rigiddyn.tradeoff` (this module, rigiddyn.work_precision, holds it and its
result, TradeoffResult). For each method x dt, `tradeoff` runs the C++ `simulate` over the problem's
horizon, measures the cost (wall time of the C++ loop per step; derivative evaluations per step from
`methods()`), and compares every recorded state with a reference at the same times:

- ``"exact"`` when the problem has a closed form: torque-free rotation (`TorqueFreeSolution`,
  Euler-Poinsot) and a centre of mass under gravity and world-fixed piecewise-constant forces
  (p = p0 + v0 t + a t^2/2 on each piece);
- ``"richardson(<method>)"`` otherwise: the highest-order method at dt/2^j, refined (j = 1, 2, ...)
  until its Richardson estimate |y_{h/2} - y_h| / (2^p - 1) is below REFERENCE_TARGET x the errors
  it referees. That estimate only holds in the method's asymptotic range, so the reference is checked
  against a second, independent one: SciPy's DOP853 (another method family, adaptive, run in pieces
  between the switch times of the loads) at rtol DOP853_RTOL, its own error estimated by a second
  run at 10 x rtol; without SciPy, or beyond DOP853_MAX_STEPS, the other 4th-order family of the
  core (splitting or Runge-Kutta-Munthe-Kaas) at the reference's finest step, with its own
  Richardson estimate. If the two disagree by more than CHECK_FACTOR x the Richardson estimate
  (plus the second reference's own error), the reference is reported ``"unreliable: ..."``.
  reference_error is the larger of the Richardson estimate and the disagreement less the second
  reference's error (what the reference's error must at least be); reference_check says what was
  compared. Loads switching inside a step cost no accuracy: `simulate` splits such a step at the
  switch time, so every method keeps its order.

Error measures (the SciML work-precision convention), "final_"
at the horizon and "max_" over the recorded states:
  attitude_error  geodesic angle |log(q_ref^-1 q)| [rad]
  momentum_error  |I (w_B - w_ref)| / |I w_ref| (body angular momentum relative to G)
  position_error  |p_W - p_ref| [m];  velocity_error |v_W - v_ref| [m/s]
  state_error     max of attitude, momentum, position / L_p and velocity / L_v (dimensionless;
                  L_p = max(radius of gyration, distance travelled), L_v = max(speed, L_p / horizon))
  energy_drift    max_t |T - T_ref| / max_t T_ref (kinetic energy)
  momentum_drift  max_t ||I w| - |I w_ref|| / max_t |I w_ref| (|L| drift)
  quaternion_norm_error  max_t ||q| - 1|
observed_order: slope of log(measure) against log(dt) between a run and the next larger dt of the
  same method, reported only in the asymptotic range: both errors above the floor (round-off,
  ROUND_OFF_PER_STEP x steps, and REFERENCE_MARGIN x reference_error) and the slope agreeing
  with a neighbouring pair's (within ORDER_AGREEMENT, relative), and not both errors 1 or more (in rad
  or relative: nothing left to converge). Otherwise nan, with the reason in
  order_note; also nan for a method that is exact on the problem (order 0, or exact_torque_free
  on a torque-free problem: its error is round-off at every dt).

estimate, effectivity, estimate_verdict: the run's own estimate of its error in the sweep's measure
  (`simulate(..., error=True)`'s `result.error`, global Richardson over runs at h, 2h and 4h; see
  GlobalError), from a separate untimed run of the same method, dt and records (the same states), beside
  the true error the reference gives: effectivity = estimate / measure (1: exact, below 1: an
  under-estimate) and the estimate's verdict ("reliable" or why not). The estimate covers the attitude,
  position and velocity errors (final_ at the horizon, max_ the largest over the records, of the bodies);
  for the other measures the columns are nan and the verdict says so. A reliable estimate promises an
  effectivity in [0.5, 2] (measured: docs/accuracy.md).
time_noise: how well a run's time repeats: (second fastest - fastest) / fastest of its repeated
  timings (nan for a run timed once; the time reported is the fastest). The sweep's timing noise is the
  NOISE_QUANTILE quantile over its runs (a minimum repeats better within a process than across runs).
  The recommendation by time counts two total times as equal when their ranges t (1 +- noise) overlap
  and breaks such ties by fewer derivative evaluations, then fewer steps (`cheapest`): timing noise
  does not flip it.
Without a tolerance there is no recommendation: the report gives the Pareto front of (cost, error)
instead, the runs that no other run beats in both (`pareto_front`).

A scene (many bodies, force elements; rigiddyn.Scene or a scene TOML file) is swept the same way by
scene_sweep, on the scene side that rigiddyn.scene_precision holds (SceneCase): Richardson reference
checked against another method family, the errors taken over the bodies, a method the scene refuses at
compile reported "not applicable: <reason>".

Before the sweep, a short timed probe of every method estimates the sweep's cost, printed on stderr
(progress=True), and a progress bar in steps follows the runs while stderr is a terminal (tqdm if
installed, else a plain one); progress=callable is called with the steps done instead, as simulate's.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import sys
import textwrap
import time
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence, Sized
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

import numpy as np

from . import _core
from ._measures import _UNITS, MEASURES, _check_measure, measure_help, measure_unit
from .problem import Problem, load_problem
from .scene_precision import SceneCase, SceneStates, _attitude_angle, scene_case
from .stability import StabilityWarning, scene_modes, scene_stability_message, stability_message

__all__ = ["COLUMNS", "MEASURES", "Recommendation", "TradeoffResult", "cheapest", "measure_unit", "pareto_front",
           "reference_states", "timing_noise", "tradeoff"]

COLUMNS = ("method", "dt", "steps", "order", "evaluations_per_step", "time_per_step", "time_noise", "total_time",
           "total_evaluations") + MEASURES + ("observed_order", "order_note", "reference", "reference_error",
                                              "reference_check", "diverged", "stability", "estimate",
                                              "effectivity", "estimate_verdict")
_COSTS = {"time": "total_time", "evaluations": "total_evaluations"}
SAMPLES = 200  # states compared per run (every k-th step)
ROUND_OFF_PER_STEP = np.finfo(float).eps  # errors below this x steps (one ulp per step) may be round-off
MIN_TIMED_SECONDS = 2e-2  # time each run at least twice, up to 5 times until this much; keep the fastest
LONG_RUN_SECONDS = 0.5  # a run this long is timed once
REFERENCE_TARGET = 0.01  # the Richardson reference is refined until its error is this x the runs' errors
REFERENCE_MARGIN = 10.0  # an error within this factor of the reference's says nothing about the method
ORDER_AGREEMENT = 0.1  # neighbouring slopes p, p' agree if |p - p'| <= this x max(|p|, |p'|, 1)
CHECK_FACTOR = 10.0  # the second reference may disagree by this x the Richardson estimate (+ its own error)
CHECK_HALVINGS = 4  # a scene's independent check: its step halved at most this often below the reference's finest
DOP853_RTOL = 1e-13  # the independent reference's relative tolerance (its error: a second run at 10x)
DOP853_MAX_STEPS = 100_000  # per DOP853 run; beyond it the check uses the core's other 4th-order family
MAX_STEPS = 2**53  # steps of one run at most (exact in a float; far beyond any run that ends)
MAX_DTS = 64  # step sizes of one tradeoff at most (one run each; 8 halvings by default)
NOISE_QUANTILE = 0.9  # the sweep's timing noise: this quantile of its runs' time_noise
PROBE_STEPS = 2000  # steps of each method's timed probe for the cost estimate
_EPS = np.finfo(float).eps


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
    q, w = _core.TorqueFreeSolution(problem.inertia_com, problem.q_WB, problem.w_B,
                                    check=problem.inertia_check).state_at(t)
    p, v = _ballistic(problem, t)
    return States(t, p, np.asarray(q), v, np.asarray(w))


# ---------------------------------------------------------------------------------------------
# error measures


def _measures(problem: Problem | SceneCase, run: Any, ref: Any, quaternion_norm_error: np.ndarray) -> dict[str, float]:
    """The error measures of `run` against `ref` (States, or SceneStates of a scene) at the same times."""
    # a run far beyond its stability limit may end with finite states of 1e154 and more, whose squares
    # overflow (norms, the kinetic energy): its errors are then inf, the verdict (beyond any tolerance)
    # that a diverged run gets, without numpy's overflow warning
    with np.errstate(over="ignore"):
        if isinstance(problem, SceneCase):
            return problem.measures(run, ref, quaternion_norm_error)
        return _body_measures(problem, run, ref, quaternion_norm_error)


def _body_measures(problem: Problem, run: States, ref: States, quaternion_norm_error: np.ndarray) -> dict[str, float]:
    """_measures of one rigid body."""
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
    """A run's states, whether it diverged, its fastest time per step [s] over the repeats and the gap
    to the second fastest relative to it (nan if timed once)."""

    states: Any  # States, or SceneStates of a scene
    quaternion_norm_error: np.ndarray
    diverged: bool
    time_per_step: float
    time_noise: float = math.nan


def _core_simulate(problem: Problem | SceneCase, method: str, dt: float, steps: int, record_every: int,
                   progress: Callable[[int], None] | None = None, error: bool = False) -> Any:
    """_core.simulate of `problem`, or rigiddyn.simulate of a scene compiled for `method` (their non-finite
    and convergence warnings are the sweep's rows); `error`: with the run's error estimate (result.error)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="simulate: the state became non-finite", category=RuntimeWarning)
        warnings.filterwarnings("ignore", message="simulate: the implicit solve", category=RuntimeWarning)
        if isinstance(problem, SceneCase):
            return problem.simulate(method, dt, steps, record_every, progress, error=error)
        # method: a str of methods() (mypy knows their literal names), checked by the core
        return _core.simulate(problem.body(), problem.initial_state(), dt, steps, cast(Any, method), record_every=record_every,
                              loads=problem.applied_loads(), gravity=problem.gravity, progress=progress,
                              error=error, accuracy_level=None)  # the sweep's coarse steps are its rows


def _simulate(problem: Problem | SceneCase, method: str, dt: float, steps: int, record_every: int, timed: bool,
              bar: _Progress | None = None) -> _Run:
    """One run of `method`; timed: repeated (up to 5 times, until MIN_TIMED_SECONDS, once if longer than
    LONG_RUN_SECONDS) keeping the fastest time per step and the repeats' spread. `bar` follows the steps."""
    times: list[float] = []
    for repeat in range(5 if timed else 1):
        at = bar.begin(steps, f"{method} dt={dt:.3g}") if bar is not None else None
        result = _core_simulate(problem, method, dt, steps, record_every, at)
        if bar is not None:
            bar.end(steps)
        times.append(result.elapsed_seconds / max(steps, 1))
        spent = sum(times) * max(steps, 1)
        if result.diverged or spent >= LONG_RUN_SECONDS or (repeat >= 1 and spent >= MIN_TIMED_SECONDS):
            break
    fastest = sorted(times)[:2]  # the gap between the two fastest: how well the minimum repeats
    best = fastest[0]
    noise = (fastest[1] - best) / best if len(fastest) > 1 and best > 0 else math.nan
    if isinstance(problem, SceneCase):
        return _Run(problem.states(result), problem.quaternion_norm_error(result), bool(result.diverged), best, noise)
    return _Run(_states(result), np.asarray(result.quaternion_norm_error), bool(result.diverged), best, noise)


# the quantity of result.error (GlobalError) that estimates each error measure's quantity
_ESTIMATED = {"attitude_error": "attitude", "position_error": "position", "velocity_error": "velocity"}
# the records whose estimate is checked, or lies between two checked ones (GlobalError's verdicts)
_CHECKED = ("reliable", "interpolated between the reliable records")


def _estimate_columns(problem: Problem | SceneCase, method: str, dt: float, steps: int, record_every: int,
                      measure: str, true: float) -> dict[str, Any]:
    """The columns estimate, effectivity and estimate_verdict of a run (module docstring): an untimed run of
    `method` at dt with the same records as the timed one (the same states) and its error estimate, of
    `measure` (the largest over the bodies; max_: over the records too), against the true error `true`."""
    when, _, quantity = measure.partition("_")
    if quantity not in _ESTIMATED:
        return {"estimate": math.nan, "effectivity": math.nan,
                "estimate_verdict": f"no estimate of {measure} (estimated: attitude, position, velocity errors)"}
    error = _core_simulate(problem, method, dt, steps, record_every, error=True).error
    verdicts = list(error.verdict)
    values = np.asarray(getattr(error, _ESTIMATED[quantity]), float).reshape(len(verdicts), -1).max(axis=1)
    if when == "final":
        estimate, verdict = float(values[-1]), verdicts[-1]
    else:  # the largest estimate, reliable when every record is checked or between checked ones
        estimate = float(np.max(values)) if np.all(np.isfinite(values)) else math.nan
        verdict = next((v for v in verdicts if not v.startswith(_CHECKED)), "reliable")
    effectivity = estimate / true if true > 0 else (math.inf if estimate > 0 else math.nan)
    return {"estimate": estimate, "effectivity": effectivity, "estimate_verdict": verdict}


_NO_ESTIMATE = {"estimate": math.nan, "effectivity": math.nan}


def _reference_method(methods_info: dict[str, dict[str, Any]]) -> str:
    """The highest-order method; ties go to one that keeps SO(3) exactly."""
    return str(max(methods_info.values(), key=lambda m: (m["order"], "SO(3)" in m["conserves"]))["name"])


@dataclass
class _Reference:
    """A refined reference: its states, the Richardson estimate of its error per measure, the
    refinement sub (its finest step is dt / sub) and the record_every of that finest run."""

    states: States
    estimate: dict[str, float]
    sub: int
    record_every: int


def _richardson_reference(problem: Problem | SceneCase, method: str, order: int, dt: float, steps: int, record_every: int,
                          runs: Sequence[_Run], max_steps: int, bar: _Progress | None = None) -> _Reference:
    """`method` at dt/2^j, j = 1, 2, ..., until the Richardson estimate of max_state_error is below
    REFERENCE_TARGET x every run's error, hits round-off, or the next refinement would exceed max_steps."""
    zeros = np.zeros(1)
    sub = 2
    coarse = _simulate(problem, method, dt / sub, steps * sub, record_every * sub, timed=False, bar=bar)
    while True:
        fine = _simulate(problem, method, dt / (2 * sub), steps * 2 * sub, record_every * 2 * sub, timed=False,
                         bar=bar)
        sub *= 2
        if fine.diverged or coarse.diverged:
            coarse = fine
            if steps * 2 * sub > max_steps:
                raise RuntimeError(f"reference: {method} diverged even at dt = {dt / sub:.3g} s")
            continue
        estimate = {k: v / (2**order - 1) for k, v in _measures(problem, fine.states, coarse.states, zeros).items()}
        errors = [_measures(problem, r.states, fine.states, zeros)["max_state_error"] for r in runs if not r.diverged]
        target = REFERENCE_TARGET * min(errors, default=0.0)
        if estimate["max_state_error"] <= max(target, 1e-14) or steps * 2 * sub > max_steps:
            return _Reference(fine.states, estimate, sub, record_every * sub)
        coarse = fine


# ---------------------------------------------------------------------------------------------
# the independent reference that checks the Richardson one


def _switch_times(problem: Problem) -> list[float]:
    """The times in (0, horizon) at which the problem's loads switch."""
    return sorted({b for load in problem.loads for b in (load.t_start, load.t_end) if 0.0 < b < problem.horizon})


def _rate(problem: Problem, t: float) -> Callable[[float, np.ndarray], np.ndarray]:
    """The Newton-Euler equations of `problem` under the loads active at time t [s], on
    y = (p_W, q_WB (x, y, z, w), v_W, w_B): p' = v, q' = q (x) (w, 0) / 2, m v' = f_W + R f_B + m g,
    I w' = n_B + R^T n_W - w x I w (R of q / |q|). Written apart from the core: a second opinion."""
    active = [load for load in problem.loads if load.t_start <= t < load.t_end]
    f_W, f_B, n_W, n_B = (sum((getattr(load, kind) for load in active if load.frame == frame), np.zeros(3))
                          for kind, frame in (("force", "world"), ("force", "body"), ("torque", "world"),
                                              ("torque", "body")))
    # plain floats: np.cross on 3-vectors costs more than the whole rate in scalars
    inertia, inverse = problem.inertia_com.tolist(), np.linalg.inv(problem.inertia_com).tolist()
    a_W = ((f_W + problem.mass * problem.gravity) / problem.mass).tolist()  # world-fixed acceleration
    a_B, couple_W, couple_B = (f_B / problem.mass).tolist(), n_W.tolist(), n_B.tolist()

    def cross(a: Sequence[float], b: Sequence[float]) -> list[float]:
        return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

    def rotate(u: Sequence[float], u_w: float, x: Sequence[float]) -> list[float]:
        """x turned by the unit quaternion (u, u_w): x + 2 u_w (u x x) + 2 u x (u x x)."""
        twice = [2.0 * c for c in cross(u, x)]
        again = cross(u, twice)
        return [x[i] + u_w * twice[i] + again[i] for i in range(3)]

    def matrix_times(m: list[list[float]], x: Sequence[float]) -> list[float]:
        return [m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] for i in range(3)]

    def rate(_: float, y: np.ndarray) -> np.ndarray:
        _, _, _, x, yq, z, s, v0, v1, v2, w0, w1, w2 = y.tolist()
        q_vec, w = (x, yq, z), (w0, w1, w2)
        scale = 1.0 / math.sqrt(x * x + yq * yq + z * z + s * s)
        u = (x * scale, yq * scale, z * scale)
        q_x_w = cross(q_vec, w)
        turned_a = rotate(u, s * scale, a_B)
        turned_n = rotate((-u[0], -u[1], -u[2]), s * scale, couple_W)
        gyro = cross(w, matrix_times(inertia, w))
        alpha = matrix_times(inverse, [couple_B[i] + turned_n[i] - gyro[i] for i in range(3)])
        return np.array([v0, v1, v2,
                         0.5 * (s * w0 + q_x_w[0]), 0.5 * (s * w1 + q_x_w[1]), 0.5 * (s * w2 + q_x_w[2]),
                         -0.5 * (x * w0 + yq * w1 + z * w2),
                         a_W[0] + turned_a[0], a_W[1] + turned_a[1], a_W[2] + turned_a[2], *alpha])

    return rate


def _dop853_states(problem: Problem, times: np.ndarray, rtol: float, max_steps: int) -> States | None:
    """The states of `problem` at `times` (ascending, in [0, horizon]) by SciPy's DOP853 (dense
    output), restarted at each switch time of the loads; None without SciPy or beyond max_steps."""
    try:
        from scipy.integrate import DOP853
    except ImportError:
        return None
    y = np.concatenate([problem.p_W, problem.q_WB, problem.v_W, problem.w_B]).astype(float)
    radius = math.sqrt(np.trace(problem.inertia_com) / (2.0 * problem.mass))
    rate_scale = max(float(np.linalg.norm(problem.w_B)), 1.0 / problem.horizon)
    length = max(radius, float(np.linalg.norm(problem.p_W)))
    speed = max(float(np.linalg.norm(problem.v_W)), radius * rate_scale)
    atol = rtol * np.repeat([length, 1.0, speed, rate_scale], [3, 4, 3, 3])
    out = np.empty((times.size, 13))
    k = int(np.searchsorted(times, 0.0, side="right"))
    out[:k] = y
    # the last record time i dt may exceed the horizon by an ulp (dt = horizon / steps, rounded): the last
    # piece runs to it, so that every time is filled (an np.empty row left would be garbage)
    edges = [0.0] + _switch_times(problem) + [max(problem.horizon, float(times[-1]))]
    taken = 0
    for start, end in zip(edges[:-1], edges[1:]):
        solver = DOP853(_rate(problem, start), start, y, end, rtol=rtol, atol=atol)
        while solver.status == "running":
            solver.step()
            taken += 1
            if solver.status == "failed" or taken > max_steps:
                return None
            done = int(np.searchsorted(times, solver.t, side="right"))
            if done > k:
                out[k:done] = solver.dense_output()(times[k:done]).T
                k = done
        y = np.array(solver.y)
        y[3:7] /= np.linalg.norm(y[3:7])
    assert k == times.size, "every time is in [0, the last edge]"
    q = out[:, 3:7] / np.linalg.norm(out[:, 3:7], axis=1, keepdims=True)
    return States(times, out[:, 0:3], q, out[:, 7:10], out[:, 10:13])


def _at(states: States, times: np.ndarray) -> States:
    """The rows of `states` (at a superset of `times`, both ascending) at `times`."""
    rows = np.searchsorted(states.t, times)
    return States(states.t[rows], states.p_W[rows], states.q_WB[rows], states.v_W[rows], states.w_B[rows])


@dataclass
class _Independent:
    """The second reference for one step grid: its states, an estimate of its own error per measure and
    its name (for reference_check)."""

    states: States
    error: dict[str, float]
    name: str


def _dop853_reference(problem: Problem, times: np.ndarray) -> Callable[[np.ndarray], _Independent] | None:
    """DOP853 at DOP853_RTOL over all `times`, its error from a second run at 10 x rtol: a function of
    the times of one grid; None when not available (no SciPy, or too many steps)."""
    tight = _dop853_states(problem, times, DOP853_RTOL, DOP853_MAX_STEPS)
    loose = _dop853_states(problem, times, 10 * DOP853_RTOL, DOP853_MAX_STEPS) if tight is not None else None
    if tight is None or loose is None:
        return None
    zeros = np.zeros(1)

    def at(t: np.ndarray) -> _Independent:
        a, b = _at(tight, t), _at(loose, t)
        return _Independent(a, _measures(problem, b, a, zeros), f"dop853(rtol={DOP853_RTOL:g})")

    return at


def _other_family(ref_method: str, info: dict[str, dict[str, Any]]) -> str:
    """A method of the reference's order from another family (splitting against Runge-Kutta)."""
    order = info[ref_method]["order"]
    splitting = "splitting" in ref_method
    same_order = [m for m, i in info.items() if i["order"] == order and m != ref_method and
                  ("splitting" in m) != splitting]
    return same_order[0] if same_order else max((m for m in info if m != ref_method and info[m]["order"] > 0),
                                                key=lambda m: info[m]["order"])


def _family_reference(problem: Problem | SceneCase, method: str, order: int, dt: float, steps: int, every: int,
                      bar: _Progress | None) -> _Independent:
    """`method` at dt and 2 dt (steps, every: at dt; both even) with its Richardson error estimate."""
    fine = _simulate(problem, method, dt, steps, every, timed=False, bar=bar)
    coarse = _simulate(problem, method, 2 * dt, steps // 2, every // 2, timed=False, bar=bar)
    error = {k: (math.inf if fine.diverged or coarse.diverged else v / (2**order - 1))
             for k, v in _measures(problem, fine.states, coarse.states, np.zeros(1)).items()}
    return _Independent(fine.states, error, f"{method}(dt={dt:.3g})")


@dataclass
class _Check:
    """The Richardson reference checked against an independent one: reliable, reference error per
    measure (max of the estimate and what the disagreement implies), and a sentence."""

    reliable: bool
    error: dict[str, float]
    text: str


def _check_reference(problem: Problem | SceneCase, ref: Any, estimate: dict[str, float], independent: _Independent,
                     steps: int) -> _Check:
    """Compare the reference (Richardson `estimate` of its error, `steps` steps) with `independent`.
    Their disagreement d bounds |e_ref| from below by d - e_ind; the reference is unreliable when that
    bound exceeds CHECK_FACTOR x the estimate (and the round-off of `steps` steps)."""
    d = _measures(problem, ref, independent.states, np.zeros(1))
    lower = {k: max(0.0, d[k] - independent.error.get(k, 0.0)) for k in d}
    error = {k: max(estimate.get(k, 0.0), lower[k]) for k in d}
    key = "max_state_error"
    reliable = lower[key] <= max(CHECK_FACTOR * estimate[key], ROUND_OFF_PER_STEP * steps)
    if reliable:
        text = f"{independent.name} agrees to {_fmt(d[key])} (its error {_fmt(independent.error.get(key, 0.0))})"
    else:
        text = (f"{independent.name} differs by {_fmt(d[key])} (its error {_fmt(independent.error.get(key, 0.0))}) "
                f"where the Richardson estimate is {_fmt(estimate[key])}")
    return _Check(reliable, error, text)


# ---------------------------------------------------------------------------------------------
# cost estimate and progress


def _probe(problem: Problem | SceneCase, method: str, dt: float, steps: int) -> float:
    """Wall time per step [s] of `method` at dt, from a short run (PROBE_STEPS steps at most)."""
    n = max(1, min(steps, PROBE_STEPS))
    return float(_core_simulate(problem, method, dt, n, n).elapsed_seconds / n)


def _duration(seconds: float) -> str:
    if not math.isfinite(seconds):
        return "?"
    for unit, size in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


@dataclass
class _Estimate:
    """The sweep's steps (runs once each and the least reference work) and their wall time [s]."""

    steps: int
    seconds: float
    text: str


def _estimate(problem: Problem | SceneCase, methods: Sequence[str], grid: Sequence[int], ref_method: str | None) -> _Estimate:
    """Probe each method at the finest step, then sum steps x time per step over the sweep: each run
    once, and (ref_method) the least Richardson reference (2 and 4 x the steps) and its check."""
    finest = max(grid)
    dt = problem.horizon / finest
    per_step = {m: _probe(problem, m, dt, finest) for m in dict.fromkeys([*methods, *([ref_method] if ref_method else [])])}
    steps = sum(grid) * len(methods)
    seconds = sum(grid) * sum(per_step[m] for m in methods)
    if ref_method is not None:
        steps += 6 * sum(grid)
        seconds += 6 * sum(grid) * per_step[ref_method]
    probe = ", ".join(f"{m} {per_step[m] * 1e9:.3g}" for m in per_step)
    text = (f"tradeoff: {problem.name}: {len(methods)} methods x {len(grid)} steps over {_fmt(problem.horizon)} s: "
            f"about {steps:.3g} steps, estimated {'>= ' if ref_method else ''}{_duration(seconds)} "
            f"(probe, ns/step: {probe})")
    return _Estimate(steps, seconds, text)


class _Progress:
    """Steps done against the estimated total on stderr: tqdm if installed, else a plain bar; shown only
    when enabled (progress=True and stderr a terminal). `report`: the caller's progress(steps_done)
    instead (progress a callable), called with the steps done over the whole sweep."""

    def __init__(self, total: int, enabled: bool, report: Callable[[int], Any] | None = None) -> None:
        self.total, self.done, self.enabled, self.label = max(total, 1), 0, enabled, ""
        self.report = report
        self.base, self.started, self.shown = 0, time.perf_counter(), 0.0
        self.bar: Any = None
        if enabled:
            try:
                from tqdm import tqdm

                self.bar = tqdm(total=self.total, desc="tradeoff", unit="step", unit_scale=True, file=sys.stderr)
            except ImportError:
                pass

    def begin(self, steps: int, label: str) -> Callable[[int], None]:
        """Starts a run of `steps` steps; returns the callback simulate reports its steps done to."""
        self.base, self.label = self.done, label
        self.total = max(self.total, self.done + steps)

        def at(steps_done: int) -> None:
            self._show(self.base + steps_done)

        return at

    def end(self, steps: int) -> None:
        self._show(self.base + steps)

    def _show(self, done: int, force: bool = False) -> None:
        delta, self.done = done - self.done, done
        if self.report is not None:
            self.report(done)
            return
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.total = max(self.bar.total, done)
            self.bar.set_postfix_str(self.label, refresh=False)
            self.bar.update(delta)
            return
        now = time.perf_counter()
        if not force and now - self.shown < 0.1:
            return
        self.shown = now
        fraction = min(1.0, done / self.total)
        left = (now - self.started) * (1.0 - fraction) / fraction if fraction > 0 else math.inf
        width = 24
        bar = "#" * int(width * fraction) + "." * (width - int(width * fraction))
        print(f"\rtradeoff [{bar}] {100 * fraction:3.0f}% {done:.3g}/{self.total:.3g} steps, {_duration(left)} left, "
              f"{self.label:<24}", end="", file=sys.stderr, flush=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.enabled:
            self._show(self.done, force=True)
            print(file=sys.stderr)


def _progress_bar(progress: bool | Callable[[int], Any], problem: Problem | SceneCase, methods: Sequence[str],
                  grid: Sequence[int], ref_method: str | None) -> _Progress:
    """The sweep's progress: progress=True prints the estimated cost on stderr (_estimate) and shows a bar
    while stderr is a terminal; a callable is called with the steps done; False shows nothing."""
    if callable(progress):
        return _Progress(1, False, progress)
    total = 1
    if progress:
        estimate = _estimate(problem, methods, grid, ref_method)
        print("\n".join(_wrap(estimate.text, 100)), file=sys.stderr, flush=True)
        total = estimate.steps
    return _Progress(total, bool(progress) and sys.stderr.isatty())


def _fmt(x: Any) -> str:
    if isinstance(x, float):
        return f"{x:.3g}" if math.isfinite(x) else str(x)
    return str(x)


# ---------------------------------------------------------------------------------------------
# ranking: timing noise, the cheapest run, the Pareto front


def timing_noise(rows: Iterable[Mapping[str, Any]]) -> float:
    """The sweep's relative timing noise: the NOISE_QUANTILE quantile of the rows' time_noise (the gap
    between the two fastest of each run's repeated timings, relative), 0 if no run was timed twice."""
    spreads = [float(r["time_noise"]) for r in rows
               if _is_real(r.get("time_noise")) and math.isfinite(r["time_noise"])]
    return float(np.quantile(spreads, NOISE_QUANTILE)) if spreads else 0.0


def _equal_within(t_a: float, t_b: float, noise: float) -> bool:
    """Two times [s] equal within the relative noise: the ranges t (1 +- noise) overlap."""
    low, high = min(t_a, t_b), max(t_a, t_b)
    return high * (1.0 - noise) <= low * (1.0 + noise)


def cheapest(rows: Sequence[Mapping[str, Any]], cost: str = "time", noise: float = 0.0) -> Mapping[str, Any] | None:
    """The cheapest of `rows` (None if empty). cost 'evaluations': fewest total_evaluations, then
    steps. cost 'time': among the rows whose total_time equals the fastest's within the relative
    `noise` (ranges t (1 +- noise) overlap), the fewest total_evaluations, then steps, then time: a
    recommendation that timing noise cannot flip."""
    _check_cost(cost)
    if not _is_real(noise):
        raise TypeError(f"noise: expected a relative timing noise (a finite number >= 0), got {noise!r}")
    if not (math.isfinite(noise) and noise >= 0):
        raise ValueError(f"noise: expected a relative timing noise (a finite number >= 0), got {noise!r}")
    if not rows:
        return None
    if cost == "evaluations":
        return min(rows, key=lambda r: (r["total_evaluations"], r["steps"], r["total_time"]))
    fastest = min(r["total_time"] for r in rows)
    tied = [r for r in rows if _equal_within(r["total_time"], fastest, noise)]
    return min(tied, key=lambda r: (r["total_evaluations"], r["steps"], r["total_time"]))


def pareto_front(points: Sequence[tuple[float, float]]) -> list[int]:
    """Indices of the non-dominated (cost, error) points, by ascending cost: no other point has cost
    and error both <= and one of them <. Equal points are all kept."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front: list[int] = []
    for i in order:
        cost, error = points[i]
        if not front:
            front.append(i)
            continue
        last_cost, last_error = points[front[-1]]
        # sorted by cost: i is dominated iff an earlier point has error < its own, or equal error at lower cost
        if error < last_error or (error == last_error and cost == last_cost):
            front.append(i)
    return front


def _ranking_rule(cost: str, noise: float) -> str:
    if cost == "evaluations":
        return "ranked by derivative evaluations, then steps"
    return (f"ranked by wall time, times equal within the timing noise ({100 * noise:.2g} %: the gap between "
            f"the two fastest repeats of a run, {100 * NOISE_QUANTILE:g}th percentile), then by fewer derivative "
            "evaluations")


# ---------------------------------------------------------------------------------------------
# results


def _cost_text(r: Mapping[str, Any]) -> str:
    """The run's cost: total time (and per step, except for a closed form, which has no step) and
    derivative evaluations."""
    per_step = "" if r.get("order") == 0 else f" ({_fmt(r['time_per_step'] * 1e9)} ns/step)"
    return f"{_fmt(r['total_time'])} s{per_step}, {r['total_evaluations']} derivative evaluations"


def _run_name(r: Mapping[str, Any]) -> str:
    """`method with dt = ... s (n steps)`, or `exact (closed form)` for a method of order 0."""
    if r.get("order") == 0:
        return f"{r['method']} (closed form)"
    return f"{r['method']} with dt = {_fmt(r['dt'])} s ({r['steps']} steps)"


@dataclass
class Recommendation:
    """The cheapest (method, dt) whose `measure` is <= tolerance (row is None if none is), `cost`
    ranked as `cheapest` does with the sweep's relative timing `noise`."""

    measure: str
    tolerance: float
    cost: str
    row: dict[str, Any] | None
    best: dict[str, Any] | None  # the most accurate run, for "none meets it"
    noise: float = 0.0

    @property
    def met(self) -> bool:
        return self.row is not None

    def __str__(self) -> str:
        if self.row is not None:
            r = self.row
            return (f"recommendation: {_run_name(r)}: {self.measure} = {_fmt(r[self.measure])} "
                    f"{_unit_text(self.measure)}<= tolerance {_fmt(self.tolerance)}, cost {_cost_text(r)}; "
                    f"reference ({r['reference']}) error {_fmt(r['reference_error'])}; "
                    f"{_ranking_rule(self.cost, self.noise)}")
        if self.best is None:
            return f"recommendation: none; every run diverged ({self.measure}, tolerance {_fmt(self.tolerance)})"
        b = self.best
        text = (f"recommendation: none meets {self.measure} <= {_fmt(self.tolerance)}; best is {_run_name(b)}: "
                f"{self.measure} = {_fmt(b[self.measure])} at {_fmt(b['total_time'])} s")
        if str(b.get("reference", "")).startswith("unreliable"):
            return (text + f"; its reference is unreliable (error {_fmt(b['reference_error'])}, see the reference "
                    f"checks): errors below it cannot be measured")
        return text + "; try smaller steps or a higher-order method"


@dataclass
class TradeoffResult:
    """The rows of a ``tradeoff`` sweep and its recommendation: what each method costs and how accurate it is.

    Made by ``tradeoff``, or read back with ``TradeoffResult.read_csv`` / ``read_json``. Every argument is
    checked: TypeError or ValueError naming it.

    Parameters
    ----------
    problem : str
        The problem's name.
    horizon : float
        Duration of each run [s] (nan if unknown).
    measure : str
        The recommendation's measure, one of ``rigiddyn.work_precision.MEASURES``.
    tolerance : float or None, default None
        The recommendation's criterion (None: no recommendation).
    rows : list of dict, default []
        One per method × dt, with the keys ``COLUMNS`` (method, dt [s], steps, errors, cost, ...).
    cost : {"time", "evaluations"}, default "time"
        What the recommendation minimises.
    recommendation : Recommendation or None, default None
        Computed from the rows when None and a tolerance is given.
    notes : list of str, default []
        What the report says besides the rows (a scene's compatibility warnings).

    See Also
    --------
    tradeoff : runs the sweep.

    Examples
    --------
    >>> result = rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=1.0, progress=False)
    >>> result.problem, len(result.rows), result.rows[0]["method"]
    ('tumbling T-handle (Dzhanibekov)', 1, 'rk4')
    >>> result.recommend(1e-3, "final_attitude_error", "evaluations").row["dt"]
    0.01
    """

    problem: str
    horizon: float
    measure: str
    tolerance: float | None = None
    rows: list[dict[str, Any]] = field(default_factory=list)
    cost: str = "time"
    recommendation: Recommendation | None = field(default=None)
    notes: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        if not isinstance(self.problem, str):
            raise TypeError(f"problem: expected the problem's name (str), got {self.problem!r}")
        self.horizon = _check_horizon(self.horizon, "horizon")
        _check_measure(self.measure)
        self.rows = _check_rows(self.rows, (*_ROW_KEYS, self.measure))
        if self.tolerance is not None:
            self.tolerance = _check_positive(self.tolerance, "tolerance")
        _check_cost(self.cost)
        if self.recommendation is not None and not isinstance(self.recommendation, Recommendation):
            raise TypeError(f"recommendation: expected None or a Recommendation, got {self.recommendation!r}")
        if self.recommendation is None and self.tolerance is not None:
            self.recommendation = self.recommend(self.tolerance, self.measure, self.cost)
        self.notes = _check_name_list(self.notes, "notes", None)

    def recommend(self, tolerance: float, measure: str | None = None, cost: str = "time") -> Recommendation:
        """The cheapest run (cost 'time': total wall time; 'evaluations': derivative evaluations) whose
        `measure` is <= tolerance also counting the reference's error (reference_error, which is that
        of the sweep's measure: a run measured against an unreliable reference does not count for
        another measure), diverged runs excluded."""
        measure = self.measure if measure is None else measure
        _check_measure(measure)
        _check_positive(tolerance, "tolerance")
        _check_cost(cost)
        usable = [r for r in self.rows if not r["diverged"] and math.isfinite(r[measure])]

        def bound(r: dict[str, Any]) -> float:  # the run's error at worst
            if measure == self.measure:
                return float(r[measure] + r.get("reference_error", 0.0))
            return math.inf if str(r.get("reference", "")).startswith("unreliable") else float(r[measure])

        meeting = [r for r in usable if bound(r) <= tolerance]
        noise = timing_noise(self.rows)
        row: Any = cheapest(meeting, cost, noise)
        best = min(usable, key=lambda r: (r[measure], r[_COSTS[cost]])) if usable else None
        return Recommendation(measure, float(tolerance), cost, row, best, noise)

    def pareto(self, measure: str | None = None, cost: str | None = None) -> list[dict[str, Any]]:
        """The runs on the Pareto front of (cost, `measure`) (default: the sweep's cost and measure):
        those no other run beats in both, by ascending cost; diverged and non-finite runs excluded."""
        measure = self.measure if measure is None else measure
        _check_measure(measure)
        cost = self.cost if cost is None else cost
        _check_cost(cost)
        usable = [r for r in self.rows if not r["diverged"] and math.isfinite(r.get(measure, math.nan))]
        front = pareto_front([(float(r[_COSTS[cost]]), float(r[measure])) for r in usable])
        return [usable[i] for i in front]

    def methods(self) -> list[str]:
        return list(dict.fromkeys(r["method"] for r in self.rows))

    # -- text
    def to_table(self, width: int = 100) -> str:
        """The report for a terminal, no line wider than `width` characters (>= 60; or than the fixed
        columns and a 10-character note, where the method names make those wider): the problem and
        reference, one row per run (method, dt [s], steps, ns/step, the sweep's measure with its unit, the
        run's own estimate of it where the width allows, observed order, short notes explained below the
        table; a closed-form method once, without dt),
        then the recommendation or, without a tolerance, the Pareto front. Every column of every run:
        to_csv / to_json."""
        if isinstance(width, (bool, np.bool_)) or not isinstance(width, (int, np.integer)):
            raise TypeError(f"width: expected an integer >= 60 (characters), got {width!r}")
        if width < 60:
            raise ValueError(f"width: expected an integer >= 60 (characters), got {width!r}")
        front = self.pareto() if self.tolerance is None else []
        cells, used = self._table_cells(front)
        headers = ["method", "dt [s]", "steps", "ns/step", f"error [{measure_unit(self.measure)}]", "estimate",
                   "order", "note"]

        def column_widths() -> list[int]:
            out = [max([len(h)] + [len(c[i]) for c in cells if i not in (1, 2) or c[2] != _MERGED])
                   for i, h in enumerate(headers[:-1])]
            merged = max((len(c[1]) for c in cells if c[2] == _MERGED), default=0)  # spans dt and steps
            out[2] = max(out[2], merged - out[1] - 2)
            return out

        widths = column_widths()
        estimates = sum(widths) + 2 * len(widths) + 10 <= width  # the estimate column where a 10-wide note fits
        if not estimates:
            del headers[5]
            cells = [c[:5] + c[6:] for c in cells]
            widths = column_widths()
        note_width = max(10, width - sum(widths) - 2 * len(widths))
        out = self._title(width)
        for note in self.notes:
            out += _wrap("note: " + note, width)
        out += [_table_line(headers, widths, note_width)[0], "  ".join("-" * w for w in widths + [note_width])]
        for c in cells:
            out += _table_line(c, widths, note_width)
        for method in self.methods():  # the reason of each method a scene refuses, once
            reason = next((str(r["order_note"]) for r in self.rows if r["method"] == method and
                           str(r.get("order_note", "")).startswith(_REFUSED)), None)
            if reason is not None:
                out += _wrap(f"{method}: {reason}", width)
        legend = [f"{tag} = {_TAGS[tag]}" for tag in _TAGS if tag in used]
        estimate = ("estimate: the run's own estimate of its error (result.error), ? where it is not reliable (why: "
                    "estimate_verdict in the CSV/JSON). " if estimates else
                    f"The runs' own error estimates (estimate, effectivity, estimate_verdict) do not fit {width} "
                    "columns here: see to_csv / to_json or a wider table. ")
        out += _wrap(estimate + "order: the observed order of convergence (- where it cannot be measured; the reason in "
                     "note). " + ("notes: " + "; ".join(legend) + "." if legend else ""), width)
        if self.recommendation is not None:
            out += _wrap(str(self.recommendation), width)
        else:
            out += self._front_text(front, width)
        return "\n".join(out)

    def _title(self, width: int) -> list[str]:
        """The problem, the measure and what it is measured against."""
        title = f"{self.problem}, {_fmt(self.horizon)} s: error = {self.measure} [{measure_unit(self.measure)}] vs "
        references = list(dict.fromkeys(str(r["reference"]) for r in self.rows))
        if references == ["exact"]:
            return _wrap(title + "the exact solution", width)
        if len(references) == 1 and references[0].startswith("exact: "):  # a scene's closed form, named
            return _wrap(title + f"the exact solution ({references[0][len('exact: '):]})", width)
        checked = {r["dt"]: r for r in self.rows if r.get("reference_check")}
        bad = [r for r in checked.values() if str(r["reference"]).startswith("unreliable")]
        out = _wrap(title + f"a refined reference ({', '.join(references)}), checked against an independent one at "
                    f"each dt: {len(checked) - len(bad)} of {len(checked)} agree", width)
        for r in bad:
            out += _wrap(f"  dt = {_fmt(r['dt'])} s: {r['reference_check']}", width)
        return out

    def _table_cells(self, front: Sequence[Mapping[str, Any]]) -> tuple[list[list[str]], set[str]]:
        """The table's cells (a closed-form method's rows merged into one) and the note tags used."""
        rec = self.recommendation.row if self.recommendation is not None else None
        on_front = {_run_key(r) for r in front}
        cells, used = [], set()
        for method in self.methods():
            mine = [r for r in self.rows if r["method"] == method]
            refused = [str(r.get("order_note", "")) for r in mine if str(r.get("order_note", "")).startswith(_REFUSED)]
            if refused and len(refused) == len(mine):  # refused by the scene's compile: the reason below the table
                cells.append([method, "not applicable", _MERGED, "-", "-", "-", "-", "reason below"])
                continue
            closed = all(r.get("order") == 0 for r in mine)
            for r in ([max(mine, key=lambda r: r["steps"])] if closed else mine):
                tags = _tags(r, closed, rec is not None and (_run_key(r) == _run_key(rec) or
                                                              (closed and rec["method"] == method)),
                             _run_key(r) in on_front or (closed and any(f["method"] == method for f in front)))
                used.update(tags)
                order = r.get("observed_order", math.nan)
                cells.append([method, "closed form" if closed else _fmt(r["dt"]), _MERGED if closed else str(r["steps"]),
                              _fmt(r["time_per_step"] * 1e9), _fmt(r[self.measure]), _estimate_text(r),
                              f"{order:.2f}" if _is_real(order) and math.isfinite(order) else "-", ", ".join(tags)])
        return cells, used

    def _front_text(self, front: Sequence[Mapping[str, Any]], width: int) -> list[str]:
        """Without a tolerance: say so, and list the Pareto front."""
        cost = "wall time" if self.cost == "time" else "derivative evaluations"
        out = _wrap("no tolerance given (--tolerance, or tolerance in the problem file's [tradeoff]): no "
                    f"recommendation. The Pareto front of ({cost}, {self.measure}), the runs no other run beats in "
                    "both (marked 'front'):", width)
        unit = measure_unit(self.measure)
        for r in front:
            where = "closed form" if r.get("order") == 0 else f"dt = {_fmt(r['dt'])} s"
            out += _wrap(f"  {r['method']}, {where}: {_fmt(r[self.measure])}{'' if unit == '-' else ' ' + unit} in "
                         f"{_fmt(r['total_time'])} s, {r['total_evaluations']} evaluations", width)
        return out if front else out + ["  (none: every run diverged)"]

    def __str__(self) -> str:
        return self.to_table()

    # -- CSV / JSON
    def to_csv(self, path: str | Path | None = None) -> str:
        """All COLUMNS as CSV (floats with 17 significant digits); written to `path` if given."""
        path = _check_path(path, "path", optional=True)
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
        """A TradeoffResult from to_csv's output (a file path or the text itself); the CSV holds the
        rows only: problem (name), horizon [s] (nan: unknown), measure and tolerance are given here."""
        text = _read_text(path_or_text)
        reader = csv.DictReader(io.StringIO(text))
        missing = [c for c in COLUMNS if c not in (reader.fieldnames or []) and c not in _OPTIONAL_COLUMNS]
        if missing:
            raise ValueError(f"path_or_text: expected a CSV file or text written by to_csv (columns {', '.join(COLUMNS)}), "
                             f"got {_describe_text(path_or_text, text)} without {', '.join(missing[:3])}"
                             f"{' ...' if len(missing) > 3 else ''}")
        try:
            rows = [_typed_row(r) for r in reader]
        except (TypeError, ValueError) as error:
            raise ValueError(f"path_or_text: expected a CSV file or text written by to_csv, got a value that does not "
                             f"parse ({error})") from None
        return TradeoffResult(problem, horizon, measure, tolerance, rows)

    def to_dict(self) -> dict[str, Any]:
        """The sweep's settings, rows and recommendation (with the relative timing noise it ranked with)."""
        rec = self.recommendation
        return {"problem": self.problem, "horizon": self.horizon, "measure": self.measure,
                "tolerance": self.tolerance, "cost": self.cost, "rows": self.rows, "notes": self.notes,
                "recommendation": None if rec is None else {"met": rec.met, "text": str(rec), "row": rec.row,
                                                            "best": rec.best, "timing_noise": rec.noise}}

    def to_json(self, path: str | Path | None = None) -> str:
        """JSON with the sweep's settings, rows and recommendation: numbers as numbers, null where a number
        is not finite (nan: not measured, e.g. observed_order; inf: the errors of a diverged run, whose
        `diverged` is true). read_json restores both."""
        path = _check_path(path, "path", optional=True)
        text = json.dumps(_json_safe(self.to_dict()), indent=1, allow_nan=False)
        if path is not None:
            Path(path).write_text(text)
        return text

    @staticmethod
    def read_json(path_or_text: str | Path) -> TradeoffResult:
        """A TradeoffResult from to_json's output (a file path or the text itself)."""
        text = _read_text(path_or_text)
        expected = "a JSON file or text written by to_json (keys problem, horizon, measure, tolerance, rows)"
        try:
            d = json.loads(text)
        except json.JSONDecodeError as error:
            raise ValueError(f"path_or_text: expected {expected}, got {_describe_text(path_or_text, text)} "
                             f"({error})") from None
        if not isinstance(d, dict) or any(k not in d for k in ("problem", "horizon", "measure", "tolerance", "rows")):
            raise ValueError(f"path_or_text: expected {expected}, got {_describe_text(path_or_text, text)}")
        rows = [_json_row(r) for r in d["rows"]] if isinstance(d["rows"], list) else d["rows"]
        horizon = math.nan if d["horizon"] is None else d["horizon"]
        return TradeoffResult(d["problem"], horizon, d["measure"], d["tolerance"], rows, d.get("cost", "time"),
                              notes=d.get("notes", []))

    # -- plot
    def _plot_axis(self, ax: Any, cost: str, measure: str) -> None:
        """One work-precision panel: `measure` against `cost` per method (log-log), a closed-form method as
        markers without line, zeros (an exact error, no evaluations), which a log axis cannot show, drawn
        on the axis itself (its floor) with a downward marker, the tolerance and the recommendation."""
        from matplotlib.transforms import blended_transform_factory

        ax.set_xscale("log")
        ax.set_yscale("log")
        rows = [r for r in self.rows if not r["diverged"] and math.isfinite(r[measure])]
        # a zero coordinate goes to the axes' edge (axes fraction 0), the other stays data
        on_floor = {(False, True): blended_transform_factory(ax.transData, ax.transAxes),
                    (True, False): blended_transform_factory(ax.transAxes, ax.transData),
                    (True, True): ax.transAxes}
        for i, method in enumerate(self.methods()):
            mine = [r for r in rows if r["method"] == method]
            closed = bool(mine) and all(r.get("order") == 0 for r in mine)
            on_scale = [r for r in mine if r[measure] > 0 and r[cost] > 0]
            name = f"{method} (closed form)" if closed else method
            if on_scale:
                ax.plot([r[cost] for r in on_scale], [r[measure] for r in on_scale], "s" if closed else "o-",
                        color=f"C{i % 10}", label=name)
            for zero, transform in on_floor.items():
                at_floor = [r for r in mine if (r[cost] <= 0, r[measure] <= 0) == zero]
                if at_floor:
                    ax.plot([0.0 if zero[0] else r[cost] for r in at_floor],
                            [0.0 if zero[1] else r[measure] for r in at_floor], "v", markersize=9,
                            color=f"C{i % 10}", clip_on=False, transform=transform,
                            label=f"{name}: 0, drawn on the axis")
        if measure == self.measure:  # the estimate columns are the sweep's measure's
            self._plot_estimates(ax, cost, measure)
        if self.tolerance is not None:
            ax.axhline(self.tolerance, color="gray", linestyle="--", linewidth=1, label="tolerance")
        rec = self.recommendation
        if rec is not None and rec.row is not None:
            zero = (rec.row[cost] <= 0, rec.row[measure] <= 0)
            ax.plot([0.0 if zero[0] else rec.row[cost]], [0.0 if zero[1] else rec.row[measure]], "o", markersize=14,
                    markerfacecolor="none", markeredgecolor="black", clip_on=False,
                    transform=on_floor.get(zero, ax.transData), label="recommended")

    def _plot_estimates(self, ax: Any, cost: str, measure: str) -> None:
        """Each run's own error estimate (the estimate column) beside its true error: a bar from the true error
        to the estimate at the run's cost, ending in a dash where the estimate is reliable, a cross where not."""
        for i, method in enumerate(self.methods()):
            for r in self.rows:
                estimate, true = r.get("estimate", math.nan), r[measure]
                if (r["method"] != method or r["diverged"] or not _is_real(estimate) or not estimate > 0
                        or not math.isfinite(estimate) or not true > 0 or not math.isfinite(true) or not r[cost] > 0):
                    continue
                reliable = r.get("estimate_verdict") == "reliable"
                ax.plot([r[cost], r[cost]], [true, estimate], "-", color=f"C{i % 10}", linewidth=0.8, alpha=0.7)
                ax.plot([r[cost]], [estimate], "_" if reliable else "x", markersize=9, color=f"C{i % 10}")
        ax.plot([], [], "_", markersize=9, color="black", label="estimate (result.error), reliable")
        ax.plot([], [], "x", markersize=9, color="black", label="estimate, not reliable")

    def plot(self, path: str | Path, formats: Sequence[str] = ("png", "svg"),
             measure: str | None = None) -> list[Path]:
        """Work-precision plot (log-log; `measure` [its unit] against wall time [s] and against derivative
        evaluations, one line per method, a closed-form method as markers, a zero error or cost at the
        axis floor (a downward triangle), the tolerance as a dashed line, the recommendation circled,
        each run's own error estimate (of the sweep's measure) as a bar from its true error, the legend
        outside the axes); written as path.<format> for each format. Needs matplotlib (pip install
        'rigiddyn[plot]'). Returns the files written."""
        try:
            import matplotlib

            matplotlib.use("Agg") if "matplotlib.pyplot" not in sys.modules else None
            import matplotlib.pyplot as plt
        except ImportError:
            raise ImportError("plot: expected matplotlib (pip install 'rigiddyn[plot]' or pip install matplotlib)") from None
        base = _check_path(path, "path", optional=False)
        measure = self.measure if measure is None else measure
        _check_measure(measure)
        from matplotlib.backend_bases import FigureCanvasBase

        formats = _check_formats(formats, FigureCanvasBase.get_supported_filetypes())
        fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
        unit = measure_unit(measure)
        for ax, cost, label in ((axes[0], "total_time", "wall time of the run [s]"),
                                (axes[1], "total_evaluations", "derivative evaluations of the run")):
            self._plot_axis(ax, cost, measure)
            ax.set_xlabel(label)
            ax.set_ylabel(f"{measure} [{unit}]" if unit != "-" else f"{measure} (dimensionless)")
            ax.grid(True, which="both", alpha=0.3)
        labels: dict[str, Any] = {}
        for ax in axes:
            for handle, text in zip(*ax.get_legend_handles_labels()):
                labels.setdefault(text, handle)
        # outside the axes, right of the second: it never covers data
        axes[1].legend(labels.values(), labels.keys(), loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0,
                       fontsize=8)
        fig.suptitle(f"{self.problem}: work-precision over {_fmt(self.horizon)} s")
        written = []
        for fmt in formats:
            out = Path(f"{base}.{fmt}")
            fig.savefig(out)
            written.append(out)
        plt.close(fig)
        return written


_REFUSED = "not applicable: "  # the order_note of a method a scene refuses at compile (its reason follows)
_MERGED = "\0"  # the steps cell of a closed-form row: its dt cell ("closed form") spans both
# the table's note tags, in the order they are shown, and their explanation below the table
_TAGS = {
    "diverged": "the state became non-finite (errors inf)",
    "unstable": "dt beyond the method's stability limit for this spin or scene (see the warning)",
    "recommended": "the recommendation below",
    "front": "on the Pareto front: no other run is both cheaper and more accurate",
    "exact here": "exact on this problem (torque-free), the error is round-off",
    "round-off": "error at round-off",
    "ref. limit": f"error within {REFERENCE_MARGIN:g}x the reference's",
    "pre-asympt.": "slope not yet steady (before the asymptotic range)",
    "unconfirmed": "a single slope, none beside it to confirm it",
    "error O(1)": "errors of 1 rad (or 100 %) or more at this dt and the previous one: no accuracy left",
    "same dt": "the same dt as the previous row",
    "bad ref.": "the reference failed its independent check (see above)",
}
_ORDER_TAGS = {"exact on this problem": "exact here", "error at round-off": "round-off", "same dt": "same dt",
               "error O(1)": "error O(1)",
               f"error within {REFERENCE_MARGIN:g}x the reference's": "ref. limit"}


def _tags(r: Mapping[str, Any], closed: bool, recommended: bool, front: bool) -> list[str]:
    """The short notes of a row (see _TAGS)."""
    note = str(r.get("order_note", ""))
    order_tag = _ORDER_TAGS.get(note, "pre-asympt." if note.startswith("not asymptotic") else
                                "unconfirmed" if note.startswith("unconfirmed") else "")
    flags = {"diverged": r["diverged"], "unstable": bool(r.get("stability")), "recommended": recommended,
             "front": front, "bad ref.": str(r.get("reference", "")).startswith("unreliable"),
             order_tag: bool(order_tag) and not closed}  # a closed form's dt cell says why it has no order
    return [t for t in _TAGS if flags.get(t)]


def _estimate_text(r: Mapping[str, Any]) -> str:
    """A row's estimate cell: the estimate, with ? where it is not reliable; - where there is none."""
    estimate = r.get("estimate", math.nan)
    if not _is_real(estimate) or math.isnan(estimate):
        return "-"
    return _fmt(float(estimate)) + ("" if r.get("estimate_verdict") == "reliable" else "?")


def _run_key(r: Mapping[str, Any]) -> tuple[Any, ...]:
    return r["method"], r["dt"], r["steps"]


def _wrap(text: str, width: int) -> list[str]:
    """text in lines of at most `width` characters, continuation lines indented by 4."""
    indent = " " * (len(text) - len(text.lstrip(" ")))
    return textwrap.wrap(text, width, initial_indent="", subsequent_indent=indent + "    ",
                         break_long_words=True, break_on_hyphens=False) or [""]


def _table_line(cells: Sequence[str], widths: Sequence[int], note_width: int) -> list[str]:
    """One table row (the last cell, the note, wrapped to note_width on continuation lines)."""
    parts = [c.ljust(w) for c, w in zip(cells[:-1], widths)]
    if cells[2] == _MERGED:  # "closed form" over the dt and steps columns
        parts[1:3] = [cells[1].ljust(widths[1] + 2 + widths[2])]
    head = "  ".join(parts)
    notes = textwrap.wrap(cells[-1], note_width, break_long_words=True, break_on_hyphens=False) or [""]
    blank = " " * len(head)
    return [((head if i == 0 else blank) + "  " + n).rstrip() for i, n in enumerate(notes)]


def _unit_text(measure: str) -> str:
    unit = measure_unit(measure)
    return "" if unit == "-" else f"{unit} "


def _is_file(x: Any) -> bool:
    try:
        return Path(x).is_file()
    except (OSError, ValueError):
        return False


def _check_path(path: Any, name: str, optional: bool) -> Path | None:
    """path as a Path (None if optional and None), else TypeError naming `name`."""
    if path is None and optional:
        return None
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"{name}: expected {'None or ' if optional else ''}a file path (str or os.PathLike), got {path!r}")
    return Path(path)


def _read_text(path_or_text: Any) -> str:
    """The text of the file path_or_text names, or path_or_text itself (a str that names no file)."""
    if not isinstance(path_or_text, (str, os.PathLike)):
        raise TypeError(f"path_or_text: expected a file path or the text (str or os.PathLike), got {path_or_text!r}")
    if _is_file(path_or_text):
        return Path(path_or_text).read_text()
    if not isinstance(path_or_text, str):
        raise ValueError(f"path_or_text: expected an existing file, got {str(path_or_text)!r}")
    return path_or_text


def _describe_text(path_or_text: Any, text: str) -> str:
    where = f"the file {str(path_or_text)!r}" if _is_file(path_or_text) else "text"
    return f"{where} beginning {text[:40]!r}"


def _check_horizon(x: Any, name: str) -> float:
    """A horizon [s]: a finite number > 0, or nan (unknown)."""
    if _is_real(x) and math.isnan(x):
        return math.nan
    return _check_positive(x, name)


def _check_cost(cost: Any) -> None:
    if not isinstance(cost, str):
        raise TypeError(f"cost: expected one of {', '.join(_COSTS)}, got {cost!r}")
    if cost not in _COSTS:
        raise ValueError(f"cost: expected one of {', '.join(_COSTS)}, got {cost!r}")


_ROW_KEYS = ("method", "dt", "steps", "diverged", "total_time", "total_evaluations")  # what a result needs


def _check_rows(rows: Any, keys: Sequence[str]) -> list[dict[str, Any]]:
    """rows as a list of dicts (keys from COLUMNS) with at least `keys`, else TypeError/ValueError naming rows."""
    expected = f"a list of rows (dicts with keys from COLUMNS, at least {', '.join(keys)})"
    if isinstance(rows, (str, bytes, Mapping)) or not isinstance(rows, Iterable):
        raise TypeError(f"rows: expected {expected}, got {rows!r}")
    out = list(rows)
    for i, row in enumerate(out):
        if not isinstance(row, Mapping):
            raise TypeError(f"rows: expected {expected}, got {row!r} at index {i}")
        missing = [k for k in keys if k not in row]
        if missing:
            raise ValueError(f"rows: expected {expected}, got row {i} without {', '.join(missing)}")
        unknown = [k for k in row if k not in COLUMNS]
        if unknown:
            raise ValueError(f"rows: expected {expected}, got row {i} with {', '.join(map(repr, unknown[:3]))}")
    return [dict(row) for row in out]


def _check_name_list(values: Any, name: str, allowed: Sequence[str] | None) -> list[str]:
    """A list of strings from `allowed` (any string if None): TypeError / ValueError naming `name` otherwise."""
    expected = "a list of strings" if allowed is None else f"a list of names from {', '.join(allowed)}"
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise TypeError(f"{name}: expected {expected}, got {values!r}")
    names = list(values)
    for v in names:
        if not isinstance(v, str):
            raise TypeError(f"{name}: expected {expected}, got {v!r}")
        if allowed is not None and v not in allowed:
            raise ValueError(f"{name}: expected {expected}, got {v!r}")
    return names


def _check_formats(formats: Any, supported: Mapping[str, str]) -> list[str]:
    return _check_name_list(formats, "formats", sorted(supported))


_INT_COLUMNS = {"steps", "order", "evaluations_per_step", "total_evaluations"}
# absent from the CSV files of earlier versions
_OPTIONAL_COLUMNS = {"time_noise", "estimate", "effectivity", "estimate_verdict"}
_STR_COLUMNS = {"method", "reference", "reference_check", "order_note", "stability", "estimate_verdict"}


def _typed_row(r: dict[str, str]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in r.items():
        if k in _INT_COLUMNS:
            out[k] = int(v)
        elif k in _STR_COLUMNS:
            out[k] = v
        elif k == "diverged":
            if v not in ("True", "False"):
                raise ValueError(f"diverged: expected True or False, got {v!r}")
            out[k] = v == "True"
        else:
            out[k] = float(v)
    return out


_FLOAT_COLUMNS = set(COLUMNS) - _INT_COLUMNS - _STR_COLUMNS - {"diverged"}


def _json_safe(x: Any) -> Any:
    """x with every non-finite float as None (JSON null: JSON has no nan or inf)."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: _json_safe(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_json_safe(v) for v in x]
    return x


def _json_row(row: Any) -> Any:
    """A row read from JSON: null in a number column back to inf (an error of a diverged run) or nan."""
    if not isinstance(row, dict):
        return row
    diverged = row.get("diverged") is True
    return {k: ((math.inf if diverged and k in MEASURES else math.nan) if v is None and k in _FLOAT_COLUMNS else v)
            for k, v in row.items()}


def _is_real(x: Any) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


def _check_positive(x: Any, name: str) -> float:
    """x as a float: a finite real number > 0, else TypeError/ValueError naming `name`."""
    if not _is_real(x):
        raise TypeError(f"{name}: expected a finite number > 0, got {x!r}")
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name}: expected a finite number > 0, got {x!r}")
    return float(x)


def _check_count(x: Any, name: str) -> int:
    """x as an int >= 1, else TypeError/ValueError naming `name`."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise TypeError(f"{name}: expected an integer >= 1, got {x!r}")
    if x < 1:
        raise ValueError(f"{name}: expected an integer >= 1, got {x!r}")
    return int(x)


def _check_names(methods: Any, known: Iterable[str]) -> list[str]:
    """methods as a non-empty list of distinct known names, else TypeError/ValueError naming `methods`."""
    known = list(known)
    if isinstance(methods, (str, bytes)) or not isinstance(methods, Iterable):
        raise TypeError(f"methods: expected a list of method names, got {methods!r}")
    names = list(methods)
    if not names:
        raise ValueError(f"methods: expected at least one name from {', '.join(known)}, got []")
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"methods: expected names (str) from {', '.join(known)}, got {name!r}")
        if name not in known:
            raise ValueError(f"methods: expected names from {', '.join(known)}, got {name!r}")
    repeated = [n for n in dict.fromkeys(names) if names.count(n) > 1]
    if repeated:
        raise ValueError(f"methods: expected distinct names, got {repeated[0]!r} {names.count(repeated[0])} times")
    return names


def _check_dts(dts: Any) -> list[float]:
    if isinstance(dts, (str, bytes)) or not isinstance(dts, Iterable):
        raise TypeError(f"dts: expected a non-empty list of finite steps > 0 [s], got {dts!r}")
    if getattr(dts, "ndim", 1) > 1:  # an array of rows, not a list of steps
        raise ValueError(f"dts: expected a 1-d list of finite steps > 0 [s], got an array of shape {getattr(dts, 'shape', None)}")
    if isinstance(dts, Sized) and len(dts) > MAX_DTS:  # one run per step: refuse before copying
        raise ValueError(f"dts: expected at most {MAX_DTS} steps (one run each), got {len(dts)}")
    values = list(dts)
    if not values:
        raise ValueError("dts: expected a non-empty list of finite steps > 0 [s], got []")
    for d in values:
        if not _is_real(d):
            raise TypeError(f"dts: expected a non-empty list of finite steps > 0 [s], got {values!r}")
        if not (math.isfinite(d) and d > 0):
            raise ValueError(f"dts: expected a non-empty list of finite steps > 0 [s], got {values!r}")
    return [float(d) for d in values]


def _step_grid(horizon: float, dts: Sequence[float], name: str) -> list[int]:
    """The step counts round(horizon / dt) (>= 1), ascending; ValueError naming `name` beyond MAX_STEPS."""
    for d in dts:
        if not horizon / d <= MAX_STEPS:
            raise ValueError(f"{name}: expected at most {MAX_STEPS:.3g} steps per run (horizon / dt), got horizon "
                             f"{horizon:g} s / dt {d:g} s = {horizon / d:.3g}")
    return sorted({max(1, round(horizon / d)) for d in dts})


def _default_dts(problem: Problem) -> list[float]:
    """Eight halvings from dt*rho = 1, rho = the fastest rate of the spin (or the horizon / 16)."""
    rho = max(float(np.linalg.norm(problem.w_B)), 1e-300)
    dt0 = min(1.0 / rho, problem.horizon / 16)
    return [dt0 / 2**j for j in range(8)]


def _exact_on(problem: Problem, info: dict[str, Any]) -> bool:
    """True if the method has no truncation error on `problem` (order 0, or exact on torque-free bodies)."""
    return bool(info["order"] == 0 or (info["exact_torque_free"] and problem.torque_free))


def _observed_orders(rows: list[dict[str, Any]], measure: str, exact_methods: set[str]) -> None:
    """observed_order and order_note of every row (see the module docstring): the slope from the next
    larger dt, kept only in the asymptotic range."""
    # an angle [rad] or a relative error of 1 or more says the run has lost all accuracy: no slope
    saturates = measure_unit(measure) in ("rad", "-")
    for method in dict.fromkeys(r["method"] for r in rows):
        mine = sorted((r for r in rows if r["method"] == method), key=lambda r: -r["dt"])
        slopes: list[float | None] = [None]  # slope of the pair (i - 1, i), None where it says nothing
        notes = ["exact on this problem" if method in exact_methods else "coarsest step"]
        for coarse, fine in zip(mine[:-1], mine[1:]):
            e0, e1 = coarse[measure], fine[measure]
            floor = max(ROUND_OFF_PER_STEP * max(coarse["steps"], fine["steps"]),
                        REFERENCE_MARGIN * max(coarse["reference_error"], fine["reference_error"]))
            note = ""
            if method in exact_methods:
                note = "exact on this problem"
            elif coarse["diverged"] or fine["diverged"] or not (math.isfinite(e0) and math.isfinite(e1)):
                note = "diverged"
            elif coarse["dt"] == fine["dt"]:
                note = "same dt"
            elif saturates and min(e0, e1) >= 1.0:
                note = "error O(1)"
            elif min(e0, e1) <= REFERENCE_MARGIN * max(coarse["reference_error"], fine["reference_error"]):
                note = f"error within {REFERENCE_MARGIN:g}x the reference's"
            elif min(e0, e1) <= floor:
                note = "error at round-off"
            slopes.append(None if note else math.log(e0 / e1) / math.log(coarse["dt"] / fine["dt"]))
            notes.append(note)
        for i, row in enumerate(mine):
            p = slopes[i]
            neighbours = [q for q in (slopes[i - 1] if i > 0 else None, slopes[i + 1] if i + 1 < len(mine) else None)
                          if q is not None]
            agree = p is not None and any(abs(p - q) <= ORDER_AGREEMENT * max(abs(p), abs(q), 1.0) for q in neighbours)
            row["observed_order"] = p if agree and p is not None else math.nan
            if p is None:
                row["order_note"] = notes[i]
            elif agree:
                row["order_note"] = ""
            elif neighbours:
                row["order_note"] = (f"not asymptotic: slope {p:.2g}, neighbouring " +
                                     ", ".join(f"{q:.2g}" for q in neighbours))
            else:
                row["order_note"] = f"unconfirmed: slope {p:.2g}, no neighbouring slope"


def _as_problem(problem: Any, horizon: Any, initial: Any = None) -> Problem | SceneCase:
    """A Problem, or the SceneCase of a scene (see rigiddyn.scene_precision.scene_case)."""
    scene = scene_case(problem, initial, None if horizon is None else _check_positive(horizon, "horizon"))
    if scene is not None:
        return scene
    if initial is not None:
        raise TypeError(f"initial: expected None for a problem (its file gives the initial state), got {initial!r}")
    if not isinstance(problem, (Problem, str, os.PathLike)):
        raise TypeError(f"problem: expected a Problem, a Scene (with initial), a .toml path or an example name, "
                        f"got {problem!r}")
    try:
        out = problem if isinstance(problem, Problem) else load_problem(problem if isinstance(problem, str) else Path(problem))
    except (TypeError, ValueError) as error:  # load_problem names its argument path_or_name: here it is `problem`
        text = str(error)
        if not text.startswith("path_or_name: "):
            raise
        raise type(error)("problem: " + text.removeprefix("path_or_name: ")) from None
    return out if horizon is None else out.with_horizon(_check_positive(horizon, "horizon"))


def tradeoff(problem: Any, methods: Iterable[str] | None = None,
             dts: Iterable[float] | None = None, horizon: float | None = None,
             tolerance: float | None = None, measure: str | None = None,
             progress: bool | Callable[[int], Any] = True,
             cost: str = "time", samples: int = SAMPLES, max_reference_steps: int = 4_000_000,
             initial: Sequence[Any] | None = None) -> TradeoffResult:
    """Measure the speed–accuracy trade of integrators on a problem: every method at every dt, against a reference.

    Each run's cost (time, derivative evaluations) and errors (attitude, state, momentum, energy drift, ...)
    are measured against a reference: the exact solution where one exists (a torque-free body), else a
    Richardson-refined run checked against another method family. With a `tolerance`, the result recommends
    the cheapest run that meets it. The module docstring (``rigiddyn.work_precision``) describes the
    measures, the reference and the timing.

    Parameters
    ----------
    problem : Problem, str, pathlib.Path, Scene or tuple
        A ``Problem``, a problem file's path or a shipped example's name (``"t_handle"``); or a scene: a
        ``Scene`` with `initial` and `horizon`, the tuple returned by ``load_scene``, a scene file or a shipped
        scene's name. On a scene the reference is Richardson-refined (the best method that compiles without
        a warning) and checked against another method family; a method the scene refuses at compile gets rows
        "not applicable: <reason>" (``order_note``), compile warnings become the result's notes, and the
        errors are taken over the bodies.
    methods : iterable of str, optional
        Names from ``methods()``. Default: the file's ``[tradeoff]`` list, else every method that can run the
        problem (``exact`` only for a torque-free body; every method on a scene).
    dts : iterable of float, optional
        Steps [s]. Default: the file's, else eight halvings from dt·|ω| = 1 (a scene: from dt·ρ = 1, ρ the
        fastest spin or linear mode of its elements, ``rigiddyn.stability.scene_modes``, or from
        horizon / 16 if shorter). Each dt is adjusted to horizon / round(horizon / dt), so that every run
        ends exactly at the horizon.
    horizon : float, optional
        Duration of each run [s]. Default: the problem's (required for a ``Scene``).
    tolerance : float, optional
        The recommendation's criterion: the cheapest run whose `measure` is at most `tolerance`. None: no
        recommendation.
    measure : str, optional
        One of ``rigiddyn.work_precision.MEASURES``. Default: ``final_attitude_error`` [rad] (a scene:
        ``final_state_error``).
    progress : bool or callable, default True
        True: print the estimated cost on stderr first (a timed probe of each method), then a progress bar
        in steps while stderr is a terminal (tqdm if installed, else a plain one). False: nothing. A
        callable: ``progress(steps_done)``, as ``simulate``'s, with the steps done over the whole sweep (runs,
        repeats and references), called during each run as ``simulate`` calls its own and at each run's end;
        an exception it raises stops the sweep and propagates. No estimate is printed.
    cost : {"time", "evaluations"}, default "time"
        What the recommendation minimises. By time, times within the measured timing noise count as equal.
    samples : int, optional
        States compared per run (>= 1).
    max_reference_steps : int, default 4000000
        The Richardson reference's step budget.
    initial : sequence of body states, optional
        The initial states of a ``Scene``'s bodies.

    Returns
    -------
    TradeoffResult
        One row per method × dt (``rows``, dicts with the keys ``COLUMNS``) and the ``recommendation``;
        ``to_table()``, ``plot()``, ``to_csv()``, ``to_json()`` report them.

    Raises
    ------
    TypeError, ValueError
        An argument that is not valid (the message names it).
    KeyboardInterrupt
        Ctrl-C stops the sweep.

    Warns
    -----
    StabilityWarning
        One warning, with one line per method that has runs whose dt is beyond its linear stability limit
        (``rigiddyn.stability``; each run's message in its row's ``stability``); diverged runs get inf errors.

    See Also
    --------
    TradeoffResult : the rows, the recommendation, the plot.
    methods : the methods and their orders.

    Examples
    --------
    RK4 and the DLM splitting on the tumbling T-handle for 1 s, against its exact solution: halving dt
    shrinks RK4's attitude error, and RK4 at 10 ms already meets a tolerance of 1 mrad:

    >>> result = rd.tradeoff("t_handle", methods=["rk4", "splitting_dlm"], dts=[0.01, 0.005], horizon=1.0,
    ...                      progress=False, tolerance=1e-3)
    >>> [(row["method"], row["dt"]) for row in result.rows]
    [('rk4', 0.01), ('rk4', 0.005), ('splitting_dlm', 0.01), ('splitting_dlm', 0.005)]
    >>> bool(result.rows[1]["final_attitude_error"] < result.rows[0]["final_attitude_error"])
    True
    >>> result.recommendation.row["method"], result.recommendation.row["dt"]
    ('rk4', 0.01)
    """
    problem = _as_problem(problem, horizon, initial)
    defaults = problem.tradeoff
    info = {m["name"]: m for m in _core.methods()}
    # by default every method that can run the problem: the exact flow (order 0) is for torque-free bodies only;
    # on a scene every method (a refused one shows why in its rows)
    runnable = [name for name, m in info.items() if isinstance(problem, SceneCase) or m["order"] != 0 or problem.torque_free]
    methods = _check_names(methods if methods is not None else defaults.get("methods", runnable), info)
    dts_name = "dts" if dts is not None else "horizon"  # what a step count out of range is due to
    default_dts = problem.default_dts() if isinstance(problem, SceneCase) else _default_dts(problem)
    dts = _check_dts(dts if dts is not None else defaults.get("dts", default_dts))
    # a scene's bodies may have no attitude (particles): its default measure takes every part of the state
    default_measure = "final_state_error" if isinstance(problem, SceneCase) else "final_attitude_error"
    measure = measure if measure is not None else defaults.get("measure", default_measure)
    _check_measure(measure)
    tolerance = tolerance if tolerance is not None else defaults.get("tolerance")
    if tolerance is not None:
        tolerance = _check_positive(tolerance, "tolerance")
    if not isinstance(progress, (bool, np.bool_)) and not callable(progress):
        raise TypeError(f"progress: expected True, False or a callable progress(steps_done), got {progress!r}")
    if not isinstance(cost, str) or cost not in _COSTS:
        raise (TypeError if not isinstance(cost, str) else ValueError)(
            f"cost: expected one of {', '.join(_COSTS)}, got {cost!r}")
    samples = _check_count(samples, "samples")
    max_reference_steps = _check_count(max_reference_steps, "max_reference_steps")
    if isinstance(problem, SceneCase):
        grid = _step_grid(problem.horizon, dts, dts_name)
        return scene_sweep(problem, methods, grid, measure, tolerance, progress, cost, samples,
                           max_reference_steps, info)

    exact = problem.has_exact_solution
    ref_method = _reference_method(info)
    grid = _step_grid(problem.horizon, dts, dts_name)
    bar = _progress_bar(progress, problem, methods, grid, None if exact else ref_method)
    sweeps: list[tuple[int, float, list[_Run], _Reference | None]] = []
    try:
        for steps in grid:
            dt = problem.horizon / steps
            every = max(1, steps // samples)
            runs = [_simulate(problem, method, dt, steps, every, timed=True, bar=bar) for method in methods]
            ref = None if exact else _richardson_reference(problem, ref_method, info[ref_method]["order"], dt, steps,
                                                           every, runs, max_reference_steps, bar)
            sweeps.append((steps, dt, runs, ref))
        checks = {} if exact else _check_references(problem, sweeps, info, ref_method, bar)
    finally:
        bar.close()
    rows: list[dict[str, Any]] = []
    unstable: list[tuple[str, float, str]] = []
    for steps, dt, runs, ref in sweeps:
        for method, run in zip(methods, runs):
            m = info[method]
            row: dict[str, Any] = {"method": method, "dt": dt, "steps": steps, "order": m["order"],
                                   "evaluations_per_step": m["evaluations"], "time_per_step": run.time_per_step,
                                   "time_noise": run.time_noise, "total_time": run.time_per_step * steps,
                                   "total_evaluations": m["evaluations"] * steps}
            if run.diverged:
                row.update({k: math.inf for k in MEASURES}, **_NO_ESTIMATE, estimate_verdict="the run diverged")
            else:
                ref_states = reference_states(problem, run.states.t) if ref is None else ref.states
                row.update(_measures(problem, run.states, ref_states, run.quaternion_norm_error))
                row.update(_estimate_columns(problem, method, dt, steps, every, measure, row[measure]))
            message = stability_message(method, dt, steps, problem.inertia_com, problem.w_B, problem.torque_free)
            if message:
                unstable.append((method, dt, message))
            if ref is None:
                reference, reference_error, reference_check = "exact", 0.0, ""
            else:
                check = checks[steps]
                reference = f"richardson({ref_method})" if check.reliable else f"unreliable: richardson({ref_method})"
                reference_error, reference_check = check.error[measure], check.text
            row.update({"observed_order": math.nan, "order_note": "", "reference": reference,
                        "reference_error": reference_error, "reference_check": reference_check,
                        "diverged": run.diverged, "stability": message or ""})
            rows.append(row)
    _observed_orders(rows, measure, {m for m in methods if _exact_on(problem, info[m])})
    rows.sort(key=lambda r: (methods.index(r["method"]), -r["dt"]))
    if unstable:
        warnings.warn(_stability_summary(unstable), StabilityWarning, stacklevel=2)
    return TradeoffResult(problem.name, problem.horizon, measure, tolerance, rows, cost)


def _stability_summary(unstable: Sequence[tuple[str, float, str]], subject: str = "for this spin") -> str:
    """One line per method from (method, dt [s], stability message) of the runs beyond a stability
    limit: its steps, and the message of its largest step (the full messages: the rows' `stability`)."""
    lines = [f"tradeoff: dt beyond the method's stability limit {subject} (rows marked 'unstable'; every "
             "run's reason: column stability of the CSV/JSON):"]
    for method in dict.fromkeys(m for m, _, _ in unstable):
        mine = sorted(((dt, text) for m, dt, text in unstable if m == method), reverse=True)
        dts = (", ".join(_fmt(dt) for dt, _ in mine) + " s" if len(mine) <= 3 else
               f"{_fmt(mine[0][0])} to {_fmt(mine[-1][0])} s ({len(mine)} runs)")
        # the figure beyond the limit at the largest step: stability_message's text between ": " and "; "
        figure = mine[0][1].split(": ", 1)[-1].split("; ", 1)[0]
        lines.append(f"  {method} at dt = {dts}: at {_fmt(mine[0][0])} s {figure}")
    return "\n".join(lines)


def _check_references(problem: Problem, sweeps: Sequence[tuple[int, float, list[_Run], _Reference | None]],
                      info: dict[str, dict[str, Any]], ref_method: str, bar: _Progress) -> dict[int, _Check]:
    """Each step grid's Richardson reference checked against an independent one: DOP853 over the
    record times of every grid at once, else the core's other 4th-order family at each reference's
    finest step."""
    refs = {steps: ref for steps, _, _, ref in sweeps if ref is not None}
    times = np.unique(np.concatenate([ref.states.t for ref in refs.values()]))
    dop853 = _dop853_reference(problem, times)
    other = _other_family(ref_method, info)
    checks = {}
    for steps, dt, _, ref in sweeps:
        if ref is None:
            continue
        if dop853 is not None:
            independent = dop853(ref.states.t)
        else:
            independent = _family_reference(problem, other, info[other]["order"], dt / ref.sub, steps * ref.sub,
                                            ref.record_every, bar)
        checks[steps] = _check_reference(problem, ref.states, ref.estimate, independent, steps * ref.sub)
    return checks


# ---------------------------------------------------------------------------------------------
# the sweep on a scene (scene_precision.SceneCase)


def _family(method: str) -> str:
    """The method's family, for the independent check: splittings (kick and free flow), Runge-Kutta,
    or the method itself (implicit midpoint, the semi-implicit Eulers)."""
    if "splitting" in method or method == "exact_flow_kick":
        return "splitting"
    if method in ("explicit_euler", "rk4", "rkmk4"):
        return "runge-kutta"
    return method


def _best(candidates: Iterable[str], info: Mapping[str, Mapping[str, Any]]) -> str | None:
    """The highest-order method of `candidates` (ties to one that keeps SO(3) exactly), None if empty."""
    return max(candidates, key=lambda m: (info[m]["order"], "SO(3)" in info[m]["conserves"]), default=None)


def _scene_independent(case: SceneCase, method: str, order: int, dt: float, steps: int, ref: Any, max_steps: int,
                       bar: Any) -> Any:
    """`method` (of another family) with its Richardson error estimate, from the reference's finest step
    dt / ref.sub, halved while its estimate exceeds CHECK_FACTOR x the reference's (a lower-order method
    needs finer steps to say anything), at most CHECK_HALVINGS times and within max_steps."""
    sub = ref.sub
    while True:
        independent = _family_reference(case, method, order, dt / sub, steps * sub, ref.record_every * sub // ref.sub,
                                        bar)
        wanted = CHECK_FACTOR * ref.estimate["max_state_error"]
        if (independent.error["max_state_error"] <= wanted or steps * sub * 2 > max_steps
                or sub >= ref.sub * 2**CHECK_HALVINGS):
            return independent
        sub *= 2


def _fixed(states: SceneStates) -> Callable[[np.ndarray], SceneStates]:
    """The reference states of a Richardson reference, already at the runs' record times."""
    return lambda t: states


def scene_sweep(case: SceneCase, methods: list[str], grid: list[int], measure: str, tolerance: float | None,
                progress: bool | Callable[[int], Any], cost: str, samples: int, max_reference_steps: int,
                info: dict[str, dict[str, Any]]) -> TradeoffResult:
    """The sweep of rigiddyn.tradeoff on a scene (arguments checked by it; `grid`: the step counts):
    against the scene's closed form when it is one's case (case.exact), else against a Richardson
    reference checked against another method family."""
    ref_method = other = None
    closed_form = case.exact
    if case.exact is None:
        clean = [m for m in info if info[m]["order"] > 0 and case.compile(m).model is not None
                 and not case.compile(m).warnings]
        ref_method = _best(clean, info)
        if ref_method is None:
            raise ValueError(f"problem: expected a scene that a method of order >= 1 runs without a compatibility "
                             f"warning, got {case.name!r} (" + "; ".join(f"{m}: {case.compile(m).reason or 'warned'}"
                                                                         for m in info) + ")")
        other = _best([m for m in clean if _family(m) != _family(ref_method)], info)
    runnable = [m for m in methods if case.compile(m).model is not None]
    free = not list(case.scene.elements) and getattr(case.scene, "frame", None) is None  # every body torque-free
    exact = {m for m in runnable if info[m]["order"] == 0 or (free and info[m]["exact_torque_free"])}
    bar = _progress_bar(progress, case, runnable, grid, ref_method)
    sweeps: list[tuple[int, float, dict[str, Any], Any, Any]] = []
    try:
        for steps in grid:
            dt = case.horizon / steps
            every = max(1, steps // samples)
            runs = {m: _simulate(case, m, dt, steps, every, timed=True, bar=bar) for m in runnable}
            if ref_method is None:  # the closed form is the reference (case.exact)
                sweeps.append((steps, dt, runs, None, None))
                continue
            # refined against the methods with a truncation error (an exact one's round-off sets no target)
            ref = _richardson_reference(case, ref_method, info[ref_method]["order"], dt, steps, every,
                                           [r for m, r in runs.items() if m not in exact], max_reference_steps, bar)
            if other is None:
                check = _Check(True, ref.estimate, "no method of another family runs this scene without a warning: "
                                  "Richardson estimate only")
            else:
                independent = _scene_independent(case, other, info[other]["order"], dt, steps, ref,
                                                 max_reference_steps, bar)
                check = _check_reference(case, ref.states, ref.estimate, independent, steps * ref.sub)
            sweeps.append((steps, dt, runs, ref, check))
    finally:
        bar.close()
    modes = scene_modes(case.scene, case.initial)
    rows: list[dict[str, Any]] = []
    unstable: list[tuple[str, float, str]] = []
    for steps, dt, runs, ref, check in sweeps:
        if ref is None:  # the closed form: no error of its own beyond round-off
            assert closed_form is not None  # a sweep without a Richardson reference has one
            reference, reference_error, reference_check = f"exact: {closed_form.name}", 0.0, ""
            states_at = closed_form.states
        else:
            states_at = _fixed(ref.states)
            reference = f"richardson({ref_method})" if check.reliable else f"unreliable: richardson({ref_method})"
            reference_error, reference_check = check.error[measure], check.text
        for method in methods:
            m = info[method]
            row: dict[str, Any] = {"method": method, "dt": dt, "steps": steps, "order": m["order"],
                                   "evaluations_per_step": m["evaluations"]}
            compiled = case.compile(method)
            if compiled.model is None:
                row.update({"time_per_step": math.nan, "time_noise": math.nan, "total_time": math.nan,
                            "total_evaluations": 0, **{k: math.nan for k in MEASURES},
                            "observed_order": math.nan, "order_note": f"not applicable: {compiled.reason}",
                            "reference": reference, "reference_error": reference_error,
                            "reference_check": reference_check, "diverged": False, "stability": "",
                            **_NO_ESTIMATE, "estimate_verdict": ""})
                rows.append(row)
                continue
            run = runs[method]
            row.update({"time_per_step": run.time_per_step, "time_noise": run.time_noise,
                        "total_time": run.time_per_step * steps, "total_evaluations": m["evaluations"] * steps})
            if run.diverged:
                row.update({k: math.inf for k in MEASURES}, **_NO_ESTIMATE, estimate_verdict="the run diverged")
            else:
                row.update(case.measures(run.states, states_at(run.states.t), run.quaternion_norm_error))
                every = max(1, steps // samples)
                row.update(_estimate_columns(case, method, dt, steps, every, measure, row[measure]))
            message = scene_stability_message(method, dt, steps, case.scene, case.initial, modes)
            if message:
                unstable.append((method, dt, message))
            row.update({"observed_order": math.nan, "order_note": "", "reference": reference,
                        "reference_error": reference_error, "reference_check": reference_check,
                        "diverged": run.diverged, "stability": message or ""})
            rows.append(row)
    applicable = [r for r in rows if not r["order_note"].startswith("not applicable")]
    _observed_orders(applicable, measure, exact)
    rows.sort(key=lambda r: (methods.index(r["method"]), -r["dt"]))
    if unstable:
        warnings.warn(_stability_summary(unstable, "for this scene"), StabilityWarning, stacklevel=3)
    notes = [f"{m}: {text} (SceneCompatibilityWarning)" for m in methods for text in case.compile(m).warnings]
    if case.exact is not None:
        notes.insert(0, f"reference: the exact solution rigiddyn.{case.exact.name} ({case.exact.case})")
    return TradeoffResult(case.name, case.horizon, measure, tolerance, rows, cost, notes=notes)
