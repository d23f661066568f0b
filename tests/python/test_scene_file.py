"""TOML scene files (rigiddyn.scene_file) and describe (rigiddyn.scene_describe): shipped scenes load,
round-trip through the canonical TOML, carry units, and every bad input is a ValueError naming its field."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import rigiddyn
from rigiddyn.scene_file import RunOptions, example_scenes, load_scene, read_scene, scene_path, scene_to_toml

# A unit conversion is a product of the number with up to three rounded factors: relative error below
# 4 roundings of 2^-53 (1e-15 bounds it).
RTOL_UNITS = 1e-15

SHIPPED = ["box_on_springs", "double_pendulum", "gravity_gradient", "kepler", "satellite_boom", "solar_array",
           "spring_chain", "three_body"]


def _state(state):
    """A state's variables as a dict of float arrays (the same for equal states)."""
    keys = [k for k in ("p_W", "q_WB", "v_W", "w_B", "theta", "omega", "q", "v") if hasattr(state, k)]
    return {k: np.asarray(getattr(state, k), dtype=float) for k in keys} | {"type": type(state).__name__}


def _same_states(a, b):
    assert len(a) == len(b)
    for x, y in zip(a, b):
        sx, sy = _state(x), _state(y)
        assert sx.keys() == sy.keys() and sx["type"] == sy["type"]
        for k in sx:
            if k != "type":
                np.testing.assert_array_equal(sx[k], sy[k], err_msg=k)


def test_the_shipped_scenes_are_listed():
    assert set(SHIPPED) <= set(example_scenes())


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_scene_round_trips_through_canonical_toml(name):
    f = read_scene(name)
    text = scene_to_toml(f.scene, f.initial, f.run, f.name, f.description)
    g = read_scene(text)
    assert g.scene == f.scene  # Scene.__eq__: bodies, names and every element field by field
    _same_states(g.initial, f.initial)
    assert g.run == f.run and g.name == f.name and g.description == f.description
    # canonical: writing what was read back gives the same text (a fixed point)
    assert scene_to_toml(g.scene, g.initial, g.run, g.name, g.description) == text
    assert _strings(tomllib.loads(text), "") <= _NAMES  # SI, radians: no value carries a unit


_NAMES = {"name", "description", "kind", "type", "frame", "inertia_check", "method", "body", "body_a", "body_b",
          "bodies", "joint", "parent"}


def _strings(value, key):
    """The keys of the string values anywhere in parsed TOML."""
    if isinstance(value, dict):
        return set().union(*(_strings(v, k) for k, v in value.items()))
    if isinstance(value, list):
        return set().union(*(_strings(v, key) for v in value))
    return {key} if isinstance(value, str) else set()


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_scene_runs_and_is_described(name):
    scene, initial, run = load_scene(name)
    assert run.dt is not None and run.duration is not None
    result = rigiddyn.simulate(scene, initial, dt=run.dt, steps=3, method=run.method)
    assert result.t.shape == (4,) and not result.diverged
    text = scene.describe(run.method)
    for body_name in scene.body_names:
        assert body_name in text
    for element in scene.elements:
        assert type(element).__name__ in text
    assert f"Method: {run.method}" in text


def test_round_trip_runs_bitwise_the_same():
    scene, initial, run = load_scene("spring_chain")
    scene2, initial2, _ = load_scene(scene_to_toml(scene, initial, run))
    a = rigiddyn.simulate(scene, initial, dt=run.dt, steps=50, method="rk4")
    b = rigiddyn.simulate(scene2, initial2, dt=run.dt, steps=50, method="rk4")
    np.testing.assert_array_equal(a.p_W, b.p_W)
    np.testing.assert_array_equal(a.work, b.work)


