"""Linear stability of the fixed-step methods for the spin at hand.

Linearising Euler's equations I w' = (I w) x w about the current w gives dw' = J dw with
J = I^-1 ([I w]x - [w]x I) (eigenvalues 0 and +-lambda: imaginary about the largest and smallest
axes (nutation), real about the intermediate one (the physical Dzhanibekov instability)). The
quaternion kinematics q' = q (x) (0, w)/2 adds no unstable mode: every method's attitude update is
q_next = q (x) P with P a quaternion built from the stages of w alone, then renormalised, so it maps
unit quaternions isometrically whatever |P| (the Runge-Kutta tableau's modes +-i|w|/2 only scale P).
A body without gyroscopic term (isotropic inertia: (I w) x w = 0 for every w, a sphere or a cube)
has nothing to destabilise: w' = I^-1 n is integrated without spin-dependent term, so no method
is beyond a stability limit on it (see gyroscopic_free).
A one-step method maps a mode exp(lambda t) by its stability polynomial R(z) at
z = h lambda, the exact flow by exp(z): the spurious growth per step is |R(z)| / exp(Re z), over n
steps its n-th power. As w moves (a tumbling body passes near axes where the nutation is fast), the
growth is averaged in log over the orbit: for a torque-free body, ORBIT_SAMPLES states of the exact
Euler-Poinsot solution over one period (or the run); otherwise the initial w only. rigiddyn warns
(StabilityWarning) when the predicted growth over the run exceeds GROWTH_LIMIT.

Methods absent from STABILITY_POLYNOMIALS are checked against the documented `stability_limit`
of methods() (carried by the C++ MethodInfo): the largest dt |w| at which the method keeps what it
promises on a free spin, |w| taken as the largest body rate along the orbit (ORBIT_SAMPLES states
of the torque-free solution, or the initial w). inf means unconditionally stable (the implicit-
gyroscopic Euler damps, the exact flow and exact_flow_kick are exact); the splitting methods lose
their small energy error beyond it (|L| stays exact), implicit midpoint's Newton iteration may stop
unconverged.

Scenes (scene_stability_message): each rigid body's spin as above, and the linear modes of the force
elements at the initial state (scene_modes: springs, dampers, gravity, drag, gravity gradient), each
checked with the method's one-step map on x'' = -k x - gamma x' (oscillator_map; the documented
stability_limit on dt (sqrt|k| + gamma) for a method not modelled there). The modes are taken one at a
time and at the start only: an estimate of the scene's fastest rates, not its full linearisation.

Bodies about a fixed point and moving frames (same reasoning, their own rates):
- a pivoted body (PivotedBody) turns about its pivot O with Euler's equations about O, I_O w' = tau_O -
  w x I_O w ("Rigid body kinematics and dynamics" notes, M_O = dH_O/dt): its spin is checked as a rigid
  body's above with the inertia about O, I_O (torque-free along its orbit when the scene has no element
  and no frame);
- its swing under uniform gravity g: the potential V = -m g.(R c) (c = p_OC_B) has, about the hanging
  attitude, the Hessian m |g| |c| P (P: the projector normal to c; gravity has no torque about c), so the
  small oscillations solve I_O x'' = -m |g| |c| P x: modes x'' = -k x with k up to m |g| |c| lambda_max(P
  I_O^-1 P) (the generalised eigenvalue of (K, I_O); m |g_xy| |c| / I_O,zz for the PivotedPlanarBody:
  the compound pendulum's sqrt(m g d / I_O)), checked as a spring's mode (pivot_swing_modes). k is taken
  positive, the swing about the hanging attitude that any swing passes near; upright (the heavy top) the
  same |k| is a physical instability, which the exact flow shares. A PivotedPlanarBody's own rate omega adds
  no mode (theta' = omega: no gyroscopic term in one degree of freedom);
- a rotating frame (scene.frame, turning at Omega) adds to every body the centrifugal -Omega x (Omega x r)
  and the Coriolis -2 Omega x v ("Rigid body kinematics and dynamics" notes, eq. 4.40). In the plane
  normal to Omega, with r written as a complex number x, they are x'' = Omega^2 x - 2 i |Omega| x': the
  mode of x'' = -k x - gamma x' with k = -Omega^2 and an imaginary gamma = 2 i |Omega| (the Coriolis
  term turns the velocity at the rate 2 |Omega|; the exact flow's eigenvalues are -i|Omega| twice, a
  turn: no growth). Every method's map of the oscillator (oscillator_map) is taken in complex
  arithmetic: explicit Euler and the kicks of the semi-implicit Euler methods (explicit in the velocity)
  grow by about sqrt(1 + (2 |Omega| s)^2) per kick of length s; the splittings' kicks take the turn's
  exact flow (the core's loads_kick), so they are bounded while the drifts resolve the centrifugal term;
  RK4's map of the eigenvalues -i|Omega| is stable up to dt |Omega| = 2 sqrt(2), and implicit midpoint's
  Cayley map is an isometry of the turn (frame_modes).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from . import _core
from ._names import require_method

__all__ = [
    "GROWTH_LIMIT",
    "ISOTROPY_TOLERANCE",
    "STABILITY_POLYNOMIALS",
    "StabilityWarning",
    "frame_modes",
    "growth_factor",
    "gyroscopic_free",
    "linear_modes",
    "mean_growth_factor",
    "mode_message",
    "orbit",
    "orbit_rate",
    "oscillator_growth",
    "oscillator_map",
    "pivot_swing_modes",
    "scene_modes",
    "scene_stability_message",
    "spin_rate",
    "stability_limit",
    "stability_message",
    "warn_if_unstable",
]

GROWTH_LIMIT = 10.0
ORBIT_SAMPLES = 64

# method -> (coefficients of R(z) = sum c_k z^k, whether the kinematic modes +-i|w|/2 count: never, the
# attitude update q (x) P is renormalised every step, an isometry of the unit quaternions; the flag
# stays for linear_modes' callers)
STABILITY_POLYNOMIALS = {
    "explicit_euler": ((1.0, 1.0), False),
    "semi_implicit_euler": ((1.0, 1.0), False),  # explicit gyroscopic term; exact exponential for q
    "rk4": ((1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24), False),
    "rkmk4": ((1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24), False),  # RK4 tableau; q by the exponential map
}
# principal moments equal within this x the largest (a few roundings of a computed sphere's inertia):
# no gyroscopic term
ISOTROPY_TOLERANCE = 64 * np.finfo(float).eps


class StabilityWarning(RuntimeWarning):
    """dt is beyond a method's linear stability limit for the spin at hand."""

    def __init__(self, *args: object) -> None:  # its signature for inspect (a built-in base has none)
        super().__init__(*args)


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def gyroscopic_free(inertia_com: np.ndarray) -> bool:
    """True if the inertia about the centre of mass [kg m^2] is isotropic (principal moments equal
    within ISOTROPY_TOLERANCE relative): then (I w) x w = 0 for every w_B, Euler's equations
    I w' = n - w x I w have no gyroscopic term and every method integrates w' = I^-1 n stably."""
    moments = np.linalg.eigvalsh(np.asarray(inertia_com, float))
    return bool(moments[-1] - moments[0] <= ISOTROPY_TOLERANCE * abs(moments[-1]))


