"""Quantities with units, read once at the edge (scene files, the Python API) and handed on in SI.

A value is either a plain number, read as SI in the unit the field expects (kg, m, s, rad, N, ...), a
string "<number> <unit>" ("2 slug", "3 ft", "30 deg", "1500 rpm", "398600.4418 km^3/s^2"), or a pint
Quantity (the Python API). A vector is a list of such values (each may carry its own unit) or a table
``{value = [x, y, z], unit = "km"}``.

A unit string is a number then its unit, nothing else, read by this module's own grammar before pint
sees any of it (so that no text can run code or take unbounded time):

- the number as TOML writes one: an optional sign, digits with a decimal point (never a comma:
  "1,5 kg" is refused), an optional exponent ("1e3", "-.5", "6.6743e-11"), digits grouped by
  underscores between digits ("1_000"); or inf / nan (then refused as not finite);
- then, after optional spaces, the unit: names of pint's registry ("kg", "ft", "rpm", "°", "µm")
  joined by "*", "/" or a space (a product: "kg m"), each name or parenthesised group ("(m/s)^2")
  raised, if at all, by "^" or "**" to a literal integer or decimal exponent ("s^-2", "Hz^0.5",
  "s**(-1)"), with "1" for a unit of its own ("1/s"). Parentheses nest at most
  MAX_UNIT_NESTING deep, every unit's total power is at most MAX_UNIT_POWER in size, and the whole
  string is at most MAX_UNIT_TEXT characters;
- nothing else: no comment ("3 kg # mass": the comment goes after the closing quote of the TOML
  string), no second number, no operator after the number ("2**10 kg").

Only single unit names reach pint (its registry looks each one up); the number is read by Python's
float (one beyond the float range is refused, never rounded to inf), and the powers are combined here.
The factor from each unit to the SI unit asked for is pint's, computed once per process and cached, so
that a file of many numbers with units reads in about 10 us a number.

Errors are ValueErrors naming the field, the value and the unit expected:
``body[2].inertia: expected kg m^2, got '3 kg m' ([mass] * [length])``. pint is imported, and its
unit registry built (about 0.2 s), only when the first unit string is read; then once per process.

Angles are dimensionless in pint (1 rad = 1), so an angle expected in rad accepts "30 deg" and an
angular rate in rad/s accepts "1500 rpm" (1 rpm = 2 pi rad / 60 s) and "90 deg/s"; a frequency in Hz
is read as rad/s with factor 1 (pint's rule), so write rev/s or rpm for turns per second.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Mapping, Sequence
from typing import Any, NoReturn

import numpy as np

__all__ = ["is_quantity", "quantity", "registry", "to_si", "unit", "vector_quantity"]

MAX_UNIT_TEXT = 100  # characters of a unit string
MAX_UNIT_NESTING = 4  # parentheses within parentheses of a unit
MAX_UNIT_POWER = 99  # |total power| of each unit name (km^3 has 3; ((km^3)^2)^2 has 12)

_DIGITS = r"[0-9]+(?:_[0-9]+)*"  # TOML's digits: underscores only between digits
_NUMBER = re.compile(rf"\s*(?P<number>[+-]?(?:(?:{_DIGITS}(?:\.(?:{_DIGITS})?)?|\.{_DIGITS})(?:[eE][+-]?{_DIGITS})?"
                     r"|(?:inf|nan)(?![\w°])))", re.IGNORECASE)  # "3", "-.5", "1_000", "6.6743e-11", "inf"
_UNIT_NAME = re.compile(r"(?:[^\W\d_]|°)(?:\w|°)*|%")  # "kg", "µm", "degC", "°", "%": a letter (or °, %) first
_EXPONENT = re.compile(r"[+-]?[0-9]+(?:\.[0-9]+)?|\(\s*[+-]?[0-9]+(?:\.[0-9]+)?\s*\)")  # "-2", "0.5", "(-1)"
_HINTS = {",": "a decimal comma? write a point, 1.5", "#": "a comment goes after the closing quote",
          "_": "an underscore only between digits, 1_000"}


@functools.lru_cache(maxsize=1)
def registry() -> Any:
    """The process's one pint UnitRegistry (built on first use; pint imported then)."""
    try:
        import pint
    except ImportError:  # pragma: no cover - pint is a dependency of the package
        raise ImportError("values with units need pint (pip install pint)") from None
    return pint.UnitRegistry()


