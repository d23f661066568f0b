"""The gyrostat in plain numpy: a rigid body carrying N wheels, each spun about an axis fixed in the body by a
motor, each wheel's speed relative to the body a state. The oracle of rigiddyn's gyrostat body kind; it never
imports rigiddyn or scipy.

Written from Hughes, "Spacecraft Attitude Dynamics", ch. 3 (the gyrostat), with the derivation checked here.
Body data: mass m [kg]; I [kg m²] the WHOLE body's inertia about its centre of mass C in B (platform and wheels,
each wheel counted as if locked to the platform); wheel k: unit axis a_k in B, axial moment J_k [kg m²] about its
own spin axis, its centre of mass on that axis (a balanced, axisymmetric wheel). Ω_k [rad/s] is wheel k's spin
relative to the body, u_k [N m] the motor torque on wheel k about a_k (the body feels −u_k a_k).

  Angular momentum about C, in B. Wheel k turns at ω + Ω_k a_k; being axisymmetric about a_k, its inertia I_k
  about its own centre has a_k as principal axis, I_k a_k = J_k a_k, so its momentum about its centre is
  I_k (ω + Ω_k a_k) = I_k ω + J_k Ω_k a_k. The platform and the wheels' centres carry the rest of I ω:
      H_B = I ω + h_w,   h_w = Σ J_k Ω_k a_k  (the wheels' momentum relative to the body).          (1)
  Euler's law about C in W, dH/dt = τ (τ the external couple), read in the turning frame B (transport theorem):
      I ω̇ + ḣ_w + ω × (I ω + h_w) = τ_B,   ḣ_w = Σ J_k Ω̇_k a_k.                                    (2)
  Wheel k alone, about its own centre: dH_k/dt = (bearing and motor couples); along a_k the bearings carry
  none, the motor u_k. In B, a_k·(I_k (ω̇ + Ω̇_k a_k) + ω × I_k (ω + Ω_k a_k)) = J_k (a_k·ω̇ + Ω̇_k) +
  a_k·(ω × I_k ω) (the Ω_k term a_k·(ω × J_k a_k) vanishes), and with I_k = J_k a_k a_kᵀ + J_t (1 − a_k a_kᵀ),
  I_k ω = J_t ω + (J_k − J_t)(a_k·ω) a_k, so ω × I_k ω ∥ ω × a_k ⟂ a_k: the axial equation is
      J_k (a_k·ω̇ + Ω̇_k) = u_k.                                                                    (3)
  Putting J_k Ω̇_k = u_k − J_k a_k·ω̇ from (3) into (2):
      (I − Σ J_k a_k a_kᵀ) ω̇ = τ_B − Σ u_k a_k − ω × (I ω + h_w),   Ω̇_k = u_k/J_k − a_k·ω̇.       (4)
  The transverse inertia A = I − Σ J_k a_k a_kᵀ (the body with the wheels free to spin) must be positive
  definite for (4) to have a solution: `gyrostat` refuses wheels that make it not. Translation: m v̇_W = f_W,
  ṗ_W = v_W; attitude: q̇_WB = ½ q_WB ⊗ (ω_B, 0) (Hamilton product).

  Kinetic energy. The platform and the wheels as if locked give ½ ωᵀ I ω; the spin adds, per wheel,
  ½ (ω + Ω a)ᵀ I_k (ω + Ω a) − ½ ωᵀ I_k ω = J Ω a·ω + ½ J Ω²:
      T = ½ m |v|² + ½ ωᵀ I ω + Σ (J_k Ω_k a_k·ω + ½ J_k Ω_k²)
        = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J_k s_k²,   s_k = a_k·ω + Ω_k (wheel k's absolute axial spin).   (5)
  Power. J_k ṡ_k = u_k by (3), and ωᵀ A ω̇ = ω·(τ − Σ u_k a_k) by (4) (ω·(ω × H) = 0), so
      dT/dt = f·v + τ·ω + Σ u_k Ω_k:                                                                  (6)
  the motor, acting between wheel and body, puts in its torque times the RELATIVE speed. Without outside
  wrench and motor torque, H_W = R_WB H_B, T and each s_k are constant (s_k linear in the state: RK4 keeps it
  to round-off).

Relation to the ReactionWheel element (scene.reaction_wheel): that element prescribes Ω(t) and puts the body's
(2) as I ω̇ + ω × (I ω + h) = τ − ḣ; the motor torque is then whatever holds the schedule, u_k = J_k (a_k·ω̇ +
Ω̇_k) by (3). With that u, (4) gives back the element's ω̇ exactly (test_gyrostat_reference).

State y of one gyrostat (13 + N): (p_W:3 [m], q_WB (x, y, z, w):4, v_W:3 [m/s], w_B:3 [rad/s], Ω:N [rad/s]).
Inputs: the outside wrench (f_W [N] at C in W, τ_B [N m] in B; `loads`: a schedule of dynamics.Load, as
scene.scheduled_loads) and the motor torques u (N,) [N m]: a constant, a schedule of MotorTorque pieces, or a
function u(t, y). rk4_step splits a step at the schedules' switch times, as scene.rk4_step does.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import NamedTuple, Union

import numpy as np

from .dynamics import Load, body_wrench, cross, loads_at, quat_product, to_world

SYMMETRY_TOLERANCE = 1e-12  # max |I − Iᵀ| allowed, relative to max |I_ij| (as the core's inertia checks)


# ---------------------------------------------------------------- the body
class Gyrostat(NamedTuple):
    """mass [kg]; inertia (3, 3) [kg m²] the whole body's about its centre of mass, in B (wheels included);
    axes (N, 3) unit wheel axes in B; J (N,) axial moments [kg m²]; transverse (3, 3) [kg m²] the transverse
    inertia A = I − Σ J_k a_k a_kᵀ (positive definite)."""
    mass: float
    inertia: np.ndarray
    axes: np.ndarray
    J: np.ndarray
    transverse: np.ndarray

    @property
    def n_wheels(self) -> int:
        return len(self.J)

    @property
    def state_size(self) -> int:
        return 13 + len(self.J)


def _finite(name, value) -> np.ndarray:
    x = np.asarray(value, float)
    if not np.all(np.isfinite(x)):
        raise ValueError(f"gyrostat: expected finite {name}, got {value!r}")
    return x


def _positive_definite(A) -> bool:
    return bool(np.linalg.eigvalsh(A)[0] > 0.0)


def _inertia(inertia_com) -> np.ndarray:
    """The symmetric part of inertia_com (principal moments (3,) or (3, 3) [kg m²]), checked finite,
    symmetric to SYMMETRY_TOLERANCE and positive definite."""
    I = _finite("inertia_com", inertia_com)
    I = np.diag(I) if I.shape == (3,) else I
    if I.shape != (3, 3):
        raise ValueError(f"gyrostat: expected inertia_com of shape (3,) or (3, 3), got shape {I.shape}")
    if np.max(np.abs(I - I.T)) > SYMMETRY_TOLERANCE * np.max(np.abs(I)):
        raise ValueError(f"gyrostat: expected a symmetric inertia_com, got {I.tolist()}")
    I = 0.5 * (I + I.T)
    if not _positive_definite(I):
        raise ValueError(f"gyrostat: expected a positive definite inertia_com, got eigenvalues "
                         f"{np.linalg.eigvalsh(I).tolist()}")
    return I


def _wheel(k, wheel) -> tuple[np.ndarray, float]:
    """(a_k, J_k) of wheels[k] = (axis_B, J): the axis normalised, refused when zero; J finite > 0."""
    axis, J = wheel
    axis = _finite(f"wheels[{k}] axis_B", axis)
    if axis.shape != (3,):
        raise ValueError(f"gyrostat: expected wheels[{k}] axis_B of shape (3,), got shape {axis.shape}")
    norm = np.linalg.norm(axis)
    if norm == 0.0:
        raise ValueError(f"gyrostat: expected a nonzero wheels[{k}] axis_B, got {axis.tolist()}")
    J = float(_finite(f"wheels[{k}] J", J))
    if not J > 0.0:
        raise ValueError(f"gyrostat: expected wheels[{k}] J > 0 [kg m²], got {J!r}")
    return axis / norm, J


def gyrostat(mass, inertia_com, wheels=()) -> Gyrostat:
    """A gyrostat body.

    Parameters
    ----------
    mass : float
        Total mass [kg], finite and > 0.
    inertia_com : array_like, shape (3,) or (3, 3)
        The whole body's rotational inertia about its centre of mass, in B [kg m²] (wheels included, as if
        locked), principal moments or the full matrix (moments on the diagonal, negated products off it);
        symmetric to 1e-12 of its largest entry (its symmetric part is kept) and positive definite.
    wheels : sequence of (axis_B, J)
        Per wheel k: axis_B (3,) in B (normalised; nonzero) and J the axial moment [kg m²] (finite, > 0).
        The transverse inertia I − Σ J_k a_k a_kᵀ must stay positive definite as the wheels are added.

    Returns
    -------
    Gyrostat

    Raises
    ------
    ValueError
        Naming the bad value: a non-finite entry, mass <= 0, an asymmetric or indefinite inertia_com, a zero
        axis, J <= 0, or the first wheel k that makes the transverse inertia not positive definite.
    """
    m = float(_finite("mass", mass))
    if not m > 0.0:
        raise ValueError(f"gyrostat: expected mass > 0 [kg], got {m!r}")
    I = _inertia(inertia_com)
    axes, Js, A = [], [], I.copy()
    for k, wheel in enumerate(wheels):
        a, J = _wheel(k, wheel)
        A = A - J * np.outer(a, a)
        if not _positive_definite(A):
            raise ValueError(f"gyrostat: wheels[{k}] (J = {J!r} kg m², axis {a.tolist()}) makes the transverse "
                             f"inertia I − Σ J a aᵀ not positive definite (eigenvalues "
                             f"{np.linalg.eigvalsh(A).tolist()})")
        axes.append(a)
        Js.append(J)
    return Gyrostat(m, I, np.reshape(axes, (len(Js), 3)), np.array(Js, float), A)


# ---------------------------------------------------------------- the state
class State(NamedTuple):
    """One gyrostat's state, split: p_W [m], q_WB (x, y, z, w), v_W [m/s], w_B [rad/s], Omega (N,) [rad/s]."""
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray
    Omega: np.ndarray


