"""The energy and momentum balance of a run (``result.balance``) and the warning when it does not close.

Every ``simulate`` run carries, besides its records, three residuals per record that are zero for the exact
dynamics (Craig, "Rigid Body Dynamics", the work-energy principle T2 - T1 = U12 and the impulse-momentum
principle; Rigid-body notes, section 4.11, f = dp/dt (4.36)):

energy
    r_E = T - T0 - sum_e W_e - sum_b E_b - sum_k W_motor,k  [J]: the kinetic energy's change less the work of
    every force element (W_e, the ``work`` records: the conservative elements' too), the mass-flow energies and
    the motor works. With the conservative elements' work written as -dV (their potential's change), this is
    E - E0 - W_nc: the total energy's change less the work of the non-conservative forces.
linear_momentum
    r_P = |sum_b m_b v_b - (sum_b m_b v_b)(t0) - J|  [kg m/s], J the linear impulse of the external forces
    (integrated with the motion in C++ as the works are; internal forces add equal and opposite forces and no
    impulse).
angular_momentum
    r_H = |H - H0 - K|  [kg m^2/s], about W's origin for a scene (H = sum p x m v + R I w, K the angular impulse of
    the elements about W's origin) and about the centre of mass for one body (H = R I w, K = 0: gravity and a
    force through the centre of mass have no moment about it).

The motion's error is the balance's only source besides round-off: a residual beyond the global error estimate
(``result.error``) or, without a reliable estimate, beyond a relative level of its scale means that the run is not
accurate, and ``simulate`` then warns with an :class:`AccuracyWarning` (rule in :func:`accuracy_message`).
"""

from __future__ import annotations

import math
import warnings
from typing import Any

import numpy as np

__all__ = ["AccuracyWarning", "Balance", "DEFAULT_LEVEL", "ESTIMATE_FACTOR", "ESTIMATE_FLOOR", "accuracy_message"]

#: The relative residual (of the quantity's scale, see Balance) beyond which a run without a reliable global error
#: estimate warns. A well-resolved run closes its balances to 1e-6 of the scale or better (rk4 at dt |w| = 0.05 on a
#: tumbling body: 2e-9); 1e-3 is three orders above and far below the failures worth a warning (whole percents).
DEFAULT_LEVEL = 1e-3

#: The factor on the global error estimate of a quantity in the allowance of its residual where the estimate is
#: reliable: a reliable estimate was within 0.5-2x the true error (docs/guide, global error), and a residual combines
#: the error of the state with that of the integrated works or impulses (of the same size): 10 leaves margin for both.
ESTIMATE_FACTOR = 10.0

#: The least allowance of a residual where the estimate is reliable, as a fraction of the level (so 1e-4 of the scale
#: by default): the estimate of the total energy's error does not cover the integrated works' and mass-flow energies'
#: own error, which can exceed it by orders (measured: implicit_midpoint on a body losing mass, a residual of 1.1e-5
#: of the scale against an estimate 1000x smaller; rk4 on a rocket near t0, 8e-11 against 100x smaller). A reliable
#: estimate thus lowers the level by at most 10x and raises it where the estimate itself reports a larger error.
ESTIMATE_FLOOR = 0.1

_QUANTITIES = (("energy", "J"), ("linear_momentum", "kg m/s"), ("angular_momentum", "kg m^2/s"))


class AccuracyWarning(UserWarning):
    """A run whose energy or momentum balance does not close: its records are not accurate there.

    ``simulate`` warns once at the end of a run when a residual of ``result.balance`` exceeds what the global error
    estimate allows (``ESTIMATE_FACTOR`` times the estimate plus the round-off bound) at a record where the estimate
    is reliable, or, where there is no reliable estimate (``error=False`` or a verdict that is not "reliable"),
    exceeds ``accuracy_level`` (default ``DEFAULT_LEVEL``) times the quantity's scale plus the round-off bound. The
    message gives the figure and suggests a smaller dt or another method. A run that diverged does not warn again
    (its RuntimeWarning says so); ``accuracy_level=None`` switches the warning off.

    See Also
    --------
    Balance : the residuals the warning reads.
    GlobalError : the estimate it compares them with.

    Examples
    --------
    rk4 at dt |w| = 2 on a body tumbling near its middle axis loses a third of its energy:

    >>> import warnings
    >>> body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    >>> state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     r = rd.simulate(body, state, dt=2.0, steps=40, error=False)
    >>> [w.category.__name__ for w in caught]
    ['AccuracyWarning']
    """

    def __init__(self, *args: object) -> None:  # its signature for inspect (a built-in base has none)
        super().__init__(*args)


