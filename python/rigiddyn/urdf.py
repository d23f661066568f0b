"""URDF robot descriptions as kinematic trees: ``load_urdf(path_or_xml)`` returns a rigiddyn.Tree, and
``urdf_joint_dampers(path_or_xml, tree, links)`` the viscous dampers of its joints as scene elements.

The file is parsed by yourdfpy (the ``urdf`` extra: ``pip install "rigiddyn[urdf]"``), imported only
when a URDF is read. What is read, and how (ROS, "URDF XML specification", wiki.ros.org/urdf/XML):

- ``<link>``: its ``<inertial>`` (mass [kg]; ``origin``, the centre of mass and the axes of the inertia
  tensor in the link frame; ``inertia``, the tensor's entries [kg m²] about the centre of mass). URDF's
  ``ixy``, ``ixz``, ``iyz`` are entries of the matrix (the negated products of inertia, as rigiddyn's
  ``inertia_com``). Visual and collision geometry (meshes) is never read.
- ``<joint>``: ``origin`` is the joint frame in the parent link's frame (the placement X_T; ``rpy`` is
  roll-pitch-yaw about the fixed axes, R = Rz(yaw) Ry(pitch) Rx(roll)); the child link's frame is the joint
  frame moved by the joint. ``revolute`` and ``continuous`` become a RevoluteJoint, ``prismatic`` a
  PrismaticJoint (``axis`` in the joint frame, default (1, 0, 0)), ``floating`` a FreeJoint and ``fixed`` a
  FixedJoint. Limits, calibration and mimic tags do not enter the dynamics: a mimic joint is loaded as an
  independent joint. ``<dynamics damping>`` (N m s/rad for a revolute joint, N s/m for a prismatic one) is not part
  of the Tree: ``urdf_joint_dampers`` makes it a RevoluteSpringDamper or PrismaticSpringDamper of stiffness 0 in a
  scene; ``<dynamics friction>`` (Coulomb friction) is not modelled, refused unless left out explicitly.

Links without mass: every link that a joint moves needs a positive-definite inertia (the Tree's rule). A
link on a fixed joint is welded into the body it is fixed to when its own inertia is not positive definite
(no ``<inertial>``, mass 0, or a point mass, as URDF's tool frames and sensor frames), or when that body's
own inertia is not (a massless link carrying its mass on fixed links, as a ``world`` link fixed to a
``base_link``): its mass, if any, is added to that body's, and its children are attached to that body
through it. It has no link of its own in the tree. The root link is fixed to the world (or, with
``floating_base=True``, joined to it by a FreeJoint at the world's origin); welded into the world, its
mass drops out of the dynamics.
"""

from __future__ import annotations

import io
import os
import reprlib
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from ._core import (FixedJoint, FreeJoint, InertiaCheck, PrismaticJoint, PrismaticSpringDamper, RevoluteJoint,
                    RevoluteSpringDamper, SpatialInertia, Transform, Tree, composite)

__all__ = ["load_urdf", "urdf_joint_dampers", "JOINT_TYPES"]

# URDF joint type -> the rigiddyn joint it becomes
JOINT_TYPES = {"revolute": "RevoluteJoint", "continuous": "RevoluteJoint", "prismatic": "PrismaticJoint",
               "floating": "FreeJoint", "fixed": "FixedJoint"}

Part = Tuple[Transform, SpatialInertia]  # a welded part: its frame in the body's frame, its mass properties


def _yourdfpy() -> Any:
    try:
        import yourdfpy
    except ImportError as error:
        raise ImportError('load_urdf needs yourdfpy: pip install "rigiddyn[urdf]" (or pip install yourdfpy)') from error
    return yourdfpy


def _read(source: Union[str, "os.PathLike[str]"]) -> Any:
    """The URDF's robot element (yourdfpy.Robot) from a path or an XML string; strict XML."""
    yourdfpy = _yourdfpy()
    from lxml import etree  # a dependency of yourdfpy

    if isinstance(source, str) and source.lstrip().startswith("<"):
        text = source.encode()
    elif isinstance(source, (str, os.PathLike)):
        if not os.path.isfile(source):
            raise ValueError(f"source: expected a URDF file's path or URDF XML (starting with '<'), got "
                             f"{os.fspath(source)!r} (no such file)")
        with open(source, "rb") as f:
            text = f.read()
    else:
        raise TypeError(f"source: expected a path or an XML string, got {type(source).__name__}")
    try:
        root = etree.fromstring(text)
    except etree.XMLSyntaxError as error:
        raise ValueError(f"source: expected well-formed URDF XML, got a syntax error: {error}") from None
    if root.tag != "robot":
        raise ValueError(f"source: expected a <robot> root element, got <{root.tag}>")
    try:
        return yourdfpy.URDF.load(io.BytesIO(text), build_scene_graph=False, build_collision_scene_graph=False,
                                  load_meshes=False, load_collision_meshes=False).robot
    except (AttributeError, KeyError, TypeError, ValueError) as error:  # a required tag or attribute missing
        raise ValueError(f"source: expected a valid URDF, got one yourdfpy cannot read ({error!r})") from None


