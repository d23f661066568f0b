"""rigiddyn.stability on bodies about a fixed point and moving frames: a pinned body's spin (Euler's equations
about O with I_O) and swing (sqrt(m g d / I_O)), and a rotating frame's centrifugal and Coriolis terms (a turn
of the velocity at 2 |Omega|). Each rule is checked three ways: its rate against the closed form, its warning
where the run really grows or diverges, and its silence where the run stays bounded."""

import math
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn.stability import (
    frame_modes,
    oscillator_growth,
    pivot_swing_modes,
    scene_modes,
    scene_stability_message,
)

METHODS = [m["name"] for m in rigiddyn.methods()]
G = 9.81


def pendulum(theta=0.3, omega=0.0):
    """A 1 m, 1 kg rod pinned at one end (I_C = 1/12 kg m^2, d = 0.5 m), gravity along -y."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedPlanarBody(1.0, 1.0 / 12.0, (0.0, -0.5)), name="rod")
    scene.add(rigiddyn.UniformGravity(g_W=(0.0, -G, 0.0)))
    return scene, [rigiddyn.PivotedPlanarBodyState(theta=theta, omega=omega)]


def heavy_top(spin=100.0):
    """The shipped heavy top: I_C = diag(0.004, 0.004, 0.006), c = (0, 0, 0.1) m, tilted 30 deg."""
    scene = rigiddyn.Scene()
    body = rigiddyn.RigidBody(1.0, np.diag([0.004, 0.004, 0.006]))
    scene.add_body(rigiddyn.PivotedBody(body, (0.0, 0.0, 0.1)), name="top")
    scene.add(rigiddyn.UniformGravity())
    half = math.radians(15.0)
    return scene, [rigiddyn.PivotedBodyState(q_WB=(math.sin(half), 0.0, 0.0, math.cos(half)), w_B=(0.0, 0.0, spin))]


def carousel(rate=1.0):
    """Two free particles seen from a frame turning at `rate` [rad/s] about (0.3, 0.4, 1)."""
    scene = rigiddyn.Scene()
    for i in range(2):
        scene.add_body(rigiddyn.Particle(1.0 + i), name=f"p{i}")
    scene.frame = rigiddyn.SceneFrame.rotating((0.3, 0.4, 1.0), rate)
    return scene, [rigiddyn.ParticleState(p_W=(1.0, 0.5, 0.0), v_W=(0.1, 0.0, 0.2)),
                   rigiddyn.ParticleState(p_W=(2.0, 0.5, -0.2), v_W=(0.1, -0.3, 0.2))]


def run(scene, initial, method, dt, steps):
    """simulate's SceneResult of the scene compiled for `method` (every state recorded)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = rigiddyn.simulate(scene.compile(method=method), initial, dt, steps, method, record_every=1)
    return result


def growth(result):
    """max |state| / initial |state| over the run (inf once diverged): positions and velocities."""
    if result.diverged:
        return math.inf
    y = np.concatenate([np.asarray(result.p_W).reshape(len(result.t), -1),
                        np.asarray(result.v_W).reshape(len(result.t), -1)], axis=1)
    return float(np.max(np.linalg.norm(y, axis=1)) / np.linalg.norm(y[0]))


# --- the rates -----------------------------------------------------------------------------------------


def test_the_compound_pendulum_swing_is_m_g_d_over_I_O():
    scene, initial = pendulum()
    (label, k, gamma), = scene_modes(scene, initial)
    # I_O = I_C + m d^2 = 1/12 + 1/4 = 1/3: k = m g d / I_O; a few roundings: 1e-14 relative
    assert k == pytest.approx(G * 0.5 / (1.0 / 3.0), rel=1e-14) and gamma == 0.0
    assert "swing of body 0" in label


def test_the_3d_swing_is_the_largest_generalised_eigenvalue_of_gravity_and_I_O():
    # symmetric top, c on its axis: m g d / I_O,1 (I_O,1 = 0.004 + 0.1^2 = 0.014)
    scene, initial = heavy_top()
    (_, k, _), = scene_modes(scene, initial)
    assert k == pytest.approx(G * 0.1 / 0.014, rel=1e-13)  # a 3x3 inverse and eigvalsh: ~10 roundings
    # an asymmetric body pinned off its principal axes: the largest eigenvalue of I_O^-1 K, K = m |g| d P
    # (P the projector normal to c), computed here by scipy's generalised symmetric solver
    from scipy.linalg import eigh

    rng = np.random.default_rng(12)
    rotation, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    inertia_com = rotation @ np.diag([1.0, 2.0, 2.5]) @ rotation.T
    inertia_com = (inertia_com + inertia_com.T) / 2
    c = rng.normal(size=3)
    body = rigiddyn.PivotedBody(rigiddyn.RigidBody(2.0, inertia_com), c)
    g = np.array([0.3, -1.0, -9.0])
    (_, k, _), = pivot_swing_modes("g", [body], [0], g)
    stiffness = 2.0 * np.linalg.norm(g) * np.linalg.norm(c) * (np.eye(3) - np.outer(c, c) / (c @ c))
    expected = float(np.max(eigh(stiffness, np.asarray(body.inertia_O))[0]))
    # both are backward-stable symmetric eigen-solves of condition ~ cond(I_O) < 1e2: 1e-12 relative
    assert k == pytest.approx(expected, rel=1e-12)


