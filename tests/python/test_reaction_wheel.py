"""The ReactionWheel element: a wheel of moment of inertia J about the unit axis a fixed in a rigid (or pivoted)
body's B, spun relative to it at Ω(t) = speed + acceleration (min(max(t, t_start), t_end) − t_start), the body's
inertia the whole gyrostat's. The wheel's angular momentum relative to the body is h = J Ω a and the body feels
τ_B = −ω × h − ḣ (Hughes, "Spacecraft Attitude Dynamics", ch. 3: the gyrostat's Euler equation
I ω̇ + ω × (I ω + h) = n − ḣ). Checked against the numpy reference (rigiddyn_ref.scene.reaction_wheel) on random
scenes (the record at t0 and one RK4 step); against exact solutions: the torque-free gyrostat keeps its total
angular momentum R (I ω + h) and, at constant wheel speed, its kinetic energy ½ ω·I ω; a body at rest turns
against a wheel spun up about a principal axis by exactly −J/I_zz times the wheel's angle; a body pinned at its
centre of mass moves as the free one; bad input refused naming the field; the element as data and in scene
files."""

import pickle

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn.scene_file import load_scene, read_scene, scene_to_toml

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

from _scene_core import EPS, core_scene, core_states, inertia_condition, record_state, run, state_vector
from test_scene_vs_reference import (componentwise_condition, random_bodies, random_kinematics, rate_lipschitz,
                                     recorded_quantities, rk4_step_tolerance, term_magnitude)

SEEDS = range(6)


# ---------------------------------------------------------------- against the reference on random scenes
def wheel_scene(seed, ramp):
    """test_scene_vs_reference's random bodies (a particle, a planar body, a rigid body with principal axes and
    one with a full inertia, spins ≤ 2 rad/s) with a wheel on each rigid body: J ∈ [0.005, 0.03] kg m², a random
    axis, speed ≤ 10 rad/s; `ramp`: both wheels speed up at ≤ 20 rad/s² from t_start = 0 to t_end = 0.5 s (the
    compared step [0, 0.02] s lies inside). |h| ≤ 0.3 N m s, J |dΩ/dt| ≤ 0.6 N m on moments ≥ 0.02 kg m²: the
    rate's Lipschitz constant × 0.02 s ≲ 1, as rk4_step_tolerance assumes."""
    rng = np.random.default_rng(seed)
    bodies = random_bodies(rng)

    def wheel(body):
        params = dict(body=body, axis_B=rng.normal(size=3), inertia=rng.uniform(0.005, 0.03),
                      speed=rng.uniform(-10, 10))
        if ramp:
            params.update(acceleration=rng.uniform(-20, 20), t_start=0.0, t_end=0.5)
        return ref.Element("ReactionWheel", params)

    scene = ref.Scene(bodies, [wheel(2), wheel(3)])
    return scene, ref.initial_state(scene, random_kinematics(rng, bodies))


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("ramp", [False, True], ids=["constant_speed", "ramp"])
def test_power_energies_and_momenta_at_t0_match_the_reference(ramp, seed):
    """The record at t0 holds each wheel's power τ·ω (= −ḣ·ω: round-off at constant speed), T, V = 0 and the
    momenta: both sides evaluate the same formulas, each within 16 eps of (the magnitude of its terms + its
    componentwise condition): tolerance 2 sides × 16 eps × that (as test_scene_vs_reference)."""
    scene, y0 = wheel_scene(seed, ramp)
    result = run(scene, y0, 0.02, 1)
    kin = ref.kinematics(scene.bodies, y0)
    want = recorded_quantities(scene, y0)
    terms = [term_magnitude(ref.evaluate(e, scene.bodies, kin, 0.0), kin) for e in scene.elements]
    scale = np.abs(want) + np.concatenate([terms, np.zeros(8)]) + componentwise_condition(
        lambda y: recorded_quantities(scene, y), y0)
    got = np.concatenate([result.power[0], [result.kinetic_energy[0], result.potential_energy[0]],
                          result.linear_momentum_W[0], result.angular_momentum_W[0]])
    np.testing.assert_array_less(np.abs(got - want), 32 * EPS * scale + 1e-300)
    assert list(result.elements) == ["ReactionWheel", "ReactionWheel"]


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("ramp", [False, True], ids=["constant_speed", "ramp"])
def test_one_rk4_step_matches_the_reference(ramp, seed):
    """One RK4 step of h = 0.02 s, core vs numpy: every body's state and each wheel's work, by simulate and by
    step, within both sides' round-off (test_scene_vs_reference.rk4_step_tolerance). With the ramp the stages
    see Ω at t, t + h/2, t + h and dΩ/dt = acceleration throughout (the step lies inside [t_start, t_end))."""
    scene, y0 = wheel_scene(seed, ramp)
    h = 0.02
    want = ref.rk4_step(scene, y0, h)
    tol = rk4_step_tolerance(scene, y0, want)
    got = record_state(scene, run(scene, y0, h, 1), 1, like=want)
    np.testing.assert_allclose(got, want, rtol=0, atol=tol)
    states, t1 = rd.step(core_scene(scene), core_states(scene, y0), h, method="rk4", t=0.0)
    n_bodies = len(want) - len(scene.elements)
    np.testing.assert_allclose(state_vector(scene, states, t1, want)[:n_bodies], want[:n_bodies], rtol=0, atol=tol)


