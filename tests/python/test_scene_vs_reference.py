"""Scenes: the numpy reference checked against itself (every conservative force = −∇V and torque = −∂V/∂θ by
finite differences, dissipative forces dissipate, Newton's third law, a one-body scene is the one-body reference
of rigiddyn_ref.integrators), then rigiddyn's scenes against it, one
force model at a time: from random states of a particle, a planar body and two rigid bodies (principal and
full inertia), the element's power and potential at t0 and one RK4 step (positions, attitudes, velocities,
work) agree to both sides' round-off."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rigiddyn as rd

from rigiddyn_ref import dynamics as dyn
from rigiddyn_ref import integrators
from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

from _scene_core import (EPS, core_scene, core_states, every_model_scene, inertia_condition, record_state, run,
                         state_vector)

settings.register_profile("scene_reference", max_examples=8, deadline=None)
seeds = st.integers(0, 2 ** 32 - 1)


# ---------------------------------------------------------------- random scenes
def box_moments(mass, dims):
    """Principal moments of a solid box m (b² + c²)/12, ...: they satisfy the triangle inequality."""
    a, b, c = np.square(dims)
    return mass / 12.0 * np.array([b + c, a + c, a + b])


def random_bodies(rng):
    """A particle, a planar body, a rigid body with principal axes and one with a full inertia (masses
    0.5–3 kg, box inertias of sides 0.5–2 m: condition ≤ 16)."""
    m = rng.uniform(0.5, 3.0, 4)
    full = so3.rotvec_to_matrix(rng.normal(size=3))
    return [ref.particle(m[0]), ref.planar(m[1], box_moments(m[1], rng.uniform(0.5, 2, 3))[2]),
            ref.rigid(m[2], box_moments(m[2], rng.uniform(0.5, 2, 3))),
            ref.rigid(m[3], full @ np.diag(box_moments(m[3], rng.uniform(0.5, 2, 3))) @ full.T)]


def random_kinematics(rng, bodies):
    """Bodies at the corners of a square of side 2 m (jitter ≤ 0.3 m: separation ≥ 1.4 m), speeds and spins
    ≤ ~2 per s; planar bodies in the xy plane."""
    corners = np.array([[1, 1, 0], [-1, 1, 0], [-1, -1, 0], [1, -1, 0]], float)
    kin = []
    for body, corner in zip(bodies, corners):
        p, v, w = corner + rng.uniform(-0.3, 0.3, 3), rng.uniform(-1, 1, 3), rng.uniform(-2, 2, 3)
        q = so3.rotvec_to_quat(rng.normal(size=3))
        if body.kind == "particle":
            q, w = ref.IDENTITY, np.zeros(3)
        if body.kind == "planar":
            p[2], v[2], w[:2] = 0.0, 0.0, 0.0
            q = ref.rz_quat(rng.uniform(-3, 3))
        kin.append(ref.Kinematics(p, q, v, w))
    return kin


def random_load(rng, kind, frame, t_start=-np.inf, t_end=np.inf):
    """A random force and couple in `frame`, active for t_start <= t < t_end, on a body of `kind`: a particle
    takes no couple, a planar body only a force in its plane and a couple about z (rigiddyn refuses others)."""
    force, couple = rng.uniform(-2, 2, 3), rng.uniform(-1, 1, 3)
    if kind == "particle":
        couple[:] = 0.0
    if kind == "planar":
        force[2], couple[:2] = 0.0, 0.0
    return dyn.Load(force, couple, frame, t_start, t_end)


def random_elements(rng, kind, bodies):
    """One or more elements of `kind` with random parameters (forces ≲ 10 N on the random bodies). Every
    switch time of a schedule or of a wheel's ramp lies outside the compared step [0, 0.02] s; a planar body's
    points lie in its xy plane (rigiddyn refuses others)."""
    direction = rng.normal(size=3)
    far = 4.0 * direction / np.linalg.norm(direction)
    if kind == "UniformGravity":
        return [ref.Element(kind, dict(g_W=rng.uniform(-10, 10, 3), bodies=None))]
    if kind == "PointMassGravity":
        return [ref.Element(kind, dict(gm=rng.uniform(5, 50), p_W=far, softening=0.0, bodies=None)),
                ref.Element(kind, dict(gm=rng.uniform(1, 5), p_W=rng.uniform(-0.2, 0.2, 3), softening=0.7,
                                       bodies=[0, 2]))]
    if kind == "ZonalGravity":  # radius 2 m, 4 m away (R/r ≤ 0.8), strong zonal terms: ≲ 25 N
        return [ref.Element(kind, dict(gm=rng.uniform(5, 50), radius=2.0, j2=rng.uniform(-0.1, 0.1),
                                       j3=rng.uniform(-0.1, 0.1), j4=rng.uniform(-0.1, 0.1), p_W=far,
                                       pole_W=rng.normal(size=3), bodies=None))]
    if kind == "AtmosphericDrag":  # a planet of radius 2 m 4 m away, air turning with it: ≲ 5 N
        air = dict(density0=rng.uniform(0.5, 2.0), altitude0=1.0, scale_height=2.0, radius=2.0, p_W=far,
                   omega_W=rng.uniform(-0.3, 0.3, 3), drag_area=rng.uniform(0.1, 1.0))
        # a table of 4 rows 0.5 to 0.6 m apart over the bodies' altitudes (about 1 to 3 m), densities falling
        # irregularly: bodies in its bands and beyond its outermost rows. Each band's scale height (its width over
        # its fall of ln rho, at most 1) is then at least 0.5 m, so the bands extended beyond the table stay near
        # their rows' densities over the bodies' altitudes (rows drawn anywhere could be 1e-3 m apart, and an
        # extended band then grows like exp(h/1e-3): a random scene whose drag overflows in one step)
        table = dict(density0=0.0, scale_height=0.0, radius=2.0, p_W=far, omega_W=air["omega_W"],
                     drag_area=air["drag_area"], table_altitude=1.0 + 0.5 * np.arange(4) + rng.uniform(0.0, 0.1, 4),
                     table_density=np.exp(-np.cumsum(rng.uniform(0.1, 1.0, 4))))
        return [ref.Element(kind, dict(air, cp_B=np.zeros(3), bodies=None)),
                ref.Element(kind, dict(air, cp_B=rng.uniform(-0.5, 0.5, 3), bodies=[2, 3])),
                ref.Element(kind, dict(table, cp_B=rng.uniform(-0.5, 0.5, 3), bodies=[2, 3]))]
    if kind == "SolarRadiationPressure":  # a turning Sun, P A ≲ 2 N: a cannonball, a plate on the rigid bodies and
        # a planet of radius 1.5 m at the origin whose shadow may cover some bodies
        sun = dict(sun_W=rng.normal(size=3), sun_rate_W=rng.uniform(-1, 1, 3), pressure=rng.uniform(0.5, 1.0),
                   area=rng.uniform(0.5, 2.0), shadow_radius=1.5)
        return [ref.Element(kind, dict(sun, reflectivity=rng.uniform(1, 2), bodies=None)),
                ref.Element(kind, dict(sun, normal_B=rng.normal(size=3), specular=0.4, diffuse=0.3,
                                       cp_B=rng.uniform(-0.5, 0.5, 3), bodies=[2, 3]))]
    if kind == "MutualGravity":
        return [ref.Element(kind, dict(G=rng.uniform(1, 5), softening=rng.choice([0.0, 0.3]), bodies=None))]
    if kind == "GravityGradient":
        return [ref.Element(kind, dict(gm=rng.uniform(5, 50), p_W=far, bodies=[0, 2, 3]))]
    if kind == "SpringDamper":
        point = lambda: rng.uniform(-0.5, 0.5, 3)  # noqa: E731
        return [ref.Element(kind, dict(body_a=2, point_a_B=point(), body_b=3, point_b=point(),
                                       stiffness=rng.uniform(1, 10), rest_length=rng.uniform(0.5, 2),
                                       damping=rng.uniform(0, 2))),
                ref.Element(kind, dict(body_a=3, point_a_B=point(), body_b=-1, point_b=rng.uniform(-1, 1, 3),
                                       stiffness=rng.uniform(1, 10), rest_length=0.0, damping=rng.uniform(0, 2))),
                ref.Element(kind, dict(body_a=0, point_a_B=np.zeros(3), body_b=1, point_b=point() * [1, 1, 0],
                                       stiffness=rng.uniform(1, 10), rest_length=rng.uniform(0.5, 2),
                                       damping=rng.uniform(0, 2)))]
    if kind == "Drag":
        c = rng.uniform(0, 2, 4)
        return [ref.Element(kind, dict(linear=c[0], quadratic=c[1], angular_linear=c[2], angular_quadratic=c[3],
                                       bodies=None))]
    if kind == "MagneticDipole":  # the source ≥ 0.6 m from every body, k|M| ≤ 0.35 T m³: ≲ 2 N, 2 N m
        return [ref.Element(kind, dict(m_B=rng.uniform(-1, 1, 3), B_W=rng.uniform(-1, 1, 3),
                                       source_moment_W=rng.uniform(-2e6, 2e6, 3),
                                       source_p_W=rng.uniform(-0.2, 0.2, 3), bodies=None)),
                ref.Element(kind, dict(m_B=rng.uniform(-1, 1, 3), B_W=rng.uniform(-1, 1, 3), bodies=[0, 1, 3]))]
    if kind == "ReactionWheel":  # on the rigid bodies: |Ω| ≤ 20.4 rad/s, |h| ≤ 0.62 N m s, J |dΩ/dt| ≤ 0.6 N m
        return [ref.Element(kind, dict(body=2, axis_B=rng.normal(size=3), inertia=rng.uniform(0.005, 0.03),
                                       speed=rng.uniform(-10, 10))),
                ref.Element(kind, dict(body=3, axis_B=rng.normal(size=3), inertia=rng.uniform(0.005, 0.03),
                                       speed=rng.uniform(-10, 10), acceleration=rng.uniform(-20, 20), t_start=-0.5,
                                       t_end=1.0))]
    if kind == "ScheduledLoads":
        kinds = [body.kind for body in bodies]
        return [ref.Element(kind, dict(body=b, point_B=rng.uniform(-0.5, 0.5, 3) if b >= 2 else np.zeros(3),
                                       loads=[random_load(rng, kinds[b], "world"),
                                              random_load(rng, kinds[b], "body", -1.0, 0.5),
                                              random_load(rng, kinds[b], "world", 0.5, 1.0)]))
                for b in range(4)]
    raise AssertionError(kind)


KINDS = list(ref.FORCE_MODELS)
CONSERVATIVE = ["UniformGravity", "PointMassGravity", "ZonalGravity", "MutualGravity", "GravityGradient",
                "SpringDamper", "MagneticDipole"]


def random_scene(seed, kinds):
    rng = np.random.default_rng(seed)
    bodies = random_bodies(rng)
    elements = [e for kind in kinds for e in random_elements(rng, kind, bodies)]
    scene = ref.Scene(bodies, elements)
    return scene, ref.initial_state(scene, random_kinematics(rng, bodies))


# ---------------------------------------------------------------- the reference against itself
def perturbed(scene, y, body, coordinate, delta):
    """y with body's position coordinate 0–2 moved by delta [m], or its attitude (3–5) turned by delta
    [rad] about B's axis coordinate − 3 (q ⊗ exp(δ e/2); planar: θ + δ about z)."""
    y = np.array(y, float)
    o = ref.body_offsets(scene.bodies)[body]
    kind = scene.bodies[body].kind
    if coordinate < 3:
        y[o + coordinate] += delta
    elif kind == "planar":
        y[o + 2] += delta
    else:
        y[o + 3:o + 7] = dyn.quat_product(y[o + 3:o + 7], so3.rotvec_to_quat(delta * np.eye(3)[coordinate - 3]))
    return y


