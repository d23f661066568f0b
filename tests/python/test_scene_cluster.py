"""The [[cluster]] generator of scene files (a Plummer sphere, Aarseth, Henon & Wielen 1974) and the shipped
1000-particle cluster: deterministic from its seed, in virial equilibrium within its sampling error, with
zero momentum; a short run conserves linear and angular momentum to round-off and energy to the method's
error; bad generator input is a ValueError naming the field."""

import math

import numpy as np
import pytest

import rigiddyn
from rigiddyn.scene_file import plummer_sphere, read_scene, scene_to_toml

EPS = np.finfo(float).eps
A_NBODY = 3 * math.pi / 16  # the Plummer scale radius of E = -1/4 with G = M = 1

SMALL = """
[[cluster]]
model = "plummer"
count = 50
total_mass = 1
scale_radius = 1
G = 1
seed = 7
"""


def _arrays(states):
    """(p_W, v_W) of particle states as (n, 3) arrays."""
    return (np.array([s.p_W for s in states], dtype=float), np.array([s.v_W for s in states], dtype=float))


def _energies(m, p, v, G):
    """(T, V) of equal masses m: V the unsoftened direct sum over pairs i < j (numpy)."""
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(axis=-1))
    i, j = np.triu_indices(len(p), 1)
    return 0.5 * m * np.sum(v ** 2), -G * m * m * np.sum(1.0 / d[i, j])


# ---------------------------------------------------------------- the generator
def test_the_shipped_cluster_is_1000_particles_under_their_mutual_gravity():
    f = read_scene("cluster")
    assert len(f.scene.bodies) == 1000 and all(isinstance(b, rigiddyn.Particle) for b in f.scene.bodies)
    assert f.scene.body_names[0] == "star0" and f.scene.body_names[-1] == "star999"
    (gravity,) = f.scene.elements
    assert isinstance(gravity, rigiddyn.MutualGravity)
    assert (gravity.G, gravity.softening, gravity.bodies) == (1.0, 0.01, None)
    assert sum(b.mass for b in f.scene.bodies) == pytest.approx(1.0, rel=1000 * EPS)


def test_the_generator_is_deterministic_from_its_seed():
    a, b = read_scene(SMALL), read_scene(SMALL)
    for x, y in zip(_arrays(a.initial), _arrays(b.initial)):
        np.testing.assert_array_equal(x, y)
    c = read_scene(SMALL.replace("seed = 7", "seed = 8"))
    assert not np.array_equal(_arrays(a.initial)[0], _arrays(c.initial)[0])
    # the file's draw is plummer_sphere's with numpy.random.default_rng(seed)
    _, p_W, v_W = plummer_sphere(50, 1.0, 1.0, 1.0, np.random.default_rng(7))
    np.testing.assert_array_equal(_arrays(a.initial)[0], p_W)
    np.testing.assert_array_equal(_arrays(a.initial)[1], v_W)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_virial_ratio_is_one_within_its_sampling_error(seed):
    """2T/|V| of N = 1000 particles (G = M = 1, a = 3 pi/16). Its sampling error, to first order (delta
    method; V is a U-statistic whose first-order term is (2/N) sum of h1(r_i) = 1/sqrt(r_i^2 + a^2), the
    Plummer potential per G M): sigma = std_i(v_i^2/<v^2> - 2 h1(r_i)/<h1>)/sqrt(N), about 0.025 for
    N = 1000, estimated from the sample itself. Biases: E[V_N] = (1 - 1/N) V (pairs, not N^2/2) and removing
    the mean velocity lowers T by T/N on average: |bias| <= 2/N. Bound: 5 sigma + 2/N (a 5-sigma normal
    deviate: probability 6e-7)."""
    n = 1000
    m, p, v = plummer_sphere(n, 1.0, A_NBODY, 1.0, np.random.default_rng(seed))
    T, V = _energies(m[0], p, v, 1.0)
    r = np.linalg.norm(p, axis=1)
    h1, v2 = 1.0 / np.sqrt(r ** 2 + A_NBODY ** 2), np.sum(v ** 2, axis=1)
    sigma = np.std(v2 / v2.mean() - 2 * h1 / h1.mean()) / math.sqrt(n)
    # the estimate itself is sane: the spread of 2T/|V| over 200 draws of N = 1000 (seeds 0..199) is 0.024
    assert 0.015 < sigma < 0.04
    assert abs(2 * T / -V - 1) <= 5 * sigma + 2 / n
    # E = -1/4 in these units, within the same relative error of T and V
    assert abs((T + V) / -0.25 - 1) <= 2 * (5 * sigma + 2 / n)


