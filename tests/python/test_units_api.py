"""Units in the Python API: wherever a physical number enters a body, a state, a force
element, a load or a run, a pint quantity of any registry is accepted and converted to the argument's SI
unit; a plain float is SI as before. The converted float is the one the SI call passes, so every object
and every run equals the SI-float call bit for bit; a quantity of another dimension is a ValueError
"<argument>: expected <SI unit>, got <quantity>"; pint is imported only when a quantity is passed."""

import re
import subprocess
import sys

import numpy as np
import pint
import pytest

import rigiddyn as rd
import rigiddyn.units as rd_units

# A user's own registry (not rigiddyn.units.registry()): its quantities convert with its own definitions.
ureg = pint.UnitRegistry()
Q = ureg.Quantity


def with_field(cls, field, **base):
    """A factory cls(**base) with `field` then assigned (the states' setters convert like the constructor)."""
    def make(value):
        obj = cls(**base)
        setattr(obj, field, value)
        return obj
    return make


def keyword(cls, arg, **base):
    """A factory cls(**base, arg=value)."""
    return lambda value: cls(**{**base, arg: value})


VECTOR = np.array([1.5, -2.0, 0.25])
# (label, factory, argument, SI unit as written in messages, a quantity of the right dimension in another
#  unit, a quantity of a wrong dimension)
CASES = [
    ("Particle.mass", keyword(rd.Particle, "mass"), "mass", "kg", Q(3.0, "lb"), Q(3, "ft")),
    ("PlanarBody.mass", keyword(rd.PlanarBody, "mass", inertia_zz=1.0), "mass", "kg", Q(3.0, "lb"), Q(3, "ft")),
    ("PlanarBody.inertia_zz", keyword(rd.PlanarBody, "inertia_zz", mass=1.0), "inertia_zz", "kg m^2",
     Q(2.0, "lb*ft^2"), Q(2, "kg*m")),
    ("RigidBody.mass", keyword(rd.RigidBody, "mass", inertia_com=(1.0, 2.0, 2.5)), "mass", "kg", Q(2.0, "slug"),
     Q(3, "ft")),
    ("RigidBody.inertia_com principal", keyword(rd.RigidBody, "inertia_com", mass=1.0), "inertia_com", "kg m^2",
     Q(np.array([1.0, 2.0, 2.5]), "lb*ft^2"), Q(np.array([1.0, 2.0, 2.5]), "kg*m")),
    ("RigidBody.inertia_com matrix", keyword(rd.RigidBody, "inertia_com", mass=1.0), "inertia_com", "kg m^2",
     Q(np.array([[2.0, 0.1, 0.0], [0.1, 3.0, 0.2], [0.0, 0.2, 4.0]]), "g*cm^2"), Q(np.eye(3), "kg")),
    ("ParticleState.p_W", keyword(rd.ParticleState, "p_W"), "p_W", "m", Q(VECTOR, "km"), Q(VECTOR, "s")),
    ("ParticleState.v_W", keyword(rd.ParticleState, "v_W"), "v_W", "m/s", Q(VECTOR, "km/h"), Q(VECTOR, "m")),
    ("ParticleState.p_W =", with_field(rd.ParticleState, "p_W"), "p_W", "m", Q(VECTOR, "ft"), Q(VECTOR, "kg")),
    ("ParticleState.v_W =", with_field(rd.ParticleState, "v_W"), "v_W", "m/s", Q(VECTOR, "mph"), Q(VECTOR, "m")),
    ("PlanarBodyState.p_W", keyword(rd.PlanarBodyState, "p_W"), "p_W", "m", Q(VECTOR[:2], "ft"), Q(VECTOR[:2], "s")),
    ("PlanarBodyState.theta", keyword(rd.PlanarBodyState, "theta"), "theta", "rad", Q(30.0, "deg"), Q(1, "m")),
    ("PlanarBodyState.v_W", keyword(rd.PlanarBodyState, "v_W"), "v_W", "m/s", Q(VECTOR[:2], "ft/s"),
     Q(VECTOR[:2], "m")),
    ("PlanarBodyState.omega", keyword(rd.PlanarBodyState, "omega"), "omega", "rad/s", Q(1500.0, "rpm"),
     Q(1, "m/s")),
    ("PlanarBodyState.p_W =", with_field(rd.PlanarBodyState, "p_W"), "p_W", "m", Q(VECTOR[:2], "cm"),
     Q(VECTOR[:2], "s")),
    ("PlanarBodyState.theta =", with_field(rd.PlanarBodyState, "theta"), "theta", "rad", Q(0.5, "turn"),
     Q(1, "s")),
    ("PlanarBodyState.v_W =", with_field(rd.PlanarBodyState, "v_W"), "v_W", "m/s", Q(VECTOR[:2], "knot"),
     Q(VECTOR[:2], "N")),
    ("PlanarBodyState.omega =", with_field(rd.PlanarBodyState, "omega"), "omega", "rad/s", Q(90.0, "deg/s"),
     Q(1, "Hz*m")),
    ("RigidBodyState.p_W", keyword(rd.RigidBodyState, "p_W"), "p_W", "m", Q(VECTOR, "mi"), Q(VECTOR, "s")),
    ("RigidBodyState.v_W", keyword(rd.RigidBodyState, "v_W"), "v_W", "m/s", Q(VECTOR, "km/s"), Q(VECTOR, "m/s^2")),
    ("RigidBodyState.w_B", keyword(rd.RigidBodyState, "w_B"), "w_B", "rad/s", Q(VECTOR, "rpm"), Q(VECTOR, "m")),
    ("RigidBodyState.p_W =", with_field(rd.RigidBodyState, "p_W"), "p_W", "m", Q(VECTOR, "in"), Q(VECTOR, "s")),
    ("RigidBodyState.v_W =", with_field(rd.RigidBodyState, "v_W"), "v_W", "m/s", Q(VECTOR, "ft/min"),
     Q(VECTOR, "m")),
    ("RigidBodyState.w_B =", with_field(rd.RigidBodyState, "w_B"), "w_B", "rad/s", Q(VECTOR, "deg/s"),
     Q(VECTOR, "1/m")),
    ("UniformGravity.g_W", keyword(rd.UniformGravity, "g_W"), "g_W", "m/s^2", Q(np.array([0.0, 0.0, -32.174]), "ft/s^2"),
     Q(VECTOR, "m/s")),
    ("PointMassGravity.gm", keyword(rd.PointMassGravity, "gm"), "gm", "m^3/s^2", Q(398600.4418, "km^3/s^2"),
     Q(1.0, "m^3/s")),
    ("PointMassGravity.p_W", keyword(rd.PointMassGravity, "p_W", gm=1.0), "p_W", "m", Q(VECTOR, "km"), Q(VECTOR, "s")),
    ("PointMassGravity.softening", keyword(rd.PointMassGravity, "softening", gm=1.0), "softening", "m",
     Q(0.5, "km"), Q(0.5, "kg")),
    ("MutualGravity.G", keyword(rd.MutualGravity, "G"), "G", "m^3/(kg s^2)", Q(6.6743e-8, "cm^3/(g*s^2)"),
     Q(1.0, "m^3/s^2")),
    ("MutualGravity.softening", keyword(rd.MutualGravity, "softening"), "softening", "m", Q(3.0, "mm"), Q(1, "s")),
    ("GravityGradient.gm", keyword(rd.GravityGradient, "gm"), "gm", "m^3/s^2", Q(4902.8, "km^3/s^2"), Q(1, "m^2/s^2")),
    ("GravityGradient.p_W", keyword(rd.GravityGradient, "p_W", gm=1.0), "p_W", "m", Q(VECTOR, "km"), Q(VECTOR, "rad")),
    ("SpringDamper.point_a_B", keyword(rd.SpringDamper, "point_a_B", body_a=0, stiffness=1.0), "point_a_B", "m",
     Q(VECTOR, "cm"), Q(VECTOR, "s")),
    ("SpringDamper.point_b", keyword(rd.SpringDamper, "point_b", body_a=0, stiffness=1.0), "point_b", "m",
     Q(VECTOR, "in"), Q(VECTOR, "kg")),
    ("SpringDamper.stiffness", keyword(rd.SpringDamper, "stiffness", body_a=0), "stiffness", "N/m",
     Q(12.0, "lbf/in"), Q(12.0, "N")),
    ("SpringDamper.rest_length", keyword(rd.SpringDamper, "rest_length", body_a=0, stiffness=1.0), "rest_length",
     "m", Q(2.0, "ft"), Q(2.0, "s")),
    ("SpringDamper.damping", keyword(rd.SpringDamper, "damping", body_a=0, stiffness=1.0), "damping", "N s/m",
     Q(0.3, "lbf*s/ft"), Q(0.3, "N/m")),
    ("Drag.linear", keyword(rd.Drag, "linear"), "linear", "N s/m", Q(0.3, "lbf*s/ft"), Q(0.3, "N")),
    ("Drag.quadratic", keyword(rd.Drag, "quadratic"), "quadratic", "N s^2/m^2", Q(0.3, "lbf*s^2/ft^2"),
     Q(0.3, "N*s/m")),
    ("Drag.angular_linear", keyword(rd.Drag, "angular_linear"), "angular_linear", "N m s", Q(0.3, "lbf*ft*s"),
     Q(0.3, "N*s")),
    ("Drag.angular_quadratic", keyword(rd.Drag, "angular_quadratic"), "angular_quadratic", "N m s^2",
     Q(0.3, "lbf*ft*s^2"), Q(0.3, "N*m*s")),
    ("MagneticDipole.m_B", keyword(rd.MagneticDipole, "m_B"), "m_B", "A m^2", Q(VECTOR, "mA*cm^2"), Q(VECTOR, "A")),
    ("MagneticDipole.B_W", keyword(rd.MagneticDipole, "B_W", m_B=VECTOR), "B_W", "T", Q(VECTOR, "uT"),
     Q(VECTOR, "A/m")),
    ("MagneticDipole.source_moment_W", keyword(rd.MagneticDipole, "source_moment_W", m_B=VECTOR), "source_moment_W",
     "A m^2", Q(VECTOR, "kA*km^2"), Q(VECTOR, "J")),
    ("MagneticDipole.source_p_W", keyword(rd.MagneticDipole, "source_p_W", m_B=VECTOR), "source_p_W", "m",
     Q(VECTOR, "km"), Q(VECTOR, "T")),
    ("ReactionWheel.inertia", keyword(rd.ReactionWheel, "inertia", body=0, axis_B=VECTOR), "inertia", "kg m^2",
     Q(500.0, "g*cm^2"), Q(1, "kg")),
    ("ReactionWheel.speed", keyword(rd.ReactionWheel, "speed", body=0, axis_B=VECTOR, inertia=0.1), "speed", "rad/s",
     Q(3000.0, "rpm"), Q(1, "m/s")),
    ("ReactionWheel.acceleration", keyword(rd.ReactionWheel, "acceleration", body=0, axis_B=VECTOR, inertia=0.1),
     "acceleration", "rad/s^2", Q(100.0, "rpm/s"), Q(1, "rad/s")),
    ("ReactionWheel.t_start", keyword(rd.ReactionWheel, "t_start", body=0, axis_B=VECTOR, inertia=0.1), "t_start", "s",
     Q(-2.0, "min"), Q(1, "m")),
    ("ReactionWheel.t_end", keyword(rd.ReactionWheel, "t_end", body=0, axis_B=VECTOR, inertia=0.1), "t_end", "s",
     Q(3.0, "min"), Q(1, "kg")),
    ("ScheduledLoads.point_B", keyword(rd.ScheduledLoads, "point_B", body=0), "point_B", "m", Q(VECTOR, "mm"),
     Q(VECTOR, "N")),
    ("AppliedLoad.force", keyword(rd.AppliedLoad, "force"), "force", "N", Q(VECTOR, "lbf"), Q(VECTOR, "N*m")),
    ("AppliedLoad.torque", keyword(rd.AppliedLoad, "torque"), "torque", "N m", Q(VECTOR, "lbf*ft"), Q(VECTOR, "N")),
    ("AppliedLoad.t_start", keyword(rd.AppliedLoad, "t_start"), "t_start", "s", Q(250.0, "ms"), Q(1, "m")),
    ("AppliedLoad.t_end", keyword(rd.AppliedLoad, "t_end"), "t_end", "s", Q(2.0, "min"), Q(1, "kg")),
]
IDS = [case[0] for case in CASES]
SI = {"kg m^2": "kg*m^2", "m^3/(kg s^2)": "m^3/(kg*s^2)", "N s/m": "N*s/m", "N s^2/m^2": "N*s^2/m^2",
      "N m s": "N*m*s", "N m s^2": "N*m*s^2", "N m": "N*m", "A m^2": "A*m^2"}


