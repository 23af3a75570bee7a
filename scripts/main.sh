#!/usr/bin/env bash
# Installs the dependencies, builds attiguard and runs the main example: a rigid body under the
# PD attitude law, with its trajectory, summary and plots written to out/rigid_body_pd/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/setup.sh
bash scripts/build.sh

out=out/rigid_body_pd
build/src/attiguard run examples/rigid_body_pd.toml --out "$out" --plot

echo
echo "Results are in $(pwd)/$out/ (trajectory.csv, summary.json and the *.png plots)."
