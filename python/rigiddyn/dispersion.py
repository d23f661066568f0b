"""Monte Carlo dispersions of a rigid body's (or a scene's bodies') initial state, mass properties and loads.

The run is the function `rigiddyn.monte_carlo` (this module, rigiddyn.dispersion, holds it, the dispersions
Normal, Uniform, UniformRotation, RotationNormal, InertiaDispersion, LoadDispersion and the result,
MonteCarloResult). `monte_carlo` draws N samples of the dispersed inputs, runs them as one `rigiddyn.simulate_batch`
(on this machine's threads, or on a Dask cluster through `rigiddyn.distributed` when `client=` is
given), and returns a `MonteCarloResult`: the stacked records, the sampled inputs (to correlate inputs
with outcomes), and statistics and percentiles of any recorded quantity at every record or at a time.

Reproducibility: sample i draws from its own generator,
``numpy.random.default_rng(numpy.random.SeedSequence(seed).spawn(n)[i])``, which depends only on
(seed, i). Serial, threaded and distributed runs therefore agree, and a run of N samples is the prefix of
a run of N' > N samples with the same seed. Within a sample the dispersed inputs are drawn in the fixed
order DRAW_ORDER (whatever the order of the `dispersions` dict).

Dispersion keys (units SI, frames as docs/conventions.md):
  "p_W"     Normal / Uniform: centre of mass position in W (3,) [m]
  "q_WB"    UniformRotation (Haar on SO(3)) or RotationNormal (small rotation about the nominal attitude)
  "v_W"     Normal / Uniform: centre of mass velocity in W (3,) [m/s]
  "w_B"     Normal / Uniform: angular velocity of B in W, expressed in B (3,) [rad/s]
  "mass"    Normal / Uniform: mass [kg] (> 0; invalid draws redrawn, see below)
  "inertia" InertiaDispersion: rotational inertia about the centre of mass in B (3, 3) [kg m^2]
  "gravity" Normal / Uniform: uniform gravity in W (3,) [m/s^2]
  "loads"   LoadDispersion: one constant load per sample (force through the centre of mass [N], torque [N m])
            added to the nominal `loads` schedule
A scene's bodies are dispersed under "<body name>.<field>" (a RigidBody's p_W, q_WB, v_W, w_B, mass, inertia; a
Particle's p_W, v_W, mass; a PivotedBody's q_WB, w_B; a PivotedPlanarBody's "theta" [rad] and "omega" [rad/s],
Normal / Uniform; a Gyrostat's p_W, q_WB, v_W, w_B, its wheel speeds kept; a tree link's joint state, below), drawn
body after body; its loads and gravity are its elements.

A link of a kinematic tree (a TreeLink, Scene.add_tree) is dispersed in its joint's coordinates, as its JointState:
  "<link>.q"  a revolute or prismatic joint's angle [rad] or offset [m] (1,): Normal / Uniform; a spherical joint's
              unit quaternion q_JL (4,) or a free joint's (p_JL, q_JL) (7,): UniformRotation or RotationNormal of
              its attitude (the rotation vector in the link frame L; a free joint's position kept)
  "<link>.v"  the joint's velocities (nv_i,) [rad/s, m/s; a ball's w_L, a free joint's (w_L, v_L)]: Normal / Uniform
A fixed joint has no key; the tree's mass properties are not dispersed.

Before any draw, the memory the run needs (each sample's records and what drawing it holds) is estimated
and a run that would not fit in the memory available is refused, naming n.

Invalid draws (a mass <= 0; an inertia with a principal moment <= 0 or a broken triangle inequality) are
REJECTED AND REDRAWN from the same sample's generator (still a function of (seed, i)), at most
`max_redraws` times (InertiaDispersion's; 100 for a mass), then ValueError naming the sample. The
dispersion is then a distribution truncated to valid values: every redraw is counted
(MonteCarloResult.redraws) and reported in one DispersionWarning.
"""

from __future__ import annotations

import importlib
import itertools
import math
import numbers
import sys
import warnings
from dataclasses import dataclass
from typing import Any, Callable, Mapping, Sequence, Union, cast

import numpy as np

from . import _core
from ._controlled_samples import controller_seeds, run_samples
from ._memory import available_bytes, format_bytes

STATE_KEYS = ("p_W", "q_WB", "v_W", "w_B")
# the order in which one sample's generator serves the dispersed inputs
DRAW_ORDER = ("p_W", "q_WB", "v_W", "w_B", "mass", "inertia", "gravity", "loads")
# the per-record arrays of a BatchSceneResult, each (N, n_records, ...) (per body: (N, n_records, bodies, ...))
SCENE_RECORD_FIELDS = ("t", "p_W", "q_WB", "v_W", "w_B", "mass", "kinetic_energy", "potential_energy",
                       "total_energy", "linear_momentum_W", "angular_momentum_W", "angular_momentum_O_W",
                       "pivot_reaction_W", "power", "work", "joint_q", "joint_v")
# the per-record arrays of one body's records (BodyRecords), each (N, n_records, ...): a body's Monte Carlo reads its
# per-body fields there
BODY_RECORD_FIELDS = ("p_W", "q_WB", "v_W", "w_B", "mass", "angular_momentum_O_W", "pivot_reaction_W",
                      "angular_momentum_norm", "quaternion_norm_error")
# the per-record arrays of a batch's GlobalError, each (N, n_records, ...), fields "error.<name>" of a MonteCarloResult
ERROR_FIELDS = ("attitude", "angular_velocity", "position", "velocity", "energy", "angular_momentum")
STANDARD_GRAVITY_W = (0.0, 0.0, -9.81)  # [m/s^2] in W, what gravity=True means (as simulate)
_KEYS_SHOWN = 40  # dispersible keys an error about an unknown key lists
# the memory estimate that refuses a run before any draw (_check_memory): float64 values per record of a
# body's batch (as simulate_batch's own check), and of a scene's (constant, per body, per element term);
# the frame terms a scene's frame adds at most; memory per sample while drawing (its SeedSequence,
# generator, drawn values and bodies) and per body state of a scene's sample [bytes]: measured at 1.2 kB a
# sample with four keys dispersed (an inertia among them) and 0.3 kB a particle's state, rounded up
_SCENE_RECORD_DOUBLES = (10, 20, 2)
_FRAME_TERMS = 4
# the error estimate's values per record beyond its coarse runs: 7 float64 and a verdict (a 32-byte std::string, then
# a reference and a bool in Python), at most 16 float64s' worth (a scene's 4 more per extra body are within what its
# coarse runs are counted for: 20 values per body, in at least a quarter of the records each)
_ERROR_DOUBLES = 16
_SAMPLE_BYTES = 2048
_STATE_BYTES = 512


# a recorded field's name, or a function of the BatchSceneResult returning (N, n_records, ...)
Quantity = Union[str, Callable[[Any], Any]]


class DispersionWarning(UserWarning):
    """Some draws were invalid (mass <= 0, an unrealizable inertia) and were redrawn: the dispersion
    sampled is the stated one truncated to valid values."""

    def __init__(self, *args: object) -> None:  # its signature for inspect (a built-in base has none)
        super().__init__(*args)


def _float_array(value: Any, name: str) -> np.ndarray:
    """`value` as a finite float array, TypeError/ValueError naming `name` otherwise."""
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected a number or an array of numbers, got {value!r}") from None
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name}: expected finite values, got {value!r}")
    return array


def _fits(array: np.ndarray, shape: tuple[int, ...], name: str, key: str) -> None:
    """ValueError naming `name` unless `array` broadcasts to the shape of dispersion `key`."""
    if not _broadcasts(array.shape, shape) or np.broadcast_shapes(array.shape, shape) != shape:
        raise ValueError(f"dispersions[{key!r}].{name}: expected a shape that broadcasts to {shape}, got {array.shape}")


