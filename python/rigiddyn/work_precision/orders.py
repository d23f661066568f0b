"""The observed order of convergence of each run, kept only in the method's asymptotic range."""

from __future__ import annotations

import math
from typing import Any

from .._measures import measure_unit
from .constants import ORDER_AGREEMENT, REFERENCE_MARGIN, ROUND_OFF_PER_STEP


def _pair_note(coarse: dict[str, Any], fine: dict[str, Any], measure: str, exact: bool) -> str:
    """Why the slope between two runs of a method says nothing ("" if it says something)."""
    # an angle [rad] or a relative error of 1 or more says the run has lost all accuracy: no slope
    saturates = measure_unit(measure) in ("rad", "-")
    e0, e1 = coarse[measure], fine[measure]
    reference_floor = REFERENCE_MARGIN * max(coarse["reference_error"], fine["reference_error"])
    floor = max(ROUND_OFF_PER_STEP * max(coarse["steps"], fine["steps"]), reference_floor)
    if exact:
        return "exact on this problem"
    if coarse["diverged"] or fine["diverged"] or not (math.isfinite(e0) and math.isfinite(e1)):
        return "diverged"
    if coarse["dt"] == fine["dt"]:
        return "same dt"
    if saturates and min(e0, e1) >= 1.0:
        return "error O(1)"
    if min(e0, e1) <= reference_floor:
        return f"error within {REFERENCE_MARGIN:g}x the reference's"
    if min(e0, e1) <= floor:
        return "error at round-off"
    return ""


def observed_orders(rows: list[dict[str, Any]], measure: str, exact_methods: set[str]) -> None:
    """observed_order and order_note of every row (rigiddyn.work_precision's docstring): the slope of
    log(error) against log(dt) from the next larger dt, kept where a neighbouring slope agrees."""
    for method in dict.fromkeys(r["method"] for r in rows):
        mine = sorted((r for r in rows if r["method"] == method), key=lambda r: -r["dt"])
        exact = method in exact_methods
        slopes: list[float | None] = [None]  # slope of the pair (i - 1, i), None where it says nothing
        notes = ["exact on this problem" if exact else "coarsest step"]
        for coarse, fine in zip(mine[:-1], mine[1:]):
            note = _pair_note(coarse, fine, measure, exact)
            slopes.append(None if note else
                          math.log(coarse[measure] / fine[measure]) / math.log(coarse["dt"] / fine["dt"]))
            notes.append(note)
        for i, row in enumerate(mine):
            p = slopes[i]
            neighbours = [q for q in (slopes[i - 1] if i > 0 else None, slopes[i + 1] if i + 1 < len(mine) else None)
                          if q is not None]
            agree = p is not None and any(abs(p - q) <= ORDER_AGREEMENT * max(abs(p), abs(q), 1.0) for q in neighbours)
            row["observed_order"] = p if agree and p is not None else math.nan
            if p is None:
                row["order_note"] = notes[i]
            elif agree:
                row["order_note"] = ""
            elif neighbours:
                row["order_note"] = (f"not asymptotic: slope {p:.2g}, neighbouring " +
                                     ", ".join(f"{q:.2g}" for q in neighbours))
            else:
                row["order_note"] = f"unconfirmed: slope {p:.2g}, no neighbouring slope"