def _structure(robot: Any) -> Tuple[str, Dict[str, List[Any]]]:
    """The root link and each link's child joints (in file order); refuses several roots and loops."""
    names = [link.name for link in robot.links]
    if not names:
        raise ValueError("source: expected a robot with at least one <link>, got none")
    twice = sorted({name for name in names if names.count(name) > 1})
    if twice:
        raise ValueError(f"links {twice} are declared more than once: expected unique link names")
    children: Dict[str, List[Any]] = {name: [] for name in names}
    parent_joint: Dict[str, str] = {}
    for joint in robot.joints:
        for end in (joint.parent, joint.child):
            if end not in children:
                raise ValueError(f"joint {joint.name!r}: link {end!r} is not declared")
        if joint.child in parent_joint:
            raise ValueError(f"link {joint.child!r} is the child of joints {parent_joint[joint.child]!r} and "
                             f"{joint.name!r}: a kinematic loop (a tree has one parent per link)")
        parent_joint[joint.child] = joint.name
        children[joint.parent].append(joint)
    roots = [name for name in names if name not in parent_joint]
    if len(roots) != 1:
        raise ValueError(f"expected one root link (a link no joint has as child), got {roots or 'none'}"
                         + (": a kinematic loop" if not roots else ""))
    reached, stack = set(), [roots[0]]
    while stack:
        reached.add(stack[-1])
        stack.extend(joint.child for joint in children[stack.pop()])
    if len(reached) != len(names):
        cycle = [name for name in names if name not in reached]
        raise ValueError(f"links {cycle} are not reached from the root {roots[0]!r}: a kinematic loop")
    return roots[0], children


def _transform(origin: Optional[np.ndarray], what: str) -> Transform:
    """An <origin> (yourdfpy's 4x4 matrix of xyz and rpy; None: identity) as a Transform."""
    if origin is None:
        return Transform()
    if not np.all(np.isfinite(origin)):
        raise ValueError(f"{what}: expected a finite origin, got {origin[:3].tolist()}")
    return Transform(origin[:3, :3], origin[:3, 3])


def _mass_properties(link: Any) -> Optional[SpatialInertia]:
    """The link's inertial in the link frame (None: no inertial or mass 0); refuses a non-PSD tensor."""
    inertial = link.inertial
    if inertial is None or inertial.mass is None or inertial.mass == 0.0:
        return None
    m = float(inertial.mass)
    I = np.zeros((3, 3)) if inertial.inertia is None else np.asarray(inertial.inertia, dtype=float)
    if not (np.isfinite(m) and m > 0.0):
        raise ValueError(f"link {link.name!r}: expected a finite mass >= 0, got {m}")
    X_LC = _transform(inertial.origin, f"link {link.name!r} inertial")  # C: the inertia frame at the centre of mass
    if not np.all(np.isfinite(I)):
        raise ValueError(f"link {link.name!r}: expected a finite inertia [kg m²], got {I.tolist()}")
    if np.linalg.eigvalsh(I).min() < 0.0:
        raise ValueError(f"link {link.name!r}: expected a positive semi-definite inertia [kg m²], got {I.tolist()} "
                         f"(principal moments {np.linalg.eigvalsh(I).tolist()})")
    # I_C in the link's axes: R_LC I R_LC^T
    R_LC = X_LC.rotation
    return SpatialInertia(m, X_LC.translation, R_LC @ I @ R_LC.T, check=InertiaCheck.allow_unrealizable)


def _positive_definite(inertia: Optional[SpatialInertia]) -> bool:
    return inertia is not None and bool(np.linalg.eigvalsh(inertia.inertia_com).min() > 0.0)


