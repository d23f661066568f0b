"""The grammar of unit strings (rigiddyn.units): a number then its unit, read here before pint sees a unit
name, so that no string runs code or takes unbounded time, and every string outside the grammar is a
ValueError naming the field and the text."""

import subprocess
import sys

import pytest

from rigiddyn.scene_file import load_scene
from rigiddyn.units import MAX_UNIT_NESTING, MAX_UNIT_POWER, MAX_UNIT_TEXT, quantity, vector_quantity

# A conversion is the number times one to three factors of the unit definitions, each rounded once:
# 4 roundings of 2^-53 give at most 4.4e-16 relative; 1e-15 bounds it.
RTOL = 1e-15

# each of these, given to pint's string parser, ran code or evaluated Python arithmetic on big integers
INJECTIONS = [
    "1 __import__('os').system('true')",
    "1 m.__class__",
    "1 m.__class__.__mro__[1].__subclasses__()",
    "1 (lambda: 1)()",
    "1 f'{m}'",
    "1 eval('1')",
    "1 kg; import os",
    "1 kg\nimport os",
    "1 [m for m in ()]",
    "1 m if 1 else s",
    "1 ().__class__",
    "1 m[0]",
    "1 {m}",
    "1 m @ s",
    "1 ~m",
    "1 m % 3",
    "1 m // s",
    "1 m == m",
    "1 `m`",
    "1 \\x41",
    "2**10 kg",
    "1 kg * 2**10",
]

# integer power towers (pint evaluated them on Python integers: "2**2**30 kg" took 9 s, "9**9**9 kg" hangs)
TOWERS = ["9**9**9 kg", "1 kg**9**9**9", "2**2**30 kg", "1 kg^9^9^9", "1 ((((kg^99)^99)^99)^99)",
          "1 kg^999999999999999999", "1 kg**(9)**(9)**(9)"]


@pytest.mark.parametrize("text", INJECTIONS)
def test_no_unit_string_reaches_python_evaluation(text):
    with pytest.raises(ValueError) as e:
        quantity(text, "body[0].mass", "kg")
    assert str(e.value).startswith(f"body[0].mass: expected kg, got {text!r} (")


def test_only_single_unit_names_reach_pint(monkeypatch):
    import re

    from rigiddyn import units

    ureg = units.registry()
    looked_up = []
    real_unit = ureg.Unit

    def unit(name):
        if isinstance(name, str):  # pint itself calls it with containers of units it built
            looked_up.append(name)
        return real_unit(name)

    monkeypatch.setattr(ureg, "Unit", unit)
    monkeypatch.setattr(ureg, "parse_expression", None)  # pint's expression parser: never called
    units._factor.cache_clear()
    for text in ["6.6743e-8 cm^3/(g*s^2)", "2 kg m / s^2", "1500 rpm", "4 (ft/s)^2", "30 °", "10 %"]:
        quantity(text, "x", "m^3/(kg*s^2)" if "cm" in text else "1" if "%" in text else "rad" if "°" in text
                 else "rad/s" if "rpm" in text else "m^2/s^2" if "ft" in text else "N")
    for text in INJECTIONS + TOWERS:
        with pytest.raises(ValueError):
            quantity(text, "x", "kg")
    assert looked_up  # the valid strings did look their names up
    assert all(name == "" or re.fullmatch(r"[^\W\d_]\w*|°|%", name) for name in looked_up), looked_up


