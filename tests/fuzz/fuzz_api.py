"""Fuzz every public callable of rigiddyn with hypothesis; every call runs in a child process watched
by this one, so a crash or a hang is reported with the call that caused it.

  python tests/fuzz/fuzz_api.py                      # the CI profile (tests/python/test_fuzz_api.py)
  python tests/fuzz/fuzz_api.py --only 'quat_.*' --examples 300 --budget 120   # a longer hunt

Targets: every name of `rigiddyn.__all__` (functions; classes: constructor, static and instance methods,
operators), of the modules it lists and of PUBLIC_SUBMODULES (units, dispersion), read by introspection
(api_model.py); arguments from strategies.py (scene files from scene_files.py). Oracle, for every call
(the target and each call made to build its arguments):
  - it returns, or raises TypeError, ValueError or MemoryError (OSError from a function that takes a
    path) whose message is non-empty and is not pybind11's overload list or cast error;
  - if it returns, every float in the result (arrays, scalars, containers, the properties of returned
    objects) is finite unless the call emitted a RuntimeWarning or the value is a documented non-finite
    one (DOCUMENTED_NON_FINITE, each with the docstring that says so);
  - the child neither dies (a crash: the signal and the child's faulthandler trace are reported) nor
    uses more than --timeout seconds of CPU and then ignores SIGINT for --grace CPU seconds (a hang; a
    call that stops with KeyboardInterrupt on SIGINT is only slow). CPU time, not wall time, so that a
    loaded machine does not turn a slow call into a hang; a call that blocks without using CPU is
    judged by wall time, WALL_FACTOR times the CPU limits.
Properties of results (properties.py, targets "check.<name>": batch = serial bitwise, SIMD = scalar to
round-off, scene files read back and read the same in any units, Monte Carlo prefixes, the command line =
the API, the closed forms' invariants) fail as "wrong result". Findings of defects known and being fixed
(KNOWN_DEFECTS) are reported apart, under "known", and do not count.
Each finding is shrunk by hypothesis to a minimal call and printed as a runnable reproducer. Seeds are
fixed per target, there is no example database, and the cost is bounded by counts, not by time:
--examples drawn per target and --calls made per target (generation and shrinking together), so the
same code (and hypothesis version) gives the same run on any machine. --budget / --total-budget
(seconds) are for interactive hunts only; a target they cut short is listed as truncated.
Exit status: 0 clean, 1 findings, 2 the harness could not exercise a target.
"""

from __future__ import annotations

import argparse
import faulthandler
import importlib
import json
import math
import multiprocessing
import os
import re
import resource
import signal
import sys
import tempfile
import time
import traceback
import warnings
import zlib
from pathlib import Path

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):  # the machine is shared
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
from hypothesis import HealthCheck, Phase, Verbosity, given, seed, settings  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from api_model import Target, build, public_attributes, public_targets, reproducer, source  # noqa: E402
from strategies import Strategies, docstring_words  # noqa: E402