def split(body: Gyrostat, y) -> State:
    """The parts of y (13 + N,); q_WB as stored (not normalised). ValueError on a wrong length."""
    y = np.asarray(y, float)
    if y.shape != (body.state_size,):
        raise ValueError(f"gyrostat: expected a state of shape ({body.state_size},), got shape {y.shape}")
    return State(y[0:3], y[3:7], y[7:10], y[10:13], y[13:])


def state(p_W, q_WB, v_W, w_B, Omega) -> np.ndarray:
    """y = (p_W, q_WB (x, y, z, w), v_W, w_B, Ω) (13 + N,)."""
    return np.concatenate([p_W, q_WB, v_W, w_B, np.atleast_1d(Omega)]).astype(float)


# ---------------------------------------------------------------- momentum and the rate
def wheel_momentum(body: Gyrostat, Omega) -> np.ndarray:
    """h_w = Σ J_k Ω_k a_k [N m s] in B (the wheels' momentum relative to the body), eq. (1)."""
    return (body.J * np.asarray(Omega, float)) @ body.axes


def angular_momentum_B(body: Gyrostat, w_B, Omega) -> np.ndarray:
    """H_B = I ω + h_w [N m s]: the total angular momentum about the centre of mass, in B, eq. (1)."""
    return body.inertia @ w_B + wheel_momentum(body, Omega)


