"""tradeoff on a scene that is a closed form's case measures the error against that closed form
(rigiddyn.scene_precision.exact_reference), says which, and the error falls with the method's order:
- one pivoted planar body under uniform gravity: CompoundPendulumSolution;
- one symmetric pivoted body, centre of mass on its axis, under uniform gravity: LagrangeTopSolution;
- one particle with a constant mass rate, one thrust, uniform gravity: ConstantThrustSolution;
- free particles in a frame turning at a constant rate: RotatingFrameFreeParticle;
any other scene (the Foucault pendulum, an unsymmetric top, a second body, another element, a mass
rate given as a function, a frame with forces): none, the Richardson reference as before."""

import math
import warnings

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn.__main__ import main
from rigiddyn.scene_file import load_scene
from rigiddyn.scene_precision import exact_reference, scene_case
from rigiddyn.stability import StabilityWarning


def rod(theta=2.0, omega=0.0, extra=()):
    """A 1 m, 1 kg rod pinned at one end, under gravity along -y (and `extra` elements)."""
    scene = rd.Scene()
    scene.add_body(rd.PivotedPlanarBody(1.0, 1.0 / 12.0, (0.0, -0.5)), name="rod")
    scene.add(rd.UniformGravity(g_W=(0.0, -9.81, 0.0)))
    for e in extra:
        scene.add(e)
    return scene, [rd.PivotedPlanarBodyState(theta=theta, omega=omega)]


def top(inertia=(0.004, 0.004, 0.006), c=(0.0, 0.0, 0.1)):
    """A 1 kg top pinned at O = 0, spinning at 50 rad/s, tilted 0.4 rad, under gravity."""
    scene = rd.Scene()
    scene.add_body(rd.PivotedBody(rd.RigidBody(1.0, np.diag(inertia)), c), name="top")
    scene.add(rd.UniformGravity())
    return scene, [rd.PivotedBodyState(q_WB=(math.sin(0.2), 0.0, 0.0, math.cos(0.2)), w_B=(0.0, 0.0, 50.0))]


