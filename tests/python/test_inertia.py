"""SpatialInertia from Python: formulas against numpy, invariants under random rotations and shifts
(hypothesis), validity (no false positives, report numbers in the error, opt-in, repair), the
(n, 3, 3) principal-axes array API against numpy.linalg.eigh, and bad inputs."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _error_bounds import EPS, product_tolerance, roundoff
from _helpers import hat

finite = st.floats(-3.0, 3.0, allow_nan=False)
positive = st.floats(0.1, 3.0)
vectors = st.tuples(finite, finite, finite).map(np.array)
rotations = st.integers(0, 2**32 - 1).map(lambda s: Rotation.random(random_state=s).as_matrix())


@st.composite
def bodies(draw):
    size = np.array([draw(positive), draw(positive), draw(positive)])
    box = rd.solid_box(size, mass=draw(positive))
    return box.transformed(rd.Transform(draw(rotations), draw(vectors)))


@settings(max_examples=100, deadline=None)
@given(bodies(), vectors, vectors, vectors)
def test_matrix_momentum_energy_against_numpy(body, w, v, p):
    m, c, I_C = body.mass, body.com, body.inertia_com
    I_O = I_C - m * hat(c) @ hat(c)
    M = np.block([[I_O, m * hat(c)], [m * hat(c).T, m * np.eye(3)]])
    # each entry: I_C + m hat(c) hat(c) (3-term sums of products <= m |c|^2), rounded on both sides
    tol_M = roundoff(np.abs(I_C).max() + m * (np.abs(c) @ np.abs(c)), 4)
    np.testing.assert_allclose(body.matrix(), M, atol=tol_M)
    twist = rd.Motion(w, v)
    h = body.momentum(twist)
    x = np.r_[w, v]
    # M x: gamma_6 |M||x| per side, plus M's own entry error times |x|
    tol_h = product_tolerance(M, x) + tol_M * np.abs(x).sum()
    np.testing.assert_allclose(h.to_vector(), M @ x, atol=tol_h)
    assert body.kinetic_energy(twist) == pytest.approx(
        0.5 * x @ M @ x, abs=0.5 * (tol_h * np.abs(x).sum() + product_tolerance([x], M @ x)))
    v_C = v + np.cross(w, c)
    # Craig: H_P = r_PC x L + H_C: one evaluation, terms |c - p| m |v_C| and |I_C| |w|
    expected = np.cross(c - p, m * v_C) + I_C @ w
    size = (np.abs(c - p).sum() * m * (np.abs(v).sum() + np.abs(w).sum() * np.abs(c).sum())
            + np.abs(I_C).sum() * np.abs(w).sum())
    np.testing.assert_allclose(body.angular_momentum_about_point(w, v_C, p), expected, atol=roundoff(size))
    np.testing.assert_allclose(body.angular_momentum_about_com(w), I_C @ w, atol=product_tolerance(I_C, w))


@settings(max_examples=100, deadline=None)
@given(bodies(), rotations, vectors)
def test_invariants_under_rotation_and_shift(body, R, p):
    moments = body.principal_axes().moments
    rotated = body.rotated(R)
    # R I R^T: gamma_9 of |I| <= 4.5 per entry; the trace, a sum of positive moments, to ~10 eps
    np.testing.assert_allclose(np.trace(rotated.inertia_com), np.trace(body.inertia_com), rtol=1e-12)
    # Weyl: each moment moves by <= |dI| <= ~8 eps |I| <= 8e-15 (|I| <= 4.5), within atol
    np.testing.assert_allclose(rotated.principal_axes().moments, moments, rtol=1e-12, atol=1e-14)
    assert rotated.report().valid()
    # parallel axis both ways
    I_P = body.inertia_about_point(p)
    r = body.com - p
    shift = body.mass * (r @ r)  # the size of the parallel-axis term (|r| <= 10.4, m <= 3: <= 324)
    np.testing.assert_allclose(I_P, body.inertia_com + body.mass * (r @ r * np.eye(3) - np.outer(r, r)),
                               atol=roundoff(np.abs(body.inertia_com).max() + shift, 4))
    back = rd.SpatialInertia.from_inertia_about_point(body.mass, body.com, I_P, p)
    # shifting back subtracts that term again: its round-off relative to |I_C| (Frobenius: 3x)
    I_C_size = np.linalg.norm(body.inertia_com)
    assert back.is_approx(body, 3 * roundoff(I_C_size + 2 * shift, 8) / I_C_size)
    report = rd.inertia_report(body.mass, I_P)
    assert report.triangle_inequality  # about any point, a real body still satisfies it


@settings(max_examples=50, deadline=None)
@given(st.lists(bodies(), min_size=2, max_size=6))
def test_composite_against_numpy_and_removal(parts):
    total = rd.composite(parts)
    m = sum(b.mass for b in parts)
    c = sum(b.mass * b.com for b in parts) / m
    I = sum(b.inertia_com + b.mass * ((b.com - c) @ (b.com - c) * np.eye(3) - np.outer(b.com - c, b.com - c)) for b in parts)
    assert total.mass == pytest.approx(m, rel=12 * EPS, abs=0)  # <= 6 positive terms: 6 eps relative per side
    # sums over <= 6 parts of terms <= m_i |com_i| and |I_i| + m_i |d_i|^2 (gamma_n, n ~ 4 per part)
    np.testing.assert_allclose(total.com, c, atol=roundoff(sum(b.mass * np.abs(b.com).max() for b in parts) / m, 24))
    size = sum(np.abs(b.inertia_com).max() + b.mass * (b.com - c) @ (b.com - c) for b in parts)
    np.testing.assert_allclose(total.inertia_com, I, atol=roundoff(size, 24))
    rest = total - parts[-1]
    # removal cancels: round-off of the total's size relative to the rest's inertia (Frobenius: 3x)
    rest_size = np.linalg.norm(rd.composite(parts[:-1]).inertia_com)
    assert rest.is_approx(rd.composite(parts[:-1]), max(1e-12, 3 * roundoff(2 * size, 48) / rest_size))


def test_composite_with_transforms_split_body():
    cube = rd.solid_box([1, 1, 1], density=2.0)
    X = [rd.Transform(translation=[x, 0, 0]) for x in (-1.0, 0.0, 1.0)]
    # three parts, shifts of 0 and 1 m: a few roundings of numbers <= 6 kg m^2 against 6.5: <= 32 eps
    assert rd.composite([(Xi, cube) for Xi in X]).is_approx(rd.solid_box([3, 1, 1], density=2.0), 1e-14)


def test_no_false_positive_after_shifting_away_and_back_and_rotating():
    rng = np.random.default_rng(3)
    for thin in (rd.thin_plate(1.0, 0.2, mass=1.0), rd.thin_rod(2.0, mass=1.0), rd.thin_disk(0.5, mass=3.0)):
        body = thin
        for _ in range(300):
            p = rng.uniform(-1e3, 1e3, 3)
            body = rd.SpatialInertia.from_inertia_about_point(body.mass, body.com, body.inertia_about_point(p), p)
            body = body.rotated(Rotation.random(random_state=rng).as_matrix())
        assert body.report().valid(), body.report().summary()


def test_unrealizable_inertia_rejected_with_numbers_and_opt_in():
    hlw = np.diag([2.0, 1.0, 2.0 / 3.0])
    with pytest.raises(ValueError, match=r"inertia_com: .*triangle.*0\.6666666.*condition number 3"):
        rd.SpatialInertia(1.0, np.zeros(3), hlw)
    body = rd.SpatialInertia(1.0, np.zeros(3), hlw, check=rd.InertiaCheck.allow_unrealizable)
    report = body.report()
    assert not report.valid() and report.valid(rd.InertiaCheck.allow_unrealizable)
    # a sum of the three moments (2, 1, 2/3; their magnitudes sum to < 4): <= 4 roundings per side
    assert report.triangle_margins[2] == pytest.approx(-1.0 / 3.0, rel=0, abs=roundoff(4.0, 4))
    with pytest.raises(ValueError, match="positive semi-definite"):
        rd.SpatialInertia(1.0, np.zeros(3), np.diag([-1.0, 1, 1]), check=rd.InertiaCheck.allow_unrealizable)


def test_repair_is_explicit_and_nearest():
    rng = np.random.default_rng(5)
    R = Rotation.random(random_state=rng).as_matrix()
    bad = R @ np.diag([0.2, 1.0, 3.0]) @ R.T
    fixed = rd.nearest_valid_inertia(bad)
    assert rd.inertia_report(1.0, fixed).valid()
    # same axes, moments projected onto I0 + I1 = I2 (deficit 1.8 spread as (1, 1, -1)/3)
    # R diag R^T and eigvalsh: a few eps of |I| <= 3 on each side
    np.testing.assert_allclose(np.linalg.eigvalsh(fixed), [0.8, 1.6, 2.4], atol=1e-12)
    good = rd.solid_box([1, 2, 3], mass=1.0).inertia_com
    np.testing.assert_allclose(rd.nearest_valid_inertia(good), good, atol=1e-15)  # valid: returned as is


def test_principal_axes_array_api_against_eigh():
    rng = np.random.default_rng(11)
    n = 500
    R = Rotation.random(n, random_state=rng).as_matrix()
    moments = np.sort(rng.uniform(1.0, 2.0, (n, 3)), axis=1)
    I = np.einsum("nij,nj,nkj->nik", R, moments, R)
    got_moments, axes = rd.principal_axes(I)
    assert got_moments.shape == (n, 3) and axes.shape == (n, 3, 3)
    # moments in [1, 2]: both eigen-solvers backward stable, <= ~8 eps |I| <= 4e-15 each (Weyl)
    np.testing.assert_allclose(got_moments, np.linalg.eigh(I)[0], atol=1e-13)
    np.testing.assert_allclose(np.linalg.det(axes), 1.0, atol=1e-12)  # orthonormal to ~8 eps
    # A diag A^T: gamma_3 of entries <= 2, plus the decomposition's backward error
    np.testing.assert_allclose(np.einsum("nij,nj,nkj->nik", axes, got_moments, axes), I, atol=1e-13)
    one_moments, one_axes = rd.principal_axes(I[0])
    assert one_moments.shape == (3,) and one_axes.shape == (3, 3)
    # coincident moments: deterministic, right-handed, the distinct axis exact
    cyl = rd.solid_cylinder(1.0, 0.2, mass=1.0)
    m2, a2 = rd.principal_axes(cyl.inertia_com)
    np.testing.assert_allclose(a2, np.eye(3), atol=1e-15)  # a diagonal inertia: exact axes
    # a sphere: the canonical axes, exactly
    np.testing.assert_array_equal(rd.principal_axes(np.eye(3) * 2.0)[1], np.eye(3))


def test_primitive_handbook_values_and_kwargs():
    # handbook formulas: <= 6 roundings of positive terms (a hollow body: outer minus inner, terms
    # <= 2x the result) on each side: 16 eps (32 eps for the hollow cylinder) of the largest moment
    np.testing.assert_allclose(rd.solid_sphere(0.5, mass=2.0).inertia_com, 0.2 * np.eye(3), rtol=0, atol=16 * EPS * 0.2)
    assert rd.solid_sphere(1.0, density=3.0).mass == pytest.approx(4 * math.pi, rel=8 * EPS, abs=0)  # 4 roundings
    np.testing.assert_allclose(rd.solid_cone(1.0, 4.0, mass=80.0).inertia_com, np.diag([60, 60, 24]), rtol=0,
                               atol=16 * EPS * 60)
    np.testing.assert_allclose(rd.hollow_cylinder(2.0, 1.0, 2.0, mass=12.0).inertia_com, np.diag([19, 19, 30]), rtol=0,
                               atol=32 * EPS * 30)
    tet = rd.solid_tetrahedron(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]]), density=6.0)
    np.testing.assert_allclose(tet.com, [0.25] * 3, rtol=0, atol=4 * EPS)  # the mean of four 0/1 coordinates
    assert rd.thin_plate(1.0, 2.0, mass=12.0).admits_symmetry_plane([0, 0, 1])


def test_point_masses_eqs_453_454():
    rng = np.random.default_rng(1)
    m = rng.uniform(0.1, 1.0, 20)
    r = rng.normal(size=(20, 3))
    body = rd.from_point_masses(m, r)
    c = (m[:, None] * r).sum(0) / m.sum()
    d = r - c
    I = sum(mi * (di @ di * np.eye(3) - np.outer(di, di)) for mi, di in zip(m, d))
    assert body.mass == pytest.approx(m.sum(), rel=roundoff(1.0, 20), abs=0)  # 20 positive terms: gamma_20 per side
    # sums of 20 terms: gamma_20 of sum m |r| / sum m and of sum m |d|^2
    np.testing.assert_allclose(body.com, c, atol=roundoff((m @ np.abs(r).max(axis=1)) / m.sum(), 20))
    np.testing.assert_allclose(body.inertia_com, I, atol=roundoff(m @ np.sum(d * d, axis=1), 24))


@pytest.mark.parametrize(
    ("call", "pattern"),
    [
        (lambda: rd.SpatialInertia(0.0, [0, 0, 0], np.eye(3)), r"^mass: expected .* got 0"),
        (lambda: rd.SpatialInertia(1.0, [0, 0, np.nan], np.eye(3)), r"^com: expected finite"),
        (lambda: rd.SpatialInertia(1.0, [0, 0], np.eye(3)), r"^com: expected shape \(3,\)"),
        (lambda: rd.SpatialInertia(1.0, [0, 0, 0], [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]), r"^inertia_com: expected a symmetric"),
        (lambda: rd.solid_sphere(-1.0, mass=1.0), r"^radius: expected .* got -1"),
        (lambda: rd.solid_sphere(1.0), r"^mass, density: expected exactly one .* got neither"),
        (lambda: rd.solid_sphere(1.0, mass=1.0, density=1.0), r"got both"),
        (lambda: rd.solid_box([1, 0, 1], density=1.0), r"^size: expected finite values > 0"),
        (lambda: rd.hollow_sphere(1.0, 2.0, mass=1.0), r"^inner_radius: expected .* got 2"),
        (lambda: rd.from_point_masses([1.0, -1.0], np.zeros((2, 3))), r"^masses\[1\]: expected .* got -1"),
        (lambda: rd.nearest_valid_inertia(np.full((3, 3), np.inf)), r"^inertia: expected finite"),
        (lambda: rd.principal_axes(np.zeros((4, 3, 2))), r"^inertia: expected shape"),
        (lambda: rd.solid_cylinder(1.0, 1.0, mass=1.0) - rd.solid_cylinder(1.0, 2.0, mass=2.0), r"^part\.mass"),
    ],
)
def test_bad_inputs_raise_naming_the_value(call, pattern):
    with pytest.raises(ValueError, match=pattern):
        call()


def test_bad_dtype_is_type_error():
    with pytest.raises(TypeError, match="com"):
        rd.SpatialInertia(1.0, ["a", "b", "c"], np.eye(3))


def test_a_sum_whose_inertia_would_overflow_is_refused_naming_the_distance():
    """m |c|² of a part 8e300 m away is beyond the largest double: a ValueError, not an inertia of inf and NaN."""
    far = rd.SpatialInertia.point_mass(1.0, [0.0, 0.0, 8e300])
    with pytest.raises(ValueError, match=r"the distance between the centres of mass: .* got 8\.0*\d*e\+300"):
        far + rd.solid_sphere(1.0, mass=1.0)
