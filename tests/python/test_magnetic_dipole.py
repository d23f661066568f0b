"""The MagneticDipole element: each listed body carries a dipole m_B [A m²] fixed in its B, in a uniform field
B_W [T] plus the field of a fixed source dipole source_moment_W [A m²] at source_p_W [m] (Jackson, §5.6–5.7:
τ = m × B, f = ∇(m·B), V = −m·B). Checked against the numpy reference (rigiddyn_ref.scene.magnetic_dipole) on
random scenes as test_scene_vs_reference checks every element (the record at t0 and one RK4 step); against exact
solutions: a compass needle in a uniform field is a pendulum (period 2π √(I/(|m||B|)) for a small swing,
4 K(k) √(I/(|m||B|)) for any, DLMF §22.19(i)), as a rigid body, a planar body and a body pinned at its centre of
mass; T + V kept by RK4 at its order near a source dipole; bad input refused naming the field; a scene file
round trip."""

import pickle

import numpy as np
import pint
import pytest
import scipy.special

import rigiddyn as rd
from rigiddyn.scene_file import load_scene, read_scene, scene_to_toml

from rigiddyn_ref import scene as ref
from rigiddyn_ref import so3

from _scene_core import EPS, core_scene, core_states, record_state, run, state_vector
from test_scene_vs_reference import (componentwise_condition, random_bodies, random_kinematics, recorded_quantities,
                                     rk4_step_tolerance, term_magnitude)

SEEDS = range(6)
FIELDS = ["uniform", "source", "both"]


# ---------------------------------------------------------------- against the reference on random scenes
def magnetic_scene(seed, field):
    """test_scene_vs_reference's random bodies (a particle, a planar body, a rigid body with principal axes and
    one with a full inertia, at the corners of a 2 m square) under two MagneticDipole elements of the `field`
    kind ('uniform': B_W only; 'source': the source dipole only; 'both'): one on every body, one listing the
    particle and the principal rigid body (the particle is skipped). |m_B| ≤ 1.7 A m², |B_W| ≤ 1.7 T, the
    source within 0.35 m of W's origin with k|M| ≤ 0.35 T m³ (k = μ0/(4π)), so ≥ 0.6 m from every body: forces
    ≲ 2 N, torques ≲ 2 N m."""
    rng = np.random.default_rng(seed)
    bodies = random_bodies(rng)

    def params(acting):
        out = dict(m_B=rng.uniform(-1, 1, 3), bodies=acting)
        if field in ("uniform", "both"):
            out["B_W"] = rng.uniform(-1, 1, 3)
        if field in ("source", "both"):
            out["source_moment_W"] = rng.uniform(-2e6, 2e6, 3)
            out["source_p_W"] = rng.uniform(-0.2, 0.2, 3)
        return out

    elements = [ref.Element("MagneticDipole", params(None)), ref.Element("MagneticDipole", params([0, 2]))]
    scene = ref.Scene(bodies, elements)
    return scene, ref.initial_state(scene, random_kinematics(rng, bodies))


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("field", FIELDS)
def test_power_energies_and_momenta_at_t0_match_the_reference(field, seed):
    """The record at t0 holds each element's power f·v + τ·ω, T, V = −Σ m_W·B(p) and the momenta of the initial
    state: both sides evaluate the same formulas, each within 16 eps of (the magnitude of its terms + its
    componentwise condition): tolerance 2 sides × 16 eps × that (as test_scene_vs_reference)."""
    scene, y0 = magnetic_scene(seed, field)
    result = run(scene, y0, 0.02, 1)
    kin = ref.kinematics(scene.bodies, y0)
    want = recorded_quantities(scene, y0)
    terms = [term_magnitude(ref.evaluate(e, scene.bodies, kin, 0.0), kin) for e in scene.elements]
    scale = np.abs(want) + np.concatenate([terms, np.zeros(8)]) + componentwise_condition(
        lambda y: recorded_quantities(scene, y), y0)
    got = np.concatenate([result.power[0], [result.kinetic_energy[0], result.potential_energy[0]],
                          result.linear_momentum_W[0], result.angular_momentum_W[0]])
    np.testing.assert_array_less(np.abs(got - want), 32 * EPS * scale + 1e-300)
    assert list(result.elements) == ["MagneticDipole", "MagneticDipole"]


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("field", FIELDS)
def test_one_rk4_step_matches_the_reference(field, seed):
    """One RK4 step of h = 0.02 s, core vs numpy: the four stage derivatives of every body (planar: in-plane force
    and τ_z; particle: untouched) and each element's work, by simulate and by step, within both sides' round-off
    (test_scene_vs_reference.rk4_step_tolerance: h × the rate's Lipschitz constant ≲ 1 here, torques ≲ 2 N m on
    moments ≥ 0.02 kg m²)."""
    scene, y0 = magnetic_scene(seed, field)
    h = 0.02
    want = ref.rk4_step(scene, y0, h)
    tol = rk4_step_tolerance(scene, y0, want)
    got = record_state(scene, run(scene, y0, h, 1), 1, like=want)
    np.testing.assert_allclose(got, want, rtol=0, atol=tol)
    states, t1 = rd.step(core_scene(scene), core_states(scene, y0), h, method="rk4", t=0.0)
    n_bodies = len(want) - len(scene.elements)
    np.testing.assert_allclose(state_vector(scene, states, t1, want)[:n_bodies], want[:n_bodies], rtol=0, atol=tol)


