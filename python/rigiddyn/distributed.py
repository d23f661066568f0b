"""Batches, Monte Carlo chunks and tradeoff grids on a Dask cluster (``pip install 'rigiddyn[distributed]'``).

Four functions (and the helpers chunk_size_for, concatenate, ChunksFailedError):

- `simulate_batch(model, initial, dt, steps, *, client=None, ...)`: rigiddyn.simulate_batch split into
  chunks of consecutive samples, one Dask task per chunk; the result is the local batch's BITWISE (each
  sample runs the same single-run code; the chunks are concatenated in sample order).
- `map_samples(function, n_samples, *, client=None, ...)`: the primitive under it, for any per-sample
  computation (a Monte Carlo's chunks: rigiddyn.monte_carlo with client= draws every sample first, then
  runs simulate_batch). Contract of `function`: ``function(chunk_start, chunk_stop)`` computes samples
  ``chunk_start <= i < chunk_stop`` and returns a piece: a numpy array (samples along axis 0), a list
  (one item per sample), a tuple or dict of pieces, or a result with a len and a tuple or dict pickle
  state (a BatchSceneResult; see `concatenate`); the pieces are concatenated in sample
  order, so the result depends only on n_samples, never on the chunking, provided sample i depends only
  on i (e.g. ``numpy.random.SeedSequence(entropy).spawn(n)[i]``). The function is sent once per worker
  (pickled with cloudpickle, as Dask does); each task carries only (start, stop).
- `tradeoff_grid(problem, ...)`: rigiddyn.tradeoff with each step size of its grid as a task; the same
  rows (errors, references, observed orders) as the local sweep, times measured on the workers.
- `measure_task_overhead(client)`: the cost of one task on a client [s].

client: None (a LocalCluster of this machine's cores as processes, one thread each, started for the
call and closed after it: about 2-5 s to start on a 2-core machine), a ``distributed.Client``, or a
scheduler address ("tcp://host:8786"; a Client connected for the call and closed after it).

Chunk size (chunk_size=None): a task costs a fixed overhead o [s] (scheduling, transfer; measured by
`measure_task_overhead`: a few ms on a 2-core machine) plus k c for k samples of c seconds each (c is
timed on the cluster by a first probe task on the first samples, whose results are kept). Overhead at
most 5 % of a task's time means o <= 0.05 (o + k c), i.e. k >= 19 o / c; at least two tasks per worker
thread (so a slow or lost worker delays a small share) means k <= ceil(n_left / (2 threads)). The chunk
is k = max(1, min(ceil(19 o / c), ceil(n_left / (2 threads)))): when the samples are too few for both,
balance wins (the overhead is then more than 5 %, and the batch is short anyway).

Failures: a task that does not return (its worker process died: KilledWorker, a lost connection; or an
exception other than ValueError/TypeError) leaves the finished chunks' results in hand (they are
gathered as they finish) and is submitted again, up to `retries` more times (on a Dask cluster the
scheduler first re-runs a task whose worker died by itself, up to its ``allowed-failures`` setting, 3 by
default). Chunks that still fail raise `ChunksFailedError` naming their samples, with the finished
chunks in its ``completed``. A ValueError/TypeError from a task is bad input, the same on every try: it
is not retried; after the round, the one of the lowest samples is raised naming them (a batch's
"sample i: ..." renumbered within the whole batch).

Warnings a task raises (RuntimeWarning, UserWarning and theirs) are raised once each in the caller;
simulate_batch's own (non-finite samples, unconverged implicit steps) once for the whole batch.

Without dask.distributed installed every function runs on this machine instead (rigiddyn.simulate_batch
on all cores; map_samples in one chunk; rigiddyn.tradeoff) after one RuntimeWarning saying so.
"""

from __future__ import annotations

import importlib
import math
import re
import time
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["ChunksFailedError", "chunk_size_for", "concatenate", "map_samples", "measure_task_overhead",
           "simulate_batch", "tradeoff_grid"]

FALLBACK_MESSAGE = ("rigiddyn.distributed: dask.distributed is not installed (pip install 'rigiddyn[distributed]'); "
                    "running on this machine's threads")
OVERHEAD_SHARE = 0.05  # a task's fixed overhead is at most this share of its time (chunk_size None)
TASKS_PER_WORKER = 2  # at least this many tasks per worker thread (chunk_size None)
PROBE_SECONDS = 1e-3  # the per-sample cost is timed on samples worth at least this long [s] (or on all)
_BATCH_WARNING = "simulate_batch: "  # the local batch's warnings: made once for the whole batch (_batch_warnings)