def _broadcasts(a: tuple[int, ...], b: tuple[int, ...]) -> bool:
    try:
        np.broadcast_shapes(a, b)
    except ValueError:
        return False
    return True


class Dispersion:
    """Base of the dispersions: `draw(rng, nominal)` returns one sample's value of its key."""

    keys: tuple[str, ...] = ()

    def bind(self, key: str, nominal: Any) -> None:
        """Checks that this dispersion can disperse `key` (a field, or "<body>.<field>" in a scene) with this
        nominal value, before any draw."""
        if _field(key) not in self.keys:
            raise TypeError(f"dispersions[{key!r}]: expected {_classes_for(key)}, got {type(self).__name__}")
        if _field(key) == "q":
            _check_joint_q(self, key, np.shape(nominal))

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        raise NotImplementedError


class Normal(Dispersion):
    """Independent normal draws per component: value = mean + std * z, z ~ N(0, 1).

    mean: None (the nominal value of the dispersed key: the state's field, the body's mass, the nominal
      gravity; zero for a load) or a float / array broadcasting to the key's shape, in the key's unit.
    std: standard deviation >= 0 per component, same unit and broadcasting (0 gives the mean exactly).
    """

    keys = ("p_W", "v_W", "w_B", "theta", "omega", "q", "v", "mass", "gravity", "force", "torque")

    def __init__(self, mean: Any = None, std: Any = None):
        if std is None:
            raise TypeError("std: expected a standard deviation >= 0 (float or array), got None")
        self.mean = None if mean is None else _float_array(mean, "mean")
        self.std = _float_array(std, "std")
        if np.any(self.std < 0):
            raise ValueError(f"std: expected a standard deviation >= 0, got {std!r}")

    def bind(self, key: str, nominal: Any) -> None:
        super().bind(key, nominal)
        shape = np.shape(nominal)
        _fits(self.std, shape, "std", key)
        if self.mean is not None:
            _fits(self.mean, shape, "mean", key)

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        mean = np.asarray(nominal, float) if self.mean is None else self.mean
        return mean + self.std * rng.standard_normal(np.shape(nominal))  # shapes checked by bind

    def __repr__(self) -> str:
        return f"Normal(mean={'nominal' if self.mean is None else self.mean.tolist()}, std={self.std.tolist()})"


class Uniform(Dispersion):
    """Independent uniform draws per component on [low, high): value = low + (high - low) * u, u ~ U[0, 1).

    low, high: floats or arrays broadcasting to the key's shape, in the key's unit, low <= high, high - low finite.
    A value that the rounding of that sum takes to high itself (u = 1 - 2**-53 on [1, 2) gives 2.0) is drawn as the
    largest double below high; where low == high every draw is low.
    """

    keys = Normal.keys

    def __init__(self, low: Any, high: Any):
        self.low = _float_array(low, "low")
        self.high = _float_array(high, "high")
        if not _broadcasts(self.low.shape, self.high.shape) or np.any(self.low > self.high):
            raise ValueError(f"high: expected high >= low (same shape), got low={low!r}, high={high!r}")
        with np.errstate(over="ignore"):
            if not np.all(np.isfinite(self.high - self.low)):
                raise ValueError(f"high: expected high - low finite (a width that overflows draws inf), "
                                 f"got low={low!r}, high={high!r}")

    def bind(self, key: str, nominal: Any) -> None:
        super().bind(key, nominal)
        _fits(self.low, np.shape(nominal), "low", key)
        _fits(self.high, np.shape(nominal), "high", key)

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        value = self.low + (self.high - self.low) * rng.random(np.shape(nominal))  # shapes checked by bind
        below_high = np.where(self.low < self.high, np.nextafter(self.high, self.low), self.low)
        return np.where(value < self.high, value, below_high)  # [low, high) after the sum's rounding

    def __repr__(self) -> str:
        return f"Uniform(low={self.low.tolist()}, high={self.high.tolist()})"


def _quat_from_rotvec(phi: np.ndarray) -> np.ndarray:
    """Unit quaternion (x, y, z, w) of the rotation vector phi (3,) [rad]: (sin(|phi|/2) phi/|phi|, cos(|phi|/2))."""
    angle = math.sqrt(float(phi @ phi))
    # sin(a/2)/a -> 1/2 as a -> 0 (series below 1e-4: error a^4/3840 < eps)
    half_sinc = 0.5 - angle * angle / 48.0 if angle < 1e-4 else math.sin(0.5 * angle) / angle
    return np.array([*(half_sinc * phi), math.cos(0.5 * angle)])


def _quat_multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product a ⊗ b of (x, y, z, w) quaternions (docs/conventions.md)."""
    ax, ay, az, aw = (float(c) for c in a)
    bx, by, bz, bw = (float(c) for c in b)
    return np.array([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz])


class UniformRotation(Dispersion):
    """Attitude q_WB uniform on SO(3) (the Haar measure), independent of the nominal attitude: a 4-D
    standard normal vector normalised to unit length (Shoemake 1992), returned as (x, y, z, w). On a tree
    link's "q": its spherical joint's q_JL, or the attitude of its free joint's (p_JL, q_JL), p_JL kept."""

    keys = ("q_WB", "q")

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        g = rng.standard_normal(4)
        norm = math.sqrt(float(g @ g))
        while norm < 1e-100:  # probability < 1e-400: the direction of g is uniform on S^3
            g = rng.standard_normal(4)
            norm = math.sqrt(float(g @ g))
        return _with_attitude(nominal, g / norm)

    def __repr__(self) -> str:
        return "UniformRotation()"


class RotationNormal(Dispersion):
    """Attitude q_WB = q_WB,nominal ⊗ exp(phi): a small rotation about the nominal attitude, its rotation
    vector phi (3,) [rad] expressed in B with independent normal components of standard deviation `std`
    [rad] (a float or (3,), >= 0). On a tree link's "q": q_JL ⊗ exp(phi), phi in the link frame L, of its
    spherical joint's q_JL or of its free joint's (p_JL, q_JL), p_JL kept."""

    keys = ("q_WB", "q")

    def __init__(self, std: Any):
        self.std = _float_array(std, "std")
        if np.any(self.std < 0) or not _broadcasts(self.std.shape, (3,)) or self.std.ndim > 1:
            raise ValueError(f"std: expected a standard deviation >= 0 [rad], a float or (3,), got {std!r}")

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        phi_B = np.broadcast_to(self.std, (3,)) * rng.standard_normal(3)
        q_nominal = np.asarray(nominal, float)[-4:]  # a free joint's (p_JL, q_JL): its attitude
        return _with_attitude(nominal, _quat_multiply(q_nominal, _quat_from_rotvec(phi_B)))

    def __repr__(self) -> str:
        return f"RotationNormal(std={self.std.tolist()})"


def _with_attitude(nominal: Any, q: np.ndarray) -> np.ndarray:
    """`nominal` with its attitude replaced by q (x, y, z, w): (p_JL, q) for a free joint's coordinates (7,), q itself
    for an attitude."""
    return np.concatenate([np.asarray(nominal, float)[:3], q]) if np.shape(nominal) == (7,) else q


