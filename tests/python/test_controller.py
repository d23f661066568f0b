"""rigiddyn.Controller: a law sampled every period seconds of a scene run, its commands held (zero-order hold).

The samples are switch times of the run loop: the law sees t = t0 + k period exactly, no step straddles a sample
(a piecewise-constant thrust is integrated as exactly as a ScheduledLoads schedule), rk4 keeps its order 4 on a
controlled run, and the hold equals the equivalent ScheduledLoads schedule bit for bit. The shipped laws against
closed forms: B-dot's rate decay exp(-k |B|^2 t / I) on a sphere in a uniform field; the PD pointing loop's small
error against the exact sampled-data (zero-order hold) solution of A theta'' = tau_k and the continuous
A theta'' + k_d theta' + k_p theta = 0. Joint motors of trees commanded from the sampled joint states: the held
forces equal motor windows bit for bit, and a hinge's PD loop is the exact sampled-data recursion. Bad inputs are
named.
"""

from __future__ import annotations

import dataclasses
import math
import pickle
from types import SimpleNamespace

import numpy as np
import pytest

import rigiddyn as rd
from _helpers import same_estimate
from rigiddyn.control import BDot, PDAttitude

EPS = np.finfo(float).eps


def thruster_scene(point_B=(0.0, 0.0, 0.0)):
    """A rigid body (m = 2 kg) with a thruster (a ScheduledLoads with no schedule: the controller commands it)."""
    body = rd.RigidBody(2.0, [0.5, 0.7, 0.9])
    return rd.Scene([body], elements=[rd.ScheduledLoads(body=0, loads=[], point_B=point_B)])


def test_law_sees_exact_sample_times():
    """t_k = t0 + k period for every sample before the end of the run, the period not a multiple of dt."""
    seen = []

    def law(state):
        seen.append(state.t)
        return {}

    t0, period, dt, steps = 0.7, 0.3, 0.125, 40  # the run ends at t0 + 5 s: samples k = 0 .. 16
    rd.simulate(thruster_scene(), [rd.RigidBodyState()], dt, steps, t0=t0, controller=rd.Controller(period, law))
    assert seen == [t0 + k * period for k in range(17)]


def test_state_is_the_state_at_the_sample():
    """The sampled state is the run's state at t_k: a body spinning at a constant rate about z (no load) has turned
    by w t_k there (rk4's error at dt = 0.01 on this free rotation: below 1e-12 rad)."""
    angles = []

    def law(state):
        q = state.q_WB[0]
        assert not state.q_WB.flags.writeable
        angles.append((state.t, 2.0 * math.atan2(q[2], q[3])))
        return {}

    rd.simulate(thruster_scene(), [rd.RigidBodyState(w_B=(0.0, 0.0, 0.5))], 0.01, duration=2.0,
                controller=rd.Controller(0.37, law))
    for t, angle in angles:
        assert angle == pytest.approx(0.5 * t, abs=1e-12)


def test_no_step_straddles_a_sample():
    """A thrust f_k = (k + 1) N held on [t_k, t_k+1), period 0.3 s, dt 0.2 s (the samples off the step grid): the
    velocity is piecewise linear in t and rk4 integrates each piece exactly, so v and p equal their closed forms to
    round-off (a step across a sample would err by O(dt |f|/m) = 0.1 m/s). Round-off: ~ 4 eps |v| per step."""
    period, dt, steps, m = 0.3, 0.2, 30, 2.0

    def law(state):
        k = round((state.t - 0.0) / period)
        return {0: ((k + 1) * 1.0, 0.0, 0.0)}

    result = rd.simulate(thruster_scene(), [rd.RigidBodyState()], dt, steps, controller=rd.Controller(period, law))
    t = result.t
    k = np.floor(t / period + 1e-9)  # the pieces before t: f = j + 1 on [j T, (j + 1) T)
    # v(t) = (1/m) [sum_{j<k} (j + 1) T + (k + 1)(t - k T)], p the integral of v
    v = (period * k * (k + 1) / 2 + (k + 1) * (t - k * period)) / m
    p = (period**2 * ((k - 1) * k * (k + 1) / 6 + k * (k + 1) / 4) + period * k * (k + 1) / 2 * (t - k * period)
         + (k + 1) * (t - k * period) ** 2 / 2) / m
    np.testing.assert_allclose(result.v_W[:, 0, 0], v, rtol=0, atol=4 * EPS * steps * v.max())
    np.testing.assert_allclose(result.p_W[:, 0, 0], p, rtol=0, atol=4 * EPS * steps * p.max())


def test_hold_equals_the_scheduled_loads_run_bit_for_bit():
    """A thruster off the centre of mass (a torque too) on a tumbling body, commanded f_k in B at each sample, is
    the same run as the ScheduledLoads schedule of the same forces on [t_k, t_k+1): same switch times, same loads,
    same arithmetic. A second body keeps both scenes on the generic model (one body would take the one-body path)."""
    period, dt, steps = 0.25, 0.1, 50
    forces = [(math.sin(k), math.cos(2.0 * k), 0.5) for k in range(21)]
    point_B = (0.1, -0.05, 0.2)
    bodies = [rd.RigidBody(2.0, [0.5, 0.7, 0.9]), rd.Particle(1.0)]
    schedule = [rd.AppliedLoad(force=f, frame="body", t_start=k * period, t_end=(k + 1) * period)
                for k, f in enumerate(forces)]
    scheduled = rd.Scene(bodies, elements=[rd.ScheduledLoads(body=0, loads=schedule, point_B=point_B)])
    commanded = rd.Scene(bodies, elements=[rd.ScheduledLoads(body=0, loads=[], point_B=point_B)])
    initial = [rd.RigidBodyState(w_B=(0.3, -0.2, 0.5)), rd.ParticleState()]

    def law(state):
        return {0: forces[round(state.t / period)]}

    a = rd.simulate(scheduled, initial, dt, steps, accuracy_level=None)
    b = rd.simulate(commanded, initial, dt, steps, controller=rd.Controller(period, law), accuracy_level=None)
    for name in ("p_W", "q_WB", "v_W", "w_B", "work"):
        np.testing.assert_array_equal(getattr(b, name), getattr(a, name), err_msg=name)


def sat_with_wheels():
    """A satellite (inertia 10, 12, 15 kg m^2 with its wheels locked) with three wheels (J = 0.05 kg m^2) on its
    principal axes."""
    body = rd.RigidBody(100.0, [10.0, 12.0, 15.0])
    return rd.Gyrostat(body, [rd.Wheel(axis, 0.05) for axis in np.eye(3)])


def test_rk4_keeps_order_four_under_a_controller():
    """A PD slew of 0.6 rad about an oblique axis (nonlinear: gyroscopic coupling, wheel momentum), sampled every
    0.3 s (off the step grid): the rk4 error of the final state against a run at 0.1/64 s (its own error 4096 times
    below the finest run's) drops by 2^4 = 16 per halving of dt. The commands depend on the sampled states, which
    differ between the runs by the method's error O(dt^4): the order is kept. The ratio is 16 (1 + c dt), the next
    term of the error expansion; at dt <= 0.1 s (|w| dt < 1e-2) within 15 % of 16."""
    sat = sat_with_wheels()
    law = PDAttitude(2.0, 6.0, np.eye(3))
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    q0 = np.append(math.sin(0.3) * axis, math.cos(0.3))
    initial = rd.GyrostatState(q_WB=q0, w_B=(0.01, -0.02, 0.015), wheel_speeds=[0.0, 0.0, 0.0])

    def final(dt):
        r = rd.simulate(sat, initial, dt, duration=8.0, method="rk4", error=False,
                        controller=rd.Controller(0.3, law))
        return np.concatenate([r.w_B[-1, 0], r.q_WB[-1, 0], r.wheel_speed[-1]])

    reference = final(0.1 / 64)
    errors = [np.abs(final(dt) - reference).max() for dt in (0.1, 0.05, 0.025)]
    for coarse, fine in zip(errors, errors[1:]):
        assert 16 * 0.85 < coarse / fine < 16 * 1.15, errors


