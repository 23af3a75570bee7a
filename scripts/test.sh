#!/usr/bin/env bash
# Installs the dependencies, builds attiguard and runs the whole test suite.
# Exits non-zero when any step or any test fails.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j2
