"""PythonForce: the cost of a force written in Python, per call, next to the built-in element it imitates.

Ten particles (1 kg) under uniform gravity g_W = (0, 0, -9.81) m/s², RK4, recording only the first and the
last step. Three scenes, each run `steps` steps:
  - builtin: rigiddyn.UniformGravity (the C++ term);
  - python:  rigiddyn.PythonForce(fn) with fn returning the same force m g (and zero torque) for each body;
  - none:    no element (the rest of the step).
Each is timed by the calling thread's CPU clock (time.thread_time: simulate steps in the calling thread,
and the CPU time is what other load on a shared machine disturbs least), the fastest of several runs;
the Python boundary of simulate() (arguments, result arrays) is in it, under 1 % at the full size. One PythonForce call = one body at one derivative evaluation (RK4: 4 per
step), so
  per call [ns] = (python − none) / (4 · bodies · steps),   per call of the built-in = (builtin − none) / (same).
The ratio line ("ratio pythonforce_per_call/...") puts the two side by side. Both runs must give the same
motion (printed: the largest |Δp_W|, a rounding-level figure). PythonForce holds the GIL in every call.

    python bench/python/bench_scene.py           # 20 000 steps
    python bench/python/bench_scene.py --small   # 1 000 steps (what ctest runs)
"""

import time

import numpy as np

import rigiddyn as rd
from _bench_common import parse_small, report_ratio

BODIES = 10
G_W = np.array([0.0, 0.0, -9.81])
MASS = 1.0


def scene_with(kind):
    """Ten particles at rest 1 m apart along x, with the element `kind` ("builtin", "python", "none")."""
    scene = rd.Scene()
    for _ in range(BODIES):
        scene.add_body(rd.Particle(MASS))
    if kind == "builtin":
        scene.add(rd.UniformGravity(g_W=tuple(G_W)))
    elif kind == "python":
        force, torque = MASS * G_W, np.zeros(3)

        def weight(t, body, p_W, q_WB, v_W, w_B):  # the PythonForce signature
            return force, torque

        scene.add(rd.PythonForce(weight))
    return scene


def initial_states():
    return [rd.ParticleState(p_W=(float(i), 0.0, 0.0), v_W=(0.0, 1.0, 0.0)) for i in range(BODIES)]


def run(kind, steps, repeats):
    """(fastest thread CPU time [s] of `repeats` runs of simulate, the last result)."""
    scene, states = scene_with(kind), initial_states()
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.thread_time()
        result = rd.simulate(scene, states, dt=1e-3, steps=steps, method="rk4", record_every=steps, error=False)
        best = min(best, time.thread_time() - start)
    return best, result


def main():
    args = parse_small(__doc__, "1000 steps (ctest)")
    steps = 1_000 if args.small else 20_000
    t_none, _ = run("none", steps, 5)
    t_builtin, builtin = run("builtin", steps, 5)
    t_python, python = run("python", steps, 3)
    calls = 4 * BODIES * steps
    print(f"PythonForce vs UniformGravity, {BODIES} particles, RK4, {steps} steps ({calls} calls of each element)")
    print(f"  scene without the element  {1e9 * t_none / steps:10.1f} ns/step")
    print(f"  with UniformGravity        {1e9 * t_builtin / steps:10.1f} ns/step")
    print(f"  with PythonForce           {1e9 * t_python / steps:10.1f} ns/step")
    report_ratio("pythonforce_per_call", calls, t_python - t_none, max(t_builtin - t_none, 1e-12), "builtin")
    difference = np.max(np.abs(np.asarray(python.p_W) - np.asarray(builtin.p_W)))
    print(f"  same motion: max |p_W(python) - p_W(builtin)| = {difference:.2e} m")


if __name__ == "__main__":
    main()
