"""Shared pieces of the Python benchmarks (bench/python/bench_*.py): the `--small` flag, best-of-N
timing, wall and CPU timings of batch runs, the uniform "ratio ..." line (the same shape bench/bench_main.cpp
prints for the C++ benchmarks), the last states of MuJoCo rollouts and the import of the numpy reference from
tests/reference."""

import argparse
import importlib
import os
import sys
import time
from pathlib import Path

import numpy as np


def parse_small(doc, small_help):
    """Parse the command line of a benchmark script: only `--small` (the size ctest runs).
    `doc` is the script's docstring (its first line becomes the description); returns args."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--small", action="store_true", help=small_help)
    return parser.parse_args()


def best_time(fn, repeats=3):
    """The fastest of `repeats` calls of fn() [s] (the least disturbed by other load)."""
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


def per_call(fn, calls, rounds):
    """The least time per call of fn() [s] over `rounds` loops of `calls` calls (the least disturbed)."""
    best = float("inf")
    for _ in range(rounds):
        start = time.perf_counter()
        for _ in range(calls):
            fn()
        best = min(best, (time.perf_counter() - start) / calls)
    return best


def cores():
    """The cores this process may run on."""
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


class Timing:
    """Wall time and CPU time of this process (every thread) from construction to stop() [s]. On a machine
    shared with other work the CPU time is the cost per core; the wall time is what a user waits."""

    def __init__(self):
        self.wall, self.cpu = time.perf_counter(), time.process_time()

    def stop(self):
        self.wall, self.cpu = time.perf_counter() - self.wall, time.process_time() - self.cpu
        return self


def fastest(timings):
    """The fastest wall time and the least CPU time of several Timings (the least disturbed by other load)."""
    best = Timing()
    best.wall, best.cpu = min(t.wall for t in timings), min(t.cpu for t in timings)
    return best


def mujoco_last_states(model, initial, steps, nthread, block=250):
    """(the last states (N, nstate) of `steps` steps of mujoco.rollout from `initial` (N, nstate), Timing of the
    rollout calls) on nthread threads (a persistent pool), `block` samples a call, so that the states rollout records
    (block x steps x nstate doubles) stay small."""
    import mujoco
    from mujoco import rollout

    datas = [mujoco.MjData(model) for _ in range(nthread)]
    last = np.empty_like(initial)
    out = np.empty((min(block, len(initial)), steps, initial.shape[1]))
    with rollout.Rollout(nthread=nthread) as runner:
        clock = Timing()
        for lo in range(0, len(initial), block):
            chunk = initial[lo:lo + block]
            state, _ = runner.rollout(model, datas if nthread > 1 else datas[0], chunk, nstep=steps,
                                      state=out[:len(chunk)])
            last[lo:lo + len(chunk)] = state[:, -1]
        clock.stop()
    return last, clock


def report_ratio(case, n, t_rd, t_other, other):
    """Print 'ratio <case>/<n>: rigiddyn X ns/op, <other> Y ns/op, rigiddyn/<other> = R' for total
    times t_rd, t_other [s] over n operations."""
    print(
        f"ratio {case}/{n}: rigiddyn {t_rd / n * 1e9:.2f} ns/op, {other} {t_other / n * 1e9:.2f} ns/op, "
        f"rigiddyn/{other} = {t_rd / t_other:.3f}"
    )


def import_reference(module):
    """rigiddyn_ref.<module> from PYTHONPATH (ctest) or from this checkout's tests/reference (run by
    hand); None if neither has it."""
    name = f"rigiddyn_ref.{module}"
    try:
        return importlib.import_module(name)
    except ImportError:
        sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tests" / "reference"))
        try:
            return importlib.import_module(name)
        except ImportError:
            return None
