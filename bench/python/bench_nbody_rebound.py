"""The N-body direct sum and leapfrog against REBOUND (the optional `rebound` package, in the `peers` extra):
the same cluster of N equal point masses under softened mutual gravity, stepped by the second-order
kick–drift–kick leapfrog in both libraries.

- rigiddyn: a scene of N particles with one MutualGravity (G = 1, softening 0.01), method `splitting_dlm`
  (the kick–drift–kick leapfrog: its closing half-kick merged with the next step's opening one, so one
  force evaluation per step), no error estimate;
- REBOUND: the same particles, `integrator = "leapfrog"` (drift–kick–drift, one force evaluation per step),
  `gravity = "basic"` (the direct O(N²) sum), the same softening and step.

Both evaluate the forces once per step, so the cost per pair is the step's CPU time / (N (N − 1) / 2)
(the O(N) drifts and kicks are under 1 % of it from N = 100 on). The relative energy error |ΔE/E0| after
the run is printed for both: the two leapfrogs are the same second-order method (kick–drift–kick and
drift–kick–drift are adjoint halves of one composition), so at the same step their errors are of the same
size, and the ratio of CPU times is the ratio at equal energy error. Both energies are computed here by one
formula, E = Σ ½ m |v|² − Σ_{i<j} G m_i m_j / √(|r_ij|² + ε²), from each library's final positions and
velocities (REBOUND's own `energy()` leaves the softening out of the potential, so it is not conserved by a
softened run). Times are process CPU time (either library may use threads: all count), the fastest of a
few runs.

Two figures per pair. The run's: rigiddyn's whole `simulate` call (the scene's compile, the states' conversion, its
two records) against REBOUND's `steps` call (its particles added before the clock starts). A step's: the time of a
run of 2s steps less that of s steps in each library, over s steps, so that neither library's cost per run enters it.

    nbody_leapfrog_pair            the runs' CPU times per pair
    nbody_leapfrog_step_pair       a step's CPU time per pair (2s steps less s)

    python bench/python/bench_nbody_rebound.py           # N = 100 and 1000
    python bench/python/bench_nbody_rebound.py --small   # N = 100 and 300 (what ctest runs)

Without rebound the script says so and prints rigiddyn's rows only.
"""

import time

import numpy as np

import rigiddyn as rd
from _bench_common import parse_small, report_ratio

G, SOFTENING, DT = 1.0, 0.01, 1e-3


def cluster(n):
    """Masses (n,) [kg], positions (n, 3) [m] and velocities (n, 3) [m/s] of an equal-mass cluster of total
    mass 1: positions normal of unit spread, velocities normal of spread 0.3 (roughly virial), seed 0."""
    rng = np.random.default_rng(0)
    return np.full(n, 1.0 / n), rng.normal(size=(n, 3)), 0.3 * rng.normal(size=(n, 3))


def energy(m, p, v):
    """E = Σ ½ m |v|² − Σ_{i<j} G m_i m_j / √(|p_i − p_j|² + ε²) [J] (the softened potential of MutualGravity)."""
    i, j = np.triu_indices(len(m), 1)
    r2 = np.sum((p[i] - p[j]) ** 2, axis=1)
    return 0.5 * np.sum(m * np.sum(v * v, axis=1)) - G * np.sum(m[i] * m[j] / np.sqrt(r2 + SOFTENING**2))


def fastest(fn, repeats):
    """(fastest process CPU time [s] of `repeats` calls of fn(), fn()'s last result)."""
    best, out = float("inf"), None
    for _ in range(repeats):
        start = time.process_time()
        out = fn()
        best = min(best, time.process_time() - start)
    return best, out


def rigiddyn_run(m, p, v, steps):
    """(CPU seconds, |ΔE/E0|) of `steps` leapfrog steps of the cluster in rigiddyn."""
    scene = rd.Scene([rd.Particle(float(mass)) for mass in m], elements=[rd.MutualGravity(G=G, softening=SOFTENING)])
    states = [rd.ParticleState(p_W=tuple(pi), v_W=tuple(vi)) for pi, vi in zip(p, v)]

    def run():
        return rd.simulate(scene, states, DT, steps=steps, method="splitting_dlm", record_every=steps, error=False)

    seconds, result = fastest(run, 3)
    E0, E = energy(m, p, v), energy(m, result.p_W[-1], result.v_W[-1])
    return seconds, abs((E - E0) / E0)


def step_seconds(run, steps):
    """CPU seconds of `steps` steps less a run's own cost: run(2 steps) − run(steps), each the fastest of 3."""
    return run(2 * steps)[0] - run(steps)[0]


def rebound_run(rebound, m, p, v, steps):
    """(CPU seconds, |ΔE/E0|) of `steps` leapfrog steps of the cluster in REBOUND (a fresh simulation per run)."""
    def run():
        sim = rebound.Simulation()
        sim.G, sim.softening, sim.dt = G, SOFTENING, DT
        sim.integrator, sim.gravity = "leapfrog", "basic"
        for mass, pi, vi in zip(m, p, v):
            sim.add(m=float(mass), x=pi[0], y=pi[1], z=pi[2], vx=vi[0], vy=vi[1], vz=vi[2])
        start = time.process_time()
        sim.steps(steps)
        seconds = time.process_time() - start
        final = np.array([(q.x, q.y, q.z, q.vx, q.vy, q.vz) for q in sim.particles])
        E0, E = energy(m, p, v), energy(m, final[:, :3], final[:, 3:])
        return seconds, abs((E - E0) / E0)

    runs = [run() for _ in range(3)]
    return min(r[0] for r in runs), runs[-1][1]


def main():
    args = parse_small(__doc__, "N = 100 and 300 instead of 100 and 1000")
    try:
        import rebound
    except ImportError:
        rebound = None
        print("rebound is not importable (pip install '.[peers]'): rigiddyn's rows only")
    print(f"vector instructions: {rd.vector_instructions()}")
    for n in (100, 300) if args.small else (100, 1000):
        steps = max(4, int(4e7 / n**2))  # about 4e7 pair evaluations per run
        m, p, v = cluster(n)
        pairs = steps * n * (n - 1) // 2
        t_rd, dE_rd = rigiddyn_run(m, p, v, steps)
        print(f"N = {n}, {steps} steps of {DT:g} s: rigiddyn {t_rd / pairs * 1e9:.2f} ns per pair, |dE/E| {dE_rd:.2e}")
        if rebound is not None:
            t_rb, dE_rb = rebound_run(rebound, m, p, v, steps)
            print(f"N = {n}, {steps} steps of {DT:g} s: REBOUND {t_rb / pairs * 1e9:.2f} ns per pair, |dE/E| {dE_rb:.2e}")
            report_ratio("nbody_leapfrog_pair", pairs, t_rd, t_rb, "rebound")
        s_rd = step_seconds(lambda k: rigiddyn_run(m, p, v, k), steps)
        print(f"N = {n}, a step: rigiddyn {s_rd / pairs * 1e9:.2f} ns per pair")
        if rebound is not None:
            s_rb = step_seconds(lambda k: rebound_run(rebound, m, p, v, k), steps)
            print(f"N = {n}, a step: REBOUND {s_rb / pairs * 1e9:.2f} ns per pair")
            report_ratio("nbody_leapfrog_step_pair", pairs, s_rd, s_rb, "rebound")


if __name__ == "__main__":
    main()
