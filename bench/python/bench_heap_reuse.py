"""A run recording every step with the freed heap kept for reuse (rigiddyn's setting at import) and with glibc's
malloc defaults (RIGIDDYN_KEEP_MALLOC=1), each in a fresh interpreter (the setting is the process's).

The shipped pendulum (rk4, recording each of 2712 steps over 20 s), simulate without and with its estimate read:
the minor page faults of a call after three warm-up calls and the best wall time of a call, printed per setting,
then the ratio of the two settings' times. glibc only (elsewhere the setting does nothing). Run::

    PYTHONPATH=build/<dir>/python python3 bench/python/bench_heap_reuse.py [--small]
"""

import json
import os
import platform
import subprocess
import sys

from _bench_common import parse_small

CHILD = """
import json, resource, sys, time, rigiddyn as rd
scene, states, _ = rd.load_scene("pendulum")
calls = int(sys.argv[1])
def plain():
    rd.simulate(scene, states, 20.0 / 2712, steps=2712, method="rk4", error=False)
def estimated():
    rd.simulate(scene, states, 20.0 / 2712, steps=2712, method="rk4").error
out = {}
for name, call in (("plain", plain), ("estimated", estimated)):
    for _ in range(3):
        call()
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    call()
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before
    best = float("inf")
    for _ in range(calls):
        start = time.perf_counter()
        call()
        best = min(best, time.perf_counter() - start)
    out[name] = {"faults": faults, "seconds": best}
print(json.dumps(out))
"""


def measure(calls, **env):
    """{case: {faults, seconds}} of a fresh interpreter whose environment is this one's without malloc's settings,
    and with `env`."""
    inherited = {k: v for k, v in os.environ.items()
                 if not k.startswith("MALLOC_") and k not in ("GLIBC_TUNABLES", "RIGIDDYN_KEEP_MALLOC")}
    run = subprocess.run([sys.executable, "-c", CHILD, str(calls)], env={**inherited, **env}, capture_output=True,
                         text=True, check=True)
    return json.loads(run.stdout)


def main():
    args = parse_small(__doc__, "5 timed calls per case instead of 30")
    if platform.system() != "Linux" or platform.libc_ver()[0] != "glibc":
        print("not glibc: rigiddyn leaves malloc's settings as they are")
        return
    calls = 5 if args.small else 30
    kept, defaults = measure(calls), measure(calls, RIGIDDYN_KEEP_MALLOC="1")
    for case in ("plain", "estimated"):
        k, d = kept[case], defaults[case]
        print(f"{case:9s} kept for reuse: {k['faults']:4d} faults, {k['seconds'] * 1e6:7.0f} us a call; "
              f"glibc's defaults: {d['faults']:4d} faults, {d['seconds'] * 1e6:7.0f} us a call; "
              f"ratio kept/defaults = {k['seconds'] / d['seconds']:.2f}")


if __name__ == "__main__":
    main()
