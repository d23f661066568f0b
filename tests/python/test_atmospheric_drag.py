"""AtmosphericDrag, an exponential atmosphere turning with its planet, against the results it exists for.

Its force and torque are checked against the numpy reference in test_scene_vs_reference.py. Here: the decay of a
circular orbit, the air's co-rotation, the torque of a centre of pressure, the work it does, and the bad input.
"""

import numpy as np
import pytest

import rigiddyn as rd

GM = 3.986004418e14  # [m^3/s^2]
R_EARTH = 6378137.0  # [m]
EPS = np.finfo(float).eps


def test_a_circular_orbit_decays_at_the_first_order_rate():
    """da/dt = -rho (C_D A / m) sqrt(GM a) on a circular orbit (Vallado §8.6.2, Curtis §12.4), the semi-major axis
    read from the energy, a = -GM / (2 E/m). The density is held constant (scale height 1e9 m) so the rate is
    constant: over 3 orbits a falls by ~30 m of 6778 km. The formula is first order in the drag (the drag
    acceleration / gravity ~ 1e-7 here), rk4 at 60 s steps resolves the energy to ~1e-12 relative: the bound
    1e-3 of the decay."""
    a0 = R_EARTH + 400e3
    rho, drag_area, mass = 3e-10, 2.2 * 4.0, 500.0
    air = rd.AtmosphericDrag(density0=rho, altitude0=400e3, scale_height=1e9, radius=R_EARTH, drag_area=drag_area)
    scene = rd.Scene([rd.Particle(mass)], elements=[rd.PointMassGravity(gm=GM), air])
    start = rd.ParticleState(p_W=(a0, 0.0, 0.0), v_W=(0.0, np.sqrt(GM / a0), 0.0))
    period = 2 * np.pi * np.sqrt(a0**3 / GM)
    result = rd.simulate(scene, [start], period / 100, steps=300, method="rk4", error=False)
    a = -GM / (2 * result.total_energy / mass)
    rate = -rho * drag_area / mass * np.sqrt(GM * a0)
    assert a[-1] - a[0] == pytest.approx(rate * result.t[-1], rel=1e-3)


def test_air_turning_with_the_body_exerts_nothing():
    """A body at rest relative to air that turns with the planet (v_W = omega x r) feels no drag at t0: its power
    record f.v_W has |f| = (1/2) rho C_D A |v_rel|^2 with |v_rel| <= 2 eps |v| (omega x r computed twice, each
    rounded), while
    the same body in still air loses (1/2) rho C_D A |v|^3."""
    omega = np.array([0.0, 0.0, 7.2921159e-5])
    p_W = np.array([R_EARTH + 300e3, 1e5, 2e5])
    v_W = np.cross(omega, p_W)
    rho, drag_area = 1e-11, 1.0

    def power_at_t0(omega_W):
        air = rd.AtmosphericDrag(density0=rho, altitude0=300e3, scale_height=1e9, radius=R_EARTH,
                                 drag_area=drag_area, omega_W=omega_W)
        result = rd.simulate(rd.Scene([rd.Particle(1.0)], elements=[air]), [rd.ParticleState(p_W=p_W, v_W=v_W)],
                             1.0, steps=1, method="rk4", error=False)
        return result.power[0, 0]

    speed = np.linalg.norm(v_W)
    rho_here = rho * np.exp(-(np.linalg.norm(p_W) - R_EARTH - 300e3) / 1e9)  # 3.7 km above the reference
    assert abs(power_at_t0(omega)) <= 0.5 * rho_here * drag_area * (2 * EPS * speed) ** 2 * speed
    assert power_at_t0((0.0, 0.0, 0.0)) == pytest.approx(-0.5 * rho_here * drag_area * speed**3, rel=1e-12)


def test_centre_of_pressure_gives_the_moment_of_the_drag():
    """A body whose centre of pressure lies 1 m behind its centre of mass along its x axis, flying along world y
    with B = W: the drag -F y_W at (-1, 0, 0) has the moment (-1, 0, 0) x (0, -F, 0) = (0, 0, F) about G, with F =
    (1/2) rho C_D A v^2 (the weathervane restoring torque). rk4 reads it at t0 (the power record): the torque's
    power is zero at w_B = 0, so the check is on the angular velocity after a step, w_z = F dt / I_zz to first
    order (the relative change of F over the step ~1e-9)."""
    rho, drag_area, v, I_zz, dt = 1e-11, 2.0, 7600.0, 50.0, 1e-3
    air = rd.AtmosphericDrag(density0=rho, altitude0=300e3, scale_height=1e9, radius=R_EARTH, drag_area=drag_area,
                             cp_B=(-1.0, 0.0, 0.0))
    body = rd.RigidBody(100.0, [40.0, 45.0, I_zz])
    start = rd.RigidBodyState(p_W=(R_EARTH + 300e3, 0.0, 0.0), v_W=(0.0, v, 0.0))
    result = rd.simulate(rd.Scene([body], elements=[air]), [start], dt, steps=1, method="rk4", error=False)
    F = 0.5 * rho * drag_area * v**2
    assert result.w_B[-1, 0] == pytest.approx([0.0, 0.0, F * dt / I_zz], rel=1e-6, abs=1e-6 * F * dt / I_zz)


@pytest.mark.parametrize("kwargs, message", [
    (dict(density0=-1.0), r"density0: expected a finite number >= 0, got -1"),
    (dict(scale_height=0.0), r"scale_height: expected a finite number > 0, got 0"),
    (dict(drag_area=float("inf")), r"drag_area: expected a finite number, got inf"),
    (dict(cp_B=(0.1, 0.0, 0.0)), r"cp_B: expected zero \(a particle is a point\)"),
])
def test_bad_input_names_the_field(kwargs, message):
    fields = dict(density0=1e-11, scale_height=5e4, radius=R_EARTH, drag_area=1.0)
    with pytest.raises(ValueError, match=message):
        rd.Scene([rd.Particle(1.0)], elements=[rd.AtmosphericDrag(**{**fields, **kwargs})]).compile("rk4")
