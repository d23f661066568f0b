"""Scenes (bodies + force elements) in plain numpy: each force model its own function, Newton–Euler per
body, a scene derivative and classical RK4. The oracle of rigiddyn's scenes; it never imports
rigiddyn or scipy.

Written from the texts: Newton's law f = m a per body (Rigid-body notes (4.35), at the centre of mass
(4.58)); Euler's law in B, I ω̇ + ω × I ω = n (Craig, "Euler's equations"); action and reaction, f_ij =
−f_ji (Rigid-body notes (4.49)); the moment of a force r × f (Rigid-body notes (4.41)); Newtonian gravity
F = G M m / r² along the line of centres (Craig, "Basic Concepts": Mass); plane kinetics Σf = m a_G,
Σn_z = I α (Craig, "Rigid Body Plane Kinetics"); the work–energy equation T2 − T1 = U12 (Craig,
"Work-Energy Equation"). The gravity-gradient term is MacCullagh's second-order potential of a central
attractor on an extended body, V₂ = −GM/(2|r|³)(tr I − 3 r̂ᵀ I_W r̂); its force is derived below. The
magnetic dipole is standard magnetostatics (Jackson, "Classical Electrodynamics", §5.6: the field of a
magnetic dipole, B = μ0/(4π) (3 r̂ (r̂·M) − M)/|r|³; §5.7: on a dipole m in a field B the torque τ = m × B,
the energy U = −m·B and the force ∇(m·B)), with μ0 of CODATA 2018. The reaction wheel is the gyrostat of Hughes,
"Spacecraft Attitude Dynamics", ch. 3: a rigid body carrying a wheel spun about an axis fixed in it, whose
Euler equation I ω̇ + ω × (I ω + h) = n − ḣ (I the whole body's inertia, h the wheel's angular momentum
relative to the body) makes the wheel a couple −ω × h − ḣ on the body.

Bodies (`particle`, `planar`, `rigid`) and the per-body state layout (y, a flat vector), per body:
  particle  (p_W:3, v_W:3)                                      6
  planar    (x, y, θ, v_x, v_y, ω)                               6
  rigid     (p_W:3, q_WB (x,y,z,w):4, v_W:3, w_B:3)              13
then t [s], then one work slot per element [J] (dW_e/dt = its power), as rigiddyn's SceneModel.
Kinematics as the elements see them: a particle has q = identity, w = 0; a planar body p = (x, y, 0),
q = Rz(θ), v = (v_x, v_y, 0), w = (0, 0, ω). A planar body keeps only the in-plane part of a wrench
(f_x, f_y, n_z): the plane's reaction takes the rest.

An element is data, Element(kind, params) with the parameter names of rigiddyn's Python classes
(UniformGravity, PointMassGravity, ZonalGravity, MutualGravity, GravityGradient, SpringDamper, Drag,
AtmosphericDrag, SolarRadiationPressure, ScheduledLoads, MagneticDipole, ReactionWheel); `evaluate` calls the force model of its kind, which returns an Effect: the force
f_W (nb, 3) [N] in W at each centre of mass, the couple tau_B (nb, 3) [N m] in each body's B, the power
Σ f·v + τ·ω [W] and the potential [J] (0 where the model has none). rk4_step splits a step at the schedules'
switch times, as rigiddyn does, and at a wheel's t_start and t_end, where its rate dΩ/dt jumps.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from .dynamics import cross, loads_at, quat_product, to_body, to_world
from .so3 import quat_to_matrix

IDENTITY = np.array([0.0, 0.0, 0.0, 1.0])
STATE_SIZE = {"particle": 6, "planar": 6, "rigid": 13}


# ---------------------------------------------------------------- bodies and kinematics
class Body(NamedTuple):
    """kind 'particle' | 'planar' | 'rigid'; mass [kg]; inertia (3, 3) [kg m²] about the centre of mass in
    B (zero for a particle, diag(0, 0, I_zz) for a planar body: only I_zz acts in the plane)."""
    kind: str
    mass: float
    inertia: np.ndarray


def particle(mass) -> Body:
    return Body("particle", float(mass), np.zeros((3, 3)))


def planar(mass, inertia_zz) -> Body:
    return Body("planar", float(mass), np.diag([0.0, 0.0, float(inertia_zz)]))


def rigid(mass, inertia) -> Body:
    """inertia: principal moments (3,) or the full (3, 3) matrix about the centre of mass in B."""
    inertia = np.asarray(inertia, float)
    return Body("rigid", float(mass), np.diag(inertia) if inertia.ndim == 1 else inertia)


class Kinematics(NamedTuple):
    """One body's kinematics: p_W [m], q_WB (x, y, z, w), v_W [m/s] (centre of mass, in W), w_B [rad/s]."""
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray


def rz_quat(theta) -> np.ndarray:
    """q of the rotation by θ [rad] about z: (0, 0, sin θ/2, cos θ/2)."""
    return np.array([0.0, 0.0, np.sin(theta / 2.0), np.cos(theta / 2.0)])


