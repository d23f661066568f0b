"""The numpy reference (rigiddyn_ref) checked on its own, so that the oracle the core is compared
with is itself trusted: rotations against SciPy, spatial structured forms against their dense
6x6 matrices, kinematics against Craig's worked example and a finite-difference trajectory,
the integrators against DOP853, the exact free flow against a long-double Taylor series.
Never imports rigiddyn."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from rigiddyn_ref import dynamics, free_flow, integrators, kinematics, so3, spatial

EPS = np.finfo(float).eps
SEQUENCES = [s for base in ("xyz", "xzy", "yxz", "yzx", "zxy", "zyx",
                            "xyx", "xzx", "yxy", "yzy", "zxz", "zyz") for s in (base, base.upper())]


@pytest.fixture(scope="module")
def rotations():
    rng = np.random.default_rng(7)
    q = rng.normal(size=(400, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    q[:50, :3] *= 1e-9  # near the identity
    q[50:100, 3] *= 1e-9  # near a half turn
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    return q, Rotation.from_quat(q)


def test_so3_conversions_match_scipy(rotations):
    # each side: a few correctly rounded operations on unit numbers (rotations <= pi, SIMD
    # transcendental functions <= 4 ulp): <= ~20 eps per entry, both sides 1e-14; products 1e-15 x 10
    q, S = rotations
    np.testing.assert_allclose(so3.quat_to_matrix(q), S.as_matrix(), atol=1e-15 * 10)
    np.testing.assert_allclose(so3.matrix_to_quat(S.as_matrix()), S.as_quat(canonical=True),
                               atol=1e-15 * 10)
    np.testing.assert_allclose(so3.quat_to_rotvec(q), S.as_rotvec(), atol=1e-14)
    np.testing.assert_allclose(so3.rotvec_to_matrix(S.as_rotvec()), S.as_matrix(), atol=1e-14)
    np.testing.assert_allclose(so3.quat_to_matrix(so3.rotvec_to_quat(S.as_rotvec())),
                               S.as_matrix(), atol=1e-14)
    np.testing.assert_allclose(so3.quat_to_matrix(q[:, [3, 0, 1, 2]], scalar_first=True),
                               S.as_matrix(), atol=1e-14)
    v = np.random.default_rng(1).normal(size=(400, 3))
    np.testing.assert_allclose(so3.quat_rotate(q, v), S.apply(v), atol=1e-14)
    np.testing.assert_allclose(so3.quat_to_matrix(so3.quat_multiply(q, q[::-1])),
                               (S * S[::-1]).as_matrix(), atol=1e-14)
    for name, axis in (("rot_x", "x"), ("rot_y", "y"), ("rot_z", "z")):
        np.testing.assert_allclose(getattr(so3, name)(0.7),
                                   Rotation.from_euler(axis, 0.7).as_matrix(), atol=1e-15)


@pytest.mark.parametrize("seq", SEQUENCES)
def test_euler_matches_scipy_including_gimbal_lock(rotations, seq):
    q, S = rotations
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SciPy warns about gimbal lock (near-identity samples)
        angles = S.as_euler(seq)
    # angles from R: R's round-off (a few eps) amplified by 1/|cos b| or 1/|sin b|; the near-lock
    # samples (1e-9 from the identity) are locked on both sides: 1e-13 covers amplification <= 50
    np.testing.assert_allclose(so3.matrix_to_euler(seq, S.as_matrix()), angles, atol=1e-13)
    # where SciPy (and the reference) declare gimbal lock (|sin|, |cos| of θ2 < ~1e-7), setting
    # θ3 = 0 loses up to ~θ2 of the rotation: the round trip is exact only elsewhere
    b = angles[:, 1]
    free = (np.abs(np.sin(b)) if seq[0].lower() == seq[2].lower() else np.abs(np.cos(b))) > 1e-6
    np.testing.assert_allclose(so3.euler_to_matrix(seq, angles[free]), S.as_matrix()[free],
                               atol=1e-14)
    np.testing.assert_allclose(so3.euler_to_matrix(seq, angles), S.as_matrix(), atol=1e-6)  # locked: <= theta2 ~ 1e-7
    dots = np.abs(np.sum(so3.euler_to_quat(seq, angles[free]) * q[free], axis=-1))
    np.testing.assert_allclose(dots, 1.0, atol=1e-14)
    rng = np.random.default_rng(3)
    locked = rng.uniform(-3, 3, size=(20, 3))
    ends = (0.0, np.pi) if seq[0].lower() == seq[2].lower() else (-np.pi / 2, np.pi / 2)
    locked[:, 1] = rng.choice(ends, size=20)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # SciPy warns about gimbal lock
        want = Rotation.from_euler(seq, locked).as_euler(seq)
    # at an exact lock, b comes from an entry +-1 (asin/acos there: sqrt(2 eps) = 2e-8 per ulp, but
    # the entry is exact here: cos 0 = 1, sin(pi/2) = 1), the first angle from O(1) entries: few eps
    np.testing.assert_allclose(so3.matrix_to_euler(seq, so3.euler_to_matrix(seq, locked)), want,
                               atol=1e-12)


def test_quat_integrate_matches_scipy(rotations):
    q, S = rotations
    w = np.random.default_rng(2).normal(size=(400, 3)) * 5
    dt = 0.2
    step = Rotation.from_rotvec(w * dt)
    # exp of angles up to |w dt| (<= 7 rad): eps relative in the angle, plus a product: both sides
    tol = 16 * EPS * (1 + np.linalg.norm(w * dt, axis=1).max())
    np.testing.assert_allclose(so3.quat_to_matrix(so3.quat_integrate(q, w, dt, "body")),
                               (S * step).as_matrix(), atol=tol)
    np.testing.assert_allclose(so3.quat_to_matrix(so3.quat_integrate(q, w, dt, "world")),
                               (step * S).as_matrix(), atol=tol)


vec6 = arrays(np.float64, (6,), elements=st.floats(-5, 5))


@settings(max_examples=100, deadline=None)
@given(vec6, vec6, arrays(np.float64, (3,), elements=st.floats(-3, 3)),
       arrays(np.float64, (3,), elements=st.floats(-3, 3)))
def test_spatial_structured_equals_dense(m1, m2, rotvec, p):
    R = so3.rotvec_to_matrix(rotvec)
    X, Xf = spatial.motion_matrix(R, p), spatial.force_matrix(R, p)
    # inputs <= 5: products <= |p| |R| |m| <= 5 sqrt(3) * 5 sqrt(6) = 106, 6-term sums: gamma_6 106
    # = 1.4e-13 per side; inverses: cond(X) <= (1 + |p|)^2 = 98 times eps times entries <= 9
    np.testing.assert_allclose(spatial.crm(m1) @ m2, spatial.cross_motion(m1, m2), atol=1e-12)
    np.testing.assert_allclose(spatial.crf(m1) @ m2, spatial.cross_force(m1, m2), atol=1e-12)
    np.testing.assert_allclose(X @ m1, spatial.act_motion(R, p, m1), atol=1e-12)
    np.testing.assert_allclose(Xf @ m1, spatial.act_force(R, p, m1), atol=1e-12)
    np.testing.assert_allclose(Xf, np.linalg.inv(X).T, atol=1e-11)
    # power is frame invariant: (X m)·(X* f) = m·f
    np.testing.assert_allclose(spatial.power(X @ m1, Xf @ m2), spatial.power(m1, m2), atol=1e-10)
    R2, p2 = spatial.transform_inverse(R, p)
    np.testing.assert_allclose(spatial.motion_matrix(R2, p2), np.linalg.inv(X), atol=1e-11)
    Rc, pc = spatial.transform_compose(R, p, R2, p2)
    np.testing.assert_allclose(Rc, np.eye(3), atol=1e-14)
    np.testing.assert_allclose(pc, np.zeros(3), atol=1e-13)


@settings(max_examples=100, deadline=None)
@given(vec6)
def test_screw_reassembles_twist(m):
    w = m[:3]
    if np.linalg.norm(w) < 1e-3:
        return
    direction, point, pitch, magnitude = spatial.twist_to_screw(m)
    # w = |w| s, v = |w| (r x s + h s): velocity of the origin of a screw motion (|w| >= 1e-3: r and
    # h to a few eps of |v|/|w| <= 1e4, times |w|: <= 1e-11 absolute)
    np.testing.assert_allclose(magnitude * direction, w, atol=1e-12)
    np.testing.assert_allclose(magnitude * (np.cross(point, direction) + pitch * direction), m[3:],
                               atol=1e-11)
    assert abs(np.dot(point, direction)) < 1e-11  # the point closest to the origin


def test_pure_translation_screw():
    direction, point, pitch, magnitude = spatial.twist_to_screw([0, 0, 0, 0, 3.0, 4.0])
    np.testing.assert_allclose(direction, [0, 0.6, 0.8])
    assert pitch == np.inf and magnitude == 5.0 and not np.any(point)


def test_seed_001_worked_example_both_solutions():
    """Shaft R1 at 5 rad/s about i, disk R2 at 4 rad/s about k1 in R1, P fixed on the disk at
    r = 0.06 m, θ = 30°: a_P = (-16 r cos θ, -41 r sin θ, 40 r cos θ) in R1 (Craig)."""
    r, th = 0.06, np.radians(30.0)
    answer = np.array([-16 * r * np.cos(th), -41 * r * np.sin(th), 40 * r * np.cos(th)])
    r_OP = np.array([r * np.cos(th), r * np.sin(th), 0.0])
    i1, k1 = np.array([5.0, 0, 0]), np.array([0, 0, 4.0])
    # first solution: P fixed in R2, which turns at ω = 5 i + 4 k1 with α = 5 i x 4 k1 in R
    w = kinematics.compose_angular_velocity(i1, k1)
    alpha = kinematics.compose_angular_acceleration(i1, np.zeros(3), k1, np.zeros(3))
    np.testing.assert_allclose(alpha, [0.0, -20.0, 0.0])
    a = kinematics.point_acceleration_terms(np.zeros(3), w, alpha, r_OP, np.zeros(3), np.zeros(3))
    np.testing.assert_allclose(a["total"], answer, atol=1e-15)  # terms <= 2.5 x 0.06: a few eps of them
    # alternate solution: P moves in R1 (on the disk), R1 turns at 5 i: Coriolis term appears
    v_rel = np.cross(k1, r_OP)
    a_rel = np.cross(k1, v_rel)
    b = kinematics.point_acceleration_terms(np.zeros(3), i1, np.zeros(3), r_OP, v_rel, a_rel)
    np.testing.assert_allclose(b["total"], answer, atol=1e-15)
    assert np.linalg.norm(b["coriolis"]) > 0.1


def _chain_states(t):
    """Two frames: A turns about a tilted axis at a varying rate and its origin moves in W; F turns
    in A at another rate and sits off A's origin. Returns (K_WA, K_AF) as functions of t."""
    axis_a = np.array([1.0, 2.0, 2.0]) / 3.0
    angle_a, rate_a, acc_a = 0.3 * t**2, 0.6 * t, 0.6
    K_WA = kinematics.frame_state(R=so3.rotvec_to_matrix(angle_a * axis_a), w=rate_a * axis_a,
                                  alpha=acc_a * axis_a, p=[np.sin(t), t**2, 1.0],
                                  v=[np.cos(t), 2 * t, 0.0], a=[-np.sin(t), 2.0, 0.0])
    axis_f = np.array([0.0, 0.6, 0.8])
    K_AF = kinematics.frame_state(R=so3.rotvec_to_matrix(1.7 * t * axis_f), w=1.7 * axis_f,
                                  p=[0.5, -0.2, t**3], v=[0, 0, 3 * t**2], a=[0, 0, 6 * t])
    return K_WA, K_AF


