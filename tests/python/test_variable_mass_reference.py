"""Variable mass: the numpy reference (rigiddyn_ref.variable_mass) checked against itself (momentum bookkeeping of
the Rigid-body notes' eq. (4.36), RK4 against the closed-form burn), then rigiddyn's MassFlow + Thrust against it on
random inputs: one RK4 step of a particle (constant rate, and a rate given as a function of t) and of a rigid body
whose inertia scales with its mass under a body-frame thrust off its centre of mass."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigiddyn as rd

from rigiddyn_ref import exact_dynamics as exact
from rigiddyn_ref import so3
from rigiddyn_ref import variable_mass as ref
from rigiddyn_ref.dynamics import quat_product

EPS = np.finfo(float).eps
settings.register_profile("variable_mass_reference", max_examples=15, deadline=None)
seeds = st.integers(0, 2 ** 32 - 1)


# ---------------------------------------------------------------- the reference against itself
@settings(settings.get_profile("variable_mass_reference"))
@given(seed=seeds)
def test_reference_momentum_bookkeeping_is_exact(seed):
    """d(m v)/dt = ṁ v + m v̇ equals f + ṁ (v + u_rel) (Rigid-body notes (4.36) with the exchanged mass's momentum):
    both sides round ≤ 8 times on |f| + |ṁ| (|v| + |u|)."""
    rng = np.random.default_rng(seed)
    m, mdot = rng.uniform(0.5, 5), rng.uniform(-2, 2)
    v, u, f = rng.uniform(-5, 5, 3), rng.uniform(-100, 100, 3), rng.uniform(-10, 10, 3)
    lhs = mdot * v + m * ref.acceleration(m, mdot, u, f)
    scale = np.linalg.norm(f) + abs(mdot) * (np.linalg.norm(v) + np.linalg.norm(u))
    np.testing.assert_allclose(lhs, ref.momentum_rate(m, mdot, v, u, f), rtol=0, atol=2 * 8 * EPS * scale)


def test_reference_rk4_burn_matches_the_closed_form_and_tsiolkovsky():
    """RK4 of the particle rate over a burn from 10 kg to 2 kg (ṁ = −1 kg/s, u = 300 m/s, g = −9.81 z) at h = 1e-3 s
    against constant_thrust: RK4's global error ≤ h⁴ max|d⁵v/dt⁵| t / 2880-type constants, d⁵v/dt⁵ = 24 |u| ṁ⁵/m⁵ ≤
    24 × 300/32 ≈ 225 m/s⁶ at m = 2 kg: ≤ 1e-12 × 225 × 8 ≈ 2e-9 m/s; 1e-8 relative to |v| ~ 500 m/s leaves room.
    With g = 0, |v(t1) − v0| = Δv = |u| ln(m0/m1) to the log's round-off (4 eps relative)."""
    u, g = np.array([0.0, 0.0, -300.0]), np.array([0.0, 0.0, -9.81])
    y = np.array([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 10.0, 0.0])
    h = 1e-3
    for _ in range(8000):
        y = ref.rk4_step(lambda z: ref.particle_rate(-1.0, u, g, z), y, h)
    p, v, m = exact.constant_thrust(10.0, -1.0, u, g, np.zeros(3), [1.0, 0.0, 0.0], 8.0)
    assert y[6] == pytest.approx(m, rel=16 * EPS)
    np.testing.assert_allclose(y[3:6], v, rtol=0, atol=1e-8 * np.linalg.norm(v))
    np.testing.assert_allclose(y[0:3], p, rtol=0, atol=1e-8 * np.linalg.norm(p))
    _, v1, m1 = exact.constant_thrust(10.0, -1.0, u, np.zeros(3), np.zeros(3), np.zeros(3), 8.0)
    assert np.linalg.norm(v1) == pytest.approx(exact.tsiolkovsky_delta_v(u, 10.0, m1), rel=8 * EPS)


# ---------------------------------------------------------------- rigiddyn against the reference
def step_tolerance(y0, y1, kappa=1.0):
    """One RK4 step, two sides: 16 eps κ per stage of max(1, |y0|, |Δy|), grown ≤ e over the stages (h ‖∂ẏ/∂y‖ ≤ 1:
    h = 0.01 s, |ṁ|/m ≤ 1 /s)."""
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(y1 - y0)))
    return 2 * 16 * EPS * kappa * np.e * size


