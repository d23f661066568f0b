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
    """A ``scipy.spatial.transform.Rotation`` of unit quaternions.

    The rotation ``Rotation.from_quat`` makes of q (in SciPy's (x, y, z, w) order), after checking
    that q is a unit quaternion as every rigiddyn function does. SciPy is imported only here.

    Parameters
    ----------
    q : array_like, shape (4,) or (n, 4)
        Unit quaternions (x, y, z, w), or (w, x, y, z) if `scalar_first`; norm within 1e-6 of 1.
    scalar_first : bool, default False
        Read q scalar first, (w, x, y, z), as MuJoCo does.

    Returns
    -------
    scipy.spatial.transform.Rotation
        A single rotation for q of shape (4,), a stack of n rotations for (n, 4).

    Raises
    ------
    ValueError
        A quaternion with a non-finite entry, q = 0, a norm farther than 1e-6 from 1, or a shape
        other than (4,) or (n, 4) (the message names `q`).
    TypeError
        `q` not an array of real numbers, or `scalar_first` not a bool.
    ImportError
        SciPy is not installed.

    See Also
    --------
    from_scipy, quat_normalize

    Examples
    --------
    >>> r = rd.to_scipy(rd.rotvec_to_quat([0.0, 0.0, np.pi / 2]))
    >>> r.apply([1.0, 0.0, 0.0]).round(12)
    array([0., 1., 0.])
    >>> rd.to_scipy([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]], scalar_first=True).as_rotvec().round(12)
    array([[0.        , 0.        , 0.        ],
           [3.14159265, 0.        , 0.        ]])
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

    SciPy's ``rotation.as_quat(canonical=canonical)``, in rigiddyn's order. SciPy is imported only
    here.

    Parameters
    ----------
    rotation : scipy.spatial.transform.Rotation
        A single rotation or a stack of n rotations.
    scalar_first : bool, default False
        Return quaternions scalar first, (w, x, y, z), as MuJoCo does.
    canonical : bool, default False
        Return the representative with w >= 0 (SciPy's ``as_quat(canonical=True)``; ties as
        `quat_canonical`).

    Returns
    -------
    ndarray, shape (4,) or (n, 4)
        Unit quaternions, (x, y, z, w) or (w, x, y, z) if `scalar_first`: (4,) for a single
        rotation, (n, 4) for a stack.

    Raises
    ------
    TypeError
        `rotation` not a Rotation (the message names `rotation`), or `scalar_first` or `canonical`
        not a bool.
    ImportError
        SciPy is not installed.

    See Also
    --------
    to_scipy, quat_canonical

    Examples
    --------
    >>> from scipy.spatial.transform import Rotation
    >>> rd.from_scipy(Rotation.from_rotvec([0.0, 0.0, np.pi]), scalar_first=True).round(12)
    array([0., 0., 0., 1.])
    >>> q = rd.random_rotations(3, rng=0)
    >>> np.array_equal(rd.from_scipy(rd.to_scipy(q)), q)
    True
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