# ---------------------------------------------------------------- the torque-free gyrostat
INERTIA = np.array([2.0, 3.0, 4.0])  # kg m², principal moments of the whole gyrostat


def gyrostat(inertia=INERTIA, axis_B=(1.0, 2.0, 2.0), speed=40.0, acceleration=0.0, t_start=0.0, t_end=np.inf):
    """A 5 kg body of inertia `inertia` (principal moments or a full matrix, the wheel's share included) tumbling
    at ω0 = (1, −0.5, 2) rad/s (|I ω0| ≈ 8 N m s) with a wheel of J = 0.05 kg m² along axis_B (by default
    (1, 2, 2)/3, no principal axis): at 40 rad/s |h| = 2 N m s, which bends the body's polhodes."""
    bodies = [ref.rigid(5.0, inertia)]
    wheel = ref.Element("ReactionWheel", dict(body=0, axis_B=list(axis_B), inertia=0.05, speed=speed,
                                              acceleration=acceleration, t_start=t_start, t_end=t_end))
    scene = ref.Scene(bodies, [wheel])
    kin = [ref.Kinematics(np.zeros(3), so3.rotvec_to_quat([0.3, -0.4, 0.2]), np.zeros(3), np.array([1.0, -0.5, 2.0]))]
    return scene, ref.initial_state(scene, kin)


def wheel_momentum_B(scene, t):
    """h_B = J Ω(t) a [N m s] of the scene's one wheel at times t (n,) [s]: (n, 3)."""
    p = scene.elements[0].params
    a = np.asarray(p["axis_B"], float) / np.linalg.norm(p["axis_B"])
    omega = [ref.wheel_speed(s, p["speed"], p["acceleration"], p["t_start"], p["t_end"])[0] for s in t]
    return p["inertia"] * np.outer(omega, a)


def integrals(scene, result):
    """From the records of the one body: T = ½ ω·I ω [J], the wheel's work W [J] and L_W = R_WB (I ω + h_B)
    [N m s] (each record's q_WB and w_B)."""
    inertia = scene.bodies[0].inertia
    w = np.asarray(result.w_B)[:, 0]
    q = np.asarray(result.q_WB)[:, 0]
    h = wheel_momentum_B(scene, np.asarray(result.t))
    T = 0.5 * np.einsum("ni,ij,nj->n", w, inertia, w)
    L = np.array([dyn.to_world(q[i], inertia @ w[i] + h[i]) for i in range(len(w))])
    return T, np.asarray(result.work)[:, 0], L