def test_kepler_units_are_read_in_si():
    scene, initial, run = load_scene("kepler")
    (gravity,) = scene.elements
    assert gravity.gm == pytest.approx(3.986004418e14, rel=RTOL_UNITS)
    np.testing.assert_allclose(initial[0].p_W, [6.3e6, 0.0, 0.0], rtol=RTOL_UNITS)
    # perigee speed of a = 7000 km, e = 0.1: sqrt(GM/a (1 + e)/(1 - e)), written to 16 digits in km/s
    gm, a, e = 3.986004418e14, 7.0e6, 0.1
    assert initial[0].v_W[1] == pytest.approx(math.sqrt(gm / a * (1 + e) / (1 - e)), rel=1e-15)
    assert run == RunOptions("rk4", 9.714194396143359, 58285.16637686015, 10)
    assert run.steps == 6000  # 10 periods of 600 steps


def test_every_unit_form_in_a_file():
    text = """
    [run]
    dt = "2 ms"
    duration = "1 min"
    [[body]]
    name = "b"
    kind = "rigid"
    mass = "2 slug"
    inertia = [["1 lb*ft^2", 0, 0], [0, "1 lb*ft^2", 0], [0, 0, "0.05 kg*m^2"]]
    p_W = ["3 ft", 0, 0]
    v_W = {value = [1, 0, 0], unit = "ft/s"}
    w_B = {value = [0, 0, 1500], unit = "rpm"}
    euler = {seq = "ZYX", angles = ["30 deg", 0, 0]}
    [[body]]
    name = "p"
    kind = "planar"
    mass = 1
    inertia = "1 g*cm^2"
    theta = "90 deg"
    omega = "60 rpm"
    [[force]]
    type = "scheduled_loads"
    body = "b"
    point_B = ["1 in", 0, 0]
    [[force.loads]]
    force = ["5 lbf", 0, 0]
    t_end = "500 ms"
    """
    scene, initial, run = load_scene(text)
    rigid, planar = scene.bodies
    lb, ft = 0.45359237, 0.3048
    assert rigid.mass == pytest.approx(2 * lb * 9.80665 / ft, rel=RTOL_UNITS)
    assert np.asarray(rigid.inertia_com)[0, 0] == pytest.approx(lb * ft**2, rel=RTOL_UNITS)
    assert planar.inertia_zz == pytest.approx(1e-7, rel=RTOL_UNITS)
    np.testing.assert_allclose(initial[0].p_W, [3 * ft, 0, 0], rtol=RTOL_UNITS)
    np.testing.assert_allclose(initial[0].v_W, [ft, 0, 0], rtol=RTOL_UNITS)
    np.testing.assert_allclose(initial[0].w_B, [0, 0, 50 * math.pi], rtol=RTOL_UNITS)
    # "30 deg" about Z: the same attitude as the problem-file form degrees = true (both through np.deg2rad's
    # factor pi/180 or pint's; they agree to a rounding of the angle, well inside 1e-15 on sin/cos)
    np.testing.assert_allclose(initial[0].q_WB, [0, 0, math.sin(math.pi / 12), math.cos(math.pi / 12)],
                               rtol=0, atol=1e-15)
    assert initial[1].theta == pytest.approx(math.pi / 2, rel=RTOL_UNITS)
    assert initial[1].omega == pytest.approx(2 * math.pi, rel=RTOL_UNITS)
    (loads,) = scene.elements
    np.testing.assert_allclose(loads.point_B, [0.0254, 0, 0], rtol=RTOL_UNITS)
    assert loads.loads[0].force[0] == pytest.approx(5 * lb * 9.80665, rel=RTOL_UNITS)
    assert loads.loads[0].t_end == 0.5 and math.isinf(loads.loads[0].t_start)
    assert run.dt == 0.002 and run.duration == 60.0 and run.method == "rk4" and run.record_every == 1
    # and the canonical text reloads to the same
    text2 = scene_to_toml(scene, initial, run)
    scene2, initial2, run2 = load_scene(text2)
    assert scene2 == scene and run2 == run
    _same_states(initial2, initial)


