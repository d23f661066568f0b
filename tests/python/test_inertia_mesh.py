"""Mesh inertia against trimesh's mass properties (test-only dependency) and against the primitives
it approximates; mesh errors; density quadrature with its error estimate."""

import math
import pickle

import numpy as np
import pytest

import rigiddyn as rd
from _error_bounds import roundoff

trimesh = pytest.importorskip("trimesh")


def relative_error(a, b):
    return max(
        abs(a.mass / b.mass - 1.0),
        np.linalg.norm(a.com - b.com) / math.sqrt(np.trace(b.inertia_com) / b.mass),
        np.linalg.norm(a.inertia_com - b.inertia_com) / np.linalg.norm(b.inertia_com),
    )


@pytest.mark.parametrize(
    "mesh",
    [
        trimesh.creation.icosphere(subdivisions=3, radius=0.7),
        trimesh.creation.box(extents=[1.0, 2.0, 0.5]),
        trimesh.creation.cylinder(radius=0.3, height=1.2, sections=40),
        trimesh.creation.capsule(height=1.0, radius=0.3),
        trimesh.creation.annulus(r_min=0.2, r_max=0.5, height=0.3),
    ],
    ids=["icosphere", "box", "cylinder", "capsule", "annulus"],
)
def test_solid_mesh_matches_trimesh(mesh):
    rng = np.random.default_rng(0)
    mesh = mesh.copy()
    mesh.apply_transform(trimesh.transformations.random_rotation_matrix(rng.random(3)))
    mesh.apply_translation(rng.normal(size=3))
    mesh.density = 2.5
    body = rd.solid_mesh(mesh, density=2.5)  # the trimesh object itself
    # sums over the faces of signed tetrahedra from an origin |c| away (trimesh integrates about the
    # origin, then shifts): gamma_n with n = faces, amplified by the cancellation (|c| + L)/L for
    # volume and com and (L^2 + |c|^2)/L^2 for the inertia, L the mesh's extent, on both sides
    n, L, c = len(mesh.faces), mesh.extents.max(), np.linalg.norm(mesh.center_mass)
    shift = 1 + c / L
    assert body.mass == pytest.approx(mesh.mass, rel=max(1e-12, roundoff(shift, n)))
    np.testing.assert_allclose(body.com, mesh.center_mass, atol=max(1e-12, roundoff((c + L) * shift, n)))
    np.testing.assert_allclose(body.inertia_com, mesh.moment_inertia,
                               atol=max(1e-12, roundoff(shift**2, n)) * np.abs(mesh.moment_inertia).max())
    same = rd.solid_mesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), density=2.5)
    assert same.is_approx(body, 1e-15)  # the same C++ on the same doubles (the object's arrays)


def test_icosphere_converges_to_sphere_and_box_is_exact():
    exact = rd.solid_sphere(1.0, mass=1.0)
    errors = [relative_error(rd.solid_mesh(trimesh.creation.icosphere(subdivisions=k), mass=1.0), exact) for k in (2, 3, 4, 5)]
    # second order in the edge: each level halves it, error/4 (1 + O(edge^2)), edge <= 0.3 here
    assert all(e2 < 0.3 * e1 for e1, e2 in zip(errors, errors[1:])), errors
    # an inscribed polyhedron: each face sags by rho^2/2 (circumradius rho = edge/sqrt(3)), relative
    # error ~ edge^2/2 = 7e-4 at k = 5 (edge 0.038)
    assert errors[-1] < 1e-3
    box = trimesh.creation.box(extents=[1.0, 2.0, 3.0])
    # exact formulas both ways, 12 faces: a few dozen roundings of numbers <= the result: <= 64 eps
    assert rd.solid_mesh(box, mass=5.0).is_approx(rd.solid_box([1, 2, 3], mass=5.0), 1e-14)
    assert rd.mesh_shell(box, density=1.0).is_approx(rd.box_shell([1, 2, 3], density=1.0), 1e-14)
    sphere = trimesh.creation.icosphere(subdivisions=5)
    assert relative_error(rd.mesh_shell(sphere, mass=1.0), rd.spherical_shell(1.0, mass=1.0)) < 1e-3  # as above