class Balance:
    """The energy and momentum balance of a run: ``result.balance`` of ``simulate``.

    Per record (n records), each residual is zero for the exact dynamics; its size measures the run's error (the
    definitions are in the guide, "The energy and momentum balance of every run"). A quantity whose balance does not apply to the run (a pinned
    or planar body, whose constraint reaction's impulse is not integrated; a mass flow; a turning frame; loads on
    one body, whose impulse is not integrated on that path) has NaN residuals and a verdict saying why.

    Parameters
    ----------
    energy : array_like, shape (n,)
        r_E, the energy residual [J] (signed: > 0 when the run gained energy).
    linear_momentum, angular_momentum : array_like, shape (n,)
        |r_P| [kg m/s] and |r_H| [kg m^2/s], the norms of the momentum residuals (NaN where not applicable).
    energy_round_off, linear_momentum_round_off, angular_momentum_round_off : array_like, shape (n,)
        The round-off each residual can hold: 8 eps times its scale per step, summed over the steps so far.
    energy_scale, linear_momentum_scale, angular_momentum_scale : array_like, shape (n,)
        The size each residual is relative to: |E0| + T0 (or |P0|-like sum of m |v|, or sum of |p x m v| + |H_C|
        at t0) plus the largest input so far (works, impulses).
    verdict : dict of str to str
        Per quantity: "closed" (within its allowance at every record), "open: ..." (the figure, as in the warning)
        or "not applicable: ...".
    about : str
        The point of the angular momentum: "W's origin" (a scene) or "the centre of mass" (one body).

    Attributes
    ----------
    energy, linear_momentum, angular_momentum, energy_round_off, linear_momentum_round_off,
    angular_momentum_round_off, energy_scale, linear_momentum_scale, angular_momentum_scale : ndarray, shape (n,)
        As the parameters (read-only float arrays).
    verdict : dict of str to str
        As the parameter.
    about : str
        As the parameter.

    See Also
    --------
    simulate : makes it on every run.
    AccuracyWarning : the warning when a residual is too large.
    GlobalError : the global error estimate of the same run.

    Examples
    --------
    The exact method keeps a torque-free body's balances at round-off:

    >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 1.0, 0.1]), dt=0.1,
    ...                 steps=100, method="exact", error=False)
    >>> b = r.balance
    >>> bool(np.all(np.abs(b.energy) <= b.energy_round_off)), b.verdict["angular_momentum"]
    (True, 'closed')
    """

    def __init__(self, energy: Any, linear_momentum: Any, angular_momentum: Any, energy_round_off: Any,
                 linear_momentum_round_off: Any, angular_momentum_round_off: Any, energy_scale: Any,
                 linear_momentum_scale: Any, angular_momentum_scale: Any, verdict: dict[str, str],
                 about: str) -> None:
        arrays = {"energy": energy, "linear_momentum": linear_momentum, "angular_momentum": angular_momentum,
                  "energy_round_off": energy_round_off, "linear_momentum_round_off": linear_momentum_round_off,
                  "angular_momentum_round_off": angular_momentum_round_off, "energy_scale": energy_scale,
                  "linear_momentum_scale": linear_momentum_scale, "angular_momentum_scale": angular_momentum_scale}
        n = None
        for name, value in arrays.items():
            a = _real_array(value, name, n)
            n = a.shape[0]
            setattr(self, name, a)
        quantities = [q for q, _ in _QUANTITIES]
        if not isinstance(verdict, dict) or sorted(verdict) != sorted(quantities) or \
                not all(isinstance(v, str) for v in verdict.values()):
            raise TypeError(f"verdict: expected a dict of str with the keys {quantities}, got {verdict!r}")
        if not isinstance(about, str):
            raise TypeError(f"about: expected a str, got {about!r}")
        self.verdict = dict(verdict)
        self.about = about

    energy: np.ndarray
    linear_momentum: np.ndarray
    angular_momentum: np.ndarray
    energy_round_off: np.ndarray
    linear_momentum_round_off: np.ndarray
    angular_momentum_round_off: np.ndarray
    energy_scale: np.ndarray
    linear_momentum_scale: np.ndarray
    angular_momentum_scale: np.ndarray

    def max(self) -> dict[str, float]:
        """The largest |residual| of each quantity over the records (NaN: not applicable or no record).

        Returns
        -------
        dict of str to float
            "energy" [J], "linear_momentum" [kg m/s], "angular_momentum" [kg m^2/s].

        Examples
        --------
        >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), 0.1, 10, error=False)
        >>> r.balance.max()
        {'energy': 0.0, 'linear_momentum': 0.0, 'angular_momentum': nan}
        """
        return {q: _max_abs(getattr(self, q)) for q, _ in _QUANTITIES}

    def summary(self) -> str:
        """One line per quantity: its largest |residual|, relative to its scale, and its verdict.

        Returns
        -------
        str
            E.g. "energy: max |residual| 1.2e-14 J (4.1e-15 of its scale): closed".

        Examples
        --------
        >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), 0.1, 10, error=False)
        >>> print(r.balance.summary())
        energy: max |residual| 0 J (0 of its scale): closed
        linear_momentum: max |residual| 0 kg m/s (0 of its scale): closed
        angular_momentum: not applicable: a Particle has no attitude
        """
        lines = []
        for q, unit in _QUANTITIES:
            if self.verdict[q].startswith("not applicable"):
                lines.append(f"{q}: {self.verdict[q]}")
                continue
            worst = _max_abs(getattr(self, q))
            scale = _max_abs(getattr(self, q + "_scale"))
            relative = worst / scale if scale > 0 else (0.0 if worst == 0 else math.inf)
            lines.append(f"{q}: max |residual| {worst:.3g} {unit} ({relative:.2g} of its scale): {self.verdict[q]}")
        return "\n".join(lines)

    def __repr__(self) -> str:
        parts = []
        for q, unit in _QUANTITIES:
            v = self.verdict[q]
            parts.append(f"{q}=not applicable" if v.startswith("not applicable")
                         else f"{q}={_max_abs(getattr(self, q)):.3g} {unit} {v.split(':')[0]}")
        return f"Balance(records={self.energy.shape[0]}, {', '.join(parts)})"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Balance):
            return NotImplemented
        return self.verdict == other.verdict and self.about == other.about and all(
            np.array_equal(getattr(self, name), getattr(other, name), equal_nan=True) for name in _array_names())

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self) -> tuple[Any, tuple[Any, ...]]:
        return (Balance, tuple(getattr(self, name) for name in _array_names()) + (self.verdict, self.about))


