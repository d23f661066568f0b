"""TOML scene files: bodies, force elements (bodies named), initial states and run options, with units.

``load_scene(path_or_text)`` returns a SceneFile, which unpacks as ``scene, initial, run``: a rigiddyn.Scene, the
list of initial states (ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, PivotedPlanarBodyState,
GyrostatState or a tree link's JointState, one per body, in file order) and a RunOptions;
``load_scene("kepler")`` reads a shipped scene (``example_scenes()``). ``scene_to_toml(scene, initial,
run)`` writes the canonical file (SI, radians, q_WB, every field explicit) that loads back to the same
scene, states and options.

Every number may carry a unit as a string, a number then its unit and nothing else (rigiddyn.units;
pint's registry gives the unit names): ``"2 slug"``, ``"3 ft"``, ``"30 deg"``, ``"1500 rpm"``,
``"398600.4418 km^3/s^2"``, ``"6.6743e-8 cm^3/(g*s^2)"``, ``"1_000 kg"``; a plain number is SI in the
unit shown below. The number is written as TOML writes one (a decimal point, never a comma: ``"1,5 kg"``
is refused; underscores only between digits); the unit is names joined by ``*``, ``/`` or a space, with
powers ``^`` or ``**`` of literal numbers and parentheses; a comment goes after the closing quote
(``mass = "2 kg"  # dry``: a ``#`` inside the string is refused). A vector is ``[x, y, z]`` (each entry
may carry a unit) or ``{value = [x, y, z], unit = "km"}``. Every key the format knows (alternatives
commented)::

    name = "two-body Kepler orbit"      # optional (default: the file name)
    description = "free text"           # optional

    [run]                               # optional; every key optional
    method = "rk4"                      # default "rk4"; one of rigiddyn.methods()
    dt = "10 s"                         # [s] > 0 (no default: simulate needs it)
    duration = "2 h"                    # [s] > 0 (no default: simulate needs it)
    record_every = 1                    # integer >= 1 (default 1)

    [tradeoff]                          # optional defaults of rigiddyn.tradeoff on this scene
    methods = ["rk4", "splitting_dlm"]  # names of rigiddyn.methods() (default: all)
    dts = ["1 ms", "0.5 ms"]            # steps [s]
    horizon = "2 s"                     # [s] (default: the [run] duration)
    tolerance = 1e-6                    # of measure, for the recommendation
    measure = "final_state_error"       # one of rigiddyn.work_precision.MEASURES

    [frame]                             # optional: the frame F the states are relative to (absent: W,
    kind = "rotating"                   # inertial); "rotating": axis (any length, in F = W at t = 0)
    axis = [0, 0, 1]                    # and rate [rad/s] about it through the origin; or
    rate = "1 rpm"                      # kind = "earth", latitude = "48.85 deg": the local frame (x east,
                                        # y north, z up) turning at 7.2921159e-5 rad/s with the Earth

    [[body]]                            # one table per body, in index order
    name = "sat"                        # optional, unique (default "body<i>"); forces refer to it
    kind = "rigid"                      # "particle" | "planar" | "rigid" | "pivoted" | "pivoted_planar" |
                                        # "gyrostat"
    mass = "2 slug"                     # [kg] > 0
    inertia = [1, 2, 3]                 # rigid: principal moments or a 3x3 [[..], [..], [..]] [kg m^2]
                                        # about the centre of mass in B; planar: I_zz [kg m^2]
    inertia_check = "physical"          # rigid only: "physical" (default) | "allow_unrealizable"
    p_W = [7000, 0, 0]                  # [m] in W (planar: [x, y]); default 0
    v_W = [0, 7.5, 0]                   # [m/s] in W (planar: [vx, vy]); default 0
    w_B = {value = [0, 0, 3000], unit = "rpm"}   # rigid: [rad/s] in B; default 0
    q_WB = [0, 0, 0, 1]                 # rigid: attitude B to W, (x, y, z, w); or one of (as in
    # scalar_first = true               # problem files, rigiddyn.problem; angles may carry units):
    # euler = {seq = "ZYX", angles = ["30 deg", 0, 0]}
    # rotvec = [0, 0, 0.5]              # angle * axis [rad]
    # axis_angle = {axis = [0, 0, 1], angle = "30 deg"}
    # theta = "30 deg"                  # planar: angle about z [rad]; default 0
    # omega = "60 rpm"                  # planar: rate about z [rad/s]; default 0
    # p_OC_B = [0, 0, 0.1]              # pivoted (pinned at a point O fixed in the scene frame; the
    # p_WO = [0, 0, 0]                  # fields of "rigid" but p_W, v_W) and pivoted_planar (those of
    #                                   # "planar" but p_W, v_W): the centre of mass relative to O in B
    #                                   # [m] (required; [x, y] planar) and O in the scene frame [m] (0)
    # [[body.wheels]]                   # gyrostat (the fields of "rigid", inertia the whole body's with its
    # axis_B = [0, 0, 1]                # wheels locked): one table per wheel, after its body's: spin axis in B,
    # inertia = "0.05 kg m^2"           # axial moment of inertia (> 0),
    # speed = "3000 rpm"                # initial speed relative to the body (default 0),
    # motor_torque = "0.01 N m"         # motor torque on the wheel (default 0), acting for
    # t_start = "0 s"                   # t_start <= t < t_end (defaults 0 and forever)
    # t_end = "60 s"
    # [body.mass_flow]                  # optional, a particle or rigid body: its mass changes (after its table)
    # rate = "-2 kg/s"                  # dm/dt [kg/s] (negative: losing mass; default 0)
    # inertia_rule = "scaled"           # I_C = I_C0 m / m0 (the only rule a file holds)
    # [body.primitive]                  # rigid, pivoted, gyrostat: instead of mass + inertia (after its
    # shape = "solid_box"               # table), a solid of rigiddyn.problem.PRIMITIVES, its size keys [m]
    # size = ["10 cm", "20 cm", 0.3]    # and mass [kg] or density [kg/m^3]; or [body.mesh]: path (a closed
    # density = "2.7 g/cm^3"            # triangle mesh file, relative to the scene file) and mass or
    #                                   # density; read as a problem file's [body] is

    [[force]]                           # one table per force element; `type` picks it
    type = "uniform_gravity"            # g_W [m/s^2] (default [0, 0, -9.81]), bodies
    # type = "point_mass_gravity"       # gm [m^3/s^2], p_W [m] (default 0), softening [m] (0), bodies
    # type = "mutual_gravity"           # G [m^3/(kg s^2)] (default 6.67430e-11), softening [m] (0), bodies
    # type = "gravity_gradient"         # gm [m^3/s^2], p_W [m] (default 0), bodies
    # type = "spring_damper"            # body_a (a name), point_a_B [m] in a's B (0), body_b (a name;
    #                                   # absent: point_b is a world anchor in W), point_b [m] (0),
    #                                   # stiffness [N/m], rest_length [m] (0), damping [N s/m] (0)
    # type = "drag"                     # linear [N s/m], quadratic [N s^2/m^2], angular_linear
    #                                   # [N m s/rad], angular_quadratic [N m s^2/rad^2] (each 0), bodies
    # type = "scheduled_loads"          # body (a name), point_B [m] in B (0), and its loads:
    # [[force.loads]]                   # force [N], torque [N m] (0), frame "world" | "body",
    #                                   # t_start, t_end [s] (default -inf, +inf), as in problem files
    # type = "thrust"                   # body (a name; it needs a [body.mass_flow]), u_rel [m/s] the
    #                                   # velocity of the ejected mass relative to the body, frame
    #                                   # "body" (default) | "world" (of u_rel), r_B [m] in B (0):
    #                                   # f = (dm/dt) u_rel at the point r_B
    # type = "magnetic_dipole"          # m_B [A m^2] in B, B_W [T] (0), source_moment_W [A m^2] (0) at
    #                                   # source_p_W [m] (0): a dipole in a uniform and a dipole field
    # type = "atmospheric_drag"         # radius [m], drag_area [m^2], and density0 [kg/m^3] at altitude0 [m]
    #                                   # with scale_height [m] (exponential), or a table: table_altitude
    #                                   # = ["200 km", "300 km", ...] (increasing) and table_density =
    #                                   # [2.5e-10, 1.9e-11, ...] [kg/m^3] (log-linear between rows)
    #                                   # (every class of rigiddyn.FORCE_ELEMENTS but PythonForce, its
    #                                   # type the class name in snake case, its keys its `fields`)
    bodies = ["sat", "boom"]            # names of the bodies it acts on; absent: every body

    [[cluster]]                         # generated particles, after the [[body]] tables, with their own
    model = "plummer"                   # MutualGravity (after the [[force]] elements); model: "plummer"
    count = 1000                        # integer >= 2 particles of mass total_mass / count (at most what
                                        # the memory holds: CLUSTER_BYTES_PER_PARTICLE each)
    total_mass = 1                      # [kg] > 0
    scale_radius = 0.5890486225480862   # Plummer scale radius a [m] > 0 (3 pi / 16: E = -1/4 with G = M = 1)
    G = 1                               # [m^3/(kg s^2)] > 0 (default 6.67430e-11), of the sampling and the gravity
    softening = 0.01                    # [m] >= 0 (default 0) of the MutualGravity
    seed = 1                            # integer >= 0: numpy.random.default_rng(seed) draws the sample
    name_prefix = "star"                # bodies "star0", "star1", ... (default "cluster<k>_")

    [[tree]]                            # after the [[body]] and [[cluster]] tables; its links are bodies named
    name = "pendulum"                   # "<name>.<link>" (name absent: each link's own name)
    [[tree.link]]                       # one table per link, parents first
    name = "upper"                      # unique in the tree
    parent = "base"                     # the parent link's name; absent: the world W
    joint = "revolute"                  # "revolute" | "prismatic" | "spherical" | "free" | "fixed"
    axis = [0, 1, 0]                    # revolute, prismatic: the joint's axis (any length) in the joint frame
    translation = [1, 0, 0]             # the placement X_T: the joint frame's origin in the parent's frame [m]
    rotation = [0, 0, 0, 1]             # and its attitude there: a unit quaternion (x, y, z, w) or a 3x3 rotation
                                        # matrix (default identity; a written file holds the matrix)
    mass = "1 kg"                       # [kg] > 0
    com = [0.5, 0, 0]                   # the centre of mass in the link frame [m] (default 0)
    inertia = [1e-3, 0.083, 0.083]      # about the centre of mass in the link frame: principal moments or 3x3
    q = ["30 deg"]                      # its joint's coordinates: an angle [rad] or an offset [m]; a quaternion
    v = ["10 rpm"]                      # (spherical); (p_JL [m], q_JL) (free); its velocities [rad/s], [m/s];
                                        # absent: the neutral configuration, at rest

    [controller]                        # optional: the run's digital controller, a shipped law of
    period = "1 s"                      # rigiddyn.control (RunOptions.controller; rigiddyn._controller_table
    law = "bdot"                        # lists its keys): "bdot" (gain, element: the index of its
    gain = "2e4 A*m^2*s/T"              # magnetic_dipole [[force]], m_max, rate) or "pd_attitude" (k_p, k_d,
    element = 1                         # target "lvlh" or [x, y, z, w], axes_B: default the body's wheels);
    body = "sat"                        # body, w_B_noise [rad/s] and seed optional

A [[tree]] table (after the [[body]] and [[cluster]] tables) holds a kinematic tree whose links become bodies
(Scene.add_tree: each link's name, or "<tree name>.<link name>"), one [[tree.link]] table per link with its
parent, joint, placement, mass properties and its joint's initial q and v; forces refer to the links by those
names. A file holds a scene's trees after its other bodies.

A [[cluster]] is a Plummer sphere in virial equilibrium (scene_file.plummer_sphere: Aarseth, Henon
& Wielen 1974) with its centre of mass at rest at W's origin; its bodies may be named in [[force]] tables.
scene_to_toml writes the generated bodies out as [[body]] tables and the gravity as a [[force]] (a Scene
does not remember its generator); that file reads back to the same scene and states.

In a scene with a [frame], "W" in the names above is that frame: the elements act in it and the
states are relative to it (rigiddyn.SceneFrame). A [body.mass_flow] table belongs to the [[body]]
table above it (TOML's rule for sub-tables of an array of tables).

A file of [[body]] tables, [[cluster]] tables or both is a scene file (is_scene_toml; a problem file,
rigiddyn.problem, has one [body] table). A scene of N bodies loads in O(N) time: bodies are named through
a name index, and forces refer to them by name.

A field without a default is required. Every error is a ValueError "<field>: expected ..., got ..."
naming the field by its path (``body[2].inertia: expected kg m^2, got '3 kg m' ([mass] * [length])``,
``force[1].body_a``); an unknown key is one too, with the closest known key. A file that is no valid
TOML, or whose arrays and tables nest more than rigiddyn.problem.MAX_TOML_NESTING deep, is a ValueError
naming the file.
"""

