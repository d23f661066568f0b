"""describe(scene, method=None): a scene as a text table of bodies x active terms x frame x method x units.

``Scene.describe(method=None)`` and ``CompiledScene.describe()`` call this (attached when rigiddyn is
imported). The text has four parts:

- a header: counts, the reference frame (W, inertial: moving frames come with a later issue), the units;
- Bodies: index, name, kind, mass [kg], inertia [kg m^2] about the centre of mass in B, state variables;
- Force elements: index, type, parameters in SI with their units and frames, properties (potential,
  velocity- or time-dependent), and one column per body naming the terms it puts on that body
  (``f`` a force, ``tau`` a torque, ``f+tau`` both, ``.`` none): a declared element acts only where marked,
  and a compiled model evaluates nothing else;
- Method (when one is given or the scene is compiled): order, evaluations per step, what it conserves,
  and the compile's verdict (accepted, its compatibility warnings, or the refusal with its reason).
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import Any

import numpy as np

from . import _core

__all__ = ["describe"]

_UNITS = ("Units: SI (m, kg, s, N, N m, J, rad); p_W [m] and v_W [m/s] in W; q_WB (x, y, z, w) maps B to W; "
          "w_B [rad/s] in B; inertia about the centre of mass in B")
_FRAME = "Frame: W, inertial (fixed)"
_STATE = {"particle": "p_W, v_W (6)", "planar": "x, y, theta, vx, vy, omega (6)", "rigid": "p_W, q_WB, v_W, w_B (13)"}


def _kind(body: Any) -> str:
    if isinstance(body, _core.Particle):
        return "particle"
    return "planar" if isinstance(body, _core.PlanarBody) else "rigid"


def _g(x: Any) -> str:
    """A number or vector in short form: 9.81, (0, 0, -9.81)."""
    a = np.asarray(x, dtype=np.float64)
    return f"{float(a):.6g}" if a.ndim == 0 else "(" + ", ".join(f"{v:.6g}" for v in a.ravel()) + ")"


def _inertia(body: Any, kind: str) -> str:
    if kind == "particle":
        return "-"
    if kind == "planar":
        return f"I_zz {_g(body.inertia_zz)}"
    inertia = np.asarray(body.inertia_com, dtype=np.float64)
    if not np.any(inertia - np.diag(np.diag(inertia))):
        return "diag" + _g(np.diag(inertia))
    return "[" + "; ".join(_g(row)[1:-1] for row in inertia) + "]"


def _acts_on(element: Any, nb: int) -> list[int]:
    """The indices of the bodies `element` acts on."""
    if hasattr(element, "bodies"):
        return list(range(nb)) if element.bodies is None else list(element.bodies)
    if hasattr(element, "body_a"):
        return [element.body_a] + ([] if element.body_b is None else [element.body_b])
    return [element.body]


def _terms(element: Any, body: int, kind: str) -> str:
    """The terms `element` puts on body number `body` of kind `kind`: "f", "tau", "f+tau" or "."."""
    cls = type(element).__name__
    force, torque = True, kind != "particle"
    if cls in ("UniformGravity", "PointMassGravity", "MutualGravity"):
        torque = False
    elif cls == "GravityGradient":
        force = torque  # the second-order term needs an extent (I = 0 for a particle)
    elif cls == "SpringDamper":
        point = element.point_a_B if body == element.body_a else element.point_b
        torque = torque and bool(np.any(np.asarray(point)))
    elif cls == "Drag":
        force = element.linear > 0 or element.quadratic > 0
        torque = torque and (element.angular_linear > 0 or element.angular_quadratic > 0)
    elif cls == "ScheduledLoads":
        force = any(np.any(np.asarray(load.force)) for load in element.loads)
        torque = torque and (any(np.any(np.asarray(load.torque)) for load in element.loads)
                             or (force and bool(np.any(np.asarray(element.point_B)))))
    return "+".join(t for t, on in (("f", force), ("tau", torque)) if on) or "."


def _parameters(element: Any, names: Sequence[str]) -> str:
    """The element's parameters in SI with units and frames."""
    cls = type(element).__name__
    if cls == "UniformGravity":
        return f"g_W = {_g(element.g_W)} m/s^2 in W"
    if cls == "PointMassGravity":
        return f"gm = {_g(element.gm)} m^3/s^2 at p_W = {_g(element.p_W)} m in W, softening {_g(element.softening)} m"
    if cls == "MutualGravity":
        return f"G = {_g(element.G)} m^3/(kg s^2), softening {_g(element.softening)} m, pairs i < j"
    if cls == "GravityGradient":
        return f"gm = {_g(element.gm)} m^3/s^2 at p_W = {_g(element.p_W)} m in W"
    if cls == "SpringDamper":
        a = _end(names[element.body_a], element.point_a_B)
        b = f"the world anchor {_g(element.point_b)} m in W" if element.body_b is None else \
            _end(names[element.body_b], element.point_b)
        return (f"{a} to {b}; k = {_g(element.stiffness)} N/m, l0 = {_g(element.rest_length)} m, "
                f"c = {_g(element.damping)} N s/m")
    if cls == "Drag":
        return (f"linear {_g(element.linear)} N s/m, quadratic {_g(element.quadratic)} N s^2/m^2, angular "
                f"{_g(element.angular_linear)} N m s/rad, {_g(element.angular_quadratic)} N m s^2/rad^2")
    if cls == "ScheduledLoads":
        frames = sorted({str(load.frame) for load in element.loads}) or ["-"]
        return (f"{len(element.loads)} piecewise-constant loads (force N, torque N m in {' and '.join(frames)}) "
                f"at point_B = {_g(element.point_B)} m")
    return "a Python callable fn(t, body, p_W, q_WB, v_W, w_B) -> (f_W N, tau_B N m); holds the GIL"