def _made(arrays: tuple[np.ndarray, ...], verdict: dict[str, str], about: str) -> Balance:
    """A Balance of the residual arrays a run made (float arrays of one length, in _array_names' order): without the
    checks of its constructor, which guard what a user or a pickle passes."""
    balance = Balance.__new__(Balance)
    for name, value in zip(_array_names(), arrays):
        a = np.array(value, dtype=float)
        a.flags.writeable = False
        setattr(balance, name, a)
    balance.verdict = dict(verdict)
    balance.about = about
    return balance


def _real_array(value: Any, name: str, n: int | None) -> np.ndarray:
    """A read-only float copy of `value`, shape (n,) (any n when n is None); TypeError or ValueError naming `name`."""
    shape = f"({'n' if n is None else n},)"
    try:
        a = np.array(value)
    except MemoryError as error:
        raise MemoryError(f"{name}: expected an array that fits in memory, got one too large to copy") from error
    except (TypeError, ValueError) as error:
        raise TypeError(f"{name}: expected an array_like of real numbers, shape {shape}, got {value!r}") from error
    if a.dtype.kind not in "iuf":
        raise TypeError(f"{name}: expected an array_like of real numbers, shape {shape}, got {value!r}")
    if a.ndim != 1 or (n is not None and a.shape[0] != n):
        raise ValueError(f"{name}: expected shape {shape}, got shape {a.shape}")
    a = a.astype(float)
    a.flags.writeable = False
    return a


def _array_names() -> list[str]:
    return [q for q, _ in _QUANTITIES] + [q + "_round_off" for q, _ in _QUANTITIES] + [q + "_scale" for q, _ in _QUANTITIES]


