"""simulate and step as a user drives them: Ctrl-C stops a long run, a
recording larger than the memory is refused with the figures, progress is reported, step takes and
returns the time (and refuses a time-windowed load without it), and step warns on a non-finite state
as simulate does."""

import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import rigiddyn as rd

BODY = rd.RigidBody(2.0, np.diag([1.0, 2.0, 3.0]))
START = rd.RigidBodyState(w_B=[0.3, 1.0, 0.2], v_W=[0.2, 0.0, -0.1])


# ------------------------------------------------------------------ Ctrl-C
CHILD = textwrap.dedent("""
    import signal
    import sys
    import numpy as np
    import rigiddyn as rd

    # as at a terminal, whatever the test runner's own disposition of SIGINT (a shell's background
    # job ignores it, and a child inherits that)
    signal.signal(signal.SIGINT, signal.default_int_handler)

    def running(steps_done):  # simulate's progress callback: the C++ loop is running
        if not running.said:
            print("running", flush=True)
            running.said = True

    running.said = False
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    steps = 10**12  # hours at any speed; 2 records
    if not {with_progress}:
        print("running", flush=True)  # just before simulate
    try:
        rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 1.0, 0.2]), 1e-9, steps, "{method}", record_every=steps,
                    progress=running if {with_progress} else None)
    except KeyboardInterrupt:
        print("KeyboardInterrupt", flush=True)
        sys.exit(3)
    print("finished", flush=True)
""")
# a guard against a hang, not a speed limit: each run takes hours, so any exit before this proves
# that the interrupt was honoured
GUARD_SECONDS = 120


@pytest.mark.parametrize("method, with_progress", [("rk4", True), ("rk4", False), ("splitting_dlm", False)])
def test_ctrl_c_stops_a_long_simulate_with_keyboard_interrupt(method, with_progress):
    """SIGINT to a process inside a run of 1e12 steps: it must exit with KeyboardInterrupt (before, the
    C++ loop ran on with the GIL released and the signal waited for its end, hours later)."""
    import select
    import time

    code = CHILD.format(method=method, with_progress=with_progress)
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=os.environ.copy())
    try:
        ready, _, _ = select.select([child.stdout], [], [], GUARD_SECONDS)
        assert ready and child.stdout.readline().strip() == "running"
        if not with_progress:  # printed just before simulate: let it enter the C++ loop
            time.sleep(0.5)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=GUARD_SECONDS)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 3 and out.strip() == "KeyboardInterrupt", (child.returncode, out, err)


def test_progress_is_reported_and_its_exception_stops_the_run():
    seen = []

    def progress(steps_done):
        seen.append(steps_done)
        if len(seen) == 3:
            raise ValueError("enough")

    steps = 10**11  # would take hours
    with pytest.raises(ValueError, match="^enough$"):
        rd.simulate(BODY, START, 1e-9, steps, "rk4", record_every=steps, progress=progress)
    assert len(seen) == 3 and seen == sorted(seen) and all(0 < n < steps for n in seen)
    with pytest.raises(TypeError, match="^progress: expected a callable"):
        rd.simulate(BODY, START, 1e-3, 10, progress=5)


# ------------------------------------------------------------------ memory
def test_a_recording_larger_than_the_memory_is_refused_with_the_figures():
    steps = 10**15  # (1e15 + 2) records of a one-body scene's 36 doubles: 288 PB, more than any machine has
    with pytest.raises(ValueError, match=r"^record_every: expected a recording that fits in the memory available "
                                         r"\([0-9.e+]+ [kMGT]?B\), got record_every=1 for steps=1000000000000000, "
                                         r"which would need 288 PB"):
        rd.simulate(BODY, START, 1e-3, steps)


# ------------------------------------------------------------------ step and time
WINDOWED = [rd.AppliedLoad(force=[0.1, -0.3, 0.2], torque=[0.3, -0.2, 0.4], frame="body", t_start=0.1234, t_end=0.5)]


def test_step_takes_and_returns_the_time():
    state, t = rd.step(BODY, START, 0.01, "rkmk4", loads=WINDOWED, t=0.12)
    assert isinstance(state, rd.RigidBodyState) and t == 0.12 + 0.01
    # without windows the time does not matter and the state comes alone
    alone = rd.step(BODY, START, 0.01, "rkmk4", loads=rd.AppliedLoad(torque=[0.0, 0.0, 1.0]))
    assert isinstance(alone, rd.RigidBodyState)
    with pytest.raises(ValueError, match="^t: expected the time"):
        rd.step(BODY, START, 0.01, "rkmk4", loads=WINDOWED)  # before, this silently never switched the load on
    with pytest.raises(TypeError, match="^t: expected"):
        rd.step(BODY, START, 0.01, "rkmk4", loads=WINDOWED, t="0.1")


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order methods on purpose: step against simulate
@pytest.mark.parametrize("method", [m["name"] for m in rd.methods() if m["order"] > 0])
def test_steps_from_t0_follow_simulate_across_switch_times(method):
    """step after step, each from the time the previous returned, splits its steps at the switch times as
    simulate does: the same states up to step's normalisation of q and the rounding of t (t + dt
    against simulate's t0 + i dt moves a sub-step's ends by an ulp): 1e-13 over 60 steps at |w| ~ 1."""
    run = rd.simulate(BODY, START, 0.01, 60, method, loads=WINDOWED, gravity=True)
    state, t = START, 0.0
    for i in range(60):
        state, t = rd.step(BODY, state, 0.01, method, loads=WINDOWED, gravity=True, t=t)
    assert t == pytest.approx(0.6, abs=1e-14)
    for name in ("p_W", "q_WB", "v_W", "w_B"):
        np.testing.assert_allclose(getattr(state, name), getattr(run.body(0), name)[-1], rtol=0, atol=1e-13,
                                   err_msg=name)


def test_step_warns_on_a_non_finite_state_as_simulate_does():
    """Explicit Euler, I = diag(1, 2, 3), w0 = (0.1, 50, 0.1), dt = 0.05: the spin about the intermediate
    axis blows up to inf within 20 steps."""
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 3.0]))
    start = rd.RigidBodyState(w_B=[0.1, 50.0, 0.1])
    with pytest.warns(RuntimeWarning, match=r"^simulate: the state became non-finite by t = "):
        run = rd.simulate(body, start, 0.05, 20, "explicit_euler")
    assert run.diverged
    state, t = start, 0.0
    with pytest.warns(RuntimeWarning, match=r"^step: the state became non-finite in the step of dt = 0.05[0-9]* "
                                            r"from t = 0.9[0-9]* \(method 'explicit_euler'\)"):
        for _ in range(20):
            state, t = rd.step(body, state, 0.05, "explicit_euler", t=t)
            if not np.all(np.isfinite(state.w_B)) or not np.all(np.isfinite(state.q_WB)):
                break
    assert not (np.all(np.isfinite(state.w_B)) and np.all(np.isfinite(state.q_WB)))
    assert t == pytest.approx(run.t[-1])  # the 20th step, as simulate found
    # without t, the message gives the step only
    last = start
    for _ in range(19):
        last = rd.step(body, last, 0.05, "explicit_euler")
    with pytest.warns(RuntimeWarning, match=r"^step: the state became non-finite in the step of dt = 0.05[0-9]* "
                                            r"\(method 'explicit_euler'\)$"):
        rd.step(body, last, 0.05, "explicit_euler")
    # and a non-finite state is not taken back in
    with pytest.raises(ValueError, match="^state"):
        rd.step(body, state, 0.05, "explicit_euler")