def drifts(scene, y0, dt, duration):
    """The largest |(T − W) − (T − W)0| and |L_W − L_W0| over a core RK4 run; and the largest T and |L_W|."""
    T, W, L = integrals(scene, run(scene, y0, dt, int(round(duration / dt))))
    return np.max(np.abs(T - W - T[0])), np.max(np.abs(L - L[0])), np.max(T), np.max(np.linalg.norm(L, axis=1))


def assert_fourth_order(coarse, fine, steps):
    """RK4 keeps a first integral to its global error C h⁴: halving h divides the drift by 16 (asserted 10–26;
    a first-order error gives 2, a third-order one 8); Richardson bounds the drift at h/2 by 2 |e(h) − e(h/2)|/15
    (the factor 2 for the next order's share: h |ω| ≤ 0.07 here), plus the round-off of `steps` steps × 16 eps of
    the scale (the run's largest T, |L|); and that bound is ≤ 1e-8 of the scale (the reference's RK4 drifts by
    ≤ 2e-9 of it in these runs), so a wrong couple, whose error would not shrink with h, is caught."""
    for e_h, e_h2, scale in ((coarse[0], fine[0], fine[2]), (coarse[1], fine[1], fine[3])):
        assert 10 <= e_h / e_h2 <= 26
        assert e_h2 <= 2 * abs(e_h - e_h2) / 15 + steps * 16 * EPS * scale
        assert e_h2 <= 1e-8 * scale


def test_torque_free_gyrostat_keeps_its_angular_momentum_and_energy():
    """Without outside torque and at constant wheel speed, d/dt R (I ω + h) = R (ω × (I ω + h) + I ω̇) = 0 and
    d/dt ½ ω·I ω = −ω·(ω × (I ω + h)) = 0 (Hughes, ch. 3): |L_W| (and the vector itself) and the body's kinetic
    energy are kept over 4 s of RK4 at h = 0.02 s and 0.01 s to RK4's error (assert_fourth_order); the wheel's
    work stays 0 to round-off (its power −(ω × h)·ω sums three products ≤ |ω|²|h| ≤ (2T/I_min)|h| = 18.75 W,
    T = 9.375 J: 16 eps of that for the 4 s)."""
    scene, y0 = gyrostat()
    assert_fourth_order(drifts(scene, y0, 0.02, 4.0), drifts(scene, y0, 0.01, 4.0), 400)
    T, W, L = integrals(scene, run(scene, y0, 0.01, 400))
    assert np.max(np.abs(W)) <= 4.0 * 16 * EPS * 18.75
    norm = np.linalg.norm(L, axis=1)
    assert np.max(np.abs(norm - norm[0])) <= np.max(np.abs(L - L[0]))  # |L| is kept as well as L


def test_a_wheel_off_the_principal_axes_of_a_full_inertia_keeps_the_energy():
    """A full inertia (the principal moments (2, 3, 4) kg m² turned by the rotation vector (0.4, −0.3, 0.5)) with
    the wheel along z_B, a non-principal axis, at constant speed: ½ ω·I ω and L_W kept to RK4's error as above."""
    turn = so3.rotvec_to_matrix([0.4, -0.3, 0.5])
    scene, y0 = gyrostat(inertia=turn @ np.diag(INERTIA) @ turn.T, axis_B=(0.0, 0.0, 1.0))
    assert_fourth_order(drifts(scene, y0, 0.02, 4.0), drifts(scene, y0, 0.01, 4.0), 400)


def test_a_spin_up_keeps_the_total_angular_momentum_and_pays_the_energy_by_the_wheels_work():
    """The wheel of the tumbling gyrostat spun up from 0 at 30 rad/s² on [0.5, 2.5) s (on the step grids of
    h = 1/32 and 1/64 s): L_W = R (I ω + h) is still kept (d/dt = R (ω × (I ω + h) + I ω̇ + ḣ) = 0), and
    ½ ω·I ω changes by the wheel's work (d/dt ½ ω·I ω = −ω·ḣ = its power): both to RK4's error
    (assert_fourth_order; a rate dΩ/dt read past t_end at the last stage of a step would make it first order)."""
    scene, y0 = gyrostat(speed=0.0, acceleration=30.0, t_start=0.5, t_end=2.5)
    assert_fourth_order(drifts(scene, y0, 1 / 32, 4.0), drifts(scene, y0, 1 / 64, 4.0), 256)


