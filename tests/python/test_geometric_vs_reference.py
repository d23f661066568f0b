"""The structure-preserving methods (implicit_midpoint, splitting_dlm, splitting_dlm_yoshida4,
exact_flow_kick, exact) against the independent numpy reference rigiddyn_ref.geometric: one step,
and every step of a 1000-step run plus the whole run (bounded by the local round-off carried by the
method's Jacobians, tests/python/_error_bounds.py), a body with products of inertia under loads of
every kind; plus short Python-side checks of the registry, the exact method and the invariants
(1e5 steps)."""

import numpy as np
import pytest
from rigiddyn_ref import dynamics as ref_dyn
from rigiddyn_ref import free_flow
from rigiddyn_ref import geometric as ref
from rigiddyn_ref import integrators as ref_int
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _error_bounds import (amplification_sum, closed_form_error, inertia_condition, local_roundoff,
                           scaled_difference, state_of)
from _helpers import planar_and_rigid_runs

MASS = 2.5
INERTIA = np.array([[0.9, 0.05, -0.1], [0.05, 1.4, 0.08], [-0.1, 0.08, 1.9]])
Q0 = Rotation.from_rotvec([0.3, -0.5, 0.8]).as_quat()
P0, V0, W0 = np.array([0.1, -0.2, 0.3]), np.array([0.5, 0.2, -0.1]), np.array([1.2, -0.7, 2.0])
GRAVITY = np.array([0.0, 0.0, -9.81])
LOADS = [((0.4, -0.2, 1.0), (0.05, 0.1, -0.2), "world"), ((0.3, 0.1, -0.2), (-0.1, 0.2, 0.15), "body")]
FORCE_ONLY = [((0.4, -0.2, 1.0), (0.0, 0.0, 0.0), "world")]
EPS = np.finfo(float).eps


def run_core(method, dt, steps, loads, inertia=INERTIA, record_every=None):
    return rd.simulate(rd.RigidBody(MASS, inertia), rd.RigidBodyState(p_W=P0, q_WB=Q0, v_W=V0, w_B=W0), dt, steps,
                       method=method, record_every=record_every or steps, loads=core_loads(loads), gravity=GRAVITY)


def core_loads(loads):
    return [rd.AppliedLoad(force=f, torque=n, frame=fr) for f, n, fr in loads]


def reference_model(loads, inertia=INERTIA):
    return (ref_int.RigidBodyModel(MASS, inertia, GRAVITY),
            [ref_dyn.Load(np.array(f), np.array(n), fr) for f, n, fr in loads])


def run_reference(method, dt, steps, loads, inertia=INERTIA):
    model, schedule = reference_model(loads, inertia)
    y0 = ref_int.RigidBodyModel.initial(P0, Q0, V0, W0)
    return ref.simulate(model, y0, dt, steps, method, schedule)


CASES = [("implicit_midpoint", LOADS), ("splitting_dlm", LOADS), ("splitting_dlm_yoshida4", LOADS),
         ("exact_flow_kick", LOADS), ("exact", FORCE_ONLY)]


@pytest.mark.parametrize("method, loads", CASES)
def test_one_step_matches_reference(method, loads):
    core, y = run_core(method, 0.01, 1, loads), run_reference(method, 0.01, 1, loads)
    # both sides round one step: local_roundoff each (16 eps κ per stage; _error_bounds), and the
    # reference's closed free flow adds its stated bound (free_flow.step_error_bound)
    flow = free_flow.step_error_bound(INERTIA, 0.01, W0) if method in ("exact_flow_kick", "exact") else 0.0
    assert scaled_difference(state_of(core, -1), y) <= 2 * local_roundoff(method, inertia_condition(INERTIA)) + flow


def check_run_against_reference(method, loads, inertia, dt, steps):
    """Every step of a core run against one reference step from the core's state (local
    round-off only), then the reference's own run against the core's: the local differences carried
    to the end by the method's Jacobians (_error_bounds.amplification_sum)."""
    kappa = inertia_condition(inertia)
    core = run_core(method, dt, steps, loads, inertia, record_every=1)
    model, schedule = reference_model(loads, inertia)
    # 'exact' evaluates the closed form at each record time: its error grows with t (not a step's)
    exact_at = (lambda t: closed_form_error(kappa, W0, t)) if method == "exact" else (lambda t: 0.0)
    step_bound = local_roundoff(method, kappa)  # the core's, per step
    # the reference's: the same, plus its closed free flow's own stated bound at step k's ω
    # (free_flow.step_error_bound; the kicks move ω by < 1 % per step, inside its factor 16)
    flows = method in ("exact_flow_kick", "exact")
    ref_bounds = [step_bound + (free_flow.step_error_bound(inertia, dt, w) if flows else 0.0)
                  for w in core.body(0).w_B]
    for k in range(steps):
        y = ref.simulate(model, state_of(core, k), dt, 1, method, schedule, t0=k * dt)
        # reference step + core step (or the core's closed form at both ends)
        tol = ref_bounds[k] + (exact_at(k * dt) + exact_at((k + 1) * dt) if method == "exact" else step_bound)
        assert scaled_difference(state_of(core, k + 1), y) <= tol, (method, k)
    y = run_reference(method, dt, steps, loads, inertia)
    amplified = amplification_sum(rd.RigidBody(MASS, inertia), core, dt, method, core_loads(loads), GRAVITY)
    # Σ_k ||J(N, k)|| (e_core + e_ref), each e at its largest over the run; 'exact': the reference
    # steps, the core is its closed form at t_N
    tol = amplified * max(ref_bounds) + (exact_at(steps * dt) if method == "exact" else amplified * step_bound)
    assert scaled_difference(state_of(core, -1), y) <= tol, method


