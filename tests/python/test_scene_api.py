"""The Python API of scenes (docs: rigiddyn.Scene, rigiddyn.simulate): building a scene, the
force elements' constructors and their checks, repr/pickle round trips, compile with its refusals and
SceneCompatibilityWarning, runs and the shapes of their records, the one-body scene against the body's own
simulate, PythonForce (its errors propagate; it holds the GIL only in its calls) and the GIL released
around a run."""

from __future__ import annotations

import pickle
import threading

import numpy as np
import pytest

import rigiddyn as rd

I_BOX = np.array([1.0, 2.0, 2.5])


def _push(t, body, p_W, q_WB, v_W, w_B):
    """A module-level PythonForce function (picklable): a constant push along x."""
    return (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)


def every_element():
    return [
        rd.UniformGravity(g_W=(0.0, 0.0, -9.81)),
        rd.PointMassGravity(gm=3.986004418e14, p_W=(1.0, 2.0, 3.0), softening=0.5, bodies=[0]),
        rd.MutualGravity(G=1.0, softening=0.1, bodies=[0, 1]),
        rd.GravityGradient(gm=2.0, p_W=(0.0, 0.0, 0.0), bodies=[1]),
        rd.SpringDamper(body_a=0, point_a_B=(0.0, 0.0, 0.0), body_b=1, point_b=(0.1, 0.0, 0.0), stiffness=3.0,
                        rest_length=0.5, damping=0.2),
        rd.SpringDamper(body_a=1, stiffness=3.0),
        rd.Drag(linear=0.1, quadratic=0.2, angular_linear=0.3, angular_quadratic=0.4),
        rd.ScheduledLoads(body=1, loads=[rd.AppliedLoad(force=[1.0, 0.0, 0.0], t_end=0.5)], point_B=(0.0, 0.1, 0.0)),
        rd.PythonForce(_push, bodies=[0]),
    ]


def two_bodies():
    scene = rd.Scene()
    scene.add_body(rd.Particle(2.0), name="dot")
    scene.add_body(rd.RigidBody(1.0, I_BOX), name="box")
    return scene


def two_states():
    return [rd.ParticleState(p_W=[1.0, 0.0, 0.0], v_W=[0.0, 1.0, 0.0]),
            rd.RigidBodyState(p_W=[0.0, 0.0, 0.0], w_B=[0.1, 1.0, 0.1])]


# ------------------------------------------------------------------------------------ construction

def test_a_scene_indexes_its_bodies_and_elements_in_the_order_added():
    scene = rd.Scene()
    assert scene.add_body(rd.Particle(2.0), name="dot") == 0
    assert scene.add_body(rd.RigidBody(1.0, I_BOX)) == 1
    assert scene.add(rd.UniformGravity()) == 0
    assert scene.add(rd.Drag(linear=0.1, bodies=[1])) == 1
    assert scene.body_names == ("dot", "body1")
    assert scene.bodies == (rd.Particle(2.0), rd.RigidBody(1.0, I_BOX))
    assert scene.elements == (rd.UniformGravity(g_W=(0.0, 0.0, -9.81)), rd.Drag(linear=0.1, bodies=(1,)))


