r"""
Inertia of a closed mesh: principal axes and planes of symmetry
===============================================================

:func:`rigiddyn.solid_mesh` computes the mass, centre of mass and rotational inertia of the uniform
solid bounded by a closed triangle mesh, exactly (surface integrals by the divergence theorem, as
in Eberly's "Polyhedral mass properties"). :func:`rigiddyn.principal_axes` diagonalises the inertia
(K. Craig's "Principal Axes"), and :func:`rigiddyn.mesh_symmetry_planes` finds the planes whose
reflection maps the solid onto itself (Craig's "Plane of Symmetry": the products of inertia with
its normal vanish).

Two solids are built here with numpy, each turned by a known rotation and moved off the origin so
that nothing lines up with the coordinate axes: an aluminium box with three different sides, and a
square pyramid, whose two equal transverse moments leave its principal axes free in a plane.

**What it checks:** the mass, centre of mass and inertia of each mesh against the closed form of the
same solid; the principal moments and axes against the rotated closed form; and that the planes of
symmetry found are exactly the solid's (three for the box, four for the pyramid), each verified by
reflecting the vertices.
"""

# %%
# Meshes of convex solids, built with numpy
# -----------------------------------------
# A convex polyhedron from its vertices and its faces (polygons of vertex indices, in cyclic
# order): each polygon is split into a fan of triangles, each triangle oriented so that its normal
# points away from the centroid of the vertices (outward, as solid_mesh requires).
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import rigiddyn as rd


def convex_mesh(vertices, polygons):
    """Outward-oriented triangles (f, 3) of a convex polyhedron's polygonal faces."""
    centre = vertices.mean(axis=0)
    faces = []
    for polygon in polygons:
        for k in range(1, len(polygon) - 1):
            tri = [polygon[0], polygon[k], polygon[k + 1]]
            a, b, c = vertices[tri]
            if np.dot(np.cross(b - a, c - a), a - centre) < 0:
                tri = [tri[0], tri[2], tri[1]]
            faces.append(tri)
    return np.array(faces)


def box(size):
    """Corners (8, 3) [m] of a box centred at the origin, and its 12 triangles."""
    bits = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)])
    vertices = (bits - 0.5) * size
    quads = [[0, 2, 6, 4], [1, 3, 7, 5], [0, 1, 5, 4], [2, 3, 7, 6], [0, 1, 3, 2], [4, 5, 7, 6]]
    return vertices, convex_mesh(vertices, quads)


