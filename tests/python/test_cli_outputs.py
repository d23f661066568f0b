"""The command line's outputs and errors (`simulate`, `tradeoff`): the default folder, a run too long to
count, a full disk, an --out the system refuses, earlier files and symbolic links in --out, a warning
raised as an error; each one line on stderr, its documented exit code (rigiddyn.out_folder), nothing
half-written."""

import errno
import os
import subprocess
import sys

import pytest
import rigiddyn.trajectory as trajectory
import rigiddyn.work_precision as work_precision
from rigiddyn.__main__ import main
from rigiddyn.out_folder import (EXIT_BAD_INPUT, EXIT_EXISTS, EXIT_INTERRUPTED, EXIT_OK, EXIT_UNWRITABLE,
                                 OutFolder)

SIMULATE = ["simulate", "t_handle", "--method", "rk4", "--dt", "0.01", "--steps", "20", "--no-plot", "--no-progress"]
SCENE = ["simulate", "rocket", "--steps", "20", "--no-plot", "--no-progress"]
TRADEOFF = ["tradeoff", "t_handle", "--methods", "rk4", "--dts", "0.02", "--horizon", "0.2", "--no-progress"]


def one_line(capsys, command: str) -> str:
    """The one line the command printed on stderr (it starts with 'rigiddyn <command>: ')."""
    err = capsys.readouterr().err
    assert err.startswith(f"rigiddyn {command}: ") and len(err.splitlines()) == 1, err
    return err


def snapshot(folder):
    """Every path below `folder` with its bytes (None for a folder or a link's target not followed)."""
    return {str(p.relative_to(folder)): (os.readlink(p) if p.is_symlink() else None if p.is_dir() else p.read_bytes())
            for p in sorted(folder.rglob("*"))}


# ------------------------------------------------------------------ the default folder


@pytest.mark.parametrize("argv,folder", [(SIMULATE, "simulate-t_handle"), (SCENE, "simulate-rocket")])
def test_simulate_without_out_writes_simulate_name(tmp_path, monkeypatch, capsys, argv, folder):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == EXIT_OK
    assert (tmp_path / folder / "trajectory.csv").is_file()
    assert f"to {folder}\n" in capsys.readouterr().out  # the summary names the folder


def test_the_default_folder_of_a_file_is_its_name(tmp_path, monkeypatch, capsys):
    from rigiddyn.simulate_command import default_out

    assert default_out("some/where/my_box.toml") == "simulate-my_box"
    assert default_out("rocket") == "simulate-rocket"


# ------------------------------------------------------------------ a run too long to count


@pytest.mark.parametrize("argv", [
    SIMULATE[:4] + ["--dt", "1e-300", "--duration", "1e300", "--no-plot"],  # duration / dt overflows to inf
    SIMULATE[:4] + ["--dt", "1e-10", "--duration", "1e10", "--no-plot"],  # 1e20 steps: finite, beyond 2**53
    ["simulate", "rocket", "--dt", "1e-300", "--duration", "1e300", "--no-plot"],
])
def test_a_run_too_long_to_count_is_bad_input(tmp_path, capsys, argv):
    out = tmp_path / "never"
    assert main([*argv, "--out", str(out)]) == EXIT_BAD_INPUT
    assert "--duration: expected a run of at most 2**53 steps" in one_line(capsys, "simulate")
    assert not out.exists()


def test_steps_beyond_the_limit_are_bad_input(tmp_path, capsys):
    assert main([*SIMULATE[:6], "--steps", str(10**30), "--out", str(tmp_path / "o")]) == EXIT_BAD_INPUT
    assert "--steps: expected an integer number of steps from 1 to 2**53" in one_line(capsys, "simulate")


# ------------------------------------------------------------------ a full disk


def _full_disk(*args, **kwargs):
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(args[1]))


