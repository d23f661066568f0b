"""rigiddyn.tradeoff on a scene: many bodies, force elements, a reference without a closed form.

`tradeoff` (rigiddyn.work_precision) takes a scene the way it takes a one-body problem: a
rigiddyn.Scene with its initial states (initial=..., horizon=...), the SceneFile (scene, initial states, run
options) that rigiddyn.load_scene returns, or a scene TOML file or shipped scene name (a file whose
`body` is an array of tables, [[body]], is a scene; [body] is a problem). This module holds the scene
side of the sweep (SceneCase: compile, run, states, error measures, exact references, stability); it is
one of the two cases the sweep runs (rigiddyn.work_precision.case.Case; the other, a problem's, is
work_precision.one_body.ProblemCase). The sweep's loop, the rows, the report, the reference refinement
and its check are rigiddyn.work_precision's.

Each method is compiled once (`scene.compile(method=...)`): a refusal (ValueError, e.g. `exact` on a
scene with forces) becomes the method's rows with "not applicable: <reason>" in order_note and nan
errors; a compatibility warning (rigiddyn.SceneCompatibilityWarning, e.g. a damper with a splitting)
becomes a note of the report. The reference is the scene's closed form when the scene is one's case
(exact_reference: one pivoted planar body under uniform gravity, CompoundPendulumSolution; one
symmetric pivoted body with its centre of mass on its axis under uniform gravity, LagrangeTopSolution;
one particle with a constant mass rate, one thrust and at most uniform gravity, ConstantThrustSolution;
free particles in a frame turning at a constant rate, RotatingFrameFreeParticle): every row's
`reference` is then "exact: <class>", the title says "the exact solution (<class>)" and a note names the
case. Otherwise it is the highest-order method that compiles without a warning, refined by Richardson
(rigiddyn.work_precision.references), and checked against the core's other method family at the
reference's finest step with its own Richardson estimate (no independent rate in Python: SciPy's
DOP853 checks problems only).

The error measures of MEASURES, many bodies (b) at the recorded times t:
  position_error  max_b |p_W - p_ref| [m];  velocity_error  max_b |v_W - v_ref| [m/s]
  attitude_error  max_b geodesic angle |log(q_ref^-1 q)| [rad] (rigid and planar bodies; a particle's
                  attitude is the identity in both, angle 0)
  momentum_error  max_b |I_b (w_B - w_ref)| / max_t |I_b w_ref| (body angular momentum relative to
                  its largest value over the run; 0 for a particle)
  state_error     max of attitude, momentum, position / L_p and velocity / L_v (L_p = max(largest radius
                  of gyration, largest displacement of a body), L_v = max(largest speed, L_p / horizon))
  energy_drift    max_t |E - E_ref| / max_t (T_ref + |V_ref|): total energy E = T + V (kinetic plus the
                  elements' potentials), relative
  momentum_drift  max_t of |P - P_ref| / max_t sum_b m_b |v_ref| and |L - L_ref| / max_t sum_b (m_b |p x
                  v_ref| + |I_b w_ref|): total linear momentum P and angular momentum L about W's origin,
                  relative to the sum of the bodies' magnitudes (a scene whose totals are 0 still has a scale)
  quaternion_norm_error  max_b,t ||q| - 1| (rigid and pivoted bodies)
A pinned body is measured as a free one (its centre of mass, attitude and w_B); a body whose mass
changes by its mass at t = 0 in the scales. The default steps also resolve a pinned body's swing
(pendulum_rates).
"""

from __future__ import annotations

import math
import os
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, ClassVar, cast

import numpy as np

from . import _core
from ._loaded_file import SceneFile

__all__ = ["BodyData", "SceneCase", "SceneStates", "attitude_angle", "is_scene_source", "scene_case",
           "scene_measures"]

_TINY = np.finfo(float).tiny


def is_scene_source(source: Any) -> bool:
    """True if `source` (a path or a name) is a scene file: a TOML file whose `body` is an array of
    tables ([[body]]; a problem file has one [body] table), or the name of a shipped scene."""
    if not isinstance(source, (str, os.PathLike)):
        return False
    path = Path(source)
    if path.is_file():
        from .scene_file import is_scene_toml

        return is_scene_toml(path)
    from .scene_file import example_scenes

    return isinstance(source, str) and not path.suffix and len(path.parts) == 1 and source in example_scenes()


