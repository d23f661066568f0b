"""The result of a sweep: its rows, the recommendation, the Pareto front, and the report as a table, CSV, JSON
and a plot."""

from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from collections.abc import Sequence
from typing import Any

from .._measures import _check_measure
from .checks import ROW_KEYS, check_cost, check_horizon, check_name_list, check_path, check_positive, check_rows
from .constants import COLUMNS, COSTS
from .files import OPTIONAL_COLUMNS, describe_text, json_row, json_safe, read_text, typed_row
from .plot import plot
from .ranking import cheapest, pareto_front, timing_noise
from .recommendation import Recommendation
from .table import table


@dataclass
class TradeoffResult:
    """The rows of a ``tradeoff`` sweep and its recommendation: what each method costs and how accurate it is.

    Made by ``tradeoff``, or read back with ``TradeoffResult.read_csv`` / ``read_json``. Every argument is
    checked: TypeError or ValueError naming it.

    Parameters
    ----------
    problem : str
        The problem's name.
    horizon : float
        Duration of each run [s] (nan if unknown).
    measure : str
        The recommendation's measure, one of ``rigiddyn.work_precision.MEASURES``.
    tolerance : float or None, default None
        The recommendation's criterion (None: no recommendation).
    rows : list of dict, default []
        One per method × dt, with the keys ``COLUMNS`` (method, dt [s], steps, errors, cost, ...).
    cost : {"time", "evaluations"}, default "time"
        What the recommendation minimises.
    recommendation : Recommendation or None, default None
        Computed from the rows when None and a tolerance is given.
    notes : list of str, default []
        What the report says besides the rows (a scene's compatibility warnings).

    See Also
    --------
    tradeoff : runs the sweep.

    Examples
    --------
    >>> result = rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=1.0, progress=False)
    >>> result.problem, len(result.rows), result.rows[0]["method"]
    ('tumbling T-handle (Dzhanibekov)', 1, 'rk4')
    >>> result.recommend(1e-3, "final_attitude_error", "evaluations").row["dt"]
    0.01
    """

    problem: str
    horizon: float
    measure: str
    tolerance: float | None = None
    rows: list[dict[str, Any]] = field(default_factory=list)
    cost: str = "time"
    recommendation: Recommendation | None = field(default=None)
    notes: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        if not isinstance(self.problem, str):
            raise TypeError(f"problem: expected the problem's name (str), got {self.problem!r}")
        self.horizon = check_horizon(self.horizon, "horizon")
        _check_measure(self.measure)
        self.rows = check_rows(self.rows, (*ROW_KEYS, self.measure))
        if self.tolerance is not None:
            self.tolerance = check_positive(self.tolerance, "tolerance")
        check_cost(self.cost)
        if self.recommendation is not None and not isinstance(self.recommendation, Recommendation):
            raise TypeError(f"recommendation: expected None or a Recommendation, got {self.recommendation!r}")
        if self.recommendation is None and self.tolerance is not None:
            self.recommendation = self.recommend(self.tolerance, self.measure, self.cost)
        self.notes = check_name_list(self.notes, "notes", None)

    def recommend(self, tolerance: float, measure: str | None = None, cost: str = "time") -> Recommendation:
        """The cheapest run (cost 'time': total wall time; 'evaluations': derivative evaluations) whose
        `measure` is <= tolerance also counting the reference's error (reference_error, which is that
        of the sweep's measure: a run measured against an unreliable reference does not count for
        another measure), diverged runs excluded."""
        measure = self.measure if measure is None else measure
        _check_measure(measure)
        check_positive(tolerance, "tolerance")
        check_cost(cost)
        usable = [r for r in self.rows if not r["diverged"] and math.isfinite(r[measure])]

        def bound(r: dict[str, Any]) -> float:  # the run's error at worst
            if measure == self.measure:
                return float(r[measure] + r.get("reference_error", 0.0))
            return math.inf if str(r.get("reference", "")).startswith("unreliable") else float(r[measure])

        meeting = [r for r in usable if bound(r) <= tolerance]
        noise = timing_noise(self.rows)
        row: Any = cheapest(meeting, cost, noise)
        best = min(usable, key=lambda r: (r[measure], r[COSTS[cost]])) if usable else None
        return Recommendation(measure, float(tolerance), cost, row, best, noise)

    def pareto(self, measure: str | None = None, cost: str | None = None) -> list[dict[str, Any]]:
        """The runs on the Pareto front of (cost, `measure`) (default: the sweep's cost and measure):
        those no other run beats in both, by ascending cost; diverged and non-finite runs excluded."""
        measure = self.measure if measure is None else measure
        _check_measure(measure)
        cost = self.cost if cost is None else cost
        check_cost(cost)
        usable = [r for r in self.rows if not r["diverged"] and math.isfinite(r.get(measure, math.nan))]
        front = pareto_front([(float(r[COSTS[cost]]), float(r[measure])) for r in usable])
        return [usable[i] for i in front]

    def methods(self) -> list[str]:
        """The methods of the rows, in their order."""
        return list(dict.fromkeys(r["method"] for r in self.rows))

    # -- text
    def to_table(self, width: int = 100) -> str:
        """The report for a terminal, no line wider than `width` characters (>= 60; or than the fixed
        columns and a 10-character note, where the method names make those wider): the problem and
        reference, one row per run (method, dt [s], steps, ns/step, the sweep's measure with its unit, the
        run's own estimate of it where the width allows, observed order, short notes explained below the
        table; a closed-form method once, without dt),
        then the recommendation or, without a tolerance, the Pareto front. Every column of every run:
        to_csv / to_json."""
        return table(self, width)

    def __str__(self) -> str:
        return self.to_table()

    # -- CSV / JSON
    def to_csv(self, path: str | Path | None = None) -> str:
        """All COLUMNS as CSV (floats with 17 significant digits); written to `path` if given."""
        path = check_path(path, "path", optional=True)
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=COLUMNS, lineterminator="\n")
        writer.writeheader()
        for r in self.rows:
            writer.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in r.items()})
        text = buf.getvalue()
        if path is not None:
            Path(path).write_text(text)
        return text

    @staticmethod
    def read_csv(path_or_text: str | Path, problem: str = "", horizon: float = math.nan,
                 measure: str = "final_attitude_error", tolerance: float | None = None) -> TradeoffResult:
        """A TradeoffResult from to_csv's output (a file path or the text itself); the CSV holds the
        rows only: problem (name), horizon [s] (nan: unknown), measure and tolerance are given here."""
        text = read_text(path_or_text)
        reader = csv.DictReader(io.StringIO(text))
        missing = [c for c in COLUMNS if c not in (reader.fieldnames or []) and c not in OPTIONAL_COLUMNS]
        if missing:
            raise ValueError(f"path_or_text: expected a CSV file or text written by to_csv (columns {', '.join(COLUMNS)}), "
                             f"got {describe_text(path_or_text, text)} without {', '.join(missing[:3])}"
                             f"{' ...' if len(missing) > 3 else ''}")
        try:
            rows = [typed_row(r) for r in reader]
        except (TypeError, ValueError) as error:
            raise ValueError(f"path_or_text: expected a CSV file or text written by to_csv, got a value that does not "
                             f"parse ({error})") from None
        return TradeoffResult(problem, horizon, measure, tolerance, rows)

    def to_dict(self) -> dict[str, Any]:
        """The sweep's settings, rows and recommendation (with the relative timing noise it ranked with)."""
        rec = self.recommendation
        return {"problem": self.problem, "horizon": self.horizon, "measure": self.measure,
                "tolerance": self.tolerance, "cost": self.cost, "rows": self.rows, "notes": self.notes,
                "recommendation": None if rec is None else {"met": rec.met, "text": str(rec), "row": rec.row,
                                                            "best": rec.best, "timing_noise": rec.noise}}

    def to_json(self, path: str | Path | None = None) -> str:
        """JSON with the sweep's settings, rows and recommendation: numbers as numbers, null where a number
        is not finite (nan: not measured, e.g. observed_order; inf: the errors of a diverged run, whose
        `diverged` is true). read_json restores both."""
        path = check_path(path, "path", optional=True)
        text = json.dumps(json_safe(self.to_dict()), indent=1, allow_nan=False)
        if path is not None:
            Path(path).write_text(text)
        return text

    @staticmethod
    def read_json(path_or_text: str | Path) -> TradeoffResult:
        """A TradeoffResult from to_json's output (a file path or the text itself)."""
        text = read_text(path_or_text)
        expected = "a JSON file or text written by to_json (keys problem, horizon, measure, tolerance, rows)"
        try:
            d = json.loads(text)
        except json.JSONDecodeError as error:
            raise ValueError(f"path_or_text: expected {expected}, got {describe_text(path_or_text, text)} "
                             f"({error})") from None
        if not isinstance(d, dict) or any(k not in d for k in ("problem", "horizon", "measure", "tolerance", "rows")):
            raise ValueError(f"path_or_text: expected {expected}, got {describe_text(path_or_text, text)}")
        rows = [json_row(r) for r in d["rows"]] if isinstance(d["rows"], list) else d["rows"]
        horizon = math.nan if d["horizon"] is None else d["horizon"]
        return TradeoffResult(d["problem"], horizon, d["measure"], d["tolerance"], rows, d.get("cost", "time"),
                              notes=d.get("notes", []))

    def plot(self, path: str | Path, formats: Sequence[str] = ("png", "svg"),
             measure: str | None = None) -> list[Path]:
        """Work-precision plot (log-log; `measure` [its unit] against wall time [s] and against derivative
        evaluations, one line per method, a closed-form method as markers, a zero error or cost at the
        axis floor (a downward triangle), the tolerance as a dashed line, the recommendation circled,
        each run's own error estimate (of the sweep's measure) as a bar from its true error, the legend
        outside the axes); written as path.<format> for each format. Needs matplotlib (pip install
        'rigiddyn[plot]'). Returns the files written."""
        return plot(self, path, formats, measure)
