"""bench/python/pair_sum_side_by_side.py, the maintainers' comparison of one N-body pair-sum kernel of two revisions
in one process, still builds and runs: the portable kernel of the checked-out revision against the working tree's
(the same source where the tree is clean), one round. Its timings are not checked (no wall-clock limits in tests);
its parts are: every size printed once, finite positive times, and a difference of zero where both sides compile the
same source."""

import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "bench" / "python" / "pair_sum_side_by_side.py"
KERNEL = "cpp/src/scene/elements/pair_forces.cpp"


def _git(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True)


@pytest.mark.skipif(shutil.which("git") is None or shutil.which("g++") is None, reason="needs git and g++")
def test_the_kernel_of_two_revisions_runs_side_by_side() -> None:
    if _git("rev-parse", "--verify", "HEAD").returncode != 0:
        pytest.skip("not a git checkout")
    same_source = _git("diff", "--quiet", "HEAD", "--", KERNEL, "cpp/include").returncode == 0
    run = subprocess.run([sys.executable, str(SCRIPT), "HEAD", "--kernel", "add_pair_forces_portable", "--rounds", "1"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    rows = [line.split() for line in run.stdout.splitlines() if line.split() and line.split()[0].isdigit()]
    assert [int(r[0]) for r in rows] == [12, 24, 50, 100, 300, 1000]
    for n, base, head, ratio, difference in rows:
        assert float(base) > 0.0 and float(head) > 0.0 and float(ratio) > 0.0
        if same_source:  # one source compiled twice: the same operations, the same bits
            assert float(difference) == 0.0, f"n = {n}: {difference}"


def test_an_unknown_kernel_or_no_round_is_refused_naming_the_value() -> None:
    for arguments, named in ((["--kernel", "no_such_kernel"], "no_such_kernel"), (["--rounds", "0"], "got 0")):
        run = subprocess.run([sys.executable, str(SCRIPT), "HEAD", *arguments], capture_output=True, text=True,
                             timeout=60)
        assert run.returncode != 0 and named in run.stderr, run.stderr


def test_a_kernel_whose_instructions_the_cpu_lacks_is_refused() -> None:
    sys.path.insert(0, str(SCRIPT.parent))
    try:
        import pair_sum_side_by_side as tool
    finally:
        sys.path.remove(str(SCRIPT.parent))
    with pytest.raises(SystemExit, match="lacks avx512f"):
        tool.check_runs_here("add_pair_forces_avx512", flags=["avx2", "fma"])
    with pytest.raises(SystemExit, match="lacks avx2, fma"):
        tool.check_runs_here("pair_potential_avx2_fma", flags=[])
    tool.check_runs_here("add_pair_forces_portable", flags=[])  # needs nothing
    tool.check_runs_here("add_pair_forces_avx512", flags=["avx512f"])
