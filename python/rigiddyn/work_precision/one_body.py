"""The one-body case of the sweep: a rigiddyn.Problem run by the core's one-body simulate, measured against its
closed form (torque-free rotation and world-fixed forces) or checked against DOP853."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from typing import Any, ClassVar, cast

import numpy as np

from .. import _core
from ..problem import Problem
from ..scene_precision import ExactReference, attitude_angle
from ..stability import stability_message
from .dop853 import dop853_reference
from .states import Independent, States, states_of


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
    """The exact states of a problem at given times: torque-free rotation and ballistic flight.

    The attitude and spin are the Euler-Poinsot motion (``TorqueFreeSolution``); the centre of mass moves
    on parabolas under gravity and world-fixed forces, p = p0 + v0 s + a s²/2 on each piece between the
    loads' switch times.

    Parameters
    ----------
    problem : Problem
        A problem with a closed form: no couple, every force fixed in W (``problem.has_exact_solution``).
    t : array_like, shape (n,)
        Times [s], ascending, from 0.

    Returns
    -------
    States
        t (n,) [s], p_W (n, 3) [m], q_WB (n, 4) (x, y, z, w), v_W (n, 3) [m/s] in W, w_B (n, 3) [rad/s] in B.

    Raises
    ------
    ValueError
        The problem has body torques or body-frame forces (no closed form).

    See Also
    --------
    tradeoff : measures every run against these states where they exist.

    Examples
    --------
    The tumbling T-handle at 0 s and 1 s: two states, each attitude a unit quaternion:

    >>> from rigiddyn.work_precision import reference_states
    >>> problem = rd.load_problem("t_handle")
    >>> states = reference_states(problem, np.array([0.0, 1.0]))
    >>> states.q_WB.shape, bool(np.allclose(np.linalg.norm(states.q_WB, axis=1), 1.0))
    ((2, 4), True)
    """
    if not problem.has_exact_solution:
        raise ValueError("problem: expected torque-free rotation and world-fixed forces (a closed form), got "
                         "body torques or body-frame forces")
    t = np.asarray(t, float)
    q, w = _core.TorqueFreeSolution(problem.inertia_com, problem.q_WB, problem.w_B,
                                    check=problem.inertia_check).state_at(t)
    p, v = _ballistic(problem, t)
    return States(t, p, np.asarray(q), v, np.asarray(w))


def body_measures(problem: Problem, run: States, ref: States, quaternion_norm_error: np.ndarray) -> dict[str, float]:
    """The error measures (rigiddyn.work_precision's docstring) of `run` against `ref` at the same times."""
    inertia, mass = problem.inertia_com, problem.mass
    h, h_ref = run.w_B @ inertia.T, ref.w_B @ inertia.T
    g_ref = np.linalg.norm(h_ref, axis=1)
    g_scale = np.maximum(g_ref, np.finfo(float).tiny)
    radius = math.sqrt(np.trace(inertia) / (2.0 * mass))  # radius of gyration about a mean axis [m]
    length = max(radius, float(np.max(np.linalg.norm(ref.p_W - ref.p_W[0], axis=1))))
    speed = max(float(np.max(np.linalg.norm(ref.v_W, axis=1))), length / problem.horizon)
    series = {
        "attitude_error": attitude_angle(ref.q_WB, run.q_WB),
        "momentum_error": np.linalg.norm(h - h_ref, axis=1) / g_scale,
        "position_error": np.linalg.norm(run.p_W - ref.p_W, axis=1),
        "velocity_error": np.linalg.norm(run.v_W - ref.v_W, axis=1),
    }
    series["state_error"] = np.max([series["attitude_error"], series["momentum_error"],
                                    series["position_error"] / length, series["velocity_error"] / speed], axis=0)
    out = {}
    for name, values in series.items():
        out[f"final_{name}"], out[f"max_{name}"] = float(values[-1]), float(np.max(values))

    def kinetic(s: States) -> np.ndarray:  # T = m |v|^2 / 2 + w_B . I w_B / 2
        return np.asarray(0.5 * mass * np.sum(s.v_W**2, axis=1) + 0.5 * np.sum(s.w_B * (s.w_B @ inertia.T), axis=1))

    t_ref = kinetic(ref)
    out["energy_drift"] = float(np.max(np.abs(kinetic(run) - t_ref)) / max(np.max(t_ref), np.finfo(float).tiny))
    out["momentum_drift"] = float(np.max(np.abs(np.linalg.norm(h, axis=1) - g_ref)) / np.max(g_scale))
    out["quaternion_norm_error"] = float(np.max(np.abs(quaternion_norm_error)))
    return out


@dataclass
class ProblemCase:
    """A problem swept by tradeoff: the one-body side of the sweep's case (its interface: case.Case)."""

    problem: Problem
    default_measure: ClassVar[str] = "final_attitude_error"
    stability_subject: ClassVar[str] = "for this spin"
    exact_label: ClassVar[str] = "exact"

    @property
    def name(self) -> str:
        return self.problem.name

    @property
    def horizon(self) -> float:
        return self.problem.horizon

    @property
    def tradeoff(self) -> Mapping[str, Any]:
        """The sweep defaults of the problem file's [tradeoff] table."""
        return self.problem.tradeoff

    @property
    def exact(self) -> ExactReference | None:
        """The closed form (reference_states) where the problem has one."""
        if not self.problem.has_exact_solution:
            return None
        return ExactReference("TorqueFreeSolution", "torque-free rotation and world-fixed forces",
                              lambda t: reference_states(self.problem, t))

    def with_horizon(self, horizon: float) -> ProblemCase:
        return replace(self, problem=self.problem.with_horizon(horizon))

    def refusal(self, method: str) -> str:
        """Why `method` cannot run the case ("": it can; the core checks a problem's methods as it runs)."""
        return ""

    def compile_warnings(self, method: str) -> tuple[str, ...]:
        return ()

    def notes(self, methods: list[str]) -> list[str]:
        """What the report says besides the rows: nothing for a problem."""
        return []

    def default_methods(self, info: Mapping[str, Mapping[str, Any]]) -> list[str]:
        """Every method that can run the problem: the exact flow (order 0) only where the problem has a
        closed form (torque-free, forces fixed in W: the core refuses it a body-frame force)."""
        return [name for name, m in info.items() if m["order"] != 0 or self.problem.has_exact_solution]

    def default_dts(self) -> list[float]:
        """Eight halvings from dt rho = 1, rho the rate of the spin (or from horizon / 16 if shorter)."""
        rho = max(float(np.linalg.norm(self.problem.w_B)), 1e-300)
        dt0 = min(1.0 / rho, self.problem.horizon / 16)
        return [dt0 / 2**j for j in range(8)]

    def exact_methods(self, info: Mapping[str, Mapping[str, Any]]) -> set[str]:
        """The methods without truncation error here: order 0, or exact on a torque-free body whose forces
        are fixed in W (a body-frame force turns with the body: its kick has a truncation error)."""
        exact = self.problem.has_exact_solution
        return {m for m, i in info.items() if i["order"] == 0 or (i["exact_torque_free"] and exact)}

    def simulate(self, method: str, dt: float, steps: int, record_every: int,
                 progress: Callable[[int], None] | None = None, error: bool = False) -> Any:
        """The core's one-body simulate of the problem; `error`: with the run's error estimate (result.error)."""
        p = self.problem
        # method: a str of methods() (mypy knows their literal names), checked by the core
        return _core.simulate(p.body(), p.initial_state(), dt, steps, cast(Any, method), record_every=record_every,
                              loads=list(p.loads), gravity=p.gravity, progress=progress, error=error,
                              accuracy_level=None)  # the sweep's coarse steps are its rows

    def states(self, result: Any) -> States:
        return states_of(result)

    def quaternion_norm_error(self, result: Any) -> np.ndarray:
        return np.asarray(result.body(0).quaternion_norm_error)

    def measures(self, run: States, ref: States, quaternion_norm_error: np.ndarray) -> dict[str, float]:
        """The error measures of `run` against `ref` at the same times (body_measures); a run far beyond
        its stability limit, of states of 1e154 and more whose squares overflow, gets inf errors."""
        with np.errstate(over="ignore"):
            return body_measures(self.problem, run, ref, quaternion_norm_error)

    def stability(self, method: str, dt: float, steps: int) -> str | None:
        """Why dt is beyond the method's linear stability limit for the initial spin (None if it is not)."""
        p = self.problem
        return stability_message(method, dt, steps, p.inertia_com, p.w_B, p.torque_free)

    def independent(self, times: np.ndarray) -> Callable[[np.ndarray], Independent] | None:
        """DOP853 over all `times` (the record times of every grid), None without SciPy or beyond its step
        budget (the sweep then checks against the core's other method family)."""
        return dop853_reference(self.problem, times, lambda run, ref: self.measures(run, ref, np.zeros(1)))