def _check_joint_q(dispersion: Dispersion, key: str, shape: tuple[int, ...]) -> None:
    """A joint's q (shape `shape`) is dispersed by Normal / Uniform when it is one coordinate (a revolute or
    prismatic joint), by a rotation when it holds a quaternion (a spherical joint's (4,), a free joint's (7,))."""
    scalar = shape == (1,)
    if isinstance(dispersion, (UniformRotation, RotationNormal)) == scalar:
        joint = "revolute or prismatic" if scalar else "spherical" if shape == (4,) else "free"
        kind = f"a {joint} joint's q {shape}"
        expected = "Normal or Uniform" if scalar else "UniformRotation or RotationNormal"
        raise TypeError(f"dispersions[{key!r}]: expected {expected} for {kind}, got {type(dispersion).__name__}")


def _rotation_matrix(phi: np.ndarray) -> np.ndarray:
    """R = exp(hat(phi)) (3, 3) by Rodrigues' formula, phi (3,) [rad]; exactly the identity for phi = 0."""
    angle = math.sqrt(float(phi @ phi))
    if angle == 0.0:
        return np.eye(3)
    K = np.array([[0.0, -phi[2], phi[1]], [phi[2], 0.0, -phi[0]], [-phi[1], phi[0], 0.0]])
    R: np.ndarray = np.eye(3) + (math.sin(angle) / angle) * K + ((1.0 - math.cos(angle)) / angle**2) * (K @ K)
    return R


def is_valid_inertia(moments: np.ndarray) -> bool:
    """Whether principal moments (3,) [kg m^2] belong to a real body: all > 0 and each at most the sum of
    the two others (Craig, principal axes; the moments of a mass distribution I_a = ∫ (r_b² + r_c²) dm).
    The triangle inequality is demanded with a relative margin 1e-12 so that round-off in rebuilding the
    matrix cannot take a boundary draw across it."""
    J0, J1, J2 = (float(J) for J in moments)
    margin = 1e-12 * (abs(J0) + abs(J1) + abs(J2))
    return min(J0, J1, J2) > 0.0 and min(J1 + J2 - J0, J0 + J2 - J1, J0 + J1 - J2) >= margin


class InertiaDispersion(Dispersion):
    """Rotational inertia about the centre of mass, in B, kept physically valid.

    The nominal inertia I = E diag(J) E^T (principal moments J, right-handed principal axes E as columns) is
    perturbed in both: J'_k = J_k (1 + rel_std z_k) and E' = E exp(hat(phi)), z ~ N(0, 1) (3,), phi ~ N(0,
    axis_std^2) (3,) [rad], the axes rotated by the rotation vector phi expressed in the principal frame;
    the draw is I' = E' diag(J') E'^T [kg m^2]. A draw whose J' is not a real body's (is_valid_inertia) is
    rejected and redrawn (fresh z and phi from the same sample's generator), at most `max_redraws` times,
    then ValueError naming the sample. Redraws are counted and reported (DispersionWarning).

    rel_std: relative standard deviation >= 0 of each principal moment (a float or (3,), in the order of
    the ascending nominal moments). axis_std: standard deviation >= 0 [rad] of each component of phi.
    nominal: None (the body's inertia_com) or a (3, 3) inertia [kg m^2] about the centre of mass in B.
    """

    keys = ("inertia",)

    def __init__(self, rel_std: Any, axis_std: float = 0.0, *, nominal: Any = None, max_redraws: int = 100):
        self.rel_std = _float_array(rel_std, "rel_std")
        if np.any(self.rel_std < 0) or self.rel_std.ndim > 1 or not _broadcasts(self.rel_std.shape, (3,)):
            raise ValueError(f"rel_std: expected a relative standard deviation >= 0, a float or (3,), got {rel_std!r}")
        axis = _float_array(axis_std, "axis_std")
        if axis.ndim != 0 or axis < 0:
            raise ValueError(f"axis_std: expected a standard deviation >= 0 [rad] (a float), got {axis_std!r}")
        self.axis_std = float(axis)
        self.nominal = None if nominal is None else _float_array(nominal, "nominal")
        if self.nominal is not None and self.nominal.shape != (3, 3):
            raise ValueError(f"nominal: expected a (3, 3) inertia [kg m^2], got shape {self.nominal.shape}")
        if isinstance(max_redraws, bool) or not isinstance(max_redraws, numbers.Integral):
            raise TypeError(f"max_redraws: expected an integer >= 0, got {max_redraws!r}")
        if max_redraws < 0:
            raise ValueError(f"max_redraws: expected an integer >= 0, got {max_redraws!r}")
        self.max_redraws = int(max_redraws)

    def bind(self, key: str, nominal: Any) -> None:
        super().bind(key, nominal)
        inertia = self.nominal if self.nominal is not None else np.asarray(nominal, float)
        J, E = np.linalg.eigh(0.5 * (inertia + inertia.T))
        if not is_valid_inertia(J):
            raise ValueError(f"nominal: expected a physically valid inertia (moments > 0, triangle inequality), "
                             f"got principal moments {J.tolist()}")
        if np.linalg.det(E) < 0:
            E[:, 2] = -E[:, 2]  # right-handed axes
        self._moments, self._axes = J, E

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        """One unchecked draw: (inertia I' (3, 3) [kg m^2], moments J' (3,) [kg m^2], axis rotation phi (3,) [rad])."""
        z = rng.standard_normal(3)
        phi = self.axis_std * rng.standard_normal(3)
        J = self._moments * (1.0 + self.rel_std * z)
        E = self._axes @ _rotation_matrix(phi)
        inertia = (E * J) @ E.T  # E diag(J) E^T
        return 0.5 * (inertia + inertia.T), J, phi

    def __repr__(self) -> str:
        return f"InertiaDispersion(rel_std={self.rel_std.tolist()}, axis_std={self.axis_std})"


class LoadDispersion(Dispersion):
    """One constant load per sample, added to the nominal `loads` schedule: a force through the centre of
    mass [N] and a torque [N m], both in `frame` ('world' W or 'body' B), active for t_start <= t < t_end [s]
    (as AppliedLoad). force, torque: None (zero) or a Normal / Uniform dispersion of a (3,) vector (a
    Normal's mean None means zero)."""

    keys = ("loads",)

    def __init__(self, force: Dispersion | None = None, torque: Dispersion | None = None, frame: str = "world",
                 t_start: float = 0.0, t_end: float = math.inf):
        for name, part in (("force", force), ("torque", torque)):
            if part is not None and not isinstance(part, (Normal, Uniform)):
                raise TypeError(f"{name}: expected None or a Normal / Uniform dispersion, got {part!r}")
            if part is not None:
                part.bind(name, np.zeros(3))
        self.force, self.torque = force, torque
        _core.AppliedLoad(frame=cast(Any, frame), t_start=t_start, t_end=t_end)  # checks frame and the window
        self.frame, self.t_start, self.t_end = frame, t_start, t_end

    def draw(self, rng: np.random.Generator, nominal: Any) -> Any:
        zero = np.zeros(3)
        force = zero if self.force is None else self.force.draw(rng, zero)
        torque = zero if self.torque is None else self.torque.draw(rng, zero)
        return force, torque

    def load(self, force: np.ndarray, torque: np.ndarray) -> Any:
        """The AppliedLoad of one sample's drawn force and torque."""
        return _core.AppliedLoad(force=force, torque=torque, frame=cast(Any, self.frame), t_start=self.t_start,  # checked
                                 t_end=self.t_end)

    def __repr__(self) -> str:
        return f"LoadDispersion(force={self.force!r}, torque={self.torque!r}, frame={self.frame!r})"


def _field(key: str) -> str:
    """The field a dispersion key names: "w_B" -> "w_B", "<body>.w_B" (a scene's body) -> "w_B"."""
    return key.rsplit(".", 1)[-1]


def _classes_for(key: str) -> str:
    names = [cls.__name__ for cls in (Normal, Uniform, UniformRotation, RotationNormal, InertiaDispersion,
                                      LoadDispersion) if _field(key) in cls.keys]
    return " or ".join(names)


