"""rigiddyn.monte_carlo: reproducible draws, dispersions with the stated distributions, statistics as
numpy computes them, and the documented example's physics.

The numpy reference pieces (quaternion angle, Haar CDF, invariants of the free body) are written here and
never call the package. Tolerances of the statistical tests follow from the sample size at a stated
false-alarm rate; the draws use fixed seeds, so each test is deterministic."""

import math
import pathlib
import pickle
import re
import statistics as stdlib_statistics
import sys
import types

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import dispersion as mc
from rigiddyn.dispersion import Normal

ROOT = pathlib.Path(__file__).resolve().parents[2]
EPS = np.finfo(float).eps
FIELDS = ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "potential_energy", "total_energy",
          "linear_momentum_W", "angular_momentum_W", "angular_momentum_O_W", "mass", "work", "power")
# false-alarm rate of every statistical test in this file (fixed seeds: each is deterministic, this says
# how unlucky a correct implementation would have to be for a seed to fail)
ALPHA = 1e-6


# ---------------------------------------------------------------------------------------------------
# the serial reference: N rigiddyn.simulate calls, stacked (what simulate_batch equals bitwise)

def serial_batch(model, initial, dt, steps, method=None, record_every=1, loads=None, gravity=None, t0=0.0):
    n = len(initial["q_WB"])
    bodies = list(model) if isinstance(model, (list, tuple)) else [model] * n
    per_sample_gravity = gravity is not None and np.ndim(gravity) == 2
    per_sample_loads = isinstance(loads, (list, tuple)) and len(loads) == n and all(
        isinstance(item, (list, tuple)) for item in loads)
    runs = []
    for i in range(n):
        state = rd.RigidBodyState(p_W=initial["p_W"][i], q_WB=initial["q_WB"][i], v_W=initial["v_W"][i],
                                  w_B=initial["w_B"][i])
        runs.append(rd.simulate(bodies[i], state, dt, steps, method=method, record_every=record_every,
                                loads=loads[i] if per_sample_loads else loads,
                                gravity=gravity[i] if per_sample_gravity else gravity, t0=t0))
    stacked = {field: np.stack([getattr(run, field) for run in runs]) for field in FIELDS}
    return types.SimpleNamespace(runs=runs, **stacked)


# ---------------------------------------------------------------------------------------------------
# numpy reference

def rotation_angle(q):
    """Rotation angle [rad] in [0, pi] of (..., 4) unit quaternions (x, y, z, w): 2 atan2(|v|, |w|)."""
    q = np.asarray(q)
    return 2.0 * np.arctan2(np.linalg.norm(q[..., :3], axis=-1), np.abs(q[..., 3]))


def angle_between(a, b):
    """Rotation angle [rad] in [0, pi] between attitudes a and b, (..., 4) unit quaternions: with the
    sign of b aligned to a (s = sign(a·b)) and φ the angle between them on S³ (rotation angle 2φ),
    |a - s b| = 2 sin(φ/2) and |a + s b| = 2 cos(φ/2), so the angle is 4 atan2(|a - s b|, |a + s b|):
    no cancellation near 0 (exactly 0 for a == b) nor near pi."""
    a, b = np.broadcast_arrays(np.asarray(a, float), np.asarray(b, float))
    s = np.where(np.sum(a * b, axis=-1) < 0, -1.0, 1.0)[..., None]
    return 4.0 * np.arctan2(np.linalg.norm(a - s * b, axis=-1), np.linalg.norm(a + s * b, axis=-1))


def quat_matrix(q):
    """(..., 3, 3) rotation matrices of (..., 4) unit quaternions (x, y, z, w)."""
    x, y, z, w = np.moveaxis(np.asarray(q), -1, 0)
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
                     np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
                     np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1)], -2)


def haar_angle_cdf(theta):
    """CDF of the rotation angle of a Haar-random rotation: density (1 - cos θ)/π on [0, π], so
    F(θ) = (θ - sin θ)/π."""
    return (theta - np.sin(theta)) / np.pi


def dkw_bound(n, alpha=ALPHA):
    """Dvoretzky-Kiefer-Wolfowitz (Massart's constant): P(sup |F_n - F| > ε) <= 2 exp(-2 n ε²) for any
    continuous F and any n, so ε = sqrt(ln(2/α) / (2 n)) bounds the KS statistic at false-alarm rate α."""
    return math.sqrt(math.log(2.0 / alpha) / (2.0 * n))


def z_bound(alpha=ALPHA, tests=1):
    """Two-sided normal quantile for `tests` simultaneous checks (Bonferroni) at total rate alpha."""
    return stdlib_statistics.NormalDist().inv_cdf(1.0 - alpha / (2.0 * tests))


def generators(seed, n):
    """Sample i's generator as the module documents it: default_rng(SeedSequence(seed).spawn(n)[i])."""
    return [np.random.default_rng(child) for child in np.random.SeedSequence(seed).spawn(n)]


SATELLITE = rd.RigidBody(12.0, [0.10, 0.14, 0.18])
TUMBLE = rd.RigidBodyState(w_B=np.radians([0.4, -1.0, 0.6]))


def small_run(n=6, steps=4, **kwargs):
    options = dict(seed=7, dt=0.5, steps=steps, dispersions={"w_B": Normal(std=1e-3), "q_WB": mc.UniformRotation()})
    options.update(kwargs)
    return mc.monte_carlo(SATELLITE, TUMBLE, n, **options)


# ---------------------------------------------------------------------------------------------------
# reproducibility

def test_sample_i_draws_from_its_own_spawned_generator():
    run = small_run(n=5, dispersions={"w_B": Normal(mean=[0.1, 0.2, 0.3], std=[1e-2, 2e-2, 3e-2])})
    for i, rng in enumerate(generators(7, 5)):
        expected = np.array([0.1, 0.2, 0.3]) + np.array([1e-2, 2e-2, 3e-2]) * rng.standard_normal(3)
        np.testing.assert_array_equal(run.inputs["w_B"][i], expected)
    # the initial record of each sample is its drawn state
    np.testing.assert_array_equal(run.values("w_B", at=0.0), run.inputs["w_B"])


def test_prefix_property_and_dict_order():
    dispersions = {"w_B": Normal(std=1e-3), "q_WB": mc.UniformRotation(),
                   "inertia": mc.InertiaDispersion(0.01, 0.01)}
    short = small_run(n=3, dispersions=dispersions)
    long = small_run(n=5, dispersions=dict(reversed(list(dispersions.items()))))
    for key in short.inputs:
        np.testing.assert_array_equal(long.inputs[key][:3], short.inputs[key])
    for field in FIELDS:
        np.testing.assert_array_equal(np.asarray(getattr(long.batch, field))[:3], getattr(short.batch, field))


