"""Stability at the extremes: every method of rigiddyn.methods() on a documented matrix of hard
cases, measured with rigiddyn.tradeoff against the exact torque-free solution.

  python bench/python/bench_extremes.py            # full matrix (horizons up to 1e7 steps),
                                                   # writes docs/extremes.md
  python bench/python/bench_extremes.py --small    # the same cases at 1e3-step horizons, printed only
  python bench/python/bench_extremes.py --out FILE # write the markdown table to FILE

Cases: spin rates up to 1e4 rad/s; principal-moment ratios up to 1e6 and the thin rod (one moment
0: refused); nearly spherical bodies (moments equal within 1e-12); the flat plate I3 = I1 + I2;
masses 1e-9..1e9 kg; dt |w| from 1e-4 to 10; initial conditions on and near the separatrix; a long
run for secular drift. The pytest subset is tests/python/test_extremes.py.

Scene cases (a second table, against a Richardson-checked reference, rigiddyn.scene_precision): a stiff
spring (omega = 1e3 rad/s) at dt omega from 0.1 to 10; a close two-body encounter (pericentre 1e-3 of
the initial separation) with and without softening; a spring chain with masses 1e-6, 1 and 1e6 kg, of
particles and of rigid cubes joined at their faces (the springs turn them). The pytest subset is
tests/python/test_extremes_scene.py.

The models of bodies about a fixed point, moving frames and variable mass (in the scene table, against their
exact reference where the scene is one's case, rigiddyn.scene_precision.exact_reference; the reference column
says which): the shipped `pendulum`, `heavy_top`, `foucault` and `rocket`, and their extremes: the pendulum next
to the separatrix (theta0 = pi - 1e-6) and spun over the top, the heavy top at dt |w| from 0.02 to 2 and pinned
1e4 radii of gyration from its centre of mass (digits of I_C lost), the rocket burning to 1 % of its mass, free
particles seen from a frame turning at dt Omega = 0.5.

The document records how it was made (command, date, machine, rigiddyn revision) and a digest of its
INPUTS; tests/python/test_generated_docs.py fails once any input differs from what the document was
made from, and names the command that regenerates it (REGENERATE).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import rigiddyn
from provenance import SIMULATION_INPUTS, markdown_comment, measured_sentence, stamp
from rigiddyn.problem import Problem
from rigiddyn.stability import StabilityWarning

ROOT = Path(__file__).resolve().parents[2]
# what the figures depend on: this script, and the Python and C++ the runs execute (the scene cases: also
# the scene sweep, the scene layer and its bindings)
INPUTS = ["bench/python/bench_extremes.py", *SIMULATION_INPUTS, "python/rigiddyn/scene_precision.py",
          "cpp/include/rigiddyn/scene/*", "cpp/include/rigiddyn/scene/elements/*", "cpp/include/rigiddyn/scene/kinds/*",
          "cpp/src/scene/*",
          "cpp/bindings/bind_scene*.cpp", "cpp/bindings/scene_run.hpp",
          # bodies about a fixed point, moving frames, variable mass: the fast one-body models, the bindings of
          # the new bodies and references, the shipped scenes
          "cpp/include/rigiddyn/scene/fast/*", "cpp/bindings/bind_pivoted.cpp", "cpp/bindings/pivoted.hpp",
          "cpp/bindings/bind_exact_dynamics.cpp", "python/rigiddyn/scene_file.py",
          "python/rigiddyn/units.py",  # the scene file's number form and units
          "python/rigiddyn/scenes/*.toml"]
REGENERATE = ("cmake --build build/<dir> --target _core && "
              "PYTHONPATH=build/<dir>/python python3 bench/python/bench_extremes.py  (a few minutes)")


def body(moments, w_B, mass=1.0, gravity=(0.0, 0.0, 0.0), v_W=(0.0, 0.0, 0.0)):
    return Problem(name="", mass=mass, inertia_com=np.diag(np.asarray(moments, float)), horizon=1.0,
                   w_B=np.asarray(w_B, float), gravity=np.asarray(gravity, float), v_W=np.asarray(v_W, float))


def separatrix_w(closeness):
    """w_B of I = (1, 2, 3) with Delta2 = -m1^2 + m3^2/3 ~ 2 closeness (0: on the separatrix)."""
    m = np.array([1.0, 0.5, math.sqrt(3.0) * (1.0 + closeness)])
    return m / np.array([1.0, 2.0, 3.0])


def stiff_spring(omega=1e3):
    """A 1 kg particle on a spring to a world anchor, k = omega^2 [N/m], released 1 mm from it."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0), name="mass")
    scene.add(rigiddyn.SpringDamper(body_a=0, stiffness=omega**2))
    return scene, [rigiddyn.ParticleState(p_W=(1e-3, 0.0, 0.0))]


