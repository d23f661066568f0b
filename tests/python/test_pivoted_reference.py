"""Bodies about a fixed point: the numpy reference (rigiddyn_ref.pivoted) checked against itself (the parallel-axis
theorem against the inertia of a point cloud, Euler about O against Newton–Euler about C with the pivot's reaction
as an unknown), then rigiddyn's PivotedBody / PivotedPlanarBody against it on random inputs: the inertia about O,
forward and inverse dynamics, the records at t0 and one RK4 step."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigiddyn as rd

from rigiddyn_ref import pivoted as ref
from rigiddyn_ref import so3

EPS = np.finfo(float).eps
settings.register_profile("pivoted_reference", max_examples=20, deadline=None)
seeds = st.integers(0, 2 ** 32 - 1)


def box_moments(mass, dims):
    """Principal moments of a solid box m (b² + c²)/12, ...: they satisfy the triangle inequality."""
    a, b, c = np.square(dims)
    return mass / 12.0 * np.array([b + c, a + c, a + b])


def random_pivoted(rng):
    """(mass [kg], I_C (3, 3) full [kg m²], c = p_OC_B [m], q_WB, w_B [rad/s]): masses 0.5–3 kg, box inertias of
    sides 0.5–2 m turned at random (condition ≤ 16), |c| 0.1–1 m, spins ≤ 3 rad/s."""
    mass = rng.uniform(0.5, 3.0)
    turn = so3.rotvec_to_matrix(rng.normal(size=3))
    inertia = turn @ np.diag(box_moments(mass, rng.uniform(0.5, 2.0, 3))) @ turn.T
    c = rng.normal(size=3)
    c *= rng.uniform(0.1, 1.0) / np.linalg.norm(c)
    return mass, inertia, c, so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-3, 3, 3)


def core_body(mass, inertia, c, p_WO=(0.0, 0.0, 0.0)):
    return rd.PivotedBody(rd.RigidBody(mass, inertia), c, p_WO)


def acceleration_tolerance(inertia_O, terms):
    """|Δα| between two evaluations of α = I_O⁻¹ (τ_O − ω × I_O ω): each side rounds the moment's terms (≤ 16
    roundings on numbers ≤ `terms` [N m], Higham's γ_n) and the solve turns a relative error into κ(I_O) times it
    (Higham, Thm 7.2, backward-stable solve): 2 sides × 16 eps κ ‖I_O⁻¹‖ terms."""
    return 2 * 16 * EPS * np.linalg.cond(inertia_O) * np.linalg.norm(np.linalg.inv(inertia_O), 2) * terms


def moment_terms(inertia_O, c, f, tau, w):
    """|τ| + |c| |f| + |ω| ‖I_O‖ |ω|: the magnitude of the terms of τ_O − ω × I_O ω [N m]."""
    return (np.linalg.norm(tau) + np.linalg.norm(c) * np.linalg.norm(f)
            + np.linalg.norm(w) ** 2 * np.linalg.norm(inertia_O, 2))


# ---------------------------------------------------------------- the reference against itself
@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_reference_parallel_axis_equals_the_inertia_of_the_shifted_point_cloud(seed):
    """I_O = I_C + m (|c|² 1 − c cᵀ) against Σ m_i (|ρ_i + c|² 1 − (ρ_i + c)(ρ_i + c)ᵀ) over a cloud with the body's
    mass, centre of mass and I_C (points from O at c + ρ_i: the centre of mass at c). Both sums round ≤ 16 times on
    numbers ≤ ‖I_O‖ + m |c|² (γ_16)."""
    mass, inertia, c, _, _ = random_pivoted(np.random.default_rng(seed))
    masses, rho = ref.point_cloud(mass, inertia)
    np.testing.assert_allclose(ref.inertia_of_points(masses, rho), inertia, rtol=0,
                               atol=2 * 16 * EPS * np.linalg.norm(inertia, 2))
    scale = np.linalg.norm(inertia, 2) + mass * c @ c
    np.testing.assert_allclose(ref.inertia_of_points(masses, rho + c), ref.inertia_about_pivot(mass, inertia, c),
                               rtol=0, atol=2 * 16 * EPS * scale)


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_reference_euler_about_o_equals_newton_euler_about_c_with_the_reaction(seed):
    """Euler about O (α, then R = m a_C − f) against the 6 × 6 solve of Newton and Euler about C with R unknown
    and a_O = 0: the same motion. The 6 × 6 system's condition bounds its solve's error (κ₆ eps per side); α's
    terms as acceleration_tolerance; R's as m |c| |Δα| plus its own 16 roundings of m |a_C| + |f|."""
    rng = np.random.default_rng(seed)
    mass, inertia, c, q, w = random_pivoted(rng)
    f, tau = rng.uniform(-10, 10, 3), rng.uniform(-3, 3, 3)
    alpha = ref.angular_acceleration(mass, inertia, c, q, w, f, tau)
    reaction = ref.pivot_reaction_W(mass, c, q, w, alpha, f)
    alpha2, reaction2 = ref.constrained_newton_euler(mass, inertia, c, q, w, f, tau)
    inertia_O = ref.inertia_about_pivot(mass, inertia, c)
    hat_c = so3.hat(c)
    A = np.block([[-mass * hat_c, -np.eye(3)], [inertia, hat_c]])
    kappa6 = np.linalg.cond(A)
    terms = moment_terms(inertia_O, c, f, tau, w)
    tol_alpha = acceleration_tolerance(inertia_O, terms) + 2 * 16 * EPS * kappa6 * np.linalg.norm(alpha2)
    np.testing.assert_allclose(alpha2, alpha, rtol=0, atol=tol_alpha)
    a_C = mass * (np.linalg.norm(alpha) + np.linalg.norm(w) ** 2) * np.linalg.norm(c)
    tol_R = mass * np.linalg.norm(c) * tol_alpha + 2 * 16 * EPS * (kappa6 * np.linalg.norm(reaction2) + a_C
                                                                   + np.linalg.norm(f))
    np.testing.assert_allclose(reaction2, reaction, rtol=0, atol=tol_R)


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_reference_inverse_dynamics_undoes_forward_dynamics(seed):
    """α from forward dynamics under gravity and a couple τ; inverse dynamics returns τ and the same reaction.
    τ = I_O α + ω × I_O ω − c × m g rounds on its terms (≤ ‖I_O‖ |α| + the moment's terms), the α it starts from
    carries acceleration_tolerance, so |Δτ| ≤ ‖I_O‖ tol_α + 2 × 16 eps (terms)."""
    rng = np.random.default_rng(seed)
    mass, inertia, c, q, w = random_pivoted(rng)
    g, tau = rng.uniform(-10, 10, 3), rng.uniform(-3, 3, 3)
    alpha = ref.angular_acceleration(mass, inertia, c, q, w, mass * g, tau)
    tau_back, reaction = ref.inverse_dynamics(mass, inertia, c, q, w, alpha, g)
    inertia_O = ref.inertia_about_pivot(mass, inertia, c)
    terms = moment_terms(inertia_O, c, mass * g, tau, w) + np.linalg.norm(inertia_O, 2) * np.linalg.norm(alpha)
    tol = np.linalg.norm(inertia_O, 2) * acceleration_tolerance(inertia_O, terms) + 2 * 16 * EPS * terms
    np.testing.assert_allclose(tau_back, tau, rtol=0, atol=tol)
    np.testing.assert_array_equal(reaction, ref.pivot_reaction_W(mass, c, q, w, alpha, mass * g))