# ----------------------------------------------------------------------------------------------------
# results


@dataclass(frozen=True)
class Statistics:
    """Statistics over the samples of one quantity, at every record (leading axis n_records) or at one time.

    t: record time(s) [s]; count: samples with a finite value (a diverged sample has none after it
    stopped); mean, std (sample standard deviation, ddof = 1; NaN below 2 samples), min, max and
    percentiles (len(q), ...) at the percents q (numpy's linear interpolation), all in the quantity's unit.
    """

    quantity: str
    t: Any
    count: Any
    mean: np.ndarray
    std: np.ndarray
    min: np.ndarray
    max: np.ndarray
    q: tuple[float, ...]
    percentiles: np.ndarray


def _check_percents(q: Any) -> tuple[float, ...]:
    percents = _float_array(q, "q")
    if percents.ndim > 1 or np.any((percents < 0) | (percents > 100)):
        raise ValueError(f"q: expected percents in [0, 100] (a float or a sequence), got {q!r}")
    return tuple(np.atleast_1d(percents).tolist())


class MonteCarloResult:
    """The outcome of `monte_carlo`.

    batch: the BatchSceneResult of rigiddyn.simulate_batch (arrays (N, n_records, ...), see it; a body's run is its
      one-body scene's, ``batch.body(0)`` its columns as (N, n_records, ...) arrays), or under a controller the
      samples' stacked records (the same arrays); n = N.
    one_body: the model was one body (monte_carlo of a RigidBody): its per-body fields are that body's records,
      ``batch.body(0)``'s (N, n_records, ...) arrays (p_W (N, n_records, 3), angular_momentum_norm, ...).
    inputs: {key: read-only array (N, ...)} of the drawn values, one row per sample, for the dispersed keys:
      "p_W" (N, 3) [m], "q_WB" (N, 4) (x, y, z, w), "v_W" (N, 3) [m/s], "w_B" (N, 3) [rad/s] (in B),
      "mass" (N,) [kg], "inertia" (N, 3, 3) [kg m^2] (about the centre of mass, in B), "inertia_moments"
      (N, 3) [kg m^2] (its principal moments, in the order of the ascending nominal ones),
      "inertia_axis_rotation" (N, 3) [rad] (the rotation vector phi turning the nominal principal axes), "gravity"
      (N, 3) [m/s^2] (in W), "loads.force" (N, 3) [N] and "loads.torque" (N, 3) [N m] (in the load's frame).
      Under a controller, "controller.seed" (N,) int: each sample's gyro-noise seed.
    redraws: {key: (N,) int} invalid draws rejected per sample for "mass" and "inertia" (see the module).
    seed: the SeedSequence entropy the samples were spawned from (rerun with seed=result.seed).
    dispersions: the dispersions used. times: (n_records,) record times [s].
    error: the batch's global error estimate (a GlobalError, arrays (N, n_records, ...)), or None.
    """

    one_body = False  # a result pickled before the field existed: a scene's

    def __init__(self, batch: Any, inputs: dict[str, np.ndarray], redraws: dict[str, np.ndarray], seed: Any,
                 dispersions: dict[str, Dispersion], one_body: bool = False):
        if not hasattr(batch, "t") or np.ndim(batch.t) != 2:
            raise TypeError(f"batch: expected a BatchSceneResult (records t of shape (N, n_records)), got {batch!r}")
        for name, value in (("inputs", inputs), ("redraws", redraws), ("dispersions", dispersions)):
            if not isinstance(value, Mapping):
                raise TypeError(f"{name}: expected a dict, got {value!r}")
        self.batch = batch
        self.inputs = inputs
        self.redraws = redraws
        self.seed = seed
        self.dispersions = dispersions
        self.one_body = bool(one_body)
        self.n = len(np.asarray(batch.t))
        self._freeze()

    def _freeze(self) -> None:
        """The drawn inputs and redraw counts are read-only (as every result array of rigiddyn)."""
        for array in (*self.inputs.values(), *self.redraws.values()):
            if isinstance(array, np.ndarray):
                array.flags.writeable = False

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__dict__.update(state)
        self._freeze()  # unpickled arrays come back writeable

    def __len__(self) -> int:
        return self.n

    def __repr__(self) -> str:
        keys = ", ".join(self.inputs) or "none"
        return f"MonteCarloResult(n={self.n}, records={len(self.times)}, seed={self.seed}, dispersed: {keys})"

    @property
    def times(self) -> np.ndarray:
        """(n_records,) record times [s] (those of the samples that filled them: a diverged one's are NaN)."""
        t = np.asarray(self.batch.t)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # an all-NaN column: no sample got there
            times: np.ndarray = np.nanmax(t, axis=0)
            return times

    def values(self, quantity: Quantity, at: float | None = None) -> np.ndarray:
        """The quantity per sample: (N, n_records, ...) at every record, or (N, ...) at the record of time
        `at` [s]. quantity: a recorded field of the batch (`fields`: 't', 'p_W', 'q_WB', 'kinetic_energy',
        'work', ...; a body's run reads its per-body fields in its records, p_W (N, n_records, 3),
        'angular_momentum_norm' (N, n_records), ...; a scene's per-body arrays have a bodies axis after the records)
        or a callable taking the BatchSceneResult and returning an array (N, n_records, ...), e.g.
        ``lambda batch: batch.body("hub").angular_momentum_norm``."""
        array = self._quantity(quantity)
        return array if at is None else array[:, self._record_index(at)]

    def statistics(self, quantity: Quantity, at: float | None = None, q: Sequence[float] = (5, 50, 95)
                   ) -> Statistics:
        """Statistics over the samples of `quantity` (see values) at every record, or at time `at` [s] (which
        must be a recorded time: see times). Samples with a non-finite value (a diverged sample after it
        stopped) are left out; `count` says how many samples each figure has. q: percents in [0, 100]."""
        percents = _check_percents(q)
        x = self.values(quantity, at)
        finite = np.isfinite(x)
        count = finite.sum(axis=0)
        t = self.times if at is None else float(self.times[self._record_index(at)])
        name = quantity if isinstance(quantity, str) else getattr(quantity, "__name__", "callable")
        if finite.all():
            std = x.std(axis=0, ddof=1) if len(x) > 1 else np.full(x.shape[1:], np.nan)
            return Statistics(name, t, count, x.mean(axis=0), std, x.min(axis=0), x.max(axis=0), percents,
                              np.percentile(x, percents, axis=0))
        x = np.where(finite, x, np.nan)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # records no sample reached: NaN, count 0
            mean = np.nanmean(x, axis=0)
            std = np.sqrt(np.nansum((x - mean) ** 2, axis=0) / np.where(count > 1, count - 1, np.nan))
            return Statistics(name, t, count, mean, std, np.nanmin(x, axis=0), np.nanmax(x, axis=0), percents,
                              np.nanpercentile(x, percents, axis=0))

    def percentiles(self, quantity: Quantity, q: Sequence[float] = (5, 50, 95), at: float | None = None
                    ) -> np.ndarray:
        """Percentiles (len(q), n_records, ...) or (len(q), ...) at time `at` [s] of `quantity` over the
        samples (see statistics), in the quantity's unit."""
        return self.statistics(quantity, at, q).percentiles

    @property
    def error(self) -> Any:
        """The global error estimate of every record of every sample: the batch's GlobalError (arrays
        (N, n_records, ...), a verdict per sample and record), or None (``monte_carlo(..., error=False)``)."""
        return getattr(self.batch, "error", None)

    @property
    def fields(self) -> tuple[str, ...]:
        """The recorded fields a quantity may name: the batch's arrays (N, n_records, ...) (SCENE_RECORD_FIELDS;
        a body's run adds its records' BODY_RECORD_FIELDS, which its per-body fields are read from), and with an
        error estimate its arrays as
        ``"error.<name>"`` (ERROR_FIELDS: e.g. ``"error.attitude"`` [rad])."""
        return self._recorded() + (tuple("error." + name for name in ERROR_FIELDS) if self.error is not None else ())

    def _recorded(self) -> tuple[str, ...]:
        """The recorded fields without the error estimate's (which the batch makes on their first read)."""
        records = np.shape(self.batch.t)
        recorded = tuple(name for name in SCENE_RECORD_FIELDS
                         if hasattr(self.batch, name) and np.shape(getattr(self.batch, name))[:2] == records)
        if self.one_body:
            recorded = tuple(dict.fromkeys(recorded + BODY_RECORD_FIELDS))
        return recorded

    def _quantity(self, quantity: Quantity) -> np.ndarray:
        records = np.asarray(self.batch.t).shape
        if isinstance(quantity, str):
            if quantity not in (self.fields if quantity.startswith("error.") else self._recorded()):
                raise ValueError(f"quantity: expected a recorded field ({', '.join(self.fields)}) or a callable, "
                                 f"got {quantity!r}")
            owner, name = (self.error, quantity[6:]) if quantity.startswith("error.") else (self.batch, quantity)
            if self.one_body and quantity in BODY_RECORD_FIELDS:
                owner = self.batch.body(0)
            return np.asarray(getattr(owner, name), float)
        if not callable(quantity):
            raise TypeError(f"quantity: expected a field name (str) or a callable of the BatchSceneResult, got "
                            f"{quantity!r}")
        array = np.asarray(quantity(self.batch), dtype=float)
        if array.shape[:2] != records:
            raise ValueError(f"quantity: expected the callable to return an array (N, n_records, ...) = "
                             f"{records + ('...',)}, got shape {array.shape}")
        return array

    def _record_index(self, at: Any) -> int:
        if isinstance(at, bool) or not isinstance(at, numbers.Real) or not math.isfinite(at):
            raise TypeError(f"at: expected None or a recorded time [s] (float), got {at!r}")
        times = self.times
        k = int(np.nanargmin(np.abs(times - at)))
        # a recorded time up to rounding: records sit at t0 + i dt computed in floating point
        if abs(times[k] - at) > 1e-9 * max(abs(float(at)), float(np.nanmax(np.abs(times))), 1e-300):
            raise ValueError(f"at: expected a recorded time [s] ({len(times)} records from {times[0]:g} to "
                             f"{np.nanmax(times):g} s, nearest {times[k]:g} s), got {at!r}")
        return k


