"""Two former crashes raise instead, each checked in a child process so that a crash
(a segfault cannot be caught) fails one test instead of taking pytest down:

(a) a FrameTree chain deeper than any recursion could go (the tree walks are iterative);
(b) an array argument whose contiguous float64 copy cannot be allocated raises MemoryError naming
    the argument, for every argument of every public entry point that takes an array (the valid
    calls of test_argument_errors.EXAMPLES, each array argument in turn replaced by a read-only
    broadcast view of 10**10 of its rows).
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import rigiddyn

HERE = Path(__file__).resolve().parent


def run_child(code: str, address_space_gib: int | None = None) -> subprocess.CompletedProcess:
    """Run `code` in a fresh Python on the rigiddyn this pytest imports (optionally with its address
    space limited, so that an allocation a large machine could make fails there too)."""
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    package_dir = os.path.dirname(os.path.dirname(os.path.abspath(rigiddyn.__file__)))  # not resolved: symlinks
    env["PYTHONPATH"] = os.pathsep.join([package_dir, str(HERE), env.get("PYTHONPATH", "")])
    prelude = ""
    if address_space_gib is not None:
        prelude = ("import resource\nresource.setrlimit(resource.RLIMIT_AS, "
                   f"({address_space_gib} << 30, resource.getrlimit(resource.RLIMIT_AS)[1]))\n")
    return subprocess.run([sys.executable, "-c", prelude + textwrap.dedent(code)], env=env,
                          capture_output=True, text=True)


def _crash_message(proc: subprocess.CompletedProcess) -> str:
    return f"child exited with {proc.returncode}\nstdout (last lines):\n{proc.stdout[-3000:]}\nstderr:\n{proc.stderr[-3000:]}"


DEPTH = 20_000  # the crash appeared at ~12 000 frames in Python's default stack


def test_deep_frame_chain_is_walked_without_recursion():
    code = f"""
    import json
    import numpy as np
    import rigiddyn as rd

    rate, t = 1e-3, 1.0
    tree = rd.FrameTree()
    parent = "world"
    for i in range({DEPTH}):
        tree.add_frame(f"f{{i}}", parent, rd.FrameMotion.constant_rotation([0, 0, 1.0], rate))
        parent = f"f{{i}}"
    out = {{
        "R": tree.rotation(parent, "world", t).tolist(),
        "w": tree.angular_velocity(parent, "world", "world", t).tolist(),
        "a": tree.point_acceleration(parent, [1.0, 0, 0], [0, 0, 0], [0, 0, 0], "world", "world", t).total.tolist(),
        "mid": tree.rotation(parent, "f{DEPTH // 2}", t).tolist(),
    }}
    try:  # the cycle check walks the whole chain too
        tree.set_parent("f0", parent, rd.FrameMotion.fixed())
    except ValueError as e:
        out["cycle"] = str(e)
    print(json.dumps(out))
    """
    proc = run_child(code)
    assert proc.returncode == 0, _crash_message(proc)
    out = json.loads(proc.stdout.splitlines()[-1])
    # DEPTH rotations about z by rate t each: about z by DEPTH rate t = 20 rad. Each composition is a
    # 3x3 product of rotations (<= 3 eps per entry, |R| = 1), so the chain errs by <= 3 eps DEPTH = 1.3e-11
    eps = np.finfo(float).eps
    angle = DEPTH * 1e-3
    c, s = np.cos(angle), np.sin(angle)
    np.testing.assert_allclose(out["R"], [[c, -s, 0], [s, c, 0], [0, 0, 1]], atol=3 * eps * DEPTH)
    # the angular velocities add up: DEPTH terms of 1e-3, each sum rounding <= eps of the total
    np.testing.assert_allclose(out["w"], [0, 0, angle], atol=eps * angle * DEPTH)
    # a point fixed at (1, 0, 0) in the last frame: centripetal acceleration |w|^2 = 400 m/s^2 towards the
    # axis (the error of R above, times |w|^2, plus that of w: 2 |w| dw)
    np.testing.assert_allclose(out["a"], [-angle**2 * c, -angle**2 * s, 0],
                               atol=angle**2 * 3 * eps * DEPTH + 2 * angle * eps * angle * DEPTH)
    half = (DEPTH - DEPTH // 2 - 1) * 1e-3  # frames below f{DEPTH/2}
    np.testing.assert_allclose(out["mid"], [[np.cos(half), -np.sin(half), 0], [np.sin(half), np.cos(half), 0],
                                            [0, 0, 1]], atol=2 * 3 * eps * DEPTH)
    assert out["cycle"].startswith("parent: expected a frame that is neither 'f0' nor one of its descendants")


def test_quat_to_matrix_of_ten_billion_rows_raises_memory_error():
    # the reproducer of case (b): 298 GiB for the float64 copy
    code = """
    import numpy as np
    import rigiddyn as rd
    try:
        rd.quat_to_matrix(np.broadcast_to([0, 0, 0, 1.0], (10**10, 4)))
    except MemoryError as e:
        print("MemoryError", e)
    """
    proc = run_child(code, address_space_gib=32)
    assert proc.returncode == 0, _crash_message(proc)
    assert proc.stdout.startswith("MemoryError q: cannot allocate a contiguous float64 copy of shape (10000000000, 4)")


def array_arguments():
    """(call, argument, value as a float64 array) for each array argument of each valid example call."""
    import test_argument_errors as T

    for target in T.TARGETS:
        if target.path not in T.EXAMPLES:
            continue
        for argument, value in T.EXAMPLES[target.path]().items():
            if callable(value) or isinstance(value, (str, bool, int, float)) or value is None:
                continue
            try:
                a = np.asarray(value, dtype=float)
            except (TypeError, ValueError):
                continue  # not an array (a bound object, a list of them)
            if a.size:  # an empty list (of rows) has no row to repeat
                yield target, argument, a


ROWS = 10**10
CASES = [f"{target.path}({argument}=...)" for target, argument, _ in array_arguments()]


@pytest.fixture(scope="module")
def huge_array_outcomes():
    """Each case called in one child process: {case: (exception type or "returned", message)}."""
    code = f"""
    import json, warnings
    import numpy as np
    import test_argument_errors as T
    from test_crash_cases import array_arguments

    warnings.simplefilter("ignore")
    for target, argument, a in array_arguments():
        case = f"{{target.path}}({{argument}}=...)"
        print(json.dumps({{"start": case}}), flush=True)
        huge = np.broadcast_to(a, ({ROWS}, *a.shape))
        try:
            T._call(target, {{**T.EXAMPLES[target.path](), argument: huge}})
            outcome = ("returned", "")
        except Exception as e:  # judged by the test of the case
            outcome = (type(e).__name__, str(e))
        print(json.dumps({{"case": case, "outcome": outcome}}), flush=True)
    """
    proc = run_child(code, address_space_gib=32)
    outcomes = {}
    for line in proc.stdout.splitlines():
        record = json.loads(line)
        outcomes[record.get("case", record.get("start"))] = record.get("outcome", ("crashed", _crash_message(proc)))
    return outcomes


@pytest.mark.parametrize("case", CASES)
def test_an_array_argument_too_large_to_copy_raises(huge_array_outcomes, case):
    """Every array argument of every valid example call, replaced by a read-only broadcast view of 10**10
    rows of itself: MemoryError naming the argument, or a ValueError/TypeError naming it (a shape that
    argument never takes), never a crash (the call then never finished) and never a result."""
    assert len(CASES) > 50  # the sweep reached the API (about 150 array arguments)
    assert case in huge_array_outcomes, "not reached: the child crashed before (see the case marked crashed)"
    kind, message = huge_array_outcomes[case]
    assert kind in ("MemoryError", "ValueError", "TypeError"), f"{kind}: {message}"
    argument = case[case.index("(") + 1:case.index("=")]
    assert _names_argument(message, argument), f"{kind} does not name {argument!r}: {message!r}"


def _names_argument(message: str, argument: str) -> bool:
    """The message's subject (before ": expected" or ": cannot allocate") names the argument."""
    for marker in (": expected", ": cannot allocate"):
        if marker in message:
            subject = message.split(marker, 1)[0]
            return re.search(rf"(?<![A-Za-z0-9_]){re.escape(argument)}(?![A-Za-z0-9_])", subject) is not None
    return False
