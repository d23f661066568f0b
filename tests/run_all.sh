#!/usr/bin/env bash
# Installs everything rigiddyn's tests need, then runs every test: pytest (Python API against the
# numpy reference, SciPy and exact solutions), ctest (the C++ unit tests under AddressSanitizer +
# UndefinedBehaviorSanitizer; the bitwise golden states, the million-step runs, the allocation counts, the
# find_package packaging test and the benchmarks at a small size, optimised) and the documentation site (built with
# warnings as errors, its gallery run, then checked in headless chromium: tests/docs/run.sh). Run from
# the repository root:
#   bash tests/run_all.sh
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian packages for the C++ tests and benchmarks (installed only when missing). .ci/run checks
# that every system header the C++ build reads comes from one of these (or their dependencies).
packages=(cmake ninja-build g++ ccache libeigen3-dev libgtest-dev libbenchmark-dev libboost-dev)
if [ "${1:-}" = "--list-packages" ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi
bash tests/install_debian_packages.sh "${packages[@]}"

# the wall time at the end of each stage (CI's budget is 20 minutes on two cores)
stage_done() { echo "run_all.sh: $1 done at ${SECONDS} s"; }

# ccache: the library compiled once for the extension (pip) serves the C++ tests' build below, and a
# second run reuses every compilation. CCACHE_BASEDIR makes the paths relative, so the two build folders
# (build/<wheel tag>, build/test) share entries; both compile with g++ against Debian's Eigen
# (tests/pip_install.sh). CMake reads CMAKE_CXX_COMPILER_LAUNCHER and CXX.
export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="$PWD" CXX="${CXX:-g++}"

# the package with the test, docs and peers extras, once (tests/docs/run.sh below finds it installed; the peers:
# the Pinocchio cross-check of the kinematic trees and the benchmarks against MuJoCo and REBOUND)
bash tests/pip_install.sh test,docs,peers
# the wheel from the same build (nothing compiled again), repaired to a manylinux tag, installed and run in a fresh
# virtual environment without a compiler (README: "A wheel to install without a compiler")
bash tests/build_wheel.sh
stage_done "the package and its wheel"

# The C++ unit tests are compiled once, under the sanitizers (the sanitize preset: its library at -O1,
# see CMakeLists.txt). That build runs in the background at the lowest priority from here on: it takes
# only the CPU time the stages below leave idle (the benchmarks run one at a time, the documentation
# site mostly on one core), so their timings are not disturbed.
cmake --preset sanitize > /dev/null
# (its own session, so that it can be stopped as a group; a session is its own scheduling group where
# the kernel groups by session, so that group is given the lowest priority too)
setsid bash -c 'echo 19 > /proc/self/autogroup 2>/dev/null || true
                exec nice -n 19 cmake --build --preset sanitize -j 2' > build/sanitize-background.log 2>&1 &
sanitize_build=$!
# a failing stage stops the background build too (its own process group)
trap 'kill -- -"$sanitize_build" 2>/dev/null || true' EXIT

# (-p no:benchmark: pytest-benchmark, where a machine has it, warns under xdist, and warnings are errors;
# --dist loadgroup: the tests marked with one xdist_group share a worker, so a module's costly fixture runs once)
python3 -m pytest -n auto --dist loadgroup -p no:benchmark
stage_done pytest

# optimised: the golden states, the long runs, the allocation counts, the packaging test, then the benchmarks at
# a small size, one at a time (timings), and their rigiddyn/baseline ratios
cmake --preset test
cmake --build --preset test -j 2
ctest --preset test -j 2 --label-exclude bench
log=build/test/benchmarks.log
if ! ctest --preset test --label-regex bench --verbose > "$log" 2>&1; then
  cat "$log"
  exit 1
fi
grep -E ": ratio |Test +#" "$log" || true
stage_done "the optimised C++ tests and the benchmarks"

# the documentation site: the gallery's examples run and assert in the build; pages, images and links checked
bash tests/docs/run.sh
stage_done "the documentation site"

# the unit tests under the sanitizers (this foreground build finishes the background one and reports its errors)
wait "$sanitize_build" || true
cmake --build --preset sanitize -j 2
stage_done "the sanitizer build"
ctest --preset sanitize -j 2
stage_done "the sanitized C++ unit tests"