def test_frame_compose_matches_finite_differences():
    t, h = 0.8, 1e-4
    K = [kinematics.compose_kinematics(*_chain_states(s)) for s in (t - h, t, t + h)]
    R_dot = (K[2]["R"] - K[0]["R"]) / (2 * h)
    # central differences, h = 1e-4: truncation h^2/6 |d3f| (<= 1e-8 |d3f|, <= 30 here) plus
    # round-off eps |f|/h (2e-12), eps |f|/h^2 x 4 for the second difference (1e-7 |f|, |f| <= 3)
    np.testing.assert_allclose(so3.vee(R_dot @ K[1]["R"].T), K[1]["w"], atol=1e-7)
    np.testing.assert_allclose((K[2]["w"] - K[0]["w"]) / (2 * h), K[1]["alpha"], atol=1e-7)
    np.testing.assert_allclose((K[2]["p"] - K[0]["p"]) / (2 * h), K[1]["v"], atol=1e-7)
    np.testing.assert_allclose((K[2]["p"] - 2 * K[1]["p"] + K[0]["p"]) / h**2, K[1]["a"],
                               atol=1e-5)


def test_frame_relative_inverts_compose():
    K_WA, K_AF = _chain_states(0.8)
    K_WF = kinematics.compose_kinematics(K_WA, K_AF)
    back = kinematics.relative_kinematics(K_WA, K_WF)
    for key in K_AF:  # compose then undo: a few dozen roundings of terms <= |w|^2 |p| ~ 10
        np.testing.assert_allclose(back[key], K_AF[key], atol=1e-13)


