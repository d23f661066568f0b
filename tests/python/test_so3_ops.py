"""The SciPy-parity rotation operations against scipy.spatial.transform: nearest rotation of rounded
matrices, slerp (two rotations and key times), angular distance, canonical sign, random rotations
(same draws as SciPy for the same generator, and Haar-uniform) and align_vectors (Wahba's problem,
weights and its special cases). Random inputs from seeded Generators, hundreds of cases each,
including angles near 0 and near pi; properties beside each comparison (slerp's endpoints and
constant rate, the distance a metric, the projection idempotent and orthonormal)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats
from scipy.spatial.transform import Rotation, Slerp

import rigiddyn as rd

EPS = np.finfo(float).eps
N = 300  # random cases per comparison


# ---------------------------------------------------------------------------- helpers


def unit_quats(rng: np.random.Generator, n: int) -> np.ndarray:
    """(n, 4) unit quaternions (x, y, z, w), uniform, either sign of w"""
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def scipy_random(n: int | None, rng: np.random.Generator) -> Rotation:
    """Rotation.random under its current keyword (rng=, SciPy >= 1.15) or the older random_state="""
    try:
        return Rotation.random(n, rng=rng)
    except TypeError:  # pragma: no cover - older SciPy
        return Rotation.random(n, random_state=rng)


def sign_free_difference(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """max |q1 - (±q2)| item by item, the sign chosen per item (q and -q are one rotation)"""
    return np.minimum(np.abs(q1 - q2).max(axis=-1), np.abs(q1 + q2).max(axis=-1))


def rotations_near(rng: np.random.Generator, q: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """q composed with rotations by the given angles about random axes"""
    axes = rng.normal(size=(len(angles), 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    return (Rotation.from_quat(q) * Rotation.from_rotvec(axes * angles[:, None])).as_quat()


# delicate angles: tiny, ordinary, near pi and pi itself
DELICATE_ANGLES = np.array([0.0, 1e-15, 1e-12, 1e-8, 1e-4, 0.5, 2.0, np.pi - 1e-4, np.pi - 1e-8, np.pi - 1e-12, np.pi])


# ---------------------------------------------------------------------------- nearest rotation


@pytest.mark.parametrize("digits", [2, 3, 4, 6, 8])
def test_nearest_rotation_of_rounded_matrices_is_scipys(digits):
    rng = np.random.default_rng(100 + digits)
    M = np.round(scipy_random(N, rng).as_matrix(), digits)
    R = rd.nearest_rotation(M)
    # SciPy's from_matrix projects with numpy's SVD (U @ Vt, det M > 0 here). Both SVDs are backward
    # stable, |E| <= ~20 eps |M|, and the polar factor moves by <= 2 |E| / (s2 + s3) <= 1.05 |E|
    # (singular values >= 0.95); U V^T adds ~3 eps per entry: <= 2 (1.05 * 20 * sqrt(3) + 3) eps
    # ~ 1.8e-14 together; 1e-13 leaves a 5x margin
    U, _, Vt = np.linalg.svd(M)
    np.testing.assert_allclose(R, U @ Vt, rtol=0, atol=1e-13)
    # and the quaternion of the projection is SciPy's from_matrix (Markley's branches, as SciPy):
    # the same 1e-13 on R, amplified by <= 1 through the conversion (divides by 4 |q_max| >= 2)
    q = rd.matrix_to_quat(R)
    q_scipy = Rotation.from_matrix(M).as_quat(canonical=True)
    assert sign_free_difference(q, q_scipy).max() < 1e-13


def test_nearest_rotation_is_orthonormal_proper_idempotent_and_nearest():
    rng = np.random.default_rng(7)
    M = scipy_random(N, rng).as_matrix() + 0.2 * rng.normal(size=(N, 3, 3))
    R = rd.nearest_rotation(M)
    I = np.eye(3)
    # Jacobi SVD: U, V orthonormal to a few eps; U V^T errs by a few eps per entry: 16 eps
    assert np.abs(np.swapaxes(R, 1, 2) @ R - I).max() < 16 * EPS
    assert np.abs(np.linalg.det(R) - 1.0).max() < 16 * EPS
    # idempotent: projecting a rotation (singular values 1 +- 16 eps) moves it by round-off
    assert np.abs(rd.nearest_rotation(R) - R).max() < 32 * EPS
    # nearest: no rotation of a random sample near R is closer to M (Frobenius)
    other = R @ Rotation.from_rotvec(1e-3 * rng.normal(size=(N, 3))).as_matrix()
    assert np.all(np.linalg.norm(M - R, axis=(1, 2)) <= np.linalg.norm(M - other, axis=(1, 2)))


def test_nearest_rotation_of_a_reflection_flips_the_smallest_direction():
    rng = np.random.default_rng(8)
    M = scipy_random(N, rng).as_matrix() @ np.diag([1.0, 1.0, -1.0]) + 0.1 * rng.normal(size=(N, 3, 3))
    M = M[np.linalg.det(M) < 0]
    U, s, Vt = np.linalg.svd(M)
    U[:, :, 2] *= -1.0  # the Kabsch correction on numpy's SVD
    # the flipped direction is well defined when s2 > s3: the polar-type factor then moves by
    # <= 2 |E| / (s2 - s3); bound per case with |E| <= 20 eps |M| per side
    bound = 4 * 20 * EPS * s[:, 0] / (s[:, 1] - s[:, 2]) + 8 * EPS
    assert np.all(np.abs(rd.nearest_rotation(M) - U @ Vt).max(axis=(1, 2)) <= bound)


def test_matrix_to_quat_accepts_rounded_matrices_as_scipy():
    rng = np.random.default_rng(9)
    M = np.round(scipy_random(N, rng).as_matrix(), 3)
    # as test_nearest_rotation_of_rounded_matrices_is_scipys: 1e-13
    assert sign_free_difference(rd.matrix_to_quat(M), Rotation.from_matrix(M).as_quat()).max() < 1e-13


@pytest.mark.parametrize("bad", [np.full((3, 3), np.nan), np.full((3, 3), np.inf)])
def test_nearest_rotation_refuses_non_finite(bad):
    with pytest.raises(ValueError, match=r"^M: expected .*finite"):
        rd.nearest_rotation(bad)


# ---------------------------------------------------------------------------- canonical sign


def test_quat_canonical_is_scipys_including_ties():
    rng = np.random.default_rng(10)
    q = unit_quats(rng, N)
    ties = np.array([[-1.0, 0, 0, 0], [0, -1.0, 0, 0], [0, 0, -1.0, 0], [-0.6, 0.8, 0, 0], [0.0, -0.6, 0.8, 0],
                     [-0.0, 0.0, -1.0, -0.0], [0.6, 0, 0, -0.8], [0, 0, 0, -1.0]])
    q = np.concatenate([q, ties, -ties])
    expected = Rotation.from_quat(q).as_quat(canonical=True)
    # a sign flip is exact; SciPy's from_quat normalises (|q| = 1 to ~1 ulp) and so does the core:
    # each side moves a component by <= 2 ulp of 1
    np.testing.assert_allclose(rd.quat_canonical(q), expected, rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(rd.quat_canonical(np.roll(q, 1, axis=1), scalar_first=True),
                               np.roll(expected, 1, axis=1), rtol=0, atol=4 * EPS)
    # a single item stays single
    assert rd.quat_canonical([0.0, 0.0, 0.0, -1.0]).shape == (4,)


# ---------------------------------------------------------------------------- slerp


def test_slerp_is_scipys_for_two_rotations():
    rng = np.random.default_rng(11)
    q0 = unit_quats(rng, N)
    # second rotations at random and at delicate angles from the first
    q1 = np.concatenate([unit_quats(rng, N), rotations_near(rng, q0[:len(DELICATE_ANGLES)], DELICATE_ANGLES)])
    q0 = np.concatenate([q0, q0[:len(DELICATE_ANGLES)]])
    t = rng.uniform(0.0, 1.0, size=len(q0))
    ours = rd.slerp(q0, q1, t)
    theirs = np.array([Slerp([0.0, 1.0], Rotation.from_quat([a, b]))(s).as_quat() for a, b, s in zip(q0, q1, t)])
    # the same formula q0 * exp(t log(q0^-1 q1)) on both sides, ~40 roundings on unit numbers each:
    # <= 2 * 40 eps = 1.8e-14; 5e-14 for the differing summation orders of the products. At the
    # exact half turn (angle pi) the shortest path is ambiguous: both sides take log with w >= 0 of
    # the same product, so they agree there too.
    assert sign_free_difference(ours, theirs).max() < 5e-14


def test_slerp_endpoints_constant_rate_and_canonical():
    rng = np.random.default_rng(12)
    q0, q1 = unit_quats(rng, N), unit_quats(rng, N)
    # exp(0) = 1 exactly and q0 * 1 = q0; only the core's normalisation of q0 (|q0| = 1 within an
    # ulp) rounds: <= 2 eps per component
    np.testing.assert_allclose(rd.slerp(q0, q1, 0.0), q0, rtol=0, atol=2 * EPS)
    # log, scale, exp and product: <= ~40 roundings on unit numbers: 64 eps in angle
    assert rd.angular_distance(rd.slerp(q0, q1, 1.0), q1).max() < 64 * EPS
    total = rd.angular_distance(q0, q1)
    t = np.linspace(0.0, 1.0, 11)
    for a, b, angle in zip(q0[:30], q1[:30], total[:30]):
        path = rd.slerp(a, b, t)
        # constant angular rate: every tenth of the way turns by a tenth of the angle (64 eps each)
        np.testing.assert_allclose(rd.angular_distance(path[:-1], path[1:]), angle / 10, rtol=0, atol=64 * EPS)
        np.testing.assert_allclose(rd.angular_distance(a, path), t * angle, rtol=0, atol=64 * EPS)
    assert np.all(rd.slerp(q0, q1, 0.3, canonical=True)[:, 3] >= 0.0)
    np.testing.assert_allclose(rd.slerp(np.roll(q0, 1, axis=1), np.roll(q1, 1, axis=1), 0.3, scalar_first=True),
                               np.roll(rd.slerp(q0, q1, 0.3), 1, axis=1), rtol=0, atol=0)


def test_slerp_keys_is_scipys_slerp():
    rng = np.random.default_rng(13)
    for k in [2, 3, 7, 20]:
        times = np.cumsum(rng.uniform(0.1, 2.0, size=k))
        q = unit_quats(rng, k)
        # inside, at every key time (SciPy uses the segment ending there) and at both ends
        t = np.concatenate([rng.uniform(times[0], times[-1], size=N // 4), times])
        ours = rd.slerp_keys(times, q, t)
        theirs = Slerp(times, Rotation.from_quat(q))(t).as_quat()
        # as test_slerp_is_scipys_for_two_rotations, plus the fraction (t - t_k) / (t_k+1 - t_k)
        # computed alike on both sides: 5e-14
        assert sign_free_difference(ours, theirs).max() < 5e-14
        assert rd.slerp_keys(times, q, times[1]).shape == (4,)


@pytest.mark.parametrize(("call", "message"), [
    (lambda: rd.slerp_keys([0.0, 1.0], np.eye(4)[:2], 1.5), r"^t: expected times within the key times \[0, 1\].*\(item 0\)|^t: expected times within"),
    (lambda: rd.slerp_keys([0.0, 1.0], np.eye(4)[:2], [0.5, -0.1]), r"^t: expected times within .*\(item 1\)"),
    (lambda: rd.slerp_keys([0.0, 0.0], np.eye(4)[:2], 0.0), r"^times: expected strictly increasing"),
    (lambda: rd.slerp_keys([0.0, 1.0, 2.0], np.eye(4)[:2], 0.0), r"^q: expected 3 key rotations"),
    (lambda: rd.slerp_keys([0.0], np.eye(4)[:1], 0.0), r"^times: expected at least 2"),
    (lambda: rd.slerp_keys([0.0, 1.0], [[0, 0, 0, 1.0], [0, 0, 0, 2.0]], 0.0), r"^q: expected a unit quaternion.*\(item 1\)"),
    (lambda: rd.slerp(np.eye(4)[:2], np.eye(4)[:3], 0.5), r"^q1: expected 2 items \(as q0\), got 3"),
    (lambda: rd.slerp([0, 0, 0, 1.0], [0, 0, 0, 1.0], [0.1, np.nan]), r"^t: expected"),
])
def test_slerp_bad_input_names_the_argument(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# ---------------------------------------------------------------------------- angular distance


def test_angular_distance_is_scipys_magnitude():
    rng = np.random.default_rng(14)
    q_a = unit_quats(rng, N)
    q_b = np.concatenate([unit_quats(rng, N - len(DELICATE_ANGLES)), rotations_near(rng, q_a[:len(DELICATE_ANGLES)], DELICATE_ANGLES)])
    expected = (Rotation.from_quat(q_a).inv() * Rotation.from_quat(q_b)).magnitude()
    # both: one quaternion product (a few roundings per component, <= 4 eps) and 2 atan2(|v|, |w|),
    # whose absolute error is 2 |dq| <= 8 eps per side at every angle (atan2 is well conditioned in
    # the angle): 16 eps
    np.testing.assert_allclose(rd.angular_distance(q_a, q_b), expected, rtol=0, atol=16 * EPS)
    np.testing.assert_allclose(rd.angular_distance(q_a, q_b, degrees=True), np.degrees(rd.angular_distance(q_a, q_b)),
                               rtol=2 * EPS, atol=0)  # one multiplication by 180/pi on each side
    assert isinstance(rd.angular_distance(q_a[0], q_b[0]), float)


def test_angular_distance_is_accurate_at_tiny_angles_and_near_pi():
    rng = np.random.default_rng(15)
    for angle in DELICATE_ANGLES:
        q_a = unit_quats(rng, 50)
        q_b = rotations_near(rng, q_a, np.full(50, angle))
        # absolute error: q_b's components round by <= ~4 eps (SciPy's product), the core's product
        # by <= 4 eps more, doubled by 2 atan2: <= 32 eps. An acos(|w|) form errs by ~sqrt(eps) =
        # 1.5e-8 near 0 and would fail here.
        np.testing.assert_allclose(rd.angular_distance(q_a, q_b), angle, rtol=0, atol=32 * EPS)


def test_angular_distance_is_a_metric():
    rng = np.random.default_rng(16)
    a, b, c = unit_quats(rng, N), unit_quats(rng, N), unit_quats(rng, N)
    d_ab, d_ba = rd.angular_distance(a, b), rd.angular_distance(b, a)
    # each distance errs by <= 8 eps (above): symmetric to 16 eps, triangle to 24 eps
    np.testing.assert_allclose(d_ab, d_ba, rtol=0, atol=16 * EPS)
    assert np.all(rd.angular_distance(a, c) <= d_ab + rd.angular_distance(b, c) + 24 * EPS)
    assert np.all(rd.angular_distance(a, -a) <= 8 * EPS)  # q and -q: the same rotation
    assert np.all(rd.angular_distance(a, a) <= 8 * EPS)
    assert np.all((d_ab >= 0.0) & (d_ab <= np.pi))


# ---------------------------------------------------------------------------- random rotations


def test_random_rotations_are_scipys_draws():
    for seed in range(5):
        ours = rd.random_rotations(N, np.random.default_rng(seed))
        theirs = scipy_random(N, np.random.default_rng(seed)).as_quat()
        # the same normal draws, normalised on both sides: |q| by <= 4 roundings and a sqrt, the
        # division by one more: <= ~3 eps relative per side, <= 8 eps together
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=8 * EPS)
    # a seed is given to numpy.random.default_rng, as SciPy does; a single rotation is (4,)
    np.testing.assert_allclose(rd.random_rotations(None, 3), scipy_random(None, np.random.default_rng(3)).as_quat(),
                               rtol=0, atol=8 * EPS)
    # the generator advances by 4 draws per rotation: two calls give SciPy's two calls
    rng_ours, rng_theirs = np.random.default_rng(4), np.random.default_rng(4)
    rd.random_rotations(7, rng_ours)
    scipy_random(7, rng_theirs)
    np.testing.assert_allclose(rd.random_rotations(3, rng_ours), scipy_random(3, rng_theirs).as_quat(), rtol=0, atol=8 * EPS)
    q = rd.random_rotations(N, 5, canonical=True, scalar_first=True)
    assert np.all(q[:, 0] >= 0.0)
    assert rd.random_rotations(0, 1).shape == (0, 4)


# KS tests below: at a false-alarm rate ALPHA a correct sampler fails with probability ALPHA per
# seed; the seed is fixed, so the outcome is deterministic (and was not chosen by trying seeds)
ALPHA = 1e-3
SAMPLES = 20_000


def haar_angle_cdf(theta):
    """CDF of the rotation angle under the Haar measure on SO(3): density (1 - cos t) / pi on [0, pi]"""
    return (theta - np.sin(theta)) / np.pi


def test_random_rotations_are_haar_uniform():
    q = rd.random_rotations(SAMPLES, np.random.default_rng(2026))
    angle = 2.0 * np.arctan2(np.linalg.norm(q[:, :3], axis=1), np.abs(q[:, 3]))
    assert stats.kstest(angle, haar_angle_cdf).pvalue > ALPHA
    # the axis is uniform on the sphere, so each of its components is uniform on [-1, 1]
    axis = q[:, :3] / np.linalg.norm(q[:, :3], axis=1, keepdims=True)
    for k in range(3):
        assert stats.kstest(axis[:, k], stats.uniform(loc=-1.0, scale=2.0).cdf).pvalue > ALPHA
    # the test has power: rotations with a uniformly distributed angle are rejected
    wrong = np.random.default_rng(2026).uniform(0.0, np.pi, size=SAMPLES)
    assert stats.kstest(wrong, haar_angle_cdf).pvalue < ALPHA


@pytest.mark.parametrize(("kwargs", "error", "message"), [
    ({"n": -1}, ValueError, r"^n: expected"),
    ({"n": 2.0}, TypeError, r"^n: expected"),
    ({"rng": "seed"}, TypeError, r"^rng: expected a numpy.random.Generator"),
    ({"rng": -3}, ValueError, r"^rng: expected"),
])
def test_random_rotations_bad_input(kwargs, error, message):
    with pytest.raises(error, match=message):
        rd.random_rotations(**{"n": 2, **kwargs})


# ---------------------------------------------------------------------------- align_vectors


def alignment_bound(a, b, w):
    """Round-off bound on the rotation angle of the SVD solution: B = sum w a b^T is formed with
    error |E| <= 4 N eps sum w |a| |b| per side, and the polar factor of B moves by <= 2 |E| / (s2 + s3)
    (Higham); both sides together, with a 4x margin for the SVDs' own backward errors"""
    B = (w[:, None] * a).T @ b
    s = np.linalg.svd(B, compute_uv=False)
    return 4 * 2 * 2 * 4 * len(a) * EPS * np.sum(w * np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1)) / (s[1] + s[2]), s


