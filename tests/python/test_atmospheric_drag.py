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


# ---------------------------------------------------------------- the tabulated density (Vallado, Table 8-4)
def drag_power_at(air, altitude, speed=7600.0):
    """The drag's power f.v [W] at t0 on a particle `altitude` [m] up moving at `speed` [m/s] through still air:
    -(1/2) rho(altitude) C_D A speed^3, read from the run's record."""
    start = rd.ParticleState(p_W=(R_EARTH + altitude, 0.0, 0.0), v_W=(0.0, speed, 0.0))
    result = rd.simulate(rd.Scene([rd.Particle(1.0)], elements=[air]), [start], 1e-3, steps=1, method="rk4",
                         error=False)
    return float(result.power[0, 0])


def test_a_table_sampled_from_the_exponential_model_is_that_model():
    """Rows (h_i, rho0 exp(-(h_i - h0)/H)) at uneven altitudes give the exponential model's density at every
    altitude, inside the table and beyond its outermost rows (where its outermost bands' exponentials are
    extended): both are exponentials with the same value at the rows. Round-off: the rows carry eps (1 + a_i)
    each (a = |h - h0|/H, the exponential's argument), so the band's slope ln(rho_{i+1}/rho_i)/(h_{i+1} - h_i)
    carries 4 eps (1 + a) of the argument per band width, times s = |h - h_i|/(h_{i+1} - h_i) bands away;
    the model's own exp carries eps (1 + a): 16 eps (1 + a)(1 + s) with room."""
    rho0, h0, H = 3e-12, 400e3, 60e3
    exponential = rd.AtmosphericDrag(density0=rho0, altitude0=h0, scale_height=H, radius=R_EARTH, drag_area=8.8)
    h_rows = np.array([200e3, 250e3, 400e3, 410e3, 700e3, 1000e3])
    table = rd.AtmosphericDrag(table_altitude=h_rows, table_density=rho0 * np.exp(-(h_rows - h0) / H),
                               radius=R_EARTH, drag_area=8.8)
    for h in [150e3, 200e3, 230e3, 399e3, 405e3, 555.5e3, 1000e3, 1300e3]:
        i = int(np.clip(np.searchsorted(h_rows, h, side="right") - 1, 0, h_rows.size - 2))
        s = abs(h - h_rows[i]) / (h_rows[i + 1] - h_rows[i])
        a = max(abs(h - h0), abs(h_rows[i] - h0), abs(h_rows[i + 1] - h0)) / H
        want = drag_power_at(exponential, h)
        assert abs(drag_power_at(table, h) / want - 1) <= 16 * EPS * (1 + a) * (1 + s), h


def test_inside_a_band_the_density_is_log_linear():
    """Between rows (h_i, rho_i) and (h_{i+1}, rho_{i+1}) rho = rho_i (rho_{i+1}/rho_i)^s, s = (h - h_i)/(h_{i+1} -
    h_i) (an exponential of scale height H_i = (h_{i+1} - h_i)/ln(rho_i/rho_{i+1})), and the outermost bands'
    exponentials beyond the table: s < 0 below it, s > 1 above. Rows of uneven densities (one band rising).
    Round-off: the slope's log carries 2 eps (1 + L), L = |ln(rho_{i+1}/rho_i)|, times |s|, and the exp and the
    products a few eps each: 16 eps (1 + L)(1 + |s|)."""
    h_rows = np.array([100e3, 150e3, 300e3, 320e3])
    rho_rows = np.array([5e-7, 2e-9, 3e-9, 1e-11])
    table = rd.AtmosphericDrag(table_altitude=h_rows, table_density=rho_rows, radius=R_EARTH, drag_area=2.0)
    for h, i in [(120e3, 0), (100e3, 0), (150e3, 1), (200e3, 1), (319e3, 2), (80e3, 0), (400e3, 2)]:
        s = (h - h_rows[i]) / (h_rows[i + 1] - h_rows[i])
        L = abs(np.log(rho_rows[i + 1] / rho_rows[i]))
        rho = rho_rows[i] * (rho_rows[i + 1] / rho_rows[i]) ** s
        want = -0.5 * rho * 2.0 * 7600.0**3
        assert abs(drag_power_at(table, h) / want - 1) <= 16 * EPS * (1 + L) * (1 + abs(s)), h