def test_attitude_forms_of_problem_files():
    def q(attitude):
        _, initial, _ = load_scene(f'[[body]]\nkind = "rigid"\nmass = 1\ninertia = [1, 1, 1]\n{attitude}\n')
        return np.asarray(initial[0].q_WB)

    reference = q("axis_angle = {axis = [0, 0, 1], angle = 0.5}")
    for form in ("rotvec = [0, 0, 0.5]", "q_WB = [0, 0, 0.24740395925452294, 0.9689124217106447]",
                 "q_WB = [0.9689124217106447, 0, 0, 0.24740395925452294]\nscalar_first = true",
                 'euler = {seq = "ZYX", angles = [0.5, 0, 0]}', 'rotvec = {value = [0, 0, "0.5 rad"]}',
                 f"axis_angle = {{axis = [0, 0, 2], angle = {math.degrees(0.5)!r}, degrees = true}}"):
        # each form is one or two roundings from the exact quaternion (cos 0.25, sin 0.25 about z)
        np.testing.assert_allclose(q(form), reference, rtol=0, atol=4e-16, err_msg=form)


def test_body_and_force_defaults():
    scene, initial, run = load_scene('[[body]]\nkind = "particle"\nmass = 2\n[[force]]\ntype = "uniform_gravity"\n'
                                     '[[force]]\ntype = "mutual_gravity"\n')
    assert scene.body_names == ("body0",)
    np.testing.assert_array_equal(initial[0].p_W, [0, 0, 0])
    assert run == RunOptions() and run.steps is None
    gravity, mutual = scene.elements
    np.testing.assert_array_equal(gravity.g_W, [0, 0, -9.81])
    assert gravity.bodies is None and mutual.G == 6.67430e-11


def test_bodies_are_referred_to_by_name():
    scene, _, _ = load_scene("""
    [[body]]
    name = "a"
    kind = "particle"
    mass = 1
    [[body]]
    name = "b"
    kind = "particle"
    mass = 1
    [[force]]
    type = "drag"
    linear = 0.1
    bodies = ["b"]
    [[force]]
    type = "spring_damper"
    body_a = "b"
    body_b = "a"
    stiffness = 3
    """)
    drag, spring = scene.elements
    assert drag.bodies == (1,) and spring.body_a == 1 and spring.body_b == 0


def test_load_scene_from_a_path(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(scene_path("three_body").read_text())
    a, b = read_scene(path), read_scene(str(path))
    assert a.scene == b.scene == read_scene("three_body").scene and a.name == "three-body figure eight"
    bare = tmp_path / "bare.toml"
    bare.write_text('[[body]]\nkind = "particle"\nmass = 1\n')
    assert read_scene(bare).name == "bare"


def test_scene_to_toml_writes_no_state_without_one():
    scene, _, _ = load_scene("box_on_springs")
    scene2, initial2, _ = load_scene(scene.to_toml())
    assert scene2 == scene
    np.testing.assert_array_equal(initial2[0].q_WB, [0, 0, 0, 1])


def test_a_python_force_has_no_file_form():
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0))
    scene.add(rigiddyn.PythonForce(lambda t, body, p, q, v, w: ((0, 0, 0), (0, 0, 0))))
    with pytest.raises(ValueError, match=r"scene.elements\[0\]: expected an element a scene file can hold"):
        scene_to_toml(scene, [rigiddyn.ParticleState()])
    with pytest.raises(ValueError, match=r"initial: expected one state per body \(1\)"):
        scene_to_toml(rigiddyn.Scene([rigiddyn.Particle(1.0)]), [])


