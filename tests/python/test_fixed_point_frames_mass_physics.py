"""The physics of bodies about a fixed point, moving frames and variable mass: the heavy top against its closed
form, the exact top against DOP853, the pendulum's period against K(m) up to the separatrix, a run in a rotating
frame against the inertial run turned into it, zero Coriolis power, Foucault's pendulum, Tsiolkovsky, the
observed order of every method on every new model, and the bad-input cases. The closed forms are the independent
numpy/scipy reference (rigiddyn_ref.exact_dynamics, which never calls rigiddyn)."""

import math
import warnings

import numpy as np
import pytest
from scipy import integrate

import rigiddyn as rd

from rigiddyn_ref import exact_dynamics as exact
from rigiddyn_ref import moving_frame, pivoted, so3

EPS = np.finfo(float).eps
ORDERS = {m["name"]: m["order"] for m in rd.methods()}
METHODS = sorted(name for name, order in ORDERS.items() if order > 0)   # 'exact' (order 0) has no truncation error
SECOND_ORDER_AND_ABOVE = sorted(name for name, order in ORDERS.items() if order >= 2)


def attitude_angle(q1, q2):
    """Angles [rad] between attitudes (..., 4) (x, y, z, w): 2 atan2(|vec(q1⁻¹ q2)|, |scalar|)."""
    d = so3.quat_multiply(so3.quat_inverse(np.asarray(q1)), np.asarray(q2))
    return 2 * np.arctan2(np.linalg.norm(d[..., :3], axis=-1), np.abs(d[..., 3]))


# ---------------------------------------------------------------- the heavy top
TOP = dict(mass=2.0, inertia=np.diag([0.3, 0.3, 0.1]), c=np.array([0.0, 0.0, 0.2]), g=np.array([0.0, 0.0, -9.81]),
           q=so3.rotvec_to_quat([0.5, 0.2, 0.0]), w=np.array([0.4, -0.3, 15.0]))


def top_reference():
    return exact.LagrangeTop(TOP["mass"], pivoted.inertia_about_pivot(TOP["mass"], TOP["inertia"], TOP["c"]), TOP["c"],
                             TOP["g"], TOP["q"], TOP["w"])


def top_body():
    return rd.PivotedBody(rd.RigidBody(TOP["mass"], TOP["inertia"]), TOP["c"])


