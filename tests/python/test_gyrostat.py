"""The Gyrostat body kind: a rigid body carrying N wheels spun by motors about axes fixed in it, each wheel's
speed relative to the body a state (Hughes, "Spacecraft Attitude Dynamics", ch. 3):
A ω̇ = τ_B − Σ u_k a_k − ω × (I ω + h_w), Ω̇_k = u_k / J_k − a_k·ω̇, A = I − Σ J_k a_k a_kᵀ.

Checked against the numpy reference (rigiddyn_ref.gyrostat: one RK4 step and a run across motor and load switches
inside steps, the records of T, H and the motor work); against exact solutions: a wheel spun up from rest about a
principal axis turns the body by exactly −J/I₃₃ times the wheel's angle relative to it, ω and Ω linear in t (RK4
exact for them); the torque-free gyrostat keeps |H| and T, each wheel's absolute spin a·ω + Ω, to the method's
order; the work–energy balance T − T(0) = Σ work + Σ motor_work; bad input refused naming the value; the kind in
scene files, pickles, batches, describe and DataFrames."""

import pickle

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn.scene_file import read_scene, scene_to_toml

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import gyrostat as gy

EPS = np.finfo(float).eps
SEEDS = range(6)


# ---------------------------------------------------------------- random gyrostats, in both worlds
def random_gyrostat(seed, wheels=3):
    """A body of mass 50–150 kg, a full inertia (principal moments 8–15 kg m², random axes), `wheels` wheels on
    random axes with J ∈ [0.02, 0.08] kg m², spins ≤ 0.5 rad/s, wheel speeds ≤ 50 rad/s, motor torques ≤ 0.05
    N m switching on at t = 0.013 s and off at 0.047 s (inside steps of 0.02 s): |h_w| ≤ 12 N m s on moments ≥ 7.7
    kg m², so the rate's Lipschitz constant × 0.02 s stays below 1."""
    rng = np.random.default_rng(seed)
    R = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    inertia = R @ np.diag(rng.uniform(8.0, 15.0, 3)) @ R.T
    inertia = 0.5 * (inertia + inertia.T)
    axes = rng.normal(size=(wheels, 3))
    J = rng.uniform(0.02, 0.08, wheels)
    u = rng.uniform(-0.05, 0.05, wheels)
    mass = rng.uniform(50.0, 150.0)
    ref_body = gy.gyrostat(mass, inertia, list(zip(axes, J)))
    motor = [gy.MotorTorque(np.where(np.arange(wheels) == k, u[k], 0.0), 0.013, 0.047) for k in range(wheels)]
    core_wheels = [rd.Wheel(axes[k], J[k], motor_torque=u[k], t_start=0.013, t_end=0.047) for k in range(wheels)]
    core_body = rd.Gyrostat(rd.RigidBody(mass, inertia), core_wheels)
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    y0 = gy.state(rng.normal(size=3), q, rng.normal(size=3), rng.uniform(-0.5, 0.5, 3), rng.uniform(-50, 50, wheels))
    return ref_body, core_body, motor, y0


def core_state(y, wheels):
    return rd.GyrostatState(p_W=y[0:3], q_WB=y[3:7], v_W=y[7:10], w_B=y[10:13], wheel_speeds=y[13:13 + wheels])


def core_vector(result, i):
    """The reference's state (13 + N,) of record i of a one-gyrostat SceneResult."""
    return np.concatenate([result.p_W[i, 0], result.q_WB[i, 0], result.v_W[i, 0], result.w_B[i, 0],
                           result.wheel_speed[i]])


def loads():
    """A world force and a body couple switching inside the first steps (both sides split there)."""
    return [dyn.Load(np.array([2.0, -1.0, 0.5]), np.zeros(3), "world", 0.0, 0.031),
            dyn.Load(np.zeros(3), np.array([0.02, 0.01, -0.03]), "body", 0.005, np.inf)]


def core_loads():
    return [rd.AppliedLoad(force=l.force, torque=l.torque, frame=l.frame, t_start=l.t_start, t_end=l.t_end)
            for l in loads()]