ACCEPTED = (TypeError, ValueError, MemoryError)
WALL_FACTOR = 20  # wall-time limit of a call = WALL_FACTOR x its CPU-time limit (a call blocked in a wait)
UNHELPFUL_MESSAGES = {
    "incompatible function arguments": "pybind11's overload list instead of a message naming the argument",
    "Unable to cast": "pybind11's cast error instead of a message naming the argument",
    "to C++ type": "pybind11's cast error instead of a message naming the argument",
}
# Non-finite values the API documents: (path pattern, '*' any text; values allowed; where it is
# documented: (module, attribute path) whose docstring or signature names the value, checked by
# tests/python/test_fuzz_api.py). A path is Class.attribute (properties of a returned object),
# function() or Class.method() for a returned value, with [] for any index or key.
DOCUMENTED_NON_FINITE = [
    ("Screw.pitch", {"inf"}, ("rigiddyn", "Screw.pitch")),
    ("InertiaReport.condition_number", {"inf"}, ("rigiddyn", "InertiaReport.condition_number")),
    ("TorqueFreeSolution.period", {"inf"}, ("rigiddyn", "TorqueFreeSolution.period")),
    ("CompoundPendulumSolution.period", {"inf"}, ("rigiddyn", "CompoundPendulumSolution.period")),
    ("LagrangeTopSolution.nutation_period", {"inf"}, ("rigiddyn", "LagrangeTopSolution.nutation_period")),
    ("ConstantThrustSolution.burnout_time", {"inf"}, ("rigiddyn", "ConstantThrustSolution.burnout_time")),
    ("ellipk()", {"inf"}, ("rigiddyn", "ellipk")),
    ("methods()[][stability_limit]", {"inf"}, ("rigiddyn", "methods")),
    ("AppliedLoad.t_start", {"-inf"}, ("rigiddyn", "AppliedLoad.__init__")),
    ("AppliedLoad.t_end", {"inf"}, ("rigiddyn", "AppliedLoad.__init__")),
    ("ReactionWheel.t_end", {"inf"}, ("rigiddyn", "ReactionWheel")),  # its Parameters: "(inf: none)"
    ("RevoluteMotor.t_start", {"-inf"}, ("rigiddyn", "RevoluteMotor")),  # its Parameters: "(-inf: on from any time)"
    ("RevoluteMotor.t_end", {"inf"}, ("rigiddyn", "RevoluteMotor")),  # its Parameters: "(inf: never)"
    ("PrismaticMotor.t_start", {"-inf"}, ("rigiddyn", "PrismaticMotor")),
    ("PrismaticMotor.t_end", {"inf"}, ("rigiddyn", "PrismaticMotor")),
    ("Wheel.t_end", {"inf"}, ("rigiddyn", "Wheel")),  # its Parameters: "default 0 and inf"
    ("*[observed_order]", {"nan"}, ("rigiddyn.work_precision", "")),  # the module's docstring: the columns
    # the module's docstring: "for the other measures the columns are nan and the verdict says so"
    ("*[estimate]", {"nan"}, ("rigiddyn.work_precision", "")),
    ("*[effectivity]", {"nan"}, ("rigiddyn.work_precision", "")),
    ("TradeoffResult.rows[]*", {"inf"}, ("rigiddyn.work_precision", "tradeoff")),  # "diverged runs get inf errors"
    ("TradeoffResult.to_dict()[rows][]*", {"inf"}, ("rigiddyn.work_precision", "tradeoff")),
    ("TradeoffResult.to_dict()[recommendation]*", {"inf"}, ("rigiddyn.work_precision", "tradeoff")),
    ("Recommendation.*", {"inf"}, ("rigiddyn.work_precision", "tradeoff")),
    ("TradeoffResult.horizon", {"nan"}, ("rigiddyn.work_precision", "TradeoffResult")),  # "nan if unknown"
    ("TradeoffResult.to_dict()[horizon]", {"nan"}, ("rigiddyn.work_precision", "TradeoffResult")),
    ("Statistics.std", {"nan"}, ("rigiddyn.dispersion", "Statistics")),  # "NaN below 2 samples"
    # "A run of fewer than m steps has no estimate (NaN, with a verdict saying so)"
    ("GlobalError.*", {"nan"}, ("rigiddyn", "GlobalError")),
    ("GlobalError.observed_order", {"nan"}, ("rigiddyn", "GlobalError.observed_order")),  # "NaN where ..."
    ("Balance.*", {"nan"}, ("rigiddyn", "Balance")),  # "NaN residuals" where a balance does not apply
    # "certified_error ... (NaN: none)"; a pilot's error, constant and seconds NaN where it was pruned
    ("ToleranceChoice.*", {"nan"}, ("rigiddyn", "ToleranceChoice")),
]
# public modules of a package that its __all__ does not list (a module it lists is
# walked anyway): their callables are targets "<submodule>.<name>"
PUBLIC_SUBMODULES = {"rigiddyn": ("units", "dispersion")}
# the module (beside this file) of a package's properties of results, fuzzed as targets "check.<name>"
PROPERTIES = {"rigiddyn": "properties", "planted_bugs": "planted_bugs"}
# targets left out, with the reason (they are listed as skipped)
_HOOK = ("a hook monte_carlo calls with its own key, nominal value and generator (a custom dispersion overrides it); "
         "what reaches it is fuzzed through monte_carlo")
