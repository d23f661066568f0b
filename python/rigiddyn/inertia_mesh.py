"""Triangle-mesh mass properties that also accept ``trimesh`` objects.

``solid_mesh`` and ``mesh_shell`` take either ``(vertices, faces)`` arrays — vertices (n, 3) [m],
faces (f, 3) integer indices, counter-clockwise seen from outside — or any object with
``vertices`` and ``faces`` attributes (a ``trimesh.Trimesh``), and call the compiled core of the
same name. trimesh itself is never imported here.
"""

from __future__ import annotations

from typing import Any, Optional, Tuple

from . import _core

__all__ = ["solid_mesh", "mesh_shell"]


def _vertices_faces(mesh_or_vertices: Any, faces: Any) -> Tuple[Any, Any]:
    if faces is not None:
        return mesh_or_vertices, faces
    if hasattr(mesh_or_vertices, "vertices") and hasattr(mesh_or_vertices, "faces"):
        return mesh_or_vertices.vertices, mesh_or_vertices.faces
    raise TypeError(
        "mesh: expected a mesh object with .vertices and .faces (e.g. trimesh.Trimesh) or "
        f"(vertices, faces) arrays, got {type(mesh_or_vertices).__name__} without faces"
    )


def solid_mesh(
    mesh_or_vertices: Any,
    faces: Any = None,
    *,
    mass: Optional[float] = None,
    density: Optional[float] = None,
) -> _core.SpatialInertia:
    """Solid bounded by a closed, outward-oriented triangle mesh (exact, divergence theorem).

    Give exactly one of ``mass`` [kg] or ``density`` [kg/m^3]. Raises ValueError naming the first
    open or inconsistently oriented edge, or an inward orientation (negative volume).
    """
    vertices, faces = _vertices_faces(mesh_or_vertices, faces)
    return _core.solid_mesh(vertices, faces, mass=mass, density=density)


def mesh_shell(
    mesh_or_vertices: Any,
    faces: Any = None,
    *,
    mass: Optional[float] = None,
    density: Optional[float] = None,
) -> _core.SpatialInertia:
    """Thin shell made of the mesh's faces (need not be closed); ``density`` in [kg/m^2]."""
    vertices, faces = _vertices_faces(mesh_or_vertices, faces)
    return _core.mesh_shell(vertices, faces, mass=mass, density=density)