def test_align_vectors_is_scipys_general_case():
    rng = np.random.default_rng(17)
    for case in range(N):
        n = rng.integers(2, 12)
        b = rng.normal(size=(n, 3))
        truth = scipy_random(None, rng)
        a = truth.apply(b) + 0.1 * rng.normal(size=(n, 3))  # noisy observations
        w = rng.uniform(0.1, 3.0, size=n)
        q, rssd, sensitivity = rd.align_vectors(a, b, w, return_sensitivity=True)
        r_scipy, rssd_scipy, sensitivity_scipy = Rotation.align_vectors(a, b, w, return_sensitivity=True)
        bound, s = alignment_bound(a, b, w)
        assert rd.angular_distance(q, r_scipy.as_quat()) <= bound, case
        assert q[3] >= 0.0
        # SciPy's rssd is sqrt(sum w (|a|^2 + |b|^2) - 2 sum s): cancellation errs by <= 4 N eps S
        # in the square (S that sum); the core sums w |a - R b|^2 directly (first order in the
        # rotation's error vanishes at the optimum). Compare the squares.
        S = np.sum(w * (np.sum(a * a, axis=1) + np.sum(b * b, axis=1)))
        assert abs(rssd**2 - rssd_scipy**2) <= 8 * n * EPS * S, case
        # sensitivity: mean(w) / zeta (kappa I + B B^T) from singular values that err by eps s1
        # each, so relatively by eps s1 / (s2 + s3) through zeta's smallest factor: 64x that
        rel = 64 * EPS * s[0] / (s[1] + s[2])
        np.testing.assert_allclose(sensitivity, sensitivity_scipy, rtol=rel, atol=rel * np.abs(sensitivity_scipy).max())


