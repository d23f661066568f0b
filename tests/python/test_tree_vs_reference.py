"""Kinematic trees (rd.Tree and Featherstone's algorithms rnea, crba, aba, forward_kinematics; the generalized
momentum and its rate) against the numpy reference rigiddyn_ref.tree, which derives the same quantities from their definitions (world
Jacobians, H = sum J^T M J, the principle of virtual power) without the recursions, on random trees of
revolute, prismatic, spherical and fixed joints with and without a free base, at random states.

Error bound of the comparisons: every entry is a sum over at most n = 8 links of products of at most n
rigid transforms, each rounding to a few eps relative to the sizes involved (lengths, masses and
velocities of order 1 here), so both sides agree to ~ 10 n² eps ≈ 1.5e-13 relative to the largest entry
of the quantity compared; asserted at 1e-12.
"""

from __future__ import annotations

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn_ref import tree as ref

RTOL = 1e-12  # module docstring: ~10 n² eps for n <= 8 links
GRAVITY = np.array([0.3, -0.2, -9.81])


def random_rotation(rng):
    return ref.quat_matrix(rng.normal(size=4))


def random_unit_quaternion(rng):
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


JOINT_ODDS = {"revolute": 0.4, "prismatic": 0.25, "spherical": 0.25, "fixed": 0.1}
VECTOR_JOINT_ODDS = {"revolute": 0.55, "prismatic": 0.3, "fixed": 0.15}  # configurations in a vector space


def random_links(rng, n, free_base, odds=JOINT_ODDS):
    """n links: a free base (if asked) then random parents and joint kinds (drawn with `odds`), random placements
    and inertias."""
    links = []
    for i in range(n):
        kind = "free" if (free_base and i == 0) else rng.choice(list(odds), p=list(odds.values()))
        parent = -1 if i == 0 else int(rng.integers(-1 if not free_base else 0, i))
        # principal moments in [1, 1.5] kg m² satisfy the triangle inequality; turned by a random rotation
        R_I = random_rotation(rng)
        inertia_com = R_I @ np.diag(1.0 + 0.5 * rng.random(3)) @ R_I.T
        links.append(ref.link(parent, str(kind), 0.5 + rng.random(), rng.normal(size=3) * 0.5, inertia_com,
                              axis=rng.normal(size=3), R_T=random_rotation(rng), p_T=rng.normal(size=3)))
    return links


def build(links, gravity):
    tree = rd.Tree(gravity=gravity)
    joints = {"revolute": lambda l: rd.RevoluteJoint(l["axis"]), "prismatic": lambda l: rd.PrismaticJoint(l["axis"]),
              "spherical": lambda l: rd.SphericalJoint(), "free": lambda l: rd.FreeJoint(),
              "fixed": lambda l: rd.FixedJoint()}
    for i, l in enumerate(links):
        tree.add_link(f"link{i}", l["parent"], joints[l["kind"]](l),
                      rd.SpatialInertia(l["mass"], l["com"], l["inertia_com"]), rd.Transform(l["R_T"], l["p_T"]))
    return tree


def depth_first(links):
    """The link indices (each link's "parent" an index, -1 the world) depth first from the root, children in index
    order: the order of a URDF reader, and the one Pinocchio needs (each subtree's velocities contiguous)."""
    order = []

    def visit(i):
        order.append(i)
        for j, link in enumerate(links):
            if link["parent"] == i:
                visit(j)

    visit(-1)
    return order[1:]


def random_state(rng, links):
    """(q, v, a) at random: angles in [-pi, pi], offsets in [-1, 1] m, unit quaternions, normal v and a."""
    q = []
    for l in links:
        if l["kind"] == "revolute":
            q.append([rng.uniform(-np.pi, np.pi)])
        elif l["kind"] == "prismatic":
            q.append([rng.uniform(-1.0, 1.0)])
        elif l["kind"] == "spherical":
            q.append(random_unit_quaternion(rng))
        elif l["kind"] == "free":
            q.append(np.concatenate([rng.normal(size=3), random_unit_quaternion(rng)]))
    nv = ref.sizes(links)[2]
    return np.concatenate(q) if q else np.zeros(0), rng.normal(size=nv), rng.normal(size=nv)