def test_seed_none_is_recorded_and_reproduces():
    first = small_run(n=3, seed=None)
    again = small_run(n=3, seed=first.seed)
    np.testing.assert_array_equal(first.inputs["q_WB"], again.inputs["q_WB"])


def test_result_pickles():
    run = small_run(n=3, dispersions={"inertia": mc.InertiaDispersion(0.01, 0.01), "q_WB": mc.UniformRotation(),
                                      "loads": mc.LoadDispersion(torque=Normal(std=1e-3))})
    again = pickle.loads(pickle.dumps(run))
    assert again.seed == run.seed and list(again.inputs) == list(run.inputs)
    np.testing.assert_array_equal(again.values("q_WB"), run.values("q_WB"))
    np.testing.assert_array_equal(again.inputs["inertia"], run.inputs["inertia"])
    for result in (run, again):
        for array in (*result.inputs.values(), *result.redraws.values()):
            with pytest.raises(ValueError, match="read-only"):
                array[...] = 0


def test_serial_equals_threaded_bitwise():
    dispersions = {"w_B": Normal(std=1e-2), "q_WB": mc.UniformRotation(),
                   "inertia": mc.InertiaDispersion(0.02, 0.02),
                   "loads": mc.LoadDispersion(torque=Normal(std=1e-4))}
    serial = small_run(n=9, steps=20, threads=1, dispersions=dispersions)
    threaded = small_run(n=9, steps=20, threads=2, dispersions=dispersions)
    for field in FIELDS:
        np.testing.assert_array_equal(getattr(serial.batch, field), getattr(threaded.batch, field))


def test_client_routes_to_distributed(monkeypatch):
    calls = []

    def fake_simulate_batch(model, initial, dt, steps, *, client, progress, **options):
        calls.append((client, progress))
        return rd.simulate_batch(model, initial, dt, steps, **options)

    monkeypatch.setitem(sys.modules, "rigiddyn.distributed",
                        types.SimpleNamespace(simulate_batch=fake_simulate_batch))
    remote = small_run(n=4, client="tcp://scheduler:8786")
    local = small_run(n=4)
    assert calls == [("tcp://scheduler:8786", False)]  # no bar unless progress=True
    np.testing.assert_array_equal(remote.batch.q_WB, local.batch.q_WB)


@pytest.mark.slow
def test_dask_cluster_run_equals_local_bitwise():
    distributed = pytest.importorskip("distributed")
    dispersions = {"w_B": Normal(std=1e-2), "q_WB": mc.UniformRotation(), "inertia": mc.InertiaDispersion(0.02, 0.02)}
    local = small_run(n=6, steps=20, dispersions=dispersions)
    # an in-process cluster (one worker thread) is enough to route through rigiddyn.distributed; its
    # multi-process behaviour is tests/python/test_distributed.py's
    cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0")
    with cluster, distributed.Client(cluster) as client:
        remote = small_run(n=6, steps=20, dispersions=dispersions, client=client)
    for field in FIELDS:
        assert np.asarray(getattr(remote.batch, field)).tobytes() == np.asarray(getattr(local.batch, field)).tobytes()


# ---------------------------------------------------------------------------------------------------
# the dispersions' distributions

def test_uniform_rotation_is_haar():
    n = 20000
    rng = np.random.default_rng(11)
    q = np.array([mc.UniformRotation().draw(rng, None) for _ in range(n)])
    np.testing.assert_allclose(np.linalg.norm(q, axis=1), 1.0, rtol=0, atol=4 * EPS)  # normalised: a few roundings
    # the rotation angle's empirical CDF against (θ - sin θ)/π: KS statistic below the DKW bound
    theta = np.sort(rotation_angle(q))
    F = haar_angle_cdf(theta)
    ks = max(np.max(np.arange(1, n + 1) / n - F), np.max(F - np.arange(n) / n))
    assert ks < dkw_bound(n)  # 0.019 at n = 2e4; a uniform angle on [0, π] would give ~0.32
    # E[R] = 0 under Haar; each entry has variance 1/3 (E[R_ij²] = 1/3 by symmetry of the columns), so
    # the mean of n draws has standard error sqrt(1/(3n)): 9 entries, Bonferroni
    mean_R = quat_matrix(q).mean(axis=0)
    assert np.max(np.abs(mean_R)) < z_bound(tests=9) * math.sqrt(1.0 / (3.0 * n))


def test_rotation_normal_angle_is_maxwell():
    n, std = 5000, 0.05
    nominal_q = np.array([0.2, -0.4, 0.1, 0.8]) / np.linalg.norm([0.2, -0.4, 0.1, 0.8])
    rng = np.random.default_rng(12)
    q = np.array([mc.RotationNormal(std).draw(rng, nominal_q) for _ in range(n)])
    # the angle from the nominal is |φ|, φ ~ N(0, std² I₃): a Maxwell (chi, 3 dof) variable of mean
    # 2 std sqrt(2/π) and variance std² (3 - 8/π)
    angle = angle_between(nominal_q, q)
    se = std * math.sqrt((3.0 - 8.0 / math.pi) / n)
    assert abs(angle.mean() - 2.0 * std * math.sqrt(2.0 / math.pi)) < z_bound() * se


def test_normal_and_uniform_means_and_spreads():
    n = 4000
    run = small_run(n=n, steps=1, dispersions={"w_B": Normal(mean=[0.01, 0.02, 0.03], std=[1e-3, 0.0, 2e-3]),
                                                "v_W": mc.Uniform([-1.0, 0.0, 2.0], [1.0, 0.0, 3.0])})
    w, v = run.inputs["w_B"], run.inputs["v_W"]
    z = z_bound(tests=4)
    # sample means within z standard errors (std/√n; a uniform on [a, b] has std (b - a)/√12)
    # (plus the mean's own round-off, n eps |mean|: an exact constant averages to itself only up to it)
    assert np.all(np.abs(w.mean(axis=0) - [0.01, 0.02, 0.03]) <=
                  z * np.array([1e-3, 0.0, 2e-3]) / math.sqrt(n) + n * EPS * 0.03)
    assert np.all(np.abs(v.mean(axis=0)[[0, 2]] - [0.0, 2.5]) < z * np.array([2.0, 1.0]) / math.sqrt(12 * n))
    assert np.all(w[:, 1] == 0.02) and np.all(v[:, 1] == 0.0)  # zero spread: the mean exactly
    assert np.all((v[:, 0] >= -1) & (v[:, 0] < 1) & (v[:, 2] >= 2) & (v[:, 2] < 3))