def test_body_split_into_parts_equals_whole():
    # a box = two half-boxes (meshes), and a sphere with a spherical hole = hollow sphere
    a = trimesh.creation.box(extents=[0.5, 1.0, 1.0])
    b = a.copy()
    a.apply_translation([-0.25, 0, 0])
    b.apply_translation([0.25, 0, 0])
    parts = [rd.solid_mesh(m, density=1.0) for m in (a, b)]
    # exact formulas, a few dozen roundings; the hole removes 1/32 of the inertia (no cancellation)
    assert rd.composite(parts).is_approx(rd.solid_box([1, 1, 1], density=1.0), 1e-14)
    hollow = rd.solid_sphere(1.0, density=1.0) - rd.solid_sphere(0.5, density=1.0)
    assert hollow.is_approx(rd.hollow_sphere(1.0, 0.5, density=1.0), 1e-14)


def test_mesh_errors_name_the_problem():
    box = trimesh.creation.box()
    v, f = np.asarray(box.vertices), np.asarray(box.faces)
    with pytest.raises(ValueError, match=r"^faces: expected a closed mesh.*open boundary"):
        rd.solid_mesh(v, f[:-1], density=1.0)
    with pytest.raises(ValueError, match=r"oriented inward; reverse their winding"):
        rd.solid_mesh(v, f[:, ::-1], density=1.0)
    flipped = f.copy()
    flipped[0] = flipped[0, ::-1]
    with pytest.raises(ValueError, match=r"inconsistent orientation"):
        rd.solid_mesh(v, flipped, density=1.0)
    with pytest.raises(ValueError, match=r"^faces\[0\]: expected vertex indices in \[0, 8\), got 9"):
        rd.solid_mesh(v, np.vstack([[9, 1, 2], f[1:]]), density=1.0)
    with pytest.raises(TypeError, match=r"^faces: expected an integer array"):
        rd.solid_mesh(v, f.astype(float), density=1.0)
    with pytest.raises(TypeError, match=r"^faces: expected the \(f, 3\) integer faces"):
        rd.solid_mesh(v, density=1.0)
    with pytest.raises(TypeError, match=r"^mesh_or_vertices: expected a mesh object"):
        rd.solid_mesh("part.stl", density=1.0)
    with pytest.raises(ValueError, match=r"^mesh_or_vertices: expected shape .*\(n, 3\), got \(8, 2\)"):
        rd.solid_mesh(v[:, :2], f, density=1.0)


def test_density_over_box_linear_and_error_estimate():
    result = rd.integrate_density_over_box(lambda p: 1.0 + p[:, 0], [0, 0, 0], [1, 1, 1], order=2, subdivisions=1)
    # Gauss order 2 integrates a linear density's moments exactly: round-off of 8 points, <= 64 eps
    assert result.inertia.mass == pytest.approx(1.5, rel=1e-14)
    np.testing.assert_allclose(result.inertia.com, [5 / 9, 0.5, 0.5], rtol=1e-14)
    gauss = rd.integrate_density_over_box(lambda p: np.exp(-(p**2).sum(axis=1)), [-1] * 3, [1] * 3, order=2, subdivisions=1)
    exact = (math.sqrt(math.pi) * math.erf(1.0)) ** 3
    assert abs(gauss.inertia.mass - exact) < gauss.mass_error
    with pytest.raises(ValueError, match=r"^rho\(points\): expected"):
        rd.integrate_density_over_box(lambda p: np.ones(3), [0] * 3, [1] * 3)


def test_density_over_mesh_uniform_matches_solid_mesh():
    mesh = trimesh.creation.icosphere(subdivisions=2)
    uniform = rd.integrate_density_over_mesh(lambda p: np.full(len(p), 2.0), mesh.vertices, mesh.faces, order=2)
    # constant density: the quadrature is exact; round-off of sums over 320 faces x points: gamma_n,
    # n ~ 320 x 4 (the error estimate is the difference of two such exact rules)
    assert uniform.inertia.is_approx(rd.solid_mesh(mesh, density=2.0), roundoff(1, 4 * len(mesh.faces)))
    assert uniform.mass_error < roundoff(uniform.inertia.mass, 4 * len(mesh.faces))