def pyramid(base, height):
    """A square pyramid: base (side `base` [m]) in the plane z = 0 centred on the z axis, apex at
    z = height [m]; its 5 vertices and 6 triangles."""
    s = base / 2
    vertices = np.array([[-s, -s, 0], [s, -s, 0], [s, s, 0], [-s, s, 0], [0, 0, height]])
    polygons = [[0, 1, 2, 3], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    return vertices, convex_mesh(vertices, polygons)


# %%
# The solids, turned and moved
# ----------------------------
# The box's closed form (about its centre, in its own axes) is m/12 diag(b^2 + c^2, a^2 + c^2,
# a^2 + b^2); the pyramid's (volume a^2 h/3, centre of mass h/4 above the base) is
# m diag(a^2/20 + 3 h^2/80, a^2/20 + 3 h^2/80, a^2/10). Each solid is turned by R_WS (Z-Y-X Euler
# angles) and moved to p_WS, so its inertia in W is R_WS I_S R_WS^T about the moved centre of mass.
density = 2700.0  # [kg/m^3], aluminium
R_WS = rd.euler_to_matrix("ZYX", [40.0, 25.0, -15.0], degrees=True)
p_WS = np.array([0.4, -0.25, 0.3])  # [m]

size = np.array([0.3, 0.2, 0.1])  # [m]
a, b, h = 0.2, 0.2, 0.15  # pyramid base sides and height [m]
solids = {}
for name, (vertices_S, faces), volume, com_S, moments_S in (
    ("box", box(size), np.prod(size), np.zeros(3),
     np.array([size[1]**2 + size[2]**2, size[0]**2 + size[2]**2, size[0]**2 + size[1]**2]) / 12),
    ("pyramid", pyramid(a, h), a * b * h / 3, np.array([0.0, 0.0, h / 4]),
     np.array([a**2 / 20 + 3 * h**2 / 80, a**2 / 20 + 3 * h**2 / 80, a**2 / 10])),
):
    mass = density * volume
    solids[name] = dict(
        vertices=vertices_S @ R_WS.T + p_WS, faces=faces, mass=mass, com=R_WS @ com_S + p_WS,
        inertia=R_WS @ np.diag(mass * moments_S) @ R_WS.T, moments=np.sort(mass * moments_S),
        axes=R_WS[:, np.argsort(moments_S)])  # closed-form principal axes, ascending moments

# %%
# Mass properties from the mesh, against the closed form
# ------------------------------------------------------
eps = np.finfo(float).eps
for name, solid in solids.items():
    body = rd.solid_mesh(solid["vertices"], solid["faces"], density=density)
    solid["body"] = body
    print(f"{name}: mass {body.mass:.6f} kg (closed form {solid['mass']:.6f}), "
          f"com {np.round(body.com, 6)} m")
    print("  inertia about the centre of mass, in W [kg m^2]:\n", np.array2string(body.inertia_com, precision=8))
    # The divergence theorem is exact: what is left is rounding. Each of the f faces adds to the
    # mass, the first and the second moments about the origin terms of size rho v^3, rho v^4 and
    # rho v^5 (v: the farthest vertex from the origin; the solids sit ~0.5 m off it, so these terms
    # exceed the results), each of a few tens of operations, so rounded to <= 50 eps of its size.
    # The centre of mass divides the first moments by m; the shift I_C = I_O - m (|c|^2 1 - c c^T)
    # adds the errors of m |c|^2: at most 2 m |c| dc + |c|^2 dm per entry.
    f, v = len(solid["faces"]), np.max(np.linalg.norm(solid["vertices"], axis=1))
    m, c = solid["mass"], np.linalg.norm(solid["com"])
    mass_bound = 50 * eps * f * density * v**3
    solid["com_bound"] = (50 * eps * f * density * v**4 + c * mass_bound) / m
    solid["inertia_bound"] = 50 * eps * f * density * v**5 + 2 * (2 * m * c * solid["com_bound"] + c**2 * mass_bound)
    assert abs(body.mass - m) <= mass_bound
    assert np.max(np.abs(body.com - solid["com"])) <= solid["com_bound"]
    assert np.max(np.abs(body.inertia_com - solid["inertia"])) <= solid["inertia_bound"]
    print(f"  largest error of the inertia {np.max(np.abs(body.inertia_com - solid['inertia'])):.2e} "
          f"kg m^2, bound {solid['inertia_bound']:.2e}")

# %%
# Principal axes
# --------------
# The moments (ascending) and the axes (columns). The box's three moments differ, so each axis is
# determined up to sign and lies along a column of R_WS (the box's edges); by the Davis-Kahan
# theorem an inertia error dI turns an axis by at most :math:`\|dI\|_2` / gap, gap the distance to the nearest
# other moment. The pyramid's two transverse moments are equal: only its symmetry axis (the third
# column of R_WS) is determined, and the other two span the plane normal to it.
for name, solid in solids.items():
    moments, axes = rd.principal_axes(solid["body"].inertia_com)
    solid["principal"] = (moments, axes)
    print(f"{name}: principal moments {moments} kg m^2 (closed form {solid['moments']})")
    dI = 3 * solid["inertia_bound"]  # |dI|_2 <= |dI|_F <= 3 max |dI_ij|
    assert np.all(np.abs(moments - solid["moments"]) <= dI)  # Weyl's inequality
    gaps = np.abs(np.subtract.outer(solid["moments"], solid["moments"])) + np.diag(np.full(3, np.inf))
    gaps = gaps.min(axis=1) - 2 * dI  # to the other moments, perturbed
    determined = [k for k in range(3) if gaps[k] > 0]  # separated moments: the box's three, the pyramid's axis
    tilt = {k: dI / gaps[k] for k in determined}  # Davis-Kahan: sin(angle) <= |dI|_2 / gap
    for k in determined:
        assert 1 - abs(axes[:, k] @ solid["axes"][:, k]) <= tilt[k] ** 2 + 4 * eps, (name, k)
    # a plane's normal is a determined axis, or built from the vertices normal to one: it is
    # off by at most the largest tilt plus the rounding of vertex differences (10 eps relative)
    solid["normal_tol"] = max(tilt.values()) + 10 * eps
print("axes determined by the moments: box 3, pyramid 1 (the symmetry axis)")

# %%
# Planes of symmetry
# ------------------
# Each plane is returned as a unit normal and a point (the centre of mass). The box, with three
# different sides, has the three planes normal to its edges; the square pyramid has the four planes
# through its axis (two through the midpoints of opposite base edges, two through opposite base
# corners). Each plane found is checked independently: reflecting the vertices in it gives the same
# set of vertices (to the rounding of the reflection, a few eps times the solid's size).
expected_normals = {
    "box": R_WS.T,  # rows: R_WS's columns
    "pyramid": (R_WS @ np.array([[1, 0, 0], [0, 1, 0], [1, 1, 0], [1, -1, 0]]).T / np.array(
        [1, 1, np.sqrt(2), np.sqrt(2)])).T,
}
for name, solid in solids.items():
    planes = rd.mesh_symmetry_planes(solid["vertices"], solid["faces"])
    solid["planes"] = planes
    print(f"{name}: {len(planes)} planes of symmetry, normals\n", np.array([n for n, _ in planes]).round(6))
    assert len(planes) == len(expected_normals[name])
    vertices, tol = solid["vertices"], solid["normal_tol"]
    radius = np.max(np.linalg.norm(vertices - solid["com"], axis=1))
    matched = set()
    for normal, point in planes:
        cosines = np.abs(expected_normals[name] @ normal)
        assert 1 - cosines.max() <= tol**2 + 4 * eps, (name, normal)  # 1 - cos <= sin^2
        matched.add(int(np.argmax(cosines)))
        assert np.max(np.abs(point - solid["com"])) <= solid["com_bound"]
        # reflecting v in the plane moves it by 2 ((v - point) . n) n: an error tol in n and
        # com_bound in the point move the image by at most 4 tol radius + 2 com_bound (+ rounding)
        mirrored = vertices - 2 * np.outer((vertices - point) @ normal, normal)
        distance = np.min(np.linalg.norm(mirrored[:, None, :] - vertices[None, :, :], axis=2), axis=1)
        bound = 4 * tol * radius + 2 * np.sqrt(3) * solid["com_bound"] + 20 * eps * np.abs(vertices).max()
        assert np.max(distance) <= bound, (name, normal)
    assert len(matched) == len(planes)  # each expected plane found once

# %%
# The figure
# ----------
# Each solid in W, its principal axes drawn from the centre of mass (length proportional to
# 1/sqrt(moment), as the axes of the inertia ellipsoid), and its planes of symmetry as translucent
# squares through the centre of mass.
fig = plt.figure(figsize=(11, 5.5), layout="constrained")
for i, (name, solid) in enumerate(solids.items()):
    ax = fig.add_subplot(1, 2, i + 1, projection="3d")
    vertices, com = solid["vertices"], solid["com"]
    ax.add_collection3d(Poly3DCollection(vertices[solid["faces"]], facecolor="lightgrey",
                                         edgecolor="dimgrey", linewidth=0.5, alpha=0.35))
    radius = np.max(np.linalg.norm(vertices - com, axis=1))
    moments, axes = solid["principal"]
    lengths = 1.3 * radius * np.sqrt(moments[0] / moments)
    for k in range(3):
        ax.quiver(*com, *(lengths[k] * axes[:, k]), color=f"C{k}", linewidth=2,
                  label=f"axis {k + 1}: {moments[k]:.3e} kg m$^2$")
    for j, (normal, point) in enumerate(solid["planes"]):
        u = np.cross(normal, [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0])
        u /= np.linalg.norm(u)
        v = np.cross(normal, u)
        square = [point + 0.85 * radius * (su * u + sv * v) for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        ax.add_collection3d(Poly3DCollection([square], facecolor=f"C{3 + j}", alpha=0.22))
    lo, hi = com - 1.2 * radius, com + 1.2 * radius
    ax.set(xlim=(lo[0], hi[0]), ylim=(lo[1], hi[1]), zlim=(lo[2], hi[2]),
           xlabel="x [m]", ylabel="y [m]", zlabel="z [m]")
    ax.set_box_aspect((1, 1, 1))
    ax.set_title(f"{name}: {len(solid['planes'])} planes of symmetry")
    ax.legend(fontsize="small", loc="upper left")
plt.show()
