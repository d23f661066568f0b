"""Every body kind and every force element the package knows round-trips and is described by name.

The registries are the scene file's: its body kinds (``scene_file._BODY_KEYS``) and its force types
(``scene_file.FORCE_TYPES``), plus ``PythonForce``, which no file can hold. Each kind and element needs an
example below: a kind or element added to a registry without one fails here, so that the checks reach it.
For each example:

- ``repr`` evaluates (with ``rigiddyn`` as ``rd``'s names) to an equal object, and ``pickle`` round-trips it;
- a scene holding it, written by ``scene_to_toml`` and read back, is equal (``PythonForce``: refused with a
  ``ValueError`` naming it);
- ``Scene.describe`` names it in its own words: the kind's short name in the bodies table, the element's class
  name with parameters of its own (the text of a Python callable only for ``PythonForce``).
"""
from __future__ import annotations

import pickle

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import scene_file

# one example of each body kind, keyed by the scene file's kind, with a state of its kind
BODY_EXAMPLES = {
    "particle": (rd.Particle(1.5), rd.ParticleState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 1.0, 0.0])),
    "planar": (rd.PlanarBody(2.0, 0.3), rd.PlanarBodyState(p_W=[0.0, 1.0], theta=0.2, v_W=[0.1, 0.0], omega=0.5)),
    "rigid": (rd.RigidBody(2.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(p_W=[0.0, 0.0, 1.0], w_B=[0.1, 0.2, 0.3])),
    "pivoted": (rd.PivotedBody(rd.RigidBody(1.0, [0.5, 0.5, 0.2]), p_OC_B=[0.0, 0.0, 0.3]),
                rd.PivotedBodyState(w_B=[0.0, 0.0, 10.0])),
    "pivoted_planar": (rd.PivotedPlanarBody(2.0, 0.05, [0.0, -0.4]), rd.PivotedPlanarBodyState(theta=0.3, omega=0.0)),
    "gyrostat": (rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]),
                             [rd.Wheel([0.0, 0.0, 1.0], 0.05, motor_torque=0.01, t_end=60.0), rd.Wheel([1.0, 0.0, 0.0], 0.05)]),
                 rd.GyrostatState(w_B=[0.0, 0.0, 0.1], wheel_speeds=[300.0, -20.0])),
}


def _force(t, body, p_W, q_WB, v_W, w_B):
    """A force for the PythonForce example: none."""
    return np.zeros(3), np.zeros(3)


# one example of each element, keyed by its class name; bodies refer to the scene built in _scene_with
ELEMENT_EXAMPLES = {
    "UniformGravity": rd.UniformGravity(g_W=[0.0, 0.0, -9.81]),
    "PointMassGravity": rd.PointMassGravity(gm=3.986004418e14, p_W=[0.0, 0.0, -7e6], softening=1.0),
    "ZonalGravity": rd.ZonalGravity(gm=3.986004418e14, radius=6378137.0, j2=1.08262668e-3, j3=-2.53265649e-6,
                                    j4=-1.61962159e-6, p_W=[0.0, 0.0, -7e6], pole_W=[0.0, 0.1, 1.0]),
    "MutualGravity": rd.MutualGravity(G=1e-3, softening=0.05, bodies=[0, 1]),
    "GravityGradient": rd.GravityGradient(gm=3.986004418e14, p_W=[0.0, 0.0, -7e6], bodies=[1]),
    "SpringDamper": rd.SpringDamper(body_a=0, point_a_B=[0.0, 0.0, 0.0], body_b=1, point_b=[0.1, 0.0, 0.0],
                                    stiffness=5.0, rest_length=0.5, damping=0.2),
    "Drag": rd.Drag(linear=0.1, quadratic=0.01, angular_linear=0.02, angular_quadratic=0.001),
    "SolarRadiationPressure": rd.SolarRadiationPressure(sun_W=[1.0, 0.2, 0.0], sun_rate_W=[0.0, 0.0, 1.99e-7], area=4.0,
                                                        normal_B=[0.0, 0.0, 1.0], specular=0.5, diffuse=0.2,
                                                        cp_B=[0.1, 0.0, 0.0], shadow_radius=6378137.0,
                                                        shadow_p_W=[0.0, 0.0, -7e6], bodies=[1]),
    "AtmosphericDrag": rd.AtmosphericDrag(density0=3e-12, altitude0=4e5, scale_height=6e4, radius=6378137.0,
                                          p_W=[0.0, 0.0, -7e6], omega_W=[0.0, 0.0, 7.29e-5], drag_area=8.8,
                                          cp_B=[0.0, 0.0, 0.1], bodies=[1]),
    "ScheduledLoads": rd.ScheduledLoads(body=1, loads=[rd.AppliedLoad(force=[1.0, 0.0, 0.0], frame="body")]),
    "Thrust": rd.Thrust(body=0, u_rel=[0.0, 0.0, -100.0], frame="world"),
    "MagneticDipole": rd.MagneticDipole(m_B=[0.2, 0.0, 0.0], B_W=[2e-5, 0.0, -4e-5], source_moment_W=[0.0, 0.0, 1e3],
                                        source_p_W=[0.0, 0.0, -10.0], bodies=[1]),
    "ReactionWheel": rd.ReactionWheel(body=1, axis_B=[0.0, 0.0, 1.0], inertia=0.01, speed=100.0, acceleration=-20.0,
                                      t_start=0.5, t_end=2.5),
    "PythonForce": rd.PythonForce(_force),
    "RevoluteSpringDamper": rd.RevoluteSpringDamper(body=2, stiffness=3.0, rest_angle=0.2, damping=0.1),
    "PrismaticSpringDamper": rd.PrismaticSpringDamper(body=3, stiffness=40.0, rest_position=-0.1, damping=2.0),
    "RevoluteMotor": rd.RevoluteMotor(body=2, torque=-1.5, t_start=0.5, t_end=2.0),
    "PrismaticMotor": rd.PrismaticMotor(body=3, force=3.0, t_start=1.0),
    "SphericalSpringDamper": rd.SphericalSpringDamper(body=4, stiffness=2.0, rest_rotation=[0.1, -0.2, 0.3], damping=0.05),
}
JOINT_ELEMENTS = ("RevoluteSpringDamper", "PrismaticSpringDamper", "RevoluteMotor", "PrismaticMotor",
                  "SphericalSpringDamper")  # on _arm's links