def _end(name: str, point: Any) -> str:
    """A spring end: a body's centre of mass, or a point of it in its frame B."""
    return f"{name}'s centre of mass" if not np.any(np.asarray(point)) else f"{name} at {_g(point)} m in its B"


def _properties(element: Any) -> str:
    cls = type(element).__name__
    props = []
    if cls in ("UniformGravity", "PointMassGravity", "MutualGravity", "GravityGradient", "SpringDamper"):
        props.append("potential")
    if cls == "Drag" or cls == "PythonForce" or (cls == "SpringDamper" and element.damping > 0):
        props.append("velocity-dependent")
    if cls in ("ScheduledLoads", "PythonForce"):
        props.append("time-dependent")
    return ", ".join(props) or "-"


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> list[str]:
    """Rows aligned under the header, columns two spaces apart."""
    widths = [max(len(r[i]) for r in [header, *rows]) for i in range(len(header))]
    return ["  " + "  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in [header, *rows]]


def _method_lines(scene: Any, method: str, compiled: Any | None) -> list[str]:
    info = next((m for m in _core.methods() if m["name"] == method), None)
    if info is None:
        raise ValueError(f"method: expected one of {', '.join(m['name'] for m in _core.methods())}, got {method!r}")
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
    lines = [f"Scene: {len(bodies)} bodies, {len(elements)} force elements", _FRAME, _UNITS, "", "Bodies"]
    lines += _table(("#", "name", "kind", "mass [kg]", "inertia [kg m^2] (B)", "state"),
                    [(str(i), names[i], kinds[i], _g(b.mass), _inertia(b, kinds[i]), _STATE[kinds[i]])
                     for i, b in enumerate(bodies)])
    lines += ["", "Force elements (terms per body: f force, tau torque, . none)"]
    if elements:
        rows = []
        for i, e in enumerate(elements):
            acting = set(_acts_on(e, len(bodies)))
            rows.append((str(i), type(e).__name__, _properties(e),
                         *[_terms(e, b, kinds[b]) if b in acting else "." for b in range(len(bodies))],
                         _parameters(e, names)))
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
