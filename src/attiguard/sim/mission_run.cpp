/// @file mission_run.cpp
/// The `mission` kind: waypoint guidance through the PET-ERG (docs/mission.md).

#include "attiguard/sim/mission_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/cone_json.hpp"

namespace attiguard::sim {

double MissionResult::delta_v() const noexcept {
  double dv = 0.0;
  for (const WaypointResult& w : flight.waypoints) dv += w.delta_v();
  return dv;
}

MissionResult simulate_mission(const MissionScenario& sc, governor::GovernorMode mode,
                               const MissionObserver& observer, const std::atomic<bool>* stop) {
  governor::GovernorParams params = sc.params;
  params.mode = mode;
  governor::AttitudeGovernor gov(params, sc.cones);
  gov.reset(0.0, sc.waypoint.R0_ib);  // R_g(0) = R(0) [PET-ERG Sec. IV-A]
  const dynamics::SpacecraftPlant plant(sc.waypoint.mission.mass, sc.waypoint.J,
                                        sc.waypoint.max_wheel_torque, sc.waypoint.main_thrust_axis_b);

  MissionResult res;
  res.min_pointing_margin = std::numeric_limits<double>::infinity();
  const governor::GovernorOutput* last = nullptr;
  auto filter = [&](double t, const dynamics::SpacecraftState& y, guidance::MissionCommand& cmd) {
    if (stop != nullptr && stop->load(std::memory_order_relaxed)) {
      throw io::Interrupted("interrupted: the mission flight was stopped at t = " + std::to_string(t) + " s");
    }
    const lie::Mat3 R_d = lie::quat_to_rotation(cmd.q_id);
    const governor::GovernorOutput& out = gov.step(t, y.R[0], dynamics::omega_b_of(y), R_d);
    last = &out;
    cmd.inputs.tau_b = out.tau_b;  // PD law [Waypoint eq. (3)] towards the governed R_g
    if (cmd.inputs.thrust > 0.0 && lie::distance(out.R_g, R_d) > sc.align_tolerance) {
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
    if (tau > params.tau_max * (1.0 + 1e-9)) ++res.torque_violations;
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
  return j;
}

}  // namespace

MissionFlights record_mission(const MissionScenario& sc, io::RowSink& rows,
                              const std::atomic<bool>* stop) {
  rows.begin({"t", "p_x", "p_y", "p_z", "v_x", "v_y", "v_z", "q_w", "q_x", "q_y", "q_z",
                     "omega_x", "omega_y", "omega_z", "tau_x", "tau_y", "tau_z", "tau_norm",
                     "thrust", "mode", "waypoint", "qg_w", "qg_x", "qg_y", "qg_z", "qd_w", "qd_x",
                     "qd_y", "qd_z", "trigger", "min_margin"});
  const auto every = std::max(1L, std::lround(sc.waypoint.output_interval / sc.waypoint.control_period));
  long k = 0;
  auto observer = [&](double t, const dynamics::SpacecraftState& y, const guidance::MissionCommand& c,
                      const governor::GovernorOutput& g) {
    if (k++ % every != 0 && !c.transition) return;
    const lie::Vec3 p = dynamics::p_i_of(y), v = dynamics::v_i_of(y), w = dynamics::omega_b_of(y);
    const lie::Quat& q = c.q_ib;
    const lie::Quat qg = lie::rotation_to_quat(g.R_g);
    const lie::Quat& qd = c.q_id;
    const std::array<double, 31> row{t, p(0), p(1), p(2), v(0), v(1), v(2), q(0), q(1), q(2), q(3),
                                     w(0), w(1), w(2), g.tau_b(0), g.tau_b(1), g.tau_b(2),
                                     g.tau_b.norm(), c.inputs.thrust,
                                     static_cast<double>(static_cast<int>(c.mode)),
                                     static_cast<double>(c.waypoint), qg(0), qg(1), qg(2), qg(3),
                                     qd(0), qd(1), qd(2), qd(3), g.trigger ? 1.0 : 0.0,
                                     g.cone_count > 0 ? g.min_margin() : 0.0};
    rows.row(row);
  };
  const governor::GovernorMode mode = sc.params.mode;
  const governor::GovernorMode twin_mode =
      mode == governor::GovernorMode::none ? governor::GovernorMode::pet : governor::GovernorMode::none;
  MissionFlights f;
  f.mode = mode;
  f.twin_mode = twin_mode;
  // A numerical failure of one flight does not lose the other's results: each is recorded in
  // its MissionResult::failure and named in the summary (kinds.cpp then exits 3 when the
  // scenario's own flight failed).
  f.own = simulate_mission(sc, mode, rows.wants_rows() ? MissionObserver(observer) : MissionObserver{},
                           stop);
  f.twin = simulate_mission(sc, twin_mode, {}, stop);
  return f;
}

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
