"""rigiddyn.distributed on a 2-worker LocalCluster (processes): bitwise equal to the local batch, a killed
worker's chunk retried, chunks failing every try reported by sample, the fallback without dask, a model
that does not pickle, bad input. The cluster is started once for the module (a start costs seconds)."""

from __future__ import annotations

import functools
import math
import os
import sys
import threading
import warnings
from typing import Any

import numpy as np
import pytest

import rigiddyn
from rigiddyn import distributed as rd

try:
    import cloudpickle
    import dask
    import distributed
except ImportError:
    distributed = None

needs_dask = pytest.mark.skipif(distributed is None, reason="dask.distributed is not installed "
                                                            "(pip install 'rigiddyn[distributed]', in the test extra)")
if distributed is not None:
    # the workers cannot import this test module: its functions (the scenes' forces, the draws) go by value
    cloudpickle.register_pickle_by_value(sys.modules[__name__])


# ---------------------------------------------------------------------------------------------
# the local batch, which every distributed run must reproduce bit for bit

LOCAL_BATCH = rigiddyn.simulate_batch
_FIELDS = ("t", "p_W", "q_WB", "v_W", "w_B", "kinetic_energy", "potential_energy", "total_energy",
           "angular_momentum_norm", "quaternion_norm_error", "work", "power", "mass", "pivot_reaction_W",
           "angular_momentum_O_W", "linear_momentum_W", "angular_momentum_W", "diverged", "filled",
           "unconverged_steps")


def assert_bitwise(a: Any, b: Any) -> None:
    """Every array field of two batch results identical bit for bit (NaN rows included)."""
    assert type(a) is type(b) and len(a) == len(b)
    for name in [f for f in _FIELDS if hasattr(b, f)]:
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        assert (x.dtype, x.shape) == (y.dtype, y.shape), name
        assert x.tobytes() == y.tobytes(), name


# ---------------------------------------------------------------------------------------------
# the problems: tumbling rigid bodies; a scene of particles with a Python force


BODY = rigiddyn.RigidBody(2.0, [0.3, 0.5, 0.7])


def tumbling_states(n: int) -> list[Any]:
    """n attitudes and rates differing per sample (rates of 1-3 rad/s in B, off every principal axis)."""
    return [rigiddyn.RigidBodyState(p_W=[i, 0.0, 0.0], v_W=[0.0, 0.1 * i, 0.0],
                                    w_B=[1.0 + 0.1 * i, 0.2, -0.5 + 0.05 * i]) for i in range(n)]


def _force(marker: str, parent: int, kill_at: float | None, t: float, body: int, p_W: Any, q_WB: Any, v_W: Any,
           w_B: Any) -> tuple[list[float], list[float]]:
    """A spring to the origin (k = 1 N/m); on a worker (not the test's process `parent`) it ends the worker
    process: kill_at None: at the first call of any run (`marker` file created atomically, so once); else
    at every call at x = kill_at, i.e. at the first call of the sample that starts there."""
    if os.getpid() != parent:
        if kill_at is not None and p_W[0] == kill_at:
            os._exit(3)
        if kill_at is None:
            try:
                os.close(os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
                os._exit(3)
            except FileExistsError:
                pass
    return [-p_W[0], -p_W[1], -p_W[2]], [0.0, 0.0, 0.0]


def spring_scene(marker: str, kill_at: float | None = None) -> Any:
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0))
    scene.add(rigiddyn.PythonForce(functools.partial(_force, marker, os.getpid(), kill_at)))
    return scene


def particle_states(n: int) -> list[list[Any]]:
    return [[rigiddyn.ParticleState(p_W=[float(i), 0.0, 0.0], v_W=[0.0, 0.0, 0.0])] for i in range(n)]


# ---------------------------------------------------------------------------------------------
# the cluster


@pytest.fixture(scope="module")
def cluster_client() -> Any:
    """2 worker processes of one thread. allowed-failures 0: a task whose worker dies fails at once (the
    scheduler does not re-run it), so the retries seen are rigiddyn.distributed's."""
    if distributed is None:
        pytest.skip("dask.distributed is not installed")
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    client = distributed.Client(cluster)
    yield client
    client.close()
    cluster.close()


@pytest.fixture
def client(cluster_client: Any) -> Any:
    cluster_client.wait_for_workers(2, timeout=120)  # after a killed worker its nanny starts another
    return cluster_client