def test_align_vectors_recovers_an_exact_rotation_and_is_optimal():
    rng = np.random.default_rng(18)
    for _ in range(100):
        b = rng.normal(size=(5, 3))
        truth = scipy_random(None, rng)
        a = truth.apply(b)
        q, rssd = rd.align_vectors(a, b)
        w = np.ones(5)
        bound, _ = alignment_bound(a, b, w)
        assert rd.angular_distance(q, truth.as_quat()) <= bound
        # rssd of the exact rotation: <= |a| (bound + a few eps) per vector
        assert rssd <= np.sqrt(5) * np.abs(a).max() * (bound + 8 * EPS) * 3
    # optimality on noisy data: small turns of the solution never lower the loss
    b = rng.normal(size=(8, 3))
    a = scipy_random(None, rng).apply(b) + 0.2 * rng.normal(size=(8, 3))
    q, rssd = rd.align_vectors(a, b)
    loss = lambda r: np.sum((a - r.apply(b)) ** 2)  # noqa: E731
    best = Rotation.from_quat(q)
    np.testing.assert_allclose(np.sqrt(loss(best)), rssd, rtol=1e-12)  # the same sum, other order
    for turn in 1e-4 * rng.normal(size=(50, 3)):
        assert loss(best) <= loss(Rotation.from_rotvec(turn) * best)


