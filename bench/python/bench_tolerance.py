"""simulate(..., tolerance=): is the tolerance met, and at what cost against the cheapest run that meets it.

For each problem and tolerance: the run to the tolerance (its method, steps, certified error), its true error
against a reference (a closed form where rigiddyn has one: TorqueFreeSolution, kepler_propagate; else a run of
rk4 at 1/16 of its step), and an exhaustive sweep of every method the run may use over steps N = 4 round(2^(j/4)):
the cheapest (method, N) whose true error meets the tolerance, its cost N x the seconds per step the method takes
on the problem (best of 3 runs of 4096 steps). Printed per row:
  met       true error <= tolerance
  final/min the wall time of a plain run (error=False, every step recorded) at the final run's (method, steps) /
            that of the sweep's cheapest
  call/min  the wall time of the whole simulate(tolerance=) call (pilots, run, certificate, refinement) / the
            same plain run at the sweep's cheapest (method, steps)
The shipped scenes (python/rigiddyn/scenes/*.toml, read with load_scene) were not used to tune the planner; a scene
with a [controller] runs under it everywhere (the run to the tolerance, the sweep and the references).
`--small` runs two problems at one tolerance (ctest). The full table takes a few minutes up to the `cluster`, the
last problem, whose sweep (1 000 bodies, each candidate against rk4 at 1/16 of its step) takes more than 40 minutes;
`--without-cluster` leaves it out.

`--instructions` adds the stable figure of the same ratio (wall times of calls of a few milliseconds move by up to
1.6x from run to run on a shared machine): callgrind's instruction count of the whole call over that of the plain run
at the sweep's cheapest (method, steps), each the second of two calls in one interpreter under valgrind (the first
compiles and warms), counted between two markers (os.getppid, `--dump-before=getppid`). Printed per row as
`instr call/min`, and their median at the end. Needs valgrind; a row takes tens of seconds under it (the table without
the cluster about 40 minutes on two cores; the cluster's rows, hours).

    python bench/python/bench_tolerance.py --without-cluster --instructions
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
import warnings

import numpy as np

import rigiddyn as rd
from _bench_common import best_time

FREE_METHODS = ("rk4", "rkmk4", "splitting_dlm_yoshida4", "splitting_dlm", "exact_flow_kick",
                "semi_implicit_euler_implicit_gyroscopic")


def attitude_error(q_a, q_b):
    """Largest geodesic angle between two (n, 4) quaternion rows (x, y, z, w) [rad]: 2 atan2(|v|, |w|) of
    q_a^-1 q_b, accurate near 0 (an arccos of the dot product would floor at ~3e-8 rad)."""
    q_a = q_a / np.linalg.norm(q_a, axis=1, keepdims=True)
    q_b = q_b / np.linalg.norm(q_b, axis=1, keepdims=True)
    w = np.sum(q_a * q_b, axis=1)
    v = q_a[:, 3:4] * q_b[:, :3] - q_b[:, 3:4] * q_a[:, :3] - np.cross(q_a[:, :3], q_b[:, :3])
    return float(np.max(2.0 * np.arctan2(np.linalg.norm(v, axis=1), np.abs(w))))


def measure_error(result, reference, measure):
    """Largest error of `measure` over the records (and bodies) of result against reference (same records; inf
    when the reference run diverged and has fewer)."""
    if len(np.asarray(reference.get("q_WB", reference.get("p_W")))) != len(result.t):
        return math.inf
    if measure == "attitude":
        q, qr = np.asarray(result.q_WB).reshape(-1, 4), np.asarray(reference["q_WB"]).reshape(-1, 4)
        return attitude_error(q, qr)
    field = {"position": "p_W", "velocity": "v_W", "angular_velocity": "w_B"}[measure]
    diff = np.asarray(getattr(result, field)) - np.asarray(reference[field])
    return float(np.max(np.linalg.norm(diff, axis=-1)))


class FreeBody:
    """A torque-free body against its closed form (TorqueFreeSolution)."""

    def __init__(self, name, inertia, w_B, duration):
        self.name, self.duration, self.measure, self.controller = name, duration, "attitude", None
        self.model = rd.RigidBody(1.0, inertia)
        self.initial = rd.RigidBodyState(w_B=w_B)
        self.solution = rd.TorqueFreeSolution(np.diag(inertia), [0, 0, 0, 1], w_B)

    def reference(self, result):
        q, _ = self.solution.state_at(np.asarray(result.t))
        return {"q_WB": q}


class Scene:
    """A shipped scene against rk4 at 1/16 of the run's step (or a closed form via `exact`)."""

    def __init__(self, name, exact=None, measure=None, duration=None):
        self.scene, self.initial, run = rd.load_scene(name)
        self.name, self.model, self.exact, self.controller = name, self.scene, exact, run.controller
        self.duration = duration or run.duration
        bodies_turn = any(not isinstance(s, rd.ParticleState) for s in self.initial)
        self.measure = measure or ("attitude" if bodies_turn else "position")

    def reference(self, result):
        if self.exact is not None:
            return self.exact(self, result)
        steps = len(result.t) - 1
        dt = (result.t[-1] - result.t[0]) / steps
        with warnings.catch_warnings():  # a reference of a sweep's step beyond the stability limit diverges
            warnings.simplefilter("ignore")
            fine = rd.simulate(self.model, self.initial, dt / 16, steps=16 * steps, record_every=16, method="rk4",
                               error=False, accuracy_level=None, controller=self.controller)
        return {"q_WB": fine.q_WB, "p_W": fine.p_W, "v_W": fine.v_W, "w_B": fine.w_B}