def _option(options: Any, key: str) -> Any:
    """A run option of load_scene (a mapping or an object with attributes), None if absent."""
    if options is None:
        return None
    if isinstance(options, Mapping):
        return options.get(key)
    return getattr(options, key, None)


@dataclass(frozen=True)
class BodyData:
    """What the measures need of a body: its kind ('particle', 'planar', 'rigid', 'pivoted', 'pivoted_planar',
    'gyrostat', 'tree_link'), mass [kg] (at t = 0) and inertia
    about its centre of mass in B [kg m^2] (0 for a particle, diag(0, 0, I_zz) for a planar body)."""

    kind: str
    mass: float
    inertia_com: np.ndarray


def _body_data(body: Any) -> BodyData:
    """A pinned body's data are its rigid body's (mass, inertia about its centre of mass), its kind
    'pivoted' or 'pivoted_planar'; the measures compare its centre of mass and attitude as for a free one."""
    kind = type(body).__name__
    if kind in ("RigidBody", "PivotedBody", "Gyrostat", "TreeLink"):
        return BodyData({"RigidBody": "rigid", "PivotedBody": "pivoted", "Gyrostat": "gyrostat",
                         "TreeLink": "tree_link"}[kind], float(body.mass), np.asarray(body.inertia_com, float))
    if kind in ("PlanarBody", "PivotedPlanarBody"):
        return BodyData("planar" if kind == "PlanarBody" else "pivoted_planar", float(body.mass),
                        np.diag([0.0, 0.0, float(body.inertia_zz)]))
    return BodyData("particle", float(body.mass), np.zeros((3, 3)))


@dataclass(frozen=True)
class Compiled:
    """A method compiled on a scene: the model (None if refused), the refusal's reason and the
    compatibility warnings."""

    model: Any
    reason: str
    warnings: tuple[str, ...]


@dataclass
class SceneStates:
    """States of nb bodies at n times: t (n,), p_W, v_W, w_B (n, nb, 3), q_WB (n, nb, 4) (x, y, z, w), and
    the scene's totals: kinetic, potential and total energy (n,) [J], linear_momentum_W (n, 3) [kg m/s],
    angular_momentum_W (n, 3) [kg m^2/s] about W's origin."""

    t: np.ndarray
    p_W: np.ndarray
    q_WB: np.ndarray
    v_W: np.ndarray
    w_B: np.ndarray
    kinetic_energy: np.ndarray
    potential_energy: np.ndarray
    total_energy: np.ndarray
    linear_momentum_W: np.ndarray
    angular_momentum_W: np.ndarray