def attitude_error(q_WB: Any, q_WB_ref: Any) -> np.ndarray:
    """Angle [rad] in [0, pi] of the rotation between two attitudes, q_ref^-1 ⊗ q (geodesic distance on
    SO(3), independent of the quaternions' signs): 2 atan2(|vec|, |w|) of the product. q_WB, q_WB_ref:
    (..., 4) (x, y, z, w) quaternions, broadcasting. Returns (...)."""
    q = np.asarray(q_WB, float)
    r = np.asarray(q_WB_ref, float)
    for name, a in (("q_WB", q), ("q_WB_ref", r)):
        if a.ndim == 0 or a.shape[-1] != 4:
            raise ValueError(f"{name}: expected quaternions of shape (..., 4), got shape {a.shape}")
    rv, rw, qv, qw = -r[..., :3], r[..., 3:], q[..., :3], q[..., 3:]  # r^-1 = conj(r) for a unit r
    vec = rw * qv + qw * rv + np.cross(rv, qv)
    w = rw[..., 0] * qw[..., 0] - np.sum(rv * qv, axis=-1)
    angle: np.ndarray = 2.0 * np.arctan2(np.linalg.norm(vec, axis=-1), np.abs(w))
    return angle


# ----------------------------------------------------------------------------------------------------
# sampling and the run


def _seed_sequence(seed: Any) -> np.random.SeedSequence:
    if seed is None:
        return np.random.SeedSequence()
    if isinstance(seed, np.random.SeedSequence):
        return seed
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
        raise TypeError(f"seed: expected an integer >= 0, a numpy.random.SeedSequence or None, got {seed!r}")
    if seed < 0:
        raise ValueError(f"seed: expected an integer >= 0, got {seed!r}")
    return np.random.SeedSequence(int(seed))


def _nominal_gravity(gravity: Any) -> np.ndarray:
    if gravity is None or gravity is False:
        return np.zeros(3)
    if gravity is True:
        return np.array(STANDARD_GRAVITY_W)
    return _float_array(gravity, "gravity")


def _nominal_loads(loads: Any) -> list[Any]:
    if loads is None:
        return []
    if isinstance(loads, _core.AppliedLoad):
        return [loads]
    if not isinstance(loads, Sequence) or not all(isinstance(load, _core.AppliedLoad) for load in loads):
        raise TypeError(f"loads: expected None, an AppliedLoad or a list of AppliedLoad, got {loads!r}")
    return list(loads)


def _check_dispersions(dispersions: Any, nominal: dict[str, Any]) -> dict[str, Dispersion]:
    if dispersions is None:
        return {}
    if not isinstance(dispersions, Mapping):
        raise TypeError(f"dispersions: expected a dict {{key: dispersion}}, got {dispersions!r}")
    for key, dispersion in dispersions.items():
        if key not in nominal:
            raise ValueError(f"dispersions: expected {_keys_among(nominal)}, got {key!r}")
        if not isinstance(dispersion, Dispersion):
            raise TypeError(f"dispersions[{key!r}]: expected {_classes_for(key)}, got {dispersion!r}")
        dispersion.bind(key, nominal[key])
    return dict(dispersions)


def _keys_among(nominal: Mapping[str, Any]) -> str:
    """The dispersible keys as an error lists them (the first _KEYS_SHOWN of a large scene, and how many)."""
    if not nominal:
        return "no key (no body of the scene has a dispersible field: see SCENE_BODY_FIELDS)"
    shown = list(itertools.islice(nominal, _KEYS_SHOWN))
    more = f", ... ({len(nominal)} keys)" if len(nominal) > len(shown) else ""
    return "keys among " + ", ".join(shown) + more


def _draw_valid(dispersion: Dispersion, rng: np.random.Generator, nominal: Any, key: str, i: int,
                valid: Callable[[Any], bool]) -> tuple[Any, int]:
    """One sample's draw of `key`, redrawn while `valid` rejects it (at most max_redraws times)."""
    max_redraws = getattr(dispersion, "max_redraws", 100)
    for redraws in range(max_redraws + 1):
        value = dispersion.draw(rng, nominal)
        if valid(value):
            return value, redraws
    raise ValueError(f"dispersions[{key!r}]: sample {i}: no valid draw in {max_redraws + 1} tries ({dispersion!r}); "
                     f"the dispersion is too wide for a physical {key}")


