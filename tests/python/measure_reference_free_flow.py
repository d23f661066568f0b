"""Figures of the numpy reference's free flow (rigiddyn_ref.free_flow) against the core, printed
(not a test; pytest collects only test_*.py). Run from the repository root:
    PYTHONPATH=<build>/python:tests/reference:tests/python python3 tests/python/measure_reference_free_flow.py
1. One call over 10 s of each closed form (the reference's free_rotation, the core's
   TorqueFreeSolution.state_at), and 1000 composed reference steps against the core's 'exact' run.
2. test_geometric_vs_reference's 1000-step comparison: the scaled difference of the core's and the
   reference's runs and the tolerance the test derives from the propagated round-off."""

import numpy as np
from scipy.spatial.transform import Rotation

import rigiddyn as rd
import test_geometric_vs_reference as geo
from _error_bounds import (amplification_sum, closed_form_error, inertia_condition, local_roundoff, scaled_difference,
                           state_of)
from rigiddyn_ref import free_flow

EPS = np.finfo(float).eps
D = np.diag([1.0, 2.0, 3.0])
ORBITS = [("geometric-test body", geo.INERTIA, geo.W0), ("diag(1, 2, 3), case B", D, np.array([1.0, 0.5, -0.3])),
          ("diag(1, 2, 3), 1e-9 off the separatrix", D, np.array([0.3, 2.0, 0.1 * np.sqrt(3) * (1 + 1e-9)]))]


def attitude_and_rate(R, w, q_core, w_core):
    """(angle [rad] between R and q_core, |w - w_core| / |w_core|)."""
    turn = (Rotation.from_matrix(R).inv() * Rotation.from_quat(q_core)).as_rotvec()
    return np.linalg.norm(turn), np.linalg.norm(w - w_core) / np.linalg.norm(w_core)


def free_flow_figures(T=10.0, steps=1000):
    R0 = Rotation.from_quat(geo.Q0).as_matrix()
    for name, inertia, w0 in ORBITS:
        q, w = rd.TorqueFreeSolution(inertia, geo.Q0, w0).state_at(T)
        one = attitude_and_rate(*free_flow.free_rotation(inertia, R0, w0, T), q, w)
        R, w_ref = R0, w0
        for _ in range(steps):
            R, w_ref = free_flow.free_rotation(inertia, R, w_ref, T / steps)
        run = rd.simulate(rd.RigidBody(1.0, inertia), rd.RigidBodyState(q_WB=geo.Q0, w_B=w0), T / steps, steps,
                          method="exact", record_every=steps)
        composed = attitude_and_rate(R, w_ref, run.q_WB[-1], run.w_B[-1])
        print(f"{name}: one call over {T} s: {one[0]:.2e} rad, |dw|/|w| {one[1]:.2e} "
              f"(bound {free_flow.step_error_bound(inertia, T, w0):.2e}); {steps} steps: {composed[0]:.2e} rad, "
              f"|dw|/|w| {composed[1]:.2e}")


def thousand_step_margins(dt=0.01, steps=1000):
    kappa = inertia_condition(geo.INERTIA)
    for method, loads in geo.CASES:
        core = geo.run_core(method, dt, steps, loads, record_every=1)
        local = local_roundoff(method, kappa)
        flows = method in ("exact_flow_kick", "exact")
        ref = max(local + (free_flow.step_error_bound(geo.INERTIA, dt, w) if flows else 0.0) for w in core.w_B)
        A = amplification_sum(rd.RigidBody(geo.MASS, geo.INERTIA), core, dt, method, geo.core_loads(loads), geo.GRAVITY)
        tol = A * ref + (closed_form_error(kappa, geo.W0, steps * dt) if method == "exact" else A * local)
        d = scaled_difference(state_of(core, -1), geo.run_reference(method, dt, steps, loads))
        print(f"{method:24s} difference {d:.2e}, tolerance {tol:.2e} (amplification sum {A:.3g})")


if __name__ == "__main__":
    free_flow_figures()
    thousand_step_margins()
