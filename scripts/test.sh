#!/usr/bin/env bash
# Installs the test tools as well (scripts/setup.sh test: GoogleTest, Google Benchmark, pytest,
# MPI, the sanitizer runtime, Chromium, node and the viewer's npm packages), builds attiguard with
# the test suite and the benchmarks, and runs the whole test suite.
# Exits non-zero when any step or any test fails.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh test
bash scripts/build.sh -DATTIGUARD_BUILD_TESTS=ON -DATTIGUARD_BUILD_BENCH=ON
ctest --test-dir build --output-on-failure -j2

# The Python package's tests (python/tests), with Debian's interpreter; conftest.py puts
# build/python (the package attiguard with its extension and attiguard.plot) first on sys.path.
# Two workers when pytest-xdist is installed (scripts/setup.sh test installs it): 99 s -> about 55 s.
pytest_workers=()
if /usr/bin/python3 -c "import xdist" >/dev/null 2>&1; then pytest_workers=(-n 2); fi
ATTIGUARD_BUILD_DIR="$(pwd)/build" /usr/bin/python3 -m pytest -q "${pytest_workers[@]}" python/tests
