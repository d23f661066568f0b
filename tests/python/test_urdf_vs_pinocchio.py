"""rigiddyn.load_urdf against Pinocchio's own URDF parser (the `peers` and `urdf` extras; skipped without
them): the same URDF loaded by both libraries, then H (crba), inverse dynamics (rnea), forward dynamics
(aba) and every link's pose compared at random states.

The robots are example-robot-data's UR5 (6 revolute joints; also on a floating base, where its massless
`world` link takes the mass of `base_link`, fixed to it), Panda (7 revolute and 2 prismatic fingers,
one a mimic joint: an independent joint in both libraries) and Talos (a humanoid on a floating base, 32
revolute joints and 27 fixed ones, some of them massless or point-mass frames) from that package (in the `peers`
extra, so CI compares them), and always Pinocchio's sample manipulator and random humanoid (free flyer) written out as URDF.

Conventions mapped: Pinocchio's free-flyer velocity is [v; w] (linear first), rigiddyn's [w; v], both in
the root link's frame; both store the free flyer's quaternion (x, y, z, w); a continuous joint is
(cos q, sin q) in Pinocchio's configuration and the angle q in rigiddyn's. Pinocchio orders the joints by
its own traversal: they are matched by name.

Error bound: each entry of H or tau is a sum over the links of a subtree (N <= 60) of terms that are
products along a chain of at most d <= 12 rigid transforms, each side rounding to ~ d eps relative to the
largest term, so both agree to ~ N d eps ≈ 1.6e-13 relative to the largest entry; asserted at 1e-12 (the
poses: ~ d eps relative to 1 m). Both libraries parse the decimal text to the nearest double, and compute
each rpy rotation to a few eps. aba: a = H^-1 (tau - C) amplifies those relative errors by cond(H) (about
1e5 for Talos, whose grippers are light against its trunk): |Δa| <= 1e-12 cond(H) (|a| + |tau - C| /
|H|) in the 2-norm.
"""

from __future__ import annotations

import importlib.util
import io
from pathlib import Path

import numpy as np
import pytest

import rigiddyn as rd
from test_tree_vs_reference import RTOL, close

pin = pytest.importorskip("pinocchio")
yourdfpy = pytest.importorskip("yourdfpy")

GRAVITY = np.array([0.3, -0.2, -9.81])


def example_robot_data() -> Path | None:
    """example-robot-data's robots folder (its PyPI wheel installs it under cmeel.prefix), or None."""
    cmeel = importlib.util.find_spec("cmeel")  # found, not imported (importing it makes a temporary folder)
    if cmeel is None or cmeel.origin is None:
        return None
    robots = Path(cmeel.origin).resolve().parents[1] / "cmeel.prefix" / "share" / "example-robot-data" / "robots"
    return robots if robots.is_dir() else None


ROBOTS = {"ur5": ("ur_description/urdf/ur5_robot.urdf", False),
          "panda": ("panda_description/urdf/panda.urdf", False),
          "talos": ("talos_data/robots/talos_reduced.urdf", True),
          # a massless `world` link fixed to `base_link`, under a floating base: base_link welded into it
          "ur5_floating": ("ur_description/urdf/ur5_robot.urdf", True)}


def sample_urdf(model, joint_type) -> str:
    """A URDF of a Pinocchio model of joints about x, y or z (under a free flyer or the world), each of the
    URDF type joint_type (revolute: with limits, which URDF requires and neither library uses)."""
    lines = ['<robot name="sample">', '<link name="world"/>']
    for j in range(1, model.njoints):
        inertia, X = model.inertias[j], model.jointPlacements[j]
        I = inertia.inertia.tolist()
        lines.append(
            f'<link name="{model.names[j]}_link"><inertial><mass value="{inertia.mass!r}"/>'
            f'<origin xyz="{" ".join(map(repr, inertia.lever.tolist()))}"/><inertia ixx="{I[0][0]!r}" '
            f'iyy="{I[1][1]!r}" izz="{I[2][2]!r}" ixy="{I[0][1]!r}" ixz="{I[0][2]!r}" iyz="{I[1][2]!r}"/></inertial></link>')
        kind = model.joints[j].shortname()
        if kind == "JointModelFreeFlyer":
            lines[1] = ""  # the root link: joined to the world by the floating base
            continue
        parent = "world" if model.parents[j] == 0 else f"{model.names[model.parents[j]]}_link"
        axis = {"JointModelRX": "1 0 0", "JointModelRY": "0 1 0", "JointModelRZ": "0 0 1"}[kind]
        lines.append(
            f'<joint name="{model.names[j]}" type="{joint_type}"><parent link="{parent}"/><child link="{model.names[j]}_link"/>'
            f'<origin xyz="{" ".join(map(repr, X.translation.tolist()))}" '
            f'rpy="{" ".join(map(repr, pin.rpy.matrixToRpy(X.rotation).tolist()))}"/><axis xyz="{axis}"/>'
            + ('<limit lower="-3" upper="3" effort="1" velocity="1"/>' if joint_type == "revolute" else "") + "</joint>")
    return "\n".join(lines + ["</robot>"])


def sample_models():
    pin.seed(7)
    return {"sample_manipulator": (sample_urdf(pin.buildSampleModelManipulator(), "continuous"), False),
            "sample_humanoid": (sample_urdf(pin.buildSampleModelHumanoidRandom(), "revolute"), True)}


def robot_source(name):
    """(URDF path or text, floating_base), skipping a robot of example-robot-data when it is missing."""
    if name in ROBOTS:
        robots = example_robot_data()
        if robots is None or not (robots / ROBOTS[name][0]).is_file():
            pytest.skip(f"example-robot-data's {name} is not installed (pip install example-robot-data)")
        return robots / ROBOTS[name][0], ROBOTS[name][1]
    return sample_models()[name]


