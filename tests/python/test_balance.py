"""result.balance, the energy and momentum balance of every run, and the AccuracyWarning when it does not close
(simulate/balance.hpp and simulate/accuracy_check.hpp in the core, the class in rigiddyn/_balance.py; the impulses
are integrated with the motion in scene/scene_model.hpp). The core is compared with the numpy reference
(rigiddyn_ref.balance) computed from the same records.

Residuals (zero for the exact dynamics): r_E = T - T0 - sum W - sum E_mass - sum W_motor, r_P = |P - P0 - J|,
r_H = |H - H0 - K| about W's origin (a body's run is its one-body scene's).
"""

import copy
import pickle
import warnings
from pathlib import Path

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn_ref import balance as ref

EPS = np.finfo(float).eps
I_B = np.array([1.0, 2.0, 3.0])
TUMBLING = [0.1, 1.0, 0.1]  # near the middle axis: |w| ~ 1.01 rad/s
THREE_BODY = Path(rd.__file__).parent / "scenes" / "three_body.toml"


def quiet_simulate(*args, **kwargs):
    """simulate with the AccuracyWarning recorded instead of raised: (result, the warnings' messages)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", rd.AccuracyWarning)
        result = rd.simulate(*args, **kwargs)
    return result, [str(w.message) for w in caught if w.category is rd.AccuracyWarning]


# ------------------------------------------------------------------ the residuals against numpy


def test_body_energy_residual_is_the_work_energy_balance_of_the_records():
    """r_E = T - T0 - work exactly (the same floating-point expression: equal to the last bit); the loads' impulses
    are integrated with the motion, so the momentum balances apply to a body's run as to any scene's."""
    loads = [rd.AppliedLoad(force=[0.5, 0.0, 0.0], torque=[0.0, 0.0, 0.2], t_start=0.3, t_end=1.1)]
    r = rd.simulate(rd.RigidBody(2.0, I_B), rd.RigidBodyState(w_B=TUMBLING, v_W=[0.0, 0.0, 3.0]), 0.01, 200,
                    loads=loads, gravity=True, error=False)
    T, W = r.kinetic_energy, r.work.sum(axis=1)
    np.testing.assert_array_equal(r.balance.energy, T - T[0] - W)
    assert r.balance.verdict == {"energy": "closed", "linear_momentum": "closed", "angular_momentum": "closed"}
    assert r.balance.about == "W's origin"


def test_body_momentum_residuals_against_numpy():
    """Under gravity alone, about W's origin: r_P = |m v - m v0 - m g s|, r_H = |H - H0 - K| with H = p x m v + R I w
    and K = m (p0 s + v0 s^2/2 + g s^3/6) x g (s = t - t0; rk4 integrates the quadratic path and the cubic K
    exactly). The reference is computed here from the records with scipy's rotation; the two agree to the round-off
    of two evaluations of the same sums, within twice Balance's round-off bound."""
    from scipy.spatial.transform import Rotation

    m, g = 2.0, np.array([0.0, 0.0, -9.81])
    p0, v0 = np.array([0.5, -1.0, 2.0]), np.array([1.0, 0.0, 3.0])
    r = rd.simulate(rd.RigidBody(m, I_B), rd.RigidBodyState(p_W=p0, w_B=TUMBLING, v_W=v0), 0.05, 100,
                    gravity=True, error=False)
    rec, b = r.body(0), r.balance
    s = (r.t - r.t[0])[:, None]
    P = m * rec.v_W
    expected_P = np.linalg.norm(P - P[0] - m * s * g, axis=1)
    assert np.all(np.abs(b.linear_momentum - expected_P) <= 2 * b.linear_momentum_round_off)
    H = np.cross(rec.p_W, P) + Rotation.from_quat(rec.q_WB).apply(rec.w_B * I_B)
    K = np.cross(m * (p0 * s + v0 * s**2 / 2 + g * s**3 / 6), g)
    expected_H = np.linalg.norm(H - H[0] - K, axis=1)
    assert np.all(np.abs(b.angular_momentum - expected_H) <= 2 * b.angular_momentum_round_off)


