#!/usr/bin/env bash
# The "any spacecraft" campaign of issue 13 (docs/waypoint.md, "Tuning"): RUNS random crafts
# (default 10^4, seed 13; tests/guidance/any_spacecraft.hpp) through `check` and the waypoint
# guidance on THREADS threads; prints the rejections by reason, the completion rate among the
# accepted runs and the median delta-v / time over the ideal bang-coast-bang. Exits non-zero if
# any accepted run ends incomplete, in NaN or in divergence. Needs build/ (scripts/build.sh).
# Usage: scripts/waypoint_any_spacecraft.sh [RUNS] [THREADS]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
ATTIGUARD_ANY_SPACECRAFT_RUNS="${1:-10000}" ATTIGUARD_ANY_SPACECRAFT_THREADS="${2:-2}" \
  exec build/tests/attiguard_tests --gtest_filter='AnySpacecraft.*'
