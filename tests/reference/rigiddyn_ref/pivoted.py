"""A rigid body pinned at a point O fixed in the (inertial) scene frame, and the compound pendulum, in plain
numpy. The oracle of rigiddyn's PivotedBody / PivotedPlanarBody; it never imports rigiddyn.

Written from the texts: Euler's law about a point O fixed in the ground, M_O = dH_O/dt with H_O = I_O ω
(Craig, "Angular Momentum of B about point O": v_O = 0 ⇒ H_O = ∫ ρ × (ω × ρ) dm), expressed in the body
frame B (Craig, "Euler's equations": I_O ω̇ + ω × I_O ω = M_O); the inertia about O by the parallel-axis
theorem with the products of inertia (Craig, [I]_2 = [I]_C + m [[b² + c², −ab, −ac], ...]: in the project's
convention of negated products, I_O = I_C + m (|c|² 1 − c cᵀ)); the reaction of the pivot from Newton's law
for the centre of mass, m a_C = f + R (Rigid-body notes (4.35), (4.58)).

Notation (as rigiddyn): B is the body frame at the centre of mass C; c = p_OC_B is C relative to O in B [m];
q_WB (x, y, z, w) the attitude, w_B [rad/s] the angular velocity in B; a wrench is f_W [N] (in W, through
C) and tau_B [N m] (a couple, in B). A second derivation (`constrained_newton_euler`) solves Newton and
Euler about C together with the constraint a_O = 0 for (α, R) as one 6 × 6 linear system.
"""

from __future__ import annotations

import numpy as np

from .dynamics import cross, quat_product, to_body, to_world


# ---------------------------------------------------------------- inertia about O
def inertia_about_pivot(mass, inertia_com, c_B) -> np.ndarray:
    """I_O = I_C + m (|c|² 1 − c cᵀ) [kg m²] in B (parallel-axis theorem, Craig; products included)."""
    c = np.asarray(c_B, float)
    return np.asarray(inertia_com, float) + mass * ((c @ c) * np.eye(3) - np.outer(c, c))


def inertia_of_points(masses, points) -> np.ndarray:
    """Σ m_i (|ρ_i|² 1 − ρ_i ρ_iᵀ) [kg m²]: the inertia of point masses about the origin of ρ (Craig,
    I_x = ∫ (y² + z²) dm, I_xy = −∫ x y dm in the negated-products convention)."""
    points = np.atleast_2d(np.asarray(points, float))
    return sum(m * ((r @ r) * np.eye(3) - np.outer(r, r)) for m, r in zip(masses, points))


def point_cloud(mass, inertia_com):
    """Six point masses m/6 at ±a_k v_k (v_k the principal axes of I_C) whose total mass is m, centre of mass
    the origin and inertia about it I_C: the second moments J = Σ m ρ ρᵀ = ½ tr(I) 1 − I have principal
    values J_k = ½ tr I − I_k ≥ 0 (triangle inequality), and 2 (m/6) a_k² = J_k. Returns (masses (6,),
    points (6, 3)) in B [kg], [m]."""
    moments, axes = np.linalg.eigh(np.asarray(inertia_com, float))
    second = 0.5 * np.sum(moments) - moments
    a = np.sqrt(np.maximum(second, 0.0) * 3.0 / mass)
    points = np.concatenate([(a * axes).T, -(a * axes).T])
    return np.full(6, mass / 6.0), points


# ---------------------------------------------------------------- Euler's equations about O
def moment_about_pivot(c_B, q_WB, f_W, tau_B) -> np.ndarray:
    """M_O in B: the couple plus the moment of the force through C, τ_O = τ_B + c × (R_BW f_W) (Rigid-body
    notes (4.41))."""
    return np.asarray(tau_B, float) + cross(c_B, to_body(q_WB, f_W))


def angular_acceleration(mass, inertia_com, c_B, q_WB, w_B, f_W, tau_B) -> np.ndarray:
    """α_B = I_O⁻¹ (M_O − ω × I_O ω) [rad/s²] (Craig, Euler's equations about O fixed in the ground)."""
    inertia_O = inertia_about_pivot(mass, inertia_com, c_B)
    w = np.asarray(w_B, float)
    return np.linalg.solve(inertia_O, moment_about_pivot(c_B, q_WB, f_W, tau_B) - cross(w, inertia_O @ w))


