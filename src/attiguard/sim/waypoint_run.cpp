#include "attiguard/sim/waypoint_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "attiguard/integrate/integrator.hpp"
#include "attiguard/lie/quaternion.hpp"

namespace attiguard::sim {

namespace {

using dynamics::SpacecraftState;
using lie::Vec3;

bool command_finite(const guidance::MissionCommand& c) noexcept {
  return c.inputs.tau_b.allFinite() && std::isfinite(c.inputs.thrust) &&
         c.inputs.f_rct_b.allFinite() && c.q_id.allFinite() && c.omega_d_d.allFinite();
}

/// A result with one entry per waypoint, indexed, nothing flown yet.
WaypointSimResult waypoint_result_for(int n_wp) {
  WaypointSimResult res;
  res.waypoints.resize(static_cast<std::size_t>(n_wp));
  for (int k = 0; k < n_wp; ++k) {
    res.waypoints[static_cast<std::size_t>(k)].index = k;
  }
  return res;
}

/// The state (R_ib, ω_b, p_i, v_i) at t = 0 of the scenario.
SpacecraftState waypoint_initial_state(const WaypointScenario& sc) {
  SpacecraftState y;
  y.R[0] = sc.R0_ib;
  y.x.segment<3>(0) = sc.omega0_b;
  y.x.segment<3>(3) = sc.p0_i;
  y.x.segment<3>(6) = sc.v0_i;
  return y;
}

/// The control sample times after t = 0: every control period, the last one at the duration.
std::vector<double> waypoint_sample_times(const WaypointScenario& sc) {
  const double Ts = sc.control_period;
  const auto n_samples = static_cast<long>(std::ceil(sc.duration / Ts - 1e-9));
  std::vector<double> stops;
  stops.reserve(static_cast<std::size_t>(n_samples));
  for (long k = 1; k <= n_samples; ++k) {
    stops.push_back(std::min(static_cast<double>(k) * Ts, sc.duration));
  }
  return stops;
}

/// Accounts the command held over the last `dt` seconds to the waypoint it served (Δv of the
/// main engine and of the RCT).
void account_held_command(WaypointSimResult& res, const guidance::MissionCommand& cmd, double dt,
                          double mass) {
  if (dt > 0.0 && cmd.waypoint < static_cast<int>(res.waypoints.size())) {
    WaypointResult& w = res.waypoints[static_cast<std::size_t>(cmd.waypoint)];
    w.delta_v_main += cmd.inputs.thrust * dt / mass;
    w.delta_v_rct += cmd.rct.sum() * dt / mass;
  }
}

/// The guidance's inputs at a sample: the measured state and the time to the next sample.
guidance::MissionInputs waypoint_guidance_inputs(const SpacecraftState& s, double Ts) {
  guidance::MissionInputs in;
  in.R_ib = s.R[0];
  in.omega_b = dynamics::omega_b_of(s);
  in.p_i = dynamics::p_i_of(s);
  in.v_i = dynamics::v_i_of(s);
  in.dt = Ts;
  return in;
}

/// The leg of waypoint `wp_before` at a sample: its peak speed, and its arrival when the
/// command reports the accuracy met.
void record_leg_sample(WaypointSimResult& res, const WaypointScenario& sc, int wp_before, double t,
                       const guidance::MissionInputs& in, const guidance::MissionCommand& cmd) {
  if (wp_before >= static_cast<int>(res.waypoints.size())) return;
  WaypointResult& w = res.waypoints[static_cast<std::size_t>(wp_before)];
  w.peak_speed = std::max(w.peak_speed, in.v_i.norm());
  if (cmd.transition && cmd.reason == guidance::TransitionReason::accuracy_met) {
    w.reached = true;
    w.arrival_time = t;
    w.final_position_error = (sc.waypoints_i[static_cast<std::size_t>(wp_before)] - in.p_i).norm();
    w.final_speed = in.v_i.norm();
  }
}

/// Logs the command's mode transition, if any, and counts re-plans and overshoots.
void record_transition(WaypointSimResult& res, double t, int wp_before,
                       const guidance::MissionCommand& cmd) {
  if (!cmd.transition) return;
  res.transitions.push_back({t, wp_before, cmd.from, cmd.mode, cmd.reason});
  if (cmd.reason == guidance::TransitionReason::replan ||
      cmd.reason == guidance::TransitionReason::overshoot) {
    ++res.replans;
  }
}

/// The end of the run: the errors of the waypoints not reached, and the guidance's final state
/// with the distance and closing speed to its active waypoint.
void finish_waypoint_result(WaypointSimResult& res, const WaypointScenario& sc,
                            const guidance::WaypointSequencer& mission, const SpacecraftState& y) {
  for (WaypointResult& w : res.waypoints) {
    if (!w.reached) {
      w.final_position_error =
          (sc.waypoints_i[static_cast<std::size_t>(w.index)] - dynamics::p_i_of(y)).norm();
      w.final_speed = dynamics::v_i_of(y).norm();
    }
  }
  res.completed = mission.done();
  res.final_mode = mission.mode();
  res.final_waypoint = mission.waypoint();
  res.final_speed = dynamics::v_i_of(y).norm();
  if (res.final_waypoint < static_cast<int>(res.waypoints.size())) {
    const Vec3 e = sc.waypoints_i[static_cast<std::size_t>(res.final_waypoint)] - dynamics::p_i_of(y);
    res.final_distance = e.norm();
    res.final_closing_speed = guidance::closing_speed(e, dynamics::v_i_of(y));
  }
}

}  // namespace

WaypointSimResult simulate_waypoint(const WaypointScenario& sc,
                                    const SampleObserver& observer,
                                    const CommandFilter& filter) {
  const dynamics::SpacecraftPlant plant(sc.mission.mass, sc.J, sc.max_wheel_torque,
                                        sc.main_thrust_axis_b);
  guidance::WaypointSequencer mission(sc.mission, sc.gains, sc.waypoints_i);
  WaypointSimResult res = waypoint_result_for(static_cast<int>(sc.waypoints_i.size()));
  SpacecraftState y = waypoint_initial_state(sc);
  const std::vector<double> stops = waypoint_sample_times(sc);

  guidance::MissionCommand cmd;
  double t_prev = 0.0;
  auto sample = [&](double t, const SpacecraftState& s) {
    account_held_command(res, cmd, t - t_prev, sc.mission.mass);
    t_prev = t;
    const guidance::MissionInputs in = waypoint_guidance_inputs(s, sc.control_period);
    const int wp_before = mission.waypoint();
    cmd = mission.step(in);
    if (filter) {
      filter(t, s, cmd);
    }
    ++res.samples;
    res.finite = res.finite && command_finite(cmd) && s.all_finite();
    res.max_torque_norm = std::max(res.max_torque_norm, plant.applied_torque(cmd.inputs.tau_b).norm());
    record_leg_sample(res, sc, wp_before, t, in, cmd);
    record_transition(res, t, wp_before, cmd);
    if (observer) {
      observer(t, s, cmd);
    }
    res.total_time = t;
    return !mission.done();
  };

  const bool go_on = sample(0.0, y);
  auto field = [&](double, const SpacecraftState& s) { return plant.derivative(s, cmd.inputs); };
  auto on_stop = [&](double t, SpacecraftState& s) { return sample(t, s); };
  auto on_step = [](double, const SpacecraftState&) {};
  if (go_on && !stops.empty()) {
    const integrate::IntegrationStats stats = integrate::integrate(
        field, y, 0.0, std::span<const double>(stops), sc.integrator, on_stop, on_step);
    res.steps = stats.accepted_steps;
  }
  finish_waypoint_result(res, sc, mission, y);
  return res;
}

namespace {

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

}  // namespace

WaypointOutcome waypoint_outcome(const WaypointScenario& sc, const WaypointSimResult& res) {
  WaypointOutcome out;
  out.completed = res.completed && res.finite;
  if (out.completed) return out;
  const int n = static_cast<int>(sc.waypoints_i.size());
  const guidance::MissionParams& mp = sc.mission;
  std::string why;
  if (!res.finite) {
    why = "non-finite state or command";
  } else if (res.final_mode == guidance::Mode::fine && res.final_distance <= mp.replan_distance) {
    why = "fine control short of its accuracy (position_accuracy " + fixed(mp.position_accuracy, 3) +
          " m, speed_accuracy " + fixed(mp.speed_accuracy, 4) + " m/s)";
  } else if (res.final_closing_speed < 0.0 && res.final_speed > mp.speed_accuracy) {
    why = "moving away from the waypoint";
  } else {
    why = std::string("in mode ") + guidance::mode_name(res.final_mode);
  }
  if (res.replans > 0) why += " after " + std::to_string(res.replans) + " re-plan(s)";
  out.reason = "time out at " + fixed(res.total_time, 1) + " s (simulation.duration " +
               fixed(sc.duration, 1) + " s): " + why + "; waypoint " +
               std::to_string(res.final_waypoint + 1) + " of " + std::to_string(n) + " is " +
               fixed(res.final_distance, 3) + " m away, speed " + fixed(res.final_speed, 4) +
               " m/s (closing " + fixed(res.final_closing_speed, 4) + " m/s)";
  return out;
}

WaypointSimResult record_waypoint(const WaypointScenario& sc, io::RowSink& rows) {
  rows.begin({"t", "p_x", "p_y", "p_z", "v_x", "v_y", "v_z", "q_w", "q_x", "q_y", "q_z",
                     "omega_x", "omega_y", "omega_z", "tau_x", "tau_y", "tau_z", "thrust", "rct_1",
                     "rct_2", "rct_3", "rct_4", "rct_5", "rct_6", "mode", "waypoint"});
  const dynamics::SpacecraftPlant plant(sc.mission.mass, sc.J, sc.max_wheel_torque,
                                        sc.main_thrust_axis_b);
  const auto every = std::max(1L, std::lround(sc.output_interval / sc.control_period));
  long k = 0;
  std::array<double, 26> last_row{};
  bool last_written = false;
  auto observer = [&](double t, const dynamics::SpacecraftState& s,
                      const guidance::MissionCommand& c) {
    const lie::Quat& q = c.q_ib;  // continuous sign, as integrating (4)
    const Vec3 w = dynamics::omega_b_of(s);
    const Vec3 p = dynamics::p_i_of(s);
    const Vec3 v = dynamics::v_i_of(s);
    const Vec3 tau = plant.applied_torque(c.inputs.tau_b);
    last_row = {t,      p(0),     p(1),     p(2),     v(0),     v(1),     v(2),
                q(0),   q(1),     q(2),     q(3),     w(0),     w(1),     w(2),
                tau(0), tau(1),   tau(2),   c.inputs.thrust,    c.rct(0), c.rct(1),
                c.rct(2), c.rct(3), c.rct(4), c.rct(5), static_cast<double>(static_cast<int>(c.mode)),
                static_cast<double>(c.waypoint)};
    last_written = (k % every == 0) || c.transition;
    if (last_written) {
      rows.row(last_row);
    }
    ++k;
  };
  const WaypointSimResult res = simulate_waypoint(sc, observer);
  if (!last_written) {
    rows.row(last_row);
  }
  if (!res.finite) {
    rows.end();
    throw NumericalError("waypoint: non-finite state or command during the run");
  }
  return res;
}


namespace {

/// summary.json `waypoints[k]`: arrival (null when not reached), final error, speed and Δv.
nlohmann::json waypoint_entry(const WaypointResult& w) {
  nlohmann::json j;
  j["index"] = w.index;
  j["arrival_time"] = w.reached ? nlohmann::json(w.arrival_time) : nlohmann::json(nullptr);
  j["final_position_error"] = w.final_position_error;
  j["final_speed"] = w.final_speed;
  j["delta_v"] = w.delta_v();
  return j;
}

/// summary.json `legs[k]`: the leg to the waypoint at `p_i`, its peak speed and its Δv split.
nlohmann::json leg_entry(const WaypointResult& w, const lie::Vec3& p_i) {
  nlohmann::json l;
  l["index"] = w.index;
  l["position"] = {p_i(0), p_i(1), p_i(2)};
  l["reached"] = w.reached;
  l["peak_speed"] = w.peak_speed;
  l["delta_v_main"] = w.delta_v_main;
  l["delta_v_rct"] = w.delta_v_rct;
  l["ideal_delta_v"] = 2.0 * w.peak_speed;  // bang-coast-bang with the same peak speed
  return l;
}

/// summary.json `waypoints`, `legs` and the figures over all waypoints (total Δv; the largest
/// final error and speed, reached or not: an unreached waypoint is far).
void write_waypoint_entries(nlohmann::json& summary, const WaypointScenario& sc,
                            const WaypointSimResult& res) {
  nlohmann::json wps = nlohmann::json::array();
  nlohmann::json legs = nlohmann::json::array();
  double total_dv = 0.0;
  double max_error = 0.0;
  double max_speed = 0.0;
  for (const WaypointResult& w : res.waypoints) {
    max_error = std::max(max_error, w.final_position_error);
    max_speed = std::max(max_speed, w.final_speed);
    wps.push_back(waypoint_entry(w));
    legs.push_back(leg_entry(w, sc.waypoints_i[static_cast<std::size_t>(w.index)]));
    total_dv += w.delta_v();
  }
  summary["waypoints"] = wps;
  summary["legs"] = legs;
  summary["total_delta_v"] = total_dv;
  summary["max_final_position_error"] = max_error;  // campaign figures (docs/campaigns.md)
  summary["max_final_speed"] = max_speed;
}

/// summary.json `transitions`: time, waypoint, modes and reason of each logged transition.
nlohmann::json transitions_entry(const WaypointSimResult& res) {
  nlohmann::json tr = nlohmann::json::array();
  for (const TransitionRecord& r : res.transitions) {
    tr.push_back({{"t", r.t}, {"waypoint", r.waypoint}, {"from", guidance::mode_name(r.from)},
                  {"to", guidance::mode_name(r.to)}, {"reason", guidance::reason_name(r.reason)}});
  }
  return tr;
}

/// summary.json `mode_names`: the mode names in the order of the trajectory's `mode` column.
nlohmann::json mode_names_entry() {
  nlohmann::json modes = nlohmann::json::array();
  for (int m = 0; m < guidance::kModeCount; ++m) {
    modes.push_back(guidance::mode_name(static_cast<guidance::Mode>(m)));
  }
  return modes;
}

/// summary.json `parameters`: the craft, gains, guidance and simulation settings flown.
nlohmann::json waypoint_parameters_entry(const WaypointScenario& sc) {
  const guidance::MissionParams& mp = sc.mission;
  return {{"profile", std::string(kGuidanceProfileNames.name(sc.profile))},
          {"mass", mp.mass},
          {"main_thrust", mp.T_max},
          {"rct_thrust", mp.f_max},
          {"max_wheel_torque", sc.max_wheel_torque},
          {"kp", sc.gains.kp},
          {"ki", sc.gains.ki},
          {"kd", sc.gains.kd},
          {"integral_zone", sc.gains.integral_zone},
          {"kappa_p", mp.rct.kappa_p},
          {"kappa_d", mp.rct.kappa_d},
          {"rct_braking_acceleration", mp.rct.braking_acceleration},
          {"on_threshold", mp.rct_threshold},
          {"cruise_speed", mp.cruise_speed},
          {"acceleration_fraction", mp.acceleration_fraction},
          {"pointing_tolerance", mp.pointing_tolerance},
          {"pointing_error", std::string(kPointingErrorNames.name(mp.pointing_thrust_axis))},
          {"arrival_radius", mp.arrival_radius},
          {"position_accuracy", mp.position_accuracy},
          {"speed_accuracy", mp.speed_accuracy},
          {"braking_margin", mp.braking_margin},
          {"braking_distance", std::string(kBrakingDistanceNames.name(mp.brake_along_velocity))},
          {"main_cutoff_speed", mp.main_cutoff_speed},
          {"replan_distance", mp.replan_distance},
          {"brake_speed", mp.brake_speed},
          {"velocity_projection", mp.velocity_projection},
          {"lateral_rct", mp.lateral_rct},
          {"rct_transfer", mp.rct_transfer},
          {"projection_blend_speed", mp.projection.blend_speed},
          {"flip_timing", std::string(kFlipTimingNames.name(mp.flip_timing))},
          {"flip_lead_time", mp.flip_lead_time},
          {"control_period", sc.control_period},
          {"integrator", std::string(integrate::kMethodNames.name(sc.integrator.method))},
          {"step", sc.integrator.step},
          {"duration", sc.duration}};
}

/// summary.json `prediction`, `predicted_time`, `time_over_predicted` and each leg's
/// `predicted_time` and `time_over_predicted` (actual leg time over predicted; null when the
/// leg or the mission was not completed) (docs/waypoint.md, "Prediction").
void write_prediction_entries(nlohmann::json& summary, const guidance::MissionPrediction& pr,
                              const WaypointSimResult& res) {
  summary["prediction"] = prediction_entry(pr);
  summary["predicted_time"] = pr.time;
  summary["time_over_predicted"] =
      res.completed && pr.time > 0.0 ? nlohmann::json(res.total_time / pr.time) : nlohmann::json(nullptr);
  double previous_arrival = 0.0;
  nlohmann::json& legs = summary["legs"];
  for (std::size_t k = 0; k < legs.size() && k < pr.legs.size(); ++k) {
    const WaypointResult& w = res.waypoints[k];
    const double predicted = pr.legs[k].time;
    legs[k]["predicted_time"] = predicted;
    legs[k]["time_over_predicted"] = w.reached && predicted > 0.0
                                         ? nlohmann::json((w.arrival_time - previous_arrival) / predicted)
                                         : nlohmann::json(nullptr);
    if (w.reached) previous_arrival = w.arrival_time;
  }
}

}  // namespace

nlohmann::json waypoint_summary(const WaypointScenario& sc, const WaypointSimResult& res) {
  nlohmann::json summary;
  summary["kind"] = "waypoint";
  summary["name"] = sc.name;
  write_waypoint_entries(summary, sc, res);
  const WaypointOutcome outcome = waypoint_outcome(sc, res);
  summary["outcome"] = outcome.value();
  if (!outcome.completed) summary["outcome_reason"] = outcome.reason;
  summary["completed"] = res.completed;
  summary["total_time"] = res.total_time;
  summary["max_torque_norm"] = res.max_torque_norm;
  summary["steps"] = res.steps;
  summary["samples"] = res.samples;
  summary["transitions"] = transitions_entry(res);
  summary["mode_names"] = mode_names_entry();
  summary["parameters"] = waypoint_parameters_entry(sc);
  write_prediction_entries(summary, predict_waypoint_mission(sc), res);
  return summary;
}

}  // namespace attiguard::sim
