"""Pictures of a recorded trajectory (needs matplotlib, extra ``plot``): the time histories of the
angular velocity, the attitude, the energy and |L|, and an animation of the body's axes; for a scene
(a SceneResult), the same over every body, overlaid (a colour per body, a line style per component).

Attitude is shown as ``"euler:SEQ"`` (Euler angles of q_WB in the sequence SEQ, as in
``rigiddyn.quat_to_euler``: uppercase intrinsic, lowercase extrinsic; the values the CSV's q_WB gives
there, jumps at the ±π cut and near gimbal lock included) or ``"rotvec"`` (the rotation vector of
q_WB, angle × axis, in W). Energy and |L| are drawn as their change since t = 0, the initial value in
the legend: a drift of 1e-14 J on 3e-3 J stays readable. ``units=`` draws every quantity in the user's
units, as the tables (rigiddyn.output_units): ``units={"angle": "deg", "time": "h"}`` draws w_B in deg/h
and the attitude in deg over t in h, each axis labelled with its unit.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal

import numpy as np

from . import _core
from .output_units import check_units, convert_unit

__all__ = ["ATTITUDE_HELP", "MAX_SCENE_BODIES", "animate_axes", "animation_writer", "check_attitude", "plot_scene",
           "plot_trajectory", "scene_figure", "trajectory_figure"]

ATTITUDE_HELP = "euler:SEQ (SEQ as quat_to_euler, e.g. euler:ZYX) or rotvec"
MAX_SCENE_BODIES = 10  # bodies drawn in a scene's plot (the first ones; the title says how many of how many)
# the line styles of the x, y, z components (or angles 1, 2, 3) of a scene's body
_STYLES: tuple[Literal["-", "--", ":"], ...] = ("-", "--", ":")
_ATTITUDE_KINDS = ("RigidBody", "PlanarBody", "PivotedBody", "PivotedPlanarBody", "Gyrostat", "TreeLink")  # with an attitude


def check_attitude(attitude: str) -> str:
    """`attitude` if it is "rotvec" or "euler:SEQ" with a sequence quat_to_euler takes, else
    ValueError "attitude: expected ..., got ..."."""
    if not isinstance(attitude, str):
        raise TypeError(f"attitude: expected a string ({ATTITUDE_HELP}), got {attitude!r}")
    kind, _, seq = attitude.partition(":")
    if attitude == "rotvec":
        return attitude
    if kind == "euler":
        try:
            with warnings.catch_warnings():  # a gimbal-lock warning is no verdict on the sequence
                warnings.simplefilter("ignore")
                _core.quat_to_euler(seq, [0.0, 0.0, 0.0, 1.0])
        except (ValueError, TypeError):
            pass
        else:
            return attitude
    raise ValueError(f"attitude: expected {ATTITUDE_HELP}, got {attitude!r}")


def _attitude(q_WB: np.ndarray, attitude: str, units: Mapping[str, str] | None = None
              ) -> tuple[np.ndarray, list[str], str, str]:
    """(n, 3) angles in the angle unit of `units` (rad by default), their legend labels, the axis label and a
    note (gimbal lock) or ""."""
    factor, unit = convert_unit("rad", units)
    if attitude == "rotvec":
        return (_core.quat_to_rotvec(q_WB) * factor, ["rotvec x", "rotvec y", "rotvec z"],
                f"rotation vector in W [{unit}]", "")
    seq = attitude.partition(":")[2]
    with warnings.catch_warnings(record=True) as caught:  # a gimbal-lock warning becomes the plot's note
        warnings.simplefilter("always")
        angles = _core.quat_to_euler(seq, q_WB)
    note = f"gimbal lock met: {caught[0].message}" if caught else ""
    primes = ("", "\u2032", "\u2033") if seq.isupper() else ("", "", "")  # intrinsic: about moved axes
    labels = [f"angle {i + 1} about {axis.upper()}{primes[i]}" for i, axis in enumerate(seq)]
    kind = "intrinsic" if seq.isupper() else "extrinsic"
    return angles * factor, labels, f"Euler {seq} ({kind}) [{unit}]", note


def _change(series: list[Any], names: list[str], quantity: str, si_unit: str,
            units: Mapping[str, str] | None = None) -> tuple[np.ndarray, list[str], str]:
    """(values - initial values, labels "name(0) = value unit", axis label) of scalar series in `si_unit`,
    drawn in its unit under `units`."""
    factor, unit = convert_unit(si_unit, units)
    values = np.stack([np.asarray(x, dtype=np.float64) for x in series], axis=1) * factor
    labels = [f"{name}(0) = {values[0, j] + 0.0:.6g} {unit}" for j, name in enumerate(names)]  # + 0.0: no "-0"
    return values - values[0], labels, f"{quantity} change\nsince t = 0 [{unit}]"


def _one_body(result: Any) -> Any:
    """The records of the one body of a SceneResult (result.body(0)); ValueError for a result of several."""
    names = tuple(result.body_names)
    if len(names) != 1:
        raise ValueError(f"result: expected a run of one body (plot_scene draws a scene), got the bodies {names}")
    return result.body(0)


def trajectory_figure(result: Any, attitude: str = "euler:ZYX", title: str = "", *,
                      units: Mapping[str, str] | None = None) -> Any:
    """A matplotlib Figure of four panels over t: w_B (components in B), the attitude (see check_attitude),
    the change since t = 0 of the kinetic and total energy and of |L| = |H_G| about the centre of mass
    (initial values in the legends). Legends sit outside the axes, to the right.

    Parameters
    ----------
    result : SceneResult
        A run of one body (``rigiddyn.simulate`` of a body), with q_WB as (x, y, z, w).
    attitude : str, optional
        "euler:SEQ" or "rotvec" (check_attitude).
    title : str, optional
        The figure's title.
    units : Mapping[str, str], optional
        The units drawn, {dimension: unit} as for the tables (rigiddyn.output_units); None: SI (t [s],
        w_B [rad/s], angles [rad], energy [J], |L| [kg m^2/s]).

    Returns
    -------
    matplotlib.figure.Figure
        Four axes, each labelled with its unit.

    Raises
    ------
    TypeError, ValueError
        A bad `attitude` or `units`; a result of more than one body (plot_scene draws a scene).

    See Also
    --------
    plot_trajectory, plot_scene

    Examples
    --------
    >>> from rigiddyn.trajectory_plot import trajectory_figure
    >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.0, 0.0, 0.1]), dt=10.0,
    ...                 steps=36, error=False)
    >>> fig = trajectory_figure(r, units={"angle": "deg", "time": "h"})
    >>> [ax.get_ylabel() for ax in fig.axes[:2]], fig.axes[-1].get_xlabel()
    (['angular velocity w_B [deg/h]', 'Euler ZYX (intrinsic) [deg]'], 't [h]')
    >>> import matplotlib.pyplot as plt
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    check_attitude(attitude)
    check_units(units)
    t_factor, t_unit = convert_unit("s", units)
    w_factor, w_unit = convert_unit("rad/s", units)
    body = _one_body(result)
    t = np.asarray(body.t) * t_factor
    angles, angle_labels, angle_axis, note = _attitude(np.asarray(body.q_WB), attitude, units)
    fig, axes = plt.subplots(4, 1, sharex=True, figsize=(9.0, 9.0), layout="constrained")
    panels = [
        (np.asarray(body.w_B) * w_factor, ["w_B x", "w_B y", "w_B z"], f"angular velocity w_B [{w_unit}]"),
        (angles, angle_labels, angle_axis),
        _change([result.kinetic_energy, result.total_energy], ["kinetic T", "total E"], "energy", "J", units),
        _change([body.angular_momentum_norm], ["|L|"], "|L|", "kg m^2/s", units),
    ]
    for ax, (values, labels, ylabel) in zip(axes, panels):
        for j, label in enumerate(labels):
            ax.plot(t, values[:, j], label=label, linestyle="--" if label.startswith("total") else "-")
        ax.set_ylabel(ylabel)
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize="small")
        ax.grid(True, alpha=0.3)
    if note:
        axes[1].set_title(note, fontsize="small")
    axes[-1].set_xlabel(f"t [{t_unit}]")
    if title:
        fig.suptitle(title)
    return fig


