#pragma once
/// @file mission_scenario.hpp
/// The validated configuration of a `mission` run: the waypoint guidance of the Waypoint paper
/// (Algorithm 1) whose desired attitude R_d(t) goes through the PET-ERG of the PET-ERG paper (PD
/// law [PET-ERG eq. (3)], reference update [PET-ERG eqs. (5)-(6)]) so that pointing cones [PET-ERG eq. (2b)] and the torque limit [PET-ERG eq. (2a)] hold
/// during the slews. Read by scenario::parse_mission (docs/mission.md,
/// docs/scenario-format.md); consumed by sim/mission_run.

#include <vector>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/sim/waypoint_scenario.hpp"

namespace attiguard::sim {

/// Everything a `mission` run needs, validated.
struct MissionScenario {
  WaypointScenario waypoint;                    ///< every key of a `waypoint` scenario
  governor::GovernorParams params;              ///< governor, [control], [erg]; J of [spacecraft]
  std::vector<governor::ConeConstraint> cones;  ///< [[cones]] (2b)
  double align_tolerance{1e-3};                 ///< [control] align_tolerance: thrust only when d(R_g, R_d) < this [rad]
};

}  // namespace attiguard::sim