def test_uniform_draws_stay_below_high_where_the_sum_rounds_to_it():
    # low + (high - low) u rounds to high for u >= 1/2 on [0, 5e-324) (one subnormal step) and for u = 1 - 2**-53 on
    # [1, 2): such a draw is the largest double below high (here 0.0 and 2 - 2**-52), never high itself
    run = small_run(n=64, steps=1, dispersions={"v_W": mc.Uniform([0.0, 1.0, 0.0], [5e-324, 2.0, 1.0])})
    v = run.inputs["v_W"]
    assert np.all(v[:, 0] == 0.0) and np.all((v[:, 1] >= 1.0) & (v[:, 1] < 2.0))

    class TopOfUnitInterval:  # a generator whose u is the largest double below 1
        def random(self, shape):
            return np.full(shape, 1.0 - 2.0**-53)

    assert mc.Uniform(1.0, 2.0).draw(TopOfUnitInterval(), np.zeros(3)).tolist() == [2.0 - 2.0**-52] * 3
    assert mc.Uniform(3.0, 3.0).draw(TopOfUnitInterval(), np.zeros(1)).tolist() == [3.0]  # low == high: low
    with pytest.raises(ValueError, match=r"high: expected high - low finite"):
        mc.Uniform(-1e308, 1e308)


def principal_moments_valid(inertia):
    """Principal moments of each (3, 3) inertia by numpy, and whether they are a real body's: positive
    and obeying the triangle inequality, up to eigvalsh's backward error (a few eps |I|; Higham)."""
    J = np.linalg.eigvalsh(inertia)
    slack = 16 * EPS * np.abs(J).sum(axis=-1)
    return J, np.all(J > 0, axis=-1) & (J[..., 0] + J[..., 1] - J[..., 2] >= -slack)


def test_inertia_draws_are_always_physical_and_redraws_are_reported():
    # a nominal body 5 % away from the triangle inequality's edge, dispersed by 30 %: many draws are not
    # a real body's and must be redrawn
    flat = rd.RigidBody(1.0, [1.0, 1.0, 1.9])
    with pytest.warns(mc.DispersionWarning, match=r"dispersions\['inertia'\]: \d+ of 400 samples"):
        run = mc.monte_carlo(flat, rd.RigidBodyState(), 400, seed=3, dt=0.1, steps=1,
                             dispersions={"inertia": mc.InertiaDispersion(0.3, axis_std=0.5)})
    J, valid = principal_moments_valid(run.inputs["inertia"])
    assert valid.all()
    assert run.redraws["inertia"].sum() > 0
    np.testing.assert_array_equal(np.asarray(run.inputs["inertia"]), np.swapaxes(run.inputs["inertia"], 1, 2))
    # an impossible dispersion: no valid draw, ValueError naming the sample
    with pytest.raises(ValueError, match=r"dispersions\['inertia'\]: sample 0: no valid draw in 1 tries"):
        mc.monte_carlo(flat, rd.RigidBodyState(), 4, seed=5, dt=0.1, steps=1,
                       dispersions={"inertia": mc.InertiaDispersion([0.0, 0.0, 5.0], max_redraws=0)})


def test_inertia_mean_is_nominal():
    n, rel_std = 4000, 0.05
    # a nominal inertia with products (principal axes rotated off B), moments (2, 3, 4): a 25-σ margin
    # from the triangle edge at 5 %, so no draw is rejected and E[J'] = J
    c, s = math.cos(0.3), math.sin(0.3)
    E = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    nominal = E @ np.diag([2.0, 3.0, 4.0]) @ E.T
    dispersion = mc.InertiaDispersion(rel_std)
    dispersion.bind("inertia", nominal)
    rng = np.random.default_rng(21)
    draws = np.array([dispersion.draw(rng, nominal)[0] for _ in range(n)])
    # I'_ij = Σ_k E_ik E_jk J_k (1 + rel_std z_k): mean I_ij, variance rel_std² Σ_k (E_ik E_jk J_k)²
    se = rel_std * np.sqrt(np.einsum("ik,jk,k->ij", E**2, E**2, np.array([2.0, 3.0, 4.0]) ** 2)) / math.sqrt(n)
    # plus the round-off of rebuilding E diag(J') E^T and of the mean: a few eps |I| (Higham)
    assert np.all(np.abs(draws.mean(axis=0) - nominal) <= z_bound(tests=6) * se + 64 * EPS * 4.0)


def test_inertia_axes_perturbation():
    n, axis_std = 2000, 0.02
    nominal = np.diag([2.0, 3.0, 4.0])  # principal axes: B's own
    dispersion = mc.InertiaDispersion(0.0, axis_std)
    dispersion.bind("inertia", nominal)
    rng = np.random.default_rng(22)
    angles, turns = [], []
    for _ in range(n):
        inertia, J, phi = dispersion.draw(rng, nominal)
        moments, E_draw = np.linalg.eigh(inertia)
        # moments unchanged: eigvalsh's backward error, a few eps |I| (Higham)
        np.testing.assert_allclose(moments, [2.0, 3.0, 4.0], rtol=0, atol=64 * EPS * 4.0)
        # angle of the rotation taking B's axes to the drawn ones (each eigenvector up to its sign)
        R = E_draw * np.sign(np.diag(E_draw))
        angles.append(math.acos(min(1.0, (np.trace(R) - 1.0) / 2.0)))
        turns.append(np.linalg.norm(phi))
    angles, turns = np.array(angles), np.array(turns)
    # the axes turn by |φ|: eigenvectors err by ≤ 8 eps |I| / gap = 32 eps (Davis-Kahan, gap 1 kg m^2),
    # the trace by 6 times that, and acos by that over sin θ
    assert np.all(np.abs(angles - turns) <= 6 * 64 * EPS / np.sin(turns))
    # φ ~ N(0, axis_std² I₃): |φ| is Maxwell, mean 2 σ sqrt(2/π), variance σ² (3 - 8/π)
    se = axis_std * math.sqrt((3.0 - 8.0 / math.pi) / n)
    assert abs(turns.mean() - 2 * axis_std * math.sqrt(2 / math.pi)) < z_bound() * se


def test_mass_dispersion_keeps_an_unrealizable_test_body():
    # Hairer-Lubich-Wanner's I = diag(2, 1, 2/3) (no real body has it: accepted on purpose by its maker)
    hlw = rd.RigidBody(1.0, [2.0, 1.0, 2.0 / 3.0], check=rd.InertiaCheck.allow_unrealizable)
    run = mc.monte_carlo(hlw, rd.RigidBodyState(w_B=[math.cos(1.1), 0.0, math.sin(1.1)]), 3, seed=2, dt=0.1, steps=2,
                         dispersions={"mass": mc.Uniform(0.5, 2.0)})
    assert np.all((run.inputs["mass"] >= 0.5) & (run.inputs["mass"] < 2.0))