def step_roundoff(ref_body, y0, y1):
    """One RK4 step, core vs reference, from the same y0: per side the update rounds ≤ 4 eps of max(|y0|, |Δy|) and
    each stage rate carries ≤ 16 eps κ of it (κ = cond(A), from solving A ω̇ = n); h × the rate's Lipschitz constant
    ≤ 1 (random_gyrostat), so a stage's error grows by ≤ e over the four stages. Two sides: 2 × 16 eps κ e × size."""
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(y1 - y0)))
    return 2 * 16 * EPS * np.linalg.cond(ref_body.transverse) * np.e * size


def rate_lipschitz(ref_body, y, u, delta=1e-7):
    """‖∂ẏ/∂y‖_∞ of the reference rate at y under the motor torques u, by forward differences."""
    f0 = gy.rate(ref_body, 0.0, y, np.zeros(3), np.zeros(3), u)
    columns = []
    for j in range(len(y)):
        step = delta * max(1.0, abs(y[j]))
        e = np.zeros(len(y))
        e[j] = step
        columns.append((gy.rate(ref_body, 0.0, y + e, np.zeros(3), np.zeros(3), u) - f0) / step)
    return np.max(np.sum(np.abs(np.array(columns).T), axis=1))


# ---------------------------------------------------------------- against the reference
@pytest.mark.parametrize("seed", SEEDS)
def test_one_rk4_step_matches_the_reference(seed):
    """One RK4 step of h = 0.02 s from t = 0.02 (the motors on throughout), by step and by simulate: the body's
    state and the wheel speeds within both sides' round-off (step_roundoff)."""
    ref_body, body, motor, y0 = random_gyrostat(seed)
    h, t0 = 0.02, 0.02
    want = gy.rk4_step(ref_body, t0, y0, h, motor, loads())
    tol = step_roundoff(ref_body, y0, want)
    state, t1 = rd.step(body, core_state(y0, 3), dt=h, method="rk4", loads=core_loads(), t=t0)
    got = np.concatenate([state.p_W, state.q_WB, state.v_W, state.w_B, state.wheel_speeds])
    np.testing.assert_allclose(got, want, rtol=0, atol=tol)
    assert t1 == t0 + h
    result = rd.simulate(body, core_state(y0, 3), dt=h, steps=1, t0=t0, loads=core_loads())
    np.testing.assert_allclose(core_vector(result, 1), want, rtol=0, atol=tol)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_run_across_switches_matches_the_reference(seed):
    """10 RK4 steps of 0.02 s from t = 0, the motors switching on at 0.013 s and off at 0.047 s and the loads at
    0.005 s and 0.031 s, inside steps (both sides split there): the states, T, H about W's origin and the motor
    and load works. The two sides differ by round-off: each step adds ≤ 2 δ (δ the one-side bound of
    step_roundoff), carried to the end by the method's Jacobian ≤ e^{L (N − k) h} (L the rate's Lipschitz
    constant with the motors on, doubled for its variation along the run): bound N e^{L N h} × 2 δ; the energy,
    momenta and works are read off the state through their Jacobian, bounded by the sizes of their terms."""
    ref_body, body, motor, y0 = random_gyrostat(seed)
    h, steps = 0.02, 10
    want = gy.rk4_run(ref_body, y0, h, steps, motor, loads())
    result = rd.simulate(body, core_state(y0, 3), dt=h, steps=steps, loads=core_loads())
    u_on = sum(p.u for p in motor)
    L = 2 * max(rate_lipschitz(ref_body, want.y[0], u_on), rate_lipschitz(ref_body, want.y[-1], u_on))
    size = max(1.0, np.max(np.abs(want.y)), np.max(np.abs(np.diff(want.y, axis=0))))
    delta = 16 * EPS * np.linalg.cond(ref_body.transverse) * np.e * size
    bound = steps * np.exp(L * steps * h) * 2 * delta
    for i in range(steps + 1):
        np.testing.assert_allclose(core_vector(result, i), want.y[i], rtol=0, atol=bound)
    # T, H: the sizes of their terms (m |v|², ω·I ω, J Ω² ...; m |p| |v|, |I| |ω|, J |Ω|) times the state's bound
    scale_T = ref_body.mass * size + np.max(np.abs(ref_body.inertia)) * size + np.max(ref_body.J) * size
    T = [gy.kinetic_energy(ref_body, y) for y in want.y]
    np.testing.assert_allclose(result.kinetic_energy, T, rtol=0, atol=2 * scale_T * bound + 64 * EPS * max(T))
    H = np.array([gy.angular_momentum_about_origin(ref_body, y) for y in want.y])
    scale_H = 2 * ref_body.mass * size + np.max(np.abs(ref_body.inertia)) + np.max(ref_body.J) * 3
    np.testing.assert_allclose(result.angular_momentum_W, H, rtol=0,
                               atol=scale_H * bound + 64 * EPS * np.max(np.abs(H)))
    # works: ∫ P dt with P = f·v + τ·ω (loads) and Σ u Ω (motors): h N × (|f| + |τ| + Σ |u|) × the state's bound
    power_scale = 3.0 + 0.1 + np.sum(np.abs(u_on))
    np.testing.assert_allclose(result.work[:, 0], want.work_loads, rtol=0, atol=h * steps * power_scale * bound
                               + 64 * EPS * np.max(np.abs(want.work_loads)))
    np.testing.assert_allclose(result.motor_work.sum(axis=1), want.work_motor, rtol=0,
                               atol=h * steps * power_scale * bound + 64 * EPS * np.max(np.abs(want.work_motor)))


