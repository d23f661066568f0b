"""Batches of robot-arm rollouts: rigiddyn.simulate_batch against MuJoCo's rollout on the same URDF.

  PYTHONPATH=build/<dir>/python python3 bench/python/bench_tree_rollout.py [--small]

The arm: a chain of 6 revolute joints on a fixed base (axes z, y, x in turn, 0.2 m apart, each link a 1 kg rod of
0.2 m: bench_tree_pinocchio.limb_urdf), swinging under gravity (9.81 m/s²) without joint torques. Sample i starts
from q ~ U(-1, 1) rad and v ~ N(0, 1) rad/s per joint (a fixed SeedSequence, so every run draws the same) and takes
n RK4 steps of dt = 1 ms. Full size N = 10^4 samples, n = 10^3 steps; --small: N = 64, n = 100 (what ctest runs).

- rigiddyn: rd.load_urdf of the URDF in a scene with a UniformGravity element, simulate_batch(method="rk4",
  record_every=n, error=False): the first and the last state recorded.
- MuJoCo (the `peers` extra: pip install mujoco): MjModel.from_xml_string of the same URDF (MuJoCo's URDF importer:
  the base link fused into the world, the same inertias), integrator RK4, the same dt and gravity, every optional
  stage off but gravity (joint limits, contacts, constraints, passive forces, actuation: none acts on this swing),
  through mujoco.rollout (its stepping loop in C; it records every step's state, a few hundred bytes a step next to
  microseconds of stepping), 250 samples a call (_bench_common.mujoco_last_states).

Both integrate the same equations with classic RK4 on (q, v) (hinge joints: q additive): the final states must
agree within 2 (e_rigiddyn + e_mujoco) + 4 n eps, e each engine's global error at dt estimated by step doubling
(Richardson, p = 4), on the first 16 samples. Runs compared are alternated in one process and the fastest of each
kept; each time is printed as wall time and as the process's CPU time (all threads), the cost per core on a shared
machine. Prints, at 1 thread and at every core, ns per sample-step of each and the "ratio ..." line (rigiddyn /
MuJoCo). Without mujoco it prints rigiddyn's times only; without yourdfpy (the `urdf` extra) it stops.
"""

from __future__ import annotations

import importlib.util

import numpy as np

import rigiddyn as rd
from _bench_common import Timing, cores, fastest, mujoco_last_states, parse_small, report_ratio
from bench_tree_pinocchio import limb_urdf

GRAVITY = (0.0, 0.0, -9.81)  # [m/s²] in W
DT = 1e-3  # [s]
SEED = 20261130
JOINTS = 6
CHECKED = 16  # samples of the same-motion check

def draws(n):
    """(q (N, 6) [rad], v (N, 6) [rad/s]) of the N samples."""
    rng = np.random.default_rng(np.random.SeedSequence(SEED))
    return rng.uniform(-1.0, 1.0, (n, JOINTS)), rng.normal(0.0, 1.0, (n, JOINTS))


class RigiddynArm:
    """The arm in a rigiddyn scene; final(q, v, steps, dt, threads) -> ((q, v) at the end, Timing)."""

    def __init__(self, urdf):
        self.tree = rd.load_urdf(urdf)
        self.scene = rd.Scene(elements=[rd.UniformGravity(g_W=GRAVITY)])
        self.scene.add_tree(self.tree, "arm")

    def final(self, q, v, steps, dt, threads):
        initial = [self.tree.joint_states(q_i, v_i) for q_i, v_i in zip(q, v)]  # (not timed)
        clock = Timing()
        batch = rd.simulate_batch(self.scene, initial, dt, steps, method="rk4", record_every=steps, error=False,
                                  threads=threads)
        clock.stop()
        return (np.asarray(batch.joint_q)[:, -1], np.asarray(batch.joint_v)[:, -1]), clock


class MuJoCoArm:
    """The arm in MuJoCo from the same URDF; final(q, v, steps, nthread) -> ((q, v) at the end, Timing)."""

    def __init__(self, mujoco, urdf, dt):
        self.mujoco = mujoco
        self.model = mujoco.MjModel.from_xml_string(urdf)
        assert self.model.nq == self.model.nv == JOINTS, (self.model.nq, self.model.nv)
        self.model.opt.timestep = dt
        self.model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
        self.model.opt.gravity[:] = GRAVITY
        every = (1 << int(mujoco.mjtDisableBit.mjNDISABLE)) - 1
        self.model.opt.disableflags = every & ~int(mujoco.mjtDisableBit.mjDSBL_GRAVITY)
        self.spec = mujoco.mjtState.mjSTATE_FULLPHYSICS  # (time, qpos, qvel, ...)
        self.size = mujoco.mj_stateSize(self.model, self.spec)

    def initial(self, q, v):
        data = self.mujoco.MjData(self.model)
        out = np.empty((len(q), self.size))
        for i, (q_i, v_i) in enumerate(zip(q, v)):
            data.qpos[:], data.qvel[:] = q_i, v_i
            self.mujoco.mj_getState(self.model, data, out[i], self.spec)
        return out

    def final(self, q, v, steps, nthread):
        last, clock = mujoco_last_states(self.model, self.initial(q, v), steps, nthread)  # (the initial not timed)
        return (last[:, 1:1 + JOINTS], last[:, 1 + JOINTS:1 + 2 * JOINTS]), clock  # (time, qpos, qvel, ...)


