"""rigiddyn.load_urdf (the `urdf` extra; skipped without yourdfpy): the mapping of URDF tags to a Tree, the
rule for massless links, and the refusals.

The reference is a Tree built by hand from the same numbers (placements from rd.rot_z(y) rd.rot_y(p)
rd.rot_x(r), URDF's fixed-axis roll-pitch-yaw), so the reader's trees must give the same algorithms'
results. Error bound: the URDF text carries each number by repr (exact), and the reader composes at most
one rotation (rpy) and one parallel-axis shift more than the hand-built tree, each a few eps relative to
the entries; test_tree_vs_reference.py's bound (~10 n² eps for n <= 8 links, asserted at 1e-12 relative to
the largest entry) covers both.
"""

from __future__ import annotations

import sys

import numpy as np
import pytest

import rigiddyn as rd
from test_tree_vs_reference import RTOL, close, depth_first

pytest.importorskip("yourdfpy")

GRAVITY = np.array([0.3, -0.2, -9.81])
ARM = """<robot name="arm">
  <link name="upper"><inertial><mass value="2.0"/><origin xyz="0 0 0.15"/>
    <inertia ixx="0.02" iyy="0.02" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="fore"><inertial><mass value="1.0"/><origin xyz="0.1 0 0"/>
    <inertia ixx="0.001" iyy="0.004" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="tool"/>
  <joint name="elbow" type="continuous"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.3" rpy="0 0 0"/><axis xyz="0 1 0"/></joint>
  <joint name="tool_mount" type="fixed"><parent link="fore"/><child link="tool"/><origin xyz="0.2 0 0"/></joint>
</robot>"""


