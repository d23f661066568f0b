"""Instructions per call from Python, counted by callgrind: the stable figure of the fixed cost of a call
(bench_call_overhead.py times the same calls, which a busy machine makes noisy).

Each case runs in a fresh interpreter under valgrind --tool=callgrind twice, with N and N + 1000 calls of it
in a loop (20 and 60 for a run of 1000 steps, its estimate's per-record work included); the difference of the two
totals / the extra calls is what one call costs (the import, the set-up and the interpreter's start cancel).
PYTHONHASHSEED=0 and one BLAS thread make the counts repeat to the instruction.
The bare call (RigidBody.mass, a property getter of a bound class) is the binding layer's floor.

    python bench/python/call_instructions.py           # every case
    python bench/python/call_instructions.py simulate  # the cases whose expression contains "simulate"

Needs valgrind (Debian's valgrind package; not a dependency of the tests, so ctest does not run this). Prints
one line per case: instructions per call and the ratio to the bare call.
"""

import os
import shutil
import subprocess
import sys
import tempfile

SETUP = """import rigiddyn as rd
BODY = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
PENDULUM, PENDULUM_STATE, _ = rd.load_scene("pendulum")
"""
CASES = [
    "BODY.mass",
    "rd.step(BODY, STATE, 0.01)",
    "rd.step(BODY, STATE, dt=0.01, method='rk4', t=0.0)",
    "rd.simulate(BODY, STATE, 0.01, steps=10, error=False)",
    "rd.simulate(BODY, STATE, 0.01, steps=10)",
    "rd.simulate(BODY, STATE, 0.01, steps=1000, error=False)",
    "rd.simulate(BODY, STATE, 0.01, steps=1000)",
    # the shipped compound pendulum recording its 800 steps, its estimate's records "not asymptotic" (their order
    # printed in their verdicts); and run to a tolerance (pilots, run, certificate: the method chosen on a timing
    # probe, which may pick rkmk4 or rk4, near a tie here, and change the count)
    "rd.simulate(PENDULUM, PENDULUM_STATE, duration=20.0, dt=0.025, method='rk4', error=False)",
    "rd.simulate(PENDULUM, PENDULUM_STATE, duration=20.0, dt=0.025, method='rk4')",
    "rd.simulate(PENDULUM, PENDULUM_STATE, duration=20.0, tolerance=1e-3, measure='attitude')",
]
BASE_CALLS = 200
EXTRA_CALLS = 1000
LONG_CALLS = (20, 40)  # the base and extra calls of a case of 1000 steps (a call costs ~100 short ones)


def total_instructions(expression, calls, folder):
    """Callgrind's instruction total for a fresh interpreter that runs `expression` `calls` times."""
    script = os.path.join(folder, "calls.py")
    with open(script, "w") as f:
        f.write(SETUP + f"for _ in range({calls}):\n    {expression}\n")
    env = dict(os.environ, PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    out = os.path.join(folder, "callgrind.out")
    run = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", sys.executable, script],
                         env=env, capture_output=True, text=True, check=True)
    for line in run.stderr.splitlines():
        if "Collected :" in line:
            return int(line.split(":")[-1].replace(",", ""))
    raise RuntimeError("callgrind printed no total:\n" + run.stderr[-2000:])


def per_call(expression, folder):
    """Instructions of one call of `expression`: the difference of two runs of the loop, / the extra calls
    (EXTRA_CALLS over BASE_CALLS; LONG_CALLS for a run of 1000 steps or a given duration)."""
    base, extra = LONG_CALLS if "steps=1000" in expression or "duration=" in expression else (BASE_CALLS, EXTRA_CALLS)
    few = total_instructions(expression, base, folder)
    many = total_instructions(expression, base + extra, folder)
    return (many - few) / extra


def main():
    if shutil.which("valgrind") is None:
        print("valgrind is not installed: no instruction counts (apt-get install valgrind)")
        return
    chosen = [c for c in CASES if len(sys.argv) < 2 or sys.argv[1] in c or c == CASES[0]]
    with tempfile.TemporaryDirectory() as folder:
        counts = {c: per_call(c, folder) for c in chosen}
    bare = counts[CASES[0]]
    for case, count in counts.items():
        print(f"{case:84s} {count:9.0f} instructions  {count / bare:7.1f} x bare")


if __name__ == "__main__":
    main()