EXCLUDED = {
    "dispersion.Dispersion": "the base class of the dispersions (a custom one subclasses it; its subclasses are fuzzed)",
    "dispersion.Statistics": "the record monte_carlo's statistics() returns (a frozen dataclass holding what it is "
                              "given; its values are checked where statistics() makes them)",
    "SampledState": "the record a Controller's law gets at each sample (a frozen dataclass holding what the run "
                    "gives it: the state there, non-finite once a run diverges; the law's commands are checked)",
    **{f"dispersion.{cls}.{hook}": _HOOK for cls in ("Dispersion", "Normal", "Uniform", "UniformRotation",
                                                       "RotationNormal", "InertiaDispersion", "LoadDispersion")
       for hook in ("bind", "draw")},
}
# Findings of defects known and being fixed: (call regex, kind regex, regex on the finding's detail or reproducer,
# the defect in plain words). A finding that matches is reported under "known", not as a finding; remove the entry
# when the fix lands (the fuzz then checks the fix).
KNOWN_DEFECTS: list[tuple[str, str, str, str]] = []
# functions that return an argument unchanged where it is not theirs to convert (a NaN passed is a NaN returned)
PASS_THROUGH = {"units.to_si": "returns a value that is not a pint quantity unchanged (its docstring)"}
_DOCUMENTED = [(re.compile(re.escape(p).replace(r"\*", ".*")), kinds) for p, kinds, _ in DOCUMENTED_NON_FINITE]


# ---------------------------------------------------------------------------------------------
# the worker (a forked child): builds a spec, makes its calls, applies the oracle


class _Raised(Exception):
    """`call` (a path) raised `error`; spec: the spec of that call alone."""

    def __init__(self, call, error, spec):
        self.call, self.error, self.spec = call, error, spec


class _Failure(Exception):
    """`call` (a path) broke the oracle; spec: the spec of that call alone (None: the last call made)."""

    def __init__(self, call, kind, key, detail, spec=None):
        self.call, self.kind, self.key, self.detail, self.spec = call, kind, key, detail, spec


def _kind(x) -> str:
    return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")


def non_finite(value, path: str, package: str, depth: int = 0, seen=None) -> list[tuple[str, str]]:
    """(path, 'nan'/'inf'/'-inf') of every non-finite float reachable from value."""
    seen = set() if seen is None else seen
    out: list[tuple[str, str]] = []
    if depth > 5:
        return out
    if isinstance(value, (bool, int, str, bytes, np.integer, np.bool_)) or value is None:
        return out
    if isinstance(value, (float, np.floating)):
        return [] if math.isfinite(value) else [(path, _kind(float(value)))]
    if isinstance(value, (complex, np.complexfloating)):
        return non_finite(value.real, path, package, depth) + non_finite(value.imag, path, package, depth)
    if isinstance(value, np.ndarray):
        if value.ndim:  # a broadcast view (stride 0) holds only the values of one slice along each broadcast axis
            value = value[tuple(slice(0, 1) if stride == 0 else slice(None) for stride in value.strides)]
        if value.dtype.kind == "c":
            return non_finite(value.real, path, package, depth) + non_finite(value.imag, path, package, depth)
        if value.dtype.kind == "f":
            bad = ~np.isfinite(value)
            return [(path, k) for k, hit in (("nan", np.isnan(value)), ("inf", value > 0), ("-inf", value < 0))
                    if np.any(hit & bad)]
        if value.dtype == object:
            for item in value.flat[:1000]:
                out += non_finite(item, path + "[]", package, depth + 1, seen)
        return out
    if isinstance(value, (list, tuple)):
        for item in value[:1000]:
            out += non_finite(item, path + "[]", package, depth + 1, seen)
        return out
    if isinstance(value, dict):
        for k, v in list(value.items())[:1000]:
            out += non_finite(v, f"{path}[{k}]", package, depth + 1, seen)
        return out
    if id(value) in seen:
        return out
    seen.add(id(value))
    for attr in public_attributes(value, package):
        where = f"{type(value).__name__}.{attr}"
        try:
            item = getattr(value, attr)
        except BaseException as e:  # noqa: BLE001  (a property that raises is a finding of its own)
            raise _Failure(where, "exception", f"property raised {type(e).__name__}", f"{where}: {e!r}") from None
        out += non_finite(item, where, package, depth + 1, seen)
    return out


