"""The error measures of a work-precision sweep (`rigiddyn.tradeoff`): their names, units and meanings.

A leaf module (numpy-free, importing nothing of the package), so that a problem file's [tradeoff] table
is checked against the same names the sweep reports.
"""

from __future__ import annotations

from typing import Any

__all__ = ["MEASURES", "measure_help", "measure_unit"]

_QUANTITIES = ("state_error", "attitude_error", "momentum_error", "position_error", "velocity_error")
MEASURES = tuple(f"{w}_{q}" for q in _QUANTITIES for w in ("final", "max")) + (
    "energy_drift", "momentum_drift", "quaternion_norm_error")
# the unit of each measure's quantity ("-": dimensionless) and what it is, for headers, axes and --help
_UNITS = {"state_error": "-", "attitude_error": "rad", "momentum_error": "-", "position_error": "m",
          "velocity_error": "m/s", "energy_drift": "-", "momentum_drift": "-", "quaternion_norm_error": "-"}
_MEANINGS = {
    "state_error": "max of attitude, momentum, position / L_p, velocity / L_v (dimensionless)",
    "attitude_error": "geodesic angle between the attitude and the reference's",
    "momentum_error": "|I (w_B - w_ref)| / |I w_ref|, body angular momentum (relative)",
    "position_error": "|p_W - p_ref|, centre of mass",
    "velocity_error": "|v_W - v_ref|, centre of mass",
    "energy_drift": "max_t |T - T_ref| / max_t T_ref, kinetic energy (relative)",
    "momentum_drift": "max_t ||L| - |L_ref|| / max_t |L_ref| (relative)",
    "quaternion_norm_error": "max_t ||q| - 1|",
}


def measure_unit(measure: str) -> str:
    """The unit of one of tradeoff's error measures.

    Parameters
    ----------
    measure : str
        A name from ``MEASURES`` (``final_attitude_error``, ``max_position_error``, ``energy_drift``, ...).

    Returns
    -------
    str
        "rad", "m", "m/s" or "-" (dimensionless: a relative error).

    Raises
    ------
    TypeError, ValueError
        `measure` is not a name from ``MEASURES`` (the message lists them).

    See Also
    --------
    tradeoff : reports each run's measures; its package's docstring defines them.

    Examples
    --------
    >>> from rigiddyn.work_precision import measure_unit
    >>> measure_unit("final_attitude_error"), measure_unit("max_velocity_error"), measure_unit("energy_drift")
    ('rad', 'm/s', '-')
    """
    _check_measure(measure)
    return _UNITS[measure.removeprefix("final_").removeprefix("max_")]


def measure_help() -> list[str]:
    """One line per quantity of MEASURES: its names, unit and meaning (for --help)."""
    lines = []
    for quantity, meaning in _MEANINGS.items():
        names = [m for m in MEASURES if m.removeprefix("final_").removeprefix("max_") == quantity]
        unit = "" if _UNITS[quantity] == "-" else f" [{_UNITS[quantity]}]"
        lines.append(f"{', '.join(names)}{unit}: {meaning}")
    return lines


def _check_measure(measure: Any) -> None:
    if not isinstance(measure, str):
        raise TypeError(f"measure: expected one of {', '.join(MEASURES)}, got {measure!r}")
    if measure not in MEASURES:
        raise ValueError(f"measure: expected one of {', '.join(MEASURES)}, got {measure!r}")