def body_offsets(bodies) -> list[int]:
    """Index in y of each body's first coordinate (and, last, the index of t)."""
    return list(np.cumsum([0] + [STATE_SIZE[b.kind] for b in bodies]))


def kinematics(bodies, y) -> list[Kinematics]:
    """The kinematics of every body from the scene state y."""
    out = []
    for body, o in zip(bodies, body_offsets(bodies)):
        s = y[o:o + STATE_SIZE[body.kind]]
        if body.kind == "particle":
            out.append(Kinematics(s[0:3], IDENTITY, s[3:6], np.zeros(3)))
        elif body.kind == "planar":
            out.append(Kinematics(np.array([s[0], s[1], 0.0]), rz_quat(s[2]), np.array([s[3], s[4], 0.0]),
                                  np.array([0.0, 0.0, s[5]])))
        else:
            out.append(Kinematics(s[0:3], s[3:7] / np.linalg.norm(s[3:7]), s[7:10], s[10:13]))
    return out


def state_of(bodies, kin, t=0.0, n_elements=0) -> np.ndarray:
    """The scene state y from every body's kinematics (planar: in-plane parts, θ from q = Rz(θ)), time t
    and zero work."""
    parts = []
    for body, k in zip(bodies, kin):
        if body.kind == "particle":
            parts += [k.p_W, k.v_W]
        elif body.kind == "planar":
            theta = 2.0 * np.arctan2(k.q_WB[2], k.q_WB[3])
            parts += [k.p_W[:2], [theta], k.v_W[:2], [k.w_B[2]]]
        else:
            parts += [k.p_W, k.q_WB, k.v_W, k.w_B]
    return np.concatenate([np.concatenate(parts), [t], np.zeros(n_elements)]).astype(float)


def point_position(k: Kinematics, r_B) -> np.ndarray:
    """x = p_W + R_WB r_B: the world position of the body point r_B (from the centre of mass, in B)."""
    return k.p_W + to_world(k.q_WB, r_B)


def point_velocity(k: Kinematics, r_B) -> np.ndarray:
    """ẋ = v_W + R_WB (ω_B × r_B) (Craig, velocity of a point of a rigid body)."""
    return k.v_W + to_world(k.q_WB, cross(k.w_B, r_B))


# ---------------------------------------------------------------- force models
class Effect(NamedTuple):
    """An element's action: f_W (nb, 3) [N] at each centre of mass in W, tau_B (nb, 3) [N m] in each B,
    power [W] = Σ f·v + τ·ω over the bodies, potential [J] (0 without one)."""
    f_W: np.ndarray
    tau_B: np.ndarray
    power: float
    potential: float


def _acting(bodies, which) -> list[int]:
    """The indices an element acts on: `which` (None or empty: every body)."""
    return list(range(len(bodies))) if not which else list(which)


def _effect(f_W, tau_B, kin, potential=0.0) -> Effect:
    power = sum(f @ k.v_W + tau @ k.w_B for f, tau, k in zip(f_W, tau_B, kin))
    return Effect(f_W, tau_B, float(power), float(potential))


def _zeros(bodies):
    return np.zeros((len(bodies), 3)), np.zeros((len(bodies), 3))


def uniform_gravity(bodies, kin, t, g_W, bodies_acted=None) -> Effect:
    """f = m g at the centre of mass; V = −m g·p (Craig, "Work-Energy Equation": the work of a constant
    force)."""
    f_W, tau_B = _zeros(bodies)
    g_W, potential = np.asarray(g_W, float), 0.0
    for i in _acting(bodies, bodies_acted):
        f_W[i] = bodies[i].mass * g_W
        potential -= bodies[i].mass * g_W @ kin[i].p_W
    return _effect(f_W, tau_B, kin, potential)


def _inverse_square(gm_m, r, softening):
    """Newtonian attraction towards the source of a body at r from it: f = −GMm r/(|r|² + ε²)^{3/2}, and
    V = −GMm/√(|r|² + ε²) (Craig, F = G M m / r² along e_r; ε the softening length)."""
    d2 = r @ r + softening * softening
    return -gm_m * r / d2 ** 1.5, -gm_m / np.sqrt(d2)


def point_mass_gravity(bodies, kin, t, gm, p_W, softening=0.0, bodies_acted=None) -> Effect:
    """A fixed attractor of gravitational parameter GM [m³/s²] at p_W: r = p_body − p_W."""
    f_W, tau_B = _zeros(bodies)
    potential = 0.0
    for i in _acting(bodies, bodies_acted):
        f, v = _inverse_square(gm * bodies[i].mass, kin[i].p_W - np.asarray(p_W, float), softening)
        f_W[i] += f
        potential += v
    return _effect(f_W, tau_B, kin, potential)


