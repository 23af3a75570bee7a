#!/usr/bin/env bash
# CTest Viewer.BrowserOpensTheViewOfEveryKind (docs/viewer.md): runs the pet_erg, waypoint,
# mission, reach and campaign examples, the plan of pet_erg_slew170 and its planned flight
# (pet_erg_slew170_planned) with --view (or `attiguard view`), then opens each
# view.html in headless Chromium (view_test.mjs). Skipped (exit 77) only when /usr/bin/chromium
# is absent; CI installs it (scripts/setup.sh).
# Usage: run_view_test.sh CLI NODE SOURCE_DIR WORK_DIR
set -euo pipefail
cli=$1 node=$2 src=$3 work=$4

if [[ ! -x /usr/bin/chromium ]]; then
  echo "SKIPPED: /usr/bin/chromium is not installed (apt-get install chromium, scripts/setup.sh);"
  echo "SKIPPED: the browser test of view.html needs it and runs in CI."
  exit 77
fi
if [[ ! -d "$src/viewer/node_modules/puppeteer-core" ]]; then
  echo "viewer/node_modules is missing: run \`npm ci\` in viewer/ (scripts/setup.sh does)" >&2
  exit 1
fi

rm -rf "$work"
mkdir -p "$work"
cd "$src"
"$cli" run examples/pet_erg_paper.toml --out "$work/pet_erg_paper" --view
"$cli" run examples/pet_erg_slew170_planned.toml --out "$work/pet_erg_slew170_planned" --view >/dev/null
"$cli" run examples/waypoint_paper.toml --out "$work/waypoint_paper" --view
"$cli" run examples/mission_sun_constrained.toml --out "$work/mission_sun_constrained" --view
"$cli" run examples/rigid_body_pd.toml --out "$work/rigid_body_pd" --view
"$cli" reach examples/conreach_paper.toml --out "$work/conreach_paper" --view
"$cli" plan examples/pet_erg_slew170.toml --out "$work/pet_erg_slew170_plan" --view >/dev/null
"$cli" campaign examples/pet_erg_campaign_retained.toml --runs 40 --seed 1 --out "$work/pet_erg_campaign" >/dev/null
"$cli" campaign examples/pet_erg_campaign_retained.toml --seed 1 --out "$work/pet_erg_campaign" --replay 5 --view >/dev/null
"$cli" view "$work/pet_erg_campaign"

size=$(stat -c %s "$work/pet_erg_paper/view.html")
echo "pet_erg_paper/view.html: $size bytes (limit 5000000)"
if ((size >= 5000000)); then
  echo "FAIL: view.html of the PET-ERG paper scenario is not under 5 MB" >&2
  exit 1
fi

"$node" "$src/tests/viewer/view_test.mjs" "$src/viewer" "$work/screenshots" \
  "$work/pet_erg_paper" "$work/waypoint_paper" "$work/mission_sun_constrained" \
  "$work/conreach_paper" "$work/pet_erg_campaign" "$work/pet_erg_campaign/run_5" "$work/rigid_body_pd" \
  "$work/pet_erg_slew170_plan" "$work/pet_erg_slew170_planned"
