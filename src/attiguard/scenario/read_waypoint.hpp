#pragma once
/// @file read_waypoint.hpp
/// Scenario kind `waypoint` → sim::WaypointScenario (sim/waypoint_scenario.hpp). Keys:
/// docs/scenario-format.md, section "waypoint".

#include <initializer_list>
#include <string_view>

#include "attiguard/scenario/document.hpp"
#include "attiguard/sim/waypoint_scenario.hpp"

namespace attiguard::scenario {

/// Parses and validates a `waypoint` document (Waypoint paper, Secs. III-VI); rejects unknown
/// keys, bad parameters and waypoints that cannot be reached within the duration (even
/// bang-bang at T_max/m). Throws InputError.
[[nodiscard]] sim::WaypointScenario parse_waypoint(const Document& doc);

/// parse_waypoint of the waypoint part of a document of kind `kind` whose caller reads the
/// top-level keys `other_keys` itself (kind mission: its governor blocks, docs/mission.md). Reads
/// the document in place, so its messages keep their FILE:LINE:COL (a copy of a Document loses
/// the source positions: toml++ copies no source regions).
[[nodiscard]] sim::WaypointScenario parse_waypoint_part(const Document& doc, std::string_view kind,
                                                        std::initializer_list<std::string_view> other_keys);

}  // namespace attiguard::scenario