def _zonal_acceleration(gm, radius, j2, j3, j4, r_W, k_W):
    """The acceleration of the zonal terms J2, J3, J4 at r_W from the centre, pole k_W (unit), in the Cartesian
    form of Vallado, "Fundamentals of Astrodynamics and Applications", §8.7 (x, y across the pole axis, z along
    it): each a_perp (along r − z k) and a_z (along k) of its term."""
    z = r_W @ k_W
    r2 = r_W @ r_W
    r = np.sqrt(r2)
    s2 = z * z / r2  # sin² of the latitude
    c2 = -1.5 * j2 * gm * radius**2 / r**5
    c3 = -2.5 * j3 * gm * radius**3 / r**7
    c4 = 1.875 * j4 * gm * radius**4 / r**7
    a_perp = c2 * (1.0 - 5.0 * s2) + c3 * (3.0 * z - 7.0 * z * s2) + c4 * (1.0 - 14.0 * s2 + 21.0 * s2 * s2)
    a_z = (c2 * z * (3.0 - 5.0 * s2) + c3 * (6.0 * z * z - 7.0 * z * z * s2 - 0.6 * r2)
           + c4 * z * (5.0 - 70.0 / 3.0 * s2 + 21.0 * s2 * s2))
    return a_perp * (r_W - z * k_W) + a_z * k_W


def zonal_gravity(bodies, kin, t, gm, radius, j2=0.0, j3=0.0, j4=0.0, p_W=(0.0, 0.0, 0.0), pole_W=(0.0, 0.0, 1.0),
                  bodies_acted=None) -> Effect:
    """An oblate central body at p_W, pole along pole_W: the point-mass attraction plus the zonal terms;
    V = −GM m/r [1 − Σ J_n (R/r)^n P_n(sin latitude)] (Vallado §8.7)."""
    f_W, tau_B = _zeros(bodies)
    k_W = np.asarray(pole_W, float) / np.linalg.norm(pole_W)
    potential = 0.0
    for i in _acting(bodies, bodies_acted):
        m, r_W = bodies[i].mass, kin[i].p_W - np.asarray(p_W, float)
        f, v = _inverse_square(gm * m, r_W, 0.0)
        f_W[i] += f + m * _zonal_acceleration(gm, radius, j2, j3, j4, r_W, k_W)
        r = np.linalg.norm(r_W)
        u = r_W @ k_W / r
        legendre = ((3 * u**2 - 1) / 2, (5 * u**3 - 3 * u) / 2, (35 * u**4 - 30 * u**2 + 3) / 8)
        zonal = sum(j * (radius / r) ** n * P for n, j, P in zip((2, 3, 4), (j2, j3, j4), legendre))
        potential += v * (1.0 - zonal)
    return _effect(f_W, tau_B, kin, potential)


def atmospheric_drag(bodies, kin, t, radius, drag_area, density0=0.0, scale_height=0.0, altitude0=0.0,
                     p_W=(0.0, 0.0, 0.0), omega_W=(0.0, 0.0, 0.0), cp_B=(0.0, 0.0, 0.0), bodies_acted=None,
                     table_altitude=(), table_density=()) -> Effect:
    """Drag of an atmosphere turning at omega_W (Vallado §8.6.2): at r = p − p_W, altitude h = |r| − radius,
    ρ = ρ0 exp(−(h − h0)/H), or from a table of rows (h_i, ρ_i): the log-density interpolated linearly in h
    between rows and extended from the outermost bands beyond them (Vallado, Table 8-4); the air's velocity
    omega_W × r, and f = −½ ρ C_D A |v_rel| v_rel applied at the centre of pressure: its moment cp_B × f about the
    centre of mass (f in B)."""
    f_W, tau_B = _zeros(bodies)
    omega_W, cp_B = np.asarray(omega_W, float), np.asarray(cp_B, float)
    h_table, log_rho = np.asarray(table_altitude, float), np.log(np.asarray(table_density, float))
    for i in _acting(bodies, bodies_acted):
        r_W = kin[i].p_W - np.asarray(p_W, float)
        h = np.linalg.norm(r_W) - radius
        if h_table.size:
            band = int(np.clip(np.searchsorted(h_table, h, side="right") - 1, 0, h_table.size - 2))
            h_a, h_b = h_table[band], h_table[band + 1]
            rho = np.exp(log_rho[band] + (log_rho[band + 1] - log_rho[band]) * (h - h_a) / (h_b - h_a))
        else:
            rho = density0 * np.exp(-(h - altitude0) / scale_height)
        v_rel = kin[i].v_W - np.cross(omega_W, r_W)
        f_W[i] = -0.5 * rho * drag_area * np.linalg.norm(v_rel) * v_rel
        tau_B[i] = np.cross(cp_B, to_body(kin[i].q_WB, f_W[i]))
    return _effect(f_W, tau_B, kin)


