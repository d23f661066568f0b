"""Scene invariants of rigiddyn's runs: the work–energy equation T2 − T1 = Σ work of every force model (Craig,
"Work-Energy Equation") and the potential's change = −(work of the conservative models), within RK4's error
bound, on a scene with every force model and on every shipped scene; N-body total linear momentum (internal
forces, Rigid-body notes (4.49) and (4.36)) to round-off with five methods, and angular momentum to round-off
with the splittings."""

import warnings

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn.scene_file import example_scenes

from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

from _scene_core import EPS, every_model_scene, run


CONSERVATIVE = ("UniformGravity", "PointMassGravity", "MutualGravity", "GravityGradient", "SpringDamper")


def residual(result):
    """(T − T0) − Σ_e work_e at the last record [J]."""
    return result.kinetic_energy[-1] - result.kinetic_energy[0] - np.sum(result.work[-1])


def test_work_energy_with_every_force_model_within_rk4s_error_bound():
    """T2 − T1 = Σ work of every element over 1 s (Craig's work–energy equation: T − Σ W is a first
    integral of the scene's extended system, dT/dt = Σ power). RK4 conserves it only up to its truncation
    error C h^p, p ≥ 4 (one error constant for the whole run): the runs at h = 0.02 s and h/2 give the
    bound |r(h/2)| ≤ |r(h) − r(h/2)|/(2^p − 1) ≤ |r(h) − r(h/2)|/15 (Richardson), to which we add the
    round-off of 100 steps × 16 eps × the energy scale and a factor 2 for the next order's share (h L ≤ 0.1
    here). A missing or wrong power in any element gives an O(1) residual that does not shrink: caught."""
    scene, y0 = every_model_scene()
    coarse = run(scene, y0, 0.02, 50)
    fine = run(scene, y0, 0.01, 100)
    scale = np.max(np.abs(fine.kinetic_energy)) + np.sum(np.abs(fine.work))
    r_coarse, r_fine = residual(coarse), residual(fine)
    assert abs(r_fine) <= 2 * abs(r_coarse - r_fine) / 15 + 100 * 16 * EPS * scale
    assert abs(r_fine) <= 1e-6 * scale  # and the bound is small: the test would see an O(h) or O(1) error


def test_potential_change_is_minus_the_work_of_the_conservative_models():
    """Without dampers and drag and loads: V2 − V1 = −Σ work of the conservative elements (each element's
    work is ∫ power = −∫ dV_e), within RK4's error bound (Richardson, as above); and T + V is conserved to
    the same bound."""
    scene, y0 = every_model_scene()
    elements = [e._replace(params={**e.params, "damping": 0.0}) if e.kind == "SpringDamper" else e
                for e in scene.elements if e.kind in CONSERVATIVE]
    scene = scene._replace(elements=elements)
    y0 = ref.initial_state(scene, ref.kinematics(scene.bodies, y0))
    results = [run(scene, y0, 0.02, 50), run(scene, y0, 0.01, 100)]
    r = [(res.potential_energy[-1] - res.potential_energy[0]) + np.sum(res.work[-1]) for res in results]
    drift = [res.total_energy[-1] - res.total_energy[0] for res in results]
    scale = np.max(np.abs(results[1].kinetic_energy)) + np.sum(np.abs(results[1].work)) + np.max(
        np.abs(results[1].potential_energy))
    for coarse, fine in (r, drift):
        assert abs(fine) <= 2 * abs(coarse - fine) / 15 + 100 * 16 * EPS * scale
        assert abs(fine) <= 1e-6 * scale


def cluster(n_particles, n_rigid, seed):
    """A gravitating cluster: n_particles particles and n_rigid rigid bodies (masses 0.5–2 kg) in a 10 m box,
    speeds ≤ 0.3 m/s, mutual gravity G = 1 with softening 0.5 m (accelerations ≲ 10 m/s²), plus one
    internal spring–damper between the first two bodies."""
    rng = np.random.default_rng(seed)
    bodies = [ref.particle(m) for m in rng.uniform(0.5, 2, n_particles)]
    bodies += [ref.rigid(m, m * rng.uniform(0.2, 0.3, 3)) for m in rng.uniform(0.5, 2, n_rigid)]
    kin = [ref.Kinematics(rng.uniform(-5, 5, 3), so3.rotvec_to_quat(rng.normal(size=3)) if b.kind == "rigid" else
                          ref.IDENTITY, rng.uniform(-0.3, 0.3, 3),
                          rng.uniform(-1, 1, 3) if b.kind == "rigid" else np.zeros(3)) for b in bodies]
    elements = [ref.Element("MutualGravity", dict(G=1.0, softening=0.5, bodies=None)),
                ref.Element("SpringDamper", dict(body_a=0, point_a_B=np.zeros(3), body_b=1, point_b=np.zeros(3),
                                                 stiffness=0.5, rest_length=2.0, damping=0.1))]
    scene = ref.Scene(bodies, elements)
    return scene, ref.initial_state(scene, kin)


