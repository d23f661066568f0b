"""rigiddyn.trajectory: a result as a table (columns with units), written to CSV, .npz and Parquet and read
back exactly, and as a pandas DataFrame: a batch sample's (SimulationResult) 19 columns, and a run's
(SceneResult) wide table of rigiddyn.scene_result."""

import sys

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn import trajectory as tj


def _run(scalar_first=False):
    """A batch sample (SimulationResult) that moves every recorded field: a spinning, translating body under
    gravity, a body-frame torque switched off half-way and a world force (the records hold non-trivial p_W,
    v_W, work)."""
    body = rd.RigidBody(1.5, np.diag([0.02, 0.03, 0.04]))
    start = rd.RigidBodyState(p_W=[0.1, -0.2, 3.0], q_WB=[0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], v_W=[1.0, 0.5, 4.0],
                              w_B=[0.3, 7.0, -0.2])
    loads = [rd.AppliedLoad(torque=[0.0, 0.0, 0.01], frame="body", t_end=0.25), rd.AppliedLoad(force=[0.2, 0.0, 0.0])]
    return rd.simulate_batch(body, [start], 1e-3, 500, "rk4", record_every=7, loads=loads, gravity=True,
                             scalar_first=scalar_first)[0]


def _one_body_run():
    """rigiddyn.simulate of the same body: a SceneResult of one body."""
    sample = _run()
    body = rd.RigidBody(1.5, np.diag([0.02, 0.03, 0.04]))
    start = rd.RigidBodyState(p_W=sample.p_W[0], q_WB=sample.q_WB[0], v_W=sample.v_W[0], w_B=sample.w_B[0])
    loads = [rd.AppliedLoad(torque=[0.0, 0.0, 0.01], frame="body", t_end=0.25), rd.AppliedLoad(force=[0.2, 0.0, 0.0])]
    return rd.simulate(body, start, 1e-3, 500, "rk4", record_every=7, loads=loads, gravity=True)


def _assert_same_fields(fields, result):
    for name in tj.FIELDS:
        # bitwise: every format stores the float64 values exactly (CSV via repr, the shortest text
        # that float() reads back to the same double), so no tolerance applies
        np.testing.assert_array_equal(fields[name], np.asarray(getattr(result, name)), strict=True, err_msg=name)


def test_columns_name_every_component_with_its_unit():
    result = _run()
    table = tj.columns(result)
    assert list(table) == tj.column_names()
    assert list(table)[:8] == ["t [s]", "p_W_x [m]", "p_W_y [m]", "p_W_z [m]", "q_WB_x", "q_WB_y", "q_WB_z", "q_WB_w"]
    for name in ("v_W_z [m/s]", "w_B_x [rad/s]", "kinetic_energy [J]", "total_energy [J]",
                 "angular_momentum_norm [kg m^2/s]", "quaternion_norm_error", "work [J]"):
        assert name in table
    assert all(v.dtype == np.float64 and v.shape == result.t.shape for v in table.values())
    np.testing.assert_array_equal(table["w_B_y [rad/s]"], result.w_B[:, 1])
    assert len(table) == 19


def test_scalar_first_results_are_labelled_w_first():
    xyzw, wxyz = _run(), _run(scalar_first=True)
    table = tj.columns(wxyz, scalar_first=True)
    assert [n for n in table if n.startswith("q_WB")] == ["q_WB_w", "q_WB_x", "q_WB_y", "q_WB_z"]
    # the same run, its quaternion only reordered: the fields read back in (x, y, z, w) order
    np.testing.assert_array_equal(tj.fields_from_columns(table)["q_WB"], xyzw.q_WB)


def test_a_scalar_first_result_remembers_its_order():
    """A run of simulate(..., scalar_first=True) records its order: its table, DataFrame and files label
    the quaternion's columns (w, x, y, z) without the flag being passed again."""
    pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    xyzw, wxyz = _run(), _run(scalar_first=True)
    assert wxyz.scalar_first is True and xyzw.scalar_first is False
    frame = wxyz.to_dataframe()
    assert [n for n in frame.columns if n.startswith("q_WB")] == ["q_WB_w", "q_WB_x", "q_WB_y", "q_WB_z"]
    # the same run, its quaternion only reordered: every column holds the value it names
    assert frame[list(xyzw.to_dataframe().columns)].equals(xyzw.to_dataframe())
    np.testing.assert_array_equal(tj.fields_from_columns(tj.columns(wxyz))["q_WB"], xyzw.q_WB)
    # True or False still declares the rows' order (a result that records none, e.g. an earlier pickle)
    assert list(wxyz.to_dataframe(scalar_first=True).columns) == list(frame.columns)
    assert list(wxyz.to_dataframe(scalar_first=False).columns) == tj.column_names()


