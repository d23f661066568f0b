"""The Python overhead of rigiddyn.simulate on each model of a body about a fixed point, a moving frame or
variable mass (target: < 10 % over the C++ call).

For each model, one run of `steps` RK4 steps recording every step (the arrays the user gets: SceneResult
adopts the C++ records without a copy) and one recording only the first and last state:
  - heavy_top:       PivotedBody (box 2 kg, c = 0.5 m above the pivot) under gravity, simulate(body, state, ...);
  - pendulum:        PivotedPlanarBody under in-plane gravity;
  - rotating_frame:  a Particle in SceneFrame.rotating under gravity (a Scene);
  - rocket:          a Particle with MassFlow(rate) and a Thrust under gravity (a Scene);
  - earth_top:       the heavy top in SceneFrame.earth (the generic scene model: every fictitious term).
The C++ time is SceneResult.elapsed_seconds (the stepping loop, measured in C++); the Python time is the wall
time of the whole rigiddyn.simulate call (argument conversion, compiling the scene, releasing the GIL, the
loop, wrapping the records), the fastest of several runs. So the overhead printed,
    rigiddyn/cpp_loop = wall / elapsed_seconds   (1.10 = 10 % over the loop),
also counts compiling the scene, which a C++ caller of simulate(scene, ...) pays too: it bounds the Python
overhead from above.

    python bench/python/bench_fixed_point_frames_mass_overhead.py           # 100 000 steps
    python bench/python/bench_fixed_point_frames_mass_overhead.py --small   # 5 000 steps (what ctest runs)
"""

import time

import numpy as np

import rigiddyn as rd
from _bench_common import parse_small, report_ratio

G_W = np.array([0.0, 0.0, -9.81])


def heavy_top():
    body = rd.PivotedBody(rd.RigidBody(2.0, [0.04, 0.04, 0.02]), [0.0, 0.0, 0.5])
    state = rd.PivotedBodyState(q_WB=rd.axis_angle_to_quat([1.0, 0.0, 0.0], 0.3), w_B=[0.0, 0.0, 60.0])
    return body, state, {"gravity": True}


def pendulum():
    body = rd.PivotedPlanarBody(1.0, 0.01, [0.0, -0.5])
    return body, rd.PivotedPlanarBodyState(theta=1.0), {"gravity": [0.0, -9.81]}


def rotating_frame():
    scene = rd.Scene([rd.Particle(1.0)], elements=[rd.UniformGravity(g_W=G_W)],
                     frame=rd.SceneFrame.rotating([0.0, 0.0, 1.0], 0.5))
    return scene, [rd.ParticleState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 1.0, 2.0])], {}


def rocket():
    scene = rd.Scene()
    scene.add_body(rd.Particle(100.0), mass_flow=rd.MassFlow(rate=-0.05))
    scene.add(rd.Thrust(0, [0.0, 0.0, -3000.0], frame="world"))
    scene.add(rd.UniformGravity(g_W=G_W))
    return scene, [rd.ParticleState()], {}


def earth_top():
    body, state, _ = heavy_top()
    scene = rd.Scene([body], elements=[rd.UniformGravity(g_W=G_W)], frame=rd.SceneFrame.earth(np.radians(48.85)))
    return scene, [state], {}


MODELS = {"heavy_top": heavy_top, "pendulum": pendulum, "rotating_frame": rotating_frame, "rocket": rocket,
          "earth_top": earth_top}


def measure(make, steps, record_every, repeats):
    """(fastest wall time of simulate [s], the C++ loop time of that run [s])."""
    model, initial, extra = make()
    best = (float("inf"), float("nan"))
    for _ in range(repeats):
        start = time.perf_counter()
        result = rd.simulate(model, initial, dt=1e-5, steps=steps, method="rk4", record_every=record_every, error=False, **extra)
        wall = time.perf_counter() - start
        if wall < best[0]:
            best = (wall, result.elapsed_seconds)
        del result  # freed outside the timed call (the next run's assignment would free it inside)
    return best


def main():
    args = parse_small(__doc__, "5 000 steps instead of 100 000")
    steps = 5_000 if args.small else 100_000
    for name, make in MODELS.items():
        for record_every, label in [(1, "every_step"), (steps, "first_last")]:
            wall, loop = measure(make, steps, record_every, repeats=5)
            report_ratio(f"simulate_overhead_{name}_{label}", steps, wall, loop, "cpp_loop")


if __name__ == "__main__":
    main()
