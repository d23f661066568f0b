"""Tables and plots in the user's units: ``units={"length": "km", "angle": "deg", "time": "h"}``.

The core records in SI, and every column of a table (rigiddyn.trajectory, rigiddyn.scene_result) carries
its SI unit in its name: ``'w_B_x [rad/s]'``. That unit is a product of powers of the symbols of
DIMENSIONS, each the SI unit of one dimension, the key a user names:

=========  ======  ==========================================================
key        SI      columns (and the parts of columns) it converts
=========  ======  ==========================================================
length     m       positions; the m of m/s, kg m/s, kg m^2/s
angle      rad     the rad of rad/s (angular velocities, wheel speeds)
time       s       t; the s of m/s, rad/s, kg m/s, kg m^2/s
mass       kg      masses; the kg of momenta
energy     J       energies and work
power      W       the elements' power
force      N       pivot reactions
=========  ======  ==========================================================

A column is converted symbol by symbol: ``'w_B_x [rad/s]'`` is angle/time, so with angle="deg" and
time="h" it becomes ``'w_B_x [deg/h]'``; ``'angular_momentum_norm [kg m^2/s]'`` follows mass, length and
time (``'[kg km^2/h]'`` with length="km", time="h"). Energy, power and force are dimensions of their own:
length="km" leaves ``'kinetic_energy [J]'`` in J (energy="kJ" converts it). A dimension not in `units`
stays SI, and the dimensionless columns (the quaternion's, quaternion_norm_error) are never converted.
A unit is any unit expression of rigiddyn.units' grammar whose names pint's registry knows ("km", "au",
"ft", "deg", "arcsec", "turn", "h", "day", "kJ", "kWh", "lb"); the column's name then holds it as
written. Angles are checked as angles: pint counts rad as a pure number, but an angle's unit must be a
multiple of rad (``"percent"`` is refused); a turn per minute is angle="turn", time="min".

Each column's values are its SI values times one factor, pint's conversion of 1 in the column's SI unit
to its new unit (computed once per column and cached; one float64 multiply per value, so a value is the
exact product to within the rounding of that multiply, 2^-53 relative, and the factor's own rounding).

Bad input is refused before anything is written: an unknown key (naming the nearest valid one), a unit
pint does not know, a unit of another dimension (naming both dimensions): a ValueError naming the bad
value; a `units` that is no mapping, or a unit that is no string: a TypeError.
"""

from __future__ import annotations

import difflib
import functools
import re
from collections.abc import Mapping
from typing import Any

import numpy as np

from .units import registry, unit

__all__ = ["DIMENSIONS", "check_units", "convert_columns", "convert_unit", "parse_units_option", "units_record"]

# dimension key -> its SI unit, as the columns' names write it
DIMENSIONS: dict[str, str] = {"length": "m", "angle": "rad", "time": "s", "mass": "kg", "energy": "J",
                              "power": "W", "force": "N"}
_DIMENSION_OF = {symbol: dimension for dimension, symbol in DIMENSIONS.items()}
_COLUMN = re.compile(r"(?P<base>.*) \[(?P<unit>[^\[\]]+)\]")  # "w_B_x [rad/s]", "work[0] UniformGravity [J]"
_POWER = re.compile(r"(?P<symbol>[A-Za-z]+)(?:\^(?P<power>-?[0-9]+))?")  # "m^2", "s"
_NAME = re.compile(r"[\w°%]+")  # a unit written without parentheses in a column's name


def check_units(units: Mapping[str, str] | None, name: str = "units") -> dict[str, str]:
    """The checked choice of output units: {dimension: unit} with each unit stripped of spaces.

    Parameters
    ----------
    units : Mapping[str, str] or None
        Dimension key (one of DIMENSIONS: "length", "angle", "time", "mass", "energy", "power",
        "force") -> unit ("km", "deg", "h", ...). None or {}: SI throughout.
    name : str, optional
        The argument's name in messages ("units"; "--units" on the command line).

    Returns
    -------
    dict of str to str
        The units chosen, in the order given ({} for SI throughout).

    Raises
    ------
    TypeError
        `units` is no mapping, or a unit is no string.
    ValueError
        An unknown dimension key (the nearest valid one named), a unit pint does not know, or a unit
        of another dimension (both dimensions named).

    See Also
    --------
    convert_columns, parse_units_option

    Examples
    --------
    >>> from rigiddyn.output_units import check_units
    >>> check_units({"length": "km", "time": " h "})
    {'length': 'km', 'time': 'h'}
    >>> check_units({"lenght": "km"})
    Traceback (most recent call last):
    ...
    ValueError: units: expected a dimension among length, angle, ..., got 'lenght' (did you mean 'length'?)
    >>> check_units({"length": "s"})
    Traceback (most recent call last):
    ...
    ValueError: units['length']: expected a unit of length (as m), got 's' (a unit of time)
    """
    if units is None:
        return {}
    if not isinstance(units, Mapping):
        raise TypeError(f"{name}: expected a mapping of dimension to unit such as {{'length': 'km', 'angle': 'deg'}}, "
                        f"got {units!r}")
    chosen: dict[str, str] = {}
    for key, text in units.items():
        if key not in DIMENSIONS:
            near = difflib.get_close_matches(key, DIMENSIONS, n=1) if isinstance(key, str) else []
            hint = (f" (did you mean {near[0]!r}?)" if near else
                    " (a compound unit follows its parts: rad/s follows angle and time)")
            raise ValueError(f"{name}: expected a dimension among {', '.join(DIMENSIONS)}, got {key!r}{hint}")
        subject = f"{name} {key}" if name.startswith("--") else f"{name}[{key!r}]"
        _checked_unit(key, text, subject)
        chosen[key] = text.strip()
    return chosen


