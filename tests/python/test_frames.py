"""Frames and moving-frame kinematics from Python: Craig's worked example term by term, the
addition theorem, angular accelerations, the transport theorem and the five acceleration terms
against finite differences (numpy and SciPy only, never the core, build the expected values),
user motions given as Python callables, the worked-example command, and bad input."""

import math

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn.__main__ import main
from rigiddyn.worked_example import format_worked_example, textbook_worked_example
from scipy.spatial.transform import Rotation

R_DISK, THETA = 0.06, math.radians(30.0)
T_EXAMPLE = THETA / 4  # the disk turns from angle 0 at t = 0 at 4 rad/s
ZERO = np.zeros(3)
C, S = math.cos(THETA), math.sin(THETA)
SEED_ANSWER = np.array([-16 * R_DISK * C, -41 * R_DISK * S, 40 * R_DISK * C])


def shaft_and_disk(shaft_length=0.0):
    """Craig's worked example: ground R ('world'), shaft R1 at 5 rad/s about i, disk R2 at 4 rad/s about k1
    relative to the shaft, about k1 through O (the end of the shaft, on its axis)."""
    tree = rd.FrameTree()
    tree.add_frame("shaft", "world", rd.FrameMotion.constant_rotation([1.0, 0, 0], 5.0))
    tree.add_frame("disk", "shaft", rd.FrameMotion.constant_rotation(
        [0, 0, 1.0], 4.0, p_PF_P=[shaft_length, 0, 0]))
    return tree


# ------------------------------------------------------------------ Craig worked example
@pytest.mark.parametrize("shaft_length", [0.0, 0.4])
def test_seed_example_point_fixed_in_disk(shaft_length):
    tree = shaft_and_disk(shaft_length)
    p = [R_DISK, 0.0, 0.0]  # P on the disk's x2 axis
    # a few roundings of numbers <= 20 (sizes 0.5, 5, 20, 2.5 below): <= 8 eps times the size
    np.testing.assert_allclose(tree.point_position("disk", p, "shaft", "shaft", T_EXAMPLE),
                               [shaft_length + R_DISK * C, R_DISK * S, 0.0], atol=1e-15)
    np.testing.assert_allclose(tree.angular_velocity("disk", "world", "shaft", T_EXAMPLE),
                               [5.0, 0.0, 4.0], atol=1e-14)
    np.testing.assert_allclose(tree.angular_acceleration("disk", "world", "shaft", T_EXAMPLE),
                               [0.0, -20.0, 0.0], atol=1e-13)  # 4 (5 i1 x k1) = -20 j1
    a = tree.point_acceleration("disk", p, ZERO, ZERO, "world", "shaft", T_EXAMPLE)
    assert isinstance(a, rd.PointAcceleration)
    expected = {
        "origin": ZERO,
        "tangential": [0.0, 0.0, 20 * R_DISK * C],
        "centripetal": [-16 * R_DISK * C, -41 * R_DISK * S, 20 * R_DISK * C],
        "relative": ZERO,
        "coriolis": ZERO,
        "total": SEED_ANSWER,
    }
    for term, want in expected.items():
        np.testing.assert_allclose(getattr(a, term), want, atol=1e-14, err_msg=term)


def test_seed_example_alternate_solution_point_moving_in_shaft():
    tree = shaft_and_disk()
    p = [R_DISK, 0.0, 0.0]
    r_OP = tree.point_position("disk", p, "shaft", "shaft", T_EXAMPLE)
    v_rel = tree.point_velocity("disk", p, ZERO, "shaft", "shaft", T_EXAMPLE).total
    a_rel = tree.point_acceleration("disk", p, ZERO, ZERO, "shaft", "shaft", T_EXAMPLE).total
    np.testing.assert_allclose(v_rel, np.cross([0, 0, 4.0], r_OP), atol=1e-15)  # |v| 0.24: a few eps of it
    a = tree.point_acceleration("shaft", r_OP, v_rel, a_rel, "world", "shaft", T_EXAMPLE)
    expected = {
        "origin": ZERO,
        "tangential": ZERO,
        "centripetal": [0.0, -25 * R_DISK * S, 0.0],
        "relative": [-16 * R_DISK * C, -16 * R_DISK * S, 0.0],
        "coriolis": [0.0, 0.0, 40 * R_DISK * C],
        "total": SEED_ANSWER,
    }
    for term, want in expected.items():
        np.testing.assert_allclose(getattr(a, term), want, atol=1e-14, err_msg=term)


