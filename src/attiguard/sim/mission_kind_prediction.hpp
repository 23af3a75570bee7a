#pragma once
/// @file mission_kind_prediction.hpp
/// The mission-time and Δv prediction of a `mission` scenario (docs/mission.md, "Prediction";
/// issue 42): the legs as the waypoint kind predicts them (guidance::predict_mission,
/// docs/waypoint.md, "Prediction"), the attitude turns between the legs' steady attitudes
/// (guidance/leg_attitudes.hpp) flown at the pace of the mission's own attitude loop: each turn is
/// the attitude-only slew of kind `pet_erg` with the mission's J, PD law [PET-ERG eq. (3)],
/// τ_max, cones, [erg], control period and wheel clamp, in the mission's governor mode (pet,
/// continuous, none or planned), from rest to rest, until the pointing error is within the
/// guidance's pointing tolerance. Set-up code (check, summary.json): it allocates and simulates.

#include <string>

#include "attiguard/guidance/mission_prediction.hpp"
#include "attiguard/sim/mission_scenario.hpp"

namespace attiguard::sim {

/// One predicted turn: its time [s] and whether the governed slew converged within
/// simulation.duration (false: the time is the duration, a lower bound).
struct PredictedTurn {
  double time{0.0};
  bool converged{true};
};

/// The governed turn of the mission's attitude loop in `mode` from R_from_ib to R_to_ib at rest
/// (docs/mission.md, "Prediction"): sim::simulate_pet_erg of the slew's scenario with the
/// convergence tolerance φ = 2 tol² of the pointing tolerance tol (‖ε‖ = sin(θ/2) < tol). A
/// planned slew the planned mode refuses (too short to plan) is predicted as tracked (mode none).
[[nodiscard]] PredictedTurn predicted_governed_turn(const MissionScenario& sc, governor::GovernorMode mode,
                                                    const lie::Mat3& R_from_ib, const lie::Mat3& R_to_ib);

/// The mission's prediction (docs/mission.md, "Prediction"): guidance::predict_mission on the
/// scenario's craft, start and waypoints with the turns of predicted_governed_turn in `mode`.
/// `all_turns_converged` is false when some turn did not converge within simulation.duration.
struct MissionKindPrediction {
  guidance::MissionPrediction prediction;
  bool all_turns_converged{true};
};
[[nodiscard]] MissionKindPrediction predict_mission_kind(const MissionScenario& sc, governor::GovernorMode mode);

/// The lines `attiguard check` prints for a mission scenario (docs/mission.md, "Prediction"): one
/// per leg and the mission's in its governor mode, the duration beside it, and a warning when the
/// duration is shorter than the predicted time or a turn does not converge.
[[nodiscard]] std::string mission_prediction_report(const MissionScenario& sc);

}  // namespace attiguard::sim