def test_align_vectors_one_pair_and_infinite_weight_are_scipys():
    rng = np.random.default_rng(19)
    for case in range(N):
        n = 1 if case % 3 == 0 else rng.integers(2, 6)
        a, b = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
        w = rng.uniform(0.1, 3.0, size=n)
        primary = rng.integers(n)
        if n > 1:
            w[primary] = np.inf
        else:
            primary = 0
        if case % 10 == 1:  # an exactly antiparallel primary pair (scaling by -2 is exact)
            b[primary] = -2.0 * a[primary]
        q, rssd = rd.align_vectors(a, b, w)
        r_scipy, rssd_scipy = Rotation.align_vectors(a, b, w)
        # the shortest arc's axis b x a / |b x a| errs by ~eps / sin(angle between them) relatively
        # (4 eps per side); the turn phi = atan2(S_sin, S_cos) by <= 4 n eps sum w |a| |b| / hypot(S_sin, S_cos)
        a_hat, b_hat = a[primary] / np.linalg.norm(a[primary]), b[primary] / np.linalg.norm(b[primary])
        sin_angle = np.linalg.norm(np.cross(b_hat, a_hat))
        arc = 16 * EPS / sin_angle if sin_angle > 0 else 16 * EPS
        c = Rotation.from_quat(q).apply(b)
        others = np.arange(n) != primary
        scale = np.sum(w[others] * np.linalg.norm(a[others], axis=1) * np.linalg.norm(b[others], axis=1))
        turn = 0.0
        if n > 1:
            s_sin = np.sum(w[others] * (np.cross(c[others], a[others]) @ a_hat))
            s_cos = np.sum(w[others] * (np.sum(c[others] * a[others], axis=1) - (c[others] @ a_hat) * (a[others] @ a_hat)))
            turn = 16 * n * EPS * scale / np.hypot(s_sin, s_cos)
        assert rd.angular_distance(q, r_scipy.as_quat()) <= arc + turn + 16 * EPS, case
        # rssd: the same sum sqrt(sum w |a - R b|^2) over the finite weights; it moves by the rotation's
        # difference times sum w |a| |b|, plus round-off
        assert abs(rssd - rssd_scipy) <= (arc + turn + 16 * EPS) * (1 + scale + np.sum(w[~np.isinf(w)])) * 4, case
        # the primary pair is aligned exactly (to the arc's round-off)
        np.testing.assert_allclose(c[primary] / np.linalg.norm(c[primary]), a_hat, rtol=0, atol=arc + 8 * EPS)