def test_worked_example_function_and_command(capsys):
    result = textbook_worked_example()
    # a few roundings of the terms (<= 2.5 m/s^2) on each side: <= 8 eps 2.5 = 4.4e-15
    np.testing.assert_allclose(result["terms"]["total"], SEED_ANSWER, atol=1e-14)
    np.testing.assert_allclose(result["terms_alternate"]["total"], SEED_ANSWER, atol=1e-14)
    assert result["max_error"] < 1e-14
    text = format_worked_example(result)
    for word in ("centripetal", "Coriolis", "tangential", "-16 r cos θ", "-1.230000", "+2.078461"):
        assert word in text
    assert main(["worked-example"]) == 0
    assert "Worked example of K. Craig" in capsys.readouterr().out


# ------------------------------------------------------------------ a 3-level chain of user motions
def wobble(axis, c0, c1, c2, p0, d, e):
    """A Python-callable motion: F turns about the fixed unit axis n of P by
    θ(t) = c0 t + c1 sin(c2 t); its origin moves along p0 + d sin(e t). SciPy builds R_PF."""
    n = np.asarray(axis, float) / np.linalg.norm(axis)
    p0, d = np.asarray(p0, float), np.asarray(d, float)

    def kinematics_at(t):
        theta = c0 * t + c1 * math.sin(c2 * t)
        return (Rotation.from_rotvec(theta * n).as_matrix(),
                (c0 + c1 * c2 * math.cos(c2 * t)) * n,
                (-c1 * c2 * c2 * math.sin(c2 * t)) * n,
                p0 + d * math.sin(e * t), d * e * math.cos(e * t), -d * e * e * math.sin(e * t))

    return rd.FrameMotion(kinematics_at)


def chain():
    tree = rd.FrameTree()
    tree.add_frame("a", "world", wobble([1, 2, 3], 0.7, 0.4, 1.3, [1, -2, 0.5], [0.3, 0.1, -0.2], 0.9))
    tree.add_frame("b", "a", wobble([-2, 1, 0.5], -1.1, 0.8, 2.1, [0.4, 0.2, -0.3], [-0.1, 0.2, 0.3], 1.7))
    tree.add_frame("c", "b", wobble([0.3, -1, 2], 2.3, -0.5, 0.6, [-0.2, 0.5, 0.1], [0.2, -0.3, 0.1], 2.5))
    tree.add_frame("side", "a", wobble([0, 1, 1], 0.5, 0.3, 3.0, [0, 0, 1], [0.1, 0.1, 0.1], 0.4))
    return tree


H = 1e-3
EPS = np.finfo(float).eps
# The finite differences below are checked against their own error estimate: a fourth-order
# difference d(h) errs by ~ (d(2h) - d(h))/15 (Richardson), so |exact - d(h)| <= |d(2h) - d(h)|
# plus round-off, which divides each value's few-eps error by h (d1: 1.5/h, d2: 5.3/h^2 times
# eps |f|, f evaluated by the core to <= 16 eps): fd_tolerance below


def d1(f, t, h=H):
    """Fourth-order central first derivative."""
    return (f(t - 2 * h) - f(t + 2 * h) + 8 * (f(t + h) - f(t - h))) / (12 * h)


def d2(f, t, h=H):
    """Fourth-order central second derivative."""
    return (-(f(t + 2 * h) + f(t - 2 * h)) + 16 * (f(t + h) + f(t - h)) - 30 * f(t)) / (12 * h * h)


