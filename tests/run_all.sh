#!/usr/bin/env bash
# Installs everything rigiddyn's tests need, then runs every test: pytest (Python API against the
# numpy reference, SciPy and exact solutions), ctest (C++ unit tests, the find_package packaging
# test, and the benchmarks at a small size) and the documentation site (built with warnings as
# errors, its gallery run, then checked in headless chromium: tests/docs/run.sh). Run from the
# repository root:
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

# ccache: the library compiled once for the extension (pip) serves the C++ tests' build below, and a
# second run reuses every compilation. CCACHE_BASEDIR makes the paths relative, so the two build folders
# (build/<wheel tag>, build/test) share entries; both compile with g++ against Debian's Eigen
# (tests/pip_install.sh). CMake reads CMAKE_CXX_COMPILER_LAUNCHER and CXX.
export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR="$PWD" CXX="${CXX:-g++}"

# the package with the test and docs extras, once (tests/docs/run.sh below finds it installed)
bash tests/pip_install.sh test,docs
# (-p no:benchmark: pytest-benchmark, where a machine has it, warns under xdist, and warnings are errors;
# --dist loadgroup: the tests marked with one xdist_group share a worker, so a module's costly fixture runs once)
python3 -m pytest -n auto --dist loadgroup -p no:benchmark

cmake --preset test
cmake --build --preset test -j 2
ctest --preset test -j 2 --label-exclude bench
# benchmarks at a small size, one at a time (timings), then their rigiddyn/baseline ratios
log=build/test/benchmarks.log
if ! ctest --preset test --label-regex bench --verbose > "$log" 2>&1; then
  cat "$log"
  exit 1
fi
grep -E ": ratio |Test +#" "$log" || true

# the documentation site: the gallery's examples run and assert in the build; pages, images and links checked
bash tests/docs/run.sh