def test_scene_residuals_against_numpy():
    """A particle and a rigid body tossed in uniform gravity: J = M g (t - t0) and K = M (integral of the centre of
    mass path) x g with the path p0 + v0 s + g s^2/2 (rk4 integrates this quadratic motion and the cubic integral
    exactly: its residuals are the round-off of the sums, bounded by Balance's round-off bounds)."""
    scene = rd.Scene(bodies=[rd.Particle(1.5), rd.RigidBody(2.0, I_B)], elements=[rd.UniformGravity()])
    p0 = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 1.0]])
    v0 = np.array([[0.0, 1.0, 4.0], [1.0, 0.0, 2.0]])
    initial = [rd.ParticleState(p_W=p0[0], v_W=v0[0]), rd.RigidBodyState(p_W=p0[1], v_W=v0[1], w_B=TUMBLING)]
    r = rd.simulate(scene, initial, 0.01, 150, record_every=10, error=False)
    b = r.balance
    m = np.array([1.5, 2.0])
    g = np.array([0.0, 0.0, -9.81])
    s = (r.t - r.t[0])[:, None]
    J = m.sum() * s * g
    first = (m[:, None] * p0).sum(axis=0)  # sum m p0
    moment = (m[:, None] * v0).sum(axis=0)  # sum m v0
    K = np.cross(first * s + moment * s**2 / 2 + m.sum() * g * s**3 / 6, g)
    P, H = r.linear_momentum_W, r.angular_momentum_W
    expected_P = np.linalg.norm(P - P[0] - J, axis=1)
    expected_H = np.linalg.norm(H - H[0] - K, axis=1)
    assert np.all(np.abs(b.linear_momentum - expected_P) <= 2 * b.linear_momentum_round_off + 1e-14)
    assert np.all(np.abs(b.angular_momentum - expected_H) <= 2 * b.angular_momentum_round_off + 1e-13)
    np.testing.assert_array_equal(b.energy, r.kinetic_energy - r.kinetic_energy[0] - r.work.sum(axis=1))
    assert b.about == "W's origin"


# ------------------------------------------------------------------ the core against the numpy reference

ARRAYS = ("energy", "linear_momentum", "angular_momentum")


def assert_matches_reference(core, expected, message, expected_message, steps=0):
    """The core's balance equals the reference computed from the same records: r_E to the bit (the same expression,
    numpy's summation order); the momentum residuals within their round-off bound (two evaluations of the same
    norms and sums in another order differ by a few eps of the terms' size, the bound is 8 eps of it per step); the
    scales and round-off bounds within 8 eps relative (sums of at most a few norms, each a few eps); the verdicts and
    the warning's text equal (the same rule at the same figures). With `steps` > 0 the reference was given impulses
    in closed form, which differ from the core's integrated ones by up to the residual's round-off bound: a scale
    holds the largest |J| (or |K|) and may differ by that bound, a round-off bound (8 eps per step of the size it
    holds) by 8 eps x steps of it."""
    np.testing.assert_array_equal(core.energy, expected["energy"])
    for q in ARRAYS:
        round_off = getattr(core, q + "_round_off")
        slack = {"": round_off, "_round_off": 8 * EPS * steps * round_off, "_scale": round_off if steps else 0 * round_off}
        for suffix in ("", "_round_off", "_scale"):
            got, want = getattr(core, q + suffix), expected[q + suffix]
            assert np.array_equal(np.isnan(got), np.isnan(want)), q + suffix
            finite = ~np.isnan(want)
            bound = (0.0 if suffix == "" else 8 * EPS * np.abs(want[finite])) + slack[suffix][finite]
            assert np.all(np.abs(got[finite] - want[finite]) <= bound), (q + suffix, np.max(np.abs(got - want)))
    assert core.verdict == expected["verdict"] and core.about == expected["about"]
    assert message == expected_message


def gravity_impulses(m, p0, v0, g):
    """The impulses of uniform gravity on one body in closed form, as a function of the record times: J = m g s,
    K = m (p0 s + v0 s^2/2 + g s^3/6) x g (s = t - t0, the centre of mass on p0 + v0 s + g s^2/2)."""
    p0, v0, g = (np.array(x, dtype=float) for x in (p0, v0, g))

    def impulses(t):
        s = (t - t[0])[:, None]
        return m * s * g, np.cross(m * (p0 * s + v0 * s**2 / 2 + g * s**3 / 6), g)

    return impulses