from __future__ import annotations

import itertools
import math
import re
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from . import _core
from ._core_call import core_call as _core_call
from ._loaded_file import RunOptions, SceneFile
from ._controller_table import controller_table, read_controller
from ._load_table import LOAD_KEYS, applied_load
from ._mass_properties import SOURCES, mass_properties
from ._memory import available_bytes, format_bytes
from ._tree_table import read_tree, tree_table
from ._names import check_keys as _check_keys
from ._names import closest as _closest
from .problem import _check_nesting, _orientation, _read_toml, _tradeoff_defaults
from .units import _floats, _shown, quantity, vector_quantity

__all__ = ["FORCE_TYPES", "RunOptions", "SceneFile", "example_scenes", "is_scene_toml", "load_scene", "parse_scene",
           "plummer_sphere", "read_scene", "scene_path", "scene_to_toml"]

_SCENES_DIR = Path(__file__).resolve().parent / "scenes"
_MASS_FLOW_KINDS = ("particle", "rigid")  # the body kinds whose mass may change (rigiddyn.MassFlow)
# the body kinds with an attitude: mass properties in the forms of a problem file's [body] (mass and inertia,
# a primitive or a mesh: rigiddyn._mass_properties)
_SOLID_KINDS = ("rigid", "pivoted", "gyrostat")
_ATTITUDES = ("q_WB", "euler", "rotvec", "axis_angle", "scalar_first")
_BODY_KEYS = {
    "particle": frozenset({"name", "kind", "mass", "p_W", "v_W", "mass_flow"}),
    "planar": frozenset({"name", "kind", "mass", "inertia", "p_W", "v_W", "theta", "omega", "mass_flow"}),
    "rigid": frozenset({"name", "kind", "mass", *SOURCES, "inertia_check", "p_W", "v_W", "w_B", *_ATTITUDES,
                        "mass_flow"}),
    "pivoted": frozenset({"name", "kind", "mass", *SOURCES, "inertia_check", "p_OC_B", "p_WO", "w_B", *_ATTITUDES,
                          "mass_flow"}),
    "pivoted_planar": frozenset({"name", "kind", "mass", "inertia", "p_OC_B", "p_WO", "theta", "omega", "mass_flow"}),
    "gyrostat": frozenset({"name", "kind", "mass", *SOURCES, "inertia_check", "p_W", "v_W", "w_B", *_ATTITUDES,
                           "wheels"}),
}
_WHEEL_KEYS = frozenset({"axis_B", "inertia", "speed", "motor_torque", "t_start", "t_end"})
_KINDS = "one of " + ", ".join(map(repr, _BODY_KEYS))
_TOP_KEYS = frozenset({"name", "description", "run", "tradeoff", "frame", "body", "force", "cluster", "tree",
                       "controller"})
