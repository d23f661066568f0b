"""Recorded trajectories as tables: named columns with units, CSV, ``.npz``, Parquet and pandas.

A SceneResult (``rigiddyn.simulate`` of a body or a scene) becomes the wide table of rigiddyn.scene_result:
one row per record, ``t [s]``, then each body's columns ``<body>:p_W_x [m]`` ..., then the scene-wide ones
(energies, momenta, each element's work and power). One sample of a batch of bodies (``BatchResult[i]``, a
SimulationResult) becomes one table, one row per record and one float64 column per scalar, named
``<field>[_<component>] [<unit>]`` after its attributes (frames as in docs/conventions.md; dimensionless
columns carry no unit)::

    t [s] | p_W_x [m] ... | q_WB_x ... q_WB_w | v_W_x [m/s] ... | w_B_x [rad/s] ... |
    kinetic_energy [J] | total_energy [J] | angular_momentum_norm [kg m^2/s] |
    quaternion_norm_error | work [J]

The quaternion's columns follow the order of the result's q_WB rows, which the result records: a run
of ``simulate(..., scalar_first=True)`` has ``result.scalar_first`` True and gives q_WB_w first.
`t [s]` is an ordinary column, not an index, in every format and in `to_dataframe`, so that all
of them hold the same columns (``df.set_index("t [s]")`` gives a time index). The files hold the
values exactly: CSV prints each number with Python's ``repr`` (the shortest text that reads back to
the same double), ``.npz`` and Parquet store the float64 bits. Parquet needs ``pyarrow`` and
`to_dataframe` needs ``pandas`` (extras ``parquet`` and ``dataframe``).

Every table function takes ``units=`` (rigiddyn.output_units): ``units={"length": "km", "angle": "deg",
"time": "h"}`` gives ``t [h]``, ``p_W_x [km]``, ``v_W_x [km/h]``, ``w_B_x [deg/h]``, ... (a dimension
not named stays SI; the quaternion's columns are never converted). `fields_from_columns` reads SI
columns only.
"""

from __future__ import annotations

import csv
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .output_units import convert_columns
from .scene_result import columns as scene_columns
from .scene_result import stored_order

__all__ = ["FIELDS", "column_names", "columns", "fields_from_columns", "read_columns", "stored_order", "to_dataframe",
           "write_csv", "write_npz", "write_parquet"]

# SimulationResult attribute -> (component suffixes or None for a scalar, unit or None)
FIELDS: dict[str, tuple[str | None, str | None]] = {
    "t": (None, "s"),
    "p_W": ("xyz", "m"),
    "q_WB": ("xyzw", None),
    "v_W": ("xyz", "m/s"),
    "w_B": ("xyz", "rad/s"),
    "kinetic_energy": (None, "J"),
    "total_energy": (None, "J"),
    "angular_momentum_norm": (None, "kg m^2/s"),
    "quaternion_norm_error": (None, None),
    "work": (None, "J"),
}


def _name(field: str, component: str | None, unit: str | None) -> str:
    base = field if component is None else f"{field}_{component}"
    return base if unit is None else f"{base} [{unit}]"


def _components(field: str, scalar_first: bool) -> str | None:
    components, _ = FIELDS[field]
    return "wxyz" if field == "q_WB" and scalar_first else components


def column_names(scalar_first: bool = False, *, units: Mapping[str, str] | None = None) -> list[str]:
    """The column names of a batch sample's table (``BatchResult[i]``) in order.

    Parameters
    ----------
    scalar_first : bool, optional
        True: q_WB_w first among the quaternion's columns.
    units : Mapping[str, str], optional
        The units of the columns, {dimension: unit} (rigiddyn.output_units); None: SI.

    Returns
    -------
    list of str
        19 names, each with its unit: ``'t [s]'``, ``'p_W_x [m]'``, ...

    Raises
    ------
    TypeError, ValueError
        A bad `units` (rigiddyn.output_units.check_units).

    See Also
    --------
    columns

    Examples
    --------
    >>> from rigiddyn.trajectory import column_names
    >>> column_names(units={"length": "km", "angle": "deg", "time": "h"})[:12:3]
    ['t [h]', 'p_W_z [km]', 'q_WB_z', 'v_W_y [km/h]']
    """
    names = []
    for field, (_, unit) in FIELDS.items():
        components = _components(field, scalar_first)
        names += [_name(field, None, unit)] if components is None else [_name(field, c, unit) for c in components]
    return list(convert_columns(dict.fromkeys(names, np.zeros(0)), units))


