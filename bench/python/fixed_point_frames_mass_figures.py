"""The figures of the shipped pendulum, heavy_top, foucault and rocket scenes quoted in
docs/fixed_point_frames_mass.md (section 5): each scene run with its file's [run] (method, dt, duration) and
measured against its closed form.

    PYTHONPATH=build/<dir>/python python3 bench/python/fixed_point_frames_mass_figures.py

- pendulum: the period, from the times the rod passes theta = 0 going up (linear interpolation between
  records), against CompoundPendulumSolution.period = 4 K(m) / omega0, and the largest angle error;
- heavy_top: the nutation bounds of the run (the tilt of the axis, max and min over the run) against
  LagrangeTopSolution.theta_min / theta_max, and the largest attitude error;
- foucault: the rate the swing line turns at (a straight-line fit of its direction, taken where the bob is
  within 5 % of its largest distance from the vertical), against -Omega sin(latitude) (clockwise);
  the Jacobi integral's drift and the Coriolis term's largest |power| (zero: it does no work);
- rocket: the mass left and v_z at the end against Tsiolkovsky less the gravity loss.
"""

from __future__ import annotations

import math

import numpy as np
import rigiddyn as rd


def run(name, record_every=1):
    scene, initial, options = rd.load_scene(name)
    result = rd.simulate(scene, initial, dt=options.dt, steps=options.steps, method=options.method,
                         record_every=record_every)
    return scene, initial, options, result


def pendulum():
    scene, (state,), options, r = run("pendulum")
    body, (gravity,) = scene.bodies[0], scene.elements
    exact = rd.CompoundPendulumSolution(body, np.asarray(gravity.g_W), state)
    theta = 2.0 * np.arctan2(r.q_WB[:, 0, 2], r.q_WB[:, 0, 3])
    omega, t = r.w_B[:, 0, 2], r.t
    up = np.nonzero((theta[:-1] < 0.0) & (theta[1:] >= 0.0) & (omega[:-1] > 0.0))[0]
    crossings = t[up] - theta[up] * (t[up + 1] - t[up]) / (theta[up + 1] - theta[up])
    period = float(np.mean(np.diff(crossings)))
    theta_exact, _ = exact.at(t)
    print(f"pendulum ({options.method}, dt = {options.dt} s, {t[-1]:g} s): period {period:.10f} s from "
          f"{len(crossings)} crossings, exact {exact.period:.10f} s (relative {period / exact.period - 1:+.1e}); "
          f"linear 2 pi / omega0 = {2 * math.pi / exact.omega0:.6f} s, ratio {exact.period * exact.omega0 / (2 * math.pi):.4f}; "
          f"max |theta - exact| {np.max(np.abs(theta - theta_exact)):.1e} rad")


def heavy_top():
    scene, (state,), options, r = run("heavy_top")
    body, (gravity,) = scene.bodies[0], scene.elements
    exact = rd.LagrangeTopSolution(body, np.asarray(gravity.g_W), state)
    axis = rd.quat_rotate(r.q_WB[:, 0], np.array([0.0, 0.0, 1.0]))
    tilt = np.arccos(np.clip(axis[:, 2], -1.0, 1.0))
    q_exact, _ = exact.at(r.t)
    angle = rd.angular_distance(r.q_WB[:, 0], q_exact)
    print(f"heavy_top ({options.method}, dt = {options.dt} s, {r.t[-1]:g} s): tilt {np.degrees(tilt.min()):.6f} to "
          f"{np.degrees(tilt.max()):.6f} deg, exact {np.degrees(exact.theta_min):.6f} to {np.degrees(exact.theta_max):.6f} "
          f"deg; nutation period {exact.nutation_period:.6f} s, mean precession {exact.mean_precession_rate:.6f} rad/s; "
          f"max attitude error {np.max(angle):.1e} rad")


def foucault():
    scene, _, options, r = run("foucault", record_every=5)
    p, t = np.asarray(r.p_W)[:, 0, :2], np.asarray(r.t)
    far = np.linalg.norm(p, axis=1) > 0.95 * np.max(np.linalg.norm(p, axis=1))
    direction = np.unwrap(2.0 * np.arctan2(p[far, 1], p[far, 0])) / 2.0  # the swing line, mod pi
    rate = float(np.polyfit(t[far], direction, 1)[0])
    expected = -7.2921159e-5 * math.sin(math.radians(48.85))
    E = np.asarray(r.total_energy)
    coriolis = list(r.elements).index("CoriolisForce")
    print(f"foucault ({options.method}, dt = {options.dt} s, {t[-1]:g} s): the swing line turns at {rate:.6e} rad/s, "
          f"-Omega sin(48.85 deg) = {expected:.6e} (relative {rate / expected - 1:+.1e}), {math.degrees(rate * t[-1]):.3f} "
          f"deg in the run; Jacobi integral drift {np.max(np.abs(E - E[0])) / abs(E[0]):.1e} relative; max |Coriolis "
          f"power| {np.max(np.abs(r.power[:, coriolis])):.1e} W")


def rocket():
    scene, (state,), options, r = run("rocket")
    v_z = float(r.v_W[-1, 0, 2])
    t = float(r.t[-1])
    expected = 2500.0 * math.log(200.0 / (200.0 - 2.0 * t)) - 9.81 * t
    print(f"rocket ({options.method}, dt = {options.dt} s, {t:g} s): mass {r.mass[-1, 0]:.12g} kg, v_z {v_z:.9f} m/s, "
          f"Tsiolkovsky less gravity loss {expected:.9f} m/s (difference {v_z - expected:+.1e})")


if __name__ == "__main__":
    pendulum()
    heavy_top()
    foucault()
    rocket()