@pytest.mark.parametrize("suffix", ["csv", "npz", "parquet"])
def test_a_scalar_first_result_is_written_in_its_order(tmp_path, suffix):
    if suffix == "parquet":
        pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    path = getattr(tj, f"write_{suffix}")(_run(scalar_first=True), tmp_path / f"run.{suffix}")
    table = tj.read_columns(path)
    assert list(table) == tj.column_names(scalar_first=True)
    _assert_same_fields(tj.fields_from_columns(table), _run())  # read back as (x, y, z, w): the plain run


def test_the_order_survives_pickling():
    import pickle

    wxyz = _run(scalar_first=True)
    back = pickle.loads(pickle.dumps(wxyz))
    assert back.scalar_first is True
    np.testing.assert_array_equal(back.q_WB, wxyz.q_WB)
    state = wxyz.__getstate__()
    old = type(wxyz).__new__(type(wxyz))
    old.__setstate__(state[:13])  # a state without the order (an earlier pickle): (x, y, z, w)
    assert old.scalar_first is False


@pytest.mark.parametrize("suffix", ["csv", "npz", "parquet"])
def test_a_run_of_one_body_is_written_as_its_scene_table(tmp_path, suffix):
    """simulate of a body gives a SceneResult: its table is rigiddyn.scene_result's (the body's columns named
    body0:..., then the scene-wide ones, each element's work), read back bitwise (CSV by repr, the others as
    float64 bits), and its one body's columns hold the batch sample's records of the same run."""
    if suffix == "parquet":
        pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    from rigiddyn import scene_result

    result, sample = _one_body_run(), _run()
    table = tj.columns(result)
    assert list(table) == scene_result.column_names(result)
    assert list(table)[:5] == ["t [s]", "body0:p_W_x [m]", "body0:p_W_y [m]", "body0:p_W_z [m]", "body0:q_WB_x"]
    assert [n for n in table if n.startswith("work")] == ["work[0] UniformGravity [J]", "work[1] ScheduledLoads [J]"]
    read = tj.read_columns(getattr(tj, f"write_{suffix}")(result, tmp_path / f"run.{suffix}"))
    assert list(read) == list(table)
    for name, values in table.items():
        np.testing.assert_array_equal(read[name], values, strict=True, err_msg=name)
    body = result.body(0)
    for field in ("p_W", "q_WB", "v_W", "w_B"):
        for i, c in enumerate("xyzw" if field == "q_WB" else "xyz"):
            unit = {"p_W": " [m]", "v_W": " [m/s]", "w_B": " [rad/s]", "q_WB": ""}[field]
            np.testing.assert_array_equal(table[f"body0:{field}_{c}{unit}"], np.asarray(getattr(body, field))[:, i])
    # the same equations, the same method and dt: the batch sample and the scene run agree to round-off,
    # rk4's 4 stages of <= 10 roundings of |x| each over 500 steps: 2e4 eps relative to max |x|
    for field in ("p_W", "q_WB", "v_W", "w_B"):
        want = np.asarray(getattr(sample, field))
        np.testing.assert_allclose(getattr(body, field), want, rtol=0, atol=2e4 * 2.2e-16 * np.max(np.abs(want)),
                                   err_msg=field)


def test_a_scene_result_remembers_its_order():
    """SceneResult as SimulationResult: its columns follow the order it records, also through pickle."""
    import pickle

    from rigiddyn import scene_result
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
    """simulate_batch(..., scalar_first=True) records its order; result[i] (a SimulationResult or SceneResult)
    carries it, so the sample's columns are labelled by what they hold; the order survives pickling, and a
    batch pickled without it reads as (x, y, z, w)."""
    import pickle

    from rigiddyn import scene_result
    from rigiddyn.scene_file import read_scene

    if kind == "body":
        state = rd.RigidBodyState(q_WB=[0.1, 0.2, 0.3, np.sqrt(1 - 0.14)], w_B=[0.3, 7.0, -0.2])
        model, initial, dt = rd.RigidBody(2.0, [1.0, 2.0, 3.0]), [state, state], 0.01
        table = tj.columns
    else:
        file = read_scene("satellite_boom")
        model, initial, dt = file.scene, [file.initial, file.initial], 0.02
        table = scene_result.columns
    plain, wxyz = (rd.simulate_batch(model, initial, dt=dt, steps=10, scalar_first=first) for first in (False, True))
    assert (plain.scalar_first, wxyz.scalar_first) == (False, True)
    assert (plain[1].scalar_first, wxyz[1].scalar_first) == (False, True)
    for name, values in table(plain[1]).items():
        np.testing.assert_array_equal(table(wxyz[1])[name], values, err_msg=name)  # each column holds what it names
    back = pickle.loads(pickle.dumps(wxyz))
    assert back.scalar_first is True and back[0].scalar_first is True
    old = type(wxyz).__new__(type(wxyz))
    # an earlier pickle, without the order and the error estimate after it (and a scene batch's wheel columns
    # between them and its joint columns after them): (x, y, z, w)
    old.__setstate__(wxyz.__getstate__()[:-2 if kind == "body" else -7])
    assert old.scalar_first is False


