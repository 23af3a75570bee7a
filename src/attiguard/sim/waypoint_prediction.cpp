#include "attiguard/sim/waypoint_prediction.hpp"

#include <cstdio>

#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::sim {

guidance::MissionPrediction predict_waypoint_mission(const WaypointScenario& sc) {
  guidance::PredictionCraft craft;
  craft.J_max = lie::symmetric_eigenvalues(sc.J)(2);
  craft.max_wheel_torque = sc.max_wheel_torque;
  craft.control_period = sc.control_period;
  craft.gains = sc.gains;
  guidance::PredictionStart start;
  start.p_i = sc.p0_i;
  start.v_i = sc.v0_i;
  start.R_ib = sc.R0_ib;
  return guidance::predict_mission(sc.mission, craft, start, sc.waypoints_i);
}

nlohmann::json prediction_entry(const guidance::MissionPrediction& prediction) {
  nlohmann::json legs = nlohmann::json::array();
  for (const guidance::LegPrediction& l : prediction.legs) {
    legs.push_back({{"time", l.time},
                    {"delta_v", l.delta_v},
                    {"turn_time", l.turn_time},
                    {"fine_time", l.fine_time},
                    {"peak_speed", l.peak_speed},
                    {"rct_only", l.rct_only}});
  }
  return {{"time", prediction.time}, {"delta_v", prediction.delta_v}, {"legs", legs}};
}

std::string prediction_report(const WaypointScenario& sc) {
  const guidance::MissionPrediction pr = predict_waypoint_mission(sc);
  std::string out;
  char line[256];
  for (std::size_t k = 0; k < pr.legs.size(); ++k) {
    const guidance::LegPrediction& l = pr.legs[k];
    std::snprintf(line, sizeof line,
                  "predicted leg %zu: %.1f s, delta-v %.4g m/s (turns %.1f s, fine control %.1f s%s)\n", k,
                  l.time, l.delta_v, l.turn_time, l.fine_time, l.rct_only ? ", RCT only" : "");
    out += line;
  }
  std::snprintf(line, sizeof line, "predicted mission: %.1f s, delta-v %.4g m/s (simulation.duration %.1f s)\n",
                pr.time, pr.delta_v, sc.duration);
  out += line;
  if (sc.duration < pr.time) {
    std::snprintf(line, sizeof line,
                  "warning: simulation.duration %.1f s is shorter than the predicted mission time %.1f s: "
                  "the run is likely to end incomplete\n",
                  sc.duration, pr.time);
    out += line;
  }
  return out;
}

}  // namespace attiguard::sim
