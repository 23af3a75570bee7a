// Scenario kind `waypoint` (docs/scenario-format.md, section "waypoint").

#include "attiguard/scenario/waypoint_scenario.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>

#include <Eigen/Eigenvalues>

#include "attiguard/guidance/craft_defaults.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

std::string num(double x) { return detail::format_number(x); }

constexpr double kPi = 3.14159265358979323846;
/// Largest main-engine misalignment accepted by `spacecraft.main_thrust_axis_b` [deg].
constexpr double kMaxThrustTiltDeg = 10.0;

}  // namespace

sim::WaypointScenario parse_waypoint(const Document& doc) {
  sim::WaypointScenario sc;
  guidance::MissionParams& mp = sc.mission;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "spacecraft", "initial", "waypoints",
                 "attitude_control", "fine_position", "guidance", "simulation"});
  sc.name = read_header(root, doc, "waypoint");

  const TableReader craft = root.table("spacecraft");
  declare(craft, {"mass", "inertia", "main_thrust", "rct_thrust", "max_wheel_torque",
                  "main_thrust_axis_b"});
  mp.mass = craft.number("mass", NumberRule::positive());
  sc.J = craft.inertia("inertia");
  mp.T_max = craft.number("main_thrust", NumberRule::positive());
  mp.f_max = craft.number("rct_thrust", NumberRule::positive());
  sc.max_wheel_torque = craft.number_or("max_wheel_torque", 0.0, NumberRule::non_negative());
  if (craft.has("main_thrust_axis_b")) {
    // A mounting misalignment the guidance does not know about (it points x_b): only a tilt
    // the thrust logic can live with is accepted.
    sc.main_thrust_axis_b = craft.direction("main_thrust_axis_b");
    const double tilt_deg =
        std::acos(std::clamp(sc.main_thrust_axis_b.x(), -1.0, 1.0)) * 180.0 / kPi;
    if (tilt_deg > kMaxThrustTiltDeg) {
      craft.fail("main_thrust_axis_b", "the main engine axis is " + num(tilt_deg) +
                                           " deg from body x; at most " + num(kMaxThrustTiltDeg) +
                                           " deg of misalignment is supported");
    }
  }

  if (const auto initial = root.optional_table("initial")) {
    declare(*initial, {"position", "velocity", "attitude", "omega_b"});
    if (initial->has("position")) sc.p0_i = initial->vector3("position");
    if (initial->has("velocity")) sc.v0_i = initial->vector3("velocity");
    if (initial->has("attitude")) sc.R0_ib = initial->rotation("attitude");
    if (initial->has("omega_b")) sc.omega0_b = initial->vector3("omega_b");
  }

  const std::vector<TableReader> wps = root.array_of_tables("waypoints");
  for (const TableReader& w : wps) {
    declare(w, {"position"});
    sc.waypoints_i.push_back(w.vector3("position"));
  }

  // [guidance] profile first: it decides the defaults of the other tables.
  const TableReader g = root.table("guidance");
  sc.profile = enum_or(g, "profile", sim::kGuidanceProfileNames, sim::GuidanceProfile::craft);
  const bool paper = sc.profile == sim::GuidanceProfile::paper;
  // The control period is needed by the craft defaults; [simulation] is read in full below.
  const TableReader sim = root.table("simulation");
  sc.control_period = sim.number_or("control_period", 0.1, NumberRule::positive());
  guidance::CraftLimits limits;
  limits.mass = mp.mass;
  limits.T_max = mp.T_max;
  limits.f_max = mp.f_max;
  limits.J_max = Eigen::SelfAdjointEigenSolver<lie::Mat3>(sc.J).eigenvalues().maxCoeff();
  limits.max_wheel_torque = sc.max_wheel_torque;
  limits.control_period = sc.control_period;

  // [attitude_control]: required by the paper profile (Table I); derived otherwise.
  const control::QuaternionPidGains craft_gains = guidance::craft_attitude_gains(limits);
  if (const auto att = paper ? std::optional<TableReader>(root.table("attitude_control"))
                             : root.optional_table("attitude_control")) {
    declare(*att, {"kp", "ki", "kd", "integral_zone"});
    sc.gains.kp = paper ? att->number("kp", NumberRule::positive())
                        : att->number_or("kp", craft_gains.kp, NumberRule::positive());
    sc.gains.ki = att->number_or("ki", 0.0, NumberRule::non_negative());
    sc.gains.kd = paper ? att->number("kd", NumberRule::positive())
                        : att->number_or("kd", craft_gains.kd, NumberRule::positive());
    sc.gains.integral_zone = att->number_or("integral_zone", 0.0, NumberRule::non_negative());
  } else {
    sc.gains = craft_gains;
  }

  declare(g, {"profile", "cruise_speed", "acceleration_fraction", "pointing_tolerance", "pointing_error", "arrival_radius",
              "position_accuracy", "speed_accuracy", "braking_margin", "braking_distance",
              "main_cutoff_speed", "replan_distance", "brake_speed",
              "velocity_projection", "projection_blend_speed", "projection_full_angle_deg",
              "flip_timing", "flip_lead_time"});
  mp.cruise_speed = g.number("cruise_speed", NumberRule::positive());
  mp.arrival_radius = g.number("arrival_radius", NumberRule::positive());
  mp.position_accuracy = g.number("position_accuracy", NumberRule::positive());
  mp.speed_accuracy = g.number("speed_accuracy", NumberRule::positive());

  // [fine_position]: required by the paper profile (κ_d of Table I); derived otherwise.
  const control::RctPositionGains craft_rct = guidance::craft_rct_gains(limits, mp.speed_accuracy);
  mp.rct = craft_rct;
  if (const auto fine = paper ? std::optional<TableReader>(root.table("fine_position"))
                              : root.optional_table("fine_position")) {
    declare(*fine, {"kappa_p", "kappa_d", "on_threshold"});
    mp.rct.kappa_d = paper ? fine->number("kappa_d", NumberRule::positive())
                           : fine->number_or("kappa_d", craft_rct.kappa_d, NumberRule::positive());
    // Craft profile: critical damping with the κ_d in force (position control on).
    mp.rct.kappa_p = fine->number_or("kappa_p", paper ? 0.0 : 0.25 * mp.rct.kappa_d * mp.rct.kappa_d,
                                     NumberRule::non_negative());
    mp.rct_threshold = fine->number_or("on_threshold", 0.5, {0.0, 1.0, true, false});
  }

  mp.acceleration_fraction =
      g.number_or("acceleration_fraction", 0.2, {0.0, 0.5, true, false});
  mp.pointing_thrust_axis = enum_or(g, "pointing_error", sim::kPointingErrorNames, !paper);
  mp.pointing_tolerance = g.number_or(
      "pointing_tolerance", paper ? 1e-6 : guidance::craft_pointing_tolerance(limits), {0.0, 1.0, true, true});
  mp.braking_margin = g.number_or(
      "braking_margin", paper ? 1.0 : guidance::craft_braking_margin(limits, mp.cruise_speed),
      {0.0, 1.0, true, false});
  mp.brake_along_velocity = enum_or(g, "braking_distance", sim::kBrakingDistanceNames, true);
  mp.main_cutoff_speed = g.number_or(
      "main_cutoff_speed", paper ? 0.02 : guidance::craft_main_cutoff_speed(limits, mp.cruise_speed),
      NumberRule::non_negative());
  mp.replan_distance = g.number_or(
      "replan_distance",
      paper ? 50.0
            : guidance::craft_replan_distance(limits, mp.main_cutoff_speed, mp.position_accuracy,
                                              mp.arrival_radius),
      NumberRule::positive());
  mp.brake_speed =
      g.number_or("brake_speed", guidance::default_brake_speed(mp), NumberRule::non_negative());
  mp.velocity_projection = g.boolean_or("velocity_projection", true);
  mp.projection.blend_speed = g.number_or("projection_blend_speed", 0.05, NumberRule::positive());
  const double full_deg =
      g.number_or("projection_full_angle_deg", 89.0, {0.0, 90.0, false, true});
  mp.projection.cos_full = std::cos(full_deg * kPi / 180.0);
  mp.flip_timing = enum_or(g, "flip_timing", sim::kFlipTimingNames,
                           paper ? guidance::FlipTiming::immediate : guidance::FlipTiming::braking_point);
  mp.flip_lead_time = g.number_or(
      "flip_lead_time", paper ? 60.0 : 1.5 * guidance::craft_slew_time(limits, sc.gains),
      NumberRule::non_negative());
  if (mp.replan_distance <= mp.arrival_radius) {
    g.fail(g.has("replan_distance") ? "replan_distance" : "arrival_radius",
           "replan_distance (" + num(mp.replan_distance) + ") must exceed arrival_radius (" +
               num(mp.arrival_radius) + ")");
  }
  if (mp.rct.kappa_p > 0.0 && mp.position_accuracy >= mp.replan_distance) {
    g.fail("position_accuracy", "must be < replan_distance (" + num(mp.replan_distance) + ")");
  }
  if (mp.main_cutoff_speed >= mp.cruise_speed) {
    g.fail("main_cutoff_speed", "must be < cruise_speed (" + num(mp.cruise_speed) + ")");
  }

  declare(sim, {"duration", "control_period", "output_interval", "integrator", "step", "abs_tol",
                "rel_tol", "max_step"});
  sc.duration = sim.number("duration", NumberRule::positive());
  sc.output_interval = sim.number_or("output_interval", 1.0, NumberRule::positive());
  sc.integrator = parse_integrator_settings(sim);
  if (sc.control_period > sc.duration) {
    sim.fail("control_period", "must be <= duration (" + num(sc.duration) + ")");
  }
  if (sc.output_interval < sc.control_period) {
    sim.fail("output_interval",
             "must be >= control_period (" + num(sc.control_period) + "): rows are logged at "
             "control samples");
  }
  if (sc.duration / sc.control_period > 1e8) {
    sim.fail("control_period", "too small for the duration (more than 1e8 control samples)");
  }
  require_step_budget(sim, sc.integrator, sc.duration);
  require_countable(sim, "output_interval", sc.output_interval, sc.duration, kMaxOutputRows,
                    "output rows");
  root.finish();

  // Reachability: every waypoint needs at least the bang-bang time of its leg.
  const double a_max = mp.T_max / mp.mass;
  double t_min = 0.0;
  lie::Vec3 from = sc.p0_i;
  for (std::size_t k = 0; k < sc.waypoints_i.size(); ++k) {
    t_min += 2.0 * std::sqrt((sc.waypoints_i[k] - from).norm() / a_max);
    from = sc.waypoints_i[k];
    if (t_min > sc.duration) {
      wps[k].fail("position",
                  "waypoint " + std::to_string(k) + " is unreachable within simulation.duration (" +
                      num(sc.duration) + " s): even bang-bang at T_max/m = " + num(a_max) +
                      " m/s^2 needs " + num(t_min) + " s to get there");
    }
  }
  return sc;
}

}  // namespace attiguard::scenario