@dataclass
class SceneCase:
    """A scene swept by tradeoff: `scene` (rigiddyn.Scene), its `initial` states (one per body), the
    `horizon` [s], its `name` and the sweep defaults `tradeoff` (methods, dts, tolerance, measure).
    The scene side of the sweep's case (its interface: rigiddyn.work_precision.case.Case)."""

    name: str
    scene: Any
    initial: list[Any]
    horizon: float
    tradeoff: dict[str, Any] = field(default_factory=dict)
    bodies: list[BodyData] = field(default_factory=list)
    _compiled: dict[str, Compiled] = field(default_factory=dict, repr=False)
    exact: ExactReference | None = field(default=None, repr=False)
    _modes: list[tuple[str, float, float]] | None = field(default=None, repr=False)
    # a scene's bodies may have no attitude (particles): its default measure takes every part of the state
    default_measure: ClassVar[str] = "final_state_error"
    stability_subject: ClassVar[str] = "for this scene"

    def __post_init__(self) -> None:
        if not self.bodies:
            self.bodies = [_body_data(b) for b in self.scene.bodies]
        if self.exact is None:
            self.exact = exact_reference(self.scene, self.initial)

    @property
    def has_exact_solution(self) -> bool:
        """True when the scene is a case of a closed form (exact_reference)."""
        return self.exact is not None

    @property
    def exact_label(self) -> str:
        """The rows' reference when the closed form is: "exact: <its rigiddyn class>"."""
        return f"exact: {self.exact.name}" if self.exact is not None else "exact"

    def with_horizon(self, horizon: float) -> SceneCase:
        return replace(self, horizon=float(horizon))

    def refusal(self, method: str) -> str:
        """Why the scene's compile refuses `method` ("": it compiles)."""
        compiled = self.compile(method)
        return "" if compiled.model is not None else compiled.reason or "refused"

    def compile_warnings(self, method: str) -> tuple[str, ...]:
        """The compatibility warnings of the scene compiled for `method`, as text."""
        return self.compile(method).warnings

    def notes(self, methods: list[str]) -> list[str]:
        """What the report says besides the rows: the closed form it is measured against, and the
        compatibility warnings of `methods`."""
        notes = [f"{m}: {text} (SceneCompatibilityWarning)" for m in methods for text in self.compile_warnings(m)]
        if self.exact is not None:
            notes.insert(0, f"reference: the exact solution rigiddyn.{self.exact.name} ({self.exact.case})")
        return notes

    def default_methods(self, info: Mapping[str, Mapping[str, Any]]) -> list[str]:
        """Every method (one the scene refuses shows why in its rows)."""
        return list(info)

    def exact_methods(self, info: Mapping[str, Mapping[str, Any]]) -> set[str]:
        """The methods without truncation error here: order 0, or exact on torque-free bodies when no
        element acts and the frame is inertial."""
        free = not list(self.scene.elements) and getattr(self.scene, "frame", None) is None
        return {m for m, i in info.items() if i["order"] == 0 or (free and i["exact_torque_free"])}

    def stability(self, method: str, dt: float, steps: int) -> str | None:
        """Why dt is beyond the method's linear stability limit for a body's spin or a mode of the
        elements (rigiddyn.stability.scene_stability_message; None if it is not)."""
        from .stability import scene_modes, scene_stability_message

        if self._modes is None:
            self._modes = scene_modes(self.scene, self.initial)
        return scene_stability_message(method, dt, steps, self.scene, self.initial, self._modes)

    def independent(self, times: np.ndarray) -> None:
        """No reference independent of the core (SciPy's DOP853 checks problems only): the sweep checks
        against the core's other method family."""
        return None

    def compile(self, method: str) -> Compiled:
        """The scene compiled for `method` (cached): a refusal's reason instead of a model, and the
        compatibility warnings (SceneCompatibilityWarning) as text."""
        if method not in self._compiled:
            category: type[Warning] = getattr(_core, "SceneCompatibilityWarning")
            with warnings.catch_warnings():  # the report's notes say them
                warnings.simplefilter("ignore", category)
                try:
                    model, reason = self.scene.compile(method=method), ""
                except ValueError as error:
                    model, reason = None, str(error)
            texts = () if model is None else tuple(str(w) for w in model.warnings)
            self._compiled[method] = Compiled(model, reason, texts)
        return self._compiled[method]

    def simulate(self, method: str, dt: float, steps: int, record_every: int,
                 progress: Callable[[int], None] | None = None, error: bool = False) -> Any:
        """rigiddyn.simulate of the scene compiled for `method` (ValueError if it is refused); `progress`
        is called with the steps done; `error`: with the run's error estimate (result.error)."""
        compiled = self.compile(method)
        if compiled.model is None:
            raise ValueError(compiled.reason)
        # method: a str of methods() (mypy knows their literal names), checked by the core
        return _core.simulate(compiled.model, self.initial, dt, steps, cast(Any, method), record_every=record_every,
                              progress=progress, error=error, accuracy_level=None)  # coarse on purpose

    def states(self, result: Any) -> SceneStates:
        """The recorded states and totals of a scene result."""
        return SceneStates(*(np.asarray(getattr(result, k), float) for k in (
            "t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "potential_energy", "total_energy",
            "linear_momentum_W", "angular_momentum_W")))

    def quaternion_norm_error(self, result: Any) -> np.ndarray:
        """||q_WB| - 1| of the bodies with a 3-D attitude at each record (n,) (0 without one)."""
        rigid = [i for i, b in enumerate(self.bodies) if b.kind in ("rigid", "pivoted", "gyrostat")]
        q = np.asarray(result.q_WB, float)
        if not rigid or q.shape[0] == 0:
            return np.zeros(q.shape[0])
        return np.asarray(np.max(np.abs(np.linalg.norm(q[:, rigid], axis=2) - 1.0), axis=1))

    def measures(self, run: SceneStates, ref: SceneStates, quaternion_norm_error: np.ndarray) -> dict[str, float]:
        """The error measures of `run` against `ref` at the same times (module docstring); a run far beyond
        its stability limit, of states of 1e154 and more whose squares overflow, gets inf errors."""
        with np.errstate(over="ignore"):
            return scene_measures(self.bodies, self.horizon, run, ref, quaternion_norm_error)

    def fastest_rate(self) -> float:
        """rho [1/s]: the fastest body spin |w_B| or linear mode of the elements (rigiddyn.stability.scene_modes,
        sqrt|k| + gamma) at the initial states."""
        from .stability import scene_modes

        rates = [float(np.linalg.norm(s.w_B)) for s in self.initial if hasattr(s, "w_B")]
        rates += [abs(float(s.omega)) for s in self.initial if hasattr(s, "omega")]
        rates += [float(np.max(np.abs(s.v), initial=0.0)) for s in self.initial if type(s).__name__ == "JointState"]
        rates += pendulum_rates(self.scene)
        rates += [math.sqrt(abs(k)) + gamma for _, k, gamma in scene_modes(self.scene, self.initial)]
        return max(rates, default=0.0)

    def default_dts(self) -> list[float]:
        """Eight halvings from dt rho = 1 (rho: fastest_rate), or from horizon / 16 if that is shorter."""
        rho = max(self.fastest_rate(), 1e-300)
        dt0 = min(1.0 / rho, self.horizon / 16)
        return [dt0 / 2**j for j in range(8)]