# ---------------------------------------------------------------- spin-up about a principal axis
J, I_ZZ, ACCELERATION, T_END = 0.05, 4.0, 2.0, 1.0  # kg m², kg m², rad/s², s


def spin_up_scene():
    """A body at rest of principal moments (2, 3, I_zz) kg m², its wheel along z_B (J = 0.05 kg m²) spun up from
    0 at 2 rad/s² on [0, 1) s, then left at 2 rad/s."""
    scene = ref.Scene([ref.rigid(1.0, [2.0, 3.0, I_ZZ])],
                      [ref.Element("ReactionWheel", dict(body=0, axis_B=[0.0, 0.0, 1.0], inertia=J, speed=0.0,
                                                         acceleration=ACCELERATION, t_start=0.0, t_end=T_END))])
    kin = [ref.Kinematics(np.zeros(3), ref.IDENTITY, np.zeros(3), np.zeros(3))]
    return scene, ref.initial_state(scene, kin)


def wheel_angle(t):
    """φ(t) = ∫ Ω: a t²/2 on the ramp, then a t_end²/2 + a t_end (t − t_end) [rad] (relative to the body)."""
    ramp = np.minimum(t, T_END)
    return ACCELERATION * ramp ** 2 / 2 + ACCELERATION * ramp * (t - ramp)


def test_a_wheel_spun_up_about_a_principal_axis_turns_the_body_back():
    """With ω ∥ h ∥ z_B (a principal axis) both ω × I ω and ω × h vanish: I_zz ω̇_z = −J dΩ/dt, so from rest
    ω_z = −(J/I_zz) Ω(t) and the body turns about z by θ = −(J/I_zz) φ(t) (the total angular momentum I_zz ω_z +
    J Ω stays 0). At every record of 3 s of RK4 at h = 1/32 and 1/64 s (t_end = 1 s on both grids):
    - ω_z: RK4 integrates the state-independent, per-step constant ω̇_z exactly; round-off ≤ 8 eps |ω_z|max per
      step; ω_x = ω_y = 0 and q_x = q_y = 0 within the same (no term feeds them);
    - θ = 2 atan2(q_z, q_w): RK4's error on the quaternion's turn, assumed at least halved by halving h
      (|e(h/2)| ≤ |e(h) − e(h/2)|), plus the round-off of each step's update and normalisation (≤ 8 eps of
      |q| = 1, doubled by θ = 2 atan2): 16 eps per step; the bound is ≤ 1e-9 of max |θ| = 0.0625 rad, while a
      rate dΩ/dt read past t_end at the step's last stage would leave ω_z off by h/6 J a/I_zz ≈ 1e-4 rad/s."""
    thetas, errors = [], []
    for per_second in (32, 64):
        scene, y0 = spin_up_scene()
        steps = 3 * per_second
        result = run(scene, y0, 1.0 / per_second, steps)
        t = np.asarray(result.t)
        w = np.asarray(result.w_B)[:, 0]
        q = np.asarray(result.q_WB)[:, 0]
        omega = ACCELERATION * np.minimum(t, T_END)
        w_scale = J / I_ZZ * ACCELERATION * T_END
        np.testing.assert_allclose(w[:, 2], -J / I_ZZ * omega, rtol=0, atol=steps * 8 * EPS * w_scale)
        np.testing.assert_allclose(w[:, :2], 0.0, rtol=0, atol=steps * 8 * EPS * w_scale)
        np.testing.assert_allclose(q[:, :2], 0.0, rtol=0, atol=steps * 8 * EPS)
        theta = 2.0 * np.arctan2(q[:, 2], q[:, 3])
        thetas.append(theta)
        errors.append(np.abs(theta + J / I_ZZ * wheel_angle(t)))
    bound = np.abs(errors[0] - errors[1][::2]) + 3 * 64 * 16 * EPS
    assert np.max(bound) <= 1e-9 * np.max(np.abs(thetas[1]))
    assert np.all(errors[1][::2] <= bound)


