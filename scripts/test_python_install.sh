#!/usr/bin/env bash
# CI check of the Python package as a user installs it (docs/python.md, "Installing"):
# `pip install --no-build-isolation .` into a fresh `--system-site-packages` venv in a temporary
# directory (offline: --no-index, Debian's setuptools, wheel and numpy), then, from that
# directory (where the source tree is not importable), prints attiguard.__version__ and runs the
# Python tests (python/tests) against the installed package, but for the sweep of hostile
# arguments (test_hostile_arguments_raise: 45 s of the 95; the same extension, built from the same
# sources, meets it in scripts/test.sh). Exits non-zero on any failure.
#
# The wheel build configures CMake afresh in build-pip/ (tests and benchmarks off) and compiles
# the library and the extension module; with ccache installed, a repeated run recompiles from
# the cache. Assumes the system packages are installed (scripts/setup.sh).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
python=/usr/bin/python3  # Debian's interpreter (docs/conventions.md, "Python")

work="$(mktemp -d "${TMPDIR:-/tmp}/attiguard-pip.XXXXXX")"
trap 'rm -rf "$work"' EXIT
start=$SECONDS

"$python" -m venv --system-site-packages "$work/venv"
rm -rf "$repo/build-pip"
"$work/venv/bin/pip" install --no-build-isolation --no-index --progress-bar off "$repo"
echo "test_python_install.sh: pip install took $((SECONDS - start)) s"

cd "$work"
"$work/venv/bin/python" -c "import attiguard; print(attiguard.__version__)"
ATTIGUARD_TEST_INSTALLED=1 ATTIGUARD_BUILD_DIR="$repo/build" \
  "$work/venv/bin/python" -m pytest -q -p no:cacheprovider -k "not test_hostile_arguments_raise" \
  "$repo/python/tests"
echo "test_python_install.sh: OK in $((SECONDS - start)) s"
