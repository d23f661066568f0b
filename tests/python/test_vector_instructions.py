"""The vector instructions of the N-body pair sum: RIGIDDYN_PORTABLE=1 forces the portable path, the default is the
widest the CPU has, and the default and portable paths give the same motion to round-off (the bound of
pair_forces.hpp carried through one RK4 step)."""

from __future__ import annotations

import json
import os
import pathlib
import platform
import subprocess
import sys

import numpy as np
import pytest

import rigiddyn as rd

PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(rd.__file__)))  # not resolved: symlinks

# One RK4 step of a 40-body cluster from the same state on the path the environment picks: the positions, velocities
# and the work of gravity, as JSON.
STEP = """
import json, numpy as np, rigiddyn as rd
rng = np.random.default_rng(7)
n = 40
bodies = [rd.Particle(float(m)) for m in rng.uniform(0.5, 2.0, n)]
scene = rd.Scene(bodies, elements=[rd.MutualGravity(G=1.0, softening=0.05)])
start = [rd.ParticleState(p_W=tuple(rng.normal(size=3)), v_W=tuple(0.1 * rng.normal(size=3))) for _ in range(n)]
r = rd.simulate(scene, start, 1e-3, steps=1, method="rk4", error=False)
print(json.dumps({"path": rd.vector_instructions(), "p_W": r.p_W[-1].tolist(), "v_W": r.v_W[-1].tolist(),
                  "p0_W": r.p_W[0].tolist(), "mass": [b.mass for b in bodies]}))
"""


def run_on_path(script: str, portable: str | None) -> dict:
    """The JSON `script` prints, run in a fresh process on this rigiddyn with RIGIDDYN_PORTABLE = `portable` (None:
    unset), since the path is chosen once per process."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([PACKAGE_PARENT, os.environ.get("PYTHONPATH", "")]))
    env.pop("RIGIDDYN_PORTABLE", None)
    if portable is not None:
        env["RIGIDDYN_PORTABLE"] = portable
    out = subprocess.run([sys.executable, "-c", script], env=env, capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def _step(portable: str | None) -> dict:
    return run_on_path(STEP, portable)


def _cpu_flags() -> set[str] | None:
    """The CPU's flags from /proc/cpuinfo on x86-64 Linux; None where it cannot be read."""
    try:
        flags = next(line for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines() if line.startswith("flags"))
    except (OSError, StopIteration):
        return None
    return set(flags.split())


def test_the_environment_forces_the_portable_path() -> None:
    assert _step("1")["path"] == "portable"


def test_the_default_path_is_the_widest_the_cpu_has() -> None:
    flags = _cpu_flags()
    if flags is None:
        pytest.skip("no /proc/cpuinfo to read the CPU's flags from")
    if platform.machine() != "x86_64":
        pytest.skip("the vector kernels are built on x86-64 only")
    # /proc/cpuinfo lists avx512f only where the kernel enables the ZMM state, as the library's check requires
    widest = ("avx512" if {"avx2", "fma", "avx512f"} <= flags else "avx2_fma" if {"avx2", "fma"} <= flags
              else "portable")
    assert _step(None)["path"] == widest
    assert _step("0")["path"] == widest


def test_both_paths_give_the_same_step_to_round_off() -> None:
    default, portable = _step(None), _step("1")
    if default["path"] == "portable":
        pytest.skip("this machine runs the portable path only")
    # Per body and component each path's force is within (n + 24) u sum_j |f_ij| of the exact sum (pair_forces.hpp),
    # so the two paths' differ by at most twice that: an acceleration of 2 (n + 24) u S_i with
    # S_i = sum_j G m_j |d_ij| / (|d_ij|^2 + eps^2)^(3/2) at the start (the stages lie within dt of it: the
    # distances change by under 1e-3 of themselves, covered by the factor 1.01). RK4 adds
    # dt times a mean of its four stages (weights summing to one) to v and dt^2 times at most 1/2 of it to p; the
    # updates' own rounding can then differ by a few units in the last place of |v| and |p| (8 u).
    u, dt, eps2 = 2.0**-53, 1e-3, 0.05**2
    p0, m = np.array(default["p0_W"]), np.array(default["mass"])
    n = len(m)
    d = p0[None, :, :] - p0[:, None, :]
    r2 = (d**2).sum(axis=2) + eps2
    pair = m[None, :] * np.sqrt((d**2).sum(axis=2)) / r2**1.5
    np.fill_diagonal(pair, 0.0)
    a_bound = 2 * 1.01 * (n + 24) * u * pair.sum(axis=1).max()
    v0, v1 = np.array(default["v_W"]), np.array(portable["v_W"])
    p1, p2 = np.array(default["p_W"]), np.array(portable["p_W"])
    assert np.abs(v0 - v1).max() <= dt * a_bound + 8 * u * np.abs(v0).max()
    assert np.abs(p1 - p2).max() <= dt * dt * a_bound + 8 * u * np.abs(p1).max()
