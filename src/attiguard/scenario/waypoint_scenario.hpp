#pragma once
/// @file waypoint_scenario.hpp
/// Scenario kind `waypoint` → sim::WaypointScenario (sim/waypoint_scenario.hpp). Keys:
/// docs/scenario-format.md, section "waypoint".

#include "attiguard/scenario/document.hpp"
#include "attiguard/sim/waypoint_scenario.hpp"

namespace attiguard::scenario {

/// Parses and validates a `waypoint` document (waypoint paper, Secs. III-VI); rejects unknown
/// keys, bad parameters and waypoints that cannot be reached within the duration (even
/// bang-bang at T_max/m). Throws InputError.
[[nodiscard]] sim::WaypointScenario parse_waypoint(const Document& doc);

}  // namespace attiguard::scenario
