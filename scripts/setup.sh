#!/usr/bin/env bash
# Installs the system packages attiguard needs (Debian 12), non-interactively.
#   bash scripts/setup.sh        the main job (scripts/main.sh): compiler, CMake, the library's
#                                dependencies, Python with numpy and matplotlib
#   bash scripts/setup.sh test   also the test tools (scripts/test.sh): GoogleTest, Google
#                                Benchmark, pytest, mypy, MPI, clang and the sanitizer runtime,
#                                h5py, ccache, Chromium, node and the viewer's npm packages
# Idempotent: when all packages are already installed it installs nothing (no apt-get update).
# Prints what it installs and its download size. Runs apt-get directly as root, through sudo
# otherwise.
set -euo pipefail

mode=${1:-main}
if [[ "$mode" != main && "$mode" != test ]]; then
  echo "setup.sh: unknown mode '$mode' (expected nothing, 'main' or 'test')" >&2
  exit 2
fi

# What building the program and the Python module and running the main job need.
packages=(
  build-essential cmake g++ pkg-config ninja-build
  libeigen3-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  libsdp-dev liblapack-dev libblas-dev libssl-dev
  libhdf5-dev                # campaign retained time series (docs/campaigns.md)
  coinor-libipopt-dev        # the slew planner's NLP solver (docs/slew-planner.md)
  python3 python3-dev python3-numpy python3-matplotlib pybind11-dev
)
if [[ "$mode" == test ]]; then
  # ccache: scripts/build.sh and the wheel build of `pip install .` (setup.py) use it when
  # present, so the wheel reuses the objects of build/ (minutes saved on CI).
  packages+=(
    ccache
    libgtest-dev libbenchmark-dev
    python3-pytest python3-pytest-xdist python3-venv python3-setuptools python3-wheel python3-mypy
    openmpi-bin libopenmpi-dev clang libclang-rt-14-dev
    python3-h5py               # the tests read the retained HDF5 files
    python3-scipy              # python/tests/test_reach_truth.py (scripts/reach_truth.py)
    chromium                   # the browser test of the viewer (docs/viewer.md)
    universal-ctags            # function lengths (tests/architecture/check_function_length.py)
  )
  # node and npm rebuild the viewer bundle for its reproducibility test and drive Chromium
  # (docs/viewer.md): Debian's when the machine has no node.
  if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    packages+=(nodejs npm)
  fi
fi

# `npm ci` in viewer/: esbuild, three and puppeteer-core as pinned in viewer/package-lock.json
# (skipped when node_modules matches the lock file already).
install_viewer_packages() {
  local viewer
  viewer="$(cd "$(dirname "${BASH_SOURCE[0]}")/../viewer" && pwd)"
  if [[ -f "$viewer/node_modules/.package-lock.json" &&
        "$viewer/node_modules/.package-lock.json" -nt "$viewer/package-lock.json" ]]; then
    echo "setup.sh: viewer/node_modules is up to date."
    return
  fi
  echo "setup.sh: npm ci in viewer/"
  (cd "$viewer" && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund)
}

# True when the package is installed ("install ok installed").
is_installed() {
  [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "setup.sh: this script needs a Debian-based system (dpkg-query and apt-get not found)." >&2
  echo "setup.sh: install these packages by other means: ${packages[*]}" >&2
  exit 1
fi

missing=()
for pkg in "${packages[@]}"; do
  is_installed "$pkg" || missing+=("$pkg")
done

if ((${#missing[@]} == 0)); then
  echo "setup.sh ($mode): all ${#packages[@]} system packages are already installed."
  if [[ "$mode" == test ]]; then install_viewer_packages; fi
  exit 0
fi

if [[ "$(id -u)" -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo --)
else
  echo "setup.sh: these packages are missing: ${missing[*]}" >&2
  echo "setup.sh: installing them needs root, and sudo is not available." >&2
  echo "setup.sh: run this script as root, or install them with: apt-get install ${missing[*]}" >&2
  exit 1
fi

apt_get=("${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get -y -q
         -o DPkg::Lock::Timeout=600)
"${apt_get[@]}" update
echo "setup.sh ($mode): installing ${missing[*]}"
# What apt-get is about to download (packages and their dependencies not yet on the machine).
"${apt_get[@]}" install --no-install-recommends -s "${missing[@]}" | grep '^Inst ' | wc -l |
  xargs -I{} echo "setup.sh ($mode): {} Debian packages with their dependencies"
"${apt_get[@]}" install --no-install-recommends "${missing[@]}"

for pkg in "${missing[@]}"; do
  if ! is_installed "$pkg"; then
    echo "setup.sh: $pkg is still not installed after apt-get install" >&2
    exit 1
  fi
done
if [[ "$mode" == test ]]; then install_viewer_packages; fi
echo "setup.sh ($mode): done."