def accelerations(body: Gyrostat, w_B, Omega, tau_B, u) -> tuple[np.ndarray, np.ndarray]:
    """(ω̇_B [rad/s²], Ω̇ (N,) [rad/s²]) under the couple tau_B [N m] (in B) and the motor torques u (N,) [N m]:
    A ω̇ = τ − Σ u_k a_k − ω × (I ω + h_w), Ω̇_k = u_k/J_k − a_k·ω̇ (eq. (4))."""
    u = np.asarray(u, float)
    rhs = np.asarray(tau_B, float) - u @ body.axes - cross(w_B, angular_momentum_B(body, w_B, Omega))
    w_dot = np.linalg.solve(body.transverse, rhs)
    return w_dot, u / body.J - body.axes @ w_dot


def rate(body: Gyrostat, t, y, f_W, tau_B, u) -> np.ndarray:
    """ẏ (13 + N,) of the gyrostat's state y under the force f_W [N] (at the centre of mass, in W), the couple
    tau_B [N m] (in B) and the motor torques u (N,) [N m], all given at the time t [s] (the rate has no other
    dependence on t). ṗ = v, q̇ = ½ q ⊗ (ω, 0) with q as stored (the stepper restores its norm), m v̇ = f,
    (ω̇, Ω̇) by eq. (4)."""
    s = split(body, y)
    q_dot = 0.5 * quat_product(s.q_WB, np.append(s.w_B, 0.0))
    w_dot, Omega_dot = accelerations(body, s.w_B, s.Omega, tau_B, u)
    return np.concatenate([s.v_W, q_dot, np.asarray(f_W, float) / body.mass, w_dot, Omega_dot])