def solar_radiation_pressure(bodies, kin, t, sun_W, area, sun_rate_W=(0.0, 0.0, 0.0), pressure=4.56e-6,
                             reflectivity=1.0, normal_B=(0.0, 0.0, 0.0), specular=0.0, diffuse=0.0,
                             cp_B=(0.0, 0.0, 0.0), shadow_radius=0.0, shadow_p_W=(0.0, 0.0, 0.0),
                             bodies_acted=None) -> Effect:
    """Radiation pressure (Montenbruck & Gill, "Satellite Orbits", §3.4): towards-the-Sun direction s = sun_W turned
    by the rotation vector sun_rate_W t; a cannonball f = −P C_R A s; a flat plate of normal n in W lit on its side
    (cos θ = n·s > 0), f = −P A cos θ [(1 − ρs) s + 2 (ρs cos θ + ρd/3) n]; nothing in the planet's cylindrical
    shadow; the moment cp_B × f about the centre of mass."""
    f_W, tau_B = _zeros(bodies)
    s = np.asarray(sun_W, float) / np.linalg.norm(sun_W)
    turn = np.asarray(sun_rate_W, float) * t
    if np.any(turn):
        s = quat_to_matrix(_rotvec_quat(turn)) @ s
    normal_B, cp_B = np.asarray(normal_B, float), np.asarray(cp_B, float)
    for i in _acting(bodies, bodies_acted):
        r = kin[i].p_W - np.asarray(shadow_p_W, float)
        if r @ s < 0.0 and np.linalg.norm(r - (r @ s) * s) < shadow_radius:
            continue
        if not np.any(normal_B):
            f = -pressure * reflectivity * area * s
        else:
            n = to_world(kin[i].q_WB, normal_B / np.linalg.norm(normal_B))
            cos_theta = n @ s
            f = (-pressure * area * cos_theta * ((1 - specular) * s + 2 * (specular * cos_theta + diffuse / 3) * n)
                 if cos_theta > 0 else np.zeros(3))
        f_W[i] = f
        tau_B[i] = np.cross(cp_B, to_body(kin[i].q_WB, f))
    return _effect(f_W, tau_B, kin)


def _rotvec_quat(phi) -> np.ndarray:
    """The unit quaternion (x, y, z, w) of the rotation vector phi [rad]."""
    angle = np.linalg.norm(phi)
    return np.append(np.sin(angle / 2) * phi / angle, np.cos(angle / 2))


def mutual_gravity(bodies, kin, t, G=6.67430e-11, softening=0.0, bodies_acted=None) -> Effect:
    """Direct sum over the pairs i < j: f on i = −G m_i m_j r_ij/(|r_ij|² + ε²)^{3/2}, r_ij = p_i − p_j,
    and f on j = −(f on i) (action and reaction, Rigid-body notes (4.49))."""
    f_W, tau_B = _zeros(bodies)
    potential = 0.0
    acting = _acting(bodies, bodies_acted)
    for a, i in enumerate(acting):
        for j in acting[a + 1:]:
            f, v = _inverse_square(G * bodies[i].mass * bodies[j].mass, kin[i].p_W - kin[j].p_W, softening)
            f_W[i] += f
            f_W[j] -= f
            potential += v
    return _effect(f_W, tau_B, kin, potential)


def gravity_gradient_potential(gm, r_W, inertia_W) -> float:
    """V₂ = −GM/(2|r|³)(tr I − 3 r̂ᵀ I_W r̂) [J] (MacCullagh): r from the attractor to the centre of mass."""
    d = np.sqrt(r_W @ r_W)
    u = r_W / d
    return -gm / (2.0 * d ** 3) * (np.trace(inertia_W) - 3.0 * u @ inertia_W @ u)


def gravity_gradient_force(gm, r_W, inertia_W) -> np.ndarray:
    """f = −∇_r V₂. With V₂ = −(GM/2)(tr I |r|⁻³ − 3 rᵀ I r |r|⁻⁵), ∇|r|⁻ⁿ = −n r |r|⁻ⁿ⁻² and
    ∇(rᵀ I r) = 2 I r:
        ∇V₂ = −(GM/2)(−3 tr I r |r|⁻⁵ − 6 I r |r|⁻⁵ + 15 (rᵀ I r) r |r|⁻⁷),
        f = 3GM/(2|r|⁵) ((5 r̂ᵀ I_W r̂ − tr I) r − 2 I_W r)."""
    d = np.sqrt(r_W @ r_W)
    u = r_W / d
    return 3.0 * gm / (2.0 * d ** 5) * ((5.0 * u @ inertia_W @ u - np.trace(inertia_W)) * r_W - 2.0 * inertia_W @ r_W)


def gravity_gradient_torque(gm, r_B, inertia_B) -> np.ndarray:
    """τ_B = 3GM/|r|⁵ r_B × (I r_B): −∂V₂/∂θ, since a small rotation δθ changes r̂ᵀ I_W r̂ by
    2 δθ·(I_W r̂ × r̂)."""
    return 3.0 * gm / np.linalg.norm(r_B) ** 5 * cross(r_B, inertia_B @ r_B)