def _sample(dispersions: dict[str, Dispersion], nominal: dict[str, Any], n: int, seeds: np.random.SeedSequence
            ) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """The drawn inputs {key: (N, ...)} and the redraw counts {key: (N,)} of samples 0..n-1."""
    order = [key for key in nominal if key in dispersions]  # nominal's keys are in draw order
    drawn: dict[str, list[Any]] = {key: [] for key in order}
    redraws = {key: np.zeros(n, dtype=np.int64) for key in order if _field(key) in ("mass", "inertia")}
    validity = {"mass": lambda m: float(m) > 0.0, "inertia": lambda draw: is_valid_inertia(draw[1])}
    for i, child in enumerate(seeds.spawn(n)):
        rng = np.random.default_rng(child)  # sample i's draws depend only on (seed, i)
        for key in order:
            if _field(key) in validity:
                value, redraws[key][i] = _draw_valid(dispersions[key], rng, nominal[key], key, i,
                                                     validity[_field(key)])
            else:
                value = dispersions[key].draw(rng, nominal[key])
            drawn[key].append(value)
    inputs = {}
    for key, values in drawn.items():
        if _field(key) == "inertia":
            inputs[key] = np.array([v[0] for v in values])
            inputs[f"{key}_moments"] = np.array([v[1] for v in values])
            inputs[f"{key}_axis_rotation"] = np.array([v[2] for v in values])
        elif key == "loads":
            inputs["loads.force"] = np.array([v[0] for v in values])
            inputs["loads.torque"] = np.array([v[1] for v in values])
        else:
            inputs[key] = np.array(values, dtype=float)
    return inputs, redraws


def _warn_redraws(redraws: dict[str, np.ndarray], n: int) -> None:
    for key, counts in redraws.items():
        samples = int(np.count_nonzero(counts))
        if samples:
            warnings.warn(f"monte_carlo: dispersions[{key!r}]: {samples} of {n} samples drew an invalid {key} "
                          f"({int(counts.sum())} draws rejected and redrawn); the {key} dispersion sampled is the "
                          f"stated one truncated to physical values (MonteCarloResult.redraws)",
                          DispersionWarning, stacklevel=3)


def _batch_inputs(model: Any, n: int, inputs: dict[str, np.ndarray], dispersions: dict[str, Dispersion],
                  nominal: dict[str, Any]) -> tuple[Any, Any, Any, Any]:
    """(model, initial, gravity, loads) arguments of simulate_batch for the drawn inputs."""
    initial = {key: inputs[key] if key in inputs else np.tile(nominal[key], (n, 1)) for key in STATE_KEYS}
    if "mass" in inputs or "inertia" in inputs:
        masses = inputs.get("mass", np.full(n, model.mass))
        inertias = inputs.get("inertia", np.broadcast_to(model.inertia_com, (n, 3, 3)))
        # the nominal inertia passed the check the user built the body with (perhaps allow_unrealizable);
        # dispersed inertias are physical by construction, and checked as such
        check = _core.InertiaCheck.physical if "inertia" in inputs else _core.InertiaCheck.allow_unrealizable
        model = [_core.RigidBody(float(m), inertia, check) for m, inertia in zip(masses, inertias)]
    gravity = inputs.get("gravity")
    loads = nominal["loads"] or None
    if "loads" in dispersions:
        load = dispersions["loads"]
        assert isinstance(load, LoadDispersion)  # checked by _check_dispersions
        loads = [nominal["loads"] + [load.load(f, tau)]
                 for f, tau in zip(inputs["loads.force"], inputs["loads.torque"])]
    return model, initial, gravity, loads


# the dispersible fields of a scene's body, by its kind, in draw order (a PlanarBody's are not dispersed; a
# pivoted body's state: its attitude and rate about the pivot)
SCENE_BODY_FIELDS = {"RigidBody": ("p_W", "q_WB", "v_W", "w_B", "mass", "inertia"),
                     "Particle": ("p_W", "v_W", "mass"),
                     "PivotedBody": ("q_WB", "w_B"),
                     "PivotedPlanarBody": ("theta", "omega"),
                     "Gyrostat": ("p_W", "q_WB", "v_W", "w_B"),
                     "TreeLink": ("q", "v")}
STATE_OF_BODY = {"RigidBody": "RigidBodyState", "Particle": "ParticleState", "PivotedBody": "PivotedBodyState",
                 "PivotedPlanarBody": "PivotedPlanarBodyState", "Gyrostat": "GyrostatState", "TreeLink": "JointState"}
# the state fields of each body kind, in its state class's constructor order (a gyrostat's wheel speeds kept at
# their nominal values)
_STATE_FIELDS = {"RigidBody": STATE_KEYS, "Particle": ("p_W", "v_W"), "PivotedBody": ("q_WB", "w_B"),
                 "PivotedPlanarBody": ("theta", "omega"), "Gyrostat": (*STATE_KEYS, "wheel_speeds"),
                 "TreeLink": ("q", "v")}


def _scene_nominal(scene: Any, nominal_state: Any) -> dict[str, Any]:
    """{"<body name>.<field>": nominal value} of every dispersible field of the scene's bodies, in draw order
    (bodies in their order, each body's fields in DRAW_ORDER)."""
    if not isinstance(nominal_state, Sequence) or len(nominal_state) != len(scene.bodies):
        raise ValueError(f"nominal_state: expected a list of the states of the scene's {len(scene.bodies)} bodies, "
                         f"got {nominal_state!r}")
    nominal: dict[str, Any] = {}
    for name, body, state in zip(scene.body_names, scene.bodies, nominal_state):
        kind = type(body).__name__
        if kind in STATE_OF_BODY and type(state).__name__ != STATE_OF_BODY[kind]:
            raise TypeError(f"nominal_state: expected a {STATE_OF_BODY[kind]} for body {name!r}, "
                            f"got {type(state).__name__}")
        for field in SCENE_BODY_FIELDS.get(kind, ()):
            value = {"mass": lambda: body.mass, "inertia": lambda: body.inertia_com}.get(
                field, lambda: getattr(state, field))()
            if np.size(value) > 0:  # (a fixed joint has no q or v)
                nominal[f"{name}.{field}"] = value
    return nominal


def _scene_batch_inputs(model: Any, nominal_state: Any, n: int, inputs: dict[str, np.ndarray]) -> tuple[Any, Any]:
    """(model, initial) arguments of simulate_batch for a scene: N lists of body states, and N scenes when a
    body's mass or inertia is dispersed (the same elements, frame and mass flows)."""
    scene = model.scene if isinstance(model, _core.CompiledScene) else model

    def drawn(name: str, field: str, i: int, nominal: Any) -> Any:
        return inputs[f"{name}.{field}"][i] if f"{name}.{field}" in inputs else nominal

    def state(name: str, body: Any, nominal: Any, i: int) -> Any:
        kind = type(body).__name__
        if kind not in _STATE_FIELDS:
            return nominal
        return getattr(_core, STATE_OF_BODY[kind])(**{f: drawn(name, f, i, getattr(nominal, f))
                                                     for f in _STATE_FIELDS[kind]})

    def body_of(name: str, body: Any, i: int) -> Any:
        kind = type(body).__name__
        if kind == "RigidBody":
            dispersed = f"{name}.inertia" in inputs
            check = _core.InertiaCheck.physical if dispersed else _core.InertiaCheck.allow_unrealizable
            return _core.RigidBody(float(drawn(name, "mass", i, body.mass)),
                                   drawn(name, "inertia", i, body.inertia_com), check)
        if kind == "Particle":
            return _core.Particle(float(drawn(name, "mass", i, body.mass)))
        return body

    named = list(zip(scene.body_names, scene.bodies, nominal_state))
    initial = [[state(name, body, nominal, i) for name, body, nominal in named] for i in range(n)]
    if any(_field(key) in ("mass", "inertia") for key in inputs):
        model = [_core.Scene(bodies=[body_of(name, body, i) for name, body, _ in named],
                             body_names=list(scene.body_names), elements=list(scene.elements), frame=scene.frame,
                             mass_flows=list(scene.mass_flows)) for i in range(n)]
    return model, initial


