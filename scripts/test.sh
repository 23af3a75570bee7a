#!/usr/bin/env bash
# Installs the dependencies, builds attiguard and runs the whole test suite.
# Exits non-zero when any step or any test fails.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2

# The Python package's tests (python/tests), with Debian's interpreter; conftest.py puts
# build/python (the package attiguard with its extension and attiguard.plot) first on sys.path.
ATTIGUARD_BUILD_DIR="$(pwd)/build" /usr/bin/python3 -m pytest -q python/tests