# --- welding (vertices closer than weld_tolerance become one, as trimesh merges them on load) ---

def unshared(mesh, delta, rng):
    """The mesh as an STL file stores it: every face with its own three vertex copies. Each vertex's
    first copy (lowest index) is exact; the others move by `delta` [m] in a random direction (at a
    coordinate 0 a 1e-33 move gives the -0.0 / 1e-33 pairs of CAD exports; elsewhere it rounds away)."""
    corners = np.asarray(mesh.faces).ravel()
    vertices = np.asarray(mesh.vertices)[corners].copy()
    _, first = np.unique(corners, return_index=True)
    moved = np.ones(len(corners), bool)
    moved[first] = False
    directions = rng.normal(size=(int(moved.sum()), 3))
    vertices[moved] += delta * directions / np.linalg.norm(directions, axis=1, keepdims=True)
    return vertices, np.arange(len(corners)).reshape(-1, 3)


def corner_at_origin_box():
    box = trimesh.creation.box(extents=[1.0, 2.0, 0.5])
    box.apply_translation([0.5, 1.0, 0.25])  # coordinates 0 and the extents: 1e-33 moves are representable
    return box


@pytest.mark.parametrize("relative_delta", [1e-33, 1e-12])
@pytest.mark.parametrize("make", [corner_at_origin_box, lambda: trimesh.creation.cylinder(radius=0.3, height=1.2)],
                         ids=["box", "cylinder"])
def test_stl_duplicates_are_welded_and_counted(make, relative_delta):
    mesh = make()
    size = np.linalg.norm(mesh.extents)
    V, F = unshared(mesh, relative_delta * size, np.random.default_rng(1))
    duplicates = len(V) - len(mesh.vertices)
    for build, density in ((rd.solid_mesh, 2.5), (rd.mesh_shell, 0.5)):
        with pytest.warns(rd.MeshWeldWarning, match=rf"^{build.__name__}: welded {duplicates} vertices .* dropped 0"):
            welded = build(V, F, density=density)
        # the welded mesh has the exact shared vertices (each cluster keeps its exact first copy):
        # it differs from the shared mesh only by summation order and the reference point (the
        # vertex mean), i.e. the round-off of the face sums, gamma_n with n = 4 f roundings per side on
        # numbers <= the size (the reference point is inside: no cancellation amplification)
        shared = build(mesh, density=density)
        assert welded.is_approx(shared, roundoff(1.0, 4 * len(F)))
        with pytest.warns(rd.MeshWeldWarning):  # a trimesh object with the same arrays, unprocessed
            assert build(trimesh.Trimesh(V, F, process=False), density=density).is_approx(welded, 0.0)
    # against trimesh's own mass properties of the shared mesh: both exact formulas, round-off as in
    # test_solid_mesh_matches_trimesh (origin within the mesh's extent: shift <= 2)
    mesh.density = 2.5
    body = build_quietly(V, F)
    assert body.mass == pytest.approx(mesh.mass, rel=roundoff(2.0, len(F)))
    np.testing.assert_allclose(body.com, mesh.center_mass, atol=roundoff(2.0 * size, len(F)))
    np.testing.assert_allclose(body.inertia_com, mesh.moment_inertia,
                               atol=roundoff(4.0, len(F)) * np.abs(mesh.moment_inertia).max())
    report = rd.weld_vertices(V, F)
    assert (report.welded_vertices, report.dropped_faces) == (duplicates, 0)
    assert len(report.vertices) == len(mesh.vertices) and len(report.faces) == len(F)
    assert report.tolerance == pytest.approx(1e-8 * np.linalg.norm(V.max(axis=0) - V.min(axis=0)), rel=1e-15)
    copy = pickle.loads(pickle.dumps(report))  # a result pickles as every rigiddyn object does
    for field in ("vertices", "faces", "vertex_index", "face_index", "welded_vertices", "dropped_faces", "tolerance"):
        np.testing.assert_array_equal(getattr(copy, field), getattr(report, field))
    assert repr(copy) == repr(report)