def encounter(softening):
    """Two 1 kg particles (G = 1) 2 m apart, each at 0.5 m/s, aimed to pass at 1e-3 m (a near-parabolic
    close encounter: about 63 m/s at the pericentre, unsoftened)."""
    scene = rigiddyn.Scene()
    for name in ("a", "b"):
        scene.add_body(rigiddyn.Particle(1.0), name=name)
    scene.add(rigiddyn.MutualGravity(G=1.0, softening=softening))
    return scene, [rigiddyn.ParticleState(p_W=(-1.0, -5e-4, 0.0), v_W=(0.5, 0.0, 0.0)),
                   rigiddyn.ParticleState(p_W=(1.0, 5e-4, 0.0), v_W=(-0.5, 0.0, 0.0))]


def mass_chain(masses=(1e-6, 1.0, 1e6), stiffness=1.0):
    """Particles of these masses [kg] in a line 1 m apart, neighbours joined by springs of rest length
    1 m; the first is pulled 1 mm out: its mode, omega = sqrt(k (1/m0 + 1/m1)), is the fastest."""
    scene = rigiddyn.Scene()
    for i, m in enumerate(masses):
        scene.add_body(rigiddyn.Particle(m), name=f"m{i}")
    for i in range(len(masses) - 1):
        scene.add(rigiddyn.SpringDamper(body_a=i, body_b=i + 1, stiffness=stiffness, rest_length=1.0))
    states = [rigiddyn.ParticleState(p_W=(float(i), 0.0, 0.0)) for i in range(len(masses))]
    states[0] = rigiddyn.ParticleState(p_W=(-1e-3, 0.0, 0.0))
    return scene, states


def rigid_chain(masses=(1e-6, 1.0, 1e6), side=0.1, stiffness=1.0):
    """Solid cubes of these masses [kg] and side [m] with centres 1 m apart in a line, neighbours joined
    face to face (+x face to -x face) by springs of rest length 1 - side; the first is moved 1 mm in -x
    and +y, so the springs also turn it: its fastest mode is the rotation, k (side/2)^2 / (m0 side^2 / 6)."""
    scene = rigiddyn.Scene()
    for i, m in enumerate(masses):
        scene.add_body(rigiddyn.RigidBody(m, np.eye(3) * m * side**2 / 6.0), name=f"cube{i}")
    for i in range(len(masses) - 1):
        scene.add(rigiddyn.SpringDamper(body_a=i, point_a_B=(side / 2, 0.0, 0.0), body_b=i + 1,
                                        point_b=(-side / 2, 0.0, 0.0), stiffness=stiffness, rest_length=1.0 - side))
    states = [rigiddyn.RigidBodyState(p_W=(float(i), 0.0, 0.0)) for i in range(len(masses))]
    states[0] = rigiddyn.RigidBodyState(p_W=(-1e-3, 1e-3, 0.0))
    return scene, states


def shipped(name):
    """(scene, initial states), dt [s] and steps of a shipped scene's [run]."""
    scene, initial, run = rigiddyn.load_scene(name)
    return (scene, initial), run.dt, run.steps