def test_a_run_under_a_law_in_cpp_estimates_its_error_and_one_in_python_names_why_not():
    """The PD slew above at dt = 0.025 s carries its global error estimate (Richardson with the runs at 2h and 4h,
    each under a fresh copy of the law): the step ratio 16 holds within 15 % up to 4h = 0.1 s (the test above), so
    the estimate is the true error (against the run at 0.1/64 s, whose own error is 16^4 times smaller) to within
    that, where the truncation error dominates the round-off (1e-14 over these 320 steps): at the record of the
    largest error, mid-slew (about 8e-13 rad). Asserted within a factor 2, the effectivity the estimator promises on
    reliable records. A law in Python not declared repeatable gets no estimate: result.error names why."""
    sat = sat_with_wheels()
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    initial = rd.GyrostatState(q_WB=np.append(math.sin(0.3) * axis, math.cos(0.3)), w_B=(0.01, -0.02, 0.015),
                               wheel_speeds=[0.0, 0.0, 0.0])

    def run(dt, law, error):
        return rd.simulate(sat, initial, dt, duration=8.0, method="rk4", error=error, record_every=round(0.4 / dt),
                           controller=rd.Controller(0.3, law))

    law = PDAttitude(2.0, 6.0, np.eye(3))
    r, reference = run(0.025, law, True), run(0.1 / 64, law, False)
    attitude = np.array([rd.angular_distance(q, q_ref) for q, q_ref in zip(r.q_WB[:, 0], reference.q_WB[:, 0])])
    rate = np.linalg.norm(r.w_B[:, 0] - reference.w_B[:, 0], axis=1)
    for estimate, true in ((r.error.attitude[:, 0], attitude), (r.error.angular_velocity[:, 0], rate)):
        i = np.argmax(true)
        assert r.error.reliable[i]
        assert 0.5 < estimate[i] / true[i] < 2.0, (r.t[i], estimate[i], true[i])
    assert run(0.1, lambda state: {}, True).error.verdict[-1].startswith("no estimate: the controller's law in Python")


# B-dot on a sphere of inertia I in a uniform field B along z, w0 normal to B, held every T seconds
BDOT_I, BDOT_B, BDOT_K, BDOT_T = 0.1, 3e-5, 1e6, 0.5
BDOT_W0 = np.array([0.03, -0.04, 0.0])
BDOT_LAMBDA = BDOT_K * BDOT_B**2 / BDOT_I


def bdot_decay(rate):
    """(t, ln(|w_perp| / closed form)) of 300 s of B-dot with the `rate` estimate, the closed form
    |w0| exp(-lambda t), lambda = k |B|^2 / I; and |w_perp| at the start and the end."""
    field = rd.MagneticDipole(m_B=(0.0, 0.0, 0.0), B_W=(0.0, 0.0, BDOT_B))
    scene = rd.Scene([rd.RigidBody(10.0, [BDOT_I, BDOT_I, BDOT_I])], elements=[field])
    result = rd.simulate(scene, [rd.RigidBodyState(w_B=BDOT_W0)], 0.05, duration=300.0, record_every=20,
                         controller=rd.Controller(BDOT_T, BDot(BDOT_K, field, element=0, rate=rate)))
    w_W = np.einsum("nij,nj->ni", rd.quat_to_matrix(result.q_WB[:, 0]), result.w_B[:, 0])
    w_perp = np.linalg.norm(w_W[:, :2], axis=1)
    closed = np.linalg.norm(BDOT_W0) * np.exp(-BDOT_LAMBDA * result.t)
    return result.t, np.log(w_perp / closed), w_perp[0], w_perp[-1]


def test_bdot_rate_decays_as_its_closed_form():
    """B-dot (gyro rate form): the torque m x B_B = -k |B|^2 w_perp gives |w_perp(t)| = |w0| exp(-lambda t)
    (w_par = 0 stays 0). Held over a period, the decay is (1 - lambda T) per period instead of exp(-lambda T): |ln|
    grows by lambda^2 T t / 2 (to first order). The hold keeps m fixed in B while B_B turns by |w| T: the torque's
    direction errs by O(|w| T), which turns w_perp about B without changing its size to first order, and its size
    by O((|w| T)^2) per period: lambda t (|w0| T)^2."""
    t, log_ratio, first, last = bdot_decay("gyro")
    lam, T = BDOT_LAMBDA, BDOT_T
    bound = lam**2 * T * t / 2 + lam * t * (np.linalg.norm(BDOT_W0) * T) ** 2 + 1e-12  # + round-off at t = 0
    assert np.all(np.abs(log_ratio) <= bound)
    assert last < 0.1 * first  # it detumbles: lambda t = 2.7


def test_bdot_difference_form_detumbles():
    """The finite-difference estimate (B_k - B_k-1)/T needs no gyro: it damps the same rate, its command zero at the
    first sample (ln errs by lambda T) and its estimate the rate at t_k - T/2, when w_perp was larger by
    lambda T / 2 (lambda^2 T t / 2 more than the gyro form's bound above)."""
    t, log_ratio, _, _ = bdot_decay("difference")
    lam, T = BDOT_LAMBDA, BDOT_T
    bound = lam * T + lam**2 * T * t + lam * t * (np.linalg.norm(BDOT_W0) * T) ** 2
    assert np.all(np.abs(log_ratio) <= bound)


def pd_response(k_p, k_d, T, theta0, duration):
    """The PD loop about z from theta0 at rest: (t, theta(t)) of the run, and A = the transverse inertia about z."""
    sat = sat_with_wheels()
    A = sat.transverse_inertia[2, 2]
    q0 = (0.0, 0.0, math.sin(theta0 / 2), math.cos(theta0 / 2))
    r = rd.simulate(sat, rd.GyrostatState(q_WB=q0, wheel_speeds=[0.0, 0.0, 0.0]), T / 10, duration=duration,
                    error=False, controller=rd.Controller(T, PDAttitude(k_p, k_d, np.eye(3))))
    q = r.q_WB[:, 0]
    return r.t, 2.0 * np.arctan2(q[:, 2], q[:, 3]), A


def test_pd_small_error_against_the_sampled_data_solution():
    """A small error (1e-3 rad) about z: one-axis motion (w and the wheel's momentum along z: no gyroscopic torque),
    A theta'' = tau_k = -k_p e_k - k_d w_k held on [t_k, t_k+1), e = 2 sin(theta/2). Its exact solution at the
    samples is the linear recurrence theta_k+1 = theta_k + w_k T + tau_k T^2/(2A), w_k+1 = w_k + tau_k T/A, up to
    the nonlinearity of e: relative theta^2/24 < 1e-7. rk4 (dt = T/10) integrates the held pieces (quadratic in t)
    exactly; the bound 1e-7 theta0 holds both."""
    k_p, k_d, T, theta0 = 3.0, 8.0, 0.1, 1e-3
    t, theta, A = pd_response(k_p, k_d, T, theta0, 20.0)
    x, w = theta0, 0.0
    expected = [x]
    for _ in range(200):
        tau = -k_p * x - k_d * w
        x, w = x + w * T + tau * T**2 / (2 * A), w + tau * T / A
        expected.append(x)
    np.testing.assert_allclose(theta[::10], expected, rtol=0, atol=1e-7 * theta0)


def test_pd_closed_loop_is_the_damped_oscillator():
    """Sampled fast (omega_n T = 0.045), the loop is A theta'' + k_d theta' + k_p theta = 0: theta0 e^(-zeta w_n t)
    (cos w_d t + zeta/sqrt(1-zeta^2) sin w_d t), omega_n = sqrt(k_p/A), zeta = k_d/(2 sqrt(k_p A)). The hold delays
    the torque by T/2 on average: a phase and damping error of O(omega_n T), bounded by omega_n T theta0."""
    k_p, k_d, T, theta0 = 3.0, 4.0, 0.1, 1e-3
    t, theta, A = pd_response(k_p, k_d, T, theta0, 20.0)
    w_n, zeta = math.sqrt(k_p / A), k_d / (2 * math.sqrt(k_p * A))
    assert 0.1 < zeta < 1  # underdamped: the oscillation is seen
    w_d = w_n * math.sqrt(1 - zeta**2)
    closed = theta0 * np.exp(-zeta * w_n * t) * (np.cos(w_d * t) + zeta / math.sqrt(1 - zeta**2) * np.sin(w_d * t))
    assert np.abs(theta - closed).max() <= w_n * T * theta0


def test_bad_period_and_law_are_named():
    for period in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(ValueError, match="period: expected a finite number > 0"):
            rd.Controller(period, lambda s: {})
    with pytest.raises(TypeError, match="law: expected a callable"):
        rd.Controller(0.1, 3.0)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="w_B_noise"):
        rd.Controller(0.1, lambda s: {}, w_B_noise=-1.0)


def run(law, scene=None, **kwargs):
    scene = scene if scene is not None else thruster_scene()
    return rd.simulate(scene, [rd.RigidBodyState()], 0.1, 10, controller=rd.Controller(0.25, law), **kwargs)