def test_align_vectors_aligns_nearly_antiparallel_primary_pairs_exactly():
    # b = -2.5 a rounds, so b x a is round-off of arbitrary direction: SciPy turns about it and may
    # miss a by O(1) here; the core removes the axis' component along a and aligns to round-off
    rng = np.random.default_rng(21)
    for _ in range(N):
        a = rng.normal(size=3)
        for b in (-2.5 * a, -a + 1e-13 * rng.normal(size=3)):
            q, _ = rd.align_vectors(a, b)
            c = Rotation.from_quat(q).apply(b)
            # a turn about an axis perpendicular to a (to ~2 eps) by pi - |b x a|: |b x a| errs by
            # <= ~4 eps (components of unit vectors, two products and a difference each), so does
            # the turn, and the normalisations of a, b and R b add ~2 eps each: 16 eps, plus b's
            # deviation from -a (the true angle's distance from pi, turned along with it)
            deviation = np.linalg.norm(b / np.linalg.norm(b) + a / np.linalg.norm(a))
            np.testing.assert_allclose(c / np.linalg.norm(c), a / np.linalg.norm(a), rtol=0, atol=16 * EPS + deviation)


def test_align_vectors_parallel_pairs_warn_as_scipy():
    a = [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]
    b = [[0.0, 1.0, 0.0], [0.0, 2.0, 0.0]]
    with pytest.warns(UserWarning, match="not unique"):
        q, rssd = rd.align_vectors(a, b)
    # still a rotation taking the y axis onto the x axis: exact up to the SVD's round-off (8 eps)
    np.testing.assert_allclose(Rotation.from_quat(q).apply(b), a, rtol=0, atol=8 * EPS)


