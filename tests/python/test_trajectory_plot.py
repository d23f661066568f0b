"""rigiddyn.trajectory_plot: the figure of a run (checked through its axes and artists, not pixels)
and the animation of the body's axes."""

import numpy as np
import pytest
import rigiddyn as rd

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import animation  # noqa: E402
from rigiddyn import trajectory_plot as tp  # noqa: E402


@pytest.fixture(scope="module")
def result():
    """A torque-free tumble near the intermediate axis (the T-handle), 0.5 s in 50 records."""
    body = rd.RigidBody(0.1, np.diag([2.0e-5, 6.5e-5, 8.0e-5]))
    return rd.simulate(body, rd.RigidBodyState(w_B=[0.1, 10.0, 0.0]), 1e-3, 500, "rk4", record_every=10)


def _legend_outside(ax):
    """The legend's box lies right of the axes' box (display coordinates after a draw)."""
    ax.figure.canvas.draw()
    legend = ax.get_legend().get_window_extent()
    return legend.x0 >= ax.get_window_extent().x1


@pytest.mark.parametrize("attitude,ylabel,labels", [
    ("euler:ZYX", "Euler ZYX (intrinsic) [rad]", ["angle 1 about Z", "angle 2 about Y\u2032", "angle 3 about X\u2033"]),
    ("euler:xyz", "Euler xyz (extrinsic) [rad]", ["angle 1 about X", "angle 2 about Y", "angle 3 about Z"]),
    ("rotvec", "rotation vector in W [rad]", ["rotvec x", "rotvec y", "rotvec z"]),
])
def test_figure_panels_units_and_legends(result, attitude, ylabel, labels):
    fig = tp.trajectory_figure(result, attitude, title="T-handle")
    body = result.body(0)  # the run's one body
    try:
        axes = fig.axes
        assert [ax.get_ylabel() for ax in axes] == ["angular velocity w_B [rad/s]", ylabel,
                                                    "energy change\nsince t = 0 [J]",
                                                    "|L| change\nsince t = 0 [kg m^2/s]"]
        assert axes[-1].get_xlabel() == "t [s]"
        assert [t.get_text() for t in axes[1].get_legend().get_texts()] == labels
        assert all(_legend_outside(ax) for ax in axes)
        assert "T-handle" in [text.get_text() for text in fig.texts + [fig._suptitle]]
        # the plotted data are the result's: w_B as is, the attitude as quat_to_euler/rotvec gives it
        np.testing.assert_array_equal(axes[0].get_lines()[1].get_ydata(), body.w_B[:, 1])
        expected = (rd.quat_to_rotvec(body.q_WB) if attitude == "rotvec"
                    else rd.quat_to_euler(attitude.split(":")[1], body.q_WB))
        for j, line in enumerate(axes[1].get_lines()):
            np.testing.assert_array_equal(line.get_ydata(), expected[:, j])
        # energy and |L| as their change since t = 0, the initial value in the legend
        np.testing.assert_array_equal(axes[3].get_lines()[0].get_ydata(),
                                      body.angular_momentum_norm - body.angular_momentum_norm[0])
        assert axes[2].get_legend().get_texts()[0].get_text() == f"kinetic T(0) = {result.kinetic_energy[0]:.6g} J"
    finally:
        plt.close(fig)


def test_plot_writes_the_file(result, tmp_path):
    path = tp.plot_trajectory(result, tmp_path / "run.png")
    assert path.is_file() and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert not plt.get_fignums()  # closed after saving


@pytest.mark.parametrize("attitude", ["euler", "euler:ZY", "euler:ABC", "quat", "euler:ZYX:x", ""])
def test_bad_attitude_is_refused(attitude):
    with pytest.raises(ValueError, match=f"attitude: expected euler:SEQ .* or rotvec, got '{attitude}'"):
        tp.check_attitude(attitude)
    with pytest.raises(TypeError, match="attitude: expected a string"):
        tp.check_attitude(3)


def test_gif_animation_is_written_with_pillow(result, tmp_path):
    assert animation.writers.is_available("pillow")  # Pillow comes with matplotlib
    path = tp.animate_axes(result, tmp_path / "axes.mp4", fmt="gif", frames=4, title="rk4")
    assert path == tmp_path / "axes.gif"
    assert path.read_bytes()[:6] in (b"GIF87a", b"GIF89a")
    assert not plt.get_fignums()