# ---------------------------------------------------------------- energy, momentum, power
def kinetic_energy(body: Gyrostat, y) -> float:
    """T = ½ m |v|² + ½ ωᵀ A ω + ½ Σ J_k (a_k·ω + Ω_k)² [J] (eq. (5), A the transverse inertia)."""
    s = split(body, y)
    spin = body.axes @ s.w_B + s.Omega
    return float(0.5 * body.mass * s.v_W @ s.v_W + 0.5 * s.w_B @ body.transverse @ s.w_B
                 + 0.5 * body.J @ (spin * spin))


def angular_momentum_W(body: Gyrostat, y) -> np.ndarray:
    """R_WB H_B [N m s]: the total angular momentum about the centre of mass, in W (q normalised first)."""
    s = split(body, y)
    return to_world(s.q_WB / np.linalg.norm(s.q_WB), angular_momentum_B(body, s.w_B, s.Omega))


def angular_momentum_about_origin(body: Gyrostat, y) -> np.ndarray:
    """p_W × m v_W + R_WB H_B [N m s]: about W's origin, in W (H_P = r_PC × L + H_C, Craig)."""
    s = split(body, y)
    return cross(s.p_W, body.mass * s.v_W) + angular_momentum_W(body, y)


def motor_power(body: Gyrostat, y, u) -> float:
    """Σ u_k Ω_k [W]: the motors' power into the system (torque times the speed relative to the body)."""
    return float(np.asarray(u, float) @ split(body, y).Omega)


def external_power(body: Gyrostat, y, f_W, tau_B) -> float:
    """f·v + τ·ω [W]: the outside wrench's power (f_W at the centre of mass in W, tau_B in B)."""
    s = split(body, y)
    return float(np.asarray(f_W, float) @ s.v_W + np.asarray(tau_B, float) @ s.w_B)


# ---------------------------------------------------------------- inputs
class MotorTorque(NamedTuple):
    """One piece of a motor schedule: the torques u (N,) [N m] on the N wheels, active for t_start <= t < t_end."""
    u: np.ndarray
    t_start: float = -np.inf
    t_end: float = np.inf


Motor = Union[None, Sequence[MotorTorque], Callable, np.ndarray, Sequence[float]]


def _is_schedule(motor) -> bool:
    """A list or tuple of MotorTorque pieces (an empty one: no torque)."""
    return isinstance(motor, (list, tuple)) and all(isinstance(piece, MotorTorque) for piece in motor)


def motor_torque_at(body: Gyrostat, motor: Motor, t, y) -> np.ndarray:
    """u (N,) [N m] at time t [s] and state y: motor None (zero), a function u(t, y), a sequence of MotorTorque
    (the sum of the pieces active at t), or constant torques (N,). ValueError when it is not N finite values."""
    if motor is None:
        return np.zeros(body.n_wheels)
    if callable(motor):
        u = np.asarray(motor(t, y), float)
    elif _is_schedule(motor):
        u = sum((np.asarray(p.u, float) for p in motor if p.t_start <= t < p.t_end), np.zeros(body.n_wheels))
    else:
        u = np.asarray(motor, float)
    if u.shape != (body.n_wheels,) or not np.all(np.isfinite(u)):
        raise ValueError(f"gyrostat: expected {body.n_wheels} finite motor torques [N m], got {u!r}")
    return u


def switch_times(motor: Motor, loads: Sequence[Load]) -> list[float]:
    """Every finite switch time (t_start, t_end) [s] of the motor schedule and of the loads."""
    pieces = list(motor) if _is_schedule(motor) else []
    return sorted({b for p in [*pieces, *loads] for b in (p.t_start, p.t_end) if np.isfinite(b)})


# ---------------------------------------------------------------- RK4
class Run(NamedTuple):
    """An RK4 run: t (n + 1,) [s], y (n + 1, 13 + N), work_loads (n + 1,) [J] = ∫ (f·v + τ·ω) dt and
    work_motor (n + 1,) [J] = ∫ Σ u_k Ω_k dt from the start (integrated as two extra states)."""
    t: np.ndarray
    y: np.ndarray
    work_loads: np.ndarray
    work_motor: np.ndarray


