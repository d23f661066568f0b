"""Stability at the extremes on scenes, fast subset (the full matrix: bench/python/bench_extremes.py, its
scene table in docs/extremes.md).

Documented behaviour asserted for every method of methods() on every scene case:
1. a method the scene cannot run is refused when compiling (ValueError with the reason), never run;
2. no NaN or Inf returned silently: either every recorded value is finite, or the run says `diverged`
   and simulate warned (RuntimeWarning);
3. a run that rigiddyn.stability does not warn about for the scene (scene_stability_message: the
   elements' linear modes) does not diverge;
4. the fastest linear mode of the scene is found: the stiff spring's omega, the light end of the mass
   chain sqrt(k (1/m0 + 1/m1)) (and, joined at the faces of cubes, the light cube's rotation
   k (s/2)^2 / (m0 s^2 / 6)), the softened pair's G M / eps^3 at zero separation;
5. methods that keep unit |q| keep ||q| - 1| at round-off on the rigid chain while stable;
6. the models of bodies about a fixed point, moving frames and variable mass run the same matrix (the
   shipped pendulum, heavy_top, foucault and rocket, the pendulum next to its separatrix, the heavy top at
   large dt |w| and pinned far from its centre of mass, a rocket burning 99 % of its mass, free particles in
   a fast carousel): 1-3 hold, a pivot far from the centre of mass warns (digits of I_C lost) and the mass
   never goes non-positive.
"""

import math
import warnings

import numpy as np
import pytest
import rigiddyn
from rigiddyn.stability import scene_modes, scene_stability_message

METHODS = {m["name"]: m for m in rigiddyn.methods()}


def stiff_spring(omega=1e3):
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0), name="mass")
    scene.add(rigiddyn.SpringDamper(body_a=0, stiffness=omega**2))
    return scene, [rigiddyn.ParticleState(p_W=(1e-3, 0.0, 0.0))]


def encounter(softening):
    scene = rigiddyn.Scene()
    for name in ("a", "b"):
        scene.add_body(rigiddyn.Particle(1.0), name=name)
    scene.add(rigiddyn.MutualGravity(G=1.0, softening=softening))
    return scene, [rigiddyn.ParticleState(p_W=(-1.0, -5e-4, 0.0), v_W=(0.5, 0.0, 0.0)),
                   rigiddyn.ParticleState(p_W=(1.0, 5e-4, 0.0), v_W=(-0.5, 0.0, 0.0))]


def mass_chain():
    scene = rigiddyn.Scene()
    for i, m in enumerate((1e-6, 1.0, 1e6)):
        scene.add_body(rigiddyn.Particle(m), name=f"m{i}")
    for i in range(2):
        scene.add(rigiddyn.SpringDamper(body_a=i, body_b=i + 1, stiffness=1.0, rest_length=1.0))
    return scene, [rigiddyn.ParticleState(p_W=(-1e-3, 0.0, 0.0)), rigiddyn.ParticleState(p_W=(1.0, 0.0, 0.0)),
                   rigiddyn.ParticleState(p_W=(2.0, 0.0, 0.0))]


def rigid_chain():
    """Cubes of 1e-6, 1, 1e6 kg (side 0.1 m) joined face to face; the light one moved to turn it."""
    scene = rigiddyn.Scene()
    for i, m in enumerate((1e-6, 1.0, 1e6)):
        scene.add_body(rigiddyn.RigidBody(m, np.eye(3) * m * 0.1**2 / 6.0), name=f"cube{i}")
    for i in range(2):
        scene.add(rigiddyn.SpringDamper(body_a=i, point_a_B=(0.05, 0.0, 0.0), body_b=i + 1, point_b=(-0.05, 0.0, 0.0),
                                        stiffness=1.0, rest_length=0.9))
    return scene, [rigiddyn.RigidBodyState(p_W=(-1e-3, 1e-3, 0.0)), rigiddyn.RigidBodyState(p_W=(1.0, 0.0, 0.0)),
                   rigiddyn.RigidBodyState(p_W=(2.0, 0.0, 0.0))]


def shipped(name):
    scene, initial, _ = rigiddyn.load_scene(name)
    return scene, initial


def pendulum(theta, omega=0.0):
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedPlanarBody(1.0, 1.0 / 12.0, (0.0, -0.5)), name="rod")
    scene.add(rigiddyn.UniformGravity(g_W=(0.0, -9.81, 0.0)))
    return scene, [rigiddyn.PivotedPlanarBodyState(theta=theta, omega=omega)]


def far_pivot(distance):
    """A symmetric top pinned `distance` [m] from its centre of mass on its axis, 100 rad/s, tilted 30 deg."""
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.PivotedBody(rigiddyn.RigidBody(1.0, np.diag([0.004, 0.004, 0.006])), (0.0, 0.0, distance)),
                   name="top")
    scene.add(rigiddyn.UniformGravity())
    half = math.radians(15.0)
    return scene, [rigiddyn.PivotedBodyState(q_WB=(math.sin(half), 0.0, 0.0, math.cos(half)), w_B=(0.0, 0.0, 100.0))]


