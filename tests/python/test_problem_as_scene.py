"""A problem file is a one-body scene file plus the problem's run settings (rigiddyn.load_problem's Notes):
the same body, initial state, gravity and loads, read by the same code, written either way."""

import textwrap

import numpy as np
import pytest
import rigiddyn
from rigiddyn.problem import parse_problem

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

PROBLEM = """
horizon = "3 s"
gravity = [0, 0, "-32.174 ft/s^2"]
[body.primitive]
shape = "solid_box"
size = ["10 cm", "20 cm", "30 cm"]
density = "2.7 g/cm^3"
[initial]
p_W = ["1 km", 0, 0]
v_W = {value = [36, 0, 0], unit = "km/h"}
w_B = [0.01, "1500 rpm", 0]
euler = {seq = "ZYX", angles = ["30 deg", "10 deg", 0]}
[[loads]]
force = ["1 kN", 0, 0]
torque = [0, 0, "1 N cm"]
frame = "body"
t_start = "1 s"
t_end = "2 s"
"""

SCENE = """
[run]
duration = "3 s"
[[body]]
name = "body"
kind = "rigid"
p_W = ["1 km", 0, 0]
v_W = {value = [36, 0, 0], unit = "km/h"}
w_B = [0.01, "1500 rpm", 0]
euler = {seq = "ZYX", angles = ["30 deg", "10 deg", 0]}
[body.primitive]
shape = "solid_box"
size = ["10 cm", "20 cm", "30 cm"]
density = "2.7 g/cm^3"
[[force]]
type = "uniform_gravity"
g_W = [0, 0, "-32.174 ft/s^2"]
[[force]]
type = "scheduled_loads"
body = "body"
[[force.loads]]
force = ["1 kN", 0, 0]
torque = [0, 0, "1 N cm"]
frame = "body"
t_start = "1 s"
t_end = "2 s"
"""


def test_a_problem_file_is_its_one_body_scene_file():
    problem = parse_problem(tomllib.loads(textwrap.dedent(PROBLEM)))
    scene, (state,), run = rigiddyn.load_scene(textwrap.dedent(SCENE))
    body, (gravity, loads) = scene.bodies[0], scene.elements
    # every number read by the same code from the same text: equal to the bit
    assert problem.body().mass == body.mass and problem.horizon == run.duration
    np.testing.assert_array_equal(problem.body().inertia_com, body.inertia_com)
    for key in ("p_W", "v_W", "w_B", "q_WB"):
        np.testing.assert_array_equal(getattr(problem, key), getattr(state, key), err_msg=key)
    np.testing.assert_array_equal(problem.gravity, gravity.g_W)
    assert problem.loads == tuple(loads.loads)


def test_both_loaders_return_a_scene_file():
    """One loader return type: load_scene gives a SceneFile and load_problem's Problem is one, each unpacking as
    scene, initial, run; the problem's scene is the scene file's, so the same run gives the same records."""
    from rigiddyn.scene_file import SceneFile

    problem = parse_problem(tomllib.loads(textwrap.dedent(PROBLEM)))
    file = rigiddyn.load_scene(textwrap.dedent(SCENE))
    assert isinstance(problem, SceneFile) and type(file) is SceneFile
    scene, initial, run = problem
    # the same body, elements, state and duration (the scene file names its body, the problem's is body0)
    assert (scene.bodies, scene.elements) == (file.scene.bodies, file.scene.elements)
    assert (initial, run.duration, run.tradeoff) == (file.initial, file.run.duration, problem.tradeoff)
    from_file = rigiddyn.simulate(file.scene, file.initial, 1e-3, duration=file.run.duration, method="rk4")
    from_problem = problem.simulate("rk4", 1e-3)
    for field in ("t", "p_W", "q_WB", "v_W", "w_B", "work", "total_energy"):
        np.testing.assert_array_equal(getattr(from_problem, field), getattr(from_file, field), err_msg=field)
    with pytest.raises(AttributeError, match="SceneFile is read-only: cannot set 'name'"):
        file.name = "other"  # type: ignore[misc]
    with pytest.raises(ValueError, match=r"^initial: expected a list of 1 body states"):
        SceneFile(file.scene, [], file.run, "short")
    with pytest.raises(TypeError, match=r"^run: expected a RunOptions"):
        SceneFile(file.scene, file.initial, {"dt": 0.1}, "dict")
