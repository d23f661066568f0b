"""Measure the figures docs/scenes.md quotes for the shipped scenes, each against its reference.

    PYTHONPATH=build/<dir>/python python3 bench/python/scene_figures.py [--cluster-steps 1000]

Prints, per shipped scene run with its file's [run] (method, dt, duration):
  kepler            period (from the mean anomaly turned over 10 orbits), energy and eccentricity vector
                    against 2 pi sqrt(a^3/GM), -m GM/(2a) and (0.1, 0, 0);
  gravity_gradient  the pitch libration frequency against n sqrt(3 (I_x - I_z)/I_y) and against the
                    pendulum-corrected value (1 - (2 theta0)^2/16) of the 2-deg amplitude;
  spring_chain      the largest position error against the closed form exp(A t) x0 (eigen-decomposition);
  three_body        the return to the start after one period, the energy drift, the total momenta;
  cluster           energy drift |E(t) - E(0)|/|E(0)| and total linear momentum over --cluster-steps steps
                    of dt = 1/128 with rk4 and splitting_dlm_yoshida4.
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

import rigiddyn
from rigiddyn.scene_file import read_scene


def _run(name: str, method: str | None = None, steps: int | None = None):
    f = read_scene(name)
    method = method or f.run.method
    start = time.perf_counter()
    result = rigiddyn.simulate(f.scene, f.initial, dt=f.run.dt, steps=steps or f.run.steps, method=method,
                               record_every=f.run.record_every)
    return f, result, time.perf_counter() - start


def _mean_anomaly(gm: float, p: np.ndarray, v: np.ndarray) -> float:
    """Mean anomaly [rad] of the osculating ellipse of (p, v) about gm (Kepler's equation M = E - e sin E)."""
    r = np.linalg.norm(p)
    a = 1.0 / (2.0 / r - v @ v / gm)
    e_cos = 1.0 - r / a
    e_sin = (p @ v) / math.sqrt(gm * a)
    E = math.atan2(e_sin, e_cos)
    return E - math.hypot(e_cos, e_sin) * math.sin(E)


def kepler() -> None:
    gm, a, e, m = 398600.4418e9, 7.0e6, 0.1, 1000.0
    f, r, seconds = _run("kepler")
    p, v = r.p_W[:, 0], r.v_W[:, 0]
    period = 2 * math.pi * math.sqrt(a**3 / gm)
    orbits = round(r.t[-1] / period)
    turned = 2 * math.pi * orbits + (
        (_mean_anomaly(gm, p[-1], v[-1]) - _mean_anomaly(gm, p[0], v[0]) + math.pi) % (2 * math.pi) - math.pi)
    measured = r.t[-1] * 2 * math.pi / turned
    energy = -m * gm / (2 * a)
    ecc = ((np.sum(v**2, axis=1) - gm / np.linalg.norm(p, axis=1))[:, None] * p
           - np.sum(p * v, axis=1)[:, None] * v) / gm
    print(f"kepler ({f.run.method}, dt = {f.run.dt:.6g} s, {orbits} orbits, {seconds:.2f} s): "
          f"period rel. error {abs(measured / period - 1):.2e}; "
          f"max energy rel. error {np.max(np.abs(r.total_energy / energy - 1)):.2e}; "
          f"max |e_vec - (0.1, 0, 0)| {np.max(np.linalg.norm(ecc - [e, 0, 0], axis=1)):.2e}")


def gravity_gradient() -> None:
    gm, radius = 398600.4418e9, 7.0e6
    f, r, seconds = _run("gravity_gradient")
    p, v, q = r.p_W[:, 0], r.v_W[:, 0], r.q_WB[:, 0]
    pitch = np.empty(len(r.t))
    for k in range(len(r.t)):  # LVLH: z to nadir, y = z x v (minus the orbit normal), x = y x z
        z = -p[k] / np.linalg.norm(p[k])
        y = np.cross(z, v[k])
        y /= np.linalg.norm(y)
        R_LB = np.column_stack([np.cross(y, z), y, z]).T @ rigiddyn.quat_to_matrix(q[k])
        pitch[k] = math.atan2(R_LB[0, 2], R_LB[2, 2])
    i = np.nonzero(pitch[:-1] * pitch[1:] < 0)[0]
    crossings = r.t[i] - pitch[i] * (r.t[i + 1] - r.t[i]) / (pitch[i + 1] - pitch[i])
    measured = math.pi * (len(crossings) - 1) / (crossings[-1] - crossings[0])
    n = math.sqrt(gm / radius**3)
    omega_p = n * math.sqrt(3 * (300 - 100) / 400)
    pendulum = omega_p * (1 - math.radians(4) ** 2 / 16)
    print(f"gravity_gradient ({f.run.method}, dt = {f.run.dt:g} s, {r.t[-1] / 3600:g} h, {seconds:.2f} s): "
          f"libration {measured:.10e} rad/s vs linear {omega_p:.10e} (rel. {measured / omega_p - 1:+.2e}), "
          f"vs pendulum-corrected (rel. {measured / pendulum - 1:+.2e})")


def spring_chain() -> None:
    f, r, seconds = _run("spring_chain")
    m, k, c = np.array([1.0, 2.0, 0.5]), [100.0, 150.0, 80.0], [0.2, 0.2, 0.1]

    def chain(s: list[float]) -> np.ndarray:
        return np.array([[s[0] + s[1], -s[1], 0], [-s[1], s[1] + s[2], -s[2]], [0, -s[2], s[2]]])

    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-chain(k) / m[:, None], -chain(c) / m[:, None]]])
    lam, V = np.linalg.eig(A)
    coefficients = np.linalg.solve(V, [0, 0, 0.1, 0, 0, 0])
    exact = np.real((V[:3] @ (coefficients[:, None] * np.exp(lam[:, None] * r.t[None, :]))).T)
    error = np.max(np.abs(r.p_W[:, :, 0] - [1, 2, 3] - exact))
    balance = r.kinetic_energy - r.work.sum(axis=1)  # work-energy theorem: T - (every element's work) = T(0)
    print(f"spring_chain ({f.run.method}, dt = {f.run.dt:g} s, {r.t[-1]:g} s, {seconds:.2f} s): "
          f"max |x - closed form| {error:.2e} m; "
          f"work-energy max |T - W - T(0)| {np.max(np.abs(balance - balance[0])):.2e} J (W: every element's work)")


