"""One way to say each thing, for the bodies, their states and the dynamics functions:
the three ways to build a RigidBody agree (as the C++ constructors and the problem files do); one
realizability check (`check=InertiaCheck...`); one gravity default (none) everywhere; angular momentum
about the world origin by default for every model; named results whose fields name their frame;
state fields assigned whole, their arrays read-only; a repr that rebuilds the object; pickling.
"""

from __future__ import annotations

import copy
import inspect
import math
import multiprocessing
import pickle

import numpy as np
import pytest

import rigiddyn as rd

HLW = [2.0, 1.0, 2.0 / 3.0]  # Hairer-Lubich-Wanner's test body: 1 + 2/3 < 2, no real body has it
MOMENTS = [1.0, 2.0, 2.5]


def rigid_state():
    q = np.array([0.1, -0.3, 0.2, 0.9])
    return rd.RigidBodyState(p_W=[1.0, -2.0, 0.5], q_WB=q / np.linalg.norm(q), v_W=[0.3, 0.1, -0.7],
                             w_B=[1.2, -0.4, 2.0])


def bodies_and_states():
    """(body, state) for the three models, each in a generic state."""
    return [
        (rd.RigidBody(1.7, MOMENTS), rigid_state()),
        (rd.PlanarBody(1.3, 0.45), rd.PlanarBodyState(p_W=[0.5, -1.5], theta=0.4, v_W=[2.0, 0.7], omega=-1.1)),
        (rd.Particle(0.9), rd.ParticleState(p_W=[1.0, 0.0, 2.0], v_W=[0.0, 3.0, -1.0])),
    ]


# --- RigidBody: three forms, one check -------------------------------------------------------------

def test_rigid_body_from_moments_matrix_and_spatial_inertia_agree():
    from_moments = rd.RigidBody(2.0, MOMENTS)
    from_matrix = rd.RigidBody(2.0, np.diag(MOMENTS))
    from_inertia = rd.RigidBody(rd.SpatialInertia(2.0, [0.3, -0.1, 0.2], np.diag(MOMENTS)))
    assert from_moments == from_matrix == from_inertia
    np.testing.assert_array_equal(from_moments.inertia_com, np.diag(MOMENTS))  # stored exactly
    assert from_moments.euler_form == "principal"


def test_problem_file_principal_moments_give_the_same_body():
    import tomllib

    from rigiddyn.problem import parse_problem  # the problem files' parser (problem.py)
    text = f"""
name = "moments"
horizon = 1.0
[body]
mass = 2.0
inertia = {MOMENTS}
"""
    assert parse_problem(tomllib.loads(text)).body() == rd.RigidBody(2.0, MOMENTS)


def test_one_realizability_check_in_every_form():
    for build in (lambda **k: rd.RigidBody(1.0, HLW, **k), lambda **k: rd.RigidBody(1.0, np.diag(HLW), **k)):
        with pytest.raises(ValueError, match="^inertia_com.*triangle"):
            build()
        assert build(check=rd.InertiaCheck.allow_unrealizable).euler_form == "principal"
    unrealizable = rd.SpatialInertia(1.0, [0, 0, 0], np.diag(HLW), rd.InertiaCheck.allow_unrealizable)
    with pytest.raises(ValueError, match="^inertia_com.*triangle"):
        rd.RigidBody(unrealizable)
    assert rd.RigidBody(unrealizable, check=rd.InertiaCheck.allow_unrealizable).euler_form == "principal"


def test_the_older_spellings_are_gone_and_messages_say_python():
    with pytest.raises(TypeError):
        rd.RigidBody(1.0, HLW, require_triangle_inequality=False)
    with pytest.raises(TypeError, match=r"^check: expected InertiaCheck\.physical or InertiaCheck\.allow_unrealizable"):
        rd.RigidBody(1.0, HLW, False)
    messages = []
    for bad in (lambda: rd.RigidBody(1.0, HLW), lambda: rd.RigidBody(1.0, HLW, True),
                lambda: rd.RigidBody(1.0, [1.0, 2.0]), lambda: rd.RigidBody(rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)),
                                                                            np.eye(3)),
                lambda: rd.RigidBody(1.0)):
        with pytest.raises((TypeError, ValueError)) as error:
            bad()
        messages.append(str(error.value))
    assert all("::" not in m for m in messages), messages
    assert "principal moments (3,) or an inertia matrix (3, 3)" in messages[2]
    assert messages[3].startswith("inertia_com: expected None next to a SpatialInertia")
    for obj in (rd.RigidBody, rd.RigidBodyState, rd.simulate, rd.step, rd.potential_energy, rd.inverse_dynamics):
        assert "::" not in (obj.__doc__ or ""), obj


