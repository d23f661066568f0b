"""The checks of the sweep's arguments and of a result's fields: TypeError or ValueError naming the bad value."""

from __future__ import annotations

import math
import os
from collections.abc import Iterable, Mapping, Sequence, Sized
from pathlib import Path
from typing import Any

import numpy as np

from .constants import COLUMNS, COSTS, MAX_DTS, MAX_STEPS

ROW_KEYS = ("method", "dt", "steps", "diverged", "total_time", "total_evaluations")  # what a result needs


def is_real(x: Any) -> bool:
    """True for an int or float (numpy's too), False for a bool."""
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


def check_positive(x: Any, name: str) -> float:
    """x as a float: a finite real number > 0, else TypeError/ValueError naming `name`."""
    if not is_real(x):
        raise TypeError(f"{name}: expected a finite number > 0, got {x!r}")
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{name}: expected a finite number > 0, got {x!r}")
    return float(x)


def check_horizon(x: Any, name: str) -> float:
    """A horizon [s]: a finite number > 0, or nan (unknown)."""
    if is_real(x) and math.isnan(x):
        return math.nan
    return check_positive(x, name)


def check_count(x: Any, name: str) -> int:
    """x as an int >= 1, else TypeError/ValueError naming `name`."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise TypeError(f"{name}: expected an integer >= 1, got {x!r}")
    if x < 1:
        raise ValueError(f"{name}: expected an integer >= 1, got {x!r}")
    return int(x)


def check_cost(cost: Any) -> None:
    """cost one of COSTS ('time', 'evaluations'), else TypeError/ValueError naming `cost`."""
    if not isinstance(cost, str):
        raise TypeError(f"cost: expected one of {', '.join(COSTS)}, got {cost!r}")
    if cost not in COSTS:
        raise ValueError(f"cost: expected one of {', '.join(COSTS)}, got {cost!r}")


def check_names(methods: Any, known: Iterable[str]) -> list[str]:
    """methods as a non-empty list of distinct known names, else TypeError/ValueError naming `methods`."""
    known = list(known)
    if isinstance(methods, (str, bytes)) or not isinstance(methods, Iterable):
        raise TypeError(f"methods: expected a list of method names, got {methods!r}")
    names = list(methods)
    if not names:
        raise ValueError(f"methods: expected at least one name from {', '.join(known)}, got []")
    for name in names:
        if not isinstance(name, str):
            raise TypeError(f"methods: expected names (str) from {', '.join(known)}, got {name!r}")
        if name not in known:
            raise ValueError(f"methods: expected names from {', '.join(known)}, got {name!r}")
    repeated = [n for n in dict.fromkeys(names) if names.count(n) > 1]
    if repeated:
        raise ValueError(f"methods: expected distinct names, got {repeated[0]!r} {names.count(repeated[0])} times")
    return names


def check_dts(dts: Any) -> list[float]:
    """dts as a non-empty list of at most MAX_DTS finite steps > 0 [s], else TypeError/ValueError naming `dts`."""
    if isinstance(dts, (str, bytes)) or not isinstance(dts, Iterable):
        raise TypeError(f"dts: expected a non-empty list of finite steps > 0 [s], got {dts!r}")
    if getattr(dts, "ndim", 1) > 1:  # an array of rows, not a list of steps
        raise ValueError(f"dts: expected a 1-d list of finite steps > 0 [s], got an array of shape {getattr(dts, 'shape', None)}")
    if isinstance(dts, Sized) and len(dts) > MAX_DTS:  # one run per step: refuse before copying
        raise ValueError(f"dts: expected at most {MAX_DTS} steps (one run each), got {len(dts)}")
    values = list(dts)
    if not values:
        raise ValueError("dts: expected a non-empty list of finite steps > 0 [s], got []")
    for d in values:
        if not is_real(d):
            raise TypeError(f"dts: expected a non-empty list of finite steps > 0 [s], got {values!r}")
        if not (math.isfinite(d) and d > 0):
            raise ValueError(f"dts: expected a non-empty list of finite steps > 0 [s], got {values!r}")
    return [float(d) for d in values]


def step_grid(horizon: float, dts: Sequence[float], name: str) -> list[int]:
    """The step counts round(horizon / dt) (>= 1), ascending; ValueError naming `name` beyond MAX_STEPS."""
    for d in dts:
        if not horizon / d <= MAX_STEPS:
            raise ValueError(f"{name}: expected at most {MAX_STEPS:.3g} steps per run (horizon / dt), got horizon "
                             f"{horizon:g} s / dt {d:g} s = {horizon / d:.3g}")
    return sorted({max(1, round(horizon / d)) for d in dts})


def check_path(path: Any, name: str, optional: bool) -> Path | None:
    """path as a Path (None if optional and None), else TypeError naming `name`."""
    if path is None and optional:
        return None
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"{name}: expected {'None or ' if optional else ''}a file path (str or os.PathLike), got {path!r}")
    return Path(path)


def check_rows(rows: Any, keys: Sequence[str]) -> list[dict[str, Any]]:
    """rows as a list of dicts (keys from COLUMNS) with at least `keys`, else TypeError/ValueError naming rows."""
    expected = f"a list of rows (dicts with keys from COLUMNS, at least {', '.join(keys)})"
    if isinstance(rows, (str, bytes, Mapping)) or not isinstance(rows, Iterable):
        raise TypeError(f"rows: expected {expected}, got {rows!r}")
    out = list(rows)
    for i, row in enumerate(out):
        if not isinstance(row, Mapping):
            raise TypeError(f"rows: expected {expected}, got {row!r} at index {i}")
        missing = [k for k in keys if k not in row]
        if missing:
            raise ValueError(f"rows: expected {expected}, got row {i} without {', '.join(missing)}")
        unknown = [k for k in row if k not in COLUMNS]
        if unknown:
            raise ValueError(f"rows: expected {expected}, got row {i} with {', '.join(map(repr, unknown[:3]))}")
    return [dict(row) for row in out]


def check_name_list(values: Any, name: str, allowed: Sequence[str] | None) -> list[str]:
    """A list of strings from `allowed` (any string if None): TypeError / ValueError naming `name` otherwise."""
    expected = "a list of strings" if allowed is None else f"a list of names from {', '.join(allowed)}"
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise TypeError(f"{name}: expected {expected}, got {values!r}")
    names = list(values)
    for v in names:
        if not isinstance(v, str):
            raise TypeError(f"{name}: expected {expected}, got {v!r}")
        if allowed is not None and v not in allowed:
            raise ValueError(f"{name}: expected {expected}, got {v!r}")
    return names
