"""A sweep's report for a terminal: the title, one row per run with short notes explained below, and the
recommendation or the Pareto front."""

from __future__ import annotations

import math
import textwrap
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._measures import measure_unit
from .checks import is_real
from .constants import REFERENCE_MARGIN, REFUSED
from .text import fmt, wrap

_MERGED = "\0"  # the steps cell of a closed-form row: its dt cell ("closed form") spans both
# the table's note tags, in the order they are shown, and their explanation below the table
TAGS = {
    "diverged": "the state became non-finite (errors inf)",
    "unstable": "dt beyond the method's stability limit for this spin or scene (see the warning)",
    "recommended": "the recommendation below",
    "front": "on the Pareto front: no other run is both cheaper and more accurate",
    "exact here": "exact on this problem (torque-free), the error is round-off",
    "round-off": "error at round-off",
    "ref. limit": f"error within {REFERENCE_MARGIN:g}x the reference's",
    "pre-asympt.": "slope not yet steady (before the asymptotic range)",
    "unconfirmed": "a single slope, none beside it to confirm it",
    "error O(1)": "errors of 1 rad (or 100 %) or more at this dt and the previous one: no accuracy left",
    "same dt": "the same dt as the previous row",
    "bad ref.": "the reference failed its independent check (see above)",
}
_ORDER_TAGS = {"exact on this problem": "exact here", "error at round-off": "round-off", "same dt": "same dt",
               "error O(1)": "error O(1)",
               f"error within {REFERENCE_MARGIN:g}x the reference's": "ref. limit"}
_HEADERS = ["method", "dt [s]", "steps", "ns/step", "error", "estimate", "order", "note"]


def tags(r: Mapping[str, Any], closed: bool, recommended: bool, front: bool) -> list[str]:
    """The short notes of a row (see TAGS)."""
    note = str(r.get("order_note", ""))
    order_tag = _ORDER_TAGS.get(note, "pre-asympt." if note.startswith("not asymptotic") else
                                "unconfirmed" if note.startswith("unconfirmed") else "")
    flags = {"diverged": r["diverged"], "unstable": bool(r.get("stability")), "recommended": recommended,
             "front": front, "bad ref.": str(r.get("reference", "")).startswith("unreliable"),
             order_tag: bool(order_tag) and not closed}  # a closed form's dt cell says why it has no order
    return [t for t in TAGS if flags.get(t)]


def _estimate_text(r: Mapping[str, Any]) -> str:
    """A row's estimate cell: the estimate, with ? where it is not reliable; - where there is none."""
    estimate = r.get("estimate", math.nan)
    if not is_real(estimate) or math.isnan(estimate):
        return "-"
    return fmt(float(estimate)) + ("" if r.get("estimate_verdict") == "reliable" else "?")


def run_key(r: Mapping[str, Any]) -> tuple[Any, ...]:
    """What names a run: (method, dt, steps)."""
    return r["method"], r["dt"], r["steps"]


def _table_line(cells: Sequence[str], widths: Sequence[int], note_width: int) -> list[str]:
    """One table row (the last cell, the note, wrapped to note_width on continuation lines)."""
    parts = [c.ljust(w) for c, w in zip(cells[:-1], widths)]
    if cells[2] == _MERGED:  # "closed form" over the dt and steps columns
        parts[1:3] = [cells[1].ljust(widths[1] + 2 + widths[2])]
    head = "  ".join(parts)
    notes = textwrap.wrap(cells[-1], note_width, break_long_words=True, break_on_hyphens=False) or [""]
    blank = " " * len(head)
    return [((head if i == 0 else blank) + "  " + n).rstrip() for i, n in enumerate(notes)]


def _title(result: Any, width: int) -> list[str]:
    """The problem, the measure and what it is measured against."""
    title = (f"{result.problem}, {fmt(result.horizon)} s: error = {result.measure} [{measure_unit(result.measure)}] "
             "vs ")
    references = list(dict.fromkeys(str(r["reference"]) for r in result.rows))
    if references == ["exact"]:
        return wrap(title + "the exact solution", width)
    if len(references) == 1 and references[0].startswith("exact: "):  # a scene's closed form, named
        return wrap(title + f"the exact solution ({references[0][len('exact: '):]})", width)
    checked = {r["dt"]: r for r in result.rows if r.get("reference_check")}
    bad = [r for r in checked.values() if str(r["reference"]).startswith("unreliable")]
    out = wrap(title + f"a refined reference ({', '.join(references)}), checked against an independent one at "
               f"each dt: {len(checked) - len(bad)} of {len(checked)} agree", width)
    for r in bad:
        out += wrap(f"  dt = {fmt(r['dt'])} s: {r['reference_check']}", width)
    return out


