"""simulate() from Python against the same run timed inside C++, and against the numpy reference.

One free rigid body (I = diag(1, 2, 3), w_B = (0.3, 2, 0.5)) stepped by RK4 (and every classical
method) for n steps, recording every 1000th step:
  - python: wall time of rd.simulate(...) called from Python (argument conversion, GIL release,
    the C++ loop, result arrays);
  - c++: result.elapsed_seconds, the wall time of the same C++ stepping loop measured inside the
    same call, so "python / c++ - 1" is exactly what the Python boundary adds (target < 10%);
  - reference: rigiddyn_ref.integrators.simulate (numpy, one step at a time) on fewer steps,
    reported per step.
The hand-written C++ loop comparison is in bench/bench_dynamics.cpp (ratio lines).

    python bench/python/bench_dynamics.py           # n = 1e6
    python bench/python/bench_dynamics.py --small   # n = 1e5 (what ctest runs)
"""

import time

import numpy as np

import rigiddyn as rd
from _bench_common import import_reference, parse_small

ref = import_reference("integrators")

METHODS = ["explicit_euler", "semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic", "rk4", "rkmk4"]
INERTIA = np.diag([1.0, 2.0, 3.0])
W0 = [0.3, 2.0, 0.5]


def run(method, steps, repeats):
    """(best Python wall time, C++ loop time of that same call) [s] over `repeats` runs."""
    body = rd.RigidBody(1.0, INERTIA)
    state = rd.RigidBodyState(w_B=W0)
    best = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = rd.simulate(body, state, 1e-4, steps, method=method, record_every=1000, error=False)
        wall = time.perf_counter() - start
        if best is None or wall < best[0]:
            best = (wall, result.elapsed_seconds)
    return best


def reference_per_step(method, steps):
    model = ref.RigidBodyModel(1.0, INERTIA)
    y0 = np.concatenate([np.zeros(3), [0, 0, 0, 1.0], np.zeros(3), W0, [0.0]])
    start = time.perf_counter()
    ref.simulate(model, y0, 1e-4, steps, method)
    return (time.perf_counter() - start) / steps


def main():
    args = parse_small(__doc__, "1e5 steps (ctest)")
    steps = 100_000 if args.small else 1_000_000
    ref_steps = 500 if args.small else 5000
    print(f"simulate, free rigid body, {steps} steps, record every 1000th")
    for method in METHODS:
        wall, cpp = run(method, steps, 3)
        line = (f"{method:42s} python {1e9 * wall / steps:8.1f} ns/step, c++ loop {1e9 * cpp / steps:8.1f} ns/step, "
                f"python/c++ = {wall / cpp:.3f}")
        if ref is not None:
            per_step = reference_per_step(method, ref_steps)
            line += f", numpy reference {1e9 * per_step:10.0f} ns/step, reference/python = {per_step * steps / wall:.0f}"
        print(line)
    if ref is None:
        print("(rigiddyn_ref not found: no reference ratio)")


if __name__ == "__main__":
    main()