def test_a_listed_particle_is_skipped():
    """A particle has no attitude, so no dipole direction: listed alone, it moves on a straight line
    (p0 + v0 t: 50 steps rounding ≤ 6 eps of |p| each), the element's power, work and potential are 0."""
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="dot")
    scene.add(rd.MagneticDipole(m_B=[1.0, 2.0, 3.0], B_W=[0.5, 0.0, 0.0], source_moment_W=[0.0, 0.0, 1e7],
                                source_p_W=[0.0, 0.0, 0.0], bodies=[0]))
    p0, v0 = np.array([1.0, 0.5, -0.2]), np.array([0.3, -0.1, 0.2])
    result = rd.simulate(scene, [rd.ParticleState(p_W=p0, v_W=v0)], dt=0.01, steps=50, method="rk4")
    np.testing.assert_allclose(result.p_W[:, 0], p0 + v0 * result.t[:, None], rtol=0, atol=50 * 6 * EPS * 2.0)
    np.testing.assert_array_equal(result.v_W[:, 0], np.broadcast_to(v0, (51, 3)))
    assert np.all(result.power == 0.0) and np.all(result.work == 0.0) and np.all(result.potential_energy == 0.0)


# ---------------------------------------------------------------- the compass needle: a pendulum
I_ZZ, M_B, B_W = 0.5, 2.0, 0.25          # kg m², A m², T: ω0 = √(|m||B|/I_zz) = 1 rad/s
OMEGA0 = np.sqrt(M_B * B_W / I_ZZ)
PERIODS = 4


def pendulum_period(theta0):
    """4 K(k)/ω0, k = sin(θ0/2) (DLMF §22.19(i); scipy's ellipk takes the parameter k²) [s]."""
    return 4.0 * scipy.special.ellipk(np.sin(theta0 / 2) ** 2) / OMEGA0


def compass_scene(kind, theta0):
    """A needle with m_B along x_B in B_W along x_W, turned by θ0 about z_W, at rest: a rigid body (principal
    moments (0.3, 0.4, I_zz): z stays a principal axis, so no gyroscopic coupling), a planar body, or a rigid
    body pinned at its centre of mass (PivotedBody with p_OC_B = 0: the pivot takes no force, the element's
    torque alone turns it). Its torque about z is m_B × B_B = −|m||B| sin θ: I_zz θ̈ = −|m||B| sin θ."""
    scene = rd.Scene()
    q = [0.0, 0.0, np.sin(theta0 / 2), np.cos(theta0 / 2)]
    if kind == "rigid":
        scene.add_body(rd.RigidBody(3.0, [0.3, 0.4, I_ZZ]), name="needle")
        initial = [rd.RigidBodyState(p_W=[1.0, 2.0, 3.0], q_WB=q)]
    elif kind == "planar":
        scene.add_body(rd.PlanarBody(3.0, I_ZZ), name="needle")
        initial = [rd.PlanarBodyState(p_W=[1.0, 2.0], theta=theta0)]
    else:
        scene.add_body(rd.PivotedBody(rd.RigidBody(3.0, [0.3, 0.4, I_ZZ]), [0.0, 0.0, 0.0], [1.0, 2.0, 3.0]),
                       name="needle")
        initial = [rd.PivotedBodyState(q_WB=q)]
    scene.add(rd.MagneticDipole(m_B=[M_B, 0.0, 0.0], B_W=[B_W, 0.0, 0.0]))
    return scene, initial


