"""The energy and momentum balance of a run in plain numpy, from its records: the oracle of the core's balance
(rigiddyn's simulate/balance.hpp) and of its accuracy check (simulate/accuracy_check.hpp). It never imports rigiddyn.

Per record (Craig, "Rigid Body Dynamics", the work-energy principle T2 - T1 = U12 and the impulse-momentum
principle; Rigid-body notes, section 4.11, f = dp/dt (4.36)):

    r_E = T - T0 - sum_e W_e - sum_b E_b - sum_k W_motor,k  [J]
    r_P = |P - P0 - J|  [kg m/s]
    r_H = |H - H0 - K|  [kg m^2/s]

about W's origin (H = sum p x m v + R I w; a body alone runs as its one-body scene). Each residual comes with its round-off bound (8 eps times the
size of its terms per step, summed) and its scale. A residual is within its allowance when it does not exceed
max(ESTIMATE_FACTOR x the estimate's bound, ESTIMATE_FLOOR x level x scale) + round-off where the global error
estimate is reliable, else level x scale + round-off.

A balance here is a dict of the nine (n,) arrays (``energy``, ``linear_momentum``, ``angular_momentum``, each also
with ``_round_off`` and ``_scale``), its ``verdict`` (a dict of str) and ``about``; a run's result is read through
its attributes (t, v_W, q_WB, ..., as rigiddyn's results name them), its estimate through ``error``.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["DEFAULT_LEVEL", "ESTIMATE_FACTOR", "ESTIMATE_FLOOR", "accuracy_message", "of_scene"]

#: The relative level of a run without a reliable estimate; the factor on a reliable estimate's bound; the least
#: allowance where the estimate is reliable, as a fraction of the level.
DEFAULT_LEVEL = 1e-3
ESTIMATE_FACTOR = 10.0
ESTIMATE_FLOOR = 0.1

_QUANTITIES = (("energy", "J"), ("linear_momentum", "kg m/s"), ("angular_momentum", "kg m^2/s"))

Balance = dict  # the nine arrays, "verdict" and "about"


def _made(arrays: tuple[np.ndarray, ...], verdict: dict[str, str], about: str) -> dict[str, Any]:
    names = ([q for q, _ in _QUANTITIES] + [q + "_round_off" for q, _ in _QUANTITIES]
             + [q + "_scale" for q, _ in _QUANTITIES])
    out: dict[str, Any] = {name: np.asarray(a, dtype=float) for name, a in zip(names, arrays)}
    out["verdict"] = dict(verdict)
    out["about"] = about
    return out


_EPS = float(np.finfo(float).eps)


def _round_off(scale: np.ndarray, steps: np.ndarray) -> np.ndarray:
    """8 eps per step, summed (as the global error estimate's bound): 8 eps |scale| max(steps, 1)."""
    return np.asarray(8.0 * _EPS * np.abs(scale) * np.maximum(steps, 1), dtype=float)


def _steps(t: np.ndarray, dt: float) -> np.ndarray:
    return np.rint((t - t[0]) / dt) if t.size else t


def _running_max(a: np.ndarray) -> np.ndarray:
    return np.maximum.accumulate(a) if a.size else a


def _norms(a: np.ndarray) -> np.ndarray:
    return np.asarray(np.sqrt(np.einsum("...i,...i->...", a, a)), dtype=float)


def _not_applicable(n: int) -> np.ndarray:
    return np.full(n, np.nan)


# ------------------------------------------------------------------ the residuals of a run


def of_scene(result: Any, impulse_W: Any, angular_impulse_W: Any, not_applicable: str, dt: float) -> Balance:
    """The balance of a scene's run (SceneResult): impulse_W, angular_impulse_W (n, 3) the elements' impulses (None
    where the run's path does not integrate them), `not_applicable` the reason the momentum balances do not apply
    ("" when they do). Records that overflowed give non-finite residuals quietly (simulate warns of them)."""
    with np.errstate(all="ignore"):
        return _of_scene(result, impulse_W, angular_impulse_W, not_applicable, dt)


def _of_scene(result: Any, impulse_W: Any, angular_impulse_W: Any, not_applicable: str, dt: float) -> Balance:
    t = np.asarray(result.t)
    n = t.shape[0]
    steps = _steps(t, dt)
    T = np.asarray(result.kinetic_energy)
    E = np.asarray(result.total_energy)
    inputs = (np.asarray(result.work).sum(axis=1) + np.asarray(result.mass_flow_energy).sum(axis=1)
              + np.asarray(result.motor_work).sum(axis=1))
    # r_E = T - T0 - sum W_e - sum E_b - sum W_motor (scene_simulation.hpp: the works hold every element's)
    energy = T - T[:1] - inputs if n else T
    magnitude = (np.abs(np.asarray(result.work)).sum(axis=1) + np.abs(np.asarray(result.mass_flow_energy)).sum(axis=1)
                 + np.abs(np.asarray(result.motor_work)).sum(axis=1))
    energy_scale = abs(E[0]) + T[0] + _running_max(magnitude) if n else T
    energy_size = _running_max(T + np.abs(E - T) + magnitude)  # the terms the records' round-off scales with
    verdict: dict[str, str] = {}
    if not_applicable or impulse_W is None:
        reason = not_applicable or "its path does not integrate the impulses"
        linear = angular = linear_scale = angular_scale = linear_size = angular_size = _not_applicable(n)
        verdict["linear_momentum"] = verdict["angular_momentum"] = "not applicable: " + reason
    else:
        J = np.asarray(impulse_W)
        K = np.asarray(angular_impulse_W)
        P = np.asarray(result.linear_momentum_W)
        H = np.asarray(result.angular_momentum_W)
        m = np.asarray(result.mass)
        p = np.asarray(result.p_W)
        mv = m[..., None] * np.asarray(result.v_W)
        # r_P = P - P0 - J, r_H = H - H0 - K about W's origin (scene_model.hpp)
        linear = _norms(P - P[:1] - J) if n else t
        angular = _norms(H - H[:1] - K) if n else t
        linear_scale = (_norms(mv[0]).sum() + _running_max(_norms(J))) if n else t
        H_C = np.asarray(result.angular_momentum_O_W)
        # |p| |m v| per part, the size of the rounding of p x m v (which stays where p and v are parallel)
        moments = (_norms(p) * _norms(mv)).sum(axis=1) + _norms(H_C).sum(axis=1)  # (n,)
        # the parts' size where they cancel (a gyrostat's body and wheels, H_C ~ 0): 2 T / |w| <= |H| of a turning body
        w_max = _norms(np.asarray(result.w_B)).max(axis=1)
        turning = np.divide(2.0 * T, w_max, out=np.zeros_like(T), where=w_max > 0)
        angular_scale = (moments[0] + _running_max(_norms(K))) if n else t
        linear_size = _running_max(_norms(mv).sum(axis=1) + _norms(J))
        angular_size = _running_max(moments + _norms(K) + turning)
        # the scale is at least the parts' largest momenta so far (a scene at rest at t0 set moving by internal
        # forces keeps its totals 0 while its parts move)
        linear_scale = np.maximum(linear_scale, linear_size) if n else t
        angular_scale = np.maximum(angular_scale, angular_size) if n else t
    return _made((energy, linear, angular, _round_off(energy_size, steps), _round_off(linear_size, steps),
                  _round_off(angular_size, steps), energy_scale, linear_scale, angular_scale),
                 {q: verdict.get(q, "closed") for q, _ in _QUANTITIES}, "W's origin")


# ------------------------------------------------------------------ the warning


def _allowances(balance: Balance, error: Any, level: float, result: Any) -> dict[str, np.ndarray]:
    """What each residual may be at each record: max(ESTIMATE_FACTOR x the estimate's bound of it, ESTIMATE_FLOOR x
    level x its scale) + round-off where the estimate is reliable, else level x its scale + round-off."""
    n = balance["energy"].shape[0]
    fallback = {q: level * balance[q + "_scale"] + balance[q + "_round_off"] for q, _ in _QUANTITIES}
    if error is None:
        return fallback
    reliable = np.asarray(error.reliable, dtype=bool)
    estimated = _estimate_bounds(error, result)
    out = {}
    for q, _ in _QUANTITIES:
        bound = (np.maximum(ESTIMATE_FACTOR * estimated[q], ESTIMATE_FLOOR * level * balance[q + "_scale"])
                 + balance[q + "_round_off"])
        out[q] = np.where(reliable & np.isfinite(bound), bound, fallback[q]) if n else fallback[q]
    return out


def _per_body(a: Any) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    return np.asarray(a[:, None] if a.ndim == 1 else a, dtype=float)


def _estimate_bounds(error: Any, result: Any) -> dict[str, np.ndarray]:
    """The global error estimate's bound of each residual (first order in the state errors):
    energy: the estimate of total_energy's error; linear momentum: sum_b m_b dv_b; angular momentum (about W's
    origin): sum_b (m_b (|v_b| dp_b + |p_b| dv_b) + |H_C,b| dtheta_b + lambda_b dw_b), lambda_b = |H_C,b| / |w_b|
    (I's largest moment for a sphere)."""
    dp, dv = _per_body(error.position), _per_body(error.velocity)
    dth, dw = _per_body(error.attitude), _per_body(error.angular_velocity)
    m = _per_body(result.mass)
    v = np.asarray(result.v_W).reshape(dv.shape + (3,))
    p = np.asarray(result.p_W).reshape(dv.shape + (3,))
    w = np.asarray(result.w_B).reshape(dv.shape + (3,))
    H_C = _norms(np.asarray(result.angular_momentum_O_W))
    norms_w = _norms(w)
    lam = np.divide(H_C, norms_w, out=np.zeros_like(H_C), where=norms_w > 0)
    angular = (m * (_norms(v) * dp + _norms(p) * dv) + H_C * dth + lam * dw).sum(axis=1)
    return {"energy": np.asarray(error.energy, dtype=float), "linear_momentum": (m * dv).sum(axis=1),
            "angular_momentum": angular}


def accuracy_message(balance: Balance, error: Any, level: float, result: Any, method: str, dt: float) -> str:
    """The AccuracyWarning's message for a run, or "" when every balance closes.

    The rule, per quantity q and record i where q applies: the residual |r_q,i| must not exceed
    max(ESTIMATE_FACTOR * (the estimate's bound of r_q,i), ESTIMATE_FLOOR * level * scale_q,i) + round_off_q,i where
    error.reliable[i] (the estimate is then contradicted), else level * scale_q,i + round_off_q,i. The message names the quantity furthest beyond its
    allowance (and the others beyond theirs) with the figure and a suggestion. Sets balance["verdict"].

    Parameters
    ----------
    balance : dict
        The run's residuals (of_scene).
    error : GlobalError or None
        The run's estimate (None: error=False).
    level : float
        The relative level where no reliable estimate exists.
    result : SceneResult
        The run's records.
    method : str
        The method's name (for the message).
    dt : float
        The step [s] (for the message).

    Returns
    -------
    str
        The message, "" when no residual exceeds its allowance.
    """
    with np.errstate(all="ignore"):
        return _accuracy_message(balance, error, level, result, method, dt)


def _accuracy_message(balance: Balance, error: Any, level: float, result: Any, method: str, dt: float) -> str:
    allowance = _allowances(balance, error, level, result)
    reliable = np.zeros(balance["energy"].shape[0], bool) if error is None else np.asarray(error.reliable, dtype=bool)
    findings = []
    for q, unit in _QUANTITIES:
        if balance["verdict"][q].startswith("not applicable"):
            continue
        r = np.abs(balance[q])
        over = np.isfinite(r) & (r > allowance[q])  # a record that overflowed: simulate's RuntimeWarning says so
        if not np.any(over):
            continue
        ratio = np.where(over, r / np.maximum(allowance[q], np.finfo(float).tiny), 0.0)
        i = int(np.nanargmax(ratio))
        scale = float(balance[q + "_scale"][i])
        relative = f" ({r[i] / scale:.3g} of its scale {scale:.3g} {unit})" if scale > 0 else ""
        why = (f"beyond {ESTIMATE_FACTOR:g} x the reliable global error estimate's bound ({allowance[q][i]:.3g} {unit} "
               "with round-off): the estimate is contradicted" if reliable[i] else
               f"beyond the level {level:g} of its scale (no reliable global error estimate there)")
        text = f"the {q.replace('_', ' ')} balance is off by {r[i]:.3g} {unit}{relative} at t = {result.t[i]:.6g} s, {why}"
        balance["verdict"][q] = "open: " + text
        findings.append((float(ratio[i]), text))
    if not findings:
        return ""
    findings.sort(key=lambda f: -f[0])
    return (f"simulate: {findings[0][1]}" + "".join(f"; also {text}" for _, text in findings[1:]) +
            f". The records of this run (method '{method}', dt = {dt:g}) are not accurate: use a smaller dt or another "
            "method (see methods()), or pass accuracy_level=None to silence this check")