_TRADEOFF_KEYS = frozenset({"methods", "dts", "tolerance", "measure", "horizon"})
_MASS_FLOW_KEYS = frozenset({"rate", "inertia_rule"})
_FRAME_KEYS = {"rotating": frozenset({"kind", "axis", "rate"}), "earth": frozenset({"kind", "latitude"})}
_CLUSTER_KEYS = frozenset({"model", "count", "total_mass", "scale_radius", "G", "softening", "seed", "name_prefix"})
_RUN_KEYS = frozenset({"method", "dt", "duration", "record_every"})
_REQUIRED = object()  # a field default: the field must be given
_NAMES_SHOWN = 20  # body names an error about a body reference lists
_NAMES_SEARCHED = 10_000  # up to this many bodies, that error also suggests the closest name
# | |q| - 1 | up to this: q_WB is a unit quaternion to round-off (4 ulp of 1), taken as written; dividing
# it by its norm again would move its last bits, so a written canonical file would not read back exactly
_UNIT_NORM = 4 * np.finfo(np.float64).eps


@dataclass(frozen=True)
class _Field:
    """A force field: how it is read ("scalar", "vector", "array": a table's column, "bodies", "body",
    "optional_body", "loads", "frame": 'body' or 'world'),
    its SI unit (a pint expression) and its default (_REQUIRED, or a value in SI)."""

    kind: str
    unit: str = "1"
    default: Any = _REQUIRED


def _snake_case(name: str) -> str:
    """'GravityGradient' -> 'gravity_gradient': a class's [[force]] type."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", name).lower()


def _force_types() -> dict[str, tuple[str, dict[str, _Field]]]:
    """Every force element a file can hold, from the classes' own field tables (rigiddyn.FORCE_ELEMENTS,
    each class's `fields`): every element but those holding a callable (PythonForce)."""
    types = {}
    for cls in _core.FORCE_ELEMENTS:
        if any(f.kind == "callable" for f in cls.fields):
            continue
        types[_snake_case(cls.__name__)] = (cls.__name__, {
            f.key: _Field(f.kind, f.unit or "1", _REQUIRED if f.required else f.default) for f in cls.fields})
    return types


# force type -> (its class in rigiddyn, its fields in the order of the class's constructor)
FORCE_TYPES: dict[str, tuple[str, dict[str, _Field]]] = _force_types()
_TYPE_OF_CLASS = {cls: name for name, (cls, _) in FORCE_TYPES.items()}


# ------------------------------------------------------------------------------------------ reading

def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {_shown(got)}")


def _required(table: Mapping[str, Any], key: str, name: str, expected: str) -> Any:
    if key not in table:
        raise _fail(f"{name}.{key}", expected, "nothing")
    return table[key]


def _string(value: Any, name: str, expected: str = "a string") -> str:
    if not isinstance(value, str):
        raise _fail(name, expected, value)
    return value


def _readdressed(function: Callable[[Mapping[str, Any]], Any], table: Mapping[str, Any], name: str) -> Any:
    """function(table) of rigiddyn.problem (its messages name "initial.<key>"), its errors and
    warnings naming "<name>.<key>" instead."""
    def readdress(text: str) -> str:
        return text.replace("initial.", f"{name}.").replace("[initial]", f"[{name}]").replace("initial:", f"{name}:")

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            result = function(table)
        except ValueError as e:
            raise ValueError(readdress(str(e))) from None
    for w in caught:
        warnings.warn(readdress(str(w.message)), w.category, stacklevel=4)
    return result


def _body(table: Any, i: int, base: Path | None) -> tuple[str, Any, Any]:
    """(name, body, initial state) of the [[body]] table number i (`base`: the folder of relative mesh paths)."""
    name = f"body[{i}]"
    if not isinstance(table, Mapping):
        raise _fail(name, "a table [[body]]", table)
    kind = _string(_required(table, "kind", name, _KINDS), f"{name}.kind", _KINDS)
    if kind not in _BODY_KEYS:
        close = _closest(kind, _BODY_KEYS)
        raise _fail(f"{name}.kind", _KINDS + (f" (did you mean {close!r}?)" if close else ""), kind)
    _check_keys(table, name, _BODY_KEYS[kind], f"a [[body]] of kind {kind!r}")
    body_name = _string(table.get("name", f"body{i}"), f"{name}.name")
    # a body with an attitude: its mass properties as a problem file's [body] gives them
    mass, inertia = (mass_properties(table, name, base) if kind in _SOLID_KINDS else
                     (quantity(_required(table, "mass", name, "a mass [kg] > 0"), f"{name}.mass", "kg", positive=True),
                      None))
    if kind.startswith("pivoted"):
        return (body_name, *_pivoted(table, name, kind, mass, inertia))
    n = 2 if kind == "planar" else 3
    p_W = vector_quantity(table.get("p_W", [0.0] * n), f"{name}.p_W", "m", n)
    v_W = vector_quantity(table.get("v_W", [0.0] * n), f"{name}.v_W", "m/s", n)
    if kind == "particle":
        return body_name, _core_call(_core.Particle, name, mass), _core_call(_core.ParticleState, name, p_W, v_W)
    if kind == "planar":
        inertia_zz, theta, omega = _planar_rotation(table, name)
        return (body_name, _core_call(_core.PlanarBody, name, mass, inertia_zz, keys={"inertia_zz": "inertia"}),
                _core_call(_core.PlanarBodyState, name, p_W, theta, v_W, omega))
    body, q_WB, w_B = _rigid_rotation(table, name, mass, inertia)
    if kind == "gyrostat":
        wheels, speeds = _wheels(table, name)
        return (body_name, _core_call(_core.Gyrostat, name, body, wheels),
                _core_call(_core.GyrostatState, name, p_W, q_WB, v_W, w_B, speeds))
    return body_name, body, _core_call(_core.RigidBodyState, name, p_W, q_WB, v_W, w_B)


def _wheels(table: Mapping[str, Any], name: str) -> tuple[list[Any], list[float]]:
    """(Wheels, initial speeds [rad/s]) of a gyrostat [[body]]'s [[body.wheels]] tables."""
    given = _required(table, "wheels", name, "[[body.wheels]] tables (one per wheel)")
    if not isinstance(given, list):
        raise _fail(f"{name}.wheels", "[[body.wheels]] tables (one per wheel)", given)
    wheels, speeds = [], []
    for k, wheel in enumerate(given):
        field = f"{name}.wheels[{k}]"
        _check_keys(wheel, field, _WHEEL_KEYS, "[[body.wheels]]")
        axis_B = vector_quantity(_required(wheel, "axis_B", field, "a spin axis in B"), f"{field}.axis_B", "1")
        inertia = quantity(_required(wheel, "inertia", field, "an axial inertia [kg m^2] > 0"), f"{field}.inertia",
                           "kg*m^2", positive=True)
        t_start = quantity(wheel.get("t_start", 0.0), f"{field}.t_start", "s")
        t_end = quantity(wheel["t_end"], f"{field}.t_end", "s") if "t_end" in wheel else float("inf")  # forever
        wheels.append(_core_call(_core.Wheel, field, axis_B, inertia,
                                 quantity(wheel.get("motor_torque", 0.0), f"{field}.motor_torque", "N*m"), t_start,
                                 t_end))
        speeds.append(quantity(wheel.get("speed", 0.0), f"{field}.speed", "rad/s"))
    return wheels, speeds


def _planar_rotation(table: Mapping[str, Any], name: str) -> tuple[float, float, float]:
    """inertia I_zz [kg m^2], theta [rad] and omega [rad/s] of a planar [[body]] (planar, pivoted_planar)."""
    inertia_zz = quantity(_required(table, "inertia", name, "I_zz [kg m^2]"), f"{name}.inertia", "kg*m^2",
                          positive=True)
    theta = quantity(table.get("theta", 0.0), f"{name}.theta", "rad")
    omega = quantity(table.get("omega", 0.0), f"{name}.omega", "rad/s")
    return inertia_zz, theta, omega