def carousel(rate=1.0):
    scene = rigiddyn.Scene()
    for i in range(2):
        scene.add_body(rigiddyn.Particle(1.0 + i), name=f"p{i}")
    scene.frame = rigiddyn.SceneFrame.rotating((0.3, 0.4, 1.0), rate)
    return scene, [rigiddyn.ParticleState(p_W=(1.0, 0.5, 0.0), v_W=(0.1, 0.0, 0.2)),
                   rigiddyn.ParticleState(p_W=(2.0, 0.5, -0.2), v_W=(0.1, -0.3, 0.2))]


FAR = 1e4 * math.sqrt(0.004)  # 1e4 transverse radii of gyration: log10(m d^2 / I_min) = 8 digits lost

# (case id, (scene, initial), dt [s], steps)
CASES = [
    ("stiff_spring_dtw_0.1", stiff_spring(), 1e-4, 300),
    ("stiff_spring_dtw_1.9", stiff_spring(), 1.9e-3, 300),
    ("stiff_spring_dtw_3", stiff_spring(), 3e-3, 300),
    ("stiff_spring_dtw_10", stiff_spring(), 1e-2, 300),
    ("encounter_unsoftened", encounter(0.0), 1e-3, 4000),
    ("encounter_softened", encounter(0.05), 1e-3, 4000),
    ("mass_chain_dtw_0.1", mass_chain(), 1e-4, 300),
    ("mass_chain_dtw_10", mass_chain(), 1e-2, 300),
    ("rigid_chain_dtw_0.12", rigid_chain(), 1e-4, 300),
    ("rigid_chain_dtw_12", rigid_chain(), 1e-2, 300),
    ("pendulum_shipped", shipped("pendulum"), 1e-3, 300),
    ("pendulum_separatrix", pendulum(math.pi - 1e-6), 1e-3, 300),
    ("heavy_top_shipped", shipped("heavy_top"), 2e-4, 300),
    ("heavy_top_dtw_2", far_pivot(0.1), 2e-2, 300),
    ("heavy_top_far_pivot", far_pivot(FAR), 2e-3, 300),
    ("foucault_shipped", shipped("foucault"), 2e-2, 300),
    ("rocket_to_1_percent", shipped("rocket"), 99.0 / 300, 300),
    ("carousel_dtw_0.5", carousel(), 0.5, 300),
]


def run_case(scene, initial, method, dt, steps):
    """(result or the refusal's ValueError, warnings raised)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            model = scene.compile(method=method)
        except ValueError as refusal:
            return refusal, caught
        result = rigiddyn.simulate(model, initial, dt, steps, method, record_every=max(1, steps // 100))
    return result, caught


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("case, scene_and_initial, dt, steps", CASES, ids=[c[0] for c in CASES])
def test_documented_behaviour(case, scene_and_initial, dt, steps, method):
    scene, initial = scene_and_initial
    result, caught = run_case(scene, initial, method, dt, steps)
    if isinstance(result, ValueError):  # 1. refused with its reason (exact: a scene with forces)
        assert str(result).startswith("method: ") and method in str(result)
        return
    arrays = [np.asarray(getattr(result, k)) for k in ("t", "p_W", "v_W", "total_energy", "linear_momentum_W",
                                                        "pivot_reaction_W", "mass")]
    finite = all(np.all(np.isfinite(a)) for a in arrays)
    warned_runtime = any(issubclass(w.category, RuntimeWarning) for w in caught)
    assert finite or (result.diverged and warned_runtime), case  # 2.
    if scene_stability_message(method, dt, steps, scene, initial) is None:  # 3.
        assert not result.diverged, f"{case} / {method}: diverged without a stability warning"
        q = np.asarray(result.q_WB)
        if case.startswith("rigid") and any(k in METHODS[method]["conserves"] for k in ("unit |q|", "SO(3)")):
            # 5. renormalised or exact rotations every step: a few ulps per step, an unbiased walk over
            # 300 steps stays within 100 eps
            assert np.max(np.abs(np.linalg.norm(q, axis=2) - 1.0)) <= 100 * np.finfo(float).eps, case
    if finite:  # 6. the rocket keeps a positive mass to the end (1 % of it left)
        assert np.all(np.asarray(result.mass) > 0.0), case
    if case == "heavy_top_far_pivot":  # 6. the digits lost are said
        assert any("keeps only" in str(w.message) for w in caught), case


def fastest(scene, initial):
    return max(math.sqrt(abs(k)) + gamma for _, k, gamma in scene_modes(scene, initial))


def test_the_fastest_modes_are_found():
    # each a few roundings of a square root: 1e-12 relative
    assert fastest(*stiff_spring(1e3)) == pytest.approx(1e3, rel=1e-12)
    assert fastest(*mass_chain()) == pytest.approx(math.sqrt(1e6 + 1.0), rel=1e-12)
    assert fastest(*rigid_chain()) == pytest.approx(math.sqrt(0.05**2 / (1e-6 * 0.1**2 / 6.0)), rel=1e-12)
    scene, initial = encounter(0.05)
    at_rest = [rigiddyn.ParticleState(p_W=(0.0, 0.0, 0.0)), rigiddyn.ParticleState(p_W=(0.0, 0.0, 0.0))]
    # softened pair at zero separation: H = G (m_a + m_b) / eps^3 in every direction
    assert fastest(scene, at_rest) == pytest.approx(math.sqrt(2.0 / 0.05**3), rel=1e-12)