def coordinates(kind):
    """The coordinates a body's potential depends on: position (particle), x, y and θ (planar: 0, 1, 5 =
    rotation about z), position and attitude (rigid)."""
    return {"particle": [0, 1, 2], "planar": [0, 1, 5], "rigid": [0, 1, 2, 3, 4, 5]}[kind]


@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
@pytest.mark.parametrize("kind", CONSERVATIVE)
def test_reference_force_and_torque_are_minus_the_gradient_of_the_potential(kind, seed):
    """f_W = −∂V/∂p_W and tau_B = −∂V/∂θ_B (the attitude turned about B's axes), by central differences
    with δ = 1e-5: truncation δ² |V'''|/6 ≲ 1e-10 × |V|-scale/d³ (distances ≥ 1 m here), round-off
    ~ eps |V|/δ ≈ 2e-11 |V|; tolerance 1e-7 of the force scale (max |f|, |τ|, |V|/1 m, 1)."""
    scene, y = random_scene(seed, [kind])
    if kind == "SpringDamper":  # the potential part: dampers off
        scene = scene._replace(elements=[e._replace(params={**e.params, "damping": 0.0}) for e in scene.elements])
    kin = ref.kinematics(scene.bodies, y)
    delta = 1e-5
    for element in scene.elements:
        effect = ref.evaluate(element, scene.bodies, kin, 0.0)
        scale = max(1.0, np.max(np.abs(effect.f_W)), np.max(np.abs(effect.tau_B)), abs(effect.potential))
        for b, body in enumerate(scene.bodies):
            for c in coordinates(body.kind):
                potential = [ref.evaluate(element, scene.bodies, ref.kinematics(scene.bodies, perturbed(
                    scene, y, b, c, s * delta)), 0.0).potential for s in (1, -1)]
                gradient = (potential[0] - potential[1]) / (2 * delta)
                generalised = effect.f_W[b, c] if c < 3 else effect.tau_B[b, c - 3 if body.kind == "rigid" else 2]
                assert abs(generalised + gradient) <= 1e-7 * scale, (element.kind, b, c)


