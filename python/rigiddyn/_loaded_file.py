"""What every file loader returns (rigiddyn.load_scene, rigiddyn.load_problem): a SceneFile, its scene, the bodies'
initial states and the run options (RunOptions). A problem file's Problem is the SceneFile of its one rigid body."""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from . import _core


@dataclass(frozen=True)
class RunOptions:
    """A scene file's [run]: method (a name of rigiddyn.methods()), dt [s] and duration [s] (None when
    the file gives none), record_every (record every k-th step); its [tradeoff] table, the defaults
    of rigiddyn.tradeoff on the scene (methods, dts [s], tolerance, measure, horizon [s]; empty: none);
    and its [controller] table, the rigiddyn.Controller the run is made under (None: none)."""

    method: str = "rk4"
    dt: float | None = None
    duration: float | None = None
    record_every: int = 1
    tradeoff: Mapping[str, Any] = field(default_factory=dict)
    controller: Any = None

    @property
    def steps(self) -> int | None:
        """round(duration / dt) (at least 1), or None without both."""
        if self.dt is None or self.duration is None:
            return None
        return max(1, round(self.duration / self.dt))


class SceneFile:
    """A read scene or problem file: what rigiddyn.load_scene and rigiddyn.load_problem return.

    It unpacks as ``scene, initial, run``; a problem file's `Problem` is one (the scene of its one rigid body).
    Read-only; the constructor checks each argument (TypeError or ValueError naming it).

    Parameters
    ----------
    scene : Scene
        The bodies and force elements.
    initial : list of body states
        Each body's initial state, in the scene's order.
    run : RunOptions
        The file's run options: method, dt [s], duration [s], record_every, tradeoff defaults, controller.
    name : str
        The file's name (its ``name`` key, else the file's stem).
    description : str, default ""
        Free text.

    See Also
    --------
    rigiddyn.load_scene, rigiddyn.load_problem

    Examples
    --------
    >>> file = rd.load_scene("pendulum")
    >>> scene, initial, run = file
    >>> file.name, len(scene.bodies), run.method
    ('compound pendulum', 1, 'rk4')
    >>> problem = rd.load_problem("t_handle")
    >>> scene, initial, run = problem
    >>> isinstance(problem, type(file)), run.duration, initial[0].w_B
    (True, 4.0, array([ 0.1, 10. ,  0. ]))
    """

    name: str
    description: str
    _scene: Any
    _initial: list[Any]
    _run: RunOptions

    def __init__(self, scene: Any, initial: list[Any], run: RunOptions, name: str, description: str = ""):
        if not isinstance(scene, _core.Scene):
            raise TypeError(f"scene: expected a Scene, got {scene!r}")
        if isinstance(initial, (str, bytes)) or not isinstance(initial, Sequence) or len(initial) != len(scene.bodies):
            raise ValueError(f"initial: expected a list of {len(scene.bodies)} body states (one per body of the "
                             f"scene), got {initial!r}")
        if not isinstance(run, RunOptions):
            raise TypeError(f"run: expected a RunOptions, got {run!r}")
        for label, text in (("name", name), ("description", description)):
            if not isinstance(text, str):
                raise TypeError(f"{label}: expected a str, got {text!r}")
        for key, value in (("_scene", scene), ("_initial", initial), ("_run", run), ("name", name),
                           ("description", description)):
            object.__setattr__(self, key, value)

    @property
    def scene(self) -> Any:
        """The bodies and force elements (a Scene)."""
        return self._scene

    @property
    def initial(self) -> list[Any]:
        """Each body's initial state, in the scene's order."""
        return self._initial

    @property
    def run(self) -> RunOptions:
        """The run options (method, dt [s], duration [s], record_every, tradeoff defaults, controller)."""
        return self._run

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is read-only: cannot set {key!r}")

    def __iter__(self) -> Iterator[Any]:
        """scene, initial, run: ``scene, initial, run = rd.load_scene(...)``."""
        return iter((self.scene, self.initial, self.run))

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return all(getattr(self, key) == getattr(other, key) for key in ("scene", "initial", "run", "name",
                                                                          "description"))

    __hash__ = None  # type: ignore[assignment]  # equal by value, holding lists

    def __repr__(self) -> str:
        return (f"{type(self).__name__}(name={self.name!r}, bodies={len(self.scene.bodies)}, "
                f"elements={len(self.scene.elements)}, run={self.run!r})")
