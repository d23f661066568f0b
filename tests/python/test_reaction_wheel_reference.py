"""The numpy reference of the reaction wheel (rigiddyn_ref.scene.reaction_wheel) checked against itself and the
gyrostat's equations, without rigiddyn (Hughes, "Spacecraft Attitude Dynamics", ch. 3: a body carrying a wheel of
angular momentum h relative to it obeys I ω̇ + ω × (I ω + h) = n − ḣ, so the wheel acts on the body as the couple
τ = −ω × h − ḣ): the wheel's speed law, the couple on a hand-worked case, the couple as minus the rate of the
wheel's angular momentum seen from W (by central differences), its power −ḣ·ω, and the reference's RK4 keeping
the gyrostat's first integrals at its order: the total angular momentum R (I ω + h) always, the body's kinetic
energy ½ ω·I ω at constant wheel speed, and ½ ω·I ω − (the wheel's work on the body) during a spin-up."""

import numpy as np
import pytest

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

EPS = np.finfo(float).eps
SEEDS = range(8)


# ---------------------------------------------------------------- the wheel's speed
def test_the_wheel_speed_ramps_between_t_start_and_t_end():
    """Ω = speed + acceleration (min(max(t, t_start), t_end) − t_start), dΩ/dt = acceleration on [t_start, t_end)
    and 0 outside (binary fractions here: every value exact)."""
    speed, acceleration, t_start, t_end = 3.0, 2.0, 0.5, 1.5
    cases = [(-1.0, 3.0, 0.0), (0.5, 3.0, 2.0), (1.0, 4.0, 2.0), (1.5, 5.0, 0.0), (7.0, 5.0, 0.0)]
    for t, omega, omega_dot in cases:
        assert ref.wheel_speed(t, speed, acceleration, t_start, t_end) == (omega, omega_dot), t
    assert ref.wheel_speed(1e9, speed, 0.0, 0.0, np.inf) == (speed, 0.0)


# ---------------------------------------------------------------- the couple
def one_body(kind="rigid"):
    body = {"rigid": ref.rigid(2.0, [0.4, 0.5, 0.7]), "planar": ref.planar(2.0, 0.7), "particle": ref.particle(2.0)}
    return [body[kind]]


def test_the_couple_on_a_hand_worked_case():
    """ω = (0, 0, 3) rad/s, a wheel of J = 0.5 kg m² along x_B (axis given as (2, 0, 0)) at Ω = 4 rad/s speeding
    up at 2 rad/s²: h = (2, 0, 0) N m s, ḣ = (1, 0, 0) N m, τ = −ω × h − ḣ = −(0, 6, 0) − (1, 0, 0); power
    τ·ω = 0. Every product is exact."""
    kin = [ref.Kinematics(np.zeros(3), so3.rotvec_to_quat([0.3, 0.2, -0.1]), np.zeros(3), np.array([0.0, 0.0, 3.0]))]
    effect = ref.reaction_wheel(one_body(), kin, 1.0, body=0, axis_B=[2.0, 0.0, 0.0], inertia=0.5, speed=2.0,
                                acceleration=2.0, t_start=0.0, t_end=2.0)
    np.testing.assert_array_equal(effect.tau_B[0], [-1.0, -6.0, 0.0])
    np.testing.assert_array_equal(effect.f_W, np.zeros((1, 3)))
    assert effect.power == 0.0 and effect.potential == 0.0


@pytest.mark.parametrize("kind", ["particle", "planar"])
def test_a_wheel_needs_a_rigid_body(kind):
    kin = ref.kinematics(one_body(kind), np.zeros(6))
    with pytest.raises(ValueError, match="expected a rigid body"):
        ref.reaction_wheel(one_body(kind), kin, 0.0, body=0, axis_B=[0.0, 0.0, 1.0], inertia=0.1, speed=1.0)


