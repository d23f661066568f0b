"""Fixed-step integrators for the particle, the planar body and the spatial rigid body, in plain numpy.

Each model's state is a flat coordinate vector whose last entry is the work W [J] done by the
applied loads and gravity since the start, integrated with the motion (dW/dt = power), so that the
work-energy equation T2 - T1 = U12 (Craig) can be checked:
  particle     y = (p_W:3, v_W:3, W)                                  (7,)
  planar body  y = (x, y, θ, v_x, v_y, ω, W)                          (7,)
  rigid body   y = (p_W:3, q_WB (x,y,z,w):4, v_W:3, w_B:3, W)         (14,)
Loads (dynamics.Loads) are piecewise constant: simulate splits a step at a switch time.

Methods (the names of rigiddyn.methods()):
- explicit_euler: y1 = y0 + h f(y0), quaternion renormalised (Euler 1768; order 1).
- semi_implicit_euler: "kick then drift", v1 = v0 + h a(x0, v0), x1 = x0 ⊕ h v1 with the exact
  exponential q1 = q0 ⊗ exp(h ω1 / 2); explicit gyroscopic term ω1 = ω0 + h I⁻¹(n - ω0 × I ω0).
- semi_implicit_euler_implicit_gyroscopic: the kick of ω solves I(ω1 - ω0) + h ω1 × I ω1 = h n by
  one Newton step from ω1 = ω0.
- rk4: classical Runge–Kutta 4 (Kutta 1901) on the coordinates, the quaternion as a 4-vector,
  renormalised at the end of the step.
- rkmk4: Runge–Kutta–Munthe-Kaas (Munthe-Kaas 1999; Hairer, Lubich, Wanner, Geometric Numerical
  Integration, IV.8.2, Algorithm 8.4) with the RK4 tableau on (vector space) × SO(3): stage
  increments Θ_i = h Σ_j a_ij K_j, K_i = dexp⁻¹(ξ(y0 ⊕ Θ_i)), y1 = y0 ⊕ h Σ b_i K_i, dexp⁻¹
  truncated after the second commutator (the Bernoulli series B0, B1, B2: enough for order 4).
"""

from __future__ import annotations

import numpy as np

from . import dynamics as dyn
from .so3 import hat, rotvec_to_quat

# classical RK4 tableau (Kutta 1901)
RK4_C = (0.0, 0.5, 0.5, 1.0)
RK4_A = ((), (0.5,), (0.0, 0.5), (0.0, 0.0, 1.0))
RK4_B = (1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0)
# Bernoulli numbers B0, B1, B2 of dexp⁻¹_Ω(H) = Σ_k B_k / k! ad_Ω^k H (HLW III.4, Lemma 4.2)
BERNOULLI = (1.0, -0.5, 1.0 / 6.0)

METHODS = ("explicit_euler", "semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic",
           "rk4", "rkmk4")


# ---------------------------------------------------------------- models
class ParticleModel:
    """m p̈ = f + m g (Rigid-body notes (4.35)). 'Body' forces are world forces (no attitude)."""

    def __init__(self, mass, g_W=None):
        self.mass, self.g_W = float(mass), dyn._vec(g_W)
        self.set_loads(dyn.no_loads())

    def set_loads(self, loads):
        self.f = loads.f_W + loads.f_B + self.mass * self.g_W

    @staticmethod
    def initial(p_W, v_W, work=0.0):
        return np.concatenate([p_W, v_W, [work]]).astype(float)

    def rate(self, y):
        v = y[3:6]
        return np.concatenate([v, dyn.particle_acceleration(self.mass, self.f), [self.f @ v]])

    velocity = rate

    def kick(self, y, h, implicit_gyroscopic=False):
        y[3:6] += h * dyn.particle_acceleration(self.mass, self.f)

    def drift(self, y, h):
        y[6] += h * (self.f @ y[3:6])
        y[0:3] += h * y[3:6]

    def loads_kick(self, y, h):
        """The exact flow of the loads part over h (the force constant): v kicked, the work by the kinetic energy
        it gives, h f·v̄ with v̄ the mean velocity of the kick (work–energy principle, Craig)."""
        dv = h * dyn.particle_acceleration(self.mass, self.f)
        y[6] += h * (self.f @ (y[3:6] + dv / 2))
        y[3:6] += dv

    @staticmethod
    def free_flow(y, h):
        """The free part over h: p moved by v, no work."""
        y[0:3] += h * y[3:6]

    def energies(self, y):
        """(kinetic, potential, |H_C|, |q|)."""
        return (0.5 * self.mass * y[3:6] @ y[3:6], dyn.potential_energy(self.mass, y[0:3], self.g_W),
                0.0, 1.0)


