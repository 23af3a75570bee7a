#pragma once
/// @file read_mission.hpp
/// Scenario kind `mission` → sim::MissionScenario (sim/mission_scenario.hpp). Keys: a
/// `waypoint` scenario plus `governor`, [control], [erg] and [[cones]] of a `pet_erg` scenario
/// (docs/mission.md, docs/scenario-format.md).

#include "attiguard/scenario/document.hpp"
#include "attiguard/sim/mission_scenario.hpp"

namespace attiguard::scenario {

/// Parses and validates a `mission` document ([PET-ERG eqs. (2)-(6)] on the Waypoint paper's
/// Algorithm 1); rejects unknown keys. Throws InputError.
[[nodiscard]] sim::MissionScenario parse_mission(const Document& doc);

}  // namespace attiguard::scenario
