"""Method and step of the shipped scenes with a [controller] (cubesat_detumbling, cubesat_pointing), measured on
the controlled run, as their files quote them.

    PYTHONPATH=build/<dir>/python python3 bench/python/controlled_scene_steps.py

`python3 -m rigiddyn tradeoff` sweeps a scene's bodies and elements without its [controller]. Both CubeSats are
isotropic: without the controller they turn at a constant rate, which rkmk4 and the splittings follow exactly, so
that sweep says nothing of the controlled motion. Here every method runs the file's duration at each step under the
file's [controller] (each step divides the controller's period: every run samples the law at the same times) and is
compared, at records 2 s apart, with rk4 at a quarter of the smallest step:
  attitude  the largest geodesic angle between the run's attitude q_WB and the reference's [rad];
  rate      the largest |w_B - w_B,ref| [rad/s];
and its cost in derivative evaluations (steps times the method's evaluations per step, rigiddyn.methods()). The
reference's own error is estimated by rk4 at twice its step against it. A method the scene refuses is named with
the reason; the balance check of each run (AccuracyWarning) is off: the table states the error.
"""

from __future__ import annotations

import numpy as np

import rigiddyn as rd
from rigiddyn.scene_precision import attitude_angle

RECORD_SPACING = 2.0  # [s]
# the steps [s] of each scene: 2x to 1/4x the file's (a step at most the controller's period, which caps it)
STEPS = {"cubesat_detumbling": (1.0, 0.5, 0.25, 0.125), "cubesat_pointing": (0.5, 0.25, 0.1, 0.05, 0.025)}


def run(name, method, dt):
    """The shipped scene `name` over its file's duration at step `dt` [s] under its [controller]."""
    scene, initial, options = rd.load_scene(name)
    steps = round(options.duration / dt)
    return rd.simulate(scene, initial, dt=dt, steps=steps, method=method, record_every=round(RECORD_SPACING / dt),
                       controller=options.controller, error=False, accuracy_level=None)  # the table states it


def errors(result, reference):
    """(attitude [rad], rate [rad/s]): the largest differences from the reference over the common records."""
    assert np.allclose(result.t, reference.t)
    attitude = attitude_angle(np.asarray(reference.q_WB), np.asarray(result.q_WB)).max()
    rate = np.linalg.norm(np.asarray(result.w_B) - np.asarray(reference.w_B), axis=-1).max()
    return float(attitude), float(rate)


def sweep(name):
    """Print the table of scene `name`: every method at each of its steps against the reference."""
    dt_ref = min(STEPS[name]) / 4
    reference = run(name, "rk4", dt_ref)
    attitude, rate = errors(run(name, "rk4", 2 * dt_ref), reference)
    options = rd.load_scene(name).run
    print(f"{name} ({options.duration:g} s under its controller, records {RECORD_SPACING:g} s apart): against rk4 "
          f"at dt = {dt_ref:g} s (rk4 at {2 * dt_ref:g} s differs by {attitude:.1e} rad, {rate:.1e} rad/s)")
    print(f"  {'method':39} {'dt [s]':>7} {'steps':>7} {'evaluations':>11} {'attitude [rad]':>14} "
          f"{'rate [rad/s]':>12}")
    for info in rd.methods():
        if info["name"] == "exact":
            continue
        for dt in STEPS[name]:
            steps = round(options.duration / dt)
            try:
                attitude, rate = errors(run(name, info["name"], dt), reference)
            except ValueError as refusal:
                print(f"  {info['name']:39} not applicable: {str(refusal).split(':')[1].strip()}")
                break
            print(f"  {info['name']:39} {dt:7g} {steps:7d} {steps * info['evaluations']:11d} {attitude:14.2e} "
                  f"{rate:12.2e}")


def main():
    for name in STEPS:
        sweep(name)


if __name__ == "__main__":
    main()