def test_load_and_gravity_dispersions_reach_the_runs():
    run = small_run(n=4, steps=3, gravity=True,
                    dispersions={"gravity": Normal(std=[0.0, 0.0, 0.01]),
                                 "mass": mc.Uniform(11.0, 13.0),
                                 "loads": mc.LoadDispersion(force=Normal(std=0.5), frame="world")})
    assert np.all(run.inputs["gravity"][:, :2] == 0) and np.all(run.inputs["gravity"][:, 2] != -9.81)
    # each sample ran with its own body, gravity and load: the batch is the serial runs of the drawn inputs
    bodies = [rd.RigidBody(m, SATELLITE.inertia_com) for m in run.inputs["mass"]]
    loads = [[rd.AppliedLoad(force=f)] for f in run.inputs["loads.force"]]
    initial = {key: np.tile(getattr(TUMBLE, key), (4, 1)) for key in ("p_W", "q_WB", "v_W", "w_B")}
    serial = serial_batch(bodies, initial, 0.5, 3, loads=loads, gravity=run.inputs["gravity"])
    for field in FIELDS:
        np.testing.assert_array_equal(getattr(run.batch, field), getattr(serial, field), err_msg=field)
    # centre of mass: p(t) = ½ (g + f/m) t² from rest (constant acceleration; RK4 is exact on a quadratic
    # up to round-off: ~10 roundings of numbers ≤ |a| t²)
    t = run.values("t")[:, -1]
    a = run.inputs["gravity"] + run.inputs["loads.force"] / run.inputs["mass"][:, None]
    expected = 0.5 * a * t[:, None] ** 2
    np.testing.assert_allclose(run.values("p_W")[:, -1], expected, rtol=0,
                               atol=16 * EPS * np.max(np.abs(expected)) * 3)


# ---------------------------------------------------------------------------------------------------
# scenes

def sat_and_tip():
    scene = rd.Scene()
    scene.add_body(rd.RigidBody(12.0, [0.10, 0.14, 0.18]), name="sat")
    scene.add_body(rd.Particle(1.0), name="tip")
    scene.add(rd.SpringDamper(body_a=0, point_a_B=(0, 0, 0.2), body_b=1, stiffness=5.0, rest_length=0.5))
    return scene, [rd.RigidBodyState(w_B=[0.0, 0.1, 0.02]), rd.ParticleState(p_W=[0.0, 0.0, 0.7])]


def test_scene_bodies_are_dispersed_by_name():
    scene, nominal = sat_and_tip()
    run = mc.monte_carlo(scene, nominal, 4, seed=5, dt=0.05, steps=10, record_every=5,
                         dispersions={"tip.p_W": Normal(std=0.01), "sat.w_B": Normal(std=0.01),
                                      "sat.q_WB": mc.UniformRotation(), "sat.inertia": mc.InertiaDispersion(0.05),
                                      "tip.mass": mc.Uniform(0.5, 1.5)})
    assert list(run.inputs) == ["sat.q_WB", "sat.w_B", "sat.inertia", "sat.inertia_moments",
                                "sat.inertia_axis_rotation", "tip.p_W", "tip.mass"]
    np.testing.assert_array_equal(run.values("w_B", at=0.0)[:, 0], run.inputs["sat.w_B"])
    np.testing.assert_array_equal(run.values("mass", at=0.0)[:, 1], run.inputs["tip.mass"])
    # each sample is the serial run of its scene (drawn bodies, same spring) from its drawn states
    for i in range(4):
        sample_scene = rd.Scene()
        sample_scene.add_body(rd.RigidBody(12.0, run.inputs["sat.inertia"][i]), name="sat")
        sample_scene.add_body(rd.Particle(float(run.inputs["tip.mass"][i])), name="tip")
        sample_scene.add(scene.elements[0])
        states = [rd.RigidBodyState(q_WB=run.inputs["sat.q_WB"][i], w_B=run.inputs["sat.w_B"][i]),
                  rd.ParticleState(p_W=run.inputs["tip.p_W"][i])]
        serial = rd.simulate(sample_scene, states, 0.05, 10, record_every=5)
        for field in ("p_W", "q_WB", "v_W", "w_B", "total_energy"):
            np.testing.assert_array_equal(np.asarray(getattr(run.batch, field))[i], getattr(serial, field))


def test_compiled_scene_runs_its_method():
    scene, nominal = sat_and_tip()
    compiled = scene.compile("rk4")
    dispersions = {"sat.w_B": Normal(std=0.01), "sat.mass": mc.Uniform(11.0, 13.0)}
    from_compiled = mc.monte_carlo(compiled, nominal, 3, seed=2, dt=0.05, steps=4, dispersions=dispersions)
    from_scene = mc.monte_carlo(scene, nominal, 3, seed=2, dt=0.05, steps=4, method="rk4", dispersions=dispersions)
    np.testing.assert_array_equal(from_compiled.batch.q_WB, from_scene.batch.q_WB)


def test_scene_bad_input():
    scene, nominal = sat_and_tip()
    with pytest.raises(ValueError, match=r"dispersions: expected keys among sat.p_W, .* got 'sat.theta'"):
        mc.monte_carlo(scene, nominal, 2, seed=1, dt=0.1, steps=1, dispersions={"sat.theta": Normal(std=1.0)})
    with pytest.raises(TypeError,
                       match=r"dispersions\['tip.mass'\]: expected Normal or Uniform, got InertiaDispersion"):
        mc.monte_carlo(scene, nominal, 2, seed=1, dt=0.1, steps=1, dispersions={"tip.mass": mc.InertiaDispersion(0.1)})
    with pytest.raises(ValueError, match=r"nominal_state: expected a list of the states of the scene's 2 bodies"):
        mc.monte_carlo(scene, nominal[:1], 2, seed=1, dt=0.1, steps=1)
    with pytest.raises(TypeError, match=r"nominal_state: expected a ParticleState for body 'tip', got RigidBodyState"):
        mc.monte_carlo(scene, [nominal[0], nominal[0]], 2, seed=1, dt=0.1, steps=1)


def pivoted_top_and_pendulum():
    """A heavy top pinned at its tip and a planar pendulum, under gravity, with their nominal states."""
    scene = rd.Scene()
    scene.add_body(rd.PivotedBody(rd.RigidBody(2.0, [0.02, 0.02, 0.01]), p_OC_B=[0.0, 0.0, 0.1]), name="top")
    scene.add_body(rd.PivotedPlanarBody(1.0, 0.01, p_OC_B=[0.0, -0.5]), name="p")
    scene.add(rd.UniformGravity())
    tilted = [math.sin(0.1), 0.0, 0.0, math.cos(0.1)]  # 0.2 rad about x
    return scene, [rd.PivotedBodyState(q_WB=tilted, w_B=[0.0, 0.0, 30.0]), rd.PivotedPlanarBodyState(theta=0.3)]


