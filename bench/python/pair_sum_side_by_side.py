"""One N-body pair-sum kernel of two revisions side by side in one process (bench/pair_sum_side_by_side.cpp).

Compiles cpp/src/scene/elements/pair_forces.cpp of BASE (a git revision) and of HEAD (a revision, or the working tree
when omitted) with their own cpp/include, the namespace renamed (-Drigiddyn=rigiddyn_base, rigiddyn_head), with the
flags of the library's Release build (g++ -O3 -DNDEBUG, C++17, Debian's Eigen), links both into the driver, and runs
it: per n = 12 ... 1000 bodies, each version's best time per pair over alternated rounds, head/base, and how far their
results differ. Run it pinned to one core for steady figures:

    taskset -c 1 python3 bench/python/pair_sum_side_by_side.py BASE [HEAD] [--kernel NAME] [--rounds 25]

NAME: add_pair_forces_avx512 (default), add_pair_forces_avx2_fma_mixed, add_pair_forces_avx2_fma_division,
add_pair_forces_portable, pair_potential_avx512, pair_potential_avx2_fma, pair_potential_portable; both revisions
must have it. A kernel whose instructions the CPU lacks (AVX-512F, AVX2 with FMA) is refused. Needs git and g++;
tests/python/test_pair_sum_side_by_side.py runs it once, on the portable kernel.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KERNEL_SOURCE = "cpp/src/scene/elements/pair_forces.cpp"
DRIVER = ROOT / "bench" / "pair_sum_side_by_side.cpp"
KERNELS = ("add_pair_forces_avx512", "add_pair_forces_avx2_fma_mixed", "add_pair_forces_avx2_fma_division",
           "add_pair_forces_portable", "pair_potential_avx512", "pair_potential_avx2_fma", "pair_potential_portable")
FLAGS = ["-O3", "-DNDEBUG", "-std=c++17", "-I/usr/include/eigen3"]
# the kernels' dispatch (pair_forces.cpp) calls vector_instructions(), defined elsewhere in the library
STUB = ('#include "rigiddyn/vector_instructions.hpp"\n'
        "namespace rigiddyn { VectorInstructions vector_instructions() { return VectorInstructions::portable; } }\n")


def cpu_flags():
    """The CPU's feature flags (/proc/cpuinfo), empty where it cannot be read."""
    try:
        with open("/proc/cpuinfo") as f:
            return next((line.split(":", 1)[1].split() for line in f if line.startswith("flags")), [])
    except OSError:
        return []


def check_runs_here(kernel, flags=None):
    """Raises SystemExit where the CPU (its feature flags: this one's when None) lacks the kernel's instructions."""
    flags = cpu_flags() if flags is None else flags
    needs = ["avx512f"] if "avx512" in kernel else ["avx2", "fma"] if "avx2" in kernel else []
    missing = [f for f in needs if f not in flags]
    if missing:
        raise SystemExit(f"--kernel {kernel}: this CPU lacks {', '.join(missing)}")


def tree_of(revision, folder):
    """cpp/include and the kernel's source of `revision` under folder (None: the working tree's)."""
    folder.mkdir(parents=True)
    if revision is None:
        shutil.copytree(ROOT / "cpp" / "include", folder / "cpp" / "include")
        (folder / KERNEL_SOURCE).parent.mkdir(parents=True)
        shutil.copy(ROOT / KERNEL_SOURCE, folder / KERNEL_SOURCE)
        return folder
    archive = folder / "tree.tar"
    subprocess.run(["git", "-C", str(ROOT), "archive", "--format=tar", f"--output={archive}", revision,
                    "cpp/include", KERNEL_SOURCE], check=True)
    with tarfile.open(archive) as tar:
        tar.extractall(folder, filter="data")
    return folder


def compile_version(tree, namespace, folder):
    """The object files of the kernel's source and of the dispatch stub of `tree`, in `namespace`."""
    stub = folder / f"stub_{namespace}.cpp"
    stub.write_text(STUB)
    objects = []
    for source in (tree / KERNEL_SOURCE, stub):
        out = folder / f"{source.stem}_{namespace}.o"
        subprocess.run(["g++", *FLAGS, f"-I{tree / 'cpp' / 'include'}", f"-Drigiddyn={namespace}", "-c", str(source),
                        "-o", str(out)], check=True)
        objects.append(str(out))
    return objects


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", help="the revision to compare against (e.g. HEAD~1)")
    parser.add_argument("head", nargs="?", help="the revision compared (default: the working tree)")
    parser.add_argument("--kernel", default=KERNELS[0], choices=KERNELS)
    parser.add_argument("--rounds", type=int, default=25, help="alternated rounds per n (default 25)")
    args = parser.parse_args()
    if args.rounds < 1:
        parser.error(f"--rounds: expected an integer >= 1, got {args.rounds}")
    check_runs_here(args.kernel)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        objects = []
        for namespace, revision in (("rigiddyn_base", args.base), ("rigiddyn_head", args.head)):
            objects += compile_version(tree_of(revision, folder / namespace), namespace, folder)
        driver = folder / "driver"
        defines = [f"-DRIGIDDYN_SIDE_KERNEL={args.kernel}", f'-DRIGIDDYN_SIDE_KERNEL_NAME="{args.kernel}"']
        if args.kernel.startswith("pair_potential"):
            defines.append("-DRIGIDDYN_SIDE_POTENTIAL")
        subprocess.run(["g++", *FLAGS, *defines, str(DRIVER), *objects, "-o", str(driver)], check=True)
        print(f"base {args.base}, head {args.head or 'the working tree'}")
        sys.stdout.flush()
        subprocess.run([str(driver), str(args.rounds)], check=True, env=dict(os.environ))


if __name__ == "__main__":
    main()