# ---------------------------------------------------------------- a pivoted body
def test_a_body_pinned_at_its_centre_of_mass_moves_as_the_free_gyrostat():
    """A PivotedBody with p_OC_B = 0 (the pivot takes no force) and the same wheel, ramp included (on the grid of
    h = 0.02 s: t_start = 0.2, t_end = 0.6), solves the free gyrostat's attitude equations: q_WB and w_B agree with
    the RigidBody's run over 50 steps within both runs' round-off carried by the method's Jacobian, N e^{L N h}
    × 2 δ (as test_scene_vs_reference: L twice the reference rate's Lipschitz constant at start and end, δ the
    one-side step round-off 16 eps κ e × max(1, |y|))."""
    scene, y0 = gyrostat(speed=10.0, acceleration=20.0, t_start=0.2, t_end=0.6)
    h, steps = 0.02, 50
    free = run(scene, y0, h, steps)
    p = scene.elements[0].params
    pinned = rd.Scene()
    pinned.add_body(rd.PivotedBody(rd.RigidBody(5.0, list(INERTIA)), [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]), name="top")
    pinned.add(rd.ReactionWheel(body=0, axis_B=p["axis_B"], inertia=p["inertia"], speed=p["speed"],
                                acceleration=p["acceleration"], t_start=p["t_start"], t_end=p["t_end"]))
    k = ref.kinematics(scene.bodies, y0)[0]
    result = rd.simulate(pinned, [rd.PivotedBodyState(q_WB=k.q_WB, w_B=k.w_B)], dt=h, steps=steps, method="rk4")
    want = ref.rk4_run(scene, y0, h, steps)
    L = 2 * max(rate_lipschitz(scene, want[0]), rate_lipschitz(scene, want[-1]))
    delta = 16 * EPS * inertia_condition(scene) * np.e * max(1.0, np.max(np.abs(want)))
    bound = steps * np.exp(L * steps * h) * 2 * delta
    q_free, q_pinned = np.asarray(free.q_WB)[:, 0], np.asarray(result.q_WB)[:, 0]
    q_pinned = q_pinned * np.sign(np.sum(q_free * q_pinned, axis=1))[:, None]
    np.testing.assert_allclose(q_pinned, q_free, rtol=0, atol=bound)
    np.testing.assert_allclose(np.asarray(result.w_B)[:, 0], np.asarray(free.w_B)[:, 0], rtol=0, atol=bound)
    np.testing.assert_allclose(np.asarray(result.work)[:, 0], np.asarray(free.work)[:, 0], rtol=0,
                               atol=bound * max(1.0, np.max(np.abs(free.work))))


# ---------------------------------------------------------------- the element as data
def test_attributes_read_back_and_the_element_round_trips():
    e = rd.ReactionWheel(body=1, axis_B=[0.0, 0.6, 0.8], inertia=0.02, speed=100.0, acceleration=-5.0, t_start=1.0,
                         t_end=3.0)
    assert e.body == 1 and e.inertia == 0.02 and e.speed == 100.0 and e.acceleration == -5.0
    assert e.t_start == 1.0 and e.t_end == 3.0
    np.testing.assert_allclose(e.axis_B, [0.0, 0.6, 0.8], rtol=0, atol=2 * EPS)  # a unit vector: kept (or
    # normalised within an eps or two)
    defaults = rd.ReactionWheel(body=0, axis_B=[0.0, 0.0, 1.0], inertia=0.1)
    assert defaults.speed == 0.0 and defaults.acceleration == 0.0 and defaults.t_start == 0.0
    assert defaults.t_end == np.inf
    assert pickle.loads(pickle.dumps(e)) == e
    assert eval(repr(e), {**vars(rd), "inf": np.inf}) == e
    assert eval(repr(defaults), {**vars(rd), "inf": np.inf}) == defaults
    assert e != rd.ReactionWheel(body=1, axis_B=[0.0, 0.6, 0.8], inertia=0.02, speed=100.0)