def _joint(joint: Any) -> Any:
    """The rigiddyn joint of a URDF joint (not fixed); refuses the types rigiddyn has no joint for."""
    kind = joint.type
    if kind not in JOINT_TYPES:
        raise ValueError(f"joint {joint.name!r}: type {kind!r} is not supported (expected one of "
                         f"{sorted(JOINT_TYPES)})")
    if kind == "floating":
        return FreeJoint()
    axis = np.array([1.0, 0.0, 0.0]) if joint.axis is None else np.asarray(joint.axis, dtype=float)
    try:
        return RevoluteJoint(axis) if kind in ("revolute", "continuous") else PrismaticJoint(axis)
    except ValueError as error:
        raise ValueError(f"joint {joint.name!r}: {error}") from None


def load_urdf(source: Union[str, "os.PathLike[str]"], floating_base: bool = False,
              gravity: Optional[Any] = None) -> Tree:
    """A kinematic tree from a URDF robot description.

    Each URDF link that a joint moves becomes a link of the tree, named as in the file, with its
    ``<inertial>`` as its SpatialInertia in the link frame; each joint's ``origin`` becomes the placement
    X_T of the joint frame in the parent link's frame (``rpy``: R = Rz(yaw) Ry(pitch) Rx(roll)), its
    ``axis`` the joint's axis in the joint frame. Links are added depth first from the root, children in
    file order. Joint limits, damping, friction and mimic tags are not used (a mimic joint is an independent
    joint), nor is any geometry. The module rigiddyn.urdf states the mapping in full.

    Massless links: a link on a fixed joint whose own inertia is not positive definite (no inertial, mass 0
    or a point mass: tool and sensor frames), or that is fixed to a body whose own inertia is not, is welded
    into that body (its mass, if any, added to the body's) and has no link of its own; every other link
    needs a positive-definite inertia after that. The root is fixed to the world, or joined to it by a FreeJoint with ``floating_base=True``.

    Parameters
    ----------
    source : str or os.PathLike
        A URDF file's path, or the URDF XML itself (a string starting with ``<``).
    floating_base : bool, default False
        Join the root link to the world by a FreeJoint (q: position [m] and unit quaternion (x, y, z, w) of
        the root's frame in W; v: [w; v] in the root's frame); False welds the root to the world.
    gravity : array_like, shape (3,), optional
        Uniform gravity g [m/s²] in W, as Tree's (None: none; URDF does not state one).

    Returns
    -------
    Tree
        Links in depth-first order; q and v stack each moving joint's coordinates in that order (a URDF
        continuous joint has one angle [rad]).

    Raises
    ------
    ImportError
        yourdfpy is not installed (``pip install "rigiddyn[urdf]"``).
    TypeError
        `source` neither a str nor a path; `floating_base` not a bool.
    ValueError
        No file at the path; not well-formed XML or not a URDF; a joint type other than revolute, continuous, prismatic,
        floating or fixed (planar is refused), naming the joint; several roots or a kinematic loop, naming
        the links; a negative mass or an inertia tensor that is not positive semi-definite, naming the link
        and the value; a moving link (or the floating root) without a positive-definite inertia, naming it.

    See Also
    --------
    Tree, rnea, crba, aba, forward_kinematics

    Examples
    --------
    A forearm hinged about y, 0.3 m up a post fixed to the world, with a massless tool frame at its end
    (welded into the forearm):

    >>> arm = '''<robot name="arm">
    ...   <link name="upper"><inertial><mass value="2.0"/><origin xyz="0 0 0.15"/>
    ...     <inertia ixx="0.02" iyy="0.02" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial></link>
    ...   <link name="fore"><inertial><mass value="1.0"/><origin xyz="0.1 0 0"/>
    ...     <inertia ixx="0.001" iyy="0.004" izz="0.004" ixy="0" ixz="0" iyz="0"/></inertial></link>
    ...   <link name="tool"/>
    ...   <joint name="elbow" type="continuous"><parent link="upper"/><child link="fore"/>
    ...     <origin xyz="0 0 0.3" rpy="0 0 0"/><axis xyz="0 1 0"/></joint>
    ...   <joint name="tool_mount" type="fixed"><parent link="fore"/><child link="tool"/>
    ...     <origin xyz="0.2 0 0"/></joint>
    ... </robot>'''
    >>> tree = rd.load_urdf(arm, gravity=[0.0, 0.0, -9.81])
    >>> tree.link_names, tree.nq
    (['upper', 'fore'], 1)
    >>> rd.rnea(tree, [0.0], [0.0], [0.0]).round(12)  # holds the 1 kg forearm level, 0.1 m out
    array([-0.981])
    """
    if not isinstance(floating_base, (bool, np.bool_)):
        raise TypeError(f"floating_base: expected a bool, got {floating_base!r}")
    robot = _read(source)
    root, children = _structure(robot)
    links = {link.name: link for link in robot.links}
    tree = Tree(gravity=gravity)

    # depth first: each URDF link is a body of the tree or welded into one, its host, at X_HL
    bodies: List[Tuple[str, int, Any, Transform]] = []  # (name, parent body, joint, X_T)
    parts: List[List[Part]] = []                        # each body's welded parts (its own first)
    host: Dict[str, Tuple[int, Transform]] = {}
    own_definite: List[bool] = []                       # each body's own inertia positive definite
    stack: List[Tuple[str, Optional[Any]]] = [(root, None)]
    while stack:
        name, joint = stack.pop()
        own = _mass_properties(links[name])
        if joint is None:  # the root, at the world's origin
            parent, X_HJ, kind = -1, Transform(), "floating" if floating_base else "fixed"
        else:
            parent, X_HP = host[joint.parent]
            X_HJ, kind = X_HP * _transform(joint.origin, f"joint {joint.name!r}"), joint.type
        # welded: fixed, and either without a positive-definite inertia or fixed to a body without one
        if kind == "fixed" and not (_positive_definite(own) and (parent < 0 or own_definite[parent])):
            host[name] = (parent, X_HJ)
            if own is not None and parent >= 0:
                parts[parent].append((X_HJ, own))
        else:
            rd_joint = FixedJoint() if kind == "fixed" else FreeJoint() if joint is None else _joint(joint)
            host[name] = (len(bodies), Transform())
            bodies.append((name, parent, rd_joint, X_HJ))
            parts.append([] if own is None else [(Transform(), own)])
            own_definite.append(_positive_definite(own))
        stack.extend((child.child, child) for child in reversed(children[name]))

    for (name, parent, rd_joint, X_T), body_parts in zip(bodies, parts):
        tree.add_link(name, parent, rd_joint, _body_inertia(name, body_parts), X_T)
    return tree