def linear_modes(inertia_com: np.ndarray, w_B: np.ndarray, kinematics: bool) -> np.ndarray:
    """Eigenvalues [1/s] of J = I^-1([I w]x - [w]x I), plus +-i|w|/2 if `kinematics`."""
    inertia = np.asarray(inertia_com, float)
    w = np.asarray(w_B, float)
    modes = np.linalg.eigvals(np.linalg.solve(inertia, _skew(inertia @ w) - _skew(w) @ inertia))
    if kinematics:
        modes = np.append(modes, 0.5j * np.linalg.norm(w))
    return modes


def spin_rate(inertia_com: np.ndarray, w_B: np.ndarray, kinematics: bool) -> float:
    """rho [rad/s]: the largest |lambda| of linear_modes."""
    return float(np.max(np.abs(linear_modes(inertia_com, w_B, kinematics))))


def growth_factor(method: str, dt: float, inertia_com: np.ndarray, w_B: np.ndarray) -> float | None:
    """max over the linear modes at w_B of |R(dt lambda)| / exp(dt Re lambda): the spurious
    amplification per step; None for a method that is not checked."""
    if method not in STABILITY_POLYNOMIALS:
        return None
    coefficients, kinematics = STABILITY_POLYNOMIALS[method]
    z = dt * linear_modes(inertia_com, w_B, kinematics)
    return float(np.max(np.abs(np.polyval(coefficients[::-1], z)) / np.exp(z.real)))


def orbit(inertia_com: np.ndarray, w_B: np.ndarray, span: float) -> np.ndarray:
    """(ORBIT_SAMPLES, 3) angular velocities [rad/s] of the torque-free motion from w_B, evenly in
    time over one period of w (or `span` [s] if shorter or the period is infinite)."""
    # the inertia of a body or problem, checked when that was built (with the check it chose)
    solution = _core.TorqueFreeSolution(inertia_com, np.array([0.0, 0.0, 0.0, 1.0]), w_B,
                                        check=_core.InertiaCheck.allow_unrealizable)
    period = solution.period
    end = min(period, span) if math.isfinite(period) else span
    _, w = solution.state_at(np.linspace(0.0, end, ORBIT_SAMPLES, endpoint=False))
    return np.asarray(w)


