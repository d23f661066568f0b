"""Recorded trajectories as tables: named columns with units, CSV, ``.npz``, Parquet and pandas.

A SceneResult (``rigiddyn.simulate`` of a body or a scene, or a batch's sample ``result[i]``) becomes the wide table
of rigiddyn.scene_result: one row per record, ``t [s]``, then each body's columns ``<body>:p_W_x [m]`` ..., then
the scene-wide ones (energies, momenta, each element's work and power); frames as in docs/conventions.md,
dimensionless columns carry no unit.

The quaternion's columns follow the order of the result's q_WB rows, which the result records: a run
of ``simulate(..., scalar_first=True)`` has ``result.scalar_first`` True and gives q_WB_w first.
`t [s]` is an ordinary column, not an index, in every format and in `to_dataframe`, so that all
of them hold the same columns (``df.set_index("t [s]")`` gives a time index). The files hold the
values exactly: CSV prints each number with Python's ``repr`` (the shortest text that reads back to
the same double), ``.npz`` and Parquet store the float64 bits. Parquet needs ``pyarrow`` and
`to_dataframe` needs ``pandas`` (extras ``parquet`` and ``dataframe``).

Every table function takes ``units=`` (rigiddyn.output_units): ``units={"length": "km", "angle": "deg",
"time": "h"}`` gives ``t [h]``, ``<body>:p_W_x [km]``, ``<body>:v_W_x [km/h]``, ``<body>:w_B_x [deg/h]``, ...
(a dimension not named stays SI; the quaternion's columns are never converted).
"""

from __future__ import annotations

import csv
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from ._core import SceneResult
from .scene_result import columns as scene_columns
from .scene_result import stored_order

__all__ = ["columns", "read_columns", "stored_order", "to_dataframe", "write_csv", "write_npz", "write_parquet"]


def columns(result: Any, scalar_first: bool | None = None, *,
            units: Mapping[str, str] | None = None) -> dict[str, np.ndarray]:
    """The columns of a result, in table order.

    Parameters
    ----------
    result : SceneResult
        The records of ``rigiddyn.simulate`` or a batch's sample ``result[i]`` (the columns of
        rigiddyn.scene_result.columns).
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
        `result` is no SceneResult, `scalar_first` no bool, or `units` no mapping.
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
    if not isinstance(result, SceneResult):
        raise TypeError(f"result: expected a SceneResult (of rigiddyn.simulate, or a batch's result[i]), got "
                        f"{type(result).__name__}")
    return scene_columns(result, scalar_first, units=units)


def write_csv(result: Any, path: str | Path, scalar_first: bool | None = None, *,
              units: Mapping[str, str] | None = None) -> Path:
    """Write the table to CSV: a header row of column names, then one row per record, each number as
    Python's repr (read back by float() or pandas.read_csv to the same double; nan and inf as
    'nan', 'inf').

    Parameters
    ----------
    result : SceneResult
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
    result : SceneResult
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
    result : SceneResult
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
    result : SceneResult
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
