"""The global error estimate of every sample of a batch (simulate_batch, monte_carlo, rigiddyn.distributed) and of
the `simulate` command.

The contract tested: sample i's estimate is the one simulate gives for that sample alone (bitwise on the scalar
path, whatever the thread count); the batch's GlobalError has the shapes of simulate's with a leading sample axis;
a diverged sample's missing rows say so; the estimate survives pickling, chunked concatenation and monte_carlo.
"""

import concurrent.futures
import gc
import json
import pickle
import subprocess
import sys

import numpy as np
import pytest

import rigiddyn as rd
from rigiddyn import distributed

ARRAYS = ("attitude", "angular_velocity", "position", "velocity", "energy", "angular_momentum", "observed_order")


def same(a, b):
    return np.array_equal(np.asarray(a), np.asarray(b), equal_nan=True)


def estimate_differences(sample, alone):
    """The fields in which a batch sample's GlobalError differs, bitwise, from the one simulate gives."""
    differ = [name for name in ("order", "verdict") if getattr(sample, name) != getattr(alone, name)]
    differ += [f"reliable_for({q})" for q in ARRAYS[:6] if not same(sample.reliable_for(q), alone.reliable_for(q))]
    return differ + [name for name in (*ARRAYS, "reliable") if not same(getattr(sample, name), getattr(alone, name))]


def spins(n):
    return [rd.RigidBodyState(w_B=[0.1, 1.0 + 0.2 * i, 0.05 * i]) for i in range(n)]


@pytest.mark.parametrize("threads", [1, 3])
def test_each_sample_is_its_own_simulate(threads):
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = spins(5)
    dts = [0.01, 0.02, 0.01, 0.015, 0.02]
    res = rd.simulate_batch(body, states, dt=dts, steps=40, method="rkmk4", record_every=2, threads=threads)
    assert res.error.order == 4
    assert res.error.attitude.shape == (5, 21, 1) and res.error.reliable.shape == (5, 21)
    assert len(res.error.verdict) == 5 and all(len(row) == 21 for row in res.error.verdict)
    for i, (state, dt) in enumerate(zip(states, dts)):
        alone = rd.simulate(body, state, dt=dt, steps=40, method="rkmk4", record_every=2).error
        assert not estimate_differences(res[i].error, alone)  # bitwise: the same one-body scene's runs
        assert res.error.verdict[i] == alone.verdict


def test_a_long_batch_compares_each_samples_records_as_simulate_does():
    # 3 074 multiples of 4 steps recorded every 4th: more than the 1 024 records an estimate compares, which are then
    # every 16 steps and the last multiple of 4 (test_global_error.py); each sample's as simulate's, bit for bit
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = spins(2)
    res = rd.simulate_batch(body, states, dt=0.01, steps=4 * 3074 + 3, record_every=4, threads=1)
    for i, state in enumerate(states):
        alone = rd.simulate(body, state, dt=0.01, steps=4 * 3074 + 3, record_every=4).error
        assert not estimate_differences(res[i].error, alone)
        assert res[i].error.verdict[1].startswith("interpolated between the reliable records")


def test_scene_batch_per_body_shapes_and_samples():
    scene = rd.Scene()
    for name in ("a", "b"):
        scene.add_body(rd.Particle(1.0), name=name)
    scene.add(rd.SpringDamper(body_a=0, body_b=1, stiffness=4.0, rest_length=1.0))
    initial = [[rd.ParticleState(p_W=[0, 0, 0]), rd.ParticleState(p_W=[1.2 + 0.1 * i, 0, 0], v_W=[0, 0.3, 0])]
               for i in range(3)]
    res = rd.simulate_batch(scene, initial, dt=0.01, steps=64, record_every=4)
    assert res.error.position.shape == (3, 17, 2) and res.error.energy.shape == (3, 17)
    for i in range(3):
        alone = rd.simulate(scene, initial[i], dt=0.01, steps=64, record_every=4).error
        assert res[i].error == alone


def test_error_false_and_the_records_unchanged():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    with_error = rd.simulate_batch(body, spins(2), dt=0.01, steps=20)
    without = rd.simulate_batch(body, spins(2), dt=0.01, steps=20, error=False)
    assert without.error is None and without[0].error is None
    assert np.array_equal(with_error.w_B, without.w_B)  # the coarse runs do not touch the answer
    with pytest.raises(TypeError, match="error: expected True or False, got str 'yes'"):
        rd.simulate_batch(body, spins(2), dt=0.01, steps=20, error="yes")