@pytest.mark.parametrize(("args", "kwargs", "message"), [
    ((np.ones((2, 3)), np.ones((3, 3))), {}, r"^b: expected the shape of a"),
    ((np.ones((2, 3)), np.ones((2, 3))), {"weights": [1.0, -1.0]}, r"^weights: expected weights >= 0"),
    ((np.ones((2, 3)), np.ones((2, 3))), {"weights": [np.inf, np.inf]}, r"^weights: expected at most one infinite"),
    ((np.ones((2, 3)), np.ones((2, 3))), {"weights": [1.0, 1.0, 1.0]}, r"^weights: expected shape \(2,\)"),
    ((np.ones((2, 3)), np.ones((2, 3))), {"weights": [np.inf, 1.0], "return_sensitivity": True}, r"^return_sensitivity: expected False"),
    (([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), {}, r"^a: expected a non-zero primary vector"),
    (([1.0, 0.0, np.nan], [1.0, 0.0, 0.0]), {}, r"^a: expected"),
])
def test_align_vectors_bad_input_names_the_argument(args, kwargs, message):
    with pytest.raises(ValueError, match=message):
        rd.align_vectors(*args, **kwargs)


def test_align_vectors_scalar_first():
    rng = np.random.default_rng(20)
    a, b = rng.normal(size=(4, 3)), rng.normal(size=(4, 3))
    q, _ = rd.align_vectors(a, b)
    q_first, _ = rd.align_vectors(a, b, scalar_first=True)
    np.testing.assert_array_equal(q_first, np.roll(q, 1))


@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_align_vectors_at_extreme_magnitudes(scale):
    # the rotation does not depend on the scale of a, b or w: B is formed from scaled vectors, so
    # 1e200-sized vectors (B ~ 1e400 unscaled) give the unscaled rotation; only the last rounding
    # of each division by a power-free scale differs: 64 eps in angle
    rng = np.random.default_rng(22)
    for n in [1, 2, 6]:
        a, b = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
        w = rng.uniform(0.5, 2.0, size=n)
        q, rssd = rd.align_vectors(a, b, w)
        q_big, rssd_big = rd.align_vectors(scale * a, scale * b, w)
        assert rd.angular_distance(q, q_big) < 64 * EPS
        # rssd moves with the rotation: |d rssd| <= |dR b| <= 64 eps sqrt(sum w |b|^2), plus the
        # residual sum's own rounding (16 eps relative)
        bound = 64 * EPS * scale * np.sqrt(np.sum(w * np.sum(b * b, axis=1))) + 16 * EPS * scale * rssd
        assert abs(rssd_big - scale * rssd) <= bound


def test_from_scipy_canonical():
    rotation = Rotation.from_quat(unit_quats(np.random.default_rng(23), N))
    q = rd.from_scipy(rotation, canonical=True)
    # SciPy's own canonical representative, unchanged (a copy)
    np.testing.assert_array_equal(q, rotation.as_quat(canonical=True))
    np.testing.assert_array_equal(rd.from_scipy(rotation, scalar_first=True, canonical=True), np.roll(q, 1, axis=1))
    with pytest.raises(TypeError, match=r"^canonical: expected True or False"):
        rd.from_scipy(rotation, canonical=1)
