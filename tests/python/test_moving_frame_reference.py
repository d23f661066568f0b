"""Moving frames: the numpy reference (rigiddyn_ref.moving_frame) checked against itself (the fictitious torques summed
over a point cloud equal the closed formulas; a free particle integrated in F follows the inertial straight line
seen from F), then rigiddyn's SceneFrame against it on random inputs: each fictitious term's power at t0 (the core's
closed formulas against the reference's summed point masses) and one RK4 step of a particle and a rigid body in a
frame with every term (rotating with a changing axis, accelerating origin)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigiddyn as rd

from rigiddyn_ref import moving_frame as ref
from rigiddyn_ref import pivoted, so3

EPS = np.finfo(float).eps
settings.register_profile("moving_frame_reference", max_examples=15, deadline=None)
seeds = st.integers(0, 2 ** 32 - 1)
TERMS = {"FrameOriginForce": "origin", "EulerForce": "euler", "CentrifugalForce": "centrifugal",
         "CoriolisForce": "coriolis"}


def box_moments(mass, dims):
    a, b, c = np.square(dims)
    return mass / 12.0 * np.array([b + c, a + c, a + b])


def random_rigid(rng):
    """mass 0.5–3 kg, a turned box inertia (condition ≤ 16), p, v, q, ω relative to F."""
    mass = rng.uniform(0.5, 3.0)
    turn = so3.rotvec_to_matrix(rng.normal(size=3))
    inertia = turn @ np.diag(box_moments(mass, rng.uniform(0.5, 2.0, 3))) @ turn.T
    return (mass, inertia, rng.uniform(-2, 2, 3), so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-1, 1, 3),
            rng.uniform(-2, 2, 3))


class WobblingFrame:
    """F relative to W: R_WF = Rz(ψ) Rx(φ), ψ = a t + b t²/2, φ = c sin(d t), origin o = (A sin t, B t², C cos t):
    ω_W = ψ̇ z + φ̇ Rz(ψ) x, α_W = ψ̈ z + φ̈ Rz(ψ) x + ψ̇ φ̇ z × Rz(ψ) x; every fictitious term acts (α ∦ ω)."""

    def __init__(self, rng):
        self.a, self.b = rng.uniform(0.2, 1.0), rng.uniform(-0.5, 0.5)
        self.c, self.d = rng.uniform(0.1, 0.5), rng.uniform(0.5, 2.0)
        self.A, self.B, self.C = rng.uniform(-1, 1, 3)

    def kinematics(self, t):
        """(R_WF, ω_W, α_W, o, ȯ, ö) at t."""
        psi, psi_d, psi_dd = self.a * t + 0.5 * self.b * t * t, self.a + self.b * t, self.b
        phi, phi_d, phi_dd = (self.c * np.sin(self.d * t), self.c * self.d * np.cos(self.d * t),
                              -self.c * self.d ** 2 * np.sin(self.d * t))
        Rz = so3.rot_z(psi)
        x = Rz @ np.array([1.0, 0.0, 0.0])
        z = np.array([0.0, 0.0, 1.0])
        w = psi_d * z + phi_d * x
        alpha = psi_dd * z + phi_dd * x + psi_d * phi_d * np.cross(z, x)
        o = np.array([self.A * np.sin(t), self.B * t * t, self.C * np.cos(t)])
        v = np.array([self.A * np.cos(t), 2 * self.B * t, -self.C * np.sin(t)])
        a = np.array([-self.A * np.sin(t), 2 * self.B, -self.C * np.cos(t)])
        return Rz @ so3.rot_x(phi), w, alpha, o, v, a

    def terms(self, t):
        """The reference's frame(t): (Ω_F, α_F, a_O_F), each R_FW of its W value."""
        R, w, alpha, _, _, a = self.kinematics(t)
        return R.T @ w, R.T @ alpha, R.T @ a

    def core(self):
        def at(t):
            R, w, alpha, o, v, a = self.kinematics(t)
            return rd.FrameKinematics(R_PF=R, w_PF_P=w, alpha_PF_P=alpha, p_PF_P=o, v_PF_P=v, a_PF_P=a)
        return rd.SceneFrame.moving(rd.FrameMotion(at))


def term_scale(mass, a_O, alpha, W, r, speed):
    """m (|a_O| + (|α| + |Ω|²) r + 2 |Ω| speed) max(1, r): the magnitude of the fictitious forces on points within r
    of the origin moving at ≤ speed, times the lever arm (for the torques)."""
    return mass * (np.linalg.norm(a_O) + (np.linalg.norm(alpha) + W @ W) * r + 2 * np.linalg.norm(W) * speed) * max(1, r)