# ---------------------------------------------------------------- exact solutions
def spin_up(h, steps, method="rk4"):
    """A body at rest with I = diag(3, 4, 5) kg m² and one wheel of J = 1 kg m² along its principal axis z,
    the motor at u = 0.5 N m: H = 0 throughout, so I₃₃ ω + J Ω = 0 and (I₃₃ − J) ω̇ = −u:
    ω = −u t / (I₃₃ − J), Ω = u I₃₃ t / (J (I₃₃ − J)), and the body's angle
    θ = −u t² / (2 (I₃₃ − J)) = −(J / I₃₃) × the wheel's angle φ."""
    body = rd.Gyrostat(rd.RigidBody(5.0, [3.0, 4.0, 5.0]), [rd.Wheel([0.0, 0.0, 1.0], 1.0, motor_torque=0.5)])
    return rd.simulate(body, rd.GyrostatState(wheel_speeds=[0.0]), dt=h, steps=steps, method=method)


def test_a_wheel_spun_up_from_rest_turns_the_body_back():
    """ω and Ω are linear in t and RK4 integrates a polynomial rate of degree ≤ 3 exactly: with h = 3/32 s every
    product is a binary fraction, so ω, Ω and H = 0 come out exactly; the body turns about z only (q_x = q_y = 0
    exactly)."""
    result = spin_up(3 / 32, 32)
    I33, J, u = 5.0, 1.0, 0.5
    t = result.t
    np.testing.assert_array_equal(result.w_B[:, 0, 2], -u * t / (I33 - J))
    np.testing.assert_array_equal(result.wheel_speed[:, 0], u * I33 * t / (J * (I33 - J)))
    np.testing.assert_array_equal(result.angular_momentum_W, np.zeros((len(t), 3)))
    np.testing.assert_array_equal(result.q_WB[:, 0, :2], np.zeros((len(t), 2)))