def test_reference_compound_pendulum_small_oscillation_frequency():
    """Linearised about the stable equilibrium, the planar rate gives θ̈ = −(m g d / I_O) θ: the reference's rate at
    θ = 1e-6 rad from it divided by −θ is ω0² = m g d/(I_zz + m d²) to the linearisation's relative θ²/6 ≈ 2e-13
    (sin θ = θ (1 − θ²/6)) plus round-off."""
    mass, inertia_zz, c = 2.0, 0.3, np.array([0.0, -0.4])   # C below O: stable at θ = 0 under g = (0, −9.81)
    theta = 1e-6
    rate = ref.planar_rate(mass, inertia_zz, c, [0.0, -9.81], np.array([theta, 0.0]))
    omega0_sq = mass * 9.81 * 0.4 / (inertia_zz + mass * 0.16)
    assert -rate[1] / theta == pytest.approx(omega0_sq, rel=theta ** 2 / 6 + 64 * EPS)


# ---------------------------------------------------------------- rigiddyn against the reference
@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_inertia_about_pivot_and_digits_lost_match_the_reference(seed):
    """PivotedBody.inertia_O is I_C + m (|c|² 1 − c cᵀ) (same formula both sides: 8 roundings each on ≤ ‖I_C‖ +
    m|c|²) and digits_lost = max(0, log10(m|c|²/λ_min(I_C))) (eigenvalues to κ eps relative: 1e-12 absolute on a
    log10 of numbers well conditioned here is loose by orders)."""
    mass, inertia, c, _, _ = random_pivoted(np.random.default_rng(seed))
    body = core_body(mass, inertia, c)
    scale = np.linalg.norm(inertia, 2) + mass * c @ c
    np.testing.assert_allclose(body.inertia_O, ref.inertia_about_pivot(mass, inertia, c), rtol=0,
                               atol=2 * 8 * EPS * scale)
    lost = max(0.0, np.log10(mass * c @ c / np.linalg.eigvalsh(inertia)[0]))
    assert body.digits_lost == pytest.approx(lost, abs=1e-12)
    assert body.mass == mass
    np.testing.assert_array_equal(body.p_OC_B, c)


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_forward_and_inverse_dynamics_match_the_reference(seed):
    """forward_dynamics(PivotedBody, ...) under gravity, a force at a point and a couple (world frame) against the
    reference (the force at p_CP reduced to C: f and the couple p_CP × f, all given in W); inverse_dynamics against
    the reference's.
    Tolerances: acceleration_tolerance on α, m |c| tol_α + 16-rounding bound on the reaction; τ as
    test_reference_inverse_dynamics_undoes_forward_dynamics."""
    rng = np.random.default_rng(seed)
    mass, inertia, c, q, w = random_pivoted(rng)
    g, force = rng.uniform(-10, 10, 3), rng.uniform(-5, 5, 3)
    torque, point = rng.uniform(-3, 3, 3), rng.uniform(-1, 1, 3)
    body, state = core_body(mass, inertia, c), rd.PivotedBodyState(q_WB=q, w_B=w)
    alpha_core, reaction_core = rd.forward_dynamics(body, state, force=force, torque=torque, point=point,
                                                    frame="world", gravity=g)
    tau_B = so3.quat_to_matrix(q).T @ (torque + np.cross(point, force))  # point, force, torque all in W (frame)
    f_W = force + mass * g
    alpha = ref.angular_acceleration(mass, inertia, c, q, w, f_W, tau_B)
    reaction = ref.pivot_reaction_W(mass, c, q, w, alpha, f_W)
    inertia_O = ref.inertia_about_pivot(mass, inertia, c)
    terms = moment_terms(inertia_O, c, f_W, tau_B, w) + np.linalg.norm(point) * np.linalg.norm(force)
    tol_alpha = acceleration_tolerance(inertia_O, terms)
    np.testing.assert_allclose(alpha_core, alpha, rtol=0, atol=tol_alpha)
    a_C = mass * (np.linalg.norm(alpha) + np.linalg.norm(w) ** 2) * np.linalg.norm(c)
    np.testing.assert_allclose(reaction_core, reaction, rtol=0,
                               atol=mass * np.linalg.norm(c) * tol_alpha + 2 * 16 * EPS * (a_C + np.linalg.norm(f_W)))
    tau_core, reaction_inv = rd.inverse_dynamics(body, state, alpha_B=alpha, gravity=g)
    tau_ref, reaction_ref = ref.inverse_dynamics(mass, inertia, c, q, w, alpha, g)
    terms_inv = moment_terms(inertia_O, c, mass * g, 0.0 * w, w) + np.linalg.norm(inertia_O, 2) * np.linalg.norm(alpha)
    np.testing.assert_allclose(tau_core, tau_ref, rtol=0, atol=2 * 16 * EPS * terms_inv)
    np.testing.assert_allclose(reaction_inv, reaction_ref, rtol=0, atol=2 * 16 * EPS * (a_C + mass * np.linalg.norm(g)))


