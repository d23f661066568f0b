"""Primitives and meshes in a scene file's [[body]]: the body forms of a problem file's [body], read by the same code."""

import textwrap

import numpy as np
import pytest
import rigiddyn
from rigiddyn.problem import load_problem, parse_problem

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib


def scene_body(text, kind="rigid", base=None):
    """The first body of a scene whose [[body]] is of `kind` with the lines `text` (sub-tables included)."""
    toml = f'[[body]]\nkind = "{kind}"\n' + textwrap.dedent(text)
    if kind == "pivoted":
        toml = toml.replace(f'kind = "{kind}"\n', f'kind = "{kind}"\np_OC_B = [0, 0, -0.5]\n')
    if kind == "gyrostat":
        toml += "[[body.wheels]]\naxis_B = [0, 0, 1]\ninertia = 1e-5\n"
    if base is None:
        return rigiddyn.load_scene(toml).scene.bodies[0]
    (base / "scene.toml").write_text(toml)
    return rigiddyn.load_scene(base / "scene.toml").scene.bodies[0]


def problem_body(text):
    return parse_problem(tomllib.loads("horizon = 1.0\n[body]\n" + textwrap.dedent(text))).body()


def rigid_of(body):
    """The RigidBody of a rigid, pivoted or gyrostat body."""
    return body if isinstance(body, rigiddyn.RigidBody) else body.body


PRIMITIVE_BODIES = [
    """
    [body.primitive]
    shape = "solid_box"
    size = [0.1, "20 cm", 0.3]
    density = "2.7 g/cm^3"
    """,
    """
    [body.primitive]
    shape = "hollow_cylinder"
    outer_radius = "5 cm"
    inner_radius = 0.04
    height = 0.2
    mass = "500 g"
    """,
    """
    [body.primitive]
    shape = "solid_ellipsoid"
    semi_axes = {value = [1, 2, 3], unit = "dm"}
    mass = 2.0
    """,
]


@pytest.mark.parametrize("text", PRIMITIVE_BODIES)
@pytest.mark.parametrize("kind", ["rigid", "pivoted", "gyrostat"])
def test_a_primitive_gives_the_same_body_in_both_files(text, kind):
    body, reference = rigid_of(scene_body(text, kind)), problem_body(text)
    # the same reader and the same core constructor on the same doubles: equal to the bit
    assert body.mass == reference.mass
    np.testing.assert_array_equal(body.inertia_com, reference.inertia_com)


def test_a_primitive_is_the_core_constructor():
    body = scene_body(PRIMITIVE_BODIES[0])
    box = rigiddyn.solid_box([0.1, 0.2, 0.3], density=2700.0)
    # each length and the density converted by one factor (2 roundings, 2 eps relative); the mass is a
    # density times 3 lengths, an inertia that mass times 2 lengths: <= 6 such factors
    rtol = 6 * 2 * np.finfo(float).eps
    assert body.mass == pytest.approx(box.mass, rel=rtol, abs=0)
    np.testing.assert_allclose(body.inertia_com, box.inertia_com, rtol=rtol, atol=0)


def test_a_mesh_gives_the_same_body_in_both_files(tmp_path):
    pytest.importorskip("trimesh")
    corners = np.array([[x, y, z] for x in (0, 1) for y in (0, 2) for z in (0, 3)], float)
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    lines = [f"v {x} {y} {z}" for x, y, z in corners] + [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    (tmp_path / "box.obj").write_text("\n".join(lines) + "\n")
    mesh = '[body.mesh]\npath = "box.obj"\nmass = "6 kg"\n'
    (tmp_path / "p.toml").write_text("horizon = 1.0\n" + mesh)
    body, reference = scene_body(mesh, base=tmp_path), load_problem(tmp_path / "p.toml").body()
    # the path relative to each file's folder, the same mesh read by the same code: equal to the bit
    assert body.mass == reference.mass == 6.0
    np.testing.assert_array_equal(body.inertia_com, reference.inertia_com)


@pytest.mark.parametrize("text, message", [
    ('mass = 1.0\n[body.primitive]\nshape = "solid_sphere"\nradius = 1.0\nmass = 1.0',
     "body[0].mass: expected no mass outside body[0].primitive"),
    ('inertia = [1, 2, 2.5]\n[body.primitive]\nshape = "solid_sphere"\nradius = 1.0\nmass = 1.0',
     "body[0]: expected exactly one of inertia (with mass), primitive or mesh"),
    ('[body.primitive]\nshape = "solid_sphere"\nradius = "1 s"\nmass = 1.0', "body[0].primitive.radius: expected m, got '1 s'"),
    ('[body.primitive]\nshape = "solid_sphere"\nradus = 1.0\nmass = 1.0',
     "body[0].primitive.radus: expected a key of [body.primitive]; did you mean 'radius'?"),
    ('[body.primitive]\nshape = "solid_sphere"\nradius = 1.0', "body[0].primitive: expected exactly one of mass"),
    ('[body.primitive]\nshape = "thin_rod"\nlength = 1.0\nmass = 1.0', "body[0].inertia: expected"),
    ('[body.mesh]\npath = "missing.stl"\nmass = 1.0', "body[0].mesh.path: expected an existing mesh file"),
])
def test_errors_name_the_scene_field(text, message):
    with pytest.raises(ValueError) as e:
        scene_body(text)
    assert str(e.value).startswith(message), str(e.value)


def test_bodies_without_an_attitude_take_no_primitive():
    with pytest.raises(ValueError, match=r"^body\[0\]\.primitive: expected a key of a \[\[body\]\] of kind 'particle'"):
        scene_body('mass = 1.0\n[body.primitive]\nshape = "solid_sphere"\nradius = 1.0\nmass = 1.0', kind="particle")
