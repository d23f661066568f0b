"""The mass properties a body table declares, in a problem file's [body] and a scene file's [[body]] alike.

A table gives exactly one of:

- ``mass`` [kg] with ``inertia`` [kg m^2]: principal moments or a 3x3 matrix about the centre of mass in B
  (the matrix with the *negated* products off the diagonal, as docs/conventions.md says);
- a ``primitive`` table: ``shape``, one of PRIMITIVES, its size keys [m] (PRIMITIVES[shape], the arguments of
  the rigiddyn constructor of that name) and ``mass`` [kg] or ``density`` [kg/m^3];
- a ``mesh`` table: ``path`` of a closed triangle mesh file (read by trimesh; relative to the file's folder),
  B being the mesh frame moved to the centre of mass, and ``mass`` [kg] or ``density`` [kg/m^3].

Every number may carry a unit (rigiddyn.units: ``"200 g"``, ``"4 cm"``, ``"2.7 g/cm^3"``); every error is a
ValueError "<field>: expected ..., got ..." naming the field by its path in the file (``body.primitive.radius``,
``body[2].mesh.density``).
"""

from __future__ import annotations

import functools
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from . import _core
from ._core_call import core_call
from ._names import check_keys, closest
from .units import _shown, quantity, vector_quantity

# primitive shape -> its size arguments [m] (the rigiddyn constructor of the same name)
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
_VECTOR_ARGS = {"size", "semi_axes"}  # size arguments of three lengths; the others are one length
PRIMITIVE_KEYS = frozenset({"shape", "mass", "density"}.union(*PRIMITIVES.values()))
MESH_KEYS = frozenset({"path", "mass", "density"})
SOURCES = ("inertia", "primitive", "mesh")  # the keys of a body table that give its mass properties
_UNITS = {"mass": "kg", "density": "kg/m^3"}


def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {_shown(got)}")


def _known_keys(value: Any, name: str, known: frozenset[str] | set[str]) -> Mapping[str, Any]:
    """`value` checked to be a table of keys in `known` (check_keys), the table named as a file writes it:
    body[2].primitive is a [body.primitive] table."""
    table = re.sub(r"\[\d+\]", "", name)
    return check_keys(value, name, known, f"[{table}]")


def inertia_matrix(value: Any, name: str) -> np.ndarray:
    """3 principal moments (entries may carry units, or a table {value = [I1, I2, I3], unit = "kg cm^2"}) or a
    3x3 matrix [kg m^2] (entries may carry units) as a 3x3 array."""
    unit = "kg*m^2"
    if isinstance(value, Mapping):
        return np.diag(vector_quantity(value, name, unit))
    if isinstance(value, (list, tuple)) and len(value) == 3 and all(isinstance(row, (list, tuple)) for row in value):
        return np.array([vector_quantity(row, f"{name}[{i}]", unit) for i, row in enumerate(value)])
    if isinstance(value, (list, tuple)) and len(value) == 3:
        return np.diag(vector_quantity(value, name, unit))
    raise _fail(name, "3 principal moments [I1, I2, I3] or a 3x3 matrix [kg m^2]", value)


def mass_properties(table: Mapping[str, Any], name: str, base: Path | None) -> tuple[float, np.ndarray]:
    """(mass m [kg], inertia about the centre of mass in B [kg m^2] (3, 3)) of the body table `table` named
    `name` (``body``, ``body[2]``): from mass and inertia, its primitive or its mesh (module docstring);
    `base` is the folder a relative mesh path refers to (None: the working directory). The inertia is
    not checked here: the RigidBody built from it checks it as its inertia_check says."""
    sources = [k for k in SOURCES if k in table]
    if not sources:
        raise _fail(f"{name}.inertia", f"3 principal moments or a 3x3 matrix [kg m^2] (with {name}.mass), or a "
                    f"{name}.primitive or {name}.mesh table", "nothing")
    if len(sources) > 1:
        raise _fail(name, "exactly one of inertia (with mass), primitive or mesh", sources)
    if sources[0] == "inertia":
        if "mass" not in table:
            raise _fail(f"{name}.mass", f"a mass [kg] > 0 next to {name}.inertia", "nothing")
        return (quantity(table["mass"], f"{name}.mass", "kg", positive=True),
                inertia_matrix(table["inertia"], f"{name}.inertia"))
    if "mass" in table:
        raise _fail(f"{name}.mass", f"no mass outside {name}.{sources[0]} (give it there)", table["mass"])
    if sources[0] == "primitive":
        return _primitive(table["primitive"], f"{name}.primitive")
    return _mesh(table["mesh"], f"{name}.mesh", base)


def _mass_or_density(table: Mapping[str, Any], name: str) -> dict[str, float]:
    """{"mass": m [kg]} or {"density": rho [kg/m^3]}: exactly one of them, > 0."""
    given = [k for k in ("mass", "density") if k in table]
    if len(given) != 1:
        raise _fail(name, "exactly one of mass = [kg] or density = [kg/m^3]", "both" if given else "neither")
    key = given[0]
    return {key: quantity(table[key], f"{name}.{key}", _UNITS[key], positive=True)}


def _primitive(value: Any, name: str) -> tuple[float, np.ndarray]:
    table = _known_keys(value, name, PRIMITIVE_KEYS)  # the keys of any shape first: `shap` gets its suggestion
    shape = table.get("shape")
    if not isinstance(shape, str) or shape not in PRIMITIVES:
        close = closest(shape, PRIMITIVES) if isinstance(shape, str) else None
        hint = f" (did you mean {close!r}?)" if close else ""
        raise _fail(f"{name}.shape", "one of " + ", ".join(PRIMITIVES) + hint, "nothing" if shape is None else shape)
    args = PRIMITIVES[shape]
    _known_keys(table, name, {"shape", "mass", "density", *args})
    values = []
    for arg in args:
        if arg not in table:
            raise _fail(f"{name}.{arg}", f"a value (shape {shape!r} needs {', '.join(args)})", "nothing")
        values.append(vector_quantity(table[arg], f"{name}.{arg}", "m") if arg in _VECTOR_ARGS else
                      quantity(table[arg], f"{name}.{arg}", "m", positive=True))
    inertia = core_call(functools.partial(getattr(_core, shape), *values, **_mass_or_density(table, name)), name)
    return float(inertia.mass), np.array(inertia.inertia_com)


def _mesh(value: Any, name: str, base: Path | None) -> tuple[float, np.ndarray]:
    table = _known_keys(value, name, MESH_KEYS)
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
        raise ImportError(f"{name}: reading mesh files needs trimesh (pip install trimesh)") from None
    mass_or_density = _mass_or_density(table, name)
    mesh = trimesh.load(str(path), force="mesh")
    inertia = core_call(functools.partial(_core.solid_mesh, np.asarray(getattr(mesh, "vertices"), float),  # a Trimesh
                                          np.asarray(getattr(mesh, "faces"), np.int64), **mass_or_density), name)
    return float(inertia.mass), np.array(inertia.inertia_com)