@pytest.mark.parametrize("table, message", [
    (dict(table_altitude=[1e5], table_density=[1e-9]), r"table_altitude: expected at least 2 rows .*, got 1"),
    (dict(table_altitude=[1e5, 2e5, 2e5], table_density=[1e-9, 1e-10, 1e-11]),
     r"table_altitude\[2\]: expected an altitude \[m\] above table_altitude\[1\] = 200000 .*, got 200000"),
    (dict(table_altitude=[1e5, 2e5, 1.5e5], table_density=[1e-9, 1e-10, 1e-11]),
     r"table_altitude\[2\]: .*, got 150000"),
    (dict(table_altitude=[1e5, 2e5], table_density=[1e-9, 0.0]),
     r"table_density\[1\]: expected a finite density > 0 \[kg/m\^3\], got 0"),
    (dict(table_altitude=[1e5, 2e5], table_density=[-1.0, 1e-10]), r"table_density\[0\]: .*, got -1$"),
    (dict(table_altitude=[1e5, 2e5], table_density=[1e-9]),
     r"table_density: expected one density per altitude of table_altitude \(2\), got 1"),
    (dict(table_altitude=[1e5, float("nan")], table_density=[1e-9, 1e-10]), r"table_altitude\[1\]: .*, got nan"),
    (dict(table_altitude=[1e5, 2e5], table_density=[1e-9, 1e-10], scale_height=6e4),
     r"scale_height: expected 0 with a density table .*, got 60000"),
])
def test_a_bad_table_is_refused_naming_the_value(table, message):
    with pytest.raises(ValueError, match=message):
        rd.AtmosphericDrag(radius=R_EARTH, drag_area=1.0, **table)


def test_a_table_reads_from_a_scene_file_with_units_and_writes_back():
    """[[force]] type = "atmospheric_drag" with table_altitude and table_density (each entry may carry a unit): the
    element has the rows in SI, and the canonical file reads back to an equal element."""
    text = '''
[[body]]
name = "sat"
kind = "particle"
mass = 500
p_W = [6778137.0, 0, 0]
v_W = [0, 7670, 0]
[[force]]
type = "atmospheric_drag"
radius = "6378.137 km"
drag_area = 8.8
table_altitude = ["300 km", "400 km", 500000.0]
table_density = {value = [2.4e-11, 3.7e-12, 6.9e-13], unit = "kg/m^3"}
'''
    scene, initial, _ = rd.load_scene(text)
    air = scene.elements[0]
    assert air.table_altitude.tolist() == [300e3, 400e3, 500e3]
    assert air.table_density.tolist() == [2.4e-11, 3.7e-12, 6.9e-13]
    again, _, _ = rd.load_scene(scene.to_toml(initial))
    assert again.elements[0] == air
    with pytest.raises(ValueError, match=r"force\[0\]\.table_altitude\[0\]: expected m"):
        rd.load_scene(text.replace('"300 km"', '"300 kg"'))


def test_the_step_size_estimate_reads_a_tabulated_density():
    """rigiddyn.stability's damping rate of the air, rho C_D A |v_rel| / m, reads the table as the element does: a
    table sampled from an exponential model gives that model's rate, inside the table and above it, within the
    round-off bound of test_a_table_sampled_from_the_exponential_model_is_that_model, 16 eps (1 + a)(1 + s)."""
    from rigiddyn.stability import scene_modes

    rho0, h0, H = 3e-12, 400e3, 60e3
    h_rows = np.array([300e3, 350e3, 500e3])
    models = [rd.AtmosphericDrag(density0=rho0, altitude0=h0, scale_height=H, radius=R_EARTH, drag_area=8.8),
              rd.AtmosphericDrag(table_altitude=h_rows, table_density=rho0 * np.exp(-(h_rows - h0) / H),
                                 radius=R_EARTH, drag_area=8.8)]
    for h in (420e3, 650e3):
        start = [rd.ParticleState(p_W=(R_EARTH + h, 0.0, 0.0), v_W=(0.0, 7600.0, 0.0))]
        (_, _, exponential), (_, _, table) = (scene_modes(rd.Scene([rd.Particle(2.0)], elements=[air]), start)[0]
                                              for air in models)
        i = min(int(np.searchsorted(h_rows, h, side="right")) - 1, h_rows.size - 2)
        s = abs(h - h_rows[i]) / (h_rows[i + 1] - h_rows[i])
        a = max(abs(h - h0), abs(h_rows[i] - h0), abs(h_rows[i + 1] - h0)) / H
        assert table == pytest.approx(exponential, rel=16 * EPS * (1 + a) * (1 + s))
