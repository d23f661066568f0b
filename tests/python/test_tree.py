"""Kinematic trees: closed forms (the pendulum, a chain held at rest, the double pendulum's mass matrix), the
joints' transforms and retractions, energy conservation under aba, and the refusals that name the bad link
or argument. The comparison with the numpy reference is in test_tree_vs_reference.py."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

import rigiddyn as rd

G = 9.81
EPS = np.finfo(float).eps


def rod(mass, length, inertia_yy):
    """A link of its frame's x axis: centre of mass at (length/2, 0, 0), inertia_yy about it (y: the joint axis)."""
    return rd.SpatialInertia(mass, [length / 2, 0.0, 0.0], np.diag([0.5 * inertia_yy, inertia_yy, inertia_yy]))


def planar_chain(masses, length, inertia_yy=0.02):
    """Revolute joints about y, link k's joint at the tip (length, 0, 0) of link k - 1; gravity -z."""
    tree = rd.Tree(gravity=[0.0, 0.0, -G])
    for k, m in enumerate(masses):
        placement = None if k == 0 else rd.Transform(translation=[length, 0.0, 0.0])
        tree.add_link(f"link{k}", k - 1, rd.RevoluteJoint([0.0, 1.0, 0.0]), rod(m, length, inertia_yy), placement)
    return tree


@pytest.mark.parametrize("theta", [0.0, 0.3, 1.2, np.pi / 2, 2.5, -2.0])
def test_single_pendulum_obeys_i_omega_dot_equals_minus_m_g_l_sin_theta(theta):
    m, l, I_C = 1.7, 0.8, 0.05
    tree = rd.Tree(gravity=[0.0, 0.0, -G])
    # the bob hangs at (0, 0, -l) at theta = 0; the axis x turns it towards +y
    tree.add_link("pendulum", -1, rd.RevoluteJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(m, [0, 0, -l], I_C * np.eye(3)))
    I = I_C + m * l**2  # about the pivot
    # a few roundings of terms of size m g l / I: 8 eps relative to it
    assert abs(rd.aba(tree, [theta], [0.7], [0.0])[0] + m * G * l * np.sin(theta) / I) <= 8 * EPS * m * G * l / I
    assert abs(rd.crba(tree, [theta])[0, 0] - I) <= 4 * EPS * I


@pytest.mark.parametrize("seed", range(4))
def test_chain_at_rest_needs_the_static_torques_by_hand(seed):
    rng = np.random.default_rng(seed)
    n, L = 5, 0.6
    masses = 0.5 + rng.random(n)
    theta = rng.uniform(-np.pi, np.pi, n)
    tree = planar_chain(masses, L)
    # by hand, in the xz plane: link k points along u_k = (cos phi_k, 0, -sin phi_k), phi_k = theta_0 + ... + theta_k;
    # joint k sits at P_k = L (u_0 + ... + u_{k-1}), link k's centre at P_k + L/2 u_k. Holding the chain takes
    # tau_k = - g sum_{j >= k} m_j (x(C_j) - x(P_k)) (the weight's moment about +y at joint k is + m g dx).
    phi = np.cumsum(theta)
    x_joint = np.concatenate([[0.0], np.cumsum(L * np.cos(phi))[:-1]])
    x_centre = x_joint + 0.5 * L * np.cos(phi)
    tau = [-G * sum(masses[j] * (x_centre[j] - x_joint[k]) for j in range(k, n)) for k in range(n)]
    # terms of size m g n L summed n times: 32 n eps relative to that size
    assert np.max(np.abs(rd.rnea(tree, theta, np.zeros(n), np.zeros(n)) - tau)) <= 32 * n * EPS * G * n * L * max(masses)
    # and at rest with those torques the chain does not move
    assert np.max(np.abs(rd.aba(tree, theta, np.zeros(n), tau))) <= 1e-12 * G / L


@pytest.mark.parametrize("theta2", [0.0, 0.4, np.pi / 2, 2.9])
def test_double_pendulum_mass_matrix_in_closed_form(theta2):
    m1, m2, l1, l2, I1, I2 = 1.3, 0.7, 0.9, 0.6, 0.04, 0.03
    tree = rd.Tree()
    tree.add_link("upper", -1, rd.RevoluteJoint([0, 1.0, 0]), rod(m1, l1, I1))
    tree.add_link("lower", 0, rd.RevoluteJoint([0, 1.0, 0]), rod(m2, l2, I2), rd.Transform(translation=[l1, 0, 0]))
    a1, a2, c2 = l1 / 2, l2 / 2, np.cos(theta2)
    H = np.array([[I1 + m1 * a1**2 + I2 + m2 * (l1**2 + a2**2 + 2 * l1 * a2 * c2), I2 + m2 * (a2**2 + l1 * a2 * c2)],
                  [I2 + m2 * (a2**2 + l1 * a2 * c2), I2 + m2 * a2**2]])
    assert np.max(np.abs(rd.crba(tree, [0.8, theta2]) - H)) <= 16 * EPS * np.max(H)  # a few roundings per entry


