"""One body's records of a run (rigiddyn.BodyRecords, SceneResult.body): each array is the body's column of the
result's, found by index (negative from the end) or by name; the views share the result's memory and are read-only;
a bad key is refused naming the valid ones; pickle and repr round trips."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import rigiddyn as rd

COLUMNS = ("p_W", "q_WB", "v_W", "w_B", "mass", "pivot_reaction_W", "angular_momentum_O_W", "mass_flow_energy")


def mixed_scene():
    """A particle, a planar body, a gyrostat with two wheels and a pivoted body, under gravity and a spring."""
    bodies = [
        rd.Particle(2.0),
        rd.PlanarBody(1.5, 0.2),
        rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]),
                    [rd.Wheel([1.0, 0.0, 0.0], 0.5), rd.Wheel([0.0, 0.0, 1.0], 0.8, motor_torque=0.1)]),
        rd.PivotedBody(rd.RigidBody(3.0, [0.4, 0.5, 0.6]), [0.0, 0.0, -0.5]),
    ]
    scene = rd.Scene(bodies, body_names=["dot", "plate", "sat", "top"],
                     elements=[rd.UniformGravity(), rd.SpringDamper(body_a=0, body_b=1, stiffness=3.0)])
    states = [rd.ParticleState(v_W=(0.1, 0.2, 0.3)), rd.PlanarBodyState(omega=0.7),
              rd.GyrostatState(w_B=[1.5, -1.0, 2.0], wheel_speeds=[30.0, -20.0]),
              rd.PivotedBodyState(w_B=[0.2, 0.0, 3.0])]
    return rd.simulate(scene, states, 0.01, steps=50, record_every=5)


@pytest.fixture(scope="module")
def result():
    return mixed_scene()


@pytest.mark.parametrize("index", range(4))
def test_each_array_is_the_bodys_column_of_the_result(result, index):
    records = result.body(index)
    assert records.name == result.body_names[index] and records.index == index
    assert np.array_equal(records.t, result.t)
    for name in COLUMNS:
        column = getattr(records, name)
        assert np.array_equal(column, getattr(result, name)[:, index]), name
        assert np.shares_memory(column, getattr(result, name)), name
        assert not column.flags.writeable, name
    wheels = [k for k, b in enumerate(result.wheel_bodies) if b == index]
    assert np.array_equal(records.wheel_speed, result.wheel_speed[:, wheels])
    assert np.array_equal(records.motor_work, result.motor_work[:, wheels])
    assert records.wheel_speed.shape == (len(result.t), 2 if records.name == "sat" else 0)
    assert records.scalar_first is result.scalar_first


def test_a_name_and_a_negative_index_find_the_same_body(result):
    for index, name in enumerate(result.body_names):
        by_name, from_end = result.body(name), result.body(index - len(result.body_names))
        assert by_name.index == from_end.index == index
        for column in COLUMNS + ("wheel_speed",):
            assert np.array_equal(getattr(by_name, column), getattr(from_end, column))


def test_a_numpy_integer_is_an_index(result):
    assert result.body(np.int64(2)).name == result.body(np.uint8(2)).name == "sat"


def test_a_one_body_run_reads_its_arrays_without_the_body_axis():
    body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    result = rd.simulate(rd.Scene([body]), [rd.RigidBodyState(w_B=(0.5, 0.1, 0.0))], 0.01, steps=20,
                         scalar_first=True)
    records = result.body(0)
    n = len(result.t)
    assert records.q_WB.shape == (n, 4) and records.p_W.shape == (n, 3) and records.mass.shape == (n,)
    assert records.scalar_first and np.array_equal(records.q_WB, result.q_WB[:, 0])


@pytest.mark.parametrize("key, error, words", [
    (4, ValueError, "an integer in [-4, 3]"),
    (-5, ValueError, "an integer in [-4, 3]"),
    ("moon", ValueError, "'dot', 'plate', 'sat', 'top'"),
    (10**30, ValueError, "got 1000000000000000000000000000000"),
    (np.int64(4), ValueError, "an integer in [-4, 3]"),
    (1.0, TypeError, "an index in [-4, 4)"),
    (np.bool_(True), TypeError, "or a name of"),
    (True, TypeError, "or a name of"),
    (None, TypeError, "or a name of"),
])
def test_a_bad_key_is_refused_naming_the_valid_ones(result, key, error, words):
    with pytest.raises(error, match=r"^key: expected") as raised:
        result.body(key)
    assert words in str(raised.value)


def test_pickle_keeps_every_array_and_repr_names_the_body(result):
    records = result.body("sat")
    back = pickle.loads(pickle.dumps(records))
    assert (back.name, back.index, back.scalar_first) == (records.name, records.index, records.scalar_first)
    for column in ("t",) + COLUMNS + ("wheel_speed", "motor_work"):
        assert np.array_equal(getattr(back, column), getattr(records, column)), column
        assert not getattr(back, column).flags.writeable, column
    assert repr(records) == f"BodyRecords(name='sat', index=2, records={len(result.t)}, t=(0.0, {float(result.t[-1])!r}))"


def test_a_pickle_of_another_shape_is_refused(result):
    state = list(result.body(0).__getstate__())
    state[3] = np.zeros((2, 3))  # p_W with 2 rows against t's
    with pytest.raises(ValueError, match="BodyRecords pickle p_W"):
        rd.BodyRecords.__new__(rd.BodyRecords).__setstate__(tuple(state))


@pytest.mark.parametrize("at, value, error, words", [
    (0, 3, TypeError, "BodyRecords pickle name"),
    (1, -1, ValueError, "BodyRecords pickle index"),
    (1, "0", TypeError, "BodyRecords pickle index"),
    (1, 10**30, ValueError, "BodyRecords pickle index"),
    (-1, 1, TypeError, "BodyRecords pickle scalar_first"),
])
def test_a_pickle_of_bad_fields_is_refused_naming_the_field(result, at, value, error, words):
    state = list(result.body(0).__getstate__())
    state[at] = value
    with pytest.raises(error, match=words):
        rd.BodyRecords.__new__(rd.BodyRecords).__setstate__(tuple(state))


@pytest.mark.parametrize("index", range(4))
def test_the_norms_are_read_off_the_records(result, index):
    """angular_momentum_norm is |angular_momentum_O_W| and quaternion_norm_error |q_WB| - 1, row by row (the same
    numpy norm: equal to the bit), as new read-only arrays."""
    records = result.body(index)
    np.testing.assert_array_equal(records.angular_momentum_norm,
                                  np.linalg.norm(records.angular_momentum_O_W, axis=1), strict=True)
    np.testing.assert_array_equal(records.quaternion_norm_error, np.linalg.norm(records.q_WB, axis=1) - 1.0,
                                  strict=True)
    assert not records.angular_momentum_norm.flags.writeable and not records.quaternion_norm_error.flags.writeable


def test_a_free_body_keeps_its_angular_momentum_norm():
    """A torque-free body in a scene: splitting_dlm keeps |H_G| and |q| to round-off (an unbiased walk of at
    most 10 eps sqrt(N) relative after N steps: 2.2e-14 at N = 100), rk4 does not keep |q| (order 4 drift)."""
    scene = rd.Scene([rd.RigidBody(2.0, [1.0, 2.0, 3.0])])
    start = [rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])]
    records = rd.simulate(scene, start, 0.05, steps=100, method="splitting_dlm").body(0)
    H0 = records.angular_momentum_norm[0]
    assert H0 == pytest.approx(np.linalg.norm(np.array([1.0, 2.0, 3.0]) * [0.1, 1.0, 0.1]), rel=1e-15)
    assert np.max(np.abs(records.angular_momentum_norm - H0)) <= 10 * 2.2e-16 * np.sqrt(100) * H0
    assert np.max(np.abs(records.quaternion_norm_error)) <= 10 * 2.2e-16 * np.sqrt(100)
