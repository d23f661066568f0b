"""describe(scene, method=None): a scene as a text table of bodies x active terms x frame x method x units.

``Scene.describe(method=None)`` and ``CompiledScene.describe()`` call this (attached when rigiddyn is
imported). The text has four parts:

- a header: counts, the scene frame (W, inertial; or F, its motion relative to the inertial W), the units;
- Bodies: index, name, kind, mass [kg], inertia [kg m^2] about the centre of mass in B, state variables;
  then, for bodies pinned at a point O (pivoted kinds), the pivot O, the centre of mass relative to it,
  the inertia about O (parallel-axis theorem) and the decimal digits of I_C it loses; and the bodies
  whose mass changes (rate, inertia rule) and the wheels of gyrostats (axis, inertia, motor torque);
- Force elements: index, type, parameters in SI with their units and frames, properties (potential,
  velocity- or time-dependent), and one column per body naming the terms it puts on that body
  (``f`` a force, ``tau`` a torque, ``f+tau`` both, ``.`` none): a declared element acts only where marked,
  and a compiled model evaluates nothing else; in a moving frame, the fictitious terms compile adds
  (frame.origin, frame.euler, frame.centrifugal, frame.coriolis: those not identically zero) follow
  the user's elements, numbered as in the result's work and power columns;
- Method (when one is given or the scene is compiled): order, evaluations per step, what it conserves,
  and the compile's verdict (accepted, its compatibility warnings, or the refusal with its reason).
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np

from . import _core
from ._names import require_method

__all__ = ["describe"]

_UNITS = ("Units: SI (m, kg, s, N, N m, J, rad); p_W [m] and v_W [m/s] in W; q_WB (x, y, z, w) maps B to W; "
          "w_B [rad/s] in B; inertia about the centre of mass in B")
_FRAME = "Frame: W, inertial (fixed)"
_STATE = {"particle": "p_W, v_W (6)", "planar": "x, y, theta, vx, vy, omega (6)", "rigid": "p_W, q_WB, v_W, w_B (13)",
          "pivoted": "q_WB, w_B (7)", "pivoted_planar": "theta, omega (2)",
          "gyrostat": "p_W, q_WB, v_W, w_B, per wheel speed and motor work (13 + 2 nw)",
          "tree_link": "its joint's q, v (a JointState)"}
_KIND = {"Particle": "particle", "PlanarBody": "planar", "RigidBody": "rigid", "PivotedBody": "pivoted",
         "PivotedPlanarBody": "pivoted_planar", "Gyrostat": "gyrostat", "TreeLink": "tree_link"}
# the fictitious terms compile adds for a moving frame: (name, class in SceneResult.elements, force)
_FICTITIOUS = (("frame.origin", "FrameOriginForce", "-m a_O"), ("frame.euler", "EulerForce", "-m alpha x r"),
               ("frame.centrifugal", "CentrifugalForce", "-m Omega x (Omega x r)"),
               ("frame.coriolis", "CoriolisForce", "-2 m Omega x v_rel"))


def _kind(body: Any) -> str:
    return _KIND[type(body).__name__]


def frame_rotation(frame: Any) -> tuple[np.ndarray, float] | None:
    """(axis in F, rate [rad/s]) of a SceneFrame turning at a constant rate about a fixed origin
    (SceneFrame.rotating, .earth, or .moving of a FrameMotion.constant_rotation; a FrameMotion.fixed
    placement: rate 0), None for another motion."""
    try:
        state = frame.motion.__getstate__()
    except (AttributeError, TypeError, ValueError):
        return None
    if state[0] == "fixed":
        return np.array([0.0, 0.0, 1.0]), 0.0
    if state[0] != "constant_rotation":
        return None
    _, axis_W, rate, R_WF0, _ = state
    return np.asarray(R_WF0, dtype=np.float64).T @ np.asarray(axis_W, dtype=np.float64), float(rate)  # axis fixed in F


def frame_terms_of(frame: Any) -> list[str]:
    """The names of the fictitious terms compile adds for `frame` (None: none), SceneFrame.terms as
    'frame.<term>': a constant rotation about a fixed origin adds frame.centrifugal and frame.coriolis (none at
    rate 0); a general motion every term, or those SceneFrame.moving(..., terms=...) declares."""
    if frame is None:
        return []
    return [f"frame.{term}" for term in frame.terms]


def _frame_line(frame: Any) -> str:
    """The header's frame line: W, or F and its motion relative to the inertial W."""
    if frame is None:
        return _FRAME
    rotation = frame_rotation(frame)
    if rotation is None:
        return ("Frame: F, moving relative to the inertial W (a general SceneFrame.moving: angular velocity, "
                "angular acceleration and origin acceleration from its FrameMotion; terms that act: "
                f"{', '.join(frame.terms) or 'none'}); states relative to F")
    axis, rate = rotation
    u = axis / np.linalg.norm(axis)
    state = frame.__getstate__()  # ("earth", latitude) for SceneFrame.earth
    earth = (f" = SceneFrame.earth at latitude {np.degrees(state[1]):.6g} deg (x east, y north, z up)"
             if state[0] == "earth" else "")
    return (f"Frame: F{earth}, rotating relative to the inertial W at Omega = {rate:.6g} rad/s about {_g(u)} "
            "(in F) through its origin; states relative to F")


