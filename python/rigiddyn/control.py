"""Digital controllers of a scene run: `Controller` (a law sampled every `period` seconds, its commands held until
the next sample) and two shipped laws, `BDot` (magnetorquer detumbling) and `PDAttitude` (reaction-wheel pointing).

A controller is passed to ``rigiddyn.simulate(scene, ..., controller=Controller(period, law))``. The run samples
the law at t_k = t0 + k period (k = 0, 1, ... before the end of the run) with the state of every body there (a
`SampledState`), and holds the actuator commands it returns constant until t_{k+1} (a zero-order hold, as the
digital-to-analogue converter of a flight computer). The steps are split at the samples, as at the switch times of
a ScheduledLoads, so no step straddles a sample and every method keeps its order. A law in Python runs with the
GIL taken at the samples only; the steps between them run in C++ without it. The shipped laws BDot and PDAttitude
run as their C++ twins (rigiddyn/scene/control_laws.hpp) without the GIL (unless the controller adds gyro noise,
or a PDAttitude's target is a callable); their Python code here is the reference the tests hold the C++ to.

Commands (a dict returned by the law; an actuator not named holds its last command, or its own schedule until it
is first commanded):

``"wheel_torque"``: array_like, shape (nw,)
    The motor torque u [N m] of every gyrostat wheel, in the scene's order (the order of SceneResult.wheel_speed).
    The wheel's motor turns the body by -u a (a the wheel's unit axis in B).
element index ``e`` (int): array_like, shape (3,)
    A MagneticDipole's dipole m_B [A m^2] in B (a magnetorquer: the torque m_B x B_B), or a ScheduledLoads' force
    f_B [N] in B at its point_B (a thruster: adds point_B x f_B), replacing its schedule.
element index ``e`` (int): float
    A ReactionWheel's speed Omega_c [rad/s] relative to its body (a rate-limited speed loop): the wheel ramps at a
    constant rate from its speed at the sample t_k to Omega_c at the next sample t_k + period, then holds it
    (replacing its own ramp); over the ramp the body feels -J dOmega/dt a - w_B x h_B.
    A RevoluteMotor's joint torque [N m] or a PrismaticMotor's joint force [N] in a tree's joint, held until the
    next command (replacing its own window). The law reads the trees' joints in ``state.joint_q`` and
    ``state.joint_v``: a joint-space law (a PD loop on a robot arm's joints, a hinge's deployment) is a law on them.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["BDot", "Controller", "PDAttitude", "SampledState", "dipole_field_W"]

_MU0_OVER_4PI = 1.0000000005443757e-7  # mu0/(4 pi) [N/A^2], as the MagneticDipole element (CODATA 2018)


@dataclass(frozen=True)
class SampledState:
    """The state a controller's law sees at a sample (read-only arrays, one row per body); the core makes it.

    Parameters
    ----------
    t : float
        The sample time t0 + k period [s].
    p_W : numpy.ndarray, shape (nb, 3)
        Centre of mass positions in W [m].
    q_WB : numpy.ndarray, shape (nb, 4)
        Attitudes (x, y, z, w), as integrated.
    v_W : numpy.ndarray, shape (nb, 3)
        Centre of mass velocities in W [m/s].
    w_B : numpy.ndarray, shape (nb, 3)
        Angular velocities in B [rad/s] (with the controller's gyro noise when it has some).
    wheel_speed : numpy.ndarray, shape (nw,)
        Each gyrostat wheel's speed relative to its body [rad/s], in the scene's order.
    joint_q : numpy.ndarray, shape (n_q,), optional
        The trees' joint coordinates, n_q of them, the trees in the scene's order (SceneResult.joint_q's columns;
        empty without a tree, the default).
    joint_v : numpy.ndarray, shape (n_v,), optional
        Their joint velocities, n_v of them (SceneResult.joint_v's columns).

    Raises
    ------
    TypeError
        t not a real number; an array not of real numbers (each named).
    ValueError
        An array of the wrong shape, or rows that are not one per body (each named).

    Examples
    --------
    >>> s = rd.SampledState(0.5, np.zeros((1, 3)), np.array([[0.0, 0.0, 0.0, 1.0]]), np.zeros((1, 3)),
    ...                     np.zeros((1, 3)), np.zeros(0))
    >>> s.t, s.q_WB.shape
    (0.5, (1, 4))
    """

    t: float
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray
    wheel_speed: np.ndarray
    joint_q: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0))
    joint_v: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(0))

    def __post_init__(self) -> None:
        # the types and shapes (the values are the run's: non-finite once a run diverges, so not refused)
        object.__setattr__(self, "t", _real(self.t, "t", "a number [s]"))
        p_W = _rows(self.p_W, "p_W", 3)
        bodies = p_W.shape[0]
        object.__setattr__(self, "p_W", p_W)
        for name, width in (("q_WB", 4), ("v_W", 3), ("w_B", 3)):
            a = _rows(getattr(self, name), name, width)
            if a.shape[0] != bodies:
                raise ValueError(f"{name}: expected {bodies} rows (one per body, as p_W), got {a.shape[0]}")
            object.__setattr__(self, name, a)
        for name, what in (("wheel_speed", "(nw,) [rad/s]"), ("joint_q", "(n_q,)"), ("joint_v", "(n_v,)")):
            a = _real_array(getattr(self, name), name, f"an array of shape {what}")
            if a.ndim != 1:
                raise ValueError(f"{name}: expected an array of shape {what}, got shape {a.shape}")
            object.__setattr__(self, name, a)


def _real(value: Any, name: str, what: str) -> float:
    """float(value) of a real number (not a bool), else TypeError naming `name`."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name}: expected {what}, got {value!r}")
    return float(value)


def _real_array(value: Any, name: str, what: str) -> np.ndarray:
    """A read-only float64 view of an array of real numbers, else TypeError naming `name`."""
    a = value if isinstance(value, np.ndarray) else np.asarray(value) if isinstance(value, (list, tuple)) else None
    if a is None or a.dtype.kind not in "fiu":
        raise TypeError(f"{name}: expected {what}, got {value!r}")
    a = a.astype(np.float64, copy=False).view()
    a.setflags(write=False)
    return a


def _rows(value: Any, name: str, width: int) -> np.ndarray:
    """An (n, width) array of real numbers, else TypeError/ValueError naming `name`."""
    what = f"an array of shape (nb, {width})"
    a = _real_array(value, name, what)
    if a.ndim != 2 or a.shape[1] != width:
        raise ValueError(f"{name}: expected {what}, got shape {a.shape}")
    return a


def _positive(value: Any, name: str, unit: str) -> float:
    """float(value), finite and > 0, else TypeError (not a real number) or ValueError naming `name`."""
    x = _real(value, name, f"a finite number > 0 {unit}")
    if not (math.isfinite(x) and x > 0.0):
        raise ValueError(f"{name}: expected a finite number > 0 {unit}, got {value!r}")
    return x


class Controller:
    """A digital controller: `law` sampled every `period` seconds of a scene run, its commands held until the next
    sample (zero-order hold).

    Parameters
    ----------
    period : float
        Sample period [s], finite and > 0. The law is called at t0 + k period, k = 0, 1, ..., before the end of
        the run; the steps are split there (a period need not divide dt).
    law : callable
        law(state) -> dict: `state` a SampledState, the dict the actuator commands (the module's docstring):
        ``"wheel_torque"`` (nw,) [N m] for the gyrostat wheels, an element index -> (3,) for a MagneticDipole
        (m_B [A m^2] in B) or a ScheduledLoads (force f_B [N] in B at its point_B), and an element index -> a float
        for a ReactionWheel (its speed [rad/s] relative to the body, reached at the next sample at a constant
        rate), a RevoluteMotor (its joint torque [N m]) or a PrismaticMotor (its joint force [N]). An actuator not
        named holds its last command.
    w_B_noise : float, keyword-only, default 0.0
        Standard deviation [rad/s] of a white gyro noise added to each sampled w_B component (>= 0).
    seed : int, keyword-only, optional
        Seed of the noise's generator (numpy.random.default_rng(seed)); a run draws from where the last one
        stopped, so give a fresh Controller (or the same seed) to repeat a run.
    repeatable : bool, keyword-only, default False
        Whether simulate's global error estimate may sample the law again: True, its two runs at 2 dt and 4 dt each go
        under a ``copy.deepcopy`` of this controller made before the run (the law's own attributes and the noise
        generator's state copied), so the law must keep its state in itself and have no effect outside it (no list
        it appends to, no device it drives). False: a law in Python is sampled by the run alone, and result.error
        gives no values, its verdict saying so, and simulate(..., tolerance=) refuses it (its planner and
        certificate run the law again). The shipped laws (BDot, PDAttitude) are always repeatable.

    The arguments are kept as the attributes of the same names (``period`` and ``w_B_noise`` as floats).

    Raises
    ------
    ValueError
        period not finite and > 0; w_B_noise negative or not finite. At a sample (raised by simulate): a command
        of the wrong shape or not finite, an unknown key, an element that takes no such command (a number to an
        element that is no ReactionWheel or joint motor, a (3,) value to one: named with its type), each named with
        the sample time.
    TypeError
        law not callable; a law that returns no dict.

    See Also
    --------
    BDot, PDAttitude : shipped laws.
    rigiddyn.simulate : its ``controller`` argument.

    Notes
    -----
    An exception the law raises stops the run and propagates, with a note naming the sample time.

    Examples
    --------
    A thruster (a ScheduledLoads at the centre of mass) pushed with 1 N for t < 1 s, off after; the law sees
    t = 0, 0.25, 0.5, ...:

    >>> seen = []
    >>> def law(state):
    ...     seen.append(state.t)
    ...     return {0: (1.0 if state.t < 1.0 else 0.0, 0.0, 0.0)}
    >>> scene = rd.Scene([rd.RigidBody(2.0, [1.0, 1.0, 1.0])], elements=[rd.ScheduledLoads(body=0, loads=[])])
    >>> result = rd.simulate(scene, [rd.RigidBodyState()], 0.1, duration=2.0,
    ...                      controller=rd.Controller(0.25, law))
    >>> seen[:5], len(seen)
    ([0.0, 0.25, 0.5, 0.75, 1.0], 8)
    >>> round(float(result.v_W[-1, 0, 0]), 12)
    0.5

    A reaction wheel (J = 0.1 kg m^2 about z) commanded to 2 rad/s at t = 0 reaches it at t = 0.5 s; the body
    (I = 1 kg m^2 about z, wheel included) turns the other way at J Omega / I:

    >>> wheel = rd.ReactionWheel(body=0, axis_B=(0.0, 0.0, 1.0), inertia=0.1)
    >>> scene = rd.Scene([rd.RigidBody(10.0, [1.0, 1.0, 1.0])], elements=[wheel])
    >>> result = rd.simulate(scene, [rd.RigidBodyState()], 0.05, duration=1.0, method="rk4",
    ...                      controller=rd.Controller(0.5, lambda state: {0: 2.0}))
    >>> result.w_B[-1, 0].round(12).tolist()
    [0.0, 0.0, -0.2]

    A PD loop on a hinge's angle (a wheel of I = 0.5 kg m² on a RevoluteMotor, sampled at 100 Hz) takes it from 0
    to 1 rad; the closed loop, ω_n = sqrt(k_p / I) = 4 rad/s at damping ratio k_d / (2 I ω_n) = 1, has settled by
    t = 3 s:

    >>> tree = rd.Tree()
    >>> hub = tree.add_link("hub", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0], 0.5 * np.eye(3)))
    >>> scene = rd.Scene()
    >>> links = scene.add_tree(tree, "drive")
    >>> motor = scene.add(rd.RevoluteMotor(body=links[0], torque=0.0))
    >>> pd = lambda state: {motor: 8.0 * (1.0 - state.joint_q[0]) - 4.0 * state.joint_v[0]}
    >>> result = rd.simulate(scene, tree.joint_states([0.0]), 0.01, duration=3.0, method="rk4",
    ...                      controller=rd.Controller(0.01, pd))
    >>> round(float(result.joint_q[-1, 0]), 3)
    1.0
    """

    def __init__(self, period: float, law: Callable[[SampledState], Mapping[Any, Any]], *, w_B_noise: float = 0.0,
                 seed: int | None = None, repeatable: bool = False) -> None:
        self.period = _positive(period, "period", "[s]")
        if not callable(law):
            raise TypeError(f"law: expected a callable law(state) -> dict of commands, got {law!r}")
        self.law = law
        noise = _real(w_B_noise, "w_B_noise", "a finite number >= 0 [rad/s]")
        if not (math.isfinite(noise) and noise >= 0.0):
            raise ValueError(f"w_B_noise: expected a finite number >= 0 [rad/s], got {w_B_noise!r}")
        self.w_B_noise = noise
        if seed is not None and (isinstance(seed, (bool, np.bool_)) or not isinstance(seed, (int, np.integer))):
            raise TypeError(f"seed: expected None or an int >= 0, got {seed!r}")
        if seed is not None and seed < 0:
            raise ValueError(f"seed: expected None or an int >= 0, got {seed!r}")
        self.seed = None if seed is None else int(seed)
        self._rng = np.random.default_rng(seed)
        if not isinstance(repeatable, (bool, np.bool_)):
            raise TypeError(f"repeatable: expected True or False, got {repeatable!r}")
        self.repeatable = bool(repeatable)

    def __repr__(self) -> str:
        return (f"Controller(period={self.period!r}, law={self.law!r}, w_B_noise={self.w_B_noise!r}, "
                f"repeatable={self.repeatable!r})")

    def _sample(self, t: float, p_W: np.ndarray, q_WB: np.ndarray, v_W: np.ndarray, w_B: np.ndarray,
                wheel_speed: np.ndarray, joint_q: np.ndarray, joint_v: np.ndarray
                ) -> tuple[list[float] | None, list[tuple[int, tuple[float, float, float] | float]]]:
        """The core's call at a sample: the law's commands at t [s], checked, as (wheel torques or None,
        [(element, value (3,) or a number: a wheel speed [rad/s], a joint motor's force), ...])."""
        if self.w_B_noise > 0.0:
            w_B = w_B + self._rng.normal(0.0, self.w_B_noise, w_B.shape)
        state = SampledState(t, p_W, q_WB, v_W, w_B, wheel_speed, joint_q, joint_v)  # read-only views
        at = f"controller.law(t={t:.17g})"  # as the core names a sample (17 significant digits)
        try:
            commands = self.law(state)
        except Exception as e:
            e.add_note(f"raised by {at}")
            raise
        if not isinstance(commands, Mapping):
            raise TypeError(f"{at}: expected a dict of commands ('wheel_torque' or element index -> value), "
                            f"got {commands!r}")
        wheels: list[float] | None = None
        elements: list[tuple[int, tuple[float, float, float] | float]] = []
        for key, value in commands.items():
            if isinstance(key, str) and key == "wheel_torque":
                wheels = _command(value, (wheel_speed.shape[0],), f"{at}['wheel_torque']", "[N m]").tolist()
            elif isinstance(key, (int, np.integer)) and not isinstance(key, bool):
                v = _command(value, None, f"{at}[{key}]", "")
                elements.append((int(key), float(v) if v.ndim == 0 else (float(v[0]), float(v[1]), float(v[2]))))
            else:
                raise ValueError(f"{at}: expected the key 'wheel_torque' or an element index (int), got {key!r}")
        return wheels, elements


def _command(value: Any, shape: tuple[int, ...] | None, name: str, unit: str) -> np.ndarray:
    """value as a float array of `shape` (None: an element's, (3,) or a number), finite, else ValueError naming
    `name`."""
    a = np.asarray(value, dtype=float)
    if shape is None and a.shape not in ((3,), ()):
        raise ValueError(f"{name}: expected shape (3,) (a MagneticDipole's m_B, a ScheduledLoads' f_B) or a number "
                         f"(a ReactionWheel's speed [rad/s], a joint motor's torque [N m] or force [N]), got shape "
                         f"{a.shape}")
    if shape is not None and a.shape != shape:
        raise ValueError(f"{name}: expected shape {shape}{' ' + unit if unit else ''}, got shape {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name}: expected finite values, got {a.tolist()}")
    return a


def _cross(a: Any, b: Any) -> np.ndarray:
    """a x b of two 3-vectors, component by component (numpy.cross costs tens of microseconds a call)."""
    a0, a1, a2 = (float(x) for x in a)
    b0, b1, b2 = (float(x) for x in b)
    return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])