def kepler_exact(problem, result):
    gm = 398600.4418e9  # the scene's GM [m^3/s^2]
    r, v = rd.kepler_propagate(problem.initial[0].p_W, problem.initial[0].v_W, gm, np.asarray(result.t))
    return {"p_W": np.asarray(r)[:, None, :], "v_W": np.asarray(v)[:, None, :]}


def methods_of(problem):
    """The methods the planner may use on the problem (those that run on it)."""
    out = []
    for m in FREE_METHODS + ("exact",):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                rd.simulate(problem.model, problem.initial, problem.duration / 4, steps=1, method=m, error=False,
                            controller=problem.controller)
        except ValueError:
            continue
        out.append(m)
    return out


def seconds_per_step(problem, method):
    """Seconds per step of `method` on the problem: best of 3 runs of 4096 steps (records every 16)."""
    dt = problem.duration / 4096
    best = math.inf
    for _ in range(3):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            r = rd.simulate(problem.model, problem.initial, dt, steps=4096, method=method, record_every=16, error=False,
                            controller=problem.controller)
        best = min(best, r.elapsed_seconds / 4096)
    return best


def sweep(problem, tolerance, methods, costs):
    """The cheapest (method, steps, cost [s]) whose true error meets the tolerance, over N = 4 round(2^(j/4))."""
    best = (None, None, math.inf)
    for m in methods:
        if m == "exact":
            continue
        for j in range(8, 4 * 18):
            n = 4 * round(2 ** (j / 4))
            if n * costs[m] >= best[2]:
                break
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                r = rd.simulate(problem.model, problem.initial, problem.duration / n, steps=n, method=m, error=False,
                                controller=problem.controller)
            if r.diverged:
                continue
            if measure_error(r, problem.reference(r), problem.measure) <= tolerance:
                best = (m, n, n * costs[m])
                break
    return best


def plain_run_seconds(problem, method, steps):
    """Wall time of simulate(..., error=False) at `steps` steps of `method`, recording every step as the run to a
    tolerance does: best of 3."""
    def run():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            rd.simulate(problem.model, problem.initial, problem.duration / steps, steps=steps, method=method,
                        error=False, controller=problem.controller)
    return best_time(run)


