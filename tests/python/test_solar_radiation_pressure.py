"""SolarRadiationPressure, against the closed forms of the light pressure on a cannonball and a flat plate.

Its force and torque are checked against the numpy reference in test_scene_vs_reference.py. Here: a plate facing
the Sun is pushed by P A (1 + rho_s + 2 rho_d / 3), a plate lit edge-on or from behind is not, a body in the
planet's shadow is not, the Sun's direction turns at its rate, and the bad input.
"""

import numpy as np
import pytest

import rigiddyn as rd

P = 4.56e-6  # [N/m^2] the default pressure, 1 au
EPS = np.finfo(float).eps


def force_after(element, body, state, t0=0.0):
    """The force of one step of 1 s from rest on a body of mass 1 (constant over the step but for the Sun's turn): the
    change of momentum, v_W [m/s] times 1 kg."""
    result = rd.simulate(rd.Scene([body], elements=[element]), [state], 1.0, steps=1, method="rk4", t0=t0,
                         error=False)
    return result.v_W[-1, 0]


def test_a_plate_facing_the_sun_is_pushed_by_its_reflectivities():
    """cos(theta) = 1: f = -P A [(1 - rho_s) + 2 (rho_s + rho_d / 3)] s (Montenbruck & Gill §3.4): a mirror
    (rho_s = 1) twice an absorber. A force constant over the step: rk4 exact up to rounding, 8 eps relative."""
    plate = rd.RigidBody(1.0, [1.0, 1.0, 1.0])
    facing = rd.RigidBodyState()  # B = W: the normal z_B points to the Sun along z_W
    for specular, diffuse in ((0.0, 0.0), (1.0, 0.0), (0.3, 0.6)):
        srp = rd.SolarRadiationPressure(sun_W=(0.0, 0.0, 2.0), area=3.0, normal_B=(0.0, 0.0, 1.0),
                                        specular=specular, diffuse=diffuse)
        expected = -P * 3.0 * (1 + specular + 2 * diffuse / 3)
        assert force_after(srp, plate, facing) == pytest.approx([0.0, 0.0, expected], rel=8 * EPS, abs=0)


def test_a_plate_lit_from_behind_or_edge_on_feels_nothing():
    plate = rd.RigidBody(1.0, [1.0, 1.0, 1.0])
    for normal in ((0.0, 0.0, -1.0), (1.0, 0.0, 0.0)):
        srp = rd.SolarRadiationPressure(sun_W=(0.0, 0.0, 1.0), area=3.0, normal_B=normal, specular=0.5)
        assert np.array_equal(force_after(srp, plate, rd.RigidBodyState()), np.zeros(3))


def test_the_planet_shadow_switches_it_off():
    """A cannonball behind a planet of radius 1 (along -s, 0.5 off the axis) is in its shadow; 1.5 off the axis, or
    in front of the planet, it is lit."""
    srp = rd.SolarRadiationPressure(sun_W=(1.0, 0.0, 0.0), area=1.0, shadow_radius=1.0)
    ball = rd.Particle(1.0)
    assert np.array_equal(force_after(srp, ball, rd.ParticleState(p_W=(-3.0, 0.5, 0.0))), np.zeros(3))
    lit = [-P, 0.0, 0.0]
    assert force_after(srp, ball, rd.ParticleState(p_W=(-3.0, 1.5, 0.0))) == pytest.approx(lit, rel=1e-15)
    assert force_after(srp, ball, rd.ParticleState(p_W=(3.0, 0.5, 0.0))) == pytest.approx(lit, rel=1e-15)


def test_the_sun_direction_turns_at_its_rate():
    """sun_rate_W = (0, 0, w) turns s = x_W by w t about z: a step of 1 s from t0 averages the force over the turn
    by Simpson's rule (rk4 on a force of t alone), exact to (w dt)^4 / 2880 of |f|; at w = 1e-3 rad/s and
    t0 = pi / (2 w) the Sun is along y_W: the force -P y_W up to that and the turn's mean (1 - w^2/24) ~ 4e-8."""
    w = 1e-3
    srp = rd.SolarRadiationPressure(sun_W=(1.0, 0.0, 0.0), sun_rate_W=(0.0, 0.0, w), area=1.0)
    t0 = np.pi / (2 * w) - 0.5  # the step's middle at a quarter turn
    f = force_after(srp, rd.Particle(1.0), rd.ParticleState(), t0=t0)
    assert f == pytest.approx([0.0, -P, 0.0], abs=1e-7 * P)


@pytest.mark.parametrize("kwargs, message", [
    (dict(sun_W=(0.0, 0.0, 0.0)), r"sun_W: expected a non-zero direction"),
    (dict(specular=0.7, diffuse=0.5), r"diffuse: expected specular \+ diffuse <= 1"),
    (dict(area=-1.0), r"area: expected a finite number >= 0, got -1"),
    (dict(normal_B=(0.0, 0.0, 1.0)), r"normal_B: expected zero on a particle"),
])
def test_bad_input_names_the_field(kwargs, message):
    fields = dict(sun_W=(1.0, 0.0, 0.0), area=1.0)
    with pytest.raises(ValueError, match=message):
        rd.Scene([rd.Particle(1.0)], elements=[rd.SolarRadiationPressure(**{**fields, **kwargs})]).compile("rk4")
