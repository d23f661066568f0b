"""Inertia benchmarks through the Python API: a ~100k-triangle mesh (rigiddyn.solid_mesh vs
trimesh's mass properties, if installed, and vs rigiddyn_ref.inertia, if present) and principal
axes of 1e6 inertias through the (n, 3, 3) array API vs numpy.linalg.eigh. Prints times and ratios.
`--small` shrinks the sizes for ctest."""

from __future__ import annotations

import importlib

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, import_reference, parse_small, report_ratio


def uv_sphere(triangles: int) -> tuple[np.ndarray, np.ndarray]:
    n = max(4, int(np.sqrt(triangles / 2)))
    phi = np.pi * np.arange(1, n) / n
    t = 2 * np.pi * np.arange(n) / n
    ring = np.stack(np.broadcast_arrays(np.sin(phi)[:, None] * np.cos(t), np.sin(phi)[:, None] * np.sin(t), -np.cos(phi)[:, None]), -1)
    V = np.vstack([[0, 0, -1], ring.reshape(-1, 3), [0, 0, 1]])
    top = len(V) - 1
    idx = lambda k, j: 1 + k * n + (j % n)  # noqa: E731
    j = np.arange(n)
    faces = [np.stack([np.zeros(n, int), idx(0, j + 1), idx(0, j)], 1)]
    for k in range(n - 2):
        faces.append(np.stack([idx(k, j), idx(k, j + 1), idx(k + 1, j + 1)], 1))
        faces.append(np.stack([idx(k, j), idx(k + 1, j + 1), idx(k + 1, j)], 1))
    faces.append(np.stack([np.full(n, top), idx(n - 2, j), idx(n - 2, j + 1)], 1))
    return V, np.vstack(faces)


def main() -> None:
    args = parse_small(__doc__, "small sizes (ctest)")
    n_tri = 2_000 if args.small else 100_000
    n_inertia = 10_000 if args.small else 1_000_000

    V, F = uv_sphere(n_tri)
    t_rd = best_time(lambda: rd.solid_mesh(V, F, density=1.0))
    body = rd.solid_mesh(V, F, density=1.0)
    print(f"solid_mesh ({len(F)} triangles): rigiddyn {t_rd * 1e3:.3f} ms")
    try:
        trimesh = importlib.import_module("trimesh")
        # a fresh Trimesh each time: trimesh caches mass properties on the object
        t_tm = best_time(lambda: trimesh.Trimesh(V, F, process=False).mass_properties)
        tm = trimesh.Trimesh(V, F, process=False)
        assert np.allclose(tm.moment_inertia, body.inertia_com, atol=1e-12)
        report_ratio("solid_mesh", len(F), t_rd, t_tm, "trimesh")
    except ImportError:
        print("trimesh not installed: skipped")
    ref = import_reference("inertia")  # optional, written elsewhere
    fn = getattr(ref, "solid_mesh", None) or getattr(ref, "mesh_inertia", None)
    if fn is None:
        print("rigiddyn_ref.inertia has no solid_mesh/mesh_inertia: skipped")
    else:
        t_ref = best_time(lambda: fn(V, F, density=1.0))
        report_ratio("solid_mesh", len(F), t_rd, t_ref, "numpy_ref")

    rng = np.random.default_rng(0)
    A = rng.normal(size=(n_inertia, 3, 3))
    I = A @ np.swapaxes(A, 1, 2)  # symmetric positive definite
    t_pa = best_time(lambda: rd.principal_axes(I))
    t_np = best_time(lambda: np.linalg.eigh(I))
    moments, _ = rd.principal_axes(I)
    assert np.allclose(moments, np.linalg.eigh(I)[0], atol=1e-10)
    print(f"principal_axes ({n_inertia} inertias): rigiddyn {t_pa * 1e3:.1f} ms, numpy.linalg.eigh {t_np * 1e3:.1f} ms")
    report_ratio("principal_axes", n_inertia, t_pa, t_np, "numpy_eigh")


if __name__ == "__main__":
    main()