# ---------------------------------------------------------------- the reference against itself
@settings(settings.get_profile("moving_frame_reference"))
@given(seed=seeds)
def test_reference_summed_point_masses_give_the_closed_fictitious_wrench(seed):
    """The cloud's summed terms equal the closed forms: forces −m a_O, −m α × p, −m Ω × (Ω × p), −2m Ω × v (Σ m ρ = 0
    drops the ρ parts), torques in B (Ω, α in B) −I α, −Ω × I Ω, −(ω × I Ω + Ω × I ω − I (ω × Ω)) (api12 §3, from
    Euler's equations of the absolute angular velocity). Both round ≤ 32 times (6 points, a dozen operations each)
    on terms ≤ the scale below."""
    rng = np.random.default_rng(seed)
    mass, inertia, p, q, v, w = random_rigid(rng)
    W, alpha, a_O = rng.uniform(-2, 2, 3), rng.uniform(-2, 2, 3), rng.uniform(-5, 5, 3)
    summed = ref.summed_fictitious_wrench(mass, inertia, p, q, v, w, W, alpha, a_O)
    R = so3.quat_to_matrix(q)
    W_B, alpha_B = R.T @ W, R.T @ alpha
    closed = {"origin": (-mass * a_O, np.zeros(3)),
              "euler": (-mass * np.cross(alpha, p), -inertia @ alpha_B),
              "centrifugal": (-mass * np.cross(W, np.cross(W, p)), -np.cross(W_B, inertia @ W_B)),
              "coriolis": (-2 * mass * np.cross(W, v), -(np.cross(w, inertia @ W_B) + np.cross(W_B, inertia @ w)
                                                       - inertia @ np.cross(w, W_B)))}
    rho = np.max(np.linalg.norm(pivoted.point_cloud(mass, inertia)[1], axis=1))
    r = np.linalg.norm(p) + rho
    speed = np.linalg.norm(v) + np.linalg.norm(w) * rho
    scale = term_scale(mass, a_O, alpha, W, r, speed)
    for name, (f, tau) in closed.items():
        np.testing.assert_allclose(summed[name][0], f, rtol=0, atol=2 * 32 * EPS * scale, err_msg=name)
        np.testing.assert_allclose(summed[name][1], tau, rtol=0, atol=2 * 32 * EPS * scale, err_msg=name)


def test_reference_free_particle_integrated_in_a_rotating_frame_follows_the_transformed_line():
    """RK4 on particle_rate_in_frame (centrifugal + Coriolis) over 2 s at h = 1e-3 against free_particle_in_frame.
    RK4's global error ≤ C h⁴ with C ~ |Ω|⁴ (|r| + |v|/|Ω|) t/5! ≈ 1e-13 here (|Ω| = 1.3, |r| ~ 3): 1e-10 leaves the
    round-off of 2000 steps (≈ 2000 × 4 eps × 5 ≈ 1e-12) and C's constant room."""
    axis, rate = np.array([0.3, -0.2, 1.0]), 1.2
    frame = ref.constant_rotation_terms(axis, rate)
    y = np.array([1.0, 0.5, -0.3, 0.2, -0.7, 0.4, 0.0])
    h = 1e-3
    for _ in range(2000):
        k1 = ref.particle_rate_in_frame(1.0, np.zeros(3), frame, y)
        k2 = ref.particle_rate_in_frame(1.0, np.zeros(3), frame, y + h / 2 * k1)
        k3 = ref.particle_rate_in_frame(1.0, np.zeros(3), frame, y + h / 2 * k2)
        k4 = ref.particle_rate_in_frame(1.0, np.zeros(3), frame, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    r, v = ref.free_particle_in_frame(axis, rate, y[6], [1.0, 0.5, -0.3], [0.2, -0.7, 0.4])
    np.testing.assert_allclose(y[:3], r, rtol=0, atol=1e-10)
    np.testing.assert_allclose(y[3:6], v, rtol=0, atol=1e-10)


# ---------------------------------------------------------------- rigiddyn against the reference
def rigid_scene(mass, inertia, frame, g_F, kind="rigid"):
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(mass, inertia) if kind == "rigid" else rd.Particle(mass), name="b")
    scene.add(rd.UniformGravity(g_W=g_F))
    scene.frame = frame
    return scene


