"""A scene file's [controller] table: a rigiddyn.Controller running a shipped law (rigiddyn.control's BDot or
PDAttitude), read and written with units, as the rest of the file::

    [controller]                        # optional: the run's digital controller (docs/guide/spacecraft.md)
    period = "1 s"                      # [s] > 0: the law's sample period
    law = "bdot"                        # "bdot": B-dot detumbling on a magnetorquer:
    gain = "2e4 A*m^2*s/T"              #   k [A m^2 s/T] > 0
    element = 1                         #   the index of its magnetic_dipole among the [[force]] tables, from 0
    # m_max = "0.2 A*m^2"               #   saturation of each component [A m^2] (default: none)
    # rate = "gyro"                     #   "gyro" (default) | "difference"
    # law = "pd_attitude"               # or PD pointing with a gyrostat's reaction wheels:
    # k_p = "1e-5 N*m/rad"              #   [N m/rad] > 0
    # k_d = "1.5e-4 N*m*s/rad"          #   [N m s/rad] > 0
    # target = "lvlh"                   #   "lvlh" | a quaternion [x, y, z, w] (default [0, 0, 0, 1])
    # axes_B = [[1, 0, 0], ...]         #   the wheels' axes in B (default: the body's [[body.wheels]] axes)
    body = "cubesat"                    # the body (a name; default the first body)
    w_B_noise = "0.01 deg/s"            # optional gyro noise [rad/s] >= 0 (default 0)
    seed = 1                            # optional integer >= 0: the noise's numpy.random.default_rng(seed)

A law given in Python (a function) has no table: such a controller is passed to rigiddyn.simulate directly.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np

from . import _core
from ._names import check_keys
from .control import BDot, Controller, PDAttitude
from .units import _shown, quantity, vector_quantity

_COMMON = frozenset({"period", "law", "body", "w_B_noise", "seed"})
_LAW_KEYS = {"bdot": _COMMON | {"gain", "element", "m_max", "rate"},
             "pd_attitude": _COMMON | {"k_p", "k_d", "target", "axes_B"}}
_LAWS = "'bdot' or 'pd_attitude'"
_IDENTITY = (0.0, 0.0, 0.0, 1.0)


def _fail(name: str, expected: str, got: Any) -> ValueError:
    return ValueError(f"{name}: expected {expected}, got {_shown(got)}")


def _required(table: Mapping[str, Any], key: str, expected: str) -> Any:
    if key not in table:
        raise _fail(f"controller.{key}", expected, "nothing")
    return table[key]


def _index(value: Any, name: str, count: int, what: str) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < count:
        raise _fail(name, f"{what} (an integer in [0, {count}))", value)
    return value


def read_controller(value: Any, scene: Any, names: Mapping[str, int],
                    body_ref: Callable[[Any, str, Mapping[str, int]], int]) -> Controller:
    """The Controller of the [controller] table `value` on `scene` (its bodies named by `names`, resolved by
    `body_ref(value, field, names)`); ValueError naming controller.<key> for a bad key or value."""
    if not isinstance(value, Mapping):
        raise _fail("controller", "a table [controller]", value)
    law_name = _required(value, "law", _LAWS)
    if not isinstance(law_name, str) or law_name not in _LAW_KEYS:
        raise _fail("controller.law", _LAWS, law_name)
    table = check_keys(value, "controller", _LAW_KEYS[law_name], f"a [controller] of law {law_name!r}")
    period = quantity(_required(table, "period", "a sample period [s] > 0"), "controller.period", "s", positive=True)
    body = body_ref(table["body"], "controller.body", names) if "body" in table else 0
    noise = quantity(table.get("w_B_noise", 0.0), "controller.w_B_noise", "rad/s", nonnegative=True)
    seed = table.get("seed")
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, int) or seed < 0):
        raise _fail("controller.seed", "an integer >= 0", seed)
    law = _bdot(table, scene, body) if law_name == "bdot" else _pd_attitude(table, scene, body)
    return Controller(period, law, w_B_noise=noise, seed=seed)


def _bdot(table: Mapping[str, Any], scene: Any, body: int) -> BDot:
    elements = list(scene.elements)
    e = _index(_required(table, "element", "the index of a magnetic_dipole [[force]]"), "controller.element",
               len(elements), "the index of a magnetic_dipole [[force]], from 0")
    if not isinstance(elements[e], _core.MagneticDipole):
        raise ValueError(f"controller.element: expected the index of a magnetic_dipole [[force]] (the magnetorquer "
                         f"the law commands), got {e} (a {type(elements[e]).__name__})")
    gain = quantity(_required(table, "gain", "a gain [A m^2 s/T] > 0"), "controller.gain", "A*m^2*s/T", positive=True)
    m_max = quantity(table["m_max"], "controller.m_max", "A*m^2", positive=True) if "m_max" in table else None
    rate = table.get("rate", "gyro")
    if rate not in ("gyro", "difference"):
        raise _fail("controller.rate", "'gyro' or 'difference'", rate)
    return BDot(gain, elements[e], e, body=body, m_max=m_max, rate=rate)


def _wheel_axes(scene: Any, body: int) -> np.ndarray:
    """The unit axes (nw, 3) in B of the wheels of gyrostat `body`; ValueError naming controller.body otherwise."""
    b = scene.bodies[body]
    if not isinstance(b, _core.Gyrostat):
        raise ValueError(f"controller.body: expected a gyrostat (pd_attitude commands its reaction wheels; or give "
                         f"axes_B), got {body} (a {type(b).__name__})")
    axes = np.array([w.axis_B for w in b.wheels], dtype=float)
    unit: np.ndarray = axes / np.linalg.norm(axes, axis=1, keepdims=True)
    return unit


def _pd_attitude(table: Mapping[str, Any], scene: Any, body: int) -> PDAttitude:
    k_p = quantity(_required(table, "k_p", "a gain [N m/rad] > 0"), "controller.k_p", "N*m/rad", positive=True)
    k_d = quantity(_required(table, "k_d", "a gain [N m s/rad] > 0"), "controller.k_d", "N*m*s/rad", positive=True)
    target: Any = table.get("target", list(_IDENTITY))
    if isinstance(target, str):
        if target != "lvlh":
            raise _fail("controller.target", "'lvlh' or a quaternion [x, y, z, w]", target)
    else:
        target = vector_quantity(target, "controller.target", "1", n=4)
    if "axes_B" in table:
        rows = table["axes_B"]
        if not isinstance(rows, list) or not rows:
            raise _fail("controller.axes_B", "an array of wheel axes [[x, y, z], ...]", rows)
        axes = np.array([vector_quantity(a, f"controller.axes_B[{i}]", "1") for i, a in enumerate(rows)])
    else:
        axes = _wheel_axes(scene, body)
    try:
        return PDAttitude(k_p, k_d, axes, q_target_WB=target, body=body)
    except ValueError as e:
        raise ValueError(f"controller.{e}") from None


def controller_table(controller: Controller, scene: Any, names: Sequence[str]) -> dict[str, Any]:
    """The [controller] table of `controller` on `scene` (bodies named by `names`): its period, noise and seed and
    its law's parameters, in SI; ValueError naming scene.controller for a law no file can hold (a Python function,
    a PDAttitude with a callable target, a BDot whose dipole is not its element)."""
    law = controller.law
    table: dict[str, Any] = {"period": float(controller.period)}
    if isinstance(law, BDot):
        elements = list(scene.elements)
        if not (0 <= law.element < len(elements)) or elements[law.element] != law.dipole:
            raise ValueError(f"scene.controller.law: expected a BDot whose dipole is the scene's element it "
                             f"commands, got element {law.element}")
        table.update({"law": "bdot", "gain": float(law.gain), "element": law.element})
        if law.m_max is not None:
            table["m_max"] = float(law.m_max)
        if law.rate != "gyro":
            table["rate"] = law.rate
    elif isinstance(law, PDAttitude) and not callable(law.q_target_WB):
        target = law.q_target_WB
        table.update({"law": "pd_attitude", "k_p": float(law.k_p), "k_d": float(law.k_d),
                      "target": target if isinstance(target, str) else np.asarray(target, dtype=float).tolist()})
        wheels = scene.bodies[law.body]
        if not (isinstance(wheels, _core.Gyrostat) and np.array_equal(_wheel_axes(scene, law.body), law.axes_B)):
            table["axes_B"] = law.axes_B.tolist()
    else:
        raise _fail("scene.controller.law", "a law a scene file can hold (a BDot, or a PDAttitude whose target is "
                    "'lvlh' or a quaternion)", law)
    table["body"] = names[law.body]
    if controller.w_B_noise > 0.0:
        table["w_B_noise"] = float(controller.w_B_noise)
    if controller.seed is not None:
        table["seed"] = int(controller.seed)
    return table
