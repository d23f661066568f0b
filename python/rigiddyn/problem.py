"""TOML problem files: one rigid body, its initial state, applied loads, gravity and a horizon.

``load_problem(path)`` reads a file, ``load_problem("t_handle")`` a shipped example (see
``example_problems()``); ``python -m rigiddyn simulate PROBLEM`` and ``python -m rigiddyn tradeoff
PROBLEM`` take either. Every number may carry a unit as a scene file's do, read by the same code
(rigiddyn.units): a string, a number then its unit (``mass = "200 g"``, ``horizon = "2 min"``,
``w_B = ["1500 rpm", 0, 0]``), or a vector ``{value = [x, y, z], unit = "km"}``; a plain number is SI (m,
kg, s, N, rad) in the unit shown below, with frames as in docs/conventions.md. Angles may also be given in
degrees by ``degrees = true``. Every key the format knows, in one commented file (lines starting
``# key =`` are alternatives)::

    name = "tumbling T-handle"          # optional (default: the file name)
    description = "free text"           # optional
    horizon = 10.0                      # [s] > 0; or with a unit: horizon = "10 s"
    gravity = false                     # false (default) | true = (0, 0, -9.81) | [gx, gy, gz] [m/s^2] in W

    [body]                              # exactly one of: mass + inertia, [body.primitive], [body.mesh]
    mass = 0.2                          # [kg] > 0; or mass = "200 g"
    inertia = [1e-4, 4e-4, 5e-4]        # principal moments [kg m^2], or a 3x3 matrix [[..], [..], [..]],
                                        # about the centre of mass in B
    inertia_check = "physical"          # optional: "physical" (default; the principal moments satisfy
                                        # the triangle inequality) | "allow_unrealizable" (symmetric
                                        # PSD only: test bodies such as Hairer's I = (2, 1, 2/3))
    # [body.primitive]                  # instead of mass + inertia: a shape of PRIMITIVES
    # shape = "solid_box"               # solid_sphere, hollow_sphere, solid_cylinder, ...
    # size = [0.1, 0.2, 0.3]            # [m]: the shape's own keys (PRIMITIVES[shape])
    # mass = 1.0                        # [kg], or density = ... [kg/m^3] (exactly one): "2.7 g/cm^3"
    # [body.mesh]                       # instead: a closed triangle mesh file (needs trimesh);
    # path = "part.stl"                 # relative to the problem file; B = the mesh frame moved to
    # density = 2700.0                  # the centre of mass; [kg/m^3], or mass = ... [kg]

    [initial]                           # all optional: default zero velocities, identity attitude
    p_W = [0, 0, 0]                     # [m]
    v_W = [0, 0, 0]                     # [m/s] in W
    w_B = [0.01, 20, 0]                 # [rad/s] in B; or with a unit of angle per time ("deg/s", "rpm"):
    # w_B = {value = [0, 0, 3000], unit = "rpm"}
    q_WB = [0, 0, 0, 1]                 # attitude (B to W), (x, y, z, w); at most one of q_WB, euler,
                                        # rotvec, axis_angle. Within 1e-3 of unit norm it is normalised
                                        # (a UserWarning notes it where | |q| - 1 | > 1e-12); farther
                                        # is an error.
    scalar_first = false                # optional, only beside q_WB: true reads it as (w, x, y, z)
    # euler = {seq = "ZYX", angles = [30, 10, 0], degrees = true}   # or angles = ["30 deg", "10 deg", 0]
    #                                   # seq as SciPy's: uppercase intrinsic (moving axes), lowercase
    #                                   # extrinsic; angles in the order of seq; [rad] unless degrees
    # rotvec = [0, 0, 0.5]              # rotation vector angle * axis [rad], or in degrees:
    # rotvec = {value = [0, 0, 30], degrees = true}
    # axis_angle = {axis = [0, 0, 1], angle = 30, degrees = true}   # axis of any non-zero length
    # axis_angle = {axis = [0, 0, 1], angle = "30 deg"}

    [[loads]]                           # any number; piecewise constant
    force = [0, 0, 0]                   # [N] through the centre of mass
    torque = [0, 0, 1e-3]               # [N m]
    frame = "body"                      # "world" (default) | "body": the frame of force and torque
    t_start = 0.0                       # [s], optional (default -inf)
    t_end = 5.0                         # [s], optional (default +inf)

    [tradeoff]                          # optional defaults for rigiddyn.tradeoff
    methods = ["rk4", "rkmk4"]
    dts = [0.01, "5 ms"]                # [s]
    tolerance = 1e-6
    measure = "final_attitude_error"

Every error in a file is a ValueError "<field>: expected ..., got ..." naming the field by its path
(``initial.euler.seq``, ``loads[0].frame``), a value of the wrong TOML type included; a key the
format does not know is one too, with the closest known key ("did you mean ...?") or the table it
belongs in. A Problem built directly checks its fields the same way, with TypeError for a value of
the wrong type. Its loads are the core's ``rigiddyn.AppliedLoad`` objects: a ``[[loads]]`` table reads
into one, as a scene file's ``[[force.loads]]`` table does.
"""