@settings(settings.get_profile("moving_frame_reference"))
@given(seed=seeds)
def test_core_fictitious_power_at_t0_matches_the_summed_point_masses(seed):
    """The core's power column of each fictitious term at t0 (its closed force and torque formulas) against f·v + τ·ω
    of the reference's point-mass sums, in a frame where every term acts: both sides round each term ≤ 32 times on
    magnitudes ≤ |f| |v| + |τ| |ω| taken with the magnitude scale of
    test_reference_summed_point_masses_give_the_closed_fictitious_wrench."""
    rng = np.random.default_rng(seed)
    frame = WobblingFrame(rng)
    t0 = rng.uniform(0, 2)
    mass, inertia, p, q, v, w = random_rigid(rng)
    scene = rigid_scene(mass, inertia, frame.core(), rng.uniform(-10, 10, 3))
    result = rd.simulate(scene, [rd.RigidBodyState(p_W=p, q_WB=q, v_W=v, w_B=w)], dt=0.01, steps=1, method="rk4",
                         t0=t0)
    W, alpha, a_O = frame.terms(t0)
    summed = ref.summed_fictitious_wrench(mass, inertia, p, q, v, w, W, alpha, a_O)
    rho = np.max(np.linalg.norm(pivoted.point_cloud(mass, inertia)[1], axis=1))
    r, speed = np.linalg.norm(p) + rho, np.linalg.norm(v) + np.linalg.norm(w) * rho
    scale = term_scale(mass, a_O, alpha, W, r, speed)
    columns = list(result.elements)
    assert set(TERMS).issubset(columns), columns
    for name, key in TERMS.items():
        f, tau = summed[key]
        want = f @ v + tau @ w
        got = result.power[0, columns.index(name)]
        assert abs(got - want) <= 2 * 32 * EPS * scale * (speed + np.linalg.norm(w)), name


def rk4(rate, y, h):
    k1 = rate(y)
    k2 = rate(y + h / 2 * k1)
    k3 = rate(y + h / 2 * k2)
    k4 = rate(y + h * k3)
    return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)


class RotatingFrame:
    """SceneFrame.rotating(axis, rate) and its reference terms (the constant-rotation fast path for one particle)."""

    def __init__(self, rng):
        self.axis, self.rate = rng.normal(size=3), rng.uniform(-2, 2)
        self.terms = ref.constant_rotation_terms(self.axis, self.rate)

    def core(self):
        return rd.SceneFrame.rotating(self.axis, self.rate)


FRAMES = {"moving": WobblingFrame, "rotating": RotatingFrame}


@settings(settings.get_profile("moving_frame_reference"))
@given(seed=seeds)
@pytest.mark.parametrize("frame_kind", ["moving", "rotating"])
@pytest.mark.parametrize("kind", ["particle", "rigid"])
def test_core_rk4_step_in_a_moving_frame_matches_the_reference(kind, frame_kind, seed):
    """One RK4 step of 0.01 s from t0 of a particle or a rigid body in the wobbling frame (every term; the generic
    scene model) or a frame turning at a constant rate (a lone particle there runs the fast model) under gravity (in F),
    core vs the reference (q renormalised): per side 16 eps κ per stage of max(1, |y|, |Δy|), grown ≤ e over the
    stages (h × the rate's Lipschitz constant ≤ 0.1 here), plus the point-cloud sum's 32 roundings on the terms'
    scale (relative to the state, ≤ 32 eps × h × rate size): 2 sides × (16 κ e + 32) eps × size."""
    rng = np.random.default_rng(seed)
    frame = FRAMES[frame_kind](rng)
    t0, h = rng.uniform(0, 2), 0.01
    mass, inertia, p, q, v, w = random_rigid(rng)
    g = rng.uniform(-10, 10, 3)
    scene = rigid_scene(mass, inertia, frame.core(), g, kind)
    if kind == "particle":
        state = rd.ParticleState(p_W=p, v_W=v)
        y0 = np.concatenate([p, v, [t0]])
        want = rk4(lambda y: ref.particle_rate_in_frame(mass, g, frame.terms, y), y0, h)
        kappa = 1.0
    else:
        state = rd.RigidBodyState(p_W=p, q_WB=q, v_W=v, w_B=w)
        y0 = np.concatenate([p, q, v, w, [t0]])
        want = rk4(lambda y: ref.rigid_rate_in_frame(mass, inertia, g, frame.terms, y), y0, h)
        want[3:7] /= np.linalg.norm(want[3:7])
        kappa = np.linalg.cond(inertia)
    result = rd.simulate(scene, [state], dt=h, steps=1, method="rk4", t0=t0)
    if kind == "particle":
        got = np.concatenate([result.p_W[1, 0], result.v_W[1, 0], [result.t[1]]])
    else:
        qc = result.q_WB[1, 0] * (1 if result.q_WB[1, 0] @ want[3:7] >= 0 else -1)
        got = np.concatenate([result.p_W[1, 0], qc, result.v_W[1, 0], result.w_B[1, 0], [result.t[1]]])
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(want - y0)))
    np.testing.assert_allclose(got, want, rtol=0, atol=2 * (16 * kappa * np.e + 32) * EPS * size)


