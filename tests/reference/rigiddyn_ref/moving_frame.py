"""Newton's and Euler's laws seen from a moving frame F, in plain numpy. The oracle of rigiddyn's SceneFrame and
its fictitious terms; it never imports rigiddyn.

Rigid-body notes §4.11.1: the position triangle (4.37) r_W = o + R_WF r_F differentiated twice, (4.38)–(4.39),
gives the inertial acceleration of a point mass
    a_W = a_O + R_WF (r̈ + α × r + Ω × (Ω × r) + 2 Ω × ṙ)      (r, ṙ, r̈ relative to F, in F)
so that the observer in F sees (eq. (4.40), here with the frame-origin and Euler terms it omits)
    m r̈ = f − m a_O − m α × r − m Ω × (Ω × r) − 2 m Ω × ṙ
          (frame origin, Euler, centrifugal, Coriolis), all in F.
Ω_F [rad/s], α_F [rad/s²] F's angular velocity and acceleration relative to W, a_O_F [m/s²] the acceleration of
F's origin, expressed in F.

For a rigid body the fictitious torques about C are computed here by SUMMING the fictitious forces of the point
masses of a cloud with the body's mass, centre of mass and inertia (pivoted.point_cloud): τ = Σ ρ_i × f_i,
independent of any closed formula. `rigid_rate_in_frame` integrates a rigid body in F with them.
"""

from __future__ import annotations

import numpy as np

from .dynamics import cross, quat_product, to_body, to_world
from .pivoted import point_cloud
from .so3 import matrix_to_quat, quat_to_matrix, rotvec_to_quat


# ---------------------------------------------------------------- point mass (eq. (4.40))
def fictitious_forces(mass, r_F, v_F, w_F, alpha_F=(0.0, 0.0, 0.0), a_O_F=(0.0, 0.0, 0.0)) -> dict:
    """The four terms of Newton's law in F [N] (Rigid-body notes (4.39)–(4.40)), in F:
    origin −m a_O, euler −m α × r, centrifugal −m Ω × (Ω × r), coriolis −2 m Ω × ṙ."""
    r, v, w = (np.asarray(x, float) for x in (r_F, v_F, w_F))
    return {"origin": -mass * np.asarray(a_O_F, float), "euler": -mass * cross(alpha_F, r),
            "centrifugal": -mass * cross(w, cross(w, r)), "coriolis": -2.0 * mass * cross(w, v)}


def centrifugal_potential(mass, r_F, w_F) -> float:
    """−½ m |Ω × r|² [J]: the potential of the centrifugal force when Ω is constant (−∇ of it is −m Ω × (Ω × r))."""
    u = cross(w_F, r_F)
    return -0.5 * mass * u @ u


def particle_rate_in_frame(mass, g_F, frame, y) -> np.ndarray:
    """ẏ of y = (r_F 3, v_F 3, t) of a particle under the applied force m g_F (constant in F) and the fictitious
    forces; frame(t) → (Ω_F, α_F, a_O_F)."""
    w, alpha, a_O = frame(y[6])
    terms = fictitious_forces(mass, y[0:3], y[3:6], w, alpha, a_O)
    f = mass * np.asarray(g_F, float) + sum(terms.values())
    return np.concatenate([y[3:6], f / mass, [1.0]])


# ---------------------------------------------------------------- rigid body: summed point masses
def summed_fictitious_wrench(mass, inertia_com, p_F, q_FB, v_F, w_B, w_F, alpha_F=(0.0, 0.0, 0.0),
                             a_O_F=(0.0, 0.0, 0.0)) -> dict:
    """Each fictitious term on a rigid body as (force in F [N] at C, torque about C in B [N m]), by summing the
    terms of eq. (4.40) over the point masses of the body's cloud: point i at r_i = p + R_FB ρ_i moving at
    ṙ_i = v + R_FB (ω × ρ_i) relative to F (ω = w_B, B's angular velocity relative to F), its force f_i from
    fictitious_forces, the torque Σ (R_FB ρ_i) × f_i taken into B."""
    masses, rho_B = point_cloud(mass, inertia_com)
    out = {}
    for m_i, rho in zip(masses, rho_B):
        rho_F = to_world(q_FB, rho)
        r_i = np.asarray(p_F, float) + rho_F
        v_i = np.asarray(v_F, float) + to_world(q_FB, cross(w_B, rho))
        for name, f_i in fictitious_forces(m_i, r_i, v_i, w_F, alpha_F, a_O_F).items():
            f, tau = out.get(name, (np.zeros(3), np.zeros(3)))
            out[name] = (f + f_i, tau + to_body(q_FB, cross(rho_F, f_i)))
    return out


def rigid_rate_in_frame(mass, inertia_com, g_F, frame, y) -> np.ndarray:
    """ẏ of y = (p_F 3, q_FB 4, v_F 3, w_B 3, t) of a rigid body in F under gravity m g_F (in F) and the summed
    fictitious wrench: m v̇ = f, I ω̇ + ω × I ω = τ (Craig, Euler's equations, for the motion relative to F:
    Σ ρ × m ρ̈_rel = R_FB (I ω̇ + ω × I ω) for rigid relative kinematics), q̇ = ½ q ⊗ (ω, 0)."""
    p, q, v, w, t = y[0:3], y[3:7], y[7:10], y[10:13], y[13]
    qn = q / np.linalg.norm(q)
    w_F, alpha_F, a_O_F = frame(t)
    terms = summed_fictitious_wrench(mass, inertia_com, p, qn, v, w, w_F, alpha_F, a_O_F)
    f = mass * np.asarray(g_F, float) + sum(ft[0] for ft in terms.values())
    tau = sum(ft[1] for ft in terms.values())
    inertia = np.asarray(inertia_com, float)
    w_dot = np.linalg.solve(inertia, tau - cross(w, inertia @ w))
    return np.concatenate([v, 0.5 * quat_product(q, np.append(w, 0.0)), f / mass, w_dot, [1.0]])


