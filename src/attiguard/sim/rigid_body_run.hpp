#pragma once
/// @file rigid_body_run.hpp
/// Simulation of the `rigid_body` scenario kind: free body, constant torque, or the PD law [PET-ERG eq. (3)]
/// of the PET-ERG paper towards a fixed reference, on SO(3) × R³ with the RKMK integrators.

#include <nlohmann/json.hpp>

#include "attiguard/io/row_sink.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/rigid_body_scenario.hpp"

namespace attiguard::sim {

/// Figures of one rigid-body simulation (drifts are maxima over the accepted steps).
struct RigidBodyResult {
  lie::Mat3 R_end{lie::Mat3::Identity()};  ///< final attitude
  lie::Vec3 omega_end{lie::Vec3::Zero()};  ///< final ω_b
  lie::Mat3 R_target{lie::Mat3::Identity()};  ///< PD reference, or the initial attitude
  double E0{0.0};                          ///< initial kinetic energy
  double h0_norm{0.0};                     ///< ‖initial angular momentum‖
  double max_torque_norm{0.0};
  double max_energy_drift{0.0};            ///< max |E − E0|
  double max_momentum_drift{0.0};          ///< max ‖h_i − h_i(0)‖
  long steps{0};
  long rejected_steps{0};
  long evaluations{0};
  long output_rows{0};                     ///< rows emitted into the sink
};

/// Simulates the scenario ([PET-ERG eq. (1)] under the scenario's torque law) and emits one
/// row per output instant into `rows` (columns t, q_w..q_z, omega_x..z, tau_x..z,
/// attitude_error_rad, phi, energy, V, h_x..h_z). Throws NumericalError on divergence.
[[nodiscard]] RigidBodyResult simulate_rigid_body(const RigidBodyScenario& sc, io::RowSink& rows);

/// The summary.json object of a rigid-body run (keys: docs/scenario-format.md, section
/// "rigid_body", "Outputs"), without wall_time_s.
[[nodiscard]] nlohmann::json rigid_body_summary(const RigidBodyScenario& sc,
                                                const RigidBodyResult& result);

}  // namespace attiguard::sim
