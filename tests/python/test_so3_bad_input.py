"""Bad input to the rotation functions: each raises TypeError (not real numbers) or ValueError
(wrong shape, non-finite, zero or far-from-unit quaternion, non-orthonormal matrix, unknown Euler
sequence) whose message names the argument, says what was expected and what came."""

from __future__ import annotations

import numpy as np
import pytest

import rigiddyn as rd

Q = np.array([0.0, 0.0, 0.0, 1.0])
V = np.array([1.0, 2.0, 3.0])
R = np.eye(3)

# function, arguments before and after the one under test, its name, its good shape
QUATERNION_ARGS = [
    (rd.quat_to_matrix, (), (), "q"),
    (rd.quat_to_rotvec, (), (), "q"),
    (rd.quat_to_axis_angle, (), (), "q"),
    (lambda q: rd.quat_to_euler("xyz", q), (), (), "q"),
    (rd.quat_inverse, (), (), "q"),
    (rd.quat_rotate, (), (V,), "q"),
    (rd.quat_multiply, (), (Q,), "q1"),
    (rd.quat_multiply, (Q,), (), "q2"),
    (rd.quat_integrate, (), (V, 0.1), "q"),
    (rd.to_scipy, (), (), "q"),
    (rd.quat_to_mrp, (), (), "q"),
    (lambda q: rd.quat_to_davenport(R, "intrinsic", q), (), (), "q"),
    (rd.quat_rate, (), (V,), "q"),
    (rd.angular_velocity_from_quat_rate, (), (Q,), "q"),
]
VECTOR_ARGS = [
    (rd.rotvec_to_quat, (), (), "rotvec"),
    (rd.rotvec_to_matrix, (), (), "rotvec"),
    (rd.axis_angle_to_quat, (), (0.3,), "axis"),
    (lambda a: rd.euler_to_quat("ZYX", a), (), (), "angles"),
    (lambda a: rd.euler_to_matrix("zxz", a), (), (), "angles"),
    (rd.quat_rotate, (Q,), (), "v"),
    (rd.quat_integrate, (Q,), (0.1,), "w"),
    (rd.hat, (), (), "v"),
    (rd.mrp_to_quat, (), (), "mrp"),
    (lambda a: rd.davenport_to_quat(R, "e", a), (), (), "angles"),
    (rd.quat_rate, (Q,), (), "w"),
]
MATRIX_ARGS = [
    (rd.matrix_to_quat, (), (), "R"),
    (rd.matrix_to_rotvec, (), (), "R"),
    (lambda m: rd.matrix_to_euler("xzy", m), (), (), "R"),  # not a proper sequence: R = I is no gimbal lock
]
# arguments checked as plain arrays (the Davenport axes, a quaternion rate of any norm)
OTHER_ARGS = [
    (lambda a: rd.quat_to_davenport(a, "e", Q), (), (), "axes", R),
    (lambda a: rd.davenport_to_quat(a, "i", V), (), (), "axes", R),
    (rd.angular_velocity_from_quat_rate, (Q,), (), "dq_dt", Q),
]
SCALAR_ARGS = [
    (rd.rot_x, (), (), "angle"),
    (rd.rot_y, (), (), "angle"),
    (rd.rot_z, (), (), "angle"),
    (rd.axis_angle_to_quat, (V,), (), "angle"),
    (rd.quat_integrate, (Q, V), (), "dt"),
]
ALL_ARGS = (
    [case + (Q,) for case in QUATERNION_ARGS]
    + [case + (V,) for case in VECTOR_ARGS]
    + [case + (R,) for case in MATRIX_ARGS]
    + [case + (0.5,) for case in SCALAR_ARGS]
    + OTHER_ARGS
)
IDS = [f"{getattr(f, '__name__', 'f')}-{name}" for f, _, _, name, _ in ALL_ARGS]


def call(case, value):
    f, before, after, _, _ = case
    return f(*before, value, *after)


@pytest.mark.parametrize("case", ALL_ARGS, ids=IDS)
def test_good_input_is_accepted(case):
    call(case, case[4])  # the baseline: the bad-input tests below change only one argument


