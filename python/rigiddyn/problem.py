"""TOML problem files: one rigid body, its initial state, applied loads, gravity and a horizon.

A problem file (SI units, frames as in docs/conventions.md)::

    name = "tumbling T-handle"
    description = "free text"
    horizon = 10.0                      # [s] > 0
    gravity = false                     # false | true (0, 0, -9.81) | [gx, gy, gz] [m/s^2] in W

    [body]                              # exactly one of: mass + inertia, primitive, mesh
    mass = 0.2                          # [kg] > 0
    inertia = [1e-4, 4e-4, 5e-4]        # principal moments [kg m^2], or a (3, 3) matrix about the
                                        # centre of mass in B
    require_triangle_inequality = true  # optional (false accepts e.g. Hairer's I = (2, 1, 2/3))
    # [body.primitive]  shape = "solid_box", size = [0.1, 0.2, 0.3], mass = 1.0 (or density = ...)
    # [body.mesh]       path = "part.stl" (relative to the file), mass = ... or density = ...
    #                   (needs trimesh; B is the mesh frame moved to the centre of mass)

    [initial]                           # all optional, default zero / identity
    p_W = [0, 0, 0]                     # [m]
    q_WB = [0, 0, 0, 1]                 # (x, y, z, w) unless scalar_first = true
    v_W = [0, 0, 0]                     # [m/s]
    w_B = [0.01, 20, 0]                 # [rad/s] in B

    [[loads]]                           # any number; piecewise constant
    force = [0, 0, 0]                   # [N] through the centre of mass
    torque = [0, 0, 1e-3]               # [N m]
    frame = "body"                      # "world" | "body"
    t_start = 0.0                       # [s], optional (default -inf)
    t_end = 5.0                         # [s], optional (default +inf)

    [tradeoff]                          # optional defaults for rigiddyn.tradeoff
    methods = ["rk4", "rkmk4"]
    dts = [0.01, 0.005]
    tolerance = 1e-6
    measure = "final_attitude_error"

Every error in a file is a ValueError "<field>: expected ..., got ..." (a value of the wrong TOML type
included); Problem and Load built directly check their fields the same way, with TypeError for a
value of the wrong type.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from . import _core
from .stability import warn_if_unstable

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - exercised on Python 3.9/3.10 only
    import tomli as tomllib

__all__ = ["PRIMITIVES", "Load", "Problem", "example_path", "example_problems", "load_problem", "parse_problem"]

# primitive shape -> its size arguments (the rigiddyn constructor of the same name)
PRIMITIVES: dict[str, tuple[str, ...]] = {
    "solid_sphere": ("radius",),
    "hollow_sphere": ("outer_radius", "inner_radius"),
    "spherical_shell": ("radius",),
    "solid_box": ("size",),
    "box_shell": ("size",),
    "solid_cylinder": ("radius", "height"),
    "hollow_cylinder": ("outer_radius", "inner_radius", "height"),
    "thin_rod": ("length",),
    "thin_disk": ("radius",),
    "thin_plate": ("size_x", "size_y"),
    "solid_cone": ("radius", "height"),
    "solid_ellipsoid": ("semi_axes",),
    "solid_capsule": ("radius", "length"),
}
_VECTOR_ARGS = {"size", "semi_axes"}
_TOP_KEYS = {"name", "description", "horizon", "gravity", "body", "initial", "loads", "tradeoff"}
_TRADEOFF_KEYS = {"methods", "dts", "tolerance", "measure"}
_EXAMPLES_DIR = Path(__file__).resolve().parent / "problems"


def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {got!r}")


def _type_fail(name: str, expected: str, got: Any) -> TypeError:
    return TypeError(f"{name}: expected {expected}, got {type(got).__name__} {got!r:.60}")


def _string(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise _type_fail(name, "a string", value)
    return value


def _flag(value: Any, name: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise _type_fail(name, "True or False", value)
    return bool(value)


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
    x = float(value)
    if not math.isfinite(x) or (positive and x <= 0.0):
        raise _fail(name, "a finite number > 0" if positive else "a finite number", value)
    return x


def _vector(value: Any, name: str, n: int = 3) -> np.ndarray:
    if not isinstance(value, (list, tuple)) or len(value) != n:
        raise _fail(name, f"an array of {n} numbers", value)
    return np.array([_number(v, f"{name}[{i}]") for i, v in enumerate(value)])


def _table(value: Any, name: str, allowed: set[str]) -> Mapping[str, Any]:
    if not isinstance(value, Mapping):
        raise _fail(name, "a table", value)
    unknown = sorted(set(value) - allowed)
    if unknown:
        raise _fail(f"{name}.{unknown[0]}", "one of the keys " + ", ".join(sorted(allowed)), "an unknown key")
    return value


@dataclass(frozen=True)
class Load:
    """A constant load active for t_start <= t < t_end [s]: force (3,) [N] through the centre of
    mass and couple torque (3,) [N m], both expressed in `frame` ('world' or 'body')."""

    force: np.ndarray
    torque: np.ndarray
    frame: str = "world"
    t_start: float = -math.inf
    t_end: float = math.inf

    def __post_init__(self) -> None:
        """Checks every field (TypeError/ValueError naming it); stores the vectors as float64 (3,)."""
        object.__setattr__(self, "force", _array(self.force, "force", (3,)))
        object.__setattr__(self, "torque", _array(self.torque, "torque", (3,)))
        if _string(self.frame, "frame") not in ("world", "body"):
            raise _fail("frame", "'world' or 'body'", self.frame)
        for key in ("t_start", "t_end"):
            value = getattr(self, key)
            if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
                raise _type_fail(key, "a time [s] (+-inf allowed)", value)
            if math.isnan(value):
                raise _fail(key, "a time [s] (+-inf allowed)", value)
            object.__setattr__(self, key, float(value))
        if not self.t_start < self.t_end:
            raise _fail("t_end", f"a time > t_start = {self.t_start}", self.t_end)

    def applied_load(self) -> _core.AppliedLoad:
        return _core.AppliedLoad(self.force, self.torque, self.frame, self.t_start, self.t_end)


@dataclass(frozen=True)
class Problem:
    """One rigid body: mass [kg], inertia_com (3, 3) [kg m^2] about the centre of mass in B, initial
    state (p_W [m], q_WB (x, y, z, w), v_W [m/s] in W, w_B [rad/s] in B), loads, gravity (3,)
    [m/s^2] in W and horizon [s]. `tradeoff` holds the file's optional sweep defaults."""

    name: str
    mass: float
    inertia_com: np.ndarray
    horizon: float
    p_W: np.ndarray = field(default_factory=lambda: np.zeros(3))
    q_WB: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, 0.0, 1.0]))
    v_W: np.ndarray = field(default_factory=lambda: np.zeros(3))
    w_B: np.ndarray = field(default_factory=lambda: np.zeros(3))
    loads: tuple[Load, ...] = ()
    gravity: np.ndarray = field(default_factory=lambda: np.zeros(3))
    require_triangle_inequality: bool = True
    description: str = ""
    tradeoff: Mapping[str, Any] = field(default_factory=dict)
    source: str | None = None

    def __post_init__(self) -> None:
        """Checks every field as a problem file's are checked (TypeError/ValueError naming it: finite,
        mass and horizon > 0, a valid inertia, a unit quaternion, loads of type Load); stores the
        vectors as float64 arrays and q_WB normalised."""
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
        q = _array(self.q_WB, "q_WB", (4,))
        if abs(np.linalg.norm(q) - 1.0) > 1e-6:
            raise _fail("q_WB", "a unit quaternion (x, y, z, w) (| |q| - 1 | <= 1e-6)", q.tolist())
        setf("q_WB", q / np.linalg.norm(q))
        if isinstance(self.loads, (str, bytes)) or not isinstance(self.loads, (tuple, list)):
            raise _type_fail("loads", "a sequence of Load", self.loads)
        for i, load in enumerate(self.loads):
            if not isinstance(load, Load):
                raise _type_fail(f"loads[{i}]", "a Load", load)
        setf("loads", tuple(self.loads))
        _flag(self.require_triangle_inequality, "require_triangle_inequality")
        if not isinstance(self.tradeoff, Mapping):
            raise _type_fail("tradeoff", "a mapping of sweep defaults (methods, dts, tolerance, measure)", self.tradeoff)
        setf("tradeoff", _tradeoff_defaults(self.tradeoff))
        try:
            _core.RigidBody(self.mass, self.inertia_com, self.require_triangle_inequality)
        except ValueError as e:
            raise _core_error(e, "inertia_com") from None

    def body(self) -> _core.RigidBody:
        return _core.RigidBody(self.mass, self.inertia_com, self.require_triangle_inequality)

    def initial_state(self) -> _core.RigidBodyState:
        return _core.RigidBodyState(self.p_W, self.q_WB, self.v_W, self.w_B)

    def applied_loads(self) -> list[_core.AppliedLoad]:
        return [load.applied_load() for load in self.loads]

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
        (rigiddyn.stability). Returns the SimulationResult."""
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
        return _core.simulate(self.body(), self.initial_state(), dt, steps, method, record_every=record_every,
                              loads=self.applied_loads(), gravity=self.gravity)

    def with_horizon(self, horizon: float) -> Problem:
        """This problem with another horizon [s] > 0."""
        from dataclasses import replace

        if isinstance(horizon, (np.integer, np.floating)):
            horizon = float(horizon)
        return replace(self, horizon=_number(horizon, "horizon", positive=True))


def _inertia_matrix(value: Any, name: str) -> np.ndarray:
    if isinstance(value, (list, tuple)) and len(value) == 3 and all(isinstance(r, (list, tuple)) for r in value):
        return np.array([_vector(row, f"{name}[{i}]") for i, row in enumerate(value)])
    if isinstance(value, (list, tuple)) and len(value) == 3:
        return np.diag(_vector(value, name))
    raise _fail(name, "3 principal moments [I1, I2, I3] or a 3x3 matrix [kg m^2]", value)


def _core_error(error: ValueError, name: str, args: tuple[str, ...] = ()) -> ValueError:
    """The core's "arg: expected ..." message re-addressed to the problem field `name` (or name.arg)."""
    arg, sep, rest = str(error).partition(": ")
    if not sep or " " in arg:
        return ValueError(f"{name}: {error}")
    return ValueError(f"{name}.{arg}: {rest}" if arg in args else f"{name}: {rest}")


