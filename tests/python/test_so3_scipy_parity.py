"""SciPy parity of the rotation parameters: `degrees=True` wherever angles go in or out, the
gimbal-lock warning, Davenport angles about arbitrary axes and modified Rodrigues parameters, each
against scipy.spatial.transform.Rotation on hundreds of random rotations (seeded
numpy.random.Generator); and the quaternion rate <-> angular velocity maps, which SciPy lacks,
against finite differences of a known motion and by round trips."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rigiddyn as rd

EPS = np.finfo(float).eps
# one conversion on each side (rigiddyn, SciPy): <= ~30 correctly rounded operations on numbers
# <= 4 (unit quaternions, rotation entries, angles) through well-conditioned forms: <= 30 eps 4 =
# 2.7e-14 per side; SciPy's and NumPy's transcendental kernels (AVX-512 or not) err by <= 4 ulp:
# TOL keeps a 10x margin over both sides together (as test_so3.TOL)
TOL = 1e-12
N = 300  # rotations per case
TO_DEGREES = 180.0 / np.pi  # the factor SciPy multiplies by (np.rad2deg); rigiddyn uses the same double
TO_RADIANS = np.pi / 180.0
PROPER = ["xyx", "xzx", "yxy", "yzy", "zxz", "zyz"]
TAIT_BRYAN = ["xyz", "xzy", "yxz", "yzx", "zxy", "zyx"]
SEQUENCES = [s for base in TAIT_BRYAN + PROPER for s in (base, base.upper())]
SETS_THIRD_TO_ZERO = "Gimbal lock detected. Setting third angle to zero since it is not possible to uniquely determine all angles."


# ---------------------------------------------------------------------------- helpers


def random_quats(rng: np.random.Generator, n: int = N) -> np.ndarray:
    """(n, 4) unit quaternions (x, y, z, w), uniform on SO(3)."""
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def wxyz(q: np.ndarray) -> np.ndarray:
    return np.roll(q, 1, axis=-1)


def xyzw(q: np.ndarray) -> np.ndarray:
    return np.roll(q, -1, axis=-1)


def assert_same_rotation(q1, q2, tol=TOL):
    """q1 = ±q2 item by item, to tol in each item's 2-norm."""
    d = np.minimum(np.linalg.norm(q1 - q2, axis=-1), np.linalg.norm(q1 + q2, axis=-1))
    assert np.all(d <= tol), d.max()


def assert_same_angles(a, b, tol, period=2 * np.pi):
    """a = b modulo `period`, entry by entry; tol may be an array broadcasting against a."""
    d = np.abs(np.remainder(np.asarray(a) - b + period / 2, period) - period / 2)
    assert np.all(d <= tol), np.max(d - tol)


def scipy_quiet(f, *args, **kwargs):
    """A SciPy call with its gimbal-lock warning silenced (the tests check rigiddyn's own)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Gimbal lock detected", category=UserWarning)
        return f(*args, **kwargs)


def gimbal_warnings(f, *args, **kwargs):
    """(result, the messages of the gimbal-lock UserWarnings that f raised)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = f(*args, **kwargs)
    messages = [str(w.message) for w in caught if issubclass(w.category, UserWarning)]
    assert all(m.startswith("Gimbal lock detected.") for m in messages), messages
    return result, messages


def euler_phi(seq: str, angles_rad: np.ndarray) -> np.ndarray:
    """φ in [0, pi], the middle angle of the equivalent proper sequence (lock at 0 and pi)."""
    b = np.atleast_2d(angles_rad)[:, 1]
    return b if seq[0].lower() == seq[2].lower() else b + np.pi / 2


def conditioning(phi: np.ndarray) -> np.ndarray:
    """1/|sin φ|: how much the first and third angles amplify a rounding error of the rotation."""
    return 1.0 / np.maximum(np.abs(np.sin(phi)), 1e-300)


