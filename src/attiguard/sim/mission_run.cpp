/// @file mission_run.cpp
/// The `mission` kind: waypoint guidance through the PET-ERG (docs/mission.md).

#include "attiguard/sim/mission_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/cone_json.hpp"
#include "attiguard/sim/mission_kind_prediction.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

namespace attiguard::sim {

double MissionResult::delta_v() const noexcept {
  double dv = 0.0;
  for (const WaypointResult& w : flight.waypoints) dv += w.delta_v();
  return dv;
}

namespace {

/// The attitude loop of one flight: the governor's output for a sample (its torque replaces the
/// guidance's, its R_g gates the thrust).
using AttitudeLoop = std::function<const governor::GovernorOutput&(
    double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& cmd)>;

/// Flies the mission with `loop` as the attitude command filter and folds every sample into
/// the constraint figures (docs/mission.md, "How it works").
MissionResult fly_mission(const MissionScenario& sc, const AttitudeLoop& loop,
                          const MissionObserver& observer, const std::atomic<bool>* stop) {
  const dynamics::SpacecraftPlant plant(sc.waypoint.mission.mass, sc.waypoint.J,
                                        sc.waypoint.max_wheel_torque, sc.waypoint.main_thrust_axis_b);
  MissionResult res;
  res.min_pointing_margin = std::numeric_limits<double>::infinity();
  const governor::GovernorOutput* last = nullptr;
  auto filter = [&](double t, const dynamics::SpacecraftState& y, guidance::MissionCommand& cmd) {
    if (stop != nullptr && stop->load(std::memory_order_relaxed)) {
      throw io::Interrupted("interrupted: the mission flight was stopped at t = " + std::to_string(t) + " s");
    }
    const governor::GovernorOutput& out = loop(t, y, cmd);
    last = &out;
    cmd.inputs.tau_b = out.tau_b;  // PD law [Waypoint eq. (3)] towards the governed R_g
    if (cmd.inputs.thrust > 0.0 &&
        lie::distance(out.R_g, lie::quat_to_rotation(cmd.q_id)) > sc.align_tolerance) {
      cmd.inputs.thrust = 0.0;  // fire only when the governed attitude is aligned
      ++res.thrust_gated;
    }
    const double margin = out.min_margin();
    res.min_pointing_margin = std::min(res.min_pointing_margin, margin);
    if (margin < 0.0 && res.first_pointing_violation_time < 0.0) {
      res.first_pointing_violation_time = t;
    }
    const double tau = plant.applied_torque(out.tau_b).norm();
    res.max_torque_norm = std::max(res.max_torque_norm, tau);
    if (tau > sc.params.tau_max * (1.0 + 1e-9)) ++res.torque_violations;
  };
  auto seen = [&](double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& cmd) {
    if (observer && last != nullptr) observer(t, y, cmd, *last);
  };
  try {
    res.flight = simulate_waypoint(sc.waypoint, seen, filter);
  } catch (const io::Interrupted&) {
    throw;  // a stop is not the flight's numerical failure: the run ends here
  } catch (const NumericalError& e) {
    res.flight.finite = false;
    res.failure = e.what();
  }
  if (res.failure.empty() && !res.flight.finite) {
    res.failure = "non-finite state or command during the flight";
  }
  return res;
}

}  // namespace

MissionResult simulate_planned_mission(const MissionScenario& sc, const PlannedMissionObserver& observer,
                                       const std::atomic<bool>* stop) {
  MissionSlews slews(sc);
  const AttitudeLoop loop = [&](double t, const dynamics::SpacecraftState& y,
                                const guidance::MissionCommand& cmd) -> const governor::GovernorOutput& {
    return slews.step(t, y, cmd);
  };
  const MissionObserver seen =
      observer ? MissionObserver([&](double t, const dynamics::SpacecraftState& y,
                                     const guidance::MissionCommand& cmd, const governor::GovernorOutput& g) {
                   observer(t, y, cmd, g, slews.state());
                 })
               : MissionObserver{};
  MissionResult res = fly_mission(sc, loop, seen, stop);
  res.slews = std::move(slews).finish(res.flight.total_time);
  return res;
}

MissionResult simulate_mission(const MissionScenario& sc, governor::GovernorMode mode,
                               const MissionObserver& observer, const std::atomic<bool>* stop) {
  if (mode == governor::GovernorMode::planned) {
    return simulate_planned_mission(
        sc,
        observer ? PlannedMissionObserver([&](double t, const dynamics::SpacecraftState& y,
                                              const guidance::MissionCommand& cmd,
                                              const governor::GovernorOutput& g,
                                              const MissionSlewState&) { observer(t, y, cmd, g); })
                 : PlannedMissionObserver{},
        stop);
  }
  governor::GovernorParams params = sc.params;
  params.mode = mode;
  governor::AttitudeGovernor gov(params, sc.cones);
  gov.reset(0.0, sc.waypoint.R0_ib);  // R_g(0) = R(0) [PET-ERG Sec. IV-A]
  const AttitudeLoop loop = [&](double t, const dynamics::SpacecraftState& y,
                                const guidance::MissionCommand& cmd) -> const governor::GovernorOutput& {
    return gov.step(t, y.R[0], dynamics::omega_b_of(y), lie::quat_to_rotation(cmd.q_id));
  };
  return fly_mission(sc, loop, observer, stop);
}

WaypointOutcome mission_outcome(const MissionScenario& sc, const MissionResult& r) {
  WaypointOutcome out;
  if (!r.failure.empty()) {
    out.reason = "numerical failure: " + r.failure;
    return out;
  }
  out = waypoint_outcome(sc.waypoint, r.flight);
  if (!out.completed && r.thrust_gated > 0) {
    out.reason = "stalled by the constraints: the governor withheld the thrust in " +
                 std::to_string(r.thrust_gated) + " of " + std::to_string(r.flight.samples) +
                 " samples (R_g not within align_tolerance of R_d); " + out.reason;
  }
  return out;
}

namespace {

/// summary.json `slews` of a planned flight (docs/mission.md, "Planned slews"): each slew's
/// start, target angle, whether it was planned, and the planned mode's figures
/// (planned_figures_json: the plan's duration and bang-bang ratio, convergence over the plan).
nlohmann::json slews_json(const std::vector<MissionSlew>& slews) {
  nlohmann::json a = nlohmann::json::array();
  for (const MissionSlew& s : slews) {
    nlohmann::json j = s.planned ? planned_figures_json(s.figures, s.convergence_time) : nlohmann::json::object();
    j["index"] = s.index;
    j["start_time"] = s.start_time;
    j["end_time"] = s.end_time;
    j["waypoint"] = s.waypoint;
    j["mode"] = guidance::mode_name(s.mode);
    j["angle_deg"] = s.angle * 180.0 / std::numbers::pi;
    j["planned"] = s.planned;
    if (!s.planned) j["not_planned_reason"] = s.not_planned_reason;
    j["convergence_time"] = s.convergence_time >= 0.0 ? nlohmann::json(s.convergence_time) : nlohmann::json(nullptr);
    a.push_back(std::move(j));
  }
  return a;
}

nlohmann::json flight_json(const MissionScenario& sc, governor::GovernorMode mode,
                           const MissionResult& r) {
  nlohmann::json j;
  j["governor"] = std::string(governor::kGovernorModeNames.name(mode));
  const WaypointOutcome outcome = mission_outcome(sc, r);
  j["outcome"] = outcome.value();
  if (!outcome.completed) j["outcome_reason"] = outcome.reason;
  j["completed"] = outcome.completed;
  j["waypoints_reached"] =
      std::count_if(r.flight.waypoints.begin(), r.flight.waypoints.end(),
                    [](const WaypointResult& w) { return w.reached; });
  j["total_time"] = r.flight.total_time;
  j["total_delta_v"] = r.delta_v();
  j["min_pointing_margin"] = std::isfinite(r.min_pointing_margin) ? nlohmann::json(r.min_pointing_margin)
                                                                   : nlohmann::json(nullptr);
  j["first_pointing_violation_time"] = r.first_pointing_violation_time;
  j["max_torque_norm"] = r.max_torque_norm;
  j["torque_violations"] = r.torque_violations;
  j["thrust_gated_samples"] = r.thrust_gated;
  j["pointing_constraints_satisfied"] = r.first_pointing_violation_time < 0.0;
  j["torque_limit_satisfied"] = r.torque_violations == 0;
  j["constraints_satisfied"] = r.first_pointing_violation_time < 0.0 && r.torque_violations == 0;
  if (mode == governor::GovernorMode::planned) j["slews"] = slews_json(r.slews);
  return j;
}

}  // namespace

namespace {

/// The columns of a mission's trajectory.csv (docs/mission.md, "Outputs"); `planned` adds the
/// slew being flown and its clock (docs/mission.md, "Planned slews").
std::vector<std::string> mission_columns(bool planned) {
  std::vector<std::string> c{"t", "p_x", "p_y", "p_z", "v_x", "v_y", "v_z", "q_w", "q_x", "q_y", "q_z",
                             "omega_x", "omega_y", "omega_z", "tau_x", "tau_y", "tau_z", "tau_norm",
                             "thrust", "mode", "waypoint", "qg_w", "qg_x", "qg_y", "qg_z", "qd_w", "qd_x",
                             "qd_y", "qd_z", "trigger", "min_margin"};
  if (planned) c.insert(c.end(), {"slew", "s", "s_dot"});
  return c;
}

/// One row of trajectory.csv: the 31 columns of every mission, then the planned ones of `slew`.
void mission_row(io::RowSink& rows, double t, const dynamics::SpacecraftState& y,
                 const guidance::MissionCommand& c, const governor::GovernorOutput& g,
                 const MissionSlewState* slew) {
  const lie::Vec3 p = dynamics::p_i_of(y), v = dynamics::v_i_of(y), w = dynamics::omega_b_of(y);
  const lie::Quat& q = c.q_ib;
  const lie::Quat qg = lie::rotation_to_quat(g.R_g);
  const lie::Quat& qd = c.q_id;
  const std::array<double, 34> row{t, p(0), p(1), p(2), v(0), v(1), v(2), q(0), q(1), q(2), q(3),
                                   w(0), w(1), w(2), g.tau_b(0), g.tau_b(1), g.tau_b(2),
                                   g.tau_b.norm(), c.inputs.thrust,
                                   static_cast<double>(static_cast<int>(c.mode)),
                                   static_cast<double>(c.waypoint), qg(0), qg(1), qg(2), qg(3),
                                   qd(0), qd(1), qd(2), qd(3), g.trigger ? 1.0 : 0.0,
                                   g.cone_count > 0 ? g.min_margin() : 0.0,
                                   slew != nullptr ? static_cast<double>(slew->slew) : 0.0,
                                   slew != nullptr ? slew->sigma : 0.0,
                                   slew != nullptr ? slew->rate : 0.0};
  rows.row(std::span<const double>(row.data(), slew != nullptr ? 34 : 31));
}

}  // namespace

MissionFlights record_mission(const MissionScenario& sc, io::RowSink& rows,
                              const std::atomic<bool>* stop) {
  const governor::GovernorMode mode = sc.params.mode;
  const bool planned = mode == governor::GovernorMode::planned;
  rows.begin(mission_columns(planned));
  const auto every = std::max(1L, std::lround(sc.waypoint.output_interval / sc.waypoint.control_period));
  long k = 0;
  auto observer = [&](double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& c,
                      const governor::GovernorOutput& g) {
    if (k++ % every != 0 && !c.transition) return;
    mission_row(rows, t, y, c, g, nullptr);
  };
  auto planned_observer = [&](double t, const dynamics::SpacecraftState& y,
                              const guidance::MissionCommand& c, const governor::GovernorOutput& g,
                              const MissionSlewState& slew) {
    if (k++ % every != 0 && !c.transition) return;
    mission_row(rows, t, y, c, g, &slew);
  };
  const governor::GovernorMode twin_mode =
      mode == governor::GovernorMode::none ? governor::GovernorMode::pet : governor::GovernorMode::none;
  MissionFlights f;
  f.mode = mode;
  f.twin_mode = twin_mode;
  // A numerical failure of one flight does not lose the other's results: each is recorded in
  // its MissionResult::failure and named in the summary (kinds.cpp then exits 3 when the
  // scenario's own flight failed).
  if (planned) {
    f.own = simulate_planned_mission(
        sc, rows.wants_rows() ? PlannedMissionObserver(planned_observer) : PlannedMissionObserver{}, stop);
  } else {
    f.own = simulate_mission(sc, mode, rows.wants_rows() ? MissionObserver(observer) : MissionObserver{},
                             stop);
  }
  f.twin = simulate_mission(sc, twin_mode, {}, stop);
  return f;
}

namespace {

/// actual / predicted, null unless the flight completed and the prediction is positive.
nlohmann::json time_over(bool completed, double actual, double predicted) {
  return completed && predicted > 0.0 ? nlohmann::json(actual / predicted) : nlohmann::json(nullptr);
}

/// summary.json `prediction` (with its governor mode and whether every governed turn converged),
/// `predicted_time`, `time_over_predicted` and each waypoint's `predicted_time` and
/// `time_over_predicted` of the leg that ends there (docs/mission.md, "Prediction").
void write_mission_prediction(nlohmann::json& summary, const MissionKindPrediction& kp, const MissionResult& own) {
  const guidance::MissionPrediction& pr = kp.prediction;
  summary["prediction"] = prediction_entry(pr);
  summary["prediction"]["turns_converged"] = kp.all_turns_converged;
  summary["predicted_time"] = pr.time;
  summary["time_over_predicted"] = time_over(own.flight.completed, own.flight.total_time, pr.time);
  double previous_arrival = 0.0;
  nlohmann::json& wps = summary["waypoints"];
  for (std::size_t k = 0; k < wps.size() && k < pr.legs.size(); ++k) {
    const WaypointResult& w = own.flight.waypoints[k];
    wps[k]["predicted_time"] = pr.legs[k].time;
    wps[k]["time_over_predicted"] = time_over(w.reached, w.arrival_time - previous_arrival, pr.legs[k].time);
    if (w.reached) previous_arrival = w.arrival_time;
  }
}

}  // namespace

nlohmann::json mission_summary(const MissionScenario& sc, const MissionFlights& f) {
  const governor::GovernorMode mode = f.mode;
  const governor::GovernorMode twin_mode = f.twin_mode;
  const MissionResult& own = f.own;
  const MissionResult& twin = f.twin;
  const bool own_constrained = mode != governor::GovernorMode::none;
  const MissionResult& con = own_constrained ? own : twin;
  const MissionResult& unc = own_constrained ? twin : own;

  nlohmann::json summary = flight_json(sc, mode, own);
  summary["kind"] = "mission";
  summary["name"] = sc.waypoint.name;
  summary["tau_max"] = sc.params.tau_max;
  nlohmann::json cones = nlohmann::json::array();
  for (const auto& c : sc.cones) {
    cones.push_back(cone_json(c));
  }
  summary["cones"] = cones;
  nlohmann::json wps = nlohmann::json::array();
  for (const WaypointResult& w : own.flight.waypoints) {
    wps.push_back({{"index", w.index},
                   {"reached", w.reached},
                   {"arrival_time", w.reached ? nlohmann::json(w.arrival_time) : nlohmann::json(nullptr)},
                   {"final_position_error", w.final_position_error},
                   {"final_speed", w.final_speed},
                   {"delta_v", w.delta_v()}});
  }
  summary["waypoints"] = wps;
  write_mission_prediction(summary, predict_mission_kind(sc, mode), own);
  summary["constrained"] = flight_json(sc, own_constrained ? mode : twin_mode, con);
  summary["unconstrained"] = flight_json(sc, governor::GovernorMode::none, unc);
  // The cost of the constraints only compares two completed flights.
  const bool both = mission_outcome(sc, con).completed && mission_outcome(sc, unc).completed;
  summary["time_cost"] = both ? nlohmann::json(con.flight.total_time - unc.flight.total_time)
                              : nlohmann::json(nullptr);
  summary["delta_v_cost"] = both ? nlohmann::json(con.delta_v() - unc.delta_v()) : nlohmann::json(nullptr);
  if (!own.failure.empty()) summary["failure"] = "flight with governor '" +
                                                 std::string(governor::kGovernorModeNames.name(mode)) +
                                                 "': " + own.failure;
  if (!twin.failure.empty()) summary["twin_failure"] = "twin with governor '" +
                                                       std::string(governor::kGovernorModeNames.name(twin_mode)) +
                                                       "': " + twin.failure;
  return summary;
}

}  // namespace attiguard::sim