def test_bad_commands_are_named():
    with pytest.raises(ValueError, match=r"controller.law\(t=0\)\[0\]: expected shape \(3,\)"):
        run(lambda s: {0: (1.0, 2.0)})
    with pytest.raises(ValueError, match=r"controller.law\(t=0.25\)\[0\]: expected finite values"):
        run(lambda s: {0: (math.nan if s.t > 0 else 0.0, 0.0, 0.0)})
    with pytest.raises(ValueError, match=r"controller.law\(t=0\)\[3\]: expected the index of an element in \[0, 1\)"):
        run(lambda s: {3: (0.0, 0.0, 0.0)})
    gravity = rd.Scene([rd.RigidBody(1.0, [1.0, 1.0, 1.0])], elements=[rd.UniformGravity()])
    with pytest.raises(ValueError, match=r"\[0\]: expected a MagneticDipole or a ScheduledLoads"):
        run(lambda s: {0: (0.0, 0.0, 0.0)}, gravity)
    with pytest.raises(ValueError, match=r"expected shape \(0,\) \[N m\]"):
        run(lambda s: {"wheel_torque": [1.0]})
    with pytest.raises(ValueError, match="expected the key 'wheel_torque' or an element index"):
        run(lambda s: {"thrust": (0.0, 0.0, 0.0)})
    with pytest.raises(TypeError, match="expected a dict of commands"):
        run(lambda s: [0.0, 0.0, 0.0])


def test_a_law_that_raises_stops_the_run():
    def law(state):
        if state.t >= 0.5:
            raise ZeroDivisionError("no attitude estimate")
        return {}

    with pytest.raises(ZeroDivisionError, match="no attitude estimate") as info:
        run(law)
    assert "raised by controller.law(t=0.5)" in info.value.__notes__


def test_a_body_takes_a_controller_as_its_one_body_scene():
    """simulate(body, ..., controller=) is the run of the body's one-body scene with it: the same records."""
    body, start = rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.1, 0.2, 0.3])
    seen = {"body": 0, "scene": 0}

    def law(key):
        def command(sampled):
            seen[key] += 1
            return {}
        return command

    alone = rd.simulate(body, start, 0.1, 10, controller=rd.Controller(0.25, law("body")))
    scene = rd.simulate(rd.Scene([body]), [start], 0.1, 10, controller=rd.Controller(0.25, law("scene")))
    assert seen["body"] == seen["scene"] > 0
    for field in ("t", "q_WB", "w_B"):
        np.testing.assert_array_equal(getattr(alone, field), getattr(scene, field), strict=True, err_msg=field)


def test_a_law_tolerance_cannot_rerun_or_not_a_controller_is_refused():
    """tolerance= reruns the law (pilots, the run, its certificate): a law in Python not declared repeatable is refused,
    and so is a duration off the grid of period / 4 that every run's step must divide."""
    with pytest.raises(ValueError, match="tolerance: expected None under a controller whose law in Python is sampled "
                                         "by the run alone"):
        rd.simulate(thruster_scene(), [rd.RigidBodyState()], duration=1.0, tolerance=1e-6,
                    controller=rd.Controller(0.25, lambda s: {}))
    with pytest.raises(ValueError, match=r"duration: expected a whole number of controller.period / 4 = 0.0625 s .*"
                                         r"got 1.01 s"):
        rd.simulate(thruster_scene(), [rd.RigidBodyState()], duration=1.01, tolerance=1e-6,
                    controller=rd.Controller(0.25, lambda s: {}, repeatable=True))
    with pytest.raises(TypeError, match="controller: expected a rigiddyn.Controller"):
        rd.simulate(thruster_scene(), [rd.RigidBodyState()], 0.1, 10, controller=lambda s: {})
    # a grid finer than the cost cap allows: the cap's message names the grid
    with pytest.raises(rd.ToleranceError, match=r"above max_steps = 1000 .* every run takes a multiple of 4000 steps"):
        rd.simulate(thruster_scene(), [rd.RigidBodyState()], duration=1.0, tolerance=1e-6, max_steps=1000,
                    controller=rd.Controller(0.001, lambda s: {}, repeatable=True))


def test_gyro_noise_is_drawn_from_the_seed():
    """w_B_noise adds N(0, sigma^2) draws of numpy.random.default_rng(seed) to the sampled w_B: the same seed, the
    same draws; the law sees the noisy rate, the run's records stay exact (the body at rest stays at rest)."""
    def noisy_rates(seed):
        seen = []
        controller = rd.Controller(0.25, lambda s: seen.append(s.w_B[0].copy()) or {}, w_B_noise=1e-3, seed=seed)
        r = rd.simulate(thruster_scene(), [rd.RigidBodyState()], 0.1, 10, controller=controller)
        assert np.all(r.w_B == 0.0)
        return np.array(seen)

    a, b = noisy_rates(7), noisy_rates(7)
    np.testing.assert_array_equal(a, b)
    expected = np.random.default_rng(7).normal(0.0, 1e-3, (len(a), 1, 3))[:, 0]
    np.testing.assert_array_equal(a, expected)


def test_pd_law_allocates_the_torque_to_redundant_wheels():
    """Four wheels (a pyramid) make the body torque tau_B = -A u by the least-norm u = -pinv(A) tau_B."""
    axes = np.array([[1.0, 0.0, 1.0], [-1.0, 0.0, 1.0], [0.0, 1.0, 1.0], [0.0, -1.0, 1.0]]) / math.sqrt(2)
    law = PDAttitude(2.0, 1.0, axes)
    state = rd.SampledState(0.0, np.zeros((1, 3)), np.array([[0.0, 0.0, 0.0, 1.0]]), np.zeros((1, 3)),
                            np.array([[0.1, -0.2, 0.3]]), np.zeros(4))
    u = law(state)["wheel_torque"]
    np.testing.assert_allclose(-axes.T @ u, -1.0 * state.w_B[0], rtol=0, atol=1e-15)


