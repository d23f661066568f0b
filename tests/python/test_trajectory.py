"""rigiddyn.trajectory: a result (SceneResult) as a table (columns with units), written to CSV, .npz and Parquet and
read back exactly, and as a pandas DataFrame: rigiddyn.scene_result's wide table."""

import sys

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn import scene_result
from rigiddyn import trajectory as tj

BODY = rd.RigidBody(1.5, np.diag([0.02, 0.03, 0.04]))
START = rd.RigidBodyState(p_W=[0.1, -0.2, 3.0], q_WB=[0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], v_W=[1.0, 0.5, 4.0],
                          w_B=[0.3, 7.0, -0.2])
LOADS = [rd.AppliedLoad(torque=[0.0, 0.0, 0.01], frame="body", t_end=0.25), rd.AppliedLoad(force=[0.2, 0.0, 0.0])]


def _run(scalar_first=False):
    """A run that moves every recorded field: a spinning, translating body under gravity, a body-frame torque
    switched off half-way and a world force (the records hold non-trivial p_W, v_W, work)."""
    return rd.simulate(BODY, START, 1e-3, 500, "rk4", record_every=7, loads=LOADS, gravity=True,
                       scalar_first=scalar_first)


def _assert_same_table(table, result):
    """The table holds the result's columns: bitwise, every format storing the float64 values exactly (CSV via
    repr, the shortest text that float() reads back to the same double), so no tolerance applies."""
    want = tj.columns(result)
    assert list(table) == list(want)
    for name, values in want.items():
        np.testing.assert_array_equal(np.asarray(table[name], dtype=np.float64), values, strict=True, err_msg=name)


def test_columns_name_every_component_with_its_unit():
    result = _run()
    table = tj.columns(result)
    assert list(table) == scene_result.column_names(result)
    assert list(table)[:8] == ["t [s]", "body0:p_W_x [m]", "body0:p_W_y [m]", "body0:p_W_z [m]", "body0:q_WB_x",
                               "body0:q_WB_y", "body0:q_WB_z", "body0:q_WB_w"]
    for name in ("body0:v_W_z [m/s]", "body0:w_B_x [rad/s]", "kinetic_energy [J]", "total_energy [J]",
                 "work[0] UniformGravity [J]", "work[1] ScheduledLoads [J]"):
        assert name in table
    assert all(v.dtype == np.float64 and v.shape == result.t.shape for v in table.values())
    np.testing.assert_array_equal(table["body0:w_B_y [rad/s]"], result.body(0).w_B[:, 1])


def test_scalar_first_results_are_labelled_w_first():
    xyzw, wxyz = _run(), _run(scalar_first=True)
    table = tj.columns(wxyz, scalar_first=True)
    assert [n for n in table if n.startswith("body0:q_WB")] == ["body0:q_WB_w", "body0:q_WB_x", "body0:q_WB_y",
                                                                 "body0:q_WB_z"]
    # the same run, its quaternion only reordered: every column holds the value it names
    for name, values in tj.columns(xyzw).items():
        np.testing.assert_array_equal(table[name], values, err_msg=name)


def test_a_scalar_first_result_remembers_its_order():
    """A run of simulate(..., scalar_first=True) records its order: its table, DataFrame and files label
    the quaternion's columns (w, x, y, z) without the flag being passed again."""
    pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    xyzw, wxyz = _run(), _run(scalar_first=True)
    assert wxyz.scalar_first is True and xyzw.scalar_first is False
    frame = wxyz.to_dataframe()
    assert [n for n in frame.columns if n.startswith("body0:q_WB")] == ["body0:q_WB_w", "body0:q_WB_x",
                                                                         "body0:q_WB_y", "body0:q_WB_z"]
    # the same run, its quaternion only reordered: every column holds the value it names
    assert frame[list(xyzw.to_dataframe().columns)].equals(xyzw.to_dataframe())
    # True or False still declares the rows' order
    assert list(wxyz.to_dataframe(scalar_first=True).columns) == list(frame.columns)
    assert list(wxyz.to_dataframe(scalar_first=False).columns) == list(xyzw.to_dataframe().columns)


