#pragma once
/// @file rigid_body_scenario.hpp
/// Scenario kind `rigid_body`: a rigid body (PET-ERG paper, eq. (1)) that is torque-free, under a
/// constant body torque, or under the PD law (3) of the PET-ERG paper towards a fixed reference.
/// Keys: docs/scenario-format.md, section "rigid_body".

#include <string>

#include "attiguard/integrate/integrator_settings.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

/// The torque applied to the body.
enum class TorqueLaw { free, constant_torque, pd };

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

/// Parses and validates a `rigid_body` document (kind already checked by the caller or here);
/// rejects unknown keys. Throws InputError.
[[nodiscard]] RigidBodyScenario parse_rigid_body(const Document& doc);

/// Parses the integrator keys of a `[simulation]` table (integrator, step, abs_tol, rel_tol,
/// max_step); shared by every scenario kind.
[[nodiscard]] integrate::IntegratorSettings parse_integrator_settings(const TableReader& simulation);

}  // namespace attiguard::scenario
