"""Ranking the runs: the sweep's timing noise, the cheapest run within it, the Pareto front of cost and error."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

import numpy as np

from .checks import check_cost, is_real
from .constants import NOISE_QUANTILE


def timing_noise(rows: Iterable[Mapping[str, Any]]) -> float:
    """The sweep's relative timing noise: how well the runs' times repeat.

    The NOISE_QUANTILE quantile of the rows' ``time_noise`` (the gap between the two fastest of each run's
    repeated timings, relative to the fastest).

    Parameters
    ----------
    rows : iterable of dict
        Rows of a ``TradeoffResult`` (a row without a finite ``time_noise`` is skipped).

    Returns
    -------
    float
        The relative noise (dimensionless), 0 if no run was timed twice.

    See Also
    --------
    cheapest : ranks times equal within this noise by derivative evaluations.

    Examples
    --------
    >>> from rigiddyn.work_precision import timing_noise
    >>> round(timing_noise([{"time_noise": 0.01}, {"time_noise": 0.03}, {"time_noise": float("nan")}]), 3)
    0.028
    """
    spreads = [float(r["time_noise"]) for r in rows
               if is_real(r.get("time_noise")) and math.isfinite(r["time_noise"])]
    return float(np.quantile(spreads, NOISE_QUANTILE)) if spreads else 0.0


def _equal_within(t_a: float, t_b: float, noise: float) -> bool:
    """Two times [s] equal within the relative noise: the ranges t (1 +- noise) overlap."""
    low, high = min(t_a, t_b), max(t_a, t_b)
    return high * (1.0 - noise) <= low * (1.0 + noise)


def cheapest(rows: Sequence[Mapping[str, Any]], cost: str = "time", noise: float = 0.0) -> Mapping[str, Any] | None:
    """The cheapest of a sweep's rows, in a ranking that timing noise cannot flip.

    cost 'evaluations': fewest total_evaluations, then steps. cost 'time': among the rows whose
    total_time equals the fastest's within the relative `noise` (ranges t (1 ± noise) overlap), the
    fewest total_evaluations, then steps, then time.

    Parameters
    ----------
    rows : sequence of dict
        Rows with total_time [s], total_evaluations and steps.
    cost : {"time", "evaluations"}, default "time"
        What to minimise.
    noise : float, default 0
        Relative timing noise (finite, >= 0; ``timing_noise`` of the sweep).

    Returns
    -------
    dict or None
        The cheapest row, None if `rows` is empty.

    Raises
    ------
    TypeError, ValueError
        A cost or noise that is not valid (the message names it).

    See Also
    --------
    timing_noise, pareto_front

    Examples
    --------
    Within 10 % noise the two times are equal, and fewer evaluations win:

    >>> from rigiddyn.work_precision import cheapest
    >>> rows = [{"total_time": 1.0, "total_evaluations": 400, "steps": 100},
    ...         {"total_time": 1.05, "total_evaluations": 200, "steps": 100}]
    >>> cheapest(rows, "time", noise=0.1)["total_evaluations"]
    200
    """
    check_cost(cost)
    if not is_real(noise):
        raise TypeError(f"noise: expected a relative timing noise (a finite number >= 0), got {noise!r}")
    if not (math.isfinite(noise) and noise >= 0):
        raise ValueError(f"noise: expected a relative timing noise (a finite number >= 0), got {noise!r}")
    if not rows:
        return None
    if cost == "evaluations":
        return min(rows, key=lambda r: (r["total_evaluations"], r["steps"], r["total_time"]))
    fastest = min(r["total_time"] for r in rows)
    tied = [r for r in rows if _equal_within(r["total_time"], fastest, noise)]
    return min(tied, key=lambda r: (r["total_evaluations"], r["steps"], r["total_time"]))


def pareto_front(points: Sequence[tuple[float, float]]) -> list[int]:
    """The non-dominated (cost, error) points: those no other point beats in both.

    No other point has cost and error both <= and one of them <; equal points are all kept.

    Parameters
    ----------
    points : sequence of (float, float)
        (cost, error) pairs.

    Returns
    -------
    list of int
        Indices into `points` of the front, by ascending cost.

    See Also
    --------
    TradeoffResult.pareto : the front of a sweep's runs.

    Examples
    --------
    >>> from rigiddyn.work_precision import pareto_front
    >>> pareto_front([(1.0, 1e-3), (2.0, 1e-6), (3.0, 1e-5)])
    [0, 1]
    """
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front: list[int] = []
    for i in order:
        cost, error = points[i]
        if not front:
            front.append(i)
            continue
        last_cost, last_error = points[front[-1]]
        # sorted by cost: i is dominated iff an earlier point has error < its own, or equal error at lower cost
        if error < last_error or (error == last_error and cost == last_cost):
            front.append(i)
    return front


def ranking_rule(cost: str, noise: float) -> str:
    """How the recommendation ranked the runs, in words."""
    if cost == "evaluations":
        return "ranked by derivative evaluations, then steps"
    return (f"ranked by wall time, times equal within the timing noise ({100 * noise:.2g} %: the gap between "
            f"the two fastest repeats of a run, {100 * NOISE_QUANTILE:g}th percentile), then by fewer derivative "
            "evaluations")
