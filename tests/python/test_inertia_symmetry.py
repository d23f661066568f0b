"""Planes of symmetry (Craig "Plane of Symmetry") from Python: every returned plane checked
independently (numpy reflection + scipy KD-tree matching), boxes, tetrahedra, a prism, random
mirrored sets at random orientations (hypothesis), broken symmetry, consistency with
SpatialInertia.admits_symmetry_plane, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _error_bounds import roundoff


def reflects_onto_itself(masses, positions, normal, point, tol=1e-9):
    """Independent check: reflecting every point about the plane lands on a point of equal mass.
    Tolerances: the plane's normal and point come out of an eigen-decomposition and sums, accurate
    to ~eps |I|/gap and ~n eps size (gap/|I| >= 1e-3 for the bodies here): a reflected point moves
    by <= 1e-12 size, far inside 1e-6 size; masses are copied (tol only guards the comparison)."""
    n = normal / np.linalg.norm(normal)
    r = positions - point
    image = positions - 2.0 * np.outer(r @ n, n)
    dist, idx = cKDTree(positions).query(image)
    size = np.max(np.linalg.norm(positions - positions.mean(axis=0), axis=1))
    return bool(np.all(dist <= 1e-6 * size) and np.allclose(masses[idx], masses, rtol=tol))


def has_normal(planes, n):
    n = np.asarray(n, float) / np.linalg.norm(n)
    return any(np.linalg.norm(np.cross(normal, n)) < 1e-9 for normal, _ in planes)  # eps |I|/gap <= 1e-12


def box_mesh(size):
    """Box with edges `size`, each face split into four triangles around its centre (outward)."""
    corners = np.array([[(i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5] for i in range(8)]) * size
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    vertices, faces = list(corners), []
    for q in quads:
        vertices.append(corners[q].mean(axis=0))
        c = len(vertices) - 1
        faces += [[c, q[j], q[(j + 1) % 4]] for j in range(4)]
    return np.array(vertices), np.array(faces)


def test_box_point_grid_and_box_mesh_have_three_planes():
    grid = np.array([[0.5 * i, 0.7 * j, 1.1 * k] for i in range(3) for j in range(4) for k in range(5)])
    masses = np.full(len(grid), 2.0)
    planes = rd.symmetry_planes(masses, grid)
    assert len(planes) == 3
    body = rd.from_point_masses(masses, grid)
    for normal, point in planes:
        assert normal.shape == (3,) and point.shape == (3,)
        np.testing.assert_allclose(point, body.com, atol=1e-12)  # sums of 60 coordinates <= 4.4: 60 eps 4.4
        assert reflects_onto_itself(masses, grid, normal, point)
        assert body.admits_symmetry_plane(normal)
    for k in range(3):
        assert has_normal(planes, np.eye(3)[k])

    V, F = box_mesh(np.array([1.0, 2.0, 3.0]))
    R = Rotation.from_rotvec([0.3, -0.8, 0.5]).as_matrix()
    planes = rd.mesh_symmetry_planes(V @ R.T + [1.0, 2.0, -3.0], F)
    assert len(planes) == 3
    for k in range(3):
        assert has_normal(planes, R[:, k])
    for _, point in planes:
        np.testing.assert_allclose(point, [1.0, 2.0, -3.0], atol=1e-12)  # mesh centroid sums: <= 48 faces, 48 eps 4


def test_tetrahedra_and_prism():
    regular = np.array([[1.0, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]])
    planes = rd.symmetry_planes(np.ones(4), regular)
    assert len(planes) == 6  # degenerate inertia (all moments equal): found among the point candidates
    for normal, point in planes:
        assert reflects_onto_itself(np.ones(4), regular, normal, point)
    faces = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]])
    if rd.mesh_volume(regular, faces) < 0:
        faces = faces[:, [0, 2, 1]]
    assert len(rd.mesh_symmetry_planes(regular, faces)) == 6

    irregular = np.array([[0.0, 0, 0], [1.3, 0.1, 0], [0.2, 0.9, 0.1], [0.3, 0.4, 1.7]])
    assert rd.symmetry_planes(np.ones(4), irregular) == []

    h = 1.5  # prism over the isosceles triangle (-1, 0), (1, 0), (0, 2): planes x = 0 and z = 0
    tri = np.array([[-1.0, 0], [1, 0], [0, 2]])
    V = np.vstack([np.c_[tri, np.full(3, -h / 2)], np.c_[tri, np.full(3, h / 2)]])
    faces = [[0, 2, 1], [3, 4, 5]]
    vertices = list(V)
    for q in ([0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]):
        vertices.append(V[q].mean(axis=0))
        faces += [[len(vertices) - 1, q[j], q[(j + 1) % 4]] for j in range(4)]
    planes = rd.mesh_symmetry_planes(np.array(vertices), np.array(faces))
    assert len(planes) == 2
    assert has_normal(planes, [1, 0, 0]) and has_normal(planes, [0, 0, 1])


@settings(max_examples=50, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(3, 12))  # k = 2 pairs are coplanar: a second plane
def test_random_mirrored_set_found_at_any_orientation_and_broken_by_perturbation(seed, k):
    rng = np.random.default_rng(seed)
    half = rng.uniform(-1, 1, (k, 3))
    half[:, 2] = 0.1 + np.abs(half[:, 2])
    masses = np.repeat(rng.uniform(0.5, 2.0, k), 2)
    points = np.repeat(half, 2, axis=0)
    points[1::2, 2] *= -1  # mirror images about z = 0
    R = Rotation.random(random_state=seed).as_matrix()
    t = rng.uniform(-5, 5, 3)
    positions = points @ R.T + t
    planes = rd.symmetry_planes(masses, positions)
    assert len(planes) == 1
    assert has_normal(planes, R[:, 2])
    body = rd.from_point_masses(masses, positions)
    normal, point = planes[0]
    assert body.admits_symmetry_plane(normal)
    assert reflects_onto_itself(masses, positions, normal, point)

    moved = positions.copy()
    moved[0, 0] += 1e-4
    assert rd.symmetry_planes(masses, moved) == []
    heavier = masses.copy()
    heavier[1] *= 1.01
    assert rd.symmetry_planes(heavier, positions) == []


def test_bad_input_names_the_argument():
    p = np.eye(3)
    with pytest.raises(ValueError, match="^positions:"):
        rd.symmetry_planes(np.ones(2), p)
    with pytest.raises(ValueError, match=r"^masses\[1\]:"):
        rd.symmetry_planes([1.0, 0.0, 1.0], p)
    with pytest.raises(ValueError, match=r"^masses\[2\]:"):
        rd.symmetry_planes([1.0, 1.0, -1.0], p)
    with pytest.raises(ValueError, match="^masses:"):
        rd.symmetry_planes(np.ones((3, 1)), p)
    with pytest.raises(ValueError, match="^positions:"):
        rd.symmetry_planes(np.ones(3), [[0, 0, np.nan], [1, 0, 0], [0, 1, 0]])
    with pytest.raises(ValueError, match="^tolerance:"):
        rd.symmetry_planes(np.ones(3), p, tolerance=-1.0)
    V, F = box_mesh(np.ones(3))
    with pytest.raises(ValueError, match="^faces"):
        rd.mesh_symmetry_planes(V, F[:-1])
    with pytest.raises(TypeError, match="^faces:"):
        rd.mesh_symmetry_planes(V, F.astype(float))
    with pytest.raises(ValueError, match="^vertices:"):
        rd.mesh_symmetry_planes(V[:, :2], F)


# --- planes of the solid for ordinary triangulations (trimesh's primitives) ---

trimesh = pytest.importorskip("trimesh")

# Hammer-Stroud degree-3 rule on a tetrahedron (barycentric points, weights summing to 1): exact
# for the cubic moments used below.
_BARY = np.array([[0.25] * 4] + [[0.5 if i == j else 1 / 6 for i in range(4)] for j in range(4)])
_WEIGHTS = np.array([-0.8] + [0.45] * 4)


def moments_to_order_3(vertices, faces, origin):
    """Volume, first, second and third moment tensors of the solid about `origin`, from signed
    tetrahedra (origin, a, b, c) and an exact cubic rule: independent of the package."""
    corners = np.asarray(vertices)[np.asarray(faces)] - origin  # (f, 3, 3)
    volume = np.einsum("fi,fi->f", corners[:, 0], np.cross(corners[:, 1], corners[:, 2])) / 6.0
    tets = np.concatenate([np.zeros((len(corners), 1, 3)), corners], axis=1)  # (f, 4, 3)
    points = np.einsum("qm,fmi->fqi", _BARY, tets)  # (f, 5, 3)
    w = volume[:, None] * _WEIGHTS[None, :]
    return (volume.sum(), np.einsum("fq,fqi->i", w, points), np.einsum("fq,fqi,fqj->ij", w, points, points),
            np.einsum("fq,fqi,fqj,fqk->ijk", w, points, points, points))


def mirror_has_same_moments(mesh, normal, point):
    """Independent check of a plane: the mirrored solid has the solid's moments up to order 3 about
    the plane's point. Both sides are sums over the same f faces of terms <= V_f L^k (L = largest
    distance to a vertex): round-off <= roundoff(sum |V_f| L^k, 8 f) each."""
    n = normal / np.linalg.norm(normal)
    V = np.asarray(mesh.vertices)
    mirrored = V - 2.0 * np.outer((V - point) @ n, n)
    L = np.max(np.linalg.norm(V - point, axis=1))
    corners = V[np.asarray(mesh.faces)] - point
    scale = np.abs(np.einsum("fi,fi->f", corners[:, 0], np.cross(corners[:, 1], corners[:, 2]))).sum() / 6.0
    for k, (a, b) in enumerate(zip(moments_to_order_3(V, mesh.faces, point),
                                   moments_to_order_3(mirrored, np.asarray(mesh.faces)[:, ::-1], point))):
        if not np.allclose(a, b, rtol=0, atol=roundoff(scale * L**k, 8 * len(mesh.faces))):
            return False
    return True


def azimuth_count(mesh):
    """Sections s of a trimesh solid of revolution about z: distinct azimuths of its off-axis vertices."""
    V = np.asarray(mesh.vertices)
    off_axis = np.hypot(V[:, 0], V[:, 1]) > 1e-9
    angles = np.round(np.arctan2(V[off_axis, 1], V[off_axis, 0]) % (2 * np.pi), 9) % np.round(2 * np.pi, 9)
    return len(np.unique(angles))


PRIMITIVES = {
    # name: (mesh, number of planes of the solid, the axis of revolution or None)
    "box": (lambda: trimesh.creation.box(extents=[1.0, 2.0, 3.0]), lambda m: 3, None),
    "cube": (lambda: trimesh.creation.box(extents=[1.0, 1.0, 1.0]), lambda m: 9, None),
    # a prism over the regular s-gon: s planes through the axis (through vertices and through edge
    # midpoints) and the plane normal to the axis
    "cylinder": (lambda: trimesh.creation.cylinder(radius=0.3, height=1.2, sections=32),
                 lambda m: azimuth_count(m) + 1, 2),
    "cylinder7": (lambda: trimesh.creation.cylinder(radius=0.3, height=1.2, sections=7),
                  lambda m: azimuth_count(m) + 1, 2),
    "capsule": (lambda: trimesh.creation.capsule(height=1.0, radius=0.3, count=[12, 10]),
                lambda m: azimuth_count(m) + 1, 2),
    # the icosahedral group's 15 mirror planes survive subdivision and projection onto the sphere
    "icosphere": (lambda: trimesh.creation.icosphere(subdivisions=2), lambda m: 15, None),
}


@pytest.mark.parametrize("moved", [False, True], ids=["as_built", "rotated_translated"])
@pytest.mark.parametrize("name", PRIMITIVES)
def test_trimesh_primitives_planes_of_the_solid(name, moved):
    make, expected, axis = PRIMITIVES[name]
    mesh = make()
    count = expected(mesh)
    R = np.eye(3)
    if moved:
        R = Rotation.from_rotvec([0.4, -1.1, 0.7]).as_matrix()
        transform = np.eye(4)
        transform[:3, :3], transform[:3, 3] = R, [0.3, -2.0, 5.0]
        mesh.apply_transform(transform)
    planes = rd.mesh_symmetry_planes(mesh.vertices, mesh.faces)
    assert len(planes) == count, (name, [p[0] for p in planes])
    body = rd.solid_mesh(mesh, density=1.0)
    for normal, point in planes:
        np.testing.assert_allclose(point, body.com, atol=1e-15)  # the same C++ com, returned as is
        assert mirror_has_same_moments(mesh, normal, point), normal
    if name == "box":
        for k in range(3):
            assert has_normal(planes, R[:, k])
    if axis is not None:  # the plane normal to the axis and planes containing it
        a = R[:, axis]
        assert has_normal(planes, a)
        # eps |I| / gap-like accuracy of normals built from vertex differences: far below 1e-9
        axial = [R.T @ normal for normal, _ in planes if abs(normal @ a) < 1e-9]
        assert len(axial) == count - 1
        # the mirror lines of the regular s-gon (moments up to order 3 cannot tell them apart: those
        # of an s-gon are isotropic below order s): normals at theta0 + pi/2 + k pi/s (mod pi),
        # theta0 the azimuth of a rim vertex; accuracy as above
        rim = np.asarray(make().vertices)
        rim = rim[np.argmax(np.hypot(rim[:, 0], rim[:, 1]))]
        sections = count - 1
        for normal in axial:
            k = (np.arctan2(normal[1], normal[0]) - np.arctan2(rim[1], rim[0]) - np.pi / 2) / (np.pi / sections)
            assert abs(k - np.round(k)) < 1e-8 * sections, (normal, k)
    # the STL-like mesh of the same solid (unshared vertices, welded first): the same planes
    V = np.asarray(mesh.vertices)[np.asarray(mesh.faces).ravel()]
    F = np.arange(len(V)).reshape(-1, 3)
    assert len(rd.mesh_symmetry_planes(V, F)) == count


@pytest.mark.parametrize("name", PRIMITIVES)
def test_slightly_asymmetric_solid_has_no_plane(name):
    mesh = PRIMITIVES[name][0]()
    rng = np.random.default_rng(7)
    V = np.array(mesh.vertices)
    size = np.linalg.norm(mesh.extents)
    k = rng.integers(len(V))
    direction = rng.normal(size=3)
    V[k] += 1e-4 * size * direction / np.linalg.norm(direction)  # one vertex, a generic direction
    assert rd.mesh_symmetry_planes(V, mesh.faces) == []
    # the planes hold to the stated tolerance (1e-9 L): a move 1e4 times smaller keeps them all
    V = np.array(mesh.vertices)
    V[k] += 1e-13 * size * direction / np.linalg.norm(direction)
    assert len(rd.mesh_symmetry_planes(V, mesh.faces)) == PRIMITIVES[name][1](mesh)
