"""Peers side by side: the tumbling T-handle and the fast spinning top in MuJoCo (optional `mujoco`
package) at the same steps as rigiddyn's methods, errors against the exact Euler-Poinsot solution.

  python bench/python/bench_peers.py [--small]

MuJoCo runs a free body (freejoint, diaginertia, no gravity, no contacts) through
mujoco.rollout (the stepping loop in C, so the cost compares C loops); its free-joint angular
velocity is in the body frame, as rigiddyn's w_B. Errors use rigiddyn.tradeoff's definitions:
geodesic attitude angle, |I (w - w_ref)| / G, and max_t |T - T_ref| / T_ref. Without mujoco the
script prints rigiddyn's rows only and says so.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np
import rigiddyn
from rigiddyn.problem import load_problem
from rigiddyn.scene_precision import attitude_angle
from rigiddyn.work_precision import reference_states

MUJOCO_INTEGRATORS = ("Euler", "RK4", "implicit", "implicitfast")


def mujoco_run(mujoco, problem, integrator, dt, steps):
    """(t (n,), q_WB (n, 4) (x, y, z, w), w_B (n, 3), ns per step) of a MuJoCo free body."""
    from mujoco import rollout

    i1, i2, i3 = (float(x) for x in np.diag(problem.inertia_com))
    xml = f"""<mujoco><option timestep="{dt!r}" integrator="{integrator}" gravity="0 0 0"/>
      <worldbody><body><freejoint/><inertial pos="0 0 0" mass="{float(problem.mass)!r}" diaginertia="{i1!r} {i2!r} {i3!r}"/>
      </body></worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    data.qpos[:3] = problem.p_W
    data.qpos[3:7] = np.roll(problem.q_WB, 1)  # MuJoCo quaternions are (w, x, y, z)
    data.qvel[:3] = problem.v_W
    data.qvel[3:6] = problem.w_B
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    state0 = np.empty(mujoco.mj_stateSize(model, spec))
    mujoco.mj_getState(model, data, state0, spec)
    start = time.perf_counter()
    states, _ = rollout.rollout(model, data, state0[None, :], nstep=steps)
    elapsed = time.perf_counter() - start
    states = states[0]
    t = np.concatenate([[0.0], states[:, 0]])
    q = np.vstack([problem.q_WB, np.roll(states[:, 4:8], -1, axis=1)])
    w = np.vstack([problem.w_B, states[:, 11:14]])
    return t, q / np.linalg.norm(q, axis=1)[:, None], w, elapsed / steps * 1e9


def errors(problem, t, q, w):
    ref = reference_states(problem, t)
    inertia = problem.inertia_com
    g = np.linalg.norm(inertia @ problem.w_B)
    energy = 0.5 * np.sum(w * (w @ inertia.T), axis=1)
    e_ref = 0.5 * problem.w_B @ inertia @ problem.w_B
    angle = attitude_angle(ref.q_WB, q)
    return {"final_attitude_error": angle[-1], "max_attitude_error": np.max(angle),
            "final_momentum_error": np.linalg.norm(inertia @ (w[-1] - ref.w_B[-1])) / g,
            "energy_drift": np.max(np.abs(energy - e_ref)) / e_ref}


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--small", action="store_true", help="short horizons")
    args = parser.parse_args(argv)
    try:
        import mujoco
    except ImportError:
        mujoco = None
        print("mujoco is not installed (pip install mujoco): printing rigiddyn's rows only")
    header = f"{'engine':9} {'method':40} {'dt':>9} {'ns/step':>9} {'final att':>10} {'max att':>10} " \
             f"{'final mom':>10} {'energy':>10}"
    for name in ("t_handle", "fast_top"):
        problem = load_problem(name)
        if args.small:
            problem = problem.with_horizon(problem.horizon / 4)
        dts = problem.tradeoff["dts"][:4] if args.small else problem.tradeoff["dts"]
        print(f"\n{problem.name}, horizon {problem.horizon:g} s\n{header}")
        with np.errstate(all="ignore"):
            import warnings

            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                result = rigiddyn.tradeoff(problem, dts=dts, progress=False)
        for dt in sorted({r["dt"] for r in result.rows}, reverse=True):
            for r in (r for r in result.rows if r["dt"] == dt):
                print(f"{'rigiddyn':9} {r['method']:40} {dt:9.3g} {r['time_per_step'] * 1e9:9.0f} "
                      f"{r['final_attitude_error']:10.2e} {r['max_attitude_error']:10.2e} "
                      f"{r['final_momentum_error']:10.2e} {r['energy_drift']:10.2e}")
            if mujoco is None:
                continue
            steps = round(problem.horizon / dt)
            for integrator in MUJOCO_INTEGRATORS:
                t, q, w, ns = mujoco_run(mujoco, problem, integrator, dt, steps)
                if not np.all(np.isfinite(q)) or not np.all(np.isfinite(w)):
                    print(f"{'mujoco':9} {integrator:40} {dt:9.3g} {ns:9.0f} {'non-finite':>10}")
                    continue
                e = errors(problem, t, q, w)
                print(f"{'mujoco':9} {integrator:40} {dt:9.3g} {ns:9.0f} {e['final_attitude_error']:10.2e} "
                      f"{e['max_attitude_error']:10.2e} {e['final_momentum_error']:10.2e} {e['energy_drift']:10.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