def test_full_inertia_planar_bodies_and_load_schedules_round_trip():
    text = """
    [[body]]
    kind = "rigid"
    mass = 1
    inertia = [[1, 0.1, 0], [0.1, 2, 0], [0, 0, 2.5]]
    w_B = [0.1, 0.2, 0.3]
    rotvec = [0.1, -0.2, 0.3]
    [[body]]
    kind = "planar"
    mass = 2
    inertia = 0.5
    p_W = [1, 2]
    v_W = [0.5, 0]
    theta = 0.3
    omega = -1
    [[force]]
    type = "scheduled_loads"
    body = "body0"
    point_B = [0, 0, 0.1]
    [[force.loads]]
    force = [1, 0, 0]
    t_end = 2
    [[force.loads]]
    torque = [0, 0, 1]
    frame = "body"
    t_start = 2
    [[force]]
    type = "drag"
    quadratic = 0.01
    angular_linear = 0.001
    bodies = ["body1", "body0"]
    """
    f = read_scene(text)
    out = scene_to_toml(f.scene, f.initial, f.run, "n", "two\nlines")
    g = read_scene(out)
    assert g.scene == f.scene and g.run == f.run and g.description == "two\nlines"
    _same_states(g.initial, f.initial)
    assert "inertia = [[1.0, 0.1, 0.0], [0.1, 2.0, 0.0], [0.0, 0.0, 2.5]]" in out  # one line per array


def test_unrealizable_inertia_is_written_with_its_check():
    text = ('[[body]]\nkind = "rigid"\nmass = 1\ninertia = [2, 1, 0.6666666666666666]\n'
            'inertia_check = "allow_unrealizable"\n')
    scene, initial, _ = load_scene(text)
    out = scene_to_toml(scene, initial)
    assert 'inertia_check = "allow_unrealizable"' in out and load_scene(out).scene == scene


B = '[[body]]\nname = "sat"\nkind = "rigid"\nmass = 1\ninertia = [1, 2, 3]\n'
P = '[[body]]\nname = "ball"\nkind = "particle"\nmass = 1\n'