def pinocchio_model(source, floating_base):
    text = source.read_text() if isinstance(source, Path) else source
    return pin.buildModelFromXML(text, pin.JointModelFreeFlyer()) if floating_base else pin.buildModelFromXML(text)


class Match:
    """rigiddyn's q, v of a tree loaded from a URDF mapped to Pinocchio's, joint by joint (by name)."""

    def __init__(self, tree, model, source, floating_base):
        text = source.read_text() if isinstance(source, Path) else source
        robot = yourdfpy.URDF.load(io.BytesIO(text.encode()), build_scene_graph=False, load_meshes=False).robot
        joint_of = {joint.child: joint for joint in robot.joints}
        self.segments = []  # (kind, rigiddyn q and v offsets, Pinocchio's)
        iq = iv = 0
        for name in tree.link_names:
            joint = joint_of.get(name)
            kind = "floating" if joint is None and floating_base else "fixed" if joint is None else joint.type
            if kind == "fixed":
                continue
            pin_joint = model.joints[model.getJointId("root_joint" if joint is None else joint.name)]
            self.segments.append((kind, iq, iv, pin_joint.idx_q, pin_joint.idx_v, pin_joint.nq))
            iq, iv = iq + (7 if kind == "floating" else 1), iv + (6 if kind == "floating" else 1)
        assert iq == tree.nq and iv == tree.nv
        # P: Pinocchio's velocity index of each of rigiddyn's; a free flyer [w; v] -> [v; w]
        self.P = np.zeros(tree.nv, dtype=int)
        for kind, _, iv, _, kv, _ in self.segments:
            self.P[iv:iv + (6 if kind == "floating" else 1)] = [kv + 3, kv + 4, kv + 5, kv, kv + 1, kv + 2] \
                if kind == "floating" else [kv]

    def q(self, q, nq_pin):
        out = np.zeros(nq_pin)
        for kind, iq, _, kq, _, nq in self.segments:
            if kind == "floating":
                out[kq:kq + 7] = q[iq:iq + 7]  # (x, y, z, qx, qy, qz, qw) in both
            elif nq == 2:  # Pinocchio's unbounded revolute: (cos q, sin q)
                out[kq:kq + 2] = np.cos(q[iq]), np.sin(q[iq])
            else:
                out[kq] = q[iq]
        return out

    def v(self, v):
        out = np.zeros_like(v)
        out[self.P] = v
        return out


def random_state(rng, tree, match):
    q = np.zeros(tree.nq)
    for kind, iq, _, _, _, _ in match.segments:
        if kind == "floating":
            quaternion = rng.normal(size=4)
            q[iq:iq + 7] = np.concatenate([rng.normal(size=3), quaternion / np.linalg.norm(quaternion)])
        elif kind == "prismatic":
            q[iq] = rng.uniform(-0.05, 0.05)
        else:
            q[iq] = rng.uniform(-np.pi, np.pi)
    return q, rng.normal(size=tree.nv), rng.normal(size=tree.nv)


NAMES = [*ROBOTS, "sample_manipulator", "sample_humanoid"]


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("seed", range(3))
def test_urdf_dynamics_and_poses_agree_with_pinocchio(name, seed):
    source, floating_base = robot_source(name)
    tree = rd.load_urdf(source, floating_base=floating_base, gravity=GRAVITY)
    model = pinocchio_model(source, floating_base)
    model.gravity.linear = GRAVITY
    data = model.createData()
    match = Match(tree, model, source, floating_base)
    assert model.nv == tree.nv
    rng = np.random.default_rng(seed)
    q, v, a = random_state(rng, tree, match)
    q_pin, v_pin, P = match.q(q, model.nq), match.v(v), match.P

    M = pin.crba(model, data, q_pin)
    H_pin = (np.triu(M) + np.triu(M, 1).T)[np.ix_(P, P)]
    H = rd.crba(tree, q)
    assert close(H, H_pin)  # RTOL: module docstring, ~ N d eps
    assert close(rd.rnea(tree, q, v, a), pin.rnea(model, data, q_pin, v_pin, match.v(a))[P])

    tau = rng.normal(size=tree.nv)
    a_rd, a_pin = rd.aba(tree, q, v, tau), pin.aba(model, data, q_pin, v_pin, match.v(tau))[P]
    b = tau - rd.bias_forces(tree, q, v)
    bound = RTOL * np.linalg.cond(H) * (np.linalg.norm(a_pin) + np.linalg.norm(b) / np.linalg.norm(H, 2))
    assert np.linalg.norm(a_rd - a_pin) <= bound  # module docstring: cond(H) times the relative error of H, b

    R_WL, p_WL, _ = rd.forward_kinematics(tree, q)
    pin.framesForwardKinematics(model, data, q_pin)
    for i, link in enumerate(tree.link_names):
        X_WL = data.oMf[model.getFrameId(link, pin.BODY)]
        assert close(R_WL[i], X_WL.rotation) and close(p_WL[i], X_WL.translation), link  # ~ d eps


def test_the_sample_urdfs_keep_every_joint():
    """The sample models written as URDF keep their joints in both libraries (the cases above compare them)."""
    pin.seed(7)
    originals = [pin.buildSampleModelManipulator(), pin.buildSampleModelHumanoidRandom()]
    for original, (text, floating_base) in zip(originals, sample_models().values()):
        model = pinocchio_model(text, floating_base)
        tree = rd.load_urdf(text, floating_base=floating_base)
        # the same joints, in the order of Pinocchio's traversal of the URDF (the tests match them by name)
        assert sorted(model.names) == sorted(original.names) and model.nv == original.nv == tree.nv
        assert tree.num_links == original.njoints - 1
