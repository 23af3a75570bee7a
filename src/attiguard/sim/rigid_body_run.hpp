#pragma once
/// @file rigid_body_run.hpp
/// Simulation of the `rigid_body` scenario kind: free body, constant torque, or the PD law (3)
/// of the PET-ERG paper towards a fixed reference, on SO(3) × R³ with the RKMK integrators.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "attiguard/scenario/rigid_body_scenario.hpp"

namespace attiguard::sim {

/// Runs the scenario, writes out_dir/trajectory.csv (one row per output instant, columns
/// t, q_w..q_z, omega_x..z, tau_x..z, attitude_error_rad, phi, energy, V, h_x..h_z) and
/// out_dir/summary.json, and returns the summary. Throws NumericalError on divergence.
nlohmann::json run_rigid_body(const scenario::RigidBodyScenario& sc,
                              const std::filesystem::path& out_dir);

}  // namespace attiguard::sim