def pivoted_rate_in_frame(mass, inertia_com, c_B, p_O_F, g_F, frame, y) -> np.ndarray:
    """ẏ of y = (q_FB 4, w_B 3, t) of a body pinned at O (fixed in F at p_O_F, C at p_O_F + R_FB c) under gravity m g_F
    and the summed fictitious forces: each point's force f_i at r_i = p_O + R_FB (c + ρ_i) (ṙ_i = R_FB (ω × (c + ρ_i)))
    taken about O, τ_O = Σ R_BF (r_i − p_O) × f_i, and Euler about O for the motion relative to F (Craig:
    Σ (c + ρ_i) × m_i a_i,rel = I_O ω̇ + ω × I_O ω for a rigid rotation about a point fixed in F)."""
    q, w, t = y[0:4], y[4:7], y[7]
    qn = q / np.linalg.norm(q)
    w_F, alpha_F, a_O_F = frame(t)
    masses, rho_B = point_cloud(mass, inertia_com)
    tau_O = cross(c_B, to_body(qn, mass * np.asarray(g_F, float)))
    for m_i, rho in zip(masses, rho_B):
        arm_B = np.asarray(c_B, float) + rho
        r_i = np.asarray(p_O_F, float) + to_world(qn, arm_B)
        v_i = to_world(qn, cross(w, arm_B))
        tau_O = tau_O + cross(arm_B, to_body(qn, sum(fictitious_forces(m_i, r_i, v_i, w_F, alpha_F, a_O_F).values())))
    c = np.asarray(c_B, float)
    inertia_O = np.asarray(inertia_com, float) + mass * ((c @ c) * np.eye(3) - np.outer(c, c))
    w_dot = np.linalg.solve(inertia_O, tau_O - cross(w, inertia_O @ w))
    return np.concatenate([0.5 * quat_product(q, np.append(w, 0.0)), w_dot, [1.0]])


# ---------------------------------------------------------------- transforming an inertial run into F
def rotation_WF(axis, rate, t) -> np.ndarray:
    """R_WF(t) = exp(hat(rate t u)) (u = axis/|axis|): F turning at `rate` [rad/s] about the fixed axis through
    the common origin, F = W at t = 0 (Craig, simple angular velocity)."""
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    return quat_to_matrix(rotvec_to_quat(rate * t * u))


def particle_into_frame(axis, rate, t, p_W, v_W):
    """(r_F, ṙ_F) of an inertial (p_W, v_W) at time t: r_F = R_FW p_W, ṙ_F = R_FW (v_W − Ω × p_W) (Rigid-body
    notes (4.38) solved for the relative velocity, origin fixed)."""
    R = rotation_WF(axis, rate, t)
    w_W = rate * np.asarray(axis, float) / np.linalg.norm(axis)
    return R.T @ np.asarray(p_W, float), R.T @ (np.asarray(v_W, float) - cross(w_W, p_W))


def particle_from_frame(axis, rate, t, r_F, v_F):
    """The inverse of particle_into_frame: p_W = R_WF r, v_W = R_WF ṙ + Ω × p_W."""
    R = rotation_WF(axis, rate, t)
    w_W = rate * np.asarray(axis, float) / np.linalg.norm(axis)
    p = R @ np.asarray(r_F, float)
    return p, R @ np.asarray(v_F, float) + cross(w_W, p)


def attitude_into_frame(axis, rate, t, q_WB, w_B):
    """(q_FB, ω relative to F in B) of an inertial attitude: R_FB = R_FW R_WB, ω_rel = ω − R_BW Ω_W (addition
    theorem of angular velocities, Craig)."""
    R_FW = rotation_WF(axis, rate, t).T
    w_W = rate * np.asarray(axis, float) / np.linalg.norm(axis)
    q_FB = matrix_to_quat(R_FW @ quat_to_matrix(q_WB))
    return q_FB, np.asarray(w_B, float) - to_body(q_WB, w_W)


def free_particle_in_frame(axis, rate, t, r0_F, v0_F):
    """A free particle seen from F (F = W at t = 0): the straight line p_W = p0 + v0_W t with v0_W = ṙ0 + Ω × r0,
    transformed into F. Returns (r_F, ṙ_F) at t."""
    p0, v0 = particle_from_frame(axis, rate, 0.0, r0_F, v0_F)
    return particle_into_frame(axis, rate, t, p0 + v0 * t, v0)


def constant_rotation_terms(axis, rate):
    """frame(t) for F turning at a constant rate about a fixed axis through its fixed origin: Ω_F = rate u (the
    axis is fixed in both W and F), α = 0, a_O = 0."""
    w = rate * np.asarray(axis, float) / np.linalg.norm(axis)
    return lambda t: (w, np.zeros(3), np.zeros(3))


__all__ = ["attitude_into_frame", "centrifugal_potential", "constant_rotation_terms", "fictitious_forces",
           "free_particle_in_frame", "particle_from_frame", "particle_into_frame", "particle_rate_in_frame",
           "pivoted_rate_in_frame",
           "rigid_rate_in_frame", "rotation_WF", "summed_fictitious_wrench"]