def columns(result: Any, scalar_first: bool | None = None, *,
            units: Mapping[str, str] | None = None) -> dict[str, np.ndarray]:
    """The columns of a result, in table order.

    Parameters
    ----------
    result : SceneResult or SimulationResult
        The records of ``rigiddyn.simulate`` (the columns of rigiddyn.scene_result.columns) or a batch sample
        ``BatchResult[i]`` (the module docstring's 19 columns).
    scalar_first : bool, optional
        The order of the result's q_WB rows; None (the default): the order the result records
        (``result.scalar_first``, set by ``simulate(..., scalar_first=True)``); True or False declares it.
    units : Mapping[str, str], optional
        The units of the columns, {dimension: unit} such as ``{"length": "km", "angle": "deg", "time":
        "h"}`` (rigiddyn.output_units.DIMENSIONS names the keys); None: SI.

    Returns
    -------
    dict of str to numpy.ndarray
        Name -> contiguous float64 (n,) array, the quaternion's columns in the order of its q_WB rows
        (q_WB_w first when they are (w, x, y, z)); a converted column is its SI values times one factor.

    Raises
    ------
    TypeError
        `result` is no SceneResult or SimulationResult, `scalar_first` no bool, or `units` no mapping.
    ValueError
        A bad `units`: an unknown dimension, an unknown unit, a unit of another dimension.

    See Also
    --------
    to_dataframe, write_csv, rigiddyn.output_units

    Examples
    --------
    >>> from rigiddyn.trajectory import columns
    >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 1.0, 1.0]), rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), dt=1.0,
    ...                 steps=2, error=False)
    >>> table = columns(r, units={"angle": "deg", "time": "min"})
    >>> table["t [min]"], table["body0:w_B_z [deg/min]"].round(6)
    (array([0.        , 0.01666667, 0.03333333]), array([3437.746771, 3437.746771, 3437.746771]))
    """
    if hasattr(result, "body_names"):  # a SceneResult
        return scene_columns(result, scalar_first, units=units)
    scalar_first = stored_order(result, scalar_first)
    out: dict[str, np.ndarray] = {}
    for field, (_, unit) in FIELDS.items():
        try:
            values = np.asarray(getattr(result, field), dtype=np.float64)
        except AttributeError:
            got = type(result).__name__
            raise TypeError(f"result: expected a SceneResult or SimulationResult (with .{field}), got {got}") from None
        components = _components(field, scalar_first)
        if components is None:
            out[_name(field, None, unit)] = np.ascontiguousarray(values)
        else:
            for i, c in enumerate(components):
                out[_name(field, c, unit)] = np.ascontiguousarray(values[:, i])
    return convert_columns(out, units)


