"""Scenes against exact solutions (rigiddyn_ref.scene_exact): the Kepler orbit (period and energy to 1e-9
over 10 orbits with RK4), the gravity-gradient pitch libration of a satellite on a circular orbit
(frequency within 0.1 %), the linear spring–damper chain (closed form exp(A t) x0) and the free particle.
The exact solutions themselves are checked first (Kepler's equation, scipy's expm, the reference's RK4)."""

import numpy as np
import pytest
import scipy.linalg

import rigiddyn as rd
from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import scene as ref
from rigiddyn_ref import scene_exact as exact
from rigiddyn_ref import so3

from _scene_core import EPS, run


# ---------------------------------------------------------------- the exact solutions
def test_kepler_state_satisfies_keplers_equation_and_the_energy():
    """kepler_state at random times: the osculating elements give back a, e, M = n t and the energy
    −μm/(2a), to 1e-13 (Newton's iteration converges to round-off; a dozen operations each)."""
    gm, a, e = 3.986004418e14, 2.0e7, 0.5
    n = np.sqrt(gm / a ** 3)
    for t in np.random.default_rng(1).uniform(0, exact.kepler_period(gm, a), 20):
        p, v = exact.kepler_state(gm, a, e, t)
        a_got, e_vec, M = exact.osculating_elements(gm, p, v)
        assert a_got == pytest.approx(a, rel=1e-13)
        np.testing.assert_allclose(e_vec, [e, 0, 0], rtol=0, atol=1e-13)
        assert np.remainder(M - n * t + np.pi, 2 * np.pi) - np.pi == pytest.approx(0, abs=1e-12)
        assert 0.5 * v @ v - gm / np.linalg.norm(p) == pytest.approx(exact.kepler_energy(gm, a, 1.0), rel=1e-13)


def test_linear_flow_matches_scipy_expm_and_rk4_transfer_is_the_reference_rk4_step():
    """The chain's closed form by eigen-decomposition equals scipy.linalg.expm(A t) x0 to 1e-12 (cond(V)
    eps amplification, cond ~ 10 here); the reference's scene RK4 step equals (Σ_{k≤4}(hA)^k/k!) x0
    to round-off (64 eps of the state)."""
    n, m, k, c = 4, 1.3, 4.0, 0.3
    A = exact.chain_matrix(n, m, k, c)
    x0 = np.random.default_rng(2).uniform(-0.2, 0.2, 2 * n)
    for t in (0.1, 1.0, 7.5):
        np.testing.assert_allclose(exact.linear_flow(A, x0, t), scipy.linalg.expm(A * t) @ x0, rtol=0, atol=1e-12)
    scene, y0 = chain_scene(n, m, k, c, x0)
    h = 0.05
    y1 = ref.rk4_step(scene, y0, h)
    np.testing.assert_allclose(chain_coordinates(y1, n), exact.rk4_transfer(A, h) @ x0, rtol=0, atol=64 * EPS * n)


def test_reference_rk4_converges_to_the_kepler_orbit_at_fourth_order():
    """The reference scene (point-mass gravity on a particle, rigiddyn_ref.scene.rk4_run) over one orbit
    (a = 1, e = 0.5, μ = 1) against kepler_state at the end: halving dt from T/200 to T/400 divides the
    error by ≥ 12 (16 expected: 4th order) and the error at T/400 is ≤ 1e-5 a (RK4's C h⁴ measured by the
    two runs: |e(h)| ≤ |e(2h) − e(h)|/15 × 2)."""
    gm, a, e = 1.0, 1.0, 0.5
    period = exact.kepler_period(gm, a)
    p0, v0 = exact.kepler_state(gm, a, e, 0.3)
    scene = ref.Scene([ref.particle(1.0)], [ref.Element("PointMassGravity", dict(gm=gm, p_W=np.zeros(3)))])
    y0 = ref.initial_state(scene, [ref.Kinematics(p0, ref.IDENTITY, v0, np.zeros(3))])
    p1, v1 = exact.kepler_state(gm, a, e, 0.3 + period)
    errors = []
    for n in (200, 400):
        y = ref.rk4_run(scene, y0, period / n, n)[-1]
        errors.append(np.max(np.abs(np.concatenate([y[0:3] - p1, y[3:6] - v1]))))
    assert errors[0] >= 12 * errors[1]
    assert errors[1] <= 2 * abs(errors[0] - errors[1]) / 15 <= 1e-5