def _max_abs(a: np.ndarray) -> float:
    if a.size == 0 or np.all(np.isnan(a)):
        return math.nan
    return float(np.nanmax(np.abs(a)))


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


def of_body(result: Any, mass: float, inertia_com: Any, gravity_W: Any, loads: bool, kind: str, dt: float) -> Balance:
    """The Balance of a one-body run (SimulationResult) of a body of `mass` [kg], inertia_com (3, 3) [kg m^2] (None
    for a particle), under uniform gravity_W [m/s^2] and, when `loads`, applied loads; `kind` the body's class.
    Records that overflowed give non-finite residuals quietly (simulate warns of them)."""
    with np.errstate(all="ignore"):
        return _of_body(result, mass, inertia_com, gravity_W, loads, kind, dt)


def _of_body(result: Any, mass: float, inertia_com: Any, gravity_W: Any, loads: bool, kind: str, dt: float) -> Balance:
    t = np.asarray(result.t)
    n = t.shape[0]
    steps = _steps(t, dt)
    T = np.asarray(result.kinetic_energy)
    W = np.asarray(result.work)
    E = np.asarray(result.total_energy)
    # r_E = T - T0 - W: the work records hold the loads' and gravity's (simulate.hpp)
    energy = T - T[:1] - W if n else T
    energy_scale = (abs(E[0]) + T[0] + _running_max(np.abs(W))) if n else T
    energy_size = _running_max(T + np.abs(E - T) + np.abs(W))  # the terms the records' round-off scales with
    verdict: dict[str, str] = {}
    v = np.asarray(result.v_W)
    g = np.asarray(gravity_W, dtype=float)
    if loads:
        linear = linear_scale = linear_size = _not_applicable(n)
        verdict["linear_momentum"] = "not applicable: the impulse of the loads is not integrated on a body's own path"
    else:
        # r_P = m v - m v0 - m g (t - t0): uniform gravity's impulse is exact
        P = mass * v
        linear = _norms(P - P[:1] - mass * np.outer(t - t[:1], g)) if n else t
        linear_scale = mass * (_norms(v[:1]) + _norms(g) * np.abs(t - t[:1])) if n else t
        linear_size = _running_max(mass * (_norms(v) + _norms(g) * np.abs(t - t[:1]))) if n else t
    if inertia_com is None:
        angular = angular_scale = angular_size = _not_applicable(n)
        verdict["angular_momentum"] = f"not applicable: a {kind} has no attitude"
    elif loads:
        angular = angular_scale = angular_size = _not_applicable(n)
        verdict["angular_momentum"] = "not applicable: the angular impulse of the loads is not integrated on a body's own path"
    else:
        # r_H = R I w - (R I w)(t0) about the centre of mass: gravity has no moment about it
        H = _world_momentum(np.asarray(result.q_WB), np.asarray(result.w_B), np.asarray(inertia_com, dtype=float),
                            bool(getattr(result, "scalar_first", False)))
        angular = _norms(H - H[:1]) if n else t
        angular_scale = np.full(n, _norms(H[:1])[0]) if n else t
        angular_size = _running_max(_norms(H))
    return _made((energy, linear, angular, _round_off(energy_size, steps), _round_off(linear_size, steps),
                  _round_off(angular_size, steps), energy_scale, linear_scale, angular_scale),
                 {q: verdict.get(q, "closed") for q, _ in _QUANTITIES}, "the centre of mass")


def _world_momentum(q: np.ndarray, w_B: np.ndarray, inertia: np.ndarray, scalar_first: bool) -> np.ndarray:
    """R_WB I w_B per record, q (n, 4) as recorded: h + 2 s (u x h) + 2 u x (u x h) for h = I w_B and the unit
    quaternion (u, s) (Rodrigues' formula in quaternion form)."""
    q = q / np.sqrt(np.einsum("ni,ni->n", q, q))[:, None]
    u, s = (q[:, 1:], q[:, :1]) if scalar_first else (q[:, :3], q[:, 3:])
    h = np.einsum("jk,nk->nj", inertia, w_B)  # no BLAS threads for (n, 3) rows
    t = 2.0 * _cross(u, h)
    return np.asarray(h + s * t + _cross(u, t), dtype=float)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """a x b row by row, (n, 3) (numpy's cross costs ~20 us of checks on short arrays)."""
    return np.column_stack((a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]))