# ---------------------------------------------------------------------------- Euler angles, degrees


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("scalar_first", [False, True])
def test_euler_degrees_in_matches_scipy(seq, scalar_first):
    rng = np.random.default_rng(1000 + SEQUENCES.index(seq))
    angles = rng.uniform(-200.0, 200.0, size=(N, 3))
    q = rd.euler_to_quat(seq, angles, scalar_first=scalar_first, degrees=True)
    r = Rotation.from_euler(seq, angles, degrees=True)
    assert_same_rotation(xyzw(q) if scalar_first else q, r.as_quat())
    np.testing.assert_allclose(rd.euler_to_matrix(seq, angles, degrees=True), r.as_matrix(), rtol=0, atol=TOL)
    # the conversion is SciPy's product x * (pi/180) at the boundary: exactly the radian call
    np.testing.assert_array_equal(q, rd.euler_to_quat(seq, angles * TO_RADIANS, scalar_first=scalar_first))
    np.testing.assert_array_equal(rd.euler_to_quat(seq, angles[0], degrees=True), rd.euler_to_quat(seq, angles[0] * TO_RADIANS))


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("degrees", [False, True])
def test_euler_out_matches_scipy(seq, degrees):
    rng = np.random.default_rng(2000 + SEQUENCES.index(seq))
    q = random_quats(rng)
    r = Rotation.from_quat(q)
    want = r.as_euler(seq, degrees=degrees)
    got_q = rd.quat_to_euler(seq, q, degrees=degrees)
    got_wxyz = rd.quat_to_euler(seq, wxyz(q), scalar_first=True, degrees=degrees)
    got_R = rd.matrix_to_euler(seq, r.as_matrix(), degrees=degrees)
    # the first and third angles amplify the rotation's round-off (TOL per side) by 1/|sin φ|; the
    # middle one is well conditioned. In degrees both sides multiply by the same 180/pi: the bound
    # scales by it (plus one rounding of that product, 180 eps, far below TOL)
    unit = TO_DEGREES if degrees else 1.0
    tol = 2 * TOL * unit * conditioning(euler_phi(seq, want / unit))[:, None]
    for got in (got_q, got_wxyz, got_R):
        assert got.shape == (N, 3)
        assert_same_angles(got, want, tol, period=360.0 if degrees else 2 * np.pi)
    if degrees:  # x * (180/pi) of the radians, bit for bit
        np.testing.assert_array_equal(got_q, rd.quat_to_euler(seq, q) * TO_DEGREES)


# ---------------------------------------------------------------------------- gimbal lock


def lock_angles(seq: str, rng, n: int, distance: float) -> np.ndarray:
    """(n, 3) angles [rad] whose middle angle is `distance` from a lock (both locks, alternating)."""
    locks = [0.0, np.pi] if seq.lower() in PROPER else [-np.pi / 2, np.pi / 2]
    middle = np.array([locks[k % 2] + (distance if k % 2 == 0 else -distance) for k in range(n)])
    return np.column_stack([rng.uniform(-3, 3, n), middle, rng.uniform(-3, 3, n)])


@pytest.mark.parametrize("seq", SEQUENCES)
def test_gimbal_lock_warns_once_and_sets_the_third_angle_to_zero(seq):
    rng = np.random.default_rng(3000 + SEQUENCES.index(seq))
    angles = lock_angles(seq, rng, 40, 0.0)
    r = Rotation.from_euler(seq, angles)
    for call in (lambda: rd.quat_to_euler(seq, r.as_quat()), lambda: rd.matrix_to_euler(seq, r.as_matrix()),
                 lambda: rd.quat_to_euler(seq, r.as_quat(), degrees=True) * TO_RADIANS):
        got, messages = gimbal_warnings(call)
        assert messages == [SETS_THIRD_TO_ZERO]  # SciPy's message, once for the whole stack
        np.testing.assert_array_equal(got[:, 2], 0.0)
        # at the lock the first angle carries θ1 ± θ3, read off O(1) entries: no amplification
        # (the ignored part of the rotation is round-off, <= 1e-16, far under both thresholds)
        assert_same_angles(got, scipy_quiet(r.as_euler, seq), 2 * TOL)
        assert_same_rotation(rd.euler_to_quat(seq, got), r.as_quat())
    with pytest.raises(UserWarning, match="Gimbal lock detected"):  # pytest turns warnings into errors
        rd.quat_to_euler(seq, r.as_quat())


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("distance", [1e-12, 1e-10, 1e-8])
def test_near_gimbal_lock_warns_where_scipy_does_and_keeps_the_rotation(seq, distance):
    rng = np.random.default_rng(4000 + SEQUENCES.index(seq))
    angles = lock_angles(seq, rng, 40, distance)
    q = rd.euler_to_quat(seq, angles)
    got, messages = gimbal_warnings(rd.quat_to_euler, seq, q)
    _, scipy_messages = gimbal_warnings(Rotation.from_quat(q).as_euler, seq)
    # both test φ within 1e-7 of the lock (φ is recovered to ~1e-16, so `distance` decides)
    assert len(messages) == 1 and len(scipy_messages) == 1
    # rigiddyn's angles are the exact ones: they give q back to round-off (SciPy sets the third
    # angle to 0 here too, which moves the rotation by up to 2 `distance`)
    assert_same_rotation(rd.euler_to_quat(seq, got), q)
    scipy_angles = scipy_quiet(Rotation.from_quat(q).as_euler, seq)
    assert_same_rotation(rd.euler_to_quat(seq, scipy_angles), q, 2 * distance + TOL)