def _swing_inertia(inertia_O: np.ndarray, c: np.ndarray) -> float:
    """The smallest moment of inertia about O [kg m^2] about an axis perpendicular to c (gravity at C
    has no torque about c itself): the smallest eigenvalue of I_O restricted to the plane normal to c."""
    u = c / np.linalg.norm(c)
    e1 = np.cross(u, np.eye(3)[int(np.argmin(np.abs(u)))])
    e1 /= np.linalg.norm(e1)
    plane = np.column_stack((e1, np.cross(u, e1)))
    return float(np.min(np.linalg.eigvalsh(plane.T @ inertia_O @ plane)))


def pendulum_rates(scene: Any) -> list[float]:
    """The small-oscillation rates sqrt(m |g| d / I) [rad/s] of the scene's pinned bodies under its
    uniform gravity (d = |p_OC_B|; I the smallest moment about O about an axis normal to p_OC_B: the
    fastest swing), each a linear mode the step choices must resolve, and sqrt(|g| / d) for each tree link
    whose centre of mass is d = |c_L| from its joint frame (an upper bound of its swing about its joint, whose
    moment is at least m d²); [] without pinned bodies or links."""
    g = sum((np.asarray(e.g_W, float) for e in scene.elements if type(e).__name__ == "UniformGravity"), np.zeros(3))
    rates = []
    for body in scene.bodies:
        kind = type(body).__name__
        if kind == "TreeLink" and np.any(body.com) and np.any(g):
            rates.append(math.sqrt(float(np.linalg.norm(g)) / float(np.linalg.norm(body.com))))
        c = np.asarray(body.p_OC_B, float) if kind.startswith("Pivoted") else np.zeros(1)
        if not np.any(c):
            continue  # unpinned, or pinned at its centre of mass: gravity has no torque
        if kind == "PivotedPlanarBody":
            inertia = float(body.inertia_O_zz)
        else:
            inertia = _swing_inertia(np.asarray(body.inertia_O, float), c)
        rates.append(math.sqrt(float(body.mass) * float(np.linalg.norm(g)) * float(np.linalg.norm(c)) / inertia))
    return rates