def test_pivoted_bodies_states_are_dispersed():
    scene, nominal = pivoted_top_and_pendulum()
    dispersions = {"p.omega": mc.Uniform(-0.1, 0.1), "p.theta": Normal(std=0.05),
                   "top.w_B": Normal(std=[0.1, 0.1, 1.0]), "top.q_WB": mc.RotationNormal(0.02)}
    run = mc.monte_carlo(scene, nominal, 4, seed=3, dt=0.01, steps=6, record_every=3, dispersions=dispersions)
    assert list(run.inputs) == ["top.q_WB", "top.w_B", "p.theta", "p.omega"]
    assert run.inputs["p.theta"].shape == (4,) and run.inputs["top.w_B"].shape == (4, 3)
    assert np.all(run.inputs["p.theta"] != 0.3) and np.all(run.inputs["p.omega"] != 0.0)
    np.testing.assert_array_equal(run.values("w_B", at=0.0)[:, 0], run.inputs["top.w_B"])
    np.testing.assert_array_equal(run.values("q_WB", at=0.0)[:, 0], run.inputs["top.q_WB"])
    # each sample is the serial run of the scene from its drawn states
    for i in range(4):
        states = [rd.PivotedBodyState(q_WB=run.inputs["top.q_WB"][i], w_B=run.inputs["top.w_B"][i]),
                  rd.PivotedPlanarBodyState(theta=run.inputs["p.theta"][i], omega=run.inputs["p.omega"][i])]
        serial = rd.simulate(scene, states, 0.01, 6, record_every=3)
        for field in ("q_WB", "w_B", "total_energy"):
            np.testing.assert_array_equal(np.asarray(getattr(run.batch, field))[i], getattr(serial, field))


def floating_chain():
    """A free-floating base with a ball-jointed, a hinged and a welded link, and its nominal joint states."""
    tree = rd.Tree()
    box = rd.SpatialInertia(2.0, [0.1, 0.0, 0.0], np.diag([0.02, 0.03, 0.04]))
    along = rd.Transform(translation=[0.3, 0.0, 0.0])
    tree.add_link("base", -1, rd.FreeJoint(), box)
    tree.add_link("ball", 0, rd.SphericalJoint(), box, along)
    tree.add_link("hinge", 1, rd.RevoluteJoint([0.0, 0.0, 1.0]), box, along)
    tree.add_link("weld", 2, rd.FixedJoint(), box, along)
    scene = rd.Scene()
    scene.add_tree(tree, "sc")
    base_q = [1.0, -2.0, 0.5, *(np.array([0.1, 0.2, -0.3, 0.9]) / np.linalg.norm([0.1, 0.2, -0.3, 0.9]))]
    q = np.concatenate([base_q, [0.0, 0.0, 0.0, 1.0], [0.4]])
    return tree, scene, tree.joint_states(q, 0.1 * np.arange(1, tree.nv + 1))


def test_tree_links_are_dispersed_in_their_joints():
    tree, scene, nominal = floating_chain()
    n, std = 400, 0.05
    dispersions = {"sc.hinge.v": mc.Uniform(-1.0, 1.0), "sc.hinge.q": Normal(std=0.2), "sc.ball.q": mc.UniformRotation(),
                   "sc.base.v": Normal(std=0.01), "sc.base.q": mc.RotationNormal(std)}
    run = mc.monte_carlo(scene, nominal, n, seed=4, dt=0.01, steps=1, dispersions=dispersions, error=False)
    assert list(run.inputs) == ["sc.base.q", "sc.base.v", "sc.ball.q", "sc.hinge.q", "sc.hinge.v"]
    assert [run.inputs[k].shape for k in run.inputs] == [(n, 7), (n, 6), (n, 4), (n, 1), (n, 1)]
    # the records start at the drawn joint states (the ball's rate, not dispersed, at its nominal value)
    np.testing.assert_array_equal(run.values("joint_q", at=0.0), np.hstack(
        [run.inputs["sc.base.q"], run.inputs["sc.ball.q"], run.inputs["sc.hinge.q"]]))
    np.testing.assert_array_equal(run.values("joint_v", at=0.0), np.hstack(
        [run.inputs["sc.base.v"], np.tile(nominal[1].v, (n, 1)), run.inputs["sc.hinge.v"]]))
    # a free joint's attitude is rotated about its nominal value, its position kept; the angle is |φ|, φ ~ N(0, std² I₃):
    # a Maxwell variable of mean 2 std sqrt(2/π), standard error std sqrt((3 - 8/π)/n)
    np.testing.assert_array_equal(run.inputs["sc.base.q"][:, :3], np.tile(nominal[0].q[:3], (n, 1)))
    angle = angle_between(nominal[0].q[3:], run.inputs["sc.base.q"][:, 3:])
    assert abs(angle.mean() - 2.0 * std * math.sqrt(2.0 / math.pi)) < z_bound() * std * math.sqrt((3.0 - 8.0 / math.pi) / n)
    # unit quaternions to a few roundings (a normalised 4-vector; the product of two unit quaternions)
    for key in ("sc.ball.q", "sc.base.q"):
        np.testing.assert_allclose(np.linalg.norm(run.inputs[key][:, -4:], axis=1), 1.0, rtol=0, atol=8 * EPS)
    # each sample is the serial run of the scene from its drawn joint states
    for i in (0, n - 1):
        drawn = {key: run.inputs[key][i] for key in run.inputs}
        states = [rd.JointState(drawn["sc.base.q"], drawn["sc.base.v"]), rd.JointState(drawn["sc.ball.q"], nominal[1].v),
                  rd.JointState(drawn["sc.hinge.q"], drawn["sc.hinge.v"]), nominal[3]]
        serial = rd.simulate(scene, states, 0.01, 1, error=False)
        for field in ("joint_q", "joint_v", "q_WB", "total_energy"):
            np.testing.assert_array_equal(np.asarray(getattr(run.batch, field))[i], getattr(serial, field))