def is_quantity(value: Any) -> bool:
    """True for a pint Quantity (of any registry): it has a magnitude, units and a dimensionality."""
    return all(hasattr(value, a) for a in ("magnitude", "units", "dimensionality", "to"))


def to_si(value: Any, unit: str, name: str) -> Any:
    """An argument of the Python API in the SI unit `unit` (a pint expression such as "kg*m^2"): a pint
    Quantity of any registry, holding a number or an array (one unit for the whole array), becomes its
    magnitude in `unit` (a float or an ndarray); a list or tuple has each quantity among its items (at
    any depth) converted, item i named name[i]; anything else is returned unchanged (the bindings then
    check it as they check a plain SI number). ValueError "<name>: expected <unit>, got <value>" for a
    quantity of another dimension. The bindings call this only when the argument holds a quantity,
    so pint is imported only then."""
    _check_si_unit(unit)
    if isinstance(value, (list, tuple)):
        return [to_si(v, unit, f"{name}[{i}]") for i, v in enumerate(value)]
    if not is_quantity(value):
        return value
    _check_si_unit(unit, known=True)
    import pint

    try:
        magnitude = value.to(unit).magnitude
    except pint.DimensionalityError:
        raise ValueError(f"{name}: expected {_spoken(unit)}, got {value}") from None
    return np.asarray(magnitude) if np.ndim(magnitude) else magnitude


def _fail(name: str, unit: str, got: Any, why: str = "") -> ValueError:
    return ValueError(f"{name}: expected {_spoken(unit)}, got {_shown(got)}" + (f" ({why})" if why else ""))


def _shown(value: Any) -> str:
    """repr(value) for a message, cut to its first 160 characters when longer than 200."""
    text = repr(value)
    return text if len(text) <= 200 else f"{text[:160]}... ({len(text)} characters)"


def _spoken(unit: str) -> str:
    """The SI unit as messages write it: "kg m^2" for "kg*m^2", "1" for a pure number."""
    return "a pure number" if unit == "1" else unit.replace("*", " ")


@functools.lru_cache(maxsize=64)
def _si_unit_checked(unit: str, known: bool) -> None:
    """ValueError naming `unit` unless it is a unit expression of this module's grammar ("kg*m^2", "1") and,
    if `known`, made of names the registry knows (which imports pint)."""
    try:
        powers = _read(f"1 {unit}")[1]
        if known:
            _unit_of(powers)
    except _Refused as e:
        raise ValueError(f"unit: expected an SI unit expression such as \"kg*m^2\", got {unit!r} ({e})") from None


def _check_si_unit(unit: Any, known: bool = False) -> None:
    """TypeError or ValueError naming `unit` unless it is a unit expression string (the target of a conversion);
    its names are looked up in the registry only when `known` (where a conversion imports pint anyway)."""
    if not isinstance(unit, str):
        raise TypeError(f"unit: expected an SI unit expression as a string such as \"kg*m^2\", got {_shown(unit)}")
    _si_unit_checked(unit, known)


def quantity(value: Any, name: str, unit: str, positive: bool = False, nonnegative: bool = False) -> float:
    """The value of `value` in the SI unit `unit` (a pint expression such as "kg*m^2", "rad/s", "1")
    as a finite float: a plain number is taken to be in `unit` already, a string "<number> <unit>"
    or a pint Quantity is converted. ValueError naming `name` for a wrong type, an unknown unit, a
    unit of another dimension, a non-finite value, or (if asked) a value <= 0 or < 0."""
    _check_si_unit(unit)
    if isinstance(value, bool):
        raise _fail(name, unit, value, "a boolean is no number")
    if isinstance(value, (int, float, np.integer, np.floating)):
        try:
            x = float(value)
        except OverflowError:  # a Python int beyond 1.8e308
            raise _fail(name, unit, value, "beyond the float range") from None
    elif isinstance(value, str) or is_quantity(value):
        x = _convert(value, name, unit)
    else:
        raise _fail(name, unit, value, "a number in SI or a string with a unit such as \"3 ft\"")
    if not math.isfinite(x):
        raise _fail(name, unit, value, "not finite")
    if positive and not x > 0.0:
        raise _fail(name, f"{_spoken(unit)} > 0", value)
    if nonnegative and not x >= 0.0:
        raise _fail(name, f"{_spoken(unit)} >= 0", value)
    return x


