#!/usr/bin/env bash
# Re-captures the committed example figures (tests/data/example_figures/*.json) with the program
# built in build/ (scripts/example_figures.py explains what is captured and compared).
# Usage: scripts/capture_example_figures.sh [EXAMPLE ...]   (no argument: every example)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
args=()
for name in "$@"; do args+=(--example "$name"); done
exec /usr/bin/python3 scripts/example_figures.py capture --cli build/src/attiguard "${args[@]}"