def build_quietly(V, F, **kwargs):
    with pytest.warns(rd.MeshWeldWarning):
        return rd.solid_mesh(V, F, density=2.5, **kwargs)


def test_welding_off_or_too_tight_refuses_with_a_clear_message():
    mesh = corner_at_origin_box()
    V, F = unshared(mesh, 1e-12 * np.linalg.norm(mesh.extents), np.random.default_rng(2))
    with pytest.raises(ValueError, match=r"^faces: expected a closed mesh.*open boundary\); welding is off "
                                         r"\(weld_tolerance=0\) and 28 vertices lie within the default weld tolerance"):
        rd.solid_mesh(V, F, density=1.0, weld_tolerance=0)
    # a tolerance below the 1e-12 moves welds nothing (no copy is exact): still open, and said so
    with pytest.raises(ValueError, match=r"open boundary\) \(after welding 0 vertices within 1\.0*\d*e-15 m\)"):
        rd.solid_mesh(V, F, density=1.0, weld_tolerance=1e-15)
    assert rd.mesh_shell(V, F, density=1.0, weld_tolerance=0).mass > 0  # a shell need not be closed
    for bad, match in ((-1.0, r"^weld_tolerance: expected a finite distance >= 0"), (np.nan, r"^weld_tolerance: expected"),
                       ("x", r"^weld_tolerance: expected")):
        with pytest.raises((ValueError, TypeError), match=match):
            rd.solid_mesh(V, F, density=1.0, weld_tolerance=bad)


def test_degenerate_faces_after_welding_are_dropped_and_counted():
    box = trimesh.creation.box(extents=[1.0, 2.0, 3.0])
    V = np.vstack([box.vertices, box.vertices[0] + 1e-13])  # vertex 8: a copy of vertex 0
    # a sliver (0, 8, 1) closed by the sliver (8, 0, 1): both collapse to edges once 8 is welded to 0
    F = np.vstack([box.faces, [[0, 8, 1], [8, 0, 1]]])
    with pytest.warns(rd.MeshWeldWarning, match=r"welded 1 vertices .* dropped 2 faces"):
        body = rd.solid_mesh(V, F, density=1.0)
    assert body.is_approx(rd.solid_box([1.0, 2.0, 3.0], density=1.0), 1e-14)  # as in the box test above
    with pytest.raises(ValueError, match=r"^faces"):
        rd.solid_mesh(V, F, density=1.0, weld_tolerance=0)
    report = rd.weld_vertices(V, F)
    assert (report.welded_vertices, report.dropped_faces) == (1, 2)
    np.testing.assert_array_equal(report.face_index, np.arange(12))
    np.testing.assert_array_equal(report.vertex_index, np.arange(8))


def test_weld_clusters_across_grid_cells_and_not_beyond_the_tolerance():
    h = 1e-8
    # 0.3 -/+ 2e-9 lie on both sides of a grid line at 0.3 (cells of side h from 0): welded all the same
    # (a rounding to multiples of h, as trimesh's digits, would keep them apart); 1.1 h apart: kept
    V = np.array([[0.0, 0, 0], [1, 1, 1], [0.3 - 2e-9, 0, 0], [0.3 + 2e-9, 0, 0], [0.5, 0, 0], [0.5 + 1.1 * h, 0, 0]])
    F = np.array([[0, 1, 2], [0, 1, 3], [0, 1, 4], [0, 1, 5]])
    report = rd.weld_vertices(V, F, tolerance=h)
    assert report.welded_vertices == 1
    np.testing.assert_array_equal(report.vertex_index, [0, 1, 2, 4, 5])
    np.testing.assert_array_equal(report.faces, [[0, 1, 2], [0, 1, 2], [0, 1, 3], [0, 1, 4]])
    assert rd.weld_vertices(V, F, tolerance=0.0).welded_vertices == 0
    assert "welded_vertices=1" in repr(report)