def test_mass_profile_is_plummers():
    """The fraction of particles inside r is r^3/(r^2 + a^2)^(3/2): at the half-mass radius
    a/sqrt(2^(2/3) - 1) it is 1/2 and at a it is 2^(-3/2); a binomial count of N = 1000 deviates by at most
    5 sqrt(P (1 - P)/N) (5 sigma) (+ the centre-of-mass shift, O(a/sqrt(N)) in r: a further 1/sqrt(N))."""
    n, a = 1000, 2.0
    _, p, _ = plummer_sphere(n, 3.0, a, 1.0, np.random.default_rng(11))
    r = np.linalg.norm(p, axis=1)
    for radius, fraction in ((a / math.sqrt(2 ** (2 / 3) - 1), 0.5), (a, 2 ** -1.5)):
        bound = 5 * math.sqrt(fraction * (1 - fraction) / n) + 1 / math.sqrt(n)
        assert abs(np.mean(r < radius) - fraction) <= bound


def test_total_momentum_and_centre_of_mass_are_zero():
    """After subtracting the sample means, sum v_i is 0 up to the rounding of the N subtractions and of the
    sum: |sum v_i| <= 2 N eps max|v| (each term rounds by eps |v_i|, the sum adds N eps max|v|); so for p."""
    f = read_scene("cluster")
    p, v = _arrays(f.initial)
    m = f.scene.bodies[0].mass
    assert np.max(np.abs(m * v.sum(axis=0))) <= 2 * len(v) * EPS * m * np.max(np.abs(v))
    assert np.max(np.abs(p.sum(axis=0))) <= 2 * len(p) * EPS * np.max(np.abs(p))
    result = rigiddyn.simulate(f.scene, f.initial, dt=f.run.dt, steps=1, method="rk4")
    assert np.max(np.abs(result.linear_momentum_W[0])) <= 2 * len(v) * EPS * m * np.max(np.abs(v))


# ---------------------------------------------------------------- a short run of the shipped cluster
@pytest.fixture(scope="module")
def cluster():
    return read_scene("cluster")


@pytest.mark.parametrize("method", ["rk4", "splitting_dlm_yoshida4"])
def test_short_run_conserves_momenta_to_round_off(cluster, method):
    """64 steps of dt = 1/128. The pair forces cancel (Newton's third law), so total momentum changes only
    by rounding: each step rounds every velocity update (<= 8 roundings of eps m |v_i| over a method's
    stages) and every force sum (N terms: N eps m |a_i| h): |P(t) - P(0)| <= steps × 8 eps × sum_i m
    (|v_i| + N h |a_i|) evaluated with the run's largest |v| and |a|. Linear momentum is a linear
    invariant, kept by every Runge-Kutta method and every splitting. Angular momentum is quadratic: rk4
    keeps it only to its truncation error, the splitting exactly (the kick's central pair forces and the
    drift each conserve it), so there it is bounded alike with the largest |r|."""
    steps, dt = 64, cluster.run.dt
    r = rigiddyn.simulate(cluster.scene, cluster.initial, dt=dt, steps=steps, method=method)
    assert not r.diverged
    m, n = cluster.scene.bodies[0].mass, len(cluster.scene.bodies)
    speed = np.max(np.linalg.norm(r.v_W, axis=-1))
    accel = np.max(np.linalg.norm(np.diff(r.v_W, axis=0), axis=-1)) / dt
    bound_P = steps * 8 * EPS * n * m * (speed + n * dt * accel)
    assert np.max(np.abs(r.linear_momentum_W - r.linear_momentum_W[0])) <= bound_P
    radius = np.max(np.linalg.norm(r.p_W, axis=-1))
    if method != "rk4":
        assert np.max(np.abs(r.angular_momentum_W - r.angular_momentum_W[0])) <= bound_P * radius * 2


@pytest.mark.parametrize("method", ["rk4", "splitting_dlm_yoshida4"])
def test_short_run_conserves_energy_to_the_methods_error(cluster, method):
    """Energy error max_t |E(t) - E(0)| over 0.25 s at dt = 1/256 and 1/512 (half and a quarter of the
    file's dt: a close pair of this draw is under-resolved at 1/128, where halving gains only 9x): both
    methods are of order 4, so halving dt divides the error by 16 in the asymptotic regime (asserted >= 8),
    and the error at the finer step is within its Richardson bound 2 |e(h) - e(h/2)|/15; round-off
    (steps x N x 4 eps |E| ~ 1e-10 |E|) is far below both."""
    errors = []
    for dt in (1 / 256, 1 / 512):
        r = rigiddyn.simulate(cluster.scene, cluster.initial, dt=dt, steps=round(0.25 / dt), method=method)
        errors.append(np.max(np.abs(r.total_energy - r.total_energy[0])))
    coarse, fine = errors
    assert coarse >= 8 * fine
    assert fine <= 2 * (coarse - fine) / 15


