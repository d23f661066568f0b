"""TOML problem files: the shipped examples, every field's validation message, primitives and meshes."""

import math
import re
import textwrap
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn.problem import PRIMITIVES, Problem, example_problems, load_problem, parse_problem

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

BASE = """
name = "test"
horizon = 1.0
[body]
mass = 2.0
inertia = [1.0, 2.0, 2.5]
[initial]
w_B = [0.1, 1.0, 0.0]
"""


def parse(text):
    return parse_problem(tomllib.loads(textwrap.dedent(text)))


def test_examples_load_and_classify():
    assert set(example_problems()) >= {"t_handle", "fast_top", "satellite_torque", "projectile"}
    t_handle = load_problem("t_handle")
    assert t_handle.has_exact_solution and t_handle.torque_free
    # T-handle spins about the intermediate axis: the Dzhanibekov case
    moments = np.diag(t_handle.inertia_com)
    assert np.argmax(np.abs(t_handle.w_B)) == 1 and moments[0] < moments[1] < moments[2]
    assert not load_problem("satellite_torque").torque_free
    projectile = load_problem("projectile")
    np.testing.assert_array_equal(projectile.gravity, [0.0, 0.0, -9.81])
    assert projectile.has_exact_solution
    for name in example_problems():
        p = load_problem(name)
        assert isinstance(p.body(), rigiddyn.RigidBody) and p.horizon > 0 and p.tradeoff


def test_direct_inertia_matrix_and_principal_moments_agree():
    a = parse(BASE)
    b = parse(BASE.replace("inertia = [1.0, 2.0, 2.5]", "inertia = [[1.0, 0, 0], [0, 2.0, 0], [0, 0, 2.5]]"))
    np.testing.assert_array_equal(a.inertia_com, b.inertia_com)
    assert a.mass == 2.0


def test_primitive_matches_the_core_constructor():
    p = parse("""
        horizon = 1.0
        [body.primitive]
        shape = "solid_box"
        size = [1.0, 2.0, 3.0]
        density = 10.0
    """)
    box = rigiddyn.solid_box([1.0, 2.0, 3.0], density=10.0)
    eps = np.finfo(float).eps
    # density x volume, products of small integers: exact in binary, <= 2 roundings in any order
    assert p.mass == pytest.approx(60.0, rel=2 * eps, abs=0)
    np.testing.assert_array_equal(p.inertia_com, box.inertia_com)  # the same constructor on the same doubles
    # closed form I_xx = m (b^2 + c^2) / 12: <= 4 roundings on each side
    assert p.inertia_com[0, 0] == pytest.approx(60.0 * (4 + 9) / 12, rel=8 * eps, abs=0)