def test_element_attributes_read_back_as_given():
    e = rd.SpringDamper(body_a=0, point_a_B=[1, 2, 3], body_b=None, point_b=(4, 5, 6), stiffness=7, rest_length=8,
                        damping=9)
    assert (e.body_a, e.body_b, e.stiffness, e.rest_length, e.damping) == (0, None, 7.0, 8.0, 9.0)
    np.testing.assert_array_equal(e.point_a_B, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(e.point_b, [4.0, 5.0, 6.0])
    with pytest.raises(ValueError):
        e.point_b[0] = 1.0  # read-only copies
    assert rd.Drag().bodies is None and rd.MutualGravity(bodies=np.array([2, 0])).bodies == (2, 0)
    assert rd.MutualGravity().G == 6.67430e-11
    loads = rd.ScheduledLoads(body=0, loads=rd.AppliedLoad(torque=[0, 0, 1.0])).loads
    assert loads == (rd.AppliedLoad(torque=[0, 0, 1.0]),)
    assert rd.PythonForce(_push).fn is _push


@pytest.mark.parametrize("make, error, message", [
    (lambda: rd.UniformGravity(g_W=(0, 0, np.nan)), ValueError, r"^g_W: expected"),
    (lambda: rd.PointMassGravity(gm=-1.0), ValueError, r"^gm: expected a finite number > 0"),
    (lambda: rd.PointMassGravity(gm=1.0, softening=-0.1), ValueError, r"^softening: expected a finite number >= 0"),
    (lambda: rd.MutualGravity(G=0.0), ValueError, r"^G: expected a finite number > 0"),
    (lambda: rd.MutualGravity(bodies=[0, 0]), ValueError, r"^bodies: expected each body once"),
    (lambda: rd.MutualGravity(bodies=[]), ValueError, r"^bodies: expected None \(every body\) or a non-empty"),
    (lambda: rd.MutualGravity(bodies=[-1]), ValueError, r"^bodies\[0\]: expected an integer in \[0, "),
    (lambda: rd.MutualGravity(bodies="01"), TypeError, r"^bodies: expected None \(every body\)"),
    (lambda: rd.GravityGradient(gm=np.inf), ValueError, r"^gm: expected"),
    (lambda: rd.SpringDamper(body_a=0, stiffness=-1.0), ValueError, r"^stiffness: expected a finite number >= 0"),
    (lambda: rd.SpringDamper(body_a=0, body_b=0, stiffness=1.0), ValueError, r"^body_b: expected None"),
    (lambda: rd.SpringDamper(body_a=1.5, stiffness=1.0), TypeError, r"^body_a: expected an integer"),
    (lambda: rd.Drag(angular_quadratic=-2.0), ValueError, r"^angular_quadratic: expected a finite number >= 0"),
    (lambda: rd.ScheduledLoads(body=0, loads=[rd.AppliedLoad(), 3]), TypeError, r"^loads: expected"),
    (lambda: rd.ScheduledLoads(body=0, point_B=(0, 0)), ValueError, r"^point_B: expected"),
    (lambda: rd.PythonForce(3), TypeError, r"^fn: expected a callable"),
])
def test_each_element_refuses_a_bad_argument_naming_it(make, error, message):
    with pytest.raises(error, match=message):
        make()


def test_scene_add_checks_the_element_against_the_bodies_so_far():
    scene = two_bodies()
    with pytest.raises(ValueError, match=r"^element.bodies\[0\]: expected a body index in \[0, 2\), got 2$"):
        scene.add(rd.Drag(linear=1.0, bodies=[2]))
    with pytest.raises(ValueError, match=r"^element.loads\[0\].torque: expected zero \(a particle takes no torque\)"):
        scene.add(rd.ScheduledLoads(body=0, loads=[rd.AppliedLoad(torque=[0, 0, 1.0])]))
    with pytest.raises(TypeError, match=r"^element: expected a force element"):
        scene.add(rd.Particle(1.0))
    with pytest.raises(ValueError, match=r"^name: expected a name no other body of the scene has"):
        scene.add_body(rd.Particle(1.0), name="dot")
    with pytest.raises(TypeError, match=r"^body: expected a Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat or TreeLink"):
        scene.add_body(rd.ParticleState())
    assert len(scene.elements) == 0 and len(scene.bodies) == 2  # nothing refused was added


# ------------------------------------------------------------------------------------ round trips

@pytest.mark.parametrize("element", every_element(), ids=lambda e: type(e).__name__)
def test_each_element_round_trips_through_pickle_and_repr(element):
    assert pickle.loads(pickle.dumps(element)) == element
    # a PythonForce shows its function by name: its repr evaluates where the function is in scope
    assert eval(repr(element), {**vars(rd), "_push": _push}) == element
    assert element != rd.Drag(linear=123.0)


def _full_scene():
    scene = two_bodies()
    for e in every_element():
        scene.add(e)
    return scene


def test_a_scene_round_trips_through_pickle_and_repr():
    scene = _full_scene()
    assert pickle.loads(pickle.dumps(scene)) == scene
    namespace = {**vars(rd), "_push": _push}
    assert eval(repr(scene), namespace) == scene
    other = _full_scene()
    other.add(rd.Drag(linear=1.0))
    assert other != scene


def test_a_compiled_scene_round_trips_and_is_immutable():
    compiled = _full_scene().compile("rk4")
    assert isinstance(compiled, rd.CompiledScene) and compiled.method == "rk4"
    assert pickle.loads(pickle.dumps(compiled)) == compiled
    assert eval(repr(compiled), {**vars(rd), "_push": _push}) == compiled
    assert compiled.scene == _full_scene()
    with pytest.raises(AttributeError):
        compiled.add  # noqa: B018  (no mutator)


# ------------------------------------------------------------------------------------ compile

def test_compile_refuses_what_a_method_cannot_run():
    scene = two_bodies()
    scene.add(rd.UniformGravity())
    with pytest.raises(ValueError, match=r"^method: "):
        scene.compile("exact")
    with pytest.raises(ValueError, match=r"^bodies: "):
        rd.Scene().compile("rk4")
    with pytest.raises(ValueError, match=r"^method: "):
        scene.compile("no_such_method")


@pytest.mark.parametrize("method", ["splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick"])
def test_velocity_dependent_elements_with_a_splitting_warn(method):
    assert issubclass(rd.SceneCompatibilityWarning, UserWarning)
    scene = two_bodies()
    scene.add(rd.Drag(linear=0.1))
    with pytest.warns(rd.SceneCompatibilityWarning) as caught:
        compiled = scene.compile(method)
    assert len(compiled.warnings) == len(caught) >= 1
    with pytest.warns(rd.SceneCompatibilityWarning):  # simulate compiles a Scene the same way
        rd.simulate(scene, two_states(), dt=0.01, steps=1, method=method)


def test_a_position_only_scene_compiles_without_warning(recwarn):
    scene = two_bodies()
    scene.add(rd.MutualGravity(G=1.0))
    assert scene.compile("splitting_dlm").warnings == ()
    assert not [w for w in recwarn if issubclass(w.category, rd.SceneCompatibilityWarning)]


def test_methods_lists_the_scene_features_of_each_method():
    for info in rd.methods():
        assert isinstance(info["scene_features"], str) and info["scene_features"]


# ------------------------------------------------------------------------------------ runs

def test_a_small_scene_runs_and_its_arrays_have_the_documented_shapes():
    scene = two_bodies()
    scene.add(rd.UniformGravity())
    scene.add(rd.SpringDamper(body_a=0, body_b=1, stiffness=2.0, damping=0.1))
    steps, every = 10, 3
    r = rd.simulate(scene, two_states(), dt=0.01, steps=steps, record_every=every)
    n = 1 + steps // every + 1  # the first, every 3rd step (3, 6, 9) and the last (10)
    nb, ne = 2, 2
    shapes = {"t": (n,), "p_W": (n, nb, 3), "q_WB": (n, nb, 4), "v_W": (n, nb, 3), "w_B": (n, nb, 3),
              "kinetic_energy": (n,), "potential_energy": (n,), "total_energy": (n,), "linear_momentum_W": (n, 3),
              "angular_momentum_W": (n, 3), "work": (n, ne), "power": (n, ne)}
    for name, shape in shapes.items():
        a = getattr(r, name)
        assert a.shape == shape and a.dtype == np.float64, name
        assert not a.flags.writeable and not a.flags.owndata, name  # read-only views of the C++ records
    assert r.body_names == ("dot", "box") and r.elements == ("UniformGravity", "SpringDamper")
    np.testing.assert_array_equal(r.t, [0.0, 0.03, 0.06, 0.09, 0.1])
    np.testing.assert_array_equal(r.q_WB[:, 0], np.tile([0.0, 0.0, 0.0, 1.0], (n, 1)))  # a particle's identity
    np.testing.assert_array_equal(r.p_W[0, 0], [1.0, 0.0, 0.0])
    first = rd.simulate(scene, two_states(), dt=0.01, steps=steps, record_every=every, scalar_first=True)
    np.testing.assert_array_equal(first.q_WB, r.q_WB[..., [3, 0, 1, 2]])
    assert pickle.loads(pickle.dumps(r)).work.tolist() == r.work.tolist()
    assert "SceneResult(records=5" in repr(r)


def test_to_dataframe_is_one_row_per_record_with_each_body_s_columns():
    pytest.importorskip("pandas")
    scene = two_bodies()
    scene.add(rd.UniformGravity())
    r = rd.simulate(scene, two_states(), dt=0.01, steps=4)
    df = r.to_dataframe()
    assert len(df) == 5 and df.columns[0] == "t [s]"
    np.testing.assert_array_equal(df["box:w_B_y [rad/s]"], r.w_B[:, 1, 1])
    np.testing.assert_array_equal(df["dot:p_W_x [m]"], r.p_W[:, 0, 0])
    np.testing.assert_array_equal(df["work[0] UniformGravity [J]"], r.work[:, 0])
    np.testing.assert_array_equal(df["angular_momentum_W_z [kg m^2/s]"], r.angular_momentum_W[:, 2])
    # per body: state 13, reaction 3, H_O 3, mass, mass-flow energy
    assert len(df.columns) == 1 + 2 * (13 + 8) + 3 + 6 + 2


@pytest.mark.parametrize("method", ["rk4", "splitting_dlm", "implicit_midpoint"])
def test_a_one_body_scene_equals_the_body_s_simulate(method):
    body, state = rd.RigidBody(1.0, I_BOX), rd.RigidBodyState(v_W=[1.0, 0.0, 2.0], w_B=[0.1, 1.0, 0.1])
    load = rd.AppliedLoad(torque=[0.0, 0.0, 0.3], frame="body", t_end=0.05)
    scene = rd.Scene()
    scene.add_body(body)
    scene.add(rd.UniformGravity(g_W=(0.0, 0.0, -9.81)))
    scene.add(rd.ScheduledLoads(body=0, loads=[load]))
    body_run = rd.simulate(body, state, dt=0.01, steps=20, method=method, loads=[load], gravity=True)
    r = rd.simulate(scene.compile(method), [state], dt=0.01, steps=20)
    # the compiled one-body scene runs the scene model's one-body layout, whose rk4 and splitting_dlm steps are the
    # rigid-body model's operations: the same bits. The implicit midpoint solves the same fixed point to its tolerance
    # (1e-14 relative) with a convergence test over other coordinates: 20 steps x 2 x 1e-14, x 10 for the growth of
    # a difference over 0.2 s, relative to each quantity
    def expect_same(actual, desired, name):
        if method == "implicit_midpoint":
            np.testing.assert_allclose(actual, desired, rtol=4e-12, atol=4e-12 * np.abs(desired).max(), err_msg=name)
        else:
            np.testing.assert_array_equal(actual, desired, err_msg=name)

    for name in ("t", "kinetic_energy", "total_energy"):
        expect_same(getattr(r, name), getattr(body_run, name), name)
    for name in ("p_W", "q_WB", "v_W", "w_B"):
        expect_same(getattr(r, name)[:, 0], getattr(body_run.body(0), name), name)


def test_step_of_a_scene_returns_the_states_of_its_bodies():
    scene = two_bodies()
    scene.add(rd.SpringDamper(body_a=0, body_b=1, stiffness=2.0))
    states = rd.step(scene, two_states(), dt=0.01)
    assert [type(s) for s in states] == [rd.ParticleState, rd.RigidBodyState]
    states, t = rd.step(scene.compile("rk4"), states, dt=0.01, t=0.01)
    assert t == 0.02
    with pytest.raises(TypeError, match=r"^state\[1\]: expected a RigidBodyState \(the state of body 1 'box'\)"):
        rd.step(scene, [rd.ParticleState(), rd.ParticleState()], dt=0.01)
    with pytest.raises(ValueError, match=r"^state: expected a list of 2 body states"):
        rd.step(scene, [rd.ParticleState()], dt=0.01)


def test_a_scene_run_refuses_body_arguments_and_another_method():
    scene = two_bodies()
    with pytest.raises(ValueError, match=r"^loads: expected None for a scene"):
        rd.simulate(scene, two_states(), dt=0.01, steps=1, loads=[rd.AppliedLoad()])
    with pytest.raises(ValueError, match=r"^gravity: expected None for a scene"):
        rd.simulate(scene, two_states(), dt=0.01, steps=1, gravity=True)
    with pytest.raises(ValueError, match=r"^method: expected None or 'rk4' \(the method `model` was compiled for\)"):
        rd.simulate(scene.compile("rk4"), two_states(), dt=0.01, steps=1, method="splitting_dlm")
    with pytest.raises(TypeError, match=r"^initial\[0\]: expected a ParticleState"):
        rd.simulate(scene, two_states()[::-1], dt=0.01, steps=1)


# ------------------------------------------------------------------------------------ PythonForce

def test_a_python_force_equals_the_built_in_element_of_the_same_law():
    # f = -k p on a particle: SpringDamper to a world anchor at the origin (rest length 0, no damping)
    # computes -k (p - 0) - 0 (v - 0) = -k p with the same floating-point operations as the callable, so
    # both runs are the same bits (a bound of 0).
    k = 4.0

    def spring(t, body, p_W, q_WB, v_W, w_B):
        return -k * p_W, np.zeros(3)

    runs = []
    for element in (rd.SpringDamper(body_a=0, stiffness=k), rd.PythonForce(spring)):
        scene = rd.Scene()
        scene.add_body(rd.Particle(2.0))
        scene.add_body(rd.Particle(3.0))
        scene.add(element)
        runs.append(rd.simulate(scene, [rd.ParticleState(p_W=[1.0, 0.0, 0.0]), rd.ParticleState(v_W=[0, 1.0, 0])],
                                dt=0.01, steps=50))
    spring_run, python_run = runs
    np.testing.assert_array_equal(python_run.p_W[:, 0], spring_run.p_W[:, 0])
    np.testing.assert_array_equal(python_run.v_W[:, 0], spring_run.v_W[:, 0])
    # the callable acts on every body; the spring only on body 0
    assert np.all(python_run.v_W[1:, 1, 1] < 1.0)


def test_the_python_force_is_called_with_each_body_s_kinematics():
    calls = []

    def record(t, body, p_W, q_WB, v_W, w_B):
        calls.append((t, body, p_W.shape, q_WB.shape, v_W.shape, w_B.shape))
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)

    scene = two_bodies()
    scene.add(rd.PythonForce(record, bodies=[1]))
    rd.simulate(scene, two_states(), dt=0.01, steps=1, method="rk4")
    assert {c[1] for c in calls} == {1}
    assert {c[2:] for c in calls} == {((3,), (4,), (3,), (3,))}
    assert sorted({c[0] for c in calls}) == [0.0, 0.005, 0.01]  # RK4's stage times