@pytest.mark.parametrize("argv", [SIMULATE, SCENE])
def test_a_full_disk_leaves_nothing_behind(tmp_path, monkeypatch, capsys, argv):
    """The second file fails as on a full disk: exit 3, one line naming it (its place in --out, not the
    temporary folder), no folder made (not even its parents), nothing left next to it."""
    import numpy as np

    monkeypatch.setattr(trajectory, "write_npz", _full_disk)  # the problem's writer of trajectory.npz
    monkeypatch.setattr(np, "savez", lambda f, **arrays: _full_disk(None, f.name))  # the scene's
    out = tmp_path / "parent" / "out"
    assert main([*argv, "--out", str(out)]) == EXIT_UNWRITABLE
    err = one_line(capsys, "simulate")
    assert f"cannot write {str(out / 'trajectory.npz')!r}: No space left on device (the disk is full)" in err
    assert "nothing written" in err
    assert list(tmp_path.iterdir()) == []


def test_a_full_disk_leaves_an_existing_folder_as_it_was(tmp_path, monkeypatch, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    monkeypatch.setattr(trajectory, "write_npz", _full_disk)
    assert main([*SIMULATE, "--out", str(out)]) == EXIT_UNWRITABLE
    one_line(capsys, "simulate")
    assert snapshot(tmp_path) == {"out": None, "out/notes.txt": b"mine"}


def test_a_full_disk_under_tradeoff_leaves_nothing_behind(tmp_path, monkeypatch, capsys):
    def full_disk(self, path=None):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))

    monkeypatch.setattr(work_precision.TradeoffResult, "to_json", full_disk)
    out = tmp_path / "out"
    assert main([*TRADEOFF, "--out", str(out)]) == EXIT_UNWRITABLE
    err = capsys.readouterr().err.splitlines()[-1]
    assert err.startswith("rigiddyn tradeoff: cannot write") and "tradeoff.json" in err and "disk is full" in err
    assert list(tmp_path.iterdir()) == []


def test_an_interrupt_while_writing_leaves_nothing_behind(tmp_path, monkeypatch, capsys):
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(trajectory, "write_npz", interrupted)
    assert main([*SIMULATE, "--out", str(tmp_path / "out")]) == EXIT_INTERRUPTED
    assert "interrupted; nothing written" in one_line(capsys, "simulate")
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------------------------------ an --out the system refuses


@pytest.mark.parametrize("argv,command", [(SIMULATE, "simulate"), (SCENE, "simulate"), (TRADEOFF, "tradeoff")])
def test_an_out_of_5000_characters_is_one_line(tmp_path, monkeypatch, capsys, argv, command):
    def no_run(*args, **kwargs):
        raise AssertionError("ran before --out was checked")

    monkeypatch.setattr(work_precision, "tradeoff", no_run)
    monkeypatch.chdir(tmp_path)
    assert main([*argv, "--out", "a" * 5000]) == EXIT_BAD_INPUT
    err = one_line(capsys, command)
    assert "--out: expected a folder where" in err and "a path of 5000 characters" in err
    assert "File name too long" in err and len(err) < 400
    assert list(tmp_path.iterdir()) == []


def test_a_problem_path_of_5000_characters_is_one_line(capsys):
    assert main(["simulate", "a" * 5000 + ".toml", "--method", "rk4", "--dt", "0.1"]) == EXIT_BAD_INPUT
    assert "PROBLEM: expected" in one_line(capsys, "simulate")


# ------------------------------------------------------------------ earlier files and links in --out


@pytest.mark.parametrize("argv,command,name", [(SIMULATE, "simulate", "trajectory.csv"),
                                               (SCENE, "simulate", "trajectory.csv"),
                                               (TRADEOFF, "tradeoff", "tradeoff.csv")])