@pytest.mark.parametrize("case", ALL_ARGS, ids=IDS)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_raises_value_error(case, bad):
    value = np.array(case[4], dtype=float)
    value.flat[-1] = bad
    with pytest.raises(ValueError, match=rf"^{case[3]}: expected .*finite"):
        call(case, value)


@pytest.mark.parametrize("case", ALL_ARGS, ids=IDS)
@pytest.mark.parametrize("bad", ["text", ["a", "b", "c", "d"], np.array([1j, 0, 0, 1]), 1 + 2j, None, object()])
def test_wrong_dtype_raises_type_error(case, bad):
    with pytest.raises(TypeError, match=rf"^{case[3]}: expected .*real number"):
        call(case, bad)


@pytest.mark.parametrize("case", [c for c in ALL_ARGS if np.ndim(c[4]) > 0], ids=lambda c: c[3])
def test_wrong_shape_raises_value_error(case):
    good = np.asarray(case[4])
    for bad in (np.zeros(5), np.zeros((2, 2)), np.zeros((2, 3, 4, 4)), np.zeros(()), np.zeros((3, 2) + good.shape)):
        with pytest.raises(ValueError, match=rf"^{case[3]}: expected shape .*got \("):
            call(case, bad)


def test_scalar_argument_must_not_be_an_array_of_two_dims():
    with pytest.raises(ValueError, match=r"^angle: expected shape"):
        rd.rot_x(np.zeros((2, 2)))
    with pytest.raises(ValueError, match=r"^dt: expected a scalar"):
        rd.quat_integrate(Q, V, [0.1, 0.2])


@pytest.mark.parametrize("case", [c + (Q,) for c in QUATERNION_ARGS], ids=lambda c: c[3])
@pytest.mark.parametrize("bad", [[0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 2.0], [1.0, 1.0, 1.0, 1.0],
                                 [0.0, 0.0, 0.0, 1.0 + 2e-6]])
def test_zero_or_far_from_unit_quaternion_raises(case, bad):
    with pytest.raises(ValueError, match=rf"^{case[3]}: expected .*(unit|non-zero) quaternion"):
        call(case, np.array(bad))


def test_bad_item_of_a_stack_is_named_with_its_index():
    q = np.tile(Q, (5, 1))
    q[3] = [0.0, 0.0, 0.0, 3.0]
    with pytest.raises(ValueError, match=r"^q: expected a unit quaternion.*\|q\| = 3.*\(item 3\)"):
        rd.quat_to_matrix(q)


def test_nearly_unit_quaternion_is_normalised():
    np.testing.assert_array_equal(rd.quat_inverse([0.0, 0.0, 0.0, 1.0 + 5e-7]), [0.0, 0.0, 0.0, 1.0])


