"""The core's mass properties (rigiddyn, C++) against the independent numpy reference
(rigiddyn_ref.inertia) on hypothesis-randomised bodies, to ~1e-12 relative: every primitive (with
mass= and with density=), point sets, solid and shell triangle meshes, the parallel axis theorem,
rotation and rigid transformation, composites and removal, the 6x6 spatial inertia, momentum,
kinetic energy, angular momentum about the centre of mass and about a point, principal axes.

The reference derives several values another way than a handbook formula (hollow shapes as a
difference of solids, box shells and capsules as composites, tetrahedra by a quadrature rule, meshes
by Eberly's surface integrals, shells by the edge-midpoint rule), so agreement checks the formulas."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import rigiddyn as rd
from _error_bounds import product_tolerance, roundoff
from rigiddyn_ref import inertia as ref
from rigiddyn_ref import so3

settings.register_profile("reference", max_examples=40, deadline=None)
settings.load_profile("reference")

# one evaluation on each side: <= ~30 roundings of terms no larger than the result (sums of
# positive moments, products with rotations): 30 eps = 7e-15 relative to the result's size; TOL
# (relative, close() and same_body()) keeps two orders of magnitude for the formulas with more
# operations (meshes: a sum over faces; hollow bodies: differences of outer and inner parts).
# Where terms cancel (a parallel-axis shift taken off, a part removed), same_body's `scale` is the
# size of the terms that cancel: the round-off is relative to it.
TOL = 1e-12

length = st.floats(0.05, 5.0)
positive = st.floats(0.1, 10.0)
vec3 = arrays(np.float64, (3,), elements=st.floats(-5.0, 5.0))
rotation = arrays(np.float64, (3,), elements=st.floats(-4.0, 4.0)).map(so3.rotvec_to_matrix)


SUBNORMAL = np.finfo(float).smallest_subnormal


def close(a, b, tol=TOL):
    """Equal to `tol` relative to the size of the larger array, plus what roundings in the subnormal
    range lose: there each rounding errs by up to half the smallest subnormal absolutely, not
    relatively (a few roundings on each side: 16 of them)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(np.max(np.abs(a)), np.max(np.abs(b)), 1e-300)
    np.testing.assert_allclose(a, b, rtol=0, atol=tol * scale + 16 * SUBNORMAL)


def same_body(core, want, tol=TOL, scale=0.0):
    """A core SpatialInertia equals a reference Inertia (mass, com and inertia about the com), the
    inertia to `tol` relative to the larger of its own size and `scale` [kg m^2] (the size of the
    terms it was computed from, when they cancel)."""
    close(core.mass, want.mass, tol)
    np.testing.assert_allclose(core.com, want.com, rtol=0,
                               atol=tol * max(1.0, np.max(np.abs(want.com))))
    # plus subnormal roundings (as close()): a part's terms round a few times (<= 4) by <= SUBNORMAL/2
    # each before they are scaled by its mass, so <= 2 m SUBNORMAL per side for the total mass m
    np.testing.assert_allclose(core.inertia_com, want.inertia_com, rtol=0,
                               atol=tol * max(np.max(np.abs(want.inertia_com)), scale)
                               + 4 * max(1.0, want.mass) * SUBNORMAL)


@st.composite
def inertias(draw):
    """A random physically valid body: mass, com and I_C = tr(C) 1 - C of a random positive second
    moment C = R diag(c) R^T (so the triangle inequality holds by construction)."""
    m = draw(positive)
    c = np.array([draw(st.floats(0.01, 5.0)) for _ in range(3)])
    R = draw(rotation)
    C = R @ np.diag(c) @ R.T
    I = np.trace(C) * np.eye(3) - C
    I = 0.5 * (I + I.T)
    return ref.Inertia(m, draw(vec3), I)


def core_body(body):
    return rd.SpatialInertia(body.mass, body.com, body.inertia_com)


def mass_or_density(draw):
    return draw(st.sampled_from(["mass", "density"])), draw(positive)


