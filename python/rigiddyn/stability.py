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
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from . import _core

__all__ = [
    "GROWTH_LIMIT",
    "ISOTROPY_TOLERANCE",
    "STABILITY_POLYNOMIALS",
    "StabilityWarning",
    "growth_factor",
    "gyroscopic_free",
    "linear_modes",
    "mean_growth_factor",
    "mode_message",
    "orbit",
    "orbit_rate",
    "oscillator_growth",
    "oscillator_map",
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
    for info in _core.methods():
        if info["name"] == method:
            return float(info["stability_limit"])
    raise ValueError(f"method: expected one of {', '.join(m['name'] for m in _core.methods())}, got {method!r}")


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
# A = [[0, 1], [-k, -gamma]]). Splittings kick with the force (velocities frozen: explicit in gamma)
# and drift the positions, as the core's loads_kick . free_flow . loads_kick compositions do.

MIDPOINT_TOLERANCE = 1e-14  # implicit midpoint's stage tolerance and iteration cap (integrators/implicit_midpoint.hpp)
MIDPOINT_ITERATIONS = 20
_YOSHIDA_OUTER = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))  # the triple jump's outer weights (Yoshida 1990)
_YOSHIDA_INNER = 1.0 - 2.0 * _YOSHIDA_OUTER


def _kick(s: float, k: float, gamma: float) -> np.ndarray:
    """v += s (-k x - gamma v) with x frozen."""
    return np.array([[1.0, 0.0], [-s * k, 1.0 - s * gamma]])


def _drift(s: float) -> np.ndarray:
    """x += s v."""
    return np.array([[1.0, s], [0.0, 1.0]])


def _strang(h: float, k: float, gamma: float) -> np.ndarray:
    """kick(h/2) drift(h) kick(h/2) (the rightmost factor acts first)."""
    return np.asarray(_kick(h / 2, k, gamma) @ _drift(h) @ _kick(h / 2, k, gamma))


def oscillator_map(method: str, h: float, k: float, gamma: float) -> np.ndarray | None:
    """The one-step map of `method` at step h [s] on x'' = -k x - gamma x' (y = (x, x')), None for a
    method not modelled here (its documented stability_limit is used instead)."""
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


def oscillator_growth(method: str, h: float, k: float, gamma: float) -> float | None:
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


def scene_modes(scene: object, initial: list[object]) -> list[tuple[str, float, float]]:
    """The linear modes (label, k [1/s^2], gamma [1/s]) of the scene's elements at the initial states:
    springs k (1/m_a + 1/m_b) and, at a point r off a body's centre, k |r|^2 / I_min (dampers the
    same in gamma); point-mass gravity the Hessian of the (softened) potential per body, mutual gravity
    that of its strongest pair (largest G (m_i + m_j) / rho^3); drag gamma = (c1 + 2 c2 |v|) / m and
    (d1 + 2 d2 |w|) / I_min; gravity gradient k = 3 GM / |r|^3 (I_max - I_min) / I_min. Uniform gravity,
    scheduled loads and user forces add no mode."""
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
            inverse_mass = sum(1.0 / mass[i] for i, _ in ends)
            k, c = float(element.stiffness), float(element.damping)
            modes.append((f"the spring {label}", k * inverse_mass, c * inverse_mass))
            for i, r in ends:
                if moment[i] > 0 and np.any(r):
                    lever = float(r @ r) / moment[i]
                    modes.append((f"the spring {label} turning body {i}", k * lever, c * lever))
        elif kind == "PointMassGravity":
            for i in _listed(element, n):
                modes += _gravity_modes(f"the attractor {label} on body {i}", float(element.gm),
                                        p[i] - np.asarray(element.p_W, float), float(element.softening))
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
        elif kind == "GravityGradient":
            for i in _listed(element, n):
                if isinstance(bodies[i], _core.RigidBody) and moment[i] > 0:
                    r = p[i] - np.asarray(element.p_W, float)
                    spread = float(np.ptp(np.linalg.eigvalsh(np.asarray(bodies[i].inertia_com, float))))
                    modes.append((f"the gravity gradient {label} on body {i}",
                                  3.0 * float(element.gm) / float(r @ r) ** 1.5 * spread / moment[i], 0.0))
    return modes