# (body, state, gravity, loads, dt, steps, the reason its momentum balances do not apply or "")
BODIES = [
    (rd.RigidBody(2.0, I_B), rd.RigidBodyState(w_B=TUMBLING, v_W=[1.0, 0.0, 3.0]), True, None, 0.05, 60, ""),
    (rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), None, None, 2.0 / np.linalg.norm(TUMBLING), 40, ""),
    (rd.Particle(1.5), rd.ParticleState(p_W=[1.0, 2.0, 0.0], v_W=[1.0, 0.0, 2.0]), True, None, 0.1, 30, ""),
    (rd.PlanarBody(2.0, 0.5), rd.PlanarBodyState(v_W=[1.0, 2.0], omega=3.0), None, None, 0.05, 50,
     "a planar body's plane takes forces whose impulse is not integrated"),
    (rd.RigidBody(1.0, I_B), rd.RigidBodyState(p_W=[0.5, 0.0, 1.0], w_B=TUMBLING, v_W=[0.0, 1.0, 0.0]), True, None,
     0.1, 50, ""),  # run by the closed form (method 'exact' below), its gravity impulses in closed form
]


def body_reference(r, case, method="rk4", level=ref.DEFAULT_LEVEL):
    """The reference balance of the one-body scene run r of BODIES[case] and its warning's text at `level`."""
    body, state, gravity, _, dt, _, not_applicable = BODIES[case]
    g = np.zeros(3) if gravity is None else np.array([0.0, 0.0, -9.81])
    rec = r.body(0)
    J, K = gravity_impulses(body.mass, rec.p_W[0], rec.v_W[0], g)(r.t)
    expected = ref.of_scene(r, J, K, not_applicable, dt)
    return expected, ref.accuracy_message(expected, r.error, level, r, method, dt)


@pytest.mark.parametrize("error", [False, True])
@pytest.mark.parametrize("case", range(len(BODIES)))
def test_body_balance_matches_the_numpy_reference(case, error):
    """A body's run is its one-body scene's: the scene's balance about W's origin, against the reference with
    gravity's impulses in closed form."""
    body, state, gravity, loads, dt, steps, _ = BODIES[case]
    method = "exact" if case == len(BODIES) - 1 else "rk4"
    r, messages = quiet_simulate(body, state, dt, steps, method=method, gravity=gravity, loads=loads, error=error)
    expected, message = body_reference(r, case, method)
    assert_matches_reference(r.balance, expected, messages[0] if messages else "", message, steps=steps)


def test_a_level_given_makes_the_reference_verdicts():
    body, state, gravity, loads, dt, steps, _ = BODIES[1]
    r, messages = quiet_simulate(body, state, dt, steps, error=False, accuracy_level=0.3)
    expected, message = body_reference(r, 1, level=0.3)
    assert_matches_reference(r.balance, expected, messages[0] if messages else "", message, steps=steps)


def tossed_scene():
    """A particle and a rigid body in uniform gravity with their impulses in closed form (test_scene_residuals)."""
    scene = rd.Scene(bodies=[rd.Particle(1.5), rd.RigidBody(2.0, I_B)], elements=[rd.UniformGravity()])
    p0 = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 1.0]])
    v0 = np.array([[0.0, 1.0, 4.0], [1.0, 0.0, 2.0]])
    initial = [rd.ParticleState(p_W=p0[0], v_W=v0[0]), rd.RigidBodyState(p_W=p0[1], v_W=v0[1], w_B=TUMBLING)]
    m, g = np.array([1.5, 2.0]), np.array([0.0, 0.0, -9.81])

    def impulses(t):
        s = (t - t[0])[:, None]
        first, moment = (m[:, None] * p0).sum(axis=0), (m[:, None] * v0).sum(axis=0)
        return m.sum() * s * g, np.cross(first * s + moment * s**2 / 2 + m.sum() * g * s**3 / 6, g)

    return scene, initial, impulses


@pytest.mark.parametrize("error", [False, True])
def test_scene_balance_matches_the_numpy_reference(error):
    """The impulses J, K of the reference are the closed forms (rk4 integrates them exactly: their difference from
    the core's integrated ones is round-off, within the residuals' round-off bound)."""
    scene, initial, impulses = tossed_scene()
    dt = 0.01
    r, messages = quiet_simulate(scene, initial, dt, 150, record_every=10, error=error)
    J, K = impulses(r.t)
    expected = ref.of_scene(r, J, K, "", dt)
    message = ref.accuracy_message(expected, r.error, ref.DEFAULT_LEVEL, r, "rk4", dt)
    assert_matches_reference(r.balance, expected, messages[0] if messages else "", message, steps=150)