def centre_acceleration_W(c_B, q_WB, w_B, alpha_B) -> np.ndarray:
    """a_C = R_WB (α × c + ω × (ω × c)) [m/s²]: the acceleration of a point of a body turning about the fixed
    O (Craig, a_P = a_O + α × r + ω × (ω × r) with a_O = 0)."""
    return to_world(q_WB, cross(alpha_B, c_B) + cross(w_B, cross(w_B, c_B)))


def pivot_reaction_W(mass, c_B, q_WB, w_B, alpha_B, f_W) -> np.ndarray:
    """R = m a_C − f_W [N] in W: the pivot's force on the body, from Newton's law for C."""
    return mass * centre_acceleration_W(c_B, q_WB, w_B, alpha_B) - np.asarray(f_W, float)


def constrained_newton_euler(mass, inertia_com, c_B, q_WB, w_B, f_W, tau_B):
    """Second derivation: Newton for C and Euler about C with the unknown reaction R_B (in B) acting at O
    (ρ = −c from C), and the constraint a_O = 0, i.e. a_C = α × c + ω × (ω × c) in B:
        m (α × c) − R_B = f_B − m ω × (ω × c)
        I_C α + c × R_B = τ_B − ω × I_C ω          ((−c) × R_B on the right moved left)
    solved as one 6 × 6 system for (α_B, R_B). Returns (alpha_B, reaction_W)."""
    c, w = np.asarray(c_B, float), np.asarray(w_B, float)
    inertia = np.asarray(inertia_com, float)
    hat_c = np.array([[0.0, -c[2], c[1]], [c[2], 0.0, -c[0]], [-c[1], c[0], 0.0]])
    A = np.zeros((6, 6))
    A[:3, :3], A[:3, 3:] = -mass * hat_c, -np.eye(3)       # m α × c = −m [c]× α
    A[3:, :3], A[3:, 3:] = inertia, hat_c
    rhs = np.concatenate([to_body(q_WB, f_W) - mass * cross(w, cross(w, c)), tau_B - cross(w, inertia @ w)])
    x = np.linalg.solve(A, rhs)
    return x[:3], to_world(q_WB, x[3:])


def inverse_dynamics(mass, inertia_com, c_B, q_WB, w_B, alpha_B, g_W):
    """The couple about O [N m] in B that gives the angular acceleration alpha_B under gravity g_W, and the
    reaction [N] in W: τ = I_O α + ω × I_O ω − c × R_BW (m g) (Euler about O solved for M_O), R = m a_C − m g."""
    inertia_O = inertia_about_pivot(mass, inertia_com, c_B)
    w, alpha = np.asarray(w_B, float), np.asarray(alpha_B, float)
    f_W = mass * np.asarray(g_W, float)
    tau = inertia_O @ alpha + cross(w, inertia_O @ w) - cross(c_B, to_body(q_WB, f_W))
    return tau, pivot_reaction_W(mass, c_B, q_WB, w, alpha, f_W)


# ---------------------------------------------------------------- the pivoted body under gravity
def centre_position_W(c_B, q_WB, p_WO=(0.0, 0.0, 0.0)) -> np.ndarray:
    """p_WC = p_WO + R_WB c [m]."""
    return np.asarray(p_WO, float) + to_world(q_WB, c_B)


def kinetic_energy(mass, inertia_com, c_B, w_B) -> float:
    """T = ½ ωᵀ I_O ω [J] (Craig, kinetic energy of a body turning about a fixed point)."""
    w = np.asarray(w_B, float)
    return 0.5 * w @ inertia_about_pivot(mass, inertia_com, c_B) @ w


def potential_energy(mass, c_B, q_WB, g_W, p_WO=(0.0, 0.0, 0.0)) -> float:
    """V = −m g·p_WC [J] (the work of a constant force)."""
    return -mass * np.asarray(g_W, float) @ centre_position_W(c_B, q_WB, p_WO)


