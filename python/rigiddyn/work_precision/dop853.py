"""The independent reference of a one-body problem: SciPy's DOP853 on Newton-Euler equations written apart
from the core (another method family, adaptive, restarted at each switch time of the loads)."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from ..problem import Problem
from .constants import DOP853_MAX_STEPS, DOP853_RTOL
from .states import Independent, States, rows_at


def switch_times(problem: Problem) -> list[float]:
    """The times in (0, horizon) at which the problem's loads switch."""
    return sorted({b for load in problem.loads for b in (load.t_start, load.t_end) if 0.0 < b < problem.horizon})


def _cross(a: Sequence[float], b: Sequence[float]) -> list[float]:
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _rotate(u: Sequence[float], u_w: float, x: Sequence[float]) -> list[float]:
    """x turned by the unit quaternion (u, u_w): x + 2 u_w (u x x) + 2 u x (u x x)."""
    twice = [2.0 * c for c in _cross(u, x)]
    again = _cross(u, twice)
    return [x[i] + u_w * twice[i] + again[i] for i in range(3)]


def _matrix_times(m: list[list[float]], x: Sequence[float]) -> list[float]:
    return [m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] for i in range(3)]


def rate(problem: Problem, t: float) -> Callable[[float, np.ndarray], np.ndarray]:
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

    def y_dot(_: float, y: np.ndarray) -> np.ndarray:
        _, _, _, x, yq, z, s, v0, v1, v2, w0, w1, w2 = y.tolist()
        q_vec, w = (x, yq, z), (w0, w1, w2)
        scale = 1.0 / math.sqrt(x * x + yq * yq + z * z + s * s)
        u = (x * scale, yq * scale, z * scale)
        q_x_w = _cross(q_vec, w)
        turned_a = _rotate(u, s * scale, a_B)
        turned_n = _rotate((-u[0], -u[1], -u[2]), s * scale, couple_W)
        gyro = _cross(w, _matrix_times(inertia, w))
        alpha = _matrix_times(inverse, [couple_B[i] + turned_n[i] - gyro[i] for i in range(3)])
        return np.array([v0, v1, v2,
                         0.5 * (s * w0 + q_x_w[0]), 0.5 * (s * w1 + q_x_w[1]), 0.5 * (s * w2 + q_x_w[2]),
                         -0.5 * (x * w0 + yq * w1 + z * w2),
                         a_W[0] + turned_a[0], a_W[1] + turned_a[1], a_W[2] + turned_a[2], *alpha])

    return y_dot


def _absolute_tolerance(problem: Problem, rtol: float) -> np.ndarray:
    """atol (13,) of y: rtol times the problem's length, 1 (a quaternion), speed and rate scales."""
    radius = math.sqrt(np.trace(problem.inertia_com) / (2.0 * problem.mass))
    rate_scale = max(float(np.linalg.norm(problem.w_B)), 1.0 / problem.horizon)
    length = max(radius, float(np.linalg.norm(problem.p_W)))
    speed = max(float(np.linalg.norm(problem.v_W)), radius * rate_scale)
    return rtol * np.repeat([length, 1.0, speed, rate_scale], [3, 4, 3, 3])


def dop853_states(problem: Problem, times: np.ndarray, rtol: float, max_steps: int) -> States | None:
    """The states of `problem` at `times` (ascending, in [0, horizon]) by SciPy's DOP853 (dense
    output), restarted at each switch time of the loads; None without SciPy or beyond max_steps."""
    try:
        from scipy.integrate import DOP853
    except ImportError:
        return None
    y = np.concatenate([problem.p_W, problem.q_WB, problem.v_W, problem.w_B]).astype(float)
    atol = _absolute_tolerance(problem, rtol)
    out = np.empty((times.size, 13))
    k = int(np.searchsorted(times, 0.0, side="right"))
    out[:k] = y
    # the last record time i dt may exceed the horizon by an ulp (dt = horizon / steps, rounded): the last
    # piece runs to it, so that every time is filled (an np.empty row left would be garbage)
    edges = [0.0] + switch_times(problem) + [max(problem.horizon, float(times[-1]))]
    taken = 0
    for start, end in zip(edges[:-1], edges[1:]):
        solver = DOP853(rate(problem, start), start, y, end, rtol=rtol, atol=atol)
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


def dop853_reference(problem: Problem, times: np.ndarray, measures: Callable[[States, States], dict[str, float]]
                     ) -> Callable[[np.ndarray], Independent] | None:
    """DOP853 at DOP853_RTOL over all `times`, its error (`measures` of a second run at 10 x rtol against
    it): a function of the times of one grid; None when not available (no SciPy, or too many steps)."""
    tight = dop853_states(problem, times, DOP853_RTOL, DOP853_MAX_STEPS)
    loose = dop853_states(problem, times, 10 * DOP853_RTOL, DOP853_MAX_STEPS) if tight is not None else None
    if tight is None or loose is None:
        return None

    def at(t: np.ndarray) -> Independent:
        a, b = rows_at(tight, t), rows_at(loose, t)
        return Independent(a, measures(b, a), f"dop853(rtol={DOP853_RTOL:g})")

    return at

