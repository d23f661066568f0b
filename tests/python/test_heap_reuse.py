"""Importing rigiddyn keeps the freed heap for reuse (glibc's M_MMAP_THRESHOLD and M_TRIM_THRESHOLD at the highest
values glibc reaches on its own), so that a run recording every step does not fault its records' pages in again at
every call; unless the user chose glibc's malloc settings or set RIGIDDYN_KEEP_MALLOC=1."""

import json
import os
import platform
import subprocess
import sys

import pytest

pytestmark = pytest.mark.skipif(platform.system() != "Linux" or platform.libc_ver()[0] != "glibc",
                                reason="glibc's malloc settings")

# The shipped pendulum recording each of 2712 rk4 steps, three calls to warm up and then the minor page faults of
# three more calls (the records: 2713 rows of ~40 numbers, ~210 pages a call, every one faulted in again where the
# heap's freed top goes back to the system)
SCRIPT = """
import json, resource, rigiddyn as rd
scene, states, _ = rd.load_scene("pendulum")
def call():
    rd.simulate(scene, states, 20.0 / 2712, steps=2712, method="rk4", error=False)
for _ in range(3):
    call()
before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
for _ in range(3):
    call()
print(json.dumps(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before))
"""


def faults_of_three_calls(**env):
    """The minor page faults of three calls in a fresh interpreter whose environment is this one's without malloc's
    settings (a Dask cluster started in this process sets MALLOC_TRIM_THRESHOLD_ in its environment) and with `env`."""
    inherited = {k: v for k, v in os.environ.items()
                 if not k.startswith("MALLOC_") and k not in ("GLIBC_TUNABLES", "RIGIDDYN_KEEP_MALLOC")}
    run = subprocess.run([sys.executable, "-c", SCRIPT], env={**inherited, **env}, capture_output=True, text=True,
                         check=True)
    return json.loads(run.stdout)


def test_a_run_recording_every_step_reuses_the_freed_heap():
    # glibc's defaults (the opt-out, and a user's own setting): every call faults its ~190 record pages in again
    given_back = faults_of_three_calls(RIGIDDYN_KEEP_MALLOC="1")
    chosen = faults_of_three_calls(MALLOC_TRIM_THRESHOLD_="131072")
    assert given_back > 300 and chosen > 300, (given_back, chosen)
    # kept: the records' pages are the last calls' (a few pages of Python objects may still fault, and another process
    # may disturb one interpreter: the fewer of two, under a tenth of the faults with the heap given back)
    kept = min(faults_of_three_calls() for _ in range(2))
    assert kept < given_back / 10, (kept, given_back)