def momentum_scales(result, scene):
    """Σ m |v| and Σ (m |p| |v| + |I ω|) over the bodies, maxima over the records: the magnitudes whose
    round-off the momenta carry."""
    masses = np.array([b.mass for b in scene.bodies])
    inertias = np.array([np.linalg.norm(b.inertia, 2) for b in scene.bodies])
    speed = np.linalg.norm(result.v_W, axis=2)
    linear = np.max(speed @ masses)
    angular = np.max((np.linalg.norm(result.p_W, axis=2) * speed) @ masses
                     + np.linalg.norm(result.w_B, axis=2) @ inertias)
    return linear, angular


@pytest.mark.parametrize("method", ["rk4", "rkmk4", "semi_implicit_euler", "splitting_dlm", "splitting_dlm_yoshida4"])
def test_n_body_linear_momentum_to_round_off(method):
    """Internal forces only (mutual gravity, one spring–damper): Σ m v is conserved by the flow, and every
    method conserves linear invariants exactly (each stage adds h Σ f_ij with f_ji = −f_ij). Round-off per
    step: each body's update v + h f/m rounds ≤ 2 eps of m |v| per stage (and the record's sum Σ m v
    ≤ n eps of Σ m |v|); bound n_steps × 4 stages × 4 eps × Σ m |v| + n eps Σ m |v|."""
    scene, y0 = cluster(20, 3, seed=7)
    steps = 200
    with warnings.catch_warnings():  # the damper with a splitting: its compatibility warning is tested elsewhere
        warnings.simplefilter("ignore", rd.SceneCompatibilityWarning)
        result = run(scene, y0, 0.01, steps, method=method, record_every=20)
    linear_scale, _ = momentum_scales(result, scene)
    bound = (steps * 16 + len(scene.bodies)) * EPS * linear_scale
    np.testing.assert_allclose(result.linear_momentum_W, np.broadcast_to(result.linear_momentum_W[0], (11, 3)),
                               rtol=0, atol=bound)


@pytest.mark.parametrize("method, n_rigid", [("semi_implicit_euler", 0), ("splitting_dlm", 3),
                                             ("splitting_dlm_yoshida4", 3)])
@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # semi_implicit_euler's energy drifts (0.7 %): this test is about momentum
def test_n_body_angular_momentum_to_round_off_with_the_splittings(method, n_rigid):
    """Mutual gravity alone (central pair forces): a kick changes Σ p × m v by h Σ_pairs (p_i − p_j) × f_ij
    = 0, a drift by h Σ v × m v = 0, and DLM's free rotation keeps each body's R I ω (exact rotations about
    principal axes); so these methods conserve the total angular momentum about W's origin up to
    round-off: per step ≤ 4 substeps × 8 eps of Σ (m |p| |v| + |I ω|) (cross products and sums), bound
    n_steps × 32 eps × that scale. semi_implicit_euler on particles only: its explicit gyroscopic step does
    not keep a rigid body's spin. (RK4 conserves it only to O(h⁴): a quadratic invariant.)"""
    scene, y0 = cluster(20, n_rigid, seed=8)
    scene = scene._replace(elements=scene.elements[:1])
    y0 = ref.initial_state(scene, ref.kinematics(scene.bodies, y0))
    steps = 200
    result = run(scene, y0, 0.01, steps, method=method, record_every=20)
    linear_scale, angular_scale = momentum_scales(result, scene)
    np.testing.assert_allclose(result.angular_momentum_W, np.broadcast_to(result.angular_momentum_W[0], (11, 3)),
                               rtol=0, atol=steps * 32 * EPS * angular_scale)
    np.testing.assert_allclose(result.linear_momentum_W, np.broadcast_to(result.linear_momentum_W[0], (11, 3)),
                               rtol=0, atol=(steps * 16 + len(scene.bodies)) * EPS * linear_scale)


@pytest.mark.parametrize("name", example_scenes())
def test_work_energy_on_every_shipped_scene(name):
    """Each shipped scene (rigiddyn/scenes/*.toml) over its own duration with RK4 at its dt and dt/2:
    T2 − T1 = Σ work + Σ mass-flow energy (d(m v²/2)/dt = f·v + ṁ v²/2 for a body whose mass changes: the rocket;
    0 for the others) within RK4's error bound, Richardson as in the test above (|r(h/2)| ≤ 2 |r(h) − r(h/2)|/15)
    plus the round-off of n steps × 16 eps × (max T + Σ max |work| + Σ max |mass-flow energy|)."""
    scene, initial, options = rd.load_scene(name)
    residuals, scale, steps = [], 0.0, options.steps
    for dt, n in ((options.dt, steps), (options.dt / 2, 2 * steps)):
        result = rd.simulate(scene, initial, dt=dt, steps=n, method="rk4", record_every=n)
        residuals.append(residual(result) - np.sum(result.mass_flow_energy[-1]))
        scale = max(scale, np.max(np.abs(result.kinetic_energy)) + np.sum(np.max(np.abs(result.work), axis=0))
                    + np.sum(np.max(np.abs(result.mass_flow_energy), axis=0)))
    bound = 2 * abs(residuals[0] - residuals[1]) / 15 + 2 * steps * 16 * EPS * scale
    assert abs(residuals[1]) <= bound, (residuals, scale)
