"""Bodies whose mass changes (MassFlow): the work–energy balance with the mass-flow energy, the masses the
methods meet inside a step (splitting_dlm_yoshida4's three-part form keeps its order), the up-front check of a
constant rate against the in-run one, and its message when the first step already empties the body.

The balance. With m v̇ = f and I ω̇ + ω × I ω = τ ("Rigid body kinematics and dynamics" notes, eq. (4.36), for
the body and the mass it exchanges), T = ½ m |v|² + ½ ω·I ω obeys dT/dt = Σ power + ½ ṁ |v|² + ½ ω·(dI/dt) ω:
the work alone does not close it (the shipped rocket: ΔT = 1.157e8 J against Σ work = 1.573e8 J). The last two
terms, integrated with the motion, are SceneResult.mass_flow_energy (one column per body), and
    T − T(0) = Σ work + Σ mass_flow_energy
holds to the method's error: its residual r(h) = C h^p (1 + O(h)) for a method of order p, so that the runs at
h and h/2 bound |r(h/2)| ≤ |r(h) − r(h/2)|/(2^p − 1) (Richardson), to which we add a factor 2 for the next
order's share and the round-off of n steps × 16 eps × the energy scale (max T + Σ max |work| + Σ max |E|), as
test_scene_invariants does. The splittings on particles close it to round-off: their kicks change T by exactly
the work they record (the mean velocity of a linear-in-time kick) and their mass parts by exactly the mass-flow
energy they record (v fixed there).
"""

import math
import pickle
import re

import numpy as np
import pytest

import rigiddyn as rd

EPS = np.finfo(float).eps
ORDER = {m["name"]: m["order"] for m in rd.methods()}
METHODS = [name for name in ORDER if name != "exact"]  # 'exact' refuses a mass flow
# the sub-flows of one step whose round-off the balance collects (Yoshida's three-part form: 4 mass parts,
# 6 kicks, 3 free flows)
PARTS = {"splitting_dlm": 3, "exact_flow_kick": 3, "splitting_dlm_yoshida4": 13}


def residual(result):
    """T − T(0) − Σ work − Σ mass_flow_energy at the last record [J]."""
    return (result.kinetic_energy[-1] - result.kinetic_energy[0] - np.sum(result.work[-1])
            - np.sum(result.mass_flow_energy[-1]))


def energy_scale(result):
    """max T + Σ max |work| + Σ max |E| over the run [J]: what the balance's sums round on."""
    return (np.max(np.abs(result.kinetic_energy)) + np.sum(np.max(np.abs(result.work), axis=0))
            + np.sum(np.max(np.abs(result.mass_flow_energy), axis=0)))


def richardson_bound(run, method, dt, steps):
    """(|r(h/2)|, its bound) from the runs at dt and dt/2 (module docstring)."""
    coarse, fine = run(method, dt, steps), run(method, dt / 2, 2 * steps)
    r_coarse, r_fine = residual(coarse), residual(fine)
    scale = max(energy_scale(coarse), energy_scale(fine))
    bound = 2 * abs(r_coarse - r_fine) / (2 ** ORDER[method] - 1) + 2 * steps * 16 * EPS * scale
    return abs(r_fine), bound, fine


def rate_of_t(t):
    """ṁ(t) [kg/s] of the tests' flow given in time: −0.5 − 0.2 sin 3t."""
    return -0.5 - 0.2 * np.sin(3.0 * t)


def mass_of_t(m0, t):
    """m0 + ∫_0^t rate_of_t [kg]."""
    return m0 - 0.5 * t + 0.2 / 3.0 * (np.cos(3.0 * t) - 1.0)


