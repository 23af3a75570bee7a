/// @file mission_kind_prediction.cpp
/// The prediction of a `mission` scenario (docs/mission.md, "Prediction").

#include "attiguard/sim/mission_kind_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"
#include "attiguard/sim/mission_slews.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::sim {

namespace {

/// Samples per eigenaxis bang-bang time the prediction's loop needs at most (a finer flight loop
/// is coarsened to it, within a tenth of the damping time J_min/k_d).
constexpr double kSamplesPerBangBang = 500.0;

/// The attitude-only slew of the mission's loop in `mode` (mission_slew_scenario with the mode
/// and the pointing tolerance's convergence tolerance), flown by simulate_pet_erg over a horizon
/// that starts at 8 eigenaxis bang-bang times and doubles up to simulation.duration until the
/// slew has converged (a 500 Hz mission of 30000 s is not simulated whole for each turn).
PredictedTurn fly_turn(const MissionScenario& sc, governor::GovernorMode mode, const lie::Mat3& R_from_ib,
                       const lie::Mat3& R_to_ib) {
  PetErgScenario ps = mission_slew_scenario(sc, R_from_ib, lie::Vec3::Zero(), R_to_ib);
  ps.params.mode = mode;
  const double tol = sc.waypoint.mission.pointing_tolerance;
  ps.convergence_tolerance = 2.0 * tol * tol;  // φ = 1 − cos θ = 2 sin²(θ/2)
  const double clamp = sc.waypoint.max_wheel_torque;
  const double torque = clamp > 0.0 ? std::min(sc.params.tau_max, clamp) : sc.params.tau_max;
  const double t_bb = dynamics::eigenaxis_bang_bang_time(sc.params.J, R_from_ib, R_to_ib, torque);
  const double J_min = lie::symmetric_eigenvalues(sc.params.J)(0);
  const double damping = sc.params.gains.kd > 0.0 ? J_min / sc.params.gains.kd : HUGE_VAL;
  const double period = std::max(ps.control_period, std::min(t_bb / kSamplesPerBangBang, 0.1 * damping));
  if (period > ps.control_period) {
    ps.control_period = period;
    ps.integrator.step = std::max(ps.integrator.step, period);
  }
  const double limit = ps.duration;
  for (double horizon = std::max(8.0 * t_bb, 20.0 * period);; horizon *= 2.0) {
    ps.duration = std::min(horizon, limit);
    const PetErgResult r = simulate_pet_erg(ps);
    if (r.convergence_time >= 0.0) return {r.convergence_time, true};
    if (ps.duration >= limit) return {limit, false};
  }
}

}  // namespace

PredictedTurn predicted_governed_turn(const MissionScenario& sc, governor::GovernorMode mode,
                                      const lie::Mat3& R_from_ib, const lie::Mat3& R_to_ib) {
  const double tol = sc.waypoint.mission.pointing_tolerance;
  if (!(std::sin(0.5 * lie::distance(R_from_ib, R_to_ib)) >= tol)) return {0.0, true};
  if (mode == governor::GovernorMode::planned) {
    try {
      return fly_turn(sc, mode, R_from_ib, R_to_ib);
    } catch (const PlannedSetupRefusal&) {
      return fly_turn(sc, governor::GovernorMode::none, R_from_ib, R_to_ib);  // tracked, as in flight
    }
  }
  return fly_turn(sc, mode, R_from_ib, R_to_ib);
}

MissionKindPrediction predict_mission_kind(const MissionScenario& sc, governor::GovernorMode mode) {
  const WaypointScenario& w = sc.waypoint;
  MissionKindPrediction out;
  guidance::PredictionCraft craft;
  craft.J_max = lie::symmetric_eigenvalues(w.J)(2);
  craft.max_wheel_torque = w.max_wheel_torque;
  craft.control_period = w.control_period;
  craft.gains = w.gains;
  craft.turn_time = [&sc, mode, &out](const lie::Mat3& R_from_ib, const lie::Mat3& R_to_ib) {
    const PredictedTurn t = predicted_governed_turn(sc, mode, R_from_ib, R_to_ib);
    out.all_turns_converged = out.all_turns_converged && t.converged;
    return t.time;
  };
  guidance::PredictionStart start;
  start.p_i = w.p0_i;
  start.v_i = w.v0_i;
  start.R_ib = w.R0_ib;
  out.prediction = guidance::predict_mission(w.mission, craft, start, w.waypoints_i);
  return out;
}

std::string mission_prediction_report(const MissionScenario& sc) {
  const governor::GovernorMode mode = sc.params.mode;
  const MissionKindPrediction kp = predict_mission_kind(sc, mode);
  const guidance::MissionPrediction& pr = kp.prediction;
  std::string out;
  char line[320];
  for (std::size_t k = 0; k < pr.legs.size(); ++k) {
    const guidance::LegPrediction& l = pr.legs[k];
    std::snprintf(line, sizeof line,
                  "predicted leg %zu: %.1f s, delta-v %.4g m/s (turns %.1f s at the governor's pace, fine control "
                  "%.1f s%s)\n",
                  k, l.time, l.delta_v, l.turn_time, l.fine_time, l.rct_only ? ", RCT only" : "");
    out += line;
  }
  std::snprintf(line, sizeof line,
                "predicted mission (governor %s): %.1f s, delta-v %.4g m/s (simulation.duration %.1f s)\n",
                std::string(governor::kGovernorModeNames.name(mode)).c_str(), pr.time, pr.delta_v,
                sc.waypoint.duration);
  out += line;
  if (!kp.all_turns_converged) {
    std::snprintf(line, sizeof line,
                  "warning: a governed turn does not reach the pointing tolerance %.3g within simulation.duration "
                  "%.1f s: the mission is likely to stall in a turn\n",
                  sc.waypoint.mission.pointing_tolerance, sc.waypoint.duration);
    out += line;
  } else if (sc.waypoint.duration < pr.time) {
    std::snprintf(line, sizeof line,
                  "warning: simulation.duration %.1f s is shorter than the predicted mission time %.1f s: the run "
                  "is likely to end incomplete\n",
                  sc.waypoint.duration, pr.time);
    out += line;
  }
  return out;
}

}  // namespace attiguard::sim