def si_unit(spoken):
    return SI.get(spoken, spoken)


@pytest.mark.parametrize("label,make,arg,unit,good,wrong", CASES, ids=IDS)
def test_a_quantity_gives_the_object_of_its_si_float(label, make, arg, unit, good, wrong):
    # The binding converts with the quantity's own registry, as m_as does: the same float, so == is exact.
    assert make(good) == make(good.m_as(si_unit(unit)))
    # A quantity already in SI gives exactly the object of the plain float.
    si_value = good.m_as(si_unit(unit))
    assert make(Q(si_value, si_unit(unit))) == make(si_value)


@pytest.mark.parametrize("label,make,arg,unit,good,wrong", CASES, ids=IDS)
def test_a_quantity_of_another_dimension_names_the_argument(label, make, arg, unit, good, wrong):
    with pytest.raises(ValueError, match=f"^{re.escape(f'{arg}: expected {unit}, got {wrong}')}$"):
        make(wrong)


def test_the_message_of_the_brief():
    with pytest.raises(ValueError, match=r"^mass: expected kg, got 3 foot$"):
        rd.RigidBody(mass=3 * ureg.ft, inertia_com=(1.0, 1.0, 1.0))


def test_a_vector_may_be_a_list_of_quantities_each_with_its_unit():
    s = rd.RigidBodyState(p_W=[Q(1.0, "km"), 2.0, Q(3.0, "ft")], w_B=(0.0, 0.0, Q(1500.0, "rpm")))
    assert s == rd.RigidBodyState(p_W=[1000.0, 2.0, Q(3.0, "ft").m_as("m")], w_B=(0.0, 0.0, Q(1500.0, "rpm").m_as("rad/s")))
    # an entry of another dimension is named by its index
    with pytest.raises(ValueError, match=r"^p_W\[1\]: expected m, got 2 second$"):
        rd.ParticleState(p_W=[Q(1, "m"), Q(2, "s"), 0.0])
    # rows of a matrix of quantities
    rows = [[Q(2.0, "kg*m^2"), 0.0, 0.0], [0.0, Q(3.0, "kg*m^2"), 0.0], [0.0, 0.0, Q(4e7, "g*cm^2")]]
    assert rd.RigidBody(1.0, rows) == rd.RigidBody(1.0, np.diag([2.0, 3.0, 4.0]))