def _body_inertia(name: str, body_parts: List[Part]) -> SpatialInertia:
    """The composite of a body's parts (Craig's parallel-axis theorem), refused unless positive definite."""
    if not body_parts:
        raise ValueError(f"link {name!r}: expected a mass > 0 (a link that moves needs one), got no inertial "
                         "or mass 0")
    inertia = composite(body_parts)
    moments = np.linalg.eigvalsh(inertia.inertia_com)
    if moments.min() <= 0.0:
        raise ValueError(f"link {name!r}: expected a positive-definite inertia (a link that moves needs one), got "
                         f"principal moments {moments.tolist()} [kg m²] about its centre of mass")
    return inertia


def _dynamics(joint: Any, field: str) -> float:
    """A URDF joint's <dynamics> `field` ("damping" or "friction"; 0 where absent), refused unless finite and >= 0."""
    value = getattr(joint.dynamics, field, None) if joint.dynamics is not None else None
    value = 0.0 if value is None else float(value)
    if not np.isfinite(value) or value < 0.0:
        raise ValueError(f"joint {joint.name!r}: expected a <dynamics> {field} >= 0, got {value!r}")
    return value


def urdf_joint_dampers(source: Union[str, "os.PathLike[str]"], tree: Tree, links: Sequence[int],
                       friction: str = "refuse") -> List[Any]:
    """The viscous dampers of a URDF's joints, as scene elements on the links of its tree in a scene.

    URDF's ``<dynamics damping="c"/>`` in a revolute or continuous joint is the joint torque τ = −c q̇ [N m]
    (c in N m s/rad), in a prismatic joint the force τ = −c q̇ [N] (c in N s/m): each joint with c > 0 gives a
    RevoluteSpringDamper or PrismaticSpringDamper of stiffness 0 on its child link's body, in joint order.
    ``<dynamics friction>`` is Coulomb friction, which rigiddyn does not model: a joint with friction > 0 is
    refused unless ``friction="ignore"`` leaves it out.

    Parameters
    ----------
    source : str or os.PathLike
        The URDF the tree was loaded from: a file's path, or the XML itself (a string starting with ``<``).
    tree : Tree
        The tree ``load_urdf(source, ...)`` returned (its links are named after the URDF's links).
    links : sequence of int
        The scene's bodies of the tree's links, in link order: what ``Scene.add_tree(tree, name)`` returned.
    friction : {"refuse", "ignore"}, default "refuse"
        What to do with a joint whose friction is > 0: refuse it (ValueError naming the joint), or leave the
        friction out of the dynamics.

    Returns
    -------
    list of RevoluteSpringDamper and PrismaticSpringDamper
        One per revolute, continuous or prismatic joint with damping > 0, in the file's joint order; add each to
        the scene (``scene.add(damper)``).

    Raises
    ------
    ImportError
        yourdfpy is not installed (``pip install "rigiddyn[urdf]"``).
    TypeError
        `source` neither a str nor a path; `tree` not a Tree; `links` not a sequence of ints.
    ValueError
        No file at the path, or not a URDF (as load_urdf); `links` not one body per link of `tree`; a joint whose
        child is not a link of `tree` (another URDF); a damping or friction that is negative or not finite, damping
        on a floating joint (naming the joint); a friction > 0 with ``friction="refuse"``, naming the joint and the
        value; an unknown `friction`.

    See Also
    --------
    load_urdf, RevoluteSpringDamper, PrismaticSpringDamper

    Examples
    --------
    A flywheel on a damped axle (I = 0.2 kg m² about it), spun at 1 rad/s, slows as exp(−c t / I):

    >>> wheel = '''<robot name="wheel"><link name="base"/>
    ...   <link name="rotor"><inertial><mass value="1.0"/>
    ...     <inertia ixx="0.1" iyy="0.1" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial></link>
    ...   <joint name="axle" type="continuous"><parent link="base"/><child link="rotor"/>
    ...     <axis xyz="0 0 1"/><dynamics damping="0.04" friction="0"/></joint></robot>'''
    >>> tree = rd.load_urdf(wheel)
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "wheel")
    >>> [scene.add(damper) for damper in rd.urdf_joint_dampers(wheel, tree, links)]
    [0]
    >>> scene.elements[0]
    RevoluteSpringDamper(body=0, stiffness=0.0, rest_angle=0.0, damping=0.04)
    >>> run = rd.simulate(scene, tree.joint_states([0.0], [1.0]), 0.01, duration=5.0, error=False)
    >>> print(f"{run.joint_v[-1, 0]:.6f} rad/s; exp(-0.2 * 5) = {np.exp(-1.0):.6f}")
    0.367879 rad/s; exp(-0.2 * 5) = 0.367879
    """
    if friction not in ("refuse", "ignore"):
        raise ValueError(f"friction: expected 'refuse' or 'ignore', got {friction!r}")
    if not isinstance(tree, Tree):
        raise TypeError(f"tree: expected the Tree load_urdf returned, got {type(tree).__name__}")
    if not isinstance(links, (Sequence, np.ndarray)) or isinstance(links, str):
        raise TypeError(f"links: expected the body indices (ints) Scene.add_tree returned, got {links!r}")
    if len(links) != tree.num_links:  # (before any copy of the sequence)
        raise ValueError(f"links: expected the {tree.num_links} bodies Scene.add_tree returned for the tree's links, "
                         f"got {len(links)} ({reprlib.repr(links)})")
    bodies = list(links)
    if not all(isinstance(b, (int, np.integer)) and not isinstance(b, bool) for b in bodies):
        raise TypeError(f"links: expected the body indices (ints) Scene.add_tree returned, got {links!r}")
    robot = _read(source)
    names = tree.link_names
    dampers = []
    for joint in robot.joints:
        damping, joint_friction = _dynamics(joint, "damping"), _dynamics(joint, "friction")
        if joint_friction > 0.0 and friction == "refuse":
            raise ValueError(f"joint {joint.name!r}: friction {joint_friction!r} (Coulomb friction) is not modelled; "
                             "give friction='ignore' to leave it out of the dynamics")
        if damping == 0.0 or joint.type == "fixed":
            continue
        if joint.type not in ("revolute", "continuous", "prismatic"):
            raise ValueError(f"joint {joint.name!r}: expected damping only in a revolute, continuous or prismatic "
                             f"joint, got damping {damping!r} in a {joint.type!r} joint")
        if joint.child not in names:
            raise ValueError(f"joint {joint.name!r}: its child link {joint.child!r} is not a link of the tree "
                             f"(links {names}): expected the tree load_urdf returned for this URDF")
        body = bodies[names.index(joint.child)]
        dampers.append(PrismaticSpringDamper(body=body, stiffness=0.0, rest_position=0.0, damping=damping)
                       if joint.type == "prismatic" else
                       RevoluteSpringDamper(body=body, stiffness=0.0, rest_angle=0.0, damping=damping))
    return dampers
