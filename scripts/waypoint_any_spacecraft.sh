#!/usr/bin/env bash
# The "any spacecraft" campaigns (docs/waypoint.md, "Tuning" and "Craft classes"): RUNS random
# crafts of today's generator (issue 13, default 10^4, seed 13; tests/guidance/any_spacecraft.hpp)
# and CLASS_RUNS crafts of each of the three classes of issue 25 (electric tugs, large chemical
# craft, cold-gas CubeSats, default 60, seed 25; tests/guidance/craft_classes.hpp), on THREADS
# threads. Prints the refusals by reason, the completion rates and the figures against the
# ideal, the prediction and the user's estimate, and per class the share of the mission time in
# mode fine and, separately, in mode rct_transfer (docs/waypoint.md, "The RCT-only legs").
# ATTIGUARD_RCT_TRANSFER=0 flies the RCT-only legs by fine control alone (the before of that
# section; the durations stay 1.5x the prediction with the transfer), and
# ATTIGUARD_CRAFT_CLASS_DUMP=FILE appends one line per craft to FILE to pair two runs. Exits
# non-zero if an accepted run of today's generator ends incomplete, if any run ends in NaN or divergence, or if a class completes less
# than 98 % of its accepted runs. Needs build/ (scripts/build.sh).
# Usage: scripts/waypoint_any_spacecraft.sh [RUNS] [THREADS] [CLASS_RUNS]
#   10^4 crafts over today's range and the three classes: scripts/waypoint_any_spacecraft.sh 2500 2 2500
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
ATTIGUARD_ANY_SPACECRAFT_RUNS="${1:-10000}" ATTIGUARD_ANY_SPACECRAFT_THREADS="${2:-2}" \
  ATTIGUARD_CRAFT_CLASS_RUNS="${3:-60}" \
  exec build/tests/attiguard_tests --gtest_filter='AnySpacecraft.*'