# ---------------------------------------------------------------------------------------------
# tests on the cluster


@needs_dask
def test_local_cluster_bitwise(client: Any, capsys: pytest.CaptureFixture[str]) -> None:
    # each sample runs the same single-run code in another process: the IEEE operations are the same,
    # so the records are identical bit for bit (no tolerance), whatever the chunking
    n, steps = 13, 200
    initial = tumbling_states(n)
    dt = np.linspace(1e-3, 2e-3, n)
    local = LOCAL_BATCH(BODY, initial, dt, steps, "rk4", record_every=10, gravity=[0.0, 0.0, -9.81])
    sized = rd.simulate_batch(BODY, initial, dt, steps, method="rk4", record_every=10, gravity=[0.0, 0.0, -9.81],
                              client=client, progress=True)  # chunk_size from the measured overheads
    assert_bitwise(sized, local)
    assert sized.elapsed_seconds > 0.0  # the distributed call's wall time [s]
    assert "simulate_batch" in capsys.readouterr().err  # the tqdm bar (tqdm is in the test extra)
    bodies = [rigiddyn.RigidBody(1.0 + i, [0.3, 0.5, 0.7]) for i in range(n)]  # per-sample models, uneven chunks
    local = LOCAL_BATCH(bodies, initial, 1e-3, steps, "rk4", record_every=10)
    assert_bitwise(rd.simulate_batch(bodies, initial, 1e-3, steps, method="rk4", record_every=10, client=client,
                                     chunk_size=5, progress=False), local)
    assert "simulate_batch" not in capsys.readouterr().err  # progress=False: no bar
    # stacked initial arrays, a load schedule and a gravity per sample, quaternions scalar first
    rng = np.random.default_rng(7)
    q = rng.normal(size=(n, 4))
    stacked = {"p_W": rng.normal(size=(n, 3)), "q_WB": q / np.linalg.norm(q, axis=1, keepdims=True),
               "v_W": rng.normal(size=(n, 3)), "w_B": rng.normal(size=(n, 3))}
    loads = [[rigiddyn.AppliedLoad(force=[0.1 * i, 0.0, 0.0], torque=[0.0, 0.01, 0.0], frame="body", t_end=0.1)]
             for i in range(n)]
    options: dict[str, Any] = dict(method="rk4", record_every=20, loads=loads, gravity=rng.normal(size=(n, 3)),
                                   scalar_first=True, t0=0.5)
    local = LOCAL_BATCH(BODY, stacked, 1e-3, steps, **options)
    assert_bitwise(rd.simulate_batch(BODY, stacked, 1e-3, steps, client=client, chunk_size=4, progress=False,
                                     **options), local)


@needs_dask
def test_a_duration_is_the_same_steps_on_the_cluster(client: Any) -> None:
    """duration= [s] is turned into steps before any chunk is sent: at a common dt, and at per-sample dt that
    agree; per-sample dt that give different counts are refused naming them (nothing runs)."""
    initial = tumbling_states(6)
    local = LOCAL_BATCH(BODY, initial, 0.01, 50, method="rk4", record_every=10)
    for dt in (0.01, np.full(6, 0.01)):
        assert_bitwise(rd.simulate_batch(BODY, initial, dt, duration=0.5, method="rk4", record_every=10,
                                         client=client, chunk_size=2, progress=False), local)
    with pytest.raises(ValueError, match=r"^duration: expected the same number of steps for every sample's dt "
                                         r"\(or steps= instead\), got 50 steps of dt\[0\] and 25 of dt\[3\]$"):
        rd.simulate_batch(BODY, initial, np.array([0.01] * 3 + [0.02] * 3), duration=0.5, client=client,
                          chunk_size=2, progress=False)


@needs_dask
def test_nonfinite_samples_named_once(client: Any) -> None:
    # explicit Euler at dt = 0.1 s: |w| about 70 rad/s grows without bound (dt |w| = 7), |w| about 1 rad/s does not
    initial = tumbling_states(9)
    for i in (2, 7):
        initial[i] = rigiddyn.RigidBodyState(w_B=[50.0, 40.0, -30.0])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        local = LOCAL_BATCH(BODY, initial, 0.1, 200, "explicit_euler")
        result = rd.simulate_batch(BODY, initial, 0.1, 200, method="explicit_euler", client=client, chunk_size=3,
                                   progress=False)
    mine = [str(w.message) for w in caught if str(w.message).startswith("simulate_batch: 2 of 9")]
    assert mine[-1:] == ["simulate_batch: 2 of 9 samples became non-finite (samples 2, 7); their runs stopped there"]
    assert_bitwise(result, local)
    assert np.flatnonzero(np.asarray(result.diverged)).tolist() == [2, 7]