@pytest.mark.parametrize("method, loads", CASES)
def test_thousand_steps_match_reference(method, loads):
    check_run_against_reference(method, loads, INERTIA, 0.01, 1000)


@pytest.mark.parametrize("inertia, w0", [(INERTIA, W0), (np.diag([1.0, 2.0, 3.0]), [1.0, 0.5, -0.3]),  # case B
                                        (np.diag([1.0, 2.0, 3.0]), [0.3, 2.0, 0.1 * np.sqrt(3) * (1 + 1e-3)])])
def test_reference_free_flow_agrees_with_the_core_closed_form(inertia, w0):
    """Two independent closed forms of the torque-free flow over 10 s in one call each: the
    reference's (addition theorem and quadrature, free_flow.free_rotation) and the core's
    (TorqueFreeSolution: u0 from R_F, the attitude through Π), the last 1e-3 off the separatrix."""
    w0, T = np.asarray(w0, float), 10.0
    q, w = rd.TorqueFreeSolution(inertia, Q0, w0).state_at(T)
    R, w_ref = free_flow.free_rotation(inertia, Rotation.from_quat(Q0).as_matrix(), w0, T)
    # both stated bounds: free_flow.step_error_bound (with its phase amplification over the
    # sub-steps) and closed_form_error (exact/free_body.hpp), attitude [rad] and |Δω|/|ω|
    tol = free_flow.step_error_bound(inertia, T, w0) + closed_form_error(inertia_condition(inertia), w0, T)
    assert np.linalg.norm((Rotation.from_matrix(R).inv() * Rotation.from_quat(q)).as_rotvec()) <= tol
    assert np.linalg.norm(w - w_ref) <= tol * np.linalg.norm(w_ref)


@pytest.mark.parametrize("inertia", [np.diag([1.0, 3.0, 2.0]), 0.7 * np.eye(3)])
@pytest.mark.parametrize("method", ["implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"])
def test_diagonal_and_spherical_inertias_match_reference(method, inertia):
    check_run_against_reference(method, LOADS, inertia, 0.01, 200)


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
    # bitwise: the same C++ code (TorqueFreeSolution::state_at, called by simulate_exact.cpp at the
    # record times) computes both from the same doubles r.t, in the one compiled extension
    np.testing.assert_array_equal(r.body(0).w_B, w)
    np.testing.assert_array_equal(r.body(0).q_WB, q)


@pytest.mark.parametrize("method", ["splitting_dlm", "implicit_midpoint"])
@pytest.mark.parametrize("w0", [(0.01, 2.0, 0.01), (0.02, 2.0, 0.01)])  # case A, case B
def test_invariants_over_1e5_steps(method, w0):
    inertia, dt, steps = np.diag([1.0, 2.0, 3.0]), 0.01, 100000
    r = rd.simulate(rd.RigidBody(1.0, inertia), rd.RigidBodyState(q_WB=Q0, w_B=w0), dt, steps, method=method)
    dE = np.abs(r.kinetic_energy / r.kinetic_energy[0] - 1)
    L = r.body(0).angular_momentum_norm
    dL = np.abs(L / L[0] - 1)
    # both keep |L| exactly in exact arithmetic: round-off only, a random walk of <= 2 eps per step
    # stays within 5 sigma = 10 eps sqrt(N) (the bound for the Lie-Poisson methods)
    roundoff_walk = 10 * EPS * np.sqrt(steps)
    assert dL.max() <= roundoff_walk
    if method == "implicit_midpoint":
        assert dE.max() <= roundoff_walk  # midpoint keeps quadratic invariants: round-off as for |L|
        return
    # DLM is symplectic: E - H~ = h^2 H2(m) + O(h^4) with H~ conserved (backward error analysis,
    # Hairer-Lubich-Wanner IX.8), so dE is a function on one closed orbit: after its first period
    # it never exceeds the first period's maximum, beyond O((h|w|)^2) relative (the samples fall on
    # other points of the orbit; the O(h^4) term) and round-off
    first = int(np.ceil(1.05 * rd.TorqueFreeSolution(inertia, Q0, w0).period / dt))
    assert first < steps // 10
    assert dE.max() <= dE[:first + 1].max() * (1 + (dt * np.linalg.norm(w0)) ** 2) + roundoff_walk


