"""Rotations on n items from arrays: rigiddyn's array API (C++ loops, every quaternion / matrix
validated per item) against the numpy reference rigiddyn_ref.so3 (vectorised numpy, no
validation) for quat_rotate, quat_to_matrix and matrix_to_quat; quat_rotate also against the
formula in plain vectorised numpy (np.cross) and against scipy's Rotation.apply.

    python bench/python/bench_so3.py           # n = 1e6
    python bench/python/bench_so3.py --small   # n = 1e4 (what ctest runs)

The reference is imported from tests/reference (on PYTHONPATH under ctest, or found next to this
repository's tests/ when run by hand).
"""

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, import_reference, parse_small
from _bench_common import report_ratio as report

ref = import_reference("so3")


def check(case, a, b):
    """rigiddyn and the reference agree (up to the sign of quaternions)"""
    err = np.abs(a - b).max() if a.shape[-1] != 4 else np.minimum(np.abs(a - b), np.abs(a + b)).max()
    if err > 1e-12:
        raise SystemExit(f"{case} disagrees with the reference: max |diff| = {err:.3g}")
    return err


def rotate_numpy(q, v):
    """v + 2 w (u × v) + 2 u × (u × v), vectorised numpy"""
    u, w = q[:, :3], q[:, 3:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def main():
    args = parse_small(__doc__, "1e4 items instead of 1e6")
    n = 10_000 if args.small else 1_000_000
    repeats = 5 if args.small else 3

    rng = np.random.default_rng(0)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    v = rng.normal(size=(n, 3))
    R = rd.quat_to_matrix(q)

    cases = [
        ("quat_rotate", lambda m: m.quat_rotate(q, v)),
        ("quat_to_matrix", lambda m: m.quat_to_matrix(q)),
        ("matrix_to_quat", lambda m: m.matrix_to_quat(R)),
    ]
    for case, call in cases:
        err = check(case, call(rd), call(ref))
        t_rd = best_time(lambda: call(rd), repeats)
        t_ref = best_time(lambda: call(ref), repeats)
        print(f"{case}, n = {n}, max |rigiddyn - reference| = {err:.2e}")
        report(case, n, t_rd, t_ref, "numpy_ref")

    check("quat_rotate (numpy cross)", rd.quat_rotate(q, v), rotate_numpy(q, v))
    t_rd = best_time(lambda: rd.quat_rotate(q, v), repeats)
    report("quat_rotate", n, t_rd, best_time(lambda: rotate_numpy(q, v), repeats), "numpy_cross")
    try:
        from scipy.spatial.transform import Rotation
    except ImportError:
        return
    r = Rotation.from_quat(q)
    report("quat_rotate", n, t_rd, best_time(lambda: r.apply(v), repeats), "scipy_apply")


if __name__ == "__main__":
    main()
