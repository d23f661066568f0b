"""What result.error costs: simulate with error=True against error=False, best of several runs each.

The estimate runs the method again at 2 dt and 4 dt (+0.75x the steps), then compares the records (a pass over
them). A run whose balances close whatever the estimate says makes it on the first read of result.error: the ratios
printed are the whole call's, Python boundary included, without reading result.error ("not read") and with it
("read"). Cases: one free rigid body (rk4), recording every 100th, every 4th (every record compared) and every step,
a scene of 10 rigid bodies under UniformGravity and pairwise SpringDampers (rk4), and a batch of 64 free bodies on one
thread (simulate_batch makes every batch's estimate on the first read of result.error).

Run: PYTHONPATH=build/py/python python3 bench/python/bench_global_error.py [--small]
(`--small`, what ctest runs: a tenth of the steps.)
"""

from __future__ import annotations

import timeit

import numpy as np

import rigiddyn as rd
from _bench_common import parse_small


def free_body(steps, record_every=100):
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    return lambda error: rd.simulate(body, state, dt=1e-3, steps=steps, record_every=record_every, error=error)


def ten_body_scene(steps):
    bodies = [rd.RigidBody(1.0, [1.0, 2.0, 3.0]) for _ in range(10)]
    springs = [rd.SpringDamper(body_a=i, body_b=i + 1, stiffness=10.0, damping=0.1, rest_length=1.0) for i in range(9)]
    scene = rd.Scene(bodies, elements=[rd.UniformGravity(), *springs])
    states = [rd.RigidBodyState(p_W=[1.0 * i, 0.0, 0.0], w_B=[0.1, 1.0, 0.1]) for i in range(10)]
    return lambda error: rd.simulate(scene, states, dt=1e-3, steps=steps, record_every=100, error=error)


def free_body_batch(steps):
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = [rd.RigidBodyState(w_B=[0.1, 1.0 + 0.01 * i, 0.1]) for i in range(64)]
    return lambda error: rd.simulate_batch(body, states, dt=1e-3, steps=steps, record_every=100, threads=1,
                                           error=error)


def best_of(run, error, read=False, repeat=5):
    return min(timeit.repeat(lambda: run(error).error if read else run(error), number=1, repeat=repeat))


def main():
    steps = 20_000 if parse_small(__doc__, "a tenth of the steps").small else 200_000  # the free body's
    cases = ((f"free body, rk4, {steps} steps", lambda: free_body(steps)),
             # every record a common record of the three runs (record_every a multiple of 4): each one compared
             ("  the same, recording every 4th step", lambda: free_body(steps, 4)),
             # three records of four between the common ones: interpolated
             ("  the same, recording every step", lambda: free_body(steps, 1)),
             (f"10-body scene, rk4, {steps // 10} steps", lambda: ten_body_scene(steps // 10)),
             (f"batch of 64 bodies, rk4, {steps // 20} steps", lambda: free_body_batch(steps // 20)))
    for name, make in cases:
        run = make()
        off, on, read = best_of(run, False), best_of(run, True), best_of(run, True, read=True)
        print(f"{name:36s} error=False {off * 1e3:8.2f} ms   error=True: not read {on / off:.2f}x, "
              f"read {read / off:.2f}x")
    assert np.isfinite(off)


if __name__ == "__main__":
    main()
