"""Quantities with units, read once at the edge (scene files, the Python API) and handed on in SI.

A value is either a plain number, read as SI in the unit the field expects (kg, m, s, rad, N, ...), a
string "<number> <unit>" parsed with pint ("2 slug", "3 ft", "30 deg", "1500 rpm",
"398600.4418 km^3/s^2"), or a pint Quantity (the Python API). A vector is a list of such values
(each may carry its own unit) or a table ``{value = [x, y, z], unit = "km"}``.

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
from typing import Any

import numpy as np

__all__ = ["is_quantity", "quantity", "registry", "to_si", "vector_quantity"]

_LEADING_NUMBER = re.compile(r"\s*[+-]?(\d|\.\d|inf|nan)", re.IGNORECASE)  # "3 ft", "-.5 m", "1e3 s"


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
    if isinstance(value, (list, tuple)):
        return [to_si(v, unit, f"{name}[{i}]") for i, v in enumerate(value)]
    if not is_quantity(value):
        return value
    import pint

    try:
        magnitude = value.to(unit).magnitude
    except pint.DimensionalityError:
        raise ValueError(f"{name}: expected {_spoken(unit)}, got {value}") from None
    return np.asarray(magnitude) if np.ndim(magnitude) else magnitude


def _fail(name: str, unit: str, got: Any, why: str = "") -> ValueError:
    return ValueError(f"{name}: expected {_spoken(unit)}, got {got!r}" + (f" ({why})" if why else ""))


def _spoken(unit: str) -> str:
    """The SI unit as messages write it: "kg m^2" for "kg*m^2", "1" for a pure number."""
    return "a pure number" if unit == "1" else unit.replace("*", " ")


def quantity(value: Any, name: str, unit: str, positive: bool = False, nonnegative: bool = False) -> float:
    """The value of `value` in the SI unit `unit` (a pint expression such as "kg*m^2", "rad/s", "1")
    as a finite float: a plain number is taken to be in `unit` already, a string "<number> <unit>"
    or a pint Quantity is converted. ValueError naming `name` for a wrong type, an unknown unit, a
    unit of another dimension, a non-finite value, or (if asked) a value <= 0 or < 0."""
    if isinstance(value, bool):
        raise _fail(name, unit, value, "a boolean is no number")
    if isinstance(value, (int, float, np.integer, np.floating)):
        x = float(value)
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
    """A unit string or a pint Quantity converted to `unit` (the quantity's own registry parses it)."""
    import pint

    if isinstance(value, str):
        if not _LEADING_NUMBER.match(value):
            raise _fail(name, unit, value, "a number then its unit, such as \"3 ft\"")
        try:
            q = registry().Quantity(value)
        except pint.UndefinedUnitError as e:
            raise _fail(name, unit, value, f"unknown unit {str(e.args[0]) if e.args else ''}".strip()) from None
        except Exception as e:  # pint's parser raises several types for text that is no quantity
            raise _fail(name, unit, value, f"no quantity: {type(e).__name__}") from None
    else:
        q = value
    if not isinstance(q.magnitude, (int, float, np.integer, np.floating)) or isinstance(q.magnitude, bool):
        raise _fail(name, unit, value, "a single number with a unit")
    try:
        return float(q.to(unit).magnitude)
    except pint.DimensionalityError:
        raise _fail(name, unit, value, str(q.dimensionality)) from None


def vector_quantity(value: Any, name: str, unit: str, n: int = 3) -> np.ndarray:
    """An (n,) float64 array in the SI unit `unit` from a list of n values (numbers in SI, unit
    strings, quantities), a table {value = [..], unit = ".."}, or a pint Quantity holding an array.
    Elements are named name[i] in errors."""
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