@pytest.mark.parametrize("seq", SEQUENCES)
@pytest.mark.parametrize("distance", [1e-6, 1e-3])
def test_away_from_gimbal_lock_neither_warns(seq, distance):
    rng = np.random.default_rng(5000 + SEQUENCES.index(seq))
    angles = lock_angles(seq, rng, 40, distance)
    q = rd.euler_to_quat(seq, angles)
    got, messages = gimbal_warnings(rd.quat_to_euler, seq, q)
    want, scipy_messages = gimbal_warnings(Rotation.from_quat(q).as_euler, seq)
    assert messages == [] and scipy_messages == []
    # well-defined angles, amplified by 1/sin(distance)
    assert_same_angles(got, want, 2 * TOL / np.sin(distance))


def test_one_locked_item_in_a_stack_warns_once():
    rng = np.random.default_rng(6)
    q = random_quats(rng, 100)
    q[37] = [0.0, 0.0, np.sin(0.4), np.cos(0.4)]  # a turn about z: "zxz" has θ2 = 0
    _, messages = gimbal_warnings(rd.quat_to_euler, "zxz", q)
    assert messages == [SETS_THIRD_TO_ZERO]
    _, messages = gimbal_warnings(rd.quat_to_euler, "zxz", np.delete(q, 37, axis=0))
    assert messages == []


# ---------------------------------------------------------------------------- Davenport angles


def davenport_axes(rng, lam: float) -> np.ndarray:
    """Rows n1, n2 ⊥ n1, n3 = R_n2(-λ) n1 ⊥ n2, random directions and lengths."""
    n1 = rng.normal(size=3)
    n1 /= np.linalg.norm(n1)
    n2 = np.cross(n1, rng.normal(size=3))
    n2 /= np.linalg.norm(n2)
    n3 = np.cos(lam) * n1 + np.sin(lam) * np.cross(n1, n2)
    return np.array([n1, n2, n3]) * rng.uniform(0.5, 2.0, size=(3, 1))


def davenport_phi(axes: np.ndarray, order: str, theta2: np.ndarray) -> np.ndarray:
    """φ in [0, pi] of Davenport angles (as euler.hpp: θ2 = ±(φ - |λ|), axes reversed if intrinsic)."""
    n = axes / np.linalg.norm(axes, axis=1, keepdims=True)
    m1, m3 = (n[0], n[2]) if order[0] == "e" else (n[2], n[0])
    lam = np.arctan2(m3 @ np.cross(m1, n[1]), m3 @ m1)
    return np.abs(lam) + np.sign(lam if lam != 0 else 1.0) * theta2


AXES_CASES = {
    "coordinate zxz": np.array([[0.0, 0, 1], [1, 0, 0], [0, 0, 1]]),
    "coordinate xyz": np.eye(3),
    "coordinate xzy": np.array([[1.0, 0, 0], [0, 0, 1], [0, 1, 0]]),
    "reversed x, y, -x": np.array([[1.0, 0, 0], [0, 1, 0], [-1, 0, 0]]),
    "random λ 0.4": 0.4,
    "random λ -1.1": -1.1,
    "random λ pi/2": np.pi / 2,
    "random λ 2.7": 2.7,
}


