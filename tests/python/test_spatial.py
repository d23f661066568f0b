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
from _error_bounds import EPS, product_tolerance
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
    assert a.dot(f) == 1 * 1 + 5 * 2  # small integers: exact
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
    assert "pitch=float('inf')" in repr(rd.twist_to_screw(rd.Motion([0, 0, 0], [1, 0, 0])))


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
    # <= 4 products <= 100 summed per entry, rounded <= 4 times on each side: 8 eps 400 = 7e-13
    np.testing.assert_allclose(m1.cross(m2).to_vector(), expected, atol=1e-12)
    np.testing.assert_allclose(rd.motion_cross_matrix(m1) @ m2.to_vector(), expected, atol=1e-12)
    expected_f = np.concatenate([np.cross(w1, n) + np.cross(v1, f), np.cross(w1, f)])
    np.testing.assert_allclose(m1.cross_force(force).to_vector(), expected_f, atol=1e-12)
    np.testing.assert_allclose(rd.force_cross_matrix(m1), -rd.motion_cross_matrix(m1).T, atol=0)  # copies
    # a 6-term dot product on each side (Higham's gamma_6 |w1||n| + ...)
    assert m1.dot(force) == pytest.approx(w1 @ n + v1 @ f, abs=product_tolerance([np.concatenate([w1, v1])],
                                                                                 np.concatenate([n, f])))


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
    np.testing.assert_allclose(m_A.to_vector(), [0, 0, 1, 0, -1, 0], atol=1e-15)  # integer entries: exact
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
    # R(q): each entry a few products of unit numbers, <= 2 eps per side (and SciPy renormalises)
    np.testing.assert_allclose(Y.rotation, Rotation.from_quat(q).as_matrix(), atol=1e-15)
    Z = rd.Transform.from_quat(np.roll(q, 1), [1, 2, 3], scalar_first=True)
    np.testing.assert_allclose(Z.rotation, Y.rotation, atol=1e-15)
    np.testing.assert_allclose(Y.quat(), q, atol=1e-15)  # q -> R -> q (Shepperd): <= 4 eps
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
    # hat(p) R: 3-term sums of products <= |p| <= 17.3 (gamma_3 |hat(p)| |R| per side)
    np.testing.assert_allclose(X.motion_matrix(), M, atol=product_tolerance(np.abs(hat(p)), np.abs(R)))
    np.testing.assert_allclose(X.force_matrix(), F, atol=product_tolerance(np.abs(hat(p)), np.abs(R)))
    # LU inverse: relative error <= 8 eps cond(M) (cond <= (1 + |p|)^2) of the largest entry
    Minv_err = 8 * EPS * np.linalg.cond(M) * np.abs(F).max()
    np.testing.assert_allclose(X.force_matrix(), np.linalg.inv(X.motion_matrix()).T, atol=Minv_err)
    np.testing.assert_allclose(X.act(m).to_vector(), M @ m.to_vector(), atol=product_tolerance(M, m.to_vector()))
    np.testing.assert_allclose(X.act(force).to_vector(), F @ force.to_vector(),
                               atol=product_tolerance(F, force.to_vector()))
    # the round trip rounds X m (gamma_6 |X||m|) and then X^-1 of it: twice the product bound,
    # amplified by |X^-1| (<= 1 + |p|)
    back_m = product_tolerance(M, m.to_vector()) * (2 + np.abs(p).sum())
    np.testing.assert_allclose(X.act_inv(X.act(m)).to_vector(), m.to_vector(), atol=back_m)
    back_f = product_tolerance(F, force.to_vector()) * (2 + np.abs(p).sum())
    np.testing.assert_allclose(X.act_inv(X.act(force)).to_vector(), force.to_vector(), atol=back_f)
    # power is invariant: the two 6-term dot products of the transformed (rounded) vectors
    power_err = product_tolerance(M, m.to_vector()) * np.abs(F @ force.to_vector()).sum() + \
        product_tolerance(F, force.to_vector()) * np.abs(M @ m.to_vector()).sum()
    power_err += product_tolerance([np.abs(M @ m.to_vector())], np.abs(F @ force.to_vector())) + \
        product_tolerance([m.to_vector()], force.to_vector())  # the two dot products' own rounding
    assert X.act(m).dot(X.act(force)) == pytest.approx(m.dot(force), abs=power_err)
    np.testing.assert_allclose(X.act_inv_point(X.act_point(w)), w, atol=1e-12)  # |R w + p| <= 35: 16 eps 35