# ------------------------------------------------------------------ primitives
PRIMITIVES = {
    # name: (number of scalar arguments, or "vec" for one 3-vector argument)
    "solid_sphere": 1, "spherical_shell": 1, "thin_rod": 1, "thin_disk": 1,
    "solid_cylinder": 2, "thin_plate": 2, "solid_cone": 2, "solid_capsule": 2,
    "solid_box": "vec", "box_shell": "vec", "solid_ellipsoid": "vec",
}


@given(st.data())
@pytest.mark.parametrize("name", sorted(PRIMITIVES))
def test_primitives(name, data):
    kind, value = mass_or_density(data.draw)
    arity = PRIMITIVES[name]
    args = ([np.array([data.draw(length) for _ in range(3)])] if arity == "vec"
            else [data.draw(length) for _ in range(arity)])
    same_body(getattr(rd, name)(*args, **{kind: value}), getattr(ref, name)(*args, **{kind: value}))


@given(st.floats(0.1, 5.0), st.floats(0.05, 0.95), st.floats(0.05, 5.0), positive,
       st.sampled_from(["mass", "density"]))
def test_hollow_primitives(outer, ratio, height, value, kind):
    inner = ratio * outer
    same_body(rd.hollow_sphere(outer, inner, **{kind: value}),
              ref.hollow_sphere(outer, inner, **{kind: value}), 1e-11)
    same_body(rd.hollow_cylinder(outer, inner, height, **{kind: value}),
              ref.hollow_cylinder(outer, inner, height, **{kind: value}), 1e-11)


@given(arrays(np.float64, (4, 3), elements=st.floats(-2.0, 2.0)), positive,
       st.sampled_from(["mass", "density"]))