def close(actual, expected, rtol=RTOL):
    scale = max(np.max(np.abs(expected)), 1.0) if np.size(expected) else 1.0
    return np.max(np.abs(actual - expected), initial=0.0) <= rtol * scale


CASES = [(seed, n, free_base) for seed in range(6) for n, free_base in [(1, False), (4, False), (8, False), (5, True), (8, True)]]


@pytest.fixture(params=CASES, ids=[f"seed{s}-n{n}-{'free' if f else 'fixed'}_base" for s, n, f in CASES])
def case(request):
    seed, n, free_base = request.param
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, free_base)
    q, v, a = random_state(rng, links)
    return links, build(links, GRAVITY), q, v, a, rng


def test_mass_matrix_is_the_sum_of_jacobian_inertias(case):
    links, tree, q, _, _, _ = case
    H = rd.crba(tree, q)
    assert close(H, ref.mass_matrix(links, q))
    assert np.array_equal(H, H.T)  # each off-diagonal block is written once and mirrored


def test_inverse_dynamics_is_the_virtual_power_balance(case):
    links, tree, q, v, a, rng = case
    f_ext = rng.normal(size=(len(links), 6))
    assert close(rd.rnea(tree, q, v, a), ref.inverse_dynamics(links, q, v, a, GRAVITY))
    assert close(rd.rnea(tree, q, v, a, f_ext), ref.inverse_dynamics(links, q, v, a, GRAVITY, f_ext))
    assert close(rd.bias_forces(tree, q, v), ref.inverse_dynamics(links, q, v, np.zeros_like(v), GRAVITY))


def test_forward_dynamics_solves_the_equation_of_motion(case):
    links, tree, q, v, _, rng = case
    tau, f_ext = rng.normal(size=tree.nv), rng.normal(size=(len(links), 6))
    assert close(rd.aba(tree, q, v, tau, f_ext), ref.forward_dynamics(links, q, v, tau, GRAVITY, f_ext), 1e-10)


def test_forward_kinematics_gives_poses_and_twists(case):
    links, tree, q, v, _, _ = case
    R, p, V = rd.forward_kinematics(tree, q, v)
    T_W, _ = ref.poses(links, q)
    assert close(R, T_W[:, :3, :3]) and close(p, T_W[:, :3, 3])
    assert close(V, ref.link_twists(links, q, v))


def test_energies(case):
    links, tree, q, v, _, _ = case
    assert np.isclose(tree.kinetic_energy(q, v), 0.5 * v @ ref.mass_matrix(links, q) @ v, rtol=RTOL, atol=0)
    assert np.isclose(tree.potential_energy(q), ref.potential_energy(links, q, GRAVITY), rtol=RTOL, atol=1e-12)


def test_aba_inverts_rnea(case):
    _, tree, q, v, a, rng = case
    f_ext = rng.normal(size=(tree.num_links, 6))
    tau = rd.rnea(tree, q, v, a, f_ext)
    # a = H^-1 (tau - C): the error is amplified by the condition number of H (< 1e3 for these trees)
    assert close(rd.aba(tree, q, v, tau, f_ext), a, 1e-10 * max(1.0, np.max(np.abs(tau), initial=0.0)))


def test_crba_columns_are_rnea_differences(case):
    _, tree, q, v, _, _ = case
    C = rd.bias_forces(tree, q, v)
    H = rd.crba(tree, q)
    columns = np.array([rd.rnea(tree, q, v, e) - C for e in np.eye(tree.nv)]).T.reshape(tree.nv, tree.nv)
    assert close(columns, H)


def test_kinetic_energy_is_half_v_h_v(case):
    _, tree, q, v, _, _ = case
    assert np.isclose(tree.kinetic_energy(q, v), 0.5 * v @ rd.crba(tree, q) @ v, rtol=RTOL, atol=0)