class PlanarBodyModel:
    """Plane kinetics (Craig): m a_G = Σf, I_zz α = Σn_z, B turned by θ about z."""

    def __init__(self, mass, inertia_zz, g_W=None):
        self.mass, self.inertia_zz, self.g_W = float(mass), float(inertia_zz), dyn._vec(g_W)
        self.set_loads(dyn.no_loads())

    def set_loads(self, loads):
        self.loads = loads

    @staticmethod
    def initial(p_W, theta, v_W, omega, work=0.0):
        return np.concatenate([p_W, [theta], v_W, [omega], [work]]).astype(float)

    def _force_couple(self, theta):
        return (dyn.planar_force_W(self.mass, theta, self.loads, self.g_W),
                self.loads.n_W[2] + self.loads.n_B[2])

    def rate(self, y):
        f, n = self._force_couple(y[2])
        a, alpha = dyn.planar_accelerations(self.mass, self.inertia_zz, y[2], self.loads, self.g_W)
        return np.concatenate([y[3:6], a, [alpha], [f @ y[3:5] + n * y[5]]])

    velocity = rate

    def kick(self, y, h, implicit_gyroscopic=False):  # no gyroscopic term in plane motion
        a, alpha = dyn.planar_accelerations(self.mass, self.inertia_zz, y[2], self.loads, self.g_W)
        y[3:5] += h * a
        y[5] += h * alpha

    def drift(self, y, h):
        f, n = self._force_couple(y[2])
        y[6] += h * (f @ y[3:5] + n * y[5])
        y[0:3] += h * y[3:6]

    def loads_kick(self, y, h):
        """The exact flow of the loads part over h (x, y and θ frozen, so the wrench is constant): the velocities
        kicked, the work by the kinetic energy it gives, h (f·v̄ + n ω̄) with v̄, ω̄ the kick's mean velocities
        (work–energy principle, Craig)."""
        f, n = self._force_couple(y[2])
        a, alpha = dyn.planar_accelerations(self.mass, self.inertia_zz, y[2], self.loads, self.g_W)
        dv, dw = h * a, h * alpha
        y[6] += h * (f @ (y[3:5] + dv / 2) + n * (y[5] + dw / 2))
        y[3:5] += dv
        y[5] += dw

    @staticmethod
    def free_flow(y, h):
        """The free part over h: x, y and θ moved by the velocities, no work."""
        y[0:3] += h * y[3:6]

    def energies(self, y):
        T = 0.5 * self.mass * y[3:5] @ y[3:5] + 0.5 * self.inertia_zz * y[5] ** 2
        return (T, -self.mass * self.g_W[:2] @ y[0:2], self.inertia_zz * abs(y[5]), 1.0)


def implicit_gyroscopic_kick(I, w, n, h):
    """One Newton step on F(ω') = I(ω' - ω) + h ω' × I ω' - h n = 0 from ω' = ω:
    F(ω) = h (ω × I ω - n), ∂F/∂ω' = I + h ([ω']x I - [I ω']x), ω' = ω - (∂F/∂ω')⁻¹ F(ω)."""
    Iw = I @ w
    F = h * (dyn.cross(w, Iw) - n)
    J = I + h * (hat(w) @ I - hat(Iw))
    return w - np.linalg.solve(J, F)


