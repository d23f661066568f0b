"""One result type: the same free body under uniform gravity written four ways (a call of simulate with the body,
a one-body Scene, a problem file, a scene file) runs the same one-body scene and gives a SceneResult with equal
arrays, bitwise (the same numbers parsed, the same model, method and steps); Scene.of_body gives the scene a body's
simulate runs, for every kind."""

import pickle

import numpy as np
import pytest

import rigiddyn as rd

MASS, MOMENTS = 2.0, [0.5, 0.75, 1.25]
P_W, V_W, W_B = [0.5, -1.0, 2.0], [3.0, 0.5, 4.0], [0.2, 1.5, -0.3]
DT, STEPS, METHOD = 0.01, 120, "rk4"

PROBLEM = f"""
name = "tossed box"
horizon = {DT * STEPS}
gravity = true

[body]
mass = {MASS}
inertia = {MOMENTS}

[initial]
p_W = {P_W}
v_W = {V_W}
w_B = {W_B}
"""

SCENE = f"""
name = "tossed box"

[run]
method = "{METHOD}"
dt = {DT}
duration = {DT * STEPS}

[[body]]
name = "body0"
kind = "rigid"
mass = {MASS}
inertia = {MOMENTS}
p_W = {P_W}
v_W = {V_W}
w_B = {W_B}

[[force]]
type = "uniform_gravity"
g_W = [0, 0, -9.81]
"""

ARRAYS = ("t", "kinetic_energy", "potential_energy", "total_energy", "linear_momentum_W", "angular_momentum_W")
BODY_ARRAYS = ("p_W", "q_WB", "v_W", "w_B", "angular_momentum_O_W")


def test_a_body_four_ways_gives_one_result_type_with_equal_arrays(tmp_path):
    body = rd.RigidBody(MASS, MOMENTS)
    state = rd.RigidBodyState(p_W=P_W, v_W=V_W, w_B=W_B)
    call = rd.simulate(body, state, DT, STEPS, METHOD, gravity=True)
    scene = rd.simulate(rd.Scene([body], elements=[rd.UniformGravity()]), [state], DT, STEPS, METHOD)
    (tmp_path / "box.toml").write_text(PROBLEM)
    problem = rd.load_problem(tmp_path / "box.toml").simulate(METHOD, DT, STEPS)
    (tmp_path / "box_scene.toml").write_text(SCENE)
    model, initial, run = rd.load_scene(tmp_path / "box_scene.toml")
    scene_file = rd.simulate(model, initial, run.dt, STEPS, run.method)
    for result in (call, scene, problem, scene_file):
        assert type(result) is rd.SceneResult
        assert result.body_names == ("body0",) and result.body(0).q_WB.shape == (STEPS + 1, 4)
    for other in (scene, problem, scene_file):
        for name in ARRAYS:
            np.testing.assert_array_equal(getattr(other, name), getattr(call, name), strict=True, err_msg=name)
        for name in BODY_ARRAYS:
            np.testing.assert_array_equal(getattr(other.body(0), name), getattr(call.body(0), name), strict=True,
                                          err_msg=name)
        assert other.balance == call.balance


# every kind simulate takes alone, with a state; the gravity each can take (a planar body's in its plane); loads on
# the free kinds
KINDS = {
    "particle": (rd.Particle(MASS), rd.ParticleState(p_W=P_W, v_W=V_W), True,
                 [rd.AppliedLoad(force=(1.0, 0.0, 0.5), t_end=0.5)]),
    "planar": (rd.PlanarBody(MASS, 0.3), rd.PlanarBodyState(v_W=(1.0, 0.5), omega=2.0), [0.0, -9.81, 0.0],
               [rd.AppliedLoad(force=(1.0, 0.5, 0.0), torque=(0.0, 0.0, 0.2), frame="body")]),
    "rigid": (rd.RigidBody(MASS, MOMENTS), rd.RigidBodyState(p_W=P_W, v_W=V_W, w_B=W_B), True,
              [rd.AppliedLoad(torque=(0.1, 0.0, -0.2), frame="world", t_start=0.3)]),
    "pivoted": (rd.PivotedBody(rd.RigidBody(1.0, [1.0, 1.0, 0.5]), p_OC_B=[0.0, 0.0, 0.2]),
                rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1.0, 0.0, 0.0], 0.3), w_B=[0.1, 0.0, 5.0]), True, None),
    "pivoted_planar": (rd.PivotedPlanarBody(1.0, 0.5, [0.1, 0.2]), rd.PivotedPlanarBodyState(theta=0.3, omega=0.1),
                       [0.0, -9.81, 0.0], None),
    "gyrostat": (rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05, motor_torque=0.01)]),
                 rd.GyrostatState(w_B=W_B, wheel_speeds=[3.0]), None, None),
}


def test_scene_of_body_is_the_scene_simulate_runs_for_every_kind():
    for kind, (body, state, gravity, loads) in KINDS.items():
        scene = rd.Scene.of_body(body, gravity=gravity, loads=loads)
        expected = [name for name, given in (("UniformGravity", gravity), ("ScheduledLoads", loads)) if given]
        assert [type(e).__name__ for e in scene.elements] == expected, kind
        call = rd.simulate(body, state, DT, 60, METHOD, gravity=gravity, loads=loads)
        ran = rd.simulate(scene, [state], DT, 60, METHOD)
        for name in ARRAYS + ("work", "power"):
            np.testing.assert_array_equal(getattr(ran, name), getattr(call, name), strict=True, err_msg=f"{kind} {name}")
        for name in BODY_ARRAYS:
            np.testing.assert_array_equal(getattr(ran.body(0), name), getattr(call.body(0), name), strict=True,
                                          err_msg=f"{kind} {name}")