from __future__ import annotations

import math
import os
import re
import sys
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import FrameType
from typing import Any, cast

import numpy as np

from . import _core
from ._load_table import LOAD_KEYS, applied_load
from ._loaded_file import RunOptions, SceneFile
from ._mass_properties import MESH_KEYS, PRIMITIVE_KEYS, PRIMITIVES, mass_properties
from ._names import closest as _closest
from ._measures import MEASURES
from .stability import warn_if_unstable
from .units import _shown, quantity, vector_quantity

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised on Python 3.9/3.10 only
    import tomli as tomllib

__all__ = ["PRIMITIVES", "Problem", "example_path", "example_problems", "load_problem", "parse_problem"]

_ORIENTATIONS = ("q_WB", "euler", "rotvec", "axis_angle")  # the forms of the initial attitude
# table -> its keys; a key unknown to its table is looked up in the others ("belongs in [initial]")
_KEYS: dict[str, frozenset[str]] = {
    "problem": frozenset({"name", "description", "horizon", "gravity", "body", "initial", "loads", "tradeoff"}),
    "body": frozenset({"mass", "inertia", "inertia_check", "primitive", "mesh"}),
    "body.primitive": PRIMITIVE_KEYS,
    "body.mesh": MESH_KEYS,
    "initial": frozenset({"p_W", "v_W", "w_B", "scalar_first", *_ORIENTATIONS}),
    "initial.w_B": frozenset({"value", "unit"}),
    "initial.euler": frozenset({"seq", "angles", "degrees"}),
    "initial.rotvec": frozenset({"value", "degrees"}),
    "initial.axis_angle": frozenset({"axis", "angle", "degrees"}),
    "loads": LOAD_KEYS,
    "tradeoff": frozenset({"methods", "dts", "tolerance", "measure"}),
}
# words users write for a key (no misspelling difflib would find)
_SYNONYMS = {"omega": "w_B", "angular_velocity": "w_B", "position": "p_W", "velocity": "v_W",
             "quaternion": "q_WB", "orientation": "q_WB", "attitude": "q_WB", "rotation_vector": "rotvec",
             "moments": "inertia", "inertia_com": "inertia", "duration": "horizon", "t_final": "horizon"}
# keys of earlier versions of the format -> what to write instead
_RENAMED = {("body", "require_triangle_inequality"):
            'inertia_check = "physical" | "allow_unrealizable" in its place (the key was renamed: true '
            'is "physical", false is "allow_unrealizable")'}
_QUATERNION_NORM_TOLERANCE = 1e-3  # | |q| - 1 | up to this: a hand-typed quaternion, normalised
# beyond this (and within the tolerance) the normalisation is noted: far above the few-ulp norm error
# of a unit quaternion computed in double precision and printed in full, so only typed values get it
_QUATERNION_NOTE_THRESHOLD = 1e-12
_EXAMPLES_DIR = Path(__file__).resolve().parent / "problems"
# arrays and tables within each other in a problem or scene file (a 3x3 inertia in a [[body]] is 4 deep);
# deeper text is refused before Python's recursion limit (tomllib reads each level by a recursive call)
MAX_TOML_NESTING = 32
# what the nesting scan of a TOML text looks at: strings and comments (skipped whole), brackets, the dots
# of dotted keys and what ends a key (=, a comma, a newline)
_TOML_SCAN = re.compile(r'''"""(?:[^"\\]|\\.|"(?!""))*"{3,5}|"(?:[^"\\\n]|\\.)*"'''
                        r"""|'''(?:[^']|'(?!''))*'{3,5}|'[^'\n]*'|#[^\n]*|[\[\]{}=,\n.]""", re.DOTALL)


def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {_shown(got)}")


def _type_fail(name: str, expected: str, got: Any) -> TypeError:
    return TypeError(f"{name}: expected {expected}, got {type(got).__name__} {got!r:.60}")


