"""Scene files for bodies about a fixed point, moving frames and variable mass (rigiddyn.scene_file): pinned
bodies ([[body]] kind "pivoted" and "pivoted_planar"), mass flows ([body.mass_flow]), the thrust element
([[force]] type "thrust"), the scene frame ([frame] kind "rotating" | "earth") and the [tradeoff] table: what
each key reads to, the field-named errors, and the canonical file (scene_to_toml) reading back to the same scene
bit for bit."""

import math

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn.scene_file import RunOptions, read_scene, scene_to_toml

NEW_SCENES = ["heavy_top", "pendulum", "foucault", "rocket"]

TOP = """
[[body]]
name = "top"
kind = "pivoted"
mass = "2 kg"
inertia = [0.01, 0.01, 0.02]
p_OC_B = {value = [0, 0, 10], unit = "cm"}
p_WO = [1, 2, 3]
axis_angle = {axis = [1, 0, 0], angle = "30 deg"}
w_B = {value = [0, 0, 600], unit = "rpm"}
"""

PENDULUM = """
[[body]]
name = "rod"
kind = "pivoted_planar"
mass = "1 kg"
inertia = "0.5 kg*m^2"
p_OC_B = [0, "-50 cm"]
theta = "90 deg"
omega = "60 rpm"
"""

ROCKET = """
[[body]]
name = "rocket"
kind = "particle"
mass = "100 kg"
[body.mass_flow]
rate = "-120 kg/min"
inertia_rule = "scaled"

[[force]]
type = "thrust"
body = "rocket"
u_rel = {value = [0, 0, -2], unit = "km/s"}
frame = "world"
"""


def test_a_pivoted_body_reads_to_a_pivoted_body_and_its_state():
    f = read_scene(TOP)
    (body,), (state,) = f.scene.bodies, f.initial
    assert isinstance(body, rd.PivotedBody) and isinstance(state, rd.PivotedBodyState)
    assert body.mass == 2.0
    np.testing.assert_array_equal(body.inertia_com, np.diag([0.01, 0.01, 0.02]))
    # unit conversions by pint: one rounding each (cm -> m, rpm -> rad/s, deg -> rad)
    np.testing.assert_allclose(body.p_OC_B, [0.0, 0.0, 0.1], rtol=1e-15, atol=0)
    np.testing.assert_array_equal(body.p_WO, [1.0, 2.0, 3.0])
    np.testing.assert_allclose(state.w_B, [0.0, 0.0, 20.0 * math.pi], rtol=1e-15, atol=0)
    half = math.radians(15.0)
    np.testing.assert_allclose(state.q_WB, [math.sin(half), 0.0, 0.0, math.cos(half)], rtol=0, atol=1e-16)


def test_a_pivoted_planar_body_reads_to_a_pivoted_planar_body_and_its_state():
    f = read_scene(PENDULUM)
    (body,), (state,) = f.scene.bodies, f.initial
    assert isinstance(body, rd.PivotedPlanarBody) and isinstance(state, rd.PivotedPlanarBodyState)
    assert (body.mass, body.inertia_zz) == (1.0, 0.5)
    np.testing.assert_allclose(body.p_OC_B, [0.0, -0.5], rtol=1e-15, atol=0)
    np.testing.assert_array_equal(body.p_WO, [0.0, 0.0])  # the default
    assert state.theta == pytest.approx(math.pi / 2, rel=1e-15)
    assert state.omega == pytest.approx(2.0 * math.pi, rel=1e-15)


def test_a_mass_flow_and_a_thrust_read_to_the_scene_s_mass_flow_and_thrust_element():
    f = read_scene(ROCKET)
    (flow,) = f.scene.mass_flows
    assert flow.rate == pytest.approx(-2.0, rel=1e-15)  # -120 kg/min: one rounding
    assert flow.inertia_rule == "scaled"
    (thrust,) = f.scene.elements
    assert type(thrust).__name__ == "Thrust" and thrust.body == 0 and thrust.frame == "world"
    np.testing.assert_array_equal(thrust.u_rel, [0.0, 0.0, -2000.0])
    np.testing.assert_array_equal(thrust.r_B, [0.0, 0.0, 0.0])  # the default


def test_a_body_without_a_mass_flow_table_has_none():
    f = read_scene('[[body]]\nname = "other"\nkind = "particle"\nmass = 1\n' + ROCKET)
    assert f.scene.mass_flows[0] is None  # the first body has no [body.mass_flow] table
    assert f.scene.mass_flows[1].rate == pytest.approx(-2.0, rel=1e-15)