# --- gravity: none unless asked ---------------------------------------------------------------------

@pytest.mark.parametrize("index", range(3))
def test_no_gravity_unless_asked(index):
    body, state = bodies_and_states()[index]
    standard = [0.0, -9.81] if isinstance(body, rd.PlanarBody) else True
    # potential energy: no field, 0 J; the standard field: -m g.p (one product and sum: 2 roundings)
    assert rd.potential_energy(body, state) == 0.0
    assert "0 J" in rd.potential_energy.__doc__
    height = state.p_W[-1] if isinstance(body, rd.PlanarBody) else state.p_W[2]
    assert rd.potential_energy(body, state, standard) == pytest.approx(body.mass * 9.81 * height, rel=1e-15)
    # forward and inverse dynamics, simulate and step: the default is the gravity=None result, exactly
    # (repr: every value as its shortest round-trip decimal, so equal texts are equal bits)
    a = rd.forward_dynamics(body, state)
    assert repr(a) == repr(rd.forward_dynamics(body, state, gravity=None))
    assert repr(rd.forward_dynamics(body, state, gravity=standard)) != repr(a)
    a_W = np.zeros(2 if isinstance(body, rd.PlanarBody) else 3)
    alpha = None if isinstance(body, rd.Particle) else (0.0 if isinstance(body, rd.PlanarBody) else np.zeros(3))
    assert repr(rd.inverse_dynamics(body, state, a_W, alpha)) == repr(rd.inverse_dynamics(body, state, a_W, alpha, None))
    assert rd.step(body, state, 0.01) == rd.step(body, state, 0.01, gravity=None)
    free, none = rd.simulate(body, state, 0.01, 5), rd.simulate(body, state, 0.01, 5, gravity=None)
    np.testing.assert_array_equal(free.v_W, none.v_W)
    for function in (rd.simulate, rd.step, rd.forward_dynamics, rd.inverse_dynamics, rd.potential_energy):
        assert "gravity: object = None" in function.__doc__.splitlines()[0], function.__name__


def test_no_gravity_keeps_a_free_particle_at_constant_velocity():
    run = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), 0.1, 10)
    np.testing.assert_array_equal(run.body(0).v_W, np.tile([1.0, 0.0, 0.0], (11, 1)))  # no force: v exactly constant


# --- angular momentum: about the world origin by default ------------------------------------------

@pytest.mark.parametrize("index", range(3))
def test_angular_momentum_defaults_to_the_world_origin(index):
    body, state = bodies_and_states()[index]
    origin = np.zeros(len(state.p_W))
    np.testing.assert_array_equal(rd.angular_momentum(body, state), rd.angular_momentum(body, state, point=origin))
    # H_O = H_G + p x m v (the notes' eq. (4.65)): about G plus the transfer term
    H_G = np.atleast_1d(rd.angular_momentum(body, state, point=state.p_W))
    p = np.append(state.p_W, 0.0) if len(state.p_W) == 2 else state.p_W
    v = np.append(state.v_W, 0.0) if len(state.v_W) == 2 else state.v_W
    transfer = np.cross(p, body.mass * v)
    want = H_G + (transfer[2:] if len(state.p_W) == 2 else transfer)
    # a sum of products of numbers <= 10: a few roundings, 1e-14
    np.testing.assert_allclose(np.atleast_1d(rd.angular_momentum(body, state)), want, rtol=0, atol=1e-14)
    if isinstance(body, rd.Particle):  # about itself a particle has none; about O, p x m v
        np.testing.assert_array_equal(H_G, [0.0, 0.0, 0.0])
        assert np.any(rd.angular_momentum(body, state) != 0.0)


# --- named results ----------------------------------------------------------------------------------

def test_inverse_dynamics_returns_a_named_wrench_that_unpacks():
    body, state = bodies_and_states()[0]
    a = rd.forward_dynamics(body, state, force=[1.0, -2.0, 0.5], torque=[0.1, 0.2, -0.3])
    assert isinstance(a, rd.BodyAcceleration)
    a_W, alpha_B = a
    np.testing.assert_array_equal(a_W, a.a_W)
    np.testing.assert_array_equal(alpha_B, a.alpha_B)
    wrench = rd.inverse_dynamics(body, state, a.a_W, a.alpha_B)
    assert isinstance(wrench, rd.ComWrench)
    f_W, tau_B = wrench
    np.testing.assert_array_equal(f_W, wrench.f_W)
    np.testing.assert_array_equal(tau_B, wrench.tau_B)
    assert len(wrench) == 2 and np.array_equal(wrench[0], f_W) and np.array_equal(wrench[-1], tau_B)  # as the tuple was
    with pytest.raises(IndexError):
        wrench[2]
    # forward then inverse: a solve with I (kappa 2.5) of terms <= 10: 1e-13
    np.testing.assert_allclose(wrench.f_W, [1.0, -2.0, 0.5], atol=1e-13)
    planar, planar_state = bodies_and_states()[1]
    pw = rd.inverse_dynamics(planar, planar_state, [1.0, 2.0], 0.5)
    assert isinstance(pw, rd.PlanarWrench) and pw.tau == 0.45 * 0.5
    f2, tau = pw
    np.testing.assert_array_equal(f2, [1.3, 2.6])
    assert isinstance(rd.forward_dynamics(planar, planar_state), rd.PlanarAcceleration)