# A fresh interpreter that makes the problem named `name` (`p`) and runs each of `statements` twice, the second time
# between two os.getppid() markers (callgrind dumps its counts before each: dump 2k + 2 holds statement k's second run)
COUNTED_SCRIPT = """import os, sys, warnings
sys.path.insert(0, {folder!r})
import bench_tolerance as bt
import rigiddyn as rd
p = bt.problems(only={name!r})[0]
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
{runs}
"""


def dumped_instructions(path):
    """The instruction total of one callgrind dump file."""
    with open(path) as f:
        for line in f:
            if line.startswith(("summary:", "totals:")):
                return int(line.split()[1])
    raise RuntimeError(f"no total in {path}")


def counted_instructions(problem, statements):
    """Callgrind's instructions of each of `statements` (Python source reading the problem as `p`, and `rd`), each the
    second of two runs in one fresh interpreter (the first compiles the scene), as a list."""
    runs = "".join(f"    {s}; os.getppid(); {s}; os.getppid()\n" for s in statements)
    with tempfile.TemporaryDirectory() as folder:
        script = os.path.join(folder, "counted.py")
        with open(script, "w") as f:
            f.write(COUNTED_SCRIPT.format(folder=os.path.dirname(os.path.abspath(__file__)), name=problem.name,
                                          runs=runs))
        out = os.path.join(folder, "callgrind.out")
        env = dict(os.environ, PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
        run = subprocess.run(["valgrind", "--tool=callgrind", "--dump-before=getppid", f"--callgrind-out-file={out}",
                              sys.executable, script], env=env, capture_output=True, text=True)
        if run.returncode != 0:
            raise RuntimeError(f"valgrind on {problem.name} ended with {run.returncode}:\n{run.stderr[-2000:]}")
        return [dumped_instructions(f"{out}.{2 * k + 2}") for k in range(len(statements))]


def call_statement(tolerance):
    """The run to `tolerance` of problem `p`, as counted_instructions reads it."""
    return (f"rd.simulate(p.model, p.initial, duration=p.duration, tolerance={tolerance!r}, measure=p.measure, "
            f"controller=p.controller)")


def plain_statement(method, steps, error=False):
    """The plain run of problem `p` at (method, steps) recording every step (`error`: with its estimate, read)."""
    run = (f"rd.simulate(p.model, p.initial, p.duration / {steps!r}, steps={steps!r}, method={method!r}, "
           f"error={error!r}, controller=p.controller)")
    return run + (".error" if error else "")


def row(problem, tolerance, costs, methods, instructions=False):
    try:
        r = rd.simulate(problem.model, problem.initial, duration=problem.duration, tolerance=tolerance,
                        measure=problem.measure, controller=problem.controller)
    except rd.ToleranceError as e:
        print(f"{problem.name:28s} {tolerance:8.0e} raised: {e}")
        return None
    call = best_time(lambda: rd.simulate(problem.model, problem.initial, duration=problem.duration,
                                         tolerance=tolerance, measure=problem.measure,
                                         controller=problem.controller), repeats=2)
    c = r.choice
    true = measure_error(r, problem.reference(r), problem.measure)
    best_m, best_n, _ = sweep(problem, tolerance, methods, costs)
    final = plain_run_seconds(problem, c.method, c.steps)
    best_cost = plain_run_seconds(problem, best_m, best_n) if best_m is not None else math.nan
    met = true <= tolerance
    counted = math.nan
    if instructions and best_m is not None:
        call_instructions, plain_instructions = counted_instructions(
            problem, [call_statement(tolerance), plain_statement(best_m, best_n)])
        counted = call_instructions / plain_instructions
    print(f"{problem.name:28s} {tolerance:8.0e} {c.method:24s} {c.steps:7d} {c.certified_error:9.2e} {true:9.2e} "
          f"{'yes' if met else 'NO ':4s} {str(best_m):24s} {best_n or 0:7d} {final / best_cost:9.2f} "
          f"{call / best_cost:9.2f}  refinements={c.refinements}"
          + (f"  instr call/min {counted:.2f}" if instructions else ""))
    return met, final / best_cost, call / best_cost, counted


def problems(cluster=True, only=None):
    """The table's problems, in its order (the shipped `cluster` last, unless `cluster` is False); `only`: the one of
    that name alone (a scene is read only where it is asked for)."""
    free = [FreeBody("free body near separatrix", [1.0, 2.0, 3.0], [0.1, 1.0, 0.1], 20.0),
            FreeBody("free body fast spin", [1.0, 2.0, 3.0], [3.0, 0.5, 1.0], 10.0),
            FreeBody("free body near-symmetric", [2.0, 2.0, 3.0], [0.5, 0.2, 2.0], 30.0)]
    scenes = ("kepler", "pendulum", "heavy_top", "spring_chain", "box_on_springs", "gravity_gradient", "satellite_boom",
              "three_body", "foucault", "rocket", "cubesat_detumbling", "cubesat_pointing", "double_pendulum",
              "j2_orbit", "solar_array") + (("cluster",) if cluster or only == "cluster" else ())
    return [p for p in free if only in (None, p.name)] + [
        Scene(n, exact=kepler_exact if n == "kepler" else None) for n in scenes if only in (None, n)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--small", action="store_true", help="two problems at one tolerance")
    parser.add_argument("--without-cluster", action="store_true", help="leave the cluster out")
    parser.add_argument("--instructions", action="store_true",
                        help="also the call over the cheapest plain run in callgrind's instructions (needs valgrind)")
    args = parser.parse_args()
    sys.stdout.reconfigure(line_buffering=True)  # each row as it is measured (the sweeps take minutes)
    if args.small:
        table = problems(only="free body near separatrix") + problems(only="kepler")
        tolerances = {"attitude": (1e-5,)}
    else:
        table, tolerances = problems(cluster=not args.without_cluster), {"attitude": (1e-3, 1e-5, 1e-7)}
    print(f"{'problem':28s} {'tol':>8s} {'method':24s} {'steps':>7s} {'certified':>9s} {'true':>9s} met  "
          f"{'sweep cheapest':24s} {'steps':>7s} {'final/min':>9s} {'call/min':>9s}")
    outcomes = []
    for p in table:
        methods = methods_of(p)
        costs = {m: seconds_per_step(p, m) for m in methods}
        if p.measure == "attitude":
            tols = tolerances["attitude"]
        else:  # positions: relative to the largest distance the run covers
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                r = rd.simulate(p.model, p.initial, p.duration / 1024, steps=1024, error=False,
                                controller=p.controller)
            scale = float(np.max(np.linalg.norm(np.asarray(r.p_W), axis=-1)))
            tols = tuple(scale * t for t in (1e-3, 1e-5, 1e-7)[:len(tolerances["attitude"])])
        for tol in tols:
            try:
                outcome = row(p, tol, costs, methods, instructions=args.instructions)
            except rd.ToleranceError as e:
                print(f"{p.name:28s} refused: {e}")
                outcome = None
            outcomes.append(outcome)
    returned = [o for o in outcomes if o is not None]
    met = [o for o in returned if o[0]]
    finals, calls = [o[1] for o in met], [o[2] for o in met]
    print(f"{len(outcomes)} cases: {len(met)} met the tolerance, {len(returned) - len(met)} returned above it, "
          f"{len(outcomes) - len(returned)} raised ToleranceError")
    if met:
        print(f"final/min median {np.median(finals):.2f} max {max(finals):.2f}; "
              f"call/min median {np.median(calls):.2f} max {max(calls):.2f}")
    counted = [o[3] for o in met if not math.isnan(o[3])]
    if counted:
        print(f"call/min in instructions: median {np.median(counted):.2f} max {max(counted):.2f} ({len(counted)} rows)")

if __name__ == "__main__":
    main()