def test_aba_conserves_energy_along_a_trajectory():
    # a free-floating base with a ball-jointed arm under gravity, integrated by RK45 on (q, v) with the
    # quaternions renormalised in the right-hand side: T + V stays within the integrator's tolerance
    tree = rd.Tree(gravity=[0.0, 0.0, -G])
    I = rd.SpatialInertia(1.0, [0.1, 0.0, 0.0], np.diag([0.1, 0.12, 0.15]))
    tree.add_link("base", -1, rd.FreeJoint(), I)
    tree.add_link("arm", 0, rd.SphericalJoint(), I, rd.Transform(translation=[0.3, 0.0, 0.0]))
    tree.add_link("hand", 1, rd.RevoluteJoint([0.0, 1.0, 1.0]), I, rd.Transform(translation=[0.3, 0.0, 0.0]))
    q0 = tree.neutral_configuration()
    v0 = np.array([0.3, -0.2, 0.5, 0.1, 0.0, 0.2, 1.0, 0.5, -0.3, 0.8])

    def qdot(q, v):
        # d/dt q from v, by the retraction over a vanishing step (central difference of second order,
        # exact to the RK tolerance for the step 1e-6 s chosen)
        h = 1e-6
        return (tree.integrate(q, v, h) - tree.integrate(q, v, -h)) / (2 * h)

    def rhs(_, x):
        q = x[:tree.nq].copy()
        for k in (3, 7):  # the quaternions of the base (q[3:7]) and the ball (q[7:11])
            q[k:k + 4] /= np.linalg.norm(q[k:k + 4])
        v = x[tree.nq:]
        return np.concatenate([qdot(q, v), rd.aba(tree, q, v, np.zeros(tree.nv))])

    sol = solve_ivp(rhs, (0.0, 1.0), np.concatenate([q0, v0]), rtol=1e-10, atol=1e-10)
    E = []
    for x in sol.y.T:
        q = x[:tree.nq].copy()
        for k in (3, 7):
            q[k:k + 4] /= np.linalg.norm(q[k:k + 4])
        E.append(tree.kinetic_energy(q, x[tree.nq:]) + tree.potential_energy(q))
    # RK45 at rtol 1e-10 over 1 s keeps the energy to ~1e-9 relative (with the central-difference qdot, 1e-10)
    assert np.ptp(E) <= 1e-7 * max(abs(E[0]), 1.0)


def test_spherical_retraction_is_the_so3_exponential():
    joint_tree = rd.Tree()
    joint_tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))
    q0 = Rotation.from_rotvec([0.2, -0.4, 0.9]).as_quat()
    w_L, dt = np.array([1.0, 2.0, -0.5]), 0.7
    q1 = joint_tree.integrate(q0, w_L, dt)
    expected = (Rotation.from_quat(q0) * Rotation.from_rotvec(w_L * dt)).as_quat()  # body-frame velocity: right product
    assert np.allclose(q1, expected * np.sign(q1 @ expected), rtol=0, atol=8 * EPS)
    assert abs(np.linalg.norm(q1) - 1.0) <= 4 * EPS


def test_free_joint_transform_and_retraction():
    joint = rd.FreeJoint()
    q = np.concatenate([[1.0, 2.0, 3.0], Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_quat()])
    X = joint.transform(q)
    assert np.allclose(X.rotation, Rotation.from_rotvec([0, 0, np.pi / 2]).as_matrix(), atol=4 * EPS)
    assert np.array_equal(X.translation, [1.0, 2.0, 3.0])
    tree = rd.Tree()
    tree.add_link("body", -1, joint, rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3)))
    # a pure translation along the body's x, which is W's y after the quarter turn
    q1 = tree.integrate(q, [0, 0, 0, 2.0, 0, 0], 0.5)
    assert np.allclose(q1[:3], [1.0, 3.0, 3.0], atol=8 * EPS) and np.allclose(q1[3:], q[3:], atol=4 * EPS)


