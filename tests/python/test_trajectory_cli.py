"""`python -m rigiddyn simulate`: end to end on a shipped problem, its checks before the run, and the
progress bar (fed by simulate's callback, so a run with it is the run without it)."""

import io
import json
import re
import subprocess
import sys

import numpy as np
import pytest
import rigiddyn as rd
from rigiddyn import trajectory as tj
from rigiddyn.__main__ import main
from rigiddyn.simulate_command import MAX_DEFAULT_RECORDS, progress_bar, simulate_problem


def _same(result, table):
    """Every column of `result`'s table (rigiddyn.trajectory.columns) equals `table`'s, to the bit: the same
    computation in the same order (or the exact file formats)."""
    expected = tj.columns(result)
    assert list(table) == list(expected)
    for name, values in expected.items():
        np.testing.assert_array_equal(np.asarray(table[name]), values, err_msg=name)


def test_cli_end_to_end_on_a_shipped_problem(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out" / "t_handle"  # parents created
    code = main(["simulate", "t_handle", "--method", "rkmk4", "--dt", "0.002", "--duration", "1.0",
                 "--record-every", "5", "--out", str(out), "--animate", "gif", "--frames", "3",
                 "--attitude", "euler:ZXZ"])
    assert code == 0
    printed = capsys.readouterr().out
    assert "101 records to t = 1 s" in printed and "wrote " in printed
    names = {"trajectory.csv", "trajectory.npz", "run.json", "trajectory.png", "axes.gif"}
    assert names <= {p.name for p in out.iterdir()}
    # the files hold the run rigiddyn.simulate gives for the same problem and settings
    expected = simulate_problem(rd.load_problem("t_handle"), "rkmk4", 0.002, 500, record_every=5)
    tables = ["trajectory.csv", "trajectory.npz"]
    if (out / "trajectory.parquet").exists():  # written when pyarrow is installed
        tables.append("trajectory.parquet")
    for name in tables:
        _same(expected, tj.read_columns(out / name))
    record = json.loads((out / "run.json").read_text())
    assert record["method"] == "rkmk4" and record["steps"] == 500 and record["records"] == 101
    assert record["columns"] == list(tj.columns(expected))


def test_cli_defaults_horizon_and_record_count(tmp_path, capsys):
    code = main(["simulate", "t_handle", "--method", "rk4", "--dt", "1e-4", "--out", str(tmp_path), "--no-plot"])
    assert code == 0
    # horizon 4 s of the file / 1e-4 s = 40000 steps; the least k with 40000 / k <= MAX_DEFAULT_RECORDS
    k = -(-40_000 // MAX_DEFAULT_RECORDS)
    assert f"{40_000 // k + 1} records to t = 4 s" in capsys.readouterr().out
    assert not (tmp_path / "trajectory.png").exists()


def test_cli_parquet_when_pyarrow_is_installed(tmp_path):
    pytest.importorskip("pyarrow", reason="the parquet extra (in the test extra: runs in CI)")
    assert main(["simulate", "projectile", "--method", "rk4", "--dt", "0.01", "--steps", "30", "--out",
                 str(tmp_path), "--no-plot"]) == 0
    parquet, csv = (tj.read_columns(tmp_path / f"trajectory.{suffix}") for suffix in ("parquet", "csv"))
    assert list(parquet) == list(csv)
    assert list(csv)[:2] == ["t [s]", "body0:p_W_x [m]"]  # the table of the one-body scene
    for name in csv:
        np.testing.assert_array_equal(parquet[name], csv[name])  # both exact: equal to the bit


@pytest.mark.parametrize("argv,message", [
    (["nothing_like_it", "--method", "rk4", "--dt", "0.01"], "PROBLEM: expected .* one of the examples .*t_handle"),
    (["t_handle", "--method", "rk5", "--dt", "0.01"], "--method: expected one of"),
    (["t_handle", "--method", "rk4", "--dt", "0.01", "--duration", "0.001"],
     r"--duration: expected a time span >= dt = 0.01 s, got 0.001"),
    (["t_handle", "--method", "rk4", "--dt", "0.01", "--attitude", "euler:ZZ"], "attitude: expected euler:SEQ"),
])
def test_cli_bad_input_is_refused_before_the_run(tmp_path, capsys, argv, message):
    out = tmp_path / "never"
    assert main(["simulate", *argv, "--out", str(out), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("rigiddyn simulate: ") and len(err.splitlines()) == 1
    assert re.search(message, err), err
    assert not out.exists()  # nothing written, not even the folder


@pytest.mark.parametrize("argv,message", [
    (["--dt", "-1"], "argument --dt: expected a time step [s] > 0, got '-1'"),
    (["--dt", "fast"], "argument --dt: expected a time step [s] > 0, got 'fast'"),
    (["--dt", "nan"], "argument --dt: expected a time step [s] > 0, got 'nan'"),
    (["--dt", "0.1", "--steps", "2.5"], "argument --steps: expected an integer number of steps >= 1, got '2.5'"),
    (["--dt", "0.1", "--steps", "10", "--duration", "1"], "argument --duration: not allowed with argument --steps"),
    (["--dt", "0.1", "--record-every", "0"], "argument --record-every: expected an integer >= 1, got '0'"),
    (["--dt", "0.1", "--animate", "avi"], "argument --animate: invalid choice: 'avi'"),
    (["--dt", "0.1", "--frames", "0"], "argument --frames: expected an integer >= 1, got '0'"),
])
def test_cli_bad_arguments_name_the_option(tmp_path, capsys, argv, message):
    with pytest.raises(SystemExit) as exit_:
        main(["simulate", "t_handle", "--method", "rk4", *argv, "--out", str(tmp_path / "never")])
    assert exit_.value.code == 2
    assert message in capsys.readouterr().err
    assert not (tmp_path / "never").exists()


def test_cli_out_must_be_a_writable_folder(tmp_path, capsys):
    file = tmp_path / "a_file"
    file.write_text("")
    assert main(["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--out", str(file)]) == 2
    assert "--out: expected a folder where trajectory.csv" in capsys.readouterr().err
    assert main(["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--out", str(file / "below")]) == 2
    assert "--out: expected a folder where trajectory.csv" in capsys.readouterr().err


def test_cli_animate_without_any_writer_is_refused_before_the_run(tmp_path, capsys, monkeypatch):
    pytest.importorskip("matplotlib")
    from matplotlib import animation

    monkeypatch.setattr(animation.writers, "is_available", lambda name: False)
    argv = ["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--animate", "--out", str(tmp_path / "o")]
    assert main(argv) == 2
    assert "--animate: animate: no animation writer: MP4 needs ffmpeg" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_progress_run_equals_the_plain_run():
    problem = rd.load_problem("t_handle")
    calls = []
    with_progress = simulate_problem(problem, "splitting_dlm", 1e-4, 40_000, 100, progress=calls.append)
    plain = simulate_problem(problem, "splitting_dlm", 1e-4, 40_000, 100)
    _same(with_progress, tj.columns(plain))
    # simulate calls back from its C++ loop between steps (every 4096 steps, at most every 0.05 s):
    # never per step, and only with step counts of the run
    assert len(calls) <= 40_000 // 4096
    assert all(0 < c <= 40_000 for c in calls) and calls == sorted(calls)


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_bar_only_on_a_terminal_with_tqdm():
    assert progress_bar(100, io.StringIO())[0] is None  # not a terminal: no bar
    pytest.importorskip("tqdm", reason="the progress extra (in the test extra: runs in CI)")
    stream = _Terminal()
    update, close = progress_bar(40_000, stream)
    problem = rd.load_problem("t_handle")
    result = simulate_problem(problem, "rk4", 1e-4, 40_000, 100, progress=update)
    update(40_000)
    close()
    assert "100%" in stream.getvalue() and "40.0k/40.0k" in stream.getvalue()
    _same(result, tj.columns(simulate_problem(problem, "rk4", 1e-4, 40_000, 100)))


def test_progress_bar_without_tqdm_is_none(monkeypatch):
    monkeypatch.setitem(sys.modules, "tqdm", None)
    update, close = progress_bar(10, _Terminal())
    assert update is None
    close()


def test_command_line_help_lists_simulate():
    done = subprocess.run([sys.executable, "-m", "rigiddyn", "simulate", "--help"], capture_output=True, text=True,
                          check=True)
    for option in ("--method", "--dt", "--duration", "--steps", "--record-every", "--out", "--attitude", "--animate",
                   "--no-progress", "splitting_dlm"):
        assert option in done.stdout


# ------------------------------------------------------------------ what the summary says about energy


def _balance(printed):
    """The residual [J] of the summary's energy balance."""
    return float(re.search(r"energy balance T\(t\) - T\(0\) - W\(t\) = (\S+) J", printed).group(1))


def test_loads_that_work_give_the_energy_balance_not_a_drift(tmp_path, capsys):
    """A body torque does work: the total energy changes by it (by +114 % here), which is no drift; the
    summary gives T(t) - T(0) - W(t) instead, as the written table's columns give it."""
    out = tmp_path / "out"
    assert main(["simulate", "satellite_torque", "--method", "rk4", "--dt", "1", "--out", str(out), "--no-plot",
                 "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert "relative drift: total energy" not in printed and "W the work of the loads and gravity" in printed
    table = tj.read_columns(out / "trajectory.csv")
    T = table["kinetic_energy [J]"]
    W = sum(values for name, values in table.items() if name.startswith("work["))  # every element's work
    # printed with 3 significant digits ("%+.2e"): equal to 0.5 % of itself
    assert _balance(printed) == pytest.approx(T[-1] - T[0] - W[-1], rel=5e-3)
    assert abs(T[-1] - T[0]) > 1e6 * abs(_balance(printed))  # the energy did change, by the work


def test_without_loads_the_summary_gives_the_drift(tmp_path, capsys):
    assert main(["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--out", str(tmp_path / "o"),
                 "--no-plot", "--no-progress"]) == 0
    assert "relative drift: total energy" in capsys.readouterr().out


@pytest.mark.parametrize("name,balance", [("box_on_springs", True), ("spring_chain", True), ("kepler", False)])
def test_a_scene_with_dampers_gives_the_energy_balance(tmp_path, capsys, name, balance):
    """Dampers dissipate: the total energy of box_on_springs falls by most of itself, no drift; the
    balance with the work of every element is the measure. kepler (gravity only) keeps its drift."""
    assert main(["simulate", name, "--steps", "200", "--out", str(tmp_path / "o"), "--no-plot", "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert ("W the work of every element" in printed) is balance
    assert ("relative drift of the total energy" in printed) is not balance