def pendulum(theta, omega=0.0):
    """The shipped pendulum's rod (1 m, 1 kg, pinned at one end, gravity along -y) from theta [rad], omega [rad/s]."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedPlanarBody(1.0, 1.0 / 12.0, (0.0, -0.5)), name="rod")
    scene.add(rigiddyn.UniformGravity(g_W=(0.0, -9.81, 0.0)))
    return scene, [rigiddyn.PivotedPlanarBodyState(theta=theta, omega=omega)]


def far_pivot(distance):
    """A symmetric top (1 kg, I_C = diag(0.004, 0.004, 0.006)) pinned `distance` [m] from its centre of
    mass on its axis, spinning at 100 rad/s, tilted 30 degrees, under gravity."""
    scene = rigiddyn.Scene()
    body = rigiddyn.RigidBody(1.0, np.diag([0.004, 0.004, 0.006]))
    scene.add_body(rigiddyn.PivotedBody(body, (0.0, 0.0, distance)), name="top")
    scene.add(rigiddyn.UniformGravity())
    half = math.radians(15.0)
    return scene, [rigiddyn.PivotedBodyState(q_WB=(math.sin(half), 0.0, 0.0, math.cos(half)), w_B=(0.0, 0.0, 100.0))]


def carousel(rate=1.0):
    """Two free particles seen from a frame turning at `rate` [rad/s] about (0.3, 0.4, 1)."""
    scene = rigiddyn.Scene()
    for i in range(2):
        scene.add_body(rigiddyn.Particle(1.0 + i), name=f"p{i}")
    scene.frame = rigiddyn.SceneFrame.rotating((0.3, 0.4, 1.0), rate)
    return scene, [rigiddyn.ParticleState(p_W=(1.0, 0.5, 0.0), v_W=(0.1, 0.0, 0.2)),
                   rigiddyn.ParticleState(p_W=(2.0, 0.5, -0.2), v_W=(0.1, -0.3, 0.2))]


def rocket(burnt):
    """The shipped rocket (200 kg, -2 kg/s, 2500 m/s, gravity) burning the fraction `burnt` of its mass."""
    (scene, initial), _, _ = shipped("rocket")
    return (scene, initial), burnt * 200.0 / 2.0


def fixed_point_frames_mass_cases(small):
    """Bodies about a fixed point, moving frames, variable mass: the shipped scenes and their extremes,
    (group, case, (scene, initial), dt, steps)."""
    n = 1000 if small else 20_000
    out = []
    for name in ("pendulum", "heavy_top", "foucault"):
        scene, dt, steps = shipped(name)
        out.append(("shipped", f"{name} (its [run] step)", scene, dt, min(n, steps)))
    rocket_scene, burn = rocket(0.99)
    out.append(("shipped", "rocket burning to 1 % of its mass", rocket_scene, burn / min(n, 6000), min(n, 6000)))
    omega0 = math.sqrt(9.81 * 0.5 / (1.0 / 3.0))
    out.append(("pendulum", "theta0 = pi - 1e-6 (next to the separatrix)", pendulum(math.pi - 1e-6), 1e-3, n))
    out.append(("pendulum", "spun over the top (omega0 = 3 x the separatrix's)", pendulum(0.0, 6.0 * omega0), 1e-3, n))
    for dtw in (0.02, 0.5, 2.0):
        out.append(("heavy top", f"dt |w| = {dtw:g}", far_pivot(0.1), dtw / 100.0, n))
    radius = math.sqrt(0.004)  # radius of gyration about a transverse axis [m]
    out.append(("heavy top", "pinned 1e4 radii of gyration from C (~8 digits of I_C lost)", far_pivot(1e4 * radius),
                2e-3, n))
    out.append(("rotating frame", "free particles, dt Omega = 0.5", carousel(), 0.5, n))
    return out


def scene_cases(small):
    """(group, case, (scene, initial states), dt [s], steps)."""
    n = 1000 if small else 20_000
    out = []
    for dtw in (0.1, 1.9, 3.0, 10.0):
        out.append(("stiff spring", f"omega = 1e3 rad/s, dt omega = {dtw:g}", stiff_spring(), dtw / 1e3, n))
    for softening in (0.0, 0.05):
        out.append(("close encounter", f"two bodies, pericentre 1e-3 m, softening {softening:g} m", encounter(softening),
                    1e-3, 4000))
    chain_rate = math.sqrt(1.0 / 1e-6 + 1.0)
    for dt in (1e-4, 1e-2):
        out.append(("mass ratio", f"chain of 1e-6, 1, 1e6 kg, dt omega = {dt * chain_rate:.2g}", mass_chain(), dt, n))
    cube_rate = math.sqrt(1.0 * 0.05**2 / (1e-6 * 0.1**2 / 6.0))
    for dt in (1e-4, 1e-2):
        out.append(("mass ratio", f"rigid cubes of 1e-6, 1, 1e6 kg joined at their faces, dt omega = {dt * cube_rate:.2g}",
                    rigid_chain(), dt, n))
    return out + fixed_point_frames_mass_cases(small)


def cases(small):
    """(group, case, problem, dt [s], steps)."""
    n = 1000 if small else 100_000
    long_n = 10_000 if small else 10_000_000
    out = []
    for spin in (1.0, 1e2, 1e4):
        out.append(("spin rate", f"|w| = {spin:g} rad/s, dt|w| = 1e-2", body([1.0, 2.0, 2.5], [0.01 * spin, 0.005 * spin, spin]),
                    1e-2 / spin, n))
    for ratio in (1e2, 1e4, 1e6):
        out.append(("moment ratio", f"I = (1/{ratio:g}, 1, 1), dt|w| = 1e-2", body([1.0 / ratio, 1.0, 1.0], [10.0, 1.0, 0.5]),
                    1e-3, n))
    out.append(("moment ratio", "thin rod (I = (0, 1, 1))", None, 1e-3, n))
    for eps in (1e-8, 1e-12):
        out.append(("near sphere", f"I = (1, 1+{eps:g}, 1+2*{eps:g})", body([1.0, 1.0 + eps, 1.0 + 2 * eps], [1.0, 2.0, 3.0]),
                    1e-2, n))
    plate = rigiddyn.thin_plate(1.0, 2.0, mass=1.0).principal_axes().moments
    out.append(("flat plate", "I3 = I1 + I2 (thin plate 1 x 2 m)", body(plate, [0.5, 1.0, 2.0]), 1e-2, n))
    for mass in (1e-9, 1.0, 1e9):
        radius = 0.1 * mass ** (1 / 3)  # constant density [m]
        out.append(("mass", f"m = {mass:g} kg T-handle, gravity",
                    body(np.array([2.0, 6.5, 8.0]) * 0.1 * mass * radius**2, [0.1, 10.0, 0.0], mass=mass,
                         gravity=(0, 0, -9.81), v_W=(1.0, 0.0, 2.0)), 1e-3, n))
    for dtw in (1e-4, 1e-2, 1e-1, 1.0, 3.0, 10.0):
        out.append(("dt |w|", f"T-handle, dt|w| = {dtw:g}", body([2.0, 6.5, 8.0], [0.1, 10.0, 0.0]), dtw / 10.0,
                    min(n, int(100 / (dtw / 10.0)) + 1)))
    for closeness in (1e-3, 1e-9, 0.0):
        mc = rigiddyn.TorqueFreeSolution(np.diag([1.0, 2.0, 3.0]), [0, 0, 0, 1], separatrix_w(closeness)).parameter_mc
        label = "on the separatrix" if closeness == 0.0 else f"near the separatrix (1 - m = {mc:.1e})"
        out.append(("separatrix", label, body([1.0, 2.0, 3.0], separatrix_w(closeness)), 1e-2, n))
    out.append(("long run", f"I = (1, 2, 3), dt|w| = 0.1, {long_n:.0e} steps", body([1.0, 2.0, 3.0], [0.3, 0.2, 1.0]),
                0.1 / 1.06, long_n))
    return out


def measure(problem, dt, steps, methods):
    """One rigiddyn.tradeoff sweep at a single dt; rows keyed by method name, plus warnings."""
    problem = Problem(**{**problem.__dict__, "horizon": dt * steps})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = rigiddyn.tradeoff(problem, methods=methods, dts=[dt], progress=False)
    warned = any(issubclass(w.category, StabilityWarning) for w in caught)
    return {r["method"]: r for r in result.rows}, warned


def cpu_ns_per_step(problem, method, dt, steps):
    """CPU time of the simulate loop per step [ns], the fastest of 3 runs (1 above 1e5 steps). The loop
    runs single-threaded on the calling thread (GIL released), so the thread's CPU time is its cost,
    without the time the scheduler gives to other jobs on a shared machine (wall time counts that)."""
    body, initial, loads = problem.body(), problem.initial_state(), list(problem.loads)
    best = math.inf
    for _ in range(3 if steps <= 100_000 else 1):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # divergence is reported by the tradeoff row
            start = time.thread_time()
            rigiddyn.simulate(body, initial, dt, steps, method, record_every=steps, loads=loads, gravity=problem.gravity,
                             error=False)
            best = min(best, time.thread_time() - start)
    return best / steps * 1e9


def measure_scene(scene_and_initial, dt, steps, methods):
    """One rigiddyn.tradeoff sweep of a scene at a single dt; rows keyed by method name."""
    scene, initial = scene_and_initial
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StabilityWarning)  # each row's `stability` says it
        result = rigiddyn.tradeoff(scene, initial=initial, horizon=dt * steps, methods=methods, dts=[dt],
                                   progress=False)
    return {r["method"]: r for r in result.rows}


def scene_cpu_ns_per_step(scene_and_initial, method, dt, steps):
    """CPU time of the simulate loop per step [ns] of the scene compiled for `method`, as cpu_ns_per_step."""
    scene, initial = scene_and_initial
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # compatibility and divergence: reported by the tradeoff row
        model = scene.compile(method=method)
        best = math.inf
        for _ in range(3 if steps <= 100_000 else 1):
            start = time.thread_time()
            rigiddyn.simulate(model, initial, dt, steps, method, record_every=steps, error=False)
            best = min(best, time.thread_time() - start)
    return best / steps * 1e9


def scene_lines(small, methods, failures):
    """The scene table's lines; diverged runs without a StabilityWarning appended to failures."""
    lines = ["| case | reference | method | outcome | max position error [m] | max attitude error [rad] "
             "| energy error | momentum error | CPU ns/step |", "|---|---|---|---|---|---|---|---|---|"]
    for group, case, scene, dt, steps in scene_cases(small):
        rows = measure_scene(scene, dt, steps, methods)
        for method in methods:
            r = rows[method]
            reference = r["reference"].replace("richardson", "Richardson")
            if r["order_note"].startswith("not applicable"):
                lines.append(f"| {group}: {case} ({steps} steps) | {reference} | {method} | {r['order_note'][:90]} "
                             "| | | | | |")
                continue
            cost = "-" if r["diverged"] else f"{scene_cpu_ns_per_step(scene, method, dt, steps):.0f}"
            if r["diverged"] and not r["stability"]:
                failures.append(f"{case} / {method}: diverged without a StabilityWarning")
            lines.append(f"| {group}: {case} ({steps} steps) | {reference} | {method} | {outcome(r)} "
                         f"| {fmt(r['max_position_error'])} | {fmt(r['max_attitude_error'])} | {fmt(r['energy_drift'])} "
                         f"| {fmt(r['momentum_drift'])} | {cost} |")
    return lines