def _g(x: Any) -> str:
    """A number or vector in short form: 9.81, (0, 0, -9.81)."""
    a = np.asarray(x, dtype=np.float64)
    return f"{float(a):.6g}" if a.ndim == 0 else "(" + ", ".join(f"{v:.6g}" for v in a.ravel()) + ")"


def _inertia(body: Any, kind: str) -> str:
    if kind == "particle":
        return "-"
    if kind in ("planar", "pivoted_planar"):
        return f"I_zz {_g(body.inertia_zz)}"
    return _matrix(body.inertia_com)


def _matrix(inertia: Any) -> str:
    """An inertia matrix: diag(...) when diagonal, else its rows."""
    inertia = np.asarray(inertia, dtype=np.float64)
    if not np.any(inertia - np.diag(np.diag(inertia))):
        return "diag" + _g(np.diag(inertia))
    return "[" + "; ".join(_g(row)[1:-1] for row in inertia) + "]"


def _pivot_lines(bodies: Sequence[Any], names: Sequence[str], kinds: Sequence[str]) -> list[str]:
    """The pinned bodies: pivot O, centre of mass relative to O, inertia about O, digits of I_C lost."""
    rows = []
    for i, (b, kind) in enumerate(zip(bodies, kinds)):
        if kind == "pivoted":
            lost = float(b.digits_lost)
            rows.append((str(i), names[i], _g(b.p_WO), _g(b.p_OC_B), _matrix(b.inertia_O),
                         f"{lost:.2g}" + (" (WARNING: > 6)" if lost > 6 else "")))
        elif kind == "pivoted_planar":
            rows.append((str(i), names[i], _g(b.p_WO), _g(b.p_OC_B), f"I_zz {_g(b.inertia_O_zz)}", "-"))
    if not rows:
        return []
    return (["", "Pivots (Euler's equations about O fixed in the scene frame; the reaction at O from Newton's law "
             "for C)"]
            + _table(("#", "name", "O: p_WO [m]", "C - O: p_OC_B [m] (B)", "inertia about O [kg m^2] (B)",
                      "digits of I_C lost"), rows))


def _tree_lines(bodies: Sequence[Any], names: Sequence[str], kinds: Sequence[str]) -> list[str]:
    """The trees' links: each link's index in its tree and the body of its parent link (W for the tree's root)."""
    rows = []
    for i, (b, kind) in enumerate(zip(bodies, kinds)):
        if kind == "tree_link":
            parent = b.tree.parents[b.link]
            rows.append((str(i), names[i], str(b.link), "W" if parent < 0 else names[i - b.link + parent]))
    if not rows:
        return []
    return (["", "Tree links (bodies joined by their trees' joints; the state of each is its joint's)"]
            + _table(("#", "name", "link", "parent"), rows))


def _wheel_lines(bodies: Sequence[Any], names: Sequence[str], kinds: Sequence[str]) -> list[str]:
    """The gyrostats' wheels: axis in B, axial inertia, motor torque and its window."""
    rows = [(str(i), names[i], str(k), _g(w.axis_B), _g(w.inertia), _g(w.motor_torque), f"[{_g(w.t_start)}, {_g(w.t_end)})")
            for i, (b, kind) in enumerate(zip(bodies, kinds)) if kind == "gyrostat" for k, w in enumerate(b.wheels)]
    if not rows:
        return []
    return (["", "Wheels (each gyrostat's, spun by its motor; the body feels the reaction; I above is the whole "
             "body's with its wheels locked)"]
            + _table(("#", "body", "wheel", "axis_B (B)", "inertia [kg m^2]", "motor torque [N m]", "for t in [s]"),
                     rows))