@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
def test_reference_drag_and_dampers_dissipate(seed):
    """Drag and dampers (stiffness 0) take energy: power = Σ f·v + τ·ω ≤ 0 (−c ℓ̇², −(c₁ + c₂|v|) v², …)."""
    scene, y = random_scene(seed, ["Drag", "SpringDamper"])
    kin = ref.kinematics(scene.bodies, y)
    for element in scene.elements:
        if element.kind == "SpringDamper":
            element = element._replace(params={**element.params, "stiffness": 0.0})
        effect = ref.evaluate(element, scene.bodies, kin, 0.0)
        assert effect.power <= 16 * EPS * term_magnitude(effect, kin)  # a −(…)² up to its sum's round-off


@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
def test_reference_internal_forces_obey_action_and_reaction(seed):
    """Mutual gravity and a spring–damper between two bodies (rest length > 0: force along the line of
    the points): Σ f = 0 and Σ (p × f + R τ_B) = 0 about W's origin (Rigid-body notes (4.49), strong form),
    to 1e-13 of Σ |p| |f| (a dozen roundings per term)."""
    scene, y = random_scene(seed, ["MutualGravity", "SpringDamper"])
    kin = ref.kinematics(scene.bodies, y)
    for element in [scene.elements[0], scene.elements[1], scene.elements[3]]:
        effect = ref.evaluate(element, scene.bodies, kin, 0.0)
        moment = sum(dyn.cross(k.p_W, f) + dyn.to_world(k.q_WB, tau)
                     for f, tau, k in zip(effect.f_W, effect.tau_B, kin))
        scale = sum((1 + np.linalg.norm(k.p_W)) * np.linalg.norm(f) for f, k in zip(effect.f_W, kin))
        assert np.max(np.abs(np.sum(effect.f_W, axis=0))) <= 1e-13 * scale
        assert np.max(np.abs(moment)) <= 1e-13 * scale