def test_earlier_files_are_refused_by_name_unless_force(tmp_path, capsys, argv, command, name):
    out = tmp_path / "out"
    assert main([*argv, "--out", str(out)]) == EXIT_OK
    (out / name).write_text("an earlier run's")
    before = snapshot(tmp_path)
    assert main([*argv, "--out", str(out)]) == EXIT_EXISTS
    capsys.readouterr()
    assert main([*argv, "--out", str(out)]) == EXIT_EXISTS
    err = one_line(capsys, command)
    assert f"{str(out / name)!r} exists" in err and "--force" in err
    assert snapshot(tmp_path) == before
    assert main([*argv, "--out", str(out), "--force"]) == EXIT_OK
    assert (out / name).read_text() != "an earlier run's"


def test_force_removes_the_earlier_plot_the_run_does_not_write(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    out = tmp_path / "out"
    plotted = [a for a in SIMULATE if a != "--no-plot"]
    assert main([*plotted, "--out", str(out)]) == EXIT_OK
    assert (out / "trajectory.png").is_file()
    assert main([*SIMULATE, "--out", str(out)]) == EXIT_EXISTS  # the plot is the command's too
    assert "trajectory" in capsys.readouterr().err
    assert main([*SIMULATE, "--out", str(out), "--force"]) == EXIT_OK
    assert not (out / "trajectory.png").exists()  # an earlier run's plot beside this run's tables: removed


@pytest.mark.parametrize("argv,command,name", [(SIMULATE, "simulate", "run.json"),
                                               (TRADEOFF, "tradeoff", "tradeoff.json")])
def test_a_symbolic_link_in_out_is_never_written_through(tmp_path, capsys, argv, command, name):
    victim = tmp_path / "elsewhere.txt"
    victim.write_text("not the command's")
    out = tmp_path / "out"
    out.mkdir()
    (out / name).symlink_to(victim)
    assert main([*argv, "--out", str(out)]) == EXIT_EXISTS
    err = one_line(capsys, command)
    assert f"{str(out / name)!r} is a symbolic link (to {str(victim)!r})" in err
    assert main([*argv, "--out", str(out), "--force"]) == EXIT_OK
    assert victim.read_text() == "not the command's"  # --force replaced the link, not what it points to
    assert not (out / name).is_symlink() and (out / name).is_file()


def test_a_file_that_appears_during_the_run_is_not_overwritten(tmp_path, monkeypatch):
    """The check is made again when the files are moved into place."""
    out = tmp_path / "out"
    out.mkdir()
    folder = OutFolder(str(out), ["a.txt"])

    def write(partial):
        (out / "a.txt").write_text("someone else's")  # meanwhile
        (partial / "a.txt").write_text("the run's")
        return [partial / "a.txt"]

    with pytest.raises(Exception, match="a.txt' exists"):
        folder.write(write)
    assert snapshot(tmp_path) == {"out": None, "out/a.txt": b"someone else's"}


# ------------------------------------------------------------------ a warning raised as an error


def test_a_warning_raised_as_an_error_is_one_line(tmp_path):
    """python -W error turns the StabilityWarning of a step beyond the method's limit into an exception:
    one line naming it, exit 2, no traceback, nothing written."""
    argv = ["simulate", "t_handle", "--method", "splitting_dlm", "--dt", "1.0", "--steps", "3", "--no-plot",
            "--out", "never"]
    done = subprocess.run([sys.executable, "-W", "error", "-m", "rigiddyn", *argv], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path)
    assert done.returncode == EXIT_BAD_INPUT, done.stderr
    assert done.stderr.startswith("rigiddyn simulate: StabilityWarning: ") and "Traceback" not in done.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_exit_codes_are_in_the_help():
    for command in ("simulate", "tradeoff"):
        done = subprocess.run([sys.executable, "-m", "rigiddyn", command, "--help"], capture_output=True, text=True,
                              check=True, timeout=120)
        text = " ".join(done.stdout.split())
        for code in ("0 done", "2 bad input", "3 the outputs could not be written", "4 --out holds files",
                     "130 interrupted"):
            assert code in text, (command, code)
        assert "--force" in text
