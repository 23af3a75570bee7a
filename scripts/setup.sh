#!/usr/bin/env bash
# Installs every system package attiguard needs (Debian 12), non-interactively.
# Idempotent: when all packages are already installed it does nothing (no apt-get update).
# Runs apt-get directly as root, through sudo otherwise.
set -euo pipefail

# ccache: scripts/build.sh and the wheel build of `pip install .` (setup.py) use it when present,
# so the wheel reuses the objects of build/ (minutes saved on a fresh machine's CI run).
packages=(
  build-essential cmake g++ pkg-config ccache
  libeigen3-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  libsdp-dev liblapack-dev libblas-dev libssl-dev
  libgtest-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-pytest pybind11-dev python3-dev
  python3-venv python3-setuptools python3-wheel python3-mypy
  openmpi-bin libopenmpi-dev clang libclang-rt-14-dev
  libhdf5-dev python3-h5py   # campaign retained time series (docs/campaigns.md)
  chromium                   # the browser test of the viewer (docs/viewer.md)
)
# node and npm bundle the viewer (docs/viewer.md): Debian's when the machine has no node.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
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
  echo "setup.sh: all ${#packages[@]} system packages are already installed."
  install_viewer_packages
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

echo "setup.sh: installing ${missing[*]}"
apt_get=("${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get -y -q
         -o DPkg::Lock::Timeout=600)
"${apt_get[@]}" update
"${apt_get[@]}" install --no-install-recommends "${missing[@]}"

for pkg in "${missing[@]}"; do
  if ! is_installed "$pkg"; then
    echo "setup.sh: $pkg is still not installed after apt-get install" >&2
    exit 1
  fi
done
install_viewer_packages
echo "setup.sh: done."