def _documented(path: str, kind: str) -> bool:
    return any(kind in kinds and pattern.fullmatch(path) for pattern, kinds in _DOCUMENTED)


def _call(package, current):
    def on_call(path, fn, args, kwargs, call):
        current.path.value = path.encode()[:250]
        text = source(call).encode()
        current.source.value = text if len(text) < len(current.source) else b""
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                result = fn(*args, **kwargs)
            except KeyboardInterrupt:
                raise
            except BaseException as e:  # noqa: BLE001
                raise _Raised(path, e, call) from None
            leaves = non_finite(result, f"{path}()", package)  # reads properties: they may warn too
            warned = any(issubclass(w.category, RuntimeWarning) for w in caught)
        silent = [(p, k) for p, k in leaves if not _documented(p, k)] if path not in PASS_THROUGH else []
        if silent and not warned:
            shown = ", ".join(f"{p} = {k}" for p, k in silent[:4])
            raise _Failure(path, "non-finite", silent[0][0], f"returned {shown} without a RuntimeWarning", call)
        return result

    return on_call


def _message_problem(error: BaseException) -> str | None:
    text = str(error)
    if not text.strip():
        return "an empty message"
    for marker, what in UNHELPFUL_MESSAGES.items():
        if marker in text:
            return what
    return None


def evaluate(spec, module, package, current, takes_path: bool) -> dict:
    on_call = _call(package, current)
    try:
        build(spec, module, on_call)
        return {"status": "returned"}
    except KeyboardInterrupt:
        return {"status": "interrupted"}
    except _Failure as f:
        expr = source(f.spec) if f.spec is not None else current.source.value.decode()
        return {"status": "failure", "call": f.call, "kind": f.kind, "key": f.key, "detail": f.detail, "source": expr}
    except _Raised as r:
        e = r.error
        if r.call.startswith("check.") and isinstance(e, AssertionError):  # a property of the results failed
            return {"status": "failure", "call": r.call, "kind": "wrong result", "key": str(e).split(":")[0][:80],
                    "detail": str(e)[:1500], "source": source(r.spec)}
        target = spec[1] if spec[0] == "call" else ("check." + spec[2] if spec[0] == "check" else None)
        top = r.call == target or (spec[0] == "method" and r.call.endswith("." + spec[2]))
        # an index past the end of a result that reads as a tuple raises IndexError, as a tuple does
        indexed = r.call.endswith(".__getitem__") and isinstance(e, IndexError)
        if not isinstance(e, ACCEPTED) and not (takes_path and isinstance(e, OSError)) and not indexed:
            return {"status": "failure", "call": r.call, "kind": "exception", "key": type(e).__name__,
                    "detail": f"{type(e).__name__}: {str(e)[:300]}", "source": source(r.spec)}
        problem = _message_problem(e)
        if problem is not None:
            return {"status": "failure", "call": r.call, "kind": "message", "key": problem,
                    "detail": f"{type(e).__name__}: {str(e)[:300]}", "source": source(r.spec)}
        return {"status": "rejected" if top else "setup_rejected", "error": type(e).__name__}
    except Exception:  # noqa: BLE001  (the harness could not build the arguments: its own mistake)
        return {"status": "harness_error", "detail": traceback.format_exc(limit=3)[-600:]}