@pytest.mark.parametrize("case", list(AXES_CASES))
@pytest.mark.parametrize("order", ["e", "extrinsic", "i", "intrinsic"])
@pytest.mark.parametrize("degrees", [False, True])
def test_davenport_matches_scipy(case, order, degrees):
    rng = np.random.default_rng(7000 + list(AXES_CASES).index(case))
    axes = AXES_CASES[case] if isinstance(AXES_CASES[case], np.ndarray) else davenport_axes(rng, AXES_CASES[case])
    unit = TO_DEGREES if degrees else 1.0
    # angles in
    angles = rng.uniform(-4, 4, size=(N, 3)) * unit
    q = rd.davenport_to_quat(axes, order, angles, degrees=degrees)
    r = Rotation.from_davenport(axes, order, angles, degrees=degrees)
    # the axes are normalised on both sides (<= 2 ulp each): within TOL's budget
    assert_same_rotation(q, r.as_quat())
    assert_same_rotation(wxyz(q), rd.davenport_to_quat(axes, order, angles, scalar_first=True, degrees=degrees))
    # angles out, on random rotations
    q = random_quats(rng)
    got = rd.quat_to_davenport(axes, order, q, degrees=degrees)
    want = Rotation.from_quat(q).as_davenport(axes, order, degrees=degrees)
    # first and third amplify the rotation's round-off by 1/|sin φ| (as Euler angles), in the unit
    tol = 2 * TOL * unit * conditioning(davenport_phi(axes, order, want[:, 1] / unit))[:, None]
    assert_same_angles(got, want, tol, period=360.0 if degrees else 2 * np.pi)
    np.testing.assert_array_equal(rd.quat_to_davenport(axes, order, wxyz(q), scalar_first=True, degrees=degrees), got)
    assert_same_rotation(rd.davenport_to_quat(axes, order, got, degrees=degrees), q)


@pytest.mark.parametrize("seq", SEQUENCES)
def test_davenport_about_coordinate_axes_are_euler_angles(seq):
    axes = np.eye(3)[["xyz".index(c) for c in seq.lower()]]
    order = "intrinsic" if seq.isupper() else "extrinsic"
    q = random_quats(np.random.default_rng(8000 + SEQUENCES.index(seq)))
    e = rd.quat_to_euler(seq, q)
    # two atan2 routes through the same quaternion: <= 20 eps each, times 1/|sin φ|
    tol = 40 * EPS * conditioning(euler_phi(seq, e))[:, None]
    assert_same_angles(rd.quat_to_davenport(axes, order, q), e, tol)
    assert_same_rotation(rd.davenport_to_quat(axes, order, e), rd.euler_to_quat(seq, e), 1e-15)


def test_davenport_gimbal_lock_warns():
    axes = davenport_axes(np.random.default_rng(9), 0.9)
    locked = np.array([[0.3, -0.9, 1.2], [0.3, np.pi - 0.9, 1.2]])  # φ = θ2 + λ = 0 and pi
    q = rd.davenport_to_quat(axes, "e", locked)
    got, messages = gimbal_warnings(rd.quat_to_davenport, axes, "e", q)
    assert messages == [SETS_THIRD_TO_ZERO]
    np.testing.assert_array_equal(got[:, 2], 0.0)
    want = scipy_quiet(Rotation.from_quat(q).as_davenport, axes, "e")
    # first angle read off O(1) entries at the lock (see the Euler test); λ from normalised axes
    assert_same_angles(got, want, 2 * TOL)
    assert_same_rotation(rd.davenport_to_quat(axes, "e", got), q)


def test_davenport_bad_input_names_the_argument():
    q = [0.0, 0.0, 0.0, 1.0]
    with pytest.raises(ValueError, match=r"^axes: expected 3 axes .*orthogonal"):
        rd.quat_to_davenport([[1, 0, 0], [1e-6, 1, 0], [0, 0, 1]], "e", q)
    with pytest.raises(ValueError, match=r"^axes\[1\]: expected a finite non-zero axis"):
        rd.davenport_to_quat([[1, 0, 0], [0, 0, 0], [0, 0, 1]], "e", [0, 0, 0])
    with pytest.raises(ValueError, match=r"^axes: expected"):
        rd.davenport_to_quat([[1, 0, 0], [0, 1, 0]], "e", [0, 0, 0])
    with pytest.raises(ValueError, match=r"^order: expected 'e', 'extrinsic', 'i' or 'intrinsic', got 'x'"):
        rd.quat_to_davenport(np.eye(3), "x", q)
    with pytest.raises(TypeError, match=r"^order: expected"):
        rd.quat_to_davenport(np.eye(3), 1, q)
    with pytest.raises(TypeError, match=r"^degrees: expected"):
        rd.davenport_to_quat(np.eye(3), "e", [0, 0, 0], degrees="yes")