def test_control_module_examples_run():
    """The examples of rigiddyn.control's laws (not in rigiddyn.__all__, so not collected by test_docstrings)."""
    import doctest

    import rigiddyn.control

    failures, attempted = doctest.testmod(rigiddyn.control, extraglobs={"np": np, "rd": rd},
                                          optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert attempted > 0 and failures == 0


def shipped_law_runs():
    """(name, scene, initial, law, period, dt, duration) of each shipped law's C++ path."""
    field = rd.MagneticDipole(m_B=(0.0, 0.0, 0.0), B_W=(1e-5, -2e-5, 3e-5))
    tumbling = rd.Scene([rd.RigidBody(10.0, [0.08, 0.1, 0.12])], elements=[field])
    w0 = [rd.RigidBodyState(w_B=(0.03, -0.04, 0.02))]
    scene, initial, _ = rd.load_scene("cubesat_pointing")
    A = scene.bodies[0].transverse_inertia[0, 0]
    k_p, k_d = A * 0.05**2, 2 * 0.7 * A * 0.05
    q = (0.1, -0.2, 0.05, 1.0)
    return [
        ("bdot gyro", tumbling, w0, BDot(2e5, field, element=0, m_max=0.05), 0.5, 0.1, 60.0),
        ("bdot difference", tumbling, w0, BDot(2e5, field, element=0, rate="difference"), 0.5, 0.1, 60.0),
        ("pd fixed", sat_with_wheels(), rd.GyrostatState(w_B=(0.01, 0.0, -0.01), wheel_speeds=[0.0] * 3),
         PDAttitude(2.0, 6.0, np.eye(3), q_target_WB=q), 0.2, 0.05, 20.0),
        ("pd lvlh", scene, initial, PDAttitude(k_p, k_d, np.eye(3), q_target_WB="lvlh"), 0.5, 0.1, 120.0),
    ]


@pytest.mark.parametrize("name, scene, initial, law, period, dt, duration", shipped_law_runs(),
                         ids=[r[0] for r in shipped_law_runs()])
def test_shipped_laws_run_in_cpp_as_their_python_reference(monkeypatch, name, scene, initial, law, period, dt,
                                                             duration):
    """simulate runs BDot and PDAttitude as C++ laws (scene/control_laws.hpp: no GIL at the samples); a lambda
    around the same law runs its Python reference. The two evaluate the same formulas in another order (the
    quaternion rotation, the normalisations): a few ulps per sample, which the contracting loops do not grow:
    the records agree within samples x 16 eps of their scale."""
    python = rd.simulate(scene, initial, dt, duration=duration, error=False,
                         controller=rd.Controller(period, lambda s: law(s)))
    if "difference" in name:
        law._last = None  # the Python law remembers its last sample; the C++ one starts afresh each run
    monkeypatch.setattr(type(law), "__call__", lambda self, s: pytest.fail("the shipped law ran in Python"))
    core = rd.simulate(scene, initial, dt, duration=duration, error=False, controller=rd.Controller(period, law))
    samples = duration / period
    for field in ("q_WB", "w_B", "wheel_speed"):
        a, b = np.asarray(getattr(core, field)), np.asarray(getattr(python, field))
        np.testing.assert_allclose(a, b, rtol=0, atol=samples * 16 * EPS * np.abs(b).max(initial=0.0), err_msg=field)
    # the laws act: the rates change by far more than the tolerance
    assert np.abs(python.w_B[-1] - python.w_B[0]).max() > 1e3 * samples * 16 * EPS * np.abs(python.w_B).max()


def test_bdot_on_the_shipped_cubesat_follows_the_orbit_averaged_decay():
    """The shipped cubesat_detumbling (an isotropic body, I w_W' = -k (|B|^2 1 - B B^T) w_W, the field of the
    Earth's dipole turning along a polar orbit): at whole orbits the rate is the orbit average's
    exp(-(k/I) <|B|^2 1 - B B^T> t) w(0) within eps |w(0)|, eps = lambda_max T_orb / (2 pi) (first-order
    averaging over the decay time; docs/examples/plot_cubesat_detumbling.py)."""
    from rigiddyn.control import dipole_field_W

    scene, initial, options = rd.load_scene("cubesat_detumbling")
    dipole, I = scene.elements[1], scene.bodies[0].inertia_com[0, 0]
    r = np.linalg.norm(initial[0].p_W)
    T_orb = 2 * np.pi * np.sqrt(r**3 / scene.elements[0].gm)
    u = np.linspace(0.0, 2 * np.pi, 1024, endpoint=False)
    B = np.array([dipole_field_W(dipole, r * np.array([np.cos(a), 0.0, np.sin(a)])) for a in u])
    M_bar = np.mean([(b @ b) * np.eye(3) - np.outer(b, b) for b in B], axis=0)
    k = 0.5 * I / (np.trace(M_bar) / 3 * T_orb)
    lam, V = np.linalg.eigh(k * M_bar / I)
    eps = lam.max() * T_orb / (2 * np.pi)
    result = rd.simulate(scene, initial, options.dt, duration=2 * T_orb - np.fmod(2 * T_orb, options.dt),
                         record_every=options.record_every, error=False,
                         controller=rd.Controller(1.0, BDot(k, dipole, element=1)))
    w_W = np.einsum("nij,nj->ni", rd.quat_to_matrix(result.q_WB[:, 0]), result.w_B[:, 0])
    for j in (1, 2):
        i = int(np.argmin(np.abs(result.t - j * T_orb)))
        w_bar = V @ (np.exp(-lam * result.t[i]) * (V.T @ w_W[0]))
        assert np.linalg.norm(w_W[i] - w_bar) <= eps * np.linalg.norm(w_W[0])


@pytest.mark.parametrize("noise", [0.0, 1e-6])  # the C++ law, and the Python one (gyro noise)
def test_a_bdot_law_must_command_a_magnetic_dipole(noise):
    """A ScheduledLoads takes a command too (a force): a BDot pointed at one is refused before the run, naming
    controller.law.element and the element's type, on either path of the law."""
    dipole = rd.MagneticDipole(m_B=(0.0, 0.0, 0.0), B_W=(0.0, 0.0, 2e-5))
    scene = rd.Scene([rd.RigidBody(1.0, [1e-3, 1e-3, 1e-3])], elements=[dipole, rd.ScheduledLoads(body=0, loads=[])])
    law = rd.control.BDot(1e4, dipole, element=1)
    with pytest.raises(ValueError, match=r"^controller\.law\.element: expected the index of a MagneticDipole .*"
                                         r"got 1 \(a ScheduledLoads\)"):
        rd.simulate(scene, [rd.RigidBodyState(w_B=(0.1, 0.0, 0.0))], 0.1, steps=2,
                    controller=rd.Controller(0.5, law, w_B_noise=noise, seed=1))


# ---------------------------------------------------------------- wheel-speed commands to a ReactionWheel
def wheel_scene(speed=0.0):
    """A body (I = diag(2, 3, 4) kg m^2, wheel included) at rest with a ReactionWheel (J = 0.25 kg m^2) about its
    principal axis z, spinning at `speed` [rad/s]."""
    wheel = rd.ReactionWheel(body=0, axis_B=(0.0, 0.0, 1.0), inertia=0.25, speed=speed)
    return rd.Scene([rd.RigidBody(10.0, [2.0, 3.0, 4.0])], elements=[wheel])


def test_a_commanded_wheel_speed_turns_the_body_by_minus_j_delta_omega_over_i():
    """About a principal axis of a body at rest the wheel's torque is -J dOmega/dt a (w_B x h = 0, w_B x I w_B = 0),
    so I dw_z/dt = -J dOmega/dt: w_z = -J (Omega(t) - Omega(0))/I at every t (the total angular momentum I w_z + J
    Omega conserved). The commanded speeds 3, -1, -1, 0.5 rad/s at the samples 0, 0.4, 0.8, 1.2 s are each reached
    at the next sample by a constant-rate ramp; the rate is constant over each sub-step, so rk4 is exact here: the
    bound is the round-off of the steps' sums, 4 eps max |w| per (sub-)step over the 20 steps and 3 sample splits."""
    J, I, period = 0.25, 4.0, 0.4
    commands = {0.0: 3.0, 0.4: -1.0, 0.8: -1.0, 1.2: 0.5}
    law = lambda state: {0: commands[round(state.t, 12)]}  # noqa: E731
    r = rd.simulate(wheel_scene(1.0), [rd.RigidBodyState()], 0.08, duration=1.6, method="rk4",
                    controller=rd.Controller(period, law))
    samples = period * np.arange(5)
    omega = np.array([1.0, 3.0, -1.0, -1.0, 0.5])  # the wheel's speed at the samples, from its own 1 rad/s
    w_max = J * np.abs(omega - omega[0]).max() / I
    want = -J * (np.interp(r.t, samples, omega) - omega[0]) / I  # Omega(t) linear between the samples
    assert np.abs(r.w_B[:, 0, :2]).max() == 0.0
    assert np.abs(r.w_B[:, 0, 2] - want).max() <= 4 * EPS * 23 * w_max


def test_a_number_is_refused_by_an_element_that_takes_none():
    """A number commanded to a ScheduledLoads names the element and its type; a (3,) value to a ReactionWheel
    names it too; a non-finite speed names the sample time."""
    with pytest.raises(ValueError, match=r"controller\.law\(t=0\)\[0\]: expected a ReactionWheel \(a speed \[rad/s\]\), "
                                         r"a RevoluteMotor \(a torque \[N m\]\) or a PrismaticMotor \(a force \[N\]\), "
                                         r"the elements that take a number, got element 0 \(a ScheduledLoads\)"):
        rd.simulate(thruster_scene(), [rd.RigidBodyState()], 0.1, steps=3,
                    controller=rd.Controller(0.1, lambda state: {0: 1.0}))
    with pytest.raises(ValueError, match=r"controller\.law\(t=0\)\[0\]: expected a MagneticDipole or a "
                                         r"ScheduledLoads .*, got element 0 \(a ReactionWheel\)"):
        rd.simulate(wheel_scene(), [rd.RigidBodyState()], 0.1, steps=3,
                    controller=rd.Controller(0.1, lambda state: {0: (1.0, 0.0, 0.0)}))
    with pytest.raises(ValueError, match=r"controller\.law\(t=0\.20000000000000001\)\[0\]: expected finite values, "
                                         r"got nan"):
        rd.simulate(wheel_scene(), [rd.RigidBodyState()], 0.1, steps=3,
                    controller=rd.Controller(0.1, lambda state: {0: 1.0 if state.t < 0.15 else math.nan}))
    with pytest.raises(ValueError, match=r"controller\.law\(t=0\)\[0\]: expected shape \(3,\) .* or a number"):
        rd.simulate(wheel_scene(), [rd.RigidBodyState()], 0.1, steps=3,
                    controller=rd.Controller(0.1, lambda state: {0: (1.0, 2.0)}))


# ---------------------------------------------------------------- joint motors of trees
def telescope(motors):
    """An arm hinged about z at the world's origin with a slider along it (a RevoluteJoint, then a PrismaticJoint
    along x), no gravity, and the joint motors `motors` ((kind, body, value, t_start, t_end) tuples) in its joints."""
    tree = rd.Tree()
    tree.add_link("arm", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.5, 0.0, 0.0],
                                                                                   np.diag([0.01, 0.2, 0.2])))
    tree.add_link("slider", 0, rd.PrismaticJoint([1.0, 0.0, 0.0]), rd.SpatialInertia(1.0, [0.0, 0.0, 0.0],
                                                                                     np.diag([0.01, 0.01, 0.01])),
                  rd.Transform(translation=[0.5, 0.0, 0.0]))
    scene = rd.Scene()
    scene.add_tree(tree, "arm")
    for kind, body, value, t_start, t_end in motors:
        scene.add(rd.RevoluteMotor(body=body, torque=value, t_start=t_start, t_end=t_end) if kind == "revolute" else
                  rd.PrismaticMotor(body=body, force=value, t_start=t_start, t_end=t_end))
    return tree, scene