@example(np.array([[0.0, 1e-308 / 4.5, 1.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]),
         1.0, "mass")  # a subnormal coordinate on a flat solid: the flatness check must not warn
def test_solid_tetrahedron(vertices, value, kind):
    e = vertices[1:] - vertices[0]
    volume = abs(np.dot(e[0], np.cross(e[1], e[2]))) / 6.0  # the triple product: no LU pivots
    if volume < 1e-3 * max(1.0, np.max(np.abs(e))) ** 3:
        return  # (nearly) flat: the core raises (a degenerate solid); tested with the bad inputs
    same_body(rd.solid_tetrahedron(vertices, **{kind: value}),
              ref.solid_tetrahedron(*vertices, **{kind: value}), 1e-11)


# ------------------------------------------------------------------ point sets
@given(st.integers(1, 12).flatmap(lambda n: st.tuples(
    arrays(np.float64, (n,), elements=st.floats(0.1, 10.0)),
    arrays(np.float64, (n, 3), elements=st.floats(-5.0, 5.0)))))
def test_point_masses(masses_positions):
    masses, positions = masses_positions
    scale = np.sum(masses * np.sum(positions**2, axis=1))  # I about the origin: what cancels
    same_body(rd.from_point_masses(masses, positions), ref.from_point_masses(masses, positions),
              1e-11, scale)
    close(rd.point_inertia(masses[0], positions[0]), ref.point_inertia(masses[0], positions[0]))


# ------------------------------------------------------------------ meshes
OCTAHEDRON_FACES = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                             [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
BOX_FACES = np.array([[0, 1, 2], [1, 3, 2], [4, 6, 5], [5, 6, 7], [0, 4, 1], [1, 4, 5],
                      [2, 3, 6], [3, 7, 6], [0, 2, 4], [2, 6, 4], [1, 5, 3], [3, 5, 7]])


def box_vertices(size):
    corners = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=float)
    return (corners - 0.5) * size


@st.composite
def meshes(draw):
    """A closed outward-oriented mesh: an octahedron with random vertex radii (star-shaped about
    its centre, so the orientation stays outward) or a box, rotated and moved at random."""
    if draw(st.booleans()):
        radii = np.array([draw(st.floats(0.3, 3.0)) for _ in range(6)])
        axes = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
        vertices, faces = axes * radii[:, None], OCTAHEDRON_FACES
    else:
        vertices = box_vertices(np.array([draw(st.floats(0.1, 3.0)) for _ in range(3)]))
        faces = BOX_FACES
    return vertices @ draw(rotation).T + draw(vec3), faces


@given(meshes(), positive, st.sampled_from(["mass", "density"]))
def test_solid_mesh(mesh, value, kind):
    vertices, faces = mesh
    assert ref.mesh_volume(vertices, faces) > 0.0  # the strategy is outward-oriented
    close(rd.mesh_volume(vertices, faces), ref.mesh_volume(vertices, faces))
    same_body(rd.solid_mesh(vertices, faces, **{kind: value}),
              ref.solid_mesh(vertices, faces, **{kind: value}), 1e-11)


@given(meshes(), positive, st.sampled_from(["mass", "density"]), st.booleans())
def test_mesh_shell(mesh, value, kind, flip):
    vertices, faces = mesh
    faces = faces[:, ::-1] if flip else faces  # a shell does not depend on the orientation
    same_body(rd.mesh_shell(vertices, faces, **{kind: value}),
              ref.mesh_shell(vertices, faces, **{kind: value}), 1e-11)


@given(arrays(np.float64, (3,), elements=st.floats(0.1, 3.0)), positive)
def test_box_mesh_equals_box_primitive(size, mass):
    """Three independent routes to one box: core mesh, reference mesh, reference primitive."""
    vertices = box_vertices(size)
    same_body(rd.solid_mesh(vertices, BOX_FACES, mass=mass), ref.solid_box(size, mass=mass), 1e-11)
    same_body(rd.mesh_shell(vertices, BOX_FACES, mass=mass), ref.box_shell(size, mass=mass), 1e-11)


# ------------------------------------------------------------------ parallel axis, rotation
@given(inertias(), vec3)
def test_parallel_axis(body, point):
    core = core_body(body)
    close(core.inertia_about_point(point), ref.inertia_about_point(body, point))
    close(core.inertia_about_origin(), ref.inertia_about_point(body, np.zeros(3)))
    I_P = ref.inertia_about_point(body, point)
    # taking the shift m |r|^2 off again cancels: relative to the size of I_P
    same_body(rd.SpatialInertia.from_inertia_about_point(body.mass, body.com, I_P, point),
              ref.from_inertia_about_point(body.mass, body.com, I_P, point), 1e-11, np.abs(I_P).max())
    I_O = ref.inertia_about_point(body, np.zeros(3))
    same_body(rd.SpatialInertia.from_inertia_about_origin(body.mass, body.com, I_O),
              ref.from_inertia_about_point(body.mass, body.com, I_O, np.zeros(3)), 1e-11, np.abs(I_O).max())


@given(inertias(), rotation, vec3)
def test_rotated_and_transformed(body, R, p):
    core = core_body(body)
    same_body(core.rotated(R), ref.rotated(body, R))
    same_body(core.transformed(rd.Transform(R, p)), ref.transformed(body, R, p))


# ------------------------------------------------------------------ composites and removal
@given(st.lists(inertias(), min_size=1, max_size=5))
def test_composite_in_one_frame(parts):
    want = ref.composite(parts)
    same_body(rd.composite([core_body(p) for p in parts]), want, 1e-11)
    total = core_body(parts[0])
    for p in parts[1:]:
        total = total + core_body(p)
    same_body(total, want, 1e-11)


@given(st.lists(st.tuples(inertias(), rotation, vec3), min_size=1, max_size=4))
def test_composite_of_placed_parts(placed):
    want = ref.composite([ref.transformed(body, R, p) for body, R, p in placed])
    got = rd.composite([(rd.Transform(R, p), core_body(body)) for body, R, p in placed])
    same_body(got, want, 1e-11)


@given(inertias(), inertias())
def test_removal_undoes_composition(body, part):
    whole = ref.composite([body, part])
    core_whole = core_body(whole)
    want = ref.remove(whole, part)
    # cancellation: m_r = m - m_p (m_p/m_r <= 100: com to 100 x TOL), I_r = I - I_p - shifts,
    # relative to the whole's inertia (the size of what cancels)
    scale = np.abs(whole.inertia_com).max()
    same_body(core_whole.remove(core_body(part)), want, 1e-10, scale)
    same_body(core_whole - core_body(part), want, 1e-10, scale)
    same_body(want, body, 1e-10, scale)  # and the reference itself gives the body back


# ------------------------------------------------------------------ 6x6, momentum, energy
@given(inertias(), arrays(np.float64, (6,), elements=st.floats(-10.0, 10.0)))
def test_spatial_matrix_momentum_and_energy(body, twist):
    core = core_body(body)
    M = ref.spatial_inertia_matrix(body)
    close(core.matrix(), M)
    # I_C = I_O - m hat(c) hat(c)^T cancels: relative to the size of I_O
    same_body(rd.SpatialInertia.from_matrix(M), body, 1e-11, np.abs(M[:3, :3]).max())
    V = rd.Motion(twist[:3], twist[3:])
    h = core.momentum(V)
    assert isinstance(h, rd.Force)
    # M V and V.M V/2: Higham's gamma_n |M||V| (entries of M V may cancel), relative to the result
    want_h = ref.momentum(body, twist)
    close(h.to_vector(), want_h, max(1e-11, product_tolerance(M, twist) / max(np.abs(want_h).max(), 1e-300)))
    T = ref.kinetic_energy(body, twist)
    tol_T = max(1e-11, 0.5 * (product_tolerance([np.abs(twist)], np.abs(M) @ np.abs(twist)) * 7) / max(T, 1e-300))
    close(core.kinetic_energy(V), T, tol_T)
    close(core.kinetic_energy(V), 0.5 * twist @ M @ twist, tol_T)  # the 6x6 quadratic form


@given(inertias(), vec3, vec3, vec3)
def test_angular_momentum(body, w, v_C, point):
    core = core_body(body)
    close(core.angular_momentum_about_com(w), ref.angular_momentum_about_com(body, w))
    # I_C w + m (c - point) x v_C: terms <= |I||w| + m |c - point||v_C|, relative to the result
    want = ref.angular_momentum_about_point(body, w, v_C, point)
    size = (np.abs(body.inertia_com).sum() * np.abs(w).max()
            + body.mass * np.abs(body.com - point).sum() * np.abs(v_C).max())
    close(core.angular_momentum_about_point(w, v_C, point), want,
          max(1e-11, roundoff(size) / max(np.abs(want).max(), 1e-300)))


# ------------------------------------------------------------------ principal axes
@given(inertias())
def test_principal_axes(body):
    moments, axes = rd.principal_axes(body.inertia_com)
    want_moments, want_axes = ref.principal_axes(body.inertia_com)
    close(moments, want_moments)
    close(axes @ np.diag(moments) @ axes.T, body.inertia_com)
    close(axes.T @ axes, np.eye(3))
    close(np.linalg.det(axes), 1.0)
    gaps = np.diff(want_moments) / want_moments[-1]
    if np.all(gaps > 1e-4):  # distinct moments: each axis is defined up to sign
        signs = np.sign(np.sum(axes * want_axes, axis=0))
        close(axes * signs, want_axes, 1e-12 / np.min(gaps))  # eigenvectors: eps |I| / gap (Davis-Kahan)
    p = core_body(body).principal_axes()
    close(p.moments, moments)
    close(p.axes, axes)


@given(st.lists(inertias(), min_size=1, max_size=5))
def test_principal_axes_stack(bodies):
    stack = np.array([b.inertia_com for b in bodies])
    moments, axes = rd.principal_axes(stack)
    assert moments.shape == (len(bodies), 3) and axes.shape == (len(bodies), 3, 3)
    for k, b in enumerate(bodies):
        close(moments[k], ref.principal_axes(b.inertia_com)[0])
        close(axes[k] @ np.diag(moments[k]) @ axes[k].T, b.inertia_com)
