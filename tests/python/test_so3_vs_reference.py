"""The core's rotations (rigiddyn, C++) against the independent numpy reference (rigiddyn_ref.so3)
on hypothesis-randomised inputs, single items and stacks, to ~1e-12. Quaternions are compared up
to sign where the API does not fix it; Euler angles modulo 2π and only where they are well
conditioned (away from gimbal lock), the matrices they give everywhere."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import rigiddyn as rd
from rigiddyn_ref import so3 as ref

settings.register_profile("reference", max_examples=50, deadline=None)
settings.load_profile("reference")

# one conversion on each side: <= ~30 correctly rounded operations on numbers <= 2 pi (unit
# quaternions, rotation matrices, angles), through well-conditioned forms (Shepperd, atan2 log,
# sinc): <= 30 eps 2 pi = 4e-14 per side; TOL keeps a 10x margin over the sum of both sides
TOL = 1e-12
SEQUENCES = [s for base in ("xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
                            "xyx", "xzx", "yxy", "yzy", "zxz", "zyz") for s in (base, base.upper())]

finite = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
count = st.integers(1, 6)


@st.composite
def unit_quats(draw, n=None):
    """(4,) or (n, 4) unit quaternions; random directions, including ones near the identity and
    near a half turn (w ~ 0), where the log map is delicate."""
    shape = (4,) if n is None else (n, 4)
    q = draw(arrays(np.float64, shape, elements=finite).filter(
        lambda a: np.all(np.linalg.norm(a, axis=-1) > 0.1)))
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    mode = draw(st.sampled_from(["generic", "near_identity", "near_half_turn"]))
    eps = draw(st.floats(1e-12, 1e-4))
    if mode == "near_identity":
        q = q * np.array([eps, eps, eps, 1.0])
    elif mode == "near_half_turn":
        q = q * np.array([1.0, 1.0, 1.0, eps])
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


@st.composite
def single_or_stack(draw, strategy_of_n):
    """One item or a stack of 1..6 items from strategy_of_n(n) (n None = single)."""
    n = draw(st.one_of(st.none(), count))
    return draw(strategy_of_n(n))


def quats():
    return single_or_stack(lambda n: unit_quats(n))


def vectors(scale=1.0):
    return single_or_stack(lambda n: arrays(np.float64, (3,) if n is None else (n, 3),
                                            elements=st.floats(-scale, scale)))


@st.composite
def rotvecs(draw):
    """Rotation vectors of any length up to 2π, including tiny ones and ones of length ~π."""
    n = draw(st.one_of(st.none(), count))
    shape = (3,) if n is None else (n, 3)
    axis = draw(arrays(np.float64, shape, elements=finite).filter(
        lambda a: np.all(np.linalg.norm(a, axis=-1) > 0.1)))
    axis = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    angle = draw(st.one_of(st.floats(0.0, 2 * np.pi), st.floats(0.0, 1e-7),
                           st.floats(np.pi - 1e-7, np.pi)))
    return angle * axis


def same_rotation(q1, q2, tol=TOL):
    """q1 and q2 equal up to the sign of each item."""
    q1, q2 = np.atleast_2d(q1), np.atleast_2d(q2)
    sign = np.where(np.sum(q1 * q2, axis=-1, keepdims=True) < 0.0, -1.0, 1.0)
    np.testing.assert_allclose(q1, sign * q2, rtol=0, atol=tol)


def close(a, b, tol=TOL):
    np.testing.assert_allclose(a, b, rtol=tol, atol=tol)


# ------------------------------------------------------------------ conversions
@given(quats(), st.booleans())
def test_quat_to_matrix(q, scalar_first):
    qq = q[..., [3, 0, 1, 2]] if scalar_first else q
    close(rd.quat_to_matrix(qq, scalar_first=scalar_first), ref.quat_to_matrix(q))


@given(quats(), st.booleans())
def test_matrix_to_quat_is_canonical(q, scalar_first):
    R = ref.quat_to_matrix(q)
    got = rd.matrix_to_quat(R, scalar_first=scalar_first)
    want = ref.matrix_to_quat(R, scalar_first=scalar_first)
    assert got.shape == want.shape
    close(got, want, 1e-12)  # both canonical (w >= 0): no sign freedom


@given(rotvecs(), st.booleans())
def test_rotvec_to_quat(r, scalar_first):
    close(rd.rotvec_to_quat(r, scalar_first=scalar_first),
          ref.rotvec_to_quat(r, scalar_first=scalar_first))


@given(quats())
def test_quat_to_rotvec(q):
    # near a half turn the log is ill conditioned by the choice of sign: compare rotations there
    got, want = rd.quat_to_rotvec(q), ref.quat_to_rotvec(q)
    near_pi = np.abs(np.atleast_2d(q)[:, 3]) < 1e-6
    if np.any(near_pi):
        close(ref.rotvec_to_matrix(got), ref.rotvec_to_matrix(want))
    else:
        close(got, want)


@given(rotvecs())
def test_rotvec_to_matrix(r):
    close(rd.rotvec_to_matrix(r), ref.rotvec_to_matrix(r))


@given(rotvecs())
def test_matrix_to_rotvec(r):
    R = ref.rotvec_to_matrix(r)
    got, want = rd.matrix_to_rotvec(R), ref.matrix_to_rotvec(R)
    assert got.shape == want.shape
    # the same rotation, angle in [0, pi]; at exactly pi the axis sign is free
    assert np.all(np.linalg.norm(np.atleast_2d(got), axis=-1) <= np.pi + 1e-12)
    close(ref.rotvec_to_matrix(got), R)
    angles = np.linalg.norm(np.atleast_2d(want), axis=-1)
    if np.all(angles < np.pi - 1e-6):
        # both take the log through Shepperd's quaternion and atan2, well conditioned up to pi (TOL's
        # bound); the angle < pi - 1e-6 filter only excludes the free axis sign at pi: 1e-10 >> bound
        close(got, want, 1e-10)


@given(single_or_stack(lambda n: arrays(np.float64, (3,) if n is None else (n, 3), elements=finite)
                       .filter(lambda a: np.all(np.linalg.norm(a, axis=-1) > 0.1))),
       st.floats(-2 * np.pi, 2 * np.pi), st.booleans())
def test_axis_angle_to_quat(axis, angle, scalar_first):
    angles = angle if axis.ndim == 1 else np.full(axis.shape[0], angle)
    close(rd.axis_angle_to_quat(axis, angles, scalar_first=scalar_first),
          ref.axis_angle_to_quat(axis, angles, scalar_first=scalar_first))


@given(quats())
def test_quat_to_axis_angle(q):
    axis, angle = rd.quat_to_axis_angle(q)
    axis_ref, angle_ref = ref.quat_to_axis_angle(q)
    close(angle, angle_ref)
    # the rotation is the same (the axis is undefined at angle 0 and its sign free at pi)
    close(ref.quat_to_matrix(ref.axis_angle_to_quat(axis, angle)), ref.quat_to_matrix(q))
    if np.all((np.atleast_1d(angle_ref) > 1e-6) & (np.atleast_1d(angle_ref) < np.pi - 1e-6)):
        # axis = v/|v| with |v| = sin(angle/2) >= 5e-7: a rounding eps of q moves it eps/|v| <= 4.4e-10
        close(axis, axis_ref, 1e-9)


@given(single_or_stack(lambda n: st.floats(-10.0, 10.0) if n is None
                       else arrays(np.float64, (n,), elements=st.floats(-10.0, 10.0))))
@pytest.mark.parametrize("name", ["rot_x", "rot_y", "rot_z"])
def test_elementary_rotations(name, angle):
    close(getattr(rd, name)(angle), getattr(ref, name)(angle))


@given(vectors(10.0))
def test_hat_vee(v):
    close(rd.hat(v), ref.hat(v))
    S = ref.hat(v) + np.diag([1.0, 2.0, 3.0])  # a symmetric part, which vee ignores
    close(rd.vee(S), ref.vee(S))


# ------------------------------------------------------------------ algebra
@given(st.data(), st.booleans())
def test_quat_multiply(data, scalar_first):
    n = data.draw(st.one_of(st.none(), count))
    q1, q2 = data.draw(unit_quats(n)), data.draw(unit_quats(n))
    sf = (lambda q: q[..., [3, 0, 1, 2]]) if scalar_first else (lambda q: q)
    close(rd.quat_multiply(sf(q1), sf(q2), scalar_first=scalar_first),
          sf(ref.quat_multiply(q1, q2)))


@given(quats(), st.booleans())
def test_quat_inverse_and_normalize(q, scalar_first):
    close(rd.quat_inverse(q, scalar_first=scalar_first), ref.quat_inverse(q, scalar_first))
    p = 1.0000001 * q  # within the core's unit tolerance
    close(rd.quat_normalize(p, scalar_first=scalar_first), ref.quat_normalize(p))


@given(st.data())
def test_quat_rotate_all_broadcasts(data):
    n = data.draw(count)
    q_single, q_stack = data.draw(unit_quats()), data.draw(unit_quats(n))
    v_single = data.draw(arrays(np.float64, (3,), elements=st.floats(-10, 10)))
    v_stack = data.draw(arrays(np.float64, (n, 3), elements=st.floats(-10, 10)))
    for q, v in [(q_single, v_single), (q_stack, v_stack), (q_single, v_stack), (q_stack, v_single)]:
        got, want = rd.quat_rotate(q, v), ref.quat_rotate(q, v)
        assert got.shape == want.shape
        close(got, want, 1e-11)  # |v| <= 10 sqrt(3): TOL's bound times |v| (17): 7e-13 per side


@given(st.data(), st.sampled_from(["body", "world"]), st.booleans())
def test_quat_integrate(data, frame, scalar_first):
    n = data.draw(st.one_of(st.none(), count))
    q = data.draw(unit_quats(n))
    w = data.draw(arrays(np.float64, (3,) if n is None else (n, 3), elements=st.floats(-20, 20)))
    dt = data.draw(st.floats(0.0, 0.5))
    sf = (lambda a: a[..., [3, 0, 1, 2]]) if scalar_first else (lambda a: a)
    got = rd.quat_integrate(sf(q), w, dt, frame=frame, scalar_first=scalar_first)
    # angle h|w| <= 18 rad: exp rounds eps relative in the angle: <= 18 * 4 eps = 2e-14 per side
    same_rotation(got, sf(ref.quat_integrate(q, w, dt, frame=frame)), 1e-12)


# ------------------------------------------------------------------ Euler angles
PER_SEQUENCE = settings(max_examples=10)  # 24 sequences: 240 examples per property


def wrapped(d):
    return (np.asarray(d) + np.pi) % (2 * np.pi) - np.pi


@st.composite
def euler_angles(draw):
    n = draw(st.one_of(st.none(), count))
    shape = (3,) if n is None else (n, 3)
    return draw(arrays(np.float64, shape, elements=st.floats(-np.pi, np.pi)))


@PER_SEQUENCE
@given(euler_angles())
@pytest.mark.parametrize("seq", SEQUENCES)
def test_euler_to_matrix_and_quat(seq, angles):
    close(rd.euler_to_matrix(seq, angles), ref.euler_to_matrix(seq, angles))
    same_rotation(rd.euler_to_quat(seq, angles), ref.euler_to_quat(seq, angles))
    same_rotation(rd.euler_to_quat(seq, angles, scalar_first=True)[..., [1, 2, 3, 0]],
                  ref.euler_to_quat(seq, angles))


def conditioning(seq, angles):
    """1/|cos θ2| (Tait-Bryan) or 1/|sin θ2| (proper): how much the first and third angles
    amplify a rounding error in R."""
    b = np.atleast_2d(angles)[:, 1]
    d = np.abs(np.sin(b)) if seq[0].lower() == seq[2].lower() else np.abs(np.cos(b))
    return 1.0 / np.maximum(d, 1e-300)


@PER_SEQUENCE
@given(quats())
@pytest.mark.parametrize("seq", SEQUENCES)
def test_matrix_and_quat_to_euler(seq, q):
    R = ref.quat_to_matrix(q)
    want = ref.matrix_to_euler(seq, R)
    with warnings.catch_warnings():
        # near-identity samples are gimbal locks of the proper sequences (tested in test_so3_scipy_parity)
        warnings.filterwarnings("ignore", message="Gimbal lock detected", category=UserWarning)
        results = (rd.matrix_to_euler(seq, R), rd.quat_to_euler(seq, q),
                   rd.quat_to_euler(seq, q[..., [3, 0, 1, 2]], scalar_first=True))
    for got in results:
        assert got.shape == want.shape
        close(ref.euler_to_matrix(seq, got), R, 1e-12)  # always: the angles give R back
        cond = conditioning(seq, want)
        if np.all(cond < 1e3):  # angles from R amplify R's round-off by cond: TOL's bound times cond
            np.testing.assert_allclose(wrapped(got - want), 0.0, atol=1e-12 * np.max(cond))


@PER_SEQUENCE
@given(st.floats(-np.pi, np.pi), st.floats(-np.pi, np.pi), st.booleans())
@pytest.mark.parametrize("seq", SEQUENCES)
def test_euler_gimbal_lock_convention(seq, first, third, upper_end):
    """At gimbal lock the third angle is 0 (SciPy's choice) and the first carries θ1 ± θ3."""
    proper = seq[0].lower() == seq[2].lower()
    middle = (np.pi if upper_end else 0.0) if proper else (np.pi / 2 if upper_end else -np.pi / 2)
    R = ref.euler_to_matrix(seq, [first, middle, third])
    with pytest.warns(UserWarning, match="Gimbal lock detected. Setting third angle to zero"):
        got = rd.matrix_to_euler(seq, R)
    want = ref.matrix_to_euler(seq, R)
    assert got[2] == 0.0 and want[2] == 0.0
    # both declare the lock (R's entries in sin/cos theta2 are round-off, <= 1e-16, under the ~1e-7
    # lock threshold) and read theta1 +- theta3 off O(1) entries: the ignored part is <= 1e-16/1e-7
    np.testing.assert_allclose(wrapped(got - want), 0.0, atol=1e-9)
    close(ref.euler_to_matrix(seq, got), R)