def measured_period(result, periods):
    """The period from the run: the time of the `periods`-th downward zero crossing of ω = w_B,z (θ back at θ0),
    by one Newton step from the record nearest to it, with ω̇ = α(θ) = −ω0² sin θ of the recorded angle
    (θ = 2 atan2(q_z, q_w)), divided by `periods`. The crossing t* has ω̇ = α(θ0), ω̈ = 0 (θ̇ = 0 there) and
    ω⃛ = −ω0² cos θ0 α(θ0), so a Newton step from t* + δ lands within ω0² |cos θ0| |δ|³/3, |δ| ≤ dt/2."""
    omega = np.asarray(result.w_B)[:, 0, 2]
    q = np.asarray(result.q_WB)[:, 0]
    theta = 2.0 * np.arctan2(q[:, 2], q[:, 3])
    down = np.nonzero((omega[:-1] > 0.0) & (omega[1:] <= 0.0))[0]
    i = down[periods - 1]
    i = i if abs(omega[i]) <= abs(omega[i + 1]) else i + 1
    return (result.t[i] - omega[i] / (-OMEGA0 ** 2 * np.sin(theta[i]))) / periods


@pytest.mark.parametrize("kind", ["rigid", "planar", "pivoted"])
@pytest.mark.parametrize("theta0", [1e-3, 2.5])
def test_compass_needle_swings_with_the_pendulum_period(kind, theta0):
    """RK4 with 1600 and 3200 steps per period over 4 periods (and a quarter more, to see the last return). The
    measured period (measured_period) errs by RK4's global error e(h) plus the Newton step's ≤ ω0² |cos θ0|
    dt³/24 over 4 T. RK4's error is C h⁴ + O(h⁵); assuming only that halving h at least halves it (16 times
    asymptotically; the runs here are close to but not always in that regime at θ0 = 2.5, near the
    separatrix), |e(h/2)| ≤ |e(h) − e(h/2)|: the bound uses only the two runs. Round-off: 13600 steps × 4 eps
    relative. Asserts the period at h/2 meets 4 K(k)/ω0 within that bound, which is ≤ 1e-9 (the dt is small
    enough by RK4's own error bound). At θ0 = 1e-3 also 2π/ω0 (1 + θ0²/16) within θ0⁴ (the series' next term
    is 11 θ0⁴/3072) plus the same bound: the small-swing period 2π √(I_zz/(|m||B|)) and its first amplitude
    correction are both seen."""
    period = pendulum_period(theta0)
    measured, newton = [], []
    for per_period in (1600, 3200):
        scene, initial = compass_scene(kind, theta0)
        dt = period / per_period
        result = rd.simulate(scene, initial, dt=dt, steps=PERIODS * per_period + per_period // 4, method="rk4")
        measured.append(measured_period(result, PERIODS))
        newton.append(OMEGA0 ** 2 * abs(np.cos(theta0)) * dt ** 3 / 24 / PERIODS)
    roundoff = (PERIODS + 1) * 3200 * 4 * EPS * period
    bound = abs(measured[0] - measured[1]) + newton[0] + newton[1] + roundoff
    assert bound <= 1e-9 * period
    assert abs(measured[1] - period) <= bound
    if theta0 < 0.01:
        linear = 2 * np.pi * np.sqrt(I_ZZ / (M_B * B_W))
        assert abs(measured[1] / linear - (1 + theta0 ** 2 / 16)) <= theta0 ** 4 + bound / period


@pytest.mark.parametrize("kind", ["rigid", "planar", "pivoted"])
def test_compass_needle_potential_is_minus_m_dot_b(kind):
    """V = −m_W·B = −|m||B| cos θ along the swing (Jackson, §5.7), and T + V is kept: at each record
    |V − (−|m||B| cos θ)| within 16 eps |m||B| (θ from the recorded attitude, a few roundings), and T + V within
    RK4's error at 400 steps per period (Richardson on the run at 200: |e(h)| ≤ 2 |e(2h) − e(h)|/15, the 16 of
    RK4's order less its next order's share) plus 1600 steps' round-off × 16 eps |m||B|."""
    theta0 = 2.0
    period = pendulum_period(theta0)
    drifts = []
    for per_period in (200, 400):
        scene, initial = compass_scene(kind, theta0)
        result = rd.simulate(scene, initial, dt=period / per_period, steps=4 * per_period, method="rk4")
        q = np.asarray(result.q_WB)[:, 0]
        theta = 2.0 * np.arctan2(q[:, 2], q[:, 3])
        np.testing.assert_allclose(result.potential_energy, -M_B * B_W * np.cos(theta), rtol=0,
                                   atol=16 * EPS * M_B * B_W)
        drifts.append(np.max(np.abs(result.total_energy - result.total_energy[0])))
    assert drifts[1] <= 2 * abs(drifts[0] - drifts[1]) / 15 + 1600 * 16 * EPS * M_B * B_W
    assert drifts[1] <= 5e-8 * M_B * B_W


# ---------------------------------------------------------------- energy near a source dipole
def tumbling_near_a_source():
    """A 20 kg rigid body (I = diag(0.02, 0.03, 0.04) kg m²) spinning at ~3.7 rad/s 0.7 m from a source dipole
    of 3e5 A m² (B ~ 0.2 T there), and a planar body 0.8 m from it in the plane z = 0, in a uniform 0.05 T
    field, m_B ~ 1 A m²: potential and kinetic energy exchange ~0.15 J over 2 s; the bodies drift ~0.05 m under
    the dipole force (~0.5 N), which so does work."""
    bodies = [ref.rigid(20.0, [0.02, 0.03, 0.04]), ref.planar(10.0, 0.05)]
    element = ref.Element("MagneticDipole", dict(m_B=[0.8, 0.3, -0.5], B_W=[0.0, 0.05, 0.02],
                                                 source_moment_W=[0.0, 0.0, 3e5], source_p_W=[0.1, -0.1, 0.0],
                                                 bodies=None))
    scene = ref.Scene(bodies, [element])
    kin = [ref.Kinematics(np.array([0.7, 0.1, 0.2]), so3.rotvec_to_quat([0.3, -0.4, 0.2]), np.array([0.0, 0.05, 0.0]),
                          np.array([3.0, -1.0, 2.0])),
           ref.Kinematics(np.array([-0.7, 0.3, 0.0]), ref.rz_quat(0.4), np.array([0.02, 0.0, 0.0]),
                          np.array([0.0, 0.0, -2.5]))]
    return scene, ref.initial_state(scene, kin)


def test_kinetic_plus_potential_energy_is_kept_near_a_source_dipole():
    """The element is conservative (f·v + τ·ω = −dV/dt): over 2 s, V2 − V1 = −work and (T + V) is constant,
    within RK4's error bound (Richardson on the runs at h = 0.01 s and h/2: |r(h/2)| ≤ 2 |r(h) − r(h/2)|/15) plus
    the round-off of 400 steps × 16 eps × the energy scale, as test_scene_invariants does for every conservative
    element; and the bound is small (1e-6 of the scale), so a missing force (whose work would then be missing)
    or a wrong potential is caught. The core's V at t0 is the reference's within both sides' 16 eps of its terms
    Σ |m|(|B_W| + 4 k|M|/|r|³)."""
    scene, y0 = tumbling_near_a_source()
    results = [run(scene, y0, 0.01, 200), run(scene, y0, 0.005, 400)]
    params = scene.elements[0].params
    k_M = ref.MU0 / (4 * np.pi) * np.linalg.norm(params["source_moment_W"])
    terms = sum(np.linalg.norm(params["m_B"]) * (np.linalg.norm(params["B_W"]) + 4 * k_M / np.linalg.norm(
        k.p_W - params["source_p_W"]) ** 3) for k in ref.kinematics(scene.bodies, y0))
    assert abs(results[0].potential_energy[0] - ref.potential_energy(scene, y0)) <= 2 * 16 * EPS * terms
    r = [(res.potential_energy[-1] - res.potential_energy[0]) + np.sum(res.work[-1]) for res in results]
    drift = [res.total_energy[-1] - res.total_energy[0] for res in results]
    scale = np.max(np.abs(results[1].kinetic_energy)) + np.sum(np.abs(results[1].work)) + np.max(
        np.abs(results[1].potential_energy))
    for coarse, fine in (r, drift):
        assert abs(fine) <= 2 * abs(coarse - fine) / 15 + 400 * 16 * EPS * scale
        assert abs(fine) <= 1e-6 * scale


# ---------------------------------------------------------------- the element as data
def test_attributes_read_back_in_si_and_the_element_round_trips():
    e = rd.MagneticDipole(m_B=[1, 2, 3], B_W=(4, 5, 6), source_moment_W=[7, 8, 9], source_p_W=[10, 11, 12],
                          bodies=[1, 0])
    for name, value in (("m_B", [1, 2, 3]), ("B_W", [4, 5, 6]), ("source_moment_W", [7, 8, 9]),
                        ("source_p_W", [10, 11, 12])):
        np.testing.assert_array_equal(getattr(e, name), value)
        with pytest.raises(ValueError):
            getattr(e, name)[0] = 1.0  # read-only copies
    assert e.bodies == (1, 0)
    defaults = rd.MagneticDipole(m_B=[0.0, 0.0, 1.0])
    for name in ("B_W", "source_moment_W", "source_p_W"):
        np.testing.assert_array_equal(getattr(defaults, name), [0.0, 0.0, 0.0])
    assert defaults.bodies is None
    assert pickle.loads(pickle.dumps(e)) == e
    assert eval(repr(e), vars(rd)) == e
    assert e != rd.MagneticDipole(m_B=[1, 2, 3])


def test_quantities_convert_to_si():
    """A pint quantity of any registry converts to A m², T, m (a product with the unit's factor: one rounding)."""
    Q = pint.UnitRegistry().Quantity
    e = rd.MagneticDipole(m_B=Q(np.array([2e4, 0.0, 0.0]), "A*cm^2"), B_W=Q(np.array([0.0, 50.0, 0.0]), "mT"),
                          source_moment_W=Q(np.array([0.0, 0.0, 3.0]), "A*m^2"),
                          source_p_W=Q(np.array([100.0, 0.0, 0.0]), "cm"))
    np.testing.assert_allclose(e.m_B, [2.0, 0.0, 0.0], rtol=2 * EPS)
    np.testing.assert_allclose(e.B_W, [0.0, 0.05, 0.0], rtol=2 * EPS)
    np.testing.assert_allclose(e.source_moment_W, [0.0, 0.0, 3.0], rtol=2 * EPS)
    np.testing.assert_allclose(e.source_p_W, [1.0, 0.0, 0.0], rtol=2 * EPS)
    with pytest.raises(ValueError, match=r"^B_W: expected"):
        rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], B_W=Q(np.array([1.0, 0.0, 0.0]), "m"))
    with pytest.raises(ValueError, match=r"^m_B: expected"):
        rd.MagneticDipole(m_B=Q(np.array([1.0, 0.0, 0.0]), "T"))