@pytest.mark.filterwarnings("ignore::rigiddyn.SceneCompatibilityWarning")
@pytest.mark.parametrize("error", [False, True])
def test_scene_energy_balance_matches_the_numpy_reference(error):
    """Scenes whose momentum balances do not apply (a mass flow) or whose impulses have no closed form (drag,
    scheduled loads, a close encounter that warns, a gyrostat's motor): the energy balance, its verdict and the
    warning against the reference, the momentum balances' verdicts as the core gives them."""
    rocket = rd.Scene(bodies=[rd.Particle(10.0)], elements=[rd.UniformGravity(), rd.Thrust(0, [0.0, 0.0, 50.0], "world"),
                                                            rd.Drag(linear=0.5, quadratic=0.05)],
                      mass_flows=[rd.MassFlow(rate=-1.0)])
    sat = rd.Gyrostat(rd.RigidBody(100.0, [10.0, 12.0, 15.0]), [rd.Wheel([0, 0, 1], 0.05, motor_torque=0.01)])
    encounter, slow, run = close_encounter()
    cases = [(rocket, [rd.ParticleState(v_W=[1.0, 0.0, 0.0])], 0.02, dict(duration=2.0)),
             (*non_conservative_scene(), 0.05, dict(duration=1.0)),
             (sat, rd.GyrostatState(w_B=[0.1, 0.0, 0.2], wheel_speeds=[0.0]), 0.1, dict(steps=100)),
             (encounter, slow, run.dt, dict(duration=run.duration, record_every=run.record_every))]
    for model, initial, dt, size in cases:
        r, messages = quiet_simulate(model, initial, dt, error=error, **size)
        expected = ref.of_scene(r, None, None, "its momentum balances are not compared here", dt)
        expected["verdict"].update({q: r.balance.verdict[q] for q in ARRAYS[1:]})
        for q in ARRAYS[1:]:  # the core's own momentum balances, as the reference reads them
            for suffix in ("", "_round_off", "_scale"):
                expected[q + suffix] = getattr(r.balance, q + suffix)
        message = ref.accuracy_message(expected, r.error, ref.DEFAULT_LEVEL, r, "rk4", dt)
        assert_matches_reference(r.balance, expected, messages[0] if messages else "", message)


# ------------------------------------------------------------------ round-off for the structure-preserving methods


def test_exact_method_balances_at_round_off():
    """The closed form of a free body keeps T, P and H up to the round-off of its records; with loads it does not
    integrate their impulses and says so. A particle under 'exact' runs its layout, whose kicks and drifts are exact
    under a constant force and which integrates the impulses: its linear momentum balances at round-off."""
    r = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), 0.1, 500, method="exact", error=False)
    b = r.balance
    assert np.all(np.abs(b.energy) <= b.energy_round_off)
    assert np.all(b.angular_momentum <= b.angular_momentum_round_off)
    assert np.all(b.linear_momentum == 0.0)  # v stays (0, 0, 0) exactly
    push = rd.AppliedLoad(force=[1.0, 0.0, 0.0])
    pushed = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), 0.1, 10, method="exact", error=False,
                         loads=push)
    assert pushed.balance.verdict["linear_momentum"].startswith("not applicable: the closed form")
    particle = rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.1, 10, method="exact", error=False, loads=push)
    assert particle.balance.verdict["linear_momentum"] == "closed"
    assert np.all(particle.balance.linear_momentum <= particle.balance.linear_momentum_round_off)


def test_splitting_dlm_keeps_the_angular_momentum_at_round_off():
    """The DLM free rotation keeps H_W = R I w exactly (up to the round-off of its solve): the balance of H closes
    to the round-off bound (8 eps |H| per step) at a step where the energy does not."""
    r = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), 0.2, 500, method="splitting_dlm",
                    error=False)
    b = r.balance
    assert np.all(b.angular_momentum <= b.angular_momentum_round_off)


# ------------------------------------------------------------------ convergence at the method's order


def non_conservative_scene():
    """A rigid body and a particle under gravity, drag and scheduled loads switching inside the run."""
    loads = [rd.AppliedLoad(force=[1.0, 0.0, 0.5], torque=[0.0, 0.3, 0.1], frame="body", t_start=0.25, t_end=0.75)]
    scene = rd.Scene(bodies=[rd.RigidBody(2.0, I_B), rd.Particle(1.0)],
                     elements=[rd.UniformGravity(), rd.Drag(linear=0.3, quadratic=0.1, angular_linear=0.2),
                               rd.ScheduledLoads(body=0, loads=loads)])
    initial = [rd.RigidBodyState(v_W=[1.0, 0.0, 2.0], w_B=[0.3, 2.0, 0.2]), rd.ParticleState(v_W=[0.0, 1.0, 3.0])]
    return scene, initial


