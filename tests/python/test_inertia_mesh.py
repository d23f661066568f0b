"""Mesh inertia against trimesh's mass properties (test-only dependency) and against the primitives
it approximates; mesh errors; density quadrature with its error estimate."""

import math

import numpy as np
import pytest

import rigiddyn as rd

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
    assert body.mass == pytest.approx(mesh.mass, rel=1e-12)
    np.testing.assert_allclose(body.com, mesh.center_mass, atol=1e-12)
    np.testing.assert_allclose(body.inertia_com, mesh.moment_inertia, atol=1e-12 * np.abs(mesh.moment_inertia).max())
    same = rd.solid_mesh(np.asarray(mesh.vertices), np.asarray(mesh.faces), density=2.5)
    assert same.is_approx(body, 1e-15)


def test_icosphere_converges_to_sphere_and_box_is_exact():
    exact = rd.solid_sphere(1.0, mass=1.0)
    errors = [relative_error(rd.solid_mesh(trimesh.creation.icosphere(subdivisions=k), mass=1.0), exact) for k in (2, 3, 4, 5)]
    assert all(e2 < 0.3 * e1 for e1, e2 in zip(errors, errors[1:])), errors
    assert errors[-1] < 1e-3
    box = trimesh.creation.box(extents=[1.0, 2.0, 3.0])
    assert rd.solid_mesh(box, mass=5.0).is_approx(rd.solid_box([1, 2, 3], mass=5.0), 1e-14)
    assert rd.mesh_shell(box, density=1.0).is_approx(rd.box_shell([1, 2, 3], density=1.0), 1e-14)
    sphere = trimesh.creation.icosphere(subdivisions=5)
    assert relative_error(rd.mesh_shell(sphere, mass=1.0), rd.spherical_shell(1.0, mass=1.0)) < 1e-3


def test_body_split_into_parts_equals_whole():
    # a box = two half-boxes (meshes), and a sphere with a spherical hole = hollow sphere
    a = trimesh.creation.box(extents=[0.5, 1.0, 1.0])
    b = a.copy()
    a.apply_translation([-0.25, 0, 0])
    b.apply_translation([0.25, 0, 0])
    parts = [rd.solid_mesh(m, density=1.0) for m in (a, b)]
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
    with pytest.raises(TypeError, match=r"^mesh: expected a mesh object"):
        rd.solid_mesh(v, density=1.0)


def test_density_over_box_linear_and_error_estimate():
    result = rd.integrate_density_over_box(lambda p: 1.0 + p[:, 0], [0, 0, 0], [1, 1, 1], order=2, subdivisions=1)
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
    assert uniform.inertia.is_approx(rd.solid_mesh(mesh, density=2.0), 1e-12)
    assert uniform.mass_error < 1e-12