def top_errors(steps_per_period, periods=10, method="rk4"):
    """Largest (attitude [rad], |Δω|/|ω|) of simulate over `periods` nutation periods against the closed form, at the
    records (every period/10)."""
    top = top_reference()
    dt = top.nutation_period / steps_per_period
    run = rd.simulate(top_body(), rd.PivotedBodyState(q_WB=TOP["q"], w_B=TOP["w"]), dt, periods * steps_per_period,
                      method=method, gravity=TOP["g"], record_every=steps_per_period // 10)
    attitude, rate = 0.0, 0.0
    for t, q, w in zip(run.t, run.q_WB[:, 0], run.w_B[:, 0]):
        q_ref, w_ref = top.at(t)
        attitude = max(attitude, attitude_angle(q, q_ref))
        rate = max(rate, np.linalg.norm(w - w_ref) / np.linalg.norm(w_ref))
    return attitude, rate


def test_heavy_top_rk4_follows_the_closed_form_over_ten_nutation_periods():
    """RK4 at T/6000 over 10 nutation periods within 1e-9 relative (the required accuracy) of the Lagrange top's
    closed form. Why this step: RK4's global error is C h⁴ once asymptotic, so the run at 2h (T/3000) has 16×
    the error; its measured error bounds this one's by e(h) ≈ e(2h)/16 and the asymptotic regime is checked
    (ratio 16 ± 25 %).
    The closed form's own error (test_exact_dynamics_reference: ≲ 1e-12 per unit phase) and the round-off of 60000
    steps (a random walk √N × 16 eps κ(I_O) ≈ 3e-12; ≤ 60000 × 16 eps × 3.8 ≈ 8e-10 even if every rounding added up)
    are below 1e-9."""
    fine, coarse = top_errors(6000), top_errors(3000)
    for e_fine, e_coarse in zip(fine, coarse):
        assert e_fine <= 1e-9, (fine, coarse)
        assert 16 / 1.25 <= e_coarse / e_fine <= 16 * 1.25, (fine, coarse)


def test_exact_top_agrees_with_dop853_over_one_nutation_period():
    """rigiddyn.LagrangeTopSolution against DOP853 (rtol 1e-13) of Euler's equations about O (the reference's rate) over
    one nutation period: within 1e-12 (the required accuracy), with DOP853's own error bounded first: by tolerance
    proportionality its error at rtol 1e-13 is ≲ 1/10^(8/9) of its difference from the run at 1e-12, asserted ≤ 3e-13,
    so the comparison can fail only by the closed form."""
    top = top_reference()
    exact_top = rd.LagrangeTopSolution(top_body(), TOP["g"], rd.PivotedBodyState(q_WB=TOP["q"], w_B=TOP["w"]))
    T = exact_top.nutation_period
    rate = lambda t, y: pivoted.rate(TOP["mass"], TOP["inertia"], TOP["c"], TOP["g"], y)  # noqa: E731
    y0 = np.concatenate([TOP["q"], TOP["w"]])
    runs = {rtol: integrate.solve_ivp(rate, (0, T), y0, method="DOP853", rtol=rtol, atol=rtol * 1e-2, dense_output=True)
            for rtol in (1e-12, 1e-13)}
    times = np.linspace(0, T, 9)
    scale = np.linalg.norm(TOP["w"])
    for t in times:
        fine, coarse = runs[1e-13].sol(t), runs[1e-12].sol(t)
        dop_error = max(attitude_angle(fine[:4] / np.linalg.norm(fine[:4]), coarse[:4] / np.linalg.norm(coarse[:4])),
                        np.linalg.norm(fine[4:] - coarse[4:]) / scale) / 10 ** (8 / 9)
        assert dop_error <= 3e-13, (t, dop_error)
        q, w = exact_top.at(t)
        assert attitude_angle(q, fine[:4] / np.linalg.norm(fine[:4])) <= 1e-12, t
        assert np.linalg.norm(w - fine[4:]) / scale <= 1e-12, t


def test_exact_top_precession_bounds_and_period_match_the_reference():
    """θ_min, θ_max, the nutation period and the mean precession rate of the core's closed form against the reference's
    (roots of the same cubic, K and Π of the same parameter: agreement to 1e-12 relative is a few hundred ulps of
    the parameter's conditioning)."""
    top = top_reference()
    core = rd.LagrangeTopSolution(top_body(), TOP["g"], rd.PivotedBodyState(q_WB=TOP["q"], w_B=TOP["w"]))
    assert core.theta_min == pytest.approx(top.theta_min, abs=1e-12)
    assert core.theta_max == pytest.approx(top.theta_max, abs=1e-12)
    assert core.nutation_period == pytest.approx(top.nutation_period, rel=1e-12)
    assert core.mean_precession_rate == pytest.approx(top.mean_precession_rate, rel=1e-12)


def test_exact_applies_to_a_pivoted_body_without_gravity():
    """Without gravity the pivoted body turns freely about O with I_O (the torque-free machinery applies):
    'exact' in 200 steps of 0.01 s against RK4 at h = 1e-3 s over 2 s. RK4's error e(h) is bounded by its
    Richardson estimate |y(2h) − y(h)|/15 (C h⁴ asymptotic), doubled for the next term; 'exact' steps the exact free
    flow about O, each step to its own round-off 16 eps κ (1 + |ω| t) (κ of I_O ≈ 3; carried to 2 s by the flow's
    Jacobian, which grows at most linearly in time away from the separatrix: a step's round-off counted with the
    whole run's phase), 200 of them; the pivot's reaction is then m a_C = m R (ω × (ω × c) + α × c) at each record
    (same formula both sides: 16 roundings on m |ω|² |c|... with α from Euler about O)."""
    body = rd.PivotedBody(rd.RigidBody(2.0, [0.3, 0.4, 0.5]), [0.1, -0.2, 0.3])
    state = rd.PivotedBodyState(q_WB=so3.rotvec_to_quat([0.2, 0.1, -0.3]), w_B=[1.0, -2.0, 1.5])
    exact_steps = 200
    exact_run = rd.simulate(body, state, 2.0 / exact_steps, exact_steps, method="exact", record_every=exact_steps)
    fine = rd.simulate(body, state, 1e-3, 2000, method="rk4", record_every=2000)
    coarse = rd.simulate(body, state, 2e-3, 1000, method="rk4", record_every=1000)
    richardson = max(attitude_angle(fine.q_WB[-1, 0], coarse.q_WB[-1, 0]),
                     np.abs(fine.w_B[-1, 0] - coarse.w_B[-1, 0]).max()) / 15
    w = np.linalg.norm(state.w_B)
    bound = 2 * richardson + exact_steps * 16 * EPS * 3 * (1 + w * 2.0)
    assert attitude_angle(exact_run.q_WB[-1, 0], fine.q_WB[-1, 0]) <= bound
    np.testing.assert_allclose(exact_run.w_B[-1, 0], fine.w_B[-1, 0], rtol=0, atol=bound * w)
    q, w_B = exact_run.q_WB[-1, 0], exact_run.w_B[-1, 0]
    c = np.asarray(body.p_OC_B)
    alpha = pivoted.angular_acceleration(2.0, body.inertia_com, c, q, w_B, np.zeros(3), np.zeros(3))
    want = pivoted.pivot_reaction_W(2.0, c, q, w_B, alpha, np.zeros(3))
    np.testing.assert_allclose(exact_run.pivot_reaction_W[-1, 0], want, rtol=0,
                               atol=2 * 16 * EPS * 3 * 2.0 * (np.linalg.norm(alpha) + w_B @ w_B) * np.linalg.norm(c))


# ---------------------------------------------------------------- the pendulum's period
AMPLITUDES = [1e-3, 0.1, 1.0, 2.0, 3.0, 3.14, np.pi - 1e-3, np.pi - 1e-6]


@pytest.mark.parametrize("theta0", AMPLITUDES)
def test_pendulum_period_matches_k_of_m_up_to_the_separatrix(theta0):
    """CompoundPendulumSolution.period released at rest at θ0 (from the stable equilibrium) against 4 K(k²)/ω0, k =
    sin(θ0/2), K from ellipkm1 of the complement cos²(θ0/2) formed without cancellation (the reference): K(m) has
    relative condition |m dK/dm|/K ≤ 1/(2 (1 − m) K) in m, but both sides form 1 − m from θ0 to a few eps relative, so
    they agree to ~64 eps relative at every θ0 (64: the complement, the AGM/Carlson evaluation, ω0), plus the
    problem's own condition in θ0 times 2 eps: a side that takes π as fl(π) (off by 1.2e-16) or rounds θ0 once
    moves T by cond · eps relative, cond = θ0 |dT/dθ0|/T = θ0 (dK/dm)(dm/dθ0)/K with dK/dm = (E − (1 − m) K)/
    (2 m (1 − m)), dm/dθ0 = sin(θ0/2) cos(θ0/2) (≈ 2e5 at π − 1e-6: 1e-10 relative there)."""
    mass, inertia_zz, d, g = 2.0, 0.05, 0.4, 9.81
    body = rd.PivotedPlanarBody(mass, inertia_zz, [0.0, -d])   # C below O at θ = 0: stable under g = (0, −9.81)
    solution = rd.CompoundPendulumSolution(body, [0.0, -g], rd.PivotedPlanarBodyState(theta=theta0, omega=0.0))
    omega0 = exact.pendulum_omega0(mass, inertia_zz + mass * d * d, d, g)
    m = np.sin(theta0 / 2) ** 2
    complement = np.sin(0.5 * ((np.pi - theta0) + exact.PI_LOW)) ** 2
    K, E = exact.special.ellipkm1(complement), exact.special.ellipe(m)
    cond = theta0 * (E - complement * K) / (2 * m * complement) * np.sin(theta0 / 2) * np.cos(theta0 / 2) / K
    want = exact.pendulum_period_from_rest(omega0, theta0)
    assert solution.period == pytest.approx(want, rel=64 * EPS + 2 * EPS * cond)
    assert solution.case == "libration"


def test_simulated_pendulum_returns_after_one_period():
    """RK4 at T/2000 from rest at θ0 = 2.5 rad over one period K-predicted: back at θ0 at rest. RK4's error per
    period ~ (ω0 h)⁴ ω0 T/120 ≈ (2π/2000)⁴ × 2π/120 ≈ 5e-12 rad; 1e-9 rad leaves the round-off of 2000 steps."""
    mass, inertia_zz, d = 2.0, 0.05, 0.4
    body = rd.PivotedPlanarBody(mass, inertia_zz, [0.0, -d])
    T = exact.pendulum_period_from_rest(exact.pendulum_omega0(mass, inertia_zz + mass * d * d, d, 9.81), 2.5)
    run = rd.simulate(body, rd.PivotedPlanarBodyState(theta=2.5, omega=0.0), T / 2000, 2000, method="rk4",
                      gravity=[0.0, -9.81], record_every=2000)
    q = run.q_WB[-1, 0]
    assert abs(2 * np.arctan2(q[2], q[3]) - 2.5) <= 1e-9
    assert abs(run.w_B[-1, 0, 2]) <= 1e-9 * 2 * np.pi / T * 10


# ---------------------------------------------------------------- rotating frame = inertial turned into it
AXIS, RATE = np.array([0.2, -0.3, 1.0]), 0.7
MASS_P, MASS_R, INERTIA_R = 1.5, 2.0, np.diag([0.4, 0.6, 0.9])
P0, V0 = np.array([1.0, 0.3, -0.2]), np.array([0.1, 0.5, 0.2])
PR0, QR0, VR0, WR0 = np.array([-0.5, 0.8, 0.3]), so3.rotvec_to_quat([0.3, -0.4, 0.2]), np.array([0.2, -0.1, 0.4]), \
    np.array([0.5, -0.3, 0.8])


def two_body_scene(frame):
    """A particle and a rigid body, each on a spring to the anchor at the (common, fixed) origin: the spring force
    depends only on distances, the same law in W and in F."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(MASS_P), name="particle")
    scene.add_body(rd.RigidBody(MASS_R, INERTIA_R), name="rigid")
    scene.add(rd.SpringDamper(body_a=0, point_a_B=[0, 0, 0], body_b=None, point_b=[0, 0, 0], stiffness=1.0,
                              rest_length=0.5))
    scene.add(rd.SpringDamper(body_a=1, point_a_B=[0.2, 0.1, -0.1], body_b=None, point_b=[0, 0, 0], stiffness=2.0,
                              rest_length=0.3))
    scene.frame = frame
    return scene


def inertial_and_frame_runs(method, dt, steps):
    """(inertial run, run in F) from the same initial motion (F = W at t = 0: positions equal, v_F = v_W − Ω × p,
    ω_rel = ω − R_BW Ω)."""
    w_W = RATE * AXIS / np.linalg.norm(AXIS)
    states_W = [rd.ParticleState(p_W=P0, v_W=V0), rd.RigidBodyState(p_W=PR0, q_WB=QR0, v_W=VR0, w_B=WR0)]
    q_F, w_rel = moving_frame.attitude_into_frame(AXIS, RATE, 0.0, QR0, WR0)
    states_F = [rd.ParticleState(p_W=P0, v_W=V0 - np.cross(w_W, P0)),
                rd.RigidBodyState(p_W=PR0, q_WB=q_F, v_W=VR0 - np.cross(w_W, PR0), w_B=w_rel)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.SceneCompatibilityWarning)
        inertial = rd.simulate(two_body_scene(None), states_W, dt, steps, method=method, record_every=steps)
        in_frame = rd.simulate(two_body_scene(rd.SceneFrame.rotating(AXIS, RATE)), states_F, dt, steps, method=method,
                               record_every=steps)
    return inertial, in_frame


def frame_difference(inertial, in_frame):
    """max over the final p, v of both bodies, the rigid body's attitude [rad] and ω of |inertial turned into F − run
    in F|."""
    t = inertial.t[-1]
    out = []
    for b in range(2):
        p, v = moving_frame.particle_into_frame(AXIS, RATE, t, inertial.p_W[-1, b], inertial.v_W[-1, b])
        out += [np.abs(p - in_frame.p_W[-1, b]).max(), np.abs(v - in_frame.v_W[-1, b]).max()]
    q, w = moving_frame.attitude_into_frame(AXIS, RATE, t, inertial.q_WB[-1, 1], inertial.w_B[-1, 1])
    out += [attitude_angle(q, in_frame.q_WB[-1, 1]), np.abs(w - in_frame.w_B[-1, 1]).max()]
    return max(out)


@pytest.mark.parametrize("method", SECOND_ORDER_AND_ABOVE)
def test_run_in_a_rotating_frame_equals_the_inertial_run_turned_into_it(method):
    """Both runs (1 s, state sizes ~1, rates ≲ 1.5 /s) differ by the two runs' truncation errors and round-off:
    C h^p. The step is checked to be in the truncation-dominated range: the difference at 8h must be 8^p times
    larger (within 25 %), so the difference at h is (difference at 8h)/8^p. With h = 1e-5 s (100000 steps) for
    p = 2 (implicit midpoint: C ≈ 0.2, 2e-11) and 1e-3 s for p = 4 (≈ 1e-13) that is ≤ 1e-10 (the required
    accuracy); the round-off of 1e5 steps (a random walk √N × 16 eps ≈ 1e-12; implicit midpoint's Newton stops
    at 1e-14 per step, also unbiased) stays below it."""
    p = ORDERS[method]
    dt = 1e-5 if p == 2 else 1e-3
    steps = round(1.0 / dt)
    fine = frame_difference(*inertial_and_frame_runs(method, dt, steps))
    assert fine <= 1e-10, (method, fine)
    coarse = frame_difference(*inertial_and_frame_runs(method, 8 * dt, steps // 8))
    assert coarse >= 8 ** p / 1.25 * fine or coarse <= 1e-10, (method, fine, coarse)


def test_coriolis_power_is_zero_up_to_round_off():
    """The CoriolisForce column of power at every record of the rigid body + particle run in F: −2m Ω × v is ⊥ v, and
    the torque −(ω × I Ω + Ω × I ω − I (ω × Ω)) is ⊥ ω: ω·(ω × IΩ) = 0 and ω·(Ω × Iω) = Iω·(ω × Ω) = ω·I(ω × Ω)
    (I symmetric). Zero up to 2 × 32 eps of the terms' magnitudes 2m |Ω| |v|² + 3 ‖I‖ |Ω| |ω|²; its work stays
    within the largest of those bounds × the run's time."""
    _, run = inertial_and_frame_runs("rk4", 1e-3, 1000)
    column = list(run.elements).index("CoriolisForce")
    w_F = RATE
    scale = (2 * MASS_P * w_F * np.sum(run.v_W[:, 0] ** 2, axis=1)
             + 2 * MASS_R * w_F * np.sum(run.v_W[:, 1] ** 2, axis=1)
             + 3 * np.linalg.norm(INERTIA_R, 2) * w_F * np.sum(run.w_B[:, 1] ** 2, axis=1))
    assert np.all(np.abs(run.power[:, column]) <= 2 * 32 * EPS * scale)
    assert abs(run.work[-1, column]) <= 2 * 32 * EPS * scale.max() * run.t[-1]


# ---------------------------------------------------------------- Foucault's pendulum
def foucault_rate(latitude, duration=1800.0, dt=0.02):
    """The measured turning rate [rad/s] (about z up) of the swing plane of a spherical pendulum in
    SceneFrame.earth(latitude): a 10 kg sphere of radius 0.1 m on L = 10 m (ω0 ≈ 1 rad/s), released at rest 0.01 rad
    off the vertical, RK4 at dt, recorded every 0.02 s. The plane's direction per swing: the principal axis of the
    bob's horizontal positions over one period (½ atan2(2 S_xy, S_xx − S_yy)); the rate: least-squares slope."""
    L, r, m = 10.0, 0.1, 10.0
    body = rd.PivotedBody(rd.RigidBody(m, np.full(3, 0.4 * m * r * r)), [0.0, 0.0, -L])
    scene = rd.Scene()
    scene.add_body(body, name="bob")
    scene.add(rd.UniformGravity(g_W=[0.0, 0.0, -9.81]))
    scene.frame = rd.SceneFrame.earth(latitude)
    steps = round(duration / dt)
    run = rd.simulate(scene, [rd.PivotedBodyState(q_WB=so3.rotvec_to_quat([-0.01, 0.0, 0.0]))], dt, steps,
                      method="rk4", record_every=round(0.02 / dt))
    xy = run.p_W[:, 0, :2]
    period = 2 * np.pi * np.sqrt(L / 9.81)
    per_swing = round(period / 0.02)
    times, angles = [], []
    for start in range(0, len(xy) - per_swing, per_swing):
        x, y = xy[start:start + per_swing].T
        angles.append(0.5 * np.arctan2(2 * np.mean(x * y), np.mean(x * x) - np.mean(y * y)))
        times.append(run.t[start + per_swing // 2])
    angles = np.unwrap(np.array(angles), period=np.pi)
    return np.polyfit(times, angles, 1)[0]


@pytest.mark.parametrize("latitude", [np.radians(48.85), np.radians(-33.9)])
def test_foucault_plane_turns_at_omega_sin_latitude_clockwise_in_the_north(latitude):
    """The plane turns at −Ω sin(latitude) about the local vertical (clockwise seen from above in the north,
    anticlockwise in the south; Landau & Lifshitz §39), within 0.5 %. What else turns it, each far below 0.5 %:
    Airy's precession of the slightly elliptic swing, (3/8) ω0 a b/L² with a = 0.01 L and b/a ≲ Ω/ω0: a relative
    (3/8)(a/L)² ≈ 4e-5; the bob's spin about the rod (a symmetric top: I3/I1 = 0.4 r²/L² ≈ 4e-5); the centrifugal
    term only tilts the vertical by Ω² L/g ≈ 5e-9. RK4 at dt = 0.02 s (ω0 dt = 0.02): its error is isotropic about the
    vertical (turns nothing at first order) and ≈ (ω0 dt)⁴/120 ≈ 1.3e-9 per radian of phase (≈ 2e-6 rad over the
    run); the run at dt/2, recorded at the same times, checks it: the rates agree within 1e-4 relative. The fit over
    ~280 swings of a turn of ~0.1 rad: its error shrinks with the duration (about −0.06 %, −0.03 %, +0.02 % at
    900, 1800, 3600 s in the runs measured), ≪ 0.5 % at 1800 s."""
    want = -7.2921159e-5 * np.sin(latitude)
    got = foucault_rate(latitude)
    assert got == pytest.approx(want, rel=5e-3)
    assert foucault_rate(latitude, dt=0.01) == pytest.approx(got, rel=1e-4)


# ---------------------------------------------------------------- Tsiolkovsky and the constant-thrust burn
def test_tsiolkovsky_and_the_constant_thrust_burn():
    """A 10 kg particle losing 1 kg/s with u_rel = (−300, 0, 0) m/s (thrust +300 N along x) under g = −9.81 z for 8 s
    (down to 2 kg), RK4 at h = 1e-3 s: v and p against the closed form within 1e-9 relative, and without gravity
    Δv = |u| ln(m0/m1) within 1e-9 relative. RK4's global error ≲ t h⁴ max|v⁽⁵⁾|/2880 with v⁽⁵⁾ = 24 |u| |ṁ|⁵/m⁵ ≤
    225 m/s⁶ at 2 kg: ≈ 8 × 1e-12 × 0.08 ≈ 6e-13 m/s (1e-15 relative), round-off of 8000 steps ≤ 8000 × 8 eps ≈ 1.4e-11
    relative: 1e-9 holds with margin; the mass m0 + ṁ t is linear (RK4 exact up to the round-off of t)."""
    m0, rate, u = 10.0, -1.0, np.array([-300.0, 0.0, 0.0])
    for g in (np.array([0.0, 0.0, -9.81]), np.zeros(3)):
        scene = rd.Scene()
        scene.add_body(rd.Particle(m0), name="rocket", mass_flow=rd.MassFlow(rate=rate))
        if g.any():
            scene.add(rd.UniformGravity(g_W=g))
        scene.add(rd.Thrust(body=0, u_rel=u, frame="world"))
        run = rd.simulate(scene, [rd.ParticleState(p_W=[0, 0, 0], v_W=[0, 0, 0])], 1e-3, 8000, method="rk4",
                          record_every=1000)
        p, v, m = (np.array(x) for x in zip(*(exact.constant_thrust(m0, rate, u, g, np.zeros(3), np.zeros(3), t)
                                                for t in run.t)))
        np.testing.assert_allclose(run.mass[:, 0], m, rtol=16 * EPS * 8000, atol=0)
        np.testing.assert_allclose(run.v_W[:, 0], v, rtol=0, atol=1e-9 * np.abs(v).max())
        np.testing.assert_allclose(run.p_W[:, 0], p, rtol=0, atol=1e-9 * np.abs(p).max())
    delta_v = np.linalg.norm(run.v_W[-1, 0] - run.v_W[0, 0])
    assert delta_v == pytest.approx(exact.tsiolkovsky_delta_v(u, m0, run.mass[-1, 0]), rel=1e-9)
    assert rd.ConstantThrustSolution(m0, rate, u).delta_v(2.0) == pytest.approx(300 * math.log(5), rel=8 * EPS)


# ---------------------------------------------------------------- observed orders
def run_model(model, method, steps):
    """The final state (flat array) of `model` after `steps` steps over its horizon, by `method`."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.SceneCompatibilityWarning)
        if model == "pivoted":
            run = rd.simulate(top_body(), rd.PivotedBodyState(q_WB=TOP["q"], w_B=[0.4, -0.3, 3.0]), 1.0 / steps, steps,
                              method=method, gravity=TOP["g"], record_every=steps)
            return np.concatenate([so3.quat_to_rotvec(run.q_WB[-1, 0]), run.w_B[-1, 0]])
        if model == "pendulum":
            run = rd.simulate(rd.PivotedPlanarBody(2.0, 0.05, [0.0, -0.4]), rd.PivotedPlanarBodyState(theta=2.0),
                              2.0 / steps, steps, method=method, gravity=[0.0, -9.81], record_every=steps)
            return np.concatenate([run.q_WB[-1, 0], run.w_B[-1, 0]])
        if model == "frame_particle":
            scene = rd.Scene()
            scene.add_body(rd.Particle(1.0))
            scene.add(rd.UniformGravity(g_W=[0.0, 0.0, -9.81]))
            scene.frame = rd.SceneFrame.rotating(AXIS, 2.0)
            run = rd.simulate(scene, [rd.ParticleState(p_W=P0, v_W=V0)], 1.0 / steps, steps, method=method,
                              record_every=steps)
            return np.concatenate([run.p_W[-1, 0], run.v_W[-1, 0]])
        if model == "frame_rigid":
            _, run = inertial_and_frame_runs(method, 1.0 / steps, steps)
            return np.concatenate([run.p_W[-1].ravel(), run.v_W[-1].ravel(), so3.quat_to_rotvec(run.q_WB[-1, 1]),
                                   run.w_B[-1, 1]])
        scene = rd.Scene()
        if model == "mass_particle":
            scene.add_body(rd.Particle(10.0), mass_flow=rd.MassFlow(rate=-2.0))
            state = rd.ParticleState(p_W=[0, 0, 0], v_W=[1, 0, 0])
            scene.add(rd.Thrust(body=0, u_rel=[-30.0, 5.0, 0.0], frame="world"))
        else:  # mass_rigid
            scene.add_body(rd.RigidBody(10.0, [1.0, 2.0, 3.0]), mass_flow=rd.MassFlow(rate=-2.0))
            state = rd.RigidBodyState(w_B=[0.5, 1.0, -0.7])
            scene.add(rd.Thrust(body=0, u_rel=[-30.0, 5.0, 0.0], frame="body", r_B=[0.1, -0.2, 0.3]))
        scene.add(rd.UniformGravity(g_W=[0.0, 0.0, -9.81]))
        run = rd.simulate(scene, [state], 2.0 / steps, steps, method=method, record_every=steps)
        return np.concatenate([run.p_W[-1, 0], run.v_W[-1, 0], so3.quat_to_rotvec(run.q_WB[-1, 0]), run.w_B[-1, 0],
                               run.mass[-1]])


MODELS = ["pivoted", "pendulum", "frame_particle", "frame_rigid", "mass_particle", "mass_rigid"]
BASE_STEPS = {1: 800, 2: 100, 4: 25}
# the large-amplitude pendulum (ω0 h = 0.37 at 25 steps) and the spinning variable-mass body reach RK4's asymptotic
# range only at finer steps
FINER = {"pendulum": 4, "mass_rigid": 2}


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps of every method on purpose (an order study)
@pytest.mark.parametrize("method, model", [(method, model) for model in MODELS for method in METHODS])
def test_observed_order_of_every_method_on_every_new_model(method, model):
    """Richardson differences d_k = |y(h_k) − y(h_k/2)| over 5 halvings; log2(d_k/d_{k+1}) tends to the method's order
    p: in the asymptotic range d = C h^p (1 + D h + ...), the slope's deviation from p halves with each halving, so
    the last deviation is at most twice the last change of slope; that change must be small (≤ 0.1: the next term
    moves d by < 7 %). Round-off: the smallest difference stays far above the runs' round-off (asserted > 1e-11
    with ≤ 12800 steps of ~16 eps each)."""
    p = ORDERS[method]
    steps = [BASE_STEPS[p] * FINER.get(model, 1) * 2 ** k for k in range(5)]
    finals = [run_model(model, method, n) for n in steps]
    d = [np.max(np.abs(a - b)) for a, b in zip(finals, finals[1:])]
    assert min(d) > 1e-11, d
    slopes = [math.log2(a / b) for a, b in zip(d, d[1:])]
    assert abs(slopes[-1] - slopes[-2]) <= 0.1, (slopes, d)
    assert abs(slopes[-1] - p) <= max(2 * abs(slopes[-1] - slopes[-2]), 0.05), (slopes, d)


# ---------------------------------------------------------------- bad input
def test_pivot_at_the_centre_of_mass_is_the_free_rotation():
    """c = 0: gravity has no moment about O = C, so the body turns as the free RigidBody (same RK4 on the same Euler
    equations, I_O = I_C): attitude and ω agree to the round-off of 200 steps (200 × 16 eps κ, κ = 3); 'exact'
    is allowed and is the closed-form free rotation (its error 16 eps κ (1 + |ω| t))."""
    inertia, w0, q0 = np.array([1.0, 2.0, 3.0]), np.array([0.3, 1.0, -0.5]), so3.rotvec_to_quat([0.1, 0.2, 0.3])
    body = rd.PivotedBody(rd.RigidBody(2.0, inertia), [0.0, 0.0, 0.0])
    assert body.digits_lost == 0.0
    free = rd.simulate(rd.RigidBody(2.0, inertia), rd.RigidBodyState(q_WB=q0, w_B=w0), 0.01, 200, method="rk4").body(0)
    for method in ("rk4", "exact"):
        pinned = rd.simulate(body, rd.PivotedBodyState(q_WB=q0, w_B=w0), 0.01, 200, method=method,
                             gravity=[0, 0, -9.81])
        # exact vs RK4: RK4's own error (0.01 |ω|)⁴ × 2/120 ≲ 1e-10
        tol = 200 * 16 * EPS * 3 if method == "rk4" else 1e-8
        assert attitude_angle(pinned.q_WB[-1, 0], free.q_WB[-1]) <= tol
        np.testing.assert_allclose(pinned.w_B[-1, 0], free.w_B[-1], rtol=0, atol=tol * 2)
        np.testing.assert_allclose(pinned.pivot_reaction_W[0, 0], [0.0, 0.0, 2.0 * 9.81], rtol=0, atol=64 * EPS * 20)


def test_far_pivot_warns_about_the_digits_of_the_inertia():
    """A pivot 1e4 m from a centre of mass with λ_min(I_C) = 1e-2 kg m²: m|c|²/λ_min = 1e10, 10 digits lost (> 6): a
    SceneCompatibilityWarning naming bodies[0] and the distance; the run still completes."""
    body = rd.PivotedBody(rd.RigidBody(1.0, [1e-2, 1e-2, 1e-2]), [0.0, 0.0, -1e4])
    assert body.digits_lost == pytest.approx(10.0, abs=1e-12)
    with pytest.warns(rd.SceneCompatibilityWarning, match=r"bodies\[0\].*pivot is .*m from the centre of mass"):
        run = rd.simulate(body, rd.PivotedBodyState(), 0.1, 10, method="rk4", gravity=[0, 0, -9.81])
    assert np.all(np.isfinite(run.q_WB))


def nan_kinematics(t):
    """A FrameMotion function whose angular velocity is NaN from t = 0.05 s (module level for pickling)."""
    bad = np.nan if t >= 0.05 else 0.0
    return rd.FrameKinematics(w_PF_P=[0.0, 0.0, bad])


def nan_tuple(t):
    """The same as a 6-tuple (R_PF, w_PF_P, alpha_PF_P, p_PF_P, v_PF_P, a_PF_P), which FrameMotion also accepts."""
    return (np.eye(3), [0.0, 0.0, np.nan if t >= 0.05 else 0.0], np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3))


@pytest.mark.parametrize("function", [nan_kinematics, nan_tuple])
def test_frame_motion_returning_nan_raises_naming_the_value(function):
    """The motion function's NaN angular velocity (at the step from t = 0.05 s) stops simulate with a ValueError naming
    the field it came in (w_PF_P): from Python the conversion of the function's value refuses it before the core's
    own check of the frame terms ("frame: expected finite values from the motion function ...")."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0))
    scene.frame = rd.SceneFrame.moving(rd.FrameMotion(function))
    with pytest.raises(ValueError, match=r"w_PF_P.*finite"):
        rd.simulate(scene, [rd.ParticleState(v_W=[1, 0, 0])], 0.01, 20, method="rk4")


def nan_rate(t):
    return np.nan if t > 0.05 else -1.0


@pytest.mark.parametrize("rate", [np.inf, -np.inf, np.nan])
def test_non_finite_mass_rate_raises_naming_the_rate(rate):
    with pytest.raises(ValueError, match="rate"):
        scene = rd.Scene()
        scene.add_body(rd.Particle(1.0), mass_flow=rd.MassFlow(rate=rate))
        rd.simulate(scene, [rd.ParticleState()], 0.01, 10, method="rk4")


def test_mass_rate_function_returning_nan_raises_naming_the_flow():
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), mass_flow=rd.MassFlow(rate=nan_rate))
    with pytest.raises(ValueError, match=r"mass_flows\[0\]\.rate"):
        rd.simulate(scene, [rd.ParticleState()], 0.01, 20, method="rk4")


def test_negative_rate_is_allowed_and_mass_reaching_zero_raises():
    """A 1 kg particle losing 1 kg/s: 0.5 s runs (mass 0.5 kg); 2 s is refused up front naming steps/dt (a constant
    rate); a rate given as a function refuses at the step where the mass would reach zero, naming mass_flows[0]."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), mass_flow=rd.MassFlow(rate=-1.0))
    run = rd.simulate(scene, [rd.ParticleState()], 0.01, 50, method="rk4")
    assert run.mass[-1, 0] == pytest.approx(0.5, rel=64 * EPS)
    with pytest.raises(ValueError, match=r"steps|dt"):
        rd.simulate(scene, [rd.ParticleState()], 0.01, 200, method="rk4")
    timed = rd.Scene()
    timed.add_body(rd.Particle(1.0), mass_flow=rd.MassFlow(rate=minus_one))
    with pytest.raises(ValueError, match=r"mass_flows\[0\].*positive mass"):
        rd.simulate(timed, [rd.ParticleState()], 0.01, 200, method="rk4")


def minus_one(t):
    return -1.0