def _rigid_rotation(table: Mapping[str, Any], name: str, mass: float, inertia: Any) -> tuple[Any, Any, np.ndarray]:
    """(RigidBody of mass [kg] and inertia [kg m^2] about C in B, q_WB (x, y, z, w), w_B [rad/s]) of a [[body]]
    with an attitude (rigid, pivoted, gyrostat)."""
    check = table.get("inertia_check", "physical")
    if not isinstance(check, str) or check not in _core.InertiaCheck.__members__:
        raise _fail(f"{name}.inertia_check", " or ".join(map(repr, _core.InertiaCheck.__members__)), check)
    body = _core_call(_core.RigidBody, name, mass, inertia, check=_core.InertiaCheck.__members__[check],
                      keys={"inertia_com": "inertia"})
    w_B = vector_quantity(table.get("w_B", [0.0, 0.0, 0.0]), f"{name}.w_B", "rad/s")
    q_WB = _readdressed(_orientation, table, name)
    if "q_WB" in table and not table.get("scalar_first", False):
        written = np.asarray(table["q_WB"], dtype=np.float64)  # numbers: _orientation checked them
        if abs(np.linalg.norm(written) - 1.0) <= _UNIT_NORM:
            q_WB = written  # unit to round-off already: kept bit for bit
    return body, q_WB if q_WB is not None else np.array([0.0, 0.0, 0.0, 1.0]), w_B


def _pivoted(table: Mapping[str, Any], name: str, kind: str, mass: float, inertia: Any) -> tuple[Any, Any]:
    """(body, initial state) of a [[body]] pinned at a point O fixed in the scene frame: kind 'pivoted'
    (a RigidBody, attitude and w_B) or 'pivoted_planar' (I_zz, theta, omega); p_OC_B: the centre of mass
    relative to O in B [m] (required), p_WO: O in the scene frame [m] (default 0); inertia: the rigid body's
    about C in B [kg m^2] (None for pivoted_planar)."""
    n = 2 if kind == "pivoted_planar" else 3
    p_OC_B = vector_quantity(_required(table, "p_OC_B", name, f"the centre of mass relative to the pivot, {n} "
                                       "lengths [m] in B"), f"{name}.p_OC_B", "m", n)
    p_WO = vector_quantity(table.get("p_WO", [0.0] * n), f"{name}.p_WO", "m", n)
    if kind == "pivoted_planar":
        inertia_zz, theta, omega = _planar_rotation(table, name)
        body = _core_call(_core.PivotedPlanarBody, name, mass, inertia_zz, p_OC_B, p_WO, keys={"inertia_zz": "inertia"})
        return body, _core_call(_core.PivotedPlanarBodyState, name, theta=theta, omega=omega)
    rigid, q_WB, w_B = _rigid_rotation(table, name, mass, inertia)
    body = _core_call(_core.PivotedBody, name, rigid, p_OC_B, p_WO)
    return body, _core_call(_core.PivotedBodyState, name, q_WB=q_WB, w_B=w_B)


def _mass_flow(table: Mapping[str, Any], name: str) -> Any:
    """The MassFlow of a [[body]]'s [body.mass_flow] table, None without one: rate [kg/s] (negative: the
    body loses mass; default 0), inertia_rule "scaled" (I_C = I_C0 m / m0; a function of the mass
    cannot be written in a file)."""
    if "mass_flow" not in table:
        return None
    field = f"{name}.mass_flow"
    if table.get("kind") not in _MASS_FLOW_KINDS:
        raise _fail(field, f"no [body.mass_flow] table on a {table.get('kind')} body (a mass flow applies to "
                    "particles and rigid bodies)", table["mass_flow"])
    flow = _check_keys(table["mass_flow"], field, _MASS_FLOW_KEYS, "[body.mass_flow]")
    rate = quantity(flow.get("rate", 0.0), f"{field}.rate", "kg/s")
    rule = flow.get("inertia_rule", "scaled")
    if rule != "scaled":
        raise _fail(f"{field}.inertia_rule", "'scaled' (a function of the mass: MassFlow in Python)", rule)
    return _core_call(_core.MassFlow, field, rate=rate, inertia_rule=rule)


def _frame(value: Any) -> Any:
    """The SceneFrame of the [frame] table: kind "rotating" (axis, any non-zero length, and rate [rad/s]
    about it through the origin) or "earth" (latitude [rad]: the local frame x east, y north, z up)."""
    kinds = " or ".join(map(repr, _FRAME_KEYS))
    if not isinstance(value, Mapping):
        raise _fail("frame", "a table [frame]", value)
    kind = _required(value, "kind", "frame", kinds)
    if kind not in _FRAME_KEYS:
        raise _fail("frame.kind", kinds, kind)
    _check_keys(value, "frame", _FRAME_KEYS[kind], f"a [frame] of kind {kind!r}")
    if kind == "earth":
        latitude = quantity(_required(value, "latitude", "frame", "an angle [rad]"), "frame.latitude", "rad")
        return _core_call(_core.SceneFrame.earth, "frame", latitude)
    axis = vector_quantity(_required(value, "axis", "frame", "an axis [x, y, z]"), "frame.axis", "1")
    rate = quantity(_required(value, "rate", "frame", "a rate [rad/s]"), "frame.rate", "rad/s")
    return _core_call(_core.SceneFrame.rotating, "frame", axis, rate)


def _body_ref(value: Any, name: str, names: Mapping[str, int]) -> int:
    """The index of the body named `value` (`names`: each body's name -> its index, in index order)."""
    if isinstance(value, str) and value in names:
        return names[value]
    shown = list(itertools.islice(names, _NAMES_SHOWN))
    listed = ", ".join(map(repr, shown)) + (f", ... ({len(names)} bodies)" if len(names) > len(shown) else "")
    close = _closest(value, names) if isinstance(value, str) and len(names) <= _NAMES_SEARCHED else None
    hint = f" (did you mean {close!r}?)" if close else ""
    raise _fail(name, "the name of a [[body]]: one of " + listed + hint, value)


def _loads(value: Any, name: str) -> list[Any]:
    """[[force.loads]]: a list of AppliedLoad (rigiddyn._load_table, as a problem file's [[loads]])."""
    if not isinstance(value, list):
        raise _fail(name, "an array of tables [[force.loads]]", value)
    return [applied_load(_check_keys(item, f"{name}[{j}]", LOAD_KEYS, "[[force.loads]]"), f"{name}[{j}]")
            for j, item in enumerate(value)]


def _array(value: Any, name: str, unit: str) -> np.ndarray:
    """An (n,) array [unit] (a table's column): a list of n values or {value = [..], unit = ".."}, each
    entry as a vector's (units.vector_quantity)."""
    items = value.get("value") if isinstance(value, Mapping) else value
    if not isinstance(items, list):
        raise _fail(name, f"an array of values [{unit}] or {{value = [..], unit = \"..\"}}", value)
    return vector_quantity(value, name, unit, n=len(items))


