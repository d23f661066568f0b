"""Kinematic trees against Pinocchio (the `peers` extra: `pip install ".[peers]"`; skipped without it): the
same random trees as test_tree_vs_reference.py built in both libraries, H (crba), inverse dynamics (rnea)
and forward dynamics (aba) compared at random states.

Two differences of convention are mapped: Pinocchio's free-flyer velocity is linear first ([v; w], both in
the link frame) where rigiddyn's is angular first, and Pinocchio has no fixed joint (a welded link's body is
appended to its parent's joint at its placement, and its children are placed through it). Pinocchio's crba
fills the upper triangle only, and it needs each subtree's velocities contiguous: the links are added to it
depth first. Tolerance: both sides round to ~10 n² eps relative to the largest entry
(test_tree_vs_reference.py); asserted at 1e-12, 1e-10 for aba (cond(H) < 1e3 amplifies).
"""

from __future__ import annotations

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn_ref import tree as ref
from test_tree_vs_reference import GRAVITY, build, close, depth_first, random_links, random_state

pin = pytest.importorskip("pinocchio")


def pinocchio_model(links):
    """The tree in Pinocchio, and for each rigiddyn velocity index the Pinocchio one."""
    model = pin.Model()
    model.gravity.linear = GRAVITY
    idx, _, nv = ref.sizes(links)
    joint_of, offset, permutation = {}, {}, np.zeros(nv, dtype=int)
    for i in depth_first(links):
        l = links[i]
        parent_joint = 0 if l["parent"] < 0 else joint_of[l["parent"]]
        parent_offset = pin.SE3.Identity() if l["parent"] < 0 else offset[l["parent"]]
        placement = parent_offset * pin.SE3(l["R_T"], l["p_T"])
        inertia = pin.Inertia(l["mass"], l["com"], l["inertia_com"])
        if l["kind"] == "fixed":
            model.appendBodyToJoint(parent_joint, inertia, placement)
            joint_of[i], offset[i] = parent_joint, placement
            continue
        joint = {"revolute": lambda: pin.JointModelRevoluteUnaligned(l["axis"]),
                 "prismatic": lambda: pin.JointModelPrismaticUnaligned(l["axis"]),
                 "spherical": pin.JointModelSpherical, "free": pin.JointModelFreeFlyer}[l["kind"]]()
        joint_id = model.addJoint(parent_joint, joint, placement, f"link{i}")
        model.appendBodyToJoint(joint_id, inertia, pin.SE3.Identity())
        joint_of[i], offset[i] = joint_id, pin.SE3.Identity()
        k = model.joints[joint_id].idx_v
        # rigiddyn's free joint [w; v] -> Pinocchio's [v; w]
        permutation[idx[i][1]:idx[i][1] + joint.nv] = [k + 3, k + 4, k + 5, k, k + 1, k + 2] if l["kind"] == "free" \
            else range(k, k + joint.nv)
    return model, permutation


def pinocchio_configuration(links, q):
    """q in Pinocchio's (depth-first) order: each joint's segment moved; the segments themselves agree."""
    idx, nq, _ = ref.sizes(links)
    out, k = np.zeros(nq), 0
    for i in depth_first(links):
        n = ref.KINDS[links[i]["kind"]][0]
        out[k:k + n] = q[idx[i][0]:idx[i][0] + n]
        k += n
    return out


CASES = [(seed, n, free_base) for seed in range(6) for n, free_base in [(4, False), (8, False), (5, True), (8, True)]]


@pytest.mark.parametrize("seed, n, free_base", CASES)
def test_crba_rnea_and_aba_agree_with_pinocchio(seed, n, free_base):
    rng = np.random.default_rng(seed)
    links = random_links(rng, n, free_base)
    q, v, a = random_state(rng, links)
    tree = build(links, GRAVITY)
    model, P = pinocchio_model(links)
    data = model.createData()
    q_pin = pinocchio_configuration(links, q)
    assert model.nq == tree.nq and model.nv == tree.nv
    v_pin, a_pin = np.zeros(tree.nv), np.zeros(tree.nv)
    v_pin[P], a_pin[P] = v, a
    M = pin.crba(model, data, q_pin)
    H_pin = np.triu(M) + np.triu(M, 1).T
    assert close(rd.crba(tree, q), H_pin[np.ix_(P, P)])
    assert close(rd.rnea(tree, q, v, a), pin.rnea(model, data, q_pin, v_pin, a_pin)[P])
    tau = rng.normal(size=tree.nv)
    tau_pin = np.zeros(tree.nv)
    tau_pin[P] = tau
    assert close(rd.aba(tree, q, v, tau), pin.aba(model, data, q_pin, v_pin, tau_pin)[P], 1e-10)
