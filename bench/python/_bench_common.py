"""Shared pieces of the Python benchmarks (bench/python/bench_*.py): the `--small` flag, best-of-N
timing, the uniform "ratio ..." line (the same shape bench/bench_main.cpp prints for the C++
benchmarks) and the import of the numpy reference from tests/reference."""

import argparse
import importlib
import sys
import time
from pathlib import Path


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