def _force(table: Any, i: int, names: Mapping[str, int]) -> Any:
    """The force element of the [[force]] table number i (bodies resolved by name in `names`)."""
    name = f"force[{i}]"
    if not isinstance(table, Mapping):
        raise _fail(name, "a table [[force]]", table)
    types = ", ".join(map(repr, FORCE_TYPES))
    kind = _required(table, "type", name, f"one of {types}")
    if not isinstance(kind, str) or kind not in FORCE_TYPES:
        close = _closest(kind, FORCE_TYPES) if isinstance(kind, str) else None
        raise _fail(f"{name}.type", f"one of {types}" + (f" (did you mean {close!r}?)" if close else ""), kind)
    cls, fields = FORCE_TYPES[kind]
    _check_keys(table, name, frozenset({"type", *fields}), f"a [[force]] of type {kind!r}")
    kwargs: dict[str, Any] = {}
    for key, f in fields.items():
        field = f"{name}.{key}"
        if key not in table:
            if f.default is _REQUIRED:
                raise _fail(field, f"a value [{f.unit}]" if f.kind in ("scalar", "vector") else "a value", "nothing")
            kwargs[key] = f.default
            continue
        value = table[key]
        if f.kind == "scalar":
            kwargs[key] = quantity(value, field, f.unit)
        elif f.kind == "vector":
            kwargs[key] = vector_quantity(value, field, f.unit)
        elif f.kind == "array":
            kwargs[key] = _array(value, field, f.unit)
        elif f.kind in ("body", "optional_body"):
            kwargs[key] = _body_ref(value, field, names)
        elif f.kind == "frame":
            if value not in ("body", "world"):
                raise _fail(field, "'body' or 'world'", value)
            kwargs[key] = value
        elif f.kind == "bodies":
            if not isinstance(value, list) or not value:
                raise _fail(field, "a non-empty array of body names (absent: every body)", value)
            kwargs[key] = [_body_ref(v, f"{field}[{j}]", names) for j, v in enumerate(value)]
        else:
            kwargs[key] = _loads(value, field)
    return _core_call(getattr(_core, cls), name, **kwargs)


def _tradeoff(value: Any) -> dict[str, Any]:
    """The [tradeoff] table: rigiddyn.tradeoff's defaults for the scene, as in problem files (methods,
    dts [s], tolerance, measure), plus horizon [s] (default: the [run] duration)."""
    table = _check_keys(value, "tradeoff", _TRADEOFF_KEYS, "[tradeoff]")
    out = _tradeoff_defaults({k: v for k, v in table.items() if k != "horizon"})
    if "horizon" in table:
        out["horizon"] = quantity(table["horizon"], "tradeoff.horizon", "s", positive=True)
    return out


def _run(value: Any, tradeoff: Any = None) -> RunOptions:
    """The [run] table (and the [tradeoff] table) as RunOptions."""
    table = _check_keys(value, "run", _RUN_KEYS, "[run]")
    method = _string(table.get("method", "rk4"), "run.method", "a method name")
    names = [m["name"] for m in _core.methods()]
    if method not in names:
        raise _fail("run.method", "one of " + ", ".join(names), method)
    dt = quantity(table["dt"], "run.dt", "s", positive=True) if "dt" in table else None
    duration = quantity(table["duration"], "run.duration", "s", positive=True) if "duration" in table else None
    record_every = table.get("record_every", 1)
    if isinstance(record_every, bool) or not isinstance(record_every, int) or record_every < 1:
        raise _fail("run.record_every", "an integer >= 1", record_every)
    return RunOptions(method, dt, duration, record_every, _tradeoff({} if tradeoff is None else tradeoff))


# ------------------------------------------------------------------------------------------ [[cluster]]

# Equal-mass samples of a Plummer sphere in virial equilibrium (Aarseth, Henon & Wielen 1974).
#
# The Plummer model of total mass M and scale radius a has the density and potential
#
#     rho(r) = 3 M / (4 pi a^3) (1 + r^2/a^2)^(-5/2),      Phi(r) = -G M / sqrt(r^2 + a^2),
#
# cumulative mass M(r)/M = r^3 / (r^2 + a^2)^(3/2), and an isotropic distribution function in which the
# speed v at radius r, as a fraction q = v / v_esc(r) of the local escape speed
# v_esc(r) = sqrt(2 G M) (r^2 + a^2)^(-1/4), has the density g(q) proportional to q^2 (1 - q^2)^(7/2).
# Its kinetic energy T = 3 pi G M^2 / (64 a) and potential energy V = -3 pi G M^2 / (32 a) satisfy the
# virial theorem 2T = -V; with G = M = 1 and a = 3 pi / 16 the energy is E = -1/4 (the standard N-body
# units of Henon and Heggie & Mathieu).

# g(q) = q^2 (1 - q^2)^(7/2) peaks at q^2 = 2/9 with g = 0.0921...; 0.1 bounds it (the rejection step
# of Aarseth, Henon & Wielen 1974)
_G_BOUND = 0.1
# memory a generated particle takes until the scene is loaded [bytes]: the peak resident memory of loading
# 10^6 particles was 845 MiB (the draws, the bodies and states in Python and C++, the names and their index),
# rounded up
CLUSTER_BYTES_PER_PARTICLE = 1000


def _isotropic(rng: np.random.Generator, lengths: np.ndarray) -> np.ndarray:
    """Vectors of the given lengths in directions uniform on the sphere (cos(theta) uniform in [-1, 1],
    phi uniform in [0, 2 pi)), shape (n, 3)."""
    cos_theta = rng.uniform(-1.0, 1.0, lengths.size)
    phi = rng.uniform(0.0, 2.0 * np.pi, lengths.size)
    sin_theta = np.sqrt(1.0 - cos_theta**2)
    directions = np.column_stack((sin_theta * np.cos(phi), sin_theta * np.sin(phi), cos_theta))
    out: np.ndarray = lengths[:, None] * directions
    return out


def _speed_fractions(rng: np.random.Generator, n: int) -> np.ndarray:
    """n draws of q = v / v_esc from g(q) ~ q^2 (1 - q^2)^(7/2) on [0, 1) by von Neumann rejection."""
    q = np.empty(n)
    filled = 0
    while filled < n:
        want = n - filled
        x = rng.uniform(0.0, 1.0, want)
        y = rng.uniform(0.0, _G_BOUND, want)
        accepted = x[y < x**2 * (1.0 - x**2) ** 3.5]
        q[filled:filled + accepted.size] = accepted
        filled += accepted.size
    return q