def gravity_gradient(bodies, kin, t, gm, p_W, bodies_acted=None) -> Effect:
    """The second-order term of a central attractor (GM [m³/s²] at p_W) on each extended body: the torque
    and the matching force of V₂, so that T + V is conserved. Particles: I = 0, no effect. Planar bodies
    are refused (their inertia about x and y is not part of the model)."""
    f_W, tau_B = _zeros(bodies)
    potential = 0.0
    for i in _acting(bodies, bodies_acted):
        body, k = bodies[i], kin[i]
        if body.kind == "planar":
            raise ValueError("gravity_gradient: a planar body's full inertia is undefined")
        if body.kind == "particle":
            continue
        R = quat_to_matrix(k.q_WB)
        r_W = k.p_W - np.asarray(p_W, float)
        inertia_W = R @ body.inertia @ R.T
        f_W[i] = gravity_gradient_force(gm, r_W, inertia_W)
        tau_B[i] = gravity_gradient_torque(gm, R.T @ r_W, body.inertia)
        potential += gravity_gradient_potential(gm, r_W, inertia_W)
    return _effect(f_W, tau_B, kin, potential)


def spring_damper(bodies, kin, t, body_a, point_a_B, stiffness, body_b=None, point_b=(0.0, 0.0, 0.0),
                  rest_length=0.0, damping=0.0) -> Effect:
    """Between the point a of body_a (point_a_B in a's B, from its centre of mass) and the point b of
    body_b (point_b in b's B) or, body_b None/−1, the world anchor point_b (in W). Force on a:
        f = −(k (ℓ − ℓ0) + c ℓ̇) u,  u = (x_a − x_b)/ℓ,  ℓ̇ = u·(ẋ_a − ẋ_b)  (along the line; no force at ℓ = 0);
    −f on b; each applied at its point, so couple r × f (Rigid-body notes (4.41)); V = ½ k (ℓ − ℓ0)²."""
    f_W, tau_B = _zeros(bodies)
    ka = kin[body_a]
    x_a, xd_a = point_position(ka, point_a_B), point_velocity(ka, point_a_B)
    if body_b is None or body_b < 0:
        x_b, xd_b = np.asarray(point_b, float), np.zeros(3)
    else:
        x_b, xd_b = point_position(kin[body_b], point_b), point_velocity(kin[body_b], point_b)
    d, d_dot = x_a - x_b, xd_a - xd_b
    length = np.sqrt(d @ d)
    if length == 0.0:
        f = np.zeros(3)
    else:
        u = d / length
        f = -(stiffness * (length - rest_length) + damping * (u @ d_dot)) * u
    f_W[body_a] += f
    tau_B[body_a] += cross(np.asarray(point_a_B, float), to_body(ka.q_WB, f))
    if body_b is not None and body_b >= 0:
        f_W[body_b] -= f
        tau_B[body_b] += cross(np.asarray(point_b, float), to_body(kin[body_b].q_WB, -f))
    return _effect(f_W, tau_B, kin, 0.5 * stiffness * (length - rest_length) ** 2)


def drag(bodies, kin, t, linear=0.0, quadratic=0.0, angular_linear=0.0, angular_quadratic=0.0,
         bodies_acted=None) -> Effect:
    """f = −(c₁ + c₂|v|) v at the centre of mass, τ_B = −(d₁ + d₂|ω|) ω; no potential."""
    f_W, tau_B = _zeros(bodies)
    for i in _acting(bodies, bodies_acted):
        v, w = kin[i].v_W, kin[i].w_B
        f_W[i] = -(linear + quadratic * np.linalg.norm(v)) * v
        tau_B[i] = -(angular_linear + angular_quadratic * np.linalg.norm(w)) * w
    return _effect(f_W, tau_B, kin)


def scheduled_loads(bodies, kin, t, body, loads, point_B=(0.0, 0.0, 0.0)) -> Effect:
    """The loads (dynamics.Load: force and couple in 'world' or 'body' frame, active for
    t_start <= t < t_end) on `body`, the forces applied at point_B (in B, from the centre of mass):
    couple r_B × f_B added (Rigid-body notes (4.41))."""
    f_W, tau_B = _zeros(bodies)
    k = kin[body]
    active = loads_at(loads, t)
    f = active.f_W + to_world(k.q_WB, active.f_B)
    f_W[body] = f
    tau_B[body] = active.n_B + to_body(k.q_WB, active.n_W) + cross(np.asarray(point_B, float), to_body(k.q_WB, f))
    return _effect(f_W, tau_B, kin)


MU0 = 1.25663706212e-6  # vacuum magnetic permeability μ0 [N/A²] (CODATA 2018)


def dipole_field(moment_W, r_W) -> np.ndarray:
    """B [T] at r_W [m] from a point dipole of moment moment_W [A m²] (both in W):
    B = μ0/(4π) (3 r̂ (r̂·M) − M)/|r|³ (Jackson, §5.6)."""
    d = np.sqrt(r_W @ r_W)
    u = r_W / d
    return MU0 / (4.0 * np.pi) * (3.0 * u * (u @ moment_W) - moment_W) / d ** 3


def magnetic_field(p_W, B_W, source_moment_W, source_p_W) -> np.ndarray:
    """B(p) = B_W + the field of the dipole source_moment_W [A m²] at source_p_W [m] (dipole_field of
    r = p − source_p_W; left out when the moment is zero) [T], at p_W [m]; every vector in W."""
    source_moment_W = np.asarray(source_moment_W, float)
    field = np.array(B_W, float)
    if np.any(source_moment_W != 0.0):
        field += dipole_field(source_moment_W, np.asarray(p_W, float) - np.asarray(source_p_W, float))
    return field


