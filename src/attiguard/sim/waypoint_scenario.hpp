#pragma once
/// @file waypoint_scenario.hpp
/// The validated configuration of a `waypoint` run: waypoint tracking with one main thruster,
/// reaction wheels and six reaction-control thrusters (Waypoint paper, Secs. III-VI). Read by
/// scenario::parse_waypoint (keys: docs/scenario-format.md, section "waypoint"); consumed by
/// sim/waypoint_run.

#include <string>
#include <vector>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/core/name_table.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/integrate/integrator_settings.hpp"

namespace attiguard::sim {

/// The names of the guidance's choices in scenario files ([guidance]) and summary.json
/// (`parameters`), docs/scenario-format.md, "waypoint": guidance::FlipTiming, and the two
/// switches of guidance::MissionParams (pointing_thrust_axis, brake_along_velocity).
inline constexpr NameTable<guidance::FlipTiming, 2> kFlipTimingNames{
    {{{guidance::FlipTiming::immediate, "immediate"},
      {guidance::FlipTiming::braking_point, "braking_point"}}}};
/// `pointing_error`: false = quaternion error ‖ε_{d,b}‖, true = thrust-axis error.
inline constexpr NameTable<bool, 2> kPointingErrorNames{{{{false, "quaternion"}, {true, "thrust_axis"}}}};
/// `braking_distance`: true = along the velocity (distance to closest approach), false = ‖e‖.
inline constexpr NameTable<bool, 2> kBrakingDistanceNames{
    {{{true, "along_velocity"}, {false, "norm"}}}};

/// `[guidance] profile`: where the defaults of the keys a file leaves out come from
/// (docs/waypoint.md, "Tuning").
enum class GuidanceProfile {
  craft,  ///< derived from the spacecraft (guidance/craft_defaults.hpp); the default
  paper,  ///< the Waypoint paper's settings (Algorithm 1 as printed, Tables I-II)
};
inline constexpr NameTable<GuidanceProfile, 2> kGuidanceProfileNames{
    {{{GuidanceProfile::craft, "craft"}, {GuidanceProfile::paper, "paper"}}}};

/// Everything a `waypoint` run needs, validated.
struct WaypointScenario {
  std::string name;
  GuidanceProfile profile{GuidanceProfile::craft};  ///< [guidance] profile
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

}  // namespace attiguard::sim
