"""Batch runs against MuJoCo's rollout and on a Dask LocalCluster.

  PYTHONPATH=build/<dir>/python python3 bench/python/bench_batch.py [--small] [--part scaling|mujoco|dask ...]

The problem (the same as bench/bench_batch.cpp): N free T-handles (m = 0.1 kg, I = diag(2, 6.5, 8)e-5
kg m^2, python/rigiddyn/problems/t_handle.toml), no gravity, no loads, each from a uniform random attitude
and w_B with N(0, 5 rad/s) components (numpy SeedSequence, so every run draws the same), n RK4 steps of
dt = 0.01 s, only the first and the last state recorded by rigiddyn (MuJoCo's rollout records every step:
112 bytes a step, next to microseconds of stepping). Full size N = 10^4, n = 10^3; --small: N = 64,
n = 100 (what ctest runs).

Every time is printed as wall time and as the process's CPU time (every thread): on a machine shared
with other work the CPU time is the cost per core, the wall time what a user waits. Runs compared are
alternated in one process, the fastest of each kept.

1. rigiddyn.simulate_batch at 1 and 2 threads: thread scaling (target >= 1.8 on 2 free cores; the
   C++ bench/bench_batch.cpp prints the same next to a hand loop's, the load's yardstick).
2. MuJoCo (optional `peers` extra: pip install mujoco): a free joint body with the same diaginertia,
   integrator RK4, the same dt, every optional stage disabled (the peer at its fastest), through
   mujoco.rollout at nthread = 1 and = cores: MuJoCo / rigiddyn per core (target >= 20); also
   simulate_batch(simd=True). Both integrate Euler's equations for w_B with classic RK4
   (MuJoCo's free joint: constant mass matrix in the body frame, qvel[3:6] = w_B); the final w_B and
   attitudes must agree within the sum of the two engines' errors at that dt, each estimated by step
   doubling (see same_motion).
3. Dask (full size only; optional `distributed` extra: pip install 'rigiddyn[distributed]'): the
   overhead of one task on a 2-worker LocalCluster (rigiddyn.distributed.measure_task_overhead), the
   chunk size that amortises it (overhead <= 5 % of a task) and the batch time against chunk_size, and
   10^5 tumbling bodies x 100 steps through rigiddyn.distributed.simulate_batch and rigiddyn.monte_carlo
   on that cluster vs the threaded local run (target: within 1.3x), checked bitwise equal.
Without mujoco or dask the script prints why and skips that part.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import sys

import numpy as np
import rigiddyn
from _bench_common import Timing, cores, fastest, mujoco_last_states, report_ratio

MASS = 0.1  # [kg]
INERTIA = (2.0e-5, 6.5e-5, 8.0e-5)  # principal moments about the centre of mass [kg m^2]
DT = 0.01  # [s]
SEED = 20261124
COMMAND = "PYTHONPATH=build/<dir>/python python3 bench/python/bench_batch.py"


def load():
    """The 1-minute load average (a figure's context on a shared machine), or nan."""
    try:
        return os.getloadavg()[0]
    except OSError:
        return float("nan")


def tumbling_states(n, seed=SEED):
    """n initial states as stacked arrays: p_W, v_W zero (n, 3), q_WB (x, y, z, w) uniform on SO(3) (a
    normalised 4-D Gaussian: the Haar measure), w_B [rad/s] with N(0, 5) components. Sample i's draws come
    from SeedSequence(seed).spawn(n)[i] alone, so any run of the first n' samples is a prefix."""
    q = np.empty((n, 4))
    w = np.empty((n, 3))
    for i, child in enumerate(np.random.SeedSequence(seed).spawn(n)):
        rng = np.random.default_rng(child)
        q[i] = rng.standard_normal(4)
        w[i] = 5.0 * rng.standard_normal(3)
    q /= np.linalg.norm(q, axis=1)[:, None]
    return {"p_W": np.zeros((n, 3)), "q_WB": q, "v_W": np.zeros((n, 3)), "w_B": w}


def subset(states, count):
    """The first `count` samples of stacked states."""
    return {key: value[:count] for key, value in states.items()}


# ---- rigiddyn ----------------------------------------------------------------------------------------
def rigiddyn_final(states, steps, dt, threads, simd=False):
    """(final (w_B (N, 3) [rad/s], q_WB (N, 4) (x, y, z, w)), Timing) of rigiddyn.simulate_batch (first and
    last records; simd: its SIMD path)."""
    body = rigiddyn.RigidBody(MASS, np.array(INERTIA))
    clock = Timing()
    # error=False: the runs alone, the same work as the baselines' (no global error estimate)
    result = rigiddyn.simulate_batch(body, states, dt, steps, method="rk4", record_every=steps, threads=threads,
                                     simd=simd, error=False)
    elapsed = clock.stop()
    final = result.body(0)  # the body's columns, (N, n_records, ...)
    return (np.array(final.w_B[:, -1, :]), np.array(final.q_WB[:, -1, :])), elapsed


# ---- MuJoCo ------------------------------------------------------------------------------------------
class MuJoCoFreeBodies:
    """The same free body in MuJoCo: one free joint, diaginertia, no gravity, no contacts, RK4 at dt, every
    optional stage disabled."""

    def __init__(self, mujoco, dt):
        i1, i2, i3 = INERTIA
        xml = f"""<mujoco><option timestep="{dt!r}" integrator="RK4" gravity="0 0 0"/>
          <worldbody><body><freejoint/><inertial pos="0 0 0" mass="{MASS!r}" diaginertia="{i1!r} {i2!r} {i3!r}"/>
          </body></worldbody></mujoco>"""
        self.mujoco = mujoco
        self.model = mujoco.MjModel.from_xml_string(xml)
        # every optional stage off (constraints, contacts, sensors, actuation, islands, ...): none applies to
        # a free body, its motion is unchanged (checked: the same final states bitwise), and MuJoCo measured
        # ~25 % faster so: the peer at its best on this problem
        self.model.opt.disableflags = (1 << int(mujoco.mjtDisableBit.mjNDISABLE)) - 1
        self.spec = mujoco.mjtState.mjSTATE_FULLPHYSICS  # (t, qpos 7 (p, q as w x y z), qvel 6 (v_W, w_B))
        self.size = mujoco.mj_stateSize(self.model, self.spec)

    def initial(self, states):
        """(N, nstate) MuJoCo states of stacked rigiddyn states."""
        n = len(states["w_B"])
        data = self.mujoco.MjData(self.model)
        out = np.empty((n, self.size))
        for i in range(n):
            data.qpos[:3] = states["p_W"][i]
            data.qpos[3:7] = np.roll(states["q_WB"][i], 1)  # MuJoCo quaternions are (w, x, y, z)
            data.qvel[:3] = states["v_W"][i]
            data.qvel[3:6] = states["w_B"][i]
            self.mujoco.mj_getState(self.model, data, out[i], self.spec)
        return out

    def final(self, initial, steps, nthread):
        """(final (w_B (N, 3) [rad/s], q_WB (N, 4) (x, y, z, w)), Timing) of mujoco.rollout from `initial`
        (N, nstate) on nthread threads (mujoco_last_states)."""
        last, clock = mujoco_last_states(self.model, initial, steps, nthread)
        return (last[:, 11:14], np.roll(last[:, 4:8], -1, axis=1)), clock  # (w, x, y, z) -> (x, y, z, w)


def attitude_angle(q1, q2):
    """Rotation angle [rad] between unit quaternions (N, 4), sign-invariant and exact for small angles."""
    sign = np.where(np.sum(q1 * q2, axis=1) < 0, -1.0, 1.0)[:, None]
    return 4.0 * np.arctan2(np.linalg.norm(q1 - sign * q2, axis=1), np.linalg.norm(q1 + sign * q2, axis=1))


def same_motion(rd, mj_final, states, steps, mj, check_count):
    """Check that MuJoCo and rigiddyn computed the same motion, on the first check_count samples: the final
    |w_rigiddyn - w_mujoco| and attitude angle between them must be within 2 (e_rigiddyn + e_mujoco) + 4 n eps
    |w| (resp. 4 n eps), e the global error of each engine at dt estimated by step doubling (Richardson:
    e(dt) ~ |x(dt) - x(dt/2)| 2^p / (2^p - 1): p = 4 for rigiddyn's RK4; for MuJoCo p = 4 in w (classic RK4
    on the same Euler equations) and, conservatively, p = 2 in the attitude (its quaternion is advanced by
    the exponential of the stage-averaged velocity, not RK4 on q); the factor 2 covers the estimate's own
    error) plus the round-off of n steps (a few ulps each). Prints the figures; True if every checked sample
    is within its bounds."""
    few = subset(states, check_count)
    rd_w, rd_q = rd[0][:check_count], rd[1][:check_count]
    mj_w, mj_q = mj_final[0][:check_count], mj_final[1][:check_count]
    (rd_w2, rd_q2), _ = rigiddyn_final(few, 2 * steps, DT / 2, threads=None)
    half = MuJoCoFreeBodies(mj, DT / 2)
    (mj_w2, mj_q2), _ = half.final(half.initial(few), 2 * steps, 1)
    scale = np.linalg.norm(rd_w, axis=1)
    roundoff = 4.0 * steps * np.finfo(float).eps
    e_rd = np.linalg.norm(rd_w - rd_w2, axis=1) * 16 / 15
    e_mj = np.linalg.norm(mj_w - mj_w2, axis=1) * 16 / 15
    w_bound = 2.0 * (e_rd + e_mj) + roundoff * scale
    w_diff = np.linalg.norm(rd_w - mj_w, axis=1)
    a_rd = attitude_angle(rd_q, rd_q2) * 16 / 15
    a_mj = attitude_angle(mj_q, mj_q2) * 4 / 3
    a_bound = 2.0 * (a_rd + a_mj) + roundoff
    a_diff = attitude_angle(rd_q, mj_q)
    ok = bool(np.all(w_diff <= w_bound) and np.all(a_diff <= a_bound))
    print(f"same motion (first {check_count} samples; bound 2 (e_rigiddyn + e_mujoco) + 4 n eps, e by step doubling):\n"
          f"  w_B: max |w_rigiddyn - w_mujoco| / |w| = {np.max(w_diff / scale):.2e}; errors at dt up to "
          f"{np.max(e_rd / scale):.2e} (rigiddyn), {np.max(e_mj / scale):.2e} (mujoco); worst difference / bound = "
          f"{np.max(w_diff / w_bound):.2e}\n"
          f"  attitude: max angle between them {np.max(a_diff):.2e} rad; errors at dt up to {np.max(a_rd):.2e} rad "
          f"(rigiddyn), {np.max(a_mj):.2e} rad (mujoco); worst difference / bound = {np.max(a_diff / a_bound):.2e}"
          f" -> {'OK' if ok else 'FAILED'}")
    all_w = np.linalg.norm(rd[0] - mj_final[0], axis=1) / np.linalg.norm(rd[0], axis=1)
    print(f"  all {len(rd[0])} samples: max |w_rigiddyn - w_mujoco| / |w| = {np.max(all_w):.2e}, max attitude angle "
          f"{np.max(attitude_angle(rd[1], mj_final[1])):.2e} rad")
    return ok


def mujoco_part(states, steps, repeats, small):
    """Section 2; returns False if the two engines disagree."""
    try:
        import mujoco
    except ImportError:
        print("\nMuJoCo: skipped (mujoco is not installed: pip install mujoco, the `peers` extra)")
        return True
    n = len(states["w_B"])
    mj = MuJoCoFreeBodies(mujoco, DT)
    initial = mj.initial(states)
    print(f"\nMuJoCo {mujoco.__version__} rollout vs rigiddyn, {n} samples x {steps} RK4 steps of dt = {DT} s "
          f"(load {load():.2f})")
    ok = True
    for threads in sorted({1, cores()}):
        runs = {"rigiddyn": [], "mujoco": [], "rigiddyn simd": []}
        for _ in range(repeats):  # alternated, so that a change of the machine's load hits every run
            rd_final, t = rigiddyn_final(states, steps, DT, threads)
            runs["rigiddyn"].append(t)
            mj_final, t = mj.final(initial, steps, threads)
            runs["mujoco"].append(t)
            runs["rigiddyn simd"].append(rigiddyn_final(states, steps, DT, threads, simd=True)[1])
        mj_t = fastest(runs["mujoco"])
        per = n * steps / 1e9  # ns per sample-step
        for name in ("rigiddyn", "rigiddyn simd"):
            rd = fastest(runs[name])
            print(f"threads = {threads}, {name}: wall {rd.wall / per:.1f} (mujoco {mj_t.wall / per:.1f}) ns/sample-step, "
                  f"mujoco/{name} = {mj_t.wall / rd.wall:.1f}; CPU (per core) {rd.cpu / per:.1f} (mujoco "
                  f"{mj_t.cpu / per:.1f}) ns/sample-step, mujoco/{name} = {mj_t.cpu / rd.cpu:.1f} (target >= 20 per core)")
            report_ratio(f"batch{'_simd' if name.endswith('simd') else ''}_vs_mujoco/threads:{threads}", n, rd.wall,
                         mj_t.wall, "mujoco")
        if threads == 1:
            ok = same_motion(rd_final, mj_final, states, steps, mujoco, min(n, 32 if small else 256)) and ok
    return ok


# ---- rigiddyn thread scaling --------------------------------------------------------------------------
def scaling_part(states, steps, repeats):
    n = len(states["w_B"])
    runs = {1: [], 2: []}
    for _ in range(repeats):  # alternated, so that a change of the machine's load hits both
        for threads, timings in runs.items():
            timings.append(rigiddyn_final(states, steps, DT, threads)[1])
    one, two = fastest(runs[1]), fastest(runs[2])
    print(f"\nrigiddyn.simulate_batch, {n} samples x {steps} RK4 steps (load {load():.2f}, {cores()} cores): "
          f"1 thread {one.wall * 1e3:.1f} ms wall ({one.wall / (n * steps) * 1e9:.1f} ns/sample-step), 2 threads "
          f"{two.wall * 1e3:.1f} ms wall: scaling {one.wall / two.wall:.2f}x (target >= 1.8 on 2 cores); CPU "
          f"{one.cpu * 1e3:.1f} ms vs {two.cpu * 1e3:.1f} ms (equal when threading adds no work)")


# ---- Dask ---------------------------------------------------------------------------------------------
MC_SAMPLES, MC_STEPS = 100_000, 100  # the Monte Carlo: 10^5 tumbling bodies, 1 s each


def monte_carlo_run(client=None, threads=None):
    """(MonteCarloResult, Timing) of rigiddyn.monte_carlo on MC_SAMPLES tumbling T-handles: attitude
    uniform on SO(3), w_B with N(0, 5 rad/s) components, MC_STEPS RK4 steps of DT, first and last records;
    on this machine's `threads` (client None) or on the Dask `client`."""
    from rigiddyn.dispersion import Normal, UniformRotation, monte_carlo

    body = rigiddyn.RigidBody(MASS, np.array(INERTIA))
    dispersions = {"q_WB": UniformRotation(), "w_B": Normal(mean=np.zeros(3), std=5.0)}
    clock = Timing()
    with contextlib.redirect_stderr(io.StringIO()):  # the distributed run's progress bar
        result = monte_carlo(body, rigiddyn.RigidBodyState(), MC_SAMPLES, seed=SEED, dispersions=dispersions, dt=DT,
                             steps=MC_STEPS, record_every=MC_STEPS, threads=threads, client=client, error=False)
    return result, clock.stop()


def dask_part(repeats):
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        print("\nDask: skipped (dask.distributed is not installed: pip install 'rigiddyn[distributed]')")
        return
    import logging

    import rigiddyn.distributed as rd_distributed

    logging.getLogger("distributed").setLevel(logging.ERROR)  # the cluster's start/stop chatter
    body = rigiddyn.RigidBody(MASS, np.array(INERTIA))
    states = tumbling_states(MC_SAMPLES, seed=SEED + 1)
    batch_kwargs = dict(method="rk4", record_every=MC_STEPS, error=False)  # the runs alone, as the baselines
    clock = Timing()
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            Client(cluster) as client:
        started = clock.stop().wall
        overhead = rd_distributed.measure_task_overhead(client)
        per_sample = fastest([rigiddyn_final(subset(states, 2000), MC_STEPS, DT, 1)[1]
                              for _ in range(repeats)]).wall / 2000
        chunk = int(np.ceil(19 * overhead / per_sample))  # o <= 5 % (o + k c)  <=>  k >= 19 o / c
        print(f"\nDask LocalCluster, 2 worker processes x 1 thread (started in {started:.2f} s; load {load():.2f}): "
              f"{overhead * 1e3:.2f} ms per task (rigiddyn.distributed.measure_task_overhead); a sample of "
              f"{MC_STEPS} steps costs {per_sample * 1e6:.1f} us on one thread, so chunks of >= {chunk} samples keep "
              f"the overhead <= 5 % of a task")
        local, dask = [], []
        for _ in range(repeats):  # alternated, so that a change of the machine's load hits both
            clock = Timing()
            local_result = rigiddyn.simulate_batch(body, states, DT, MC_STEPS, threads=2, **batch_kwargs)
            local.append(clock.stop())
            clock = Timing()
            remote = rd_distributed.simulate_batch(body, states, DT, MC_STEPS, client=client, progress=False,
                                                   **batch_kwargs)
            dask.append(clock.stop())
        local, dask = fastest(local), fastest(dask)
        equal = all(np.array_equal(getattr(local_result, k), getattr(remote, k), equal_nan=True)
                    for k in ("t", "p_W", "q_WB", "v_W", "w_B"))
        print(f"batch of {MC_SAMPLES} x {MC_STEPS} steps: local simulate_batch(threads=2) {local.wall:.3f} s, "
              f"rigiddyn.distributed.simulate_batch (chunk_size None) {dask.wall:.3f} s: dask/local = "
              f"{dask.wall / local.wall:.2f} (target <= 1.3); bitwise equal: {equal}")
        report_ratio("batch_dask", MC_SAMPLES, local.wall, dask.wall, "dask")
        sweep = []
        for size in (500, 2000, 8000, 25000):  # the overhead amortised: time against the chunk size
            clock = Timing()
            rd_distributed.simulate_batch(body, states, DT, MC_STEPS, client=client, chunk_size=size, progress=False,
                                          **batch_kwargs)
            sweep.append(f"{size}: {clock.stop().wall:.3f} s ({-(-MC_SAMPLES // size)} tasks)")
        print(f"  the same with chunk_size = {'; '.join(sweep)}")
        local, dask = [], []
        for _ in range(repeats):
            local_mc, t = monte_carlo_run(threads=2)
            local.append(t)
            remote_mc, t = monte_carlo_run(client=client)
            dask.append(t)
        local, dask = fastest(local), fastest(dask)
        equal = np.array_equal(local_mc.batch.w_B, remote_mc.batch.w_B)
        print(f"rigiddyn.monte_carlo of {MC_SAMPLES} tumbling bodies x {MC_STEPS} steps (the draws made locally, "
              f"{MC_SAMPLES} SeedSequence children, in both): threads=2 {local.wall:.3f} s, client= {dask.wall:.3f} s: "
              f"dask/local = {dask.wall / local.wall:.2f} (target <= 1.3); w_B bitwise equal: {equal}")
        report_ratio("monte_carlo_dask", MC_SAMPLES, local.wall, dask.wall, "dask")
    clock = Timing()
    rd_distributed.simulate_batch(body, states, DT, MC_STEPS, progress=False, **batch_kwargs)
    print(f"end to end with client=None (a LocalCluster of the machine's cores started and closed by the call): "
          f"{clock.stop().wall:.3f} s")


PARTS = ("scaling", "mujoco", "dask")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--small", action="store_true", help="64 samples x 100 steps, no Dask (what ctest runs)")
    parser.add_argument("--part", choices=PARTS, action="append",
                        help="run only this part (repeatable; default: every part)")
    args = parser.parse_args(argv)
    parts = args.part or PARTS
    n, steps = (64, 100) if args.small else (10_000, 1000)
    repeats = 2 if args.small else 5
    print(f"command: {COMMAND}{' --small' if args.small else ''}" + "".join(f" --part {p}" for p in args.part or ()))
    states = tumbling_states(n)
    ok = True
    if "scaling" in parts:
        scaling_part(states, steps, repeats)
    if "mujoco" in parts:
        ok = mujoco_part(states, steps, 2, args.small)  # 2: MuJoCo's full size takes ~45 s a run per core
    if "dask" in parts and args.small:
        print("\nDask: skipped at --small (a LocalCluster takes seconds to start; run the full size)")
    elif "dask" in parts:
        dask_part(repeats)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