def mean_growth_factor(method: str, dt: float, inertia_com: np.ndarray, w_B: np.ndarray, span: float,
                       torque_free: bool = True) -> float | None:
    """growth_factor averaged in log over the orbit (torque-free) or at w_B; None if not checked."""
    if method not in STABILITY_POLYNOMIALS:
        return None
    states = orbit(inertia_com, w_B, span) if torque_free and np.any(w_B) else [w_B]
    factors = [growth_factor(method, dt, inertia_com, w) for w in states]
    return float(np.exp(np.mean([math.log(g) for g in factors if g is not None])))


def stability_limit(method: str) -> float:
    """The documented largest dt |w| [rad] of `method` on a free spin (methods()['stability_limit'])."""
    require_method(method)
    return float(next(m["stability_limit"] for m in _core.methods() if m["name"] == method))


def orbit_rate(inertia_com: np.ndarray, w_B: np.ndarray, span: float, torque_free: bool = True) -> float:
    """The largest |w| [rad/s] along the torque-free orbit from w_B (torque-free) or |w_B|."""
    w = np.asarray(w_B, float)
    states = orbit(inertia_com, w, span) if torque_free and np.any(w) else [w]
    return float(max(np.linalg.norm(x) for x in states))


def _limit_message(method: str, dt: float, steps: int, inertia_com: np.ndarray, w_B: np.ndarray,
                   torque_free: bool) -> str | None:
    """A message if dt |w| exceeds the documented stability_limit of a method without a polynomial."""
    limit = stability_limit(method)
    if math.isinf(limit):
        return None
    rate = orbit_rate(inertia_com, w_B, dt * steps, torque_free)
    if dt * rate <= limit:
        return None
    return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for this spin: dt*|w| = {dt * rate:.3g} "
            f"> {limit:.3g}, the documented limit (methods()); |w| up to {rate:.3g} rad/s along the orbit, "
            f"where {method} does not keep what it promises")


def stability_message(method: str, dt: float, steps: int, inertia_com: np.ndarray, w_B: np.ndarray,
                      torque_free: bool = True) -> str | None:
    """A message if perturbations grow by more than GROWTH_LIMIT over `steps` steps (methods with a
    stability polynomial) or dt |w| exceeds the documented stability_limit (the others), else None
    ("<method> at dt = ... s is beyond ...: <the figure that exceeds its limit>; <details>");
    always None for a body without gyroscopic term (gyroscopic_free: nothing to destabilise)."""
    if gyroscopic_free(inertia_com):
        return None
    if method not in STABILITY_POLYNOMIALS:
        return _limit_message(method, dt, steps, inertia_com, w_B, torque_free)
    g = mean_growth_factor(method, dt, inertia_com, w_B, dt * steps, torque_free)
    if g is None or g <= 1.0:
        return None
    log_growth = steps * math.log(g)
    if log_growth <= math.log(GROWTH_LIMIT):
        return None
    rho = spin_rate(inertia_com, w_B, STABILITY_POLYNOMIALS[method][1])
    return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for this spin: dt*rho = {dt * rho:.3g}, "
            f"perturbations grow spuriously about 10^{log_growth / math.log(10):.3g}-fold over {steps} steps; "
            f"rho = {rho:.3g} rad/s (the fastest linear mode at the start), x{g:.6g} per step on average")


def warn_if_unstable(method: str, dt: float, steps: int, inertia_com: np.ndarray, w_B: np.ndarray,
                     torque_free: bool = True, stacklevel: int = 2) -> str | None:
    """Emit a StabilityWarning with stability_message(...) when there is one; return it."""
    message = stability_message(method, dt, steps, inertia_com, w_B, torque_free)
    if message is not None:
        warnings.warn(message, StabilityWarning, stacklevel=stacklevel + 1)
    return message


# ---------------------------------------------------------------------------------------------
# scenes: the linear modes of the force elements
#
# Linearised about the initial state, each element adds modes of x'' = -k x - gamma x' to the bodies
# it couples (k [1/s^2], gamma [1/s]; k < 0: a physical instability, the radial mode of gravity). A
# method's one-step map on y = (x, x') is a 2x2 matrix M(h); its spurious growth per step is the
# spectral radius of M over the exact flow's, exp(h max Re lambda) (lambda: eigenvalues of
# A = [[0, 1], [-k, -gamma]]). Splittings kick with the force (velocities frozen: explicit in gamma,
# exact for a turn) and drift the positions, as the core's loads_kick . free_flow . loads_kick
# compositions do.