def _die_with_parent() -> None:
    """Linux: SIGKILL this process when the driver dies, even in a call that never returns."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


def worker_main(conn, module_name: str, current, log_path: str, memory_bytes: int) -> None:
    _die_with_parent()
    os.chdir(Path(log_path).parent)  # files a call writes stay in the scratch directory
    log = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
    os.dup2(log, 1)
    os.dup2(log, 2)
    faulthandler.enable()
    in_use = int(re.search(r"VmSize:\s+(\d+) kB", Path("/proc/self/status").read_text()).group(1)) * 1024
    resource.setrlimit(resource.RLIMIT_AS, (in_use + memory_bytes, in_use + memory_bytes))
    signal.signal(signal.SIGINT, signal.default_int_handler)
    module = importlib.import_module(module_name)
    package = module_name.split(".")[0]
    while True:
        try:
            spec, takes_path = conn.recv()
        except (EOFError, KeyboardInterrupt):
            os._exit(0)
        try:
            outcome = evaluate(spec, module, package, current, takes_path)
            conn.send(outcome)
        except KeyboardInterrupt:
            conn.send({"status": "interrupted"})


# ---------------------------------------------------------------------------------------------
# the driver


class _Current:
    """The call the worker is making, in shared memory: its path and the source that makes it alone
    (empty if longer than the buffer). The driver reads them after a crash or a hang."""

    def __init__(self, ctx):
        self.path = ctx.Array("c", 256, lock=False)
        self.source = ctx.Array("c", 1 << 16, lock=False)


class Runner:
    """Sends each spec to a forked worker, with a watchdog; restarts the worker after a crash or hang."""

    def __init__(self, module_name: str, timeout: float, grace: float, memory_gb: float, scratch: Path):
        self.module_name, self.timeout, self.grace = module_name, timeout, grace
        self.memory = int(memory_gb * 2**30)
        self.scratch = scratch
        self.ctx = multiprocessing.get_context("fork")
        self.proc = None
        self.starts = 0

    def _start(self) -> None:
        self.starts += 1
        self.log = str(self.scratch / f"worker-{self.starts}.log")
        self.current = _Current(self.ctx)
        self.conn, child = self.ctx.Pipe()
        self.proc = self.ctx.Process(target=worker_main, args=(child, self.module_name, self.current, self.log,
                                                                self.memory), daemon=True)
        self.proc.start()
        child.close()

    def _stop(self) -> None:
        if self.proc is not None:
            if self.proc.is_alive():
                self.proc.kill()
            self.proc.join()
            self.conn.close()
            self.proc = None

    def close(self) -> None:
        self._stop()

    def _log_tail(self) -> str:
        try:
            lines = Path(self.log).read_text(errors="replace").splitlines()
        except OSError:
            return ""
        # what the process said before dying, without faulthandler's frames (they are the harness's)
        said = [line for line in lines if line.strip() and not line.startswith(
            ("  File ", "Current thread", "Thread 0x", "Extension modules:")) and "most recent call first" not in line]
        return "\n".join(said[-4:])

    def _crashed(self) -> dict:
        self.proc.join(5)
        code = self.proc.exitcode
        call, expr = self._current()
        name = signal.Signals(-code).name if code is not None and code < 0 else f"exit status {code}"
        detail = f"the process died ({name}) in {call}\n{self._log_tail()}"
        self._stop()
        return {"status": "failure", "call": call, "kind": "crash", "key": name, "detail": detail, "source": expr}

    def _current(self) -> tuple[str, str]:
        return (self.current.path.value.decode(errors="replace"), self.current.source.value.decode(errors="replace"))

    def _replied(self, cpu_limit: float) -> bool:
        """Wait for the worker's reply until it has used cpu_limit seconds of CPU (or WALL_FACTOR times
        that in wall time); whether it replied."""
        start_cpu, start = _cpu_seconds(self.proc.pid), time.monotonic()
        while not self.conn.poll(0.05):
            if (_cpu_seconds(self.proc.pid) - start_cpu > cpu_limit
                    or time.monotonic() - start > WALL_FACTOR * cpu_limit):
                return False
        return True

    def run(self, spec, takes_path: bool = False) -> dict:
        """The outcome of the call of `spec`; takes_path: the target reads or writes a file (OSError is
        then an accepted answer)."""
        if self.proc is None or not self.proc.is_alive():
            self._stop()
            self._start()
        self.current.path.value = self.current.source.value = b""
        try:
            self.conn.send((spec, takes_path))
            if self._replied(self.timeout):
                return self.conn.recv()
        except (EOFError, OSError):
            return self._crashed()
        os.kill(self.proc.pid, signal.SIGINT)  # a long call must stop on Ctrl-C
        try:
            if self._replied(self.grace):
                outcome = self.conn.recv()
                self._stop()  # the SIGINT may land after the reply: start afresh
                return {"status": "slow"} if outcome["status"] in ("interrupted", "returned", "rejected",
                                                                   "setup_rejected") else outcome
        except (EOFError, OSError):
            return self._crashed()
        call, expr = self._current()
        self._stop()
        return {"status": "failure", "call": call, "kind": "hang", "key": "no return, SIGINT ignored",
                "detail": f"{call} used over {self.timeout:g} s of CPU and ignored SIGINT for {self.grace:g} s of CPU",
                "source": expr}


_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def _cpu_seconds(pid: int) -> float:
    """CPU time (user + system, all threads) a process has used [s]; 0 where /proc cannot tell (then
    only the wall-time limit applies) or the process is gone (then its reply or EOF is waiting)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except (OSError, IndexError):
        return 0.0
    return (int(fields[11]) + int(fields[12])) / _TICKS  # utime, stime: fields 14 and 15 of proc(5)


