"""The samples of a Monte Carlo run under a digital controller (rigiddyn.monte_carlo's ``controller``): each
sample is one rigiddyn.simulate of its drawn scene and states under its own copy of the controller, whose gyro
noise draws from a seed of its own, a function of (seed, i) only; the records stacked as simulate_batch stacks
them (arrays (N, n_records, ...)), and the samples' global error estimates as simulate_batch's GlobalError.
"""

from __future__ import annotations

import copy
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any

import numpy as np

from . import _core
from .control import Controller

_SEED_BOUND = 2**63  # a sample's controller seed is drawn in [0, 2^63)


def stacked_error(errors: Sequence[Any]) -> Any:
    """One GlobalError of N runs' estimates of equal length, as simulate_batch's: each array with a leading sample
    axis (N, n_records, ...), the verdict a tuple per sample; sample i's values are errors[i]'s. It is built from
    their pickle states (order, the seven arrays, verdict, reliable, reliable_quantities), the one way to make a
    GlobalError."""
    states = [e.__getstate__() for e in errors]
    arrays = [np.stack([s[k] for s in states]) for k in range(1, 8)]
    stacked = _core.GlobalError.__new__(_core.GlobalError)
    stacked.__setstate__((states[0][0], *arrays, tuple(s[8] for s in states), np.stack([s[9] for s in states]),
                          np.stack([s[10] for s in states])))
    return stacked


class StackedRuns:
    """The records of N scene runs of equal length, each field an array (N, n_records, ...) as a
    BatchSceneResult's (`fields`: the names stacked); error: their global error estimates `errors` (each run's
    GlobalError) as one (stacked_error), or None where the runs have none (``simulate(..., error=False)``)."""

    t: np.ndarray  # (N, n_records) record times [s], as every field set by __init__

    def __init__(self, runs: Sequence[Any], fields: Sequence[str], errors: Sequence[Any]) -> None:
        self.fields = tuple(f for f in fields if hasattr(runs[0], f))
        for f in self.fields:
            stacked = np.stack([np.asarray(getattr(r, f)) for r in runs])
            stacked.flags.writeable = False
            setattr(self, f, stacked)
        self.body_names = tuple(runs[0].body_names)
        self.error = None if errors[0] is None else stacked_error(errors)

    def __repr__(self) -> str:
        return f"StackedRuns(n={len(self.t)}, records={self.t.shape[1]})"


def controller_seeds(seeds: np.random.SeedSequence, n: int) -> np.ndarray:
    """(n,) the controllers' noise seeds: sample i's drawn from SeedSequence(entropy, spawn_key + (i, 0)), a
    grandchild of the sample's own SeedSequence (independent of its dispersion draws, a function of (seed, i))."""
    return np.array([np.random.default_rng(np.random.SeedSequence(seeds.entropy, spawn_key=(*seeds.spawn_key, i, 0)))
                     .integers(_SEED_BOUND) for i in range(n)], dtype=np.int64)


class _Stopped(Exception):
    """A sample stopped because another failed (or the call was interrupted)."""


def run_samples(models: Any, initial: Sequence[Any], dt: Any, steps: int, controller: Controller,
                seeds: np.ndarray, options: dict[str, Any], fields: Sequence[str],
                progress: Callable[[int], Any] | None, threads: int = 1) -> StackedRuns:
    """Sample i run by rigiddyn.simulate (`models`: one Scene or CompiledScene for all, or a list of one per
    sample) under a copy of `controller` (its law deep-copied: a law's memory, as BDot's last sample, starts
    afresh) with seed seeds[i], with simulate's `options` (`error` too: each sample's estimate is simulate's for
    it, made right after its run); progress(samples_done) from the calling thread after each.

    `threads` samples run at once (each simulate releases the GIL while it steps: a law in C++ runs in parallel, a
    law in Python takes the GIL at its samples, from that many threads). The samples are independent, so the result
    is the same, bit for bit, whatever `threads`. An exception a sample raises (or Ctrl-C) stops the others at their
    next progress check (about every 0.05 s) and propagates."""

    def sample(i: int, check: Callable[[int], Any] | None) -> tuple[Any, Any]:
        model = models[i] if isinstance(models, list) else models
        own = Controller(controller.period, copy.deepcopy(controller.law), w_B_noise=controller.w_B_noise,
                         seed=int(seeds[i]), repeatable=controller.repeatable)
        run = _core.simulate(model, initial[i], dt, steps, controller=own, progress=check, **options)
        return run, run.error  # a run under a law in C++ makes its estimate on this first read

    n = len(initial)
    done: list[Any] = [None] * n  # (run, its estimate) of each sample
    if threads == 1:
        for i in range(n):
            done[i] = sample(i, None)
            if progress is not None:
                progress(i + 1)
    else:
        stop = threading.Event()

        def check(steps_done: int) -> None:
            if stop.is_set():
                raise _Stopped

        pool = ThreadPoolExecutor(min(threads, n))
        futures = {pool.submit(sample, i, check): i for i in range(n)}
        try:
            for count, future in enumerate(as_completed(futures), 1):
                done[futures[future]] = future.result()
                if progress is not None:
                    progress(count)
        except BaseException:
            stop.set()
            pool.shutdown(wait=True, cancel_futures=True)
            raise
        pool.shutdown()
    return StackedRuns([run for run, _ in done], fields, [error for _, error in done])