def _convert(value: Any, name: str, unit: str) -> float:
    """A unit string (read by the grammar of the module docstring) or a pint Quantity (by its own registry)
    converted to `unit`."""
    _check_si_unit(unit, known=True)
    import pint

    if not isinstance(value, str):
        return _convert_quantity(value, value, name, unit)
    try:
        magnitude, powers = _read(value)
        factor = _factor(tuple(powers.items()), unit)
        if factor is None:  # an offset unit: pint's conversion of the quantity
            return _convert_quantity(registry().Quantity(magnitude, _unit_of(powers)), value, name, unit)
    except _Refused as e:
        raise _fail(name, unit, value, str(e)) from None
    except pint.DimensionalityError:
        raise _fail(name, unit, value, str(_unit_of(powers).dimensionality)) from None
    except OverflowError:  # the factor itself (a power of a large unit)
        raise _fail(name, unit, value, f"beyond the float range in {_spoken(unit)}") from None
    except pint.PintError as e:  # an offset unit (degC) raised to a power, ...
        raise _fail(name, unit, value, f"no quantity: {e}") from None
    return _finite_in(magnitude * factor, magnitude, name, unit, value)


def _convert_quantity(q: Any, value: Any, name: str, unit: str) -> float:
    """The pint Quantity q (given as `value`) converted to `unit` by its registry."""
    import pint

    if not isinstance(q.magnitude, (int, float, np.integer, np.floating)) or isinstance(q.magnitude, bool):
        raise _fail(name, unit, value, "a single number with a unit")
    try:
        x = float(q.to(unit).magnitude)
    except pint.DimensionalityError:
        raise _fail(name, unit, value, str(q.dimensionality)) from None
    except OverflowError:
        x = math.inf
    except pint.PintError as e:  # an offset unit (degC) in a product, ...
        raise _fail(name, unit, value, f"no quantity: {e}") from None
    return _finite_in(x, q.magnitude, name, unit, value)


def _finite_in(x: float, magnitude: Any, name: str, unit: str, value: Any) -> float:
    """x, the value in `unit` of a quantity of `magnitude`: ValueError when a finite magnitude (an integer,
    of any size, or a finite float) converts to inf."""
    if math.isinf(x) and (isinstance(magnitude, (int, np.integer)) or math.isfinite(magnitude)):
        raise _fail(name, unit, value, f"beyond the float range in {_spoken(unit)}")
    return x


@functools.lru_cache(maxsize=256)
def _factor(powers: tuple[tuple[str, float], ...], unit: str) -> float | None:
    """The factor pint converts the unit prod(name ** power) to `unit` by, cached (pint's conversion of x is
    x * factor, so the product is pint's result bit for bit); None for an offset unit (degC), whose
    conversion is no product."""
    source = _unit_of(dict(powers))
    ureg = registry()
    if ureg.Quantity(0.0, source).to(unit).magnitude != 0.0:
        return None
    return float(ureg.Quantity(1.0, source).to(unit).magnitude)


class _Refused(Exception):
    """A unit string outside the grammar (the reason: the message's parenthesis)."""


def _read(text: str) -> tuple[float, dict[str, float]]:
    """(number, {unit name: total power}) of a unit string "<number> <unit>" (module docstring's grammar)."""
    if len(text) > MAX_UNIT_TEXT:
        raise _Refused(f"a unit string of at most {MAX_UNIT_TEXT} characters")
    match = _NUMBER.match(text)
    if not match:
        raise _Refused('a number then its unit, such as "3 ft"')
    number = match.group("number")
    magnitude = float(number)
    if not math.isfinite(magnitude) and number.lstrip("+-").lower() not in ("inf", "nan"):
        raise _Refused("beyond the float range")
    return magnitude, _read_unit(text, match.end(), 'a number then its unit, such as "3 ft"')