@settings(settings.get_profile("moving_frame_reference"))
@given(seed=seeds)
def test_core_potential_in_a_rotating_frame_includes_the_centrifugal_potential(seed):
    """In a frame turning at a constant rate, the recorded potential is gravity's −m g·p plus the centrifugal
    −½ m |Ω × p|² − ½ Ω_B·I Ω_B (the Jacobi integral's potential): at t0 against the reference (a dozen roundings
    per term on m |g| |p| + m |Ω|² |p|² + ‖I‖ |Ω|²)."""
    rng = np.random.default_rng(seed)
    mass, inertia, p, q, v, w = random_rigid(rng)
    axis, rate, g = rng.normal(size=3), rng.uniform(-2, 2), rng.uniform(-10, 10, 3)
    frame = rd.SceneFrame.rotating(axis, rate)
    result = rd.simulate(rigid_scene(mass, inertia, frame, g), [rd.RigidBodyState(p_W=p, q_WB=q, v_W=v, w_B=w)],
                         dt=0.01, steps=1, method="rk4")
    W = rate * axis / np.linalg.norm(axis)
    W_B = so3.quat_to_matrix(q).T @ W
    want = -mass * g @ p + ref.centrifugal_potential(mass, p, W) - 0.5 * W_B @ inertia @ W_B
    scale = mass * np.linalg.norm(g) * np.linalg.norm(p) + (mass * (p @ p) + np.linalg.norm(inertia, 2)) * (W @ W)
    assert abs(result.potential_energy[0] - want) <= 2 * 16 * EPS * scale


@settings(settings.get_profile("moving_frame_reference"))
@given(seed=seeds)
def test_core_pivoted_body_in_a_moving_frame_matches_the_reference(seed):
    """A PivotedBody (O fixed in F) in the wobbling frame under gravity: one RK4 step of 0.01 s from t0 against the
    reference's Euler about O with the summed fictitious forces (moving_frame.pivoted_rate_in_frame); tolerance as
    test_core_rk4_step_in_a_moving_frame_matches_the_reference with κ = cond(I_O)."""
    rng = np.random.default_rng(seed)
    frame = WobblingFrame(rng)
    t0, h = rng.uniform(0, 2), 0.01
    mass, inertia, _, q, _, w = random_rigid(rng)
    c, p_O, g = rng.uniform(-0.8, 0.8, 3), rng.uniform(-1, 1, 3), rng.uniform(-10, 10, 3)
    scene = rd.Scene()
    scene.add_body(rd.PivotedBody(rd.RigidBody(mass, inertia), c, p_O), name="b")
    scene.add(rd.UniformGravity(g_W=g))
    scene.frame = frame.core()
    result = rd.simulate(scene, [rd.PivotedBodyState(q_WB=q, w_B=w)], dt=h, steps=1, method="rk4", t0=t0)
    y0 = np.concatenate([q, w, [t0]])
    want = rk4(lambda y: ref.pivoted_rate_in_frame(mass, inertia, c, p_O, g, frame.terms, y), y0, h)
    want[:4] /= np.linalg.norm(want[:4])
    qc = result.q_WB[1, 0] * (1 if result.q_WB[1, 0] @ want[:4] >= 0 else -1)
    got = np.concatenate([qc, result.w_B[1, 0], [result.t[1]]])
    kappa = np.linalg.cond(pivoted.inertia_about_pivot(mass, inertia, c))
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(want - y0)))
    np.testing.assert_allclose(got, want, rtol=0, atol=2 * (16 * kappa * np.e + 32) * EPS * size)