def _unit(q: Any) -> np.ndarray:
    """q / |q| of a quaternion."""
    q = np.asarray(q, dtype=float)
    unit: np.ndarray = q / math.sqrt(float(q @ q))
    return unit


def _rotate_inverse(q_WB: np.ndarray, v_W: np.ndarray) -> np.ndarray:
    """R_WB^T v_W for the quaternion q_WB (x, y, z, w): the rotation by its conjugate (-u, w),
    v + 2 w (-u x v) + 2 (-u) x (-u x v)."""
    q = _unit(q_WB)
    u, w = -q[:3], float(q[3])
    c = _cross(u, v_W)
    out: np.ndarray = v_W + 2.0 * w * c + 2.0 * _cross(u, c)
    return out


def dipole_field_W(dipole: Any, p_W: np.ndarray) -> np.ndarray:
    """The magnetic field B(p_W) [T] in W of a MagneticDipole element: B_W + mu0/(4 pi) (3 r (r . M)/|r|^5 - M/|r|^3),
    r = p_W - source_p_W (Jackson, "Classical Electrodynamics", §5.6), as the element computes it.

    Parameters
    ----------
    dipole : MagneticDipole
        The element (its B_W, source_moment_W and source_p_W are read).
    p_W : array_like, shape (3,)
        The point [m] in W.

    Returns
    -------
    numpy.ndarray, shape (3,)
        B [T] in W.

    Examples
    --------
    >>> field = rd.MagneticDipole(m_B=(0.0, 0.0, 0.0), B_W=(1e-5, 0.0, 0.0))
    >>> rd.control.dipole_field_W(field, np.zeros(3)).tolist()
    [1e-05, 0.0, 0.0]
    """
    B = np.asarray(dipole.B_W, dtype=float)
    M = np.asarray(dipole.source_moment_W, dtype=float)
    if not M.any():
        return B
    r = np.asarray(p_W, dtype=float) - np.asarray(dipole.source_p_W, dtype=float)
    r2 = float(r @ r)
    field: np.ndarray = B + _MU0_OVER_4PI / (r2 * math.sqrt(r2)) * (3.0 * float(r @ M) / r2 * r - M)
    return field


