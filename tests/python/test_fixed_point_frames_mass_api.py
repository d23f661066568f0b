"""The Python API of bodies about a fixed point, moving frames and variable mass (and bad input at the Python
surface): the bodies about a fixed point (PivotedBody, PivotedPlanarBody, their states, forward and inverse
dynamics), the scene's moving frame (SceneFrame), variable mass (MassFlow, Thrust), and what a run of them
records (SceneResult.pivot_reaction_W, angular_momentum_O_W, mass). Construction and its checks
(ValueError/TypeError naming the argument), repr and pickle round trips, ==, the shapes and dtypes of the new
records, Python callables (frame motion, mass rate, inertia rule) whose exceptions propagate and whose
non-finite values raise ValueError naming the field, and the GIL released while a pivoted body runs. The physics
of these models is tested against the numpy reference elsewhere (test_pivoted*.py, test_moving_frame*.py,
test_variable_mass*.py); here only the wiring."""

from __future__ import annotations

import math
import pickle
import threading

import numpy as np
import pytest

import rigiddyn as rd

EPS = np.finfo(float).eps
I_BOX = np.array([1.0, 2.0, 2.5])
G = np.array([0.0, 0.0, -9.81])


def top() -> rd.PivotedBody:
    """A spinning box pinned at p_WO, its centre of mass off B's axes (products of inertia about O)."""
    return rd.PivotedBody(rd.RigidBody(2.0, I_BOX), [0.1, -0.2, 0.5], p_WO=[1.0, 2.0, 3.0])


def top_state() -> rd.PivotedBodyState:
    return rd.PivotedBodyState(q_WB=rd.quat_normalize([0.1, 0.2, 0.3, 0.9]), w_B=[0.3, -0.2, 12.0])


def pendulum() -> rd.PivotedPlanarBody:
    return rd.PivotedPlanarBody(1.5, 0.02, [0.0, -0.4], p_WO=[0.5, 1.0])


def module_rate(t):
    """A module-level mass rate (picklable): a constant loss of 0.1 kg/s."""
    return -0.1


def module_inertia(m):
    """A module-level inertia rule (picklable): a sphere of radius 0.1 m."""
    return 0.4 * m * 0.01 * np.eye(3)


def module_kinematics(t):
    """A module-level frame motion (picklable): F turning about z at 0.5 rad/s, its origin fixed."""
    return rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 0.5).at(t)


# ------------------------------------------------------------------------------------ the bodies

