#pragma once
/// @file outcome_line.hpp
/// The one line every command prints on stdout before the paths it wrote (docs/conventions.md,
/// "Outcome line"): `outcome: <word>` and the figures a user looks for first, read from the
/// result file the command has just written (summary.json, reach.json, campaign.json,
/// tune.json). Pure functions of that JSON, so that the line and the file never disagree.
/// A figure the file does not have (null, absent) is left out of the line, never invented.

#include <string>

#include <nlohmann/json.hpp>

namespace attiguard::app {

/// Kind pet_erg: outcome, the convergence time and its ratio to the eigenaxis bang-bang time,
/// the minimum pointing margin, max ‖τ‖/τ_max and whether every constraint held
/// (docs/pet-erg.md, "Outcomes").
[[nodiscard]] std::string pet_erg_outcome_line(const nlohmann::json& summary);

/// Kind rigid_body: the final attitude error and rate, the energy drift (docs/scenario-format.md).
[[nodiscard]] std::string rigid_body_outcome_line(const nlohmann::json& summary);

/// Kind waypoint: completed or not, the mission time, Δv and the worst arrival error
/// (docs/waypoint.md, "Outcome").
[[nodiscard]] std::string waypoint_outcome_line(const nlohmann::json& summary);

/// Kind mission: the waypoint figures of the run's own flight, its minimum pointing margin and
/// the time and Δv the constraints cost against the unconstrained twin (docs/mission.md).
[[nodiscard]] std::string mission_outcome_line(const nlohmann::json& summary);

/// `attiguard reach` (reach.json): the verdict, the first unproved interval if any, the final
/// radius and the tightness of the enclosure (docs/reach.md).
[[nodiscard]] std::string reach_outcome_line(const nlohmann::json& reach);

/// `attiguard campaign` (campaign.json): runs by status and by outcome, violations, and the
/// range of the kind's headline figure (docs/campaigns.md).
[[nodiscard]] std::string campaign_outcome_line(const nlohmann::json& campaign);

/// `attiguard tune` (tune.json): the points by status and outcome, those with a violation, and
/// the best admissible point (docs/pet-erg.md, "Tuning").
[[nodiscard]] std::string tune_outcome_line(const nlohmann::json& tune);

/// `attiguard plan` (plan.json): planned or no_admissible_path, the duration and its ratio to
/// the eigenaxis bang-bang time, the dense check's smallest cone margin and largest ‖τ‖/τ_max,
/// IPOPT's status and iterations, the planning time, the reason of a refusal
/// (docs/slew-planner.md, "Outputs").
[[nodiscard]] std::string plan_outcome_line(const nlohmann::json& plan);

}  // namespace attiguard::app