def test_an_exception_in_a_python_force_stops_the_run_and_propagates():
    class Boom(Exception):
        pass

    count = [0]

    def fail_later(t, body, p_W, q_WB, v_W, w_B):
        count[0] += 1
        if count[0] > 7:
            raise Boom("from the force")
        return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)

    scene = two_bodies()
    scene.add(rd.PythonForce(fail_later))
    with pytest.raises(Boom, match="from the force"):
        rd.simulate(scene, two_states(), dt=0.01, steps=1000)
    assert count[0] == 8  # stopped at the first exception
    with pytest.raises(Boom):
        rd.step(scene, two_states(), dt=0.01, t=0.0)


@pytest.mark.parametrize("returned, error, message", [
    (lambda p: (p, p, p), TypeError, r"^fn: expected a callable returning \(f_W"),
    (lambda p: 3.0, TypeError, r"^fn: expected a callable returning \(f_W"),
    (lambda p: (p[:2], p), ValueError, r"^fn: returned f_W: expected"),
    (lambda p: (p, p * np.nan), ValueError, r"^fn: returned tau_B: expected"),
])
def test_a_python_force_returning_a_wrong_value_is_refused_naming_fn(returned, error, message):
    scene = two_bodies()
    scene.add(rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: returned(np.ones(3))))
    with pytest.raises(error, match=message):
        rd.simulate(scene, two_states(), dt=0.01, steps=3)