def _rate_and_power(body: Gyrostat, t, z, motor, loads, schedule_time) -> np.ndarray:
    """ż of z = (y, W_loads, W_motor): the rate and the two powers. The loads see the attitude q/|q|;
    schedules (MotorTorque pieces, loads) are read at schedule_time, a function u(t, y) at (t, y)."""
    y = z[:-2]
    s = split(body, y)
    f_W, tau_B = body_wrench(s.q_WB, loads_at(loads, schedule_time))
    u = motor_torque_at(body, motor, t if callable(motor) else schedule_time, y)
    return np.concatenate([rate(body, t, y, f_W, tau_B, u),
                           [external_power(body, y, f_W, tau_B), motor_power(body, y, u)]])


def _normalised(z) -> np.ndarray:
    z = np.array(z, float)
    z[3:7] /= np.linalg.norm(z[3:7])
    return z


def _rk4_piece(body: Gyrostat, t, z, h, motor, loads) -> np.ndarray:
    """Classical Runge–Kutta 4 (Kutta 1901) over h [s] from (t, z), the schedules read at the piece's middle,
    the quaternion renormalised at the end."""
    mid = t + 0.5 * h
    k1 = _rate_and_power(body, t, z, motor, loads, mid)
    k2 = _rate_and_power(body, mid, z + 0.5 * h * k1, motor, loads, mid)
    k3 = _rate_and_power(body, mid, z + 0.5 * h * k2, motor, loads, mid)
    k4 = _rate_and_power(body, t + h, z + h * k3, motor, loads, mid)
    return _normalised(z + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4))


def _rk4_step_with_work(body: Gyrostat, t, z, h, motor, loads) -> np.ndarray:
    cuts = [b for b in switch_times(motor, loads) if t < b < t + h] + [t + h]
    start = t
    for end in cuts:
        z = _rk4_piece(body, start, z, end - start, motor, loads)
        start = end
    return z


def _checked(body: Gyrostat, y, h) -> np.ndarray:
    """y as floats, refused unless of length 13 + N and finite; h refused unless finite and > 0."""
    y = np.asarray(y, float)
    split(body, y)
    if not np.all(np.isfinite(y)):
        raise ValueError(f"gyrostat: expected a finite state, got {y.tolist()}")
    if not (np.isfinite(h) and h > 0.0):
        raise ValueError(f"gyrostat: expected a finite step h > 0 [s], got {h!r}")
    return y


def rk4_step(body: Gyrostat, t, y, h, motor: Motor = None, loads: Sequence[Load] = ()) -> np.ndarray:
    """One RK4 step of h [s] from the state y (13 + N,) at time t [s].

    Split at the switch times strictly inside the step (switch_times) into pieces, each a full RK4 step during
    which the schedules hold the values active inside it (read at its middle), so that piecewise-constant
    inputs are integrated to the method's order; a function u(t, y) is evaluated at every stage. q_WB is
    renormalised after each piece.

    Parameters
    ----------
    body : Gyrostat
    t : float
        Time at the start of the step [s].
    y : array_like, shape (13 + N,)
        State (p_W, q_WB, v_W, w_B, Ω), finite.
    h : float
        Step [s].
    motor : None, array_like (N,), sequence of MotorTorque, or callable (t, y) -> (N,)
        The motor torques [N m] (motor_torque_at); None: zero.
    loads : sequence of dynamics.Load
        The outside force at the centre of mass and couple (world or body frame) schedule.

    Returns
    -------
    numpy.ndarray, shape (13 + N,)
    """
    z = np.append(_checked(body, y, h), [0.0, 0.0])
    return _rk4_step_with_work(body, t, z, h, motor, loads)[:-2]


def rk4_run(body: Gyrostat, y0, h, steps, motor: Motor = None, loads: Sequence[Load] = (), t0=0.0) -> Run:
    """`steps` RK4 steps of h [s] from y0 (13 + N,) at t0 [s] (rk4_step; t_i = t0 + i h), with the work of the
    loads and of the motors integrated alongside. Returns a Run."""
    z = [np.append(_checked(body, y0, h), [0.0, 0.0])]
    for i in range(steps):
        z.append(_rk4_step_with_work(body, t0 + i * h, z[-1], h, motor, loads))
    z = np.array(z)
    return Run(t0 + h * np.arange(steps + 1), z[:, :-2], z[:, -2], z[:, -1])


__all__ = ["Gyrostat", "MotorTorque", "Run", "State", "accelerations", "angular_momentum_B",
           "angular_momentum_W", "angular_momentum_about_origin", "external_power", "gyrostat", "kinetic_energy",
           "motor_power", "motor_torque_at", "rate", "rk4_run", "rk4_step", "split", "state", "switch_times",
           "wheel_momentum"]
