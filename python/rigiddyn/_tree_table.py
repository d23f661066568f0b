"""A scene file's [[tree]] tables: a kinematic tree whose links become bodies of the scene (Scene.add_tree), read and
written (rigiddyn.scene_file); rigiddyn.scene_file's docstring lists the keys.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from . import _core
from ._core_call import core_call
from ._mass_properties import inertia_matrix
from ._names import check_keys
from .units import _floats, quantity, vector_quantity

__all__ = ["TREE_KEYS", "LINK_KEYS", "JOINTS", "read_tree", "tree_table"]

TREE_KEYS = frozenset({"name", "link"})
LINK_KEYS = frozenset({"name", "parent", "joint", "axis", "translation", "rotation", "mass", "com", "inertia", "q", "v"})
JOINTS = {"revolute": "RevoluteJoint", "prismatic": "PrismaticJoint", "spherical": "SphericalJoint",
          "free": "FreeJoint", "fixed": "FixedJoint"}
# each joint's neutral configuration (an angle or offset 0, an identity quaternion)
_NEUTRAL = {"revolute": np.zeros(1), "prismatic": np.zeros(1), "spherical": np.array([0.0, 0.0, 0.0, 1.0]),
            "free": np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0]), "fixed": np.zeros(0)}
# the units of a joint's q and v entries (None: a quaternion's components, plain numbers)
_UNITS: dict[str, tuple[Sequence[str | None], Sequence[str | None]]] = {
    "revolute": (["rad"], ["rad/s"]), "prismatic": (["m"], ["m/s"]), "spherical": ([None] * 4, ["rad/s"] * 3),
    "free": (["m"] * 3 + [None] * 4, ["rad/s"] * 3 + ["m/s"] * 3), "fixed": ([], [])}


def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {got!r}")


def _entries(value: Any, name: str, units: Sequence[str | None]) -> np.ndarray:
    """len(units) entries of a joint's q or v, each in its unit (None: a plain number)."""
    if not isinstance(value, (list, tuple)) or len(value) != len(units):
        raise _fail(name, f"{len(units)} entries", value)
    return np.array([quantity(x, f"{name}[{i}]", unit or "1") for i, (x, unit) in enumerate(zip(value, units))])


def _joint(table: Mapping[str, Any], name: str) -> tuple[str, Any]:
    kind = table.get("joint")
    if kind not in JOINTS:
        raise _fail(f"{name}.joint", "one of " + ", ".join(map(repr, JOINTS)), kind)
    axial = kind in ("revolute", "prismatic")
    if axial != ("axis" in table):
        raise ValueError(f"{name}.axis: expected " + ("an axis for a " if axial else "none for a ") + f"{kind} joint")
    cls = getattr(_core, JOINTS[kind])
    joint = core_call(cls, name, vector_quantity(table["axis"], f"{name}.axis", "1")) if axial else cls()
    return kind, joint


def _rotation(value: Any, name: str) -> np.ndarray:
    """R of a placement: a unit quaternion (x, y, z, w), a 3x3 rotation matrix (as written: it reads back bit for
    bit), or None (the identity)."""
    if value is None:
        return np.eye(3)
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        a = np.zeros(0)
    if a.shape == (4,):
        return np.asarray(core_call(_core.quat_to_matrix, name, a, keys={"q": ""}), dtype=np.float64)
    if a.shape == (3, 3):
        return a
    raise _fail(name, "a unit quaternion (x, y, z, w) or a 3x3 rotation matrix", value)


def _link(table: Any, name: str, links: Mapping[str, int]) -> tuple[str, int, str, Any, Any, Any]:
    """(name, parent index, joint kind, joint, inertia, placement) of a [[tree.link]] table."""
    table = check_keys(table, name, LINK_KEYS, "a [[tree.link]] table")
    link_name = table.get("name")
    if not isinstance(link_name, str) or not link_name:
        raise _fail(f"{name}.name", "a non-empty string", link_name)
    parent = table.get("parent")
    if parent is not None and parent not in links:
        raise _fail(f"{name}.parent", "the name of a link above it (parents first; absent: the world)", parent)
    kind, joint = _joint(table, name)
    mass = quantity(table.get("mass"), f"{name}.mass", "kg", positive=True)
    com = vector_quantity(table.get("com", [0.0, 0.0, 0.0]), f"{name}.com", "m")
    inertia = core_call(_core.SpatialInertia, name, mass, com, inertia_matrix(table.get("inertia"), f"{name}.inertia"))
    placement = core_call(_core.Transform, name, _rotation(table.get("rotation"), f"{name}.rotation"),
                          vector_quantity(table.get("translation", [0.0, 0.0, 0.0]), f"{name}.translation", "m"))
    return link_name, -1 if parent is None else links[parent], kind, joint, inertia, placement


def read_tree(table: Any, k: int) -> tuple[str | None, Any, list[Any]]:
    """(name or None, Tree, the links' JointStates) of the [[tree]] table number k."""
    name = f"tree[{k}]"
    table = check_keys(table, name, TREE_KEYS, "a [[tree]] table")
    prefix = table.get("name")
    if prefix is not None and (not isinstance(prefix, str) or not prefix):
        raise _fail(f"{name}.name", "a non-empty string", prefix)
    tables = table.get("link")
    if not isinstance(tables, list) or not tables:
        raise _fail(f"{name}.link", "one [[tree.link]] table per link", tables)
    tree, links, states = _core.Tree(), dict[str, int](), []
    for i, link_table in enumerate(tables):
        link_name = f"{name}.link[{i}]"
        if not isinstance(link_table, Mapping):
            raise _fail(link_name, "a [[tree.link]] table", link_table)
        named, parent, kind, joint, inertia, placement = _link(link_table, link_name, links)
        links[named] = core_call(tree.add_link, link_name, named, parent, joint, inertia, placement)
        units_q, units_v = _UNITS[kind]
        q = _entries(link_table["q"], f"{link_name}.q", units_q) if "q" in link_table else _NEUTRAL[kind]
        v = _entries(link_table["v"], f"{link_name}.v", units_v) if "v" in link_table else np.zeros(len(units_v))
        states.append(core_call(_core.JointState, link_name, q, v))
    return prefix, tree, states


def tree_table(prefix: str | None, tree: Any, states: Sequence[Any] | None) -> dict[str, Any]:
    """The [[tree]] table of `tree` (its bodies named with `prefix`), with its links' states (None: none written)."""
    names, kinds = tree.link_names, {cls: kind for kind, cls in JOINTS.items()}
    links = []
    for i, (parent, joint, inertia, placement) in enumerate(zip(tree.parents, tree.joints, tree.inertias,
                                                                tree.placements)):
        kind = kinds[type(joint).__name__]
        link: dict[str, Any] = {"name": names[i]}
        if parent >= 0:
            link["parent"] = names[parent]
        link["joint"] = kind
        if kind in ("revolute", "prismatic"):
            link["axis"] = _floats(joint.axis)
        link.update({"translation": _floats(placement.translation),
                     "rotation": _floats(placement.rotation),
                     "mass": float(inertia.mass), "com": _floats(inertia.com), "inertia": _floats(inertia.inertia_com)})
        if states is not None:
            link.update({"q": _floats(states[i].q), "v": _floats(states[i].v)})
        links.append(link)
    return ({} if prefix is None else {"name": prefix}) | {"link": links}
