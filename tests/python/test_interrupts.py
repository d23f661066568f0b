"""Ctrl-C and errors that stop a run: a SIGINT stops simulate and simulate_batch within about 0.05 s however
long a step takes (monitor_pace.hpp), also the runs of an estimate made on the first read of result.error, is
never swallowed by the conversion of an argument, and an exception from a PythonForce stops every sample of a
batch, raised with its sample's index.

The signal tests install Python's default SIGINT handler for their duration (a process started as a
background job inherits SIGINT ignored, and then a Ctrl-C, real or simulated, does nothing) and send the
signal only once the run has demonstrably started (from its progress callback or its force)."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import rigiddyn as rd

BODY = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
START = rd.RigidBodyState(w_B=[0.3, 1.0, 0.2], v_W=[0.2, 0.0, -0.1])
# a guard against a hang, not a speed limit: every run below takes minutes unless it is stopped
GUARD_SECONDS = 300


@pytest.fixture(autouse=True)
def sigint_raises():
    """SIGINT raises KeyboardInterrupt during the test, as at a terminal, whatever the runner's disposition."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


def seconds_to_stop(run):
    """Calls run(started) on this (the main) thread while another thread waits for the Event `started`, set by
    run once its C++ loop is running, and then sends SIGINT to this process. Returns the wall time from the
    signal to the KeyboardInterrupt out of run [s]; fails the test if run ends otherwise."""
    started, done, sent = threading.Event(), threading.Event(), []

    def send():
        while not started.wait(0.01):
            if done.is_set():
                return
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    sender = threading.Thread(target=send, daemon=True)
    sender.start()
    try:
        try:
            run(started)
        finally:
            done.set()
            sender.join()
            time.sleep(0)  # a signal sent after run returned is raised here at the latest, not after the test
    except KeyboardInterrupt:
        if not sent:
            pytest.fail("KeyboardInterrupt before the signal was sent")
        return time.monotonic() - sent[0]
    pytest.fail("the run ended without KeyboardInterrupt" + (" (signal sent)" if sent else " (run never started)"))


def set_on_first_call(started):
    """A progress callback that reports the loop is running."""
    return lambda done: started.set()


# ------------------------------------------------------------------ Ctrl-C during a run

def test_ctrl_c_stops_a_simd_batch():
    def run(started):
        rd.simulate_batch(BODY, [START] * 8, 1e-4, 10**9, record_every=10**9, threads=2, simd=True,
                          progress=set_on_first_call(started))

    seconds_to_stop(run)


def mutual_gravity_cluster(n):
    """n particles on a jittered grid under MutualGravity: each step evaluates n (n - 1) / 2 pairs per stage."""
    scene = rd.Scene()
    for _ in range(n):
        scene.add_body(rd.Particle(1.0))
    scene.add(rd.MutualGravity(G=1e-6, softening=0.1))
    rng = np.random.default_rng(7)
    states = [rd.ParticleState(p_W=rng.uniform(-10.0, 10.0, 3), v_W=rng.uniform(-0.01, 0.01, 3)) for _ in range(n)]
    return scene, states


def expensive_cluster():
    """A scene whose 4096 steps take at least 6 s on this machine (a loop that checked for Ctrl-C every 4096
    steps would answer that late): 300 particles under mutual gravity (~1 ms a step), more on a machine fast
    enough to run those 4096 steps sooner (the cost grows as n^2)."""
    n = 300
    scene, states = mutual_gravity_cluster(n)
    step_seconds = rd.simulate(scene, states, 1e-3, 20, record_every=20).elapsed_seconds / 20
    if 4096 * step_seconds < 6.0:
        n = int(np.ceil(n * np.sqrt(6.0 / (4096 * step_seconds))))
        scene, states = mutual_gravity_cluster(n)
    return scene, states