def same_motion(ours, theirs, arm, mj_half, q, v, steps):
    """True when the final (q, v) of the two engines agree within 2 (e_rigiddyn + e_mujoco) + 4 n eps |x| on the first
    CHECKED samples, e by step doubling (|x(dt) − x(dt/2)| 16/15, RK4's p = 4); prints the figures."""
    q, v = q[:CHECKED], v[:CHECKED]
    halved_ours, _ = arm.final(q, v, 2 * steps, DT / 2, None)
    halved_theirs, _ = mj_half.final(q, v, 2 * steps, 1)
    worst = 0.0
    for name, k in (("q", 0), ("v", 1)):
        x_rd, x_mj = ours[k][:CHECKED], theirs[k][:CHECKED]
        e_rd = np.abs(x_rd - halved_ours[k]) * 16 / 15
        e_mj = np.abs(x_mj - halved_theirs[k]) * 16 / 15
        bound = 2.0 * (e_rd + e_mj) + 4 * steps * np.finfo(float).eps * np.maximum(np.abs(x_rd), 1.0)
        worst = max(worst, float(np.max(np.abs(x_rd - x_mj) / bound)))
        print(f"  {name}: max |rigiddyn - mujoco| = {np.max(np.abs(x_rd - x_mj)):.2e}; errors at dt up to "
              f"{np.max(e_rd):.2e} (rigiddyn), {np.max(e_mj):.2e} (mujoco)")
    print(f"  worst difference / bound = {worst:.2e} -> {'OK' if worst <= 1.0 else 'FAILED'}")
    return worst <= 1.0


def main():
    args = parse_small(__doc__, "N = 64 samples of 100 steps instead of 10^4 of 10^3")
    n, steps, repeats = (64, 100, 2) if args.small else (10_000, 1_000, 3)
    if importlib.util.find_spec("yourdfpy") is None:
        print("yourdfpy is not importable (pip install '.[urdf]'): the arm cannot be read, nothing timed")
        return
    urdf = limb_urdf(1, JOINTS, "arm6")
    arm = RigiddynArm(urdf)
    q, v = draws(n)
    try:
        import mujoco
    except ImportError:
        mujoco = None
        print("mujoco is not importable (pip install '.[peers]'): rigiddyn's times only")
    mj = None if mujoco is None else MuJoCoArm(mujoco, urdf, DT)
    print(f"{n} rollouts of a {JOINTS}-joint arm x {steps} RK4 steps of dt = {DT} s"
          + ("" if mj is None else f", against MuJoCo {mujoco.__version__} rollout"))
    per = n * steps / 1e9  # ns per sample-step
    for threads in sorted({1, cores()}):
        runs = {"rigiddyn": [], "mujoco": []}
        for _ in range(repeats):  # alternated, so that a change of the machine's load hits both
            ours, t = arm.final(q, v, steps, DT, threads)
            runs["rigiddyn"].append(t)
            if mj is not None:
                theirs, t = mj.final(q, v, steps, threads)
                runs["mujoco"].append(t)
        best = {name: fastest(times) for name, times in runs.items() if times}
        line = ", ".join(f"{name} wall {t.wall / per:.1f} ns, CPU {t.cpu / per:.1f} ns" for name, t in best.items())
        print(f"threads = {threads}: per sample-step {line}")
        if mj is not None:
            report_ratio(f"arm6_rollout_threads{threads}", n * steps, best["rigiddyn"].wall, best["mujoco"].wall,
                         "mujoco")
    if mj is not None:
        print(f"same motion (first {CHECKED} samples; bound 2 (e_rigiddyn + e_mujoco) + 4 n eps, e by step doubling):")
        if not same_motion(ours, theirs, arm, MuJoCoArm(mujoco, urdf, DT / 2), q, v, steps):
            raise SystemExit("rigiddyn and MuJoCo disagree beyond their errors: the comparison does not hold")


if __name__ == "__main__":
    main()