@SETTINGS
@given(quat, vec3, quat, vec3, quat, vec3)
def test_composition_inverse_and_associativity(q1, p1, q2, p2, q3, p3):
    X1, X2, X3 = rd.Transform(rotation(q1), p1), rd.Transform(rotation(q2), p2), rd.Transform(rotation(q3), p3)
    M1, M2 = X1.motion_matrix(), X2.motion_matrix()
    # a 6x6 product on the numpy side (gamma_6 |M1||M2|), 3x3 ones in the core
    np.testing.assert_allclose((X1 * X2).motion_matrix(), M1 @ M2, atol=product_tolerance(M1, M2))
    left, right = (X1 * X2) * X3, X1 * (X2 * X3)
    # three rotations multiplied in two orders: <= 2 x gamma_3 per product, entries <= 1
    np.testing.assert_allclose(left.rotation, right.rotation, atol=1e-13)
    # translations R1 (R2 p3 + p2) + p1, sizes <= 3 x 17.3: gamma_3 per level, 3 levels, 2 orders
    np.testing.assert_allclose(left.translation, right.translation, atol=1e-12)
    identity = X1 * X1.inverse()
    np.testing.assert_allclose(identity.rotation, np.eye(3), atol=1e-13)  # R R^T: gamma_3 of unit entries
    np.testing.assert_allclose(identity.translation, np.zeros(3), atol=1e-12)  # p - R R^T p: gamma_3 17.3


def test_act_point_on_stacks():
    X = rd.Transform(rotation([0.3, 0.1, -0.2, 0.9]), [1, -2, 3])
    points = np.arange(12.0).reshape(4, 3)
    out = X.act_point(points)
    assert out.shape == (4, 3)
    # points <= 11, |R p + t| <= 23: gamma_3 of that per side, and back once more
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
        # the same C++ composition (array function and Transform) on the same doubles: <= 1 ulp
        # apart if the compiler orders the sums differently (entries <= 1, translations <= 5)
        np.testing.assert_allclose(R_AC[i], X.rotation, atol=1e-15)
        np.testing.assert_allclose(p_AC[i], X.translation, atol=1e-15)
    # against numpy's einsum: gamma_3 of entries <= 1 (rotations) and <= 5 (normal translations)
    np.testing.assert_allclose(R_AC, np.einsum("nij,njk->nik", R_AB, R_BC), atol=1e-14)
    np.testing.assert_allclose(p_AC, np.einsum("nij,nj->ni", R_AB, p_BC) + p_AB, atol=1e-14)


def test_transform_compose_broadcasts_single_items():
    rng = np.random.default_rng(8)
    R_AB, p_AB = random_transforms(rng, 5)
    R_BC, p_BC = random_transforms(rng, 1)
    R_AC, p_AC = rd.transform_compose(R_AB, p_AB, R_BC[0], p_BC[0])
    assert R_AC.shape == (5, 3, 3)
    np.testing.assert_allclose(p_AC, R_AB @ p_BC[0] + p_AB, atol=1e-14)  # gamma_3 of normal sizes (<= 5)
    R_single, p_single = rd.transform_compose(R_AB[0], p_AB[0], R_BC[0], p_BC[0])
    assert R_single.shape == (3, 3) and p_single.shape == (3,)
    np.testing.assert_allclose(R_single, R_AC[0], atol=0)  # the same code on the same doubles


def test_transform_points():
    rng = np.random.default_rng(9)
    R_AB, p_AB = random_transforms(rng, 6)
    p_B = rng.normal(size=(6, 3))
    p_A = rd.transform_points(R_AB, p_AB, p_B)
    np.testing.assert_allclose(p_A, np.einsum("nij,nj->ni", R_AB, p_B) + p_AB, atol=1e-14)  # gamma_3, sizes <= 5
    single = rd.transform_points(R_AB[2], p_AB[2], p_B)
    np.testing.assert_allclose(single, p_B @ R_AB[2].T + p_AB[2], atol=1e-14)
    assert rd.transform_points(np.eye(3), [1, 2, 3], [0, 0, 0]).shape == (3,)