def _lambda_scene() -> Any:
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0))
    scene.add(rigiddyn.PythonForce(lambda t, b, p, q, v, w: ([-p[0], -p[1], -p[2]], [0.0, 0.0, 0.0])))
    return scene


@needs_dask
def test_lambda_force_sent_by_value(client: Any) -> None:
    # a lambda pickles by value (cloudpickle, as Dask sends functions): the scene runs on the workers
    scene, initial = _lambda_scene(), particle_states(4)
    assert_bitwise(rd.simulate_batch(scene, initial, 0.01, 20, client=client, chunk_size=2, progress=False),
                   LOCAL_BATCH(scene, initial, 0.01, 20))


@needs_dask
def test_killed_worker_chunk_retried(client: Any, tmp_path: Any) -> None:
    marker = str(tmp_path / "killed")
    scene, initial = spring_scene(marker), particle_states(8)
    local = LOCAL_BATCH(scene, initial, 0.01, 50, "rk4")  # in this process: the force never kills it
    result = rd.simulate_batch(scene, initial, 0.01, 50, method="rk4", client=client, chunk_size=3, retries=1,
                               progress=False)
    assert os.path.exists(marker)  # a worker did end mid-run
    assert_bitwise(result, local)


@needs_dask
def test_chunks_failing_every_try_named(client: Any, tmp_path: Any) -> None:
    scene, initial = spring_scene(str(tmp_path / "unused"), kill_at=5.0), particle_states(10)
    # chunk 4-7 ends its worker on every try; a chunk sent to the same worker meanwhile may fail with it
    with pytest.raises(rd.ChunksFailedError, match=r"samples (.+, )?4-7(, .+)? failed on all 2 tries") as caught:
        rd.simulate_batch(scene, initial, 0.01, 20, method="rk4", client=client, chunk_size=4, retries=1,
                          progress=False)
    failed, completed = caught.value.failed, caught.value.completed
    assert (4, 8) in failed and sorted([*failed, *completed]) == [(0, 4), (4, 8), (8, 10)]
    for (a, b), piece in completed.items():  # the chunks that finished are kept, as a local run of theirs
        assert_bitwise(piece, LOCAL_BATCH(scene, initial[a:b], 0.01, 20, "rk4"))


@needs_dask
def test_sample_error_renumbered(client: Any) -> None:
    dt = np.full(9, 1e-3)
    dt[6] = -1e-3
    with pytest.raises(ValueError, match=r"^sample 6: dt"):  # sample 2 of the chunk 4-7
        rd.simulate_batch(BODY, tumbling_states(9), dt, 10, client=client, chunk_size=4, progress=False)


def _draws(entropy: int, start: int, stop: int) -> tuple[np.ndarray, list[int]]:
    """Per-sample draws that depend only on (entropy, i): 3 normals and an int per sample."""
    children = np.random.SeedSequence(entropy).spawn(stop)[start:stop]
    rngs = [np.random.default_rng(c) for c in children]
    return np.array([r.normal(size=3) for r in rngs]).reshape(-1, 3), [int(r.integers(100)) for r in rngs]


@needs_dask
def test_map_samples_in_sample_order(client: Any) -> None:
    function = functools.partial(_draws, 2026)
    local = function(0, 11)
    # a Client, and the scheduler's address (a Client connected for the call)
    for where, chunk_size in ((client, 3), (client, None), (client.scheduler.address, 4)):
        values, ints = rd.map_samples(function, 11, client=where, chunk_size=chunk_size, progress=False)
        assert values.tobytes() == local[0].tobytes() and ints == local[1]
    assert client.status == "running"  # the caller's Client is left open


