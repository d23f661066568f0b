"""One result type: the same free body under uniform gravity written four ways (a call of simulate with the body,
a one-body Scene, a problem file, a scene file) runs the same one-body scene and gives a SceneResult with equal
arrays, bitwise (the same numbers parsed, the same model, method and steps)."""

import numpy as np

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