def test_the_arguments_are_keywords():
    with pytest.raises(TypeError):
        rd.ReactionWheel(0, [0.0, 0.0, 1.0], 0.1)
    with pytest.raises(TypeError):
        rd.ReactionWheel(body=0, inertia=0.1)  # axis_B is required


def test_the_axis_is_any_non_zero_vector():
    """axis_B = (0, 0, 3) acts as (0, 0, 1): the same one RK4 step of a tumbling body (both normalise the axis:
    equal within the step's round-off, rk4_step_tolerance of the scene)."""
    runs = []
    for axis in ([0.0, 0.0, 3.0], [0.0, 0.0, 1.0]):
        scene, y0 = gyrostat(axis_B=axis)
        runs.append(record_state(scene, run(scene, y0, 0.02, 1), 1))
    np.testing.assert_allclose(runs[0], runs[1], rtol=0, atol=rk4_step_tolerance(scene, y0, runs[1]))


WHEEL = dict(body=0, axis_B=[0.0, 0.0, 1.0], inertia=0.1)


@pytest.mark.parametrize("change, message", [
    (dict(axis_B=[0.0, 0.0, 0.0]), r"^axis_B: expected"),
    (dict(axis_B=[0.0, 1.0]), r"^axis_B: expected"),
    (dict(axis_B=[0.0, np.nan, 1.0]), r"^axis_B: expected"),
    (dict(axis_B=[np.inf, 0.0, 1.0]), r"^axis_B: expected"),
    (dict(inertia=0.0), r"^inertia: expected"),
    (dict(inertia=-0.1), r"^inertia: expected"),
    (dict(inertia=np.nan), r"^inertia: expected"),
    (dict(inertia=np.inf), r"^inertia: expected"),
    (dict(speed=np.nan), r"^speed: expected"),
    (dict(speed=np.inf), r"^speed: expected"),
    (dict(acceleration=np.nan), r"^acceleration: expected"),
    (dict(acceleration=-np.inf), r"^acceleration: expected"),
    (dict(t_start=np.nan), r"^t_start: expected"),
    (dict(t_end=np.nan), r"^t_end: expected"),
    (dict(t_start=1.0, t_end=1.0), r"^t_end: expected"),
    (dict(t_start=2.0, t_end=1.0), r"^t_end: expected"),
    (dict(body=-1), r"^body: expected"),
])
def test_bad_arguments_are_refused_naming_the_field(change, message):
    with pytest.raises(ValueError, match=message):
        rd.ReactionWheel(**{**WHEEL, **change})


@pytest.mark.parametrize("body", [rd.Particle(1.0), rd.PlanarBody(1.0, 0.5)], ids=["particle", "planar"])
def test_scene_add_refuses_a_body_without_a_full_attitude(body):
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(1.0, [1.0, 2.0, 2.5]), name="box")
    scene.add_body(body, name="other")
    with pytest.raises(ValueError, match=r"^element\.body: expected"):
        scene.add(rd.ReactionWheel(**{**WHEEL, "body": 1}))
    with pytest.raises(ValueError, match=r"^element\.body: expected a body index in \[0, 2\), got 5$"):
        scene.add(rd.ReactionWheel(**{**WHEEL, "body": 5}))
    assert scene.add(rd.ReactionWheel(**WHEEL)) == 0
    assert "ReactionWheel" in scene.describe("rk4")


# ---------------------------------------------------------------- scene files
SCENE_FILE = """
name = "wheel in a box"
[run]
dt = 0.01
duration = 1.0
[[body]]
name = "box"
kind = "rigid"
mass = 2.0
inertia = [0.2, 0.3, 0.4]
w_B = [0.1, 0.0, 0.5]
[[body]]
name = "bead"
kind = "particle"
mass = 0.1
p_W = [0.0, 1.0, 0.0]
[[force]]
type = "reaction_wheel"
body = "box"
axis_B = [0, 0, 2]
inertia = "20 g*m^2"
speed = "30 rad/s"
acceleration = "180 deg/s^2"
t_start = "100 ms"
t_end = 0.6
[[force]]
type = "reaction_wheel"
body = "box"
axis_B = [1, 0, 0]
inertia = 0.01
"""


