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
    """Mass properties of the solid bounded by a closed, outward-oriented triangle mesh.

    Exact for the polyhedron (divergence theorem: each face spans a signed tetrahedron whose moments
    sum to the solid's). When the weld changed anything, a ``MeshWeldWarning`` gives the numbers of
    welded vertices and dropped faces (``weld_vertices`` gives them without a warning).

    Parameters
    ----------
    mesh_or_vertices : array_like, shape (n, 3), or mesh object
        Vertex positions [m] in any frame A, or an object with ``vertices`` and ``faces`` attributes
        (a ``trimesh.Trimesh``; then `faces` is None).
    faces : array_like of int, shape (f, 3), optional
        Vertex indices of each triangle, counter-clockwise seen from outside.
    mass : float, optional
        Total mass [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Volume density [kg/m^3], finite and > 0.
    weld_tolerance : float or None, default None
        Vertices closer than this [m] are welded first (None: 1e-8 times the bounding-box diagonal;
        0: off), as trimesh does on load; faces left with a repeated vertex are dropped.

    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.

    Raises
    ------
    ValueError
        The first open or inconsistently oriented edge (input indices), an inward orientation
        (negative volume), a zero volume, bad vertices or indices (the message names the argument);
        not exactly one of `mass` and `density`.
    TypeError
        `mesh_or_vertices` neither arrays nor a mesh object, or `faces` missing for arrays.

    Warns
    -----
    MeshWeldWarning
        When welding merged vertices or dropped faces.

    See Also
    --------
    mesh_shell, weld_vertices, mesh_volume, require_closed_oriented_mesh, integrate_density_over_mesh

    Examples
    --------
    The corner tetrahedron as a mesh gives the solid tetrahedron:

    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    >>> rd.solid_mesh(v, faces, density=6.0).is_approx(rd.solid_tetrahedron(v, density=6.0))
    True
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
    """Mass properties of a thin shell made of a mesh's triangles (need not be closed).

    Each triangle is a uniform thin sheet; orientation does not matter. Welded as in ``solid_mesh``
    (with its ``MeshWeldWarning``).

    Parameters
    ----------
    mesh_or_vertices : array_like, shape (n, 3), or mesh object
        Vertex positions [m] in any frame A, or an object with ``vertices`` and ``faces`` attributes
        (a ``trimesh.Trimesh``; then `faces` is None).
    faces : array_like of int, shape (f, 3), optional
        Vertex indices of each triangle (any orientation).
    mass : float, optional
        Total mass [kg], finite and > 0. Give exactly one of `mass` and `density`.
    density : float, optional
        Area density [kg/m^2], finite and > 0.
    weld_tolerance : float or None, default None
        Vertices closer than this [m] are welded first (None: 1e-8 times the bounding-box diagonal;
        0: off), as trimesh does on load; faces left with a repeated vertex are dropped.

    Returns
    -------
    SpatialInertia
        Mass [kg], centre of mass [m] and inertia_com [kg m^2] about it, expressed in A.

    Raises
    ------
    ValueError
        A zero total area, bad vertices or indices (the message names the argument); not exactly one
        of `mass` and `density`.
    TypeError
        `mesh_or_vertices` neither arrays nor a mesh object, or `faces` missing for arrays.

    Warns
    -----
    MeshWeldWarning
        When welding merged vertices or dropped faces.

    See Also
    --------
    solid_mesh, box_shell, spherical_shell, weld_vertices

    Examples
    --------
    A single triangle has its centre of mass at its centroid:

    >>> rd.mesh_shell([[0, 0, 0], [3, 0, 0], [0, 3, 0]], [[0, 1, 2]], mass=1.0).com
    array([1., 1., 0.])
    """
    return _call_core(_core.mesh_shell, mesh_or_vertices, faces, mass, density, weld_tolerance)