@needs_dask
def test_map_samples_on_the_given_client_while_another_is_the_default(client: Any,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    # A Client opened after the caller's becomes Dask's default, on its own event loop. The results are gathered on
    # the given client's loop (as_completed's default, the default client's loop, stalled each round by 5 s here, and
    # can hang): every as_completed is asked for the given client's loop, and the pieces are complete and in order.
    loops = []
    as_completed = distributed.as_completed

    def recording(*args: Any, **kwargs: Any) -> Any:
        loops.append(kwargs.get("loop"))
        return as_completed(*args, **kwargs)

    monkeypatch.setattr(distributed, "as_completed", recording)
    function = functools.partial(_draws, 2027)
    local = function(0, 7)
    with distributed.Client(client.scheduler.address) as other:
        assert distributed.default_client() is other and other.loop is not client.loop
        values, ints = rd.map_samples(function, 7, client=client, chunk_size=2, progress=False)
    assert values.tobytes() == local[0].tobytes() and ints == local[1]
    assert loops and all(loop is client.loop for loop in loops)


@needs_dask
def test_measure_task_overhead(client: Any) -> None:
    overhead = rd.measure_task_overhead(client, tasks=10)
    assert math.isfinite(overhead) and overhead > 0.0
    with pytest.raises(TypeError, match="^client: expected a distributed.Client"):
        rd.measure_task_overhead("tcp://127.0.0.1:8786")


@needs_dask
def test_tradeoff_grid_same_rows(client: Any) -> None:
    arguments: dict[str, Any] = dict(methods=["rk4", "explicit_euler"], dts=[0.02, 0.01, 0.005], horizon=0.5)
    local = rigiddyn.tradeoff("t_handle", progress=False, **arguments)
    grid = rd.tradeoff_grid("t_handle", client=client, progress=False, **arguments)
    timed = {"time_per_step", "time_noise", "total_time"}  # measured, not computed: differ run to run
    assert len(grid.rows) == len(local.rows)
    for a, b in zip(grid.rows, local.rows):
        assert a.keys() == b.keys()
        for key in a.keys() - timed:  # computed from the same runs: equal, nan where nan
            same = a[key] == b[key] or (isinstance(a[key], float) and math.isnan(a[key]) and math.isnan(b[key]))
            assert same, (key, a[key], b[key])


# ---------------------------------------------------------------------------------------------
# without a cluster


def test_fallback_without_dask(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "distributed", None)  # `import distributed` raises ImportError
    initial = tumbling_states(4)
    local = LOCAL_BATCH(BODY, initial, 1e-3, 20, "rk4")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = rd.simulate_batch(BODY, initial, 1e-3, 20, method="rk4")
        values = rd.map_samples(lambda a, b: np.arange(a, b), 5)
    assert [str(w.message) for w in caught] == [rd.FALLBACK_MESSAGE] * 2  # one per call
    assert all(w.category is RuntimeWarning for w in caught)
    assert_bitwise(result, local)
    assert values.tolist() == [0, 1, 2, 3, 4]
    arguments: dict[str, Any] = dict(methods=["rk4"], dts=[0.1, 0.05], horizon=0.2)
    with pytest.warns(RuntimeWarning, match="dask.distributed is not installed") as caught:
        grid = rd.tradeoff_grid("t_handle", progress=False, **arguments)
    assert len(caught) == 1
    local_rows = rigiddyn.tradeoff("t_handle", progress=False, **arguments).rows
    assert [r["final_attitude_error"] for r in grid.rows] == [r["final_attitude_error"] for r in local_rows]


@needs_dask
def test_model_that_does_not_pickle(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_cluster(*args: Any) -> Any:
        raise AssertionError("a cluster was asked for before the model was checked")

    monkeypatch.setattr(rd, "_client_for", no_cluster)
    lock = threading.Lock()
    scene = rigiddyn.Scene()
    scene.add_body(rigiddyn.Particle(1.0))
    # a lambda alone goes by value (cloudpickle, as Dask sends it); one holding a lock cannot go at all
    scene.add(rigiddyn.PythonForce(lambda t, b, p, q, v, w: ([0.0, 0.0, 0.0] if lock else [1.0, 0, 0],
                                                             [0.0, 0.0, 0.0])))
    with pytest.raises(ValueError, match=r"^model: expected an object that pickles .*lock"):
        rd.simulate_batch(scene, particle_states(2), 0.01, 10)
    with pytest.raises(ValueError, match=r"^function: expected an object that pickles"):
        rd.map_samples(lambda a, b: [lock] * (b - a), 3)


def test_bad_input(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_cluster(*args: Any) -> Any:
        raise AssertionError("a cluster was asked for before the arguments were checked")

    monkeypatch.setattr(rd, "_client_for", no_cluster)
    initial = tumbling_states(3)
    cases: list[tuple[type[Exception], str, dict[str, Any]]] = [
        (ValueError, r"^chunk_size: expected an int >= 1, got 0$", {"chunk_size": 0}),
        (TypeError, r"^chunk_size: expected an int >= 1, got 1.5$", {"chunk_size": 1.5}),
        (ValueError, r"^retries: expected an int >= 0, got -1$", {"retries": -1}),
        (TypeError, r"^retries: expected an int >= 0, got True$", {"retries": True}),
        (TypeError, r"^progress: expected True or False, got 'yes'$", {"progress": "yes"}),
        (TypeError, r"^client: expected None, a distributed.Client or a scheduler address \(str\), got 3$",
         {"client": 3}),
        (TypeError, r"^threads: not an argument", {"threads": 2}),
    ]
    for kind, message, kwargs in cases:
        with pytest.raises(kind, match=message):
            rd.simulate_batch(BODY, initial, 1e-3, 10, **kwargs)
    with pytest.raises(ValueError, match=r"^n_samples: expected an int >= 1, got 0$"):
        rd.map_samples(lambda a, b: [], 0)
    with pytest.raises(TypeError, match=r"^function: expected a callable"):
        rd.map_samples(3, 2)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^retries: expected an int >= 0, got -2$"):
        rd.tradeoff_grid("t_handle", retries=-2)


@needs_dask
def test_bad_batch_shapes(monkeypatch: pytest.MonkeyPatch) -> None:
    def no_cluster(*args: Any) -> Any:
        raise AssertionError("a cluster was asked for before the arguments were checked")

    monkeypatch.setattr(rd, "_client_for", no_cluster)
    initial = tumbling_states(3)
    with pytest.raises(ValueError, match=r"^initial: expected at least one sample, got 0$"):
        rd.simulate_batch(BODY, [], 1e-3, 10)
    with pytest.raises(ValueError, match=r"^dt: expected 3 entries, one per sample of initial \(3\), got 2$"):
        rd.simulate_batch(BODY, initial, [1e-3, 1e-3], 10)
    with pytest.raises(ValueError, match=r"^gravity: expected 3 entries, one per sample of initial \(3\), got 4$"):
        rd.simulate_batch(BODY, initial, 1e-3, 10, gravity=np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"^model: expected 3 entries, one per sample of initial \(3\), got 2$"):
        rd.simulate_batch([BODY, BODY], initial, 1e-3, 10)
    with pytest.raises(TypeError, match=r"^initial: expected a sequence of N states"):
        rd.simulate_batch(BODY, initial[0], 1e-3, 10)
    with pytest.raises(ValueError, match=r"^measure: expected one of"):
        rd.tradeoff_grid("t_handle", measure="speed")


def test_chunk_size_rule() -> None:
    # overhead 2 ms, 10 us per sample: 19 x 2e-3 / 1e-5 = 3800 samples amortise it (3800 x 1e-5 = 38 ms, and
    # 2 / (2 + 38) = 5 %); 10^4 samples on 2 threads: 2 tasks per thread allow 2500, which wins
    assert rd.chunk_size_for(2e-3, 1e-5, 10**5, 2) == 3800
    assert rd.chunk_size_for(2e-3, 1e-5, 10**4, 2) == 2500
    assert rd.chunk_size_for(2e-3, 1.0, 10**4, 2) == 1  # long samples: one per task
    with pytest.raises(ValueError, match=r"^per_sample: expected a finite time >= 0 \[s\], got nan$"):
        rd.chunk_size_for(2e-3, math.nan, 10, 2)
    with pytest.raises(ValueError, match=r"^threads: expected an int >= 1, got 0$"):
        rd.chunk_size_for(2e-3, 1e-5, 10, 0)


def test_concatenate_pieces() -> None:
    a, b = np.arange(6.0).reshape(3, 2), np.arange(6.0, 8.0).reshape(1, 2)
    assert rd.concatenate([a, b]).tolist() == np.arange(8.0).reshape(4, 2).tolist()
    assert rd.concatenate([[1, 2], [3]]) == [1, 2, 3]
    assert rd.concatenate([({"x": a}, [0, 1, 2]), ({"x": b}, [3])])[1] == [0, 1, 2, 3]
    with pytest.raises(TypeError, match="^function: expected pieces that concatenate"):
        rd.concatenate([1.0, 2.0])