# ---------------------------------------------------------------- the file format
def test_a_cluster_round_trips_through_canonical_toml_as_bodies():
    """scene_to_toml writes the generated bodies as [[body]] tables: it reads back to the same scene and
    states bit for bit, and writing it again gives the same text."""
    f = read_scene("cluster")
    text = scene_to_toml(f.scene, f.initial, f.run, f.name, f.description)
    g = read_scene(text)
    assert g.scene == f.scene and g.run == f.run
    for x, y in zip(_arrays(f.initial), _arrays(g.initial)):
        np.testing.assert_array_equal(x, y)
    assert scene_to_toml(g.scene, g.initial, g.run, g.name, g.description) == text


def test_cluster_beside_bodies_forces_refer_to_its_stars_and_units_are_read():
    text = ('[[body]]\nname = "planet"\nkind = "particle"\nmass = 5\n'
            + SMALL.replace("scale_radius = 1", 'scale_radius = "100 cm"').replace("count = 50", "count = 50\n"
                                                                                   'name_prefix = "s"')
            + '[[force]]\ntype = "drag"\nlinear = 0.1\nbodies = ["s3"]\n')
    f = read_scene(text)
    assert len(f.scene.bodies) == 51 and f.scene.body_names[1] == "s0"
    drag, gravity = f.scene.elements
    assert tuple(drag.bodies) == (4,)
    assert tuple(gravity.bodies) == tuple(range(1, 51))  # the cluster's own gravity acts on its bodies only
    np.testing.assert_array_equal(_arrays(f.initial[1:])[0], _arrays(read_scene(SMALL).initial)[0])


@pytest.mark.parametrize("change,message", [
    (('model = "plummer"', 'model = "king"'), "cluster[0].model: expected 'plummer', got 'king'"),
    (("count = 50", "count = 1"), "cluster[0].count: expected an integer >= 2, got 1"),
    (("count = 50", "count = 2.5"), "cluster[0].count: expected an integer >= 2, got 2.5"),
    (("count = 50", "count = true"), "cluster[0].count: expected an integer >= 2, got True"),
    (("count = 50\n", ""), "cluster[0].count: expected an integer >= 2, got 'nothing'"),
    (("seed = 7", "seed = -1"), "cluster[0].seed: expected an integer >= 0, got -1"),
    (("seed = 7\n", ""), "cluster[0].seed: expected an integer >= 0, got 'nothing'"),
    (("total_mass = 1", 'total_mass = "1 m"'), "cluster[0].total_mass: expected kg, got '1 m'"),
    (("total_mass = 1", "total_mass = 0"), "cluster[0].total_mass: expected kg > 0, got 0"),
    (("scale_radius = 1", "scale_radius = -2"), "cluster[0].scale_radius: expected m > 0, got -2"),
    (("G = 1", 'G = "1 m^3/s^2"'), "cluster[0].G: expected m^3/(kg s^2), got '1 m^3/s^2'"),
    (("G = 1", "G = 1\nsoftening = -0.1"), "cluster[0].softening: expected m >= 0, got -0.1"),
    (("seed = 7", "sead = 7"), "cluster[0].sead: expected a key of [[cluster]]; did you mean 'seed'?"),
    (("[[cluster]]", '[[body]]\nname = "cluster0_3"\nkind = "particle"\nmass = 1\n[[cluster]]'),
     "cluster[0].name_prefix: expected a prefix giving names no other body has, got \"'cluster0_' "
     "(names 'cluster0_3')\""),
])
def test_bad_generator_input_is_a_value_error_naming_the_field(change, message):
    old, new = change
    assert old in SMALL
    with pytest.raises(ValueError) as e:
        read_scene(SMALL.replace(old, new))
    assert message in str(e.value)


def test_a_cluster_table_must_be_an_array_of_tables():
    with pytest.raises(ValueError, match=r"cluster: expected an array of \[\[cluster\]\] tables"):
        read_scene('cluster = 3\n')