def three_body() -> None:
    f, r, seconds = _run("three_body")
    back = np.max(np.abs(r.p_W[-1] - r.p_W[0]))
    drift = np.max(np.abs(r.total_energy / r.total_energy[0] - 1))
    print(f"three_body ({f.run.method}, dt = T/6000, one period, {seconds:.2f} s): "
          f"return max |p(T) - p(0)| {back:.2e} m; E(0) = {r.total_energy[0]:.7f} J, max energy rel. drift "
          f"{drift:.2e}; max |P| {np.max(np.abs(r.linear_momentum_W)):.2e}, "
          f"max |L| {np.max(np.abs(r.angular_momentum_W)):.2e}")


def cluster(steps: int) -> None:
    f = read_scene("cluster")
    for method in ("rk4", "splitting_dlm_yoshida4"):
        start = time.perf_counter()
        r = rigiddyn.simulate(f.scene, f.initial, dt=f.run.dt, steps=steps, method=method,
                              record_every=max(1, steps // 100))
        seconds = time.perf_counter() - start
        E0 = r.total_energy[0]
        drift = np.abs(r.total_energy / E0 - 1)
        L = r.angular_momentum_W
        print(f"cluster ({method}, N = {len(f.scene.bodies)}, dt = {f.run.dt:g}, {steps} steps = {steps * f.run.dt:g} "
              f"time units, {seconds:.2f} s): E(0) = {E0:.6f}; |E - E(0)|/|E(0)| max {drift.max():.2e}, "
              f"at the end {drift[-1]:.2e}; max |P| {np.max(np.abs(r.linear_momentum_W)):.2e}; "
              f"max |L - L(0)| {np.max(np.abs(L - L[0])):.2e} (|L(0)| {np.linalg.norm(L[0]):.2e})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cluster-steps", type=int, default=1000)
    args = parser.parse_args()
    kepler()
    gravity_gradient()
    spring_chain()
    three_body()
    cluster(args.cluster_steps)


if __name__ == "__main__":
    main()
