"""Triangle-mesh mass properties that also accept ``trimesh`` objects.

``solid_mesh`` and ``mesh_shell`` take either ``(vertices, faces)`` arrays — vertices (n, 3) [m],
faces (f, 3) integer indices, counter-clockwise seen from outside — or any object with
``vertices`` and ``faces`` attributes (a ``trimesh.Trimesh``), and call the compiled core of the
same name. Both first weld vertices closer than ``weld_tolerance`` [m] (None: 1e-8 times the
bounding-box diagonal; 0: off), as trimesh does on load, and warn a ``MeshWeldWarning`` saying how
many vertices were welded and degenerate faces dropped. trimesh itself is never imported here.
"""

from __future__ import annotations

from typing import Any, Callable, Optional, Tuple

import numpy as np

from . import _core

__all__ = ["solid_mesh", "mesh_shell"]


def _is_mesh(obj: Any) -> bool:
    return hasattr(obj, "vertices") and hasattr(obj, "faces")


def _vertices_faces(mesh_or_vertices: Any, faces: Any) -> Tuple[Any, Any]:
    if faces is not None:
        return mesh_or_vertices, faces
    if _is_mesh(mesh_or_vertices):
        return mesh_or_vertices.vertices, mesh_or_vertices.faces
    if isinstance(mesh_or_vertices, (np.ndarray, list, tuple)):  # vertices given, their faces missing
        raise TypeError("faces: expected the (f, 3) integer faces of the vertices given as mesh_or_vertices, got None")
    raise TypeError(
        "mesh_or_vertices: expected a mesh object with .vertices and .faces (e.g. trimesh.Trimesh) or "
        f"(vertices, faces) arrays, got {type(mesh_or_vertices).__name__} {mesh_or_vertices!r:.60}"
    )


def _call_core(build: Callable[..., _core.SpatialInertia], mesh_or_vertices: Any, faces: Any,
               mass: Optional[float], density: Optional[float],
               weld_tolerance: Optional[float]) -> _core.SpatialInertia:
    """build(vertices, faces, ...) with the core's "vertices: ..." errors (TypeError, ValueError,
    MemoryError) addressed to this function's argument (mesh_or_vertices, or mesh_or_vertices.vertices
    for a mesh object)."""
    vertices, faces = _vertices_faces(mesh_or_vertices, faces)
    try:
        return build(vertices, faces, mass=mass, density=density, weld_tolerance=weld_tolerance)
    except (TypeError, ValueError, MemoryError) as error:  # MemoryError: a copy too large to allocate
        message = str(error)
        if not message.startswith("vertices"):
            raise
        name = "mesh_or_vertices.vertices" if _is_mesh(mesh_or_vertices) else "mesh_or_vertices"
        raise type(error)(name + message[len("vertices"):]) from None


def solid_mesh(
    mesh_or_vertices: Any,
    faces: Any = None,
    *,
    mass: Optional[float] = None,
    density: Optional[float] = None,
    weld_tolerance: Optional[float] = None,
) -> _core.SpatialInertia:
    """Solid bounded by a closed, outward-oriented triangle mesh (exact, divergence theorem).

    Give exactly one of ``mass`` [kg] or ``density`` [kg/m^3]; the result is in the frame of the
    vertices. Vertices closer than ``weld_tolerance`` [m] are welded first (None: 1e-8 times the
    bounding-box diagonal; 0: off), faces left with a repeated vertex dropped, and a
    ``MeshWeldWarning`` gives both counts (``weld_vertices`` gives them without a warning). Raises
    ValueError naming the first open or inconsistently oriented edge (input indices), or an inward
    orientation (negative volume).
    """
    return _call_core(_core.solid_mesh, mesh_or_vertices, faces, mass, density, weld_tolerance)


def mesh_shell(
    mesh_or_vertices: Any,
    faces: Any = None,
    *,
    mass: Optional[float] = None,
    density: Optional[float] = None,
    weld_tolerance: Optional[float] = None,
) -> _core.SpatialInertia:
    """Thin shell made of the mesh's faces (need not be closed); ``density`` in [kg/m^2]; welded
    as in ``solid_mesh`` (``weld_tolerance`` [m])."""
    return _call_core(_core.mesh_shell, mesh_or_vertices, faces, mass, density, weld_tolerance)
