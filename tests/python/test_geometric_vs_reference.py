"""The structure-preserving methods (implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4,
exact_flow_kick, exact) against the independent numpy reference rigiddyn_ref.geometric: one step
and 1000 steps, a body with products of inertia under loads of every kind; plus short Python-side
checks of the registry, the exact method and the invariants (1e5 steps)."""

import numpy as np
import pytest
from rigiddyn_ref import dynamics as ref_dyn
from rigiddyn_ref import geometric as ref
from rigiddyn_ref import integrators as ref_int
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _helpers import planar_and_rigid_runs

MASS = 2.5
INERTIA = np.array([[0.9, 0.05, -0.1], [0.05, 1.4, 0.08], [-0.1, 0.08, 1.9]])
Q0 = Rotation.from_rotvec([0.3, -0.5, 0.8]).as_quat()
P0, V0, W0 = np.array([0.1, -0.2, 0.3]), np.array([0.5, 0.2, -0.1]), np.array([1.2, -0.7, 2.0])
GRAVITY = np.array([0.0, 0.0, -9.81])
LOADS = [((0.4, -0.2, 1.0), (0.05, 0.1, -0.2), "world"), ((0.3, 0.1, -0.2), (-0.1, 0.2, 0.15), "body")]
FORCE_ONLY = [((0.4, -0.2, 1.0), (0.0, 0.0, 0.0), "world")]


def run_core(method, dt, steps, loads, inertia=INERTIA):
    return rd.simulate(rd.RigidBody(MASS, inertia), rd.RigidBodyState(p_W=P0, q_WB=Q0, v_W=V0, w_B=W0), dt, steps,
                       method=method, record_every=steps,
                       loads=[rd.AppliedLoad(force=f, torque=n, frame=fr) for f, n, fr in loads], gravity=GRAVITY)


def run_reference(method, dt, steps, loads, inertia=INERTIA):
    model = ref_int.RigidBodyModel(MASS, inertia, GRAVITY)
    schedule = [ref_dyn.Load(np.array(f), np.array(n), fr) for f, n, fr in loads]
    y0 = ref_int.RigidBodyModel.initial(P0, Q0, V0, W0)
    return ref.simulate(model, y0, dt, steps, method, schedule)


def difference(core, y):
    """Largest difference, relative to max(1, |value|) per component (p and work grow large)."""
    def rel(a, b):
        return np.max(np.abs(np.atleast_1d(a) - b) / np.maximum(1.0, np.abs(b)))
    angle = (Rotation.from_quat(y[3:7]).inv() * Rotation.from_quat(core.q_WB[-1])).magnitude()
    return max(rel(core.p_W[-1], y[0:3]), angle, rel(core.v_W[-1], y[7:10]), rel(core.w_B[-1], y[10:13]),
               rel(core.work[-1], y[13]))


CASES = [("implicit_midpoint", LOADS), ("splitting_dlm", LOADS), ("splitting_dlm_yoshida4", LOADS),
         ("exact_flow_kick", LOADS), ("exact", FORCE_ONLY)]


@pytest.mark.parametrize("method, loads", CASES)
def test_one_step_matches_reference(method, loads):
    assert difference(run_core(method, 0.01, 1, loads), run_reference(method, 0.01, 1, loads)) < 1e-13


@pytest.mark.parametrize("method, loads", CASES)
def test_thousand_steps_match_reference(method, loads):
    # the reference's free flow for exact_flow_kick/exact is a fine composition (~1e-15 per step)
    assert difference(run_core(method, 0.01, 1000, loads), run_reference(method, 0.01, 1000, loads)) < 1e-10


def test_diagonal_and_spherical_inertias_match_reference():
    for inertia in (np.diag([1.0, 3.0, 2.0]), 0.7 * np.eye(3)):
        for method in ("implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4"):
            core = run_core(method, 0.01, 200, LOADS, inertia)
            assert difference(core, run_reference(method, 0.01, 200, LOADS, inertia)) < 1e-11, (method, inertia)


def test_registry_lists_the_new_methods():
    table = {m["name"]: m for m in rd.methods()}
    expected = {"implicit_midpoint": 2, "splitting_dlm": 2, "splitting_dlm_yoshida4": 4, "exact_flow_kick": 2, "exact": 0}
    for name, order in expected.items():
        assert table[name]["order"] == order
        assert table[name]["conserves"] and table[name]["notes"]


