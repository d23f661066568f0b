"""The shipped scenes of bodies about a fixed point, moving frames and variable mass (heavy_top, pendulum,
foucault, rocket): each loads, describes what matters about it (the pivot and I_O, the frame and its fictitious
terms, the mass flow and thrust), runs finite from Python and from `python3 -m rigiddyn simulate` (whose summary
line says the mass burnt, the pivot's reaction range), and its physics is what its file's comment says where
that is cheap to check exactly."""

import json
import math

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn.__main__ import main
from rigiddyn.scene_file import example_scenes, read_scene

NEW = ["heavy_top", "pendulum", "foucault", "rocket"]


def test_the_new_scenes_are_shipped():
    assert set(NEW) <= set(example_scenes())


# what describe must say of each (the body kind and its state, the pivot table, the frame, the terms)
DESCRIBED = {
    "heavy_top": ["pivoted", "q_WB, w_B (7)", "Pivots", "diag(0.014, 0.014, 0.006)", "Frame: W, inertial",
                  "UniformGravity"],
    "pendulum": ["pivoted_planar", "theta, omega (2)", "Pivots", "I_zz 0.333333", "UniformGravity"],
    "foucault": ["pivoted", "Frame: F = SceneFrame.earth at latitude 48.85 deg", "rotating relative to the inertial W",
                 "CentrifugalForce (frame.centrifugal)", "CoriolisForce (frame.coriolis)", "digits of I_C lost",
                 "p_W [m] and v_W [m/s] in F"],
    "rocket": ["Mass flows", "-2 kg/s", "p_W, v_W (6) + m (1)", "no jet damping", "Thrust",
               "u_rel = (0, 0, -2500) m/s, frame = world"],
}


@pytest.mark.parametrize("name", NEW)
def test_describe_says_what_matters(name):
    text = read_scene(name).scene.describe("rk4")
    for expected in DESCRIBED[name]:
        assert expected in text, (expected, text)
    assert "refused" not in text


@pytest.mark.parametrize("name", NEW)
def test_each_runs_finite_with_the_new_records(name):
    f = read_scene(name)
    r = rd.simulate(f.scene, f.initial, dt=f.run.dt, steps=200, method=f.run.method, record_every=20)
    for key in ("p_W", "q_WB", "v_W", "w_B", "pivot_reaction_W", "angular_momentum_O_W", "mass", "total_energy",
                "work", "power"):
        assert np.all(np.isfinite(np.asarray(getattr(r, key)))), key
    assert np.asarray(r.pivot_reaction_W).shape == (11, 1, 3)
    assert np.asarray(r.mass).shape == (11, 1)
    pytest.importorskip("pandas")
    df = r.to_dataframe()
    body = f.scene.body_names[0]
    np.testing.assert_array_equal(df[f"{body}:mass [kg]"], np.asarray(r.mass)[:, 0])
    np.testing.assert_array_equal(df[f"{body}:pivot_reaction_W_z [N]"], np.asarray(r.pivot_reaction_W)[:, 0, 2])
    np.testing.assert_array_equal(df[f"{body}:angular_momentum_O_W_x [kg m^2/s]"],
                                  np.asarray(r.angular_momentum_O_W)[:, 0, 0])


def test_the_foucault_scene_reports_the_fictitious_terms_one_by_one():
    f = read_scene("foucault")
    r = rd.simulate(f.scene, f.initial, dt=f.run.dt, steps=100, method="rk4", record_every=10)
    assert list(r.elements) == ["UniformGravity", "CentrifugalForce", "CoriolisForce"]


def test_the_rocket_burns_to_the_mass_and_speed_its_file_states():
    f = read_scene("rocket")
    steps = f.run.steps
    r = rd.simulate(f.scene, f.initial, dt=f.run.dt, steps=steps, method="rk4", record_every=steps)
    # m(t) = m0 + rate t is linear: every method integrates it exactly, to one rounding per step
    assert np.asarray(r.mass)[-1, 0] == pytest.approx(80.0, rel=steps * 2**-52)
    # v_z(60 s) = 2500 ln(2.5) - 9.81 * 60 (Tsiolkovsky less the gravity loss); RK4 at 0.1 s on
    # ln(m(t)), whose 5th derivative is at most 24 (2/80)^5 |u| ~ 6e-7 m/s^5: an error C h^4 t well below 1e-6
    assert np.asarray(r.v_W)[-1, 0, 2] == pytest.approx(2500.0 * math.log(2.5) - 9.81 * 60.0, abs=1e-6)


def test_a_longer_rocket_burn_is_refused_naming_the_mass():
    f = read_scene("rocket")
    with pytest.raises(ValueError, match="mass"):
        rd.simulate(f.scene, f.initial, dt=0.1, steps=1100, method="rk4")  # the mass reaches 0 at t = 100 s


@pytest.mark.parametrize("name, said", [
    ("rocket", "rocket: mass 200 -> 198 kg (2 kg burnt)"),
    ("pendulum", "rod: pivot reaction |R|"),
    ("heavy_top", "top: pivot reaction |R|"),
    ("foucault", "(the Jacobi integral)"),
])
def test_the_simulate_command_runs_each_and_its_summary_says_what_matters(name, said, tmp_path, capsys):
    out = tmp_path / name
    steps = {"rocket": "10", "pendulum": "200", "heavy_top": "200", "foucault": "50"}[name]
    assert main(["simulate", name, "--steps", steps, "--out", str(out), "--no-plot", "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert said in printed, printed
    record = json.loads((out / "run.json").read_text())
    assert any(c.endswith(":mass [kg]") for c in record["columns"])


@pytest.mark.parametrize("name", NEW)
def test_the_tradeoff_command_runs_each(name, capsys):
    f = read_scene(name)
    dt = f.run.dt
    # two steps on a short horizon: the command's path, not its figures
    assert main(["tradeoff", name, "--methods", "rk4", "--dts", f"{4 * dt},{2 * dt}", "--horizon", f"{40 * dt}",
                 "--no-progress"]) == 0
    out = " ".join(capsys.readouterr().out.split())  # the report wraps at 100 columns
    if name == "foucault":
        assert "richardson(" in out
    else:
        assert "vs the exact solution (" in out


@pytest.mark.parametrize("frame", [
    lambda: rd.SceneFrame.rotating((0.0, 0.0, 1.0), 0.3), lambda: rd.SceneFrame.rotating((0.0, 0.0, 1.0), 0.0),
    lambda: rd.SceneFrame.earth(0.5), lambda: rd.SceneFrame.moving(rd.FrameMotion.fixed()),
    lambda: rd.SceneFrame.moving(rd.FrameMotion(lambda t: rd.FrameKinematics())),
], ids=["rotating", "rate 0", "earth", "fixed placement", "general"])
def test_describe_lists_the_fictitious_terms_the_run_records(frame):
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="p")
    scene.frame = frame()
    recorded = list(rd.simulate(scene, [rd.ParticleState()], dt=0.1, steps=1).elements)
    text = scene.describe()
    for name in ("FrameOriginForce", "EulerForce", "CentrifugalForce", "CoriolisForce"):
        assert (f"  {name} (frame." in text) == (name in recorded), (name, recorded, text)
