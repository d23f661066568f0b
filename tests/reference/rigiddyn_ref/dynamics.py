"""Newton–Euler dynamics of a particle, a planar rigid body and a spatial rigid body, in plain numpy.

Written from the theory texts (docs/references.md): Newton's law for a point mass f = m a (Rigid-body notes
(4.35)) and its momentum p = m v (4.36); for a rigid body Newton's law at the centre of mass f = m d²r_c/dt²
(Rigid-body notes (4.58)), Euler's law n = d(I ω)/dt about the centre of mass (Rigid-body notes (4.69)), which
in the body frame B reads I ω̇ + ω × I ω = n (Craig "Euler's equations"); plane kinetics Σf = m a_G,
Σn_z = I_zz α (Craig, "Supplement: Rigid Body Plane Kinetics"); angular momentum about a point
H_P = r_PC × L + H_C (Craig, Rigid-body notes (4.65)); kinetic energy T = ½ m v·v + ½ ω·I ω (Craig "Kinetic
Energy"); impulse–momentum ∫f dt = m Δv, ∫n dt = ΔH (Craig "Impulse-Momentum Principle").

State of a spatial body (docs/conventions.md): p_W centre of mass [m], q_WB (x, y, z, w) unit
quaternion, v_W centre-of-mass velocity in W [m/s], w_B angular velocity in B [rad/s]. Inertias
are about the centre of mass, expressed in B [kg m²]. Gravity g_W [m/s²] in W.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


STANDARD_GRAVITY = np.array([0.0, 0.0, -9.81])


def _vec(x, n=3) -> np.ndarray:
    return np.zeros(n) if x is None else np.asarray(x, dtype=float)


def cross(a, b) -> np.ndarray:
    """a × b for 3-vectors, written out (numpy's cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def rotate(q, u) -> np.ndarray:
    """R(q) u for one unit quaternion (x, y, z, w) and one vector: u + 2 w (v x u) + 2 v x (v x u)
    (the single-item form of so3.quat_rotate, fast on single vectors)."""
    v, w = q[:3], q[3]
    t = cross(v, u)
    return np.asarray(u, float) + 2.0 * w * t + 2.0 * cross(v, t)


def quat_product(q1, q2) -> np.ndarray:
    """Hamilton product q1 ⊗ q2 of single quaternions (x, y, z, w) (so3.quat_multiply, one item)."""
    v1, w1, v2, w2 = q1[:3], q1[3], q2[:3], q2[3]
    return np.append(w1 * v2 + w2 * v1 + cross(v1, v2), w1 * w2 - v1 @ v2)


def to_body(q_WB, u_W) -> np.ndarray:
    """u_B = R_WB^T u_W (the conjugate rotates back)."""
    q = np.asarray(q_WB, float)
    return rotate(np.append(-q[:3], q[3]), u_W)


def to_world(q_WB, u_B) -> np.ndarray:
    """u_W = R_WB u_B."""
    return rotate(np.asarray(q_WB, float), u_B)


# ---------------------------------------------------------------- applied loads
class Loads(NamedTuple):
    """Resultant of the applied loads at one instant, split by frame of expression: forces through
    the centre of mass [N] and couples [N m] in W and in B (gravity is separate)."""
    f_W: np.ndarray
    f_B: np.ndarray
    n_W: np.ndarray
    n_B: np.ndarray


def no_loads() -> Loads:
    return Loads(np.zeros(3), np.zeros(3), np.zeros(3), np.zeros(3))


class Load(NamedTuple):
    """One load: force through the centre of mass and couple, in `frame` ('world' or 'body'),
    active for t_start <= t < t_end."""
    force: np.ndarray
    torque: np.ndarray
    frame: str = "world"
    t_start: float = -np.inf
    t_end: float = np.inf


def loads_at(schedule, t: float) -> Loads:
    """Sum of the loads of `schedule` active at time t (a piecewise-constant schedule)."""
    total = no_loads()
    for load in schedule:
        if not (load.t_start <= t < load.t_end):
            continue
        f, n = np.asarray(load.force, float), np.asarray(load.torque, float)
        if load.frame == "world":
            total = total._replace(f_W=total.f_W + f, n_W=total.n_W + n)
        else:
            total = total._replace(f_B=total.f_B + f, n_B=total.n_B + n)
    return total


def step_pieces(schedule, t: float, h: float):
    """The pieces (start, length) of a step from t to t + h between the switch times of `schedule`
    (its finite t_start and t_end strictly inside the step), for integrating a piecewise-constant
    schedule exactly: each piece takes the loads active at its start. One piece (t, h) when no
    switch time falls inside the step."""
    cuts = sorted({b for load in schedule for b in (load.t_start, load.t_end) if t < b < t + h})
    if not cuts:
        return [(t, h)]
    ends = cuts + [t + h]
    return [(a, b - a) for a, b in zip([t] + cuts, ends)]


def wrench_of_force_at_point(q_WB, force, point, frame="world"):
    """A force applied at a point of the body, reduced to the centre of mass: the same force and the
    couple r × f (moment about the centre of mass, Rigid-body notes (4.41)). `point` is the point's position
    relative to the centre of mass; `force` and `point` are both expressed in `frame`.
    Returns (f_W, n_B)."""
    f, r = np.asarray(force, float), np.asarray(point, float)
    n = cross(r, f)
    if frame == "world":
        return f, to_body(q_WB, n)
    return to_world(q_WB, f), n


def body_wrench(q_WB, loads: Loads, mass: float = 0.0, g_W=None):
    """Total force in W (gravity m g included) and couple in B at attitude q_WB (normalised first:
    the body-frame parts turn with the body)."""
    u = np.asarray(q_WB, float) / np.linalg.norm(q_WB)
    f_W = loads.f_W + to_world(u, loads.f_B) + mass * _vec(g_W)
    n_B = loads.n_B + to_body(u, loads.n_W)
    return f_W, n_B


# ---------------------------------------------------------------- particle (Rigid-body notes §4.11)
def particle_acceleration(mass, f_W, g_W=None) -> np.ndarray:
    """a = f/m + g (Rigid-body notes (4.35) with the weight m g added to the applied force)."""
    return np.asarray(f_W, float) / mass + _vec(g_W)


def particle_force(mass, a_W, g_W=None) -> np.ndarray:
    """Inverse of particle_acceleration: the applied force a motion requires, f = m (a - g)."""
    return mass * (np.asarray(a_W, float) - _vec(g_W))


def linear_momentum(mass, v_W) -> np.ndarray:
    """p = m v (Rigid-body notes (4.36)); for a rigid body v is the centre-of-mass velocity."""
    return mass * np.asarray(v_W, float)


# ---------------------------------------------------------------- planar rigid body (Craig)
def rot2(theta) -> np.ndarray:
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


def planar_force_W(mass, theta, loads: Loads, g_W=None) -> np.ndarray:
    """In-plane resultant in W: f_W.xy + Rz(θ) f_B.xy + m g.xy."""
    return loads.f_W[:2] + rot2(theta) @ loads.f_B[:2] + mass * _vec(g_W)[:2]


def planar_accelerations(mass, inertia_zz, theta, loads: Loads, g_W=None):
    """Plane kinetics (Craig): Σf = m a_G, Σn_z = I_zz α. Returns (a_G (2,), α)."""
    f = planar_force_W(mass, theta, loads, g_W)
    return f / mass, (loads.n_W[2] + loads.n_B[2]) / inertia_zz


def planar_loads(mass, inertia_zz, a_G, alpha, g_W=None):
    """Inverse plane kinetics: the in-plane force in W and the couple about z a motion requires."""
    return mass * (np.asarray(a_G, float) - _vec(g_W)[:2]), inertia_zz * alpha


# ---------------------------------------------------------------- spatial rigid body
def gyroscopic_term(I, w_B) -> np.ndarray:
    """ω × I ω (Craig "Euler's equations"; zero for a spherical inertia)."""
    return cross(w_B, np.asarray(I, float) @ w_B)


def euler_angular_acceleration(I, w_B, n_B) -> np.ndarray:
    """ω̇ = I⁻¹ (n - ω × I ω): Euler's law (Rigid-body notes (4.69)) in the body frame, full form with
    products of inertia."""
    return np.linalg.solve(np.asarray(I, float), np.asarray(n_B, float) - gyroscopic_term(I, w_B))


def euler_angular_acceleration_principal(I_diag, w_B, n_B) -> np.ndarray:
    """Euler's equations on principal axes, written component by component as in Craig:
    I1 ω̇1 + (I3 - I2) ω2 ω3 = M1, I2 ω̇2 + (I1 - I3) ω3 ω1 = M2, I3 ω̇3 + (I2 - I1) ω1 ω2 = M3."""
    I1, I2, I3 = I_diag
    w1, w2, w3 = w_B
    M1, M2, M3 = n_B
    return np.array([(M1 - (I3 - I2) * w2 * w3) / I1,
                     (M2 - (I1 - I3) * w3 * w1) / I2,
                     (M3 - (I2 - I1) * w1 * w2) / I3])


def euler_torque(I, w_B, dw_B) -> np.ndarray:
    """Inverse of Euler's equations: n = I ω̇ + ω × I ω (the couple about the centre of mass a
    rotation requires)."""
    return np.asarray(I, float) @ dw_B + gyroscopic_term(I, w_B)


def rigid_body_accelerations(mass, I, q_WB, w_B, loads: Loads, g_W=None):
    """Newton–Euler forward dynamics (Rigid-body notes (4.58), (4.69)): returns (a_W, ω̇_B)."""
    f_W, n_B = body_wrench(q_WB, loads, mass, g_W)
    return f_W / mass, euler_angular_acceleration(I, w_B, n_B)


def rigid_body_wrench(mass, I, w_B, a_W, dw_B, g_W=None):
    """Newton–Euler inverse dynamics: the applied force f_W (gravity excluded) and couple n_B about
    the centre of mass that produce the accelerations (a_W, ω̇_B)."""
    return mass * (np.asarray(a_W, float) - _vec(g_W)), euler_torque(I, w_B, dw_B)


# ---------------------------------------------------------------- momentum, energy, power
def angular_momentum_about_com(I, q_WB, w_B, frame="world") -> np.ndarray:
    """H_C = I ω (Rigid-body notes (4.67)): in B as I w_B, in W as R_WB I w_B."""
    h_B = np.asarray(I, float) @ w_B
    return h_B if frame == "body" else to_world(q_WB, h_B)


def angular_momentum_about_point(mass, I, p_W, q_WB, v_W, w_B, point_W) -> np.ndarray:
    """H_P = r_PC × L + H_C in W, L = m v_C, r_PC = p_C - p_P (Craig "H_P = (r^PC x L) + H";
    Rigid-body notes (4.65) for P the origin). Holds for a fixed point and for any point P."""
    r_PC = np.asarray(p_W, float) - np.asarray(point_W, float)
    return cross(r_PC, linear_momentum(mass, v_W)) + angular_momentum_about_com(I, q_WB, w_B)


def kinetic_energy(mass, I, v_W, w_B):
    """(T_translation, T_rotation) = (½ m v·v, ½ ω·I ω) (Craig "Kinetic Energy")."""
    v, w = np.asarray(v_W, float), np.asarray(w_B, float)
    return 0.5 * mass * v @ v, 0.5 * w @ np.asarray(I, float) @ w


def potential_energy(mass, p_W, g_W=None) -> float:
    """V = -m g·p of uniform gravity (zero at the origin)."""
    return -mass * _vec(g_W) @ np.asarray(p_W, float)


def power(f_W, n_B, v_W, w_B) -> float:
    """P = f·v_C + n·ω of a force through the centre of mass and a couple (each dot product in one
    frame); the rate of the work-energy equation T2 - T1 = U12 (Craig)."""
    return float(np.asarray(f_W, float) @ v_W + np.asarray(n_B, float) @ w_B)


def point_velocity(q_WB, v_W, w_B, point_B) -> np.ndarray:
    """Velocity in W of the body point at point_B (from the centre of mass, in B): v + ω × r."""
    return np.asarray(v_W, float) + to_world(q_WB, cross(w_B, point_B))


def apply_impulse(mass, I, q_WB, v_W, w_B, impulse, point, frame="world", angular_impulse=None):
    """Instant change of velocities from an impulse J [N s] applied at `point` (from the centre of
    mass) and an angular impulse K [N m s], all three in `frame`: impulse–momentum (Craig)
    m Δv = J, ΔH_C = r × J + K, so Δv_W = J_W / m and Δω_B = I⁻¹ (r × J + K)_B.
    Returns (v_W', w_B')."""
    J_W, dH_B = wrench_of_force_at_point(q_WB, impulse, point, frame)
    K = _vec(angular_impulse)
    dH_B = dH_B + (K if frame == "body" else to_body(q_WB, K))
    return (np.asarray(v_W, float) + J_W / mass,
            np.asarray(w_B, float) + np.linalg.solve(np.asarray(I, float), dH_B))
