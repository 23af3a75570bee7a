#pragma once
/// @file waypoint_prediction.hpp
/// The mission-time and Δv prediction of a waypoint scenario (docs/waypoint.md, "Prediction"):
/// guidance::predict_mission on the scenario's craft, start and waypoints, and its summary.json
/// and `check` forms.

#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/guidance/mission_prediction.hpp"
#include "attiguard/sim/waypoint_scenario.hpp"

namespace attiguard::sim {

/// guidance::predict_mission for the scenario (docs/waypoint.md, "Prediction").
[[nodiscard]] guidance::MissionPrediction predict_waypoint_mission(const WaypointScenario& sc);

/// summary.json `prediction` (docs/waypoint.md, "Prediction"): `time`, `delta_v` and `legs[k]`
/// (`time`, `delta_v`, `turn_time`, `fine_time`, `peak_speed`, `rct_only`).
[[nodiscard]] nlohmann::json prediction_entry(const guidance::MissionPrediction& prediction);

/// The lines `attiguard check` prints for a waypoint scenario (docs/waypoint.md, "Prediction"):
/// one per leg and the mission's, with simulation.duration beside it, and a warning when the
/// duration is shorter than the predicted mission time.
[[nodiscard]] std::string prediction_report(const WaypointScenario& sc);

}  // namespace attiguard::sim