def test_commanded_joint_forces_are_held_as_motor_windows_bit_for_bit():
    """A PD law on the joints (from state.joint_q and state.joint_v) commanding the hinge's RevoluteMotor and the
    slider's PrismaticMotor is the run of the same forces as motor windows [t_k, t_k+1): same switch times, same
    wrenches in the same order, the same arithmetic. The period is off the step grid (the steps are split)."""
    period, dt, steps = 0.05, 0.02, 60
    tree, commanded = telescope([("revolute", 0, 0.0, -math.inf, math.inf), ("prismatic", 1, 0.0, -math.inf, math.inf)])
    initial = tree.joint_states([0.5, 0.2], [0.0, -0.3])
    windows = []

    def law(state):
        k = round(state.t / period)
        tau = -8.0 * (state.joint_q - [1.0, 0.0]) - 2.0 * state.joint_v
        windows.extend([("revolute", 0, tau[0], k * period, (k + 1) * period),
                        ("prismatic", 1, tau[1], k * period, (k + 1) * period)])
        return {0: tau[0], 1: tau[1]}

    a = rd.simulate(commanded, initial, dt, steps, method="rk4", controller=rd.Controller(period, law), error=False)
    _, windowed = telescope(windows)
    b = rd.simulate(windowed, initial, dt, steps, method="rk4", error=False)
    for name in ("joint_q", "joint_v", "p_W", "q_WB"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    assert abs(a.joint_q[-1, 0] - 1.0) < abs(a.joint_q[0, 0] - 1.0)  # the loop pulls the hinge towards 1 rad


def test_a_joint_pd_loop_follows_the_sampled_data_recursion():
    """A wheel (I = 0.5 kg m² about its hinge) under τ_k = k_p (θ_ref − θ_k) − k_d ω_k held over each period T:
    between samples θ is a quadratic in t, which rk4 integrates exactly, so the run is the exact sampled-data
    recursion θ_k+1 = θ_k + T ω_k + T² τ_k / (2 I), ω_k+1 = ω_k + T τ_k / I to round-off (a few eps |θ| per step,
    over the 300 steps). The law sees the run's joint state at each sample."""
    tree = rd.Tree()
    tree.add_link("wheel", -1, rd.RevoluteJoint([0.0, 0.0, 1.0]), rd.SpatialInertia(2.0, [0.0, 0.0, 0.0],
                                                                                     0.5 * np.eye(3)))
    scene = rd.Scene()
    scene.add(rd.RevoluteMotor(body=scene.add_tree(tree)[0], torque=0.0))
    I, T, k_p, k_d, ref = 0.5, 0.02, 8.0, 4.0, 1.0
    seen = []

    def law(state):
        seen.append((state.t, state.joint_q[0], state.joint_v[0]))
        return {0: k_p * (ref - state.joint_q[0]) - k_d * state.joint_v[0]}

    run = rd.simulate(scene, tree.joint_states([0.0]), 0.01, 300, method="rk4", controller=rd.Controller(T, law),
                      error=False)
    theta, omega = 0.0, 0.0
    for k, (t, theta_seen, omega_seen) in enumerate(seen):
        assert t == k * T and theta_seen == run.joint_q[2 * k, 0] and omega_seen == run.joint_v[2 * k, 0]
        assert abs(theta_seen - theta) <= 8 * EPS * (2 * k + 1) and abs(omega_seen - omega) <= 8 * EPS * (2 * k + 1)
        tau = k_p * (ref - theta) - k_d * omega
        theta, omega = theta + T * omega + T * T * tau / (2 * I), omega + T * tau / I
    assert abs(run.joint_q[-1, 0] - ref) < 1e-3  # settled (critically damped at 4 rad/s, 3 s)


def test_monte_carlo_of_a_tree_under_a_joint_law():
    """Dispersed joint states under a joint-space law: each sample is simulate of its drawn joint state, bit for bit."""
    tree, scene = telescope([("revolute", 0, 0.0, -math.inf, math.inf)])
    law = lambda state: {0: -5.0 * state.joint_q[0] - 1.0 * state.joint_v[0]}  # noqa: E731
    nominal = tree.joint_states([0.3, 0.1])
    run = rd.monte_carlo(scene, nominal, 3, seed=7, dt=0.02, steps=25, error=False,
                         dispersions={"arm.arm.q": rd.dispersion.Normal(std=0.1)}, controller=rd.Controller(0.05, law))
    for i in range(3):
        states = [rd.JointState(run.inputs["arm.arm.q"][i], [0.0]), nominal[1]]
        one = rd.simulate(scene, states, 0.02, 25, error=False, controller=rd.Controller(0.05, law))
        np.testing.assert_array_equal(run.values("joint_q")[i], one.joint_q)


# ---------------------------------------------------------------- the [controller] table of scene files
BDOT_FILE = '''
[[body]]
name = "sat"
kind = "rigid"
mass = 10.0
inertia = [0.08, 0.1, 0.12]
w_B = ["2 deg/s", -0.04, 0.02]
[[force]]
type = "uniform_gravity"
g_W = [0, 0, 0]
[[force]]
type = "magnetic_dipole"
m_B = [0, 0, 0]
B_W = ["10 uT", "-20 uT", "30 uT"]
[controller]
period = "500 ms"
law = "bdot"
gain = "2e5 A*m^2*s/T"
element = 1
m_max = "0.05 A*m^2"
body = "sat"
w_B_noise = "0.01 deg/s"
seed = 7
'''


def test_a_controller_table_reads_with_units_and_writes_back():
    """[controller] gives RunOptions.controller: a Controller of the law it names, each quantity in SI; the
    canonical file (scene_to_toml with the run options) holds it and reads back to the same controller, whose
    run (the same seed: the same gyro noise) is the same bit for bit."""
    scene, initial, run = rd.load_scene(BDOT_FILE)
    c = run.controller
    assert (c.period, c.w_B_noise, c.seed) == (0.5, math.radians(0.01), 7)
    assert isinstance(c.law, BDot) and (c.law.gain, c.law.element, c.law.m_max, c.law.body) == (2e5, 1, 0.05, 0)
    assert c.law.dipole == scene.elements[1]
    text = scene.to_toml(initial, run)
    assert "[controller]" in text
    again = rd.load_scene(text).run.controller
    assert (again.period, again.w_B_noise, again.seed) == (c.period, c.w_B_noise, c.seed)
    assert vars(again.law).keys() == vars(c.law).keys()
    assert all(getattr(again.law, k) == getattr(c.law, k) for k in ("gain", "element", "m_max", "body", "rate"))
    runs = [rd.simulate(scene, initial, 0.1, duration=5.0, error=False, controller=controller)
            for controller in (rd.load_scene(BDOT_FILE).run.controller, again)]
    np.testing.assert_array_equal(runs[0].w_B, runs[1].w_B)
    assert np.abs(runs[0].w_B[-1] - runs[0].w_B[0]).max() > 1e-3  # the law acts


def test_the_shipped_cubesat_scenes_carry_their_controllers():
    """cubesat_detumbling's [controller] is B-dot on its magnetorquer every second, cubesat_pointing's the PD law
    to LVLH every 0.5 s with k_p = A w_n^2, k_d = 2 zeta A w_n (w_n = 0.05 rad/s, zeta = 0.7: the decimals of the
    file, to their rounding); each writes back to a file that reads back to the same law."""
    _, _, run = rd.load_scene("cubesat_detumbling")
    assert isinstance(run.controller.law, BDot) and run.controller.period == 1.0 and run.controller.law.element == 1
    scene, initial, run = rd.load_scene("cubesat_pointing")
    law = run.controller.law
    assert isinstance(law, PDAttitude) and law.q_target_WB == "lvlh" and run.controller.period == 0.5
    A = scene.bodies[0].transverse_inertia[0, 0]
    assert math.sqrt(law.k_p / A) == pytest.approx(0.05, rel=4 * EPS)
    assert law.k_d / (2 * math.sqrt(law.k_p * A)) == pytest.approx(0.7, rel=4 * EPS)
    np.testing.assert_array_equal(law.axes_B, np.eye(3))  # the gyrostat's wheels
    again = rd.load_scene(scene.to_toml(initial, run)).run.controller.law
    assert (again.k_p, again.k_d, again.q_target_WB) == (law.k_p, law.k_d, law.q_target_WB)


def test_a_pd_controller_table_takes_a_quaternion_target_and_axes():
    """target = [x, y, z, w] and axes_B (any lengths, normalised) on a rigid body with ReactionWheel-free axes:
    the law as PDAttitude(k_p, k_d, axes_B, q_target_WB=target) builds it; written back with its axes."""
    text = BDOT_FILE.split("[controller]")[0] + '''[controller]
period = 0.2
law = "pd_attitude"
k_p = "2 N*m/rad"
k_d = 6.0
target = [0.1, -0.2, 0.05, 1.0]
axes_B = [[2, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]
'''
    scene, initial, run = rd.load_scene(text)
    law = run.controller.law
    assert law.q_target_WB.tolist() == [0.1, -0.2, 0.05, 1.0]
    np.testing.assert_array_equal(law.axes_B[0], [1.0, 0.0, 0.0])
    assert "axes_B = [[1.0, 0.0, 0.0]" in scene.to_toml(initial, run)


@pytest.mark.parametrize("change, message", [
    (("law = \"bdot\"", "law = \"bdott\""), r"controller\.law: expected 'bdot' or 'pd_attitude', got 'bdott'"),
    (("gain =", "gian ="), r"controller\.gian: expected a key of a \[controller\] of law 'bdot'; did you mean 'gain'"),
    (("element = 1", "element = 0"), r"controller\.element: expected the index of a magnetic_dipole .*got 0 "
                                     r"\(a UniformGravity\)"),
    (("element = 1", "element = 2"), r"controller\.element: expected .* \(an integer in \[0, 2\)\), got 2"),
    (("period = \"500 ms\"", "period = \"500 kg\""), r"controller\.period: expected s"),
    (("body = \"sat\"", "body = \"sta\""), r"controller\.body: expected the name of a \[\[body\]\].*did you mean 'sat'"),
    (("seed = 7", "seed = -1"), r"controller\.seed: expected an integer >= 0, got -1"),
    (("gain = \"2e5 A*m^2*s/T\"", "k_p = 1.0"), r"controller\.k_p: expected a key of a \[controller\] of law 'bdot'"),
])
def test_a_bad_controller_table_is_named(change, message):
    with pytest.raises(ValueError, match=message):
        rd.load_scene(BDOT_FILE.replace(*change))


def test_a_pd_controller_on_a_body_without_wheels_needs_axes():
    text = BDOT_FILE.split("[controller]")[0] + '[controller]\nperiod = 1\nlaw = "pd_attitude"\nk_p = 1\nk_d = 1\n'
    with pytest.raises(ValueError, match=r"controller\.body: expected a gyrostat .*, got 0 \(a RigidBody\)"):
        rd.load_scene(text)


def test_a_law_in_python_cannot_be_written_to_a_file():
    scene, initial, run = rd.load_scene(BDOT_FILE)
    python = dataclasses.replace(run, controller=rd.Controller(1.0, lambda state: {}))
    with pytest.raises(ValueError, match=r"scene\.controller\.law: expected a law a scene file can hold"):
        scene.to_toml(initial, python)


def test_the_cli_runs_a_scene_under_its_controller(tmp_path, capsys):
    """python -m rigiddyn simulate cubesat_pointing: the run is the one rd.simulate makes under the file's
    controller (the same records bit for bit), run.json records the [controller] and the run's global error
    estimate (its law runs in C++), and the summary gives the energy balance (the commands change the elements: no
    energy is conserved)."""
    import json

    from rigiddyn.__main__ import main

    out = tmp_path / "out"
    assert main(["simulate", "cubesat_pointing", "--duration", "30", "--no-plot", "--no-progress",
                 "--out", str(out)]) == 0
    assert "energy balance T(t) - T(0) - W(t)" in capsys.readouterr().out
    record = json.loads((out / "run.json").read_text())
    assert record["controller"]["law"] == "pd_attitude" and record["global error"]["order"] == 4
    scene, initial, run = rd.load_scene("cubesat_pointing")
    want = rd.simulate(scene, initial, run.dt, duration=30.0, record_every=run.record_every, controller=run.controller)
    got = np.load(out / "trajectory.npz")
    w = [k for k in got.files if "w_B_x" in k]
    np.testing.assert_array_equal(got[w[0]], want.w_B[:, 0, 0])
    # to a tolerance under its controller: the chosen step divides the period (0.5 s) four times over
    assert main(["simulate", "cubesat_pointing", "--tolerance", "1e-6", "--duration", "30", "--no-plot",
                 "--no-progress", "--out", str(tmp_path / "o2")]) == 0
    record = json.loads((tmp_path / "o2" / "run.json").read_text())
    blocks = run.controller.period / (4.0 * record["dt [s]"])
    assert blocks == round(blocks) and record["controller"]["law"] == "pd_attitude"


# ---------------------------------------------------------------- Monte Carlo under a controller
def noisy_thrust_scene():
    """A body at rest with a thruster whose law pushes along x by the sampled w_B_x [N per rad/s]: the true rate
    stays zero, so the thrust is the gyro noise alone and each sample's velocity is its own noise's."""
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 1.0, 1.0])], elements=[rd.ScheduledLoads(body=0, loads=[])],
                     body_names=["sat"])
    law = lambda state: {0: (float(state.w_B[0, 0]), 0.0, 0.0)}  # noqa: E731
    return scene, rd.Controller(0.1, law, w_B_noise=0.01)