def _string(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise _type_fail(name, "a string", value)
    return value


def _array(value: Any, name: str, shape: tuple[int, ...]) -> np.ndarray:
    """A finite float64 copy of `value` (any array-like of real numbers) of exactly `shape`."""
    expected = f"an array of real numbers of shape {shape}"
    if value is None or isinstance(value, (str, bytes, Mapping)):
        raise _type_fail(name, expected, value)
    try:
        a = np.asarray(value)
    except ValueError:
        raise _fail(name, expected, value) from None
    if a.dtype.kind not in "biuf":
        raise _type_fail(name, expected, value)
    if a.shape != shape:
        raise _fail(name, expected, f"shape {a.shape}")
    a = a.astype(np.float64)
    if not np.all(np.isfinite(a)):
        raise _fail(name, "finite values", a.tolist())
    return a


def _number(value: Any, name: str, positive: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise _fail(name, "a number", value)
    x = float(value) if not isinstance(value, int) or abs(value) <= sys.float_info.max else math.inf
    if not math.isfinite(x) or (positive and x <= 0.0):
        raise _fail(name, "a finite number > 0" if positive else "a finite number", value)
    return x


def _vector(value: Any, name: str, n: int = 3) -> np.ndarray:
    if not isinstance(value, (list, tuple)) or len(value) != n:
        raise _fail(name, f"an array of {n} numbers", value)
    return np.array([_number(v, f"{name}[{i}]") for i, v in enumerate(value)])


def _table(value: Any, name: str, kind: str | None = None, allowed: frozenset[str] | set[str] | None = None
           ) -> Mapping[str, Any]:
    """`value` checked to be a table of known keys: `kind` names its entry of _KEYS (default `name`);
    `allowed` narrows the keys (a primitive's shape)."""
    kind = name if kind is None else kind
    if not isinstance(value, Mapping):
        raise _fail(name, "a table", value)
    known = _KEYS[kind] if allowed is None else frozenset(allowed)
    unknown = sorted(set(value) - known, key=str)
    if unknown:
        raise _unknown_key(name, kind, str(unknown[0]), known, value[unknown[0]])
    return value


def _unknown_key(name: str, kind: str, key: str, known: frozenset[str], value: Any) -> ValueError:
    """"<table>.<key>: expected a key of [<table>]; did you mean '<closest>'? (one of: ...), got an
    unknown key", the hint naming the table where the key belongs if it is no misspelling."""
    field = f"{name}.{key}"
    if (kind, key) in _RENAMED:
        return _fail(field, _RENAMED[kind, key], value)
    close = _closest(key, known)
    if close is None and _SYNONYMS.get(key.lower()) in known:
        close = _SYNONYMS[key.lower()]
    homes = [t for t, keys in _KEYS.items() if key in keys and t != kind]
    if close:
        hint = f"; did you mean {close!r}?"
    elif homes:
        hint = f"; {key!r} belongs in " + " or ".join(_where(t, t) for t in homes)
    else:
        hint = ""
    return ValueError(f"{field}: expected a key of {_where(name, kind)}{hint} (one of: {', '.join(sorted(known))}), "
                      "got an unknown key")


def _where(name: str, kind: str) -> str:
    """The table `name` as a file shows it: the top level, [initial], [[loads]] (loads[0])."""
    if kind == "problem":
        return "the top level"
    if kind == "loads":
        return "[[loads]]" if name == kind else f"[[loads]] ({name})"
    return f"[{name}]"


@dataclass(frozen=True)
class Problem(SceneFile):
    """One rigid body with its initial state, loads, gravity and horizon: what a problem file declares.

    A Problem is the SceneFile of its body's one-body scene (``scene``, ``initial``, ``run``; it unpacks as
    ``scene, initial, run``), with the body's closed-form references that `rigiddyn.tradeoff` computes.

    Every field is checked as a problem file's are (TypeError or ValueError naming it). q_WB within 1e-3 of
    unit norm is normalised (a UserWarning notes it beyond 1e-12), as in a problem file.

    Parameters
    ----------
    name : str
        The problem's name (in reports and plots).
    mass : float
        Mass m [kg], > 0.
    inertia_com : array_like, shape (3, 3)
        Inertia about the centre of mass in B [kg m²], checked by `inertia_check`.
    horizon : float
        Duration of a run [s], > 0.
    p_W, v_W : array_like, shape (3,), default zeros
        Initial position [m] and velocity [m/s] of the centre of mass in W.
    q_WB : array_like, shape (4,), default (0, 0, 0, 1)
        Initial attitude, unit quaternion (x, y, z, w).
    w_B : array_like, shape (3,), default zeros
        Initial angular velocity [rad/s] in B.
    loads : sequence of AppliedLoad, default ()
        Applied forces [N] and torques [N m] with their frames and time windows (stored as a tuple).
    gravity : array_like, shape (3,), default zeros
        Uniform gravity g [m/s²] in W.
    inertia_check : InertiaCheck, default InertiaCheck.physical
        How `inertia_com` is checked (``allow_unrealizable`` accepts moments that violate the triangle
        inequality).
    description : str, default ""
        Free text.
    tradeoff : mapping, default {}
        The sweep defaults of the file's ``[tradeoff]`` table.
    source : str or None, default None
        The file it was read from.

    See Also
    --------
    load_problem : reads one from a TOML file.
    simulate : the run it makes (``Problem.simulate(method, dt)``).

    Examples
    --------
    A body spinning about its intermediate principal axis, exactly, keeps that spin (a relative equilibrium):

    >>> problem = rd.Problem(name="spinner", mass=2.0, inertia_com=np.diag([1.0, 2.0, 3.0]), horizon=10.0,
    ...                      w_B=np.array([0.0, 2.0, 0.0]))
    >>> result = problem.simulate("rk4", 0.01)
    >>> float(result.t[-1]), result.body(0).w_B[-1].round(12)
    (10.0, array([0., 2., 0.]))
    """

    name: str
    mass: float
    inertia_com: np.ndarray
    horizon: float
    p_W: np.ndarray = field(default_factory=lambda: np.zeros(3))
    q_WB: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 0.0, 1.0]))
    v_W: np.ndarray = field(default_factory=lambda: np.zeros(3))
    w_B: np.ndarray = field(default_factory=lambda: np.zeros(3))
    loads: tuple[_core.AppliedLoad, ...] = ()
    gravity: np.ndarray = field(default_factory=lambda: np.zeros(3))
    inertia_check: _core.InertiaCheck = _core.InertiaCheck.physical
    description: str = ""
    tradeoff: Mapping[str, Any] = field(default_factory=dict)
    source: str | None = None

    def __post_init__(self) -> None:
        """Checks every field as a problem file's are checked (TypeError/ValueError naming it: finite,
        mass and horizon > 0, a valid inertia, a unit quaternion to 1e-3, loads of type AppliedLoad);
        stores the vectors as float64 arrays and q_WB normalised."""
        def setf(key: str, value: Any) -> None:  # a frozen dataclass sets its fields this way
            object.__setattr__(self, key, value)

        _string(self.name, "name")
        _string(self.description, "description")
        if self.source is not None:
            _string(self.source, "source")
        if isinstance(self.mass, bool) or not isinstance(self.mass, (int, float, np.integer, np.floating)):
            raise _type_fail("mass", "a mass [kg] > 0", self.mass)
        setf("mass", _number(float(self.mass), "mass", positive=True))
        if isinstance(self.horizon, bool) or not isinstance(self.horizon, (int, float, np.integer, np.floating)):
            raise _type_fail("horizon", "a time span [s] > 0", self.horizon)
        setf("horizon", _number(float(self.horizon), "horizon", positive=True))
        setf("inertia_com", _array(self.inertia_com, "inertia_com", (3, 3)))
        for key in ("p_W", "v_W", "w_B", "gravity"):
            setf(key, _array(getattr(self, key), key, (3,)))
        setf("q_WB", _unit_quaternion(_array(self.q_WB, "q_WB", (4,)), "q_WB"))
        if isinstance(self.loads, (str, bytes)) or not isinstance(self.loads, (tuple, list)):
            raise _type_fail("loads", "a sequence of AppliedLoad", self.loads)
        for i, load in enumerate(self.loads):
            if not isinstance(load, _core.AppliedLoad):
                raise _type_fail(f"loads[{i}]", "an AppliedLoad", load)
        setf("loads", tuple(self.loads))
        if not isinstance(self.inertia_check, _core.InertiaCheck):
            raise _type_fail("inertia_check", "InertiaCheck.physical or InertiaCheck.allow_unrealizable",
                             self.inertia_check)
        if not isinstance(self.tradeoff, Mapping):
            raise _type_fail("tradeoff", "a mapping of sweep defaults (methods, dts, tolerance, measure)", self.tradeoff)
        setf("tradeoff", _tradeoff_defaults(self.tradeoff))
        try:
            self.body()
        except ValueError as e:
            raise _core_error(e, "inertia_com") from None

    @property
    def scene(self) -> Any:
        """The one-body Scene of the body under the gravity and loads (Scene.of_body: the scene simulate(body, ...)
        runs)."""
        return _core.Scene.of_body(self.body(), gravity=self.gravity, loads=list(self.loads))

    @property
    def initial(self) -> list[Any]:
        """[initial_state()]: the body's state at t = 0."""
        return [self.initial_state()]

    @property
    def run(self) -> RunOptions:
        """RunOptions of the problem: duration = horizon [s] and its tradeoff defaults (no method or dt: a problem
        file gives none; Problem.simulate takes them)."""
        return RunOptions(duration=self.horizon, tradeoff=self.tradeoff)

    def body(self) -> _core.RigidBody:
        """The RigidBody of mass [kg] and inertia_com [kg m^2] (B at the centre of mass)."""
        return _core.RigidBody(self.mass, self.inertia_com, check=self.inertia_check)

    def initial_state(self) -> _core.RigidBodyState:
        """The RigidBodyState at t = 0 (p_W [m], q_WB, v_W [m/s] in W, w_B [rad/s] in B)."""
        return _core.RigidBodyState(self.p_W, self.q_WB, self.v_W, self.w_B)

    @property
    def torque_free(self) -> bool:
        """No applied couple: the rotation is the Euler-Poinsot motion (gravity and forces through
        the centre of mass exert no moment about it)."""
        return all(not np.any(load.torque) for load in self.loads)

    @property
    def translation_closed_form(self) -> bool:
        """Every force is fixed in W (or zero): the centre of mass moves on piecewise parabolas."""
        return all(load.frame == "world" or not np.any(load.force) for load in self.loads)

    @property
    def has_exact_solution(self) -> bool:
        return self.torque_free and self.translation_closed_form

    def simulate(self, method: str, dt: float, steps: int | None = None, record_every: int = 1) -> Any:
        """rigiddyn.simulate of this problem (steps default: round(horizon / dt)), after a
        StabilityWarning if dt is beyond the method's linear stability limit for the initial spin
        (rigiddyn.stability). Returns the SceneResult of its one-body scene (``result.body(0)``: the body's records)."""
        _string(method, "method")
        if isinstance(dt, bool) or not isinstance(dt, (int, float, np.integer, np.floating)):
            raise _type_fail("dt", "a time step [s] > 0", dt)
        dt = _number(float(dt), "dt", positive=True)
        if steps is not None and (isinstance(steps, bool) or not isinstance(steps, (int, np.integer))):
            raise _type_fail("steps", "an integer >= 1 (or None: round(horizon / dt))", steps)
        if isinstance(record_every, bool) or not isinstance(record_every, (int, np.integer)):
            raise _type_fail("record_every", "an integer >= 1", record_every)
        steps = max(1, round(self.horizon / dt)) if steps is None else steps
        warn_if_unstable(method, dt, steps, self.inertia_com, self.w_B, self.torque_free, stacklevel=2)
        # method: a str of methods() (mypy knows their literal names), checked by the core
        return _core.simulate(self.body(), self.initial_state(), dt, steps, cast(Any, method), record_every=record_every,
                              loads=list(self.loads), gravity=self.gravity)

    def with_horizon(self, horizon: float) -> Problem:
        """This problem with another horizon [s] > 0."""
        from dataclasses import replace

        if isinstance(horizon, (np.integer, np.floating)):
            horizon = float(horizon)
        return replace(self, horizon=_number(horizon, "horizon", positive=True))


