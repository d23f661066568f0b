#!/usr/bin/env bash
# Installs rigiddyn from this tree with the extras named (comma-separated), built the same way every
# time so that installing again compiles only what changed; with --wheel DIR, builds its wheel into DIR
# instead, from the same build folder (nothing is compiled again after an install). Used by
# tests/run_all.sh, tests/docs/run.sh and tests/build_wheel.sh; run from anywhere:
#   bash tests/pip_install.sh test,docs
#   bash tests/pip_install.sh --wheel build/wheel
# - Without pip's build isolation (its build requirements, [build-system] requires of pyproject.toml,
#   installed into this Python first): an isolated build compiles against the pybind11 and Eigen
#   headers of a new temporary folder each time, so every command line changes and the persistent
#   build folder (build/<wheel tag>) is rebuilt from scratch.
# - Against Debian's Eigen where libeigen3-dev is installed (the C++ tests' build uses it), and with
#   g++ as the C++ tests' build has it: the library's objects compiled for the extension are then
#   ccache hits for the C++ tests' build (tests/run_all.sh sets the launcher and its base folder).
set -euo pipefail
cd "$(dirname "$0")/.."
usage="usage: bash tests/pip_install.sh EXTRA[,EXTRA...] | --wheel DIR"
wheel_dir=""
if [ "${1:-}" = "--wheel" ]; then
  wheel_dir="${2:?$usage}"
else
  extras="${1:?$usage}"
fi

requires=$(python3 - <<'EOF'
try:
    import tomllib
except ImportError:  # Python < 3.11: pip's own copy of the same parser
    from pip._vendor import tomli as tomllib
with open("pyproject.toml", "rb") as f:
    print("\n".join(tomllib.load(f)["build-system"]["requires"]))
EOF
)
mapfile -t requires <<< "$requires"
python3 -m pip install --quiet "${requires[@]}"

options=(--no-build-isolation)
if [ -f /usr/share/eigen3/cmake/Eigen3Config.cmake ]; then
  options+=(--config-settings=cmake.define.Eigen3_DIR=/usr/share/eigen3/cmake)
fi
if [ -n "$wheel_dir" ]; then
  CXX="${CXX:-g++}" python3 -m pip wheel --quiet --no-deps "${options[@]}" --wheel-dir "$wheel_dir" .
else
  CXX="${CXX:-g++}" python3 -m pip install --quiet "${options[@]}" ".[$extras]"
fi