def test_simd_path_estimates_agree_with_the_scalar_path():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = spins(4)
    steps = 200
    scalar = rd.simulate_batch(body, states, dt=0.01, steps=steps, record_every=4)
    simd = rd.simulate_batch(body, states, dt=0.01, steps=steps, record_every=4, simd=True)
    # The SIMD runs equal the scalar ones up to round-off: each of the three runs within the round-off bound of the
    # estimate (8 eps per step, relative to |w_B| <= 2 rad/s), so each difference within twice that, and the
    # estimate d1 / (2^4 - 1) within 2 * 2 * bound / 15.
    bound = 8 * np.finfo(float).eps * steps * 2.0
    assert np.max(np.abs(simd.error.angular_velocity - scalar.error.angular_velocity)) <= 4 * bound / 15
    assert simd.error.verdict == scalar.error.verdict


def test_a_diverged_sample_says_so_in_its_rows():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = [rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), rd.RigidBodyState(w_B=[0.0, 0.0, 1e200])]
    with pytest.warns(RuntimeWarning, match="non-finite|overflow"):
        res = rd.simulate_batch(body, states, dt=0.01, steps=40, method="explicit_euler")
    filled = int(res.filled[1])
    assert res.diverged[1] and filled < 41
    assert np.all(np.isnan(res.error.attitude[1, filled:]))
    assert all(v == "no record: the run at h diverged" for v in res.error.verdict[1][filled:])
    assert not res.error.reliable[1, filled:].any()
    alone = rd.simulate(body, states[0], dt=0.01, steps=40, method="explicit_euler").error
    assert not estimate_differences(res[0].error, alone)


@pytest.mark.parametrize("method", ["rk4", "rkmk4"])
@pytest.mark.parametrize("record_every", [1, 4, 7])
def test_an_estimate_made_on_first_read_is_each_samples_own(method, record_every):
    # simulate_batch makes its estimate when result.error, result[i] or a pickle first needs it, from the arrays the
    # result keeps; each sample's is then the one simulate makes at once for it (a progress callback makes it at
    # once), to the bit, however the result is read first
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = spins(3)
    run = dict(dt=0.01, steps=203, method=method, record_every=record_every)
    alone = [rd.simulate(body, state, **run, progress=lambda done: None).error for state in states]

    def batch(**extra):
        return rd.simulate_batch(rd.RigidBody(1.0, [1.0, 2.0, 3.0]), states, **run, threads=2, **extra)

    def expect_each_samples_own(result):
        for i in range(len(states)):
            assert not estimate_differences(result[i].error, alone[i]), i

    later = batch()
    assert later.error is later.error  # made once
    expect_each_samples_own(later)
    expect_each_samples_own(batch())  # result[i].error first
    samples_first = batch()
    samples = [samples_first[i] for i in range(len(states))]  # no estimate made yet: each sample's waits for it
    del samples_first  # each sample keeps its batch
    for i, sample in enumerate(samples):
        assert not estimate_differences(sample.error, alone[i]) and sample.error is sample.error
    expect_each_samples_own(pickle.loads(pickle.dumps(batch())))
    read_first = batch()
    for name in ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "total_energy", "angular_momentum_W", "filled"):
        getattr(read_first, name)  # the estimate then reads these arrays
    expect_each_samples_own(read_first)
    expect_each_samples_own(batch(scalar_first=True))  # its q_WB rows read as (w, x, y, z)


def test_a_scene_batchs_estimate_keeps_what_its_runs_need():
    shipped = rd.load_scene("box_on_springs")
    alone = rd.simulate(shipped.scene, shipped.initial, 0.001, steps=300, progress=lambda done: None).error
    compiled = shipped.scene.compile("rk4")
    initial = [list(shipped.initial), list(shipped.initial)]
    later = rd.simulate_batch(compiled, initial, dt=0.001, steps=300)
    del compiled, initial[:]  # the estimate keeps its own model and states
    gc.collect()
    assert not estimate_differences(later[0].error, alone) and not estimate_differences(later[1].error, alone)


SHIPPED = ("box_on_springs", "cluster", "double_pendulum", "foucault", "gravity_gradient", "heavy_top", "j2_orbit",
           "kepler", "pendulum", "rocket", "satellite_boom", "solar_array", "spring_chain", "three_body")


@pytest.mark.parametrize("name", SHIPPED)
def test_each_sample_of_a_shipped_scene_is_its_own_simulate(name):
    # the batch reads each sample's records as simulate reads its run's: the energy balance T - W checked against the
    # estimate, |L|'s round-off sized by its bodies' terms (springs, gravity, a mass flow, pivots, a tree)
    shipped = rd.load_scene(name)
    compiled = shipped.scene.compile(shipped.run.method)
    run = dict(dt=shipped.run.dt, steps=200, record_every=4)
    alone = rd.simulate(compiled, shipped.initial, **run, progress=lambda done: None).error
    batch = rd.simulate_batch(compiled, [shipped.initial, shipped.initial], **run, threads=2)
    assert not estimate_differences(batch[0].error, alone) and not estimate_differences(batch[1].error, alone)