def _cells(result: Any, front: Sequence[Mapping[str, Any]]) -> tuple[list[list[str]], set[str]]:
    """The table's cells (a closed-form method's rows merged into one) and the note tags used."""
    rec = result.recommendation.row if result.recommendation is not None else None
    on_front = {run_key(r) for r in front}
    cells, used = [], set()
    for method in result.methods():
        mine = [r for r in result.rows if r["method"] == method]
        refused = [str(r.get("order_note", "")) for r in mine if str(r.get("order_note", "")).startswith(REFUSED)]
        if refused and len(refused) == len(mine):  # refused by the case: the reason below the table
            cells.append([method, "not applicable", _MERGED, "-", "-", "-", "-", "reason below"])
            continue
        closed = all(r.get("order") == 0 for r in mine)
        for r in ([max(mine, key=lambda r: r["steps"])] if closed else mine):
            row_tags = tags(r, closed, rec is not None and (run_key(r) == run_key(rec) or
                                                            (closed and rec["method"] == method)),
                            run_key(r) in on_front or (closed and any(f["method"] == method for f in front)))
            used.update(row_tags)
            order = r.get("observed_order", math.nan)
            cells.append([method, "closed form" if closed else fmt(r["dt"]), _MERGED if closed else str(r["steps"]),
                          fmt(r["time_per_step"] * 1e9), fmt(r[result.measure]), _estimate_text(r),
                          f"{order:.2f}" if is_real(order) and math.isfinite(order) else "-", ", ".join(row_tags)])
    return cells, used


def _front_text(result: Any, front: Sequence[Mapping[str, Any]], width: int) -> list[str]:
    """Without a tolerance: say so, and list the Pareto front."""
    cost = "wall time" if result.cost == "time" else "derivative evaluations"
    out = wrap("no tolerance given (--tolerance, or tolerance in the problem file's [tradeoff]): no "
               f"recommendation. The Pareto front of ({cost}, {result.measure}), the runs no other run beats in "
               "both (marked 'front'):", width)
    unit = measure_unit(result.measure)
    for r in front:
        where = "closed form" if r.get("order") == 0 else f"dt = {fmt(r['dt'])} s"
        out += wrap(f"  {r['method']}, {where}: {fmt(r[result.measure])}{'' if unit == '-' else ' ' + unit} in "
                    f"{fmt(r['total_time'])} s, {r['total_evaluations']} evaluations", width)
    return out if front else out + ["  (none: every run diverged)"]


def _column_widths(headers: Sequence[str], cells: Sequence[Sequence[str]]) -> list[int]:
    """The widths of the columns before the note (a closed form's dt cell spans dt and steps)."""
    out = [max([len(h)] + [len(c[i]) for c in cells if i not in (1, 2) or c[2] != _MERGED])
           for i, h in enumerate(headers[:-1])]
    merged = max((len(c[1]) for c in cells if c[2] == _MERGED), default=0)
    out[2] = max(out[2], merged - out[1] - 2)
    return out


def _legend(used: set[str], estimates: bool, width: int) -> list[str]:
    """The explanation of the estimate and order columns and of the note tags used."""
    legend = [f"{tag} = {TAGS[tag]}" for tag in TAGS if tag in used]
    estimate = ("estimate: the run's own estimate of its error (result.error), ? where it is not reliable (why: "
                "estimate_verdict in the CSV/JSON). " if estimates else
                f"The runs' own error estimates (estimate, effectivity, estimate_verdict) do not fit {width} "
                "columns here: see to_csv / to_json or a wider table. ")
    return wrap(estimate + "order: the observed order of convergence (- where it cannot be measured; the reason in "
                "note). " + ("notes: " + "; ".join(legend) + "." if legend else ""), width)


def table(result: Any, width: int) -> str:
    """TradeoffResult.to_table: the report of `result` in lines of at most `width` characters."""
    if isinstance(width, (bool, np.bool_)) or not isinstance(width, (int, np.integer)):
        raise TypeError(f"width: expected an integer >= 60 (characters), got {width!r}")
    if width < 60:
        raise ValueError(f"width: expected an integer >= 60 (characters), got {width!r}")
    front = result.pareto() if result.tolerance is None else []
    cells, used = _cells(result, front)
    headers = [*_HEADERS[:4], f"error [{measure_unit(result.measure)}]", *_HEADERS[5:]]
    widths = _column_widths(headers, cells)
    estimates = sum(widths) + 2 * len(widths) + 10 <= width  # the estimate column where a 10-wide note fits
    if not estimates:
        del headers[5]
        cells = [c[:5] + c[6:] for c in cells]
        widths = _column_widths(headers, cells)
    note_width = max(10, width - sum(widths) - 2 * len(widths))
    out = _title(result, width)
    for note in result.notes:
        out += wrap("note: " + note, width)
    out += [_table_line(headers, widths, note_width)[0], "  ".join("-" * w for w in widths + [note_width])]
    for c in cells:
        out += _table_line(c, widths, note_width)
    for method in result.methods():  # the reason of each method a case refuses, once
        reason = next((str(r["order_note"]) for r in result.rows if r["method"] == method and
                       str(r.get("order_note", "")).startswith(REFUSED)), None)
        if reason is not None:
            out += wrap(f"{method}: {reason}", width)
    out += _legend(used, estimates, width)
    if result.recommendation is not None:
        out += wrap(str(result.recommendation), width)
    else:
        out += _front_text(result, front, width)
    return "\n".join(out)