def fields_from_columns(table: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """A batch sample's (SimulationResult) arrays back from its table's columns (any order of q_WB's columns):
    t (n,), p_W (n, 3), q_WB (n, 4) as (x, y, z, w), ..., as float64 arrays."""
    out: dict[str, np.ndarray] = {}
    for field, (components, unit) in FIELDS.items():
        names = [_name(field, None, unit)] if components is None else [_name(field, c, unit) for c in components]
        missing = [n for n in names if n not in table]
        if missing:
            raise ValueError(f"table: expected the column {missing[0]!r}, got columns {list(table)}")
        arrays = [np.asarray(table[n], dtype=np.float64) for n in names]
        out[field] = arrays[0] if components is None else np.stack(arrays, axis=1)
    return out


def write_csv(result: Any, path: str | Path, scalar_first: bool | None = None, *,
              units: Mapping[str, str] | None = None) -> Path:
    """Write the table to CSV: a header row of column names, then one row per record, each number as
    Python's repr (read back by float() or pandas.read_csv to the same double; nan and inf as
    'nan', 'inf').

    Parameters
    ----------
    result : SceneResult or SimulationResult
        As in `columns`.
    path : str or pathlib.Path
        The file written (replaced if it exists).
    scalar_first : bool, optional
        As in `columns`.
    units : Mapping[str, str], optional
        The units of the columns, as in `columns` (the header names them); None: SI.

    Returns
    -------
    pathlib.Path
        `path`.

    Raises
    ------
    TypeError, ValueError
        As `columns` (checked before the file is opened).

    See Also
    --------
    read_columns, write_npz, write_parquet

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = tempfile.TemporaryDirectory()
    >>> from rigiddyn.trajectory import read_columns, write_csv
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1000.0, 0.0, 0.0]), dt=1800.0, steps=2,
    ...                 error=False)
    >>> path = write_csv(r, pathlib.Path(folder.name) / "t.csv", units={"length": "km", "time": "h"})
    >>> read_columns(path)["body0:p_W_x [km]"], read_columns(path)["body0:v_W_x [km/h]"]
    (array([   0., 1800., 3600.]), array([3600., 3600., 3600.]))
    >>> folder.cleanup()
    """
    table = columns(result, scalar_first, units=units)
    path = Path(path)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(table)
        writer.writerows(zip(*(values.tolist() for values in table.values())))  # tolist: Python floats, printed by repr
    return path


def write_npz(result: Any, path: str | Path, scalar_first: bool | None = None, *,
              units: Mapping[str, str] | None = None) -> Path:
    """Write the table to an uncompressed ``.npz``, one (n,) float64 array per column name:
    ``pandas.DataFrame(dict(numpy.load(path)))`` is the table.

    Parameters
    ----------
    result : SceneResult or SimulationResult
        As in `columns`.
    path : str or pathlib.Path
        The file written (replaced if it exists; no suffix is added).
    scalar_first : bool, optional
        As in `columns`.
    units : Mapping[str, str], optional
        The units of the columns, as in `columns` (the arrays' names name them); None: SI.

    Returns
    -------
    pathlib.Path
        `path`.

    Raises
    ------
    TypeError, ValueError
        As `columns` (checked before the file is opened).

    See Also
    --------
    read_columns, write_csv, write_parquet

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = tempfile.TemporaryDirectory()
    >>> from rigiddyn.trajectory import write_npz
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1000.0, 0.0, 0.0]), dt=1800.0, steps=2,
    ...                 error=False)
    >>> path = write_npz(r, pathlib.Path(folder.name) / "t.npz", units={"length": "km", "time": "h"})
    >>> np.load(path)["t [h]"]
    array([0. , 0.5, 1. ])
    >>> folder.cleanup()
    """
    path = Path(path)
    table: dict[str, Any] = columns(result, scalar_first, units=units)  # Any: numpy's stub types savez's keywords
    with open(path, "wb") as f:  # a file object: numpy would append '.npz' to a name without it
        np.savez(f, **table)
    return path


def write_parquet(result: Any, path: str | Path, scalar_first: bool | None = None,
                  metadata: Mapping[str, Any] | None = None, *, units: Mapping[str, str] | None = None) -> Path:
    """Write the table to Parquet (needs pyarrow, extra ``parquet``).

    Parameters
    ----------
    result : SceneResult or SimulationResult
        As in `columns`.
    path : str or pathlib.Path
        The file written (replaced if it exists).
    scalar_first : bool, optional
        As in `columns`.
    metadata : Mapping[str, Any], optional
        JSON-serialisable; stored in the file's key-value metadata under b"rigiddyn".
    units : Mapping[str, str], optional
        The units of the columns, as in `columns` (the column names name them); None: SI.

    Returns
    -------
    pathlib.Path
        `path`.

    Raises
    ------
    ImportError
        pyarrow is not installed.
    TypeError, ValueError
        As `columns` (checked before the file is opened).

    See Also
    --------
    read_columns, write_csv, write_npz

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = tempfile.TemporaryDirectory()
    >>> from rigiddyn.trajectory import read_columns, write_parquet
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1000.0, 0.0, 0.0]), dt=1800.0, steps=2,
    ...                 error=False)
    >>> path = write_parquet(r, pathlib.Path(folder.name) / "t.parquet", units={"length": "km"})
    >>> read_columns(path)["body0:p_W_x [km]"]
    array([   0., 1800., 3600.])
    >>> folder.cleanup()
    """
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise ImportError("write_parquet needs pyarrow: pip install 'rigiddyn[parquet]' (or pyarrow)") from None
    table = pa.table(columns(result, scalar_first, units=units))
    if metadata is not None:
        table = table.replace_schema_metadata({b"rigiddyn": json.dumps(dict(metadata)).encode()})
    path = Path(path)
    pq.write_table(table, path)
    return path


def read_columns(path: str | Path) -> dict[str, np.ndarray]:
    """The columns of a table written by write_csv, write_npz or write_parquet (chosen by the suffix
    .csv, .npz, .parquet): name -> float64 (n,) array, in file order."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".csv":
        with open(path, newline="") as f:
            rows = list(csv.reader(f))
        if not rows:
            raise ValueError(f"path: expected a CSV table with a header row, got the empty file {str(path)!r}")
        values = np.array([[float(x) for x in row] for row in rows[1:]], dtype=np.float64).reshape(-1, len(rows[0]))
        return {name: np.ascontiguousarray(values[:, i]) for i, name in enumerate(rows[0])}
    if suffix == ".npz":
        with np.load(path) as data:
            return {name: data[name] for name in data.files}
    if suffix == ".parquet":
        try:
            import pyarrow.parquet as pq
        except ImportError:
            raise ImportError("reading Parquet needs pyarrow: pip install 'rigiddyn[parquet]' (or pyarrow)") from None
        table = pq.read_table(path)
        return {name: table.column(name).to_numpy() for name in table.column_names}
    raise ValueError(f"path: expected a .csv, .npz or .parquet file, got {str(path)!r}")


def to_dataframe(result: Any, scalar_first: bool | None = None, *, units: Mapping[str, str] | None = None) -> Any:
    """The result as a pandas.DataFrame (needs pandas, extra ``dataframe``): one row per
    record, the columns of the CSV file in the same order, `t [s]` a column (not the index; use
    ``.set_index("t [s]")`` for a time index).

    Parameters
    ----------
    result : SceneResult or SimulationResult
        As in `columns`.
    scalar_first : bool, optional
        As in `columns`.
    units : Mapping[str, str], optional
        The units of the columns, as in `columns` (``{"length": "km", "angle": "deg", "time": "h"}``
        gives 't [h]', 'p_W_x [km]', 'w_B_x [deg/h]', ...); None: SI.

    Returns
    -------
    pandas.DataFrame
        n rows, the columns of `columns`.

    Raises
    ------
    ImportError
        pandas is not installed.
    TypeError, ValueError
        As `columns`.

    See Also
    --------
    columns, write_csv

    Examples
    --------
    >>> from rigiddyn.trajectory import to_dataframe
    >>> r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1000.0, 0.0, 0.0]), dt=1800.0, steps=2,
    ...                 error=False)
    >>> to_dataframe(r, units={"length": "km", "time": "h"})[["t [h]", "body0:p_W_x [km]"]]
       t [h]  body0:p_W_x [km]
    0    0.0               0.0
    1    0.5            1800.0
    2    1.0            3600.0
    """
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("to_dataframe needs pandas: pip install 'rigiddyn[dataframe]' (or pandas)") from None
    return pd.DataFrame(columns(result, scalar_first, units=units))