def _core_error(error: ValueError, name: str, args: tuple[str, ...] = ()) -> ValueError:
    """The core's "arg: expected ..." message re-addressed to the problem field `name` (or name.arg)."""
    arg, sep, rest = str(error).partition(": ")
    if not sep or " " in arg:
        return ValueError(f"{name}: {error}")
    return ValueError(f"{name}.{arg}: {rest}" if arg in args else f"{name}: {rest}")


def _body(value: Any, base: Path | None) -> tuple[Any, ...]:
    body = _table(value, "body")
    check_name = body.get("inertia_check", "physical")
    if not isinstance(check_name, str) or check_name not in _core.InertiaCheck.__members__:
        raise _fail("body.inertia_check", " or ".join(map(repr, _core.InertiaCheck.__members__)), check_name)
    check = _core.InertiaCheck.__members__[check_name]
    mass, inertia = mass_properties(body, "body", base)
    try:
        _core.RigidBody(mass, inertia, check=check)
    except ValueError as e:
        raise _core_error(e, "body.inertia") from None
    return mass, inertia, check


def _gravity(value: Any) -> np.ndarray:
    """g [m/s^2] in W: true is (0, 0, -9.81), false none, else a vector (entries may carry units)."""
    if isinstance(value, bool):
        return np.array([0.0, 0.0, -9.81]) if value else np.zeros(3)
    return vector_quantity(value, "gravity", "m/s^2")


