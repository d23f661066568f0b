"""What result.error costs: simulate with error=True against error=False, best of several runs each.

The estimate runs the method again at 2 dt and 4 dt (+0.75x the steps), then compares the records (a pass over
them); the ratio printed is the whole call's, Python boundary included. Cases: one free rigid body (rk4) and a
scene of 10 rigid bodies under UniformGravity and pairwise SpringDampers (rk4).

Run: PYTHONPATH=build/py/python python3 bench/python/bench_global_error.py
"""

from __future__ import annotations

import timeit

import numpy as np

import rigiddyn as rd


def free_body():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    state = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])
    return lambda error: rd.simulate(body, state, dt=1e-3, steps=200_000, record_every=100, error=error)


def ten_body_scene():
    bodies = [rd.RigidBody(1.0, [1.0, 2.0, 3.0]) for _ in range(10)]
    springs = [rd.SpringDamper(body_a=i, body_b=i + 1, stiffness=10.0, damping=0.1, rest_length=1.0) for i in range(9)]
    scene = rd.Scene(bodies, elements=[rd.UniformGravity(), *springs])
    states = [rd.RigidBodyState(p_W=[1.0 * i, 0.0, 0.0], w_B=[0.1, 1.0, 0.1]) for i in range(10)]
    return lambda error: rd.simulate(scene, states, dt=1e-3, steps=20_000, record_every=100, error=error)


def best_of(run, error, repeat=5):
    return min(timeit.repeat(lambda: run(error), number=1, repeat=repeat))


def main():
    for name, make in (("free body, rk4, 200000 steps", free_body), ("10-body scene, rk4, 20000 steps", ten_body_scene)):
        run = make()
        off, on = best_of(run, False), best_of(run, True)
        print(f"{name:34s} error=False {off * 1e3:8.2f} ms   error=True {on * 1e3:8.2f} ms   ratio {on / off:.2f}")
    assert np.isfinite(off)


if __name__ == "__main__":
    main()