def random_wheel(rng):
    """A random attitude and spin (|ω| ≲ 3.5 rad/s), axis, J ∈ [0.01, 0.1] kg m², speed ≤ 50 rad/s, acceleration
    ≤ 20 rad/s², ramp on [0.2, 0.8] s."""
    kin = [ref.Kinematics(rng.uniform(-1, 1, 3), so3.rotvec_to_quat(rng.normal(size=3)), rng.uniform(-1, 1, 3),
                          rng.uniform(-2, 2, 3))]
    params = dict(body=0, axis_B=rng.normal(size=3), inertia=rng.uniform(0.01, 0.1), speed=rng.uniform(-50, 50),
                  acceleration=rng.uniform(-20, 20), t_start=0.2, t_end=0.8)
    return kin, params


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("t", [0.1, 0.5, 1.0])
def test_the_couple_is_minus_the_rate_of_the_wheel_momentum_seen_from_w(seed, t):
    """The body turning at ω (R(s) = R exp((s − t) [ω]×)) with the wheel's h_B(s) = J Ω(s) a: the wheel's angular
    momentum in W is R h_B and the body feels minus its rate, τ_B = −Rᵀ d(R h_B)/ds (the transport theorem gives
    ω × h + ḣ). Central differences with δ = 1e-4 s (t ± δ stay on one side of t_start and t_end: Ω linear
    there): truncation δ²/6 |d³(R h_B)/ds³| ≤ δ²/6 (|ω|³ |h| + 3 |ω|² |ḣ|) (ḧ = 0); round-off: R h_B rounds by
    ≤ 16 eps |h| per side, over 2δ."""
    rng = np.random.default_rng(seed)
    kin, params = random_wheel(rng)
    k = kin[0]
    a = params["axis_B"] / np.linalg.norm(params["axis_B"])
    wheel_args = (params["speed"], params["acceleration"], params["t_start"], params["t_end"])

    def h_W(s):
        R = so3.quat_to_matrix(k.q_WB) @ so3.rotvec_to_matrix((s - t) * k.w_B)
        return R @ (params["inertia"] * ref.wheel_speed(s, *wheel_args)[0] * a)

    delta = 1e-4
    rate_W = (h_W(t + delta) - h_W(t - delta)) / (2 * delta)
    effect = ref.reaction_wheel(one_body(), kin, t, **params)
    omega, omega_dot = ref.wheel_speed(t, *wheel_args)
    h, h_dot, w = abs(params["inertia"] * omega), abs(params["inertia"] * omega_dot), np.linalg.norm(k.w_B)
    bound = delta ** 2 / 6 * (w ** 3 * h + 3 * w ** 2 * h_dot) + 16 * EPS * h / delta
    np.testing.assert_allclose(effect.tau_B[0], -so3.quat_to_matrix(k.q_WB).T @ rate_W, rtol=0, atol=bound)


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("t", [0.1, 0.5, 1.0])
def test_the_power_is_minus_h_dot_dot_omega(seed, t):
    """τ·ω = −(ω × h)·ω − ḣ·ω = −J (dΩ/dt) a·ω: 0 outside the ramp (the gyroscopic part does no work), the
    motor's power inside; the power sums 3 products of terms ≤ (|ω||h| + |ḣ|)|ω|, each rounded a few times:
    16 eps of that."""
    rng = np.random.default_rng(seed)
    kin, params = random_wheel(rng)
    k = kin[0]
    a = params["axis_B"] / np.linalg.norm(params["axis_B"])
    omega, omega_dot = ref.wheel_speed(t, params["speed"], params["acceleration"], params["t_start"], params["t_end"])
    effect = ref.reaction_wheel(one_body(), kin, t, **params)
    w = np.linalg.norm(k.w_B)
    scale = (w * abs(params["inertia"] * omega) + abs(params["inertia"] * omega_dot)) * w
    assert abs(effect.power - (-params["inertia"] * omega_dot * a @ k.w_B)) <= 16 * EPS * scale