def _note(message: str) -> None:
    """A UserWarning attributed to the first caller outside this package (the command line prints it
    as "rigiddyn: UserWarning: ...")."""
    package, level = os.path.dirname(os.path.abspath(__file__)), 2  # 2: the caller of _note
    frame: FrameType | None = sys._getframe(1)
    while frame is not None and (frame.f_code.co_filename == "<string>"  # a dataclass's __init__
                                 or os.path.dirname(os.path.abspath(frame.f_code.co_filename)) == package):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, UserWarning, stacklevel=level)


def _unit_quaternion(q: np.ndarray, name: str) -> np.ndarray:
    """q / |q| for | |q| - 1 | <= 1e-3 (noted beyond 1e-12: a hand-typed value such as 0.7071);
    ValueError naming `name` farther from unit norm, where a typing error is likelier than rounding."""
    norm = float(np.linalg.norm(q))
    if not abs(norm - 1.0) <= _QUATERNION_NORM_TOLERANCE:
        raise ValueError(f"{name}: expected a unit quaternion (| |q| - 1 | <= {_QUATERNION_NORM_TOLERANCE:g}, "
                         f"then normalised), got {q.tolist()} of norm |q| = {norm:.9g}")
    if abs(norm - 1.0) > _QUATERNION_NOTE_THRESHOLD:
        _note(f"{name}: normalised {q.tolist()} (|q| = {norm:.9g}) to unit norm (a quaternion within "
              f"{_QUATERNION_NORM_TOLERANCE:g} of unit norm is normalised, farther is an error)")
    return q / norm


def _degrees_flag(table: Mapping[str, Any], name: str) -> bool:
    degrees = table.get("degrees", False)
    if not isinstance(degrees, bool):
        raise _fail(f"{name}.degrees", "true (angles in degrees) or false (radians)", degrees)
    return degrees


def _angles(values: Any, degrees: bool) -> Any:
    """Angles [rad] from values [deg] if `degrees` (np.deg2rad, as SciPy's degrees=True) else values."""
    return np.deg2rad(values) if degrees else values


def _core_quaternion(convert: Any, name: str, args: tuple[str, ...], *values: Any) -> np.ndarray:
    """The core's conversion `convert(*values)` to q_WB (x, y, z, w); its errors re-addressed to name.arg."""
    try:
        return np.asarray(convert(*values), dtype=np.float64)
    except ValueError as e:
        raise _core_error(e, name, args) from None