def _mass_flow_lines(scene: Any, names: Sequence[str]) -> list[str]:
    """The bodies whose mass changes: rate [kg/s] and inertia rule."""
    flows = list(getattr(scene, "mass_flows", []) or [])
    rows = []
    for i, flow in enumerate(flows):
        if flow is None:
            continue
        rate = "a function of t" if callable(flow.rate) else f"{_g(flow.rate)} kg/s"
        rule = ("I_C = I_C0 m / m0" if flow.inertia_rule == "scaled" else "I_C = a function of m")
        if isinstance(scene.bodies[i], _core.Particle):
            rule = "- (a particle)"
        rows.append((str(i), names[i], rate, rule))
    if not rows:
        return []
    return (["", "Mass flows (the mass is one more state; the ejected mass carries its own angular momentum: "
             "no jet damping)"] + _table(("#", "name", "dm/dt", "inertia rule"), rows))


def _acts_on(element: Any, nb: int) -> list[int]:
    """The indices of the bodies `element` acts on, from its class's field table: a `bodies` field (None:
    every body) and its body fields (an optional one when given)."""
    acting: list[int] = []
    for f in type(element).fields:
        value = getattr(element, f.key)
        if f.kind == "bodies":
            acting += range(nb) if value is None else value
        elif f.kind in ("body", "optional_body") and value is not None:
            acting.append(value)
    return acting


def _terms(traits: dict[str, bool] | None, kind: str) -> str:
    """The terms an element with `traits` (CompiledScene.element_traits) puts on a body of `kind` it acts on:
    "f", "tau", "f+tau" or "." (a particle feels no torque, and nothing from an element that needs an
    attitude)."""
    if traits is None:
        return "f+tau" if kind != "particle" else "f"
    if kind == "particle" and traits["needs_attitude"]:
        return "."
    force, torque = traits["has_force"], traits["has_torque"] and kind != "particle"
    return "+".join(t for t, on in (("f", force), ("tau", torque)) if on) or "."


def _fictitious_terms(kind: str) -> str:
    """The terms a fictitious force of the frame puts on a body of `kind` (a torque on bodies with an
    attitude: Euler's equations relative to F)."""
    return "f" if kind == "particle" else "f+tau"


def _parameters(element: Any, names: Sequence[str]) -> str:
    """The element's parameters in SI with their units, from its class's field table (``fields``); the
    bodies it acts on are the columns, not repeated here."""
    parts = []
    for f in type(element).fields:
        value = getattr(element, f.key)
        unit = f" {f.unit.replace('*', ' ')}" if f.unit and f.unit != "1" else ""  # as messages write it
        if f.kind in ("scalar", "vector"):
            parts.append(f"{f.key} = {_g(value)}{unit}")
        elif f.kind == "array" and len(value):  # empty: not used
            parts.append(f"{f.key} = {_g(value)}{unit}")
        elif f.kind in ("body", "optional_body"):
            parts.append(f"{f.key} = {'none' if value is None else names[value]}")
        elif f.kind == "frame":
            parts.append(f"{f.key} = {value}")
        elif f.kind == "loads":
            frames = sorted({str(load.frame) for load in value}) or ["-"]
            parts.append(f"{len(value)} piecewise-constant loads (force N, torque N m in {' and '.join(frames)})")
        elif f.kind == "callable":
            parts.append(f"{f.key} = a Python callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W N, tau_B N m); holds the GIL")
    return ", ".join(parts)


def _properties(traits: dict[str, bool] | None) -> str:
    """What the compiled term depends on and provides (CompiledScene.element_traits)."""
    if traits is None:
        return "-"
    props = [name for name, on in (("potential", traits["has_potential"]),
                                   ("velocity-dependent", traits["velocity_dependent"]),
                                   ("time-dependent", traits["time_dependent"]),
                                   ("internal", traits["zero_net_wrench"])) if on]
    return ", ".join(props) or "-"


def _element_traits(scene: Any, compiled: Any | None) -> list[dict[str, bool] | None]:
    """Each element's traits, from `compiled` or a compile for rk4 (None each where the scene does not compile)."""
    if compiled is None:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                compiled = scene.compile("rk4")
        except ValueError:
            return [None] * len(scene.elements)
    return list(compiled.element_traits)


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> list[str]:
    """Rows aligned under the header, columns two spaces apart."""
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    return ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in [header, *rows]]