@pytest.mark.parametrize("make, error, message", [
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0]), ValueError, r"^m_B: expected"),
    (lambda: rd.MagneticDipole(m_B=[[1.0, 0.0, 0.0]] * 3), ValueError, r"^m_B: expected"),
    (lambda: rd.MagneticDipole(m_B=[np.nan, 0.0, 0.0]), ValueError, r"^m_B: expected"),
    (lambda: rd.MagneticDipole(m_B="north"), (TypeError, ValueError), r"^m_B: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], B_W=[0.0, np.inf, 0.0]), ValueError, r"^B_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], B_W=[0.0, np.nan, 0.0]), ValueError, r"^B_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], B_W=[1.0, 2.0, 3.0, 4.0]), ValueError, r"^B_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], source_moment_W=[0.0, 0.0, -np.inf]), ValueError,
     r"^source_moment_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], source_p_W=[np.nan, 0.0, 0.0]), ValueError,
     r"^source_p_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], source_p_W=1.0), (TypeError, ValueError), r"^source_p_W: expected"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], bodies=[0, 0]), ValueError, r"^bodies: expected each body once"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], bodies=[-1]), ValueError, r"^bodies\[0\]: expected an integer"),
    (lambda: rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], bodies="01"), TypeError, r"^bodies: expected None"),
])
def test_bad_arguments_are_refused_naming_the_field(make, error, message):
    with pytest.raises(error, match=message):
        make()


