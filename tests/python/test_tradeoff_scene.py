"""rigiddyn.tradeoff on scenes (rigiddyn.scene_precision): a scene is swept like a problem, its
reference is Richardson-refined and checked against another method family, a method the scene refuses
shows "not applicable: <reason>", compile warnings are notes, the errors are taken over the bodies."""

import json
import math
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn.__main__ import main
from rigiddyn.scene_precision import BodyData, SceneStates, attitude_angle, is_scene_source, scene_measures
from rigiddyn.stability import StabilityWarning, oscillator_growth, scene_modes, scene_stability_message
from rigiddyn.work_precision import MEASURES, REFERENCE_TARGET, TradeoffResult, tradeoff

OMEGA = 2.0  # [rad/s] of the oscillator scene
AMPLITUDE = 0.1  # [m]


def oscillator(damping=0.0):
    """A 1 kg particle on a spring k = OMEGA^2 to a world anchor at the origin, released at AMPLITUDE."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0), name="bob")
    scene.add(rigiddyn.SpringDamper(body_a=0, stiffness=OMEGA**2, damping=damping))
    return scene, [rigiddyn.ParticleState(p_W=(AMPLITUDE, 0.0, 0.0))]


SCENE_FILE = """
name = "spring and spinner"
[run]
dt = 0.01
duration = 2.0
[[body]]
name = "bob"
kind = "particle"
mass = 1.0
p_W = [0.1, 0, 0]
[[body]]
name = "top"
kind = "rigid"
mass = 2.0
inertia = [1.0, 2.0, 3.0]
w_B = [0.3, 0.1, 1.0]
[[force]]
type = "spring_damper"
body_a = "bob"
stiffness = 4.0
"""


def test_spring_errors_match_the_closed_form_and_exact_is_not_applicable():
    scene, initial = oscillator()
    dts = [0.1, 0.05, 0.025]
    result = tradeoff(scene, initial=initial, horizon=2.0, methods=["rk4", "exact"], dts=dts,
                      measure="max_position_error", progress=False)
    rk4 = sorted((r for r in result.rows if r["method"] == "rk4"), key=lambda r: -r["dt"])
    exact = [r for r in result.rows if r["method"] == "exact"]
    assert len(exact) == len(dts)
    for r in exact:  # refused by compile (a force element): the reason, no numbers, not a crash
        assert r["order_note"].startswith("not applicable: ") and "exact" in r["order_note"], r["order_note"]
        assert all(math.isnan(r[k]) for k in MEASURES) and not r["diverged"]
    table = result.to_table()
    assert "not applicable" in table and max(len(line) for line in table.splitlines()) <= 100
    for r in rk4:
        assert r["reference"] == "richardson(rk4)" or r["reference"].startswith("richardson("), r["reference"]
        assert not r["reference"].startswith("unreliable"), r["reference_check"]
        # the same run against the closed form x = A cos(omega t)
        run = rigiddyn.simulate(scene.compile(method="rk4"), initial, r["dt"], r["steps"], "rk4")
        t = np.asarray(run.t)
        true = float(np.max(np.linalg.norm(np.asarray(run.p_W)[:, 0] - np.outer(AMPLITUDE * np.cos(OMEGA * t),
                                                                               [1.0, 0.0, 0.0]), axis=1)))
        # the reference is refined until its Richardson estimate is REFERENCE_TARGET (1 %) of the smallest
        # run's max_state_error; here that is at most twice the position error / L_p (a phase error d:
        # velocity error A omega d / L_v (L_v = A omega) against position A d / L_p (L_p = 2 A)), so the
        # reference is off by <= 2 % of the run's position error, and the estimate is within a factor
        # 1 +- 2^-4 of its true error in the asymptotic range: 5 % leaves room
        assert abs(r["max_position_error"] - true) <= 5 * REFERENCE_TARGET * true, (r["max_position_error"], true)
    # 4th order: the errors fall 16x per halving while dt omega <= 0.2 (asymptotic range)
    assert rk4[-1]["observed_order"] == pytest.approx(4.0, abs=0.2)


def test_a_compatibility_warning_is_a_note_and_the_reference_avoids_it():
    scene, initial = oscillator(damping=0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the compile warning must not escape as a warning
        result = tradeoff(scene, initial=initial, horizon=1.0, methods=["splitting_dlm", "rk4"], dts=[0.05, 0.025],
                          progress=False)
    notes = [n for n in result.notes if n.startswith("splitting_dlm: ")]
    assert notes and "SceneCompatibilityWarning" in notes[0]
    assert all("splitting" not in r["reference"] for r in result.rows)
    assert "note: splitting_dlm: " in result.to_table()
    back = TradeoffResult.read_json(result.to_json())
    assert back.notes == result.notes


def test_a_scene_file_and_the_load_scene_tuple(tmp_path):
    path = tmp_path / "spinner.toml"
    path.write_text(SCENE_FILE)
    assert is_scene_source(path) and is_scene_source(str(path)) and not is_scene_source("t_handle")
    by_file = tradeoff(path, methods=["rkmk4", "implicit_midpoint"], dts=[0.02, 0.01], progress=False)
    by_tuple = tradeoff(rigiddyn.load_scene(path), methods=["rkmk4", "implicit_midpoint"], dts=[0.02, 0.01],
                        progress=False)
    assert by_file.problem == "spring and spinner" and by_file.horizon == 2.0
    assert by_tuple.horizon == 2.0
    for a, b in zip(by_file.rows, by_tuple.rows):  # the same runs: deterministic errors
        assert a["method"] == b["method"] and a["max_state_error"] == b["max_state_error"]
    # the rigid body turns: attitude and body momentum errors are measured, nonzero for a 2nd-order method
    mid = [r for r in by_file.rows if r["method"] == "implicit_midpoint"]
    assert all(r["max_attitude_error"] > 0 and r["max_momentum_error"] > 0 for r in mid)


def test_the_command_line_takes_a_scene_file(tmp_path, capsys):
    path = tmp_path / "spinner.toml"
    path.write_text(SCENE_FILE)
    code = main(["tradeoff", str(path), "--methods", "rk4,exact", "--dts", "0.02,0.01", "--no-progress",
                 "--out", str(tmp_path / "out")])
    out = capsys.readouterr()
    assert code == 0, out.err
    assert "spring and spinner" in out.out and "not applicable" in out.out
    data = json.loads((tmp_path / "out" / "tradeoff.json").read_text())
    assert any(r["order_note"].startswith("not applicable") for r in data["rows"])


@pytest.mark.parametrize("kwargs, name", [({}, "initial"), ({"initial": "x"}, "initial"),
                                          ({"initial": "states", "horizon": None}, "horizon"),
                                          ({"initial": "states", "horizon": -1.0}, "horizon")])
def test_bad_scene_arguments_name_the_argument(kwargs, name):
    scene, initial = oscillator()
    kwargs = {k: (initial if v == "states" else v) for k, v in kwargs.items()}
    with pytest.raises((ValueError, TypeError), match=f"^{name}: expected"):
        tradeoff(scene, progress=False, **kwargs)


def synthetic(n, nb, seed):
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(n, nb, 4))
    q /= np.linalg.norm(q, axis=2, keepdims=True)
    return SceneStates(np.linspace(0.0, 1.0, n), rng.normal(size=(n, nb, 3)), q, rng.normal(size=(n, nb, 3)),
                       rng.normal(size=(n, nb, 3)), rng.uniform(1, 2, n), rng.normal(size=n), rng.normal(size=n),
                       rng.normal(size=(n, 3)), rng.normal(size=(n, 3)))


def test_measures_are_the_largest_over_the_bodies():
    bodies = [BodyData("particle", 1.0, np.zeros((3, 3))), BodyData("rigid", 2.0, np.diag([1.0, 2.0, 3.0]))]
    ref = synthetic(5, 2, 0)
    run = SceneStates(**{k: np.array(v, copy=True) for k, v in ref.__dict__.items()})
    run.p_W[3, 1] += [0.0, 0.0, 1e-3]  # body 1 off by 1 mm at record 3
    run.v_W[2, 0] += [2e-4, 0.0, 0.0]
    angle = 1e-4  # body 1 turned by 1e-4 rad about its x axis at the last record: q (x) (sin(a/2), 0, 0, cos(a/2))
    x, y, z, w = ref.q_WB[-1, 1]
    s, c = math.sin(angle / 2), math.cos(angle / 2)
    run.q_WB[-1, 1] = [w * s + x * c, y * c + z * s, z * c - y * s, w * c - x * s]
    run.total_energy = ref.total_energy + 1e-6
    out = scene_measures(bodies, 1.0, run, ref, np.zeros(5))
    # each is a difference of a few roundings of O(1) numbers: 1e-12 absolute
    assert out["max_position_error"] == pytest.approx(1e-3, abs=1e-12)
    assert out["final_position_error"] == pytest.approx(0.0, abs=1e-12)
    assert out["max_velocity_error"] == pytest.approx(2e-4, abs=1e-12)
    assert out["final_attitude_error"] == pytest.approx(angle, rel=1e-8)  # atan2 of the exact half-angle
    assert out["max_momentum_error"] == 0.0
    scale = float(np.max(ref.kinetic_energy + np.abs(ref.potential_energy)))
    assert out["energy_drift"] == pytest.approx(1e-6 / scale, rel=1e-9)
    assert out["momentum_drift"] == 0.0


def test_momentum_measure_is_relative_to_the_bodies_momenta_when_the_total_is_zero():
    bodies = [BodyData("particle", 1.0, np.zeros((3, 3)))] * 2
    ref = synthetic(3, 2, 1)
    ref.v_W[:, 1] = -ref.v_W[:, 0]  # total momentum 0
    ref.linear_momentum_W[:] = 0.0
    run = SceneStates(**{k: np.array(v, copy=True) for k, v in ref.__dict__.items()})
    run.linear_momentum_W[1] = [1e-9, 0.0, 0.0]
    out = scene_measures(bodies, 1.0, run, ref, np.zeros(3))
    scale = float(np.max(2 * np.linalg.norm(ref.v_W[:, 0], axis=1)))
    assert math.isfinite(out["momentum_drift"]) and out["momentum_drift"] == pytest.approx(1e-9 / scale, rel=1e-9)


@pytest.mark.parametrize("method, limit", [("splitting_dlm", 2.0), ("exact_flow_kick", 2.0),
                                           ("semi_implicit_euler", 2.0), ("rk4", 2.0 * math.sqrt(2.0))])
def test_oscillator_stability_limits(method, limit):
    # leapfrog and symplectic Euler: tr M = 2 - (h omega)^2, stable iff h omega <= 2; RK4 on i y:
    # |R|^2 = 1 - y^6/72 + y^8/576 <= 1 iff y <= 2 sqrt(2). Inside, |eig| = 1 up to the rounding of a 2x2
    # eigenvalue (1e-12); 1 % beyond, the growth is clearly above 1
    assert oscillator_growth(method, 0.99 * limit, 1.0, 0.0) <= 1.0 + 1e-12
    assert oscillator_growth(method, 1.01 * limit, 1.0, 0.0) > 1.0 + 1e-3


def test_a_stiff_spring_at_a_huge_step_warns():
    scene, initial = oscillator()
    modes = scene_modes(scene, initial)
    assert any(k == pytest.approx(OMEGA**2) for _, k, _ in modes)
    assert scene_stability_message("rk4", 0.5 / OMEGA, 100, scene, initial) is None
    assert "beyond its stability limit" in scene_stability_message("rk4", 3.0 / OMEGA, 100, scene, initial)
    with pytest.warns(StabilityWarning, match="rk4"):
        result = tradeoff(scene, initial=initial, horizon=30.0, methods=["rk4"], dts=[3.0 / OMEGA], progress=False)
    assert result.rows[0]["stability"]


def test_default_steps_start_at_dt_times_the_fastest_rate_one():
    from rigiddyn.scene_precision import scene_case

    scene, initial = oscillator()
    case = scene_case(scene, initial, 100.0)
    # eight halvings from dt omega = 1 (the spring is the fastest mode; horizon / 16 is longer)
    assert case.default_dts() == pytest.approx([1.0 / OMEGA / 2**j for j in range(8)], rel=1e-15)
    short = scene_case(scene, initial, 1.0)  # horizon / 16 shorter than 1 / omega
    assert short.default_dts()[0] == pytest.approx(1.0 / 16, rel=1e-15)


def test_attitude_angle_is_the_geodesic_angle_of_quaternions_of_any_norm():
    """The attitude error of a run compares quaternions of any norm (an unnormalising method's drift, a
    blow-up's 1e200) and either sign: the angle of the unit ones, SciPy's (r_a.inv() * r_b).magnitude();
    a zero quaternion has no attitude (nan)."""
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(3)
    q_a, q_b = rng.normal(size=(20, 4)), rng.normal(size=(20, 4))
    scale = np.geomspace(1e-3, 1e200, 20)[:, None]
    angle = attitude_angle(q_a * scale, -0.5 * q_b)
    expected = (Rotation.from_quat(q_a).inv() * Rotation.from_quat(q_b)).magnitude()
    # both 2 atan2(|d_xyz|, |d_w|) of unit quaternions, each rounded a few times: a few ulps of pi
    np.testing.assert_allclose(angle, expected, rtol=0, atol=1e-14)
    assert angle.shape == (20,) and np.isnan(attitude_angle(np.zeros(4), q_b[0]))
