#!/usr/bin/env bash
# Configures and builds attiguard (Release) into build/ at the repository root.
# Extra arguments are passed to the CMake configure step (e.g. -DATTIGUARD_BUILD_BENCH=OFF).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Debian's interpreter, never a pyenv shim: it is the one that sees python3-matplotlib/numpy
# (docs/conventions.md, "Python").
# ccache, when installed, also serves the wheel build of `pip install .` (setup.py).
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths below the repository become relative in ccache's keys: the wheel build in build-pip/
  # (setup.py sets the same base_dir) then reuses these objects.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(pwd)}"
fi
# Ninja when installed (scripts/setup.sh installs it), unless build/ was configured with
# another generator (a CMake cache keeps its generator).
generator=()
if command -v ninja >/dev/null 2>&1 && ! grep -qs '^CMAKE_GENERATOR:' build/CMakeCache.txt; then
  generator=(-G Ninja)
fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 "${launcher[@]}" "$@"
cmake --build build --parallel "$(nproc)"

# The Python package is built into build/python/attiguard: PYTHONPATH=build/python imports it
# (docs/python.md, "Installing"; `pip install .` installs it into a venv).