def test_pivoted_body_holds_its_parameters_and_the_inertia_about_the_pivot():
    body = top()
    c = np.array([0.1, -0.2, 0.5])
    np.testing.assert_array_equal(body.p_OC_B, c)
    np.testing.assert_array_equal(body.p_WO, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(body.inertia_com, np.diag(I_BOX))
    assert body.mass == 2.0 and body.body == rd.RigidBody(2.0, I_BOX)
    # parallel-axis theorem, products included: each entry of I_O is a sum of at most three rounded terms of
    # size <= |I_C| + m|c|^2 = 3.1, so it is exact to a few ulps of that size
    I_O = np.diag(I_BOX) + 2.0 * (c @ c * np.eye(3) - np.outer(c, c))
    np.testing.assert_allclose(body.inertia_O, I_O, rtol=0, atol=8 * EPS * 3.1)
    assert body.euler_form == "full"  # c off the axes: products of inertia about O
    # digits lost: log10(m|c|^2 / smallest moment of I_C), here below 1 -> max(0, ...) = 0
    assert body.digits_lost == max(0.0, math.log10(2.0 * (c @ c) / 1.0))
    assert rd.PivotedBody(rd.RigidBody(2.0, I_BOX), [0.0, 0.0, 0.0]).digits_lost == 0.0  # free rotation about C


def test_pivoted_planar_body_holds_its_parameters():
    body = pendulum()
    assert body.mass == 1.5 and body.inertia_zz == 0.02
    np.testing.assert_array_equal(body.p_OC_B, [0.0, -0.4])
    np.testing.assert_array_equal(body.p_WO, [0.5, 1.0])
    assert body.inertia_O_zz == pytest.approx(0.02 + 1.5 * 0.16, rel=4 * EPS)  # two rounded operations


@pytest.mark.parametrize("call, error, message", [
    (lambda: rd.PivotedBody(5, [0, 0, 1.0]), TypeError, r"^body: expected a RigidBody"),
    (lambda: rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0, 0, np.nan]), ValueError, r"^p_OC_B: expected"),
    (lambda: rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0, 0, 1.0], [np.inf, 0, 0]), ValueError, r"^p_WO: expected"),
    (lambda: rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0, 1.0]), ValueError, r"^p_OC_B: expected"),
    (lambda: rd.PivotedPlanarBody(-1.0, 0.1, [0, 1.0]), ValueError, r"^mass: expected"),
    (lambda: rd.PivotedPlanarBody(1.0, 0.0, [0, 1.0]), ValueError, r"^inertia_zz: expected"),
    (lambda: rd.PivotedPlanarBody(1.0, 0.1, "x"), TypeError, r"^p_OC_B: expected"),
    (lambda: rd.PivotedBodyState(q_WB=[0, 0, 0, 2.0]), ValueError, r"^q_WB: expected"),
    (lambda: rd.PivotedBodyState(w_B=[0, np.nan, 0]), ValueError, r"^w_B: expected"),
    (lambda: rd.PivotedPlanarBodyState(theta=np.inf), ValueError, r"^theta: expected"),
    (lambda: rd.PivotedPlanarBodyState(omega="1"), TypeError, r"^omega: expected"),
])
def test_bad_bodies_and_states_are_refused_naming_the_argument(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_a_state_field_is_assigned_whole_and_checked():
    s = rd.PivotedBodyState()
    s.w_B = [1.0, 2.0, 3.0]
    np.testing.assert_array_equal(s.w_B, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError):
        s.w_B[0] = 5.0  # read-only array
    with pytest.raises(ValueError, match=r"^q_WB: expected"):
        s.q_WB = [0.0, 0.0, 0.0, 0.0]
    np.testing.assert_array_equal(s.q_WB, [0.0, 0.0, 0.0, 1.0])
    np.testing.assert_array_equal(rd.PivotedBodyState(q_WB=[1.0, 0, 0, 0], scalar_first=True).q_WB, [0, 0, 0, 1.0])
    p = rd.PivotedPlanarBodyState()
    p.theta = 0.5
    assert p.theta == 0.5


def test_pint_quantities_are_converted_to_si():
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    body = rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0, 0, 50.0] * u.cm)
    np.testing.assert_array_equal(body.p_OC_B, [0.0, 0.0, 0.5])
    assert rd.PivotedPlanarBodyState(theta=90 * u.deg).theta == pytest.approx(math.pi / 2, rel=2 * EPS)
    assert rd.MassFlow(rate=-3.6 * u.kg / u.hour).rate == pytest.approx(-1e-3, rel=2 * EPS)
    with pytest.raises(ValueError, match=r"^p_OC_B: expected m"):
        rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0, 0, 1.0] * u.s)


# ------------------------------------------------------------------------------------ value protocol

def _module_motion_frame():
    return rd.SceneFrame.moving(rd.FrameMotion(module_kinematics))


VALUES = {
    "PivotedBody": top, "PivotedPlanarBody": pendulum, "PivotedBodyState": top_state,
    "PivotedPlanarBodyState": lambda: rd.PivotedPlanarBodyState(theta=0.3, omega=-1.5),
    "PivotedAcceleration": lambda: rd.forward_dynamics(top(), top_state(), gravity=G),
    "PivotedTorque": lambda: rd.inverse_dynamics(top(), top_state(), alpha_B=[1.0, 2.0, 3.0], gravity=G),
    "PivotedPlanarAcceleration": lambda: rd.forward_dynamics(pendulum(), rd.PivotedPlanarBodyState(0.3), gravity=[0, -9.81]),
    "PivotedPlanarTorque": lambda: rd.inverse_dynamics(pendulum(), rd.PivotedPlanarBodyState(0.3), alpha_B=2.0),
    "SceneFrame.rotating": lambda: rd.SceneFrame.rotating([0.0, 1.0, 1.0], 0.3),
    "SceneFrame.earth": lambda: rd.SceneFrame.earth(math.radians(48.85)),
    "SceneFrame.moving": _module_motion_frame,
    "MassFlow": lambda: rd.MassFlow(rate=-2.0),
    "MassFlow of callables": lambda: rd.MassFlow(rate=module_rate, inertia_rule=module_inertia),
    "Thrust": lambda: rd.Thrust(0, [0.0, 0.0, -300.0], frame="world", r_B=[0.0, 0.0, 0.0]),
}