MIDPOINT_TOLERANCE = 1e-14  # implicit midpoint's stage tolerance and iteration cap (integrators/implicit_midpoint.hpp)
MIDPOINT_ITERATIONS = 20
_YOSHIDA_OUTER = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))  # the triple jump's outer weights (Yoshida 1990)
_YOSHIDA_INNER = 1.0 - 2.0 * _YOSHIDA_OUTER


def _kick(s: float, k: float, gamma: complex, exact_turn: bool = False) -> np.ndarray:
    """v += phi (-k x - gamma v) with x frozen: phi = s (explicit), or, for a turn (imaginary gamma) with
    `exact_turn`, phi = (1 - exp(-gamma s)) / gamma, the exact flow of v' = -k x - gamma v (the splittings'
    loads_kick takes the Coriolis part's exact flow: scene_model.hpp, detail::exact_linear_kick)."""
    phi = (1.0 - np.exp(-gamma * s)) / gamma if exact_turn and isinstance(gamma, complex) and gamma != 0 else s
    return np.array([[1.0, 0.0], [-phi * k, 1.0 - phi * gamma]])


def _drift(s: float) -> np.ndarray:
    """x += s v."""
    return np.array([[1.0, s], [0.0, 1.0]])


def _strang(h: float, k: float, gamma: complex) -> np.ndarray:
    """loads_kick(h/2) drift(h) loads_kick(h/2) (the rightmost factor acts first; a turn's kick exact)."""
    return np.asarray(_kick(h / 2, k, gamma, True) @ _drift(h) @ _kick(h / 2, k, gamma, True))


def oscillator_map(method: str, h: float, k: float, gamma: complex) -> np.ndarray | None:
    """The one-step map of `method` at step h [s] on x'' = -k x - gamma x' (y = (x, x')), None for a
    method not modelled here (its documented stability_limit is used instead). gamma [1/s] may be
    imaginary (a turn of the velocity: the Coriolis term of frame_modes, x complex); the map is then
    complex."""
    a = np.array([[0.0, 1.0], [-k, -gamma]])
    if method in STABILITY_POLYNOMIALS and method not in ("semi_implicit_euler",):
        coefficients, _ = STABILITY_POLYNOMIALS[method]
        power, out = np.eye(2), np.zeros((2, 2))
        for c in coefficients:  # R(h A) = sum c_j (h A)^j
            out, power = out + c * power, power @ (h * a)
        return out
    if method.startswith("semi_implicit_euler"):  # v first from x, then x from the new v
        return np.asarray(_drift(h) @ _kick(h, k, gamma))
    if method in ("splitting_dlm", "exact_flow_kick"):
        return _strang(h, k, gamma)
    if method == "splitting_dlm_yoshida4":
        outer = _strang(_YOSHIDA_OUTER * h, k, gamma)
        return np.asarray(outer @ _strang(_YOSHIDA_INNER * h, k, gamma) @ outer)
    if method == "implicit_midpoint":  # the Cayley map (I - hA/2)^-1 (I + hA/2), once converged
        return np.linalg.solve(np.eye(2) - 0.5 * h * a, np.eye(2) + 0.5 * h * a)
    return None


def oscillator_growth(method: str, h: float, k: float, gamma: complex) -> float | None:
    """Spurious growth per step of `method` on x'' = -k x - gamma x': the spectral radius of its map
    over exp(h max Re lambda) of the exact flow; None for a method not modelled."""
    m = oscillator_map(method, h, k, gamma)
    if m is None:
        return None
    exact = float(np.max(np.linalg.eigvals(np.array([[0.0, 1.0], [-k, -gamma]])).real))
    return float(np.max(np.abs(np.linalg.eigvals(m)))) / math.exp(h * exact)


def _minimum_moment(body: object) -> float:
    """The smallest principal moment [kg m^2] of a rigid body, I_zz of a planar one, 0 for a particle."""
    if isinstance(body, _core.RigidBody):
        return float(np.linalg.eigvalsh(np.asarray(body.inertia_com, float))[0])
    if isinstance(body, _core.PlanarBody):
        return float(body.inertia_zz)
    return 0.0


def _joint_inertia(link: _core.TreeLink) -> float:
    """The link's own inertia along its joint [kg m^2 or kg]: a . I_O a, I_O its inertia about the link frame's
    origin (SpatialInertia.inertia_about_origin), for a revolute joint's axis a; the least principal moment of I_O for
    a spherical joint; its mass for a prismatic joint (the links beyond add to it, the parent's freedom takes from it:
    a mode's estimate, as the springs' above)."""
    joint = link.tree.joints[link.link]
    if isinstance(joint, _core.PrismaticJoint):
        return float(link.mass)
    inertia_O = np.asarray(link.tree.inertias[link.link].inertia_about_origin(), float)
    if isinstance(joint, _core.SphericalJoint):  # its least principal moment: the fastest of its three modes
        return float(np.linalg.eigvalsh(inertia_O)[0])
    a = np.asarray(joint.axis, float)
    return float(a @ inertia_O @ a)


