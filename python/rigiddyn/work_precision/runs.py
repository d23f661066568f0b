"""One run of a method on a case: its states, whether it diverged, its time per step and how well that repeats,
and its own error estimate beside the true error."""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from .case import Case
from .constants import LONG_RUN_SECONDS, MIN_TIMED_SECONDS


class StepCounter(Protocol):
    """What follows the steps of the runs (progress.Progress)."""

    def begin(self, steps: int, label: str) -> Callable[[int], None]: ...  # the run's progress(steps_done)

    def end(self, steps: int) -> None: ...


@dataclass
class Run:
    """A run's states, whether it diverged, its fastest time per step [s] over the repeats and the gap
    to the second fastest relative to it (nan if timed once)."""

    states: Any  # States, or SceneStates of a scene
    quaternion_norm_error: np.ndarray
    diverged: bool
    time_per_step: float
    time_noise: float = math.nan


def simulate_quietly(case: Case, method: str, dt: float, steps: int, record_every: int,
                     progress: Callable[[int], None] | None = None, error: bool = False) -> Any:
    """case.simulate without its non-finite and convergence warnings (the sweep's rows say them); `error`:
    with the run's error estimate (result.error)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="simulate: the state became non-finite", category=RuntimeWarning)
        warnings.filterwarnings("ignore", message="simulate: the implicit solve", category=RuntimeWarning)
        return case.simulate(method, dt, steps, record_every, progress, error=error)


def run(case: Case, method: str, dt: float, steps: int, record_every: int, timed: bool,
        bar: StepCounter | None = None) -> Run:
    """One run of `method`; timed: repeated (up to 5 times, until MIN_TIMED_SECONDS, once if longer than
    LONG_RUN_SECONDS) keeping the fastest time per step and the repeats' spread. `bar` follows the steps."""
    times: list[float] = []
    for repeat in range(5 if timed else 1):
        at = bar.begin(steps, f"{method} dt={dt:.3g}") if bar is not None else None
        result = simulate_quietly(case, method, dt, steps, record_every, at)
        if bar is not None:
            bar.end(steps)
        times.append(result.elapsed_seconds / max(steps, 1))
        spent = sum(times) * max(steps, 1)
        if result.diverged or spent >= LONG_RUN_SECONDS or (repeat >= 1 and spent >= MIN_TIMED_SECONDS):
            break
    fastest = sorted(times)[:2]  # the gap between the two fastest: how well the minimum repeats
    best = fastest[0]
    noise = (fastest[1] - best) / best if len(fastest) > 1 and best > 0 else math.nan
    return Run(case.states(result), case.quaternion_norm_error(result), bool(result.diverged), best, noise)


# the quantity of result.error (GlobalError) that estimates each error measure's quantity
_ESTIMATED = {"attitude_error": "attitude", "position_error": "position", "velocity_error": "velocity"}
# the verdict of a record whose estimate lies between two reliable records (GlobalError's verdicts)
_BETWEEN_RELIABLE = "interpolated between the reliable records"
NO_ESTIMATE = {"estimate": math.nan, "effectivity": math.nan}


def estimate_columns(case: Case, method: str, dt: float, steps: int, record_every: int, measure: str,
                     true: float) -> dict[str, Any]:
    """The columns estimate, effectivity and estimate_verdict of a run (rigiddyn.work_precision's docstring):
    an untimed run of `method` at dt with the same records as the timed one (the same states) and its error
    estimate, of `measure` (the largest over the bodies; max_: over the records too), against the true
    error `true`."""
    when, _, quantity = measure.partition("_")
    if quantity not in _ESTIMATED:
        return {**NO_ESTIMATE,
                "estimate_verdict": f"no estimate of {measure} (estimated: attitude, position, velocity errors)"}
    error = simulate_quietly(case, method, dt, steps, record_every, error=True).error
    verdicts = list(error.verdict)
    values = np.asarray(getattr(error, _ESTIMATED[quantity]), float).reshape(len(verdicts), -1).max(axis=1)
    # a record's estimate of the quantity is reliable where its own check is (reliable_for: a record whose verdict
    # fails on another quantity, e.g. an energy that a damper does not conserve, may still hold it), or where the
    # record lies between two records reliable as a whole
    held = np.array(error.reliable_for(_ESTIMATED[quantity]), bool).reshape(-1)
    held |= np.array([v.startswith(_BETWEEN_RELIABLE) for v in verdicts], bool)
    if when == "final":
        estimate, verdict = float(values[-1]), "reliable" if held[-1] else verdicts[-1]
    else:  # the largest estimate, reliable when every record's is
        estimate = float(np.max(values)) if np.all(np.isfinite(values)) else math.nan
        verdict = next((v for v, ok in zip(verdicts, held) if not ok), "reliable")
    effectivity = estimate / true if true > 0 else (math.inf if estimate > 0 else math.nan)
    return {"estimate": estimate, "effectivity": effectivity, "estimate_verdict": verdict}