# ---------------------------------------------------------------- free particle
@pytest.mark.parametrize("method", [m["name"] for m in rd.methods() if m["name"] != "exact"])
def test_free_particles_and_free_bodies_move_on_straight_lines(method):
    """No element: p(t) = p0 + v0 t, v constant (law of inertia) for every method ('exact' takes one body
    only: refused for this three-body scene with a ValueError naming the method). Each step adds h v to p
    (rounding ≤ 2 eps (|p| + h|v|) per side, a composition of s ≤ 3 substeps rounds s times): after N steps
    |p − p_exact| ≤ N × 6 eps × max |p|, and the exact p0 + v0 t rounds once more."""
    rng = np.random.default_rng(3)
    scene = ref.Scene([ref.particle(2.0), ref.rigid(3.0, [1.0, 2.0, 2.5]), ref.planar(1.5, 0.4)], [])
    kin = [ref.Kinematics(rng.uniform(-5, 5, 3), ref.IDENTITY, rng.uniform(-2, 2, 3), np.zeros(3)),
           ref.Kinematics(rng.uniform(-5, 5, 3), so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-2, 2, 3),
                          rng.uniform(-1, 1, 3)),
           ref.Kinematics(np.append(rng.uniform(-5, 5, 2), 0), ref.rz_quat(0.3), np.append(rng.uniform(-2, 2, 2), 0),
                          np.array([0, 0, 0.7]))]
    y0 = ref.initial_state(scene, kin)
    steps, dt = 500, 0.01
    result = run(scene, y0, dt, steps, method=method)
    for b, k in enumerate(kin):
        p, v = exact.free_particle(k.p_W, k.v_W, result.t[:, None])
        scale = np.max(np.abs(p))
        np.testing.assert_allclose(result.p_W[:, b], p, rtol=0, atol=(steps * 6 + 1) * EPS * scale)
        np.testing.assert_allclose(result.v_W[:, b], np.broadcast_to(v, p.shape), rtol=0,
                                   atol=steps * 6 * EPS * np.max(np.abs(v)))


# ---------------------------------------------------------------- Kepler
GM_EARTH = 3.986004418e14


def kepler_run(steps_per_orbit, orbits, gm=GM_EARTH, a=2.0e7, e=0.5, mass=1000.0):
    """A particle on the orbit (a, e) about a fixed attractor at W's origin, from its pericentre, RK4 with
    dt = T/steps_per_orbit; returns (result, T)."""
    period = exact.kepler_period(gm, a)
    p, v = exact.kepler_state(gm, a, e, 0.0)
    scene = ref.Scene([ref.particle(mass)], [ref.Element("PointMassGravity", dict(gm=gm, p_W=np.zeros(3)))])
    y0 = ref.initial_state(scene, [ref.Kinematics(p, ref.IDENTITY, v, np.zeros(3))])
    return run(scene, y0, period / steps_per_orbit, steps_per_orbit * orbits, record_every=steps_per_orbit), period


def measured_period(result, orbits, gm=GM_EARTH):
    """The period from the run: t_end × 2π/(total mean anomaly), the mean anomaly of the osculating orbit
    of the last record unwrapped by the `orbits` whole turns."""
    _, _, M0 = exact.osculating_elements(gm, result.p_W[0, 0], result.v_W[0, 0])
    _, _, M1 = exact.osculating_elements(gm, result.p_W[-1, 0], result.v_W[-1, 0])
    turned = 2 * np.pi * orbits + np.remainder(M1 - M0 + np.pi, 2 * np.pi) - np.pi
    return (result.t[-1] - result.t[0]) * 2 * np.pi / turned