def _euler(value: Any) -> np.ndarray:
    name = "initial.euler"
    table = _table(value, name)
    for key in ("seq", "angles"):
        if key not in table:
            raise _fail(f"{name}.{key}", "a value (euler = {seq = \"ZYX\", angles = [..], degrees = true})", "nothing")
    seq = table["seq"]
    if not isinstance(seq, str):
        raise _fail(f"{name}.seq", "an axis sequence such as \"ZYX\" (intrinsic) or \"xyz\" (extrinsic)", seq)
    angles = _angles(_vector(table["angles"], f"{name}.angles"), _degrees_flag(table, name))
    return _core_quaternion(_core.euler_to_quat, name, ("seq", "angles"), seq, angles)


def _rotvec(value: Any) -> np.ndarray:
    name = "initial.rotvec"
    if not isinstance(value, (Mapping, list, tuple)):
        raise _fail(name, "an array of 3 numbers [rad] or a table {value = [x, y, z], degrees = true}", value)
    if isinstance(value, Mapping):
        table = _table(value, name)
        if "value" not in table:
            raise _fail(f"{name}.value", "a rotation vector angle * axis [rad, or deg if degrees = true]", "nothing")
        rotvec = _angles(_vector(table["value"], f"{name}.value"), _degrees_flag(table, name))
    else:
        rotvec = _vector(value, name)
    return _core_quaternion(_core.rotvec_to_quat, name, ("rotvec",), rotvec)


def _axis_angle(value: Any) -> np.ndarray:
    name = "initial.axis_angle"
    table = _table(value, name)
    for key in ("axis", "angle"):
        if key not in table:
            raise _fail(f"{name}.{key}", "a value (axis_angle = {axis = [x, y, z], angle = .., degrees = true})",
                        "nothing")
    axis = _vector(table["axis"], f"{name}.axis")
    angle = float(_angles(_number(table["angle"], f"{name}.angle"), _degrees_flag(table, name)))
    return _core_quaternion(_core.axis_angle_to_quat, name, ("axis", "angle"), axis, angle)


def _angles_in_radians(table: Mapping[str, Any], name: str) -> dict[str, Any]:
    """The attitude keys of the table `name` ([initial], a scene file's [[body]]) with every angle that carries
    a unit ("30 deg") converted to radians, for _orientation (which reads numbers and a `degrees` flag)."""
    out = {k: table[k] for k in (*_ORIENTATIONS, "scalar_first") if k in table}

    def has_unit(value: Any) -> bool:
        return isinstance(value, str) or (isinstance(value, list) and any(isinstance(v, str) for v in value))

    for key, angle_key in (("euler", "angles"), ("axis_angle", "angle"), ("rotvec", "value")):
        sub = out.get(key)
        if isinstance(sub, Mapping) and has_unit(sub.get(angle_key)):
            value = sub[angle_key]
            field = f"{name}.{key}.{angle_key}"
            converted = (quantity(value, field, "rad") if isinstance(value, str)
                         else list(vector_quantity(value, field, "rad", len(value))))
            if sub.get("degrees", False) is True:
                raise _fail(f"{name}.{key}.degrees", "no degrees flag beside angles with units", True)
            out[key] = {**{k: v for k, v in sub.items() if k != "degrees"}, angle_key: converted}
    if isinstance(out.get("rotvec"), list) and has_unit(out["rotvec"]):
        out["rotvec"] = list(vector_quantity(out["rotvec"], f"{name}.rotvec", "rad"))
    return out


def _orientation(table: Mapping[str, Any]) -> np.ndarray | None:
    """q_WB (x, y, z, w) from the one orientation form in [initial], or None if none is given."""
    table = _angles_in_radians(table, "initial")
    given = [k for k in _ORIENTATIONS if k in table]
    if len(given) > 1:
        raise ValueError("initial: expected at most one orientation of " + ", ".join(_ORIENTATIONS) +
                         ", got " + " and ".join(given))
    scalar_first = table.get("scalar_first", False)
    if not isinstance(scalar_first, bool):
        raise _fail("initial.scalar_first", "true or false", scalar_first)
    if "scalar_first" in table and given != ["q_WB"]:
        raise ValueError("initial.scalar_first: expected it only beside q_WB (it orders q_WB's components), got "
                         + (f"it with {given[0]}" if given else "it without q_WB"))
    if not given:
        return None
    if given[0] == "q_WB":
        q = _vector(table["q_WB"], "initial.q_WB", 4)
        return _unit_quaternion(np.roll(q, -1) if scalar_first else q, "initial.q_WB")
    return {"euler": _euler, "rotvec": _rotvec, "axis_angle": _axis_angle}[given[0]](table[given[0]])


def _angular_rate(value: Any, name: str) -> np.ndarray:
    """An angular rate [rad/s] from [x, y, z] (entries may carry units: "1500 rpm") or {value = [x, y, z],
    unit = "rpm"} (any unit of angle per time: "rad/s", "deg/s", "rpm", "turn/s")."""
    if isinstance(value, Mapping):
        _table(value, name, "initial.w_B")
    return vector_quantity(value, name, "rad/s")


