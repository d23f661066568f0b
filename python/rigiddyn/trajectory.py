"""Recorded trajectories as tables: named columns with units, CSV, ``.npz``, Parquet and pandas.

A SimulationResult (see ``rigiddyn.simulate``) becomes one table, one row per record and one float64
column per scalar, named ``<field>[_<component>] [<unit>]`` after the result's attributes (frames as
in docs/conventions.md; dimensionless columns carry no unit)::

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
"""

from __future__ import annotations

import csv
import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

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


def column_names(scalar_first: bool = False) -> list[str]:
    """The table's column names in order (q_WB_w first among the quaternion's if scalar_first)."""
    names = []
    for field, (_, unit) in FIELDS.items():
        components = _components(field, scalar_first)
        names += [_name(field, None, unit)] if components is None else [_name(field, c, unit) for c in components]
    return names


def stored_order(result: Any, scalar_first: bool | None) -> bool:
    """The order of `result`'s q_WB rows: scalar_first if given (True: (w, x, y, z)), else the order the
    result records (its `scalar_first`, True for a run of ``simulate(..., scalar_first=True)``; a result
    that records none holds (x, y, z, w)). TypeError for anything but None, True or False."""
    if scalar_first is None:
        scalar_first = getattr(result, "scalar_first", False)
    if not isinstance(scalar_first, (bool, np.bool_)):
        raise TypeError(f"scalar_first: expected None, True or False, got {scalar_first!r}")
    return bool(scalar_first)


def columns(result: Any, scalar_first: bool | None = None) -> dict[str, np.ndarray]:
    """The columns of a SimulationResult: name -> contiguous float64 (n,) array, in table order, the
    quaternion's columns in the order of its q_WB rows (q_WB_w first when they are (w, x, y, z)).

    scalar_first: the order of the result's q_WB rows; None (the default): the order the result records
    (``result.scalar_first``, set by ``simulate(..., scalar_first=True)``); True or False declares it.
    """
    scalar_first = stored_order(result, scalar_first)
    out: dict[str, np.ndarray] = {}
    for field, (_, unit) in FIELDS.items():
        try:
            values = np.asarray(getattr(result, field), dtype=np.float64)
        except AttributeError:
            got = type(result).__name__
            raise TypeError(f"result: expected a SimulationResult (with .{field}), got {got}") from None
        components = _components(field, scalar_first)
        if components is None:
            out[_name(field, None, unit)] = np.ascontiguousarray(values)
        else:
            for i, c in enumerate(components):
                out[_name(field, c, unit)] = np.ascontiguousarray(values[:, i])
    return out


def fields_from_columns(table: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """The SimulationResult arrays back from a table's columns (any order of q_WB's columns):
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


def write_csv(result: Any, path: str | Path, scalar_first: bool | None = None) -> Path:
    """Write the table to CSV: a header row of column names, then one row per record, each number as
    Python's repr (read back by float() or pandas.read_csv to the same double; nan and inf as
    'nan', 'inf'). scalar_first: as in `columns`. Returns the path."""
    table = columns(result, scalar_first)
    path = Path(path)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(table)
        writer.writerows(zip(*(values.tolist() for values in table.values())))  # tolist: Python floats, printed by repr
    return path


def write_npz(result: Any, path: str | Path, scalar_first: bool | None = None) -> Path:
    """Write the table to an uncompressed ``.npz``, one (n,) float64 array per column name:
    ``pandas.DataFrame(dict(numpy.load(path)))`` is the table. scalar_first: as in `columns`. Returns the
    path."""
    path = Path(path)
    table: dict[str, Any] = columns(result, scalar_first)  # Any: numpy's stub types savez's keywords as its own
    with open(path, "wb") as f:  # a file object: numpy would append '.npz' to a name without it
        np.savez(f, **table)
    return path


def write_parquet(result: Any, path: str | Path, scalar_first: bool | None = None,
                  metadata: Mapping[str, Any] | None = None) -> Path:
    """Write the table to Parquet (needs pyarrow, extra ``parquet``); `metadata` (JSON-serialisable)
    is stored in the file's key-value metadata under b"rigiddyn". scalar_first: as in `columns`.
    Returns the path."""
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise ImportError("write_parquet needs pyarrow: pip install 'rigiddyn[parquet]' (or pyarrow)") from None
    table = pa.table(columns(result, scalar_first))
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


def to_dataframe(result: Any, scalar_first: bool | None = None) -> Any:
    """The SimulationResult as a pandas.DataFrame (needs pandas, extra ``dataframe``): one row per
    record, the columns of the CSV file in the same order, `t [s]` a column (not the index; use
    ``.set_index("t [s]")`` for a time index). scalar_first: as in `columns`."""
    try:
        import pandas as pd
    except ImportError:
        raise ImportError("to_dataframe needs pandas: pip install 'rigiddyn[dataframe]' (or pandas)") from None
    return pd.DataFrame(columns(result, scalar_first))