@pytest.mark.parametrize("method", ["implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick",
                                    "exact"])
def test_particle_under_constant_force_is_exact(method):
    # models without attitude: the methods reduce to velocity Verlet / fixed-point midpoint, exact here
    f, p0, v0 = np.array([0.5, -1.0, 2.0]), np.array([1.0, 2.0, 3.0]), np.array([0.3, -0.2, 4.0])
    steps = 20
    r = rd.simulate(rd.Particle(2.0), rd.ParticleState(p0, v0), 0.1, steps, method=method,
                    loads=rd.AppliedLoad(force=f), gravity=True)
    a = f / 2.0 + GRAVITY
    rec, work = r.body(0), r.work.sum(axis=1)
    # exact in exact arithmetic; round-off: <= 4 roundings per step of numbers <= max(|p|, |v|)
    size = max(np.abs(rec.p_W).max(), np.abs(rec.v_W).max())
    np.testing.assert_allclose(rec.p_W[-1], p0 + 2.0 * v0 + 2.0 * a, rtol=0, atol=4 * steps * EPS * size)
    np.testing.assert_allclose(rec.v_W[-1], v0 + 2.0 * a, rtol=0, atol=4 * steps * EPS * size)
    # work-energy is exact for these steps; each step rounds the work sum and its term, T rounds 4x
    np.testing.assert_allclose(work[-1], r.kinetic_energy[-1] - r.kinetic_energy[0], rtol=0,
                               atol=(2 * steps + 4) * EPS * max(r.kinetic_energy.max(), np.abs(work).max()))


# sum of the squared sub-step fractions of one step (Yoshida: 2 g1^2 + g0^2), for O(h^2) terms
SQUARED_FRACTIONS = {"splitting_dlm": 1.0, "exact_flow_kick": 1.0,
                     "splitting_dlm_yoshida4": 2 * ref.YOSHIDA_GAMMA1**2 + ref.YOSHIDA_GAMMA0**2}


@pytest.mark.parametrize("method", ["splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"])
def test_planar_body_equals_rigid_body_kept_in_plane(method):
    f_W, f_B, n_W, n_B = [0.5, -1.0, 0.0], [1.0, 0.4, 0.0], [0, 0, 0.3], [0, 0, -0.1]
    loads = [rd.AppliedLoad(force=f_W, torque=n_W), rd.AppliedLoad(force=f_B, torque=n_B, frame="body")]
    planar, spatial = planar_and_rigid_runs(method, loads)
    h, steps = np.diff(spatial.t)[0], len(spatial.t) - 1
    # one motion, two code paths: both round each step (local_roundoff each), and a difference
    # grows by at most 1 + t + |f_B| t^2/m <= 3 over t = 1 s (theta turns the body force, omega
    # turns theta; p, v, omega enter linearly)
    planar_work, spatial_work = planar.work.sum(axis=1), spatial.work.sum(axis=1)
    for name in ["p_W", "q_WB", "v_W", "w_B", "kinetic_energy"]:
        got, want = (getattr(run if name == "kinetic_energy" else run.body(0), name) for run in (planar, spatial))
        tol = steps * 2 * local_roundoff(method) * 3 * max(1.0, np.abs(want).max())
        np.testing.assert_allclose(got, want, rtol=0, atol=tol, err_msg=name)
    # the rigid body's kicks book exactly the kinetic-energy change they make: round-off of the
    # work sum (2 roundings per step) and of T (4)
    size = max(spatial.kinetic_energy.max(), np.abs(spatial_work).max())
    np.testing.assert_allclose(spatial.kinetic_energy - spatial.kinetic_energy[0], spatial_work, rtol=0,
                               atol=(2 * steps + 4) * EPS * size)
    # the planar drift books h f(theta0).v_half instead: per (sub)step of tau the two differ by
    # (tau^2/2) (w x f_B).v (the body force turns; not telescoping) plus (tau^2/8) (f.a + n alpha) at
    # both ends of the step (telescoping): summed over the run, with Yoshida's fractions
    speed, turn = np.abs(spatial.body(0).v_W).max(), np.abs(spatial.body(0).w_B).max()
    force = np.linalg.norm(f_W) + np.linalg.norm(f_B) + 2.0 * 9.81  # m = 2 kg
    accel = force / 2.0 + 0.4 / 0.7  # |f|/m + |n|/I_zz
    bound = SQUARED_FRACTIONS[method] * (0.5 * h * h * steps * turn * np.linalg.norm(f_B) * speed
                                         + 0.25 * h * h * force * accel)
    np.testing.assert_allclose(planar_work, spatial_work, rtol=0, atol=bound)
