"""TOML problem files: the shipped examples, every field's validation message, primitives and meshes."""

import math
import re
import textwrap
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn.problem import PRIMITIVES, example_problems, load_problem, parse_problem

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
    assert p.mass == pytest.approx(60.0)
    np.testing.assert_allclose(p.inertia_com, box.inertia_com, rtol=1e-15)
    # closed form I_xx = m (b^2 + c^2) / 12
    assert p.inertia_com[0, 0] == pytest.approx(60.0 * (4 + 9) / 12)


def test_mesh_file_matches_the_box(tmp_path):
    pytest.importorskip("trimesh")
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 2) for z in (0, 3)], float)
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    lines = [f"v {x} {y} {z}" for x, y, z in corners] + [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    (tmp_path / "box.obj").write_text("\n".join(lines) + "\n")
    (tmp_path / "p.toml").write_text('horizon = 1.0\n[body.mesh]\npath = "box.obj"\nmass = 6.0\n')
    p = load_problem(tmp_path / "p.toml")
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
    assert len(p.applied_loads()) == 2


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
        ("inertia = [1.0, 2.0, 2.5]", "", "body"),
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
    with pytest.raises(ValueError, match=r"^problem: expected .*t_handle"):
        load_problem("no_such_example")
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
    w_perp = np.linalg.norm(r.w_B[:, :2], axis=1)
    if r.diverged:
        assert any(issubclass(w.category, RuntimeWarning) and "non-finite" in str(w.message) for w in caught)
    else:
        assert np.all(np.isfinite(r.w_B)) and w_perp[-1] > 1e30 * w_perp[0]
    r = p.simulate("rk4", 1e-4, steps=100)  # within the limit: no warning (warnings are errors here)
    assert np.all(np.isfinite(r.q_WB))


def test_hairer_body_needs_the_explicit_opt_out():
    text = BASE.replace("inertia = [1.0, 2.0, 2.5]", "inertia = [2.0, 1.0, 0.6666666666666666]")
    with pytest.raises(ValueError, match="^body.inertia: "):
        parse(text)
    p = parse(text.replace("[initial]", "require_triangle_inequality = false\n[initial]"))
    assert not p.require_triangle_inequality and p.body().mass == 2.0


def test_error_message_names_expected_value():
    with pytest.raises(ValueError) as e:
        parse(BASE.replace("mass = 2.0", "mass = -3"))
    assert re.search(r"body.mass: expected a finite number > 0, got -3", str(e.value))