_FAILURE_TYPES: dict[tuple, type] = {}


def _failure_type(key) -> type:
    """One exception class per (call, kind, key): hypothesis keeps and shrinks each distinct failure."""
    if key not in _FAILURE_TYPES:
        _FAILURE_TYPES[key] = type("Fuzz_" + re.sub(r"\W+", "_", "_".join(key))[:80], (AssertionError,), {})
    return _FAILURE_TYPES[key]


class _OutOfBudget(BaseException):
    """Stops hypothesis (it lets BaseException through) when a target has used its time."""


def fuzz_target(target, strategy, runner: Runner, module_name: str, examples: int, max_calls: int, budget: float,
                known: set, seed_offset: int = 0):
    """Run hypothesis on one target for at most `max_calls` calls of the worker and `budget` seconds.
    Returns (findings, counts of outcomes).

    Hypothesis stops generating at the first failure and shrinks it, so the search runs in rounds: each
    round (its own fixed seed) passes over every failure already known (this target's earlier rounds,
    and every other target's) and stops at a new one; rounds go on until one finds nothing new or the
    budget is spent. The smallest reproducer seen of each new failure is kept."""
    cache: dict[str, dict] = {}
    counts: dict[str, int] = {}
    best: dict[tuple, tuple] = {}  # (call, kind, key) -> (source, spec, outcome)
    errors: list[str] = []
    known_hits: dict[tuple, tuple] = {}  # findings of KNOWN_DEFECTS
    start = time.monotonic()
    out_of_budget = []
    takes_path = any("path" in p.name for params in target.overloads for p in params)

    def search(round_number: int, masked: set) -> bool:
        @settings(max_examples=examples, database=None, deadline=None, suppress_health_check=list(HealthCheck),
                  verbosity=Verbosity.quiet, report_multiple_bugs=True, phases=(Phase.generate, Phase.shrink))
        @seed(zlib.crc32(target.path.encode()) + round_number + 1000 * seed_offset)
        @given(strategy)
        def check(spec):
            text = source(spec)
            if text not in cache:
                if len(cache) >= max_calls or time.monotonic() - start > budget:
                    out_of_budget.append("calls" if len(cache) >= max_calls else "seconds")
                    raise _OutOfBudget
                cache[text] = runner.run(spec, takes_path)
                status = cache[text]["status"]
                counts[status] = counts.get(status, 0) + 1
                if status == "harness_error":
                    errors.append(cache[text]["detail"])
            outcome = cache[text]
            if outcome["status"] != "failure":
                return
            defect = known_defect(outcome)
            if defect is not None:
                known_hits.setdefault((outcome["call"], outcome["kind"], outcome["key"]), (text, outcome, defect))
                return
            key = (outcome["call"], outcome["kind"], outcome["key"])
            if key in best and len(text) < len(best[key][0]):
                best[key] = (text, spec, outcome)
            if key in masked:
                return
            best.setdefault(key, (text, spec, outcome))
            raise _failure_type(key)(outcome["detail"])

        try:
            check()
        except _OutOfBudget:
            return False
        except BaseException as caught:  # noqa: BLE001  (hypothesis re-raises each failure it kept)
            for e in _leaves(caught):
                if isinstance(e, KeyboardInterrupt):
                    raise e
                if not type(e).__name__.startswith("Fuzz_"):
                    errors.append("".join(traceback.format_exception(e))[-3000:])
                    return False
            return True
        return False

    for round_number in range(1000):
        masked = known | set(best)
        if not search(round_number, masked) or out_of_budget:
            break
    counts["rounds"] = round_number + 1
    counts["calls"] = len(cache)
    if out_of_budget:
        counts[f"truncated ({out_of_budget[0]})"] = 1
    findings = []
    for text, spec, outcome in best.values():
        known.add((outcome["call"], outcome["kind"], outcome["key"]))
        findings.append({**outcome, "target": target.path, "reproducer": reproducer(outcome["source"] or text, module_name)})
    if errors:
        counts["harness_errors"] = errors[:3]
    for text, outcome, defect in known_hits.values():
        findings.append({**outcome, "target": target.path, "known": defect,
                         "reproducer": reproducer(outcome["source"] or text, module_name)})
    return findings, counts


