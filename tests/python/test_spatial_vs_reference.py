"""The core's spatial algebra (rigiddyn, C++) against the independent numpy reference
(rigiddyn_ref.spatial: dense Featherstone matrices and the formulas written out) on
hypothesis-randomised twists, wrenches and transforms, to ~1e-12."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import rigiddyn as rd
from rigiddyn_ref import so3
from rigiddyn_ref import spatial as ref

settings.register_profile("reference", max_examples=80, deadline=None)
settings.load_profile("reference")

# one evaluation on each side: <= ~20 roundings (3x3 and 6x6 products, cross products) of terms
# <= |R| |p| |v| <= 1e3 (inputs <= 10, rotations <= 4 rad): <= 40 eps 1e3 = 9e-12 absolute, i.e.
# TOL relative to max(1e3, |value|) with a factor ~10 to spare
TOL = 1e-12
vec3 = arrays(np.float64, (3,), elements=st.floats(-10.0, 10.0))
vec6 = arrays(np.float64, (6,), elements=st.floats(-10.0, 10.0))
rotvec = arrays(np.float64, (3,), elements=st.floats(-4.0, 4.0))
scalar = st.floats(-10.0, 10.0)


def close(a, b, tol=TOL):
    np.testing.assert_allclose(a, b, rtol=tol, atol=tol * 1e3)  # entries up to ~1e3 in size


def motion(v6):
    return rd.Motion(v6[:3], v6[3:])


def force(v6):
    return rd.Force(v6[:3], v6[3:])


def transform(r, p):
    return rd.Transform(so3.rotvec_to_matrix(r), p)


# ------------------------------------------------------------------ containers
@given(vec6, vec6, scalar)
def test_motion_and_force_containers(a, b, s):
    for cls in (rd.Motion, rd.Force):
        x, y = cls(a[:3], a[3:]), cls.from_vector(b)
        close(x.angular, a[:3])
        close(x.linear, a[3:])
        close(y.to_vector(), b)
        close((x + y).to_vector(), a + b)
        close((x - y).to_vector(), a - b)
        close((-x).to_vector(), -a)
        close((x * s).to_vector(), s * a)


# ------------------------------------------------------------------ cross products and power
@given(vec6, vec6)
def test_motion_cross(m1, m2):
    got = motion(m1).cross(motion(m2)).to_vector()
    close(got, ref.cross_motion(m1, m2))
    close(got, ref.crm(m1) @ m2)
    close(rd.motion_cross_matrix(motion(m1)), ref.crm(m1))


@given(vec6, vec6)
def test_force_cross(m, f):
    got = motion(m).cross_force(force(f)).to_vector()
    close(got, ref.cross_force(m, f))
    close(got, ref.crf(m) @ f)
    close(rd.force_cross_matrix(motion(m)), ref.crf(m))


@given(vec6, vec6)
def test_power_pairing(m, f):
    want = ref.power(m, f)
    close(motion(m).dot(force(f)), want)
    close(force(f).dot(motion(m)), want)


# ------------------------------------------------------------------ transforms
@given(rotvec, vec3)
def test_transform_matrices(r, p):
    X = transform(r, p)
    R = so3.rotvec_to_matrix(r)
    close(X.rotation, R)
    close(X.translation, p)
    close(X.motion_matrix(), ref.motion_matrix(R, p))
    close(X.force_matrix(), ref.force_matrix(R, p))
    close(X.quat(), so3.matrix_to_quat(R))
    close(X.quat(scalar_first=True), so3.matrix_to_quat(R, scalar_first=True))


@given(rotvec, vec3)
def test_transform_from_quat(r, p):
    q = so3.rotvec_to_quat(r)
    for sf, qq in ((False, q), (True, q[[3, 0, 1, 2]])):
        X = rd.Transform.from_quat(qq, p, scalar_first=sf)
        close(X.motion_matrix(), ref.motion_matrix(so3.quat_to_matrix(q), p))


@given(rotvec, vec3, vec3, vec6, vec6)
def test_transform_actions(r, p, point, m, f):
    X, R = transform(r, p), so3.rotvec_to_matrix(r)
    close(X.act_point(point), ref.act_point(R, p, point))
    close(X.act_inv_point(point), ref.act_inv_point(R, p, point))
    close(X.act(motion(m)).to_vector(), ref.motion_matrix(R, p) @ m)
    close(X.act(force(f)).to_vector(), ref.force_matrix(R, p) @ f)
    # the reference solves with the 6x6 X: its condition (1 + |p|)^2 <= 340 multiplies eps (LU,
    # backward stable): <= 340 * 8 eps = 6e-13 relative; the core applies the closed-form inverse
    close(X.act_inv(motion(m)).to_vector(), np.linalg.solve(ref.motion_matrix(R, p), m), 1e-11)
    close(X.act_inv(force(f)).to_vector(), np.linalg.solve(ref.force_matrix(R, p), f), 1e-11)
    assert isinstance(X.act(motion(m)), rd.Motion)
    assert isinstance(X.act(force(f)), rd.Force)


@given(rotvec, vec3, rotvec, vec3)
def test_transform_compose_and_inverse(r1, p1, r2, p2):
    X_AB, X_BC = transform(r1, p1), transform(r2, p2)
    R1, R2 = so3.rotvec_to_matrix(r1), so3.rotvec_to_matrix(r2)
    R_AC, p_AC = ref.transform_compose(R1, p1, R2, p2)
    X_AC = X_AB * X_BC
    close(X_AC.rotation, R_AC)
    close(X_AC.translation, p_AC)
    close(X_AC.motion_matrix(), ref.motion_matrix(R1, p1) @ ref.motion_matrix(R2, p2))
    R_BA, p_BA = ref.transform_inverse(R1, p1)
    X_BA = X_AB.inverse()
    close(X_BA.rotation, R_BA)
    close(X_BA.translation, p_BA)


# ------------------------------------------------------------------ screws
@given(vec6)
@example(np.full(6, 5e-324))  # a subnormal w, whose norm rounds to 1e-323 (w / |w| = 0.5 each)
def test_twist_to_screw(m):
    if np.all(m == 0.0):
        return  # no axis: the core raises (tested with the bad-input tests)
    with np.errstate(over="ignore", divide="ignore"):
        direction, point, pitch, magnitude = ref.twist_to_screw(m)
        # pitch and point scale like |v|/|w| (inf for a pure translation, may overflow for a subnormal w)
        size = np.linalg.norm(m[3:]) / magnitude
    rotating = bool(np.any(m[:3] != 0.0))  # not |w| > 0: the plain norm of a subnormal w underflows to 0
    if rotating and size > 1e300:
        # |w| so small (subnormal) that |v|/|w| is within a few roundings of overflow: the two sides
        # round |w| differently, so either may overflow first. The core either refuses the twist by
        # name or returns a finite screw; compare where both are finite.
        try:
            screw = rd.twist_to_screw(motion(m))
        except ValueError as error:
            assert "twist: expected an angular part large enough" in str(error)
            return
        assert np.all(np.isfinite(screw.point)) and np.isfinite(screw.pitch)
        close(screw.direction, direction)
        if np.isfinite(size) and np.all(np.isfinite(point)) and np.isfinite(pitch):
            np.testing.assert_allclose(screw.pitch, pitch, rtol=1e-11, atol=1e-11 * size)  # relative to |v|/|w|
            np.testing.assert_allclose(screw.point, point, rtol=1e-11, atol=1e-11 * size)
        return
    screw = rd.twist_to_screw(motion(m))
    close(screw.direction, direction)
    close(screw.magnitude, magnitude)
    if np.isinf(pitch):
        assert np.isinf(screw.pitch) and screw.pitch > 0
        close(screw.point, np.zeros(3))
    else:
        scale = max(1.0, size)
        # w.v/|w|^2 and w x v/|w|^2: a few roundings, relative to |v|/|w| (also where w.v cancels)
        close(screw.pitch / scale, pitch / scale, 1e-11)
        close(screw.point / scale, point / scale, 1e-11)