# --- screw ----------------------------------------------------------------------------------


def test_screw_hand_computed():
    # 2 rad/s about z through (1, 2, 0), 0.5 m/rad: v at the origin = w x (0 - c) + h w = (4, -2, 1)
    s = rd.twist_to_screw(rd.Motion([0, 0, 2], [4, -2, 1]))
    # small integers and halves: exact, or one rounding
    np.testing.assert_allclose(s.direction, [0, 0, 1], atol=1e-15)
    np.testing.assert_allclose(s.point, [1, 2, 0], atol=1e-15)
    assert s.pitch == pytest.approx(0.5, rel=4 * EPS, abs=0)
    assert s.magnitude == pytest.approx(2.0, rel=4 * EPS, abs=0)


def test_screw_of_pure_translation():
    s = rd.twist_to_screw(rd.Motion([0, 0, 0], [0, 3, 4]))
    assert s.pitch == math.inf
    np.testing.assert_allclose(s.direction, [0, 0.6, 0.8], atol=1e-15)  # (3, 4)/5: one rounding each
    np.testing.assert_array_equal(s.point, [0, 0, 0])
    assert s.magnitude == 5.0
    np.testing.assert_allclose(rd.screw_to_twist(s).to_vector(), [0, 0, 0, 0, 3, 4], atol=1e-15)


@SETTINGS
@given(vec3.filter(lambda w: np.linalg.norm(w) > 1e-3), vec3)
def test_screw_reconstructs_twist(w, v):
    twist = rd.Motion(w, v)
    s = rd.twist_to_screw(twist)
    # w/|w|: <= 2 roundings, the norm 3 more
    assert np.linalg.norm(s.direction) == pytest.approx(1.0, rel=8 * EPS, abs=0)
    # |w| >= 1e-3: point = w x v/|w|^2 has relative error a few eps of |v|/|w| <= 1.7e4; checked
    # through products with w (<= 17): a few eps times 17 |v|/|w| <= 1e-10, 1e-9 scaled by |point|
    assert s.point @ s.direction == pytest.approx(0.0, abs=1e-9 * (1 + np.linalg.norm(s.point)))
    # the body point on the axis moves along the axis: v + w x c = pitch w (c, pitch to a few eps
    # of |v|/|w| <= 1.7e4, times |w| <= 17: <= 1e-10)
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


def _overflowed(cls):
    """A Motion/Force with an infinite part, as an overflowing product makes one (after its warning)."""
    with pytest.warns(RuntimeWarning, match="expected a finite result"):
        return cls([0, 0, 9.0], [0, 0, 0]) * 1.7976931348623157e308


@pytest.mark.parametrize("call, name", [
    (lambda m, f: rd.motion_cross_matrix(m), "motion"),  # returned inf without a word (the API fuzz's finding)
    (lambda m, f: rd.force_cross_matrix(m), "motion"),
    (lambda m, f: rd.twist_to_screw(m), "twist"),
    (lambda m, f: rd.Motion().cross(m), "other"),
    (lambda m, f: rd.Motion().cross_force(f), "force"),
    (lambda m, f: rd.Motion().dot(f), "force"),
    (lambda m, f: rd.Force().dot(m), "motion"),
    (lambda m, f: rd.Transform().act(m), "spatial_vector"),
    (lambda m, f: rd.Transform().act_inv(f), "spatial_vector"),
    (lambda m, f: rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)).momentum(m), "twist"),
    (lambda m, f: rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)).kinetic_energy(m), "twist"),
])
def test_a_non_finite_spatial_argument_is_refused(call, name):
    # every public function validates what it takes (a non-finite Motion/Force exists
    # only as the result of an overflow, which warned)
    m, f = _overflowed(rd.Motion), _overflowed(rd.Force)
    with pytest.raises(ValueError, match=rf"^{name}: expected a (Motion|Force) with finite values, got angular \[0, 0, inf\], linear \[0, 0, 0\]"):
        call(m, f)