def test_the_arguments_are_keywords_and_m_b_is_required():
    with pytest.raises(TypeError):
        rd.MagneticDipole([1.0, 0.0, 0.0])
    with pytest.raises(TypeError):
        rd.MagneticDipole(B_W=[1.0, 0.0, 0.0])


def test_scene_add_checks_the_bodies_against_the_scene():
    scene = rd.Scene()
    scene.add_body(rd.Particle(1.0), name="dot")
    scene.add_body(rd.RigidBody(1.0, [1.0, 2.0, 2.5]), name="box")
    with pytest.raises(ValueError, match=r"^element.bodies\[0\]: expected a body index in \[0, 2\), got 5$"):
        scene.add(rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], bodies=[5]))
    assert scene.add(rd.MagneticDipole(m_B=[1.0, 0.0, 0.0], bodies=[0, 1])) == 0  # a listed particle is accepted
    assert "MagneticDipole" in scene.describe("rk4")


# ---------------------------------------------------------------- scene files
SCENE_FILE = """
name = "compass and needle"
[run]
dt = 0.01
duration = 1.0
[[body]]
name = "needle"
kind = "rigid"
mass = 0.5
inertia = [0.01, 0.02, 0.025]
p_W = [0.6, 0.1, 0.2]
w_B = [0.0, 0.0, 1.5]
[[body]]
name = "disc"
kind = "planar"
mass = 1.0
inertia = 0.05
p_W = [-0.7, 0.3]
theta = 0.4
[[body]]
name = "bead"
kind = "particle"
mass = 0.1
p_W = [0.0, 1.0, 0.0]
[[force]]
type = "magnetic_dipole"
m_B = ["2 A*m^2", 0, 0]
B_W = {value = [0, 50, 0], unit = "uT"}
source_moment_W = [0, 0, 3e3]
source_p_W = [0.1, -0.1, 0.0]
bodies = ["needle", "disc", "bead"]
[[force]]
type = "magnetic_dipole"
m_B = [0, 0.5, 0]
"""


