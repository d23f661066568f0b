"""The sweep: every method at every step size on one case, each run measured against the reference, the rows
and the stability summary; `tradeoff`, the entrance."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import _core
from .._measures import MEASURES, _check_measure
from ..stability import StabilityWarning
from .case import Case, as_case
from .checks import check_count, check_cost, check_dts, check_names, check_positive, step_grid
from .constants import REFUSED, SAMPLES
from .orders import observed_orders
from .progress import Progress, progress_bar
from .references import Check, Reference, check_references, reference_methods, richardson_reference
from .result import TradeoffResult
from .runs import NO_ESTIMATE, Run, estimate_columns, run
from .text import fmt


@dataclass
class _Grid:
    """One step size of the sweep: its steps, dt [s], record_every, the runs by method and the Richardson
    reference (None where the closed form is the reference)."""

    steps: int
    dt: float
    every: int
    runs: dict[str, Run]
    ref: Reference | None

    def reference_at(self, case: Case, t: np.ndarray) -> Any:
        """The reference states at the record times t: the Richardson reference's (recorded at them), else
        the closed form's."""
        if self.ref is not None:
            return self.ref.states
        assert case.exact is not None, "a grid without a Richardson reference has a closed form"
        return case.exact.states(t)


def _run_grid(case: Case, methods: Sequence[str], steps: int, samples: int, ref_method: str | None,
              info: Mapping[str, Mapping[str, Any]], exact: set[str], max_reference_steps: int, bar: Progress) -> _Grid:
    """Every method at dt = horizon / steps, timed, and (ref_method) the Richardson reference refined against
    the methods with a truncation error (an exact one's round-off sets no target)."""
    dt = case.horizon / steps
    every = max(1, steps // samples)
    runs = {m: run(case, m, dt, steps, every, timed=True, bar=bar) for m in methods}
    ref = None if ref_method is None else richardson_reference(
        case, ref_method, info[ref_method]["order"], dt, steps, every,
        [r for m, r in runs.items() if m not in exact], max_reference_steps, bar)
    return _Grid(steps, dt, every, runs, ref)


def _reference_columns(case: Case, check: Check | None, ref_method: str | None, measure: str) -> dict[str, Any]:
    """reference, reference_error and reference_check of a grid's rows (check None: the closed form)."""
    if check is None:
        return {"reference": case.exact_label, "reference_error": 0.0, "reference_check": ""}
    reference = f"richardson({ref_method})" if check.reliable else f"unreliable: richardson({ref_method})"
    return {"reference": reference, "reference_error": check.error[measure], "reference_check": check.text}


def _refused_row(head: dict[str, Any], reason: str, reference: dict[str, Any]) -> dict[str, Any]:
    """The row of a method the case refuses: no cost, nan errors, the reason in order_note."""
    return {**head, "time_per_step": math.nan, "time_noise": math.nan, "total_time": math.nan,
            "total_evaluations": 0, **{k: math.nan for k in MEASURES}, "observed_order": math.nan,
            "order_note": REFUSED + reason, **reference, "diverged": False, "stability": "", **NO_ESTIMATE,
            "estimate_verdict": ""}


def _row(case: Case, g: _Grid, method: str, info: Mapping[str, Any], measure: str,
         reference: dict[str, Any]) -> dict[str, Any]:
    """The row of one run: its cost, its errors against the reference, its own estimate, its stability."""
    head: dict[str, Any] = {"method": method, "dt": g.dt, "steps": g.steps, "order": info["order"],
                            "evaluations_per_step": info["evaluations"]}
    reason = case.refusal(method)
    if reason:
        return _refused_row(head, reason, reference)
    r = g.runs[method]
    row = {**head, "time_per_step": r.time_per_step, "time_noise": r.time_noise,
           "total_time": r.time_per_step * g.steps, "total_evaluations": info["evaluations"] * g.steps}
    if r.diverged:
        row.update({k: math.inf for k in MEASURES}, **NO_ESTIMATE, estimate_verdict="the run diverged")
    else:
        row.update(case.measures(r.states, g.reference_at(case, r.states.t), r.quaternion_norm_error))
        row.update(estimate_columns(case, method, g.dt, g.steps, g.every, measure, row[measure]))
    row.update({"observed_order": math.nan, "order_note": "", **reference, "diverged": r.diverged,
                "stability": case.stability(method, g.dt, g.steps) or ""})
    return row


def stability_summary(unstable: Sequence[tuple[str, float, str]], subject: str = "for this spin") -> str:
    """One line per method from (method, dt [s], stability message) of the runs beyond a stability
    limit: its steps, and the message of its largest step (the full messages: the rows' `stability`)."""
    lines = [f"tradeoff: dt beyond the method's stability limit {subject} (rows marked 'unstable'; every "
             "run's reason: column stability of the CSV/JSON):"]
    for method in dict.fromkeys(m for m, _, _ in unstable):
        mine = sorted(((dt, text) for m, dt, text in unstable if m == method), reverse=True)
        dts = (", ".join(fmt(dt) for dt, _ in mine) + " s" if len(mine) <= 3 else
               f"{fmt(mine[0][0])} to {fmt(mine[-1][0])} s ({len(mine)} runs)")
        # the figure beyond the limit at the largest step: stability_message's text between ": " and "; "
        figure = mine[0][1].split(": ", 1)[-1].split("; ", 1)[0]
        lines.append(f"  {method} at dt = {dts}: at {fmt(mine[0][0])} s {figure}")
    return "\n".join(lines)


def sweep(case: Case, methods: list[str], grid: list[int], measure: str, tolerance: float | None,
          progress: bool | Callable[[int], Any], cost: str, samples: int, max_reference_steps: int,
          info: dict[str, dict[str, Any]]) -> TradeoffResult:
    """The sweep of rigiddyn.tradeoff (arguments checked by it; `grid`: the step counts): against the case's
    closed form where it has one, else against a Richardson reference checked against an independent one."""
    runnable = [m for m in methods if not case.refusal(m)]
    exact = case.exact_methods(info) & set(runnable)
    ref_method, other = (None, None) if case.exact is not None else reference_methods(case, info)
    bar = progress_bar(progress, case, runnable, grid, ref_method)
    try:
        grids = [_run_grid(case, runnable, steps, samples, ref_method, info, exact, max_reference_steps, bar)
                 for steps in grid]
        refs = {g.steps: (g.dt, g.ref) for g in grids if g.ref is not None}
        checks = check_references(case, refs, info, other, max_reference_steps, bar) if refs else {}
    finally:
        bar.close()
    rows = []
    for g in grids:
        reference = _reference_columns(case, checks.get(g.steps), ref_method, measure)
        rows += [_row(case, g, method, info[method], measure, reference) for method in methods]
    unstable = [(r["method"], r["dt"], r["stability"]) for r in rows if r["stability"]]
    observed_orders([r for r in rows if not r["order_note"].startswith(REFUSED)], measure, exact)
    rows.sort(key=lambda r: (methods.index(r["method"]), -r["dt"]))
    if unstable:
        warnings.warn(stability_summary(unstable, case.stability_subject), StabilityWarning, stacklevel=3)
    return TradeoffResult(case.name, case.horizon, measure, tolerance, rows, cost, notes=case.notes(methods))


def tradeoff(problem: Any, methods: Iterable[str] | None = None,
             dts: Iterable[float] | None = None, horizon: float | None = None,
             tolerance: float | None = None, measure: str | None = None,
             progress: bool | Callable[[int], Any] = True,
             cost: str = "time", samples: int = SAMPLES, max_reference_steps: int = 4_000_000,
             initial: Sequence[Any] | None = None) -> TradeoffResult:
    """Measure the speed–accuracy trade of integrators on a problem: every method at every dt, against a reference.

    Each run's cost (time, derivative evaluations) and errors (attitude, state, momentum, energy drift, ...)
    are measured against a reference: the exact solution where one exists (a torque-free body), else a
    Richardson-refined run checked against another method family. With a `tolerance`, the result recommends
    the cheapest run that meets it. The module docstring (``rigiddyn.work_precision``) describes the
    measures, the reference and the timing.

    Parameters
    ----------
    problem : Problem, str, pathlib.Path, Scene or SceneFile
        A ``Problem``, a problem file's path or a shipped example's name (``"t_handle"``); or a scene: a
        ``Scene`` with `initial` and `horizon`, the ``SceneFile`` ``load_scene`` returns, a scene file or a shipped
        scene's name. On a scene the reference is Richardson-refined (the best method that compiles without
        a warning) and checked against another method family; a method the scene refuses at compile gets rows
        "not applicable: <reason>" (``order_note``), compile warnings become the result's notes, and the
        errors are taken over the bodies.
    methods : iterable of str, optional
        Names from ``methods()``. Default: the file's ``[tradeoff]`` list, else every method that can run the
        problem (``exact`` only for a torque-free body whose forces are fixed in W; every method on a scene).
    dts : iterable of float, optional
        Steps [s]. Default: the file's, else eight halvings from dt·|ω| = 1 (a scene: from dt·ρ = 1, ρ the
        fastest spin or linear mode of its elements, ``rigiddyn.stability.scene_modes``, or from
        horizon / 16 if shorter). Each dt is adjusted to horizon / round(horizon / dt), so that every run
        ends exactly at the horizon.
    horizon : float, optional
        Duration of each run [s]. Default: the problem's (required for a ``Scene``).
    tolerance : float, optional
        The recommendation's criterion: the cheapest run whose `measure` is at most `tolerance`. None: no
        recommendation.
    measure : str, optional
        One of ``rigiddyn.work_precision.MEASURES``. Default: ``final_attitude_error`` [rad] (a scene:
        ``final_state_error``).
    progress : bool or callable, default True
        True: print the estimated cost on stderr first (a timed probe of each method), then a progress bar
        in steps while stderr is a terminal (tqdm if installed, else a plain one). False: nothing. A
        callable: ``progress(steps_done)``, as ``simulate``'s, with the steps done over the whole sweep (runs,
        repeats and references), called during each run as ``simulate`` calls its own and at each run's end;
        an exception it raises stops the sweep and propagates. No estimate is printed.
    cost : {"time", "evaluations"}, default "time"
        What the recommendation minimises. By time, times within the measured timing noise count as equal.
    samples : int, optional
        States compared per run (>= 1).
    max_reference_steps : int, default 4000000
        The Richardson reference's step budget.
    initial : sequence of body states, optional
        The initial states of a ``Scene``'s bodies.

    Returns
    -------
    TradeoffResult
        One row per method × dt (``rows``, dicts with the keys ``COLUMNS``) and the ``recommendation``;
        ``to_table()``, ``plot()``, ``to_csv()``, ``to_json()`` report them.

    Raises
    ------
    TypeError, ValueError
        An argument that is not valid (the message names it).
    KeyboardInterrupt
        Ctrl-C stops the sweep.

    Warns
    -----
    StabilityWarning
        One warning, with one line per method that has runs whose dt is beyond its linear stability limit
        (``rigiddyn.stability``; each run's message in its row's ``stability``); diverged runs get inf errors.

    See Also
    --------
    TradeoffResult : the rows, the recommendation, the plot.
    methods : the methods and their orders.

    Examples
    --------
    RK4 and the DLM splitting on the tumbling T-handle for 1 s, against its exact solution: halving dt
    shrinks RK4's attitude error, and RK4 at 10 ms already meets a tolerance of 1 mrad:

    >>> result = rd.tradeoff("t_handle", methods=["rk4", "splitting_dlm"], dts=[0.01, 0.005], horizon=1.0,
    ...                      progress=False, tolerance=1e-3)
    >>> [(row["method"], row["dt"]) for row in result.rows]
    [('rk4', 0.01), ('rk4', 0.005), ('splitting_dlm', 0.01), ('splitting_dlm', 0.005)]
    >>> bool(result.rows[1]["final_attitude_error"] < result.rows[0]["final_attitude_error"])
    True
    >>> result.recommendation.row["method"], result.recommendation.row["dt"]
    ('rk4', 0.01)
    """
    case = as_case(problem, horizon, initial)
    defaults = case.tradeoff
    info = {m["name"]: m for m in _core.methods()}
    methods = check_names(methods if methods is not None else defaults.get("methods", case.default_methods(info)), info)
    dts_name = "dts" if dts is not None else "horizon"  # what a step count out of range is due to
    dts = check_dts(dts if dts is not None else defaults.get("dts", case.default_dts()))
    measure = measure if measure is not None else defaults.get("measure", case.default_measure)
    _check_measure(measure)
    tolerance = tolerance if tolerance is not None else defaults.get("tolerance")
    if tolerance is not None:
        tolerance = check_positive(tolerance, "tolerance")
    if not isinstance(progress, (bool, np.bool_)) and not callable(progress):
        raise TypeError(f"progress: expected True, False or a callable progress(steps_done), got {progress!r}")
    check_cost(cost)
    samples = check_count(samples, "samples")
    max_reference_steps = check_count(max_reference_steps, "max_reference_steps")
    grid = step_grid(case.horizon, dts, dts_name)
    return sweep(case, methods, grid, measure, tolerance, progress, cost, samples, max_reference_steps, info)
