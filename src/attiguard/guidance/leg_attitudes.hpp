#pragma once
/// @file leg_attitudes.hpp
/// The nominal desired attitudes of a waypoint mission, predicted before flying (docs/mission.md,
/// "Checks before flying"): per leg, the attitude that points x_b at the waypoint (the chart of
/// guidance::WaypointSequencer's leg start: the previous attitude turned by the shortest arc,
/// [Waypoint eqs. (6)-(12)] with ϑ = 0) and the reversed one of the braking phase (turned by π about its
/// z axis, Fig. 1(b)). The mission kind checks them against the pointing cones.

#include <span>
#include <vector>

#include "attiguard/lie/quaternion.hpp"

namespace attiguard::guidance {

/// One predicted steady desired attitude.
struct LegAttitude {
  int waypoint{0};      ///< index of the leg's waypoint
  bool braking{false};  ///< false: x_b towards the waypoint (accelerate); true: reversed (decelerate)
  lie::Mat3 R_id{lie::Mat3::Identity()};
};

/// The accelerate and decelerate attitudes of every leg longer than `skip_below` [m] (shorter
/// legs are flown by fine control with the attitude held), starting from R0_ib at p0_i, in
/// order. Not for the flight loop (allocates).
[[nodiscard]] std::vector<LegAttitude> nominal_leg_attitudes(const lie::Mat3& R0_ib, const lie::Vec3& p0_i,
                                                             std::span<const lie::Vec3> waypoints_i,
                                                             double skip_below);

}  // namespace attiguard::guidance