def test_towers_are_refused_in_bounded_time():
    # a subprocess with a timeout 100x what the refusals take (about 1 ms each after pint's 0.2 s import):
    # it catches a hang, never a slow machine
    code = ("from rigiddyn.units import quantity\n"
            f"for text in {TOWERS!r}:\n"
            "    try:\n"
            "        quantity(text, 'mass', 'kg')\n"
            "    except ValueError as e:\n"
            "        print(e)\n"
            "    else:\n"
            "        raise SystemExit(f'{text!r} was accepted')\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60, check=True).stdout
    lines = out.splitlines()
    assert len(lines) == len(TOWERS)
    for text, line in zip(TOWERS, lines):
        assert line.startswith(f"mass: expected kg, got {text!r} (")


@pytest.mark.parametrize("text,why", [
    ("1,5 kg", "',' at character 2: a decimal comma? write a point, 1.5"),
    ("1,000 kg", "',' at character 2: a decimal comma"),
    ("3 kg # the mass", "'#' at character 6: a comment goes after the closing quote"),
    ("3 kg#", "'#' at character 5: a comment goes after the closing quote"),
    ("1_kg", "'_' at character 2: an underscore only between digits, 1_000"),
    ("1__000 kg", "'_' at character 2: an underscore only between digits"),
    ("1 kg^", "a unit or an exponent missing at the end"),
    ("1 (m/s", "a unit or an exponent missing at the end"),
    ("1 m/s)", "')' at character 6"),
    ("1 kg 2", "'2' at character 6"),
    ("1.5.3 kg", "'.' at character 4"),
    ("kg 3", 'a number then its unit, such as "3 ft"'),
    ("", 'a number then its unit, such as "3 ft"'),
    ("2**1024 kg", "'*' at character 2"),
    ("1e400 kg", "beyond the float range"),
    ("1" * 400 + " kg", f"a unit string of at most {MAX_UNIT_TEXT} characters"),
    ("1e308 km", "beyond the float range in kg"),
    ("1 " + "(" * (MAX_UNIT_NESTING + 1) + "kg" + ")" * (MAX_UNIT_NESTING + 1),
     f"parentheses nested at most {MAX_UNIT_NESTING} deep"),
    ("1 kg^100", f"kg to the power 100: a power of at most {MAX_UNIT_POWER} in size"),
    ("1 (kg^10)^10", "kg to the power 100"),
    ("1 nan", "unknown unit 'nan'"),
    ("1 kgg", "unknown unit 'kgg'"),
])
def test_text_outside_the_grammar_is_named_with_the_reason(text, why):
    unit = "m" if text == "1e308 km" else "kg"
    with pytest.raises(ValueError) as e:
        quantity(text, "body[3].mass", unit)
    message = str(e.value)
    assert message.startswith(f"body[3].mass: expected {unit}, got ")
    assert why.replace("in kg", f"in {unit}") in message
    assert len(message) < 400  # a long text is cut in the message


@pytest.mark.parametrize("text,unit,expected", [
    ("1_000 kg", "kg", 1000.0),  # underscores between digits, as TOML numbers take them
    ("1_000.000_5 kg", "kg", 1000.0005),
    ("3ft", "m", 3 * 0.3048),
    ("1e3m", "m", 1000.0),
    ("-.5 m", "m", -0.5),
    ("+2 m", "m", 2.0),
    ("2 1/s", "1/s", 2.0),
    ("2 s^-1", "1/s", 2.0),
    ("2 s**-1", "1/s", 2.0),
    ("2 s^(-1)", "1/s", 2.0),
    ("2 s ^ 2", "s^2", 2.0),
    ("4 (ft/s)^2", "m^2/s^2", 4 * 0.3048**2),
    ("6.6743e-8 cm^3/(g*s^2)", "m^3/(kg*s^2)", 6.6743e-11),
    ("2 kg m / s^2", "N", 2.0),
    ("30 °", "rad", 3.141592653589793 / 6),
    ("5 µm", "m", 5e-6),
    ("9 Hz^0.5", "Hz^0.5", 9.0),
    ("1 km^3", "m^3", 1e9),
])
def test_the_grammar_reads_the_unit_forms(text, unit, expected):
    assert quantity(text, "x", unit) == pytest.approx(expected, rel=RTOL)


def test_a_python_number_beyond_the_float_range_is_named():
    with pytest.raises(ValueError, match=r"^mass: expected kg, got 1{160}\.\.\. \(400 characters\) "
                                         r"\(beyond the float range\)$"):
        quantity(int("1" * 400), "mass", "kg")
    with pytest.raises(ValueError, match=r"^v\[1\]: expected m/s, got 179769\d+\.\.\. \(309 characters\) "
                                         r"\(beyond the float range\)$"):
        vector_quantity([0.0, 2**1024, 0.0], "v", "m/s")


def test_a_unit_table_s_unit_is_read_by_the_same_grammar():
    with pytest.raises(ValueError, match=r"p_W\.unit: expected m, got 'km # x' \('#' at character"):
        vector_quantity({"value": [1, 2, 3], "unit": "km # x"}, "p_W", "m")
    with pytest.raises(ValueError, match=r"p_W\.unit: expected m, got 'km\*\*9\*\*9\*\*9'"):
        vector_quantity({"value": [1, 2, 3], "unit": "km**9**9**9"}, "p_W", "m")


@pytest.mark.parametrize("text,message", [
    ('mass = "1,5 kg"', r"body\[0\]\.mass: expected kg, got '1,5 kg' \(',' at character 2: a decimal comma"),
    ('mass = "9**9**9 kg"', r"body\[0\]\.mass: expected kg, got '9\*\*9\*\*9 kg'"),
    ('mass = "2 kg # two"', r"body\[0\]\.mass: expected kg, got '2 kg # two' \('#' at character 6"),
    ('mass = "2**1024 kg"', r"body\[0\]\.mass: expected kg, got '2\*\*1024 kg'"),
    (f'mass = "{"9" * 400} kg"', r"body\[0\]\.mass: expected kg, got '9{100}"),
])
def test_a_scene_file_names_the_field_of_a_bad_number(text, message):
    with pytest.raises(ValueError, match=message):
        load_scene(f'[[body]]\nkind = "particle"\n{text}\n')


def test_a_scene_file_reads_grouped_digits():
    _, initial, _ = load_scene('[[body]]\nkind = "particle"\nmass = "1_000 kg"\np_W = ["1_500 m", 0, 0]\n')
    assert initial[0].p_W[0] == 1500.0