class BDot:
    """The B-dot detumbling law on a magnetorquer: m_B = -k dB_B/dt, held over each sample period.

    With the field B_B = R_WB^T B(p_W) in the body, its rate seen by the body is dB_B/dt = -w_B x B_B (the field
    fixed in W over a sample; ``rate="gyro"``) or the difference of two samples (B_B(t_k) - B_B(t_{k-1}))/period
    (``rate="difference"``, no gyro needed; zero at the first sample). The torque m_B x B_B = -k |B|^2 w_perp
    (``"gyro"``) damps the angular velocity normal to the field: for a body of inertia I (a sphere) in a uniform
    field, |w_perp| decays as exp(-k |B|^2 t / I) (Stickler & Alfriend, "Elementary magnetic attitude control
    system").

    Parameters
    ----------
    gain : float
        k [A m^2 s / T], > 0.
    dipole : MagneticDipole
        The scene's magnetorquer element (its field is read: B_W, source_moment_W, source_p_W).
    element : int
        The element's index in the scene (the command's key).
    body : int, default 0
        The body that carries it.
    m_max : float, optional
        The saturation [A m^2] of each component of m_B (None: none).
    rate : {'gyro', 'difference'}, default 'gyro'
        How dB_B/dt is estimated (above).

    Raises
    ------
    ValueError
        gain or m_max not finite and > 0, an unknown rate.

    Examples
    --------
    >>> law = rd.control.BDot(1e4, rd.MagneticDipole(m_B=(0.0, 0.0, 0.0), B_W=(0.0, 0.0, 2e-5)), element=0)
    >>> state = rd.SampledState(0.0, np.zeros((1, 3)), np.array([[0.0, 0.0, 0.0, 1.0]]), np.zeros((1, 3)),
    ...                         np.array([[0.1, 0.0, 0.0]]), np.zeros(0))
    >>> law(state)[0].round(12).tolist()
    [0.0, -0.02, 0.0]
    """

    def __init__(self, gain: float, dipole: Any, element: int, *, body: int = 0, m_max: float | None = None,
                 rate: str = "gyro") -> None:
        self.gain = _positive(gain, "gain", "[A m^2 s/T]")
        self.m_max = None if m_max is None else _positive(m_max, "m_max", "[A m^2]")
        if rate not in ("gyro", "difference"):
            raise ValueError(f"rate: expected 'gyro' or 'difference', got {rate!r}")
        self.dipole, self.element, self.body, self.rate = dipole, int(element), int(body), rate
        self._last: tuple[float, np.ndarray] | None = None

    def __call__(self, state: SampledState) -> dict[Any, Any]:
        b = self.body
        B_B = _rotate_inverse(state.q_WB[b], dipole_field_W(self.dipole, state.p_W[b]))
        if self.rate == "gyro":
            B_dot = -_cross(state.w_B[b], B_B)  # dB_B/dt = -w_B x B_B
        else:
            last, self._last = self._last, (state.t, B_B)
            B_dot = np.zeros(3) if last is None or state.t <= last[0] else (B_B - last[1]) / (state.t - last[0])
        m_B = -self.gain * B_dot
        if self.m_max is not None:
            m_B = np.clip(m_B, -self.m_max, self.m_max)
        return {self.element: m_B}