def test_a_joint_q_is_dispersed_as_its_joint_allows():
    _, scene, nominal = floating_chain()
    for key, dispersion, message in (
            ("sc.ball.q", Normal(std=0.1), "expected UniformRotation or RotationNormal for a spherical joint's q (4,), "
                                           "got Normal"),
            ("sc.base.q", mc.Uniform(0.0, 1.0), "expected UniformRotation or RotationNormal for a free joint's q (7,), "
                                                "got Uniform"),
            ("sc.hinge.q", mc.UniformRotation(), "expected Normal or Uniform for a revolute or prismatic joint's q (1,), "
                                                 "got UniformRotation")):
        with pytest.raises(TypeError, match=re.escape(f"dispersions[{key!r}]: {message}")):
            mc.monte_carlo(scene, nominal, 2, seed=1, dt=0.1, steps=1, dispersions={key: dispersion})
    # a fixed joint has no coordinates to disperse: its link has no key
    with pytest.raises(ValueError, match=r"^dispersions: expected keys among sc\.base\.q, sc\.base\.v, sc\.ball\.q, "
                                         r"sc\.ball\.v, sc\.hinge\.q, sc\.hinge\.v, got 'sc\.weld\.q'$"):
        mc.monte_carlo(scene, nominal, 2, seed=1, dt=0.1, steps=1, dispersions={"sc.weld.q": Normal(std=1.0)})
    with pytest.raises(TypeError, match=r"nominal_state: expected a JointState for body 'sc\.base', got RigidBodyState"):
        mc.monte_carlo(scene, [rd.RigidBodyState(), *nominal[1:]], 2, seed=1, dt=0.1, steps=1)


def test_a_wrong_key_lists_the_valid_ones():
    scene, nominal = pivoted_top_and_pendulum()
    with pytest.raises(ValueError, match=r"^dispersions: expected keys among top\.q_WB, top\.w_B, p\.theta, p\.omega, "
                                         r"got 'p\.thetta'$"):
        mc.monte_carlo(scene, nominal, 2, seed=1, dt=0.1, steps=1, dispersions={"p.thetta": Normal(std=1.0)})
    many = rd.Scene(bodies=[rd.Particle(1.0)] * 100)
    with pytest.raises(ValueError) as e:
        mc.monte_carlo(many, [rd.ParticleState()] * 100, 2, seed=1, dt=0.1, steps=1, dispersions={"x": Normal(std=1.0)})
    assert str(e.value).startswith("dispersions: expected keys among body0.p_W, body0.v_W, body0.mass, body1.p_W, ")
    assert str(e.value).endswith(", ... (300 keys), got 'x'")
    planar = rd.Scene(bodies=[rd.PlanarBody(1.0, 1.0)])
    with pytest.raises(ValueError, match=r"^dispersions: expected no key \(no body of the scene has a dispersible"):
        mc.monte_carlo(planar, [rd.PlanarBodyState()], 2, seed=1, dt=0.1, steps=1, dispersions={"x": Normal(std=1.0)})


def test_the_memory_estimate_refuses_a_run_before_any_draw(monkeypatch):
    def no_draw(*args, **kwargs):
        raise AssertionError("drawn before the memory estimate")

    monkeypatch.setattr(mc, "_sample", no_draw)
    monkeypatch.setattr(mc, "available_bytes", lambda: 2**34)
    with pytest.raises(ValueError) as e:
        mc.monte_carlo(SATELLITE, TUMBLE, 10**7, seed=1, dt=0.01, steps=10**4, dispersions={"w_B": Normal(std=0.1)})
    # 10^4 steps: 10001 records, the error estimate's own values at each; its two coarse runs record every 4th step
    body_record = mc._SCENE_RECORD_DOUBLES[0] + mc._SCENE_RECORD_DOUBLES[1] + 2 * mc._SCENE_RECORD_DOUBLES[2]
    per_sample = mc._SAMPLE_BYTES + (10001 * (body_record + mc._ERROR_DOUBLES) + 2 * 2501 * body_record) * 8
    assert str(e.value) == (
        f"n: expected a sample count whose runs fit in the available memory (16 GiB: at most {2**34 // per_sample} "
        f"samples of 10001 records, {mc.format_bytes(per_sample)} each), got 10000000 (an estimated "
        f"{mc.format_bytes(10**7 * per_sample)}; fewer samples, or a larger record_every)")
    scene, nominal = sat_and_tip()
    # 2 bodies, 1 element; 10 steps recorded every 4th: steps 0, 4, 8 and the last, 10 (with the error estimate its
    # own values per record, and its two coarse runs recording steps 0, 4 and 8)
    scene_record = 10 + 20 * 2 + 2 * 1
    per_sample = (mc._SAMPLE_BYTES + 2 * mc._STATE_BYTES
                  + (4 * (scene_record + mc._ERROR_DOUBLES) + 2 * 3 * scene_record) * 8)
    with pytest.raises(ValueError, match=rf"at most {2**34 // per_sample} samples of 4 records"):
        mc.monte_carlo(scene, nominal, 10**9, seed=1, dt=0.01, steps=10, record_every=4)


def test_a_sample_count_beyond_any_memory_is_named():
    with pytest.raises(ValueError, match=r"^n: expected a sample count whose runs fit in the available memory .* "
                                         r"got 100000000000000000000 \(an estimated"):
        mc.monte_carlo(SATELLITE, TUMBLE, 10**20, seed=1, dt=0.1, steps=1)


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(steps=-1), ValueError, r"^steps: expected an integer >= 0, got -1$"),
    (dict(steps=2.5), TypeError, r"^steps: expected an integer >= 0, got 2.5$"),
    (dict(record_every=0), ValueError, r"^record_every: expected an integer >= 1, got 0$"),
    (dict(record_every=True), TypeError, r"^record_every: expected an integer >= 1, got True$"),
])
def test_steps_and_record_every_are_checked_before_any_draw(monkeypatch, kwargs, error, message):
    monkeypatch.setattr(mc, "_sample", None)  # a draw would be a TypeError naming no argument
    options = dict(seed=1, dt=0.1, steps=2)
    options.update(kwargs)
    with pytest.raises(error, match=message):
        mc.monte_carlo(SATELLITE, TUMBLE, 2, **options)


# ---------------------------------------------------------------------------------------------------
# statistics

def fake_result(values, times):
    """A MonteCarloResult over known per-record values (N, n_records) (no simulation)."""
    batch = types.SimpleNamespace(t=np.broadcast_to(times, values.shape).copy(), kinetic_energy=values)
    return mc.MonteCarloResult(batch, {}, {}, 0, {})