def plummer_sphere(count: int, total_mass: float, scale_radius: float, G: float,
                   rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(masses [kg] (count,), p_W [m] (count, 3), v_W [m/s] (count, 3)) of `count` equal-mass particles
    drawn from the Plummer sphere of `total_mass` [kg], `scale_radius` a [m] and gravitational constant
    G [m^3/(kg s^2)] (Aarseth, Henon & Wielen 1974): radius from the inverted cumulative mass
    r = a / sqrt(X^(-2/3) - 1) with X uniform in [0, 1) (no radial cut-off), speed v = q v_esc(r) with q
    drawn by rejection from q^2 (1 - q^2)^(7/2), both directions isotropic. The centre of mass is then
    moved to W's origin and the total momentum removed (each a shift by the sample mean, equal masses).
    Deterministic for a given state of `rng`. The velocities are those of the unsoftened potential."""
    m = total_mass / count
    x = rng.uniform(0.0, 1.0, count)
    # r = a / sqrt(X^(-2/3) - 1) written without the division by 0 at X = 0
    x13 = np.cbrt(x)
    r = scale_radius * x13 / np.sqrt(1.0 - x13**2)
    p_W = _isotropic(rng, r)
    v_esc = np.sqrt(2.0 * G * total_mass) * (r**2 + scale_radius**2) ** -0.25
    v_W = _isotropic(rng, _speed_fractions(rng, count) * v_esc)
    p_W -= p_W.mean(axis=0)
    v_W -= v_W.mean(axis=0)
    return np.full(count, m), p_W, v_W


def _integer(value: Any, name: str, least: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        raise _fail(name, f"an integer >= {least}", value)
    return value


@dataclass(frozen=True)
class _Cluster:
    """A read [[cluster]]: its bodies' names, particles and states, and its gravity's G and softening."""

    names: list[str]
    bodies: list[Any]
    states: list[Any]
    G: float
    softening: float


def _cluster(table: Any, k: int) -> _Cluster:
    """The generated particles of the [[cluster]] table number k (a Plummer sphere: plummer_sphere)."""
    name = f"cluster[{k}]"
    _check_keys(table, name, _CLUSTER_KEYS, "[[cluster]]")
    model = _required(table, "model", name, "'plummer'")
    if model != "plummer":
        raise _fail(f"{name}.model", "'plummer'", model)
    count = _integer(_required(table, "count", name, "an integer >= 2"), f"{name}.count", 2)
    _check_cluster_memory(count, f"{name}.count")
    total_mass = quantity(_required(table, "total_mass", name, "a mass [kg] > 0"), f"{name}.total_mass", "kg",
                          positive=True)
    scale_radius = quantity(_required(table, "scale_radius", name, "a length [m] > 0"), f"{name}.scale_radius",
                            "m", positive=True)
    G = quantity(table.get("G", 6.67430e-11), f"{name}.G", "m^3/(kg*s^2)", positive=True)
    softening = quantity(table.get("softening", 0.0), f"{name}.softening", "m", nonnegative=True)
    seed = _integer(_required(table, "seed", name, "an integer >= 0"), f"{name}.seed", 0)
    prefix = _string(table.get("name_prefix", f"cluster{k}_"), f"{name}.name_prefix")
    masses, p_W, v_W = plummer_sphere(count, total_mass, scale_radius, G, np.random.default_rng(seed))
    return _Cluster([f"{prefix}{j}" for j in range(count)], [_core.Particle(m) for m in masses],
                    [_core.ParticleState(p, v) for p, v in zip(p_W, v_W)], G, softening)


def _check_cluster_memory(count: int, name: str) -> None:
    """ValueError naming `name` when `count` generated particles would not fit in the memory available
    (CLUSTER_BYTES_PER_PARTICLE each), before any is drawn."""
    available = available_bytes()
    needed = count * CLUSTER_BYTES_PER_PARTICLE
    if available is not None and needed > available:
        raise ValueError(f"{name}: expected a count whose particles fit in the available memory "
                         f"({format_bytes(available)}: at most {available // CLUSTER_BYTES_PER_PARTICLE} particles of "
                         f"about {CLUSTER_BYTES_PER_PARTICLE} bytes), got {count} "
                         f"(an estimated {format_bytes(needed)})")


def parse_scene(data: Mapping[str, Any], source: str = "scene", base: str | Path | None = None) -> SceneFile:
    """A SceneFile from parsed TOML `data` (`source` names it when the file sets no name; `base` is the folder
    that relative mesh paths refer to, None: the working directory)."""
    _check_nesting(data, source)
    data = _check_keys(data, "scene", _TOP_KEYS, "the top level")
    if "body" not in data and "cluster" not in data and "tree" not in data:
        raise _fail("scene.body", "at least one [[body]], [[cluster]] or [[tree]] table", "nothing")
    tables = data.get("body", [])
    if not isinstance(tables, list) or ("body" in data and not tables):
        raise _fail("body", "an array of [[body]] tables", tables)
    clusters = data.get("cluster", [])
    if not isinstance(clusters, list) or ("cluster" in data and not clusters):
        raise _fail("cluster", "an array of [[cluster]] tables", clusters)
    names: dict[str, int] = {}  # each body's name -> its index (a dict: a name is checked in O(1))
    bodies, flows, initial = [], [], []
    for i, table in enumerate(tables):
        body_name, body, state = _body(table, i, None if base is None else Path(base))
        if body_name in names:
            raise _fail(f"body[{i}].name", "a name no other [[body]] has", body_name)
        names[body_name] = i
        bodies.append(body)
        flows.append(_mass_flow(table, f"body[{i}]"))
        initial.append(state)
    frame = _frame(data["frame"]) if "frame" in data else None
    gravities = []  # (first body, count, G, softening) of each cluster
    for k, table in enumerate(clusters):
        cluster = _cluster(table, k)
        taken = next((n for n in cluster.names if n in names), None)
        if taken is not None:
            raise _fail(f"cluster[{k}].name_prefix", "a prefix giving names no other body has",
                        f"{table.get('name_prefix', f'cluster{k}_')!r} (names {taken!r})")
        gravities.append((len(names), len(cluster.names), cluster.G, cluster.softening))
        names.update(zip(cluster.names, range(len(names), len(names) + len(cluster.names))))
        bodies += cluster.bodies
        flows += [None] * len(cluster.bodies)
        initial += cluster.states
    # one call: the scene's bodies, named, with their flows (each name checked by the scene's name index)
    scene = _core.Scene(bodies=bodies, body_names=list(names), frame=frame,
                        mass_flows=flows if any(f is not None for f in flows) else None)
    trees = data.get("tree", [])
    if not isinstance(trees, list) or ("tree" in data and not trees):
        raise _fail("tree", "an array of [[tree]] tables", trees)
    for k, table in enumerate(trees):  # each link a body, after the others (rigiddyn._tree_table)
        prefix, tree, states = read_tree(table, k)
        indices = _core_call(scene.add_tree, f"tree[{k}]", tree, prefix)
        names.update((scene.body_names[i], i) for i in indices)
        initial += states
    forces = data.get("force", [])
    if not isinstance(forces, list):
        raise _fail("force", "an array of [[force]] tables", forces)
    for i, table in enumerate(forces):
        _core_call(scene.add, f"force[{i}]", _force(table, i, names))
    for first, count, G, softening in gravities:  # one cluster's bodies, or None when they are all of them
        cluster_bodies = None if count == len(names) else list(range(first, first + count))
        scene.add(_core.MutualGravity(G=G, softening=softening, bodies=cluster_bodies))
    description = _string(data.get("description", ""), "description")
    run = _run(data.get("run", {}), data.get("tradeoff", {}))
    if "controller" in data:
        run = replace(run, controller=read_controller(data["controller"], scene, names, _body_ref))
    return SceneFile(scene, initial, run, _string(data.get("name", source), "name"), description.strip())


def example_scenes() -> list[str]:
    """Names of the shipped scenes (rigiddyn/scenes/*.toml)."""
    return sorted(p.stem for p in _SCENES_DIR.glob("*.toml"))


def scene_path(name: str) -> Path:
    """The file of the shipped scene `name` (ValueError for an unknown one)."""
    path = _SCENES_DIR / f"{name}.toml"
    if not isinstance(name, str) or not _is_file(str(path)):
        raise _fail("path_or_text", "a .toml path, TOML text or one of the shipped scenes "
                    + ", ".join(example_scenes()), name)
    return path


def _is_file(path: str) -> bool:
    """Path(path).is_file(), False for a string no file system takes as a path (too long, a NUL)."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def is_scene_toml(path: str | Path) -> bool:
    """True for a readable TOML file that is a scene file: [[body]] tables (a problem file has one [body]
    table), [[cluster]] tables (a scene of generated particles only) or [[tree]] tables (a scene of trees only).
    False for anything else, a file that is no valid TOML included (its loader says what is wrong with it)."""
    try:
        data = _read_toml(Path(path).read_text(encoding="utf-8"), str(path))
    except (OSError, ValueError):  # UnicodeDecodeError is a ValueError
        return False
    return isinstance(data.get("body"), list) or "cluster" in data or "tree" in data


def read_scene(path_or_text: str | Path) -> SceneFile:
    """Read a scene: a path (str or Path) to a .toml file, the TOML text itself (a str holding a
    newline, or an '=' and naming no file), or the name of a shipped scene (example_scenes())."""
    if not isinstance(path_or_text, (str, Path)):
        raise TypeError(f"path_or_text: expected a path, TOML text or a shipped scene name, got "
                        f"{type(path_or_text).__name__}")
    if isinstance(path_or_text, str) and ("\n" in path_or_text or ("=" in path_or_text and not _is_file(path_or_text))):
        text, source, base = path_or_text, "scene", None
    else:
        path = Path(path_or_text)
        if not _is_file(str(path)):
            if isinstance(path_or_text, Path) or path.suffix or len(path.parts) > 1:
                raise _fail("path_or_text", "an existing .toml file", str(path_or_text))
            path = scene_path(str(path_or_text))
        text, source, base = path.read_text(encoding="utf-8"), path.stem, path.parent
    return parse_scene(_read_toml(text, source), source, base)


def load_scene(path_or_text: str | Path) -> SceneFile:
    """Read a scene: its bodies, force elements and run options from a TOML file, TOML text or a shipped scene.

    A scene file declares ``[[body]]`` tables (kind, mass properties, initial state), ``[[force]]`` tables (one
    force element each, by its ``type``), an optional ``[frame]`` and ``[run]``; every quantity may carry a unit
    (``mass = "200 g"``), converted to SI (docs/scenes.md lists the keys).

    Parameters
    ----------
    path_or_text : str or pathlib.Path
        A ``.toml`` file, the TOML text itself, or the name of a shipped scene
        (``rigiddyn.scene_file.example_scenes()``: ``"pendulum"``, ``"three_body"``, ...).

    Returns
    -------
    SceneFile
        The file read, which unpacks as ``scene, initial, run``: the bodies and force elements (a Scene), each
        body's initial state in the scene's order (``RigidBodyState``, ``ParticleState``, ...), and the
        ``RunOptions`` of ``[run]`` (``method``, ``dt`` [s], ``duration`` [s], ``record_every``, the ``tradeoff``
        defaults); besides ``name`` and ``description``. ``load_problem`` returns one too.

    Raises
    ------
    ValueError
        A key, value or unit that the file format does not accept; the message names it (``force[0].type``) and
        suggests the closest valid name.

    See Also
    --------
    simulate : runs the scene.
    load_problem : a one-body problem file.

    Examples
    --------
    A ball of 200 g thrown at 3 m/s under gravity lands ½ g t² below after 1 s:

    >>> text = '''
    ... [[body]]
    ... name = "ball"
    ... kind = "particle"
    ... mass = "200 g"
    ... v_W = ["3 m/s", 0.0, 0.0]
    ... [[force]]
    ... type = "uniform_gravity"
    ... g_W = [0.0, 0.0, -9.81]
    ... [run]
    ... method = "rk4"
    ... dt = 0.01
    ... duration = "1 s"
    ... '''
    >>> scene, initial, run = rd.load_scene(text)
    >>> scene.bodies[0].mass, run.duration
    (0.2, 1.0)
    >>> result = rd.simulate(scene, initial, run.dt, duration=run.duration, method=run.method)
    >>> result.p_W[-1].round(12)
    array([[ 3.   ,  0.   , -4.905]])

    A shipped scene, the simple pendulum, keeps its energy to RK4's error:

    >>> scene, initial, run = rd.load_scene("pendulum")
    >>> result = rd.simulate(scene, initial, run.dt, duration=run.duration, method=run.method)
    >>> E = result.total_energy
    >>> bool(abs(E[-1] - E[0]) < 1e-9 * abs(E[0]))
    True
    """
    return read_scene(path_or_text)


# ------------------------------------------------------------------------------------------ writing

def _body_table(name: str, body: Any, state: Any) -> dict[str, Any]:
    """A [[body]] table; its initial state left out for state None (the file's defaults: at rest)."""
    if isinstance(body, _core.Particle):
        head = {"name": name, "kind": "particle", "mass": float(body.mass)}
        return head if state is None else {**head, "p_W": _floats(state.p_W), "v_W": _floats(state.v_W)}
    if isinstance(body, _core.PlanarBody):
        head = {"name": name, "kind": "planar", "mass": float(body.mass), "inertia": float(body.inertia_zz)}
        return head if state is None else {**head, "p_W": _floats(state.p_W), "v_W": _floats(state.v_W),
                                           "theta": float(state.theta), "omega": float(state.omega)}
    if isinstance(body, _core.RigidBody):
        table = {"name": name, "kind": "rigid", **_rigid_head(body)}
        return table if state is None else {**table, "p_W": _floats(state.p_W), "v_W": _floats(state.v_W),
                                            "w_B": _floats(state.w_B), "q_WB": _floats(state.q_WB)}
    if isinstance(body, _core.Gyrostat):
        table = {"name": name, "kind": "gyrostat", **_rigid_head(body.body)}
        if state is not None:
            table.update({"p_W": _floats(state.p_W), "v_W": _floats(state.v_W), "w_B": _floats(state.w_B),
                          "q_WB": _floats(state.q_WB)})
        speeds = [0.0] * len(body.wheels) if state is None else _floats(state.wheel_speeds)
        return {**table, "wheels": [_wheel_table(wheel, speed) for wheel, speed in zip(body.wheels, speeds)]}
    if type(body).__name__ == "PivotedPlanarBody":
        head = {"name": name, "kind": "pivoted_planar", "mass": float(body.mass), "inertia": float(body.inertia_zz),
                "p_OC_B": _floats(body.p_OC_B), "p_WO": _floats(body.p_WO)}
        return head if state is None else {**head, "theta": float(state.theta), "omega": float(state.omega)}
    table = {"name": name, "kind": "pivoted", **_rigid_head(body.body), "p_OC_B": _floats(body.p_OC_B),
             "p_WO": _floats(body.p_WO)}  # a PivotedBody
    return table if state is None else {**table, "w_B": _floats(state.w_B), "q_WB": _floats(state.q_WB)}


def _wheel_table(wheel: Any, speed: float) -> dict[str, Any]:
    """A [[body.wheels]] table (t_end left out when the motor never stops: a file holds finite numbers)."""
    table = {"axis_B": _floats(wheel.axis_B), "inertia": float(wheel.inertia), "speed": float(speed),
             "motor_torque": float(wheel.motor_torque), "t_start": float(wheel.t_start)}
    return table if np.isinf(wheel.t_end) else {**table, "t_end": float(wheel.t_end)}


def _rigid_head(body: Any) -> dict[str, Any]:
    """mass, inertia (principal moments when diagonal) and, when needed, inertia_check of a RigidBody."""
    inertia = np.asarray(body.inertia_com, dtype=np.float64)
    table: dict[str, Any] = {"mass": float(body.mass),
                             "inertia": _floats(np.diag(inertia)) if not np.any(inertia - np.diag(np.diag(inertia)))
                             else _floats(inertia)}
    try:
        _core.RigidBody(body.mass, inertia)
    except ValueError:
        table["inertia_check"] = "allow_unrealizable"
    return table


def _mass_flow_table(flow: Any, name: str) -> dict[str, Any]:
    """The [body.mass_flow] table of a MassFlow (ValueError for one given by Python functions)."""
    rate, rule = flow.rate, flow.inertia_rule
    if callable(rate) or not isinstance(rule, str):
        raise _fail(f"{name}.mass_flow", "a constant rate and inertia_rule 'scaled' (a scene file holds no function)",
                    flow)
    return {"rate": float(rate), "inertia_rule": rule}


def _frame_table(frame: Any) -> dict[str, Any]:
    """The [frame] table of a SceneFrame built by SceneFrame.rotating (axis and rate as stored) or
    SceneFrame.earth (its latitude), so that the file reads back bit for bit; ValueError for a general
    moving frame (its motion is a function)."""
    state = frame.__getstate__()  # ("rotating", axis, rate), ("earth", latitude) or ("moving", motion)
    if state[0] == "earth":
        return {"kind": "earth", "latitude": float(state[1])}
    if state[0] == "rotating":
        return {"kind": "rotating", "axis": _floats(state[1]), "rate": float(state[2])}
    raise _fail("scene.frame", "a frame a scene file can hold (SceneFrame.rotating or SceneFrame.earth)", frame)


def _force_table(element: Any, i: int, names: Sequence[str]) -> dict[str, Any]:
    cls = type(element).__name__
    if cls not in _TYPE_OF_CLASS:
        raise _fail(f"scene.elements[{i}]", "an element a scene file can hold (" + ", ".join(_TYPE_OF_CLASS) + ")", cls)
    kind = _TYPE_OF_CLASS[cls]
    table: dict[str, Any] = {"type": kind}
    for key, f in FORCE_TYPES[kind][1].items():
        value = getattr(element, key)
        if f.kind == "scalar" and not math.isfinite(value) and value == f.default:
            continue  # an endless time (a ramp's t_end): the default, left out as a load's is
        if f.kind in ("scalar", "vector"):
            table[key] = _floats(value)
        elif f.kind == "array":
            if len(value):  # empty: the default, left out
                table[key] = _floats(value)
        elif f.kind == "frame":
            table[key] = str(value)
        elif f.kind in ("body", "optional_body"):
            if value is not None:
                table[key] = names[value]
        elif f.kind == "bodies":
            if value is not None:
                table[key] = [names[b] for b in value]
        else:
            table[key] = [_load_table(load) for load in value]
    return table


def _load_table(load: Any) -> dict[str, Any]:
    table = {"force": _floats(load.force), "torque": _floats(load.torque), "frame": str(load.frame)}
    for key in ("t_start", "t_end"):  # infinite: the default, left out
        if math.isfinite(getattr(load, key)):
            table[key] = float(getattr(load, key))
    return table


def scene_to_toml(scene: Any, initial: Sequence[Any] | None = None, run: RunOptions | None = None,
                  name: str | None = None, description: str | None = None) -> str:
    """The canonical scene file of `scene` with `initial` states (one per body; None: none written, the
    bodies start at rest) and `run`: SI units, radians, attitudes as q_WB (x, y, z, w), every field
    explicit except bodies = every body, a world anchor and infinite load times. read_scene of it gives
    the same scene, states and run options. ValueError for an element no file can hold (PythonForce)."""
    if not isinstance(scene, _core.Scene):
        raise TypeError(f"scene: expected a Scene, got {type(scene).__name__}")
    bodies, names, elements = list(scene.bodies), _body_names(scene), list(scene.elements)
    initial = _checked_states(initial, bodies, names)
    first_link = next((i for i, b in enumerate(bodies) if isinstance(b, _core.TreeLink)), len(bodies))
    if any(not isinstance(b, _core.TreeLink) for b in bodies[first_link:]):
        raise ValueError(f"scene: expected the trees' links after every other body (a scene file holds its [[tree]] "
                         f"tables after its [[body]] tables), got body '{names[first_link]}', a tree's link, before "
                         "others")
    if run is not None and not isinstance(run, RunOptions):
        raise TypeError(f"run: expected None or a RunOptions, got {type(run).__name__}")
    for key, text in (("name", name), ("description", description)):
        if text is not None and not isinstance(text, str):
            raise TypeError(f"{key}: expected None or a str, got {type(text).__name__}")
    data: dict[str, Any] = {}
    if name is not None:
        data["name"] = name
    if description:
        data["description"] = description
    if run is not None:
        data["run"] = {k: v for k, v in (("method", run.method), ("dt", run.dt), ("duration", run.duration),
                                         ("record_every", run.record_every)) if v is not None}
    lines = [f"{k} = {_literal(v)}" for k, v in data.items() if k != "run"]
    if "run" in data:
        lines += ["", "[run]"] + [f"{k} = {_literal(v)}" for k, v in data["run"].items()]
    if run is not None and run.tradeoff:
        lines += ["", "[tradeoff]"] + [f"{k} = {_literal(v)}" for k, v in run.tradeoff.items()]
    frame = getattr(scene, "frame", None)
    if frame is not None:
        lines += ["", "[frame]"] + [f"{k} = {_literal(v)}" for k, v in _frame_table(frame).items()]
    flows = list(getattr(scene, "mass_flows", []) or [None] * len(bodies))
    for i, (n, b, s) in enumerate(zip(names[:first_link], bodies[:first_link], initial[:first_link])):
        table = _body_table(n, b, s)
        lines += ["", "[[body]]"] + [f"{k} = {_literal(v)}" for k, v in table.items() if k != "wheels"]
        for wheel in table.get("wheels", []):
            lines += ["[[body.wheels]]"] + [f"{k} = {_literal(v)}" for k, v in wheel.items()]
        if flows[i] is not None:
            lines += ["[body.mass_flow]"] + [f"{k} = {_literal(v)}"
                                             for k, v in _mass_flow_table(flows[i], f"body[{i}]").items()]
    for first in (i for i in range(first_link, len(bodies)) if bodies[i].link == 0):
        tree = bodies[first].tree
        states = None if initial[first] is None else initial[first:first + tree.num_links]
        own = tree.link_names[0]
        prefix = names[first][:-len(own) - 1] if names[first].endswith("." + own) else None
        table = tree_table(prefix, tree, states)
        lines += ["", "[[tree]]"] + ([f"name = {_literal(prefix)}"] if prefix is not None else [])
        for link in table["link"]:
            lines += ["[[tree.link]]"] + [f"{k} = {_literal(v)}" for k, v in link.items()]
    for i, e in enumerate(elements):
        table = _force_table(e, i, names)
        lines += ["", "[[force]]"] + [f"{k} = {_literal(v)}" for k, v in table.items() if k != "loads"]
        for load in table.get("loads", []):
            lines += ["[[force.loads]]"] + [f"{k} = {_literal(v)}" for k, v in load.items()]
    if run is not None and run.controller is not None:
        lines += ["", "[controller]"] + [f"{k} = {_literal(v)}"
                                         for k, v in controller_table(run.controller, scene, names).items()]
    return "\n".join(lines).lstrip("\n") + "\n"


def _literal(value: Any) -> str:
    """A TOML value: arrays on one line (tomli-w writes one entry a line), scalars as tomli-w writes
    them (floats by repr: they read back bit for bit)."""
    import tomli_w

    if isinstance(value, list):
        return "[" + ", ".join(_literal(v) for v in value) + "]"
    return str(tomli_w.dumps({"v": value}, multiline_strings=True))[len("v = "):].rstrip("\n")


def _checked_states(initial: Any, bodies: Sequence[Any], names: Sequence[str]) -> list[Any]:
    """`initial` (None: no states) as a list of one state per body, each of its body's kind."""
    if initial is None:
        return [None] * len(bodies)
    if isinstance(initial, (str, bytes, Mapping)) or not isinstance(initial, Sequence):
        raise TypeError(f"initial: expected None or a sequence of one state per body, got {type(initial).__name__}")
    if len(initial) != len(bodies):
        raise _fail("initial", f"one state per body ({len(bodies)})", f"{len(initial)} states")
    for i, (body, state) in enumerate(zip(bodies, initial)):
        kind = "JointState" if isinstance(body, _core.TreeLink) else type(body).__name__ + "State"  # ParticleState, ...
        if type(state).__name__ != kind:
            raise TypeError(f"initial[{i}]: expected a {kind} (body {names[i]!r} is a {type(body).__name__}), "
                            f"got {type(state).__name__}")
    return list(initial)


def _body_names(scene: Any) -> list[str]:
    """Each body's name ("body<i>" where the scene has none)."""
    names = list(getattr(scene, "body_names", []))
    return [names[i] if i < len(names) and names[i] else f"body{i}" for i in range(len(scene.bodies))]


def _attach() -> None:
    """Scene.to_toml(initial=None, run=None, name=None, description=None) as a method (when the core has Scene)."""
    scene_cls = getattr(_core, "Scene", None)
    if scene_cls is not None and not hasattr(scene_cls, "to_toml"):
        def to_toml(self: Any, initial: Sequence[Any] | None = None, run: RunOptions | None = None,
                    name: str | None = None, description: str | None = None) -> str:
            return scene_to_toml(self, initial, run, name, description)

        to_toml.__doc__ = scene_to_toml.__doc__
        scene_cls.to_toml = to_toml


_attach()