def rocket(rate=-2.0, thrusts=1):
    """A 200 kg particle burning `rate` kg/s at 2500 m/s, under gravity."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(200.0), name="rocket", mass_flow=rd.MassFlow(rate=rate))
    scene.add(rd.UniformGravity())
    for _ in range(thrusts):
        scene.add(rd.Thrust(body=0, u_rel=(0.0, 0.0, -2500.0), frame="world"))
    return scene, [rd.ParticleState(v_W=(50.0, 0.0, 0.0))]


def carousel(n=2, gravity=False):
    """n free particles seen from a frame turning at 0.5 rad/s about (0.3, 0.4, 1)."""
    scene = rd.Scene()
    for i in range(n):
        scene.add_body(rd.Particle(1.0 + i), name=f"p{i}")
    if gravity:
        scene.add(rd.UniformGravity())
    scene.frame = rd.SceneFrame.rotating((0.3, 0.4, 1.0), 0.5)
    states = [rd.ParticleState(p_W=(1.0 + i, 0.5, -0.2 * i), v_W=(0.1, -0.3 * i, 0.2)) for i in range(n)]
    return scene, states


def name_of(scene_and_initial):
    reference = exact_reference(*scene_and_initial)
    return None if reference is None else reference.name


def shipped(name):
    scene, initial, _ = load_scene(name)
    return scene, initial


@pytest.mark.parametrize("case, expected", [
    (lambda: shipped("pendulum"), "CompoundPendulumSolution"),
    (lambda: shipped("heavy_top"), "LagrangeTopSolution"),
    (lambda: shipped("rocket"), "ConstantThrustSolution"),
    (lambda: shipped("foucault"), None),  # a pinned body in a rotating frame: no closed form here
    (lambda: rod(), "CompoundPendulumSolution"),
    (lambda: rod(extra=[rd.Drag(linear=0.1)]), None),
    (lambda: top(), "LagrangeTopSolution"),
    (lambda: top(inertia=(0.004, 0.005, 0.006)), None),  # I_O not symmetric about the axis through C
    (lambda: top(c=(0.1, 0.0, 0.0)), None),  # symmetric about z, but C off that axis
    (lambda: rocket(), "ConstantThrustSolution"),
    (lambda: rocket(thrusts=2), None),
    (lambda: rocket(rate=lambda t: -2.0), None),  # not a constant rate
    (lambda: carousel(), "RotatingFrameFreeParticle"),
    (lambda: carousel(gravity=True), None),
    (lambda: shipped("kepler"), None),
], ids=["pendulum", "heavy_top", "rocket", "foucault", "rod", "rod+drag", "top", "unsymmetric top", "C off axis",
        "rocket2", "two thrusts", "rate(t)", "carousel", "carousel+gravity", "kepler"])
def test_the_reference_is_the_closed_form_whose_case_the_scene_is(case, expected):
    assert name_of(case()) == expected


def test_two_pinned_bodies_have_no_closed_form():
    scene, initial = rod()
    scene.add_body(rd.PivotedPlanarBody(1.0, 0.1, (0.0, -0.3)), name="rod2")
    assert exact_reference(scene, initial + [rd.PivotedPlanarBodyState(theta=0.1)]) is None


def _run(scene, initial, dt, steps, method="rk4"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.SceneCompatibilityWarning)
        return rd.simulate(scene, initial, dt=dt, steps=steps, method=method, record_every=steps // 8)


@pytest.mark.parametrize("case, horizon, steps", [
    (lambda: rod(), 3.0, 600), (lambda: top(), 0.5, 1000), (lambda: rocket(), 60.0, 200),
    (lambda: carousel(), 10.0, 200)], ids=["pendulum", "top", "rocket", "carousel"])
def test_the_reference_states_are_the_motion_the_core_integrates(case, horizon, steps):
    """RK4 at h and h/2: in the asymptotic range its error at h is (16/15) |y_h - y_{h/2}| to O(h^5)
    (Richardson). The exact reference must agree with that estimate within a factor 2 (a wrong angle
    convention, frame or mass in the reference would make its difference O(1) instead), in every state
    and total the measures use."""
    scene, initial = case()
    case_ = scene_case(scene, initial, horizon)
    coarse, fine = (case_.states(_run(scene, initial, horizon / n, n)) for n in (steps, 2 * steps))
    exact = case_.exact.states(coarse.t)
    for name in ("p_W", "v_W", "w_B", "kinetic_energy", "potential_energy", "linear_momentum_W", "angular_momentum_W"):
        error = np.max(np.abs(getattr(coarse, name) - getattr(exact, name)))
        estimate = 16.0 / 15.0 * np.max(np.abs(getattr(coarse, name) - getattr(fine, name)))
        scale = np.max(np.abs(getattr(exact, name)))
        floor = 1e-13 * max(scale, 1.0)  # both at round-off: nothing to compare
        assert error <= 2.0 * estimate + floor, (name, error, estimate)
        assert error >= 0.5 * estimate - floor, (name, error, estimate)
    # attitude (the angle between the attitudes, rd.angular_distance): the same estimate
    error = np.max(rd.angular_distance(coarse.q_WB.reshape(-1, 4), exact.q_WB.reshape(-1, 4)))
    estimate = 16.0 / 15.0 * np.max(rd.angular_distance(coarse.q_WB.reshape(-1, 4), fine.q_WB.reshape(-1, 4)))
    assert 0.5 * estimate - 1e-13 <= error <= 2.0 * estimate + 1e-13, ("q_WB", error, estimate)


def _sweep(source, methods, dts, horizon):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", StabilityWarning)
        return rd.tradeoff(source, methods=methods, dts=dts, horizon=horizon, progress=False)


@pytest.mark.parametrize("source, horizon, dts", [
    ("pendulum", 4.5, [0.01, 0.005, 0.0025, 0.00125]),
    ("heavy_top", 0.3, [0.002, 0.001, 0.0005, 0.00025]),
    ("rocket", 60.0, [2.0, 1.0, 0.5, 0.25]),
], ids=["pendulum", "heavy_top", "rocket"])
def test_the_error_against_the_exact_reference_falls_with_the_method_s_order(source, horizon, dts):
    result = _sweep(source, ["rk4", "implicit_midpoint"], dts, horizon)
    reference = exact_reference(*shipped(source)).name
    assert {r["reference"] for r in result.rows} == {f"exact: {reference}"}
    assert all(r["reference_error"] == 0.0 for r in result.rows)
    for method, order in (("rk4", 4), ("implicit_midpoint", 2)):
        observed = [r["observed_order"] for r in sorted(result.rows, key=lambda r: -r["dt"])
                    if r["method"] == method and math.isfinite(r["observed_order"])]
        # the slope between h and h/2 in the asymptotic range is order + c h (the next term of the error),
        # the deviation halving with h: within 0.5 at the coarsest pairs (the pendulum at 120 degrees has
        # the largest c, 0.4 at h = 0.01 s), within 0.1 at the finest pair
        assert len(observed) >= 2 and all(abs(p - order) <= 0.5 for p in observed), (method, observed)
        assert abs(observed[-1] - order) <= 0.1, (method, observed)
    table = " ".join(result.to_table().split())  # wrapped at 100 columns
    assert f"the exact solution ({reference})" in table
    assert f"reference: the exact solution rigiddyn.{reference}" in table


def test_a_scene_without_a_closed_form_keeps_the_richardson_reference():
    scene, initial = rod(extra=[rd.Drag(linear=0.1)])
    result = _sweep((scene, initial, None), ["rk4"], [0.02, 0.01], 1.0)
    assert all(r["reference"].endswith("richardson(rk4)") or "richardson" in r["reference"] for r in result.rows)


def test_the_command_line_says_which_reference_it_used(capsys):
    assert main(["tradeoff", "pendulum", "--methods", "rk4", "--dts", "0.02,0.01", "--horizon", "2.25",
                 "--no-progress"]) == 0
    out = " ".join(capsys.readouterr().out.split())  # the report wraps at 100 columns
    assert "vs the exact solution (CompoundPendulumSolution)" in out
    assert "rigiddyn.CompoundPendulumSolution (one pivoted planar body under uniform gravity)" in out


def test_a_pinned_body_s_swing_sets_the_default_steps():
    """The default steps start at dt rho = 1 with rho the pendulum's swing rate sqrt(m g d / I), I the
    moment about O about an axis normal to p_OC_B (not about p_OC_B itself, which gravity cannot turn)."""
    from rigiddyn.scene_precision import pendulum_rates

    scene, _ = shipped("foucault")
    bob = scene.bodies[0]
    inertia = 0.448 + 28.0 * 67.0**2  # I_C + m d^2 about a horizontal axis [kg m^2]
    # a square root of a few products: 1e-14 relative
    assert pendulum_rates(scene) == [pytest.approx(math.sqrt(28.0 * 9.81 * 67.0 / inertia), rel=1e-14)]
    assert bob.mass == 28.0
    scene, _ = rod()
    assert pendulum_rates(scene) == [pytest.approx(math.sqrt(9.81 * 0.5 / (1.0 / 3.0)), rel=1e-14)]