def _arm() -> rd.Tree:
    """A hinge about z at W's origin, a slider along its x and a ball joint at the slider's end: the joints of the
    joint elements."""
    arm = rd.Tree()
    link = rd.SpatialInertia(1.0, [0.2, 0.0, 0.0], np.diag([0.01, 0.05, 0.05]))
    arm.add_link("hinge", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), link)
    arm.add_link("slider", 0, rd.PrismaticJoint([1.0, 0.0, 0.0]), link, rd.Transform(translation=[0.5, 0.0, 0.0]))
    arm.add_link("ball", 1, rd.SphericalJoint(), link, rd.Transform(translation=[0.4, 0.0, 0.0]))
    return arm


def _scene_with(body=None, element=None) -> rd.Scene:
    """A particle with a mass flow (body 0) and a rigid body (body 1), then _arm's links (bodies 2, 3, 4) for a joint
    element, plus `body` and `element`."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(10.0), name="rocket", mass_flow=rd.MassFlow(rate=-0.5))
    scene.add_body(rd.RigidBody(2.0, [1.0, 2.0, 3.0]), name="box")
    if type(element).__name__ in JOINT_ELEMENTS:
        scene.add_tree(_arm(), "arm")
    if body is not None:
        scene.add_body(body, name="example")
    if element is not None:
        scene.add(element)
    return scene


def _states(scene: rd.Scene, extra=None) -> list:
    states = [rd.ParticleState(v_W=[0.0, 0.0, 1.0]), rd.RigidBodyState(p_W=[0.0, 0.0, 0.5], w_B=[0.1, 0.2, 0.3])]
    if len(scene.bodies) > 2 and isinstance(scene.bodies[2], rd.TreeLink):
        ball = [0.1, -0.2, 0.3, 0.9] / np.linalg.norm([0.1, -0.2, 0.3, 0.9])
        states += _arm().joint_states([0.3, 0.05, *ball], [1.0, -0.2, 0.4, -0.1, 0.2])
    return states + ([extra] if extra is not None else [])


def test_every_registered_kind_and_element_has_an_example() -> None:
    assert set(BODY_EXAMPLES) == set(scene_file._BODY_KEYS)
    assert set(ELEMENT_EXAMPLES) == {name for name, _ in scene_file.FORCE_TYPES.values()} | {"PythonForce"}
    for name in ELEMENT_EXAMPLES:
        assert type(ELEMENT_EXAMPLES[name]).__name__ == name
        assert getattr(rd, name) is type(ELEMENT_EXAMPLES[name])


def _round_trips(value) -> None:
    names = {name: getattr(rd, name) for name in dir(rd) if not name.startswith("_")}
    names["_force"] = _force
    assert eval(repr(value), names) == value, repr(value)  # noqa: S307 (the package's own repr)
    assert pickle.loads(pickle.dumps(value)) == value


@pytest.mark.parametrize("kind", sorted(BODY_EXAMPLES))
def test_a_body_kind_round_trips(kind: str) -> None:
    body, state = BODY_EXAMPLES[kind]
    _round_trips(body)
    scene = _scene_with(body=body)
    states = _states(scene, state)
    read = scene_file.read_scene(scene_file.scene_to_toml(scene, states))
    assert read.scene == scene


@pytest.mark.parametrize("name", sorted(ELEMENT_EXAMPLES))
def test_an_element_round_trips(name: str) -> None:
    element = ELEMENT_EXAMPLES[name]
    _round_trips(element)
    scene = _scene_with(element=element)
    if name == "PythonForce":
        with pytest.raises(ValueError, match="PythonForce"):
            scene_file.scene_to_toml(scene, _states(scene))
        return
    read = scene_file.read_scene(scene_file.scene_to_toml(scene, _states(scene)))
    assert read.scene == scene


@pytest.mark.parametrize("kind", sorted(BODY_EXAMPLES))
def test_describe_names_a_body_kind(kind: str) -> None:
    body, _ = BODY_EXAMPLES[kind]
    bodies_table = _scene_with(body=body).describe().split("\nBodies\n", 1)[1].split("\n\n", 1)[0]
    row = [line for line in bodies_table.splitlines() if line.split()[1:2] == ["example"]]
    assert len(row) == 1, bodies_table
    assert row[0].split()[2] == kind, row[0]


@pytest.mark.parametrize("name", sorted(ELEMENT_EXAMPLES))
def test_describe_names_an_element(name: str) -> None:
    text = _scene_with(element=ELEMENT_EXAMPLES[name]).describe()
    rows = [line for line in text.split("Force elements", 1)[1].splitlines() if line.split()[1:2] == [name]]
    assert len(rows) == 1, text
    assert ("a Python callable" in rows[0]) == (name == "PythonForce"), rows[0]
