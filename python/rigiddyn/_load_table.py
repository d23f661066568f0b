"""A load table of a file (a problem file's [[loads]], a scene file's [[force.loads]]) as the core's AppliedLoad.

Keys (the caller checks that the table holds no other): ``force`` [N] through the centre of mass and
``torque`` [N m] (each default 0), both in ``frame`` "world" (default) or "body", active for
``t_start`` <= t < ``t_end`` [s] (defaults -inf, +inf). Every number may carry a unit (rigiddyn.units).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from . import _core
from ._core_call import core_call
from .units import _shown, quantity, vector_quantity

LOAD_KEYS = frozenset({"force", "torque", "frame", "t_start", "t_end"})


def applied_load(table: Mapping[str, Any], name: str) -> _core.AppliedLoad:
    """The AppliedLoad of the load table `table` named `name` (``loads[0]``, ``force[1].loads[0]``);
    ValueError "<name>.<key>: expected ..., got ..." for a bad value."""
    frame = table.get("frame", "world")
    if not isinstance(frame, str):
        raise ValueError(f"{name}.frame: expected 'world' or 'body', got {_shown(frame)}")
    t_start = quantity(table["t_start"], f"{name}.t_start", "s") if "t_start" in table else -math.inf
    t_end = quantity(table["t_end"], f"{name}.t_end", "s") if "t_end" in table else math.inf
    if not t_start < t_end:  # here, where the file's field is known
        raise ValueError(f"{name}.t_end: expected a time > t_start = {t_start:g} s, got {_shown(table['t_end'])}")
    load: _core.AppliedLoad = core_call(
        _core.AppliedLoad, name,
        force=vector_quantity(table.get("force", [0.0] * 3), f"{name}.force", "N"),
        torque=vector_quantity(table.get("torque", [0.0] * 3), f"{name}.torque", "N*m"),
        frame=frame, t_start=t_start, t_end=t_end)
    return load