def test_monte_carlo_under_a_controller_draws_each_runs_noise_seed_from_its_seed():
    """Each sample is simulate of its drawn state under the controller with its own seed
    (inputs["controller.seed"], bit for bit); the seeds depend on (seed, i) only (a run of 6 samples starts with
    the 4 of a run of 4) and leave the dispersion draws as they are without a controller; the noise differs
    between samples (the velocities differ)."""
    scene, controller = noisy_thrust_scene()
    nominal = [rd.RigidBodyState()]
    dispersions = {"sat.p_W": rd.dispersion.Normal(std=1.0)}
    run = dict(seed=5, dt=0.05, steps=20, dispersions=dispersions, error=False)
    mc = rd.monte_carlo(scene, nominal, 4, controller=controller, **run)
    seeds = mc.inputs["controller.seed"]
    for i in range(4):
        one = rd.simulate(scene, [rd.RigidBodyState(p_W=mc.inputs["sat.p_W"][i])], 0.05, 20, error=False,
                          controller=rd.Controller(0.1, controller.law, w_B_noise=0.01, seed=int(seeds[i])))
        np.testing.assert_array_equal(mc.values("v_W")[i], one.v_W)
        np.testing.assert_array_equal(mc.values("p_W")[i], one.p_W)
    longer = rd.monte_carlo(scene, nominal, 6, controller=controller, **run)
    np.testing.assert_array_equal(longer.inputs["controller.seed"][:4], seeds)
    plain = rd.monte_carlo(scene, nominal, 4, **run)
    np.testing.assert_array_equal(plain.inputs["sat.p_W"], mc.inputs["sat.p_W"])
    v_end = mc.values("v_W")[:, -1, 0, 0]
    assert len(set(v_end.tolist())) == 4 and np.abs(v_end).min() > 0.0


def _sample_error(error, i):
    """Sample i of a Monte Carlo's GlobalError (arrays (N, n, ...)): a SimpleNamespace of same_estimate's fields."""
    names = ("attitude", "angular_velocity", "position", "velocity", "energy", "angular_momentum", "observed_order",
             "reliable")
    return SimpleNamespace(order=error.order, verdict=error.verdict[i], **{n: getattr(error, n)[i] for n in names},
                           reliable_for=lambda quantity: error.reliable_for(quantity)[i])