def _unit(q: np.ndarray) -> np.ndarray:
    """Each quaternion (last axis) of any norm made unit: divided by its largest absolute component first
    (a run blowing up may hold quaternions of 1e200, whose squares would overflow), then by its norm; a
    zero or non-finite one becomes nan."""
    largest = np.max(np.abs(q), axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        scaled = q / largest
        return np.asarray(scaled / np.linalg.norm(scaled, axis=-1, keepdims=True))


def attitude_angle(q_ref: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Geodesic angle [rad] between quaternions (x, y, z, w) along the last axis, shape (..., 4) -> (...),
    of any norm (rigiddyn.angular_distance of the unit ones: the angle does not change when a quaternion is
    scaled); nan where one is zero or not finite. The attitude_error of a problem and of a scene."""
    a, b = np.broadcast_arrays(_unit(np.asarray(q_ref, float)), _unit(np.asarray(q, float)))
    shape = a.shape[:-1]
    a, b = a.reshape(-1, 4), b.reshape(-1, 4)
    angle = np.full(a.shape[0], math.nan)
    valid = np.all(np.isfinite(a), axis=1) & np.all(np.isfinite(b), axis=1)
    if np.any(valid):
        angle[valid] = _core.angular_distance(a[valid], b[valid])
    return angle.reshape(shape)


def scene_measures(bodies: Sequence[BodyData], horizon: float, run: SceneStates, ref: SceneStates,
                   quaternion_norm_error: np.ndarray) -> dict[str, float]:
    """The error measures of `run` against `ref` (module docstring) for bodies of these masses and
    inertias over `horizon` [s]."""
    mass = np.array([b.mass for b in bodies])
    inertia = np.array([b.inertia_com for b in bodies]).reshape(len(bodies), 3, 3)
    h, h_ref = (np.einsum("bij,nbj->nbi", inertia, s.w_B) for s in (run, ref))  # I_b w_B per body
    h_scale = np.maximum(np.max(np.linalg.norm(h_ref, axis=2), axis=0), _TINY)  # (nb,)
    radius = float(np.max(np.sqrt(np.trace(inertia, axis1=1, axis2=2) / (2.0 * mass))))
    moved = float(np.max(np.linalg.norm(ref.p_W - ref.p_W[:1], axis=2)))
    length = max(radius, moved, _TINY)
    speed = max(float(np.max(np.linalg.norm(ref.v_W, axis=2))), length / horizon)
    series = {
        "attitude_error": np.max(attitude_angle(ref.q_WB, run.q_WB), axis=1),
        "momentum_error": np.max(np.linalg.norm(h - h_ref, axis=2) / h_scale, axis=1),
        "position_error": np.max(np.linalg.norm(run.p_W - ref.p_W, axis=2), axis=1),
        "velocity_error": np.max(np.linalg.norm(run.v_W - ref.v_W, axis=2), axis=1),
    }
    series["state_error"] = np.max([series["attitude_error"], series["momentum_error"],
                                    series["position_error"] / length, series["velocity_error"] / speed], axis=0)
    out = {}
    for name, values in series.items():
        out[f"final_{name}"], out[f"max_{name}"] = float(values[-1]), float(np.max(values))
    energy_scale = max(float(np.max(ref.kinetic_energy + np.abs(ref.potential_energy))), _TINY)
    out["energy_drift"] = float(np.max(np.abs(run.total_energy - ref.total_energy))) / energy_scale
    momentum_W = mass[None, :, None] * ref.v_W  # m_b v_b per body (n, nb, 3)
    p_scale = max(float(np.max(np.sum(np.linalg.norm(momentum_W, axis=2), axis=1))), _TINY)
    l_scale = max(float(np.max(np.sum(np.linalg.norm(np.cross(ref.p_W, momentum_W), axis=2)
                                      + np.linalg.norm(h_ref, axis=2), axis=1))), _TINY)
    out["momentum_drift"] = max(
        float(np.max(np.linalg.norm(run.linear_momentum_W - ref.linear_momentum_W, axis=1))) / p_scale,
        float(np.max(np.linalg.norm(run.angular_momentum_W - ref.angular_momentum_W, axis=1))) / l_scale)
    out["quaternion_norm_error"] = float(np.max(np.abs(quaternion_norm_error)))
    return out


# ---------------------------------------------------------------------------------------------
# exact references: scenes that are one of the closed forms' cases


@dataclass(frozen=True)
class ExactReference:
    """The closed form a scene is measured against: `name` (its rigiddyn class), `case` (the scene's
    case, in words) and `states(t)`, the exact SceneStates at the times t (n,) [s]."""

    name: str
    case: str
    states: Callable[[np.ndarray], Any]  # SceneStates (work_precision.states.States of a problem's)


def _rotation_z(theta: np.ndarray) -> np.ndarray:
    """q_WB (n, 4) (x, y, z, w) of the rotations by theta [rad] about z."""
    half = 0.5 * np.asarray(theta, float)
    zero = np.zeros_like(half)
    return np.column_stack((zero, zero, np.sin(half), np.cos(half)))


def _rotate(q: np.ndarray, x: np.ndarray) -> np.ndarray:
    """R(q) x row by row: q (n, 4) (x, y, z, w), x (n, 3) or (3,)."""
    u, w = q[:, :3], q[:, 3:]
    x = np.broadcast_to(x, u.shape)
    t = 2.0 * np.cross(u, x)
    return np.asarray(x + w * t + np.cross(u, t))


def _one_body_states(t: np.ndarray, body: BodyData, p: np.ndarray, q: np.ndarray, v: np.ndarray, w: np.ndarray,
                     potential: np.ndarray, mass: np.ndarray | None = None) -> SceneStates:
    """SceneStates of one body (centre of mass p_W, q_WB, v_W, w_B at the times t) with the totals as
    SceneResult defines them: T = m |v|^2 / 2 + w_B . I_C w_B / 2, V = `potential`, P = m v,
    L = p x m v + R I_C w_B (about the origin). `mass` (n,): the mass at each time (default constant)."""
    m = np.full(t.shape, body.mass) if mass is None else np.asarray(mass, float)
    h_B = w @ body.inertia_com.T
    kinetic = 0.5 * m * np.sum(v * v, axis=1) + 0.5 * np.sum(w * h_B, axis=1)
    momentum = m[:, None] * v
    return SceneStates(t, p[:, None], q[:, None], v[:, None], w[:, None], kinetic, potential, kinetic + potential,
                       momentum, np.cross(p, momentum) + _rotate(q, h_B))


def _vector_rows(values: Any, n: int, width: int) -> np.ndarray:
    """An array of n rows of `width` numbers (a (width,) vector repeated when n = 1 comes back flat)."""
    return np.asarray(values, float).reshape(n, width)


def _gravity(elements: Sequence[Any], classes: Sequence[str]) -> np.ndarray | None:
    """g_W [m/s^2] of a scene whose elements, on its one body, are at most one UniformGravity and one of
    each of `classes` (the zero vector without gravity); None for any other element list."""
    names = [type(e).__name__ for e in elements]
    if any(n not in ("UniformGravity", *classes) for n in names) or len(set(names)) != len(names):
        return None
    if any(getattr(e, "bodies", None) not in (None, [0]) for e in elements):
        return None
    gravity = [e for e in elements if type(e).__name__ == "UniformGravity"]
    return np.asarray(gravity[0].g_W, float) if gravity else np.zeros(3)


def _pendulum(body: Any, state: Any, g_W: np.ndarray) -> ExactReference:
    """A pivoted planar body under uniform gravity: rigiddyn.CompoundPendulumSolution."""
    g_plane = np.array([g_W[0], g_W[1], 0.0])  # the plane takes g's z part (and it does no work: z = 0)
    solution = _core.CompoundPendulumSolution(body, g_plane, state)
    data = _body_data(body)
    c, o = np.append(np.asarray(body.p_OC_B, float), 0.0), np.append(np.asarray(body.p_WO, float), 0.0)

    def states(t: np.ndarray) -> SceneStates:
        t = np.asarray(t, float)
        theta, omega = (np.asarray(x, float).reshape(t.shape) for x in solution.at(t))
        q = _rotation_z(theta)
        r = _rotate(q, c)  # C - O in W
        w = np.column_stack((np.zeros_like(omega), np.zeros_like(omega), omega))
        p, v = o + r, np.cross(w, r)
        return _one_body_states(t, data, p, q, v, w, -data.mass * (p @ g_plane))

    return ExactReference("CompoundPendulumSolution", "one pivoted planar body under uniform gravity", states)


def _top(body: Any, state: Any, g_W: np.ndarray) -> ExactReference:
    """A symmetric pivoted body, its centre of mass on its axis, under uniform gravity: rigiddyn.LagrangeTopSolution."""
    solution = _core.LagrangeTopSolution(body, g_W, state)
    data = _body_data(body)
    c, o = np.asarray(body.p_OC_B, float), np.asarray(body.p_WO, float)

    def states(t: np.ndarray) -> SceneStates:
        t = np.asarray(t, float)
        q_WB, w_B = solution.at(t)
        q, w = _vector_rows(q_WB, t.size, 4), _vector_rows(w_B, t.size, 3)
        p, v = o + _rotate(q, c), _rotate(q, np.cross(w, c))  # p_WC = p_WO + R c, v = R (w x c)
        return _one_body_states(t, data, p, q, v, w, -data.mass * (p @ g_W))

    return ExactReference("LagrangeTopSolution", "one symmetric pivoted body, centre of mass on its axis, under "
                          "uniform gravity", states)


def _rocket(body: Any, flow: Any, thrust: Any, state: Any, g_W: np.ndarray) -> ExactReference:
    """A particle with a constant mass rate, one thrust along a fixed direction, uniform gravity:
    rigiddyn.ConstantThrustSolution."""
    solution = _core.ConstantThrustSolution(float(body.mass), float(flow.rate), np.asarray(thrust.u_rel, float), g_W,
                                            np.asarray(state.p_W, float), np.asarray(state.v_W, float))
    data = _body_data(body)

    def states(t: np.ndarray) -> SceneStates:
        t = np.asarray(t, float)
        p_W, v_W = solution.at(t)[:2]
        p, v = _vector_rows(p_W, t.size, 3), _vector_rows(v_W, t.size, 3)
        mass = body.mass + flow.rate * t  # m(t) = m0 + (dm/dt) t
        q = np.tile([0.0, 0.0, 0.0, 1.0], (t.size, 1))
        return _one_body_states(t, data, p, q, v, np.zeros_like(v), -mass * (p @ g_W), mass)

    return ExactReference("ConstantThrustSolution", "one particle with a constant mass rate, one thrust along a "
                          "fixed direction, uniform gravity", states)


def _rotating(scene: Any, initial: Sequence[Any], axis: np.ndarray, rate: float) -> ExactReference:
    """Free particles seen from a frame turning at a constant rate about `axis` [rad/s]:
    rigiddyn.RotatingFrameFreeParticle."""
    solutions = [_core.RotatingFrameFreeParticle(scene.frame, s.p_W, s.v_W) for s in initial]
    bodies = [_body_data(b) for b in scene.bodies]
    omega = rate * axis / np.linalg.norm(axis)

    def states(t: np.ndarray) -> SceneStates:
        t = np.asarray(t, float)
        parts = []
        for solution, body in zip(solutions, bodies):
            p_F, v_F = solution.at(t)[:2]
            p, v = _vector_rows(p_F, t.size, 3), _vector_rows(v_F, t.size, 3)
            q = np.tile([0.0, 0.0, 0.0, 1.0], (t.size, 1))
            # the centrifugal potential -m |Omega x r|^2 / 2 (total energy: the Jacobi integral)
            centrifugal = -0.5 * body.mass * np.sum(np.cross(omega, p) ** 2, axis=1)
            parts.append(_one_body_states(t, body, p, q, v, np.zeros_like(v), centrifugal))
        return SceneStates(t, *(np.concatenate([getattr(s, k) for s in parts], axis=1)
                                for k in ("p_W", "q_WB", "v_W", "w_B")),
                           *(np.sum([getattr(s, k) for s in parts], axis=0) for k in (
                               "kinetic_energy", "potential_energy", "total_energy", "linear_momentum_W",
                               "angular_momentum_W")))

    return ExactReference("RotatingFrameFreeParticle", "free particles in a frame turning at a constant rate", states)


def exact_reference(scene: Any, initial: Sequence[Any]) -> ExactReference | None:
    """The closed form `scene` (with its `initial` states) is a case of, None if none:
    - one pivoted planar body under uniform gravity (or none): CompoundPendulumSolution;
    - one pivoted body, symmetric about the line through its pivot and centre of mass, under uniform
      gravity: LagrangeTopSolution (the class refuses an unsymmetric body: then None);
    - one particle with a constant mass rate, one Thrust (a particle does not turn: its direction is
      fixed in W) and at most uniform gravity: ConstantThrustSolution;
    - particles without elements in a frame turning at a constant rate about a fixed origin:
      RotatingFrameFreeParticle.
    Each in an inertial scene without mass flows unless named."""
    from .scene_describe import frame_rotation

    bodies, elements = list(scene.bodies), list(scene.elements)
    frame = getattr(scene, "frame", None)
    flows = [f for f in (getattr(scene, "mass_flows", None) or []) if f is not None]
    kinds = [type(b).__name__ for b in bodies]
    if frame is not None:  # F = W at t = 0, turning about its origin: SceneFrame.rotating or .earth
        rotation = frame_rotation(frame)
        if frame.__getstate__()[0] not in ("rotating", "earth") or rotation is None or flows or elements \
                or set(kinds) != {"Particle"}:
            return None
        return _rotating(scene, initial, *rotation)
    if len(bodies) != 1:
        return None
    kind, body, state = kinds[0], bodies[0], initial[0]
    if kind == "Particle" and len(flows) == 1 and not callable(flows[0].rate):
        g_W = _gravity(elements, ["Thrust"])
        thrusts = [e for e in elements if type(e).__name__ == "Thrust"]
        if g_W is None or not thrusts:
            return None
        return _rocket(body, flows[0], thrusts[0], state, g_W)
    g_W = _gravity(elements, [])
    if flows or g_W is None:
        return None
    try:
        if kind == "PivotedPlanarBody":
            return _pendulum(body, state, g_W)
        if kind == "PivotedBody" and elements:
            return _top(body, state, g_W)
    except ValueError:  # not the closed form's case (e.g. an unsymmetric top)
        return None
    return None


# ---------------------------------------------------------------------------------------------
# what tradeoff accepts as a scene


def _is_scene(x: Any) -> bool:
    scene_type = getattr(_core, "Scene", None)
    return scene_type is not None and isinstance(x, scene_type)


def scene_case(source: Any, initial: Any = None, horizon: float | None = None) -> SceneCase | None:
    """The SceneCase of `source`: a SceneCase, a rigiddyn.Scene (with `initial`, one state per body),
    the SceneFile rigiddyn.load_scene returns (or its unpacked tuple (scene, initial, run)), or a scene file path /
    shipped scene name; None if `source` is none of these (a problem: a Problem, whose tradeoff has its closed-form
    references). The horizon [s]: `horizon`, else the [run] duration of the file."""
    if isinstance(source, SceneCase):
        return source
    options: Any = None
    if _is_scene(source):
        scene, name = source, "scene"
        if initial is None:
            raise ValueError("initial: expected the initial states of the scene's bodies (one per body), got None")
    elif type(source) is SceneFile:
        scene, options, name = source.scene, source.run, source.name
        initial = source.initial if initial is None else initial
    elif isinstance(source, tuple) and len(source) == 3 and _is_scene(source[0]):
        scene, initial, options = (source[0], source[1] if initial is None else initial, source[2])
        name = "scene"
    elif is_scene_source(source):
        from .scene_file import read_scene

        read = read_scene(source)
        scene, options, name = read.scene, read.run, read.name
        initial = read.initial if initial is None else initial
    else:
        return None
    names = ("ParticleState", "PlanarBodyState", "RigidBodyState", "PivotedBodyState", "PivotedPlanarBodyState",
             "GyrostatState", "JointState")
    kinds = tuple(getattr(_core, n) for n in names if hasattr(_core, n))
    expected = f"a list of initial states ({', '.join(names)}), one per body ({len(scene.bodies)})"
    if isinstance(initial, (str, bytes)) or not isinstance(initial, Iterable):
        raise TypeError(f"initial: expected {expected}, got {initial!r}")
    initial = list(initial)
    if len(initial) != len(scene.bodies) or not all(isinstance(s, kinds) for s in initial):
        raise ValueError(f"initial: expected {expected}, got {initial!r}")
    defaults = _option(options, "tradeoff")
    defaults = dict(defaults) if isinstance(defaults, Mapping) else {}
    span = horizon if horizon is not None else defaults.pop("horizon", None) or _option(options, "duration")
    if span is None:
        raise ValueError("horizon: expected a finite number > 0 [s] (the scene file's [tradeoff] horizon or [run] "
                         "duration gives none), got None")
    if isinstance(span, bool) or not isinstance(span, (int, float, np.integer, np.floating)):
        raise TypeError(f"horizon: expected a finite number > 0 [s], got {span!r}")
    if not (math.isfinite(span) and span > 0):
        raise ValueError(f"horizon: expected a finite number > 0 [s], got {span!r}")
    defaults.pop("horizon", None)
    return SceneCase(name, scene, initial, float(span), defaults)