def test_a_scene_file_round_trips_with_its_magnetic_dipoles():
    """[[force]] type = "magnetic_dipole" with the constructor's keys (units: A m², T, m; a value with its unit
    converted by one factor, within 2 eps): read, the elements equal the constructor's; written canonically and
    read back, the same scene and states (a fixed point of the writer); both runs bit for bit the same."""
    f = read_scene(SCENE_FILE)
    first, second = f.scene.elements
    assert type(first) is rd.MagneticDipole and first.bodies == (0, 1, 2)
    np.testing.assert_allclose(first.m_B, [2.0, 0.0, 0.0], rtol=2 * EPS)
    np.testing.assert_allclose(first.B_W, [0.0, 5e-5, 0.0], rtol=2 * EPS)
    np.testing.assert_array_equal(first.source_moment_W, [0.0, 0.0, 3e3])
    np.testing.assert_array_equal(first.source_p_W, [0.1, -0.1, 0.0])
    assert second == rd.MagneticDipole(m_B=[0.0, 0.5, 0.0])
    text = scene_to_toml(f.scene, f.initial, f.run, f.name, f.description)
    assert 'type = "magnetic_dipole"' in text
    g = read_scene(text)
    assert g.scene == f.scene and g.run == f.run and g.name == f.name
    assert scene_to_toml(g.scene, g.initial, g.run, g.name, g.description) == text
    a = rd.simulate(f.scene, f.initial, dt=f.run.dt, steps=f.run.steps, method="rk4")
    b = rd.simulate(g.scene, g.initial, dt=g.run.dt, steps=g.run.steps, method="rk4")
    np.testing.assert_array_equal(a.p_W, b.p_W)
    np.testing.assert_array_equal(a.q_WB, b.q_WB)
    np.testing.assert_array_equal(a.work, b.work)


P = '[[body]]\nname = "ball"\nkind = "rigid"\nmass = 1\ninertia = [1, 1, 1]\n[[force]]\ntype = "magnetic_dipole"\n'


@pytest.mark.parametrize("text, message", [
    (P, "force[0].m_B: expected"),
    (P + "m_B = [1, 2]", "force[0].m_B: expected"),
    (P + 'm_B = [1, 0, 0]\nB_W = ["1 m", 0, 0]', "force[0].B_W[0]: expected T"),
    (P + "m_B = [1, 0, 0]\nB_w = [1, 0, 0]", "force[0].B_w: expected a key of a [[force]] of type 'magnetic_dipole'"),
    (P + 'm_B = [1, 0, 0]\nbodies = ["bal"]', "force[0].bodies[0]: expected the name of a [[body]]"),
])
def test_bad_scene_file_fields_name_the_field(text, message):
    with pytest.raises(ValueError) as e:
        load_scene(text)
    assert message in str(e.value)