def known_defect(outcome: dict) -> str | None:
    """The KNOWN_DEFECTS description a failure matches, if any."""
    for call, kind, text, defect in KNOWN_DEFECTS:
        if (re.fullmatch(call, outcome["call"]) and re.fullmatch(kind, outcome["kind"])
                and (re.search(text, outcome["detail"]) or re.search(text, outcome.get("source") or ""))):
            return defect
    return None


def all_targets(module) -> tuple[list[Target], dict[str, str]]:
    """The targets of a module (public_targets with its PUBLIC_SUBMODULES, less EXCLUDED) and, for rigiddyn,
    the properties of properties.py as targets "check.<name>"; the names left out with the reason."""
    every, skipped = public_targets(module, PUBLIC_SUBMODULES.get(module.__name__, ()))
    skipped.update({t.path: EXCLUDED[t.path] for t in every if t.path in EXCLUDED})
    every = [t for t in every if t.path not in EXCLUDED]
    if module.__name__ in PROPERTIES:
        properties = importlib.import_module(PROPERTIES[module.__name__])
        every += [Target(f"check.{name}", None, ((),), ("None",), getattr(properties, name).__doc__ or "")
                  for name in properties.STRATEGIES]
    return every, skipped


def target_strategy(strategies: Strategies, t: Target):
    """The specs of calls of target t: a property's drawn parameters, else strategies.call(t)."""
    if t.path.startswith("check."):
        where, name = PROPERTIES[strategies.module.__name__], t.path.split(".", 1)[1]
        return importlib.import_module(where).STRATEGIES[name].map(lambda params: ("check", where, name, params))
    return strategies.call(t)


def _leaves(error: BaseException):
    if isinstance(error, BaseExceptionGroup):
        for e in error.exceptions:
            yield from _leaves(e)
    else:
        yield error


def format_findings(findings) -> str:
    out = []
    for f in findings:
        out.append(f"== {f['call']}: {f['kind']} ({f['key']}) [found via {f['target']}]"
                   + (f"\n   known defect: {f['known']}" if "known" in f else ""))
        out.append("   " + f["detail"].replace("\n", "\n   "))
        if f["reproducer"]:
            out.append("   reproducer:\n      " + f["reproducer"].replace("\n", "\n      "))
    return "\n".join(out)