def test_reference_gravity_gradient_torque_on_a_satellite_in_pitch():
    """A body with y normal to the orbit pitched by θ: τ_y = −3n² (I_x − I_z) sin θ cos θ
    (scene_exact.pitch_libration_frequency's derivation), n² = GM/R³."""
    gm, radius, theta = 2.0, 3.0, 0.3
    inertia = np.diag([5.0, 4.0, 2.0])
    r_B = so3.rot_y(-theta) @ np.array([0.0, 0.0, radius])  # the local vertical seen from the pitched body
    tau = ref.gravity_gradient_torque(gm, r_B, inertia)
    assert tau[1] == pytest.approx(-3 * gm / radius ** 3 * (5.0 - 2.0) * np.sin(theta) * np.cos(theta), rel=1e-14)
    assert tau[0] == 0.0 and tau[2] == 0.0


@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
def test_reference_scene_of_one_body_agrees_with_the_one_body_reference(seed):
    """A one-rigid-body scene with uniform gravity and loads at the centre of mass is the one-body problem of
    rigiddyn_ref.integrators (written earlier, separately): one RK4 step agrees to both sides' round-off
    (rk4_step_tolerance), the two elements' work summing to the one-body model's work."""
    rng = np.random.default_rng(seed)
    scene, y = random_scene(seed, [])
    body, k = scene.bodies[3], ref.kinematics(scene.bodies, y)[3]
    g_W = rng.uniform(-10, 10, 3)
    loads = [random_load(rng, "rigid", "world"), random_load(rng, "rigid", "body")]
    scene = ref.Scene([body], [ref.Element("UniformGravity", dict(g_W=g_W, bodies=None)),
                               ref.Element("ScheduledLoads", dict(body=0, loads=loads))])
    y0 = ref.initial_state(scene, [k])
    h = 0.02
    got = ref.rk4_step(scene, y0, h)
    one_body = integrators.RigidBodyModel(body.mass, body.inertia, g_W)
    one_body.set_loads(dyn.loads_at(loads, 0.0))
    want = integrators.rk4(one_body, one_body.initial(k.p_W, k.q_WB, k.v_W, k.w_B), h)
    np.testing.assert_allclose(np.append(got[:13], got[14] + got[15]), want, rtol=0,
                               atol=rk4_step_tolerance(scene, y0, got))


