"""Welding and symmetry-plane benchmarks through the Python API (trimesh meshes; skipped without
trimesh): solid_mesh with the default weld vs weld_tolerance=0 on a shared 81920-face icosphere,
weld_vertices on STL-like copies (every face with its own vertices) of 15k to 1M vertices (the
growth shows O(n log n)) vs trimesh's merge on load, and mesh_symmetry_planes on trimesh
primitives. Prints best-of times. `--small` shrinks the sizes for ctest."""

from __future__ import annotations

import importlib
import warnings

import numpy as np

import rigiddyn as rd
from _bench_common import best_time, parse_small


def unshared(mesh) -> tuple[np.ndarray, np.ndarray]:
    vertices = np.asarray(mesh.vertices)[np.asarray(mesh.faces).ravel()]
    return vertices, np.arange(len(vertices)).reshape(-1, 3)


def main() -> None:
    small = parse_small(__doc__, "icospheres of <= 5120 faces, no cylinder(256)").small
    try:
        trimesh = importlib.import_module("trimesh")
    except ImportError:
        print("trimesh not installed: skipped")
        return
    top = 4 if small else 6
    mesh = trimesh.creation.icosphere(subdivisions=top)
    V, F = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    print(f"solid_mesh ({len(F)} faces, shared): weld default {best_time(lambda: rd.solid_mesh(V, F, density=1.0)) * 1e3:.1f} ms, "
          f"weld_tolerance=0 {best_time(lambda: rd.solid_mesh(V, F, density=1.0, weld_tolerance=0)) * 1e3:.1f} ms")
    for k in range(top - 2, top + 2):
        Vs, Fs = unshared(trimesh.creation.icosphere(subdivisions=k))
        print(f"weld_vertices ({len(Vs)} STL vertices): {best_time(lambda: rd.weld_vertices(Vs, Fs)) * 1e3:.1f} ms")
    Vs, Fs = unshared(mesh)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rd.MeshWeldWarning)
        t_rd = best_time(lambda: rd.solid_mesh(Vs, Fs, density=1.0))
    t_tm = best_time(lambda: trimesh.Trimesh(Vs, Fs, process=True))
    print(f"STL icosphere ({len(Vs)} vertices): rigiddyn.solid_mesh (weld + integrals) {t_rd * 1e3:.1f} ms, "
          f"trimesh.Trimesh(process=True) (merge only) {t_tm * 1e3:.1f} ms")
    for name, m in (("box", trimesh.creation.box(extents=[1, 2, 3])),
                    (f"icosphere({top - 1})", trimesh.creation.icosphere(subdivisions=top - 1)),
                    ("capsule", trimesh.creation.capsule(height=1.0, radius=0.3)),
                    (f"cylinder({64 if small else 256})", trimesh.creation.cylinder(radius=0.3, height=1.0, sections=64 if small else 256))):
        planes = rd.mesh_symmetry_planes(m.vertices, m.faces)
        t = best_time(lambda: rd.mesh_symmetry_planes(m.vertices, m.faces))
        print(f"mesh_symmetry_planes {name} ({len(m.faces)} faces): {len(planes)} planes, {t * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