def test_quat_normalize_accepts_any_norm_but_zero():
    np.testing.assert_allclose(rd.quat_normalize([0.0, 0.0, 0.0, 7.0]), Q)
    with pytest.raises(ValueError, match=r"^q: expected a non-zero quaternion"):
        rd.quat_normalize([0.0, 0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"^q: expected .*finite"):
        rd.quat_normalize([np.nan, 0.0, 0.0, 1.0])


@pytest.mark.parametrize("case", [c + (R,) for c in MATRIX_ARGS], ids=lambda c: c[3])
@pytest.mark.parametrize("bad", [2 * np.eye(3), np.zeros((3, 3)), np.diag([1.0, 1.0, -1.0]),
                                 np.eye(3) + 0.1 * np.triu(np.ones((3, 3)), 1), -np.eye(3)])
def test_non_rotation_matrix_raises(case, bad):
    with pytest.raises(ValueError, match=rf"^{case[3]}: expected a rotation matrix"):
        call(case, bad)


def test_nearly_orthonormal_matrix_is_projected_as_scipy():
    """A rotation matrix rounded to 3 decimals is read as the nearest rotation, as SciPy's
    Rotation.from_matrix reads it, by every function that takes a matrix."""
    from scipy.spatial.transform import Rotation

    M = np.round(Rotation.from_euler("xyz", [0.3, -0.2, 1.1]).as_matrix(), 3)
    r = Rotation.from_matrix(M)
    q = rd.matrix_to_quat(M)
    # both sides take the same polar factor (SVD to ~10 eps) then one well-conditioned conversion
    # each: test_so3.TOL
    assert min(np.abs(q - r.as_quat()).max(), np.abs(q + r.as_quat()).max()) < 1e-12
    np.testing.assert_allclose(rd.matrix_to_rotvec(M), r.as_rotvec(), rtol=0, atol=1e-12)
    # Tait-Bryan angles away from lock (θ2 = -0.2): conditioning 1/cos(0.2) ~ 1
    np.testing.assert_allclose(rd.matrix_to_euler("xyz", M), r.as_euler("xyz"), rtol=0, atol=1e-12)


def test_zero_axis_raises():
    with pytest.raises(ValueError, match=r"^axis: expected a non-zero vector"):
        rd.axis_angle_to_quat([0.0, 0.0, 0.0], 1.0)
    with pytest.raises(ValueError, match=r"^axis: expected a non-zero vector.*\(item 1\)"):
        rd.axis_angle_to_quat([[1.0, 0.0, 0.0], [0.0, 0.0, 0.0]], 1.0)


def test_stacks_of_different_lengths_raise():
    with pytest.raises(ValueError, match=r"^v: expected 2 items \(as q\), got 3"):
        rd.quat_rotate(np.tile(Q, (2, 1)), np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"^q2: expected 2 items \(as q1\), got 4"):
        rd.quat_multiply(np.tile(Q, (2, 1)), np.tile(Q, (4, 1)))
    with pytest.raises(ValueError, match=r"^angle: expected 2 items \(as axis\), got 3"):
        rd.axis_angle_to_quat(np.ones((2, 3)), np.ones(3))


EULER_FUNCTIONS = [
    (rd.euler_to_quat, V),
    (rd.euler_to_matrix, V),
    (rd.quat_to_euler, Q),
    (rd.matrix_to_euler, R),
]


@pytest.mark.parametrize("f, x", EULER_FUNCTIONS)
@pytest.mark.parametrize("seq", ["", "xy", "xyzx", "xxy", "xyy", "xYz", "XyZ", "abc", "xyw", "x y", "zzz"])
def test_unknown_euler_sequence_raises(f, x, seq):
    with pytest.raises(ValueError, match=rf"^seq: expected one of the 12 axis sequences.*got '{seq}'"):
        f(seq, x)


@pytest.mark.parametrize("f, x", EULER_FUNCTIONS)
@pytest.mark.parametrize("seq", [None, 3, b"xyz", ["x", "y", "z"]])
def test_non_string_euler_sequence_raises_type_error(f, x, seq):
    with pytest.raises(TypeError, match=r"^seq: expected a str"):
        f(seq, x)


def test_bad_frame_raises():
    with pytest.raises(ValueError, match=r"^frame: expected 'world' or 'body', got 'inertial'"):
        rd.quat_integrate(Q, V, 0.1, frame="inertial")
    with pytest.raises(TypeError, match=r"^frame: expected 'world' or 'body'"):
        rd.quat_integrate(Q, V, 0.1, frame=1)


def test_from_scipy_rejects_non_rotations():
    with pytest.raises(TypeError, match=r"^rotation: expected a scipy.spatial.transform.Rotation, got ndarray"):
        rd.from_scipy(Q)


@pytest.mark.parametrize("f", [rd.rotvec_to_quat, rd.rotvec_to_matrix], ids=lambda f: f.__name__)
def test_rotation_vector_whose_angle_overflows_warns(f):
    # |rotvec|^2 overflows beyond 1.3e154 rad: the angle is not finite, nor is the result
    with pytest.warns(RuntimeWarning, match=rf"^{f.__name__}: expected a finite result"):
        f(np.array([[0.1, 0.0, 0.0], [1e155, 0.0, 0.0]]))
    assert np.isfinite(f(np.array([1e150, 0.0, 0.0]))).all()  # |rotvec|^2 = 1e300: no warning
