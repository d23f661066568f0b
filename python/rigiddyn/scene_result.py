"""A SceneResult (``rigiddyn.simulate`` of a Scene) as one wide table: one row per record, one float64
column per scalar, named ``[<body>:]<field>[_<component>] [<unit>]`` (frames as in docs/conventions.md;
dimensionless columns carry no unit)::

    t [s] | sat:p_W_x [m] ... | sat:q_WB_x ... sat:q_WB_w | sat:v_W_x [m/s] ... | sat:w_B_x [rad/s] ... |
    sat:pivot_reaction_W_x [N] ... | sat:angular_momentum_O_W_x [kg m^2/s] ... | sat:mass [kg] |
    sat:mass_flow_energy [J] | (a gyrostat's) sat:wheel_speed_0 [rad/s] ... | sat:motor_work_0 [J] ... |
    (the same for every body, in the scene's order) |
    kinetic_energy [J] | potential_energy [J] | total_energy [J] |
    linear_momentum_W_x [kg m/s] ... | angular_momentum_W_x [kg m^2/s] ... |
    (with a tree) joint_q[0] ... | joint_v[0] ... |
    work[0] UniformGravity [J] ... | power[0] UniformGravity [W] ...

Wide rather than long (one row per record and body): the scene-wide columns (energies, momenta, each
element's work and power) belong to a record, not to a body, so a long table would repeat them on every
body's row; the wide one has one row per record, ``t [s]`` an ordinary column,
and ``df.filter(like="sat:")`` selects one body. ``units=`` gives the columns in the user's units, as for a
batch sample's table (rigiddyn.output_units): ``units={"length": "km", "time": "h"}`` gives ``t [h]``,
``sat:p_W_x [km]``, ``sat:v_W_x [km/h]``, ``sat:angular_momentum_O_W_x [kg km^2/h]``, ...

"W" is the scene frame (F when the scene has a moving frame: states relative to it). Per body:
pivot_reaction_W is the pivot's force on a pinned body (0 for an unpinned one), angular_momentum_O_W
the angular momentum about the pivot O (about the centre of mass for an unpinned body), mass the body's
mass at the record (it changes with a MassFlow), mass_flow_energy the kinetic energy its mass flow has taken
away or brought since t0 (0 for a constant mass); a gyrostat adds wheel_speed_<k>, wheel k's speed relative to
the body, and motor_work_<k>, the work its motor has done since t0 (k counts the gyrostat's own wheels): the
work–energy balance reads ``kinetic_energy − kinetic_energy[0] ≈ Σ work[i] + Σ <body>:mass_flow_energy + Σ
<body>:motor_work_<k>``. A scene with trees (Scene.add_tree) adds joint_q[k] and joint_v[k], the trees' stacked
coordinates and velocities (angles [rad], offsets [m], quaternion components, rates: mixed units, so none is named).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .output_units import convert_columns

__all__ = ["BODY_FIELDS", "SCENE_FIELDS", "column_names", "columns", "to_dataframe"]

# per-body SceneResult attribute -> (components ("" for a scalar), unit or None)
BODY_FIELDS: dict[str, tuple[str, str | None]] = {
    "p_W": ("xyz", "m"),
    "q_WB": ("xyzw", None),
    "v_W": ("xyz", "m/s"),
    "w_B": ("xyz", "rad/s"),
    "pivot_reaction_W": ("xyz", "N"),
    "angular_momentum_O_W": ("xyz", "kg m^2/s"),
    "mass": ("", "kg"),
    "mass_flow_energy": ("", "J"),
}
# scene-wide attribute -> (components or None for a scalar, unit)
SCENE_FIELDS: dict[str, tuple[str | None, str]] = {
    "kinetic_energy": (None, "J"),
    "potential_energy": (None, "J"),
    "total_energy": (None, "J"),
    "linear_momentum_W": ("xyz", "kg m/s"),
    "angular_momentum_W": ("xyz", "kg m^2/s"),
}
ELEMENT_FIELDS: dict[str, str] = {"work": "J", "power": "W"}
# per-wheel attribute (n, nw) of a gyrostat -> unit
WHEEL_FIELDS: dict[str, str] = {"wheel_speed": "rad/s", "motor_work": "J"}


def _unit(name: str, unit: str | None) -> str:
    return name if unit is None else f"{name} [{unit}]"


def stored_order(result: Any, scalar_first: bool | None) -> bool:
    """The order of `result`'s q_WB rows: scalar_first if given (True: (w, x, y, z)), else the order the
    result records (its `scalar_first`, True for a run of ``simulate(..., scalar_first=True)``; a result
    that records none holds (x, y, z, w)). TypeError for anything but None, True or False."""
    if scalar_first is None:
        scalar_first = getattr(result, "scalar_first", False)
    if not isinstance(scalar_first, (bool, np.bool_)):
        raise TypeError(f"scalar_first: expected None, True or False, got {scalar_first!r}")
    return bool(scalar_first)


def columns(result: Any, scalar_first: bool | None = None, *,
            units: Mapping[str, str] | None = None) -> dict[str, np.ndarray]:
    """The columns of a SceneResult, in table order (the module docstring lists them).

    Parameters
    ----------
    result : SceneResult
        The records of ``rigiddyn.simulate`` (of a body or a scene) or ``BatchSceneResult[i]``.
    scalar_first : bool, optional
        The order of the result's q_WB rows; None (the default): the order the result records
        (``result.scalar_first``, set by ``simulate(..., scalar_first=True)``); True or False declares it.
    units : Mapping[str, str], optional
        The units of the columns, {dimension: unit} such as ``{"length": "km", "angle": "deg", "time":
        "h"}`` (rigiddyn.output_units.DIMENSIONS names the keys); None: SI.

    Returns
    -------
    dict of str to numpy.ndarray
        Name -> contiguous float64 (n,) array; a converted column is its SI values times one factor.

    Raises
    ------
    TypeError, ValueError
        A bad `scalar_first` or `units` (rigiddyn.output_units.check_units).

    See Also
    --------
    to_dataframe, rigiddyn.trajectory.columns

    Examples
    --------
    >>> from rigiddyn.scene_result import columns
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.Particle(1.0), name="sat")
    0
    >>> r = rd.simulate(scene, [rd.ParticleState(v_W=[1000.0, 0.0, 0.0])], dt=1800.0, steps=2, error=False)
    >>> table = columns(r, units={"length": "km", "time": "h"})
    >>> table["t [h]"], table["sat:p_W_x [km]"]
    (array([0. , 0.5, 1. ]), array([   0., 1800., 3600.]))
    """
    scalar_first = stored_order(result, scalar_first)
    out: dict[str, np.ndarray] = {"t [s]": np.ascontiguousarray(result.t, dtype=np.float64)}
    for b, body in enumerate(result.body_names):
        for field, (components, unit) in BODY_FIELDS.items():
            if field == "q_WB" and scalar_first:
                components = "wxyz"
            values = np.asarray(getattr(result, field), dtype=np.float64)[:, b]
            if not components:
                out[_unit(f"{body}:{field}", unit)] = np.ascontiguousarray(values)
            for i, c in enumerate(components):
                out[_unit(f"{body}:{field}_{c}", unit)] = np.ascontiguousarray(values[:, i])
        wheels = [w for w, owner in enumerate(result.wheel_bodies) if owner == b]
        for field, unit in WHEEL_FIELDS.items():
            values = np.asarray(getattr(result, field), dtype=np.float64)
            for k, w in enumerate(wheels):
                out[_unit(f"{body}:{field}_{k}", unit)] = np.ascontiguousarray(values[:, w])
    for field, (parts, unit) in SCENE_FIELDS.items():
        values = np.asarray(getattr(result, field), dtype=np.float64)
        if parts is None:
            out[_unit(field, unit)] = np.ascontiguousarray(values)
        else:
            for i, c in enumerate(parts):
                out[_unit(f"{field}_{c}", unit)] = np.ascontiguousarray(values[:, i])
    for field in ("joint_q", "joint_v"):
        values = np.asarray(getattr(result, field), dtype=np.float64)
        for k in range(values.shape[1]):
            out[f"{field}[{k}]"] = np.ascontiguousarray(values[:, k])
    for field, unit in ELEMENT_FIELDS.items():
        values = np.asarray(getattr(result, field), dtype=np.float64)
        for i, kind in enumerate(result.elements):
            out[_unit(f"{field}[{i}] {kind}", unit)] = np.ascontiguousarray(values[:, i])
    return convert_columns(out, units)


def column_names(result: Any, scalar_first: bool | None = None, *, units: Mapping[str, str] | None = None) -> list[str]:
    """The table's column names in order (they depend on the scene's bodies and elements).

    Parameters
    ----------
    result : SceneResult
        As in `columns`.
    scalar_first : bool, optional
        As in `columns`.
    units : Mapping[str, str], optional
        As in `columns`.

    Returns
    -------
    list of str
        The names, each with its unit.

    Raises
    ------
    TypeError, ValueError
        As `columns`.

    See Also
    --------
    columns

    Examples
    --------
    >>> from rigiddyn.scene_result import column_names
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.Particle(1.0), name="sat")
    0
    >>> r = rd.simulate(scene, [rd.ParticleState()], dt=1.0, steps=1, error=False)
    >>> [name for name in column_names(r, units={"length": "km", "mass": "t"}) if name.startswith("sat:p_W")]
    ['sat:p_W_x [km]', 'sat:p_W_y [km]', 'sat:p_W_z [km]']
    >>> [name for name in column_names(r, units={"length": "km", "mass": "t"}) if "mass" in name]
    ['sat:mass [t]', 'sat:mass_flow_energy [J]']
    """
    return list(columns(result, scalar_first, units=units))


def to_dataframe(result: Any, scalar_first: bool | None = None, *, units: Mapping[str, str] | None = None) -> Any:
    """The table as a pandas.DataFrame (needs pandas: pip install 'rigiddyn[dataframe]').

    Parameters
    ----------
    result : SceneResult
        As in `columns`.
    scalar_first : bool, optional
        As in `columns`.
    units : Mapping[str, str], optional
        The units of the columns, as in `columns`; None: SI.

    Returns
    -------
    pandas.DataFrame
        One row per record, the columns of `columns` in order.

    Raises
    ------
    ImportError
        pandas is not installed.
    TypeError, ValueError
        As `columns`.

    See Also
    --------
    columns

    Examples
    --------
    >>> from rigiddyn.scene_result import to_dataframe
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.Particle(1.0), name="sat")
    0
    >>> r = rd.simulate(scene, [rd.ParticleState(v_W=[1000.0, 0.0, 0.0])], dt=1800.0, steps=2, error=False)
    >>> to_dataframe(r, units={"length": "km", "time": "h"})[["t [h]", "sat:v_W_x [km/h]"]]
       t [h]  sat:v_W_x [km/h]
    0    0.0            3600.0
    1    0.5            3600.0
    2    1.0            3600.0
    """
    try:
        import pandas as pd
    except ImportError as error:  # pragma: no cover - depends on the environment
        raise ImportError("SceneResult.to_dataframe needs pandas: pip install 'rigiddyn[dataframe]'") from error
    return pd.DataFrame(columns(result, scalar_first, units=units))