class PDAttitude:
    """A PD attitude law on reaction wheels: the body torque tau_B = -k_p e - k_d w_B, e = 2 sign(eta) epsilon the
    rotation vector of the error q_e = q_target^-1 q_WB = (epsilon, eta) to first order, made by the wheels' motors
    (their torque on the body is -sum u_k a_k, so u = -pinv([a_1 ... a_n]) tau_B); Wie, "Space Vehicle Dynamics
    and Control".

    For a small error about a principal axis that carries a wheel, of moment A (the gyrostat's transverse inertia
    about it, Gyrostat.transverse_inertia: the body's without its wheels' spin inertia), the closed loop is
    A theta'' + k_d theta' + k_p theta = 0 (between samples; the hold delays the torque by about period/2):
    omega_n = sqrt(k_p/A), zeta = k_d/(2 sqrt(k_p A)).

    Parameters
    ----------
    k_p : float
        Proportional gain [N m/rad], > 0.
    k_d : float
        Derivative gain [N m s/rad], > 0.
    axes_B : array_like, shape (nw, 3)
        The wheels' spin axes in B (the gyrostat's, in the scene's order), spanning 3 dimensions.
    q_target_WB : array_like, shape (4,), callable or 'lvlh', default (0, 0, 0, 1)
        The target attitude (x, y, z, w); q_target_WB(t) of the sample time t [s] (a slew); or 'lvlh': the
        local-vertical local-horizontal frame of the body's sampled p_W, v_W (about a central body at W's origin,
        orbit_frame_rotation). The law feeds back the body rate w_B, not its rate relative to the target: a target
        turning at w_t is followed with the lag e = (k_d/k_p) w_t in steady state (on a circular orbit, LVLH turns
        at n about -y: sin(theta/2) = k_d n/(2 k_p) about the pitch axis).
    body : int, default 0
        The controlled body.

    Attributes
    ----------
    k_p, k_d, q_target_WB, body
        As given.
    axes_B : numpy.ndarray, shape (nw, 3)
        The wheels' unit axes in B (axes_B normalised row by row), read-only.

    Raises
    ------
    ValueError
        k_p or k_d not finite and > 0; axes_B not of shape (nw, 3) or not spanning 3 dimensions; q_target_WB a
        string other than 'lvlh'.

    Examples
    --------
    Three wheels on the body axes; a body turned by 0.1 rad about z, at rest: the wheels push it back (the motor
    torque about z is +k_p e_z, the body's -k_p e_z):

    >>> law = rd.control.PDAttitude(2.0, 1.0, np.eye(3))
    >>> q = [0.0, 0.0, np.sin(0.05), np.cos(0.05)]
    >>> state = rd.SampledState(0.0, np.zeros((1, 3)), np.array([q]), np.zeros((1, 3)), np.zeros((1, 3)),
    ...                         np.zeros(3))
    >>> law(state)["wheel_torque"].round(6).tolist()
    [0.0, 0.0, 0.199917]
    """

    def __init__(self, k_p: float, k_d: float, axes_B: Any, *, q_target_WB: Any = (0.0, 0.0, 0.0, 1.0),
                 body: int = 0) -> None:
        self.k_p = _positive(k_p, "k_p", "[N m/rad]")
        self.k_d = _positive(k_d, "k_d", "[N m s/rad]")
        A = np.asarray(axes_B, dtype=float)
        if A.ndim != 2 or A.shape[1] != 3 or not np.all(np.isfinite(A)):
            raise ValueError(f"axes_B: expected finite wheel axes of shape (nw, 3), got shape {A.shape}")
        if np.linalg.matrix_rank(A) < 3:
            raise ValueError(f"axes_B: expected wheel axes spanning 3 dimensions, got {A.tolist()}")
        A = A / np.linalg.norm(A, axis=1, keepdims=True)
        A.setflags(write=False)
        self.axes_B = A  # the unit axes, as the allocation uses them
        self._allocation = -np.linalg.pinv(A.T)  # u = -pinv([a_1 ... a_n]) tau_B
        if isinstance(q_target_WB, str) and q_target_WB != "lvlh":
            raise ValueError(f"q_target_WB: expected a quaternion (x, y, z, w), a callable of t or 'lvlh', "
                             f"got {q_target_WB!r}")
        self.q_target_WB = q_target_WB
        self.body = int(body)

    def target(self, state: SampledState) -> np.ndarray:
        """The target attitude q_target_WB (x, y, z, w) at the sample `state`.

        Parameters
        ----------
        state : SampledState
            The sample (its t, and the body's p_W and v_W for 'lvlh').

        Returns
        -------
        numpy.ndarray, shape (4,)
            The target, as given, of t, or LVLH's q_WO.

        Examples
        --------
        Below the centre on -z_W, moving along +x_W: LVLH's z points up +z_W (to the centre), x along the track
        +x_W, y along +y_W (opposite the orbit normal r x v along -y_W): LVLH is W itself:

        >>> law = rd.control.PDAttitude(1.0, 1.0, np.eye(3), q_target_WB="lvlh")
        >>> state = rd.SampledState(0.0, np.array([[0.0, 0.0, -7e6]]), np.array([[0.0, 0.0, 0.0, 1.0]]),
        ...                         np.array([[7.5e3, 0.0, 0.0]]), np.zeros((1, 3)), np.zeros(3))
        >>> np.abs(law.target(state)).round(12).tolist()
        [0.0, 0.0, 0.0, 1.0]
        """
        if isinstance(self.q_target_WB, str):  # 'lvlh'
            from . import _core

            b = self.body
            R_WO = _core.orbit_frame_rotation(state.p_W[b], state.v_W[b], frame="lvlh")
            return np.asarray(_core.matrix_to_quat(R_WO), dtype=float)
        target = self.q_target_WB(state.t) if callable(self.q_target_WB) else self.q_target_WB
        return np.asarray(target, dtype=float)

    @staticmethod
    def error(q_WB: Any, q_target_WB: Any) -> np.ndarray:
        """The attitude error e = 2 sign(eta) epsilon of q_e = q_target^-1 q_WB = (epsilon, eta), in B.

        Parameters
        ----------
        q_WB : array_like, shape (4,)
            The attitude (x, y, z, w).
        q_target_WB : array_like, shape (4,)
            The target (x, y, z, w).

        Returns
        -------
        numpy.ndarray, shape (3,)
            e [rad], the rotation vector of q_e to first order (|e| = 2 sin(angle/2)).

        Examples
        --------
        >>> rd.control.PDAttitude.error([np.sin(0.05), 0.0, 0.0, np.cos(0.05)], [0.0, 0.0, 0.0, 1.0]).round(6).tolist()
        [0.099958, 0.0, 0.0]
        """
        q_t, q = _unit(q_target_WB), _unit(q_WB)
        u_t, w_t, u, w = -q_t[:3], float(q_t[3]), q[:3], float(q[3])  # q_target^-1 = (-u_t, w_t)
        epsilon = w_t * u + w * u_t + _cross(u_t, u)  # the Hamilton product's vector part
        eta = w_t * w - float(u_t @ u)
        e: np.ndarray = 2.0 * math.copysign(1.0, eta) * epsilon
        return e

    def __call__(self, state: SampledState) -> dict[Any, Any]:
        b = self.body
        tau_B = -self.k_p * self.error(state.q_WB[b], self.target(state)) - self.k_d * state.w_B[b]
        return {"wheel_torque": self._allocation @ tau_B}
