"""The cost of a Controller's sample (rigiddyn.Controller): a gyrostat with three wheels, RK4 at dt = 0.01 s.

Each case runs `steps` steps recording only the first and last state, without the global error estimate, and
prints the time per step and, with a controller, the cost of a sample over the plain run's,
    (t_controlled - t_plain) / samples,
for a Python law that returns no command (the core's own cost: the state read, the call, the commands held), for
rigiddyn.control.PDAttitude in C++ (what simulate runs for it, without the GIL) and in Python (the same law behind a
lambda), each at 100 and 10 samples per simulated second; and a PythonForce (a zero force, called at every stage
of every step: four calls per RK4 step) for comparison. The fastest of three runs each.

Then rigiddyn.monte_carlo of the shipped cubesat_detumbling under its B-dot law (in C++), 16 samples of 8 000
steps (2 000 with --small) with their global error estimates: the samples one after the other, and threads=k at
once on every core (k = default_thread_count()); its ratio line is the speed-up (the same result, bit for bit: a
test holds it). Each sample's Python work (its law's copy, the call, its result) takes the GIL, so samples of a few
milliseconds gain less.

    python bench/python/bench_controller.py           # 100 000 steps
    python bench/python/bench_controller.py --small   # 5 000 steps (what ctest runs)
"""

import warnings

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, parse_small
from rigiddyn.control import PDAttitude


def main():
    args = parse_small(__doc__, "5 000 steps instead of 100 000")
    steps, dt = (5_000 if args.small else 100_000), 0.01
    sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel(a, 0.05) for a in np.eye(3)])
    x0 = rd.GyrostatState(q_WB=(0.0, 0.0, np.sin(0.05), np.cos(0.05)), wheel_speeds=[0.0, 0.0, 0.0])

    def run(model, initial, **kwargs):
        with warnings.catch_warnings():  # a body at rest: the balance's scale is round-off (not this figure's subject)
            warnings.simplefilter("ignore", rd.AccuracyWarning)
            return best_time(lambda: rd.simulate(model, initial, dt, steps, record_every=steps, error=False,
                                                 **kwargs))

    plain = run(sat, x0)
    print(f"plain: {plain / steps * 1e9:.0f} ns/step")
    law = PDAttitude(3.0, 8.0, np.eye(3))
    cases = (("python law, no command", lambda s: {}), ("PDAttitude in C++", law),
             ("PDAttitude in Python", lambda s: law(s)))
    for period in (0.01, 0.1):
        samples = round(steps * dt / period)
        for name, fn in cases:
            t = run(sat, x0, controller=rd.Controller(period, fn))
            print(f"period {period} s ({samples} samples), {name}: {(t - plain) / samples * 1e6:.2f} us/sample")
    force = rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0)))
    scene = rd.Scene([rd.RigidBody(100.0, [10.0, 12.0, 15.0])], elements=[force])
    t = run(scene, [rd.RigidBodyState()])
    print(f"PythonForce (four calls per step): {t / steps * 1e6:.2f} us/step")
    monte_carlo_on_threads(2000 if args.small else 8000)


def monte_carlo_on_threads(steps):
    """monte_carlo under a shipped law, its samples one after the other and on every core."""
    detumbling = rd.load_scene("cubesat_detumbling")
    run = dict(seed=1, dt=detumbling.run.dt, steps=steps, record_every=20, controller=detumbling.run.controller,
               dispersions={"cubesat.w_B": rd.dispersion.Normal(std=1e-2)})
    threads = rd.default_thread_count()
    one = best_time(lambda: rd.monte_carlo(detumbling.scene, detumbling.initial, 16, **run))
    at_once = best_time(lambda: rd.monte_carlo(detumbling.scene, detumbling.initial, 16, threads=threads, **run))
    print(f"monte_carlo, 16 samples under B-dot: one after the other {one * 1e3:.1f} ms, threads={threads} "
          f"{at_once * 1e3:.1f} ms: ratio {one / at_once:.2f}")


if __name__ == "__main__":
    main()
