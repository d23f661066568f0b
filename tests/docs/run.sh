#!/usr/bin/env bash
# Builds the documentation site with the README's command (warnings as errors; every gallery example
# runs and asserts its result) and checks it: every page opens in headless chromium with its images
# loaded, the gallery pages have figures, and no internal link or anchor is broken. Run from anywhere:
#   bash tests/docs/run.sh
# Installs chromium and chromium-driver (Debian) when missing, and the package with its "docs" extra
# (tests/pip_install.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."

packages=(chromium chromium-driver)
bash tests/install_debian_packages.sh "${packages[@]}"

# (built as tests/run_all.sh built it just before: nothing is compiled again)
bash tests/pip_install.sh docs

# a fresh build: Sphinx reports the warnings of the pages it reads, and sphinx-gallery re-runs only the
# examples whose source changed, so output and generated sources of an earlier build would hide both
rm -rf docs/_build/html docs/api/generated docs/auto_examples docs/sg_execution_times.rst
python3 -m sphinx -W -b html docs docs/_build/html

# the checks (tests/docs is outside the default pytest run: pyproject.toml's testpaths)
RIGIDDYN_DOCS_HTML=docs/_build/html python3 -m pytest tests/docs -q