@pytest.mark.parametrize("table, axis, rate", [
    ('kind = "rotating"\naxis = [0, 0, 2]\nrate = "1 rpm"', [0.0, 0.0, 2.0], 2.0 * math.pi / 60.0),
    ('kind = "earth"\nlatitude = "48.85 deg"', [0.0, math.cos(math.radians(48.85)), math.sin(math.radians(48.85))],
     7.2921159e-5),
])
def test_a_frame_table_reads_to_the_scene_frame(table, axis, rate):
    from rigiddyn.scene_describe import frame_rotation

    f = read_scene(f"[frame]\n{table}\n" + PENDULUM.replace("pivoted_planar", "planar").replace(
        "p_OC_B", "p_W"))
    got_axis, got_rate = frame_rotation(f.scene.frame)
    # the unit axis: a few roundings of cos, sin and the normalisation
    np.testing.assert_allclose(got_axis / np.linalg.norm(got_axis), np.asarray(axis) / np.linalg.norm(axis),
                               rtol=0, atol=4e-16)
    assert got_rate == pytest.approx(rate, rel=1e-15)


def test_no_frame_table_is_the_inertial_w():
    assert read_scene(PENDULUM).scene.frame is None


BAD = [
    (TOP.replace('p_WO = [1, 2, 3]', 'p_W = [1, 2, 3]'), "body[0].p_W: expected a key of a [[body]] of kind 'pivoted'"),
    (TOP.replace('p_OC_B = {value = [0, 0, 10], unit = "cm"}', ''),
     "body[0].p_OC_B: expected the centre of mass relative to the pivot, 3 lengths [m] in B, got 'nothing'"),
    (TOP.replace('unit = "cm"', 'unit = "kg"'), "body[0].p_OC_B.unit"),
    (PENDULUM.replace('p_OC_B = [0, "-50 cm"]', 'p_OC_B = [0, 0, -0.5]'), "body[0].p_OC_B"),
    (PENDULUM.replace('inertia = "0.5 kg*m^2"', 'inertia = "-0.5 kg*m^2"'), "body[0].inertia: expected"),
    (PENDULUM.replace('kind = "pivoted_planar"', 'kind = "pivoted_plane"'),
     "body[0].kind: expected one of 'particle', 'planar', 'rigid', 'pivoted', 'pivoted_planar', 'gyrostat' (did you mean "
     "'pivoted_planar'?), got 'pivoted_plane'"),
    (ROCKET.replace('rate = "-120 kg/min"', 'rate = "-2 kg"'), "body[0].mass_flow.rate: expected kg/s"),
    (ROCKET.replace('rate = "-120 kg/min"', 'rate = inf'), "body[0].mass_flow.rate: expected kg/s, got inf"),
    (ROCKET.replace('rate = "-120 kg/min"', 'rat = -2'), "body[0].mass_flow.rat: expected a key of "
     "[body.mass_flow]; did you mean 'rate'?"),
    (ROCKET.replace('inertia_rule = "scaled"', 'inertia_rule = "function"'),
     "body[0].mass_flow.inertia_rule: expected 'scaled' (a function of the mass: MassFlow in Python), got 'function'"),
    (ROCKET.replace('frame = "world"', 'frame = "inertial"'), "force[0].frame: expected 'body' or 'world', got 'inertial'"),
    # a mass flow on a kind without one is refused when the file is read, naming the file's table
    (TOP + '[body.mass_flow]\nrate = "-1 kg/s"\n', "body[0].mass_flow: expected no [body.mass_flow] table on a "
     "pivoted body (a mass flow applies to particles and rigid bodies)"),
    (PENDULUM + '[body.mass_flow]\nrate = "-1 kg/s"\n', "body[0].mass_flow: expected no [body.mass_flow] table on a "
     "pivoted_planar body"),
    (ROCKET.replace('unit = "km/s"', 'unit = "km"'), "force[0].u_rel.unit"),
    (ROCKET.replace('body = "rocket"', 'body = "rockett"'), "force[0].body: expected the name of a [[body]]"),
    (ROCKET.replace('u_rel = {value = [0, 0, -2], unit = "km/s"}', ''), "force[0].u_rel: expected a value [m/s], "
     "got 'nothing'"),
    ('[frame]\nkind = "spinning"\n' + PENDULUM, "frame.kind: expected 'rotating' or 'earth', got 'spinning'"),
    ('[frame]\nkind = "earth"\n' + PENDULUM, "frame.latitude: expected an angle [rad], got 'nothing'"),
    ('[frame]\nkind = "earth"\nlatitude = "1 m"\n' + PENDULUM, "frame.latitude: expected rad"),
    ('[frame]\nkind = "earth"\nlatitude = "100 deg"\n' + PENDULUM, "frame.latitude: expected"),
    ('[frame]\nkind = "rotating"\naxis = [0, 0, 0]\nrate = 1\n' + PENDULUM, "frame.axis"),
    ('[frame]\nkind = "rotating"\naxis = [0, 0, 1]\nrate = "1 m/s"\n' + PENDULUM, "frame.rate: expected rad/s"),
    ('[frame]\nkind = "rotating"\naxis = [0, 0, 1]\nrate = 1\nlatitude = 0\n' + PENDULUM,
     "frame.latitude: expected a key of a [frame] of kind 'rotating'"),
    ('[tradeoff]\ndts = ["1 kg"]\n' + PENDULUM, "tradeoff.dts[0]: expected s"),
    ('[tradeoff]\nhorizon = -1\n' + PENDULUM, "tradeoff.horizon: expected"),
    ('[tradeoff]\nmethods = ["rk5"]\n' + PENDULUM, "tradeoff.methods[0]: expected one of"),
    ('[tradeoff]\nstep = 1\n' + PENDULUM, "tradeoff.step: expected a key of [tradeoff]"),
]