def dipole_dipole_force(m_W, M_W, r_W) -> np.ndarray:
    """f = ∇_r (m·B_M(r)) [N] on the dipole m at r from the dipole M (the attitude of m held). With k = μ0/(4π),
    m·B_M = k (3 (m·r)(M·r)/|r|⁵ − (m·M)/|r|³), ∇(m·r) = m, ∇|r|⁻ⁿ = −n r |r|⁻ⁿ⁻²:
        f = 3k/|r|⁵ ((m·r) M + (M·r) m + (m·M) r − 5 (m·r)(M·r) r/|r|²).
    Symmetric in (m, M) and odd in r: the source feels −f (action and reaction)."""
    d2 = r_W @ r_W
    mr, Mr = m_W @ r_W, M_W @ r_W
    return 3.0 * MU0 / (4.0 * np.pi) / d2 ** 2.5 * (mr * M_W + Mr * m_W + (m_W @ M_W) * r_W - 5.0 * mr * Mr / d2 * r_W)


def magnetic_dipole(bodies, kin, t, m_B, B_W=(0.0, 0.0, 0.0), source_moment_W=(0.0, 0.0, 0.0),
                    source_p_W=(0.0, 0.0, 0.0), bodies_acted=None) -> Effect:
    """Each acting body carries the dipole m_B [A m²] fixed in its B, at its centre of mass, in the field
    B(p) = B_W [T] + the field of the fixed dipole source_moment_W [A m²] at source_p_W [m] (magnetic_field).
    With m_W = R_WB m_B (Jackson, §5.7):
        τ_B = m_B × B_B, B_B = R_WBᵀ B(p);  f_W = ∇_p (m_W·B(p)) (dipole_dipole_force; 0 in the uniform part);
        V = −m_W·B(p) [J],
    so that f·v + τ·ω = −dV/dt. Particles have no attitude: skipped, even when listed. Planar bodies: the
    full wrench (body_rate keeps f_x, f_y and τ_z), with p = (x, y, 0) and q = Rz(θ)."""
    f_W, tau_B = _zeros(bodies)
    m_B, source_moment_W = np.asarray(m_B, float), np.asarray(source_moment_W, float)
    potential = 0.0
    for i in _acting(bodies, bodies_acted):
        if bodies[i].kind == "particle":
            continue
        k = kin[i]
        m_W = to_world(k.q_WB, m_B)
        field_W = magnetic_field(k.p_W, B_W, source_moment_W, source_p_W)
        tau_B[i] = cross(m_B, to_body(k.q_WB, field_W))
        if np.any(source_moment_W != 0.0):
            f_W[i] = dipole_dipole_force(m_W, source_moment_W, k.p_W - np.asarray(source_p_W, float))
        potential -= m_W @ field_W
    return _effect(f_W, tau_B, kin, potential)


def wheel_speed(t, speed, acceleration, t_start, t_end) -> tuple[float, float]:
    """The wheel's speed relative to its body Ω(t) = speed + acceleration (min(max(t, t_start), t_end) − t_start)
    [rad/s] and its rate dΩ/dt [rad/s²]: acceleration for t_start <= t < t_end, 0 outside. t_start finite."""
    ramp = min(max(t, t_start), t_end) - t_start
    return speed + acceleration * ramp, acceleration if t_start <= t < t_end else 0.0


def reaction_wheel(bodies, kin, t, body, axis_B, inertia, speed=0.0, acceleration=0.0, t_start=0.0, t_end=np.inf,
                   rate_time=None) -> Effect:
    """A wheel of moment of inertia J = `inertia` [kg m²] about the unit axis a = axis_B/|axis_B| fixed in the B
    of the rigid body `body`, spun relative to it at Ω(t) (wheel_speed) [rad/s]; the body's inertia is the whole
    body's, wheel included. Its angular momentum relative to the body is h_B = J Ω a and the gyrostat's Euler
    equation (Hughes, ch. 3) I ω̇ + ω × (I ω + h) = n − ḣ makes it the couple
        τ_B = −ω_B × h_B − ḣ_B,  ḣ_B = J (dΩ/dt) a,
    no force, no potential; its power τ·ω = −ḣ·ω (the motor's work: 0 at constant speed). dΩ/dt is read at
    rate_time [s] (default t: rk4_step passes the middle of the piece, so that a step ending at t_end sees the
    ramp throughout). Particles and planar bodies are refused (a wheel needs a full attitude)."""
    if bodies[body].kind != "rigid":
        raise ValueError(f"reaction_wheel: body {body} is a {bodies[body].kind}, expected a rigid body")
    a = np.asarray(axis_B, float) / np.linalg.norm(axis_B)
    omega, _ = wheel_speed(t, speed, acceleration, t_start, t_end)
    _, omega_dot = wheel_speed(t if rate_time is None else rate_time, speed, acceleration, t_start, t_end)
    h_B, h_dot_B = inertia * omega * a, inertia * omega_dot * a
    f_W, tau_B = _zeros(bodies)
    tau_B[body] = -cross(kin[body].w_B, h_B) - h_dot_B
    return _effect(f_W, tau_B, kin)


