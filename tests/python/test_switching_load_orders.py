"""Every method keeps its order when a load switches inside a step.

The problem (tests/python/problems/satellite_switching_torque.toml): a 200 kg box tumbling slowly,
a body-fixed couple on from t = 10 s to t = 200 s, horizon 300 s. The steps dt = 300 s / (877 2^k)
put both switch times strictly inside a step (877 is prime: 10 / dt and 200 / dt are never integers).
Each method's attitude is compared, at every recorded time, with an independent reference: SciPy's
DOP853 on the Newton-Euler equations of the numpy reference (tests/reference/rigiddyn_ref, which
never calls the package), restarted at both switch times, at rtol 2.5e-14. The observed order is
log2(e(dt) / e(dt/2)) of the largest attitude error over the run.

Before simulate split a step at a switch time, the loads active at a step's start were held over the
whole step (the switch took effect at the next grid time) and every method was first order, erratically.
The table also shows that behaviour ("held"), emulated by moving each switch time up to the next grid
time: the same figures the old behaviour gave. Print the table:

    PYTHONPATH=build/<dir>/python python3 tests/python/test_switching_load_orders.py
"""

from __future__ import annotations

import math
import sys
import warnings
from dataclasses import replace
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "reference"))  # also when run as a script

import rigiddyn as rd  # noqa: E402
from rigiddyn_ref import dynamics as dyn  # noqa: E402

scipy_integrate = pytest.importorskip("scipy.integrate")

PROBLEM = rd.load_problem(Path(__file__).resolve().parent / "problems" / "satellite_switching_torque.toml")
SWITCH_TIMES = (10.0, 200.0)  # [s], the file's t_start and t_end
METHODS = {m["name"]: m["order"] for m in rd.methods() if m["order"] > 0}  # exact (order 0) is torque-free only
# k of dt = 300 / (877 2^k): the asymptotic range of the first-order methods begins at smaller steps
K_RANGE = {1: range(3, 8), 2: range(0, 5), 4: range(0, 4)}
RTOL = 2.5e-14  # DOP853's relative tolerance (solve_ivp's least: 100 eps); its error: a run at 10 x RTOL
RECORDS = 300  # attitude compared at about this many times (every k-th step)


def dt_of(k: int) -> float:
    return PROBLEM.horizon / (877 * 2**k)


# ------------------------------------------------------------------ the independent reference
def _reference_schedule():
    return [dyn.Load(np.asarray(load.force, float), np.asarray(load.torque, float), load.frame, load.t_start,
                     load.t_end) for load in PROBLEM.loads]


def _rate(loads: dyn.Loads):
    """y = (q_WB (x, y, z, w), w_B): q' = q (x) (w, 0) / 2 (attitude kinematics), I w' = n_B - w x I w
    (Euler's equations, rigiddyn_ref.dynamics) under the constant loads of one piece."""
    mass, inertia = PROBLEM.mass, PROBLEM.inertia_com

    def rate(_t: float, y: np.ndarray) -> np.ndarray:
        q, w = y[:4] / np.linalg.norm(y[:4]), y[4:]
        _, dw = dyn.rigid_body_accelerations(mass, inertia, q, w, loads)
        return np.concatenate([0.5 * dyn.quat_product(y[:4], np.append(w, 0.0)), dw])

    return rate


@lru_cache(maxsize=None)
def reference_dense(rtol: float):
    """DOP853 over [0, horizon] restarted at each switch time: a list of (start, end, dense output)."""
    schedule = _reference_schedule()
    edges = [0.0, *SWITCH_TIMES, PROBLEM.horizon]
    y = np.concatenate([PROBLEM.q_WB, PROBLEM.w_B]).astype(float)
    pieces = []
    for start, end in zip(edges[:-1], edges[1:]):
        loads = dyn.loads_at(schedule, start)  # constant on [start, end)
        atol = rtol * np.array([1.0] * 4 + [max(float(np.linalg.norm(y[4:])), 1e-3)] * 3)
        sol = scipy_integrate.solve_ivp(_rate(loads), (start, end), y, method="DOP853", rtol=rtol, atol=atol,
                                        dense_output=True)
        assert sol.status == 0, sol.message
        pieces.append((start, end, sol.sol))
        y = sol.y[:, -1]
    return pieces


def reference_at(t: np.ndarray, rtol: float = RTOL) -> tuple[np.ndarray, np.ndarray]:
    """q_WB (n, 4) and w_B (n, 3) of the reference at times t (n,) [s]."""
    out = np.full((t.size, 7), np.nan)
    pieces = reference_dense(rtol)
    for i, (start, end, dense) in enumerate(pieces):
        # each piece on [start, end); the last also takes a time an ulp past the horizon (t0 + i dt)
        inside = (t >= start) & ((t < end) | (i == len(pieces) - 1))
        if inside.any():
            out[inside] = dense(t[inside]).T
    assert np.isfinite(out).all() and t.max() <= PROBLEM.horizon * (1 + 1e-14), t.max()
    return out[:, :4] / np.linalg.norm(out[:, :4], axis=1, keepdims=True), out[:, 4:]


def attitude_angle(q_a: np.ndarray, q_b: np.ndarray) -> np.ndarray:
    """Geodesic angle 2 atan2(|vec(r)|, |scalar(r)|), r = q_a^-1 (x) q_b [rad], rows (x, y, z, w)."""
    r = np.array([dyn.quat_product(np.append(-a[:3], a[3]), b) for a, b in zip(q_a, q_b)])
    return np.asarray(2.0 * np.arctan2(np.linalg.norm(r[:, :3], axis=1), np.abs(r[:, 3])))