def plot_trajectory(result: Any, path: str | Path, attitude: str = "euler:ZYX", title: str = "", *,
                    units: Mapping[str, str] | None = None) -> Path:
    """Save trajectory_figure(result, attitude, title, units=units) to `path`.

    Parameters
    ----------
    result : SceneResult
        As in trajectory_figure.
    path : str or pathlib.Path
        The file written, its format from its suffix (e.g. .png).
    attitude : str, optional
        As in trajectory_figure.
    title : str, optional
        As in trajectory_figure.
    units : Mapping[str, str], optional
        The units drawn, as in trajectory_figure; None: SI.

    Returns
    -------
    pathlib.Path
        `path`.

    Raises
    ------
    TypeError, ValueError
        As trajectory_figure.

    See Also
    --------
    trajectory_figure

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = tempfile.TemporaryDirectory()
    >>> from rigiddyn.trajectory_plot import plot_trajectory
    >>> r = rd.simulate(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), rd.RigidBodyState(w_B=[0.0, 0.0, 0.1]), dt=10.0,
    ...                 steps=36, error=False)
    >>> plot_trajectory(r, pathlib.Path(folder.name) / "w.png", units={"angle": "deg"}).name
    'w.png'
    >>> folder.cleanup()
    """
    import matplotlib.pyplot as plt

    fig = trajectory_figure(result, attitude, title, units=units)
    try:
        fig.savefig(path, dpi=120)
    finally:
        plt.close(fig)
    return Path(path)