FORCE_MODELS = {"UniformGravity": uniform_gravity, "PointMassGravity": point_mass_gravity,
                "MutualGravity": mutual_gravity, "GravityGradient": gravity_gradient,
                "SpringDamper": spring_damper, "Drag": drag, "ScheduledLoads": scheduled_loads,
                "MagneticDipole": magnetic_dipole, "ReactionWheel": reaction_wheel, "ZonalGravity": zonal_gravity,
                "AtmosphericDrag": atmospheric_drag, "SolarRadiationPressure": solar_radiation_pressure}


class Element(NamedTuple):
    """A force element as data: kind (a key of FORCE_MODELS, the rigiddyn class name) and its parameters
    with rigiddyn's keyword names (`bodies` the list it acts on, None for every body)."""
    kind: str
    params: dict[str, Any]


def evaluate(element: Element, bodies, kin, t, schedule_time=None) -> Effect:
    """The Effect of one element on the scene's bodies at time t [s]; the piecewise-constant parts read theirs at
    `schedule_time` instead when it is given (the piece of a step they are constant on): a schedule's loads
    (ScheduledLoads), a wheel's rate dΩ/dt (ReactionWheel)."""
    params = dict(element.params)
    if "bodies" in params:
        params["bodies_acted"] = params.pop("bodies")
    if schedule_time is not None and element.kind == "ScheduledLoads":
        t = schedule_time
    if schedule_time is not None and element.kind == "ReactionWheel":
        params["rate_time"] = schedule_time
    return FORCE_MODELS[element.kind](bodies, kin, t, **params)


class Scene(NamedTuple):
    bodies: list
    elements: list


def initial_state(scene: Scene, kin, t=0.0) -> np.ndarray:
    """y at time t [s] from each body's Kinematics, work zero."""
    return state_of(scene.bodies, kin, t, len(scene.elements))


def time_of(scene: Scene, y) -> float:
    return float(y[body_offsets(scene.bodies)[-1]])


def work_of(scene: Scene, y) -> np.ndarray:
    return np.asarray(y[body_offsets(scene.bodies)[-1] + 1:])


# ---------------------------------------------------------------- Newton–Euler and the derivative
def body_rate(body: Body, k: Kinematics, f_W, tau_B) -> np.ndarray:
    """The state rate of one body under the wrench (f_W at the centre of mass, tau_B):
    a = f/m (Rigid-body notes (4.35), (4.58)); rigid: q̇ = ½ q ⊗ (ω_B, 0), I ω̇ = τ − ω × I ω (Craig,
    Euler's equations); planar: in-plane parts only, I_zz ω̇ = τ_z (Craig, plane kinetics)."""
    a_W = np.asarray(f_W, float) / body.mass
    if body.kind == "particle":
        return np.concatenate([k.v_W, a_W])
    if body.kind == "planar":
        return np.array([k.v_W[0], k.v_W[1], k.w_B[2], a_W[0], a_W[1], tau_B[2] / body.inertia[2, 2]])
    w = k.w_B
    q_dot = 0.5 * quat_product(k.q_WB, np.append(w, 0.0))
    w_dot = np.linalg.solve(body.inertia, tau_B - cross(w, body.inertia @ w))
    return np.concatenate([k.v_W, q_dot, a_W, w_dot])


def effects(scene: Scene, y, schedule_time=None) -> list[Effect]:
    """Every element's Effect at the state y (its time t); schedules (ScheduledLoads) and a wheel's rate
    (ReactionWheel) read theirs at `schedule_time` instead when it is given (evaluate)."""
    kin = kinematics(scene.bodies, y)
    t = time_of(scene, y)
    return [evaluate(e, scene.bodies, kin, t, schedule_time) for e in scene.elements]


def rate(scene: Scene, y, schedule_time=None) -> np.ndarray:
    """ẏ: each body's Newton–Euler rate under the sum of the element wrenches, dt/dt = 1, and each
    element's power (the rate of its work). The elements see each attitude as q/|q|; the quaternion rate is
    taken at q itself. schedule_time: as in `effects`."""
    parts = effects(scene, y, schedule_time)
    nb = len(scene.bodies)
    f_W = sum((e.f_W for e in parts), np.zeros((nb, 3)))
    tau_B = sum((e.tau_B for e in parts), np.zeros((nb, 3)))
    rates = []
    for body, o, k, f, tau in zip(scene.bodies, body_offsets(scene.bodies), kinematics(scene.bodies, y), f_W, tau_B):
        if body.kind == "rigid":  # q̇ = ½ q ⊗ ω of the stage's q as it is (the norm is restored after the step)
            k = k._replace(q_WB=y[o + 3:o + 7])
        rates.append(body_rate(body, k, f, tau))
    return np.concatenate(rates + [[1.0], [e.power for e in parts]])