# ------------------------------------------------------------------ the runs
def held_loads():
    """The schedule as the old zero-order hold saw it on the grid of dt: each switch time moved up to the
    next grid time (the loads at a step's start were held over the whole step)."""
    def up(t, dt):
        return math.ceil(t / dt) * dt if math.isfinite(t) else t
    return lambda dt: tuple(rd.AppliedLoad(load.force, load.torque, load.frame, up(load.t_start, dt),
                                           up(load.t_end, dt)) for load in PROBLEM.loads)


def max_attitude_error(method: str, k: int, held: bool = False) -> float:
    """The largest attitude error [rad] of `method` at dt_of(k) against the reference over the run."""
    dt = dt_of(k)
    steps = round(PROBLEM.horizon / dt)
    problem = replace(PROBLEM, loads=held_loads()(dt)) if held else PROBLEM
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.StabilityWarning)
        run = rd.simulate(problem.body(), problem.initial_state(), dt, steps, method, loads=list(problem.loads),
                          record_every=max(1, steps // RECORDS))
    t = np.asarray(run.t)
    q_ref, _ = reference_at(t)
    return float(np.max(attitude_angle(q_ref, np.asarray(run.body(0).q_WB))))


@lru_cache(maxsize=None)
def errors(method: str, held: bool = False) -> tuple[tuple[int, float], ...]:
    return tuple((k, max_attitude_error(method, k, held)) for k in K_RANGE[METHODS[method]])


def slopes(errs) -> list[float]:
    return [math.log2(e0 / e1) for (_, e0), (_, e1) in zip(errs[:-1], errs[1:])]


@lru_cache(maxsize=None)
def reference_error() -> float:
    """The reference's own error [rad], bounded by its difference from a run at 10 x RTOL (DOP853's error
    grows about in proportion to its tolerance, so that difference is ~9x the error at RTOL)."""
    t = np.linspace(0.0, PROBLEM.horizon, 3001)
    return float(np.max(attitude_angle(reference_at(t, RTOL)[0], reference_at(t, 10 * RTOL)[0])))


# ------------------------------------------------------------------ tests
def test_the_steps_put_both_switch_times_inside_a_step():
    for k in range(0, 8):
        for s in SWITCH_TIMES:
            x = s / dt_of(k)
            assert abs(x - round(x)) > 0.05, (k, s, x)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps of every method on purpose (an order study)
@pytest.mark.parametrize("method", sorted(METHODS))
def test_every_method_keeps_its_order_with_a_torque_switching_inside_steps(method):
    errs = errors(method)
    p = slopes(errs)
    # round-off: each step rounds the attitude by a few ulps; <= 1e5 steps stay below 1e-10 rad
    assert min(e for _, e in errs) > 1e-10, errs
    # the reference's error r moves a slope between errors e0, e1 by at most log2((1 + r/e0)(1 + r/e1));
    # over the last two slopes (here < 0.08: r <= 0.05 e)
    r = reference_error()
    contamination = sum(math.log2(1 + r / e) for _, e in errs[-3:])
    # in the asymptotic range e(dt) = C dt^p (1 + D dt + ...): the slope's deviation from p halves with
    # each halving of dt, so the last deviation is at most the last change of slope (x2 margin); the
    # range is reached when that change is small (0.1: the next term moves the error by < 7 %)
    assert abs(p[-1] - p[-2]) <= 0.1 + contamination, (p, errs)
    assert abs(p[-1] - METHODS[method]) <= max(2 * abs(p[-1] - p[-2]), 0.02) + contamination, (p, errs, r)


def test_holding_the_loads_over_a_step_loses_the_order():
    """The emulated old behaviour: a switch off by up to a step is an O(dt) error that does not shrink
    smoothly (it depends on where the switch falls in its step): no 4th order, and errors ~1e-3 rad at
    dt ~ 0.04 s, the figures the old behaviour gave for rkmk4. The order test above fails on it."""
    held, split = errors("rkmk4", held=True), errors("rkmk4")
    assert not all(abs(p - 4) <= 0.25 for p in slopes(held)), held
    assert held[-1][1] > 1e6 * split[-1][1], (held, split)


def table() -> str:
    lines = [f"{PROBLEM.name}: horizon {PROBLEM.horizon:g} s, switch times {SWITCH_TIMES} s; largest attitude "
             f"error over the run [rad] against DOP853 (rtol {RTOL:g}, its own error {reference_error():.1e} rad)",
             "dt = 300 s / (877 2^k); 'order': log2 of the error ratio to the next larger dt",
             f"{'method':<40} {'order':>5} {'k':>2} {'dt [s]':>9} {'split (now)':>12} {'order':>6} "
             f"{'held (before)':>14} {'order':>6}"]
    for method in sorted(METHODS, key=lambda m: (METHODS[m], m)):
        now, before = errors(method), errors(method, held=True)
        p_now, p_before = [math.nan, *slopes(now)], [math.nan, *slopes(before)]
        for i, ((k, e), (_, e_held)) in enumerate(zip(now, before)):
            lines.append(f"{method if i == 0 else '':<40} {METHODS[method] if i == 0 else '':>5} {k:>2} "
                         f"{dt_of(k):>9.4g} {e:>12.3e} {p_now[i]:>6.2f} {e_held:>14.3e} {p_before[i]:>6.2f}")
    return "\n".join(lines)


if __name__ == "__main__":
    print(table())