def test_a_scene_file_round_trips_with_its_reaction_wheels():
    """[[force]] type = "reaction_wheel" with the constructor's keys, the body by name (units: kg m², rad/s,
    rad/s², s; a value with its unit converted by one factor, within 2 eps): read, the elements equal the
    constructor's; written canonically and read back, the same scene (a fixed point of the writer); both runs bit
    for bit the same."""
    f = read_scene(SCENE_FILE)
    first, second = f.scene.elements
    assert type(first) is rd.ReactionWheel and first.body == 0
    np.testing.assert_allclose(first.axis_B / np.linalg.norm(first.axis_B), [0.0, 0.0, 1.0], rtol=0, atol=2 * EPS)
    assert first.inertia == pytest.approx(0.02, rel=2 * EPS)
    assert first.speed == 30.0
    assert first.acceleration == pytest.approx(np.pi, rel=2 * EPS)
    assert first.t_start == pytest.approx(0.1, rel=2 * EPS) and first.t_end == 0.6
    assert second == rd.ReactionWheel(body=0, axis_B=[1.0, 0.0, 0.0], inertia=0.01)
    text = scene_to_toml(f.scene, f.initial, f.run, f.name, f.description)
    assert 'type = "reaction_wheel"' in text
    g = read_scene(text)
    assert g.scene == f.scene and g.run == f.run and g.name == f.name
    assert scene_to_toml(g.scene, g.initial, g.run, g.name, g.description) == text
    a = rd.simulate(f.scene, f.initial, dt=f.run.dt, steps=f.run.steps, method="rk4")
    b = rd.simulate(g.scene, g.initial, dt=g.run.dt, steps=g.run.steps, method="rk4")
    np.testing.assert_array_equal(a.q_WB, b.q_WB)
    np.testing.assert_array_equal(a.w_B, b.w_B)
    np.testing.assert_array_equal(a.work, b.work)


P = ('[[body]]\nname = "box"\nkind = "rigid"\nmass = 1\ninertia = [1, 1, 1]\n'
     '[[body]]\nname = "bead"\nkind = "particle"\nmass = 1\n[[force]]\ntype = "reaction_wheel"\n')


@pytest.mark.parametrize("text, message", [
    (P + 'axis_B = [0, 0, 1]\ninertia = 0.1', "force[0].body: expected"),
    (P + 'body = "box"\ninertia = 0.1', "force[0].axis_B: expected"),
    (P + 'body = "box"\naxis_B = [0, 0, 0]\ninertia = 0.1', "force[0].axis_B: expected"),
    (P + 'body = "box"\naxis_B = [0, 0, 1]', "force[0].inertia: expected"),
    (P + 'body = "box"\naxis_B = [0, 0, 1]\ninertia = "1 kg"', "force[0].inertia: expected"),
    (P + 'body = "box"\naxis_B = [0, 0, 1]\ninertia = 0.1\nspeed = "3 m/s"', "force[0].speed: expected"),
    (P + 'body = "box"\naxis_B = [0, 0, 1]\ninertia = 0.1\nt_start = 1\nt_end = 0.5', "force[0].t_end: expected"),
    (P + 'body = "bx"\naxis_B = [0, 0, 1]\ninertia = 0.1', "force[0].body: expected the name of a [[body]]"),
    (P + 'body = "box"\naxis_B = [0, 0, 1]\ninertia = 0.1\nsped = 1',
     "force[0].sped: expected a key of a [[force]] of type 'reaction_wheel'"),
])
def test_bad_scene_file_fields_name_the_field(text, message):
    with pytest.raises(ValueError) as e:
        load_scene(text)
    assert message in str(e.value)