# ------------------------------------------------------------------------------------ the GIL

def test_other_python_threads_run_during_a_scene_run():
    # A thread appends -1 to `log` in a loop; the run's progress callback is log.append itself, a C
    # function: it appends steps_done (>= 0) with the GIL and runs no bytecode, so it never hands the GIL
    # to the thread. With the GIL held through the run, no -1 could land between two progress marks; with
    # it released, the thread appends between them. The run is lengthened until it makes 4 marks (one
    # about every 0.05 s).
    scene = rd.Scene()
    for i in range(8):
        scene.add_body(rd.Particle(1.0 + i))
    scene.add(rd.MutualGravity(G=1e-3, softening=0.1))
    states = [rd.ParticleState(p_W=[float(i), 0.0, 0.0], v_W=[0.0, 0.1, 0.0]) for i in range(8)]
    log: list[int] = []
    stop = threading.Event()

    def other():
        while not stop.is_set():
            log.append(-1)

    thread = threading.Thread(target=other)
    thread.start()
    try:
        steps = 20_000
        for _ in range(12):
            log.clear()
            rd.simulate(scene, states, dt=1e-3, steps=steps, record_every=steps, progress=log.append)
            marks = [i for i, x in enumerate(log) if x >= 0]
            if len(marks) >= 4:
                break
            steps *= 2
    finally:
        stop.set()
        thread.join()
    assert len(marks) >= 4, "the run never lasted 4 progress intervals"
    between = log[marks[0]:marks[-1]]
    assert between.count(-1) > 0


