"""The recommendation of a sweep: the cheapest run that meets the tolerance, or why none does."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from .._measures import measure_unit
from .ranking import ranking_rule
from .text import fmt


def _cost_text(r: Mapping[str, Any]) -> str:
    """The run's cost: total time (and per step, except for a closed form, which has no step) and
    derivative evaluations."""
    per_step = "" if r.get("order") == 0 else f" ({fmt(r['time_per_step'] * 1e9)} ns/step)"
    return f"{fmt(r['total_time'])} s{per_step}, {r['total_evaluations']} derivative evaluations"


def _run_name(r: Mapping[str, Any]) -> str:
    """`method with dt = ... s (n steps)`, or `exact (closed form)` for a method of order 0."""
    if r.get("order") == 0:
        return f"{r['method']} (closed form)"
    return f"{r['method']} with dt = {fmt(r['dt'])} s ({r['steps']} steps)"


def _unit_text(measure: str) -> str:
    unit = measure_unit(measure)
    return "" if unit == "-" else f"{unit} "


@dataclass
class Recommendation:
    """The cheapest run of a sweep that meets its tolerance, as ``TradeoffResult.recommend`` chooses it.

    The cheapest (method, dt) whose `measure` is <= tolerance (row is None if none is), `cost` ranked as
    ``cheapest`` does with the sweep's relative timing `noise`. ``str()`` says it in a sentence.

    Parameters
    ----------
    measure : str
        The error measure, one of ``MEASURES``.
    tolerance : float
        Its bound (in the measure's unit).
    cost : {"time", "evaluations"}
        What was minimised.
    row : dict or None
        The recommended run's row; None if no run meets the tolerance.
    best : dict or None
        The most accurate run (for "none meets it"); None if every run diverged.
    noise : float, default 0
        The relative timing noise the ranking used.

    See Also
    --------
    TradeoffResult.recommend, cheapest

    Examples
    --------
    >>> result = rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=1.0, progress=False)
    >>> recommendation = result.recommend(1e-3)
    >>> recommendation.met, recommendation.row["method"]
    (True, 'rk4')
    """

    measure: str
    tolerance: float
    cost: str
    row: dict[str, Any] | None
    best: dict[str, Any] | None  # the most accurate run, for "none meets it"
    noise: float = 0.0

    @property
    def met(self) -> bool:
        """True if a run meets the tolerance."""
        return self.row is not None

    def __str__(self) -> str:
        if self.row is not None:
            r = self.row
            return (f"recommendation: {_run_name(r)}: {self.measure} = {fmt(r[self.measure])} "
                    f"{_unit_text(self.measure)}<= tolerance {fmt(self.tolerance)}, cost {_cost_text(r)}; "
                    f"reference ({r['reference']}) error {fmt(r['reference_error'])}; "
                    f"{ranking_rule(self.cost, self.noise)}")
        if self.best is None:
            return f"recommendation: none; every run diverged ({self.measure}, tolerance {fmt(self.tolerance)})"
        b = self.best
        text = (f"recommendation: none meets {self.measure} <= {fmt(self.tolerance)}; best is {_run_name(b)}: "
                f"{self.measure} = {fmt(b[self.measure])} at {fmt(b['total_time'])} s")
        if str(b.get("reference", "")).startswith("unreliable"):
            return (text + f"; its reference is unreliable (error {fmt(b['reference_error'])}, see the reference "
                    f"checks): errors below it cannot be measured")
        return text + "; try smaller steps or a higher-order method"