def test_statistics_match_numpy_on_known_draws():
    rng = np.random.default_rng(5)
    values = rng.gamma(2.0, size=(500, 4))
    run = fake_result(values, [0.0, 1.0, 2.0, 3.0])
    stats = run.statistics("kinetic_energy", q=(1, 25, 50, 99))
    # the same sums in a possibly different order: n - 1 roundings of terms ≤ max|x| (Higham, §4.2)
    tol = 500 * EPS * np.max(values)
    np.testing.assert_allclose(stats.mean, values.sum(axis=0) / 500, rtol=0, atol=tol)
    deviation = values - values.sum(axis=0) / 500
    np.testing.assert_allclose(stats.std, np.sqrt((deviation**2).sum(axis=0) / 499), rtol=0, atol=tol)
    np.testing.assert_array_equal(stats.min, values.min(axis=0))
    np.testing.assert_array_equal(stats.max, values.max(axis=0))
    # numpy's linear percentile by hand: sorted values at rank (n - 1) q / 100, interpolated
    ordered = np.sort(values, axis=0)
    for row, q in zip(stats.percentiles, (1, 25, 50, 99)):
        rank = (500 - 1) * q / 100
        low = int(math.floor(rank))
        expected = ordered[low] + (rank - low) * (ordered[min(low + 1, 499)] - ordered[low])
        np.testing.assert_allclose(row, expected, rtol=0, atol=4 * EPS * np.max(values))
    assert np.all(stats.count == 500) and stats.t.tolist() == [0.0, 1.0, 2.0, 3.0]
    at = run.statistics("kinetic_energy", at=2.0)
    assert at.t == 2.0
    np.testing.assert_allclose(at.mean, stats.mean[2], rtol=0, atol=tol)  # one column, summed in another order
    np.testing.assert_array_equal(run.percentiles(lambda batch: batch.kinetic_energy * 2, q=50, at=3.0),
                                  [2 * stats.percentiles[2, 3]])


def test_statistics_leave_out_diverged_rows():
    values = np.array([[1.0, 2.0, 3.0], [3.0, 4.0, np.nan], [5.0, np.nan, np.nan]])
    stats = fake_result(values, [0.0, 1.0, 2.0]).statistics("kinetic_energy", q=50)
    assert stats.count.tolist() == [3, 2, 1]
    assert stats.mean.tolist() == [3.0, 3.0, 3.0]
    assert stats.std[0] == 2.0 and stats.std[1] == math.sqrt(2.0) and np.isnan(stats.std[2])
    assert stats.percentiles.tolist() == [[3.0, 3.0, 3.0]]


def test_diverged_samples_are_left_out_of_the_statistics():
    # RK4 on Euler's equations is unstable once h |w| is large (shared notes: beyond ~2.8): rates up to
    # 8 rad/s at h = 1 s make some samples non-finite; they stop alone (NaN rows after they stopped)
    with pytest.warns(RuntimeWarning, match=r"simulate_batch: \d+ of 8 samples became non-finite"):
        run = mc.monte_carlo(rd.RigidBody(1.0, [1.0, 2.0, 2.5]), rd.RigidBodyState(), 8, seed=1, dt=1.0, steps=200,
                             record_every=20, dispersions={"w_B": mc.Uniform([0, 0, 0], [0.1, 8.0, 0.1])})
    diverged = np.asarray(run.batch.diverged)
    assert 0 < diverged.sum() < 8
    stats = run.statistics("kinetic_energy", at=200.0)
    finite = run.values("kinetic_energy", at=200.0)[~diverged]
    assert stats.count == len(finite)
    np.testing.assert_allclose(stats.mean, finite.sum() / len(finite), rtol=8 * EPS)  # ≤ 8 terms: 8 roundings


# ---------------------------------------------------------------------------------------------------
# the documented example and its physics

def example_code():
    (code,) = [block for block in re.findall(r"```python\n(.*?)```", (ROOT / "docs/monte_carlo.md").read_text(),
                                             flags=re.DOTALL) if "monte_carlo(" in block]
    return code


def test_documented_example_runs_shortened(capsys):
    code = example_code()
    for long, short in (("N = 1000 ", "N = 24 "), ("DURATION = 3600.0 ", "DURATION = 120.0 "),
                        ("RECORD = 600.0 ", "RECORD = 60.0 ")):
        assert long in code
        code = code.replace(long, short)
    exec(compile(code, "docs/monte_carlo.md", "exec"), {})
    printed = capsys.readouterr().out
    percentiles = [float(x) for x in re.findall(r"\d+%: ([\d.]+)", printed)]
    assert len(percentiles) == 4 and percentiles == sorted(percentiles)
    assert "rank correlation with the error: rates" in printed


@pytest.mark.slow
def test_documented_output_is_what_the_example_prints(capsys):
    # the full example (1000 samples x 3600 RK4 steps, twice: a few seconds): its printed lines are the doc's
    text = (ROOT / "docs/monte_carlo.md").read_text()
    exec(compile(example_code(), "docs/monte_carlo.md", "exec"), {})
    for line in capsys.readouterr().out.splitlines():
        assert line in text, line


def test_zero_dispersion_gives_zero_attitude_error():
    n, steps = 6, 40
    zero = {"q_WB": mc.UniformRotation(), "w_B": Normal(std=0.0),
            "inertia": mc.InertiaDispersion(0.0, 0.0),
            "loads": mc.LoadDispersion(torque=Normal(std=0.0))}
    run = mc.monte_carlo(SATELLITE, TUMBLE, n, seed=1, dispersions=zero, dt=0.5, steps=steps, record_every=10)
    predicted = serial_batch(SATELLITE, {"p_W": np.zeros((n, 3)), "q_WB": run.inputs["q_WB"],
                                         "v_W": np.zeros((n, 3)), "w_B": np.tile(TUMBLE.w_B, (n, 1))},
                             0.5, steps, record_every=10)
    # nothing dispersed but the attitude: each sample IS the nominal run from its attitude (the same body
    # bitwise: the inertia rebuilt from exact principal axes, the zero torque adds exact zeros)
    assert np.all(angle_between(predicted.q_WB, run.batch.q_WB) == 0.0)
    assert np.all(mc.attitude_error(run.batch.q_WB, predicted.q_WB) == 0.0)


def test_attitude_error_is_the_angle_between_attitudes():
    rng = np.random.default_rng(9)
    a = rng.standard_normal((200, 4))
    a /= np.linalg.norm(a, axis=1, keepdims=True)
    b = rng.standard_normal((200, 4))
    b /= np.linalg.norm(b, axis=1, keepdims=True)
    # either side: a product of unit quaternions (≤ 4 roundings per component, ~2 eps) then atan2 of
    # a norm (a few eps): ≤ 16 eps [rad] in all (d atan2 ≤ 1 per unit argument)
    tolerance = 16 * EPS
    np.testing.assert_allclose(mc.attitude_error(a, b), angle_between(a, b), rtol=0, atol=tolerance)
    np.testing.assert_allclose(mc.attitude_error(a, -b), angle_between(a, b), rtol=0, atol=tolerance)
    stacked = mc.attitude_error(a.reshape(20, 10, 4), b[:10])  # broadcasting (N, n, 4) with (n, 4)
    np.testing.assert_allclose(stacked, angle_between(a.reshape(20, 10, 4), b[:10]), rtol=0, atol=tolerance)


