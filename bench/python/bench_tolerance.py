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
last problem, whose sweep (1 000 bodies, each candidate against rk4 at 1/16 of its step) takes more than 40 minutes.
"""

import math
import sys
import warnings

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, parse_small

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


def row(problem, tolerance, costs, methods):
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
    print(f"{problem.name:28s} {tolerance:8.0e} {c.method:24s} {c.steps:7d} {c.certified_error:9.2e} {true:9.2e} "
          f"{'yes' if met else 'NO ':4s} {str(best_m):24s} {best_n or 0:7d} {final / best_cost:9.2f} "
          f"{call / best_cost:9.2f}  refinements={c.refinements}")
    return met, final / best_cost, call / best_cost


def main():
    args = parse_small(__doc__, "two problems at one tolerance")
    sys.stdout.reconfigure(line_buffering=True)  # each row as it is measured (the sweeps take minutes)
    free = [FreeBody("free body near separatrix", [1.0, 2.0, 3.0], [0.1, 1.0, 0.1], 20.0),
            FreeBody("free body fast spin", [1.0, 2.0, 3.0], [3.0, 0.5, 1.0], 10.0),
            FreeBody("free body near-symmetric", [2.0, 2.0, 3.0], [0.5, 0.2, 2.0], 30.0)]
    scenes = [Scene("kepler", exact=kepler_exact)] + [
        Scene(n) for n in ("pendulum", "heavy_top", "spring_chain", "box_on_springs", "gravity_gradient",
                           "satellite_boom", "three_body", "foucault", "rocket", "cubesat_detumbling",
                           "cubesat_pointing", "double_pendulum", "j2_orbit", "solar_array", "cluster")]
    problems = free + scenes
    tolerances = {"attitude": (1e-3, 1e-5, 1e-7)}
    if args.small:
        problems, tolerances = [free[0], scenes[0]], {"attitude": (1e-5,)}
    print(f"{'problem':28s} {'tol':>8s} {'method':24s} {'steps':>7s} {'certified':>9s} {'true':>9s} met  "
          f"{'sweep cheapest':24s} {'steps':>7s} {'final/min':>9s} {'call/min':>9s}")
    outcomes = []
    for p in problems:
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
                outcome = row(p, tol, costs, methods)
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

if __name__ == "__main__":
    main()