def of_scene(result: Any, impulse_W: Any, angular_impulse_W: Any, not_applicable: str, dt: float) -> Balance:
    """The Balance of a scene's run (SceneResult): impulse_W, angular_impulse_W (n, 3) the elements' impulses (None
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
        moments = _norms(np.cross(p, mv)).sum(axis=1) + _norms(H_C).sum(axis=1)  # (n,)
        # the parts' size where they cancel (a gyrostat's body and wheels, H_C ~ 0): 2 T / |w| <= |H| of a turning body
        w_max = _norms(np.asarray(result.w_B)).max(axis=1)
        turning = np.divide(2.0 * T, w_max, out=np.zeros_like(T), where=w_max > 0)
        angular_scale = (moments[0] + _running_max(_norms(K))) if n else t
        linear_size = _running_max(_norms(mv).sum(axis=1) + _norms(J))
        angular_size = _running_max(moments + _norms(K) + turning)
    return _made((energy, linear, angular, _round_off(energy_size, steps), _round_off(linear_size, steps),
                  _round_off(angular_size, steps), energy_scale, linear_scale, angular_scale),
                 {q: verdict.get(q, "closed") for q, _ in _QUANTITIES}, "W's origin")


# ------------------------------------------------------------------ the warning


def _allowances(balance: Balance, error: Any, level: float, result: Any, inertia_bound: Any) -> dict[str, np.ndarray]:
    """What each residual may be at each record: max(ESTIMATE_FACTOR x the estimate's bound of it, ESTIMATE_FLOOR x
    level x its scale) + round-off where the estimate is reliable, else level x its scale + round-off."""
    n = balance.energy.shape[0]
    fallback = {q: level * getattr(balance, q + "_scale") + getattr(balance, q + "_round_off") for q, _ in _QUANTITIES}
    if error is None:
        return fallback
    reliable = np.asarray(error.reliable, dtype=bool)
    estimated = _estimate_bounds(error, result, inertia_bound)
    out = {}
    for q, _ in _QUANTITIES:
        bound = (np.maximum(ESTIMATE_FACTOR * estimated[q], ESTIMATE_FLOOR * level * getattr(balance, q + "_scale"))
                 + getattr(balance, q + "_round_off"))
        out[q] = np.where(reliable & np.isfinite(bound), bound, fallback[q]) if n else fallback[q]
    return out


def _per_body(a: Any) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    return np.asarray(a[:, None] if a.ndim == 1 else a, dtype=float)


def _estimate_bounds(error: Any, result: Any, inertia_bound: Any) -> dict[str, np.ndarray]:
    """The global error estimate's bound of each residual (first order in the state errors):
    energy: the estimate of total_energy's error; linear momentum: sum_b m_b dv_b; angular momentum:
    sum_b (m_b (|v_b| dp_b + |p_b| dv_b) + |H_C,b| dtheta_b + lambda_b dw_b), lambda_b I's largest moment (for a
    scene |H_C,b| / |w_b|, exact for a sphere; a scene's H is about W's origin, one body's about its centre)."""
    dp, dv = _per_body(error.position), _per_body(error.velocity)
    dth, dw = _per_body(error.attitude), _per_body(error.angular_velocity)
    m = _per_body(result.mass if hasattr(result, "mass") else np.full(dv.shape[0], inertia_bound[0]))  # one body: its mass
    v = np.asarray(result.v_W).reshape(dv.shape + (3,))
    p = np.asarray(result.p_W).reshape(dv.shape + (3,))
    w = np.asarray(result.w_B).reshape(dv.shape + (3,))
    if hasattr(result, "angular_momentum_O_W"):  # a scene: about W's origin
        H_C = _norms(np.asarray(result.angular_momentum_O_W))
        norms_w = _norms(w)
        lam = np.divide(H_C, norms_w, out=np.zeros_like(H_C), where=norms_w > 0)
        angular = (m * (_norms(v) * dp + _norms(p) * dv) + H_C * dth + lam * dw).sum(axis=1)
    else:  # one body, about its centre of mass
        H_C = np.asarray(result.angular_momentum_norm)[:, None]
        angular = (H_C * dth + inertia_bound[1] * dw).sum(axis=1)
    return {"energy": np.asarray(error.energy, dtype=float), "linear_momentum": (m * dv).sum(axis=1),
            "angular_momentum": angular}


