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
    "orbit",
    "orbit_rate",
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