class RigidBodyModel:
    """Newton–Euler about the centre of mass (Rigid-body notes (4.58), (4.69); Craig):
    ṗ = v, q̇ = ½ q ⊗ (ω_B, 0), m v̇ = f_W + m g, I ω̇ + ω × I ω = n_B."""

    def __init__(self, mass, inertia_com, g_W=None):
        self.mass, self.I, self.g_W = float(mass), np.asarray(inertia_com, float), dyn._vec(g_W)
        self.set_loads(dyn.no_loads())

    def set_loads(self, loads):
        self.loads = loads

    @staticmethod
    def initial(p_W, q_WB, v_W, w_B, work=0.0):
        return np.concatenate([p_W, q_WB, v_W, w_B, [work]]).astype(float)

    def _accelerations(self, y):
        f_W, n_B = dyn.body_wrench(y[3:7], self.loads, self.mass, self.g_W)
        w = y[10:13]
        return f_W / self.mass, dyn.euler_angular_acceleration(self.I, w, n_B), \
            dyn.power(f_W, n_B, y[7:10], w)

    def rate(self, y):
        a, dw, P = self._accelerations(y)
        q_dot = 0.5 * dyn.quat_product(y[3:7], np.concatenate([y[10:13], [0.0]]))
        return np.concatenate([y[7:10], q_dot, a, dw, [P]])

    def velocity(self, y):
        """ξ = (v_W, ω_B, a_W, ω̇_B, power) (13,): the attitude part body-trivialised."""
        a, dw, P = self._accelerations(y)
        return np.concatenate([y[7:10], y[10:13], a, dw, [P]])

    @staticmethod
    def retract(y, theta):
        """y ⊕ Θ: vector parts added, q ⊗ exp(Θ_rot) for the attitude."""
        return np.concatenate([y[0:3] + theta[0:3], dyn.quat_product(y[3:7], rotvec_to_quat(theta[3:6])),
                               y[7:14] + theta[6:13]])

    @staticmethod
    def dexp_inv(theta, xi):
        """Body-trivialised: R = R0 exp([Θ]x) gives Θ̇ = dexp⁻¹_{-Θ}(ω) with dexp⁻¹_Ω(H) =
        Σ_k B_k/k! ad_Ω^k H, ad_Ω H = Ω × H in so(3), truncated at k = 2."""
        out = np.array(xi, dtype=float)
        omega, h = -theta[3:6], xi[3:6]
        ad1 = dyn.cross(omega, h)
        ad2 = dyn.cross(omega, ad1)
        out[3:6] = BERNOULLI[0] * h + BERNOULLI[1] * ad1 + BERNOULLI[2] / 2.0 * ad2
        return out

    @staticmethod
    def project(y):
        y[3:7] /= np.linalg.norm(y[3:7])

    def kick(self, y, h, implicit_gyroscopic=False):
        f_W, n_B = dyn.body_wrench(y[3:7], self.loads, self.mass, self.g_W)
        y[7:10] += h * f_W / self.mass
        w = y[10:13]
        if implicit_gyroscopic:
            y[10:13] = implicit_gyroscopic_kick(self.I, w, n_B, h)
        else:
            y[10:13] = w + h * dyn.euler_angular_acceleration(self.I, w, n_B)

    def drift(self, y, h):
        f_W, n_B = dyn.body_wrench(y[3:7], self.loads, self.mass, self.g_W)
        y[13] += h * dyn.power(f_W, n_B, y[7:10], y[10:13])
        y[0:3] += h * y[7:10]
        q = dyn.quat_product(y[3:7], rotvec_to_quat(h * y[10:13]))
        y[3:7] = q / np.linalg.norm(q)

    def energies(self, y):
        T_trans, T_rot = dyn.kinetic_energy(self.mass, self.I, y[7:10], y[10:13])
        return (T_trans + T_rot, dyn.potential_energy(self.mass, y[0:3], self.g_W),
                np.linalg.norm(self.I @ y[10:13]), np.linalg.norm(y[3:7]))


# ---------------------------------------------------------------- methods
def _project(model, y):
    if hasattr(model, "project"):
        model.project(y)
    return y


def explicit_euler(model, y, h):
    return _project(model, y + h * model.rate(y))


def semi_implicit_euler(model, y, h, implicit_gyroscopic=False):
    y = np.array(y, dtype=float)
    model.kick(y, h, implicit_gyroscopic)
    model.drift(y, h)
    return y


def rk4(model, y, h):
    k = []
    for i in range(4):
        stage = y + h * sum((a * kj for a, kj in zip(RK4_A[i], k)), np.zeros_like(y))
        k.append(model.rate(stage))
    return _project(model, y + h * sum(b * ki for b, ki in zip(RK4_B, k)))


def rkmk4(model, y, h):
    if not hasattr(model, "retract"):  # a vector space: RKMK is RK4
        return rk4(model, y, h)
    K = []
    for i in range(4):
        theta = h * sum((a * Kj for a, Kj in zip(RK4_A[i], K)), np.zeros(13))
        K.append(model.dexp_inv(theta, model.velocity(model.retract(y, theta))))
    return _project(model, model.retract(y, h * sum(b * Ki for b, Ki in zip(RK4_B, K))))


def step(model, y, h, method):
    """One step of `method` (a name from METHODS)."""
    if method == "explicit_euler":
        return explicit_euler(model, y, h)
    if method == "semi_implicit_euler":
        return semi_implicit_euler(model, y, h, False)
    if method == "semi_implicit_euler_implicit_gyroscopic":
        return semi_implicit_euler(model, y, h, True)
    if method == "rk4":
        return rk4(model, y, h)
    if method == "rkmk4":
        return rkmk4(model, y, h)
    raise ValueError(f"method: expected one of {METHODS}, got {method!r}")


def simulate(model, y0, h, steps, method, schedule=(), t0=0.0):
    """`steps` steps from y0 at t0; a step across a switch time of the schedule is split there
    (dynamics.step_pieces), each piece with the loads active on it. Returns the final coordinates."""
    y = np.array(y0, dtype=float)
    for i in range(steps):
        for start, length in dyn.step_pieces(schedule, t0 + i * h, h):
            model.set_loads(dyn.loads_at(schedule, start))
            y = step(model, y, length, method)
    return y