def _read_unit(text: str, pos: int, rule: str) -> dict[str, float]:
    """{unit name: total power} of the unit that fills `text` from character `pos` on (module docstring's
    grammar); `rule` says in messages what the text should be."""
    reader = _UnitReader(text, pos, rule)
    powers = reader.product(depth=0)
    if reader.pos < len(text):  # a ')' without its '('
        reader.refuse()
    for unit_name, power in powers.items():
        if not abs(power) <= MAX_UNIT_POWER:
            raise _Refused(f"{unit_name} to the power {power:g}: a power of at most {MAX_UNIT_POWER} in size")
    return powers


def unit(text: Any, name: str) -> Any:
    """The pint Unit of a unit expression alone, without a number, read by the grammar of the module docstring
    (each name looked up alone in the registry, which imports pint).

    Parameters
    ----------
    text : str
        A unit: "km", "deg", "kg*km^2/h", "kg km^2 / h" (at most MAX_UNIT_TEXT characters).
    name : str
        What the text is, for messages (``units['length']``).

    Returns
    -------
    pint.Unit
        Of the registry of `registry()`.

    Raises
    ------
    TypeError
        `text` is no string.
    ValueError
        "<name>: expected a unit such as "km", got <text> (<why>)": text outside the grammar (a number, an
        operator, unbalanced parentheses, nothing) or a name the registry does not know.

    See Also
    --------
    quantity, registry

    Examples
    --------
    >>> from rigiddyn.units import unit
    >>> unit("kg km^2 / h", "u")
    <Unit('kilogram * kilometer ** 2 / hour')>
    >>> unit("km; import os", "units['length']")
    Traceback (most recent call last):
    ...
    ValueError: units['length']: expected a unit such as "km", got 'km; import os' (';' at character 3: ...)
    """
    if not isinstance(text, str):
        raise TypeError(f'{name}: expected a unit as a string such as "km", got {_shown(text)}')
    try:
        if not text.strip():
            raise _Refused("no unit")
        if len(text) > MAX_UNIT_TEXT:
            raise _Refused(f"a unit of at most {MAX_UNIT_TEXT} characters")
        return _unit_of(_read_unit(text, 0, 'a unit such as "km" or "deg/s"'))
    except _Refused as e:
        raise ValueError(f'{name}: expected a unit such as "km", got {_shown(text)} ({e})') from None


class _UnitReader:
    """Recursive descent over the unit of a unit string from character `pos` on, giving {name: power}:

        product := factor (("*" | "/" | spaces) factor)*
        factor  := (name | "1" | "(" product ")") [("^" | "**") exponent]
        exponent := a literal number, optionally signed and in parentheses ("-2", "0.5", "(-1)")
    """

    def __init__(self, text: str, pos: int, rule: str):
        self.text, self.pos, self.rule = text, pos, rule  # rule: what the text should be, for messages

    def refuse(self) -> NoReturn:
        rule = self.rule
        if self.pos == len(self.text):
            raise _Refused(f"a unit or an exponent missing at the end: {rule}")
        char = self.text[self.pos]
        raise _Refused(f"{char!r} at character {self.pos + 1}: {_HINTS.get(char, rule)}")

    def _spaces(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos].isspace():
            self.pos += 1

    def _at(self, token: str) -> bool:
        return self.text.startswith(token, self.pos)

    def product(self, depth: int) -> dict[str, float]:
        powers: dict[str, float] = {}
        sign = 1.0
        while True:
            for unit_name, power in self.factor(depth).items():
                powers[unit_name] = powers.get(unit_name, 0.0) + sign * power
            self._spaces()
            if self.pos == len(self.text) or self._at(")"):
                return powers
            sign = -1.0 if self._at("/") else 1.0
            if self._at("*") or self._at("/"):
                self.pos += 1

    def factor(self, depth: int) -> dict[str, float]:
        self._spaces()
        name = _UNIT_NAME.match(self.text, self.pos)
        if self._at("("):
            if depth == MAX_UNIT_NESTING:
                raise _Refused(f"parentheses nested at most {MAX_UNIT_NESTING} deep")
            self.pos += 1
            powers = self.product(depth + 1)
            if not self._at(")"):
                self.refuse()
            self.pos += 1
        elif self._at("1") and not self.text[self.pos + 1:self.pos + 2].isdigit():
            self.pos += 1
            powers = {}  # the unit one, as in "1/s"
        elif name:
            self.pos = name.end()
            powers = {name.group(): 1.0}
        else:
            self.refuse()
        self._spaces()
        if self._at("**") or self._at("^"):
            self.pos += 2 if self._at("**") else 1
            self._spaces()
            exponent = _EXPONENT.match(self.text, self.pos)
            if not exponent:
                self.refuse()
            self.pos = exponent.end()
            e = float(exponent.group().strip("() \t"))
            powers = {k: v * e for k, v in powers.items()}
        return powers