def rk4_tolerance(inertia_O, y0, y1):
    """One RK4 step, core vs reference, from the same y0: per side 16 eps κ(I_O) per stage of max(1, |y0|, |Δy|),
    grown ≤ e over the four stages (h ‖∂ẏ/∂y‖ ≤ 1 here: h = 0.01 s, rates ≲ 30 /s); two sides."""
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(y1 - y0)))
    return 2 * 16 * EPS * np.linalg.cond(inertia_O) * np.e * size


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_rk4_step_and_records_match_the_reference(seed):
    """simulate(PivotedBody, ..., gravity=g, method='rk4') for one step of 0.01 s against the reference's RK4 step on
    (q_WB, w_B) (rk4_tolerance), and the records at t0: the centre of mass p_WO + R c, the pivot reaction, H_O and
    the kinetic and potential energies (same formulas both sides: 16 roundings on the terms' magnitudes)."""
    rng = np.random.default_rng(seed)
    mass, inertia, c, q, w = random_pivoted(rng)
    g, p_WO = rng.uniform(-10, 10, 3), rng.uniform(-1, 1, 3)
    h = 0.01
    result = rd.simulate(core_body(mass, inertia, c, p_WO), rd.PivotedBodyState(q_WB=q, w_B=w), h, 1, method="rk4",
                         gravity=g)
    y0 = np.concatenate([q, w])
    want = ref.rk4_step(mass, inertia, c, g, y0, h)
    got = np.concatenate([result.q_WB[1, 0], result.w_B[1, 0]])
    if got[:4] @ want[:4] < 0:
        got[:4] *= -1
    inertia_O = ref.inertia_about_pivot(mass, inertia, c)
    np.testing.assert_allclose(got, want, rtol=0, atol=rk4_tolerance(inertia_O, y0, want))
    alpha = ref.angular_acceleration(mass, inertia, c, q, w, mass * g, np.zeros(3))
    size = np.linalg.norm(p_WO) + np.linalg.norm(c)
    np.testing.assert_allclose(result.p_W[0, 0], ref.centre_position_W(c, q, p_WO), rtol=0, atol=2 * 16 * EPS * size)
    terms = moment_terms(inertia_O, c, mass * g, np.zeros(3), w)
    tol_alpha = acceleration_tolerance(inertia_O, terms)
    a_C = mass * (np.linalg.norm(alpha) + np.linalg.norm(w) ** 2) * np.linalg.norm(c)
    np.testing.assert_allclose(result.pivot_reaction_W[0, 0], ref.pivot_reaction_W(mass, c, q, w, alpha, mass * g),
                               rtol=0, atol=mass * np.linalg.norm(c) * tol_alpha
                               + 2 * 16 * EPS * (a_C + mass * np.linalg.norm(g)))
    H = ref.angular_momentum_O_W(mass, inertia, c, q, w)
    np.testing.assert_allclose(result.angular_momentum_O_W[0, 0], H, rtol=0,
                               atol=2 * 16 * EPS * np.linalg.norm(inertia_O, 2) * np.linalg.norm(w))
    T = ref.kinetic_energy(mass, inertia, c, w)
    V = ref.potential_energy(mass, c, q, g, p_WO)
    assert abs(result.kinetic_energy[0] - T) <= 2 * 16 * EPS * np.linalg.norm(inertia_O, 2) * (w @ w)
    assert abs(result.potential_energy[0] - V) <= 2 * 16 * EPS * mass * np.linalg.norm(g) * size


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_compound_pendulum_matches_the_reference(seed):
    """PivotedPlanarBody: forward_dynamics (α, reaction) under gravity (2,), and one RK4 step of 0.01 s of (θ, ω),
    against the planar reference: α = (c_W × m g)_z / I_O,zz (a dozen roundings on m |g| |c|, divided by I_O,zz);
    RK4 as rk4_tolerance with κ = 1."""
    rng = np.random.default_rng(seed)
    mass, inertia_zz = rng.uniform(0.5, 3.0), rng.uniform(0.05, 1.0)
    c, p_WO, g = rng.uniform(-1, 1, 2), rng.uniform(-1, 1, 2), rng.uniform(-10, 10, 2)
    theta, omega = rng.uniform(-3, 3), rng.uniform(-3, 3)
    body, state = rd.PivotedPlanarBody(mass, inertia_zz, c, p_WO), rd.PivotedPlanarBodyState(theta=theta, omega=omega)
    alpha_core, reaction_core = rd.forward_dynamics(body, state, gravity=g)
    alpha = ref.planar_angular_acceleration(mass, inertia_zz, c, theta, mass * g)
    inertia_O = inertia_zz + mass * c @ c
    scale = mass * np.linalg.norm(g) * np.linalg.norm(c)
    tol_alpha = 2 * 16 * EPS * scale / inertia_O
    assert abs(alpha_core - alpha) <= tol_alpha
    reaction = ref.planar_reaction_W(mass, c, theta, omega, alpha, mass * g)
    np.testing.assert_allclose(np.asarray(reaction_core)[:2], reaction, rtol=0,
                               atol=mass * np.linalg.norm(c) * tol_alpha
                               + 2 * 16 * EPS * (mass * np.linalg.norm(c) * (abs(alpha) + omega ** 2) + scale))
    h = 0.01
    result = rd.simulate(body, state, h, 1, method="rk4", gravity=g)
    y0 = np.array([theta, omega])
    f = lambda y: ref.planar_rate(mass, inertia_zz, c, g, y)  # noqa: E731
    k1 = f(y0)
    k2 = f(y0 + h / 2 * k1)
    k3 = f(y0 + h / 2 * k2)
    k4 = f(y0 + h * k3)
    want = y0 + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    q = result.q_WB[1, 0]
    got_theta = 2 * np.arctan2(q[2], q[3])
    got_theta += 2 * np.pi * np.round((want[0] - got_theta) / (2 * np.pi))
    tol = rk4_tolerance(np.eye(3), y0, want) + 4 * EPS * max(1.0, abs(want[0]))  # + θ read back from Rz(θ) (atan2)
    assert abs(got_theta - want[0]) <= tol
    assert abs(result.w_B[1, 0, 2] - want[1]) <= tol


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_compound_pendulum_inverse_dynamics_matches_the_reference(seed):
    """inverse_dynamics(PivotedPlanarBody, state, alpha) under gravity: τ_O = I_O,zz α − (c_W × m g)_z (plane kinetics
    about O solved for the couple) and the reaction m a_C − m g, against the reference (16 roundings on the terms
    I_O |α| + m |g| |c| and m |c| (|α| + ω²) + m |g|)."""
    rng = np.random.default_rng(seed)
    mass, inertia_zz = rng.uniform(0.5, 3.0), rng.uniform(0.05, 1.0)
    c, g = rng.uniform(-1, 1, 2), rng.uniform(-10, 10, 2)
    theta, omega, alpha = rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-5, 5)
    body, state = rd.PivotedPlanarBody(mass, inertia_zz, c), rd.PivotedPlanarBodyState(theta=theta, omega=omega)
    tau_core, reaction_core = rd.inverse_dynamics(body, state, alpha_B=alpha, gravity=g)
    inertia_O = inertia_zz + mass * c @ c
    c_W = ref.planar_centre_W(c, theta)
    tau = inertia_O * alpha - (c_W[0] * mass * g[1] - c_W[1] * mass * g[0])
    assert abs(tau_core - tau) <= 2 * 16 * EPS * (inertia_O * abs(alpha) + mass * np.linalg.norm(g) * np.linalg.norm(c))
    reaction = ref.planar_reaction_W(mass, c, theta, omega, alpha, mass * g)
    np.testing.assert_allclose(np.asarray(reaction_core)[:2], reaction, rtol=0, atol=2 * 16 * EPS * mass * (
        np.linalg.norm(c) * (abs(alpha) + omega ** 2) + np.linalg.norm(g)))


@settings(settings.get_profile("pivoted_reference"))
@given(seed=seeds)
def test_core_step_is_one_step_of_simulate(seed):
    """rigiddyn.step(PivotedBody, state, dt, gravity=...) returns the state simulate records after one step (the same
    one-body scene and method; the run may take the fast one-body model and the step the generic scene, which round
    differently: rk4_tolerance)."""
    rng = np.random.default_rng(seed)
    mass, inertia, c, q, w = random_pivoted(rng)
    g = rng.uniform(-10, 10, 3)
    body, state = core_body(mass, inertia, c), rd.PivotedBodyState(q_WB=q, w_B=w)
    stepped = rd.step(body, state, 0.01, method="rk4", gravity=g)
    run = rd.simulate(body, state, 0.01, 1, method="rk4", gravity=g)
    y0, y1 = np.concatenate([q, w]), np.concatenate([run.q_WB[1, 0], run.w_B[1, 0]])
    tol = rk4_tolerance(ref.inertia_about_pivot(mass, inertia, c), y0, y1)
    np.testing.assert_allclose(np.concatenate([stepped.q_WB, stepped.w_B]), y1, rtol=0, atol=tol)