@pytest.mark.parametrize("text, message", BAD, ids=[m[:40] for _, m in BAD])
def test_bad_input_is_a_value_error_naming_the_field(text, message):
    with pytest.raises(ValueError) as error:
        read_scene(text)
    assert str(error.value).startswith(message), str(error.value)


def test_the_tradeoff_table_reads_to_the_run_options():
    f = read_scene('[tradeoff]\nmethods = ["rk4"]\ndts = ["1 ms", 0.002]\nhorizon = "1 min"\ntolerance = 1e-6\n'
                   'measure = "max_state_error"\n' + PENDULUM)
    assert f.run.tradeoff == {"methods": ["rk4"], "dts": [1e-3, 2e-3], "horizon": 60.0, "tolerance": 1e-6,
                              "measure": "max_state_error"}
    assert read_scene(PENDULUM).run.tradeoff == {}


def _same_scene(a, b):
    """Two SceneFiles hold the same scene and states, number for number."""
    assert a.scene == b.scene
    assert [repr(s) for s in a.initial] == [repr(s) for s in b.initial]
    assert a.run == b.run


@pytest.mark.parametrize("name", NEW_SCENES)
def test_the_new_shipped_scenes_round_trip_through_the_canonical_file(name):
    f = read_scene(name)
    text = scene_to_toml(f.scene, f.initial, f.run, name=f.name)
    g = read_scene(text)
    _same_scene(f, g)
    assert scene_to_toml(g.scene, g.initial, g.run, name=g.name) == text  # canonical: a fixed point


@pytest.mark.parametrize("text", [TOP, PENDULUM, ROCKET,
                                  '[frame]\nkind = "rotating"\naxis = [0.3, 0.4, 1.2]\nrate = 0.1\n' + TOP,
                                  '[frame]\nkind = "earth"\nlatitude = "-33.9 deg"\n' + ROCKET])
def test_written_files_read_back_bit_for_bit(text):
    f = read_scene(text)
    g = read_scene(scene_to_toml(f.scene, f.initial, RunOptions(tradeoff={"dts": [0.1, 0.05], "horizon": 2.0})))
    assert f.scene == g.scene
    assert [repr(s) for s in f.initial] == [repr(s) for s in g.initial]
    assert g.run.tradeoff == {"dts": [0.1, 0.05], "horizon": 2.0}


def test_a_general_moving_frame_or_a_mass_rate_function_cannot_be_written():
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="p", mass_flow=rd.MassFlow(rate=lambda t: -0.1))
    with pytest.raises(ValueError, match=r"^body\[0\]\.mass_flow: expected a constant rate"):
        scene_to_toml(scene)
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="p")
    motion = rd.FrameMotion(lambda t: rd.FrameKinematics())
    scene.frame = rd.SceneFrame.moving(motion)
    with pytest.raises(ValueError, match=r"^scene\.frame: expected a frame a scene file can hold"):
        scene_to_toml(scene)
