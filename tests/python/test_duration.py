"""The length of a run as a time span: simulate, simulate_batch and monte_carlo take duration= [s] (a float
or a pint quantity) beside steps=, exactly one of them; a duration is a whole number of steps of dt (to 1e-9
relative, so decimal time steps work: 10 s at dt = 0.01 s is 1000 steps), else a ValueError naming duration
and dt with the two nearest durations that are. A run given by its duration is the run of that many steps,
bitwise."""

import numpy as np
import pint
import pytest

import rigiddyn as rd
from rigiddyn import dispersion as mc

ureg = pint.UnitRegistry()
BODY = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
STATE = rd.RigidBodyState(w_B=[0.1, 1.0, 0.2])
FIELDS = ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "total_energy", "work")


def _same(a, b, fields=FIELDS):
    for name in fields:
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def _scene():
    scene = rd.Scene()
    scene.add_body(BODY, name="b")
    scene.add(rd.UniformGravity())
    return scene


@pytest.mark.parametrize("dt, duration, steps", [(0.01, 10.0, 1000), (0.1, 0.3, 3), (1e-3, 2.5, 2500),
                                                 (0.25, 0.0, 0)])
def test_a_duration_is_the_run_of_its_steps_bitwise(dt, duration, steps):
    # 10 / 0.01 = 999.9999999999999 and 0.3 / 0.1 = 2.9999999999999996 in floating point: whole within 1e-9
    _same(rd.simulate(BODY, STATE, dt, duration=duration), rd.simulate(BODY, STATE, dt, steps))


def test_a_duration_may_carry_its_unit():
    _same(rd.simulate(BODY, STATE, 0.01, duration=2 * ureg.minute), rd.simulate(BODY, STATE, 0.01, 12000))
    _same(rd.simulate(BODY, STATE, 10 * ureg.ms, duration=1500 * ureg.ms), rd.simulate(BODY, STATE, 0.01, 150))


@pytest.mark.parametrize("model, initial", [
    (_scene(), [STATE]),
    (rd.PivotedBody(BODY, [0.0, 0.0, 0.5]), rd.PivotedBodyState(w_B=[0.1, 0.0, 3.0])),
    (rd.Particle(1.0), rd.ParticleState(v_W=[1.0, 0.0, 0.0])),
])
def test_every_model_takes_a_duration(model, initial):
    by_duration = rd.simulate(model, initial, 0.02, duration=1.0)
    by_steps = rd.simulate(model, initial, 0.02, 50)
    _same(by_duration, by_steps, ("t", "p_W", "v_W", "total_energy"))


def test_a_batch_takes_a_duration_at_a_common_or_a_per_sample_dt():
    states = [STATE, rd.RigidBodyState(w_B=[1.0, 0.0, 0.5])]
    _same(rd.simulate_batch(BODY, states, 0.01, duration=0.5), rd.simulate_batch(BODY, states, 0.01, 50))
    per_sample = rd.simulate_batch(BODY, states, np.array([0.01, 0.01]), duration=0.5)
    assert per_sample.t.shape == (2, 51)
    with pytest.raises(ValueError, match=r"^duration: expected the same number of steps for every sample's dt "
                                         r"\(or steps= instead\), got 50 steps of dt\[0\] = 0.01 s and 25 of "
                                         r"dt\[1\] = 0.02 s$"):
        rd.simulate_batch(BODY, states, np.array([0.01, 0.02]), duration=0.5)


def test_monte_carlo_takes_a_duration_and_checks_it_before_drawing():
    run = mc.monte_carlo(BODY, STATE, 3, seed=1, dt=0.05, duration=1.0)
    assert run.batch.t.shape == (3, 21)
    with pytest.raises(ValueError, match=r"^duration: expected a whole number of steps"):
        mc.monte_carlo(BODY, STATE, 10**6, seed=1, dt=0.3, duration=1.0)  # refused before a million draws


@pytest.mark.parametrize("kwargs, message", [
    ({}, r"^steps, duration: expected exactly one of them \(a step count, or a time span \[s\]\), got neither$"),
    ({"steps": 10, "duration": 0.1}, r"^steps, duration: expected exactly one of them .*, got both$"),
    ({"duration": 1.0, "dt": 0.3}, r"^duration: expected a whole number of steps of dt = 0.29999999999999999 s "
                                   r"\(e.g. 0.9 s or 1.2 s\), got 1 s \(3.33333333333 steps\)$"),
    ({"duration": -1.0}, r"^duration: expected a time span >= 0 \[s\], got -1$"),
    ({"duration": float("nan")}, r"^duration: "),
    ({"duration": 1e300, "dt": 1e-300}, r"^duration: expected a run of at most 2\*\*53 steps of dt = 1e-300 s, "),
    ({"duration": 1.0, "dt": -0.1}, r"^dt: expected a finite number > 0, got -0.1"),
    ({"duration": 3 * ureg.kg}, r"^duration: "),
    ({"duration": "1 s"}, r"^duration: "),
])
def test_a_bad_length_is_refused_naming_it(kwargs, message):
    dt = kwargs.pop("dt", 0.1)
    for call in (lambda: rd.simulate(BODY, STATE, dt, **kwargs),
                 lambda: rd.simulate(_scene(), [STATE], dt, **kwargs),
                 lambda: rd.simulate_batch(BODY, [STATE], dt, **kwargs),
                 lambda: mc.monte_carlo(BODY, STATE, 2, seed=1, dt=dt, **kwargs)):
        with pytest.raises((ValueError, TypeError), match=message):
            call()


def test_duration_is_a_keyword():
    with pytest.raises(TypeError):
        rd.simulate(BODY, STATE, 0.1, None, "rk4", 1, None, None, 0.0, False, None, 1.0)