def _checked_unit(dimension: str, text: Any, subject: str) -> Any:
    """The pint Unit of `text` if it is a unit of `dimension` (same root units as its SI unit: an angle a
    multiple of rad, never a pure number), else the error naming `subject`, `text` and its dimension."""
    if not isinstance(text, str):
        raise TypeError(f'{subject}: expected a unit as a string such as "km", got {text!r}')
    return _dimension_unit(dimension, text.strip(), subject)


@functools.lru_cache(maxsize=64)
def _dimension_unit(dimension: str, text: str, subject: str) -> Any:
    ureg = registry()
    chosen = unit(text, subject)
    root = ureg.get_root_units(chosen)[1]
    if root != ureg.get_root_units(DIMENSIONS[dimension])[1]:
        other = [d for d, si in DIMENSIONS.items() if ureg.get_root_units(si)[1] == root]
        if other:
            what = f"a unit of {other[0]}"
        else:
            what = "a pure number" if root == ureg.Unit("") else f"a unit of {chosen.dimensionality}"
        raise ValueError(f"{subject}: expected a unit of {dimension} (as {DIMENSIONS[dimension]}), got {text!r} "
                         f"({what})")
    return chosen


def _powers(si_unit: str) -> list[tuple[str, int]]:
    """[(SI symbol, power)] of a column's unit ("kg m^2/s" -> kg^1 m^2 s^-1), in the order written."""
    numerator, _, denominator = si_unit.partition("/")
    out = []
    for side, sign in ((numerator, 1), (denominator, -1)):
        for token in side.split():
            match = _POWER.fullmatch(token)
            if match is None or match["symbol"] not in _DIMENSION_OF:
                raise ValueError(f"column unit: expected a product of powers of {', '.join(DIMENSIONS.values())}, "
                                 f"got {si_unit!r}")
            out.append((match["symbol"], sign * int(match["power"] or 1)))
    return out


def _written(text: str, power: int) -> str:
    """A unit to a power as a column's name writes it: "km", "km^2", "(kg*km)^2"."""
    text = text if _NAME.fullmatch(text) else f"({text})"
    return text if abs(power) == 1 else f"{text}^{abs(power)}"


@functools.lru_cache(maxsize=256)
def _converted(si_unit: str, chosen: tuple[tuple[str, str], ...]) -> tuple[float, str]:
    """(factor, unit) of a column in SI unit `si_unit` under the checked choice `chosen`."""
    units = dict(chosen)
    powers = _powers(si_unit)
    if not any(_DIMENSION_OF[symbol] in units for symbol, _ in powers):
        return 1.0, si_unit
    ureg = registry()
    source, target = ureg.Unit(""), ureg.Unit("")
    up: list[str] = []
    down: list[str] = []
    for symbol, power in powers:
        text = units.get(_DIMENSION_OF[symbol], symbol)
        source = source * ureg.Unit(symbol) ** power
        target = target * unit(text, "units") ** power  # checked: read by rigiddyn.units' grammar
        (up if power > 0 else down).append(_written(text, power))
    written = " ".join(up) + ("/" + " ".join(down) if down else "")
    return float(ureg.Quantity(1.0, source).to(target).magnitude), written


def convert_unit(si_unit: str, units: Mapping[str, str] | None) -> tuple[float, str]:
    """The factor and the new unit of a quantity in the SI unit `si_unit` under the choice `units`.

    Parameters
    ----------
    si_unit : str
        A unit as the columns' names write it: powers of m, rad, s, kg, J, W, N ("m", "rad/s",
        "kg m^2/s").
    units : Mapping[str, str] or None
        As in check_units.

    Returns
    -------
    factor : float
        The value in the new unit is the SI value times this factor (pint's, 1.0 when no dimension of
        `si_unit` is chosen).
    unit : str
        The new unit as the columns' names write it (`si_unit` when no dimension of it is chosen).

    Raises
    ------
    TypeError, ValueError
        As check_units.

    See Also
    --------
    check_units, convert_columns

    Examples
    --------
    >>> from rigiddyn.output_units import convert_unit
    >>> convert_unit("kg m^2/s", {"length": "km", "time": "h"})
    (0.0036, 'kg km^2/h')
    >>> convert_unit("J", {"length": "km"})
    (1.0, 'J')
    """
    return _converted(si_unit, tuple(check_units(units).items()))


