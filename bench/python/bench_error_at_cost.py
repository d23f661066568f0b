"""Error at equal cost for EVERY method of rigiddyn.methods(), against the exact torque-free solution
(rigiddyn.TorqueFreeSolution), on two problems (I = diag(1, 2, 3) kg m^2, 100 s):

  tumbling  w0 = (0.01, 2, 0.01) rad/s  (near the intermediate-axis separatrix: flips)
  fast_spin w0 = (0.1, 0.1, 50) rad/s

For each method and dt: ns per step (C++ loop wall time / steps, from simulate's elapsed_seconds;
for 'exact', ns per closed-form evaluation at the record times), the final attitude error
||log(R_ref^T R)|| [rad], max over the run of |dE|/E and of |d|L||/|L| (records every ~0.1 s).
Then, per problem, each method's smallest final attitude error at a cost (total ns) no larger than
RK4's at dt = 0.01 s (the "equal cost" column).

    python bench/python/bench_error_at_cost.py           # dt sweep 0.1 ... 3e-4 s
    python bench/python/bench_error_at_cost.py --small   # dt 0.01 and 0.001 s (what ctest runs)
"""

import argparse
import math
import warnings

import numpy as np
from scipy.spatial.transform import Rotation

import rigiddyn as rd

INERTIA = np.diag([1.0, 2.0, 3.0])
PROBLEMS = {"tumbling": (0.01, 2.0, 0.01), "fast_spin": (0.1, 0.1, 50.0)}
T_END = 100.0


def run(method, w0, dt):
    steps = int(round(T_END / dt))
    record_every = max(1, int(round(0.1 / dt)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # divergence is reported in the table
        r = rd.simulate(rd.RigidBody(1.0, INERTIA), rd.RigidBodyState(w_B=w0), dt, steps, method=method,
                        record_every=record_every, error=False)
    evaluations = len(r.t) if method == "exact" else steps
    ns = 1e9 * r.elapsed_seconds / evaluations
    body = r.body(0)
    if r.diverged or not np.all(np.isfinite(body.q_WB[-1])):
        return steps, ns, math.inf, math.inf, math.inf
    q_ref, _ = rd.TorqueFreeSolution(INERTIA, [0, 0, 0, 1.0], w0).state_at(r.t[-1])
    attitude = (Rotation.from_quat(q_ref).inv() * Rotation.from_quat(body.q_WB[-1])).magnitude()
    dE = np.abs(r.kinetic_energy / r.kinetic_energy[0] - 1.0).max()
    dL = np.abs(body.angular_momentum_norm / body.angular_momentum_norm[0] - 1.0).max()
    return steps, ns, attitude, dE, dL


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--small", action="store_true", help="two step sizes only (CI)")
    args = parser.parse_args()
    dts = [0.01, 0.001] if args.small else [0.1, 0.03, 0.01, 0.003, 0.001, 3e-4]
    methods = [m["name"] for m in rd.methods()]
    for problem, w0 in PROBLEMS.items():
        print(f"\n== {problem}: I = diag(1, 2, 3) kg m^2, w0 = {w0} rad/s, {T_END:g} s ==")
        print(f"{'method':42s} {'dt [s]':>8s} {'ns/step':>9s} {'attitude err [rad]':>19s} "
              f"{'max|dE|/E':>10s} {'max|dL|/L':>10s}")
        rows = []
        for method in methods:
            for dt in ([0.1] if method == "exact" else dts):
                steps, ns, att, dE, dL = run(method, w0, dt)
                rows.append((method, dt, steps, ns, att, dE, dL))
                print(f"{method:42s} {dt:8.0e} {ns:9.1f} {att:19.3e} {dE:10.2e} {dL:10.2e}")
        budget = next(r[2] * r[3] for r in rows if r[0] == "rk4" and r[1] == 0.01)
        print(f"-- equal cost: best final attitude error at total cost <= RK4's at dt = 0.01 ({budget / 1e6:.2f} ms)")
        for method in methods:
            within = [r for r in rows if r[0] == method and r[2] * r[3] <= budget * 1.05]
            if not within:
                print(f"   {method:42s} (no run within the budget)")
                continue
            best = min(within, key=lambda r: r[4])
            print(f"   {method:42s} error {best[4]:10.3e} rad at dt = {best[1]:.0e} s")


if __name__ == "__main__":
    main()