def _overlaid(ax: Any, t: np.ndarray, values: np.ndarray, drawn: list[int], names: list[str], ylabel: str,
              components: list[str]) -> None:
    """values (n, nb, 3) of the bodies `drawn` on `ax`: a colour per body, a line style per component,
    and a legend of both (outside the axes, to the right)."""
    from matplotlib.lines import Line2D

    for colour, b in enumerate(drawn):
        for j in range(values.shape[2]):
            ax.plot(t, values[:, b, j], color=f"C{colour % 10}", linestyle=_STYLES[j], linewidth=1.2)
    handles = [Line2D([], [], color=f"C{colour % 10}", label=names[b]) for colour, b in enumerate(drawn)]
    if len(components) > 1:
        handles += [Line2D([], [], color="black", linestyle=_STYLES[j], label=c) for j, c in enumerate(components)]
    ax.set_ylabel(ylabel)
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize="small")


def _series(ax: Any, t: np.ndarray, panel: tuple[np.ndarray, list[str], str]) -> None:
    """Scalar series (n, k) with their labels and axis label on `ax`, legend outside to the right."""
    values, labels, ylabel = panel
    for j, label in enumerate(labels):
        ax.plot(t, values[:, j], label=label, linestyle="--" if label.startswith("total") else "-")
    ax.set_ylabel(ylabel)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize="small")