def test_exact_method_rejects_couples():
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    with pytest.raises(ValueError, match=r"^loads\[0\]\.torque"):
        rd.simulate(body, rd.RigidBodyState(w_B=[0.01, 2.0, 0.01]), 0.1, 10, method="exact",
                    loads=rd.AppliedLoad(torque=[0, 0, 1.0]))
    with pytest.raises(ValueError, match="^method"):
        rd.step(body, rd.RigidBodyState(w_B=[0.01, 2.0, 0.01]), 0.1, method="exact", loads=rd.AppliedLoad(torque=[0, 0, 1.0]))


def test_exact_method_equals_torque_free_solution_at_record_times():
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    r = rd.simulate(body, rd.RigidBodyState(q_WB=Q0, w_B=[0.01, 2.0, 0.01]), 0.5, 200, method="exact", record_every=50)
    q, w = rd.TorqueFreeSolution(np.diag([1.0, 2.0, 3.0]), Q0, [0.01, 2.0, 0.01]).state_at(r.t)
    np.testing.assert_array_equal(r.w_B, w)
    np.testing.assert_array_equal(r.q_WB, q)


@pytest.mark.parametrize("method, dE, dL", [("splitting_dlm", 1e-4, 1e-12), ("implicit_midpoint", 1e-12, 1e-12)])
@pytest.mark.parametrize("w0", [(0.01, 2.0, 0.01), (0.02, 2.0, 0.01)])  # case A, case B
def test_invariants_over_1e5_steps(method, dE, dL, w0):
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    r = rd.simulate(body, rd.RigidBodyState(q_WB=Q0, w_B=w0), 0.01, 100000, method=method, record_every=100)
    assert np.abs(r.kinetic_energy / r.kinetic_energy[0] - 1).max() < dE
    assert np.abs(r.angular_momentum_norm / r.angular_momentum_norm[0] - 1).max() < dL


@pytest.mark.parametrize("method", ["implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick",
                                    "exact"])
def test_particle_under_constant_force_is_exact(method):
    # models without attitude: the methods reduce to velocity Verlet / fixed-point midpoint, exact here
    f, p0, v0 = np.array([0.5, -1.0, 2.0]), np.array([1.0, 2.0, 3.0]), np.array([0.3, -0.2, 4.0])
    r = rd.simulate(rd.Particle(2.0), rd.ParticleState(p0, v0), 0.1, 20, method=method,
                    loads=rd.AppliedLoad(force=f), gravity=True)
    a = f / 2.0 + GRAVITY
    np.testing.assert_allclose(r.p_W[-1], p0 + 2.0 * v0 + 2.0 * a, rtol=0, atol=1e-12)
    np.testing.assert_allclose(r.v_W[-1], v0 + 2.0 * a, rtol=0, atol=1e-12)
    np.testing.assert_allclose(r.work[-1], r.kinetic_energy[-1] - r.kinetic_energy[0], rtol=1e-12)


@pytest.mark.parametrize("method", ["splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"])
def test_planar_body_equals_rigid_body_kept_in_plane(method):
    loads = [rd.AppliedLoad(force=[0.5, -1.0, 0.0], torque=[0, 0, 0.3]),
             rd.AppliedLoad(force=[1.0, 0.4, 0.0], torque=[0, 0, -0.1], frame="body")]
    planar, spatial = planar_and_rigid_runs(method, loads)
    for name in ["p_W", "q_WB", "v_W", "w_B", "kinetic_energy"]:
        np.testing.assert_allclose(getattr(planar, name), getattr(spatial, name), rtol=0, atol=1e-11, err_msg=name)
    # the work differs at O(h^2): the rigid body's kicks book exactly the kinetic-energy change they
    # make, the planar model's drift books f(theta0).v h
    np.testing.assert_allclose(spatial.kinetic_energy - spatial.kinetic_energy[0], spatial.work, rtol=0, atol=1e-12)
    np.testing.assert_allclose(planar.work, spatial.work, rtol=0.01, atol=1e-3)
