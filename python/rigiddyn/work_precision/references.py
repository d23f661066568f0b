"""The reference a sweep measures against where there is no closed form: the best method refined by Richardson
extrapolation, checked against an independent reference (DOP853, else the core's other method family)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .case import Case
from .constants import CHECK_FACTOR, CHECK_HALVINGS, REFERENCE_TARGET, ROUND_OFF_PER_STEP
from .runs import Run, StepCounter, run
from .states import Independent
from .text import fmt


def family(method: str) -> str:
    """The method's family, for the independent check: splittings (kick and free flow), Runge-Kutta,
    or the method itself (implicit midpoint, the semi-implicit Eulers)."""
    if "splitting" in method or method == "exact_flow_kick":
        return "splitting"
    if method in ("explicit_euler", "rk4", "rkmk4"):
        return "runge-kutta"
    return method


def best(candidates: Iterable[str], info: Mapping[str, Mapping[str, Any]]) -> str | None:
    """The highest-order method of `candidates` (ties to one that keeps SO(3) exactly), None if empty."""
    return max(candidates, key=lambda m: (info[m]["order"], "SO(3)" in info[m]["conserves"]), default=None)


def reference_methods(case: Case, info: Mapping[str, Mapping[str, Any]]) -> tuple[str, str | None]:
    """The Richardson reference's method (the best that runs the case without a warning) and the best
    such method of another family, for the check (None if there is none)."""
    clean = [m for m in info if info[m]["order"] > 0 and not case.refusal(m) and not case.compile_warnings(m)]
    ref_method = best(clean, info)
    if ref_method is None:
        raise ValueError(f"problem: expected a scene that a method of order >= 1 runs without a compatibility "
                         f"warning, got {case.name!r} (" + "; ".join(f"{m}: {case.refusal(m) or 'warned'}"
                                                                     for m in info) + ")")
    return ref_method, best([m for m in clean if family(m) != family(ref_method)], info)


@dataclass
class Reference:
    """A refined reference: its states, the Richardson estimate of its error per measure, the
    refinement sub (its finest step is dt / sub) and the record_every of that finest run."""

    states: Any  # States, or SceneStates of a scene
    estimate: dict[str, float]
    sub: int
    record_every: int


def richardson_reference(case: Case, method: str, order: int, dt: float, steps: int, record_every: int,
                         runs: Sequence[Run], max_steps: int, bar: StepCounter | None = None) -> Reference:
    """`method` at dt/2^j, j = 1, 2, ..., until the Richardson estimate |y_{h/2} - y_h| / (2^p - 1) of
    max_state_error is below REFERENCE_TARGET x every run's error, hits round-off, or the next refinement
    would exceed max_steps."""
    zeros = np.zeros(1)
    sub = 2
    coarse = run(case, method, dt / sub, steps * sub, record_every * sub, timed=False, bar=bar)
    while True:
        fine = run(case, method, dt / (2 * sub), steps * 2 * sub, record_every * 2 * sub, timed=False, bar=bar)
        sub *= 2
        if fine.diverged or coarse.diverged:
            coarse = fine
            if steps * 2 * sub > max_steps:
                raise RuntimeError(f"reference: {method} diverged even at dt = {dt / sub:.3g} s")
            continue
        estimate = {k: v / (2**order - 1) for k, v in case.measures(fine.states, coarse.states, zeros).items()}
        errors = [case.measures(r.states, fine.states, zeros)["max_state_error"] for r in runs if not r.diverged]
        target = REFERENCE_TARGET * min(errors, default=0.0)
        if estimate["max_state_error"] <= max(target, 1e-14) or steps * 2 * sub > max_steps:
            return Reference(fine.states, estimate, sub, record_every * sub)
        coarse = fine


def family_reference(case: Case, method: str, order: int, dt: float, steps: int, every: int,
                     bar: StepCounter | None) -> Independent:
    """`method` at dt and 2 dt (steps, every: at dt; both even) with its Richardson error estimate."""
    fine = run(case, method, dt, steps, every, timed=False, bar=bar)
    coarse = run(case, method, 2 * dt, steps // 2, every // 2, timed=False, bar=bar)
    error = {k: (math.inf if fine.diverged or coarse.diverged else v / (2**order - 1))
             for k, v in case.measures(fine.states, coarse.states, np.zeros(1)).items()}
    return Independent(fine.states, error, f"{method}(dt={dt:.3g})")


def other_family_reference(case: Case, method: str, order: int, dt: float, steps: int, ref: Reference,
                           max_steps: int, bar: StepCounter | None) -> Independent:
    """`method` (of another family) with its Richardson error estimate, from the reference's finest step
    dt / ref.sub, halved while its estimate exceeds CHECK_FACTOR x the reference's (a lower-order method
    needs finer steps to say anything), at most CHECK_HALVINGS times and within max_steps."""
    sub = ref.sub
    while True:
        independent = family_reference(case, method, order, dt / sub, steps * sub, ref.record_every * sub // ref.sub,
                                       bar)
        wanted = CHECK_FACTOR * ref.estimate["max_state_error"]
        if (independent.error["max_state_error"] <= wanted or steps * sub * 2 > max_steps
                or sub >= ref.sub * 2**CHECK_HALVINGS):
            return independent
        sub *= 2


@dataclass
class Check:
    """The Richardson reference checked against an independent one: reliable, reference error per
    measure (max of the estimate and what the disagreement implies), and a sentence."""

    reliable: bool
    error: dict[str, float]
    text: str


def check_reference(case: Case, ref: Any, estimate: dict[str, float], independent: Independent, steps: int) -> Check:
    """Compare the reference (Richardson `estimate` of its error, `steps` steps) with `independent`.
    Their disagreement d bounds |e_ref| from below by d - e_ind; the reference is unreliable when that
    bound exceeds CHECK_FACTOR x the estimate (and the round-off of `steps` steps)."""
    d = case.measures(ref, independent.states, np.zeros(1))
    lower = {k: max(0.0, d[k] - independent.error.get(k, 0.0)) for k in d}
    error = {k: max(estimate.get(k, 0.0), lower[k]) for k in d}
    key = "max_state_error"
    reliable = lower[key] <= max(CHECK_FACTOR * estimate[key], ROUND_OFF_PER_STEP * steps)
    if reliable:
        text = f"{independent.name} agrees to {fmt(d[key])} (its error {fmt(independent.error.get(key, 0.0))})"
    else:
        text = (f"{independent.name} differs by {fmt(d[key])} (its error {fmt(independent.error.get(key, 0.0))}) "
                f"where the Richardson estimate is {fmt(estimate[key])}")
    return Check(reliable, error, text)


def check_references(case: Case, refs: Mapping[int, tuple[float, Reference]], info: Mapping[str, Mapping[str, Any]],
                     other: str | None, max_steps: int, bar: StepCounter) -> dict[int, Check]:
    """Each grid's Richardson reference (steps -> (dt, reference)) checked against an independent one: the
    case's own (DOP853 of a problem) over the record times of every grid at once, else `other`, a method of
    another family, from each reference's finest step."""
    times = np.unique(np.concatenate([ref.states.t for _, ref in refs.values()]))
    independent = case.independent(times)
    checks = {}
    for steps, (dt, ref) in refs.items():
        if independent is not None:
            second = independent(ref.states.t)
        elif other is None:
            checks[steps] = Check(True, ref.estimate, "no method of another family runs this scene without a warning: "
                                  "Richardson estimate only")
            continue
        else:
            second = other_family_reference(case, other, info[other]["order"], dt, steps, ref, max_steps, bar)
        checks[steps] = check_reference(case, ref.states, ref.estimate, second, steps * ref.sub)
    return checks
