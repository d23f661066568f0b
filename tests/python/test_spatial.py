"""Python API of the spatial layer: Motion, Force, Transform, Screw, cross-product matrices and the
array functions, checked against formulas written out here in numpy (angular part first), with
property tests (hypothesis) and bad-input tests. The comparison with the independent numpy
reference (rigiddyn_ref.spatial) is in a separate file."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _helpers import hat

SETTINGS = settings(max_examples=60, deadline=None)
finite = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
vec3 = arrays(np.float64, 3, elements=finite)
# a rotation from a random direction in R^4 (SciPy normalises the quaternion)
quat = arrays(np.float64, 4, elements=st.floats(-1.0, 1.0)).filter(lambda q: np.linalg.norm(q) > 0.1)


def rotation(q):
    return Rotation.from_quat(q).as_matrix()


def motion(w, v):
    return rd.Motion(w, v)


# --- containers ------------------------------------------------------------------------------


def test_motion_and_force_layout_is_angular_first():
    m = rd.Motion([1, 2, 3], [4, 5, 6])
    np.testing.assert_array_equal(m.angular, [1, 2, 3])
    np.testing.assert_array_equal(m.linear, [4, 5, 6])
    np.testing.assert_array_equal(m.to_vector(), [1, 2, 3, 4, 5, 6])
    np.testing.assert_array_equal(rd.Motion.from_vector(np.arange(6.0)).angular, [0, 1, 2])
    f = rd.Force.from_vector([1, 2, 3, 4, 5, 6])
    np.testing.assert_array_equal(f.angular, [1, 2, 3])
    np.testing.assert_array_equal(f.linear, [4, 5, 6])
    np.testing.assert_array_equal(rd.Motion().to_vector(), np.zeros(6))
    np.testing.assert_array_equal(rd.Force().to_vector(), np.zeros(6))


def test_arithmetic():
    a = rd.Motion([1, 2, 3], [4, 5, 6])
    b = rd.Motion([-1, 0.5, 2], [0, 1, -1])
    np.testing.assert_array_equal((a + b).to_vector(), a.to_vector() + b.to_vector())
    np.testing.assert_array_equal((a - b).to_vector(), a.to_vector() - b.to_vector())
    np.testing.assert_array_equal((-a).to_vector(), -a.to_vector())
    np.testing.assert_array_equal((2 * a).to_vector(), 2 * a.to_vector())
    np.testing.assert_array_equal((a * 0.5).to_vector(), 0.5 * a.to_vector())
    f = rd.Force([1, 0, 0], [0, 2, 0])
    g = rd.Force([0, 1, 0], [3, 0, 0])
    np.testing.assert_array_equal((f + g - f).to_vector(), g.to_vector())
    np.testing.assert_array_equal((3.0 * f).to_vector(), 3 * f.to_vector())
    assert a.dot(f) == pytest.approx(1 * 1 + 5 * 2)
    assert f.dot(a) == a.dot(f)


def test_repr_round_trips():
    ns = {"Motion": rd.Motion, "Force": rd.Force, "Transform": rd.Transform, "Screw": rd.Screw}
    m = rd.Motion([0.1, -2, 3], [4, 5, 1e-300])
    np.testing.assert_array_equal(eval(repr(m), ns).to_vector(), m.to_vector())
    f = rd.Force([0.1, -2, 3], [4, 5, 6])
    np.testing.assert_array_equal(eval(repr(f), ns).to_vector(), f.to_vector())
    X = rd.Transform(rotation([0.1, 0.2, 0.3, 0.9]), [1, 2, 3])
    Y = eval(repr(X), ns)
    np.testing.assert_array_equal(Y.rotation, X.rotation)
    np.testing.assert_array_equal(Y.translation, X.translation)
    assert "pitch=inf" in repr(rd.twist_to_screw(rd.Motion([0, 0, 0], [1, 0, 0])))


def test_members_are_read_only():
    m = rd.Motion([1, 2, 3], [4, 5, 6])
    with pytest.raises(ValueError, match="read-only"):
        m.angular[0] = 7.0
    X = rd.Transform()
    with pytest.raises(ValueError, match="read-only"):
        X.translation[0] = 1.0


# --- cross products --------------------------------------------------------------------------


@SETTINGS
@given(vec3, vec3, vec3, vec3, vec3, vec3)
def test_cross_products_match_written_out_formulas(w1, v1, w2, v2, n, f):
    m1, m2, force = rd.Motion(w1, v1), rd.Motion(w2, v2), rd.Force(n, f)
    expected = np.concatenate([np.cross(w1, w2), np.cross(w1, v2) + np.cross(v1, w2)])
    np.testing.assert_allclose(m1.cross(m2).to_vector(), expected, atol=1e-12)
    np.testing.assert_allclose(rd.motion_cross_matrix(m1) @ m2.to_vector(), expected, atol=1e-12)
    expected_f = np.concatenate([np.cross(w1, n) + np.cross(v1, f), np.cross(w1, f)])
    np.testing.assert_allclose(m1.cross_force(force).to_vector(), expected_f, atol=1e-12)
    np.testing.assert_allclose(rd.force_cross_matrix(m1), -rd.motion_cross_matrix(m1).T, atol=0)
    assert m1.dot(force) == pytest.approx(w1 @ n + v1 @ f, abs=1e-12)


def test_cross_matrix_blocks():
    m = rd.Motion([1, 2, 3], [-4, 5, -6])
    crm = rd.motion_cross_matrix(m)
    assert crm.shape == (6, 6)
    np.testing.assert_array_equal(crm[:3, :3], hat([1, 2, 3]))
    np.testing.assert_array_equal(crm[3:, :3], hat([-4, 5, -6]))
    np.testing.assert_array_equal(crm[:3, 3:], np.zeros((3, 3)))


# --- transforms -----------------------------------------------------------------------------


def test_hand_computed_transform():
    # B turned 90 deg about z, origin at (1, 0, 0): spinning about B's z axis at 1 rad/s moves
    # A's origin with w x (0 - p) = (0, -1, 0)
    X = rd.Transform(rotation=[[0, -1, 0], [1, 0, 0], [0, 0, 1]], translation=[1, 0, 0])
    m_A = X.act(rd.Motion([0, 0, 1], [0, 0, 0]))
    np.testing.assert_allclose(m_A.to_vector(), [0, 0, 1, 0, -1, 0], atol=1e-15)
    f_A = X.act(rd.Force([0, 0, 0], [1, 0, 0]))
    np.testing.assert_allclose(f_A.to_vector(), [0, 0, 1, 0, 1, 0], atol=1e-15)
    np.testing.assert_allclose(X.act_point([1, 0, 0]), [1, 1, 0], atol=1e-15)


def test_identity_default_and_from_quat():
    X = rd.Transform()
    np.testing.assert_array_equal(X.rotation, np.eye(3))
    np.testing.assert_array_equal(X.translation, np.zeros(3))
    q = np.array([0.1, -0.2, 0.3, 0.9])
    q /= np.linalg.norm(q)
    Y = rd.Transform.from_quat(q, [1, 2, 3])
    np.testing.assert_allclose(Y.rotation, Rotation.from_quat(q).as_matrix(), atol=1e-15)
    Z = rd.Transform.from_quat(np.roll(q, 1), [1, 2, 3], scalar_first=True)
    np.testing.assert_allclose(Z.rotation, Y.rotation, atol=1e-15)
    np.testing.assert_allclose(Y.quat(), q, atol=1e-15)
    np.testing.assert_allclose(Y.quat(scalar_first=True), np.roll(q, 1), atol=1e-15)
    np.testing.assert_allclose(rd.Transform.from_quat(-q).quat(), q, atol=1e-15)  # w >= 0


@SETTINGS
@given(quat, vec3, vec3, vec3, vec3, vec3)
def test_act_matches_dense_matrices_and_preserves_power(q, p, w, v, n, f):
    R = rotation(q)
    X = rd.Transform(R, p)
    m, force = rd.Motion(w, v), rd.Force(n, f)
    M = np.block([[R, np.zeros((3, 3))], [hat(p) @ R, R]])
    F = np.block([[R, hat(p) @ R], [np.zeros((3, 3)), R]])
    np.testing.assert_allclose(X.motion_matrix(), M, atol=1e-13)
    np.testing.assert_allclose(X.force_matrix(), F, atol=1e-13)
    np.testing.assert_allclose(X.force_matrix(), np.linalg.inv(X.motion_matrix()).T, atol=1e-12)
    np.testing.assert_allclose(X.act(m).to_vector(), M @ m.to_vector(), atol=1e-12)
    np.testing.assert_allclose(X.act(force).to_vector(), F @ force.to_vector(), atol=1e-12)
    np.testing.assert_allclose(X.act_inv(X.act(m)).to_vector(), m.to_vector(), atol=1e-12)
    np.testing.assert_allclose(X.act_inv(X.act(force)).to_vector(), force.to_vector(), atol=1e-11)
    assert X.act(m).dot(X.act(force)) == pytest.approx(m.dot(force), abs=1e-10)
    np.testing.assert_allclose(X.act_inv_point(X.act_point(w)), w, atol=1e-12)


@SETTINGS
@given(quat, vec3, quat, vec3, quat, vec3)
def test_composition_inverse_and_associativity(q1, p1, q2, p2, q3, p3):
    X1, X2, X3 = rd.Transform(rotation(q1), p1), rd.Transform(rotation(q2), p2), rd.Transform(rotation(q3), p3)
    np.testing.assert_allclose((X1 * X2).motion_matrix(), X1.motion_matrix() @ X2.motion_matrix(), atol=1e-12)
    left, right = (X1 * X2) * X3, X1 * (X2 * X3)
    np.testing.assert_allclose(left.rotation, right.rotation, atol=1e-13)
    np.testing.assert_allclose(left.translation, right.translation, atol=1e-12)
    identity = X1 * X1.inverse()
    np.testing.assert_allclose(identity.rotation, np.eye(3), atol=1e-13)
    np.testing.assert_allclose(identity.translation, np.zeros(3), atol=1e-12)


def test_act_point_on_stacks():
    X = rd.Transform(rotation([0.3, 0.1, -0.2, 0.9]), [1, -2, 3])
    points = np.arange(12.0).reshape(4, 3)
    out = X.act_point(points)
    assert out.shape == (4, 3)
    np.testing.assert_allclose(out, points @ X.rotation.T + X.translation, atol=1e-13)
    np.testing.assert_allclose(X.act_inv_point(out), points, atol=1e-13)
    assert X.act_point([0, 0, 0]).shape == (3,)


# --- array functions ------------------------------------------------------------------------


def random_transforms(rng, n):
    return Rotation.random(n, random_state=rng).as_matrix(), rng.normal(size=(n, 3))


def test_transform_compose_matches_transform_products():
    rng = np.random.default_rng(7)
    R_AB, p_AB = random_transforms(rng, 20)
    R_BC, p_BC = random_transforms(rng, 20)
    R_AC, p_AC = rd.transform_compose(R_AB, p_AB, R_BC, p_BC)
    assert R_AC.shape == (20, 3, 3) and p_AC.shape == (20, 3)
    for i in range(20):
        X = rd.Transform(R_AB[i], p_AB[i]) * rd.Transform(R_BC[i], p_BC[i])
        np.testing.assert_allclose(R_AC[i], X.rotation, atol=1e-15)
        np.testing.assert_allclose(p_AC[i], X.translation, atol=1e-15)
    np.testing.assert_allclose(R_AC, np.einsum("nij,njk->nik", R_AB, R_BC), atol=1e-14)
    np.testing.assert_allclose(p_AC, np.einsum("nij,nj->ni", R_AB, p_BC) + p_AB, atol=1e-14)


def test_transform_compose_broadcasts_single_items():
    rng = np.random.default_rng(8)
    R_AB, p_AB = random_transforms(rng, 5)
    R_BC, p_BC = random_transforms(rng, 1)
    R_AC, p_AC = rd.transform_compose(R_AB, p_AB, R_BC[0], p_BC[0])
    assert R_AC.shape == (5, 3, 3)
    np.testing.assert_allclose(p_AC, R_AB @ p_BC[0] + p_AB, atol=1e-14)
    R_single, p_single = rd.transform_compose(R_AB[0], p_AB[0], R_BC[0], p_BC[0])
    assert R_single.shape == (3, 3) and p_single.shape == (3,)
    np.testing.assert_allclose(R_single, R_AC[0], atol=0)


def test_transform_points():
    rng = np.random.default_rng(9)
    R_AB, p_AB = random_transforms(rng, 6)
    p_B = rng.normal(size=(6, 3))
    p_A = rd.transform_points(R_AB, p_AB, p_B)
    np.testing.assert_allclose(p_A, np.einsum("nij,nj->ni", R_AB, p_B) + p_AB, atol=1e-14)
    single = rd.transform_points(R_AB[2], p_AB[2], p_B)
    np.testing.assert_allclose(single, p_B @ R_AB[2].T + p_AB[2], atol=1e-14)
    assert rd.transform_points(np.eye(3), [1, 2, 3], [0, 0, 0]).shape == (3,)


# --- screw ----------------------------------------------------------------------------------


def test_screw_hand_computed():
    # 2 rad/s about z through (1, 2, 0), 0.5 m/rad: v at the origin = w x (0 - c) + h w = (4, -2, 1)
    s = rd.twist_to_screw(rd.Motion([0, 0, 2], [4, -2, 1]))
    np.testing.assert_allclose(s.direction, [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(s.point, [1, 2, 0], atol=1e-15)
    assert s.pitch == pytest.approx(0.5)
    assert s.magnitude == pytest.approx(2.0)


def test_screw_of_pure_translation():
    s = rd.twist_to_screw(rd.Motion([0, 0, 0], [0, 3, 4]))
    assert s.pitch == math.inf
    np.testing.assert_allclose(s.direction, [0, 0.6, 0.8], atol=1e-15)
    np.testing.assert_array_equal(s.point, [0, 0, 0])
    assert s.magnitude == 5.0
    np.testing.assert_allclose(rd.screw_to_twist(s).to_vector(), [0, 0, 0, 0, 3, 4], atol=1e-15)


@SETTINGS
@given(vec3.filter(lambda w: np.linalg.norm(w) > 1e-3), vec3)
def test_screw_reconstructs_twist(w, v):
    twist = rd.Motion(w, v)
    s = rd.twist_to_screw(twist)
    assert np.linalg.norm(s.direction) == pytest.approx(1.0)
    assert s.point @ s.direction == pytest.approx(0.0, abs=1e-9 * (1 + np.linalg.norm(s.point)))
    # the body point on the axis moves along the axis: v + w x c = pitch w
    np.testing.assert_allclose(v + np.cross(w, s.point), s.pitch * np.asarray(w), atol=1e-9)
    np.testing.assert_allclose(rd.screw_to_twist(s).to_vector(), twist.to_vector(), atol=1e-9)


# --- bad input ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("make", "error", "name"),
    [
        (lambda: rd.Motion([1, 2], [0, 0, 0]), ValueError, "angular"),
        (lambda: rd.Motion([0, 0, 0], [0, np.nan, 0]), ValueError, "linear"),
        (lambda: rd.Motion(["a", "b", "c"], [0, 0, 0]), TypeError, "angular"),
        (lambda: rd.Force([0, 0, 0], np.zeros((2, 3))), ValueError, "linear"),
        (lambda: rd.Force([np.inf, 0, 0], [0, 0, 0]), ValueError, "angular"),
        (lambda: rd.Motion.from_vector(np.zeros(5)), ValueError, "vector"),
        (lambda: rd.Force.from_vector(np.array([0, 0, 0, 0, 0, np.nan])), ValueError, "vector"),
        (lambda: rd.Motion([1, 2, 3], [0, 0, 0]) * np.nan, ValueError, "scalar"),
        (lambda: rd.Force([1, 2, 3], [0, 0, 0]) * "x", TypeError, "scalar"),
        (lambda: rd.Transform(2 * np.eye(3)), ValueError, "rotation"),
        (lambda: rd.Transform(np.diag([1.0, 1.0, -1.0])), ValueError, "rotation"),
        (lambda: rd.Transform(np.eye(4)), ValueError, "rotation"),
        (lambda: rd.Transform(np.eye(3), [0, 0, np.nan]), ValueError, "translation"),
        (lambda: rd.Transform(np.eye(3), np.array(["1", "2", "3"], dtype=object)), TypeError, "translation"),
        (lambda: rd.Transform.from_quat([0, 0, 0, 2.0]), ValueError, "q_AB"),
        (lambda: rd.Transform.from_quat([0, 0, 0]), ValueError, "q_AB"),
        (lambda: rd.Transform().act_point(np.zeros((4, 2))), ValueError, "p_B"),
        (lambda: rd.Transform().act_inv_point([np.nan, 0, 0]), ValueError, "p_A"),
        (lambda: rd.twist_to_screw(rd.Motion()), ValueError, "twist"),
        (lambda: rd.screw_to_twist(rd.Screw([1, 1, 0], [0, 0, 0], 0.0, 1.0)), ValueError, "direction"),
        (lambda: rd.screw_to_twist(rd.Screw([1, 0, 0], [0, 0, 0], math.nan, 1.0)), ValueError, "pitch"),
        (lambda: rd.transform_compose(np.eye(3), [0, 0, 0], np.eye(3), [0, 0]), ValueError, "p_BC"),
        (lambda: rd.transform_compose(np.eye(3), [0, 0, 0], np.eye(3) * 1.1, [0, 0, 0]), ValueError, "R_BC"),
        (lambda: rd.transform_compose(np.eye(3), [0, 0, 0], np.eye(3), [0, 0, "x"]), TypeError, "p_BC"),
        (lambda: rd.transform_points(np.eye(3), [0, 0, 0], [[0, 0, np.inf]]), ValueError, "p_B"),
    ],
)
def test_bad_input_names_the_argument(make, error, name):
    with pytest.raises(error, match=rf"^{name}\b"):
        make()


def test_stack_errors_name_the_item_and_the_length():
    R = np.stack([np.eye(3)] * 5)
    R[3] = np.diag([1.0, -1.0, -1.0]) * 1.01
    with pytest.raises(ValueError, match=r"^R_AB\[3\]: expected"):
        rd.transform_compose(R, np.zeros((5, 3)), np.eye(3), np.zeros(3))
    with pytest.raises(ValueError, match=r"^p_AB: expected 4 items \(as R_AB\), got 5"):
        rd.transform_compose(np.stack([np.eye(3)] * 4), np.zeros((5, 3)), np.eye(3), np.zeros(3))
    with pytest.raises(ValueError, match=r"^p_B: expected 2 items"):
        rd.transform_points(np.stack([np.eye(3)] * 2), np.zeros(3), np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"^R_AB\[3\]: expected"):  # a bad rotation in a stack
        rd.transform_points(R, np.zeros(3), np.zeros((5, 3)))
    with pytest.raises(ValueError, match=r"^R_AB: expected"):  # one bad rotation, broadcast over points
        rd.transform_points(np.diag([1.0, 1.0, -1.0]), np.zeros((5, 3)), np.zeros((5, 3)))


def test_wrong_argument_types():
    with pytest.raises(TypeError):
        rd.Transform().act(np.zeros(6))
    with pytest.raises(TypeError):
        rd.Motion().cross(rd.Force())
    with pytest.raises(TypeError):
        rd.twist_to_screw(np.ones(6))