@pytest.mark.parametrize("method", ["rk4", "implicit_midpoint"])
def test_the_body_turns_by_minus_J_over_I_times_the_wheel_angle(method):
    """θ(t) = −u t² / (2 (I₃₃ − J)) at t = 3 s: the method's error shrinks at its order (rk4 4, implicit midpoint
    2) when h halves; the observed ratio lies within a factor 1.5 of 2^order (the next term of the error's
    expansion is h² smaller: at most 30 % here), and the finest error is below 1e-6 of θ."""
    order = {"rk4": 4, "implicit_midpoint": 2}[method]
    theta = -0.5 * 3.0**2 / (2 * 4.0)
    errors = []
    for steps in (30, 60, 120):
        r = spin_up(3.0 / steps, steps, method)
        q = r.q_WB[-1, 0]
        errors.append(abs(2 * np.arctan2(q[2], q[3]) - theta))
    ratios = [errors[0] / errors[1], errors[1] / errors[2]]
    assert all(2**order / 1.5 < r < 2**order * 1.5 for r in ratios), (errors, ratios)
    assert errors[-1] < 1e-6 * abs(theta)


def torque_free(h, duration=20.0):
    """A tumbling gyrostat (I = diag(10, 12, 15) kg m², wheels of 0.5 and 0.8 kg m² along x and z at 30 and
    −20 rad/s, |ω| ≈ 2.7 rad/s, no motor torque, no outside wrench): |H|, T and each wheel's absolute spin a·ω + Ω
    are first integrals."""
    body = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]),
                       [rd.Wheel([1.0, 0.0, 0.0], 0.5), rd.Wheel([0.0, 0.0, 1.0], 0.8)])
    state = rd.GyrostatState(w_B=[1.5, -1.0, 2.0], wheel_speeds=[30.0, -20.0])
    return rd.simulate(body, state, dt=h, steps=round(duration / h))


def test_the_torque_free_gyrostat_keeps_its_first_integrals_at_the_method_order():
    """RK4 over 20 s: the drifts of T and |H| shrink at least at the method's order 4 when h halves (ratio > 12:
    16 less the next term of the error's expansion, h² smaller, ≤ 25 % at these steps), the finest below 1e-8 of
    the value; each wheel's absolute spin a·ω + Ω is linear in the state, so RK4 keeps it to round-off (steps ×
    16 eps × its terms' size, 32 rad/s)."""
    drifts, values = [], None
    for h in (0.04, 0.02, 0.01):
        r = torque_free(h)
        H = np.linalg.norm(r.angular_momentum_W, axis=1)
        drifts.append((abs(r.kinetic_energy[-1] - r.kinetic_energy[0]), abs(H[-1] - H[0])))
        values = (r.kinetic_energy[0], H[0])
        spin = np.stack([r.w_B[:, 0, 0] + r.wheel_speed[:, 0], r.w_B[:, 0, 2] + r.wheel_speed[:, 1]], axis=1)
        np.testing.assert_allclose(spin, np.broadcast_to(spin[0], spin.shape), rtol=0, atol=len(r.t) * 16 * EPS * 32)
    drifts = np.array(drifts)
    ratios = drifts[:-1] / drifts[1:]
    assert np.all(ratios > 12), (drifts, ratios)
    assert np.all(drifts[-1] < 1e-8 * np.array(values)), drifts


def test_the_work_energy_balance_holds_with_motors_and_loads():
    """T − T(0) = Σ work + Σ motor_work over 4 s of the tumbling gyrostat of torque_free with motors at 2 and
    −1 N m (one switching on and off inside steps), a body couple and a world force: each side's integral is
    RK4's, so the balance's residual is the method's error, shrinking at least at order 4 when h halves (ratio >
    12, as above) and below 1e-9 of the energy exchanged at the finest step."""
    body = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]),
                       [rd.Wheel([1.0, 0.0, 0.0], 0.5, motor_torque=2.0, t_start=0.31, t_end=1.67),
                        rd.Wheel([0.0, 0.0, 1.0], 0.8, motor_torque=-1.0)])
    state = rd.GyrostatState(v_W=[1.0, 0.0, 0.0], w_B=[1.5, -1.0, 2.0], wheel_speeds=[30.0, -20.0])
    applied = [rd.AppliedLoad(torque=[1.0, -0.5, 0.3], frame="body", t_start=0.1, t_end=2.5),
               rd.AppliedLoad(force=[5.0, 0.0, 0.0], t_start=1.0)]
    residuals = []
    for h in (0.04, 0.02, 0.01):
        r = rd.simulate(body, state, dt=h, steps=round(4.0 / h), loads=applied)
        residual = r.kinetic_energy - r.kinetic_energy[0] - r.work.sum(axis=1) - r.motor_work.sum(axis=1)
        residuals.append(np.max(np.abs(residual)))
        exchanged = np.max(np.abs(r.work.sum(axis=1))) + np.max(np.abs(r.motor_work.sum(axis=1)))
    ratios = np.array(residuals[:-1]) / np.array(residuals[1:])
    assert np.all(ratios > 12), (residuals, ratios)
    assert residuals[-1] < 1e-9 * exchanged