class IntegralThrust:
    """A law in Python with a state of its own: a thruster along x in B, f = -2 v_x - 0.5 ∫ v_x dt + 0.5 w_B,x [N] (the
    integral summed at each sample, w_B,x the gyro's), on a tumbling body whose attitude carries rk4's error into p_W."""

    def __init__(self, period):
        self.period, self.integral = period, 0.0

    def __call__(self, state):
        v = float(state.v_W[0, 0])
        self.integral += self.period * v
        return {0: (-2.0 * v - 0.5 * self.integral + 0.5 * float(state.w_B[0, 0]), 0.0, 0.0)}


@pytest.mark.parametrize("noise", [0.0, 1e-3])
def test_a_run_under_a_python_law_estimates_its_error(noise):
    """Under a law in Python that keeps a state, with gyro noise or not, the estimate's runs at 2 dt and 4 dt each go
    under a copy of the controller as it was before the run (the law's integral, the noise generator): the reliable
    estimates lie within the estimator's factor 2 of the true error (docs/accuracy.md), measured against the same run
    at dt / 16 (whose own error, 16^4 times smaller, is negligible). A law the estimate cannot copy is named."""
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.ScheduledLoads(body=0, loads=[])])
    start = [rd.RigidBodyState(v_W=[1.0, 0.0, 0.0], w_B=[0.1, 2.0, 0.1])]
    period, dt, steps = 0.16, 0.02, 400  # the period a multiple of 4 dt: the three runs sample on their steps' ends
    law = IntegralThrust(period)
    run = rd.simulate(scene, start, dt, steps, record_every=4, method="rk4",
                      controller=rd.Controller(period, law, w_B_noise=noise, seed=4, repeatable=True))
    assert law.integral != 0.0  # the run's own law, sampled by the run alone
    fine = rd.simulate(scene, start, dt / 16, steps * 16, record_every=64, method="rk4", error=False,
                       controller=rd.Controller(period, IntegralThrust(period), w_B_noise=noise, seed=4))
    reliable = run.error.reliable.copy()
    reliable[0] = False  # no error at t0 to compare with
    assert reliable.mean() > 0.5
    true_p = np.linalg.norm(run.p_W - fine.p_W, axis=-1)[reliable, 0]
    true_q = rd.angular_distance(run.q_WB[reliable, 0], fine.q_WB[reliable, 0])
    for estimate, true in ((run.error.position[reliable, 0], true_p), (run.error.attitude[reliable, 0], true_q)):
        assert np.all((estimate >= 0.5 * true) & (estimate <= 2.0 * true))

    class Locked(IntegralThrust):
        def __deepcopy__(self, memo):
            raise TypeError("a lock")

    locked = rd.Controller(period, Locked(period), repeatable=True)
    with pytest.raises(TypeError, match=r"^controller.law: expected a law that copy.deepcopy copies .*\(a lock\)"
                                        r"$"):
        rd.simulate(scene, start, dt, 8, controller=locked)
    # to a tolerance, every run of the planner takes a copy: the same error, which names tolerance's runs
    with pytest.raises(TypeError, match=r"^controller.law: expected a law that copy.deepcopy copies \(tolerance= runs "
                                        r"it again in each of its runs, each from a copy; or pass dt=\), got "
                                        r".*\(a lock\)$"):
        rd.simulate(scene, start, duration=8 * period, tolerance=1e-6, controller=locked)
    assert rd.simulate(scene, start, dt, 8, controller=locked, error=False).error is None


def test_a_period_off_the_grid_of_4_dt_is_named_where_the_order_check_fails():
    """Samples off the 4 dt grid split the steps of the runs at 2 dt and 4 dt unlike those at dt: the verdicts that
    fail the order check say so (a law in Python made now, a shipped law's estimate made on the first read); on the
    grid, most records are reliable and none says so."""
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.ScheduledLoads(body=0, loads=[])])
    start = [rd.RigidBodyState(v_W=[1.0, 0.0, 0.0], w_B=[0.1, 2.0, 0.1])]
    cause = ("(the controller's samples every 0.1 s split the steps of the runs at 2 dt and 4 dt unlike those at dt: "
             "a period that is a multiple of 4 dt keeps them alike)")

    def run(period):
        controller = rd.Controller(period, lambda state: {0: (1.0, 0.0, 0.0)}, repeatable=True)
        return rd.simulate(scene, start, 0.02, 400, record_every=4, method="rk4", controller=controller).error

    off, on = run(0.1), run(0.16)
    failed = [v for v in off.verdict if v.startswith("not asymptotic")]
    assert failed and all(v.endswith(cause) for v in failed)
    assert on.reliable.mean() > 0.5 and not any("controller's samples" in v for v in on.verdict)
    shipped = rd.load_scene("cubesat_detumbling")  # B-dot every 1 s, the runs at 2 dt and 4 dt step 1 s and 2 s
    later = rd.simulate(shipped.scene, shipped.initial, 0.5, 80, record_every=4, controller=shipped.run.controller)
    failed = [v for v in later.error.verdict if v.startswith("not asymptotic")]
    # (the 4 dt run's 2 s steps split at every sample: it steps as the 2 dt run does, and the two agree exactly)
    assert failed and all(v.endswith(cause.replace("0.1 s", "1 s")) for v in failed)


def test_a_law_in_python_not_declared_repeatable_is_sampled_by_the_run_alone():
    """Without repeatable=True a law in Python is called at the run's samples only (one call per sample, in order) and
    result.error says why it has no values; with it, the runs at 2 dt and 4 dt sample copies of the law (their calls
    reach a list the copies share)."""
    seen = []

    def law(state):
        seen.append(state.t)
        return {}

    run = rd.simulate(thruster_scene(), [rd.RigidBodyState()], 0.1, 16, controller=rd.Controller(0.4, law))
    assert seen == [0.4 * k for k in range(4)]
    assert run.error.verdict == ("no estimate: the controller's law in Python is sampled by the run alone (declare it "
                                 "Controller(..., repeatable=True) to have the runs at 2 dt and 4 dt sample copies of "
                                 "it)",) * 17
    assert np.isnan(run.error.attitude).all() and not run.error.reliable.any()
    seen.clear()
    run = rd.simulate(thruster_scene(), [rd.RigidBodyState()], 0.1, 16, controller=rd.Controller(0.4, law,
                                                                                                 repeatable=True))
    assert sorted(seen) == sorted([0.4 * k for k in range(4)] * 3) and run.error.reliable[::4].all()
    with pytest.raises(TypeError, match=r"^repeatable: expected True or False, got 1$"):
        rd.Controller(0.4, law, repeatable=1)


def test_monte_carlo_under_a_python_law_estimates_each_sample_as_simulate_does():
    """Each sample's global error estimate is the one simulate gives for it under its own seed, bit for bit; the
    estimate's quantities are fields of the result, and it survives a pickle."""
    scene, noisy = noisy_thrust_scene()
    controller = rd.Controller(noisy.period, noisy.law, w_B_noise=noisy.w_B_noise, repeatable=True)
    run = dict(seed=5, dt=0.05, steps=20, dispersions={"sat.v_W": rd.dispersion.Normal(std=1.0)})
    mc = rd.monte_carlo(scene, [rd.RigidBodyState()], 3, controller=controller, **run)
    seeds = mc.inputs["controller.seed"]
    assert mc.error.attitude.shape == (3, 21, 1) and mc.error.energy.shape == (3, 21) and len(mc.error.verdict) == 3
    for i in range(3):
        one = rd.simulate(scene, [rd.RigidBodyState(v_W=mc.inputs["sat.v_W"][i])], 0.05, 20,
                          controller=rd.Controller(0.1, controller.law, w_B_noise=0.01, seed=int(seeds[i]),
                                                   repeatable=True))
        assert same_estimate(_sample_error(mc.error, i), one.error)
    assert mc.error.reliable.any()
    assert "error.position" in mc.fields
    np.testing.assert_array_equal(mc.values("error.position"), mc.error.position)
    assert same_estimate(pickle.loads(pickle.dumps(mc)).error, mc.error)
    assert rd.monte_carlo(scene, [rd.RigidBodyState()], 3, controller=controller, error=False, **run).error is None