def test_threads_reading_a_batchs_deferred_estimate_get_the_one_made():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    results = [rd.simulate_batch(body, spins(4), dt=0.01, steps=400, threads=1) for _ in range(4)]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        read = list(pool.map(lambda r: r.error, [r for r in results for _ in range(4)]))
    assert all(read[4 * i] is read[4 * i + k] and read[4 * i] is not None for i in range(4) for k in range(4))
    assert all(read[4 * i] == read[0] for i in range(4))


def test_a_batch_with_a_python_force_makes_its_estimate_at_once():
    # a PythonForce's calls may not repeat in a later run (here: its torque changed after the run), so such a batch
    # estimates at once, from the force the run met
    torque = {"z": 0.5}

    def push(t, body, p_W, q_WB, v_W, w_B):
        return (0.0, 0.0, 0.0), (0.0, 0.0, torque["z"])

    scene = rd.Scene([rd.RigidBody(1.0, [1.0, 2.0, 3.0])], elements=[rd.PythonForce(push)])
    initial = [[state] for state in spins(2)]
    first = rd.simulate_batch(scene, initial, dt=0.01, steps=40, threads=1)
    torque["z"] = 5.0
    assert first.error != rd.simulate_batch(scene, initial, dt=0.01, steps=40, threads=1).error
    torque["z"] = 0.5
    assert first.error == rd.simulate_batch(scene, initial, dt=0.01, steps=40, threads=1).error


def test_pickle_and_sample_of_the_estimate():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    res = rd.simulate_batch(body, spins(3), dt=0.01, steps=24)
    back = pickle.loads(pickle.dumps(res))
    assert back.error == res.error and back[2].error == res[2].error
    assert "of 75 records reliable" in res.error.summary()  # 3 samples x 25 records
    assert res.error.reliable_for("attitude").shape == (3, 25)
    assert np.array_equal(res[2].error.reliable_for("attitude"), res.error.reliable_for("attitude")[2])


def test_chunks_concatenate_to_the_whole_estimate():
    body = rd.RigidBody(1.0, [1.0, 2.0, 3.0])
    states = spins(5)
    whole = rd.simulate_batch(body, states, dt=0.01, steps=24, threads=1)
    pieces = [rd.simulate_batch(body, states[a:b], dt=0.01, steps=24, threads=1) for a, b in ((0, 2), (2, 5))]
    joined = distributed.concatenate(pieces)
    assert joined.error == whole.error


def test_monte_carlo_carries_the_estimate_and_its_statistics():
    body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
    run = rd.monte_carlo(body, rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), 6, seed=3,
                         dispersions={"w_B": rd.dispersion.Normal(std=0.2)}, dt=0.01, steps=40)
    assert run.error.attitude.shape == (6, 41, 1)
    assert "error.attitude" in run.fields
    stats = run.statistics("error.attitude", at=0.4)
    assert stats.count == 6 and stats.max == pytest.approx(np.max(run.error.attitude[:, -1]))
    quiet = rd.monte_carlo(body, rd.RigidBodyState(w_B=[0.0, 0.0, 1.0]), 2, seed=3, dt=0.01, steps=4, error=False)
    assert quiet.error is None and "error.attitude" not in quiet.fields
    with pytest.raises(TypeError, match="error"):
        rd.monte_carlo(body, rd.RigidBodyState(), 2, seed=3, dt=0.01, steps=4, error=1)


@pytest.mark.parametrize("extra, reported", [([], True), (["--no-error"], False)])
def test_simulate_command_reports_the_estimate(tmp_path, extra, reported):
    out = tmp_path / "run"
    done = subprocess.run([sys.executable, "-m", "rigiddyn", "simulate", "t_handle", "--method", "rk4", "--dt", "0.01",
                           "--steps", "400", "--no-plot", "--no-progress", "--out", str(out), *extra],
                          capture_output=True, text=True, check=True)
    record = json.loads((out / "run.json").read_text())["global error"]
    assert ("global error estimate: order 4" in done.stdout) == reported
    if reported:
        assert record["order"] == 4 and record["records"] == 401
        assert record["largest estimates"]["attitude [rad]"] > 0
        assert record["reliable records by quantity"]["attitude"] >= record["reliable records"]
    else:
        assert record is None