def test_chain_angular_acceleration_has_cross_terms():
    w_rel = np.array([[1.0, 0, 0], [0, 2.0, 0], [0, 0, 3.0]])
    alpha = kinematics.chain_angular_acceleration(w_rel, np.zeros((3, 3)))
    # ω01 x ω12 + (ω01 + ω12) x ω23
    want = np.cross(w_rel[0], w_rel[1]) + np.cross(w_rel[0] + w_rel[1], w_rel[2])
    np.testing.assert_allclose(alpha, want)
    np.testing.assert_allclose(kinematics.chain_angular_velocity(w_rel), [1.0, 2.0, 3.0])


# ------------------------------------------------------------------ dynamics and integrators
I_FULL = np.array([[2.0, 0.3, -0.2], [0.3, 1.5, 0.1], [-0.2, 0.1, 1.2]])
LOADS = [dynamics.Load(np.array([0.3, -0.2, 0.5]), np.array([0.1, 0.2, -0.3]), "body"),
         dynamics.Load(np.array([0.0, 1.0, 0.0]), np.array([0.2, 0.0, 0.1]), "world")]
GRAVITY = dynamics.STANDARD_GRAVITY


def _matrix_ode(t, x, mass=1.7):
    """The same rigid body written with a rotation matrix instead of a quaternion (Ṙ = R [ω]x),
    for SciPy: x = (p, R (9), v, ω, W)."""
    R, v, w = x[3:12].reshape(3, 3), x[12:15], x[15:18]
    q = Rotation.from_matrix(R).as_quat()
    f_W, n_B = dynamics.body_wrench(q, dynamics.loads_at(LOADS, t), mass, GRAVITY)
    dw = np.linalg.solve(I_FULL, n_B - np.cross(w, I_FULL @ w))
    return np.concatenate([v, (R @ so3.hat(w)).ravel(), f_W / mass, dw, [f_W @ v + n_B @ w]])