@pytest.mark.parametrize("suffix", ["csv", "npz", "parquet"])
def test_a_scalar_first_result_is_written_in_its_order(tmp_path, suffix):
    if suffix == "parquet":
        pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    wxyz = _run(scalar_first=True)
    table = tj.read_columns(getattr(tj, f"write_{suffix}")(wxyz, tmp_path / f"run.{suffix}"))
    assert list(table) == list(tj.columns(wxyz))
    plain = tj.columns(_run())
    for name, values in plain.items():  # read back by name: the plain run's values
        np.testing.assert_array_equal(table[name], values, strict=True, err_msg=name)


def test_a_scene_result_remembers_its_order():
    """A scene's run: its columns follow the order it records, also through pickle."""
    import pickle

    from rigiddyn.scene_file import read_scene

    file = read_scene("satellite_boom")
    runs = [rd.simulate(file.scene, file.initial, dt=0.02, steps=10, scalar_first=first) for first in (False, True)]
    assert [r.scalar_first for r in runs] == [False, True]
    plain, wxyz = (scene_result.columns(r) for r in runs)
    assert [n for n in wxyz if n.startswith("hub:q_WB")] == ["hub:q_WB_w", "hub:q_WB_x", "hub:q_WB_y", "hub:q_WB_z"]
    for name, values in plain.items():
        np.testing.assert_array_equal(wxyz[name], values, err_msg=name)  # each column holds what it names
    assert pickle.loads(pickle.dumps(runs[1])).scalar_first is True
    pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    assert list(runs[1].to_dataframe().columns) == list(wxyz)


@pytest.mark.parametrize("kind", ["body", "scene"])
def test_a_batch_remembers_its_order_and_gives_it_to_its_samples(kind):
    """simulate_batch(..., scalar_first=True) records its order; result[i] (a SceneResult) carries it, so the
    sample's columns are labelled by what they hold; the order survives pickling, and a batch pickled without it
    reads as (x, y, z, w)."""
    import pickle

    from rigiddyn.scene_file import read_scene

    if kind == "body":
        state = rd.RigidBodyState(q_WB=[0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], w_B=[0.3, 7.0, -0.2])
        model, initial, dt = rd.RigidBody(2.0, [1.0, 2.0, 3.0]), [state, state], 0.01
    else:
        file = read_scene("satellite_boom")
        model, initial, dt = file.scene, [file.initial, file.initial], 0.02
    plain, wxyz = (rd.simulate_batch(model, initial, dt=dt, steps=10, scalar_first=first) for first in (False, True))
    assert (plain.scalar_first, wxyz.scalar_first) == (False, True)
    assert (plain[1].scalar_first, wxyz[1].scalar_first) == (False, True)
    for name, values in tj.columns(plain[1]).items():
        np.testing.assert_array_equal(tj.columns(wxyz[1])[name], values, err_msg=name)  # each holds what it names
    back = pickle.loads(pickle.dumps(wxyz))
    assert back.scalar_first is True and back[0].scalar_first is True
    old = type(wxyz).__new__(type(wxyz))
    # an earlier pickle, without the order and the error estimate after it, its wheel columns between them and its
    # joint columns after them: (x, y, z, w)
    old.__setstate__(wxyz.__getstate__()[:-7])
    assert old.scalar_first is False


def test_a_batch_sample_has_the_table_of_its_serial_run():
    """result[i] of a batch of bodies is the SceneResult of the sample's simulate: the same table, bitwise."""
    batch = rd.simulate_batch(BODY, [START, START], 1e-3, 500, "rk4", record_every=7, loads=LOADS, gravity=True)
    _assert_same_table(tj.columns(batch[1]), _run())


