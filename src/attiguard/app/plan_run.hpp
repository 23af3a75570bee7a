#pragma once
/// @file plan_run.hpp
/// `attiguard plan`'s work (docs/slew-planner.md, "Outputs"): the slew of a pet_erg scenario
/// planned, DIR/plan.csv and DIR/plan.json written.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "attiguard/plan/slew_planner.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::app {

/// plan.json of a plan (docs/slew-planner.md, "Outputs"): the duration, the eigenaxis bang-bang
/// time at [control] tau_max and the ratio, the dense check, the solver's figures.
[[nodiscard]] nlohmann::json plan_summary(const sim::PetErgScenario& sc,
                                          const plan::SlewProblem& problem,
                                          const plan::PlannedSlew& planned);

/// Writes `plan` into `path` (plan.csv; docs/slew-planner.md, "Outputs"): t, q_w…q_z,
/// omega_x…, tau_x…, tau_norm and margin_i (a_cᵀ R a_b − cos θ_c of cone i, as trajectory.csv),
/// at `points_per_interval` points per interval.
void write_plan_csv(const std::filesystem::path& path, const governor::SlewPlan& plan,
                    const sim::PetErgScenario& sc, int points_per_interval = 10);

/// Plans the slew of `sc` and writes DIR/plan.csv and DIR/plan.json; returns plan.json's content.
/// When there is no admissible path (exit 4) it writes plan.json with outcome
/// "no_admissible_path" and the reason, then rethrows the VerificationFailure; a solver failure
/// (exit 3) writes nothing and rethrows.
nlohmann::json run_plan(const sim::PetErgScenario& sc, const std::filesystem::path& dir);

}  // namespace attiguard::app
