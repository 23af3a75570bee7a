#!/usr/bin/env bash
# CTest Viewer.CommittedBundleIsTheBuildOfTheLockFile (docs/viewer.md, "The bundle"): rebuilds
# the viewer bundle from viewer/src with the esbuild and three.js of viewer/node_modules (`npm ci`
# of viewer/package-lock.json) and compares it byte for byte with the committed
# viewer/dist/attiguard_viewer.js that the attiguard program embeds.
# Usage: check_bundle.sh NODE SOURCE_DIR WORK_DIR
set -euo pipefail
node=$1 src=$2 work=$3

if [[ ! -f "$src/viewer/node_modules/esbuild/package.json" ||
      ! -f "$src/viewer/node_modules/three/package.json" ]]; then
  echo "viewer/node_modules is missing: run \`npm ci --prefix viewer\` (scripts/setup.sh test does)" >&2
  exit 1
fi
rm -rf "$work"
mkdir -p "$work"
"$node" "$src/viewer/build.mjs" "$work/attiguard_viewer.js"
if ! cmp "$work/attiguard_viewer.js" "$src/viewer/dist/attiguard_viewer.js"; then
  echo "FAIL: viewer/dist/attiguard_viewer.js is not the build of viewer/src: run" >&2
  echo "      \`npm run build --prefix viewer\` and commit viewer/dist/attiguard_viewer.js" >&2
  exit 1
fi
echo "viewer/dist/attiguard_viewer.js: $(stat -c %s "$work/attiguard_viewer.js") bytes, identical to the rebuild"
