"""rigiddyn.units: values with units read once at the edge, handed on in SI; bad units named."""

import math
import subprocess
import sys

import numpy as np
import pytest

from rigiddyn.units import is_quantity, quantity, registry, vector_quantity

# A conversion is a product of the number with one to three factors of the unit definitions, each rounded
# once (relative error <= 2^-53 each): 4 roundings give at most 4 * 1.1e-16 < 1e-15 relative.
RTOL = 1e-15

# (text, SI unit, exact SI value from the unit definitions: 1 ft = 0.3048 m, 1 lb = 0.45359237 kg,
#  g0 = 9.80665 m/s^2, 1 slug = 1 lbf s^2/ft, 1 rpm = 2 pi rad/60 s, 1 deg = pi/180 rad)
CASES = [
    ("2 slug", "kg", 2 * 0.45359237 * 9.80665 / 0.3048),
    ("3 ft", "m", 3 * 0.3048),
    ("30 deg", "rad", math.pi / 6),
    ("1500 rpm", "rad/s", 1500 * 2 * math.pi / 60),
    ("398600.4418 km^3/s^2", "m^3/s^2", 398600.4418e9),
    ("5 lbf", "N", 5 * 0.45359237 * 9.80665),
    ("2 km", "m", 2000.0),
    ("1.5 h", "s", 5400.0),
    ("3 kg*m^2", "kg*m^2", 3.0),
    ("-0.5 ft", "m", -0.5 * 0.3048),
]


@pytest.mark.parametrize("text,unit,expected", CASES)
def test_unit_strings_convert_to_si(text, unit, expected):
    assert quantity(text, "x", unit) == pytest.approx(expected, rel=RTOL)


def test_plain_numbers_are_si_and_pass_unchanged():
    for value in (0, 3, -2.5, 1e300, np.float32(0.25), np.int64(7)):
        assert quantity(value, "x", "kg*m^2") == float(value)


def test_pint_quantities_are_accepted():
    ureg = registry()
    assert quantity(ureg.Quantity(3, "ft"), "x", "m") == pytest.approx(0.9144, rel=RTOL)
    v = vector_quantity(ureg.Quantity(np.array([1.0, 2.0, 3.0]), "km"), "p_W", "m")
    np.testing.assert_array_equal(v, [1000.0, 2000.0, 3000.0])
    assert is_quantity(ureg.Quantity(1, "m")) and not is_quantity(1.0) and not is_quantity("1 m")


def test_vectors_take_a_unit_per_entry_or_one_for_the_table():
    np.testing.assert_allclose(vector_quantity(["1 km", 2, "3 ft"], "p_W", "m"), [1000.0, 2.0, 0.9144], rtol=RTOL)
    np.testing.assert_allclose(vector_quantity({"value": [0, 0, 3000], "unit": "rpm"}, "w_B", "rad/s"),
                               [0.0, 0.0, 100 * math.pi], rtol=RTOL)
    np.testing.assert_array_equal(vector_quantity([1, 2], "p_W", "m", n=2), [1.0, 2.0])


def test_the_registry_is_built_once():
    assert registry() is registry()


def test_pint_is_imported_only_when_a_unit_string_is_read():
    code = ("import sys, rigiddyn.units as u\n"
            "u.quantity(3.0, 'x', 'kg'); u.vector_quantity([1, 2, 3], 'v', 'm')\n"
            "assert 'pint' not in sys.modules, 'pint imported for plain numbers'\n"
            "u.quantity('3 ft', 'x', 'm')\n"
            "assert 'pint' in sys.modules\n")
    subprocess.run([sys.executable, "-c", code], check=True)


@pytest.mark.parametrize("value,unit,words", [
    ("3 kg m", "kg*m^2", ["body[2].inertia: expected kg m^2", "'3 kg m'", "[mass] * [length]"]),
    ("2 slugz", "kg", ["body[2].inertia: expected kg", "'2 slugz'", "unknown unit"]),
    ("3 ft", "kg", ["expected kg", "'3 ft'", "[length]"]),
    ("30 deg", "m", ["expected m", "'30 deg'", "dimensionless"]),
    ("nan m", "m", ["not finite"]),
    ("inf s", "s", ["not finite"]),
    ("ft", "m", ["a number then its unit"]),
    ("[1, 2] m", "m", ["a number then its unit"]),
    (True, "m", ["a boolean is no number"]),
    (None, "m", ["a number in SI or a string with a unit"]),
    ([1.0], "m", ["a number in SI or a string with a unit"]),
])
def test_bad_values_are_named_with_the_expected_unit(value, unit, words):
    with pytest.raises(ValueError) as e:
        quantity(value, "body[2].inertia", unit)
    for w in words:
        assert w in str(e.value)


def test_sign_checks():
    with pytest.raises(ValueError, match=r"mass: expected kg > 0, got '-1 kg'"):
        quantity("-1 kg", "mass", "kg", positive=True)
    with pytest.raises(ValueError, match=r"damping: expected N s/m >= 0, got -0.5"):
        quantity(-0.5, "damping", "N*s/m", nonnegative=True)
    assert quantity(0.0, "damping", "N*s/m", nonnegative=True) == 0.0


@pytest.mark.parametrize("value,words", [
    ({"value": [1, 2, 3], "unit": "kmz"}, ["p_W.unit: expected m", "'kmz'", "unknown unit"]),
    ({"value": [1, 2, 3], "unit": "kg"}, ["p_W.unit: expected m", "'kg'", "[mass]"]),
    ({"value": [1, 2, 3]}, ["p_W.unit: expected a value"]),
    ({"value": [1, 2, 3], "unit": "m", "units": "m"}, ["p_W.units: expected a key"]),
    ({"value": [1, "2 m", 3], "unit": "m"}, ["p_W.value[1]: expected a number"]),
    ([1, 2], ["p_W: expected an array of 3 values"]),
    ("1 m", ["p_W: expected an array of 3 values"]),
    ([1, "2 s", 3], ["p_W[1]: expected m", "'2 s'", "[time]"]),
])
def test_bad_vectors_name_the_entry(value, words):
    with pytest.raises(ValueError) as e:
        vector_quantity(value, "p_W", "m")
    for w in words:
        assert w in str(e.value)
