"""The case a sweep runs: one interface for a problem (one_body.ProblemCase) and a scene
(rigiddyn.scene_precision.SceneCase), and the entrance that makes one of tradeoff's `problem` argument."""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any, ClassVar, Protocol

import numpy as np

from ..problem import Problem, load_problem
from ..scene_precision import ExactReference, SceneCase, scene_case
from .checks import check_positive
from .one_body import ProblemCase
from .states import Independent


class Case(Protocol):
    """What the sweep asks of a case: its runs, states, error measures, references and defaults."""

    default_measure: ClassVar[str]
    stability_subject: ClassVar[str]  # "for this spin" / "for this scene", in the StabilityWarning

    @property
    def name(self) -> str: ...

    @property
    def horizon(self) -> float: ...  # [s]

    @property
    def tradeoff(self) -> Mapping[str, Any]: ...  # the sweep defaults of its file's [tradeoff] table

    @property
    def exact_label(self) -> str: ...  # the rows' reference when the closed form is

    @property
    def exact(self) -> ExactReference | None: ...  # the closed form, None if there is none

    def refusal(self, method: str) -> str: ...  # why `method` cannot run the case ("" if it can)

    def compile_warnings(self, method: str) -> tuple[str, ...]: ...

    def notes(self, methods: list[str]) -> list[str]: ...  # what the report says besides the rows

    def default_methods(self, info: Mapping[str, Mapping[str, Any]]) -> list[str]: ...

    def default_dts(self) -> list[float]: ...

    def exact_methods(self, info: Mapping[str, Mapping[str, Any]]) -> set[str]: ...  # no truncation error here

    def simulate(self, method: str, dt: float, steps: int, record_every: int,
                 progress: Callable[[int], None] | None = None, error: bool = False) -> Any: ...

    def states(self, result: Any) -> Any: ...

    def quaternion_norm_error(self, result: Any) -> np.ndarray: ...

    def measures(self, run: Any, ref: Any, quaternion_norm_error: np.ndarray) -> dict[str, float]: ...

    def stability(self, method: str, dt: float, steps: int) -> str | None: ...

    def independent(self, times: np.ndarray) -> Callable[[np.ndarray], Independent] | None: ...


def _problem(source: Any) -> Problem:
    """A Problem from a Problem, a problem file's path or a shipped example's name (errors name `problem`)."""
    if not isinstance(source, (Problem, str, os.PathLike)):
        raise TypeError(f"problem: expected a Problem, a Scene (with initial), a .toml path or an example name, "
                        f"got {source!r}")
    if isinstance(source, Problem):
        return source
    try:
        return load_problem(source if isinstance(source, str) else Path(source))
    except (TypeError, ValueError) as error:  # load_problem names its argument path_or_name: here it is `problem`
        text = str(error)
        if not text.startswith("path_or_name: "):
            raise
        raise type(error)("problem: " + text.removeprefix("path_or_name: ")) from None


def as_case(problem: Any, horizon: Any, initial: Any = None) -> Case:
    """The case of tradeoff's `problem` (a case already, a scene: rigiddyn.scene_precision.scene_case, or a
    problem), over `horizon` [s] (None: its own)."""
    if isinstance(problem, ProblemCase):
        return problem if horizon is None else problem.with_horizon(check_positive(horizon, "horizon"))
    scene = scene_case(problem, initial, None if horizon is None else check_positive(horizon, "horizon"))
    if isinstance(scene, SceneCase):
        return scene
    if initial is not None:
        raise TypeError(f"initial: expected None for a problem (its file gives the initial state), got {initial!r}")
    case = ProblemCase(_problem(problem))
    return case if horizon is None else case.with_horizon(check_positive(horizon, "horizon"))