def _initial(value: Any) -> dict[str, np.ndarray]:
    table = _table(value, "initial")
    out = {k: vector_quantity(table[k], f"initial.{k}", unit) for k, unit in (("p_W", "m"), ("v_W", "m/s"))
           if k in table}
    if "w_B" in table:
        out["w_B"] = _angular_rate(table["w_B"], "initial.w_B")
    q_WB = _orientation(table)
    if q_WB is not None:
        out["q_WB"] = q_WB
    return out


def _loads(value: Any) -> tuple[Any, ...]:
    """The [[loads]] tables (rigiddyn._load_table: force [N], torque [N m], frame, t_start, t_end [s])."""
    if not isinstance(value, list):
        raise _fail("loads", "an array of tables [[loads]]", value)
    return tuple(applied_load(_table(item, f"loads[{i}]", "loads"), f"loads[{i}]") for i, item in enumerate(value))


def _tradeoff_defaults(value: Any) -> dict[str, Any]:
    table = dict(_table(value, "tradeoff"))
    if "dts" in table:
        dts = table["dts"]
        if not isinstance(dts, list) or not dts:
            raise _fail("tradeoff.dts", "a non-empty array of steps [s]", dts)
        table["dts"] = [quantity(d, f"tradeoff.dts[{i}]", "s", positive=True) for i, d in enumerate(dts)]
    if "methods" in table:
        names = {m["name"] for m in _core.methods()}
        methods = table["methods"]
        if not isinstance(methods, list) or not methods:
            raise _fail("tradeoff.methods", "a non-empty array of method names", methods)
        for i, m in enumerate(methods):
            if not isinstance(m, str) or m not in names:  # a list or table is no name (nor hashable)
                raise _fail(f"tradeoff.methods[{i}]", "one of " + ", ".join(sorted(names)), m)
    if "tolerance" in table:
        table["tolerance"] = _number(table["tolerance"], "tradeoff.tolerance", positive=True)
    if "measure" in table:
        if not isinstance(table["measure"], str) or table["measure"] not in MEASURES:
            raise _fail("tradeoff.measure", "one of " + ", ".join(MEASURES), table["measure"])
    return table


def parse_problem(data: Mapping[str, Any], base: str | Path | None = None,
                  source: str | None = None) -> Problem:
    """A Problem from parsed TOML `data`; `base` is the folder that relative mesh paths refer to."""
    _check_nesting(data, source or "problem")
    data = _table(data, "problem")
    if "horizon" not in data:
        raise _fail("horizon", "a time span [s] > 0", "nothing")
    if "body" not in data:
        raise _fail("body", "a [body] table", "nothing")
    name = data.get("name", source or "problem")
    if not isinstance(name, str):
        raise _fail("name", "a string", name)
    description = data.get("description", "")
    if not isinstance(description, str):
        raise _fail("description", "a string", description)
    mass, inertia, check = _body(data["body"], Path(base) if base is not None else None)
    return Problem(name=name, description=description, mass=mass, inertia_com=inertia,
                   horizon=quantity(data["horizon"], "horizon", "s", positive=True),
                   loads=_loads(data.get("loads", [])), gravity=_gravity(data.get("gravity", False)),
                   inertia_check=check, tradeoff=_tradeoff_defaults(data.get("tradeoff", {})),
                   source=source, **_initial(data.get("initial", {})))


def example_problems() -> list[str]:
    """Names of the shipped example problems (rigiddyn/problems/*.toml)."""
    return sorted(p.stem for p in _EXAMPLES_DIR.glob("*.toml"))


def example_path(name: str, argument: str = "name") -> Path:
    """The file of the shipped example `name` (ValueError naming `argument` for an unknown one)."""
    _string(name, argument)
    path = _EXAMPLES_DIR / f"{name}.toml"
    if not path.is_file():
        raise _fail(argument, "a .toml path or one of the examples " + ", ".join(example_problems()), name)
    return path