def outcome(row):
    if row["diverged"]:
        return "diverged (warned)"
    return "warned" if row["stability"] else "ok"


def fmt(x):
    return f"{x:.1e}" if math.isfinite(x) else str(x)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--small", action="store_true", help="short horizons; print only")
    parser.add_argument("--out", help="markdown file (default: docs/extremes.md unless --small)")
    args = parser.parse_args(argv)
    out = Path(args.out) if args.out else (None if args.small else ROOT / "docs" / "extremes.md")
    methods = [m["name"] for m in rigiddyn.methods()]
    lines = [
        ("| case | method | outcome | max attitude error [rad] | max momentum error | energy drift | |L| drift "
        "| max ||q| - 1| | CPU ns/step |"),
        "|---|---|---|---|---|---|---|---|---|",
    ]
    failures = []
    made = stamp(INPUTS)  # the inputs as the measurement starts, and the machine's load then
    start = time.perf_counter()
    for group, case, problem, dt, steps in cases(args.small):
        if problem is None:
            try:
                rigiddyn.RigidBody(1.0, np.diag([0.0, 1.0, 1.0]))
                failures.append(f"{case}: accepted")
                lines.append(f"| {group}: {case} | all | ACCEPTED (should be refused) | | | | | | |")
            except ValueError as e:
                lines.append(f"| {group}: {case} | all | refused: ValueError \"{str(e)[:70]}...\" | | | | | | |")
            continue
        rows, _ = measure(problem, dt, steps, methods)
        for method in methods:
            r = rows[method]
            cost = "-" if r["diverged"] else f"{cpu_ns_per_step(problem, method, dt, steps):.0f}"
            if r["diverged"] and not r["stability"]:
                failures.append(f"{case} / {method}: diverged without a StabilityWarning")
            lines.append(f"| {group}: {case} ({steps} steps) | {method} | {outcome(r)} | {fmt(r['max_attitude_error'])} "
                         f"| {fmt(r['max_momentum_error'])} | {fmt(r['energy_drift'])} | {fmt(r['momentum_drift'])} "
                         f"| {fmt(r['quaternion_norm_error'])} | {cost} |")
    lines += ["", SCENES_HEADER] + scene_lines(args.small, methods, failures)
    elapsed = time.perf_counter() - start
    table = "\n".join(lines)
    print(table)
    rows = sum(1 for line in lines if line.startswith("| ") and not line.startswith("| case "))
    print(f"\n{rows} rows in {elapsed:.1f} s; {len(failures)} unexpected behaviours")
    for f in failures:
        print("UNEXPECTED:", f)
    if out is not None:
        out.write_text(HEADER.format(measured=measured_sentence(made)) + table + "\n\n"
                       + FOOTER.format(elapsed=elapsed) + "\n" + markdown_comment(made))
        print(f"wrote {out}")
    return 1 if failures else 0