def normalise_attitudes(scene: Scene, y) -> np.ndarray:
    """y with every rigid body's quaternion divided by its norm (the projection after an RK4 step)."""
    y = np.array(y, float)
    for body, o in zip(scene.bodies, body_offsets(scene.bodies)):
        if body.kind == "rigid":
            y[o + 3:o + 7] /= np.linalg.norm(y[o + 3:o + 7])
    return y


def _rk4_piece(scene: Scene, y, h, schedule_time) -> np.ndarray:
    """Classical Runge–Kutta 4 (Kutta 1901) over h [s] on the whole y (quaternions as 4-vectors,
    renormalised at the end); time-dependent forces see the stage times t + c_i h, schedules their
    schedule_time."""
    k1 = rate(scene, y, schedule_time)
    k2 = rate(scene, y + 0.5 * h * k1, schedule_time)
    k3 = rate(scene, y + 0.5 * h * k2, schedule_time)
    k4 = rate(scene, y + h * k3, schedule_time)
    return normalise_attitudes(scene, y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4))


def schedule_switches(scene: Scene) -> list[float]:
    """Every finite switch time (t_start, t_end) [s] of the scene's schedules and of its wheels' ramps."""
    loads = {b for e in scene.elements if e.kind == "ScheduledLoads" for load in e.params["loads"]
             for b in (load.t_start, load.t_end)}
    wheels = {e.params.get(key, default) for e in scene.elements if e.kind == "ReactionWheel"
              for key, default in (("t_start", 0.0), ("t_end", np.inf))}
    return sorted(b for b in loads | wheels if np.isfinite(b))


def rk4_step(scene: Scene, y, h) -> np.ndarray:
    """One RK4 step of h [s] from y, split at the switch times strictly inside it (schedule_switches) into
    pieces, each a full RK4 step during which the schedules hold the loads active inside the piece and the
    wheels their rate dΩ/dt there (read at its middle), so that a piecewise-constant schedule and a wheel's
    ramp are integrated to the method's order."""
    t = time_of(scene, y)
    cuts = [b for b in schedule_switches(scene) if t < b < t + h] + [t + h]
    start = t
    for end in cuts:
        y = _rk4_piece(scene, y, end - start, 0.5 * (start + end))
        start = end
    return y


def rk4_run(scene: Scene, y0, h, steps) -> np.ndarray:
    """(steps + 1, len(y)) states of `steps` RK4 steps of h [s]; t set to t0 + i h after each step."""
    ys = [np.asarray(y0, float)]
    t_index, t0 = body_offsets(scene.bodies)[-1], time_of(scene, y0)
    for i in range(1, steps + 1):
        y = rk4_step(scene, ys[-1], h)
        y[t_index] = t0 + i * h
        ys.append(y)
    return np.array(ys)


# ---------------------------------------------------------------- diagnostics
def kinetic_energy(scene: Scene, y) -> float:
    """T = Σ ½ m v·v + ½ ω·I ω (Craig, "Kinetic Energy") [J]."""
    return float(sum(0.5 * b.mass * k.v_W @ k.v_W + 0.5 * k.w_B @ b.inertia @ k.w_B
                     for b, k in zip(scene.bodies, kinematics(scene.bodies, y))))


def potential_energy(scene: Scene, y) -> float:
    """Σ of the element potentials [J]."""
    return float(sum(e.potential for e in effects(scene, y)))


def linear_momentum(scene: Scene, y) -> np.ndarray:
    """Σ m v_W [kg m/s] (Rigid-body notes (4.36))."""
    return sum(b.mass * k.v_W for b, k in zip(scene.bodies, kinematics(scene.bodies, y)))


def angular_momentum(scene: Scene, y) -> np.ndarray:
    """About W's origin, in W: Σ p × m v + R I ω (H_P = r_PC × L + H_C, Craig) [kg m²/s]."""
    return sum(cross(k.p_W, b.mass * k.v_W) + to_world(k.q_WB, b.inertia @ k.w_B)
               for b, k in zip(scene.bodies, kinematics(scene.bodies, y)))


__all__ = ["Body", "Effect", "Element", "FORCE_MODELS", "IDENTITY", "Kinematics", "MU0", "STATE_SIZE", "Scene",
           "angular_momentum", "body_offsets", "body_rate", "dipole_dipole_force", "dipole_field", "drag", "effects",
           "evaluate", "gravity_gradient", "gravity_gradient_force", "gravity_gradient_potential",
           "gravity_gradient_torque", "initial_state", "kinematics", "kinetic_energy", "linear_momentum",
           "magnetic_dipole", "magnetic_field", "mutual_gravity", "normalise_attitudes", "particle", "planar",
           "point_mass_gravity", "point_position", "point_velocity", "potential_energy", "rate", "reaction_wheel",
           "rigid", "rk4_run", "rk4_step", "rz_quat", "schedule_switches", "scheduled_loads", "spring_damper",
           "state_of", "time_of", "uniform_gravity", "wheel_speed", "work_of"]