def rate_function(t):
    """ṁ(t) [kg/s] of the tests' time-dependent flow (module level: MassFlow pickles it)."""
    return -0.5 - 0.2 * np.sin(3.0 * t)


@settings(settings.get_profile("variable_mass_reference"))
@given(seed=seeds)
@pytest.mark.parametrize("timed", [False, True])
def test_core_particle_with_thrust_one_rk4_step_matches_the_reference(timed, seed):
    """A Particle with MassFlow(rate) (a constant, or rate_function) and a world-frame Thrust under gravity: one RK4
    step of 0.01 s from t0 (p, v, m) and the recorded mass, against the reference (step_tolerance)."""
    rng = np.random.default_rng(seed)
    m0, t0, h = rng.uniform(2, 10), rng.uniform(0, 1), 0.01
    rate = rate_function if timed else rng.uniform(-1, 1)
    u, g, p, v = rng.uniform(-100, 100, 3), rng.uniform(-10, 10, 3), rng.uniform(-1, 1, 3), rng.uniform(-5, 5, 3)
    scene = rd.Scene()
    scene.add_body(rd.Particle(m0), name="rocket", mass_flow=rd.MassFlow(rate=rate))
    scene.add(rd.UniformGravity(g_W=g))
    scene.add(rd.Thrust(body=0, u_rel=u, frame="world"))
    result = rd.simulate(scene, [rd.ParticleState(p_W=p, v_W=v)], dt=h, steps=1, method="rk4", t0=t0)
    y0 = np.concatenate([p, v, [m0, t0]])
    want = ref.rk4_step(lambda z: ref.particle_rate(rate, u, g, z), y0, h)
    got = np.concatenate([result.p_W[1, 0], result.v_W[1, 0], [result.mass[1, 0], result.t[1]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=step_tolerance(y0, want))
    assert result.mass[0, 0] == m0


def rigid_rate(m0, inertia0, rate, u_B, r_B, g, y):
    """ẏ of (p 3, q 4, v 3, ω 3, m, t) for a rigid body whose inertia scales with its mass, under gravity and the
    body-frame thrust ṁ u_B applied at r_B (force R ṁ u_B at C, couple r_B × ṁ u_B; Rigid-body notes (4.36), (4.41))."""
    q, w, m = y[3:7], y[10:13], y[13]
    thrust_B = rate * np.asarray(u_B)
    v_dot = ref.acceleration(m, rate, so3.quat_to_matrix(q / np.linalg.norm(q)) @ u_B, m * g)
    w_dot = ref.angular_acceleration_scaled(m, m0, inertia0, w, np.cross(r_B, thrust_B))
    return np.concatenate([y[7:10], 0.5 * quat_product(q, np.append(w, 0.0)), v_dot, w_dot, [rate, 1.0]])


@settings(settings.get_profile("variable_mass_reference"))
@given(seed=seeds)
def test_core_rigid_body_with_scaled_inertia_and_off_centre_thrust_matches_the_reference(seed):
    """A RigidBody with MassFlow(rate, 'scaled') and a body-frame Thrust at r_B: one RK4 step of 0.01 s against the
    reference (α = I0⁻¹ ((m0/m) τ − ω × I0 ω)); step_tolerance with κ = cond(I0)."""
    rng = np.random.default_rng(seed)
    m0, h, rate = rng.uniform(2, 10), 0.01, rng.uniform(-1, 0)
    a, b, c = np.square(rng.uniform(0.5, 2.0, 3))  # a solid box's moments m (b² + c²)/12, ...: a real body
    inertia0 = m0 / 12.0 * np.diag([b + c, a + c, a + b])
    u, r_B, g = rng.uniform(-50, 50, 3), rng.uniform(-0.5, 0.5, 3), rng.uniform(-10, 10, 3)
    p, q = rng.uniform(-1, 1, 3), so3.rotvec_to_quat(rng.normal(size=3))
    v, w = rng.uniform(-5, 5, 3), rng.uniform(-2, 2, 3)
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(m0, inertia0), name="rocket", mass_flow=rd.MassFlow(rate=rate, inertia_rule="scaled"))
    scene.add(rd.UniformGravity(g_W=g))
    scene.add(rd.Thrust(body=0, u_rel=u, frame="body", r_B=r_B))
    result = rd.simulate(scene, [rd.RigidBodyState(p_W=p, q_WB=q, v_W=v, w_B=w)], dt=h, steps=1, method="rk4")
    y0 = np.concatenate([p, q, v, w, [m0, 0.0]])
    want = ref.rk4_step(lambda z: rigid_rate(m0, inertia0, rate, u, r_B, g, z), y0, h)
    want[3:7] /= np.linalg.norm(want[3:7])
    qc = result.q_WB[1, 0] * (1 if result.q_WB[1, 0] @ want[3:7] >= 0 else -1)
    got = np.concatenate([result.p_W[1, 0], qc, result.v_W[1, 0], result.w_B[1, 0], [result.mass[1, 0], result.t[1]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=step_tolerance(y0, want, np.linalg.cond(inertia0)))


def inertia_of_mass(m):
    """I_C(m) [kg m²] of the tests' 'function' rule: a body that loses mass mostly from its ends (module level: MassFlow
    pickles it)."""
    return np.diag([0.2 + 0.05 * m, 0.3 + 0.04 * m, 0.4 + 0.02 * m])


def test_core_rigid_body_with_an_inertia_function_matches_the_reference():
    """MassFlow(rate, inertia_rule=inertia_of_mass): I(m) ω̇ + ω × I(m) ω = τ (no jet damping) with τ = r_B × ṁ u_B;
    one RK4 step of 0.01 s against the reference (step_tolerance, κ = cond I(m) ≤ 2)."""
    m0, h, rate = 5.0, 0.01, -0.8
    u, r_B, g = np.array([-40.0, 10.0, 5.0]), np.array([0.1, -0.3, 0.2]), np.array([0.0, 0.0, -9.81])
    p, q = np.zeros(3), so3.rotvec_to_quat([0.3, -0.2, 0.1])
    v, w = np.array([1.0, 0.0, 0.0]), np.array([0.5, -1.0, 2.0])
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(m0, inertia_of_mass(m0)), name="rocket",
                   mass_flow=rd.MassFlow(rate=rate, inertia_rule=inertia_of_mass))
    scene.add(rd.UniformGravity(g_W=g))
    scene.add(rd.Thrust(body=0, u_rel=u, frame="body", r_B=r_B))
    result = rd.simulate(scene, [rd.RigidBodyState(p_W=p, q_WB=q, v_W=v, w_B=w)], dt=h, steps=1, method="rk4")

    def rate_of(y):
        qn, m = y[3:7] / np.linalg.norm(y[3:7]), y[13]
        v_dot = ref.acceleration(m, rate, so3.quat_to_matrix(qn) @ u, m * g)
        w_dot = ref.angular_acceleration(inertia_of_mass(m), y[10:13], np.cross(r_B, rate * u))
        q_dot = 0.5 * quat_product(y[3:7], np.append(y[10:13], 0.0))
        return np.concatenate([y[7:10], q_dot, v_dot, w_dot, [rate, 1.0]])

    y0 = np.concatenate([p, q, v, w, [m0, 0.0]])
    want = ref.rk4_step(rate_of, y0, h)
    want[3:7] /= np.linalg.norm(want[3:7])
    qc = result.q_WB[1, 0] * (1 if result.q_WB[1, 0] @ want[3:7] >= 0 else -1)
    got = np.concatenate([result.p_W[1, 0], qc, result.v_W[1, 0], result.w_B[1, 0], [result.mass[1, 0], result.t[1]]])
    np.testing.assert_allclose(got, want, rtol=0, atol=step_tolerance(y0, want, 2.0))


@pytest.mark.parametrize("method", ["splitting_dlm", "splitting_dlm_yoshida4"])
def test_splitting_methods_are_refused_with_an_inertia_function(method):
    """Under the 'function' rule the Euler form of I(m) changes with m: the splitting methods (exact rotations about
    fixed principal axes) do not apply and are refused naming the method (api12 §4)."""
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(5.0, inertia_of_mass(5.0)),
                   mass_flow=rd.MassFlow(rate=-0.5, inertia_rule=inertia_of_mass))
    with pytest.raises(ValueError, match="method"):
        rd.simulate(scene, [rd.RigidBodyState(w_B=[0.1, 0.2, 0.3])], 0.01, 10, method=method)