def test_a_body_pinned_at_its_centre_of_mass_or_free_has_no_swing():
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedBody(rigiddyn.RigidBody(1.0, np.diag([1.0, 2.0, 3.0])), (0.0, 0.0, 0.0)))
    scene.add_body(rigiddyn.RigidBody(1.0, np.diag([1.0, 2.0, 3.0])))
    scene.add(rigiddyn.UniformGravity())
    assert scene_modes(scene, [rigiddyn.PivotedBodyState(), rigiddyn.RigidBodyState()]) == []


def test_the_frame_mode_is_the_centrifugal_and_coriolis_turn():
    scene, _ = carousel(0.7)
    (label, k, gamma), = frame_modes(scene)
    assert k == pytest.approx(-0.49, rel=1e-15) and gamma == pytest.approx(1.4j, rel=1e-15)
    assert "rotating frame" in label
    assert frame_modes(carousel(0.0)[0]) == [] and frame_modes(pendulum()[0]) == []
    earth = rigiddyn.Scene()
    earth.add_body(rigiddyn.Particle(1.0))
    earth.frame = rigiddyn.SceneFrame.earth(math.radians(48.85))
    (_, k, _), = frame_modes(earth)
    assert k == pytest.approx(-7.2921159e-5**2, rel=1e-14)


def test_the_turn_maps_of_the_explicit_methods():
    # x'' = W^2 x - 2 i W x' (k = -W^2, gamma = 2 i W): A's eigenvalues are -i W twice. Explicit Euler maps
    # them to 1 - i h W: growth sqrt(1 + (h W)^2) per step (the eigenvalues of a defective 2x2 matrix are
    # found to ~sqrt(eps) ~ 1e-8: that tolerance)
    for hw in (0.1, 0.5, 2.0):
        assert oscillator_growth("explicit_euler", hw, -1.0, 2j) == pytest.approx(math.sqrt(1 + hw**2), abs=1e-7)
        # RK4: |R(-i h W)| <= 1 up to h W = 2 sqrt(2); implicit midpoint (Cayley) and the Strang splittings
        # with their exact Coriolis kick (drifts: the centrifugal term resolved while h W < 2): no growth
        for method in ("rk4", "implicit_midpoint", "splitting_dlm", "exact_flow_kick"):
            assert oscillator_growth(method, hw, -1.0, 2j) <= 1.0 + 1e-7, (method, hw)
    # Yoshida's triple jump: substeps up to 1.70 h, so bounded at h W = 0.5 (1.70 x 0.5 < 2), not at 2
    assert oscillator_growth("splitting_dlm_yoshida4", 0.5, -1.0, 2j) <= 1.0 + 1e-7
    assert oscillator_growth("splitting_dlm_yoshida4", 2.0, -1.0, 2j) > 1.1
    # semi-implicit Euler: the kick explicit in v, growing already at h W = 0.1
    assert oscillator_growth("semi_implicit_euler", 0.1, -1.0, 2j) > 1.01


# --- warned where the run grows or diverges, silent where it stays bounded -----------------------------

STEPS = 300
# The carousel's exact motion is a straight line in W: over t = 150 s, |p| <= |p0| + |v0| t and
# |v_F| <= |v0| + |Omega| |p| bound |(p, v_F)| by 40 x its start. A method stable on the turn keeps that
# secular growth up to the O(1) factor of its phase error (measured up to 4x: 162 for RK4): BOUNDED =
# 1e3; spurious exponential growth at the rates predicted (>= 1.035 per step over 300 steps) passes
# GROWN = 1e5.
BOUNDED, GROWN = 1e3, 1e5


@pytest.mark.parametrize("method", ["explicit_euler", "semi_implicit_euler"])
def test_the_fast_heavy_top_warns_and_grows(method):
    # dt |w| = 2 (and 0.5): the spin about O (I_O = diag(0.014, 0.014, 0.006)) nutates at 57 rad/s,
    # explicit in both methods
    for dt in (2e-2, 5e-3):
        scene, initial = heavy_top()
        message = scene_stability_message(method, dt, STEPS, scene, initial)
        assert message is not None and "spin of body 0" in message, dt
        result = run(scene, initial, method, dt, STEPS)
        w = np.linalg.norm(np.asarray(result.w_B)[:, 0], axis=1)
        # the physical top keeps |w| within a few % of 100 rad/s (energy conserved); 10x is growth
        assert result.diverged or np.max(w) > 10 * 100.0, (method, dt)


@pytest.mark.parametrize("method", ["explicit_euler", "semi_implicit_euler", "semi_implicit_euler_implicit_gyroscopic"])
def test_the_fast_carousel_warns_and_grows(method):
    scene, initial = carousel()
    message = scene_stability_message(method, 0.5, STEPS, scene, initial)
    assert message is not None and "rotating frame" in message
    assert growth(run(scene, initial, method, 0.5, STEPS)) > GROWN


