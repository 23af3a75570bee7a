#pragma once
/// @file rigid_body_scenario.hpp
/// The validated configuration of a `rigid_body` run: a rigid body [PET-ERG eq. (1)] that
/// is torque-free, under a constant body torque, or under the PD law [PET-ERG eq. (3)]
/// towards a fixed reference. Read from a scenario file by scenario::parse_rigid_body (keys:
/// docs/scenario-format.md, section "rigid_body"); consumed by sim/rigid_body_run.

#include <string>

#include "attiguard/core/name_table.hpp"
#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::sim {

/// The torque applied to the body.
enum class TorqueLaw { free, constant_torque, pd };

/// Names of TorqueLaw in scenario files and summaries (docs/scenario-format.md, "rigid_body").
inline constexpr NameTable<TorqueLaw, 3> kTorqueLawNames{{{{TorqueLaw::free, "free"},
                                                           {TorqueLaw::constant_torque, "constant_torque"},
                                                           {TorqueLaw::pd, "pd"}}}};

/// Everything a `rigid_body` run needs, validated.
struct RigidBodyScenario {
  std::string name;
  lie::Mat3 J{lie::Mat3::Identity()};    ///< [body] inertia [kg·m²]
  lie::Mat3 R0_ib{lie::Mat3::Identity()};  ///< [initial] attitude
  lie::Vec3 omega0_b{lie::Vec3::Zero()};   ///< [initial] omega_b [rad/s]
  TorqueLaw law{TorqueLaw::free};          ///< [control] law
  lie::Vec3 torque_b{lie::Vec3::Zero()};   ///< [control] torque_b (constant_torque) [N·m]
  double kp{0.0};                          ///< [control] kp (pd) [N·m]
  double kd{0.0};                          ///< [control] kd (pd) [N·m·s]
  lie::Mat3 R_ref_ib{lie::Mat3::Identity()};  ///< [control] reference (pd)
  double duration{0.0};                    ///< [simulation] duration [s]
  double output_interval{0.0};             ///< [simulation] output_interval [s]
  integrate::IntegratorSettings integrator;  ///< [simulation] integrator, step, tolerances
};

}  // namespace attiguard::sim