def _preload() -> None:
    """Import what calls may need before forking, so no worker pays for it inside the timeout."""
    for name in ("scipy.spatial.transform", "matplotlib"):
        try:
            importlib.import_module(name)
        except ImportError:
            pass
    if "matplotlib" in sys.modules:
        sys.modules["matplotlib"].use("Agg")
        importlib.import_module("matplotlib.pyplot")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--module", default="rigiddyn", help="module whose __all__ is fuzzed")
    parser.add_argument("--examples", type=int, default=25, help="hypothesis examples per target")
    parser.add_argument("--calls", type=int, default=150,
                        help="calls per target, generation and shrinking together (the reproducible bound)")
    parser.add_argument("--budget", type=float, default=math.inf,
                        help="seconds per target, shrinking included (interactive hunts: ends runs by time)")
    parser.add_argument("--total-budget", type=float, default=math.inf,
                        help="seconds for all targets: each gets at most its share of what is left")
    parser.add_argument("--timeout", type=float, default=2.0, help="CPU seconds before a call is sent SIGINT")
    parser.add_argument("--grace", type=float, default=3.0, help="CPU seconds a call may take to stop after SIGINT")
    parser.add_argument("--memory-gb", type=float, default=2.0, help="address space a worker may add")
    parser.add_argument("--only", default="", help="regex: fuzz only the targets whose path matches")
    parser.add_argument("--seed-offset", type=int, default=0,
                        help="shift every target's seeds (a deep hunt explores beyond the CI profile's examples)")
    parser.add_argument("--json", help="write the findings and per-target counts here")
    parser.add_argument("--list", action="store_true", help="print the targets and exit")
    args = parser.parse_args(argv)
    # the driver only generates values (numpy casts of 1e300 to float32 overflow on purpose)
    warnings.filterwarnings("ignore", category=RuntimeWarning)
    warnings.filterwarnings("ignore", message="Generating overly large repr")

    module = importlib.import_module(args.module)
    every, skipped = all_targets(module)
    targets = [t for t in every if re.search(args.only, t.path)]
    if args.list:
        print("\n".join(t.path for t in targets))
        return 0
    _preload()
    words = docstring_words(module, every)
    started = time.monotonic()
    findings, counts = [], {}
    with tempfile.TemporaryDirectory(prefix="rigiddyn-fuzz-") as scratch:
        runner = Runner(args.module, args.timeout, args.grace, args.memory_gb, Path(scratch))
        known: set = set()
        try:
            strategies = Strategies(module, every, words, PUBLIC_SUBMODULES.get(args.module, ()))
            for i, t in enumerate(targets):
                t0 = time.monotonic()
                share = (args.total_budget - (t0 - started)) / (len(targets) - i)
                found, counts[t.path] = fuzz_target(t, target_strategy(strategies, t), runner, args.module, args.examples,
                                                    args.calls, max(0.5, min(args.budget, share)), known,
                                                    args.seed_offset)
                findings += found
                print(f"{t.path}: {time.monotonic() - t0:.1f} s, "
                      f"{ {k: v for k, v in counts[t.path].items() if k != 'harness_errors'} }"
                      + (f", {len(found)} finding(s)" if found else ""), flush=True)  # known defects' included
        finally:
            runner.close()
    findings.sort(key=lambda f: (f["call"], f["kind"], f["key"]))  # each (call, kind, key) is found once
    known = [f for f in findings if "known" in f]
    findings = [f for f in findings if "known" not in f]
    elapsed = time.monotonic() - started
    unexercised = [p for p, c in counts.items() if not c.get("returned") and not c.get("rejected")
                   and not any(f["target"] == p for f in findings + known)]
    truncated = [p for p, c in counts.items() if any(k.startswith("truncated") for k in c)]
    print(f"\n{len(targets)} targets in {elapsed:.0f} s; {len(findings)} distinct finding(s); "
          f"not exercised: {unexercised or 'none'}; cut short by --calls/--budget: {truncated or 'none'}")
    if findings:
        print(format_findings(findings))
    if known:
        print(f"\n{len(known)} finding(s) of known defects (KNOWN_DEFECTS):")
        print(format_findings(known))
    if args.json:
        Path(args.json).write_text(json.dumps({"findings": findings, "known": known, "counts": counts, "skipped": skipped,
                                               "unexercised": unexercised, "truncated": truncated,
                                               "seconds": elapsed}, indent=1))
    return 1 if findings else (2 if unexercised else 0)


if __name__ == "__main__":
    sys.exit(main())