def convert_columns(table: Mapping[str, np.ndarray], units: Mapping[str, str] | None,
                    name: str = "units") -> dict[str, np.ndarray]:
    """A table's columns in the units chosen: each column with an SI unit in its name, ``'<base> [<unit>]'``,
    renamed with its new unit and multiplied by its factor (convert_unit); the others as they are.

    Parameters
    ----------
    table : Mapping[str, numpy.ndarray]
        Column name -> (n,) float64 values in SI, as rigiddyn.trajectory.columns and
        rigiddyn.scene_result.columns give them.
    units : Mapping[str, str] or None
        As in check_units (None or {}: the table unchanged).
    name : str, optional
        The argument's name in messages.

    Returns
    -------
    dict of str to numpy.ndarray
        The columns in the same order, each (n,) float64.

    Raises
    ------
    TypeError, ValueError
        As check_units.

    See Also
    --------
    check_units, rigiddyn.trajectory.columns

    Examples
    --------
    >>> import numpy as np
    >>> from rigiddyn.output_units import convert_columns
    >>> table = {"t [s]": np.array([0.0, 7200.0]), "p_W_x [m]": np.array([0.0, 1500.0]), "q_WB_w": np.ones(2)}
    >>> {k: v.tolist() for k, v in convert_columns(table, {"length": "km", "time": "h"}).items()}
    {'t [h]': [0.0, 2.0], 'p_W_x [km]': [0.0, 1.5], 'q_WB_w': [1.0, 1.0]}
    """
    chosen = tuple(check_units(units, name).items())
    if not chosen:
        return dict(table)
    out: dict[str, np.ndarray] = {}
    for column, values in table.items():
        match = _COLUMN.fullmatch(column)
        if match is None:  # dimensionless: never converted
            out[column] = values
            continue
        factor, written = _converted(match["unit"], chosen)
        out[f"{match['base']} [{written}]"] = values if written == match["unit"] else values * factor
    return out


def parse_units_option(text: str, name: str = "--units") -> dict[str, str]:
    """The command line's ``--units length=km,angle=deg,time=h`` as a checked choice of units.

    Parameters
    ----------
    text : str
        Comma-separated ``dimension=unit`` pairs, each dimension once.
    name : str, optional
        The option's name in messages.

    Returns
    -------
    dict of str to str
        As check_units.

    Raises
    ------
    ValueError
        A pair without "=", a dimension given twice, or as check_units.

    See Also
    --------
    check_units

    Examples
    --------
    >>> from rigiddyn.output_units import parse_units_option
    >>> parse_units_option("length=km, angle=deg,time=h")
    {'length': 'km', 'angle': 'deg', 'time': 'h'}
    >>> parse_units_option("length=s")
    Traceback (most recent call last):
    ...
    ValueError: --units length: expected a unit of length (as m), got 's' (a unit of time)
    """
    pairs: dict[str, str] = {}
    for pair in text.split(","):
        key, equals, value = pair.partition("=")
        key = key.strip()
        if not equals or not key:
            raise ValueError(f"{name}: expected dimension=unit pairs separated by commas such as "
                             f"length=km,angle=deg,time=h, got {pair.strip()!r}")
        if key in pairs:
            raise ValueError(f"{name}: expected each dimension once, got {key!r} twice")
        pairs[key] = value
    return check_units(pairs, name)


def units_record(units: Mapping[str, str] | None) -> dict[str, str]:
    """The unit of every dimension of a table under the choice `units`: the chosen unit, else the SI one.

    Parameters
    ----------
    units : Mapping[str, str] or None
        As in check_units.

    Returns
    -------
    dict of str to str
        Every key of DIMENSIONS, in its order, with its unit (run.json's "units").

    Raises
    ------
    TypeError, ValueError
        As check_units.

    See Also
    --------
    check_units

    Examples
    --------
    >>> from rigiddyn.output_units import units_record
    >>> units_record({"time": "h", "length": "km"})
    {'length': 'km', 'angle': 'rad', 'time': 'h', 'mass': 'kg', 'energy': 'J', 'power': 'W', 'force': 'N'}
    """
    chosen = check_units(units)
    return {dimension: chosen.get(dimension, si) for dimension, si in DIMENSIONS.items()}
