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


def test_a_kernel_the_cpu_lacks_or_a_bad_name_is_refused() -> None:
    run = subprocess.run([sys.executable, str(SCRIPT), "HEAD", "--kernel", "no_such_kernel"], capture_output=True,
                         text=True, timeout=60)
    assert run.returncode != 0 and "no_such_kernel" in run.stderr