def _inverse_mass_at(body: object, r_B: np.ndarray) -> float:
    """1 / m_eff [1/kg] of the body point r_B (from the centre of mass, in B [m]) moved by a spring: 1/m
    for a free body (its turn is a mode of its own), |c + r|^2 / I_min about O for a pinned body, which
    can only turn about its pivot (c = p_OC_B; _turn_compliance; the in-plane part and I_O,zz for a
    PivotedPlanarBody)."""
    if isinstance(body, _core.PivotedBody):
        return _turn_compliance(np.asarray(body.inertia_O, float), np.asarray(body.p_OC_B, float) + r_B)
    if isinstance(body, _core.PivotedPlanarBody):
        arm = np.asarray(body.p_OC_B, float) + r_B[:2]
        return float(arm @ arm) / float(body.inertia_O_zz)
    return 1.0 / float(getattr(body, "mass"))


def _listed(element: object, n: int) -> list[int]:
    bodies = getattr(element, "bodies", None)
    return list(range(n)) if not bodies else [int(b) for b in bodies]


def _gravity_modes(label: str, gm: float, r: np.ndarray, softening: float) -> list[tuple[str, float, float]]:
    """x'' = -H x for V = -gm / rho (rho^2 = |r|^2 + eps^2): H's eigenvalues gm / rho^3 (transverse)
    and gm (eps^2 - 2 |r|^2) / rho^5 (radial; < 0 unsoftened: the physical instability)."""
    r2 = float(r @ r)
    rho2 = r2 + softening**2
    if rho2 == 0.0:
        return [(label + " at zero separation", math.inf, 0.0)]
    rho3 = rho2 * math.sqrt(rho2)
    return [(label, gm / rho3, 0.0), (label + " (radial)", gm * (softening**2 - 2.0 * r2) / (rho2 * rho3), 0.0)]


def _swing_stiffness(body: object) -> float:
    """k / |g| [1/m] of a pinned body's fastest swing, 0 for another body or one pinned at its centre of
    mass: m |c| lambda_max(P I_O^-1 P) (P the projector normal to c = p_OC_B; module docstring), m |c| /
    I_O,zz in the plane (the caller projects g onto it)."""
    if isinstance(body, _core.PivotedPlanarBody):
        return float(body.mass) * float(np.linalg.norm(np.asarray(body.p_OC_B, float))) / float(body.inertia_O_zz)
    if not isinstance(body, _core.PivotedBody):
        return 0.0
    c = np.asarray(body.p_OC_B, float)
    d = float(np.linalg.norm(c))
    return 0.0 if d == 0.0 else float(body.mass) / d * _turn_compliance(np.asarray(body.inertia_O, float), c)


def _turn_compliance(inertia_O: np.ndarray, arm: np.ndarray) -> float:
    """|a|^2 lambda_max(P I_O^-1 P) [1/kg], P the projector normal to the arm a (from O, in B [m]): the
    largest (a x f).I_O^-1 (a x f) / |f|^2 over forces f at a, the inverse mass a force at a meets on a
    body that can only turn about O (I_O [kg m^2] in B); 0 for a = 0."""
    length2 = float(arm @ arm)
    if length2 == 0.0:
        return 0.0
    normal = np.eye(3) - np.outer(arm, arm) / length2
    return length2 * float(np.max(np.linalg.eigvalsh(normal @ np.linalg.inv(inertia_O) @ normal)))


def pivot_swing_modes(label: str, bodies: list[object], listed: list[int], g_W: np.ndarray) -> list[tuple[str, float, float]]:
    """The swing modes (label, k [1/s^2], 0) of the pinned bodies `listed` under uniform gravity g_W
    [m/s^2] in the scene frame: k = |g| m |c| lambda_max(P I_O^-1 P), sqrt(k) the pendulum frequency
    sqrt(m g d / I_O) of the fastest swing (g's in-plane part for a PivotedPlanarBody)."""
    g = np.asarray(g_W, float)
    modes = []
    for i in listed:
        stiffness = _swing_stiffness(bodies[i])
        g_acting = g[:2] if isinstance(bodies[i], _core.PivotedPlanarBody) else g
        if stiffness > 0.0 and np.any(g_acting):
            modes.append((f"the swing of body {i} under {label}", stiffness * float(np.linalg.norm(g_acting)), 0.0))
    return modes