def assert_within_rk4_bound(fine, coarse, steps, requirement):
    """fine, coarse: errors (each a non-negative figure: relative period error, …) of runs at h and 2h.
    RK4's global error is C h^p with p ≥ 4 (one constant C for the run: the asymptotic regime, checked by
    the ratio), so the run at 2h errs 2^p − 1 ≥ 15 times more than the run at h beyond it, and
    |coarse − fine|/15 bounds the error at h (Richardson). Round-off: `steps` × 4 eps (each step's update
    rounds a few eps of the state's figures). Asserts that bound meets `requirement` (dt is small enough by
    RK4's own error bound), that the error at h does, and the order (ratio ≥ 8 for 16 expected)."""
    roundoff = steps * 4 * EPS
    for got, rough in zip(fine, coarse):
        assert abs(rough - got) / 15 + roundoff <= requirement
        assert got <= requirement
        assert rough >= 8 * got or got <= roundoff


def test_kepler_period_and_energy_to_1e9_over_ten_orbits_with_rk4():
    """Orbit a = 20000 km, e = 0.5 about GM_Earth (pericentre 10000 km), 10 orbits, RK4 with 3000 steps
    per orbit (dt = 9.4 s): the measured period (from the mean anomaly turned) and the energy at every
    orbit agree with 2π √(a³/GM) and −GMm/(2a) to 1e-9, and RK4's error bound at this dt (the run at
    1500 steps per orbit) is below 1e-9."""
    orbits, per_orbit = 10, 3000
    energy = exact.kepler_energy(GM_EARTH, 2.0e7, 1000.0)

    def errors(steps_per_orbit):
        result, period = kepler_run(steps_per_orbit, orbits)
        return (abs(measured_period(result, orbits) / period - 1),
                np.max(np.abs(result.total_energy / energy - 1)))

    assert_within_rk4_bound(errors(per_orbit), errors(per_orbit // 2), orbits * per_orbit, 1e-9)


def test_two_body_kepler_orbit_of_mutual_gravity():
    """Two bodies (m1 = 3, m2 = 1 kg, G = 1) attracting each other: the relative orbit is Kepler's with
    μ = G (m1 + m2) and the energy −G m1 m2/(2a) (plus the centre of mass's and the spin's kinetic energy).
    Over 2 orbits of RK4 with 4000 steps each, the period and the energy agree to 1e-9 and the relative
    position returns to its start to 1e-9 a, each within RK4's error bound (the run at 2000 steps per orbit,
    assert_within_rk4_bound)."""
    G, m1, m2, a, e = 1.0, 3.0, 1.0, 1.0, 0.3
    mu = G * (m1 + m2)
    p, v = exact.kepler_state(mu, a, e, 0.0)   # relative motion p = p1 − p2
    cm_v = np.array([0.1, -0.2, 0.05])
    scene = ref.Scene([ref.particle(m1), ref.rigid(m2, [0.1, 0.2, 0.25])], [ref.Element("MutualGravity", dict(G=G))])
    kin = [ref.Kinematics(m2 / (m1 + m2) * p, ref.IDENTITY, cm_v + m2 / (m1 + m2) * v, np.zeros(3)),
           ref.Kinematics(-m1 / (m1 + m2) * p, ref.IDENTITY, cm_v - m1 / (m1 + m2) * v, np.array([0.0, 0.0, 0.3]))]
    y0 = ref.initial_state(scene, kin)
    period, orbits = exact.kepler_period(mu, a), 2
    # the orbit's energy plus the centre of mass's ½ M v_cm² and the second body's spin ½ ω·I ω
    energy = -G * m1 * m2 / (2 * a) + 0.5 * (m1 + m2) * cm_v @ cm_v + 0.5 * 0.25 * 0.3 ** 2

    def errors(per_orbit):
        result = run(scene, y0, period / per_orbit, orbits * per_orbit, record_every=per_orbit)
        relative_p = result.p_W[:, 0] - result.p_W[:, 1]
        relative_v = result.v_W[:, 0] - result.v_W[:, 1]
        _, _, M0 = exact.osculating_elements(mu, relative_p[0], relative_v[0])
        _, _, M1 = exact.osculating_elements(mu, relative_p[-1], relative_v[-1])
        turned = 2 * np.pi * orbits + np.remainder(M1 - M0 + np.pi, 2 * np.pi) - np.pi
        return (abs(result.t[-1] * 2 * np.pi / turned / period - 1),
                np.max(np.abs(result.total_energy / energy - 1)),
                np.max(np.abs(relative_p[-1] - p)) / a)

    assert_within_rk4_bound(errors(4000), errors(2000), orbits * 4000, 1e-9)


# ---------------------------------------------------------------- pitch libration
def test_gravity_gradient_pitch_libration_frequency_within_a_tenth_of_a_percent():
    """A satellite (500 kg, I = diag(300, 250, 100) kg m²) on a circular orbit of radius 7000 km about
    GM_Earth, body y along the orbit normal, z to nadir, pitched by 0.01 rad: its pitch angle oscillates at
    ω_lib = n √(3 (I_x − I_z)/I_y) (scene_exact.pitch_libration_frequency). The frequency is measured from
    the zero crossings of the recorded pitch angle over ~10 libration periods (linear interpolation between
    records of 10 s: error O((ω dt)² dt) per crossing ~ 1e-4 s of a 3764 s period). Error budget of the
    0.1 % tolerance: the amplitude's nonlinear shift (2θ0)²/16 = 2.5e-5, the orbit's perturbation by
    the gradient force I/(m R²) ~ 1e-14, RK4's phase error (ω dt)⁴ ~ 1e-7."""
    gm, radius, mass, inertia = GM_EARTH, 7.0e6, 500.0, np.array([300.0, 250.0, 100.0])
    n = exact.circular_mean_motion(gm, radius)
    omega = exact.pitch_libration_frequency(n, *inertia)
    # at t = 0: p = R x_W, v = n R y_W; B's columns in W: x_B = −y_W (along −track), y_B = z_W (normal),
    # z_B = −x_W (nadir); then pitched by θ0 about y_B; B turns with the orbit: w_B = (0, n, 0)
    R_WB = np.array([[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]) @ so3.rot_y(0.01)
    scene = ref.Scene([ref.rigid(mass, inertia)], [ref.Element("PointMassGravity", dict(gm=gm, p_W=np.zeros(3))),
                                                   ref.Element("GravityGradient", dict(gm=gm, p_W=np.zeros(3)))])
    kin = [ref.Kinematics(np.array([radius, 0, 0]), so3.matrix_to_quat(R_WB), np.array([0, n * radius, 0]),
                          np.array([0.0, n, 0.0]))]
    dt = 10.0
    steps = int(10 * 2 * np.pi / omega / dt)
    result = run(scene, ref.initial_state(scene, kin), dt, steps)
    z_B = so3.quat_rotate(result.q_WB[:, 0], np.array([0.0, 0.0, 1.0]))
    nadir = -result.p_W[:, 0] / np.linalg.norm(result.p_W[:, 0], axis=1, keepdims=True)
    pitch = np.arctan2(np.cross(z_B, nadir)[:, 2], np.sum(z_B * nadir, axis=1))
    i = np.nonzero(np.sign(pitch[:-1]) != np.sign(pitch[1:]))[0]
    crossings = result.t[i] - pitch[i] * (result.t[i + 1] - result.t[i]) / (pitch[i + 1] - pitch[i])
    assert len(crossings) >= 15
    measured = np.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0])   # half a period between crossings
    assert abs(measured / omega - 1) <= 1e-3   # the required accuracy of the linearised frequency
    # sharper: the pitch obeys φ̈ = −ω² sin φ with φ = 2θ (I_y θ̈ = −3n² (I_x − I_z) sin θ cos θ), a pendulum
    # of amplitude φ0 = 0.02 whose frequency is ω (1 − φ0²/16 + O(φ0⁴ 11/3072 ≈ 6e-10)); the rest of the
    # budget above (interpolation ~2e-8, RK4 ~1e-7, the orbit's perturbation 1e-14) stays below 1e-6
    assert abs(measured / omega - (1 - 0.02 ** 2 / 16)) <= 1e-6


# ---------------------------------------------------------------- spring–damper chain
def chain_scene(n, mass, stiffness, damping, x0, spacing=1.0):
    """n particles of `mass` on W's x axis at rest positions i × spacing (i = 1..n), the first tied to a wall
    anchor at the origin, each to the next, by springs of rest length `spacing` in parallel with dampers;
    displaced by x0 = (u, u̇) along x. While the particles keep their order the law is exactly linear:
    f on a = −(k (ℓ − ℓ0) + c ℓ̇) x̂."""
    spring = dict(stiffness=stiffness, rest_length=spacing, damping=damping, point_a_B=np.zeros(3),
                  point_b=np.zeros(3))
    elements = [ref.Element("SpringDamper", dict(spring, body_a=0, body_b=-1))]
    elements += [ref.Element("SpringDamper", dict(spring, body_a=i + 1, body_b=i)) for i in range(n - 1)]
    scene = ref.Scene([ref.particle(mass) for _ in range(n)], elements)
    x_axis = np.array([1.0, 0.0, 0.0])
    kin = [ref.Kinematics((i + 1) * spacing * x_axis + x0[i] * x_axis, ref.IDENTITY, x0[n + i] * x_axis, np.zeros(3))
           for i in range(n)]
    return scene, ref.initial_state(scene, kin)


def chain_coordinates(y, n, spacing=1.0):
    """(u, u̇) of the chain from a reference state y (x coordinates minus the rest positions)."""
    s = np.asarray(y)[:6 * n].reshape(n, 6)
    return np.concatenate([s[:, 0] - spacing * np.arange(1, n + 1), s[:, 3]])


def test_spring_damper_chain_against_its_closed_form():
    """Four 1.3 kg masses, k = 4 N/m, c = 0.3 N s/m, 1000 RK4 steps of 0.01 s. RK4 on ẋ = A x is exactly
    x_{N} = P^N x0 with P = Σ_{k≤4} (hA)^k/k! (scene_exact.rk4_transfer), so
    (1) the core equals P^N x0 to round-off: each step rounds ≤ 16 eps of max |x| (the reference's step
        bound), carried by ‖P^k‖ ≤ cond(V) (V the eigenvectors of A; |eigenvalues of P| ≤ 1: damped), so
        ≤ N × 16 eps × cond(V) × max|x| (+ 16 eps of the rest positions, ~n m, that the coordinates carry);
    (2) the core equals the closed form exp(A t) x0 within RK4's exact truncation error |P^N x0 − exp(ANh) x0|
        plus that round-off."""
    n, mass, k, c, h, steps = 4, 1.3, 4.0, 0.3, 0.01, 1000
    A = exact.chain_matrix(n, mass, k, c)
    x0 = np.random.default_rng(4).uniform(-0.2, 0.2, 2 * n)
    scene, y0 = chain_scene(n, mass, k, c, x0)
    result = run(scene, y0, h, steps, record_every=100)
    P = exact.rk4_transfer(A, h)
    condition = np.linalg.cond(np.linalg.eig(A)[1])
    for i, t in enumerate(result.t):
        i_step = int(round(t / h))
        got = np.concatenate([result.p_W[i, :, 0] - np.arange(1, n + 1), result.v_W[i, :, 0]])
        rk4 = np.linalg.matrix_power(P, i_step) @ x0
        closed = exact.linear_flow(A, x0, t)
        roundoff = (i_step + 1) * 16 * EPS * condition * max(n + 1.0, np.max(np.abs(x0)))
        np.testing.assert_allclose(got, rk4, rtol=0, atol=roundoff)
        # RK4's truncation on ẋ = A x, a priori: |exp(hA) − P| ≤ (h‖A‖)⁵/5! e^{h‖A‖} per step (the Taylor
        # remainder), carried by ‖exp(kAh)‖, ‖P^k‖ ≤ cond(V): |P^N x0 − exp(ANh) x0| ≤ N cond(V)² (that) |x0|
        norm_hA = h * np.linalg.norm(A, 2)
        truncation = i_step * condition ** 2 * norm_hA ** 5 / 120 * np.exp(norm_hA) * np.linalg.norm(x0)
        assert np.max(np.abs(rk4 - closed)) <= truncation + 1e-15
        np.testing.assert_allclose(got, closed, rtol=0, atol=truncation + roundoff)
    assert np.all(result.p_W[:, :, 1:] == 0.0)  # no force across the line: y and z stay exactly zero


# ---------------------------------------------------------------- scheduled loads switching inside steps
def piecewise_constant_motion(p0, v0, accelerations, t):
    """p(t), v(t) under the accelerations [(t_start, t_end, a)] (piecewise constant, summed where they
    overlap): v = v0 + Σ a × |[t_start, t_end) ∩ [0, t)|, p = p0 + v0 t + Σ a × ∫_0^t |[t_start, t_end) ∩ [0, s)| ds,
    the inner integral of a ramp: (s − t_start) on the window, the window's length after it."""
    p, v = np.array(p0, float) + np.asarray(v0, float) * t, np.array(v0, float)
    for t_start, t_end, a in accelerations:
        on = np.clip(t, t_start, t_end) - t_start              # time spent in the window up to t
        v = v + on * np.asarray(a)
        p = p + (0.5 * on ** 2 + on * max(0.0, t - t_end) if t >= t_start else 0.0) * np.asarray(a)
    return p, v


@pytest.mark.parametrize("method", ["rk4", "rkmk4", "splitting_dlm", "splitting_dlm_yoshida4"])
def test_schedules_switching_inside_steps_give_the_exact_piecewise_motion(method):
    """A particle and a rigid body under world forces at their centres of mass switching on and off inside
    steps (t = 0.013, 0.0371, 0.05 s; dt = 0.01 s): the core splits a step at each switch time, and on each
    piece these methods integrate a constant force exactly (RK4 and RKMK4: a quadratic polynomial; the
    splittings: kick h/2 · drift h · kick h/2 is the exact flow under a constant force). So p and v equal
    the piecewise-quadratic motion to round-off: ≤ 3 pieces per step, each rounding ≤ 8 eps of max(|p|, |v|,
    1) per substep (3 substeps for Yoshida's jump): bound n_steps × 3 × 3 × 8 eps × that scale."""
    loads_0 = [dyn.Load([1.0, -2.0, 0.5], [0, 0, 0], "world", 0.013, 0.05),
               dyn.Load([0.0, 0.7, 0.0], [0, 0, 0], "world", 0.0371, np.inf)]
    loads_1 = [dyn.Load([-0.4, 0.3, 1.2], [0, 0, 0], "world", -np.inf, 0.0371)]
    scene = ref.Scene([ref.particle(2.0), ref.rigid(0.5, [0.1, 0.2, 0.25])],
                      [ref.Element("ScheduledLoads", dict(body=0, loads=loads_0)),
                       ref.Element("ScheduledLoads", dict(body=1, loads=loads_1))])
    kin = [ref.Kinematics(np.array([1.0, 2.0, 3.0]), ref.IDENTITY, np.array([0.5, -0.2, 0.1]), np.zeros(3)),
           ref.Kinematics(np.array([-1.0, 0.5, 0.0]), so3.rotvec_to_quat([0.2, 0.1, -0.3]), np.array([0.0, 0.3, 0.0]),
                          np.zeros(3))]
    steps, dt = 8, 0.01
    result = run(scene, ref.initial_state(scene, kin), dt, steps, method=method)
    masses = (2.0, 0.5)
    for b, loads in enumerate((loads_0, loads_1)):
        accelerations = [(max(load.t_start, 0.0), load.t_end, np.asarray(load.force) / masses[b]) for load in loads]
        for i, t in enumerate(result.t):
            p, v = piecewise_constant_motion(kin[b].p_W, kin[b].v_W, accelerations, t)
            scale = max(1.0, np.max(np.abs(p)), np.max(np.abs(v)))
            np.testing.assert_allclose(result.p_W[i, b], p, rtol=0, atol=steps * 72 * EPS * scale)
            np.testing.assert_allclose(result.v_W[i, b], v, rtol=0, atol=steps * 72 * EPS * scale)
