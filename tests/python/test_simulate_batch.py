"""rigiddyn.simulate_batch: a batch is N serial rigiddyn.simulate calls bitwise, for every body kind (its one-body
scene) and for scenes, whatever the thread count; per-sample bodies, dt, gravity and loads are each the serial run with
that parameter; a diverged sample stops alone (flagged, NaN-padded, one RuntimeWarning); a failing sample raises
"sample <i>: ..."; bad input is refused naming the argument; BatchSceneResult pickles; the SIMD path gives the scene's
columns to round-off."""

import os
import pickle
import re
import signal
import threading

import numpy as np
import pytest

import rigiddyn as rd

EPS = np.finfo(float).eps
BODY = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
SCENE_ARRAYS = ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "potential_energy", "total_energy",
                "linear_momentum_W", "angular_momentum_W", "pivot_reaction_W", "angular_momentum_O_W", "mass", "work",
                "power")


def tumbling_states(n):
    """n different tumbling rigid-body states (rates growing with the index)."""
    out = []
    for i in range(n):
        s = 1.0 + 0.1 * i
        angle = 0.3 * s
        axis = np.array([1.0, -1.0, 2.0]) / np.sqrt(6.0)
        q = np.concatenate([np.sin(angle / 2) * axis, [np.cos(angle / 2)]])
        out.append(rd.RigidBodyState(p_W=[0.5 * s, -1.0, 2.0], q_WB=q, v_W=[0.2, 0.1 * s, -0.1],
                                     w_B=[0.3 * s, 1.0, -0.2 * s]))
    return out


def as_dict(states, scalar_first=False):
    q = np.array([s.q_WB for s in states])
    return {"p_W": np.array([s.p_W for s in states]), "q_WB": q[:, [3, 0, 1, 2]] if scalar_first else q,
            "v_W": np.array([s.v_W for s in states]), "w_B": np.array([s.w_B for s in states])}


def assert_sample_is(batch, i, serial, names=SCENE_ARRAYS):
    """Sample i of the batch is the serial result bitwise, its rows after filled[i] NaN."""
    n = len(serial.t)
    assert batch.filled[i] == n
    assert batch.diverged[i] == serial.diverged
    assert batch.unconverged_steps[i] == serial.unconverged_steps
    for name in names:
        stacked = getattr(batch, name)[i]
        assert np.isnan(stacked[n:]).all(), name
        assert np.array_equal(getattr(batch[i], name), stacked[:n], equal_nan=True), name
        assert np.array_equal(stacked[:n], getattr(serial, name), equal_nan=serial.diverged), name


