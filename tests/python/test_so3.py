"""The rotation functions of rigiddyn against scipy.spatial.transform.Rotation: every conversion on
random inputs (hypothesis), single items and stacks, scalar_first both ways, and the hand-picked
delicate cases (identity, angle pi, tiny angles, gimbal lock). Quaternions are compared up to sign
where the API does not fix it, Euler angles modulo 2 pi."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import rigiddyn as rd

settings.register_profile("so3", max_examples=60, deadline=None)
settings.load_profile("so3")

# one conversion on each side (rigiddyn, SciPy): <= ~30 correctly rounded operations on numbers
# <= 4 (unit quaternions, rotations, angles), well-conditioned forms: <= 30 eps 4 = 3e-14 per side,
# and SciPy's and NumPy's SIMD kernels (AVX-512 or not) round transcendental functions to <= 4 ulp:
# TOL keeps a 10x margin over both sides together
TOL = 1e-12
EPS = np.finfo(float).eps
PROPER = ["xyx", "xzx", "yxy", "yzy", "zxz", "zyz"]
TAIT_BRYAN = ["xyz", "xzy", "yxz", "yzx", "zxy", "zyx"]
SEQUENCES = [s for base in TAIT_BRYAN + PROPER for s in (base, base.upper())]

seeds = st.integers(0, 2**32 - 1)
counts = st.integers(1, 8)


# ---------------------------------------------------------------------------- helpers


def random_quats(seed: int, n: int | None) -> np.ndarray:
    """(4,) or (n, 4) unit quaternions (x, y, z, w), uniform on the sphere."""
    q = np.random.default_rng(seed).normal(size=(1 if n is None else n, 4))
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    return q[0] if n is None else q


def scipy_xyzw(r: Rotation) -> np.ndarray:
    return np.asarray(r.as_quat())


def wxyz(q: np.ndarray) -> np.ndarray:
    """(x, y, z, w) -> (w, x, y, z)"""
    return np.roll(q, 1, axis=-1)


def xyzw(q: np.ndarray) -> np.ndarray:
    """(w, x, y, z) -> (x, y, z, w)"""
    return np.roll(q, -1, axis=-1)


def assert_same_rotation(q1: np.ndarray, q2: np.ndarray, tol: float = TOL) -> None:
    """q1 = ±q2 item by item"""
    d = np.minimum(np.linalg.norm(q1 - q2, axis=-1), np.linalg.norm(q1 + q2, axis=-1))
    assert np.all(d < tol), d.max()


def assert_same_angles(a: np.ndarray, b: np.ndarray, tol: float = 1e-10) -> None:  # default: 100 TOL, angles <= 4
    """equal modulo 2 pi"""
    d = np.abs(np.remainder(a - b + np.pi, 2 * np.pi) - np.pi)
    assert np.all(d < tol), d.max()


def canonical(q: np.ndarray) -> np.ndarray:
    """sign with w >= 0 ((x, y, z, w) order)"""
    return np.where(q[..., 3:4] < 0, -q, q)


def scipy_euler(seq: str, r: Rotation) -> np.ndarray:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # SciPy warns at gimbal lock; we test that case
        return np.asarray(r.as_euler(seq))


# ---------------------------------------------------------------------------- matrices


@given(seeds, st.one_of(st.none(), counts), st.booleans())
def test_quat_to_matrix_matches_scipy(seed, n, scalar_first):
    q = random_quats(seed, n)
    R = rd.quat_to_matrix(wxyz(q) if scalar_first else q, scalar_first=scalar_first)
    assert R.shape == ((3, 3) if n is None else (n, 3, 3))
    np.testing.assert_allclose(R, Rotation.from_quat(q).as_matrix(), rtol=0, atol=TOL)


@given(seeds, st.one_of(st.none(), counts), st.booleans())
def test_matrix_to_quat_matches_scipy_with_canonical_sign(seed, n, scalar_first):
    R = Rotation.from_quat(random_quats(seed, n)).as_matrix()
    q = rd.matrix_to_quat(R, scalar_first=scalar_first)
    assert q.shape == ((4,) if n is None else (n, 4))
    q_xyzw = xyzw(q) if scalar_first else q
    assert np.all(q_xyzw[..., 3] >= 0)
    np.testing.assert_allclose(q_xyzw, canonical(scipy_xyzw(Rotation.from_matrix(R))), rtol=0, atol=TOL)


# ---------------------------------------------------------------------------- exp / log


@given(seeds, st.one_of(st.none(), counts), st.floats(0.0, 3 * np.pi), st.booleans())
def test_rotvec_conversions_match_scipy(seed, n, max_angle, scalar_first):
    rng = np.random.default_rng(seed)
    rotvec = rng.normal(size=(1 if n is None else n, 3))
    rotvec *= rng.uniform(0, max_angle, size=(len(rotvec), 1)) / np.linalg.norm(rotvec, axis=-1, keepdims=True)
    if n is None:
        rotvec = rotvec[0]
    r = Rotation.from_rotvec(rotvec)
    q = rd.rotvec_to_quat(rotvec, scalar_first=scalar_first)
    np.testing.assert_allclose(xyzw(q) if scalar_first else q, scipy_xyzw(r), rtol=0, atol=TOL)
    np.testing.assert_allclose(rd.rotvec_to_matrix(rotvec), r.as_matrix(), rtol=0, atol=TOL)
    # the logs: angle in [0, pi], as SciPy (which also folds angles > pi back)
    np.testing.assert_allclose(rd.quat_to_rotvec(q, scalar_first=scalar_first), r.as_rotvec(), rtol=0, atol=1e-11)
    np.testing.assert_allclose(rd.matrix_to_rotvec(r.as_matrix()), r.as_rotvec(), rtol=0, atol=1e-11)
    assert rd.quat_to_rotvec(q, scalar_first=scalar_first).shape == np.shape(rotvec)


@pytest.mark.parametrize("angle", [0.0, 1e-300, 1e-12, 1e-8, 1e-4, 1.0, np.pi - 1e-9, np.pi])
def test_rotvec_edge_angles(angle):
    axis = np.array([0.48, -0.6, 0.64])  # unit
    rotvec = angle * axis
    r = Rotation.from_rotvec(rotvec)
    q = rd.rotvec_to_quat(rotvec)
    # relative: sin, cos to <= 4 ulp (libm or SIMD), <= 2 roundings more per side; absolute: the
    # angle |rotvec| is itself rounded (eps relative, moving q by <= eps angle/2) differently per side
    np.testing.assert_allclose(q, scipy_xyzw(r), rtol=16 * EPS, atol=2 * EPS * angle)
    # tiny angles keep full relative accuracy through the quaternion (the same bound)
    back = rd.quat_to_rotvec(q)
    if angle < np.pi:
        np.testing.assert_allclose(back, rotvec, rtol=16 * EPS, atol=2 * EPS * angle)
    else:  # at exactly pi, +rotvec and -rotvec are the same rotation
        assert np.allclose(back, rotvec, atol=1e-14) or np.allclose(back, -rotvec, atol=1e-14)
    R = rd.rotvec_to_matrix(rotvec)
    np.testing.assert_allclose(R, r.as_matrix(), rtol=0, atol=16 * EPS)  # O(1) entries, <= 8 eps per side
    from_R = rd.matrix_to_rotvec(R)
    sign = 1.0 if from_R @ axis >= 0 else -1.0
    # R to eps per entry, the log through Shepperd + atan2 rounds <= 8 eps of the angle (<= pi)
    np.testing.assert_allclose(from_R, sign * rotvec, rtol=0, atol=16 * EPS * np.pi)


def test_half_turn_matrices():
    for i in range(3):
        R = -np.eye(3)
        R[i, i] = 1.0
        q = rd.matrix_to_quat(R)
        expected = np.zeros(4)
        expected[i] = 1.0
        assert_same_rotation(q, expected, 1e-15)  # exact entries: sqrt(4)/2 = 1 and 0 are exact
        assert_same_angles(np.linalg.norm(rd.matrix_to_rotvec(R)), np.pi, 1e-15)  # 2 atan2(1, 0): pi rounded


# ---------------------------------------------------------------------------- axis-angle


@given(seeds, st.one_of(st.none(), counts), st.booleans())
def test_axis_angle_matches_scipy(seed, n, scalar_first):
    rng = np.random.default_rng(seed)
    m = 1 if n is None else n
    axis = rng.normal(size=(m, 3))
    angle = rng.uniform(-4, 4, size=m)
    unit = axis / np.linalg.norm(axis, axis=-1, keepdims=True)
    r = Rotation.from_rotvec(unit * angle[:, None])
    if n is None:
        axis, angle, unit, r = axis[0], float(angle[0]), unit[0], r[0]
    q = rd.axis_angle_to_quat(axis, angle, scalar_first=scalar_first)
    assert_same_rotation(xyzw(q) if scalar_first else q, scipy_xyzw(r))
    axis_back, angle_back = rd.quat_to_axis_angle(q, scalar_first=scalar_first)
    # the log: TOL's bound (angles <= pi; the axis sign is fixed away from pi)
    np.testing.assert_allclose(axis_back * np.asarray(angle_back)[..., None], r.as_rotvec(), rtol=0, atol=1e-11)
    assert np.all((0 <= np.asarray(angle_back)) & (np.asarray(angle_back) <= np.pi))
    if n is None:
        assert isinstance(angle_back, float) and axis_back.shape == (3,)
    else:
        assert axis_back.shape == (n, 3) and angle_back.shape == (n,)


def test_axis_angle_broadcasts_one_axis_over_many_angles():
    angles = np.linspace(-3, 3, 7)
    q = rd.axis_angle_to_quat([0.0, 0.0, 2.0], angles)
    assert_same_rotation(q, scipy_xyzw(Rotation.from_rotvec(np.outer(angles, [0, 0, 1]))))


def test_axis_angle_of_identity():
    axis, angle = rd.quat_to_axis_angle([0.0, 0.0, 0.0, 1.0])
    assert angle == 0.0
    np.testing.assert_array_equal(axis, [1.0, 0.0, 0.0])


# ---------------------------------------------------------------------------- Euler angles


@pytest.mark.parametrize("seq", SEQUENCES)
@given(seed=seeds, n=st.one_of(st.none(), counts), scalar_first=st.booleans())
@settings(max_examples=15)
def test_euler_matches_scipy(seq, seed, n, scalar_first):
    rng = np.random.default_rng(seed)
    angles = rng.uniform(-4, 4, size=(1 if n is None else n, 3))
    if n is None:
        angles = angles[0]
    r = Rotation.from_euler(seq, angles)
    q = rd.euler_to_quat(seq, angles, scalar_first=scalar_first)
    assert_same_rotation(xyzw(q) if scalar_first else q, scipy_xyzw(r))
    np.testing.assert_allclose(rd.euler_to_matrix(seq, angles), r.as_matrix(), rtol=0, atol=TOL)
    # the first and third angles amplify R's round-off (TOL per side) by 1/|cos b| (Tait-Bryan) or
    # 1/|sin b| (proper); beyond 1e6 the gimbal-lock thresholds of SciPy and the core may differ
    b = np.atleast_2d(scipy_euler(seq, r))[:, 1]
    # the worst-conditioned row sets the bound (the smallest |cos b| or |sin b|)
    cond = 1.0 / max(np.abs(np.sin(b) if seq[0].lower() == seq[2].lower() else np.cos(b)).min(), 1e-300)
    if cond < 1e6:
        assert_same_angles(rd.quat_to_euler(seq, q, scalar_first=scalar_first), scipy_euler(seq, r), 2 * TOL * cond)
        assert_same_angles(rd.matrix_to_euler(seq, r.as_matrix()), scipy_euler(seq, r), 2 * TOL * cond)
    assert rd.quat_to_euler(seq, q, scalar_first=scalar_first).shape == np.shape(angles)


@pytest.mark.parametrize("seq", SEQUENCES)
def test_euler_gimbal_lock(seq):
    """At gimbal lock the third angle is 0 (as SciPy, with SciPy's warning), and the angles still
    give the rotation."""
    rng = np.random.default_rng(7)
    locks = [0.0, np.pi] if seq.lower() in PROPER else [-np.pi / 2, np.pi / 2]
    for middle in locks:
        angles = np.column_stack([rng.uniform(-3, 3, 10), np.full(10, middle), rng.uniform(-3, 3, 10)])
        r = Rotation.from_euler(seq, angles)
        with pytest.warns(UserWarning, match="Gimbal lock detected. Setting third angle to zero"):
            from_quat = rd.quat_to_euler(seq, scipy_xyzw(r))
        with pytest.warns(UserWarning, match="Gimbal lock detected. Setting third angle to zero"):
            from_matrix = rd.matrix_to_euler(seq, r.as_matrix())
        for e in (from_quat, from_matrix):
            np.testing.assert_array_equal(e[:, 2], 0.0)
            # b read off an entry +-1 rounded by <= 4 ulp: asin/acos there turn d into sqrt(2 d) = 4e-8
            np.testing.assert_allclose(e[:, 1], middle, atol=1e-7)
            np.testing.assert_allclose(rd.euler_to_matrix(seq, e), r.as_matrix(), rtol=0, atol=1e-7)
            assert_same_angles(e, scipy_euler(seq, r), 1e-7)


@pytest.mark.parametrize("seq", ["xyz", "ZYX", "zxz", "XYX"])
def test_euler_identity(seq):
    np.testing.assert_allclose(rd.euler_to_quat(seq, [0.0, 0.0, 0.0]), [0, 0, 0, 1], atol=0)
    with warnings.catch_warnings():
        # the identity is a gimbal lock of the proper sequences (middle angle 0): they warn
        warnings.filterwarnings("ignore", message="Gimbal lock detected", category=UserWarning)
        e = rd.quat_to_euler(seq, [0.0, 0.0, 0.0, 1.0])
    np.testing.assert_allclose(rd.euler_to_matrix(seq, e), np.eye(3), atol=1e-15)  # angles 0: cos 0, sin 0 exact


# ---------------------------------------------------------------------------- elementary


@given(st.floats(-10, 10))
def test_elementary_rotations_match_scipy(angle):
    for name, axis in (("rot_x", "x"), ("rot_y", "y"), ("rot_z", "z")):
        expected = Rotation.from_euler(axis, angle).as_matrix()
        np.testing.assert_allclose(getattr(rd, name)(angle), expected, rtol=0, atol=TOL)
        stacked = getattr(rd, name)(np.array([angle, -angle]))
        assert stacked.shape == (2, 3, 3)
        np.testing.assert_allclose(stacked[1], expected.T, rtol=0, atol=TOL)


def test_elementary_rotations_are_active():
    # cos(pi/2) rounds to 6e-17: the only inexact entry
    np.testing.assert_allclose(rd.rot_z(np.pi / 2) @ [1, 0, 0], [0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(rd.rot_x(np.pi / 2) @ [0, 1, 0], [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(rd.rot_y(np.pi / 2) @ [0, 0, 1], [1, 0, 0], atol=1e-15)


# ---------------------------------------------------------------------------- quaternion algebra


@given(seeds, st.sampled_from([(None, None), (5, 5), (None, 5), (5, None)]), st.booleans())
def test_multiply_inverse_rotate_match_scipy(seed, shapes, scalar_first):
    n1, n2 = shapes
    q1, q2 = random_quats(seed, n1), random_quats(seed + 1, n2)
    v = np.random.default_rng(seed).normal(size=(3,) if n2 is None else (n2, 3))
    r1, r2 = Rotation.from_quat(q1), Rotation.from_quat(q2)
    a, b = (wxyz(q1), wxyz(q2)) if scalar_first else (q1, q2)
    out = lambda q: xyzw(q) if scalar_first else q  # noqa: E731
    product = rd.quat_multiply(a, b, scalar_first=scalar_first)
    assert_same_rotation(out(product), scipy_xyzw(r1 * r2))
    assert product.shape == ((4,) if n1 is None and n2 is None else (5, 4))
    np.testing.assert_allclose(out(rd.quat_inverse(a, scalar_first=scalar_first)), scipy_xyzw(r1.inv()), atol=TOL)
    rotated = rd.quat_rotate(a, v, scalar_first=scalar_first)
    np.testing.assert_allclose(rotated, r1.apply(v), rtol=0, atol=TOL)


def test_quat_normalize_and_broadcast_shapes():
    q = np.array([[0.0, 0.0, 0.0, 2.0], [1.0, 1.0, 1.0, 1.0]])
    # powers of two: exact
    np.testing.assert_allclose(rd.quat_normalize(q), [[0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5]], atol=1e-16)
    np.testing.assert_allclose(rd.quat_normalize([2.0, 0, 0, 0], scalar_first=True), [1, 0, 0, 0], atol=1e-16)
    v = np.arange(12.0).reshape(4, 3)
    assert rd.quat_rotate([0.0, 0.0, 0.0, 1.0], v).shape == (4, 3)
    np.testing.assert_array_equal(rd.quat_rotate([0.0, 0.0, 0.0, 1.0], v), v)
    assert rd.quat_to_matrix(np.zeros((0, 4))).shape == (0, 3, 3)
    assert rd.quat_to_matrix(np.array([[0.0, 0.0, 0.0, 1.0]])).shape == (1, 3, 3)


# ---------------------------------------------------------------------------- integration


@given(seeds, st.one_of(st.none(), counts), st.floats(-2, 2), st.booleans())
def test_integrate_matches_the_exponential(seed, n, dt, scalar_first):
    q = random_quats(seed, n)
    w = np.random.default_rng(seed).normal(scale=5, size=(3,) if n is None else (n, 3))
    r, step = Rotation.from_quat(q), Rotation.from_rotvec(w * dt)
    a = wxyz(q) if scalar_first else q
    out = lambda q: xyzw(q) if scalar_first else q  # noqa: E731
    body = rd.quat_integrate(a, w, dt, frame="body", scalar_first=scalar_first)
    world = rd.quat_integrate(a, w, dt, frame="world", scalar_first=scalar_first)
    assert_same_rotation(out(body), scipy_xyzw(r * step))
    assert_same_rotation(out(world), scipy_xyzw(step * r))
    assert body.shape == np.shape(q)


def test_integrate_default_frame_is_body_and_spin_closed_form():
    # spin at 2 rad/s about body z for 0.3 s from a tilted attitude: q0 ⊗ (0, 0, sin 0.3, cos 0.3)
    q0 = scipy_xyzw(Rotation.from_rotvec([0.4, 0.0, 0.0]))
    expected = scipy_xyzw(Rotation.from_quat(q0) * Rotation.from_quat([0, 0, np.sin(0.3), np.cos(0.3)]))
    # one product of unit quaternions on each side (<= 4 eps per component), 4 components
    assert_same_rotation(rd.quat_integrate(q0, [0.0, 0.0, 2.0], 0.3), expected, 16 * EPS)


# ---------------------------------------------------------------------------- skew


@given(seeds, st.one_of(st.none(), counts))
def test_hat_vee(seed, n):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(3,) if n is None else (n, 3))
    x = rng.normal(size=np.shape(v))
    S = rd.hat(v)
    # a b - c d on each side: <= 2 roundings of products <= max|v| max|x|
    np.testing.assert_allclose(np.einsum("...ij,...j->...i", S, x), np.cross(v, x), rtol=0,
                               atol=8 * EPS * np.abs(v).max() * np.abs(x).max())
    np.testing.assert_array_equal(rd.vee(S), v)
    np.testing.assert_array_equal(S, -np.swapaxes(S, -1, -2))


# ---------------------------------------------------------------------------- scipy interop


@given(seeds, st.one_of(st.none(), counts), st.booleans())
def test_to_and_from_scipy(seed, n, scalar_first):
    q = random_quats(seed, n)
    a = wxyz(q) if scalar_first else q
    r = rd.to_scipy(a, scalar_first=scalar_first)
    assert isinstance(r, Rotation)
    assert r.single == (n is None)
    np.testing.assert_allclose(r.as_matrix(), rd.quat_to_matrix(q), rtol=0, atol=TOL)
    # SciPy renormalises the unit q once: <= 2 eps per component
    np.testing.assert_allclose(rd.from_scipy(r, scalar_first=scalar_first), a, rtol=0, atol=1e-15)


def test_interop_names_exported():
    assert "to_scipy" in rd.__all__ and "from_scipy" in rd.__all__