# The stop after a Ctrl-C of a run of expensive steps: within the 0.05 s of the Python monitor, the clock's pace
# of checks (about 0.01 s) and one step (~1 ms here, a few times that on a loaded machine), well under 1.5 s;
# checks every 4096 steps would stop the same run 4096 steps (>= 6 s) later. 1.5 s catches that and leaves 10x
# room for a loaded machine.
PROMPT_SECONDS = 1.5


@pytest.mark.parametrize("with_progress", [True, False])
def test_ctrl_c_stops_a_run_of_expensive_steps_promptly(with_progress):
    scene, states = expensive_cluster()
    compiled = rd.CompiledScene(scene, "rk4")

    def run(started):
        if with_progress:
            rd.simulate(compiled, states, 1e-3, 10**7, record_every=10**7, progress=set_on_first_call(started))
        else:  # no callback, the signal check alone: the signal comes 0.3 s into the call (the loop runs by then;
            # were it still converting arguments, the KeyboardInterrupt would come from there, as promptly)
            threading.Timer(0.3, started.set).start()
            rd.simulate(compiled, states, 1e-3, 10**7, record_every=10**7)

    assert seconds_to_stop(run) < PROMPT_SECONDS


def test_ctrl_c_stops_a_batch_of_expensive_steps_promptly():
    scene, states = expensive_cluster()

    def run(started):
        rd.simulate_batch(scene, [states] * 4, 1e-3, 10**7, record_every=10**7, threads=2,
                          progress=set_on_first_call(started))

    assert seconds_to_stop(run) < PROMPT_SECONDS


def test_ctrl_c_stops_a_batch_whose_python_force_is_slow():
    # each call of the force sleeps 2 ms: 4 samples of 2000 steps (4 calls each) on 2 threads take about 32 s;
    # the signal interrupts the sleep of the calling thread's force (a KeyboardInterrupt out of the force), and
    # the other thread's sample stops at its next check
    def slow_push(t, body, p_W, q_WB, v_W, w_B):
        slow_push.started.set()
        time.sleep(0.002)
        return np.array([0.0, 0.0, 1.0]), np.zeros(3)

    scene = rd.Scene(bodies=[rd.Particle(1.0)], elements=[rd.PythonForce(slow_push)])

    def run(started):
        slow_push.started = started
        rd.simulate_batch(scene, [[rd.ParticleState()]] * 4, 1e-3, 2000, threads=2)

    assert seconds_to_stop(run) < PROMPT_SECONDS


# ------------------------------------------------------------------ Ctrl-C while an estimate is made on its read

# Records every 2^20 steps (a multiple of 4: every record a common record of the estimate's runs at h, 2h and 4h).
RECORD_EVERY = 2**20


def steps_taking(seconds, run):
    """The steps, a multiple of RECORD_EVERY, that run(steps) (a call without an estimate) takes `seconds` for on
    this machine."""
    per_step = run(4 * RECORD_EVERY).elapsed_seconds / (4 * RECORD_EVERY)
    return RECORD_EVERY * max(4, int(seconds / per_step / RECORD_EVERY))


# The estimate's runs at 2h and 4h take 0.75x its run's time: after a run of 3.4 s, at least 2.5 s. The signal comes
# 0.3 s into the read; were the runs not checking for it, they would go on for at least 2.2 s more, beyond
# PROMPT_SECONDS.
@pytest.mark.parametrize("batch", [False, True])
def test_ctrl_c_stops_an_estimate_made_on_its_read(batch):
    def run(steps, error=True):
        if batch:
            return rd.simulate_batch(BODY, [START] * 2, 1e-4, steps, record_every=RECORD_EVERY, threads=2,
                                     error=error)
        return rd.simulate(BODY, START, 1e-4, steps, record_every=RECORD_EVERY, error=error)

    result = run(steps_taking(3.4, lambda steps: run(steps, error=False)))

    def read(started):
        threading.Timer(0.3, started.set).start()
        result.error

    assert seconds_to_stop(read) < PROMPT_SECONDS


# ------------------------------------------------------------------ a Python force's exception in a batch