def test_any_registry_with_its_own_definitions():
    own = pint.UnitRegistry()
    own.define("smoot = 1.7018 m")
    a = rd.ParticleState(p_W=own.Quantity(np.array([1.0, 2.0, 3.0]), "smoot"))
    assert a == rd.ParticleState(p_W=own.Quantity(np.array([1.0, 2.0, 3.0]), "smoot").m_as("m"))
    # rigiddyn's own registry (the one scene files use) works alike
    from rigiddyn.units import registry
    assert rd.Particle(mass=registry().Quantity(2.0, "lb")) == rd.Particle(mass=Q(2.0, "lb").m_as("kg"))


def run_arrays(result):
    return [np.asarray(getattr(result, name)) for name in ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy")]


def assert_same_run(a, b):
    for x, y in zip(run_arrays(a), run_arrays(b)):
        np.testing.assert_array_equal(x, y)  # the same floats in, the same code: bitwise


BODY = rd.RigidBody(2.0, (1.0, 2.0, 2.5))
STATE = rd.RigidBodyState(w_B=(0.3, 1.0, -0.2))
LOADS = [rd.AppliedLoad(force=(1.0, 0.0, 0.0), t_start=60.002)]


def one_body_scene():
    scene = rd.Scene()
    scene.add_body(BODY)
    scene.add(rd.PointMassGravity(gm=1.0, p_W=(0.0, 0.0, -5.0)))
    return scene


def test_simulate_and_step_take_dt_and_t0_as_quantities():
    assert_same_run(rd.simulate(BODY, STATE, dt=Q(1.0, "ms"), steps=5, t0=Q(1.0, "min"), loads=LOADS),
                    rd.simulate(BODY, STATE, dt=0.001, steps=5, t0=60.0, loads=LOADS))
    assert rd.step(BODY, STATE, dt=Q(1.0, "ms"), t=Q(1.0, "min"), loads=LOADS) == \
        rd.step(BODY, STATE, dt=0.001, t=60.0, loads=LOADS)
    scene = one_body_scene()
    assert_same_run(rd.simulate(scene, [STATE], dt=Q(1.0, "ms"), steps=5, t0=Q(1.0, "min")),
                    rd.simulate(scene, [STATE], dt=0.001, steps=5, t0=60.0))
    assert rd.step(scene, [STATE], dt=Q(1.0, "ms"), t=Q(1.0, "min")) == rd.step(scene, [STATE], dt=0.001, t=60.0)


@pytest.mark.parametrize("model", ["body", "scene"])
def test_a_run_names_a_time_of_another_dimension(model):
    target, state = (BODY, STATE) if model == "body" else (one_body_scene(), [STATE])
    with pytest.raises(ValueError, match=r"^dt: expected s, got 1 meter$"):
        rd.simulate(target, state, dt=Q(1, "m"), steps=1)
    with pytest.raises(ValueError, match=r"^t0: expected s, got 1 kilogram$"):
        rd.simulate(target, state, dt=0.1, steps=1, t0=Q(1, "kg"))
    with pytest.raises(ValueError, match=r"^dt: expected s, got 1 meter$"):
        rd.step(target, state, dt=Q(1, "m"))
    with pytest.raises(ValueError, match=r"^t: expected s, got 1 meter$"):
        rd.step(target, state, dt=0.1, t=Q(1, "m"))


def test_a_scene_of_quantities_runs_as_its_si_twin():
    def scene(q):
        s = rd.Scene()
        s.add_body(rd.RigidBody(q(2.0, "kg", "lb"), q(np.array([1.0, 2.0, 2.5]), "kg*m^2", "lb*ft^2")))
        s.add_body(rd.Particle(q(1.0, "kg", "lb")))
        s.add(rd.SpringDamper(body_a=0, point_a_B=q(VECTOR, "m", "cm"), body_b=1, stiffness=q(3.0, "N/m", "lbf/ft"),
                              rest_length=q(0.5, "m", "ft"), damping=q(0.1, "N*s/m", "lbf*s/ft")))
        s.add(rd.Drag(linear=q(0.01, "N*s/m", "lbf*s/ft"), angular_linear=q(0.02, "N*m*s", "lbf*ft*s")))
        return s

    with_units = scene(lambda x, si, other: Q(x, other))
    in_si = scene(lambda x, si, other: Q(x, other).m_as(si))
    states = [rd.RigidBodyState(w_B=(0.3, 1.0, -0.2)), rd.ParticleState(p_W=(1.0, 0.0, 0.0))]
    assert_same_run(rd.simulate(with_units, states, dt=0.01, steps=20), rd.simulate(in_si, states, dt=0.01, steps=20))


def test_plain_floats_never_import_pint():
    code = ("import sys, rigiddyn as rd\n"
            "b = rd.RigidBody(2.0, (1.0, 2.0, 2.5)); s = rd.RigidBodyState((1.0, 0, 0), None, (0, 1.0, 0), (0, 0, 1.0))\n"
            "e = rd.SpringDamper(body_a=0, stiffness=1.0); l = rd.AppliedLoad(force=(1.0, 0, 0), t_end=2.0)\n"
            "rd.simulate(b, s, dt=0.01, steps=3, t0=1.0, loads=[l])\n"
            "assert 'pint' not in sys.modules, 'pint imported for plain floats'\n"
            "rd.Particle(mass=__import__('pint').UnitRegistry().Quantity(2, 'lb'))\n")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_the_body_functions_take_quantities():
    body, state = BODY, rd.RigidBodyState(v_W=(1.0, 0.0, 0.0), w_B=(0.3, 1.0, -0.2))
    force, torque, point = Q(VECTOR, "lbf"), Q(VECTOR, "lbf*ft"), Q(VECTOR, "in")
    a = rd.forward_dynamics(body, state, force=force, torque=torque, point=point, gravity=Q(VECTOR, "ft/s^2"))
    b = rd.forward_dynamics(body, state, force=force.m_as("N"), torque=torque.m_as("N*m"), point=point.m_as("m"),
                            gravity=Q(VECTOR, "ft/s^2").m_as("m/s^2"))
    assert a == b
    impulse, angular = Q(VECTOR, "lbf*s"), Q(VECTOR, "lbf*ft*s")
    assert rd.apply_impulse(body, state, impulse, angular_impulse=angular) == \
        rd.apply_impulse(body, state, impulse.m_as("N*s"), angular_impulse=angular.m_as("N*m*s"))
    assert rd.power(state, Q(VECTOR, "kN")) == rd.power(state, Q(VECTOR, "kN").m_as("N"))
    newtons = Q(VECTOR, "N")
    with pytest.raises(ValueError, match=f"^{re.escape(f'impulse: expected N s, got {newtons}')}$"):
        rd.apply_impulse(body, state, newtons)
    with pytest.raises(ValueError, match=r"^gravity: expected m/s\^2, got"):
        rd.simulate(body, state, dt=0.1, steps=1, gravity=Q(VECTOR, "m/s"))


@pytest.mark.parametrize("unit, error", [("rk4", ValueError), ("m^", ValueError), ("m^9^9^9", ValueError),
                                         (1.0, TypeError), (None, TypeError)])
def test_a_bad_target_unit_is_refused_naming_unit(unit, error):
    # the SI unit a value is converted to is itself read by the unit grammar: never pint's own exceptions
    for convert in (lambda: rd_units.quantity("1 m", "x", unit), lambda: rd_units.vector_quantity(["1 m", "2 m", "3 m"], "x", unit),
                    lambda: rd_units.to_si(rd_units.registry().Quantity(1.0, "m"), unit, "x")):
        with pytest.raises(error, match="unit: expected"):
            convert()


def test_attitude_error_refuses_what_is_no_quaternion_array():
    from rigiddyn.dispersion import attitude_error

    for q, ref in ((0.0, 0.0), (np.array(1.0), np.zeros(3)), (np.zeros(3), np.array([0.0, 0.0, 0.0, 1.0]))):
        with pytest.raises(ValueError, match=r"q_WB(_ref)?: expected quaternions of shape \(\.\.\., 4\)"):
            attitude_error(q, ref)