def _mass_or_density(table: Mapping[str, Any], name: str) -> dict[str, float]:
    given = [k for k in ("mass", "density") if k in table]
    if len(given) != 1:
        raise _fail(name, "exactly one of mass = [kg] or density =", "both" if len(given) == 2 else "neither")
    key = given[0]
    return {key: _number(table[key], f"{name}.{key}", positive=True)}


def _primitive(table: Any) -> tuple[Any, ...]:
    name = "body.primitive"
    if not isinstance(table, Mapping) or "shape" not in table:
        raise _fail(f"{name}.shape", "one of " + ", ".join(PRIMITIVES), table.get("shape") if isinstance(table, Mapping) else table)
    shape = table["shape"]
    if not isinstance(shape, str) or shape not in PRIMITIVES:
        raise _fail(f"{name}.shape", "one of " + ", ".join(PRIMITIVES), shape)
    args = PRIMITIVES[shape]
    _table(table, name, {"shape", "mass", "density", *args})
    values = []
    for arg in args:
        if arg not in table:
            raise _fail(f"{name}.{arg}", f"a value (shape {shape!r} needs {', '.join(args)})", "nothing")
        values.append(_vector(table[arg], f"{name}.{arg}") if arg in _VECTOR_ARGS else
                      _number(table[arg], f"{name}.{arg}", positive=True))
    mass_or_density = _mass_or_density(table, name)  # its own errors name body.primitive.mass/density
    try:
        inertia = getattr(_core, shape)(*values, **mass_or_density)
    except ValueError as e:
        raise _core_error(e, name, args) from None
    return inertia.mass, np.array(inertia.inertia_com)