def test_monte_carlo_under_a_shipped_law_estimates_each_sample_as_simulate_does():
    """Under a law in C++ (whose runs make their estimate when first read) each sample's estimate is simulate's for
    it, made under a fresh copy of the law as it was before the sample's run; most records are reliable."""
    shipped = rd.load_scene("cubesat_detumbling")
    controller, start = shipped.run.controller, shipped.initial[0]
    run = dict(seed=3, dt=shipped.run.dt, steps=200, record_every=4,
               dispersions={"cubesat.w_B": rd.dispersion.Normal(std=1e-3)})
    mc = rd.monte_carlo(shipped.scene, shipped.initial, 2, controller=controller, **run)
    for i in range(2):
        states = [rd.RigidBodyState(p_W=start.p_W, q_WB=start.q_WB, v_W=start.v_W, w_B=mc.inputs["cubesat.w_B"][i])]
        own = rd.Controller(controller.period, controller.law, w_B_noise=controller.w_B_noise,
                            seed=int(mc.inputs["controller.seed"][i]))
        one = rd.simulate(shipped.scene, states, shipped.run.dt, 200, record_every=4, controller=own)
        assert same_estimate(_sample_error(mc.error, i), one.error)


@pytest.mark.parametrize("shipped", [True, False])
def test_monte_carlo_under_a_controller_on_threads_is_the_same_to_the_bit(shipped):
    """Samples under a controller run `threads` at once (a law in C++ in parallel, one in Python taking the GIL at its
    samples): the records and the estimates are those of the samples one after the other, bit for bit; progress counts
    every sample from the calling thread."""
    if shipped:
        scene_file = rd.load_scene("cubesat_detumbling")
        scene, nominal, controller = scene_file.scene, scene_file.initial, scene_file.run.controller
        run = dict(seed=4, dt=scene_file.run.dt, steps=80, record_every=4,
                   dispersions={"cubesat.w_B": rd.dispersion.Normal(std=1e-2)})
    else:
        scene, noisy = noisy_thrust_scene()
        nominal = [rd.RigidBodyState()]
        controller = rd.Controller(noisy.period, noisy.law, w_B_noise=noisy.w_B_noise, repeatable=True)
        run = dict(seed=4, dt=0.05, steps=40, record_every=4, dispersions={"sat.v_W": rd.dispersion.Normal(std=1.0)})
    one_by_one = rd.monte_carlo(scene, nominal, 5, controller=controller, **run)
    counts = []
    at_once = rd.monte_carlo(scene, nominal, 5, controller=controller, threads=3, progress=counts.append, **run)
    assert counts == [1, 2, 3, 4, 5]
    for name in ("t", "p_W", "q_WB", "v_W", "w_B", "total_energy", "work"):
        np.testing.assert_array_equal(at_once.values(name), one_by_one.values(name))
    assert same_estimate(at_once.error, one_by_one.error)


def test_a_sample_that_fails_on_threads_propagates_its_exception():
    """A law that raises in one sample of a run on threads: the call raises that exception (the others are stopped
    at their next progress check and those not started are cancelled) and returns."""

    class FailsLate:
        def __init__(self):
            self.calls = 0

        def __call__(self, state):
            self.calls += 1
            if state.v_W[0, 0] > 0.0 and self.calls > 3:
                raise RuntimeError("thruster fault")
            return {0: (0.0, 0.0, 0.0)}

    scene, _ = noisy_thrust_scene()
    dispersions = {"sat.v_W": rd.dispersion.Normal(std=1.0)}
    with pytest.raises(RuntimeError, match="thruster fault"):
        rd.monte_carlo(scene, [rd.RigidBodyState()], 6, seed=1, dt=0.01, steps=2000, dispersions=dispersions,
                       controller=rd.Controller(0.1, FailsLate()), threads=2, error=False)


def test_monte_carlo_refuses_a_controller_it_cannot_run():
    scene, controller = noisy_thrust_scene()
    run = dict(seed=1, dt=0.1, steps=2, controller=controller)
    with pytest.raises(ValueError, match=r"client: expected None with a controller"):
        rd.monte_carlo(scene, [rd.RigidBodyState()], 2, client="tcp://localhost:1", error=False, **run)
    with pytest.raises(ValueError, match=r"^threads: expected an integer >= 1, got 0$"):
        rd.monte_carlo(scene, [rd.RigidBodyState()], 2, threads=0, **run)
    with pytest.raises(ValueError, match=r"controller: expected None for a RigidBody model"):
        rd.monte_carlo(rd.RigidBody(1.0, [1.0, 1.0, 1.0]), rd.RigidBodyState(), 2, error=False, **run)
    with pytest.raises(TypeError, match=r"controller: expected a rigiddyn.Controller or None"):
        rd.monte_carlo(scene, [rd.RigidBodyState()], 2, seed=1, dt=0.1, steps=2, error=False, controller=len)


# ---------------------------------------------------------------- tolerance= under a controller
def on_the_grid(dt, period):
    """Whether period / (4 dt) is a whole number (within the rounding of a division)."""
    blocks = period / (4.0 * dt)
    return abs(blocks - round(blocks)) <= 1e-9 * blocks


@pytest.mark.parametrize("tolerance", [1e-6, 1e-9])
def test_tolerance_under_the_shipped_bdot_meets_it(tolerance):
    """The shipped CubeSat under B-dot (sampled every second) over 10 minutes, to an attitude tolerance: every run the
    planner makes (pilots and the run) steps on a divisor of period / 4, so that the certificate's runs at 2 dt and
    4 dt sample the law where the run does; the true error meets the tolerance: its difference from rk4 at an eighth of
    the chosen step under the same law, plus that reference's own estimated error, is at most the tolerance."""
    scene, initial, run = rd.load_scene("cubesat_detumbling")
    r = rd.simulate(scene, initial, duration=600.0, tolerance=tolerance, record_every=20, controller=run.controller)
    c = r.choice
    assert c.refinements <= 3 and c.certified_error <= tolerance
    assert on_the_grid(c.dt, run.controller.period) and c.steps * c.dt == pytest.approx(600.0, rel=1e-12)
    assert all(on_the_grid(p["dt"], run.controller.period) for p in c.pilots if p["steps"] > 0)
    assert all(p["method"] != "exact" for p in c.pilots)  # a closed form takes no law
    fine = rd.simulate(scene, initial, c.dt / 8, 8 * c.steps, method="rk4", record_every=160,
                       controller=run.controller)
    assert fine.error.reliable[1:].all()
    largest = float(np.max(rd.angular_distance(r.q_WB.reshape(-1, 4), fine.q_WB.reshape(-1, 4))))
    assert largest + np.nanmax(fine.error.attitude) <= tolerance


def test_tolerance_under_a_repeatable_python_law_meets_it_and_leaves_the_law_alone():
    """A law in Python with a state of its own (IntegralThrust), declared repeatable: each of the planner's runs
    samples its own copy of the controller as it was before the call, so the law given keeps its state; the position
    meets the tolerance: its difference from the same law's run at an eighth of the chosen step, plus that reference's
    own estimated error, is at most the tolerance."""
    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.ScheduledLoads(body=0, loads=[])])
    start = [rd.RigidBodyState(v_W=[1.0, 0.0, 0.0], w_B=[0.1, 2.0, 0.1])]
    period, tolerance = 0.16, 1e-7
    law = IntegralThrust(period)
    r = rd.simulate(scene, start, duration=8.0, tolerance=tolerance, measure="position", record_every=4,
                    controller=rd.Controller(period, law, repeatable=True))
    assert law.integral == 0.0
    c = r.choice
    assert on_the_grid(c.dt, period) and c.certified_error <= tolerance
    fine = rd.simulate(scene, start, c.dt / 8, 8 * c.steps, method="rk4", record_every=32,
                       controller=rd.Controller(period, IntegralThrust(period), repeatable=True))
    assert fine.error.reliable[1:].mean() > 0.9
    assert np.max(np.linalg.norm(r.p_W - fine.p_W, axis=-1)) + np.nanmax(fine.error.position) <= tolerance


def test_tolerance_replans_a_low_order_whose_error_outgrew_its_short_pilot():
    """Over the whole 4 orbits of the shipped detumbling, every candidate's step is capped at the grid's 0.25 s, so the
    cheapest per step may be a second-order splitting whose 16-step pilot over 4 s predicted 4e-5 rad where the run
    shows ~0.02 rad: scaling every candidate's prediction by that factor alike, a fourth-order method at the same 93 600
    steps is far cheaper than the splitting refined to ~7x its steps. Whatever the pilots' timings choose first, the
    certified run takes the grid's 93 600 steps."""
    scene, initial, run = rd.load_scene("cubesat_detumbling")
    r = rd.simulate(scene, initial, duration=run.duration, tolerance=1e-3, record_every=run.record_every,
                    controller=run.controller)
    assert r.choice.met and r.choice.steps == 93600 and r.choice.order == 4, r.choice.reason