def test_torque_free_samples_keep_momentum_and_energy_within_rk4_bound():
    n, dt, steps = 8, 0.5, 400
    run = mc.monte_carlo(SATELLITE, TUMBLE, n, seed=4, dt=dt, steps=steps, record_every=50,
                         dispersions={"q_WB": mc.UniformRotation(), "w_B": Normal(std=0.01),
                                      "inertia": mc.InertiaDispersion(0.05, 0.1)})
    inertia = run.inputs["inertia"]                        # (N, 3, 3) about the centre of mass, in B
    w_B = run.values("w_B")                                # (N, records, 3) [rad/s] in B: the body's records
    m_B = np.einsum("nij,nrj->nri", inertia, w_B)          # body angular momentum I w (N, records, 3)
    H = np.linalg.norm(m_B, axis=-1)
    T = 0.5 * np.einsum("nri,nri->nr", m_B, w_B)
    J = np.linalg.eigvalsh(inertia)
    kappa = J[:, 2] / J[:, 0]
    # RK4's local error on Euler's equations m' = m × I⁻¹m, a quadratic field with |a × I⁻¹b| ≤ |a||b|/I_min:
    # by majorants (the scalar u' = u²/I_min, whose exact Taylor coefficients and RK4's are both ≤ 1 per
    # power of x = h|m|/I_min, RK4's weights being positive), |e| ≤ 2 |m| x⁵/(1 - x) per step. The flow keeps
    # |m| and T, so |Δ|m|| ≤ |e| and |ΔT|/T ≤ 2|e|/(I_min |ω|) ≤ 4 κ x⁵/(1 - x) per step; round-off adds
    # 16 κ eps per step and side (tests/python/_error_bounds.local_roundoff)
    x = dt * H.max(axis=1) / J[:, 0]
    truncation = steps * 2 * x**5 / (1 - x)
    roundoff = steps * 16 * EPS * kappa
    assert np.all(np.abs(H / H[:, :1] - 1).max(axis=1) <= truncation + roundoff)
    assert np.all(np.abs(T / T[:, :1] - 1).max(axis=1) <= 2 * kappa * truncation + 2 * roundoff)


# ---------------------------------------------------------------------------------------------------
# bad input

@pytest.mark.parametrize("kwargs, error, message", [
    (dict(n=0), ValueError, r"n: expected a sample count >= 1, got 0"),
    (dict(n=2.5), TypeError, r"n: expected a sample count"),
    (dict(n=True), TypeError, r"n: expected a sample count"),
    (dict(seed=-1), ValueError, r"seed: expected an integer >= 0, got -1"),
    (dict(seed="x"), TypeError, r"seed: expected an integer"),
    (dict(dispersions={"omega": Normal(std=1.0)}), ValueError, r"dispersions: expected keys among .* got 'omega'"),
    (dict(dispersions={"q_WB": Normal(std=1.0)}), TypeError,
     r"dispersions\['q_WB'\]: expected UniformRotation or RotationNormal, got Normal"),
    (dict(dispersions={"w_B": 0.1}), TypeError, r"dispersions\['w_B'\]: expected Normal or Uniform, got 0.1"),
    (dict(dispersions={"w_B": Normal(std=[1.0, 2.0])}), ValueError,
     r"dispersions\['w_B'\].std: expected a shape that broadcasts to \(3,\), got \(2,\)"),
    (dict(dispersions=[1]), TypeError, r"dispersions: expected a dict"),
    (dict(client="tcp://x:1", threads=2), ValueError, r"threads: expected None with client="),
])
def test_bad_arguments_are_named(kwargs, error, message):
    options = dict(n=2, seed=1, dt=0.5, steps=2)
    options.update(kwargs)
    with pytest.raises(error, match=message):
        mc.monte_carlo(SATELLITE, TUMBLE, options.pop("n"), **options)


def test_bad_model_state_and_dispersion_parameters():
    with pytest.raises(TypeError, match=r"model: expected a RigidBody, a Scene or a CompiledScene, got Particle"):
        mc.monte_carlo(rd.Particle(1.0), TUMBLE, 2, seed=1, dt=0.5, steps=1)
    with pytest.raises(TypeError, match=r"nominal_state: expected a RigidBodyState"):
        mc.monte_carlo(SATELLITE, rd.ParticleState(), 2, seed=1, dt=0.5, steps=1)
    with pytest.raises(ValueError, match=r"std: expected a standard deviation >= 0, got -1"):
        Normal(std=-1)
    with pytest.raises(TypeError, match=r"std: expected a standard deviation >= 0 .* got None"):
        Normal(0.0)
    with pytest.raises(ValueError, match=r"mean: expected finite values"):
        Normal(np.nan, 1.0)
    with pytest.raises(ValueError, match=r"high: expected high >= low"):
        mc.Uniform(1.0, 0.0)
    with pytest.raises(ValueError, match=r"rel_std: expected a relative standard deviation >= 0"):
        mc.InertiaDispersion(-0.1)
    with pytest.raises(ValueError, match=r"axis_std: expected a standard deviation >= 0"):
        mc.InertiaDispersion(0.1, -1.0)
    with pytest.raises(ValueError, match=r"std: expected a standard deviation >= 0 \[rad\]"):
        mc.RotationNormal(-0.1)
    with pytest.raises(TypeError, match=r"torque: expected None or a Normal / Uniform dispersion"):
        mc.LoadDispersion(torque=mc.UniformRotation())
    with pytest.raises(ValueError, match=r"nominal: expected a physically valid inertia"):
        mc.monte_carlo(SATELLITE, TUMBLE, 2, seed=1, dt=0.5, steps=1,
                       dispersions={"inertia": mc.InertiaDispersion(0.1, nominal=np.diag([1.0, 1.0, 3.0]))})


def test_bad_statistics_arguments():
    run = fake_result(np.ones((3, 2)), [0.0, 1.0])
    with pytest.raises(ValueError, match=r"quantity: expected a recorded field .* got 'energy'"):
        run.statistics("energy")
    with pytest.raises(TypeError, match=r"quantity: expected a field name \(str\) or a callable"):
        run.statistics(3)
    with pytest.raises(ValueError, match=r"quantity: expected the callable to return an array \(N, n_records"):
        run.statistics(lambda batch: np.ones(3))
    with pytest.raises(ValueError, match=r"at: expected a recorded time \[s\] \(2 records from 0 to 1 s"):
        run.statistics("kinetic_energy", at=0.5)
    with pytest.raises(TypeError, match=r"at: expected None or a recorded time"):
        run.statistics("kinetic_energy", at="end")
    with pytest.raises(ValueError, match=r"q: expected percents in \[0, 100\]"):
        run.percentiles("kinetic_energy", q=(50, 101))