def frame_modes(scene: object, t: float = 0.0) -> list[tuple[str, float, complex]]:
    """The mode (label, k = -|Omega|^2 [1/s^2], gamma = 2 i |Omega| [1/s]) of the scene's frame turning at
    Omega [rad/s] at time t [s] (the centrifugal and Coriolis terms in the plane normal to Omega, module
    docstring); [] without a frame or while it does not turn."""
    frame = getattr(scene, "frame", None)
    if frame is None or not len(list(getattr(scene, "bodies"))):
        return []
    rate = float(np.linalg.norm(np.asarray(frame.motion.at(t).w_PF_P, float)))
    if rate == 0.0 or not math.isfinite(rate):  # non-finite: compile refuses the frame, naming it
        return []
    return [(f"the rotating frame (|Omega| = {rate:.3g} rad/s: Coriolis turn 2|Omega|, centrifugal |Omega|^2)",
             -rate**2, 2j * rate)]


def _air_density(air: _core.AtmosphericDrag, altitude: float) -> float:
    """An AtmosphericDrag's density [kg/m^3] at `altitude` [m], as the element computes it: exponential, or
    log-linear between its table's rows (the outermost bands extended); infinite deep inside the planet."""
    with np.errstate(over="ignore"):  # deep inside the planet: an infinite rate, named as such
        h = np.asarray(air.table_altitude, float)
        if h.size == 0:
            return float(air.density0) * float(np.exp(-(altitude - float(air.altitude0)) / float(air.scale_height)))
        log_rho = np.log(np.asarray(air.table_density, float))
        i = int(np.clip(np.searchsorted(h, altitude, side="right") - 1, 0, h.size - 2))
        slope = (log_rho[i + 1] - log_rho[i]) / (h[i + 1] - h[i])
        return float(np.exp(log_rho[i] + slope * (altitude - h[i])))


