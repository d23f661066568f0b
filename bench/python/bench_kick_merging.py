"""Kick-drift-kick methods on an N-body cluster: one force evaluation per step against RK4's four.

splitting_dlm, splitting_dlm_yoshida4 and exact_flow_kick open and close each step with a kick; between records a
run merges a step's closing kick with the next step's opening one where the loads do not read the velocities (first
same as last, cpp/include/rigiddyn/simulate/run_loop.hpp), so a step costs 1 (splitting_dlm, exact_flow_kick) or 3
(splitting_dlm_yoshida4) evaluations of the direct sum. The baseline, in the same process, is RK4 on the same scene
(4 evaluations per step): the ratios approach 1/4 and 3/4 as N grows and the O(N^2) sum dominates.

    PYTHONPATH=build/<dir>/python python3 bench/python/bench_kick_merging.py [--small]

A run recorded at every step closes each step for its record (kick_merging_<method>_every_step_over_ends: the same
run recorded at every step over recorded at its ends, in the same process): a record costs the potential's O(N^2)
sum, and takes the elements' powers from the closing kick's wrenches, which the next step's opening kick repeats (no
evaluation).

Without --small it also measures the shipped cluster's default method and step against the two it was weighed
against (the figures of the file's comment).
"""

import time

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, parse_small, report_ratio

args = parse_small(__doc__, "N = 100 and 20 steps (ctest)")
n, steps = (100, 20) if args.small else (300, 200)
rng = np.random.default_rng(3)
bodies = [rd.Particle(float(m)) for m in rng.uniform(0.5, 1.5, n)]
scene = rd.Scene(bodies, elements=[rd.MutualGravity(G=1e-3, softening=0.05)])
start = [rd.ParticleState(p_W=tuple(rng.uniform(size=3))) for _ in range(n)]


def run(method, record_every=steps):
    # by default one record at each end (each an O(N^2) evaluation and potential, the same for every method)
    return lambda: rd.simulate(scene, start, 1e-3, steps=steps, method=method, record_every=record_every, error=False,
                               accuracy_level=None)


t_rk4 = best_time(run("rk4"))
for method in ("splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"):
    t_ends = best_time(run(method))
    report_ratio(f"kick_merging_{method}_over_rk4", steps, t_ends, t_rk4, "rk4")
    report_ratio(f"kick_merging_{method}_every_step_over_ends", steps, best_time(run(method, 1)), t_ends, "ends")


def cluster_defaults():
    """The shipped cluster's method and step (its file's comment, docs/scenes.md): |E(2) - E(0)|/|E(0)| and the
    CPU time of its 2 time units for the file's choice and the two it was weighed against."""
    cluster, start_states, _ = rd.load_scene("cluster")
    for method, dt in (("splitting_dlm", 1 / 256), ("splitting_dlm", 1 / 384), ("splitting_dlm_yoshida4", 1 / 128)):
        steps = round(2 / dt)
        began = time.process_time()
        r = rd.simulate(cluster, start_states, dt, steps=steps, method=method, record_every=steps, error=False,
                        accuracy_level=None)
        seconds = time.process_time() - began
        energy = r.total_energy
        print(f"cluster {method} at dt = 1/{round(1 / dt)}: |dE/E| {abs(energy[-1] - energy[0]) / abs(energy[0]):.2e} "
              f"in {seconds:.2f} s of CPU")


if not args.small:
    cluster_defaults()
