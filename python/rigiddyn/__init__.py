"""rigiddyn: rigid-body dynamics with measured accuracy.

The compiled core (``rigiddyn._core``) is re-exported here. Conventions (SI units; quaternions as
(x, y, z, w) unless ``scalar_first=True``; spatial vectors angular part first; ``q_WB`` maps body
coordinates to world coordinates) are in ``docs/conventions.md``.
"""

from . import _core
from ._core import *  # noqa: F401,F403  (the core's names are the package's API)
from .rotation_scipy import from_scipy, to_scipy
from .inertia_mesh import mesh_shell, solid_mesh  # type: ignore[assignment]  # the core's, also taking trimesh objects
from .problem import Problem, load_problem
from . import scene_describe as _scene_describe  # noqa: F401  (attaches Scene.describe, CompiledScene.describe)
from .scene_file import load_scene
from .urdf import load_urdf, urdf_joint_dampers
from .stability import StabilityWarning
from ._balance import AccuracyWarning, Balance
from .work_precision import TradeoffResult, tradeoff  # the function; its module is rigiddyn.work_precision
from . import control
from .control import Controller, SampledState
from .dispersion import DispersionWarning, monte_carlo  # the function; its module, rigiddyn.dispersion, holds the dispersions

__version__: str = _core.__version__
__all__ = [name for name in dir(_core) if not name.startswith("_")]
# a list of names of its own (mypy reads the exports of a module from `__all__ +=` of a literal list)
__all__ += ["to_scipy", "from_scipy", "Problem", "load_problem", "StabilityWarning", "TradeoffResult", "tradeoff",
            "load_scene", "load_urdf", "urdf_joint_dampers"]
__all__ += ["AccuracyWarning", "Balance"]
__all__ += ["monte_carlo", "DispersionWarning"]  # monte_carlo: the function (rigiddyn.dispersion: Normal, ...)
__all__ += ["Controller", "SampledState"]  # rigiddyn.control also holds the shipped laws BDot, PDAttitude