def _count(value: Any, name: str, least: int) -> int:
    """`value` as an int >= `least` (TypeError / ValueError naming `name`)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: expected an integer >= {least}, got {value!r}")
    if value < least:
        raise ValueError(f"{name}: expected an integer >= {least}, got {value!r}")
    return int(value)


def _check_memory(n: int, steps: int, record_every: int, model: Any, error: bool) -> None:
    """ValueError naming n, before any draw, when N samples would not fit in the available memory: each
    sample's records (as simulate_batch counts them: step 0, every record_every-th step and the last;
    _SCENE_RECORD_DOUBLES of a scene per record, a body's as its one-body scene's with gravity and loads; with
    the error estimate its two coarse runs, at most as many values a record and at most floor(steps / m) + 1
    records each (m = lcm(record_every, 4); a long run's are fewer), and _ERROR_DOUBLES per record of the estimate)
    and what drawing it holds
    (_SAMPLE_BYTES, and a state object per body of a scene, _STATE_BYTES)."""
    records = 1 + steps // record_every + (1 if steps % record_every else 0)
    if isinstance(model, _core.Scene):
        nb = len(model.bodies)
        terms = len(model.elements) + (_FRAME_TERMS if model.frame is not None else 0)
        per_record = _SCENE_RECORD_DOUBLES[0] + _SCENE_RECORD_DOUBLES[1] * nb + _SCENE_RECORD_DOUBLES[2] * terms
        per_sample = _SAMPLE_BYTES + _STATE_BYTES * nb
    else:
        per_record = _SCENE_RECORD_DOUBLES[0] + _SCENE_RECORD_DOUBLES[1] + 2 * _SCENE_RECORD_DOUBLES[2]
        per_sample = _SAMPLE_BYTES
    doubles = records * per_record
    if error:
        doubles += 2 * (steps // math.lcm(record_every, 4) + 1) * per_record + records * _ERROR_DOUBLES
    per_sample += doubles * 8
    available = available_bytes()
    available = sys.maxsize if available is None else available  # unknown: only what no array can hold
    if n * per_sample > available:
        raise ValueError(f"n: expected a sample count whose runs fit in the available memory "
                         f"({format_bytes(available)}: at most {available // per_sample} samples of {records} records, "
                         f"{format_bytes(per_sample)} each), got {n} (an estimated {format_bytes(n * per_sample)}; "
                         "fewer samples, or a larger record_every)")


def _check_controlled(model: Any, controller: Any, client: Any) -> None:
    """What monte_carlo's controller needs: a Controller on a scene, run here (no client: the samples run through
    simulate)."""
    from .control import Controller

    if not isinstance(controller, Controller):
        raise TypeError(f"controller: expected a rigiddyn.Controller or None, got {controller!r}")
    if isinstance(model, _core.RigidBody):
        raise ValueError("controller: expected None for a RigidBody model (a controller drives a Scene's actuators), "
                         f"got {controller!r}")
    if client is not None:
        raise ValueError(f"client: expected None with a controller (its samples run on this machine through "
                         f"simulate), got {client!r}")


def _sample_bar(n: int, enabled: bool) -> tuple[Callable[[int], None] | None, Callable[[], None] | None]:
    """(progress(samples_done) for simulate_batch, close()) of a bar of n samples on stderr: tqdm if installed,
    else a plain one; (None, None) when not enabled."""
    if not enabled:
        return None, None
    try:
        from tqdm import tqdm
    except ImportError:
        def show(done: int) -> None:
            print(f"\rmonte_carlo: {done}/{n} samples", end="", file=sys.stderr, flush=True)

        def end() -> None:
            print(file=sys.stderr)

        return show, end
    bar = tqdm(total=n, desc="monte_carlo", unit="sample", file=sys.stderr)

    def update(done: int) -> None:
        bar.update(done - bar.n)

    return update, bar.close


def monte_carlo(model: Any, nominal_state: Any, n: int, *, seed: Any,
                dispersions: Mapping[str, Dispersion] | None = None,
                dt: Any, steps: int | None = None, duration: Any = None, method: str | None = None,
                record_every: int = 1, loads: Any = None, gravity: Any = None, t0: Any = 0.0,
                threads: int | None = None, client: Any = None,
                progress: bool | Callable[[int], Any] = False, error: bool = True,
                controller: Any = None) -> MonteCarloResult:
    """N runs of a rigid body, or of a scene, with dispersed initial states, mass properties and loads.

    Draws N samples of the dispersed inputs (sample i from its own generator, a function of (seed, i) only:
    module docstring of ``rigiddyn.dispersion``), then runs them as one ``simulate_batch`` on this machine's
    threads, or through ``rigiddyn.distributed.simulate_batch`` on a Dask cluster (the same draws and,
    bitwise, the same result).

    Parameters
    ----------
    model : RigidBody, Scene or CompiledScene
        The nominal body (mass [kg], inertia about the centre of mass in B [kg m²]); or a scene, whose
        bodies' states and mass properties are dispersed under the keys ``"<body name>.<field>"`` (fields
        p_W, q_WB, v_W, w_B, mass, inertia of a RigidBody; p_W, v_W, mass of a Particle; q_WB, w_B of a
        PivotedBody; theta [rad], omega [rad/s] of a PivotedPlanarBody; q and v, the joint's coordinates and
        velocities, of a tree link; a PlanarBody is not dispersed); a scene's loads and gravity are its elements.
    nominal_state : RigidBodyState or list of body states
        p_W [m], q_WB (x, y, z, w), v_W [m/s] in W, w_B [rad/s] in B; for a scene, its bodies' states.
    n : int
        Number of samples N >= 1, whose records fit in the memory available (estimated before any draw:
        ValueError naming n otherwise).
    seed : int, numpy.random.SeedSequence or None, keyword-only
        An integer >= 0, a SeedSequence, or None (fresh entropy, kept as ``result.seed``); sample i draws
        from ``SeedSequence(seed).spawn(n)[i]``.
    dispersions : dict of str to Dispersion, optional
        {key: dispersion} (keys and classes in the module docstring of ``rigiddyn.dispersion``); a key not
        given keeps its nominal value (the state's field, the body's mass and inertia, `gravity`, `loads`).
    dt : float, keyword-only
        Step [s].
    steps : int, optional
        Steps of every run; exactly one of `steps` and `duration`.
    duration : float, optional
        Length of the runs [s], a whole number of steps of dt.
    method : str, optional
        None: ``"rk4"``, or a CompiledScene's method.
    record_every, loads, gravity, t0
        As ``simulate``, common to every sample: record every k-th step; the nominal load schedule; gravity
        (None/False: none, True: (0, 0, -9.81) m/s², or a 3-vector in W [m/s²]); the initial time [s].
    threads : int, optional
        Threads of the local run (None: all cores); None with `client`. Under a controller, how many samples run
        at once (None: one, the samples one after the other): the same result, bit for bit; a law in C++ then runs
        in parallel, a law in Python is called from that many threads (each sample under its own copy). Each
        sample's Python work takes the GIL, so short samples gain less (16 samples of cubesat_detumbling on 2
        cores: 1.9x faster with 8 000 steps each, 1.1-1.2x with 400).
    client : dask.distributed.Client or str, optional
        None: run on this machine with ``simulate_batch``; a Client or a scheduler address: run through
        ``rigiddyn.distributed.simulate_batch``.
    progress : bool or callable, default False
        False: nothing. True: a bar of samples on stderr (tqdm if installed, else a plain one). A callable:
        ``progress(samples_done)``, as ``simulate_batch`` calls its own (from the calling thread once before
        the samples start, then about every 0.05 s; an exception it raises stops the run and propagates).
        With `client`: True or False (``rigiddyn.distributed``'s bar of chunks).
    error : bool, default True
        Estimate the global error of every record of every sample (``result.error``, a GlobalError with a
        leading sample axis: ``simulate_batch``'s `error`, +0.75x the cost when it is first read); its quantities
        are fields too (``result.statistics("error.attitude")``). False: none. Under a controller, each sample's
        estimate is the one ``simulate`` gives for it, made right after its run (+0.75x its cost then).
    controller : Controller, keyword-only, optional
        A digital controller (rigiddyn.Controller) of a scene's runs: each sample runs under its own copy (its law
        deep-copied), whose gyro noise draws from the seed ``result.inputs["controller.seed"][i]`` (N,), itself
        drawn from ``SeedSequence(seed)`` and a function of (seed, i) only (the sample's dispersions are drawn as
        without it). The samples then run through ``simulate`` (a law in Python takes the GIL at its samples), one
        after the other or `threads` at once: ``result.batch`` holds their stacked records and estimates, as a
        BatchSceneResult's. None (the default): no controller. Not with a RigidBody model or `client`.

    Returns
    -------
    MonteCarloResult
        The BatchSceneResult, the drawn inputs, statistics and percentiles.

    Raises
    ------
    TypeError, ValueError
        An argument that is not valid (the message names it).

    Warns
    -----
    DispersionWarning
        When invalid draws (a mass <= 0, an unphysical inertia) were redrawn.

    See Also
    --------
    simulate_batch : the batch it runs.

    Examples
    --------
    A torque-free body spun about its major axis with rates dispersed by 0.01 rad/s: every sample keeps
    the magnitude of its body angular momentum |I w_B| (RK4 at dt·|ω| = 0.01 over 1 s: drift below 1e-6):

    >>> body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    >>> spin = rd.RigidBodyState(w_B=[0.0, 0.0, 1.0])
    >>> run = rd.monte_carlo(body, spin, 100, seed=1, dispersions={"w_B": rd.dispersion.Normal(std=0.01)},
    ...                      dt=0.01, steps=100)
    >>> len(run), run.values("w_B").shape
    (100, (100, 101, 3))
    >>> L_0 = np.linalg.norm(run.inputs["w_B"] * [1.0, 2.0, 3.0], axis=1)
    >>> L_1 = np.linalg.norm(run.values("w_B", at=1.0) * [1.0, 2.0, 3.0], axis=1)
    >>> bool(np.all(np.abs(L_1 - L_0) <= 1e-6 * L_0))
    True

    A scene under a controller (a body driven to rest by a thruster law from dispersed rates), each sample with
    its own gyro-noise seed; the law keeps no state, so the error estimate may sample copies of it (repeatable):

    >>> scene = rd.Scene([rd.RigidBody(1.0, [1.0, 1.0, 1.0])], elements=[rd.ScheduledLoads(body=0, loads=[])])
    >>> law = lambda state: {0: tuple(-2.0 * state.v_W[0])}
    >>> runs = rd.monte_carlo(scene, [rd.RigidBodyState(v_W=[1.0, 0.0, 0.0])], 4, seed=2, dt=0.01, steps=50,
    ...                       dispersions={"body0.v_W": rd.dispersion.Normal(std=0.1)},
    ...                       controller=rd.Controller(0.1, law, w_B_noise=1e-3, repeatable=True))
    >>> runs.values("v_W").shape, runs.inputs["controller.seed"].shape, runs.error.position.shape
    ((4, 51, 1, 3), (4,), (4, 51, 1))
    """
    scene = model.scene if isinstance(model, _core.CompiledScene) else model
    if not isinstance(model, (_core.RigidBody, _core.Scene, _core.CompiledScene)):
        raise TypeError(f"model: expected a RigidBody, a Scene or a CompiledScene, got {type(model).__name__}")
    if isinstance(model, _core.RigidBody) and not isinstance(nominal_state, _core.RigidBodyState):
        raise TypeError(f"nominal_state: expected a RigidBodyState, got {type(nominal_state).__name__}")
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise TypeError(f"n: expected a sample count (an integer >= 1), got {n!r}")
    if n < 1:
        raise ValueError(f"n: expected a sample count >= 1, got {n!r}")
    if not isinstance(progress, (bool, np.bool_)) and not callable(progress):
        raise TypeError(f"progress: expected True, False or a callable progress(samples_done), got {progress!r}")
    if not isinstance(error, (bool, np.bool_)):
        raise TypeError(f"error: expected True or False, got {error!r}")
    if client is not None and callable(progress):
        raise TypeError(f"progress: expected True or False with client= (the cluster's bar of chunks), "
                        f"got {progress!r}")
    if client is not None and threads is not None:
        raise ValueError(f"threads: expected None with client= (the workers' threads are the cluster's), "
                         f"got {threads!r}")
    if controller is not None:
        _check_controlled(model, controller, client)
        samples_at_once = 1 if threads is None else _count(threads, "threads", 1)
    # checked before any draw, as the memory below
    steps = _core._steps_of(None if steps is None else _count(steps, "steps", 0), duration, dt)
    _check_memory(int(n), steps, _count(record_every, "record_every", 1), scene, bool(error))
    seeds = _seed_sequence(seed)
    if isinstance(model, _core.RigidBody):
        nominal = {"p_W": nominal_state.p_W, "q_WB": nominal_state.q_WB, "v_W": nominal_state.v_W,
                   "w_B": nominal_state.w_B, "mass": model.mass, "inertia": model.inertia_com,
                   "gravity": _nominal_gravity(gravity), "loads": _nominal_loads(loads)}  # in DRAW_ORDER
    else:
        nominal = _scene_nominal(scene, nominal_state)
    dispersions = _check_dispersions(dispersions, nominal)
    inputs, redraws = _sample(dispersions, nominal, int(n), seeds)
    _warn_redraws(redraws, int(n))
    if isinstance(model, _core.RigidBody):
        batch_model, initial, gravity_n, loads_n = _batch_inputs(model, int(n), inputs, dispersions, nominal)
        options = dict(record_every=record_every, loads=loads_n, gravity=gravity if gravity_n is None else gravity_n)
    else:
        batch_model, initial = _scene_batch_inputs(model, nominal_state, int(n), inputs)
        options = dict(record_every=record_every, loads=loads, gravity=gravity)
        if method is None and isinstance(model, _core.CompiledScene):
            method = model.method  # also when the samples run rebuilt scenes
    if controller is not None:
        seeds_of_laws = controller_seeds(seeds, int(n))
        update, close = (progress, None) if callable(progress) else _sample_bar(int(n), bool(progress))
        try:
            batch = run_samples(batch_model, initial, dt, steps, controller, seeds_of_laws,
                                dict(options, method=method, t0=t0, error=bool(error)), SCENE_RECORD_FIELDS, update,
                                samples_at_once)
        finally:
            if close is not None:
                close()
        return MonteCarloResult(batch, {**inputs, "controller.seed": seeds_of_laws}, redraws, seeds.entropy,
                                dispersions)
    options.update(method=method, t0=t0, error=bool(error))
    if client is None:
        update, close = (progress, None) if callable(progress) else _sample_bar(int(n), bool(progress))
        try:
            batch = _core.simulate_batch(batch_model, initial, dt, steps, threads=threads, progress=update, **options)
            if close is not None and update is not None:  # the bar shows the run complete
                update(int(n))
        finally:
            if close is not None:
                close()
    else:
        distributed = importlib.import_module("rigiddyn.distributed")
        batch = distributed.simulate_batch(batch_model, initial, dt, steps, client=client, progress=bool(progress),
                                           **options)
    return MonteCarloResult(batch, inputs, redraws, seeds.entropy, dispersions,
                            one_body=isinstance(model, _core.RigidBody))