def test_kinetic_energy_is_constructible_with_a_total():
    T = rd.KineticEnergy(translational=1.5, rotational=2.25)
    assert (T.translational, T.rotational, T.total) == (1.5, 2.25, 3.75)
    body, state = bodies_and_states()[0]
    got = rd.kinetic_energy(body, state)
    assert isinstance(got, rd.KineticEnergy) and got.total == got.translational + got.rotational


def test_names_say_torque():
    assert "tau_B" in rd.power.__doc__.splitlines()[0] and "n_B" not in rd.power.__doc__
    body, state = bodies_and_states()[0]
    assert rd.power(state, f_W=[1.0, 0, 0], tau_B=[0, 0, 1.0]) == pytest.approx(0.3 + 2.0, abs=1e-15)
    for function in (rd.power, rd.forward_dynamics, rd.inverse_dynamics, rd.apply_impulse):
        assert "couple" not in function.__doc__ and "moment n" not in function.__doc__, function.__name__
    with pytest.raises(ValueError, match="^torque: expected None for a Particle .*no torque"):
        rd.forward_dynamics(rd.Particle(1.0), rd.ParticleState(), torque=[0, 0, 1.0])


# --- state fields: assigned whole, read-only arrays -----------------------------------------------

STATE_FIELDS = [
    (rd.ParticleState, "p_W", [1.0, 2.0, 3.0]), (rd.ParticleState, "v_W", [1.0, 2.0, 3.0]),
    (rd.PlanarBodyState, "p_W", [1.0, 2.0]), (rd.PlanarBodyState, "v_W", [1.0, 2.0]),
    (rd.RigidBodyState, "p_W", [1.0, 2.0, 3.0]), (rd.RigidBodyState, "v_W", [1.0, 2.0, 3.0]),
    (rd.RigidBodyState, "w_B", [1.0, 2.0, 3.0]), (rd.RigidBodyState, "q_WB", [0.0, 0.6, 0.0, 0.8]),
]


@pytest.mark.parametrize("cls, field, value", STATE_FIELDS, ids=[f"{c.__name__}.{f}" for c, f, _ in STATE_FIELDS])
def test_state_fields_assign_whole_and_refuse_element_writes(cls, field, value):
    s = cls()
    setattr(s, field, value)
    np.testing.assert_array_equal(getattr(s, field), value)  # 0.6, 0.8: |q| = 1 to round-off, kept
    with pytest.raises(ValueError, match="read-only"):
        getattr(s, field)[0] = 5.0
    np.testing.assert_array_equal(getattr(s, field), value)
    # checked as the constructor checks: shape, finite values, type
    with pytest.raises(ValueError, match=f"^{field}: expected"):
        setattr(s, field, value[:-1])
    with pytest.raises(ValueError, match=f"^{field}"):
        setattr(s, field, [math.nan] * len(value))
    with pytest.raises(TypeError, match=f"^{field}: expected"):
        setattr(s, field, "wrong")
    np.testing.assert_array_equal(getattr(s, field), value)


def test_state_scalars_and_quaternion_checks():
    s = rd.PlanarBodyState()
    s.theta, s.omega = 0.5, -2.0
    assert (s.theta, s.omega) == (0.5, -2.0)
    with pytest.raises(ValueError, match="^omega: expected a finite number"):
        s.omega = math.inf
    r = rd.RigidBodyState()
    r.q_WB = [0.0, 0.0, 1.0 + 5e-7, 0.0]  # within 1e-6 of unit norm: normalised, as the constructor does
    np.testing.assert_array_equal(r.q_WB, rd.RigidBodyState(q_WB=[0.0, 0.0, 1.0 + 5e-7, 0.0]).q_WB)
    assert r.q_WB[2] == 1.0
    with pytest.raises(ValueError, match="^q_WB"):
        r.q_WB = [0.0, 0.0, 0.0, 2.0]
    with pytest.raises(ValueError, match="read-only"):
        r.quaternion(scalar_first=True)[0] = 1.0