# ---------------------------------------------------------------- the rocket (the shipped scene)
def test_the_shipped_rocket_closes_the_balance_with_its_mass_flow_energy():
    """The rocket (rk4, 0.1 s, 60 s) at dt and dt/2: the residual of T − T(0) = Σ work + E within RK4's Richardson
    bound, while the work alone misses by −ṁ-weighted kinetic energy, ~4e7 J (the documentation's old claim). And E
    against its closed value: E = ½ ṁ ∫ |v|² dt over the exact velocity (ConstantThrustSolution), by 40-point
    Gauss–Legendre on [0, 60 s] (v is analytic there, its nearest singularity at the burn-out t = 100 s: the rule's
    error ~ 4.4^(−80), none), to RK4's error: |ΔE| ≤ the balance bound plus the velocity's own error
    |ṁ| t max|v| |Δv| with |Δv| ≤ 1e-8 m/s (the docs' 1.4e-10 m/s at the end)."""
    scene, initial, options = rd.load_scene("rocket")

    def run(method, dt, steps):
        return rd.simulate(scene, initial, dt=dt, steps=steps, method=method, record_every=steps)

    r, bound, result = richardson_bound(run, "rk4", options.dt, options.steps)
    assert r <= bound, (r, bound)
    work_alone = result.kinetic_energy[-1] - result.kinetic_energy[0] - np.sum(result.work[-1])
    assert abs(work_alone) > 1e6 * bound  # the mass-flow energy is what closes it
    assert result.mass_flow_energy.shape == (2, 1)
    flow, thrust = scene.mass_flows[0], scene.elements[1]
    exact = rd.ConstantThrustSolution(scene.bodies[0].mass, flow.rate, thrust.u_rel, scene.elements[0].g_W,
                                      initial[0].p_W, initial[0].v_W)
    duration = options.dt * options.steps
    nodes, weights = np.polynomial.legendre.leggauss(40)
    t = 0.5 * duration * (nodes + 1.0)
    _, v, _ = exact.at(t)
    E = 0.5 * flow.rate * 0.5 * duration * np.sum(weights * np.sum(v * v, axis=1))
    assert E == pytest.approx(-4.16e7, rel=1e-2)
    speed = np.max(np.linalg.norm(v, axis=1))
    assert abs(result.mass_flow_energy[-1, 0] - E) <= bound + abs(flow.rate) * duration * speed * 1e-8


# ---------------------------------------------------------------- a spinning body losing mass
def spinning_scene(rate, inertia_rule="scaled", inertia=(2.0, 3.0, 4.0)):
    """A torque-free rigid body (no element) of 10 kg losing mass at `rate`, spinning and moving."""
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(10.0, list(inertia)), name="spinner",
                   mass_flow=rd.MassFlow(rate=rate, inertia_rule=inertia_rule))
    return scene


SPIN = rd.RigidBodyState(v_W=[1.0, -2.0, 0.5], w_B=[3.0, 0.2, -1.0])


def spinning_run(rate, inertia_rule="scaled"):
    scene = spinning_scene(rate, inertia_rule)

    def run(method, dt, steps):
        return rd.simulate(scene, [SPIN], dt=dt, steps=steps, method=method, record_every=steps)

    return run


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("rate", [-0.8, rate_of_t], ids=["constant", "of_t"])
@pytest.mark.parametrize("method", METHODS)
def test_a_spinning_body_losing_mass_closes_the_balance(method, rate):
    """No force, so Σ work = 0 and T − T(0) = E: ½ ṁ |v|² and the ½ ω·(dI/dt) ω part (I = I_C0 m/m0 under the
    scaled rule). Exactly, v is constant and ω is the free rotation of I_C0 (the torque scale m0/m multiplies no
    torque), so T(t) = (m(t)/m0) T(0). The balance within the Richardson bound of the method's order (module
    docstring) over 5 s at 0.05 s (the mass 10 kg → ≥ 6 kg); exact_flow_kick, whose free rotation is exact,
    closes it to round-off (3 parts a step, 200 steps) and keeps T = (m/m0) T(0) at its own masses to the same."""
    run = spinning_run(rate)
    r, bound, result = richardson_bound(run, method, 0.05, 100)
    assert r <= bound, (method, r, bound)
    assert abs(result.mass_flow_energy[-1, 0]) > 1.0  # T drops by ~ 40 % of ~ 30 J: the term is not small
    if method == "exact_flow_kick":
        roundoff = 200 * PARTS[method] * 16 * EPS * energy_scale(result)
        assert r <= roundoff
        T0 = result.kinetic_energy[0]
        assert abs(result.kinetic_energy[-1] - result.mass[-1, 0] / 10.0 * T0) <= roundoff