def test_scene_of_body_names_what_it_refuses():
    with pytest.raises(TypeError, match="body"):
        rd.Scene.of_body("a box")
    with pytest.raises(ValueError, match="gravity"):
        rd.Scene.of_body(rd.PlanarBody(1.0, 0.5), gravity=True)  # out of its plane
    with pytest.raises(ValueError, match=r"loads\[0\]"):
        rd.Scene.of_body(rd.Particle(1.0), loads=[rd.AppliedLoad(torque=(0.0, 0.0, 1.0))])


def assert_same_run(result, expected, what):
    for name in ARRAYS + ("work", "power"):
        np.testing.assert_array_equal(getattr(result, name), getattr(expected, name), strict=True, err_msg=f"{what} {name}")
    for name in BODY_ARRAYS:
        np.testing.assert_array_equal(getattr(result.body(0), name), getattr(expected.body(0), name), strict=True,
                                      err_msg=f"{what} {name}")
    assert result.elements == expected.elements, what


def test_a_body_simulated_again_and_again_runs_the_scene_of_its_own_inputs_every_time():
    # simulate of a particle, a planar or a rigid body keeps its compiled scene for the next call of the same body,
    # gravity, loads and method: each call of a sequence that changes one of them at a time runs what a fresh
    # compile of its own scene runs, bitwise (a principal inertia turned full changes the Euler form; a load's window,
    # the schedule)
    rigid, state = rd.RigidBody(MASS, MOMENTS), rd.RigidBodyState(p_W=P_W, v_W=V_W, w_B=W_B)
    full = rd.RigidBody(MASS, [[0.5, 0.01, 0.0], [0.01, 0.75, 0.0], [0.0, 0.0, 1.25]])
    push = [rd.AppliedLoad(force=(1.0, 0.0, 0.5), t_end=0.5)]
    calls = [(rigid, state, None, None, "rk4"), (rigid, state, None, None, "rk4"),
             (rd.RigidBody(MASS * 2.0, MOMENTS), state, None, None, "rk4"), (full, state, None, None, "rk4"),
             (rigid, state, True, None, "rk4"), (rigid, state, True, push, "rk4"),
             (rigid, state, True, [rd.AppliedLoad(force=(1.0, 0.0, 0.5), t_end=0.25)], "rk4"),
             (rigid, state, True, push, "rkmk4"), (rigid, state, None, None, "rk4")]
    calls += [(body, state, gravity, loads, METHOD) for body, state, gravity, loads in KINDS.values()]
    for i, (body, state, gravity, loads, method) in enumerate(calls):
        result = rd.simulate(body, state, DT, 30, method, gravity=gravity, loads=loads)
        expected = rd.simulate(rd.Scene.of_body(body, gravity=gravity, loads=loads).compile(method), [state], DT, 30)
        assert_same_run(result, expected, f"call {i}")


def test_a_run_keeps_its_compiled_scene_when_a_call_during_it_simulates_another_body():
    # a progress callback that simulates another body replaces the kept scene while the first run still uses its own
    rigid, state = rd.RigidBody(MASS, MOMENTS), rd.RigidBodyState(p_W=P_W, v_W=V_W, w_B=W_B)
    other, other_state = rd.Particle(3.0), rd.ParticleState(v_W=(1.0, 0.0, 0.0))
    calls = []

    def progress(steps_done):
        calls.append(rd.simulate(other, other_state, DT, 5, METHOD, gravity=True))

    result = rd.simulate(rigid, state, DT, 30, METHOD, gravity=True, progress=progress)
    assert calls, "progress was called"
    expected = rd.simulate(rd.Scene.of_body(rigid, gravity=True), [state], DT, 30, METHOD)
    assert_same_run(result, expected, "the run under the callback")
    assert_same_run(rd.simulate(rigid, state, DT, 30, METHOD, gravity=True), expected, "the next run")


@pytest.mark.parametrize("steps", [3, 600])  # a run that holds the GIL and one that releases it (512 body-steps)
def test_a_run_without_mass_flow_reads_zeros_of_its_shape_as_its_mass_flow_energy(steps):
    """Without a mass flow, mass_flow_energy is an (n, bodies) array of zeros, made on its first read: read-only,
    pickled as any other array, and the same zeros every read."""
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(1.0, [1.0, 2.0, 3.0]))
    scene.add_body(rd.Particle(2.0))
    initial = [rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), rd.ParticleState(v_W=[1.0, 0.0, 0.0])]
    result = rd.simulate(scene, initial, 0.01, steps=steps, method="rk4")
    energy = result.mass_flow_energy
    assert energy.shape == (steps + 1, 2)
    assert energy.dtype == np.float64 and not energy.flags.writeable
    assert np.array_equal(energy, np.zeros((steps + 1, 2)))
    assert result.mass_flow_energy is energy
    assert np.array_equal(pickle.loads(pickle.dumps(result)).mass_flow_energy, energy)