def vee(S):
    return np.array([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2


PAIRS = [("c", "world"), ("c", "a"), ("c", "b"), ("world", "c"), ("side", "c"), ("b", "side")]


@pytest.mark.parametrize(("F", "A"), PAIRS)
def test_angular_velocity_and_acceleration_vs_rotation_derivatives(F, A):
    tree = chain()
    t = 0.37

    def w_AF_A(s):  # hat(w_AF_A) = dR_AF/dt R_AF^T, from rotation matrices only
        return vee(d1(lambda u: tree.rotation(F, A, u), s) @ tree.rotation(F, A, s).T)

    R_AF = tree.rotation(F, A, t)
    # Richardson estimate of d1's truncation plus its round-off (1.5/h x 16 eps, |R| = 1; twice)
    tol_w = np.abs(w_AF_A(t) - vee(d1(lambda u: tree.rotation(F, A, u), t, 2 * H) @ R_AF.T)).max() + 48 * EPS / H
    np.testing.assert_allclose(tree.angular_velocity(F, A, A, t), w_AF_A(t), atol=tol_w)
    np.testing.assert_allclose(tree.angular_velocity(F, A, F, t), R_AF.T @ w_AF_A(t), atol=tol_w)
    # alpha_AF = d/dt in A of w_AF: in A components, the time derivative of w_AF_A (a difference of
    # differences: the inner round-off tol_w is divided by h once more, 1.5/h)
    tol_a = np.abs(d1(w_AF_A, t) - d1(w_AF_A, t, 2 * H)).max() + 3 * tol_w / H
    np.testing.assert_allclose(tree.angular_acceleration(F, A, A, t), d1(w_AF_A, t), atol=tol_a)


def test_no_addition_theorem_for_angular_acceleration():
    tree = chain()
    t = 0.37
    links = sum(tree.angular_acceleration(f, p, "world", t) for f, p in [("a", "world"), ("b", "a"), ("c", "b")])
    w_a = tree.angular_velocity("a", "world", "world", t)
    w_b = tree.angular_velocity("b", "a", "world", t)
    w_c = tree.angular_velocity("c", "b", "world", t)
    cross_terms = np.cross(w_a, w_b) + np.cross(w_a + w_b, w_c)
    assert np.linalg.norm(cross_terms) > 0.1
    # sums and cross products of rates <= 7 rad/s and accelerations <= 10 rad/s^2: <= 16 eps 50
    np.testing.assert_allclose(tree.angular_acceleration("c", "world", "world", t), links + cross_terms,
                               atol=1e-12)


@pytest.mark.parametrize(("B", "A"), PAIRS)
@pytest.mark.parametrize("E", ["world", "side"])
def test_transport_theorem_vs_finite_differences(B, A, E):
    tree = chain()
    t = 0.81

    def u_B(s):  # components of u in B; their derivative is u's derivative seen from B
        return np.array([math.sin(s), s * s, math.cos(2 * s)])

    du_B = np.array([math.cos(t), 2 * t, -2 * math.sin(2 * t)])
    R_EB, R_EA = tree.rotation(B, E, t), tree.rotation(A, E, t)
    got = tree.transport_derivative(R_EB @ u_B(t), R_EB @ du_B, B, A, E, t)
    want = R_EA @ d1(lambda s: tree.rotation(B, A, s) @ u_B(s), t)
    # Richardson estimate of d1's truncation plus its round-off (1.5/h x 16 eps |u| (<= 1.2), twice)
    tol = np.abs(want - R_EA @ d1(lambda s: tree.rotation(B, A, s) @ u_B(s), t, 2 * H)).max() + 64 * EPS / H
    np.testing.assert_allclose(got, want, atol=tol)


@pytest.mark.parametrize(("F", "A"), PAIRS)
@pytest.mark.parametrize("E", ["world", "b"])
def test_point_velocity_and_acceleration_vs_finite_differences_of_position(F, A, E):
    tree = chain()
    t = 1.3

    def p(s):  # Q moves in F
        return np.array([0.3 + 0.2 * math.sin(3 * s), -0.1 * s * s, 0.5 * math.cos(s)])

    v = np.array([0.6 * math.cos(3 * t), -0.2 * t, -0.5 * math.sin(t)])
    a = np.array([-1.8 * math.sin(3 * t), -0.2, -0.5 * math.cos(t)])

    def p_AQ_A(s):
        return tree.point_position(F, p(s), A, A, s)

    R_EA = tree.rotation(A, E, t)
    vel = tree.point_velocity(F, p(t), v, A, E, t)
    acc = tree.point_acceleration(F, p(t), v, a, A, E, t)
    # Richardson estimates of the truncation plus round-off (|p_AQ| <= 4: 16 eps 4 per value,
    # d1: 1.5/h, d2: 5.3/h^2, each difference twice)
    size = np.abs(p_AQ_A(t)).max()
    tol_v = np.abs(d1(p_AQ_A, t) - d1(p_AQ_A, t, 2 * H)).max() + 2 * 1.5 * 16 * EPS * size / H
    tol_a = np.abs(d2(p_AQ_A, t) - d2(p_AQ_A, t, 2 * H)).max() + 2 * 5.3 * 16 * EPS * size / H**2
    np.testing.assert_allclose(vel.total, R_EA @ d1(p_AQ_A, t), atol=tol_v)
    np.testing.assert_allclose(acc.total, R_EA @ d2(p_AQ_A, t), atol=tol_a)
    # the total is the sum of the terms: the core adds the same numbers, numpy in another order
    # (<= 4 roundings of terms <= 10 m/s, 50 m/s^2)
    np.testing.assert_allclose(vel.origin + vel.rotational + vel.relative, vel.total, atol=1e-15 * 10)
    np.testing.assert_allclose(acc.origin + acc.tangential + acc.centripetal + acc.relative + acc.coriolis,
                               acc.total, atol=1e-14 * 5)
    # the terms are the ones named: rebuild them from the frame's kinematics
    K = tree.kinematics(F, A, t)
    r, v_rel = K.R_PF @ p(t), K.R_PF @ v
    # one evaluation per term on each side: a few roundings of numbers <= 50: <= 16 eps 50 = 2e-13
    np.testing.assert_allclose(acc.origin, R_EA @ K.a_PF_P, atol=1e-12)
    np.testing.assert_allclose(acc.tangential, R_EA @ np.cross(K.alpha_PF_P, r), atol=1e-12)
    np.testing.assert_allclose(acc.centripetal, R_EA @ np.cross(K.w_PF_P, np.cross(K.w_PF_P, r)), atol=1e-12)
    np.testing.assert_allclose(acc.relative, R_EA @ K.R_PF @ a, atol=1e-12)
    np.testing.assert_allclose(acc.coriolis, R_EA @ (2 * np.cross(K.w_PF_P, v_rel)), atol=1e-12)


def test_motion_may_return_frame_kinematics_and_fixed_motion():
    tree = rd.FrameTree()
    R = Rotation.from_rotvec([0.1, 0.2, 0.3]).as_matrix()
    tree.add_frame("k", "world", rd.FrameMotion(lambda t: rd.FrameKinematics(R_PF=R, v_PF_P=[1.0, 0, 0])))
    tree.add_frame("fix", "k", rd.FrameMotion.fixed(R.T, [0, 0, 2.0]))
    np.testing.assert_allclose(tree.rotation("fix", "world", 3.0), np.eye(3), atol=1e-15)  # R R^T: gamma_3 = 3 eps
    np.testing.assert_allclose(tree.point_velocity("fix", ZERO, ZERO, "world", "world", 3.0).total,
                               [1.0, 0, 0], atol=1e-15)
    assert tree.frame_names() == ["world", "k", "fix"]
    assert tree.parent("fix") == "k" and tree.has_frame("k") and not tree.has_frame("nope")
    assert rd.FrameTree.world == "world"


# ------------------------------------------------------------------ bad input
def test_unknown_and_duplicate_names():
    tree = shaft_and_disk()
    with pytest.raises(ValueError, match=r"parent: .*got 'nowhere'"):
        tree.add_frame("x", "nowhere", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"name: .*not already in the tree.*got 'disk'"):
        tree.add_frame("disk", "world", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"frame: .*\(world, shaft, disk\).*got 'nope'"):
        tree.rotation("nope", "world", 0.0)
    with pytest.raises(ValueError, match=r"relative_to: .*got 'nope'"):
        tree.angular_velocity("disk", "nope", "world", 0.0)
    with pytest.raises(ValueError, match=r"expressed_in: .*got 'nope'"):
        tree.point_acceleration("disk", ZERO, ZERO, ZERO, "world", "nope", 0.0)


def test_cycles_are_refused():
    tree = shaft_and_disk()
    tree.add_frame("pin", "disk", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"parent: .*got 'loop'"):
        tree.add_frame("loop", "loop", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"parent: .*cycle.*got 'pin'"):
        tree.set_parent("shaft", "pin", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"parent: .*cycle.*got 'shaft'"):
        tree.set_parent("shaft", "shaft", rd.FrameMotion.fixed())
    with pytest.raises(ValueError, match=r"name: .*root"):
        tree.set_parent("world", "disk", rd.FrameMotion.fixed())
    assert tree.parent("shaft") == "world"
    tree.set_parent("pin", "world", rd.FrameMotion.fixed(p_PF_P=[0, 0, 1.0]))
    assert tree.parent("pin") == "world"


def test_bad_values():
    skewed = np.eye(3)
    skewed[0, 1] = 0.1
    with pytest.raises(ValueError, match="R_PF"):
        rd.FrameMotion.fixed(skewed)
    with pytest.raises(ValueError, match="R_PF"):
        rd.FrameMotion.fixed(-np.eye(3))
    with pytest.raises(ValueError, match="p_PF_P"):
        rd.FrameMotion.fixed(np.eye(3), [0, np.nan, 0])
    with pytest.raises(ValueError, match="axis_P: expected a non-zero vector"):
        rd.FrameMotion.constant_rotation(ZERO, 1.0)
    with pytest.raises(ValueError, match="rate"):
        rd.FrameMotion.constant_rotation([1.0, 0, 0], math.inf)
    with pytest.raises(ValueError, match="axis_P"):
        rd.FrameMotion.constant_rotation([1.0, 0], 1.0)
    with pytest.raises(TypeError, match="axis_P"):
        rd.FrameMotion.constant_rotation(["a", "b", "c"], 1.0)
    with pytest.raises(ValueError, match="w_PF_P"):
        rd.FrameKinematics(w_PF_P=[np.inf, 0, 0])
    with pytest.raises(ValueError, match=r"^motion at t=1\.0+1e\+300: t: expected a time with rate \* t finite \(rate = 1\.0+1e\+300 rad/s\)"):
        rd.FrameMotion.constant_rotation([1.0, 0, 0], 1e300).at(1e300)
    tree = shaft_and_disk()
    with pytest.raises(ValueError, match="t: "):
        tree.rotation("disk", "world", math.nan)
    with pytest.raises(ValueError, match="p_FQ_F"):
        tree.point_velocity("disk", [np.nan, 0, 0], ZERO, "world", "world", 0.0)
    with pytest.raises(ValueError, match="a_FQ_F"):
        tree.point_acceleration("disk", ZERO, ZERO, np.zeros(4), "world", "world", 0.0)
    with pytest.raises(ValueError, match="u_E"):
        tree.transport_derivative([np.nan, 0, 0], ZERO, "disk", "world", "world", 0.0)


def test_bad_user_motions():
    tree = rd.FrameTree()
    skewed = np.eye(3)
    skewed[0, 1] = 0.1
    tree.add_frame("skewed", "world", rd.FrameMotion(lambda t: (skewed, ZERO, ZERO, ZERO, ZERO, ZERO)))
    tree.add_frame("nan", "world", rd.FrameMotion(lambda t: (np.eye(3), ZERO, ZERO, ZERO, [0, math.nan, 0], ZERO)))
    tree.add_frame("short", "world", rd.FrameMotion(lambda t: (np.eye(3), ZERO)))
    tree.add_frame("shape", "world", rd.FrameMotion(lambda t: (np.eye(2), ZERO, ZERO, ZERO, ZERO, ZERO)))
    tree.add_frame("raises", "world", rd.FrameMotion(lambda t: 1 / 0))
    with pytest.raises(ValueError, match=r"frame 'skewed' at t=0.5: R_PF"):
        tree.rotation("skewed", "world", 0.5)
    with pytest.raises(ValueError, match=r"frame 'nan' .*v_PF_P"):
        tree.angular_velocity("world", "nan", "world", 0.0)
    with pytest.raises(TypeError, match="6-tuple"):
        tree.rotation("short", "world", 0.0)
    with pytest.raises(ValueError, match=r"R_PF.*shape"):
        tree.rotation("shape", "world", 0.0)
    with pytest.raises(ZeroDivisionError):
        tree.rotation("raises", "world", 0.0)
    with pytest.raises(TypeError):
        rd.FrameMotion(42)


def test_constant_rotation_at_any_finite_angle_is_a_rotation():
    # rate t = 1e300 rad: the rotation vector's norm overflowed (NaN R_PF, the API fuzz's finding); the
    # angle itself is a double, so R is the rotation by that double's sine and cosine (|R| = 1: the
    # orthonormality of a computed quaternion's matrix holds to a few eps)
    for rate, t in [(1e300, 1.0), (-1e300, 1.5), (1e-300, 1e-10), (1.0, 1e300)]:
        K = rd.FrameMotion.constant_rotation([0, 0, 2.0], rate).at(t)
        angle = rate * t
        c, s = math.cos(angle), math.sin(angle)
        np.testing.assert_allclose(K.R_PF, [[c, -s, 0], [s, c, 0], [0, 0, 1]], atol=4 * np.finfo(float).eps)
        np.testing.assert_array_equal(K.w_PF_P, [0, 0, rate])