def _unit_of(powers: Mapping[str, float]) -> Any:
    """The pint Unit prod(name ** power): each name looked up alone in the registry (never an expression),
    an integral power as an int."""
    import pint

    ureg = registry()
    unit = ureg.Unit("")
    for unit_name, power in powers.items():
        try:
            named = ureg.Unit(unit_name)
        except (pint.UndefinedUnitError, ValueError):  # ValueError: a name pint reads as a number ("nan")
            raise _Refused(f"unknown unit {unit_name!r}") from None
        unit = unit * named ** (int(power) if power.is_integer() else power)
    return unit


def vector_quantity(value: Any, name: str, unit: str, n: int = 3) -> np.ndarray:
    """An (n,) float64 array in the SI unit `unit` from a list of n values (numbers in SI, unit
    strings, quantities), a table {value = [..], unit = ".."}, or a pint Quantity holding an array.
    Elements are named name[i] in errors."""
    _check_si_unit(unit)
    if isinstance(value, Mapping):
        unknown = sorted(set(value) - {"value", "unit"})
        if unknown:
            raise ValueError(f"{name}.{unknown[0]}: expected a key of {{value = [..], unit = \"..\"}}, "
                             "got an unknown key")
        if "value" not in value or "unit" not in value:
            missing = "value" if "value" not in value else "unit"
            raise ValueError(f"{name}.{missing}: expected a value ({name} = {{value = [x, y, z], unit = \"km\"}}), "
                             "got nothing")
        _check_unit(value["unit"], f"{name}.unit", unit)
        items = _items(value["value"], f"{name}.value", n)
        return np.array([quantity(_with_unit(v, value["unit"], f"{name}.value[{i}]"), f"{name}.value[{i}]", unit)
                         for i, v in enumerate(items)])
    if is_quantity(value) and np.ndim(value.magnitude) == 1:
        magnitudes = _items(list(np.asarray(value.magnitude)), name, n)
        return np.array([quantity(m * value.units, f"{name}[{i}]", unit) for i, m in enumerate(magnitudes)])
    items = _items(value, name, n)
    return np.array([quantity(v, f"{name}[{i}]", unit) for i, v in enumerate(items)])


def _check_unit(text: Any, name: str, unit: str) -> None:
    """ValueError naming `name` unless `text` is a unit string of the dimension of `unit`."""
    if not isinstance(text, str):
        raise _fail(name, f"a unit of {_spoken(unit)} as a string", text)
    try:
        quantity(f"1 {text}", name, unit)
    except ValueError as e:
        raise ValueError(str(e).replace(repr(f"1 {text}"), repr(text), 1)) from None


def _items(value: Any, name: str, n: int) -> Sequence[Any]:
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, (list, tuple, np.ndarray)) \
            or len(value) != n:
        raise ValueError(f"{name}: expected an array of {n} values, got {value!r}")
    return list(value)


def _with_unit(number: Any, unit: str, name: str) -> Any:
    """A number of a {value, unit} table as a quantity of that unit (a string there is an error)."""
    if isinstance(number, bool) or not isinstance(number, (int, float)):
        raise ValueError(f"{name}: expected a number (its unit is the table's unit), got {number!r}")
    return f"{float(number)!r} {unit}"  # parsed as any unit string (its errors name the field)


def _floats(v: Any) -> Any:
    """Arrays and numbers as (nested lists of) Python floats, as a written file holds them (tomli-w)."""
    return np.asarray(v, dtype=np.float64).tolist()