def test_results_arrays_are_read_only():
    body, state = bodies_and_states()[0]
    run = rd.simulate(body, state, 0.01, 3)
    for name in ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "total_energy", "work"):
        with pytest.raises(ValueError, match="read-only"):
            getattr(run, name)[0] = 1.0
    for name in ("t", "p_W", "q_WB", "v_W", "w_B", "angular_momentum_norm", "quaternion_norm_error"):
        with pytest.raises(ValueError, match="read-only"):
            getattr(run.body(0), name)[0] = 1.0
    wrench = rd.inverse_dynamics(body, state, [0, 0, 0.0], [0, 0, 0.0])
    with pytest.raises(ValueError, match="read-only"):
        wrench.tau_B[0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        body.inertia_com[0, 0] = 1.0


# --- repr and pickle ------------------------------------------------------------------------------

def objects():
    body, state = bodies_and_states()[0]
    return [
        rd.Particle(0.9), rd.PlanarBody(1.3, 0.45), body, rd.RigidBody(1.0, np.array([[1.0, 0.1, 0.0], [0.1, 2.0, 0.0],
                                                                                       [0.0, 0.0, 2.5]])),
        rd.RigidBody(1.0, HLW, check=rd.InertiaCheck.allow_unrealizable),
        *[s for _, s in bodies_and_states()],
        rd.KineticEnergy(translational=0.1, rotational=1 / 3),
        rd.inverse_dynamics(body, state, [0.1, 0.2, 0.3], [0.3, 0.2, 0.1]),
        rd.forward_dynamics(body, state, force=[0.1, 0.2, 0.3]),
        rd.inverse_dynamics(rd.PlanarBody(1.3, 0.45), rd.PlanarBodyState(), [0.1, 0.2], 0.3),
        rd.forward_dynamics(rd.PlanarBody(1.3, 0.45), rd.PlanarBodyState(), force=[0.1, 0.2]),
        rd.AppliedLoad(force=[1.0, 0.0, 0.1], torque=[0.0, 0.2, 0.0], frame="body"),
        rd.AppliedLoad(torque=[0.0, 0.2, 0.0], t_start=0.5, t_end=1 / 3 + 1),
    ]


@pytest.mark.parametrize("obj", objects(), ids=lambda o: type(o).__name__)
def test_repr_rebuilds_the_object(obj):
    text = repr(obj)
    assert text.startswith(type(obj).__name__ + "(")
    assert eval(text, vars(rd)) == obj  # shortest round-trip decimals: bitwise the same values


def _same_bits(a, b):
    """Every field of a and b the same bits (pickle keeps them exactly)."""
    fields = [name for name, value in inspect.getmembers(type(a)) if isinstance(value, property)]
    for name in fields:
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        if x.dtype.kind == "f":
            assert x.tobytes() == y.tobytes(), name
        else:
            assert np.array_equal(x, y), name
    return True


@pytest.mark.parametrize("obj", objects(), ids=lambda o: type(o).__name__)
def test_pickle_and_deepcopy_round_trip_bitwise(obj):
    for back in (pickle.loads(pickle.dumps(obj)), copy.deepcopy(obj), copy.copy(obj)):
        assert type(back) is type(obj) and back == obj and _same_bits(back, obj)


def test_a_diverged_state_pickles_as_it_is():
    # the constructor refuses NaN; a state a diverged step returned is pickled and restored as it is
    s = rd.RigidBodyState.__new__(rd.RigidBodyState)
    s.__setstate__((np.array([math.nan, 0.0, 0.0]), np.array([0.0, 0.0, 0.0, 1.0]), np.zeros(3), np.zeros(3)))
    back = pickle.loads(pickle.dumps(s))
    assert math.isnan(back.p_W[0]) and _same_bits(back, s)


def test_simulation_result_pickles_and_reprs():
    body, state = bodies_and_states()[0]
    run = rd.simulate(body, state, 0.01, 4, loads=rd.AppliedLoad(torque=[0, 0, 1.0]))
    back = pickle.loads(pickle.dumps(run))
    _same_bits(back, run)
    assert back.t.flags.writeable is False
    assert repr(run).startswith("SceneResult(records=5, body_names=('body0',), elements=('ScheduledLoads',), "
                                "t=(0.0, 0.04")


def test_objects_cross_process_boundaries():
    objs = objects()
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        back = pool.map(copy.deepcopy, objs)  # pickled out and back
    for a, b in zip(objs, back):
        assert b == a and _same_bits(b, a)
