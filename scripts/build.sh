#!/usr/bin/env bash
# Configures and builds attiguard (Release) into build/ at the repository root.
# Extra arguments are passed to the CMake configure step (e.g. -DATTIGUARD_BUILD_BENCH=OFF).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Debian's interpreter, never a pyenv shim: it is the one that sees python3-matplotlib/numpy
# (docs/conventions.md, "Python").
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 "$@"
cmake --build build --parallel "$(nproc)"

# `import attiguard` (docs/python.md): the package is built into build/python/attiguard; a .pth
# file in the user site-packages of Debian's /usr/bin/python3 puts build/python on its sys.path.
if [[ -f build/python/attiguard/__init__.py ]]; then
  user_site="$(/usr/bin/python3 -m site --user-site)"
  mkdir -p "$user_site"
  echo "$(pwd)/build/python" >"$user_site/attiguard-build.pth"
  echo "build.sh: /usr/bin/python3 imports attiguard from build/python ($user_site/attiguard-build.pth)"
fi
