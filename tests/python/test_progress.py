"""One `progress` convention: tradeoff and monte_carlo take True (a bar), False (nothing) or a callable
progress(done), as simulate (steps done) and simulate_batch (samples done) call theirs."""

from __future__ import annotations

import time

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import dispersion as mc

BODY = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.1])


def test_tradeoff_calls_a_callable_with_the_steps_done_over_the_sweep():
    done: list[int] = []
    result = rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01, 0.005], horizon=1.0, progress=done.append)
    assert len(result.rows) == 2
    assert done and all(b >= a for a, b in zip(done, done[1:]))  # steps done only grow
    # every run (timed: repeated at least twice) ends with its steps reported: at least 2 x (100 + 200) steps
    assert done[-1] >= 2 * (100 + 200)


def test_tradeoff_stops_when_the_callable_raises():
    def stop(steps_done: int) -> None:
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=1.0, progress=stop)


@pytest.mark.parametrize("bad", ["yes", 1, None])
def test_tradeoff_refuses_a_progress_that_is_neither_bool_nor_callable(bad):
    with pytest.raises(TypeError, match="progress: expected True, False or a callable"):
        rd.tradeoff("t_handle", methods=["rk4"], dts=[0.01], horizon=1.0, progress=bad)


def test_monte_carlo_calls_a_callable_with_the_samples_done():
    done: list[int] = []
    run = mc.monte_carlo(BODY, STATE, 8, seed=1, dispersions={"w_B": mc.Normal(std=0.01)}, dt=0.01, steps=10,
                         threads=1, progress=done.append)
    assert len(run.batch.diverged) == 8
    assert done and all(0 <= d <= 8 for d in done)


def test_monte_carlo_with_a_bar_gives_the_same_result(capsys):
    kwargs = dict(seed=3, dispersions={"w_B": mc.Normal(std=0.01)}, dt=0.01, steps=10)
    plain = mc.monte_carlo(BODY, STATE, 4, **kwargs)
    barred = mc.monte_carlo(BODY, STATE, 4, progress=True, **kwargs)
    np.testing.assert_array_equal(plain.batch.w_B, barred.batch.w_B)  # the bar changes nothing of the run


@pytest.mark.parametrize("bad", ["yes", 1, None])
def test_monte_carlo_refuses_a_progress_that_is_neither_bool_nor_callable(bad):
    with pytest.raises(TypeError, match="progress: expected True, False or a callable"):
        mc.monte_carlo(BODY, STATE, 2, seed=1, dt=0.01, steps=2, progress=bad)


@pytest.mark.parametrize("method", ["splitting_dlm", "splitting_dlm_yoshida4", "exact_flow_kick", "rk4"])
def test_a_progress_callback_changes_no_bit_of_a_run(method):
    # a slow callback moves the calls to other steps (their pace follows the wall clock); the kick-drift-kick
    # methods merge a step's closing kick with the next one's opening kick across a call, so the run is the same
    pairs = rd.Scene()
    for mass in (1.0, 2.0, 0.5):
        pairs.add_body(rd.Particle(mass))
    pairs.add(rd.SpringDamper(body_a=0, body_b=1, stiffness=40.0, rest_length=0.8))
    pairs.add(rd.SpringDamper(body_a=1, body_b=2, stiffness=25.0, rest_length=1.2))
    states = [rd.ParticleState(p_W=(0.0, 0.1, 0.0)), rd.ParticleState(p_W=(1.0, 0.0, 0.0), v_W=(0.0, 0.3, 0.0)),
              rd.ParticleState(p_W=(2.5, 0.0, 0.0))]

    def slow(steps_done: int) -> None:
        time.sleep(0.002)

    plain = rd.simulate(pairs, states, 1e-3, 20000, method, record_every=5000, error=False)
    watched = rd.simulate(pairs, states, 1e-3, 20000, method, record_every=5000, error=False, progress=slow)
    for column in ("p_W", "v_W", "linear_momentum_W", "angular_momentum_W", "total_energy"):
        np.testing.assert_array_equal(getattr(watched, column), getattr(plain, column), err_msg=column)