# ---------------------------------------------------------------------------- MRP


def test_mrp_matches_scipy():
    rng = np.random.default_rng(10)
    q = random_quats(rng)
    # near a half turn (w ~ 0, both signs: the set with |p| <= 1 is chosen by the sign of w), and the identity
    near_pi = random_quats(rng, 40) * np.array([1, 1, 1, 0]) + np.array([0, 0, 0, 1]) * np.repeat([1e-17, -1e-12], 20)[:, None]
    q = np.vstack([q, near_pi / np.linalg.norm(near_pi, axis=1, keepdims=True), [[0, 0, 0, 1.0], [0, 0, 0, -1.0]]])
    got = rd.quat_to_mrp(q)
    # p = v / (1 + |w|) on numbers <= 1: normalisation (<= 2 ulp), one sum and one quotient per side
    # (<= 2 ulp): <= 4 eps per side on |p| <= 1
    np.testing.assert_allclose(got, Rotation.from_quat(q).as_mrp(), rtol=0, atol=8 * EPS)
    np.testing.assert_array_equal(rd.quat_to_mrp(wxyz(q), scalar_first=True), got)
    assert np.all(np.linalg.norm(got, axis=1) <= 1 + 4 * EPS)
    assert_same_rotation(rd.mrp_to_quat(got), q, 16 * EPS)  # |p| <= 1: a few roundings of numbers <= 2


def test_mrp_to_quat_matches_scipy_for_either_shadow_set():
    rng = np.random.default_rng(11)
    direction = rng.normal(size=(N, 3))
    p = direction / np.linalg.norm(direction, axis=1, keepdims=True) * 10.0 ** rng.uniform(-3, 3, size=(N, 1))
    q = rd.mrp_to_quat(p)
    # (2 p, 1 - |p|²)/(1 + |p|²): |p|² (3 roundings), the sum and difference, the quotients, and
    # SciPy's normalisation: <= 8 roundings per side, relative to the unit result
    assert_same_rotation(q, Rotation.from_mrp(p).as_quat(), 16 * EPS)
    assert_same_rotation(rd.mrp_to_quat(-p / np.sum(p * p, axis=1, keepdims=True)), q, 16 * EPS)
    np.testing.assert_array_equal(np.sign(q[:, 3]), np.where(np.linalg.norm(p, axis=1) > 1, -1.0, 1.0))
    np.testing.assert_array_equal(rd.mrp_to_quat(p, scalar_first=True), wxyz(q))
    # back to the set with |p| <= 1: p itself or its shadow -p/|p|²
    small = np.linalg.norm(p, axis=1, keepdims=True) <= 1
    np.testing.assert_allclose(rd.quat_to_mrp(q), np.where(small, p, -p / np.sum(p * p, axis=1, keepdims=True)),
                               rtol=16 * EPS, atol=16 * EPS)
    # |p|² beyond the range of doubles: no overflow; |p| = 5e200, q = (2 p/|p|², -1) to round-off
    # (a turn by 4 atan|p| = 2 pi - 4/|p| about p)
    huge = rd.mrp_to_quat([0.0, 3e200, 4e200])
    np.testing.assert_allclose(huge, [0.0, 0.6 * 2 / 5e200, 0.8 * 2 / 5e200, -1.0], rtol=4 * EPS, atol=0)
    with pytest.raises(ValueError, match=r"^mrp: expected"):
        rd.mrp_to_quat([0.0, np.nan, 0.0])


# ---------------------------------------------------------------------------- rotation vectors, axis-angle, elementary