# ---------------------------------------------------------------- rigiddyn against the reference
def componentwise_condition(fn, y, step=1e-7):
    """Σ_j |∂fn/∂y_j| |y_j| for each component of fn, by forward differences of relative step `step`: the
    change of fn when every coordinate of y moves by its own relative rounding, per unit of that relative
    size. With the magnitude of fn's terms it bounds an evaluation's round-off: rounding inside a formula
    of a dozen operations acts as relative perturbations of a few eps of its inputs (cancellations such as
    p_i − p_j, ℓ − ℓ0 or tr I − 3 r̂ᵀ I r̂ show up as large derivatives). The difference's own error
    (~eps |fn|/step) only enlarges it."""
    base = fn(y)
    total = np.zeros_like(base)
    for j in np.nonzero(y)[0]:
        moved = np.array(y, float)
        moved[j] *= 1 + step
        total += np.abs(fn(moved) - base) / step
    return total


def term_magnitude(effect, kin):
    """Σ over the bodies of |f|·|v| + |τ|·|ω| componentwise: the magnitude of the power's terms."""
    return sum(np.abs(f) @ np.abs(k.v_W) + np.abs(tau) @ np.abs(k.w_B)
               for f, tau, k in zip(effect.f_W, effect.tau_B, kin))


def recorded_quantities(scene, y):
    """[each element's power, T, V, linear momentum (3), angular momentum (3)] of the reference at y."""
    effects = ref.effects(scene, y)
    energies = [ref.kinetic_energy(scene, y), sum(e.potential for e in effects)]
    return np.concatenate([[e.power for e in effects], energies, ref.linear_momentum(scene, y),
                           ref.angular_momentum(scene, y)])


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # one step of a random scene against the reference: not an accurate run, nor meant to be
@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
@pytest.mark.parametrize("kind", KINDS + ["all"])
def test_core_power_energy_and_momenta_at_t0_match_the_reference(kind, seed):
    """At t0 the record holds each element's power, the energies and the momenta of the initial state: both
    sides evaluate the same formulas, each within 16 eps of (the magnitude of its terms + its componentwise
    condition, componentwise_condition): tolerance 2 sides × 16 eps × that."""
    scene, y0 = random_scene(seed, KINDS if kind == "all" else [kind])
    result = run(scene, y0, 0.02, 1)
    kin = ref.kinematics(scene.bodies, y0)
    want = recorded_quantities(scene, y0)
    terms = [term_magnitude(ref.evaluate(e, scene.bodies, kin, 0.0), kin) for e in scene.elements]
    scale = np.abs(want) + np.concatenate([terms, np.zeros(8)]) + componentwise_condition(
        lambda y: recorded_quantities(scene, y), y0)
    got = np.concatenate([result.power[0], [result.kinetic_energy[0], result.potential_energy[0]],
                          result.linear_momentum_W[0], result.angular_momentum_W[0]])
    np.testing.assert_array_less(np.abs(got - want), 32 * EPS * scale + 1e-300)


