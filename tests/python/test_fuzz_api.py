"""A hypothesis fuzz of the whole public API, run in a subprocess (tests/fuzz/fuzz_api.py).

Every callable of rigiddyn.__all__ (found by introspection, so a new function is fuzzed without a
change here), of the modules it lists and of its other public modules
(rigiddyn.units, rigiddyn.dispersion) is called with plausible and wild arguments: random shapes, dtypes (float64/32/16, int,
bool, complex, object, big-endian) and layouts, magnitudes log-uniform from 1e-323 to 1e308 of both
signs, NaN, inf, empty and 0-d arrays, read-only broadcast views of up to 1e12 rows, scene files (valid,
with units, mutated, broken: tests/fuzz/scene_files.py). Each call runs in a
child process of the fuzz driver, so a segfault or a hang is a finding that names the call, never a
dead pytest. The oracle: the call returns, or raises TypeError/ValueError/MemoryError with a message
(not pybind11's overload list); what it returns is finite unless it warned (RuntimeWarning) or the
docstring says the value may be infinite; it neither crashes nor, past its CPU-time limit, ignores
SIGINT. Beside the calls, the properties of tests/fuzz/properties.py ("check.<name>") check results where
a cheap reference exists: simulate_batch equals serial simulate bitwise (bodies, scenes, any thread count)
and its SIMD path the scalar one to round-off, scene files read back bit for bit and read the same in
any units, Monte Carlo runs are prefixes of longer ones on any thread count, the command line writes what
the API computes, the closed forms (Lagrange top, compound pendulum, rotating frame, constant thrust) keep
their invariants and agree with simulate. Each finding is reported with a minimal reproducer, one test per
function (the function that misbehaved, also when it was only called to build another call's arguments).
Findings of known defects being fixed (fuzz_api.KNOWN_DEFECTS) are listed apart and do not fail.

Cost: the CI profile below is bounded by counts, not time (fixed seeds per target, no example
database, at most 20 examples and 100 calls per target with shrinking), so CI makes the same calls on
every machine (with the same hypothesis version). Measured 2026-11-28 on 2 CPUs shared with other jobs (load
about 10), for the fuzz and the planted-bug check together (`time python3 -m pytest tests/python/test_fuzz_api.py`):
129 s of CPU, 6.5 min of wall time; the same run before the scenes, Monte Carlo, units, scene files, command line
and properties were fuzzed: 101 s of CPU, 5 min of wall time (so they add about 28 s of CPU). A deeper hunt: RIGIDDYN_FUZZ_PROFILE=deep (PROFILES below), or
python tests/fuzz/fuzz_api.py --examples 300 --calls 2000 [--only REGEX].
"""

from __future__ import annotations

import importlib
import inspect
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import rigiddyn

FUZZ_DIR = Path(__file__).resolve().parents[1] / "fuzz"
sys.path.insert(0, str(FUZZ_DIR))
from api_model import public_names  # noqa: E402
from fuzz_api import DOCUMENTED_NON_FINITE, PUBLIC_SUBMODULES, all_targets  # noqa: E402
from planted_bugs import EXPECTED  # noqa: E402

# examples drawn per target, calls per target (shrinking included): a reproducible bound on the cost; "ci" by
# default, RIGIDDYN_FUZZ_PROFILE=deep for a local hunt (about 10x the CI profile's calls)
PROFILES = {"ci": ["--examples", "20", "--calls", "100"], "deep": ["--examples", "200", "--calls", "1000"]}
PROFILE = PROFILES[os.environ.get("RIGIDDYN_FUZZ_PROFILE", "ci")]
TARGETS = [t.path for t in all_targets(rigiddyn)[0]]


def run_fuzz(tmp_path: Path, *args: str) -> dict:
    """Run the fuzz driver in a subprocess on the rigiddyn this pytest imports; its JSON report."""
    report = tmp_path / "fuzz.json"
    env = dict(os.environ)
    package_dir = os.path.dirname(os.path.dirname(os.path.abspath(rigiddyn.__file__)))  # not resolved: symlinks
    env["PYTHONPATH"] = os.pathsep.join([package_dir, env.get("PYTHONPATH", "")])
    proc = subprocess.run([sys.executable, str(FUZZ_DIR / "fuzz_api.py"), "--json", str(report), *args],
                          env=env, capture_output=True, text=True)
    if not report.exists():
        pytest.fail(f"the fuzz driver itself failed (exit {proc.returncode}):\n{proc.stdout[-4000:]}\n{proc.stderr[-4000:]}")
    return json.loads(report.read_text())


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    return run_fuzz(tmp_path_factory.mktemp("fuzz"), *PROFILE)