HEADER = """# Stability at the extremes

Generated by `python bench/python/bench_extremes.py` (do not edit by hand; regenerate it when
`tests/python/test_generated_docs.py` says its inputs changed). {measured}
The errors are deterministic. The CPU ns/step column is the CPU time of the simulate loop per step
(single-threaded, the fastest of 3 runs, 1 above 1e5 steps; "-" for a diverged run): unlike wall
time it leaves out the time the scheduler gives to other jobs on this shared machine, but their cache
and frequency effects remain, so it is noisy: compare methods within this table, not with figures
from another run; the C++ benchmarks (`bench/`, each method next to a hand-written loop) measure speed.

Every method of `rigiddyn.methods()` on each case, against the exact torque-free solution (and the
exact ballistic centre of mass where there is gravity), measured with `rigiddyn.tradeoff` (error definitions in
`rigiddyn.work_precision`). Outcomes: **ok**; **warned**: dt is beyond the method's linear
stability limit for the spin at hand (`rigiddyn.StabilityWarning`, see
`python/rigiddyn/stability.py`) but the run stayed finite; **diverged (warned)**: the state became
non-finite, simulate stopped and warned (RuntimeWarning) and a StabilityWarning was also issued.
A divergence without a StabilityWarning, or a NaN returned silently, would be a bug (counted as
"unexpected" by the script). The fast subset is asserted in `tests/python/test_extremes.py`.

Documented behaviour: no NaN or Inf is ever returned silently; methods that keep unit |q| keep
||q| - 1| at round-off; a body with a zero principal moment (thin rod) is refused; explicit Euler and
the explicit-gyroscopic semi-implicit Euler gain energy every step (they warn once the predicted
growth over the run exceeds 10x); RK4 and RKMK4 are stable up to dt rho ~ 2.8 and drift slowly in
energy and |L|; the implicit-gyroscopic Euler never blows up but damps nutation (the fast top
loses all its wobble within 0.3 s even at dt = 0.25 ms, see the tradeoff table of `fast_top`).

The structure-preserving methods carry their documented limit in `methods()["stability_limit"]`
(the C++ `MethodInfo`), a bound on dt |w| with |w| the largest body rate along the torque-free
orbit; `rigiddyn.stability` warns beyond it. `implicit_midpoint` keeps energy and |L| to ~1e-14
while its Newton iteration converges (limit 3: measured to fail from dt |w| ~ 3.5 near the
separatrix, where energy and |L| are lost). `splitting_dlm` (limit 1) and `splitting_dlm_yoshida4`
(limit 0.7: its substeps reach 1.70 dt) keep |L| and unit |q| to round-off at ANY step, but their
bounded energy error becomes O(1) beyond the limit. All three are second or fourth order, so at
dt |w| = 1e-2 their error is the truncation error of that order (e.g. 4.2e-5 in body momentum
for implicit midpoint after 500 steps at moment ratio 1e6, exactly N (h Omega)^3 / 12), not
round-off. `exact` (order 0) and `exact_flow_kick` (exact without couples) are at round-off on
every torque-free case, at any step.

"""