@pytest.mark.parametrize("scalar_first", [False, True])
def test_rotvec_and_axis_angle_degrees_match_scipy(scalar_first):
    rng = np.random.default_rng(12)
    rotvec = rng.normal(size=(N, 3)) * 100.0  # degrees, angles up to several turns
    r = Rotation.from_rotvec(rotvec, degrees=True)
    q = rd.rotvec_to_quat(rotvec, scalar_first, degrees=True)
    assert_same_rotation(xyzw(q) if scalar_first else q, r.as_quat())
    np.testing.assert_array_equal(q, rd.rotvec_to_quat(rotvec * TO_RADIANS, scalar_first))
    np.testing.assert_allclose(rd.rotvec_to_matrix(rotvec, degrees=True), r.as_matrix(), rtol=0, atol=TOL)
    # out: angle in [0, 180] degrees; both sides multiply the same radians by 180/pi (TOL in rad)
    q = random_quats(rng)
    want = Rotation.from_quat(q).as_rotvec(degrees=True)
    got = rd.quat_to_rotvec(wxyz(q) if scalar_first else q, scalar_first, degrees=True)
    np.testing.assert_allclose(got, want, rtol=0, atol=TOL * TO_DEGREES)
    np.testing.assert_array_equal(got, rd.quat_to_rotvec(q) * TO_DEGREES)
    np.testing.assert_allclose(rd.matrix_to_rotvec(Rotation.from_quat(q).as_matrix(), degrees=True), want,
                               rtol=0, atol=TOL * TO_DEGREES)
    # axis-angle: the same rotations, the angle in degrees
    axis, angle = rd.quat_to_axis_angle(q, degrees=True)
    np.testing.assert_allclose(angle, np.linalg.norm(want, axis=1), rtol=0, atol=TOL * TO_DEGREES)
    np.testing.assert_array_equal(angle, rd.quat_to_axis_angle(q)[1] * TO_DEGREES)
    assert_same_rotation(rd.axis_angle_to_quat(axis, angle, degrees=True), q)
    angles = rng.uniform(-720, 720, N)
    assert_same_rotation(rd.axis_angle_to_quat(axis, angles, degrees=True),
                         Rotation.from_rotvec(axis * angles[:, None], degrees=True).as_quat())
    single_axis, single_angle = rd.quat_to_axis_angle(q[0], degrees=True)
    assert isinstance(single_angle, float) and 0.0 <= single_angle <= 180.0


def test_elementary_rotations_in_degrees():
    angles = np.random.default_rng(13).uniform(-720, 720, N)
    for name, axis in (("rot_x", "x"), ("rot_y", "y"), ("rot_z", "z")):
        rot = getattr(rd, name)
        np.testing.assert_allclose(rot(angles, degrees=True), Rotation.from_euler(axis, angles[:, None], degrees=True).as_matrix(),
                                   rtol=0, atol=TOL)
        np.testing.assert_array_equal(rot(angles, degrees=True), rot(angles * TO_RADIANS))


def test_degrees_is_keyword_only_and_a_bool():
    # positional True after scalar_first would be ambiguous: degrees is keyword-only
    with pytest.raises(TypeError):
        rd.euler_to_quat("xyz", [1.0, 2.0, 3.0], False, True)
    with pytest.raises(TypeError, match=r"^degrees: expected"):
        rd.quat_to_euler("xyz", [0.0, 0.0, 0.0, 1.0], degrees=1)


# ---------------------------------------------------------------------------- quaternion rate


def quat_product(a, b):
    """Hamilton product of (..., 4) quaternions (x, y, z, w), written out."""
    va, wa, vb, wb = a[..., :3], a[..., 3:], b[..., :3], b[..., 3:]
    return np.concatenate([wa * vb + wb * va + np.cross(va, vb), wa * wb - np.sum(va * vb, axis=-1, keepdims=True)], axis=-1)


def exp_half(rotvec):
    """(sin(|u|/2) u/|u|, cos(|u|/2)) of (..., 3) rotation vectors u (none zero here)."""
    angle = np.linalg.norm(rotvec, axis=-1, keepdims=True)
    return np.concatenate([np.sin(angle / 2) * rotvec / angle, np.cos(angle / 2)], axis=-1)