@pytest.mark.parametrize("suffix", ["csv", "npz", "parquet"])
def test_files_read_back_to_the_same_arrays(tmp_path, suffix):
    if suffix == "parquet":
        pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    result = _run()
    path = getattr(tj, f"write_{suffix}")(result, tmp_path / f"run.{suffix}")
    _assert_same_table(tj.read_columns(path), result)


def test_csv_keeps_non_finite_values_and_reads_with_pandas(tmp_path):
    pd = pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 2.5]))
    with pytest.warns(RuntimeWarning, match="non-finite"):  # explicit Euler blows up at this step
        result = rd.simulate(body, rd.RigidBodyState(w_B=[1e3, 1e3, 1e3]), 1.0, 2000, "explicit_euler", error=False)
    assert result.diverged and not np.all(np.isfinite(result.body(0).w_B[-1]))
    path = tj.write_csv(result, tmp_path / "run.csv")
    _assert_same_table(tj.read_columns(path), result)
    frame = pd.read_csv(path)
    want = tj.columns(result)
    assert list(frame.columns) == list(want)
    for name, values in want.items():
        got = frame[name].to_numpy(dtype=np.float64)
        finite = np.isfinite(values)
        np.testing.assert_array_equal(got[~finite], values[~finite])  # nan, inf and -inf as written
        # pandas' C parser (its "high" precision before pandas 3) may round a 17-digit decimal one unit
        # in the last place off the nearest double; Python's float(), as read_columns uses, is exact
        np.testing.assert_array_max_ulp(got[finite], values[finite], maxulp=1)


def test_npz_loads_into_pandas_as_the_table(tmp_path):
    pd = pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    result = _run()
    path = tj.write_npz(result, tmp_path / "run")  # no suffix given: written as given, not run.npz
    assert path.is_file() and path.name == "run"
    with np.load(path) as data:
        frame = pd.DataFrame(dict(data))
    _assert_same_table(dict(frame), result)


def test_parquet_carries_the_metadata(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the parquet extra (in the test extra: runs in CI)")
    path = tj.write_parquet(_run(), tmp_path / "run.parquet", metadata={"method": "rk4", "dt [s]": 1e-3})
    meta = pq.read_schema(path).metadata
    assert b'"method": "rk4"' in meta[b"rigiddyn"]


def test_to_dataframe_has_the_csv_columns_and_t_as_a_column(tmp_path):
    pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    result = _run()
    frame = tj.to_dataframe(result)
    assert frame.index.equals(frame.index.__class__(range(len(result.t))))  # a plain row index
    _assert_same_table(dict(frame), result)
    assert result.to_dataframe().equals(frame)  # the method of SceneResult calls the same function
    wxyz = _run(scalar_first=True).to_dataframe(scalar_first=True)
    assert wxyz[frame.columns].equals(frame)  # the same run: the same columns, q_WB_w moved first


def test_to_dataframe_names_the_extra_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now raises ImportError
    with pytest.raises(ImportError, match=r"rigiddyn\[dataframe\]"):
        tj.to_dataframe(_run())


def test_parquet_names_the_extra_without_pyarrow(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    with pytest.raises(ImportError, match=r"rigiddyn\[parquet\]"):
        tj.write_parquet(_run(), tmp_path / "run.parquet")
    assert not (tmp_path / "run.parquet").exists()


def test_bad_input_names_the_argument(tmp_path):
    with pytest.raises(TypeError, match=r"result: expected a SceneResult \(of rigiddyn\.simulate, .*\), got dict"):
        tj.columns({"t": [0.0]})
    with pytest.raises(TypeError, match="scalar_first: expected None, True or False, got 'yes'"):
        tj.columns(_run(), scalar_first="yes")
    with pytest.raises(ValueError, match=r"path: expected a \.csv, \.npz or \.parquet file, got .*run\.txt"):
        tj.read_columns(tmp_path / "run.txt")
    (tmp_path / "empty.csv").write_text("")
    with pytest.raises(ValueError, match="path: expected a CSV table with a header row"):
        tj.read_columns(tmp_path / "empty.csv")