def test_writer_choice_and_missing_writers(monkeypatch):
    present = {"ffmpeg": False, "pillow": True}
    monkeypatch.setattr(animation.writers, "is_available", lambda name: present.get(name, False))
    assert tp.animation_writer("auto") == ("pillow", ".gif")
    with pytest.raises(ValueError, match=r"animate: expected a format whose writer is present \(mp4 needs ffmpeg\)"):
        tp.animation_writer("mp4")
    present["ffmpeg"] = True
    assert tp.animation_writer("auto") == ("ffmpeg", ".mp4")
    present.update(ffmpeg=False, pillow=False)
    with pytest.raises(RuntimeError, match="MP4 needs ffmpeg on the PATH, GIF needs Pillow"):
        tp.animation_writer("auto")
    with pytest.raises(ValueError, match="animate: expected one of auto, mp4, gif, got 'avi'"):
        tp.animation_writer("avi")


def test_bad_animation_arguments(result, tmp_path):
    for name, kwargs in (("frames", {"frames": 0}), ("fps", {"fps": 2.5}), ("frames", {"frames": True})):
        with pytest.raises(ValueError, match=f"{name}: expected an integer >= 1"):
            tp.animate_axes(result, tmp_path / "a", fmt="gif", **kwargs)
    assert not list(tmp_path.iterdir())


def test_gimbal_lock_is_noted_on_the_plot_not_raised(result):
    # ZXZ (proper Euler angles) is singular at the identity, where the run starts: quat_to_euler warns
    # there as SciPy does; the figure turns that into a note over the attitude panel
    fig = tp.trajectory_figure(result, "euler:ZXZ")
    try:
        assert fig.axes[1].get_title().startswith("gimbal lock met: ")
    finally:
        plt.close(fig)
    fig = tp.trajectory_figure(result, "euler:ZYX")  # no lock on this tumble: no note
    try:
        assert fig.axes[1].get_title() == ""
    finally:
        plt.close(fig)


# ------------------------------------------------------------------ scenes


def _scene_run(name, steps=20):
    from rigiddyn.scene_file import read_scene

    file = read_scene(name)
    result = rd.simulate(file.scene, file.initial, dt=file.run.dt, steps=steps, method=file.run.method)
    return result, [type(b).__name__ for b in file.scene.bodies]


@pytest.mark.parametrize("name,ylabels", [
    # a rigid body and a particle: the attitude panels draw the rigid body only
    ("satellite_boom", ["position p_W [m]", "angular velocity\nw_B [rad/s]", "Euler ZYX (intrinsic)\n[rad]",
                        "energy change\nsince t = 0 [J]", "|H| about W's origin change\nsince t = 0 [kg m^2/s]"]),
    # particles only: no attitude panels
    ("spring_chain", ["position p_W [m]", "energy change\nsince t = 0 [J]",
                      "|H| about W's origin change\nsince t = 0 [kg m^2/s]"]),
    # a mass flow: the mass panel
    ("rocket", ["position p_W [m]", "energy change\nsince t = 0 [J]",
                "|H| about W's origin change\nsince t = 0 [kg m^2/s]", "mass [kg]"]),
])
def test_a_scene_figure_overlays_its_bodies(name, ylabels):
    result, kinds = _scene_run(name)
    fig = tp.scene_figure(result, kinds, title=name)
    try:
        assert [ax.get_ylabel() for ax in fig.axes] == ylabels
        nb = len(result.body_names)
        assert len(fig.axes[0].get_lines()) == 3 * nb  # x, y, z of each body
        turning = [i for i, k in enumerate(kinds) if k != "Particle"]
        if turning:
            assert len(fig.axes[1].get_lines()) == 3 * len(turning)
            np.testing.assert_array_equal(fig.axes[1].get_lines()[1].get_ydata(), result.w_B[:, turning[0], 1])
        # the bodies in the legend by name, the components by line style
        legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        assert legend == [*result.body_names, "x", "y", "z"]
        assert all(_legend_outside(ax) for ax in fig.axes)
    finally:
        plt.close(fig)


def test_a_scene_of_many_bodies_draws_the_first_and_says_so():
    result, kinds = _scene_run("cluster", steps=2)
    fig = tp.scene_figure(result, kinds, title="cluster")
    try:
        assert len(fig.axes[0].get_lines()) == 3 * tp.MAX_SCENE_BODIES
        assert f"(the first {tp.MAX_SCENE_BODIES} of 1000 bodies drawn)" in fig._suptitle.get_text()
    finally:
        plt.close(fig)


def test_the_simulate_command_plots_a_scene(tmp_path, capsys):
    from rigiddyn.__main__ import main

    out = tmp_path / "out"
    assert main(["simulate", "satellite_boom", "--steps", "50", "--out", str(out), "--no-progress"]) == 0
    assert (out / "trajectory.png").stat().st_size > 0
    assert "no plot" not in capsys.readouterr().err