def rpy_matrix(rpy):
    """URDF's roll-pitch-yaw about the fixed axes: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    return rd.rot_z(rpy[2]) @ rd.rot_y(rpy[1]) @ rd.rot_x(rpy[0])


def numbers(values):
    return " ".join(repr(float(x)) for x in values)


def inertial_tag(link):
    I = link["inertia"].tolist()  # Python floats: repr gives the shortest exact decimal
    return (f'<inertial><mass value="{float(link["mass"])!r}"/><origin xyz="{numbers(link["com"])}" '
            f'rpy="{numbers(link["com_rpy"])}"/><inertia ixx="{I[0][0]!r}" iyy="{I[1][1]!r}" izz="{I[2][2]!r}" '
            f'ixy="{I[0][1]!r}" ixz="{I[0][2]!r}" iyz="{I[1][2]!r}"/></inertial>')


def urdf_text(links):
    """A URDF of links (dicts: parent index, joint type, axis, xyz, rpy, mass, com, com_rpy, inertia)."""
    lines = ['<robot name="random">', '<link name="root"/>']
    for i, link in enumerate(links):
        parent = "root" if link["parent"] < 0 else f"link{link['parent']}"
        lines.append(f'<link name="link{i}">{inertial_tag(link) if link["mass"] else ""}</link>')
        lines.append(f'<joint name="joint{i}" type="{link["type"]}"><parent link="{parent}"/><child link="link{i}"/>'
                     f'<origin xyz="{numbers(link["xyz"])}" rpy="{numbers(link["rpy"])}"/>'
                     f'<axis xyz="{numbers(link["axis"])}"/></joint>')
    return "\n".join(lines + ["</robot>"])


def random_links(rng, n):
    """n links of random joint types, placements (rpy in [-pi, pi]) and inertias (tilted inertia frames)."""
    links = []
    for i in range(n):
        I = np.diag(1.0 + 0.5 * rng.random(3))  # principal moments in [1, 1.5]: the triangle inequality holds
        R = rpy_matrix(rng.uniform(-np.pi, np.pi, 3))
        links.append({"parent": int(rng.integers(-1, i)), "type": str(rng.choice(["revolute", "continuous",
                                                                                  "prismatic", "fixed"])),
                      "axis": rng.normal(size=3), "xyz": rng.normal(size=3), "rpy": rng.uniform(-np.pi, np.pi, 3),
                      "mass": 0.5 + rng.random(), "com": 0.5 * rng.normal(size=3),
                      "com_rpy": rng.uniform(-np.pi, np.pi, 3), "inertia": R @ I @ R.T})
    return links


def hand_built(links, floating_base=False):
    """The Tree of the same links, built with rd.Tree.add_link (the root: massless, welded into the world)."""
    tree = rd.Tree(gravity=GRAVITY)
    joints = {"revolute": rd.RevoluteJoint, "continuous": rd.RevoluteJoint, "prismatic": rd.PrismaticJoint}
    for i, link in enumerate(links):
        R_LC = rpy_matrix(link["com_rpy"])
        inertia = rd.SpatialInertia(link["mass"], link["com"], R_LC @ link["inertia"] @ R_LC.T)
        joint = rd.FixedJoint() if link["type"] == "fixed" else joints[link["type"]](link["axis"])
        tree.add_link(f"link{i}", link["parent"], joint, inertia, rd.Transform(rpy_matrix(link["rpy"]), link["xyz"]))
    return tree


def random_state(rng, tree):
    return rng.uniform(-np.pi, np.pi, tree.nq), rng.normal(size=tree.nv), rng.normal(size=tree.nv)


@pytest.mark.parametrize("seed", range(8))
def test_a_random_urdf_gives_the_hand_built_tree(seed):
    rng = np.random.default_rng(seed)
    links = random_links(rng, 6)
    tree = rd.load_urdf(urdf_text(links), gravity=GRAVITY)
    order = depth_first(links)
    # the same links, reordered depth first (parents renumbered): the hand-built tree in the reader's order
    renumber = {old: new for new, old in enumerate(order)}
    reordered = [dict(links[i], parent=renumber.get(links[i]["parent"], -1)) for i in order]
    expected = hand_built(reordered)
    assert tree.link_names == [f"link{i}" for i in order] and tree.parents == expected.parents
    q, v, a = random_state(rng, tree)
    assert close(rd.crba(tree, q), rd.crba(expected, q))  # RTOL: module docstring
    assert close(rd.rnea(tree, q, v, a), rd.rnea(expected, q, v, a))
    R, p, V = rd.forward_kinematics(tree, q, v)
    R_e, p_e, V_e = rd.forward_kinematics(expected, q, v)
    assert close(R, R_e) and close(p, p_e) and close(V, V_e)


def test_the_docstring_arm():
    tree = rd.load_urdf(ARM, gravity=[0.0, 0.0, -9.81])
    assert tree.link_names == ["upper", "fore"] and tree.nq == tree.nv == 1
    R, p, _ = rd.forward_kinematics(tree, [np.pi / 2])
    assert close(p[1], [0.0, 0.0, 0.3]) and close(R[1], rd.rot_y(np.pi / 2))
    # the welded massless tool adds nothing: the torque holding the forearm level is m g x_C
    assert close(rd.rnea(tree, [0.0], [0.0], [0.0]), [-1.0 * 9.81 * 0.1])


def test_a_file_path_reads_as_its_text(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ARM)
    q = [0.7]
    assert close(rd.crba(rd.load_urdf(path), q), rd.crba(rd.load_urdf(ARM), q), 0.0)
    assert close(rd.crba(rd.load_urdf(str(path)), q), rd.crba(rd.load_urdf(ARM), q), 0.0)


def single_link(joint_type="floating", extra="", inertial=None, axis="1 0 0"):
    inertial = inertial if inertial is not None else ('<inertial><mass value="2.0"/><origin xyz="0.1 0.2 0.3" '
                                                      'rpy="0.3 -0.2 0.5"/><inertia ixx="1.0" iyy="1.2" '
                                                      'izz="1.4" ixy="0.1" ixz="-0.05" iyz="0.02"/></inertial>')
    return (f'<robot name="one"><link name="world"/><link name="body">{inertial}</link>{extra}'
            f'<joint name="j" type="{joint_type}"><parent link="world"/><child link="body"/>'
            f'<axis xyz="{axis}"/></joint></robot>')


def spatial_inertia_matrix(m, c, I_C):
    """Featherstone's 6x6 spatial inertia about the frame's origin, angular rows first."""
    C = rd.hat(c)
    return np.block([[I_C + m * C @ C.T, m * C], [m * C.T, m * np.eye(3)]])


def test_inertial_origin_and_tensor_entries():
    # a floating body at the identity: H is its spatial inertia in the link frame
    tree = rd.load_urdf(single_link())
    assert tree.nq == 7 and tree.nv == 6
    I = np.array([[1.0, 0.1, -0.05], [0.1, 1.2, 0.02], [-0.05, 0.02, 1.4]])  # ixy etc. are matrix entries
    R = rpy_matrix([0.3, -0.2, 0.5])
    expected = spatial_inertia_matrix(2.0, [0.1, 0.2, 0.3], R @ I @ R.T)
    assert close(rd.crba(tree, tree.neutral_configuration()), expected)


def test_a_massless_or_point_mass_link_on_a_fixed_joint_is_welded_into_its_body():
    # a 0.5 kg point mass (zero inertia) at (0, 0, 1) and a frame without inertial, both fixed to the body
    extra = ('<link name="sensor"><inertial><mass value="0.5"/><origin xyz="0 0 0.5"/><inertia ixx="0" iyy="0" '
             'izz="0" ixy="0" ixz="0" iyz="0"/></inertial></link><link name="frame"/>'
             '<joint name="s" type="fixed"><parent link="body"/><child link="sensor"/><origin xyz="0 0 0.5"/></joint>'
             '<joint name="f" type="fixed"><parent link="sensor"/><child link="frame"/><origin xyz="1 0 0"/></joint>')
    tree = rd.load_urdf(single_link(extra=extra))
    assert tree.link_names == ["body"]
    R = rpy_matrix([0.3, -0.2, 0.5])
    I = np.array([[1.0, 0.1, -0.05], [0.1, 1.2, 0.02], [-0.05, 0.02, 1.4]])
    expected = spatial_inertia_matrix(2.0, [0.1, 0.2, 0.3], R @ I @ R.T) + \
        spatial_inertia_matrix(0.5, [0.0, 0.0, 1.0], np.zeros((3, 3)))  # the spatial inertias of welded bodies add
    assert close(rd.crba(tree, tree.neutral_configuration()), expected)


def test_a_link_with_inertia_on_a_fixed_joint_keeps_its_own_link():
    tree = rd.load_urdf(ARM.replace('<link name="tool"/>', '<link name="tool"><inertial><mass value="1.0"/>'
                                    '<inertia ixx="1e-3" iyy="1e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/>'
                                    '</inertial></link>'))
    assert tree.link_names == ["upper", "fore", "tool"] and tree.nv == 1
    _, p, _ = rd.forward_kinematics(tree, [np.pi / 2])
    assert close(p[2], [0.0, 0.0, 0.3 - 0.2])  # the elbow turned the 0.2 m offset along x to -z


def test_a_massless_body_takes_the_mass_of_the_links_fixed_to_it():
    # a massless root `world` fixed to `upper` (with mass), on a floating base: `upper` is welded into it
    text = ARM.replace("<robot name=\"arm\">", '<robot name="arm"><link name="world"/><joint name="mount" '
                       'type="fixed"><parent link="world"/><child link="upper"/><origin xyz="0 0 1"/></joint>')
    floating = rd.load_urdf(text, floating_base=True)
    assert floating.link_names == ["world", "fore"] and floating.parents == [-1, 0]
    direct = rd.load_urdf(ARM, floating_base=True)  # the same body, its frame 1 m lower
    q = direct.neutral_configuration()
    q_world = q.copy()
    q_world[2] = -1.0
    H_world, H = rd.crba(floating, q_world), rd.crba(direct, q)
    assert close(H_world[3:6, 3:6], 3.0 * np.eye(3)) and close(H_world[6:, 6:], H[6:, 6:])
    # the centre of mass (H's block m [c]x) of all of it 1 m higher in `world`'s frame than in `upper`'s
    assert close(rd.vee(H_world[:3, 3:6]) / 3.0, rd.vee(H[:3, 3:6]) / 3.0 + [0.0, 0.0, 1.0])
    # welded to the world, the massless root keeps `upper` as a link of its own
    assert rd.load_urdf(text).link_names == ["upper", "fore"]


def test_floating_base_and_joint_kinds():
    tree = rd.load_urdf(ARM, floating_base=True)
    assert tree.nq == 7 + 1 and tree.nv == 6 + 1
    q = tree.neutral_configuration()
    q[:3] = [1.0, 2.0, 3.0]
    _, p, _ = rd.forward_kinematics(tree, q)
    assert close(p, [[1.0, 2.0, 3.0], [1.0, 2.0, 3.3]])
    prismatic = rd.load_urdf(single_link("prismatic", axis="0 0 2"))
    _, p, _ = rd.forward_kinematics(prismatic, [0.25])
    assert close(p[0], [0.0, 0.0, 0.25])  # the axis normalised


def test_the_root_with_mass_welded_to_the_world_is_a_fixed_link():
    tree = rd.load_urdf(ARM)
    assert tree.parents == [-1, 0]
    # with no mass, the root is the world itself: its children hang from link -1
    assert rd.load_urdf(single_link("revolute")).parents == [-1]


@pytest.mark.parametrize("text, match", [
    (single_link("planar"), r"joint 'j': type 'planar' is not supported"),
    (single_link("screw"), r"joint 'j': type 'screw' is not supported"),
    (single_link("revolute", inertial=""), r"link 'body': expected a mass > 0 .*got no inertial"),
    (single_link("revolute", inertial='<inertial><mass value="0"/></inertial>'), r"link 'body'.*no inertial or mass 0"),
    (single_link("revolute", inertial='<inertial><mass value="-1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" '
                 'ixz="0" iyz="0"/></inertial>'), r"link 'body': expected a finite mass >= 0, got -1.0"),
    (single_link("revolute", inertial='<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="-1" ixy="0" '
                 'ixz="0" iyz="0"/></inertial>'), r"link 'body': expected a positive semi-definite inertia.*-1.0"),
    (single_link("revolute", inertial='<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="0" ixy="0" '
                 'ixz="0" iyz="0"/></inertial>'), r"link 'body': expected a positive-definite inertia.*\[0.0, 1.0, 1.0\]"),
    (single_link("revolute", axis="0 0 0"), r"joint 'j': axis"),
    (single_link("floating").replace('type="floating"', 'type="fixed"').replace("<link name=\"world\"/>", ""),
     r"joint 'j': link 'world' is not declared"),
    (ARM.replace('<joint name="elbow"', '<joint name="again" type="fixed"><parent link="tool"/><child link="fore"/>'
                 '</joint><joint name="elbow"'), r"link 'fore' is the child of joints 'again' and 'elbow': a kinematic loop"),
    (ARM.replace("</robot>", '<joint name="back" type="fixed"><parent link="tool"/><child link="upper"/></joint></robot>'),
     r"expected one root link .*got none: a kinematic loop"),
    (ARM.replace("</robot>", '<link name="other"/></robot>'), r"expected one root link .*\['upper', 'other'\]"),
    (ARM.replace("</robot>", '<link name="fore"/></robot>'), r"links \['fore'\] are declared more than once"),
    ('<robot name="empty"/>', r"expected a robot with at least one <link>, got none"),
    (single_link("revolute", inertial='<inertial><mass value="1"/><inertia ixx="nan" iyy="1" izz="1" ixy="0" '
                 'ixz="0" iyz="0"/></inertial>'), r"link 'body': expected a finite inertia"),
    (ARM.replace('value="2.0"', 'value="heavy"'), r"expected a valid URDF, got one yourdfpy cannot read"),
    (ARM.replace("</robot>", ""), r"expected well-formed URDF XML"),
    ("<sdf/>", r"expected a <robot> root element, got <sdf>"),
])
def test_refusals_name_the_link_or_joint(text, match):
    with pytest.raises(ValueError, match=match):
        rd.load_urdf(text)


def test_a_floating_root_without_mass_is_refused():
    with pytest.raises(ValueError, match=r"link 'world': expected a mass > 0"):
        rd.load_urdf(single_link("revolute"), floating_base=True)


def test_a_missing_file_and_a_wrong_type():
    with pytest.raises(ValueError, match=r"source: expected a URDF file's path .*got 'no_such\.urdf' \(no such file\)"):
        rd.load_urdf("no_such.urdf")
    with pytest.raises(TypeError, match=r"source: expected a path or an XML string, got int"):
        rd.load_urdf(3)
    with pytest.raises(TypeError, match=r"floating_base: expected a bool, got 'yes'"):
        rd.load_urdf(ARM, floating_base="yes")


def test_without_yourdfpy_the_error_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "yourdfpy", None)  # import yourdfpy raises ImportError
    with pytest.raises(ImportError, match=r'pip install "rigiddyn\[urdf\]"'):
        rd.load_urdf(ARM)


def damped_chain(axle="", slide="", hinge=""):
    """A rotor on an axle, a slider on it and a hinged tip, each joint with the <dynamics> tag given."""
    inertial = '<inertial><mass value="1.0"/><inertia ixx="0.1" iyy="0.1" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial>'
    return (f'<robot name="chain"><link name="base"/><link name="rotor">{inertial}</link>'
            f'<link name="slider">{inertial}</link><link name="tip">{inertial}</link>'
            f'<joint name="axle" type="continuous"><parent link="base"/><child link="rotor"/><axis xyz="0 0 1"/>{axle}'
            f'</joint><joint name="slide" type="prismatic"><parent link="rotor"/><child link="slider"/>'
            f'<axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>{slide}</joint>'
            f'<joint name="hinge" type="revolute"><parent link="slider"/><child link="tip"/><axis xyz="0 1 0"/>'
            f'<limit lower="-1" upper="1" effort="1" velocity="1"/>{hinge}</joint></robot>')


def test_joint_dampers_are_read_from_the_dynamics_tags():
    text = damped_chain(axle='<dynamics damping="0.04"/>', slide='<dynamics damping="2.5" friction="0.0"/>')
    tree = rd.load_urdf(text)
    scene = rd.Scene(bodies=[rd.Particle(1.0)])
    links = scene.add_tree(tree, "chain")
    assert links == (1, 2, 3)
    dampers = rd.urdf_joint_dampers(text, tree, links)
    # one per joint with damping > 0, on its child link's body, in joint order (the hinge has no <dynamics>)
    assert dampers == [rd.RevoluteSpringDamper(body=1, stiffness=0.0, rest_angle=0.0, damping=0.04),
                       rd.PrismaticSpringDamper(body=2, stiffness=0.0, rest_position=0.0, damping=2.5)]


def test_a_damped_axle_slows_as_its_closed_form():
    text = damped_chain(axle='<dynamics damping="0.04"/>')
    tree = rd.load_urdf(text)
    scene = rd.Scene()
    for damper in rd.urdf_joint_dampers(text, tree, scene.add_tree(tree, "chain")):
        scene.add(damper)
    # the links beyond the axle at rest on it, slider and tip on the axis: I about the axle = 3 × 0.2 kg m²;
    # ω(t) = ω0 exp(−c t / I). RK4 on the linear ω' = −λω: local error (hλ)⁵/120 |ω| a step, plus a few roundings
    dt, steps, c, inertia = 0.01, 500, 0.04, 0.6
    run = rd.simulate(scene, tree.joint_states([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), dt, steps, method="rk4", error=False)
    exact = np.exp(-c * run.t / inertia)
    bound = steps * ((dt * c / inertia) ** 5 / 120.0 + 8 * np.finfo(float).eps)
    assert np.max(np.abs(run.joint_v[:, 0] - exact)) <= bound
    assert run.balance.verdict["energy"] == "closed"  # the kinetic energy lost is the damper's work


@pytest.mark.parametrize("tags, kwargs, match", [
    (dict(slide='<dynamics damping="0.1" friction="0.3"/>'), {},
     r"joint 'slide': friction 0\.3 \(Coulomb friction\) is not modelled; give friction='ignore'"),
    (dict(axle='<dynamics damping="-0.1"/>'), {}, r"joint 'axle': expected a <dynamics> damping >= 0, got -0\.1"),
    (dict(hinge='<dynamics damping="nan"/>'), {}, r"joint 'hinge': expected a <dynamics> damping >= 0, got nan"),
    (dict(hinge='<dynamics friction="-1"/>'), dict(friction="ignore"),
     r"joint 'hinge': expected a <dynamics> friction >= 0, got -1\.0"),
    ({}, dict(friction="drop"), r"friction: expected 'refuse' or 'ignore', got 'drop'"),
])
def test_joint_damper_refusals_name_the_joint(tags, kwargs, match):
    text = damped_chain(**tags)
    tree = rd.load_urdf(text)
    with pytest.raises(ValueError, match=match):
        rd.urdf_joint_dampers(text, tree, (0, 1, 2), **kwargs)


def test_friction_is_left_out_only_when_asked():
    text = damped_chain(slide='<dynamics damping="0.1" friction="0.3"/>')
    dampers = rd.urdf_joint_dampers(text, rd.load_urdf(text), (0, 1, 2), friction="ignore")
    assert dampers == [rd.PrismaticSpringDamper(body=1, stiffness=0.0, rest_position=0.0, damping=0.1)]


def test_joint_dampers_need_the_trees_links():
    text = damped_chain(axle='<dynamics damping="0.04"/>')
    tree = rd.load_urdf(text)
    with pytest.raises(ValueError, match=r"links: expected the 3 bodies Scene.add_tree returned for the tree's links, "
                                         r"got 2 \(\(0, 1\)\)"):
        rd.urdf_joint_dampers(text, tree, (0, 1))
    with pytest.raises(ValueError, match=r"joint 'axle': its child link 'rotor' is not a link of the tree "
                                         r"\(links \['upper', 'fore'\]\)"):
        rd.urdf_joint_dampers(text, rd.load_urdf(ARM), (0, 1))
    with pytest.raises(TypeError, match=r"tree: expected the Tree load_urdf returned, got str"):
        rd.urdf_joint_dampers(text, text, (0, 1, 2))
    floating = single_link("floating", inertial=None).replace('<axis xyz="1 0 0"/>', '<dynamics damping="0.2"/>')
    with pytest.raises(ValueError, match=r"joint 'j': expected damping only in a revolute, continuous or prismatic "
                                         r"joint, got damping 0\.2 in a 'floating' joint"):
        rd.urdf_joint_dampers(floating, rd.load_urdf(floating), (0,))