@pytest.mark.parametrize("name", list(VALUES))
def test_values_pickle_evaluate_from_their_repr_and_compare(name):
    value = VALUES[name]()
    assert pickle.loads(pickle.dumps(value)) == value
    assert eval(repr(value), {**vars(rd), **globals()}) == value  # noqa: S307 (the repr reads as the call)
    assert value == VALUES[name]() and value != 5
    with pytest.raises(TypeError):
        hash(value)


def test_an_earth_frame_reads_as_earth():
    assert repr(rd.SceneFrame.earth(0.8)).startswith("SceneFrame.earth(latitude=")
    assert rd.SceneFrame.earth(0.8).constant_rotation and not _module_motion_frame().constant_rotation


def test_results_unpack_as_pairs():
    alpha_B, reaction_W = rd.forward_dynamics(top(), top_state(), gravity=G)
    assert alpha_B.shape == (3,) and reaction_W.shape == (3,)
    alpha, reaction = rd.forward_dynamics(pendulum(), rd.PivotedPlanarBodyState(0.3), gravity=[0, -9.81])
    assert isinstance(alpha, float) and reaction.shape == (3,)


# ------------------------------------------------------------------------------------ dynamics

def test_inverse_dynamics_undoes_forward_dynamics():
    body, state = top(), top_state()
    acc = rd.forward_dynamics(body, state, torque=[0.5, -0.2, 0.1], frame="body", gravity=G)
    need = rd.inverse_dynamics(body, state, alpha_B=acc.alpha_B, gravity=G)
    # the couple about O that gives acc.alpha_B besides gravity is the torque applied about C (a couple is the
    # same about any point); both directions round sums of terms of size |I_O||alpha| + |w x I_O w| ~ 1e3, so
    # they agree to a few ulps of that size (cond(I_O) ~ 3 enters once)
    scale = np.abs(body.inertia_O).max() * (np.abs(acc.alpha_B).max() + 12.0**2)
    np.testing.assert_allclose(need.tau_O_B, [0.5, -0.2, 0.1], rtol=0, atol=64 * EPS * scale)
    np.testing.assert_allclose(need.reaction_W, acc.reaction_W, rtol=0, atol=64 * EPS * scale)
    p, ps = pendulum(), rd.PivotedPlanarBodyState(theta=0.3, omega=2.0)
    planar = rd.forward_dynamics(p, ps, torque=0.7, gravity=[0.0, -9.81])
    back = rd.inverse_dynamics(p, ps, alpha_B=planar.alpha, gravity=[0.0, -9.81])
    assert back.tau_O == pytest.approx(0.7, abs=16 * EPS * 10.0)  # terms of size I_O alpha, m g |c| < 10
    np.testing.assert_allclose(back.reaction_W, planar.reaction_W, rtol=0, atol=16 * EPS * 100.0)


def test_the_dynamics_of_a_pivoted_body_check_their_arguments():
    with pytest.raises(ValueError, match=r"^a_W: expected None for a pivoted body"):
        rd.inverse_dynamics(top(), top_state(), a_W=[0.0, 0.0, 0.0], alpha_B=[0.0, 0.0, 0.0])
    with pytest.raises(TypeError, match=r"^state: expected a PivotedBodyState"):
        rd.forward_dynamics(top(), rd.RigidBodyState())
    with pytest.raises(ValueError, match=r"^gravity: expected None or an in-plane vector"):
        rd.forward_dynamics(pendulum(), rd.PivotedPlanarBodyState(), gravity=True)
    with pytest.raises(ValueError, match=r"^frame: expected"):
        rd.forward_dynamics(top(), top_state(), frame="sideways")


# ------------------------------------------------------------------------------------ runs

