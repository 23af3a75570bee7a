#pragma once
/// @file mission_scenario.hpp
/// Scenario kind `mission`: the waypoint guidance of the waypoint paper (Algorithm 1) whose
/// desired attitude R_d(t) goes through the PET-ERG of the PET-ERG paper (PD law (3), reference
/// update (5)-(6)) so that pointing cones (2b) and the torque limit (2a) hold during the slews.
/// Keys: a `waypoint` scenario plus `governor`, [control], [erg] and [[cones]] of a `pet_erg`
/// scenario (docs/mission.md, docs/scenario-format.md).

#include <vector>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/waypoint_scenario.hpp"

namespace attiguard::scenario {

/// Everything a `mission` run needs, validated.
struct MissionScenario {
  WaypointScenario waypoint;                    ///< every key of a `waypoint` scenario
  governor::GovernorParams params;              ///< governor, [control], [erg]; J of [spacecraft]
  std::vector<governor::ConeConstraint> cones;  ///< [[cones]] (2b)
  double align_tolerance{1e-3};                 ///< [control] align_tolerance: thrust only when d(R_g, R_d) < this [rad]
};

/// Parses and validates a `mission` document (PET-ERG paper (2)-(6) on the waypoint paper's
/// Algorithm 1); rejects unknown keys. Throws InputError.
[[nodiscard]] MissionScenario parse_mission(const Document& doc);

}  // namespace attiguard::scenario
