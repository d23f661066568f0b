#!/usr/bin/env bash
# Installs the Debian packages named as arguments that are missing (apt-get, with sudo when not root);
# installs nothing when every one is there. Used by tests/run_all.sh and tests/docs/run.sh:
#   bash tests/install_debian_packages.sh cmake g++ ...
set -euo pipefail
missing=()
for p in "$@"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