def test_simulate_a_pivoted_body_records_the_new_arrays():
    result = rd.simulate(top(), top_state(), dt=1e-3, steps=20, gravity=True, record_every=5)
    n = 5  # records 0, 5, 10, 15, 20
    assert isinstance(result, rd.SceneResult) and result.elements == ("UniformGravity",)
    for name, shape in [("pivot_reaction_W", (n, 1, 3)), ("angular_momentum_O_W", (n, 1, 3)), ("mass", (n, 1)),
                        ("p_W", (n, 1, 3)), ("q_WB", (n, 1, 4)), ("work", (n, 1))]:
        array = getattr(result, name)
        assert array.shape == shape and array.dtype == np.float64, name
        assert not array.flags.writeable, name
    np.testing.assert_array_equal(result.mass, 2.0)
    # the record at t0 is the initial state: H_O = R_WB I_O w_B (a 3x3 product and a rotation: a few ulps of
    # |I_O||w| ~ 40)
    q = top_state().q_WB
    H_O = rd.quat_rotate(q, top().inertia_O @ top_state().w_B)
    np.testing.assert_allclose(result.angular_momentum_O_W[0, 0], H_O, rtol=0, atol=32 * EPS * 40.0)
    # the same run as the one-body scene it is
    scene = rd.Scene([top()], elements=[rd.UniformGravity(g_W=G)])
    same = rd.simulate(scene, [top_state()], dt=1e-3, steps=20, record_every=5)
    for name in ("q_WB", "w_B", "pivot_reaction_W", "angular_momentum_O_W", "work"):
        np.testing.assert_array_equal(getattr(result, name), getattr(same, name), err_msg=name)


def test_a_hanging_body_at_rest_is_held_by_its_weight():
    # c straight down, at rest: no torque, alpha = 0, a_C = 0, so the reaction is -m g exactly
    body = rd.PivotedBody(rd.RigidBody(2.0, I_BOX), [0.0, 0.0, -0.5])
    result = rd.simulate(body, rd.PivotedBodyState(), dt=1e-2, steps=3, gravity=True)
    np.testing.assert_array_equal(result.pivot_reaction_W[:, 0], np.tile([0.0, 0.0, 2.0 * 9.81], (4, 1)))
    planar = rd.simulate(pendulum(), rd.PivotedPlanarBodyState(), dt=1e-2, steps=3, gravity=[0.0, -9.81])
    np.testing.assert_array_equal(planar.pivot_reaction_W[:, 0], np.tile([0.0, 1.5 * 9.81, 0.0], (4, 1)))


def test_step_returns_the_state_of_the_body():
    state = rd.step(top(), top_state(), dt=1e-3, gravity=True)
    assert isinstance(state, rd.PivotedBodyState)
    state, t = rd.step(pendulum(), rd.PivotedPlanarBodyState(0.2), dt=1e-3, gravity=[0.0, -9.81], t=1.0)
    assert isinstance(state, rd.PivotedPlanarBodyState) and t == 1.001
    run = rd.simulate(pendulum(), rd.PivotedPlanarBodyState(0.2), dt=1e-3, steps=1, gravity=[0.0, -9.81], t0=1.0)
    # the run records q_WB = Rz(theta): theta = 2 atan2(q_z, q_w) to a few ulps (sin, cos, atan2 each rounded)
    assert state.theta == pytest.approx(2 * math.atan2(run.q_WB[1, 0, 2], run.q_WB[1, 0, 3]), rel=0, abs=8 * EPS)


def test_step_refuses_a_scene_whose_mass_changes():
    # a body state does not carry the mass: a second step would restart from the initial mass, silently wrong
    with pytest.raises(ValueError, match=r"^model: expected a scene without mass flows for step"):
        rd.step(_rocket(rd.MassFlow(rate=-0.5)), [rd.ParticleState()], dt=0.1)


def test_loads_act_on_a_pivoted_body():
    load = rd.AppliedLoad(torque=[0.0, 0.0, 1.0], frame="body")
    result = rd.simulate(top(), rd.PivotedBodyState(), dt=1e-3, steps=10, loads=load)
    assert result.elements == ("ScheduledLoads",) and result.work[-1, 0] > 0.0