def test_the_rotational_part_alone_is_half_w_dI_dt_w():
    """A body that only spins (v = 0) loses T = ½ ω·I ω at the rate ½ ω·(dI/dt) ω = (ṁ/m) T_rot: with exact_flow_kick
    E = T − T(0) = (m/m0 − 1) T(0) to round-off (nothing else moves T)."""
    scene = spinning_scene(-0.8)
    result = rd.simulate(scene, [rd.RigidBodyState(w_B=[3.0, 0.2, -1.0])], dt=0.05, steps=100, method="exact_flow_kick")
    T0 = result.kinetic_energy[0]
    expected = (result.mass[:, 0] / 10.0 - 1.0) * T0
    np.testing.assert_allclose(result.mass_flow_energy[:, 0], expected, rtol=0, atol=100 * 3 * 16 * EPS * T0)


def inertia_of_mass(m):
    """I_C(m) [kg m²]: a body that loses mass mostly from its ends."""
    return np.diag([0.2 + 0.05 * m, 0.3 + 0.04 * m, 0.4 + 0.02 * m])


@pytest.mark.parametrize("method", ["rk4", "implicit_midpoint", "semi_implicit_euler"])
def test_an_inertia_function_of_the_mass_closes_the_balance(method):
    """InertiaRule 'function': dI/dt = ṁ dI/dm, taken by a one-sided difference of second order (mass_flow.hpp: about
    3e-11 of |I|/m, far below the Richardson bound here), and exactly in a drift (½ ω·(I(m + Δm) − I(m)) ω)."""
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(5.0, inertia_of_mass(5.0)), name="spinner",
                   mass_flow=rd.MassFlow(rate=-0.5, inertia_rule=inertia_of_mass))

    def run(method, dt, steps):
        return rd.simulate(scene, [SPIN], dt=dt, steps=steps, method=method, record_every=steps)

    r, bound, result = richardson_bound(run, method, 0.05, 80)
    assert r <= bound, (method, r, bound)
    assert abs(result.mass_flow_energy[-1, 0]) > 1.0