def test_generalized_momentum_is_h_v(case):
    links, tree, q, v, _, _ = case
    assert close(rd.generalized_momentum(tree, q, v), ref.mass_matrix(links, q) @ v)


VECTOR_CASES = [(seed, n) for seed in range(6) for n in (1, 4, 8)]


@pytest.mark.parametrize("seed,n", VECTOR_CASES)
def test_generalized_momentum_rate_is_lagranges_equation(seed, n):
    """ṗ = ∂T/∂q + Q against the reference's ∂T/∂q from T = ½ Σ V·M V in W and Q = −rnea(q, 0, 0)."""
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, False, VECTOR_JOINT_ODDS)
    q, v, _ = random_state(rng, links)
    tree = build(links, GRAVITY)
    f_ext = rng.normal(size=(n, 6))
    zero = np.zeros_like(v)
    expected = ref.kinetic_energy_gradient(links, q, v) - ref.inverse_dynamics(links, q, zero, zero, GRAVITY, f_ext)
    assert close(rd.generalized_momentum_rate(tree, q, v, f_ext), expected)
    # With the joint forces τ of an acceleration a, τ + ṗ is d(H v)/dt = H a + Ḣ v, Ḣ v by central differences of H
    # along v: error ~ s² |H'''| |v|³ + eps |H| |v| / s, about 1e-9 at s = 1e-5 for these trees; asserted at 1e-7.
    a = rng.normal(size=tree.nv)
    tau = rd.rnea(tree, q, v, a, f_ext)
    s = 1e-5
    H_dot_v = (rd.crba(tree, q + s * v) - rd.crba(tree, q - s * v)) @ v / (2.0 * s)
    assert close(tau + rd.generalized_momentum_rate(tree, q, v, f_ext), rd.crba(tree, q) @ a + H_dot_v, 1e-7)


def test_generalized_momentum_rate_refuses_rotation_group_joints():
    tree = rd.Tree()
    tree.add_link("ball", -1, rd.SphericalJoint(), rd.SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3)))
    with pytest.raises(ValueError, match="spherical joint at link 'ball'"):
        rd.generalized_momentum_rate(tree, [0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0])


def test_trees_of_the_same_size_take_turns_in_the_kept_workspace():
    """The algorithms keep their workspace between calls and make it again for a tree of another shape: two trees
    with the same links and nv but their ball and hinge joints swapped (each link's nv differs), called in turn,
    each agree with the reference every time, and a tree that gains a link is sized again."""
    rng = np.random.default_rng(7)
    first = random_links(rng, 2, False)
    first[0]["kind"], first[1]["kind"], first[1]["parent"] = "spherical", "revolute", 0
    second = [dict(first[0], kind="revolute"), dict(first[1], kind="spherical")]
    trees = [(links, build(links, GRAVITY)) for links in (first, second)]
    for links, tree in trees + trees + trees[:1]:
        q, v, a = random_state(rng, links)
        assert close(rd.crba(tree, q), ref.mass_matrix(links, q))
        assert close(rd.rnea(tree, q, v, a), ref.inverse_dynamics(links, q, v, a, GRAVITY))
        assert close(rd.aba(tree, q, v, a), ref.forward_dynamics(links, q, v, a, GRAVITY), 1e-10)
    links, tree = trees[0]
    grown = links + random_links(rng, 1, False)
    grown[2]["parent"] = 1
    tree.add_link("link2", 1, rd.RevoluteJoint(grown[2]["axis"]) if grown[2]["kind"] == "revolute" else rd.FixedJoint(),
                  rd.SpatialInertia(grown[2]["mass"], grown[2]["com"], grown[2]["inertia_com"]),
                  rd.Transform(grown[2]["R_T"], grown[2]["p_T"]))
    grown[2]["kind"] = "revolute" if grown[2]["kind"] == "revolute" else "fixed"
    q, v, a = random_state(rng, grown)
    assert close(rd.crba(tree, q), ref.mass_matrix(grown, q))