@pytest.fixture(scope="module")
def dop853_solution():
    x0 = np.concatenate([[0.1, 0.2, 0.3], so3.rotvec_to_matrix([0.4, -0.3, 0.2]).ravel(),
                         [1.0, 0.0, -1.0], [2.0, -1.0, 3.0], [0.0]])
    sol = solve_ivp(_matrix_ode, (0.0, 1.0), x0, method="DOP853", rtol=1e-13, atol=1e-13)
    return x0, sol.y[:, -1]


def _run_reference(method, steps, x0):
    model = integrators.RigidBodyModel(1.7, I_FULL, GRAVITY)
    y0 = model.initial(x0[:3], so3.matrix_to_quat(x0[3:12].reshape(3, 3)), x0[12:15], x0[15:18])
    return integrators.simulate(model, y0, 1.0 / steps, steps, method, LOADS)


def _error(y, x):
    R = so3.quat_to_matrix(y[3:7])
    attitude = np.linalg.norm(so3.matrix_to_rotvec(R.T @ x[3:12].reshape(3, 3)))
    return max(attitude, np.max(np.abs(y[10:13] - x[15:18])), np.max(np.abs(y[:3] - x[:3])),
               abs(y[13] - x[18]))


@pytest.mark.parametrize("method, order", [("explicit_euler", 1), ("semi_implicit_euler", 1),
                                           ("semi_implicit_euler_implicit_gyroscopic", 1),
                                           ("rk4", 4), ("rkmk4", 4)])
def test_integrators_converge_to_dop853_at_their_order(dop853_solution, method, order):
    """Observed order (log2 of the error ratio for h and h/2) of each reference method on a body
    with a full inertia, body- and world-frame loads and gravity, against SciPy's DOP853 on the
    rotation-matrix form of the same equations (attitude, ω, position and work)."""
    x0, x1 = dop853_solution
    n = 50 if order == 1 else 20
    e1, e2 = _error(_run_reference(method, n, x0), x1), _error(_run_reference(method, 2 * n, x0), x1)
    # the next term of the expansion is O(h |w|) <= 0.2 relative at these steps (|w| <= 4, h >= 1/100);
    # DOP853 at 1e-13 errs by ~1e-13, far below e2
    assert abs(np.log2(e1 / e2) - order) < 0.2, (e1, e2)
    if order == 4:  # further into the asymptotic range: C h^4 from e2, within the same O(h) slack (x2)
        assert _error(_run_reference(method, 200, x0), x1) < 2 * e2 * (2 * n / 200) ** 4 + 1e-12