def rk4_step_tolerance(scene, y0, y1):
    """One RK4 step, core vs reference, from the same y0: per side the update y0 + h/6 Σ b_i k_i rounds ≤ 4 eps
    of max(|y0|, |Δy|), and each stage rate carries ≤ 16 eps κ of it (as _error_bounds.local_roundoff:
    κ = I_max/I_min from solving I ω̇ = n); the random scenes keep h × (the rate's Lipschitz constant) ≤ 1
    (h = 0.02 s, stiffness ≤ 10 N/m on ≥ 0.5 kg, spins ≤ 2 rad/s), so a stage's error grows by ≤ e over
    the four stages. Two sides: 2 × 16 eps κ e × max(1, |y0|, |y1 − y0|), as an absolute bound per
    component."""
    size = max(1.0, np.max(np.abs(y0)), np.max(np.abs(y1 - y0)))
    return 2 * 16 * EPS * inertia_condition(scene) * np.e * size


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # one step of a random scene against the reference: not an accurate run, nor meant to be
@settings(settings.get_profile("scene_reference"))
@given(seed=seeds)
@pytest.mark.parametrize("kind", KINDS + ["all"])
def test_core_rk4_step_matches_the_reference_for_each_force_model(kind, seed):
    """One RK4 step of h = 0.02 s of the scene with only `kind` (or every model, 'all'), core vs numpy: by
    simulate (its record after one step, work included) and by step (the bodies' states)."""
    scene, y0 = random_scene(seed, KINDS if kind == "all" else [kind])
    h = 0.02
    want = ref.rk4_step(scene, y0, h)
    tol = rk4_step_tolerance(scene, y0, want)
    got = record_state(scene, run(scene, y0, h, 1), 1, like=want)
    np.testing.assert_allclose(got, want, rtol=0, atol=tol)
    states, t1 = rd.step(core_scene(scene), core_states(scene, y0), h, method="rk4", t=0.0)
    assert t1 == h
    n_bodies = len(want) - len(scene.elements)
    np.testing.assert_allclose(state_vector(scene, states, t1, want)[:n_bodies], want[:n_bodies], rtol=0, atol=tol)


def rate_lipschitz(scene, y, delta=1e-7):
    """‖∂ẏ/∂y‖_∞ of the reference rate at y, by forward differences (relative step delta of max(1, |y_j|))."""
    f0 = ref.rate(scene, y)
    columns = []
    for j in range(len(y)):
        step = delta * max(1.0, abs(y[j]))
        e = np.zeros(len(y))
        e[j] = step
        columns.append((ref.rate(scene, y + e) - f0) / step)
    return np.max(np.sum(np.abs(np.array(columns).T), axis=1))


def test_core_rk4_run_of_every_model_matches_the_reference_across_a_schedule_switch():
    """30 RK4 steps of 0.02 s of the scene with every force model (_scene_core.every_model_scene:
    springs, dampers, drag, gravity of every kind, schedules switching at t = 0.55 s inside a step, which
    both sides split there). The two sides differ only by round-off: each step adds ≤ 2 δ (δ the one-side
    bound of rk4_step_tolerance), carried to the end by the method's Jacobian ‖J(N, k)‖ ≤ e^{L (N − k) h}
    with L ≥ ‖∂ẏ/∂y‖_∞ (measured on the reference at the start and the end, the larger, doubled for its
    variation along the run): bound N e^{L N h} × 2 δ, δ taken on the run's largest state and step."""
    scene, y0 = every_model_scene()
    h, steps = 0.02, 30
    want = ref.rk4_run(scene, y0, h, steps)
    result = run(scene, y0, h, steps)
    L = 2 * max(rate_lipschitz(scene, want[0]), rate_lipschitz(scene, want[-1]))
    size = max(1.0, np.max(np.abs(want)), np.max(np.abs(np.diff(want, axis=0))))
    delta = 16 * EPS * inertia_condition(scene) * np.e * size
    bound = steps * np.exp(L * steps * h) * 2 * delta
    for i in range(steps + 1):
        np.testing.assert_allclose(record_state(scene, result, i, like=want[i]), want[i], rtol=0, atol=bound)
