"""Dynamics, integrators and simulate: orders against SciPy DOP853, model equivalences, invariants,
work-energy, impulses, inverse dynamics and bad inputs."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

import rigiddyn as rd
from _error_bounds import EPS, local_roundoff, roundoff
from _helpers import planar_and_rigid_runs

# the classical methods (the structure-preserving ones are tested with the exact solution)
METHODS = ["explicit_euler", "semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic", "rk4", "rkmk4"]
ORDER = {m["name"]: m["order"] for m in rd.methods()}

# A body with products of inertia (full Euler form), a generic initial state and constant loads
# of every kind (world force, body force, world torque, body torque) plus gravity.
MASS = 2.5
INERTIA = np.array([[0.9, 0.05, -0.1], [0.05, 1.4, 0.08], [-0.1, 0.08, 1.9]])
Q0 = Rotation.from_rotvec([0.3, -0.5, 0.8]).as_quat()
LOADS = [
    rd.AppliedLoad(force=[0.4, -0.2, 1.0], torque=[0.05, 0.1, -0.2], frame="world"),
    rd.AppliedLoad(force=[0.3, 0.1, -0.2], torque=[-0.1, 0.2, 0.15], frame="body"),
]
GRAVITY = np.array([0.0, 0.0, -9.81])


def initial_state():
    return rd.RigidBodyState(p_W=[0.1, -0.2, 0.3], q_WB=Q0, v_W=[0.5, 0.2, -0.1], w_B=[1.2, -0.7, 2.0])


def rigid_body_rhs(t, y):
    """Independent Newton-Euler right-hand side on (p, q xyzw, v, w) for SciPy (Craig)."""
    q, v, w = y[3:7], y[7:10], y[10:13]
    R = Rotation.from_quat(q / np.linalg.norm(q)).as_matrix()
    f_W = LOADS[0].force + R @ LOADS[1].force + MASS * GRAVITY
    tau_B = R.T @ LOADS[0].torque + LOADS[1].torque
    w_dot = np.linalg.solve(INERTIA, tau_B - np.cross(w, INERTIA @ w))
    x, yq, z, s = q
    # q_dot = 1/2 q (x) (w, 0), Hamilton product written out
    q_dot = 0.5 * np.array([
        s * w[0] + yq * w[2] - z * w[1],
        s * w[1] + z * w[0] - x * w[2],
        s * w[2] + x * w[1] - yq * w[0],
        -(x * w[0] + yq * w[1] + z * w[2]),
    ])
    return np.concatenate([v, q_dot, f_W / MASS, w_dot])


def reference(T):
    s = initial_state()
    y0 = np.concatenate([s.p_W, s.q_WB, s.v_W, s.w_B])
    sol = solve_ivp(rigid_body_rhs, (0.0, T), y0, method="DOP853", rtol=1e-12, atol=1e-12)
    return sol.y[:, -1]


def rigid_body_error(result, y_ref):
    result = result.body(0)
    q = result.q_WB[-1]
    angle = (Rotation.from_quat(y_ref[3:7]).inv() * Rotation.from_quat(q)).magnitude()
    return max(np.abs(result.p_W[-1] - y_ref[0:3]).max(), angle,
               np.abs(result.v_W[-1] - y_ref[7:10]).max(), np.abs(result.w_B[-1] - y_ref[10:13]).max())


def observed_order(steps, errors, T):
    h = T / np.asarray(steps, dtype=float)
    return np.polyfit(np.log(h), np.log(errors), 1)[0]


@pytest.mark.parametrize("method", METHODS)
def test_order_rigid_body_against_dop853(method):
    T = 1.0
    y_ref = reference(T)
    body = rd.RigidBody(MASS, INERTIA)
    assert body.euler_form == "full"
    steps = [16, 32, 64, 128] if ORDER[method] == 4 else [200, 400, 800, 1600]
    errors = []
    for n in steps:
        res = rd.simulate(body, initial_state(), T / n, n, method=method, record_every=n,
                          loads=LOADS, gravity=GRAVITY)
        errors.append(rigid_body_error(res, y_ref))
    # the fitted slope moves by the next term of the expansion, O(h |w|) <= 0.03 relative at these
    # steps, and by DOP853's own error at 1e-12 (~1e-12, <= |y(1e-12) - y(1e-13)|), 100x below the
    # smallest error fitted: far inside 0.2
    assert abs(observed_order(steps, errors, T) - ORDER[method]) < 0.2, errors


def planar_rhs(t, y, m, I, f_W, f_B, n, g):
    c, s = math.cos(y[2]), math.sin(y[2])
    f = f_W + np.array([c * f_B[0] - s * f_B[1], s * f_B[0] + c * f_B[1]]) + m * g
    return np.array([y[3], y[4], y[5], f[0] / m, f[1] / m, n / I])


@pytest.mark.parametrize("method", METHODS)
def test_order_planar_body_against_dop853(method):
    m, I, T = 1.5, 0.4, 2.0
    f_W, f_B, n, g = np.array([0.3, -0.1]), np.array([1.0, 0.5]), 0.7, np.array([0.0, -9.81])
    loads = [rd.AppliedLoad(force=[*f_W, 0], torque=[0, 0, n], frame="world"),
             rd.AppliedLoad(force=[*f_B, 0], frame="body")]
    y0 = np.array([0.1, 0.2, 0.3, -0.4, 0.5, 1.3])
    y_ref = solve_ivp(planar_rhs, (0, T), y0, args=(m, I, f_W, f_B, n, g), method="DOP853",
                      rtol=1e-12, atol=1e-12).y[:, -1]
    body = rd.PlanarBody(m, I)
    state = rd.PlanarBodyState(p_W=y0[0:2], theta=y0[2], v_W=y0[3:5], omega=y0[5])
    steps = [16, 32, 64, 128] if ORDER[method] == 4 else [200, 400, 800, 1600]
    errors = []
    for k in steps:
        res = rd.simulate(body, state, T / k, k, method=method, record_every=k, loads=loads,
                          gravity=[0, -9.81, 0]).body(0)
        theta = 2 * math.atan2(res.q_WB[-1, 2], res.q_WB[-1, 3])
        errors.append(max(np.abs(res.p_W[-1, :2] - y_ref[0:2]).max(), abs(math.remainder(theta - y_ref[2], 2 * math.pi)),
                          np.abs(res.v_W[-1, :2] - y_ref[3:5]).max(), abs(res.w_B[-1, 2] - y_ref[5])))
    # as for the rigid body: the next term O(h |w|) and DOP853's ~1e-12 move the slope far less than 0.2
    assert abs(observed_order(steps, errors, T) - ORDER[method]) < 0.2, errors


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("method", METHODS)
def test_particle_equals_non_rotating_rigid_body(method):
    loads = [rd.AppliedLoad(force=[0.5, -1.0, 2.0], t_end=0.25), rd.AppliedLoad(force=[-1.0, 0.2, 0.3], t_start=0.25)]
    p0, v0 = [1.0, 2.0, 3.0], [0.3, -0.2, 4.0]
    a = rd.simulate(rd.Particle(3.0), rd.ParticleState(p0, v0), 0.01, 50, method=method, loads=loads, gravity=True)
    b = rd.simulate(rd.RigidBody(3.0, np.diag([1.0, 2.0, 2.5])), rd.RigidBodyState(p_W=p0, v_W=v0), 0.01, 50,
                    method=method, loads=loads, gravity=True)
    # one template integrator on the same translation arithmetic (f/m + g, the same sums): equal to
    # within a rounding or two of each value (45 eps relative)
    for name in ["t", "p_W", "v_W", "w_B", "kinetic_energy", "total_energy", "work"]:
        np.testing.assert_allclose(getattr(a, name), getattr(b, name), rtol=1e-14, atol=1e-14, err_msg=name)
    np.testing.assert_allclose(b.body(0).q_WB, np.tile([0, 0, 0, 1.0], (len(b.t), 1)), atol=0)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("method", METHODS)
def test_planar_body_equals_rigid_body_kept_in_plane(method):
    loads = [rd.AppliedLoad(force=[0.5, -1.0, 0.0], torque=[0, 0, 0.3]),
             rd.AppliedLoad(force=[1.0, 0.4, 0.0], torque=[0, 0, -0.1], frame="body", t_start=0.1)]
    planar, spatial = planar_and_rigid_runs(method, loads)
    # exponential attitude updates (semi-implicit Euler, RKMK4) turn theta exactly as the planar
    # body does: round-off only (local_roundoff per side and step); the quaternion-as-4-vector methods
    # differ from the angle form by their phase error per step, at e = i h w/2 the missing terms of
    # e^e: explicit Euler (h w)^3/12, RK4 (h w)^5/1920; a difference grows by <= 3 over 1 s (theta
    # turns the body force: 1 + t + |f_B| t^2/m)
    h, w_max = np.diff(spatial.t)[0], np.abs(spatial.w_B).max()
    phase = {"rk4": (h * w_max) ** 5 / 1920, "explicit_euler": (h * w_max) ** 3 / 12}.get(method, 0.0)
    tol = (len(spatial.t) - 1) * (2 * local_roundoff(method) + phase) * 3
    for name in ["p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "work"]:
        np.testing.assert_allclose(getattr(planar, name), getattr(spatial, name), rtol=0,
                                   atol=tol * max(1.0, np.abs(getattr(spatial, name)).max()), err_msg=name)


def free_spin(method, dt, steps, w_B=(0.2, 3.0, 0.3)):
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    return rd.simulate(body, rd.RigidBodyState(w_B=w_B), dt, steps, method=method)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
def test_torque_free_explicit_euler_gains_energy_and_momentum():
    r = free_spin("explicit_euler", 0.01, 2000)
    # exact property: |w + h w'|^2 grows by h^2 |w'|^2 ~ 1e-4 per step, far above round-off
    assert np.all(np.diff(r.kinetic_energy) > 0) and np.all(np.diff(r.body(0).angular_momentum_norm) > 0)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
def test_torque_free_semi_implicit_euler_explicit_gyroscopic_gains_energy():
    r = free_spin("semi_implicit_euler", 0.01, 2000)
    assert r.kinetic_energy[-1] > r.kinetic_energy[0] * (1 + 1e-3)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
def test_semi_implicit_euler_explicit_gyroscopic_blows_up_on_fast_spin():
    with pytest.warns(RuntimeWarning, match="non-finite"):
        r = free_spin("semi_implicit_euler", 0.1, 2000, w_B=(0.5, 20.0, 0.5))
    assert r.diverged


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
def test_implicit_gyroscopic_is_dissipative():
    # h |w| = 0.3: the energy decays monotonically (where the explicit term blows up)
    r = free_spin("semi_implicit_euler_implicit_gyroscopic", 0.1, 2000)
    # each step loses O(h^2) energy; round-off of T is <= 4 eps T, far below 1e-12 T
    assert np.all(np.diff(r.kinetic_energy) <= 1e-12 * r.kinetic_energy[0])
    assert r.kinetic_energy[-1] < 0.5 * r.kinetic_energy[0]
    np.testing.assert_array_less(np.abs(r.body(0).quaternion_norm_error), 1e-14)  # exact unit update: ~2 eps
    with pytest.warns(RuntimeWarning, match="non-finite"):
        assert free_spin("semi_implicit_euler", 0.1, 2000).diverged


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
def test_implicit_gyroscopic_stays_finite_on_fast_spin():
    # h |w| = 2 about the intermediate axis: bounded (energy may grow transiently), no blow-up
    r = free_spin("semi_implicit_euler_implicit_gyroscopic", 0.1, 2000, w_B=(0.5, 20.0, 0.5))
    assert not r.diverged and np.all(np.isfinite(r.w_B))
    assert r.kinetic_energy.max() < 1e4 * r.kinetic_energy[0]


@pytest.mark.parametrize("method", ["rk4", "rkmk4"])
def test_fourth_order_methods_keep_invariants_closely(method):
    r = free_spin(method, 0.001, 5000)
    # each step changes a quadratic invariant by its local error, ~(h |w|)^5/120 = 2e-15 at h|w| = 3e-3,
    # over 5000 steps 1e-11, plus round-off (<= 4 eps per step: 4e-12)
    assert np.ptp(r.kinetic_energy) / r.kinetic_energy[0] < 1e-10
    rec = r.body(0)
    assert np.ptp(rec.angular_momentum_norm) / rec.angular_momentum_norm[0] < 1e-10
    np.testing.assert_array_less(np.abs(rec.quaternion_norm_error), 1e-14)  # renormalised: ~2 eps
    np.testing.assert_allclose(r.work, 0.0, atol=0)


@pytest.mark.parametrize("method", METHODS)
def test_sphere_has_no_gyroscopic_term(method):
    body = rd.RigidBody(1.0, 0.4 * np.eye(3))
    assert body.euler_form == "spherical"
    r = rd.simulate(body, rd.RigidBodyState(w_B=[1.0, -2.0, 0.5]), 0.01, 100, method=method)
    # no gyroscopic term, no torque: every method adds exactly zero to w
    np.testing.assert_allclose(r.body(0).w_B, np.tile([1.0, -2.0, 0.5], (101, 1)), rtol=0, atol=1e-15)


@pytest.mark.parametrize("method", ["rk4", "rkmk4"])
def test_work_energy(method):
    body = rd.RigidBody(MASS, INERTIA)
    r = rd.simulate(body, initial_state(), 1e-3, 1000, method=method, record_every=100, loads=LOADS, gravity=GRAVITY)
    # T2 - T1 = U12 (Craig), the work integrated alongside by the same method: T - W is an
    # invariant of the ODE, which the method changes by its local error, ~(h |w|)^5/120 T per step,
    # and by round-off, 2 roundings per step of numbers <= max T (worst case linear)
    steps, w_max = 1000, np.abs(r.w_B).max()
    trunc = steps * (1e-3 * w_max) ** 5 / 120 * r.kinetic_energy.max()
    np.testing.assert_allclose(r.kinetic_energy - r.kinetic_energy[0], r.work.sum(axis=1), rtol=0,
                               atol=trunc + roundoff(r.kinetic_energy.max(), 2 * steps))
    # gravity alone: total energy conserved (ballistic part exact, rotation as above)
    g = rd.simulate(body, initial_state(), 1e-3, 1000, method=method, gravity=True)
    size = np.abs(g.total_energy).max() + np.abs(g.kinetic_energy).max()
    np.testing.assert_allclose(g.total_energy, g.total_energy[0], rtol=0, atol=trunc + roundoff(size, 2 * steps))


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("method", ["semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic"])
def test_work_energy_first_order_methods(method):
    body = rd.RigidBody(MASS, INERTIA)
    gaps = []
    for dt in (2e-3, 1e-3):
        r = rd.simulate(body, initial_state(), dt, round(1.0 / dt), method=method, loads=LOADS, gravity=GRAVITY)
        gaps.append(abs(r.kinetic_energy[-1] - r.kinetic_energy[0] - r.work[-1].sum()))
    assert gaps[1] < 0.6 * gaps[0]  # the mismatch is the method's O(h) error: halves, to O(h) relative


def test_piecewise_constant_schedule_switches_on_the_step_grid():
    particle = rd.Particle(2.0)
    loads = [rd.AppliedLoad(force=[4.0, 0, 0], t_start=0.0, t_end=0.5),
             rd.AppliedLoad(force=[0, -2.0, 0], t_start=0.5)]
    r = rd.simulate(particle, rd.ParticleState(), 0.1, 10, method="rk4", loads=loads).body(0)
    # v = (2 t, 0, 0) up to 0.5 s, then -1 m/s^2 along y; rk4 is exact for constant acceleration:
    # round-off of 10 steps on numbers <= 1
    np.testing.assert_allclose(r.v_W[-1], [1.0, -0.5, 0.0], atol=1e-14)
    np.testing.assert_allclose(r.p_W[-1], [0.25 + 0.5, -0.125, 0.0], atol=1e-14)


def test_record_every_keeps_first_and_last():
    r = free_spin("rk4", 0.01, 25)
    assert len(r.t) == 26
    r = rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.01, 25, record_every=10).body(0)
    np.testing.assert_allclose(r.t, [0.0, 0.1, 0.2, 0.25], rtol=4 * EPS)  # k dt, rounded once or twice
    assert r.q_WB.shape == (4, 4) and r.p_W.shape == (4, 3)


def test_scalar_first_quaternions():
    s = rd.RigidBodyState(q_WB=[math.cos(0.2), 0, math.sin(0.2), 0], scalar_first=True, w_B=[0, 1.0, 0])
    # unit already: renormalising moves it by <= 2 eps
    np.testing.assert_allclose(s.q_WB, [0, math.sin(0.2), 0, math.cos(0.2)], rtol=0, atol=4 * EPS)
    a = rd.simulate(rd.RigidBody(1.0, np.eye(3)), s, 0.1, 3, scalar_first=True).body(0)
    b = rd.simulate(rd.RigidBody(1.0, np.eye(3)), s, 0.1, 3).body(0)
    np.testing.assert_array_equal(a.q_WB, b.q_WB[:, [3, 0, 1, 2]])  # one run, two layouts of the same doubles


# step of a body is one step of the layout simulate runs for its one-body scene: every kind (a rigid body of each
# Euler form), every element set the scene declares, a load switching on inside the step, every method
STEP_BODIES = {
    "particle": (rd.Particle(MASS), rd.ParticleState(p_W=[0.1, -0.2, 0.3], v_W=[0.5, 0.2, -0.1])),
    "planar": (rd.PlanarBody(MASS, 0.7), rd.PlanarBodyState(p_W=[0.1, -0.2], theta=0.4, v_W=[0.5, 0.2], omega=1.3)),
    "rigid spherical": (rd.RigidBody(MASS, np.eye(3)), initial_state()),
    "rigid principal": (rd.RigidBody(MASS, np.diag([0.9, 1.4, 1.9])), initial_state()),
    "rigid full": (rd.RigidBody(MASS, INERTIA), initial_state()),
}
STEP_LOADS = {  # the loads each kind takes (a particle no torque, a planar body in its plane)
    "particle": [rd.AppliedLoad(force=[0.4, -0.2, 1.0]), rd.AppliedLoad(force=[0.3, 0.1, -0.2], t_start=0.0123)],
    "planar": [rd.AppliedLoad(force=[0.4, -0.2, 0.0], torque=[0.0, 0.0, 0.2]),
               rd.AppliedLoad(force=[0.3, 0.1, 0.0], torque=[0.0, 0.0, -0.1], frame="body", t_start=0.0123)],
    "rigid": [LOADS[0], rd.AppliedLoad(force=[0.3, 0.1, -0.2], torque=[-0.1, 0.2, 0.15], frame="body", t_start=0.0123)],
}
STEP_CASES = [(kind, elements) for kind in STEP_BODIES for elements in ("none", "gravity", "gravity and loads")]


@pytest.mark.parametrize("method", [m["name"] for m in rd.methods()])
@pytest.mark.parametrize(("kind", "elements"), STEP_CASES, ids=[f"{k}-{e}" for k, e in STEP_CASES])
def test_step_is_bitwise_the_first_step_of_simulate(kind, elements, method):
    body, state = STEP_BODIES[kind]
    gravity = {"none": None, "gravity": [0.0, -9.81, 0.0]}.get(elements, [0.3, -9.81, 0.0])
    loads = STEP_LOADS[kind.split()[0]] if elements == "gravity and loads" else None
    if method == "exact" and loads is not None and kind.startswith("rigid"):  # the free rotation takes no torque
        with pytest.raises(ValueError, match="torque-free"):
            rd.step(body, state, 0.01, method=method, loads=loads, gravity=gravity, t=0.01)
        return
    # from t = 0.01 the second load switches on at 0.0123, inside the step to 0.02: both split the step there
    s1, t1 = rd.step(body, state, 0.01, method=method, loads=loads, gravity=gravity, t=0.01)
    r = rd.simulate(body, state, 0.01, 1, method=method, loads=loads, gravity=gravity, t0=0.01, error=False, accuracy_level=None)
    assert t1 == r.t[-1]
    record = r.body(0)
    names = {"particle": ["p_W", "v_W"], "planar": ["p_W", "v_W"]}.get(kind, ["p_W", "q_WB", "v_W", "w_B"])
    for name in names:
        # the state's own columns of the record (a planar body's in W: its x, y and their rates)
        expected = getattr(record, name)[-1][: len(getattr(s1, name))]
        if method == "exact":
            # simulate evaluates the closed form, step composes the exact free flow with exact kicks (exact for a
            # constant force and torque about a fixed axis): equal but for the rounding of a few operations on
            # values of size |x| + |v| dt + |g| dt² ≤ 1: 8 eps
            np.testing.assert_allclose(getattr(s1, name), expected, rtol=0, atol=8 * EPS, err_msg=name)
        else:
            np.testing.assert_array_equal(getattr(s1, name), expected, err_msg=name)


# step of a scene runs the model simulate runs: a one-body scene's layout, a pivoted body's fast model, the scene
# model for two bodies; its step is bitwise simulate's first step (implicit midpoint included)
STEP_SCENES = {
    "layout": (rd.Scene([rd.RigidBody(MASS, INERTIA)], elements=[rd.UniformGravity(), rd.ScheduledLoads(body=0, loads=LOADS)]),
               [initial_state()]),
    "fast model": (rd.Scene([rd.PivotedBody(rd.RigidBody(MASS, INERTIA), [0.0, 0.0, -0.3])], elements=[rd.UniformGravity()]),
                   [rd.PivotedBodyState(q_WB=Q0, w_B=[1.2, -0.7, 2.0])]),
    "scene model": (rd.Scene([rd.RigidBody(MASS, INERTIA), rd.Particle(1.0)], elements=[rd.UniformGravity()]),
                    [initial_state(), rd.ParticleState(v_W=[0.1, 0.0, 0.0])]),
}


@pytest.mark.parametrize("method", [m["name"] for m in rd.methods() if m["name"] != "exact"])
@pytest.mark.parametrize("model", STEP_SCENES)
def test_step_of_a_scene_is_bitwise_the_first_step_of_simulate(model, method):
    scene, state = STEP_SCENES[model]
    compiled = rd.CompiledScene(scene, method)
    after = rd.step(compiled, state, 0.01)
    r = rd.simulate(compiled, state, 0.01, 1, error=False, accuracy_level=None)
    for i, body_state in enumerate(after):
        for name in ("q_WB", "v_W", "w_B"):  # those of the body's state (a particle has v_W alone)
            if hasattr(body_state, name):
                np.testing.assert_array_equal(getattr(body_state, name), getattr(r, name)[-1, i], err_msg=name)


def _load(**fields):
    return rd.AppliedLoad(**{"force": [0.4, -0.2, 1.0], "torque": [0.05, 0.1, -0.2], "t_end": 0.005, **fields})


# step keeps the last layout it built on this thread; a call whose body, gravity or loads differ in any number the
# layout is made of must step its own (each case differs from BASE in one of them)
STEP_BASE = {"model": rd.RigidBody(MASS, INERTIA), "gravity": [0.0, 0.0, -9.81], "loads": [_load()]}
STEP_CHANGED = {
    "mass": {"model": rd.RigidBody(2 * MASS, INERTIA)},
    "inertia": {"model": rd.RigidBody(MASS, INERTIA + 0.1 * np.eye(3))},
    "gravity": {"gravity": [0.0, 0.0, -1.62]},
    "no gravity": {"gravity": None},
    "force": {"loads": [_load(force=[0.4, -0.2, 2.0])]},
    "torque": {"loads": [_load(torque=[0.05, 0.1, -0.4])]},
    "frame": {"loads": [_load(frame="body")]},
    "t_start": {"loads": [_load(t_start=0.002)]},
    "t_end": {"loads": [_load(t_end=0.008)]},
    "a second load": {"loads": [_load(), _load(t_end=math.inf)]},
    "no loads": {"loads": None},
}


@pytest.mark.parametrize("change", STEP_CHANGED)
def test_step_after_a_step_of_other_inputs_steps_its_own(change):
    case = {**STEP_BASE, **STEP_CHANGED[change]}
    rd.step(state=initial_state(), dt=0.01, t=0.0, **STEP_BASE)  # the layout of BASE kept
    s1, _ = rd.step(state=initial_state(), dt=0.01, t=0.0, **case)
    r = rd.simulate(case["model"], initial_state(), 0.01, 1, loads=case["loads"], gravity=case["gravity"], error=False,
                    accuracy_level=None).body(0)
    for name in ["p_W", "q_WB", "v_W", "w_B"]:  # bitwise: step is simulate's first step (above)
        np.testing.assert_array_equal(getattr(s1, name), getattr(r, name)[-1], err_msg=name)
    # and BASE again after it: its own step, not the case's
    again, _ = rd.step(state=initial_state(), dt=0.01, t=0.0, **STEP_BASE)
    fresh = rd.simulate(STEP_BASE["model"], initial_state(), 0.01, 1, loads=STEP_BASE["loads"],
                        gravity=STEP_BASE["gravity"], error=False, accuracy_level=None).body(0)
    np.testing.assert_array_equal(again.w_B, fresh.w_B[-1])
    np.testing.assert_array_equal(again.v_W, fresh.v_W[-1])


# --- dynamics functions ---------------------------------------------------------------------

def random_state(rng):
    return rd.RigidBodyState(p_W=rng.normal(size=3), q_WB=Rotation.random(random_state=rng).as_quat(),
                             v_W=rng.normal(size=3), w_B=rng.normal(size=3))


@pytest.mark.parametrize("seed", range(20))
def test_inverse_dynamics_undoes_forward(seed):
    rng = np.random.default_rng(seed)
    body = rd.RigidBody(1.7, INERTIA)
    state = random_state(rng)
    f, n, point = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
    for frame in ("world", "body"):
        a_W, alpha_B = rd.forward_dynamics(body, state, force=f, torque=n, point=point, frame=frame, gravity=True)
        f_W, tau_B = rd.inverse_dynamics(body, state, a_W, alpha_B, gravity=True)
        R = Rotation.from_quat(state.q_WB).as_matrix()
        f_expected = f if frame == "world" else R @ f
        n_G = n + np.cross(point, f)
        n_expected = R.T @ n_G if frame == "world" else n_G
        # forward then inverse: a solve with I (kappa <= 3) and terms <= |w| |I w| + |n| ~ 30 (normal
        # inputs), a few dozen roundings: 30 kappa 30 eps = 6e-13
        np.testing.assert_allclose(f_W, f_expected, atol=1e-12)
        np.testing.assert_allclose(tau_B, n_expected, atol=1e-12)


def test_forward_dynamics_matches_euler_equations():
    body = rd.RigidBody(2.0, np.diag([1.0, 2.0, 3.0]))
    state = rd.RigidBodyState(w_B=[1.0, 2.0, 3.0])
    a_W, alpha_B = rd.forward_dynamics(body, state, torque=[1.0, 0, 0], frame="body", gravity=True)
    # I1 w1' = n1 + (I2 - I3) w2 w3 and cyclic (principal axes)
    # small integers: exact but for 2/3 (one rounding)
    np.testing.assert_allclose(alpha_B, [(1.0 + (2 - 3) * 6) / 1, (3 - 1) * 3 / 2, (1 - 2) * 2 / 3], atol=1e-14)
    np.testing.assert_array_equal(a_W, [0, 0, -9.81])  # gravity alone: copied


@pytest.mark.parametrize("seed", range(20))
def test_impulse_changes_momentum_by_the_impulse(seed):
    rng = np.random.default_rng(100 + seed)
    body = rd.RigidBody(1.3, INERTIA)
    state = random_state(rng)
    J, point, origin = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
    R = Rotation.from_quat(state.q_WB).as_matrix()
    for frame, J_W, p_GP_W in (("world", J, point), ("body", R @ J, R @ point)):
        after = rd.apply_impulse(body, state, J, point=point, frame=frame)
        # m (v + J/m) - m v and the moments of it: a few roundings of numbers <= 20 (normal inputs, m 1.3)
        np.testing.assert_allclose(rd.linear_momentum(body, after) - rd.linear_momentum(body, state), J_W, atol=1e-12)
        # about any point O fixed in W: dH_O = (p_P - p_O) x J with p_P = p_G + p_GP
        dH = rd.angular_momentum(body, after, point=origin) - rd.angular_momentum(body, state, point=origin)
        np.testing.assert_allclose(dH, np.cross(state.p_W + p_GP_W - origin, J_W), atol=1e-12)
        np.testing.assert_array_equal(after.p_W, state.p_W)
        np.testing.assert_array_equal(after.q_WB, state.q_WB)


def test_momentum_energy_power():
    body = rd.RigidBody(2.0, np.diag([1.0, 2.0, 3.0]))
    q = Rotation.from_rotvec([0, 0, math.pi / 2]).as_quat()
    state = rd.RigidBodyState(p_W=[1.0, 0, 2.0], q_WB=q, v_W=[0, 3.0, 0], w_B=[1.0, 0, 0])
    np.testing.assert_array_equal(rd.linear_momentum(body, state), [0, 6.0, 0])  # small integers: exact
    # H_G = R I w = Rz(90 deg) (1, 0, 0) = (0, 1, 0); about the origin (the default) add
    # p x m v = (1,0,2) x (0,6,0) (cos 90 deg rounds to 6e-17: the only inexact entry)
    np.testing.assert_allclose(rd.angular_momentum(body, state, point=state.p_W), [0, 1.0, 0], atol=1e-15)
    np.testing.assert_allclose(rd.angular_momentum(body, state, point=[0, 0, 0]), [-12.0, 1.0, 6.0], atol=1e-15)
    np.testing.assert_array_equal(rd.angular_momentum(body, state), rd.angular_momentum(body, state, point=[0, 0, 0]))
    T = rd.kinetic_energy(body, state)
    # small integers and halves: exact but for the rotation's 6e-17 entries (one rounding each)
    assert (T.translational, T.rotational, T.total) == pytest.approx((9.0, 0.5, 9.5), rel=4 * EPS, abs=0)
    assert rd.potential_energy(body, state) == 0.0  # no gravity unless asked
    assert rd.potential_energy(body, state, gravity=True) == pytest.approx(2.0 * 9.81 * 2.0, rel=4 * EPS, abs=0)  # m g.p: 2 roundings
    assert rd.power(state, [0, 1.0, 0], [2.0, 0, 0]) == pytest.approx(3.0 + 2.0, rel=4 * EPS, abs=0)


# --- particle and planar body: the same dynamics functions ------------------------------------

def planar_as_spatial(planar_state):
    """The spatial state of a planar state: p = (x, y, 0), q = Rz(theta), v = (vx, vy, 0), w_B = (0, 0, omega)."""
    return rd.RigidBodyState(p_W=[*planar_state.p_W, 0.0],
                             q_WB=Rotation.from_rotvec([0, 0, planar_state.theta]).as_quat(),
                             v_W=[*planar_state.v_W, 0.0], w_B=[0.0, 0.0, planar_state.omega])


def random_planar_state(rng):
    return rd.PlanarBodyState(p_W=rng.normal(size=2), theta=rng.uniform(-math.pi, math.pi), v_W=rng.normal(size=2),
                              omega=rng.normal())


@pytest.mark.parametrize("seed", range(10))
def test_particle_inverse_dynamics_undoes_forward(seed):
    rng = np.random.default_rng(200 + seed)
    particle = rd.Particle(1.9)
    state = rd.ParticleState(p_W=rng.normal(size=3), v_W=rng.normal(size=3))
    f, g = rng.normal(size=3), rng.normal(size=3)
    a_W = rd.forward_dynamics(particle, state, force=f, gravity=g)
    # Newton, m a = f + m g: 2 roundings of numbers <= 5 (normal inputs); and back: 1.9 x that
    np.testing.assert_allclose(a_W, f / 1.9 + g, atol=1e-14)
    np.testing.assert_allclose(rd.inverse_dynamics(particle, state, a_W, gravity=g), f, atol=1e-13)


@pytest.mark.parametrize("seed", range(10))
def test_particle_impulse_changes_momentum_by_the_impulse(seed):
    rng = np.random.default_rng(300 + seed)
    particle = rd.Particle(0.7)
    state = rd.ParticleState(p_W=rng.normal(size=3), v_W=rng.normal(size=3))
    J, origin = rng.normal(size=3), rng.normal(size=3)
    after = rd.apply_impulse(particle, state, J)
    # m (v + J/m) - m v: 3 roundings of numbers <= 4 (normal inputs, m 0.7); moments: x |r| <= 8
    np.testing.assert_allclose(rd.linear_momentum(particle, after) - rd.linear_momentum(particle, state), J, atol=1e-14)
    dH = rd.angular_momentum(particle, after, point=origin) - rd.angular_momentum(particle, state, point=origin)
    np.testing.assert_allclose(dH, np.cross(state.p_W - origin, J), atol=1e-13)
    np.testing.assert_array_equal(after.p_W, state.p_W)


def test_particle_momentum_energy_power():
    particle = rd.Particle(2.0)
    state = rd.ParticleState(p_W=[1.0, 0, 2.0], v_W=[0, 3.0, 0])
    # small integers: exact
    np.testing.assert_array_equal(rd.linear_momentum(particle, state), [0, 6.0, 0])
    # about the world origin by default, H_O = p x m v (the notes' eq. (4.42)); about itself, zero
    np.testing.assert_array_equal(rd.angular_momentum(particle, state), [-12.0, 0, 6.0])
    np.testing.assert_array_equal(rd.angular_momentum(particle, state, point=[0, 0, 0]), [-12.0, 0, 6.0])
    np.testing.assert_array_equal(rd.angular_momentum(particle, state, point=state.p_W), [0, 0, 0])
    T = rd.kinetic_energy(particle, state)
    assert (T.translational, T.rotational, T.total) == (9.0, 0.0, 9.0)
    assert rd.potential_energy(particle, state) == 0.0  # no gravity unless asked
    assert rd.potential_energy(particle, state, gravity=True) == pytest.approx(2.0 * 9.81 * 2.0, rel=4 * EPS, abs=0)  # 2 roundings
    assert rd.power(state, [0, 1.0, 5.0]) == 3.0


def test_particle_equals_non_rotating_rigid_body_dynamics():
    particle, body = rd.Particle(1.5), rd.RigidBody(1.5, np.diag([0.3, 0.4, 0.5]))
    ps = rd.ParticleState(p_W=[0.3, -1.0, 2.0], v_W=[1.0, 2.0, -0.5])
    bs = rd.RigidBodyState(p_W=ps.p_W, v_W=ps.v_W)
    f, origin = np.array([0.2, -0.4, 1.0]), np.array([1.0, 1.0, -1.0])
    # the same translation arithmetic on the same doubles (<= 1 rounding apart)
    np.testing.assert_allclose(rd.forward_dynamics(particle, ps, force=f, gravity=True),
                               rd.forward_dynamics(body, bs, force=f, gravity=True)[0], atol=1e-15)
    np.testing.assert_allclose(rd.angular_momentum(particle, ps, point=origin),
                               rd.angular_momentum(body, bs, point=origin), atol=1e-15)
    assert rd.kinetic_energy(particle, ps).total == rd.kinetic_energy(body, bs).total
    assert rd.potential_energy(particle, ps, True) == rd.potential_energy(body, bs, True)
    assert rd.power(ps, f) == rd.power(bs, f, [0.0, 0.0, 0.0])


@pytest.mark.parametrize("seed", range(10))
def test_planar_inverse_dynamics_undoes_forward(seed):
    rng = np.random.default_rng(400 + seed)
    body = rd.PlanarBody(1.7, 0.6)
    state = random_planar_state(rng)
    f, n, point, g = rng.normal(size=2), rng.normal(), rng.normal(size=2), rng.normal(size=2)
    c, s = math.cos(state.theta), math.sin(state.theta)
    for frame, f_W in (("world", f), ("body", np.array([c * f[0] - s * f[1], s * f[0] + c * f[1]]))):
        a_W, alpha = rd.forward_dynamics(body, state, force=f, torque=n, point=point, frame=frame, gravity=g)
        f_back, n_back = rd.inverse_dynamics(body, state, a_W, alpha, gravity=g)
        # forward then inverse: a few roundings of numbers <= 15 (normal inputs, g, m 1.7): 16 eps 15
        np.testing.assert_allclose(f_back, f_W, atol=1e-13)
        # torque about G of the force at P (2-D cross product, frame independent) plus the applied torque
        assert n_back == pytest.approx(n + point[0] * f[1] - point[1] * f[0], abs=1e-13)


@pytest.mark.parametrize("seed", range(10))
def test_planar_impulse_changes_momentum_by_the_impulse(seed):
    rng = np.random.default_rng(500 + seed)
    body = rd.PlanarBody(1.3, 0.45)
    state = random_planar_state(rng)
    J, point, origin, angular = rng.normal(size=2), rng.normal(size=2), rng.normal(size=2), rng.normal()
    c, s = math.cos(state.theta), math.sin(state.theta)
    R = np.array([[c, -s], [s, c]])
    for frame, J_W, p_GP_W in (("world", J, point), ("body", R @ J, R @ point)):
        after = rd.apply_impulse(body, state, J, point=point, frame=frame, angular_impulse=angular)
        # as for the particle: a few roundings of numbers <= 10
        np.testing.assert_allclose(rd.linear_momentum(body, after) - rd.linear_momentum(body, state), J_W, atol=1e-13)
        # about any point O fixed in W: dH_O = (p_P - p_O) x J + angular impulse
        r = state.p_W + p_GP_W - origin
        dH = rd.angular_momentum(body, after, point=origin) - rd.angular_momentum(body, state, point=origin)
        assert dH == pytest.approx(r[0] * J_W[1] - r[1] * J_W[0] + angular, abs=1e-12)
        np.testing.assert_array_equal(after.p_W, state.p_W)
        assert after.theta == state.theta


@pytest.mark.parametrize("seed", range(10))
def test_planar_dynamics_equal_spatial_body_kept_in_plane(seed):
    rng = np.random.default_rng(600 + seed)
    planar = rd.PlanarBody(2.2, 0.8)
    spatial = rd.RigidBody(2.2, np.diag([0.5, 0.6, 0.8]))  # I_zz = 0.8 about the plane normal
    ps = random_planar_state(rng)
    bs = planar_as_spatial(ps)
    f, n, point, origin = rng.normal(size=2), rng.normal(), rng.normal(size=2), rng.normal(size=2)
    g = np.array([0.0, -9.81])
    for frame in ("world", "body"):
        a_W, alpha = rd.forward_dynamics(planar, ps, force=f, torque=n, point=point, frame=frame, gravity=g)
        a3, alpha3 = rd.forward_dynamics(spatial, bs, force=[*f, 0], torque=[0, 0, n], point=[*point, 0],
                                         frame=frame, gravity=[*g, 0])
        # planar and spatial formulas of one motion: a few roundings each of numbers <= 15 (g 9.81)
        np.testing.assert_allclose([*a_W, 0.0], a3, atol=1e-13)
        np.testing.assert_allclose([0.0, 0.0, alpha], alpha3, atol=1e-13)
        after, after3 = (rd.apply_impulse(planar, ps, f, point=point, frame=frame, angular_impulse=n),
                         rd.apply_impulse(spatial, bs, [*f, 0], point=[*point, 0], frame=frame,
                                          angular_impulse=[0, 0, n]))
        np.testing.assert_allclose([*after.v_W, 0.0, 0.0, 0.0, after.omega], [*after3.v_W, *after3.w_B], atol=1e-13)
    f_W, n_G = rd.inverse_dynamics(planar, ps, f, n, gravity=g)
    f3, n3 = rd.inverse_dynamics(spatial, bs, [*f, 0], [0, 0, n], gravity=[*g, 0])
    np.testing.assert_allclose([*f_W, 0.0, 0.0, 0.0, n_G], [*f3, *n3], atol=1e-13)
    np.testing.assert_allclose([*rd.linear_momentum(planar, ps), 0.0], rd.linear_momentum(spatial, bs), atol=1e-15)
    np.testing.assert_allclose([0.0, 0.0, rd.angular_momentum(planar, ps, point=origin)],
                               rd.angular_momentum(spatial, bs, point=[*origin, 0.0]), atol=1e-13)
    T, T3 = rd.kinetic_energy(planar, ps), rd.kinetic_energy(spatial, bs)
    assert (T.translational, T.rotational) == pytest.approx((T3.translational, T3.rotational), abs=1e-14)
    assert rd.potential_energy(planar, ps, g) == pytest.approx(rd.potential_energy(spatial, bs, [*g, 0]), abs=1e-13)
    assert rd.power(ps, f, n) == pytest.approx(rd.power(bs, [*f, 0], [0, 0, n]), abs=1e-14)


def test_planar_momentum_energy_closed_form():
    body = rd.PlanarBody(2.0, 0.5)
    state = rd.PlanarBodyState(p_W=[1.0, 2.0], theta=0.3, v_W=[3.0, 0.0], omega=4.0)
    np.testing.assert_array_equal(rd.linear_momentum(body, state), [6.0, 0.0])  # small integers: exact
    assert rd.angular_momentum(body, state, point=state.p_W) == 2.0  # about G: I_zz omega
    # about the origin (the default): I_zz omega + p x m v = 2 + (1 * 0 - 2 * 6), small integers: exact
    assert rd.angular_momentum(body, state, point=[0.0, 0.0]) == 2.0 - 12.0
    assert rd.angular_momentum(body, state) == 2.0 - 12.0
    assert rd.potential_energy(body, state) == 0.0  # no gravity unless asked
    T = rd.kinetic_energy(body, state)
    assert (T.translational, T.rotational) == (9.0, 4.0)
    assert rd.power(state, [1.0, 0.0], 0.5) == 3.0 + 2.0


def test_particle_planar_dynamics_bad_arguments():
    with pytest.raises(ValueError, match="^force"):
        rd.forward_dynamics(rd.Particle(1.0), rd.ParticleState(), force=[1.0, math.nan, 0])
    with pytest.raises(ValueError, match="^force"):
        rd.forward_dynamics(rd.PlanarBody(1.0, 1.0), rd.PlanarBodyState(), force=[1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="^frame"):
        rd.apply_impulse(rd.PlanarBody(1.0, 1.0), rd.PlanarBodyState(), [1.0, 0.0], frame="inertial")
    with pytest.raises(ValueError, match="^gravity"):
        rd.potential_energy(rd.PlanarBody(1.0, 1.0), rd.PlanarBodyState(), [0.0, 0.0, -9.81])


def test_rigid_body_inertia_check_is_the_inertia_layers():
    hlw = np.diag([2.0, 1.0, 2.0 / 3.0])  # Hairer-Lubich-Wanner's test body: 1 + 2/3 < 2, no real body
    with pytest.raises(ValueError, match="^inertia_com.*triangle") as body_error:
        rd.RigidBody(1.0, hlw)
    with pytest.raises(ValueError) as inertia_error:
        rd.SpatialInertia(1.0, [0, 0, 0], hlw)
    assert str(body_error.value) == str(inertia_error.value)  # one check, one message
    assert rd.RigidBody(1.0, hlw, check=rd.InertiaCheck.allow_unrealizable).euler_form == "principal"
    assert rd.RigidBody(1.0, hlw, rd.InertiaCheck.allow_unrealizable).euler_form == "principal"
    # one spelling: the older require_triangle_inequality flag (or a bool) is refused, naming check
    with pytest.raises(TypeError):
        rd.RigidBody(1.0, hlw, require_triangle_inequality=False)
    with pytest.raises(TypeError, match=r"^check: expected InertiaCheck\.physical or InertiaCheck\.allow_unrealizable"):
        rd.RigidBody(1.0, hlw, False)
    with pytest.raises(TypeError, match="^check"):
        rd.RigidBody(1.0, hlw, check="allow_unrealizable")
    # PSD but singular (a thin rod) passes the inertia layer, not Euler's equations
    with pytest.raises(ValueError, match="^inertia_com.*positive definite"):
        rd.RigidBody(1.0, np.diag([0.0, 1.0, 1.0]))


# --- metadata and bad inputs ------------------------------------------------------------------

def test_methods_metadata():
    table = {m["name"]: m for m in rd.methods()}
    assert set(METHODS) <= set(table)
    assert (table["rk4"]["order"], table["rk4"]["evaluations"]) == (4, 4)
    assert (table["explicit_euler"]["order"], table["explicit_euler"]["evaluations"]) == (1, 1)
    assert all(m["conserves"] and m["notes"] for m in table.values())


@pytest.mark.parametrize("kwargs, name", [
    ({"dt": 0.0}, "dt"), ({"dt": -1e-3}, "dt"), ({"dt": math.nan}, "dt"), ({"steps": -1}, "steps"),
    ({"record_every": 0}, "record_every"), ({"method": "rk5"}, "method"), ({"gravity": [0, 0]}, "gravity"),
    ({"gravity": [0, 0, math.inf]}, "gravity"),
])
def test_simulate_bad_arguments(kwargs, name):
    args = {"dt": 1e-3, "steps": 10}
    args.update(kwargs)
    with pytest.raises(ValueError, match=f"^{name}"):
        rd.simulate(rd.RigidBody(1.0, np.eye(3)), rd.RigidBodyState(), **args)


def test_bad_states_and_bodies():
    with pytest.raises(ValueError, match="^p_W"):
        rd.RigidBodyState(p_W=[0, math.nan, 0])
    with pytest.raises(ValueError, match="^w_B"):
        rd.RigidBodyState(w_B=[0, 1.0])
    with pytest.raises(ValueError, match="q_WB"):
        rd.RigidBodyState(q_WB=[0, 0, 0, 2.0])
    with pytest.raises(TypeError, match="^v_W"):
        rd.RigidBodyState(v_W=["a", "b", "c"])
    with pytest.raises(ValueError, match="^mass"):
        rd.RigidBody(0.0, np.eye(3))
    with pytest.raises(ValueError, match="^inertia_com"):
        rd.RigidBody(1.0, np.diag([1.0, -1.0, 1.0]))
    with pytest.raises(ValueError, match="^inertia_com"):
        rd.RigidBody(1.0, [[1.0, 0.5, 0], [0, 1.0, 0], [0, 0, 1.0]])
    with pytest.raises(ValueError, match="^inertia_com.*triangle"):
        rd.RigidBody(1.0, np.diag([2.0, 1.0, 2.0 / 3.0]))
    assert rd.RigidBody(1.0, np.diag([2.0, 1.0, 2.0 / 3.0]), check=rd.InertiaCheck.allow_unrealizable).euler_form == "principal"
    with pytest.raises(ValueError, match="^inertia_com"):
        rd.RigidBody(1.0, np.eye(2))
    with pytest.raises(ValueError, match="^inertia_zz"):
        rd.PlanarBody(1.0, 0.0)
    with pytest.raises(ValueError, match="^mass"):
        rd.Particle(-1.0)
    with pytest.raises(ValueError, match="^frame"):
        rd.AppliedLoad(frame="inertial")
    with pytest.raises(ValueError, match=r"^loads\[0\].t_end"):
        rd.AppliedLoad(t_start=1.0, t_end=0.5)


def test_loads_a_model_cannot_take():
    with pytest.raises(ValueError, match=r"^loads\[1\].torque"):
        rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.1, 1, loads=[rd.AppliedLoad(), rd.AppliedLoad(torque=[0, 0, 1])])
    with pytest.raises(ValueError, match=r"^loads\[0\].force"):
        rd.simulate(rd.PlanarBody(1.0, 1.0), rd.PlanarBodyState(), 0.1, 1, loads=[rd.AppliedLoad(force=[0, 0, 1])])
    with pytest.raises(ValueError, match="^gravity"):
        rd.simulate(rd.PlanarBody(1.0, 1.0), rd.PlanarBodyState(), 0.1, 1, gravity=True)
    with pytest.raises(TypeError, match="^loads"):
        rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.1, 1, loads=[1.0])