def mode_message(method: str, dt: float, steps: int, label: str, k: float, gamma: float) -> str | None:
    """A message if `method` at dt [s] amplifies the mode x'' = -k x - gamma x' spuriously by more than
    GROWTH_LIMIT over `steps` steps (or, for a method not modelled, dt sqrt(|k|) or dt gamma exceeds
    its documented stability_limit), else None; worded as stability_message."""
    rate = math.sqrt(abs(k)) + gamma  # the mode's fastest rate [1/s]
    if not math.isfinite(rate):
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: an infinite rate "
                f"(bodies at zero separation)")
    contraction = dt * rate / 2
    if method == "implicit_midpoint" and contraction**MIDPOINT_ITERATIONS > MIDPOINT_TOLERANCE:
        # its stage solves y = y0 + (h/2) f(y) by fixed-point iteration on the forces (the Newton step covers
        # only the gyroscopic term), contracting by h |lambda| / 2 per iteration: beyond this it stops at
        # its cap unconverged and keeps neither energy nor its order
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate/2 = "
                f"{contraction:.3g}, the contraction of its fixed-point iteration, does not reach the tolerance "
                f"{MIDPOINT_TOLERANCE:g} in {MIDPOINT_ITERATIONS} iterations ({'diverges' if contraction >= 1 else 'slow'}); "
                f"rate = {rate:.3g} 1/s (sqrt|k| + gamma at the start)")
    g = oscillator_growth(method, dt, k, gamma)
    if g is None:
        limit = stability_limit(method)
        if dt * rate <= limit:
            return None
        return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate = {dt * rate:.3g} "
                f"> {limit:.3g}, the documented limit (methods()); rate {rate:.3g} 1/s")
    if g <= 1.0 or steps * math.log(g) <= math.log(GROWTH_LIMIT):
        return None
    return (f"{method} at dt = {dt:.3g} s is beyond its stability limit for {label}: dt*rate = {dt * rate:.3g}, "
            f"perturbations grow spuriously about 10^{steps * math.log(g) / math.log(10):.3g}-fold over {steps} "
            f"steps; rate = {rate:.3g} 1/s (sqrt|k| + gamma, k = {k:.3g} 1/s^2, gamma = {gamma:.3g} 1/s at the "
            f"start), x{g:.6g} per step")


def scene_stability_message(method: str, dt: float, steps: int, scene: object, initial: list[object],
                            modes: list[tuple[str, float, float]] | None = None) -> str | None:
    """The first (largest-rate) stability message of `method` at dt [s] over `steps` steps on a scene:
    each rigid body's spin (stability_message, torque-free along the orbit if the scene has no
    element) and each mode of scene_modes (or `modes`, computed once by the caller); None if stable."""
    modes = scene_modes(scene, initial) if modes is None else modes
    messages: list[tuple[float, str]] = []
    free = len(list(getattr(scene, "elements"))) == 0
    for i, (body, state) in enumerate(zip(getattr(scene, "bodies"), initial)):
        if isinstance(body, _core.RigidBody):
            w_B = np.asarray(getattr(state, "w_B"), float)
            text = stability_message(method, dt, steps, np.asarray(body.inertia_com, float), w_B, free)
            if text:
                messages.append((float(np.linalg.norm(w_B)), text.replace("for this spin", f"for the spin of body {i}")))
    for label, k, gamma in modes:
        text = mode_message(method, dt, steps, label, k, gamma)
        if text:
            messages.append((math.sqrt(abs(k)) + gamma, text))
    return max(messages)[1] if messages else None