def test_quat_rate_is_the_derivative_of_a_known_motion():
    """q(t) = exp(t A/2) ⊗ q0 ⊗ exp(t b/2) turns at w_W = A + R(q) b, w_B = R(q)^T A + b:
    dq/dt = ½ (A, 0) ⊗ q + ½ q ⊗ (b, 0)."""
    rng = np.random.default_rng(14)
    A, b = rng.normal(size=(N, 3)), rng.normal(size=(N, 3))
    A /= np.linalg.norm(A, axis=1, keepdims=True)
    b *= rng.uniform(0.1, 1.0, size=(N, 1)) / np.linalg.norm(b, axis=1, keepdims=True)
    q0, t = random_quats(rng), rng.uniform(-2, 2, size=(N, 1))

    def q_at(s):
        return quat_product(quat_product(exp_half(s * A), q0), exp_half(s * b))

    q = q_at(t)
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    R = Rotation.from_quat(q).as_matrix()
    w_W = A + np.einsum("nij,nj->ni", R, b)
    w_B = np.einsum("nji,nj->ni", R, A) + b
    h = 1e-5
    fd = (q_at(t + h) - q_at(t - h)) / (2 * h)
    # central difference: truncation h²/6 |q'''| with |q'''| <= ((|A| + |b|)/2)³ <= 1, 1.7e-11;
    # round-off: q(t ± h) each to <= 10 eps (two products, sin/cos): 10 eps / h = 2.2e-10
    tol = 3e-10
    for frame, w in (("body", w_B), ("world", w_W)):
        np.testing.assert_allclose(rd.quat_rate(q, w, frame=frame), fd, rtol=0, atol=tol)
        np.testing.assert_allclose(rd.quat_rate(wxyz(q), w, frame=frame, scalar_first=True), wxyz(fd), rtol=0, atol=tol)
        # w = 2 vec(...) of a unit quaternion times dq/dt: twice the finite difference's error
        np.testing.assert_allclose(rd.angular_velocity_from_quat_rate(q, fd, frame=frame), w, rtol=0, atol=2 * tol)
    assert rd.quat_rate(q[0], w_B[0]).shape == (4,)


def test_angular_velocity_from_quat_rate_inverts_quat_rate():
    rng = np.random.default_rng(15)
    q = random_quats(rng)
    w = rng.normal(size=(N, 3)) * 10.0
    size = np.linalg.norm(w, axis=1, keepdims=True)
    for frame in ("body", "world"):
        dq_dt = rd.quat_rate(q, w, frame=frame)
        # two Hamilton products (4 products and 3 sums per entry) on |q| = 1, |w|: <= 16 eps |w|
        np.testing.assert_allclose(rd.angular_velocity_from_quat_rate(q, dq_dt, frame=frame), w, rtol=0,
                                   atol=16 * EPS * size.max())
        # tangent: q . dq/dt = 0 and |dq/dt| = |w|/2 (one product: <= 8 eps |w|)
        assert np.all(np.abs(np.sum(q * dq_dt, axis=1)) <= 8 * EPS * size[:, 0])
        np.testing.assert_allclose(np.linalg.norm(dq_dt, axis=1), size[:, 0] / 2, rtol=8 * EPS)
        # a part along q (it would change |q|, not the rotation) is ignored
        np.testing.assert_allclose(rd.angular_velocity_from_quat_rate(q, dq_dt + 5.0 * q, frame=frame), w, rtol=0,
                                   atol=16 * EPS * (size.max() + 10.0))
    # body and world describe one motion: w_W = R(q) w_B
    np.testing.assert_allclose(rd.quat_rate(q, rd.quat_rotate(q, w), frame="world"), rd.quat_rate(q, w), rtol=0,
                               atol=32 * EPS * size.max())


def test_quat_rate_bad_input_names_the_argument():
    q = [0.0, 0.0, 0.0, 1.0]
    with pytest.raises(ValueError, match=r"^frame: expected 'world' or 'body', got 'inertial'"):
        rd.quat_rate(q, [1.0, 0.0, 0.0], frame="inertial")
    with pytest.raises(ValueError, match=r"^dq_dt: expected"):
        rd.angular_velocity_from_quat_rate(q, [0.0, np.inf, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"^dq_dt: expected 3 items \(as q\), got 2"):
        rd.angular_velocity_from_quat_rate(np.tile(q, (3, 1)), np.zeros((2, 4)))
    with pytest.raises(ValueError, match=r"^q: expected a unit quaternion"):
        rd.quat_rate([0.0, 0.0, 0.0, 2.0], [1.0, 0.0, 0.0])