def _format(findings) -> str:
    return "\n\n".join(f"{f['kind']} ({f['key']}), found while fuzzing {f['target']}:\n{f['detail']}\n"
                       f"reproducer:\n{f['reproducer']}" for f in findings)


# The tests that read the fuzz report share one xdist worker (tests/run_all.sh runs pytest with --dist loadgroup): the
# module's fixture runs once per worker that takes one of its tests, and the fuzz is a minute or more of CPU.
@pytest.mark.slow
@pytest.mark.xdist_group("fuzz_report")
@pytest.mark.parametrize("target", TARGETS)
def test_no_crash_hang_or_silent_non_finite(report, target):
    findings = [f for f in report["findings"]
                if f["call"] == target or (f["call"] not in TARGETS and f["target"] == target)]
    assert not findings, f"{target}: {len(findings)} finding(s)\n\n" + _format(findings)


@pytest.mark.slow
@pytest.mark.xdist_group("fuzz_report")
def test_every_target_was_exercised(report):
    """Each target was called and reached its code (returned or refused its own arguments) at least once,
    and the harness could build every argument it drew."""
    assert report["unexercised"] == []
    broken = {t: c["harness_errors"] for t, c in report["counts"].items() if "harness_errors" in c}
    assert not broken, f"the harness failed to build arguments: {broken}"
    assert sorted(report["counts"]) == sorted(TARGETS)


def test_every_public_name_is_fuzzed_or_explained():
    """Every name of rigiddyn.__all__, of a module it lists and of its other public modules is a target (a class:
    its constructor or methods) or is skipped with a reason."""
    targets, skipped = all_targets(rigiddyn)
    paths = {t.path for t in targets} | set(skipped)
    covered = {p.split(".")[0] for p in paths}
    assert set(rigiddyn.__all__) <= covered
    modules = [n for n in rigiddyn.__all__ if inspect.ismodule(getattr(rigiddyn, n))] + list(PUBLIC_SUBMODULES["rigiddyn"])
    for name in modules:
        module = importlib.import_module(f"rigiddyn.{name}")
        assert {f"{name}.{n}" for n in public_names(module)} <= {".".join(p.split(".")[:2]) for p in paths}, name


@pytest.mark.parametrize("path, kinds, where", DOCUMENTED_NON_FINITE, ids=[e[0] for e in DOCUMENTED_NON_FINITE])
def test_each_allowed_non_finite_value_is_documented(path, kinds, where):
    """The oracle lets a non-finite value through only where the API's own documentation names it."""
    module, attribute = where
    obj = importlib.import_module(module)
    for part in filter(None, attribute.split(".")):
        obj = getattr(obj, part)
    text = inspect.getdoc(obj) or ""
    try:
        text += str(inspect.signature(obj))
    except (TypeError, ValueError):  # pybind11: the signature is the docstring's first line
        pass
    for kind in kinds:
        assert re.search(rf"(?<![\w-]){re.escape(kind)}\b", text, re.IGNORECASE), \
            f"{module}.{attribute} does not mention {kind}"


@pytest.mark.slow
def test_the_harness_finds_each_planted_bug_and_nothing_else(tmp_path):
    """The oracle on a module with one bug of each kind (crash, hang, silent NaN, wrong exception, empty
    message, NaN in a returned object's property, a method's wrong exception) beside correct functions
    (a warned NaN, validation, a slow call that stops on SIGINT)."""
    found = run_fuzz(tmp_path, "--module", "planted_bugs", "--examples", "40", "--calls", "100", "--timeout", "0.2",
                     "--grace", "0.3")
    assert {(f["call"], f["kind"]) for f in found["findings"]} == EXPECTED
    crash = next(f for f in found["findings"] if f["kind"] == "crash")
    assert "SIGSEGV" in crash["detail"] and crash["reproducer"].splitlines()[-1].startswith("rd.crash(")