# ---------------------------------------------------------------- bad input
@pytest.mark.parametrize(("make", "message"), [
    (lambda: rd.Wheel([0.0, 0.0, 0.0], 0.1), r"^axis_B: expected a non-zero axis"),
    (lambda: rd.Wheel([0.0, 0.0, 1.0], 0.0), r"^inertia: expected a finite number > 0"),
    (lambda: rd.Wheel([0.0, 0.0, 1.0], 0.1, motor_torque=np.nan), r"^motor_torque"),
    (lambda: rd.Wheel([0.0, 0.0, 1.0], 0.1, t_start=2.0, t_end=1.0), r"^t_end: expected a time after t_start"),
    (lambda: rd.Gyrostat(rd.RigidBody(1.0, [1.0, 1.0, 1.0]), [rd.Wheel([0, 0, 1], 0.6), rd.Wheel([0, 0, 1], 0.6)]),
     r"^wheels\[1\]\.inertia: expected an axial inertia that leaves the transverse inertia"),
    (lambda: rd.Gyrostat(rd.RigidBody(1.0, [1.0, 1.0, 1.0]), [0.5]), r"^wheels\[0\]: expected a Wheel"),
    (lambda: rd.GyrostatState(wheel_speeds=[1.0, np.inf]), r"^wheel_speeds"),
])
def test_bad_input_is_refused_naming_the_value(make, message):
    with pytest.raises((ValueError, TypeError), match=message):
        make()


def test_an_axis_of_huge_entries_stays_an_axis():
    """|axis_B|² overflows for entries of 1e308: the unit axis is taken after scaling (stableNormalized), never
    the zero vector a plain normalisation gives; for the Wheel and for the ReactionWheel element, whose couple
    −ω × J Ω a on a body at ω = (0, 0, 1) with a wheel at Ω = 1 must then be J (a_y, −a_x, 0)."""
    np.testing.assert_allclose(rd.Wheel([1e308, 1e308, 0.0], 0.1).axis_B, [2**-0.5, 2**-0.5, 0.0], rtol=4 * EPS)
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(1.0, [1.0, 1.0, 1.0]))
    scene.add(rd.ReactionWheel(body=0, axis_B=[1e308, 1e308, 0.0], inertia=0.5, speed=1.0))
    r = rd.simulate(scene, [rd.RigidBodyState(w_B=[0.0, 0.0, 1.0])], dt=1e-6, steps=1)
    # the couple is τ ⟂ ω (no power): read it from the first step's Δω/h (unit sphere: ω̇ = τ). Bound: ω̇ turns
    # with ω at |τ| = 0.5 rad/s², so Δω/h differs from ω̇(0) by ≤ h |∂ω̇/∂ω| |ω̇| ~ 1e-6 relative, and the
    # difference's round-off is ≤ 2 eps |ω| / h ≈ 5e-10: rtol 1e-5
    dw = (r.w_B[1, 0] - r.w_B[0, 0]) / 1e-6
    np.testing.assert_allclose(dw[:2], 0.5 * np.array([2**-0.5, -(2**-0.5)]), rtol=1e-5)