@pytest.mark.parametrize("suffix", ["csv", "npz", "parquet"])
def test_files_read_back_to_the_same_arrays(tmp_path, suffix):
    if suffix == "parquet":
        pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    result = _run()
    path = getattr(tj, f"write_{suffix}")(result, tmp_path / f"run.{suffix}")
    table = tj.read_columns(path)
    assert list(table) == tj.column_names()
    _assert_same_fields(tj.fields_from_columns(table), result)


def test_csv_keeps_non_finite_values_and_reads_with_pandas(tmp_path):
    pd = pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    body = rd.RigidBody(1.0, np.diag([1.0, 2.0, 2.5]))
    with pytest.warns(RuntimeWarning, match="non-finite"):  # explicit Euler blows up at this step
        result = rd.simulate_batch(body, [rd.RigidBodyState(w_B=[1e3, 1e3, 1e3])], 1.0, 2000, "explicit_euler")[0]
    assert result.diverged and not np.all(np.isfinite(result.w_B[-1]))
    path = tj.write_csv(result, tmp_path / "run.csv")
    _assert_same_fields(tj.fields_from_columns(tj.read_columns(path)), result)
    frame = pd.read_csv(path)
    assert list(frame.columns) == tj.column_names()
    read = tj.fields_from_columns(frame)
    for name in tj.FIELDS:
        got, want = read[name], np.asarray(getattr(result, name))
        finite = np.isfinite(want)
        np.testing.assert_array_equal(got[~finite], want[~finite])  # nan, inf and -inf as written
        # pandas' C parser (its "high" precision before pandas 3) may round a 17-digit decimal one unit
        # in the last place off the nearest double; Python's float(), as read_columns uses, is exact
        np.testing.assert_array_max_ulp(got[finite], want[finite], maxulp=1)


def test_npz_loads_into_pandas_as_the_table(tmp_path):
    pd = pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    result = _run()
    path = tj.write_npz(result, tmp_path / "run")  # no suffix given: written as given, not run.npz
    assert path.is_file() and path.name == "run"
    with np.load(path) as data:
        frame = pd.DataFrame(dict(data))
    assert list(frame.columns) == tj.column_names()
    _assert_same_fields(tj.fields_from_columns(frame), result)


def test_parquet_carries_the_metadata(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the parquet extra (in the test extra: runs in CI)")
    path = tj.write_parquet(_run(), tmp_path / "run.parquet", metadata={"method": "rk4", "dt [s]": 1e-3})
    meta = pq.read_schema(path).metadata
    assert b'"method": "rk4"' in meta[b"rigiddyn"]


def test_to_dataframe_has_the_csv_columns_and_t_as_a_column(tmp_path):
    pytest.importorskip("pandas", reason="the dataframe extra (in the test extra: runs in CI)")
    result = _run()
    frame = tj.to_dataframe(result)
    assert list(frame.columns) == tj.column_names()
    assert frame.index.equals(frame.index.__class__(range(len(result.t))))  # a plain row index
    _assert_same_fields(tj.fields_from_columns(frame), result)
    assert result.to_dataframe().equals(frame)  # the method of SimulationResult calls the same function
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
    with pytest.raises(TypeError, match=r"result: expected a SceneResult or SimulationResult \(with \.t\), got dict"):
        tj.columns({"t": [0.0]})
    with pytest.raises(TypeError, match="scalar_first: expected None, True or False, got 'yes'"):
        tj.columns(_run(), scalar_first="yes")
    with pytest.raises(ValueError, match=r"path: expected a \.csv, \.npz or \.parquet file, got .*run\.txt"):
        tj.read_columns(tmp_path / "run.txt")
    with pytest.raises(ValueError, match=r"table: expected the column 't \[s\]'"):
        tj.fields_from_columns({"time": np.zeros(2)})
    (tmp_path / "empty.csv").write_text("")
    with pytest.raises(ValueError, match="path: expected a CSV table with a header row"):
        tj.read_columns(tmp_path / "empty.csv")