class ChunksFailedError(RuntimeError):
    """Chunks of samples that failed on every try: `failed` maps (start, stop) to the last exception of
    the chunk of samples start <= i < stop; `completed` maps (start, stop) to the pieces that finished."""

    def __init__(self, failed: Mapping[tuple[int, int], BaseException], completed: Mapping[tuple[int, int], Any],
                 attempts: int) -> None:
        self.failed, self.completed = dict(failed), dict(completed)
        spans = ", ".join(_span(a, b) for a, b in sorted(self.failed))
        first = self.failed[min(self.failed)]
        super().__init__(f"rigiddyn.distributed: samples {spans} failed on all {attempts} tries "
                         f"(last error of samples {_span(*min(self.failed))}: {type(first).__name__}: {first}); "
                         f"{sum(b - a for a, b in self.completed)} samples finished (ChunksFailedError.completed)")


def _span(start: int, stop: int) -> str:
    return str(start) if stop == start + 1 else f"{start}-{stop - 1}"


# ---------------------------------------------------------------------------------------------
# the client: None (a LocalCluster for the call), an address, or a Client


def _distributed() -> Any:
    """The dask.distributed module, or None when it (or dask) is not installed (an optional dependency:
    imported by name, so that the package type-checks without it)."""
    try:
        return importlib.import_module("distributed")
    except ImportError:
        return None


def _fallback() -> None:
    warnings.warn(FALLBACK_MESSAGE, RuntimeWarning, stacklevel=3)