# (method, order, the balances it keeps exactly): a Runge-Kutta method keeps the linear invariant P - J of the
# augmented system (Hairer, Lubich, Wanner, linear invariants); the splittings' kicks add exactly the impulse they
# integrate and their free flow keeps P and H; implicit midpoint's work is exactly the change of T (its mean
# velocity is the midpoint's)
CONVERGENCE = [("rk4", 4, ("linear_momentum",)), ("rkmk4", 4, ("linear_momentum",)),
               ("splitting_dlm", 2, ("linear_momentum", "angular_momentum")),
               ("implicit_midpoint", 2, ("linear_momentum", "energy"))]


@pytest.mark.filterwarnings("ignore::rigiddyn.SceneCompatibilityWarning")  # drag under a splitting: expected
@pytest.mark.parametrize("method, order, exact", CONVERGENCE, ids=[c[0] for c in CONVERGENCE])
def test_residuals_converge_at_the_methods_order(method, order, exact):
    """Halving dt divides the final residual by 2^p: the ratio lies in [2^p / 1.5, 2^p * 1.5], the window of the
    global error estimate's order check (GlobalError), with both residuals 100x above their round-off bound; the
    balances a method keeps exactly stay within their round-off bound."""
    scene, initial = non_conservative_scene()
    final = {}
    for dt in (0.05, 0.025):
        final[dt] = rd.simulate(scene, initial, dt, duration=1.0, method=method, error=False).balance
    for q in ("energy", "linear_momentum", "angular_momentum"):
        coarse, fine = (abs(getattr(final[dt], q)[-1]) for dt in (0.05, 0.025))
        if q in exact:
            assert fine <= getattr(final[0.025], q + "_round_off")[-1], (q, fine)
            continue
        assert fine > 100 * getattr(final[0.025], q + "_round_off")[-1], (q, fine)
        assert 2**order / 1.5 <= coarse / fine <= 2**order * 1.5, (q, coarse / fine)


def test_thrust_energy_balance_converges():
    """A particle losing mass with a thrust: r_E holds the mass-flow energy; it converges at rk4's order 4 (window as
    above); the momentum balances do not apply (the mass flow carries momentum)."""
    scene = rd.Scene(bodies=[rd.Particle(10.0)], elements=[rd.UniformGravity(), rd.Thrust(0, [0.0, 0.0, 50.0], "world"),
                                                           rd.Drag(linear=0.5, quadratic=0.05)],
                     mass_flows=[rd.MassFlow(rate=-1.0)])
    initial = [rd.ParticleState(v_W=[1.0, 0.0, 0.0])]
    ends = []
    for dt in (0.02, 0.01):
        r = rd.simulate(scene, initial, dt, duration=2.0, error=False)
        ends.append(abs(r.balance.energy[-1]))
        assert r.balance.verdict["linear_momentum"].startswith("not applicable: a mass flow")
    assert 16 / 1.5 <= ends[0] / ends[1] <= 16 * 1.5, ends


# ------------------------------------------------------------------ the warning


def test_rk4_tumbling_at_a_coarse_step_warns():
    """rk4 at dt |w| = 2 near the middle axis loses ~1/3 of the energy and ~1/5 of |L| (without an estimate)."""
    w = np.array(TUMBLING)
    dt = 2.0 / np.linalg.norm(w)
    r, messages = quiet_simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=w), dt, 120, error=False)
    T, L = r.kinetic_energy, r.body(0).angular_momentum_norm
    assert 1 - T[-1] / T[0] > 0.3 and 1 - L[-1] / L[0] > 0.15  # the silent failure: 34 % of T, 19 % of |L| lost
    assert len(messages) == 1
    assert "energy balance is off" in messages[0] and "angular momentum balance is off" in messages[0]
    assert "smaller dt" in messages[0]
    assert r.balance.verdict["energy"].startswith("open") and r.balance.verdict["angular_momentum"].startswith("open")
    # with the estimate (error=True) the verdict is not reliable there, so the same level decides: it warns too
    with pytest.warns(rd.AccuracyWarning, match="balance is off"):
        rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=w), dt, 120)