def angular_momentum_O_W(mass, inertia_com, c_B, q_WB, w_B) -> np.ndarray:
    """H_O = R_WB I_O ω [kg m²/s] in W."""
    return to_world(q_WB, inertia_about_pivot(mass, inertia_com, c_B) @ np.asarray(w_B, float))


def rate(mass, inertia_com, c_B, g_W, y, tau_B=(0.0, 0.0, 0.0)) -> np.ndarray:
    """ẏ of y = (q_WB (x, y, z, w) 4, w_B 3) under gravity g_W and a constant couple tau_B: q̇ = ½ q ⊗ (ω, 0)
    (Solà), ω̇ = α of Euler's equations about O with f_W = m g through C. The quaternion is used as given
    (unnormalised) in q̇ and as q/|q| for the force direction."""
    q, w = y[:4], y[4:7]
    alpha = angular_acceleration(mass, inertia_com, c_B, q / np.linalg.norm(q), w, mass * np.asarray(g_W, float),
                                 tau_B)
    return np.concatenate([0.5 * quat_product(q, np.append(w, 0.0)), alpha])


def rk4_step(mass, inertia_com, c_B, g_W, y, h) -> np.ndarray:
    """Classical RK4 (Kutta 1901) on y = (q, ω), q renormalised at the end (as rigiddyn's rk4)."""
    f = lambda z: rate(mass, inertia_com, c_B, g_W, z)  # noqa: E731
    k1 = f(y)
    k2 = f(y + 0.5 * h * k1)
    k3 = f(y + 0.5 * h * k2)
    k4 = f(y + h * k3)
    y1 = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
    y1[:4] /= np.linalg.norm(y1[:4])
    return y1


# ---------------------------------------------------------------- the compound pendulum (plane, about z)
def planar_centre_W(c_B, theta, p_WO=(0.0, 0.0)) -> np.ndarray:
    """p_WC = p_WO + Rz(θ) c (2,) [m]."""
    c, s = np.cos(theta), np.sin(theta)
    return np.asarray(p_WO, float) + np.array([c * c_B[0] - s * c_B[1], s * c_B[0] + c * c_B[1]])


def planar_angular_acceleration(mass, inertia_zz, c_B, theta, f_W, tau_z=0.0) -> float:
    """α = (τ_z + (c_W × f)_z) / I_O,zz, I_O,zz = I_zz + m |c|² (Craig, plane kinetics about a fixed point;
    parallel-axis theorem); c_W = Rz(θ) c, f (2,) [N] through C."""
    c_W = planar_centre_W(c_B, theta)
    inertia_O = inertia_zz + mass * float(np.dot(c_B, c_B))
    return (tau_z + c_W[0] * f_W[1] - c_W[1] * f_W[0]) / inertia_O


def planar_reaction_W(mass, c_B, theta, omega, alpha, f_W) -> np.ndarray:
    """R = m a_C − f (2,) [N], a_C = α ẑ × c_W − ω² c_W."""
    c_W = planar_centre_W(c_B, theta)
    a_C = alpha * np.array([-c_W[1], c_W[0]]) - omega ** 2 * c_W
    return mass * a_C - np.asarray(f_W, float)


def planar_rate(mass, inertia_zz, c_B, g_W, y) -> np.ndarray:
    """ẏ of y = (θ, ω) under gravity g_W (2,) or (3,) (its xy part acts)."""
    f = mass * np.asarray(g_W, float)[:2]
    return np.array([y[1], planar_angular_acceleration(mass, inertia_zz, c_B, y[0], f)])


__all__ = ["angular_acceleration", "angular_momentum_O_W", "centre_acceleration_W", "centre_position_W",
           "constrained_newton_euler", "inertia_about_pivot", "inertia_of_points", "inverse_dynamics",
           "kinetic_energy", "moment_about_pivot", "pivot_reaction_W", "planar_angular_acceleration",
           "planar_centre_W", "planar_rate", "planar_reaction_W", "point_cloud", "potential_energy", "rate",
           "rk4_step"]
