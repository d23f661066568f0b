"""rigiddyn: rigid-body dynamics with measured accuracy.

The compiled core (``rigiddyn._core``) is re-exported here. Conventions (SI units; quaternions as
(x, y, z, w) unless ``scalar_first=True``; spatial vectors angular part first; ``q_WB`` maps body
coordinates to world coordinates) are in ``docs/conventions.md``.
"""

from . import _core
from ._core import *  # noqa: F401,F403  (the core's names are the package's API)

__version__: str = _core.__version__
__all__ = [name for name in dir(_core) if not name.startswith("_")]
