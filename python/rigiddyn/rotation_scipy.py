"""Conversion between rigiddyn quaternions and ``scipy.spatial.transform.Rotation``.

SciPy is optional for rigiddyn: it is imported only when these functions are called. Quaternions
are (x, y, z, w) arrays, or (w, x, y, z) with ``scalar_first=True``, shape (4,) or (n, 4).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from . import _core

# | |q| - 1 | above which to_scipy rejects a quaternion (the core's unit_quaternion_tolerance)
_UNIT_TOLERANCE = 1e-6


def _rotation_class() -> Any:
    try:
        from scipy.spatial.transform import Rotation
    except ImportError as error:  # pragma: no cover - depends on the environment
        raise ImportError(
            "rigiddyn.to_scipy / rigiddyn.from_scipy need SciPy, which is not installed: "
            "pip install scipy"
        ) from error
    return Rotation


def to_scipy(q: npt.ArrayLike, scalar_first: bool = False) -> Any:
    """A ``scipy.spatial.transform.Rotation`` of unit quaternions q.

    q: (4,) or (n, 4), (x, y, z, w) or (w, x, y, z) if ``scalar_first``; unit norm within 1e-6
    (TypeError/ValueError naming ``q`` otherwise). A single q gives a single Rotation, a stack a
    stack of n rotations.
    """
    Rotation = _rotation_class()
    q_unit = _core.quat_normalize(q, scalar_first=scalar_first)  # dtype, shape, finite, non-zero
    norm = np.linalg.norm(np.asarray(q, dtype=float), axis=-1)
    if np.any(np.abs(norm - 1.0) > _UNIT_TOLERANCE):
        raise ValueError(
            f"q: expected unit quaternions (| |q| - 1 | <= {_UNIT_TOLERANCE}; normalise them first, "
            f"e.g. with quat_normalize), got |q| = {norm}"
        )
    xyzw = np.roll(q_unit, -1, axis=-1) if scalar_first else q_unit
    return Rotation.from_quat(xyzw)


def from_scipy(rotation: Any, scalar_first: bool = False, canonical: bool = False) -> npt.NDArray[np.float64]:
    """The unit quaternions of a ``scipy.spatial.transform.Rotation``.

    Returns (4,) for a single rotation, (n, 4) for a stack: (x, y, z, w), or (w, x, y, z) if
    ``scalar_first``; with ``canonical=True`` the representative with w >= 0 (SciPy's
    ``as_quat(canonical=True)``, ties as ``quat_canonical``). TypeError naming ``rotation`` for
    anything but a Rotation.
    """
    Rotation = _rotation_class()
    for name, flag in (("scalar_first", scalar_first), ("canonical", canonical)):
        if not isinstance(flag, (bool, np.bool_)):
            raise TypeError(f"{name}: expected True or False, got {type(flag).__name__} {flag!r:.60}")
    if not isinstance(rotation, Rotation):
        raise TypeError(
            f"rotation: expected a scipy.spatial.transform.Rotation, got {type(rotation).__name__}"
        )
    xyzw = np.asarray(rotation.as_quat(canonical=bool(canonical)), dtype=np.float64)
    return np.roll(xyzw, 1, axis=-1) if scalar_first else xyzw