@contextmanager
def _client_for(client: Any, distributed: Any) -> Iterator[Any]:
    """The Client to run on: `client` itself, a Client of the address `client`, or of a LocalCluster
    (processes, one thread per core) started here; what is started here is closed on leaving."""
    if isinstance(client, distributed.Client):
        yield client
        return
    if client is None:
        from os import cpu_count

        with distributed.LocalCluster(n_workers=max(1, cpu_count() or 1), threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, distributed.Client(cluster) as own:
            yield own
        return
    if isinstance(client, str):
        try:
            own = distributed.Client(client)
        except ValueError as error:  # dask's own words do not say which argument held the address
            raise ValueError(f"client: expected a scheduler address such as 'tcp://host:8786', got {client!r} "
                             f"({error})") from None
        with own:
            yield own
        return
    raise TypeError(f"client: expected None, a distributed.Client or a scheduler address (str), got {client!r}")


def _check_client(client: Any) -> None:
    """TypeError unless `client` is None, a str or (dask installed) a Client; checked before any work."""
    distributed = _distributed()
    if client is None or isinstance(client, str):
        return
    if distributed is not None and isinstance(client, distributed.Client):
        return
    raise TypeError(f"client: expected None, a distributed.Client or a scheduler address (str), got {client!r}")


def _worker_threads(client: Any) -> int:
    """The threads of all the client's workers (at least 1)."""
    return max(1, sum(int(w.get("nthreads", 1)) for w in client.scheduler_info()["workers"].values()))


def _noop() -> None:
    return None


def measure_task_overhead(client: Any, tasks: int | None = None) -> float:
    """The fixed cost of one Dask task on `client` (a distributed.Client) [s]: the wall time of `tasks`
    empty tasks submitted together (default 10 per worker thread, at least 20; after a warm-up round),
    divided by `tasks` and multiplied by the worker threads, i.e. the time each task takes from a worker
    thread beyond its own work. Measured on a 2-worker LocalCluster of a 2-core machine: 4-17 ms under a
    load average of 10 (docs/distributed.md); 1.6-2.1 ms idle."""
    distributed = _distributed()
    if distributed is None or not isinstance(client, distributed.Client):
        raise TypeError(f"client: expected a distributed.Client, got {client!r}")
    threads = _worker_threads(client)
    n = max(20, 10 * threads) if tasks is None else _check_int(tasks, "tasks", 1)
    client.gather([client.submit(_noop, pure=False) for _ in range(threads)])  # warm-up: connections, imports
    start = time.perf_counter()
    client.gather([client.submit(_noop, pure=False) for _ in range(n)])
    return (time.perf_counter() - start) * threads / n


# ---------------------------------------------------------------------------------------------
# argument checks


def _check_int(x: Any, name: str, least: int) -> int:
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise TypeError(f"{name}: expected an int >= {least}, got {x!r}")
    if x < least:
        raise ValueError(f"{name}: expected an int >= {least}, got {x!r}")
    return int(x)


def _check_common(chunk_size: Any, retries: Any, progress: Any) -> tuple[int | None, int, bool]:
    if not isinstance(progress, (bool, np.bool_)):
        raise TypeError(f"progress: expected True or False, got {progress!r}")
    size = None if chunk_size is None else _check_int(chunk_size, "chunk_size", 1)
    return size, _check_int(retries, "retries", 0), bool(progress)


def _check_picklable(x: Any, name: str) -> None:
    """ValueError naming `name` unless `x` pickles as Dask sends it (distributed.protocol.pickle: pickle,
    else cloudpickle, which also sends lambdas and functions of __main__ by value)."""
    try:
        _distributed().protocol.pickle.dumps(x)
    except Exception as error:  # noqa: BLE001 - whatever stops pickling is the user's to know
        raise ValueError(f"{name}: expected an object that pickles (it is sent to the Dask workers), got {x!r}, "
                         f"which does not: {type(error).__name__}: {error}") from None


# ---------------------------------------------------------------------------------------------
# running chunks as tasks, with retries and a progress bar


class _Bar:
    """Samples done on stderr with tqdm when installed and enabled; nothing otherwise."""

    def __init__(self, total: int, enabled: bool, label: str, unit: str) -> None:
        self.bar: Any = None
        if enabled:
            try:
                from tqdm import tqdm
            except ImportError:
                return
            self.bar = tqdm(total=total, desc=label, unit=unit, unit_scale=True)

    def update(self, n: int) -> None:
        if self.bar is not None:
            self.bar.update(n)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


@dataclass
class _Done:
    """A finished chunk: its piece, the task's own time [s] and the warnings it raised (category, text)."""

    piece: Any
    seconds: float
    warned: list[tuple[type[Warning], str]]


def _execute(function: Callable[..., Any], start: int, stop: int, payload: Any) -> _Done:
    """Runs on a worker: function(start, stop) (or function(start, stop, payload) when a payload is
    sent), timed, its warnings recorded to be raised once by the caller."""
    with warnings.catch_warnings(record=True) as caught:
        for category in (RuntimeWarning, UserWarning):  # rigiddyn's kinds: each call's own, as a local call shows them
            warnings.filterwarnings("always", category=category)
        began = time.perf_counter()
        piece = function(start, stop) if payload is None else function(start, stop, payload)
        seconds = time.perf_counter() - began
    return _Done(piece, seconds, [(w.category, str(w.message)) for w in caught])


_SAMPLE_PREFIX = re.compile(r"^sample (\d+): ")


def _renumbered(error: BaseException, start: int, stop: int) -> BaseException:
    """A task's ValueError/TypeError for the whole run: "sample i: ..." of a chunk becomes "sample
    start+i: ...", any other message is prefixed with the chunk's samples."""
    text = str(error)
    match = _SAMPLE_PREFIX.match(text)
    if match:
        text = f"sample {start + int(match.group(1))}: " + text[match.end():]
    else:
        text = f"samples {_span(start, stop)}: {text}"
    return type(error)(text)


class _Chunks:
    """Runs chunks of samples of one function as Dask tasks on `client`: the function scattered to every
    worker once per round, (start, stop, payload) per task; results gathered as they finish."""

    def __init__(self, client: Any, function: Callable[..., Any], payload: Callable[[int, int], Any] | None,
                 retries: int, bar: _Bar) -> None:
        self.client, self.function, self.payload, self.retries, self.bar = client, function, payload, retries, bar
        self.done: dict[tuple[int, int], _Done] = {}

    def run(self, chunks: Sequence[tuple[int, int]]) -> None:
        """Runs `chunks` ((start, stop) each) to completion, retrying those whose task failed."""
        distributed = _distributed()
        pending, errors = list(chunks), dict[tuple[int, int], BaseException]()
        for _ in range(1 + self.retries):
            if not pending:
                break
            # scattered afresh each round: a round after lost workers must not depend on data they held
            function = self.client.scatter(self.function, broadcast=True, hash=False)
            futures = {self.client.submit(_execute, function, a, b, self.payload(a, b) if self.payload else None,
                                          pure=False, retries=0): (a, b) for a, b in pending}
            errors, refused = dict[tuple[int, int], BaseException](), dict[tuple[int, int], BaseException]()
            try:
                # on this client's own loop: as_completed's default is the default client's, which is another
                # client's where one was opened later, and its gathers there stalled 5 s a round or hung
                finished = distributed.as_completed(futures, loop=self.client.loop, with_results=True,
                                                    raise_errors=False)
                for future, value in finished:
                    chunk = futures.pop(future)  # released: the worker frees the piece, now held here
                    if future.status == "finished":
                        self.done[chunk] = value
                        self.bar.update(chunk[1] - chunk[0])
                        continue
                    error = _exception_of(value)
                    # bad input is the same on every try: not retried
                    (refused if isinstance(error, (ValueError, TypeError)) else errors)[chunk] = error
            finally:
                self.client.cancel(list(futures))  # those not finished (after an interrupt or bad input)
                del function
            if refused:  # the error of the lowest sample, whatever order the chunks finished in
                first = min(refused)
                raise _renumbered(refused[first], *first) from refused[first]
            pending = sorted(errors)
        if errors:
            raise ChunksFailedError(errors, {c: d.piece for c, d in self.done.items()}, 1 + self.retries)

    def pieces(self) -> list[Any]:
        """The finished pieces in sample order."""
        return [self.done[c].piece for c in sorted(self.done)]

    def reraise_warnings(self) -> None:
        """Each distinct warning the tasks raised, once."""
        seen = dict.fromkeys((w for c in sorted(self.done) for w in self.done[c].warned))
        for category, text in seen:
            warnings.warn(text, category, stacklevel=3)


def _exception_of(value: Any) -> BaseException:
    """The exception of a failed future from as_completed(raise_errors=False): (type, exception, traceback)."""
    if isinstance(value, tuple) and len(value) == 3 and isinstance(value[1], BaseException):
        return value[1]
    return value if isinstance(value, BaseException) else RuntimeError(f"the task failed: {value!r}")


def chunk_size_for(overhead: float, per_sample: float, n_samples: int, threads: int) -> int:
    """Samples per task for n_samples samples of per_sample seconds each on `threads` worker threads, a
    task costing `overhead` seconds besides (measure_task_overhead): the overhead at most OVERHEAD_SHARE
    of a task's time, o <= 0.05 (o + k c), i.e. k >= 19 o / c, but at least TASKS_PER_WORKER tasks per
    worker thread, k <= ceil(n / (2 threads)); balance wins when both cannot hold."""
    for value, name in ((overhead, "overhead"), (per_sample, "per_sample")):
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
            raise ValueError(f"{name}: expected a finite time >= 0 [s], got {value!r}")
    n, threads = _check_int(n_samples, "n_samples", 1), _check_int(threads, "threads", 1)
    amortised = math.ceil((1 - OVERHEAD_SHARE) / OVERHEAD_SHARE * overhead / max(per_sample, 1e-12))
    balanced = math.ceil(n / (TASKS_PER_WORKER * threads))
    return max(1, min(amortised, balanced))


def _chunk_plan(n: int, start: int, size: int) -> list[tuple[int, int]]:
    return [(a, min(a + size, n)) for a in range(start, n, size)]


def _run_map(client: Any, function: Callable[..., Any], payload: Callable[[int, int], Any] | None, n: int,
             chunk_size: int | None, retries: int, progress: bool, label: str, unit: str = "sample") -> _Chunks:
    """All n samples run as chunks on `client`; chunk_size None: sized by the module docstring's rule
    from measure_task_overhead and the per-sample cost of probe tasks on the first samples."""
    bar = _Bar(n, progress, label, unit)
    runner = _Chunks(client, function, payload, retries, bar)
    try:
        if chunk_size is not None:
            runner.run(_chunk_plan(n, 0, chunk_size))
            return runner
        overhead = measure_task_overhead(client)
        runner.run([(0, 1)])
        per_sample, done = runner.done[(0, 1)].seconds, 1
        if per_sample < PROBE_SECONDS and n > 1:  # too short to time alone: a second probe on more samples
            probe = (1, min(n, 1 + math.ceil(PROBE_SECONDS / max(per_sample, 1e-9))))
            runner.run([probe])
            per_sample, done = runner.done[probe].seconds / (probe[1] - probe[0]), probe[1]
        if done < n:
            runner.run(_chunk_plan(n, done, chunk_size_for(overhead, per_sample, n - done, _worker_threads(client))))
        return runner
    finally:
        bar.close()


# ---------------------------------------------------------------------------------------------
# concatenation of pieces in sample order


def concatenate(pieces: Sequence[Any]) -> Any:
    """The pieces of consecutive chunks as one: numpy arrays along axis 0, lists joined, tuples and
    dicts item by item; another object (a BatchSceneResult) by its class's
    ``concatenate(pieces)`` if it has one, else through its pickle state (a tuple or a dict): arrays with
    a leading sample axis (len(piece) rows) concatenated, equal items (labels) kept, float items (the
    elapsed time [s]) summed."""
    first = pieces[0]
    if isinstance(first, np.ndarray):
        return np.concatenate(pieces, axis=0)
    if isinstance(first, list):
        return [x for p in pieces for x in p]
    if isinstance(first, tuple):
        return tuple(concatenate(items) for items in zip(*pieces))
    if isinstance(first, dict):
        return {k: concatenate([p[k] for p in pieces]) for k in first}
    joined = getattr(type(first), "concatenate", None)
    if callable(joined):
        return joined(pieces)
    states = [_state(p) for p in pieces]
    if hasattr(first, "__len__") and isinstance(states[0], (tuple, dict)):
        sizes = [len(p) for p in pieces]
        if isinstance(states[0], dict):
            return _rebuilt(first, {k: _merge_item([x[k] for x in states], sizes) for k in states[0]})
        return _rebuilt(first, tuple(_merge_item(list(items), sizes) for items in zip(*states)))
    raise TypeError(f"function: expected pieces that concatenate (numpy arrays, lists, tuples, dicts, or results "
                    f"with a len and a tuple or dict pickle state), got {type(first).__name__}")


def _state(x: Any) -> Any:
    """x's pickle state: __getstate__() where defined, else its __dict__ (None without one)."""
    return x.__getstate__() if hasattr(x, "__getstate__") else getattr(x, "__dict__", None)


def _rebuilt(like: Any, state: Any) -> Any:
    """An object of like's class from a pickle state (as pickle rebuilds one)."""
    kind: Any = type(like)
    out = kind.__new__(kind)
    if hasattr(out, "__setstate__"):
        out.__setstate__(state)
    else:
        out.__dict__.update(state)
    return out


def _with_elapsed(result: Any, seconds: float) -> Any:
    """`result` with its elapsed_seconds [s] (the float of its pickle state) set to `seconds`."""
    state = _state(result)
    if isinstance(state, dict) and "elapsed_seconds" in state:
        return _rebuilt(result, {**state, "elapsed_seconds": seconds})
    if isinstance(state, tuple) and sum(isinstance(x, float) for x in state) == 1:
        return _rebuilt(result, tuple(seconds if isinstance(x, float) else x for x in state))
    return result


def _merge_item(items: list[Any], sizes: list[int]) -> Any:
    """One state item of pieces of `sizes` samples: arrays with a leading sample axis concatenated, tuples
    of one tuple per sample (a GlobalError's verdicts) joined, a per-sample result held in the state (the
    batch's GlobalError) merged through its own state, the same value kept, a per-piece wall time summed."""
    if all(isinstance(x, np.ndarray) and x.ndim >= 1 and x.shape[0] == s for x, s in zip(items, sizes)):
        out = np.concatenate(items, axis=0)
        out.flags.writeable = all(x.flags.writeable for x in items)
        return out
    if all(isinstance(x, tuple) and len(x) == s and all(isinstance(row, tuple) for row in x)
           for x, s in zip(items, sizes)):
        return tuple(row for x in items for row in x)
    from . import _core

    if all(isinstance(x, _core.GlobalError) for x in items):
        return _rebuilt(items[0], tuple(_merge_item(list(parts), sizes) for parts in zip(*map(_state, items))))
    if all(isinstance(x, float) for x in items):
        return float(sum(items))  # elapsed time: the tasks' total
    if all(np.array_equal(x, items[0]) for x in items):
        return items[0]
    raise TypeError("function: expected pieces whose state items are per-sample arrays or equal, got differing "
                    f"{type(items[0]).__name__} items")


# ---------------------------------------------------------------------------------------------
# map_samples


def map_samples(function: Callable[[int, int], Any], n_samples: int, *, client: Any = None,
                chunk_size: int | None = None, retries: int = 2, progress: bool = True) -> Any:
    """function(chunk_start, chunk_stop) over chunks of range(n_samples) as Dask tasks, the pieces
    concatenated in sample order (see the module docstring for the contract, the chunk size rule and
    failures).

    function: a callable (start, stop) -> piece, picklable by cloudpickle (ValueError naming function
    otherwise, before any task); it is sent once per worker. n_samples: int >= 1. client: None (a
    LocalCluster for the call), a distributed.Client or a scheduler address. chunk_size: samples per
    task (int >= 1) or None (sized from the measured overheads). retries: further tries of a failed
    chunk (int >= 0). progress: a tqdm bar of samples on stderr when tqdm is installed. Without
    dask.distributed: function(0, n_samples) here after one RuntimeWarning."""
    if not callable(function):
        raise TypeError(f"function: expected a callable function(chunk_start, chunk_stop), got {function!r}")
    n = _check_int(n_samples, "n_samples", 1)
    size, retries, progress = _check_common(chunk_size, retries, progress)
    _check_client(client)
    distributed = _distributed()
    if distributed is None:
        _fallback()
        return function(0, n)
    _check_picklable(function, "function")
    with _client_for(client, distributed) as c:
        runner = _run_map(c, function, None, n, size, retries, progress, "map_samples")
    runner.reraise_warnings()
    return concatenate(runner.pieces())


# ---------------------------------------------------------------------------------------------
# simulate_batch


@dataclass
class _BatchChunk:
    """What every worker gets once: the model when it is common to the samples, the step count and the
    common keyword arguments of rigiddyn.simulate_batch. Called with a chunk's per-sample inputs
    (`payload`: argument name -> the chunk's slice)."""

    model: Any
    steps: Any
    common: dict[str, Any]

    def __call__(self, start: int, stop: int, payload: dict[str, Any]) -> Any:
        arguments = {"model": self.model, **self.common, **payload}
        with warnings.catch_warnings():  # the batch's own warnings are given once for the whole batch
            warnings.filterwarnings("ignore", message=_BATCH_WARNING, category=RuntimeWarning)
            return _batch_function()(arguments.pop("model"), arguments.pop("initial"), arguments.pop("dt"), self.steps,
                                     threads=1, **arguments)


def _samples_of(initial: Any) -> int:
    """N: the length of `initial` (a sequence of states, or a dict of stacked arrays with a leading N axis)."""
    if isinstance(initial, Mapping):
        shapes = {k: np.shape(v) for k, v in initial.items()}
        sizes = {shape[0] if shape else -1 for shape in shapes.values()}
        if len(sizes) != 1 or -1 in sizes:
            raise ValueError(f"initial: expected a dict of arrays with the same leading (sample) axis, got shapes "
                             f"{shapes}")
        return int(sizes.pop())
    if isinstance(initial, (str, bytes)) or not isinstance(initial, Sequence):
        raise TypeError(f"initial: expected a sequence of N states or a dict of stacked arrays, got {initial!r}")
    return len(initial)


def _per_sample(name: str, value: Any, n: int) -> bool:
    """True when `value` holds one entry per sample (ValueError naming `name` when it holds another
    count): model a sequence, dt an (N,) array, gravity (N, 3), loads a sequence of schedules."""
    if value is None:
        return False
    if name == "model":
        count = len(value) if isinstance(value, (list, tuple)) else None
    elif name == "loads":
        schedules = isinstance(value, (list, tuple)) and len(value) > 0
        count = len(value) if schedules and all(isinstance(s, (list, tuple)) for s in value) else None
    else:
        shape = np.shape(getattr(value, "magnitude", value))
        count = shape[0] if len(shape) == (1 if name == "dt" else 2) else None
    if count is not None and count != n:
        raise ValueError(f"{name}: expected {n} entries, one per sample of initial ({n}), got {count}")
    return count is not None


def _slice(value: Any, a: int, b: int) -> Any:
    if isinstance(value, Mapping):
        return {k: v[a:b] for k, v in value.items()}
    return value[a:b]


def _batch_function() -> Callable[..., Any]:
    from . import _core

    return _core.simulate_batch


def _batch_warnings(result: Any, method: str) -> None:
    """The local batch's warnings, once for the whole batch: the samples that became non-finite (the
    first five named) and the steps of `method`'s implicit solve that did not converge."""
    diverged = np.flatnonzero(np.asarray(result.diverged))
    if diverged.size:
        first = ", ".join(str(i) for i in diverged[:5]) + (", ..." if diverged.size > 5 else "")
        warnings.warn(f"simulate_batch: {diverged.size} of {len(result.diverged)} samples became non-finite "
                      f"(samples {first}); their runs stopped there", RuntimeWarning, stacklevel=3)
    unconverged = np.asarray(result.unconverged_steps)
    if np.any(unconverged > 0):
        warnings.warn(f"simulate_batch: the implicit solve of method '{method}' did not converge in "
                      f"{int(unconverged.sum())} steps of {int(np.count_nonzero(unconverged))} samples (see "
                      "unconverged_steps; their conservation is lost there); reduce dt", RuntimeWarning, stacklevel=3)


def _method_name(model: Any, method: Any) -> str:
    """The method a batch runs: `method`, else a CompiledScene's own, else 'rk4' (as rigiddyn.simulate_batch)."""
    if method is not None:
        return str(method)
    first = model[0] if isinstance(model, (list, tuple)) and model else model
    return str(getattr(first, "method", "rk4"))


def _batch_steps(steps: Any, duration: Any, dt: Any, n: int) -> Any:
    """The steps of every sample from steps= or duration= [s] at dt (a float, or one per sample, each giving the
    same count: the chunks' records are stacked), as rigiddyn.simulate_batch checks them."""
    from . import _core

    if duration is None:
        return steps  # (checked by each chunk's simulate_batch, as dt)
    if steps is not None or not _per_sample("dt", dt, n):
        return int(_core._steps_of(steps, duration, dt if steps is None else 1.0))
    counts: dict[int, int] = {}  # step count -> the first sample with it
    for i, dt_i in enumerate(dt):
        counts.setdefault(int(_core._steps_of(None, duration, dt_i)), i)
    if len(counts) > 1:
        (first, i), (other, j) = list(counts.items())[:2]
        raise ValueError(f"duration: expected the same number of steps for every sample's dt (or steps= instead), "
                         f"got {first} steps of dt[{i}] and {other} of dt[{j}]")
    return next(iter(counts))


def simulate_batch(model: Any, initial: Any, dt: Any, steps: Any = None, *, client: Any = None,
                   chunk_size: int | None = None, retries: int = 2, progress: bool = True,
                   **simulate_batch_kwargs: Any) -> Any:
    """rigiddyn.simulate_batch on a Dask cluster: N runs of `model` in chunks of consecutive samples, one
    task each, concatenated in sample order; BITWISE the local rigiddyn.simulate_batch's result (a
    BatchSceneResult: arrays with a leading sample axis, e.g. p_W (N, n_records, nb, 3) [m],
    q_WB (N, n_records, nb, 4), w_B (N, n_records, nb, 3) [rad/s] in B; elapsed_seconds the call's wall time [s]).

    model, initial, dt [s], steps and simulate_batch_kwargs (duration, method, record_every, loads, gravity,
    t0, simd, scalar_first) as rigiddyn.simulate_batch (a duration is turned into steps here, at dt or at
    each sample's dt, which must agree, before any chunk is sent); a model common to the samples (one body or scene) is
    sent once per worker, per-sample inputs (a sequence of N models, the N initial states, an (N,) dt, an
    (N, 3) gravity [m/s^2] in W, N load schedules) only with their chunk. Each task runs on one thread
    (threads is not an argument: the workers' threads run tasks side by side). client, chunk_size,
    retries, progress: as map_samples (chunk_size None: sized from the measured task overhead and the
    per-sample cost, see the module docstring). A model that does not pickle (e.g. a Scene whose
    PythonForce's function holds a lock or an open file) raises ValueError naming model before any
    task. Samples that become non-finite: one RuntimeWarning naming them, as the local batch.
    Without dask.distributed: rigiddyn.simulate_batch on this machine's threads after one RuntimeWarning.
    """
    size, retries, progress = _check_common(chunk_size, retries, progress)
    _check_client(client)
    if "threads" in simulate_batch_kwargs:
        raise TypeError("threads: not an argument of rigiddyn.distributed.simulate_batch (each task runs on one "
                        "thread; the workers' threads run tasks side by side)")
    distributed = _distributed()
    if distributed is None:
        _fallback()
        return _batch_function()(model, initial, dt, steps, **simulate_batch_kwargs)
    n = _samples_of(initial)
    if n == 0:
        raise ValueError("initial: expected at least one sample, got 0")
    steps = _batch_steps(steps, simulate_batch_kwargs.pop("duration", None), dt, n)
    inputs = {"model": model, "initial": initial, "dt": dt, **simulate_batch_kwargs}
    sliced = {k: v for k, v in inputs.items() if k == "initial" or (k in ("model", "dt", "gravity", "loads")
                                                                    and _per_sample(k, v, n))}
    common = {k: v for k, v in inputs.items() if k not in sliced and k != "model"}
    shared = _BatchChunk(None if "model" in sliced else model, steps, common)
    _check_picklable(model, "model")
    _check_picklable(shared, "simulate_batch_kwargs")
    started = time.perf_counter()
    with _client_for(client, distributed) as c:
        runner = _run_map(c, shared, lambda a, b: {k: _slice(v, a, b) for k, v in sliced.items()}, n, size,
                          retries, progress, "simulate_batch")
    result = _with_elapsed(concatenate(runner.pieces()), time.perf_counter() - started)  # the call's wall time
    runner.reraise_warnings()
    _batch_warnings(result, _method_name(model, simulate_batch_kwargs.get("method")))
    return result


# ---------------------------------------------------------------------------------------------
# tradeoff grids


@dataclass
class _TradeoffPoint:
    """What every worker gets once for a tradeoff grid: the resolved problem (a Problem or SceneCase),
    its step counts and the arguments of rigiddyn.tradeoff. Called for grid points start <= j < stop."""

    problem: Any
    grid: list[int]
    arguments: dict[str, Any]

    def __call__(self, start: int, stop: int) -> list[Any]:
        from .stability import StabilityWarning
        from .work_precision import tradeoff

        with warnings.catch_warnings():  # the stability summary is made once for the whole grid
            warnings.simplefilter("ignore", StabilityWarning)
            return [tradeoff(self.problem, dts=[self.problem.horizon / steps], progress=False, **self.arguments)
                    for steps in self.grid[start:stop]]


def tradeoff_grid(problem: Any, methods: Sequence[str] | None = None, dts: Sequence[float] | None = None,
                  horizon: float | None = None, tolerance: float | None = None, measure: str | None = None,
                  cost: str = "time", samples: int | None = None, max_reference_steps: int = 4_000_000,
                  initial: Sequence[Any] | None = None, *, client: Any = None, retries: int = 2,
                  progress: bool = True) -> Any:
    """rigiddyn.tradeoff (same arguments, same TradeoffResult) with each step size of the grid run as a
    Dask task (one task per dt: every method at that dt, its Richardson reference and check). Each step
    size's runs and references are independent of the others', so the rows (errors, references,
    reference checks) are those of the local sweep; the observed orders, which compare neighbouring
    steps, and the StabilityWarning summary are made here from all the rows. Times per step [s] are
    measured on the workers (each worker thread runs one task at a time; the times reflect the load of
    the worker's machine, as a local sweep's do). Without dask.distributed: rigiddyn.tradeoff here after
    one RuntimeWarning."""
    from .work_precision import constants, sweep
    from .work_precision.case import as_case
    from .work_precision.checks import check_dts, step_grid

    _, retries, progress = _check_common(None, retries, progress)
    _check_client(client)
    arguments: dict[str, Any] = {"methods": methods, "tolerance": tolerance, "measure": measure, "cost": cost,
                                 "samples": constants.SAMPLES if samples is None else samples,
                                 "max_reference_steps": max_reference_steps}
    distributed = _distributed()
    if distributed is None:
        _fallback()
        return sweep.tradeoff(problem, dts=dts, horizon=horizon, initial=initial, progress=progress, **arguments)
    case = as_case(problem, horizon, initial)
    chosen = dts if dts is not None else case.tradeoff.get("dts", case.default_dts())
    steps = step_grid(case.horizon, check_dts(chosen), "dts" if dts is not None else "horizon")
    _check_tradeoff_arguments(arguments)
    point = _TradeoffPoint(case, steps, arguments)
    _check_picklable(case, "problem")
    with _client_for(client, distributed) as c:
        runner = _run_map(c, point, None, len(steps), 1, retries, progress, "tradeoff", "dt")
    parts = concatenate(runner.pieces())
    return _joined_tradeoff(parts, case.stability_subject)


def _check_tradeoff_arguments(arguments: dict[str, Any]) -> None:
    """rigiddyn.tradeoff's checks of its arguments, made here before any task (TypeError/ValueError naming one)."""
    from . import _core, _measures
    from .work_precision.checks import check_cost, check_count, check_names, check_positive

    if arguments["methods"] is not None:
        arguments["methods"] = check_names(arguments["methods"], [m["name"] for m in _core.methods()])
    if arguments["measure"] is not None:
        _measures._check_measure(arguments["measure"])
    if arguments["tolerance"] is not None:
        check_positive(arguments["tolerance"], "tolerance")
    check_cost(arguments["cost"])
    check_count(arguments["samples"], "samples")
    check_count(arguments["max_reference_steps"], "max_reference_steps")


def _joined_tradeoff(parts: list[Any], subject: str) -> Any:
    """One TradeoffResult from the one-step-size results `parts`: rows joined, observed orders over all
    step sizes (as rigiddyn.tradeoff does), rows in its order, the stability summary ("dt beyond the
    method's stability limit <subject>") warned once."""
    from .stability import StabilityWarning
    from .work_precision.orders import observed_orders
    from .work_precision.result import TradeoffResult
    from .work_precision.sweep import stability_summary

    first = parts[0]
    rows = [row for part in parts for row in part.rows]
    exact = {r["method"] for r in rows if r["order_note"] == "exact on this problem"}
    applicable = [r for r in rows if not r["order_note"].startswith("not applicable")]
    observed_orders(applicable, first.measure, exact)
    order = list(dict.fromkeys(r["method"] for r in first.rows))
    rows.sort(key=lambda r: (order.index(r["method"]), -r["dt"]))
    unstable = [(r["method"], r["dt"], r["stability"]) for r in rows if r["stability"]]
    if unstable:
        warnings.warn(stability_summary(unstable, subject), StabilityWarning, stacklevel=3)
    return TradeoffResult(first.problem, first.horizon, first.measure, first.tolerance, rows, first.cost,
                             notes=first.notes)