def assert_same_batch(a, b, names=SCENE_ARRAYS):
    for name in names:
        assert np.array_equal(getattr(a, name), getattr(b, name), equal_nan=True), name
    for name in ("diverged", "filled", "unconverged_steps"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


# ---- the batch is N serial runs bitwise -----------------------------------------------------------------

def test_rigid_body_batch_is_serial_runs_bitwise_on_any_thread_count():
    states = tumbling_states(9)
    first = rd.simulate_batch(BODY, states, 0.01, 50, record_every=3, threads=1)  # 50 = 16*3 + 2
    assert len(first) == 9 and first.p_W.shape == (9, 18, 1, 3) and first.q_WB.shape == (9, 18, 1, 4)
    assert first.body(0).p_W.shape == (9, 18, 3) and first.body_names == ("body0",) and first.elements == ()
    for i, s in enumerate(states):
        assert_sample_is(first, i, rd.simulate(BODY, s, 0.01, 50, record_every=3))
    for threads in (2, 3, 7, None):
        assert_same_batch(rd.simulate_batch(BODY, states, 0.01, 50, record_every=3, threads=threads), first)


def test_dict_input_equals_the_states_in_either_quaternion_order():
    states = tumbling_states(4)
    base = rd.simulate_batch(BODY, states, 0.01, 20, threads=2)
    assert_same_batch(rd.simulate_batch(BODY, as_dict(states), 0.01, 20, threads=2), base)
    first = rd.simulate_batch(BODY, as_dict(states, True), 0.01, 20, threads=2, scalar_first=True)
    assert np.array_equal(first.q_WB[..., [1, 2, 3, 0]], base.q_WB)
    assert np.array_equal(first.w_B, base.w_B)


def test_particle_and_planar_batches_with_per_sample_gravity_are_serial_runs():
    n = 5
    gravity = np.array([[0.1 * i, -9.81, 0.0] for i in range(n)])
    particle, planar = rd.Particle(1.5), rd.PlanarBody(2.0, 0.3)
    particles = {"p_W": np.array([[1.0, 0.1 * i, 0.0] for i in range(n)]),
                 "v_W": np.array([[0.0, 1.0, 0.5 * i] for i in range(n)])}
    planars = [rd.PlanarBodyState(p_W=[0.2 * i, 1.0], theta=0.1 * i, v_W=[1.0, -0.5], omega=1.0 + i) for i in range(n)]
    planar_dict = {"p_W": np.array([s.p_W for s in planars]), "theta": np.array([s.theta for s in planars]),
                   "v_W": np.array([s.v_W for s in planars]), "omega": np.array([s.omega for s in planars])}
    bp = rd.simulate_batch(particle, particles, 0.01, 40, record_every=7, gravity=gravity, threads=2)
    bq = rd.simulate_batch(planar, planars, 0.01, 40, record_every=7, gravity=gravity, threads=2)
    assert_same_batch(rd.simulate_batch(planar, planar_dict, 0.01, 40, record_every=7, gravity=gravity, threads=3), bq)
    for i in range(n):
        state = rd.ParticleState(p_W=particles["p_W"][i], v_W=particles["v_W"][i])
        assert_sample_is(bp, i, rd.simulate(particle, state, 0.01, 40, record_every=7, gravity=gravity[i]))
        assert_sample_is(bq, i, rd.simulate(planar, planars[i], 0.01, 40, record_every=7, gravity=gravity[i]))


def test_each_per_sample_parameter_is_the_serial_run_with_it():
    n = 5
    states = tumbling_states(n)
    scale = 1.0 + 0.25 * np.arange(n)
    bodies = [rd.RigidBody(s, [1.0 * s, 1.5 * s, 2.0 * s]) for s in scale]
    dts = 0.01 * scale
    gravity = np.array([[0.0, -s, -9.81] for s in scale])
    loads = [[rd.AppliedLoad(force=[s, 0.0, 0.0], torque=[0.0, 0.0, 0.1 * s], frame="world", t_start=0.05 * s,
                             t_end=0.2)] for s in scale]  # a switch inside most samples' runs
    common = dict(dt=0.01, gravity=True, loads=rd.AppliedLoad(torque=[0.0, 0.2, 0.0], frame="body"))
    cases = {"model": bodies, "dt": dts, "gravity": gravity, "loads": loads}
    for name, values in cases.items():
        args = dict(common, **({} if name == "model" else {name: values}))
        batch = rd.simulate_batch(values if name == "model" else BODY, states, steps=30, record_every=4, threads=2,
                                  **args)
        for i in range(n):
            one = dict(common, **({} if name == "model" else {name: values[i]}))
            serial = rd.simulate(bodies[i] if name == "model" else BODY, states[i], steps=30, record_every=4, **one)
            assert_sample_is(batch, i, serial)


def test_per_sample_gravity_and_loads_are_declared_in_every_sample():
    """Gravity and loads given per sample are elements of every sample's scene, g = 0 and no load included: the
    samples' records have the same columns, and each sample is the serial run of its scene."""
    states = tumbling_states(3)
    gravity = np.array([[0.0, 0.0, -9.81], [0.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
    loads = [[rd.AppliedLoad(torque=[0.0, 0.0, 0.3], frame="body")], [], [rd.AppliedLoad(force=[1.0, 0.0, 0.0])]]
    batch = rd.simulate_batch(BODY, states, 0.01, 20, record_every=5, gravity=gravity, loads=loads, threads=2)
    assert batch.elements == ("UniformGravity", "ScheduledLoads") and batch.work.shape == (3, 5, 2)
    for i in range(3):
        elements = [rd.UniformGravity(g_W=gravity[i]), rd.ScheduledLoads(body=0, loads=loads[i])]
        scene = rd.Scene([BODY], elements=elements)
        assert_sample_is(batch, i, rd.simulate(scene, [states[i]], 0.01, 20, record_every=5))
    # given for all: declared only where it acts, as simulate declares a body's
    assert rd.simulate_batch(BODY, states, 0.01, 20, gravity=[0.0, 0.0, 0.0], loads=[]).elements == ()


def test_body_reads_one_body_of_every_sample():
    batch = rd.simulate_batch(BODY, tumbling_states(3), 0.01, 20, record_every=5, gravity=True)
    records = batch.body(0)
    assert records.name == "body0" and records.t.shape == (3, 5) and records.q_WB.shape == (3, 5, 4)
    assert np.array_equal(records.w_B, batch.w_B[:, :, 0]) and np.array_equal(records.mass, batch.mass[:, :, 0])
    for i in range(3):  # the derived columns of each sample are its run's
        assert np.array_equal(records.angular_momentum_norm[i], batch[i].body(0).angular_momentum_norm)
        assert np.array_equal(records.quaternion_norm_error[i], batch[i].body(0).quaternion_norm_error)
    assert np.array_equal(batch.body("body0").p_W, records.p_W)  # by its name
    assert pickle.loads(pickle.dumps(records)).p_W.shape == (3, 5, 3)
    with pytest.raises(ValueError, match=re.escape("key: expected an integer in [-1, 0], got 1")):
        batch.body(1)


# ---- a diverged sample stops alone ----------------------------------------------------------------------

def test_a_diverged_sample_stops_alone_nan_padded_with_one_warning():
    states = tumbling_states(7)
    # explicit Euler: the gyroscopic term (I w) x w ~ 1e300 at |w| ~ 1e150 overflows to inf within a few steps
    for i in (2, 5):
        states[i] = rd.RigidBodyState(w_B=[1e150, 2e150, 3e150])
    for threads in (1, 2, 3):
        with pytest.warns(RuntimeWarning) as record:
            batch = rd.simulate_batch(BODY, states, 0.1, 20, method="explicit_euler", threads=threads)
        assert len(record) == 1
        assert str(record[0].message) == ("simulate_batch: 2 of 7 samples became non-finite (samples 2, 5); "
                                          "their runs stopped there")
        assert batch.diverged.tolist() == [False, False, True, False, False, True, False]
        assert (batch.filled[[2, 5]] < 21).all() and (batch.filled[[0, 1, 3, 4, 6]] == 21).all()
        for i, s in enumerate(states):
            if i in (2, 5):
                with pytest.warns(RuntimeWarning, match="non-finite"):
                    serial = rd.simulate(BODY, s, 0.1, 20, method="explicit_euler")
            else:  # the batch's own run, coarse on purpose: no AccuracyWarning (the batch gives none)
                serial = rd.simulate(BODY, s, 0.1, 20, method="explicit_euler", accuracy_level=None)
            assert_sample_is(batch, i, serial)


# ---- scenes ---------------------------------------------------------------------------------------------

def spring_scene(stiffness):
    return rd.Scene(bodies=[BODY, rd.RigidBody(1.0, [0.5, 0.5, 0.8])], elements=[
        rd.UniformGravity(g_W=(0.0, 0.0, -9.81)),
        rd.SpringDamper(body_a=0, point_a_B=(0.1, 0.0, 0.0), body_b=1, stiffness=stiffness, rest_length=0.5,
                        damping=0.1)])


def spring_states(n):
    a = tumbling_states(n)
    return [[a[i], rd.RigidBodyState(p_W=np.add(a[n - 1 - i].p_W, [1.0, 0.0, 0.0]), q_WB=a[n - 1 - i].q_WB,
                                     w_B=a[n - 1 - i].w_B)] for i in range(n)]


def test_scene_batch_is_serial_runs_bitwise_shared_or_per_sample():
    n = 4
    states = spring_states(n)
    shared = spring_scene(20.0).compile("rk4")
    scenes = [spring_scene(10.0 + 5.0 * i) for i in range(n)]
    dts = 0.005 * (1.0 + np.arange(n))
    a = rd.simulate_batch(shared, states, 0.01, 25, record_every=4, threads=1)
    b = rd.simulate_batch(scenes, states, dts, 25, record_every=4, threads=2)
    assert a.p_W.shape == (n, 8, 2, 3) and a.work.shape == (n, 8, 2) and a.body_names == ("body0", "body1")
    for threads in (2, 3):
        assert_same_batch(rd.simulate_batch(shared, states, 0.01, 25, record_every=4, threads=threads), a)
    for i in range(n):
        assert_sample_is(a, i, rd.simulate(shared, states[i], 0.01, 25, record_every=4))
        assert_sample_is(b, i, rd.simulate(scenes[i], states[i], dts[i], 25, record_every=4))
    assert isinstance(a[0], rd.SceneResult)


def test_a_scene_with_a_python_force_runs_on_threads():
    def push(t, body, p_W, q_WB, v_W, w_B):
        return (np.array([0.0, 0.0, 1.0 + t]), np.zeros(3))

    scene = rd.Scene(bodies=[rd.Particle(1.0)], elements=[rd.PythonForce(push)])
    states = [[rd.ParticleState(v_W=[float(i), 0.0, 0.0])] for i in range(4)]
    batch = rd.simulate_batch(scene, states, 0.01, 10, threads=2)
    for i in range(4):
        assert_sample_is(batch, i, rd.simulate(scene, states[i], 0.01, 10))


# ---- errors of one sample ------------------------------------------------------------------------------

def test_a_sample_whose_mass_runs_out_raises_naming_the_lowest_sample():
    # 1 kg losing 1 kg/s runs out at t = 1 s: samples 2 and 3 (dt 0.1 s, 20 steps) reach it, the others end at 0.2 s
    scene = rd.Scene(bodies=[rd.Particle(1.0)], mass_flows=[rd.MassFlow(rate=-1.0)])
    states = [[rd.ParticleState()] for _ in range(5)]
    with pytest.raises(ValueError, match=r"^sample 2: mass_flows\[0\]"):
        rd.simulate_batch(scene, states, [0.01, 0.01, 0.1, 0.1, 0.01], 20, threads=2)


def test_a_bad_state_raises_naming_its_sample():
    d = as_dict(tumbling_states(4))
    d["p_W"][3, 0] = np.nan
    d["q_WB"][1] = [0.0, 0.0, 0.0, 2.0]  # not a unit quaternion
    with pytest.raises(ValueError, match=r"^sample 1: initial\[0\]\.q_WB"):  # body 0 of sample 1
        rd.simulate_batch(BODY, d, 0.01, 5, threads=2)


def test_a_sample_s_bad_parameter_raises_naming_the_lowest_such_sample():
    """Per-sample scenes are compiled on every thread; the lowest sample whose gravity a planar body cannot take is
    named, whatever the thread count."""
    gravity = [[0.0, -9.81, 1.0 if i in (150, 170) else 0.0] for i in range(200)]
    for threads in (1, 3):
        with pytest.raises(ValueError, match=re.escape("sample 150: gravity: expected gravity in the xy plane "
                                                       "(z = 0) for a PlanarBody")):
            rd.simulate_batch(rd.PlanarBody(1.0, 0.5), [rd.PlanarBodyState()] * 200, 0.01, 2, gravity=gravity,
                              threads=threads)


# ---- bad input --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, error, message", [
    (dict(initial=[]), ValueError, "initial: expected at least one sample, got 0"),
    (dict(model=[BODY, BODY]), ValueError, "model: expected one RigidBody per sample (N = 3, as initial), got 2"),
    (dict(model=[BODY, BODY, rd.Particle(1.0)]), TypeError, "model[2]: expected a RigidBody (as model[0])"),
    (dict(model="body"), TypeError, "model: expected a RigidBody, PlanarBody, Particle, Scene or CompiledScene"),
    (dict(dt=[0.1, 0.2]), ValueError, "dt: expected one step [s] per sample (N = 3, as initial), got 2"),
    (dict(dt=np.zeros((3, 1))), ValueError, "dt: expected a float [s] or an array of shape (N,)"),
    (dict(gravity=np.zeros((4, 3))), ValueError,
     "gravity: expected one gravity vector per sample (N = 3, as initial), got 4"),
    (dict(loads=[[], []]), ValueError, "loads: expected one load schedule per sample (N = 3, as initial), got 2"),
    (dict(threads=0), ValueError, "threads: expected None (all cores) or an integer >= 1, got 0"),
    (dict(threads=-2), ValueError, "threads: expected None (all cores) or an integer >= 1, got -2"),
    (dict(threads=1.5), TypeError, "threads: expected an integer"),
    (dict(threads=True), TypeError, "threads: expected an integer"),
    (dict(steps=-1), ValueError, "steps: expected an integer in [0, "),
    (dict(initial={"p_W": np.zeros((3, 3)), "v_W": np.zeros((3, 3))}), ValueError,
     "initial: expected a dict with the keys 'p_W', 'q_WB', 'v_W', 'w_B', got keys 'p_W', 'v_W'"),
    (dict(initial=dict(as_dict(tumbling_states(3)), q_WB=np.zeros((3, 3)))), ValueError,
     "initial['q_WB']: expected an array of shape (N, 4)"),
    (dict(initial=dict(as_dict(tumbling_states(3)), w_B=np.zeros((2, 3)))), ValueError,
     "initial['w_B']: expected an array of shape (N, 3) with N = 3 (as initial['p_W'])"),
    (dict(initial=[rd.ParticleState()] * 3), TypeError, "initial[0]: expected a RigidBodyState"),
    (dict(simd=True, method="explicit_euler"), ValueError, "simd: expected False for method 'explicit_euler'"),
    (dict(model=rd.Particle(1.0), initial=[rd.ParticleState()] * 3, simd=True), ValueError,
     "simd: expected False for a Particle"),
])
def test_bad_input_names_the_argument(kwargs, error, message):
    args = dict(model=BODY, initial=tumbling_states(3), dt=0.01, steps=5, threads=1)
    args.update(kwargs)
    with pytest.raises(error, match="^" + re.escape(message)):
        rd.simulate_batch(**args)


def test_bad_scene_input_names_the_argument():
    scene = spring_scene(1.0)
    states = spring_states(3)
    with pytest.raises(ValueError, match=re.escape("gravity: expected None for a scene")):
        rd.simulate_batch(scene, states, 0.01, 5, gravity=True)
    with pytest.raises(ValueError, match=re.escape("model: expected one Scene or CompiledScene per sample (N = 3")):
        rd.simulate_batch([scene, scene], states, 0.01, 5)
    with pytest.raises(ValueError, match=re.escape("initial[1]: expected a list of 2 body states")):
        rd.simulate_batch(scene, [states[0], states[1][:1], states[2]], 0.01, 5)
    with pytest.raises(ValueError, match=re.escape("method: expected None or 'rk4'")):
        rd.simulate_batch(scene.compile("rk4"), states, 0.01, 5, method="explicit_euler")
    with pytest.raises(ValueError, match=r"^scenes\[1\]: expected a scene of 2 bodies"):
        rd.simulate_batch([scene, rd.Scene(bodies=[BODY])], [states[0], [states[1][0]]], 0.01, 5)


# ---- results, progress, SIMD --------------------------------------------------------------------------------

def test_results_are_read_only_and_pickle():
    states = tumbling_states(3)
    states[1] = rd.RigidBodyState(w_B=[1e150, 2e150, 3e150])
    with pytest.warns(RuntimeWarning, match="1 of 3 samples"):
        batch = rd.simulate_batch(BODY, states, 0.1, 20, method="explicit_euler", threads=2)
    with pytest.raises(ValueError):
        batch.w_B[0, 0, 0] = 1.0
    again = pickle.loads(pickle.dumps(batch))
    assert len(again) == 3 and again.elapsed_seconds == batch.elapsed_seconds
    assert_same_batch(again, batch)
    assert again[-1].diverged is False and again[1].diverged is True
    with pytest.raises(IndexError):
        batch[3]
    scene_batch = rd.simulate_batch(spring_scene(5.0), spring_states(2), 0.01, 5)
    scene_again = pickle.loads(pickle.dumps(scene_batch))
    assert_same_batch(scene_again, scene_batch)
    assert scene_again.body_names == scene_batch.body_names and scene_again.elements == scene_batch.elements


def test_progress_is_called_and_its_exception_stops_the_batch():
    seen = []
    rd.simulate_batch(BODY, tumbling_states(4), 0.01, 10, threads=2, progress=seen.append)
    assert seen and all(0 <= k <= 4 for k in seen)

    def stop(samples_done):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rd.simulate_batch(BODY, tumbling_states(4), 0.01, 10, threads=2, progress=stop)
    with pytest.raises(KeyboardInterrupt):  # the SIMD path asks its monitor too
        rd.simulate_batch(BODY, tumbling_states(4), 0.01, 5000, record_every=5000, threads=2, simd=True, progress=stop)


def test_ctrl_c_stops_every_sample():
    # SIGINT handled as at a terminal (a process started as a background job inherits it ignored, and then no
    # Ctrl-C, real or simulated, does anything), sent from another thread once progress reports the batch
    # running: 4 samples of 1e8 steps, minutes, stopped on both threads (a failure is a slow test, not a hang)
    started, done = threading.Event(), threading.Event()

    def send():
        while not started.wait(0.01):
            if done.is_set():
                return
        os.kill(os.getpid(), signal.SIGINT)

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    sender = threading.Thread(target=send)
    sender.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            try:
                rd.simulate_batch(BODY, tumbling_states(4), 1e-4, 10**8, record_every=10**8, threads=2,
                                  progress=lambda samples_done: started.set())
            finally:
                done.set()
                sender.join()
    finally:
        signal.signal(signal.SIGINT, previous)
    assert started.is_set()


def test_simd_refuses_a_load_that_turns_with_the_body_naming_its_part_under_its_frame():
    # a world-frame load: its force (in W) is taken, its torque (in W) is not; the message names that torque as
    # the load's, in W (before: "got a force in B [0, 0, 0] N and a torque in W ...", a force the load lacks)
    load = rd.AppliedLoad(force=[1.0, 0.0, 0.0], torque=[0.0, 0.0, 2.0])
    with pytest.raises(ValueError, match=r"^loads: expected forces in W and torques in B \(.*\), got loads\[0\] "
                                         r"\(frame 'world'\) with a torque in W of \[0, 0, 2\] N m$"):
        rd.simulate_batch(BODY, tumbling_states(2), 0.01, 10, loads=load, simd=True)
    body_force = rd.AppliedLoad(force=[0.0, 3.0, 0.0], torque=[0.0, 0.0, 2.0], frame="body")
    with pytest.raises(ValueError, match=r"got loads\[1\] \(frame 'body'\) with a force in B of \[0, 3, 0\] N$"):
        rd.simulate_batch(BODY, tumbling_states(2), 0.01, 10, loads=[rd.AppliedLoad(force=[1.0, 0.0, 0.0]), body_force],
                          simd=True)


def test_simd_path_matches_the_scalar_path_to_round_off():
    states = tumbling_states(6)
    steps = 50
    gravity, loads = [0.0, -1.0, -9.81], [rd.AppliedLoad(force=[1.0, 0.0, 0.5]), rd.AppliedLoad(torque=[0.0, 0.3, 0.0],
                                                                                                frame="body")]
    scalar = rd.simulate_batch(BODY, states, 0.01, steps, threads=2, gravity=gravity, loads=loads)
    simd = rd.simulate_batch(BODY, states, 0.01, steps, threads=2, simd=True, gravity=gravity, loads=loads)
    assert simd.w_B.shape == scalar.w_B.shape and (simd.filled == scalar.filled).all()
    assert simd.elements == scalar.elements == ("UniformGravity", "ScheduledLoads")
    # the SIMD path runs the full form of Euler's equations where the scalar one may run the principal form: a
    # few ulps per derivative evaluation (<= 16 eps of the state's scale per stage, 4 stages a step), carried
    # without growth over 0.5 s of a body spinning at ~1 rad/s: <= steps * 4 * 16 eps * scale
    state_rel = steps * 4 * 16 * EPS
    for name in ("p_W", "q_WB", "v_W", "w_B"):
        a, b = getattr(simd, name), getattr(scalar, name)
        assert np.abs(a - b).max() <= state_rel * np.abs(b).max(), name
    # every other column is at most quadratic in the state (T, V = -m g.p, m v, p x m v + R I w, the powers) or, for
    # the works, the integral of such a column over the run: each differs by <= 2 state_rel of the size of its
    # terms S (first order in the state's difference), plus its own rounding, <= 16 eps S per evaluation and
    # 4 eps S per step of an integral; S bounds every term of every column, the product of the largest state
    # magnitude, the mass properties and the loads
    r = np.abs(scalar.p_W).max() + 1.0
    v, w = np.abs(scalar.v_W).max(), np.abs(scalar.w_B).max()
    S = (BODY.mass * (v + 9.9) + 3.0 * w + 1.2) * (r + v + w + 1.0)
    bound = (2 * state_rel + 16 * EPS + 4 * EPS * (steps + 1)) * S
    for name in SCENE_ARRAYS[5:]:
        a, b = getattr(simd, name), getattr(scalar, name)
        assert np.abs(a - b).max() <= bound, name