def accuracy_message(balance: Balance, error: Any, level: float, result: Any, method: str, dt: float,
                     inertia_bound: Any = None) -> str:
    """The AccuracyWarning's message for a run, or "" when every balance closes.

    The rule, per quantity q and record i where q applies: the residual |r_q,i| must not exceed
    max(ESTIMATE_FACTOR * (the estimate's bound of r_q,i), ESTIMATE_FLOOR * level * scale_q,i) + round_off_q,i where
    error.reliable[i] (the estimate is then contradicted), else level * scale_q,i + round_off_q,i. The message names the quantity furthest beyond its
    allowance (and the others beyond theirs) with the figure and a suggestion. Sets balance.verdict.

    Parameters
    ----------
    balance : Balance
        The run's residuals.
    error : GlobalError or None
        The run's estimate (None: error=False).
    level : float
        The relative level where no reliable estimate exists.
    result : SimulationResult or SceneResult
        The run's records.
    method : str
        The method's name (for the message).
    dt : float
        The step [s] (for the message).
    inertia_bound : tuple of float, optional
        (mass [kg], a bound of the largest principal moment [kg m^2]) of a one-body run.

    Returns
    -------
    str
        The message, "" when no residual exceeds its allowance.

    Examples
    --------
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), 0.1, 10, error=False)
    >>> from rigiddyn._balance import accuracy_message
    >>> accuracy_message(r.balance, None, 1e-3, r, "rk4", 0.1)
    ''
    """
    allowance = _allowances(balance, error, level, result, inertia_bound)
    reliable = np.zeros(balance.energy.shape[0], bool) if error is None else np.asarray(error.reliable, dtype=bool)
    findings = []
    for q, unit in _QUANTITIES:
        if balance.verdict[q].startswith("not applicable"):
            continue
        r = np.abs(getattr(balance, q))
        over = np.isfinite(r) & (r > allowance[q])  # a record that overflowed: simulate's RuntimeWarning says so
        if not np.any(over):
            continue
        ratio = np.where(over, r / np.maximum(allowance[q], np.finfo(float).tiny), 0.0)
        i = int(np.nanargmax(ratio))
        scale = float(getattr(balance, q + "_scale")[i])
        relative = f" ({r[i] / scale:.3g} of its scale {scale:.3g} {unit})" if scale > 0 else ""
        why = (f"beyond {ESTIMATE_FACTOR:g} x the reliable global error estimate's bound ({allowance[q][i]:.3g} {unit} "
               "with round-off): the estimate is contradicted" if reliable[i] else
               f"beyond the level {level:g} of its scale (no reliable global error estimate there)")
        text = f"the {q.replace('_', ' ')} balance is off by {r[i]:.3g} {unit}{relative} at t = {result.t[i]:.6g} s, {why}"
        balance.verdict[q] = "open: " + text
        findings.append((float(ratio[i]), text))
    if not findings:
        return ""
    findings.sort(key=lambda f: -f[0])
    return (f"simulate: {findings[0][1]}" + "".join(f"; also {text}" for _, text in findings[1:]) +
            f". The records of this run (method '{method}', dt = {dt:g}) are not accurate: use a smaller dt or another "
            "method (see methods()), or pass accuracy_level=None to silence this check")


def check_run(result: Any, balance: Balance, level: Any, method: str, dt: float, inertia_bound: Any = None) -> Balance:
    """simulate's end-of-run check: sets the verdicts of `balance` and warns once with an AccuracyWarning when a
    balance does not close (accuracy_message); level None skips the warning (the verdicts still follow
    DEFAULT_LEVEL), and so does a run that diverged (simulate has warned with a RuntimeWarning already)."""
    with np.errstate(all="ignore"):
        message = accuracy_message(balance, result.error, DEFAULT_LEVEL if level is None else level, result, method,
                                   dt, inertia_bound)
    if message and level is not None and not result.diverged:
        warnings.warn(message, AccuracyWarning, stacklevel=2)
    return balance


# the public names are rigiddyn's (rigiddyn.Balance, rigiddyn.AccuracyWarning): pickles and reprs name them there
Balance.__module__ = AccuracyWarning.__module__ = "rigiddyn"