def _mesh(table: Any, base: Path | None) -> tuple[Any, ...]:
    name = "body.mesh"
    table = _table(table, name, {"path", "mass", "density"})
    if not isinstance(table.get("path"), str):
        raise _fail(f"{name}.path", "a mesh file path (string)", table.get("path"))
    path = Path(table["path"])
    if not path.is_absolute() and base is not None:
        path = base / path
    if not path.is_file():
        raise _fail(f"{name}.path", "an existing mesh file", str(path))
    try:
        import trimesh
    except ImportError:
        raise ImportError("body.mesh: reading mesh files needs trimesh (pip install trimesh)") from None
    mass_or_density = _mass_or_density(table, name)  # its own errors name body.mesh.mass/density
    mesh = trimesh.load(str(path), force="mesh")
    try:
        inertia = _core.solid_mesh(np.asarray(getattr(mesh, "vertices"), float),  # a trimesh.Trimesh
                                   np.asarray(getattr(mesh, "faces"), np.int64), **mass_or_density)
    except ValueError as e:
        raise _core_error(e, name) from None
    return inertia.mass, np.array(inertia.inertia_com)


def _body(value: Any, base: Path | None) -> tuple[Any, ...]:
    body = _table(value, "body", {"mass", "inertia", "primitive", "mesh", "require_triangle_inequality"})
    sources = [k for k in ("inertia", "primitive", "mesh") if k in body]
    if len(sources) != 1:
        raise _fail("body", "exactly one of inertia (with mass), primitive or mesh", sources or "none")
    triangle = body.get("require_triangle_inequality", True)
    if not isinstance(triangle, bool):
        raise _fail("body.require_triangle_inequality", "true or false", triangle)
    if sources[0] == "inertia":
        if "mass" not in body:
            raise _fail("body.mass", "a mass [kg] > 0 next to body.inertia", "nothing")
        mass, inertia = _number(body["mass"], "body.mass", positive=True), _inertia_matrix(body["inertia"], "body.inertia")
    elif "mass" in body:
        raise _fail("body.mass", f"no mass outside body.{sources[0]} (give it there)", body["mass"])
    elif sources[0] == "primitive":
        mass, inertia = _primitive(body["primitive"])
    else:
        mass, inertia = _mesh(body["mesh"], base)
    try:
        _core.RigidBody(mass, inertia, triangle)
    except ValueError as e:
        raise _core_error(e, "body.inertia") from None
    return mass, inertia, triangle