@pytest.mark.parametrize("text,message", [
    # unknown unit, wrong dimension
    (B.replace("mass = 1", 'mass = "2 slugz"'), "body[0].mass: expected kg, got '2 slugz' (unknown unit"),
    (B.replace("[1, 2, 3]", '["3 kg m", 2, 3]'), "body[0].inertia[0]: expected kg m^2, got '3 kg m' ([mass] * [length])"),
    (B + 'p_W = {value = [1, 2, 3], unit = "s"}', "body[0].p_W.unit: expected m, got 's' ([time])"),
    (B + 'w_B = [0, 0, "3 m/s"]', "body[0].w_B[2]: expected rad/s, got '3 m/s'"),
    (P + '[[force]]\ntype = "point_mass_gravity"\ngm = "3 km^2/s^2"', "force[0].gm: expected m^3/s^2, got '3 km^2/s^2'"),
    ('[run]\ndt = "1 m"\n' + P, "run.dt: expected s, got '1 m' ([length])"),
    # unknown body name
    (P + '[[force]]\ntype = "drag"\nbodies = ["bal"]', "force[0].bodies[0]: expected the name of a [[body]]: one of "
                                                        "'ball' (did you mean 'ball'?), got 'bal'"),
    (P + '[[force]]\ntype = "spring_damper"\nbody_a = "sat"\nstiffness = 1', "force[0].body_a: expected the name of a "
                                                                             "[[body]]: one of 'ball', got 'sat'"),
    (P + '[[force]]\ntype = "scheduled_loads"\nbody = 0', "force[0].body: expected the name of a [[body]]"),
    (P + '[[force]]\ntype = "drag"\nbodies = []', "force[0].bodies: expected a non-empty array of body names"),
    # unknown force type
    (P + '[[force]]\ntype = "uniform_gravityy"', "force[0].type: expected one of 'uniform_gravity', "),
    (P + '[[force]]\ntype = "uniform_gravityy"', "(did you mean 'uniform_gravity'?), got 'uniform_gravityy'"),
    # missing required fields
    ('[[body]]\nkind = "particle"\n', "body[0].mass: expected a mass [kg] > 0, got 'nothing'"),
    ('[[body]]\nmass = 1\n', "body[0].kind: expected one of 'particle', 'planar', 'rigid', 'pivoted', 'pivoted_planar', 'gyrostat', got 'nothing'"),
    ('[[body]]\nkind = "rigid"\nmass = 1\n', "body[0].inertia: expected 3 principal moments or a 3x3 matrix"),
    (P + '[[force]]\ntype = "point_mass_gravity"', "force[0].gm: expected a value [m^3/s^2], got 'nothing'"),
    (P + '[[force]]\ntype = "spring_damper"\nbody_a = "ball"', "force[0].stiffness: expected a value [N/m], got 'nothing'"),
    (P + '[[force]]\ngm = 1', "force[0].type: expected one of"),
    (P + '[[force]]\ntype = "scheduled_loads"', "force[0].body: expected a value, got 'nothing'"),
    ('name = "x"\n', "scene.body: expected at least one [[body]], [[cluster]] or [[tree]] table, got 'nothing'"),
    # unknown keys, with the closest known one
    (B + "w_b = [1, 2, 3]", "body[0].w_b: expected a key of a [[body]] of kind 'rigid'; did you mean 'w_B'?"),
    (P + "w_B = [1, 2, 3]", "body[0].w_B: expected a key of a [[body]] of kind 'particle'"),
    (P + '[[force]]\ntype = "drag"\nlinaer = 1', "force[0].linaer: expected a key of a [[force]] of type 'drag'; did "
                                                 "you mean 'linear'?"),
    ('[run]\nsteps = 3\n' + P, "run.steps: expected a key of [run]"),
    ('horizon = 3\n' + P, "scene.horizon: expected a key of the top level"),
    (P + '[[force]]\ntype = "scheduled_loads"\nbody = "ball"\n[[force.loads]]\nforce = [1, 0, 0]\ntorq = [0, 0, 1]',
     "force[0].loads[0].torq: expected a key of [[force.loads]]; did you mean 'torque'?"),
    # other values the core or the format refuses, named by their field
    (P + P, "body[1].name: expected a name no other [[body]] has, got 'ball'"),
    ('[[body]]\nkind = "soft"\nmass = 1\n', "body[0].kind: expected one of 'particle', 'planar', 'rigid', 'pivoted', 'pivoted_planar', 'gyrostat', got 'soft'"),
    (B.replace("[1, 2, 3]", "[1, 2, 30]"), "body[0].inertia: expected a symmetric inertia satisfying the triangle"),
    ('[[body]]\nkind = "planar"\nmass = 1\ninertia = -1\n', "body[0].inertia: expected kg m^2 > 0, got -1"),
    (P.replace("mass = 1", "mass = 0"), "body[0].mass: expected kg > 0, got 0"),
    (B + 'euler = {seq = "ZYQ", angles = [0, 0, 0]}', "body[0].euler.seq"),
    (B + 'euler = {seq = "ZYX", angles = ["30 deg", 0, 0], degrees = true}', "body[0].euler.degrees: expected no "
                                                                             "degrees flag beside angles with units"),
    (B + 'q_WB = [0, 0, 0, 2]', "body[0].q_WB: expected a unit quaternion"),
    (B + 'q_WB = [0, 0, 0, 1]\nrotvec = [0, 0, 1]', "body[0]: expected at most one orientation"),
    (P + '[[force]]\ntype = "spring_damper"\nbody_a = "ball"\nstiffness = -1', "force[0].stiffness: expected"),
    (P + '[[force]]\ntype = "spring_damper"\nbody_a = "ball"\nbody_b = "ball"\nstiffness = 1', "force[0].body_b"),
    (P + '[[force]]\ntype = "scheduled_loads"\nbody = "ball"\n[[force.loads]]\nforce = [1, 0, 0]\nframe = "inertial"',
     "force[0].loads[0].frame"),
    ('[run]\nmethod = "rk5"\n' + P, "run.method: expected one of"),
    ('[run]\nrecord_every = 0\n' + P, "run.record_every: expected an integer >= 1, got 0"),
    ("[[body]\n", "scene: expected valid TOML"),
])
def test_bad_input_is_a_value_error_naming_the_field(text, message):
    with pytest.raises(ValueError) as e:
        load_scene(text)
    assert message in str(e.value)