def close_encounter():
    """The figure-eight scene with a mistaken initial condition: the velocities a tenth of the orbit's (a unit slip),
    so the three fall towards each other into close encounters that rk4 at the orbit's dt does not resolve."""
    scene, initial, run = rd.load_scene(THREE_BODY)
    slow = [rd.ParticleState(p_W=s.p_W, v_W=0.1 * np.asarray(s.v_W)) for s in initial]
    return scene, slow, run


def test_three_body_close_encounter_warns():
    scene, initial, run = close_encounter()
    r, messages = quiet_simulate(scene, initial, run.dt, duration=run.duration, record_every=run.record_every,
                                 error=False)
    E = r.total_energy
    relative = np.max(np.abs(E - E[0])) / abs(E[0])
    assert relative > 5.0  # the silent failure: the energy is off by several times itself (31x)
    assert len(messages) == 1 and "energy balance is off" in messages[0]


def test_a_well_resolved_run_does_not_warn():
    scene, initial, run = rd.load_scene(THREE_BODY)
    with warnings.catch_warnings():
        warnings.simplefilter("error", rd.AccuracyWarning)
        r = rd.simulate(scene, initial, run.dt, duration=run.duration, record_every=run.record_every)
        body = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), 0.01, 2000)
    assert all(v == "closed" for v in r.balance.verdict.values())
    assert body.balance.verdict["energy"] == "closed"


def test_accuracy_level_none_silences_and_a_level_decides():
    w = np.array(TUMBLING)
    dt = 2.0 / np.linalg.norm(w)
    with warnings.catch_warnings():
        warnings.simplefilter("error", rd.AccuracyWarning)
        r = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=w), dt, 20, error=False, accuracy_level=None)
        rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=w), dt, 20, error=False, accuracy_level=0.9)
    assert r.balance.verdict["energy"].startswith("open")  # the verdict is kept


@pytest.mark.parametrize("bad", [0.0, -1e-3, float("nan"), float("inf"), "1e-3", True])
def test_bad_accuracy_level_names_the_value(bad):
    with pytest.raises((ValueError, TypeError), match="accuracy_level"):
        rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.1, 2, accuracy_level=bad)


# ------------------------------------------------------------------ the class


def test_balance_pickles_with_its_result():
    r = rd.simulate(rd.RigidBody(1.0, I_B), rd.RigidBodyState(w_B=TUMBLING), 0.1, 20)
    for obj in (r.balance, r):
        back = pickle.loads(pickle.dumps(obj))
        b = back if isinstance(back, rd.Balance) else back.balance
        assert b == r.balance
    scene, initial = non_conservative_scene()
    s = rd.simulate(scene, initial, 0.01, 20, error=False)
    assert pickle.loads(pickle.dumps(s)).balance == s.balance
    assert copy.deepcopy(s.balance) == s.balance


def test_balance_summary_and_repr():
    r = rd.simulate(rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0]), 0.1, 10, gravity=True, error=False)
    b = r.balance
    assert repr(b).startswith("Balance(records=11, energy=")
    assert b.summary().splitlines()[0].startswith("energy: max |residual|")
    assert b.summary().splitlines()[2].startswith("angular_momentum: max |residual|")
    assert set(b.max()) == {"energy", "linear_momentum", "angular_momentum"}


def test_balance_arrays_are_read_only():
    b = rd.simulate(rd.Particle(1.0), rd.ParticleState(), 0.1, 3, error=False).balance
    with pytest.raises(ValueError):
        b.energy[0] = 1.0


@pytest.mark.parametrize("field, value", [("energy", np.zeros((2, 2))), ("verdict", {"energy": "closed"})])
def test_balance_refuses_bad_fields(field, value):
    args = dict(energy=np.zeros(2), linear_momentum=np.zeros(2), angular_momentum=np.zeros(2),
                energy_round_off=np.zeros(2), linear_momentum_round_off=np.zeros(2),
                angular_momentum_round_off=np.zeros(2), energy_scale=np.ones(2), linear_momentum_scale=np.ones(2),
                angular_momentum_scale=np.ones(2),
                verdict={"energy": "closed", "linear_momentum": "closed", "angular_momentum": "closed"}, about="x")
    args[field] = value
    with pytest.raises((TypeError, ValueError), match=f"^{field}: expected"):
        rd.Balance(**args)
