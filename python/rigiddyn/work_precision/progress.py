"""The sweep's cost estimate (a timed probe of each method) and its progress bar in steps."""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from .case import Case
from .constants import PROBE_STEPS
from .runs import simulate_quietly
from .text import duration, fmt, wrap


def _probe(case: Case, method: str, dt: float, steps: int) -> float:
    """Wall time per step [s] of `method` at dt, from a short run (PROBE_STEPS steps at most)."""
    n = max(1, min(steps, PROBE_STEPS))
    return float(simulate_quietly(case, method, dt, n, n).elapsed_seconds / n)


@dataclass
class Estimate:
    """The sweep's steps (runs once each and the least reference work) and their wall time [s]."""

    steps: int
    seconds: float
    text: str


def estimate(case: Case, methods: Sequence[str], grid: Sequence[int], ref_method: str | None) -> Estimate:
    """Probe each method at the finest step, then sum steps x time per step over the sweep: each run
    once, and (ref_method) the least Richardson reference (2 and 4 x the steps) and its check."""
    finest = max(grid)
    dt = case.horizon / finest
    per_step = {m: _probe(case, m, dt, finest) for m in dict.fromkeys([*methods, *([ref_method] if ref_method else [])])}
    steps = sum(grid) * len(methods)
    seconds = sum(grid) * sum(per_step[m] for m in methods)
    if ref_method is not None:
        steps += 6 * sum(grid)
        seconds += 6 * sum(grid) * per_step[ref_method]
    probe = ", ".join(f"{m} {per_step[m] * 1e9:.3g}" for m in per_step)
    text = (f"tradeoff: {case.name}: {len(methods)} methods x {len(grid)} steps over {fmt(case.horizon)} s: "
            f"about {steps:.3g} steps, estimated {'>= ' if ref_method else ''}{duration(seconds)} "
            f"(probe, ns/step: {probe})")
    return Estimate(steps, seconds, text)


class Progress:
    """Steps done against the estimated total on stderr: tqdm if installed, else a plain bar; shown only
    when enabled (progress=True and stderr a terminal). `report`: the caller's progress(steps_done)
    instead (progress a callable), called with the steps done over the whole sweep."""

    def __init__(self, total: int, enabled: bool, report: Callable[[int], Any] | None = None) -> None:
        self.total, self.done, self.enabled, self.label = max(total, 1), 0, enabled, ""
        self.report = report
        self.base, self.started, self.shown = 0, time.perf_counter(), 0.0
        self.bar: Any = None
        if enabled:
            try:
                from tqdm import tqdm

                self.bar = tqdm(total=self.total, desc="tradeoff", unit="step", unit_scale=True, file=sys.stderr)
            except ImportError:
                pass

    def begin(self, steps: int, label: str) -> Callable[[int], None]:
        """Starts a run of `steps` steps; returns the callback simulate reports its steps done to."""
        self.base, self.label = self.done, label
        self.total = max(self.total, self.done + steps)

        def at(steps_done: int) -> None:
            self._show(self.base + steps_done)

        return at

    def end(self, steps: int) -> None:
        self._show(self.base + steps)

    def _show(self, done: int, force: bool = False) -> None:
        delta, self.done = done - self.done, done
        if self.report is not None:
            self.report(done)
            return
        if not self.enabled:
            return
        if self.bar is not None:
            self.bar.total = max(self.bar.total, done)
            self.bar.set_postfix_str(self.label, refresh=False)
            self.bar.update(delta)
            return
        now = time.perf_counter()
        if not force and now - self.shown < 0.1:
            return
        self.shown = now
        fraction = min(1.0, done / self.total)
        left = (now - self.started) * (1.0 - fraction) / fraction if fraction > 0 else math.inf
        width = 24
        bar = "#" * int(width * fraction) + "." * (width - int(width * fraction))
        print(f"\rtradeoff [{bar}] {100 * fraction:3.0f}% {done:.3g}/{self.total:.3g} steps, {duration(left)} left, "
              f"{self.label:<24}", end="", file=sys.stderr, flush=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
        elif self.enabled:
            self._show(self.done, force=True)
            print(file=sys.stderr)


def progress_bar(progress: bool | Callable[[int], Any], case: Case, methods: Sequence[str], grid: Sequence[int],
                 ref_method: str | None) -> Progress:
    """The sweep's progress: progress=True prints the estimated cost on stderr (estimate) and shows a bar
    while stderr is a terminal; a callable is called with the steps done; False shows nothing."""
    if callable(progress):
        return Progress(1, False, progress)
    total = 1
    if progress:
        cost = estimate(case, methods, grid, ref_method)
        print("\n".join(wrap(cost.text, 100)), file=sys.stderr, flush=True)
        total = cost.steps
    return Progress(total, bool(progress) and sys.stderr.isatty())