def test_fixed_joint_welds_the_inertia_onto_the_parent():
    # a link welded at an offset adds its inertia to the parent's: one revolute joint sees both
    I = rd.SpatialInertia(0.5, [0.0, 0.0, 0.0], 0.01 * np.eye(3))
    welded = rd.Tree()
    welded.add_link("arm", -1, rd.RevoluteJoint(), I)
    welded.add_link("weight", 0, rd.FixedJoint(), I, rd.Transform(translation=[0.4, 0.0, 0.0]))
    single = rd.Tree()
    single.add_link("arm", -1, rd.RevoluteJoint(), I + I.transformed(rd.Transform(translation=[0.4, 0.0, 0.0])))
    assert welded.nv == 1 and welded.nq == 1
    assert np.isclose(rd.crba(welded, [0.3])[0, 0], rd.crba(single, [0.3])[0, 0], rtol=4 * EPS)
    assert np.isclose(rd.crba(welded, [0.3])[0, 0], 2 * 0.01 + 0.5 * 0.4**2, rtol=4 * EPS)


# ------------------------------------------------------------------ refusals


def _inertia():
    return rd.SpatialInertia(1.0, [0, 0, 0], np.eye(3))


def test_a_bad_parent_names_the_link():
    tree = rd.Tree()
    tree.add_link("base", -1, rd.RevoluteJoint(), _inertia())
    with pytest.raises(ValueError, match=r"link 1 \('elbow'\): parent: expected an index in \[-1, 0\].*got 3"):
        tree.add_link("elbow", 3, rd.RevoluteJoint(), _inertia())
    with pytest.raises(ValueError, match=r"link 1 \('elbow'\): parent: expected an index in \[-1, 0\].*got -2"):
        tree.add_link("elbow", -2, rd.RevoluteJoint(), _inertia())
    with pytest.raises(ValueError, match=r"link 1 \('base'\): name: expected a name not yet used"):
        tree.add_link("base", 0, rd.RevoluteJoint(), _inertia())
    assert tree.num_links == 1  # nothing was added by a refused call


def test_a_point_mass_link_is_refused_naming_the_link():
    tree = rd.Tree()
    with pytest.raises(ValueError, match=r"link 0 \('bob'\): inertia: expected a positive-definite spatial inertia"):
        tree.add_link("bob", -1, rd.RevoluteJoint(), rd.SpatialInertia.point_mass(1.0, [0, 0, -1.0]))


def test_a_non_unit_quaternion_names_the_link_and_the_entries():
    tree = rd.Tree()
    tree.add_link("base", -1, rd.RevoluteJoint(), _inertia())
    tree.add_link("shoulder", 0, rd.SphericalJoint(), _inertia())
    with pytest.raises(ValueError, match=r"q\[1:5\] \(the quaternion of link 1 \('shoulder'\)\): expected a unit"):
        rd.crba(tree, [0.0, 0.0, 0.0, 0.0, 2.0])


@pytest.mark.parametrize("call, message", [
    (lambda t: rd.rnea(t, [0.0, 1.0], [0.0], [0.0]), r"q: expected shape \(nq,\) = \(1,\)"),
    (lambda t: rd.rnea(t, [0.0], [0.0, 1.0], [0.0]), r"v: expected shape \(nv,\) = \(1,\)"),
    (lambda t: rd.rnea(t, [0.0], [0.0], [np.nan]), r"a: expected finite values"),
    (lambda t: rd.aba(t, [0.0], [0.0], [np.inf]), r"tau: expected finite values"),
    (lambda t: rd.aba(t, [0.0], [0.0], [0.0], np.zeros((2, 6))), r"f_ext: expected shape \(n_links, 6\) = \(1, 6\)"),
    (lambda t: rd.crba(t, [[0.0]]), r"q: expected a 1-D array"),
    (lambda t: t.integrate([0.0], [0.0], np.nan), r"dt: expected a finite"),
    (lambda t: rd.RevoluteJoint([0.0, 0.0, 0.0]), r"axis: expected a finite non-zero 3-vector"),
    (lambda t: rd.Tree(gravity=[0.0, np.nan, 0.0]), r"gravity: expected finite"),
    (lambda t: t.link_index("nope"), r"name: expected the name of a link, got 'nope'"),
])
def test_bad_arguments_are_named(call, message):
    tree = rd.Tree()
    tree.add_link("arm", -1, rd.RevoluteJoint(), _inertia())
    with pytest.raises(ValueError, match=message):
        call(tree)


def test_an_empty_tree_has_empty_results():
    tree = rd.Tree()
    assert rd.crba(tree, []).shape == (0, 0) and rd.rnea(tree, [], [], []).shape == (0,)
    assert tree.kinetic_energy([], []) == 0.0
