"""Composing n rigid transforms from arrays, X_AC = X_AB * X_BC (R_AC = R_AB R_BC,
p_AC = R_AB p_BC + p_AB): rigiddyn.transform_compose (C++ loop, rotations validated per item)
against the numpy reference rigiddyn_ref.spatial.transform_compose (vectorised numpy, no
validation). Also transform_points against numpy einsum.

    python bench/python/bench_spatial.py           # n = 1e6
    python bench/python/bench_spatial.py --small   # n = 1e4 (what ctest runs)

The reference is imported from tests/reference (on PYTHONPATH under ctest, or found next to this
repository's tests/ when run by hand).
"""

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, import_reference, parse_small
from _bench_common import report_ratio as report

ref = import_reference("spatial")


def random_rotations(rng, n):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    x, y, z, w = q.T
    # R(q) of a unit quaternion (x, y, z, w), written out
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], axis=-1),
            np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], axis=-1),
            np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], axis=-1),
        ],
        axis=1,
    )


def main():
    args = parse_small(__doc__, "1e4 items instead of 1e6")
    n = 10_000 if args.small else 1_000_000
    repeats = 5 if args.small else 3

    rng = np.random.default_rng(0)
    R_AB, R_BC = random_rotations(rng, n), random_rotations(rng, n)
    p_AB, p_BC = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))

    R_rd, p_rd = rd.transform_compose(R_AB, p_AB, R_BC, p_BC)
    R_ref, p_ref = ref.transform_compose(R_AB, p_AB, R_BC, p_BC)
    err = max(np.abs(R_rd - R_ref).max(), np.abs(p_rd - p_ref).max())
    if err > 1e-12:
        raise SystemExit(f"transform_compose disagrees with the reference: max |diff| = {err:.3g}")

    t_rd = best_time(lambda: rd.transform_compose(R_AB, p_AB, R_BC, p_BC), repeats)
    t_ref = best_time(lambda: ref.transform_compose(R_AB, p_AB, R_BC, p_BC), repeats)
    print(f"transform_compose, n = {n}, max |rigiddyn - reference| = {err:.2e}")
    report("transform_compose", n, t_rd, t_ref, "numpy_ref")

    p_B = rng.normal(size=(n, 3))
    t_rd = best_time(lambda: rd.transform_points(R_AB, p_AB, p_B), repeats)
    t_np = best_time(lambda: np.einsum("nij,nj->ni", R_AB, p_B) + p_AB, repeats)
    report("transform_points", n, t_rd, t_np, "numpy_einsum")


if __name__ == "__main__":
    main()