def load_problem(path_or_name: str | Path) -> Problem:
    """Read a one-body problem: a rigid body, its initial state, loads, gravity and horizon from a TOML file.

    Parameters
    ----------
    path_or_name : str or pathlib.Path
        A ``.toml`` problem file, or the name of a shipped example (``rigiddyn.problem.example_problems()``:
        ``"t_handle"``, ``"fast_top"``, ``"projectile"``, ``"satellite_torque"``).

    Returns
    -------
    Problem
        The body (``Problem.body()``), initial state (``Problem.initial_state()``), loads, gravity [m/s²] in W
        and horizon [s]; ``Problem.simulate(method, dt)`` runs it. A Problem is a ``SceneFile``, as
        ``load_scene`` returns: it unpacks as ``scene, initial, run`` (its one-body scene).

    Raises
    ------
    TypeError, ValueError
        A path that is neither a file nor an example name, or a key or value the format does not accept (the
        message names it).

    See Also
    --------
    load_scene : a scene file (any number of bodies and force elements).
    tradeoff : every method's cost and accuracy on the problem.

    Notes
    -----
    A problem file is a scene file of one ``rigid`` body plus the problem's run settings, its tables read by
    the same code as a scene file's: ``[body]`` is that body's mass properties (``mass`` and ``inertia``, a
    ``[body.primitive]`` or a ``[body.mesh]``, as a scene file's ``[[body]]`` gives them), ``[initial]`` its
    initial state (the keys ``p_W``, ``v_W``, ``w_B`` and the attitude of a ``rigid`` ``[[body]]``), ``gravity``
    a ``uniform_gravity`` element, each ``[[loads]]`` table an ``AppliedLoad`` of a ``scheduled_loads`` element on
    the body (read as a ``[[force.loads]]`` table), ``horizon`` the ``[run]`` duration, and ``[tradeoff]`` the
    same table; every number may carry a unit (``mass = "200 g"``). What differs: the result is a `Problem` (one
    RigidBody, its state, loads, gravity and horizon: the SceneFile of its one-body scene), for the closed-form
    references that ``rd.tradeoff`` computes on one body; a problem file has no ``[run]`` method or step
    (``Problem.simulate(method, dt)`` takes them), no second body, force element, ``[frame]``, gyrostat wheels or
    mass flow (write a scene file for these); and a ``q_WB`` is always divided by its norm, where a scene file
    keeps one of unit norm to 4 ulp bit for bit.

    Examples
    --------
    The T-handle spinning about its intermediate axis (Dzhanibekov effect); RK4 at 1 ms keeps its kinetic
    energy to 1e-8 over the 4 s horizon:

    >>> problem = rd.load_problem("t_handle")
    >>> problem.mass, problem.horizon
    (0.1, 4.0)
    >>> result = problem.simulate("rk4", 1e-3)
    >>> result.body(0).q_WB.shape
    (4001, 4)
    >>> T = result.kinetic_energy
    >>> bool(abs(T[-1] - T[0]) < 1e-8 * T[0])
    True
    """
    expected = "an existing .toml file or one of the examples " + ", ".join(example_problems())
    if not isinstance(path_or_name, (str, Path)):
        raise _type_fail("path_or_name", expected, path_or_name)
    path = Path(path_or_name)
    if not path.is_file():
        if path.suffix or len(path.parts) > 1:
            raise _fail("path_or_name", expected, str(path_or_name))
        path = example_path(str(path_or_name), "path_or_name")
    try:
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError as e:
        raise ValueError(f"{path}: expected a UTF-8 text file, got {e}") from None
    return parse_problem(_read_toml(text, str(path)), base=path.parent, source=str(path))


def _read_toml(text: str, source: str) -> dict[str, Any]:
    """The parsed TOML `text` of the file `source` (a problem or scene file): ValueError naming `source`
    for invalid TOML or for arrays and inline tables nested beyond Python's recursion limit (the parsers
    of the data, parse_problem and parse_scene, refuse more than MAX_TOML_NESTING levels)."""
    _check_text_nesting(text, source)
    try:
        data = tomllib.loads(text)
    except ValueError as e:  # TOMLDecodeError, or an integer of more digits than int() converts
        raise ValueError(f"{source}: expected valid TOML, got {e}") from None
    except RecursionError:  # tomllib recurses once per level of an array or inline table (a deep caller's stack)
        raise _nesting_error(source) from None
    return data


def _check_text_nesting(text: str, source: str) -> None:
    """ValueError naming `source` when, outside strings and comments, brackets [ { are open more than
    MAX_TOML_NESTING deep or a dotted key has more than MAX_TOML_NESTING parts: one pass over the text
    before tomllib reads it (its time grows with the square of a dotted key's parts: 5 s for 10^4)."""
    depth = dots = 0
    for token in _TOML_SCAN.finditer(text):
        c = token.group()[0]
        if c in "[{":
            depth, dots = depth + 1, 0
        elif c in "]}":
            depth, dots = max(depth - 1, 0), 0
        elif c == ".":
            dots += 1
        elif c in "=,\n":
            dots = 0
        if depth > MAX_TOML_NESTING or dots >= MAX_TOML_NESTING:
            raise _nesting_error(source)


def _check_nesting(data: Any, source: str) -> None:
    """ValueError naming `source` when arrays and tables (lists, tuples, mappings) lie within each other more
    than MAX_TOML_NESTING deep in `data` (dotted keys a.b.c... build such tables without tomllib
    recursing; what reads them would). Walks the values without recursion."""
    stack = [(data, 0)]
    while stack:
        value, depth = stack.pop()
        if isinstance(value, Mapping):
            children: Any = value.values()
        elif isinstance(value, (list, tuple)):
            children = value
        else:
            continue
        if depth == MAX_TOML_NESTING:
            raise _nesting_error(source)
        stack.extend((child, depth + 1) for child in children)


def _nesting_error(source: str) -> ValueError:
    return ValueError(f"{source}: expected arrays and tables nested at most {MAX_TOML_NESTING} deep, got deeper ones")