def test_bad_paths():
    with pytest.raises(ValueError, match="path_or_text: expected an existing .toml file"):
        load_scene("no/such/file.toml")
    with pytest.raises(ValueError, match="path_or_text: expected a .toml path, TOML text or one of the shipped scenes"):
        load_scene("keplr")
    with pytest.raises(TypeError, match="path_or_text"):
        load_scene(3)
    with pytest.raises(ValueError, match="path_or_text"):
        load_scene(Path("missing.toml"))


def test_describe_tables_bodies_terms_frame_method_units():
    scene, _, _ = load_scene("box_on_springs")
    text = scene.describe()
    assert "Scene: 1 body, 5 force elements" in text and "Frame: W, inertial" in text and "Units: SI" in text
    assert "box" in text and "rigid" in text and "diag(0.866667, 1.93333, 2.26667)" in text
    rows = [line for line in text.splitlines() if "SpringDamper" in line]
    assert len(rows) == 4 and all("f+tau" in r and "velocity-dependent" in r for r in rows)  # corner springs
    assert not any("internal" in r for r in rows)  # each hangs the box from a world anchor, which takes its reaction
    three_body, _, _ = load_scene("three_body")
    assert "potential, internal" in three_body.describe()  # mutual gravity: its pair forces cancel
    assert "Method" not in text
    assert "Method: rk4" in scene.describe("rk4") and "accepted" in scene.describe("rk4")
    compiled = scene.compile("rk4")
    assert compiled.describe() == scene.describe("rk4")
    assert "refused" in scene.describe("exact")  # 'exact' runs no force element
    with pytest.raises(ValueError, match="method: expected one of"):
        scene.describe("rk5")


def test_describe_marks_only_the_bodies_an_element_acts_on():
    scene, _, _ = load_scene(P + '[[body]]\nname = "top"\nkind = "rigid"\nmass = 1\ninertia = [1, 1, 2]\n'
                             '[[force]]\ntype = "uniform_gravity"\nbodies = ["top"]\n'
                             '[[force]]\ntype = "gravity_gradient"\ngm = 1\n')
    lines = scene.describe().splitlines()
    header = next(line for line in lines if "element" in line and "parameters" in line)
    gravity = next(line for line in lines if "UniformGravity" in line)
    gradient = next(line for line in lines if "GravityGradient" in line)
    columns = header.index("ball"), header.index("top")
    assert gravity[columns[0]] == "." and gravity[columns[1]] == "f"
    assert gradient[columns[0]] == "." and gradient[columns[1]:].startswith("f+tau")  # a particle has no extent


def test_simulate_command_runs_a_scene_file(tmp_path, capsys):
    from rigiddyn.__main__ import main
    from rigiddyn.trajectory import read_columns

    out = tmp_path / "out"
    assert main(["simulate", "spring_chain", "--steps", "20", "--out", str(out), "--no-progress"]) == 0
    scene, initial, run = load_scene("spring_chain")
    expected = rigiddyn.simulate(scene, initial, dt=run.dt, steps=20, method=run.method, record_every=run.record_every)
    for suffix in ("csv", "npz"):
        table = read_columns(out / f"trajectory.{suffix}")
        # the same run, written by repr (CSV) or as doubles (npz): bit for bit
        np.testing.assert_array_equal(table["m3:p_W_x [m]"], expected.p_W[:, 2, 0])
        np.testing.assert_array_equal(table["work[2] SpringDamper [J]"], expected.work[:, 2])
        assert list(table)[:2] == ["t [s]", "m1:p_W_x [m]"]
    record = __import__("json").loads((out / "run.json").read_text())
    assert record["scene"] == "spring-mass-damper chain" and record["steps"] == 20 and record["dt [s]"] == 0.001
    assert (out / "trajectory.png").is_file() or "no plot: matplotlib is not installed" in capsys.readouterr().err


