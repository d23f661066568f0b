"""The numpy reference of the gyrostat (rigiddyn_ref.gyrostat) checked against exact solutions and its first
integrals, without rigiddyn (Hughes, "Spacecraft Attitude Dynamics", ch. 3; the equations are derived in the
module's docstring): a hand-worked rate, the torque-free integrals under RK4 at fourth order, wheels held at
constant speed, the spin-up from rest in closed form, the energy balance with motors and outside loads, the
reduction to the rigid body and to the ReactionWheel element, and bad input."""

import numpy as np
import pytest

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import gyrostat as gy
from rigiddyn_ref import scene
from rigiddyn_ref import so3

EPS = np.finfo(float).eps
SEEDS = range(6)


# ---------------------------------------------------------------- 1. the rate on a hand-worked case
def test_the_rate_on_a_hand_worked_case():
    """m = 2 kg, I = diag(3, 4, 10) kg m², wheel 0 along x_B (axis given as (2, 0, 0)) with J = 1, wheel 1 along
    z_B with J = 2: A = I − Σ J a aᵀ = diag(2, 4, 8). q = (0, 0, 1, 0) (half turn about z), p = (1, 2, 3),
    v = (0.5, 0, −1), ω = (1, 2, 0.5), Ω = (4, −2); f_W = (2, −4, 6), τ_B = (1, 0, 2), u = (0.5, −1).
      h_w = (4, 0, −4), H_B = I ω + h_w = (3, 8, 5) + h_w = (7, 8, 1), ω × H = (−2, 2.5, −6),
      A ω̇ = τ − Σ u a − ω × H = (1, 0, 2) − (0.5, 0, −1) − (−2, 2.5, −6) = (2.5, −2.5, 9) ⇒ ω̇ = (1.25, −0.625, 1.125),
      Ω̇ = u/J − a·ω̇ = (0.5 − 1.25, −0.5 − 1.125) = (−0.75, −1.625), v̇ = f/m = (1, −2, 3),
      q̇ = ½ q ⊗ (ω, 0) = ½ ((0, 0, 1) × ω, −ω_z) = (−1, 0.5, 0, −0.25).
    T = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J (a·ω + Ω)² = 1.25 + 10 + 12.5 + 2.25 = 26 J (and the other form, ½ ωᵀ I ω +
    Σ J Ω a·ω + ½ Σ J Ω² + 1.25 = 10.75 + 2 + 12 + 1.25, agrees); H_W = Rz(π) H_B = (−7, −8, 1);
    p × m v = (−4, 5, −2); Σ u Ω = 4 W; f·v + τ·ω = −5 + 2 W. Binary fractions throughout: every value exact."""
    body = gy.gyrostat(2.0, [3.0, 4.0, 10.0], [([2.0, 0.0, 0.0], 1.0), ([0.0, 0.0, 1.0], 2.0)])
    np.testing.assert_array_equal(body.axes, [[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    np.testing.assert_array_equal(body.transverse, np.diag([2.0, 4.0, 8.0]))
    y = gy.state([1.0, 2.0, 3.0], [0.0, 0.0, 1.0, 0.0], [0.5, 0.0, -1.0], [1.0, 2.0, 0.5], [4.0, -2.0])
    f_W, tau_B, u = [2.0, -4.0, 6.0], [1.0, 0.0, 2.0], [0.5, -1.0]
    np.testing.assert_array_equal(gy.rate(body, 0.0, y, f_W, tau_B, u),
                                  [0.5, 0.0, -1.0, -1.0, 0.5, 0.0, -0.25, 1.0, -2.0, 3.0, 1.25, -0.625, 1.125,
                                   -0.75, -1.625])
    assert gy.kinetic_energy(body, y) == 26.0
    np.testing.assert_array_equal(gy.angular_momentum_B(body, y[10:13], y[13:]), [7.0, 8.0, 1.0])
    np.testing.assert_array_equal(gy.angular_momentum_W(body, y), [-7.0, -8.0, 1.0])
    np.testing.assert_array_equal(gy.angular_momentum_about_origin(body, y), [-11.0, -3.0, -1.0])
    assert gy.motor_power(body, y, u) == 4.0
    assert gy.external_power(body, y, f_W, tau_B) == -3.0


# ---------------------------------------------------------------- the power identity, pointwise
def random_case(rng, n_wheels=3):
    """A 5 kg body with a full inertia (principal moments 2..4 kg m², turned), n_wheels wheels of J ∈ [0.02, 0.1]
    kg m² on random axes (A stays positive definite: Σ J ≤ 0.3 < 2), and a random state and inputs: |ω| ≲ 3.5
    rad/s, |Ω| ≤ 50 rad/s, |u| ≤ 0.5 N m, |f| ≲ 3.5 N, |τ| ≲ 1.7 N m."""
    R = so3.rotvec_to_matrix(rng.normal(size=3))
    I = R @ np.diag(rng.uniform(2.0, 4.0, 3)) @ R.T
    body = gy.gyrostat(5.0, 0.5 * (I + I.T), [(rng.normal(size=3), rng.uniform(0.02, 0.1)) for _ in range(n_wheels)])
    y = gy.state(rng.uniform(-1, 1, 3), so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-1, 1, 3),
                 rng.uniform(-2, 2, 3), rng.uniform(-50, 50, n_wheels))
    return body, y, rng.uniform(-2, 2, 3), rng.uniform(-1, 1, 3), rng.uniform(-0.5, 0.5, n_wheels)


@pytest.mark.parametrize("seed", SEEDS)
def test_the_rate_of_the_kinetic_energy_is_the_power(seed):
    """Along ẏ, dT/dt = m v·v̇ + ωᵀ A ω̇ + Σ J_k s_k (a_k·ω̇ + Ω̇_k) (s_k = a_k·ω + Ω_k, eq. (5)) equals f·v + τ·ω +
    Σ u_k Ω_k (eq. (6)). Round-off: the solve is backward stable, so A ω̇ differs from the right-hand side by
    ≤ 3·3 eps |A| |ω̇| per component (n = 3) and the right-hand side rounds by ≤ 4 eps of its terms; Ω̇_k + a_k·ω̇
    differs from u_k/J_k by ≤ 4 eps (|u_k/J_k| + |ω̇|); each dot product adds ≤ 3 eps: 32 eps of the sum of the
    terms' sizes bounds the whole."""
    body, y, f_W, tau_B, u = random_case(np.random.default_rng(seed))
    s = gy.split(body, y)
    y_dot = gy.rate(body, 0.0, y, f_W, tau_B, u)
    v_dot, w_dot, Omega_dot = y_dot[7:10], y_dot[10:13], y_dot[13:]
    spin = body.axes @ s.w_B + s.Omega
    dT = (body.mass * s.v_W @ v_dot + s.w_B @ body.transverse @ w_dot
          + body.J @ (spin * (body.axes @ w_dot + Omega_dot)))
    H = gy.angular_momentum_B(body, s.w_B, s.Omega)
    w, wd = np.linalg.norm(s.w_B), np.linalg.norm(w_dot)
    scale = (body.mass * np.linalg.norm(s.v_W) * np.linalg.norm(v_dot)
             + w * (np.linalg.norm(body.transverse, 2) * wd + np.linalg.norm(tau_B) + np.abs(u).sum()
                    + w * np.linalg.norm(H))
             + body.J @ (np.abs(spin) * (np.abs(u) / body.J + 2 * wd)) + np.linalg.norm(f_W) * np.linalg.norm(s.v_W))
    power = gy.external_power(body, y, f_W, tau_B) + gy.motor_power(body, y, u)
    assert abs(dT - power) <= 32 * EPS * scale


# ---------------------------------------------------------------- RK4 runs
def tumbling_gyrostat():
    """A 5 kg body, I = (2, −0.1, 0.05; −0.1, 3, 0.2; 0.05, 0.2, 4) kg m² (wheels included), three wheels:
    J = 0.05 along (1, 2, 2)/3 at 40 rad/s, J = 0.04 along y_B at −30 rad/s, J = 0.03 along (1, −1, 0)/√2 at
    25 rad/s (|h_w| ≈ 2.3 N m s, comparable to |I ω| ≈ 8.4: it bends the polhodes); ω0 = (1, −0.5, 2) rad/s,
    p0 = (1, −2, 0.5) m, v0 = (0.3, 0.1, −0.2) m/s."""
    inertia = [[2.0, -0.1, 0.05], [-0.1, 3.0, 0.2], [0.05, 0.2, 4.0]]
    body = gy.gyrostat(5.0, inertia, [([1.0, 2.0, 2.0], 0.05), ([0.0, 1.0, 0.0], 0.04), ([1.0, -1.0, 0.0], 0.03)])
    y0 = gy.state([1.0, -2.0, 0.5], so3.rotvec_to_quat([0.3, -0.4, 0.2]), [0.3, 0.1, -0.2], [1.0, -0.5, 2.0],
                  [40.0, -30.0, 25.0])
    return body, y0


def assert_fourth_order(e_h, e_h2, scale, steps_h2, relative=1e-8):
    """The drift of a first integral under RK4 is its global error C₄ h⁴ + C₅ h⁵ + …: halving h divides it by 16
    to 32 (asserted 10–34: the energy's C₄ can be small, so that at these steps part of the drift is the h⁵ term
    (measured 28 for T torque-free at h = 0.02 s, 25 at 0.01 s, tending to 16); a first-order mistake gives 2, a
    second-order one 4). Richardson: e(h/2) ≤ 2 |e(h) − e(h/2)|/15 (the factor 2 for the next order's share,
    h |ω| ≤ 0.05 here), plus the round-off, steps × 16 eps of the scale (each step rounds its increment and the
    state); and the drift at h/2 is ≤ `relative` of the scale (the run's largest value of the integral)."""
    assert 10 <= e_h / e_h2 <= 34, (e_h, e_h2)
    assert e_h2 <= 2 * abs(e_h - e_h2) / 15 + steps_h2 * 16 * EPS * scale
    assert e_h2 <= relative * scale


def torque_free_drifts(h, duration):
    """The largest drifts of T, H_W, the angular momentum about W's origin and the absolute axial spins s_k over a
    torque-free, motor-free RK4 run; and the scales (largest T, |H_W|, |H_O|, |s|)."""
    body, y0 = tumbling_gyrostat()
    run = gy.rk4_run(body, y0, h, int(round(duration / h)))
    T = np.array([gy.kinetic_energy(body, y) for y in run.y])
    H = np.array([gy.angular_momentum_W(body, y) for y in run.y])
    H_O = np.array([gy.angular_momentum_about_origin(body, y) for y in run.y])
    spin = run.y[:, 10:13] @ body.axes.T + run.y[:, 13:]
    # after each step q ← q/|q|: the division and the norm round by ≤ 2 eps, |q/|q|| by ≤ 2 eps more
    assert np.max(np.abs(np.linalg.norm(run.y[:, 3:7], axis=1) - 1.0)) <= 4 * EPS
    drift = [np.max(np.abs(T - T[0])), np.max(np.linalg.norm(H - H[0], axis=1)),
             np.max(np.linalg.norm(H_O - H_O[0], axis=1)), np.max(np.abs(spin - spin[0]))]
    scale = [np.max(T), np.max(np.linalg.norm(H, axis=1)), np.max(np.linalg.norm(H_O, axis=1)), np.max(np.abs(spin))]
    return drift, scale, len(run.t) - 1


def test_torque_free_integrals_are_kept_at_fourth_order():
    """No outside wrench, u = 0: H_W = R H_B (so |H_W|), T, the momentum about W's origin (p × m v + R H_B, the
    centre of mass drifting at constant v) are first integrals; over 20 s (≈ 7 turns) RK4 keeps them to its
    global error (assert_fourth_order, h = 0.02 s and 0.01 s). Each wheel's absolute axial spin s_k = a_k·ω + Ω_k
    has ṡ_k = u_k/J_k = 0 and is linear in the state: every RK4 stage adds h c (a_k·ω̇ + Ω̇_k), zero up to the
    rounding of Ω̇_k = −a_k·ω̇ (≤ eps |ω̇|, |ω̇| ≤ 10 rad/s²), so s_k moves by round-off only: per step ≤ 4 eps
    |s| (the sums) + h · 4 eps |ω̇|."""
    coarse, _, _ = torque_free_drifts(0.02, 20.0)
    fine, scale, steps = torque_free_drifts(0.01, 20.0)
    for i in range(3):
        assert_fourth_order(coarse[i], fine[i], scale[i], steps)
    assert fine[3] <= steps * (4 * EPS * scale[3] + 0.01 * 4 * EPS * 10.0)


# ---------------------------------------------------------------- 3. wheels held at constant speed
def holding_torque(body):
    """u(t, y) that holds every Ω_k: by eq. (3) with Ω̇_k = 0, u_k = J_k a_k·ω̇, where ω̇ then solves
    I ω̇ = −ω × (I ω + h_w) (eq. (2) with ḣ_w = 0, no outside couple)."""
    def u(t, y):
        s = gy.split(body, y)
        w_dot = np.linalg.solve(body.inertia, -dyn.cross(s.w_B, gy.angular_momentum_B(body, s.w_B, s.Omega)))
        return body.J * (body.axes @ w_dot)
    return u


def held_drifts(h, duration):
    body, y0 = tumbling_gyrostat()
    run = gy.rk4_run(body, y0, h, int(round(duration / h)), motor=holding_torque(body))
    H = np.array([np.linalg.norm(gy.angular_momentum_W(body, y)) for y in run.y])
    E = np.array([0.5 * y[10:13] @ body.inertia @ y[10:13] for y in run.y])
    drift = [np.max(np.abs(H - H[0])), np.max(np.abs(E - E[0])), np.max(np.abs(run.y[:, 13:] - y0[13:]))]
    return drift, [np.max(H), np.max(E), np.max(np.abs(y0[13:]))], len(run.t) - 1, body


def test_wheels_held_at_constant_speed():
    """With u_k = J_k a_k·ω̇ (holding_torque) the wheels keep their speeds and the body obeys I ω̇ + ω × (I ω + h_w)
    = 0 with h_w constant: |H| and ½ ωᵀ I ω are first integrals (d/dt ½ ωᵀ I ω = −ω·(ω × H) = 0), kept at RK4's
    order (assert_fourth_order, h = 0.02 s and 0.01 s over 10 s). Ω moves by round-off only: per stage Ω̇_k =
    u_k/J_k − a_k·ω̇ is a difference of two values ≤ |ω̇| ≤ 10 rad/s² that agree to the solves' error, ≤ 16 eps
    κ(A) |ω̇| (κ(A) ≈ 2.3, both solves backward stable), and each step rounds Ω + increment by ≤ eps |Ω|."""
    coarse, _, _, _ = held_drifts(0.02, 10.0)
    fine, scale, steps, body = held_drifts(0.01, 10.0)
    for i in range(2):
        assert_fourth_order(coarse[i], fine[i], scale[i], steps)
    kappa = np.linalg.cond(body.transverse)
    assert fine[2] <= steps * (EPS * scale[2] + 0.01 * 2 * 16 * EPS * kappa * 10.0)


# ---------------------------------------------------------------- 4. spin-up from rest
I33, J, U = 5.0, 1.0, 1.0  # [kg m²], [kg m²], [N m]: I33 − J = 4, so every rate below is a binary fraction


def spin_up_closed_form(t):
    """A body at rest, I = diag(2, 3, I33), one wheel J along e3 driven by a constant u from Ω = 0. ω stays along
    e3 (ω × H = 0) and H = 0 stays: I33 ω + J Ω = 0, so ω = −(J/I33) Ω and the body's angle θ = −(J/I33) φ (φ the
    wheel's angle relative to the body). Eq. (4): (I33 − J) ω̇ = −u, Ω̇ = u/J − ω̇ = u I33/(J (I33 − J)):
        ω(t) = −u t/(I33 − J),  Ω(t) = u I33 t/(J (I33 − J)),
        θ(t) = −u t²/(2 (I33 − J)),  φ(t) = u I33 t²/(2 J (I33 − J)),  q_WB(t) = (0, 0, sin θ/2, cos θ/2)."""
    return (-U * t / (I33 - J), U * I33 * t / (J * (I33 - J)), -U * t ** 2 / (2 * (I33 - J)),
            U * I33 * t ** 2 / (2 * J * (I33 - J)))


def spin_up_run(h, duration):
    """The RK4 run of the spin-up (spin_up_closed_form) at step h [s] to `duration` [s]."""
    body = gy.gyrostat(3.0, [2.0, 3.0, I33], [([0.0, 0.0, 1.0], J)])
    y0 = gy.state(np.zeros(3), [0.0, 0.0, 0.0, 1.0], np.zeros(3), np.zeros(3), [0.0])
    return body, gy.rk4_run(body, y0, h, int(round(duration / h)), motor=[U])


def test_spin_up_from_rest_rates_exact_to_the_bit():
    """h = 3/32 s, so h/2 = 3/64 and h/6 = 1/64: the rates ω̇ = −1/4, Ω̇ = 5/4 are exact (ω × H = 0 exactly: ω and H
    along e3; the solve on A = diag(2, 3, 4) divides by 4), every stage value ω + c h ω̇ and every RK4 sum
    h/6 (6 ω̇) is a short binary fraction: RK4 integrates the linear ω(t), Ω(t) without error, so they equal the
    closed form bit for bit, H_B = 0 exactly (5 ω + Ω = 0), and q_x = q_y = ω_x = ω_y = 0 exactly (q̇ = ½ q ⊗
    (0, 0, ω, 0) keeps q in the (z, w) plane). The closed forms satisfy θ = −(J/I33) φ identically."""
    body, run = spin_up_run(3.0 / 32.0, 6.0)
    omega, Omega, theta, phi = spin_up_closed_form(run.t)
    np.testing.assert_array_equal(run.y[:, 12], omega)
    np.testing.assert_array_equal(run.y[:, 13], Omega)
    np.testing.assert_array_equal(run.y[:, [0, 1, 2, 3, 4, 7, 8, 9, 10, 11]], 0.0)
    np.testing.assert_array_equal([gy.angular_momentum_B(body, y[10:13], y[13:]) for y in run.y], 0.0)
    np.testing.assert_array_equal(theta, -(J / I33) * phi)


def spin_up_angle_error(h, duration):
    """The largest |θ_RK4 − θ(t)| [rad], θ_RK4 = 2 atan2(q_z, q_w) unwrapped."""
    _, run = spin_up_run(h, duration)
    angle = 2.0 * np.unwrap(np.arctan2(run.y[:, 5], run.y[:, 6]))
    return np.max(np.abs(angle - spin_up_closed_form(run.t)[2])), np.max(np.abs(angle))


def test_spin_up_from_rest_attitude_at_fourth_order():
    """The attitude q̇ = ½ q ⊗ (0, 0, ω(t), 0) with ω(t) linear: the angle θ = −t²/8 is quadratic in t, but q(t) is
    not polynomial, and RK4's stages see exact ω(t + c h) (the stage states carry it): the angle error is RK4's
    global error C h⁴. To t = 6 s (θ = −4.5 rad, h|ω| ≤ 0.14): halving h = 3/32 s divides it by 16 and Richardson
    bounds it (assert_fourth_order, scale the largest |θ|, relative 1e-6: the rate |θ̇| = 1.5 rad/s at the end,
    C ~ |θ̇|⁵ t/(2⁵ 5!) ≈ 0.01 rad/s⁴, h⁴ ≈ 5e-6 s⁴ gives ~5e-8 rad at h/2)."""
    coarse, _ = spin_up_angle_error(3.0 / 32.0, 6.0)
    fine, scale = spin_up_angle_error(3.0 / 64.0, 6.0)
    assert_fourth_order(coarse, fine, scale, 128, relative=1e-6)


# ---------------------------------------------------------------- 5. the energy balance
MOTOR_SCHEDULE = [gy.MotorTorque(np.array([0.25, -0.125, 0.0625]), 0.0, 1.237),
                  gy.MotorTorque(np.array([-0.375, 0.125, 0.125]), 1.237, 2.771),
                  gy.MotorTorque(np.array([0.125, 0.0, -0.25]), 2.0, 3.5)]
LOADS = [dyn.Load(np.array([0.5, -0.2, 0.1]), np.array([0.2, 0.3, -0.1]), "body", 0.513, 3.109),
         dyn.Load(np.array([0.0, 0.1, -0.3]), np.array([-0.1, 0.05, 0.2]), "world", 0.0, 2.357)]


def balance_drift(h, duration):
    """The largest |T(t) − T(0) − W_loads(t) − W_motor(t)| [J] over an RK4 run under MOTOR_SCHEDULE and LOADS, and
    the largest T."""
    body, y0 = tumbling_gyrostat()
    run = gy.rk4_run(body, y0, h, int(round(duration / h)), motor=MOTOR_SCHEDULE, loads=LOADS)
    T = np.array([gy.kinetic_energy(body, y) for y in run.y])
    return np.max(np.abs(T - T[0] - run.work_loads - run.work_motor)), np.max(T), len(run.t) - 1


def test_energy_balance_with_motors_and_outside_loads():
    """T(t) − T(0) = ∫ (f·v + τ·ω + Σ u_k Ω_k) dt (eq. (6)), the powers integrated by RK4 alongside the state: a
    first integral of the augmented system, kept at RK4's order (assert_fourth_order, h = 0.02 s and 0.01 s over
    4 s) while the motor torques and the outside loads switch at times inside steps (rk4_step splits there; a step
    that read a schedule across a switch would leave a first-order error: ratio 2)."""
    e_h, _, _ = balance_drift(0.02, 4.0)
    e_h2, scale, steps = balance_drift(0.01, 4.0)
    assert_fourth_order(e_h, e_h2, scale, steps)


def test_switching_inputs_are_integrated_at_fourth_order():
    """The balance holds for any torque held within a step, so it cannot see WHEN the inputs switch: the state does.
    Under MOTOR_SCHEDULE and LOADS, the end states of runs at h = 0.02, 0.01, 0.005 s over 4 s converge at order
    4: |y_h − y_h/2| / |y_h/2 − y_h/4| in 10–34 (assert_fourth_order's window; reading a schedule across a switch
    inside a step leaves an O(h) error per switch: ratio 2)."""
    body, y0 = tumbling_gyrostat()
    ends = [gy.rk4_run(body, y0, h, int(round(4.0 / h)), motor=MOTOR_SCHEDULE, loads=LOADS).y[-1]
            for h in (0.02, 0.01, 0.005)]
    ratio = np.max(np.abs(ends[0] - ends[1])) / np.max(np.abs(ends[1] - ends[2]))
    assert 10 <= ratio <= 34, ratio


def test_motor_inputs():
    """motor_torque_at: None is zero; constants are taken as they are; a schedule sums the pieces active at t
    (t_start <= t < t_end; binary fractions: the sums exact); a function is called with (t, y); anything but N
    finite values is refused."""
    body, y0 = tumbling_gyrostat()
    np.testing.assert_array_equal(gy.motor_torque_at(body, None, 0.0, y0), np.zeros(3))
    np.testing.assert_array_equal(gy.motor_torque_at(body, [1.0, 2.0, 3.0], 0.0, y0), [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(gy.motor_torque_at(body, MOTOR_SCHEDULE, 2.5, y0), [-0.25, 0.125, -0.125])
    np.testing.assert_array_equal(gy.motor_torque_at(body, MOTOR_SCHEDULE, 1.237, y0), [-0.375, 0.125, 0.125])
    np.testing.assert_array_equal(gy.motor_torque_at(body, MOTOR_SCHEDULE, 3.5, y0), np.zeros(3))
    np.testing.assert_array_equal(gy.motor_torque_at(body, lambda t, y: t * y[13:], 0.5, y0), [20.0, -15.0, 12.5])
    assert gy.switch_times(MOTOR_SCHEDULE, LOADS) == [0.0, 0.513, 1.237, 2.0, 2.357, 2.771, 3.109, 3.5]
    for bad in ([1.0, 2.0], [1.0, np.nan, 0.0], lambda t, y: np.zeros(2)):
        with pytest.raises(ValueError, match="expected 3 finite motor torques"):
            gy.motor_torque_at(body, bad, 0.0, y0)


# ---------------------------------------------------------------- 6. the reductions
@pytest.mark.parametrize("seed", SEEDS)
def test_without_wheels_the_rate_is_the_rigid_body_rate(seed):
    """N = 0: h_w = 0, A = I, and eq. (4) is Euler's I ω̇ = τ − ω × I ω: the rate equals scene.body_rate of a
    rigid body of the same m, I (the quaternion as stored in both). Round-off: the same operations (ω × I ω, one
    solve), so ≤ 16 eps κ(I) of |ω̇| + |I⁻¹| (|τ| + |ω||I ω|) per component, and equal elsewhere."""
    rng = np.random.default_rng(seed)
    body, y, f_W, tau_B, _ = random_case(rng, n_wheels=0)
    s = gy.split(body, y)
    rigid = scene.rigid(body.mass, body.inertia)
    expected = scene.body_rate(rigid, scene.Kinematics(s.p_W, s.q_WB, s.v_W, s.w_B), f_W, tau_B)
    got = gy.rate(body, 0.0, y, f_W, tau_B, np.zeros(0))
    np.testing.assert_array_equal(got[:10], expected[:10])
    I_inv = np.linalg.norm(np.linalg.inv(body.inertia), 2)
    w = np.linalg.norm(s.w_B)
    scale = I_inv * (np.linalg.norm(tau_B) + w * np.linalg.norm(body.inertia @ s.w_B))
    np.testing.assert_allclose(got[10:], expected[10:], rtol=0, atol=16 * EPS * np.linalg.cond(body.inertia) * scale)


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("acceleration", [0.0, 7.0], ids=["constant_speed", "ramp"])
def test_the_reaction_wheel_element_is_the_gyrostat_with_its_holding_torque(seed, acceleration):
    """The ReactionWheel element prescribes each Ω_k(t) (here speed Ω_k, ramp rate α inside [0, 1)) and acts on a
    rigid body of the whole inertia I as the couple −ω × h − ḣ: I ω̇ = τ − ω × (I ω + h) − ḣ. The gyrostat
    with the torques that hold that schedule, u_k = J_k (a_k·ω̇ + α) by eq. (3) (ω̇ the element's), gives by eq. (4)
    A ω̇' = τ − Σ J_k (a_k·ω̇ + α) a_k − ω × H = (I ω̇ + Σ J_k α a_k) − Σ J_k (a_k·ω̇ + α) a_k = A ω̇ (the element's
    equation put in for τ − ω × H): ω̇' = ω̇, and Ω̇_k = u_k/J_k − a_k·ω̇ = α. The two models are one body: the
    element is the gyrostat whose wheel speeds are prescribed (the motors doing whatever it takes), the gyrostat
    the one whose motor torques are prescribed and wheel speeds integrated. Round-off: ω̇' − ω̇ =
    A⁻¹ (the residuals of both right-hand sides and both solves), ≤ 32 eps |A⁻¹| (|τ| + |ω||H| + |I||ω̇| + Σ J
    (|ω̇| + α)); Ω̇_k − α ≤ that + 4 eps (|ω̇| + α)."""
    rng = np.random.default_rng(seed)
    body, y, f_W, tau_B, _ = random_case(rng)
    s = gy.split(body, y)
    elements = [scene.Element("ReactionWheel", dict(body=0, axis_B=a, inertia=J_k, speed=Omega_k,
                                                    acceleration=acceleration, t_start=0.0, t_end=1.0))
                for a, J_k, Omega_k in zip(body.axes, body.J, s.Omega)]
    elements.append(scene.Element("ScheduledLoads", dict(body=0, loads=[dyn.Load(f_W, tau_B, "body")])))
    rigid_scene = scene.Scene([scene.rigid(body.mass, body.inertia)], elements)
    y_scene = scene.initial_state(rigid_scene, [scene.Kinematics(s.p_W, s.q_WB, s.v_W, s.w_B)])
    w_dot = scene.rate(rigid_scene, y_scene)[10:13]
    u = body.J * (body.axes @ w_dot + acceleration)
    got = gy.rate(body, 0.0, y, dyn.to_world(s.q_WB, f_W), tau_B, u)
    H = gy.angular_momentum_B(body, s.w_B, s.Omega)
    wd = np.linalg.norm(w_dot)
    bound = 32 * EPS * np.linalg.norm(np.linalg.inv(body.transverse), 2) * (
        np.linalg.norm(tau_B) + np.linalg.norm(s.w_B) * np.linalg.norm(H) + np.linalg.norm(body.inertia, 2) * wd
        + body.J.sum() * (wd + acceleration))
    np.testing.assert_allclose(got[10:13], w_dot, rtol=0, atol=bound)
    np.testing.assert_allclose(got[13:], acceleration, rtol=0, atol=bound + 4 * EPS * (wd + acceleration))


# ---------------------------------------------------------------- 7. bad input
GOOD_WHEEL = ([0.0, 0.0, 1.0], 0.5)


@pytest.mark.parametrize("args, match", [
    ((0.0, [1.0, 2.0, 3.0], []), r"mass > 0 \[kg\], got 0.0"),
    ((-1.0, [1.0, 2.0, 3.0], []), r"mass > 0 \[kg\], got -1.0"),
    ((np.nan, [1.0, 2.0, 3.0], []), "finite mass"),
    ((1.0, [1.0, np.inf, 3.0], []), "finite inertia_com"),
    ((1.0, [[1.0, 0.5, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]], []), "symmetric inertia_com"),
    ((1.0, [1.0, -2.0, 3.0], []), "positive definite inertia_com"),
    ((1.0, np.eye(2), []), r"inertia_com of shape \(3,\) or \(3, 3\)"),
    ((1.0, [1.0, 2.0, 3.0], [GOOD_WHEEL, ([0.0, 0.0, 0.0], 0.5)]), r"nonzero wheels\[1\] axis_B"),
    ((1.0, [1.0, 2.0, 3.0], [([np.nan, 0.0, 1.0], 0.5)]), r"finite wheels\[0\] axis_B"),
    ((1.0, [1.0, 2.0, 3.0], [([1.0, 0.0], 0.5)]), r"wheels\[0\] axis_B of shape \(3,\)"),
    ((1.0, [1.0, 2.0, 3.0], [([1.0, 0.0, 0.0], 0.0)]), r"wheels\[0\] J > 0 \[kg m²\], got 0.0"),
    ((1.0, [1.0, 2.0, 3.0], [([1.0, 0.0, 0.0], -0.1)]), r"wheels\[0\] J > 0 \[kg m²\], got -0.1"),
    ((1.0, [1.0, 2.0, 3.0], [([1.0, 0.0, 0.0], np.inf)]), r"finite wheels\[0\] J"),
    # A_xx = 1 − 1 = 0: singular; then two wheels that together exceed I_zz = 3 along z
    ((1.0, [1.0, 2.0, 3.0], [([1.0, 0.0, 0.0], 1.0)]), r"wheels\[0\] \(J = 1.0 kg m², axis \[1.0, 0.0, 0.0\]\) makes"),
    ((1.0, [1.0, 2.0, 3.0], [GOOD_WHEEL, ([0.0, 0.0, -2.0], 2.75)]), r"wheels\[1\] .* not positive definite"),
])
def test_bad_bodies_are_refused_naming_the_value(args, match):
    with pytest.raises(ValueError, match=match):
        gy.gyrostat(*args)


def test_bad_states_and_steps_are_refused():
    """A state of the wrong length or with a non-finite entry, or a step that is not finite and > 0, is refused
    before a step."""
    body, y0 = tumbling_gyrostat()
    with pytest.raises(ValueError, match=r"expected a state of shape \(16,\), got shape \(15,\)"):
        gy.rk4_step(body, 0.0, y0[:-1], 0.01)
    bad = y0.copy()
    bad[11] = np.nan
    with pytest.raises(ValueError, match="expected a finite state"):
        gy.rk4_run(body, bad, 0.01, 3)
    for h in (0.0, -0.01, np.nan, np.inf):
        with pytest.raises(ValueError, match=r"expected a finite step h > 0 \[s\]"):
            gy.rk4_step(body, 0.0, y0, h)