def _gravity(value: Any) -> np.ndarray:
    if isinstance(value, bool):
        return np.array([0.0, 0.0, -9.81]) if value else np.zeros(3)
    return _vector(value, "gravity")


def _initial(value: Any) -> dict[str, np.ndarray]:
    table = _table(value, "initial", {"p_W", "q_WB", "v_W", "w_B", "scalar_first"})
    scalar_first = table.get("scalar_first", False)
    if not isinstance(scalar_first, bool):
        raise _fail("initial.scalar_first", "true or false", scalar_first)
    out = {k: _vector(table[k], f"initial.{k}") for k in ("p_W", "v_W", "w_B") if k in table}
    if "q_WB" in table:
        q = _vector(table["q_WB"], "initial.q_WB", 4)
        if scalar_first:
            q = np.roll(q, -1)
        if abs(np.linalg.norm(q) - 1.0) > 1e-6:
            raise _fail("initial.q_WB", "a unit quaternion (| |q| - 1 | <= 1e-6)", table["q_WB"])
        out["q_WB"] = q / np.linalg.norm(q)
    return out


def _loads(value: Any) -> tuple[Any, ...]:
    if not isinstance(value, list):
        raise _fail("loads", "an array of tables [[loads]]", value)
    loads = []
    for i, item in enumerate(value):
        name = f"loads[{i}]"
        table = _table(item, name, {"force", "torque", "frame", "t_start", "t_end"})
        frame = table.get("frame", "world")
        if frame not in ("world", "body"):
            raise _fail(f"{name}.frame", "'world' or 'body'", frame)
        t_start = _number(table["t_start"], f"{name}.t_start") if "t_start" in table else -math.inf
        t_end = _number(table["t_end"], f"{name}.t_end") if "t_end" in table else math.inf
        if not t_start < t_end:
            raise _fail(f"{name}.t_end", f"a time > t_start = {t_start}", t_end)
        zero = np.zeros(3)
        loads.append(Load(_vector(table["force"], f"{name}.force") if "force" in table else zero,
                          _vector(table["torque"], f"{name}.torque") if "torque" in table else zero,
                          frame, t_start, t_end))
    return tuple(loads)


def _tradeoff_defaults(value: Any) -> dict[str, Any]:
    table = dict(_table(value, "tradeoff", _TRADEOFF_KEYS))
    if "dts" in table:
        dts = table["dts"]
        if not isinstance(dts, list) or not dts:
            raise _fail("tradeoff.dts", "a non-empty array of steps [s]", dts)
        table["dts"] = [_number(d, f"tradeoff.dts[{i}]", positive=True) for i, d in enumerate(dts)]
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
        from .tradeoff import MEASURES  # imported here: rigiddyn.tradeoff imports this module

        if not isinstance(table["measure"], str) or table["measure"] not in MEASURES:
            raise _fail("tradeoff.measure", "one of " + ", ".join(MEASURES), table["measure"])
    return table


def parse_problem(data: Mapping[str, Any], base: str | Path | None = None,
                  source: str | None = None) -> Problem:
    """A Problem from parsed TOML `data`; `base` is the folder that relative mesh paths refer to."""
    data = _table(data, "problem", _TOP_KEYS)
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
    mass, inertia, triangle = _body(data["body"], Path(base) if base is not None else None)
    return Problem(name=name, description=description, mass=mass, inertia_com=inertia,
                   horizon=_number(data["horizon"], "horizon", positive=True),
                   loads=_loads(data.get("loads", [])), gravity=_gravity(data.get("gravity", False)),
                   require_triangle_inequality=triangle, tradeoff=_tradeoff_defaults(data.get("tradeoff", {})),
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
    """Read a TOML problem file, or a shipped example by name (see example_problems())."""
    expected = "an existing .toml file or one of the examples " + ", ".join(example_problems())
    if not isinstance(path_or_name, (str, Path)):
        raise _type_fail("path_or_name", expected, path_or_name)
    path = Path(path_or_name)
    if not path.is_file():
        if path.suffix or len(path.parts) > 1:
            raise _fail("path_or_name", expected, str(path_or_name))
        path = example_path(str(path_or_name), "path_or_name")
    with open(path, "rb") as f:
        try:
            data = tomllib.load(f)
        except tomllib.TOMLDecodeError as e:
            raise ValueError(f"{path}: expected valid TOML, got {e}") from None
    return parse_problem(data, base=path.parent, source=str(path))