def test_rkmk4_attitude_is_fourth_order_without_torque():
    """Torque-free spin: RKMK4 keeps fourth order in the attitude itself (the dexp⁻¹ correction)."""
    x0 = np.concatenate([np.zeros(3), np.eye(3).ravel(), np.zeros(3), [3.0, -1.0, 2.0], [0.0]])
    model = integrators.RigidBodyModel(1.0, I_FULL)

    def ode(t, x):  # Ṙ = R [ω]x, I ω̇ = -ω x I ω
        R, w = x[3:12].reshape(3, 3), x[15:18]
        dw = np.linalg.solve(I_FULL, -np.cross(w, I_FULL @ w))
        return np.concatenate([x[12:15], (R @ so3.hat(w)).ravel(), np.zeros(3), dw, [0.0]])

    x1 = solve_ivp(ode, (0.0, 1.0), x0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
    errors = []
    for steps in (10, 20):
        y0 = model.initial(np.zeros(3), [0, 0, 0, 1.0], np.zeros(3), x0[15:18])
        y = integrators.simulate(model, y0, 1.0 / steps, steps, "rkmk4")
        R_err = so3.quat_to_matrix(y[3:7]).T @ x1[3:12].reshape(3, 3)
        errors.append(np.linalg.norm(so3.matrix_to_rotvec(R_err)))
    # h |w| = 0.37 at 10 steps: the next term moves log2 by O(h |w|) ~ 0.2
    assert abs(np.log2(errors[0] / errors[1]) - 4.0) < 0.3, errors


def test_euler_principal_form_equals_full_form():
    rng = np.random.default_rng(3)
    for _ in range(20):
        d, w, n = rng.uniform(0.5, 2.0, 3), rng.normal(size=3), rng.normal(size=3)
        # a few roundings of terms |n| + |w| |d w| over min d, and LAPACK's solve (kappa = max d/min d)
        tol = 16 * EPS * d.max() / d.min() * (np.abs(n).max() + np.abs(w).sum() * np.abs(d * w).sum()) / d.min()
        np.testing.assert_allclose(dynamics.euler_angular_acceleration_principal(d, w, n),
                                   dynamics.euler_angular_acceleration(np.diag(d), w, n), atol=tol)


def test_inverse_dynamics_undoes_forward_dynamics():
    rng = np.random.default_rng(4)
    q = so3.quat_normalize(rng.normal(size=4))
    w = rng.normal(size=3)
    loads = dynamics.Loads(rng.normal(size=3), rng.normal(size=3), rng.normal(size=3), rng.normal(size=3))
    a, dw = dynamics.rigid_body_accelerations(1.7, I_FULL, q, w, loads, GRAVITY)
    f_W, n_B = dynamics.rigid_body_wrench(1.7, I_FULL, w, a, dw, GRAVITY)
    want_f, want_n = dynamics.body_wrench(q, loads)
    # forward then inverse: a solve with I (kappa 2.3) and terms <= ~10 (normal inputs): 16 eps 2.3 10
    np.testing.assert_allclose(f_W, want_f, atol=1e-13)
    np.testing.assert_allclose(n_B, want_n, atol=1e-13)
    a_p = dynamics.particle_acceleration(1.7, f_W, GRAVITY)
    np.testing.assert_allclose(dynamics.particle_force(1.7, a_p, GRAVITY), f_W, atol=1e-13)
    a2, alpha = dynamics.planar_accelerations(1.7, 0.8, 0.3, loads, GRAVITY * [1, 1, 0])
    f2, n2 = dynamics.planar_loads(1.7, 0.8, a2, alpha, GRAVITY * [1, 1, 0])
    np.testing.assert_allclose(f2, dynamics.planar_force_W(1.7, 0.3, loads), atol=1e-13)
    assert abs(n2 - loads.n_W[2] - loads.n_B[2]) < 1e-13


def test_impulse_changes_momentum_by_the_impulse():
    """Impulse–momentum (Craig): Δ(m v) = J, and about the centre of mass and about any fixed
    point O the angular momentum changes by the moment of the impulse (r x J), with J and its point
    of application given in the world or in the body frame."""
    rng = np.random.default_rng(5)
    q = so3.quat_normalize(rng.normal(size=4))
    p, v, w, J_W, r_W, O = (rng.normal(size=3) for _ in range(6))
    to_B = so3.quat_inverse(q)
    for frame, J, r in (("world", J_W, r_W),
                        ("body", so3.quat_rotate(to_B, J_W), so3.quat_rotate(to_B, r_W))):
        v1, w1 = dynamics.apply_impulse(1.7, I_FULL, q, v, w, J, r, frame)
        # m (v + J/m - v) and the moments of it: a few roundings of numbers <= 10 (normal inputs)
        np.testing.assert_allclose(dynamics.linear_momentum(1.7, v1 - v), J_W, atol=1e-13)
        dH_C = (dynamics.angular_momentum_about_com(I_FULL, q, w1)
                - dynamics.angular_momentum_about_com(I_FULL, q, w))
        np.testing.assert_allclose(dH_C, np.cross(r_W, J_W), atol=1e-12)
        dH_O = (dynamics.angular_momentum_about_point(1.7, I_FULL, p, q, v1, w1, O)
                - dynamics.angular_momentum_about_point(1.7, I_FULL, p, q, v, w, O))
        np.testing.assert_allclose(dH_O, np.cross(p + r_W - O, J_W), atol=1e-12)


def test_work_matches_kinetic_energy_change():
    """Work–energy (Craig, T2 - T1 = U12): with RK4 at a small step the work integrated with the
    motion (loads and gravity) equals the change of kinetic energy."""
    model = integrators.RigidBodyModel(1.7, I_FULL, GRAVITY)
    y0 = model.initial(np.zeros(3), [0, 0, 0, 1.0], [1.0, 0, 0], [1.0, 2.0, -1.0])
    y = integrators.simulate(model, y0, 1e-3, 1000, "rk4", LOADS)
    T0, T1 = sum(dynamics.kinetic_energy(1.7, I_FULL, y0[7:10], y0[10:13])), \
        sum(dynamics.kinetic_energy(1.7, I_FULL, y[7:10], y[10:13]))
    # T - W is an invariant of the ODE; RK4 changes it by its local error, ~(h |w|)^5/120 T per step
    # (h |w| = 2.5e-3: 1e-15 T), and round-off 2 eps T per step: 1000 steps, 2.2e-12 T
    assert abs((T1 - T0) - y[13]) < 1e-10 * max(1.0, abs(T1))


# ------------------------------------------------------------------ the exact free flow
LONG = np.longdouble
EXTENDED = np.finfo(LONG).eps < 1e-18  # x86-64 Linux: 80-bit, eps 1.1e-19


def _inverse3(A):
    """Inverse of a 3x3 matrix by its adjugate (numpy's inv has no long double)."""
    C = np.array([[np.cross(A[(j + 1) % 3], A[(j + 2) % 3])[i] for j in range(3)] for i in range(3)])
    return C / (A[0] @ C[:, 0])


def taylor_free_flow(I, R0, w0, h, chunk=0.1, order=24):
    """The Euler–Poinsot flow over h by Taylor series in long double: ṁ = m x J m (J = I⁻¹),
    Ṙ = R [J m]x, coefficients by the Cauchy products of the quadratic right-hand side, on
    chunks with |ω| tau <= 0.1 (remainder <= 0.1^25), so the error is round-off ~1e-18.
    Returns (R, w) in long double."""
    Iq = np.array(I, LONG)
    J = _inverse3(Iq)
    m, R = Iq @ np.array(w0, LONG), np.array(R0, LONG)
    n = max(1, int(np.ceil(abs(h) * np.linalg.norm(w0) / chunk)))
    tau = LONG(h) / n
    for _ in range(n):
        ms, ws, Rs = [m], [J @ m], [R]
        for k in range(order):
            ms.append(sum(np.cross(ms[j], ws[k - j]) for j in range(k + 1)) / (k + 1))
            Rs.append(sum(Rs[j] @ so3.hat(ws[k - j]).astype(LONG) for j in range(k + 1)) / (k + 1))
            ws.append(J @ ms[-1])
        m, R = ms[-1], Rs[-1]
        for k in range(order - 1, -1, -1):
            m, R = ms[k] + tau * m, Rs[k] + tau * R
    return R, J @ m


def _flow_errors(I, R0, w0, h):
    """(attitude error [rad], |Δω|/|ω|) of free_flow.free_rotation against taylor_free_flow."""
    R_want, w_want = taylor_free_flow(I, R0, w0, h)
    R, w = free_flow.free_rotation(I, R0, w0, h)
    D = R_want.T @ np.array(R, LONG)
    angle = np.linalg.norm([D[2, 1] - D[1, 2], D[0, 2] - D[2, 0], D[1, 0] - D[0, 1]]) / 2
    return float(angle), float(np.linalg.norm(np.array(w, LONG) - w_want) / np.linalg.norm(w_want))


def _free_flow_cases():
    D = np.diag([1.0, 2.0, 3.0])
    tilt = so3.rotvec_to_matrix([0.4, 0.1, -0.3])
    w_sep = 0.3 * np.sqrt(3) / 3  # Δ2 = 0 for diag(1, 2, 3): m3² = 3 m1²
    cases = [(np.array([[0.9, 0.05, -0.1], [0.05, 1.4, 0.08], [-0.1, 0.08, 1.9]]), [1.2, -0.7, 2.0], 0.01),
             (tilt @ np.diag([3.0, 1.0, 2.0]) @ tilt.T, [0.3, -0.5, 1.0], 0.7),
             (D, [0.3, 2.0, -0.4], -0.5), (D, [1.0, 0.5, -0.3], 3.0)]  # case B; several sub-steps
    for closeness in (1e-3, 1e-9, 1e-14, 0.0):  # both sides of the separatrix, and on it
        cases += [(D, [0.3, 2.0, w_sep * (1 + closeness)], 0.4), (D, [0.3, 2.0, w_sep * (1 - closeness)], 0.4)]
    # ~40 sub-steps near the separatrix, past the saddle: the walk's phase shifts amplified (A ~ 3e4)
    cases.append((D, [0.3, 2.0, w_sep * (1 + 1e-9)], 10.0))
    for small in (1e-4, 1e-10):  # near steady spins about each axis
        cases += [(D, [small, 0.3 * small, 2.0], 0.4), (D, [2.0, small, -0.4 * small], 0.4),
                  (D, [small, 2.0, small], 0.4)]
    cases += [(np.diag([1.0, 1.0 + 1e-9, 2.0]), [0.5, -0.7, 0.4], 0.4),  # nearly symmetric: elliptic
              (np.diag([1.0, 1.0, 2.0]), [0.5, -0.7, 0.4], 0.4), (np.diag([1.0, 2.0, 2.0]), [0.5, -0.7, 0.4], 0.4),
              (0.7 * np.eye(3), [0.5, -0.7, 0.4], 0.4), (D, [0.0, 2.0, 0.0], 0.4), (D, [0.0, 0.0, 0.0], 0.4)]
    rng = np.random.default_rng(11)
    for _ in range(4):
        A = rng.normal(size=(3, 3))
        w = rng.normal(size=3)
        cases.append((A @ A.T + 0.5 * np.eye(3), w, rng.uniform(-1.0, 1.0) / np.linalg.norm(w)))
    return cases


@pytest.mark.skipif(not EXTENDED, reason="needs an extended-precision long double for the Taylor reference")
@pytest.mark.parametrize("index", range(len(_free_flow_cases())))
def test_free_flow_meets_its_stated_bound(index):
    """free_flow.free_rotation against a long-double Taylor series of Euler's equations (error
    ~1e-18, far below the bound) in every branch: full inertia, cases A and B, the separatrix
    approached from both sides to 1e-14 and on it, near steady spins about each axis, nearly and
    exactly symmetric bodies, a sphere, rest, negative and multi-sub-step steps."""
    I, w0, h = _free_flow_cases()[index]
    w0 = np.asarray(w0, float)
    R0 = so3.rotvec_to_matrix([0.3, -0.5, 0.8])
    if not np.any(w0):
        R, w = free_flow.free_rotation(I, R0, w0, h)
        assert np.array_equal(R, R0) and not np.any(w)
        return
    angle, dw = _flow_errors(I, R0, w0, h)
    bound = free_flow.step_error_bound(I, h, w0)
    assert angle <= bound and dw <= bound, (angle / EPS, dw / EPS, bound / EPS)


def test_jacobi_functions_of_small_argument():
    """The AGM's sn, cn, dn against SciPy's ellipj where SciPy is accurate (k away from 1: its own
    error is a few eps, DLMF 22.20(ii) with the same AGM), the identities, and k = 0, 1 closed forms."""
    from scipy.special import ellipj
    v = np.linspace(-0.5, 0.5, 41)
    for k in (0.0, 1e-8, 0.3, 0.51, 0.9, 0.999):
        sn, cn, dn = free_flow.jacobi_small(v, k, 1.0 - k)
        want = ellipj(v, k)[:3]
        # values <= 1. Ours: sin, cos, arcsin of NumPy's SIMD kernels (<= 4 ulp, AVX-512 or not) at
        # the end of the AGM's chain (whose earlier errors halve at each level), dn one sqrt more:
        # <= 10 eps; SciPy's (cephes, the same AGM on libm): <= 4 eps; 16 eps covers both
        for got, expected in zip((sn, cn, dn), want):
            np.testing.assert_allclose(got, expected, rtol=0, atol=16 * EPS)
        # sn² + cn²: each square doubles its function's <= 4 ulp, plus 3 roundings: <= 11 eps
        np.testing.assert_allclose(sn**2 + cn**2, 1.0, rtol=0, atol=12 * EPS)
        # dn = √(1 − k sn²) by construction: the sqrt and 4 roundings, <= 6 eps
        np.testing.assert_allclose(dn**2 + k * sn**2, 1.0, rtol=0, atol=6 * EPS)
    sn, cn, dn = free_flow.jacobi_small(v, 1.0, 0.0)  # k = 1: tanh, sech, sech (DLMF 22.5.3)
    np.testing.assert_allclose(sn, np.tanh(v), rtol=0, atol=2 * EPS)
    np.testing.assert_allclose(cn, 1 / np.cosh(v), rtol=0, atol=2 * EPS)
    with pytest.raises(ValueError, match="^v"):
        free_flow.jacobi_small(0.6, 0.5, 0.5)


def test_addition_theorem_walks_a_whole_period():
    """DETEST B5 (Hull, Enright, Fellen, Sedgwick 1972): (sn, cn, dn)(t | 0.51) has period
    4K = 7.450563; 400 addition-theorem steps of 4K/400 return to (0, 1, 1) within 400 steps of
    a few eps each (linear accumulation: the walk is neutrally stable in the phase only)."""
    from scipy.special import ellipk
    k = 0.51
    quarter = ellipk(k)
    assert abs(4 * quarter - 7.450563) < 5e-7  # the published figure has 7 digits
    step = free_flow.jacobi_small(4 * quarter / 400, k, 1 - k)
    triple = (0.0, 1.0, 1.0)
    for _ in range(400):
        triple = free_flow.jacobi_add(*triple, *step, k)
    np.testing.assert_allclose(triple, (0.0, 1.0, 1.0), rtol=0, atol=400 * 8 * EPS)


def test_free_flow_composes_and_asserts():
    """Two half steps equal one step (each within the stated bound), and the assertions fire:
    a momentum off its orbit's identities, a quadrature that cannot converge."""
    I = np.array([[0.9, 0.05, -0.1], [0.05, 1.4, 0.08], [-0.1, 0.08, 1.9]])
    R0, w0, h = so3.rotvec_to_matrix([0.3, -0.5, 0.8]), np.array([1.2, -0.7, 2.0]), 0.6
    R1, w1 = free_flow.free_rotation(I, R0, w0, h)
    R2, w2 = free_flow.free_rotation(I, *free_flow.free_rotation(I, R0, w0, h / 2), h / 2)
    bound = 3 * free_flow.step_error_bound(I, h, w0)  # one step and two half steps
    assert np.linalg.norm(so3.matrix_to_rotvec(R1.T @ R2)) <= bound
    assert np.linalg.norm(w1 - w2) <= bound * np.linalg.norm(w0)
    orbit = free_flow._EllipticOrbit(np.array([1.0, 2.0, 3.0]), np.array([0.6, 0.0, 0.8]))
    with pytest.raises(FloatingPointError, match="^m"):
        orbit.triple(np.array([0.6, 0.1, 0.8]))
    with pytest.raises(FloatingPointError, match="^quadrature"):
        free_flow.integrate_positive(lambda t: 1.0 / np.abs(t - 0.3), 0.0, 1.0)


@pytest.mark.parametrize("w0", [[0.3, 2.0, 0.4], [1.0, 0.5, -0.3], [0.3, 2.0, 0.1 * np.sqrt(3) * (1 + 1e-3)]])
def test_phase_amplification_is_the_orbit_extreme_ratio(w0):
    """free_flow's A = max |ṁ| / min |ṁ| on an orbit (closed form at the orbit's ends) against |m × ω|
    sampled along one period walked by the addition theorem (cases A, B and near the separatrix)."""
    from scipy.special import ellipk
    I = np.array([1.0, 2.0, 3.0])
    m = I * np.asarray(w0)
    n = m / np.linalg.norm(m)
    orbit = free_flow._EllipticOrbit(I, n)
    period = 4 * ellipk(orbit.k) / orbit.rate  # in the scaled time s = G t
    steps = 4000
    step = free_flow.jacobi_small(orbit.rate * period / steps, orbit.k, orbit.kc)
    triple, rates = orbit.triple(n), []
    for _ in range(steps):
        triple = orbit.project(*free_flow.jacobi_add(*triple, *step, orbit.k))
        n_t = orbit.momentum(*triple)
        rates.append(np.linalg.norm(np.cross(n_t, n_t / I)))
    sampled = max(rates) / min(rates)
    # the samples miss each extreme by at most a step of 4K/4000 in phase: |ṁ| is smooth there (its
    # derivative vanishes at the extremes), so the ratio is short by O((2π/4000)²) relative
    A = orbit.phase_amplification()
    assert sampled <= A * (1 + 1e-12) and sampled >= A * (1 - 1e-4), (sampled, A)