def test_simulate_command_options_override_the_scene_run(tmp_path):
    from rigiddyn.__main__ import main

    path = tmp_path / "s.toml"
    path.write_text('[[body]]\nname = "p"\nkind = "particle"\nmass = 1\nv_W = [1, 0, 0]\n')
    out = tmp_path / "out"
    assert main(["simulate", str(path), "--method", "splitting_dlm", "--dt", "0.5", "--duration", "2", "--out", str(out),
                 "--no-plot", "--no-progress"]) == 0
    record = __import__("json").loads((out / "run.json").read_text())
    assert record["method"] == "splitting_dlm" and record["steps"] == 4 and record["t_end [s]"] == 2.0


@pytest.mark.parametrize("argv,message", [
    (["--steps", "3"], "--dt: expected a time step [s] > 0 (or dt in the scene's [run]), got nothing"),
    (["--dt", "0.1"], "--duration: expected a time span [s] (or --steps, or duration in the scene's [run])"),
    (["--dt", "0.1", "--steps", "3", "--method", "rk5"], "--method: expected one of"),
    (["--dt", "0.1", "--steps", "3", "--animate"], "--animate: expected a problem file"),
])
def test_simulate_command_bad_scene_arguments(tmp_path, capsys, argv, message):
    from rigiddyn.__main__ import main

    path = tmp_path / "s.toml"
    path.write_text('[[body]]\nkind = "particle"\nmass = 1\n')
    assert main(["simulate", str(path), "--out", str(tmp_path / "out"), "--no-progress", *argv]) == 2
    assert message in capsys.readouterr().err


def test_simulate_command_names_a_bad_scene_file(tmp_path, capsys):
    from rigiddyn.__main__ import main

    path = tmp_path / "s.toml"
    path.write_text('[[body]]\nkind = "particle"\nmass = "1 m"\n')
    assert main(["simulate", str(path), "--dt", "0.1", "--steps", "3", "--out", str(tmp_path / "o")]) == 2
    assert "PROBLEM: body[0].mass: expected kg, got '1 m' ([length])" in capsys.readouterr().err


# ---------------------------------------------------------------- the shipped scenes are what their headers say

GM_EARTH = 398600.4418e9  # [m^3/s^2]


def test_kepler_file_starts_on_its_documented_orbit():
    scene, initial, _ = load_scene("kepler")
    p, v, m = np.asarray(initial[0].p_W), np.asarray(initial[0].v_W), scene.bodies[0].mass
    a, e = 7.0e6, 0.1
    # energy -m GM/(2a) and eccentricity vector (e, 0, 0) from the 16-digit initial state: each term is
    # within a few roundings (<= 1e-15 relative), and v^2/2 - GM/r cancels by a factor
    # |v^2/2| / |E/m| ~ 1.2 (perigee), so 1e-14 relative bounds both
    energy = m * (v @ v / 2 - GM_EARTH / np.linalg.norm(p))
    assert energy == pytest.approx(-m * GM_EARTH / (2 * a), rel=1e-14)
    assert energy == pytest.approx(-2.8471460128571e10, rel=1e-13)  # the header's 14 digits
    ecc = ((v @ v - GM_EARTH / np.linalg.norm(p)) * p - (p @ v) * v) / GM_EARTH
    np.testing.assert_allclose(ecc, [e, 0, 0], rtol=0, atol=1e-14)


def test_gravity_gradient_file_starts_in_lvlh_pitched_by_two_degrees():
    scene, initial, _ = load_scene("gravity_gradient")
    s = initial[0]
    r = 7.0e6
    n = math.sqrt(GM_EARTH / r**3)
    # circular speed and orbit rate written to 16 digits: a few roundings, 1e-15 relative
    assert np.linalg.norm(s.v_W) == pytest.approx(math.sqrt(GM_EARTH / r), rel=1e-15)
    np.testing.assert_allclose(s.w_B, [0, -n, 0], rtol=1e-15, atol=0)
    half = math.radians(2) / 2  # 2 deg about the pitch axis y_B from q_WB = identity (LVLH at t = 0)
    np.testing.assert_allclose(s.q_WB, [0, math.sin(half), 0, math.cos(half)], rtol=0, atol=1e-16)
    np.testing.assert_array_equal(s.p_W, [0, 0, -r])