def test_the_rate_is_read_at_rate_time():
    """rk4_step passes the middle of its piece as rate_time: Ω stays the stage time's, dΩ/dt is the piece's (at
    t = t_end the ramp's, read inside it)."""
    kin = [ref.Kinematics(np.zeros(3), ref.IDENTITY, np.zeros(3), np.zeros(3))]
    params = dict(body=0, axis_B=[0.0, 0.0, 1.0], inertia=0.5, speed=0.0, acceleration=2.0, t_start=0.0, t_end=1.0)
    at_end = ref.reaction_wheel(one_body(), kin, 1.0, **params)
    inside = ref.reaction_wheel(one_body(), kin, 1.0, rate_time=0.75, **params)
    np.testing.assert_array_equal(at_end.tau_B[0], [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(inside.tau_B[0], [0.0, 0.0, -1.0])
    assert ref.schedule_switches(ref.Scene(one_body(), [ref.Element("ReactionWheel", params)])) == [0.0, 1.0]


# ---------------------------------------------------------------- first integrals under the reference's RK4
def tumbling_gyrostat(speed=40.0, acceleration=0.0, t_start=0.0, t_end=np.inf):
    """A 5 kg body of principal moments (2, 3, 4) kg m² (the wheel's share included) tumbling at ω0 = (1, −0.5, 2)
    rad/s, |I ω0| ≈ 8.2 N m s, with a wheel of J = 0.05 kg m² along (1, 2, 2)/3 (no principal axis): at 40 rad/s
    |h| = 2 N m s, which bends the body's polhodes."""
    bodies = [ref.rigid(5.0, [2.0, 3.0, 4.0])]
    wheel = ref.Element("ReactionWheel", dict(body=0, axis_B=[1.0, 2.0, 2.0], inertia=0.05, speed=speed,
                                              acceleration=acceleration, t_start=t_start, t_end=t_end))
    scene = ref.Scene(bodies, [wheel])
    kin = [ref.Kinematics(np.zeros(3), so3.rotvec_to_quat([0.3, -0.4, 0.2]), np.zeros(3), np.array([1.0, -0.5, 2.0]))]
    return scene, ref.initial_state(scene, kin)


def total_angular_momentum(scene, y):
    """L_W = R_WB (I ω_B + h_B(t)) [N m s] of the one body and its wheel (Hughes, ch. 3)."""
    p = scene.elements[0].params
    k = ref.kinematics(scene.bodies, y)[0]
    a = np.asarray(p["axis_B"], float) / np.linalg.norm(p["axis_B"])
    omega, _ = ref.wheel_speed(ref.time_of(scene, y), p["speed"], p["acceleration"], p["t_start"], p["t_end"])
    return dyn.to_world(k.q_WB, scene.bodies[0].inertia @ k.w_B + p["inertia"] * omega * a)


def drifts(scene, y0, h, duration):
    """The largest |(T − W) − (T − W)0| (T = ½ ω·I ω, W the wheel's work on the body) and |L_W − L_W0| over an
    RK4 run of `duration` [s] at step h [s]; and the largest T and |L_W|."""
    ys = ref.rk4_run(scene, y0, h, int(round(duration / h)))
    T = np.array([ref.kinetic_energy(scene, y) for y in ys])
    W = np.array([ref.work_of(scene, y)[0] for y in ys])
    L = np.array([total_angular_momentum(scene, y) for y in ys])
    return np.max(np.abs(T - W - T[0])), np.max(np.abs(L - L[0])), np.max(T), np.max(np.linalg.norm(L, axis=1))


@pytest.mark.parametrize("wheel", [dict(), dict(speed=0.0, acceleration=30.0, t_start=0.513, t_end=2.771)],
                         ids=["constant_speed", "spin_up"])
def test_reference_rk4_keeps_the_gyrostat_integrals_at_fourth_order(wheel):
    """Without outside torque, d/dt R (I ω + h) = R (ω × (I ω + h) + I ω̇ + ḣ) = 0, and d/dt ½ ω·I ω = ω·I ω̇ =
    −ω·ḣ = the wheel's power: L_W and T − W are first integrals, at constant speed (W = 0) and through a spin-up
    from 0 to 67.7 rad/s whose ends lie inside steps (rk4_step splits there). RK4 keeps them to its global
    error C h⁴: halving h = 0.02 s divides the largest drift over 4 s by 16 (asserted 10–26; a first-order
    error, as from reading dΩ/dt at a stage past t_end, gives 2), Richardson bounds the drift at h/2 by
    2 |e(h) − e(h/2)|/15 (the factor 2 for the next order's share: h |ω| ≤ 0.05), which is ≤ 1e-8 of the scale
    (the run's largest T, |L|). Round-off: 400 steps × 16 eps of the scale (~1e-12), far below."""
    scene, y0 = tumbling_gyrostat(**wheel)
    coarse = drifts(scene, y0, 0.02, 4.0)
    fine = drifts(scene, y0, 0.01, 4.0)
    for e_h, e_h2, scale in ((coarse[0], fine[0], fine[2]), (coarse[1], fine[1], fine[3])):
        assert 10 <= e_h / e_h2 <= 26
        assert e_h2 <= 2 * abs(e_h - e_h2) / 15 + 400 * 16 * EPS * scale
        assert e_h2 <= 1e-8 * scale