def _method_lines(scene: Any, method: str, compiled: Any | None) -> list[str]:
    require_method(method)
    info = next(m for m in _core.methods() if m["name"] == method)
    lines = [f"Method: {method} (order {info['order']}, {info['evaluations']} evaluations per step; conserves "
             f"{info['conserves']})"]
    if compiled is None:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                compiled = scene.compile(method)
        except ValueError as e:
            return lines + [f"  refused: {e}"]
    found = list(getattr(compiled, "warnings", ()))
    return lines + ([f"  warning: {w}" for w in found] or ["  accepted: no compatibility warning"])


def _count(n: int, one: str, many: str) -> str:
    """'1 body', '3 bodies': n with the noun in its number."""
    return f"{n} {one if n == 1 else many}"


def describe(scene: Any, method: str | None = None) -> str:
    """A text table of `scene` (a Scene, or a CompiledScene: its scene and method): bodies (kind, mass
    [kg], inertia [kg m^2] in B, state), force elements (parameters in SI with frames, properties, the
    terms on each body), the frame, the units and, with `method` (a name of rigiddyn.methods()), its
    order and the compile's verdict for this scene (warnings or the refusal)."""
    compiled = None
    if isinstance(scene, _core.CompiledScene):
        if method is not None and method != scene.method:
            raise ValueError(f"method: expected None or the compiled method {scene.method!r}, got {method!r}")
        compiled, method, scene = scene, scene.method, scene.scene
    if not isinstance(scene, _core.Scene):
        raise TypeError(f"scene: expected a Scene or CompiledScene, got {type(scene).__name__}")
    if method is not None and not isinstance(method, str):
        raise TypeError(f"method: expected None or a method name (str), got {type(method).__name__}")
    bodies, names, elements = list(scene.bodies), list(scene.body_names), list(scene.elements)
    kinds = [_kind(b) for b in bodies]
    frame = getattr(scene, "frame", None)
    units = _UNITS if frame is None else _UNITS.replace(" in W;", " in F (the scene frame: 'W' in names);").replace(
        "maps B to W", "maps B to F")
    lines = [f"Scene: {_count(len(bodies), 'body', 'bodies')}, {_count(len(elements), 'force element', 'force elements')}",
             _frame_line(frame), units, "", "Bodies"]
    flows = list(getattr(scene, "mass_flows", []) or [None] * len(bodies))
    lines += _table(("#", "name", "kind", "mass [kg]", "inertia [kg m^2] (B)", "state"),
                    [(str(i), names[i], kinds[i], _g(b.mass), _inertia(b, kinds[i]),
                      _STATE[kinds[i]] + ("" if flows[i] is None else " + m (1)")) for i, b in enumerate(bodies)])
    lines += (_pivot_lines(bodies, names, kinds) + _tree_lines(bodies, names, kinds) + _wheel_lines(bodies, names, kinds)
              + _mass_flow_lines(scene, names))
    lines += ["", "Force elements (terms per body: f force, tau torque, . none)"]
    rows = []
    traits = _element_traits(scene, compiled)
    for i, e in enumerate(elements):
        acting = set(_acts_on(e, len(bodies)))
        rows.append((str(i), type(e).__name__, _properties(traits[i]),
                     *[_terms(traits[i], kinds[b]) if b in acting else "." for b in range(len(bodies))],
                     _parameters(e, names)))
    fictitious = {name: (cls, force) for name, cls, force in _FICTITIOUS}
    for j, name in enumerate(frame_terms_of(frame)):
        cls, force = fictitious[name]
        rows.append((str(len(elements) + j), f"{cls} ({name})", "fictitious, of the frame",
                     *[_fictitious_terms(kinds[b]) for b in range(len(bodies))], f"f = {force} on every body"))
    if rows:
        lines += _table(("#", "element", "properties", *names, "parameters (SI)"), rows)
    else:
        lines.append("  none: free bodies")
    if method is not None:
        lines += [""] + _method_lines(scene, method, compiled)
    return "\n".join(lines) + "\n"


def _attach() -> None:
    """Scene.describe(method=None) and CompiledScene.describe() as methods (when the core has them)."""
    scene_cls, compiled_cls = getattr(_core, "Scene", None), getattr(_core, "CompiledScene", None)
    if scene_cls is not None and not hasattr(scene_cls, "describe"):
        def scene_describe(self: Any, method: str | None = None) -> str:
            return describe(self, method)

        scene_describe.__doc__ = describe.__doc__
        scene_cls.describe = scene_describe
    if compiled_cls is not None and not hasattr(compiled_cls, "describe"):
        def compiled_describe(self: Any) -> str:
            return describe(self)

        compiled_describe.__doc__ = describe.__doc__
        compiled_cls.describe = compiled_describe


_attach()