def test_a_python_force_exception_stops_every_sample_and_names_its_sample():
    # the force raises on its 1000th call, whichever sample makes it; 4 samples x 5000 steps x 4 calls would make
    # 80000 calls. The other thread's sample stops at its next check (about 0.01 s of calls, a few thousand); the
    # samples not started never start.
    calls = []
    lock = threading.Lock()

    def push(t, body, p_W, q_WB, v_W, w_B):
        with lock:
            calls.append(t)
            if len(calls) == 1000:
                raise ValueError("boom")
        return np.array([0.0, 0.0, 1.0]), np.zeros(3)

    scene = rd.Scene(bodies=[rd.Particle(1.0)], elements=[rd.PythonForce(push)])
    with pytest.raises(ValueError, match=r"^sample [0-3]: boom$"):
        rd.simulate_batch(scene, [[rd.ParticleState()]] * 4, 1e-3, 5000, threads=2)
    assert len(calls) < 20000


def test_a_python_force_wrong_return_names_its_sample():
    scene = rd.Scene(bodies=[rd.Particle(1.0)],
                     elements=[rd.PythonForce(lambda t, body, p_W, q_WB, v_W, w_B: (np.ones(2), np.zeros(3)))])
    with pytest.raises(ValueError, match=r"^sample [01]: fn: returned f_W: expected"):
        rd.simulate_batch(scene, [[rd.ParticleState()]] * 2, 1e-3, 10, threads=2)


def test_a_python_exception_without_a_message_names_its_sample():
    class Stop(Exception):
        pass

    def stop(t, body, p_W, q_WB, v_W, w_B):
        raise Stop

    scene = rd.Scene(bodies=[rd.Particle(1.0)], elements=[rd.PythonForce(stop)])
    with pytest.raises(Stop, match=r"^sample 0: .*Stop$"):
        rd.simulate_batch(scene, [[rd.ParticleState()]], 1e-3, 10, threads=1)


# ------------------------------------------------------------------ Ctrl-C met while an argument is converted

class InterruptOnce:
    """A Ctrl-C that lands while Python code runs for the conversion of an argument: the first call of the
    special method `name` raises KeyboardInterrupt (as the signal handler would, there), the later ones answer
    as `answer` does."""

    def __init__(self, name, answer):
        self.raised = False
        self.name, self.answer = name, answer

    def trip(self, *args):
        if not self.raised:
            self.raised = True
            raise KeyboardInterrupt
        return self.answer(*args)


def interrupting(name, answer):
    """An object whose special method `name` raises KeyboardInterrupt once (InterruptOnce)."""
    once = InterruptOnce(name, answer)
    cls = type("Interrupting", (), {name: lambda self, *args: once.trip(*args)})
    return cls(), once


def test_a_ctrl_c_in_an_index_conversion_is_raised():
    steps, once = interrupting("__index__", lambda: 10)  # before: TypeError "steps: expected an integer"
    with pytest.raises(KeyboardInterrupt):
        rd.simulate(BODY, START, 1e-3, steps)
    assert once.raised


def test_a_ctrl_c_in_the_repr_of_a_bad_argument_is_raised():
    dt, once = interrupting("__repr__", lambda: "dt")  # before: TypeError "dt: expected ..., got ... (no repr)"
    with pytest.raises(KeyboardInterrupt):
        rd.simulate(BODY, START, dt, 10)
    assert once.raised


def test_a_ctrl_c_in_an_attribute_lookup_is_raised():
    # the check for a pint quantity asks for `magnitude`: a __getattr__ interrupted there (before: the
    # KeyboardInterrupt was cleared as a missing attribute, then TypeError "dt: expected a real number")
    def missing(attribute):
        raise AttributeError(attribute)

    dt, once = interrupting("__getattr__", missing)
    with pytest.raises(KeyboardInterrupt):
        rd.simulate_batch(BODY, [START], dt, 10)
    assert once.raised