def scene_figure(result: Any, kinds: list[str], attitude: str = "euler:ZYX", title: str = "", *,
                 units: Mapping[str, str] | None = None) -> Any:
    """A matplotlib Figure of a SceneResult over t, the bodies overlaid (a colour per body, a line style per
    component; the first MAX_SCENE_BODIES drawn): p_W of each body in W; for the bodies with an attitude
    w_B in B and the attitude (see check_attitude); the change since t = 0 of the scene's kinetic,
    potential and total energy and of the work of all its elements (initial values in the legend); |H|
    about W's origin; each body's mass when one changes.

    Parameters
    ----------
    result : SceneResult
        With q_WB as (x, y, z, w).
    kinds : list of str
        The type name of each body, e.g. "RigidBody", "Particle" (a particle has no attitude).
    attitude : str, optional
        "euler:SEQ" or "rotvec" (check_attitude).
    title : str, optional
        The figure's title.
    units : Mapping[str, str], optional
        The units drawn, {dimension: unit} as for the tables (rigiddyn.output_units); None: SI (t [s],
        p_W [m], w_B [rad/s], angles [rad], energy [J], |H| [kg m^2/s], mass [kg]).

    Returns
    -------
    matplotlib.figure.Figure
        One axes per panel, each labelled with its unit.

    Raises
    ------
    TypeError, ValueError
        A bad `attitude`, `kinds` or `units`.

    See Also
    --------
    plot_scene

    Examples
    --------
    >>> from rigiddyn.trajectory_plot import scene_figure
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.Particle(1.0), name="sat")
    0
    >>> r = rd.simulate(scene, [rd.ParticleState(v_W=[1000.0, 0.0, 0.0])], dt=60.0, steps=10, error=False)
    >>> fig = scene_figure(r, ["Particle"], units={"length": "km", "time": "min"})
    >>> fig.axes[0].get_ylabel(), fig.axes[-1].get_xlabel()
    ('position p_W [km]', 't [min]')
    >>> import matplotlib.pyplot as plt
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    check_attitude(attitude)
    check_units(units)
    t_factor, t_unit = convert_unit("s", units)
    p_factor, p_unit = convert_unit("m", units)
    w_factor, w_unit = convert_unit("rad/s", units)
    m_factor, m_unit = convert_unit("kg", units)
    t = np.asarray(result.t) * t_factor
    names = list(result.body_names)
    if len(kinds) != len(names):
        raise ValueError(f"kinds: expected one body type per body ({len(names)}), got {len(kinds)}")
    drawn = list(range(min(len(names), MAX_SCENE_BODIES)))
    turning = [b for b in drawn if kinds[b] in _ATTITUDE_KINDS]
    mass = np.asarray(result.mass)
    mass_changes = bool(np.any(mass != mass[:1]))
    rows = 3 + 2 * bool(turning) + mass_changes
    fig, axes = plt.subplots(rows, 1, sharex=True, figsize=(9.0, 2.0 + 1.9 * rows), layout="constrained")
    panels = iter(axes)
    _overlaid(next(panels), t, np.asarray(result.p_W) * p_factor, drawn, names, f"position p_W [{p_unit}]",
              ["x", "y", "z"])
    if turning:
        _overlaid(next(panels), t, np.asarray(result.w_B) * w_factor, turning, names,
                  f"angular velocity\nw_B [{w_unit}]", ["x", "y", "z"])
        q_WB = np.asarray(result.q_WB)
        angles, notes = [], []
        for b in turning:
            values, labels, angle_axis, note = _attitude(q_WB[:, b], attitude, units)
            angles.append(values)
            notes += [f"{names[b]}: {note}"] if note else []
        ax = next(panels)
        stacked = np.zeros((len(t), len(names), 3))
        stacked[:, turning] = np.stack(angles, axis=1)
        _overlaid(ax, t, stacked, turning, names, angle_axis.replace(" [", "\n["),
                  [label.partition(" about ")[2] or label for label in labels])
        if notes:
            ax.set_title("; ".join(notes), fontsize="small")
    work = np.sum(np.asarray(result.work).reshape(len(t), -1), axis=1)
    _series(next(panels), t, _change([result.kinetic_energy, result.potential_energy, result.total_energy, work],
                                     ["kinetic T", "potential V", "total E", "work of the elements W"], "energy", "J",
                                     units))
    _series(next(panels), t, _change([np.linalg.norm(np.asarray(result.angular_momentum_W), axis=1)],
                                     ["|H|"], "|H| about W's origin", "kg m^2/s", units))
    if mass_changes:
        _overlaid(next(panels), t, mass[:, :, None] * m_factor, drawn, names, f"mass [{m_unit}]", [""])
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel(f"t [{t_unit}]")
    shown = "" if len(drawn) == len(names) else f" (the first {len(drawn)} of {len(names)} bodies drawn)"
    if title or shown:
        fig.suptitle(f"{title}{shown}")
    return fig


def plot_scene(result: Any, kinds: list[str], path: str | Path, attitude: str = "euler:ZYX", title: str = "", *,
               units: Mapping[str, str] | None = None) -> Path:
    """Save scene_figure(result, kinds, attitude, title, units=units) to `path`.

    Parameters
    ----------
    result : SceneResult
        As in scene_figure.
    kinds : list of str
        As in scene_figure.
    path : str or pathlib.Path
        The file written, its format from its suffix (e.g. .png).
    attitude : str, optional
        As in scene_figure.
    title : str, optional
        As in scene_figure.
    units : Mapping[str, str], optional
        The units drawn, as in scene_figure; None: SI.

    Returns
    -------
    pathlib.Path
        `path`.

    Raises
    ------
    TypeError, ValueError
        As scene_figure.

    See Also
    --------
    scene_figure

    Examples
    --------
    >>> import tempfile, pathlib
    >>> folder = tempfile.TemporaryDirectory()
    >>> from rigiddyn.trajectory_plot import plot_scene
    >>> scene = rd.Scene()
    >>> scene.add_body(rd.Particle(1.0), name="sat")
    0
    >>> r = rd.simulate(scene, [rd.ParticleState(v_W=[1000.0, 0.0, 0.0])], dt=60.0, steps=10, error=False)
    >>> plot_scene(r, ["Particle"], pathlib.Path(folder.name) / "s.png", units={"length": "km"}).name
    's.png'
    >>> folder.cleanup()
    """
    import matplotlib.pyplot as plt

    fig = scene_figure(result, kinds, attitude, title, units=units)
    try:
        fig.savefig(path, dpi=120)
    finally:
        plt.close(fig)
    return Path(path)


def animation_writer(fmt: str = "auto") -> tuple[str, str]:
    """(matplotlib writer name, file suffix) for `fmt`: "mp4" (ffmpeg), "gif" (Pillow) or "auto"
    (MP4 if ffmpeg is present, else GIF). RuntimeError naming both when no writer is available;
    ValueError for an unknown fmt or one whose writer is missing."""
    from matplotlib import animation

    writers = {"mp4": ("ffmpeg", ".mp4"), "gif": ("pillow", ".gif")}
    if fmt == "auto":
        for name, suffix in writers.values():
            if animation.writers.is_available(name):
                return name, suffix
        raise RuntimeError("animate: no animation writer: MP4 needs ffmpeg on the PATH, GIF needs Pillow "
                           "(pip install pillow); neither is available")
    if fmt not in writers:
        raise ValueError(f"animate: expected one of auto, mp4, gif, got {fmt!r}")
    name, suffix = writers[fmt]
    if not animation.writers.is_available(name):
        raise ValueError(f"animate: expected a format whose writer is present ({fmt} needs {name}), got {fmt!r}")
    return name, suffix


def animate_axes(result: Any, path: str | Path, fmt: str = "auto", frames: int = 100, fps: int = 25,
                 title: str = "") -> Path:
    """Animate the body axes (the columns of R_WB: x red, y green, z blue, unit length, drawn from
    the origin of W) of a run of one body (a SceneResult) over the records, at most `frames` frames evenly
    spaced in record index, `fps` frames per second. Written with animation_writer(fmt) to `path` with the
    writer's suffix; returns that path."""
    import matplotlib.pyplot as plt
    from matplotlib import animation

    for name, value in (("frames", frames), ("fps", fps)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError(f"{name}: expected an integer >= 1, got {value!r}")
    writer, suffix = animation_writer(fmt)
    path = Path(path).with_suffix(suffix)
    body = _one_body(result)
    t = np.asarray(body.t)
    R_WB = _core.quat_to_matrix(np.asarray(body.q_WB)).reshape(-1, 3, 3)
    shown = np.unique(np.linspace(0, len(t) - 1, min(int(frames), len(t))).round().astype(int))
    fig = plt.figure(figsize=(4.5, 4.5), dpi=100)
    ax: Any = fig.add_axes((0.02, 0.12, 0.86, 0.8), projection="3d")  # Axes3D; room for the z label and legend
    for lim, ticks in ((ax.set_xlim, ax.set_xticks), (ax.set_ylim, ax.set_yticks), (ax.set_zlim, ax.set_zticks)):
        lim(-1.0, 1.0)
        ticks([-1.0, 0.0, 1.0])
    ax.set_xlabel("x_W")
    ax.set_ylabel("y_W")
    ax.set_zlabel("z_W")
    lines: list[Any] = [ax.plot([0.0, 0.0], [0.0, 0.0], [0.0, 0.0], color=c, linewidth=3, label=f"body {a}")[0]
             for a, c in zip("xyz", ("tab:red", "tab:green", "tab:blue"))]
    fig.legend(loc="lower center", ncol=3, fontsize="small")  # below the axes, never over the data
    label = ax.set_title("")

    def draw(i: int) -> list[Any]:
        for k, line in enumerate(lines):
            axis_W = R_WB[i, :, k]
            line.set_data_3d([0.0, axis_W[0]], [0.0, axis_W[1]], [0.0, axis_W[2]])
        label.set_text(f"{title}  t = {t[i]:.3f} s".strip())
        return [*lines, label]

    try:
        movie = animation.FuncAnimation(fig, draw, frames=shown.tolist(), blit=False)
        movie.save(str(path), writer=writer, fps=int(fps))
    finally:
        plt.close(fig)
    return path
