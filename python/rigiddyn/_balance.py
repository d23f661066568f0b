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
    r_H = |H - H0 - K|  [kg m^2/s] about W's origin (H = sum p x m v + R I w, K the angular impulse of the
    elements about W's origin; a body alone runs as its one-body scene).

The motion's error is the balance's only source besides round-off: a residual beyond the global error estimate
(``result.error``) or, without a reliable estimate, beyond a relative level of its scale means that the run is not
accurate, and ``simulate`` then warns with an :class:`AccuracyWarning`.

The core computes the residuals from the run's records and applies that rule (simulate/balance.hpp and
simulate/accuracy_check.hpp, where the equations and the rule are written out); this module holds the Python class
the core hands its arrays to (made on the first read of ``result.balance``) and the warning's class.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from . import _core

__all__ = ["AccuracyWarning", "Balance", "DEFAULT_LEVEL", "ESTIMATE_FACTOR", "ESTIMATE_FLOOR"]

#: The relative residual (of the quantity's scale, see Balance) beyond which a run without a reliable global error
#: estimate warns. A well-resolved run closes its balances to 1e-6 of the scale or better (rk4 at dt |w| = 0.05 on a
#: tumbling body: 2e-9); 1e-3 is three orders above and far below the failures worth a warning (whole percents).
DEFAULT_LEVEL: float = _core._accuracy_rule[0]

#: The factor on the global error estimate of a quantity in the allowance of its residual where the estimate is
#: reliable: a reliable estimate was within 0.5-2x the true error (docs/guide, global error), and a residual combines
#: the error of the state with that of the integrated works or impulses (of the same size): 10 leaves margin for both.
ESTIMATE_FACTOR: float = _core._accuracy_rule[1]

#: The least allowance of a residual where the estimate is reliable, as a fraction of the level (so 1e-4 of the scale
#: by default): the estimate of the total energy's error does not cover the integrated works' and mass-flow energies'
#: own error, which can exceed it by orders (measured: implicit_midpoint on a body losing mass, a residual of 1.1e-5
#: of the scale against an estimate 1000x smaller; rk4 on a rocket near t0, 8e-11 against 100x smaller). A reliable
#: estimate thus lowers the level by at most 10x and raises it where the estimate itself reports a larger error.
ESTIMATE_FLOOR: float = _core._accuracy_rule[2]

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
        The point of the angular momentum: "W's origin".

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
    >>> bool(np.all(np.abs(b.energy) <= b.energy_round_off)), b.verdict["energy"]
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
        {'energy': 0.0, 'linear_momentum': 0.0, 'angular_momentum': 0.0}
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
        angular_momentum: max |residual| 0 kg m^2/s (0 of its scale): closed
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
    """A Balance of the residual arrays the core made for a run (read-only float arrays of one length, in
    _array_names' order), taken as they are: without the checks and copies of its constructor, which guard what a
    user or a pickle passes."""
    balance = Balance.__new__(Balance)
    for name, value in zip(_ARRAY_NAMES, arrays):
        setattr(balance, name, value)
    balance.verdict = verdict
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


_ARRAY_NAMES = ([q for q, _ in _QUANTITIES] + [q + "_round_off" for q, _ in _QUANTITIES]
                + [q + "_scale" for q, _ in _QUANTITIES])


def _array_names() -> list[str]:
    return list(_ARRAY_NAMES)


def _max_abs(a: np.ndarray) -> float:
    if a.size == 0 or np.all(np.isnan(a)):
        return math.nan
    return float(np.nanmax(np.abs(a)))


# the public names are rigiddyn's (rigiddyn.Balance, rigiddyn.AccuracyWarning): pickles and reprs name them there
Balance.__module__ = AccuracyWarning.__module__ = "rigiddyn"