def test_mesh_file_matches_the_box(tmp_path):
    pytest.importorskip("trimesh")
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 2) for z in (0, 3)], float)
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    lines = [f"v {x} {y} {z}" for x, y, z in corners] + [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    (tmp_path / "box.obj").write_text("\n".join(lines) + "\n")
    (tmp_path / "p.toml").write_text('horizon = 1.0\n[body.mesh]\npath = "box.obj"\nmass = 6.0\n')
    p = load_problem(tmp_path / "p.toml")
    # 12 faces of a mesh against the closed form: a few dozen roundings of numbers <= 7 kg m^2
    np.testing.assert_allclose(p.inertia_com, rigiddyn.solid_box([1.0, 2.0, 3.0], mass=6.0).inertia_com,
                               rtol=1e-12, atol=1e-12)


def test_scalar_first_quaternion_and_loads():
    p = parse(BASE + """
        scalar_first = true
        q_WB = [0.0, 1.0, 0.0, 0.0]
        [[loads]]
        torque = [0.0, 0.0, 1.0]
        frame = "body"
        t_end = 0.5
        [[loads]]
        force = [1.0, 0.0, 0.0]
    """)
    np.testing.assert_array_equal(p.q_WB, [1.0, 0.0, 0.0, 0.0])
    assert len(p.loads) == 2 and p.loads[0].frame == "body" and p.loads[0].t_end == 0.5
    assert p.loads[1].t_start == -math.inf and p.loads[1].frame == "world"
    assert not p.torque_free and p.translation_closed_form
    assert all(isinstance(load, rigiddyn.AppliedLoad) for load in p.loads)


@pytest.mark.parametrize(
    "old, new, field",
    [
        ("horizon = 1.0", "horizon = -1.0", "horizon"),
        ("horizon = 1.0", "horizon = 'long'", "horizon"),
        ("horizon = 1.0", "", "horizon"),
        ("mass = 2.0", "mass = 0.0", "body.mass"),
        ("mass = 2.0", "", "body.mass"),
        ("inertia = [1.0, 2.0, 2.5]", "inertia = [1.0, 2.0]", "body.inertia"),
        ("inertia = [1.0, 2.0, 2.5]", "inertia = [1.0, 2.0, 5.0]", "body.inertia"),  # triangle inequality
        ("inertia = [1.0, 2.0, 2.5]", "inertia = [1.0, 2.0, nan]", r"body.inertia\[2\]"),
        ("inertia = [1.0, 2.0, 2.5]", "", "body.inertia"),
        ("w_B = [0.1, 1.0, 0.0]", "w_B = [0.1, 1.0]", "initial.w_B"),
        ("w_B = [0.1, 1.0, 0.0]", "q_WB = [0.0, 0.0, 0.0, 2.0]", "initial.q_WB"),
        ("w_B = [0.1, 1.0, 0.0]", "omega = [1, 2, 3]", "initial.omega"),
        ("name = \"test\"", "name = \"test\"\ngravity = [0, 0]", "gravity"),
        ("name = \"test\"", "name = \"test\"\ncolour = 1", "problem.colour"),
        ("name = \"test\"", "name = 3", "name"),
    ],
)
def test_validation_names_the_field(old, new, field):
    with pytest.raises(ValueError, match=rf"^{field}: expected "):
        parse(BASE.replace(old, new))


@pytest.mark.parametrize(
    "extra, field",
    [
        ("[[loads]]\nframe = 'space'", r"loads\[0\].frame"),
        ("[[loads]]\nforce = [1, 2]", r"loads\[0\].force"),
        ("[[loads]]\nt_start = 2.0\nt_end = 1.0", r"loads\[0\].t_end"),
        ("[[loads]]\nspin = 1", r"loads\[0\].spin"),
        ("[tradeoff]\ndts = []", "tradeoff.dts"),
        ("[tradeoff]\ndts = [0.1, -0.1]", r"tradeoff.dts\[1\]"),
        ("[tradeoff]\nmethods = ['rk5']", r"tradeoff.methods\[0\]"),
        ("[tradeoff]\ntolerance = 0", "tradeoff.tolerance"),
        ("[tradeoff]\nbudget = 0", "tradeoff.budget"),
    ],
)
def test_validation_of_loads_and_tradeoff(extra, field):
    with pytest.raises(ValueError, match=rf"^{field}: expected "):
        parse(BASE + extra)


@pytest.mark.parametrize(
    "table, field",
    [
        ("shape = 'blob'\nmass = 1.0", "body.primitive.shape"),
        ("shape = 'solid_box'\nmass = 1.0", "body.primitive.size"),
        ("shape = 'solid_sphere'\nradius = 1.0", "body.primitive"),  # neither mass nor density
        ("shape = 'solid_sphere'\nradius = 1.0\nmass = 1.0\ndensity = 2.0", "body.primitive"),
        ("shape = 'solid_sphere'\nradius = -1.0\nmass = 1.0", "body.primitive.radius"),
        ("shape = 'solid_sphere'\nradius = 1.0\nmass = 1.0\nheight = 2.0", "body.primitive.height"),
        ("shape = 'thin_rod'\nlength = 1.0\nmass = 1.0", "body.inertia"),  # one moment is zero
    ],
)
def test_primitive_validation(table, field):
    with pytest.raises(ValueError, match=rf"^{field}: "):
        parse("horizon = 1.0\n[body.primitive]\n" + table)


def test_mesh_validation(tmp_path):
    with pytest.raises(ValueError, match=r"^body.mesh.path: expected an existing mesh file"):
        parse_problem({"horizon": 1.0, "body": {"mesh": {"path": "missing.stl", "mass": 1.0}}}, base=tmp_path)
    with pytest.raises(ValueError, match=r"^body.mass: expected no mass outside body.mesh"):
        parse_problem({"horizon": 1.0, "body": {"mass": 1.0, "mesh": {"path": "x.stl", "mass": 1.0}}})


def test_unknown_example_and_bad_toml(tmp_path):
    with pytest.raises(ValueError, match=r"^path_or_name: expected .*t_handle"):
        load_problem("no_such_example")
    with pytest.raises(TypeError, match=r"^path_or_name: expected .*, got int 5"):
        load_problem(5)
    bad = tmp_path / "bad.toml"
    bad.write_text("horizon = = 1")
    with pytest.raises(ValueError, match="expected valid TOML"):
        load_problem(bad)


def test_every_primitive_has_its_core_constructor():
    for shape in PRIMITIVES:
        assert callable(getattr(rigiddyn, shape)), shape


def test_problem_simulate_warns_beyond_the_stability_limit():
    p = load_problem("fast_top")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = p.simulate("explicit_euler", 0.004)
    assert any(issubclass(w.category, rigiddyn.StabilityWarning)
               and "explicit_euler at dt = 0.004" in str(w.message) for w in caught)
    # the spurious growth (x1.5 per step) is real: the wobble grows by ~10^40 over the run; the
    # result is either that huge finite state or, past overflow, a run stopped with a warning
    w_B = r.body(0).w_B
    w_perp = np.linalg.norm(w_B[:, :2], axis=1)
    if r.diverged:
        assert any(issubclass(w.category, RuntimeWarning) and "non-finite" in str(w.message) for w in caught)
    else:
        assert np.all(np.isfinite(w_B)) and w_perp[-1] > 1e30 * w_perp[0]
    r = p.simulate("rk4", 1e-4, steps=100)  # within the limit: no warning (warnings are errors here)
    assert np.all(np.isfinite(r.q_WB))


def test_hairer_body_needs_the_explicit_opt_out():
    text = BASE.replace("inertia = [1.0, 2.0, 2.5]", "inertia = [2.0, 1.0, 0.6666666666666666]")
    with pytest.raises(ValueError, match="^body.inertia: "):
        parse(text)
    p = parse(text.replace("[initial]", "inertia_check = 'allow_unrealizable'\n[initial]"))
    assert p.inertia_check == rigiddyn.InertiaCheck.allow_unrealizable and p.body().mass == 2.0
    with pytest.raises(ValueError, match="^body.inertia_check: expected 'physical' or 'allow_unrealizable', got 'off'"):
        parse(text.replace("[initial]", "inertia_check = 'off'\n[initial]"))


@pytest.mark.parametrize("old", ["true", "false"])
def test_renamed_triangle_inequality_key_points_to_inertia_check(old):
    # one way to say it: the key of earlier versions is refused with the key that replaces it
    with pytest.raises(ValueError, match=r'^body.require_triangle_inequality: expected inertia_check = '
                                         r'"physical" \| "allow_unrealizable" in its place '
                                         r'.*false is "allow_unrealizable"'):
        parse(BASE.replace("[initial]", f"require_triangle_inequality = {old}\n[initial]"))


def test_error_message_names_expected_value():
    with pytest.raises(ValueError) as e:
        parse(BASE.replace("mass = 2.0", "mass = -3"))
    assert re.search(r"body.mass: expected kg > 0, got -3", str(e.value))


def test_primitive_shape_of_the_wrong_type():
    # a TOML array where a string belongs (was "TypeError: unhashable type")
    with pytest.raises(ValueError, match=r"^body.primitive.shape: expected one of solid_sphere.*got \['solid_box'\]"):
        parse_problem({"horizon": 1.0, "body": {"primitive": {"shape": ["solid_box"], "size": [1, 2, 3], "mass": 1.0}}})


@pytest.mark.parametrize("field, value, error", [
    ("name", 5, TypeError), ("mass", -1.0, ValueError), ("mass", "1", TypeError), ("horizon", 0.0, ValueError),
    ("inertia_com", np.diag([1.0, 1.0, 5.0]), ValueError), ("inertia_com", np.eye(2), ValueError),
    ("w_B", [np.nan, 0, 0], ValueError), ("q_WB", [0, 0, 0, 2.0], ValueError), ("loads", [1, 2], TypeError),
    ("gravity", "down", TypeError), ("inertia_check", True, TypeError), ("inertia_check", "physical", TypeError),
    ("tradeoff", [], TypeError),
])
def test_problem_constructor_checks_every_field(field, value, error):
    # the dataclass is public: built directly it is checked as a problem file is
    good = dict(name="p", mass=1.0, inertia_com=np.diag([1.0, 2.0, 2.5]), horizon=1.0)
    with pytest.raises(error, match=rf"^{field}(\.\w+|\[0\])?: expected"):
        Problem(**{**good, field: value})
    problem = Problem(**good, w_B=[0, 1, 0])
    assert problem.w_B.dtype == np.float64 and problem.w_B.shape == (3,)


FULL = {  # every field a problem file may hold (one [body] source at a time)
    "name": "full", "description": "every field", "horizon": 1.0, "gravity": [0.0, 0.0, -9.81],
    "body": {"mass": 2.0, "inertia": [1.0, 2.0, 2.5], "inertia_check": "physical"},
    "initial": {"p_W": [0.0, 0, 0], "q_WB": [0.0, 0, 0, 1], "v_W": [0.0, 0, 0], "w_B": [0.1, 1, 0],
                "scalar_first": False},
    "loads": [{"force": [0.0, 0, 1], "torque": [0.0, 0, 1e-3], "frame": "body", "t_start": 0.0, "t_end": 0.5}],
    "tradeoff": {"methods": ["rk4"], "dts": [0.01], "tolerance": 1e-6, "measure": "final_attitude_error"},
}
PRIMITIVE_BODY = {"primitive": {"shape": "solid_box", "size": [1.0, 2.0, 3.0], "mass": 1.0}}
# TOML values of every kind but the right one: an array where a string belongs (the reported
# `shape = ["solid_box"]`), a table, a string, a boolean, an array of tables
WRONG_TOML = {"array of str": ["solid_box"], "table": {"a": 1}, "string": "text", "bool": True,
              "array of tables": [{"a": 1}]}


def _leaves(table, prefix=()):
    for key, value in table.items():
        if isinstance(value, dict):
            yield from _leaves(value, (*prefix, key))
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            for i, item in enumerate(value):
                yield from _leaves(item, (*prefix, key, i))
        else:
            yield (*prefix, key)


def _replaced(data, path, value):
    import copy

    data = copy.deepcopy(data)
    target = data
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    return data


def _field_name(path):
    name = ""
    for key in path:
        name += f"[{key}]" if isinstance(key, int) else (f".{key}" if name else key)
    return name


# the other forms of the attitude and an angular rate with a unit
INITIAL_FORMS = [{"euler": {"seq": "ZYX", "angles": [10, 0, 0], "degrees": True},
                  "w_B": {"value": [0, 0, 60], "unit": "rpm"}},
                 {"rotvec": {"value": [0, 0, 10], "degrees": True}},
                 {"axis_angle": {"axis": [0, 0, 1], "angle": 10, "degrees": True}}]
TOML_CASES = [(data, path, kind) for data in (FULL, {**FULL, "body": PRIMITIVE_BODY},
                                              *({**FULL, "initial": initial} for initial in INITIAL_FORMS))
              for path in _leaves(data) for kind in WRONG_TOML]


@pytest.mark.parametrize("data, path, kind", TOML_CASES,
                         ids=[f"{_field_name(p)}-{k}" for _, p, k in TOML_CASES])
def test_every_toml_field_of_the_wrong_type_is_named(data, path, kind):
    # a value of the wrong TOML type is a ValueError "<field>: expected ..." naming the
    # field (never "TypeError: unhashable type" or another Python error from inside the parser)
    assert parse_problem(data).name == data["name"]  # the file is valid before the change
    value = WRONG_TOML[kind]
    try:
        parse_problem(_replaced(data, path, value))
    except ValueError as e:
        field = re.escape(_field_name(path))
        # a table {a = 1} where a table belongs (initial.w_B = {value, unit}): its unknown key is named
        sub_key = r"|\.a" if kind == "table" else ""
        assert re.match(rf"^{field}(\[\d+\]{sub_key})?: expected ", str(e)), str(e)
        return
    # accepted: only where the value is a valid one (free text, the switches)
    valid = {(("name",), "string"), (("description",), "string"), (("gravity",), "bool"),
             (("initial", "scalar_first"), "bool"),
             *((("initial", form, "degrees"), "bool") for form in ("euler", "rotvec", "axis_angle"))}
    assert (path, kind) in valid, f"{_field_name(path)} = {value!r} was accepted"


def test_loads_are_the_cores_applied_loads_read_as_a_scene_files():
    # one load class: a [[loads]] table reads into the AppliedLoad that a scene's [[force.loads]] table gives
    table = 'force = ["1 kN", 0, 0]\ntorque = [0, 0, 0.5]\nframe = "body"\nt_start = "1 min"\nt_end = 90.0\n'
    p = parse(BASE + "[[loads]]\n" + table)
    scene, _, _ = rigiddyn.load_scene('[[body]]\nkind = "rigid"\nmass = 1\ninertia = [1, 2, 2.5]\n[[force]]\n'
                                      'type = "scheduled_loads"\nbody = "body0"\n[[force.loads]]\n' + table)
    assert isinstance(p.loads[0], rigiddyn.AppliedLoad) and p.loads == tuple(scene.elements[0].loads)
    with pytest.raises(TypeError, match=r"^loads\[0\]: expected an AppliedLoad, got tuple"):
        Problem(name="p", mass=1.0, inertia_com=np.diag([1.0, 2.0, 2.5]), horizon=1.0, loads=[((1, 0, 0), (0, 0, 0))])