def test_gravity_gradient_pitch_libration_frequency():
    scene, initial, run = load_scene("gravity_gradient")
    result = rigiddyn.simulate(scene, initial, dt=run.dt, steps=run.steps, method=run.method)
    r_W, v_W, q = result.p_W[:, 0], result.v_W[:, 0], result.q_WB[:, 0]
    pitch = np.empty(len(result.t))
    for k in range(len(result.t)):
        z = -r_W[k] / np.linalg.norm(r_W[k])  # LVLH: z nadir, y = z x v (minus the orbit normal), x = y x z
        y = np.cross(z, v_W[k])
        y /= np.linalg.norm(y)
        R_LB = np.column_stack([np.cross(y, z), y, z]).T @ rigiddyn.quat_to_matrix(q[k])
        pitch[k] = math.atan2(R_LB[0, 2], R_LB[2, 2])
    t = result.t
    crossings = [t[k] - pitch[k] * (t[k + 1] - t[k]) / (pitch[k + 1] - pitch[k])
                 for k in range(len(t) - 1) if pitch[k] * pitch[k + 1] < 0]
    period = 2 * np.mean(np.diff(crossings))
    n = math.sqrt(GM_EARTH / 7.0e6**3)
    omega_p = n * math.sqrt(3 * (300 - 100) / 400)
    # linear theory vs the full motion: the pendulum in 2 theta lengthens the period by (2 theta0)^2/16 =
    # 3.0e-4 for theta0 = 2 deg; rk4's phase error at n dt = 5.4e-3 is O((omega dt)^4) < 1e-9; a zero
    # crossing interpolated linearly over 50 s errs by O(theta''') ~ 1e-6 of the period: 0.1 % bounds all
    assert period == pytest.approx(2 * math.pi / omega_p, rel=1e-3)


def test_three_body_file_has_its_documented_invariants():
    scene, initial, run = load_scene("three_body")
    p = np.array([s.p_W for s in initial])
    v = np.array([s.v_W for s in initial])
    np.testing.assert_array_equal(v.sum(axis=0), [0, 0, 0])  # v1 = v2 = -v3/2 exactly in binary here
    energy = 0.5 * (v**2).sum() - sum(1 / np.linalg.norm(p[i] - p[j]) for i in range(3) for j in range(i + 1, 3))
    assert energy == pytest.approx(-1.287142, abs=5e-7)  # the header's 7 digits
    assert run.steps == 6000 and run.dt * 6000 == pytest.approx(6.32591398, rel=1e-15)


def test_spring_chain_against_its_closed_form():
    scene, initial, run = load_scene("spring_chain")
    result = rigiddyn.simulate(scene, initial, dt=run.dt, steps=run.steps, method=run.method,
                               record_every=run.record_every)
    m, k, c = np.array([1.0, 2.0, 0.5]), [100.0, 150.0, 80.0], [0.2, 0.2, 0.1]

    def chain(a):
        return np.array([[a[0] + a[1], -a[1], 0], [-a[1], a[1] + a[2], -a[2]], [0, -a[2], a[2]]])

    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-chain(k) / m[:, None], -chain(c) / m[:, None]]])
    lam, V = np.linalg.eig(A)
    coefficients = np.linalg.solve(V, [0, 0, 0.1, 0, 0, 0])
    exact = np.real((V[:3] @ (coefficients[:, None] * np.exp(lam[:, None] * result.t[None, :]))).T)
    # rk4's global error over T = 10 s at h = 1 ms: <= T omega_max (omega_max h)^4/120 x amplitude (0.1 m),
    # omega_max^2 = the largest eigenvalue of M^-1 K ~ 400 s^-2: 10 * 20 * (0.02)^4 / 120 * 0.1 = 2.7e-8 m
    np.testing.assert_allclose(result.p_W[:, :, 0] - [1, 2, 3], exact, rtol=0, atol=3e-8)
    np.testing.assert_array_equal(result.p_W[:, :, 1:], 0)  # the motion stays on the x axis