def test_a_scene_with_a_frame_and_a_mass_flow_round_trips_and_runs():
    scene = rd.Scene()
    scene.add_body(rd.Particle(10.0), name="rocket", mass_flow=rd.MassFlow(rate=-0.5))
    scene.add(rd.Thrust(0, [0.0, 0.0, -200.0], frame="world"))
    scene.add(rd.UniformGravity())
    scene.frame = rd.SceneFrame.rotating([0.0, 0.0, 1.0], 0.1)
    assert scene.mass_flows == (rd.MassFlow(rate=-0.5),) and scene.frame == rd.SceneFrame.rotating([0, 0, 1.0], 0.1)
    assert pickle.loads(pickle.dumps(scene)) == scene
    assert eval(repr(scene), vars(rd)) == scene  # noqa: S307
    other = pickle.loads(pickle.dumps(scene))
    other.frame = None
    assert other != scene and other.frame is None
    result = rd.simulate(scene, [rd.ParticleState()], dt=0.01, steps=100)
    assert result.elements == ("Thrust", "UniformGravity", "CentrifugalForce", "CoriolisForce")
    assert result.work.shape == (101, 4) and result.mass.shape == (101, 1)
    # a constant rate is integrated exactly by every method up to the rounding of m0 + rate t (a few ulps of
    # m0 = 10 per step, 100 steps)
    np.testing.assert_allclose(result.mass[:, 0], 10.0 - 0.5 * result.t, rtol=0, atol=100 * 4 * EPS * 10.0)
    assert pickle.loads(pickle.dumps(result)).mass.shape == (101, 1)
    copy = pickle.loads(pickle.dumps(result))
    for name in ("pivot_reaction_W", "angular_momentum_O_W", "mass", "work"):
        np.testing.assert_array_equal(getattr(copy, name), getattr(result, name))