def test_semi_implicit_euler_grows_in_a_slow_carousel_too():
    scene, initial = carousel()
    assert scene_stability_message("semi_implicit_euler", 0.1, 1000, scene, initial) is not None
    assert growth(run(scene, initial, "semi_implicit_euler", 0.1, 1000)) > GROWN  # x1.035 per step predicted


@pytest.mark.parametrize("method", ["rk4", "rkmk4", "implicit_midpoint", "splitting_dlm", "splitting_dlm_yoshida4",
                                    "exact_flow_kick"])
def test_the_fast_carousel_is_silent_for_the_stable_methods(method):
    scene, initial = carousel()
    assert scene_stability_message(method, 0.5, 20_000, scene, initial) is None
    assert growth(run(scene, initial, method, 0.5, STEPS)) < BOUNDED


@pytest.mark.parametrize("method", [m for m in METHODS if m != "exact"])
def test_the_slow_heavy_top_and_the_shipped_scenes_are_silent(method):
    scene, initial = heavy_top()
    assert scene_stability_message(method, 2e-4, 20_000, scene, initial) is None  # dt |w| = 0.02
    for name in ("pendulum", "heavy_top", "foucault"):  # at the extremes matrix's horizon
        scene, initial, settings = rigiddyn.load_scene(name)
        assert scene_stability_message(method, settings.dt, min(settings.steps, 20_000), scene, initial) is None, name


def test_explicit_euler_over_the_shipped_foucault_hour_warns_and_grows():
    # the swing sqrt(g / L) ~ 0.38 rad/s at dt = 20 ms: x(1 + 2.9e-5) per step, ~200x over 180 000 steps
    scene, initial, settings = rigiddyn.load_scene("foucault")
    message = scene_stability_message("explicit_euler", settings.dt, settings.steps, scene, initial)
    assert message is not None and "swing of body 0" in message
    result = run(scene, initial, "explicit_euler", settings.dt, settings.steps)
    # released 3 m from the lowest point: 10x that is spurious growth (or a divergence)
    assert result.diverged or np.max(np.linalg.norm(np.asarray(result.p_W)[:, 0, :2], axis=1)) > 30.0


def test_the_swing_warns_explicit_euler_and_a_splitting_beyond_its_limit():
    scene, initial = pendulum(theta=0.05)
    omega0 = math.sqrt(G * 0.5 / (1.0 / 3.0))
    # explicit Euler on x'' = -omega0^2 x: growth sqrt(1 + (h omega0)^2) per step: 1.018 at h = 0.05 s
    message = scene_stability_message("explicit_euler", 0.05, STEPS, scene, initial)
    assert message is not None and "swing of body 0" in message
    # the rod's centre is at x = 0.5 sin(theta): released at 0.05 rad (x = 0.025 m), 10x is growth
    x = np.asarray(run(scene, initial, "explicit_euler", 0.05, STEPS).p_W)[:, 0, 0]
    assert np.max(np.abs(x)) > 0.25
    # Strang (kick-drift-kick) is stable for h omega0 < 2: silent at 1.5, warned at 2.3
    assert scene_stability_message("splitting_dlm", 1.5 / omega0, STEPS, scene, initial) is None
    assert scene_stability_message("splitting_dlm", 2.3 / omega0, STEPS, scene, initial) is not None
    x = np.asarray(run(scene, initial, "splitting_dlm", 1.5 / omega0, STEPS).p_W)[:, 0, 0]
    assert np.max(np.abs(x)) < 0.05  # bounded: within 2x its start


def test_a_spring_on_a_pinned_body_turns_it_about_its_pivot():
    # the rod pinned at one end (I_O = 1/3 kg m^2), a spring from its free tip (1 m from O) to the world:
    # the point's inverse mass is |arm|^2 / I_O = 3 /kg, not 1/m (a pinned body does not translate)
    scene, initial = pendulum()
    scene.add(rigiddyn.SpringDamper(body_a=0, point_a_B=(0.0, -0.5, 0.0), stiffness=10.0, damping=0.2))
    spring = [(k, gamma) for label, k, gamma in scene_modes(scene, initial) if "spring" in label]
    assert spring == [pytest.approx((30.0, 0.6), rel=1e-14)]  # a few roundings
    # a sphere (I_C = 0.4 kg m^2) hung 1 m below O, the spring at its centre: turns about an axis normal
    # to the arm, I_O = 0.4 + 1 = 1.4 (not the axial 0.4: no torque about the arm)
    ball = rigiddyn.Scene()
    ball.add_body(rigiddyn.PivotedBody(rigiddyn.RigidBody(1.0, 0.4 * np.eye(3)), (0.0, 0.0, -1.0)))
    ball.add(rigiddyn.SpringDamper(body_a=0, stiffness=7.0))
    (_, k, _), = scene_modes(ball, [rigiddyn.PivotedBodyState()])
    assert k == pytest.approx(7.0 / 1.4, rel=1e-13)  # a 3x3 inverse and eigvalsh: ~10 roundings
