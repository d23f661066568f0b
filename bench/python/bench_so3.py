"""Rotations on n items from arrays: rigiddyn's array API (C++ loops, every quaternion / matrix
validated per item) against the numpy reference rigiddyn_ref.so3 (vectorised numpy, no
validation) for quat_rotate, quat_to_matrix and matrix_to_quat; quat_rotate also against the
formula in plain vectorised numpy (np.cross); and every array rotation function against SciPy's
Rotation (where SciPy is installed). A constructor (from_matrix, from_rotvec, from_mrp, from_euler) is
timed with the as_quat that gives rigiddyn's output. rigiddyn validates every item (finite, unit norm,
rotation matrix) and normalises every quaternion in its time.

A SciPy method that starts from a rotation (as_matrix, as_rotvec, as_mrp, as_euler, inv, apply, *) is
timed twice: on a Rotation built beforehand, as a SciPy user holds one ("scipy": SciPy's time then
excludes the checks and the normalisation that Rotation.from_quat did once, which rigiddyn's includes),
and like with like, from the quaternion array with Rotation.from_quat (its finiteness check and
normalisation) included ("scipy_from_quat").

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
    compare_with_scipy(Rotation, q, v, R, n, repeats)


def compare_with_scipy(Rotation, q, v, R, n, repeats):
    """rigiddyn's array rotation functions against SciPy's Rotation on the same items (each pair
    checked equal first: rotations up to the sign of quaternions, angles to 1e-9 rad). A SciPy method
    of a Rotation also against SciPy from the quaternions (from_quat included: like with like)."""
    r = Rotation.from_quat(q)
    r2 = Rotation.from_quat(q[::-1].copy())
    q2 = r2.as_quat()
    rotvec, mrp, angles = r.as_rotvec(), r.as_mrp(), r.as_euler("xyz")
    cases = [
        ("quat_to_matrix", lambda: rd.quat_to_matrix(q), r.as_matrix),
        ("matrix_to_quat", lambda: rd.matrix_to_quat(R), lambda: Rotation.from_matrix(R).as_quat()),
        ("quat_to_rotvec", lambda: rd.quat_to_rotvec(q), r.as_rotvec),
        ("rotvec_to_quat", lambda: rd.rotvec_to_quat(rotvec), lambda: Rotation.from_rotvec(rotvec).as_quat()),
        ("rotvec_to_matrix", lambda: rd.rotvec_to_matrix(rotvec), lambda: Rotation.from_rotvec(rotvec).as_matrix()),
        ("matrix_to_rotvec", lambda: rd.matrix_to_rotvec(R), lambda: Rotation.from_matrix(R).as_rotvec()),
        ("quat_to_mrp", lambda: rd.quat_to_mrp(q), r.as_mrp),
        ("mrp_to_quat", lambda: rd.mrp_to_quat(mrp), lambda: Rotation.from_mrp(mrp).as_quat()),
        ("quat_to_euler", lambda: rd.quat_to_euler("xyz", q), lambda: r.as_euler("xyz")),
        ("euler_to_quat", lambda: rd.euler_to_quat("xyz", angles), lambda: Rotation.from_euler("xyz", angles).as_quat()),
        ("quat_inverse", lambda: rd.quat_inverse(q), lambda: r.inv().as_quat()),
        ("quat_multiply", lambda: rd.quat_multiply(q, q2), lambda: (r * r2).as_quat()),
        ("quat_rotate", lambda: rd.quat_rotate(q, v), lambda: r.apply(v)),
    ]
    from_quat = {
        "quat_to_matrix": lambda: Rotation.from_quat(q).as_matrix(),
        "quat_to_rotvec": lambda: Rotation.from_quat(q).as_rotvec(),
        "quat_to_mrp": lambda: Rotation.from_quat(q).as_mrp(),
        "quat_to_euler": lambda: Rotation.from_quat(q).as_euler("xyz"),
        "quat_inverse": lambda: Rotation.from_quat(q).inv().as_quat(),
        "quat_multiply": lambda: (Rotation.from_quat(q) * Rotation.from_quat(q2)).as_quat(),
        "quat_rotate": lambda: Rotation.from_quat(q).apply(v),
    }
    for case, ours, theirs in cases:
        a, b = ours(), theirs()
        same = np.minimum(np.abs(a - b), np.abs(a + b)) if a.shape[-1] == 4 else np.abs(a - b)
        if same.max() > 1e-9:
            raise SystemExit(f"{case} disagrees with SciPy: max |diff| = {same.max():.3g}")
        t_rd = best_time(ours, repeats)
        report(case, n, t_rd, best_time(theirs, repeats), "scipy")
        if case in from_quat:
            report(case, n, t_rd, best_time(from_quat[case], repeats), "scipy_from_quat")


if __name__ == "__main__":
    main()