SCENES_HEADER = """## Scenes

Every method on scenes of several bodies and force elements, against a Richardson-refined reference (the
highest-order method the scene compiles without a warning, checked against another method family; see
`python/rigiddyn/scene_precision.py`) or, where the scene is the case of a closed form (the pendulum,
the symmetric heavy top, the constant-thrust rocket, free particles in a rotating frame), against that
exact solution (the reference column names it), measured with `rigiddyn.tradeoff`. Position and attitude errors
are the largest over the bodies; energy error: max |E - E_ref| / max (T + |V|) of the reference; momentum
error: the larger relative error of the total linear and angular momentum. Outcomes as above, with
stability judged from the scene's linear modes (`rigiddyn.stability.scene_modes`: springs, gravity, drag),
and **not applicable** where compiling the scene for the method refuses it (the reason given).
An unsoftened close encounter has no linear warning at the start: its error grows at the pericentre.
The last rows are the models of bodies pinned at a point, a frame turning with the Earth or a
carousel, a rocket losing 99 % of its mass (docs/fixed_point_frames_mass.md). Energy error there: the
Jacobi integral in a rotating frame; with a mass flow the energy is not conserved (the thrust works)
and its error is measured against the exact reference's.
"""

FOOTER = "Run time of the whole matrix: {elapsed:.1f} s on the machine above.\n"


if __name__ == "__main__":
    sys.exit(main())