def test_a_run_refuses_what_the_gyrostat_cannot_do():
    body = rd.Gyrostat(rd.RigidBody(5.0, [3.0, 4.0, 5.0]), [rd.Wheel([0.0, 0.0, 1.0], 1.0)])
    with pytest.raises(ValueError, match=r"^initial\[0\]\.wheel_speeds: expected 1 speeds \(one per wheel"):
        rd.simulate(body, rd.GyrostatState(wheel_speeds=[1.0, 2.0]), dt=0.1, steps=1)
    for method in ("splitting_dlm", "exact_flow_kick", "semi_implicit_euler_implicit_gyroscopic", "exact"):
        with pytest.raises(ValueError, match=r"^method: expected a method that integrates the whole motion"):
            rd.simulate(body, rd.GyrostatState(wheel_speeds=[0.0]), dt=0.1, steps=1, method=method)
    scene = rd.Scene()
    scene.add_body(body, name="sat")
    scene.frame = rd.SceneFrame.rotating([0.0, 0.0, 1.0], 0.1)
    with pytest.raises(ValueError, match=r"^frame: expected none in a scene with body 0 'sat' \(a gyrostat\)"):
        rd.simulate(scene, [rd.GyrostatState(wheel_speeds=[0.0])], dt=0.1, steps=1)


# ---------------------------------------------------------------- the kind as data
def test_a_gyrostat_scene_round_trips_through_a_file_and_pickle():
    text = """
[[body]]
name = "sat"
kind = "gyrostat"
mass = "100 kg"
inertia = [10, 12, 15]
w_B = {value = [0, 0, 6], unit = "deg/s"}
[[body.wheels]]
axis_B = [0, 0, 2]
inertia = "0.05 kg m^2"
speed = "3000 rpm"
motor_torque = "10 mN m"
t_end = "1 min"
"""
    f = read_scene(text)
    (body,), (state,) = f.scene.bodies, f.initial
    assert body.wheels[0] == rd.Wheel([0.0, 0.0, 1.0], 0.05, motor_torque=0.01, t_end=60.0)
    np.testing.assert_allclose(state.wheel_speeds, [100 * np.pi], rtol=4 * EPS)
    again = read_scene(scene_to_toml(f.scene, f.initial, f.run))
    assert again.scene.bodies[0] == body and again.initial[0] == state
    assert pickle.loads(pickle.dumps(body)) == body and pickle.loads(pickle.dumps(state)) == state
    result = rd.simulate(f.scene, f.initial, dt=0.5, steps=4)
    back = pickle.loads(pickle.dumps(result))
    np.testing.assert_array_equal(back.wheel_speed, result.wheel_speed)
    np.testing.assert_array_equal(back.motor_work, result.motor_work)
    assert back.wheel_bodies == (0,)
    columns = [c for c in result.to_dataframe().columns if "wheel" in c or "motor" in c]
    assert columns == ["sat:wheel_speed_0 [rad/s]", "sat:motor_work_0 [J]"]
    assert "gyrostat" in f.scene.describe() and "Wheels" in f.scene.describe()


def test_a_batch_of_gyrostats_records_each_sample_as_its_own_run():
    """simulate_batch over three wheel speeds: each sample's wheel_speed and motor_work equal its own simulate
    (the same loop on one thread or several)."""
    body = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0.0, 0.0, 1.0], 0.05, motor_torque=0.01)])
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="probe")
    scene.add_body(body, name="sat")
    states = [[rd.ParticleState(), rd.GyrostatState(w_B=[0.1, 0.0, 0.2], wheel_speeds=[s])] for s in (0.0, 50.0, -80.0)]
    batch = rd.simulate_batch(scene, states, dt=0.1, steps=20)
    assert batch.wheel_speed.shape == (3, 21, 1) and batch.wheel_bodies == (1,)
    for i, initial in enumerate(states):
        one = rd.simulate(scene, initial, dt=0.1, steps=20)
        np.testing.assert_array_equal(batch[i].wheel_speed, one.wheel_speed)
        np.testing.assert_array_equal(batch.motor_work[i], one.motor_work)
