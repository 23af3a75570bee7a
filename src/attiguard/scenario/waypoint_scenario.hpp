#pragma once
/// @file waypoint_scenario.hpp
/// Scenario kind `waypoint`: waypoint tracking with one main thruster, reaction wheels and six
/// reaction-control thrusters (waypoint paper, Secs. III-VI). Keys: docs/scenario-format.md,
/// section "waypoint".

#include <string>
#include <vector>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/guidance/mission.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Everything a `waypoint` run needs, validated.
struct WaypointScenario {
  std::string name;
  lie::Mat3 J{lie::Mat3::Identity() * 20.0};  ///< [spacecraft] inertia [kg·m²]
  double max_wheel_torque{0.0};               ///< [spacecraft] per-axis limit; 0 = none [N·m]
  lie::Vec3 main_thrust_axis_b{lie::Vec3::UnitX()};  ///< [spacecraft] actual engine axis (unit)
  guidance::MissionParams mission;            ///< mass, thrusts, [guidance], [fine_position]
  control::QuaternionPidGains gains;          ///< [attitude_control]
  std::vector<lie::Vec3> waypoints_i;         ///< [[waypoints]] position [m]
  lie::Mat3 R0_ib{lie::Mat3::Identity()};     ///< [initial] attitude
  lie::Vec3 omega0_b{lie::Vec3::Zero()};      ///< [initial] omega_b [rad/s]
  lie::Vec3 p0_i{lie::Vec3::Zero()};          ///< [initial] position [m]
  lie::Vec3 v0_i{lie::Vec3::Zero()};          ///< [initial] velocity [m/s]
  double duration{0.0};                       ///< [simulation] duration (upper bound) [s]
  double control_period{0.1};                 ///< [simulation] control_period [s]
  double output_interval{1.0};                ///< [simulation] output_interval [s]
  integrate::IntegratorSettings integrator;   ///< [simulation] integrator keys
};

/// Parses and validates a `waypoint` document; rejects unknown keys, bad parameters and
/// waypoints that cannot be reached within the duration. Throws InputError.
[[nodiscard]] WaypointScenario parse_waypoint(const Document& doc);

/// A lower bound of the mission time: Σ over legs of the bang-bang time 2√(d/(T_max/m)).
[[nodiscard]] double minimum_mission_time(const WaypointScenario& sc) noexcept;

}  // namespace attiguard::scenario