# ---------------------------------------------------------------- a particle with thrust, rate given in time
def thrust_scene(rate, bystander=False):
    """A 10 kg particle with a world thrust (u_rel = 300 m/s down and sideways) under gravity; with a bystander
    particle (constant mass, free fall) the scene runs on the generic model instead of the fast one."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(10.0), name="rocket", mass_flow=rd.MassFlow(rate=rate))
    if bystander:
        scene.add_body(rd.Particle(1.0), name="bystander")
    scene.add(rd.UniformGravity())
    scene.add(rd.Thrust(body=0, u_rel=[20.0, -5.0, -300.0], frame="world"))
    return scene


def thrust_initial(bystander=False):
    states = [rd.ParticleState(p_W=[1.0, 2.0, 3.0], v_W=[5.0, -1.0, 0.0])]
    return states + ([rd.ParticleState(v_W=[0.0, 1.0, 2.0])] if bystander else [])


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("bystander", [False, True], ids=["fast", "generic"])
@pytest.mark.parametrize("rate", [-1.5, rate_of_t], ids=["constant", "of_t"])
@pytest.mark.parametrize("method", METHODS)
def test_a_thrusting_particle_closes_the_balance(method, rate, bystander):
    """Gravity and a thrust do work; the mass flow takes ½ ṁ |v|² away. Within the method's Richardson bound over 4 s
    at 0.05 s (10 kg → ≥ 4 kg); the splittings close it to round-off (their parts change T by exactly what they
    record)."""
    scene, initial = thrust_scene(rate, bystander), thrust_initial(bystander)

    def run(method, dt, steps):
        return rd.simulate(scene, initial, dt=dt, steps=steps, method=method, record_every=steps)

    r, bound, result = richardson_bound(run, method, 0.05, 80)
    assert r <= bound, (method, r, bound)
    assert abs(result.mass_flow_energy[-1, 0]) > 100.0
    if bystander:
        assert result.mass_flow_energy[-1, 1] == 0.0
    if method in PARTS:
        assert r <= 160 * PARTS[method] * 16 * EPS * energy_scale(result)


def test_mass_flow_energy_columns_and_pickle():
    """One column per body '<name>:mass_flow_energy [J]' after its mass; 0 for a scene without a mass flow; the
    result pickles with it."""
    result = rd.simulate(thrust_scene(-1.5, bystander=True), thrust_initial(True), dt=0.1, steps=10, method="rk4")
    df = result.to_dataframe()
    np.testing.assert_array_equal(df["rocket:mass_flow_energy [J]"], result.mass_flow_energy[:, 0])
    assert list(df.columns).index("rocket:mass_flow_energy [J]") == list(df.columns).index("rocket:mass [kg]") + 1
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(result)).mass_flow_energy, result.mass_flow_energy)
    constant = rd.Scene()
    constant.add_body(rd.Particle(1.0))
    constant.add(rd.UniformGravity())
    plain = rd.simulate(constant, [rd.ParticleState(v_W=[1.0, 0.0, 0.0])], dt=0.1, steps=10)
    assert plain.mass_flow_energy.shape == (11, 1) and not np.any(plain.mass_flow_energy)


# ---------------------------------------------------------------- the masses inside a step
@pytest.mark.parametrize("bystander", [False, True], ids=["fast", "generic"])
def test_yoshida_keeps_its_order_on_a_burn_against_the_closed_form(bystander):
    """splitting_dlm_yoshida4 on a burn from 10 kg to 4 kg in 4 s (|ṁ|/m ≤ 0.375 /s) against ConstantThrustSolution
    (Tsiolkovsky's v(t) = v0 + g t + u_rel ln(m/m0)): e = C h⁴ (1 + O(h |ṁ|/m)), h |ṁ|/m ≤ 0.05 at 32 steps, so
    the slope between 32 and 128 steps is 4 to within 0.2; the errors (≥ 1e-9) far above round-off (≤ 1e-12)."""
    scene, initial = thrust_scene(-1.5, bystander), thrust_initial(bystander)
    exact = rd.ConstantThrustSolution(10.0, -1.5, [20.0, -5.0, -300.0], [0.0, 0.0, -9.81], initial[0].p_W,
                                      initial[0].v_W)
    p, v, _ = exact.at(4.0)

    def error(n):
        r = rd.simulate(scene, initial, dt=4.0 / n, steps=n, method="splitting_dlm_yoshida4", record_every=n)
        return max(np.linalg.norm(r.p_W[-1, 0] - p), np.linalg.norm(r.v_W[-1, 0] - v))

    e0, e2 = error(32), error(128)
    assert math.log2(e0 / e2) / 2 == pytest.approx(4.0, abs=0.2), (e0, e2)
    assert e2 > 1e-9


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # first-order or coarse steps on purpose
@pytest.mark.parametrize("method", METHODS)
def test_a_body_gaining_mass_fast_is_not_refused(method):
    """324.31 kg gaining 1e4 kg/s, dt = 0.14 s: the mass grows 5-fold in the first step. Every mass of the run is
    positive, and so is every mass a method meets (Yoshida's mass parts stay between the step's end masses; the
    three-part form of integrators/yoshida4.hpp): no refusal, the end mass m0 + ṁ t to the round-off of 3 steps."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(324.31), name="b", mass_flow=rd.MassFlow(rate=1e4))
    scene.add(rd.UniformGravity())
    scene.add(rd.Thrust(body=0, u_rel=[0.0, 0.0, -100.0], frame="world"))
    result = rd.simulate(scene, [rd.ParticleState()], dt=0.14, steps=3, method=method)
    np.testing.assert_allclose(result.mass[:, 0], 324.31 + 1e4 * result.t, rtol=3 * 16 * EPS)


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps at the mass limit on purpose
@pytest.mark.parametrize("method", METHODS)
def test_a_run_that_ends_at_a_fifth_of_a_kilogram_is_not_refused(method):
    """10.2 kg at −1 kg/s for 10 steps of 1 s ends at 0.2 kg: the up-front check passes, and no method refuses it
    (Yoshida's sub-steps used to reach t0 + 1.35 dt, where the mass would be −0.15 kg)."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(10.2), name="b", mass_flow=rd.MassFlow(rate=-1.0))
    scene.add(rd.UniformGravity())
    scene.add(rd.Thrust(body=0, u_rel=[0.0, 0.0, -100.0], frame="world"))
    result = rd.simulate(scene, [rd.ParticleState()], dt=1.0, steps=10, method=method)
    assert result.mass[-1, 0] == pytest.approx(0.2, abs=10 * 16 * EPS * 10.2)


NEAR_LIMIT = [  # (m0 [kg], ṁ [kg/s], dt [s], the last step count with a mass well above 16 eps k m0)
    (1.0, -1.0, 0.1, 9),                 # 10 steps end at 1 − 10 × 0.1 = 0 (to round-off)
    (1.0 + 2.0 ** -50, -1.0, 2.0 ** -10, 1023),  # 1024 steps end at 2^-50 kg: within 16 eps × 1024 × m0
    (1.0, -1.0, 1.0 / 3.0, 2),          # 3 steps end at 1 − 3 × (1/3): 0 or an ulp
    (7.0, -2.0, 0.35, 9),               # 10 steps end at 0
]


@pytest.mark.filterwarnings("ignore::rigiddyn.AccuracyWarning")  # coarse steps at the mass limit on purpose
@pytest.mark.parametrize("m0, rate, dt, last", NEAR_LIMIT)
@pytest.mark.parametrize("method", METHODS)
def test_the_up_front_check_and_the_run_agree_at_the_documented_limit(method, m0, rate, dt, last):
    """The documented limit (mass_flow.hpp check_mass_over_run): a constant-rate run is accepted when its end mass
    m0 + ṁ k dt exceeds 16 eps k m0, the round-off of the mass every method accumulates. At the last step count
    below it the run completes with every recorded mass positive; one step more is refused before the run starts
    (the message ends with the steps it allows), never inside it."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(m0), name="b", mass_flow=rd.MassFlow(rate=rate))
    scene.add(rd.Thrust(body=0, u_rel=[0.0, 0.0, -10.0], frame="world"))
    result = rd.simulate(scene, [rd.ParticleState()], dt=dt, steps=last, method=method)
    assert np.all(result.mass[:, 0] > 0.0)
    assert result.mass[-1, 0] == pytest.approx(m0 + rate * last * dt, abs=16 * EPS * last * m0)
    with pytest.raises(ValueError, match=rf"; steps, dt: expected a run .* \(at most {last} steps of dt = .*\), got "
                                         rf"{last + 1} steps$"):
        rd.simulate(scene, [rd.ParticleState()], dt=dt, steps=last + 1, method=method)


def test_a_body_empty_within_the_first_step_is_named_so():
    """MassFlow(−1e300) with dt = 1e12 s: the mass lasts 1e-300 s. The message says the body is empty within the first
    step and the longest dt, not 'at most −1 steps' (nor a mass or a step from before t0)."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="probe", mass_flow=rd.MassFlow(rate=-1e300))
    with pytest.raises(ValueError) as error:
        rd.simulate(scene, [rd.ParticleState()], dt=1e12, steps=3)
    text = str(error.value)
    assert re.fullmatch(r"mass_flows\[0\]: expected a positive mass, got a body that is empty within the first step: "
                        r"'probe' \(m = 1 kg at t = 0 s, dm/dt = -1(\.0*1)?e\+300 kg/s\) runs out at t = 1e-300 s, "
                        r"before the step of dt = 1000000000000 s ends; steps, dt: expected dt < (9\.9*\d*e-301|1e-300) s "
                        r"\(the time the mass lasts, less 16 eps of it\), got dt = 1000000000000 s", text), text
    assert "-1 steps" not in text


def test_a_batch_records_the_mass_flow_energy_of_each_sample():
    """simulate_batch over a scene with a mass flow: mass_flow_energy (N, n, nb), each sample's as simulate's."""
    scene, initial = thrust_scene(-1.5, bystander=True), thrust_initial(True)
    states = [initial, [rd.ParticleState(v_W=[0.0, 3.0, 1.0]), initial[1]]]
    batch = rd.simulate_batch(scene, states, 0.05, 20, method="rk4")
    assert batch.mass_flow_energy.shape == (2, 21, 2)
    for i, state in enumerate(states):
        np.testing.assert_array_equal(batch[i].mass_flow_energy,
                                      rd.simulate(scene, state, 0.05, 20, method="rk4").mass_flow_energy)
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(batch)).mass_flow_energy, batch.mass_flow_energy)