def scene_modes(scene: object, initial: list[object]) -> list[tuple[str, float, float]]:
    """The linear modes (label, k [1/s^2], gamma [1/s]) of the scene's elements at the initial states:
    springs k (1/m_a + 1/m_b) (a pinned end: |c + r|^2 / I_O,min for 1/m, _inverse_mass_at) and, at a
    point r off a free body's centre, k |r|^2 / I_min (dampers the same in gamma); point-mass gravity the Hessian of the (softened) potential per body, mutual gravity
    that of its strongest pair (largest G (m_i + m_j) / rho^3); drag gamma = (c1 + 2 c2 |v|) / m and
    (d1 + 2 d2 |w|) / I_min; gravity gradient k = 3 GM / |r|^3 (I_max - I_min) / I_min; uniform gravity
    the swing of each pinned body (pivot_swing_modes); a joint spring k / I_a and c / I_a, I_a the link's own
    inertia along its joint (_joint_inertia). Scheduled loads and user forces add no mode, nor
    does uniform gravity on a free body; the frame's modes are frame_modes."""
    bodies = list(getattr(scene, "bodies"))
    n = len(bodies)
    p = [np.asarray(getattr(s, "p_W", np.zeros(3)), float) for s in initial]
    v = [np.asarray(getattr(s, "v_W", np.zeros(3)), float) for s in initial]
    w = [float(np.linalg.norm(getattr(s, "w_B", np.zeros(3)))) or abs(float(getattr(s, "omega", 0.0)))
         for s in initial]
    mass = [float(getattr(b, "mass")) for b in bodies]
    moment = [_minimum_moment(b) for b in bodies]
    modes: list[tuple[str, float, float]] = []
    for index, element in enumerate(getattr(scene, "elements")):
        kind, label = type(element).__name__, f"elements[{index}]"
        if kind == "SpringDamper":
            a, b = int(element.body_a), element.body_b
            ends = [(a, np.asarray(element.point_a_B, float))]
            if b is not None and int(b) >= 0:
                ends.append((int(b), np.asarray(element.point_b, float)))
            inverse_mass = sum(_inverse_mass_at(bodies[i], r) for i, r in ends)
            k, c = float(element.stiffness), float(element.damping)
            modes.append((f"the spring {label}", k * inverse_mass, c * inverse_mass))
            for i, r in ends:
                if moment[i] > 0 and np.any(r):
                    lever = float(r @ r) / moment[i]
                    modes.append((f"the spring {label} turning body {i}", k * lever, c * lever))
        elif kind in ("RevoluteSpringDamper", "PrismaticSpringDamper", "SphericalSpringDamper"):
            inertia = _joint_inertia(bodies[int(element.body)])
            k, c = float(element.stiffness), float(element.damping)
            modes.append((f"the joint spring {label}", k / inertia, c / inertia))
        elif kind == "PointMassGravity":
            for i in _listed(element, n):
                modes += _gravity_modes(f"the attractor {label} on body {i}", float(element.gm),
                                        p[i] - np.asarray(element.p_W, float), float(element.softening))
        elif kind == "ZonalGravity":  # its central term (the zonal ones are J_n (R/r)^n smaller)
            for i in _listed(element, n):
                modes += _gravity_modes(f"the central body {label} on body {i}", float(element.gm),
                                        p[i] - np.asarray(element.p_W, float), 0.0)
        elif kind == "MutualGravity" and len(_listed(element, n)) > 1:
            # the pair with the largest G (m_i + m_j) / rho^3 (vectorised: O(N^2) pairs in numpy)
            listed = np.array(_listed(element, n))
            position, m = np.array([p[i] for i in listed]), np.array([mass[i] for i in listed])
            rho2 = np.sum((position[:, None] - position[None]) ** 2, axis=2) + float(element.softening) ** 2
            with np.errstate(divide="ignore"):
                strength = (m[:, None] + m[None]) / rho2**1.5
            np.fill_diagonal(strength, -np.inf)
            i, j = (int(listed[x]) for x in np.unravel_index(int(np.argmax(strength)), strength.shape))
            modes += _gravity_modes(f"the gravity {label} between bodies {min(i, j)} and {max(i, j)} (the strongest pair)",
                                    float(element.G) * (mass[i] + mass[j]), p[i] - p[j], float(element.softening))
        elif kind == "Drag":
            for i in _listed(element, n):
                modes.append((f"the drag {label} on body {i}", 0.0,
                              (float(element.linear) + 2.0 * float(element.quadratic) * float(np.linalg.norm(v[i]))) / mass[i]))
                if moment[i] > 0:
                    modes.append((f"the angular drag {label} on body {i}", 0.0,
                                  (float(element.angular_linear) + 2.0 * float(element.angular_quadratic) * w[i]) / moment[i]))
        elif kind == "AtmosphericDrag":  # f = -(1/2) rho C_D A |v_rel| v_rel: a damping rate rho C_D A |v_rel| / m
            for i in _listed(element, n):
                r = p[i] - np.asarray(element.p_W, float)
                altitude = float(np.linalg.norm(r)) - float(element.radius)
                rho = _air_density(element, altitude)
                v_rel = float(np.linalg.norm(v[i] - np.cross(np.asarray(element.omega_W, float), r)))
                modes.append((f"the air {label} on body {i}", 0.0, rho * float(element.drag_area) * v_rel / mass[i]))
        elif kind == "UniformGravity":
            modes += pivot_swing_modes(f"the gravity {label}", bodies, _listed(element, n), np.asarray(element.g_W, float))
        elif kind == "GravityGradient":
            for i in _listed(element, n):
                if isinstance(bodies[i], _core.RigidBody) and moment[i] > 0:
                    r = p[i] - np.asarray(element.p_W, float)
                    spread = float(np.ptp(np.linalg.eigvalsh(np.asarray(bodies[i].inertia_com, float))))
                    modes.append((f"the gravity gradient {label} on body {i}",
                                  3.0 * float(element.gm) / float(r @ r) ** 1.5 * spread / moment[i], 0.0))
        elif kind == "MagneticDipole":
            dipole = float(np.linalg.norm(np.asarray(element.m_B, float)))
            for i in _listed(element, n):
                if moment[i] > 0:  # a compass needle's libration: I theta'' = -|m| |B| theta
                    field = float(np.linalg.norm(_magnetic_field(p[i], element)))
                    modes.append((f"the magnetic dipole {label} on body {i}", dipole * field / moment[i], 0.0))
    return modes


MU0_OVER_4PI = 1.25663706212e-6 / (4.0 * math.pi)  # mu0/(4 pi) [N/A^2] (CODATA 2018), as the core's MagneticDipole


def _magnetic_field(p_W: np.ndarray, element: object) -> np.ndarray:
    """B(p_W) [T] of a MagneticDipole's field: its uniform B_W plus its source dipole's
    mu0/(4 pi) (3 r (r . M)/|r|^5 - M/|r|^3), r = p_W - source_p_W."""
    field = np.asarray(getattr(element, "B_W"), float).copy()
    moment = np.asarray(getattr(element, "source_moment_W"), float)
    if np.any(moment):
        r = p_W - np.asarray(getattr(element, "source_p_W"), float)
        r2 = float(r @ r)
        field += MU0_OVER_4PI / (r2 * math.sqrt(r2)) * (3.0 * float(r @ moment) / r2 * r - moment)
    return field


def _mode_rate(k: float, gamma: complex) -> float:
    """The fastest rate [1/s] of x'' = -k x - gamma x': sqrt|k| + gamma (a bound on |lambda|); for a turn
    (imaginary gamma: frame_modes) |gamma| = 2 |Omega|, the rate at which a kick turns the velocity."""
    return abs(gamma) if isinstance(gamma, complex) else math.sqrt(abs(k)) + gamma