def test_an_exception_in_progress_stops_a_scene_run_and_propagates():
    class Stop(Exception):
        pass

    def progress(steps_done):
        raise Stop(steps_done)

    scene = two_bodies()
    scene.add(rd.MutualGravity(G=1e-3, softening=0.1))
    steps = 4096
    for _ in range(12):  # the monitor reports about every 0.05 s: lengthen the run until it does
        try:
            rd.simulate(scene, two_states(), dt=1e-3, steps=steps, record_every=steps, progress=progress)
        except Stop as stopped:
            assert 0 < stopped.args[0] <= steps  # no result: the exception replaced it
            return
        steps *= 4
    pytest.fail("progress was never called")


def test_exact_runs_a_one_body_scene_in_closed_form():
    """'exact' compiles for one body under uniform gravity (the closed form and a constant force, as
    simulate(body, ...) runs it) and gives the body's own numbers bitwise."""
    body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    state = rd.RigidBodyState(v_W=[1.0, 0.0, 2.0], w_B=[0.1, 1.0, 0.2])
    scene = rd.Scene()
    scene.add_body(body)
    scene.add(rd.UniformGravity(g_W=[0.0, 0.0, -9.81]))
    got = rd.simulate(scene.compile("exact"), [state], dt=0.01, steps=50)
    want = rd.simulate(body, state, dt=0.01, steps=50, method="exact", gravity=[0.0, 0.0, -9.81])
    for name in ("p_W", "q_WB", "v_W", "w_B"):
        np.testing.assert_array_equal(getattr(got, name)[:, 0], getattr(want.body(0), name))
    scene.add(rd.Drag(linear=0.1))
    with pytest.raises(ValueError, match=r"^method: 'exact' needs one torque-free body"):
        scene.compile("exact")
