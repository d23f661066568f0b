"""First same as last: the kick-drift-kick methods merge a step's closing kick with the next step's opening kick
between records where the loads do not depend on the velocities (simulate/run_loop.hpp). A run recorded at every
step is never merged (each step is closed for its record), so comparing it with the same run recorded every 100th
step compares the merged and unmerged steps: the same trajectory to round-off. Where a load reads the velocities
(drag) nothing is merged: the two runs agree bit for bit."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import rigiddyn as rd

MERGING = ["splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"]
STEPS, EVERY, DT = 1000, 100, 1e-3
U = 2.0**-53


def _bound(scale: float) -> float:
    # A merged kick of 2 e h equals the two kicks of e h it replaces up to the rounding of the velocity update and
    # of the work: a few u of the state per step. Carried by a stable step over N steps these perturbations add
    # up, and an error in the energy makes the phase drift at a rate that grows with it: at most about N^2 of them
    # on these regular motions (N = 1000 steps; 4 u per step).
    return 4.0 * U * STEPS**2 * scale


def _compare(fine, coarse, fields: tuple[str, ...]) -> None:
    for name in fields:
        a, b = np.asarray(getattr(fine, name))[::EVERY], np.asarray(getattr(coarse, name))
        assert a.shape == b.shape, name
        scale = max(np.abs(a).max(), 1.0)
        assert np.abs(a - b).max() <= _bound(scale), (name, np.abs(a - b).max(), _bound(scale))


def _body_runs(method: str):
    body = rd.RigidBody(2.0, np.diag([0.5, 0.8, 1.1]))
    state = rd.RigidBodyState(v_W=[0.3, 0.0, 1.0], w_B=[0.4, 1.5, 0.2])
    push = rd.AppliedLoad(torque=[0.05, -0.02, 0.01], frame="body")
    return [rd.simulate(body, state, DT, steps=STEPS, method=method, record_every=every, loads=push, gravity=True,
                        error=False) for every in (1, EVERY)]


@pytest.mark.parametrize("method", MERGING)
def test_a_body_under_loads_and_gravity_keeps_its_trajectory(method: str) -> None:
    fine, coarse = _body_runs(method)
    _compare(fine, coarse, ("p_W", "q_WB", "v_W", "w_B", "work"))


def _cluster(elements):
    bodies = [rd.RigidBody(1.0 + 0.2 * k, np.diag([0.3, 0.4, 0.5 + 0.1 * k])) for k in range(3)]
    start = [rd.RigidBodyState(p_W=[np.cos(2.1 * k), np.sin(2.1 * k), 0.1 * k], v_W=[-0.4 * np.sin(2.1 * k),
                               0.4 * np.cos(2.1 * k), 0.0], w_B=[0.2, 1.0 + k, -0.3]) for k in range(3)]
    return rd.Scene(bodies, elements=elements), start


@pytest.mark.parametrize("method", MERGING)
def test_a_scene_of_bodies_under_gravity_keeps_its_trajectory(method: str) -> None:
    scene, start = _cluster([rd.MutualGravity(G=1.0, softening=0.05), rd.UniformGravity(g_W=[0.0, 0.0, -1.0])])
    fine, coarse = (rd.simulate(scene, start, DT, steps=STEPS, method=method, record_every=every, error=False)
                    for every in (1, EVERY))
    _compare(fine, coarse, ("p_W", "q_WB", "v_W", "w_B", "work"))


@pytest.mark.parametrize("method", MERGING)
def test_a_pivoted_top_keeps_its_trajectory(method: str) -> None:
    top = rd.PivotedBody(rd.RigidBody(1.0, np.diag([0.02, 0.02, 0.01])), [0.0, 0.0, 0.1])
    scene = rd.Scene([top], elements=[rd.UniformGravity(g_W=[0.0, 0.0, -9.81])])
    start = [rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1.0, 0.0, 0.0], 0.3), w_B=[0.0, 0.0, 50.0])]
    fine, coarse = (rd.simulate(scene, start, DT, steps=STEPS, method=method, record_every=every, error=False)
                    for every in (1, EVERY))
    _compare(fine, coarse, ("q_WB", "w_B", "work"))


@pytest.mark.parametrize("method", MERGING)
def test_velocity_dependent_loads_are_not_merged(method: str) -> None:
    scene, start = _cluster([rd.UniformGravity(g_W=[0.0, 0.0, -1.0]), rd.Drag(linear=0.3)])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.SceneCompatibilityWarning)  # drag under a kick-based splitting
        fine, coarse = (rd.simulate(scene, start, DT, steps=STEPS, method=method, record_every=every, error=False)
                        for every in (1, EVERY))
    for name in ("p_W", "q_WB", "v_W", "w_B", "work"):
        assert np.array_equal(np.asarray(getattr(fine, name))[::EVERY], np.asarray(getattr(coarse, name))), name
