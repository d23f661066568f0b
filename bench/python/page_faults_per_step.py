"""The minor page faults per step of a run after its first step, through the Python package.

1000 rigid spheres (1 kg, I = 0.004 kg m² about every axis) under UniformGravity, RK4, dt = 1 ms,
recording only the first and last states. Before each run glibc's ``malloc_trim(0)`` gives the heap's free
memory back to the system, as in a process that freed a large block: a step that allocated a vector of the
state's size would then fault its pages in again at every step. Prints (faults of a 101-step run − faults of
a 1-step run) / 100, three times; 0 when no step allocates. Linux with glibc only. Run::

    PYTHONPATH=build/<dir>/python python3 bench/python/page_faults_per_step.py
"""
from __future__ import annotations

import ctypes
import resource

import numpy as np

import rigiddyn as rd


def faults_of_run(compiled: rd.CompiledScene, initial: list, steps: int) -> int:
    """Minor page faults [count] of one `simulate` of `steps` steps, after trimming the heap."""
    ctypes.CDLL("libc.so.6").malloc_trim(0)
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    rd.simulate(compiled, initial, dt=1e-3, steps=steps, record_every=steps, error=False)
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before


def main() -> None:
    """Prints the faults per step after the first, three times."""
    rng = np.random.default_rng(1)
    scene = rd.Scene()
    initial = []
    for _ in range(1000):
        scene.add_body(rd.RigidBody(1.0, [0.004, 0.004, 0.004]))
        initial.append(rd.RigidBodyState(p_W=rng.normal(size=3), v_W=rng.normal(size=3), w_B=[0.3, 2.0, 0.5]))
    scene.add(rd.UniformGravity(g_W=[0.0, 0.0, -9.81]))
    compiled = scene.compile("rk4")
    faults_of_run(compiled, initial, 1)  # what a first run touches once
    for _ in range(3):
        per_step = (faults_of_run(compiled, initial, 101) - faults_of_run(compiled, initial, 1)) / 100
        print(f"{per_step:.2f} minor page faults per step after the first")


if __name__ == "__main__":
    main()