@pytest.mark.parametrize("call, error, message", [
    (lambda: rd.SceneFrame.rotating([0.0, 0.0, 0.0], 1.0), ValueError, r"^axis: expected a non-zero"),
    (lambda: rd.SceneFrame.rotating([0.0, 0.0, 1.0], np.nan), ValueError, r"^rate: expected"),
    (lambda: rd.SceneFrame.earth(2.0), ValueError, r"^latitude: expected"),
    (lambda: rd.SceneFrame.moving(5), TypeError, r"^frame_motion: expected a FrameMotion"),
    (lambda: rd.MassFlow(rate=np.inf), ValueError, r"^rate: expected"),
    (lambda: rd.MassFlow(rate="fast"), TypeError, r"^rate: expected"),
    (lambda: rd.MassFlow(inertia_rule="shrinking"), ValueError, r"^inertia_rule: expected 'scaled' or a callable"),
    (lambda: rd.MassFlow(inertia_rule=3), TypeError, r"^inertia_rule: expected"),
    (lambda: rd.Thrust(0, [0.0, np.nan, 0.0]), ValueError, r"^u_rel: expected"),
    (lambda: rd.Thrust(0, [0.0, 0.0, 1.0], frame="up"), ValueError, r"^frame: expected"),
    (lambda: rd.Scene().add_body(rd.Particle(1.0), mass_flow=-1.0), TypeError, r"^mass_flow: expected None"),
    (lambda: rd.Scene([rd.Particle(1.0)], mass_flows=[]), ValueError, r"^mass_flows: expected None or one"),
    (lambda: rd.Scene(frame="F"), TypeError, r"^frame: expected None"),
    (lambda: rd.Scene([rd.Particle(1.0)], elements=[rd.Thrust(0, [0.0, 0.0, 1.0], frame="world")]), ValueError,
     r"^elements\[0\]\.body: expected a body with a mass flow"),
])
def test_bad_frames_flows_and_thrusts_are_refused_naming_the_argument(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_setting_a_bad_frame_leaves_the_scene_unchanged():
    scene = rd.Scene([rd.Particle(1.0)])
    with pytest.raises(TypeError, match=r"^frame: expected"):
        scene.frame = 3
    assert scene.frame is None


# ------------------------------------------------------------------------------------ Python callables

class Boom(Exception):
    pass


def _rocket(flow: rd.MassFlow, body=None) -> rd.Scene:
    scene = rd.Scene()
    scene.add_body(body or rd.Particle(10.0), mass_flow=flow)
    scene.add(rd.Thrust(0, [0.0, 0.0, -100.0], frame="world"))
    return scene


def _raise(*args):
    raise Boom(args)


@pytest.mark.parametrize("build, initial", [
    (lambda: _rocket(rd.MassFlow(rate=_raise)), rd.ParticleState()),
    (lambda: _rocket(rd.MassFlow(inertia_rule=_raise), rd.RigidBody(10.0, I_BOX)), rd.RigidBodyState(w_B=[1.0, 2, 3])),
    (lambda: rd.Scene([rd.Particle(1.0)], frame=rd.SceneFrame.moving(rd.FrameMotion(_raise))), rd.ParticleState()),
])
def test_an_exception_in_a_python_callable_propagates_out_of_simulate(build, initial):
    with pytest.raises(Boom):
        rd.simulate(build(), [initial], dt=0.01, steps=5)


def _nan(*args):
    return float("nan")


def _nan_inertia(m):
    return np.full((3, 3), np.nan)


def _nan_motion(t):
    K = rd.FrameMotion.constant_rotation([0.0, 0.0, 1.0], 0.5).at(t)
    return (K.R_PF, [0.0, 0.0, np.nan], K.alpha_PF_P, K.p_PF_P, K.v_PF_P, K.a_PF_P)


@pytest.mark.parametrize("build, initial, message", [
    (lambda: _rocket(rd.MassFlow(rate=_nan)), rd.ParticleState(), r"mass_flows\[0\]\.rate: expected a finite"),
    (lambda: _rocket(rd.MassFlow(inertia_rule=_nan_inertia), rd.RigidBody(10.0, I_BOX)),
     rd.RigidBodyState(w_B=[1.0, 2, 3]), r"inertia_rule: expected"),
    (lambda: rd.Scene([rd.Particle(1.0)], frame=rd.SceneFrame.moving(rd.FrameMotion(_nan_motion))),
     rd.ParticleState(p_W=[1.0, 0.0, 0.0]), r"^kinematics_at\(t\)\[1\] \(w_PF_P\): expected finite values"),
])
def test_a_python_callable_returning_nan_raises_naming_the_field(build, initial, message):
    with pytest.raises(ValueError, match=message):
        rd.simulate(build(), [initial], dt=0.01, steps=5)


def test_a_mass_running_out_is_an_error_naming_the_flow():
    # 10 kg at -1 kg/s runs out at t = 10 s: a run to 20 s is refused before it starts (constant rate) ...
    with pytest.raises(ValueError, match=r"^mass_flows\[0\]: expected a positive mass.*steps, dt"):
        rd.simulate(_rocket(rd.MassFlow(rate=-1.0)), [rd.ParticleState()], dt=1.0, steps=20)

    # ... and, given as a function of t, at the step where it happens
    def rate(t):
        return -1.0

    with pytest.raises(ValueError, match=r"mass_flows\[0\]: expected a positive mass"):
        rd.simulate(_rocket(rd.MassFlow(rate=rate)), [rd.ParticleState()], dt=1.0, steps=20)


def test_a_distant_pivot_warns_the_digits_it_loses():
    far = rd.PivotedBody(rd.RigidBody(1.0, I_BOX), [0.0, 0.0, 1e4])  # m|c|^2 = 1e8 against 1 kg m^2: 8 digits
    assert far.digits_lost == pytest.approx(8.0, abs=1e-12)
    with pytest.warns(rd.SceneCompatibilityWarning, match=r"bodies\[0\] 'body0': the pivot is"):
        rd.Scene([far]).compile("rk4")


# ------------------------------------------------------------------------------------ the GIL

def test_other_python_threads_run_during_a_pivoted_run():
    # as test_scene_api's: the progress callback is log.append (a C function that never hands the GIL over);
    # with the GIL released during the run, the other thread's -1 land between two progress marks
    log: list[int] = []
    stop = threading.Event()

    def other():
        while not stop.is_set():
            log.append(-1)

    thread = threading.Thread(target=other)
    thread.start()
    try:
        steps = 100_000
        for _ in range(12):
            log.clear()
            rd.simulate(top(), top_state(), dt=1e-5, steps=steps, record_every=steps, gravity=True,
                        method="rk4", progress=log.append)
            marks = [i for i, x in enumerate(log) if x >= 0]
            if len(marks) >= 4:
                break
            steps *= 2
    finally:
        stop.set()
        thread.join()
    assert len(marks) >= 4, "the run never lasted 4 progress intervals"
    assert log[marks[0]:marks[-1]].count(-1) > 0
