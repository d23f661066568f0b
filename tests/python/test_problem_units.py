"""Units in problem files: every number accepts a unit string, read by rigiddyn.units as a scene file's are."""

import math
import textwrap

import numpy as np
import pytest
from rigiddyn.problem import parse_problem

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

EPS = np.finfo(float).eps
# a value with a unit is its number times pint's factor to SI: two roundings, each <= eps / 2 relative
RTOL = 2 * EPS

SI = """
name = "units"
horizon = 120.0
gravity = [0.0, 0.0, -9.80665]
[body]
mass = 0.2
inertia = [1e-4, 2e-4, 2.5e-4]
[initial]
p_W = [1000.0, 0.0, 0.0]
v_W = [10.0, 0.0, 0.0]
w_B = [0.0, 157.07963267948966, 0.0]
euler = {seq = "ZYX", angles = [0.5235987755982988, 0.0, 0.0]}
[[loads]]
force = [1000.0, 0.0, 0.0]
torque = [0.0, 0.0, 0.01]
t_start = 60.0
t_end = 90.0
[tradeoff]
dts = [0.005]
"""

WITH_UNITS = """
name = "units"
horizon = "2 min"
gravity = [0.0, 0.0, "-1 g0"]
[body]
mass = "200 g"
inertia = {value = [1, 2, 2.5], unit = "kg cm^2"}
[initial]
p_W = ["1 km", 0.0, 0.0]
v_W = {value = [36, 0, 0], unit = "km/h"}
w_B = [0.0, "1500 rpm", 0.0]
euler = {seq = "ZYX", angles = ["30 deg", 0.0, 0.0]}
[[loads]]
force = ["1 kN", 0.0, 0.0]
torque = [0.0, 0.0, "1 N cm"]
t_start = "1 min"
t_end = "1.5 min"
[tradeoff]
dts = ["5 ms"]
"""


def parse(text):
    return parse_problem(tomllib.loads(textwrap.dedent(text)))


def test_every_field_with_a_unit_is_its_si_number():
    si, united = parse(SI), parse(WITH_UNITS)
    assert united.horizon == pytest.approx(si.horizon, rel=RTOL, abs=0)
    assert united.mass == pytest.approx(si.mass, rel=RTOL, abs=0)
    for key in ("gravity", "inertia_com", "p_W", "v_W", "w_B"):
        np.testing.assert_allclose(getattr(united, key), getattr(si, key), rtol=RTOL, atol=0, err_msg=key)
    # q_WB: the angle converted (2 roundings), then the core's half-angle sine and cosine (a few ulp more)
    np.testing.assert_allclose(united.q_WB, si.q_WB, rtol=0, atol=8 * EPS)
    (load,), (si_load,) = united.loads, si.loads
    np.testing.assert_allclose(load.force, si_load.force, rtol=RTOL, atol=0)
    np.testing.assert_allclose(load.torque, si_load.torque, rtol=RTOL, atol=0)
    assert (load.t_start, load.t_end) == pytest.approx((si_load.t_start, si_load.t_end), rel=RTOL, abs=0)
    assert united.tradeoff["dts"] == pytest.approx(si.tradeoff["dts"], rel=RTOL, abs=0)


@pytest.mark.parametrize("table, key, value, expected", [
    ("[body.primitive]\nshape = 'solid_sphere'", "radius", '"10 cm"', {"radius": 0.1}),
    ("[body.primitive]\nshape = 'solid_box'", "size", '["10 cm", "20 cm", "0.3 m"]', {"size": [0.1, 0.2, 0.3]}),
])
def test_primitive_sizes_and_density_with_units(table, key, value, expected):
    import rigiddyn

    p = parse(f"horizon = 1.0\n{table}\n{key} = {value}\ndensity = \"2.7 g/cm^3\"\n")
    shape = table.split("'")[1]
    reference = getattr(rigiddyn, shape)(*expected.values(), density=2700.0)
    # each length and the density: one factor each (RTOL), then the same constructor; a mass is a density
    # times a volume of 3 lengths, an inertia that mass times 2 lengths: <= 6 factors of (1 + RTOL)
    assert p.mass == pytest.approx(reference.mass, rel=6 * RTOL, abs=0)
    np.testing.assert_allclose(p.inertia_com, reference.inertia_com, rtol=6 * RTOL, atol=0)


H, BODY = "horizon = 1.0\n", "[body]\nmass = 1.0\ninertia = [1, 2, 2.5]\n"


@pytest.mark.parametrize("text, message", [
    ('horizon = "2 m"\n' + BODY, "horizon: expected s, got '2 m' ([length])"),
    (H + 'gravity = [0, 0, "9.81 N"]\n' + BODY, "gravity[2]: expected m/s^2, got '9.81 N'"),
    (H + '[body]\nmass = "3 m"\ninertia = [1, 2, 2.5]', "body.mass: expected kg, got '3 m' ([length])"),
    (H + '[body]\nmass = 1\ninertia = [1, 2, "2.5 kg m"]', "body.inertia[2]: expected kg m^2, got '2.5 kg m'"),
    (H + '[body.primitive]\nshape = "solid_sphere"\nradius = "1 s"\nmass = 1',
     "body.primitive.radius: expected m, got '1 s' ([time])"),
    (H + '[body.primitive]\nshape = "solid_sphere"\nradius = 1\ndensity = "1 kg/m^2"',
     "body.primitive.density: expected kg/m^3, got '1 kg/m^2'"),
    (H + BODY + '[initial]\np_W = ["1 s", 0, 0]', "initial.p_W[0]: expected m, got '1 s'"),
    (H + BODY + '[initial]\nv_W = {value = [1, 0, 0], unit = "m"}', "initial.v_W.unit: expected m/s, got 'm'"),
    (H + BODY + '[initial]\nw_B = [0, "3 m/s", 0]', "initial.w_B[1]: expected rad/s, got '3 m/s'"),
    (H + BODY + '[initial]\naxis_angle = {axis = [0, 0, 1], angle = "30 m"}',
     "initial.axis_angle.angle: expected rad, got '30 m'"),
    (H + BODY + '[[loads]]\nforce = ["1 kg", 0, 0]', "loads[0].force[0]: expected N, got '1 kg'"),
    (H + BODY + '[[loads]]\ntorque = [0, 0, "1 N"]', "loads[0].torque[2]: expected N m, got '1 N'"),
    (H + BODY + '[[loads]]\nt_end = "1 m"', "loads[0].t_end: expected s, got '1 m'"),
    (H + BODY + '[tradeoff]\ndts = ["1 m"]', "tradeoff.dts[0]: expected s, got '1 m'"),
])
def test_a_wrong_dimension_is_refused_by_name(text, message):
    with pytest.raises(ValueError) as e:
        parse(text)
    assert str(e.value).startswith(message), str(e.value)


def test_the_unit_reader_is_the_scene_files():
    # the same string gives the same double in a problem file and a scene file (one reader: rigiddyn.units)
    import rigiddyn

    problem = parse('horizon = 1.0\n[body]\nmass = "7.3 lb"\ninertia = [1, 2, 2.5]\n')
    scene, _, _ = rigiddyn.load_scene('[[body]]\nkind = "rigid"\nmass = "7.3 lb"\ninertia = [1, 2, 2.5]\n')
    assert problem.mass == scene.bodies[0].mass and math.isfinite(problem.mass)