def mode_message(method: str, dt: float, steps: int, label: str, k: float, gamma: complex) -> str | None:
    """A message if `method` at dt [s] amplifies the mode x'' = -k x - gamma x' spuriously by more than
    GROWTH_LIMIT over `steps` steps (or, for a method not modelled, dt sqrt(|k|) or dt gamma exceeds
    its documented stability_limit), else None; worded as stability_message. An imaginary gamma is a
    turn (frame_modes)."""
    turn = isinstance(gamma, complex)
    rate = _mode_rate(k, gamma)  # the mode's fastest rate [1/s]
    if not math.isfinite(rate):
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: an infinite rate "
                f"(bodies at zero separation)")
    # the fixed-point iteration below contracts by h |lambda| / 2, |lambda| = |Omega| = sqrt|k| for a turn
    contraction = dt * (math.sqrt(abs(k)) if turn else rate) / 2
    # a turn: warned only once the iteration diverges; while it converges slowly it stays within the
    # tolerance's reach (measured on two free particles at dt |Omega| = 0.5, contraction 0.25: the run is
    # within 4e-10 relative of the converged Cayley map after 1000 steps, the Jacobi integral at 1e-14)
    unconverged = contraction >= 1.0 if turn else contraction**MIDPOINT_ITERATIONS > MIDPOINT_TOLERANCE
    if method == "implicit_midpoint" and unconverged:
        # its stage solves y = y0 + (h/2) f(y) by fixed-point iteration on the forces (the Newton step covers
        # only the gyroscopic term), contracting by h |lambda| / 2 per iteration: beyond this it stops at
        # its cap unconverged and keeps neither energy nor its order
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate/2 = "
                f"{contraction:.3g}, the contraction of its fixed-point iteration, does not reach the tolerance "
                f"{MIDPOINT_TOLERANCE:g} in {MIDPOINT_ITERATIONS} iterations ({'diverges' if contraction >= 1 else 'slow'}); "
                f"rate = {2 * contraction / dt:.3g} 1/s ({'|Omega|' if turn else 'sqrt|k| + gamma'} at the start)")
    g = oscillator_growth(method, dt, k, gamma)
    if g is None:
        limit = stability_limit(method)
        if dt * rate <= limit:
            return None
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate = {dt * rate:.3g} "
                f"> {limit:.3g}, the documented limit (methods()); rate {rate:.3g} 1/s")
    if g <= 1.0 or steps * math.log(g) <= math.log(GROWTH_LIMIT):
        return None
    figures = (f"2|Omega| = {rate:.3g} rad/s (the Coriolis turn of the velocity; centrifugal k = {k:.3g} 1/s^2)" if turn
               else f"{rate:.3g} 1/s (sqrt|k| + gamma, k = {k:.3g} 1/s^2, gamma = {gamma:.3g} 1/s at the start)")
    return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate = {dt * rate:.3g}, "
            f"perturbations grow spuriously about 10^{steps * math.log(g) / math.log(10):.3g}-fold over {steps} "
            f"steps; rate = {figures}, x{g:.6g} per step")


def scene_stability_message(method: str, dt: float, steps: int, scene: object, initial: list[object],
                            modes: list[tuple[str, float, float]] | None = None) -> str | None:
    """The first (largest-rate) stability message of `method` at dt [s] over `steps` steps on a scene:
    each rigid body's spin (stability_message; a pinned body's with its inertia about the pivot, I_O;
    torque-free along the orbit if the scene has no element and no frame), each mode of scene_modes (or
    `modes`, computed once by the caller) and of frame_modes; None if stable."""
    modes = scene_modes(scene, initial) if modes is None else modes
    messages: list[tuple[float, str]] = []
    free = len(list(getattr(scene, "elements"))) == 0 and getattr(scene, "frame", None) is None
    for i, (body, state) in enumerate(zip(getattr(scene, "bodies"), initial)):
        inertia = (body.inertia_com if isinstance(body, _core.RigidBody)
                   else body.inertia_O if isinstance(body, _core.PivotedBody) else None)
        if inertia is not None:
            w_B = np.asarray(getattr(state, "w_B"), float)
            text = stability_message(method, dt, steps, np.asarray(inertia, float), w_B, free)
            if text:
                messages.append((float(np.linalg.norm(w_B)), text.replace("for this spin", f"for the spin of body {i}")))
    for label, k, gamma in [*modes, *frame_modes(scene)]:
        text = mode_message(method, dt, steps, label, k, gamma)
        if text:
            messages.append((_mode_rate(k, gamma), text))
    return max(messages)[1] if messages else None
