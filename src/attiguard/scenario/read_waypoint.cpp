// Scenario kind `waypoint` (docs/scenario-format.md, section "waypoint").

#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <numbers>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <optional>


#include "attiguard/core/four_digits.hpp"
#include "attiguard/guidance/craft_defaults.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/ephemeris_check.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {


constexpr double kPi = std::numbers::pi;
/// Largest main-engine misalignment accepted by `spacecraft.main_thrust_axis_b` [deg].
constexpr double kMaxThrustTiltDeg = 10.0;

/// Speeds are below the speed of light [m/s] (docs/scenario-format.md, "waypoint", bounds).
constexpr double kSpeedOfLight = 299792458.0;
/// Positions are at most one light-year [m] from the origin: the waypoint model is flat,
/// gravity-free space; beyond it no spacecraft's translation is modelled by it, and squared
/// distances (≤ 4e32 m², between two points) stay far inside double precision.
constexpr double kMaxPosition = kSpeedOfLight * 365.25 * 86400.0;

/// A position vector no farther than kMaxPosition from the origin.
lie::Vec3 bounded_position(const TableReader& t, std::string_view key) {
  const lie::Vec3 p = t.vector3(key);
  if (const double r = p.stableNorm(); !(r <= kMaxPosition)) {
    t.fail(key, "at most one light-year (" + detail::format_number(kMaxPosition) +
                    " m) from the origin, got " + detail::format_number(r) + " m");
  }
  return p;
}


/// [spacecraft]: mass, inertia, thrust levels and the main engine's mounting (docs/waypoint.md).
/// Returns the table, whose rct_thrust a later authority check names.
TableReader read_waypoint_spacecraft(const TableReader& root, sim::WaypointScenario& sc) {
  guidance::MissionParams& mp = sc.mission;
  TableReader craft = root.table("spacecraft");
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
      craft.fail("main_thrust_axis_b", "the main engine axis is " + detail::format_number(tilt_deg) +
                                           " deg from body x; at most " + detail::format_number(kMaxThrustTiltDeg) +
                                           " deg of misalignment is supported");
    }
  }
  return craft;
}

/// [initial]: the optional initial position, velocity (below the speed of light), attitude and
/// body rate.
void read_waypoint_initial(const TableReader& root, sim::WaypointScenario& sc) {
  const auto initial = root.optional_table("initial");
  if (!initial) return;
  declare(*initial, {"position", "velocity", "attitude", "omega_b"});
  if (initial->has("position")) sc.p0_i = bounded_position(*initial, "position");
  if (initial->has("velocity")) {
    sc.v0_i = initial->vector3("velocity");
    if (const double speed = sc.v0_i.stableNorm(); !(speed < kSpeedOfLight)) {
      initial->fail("velocity", "speed " + detail::format_number(speed) +
                                    " m/s is not below the speed of light, " +
                                    detail::format_number(kSpeedOfLight) + " m/s");
    }
  }
  if (initial->has("attitude")) sc.R0_ib = initial->rotation("attitude");
  if (initial->has("omega_b")) sc.omega0_b = initial->vector3("omega_b");
}

/// [[waypoints]]: their positions; returns the tables, which the reachability check names.
std::vector<TableReader> read_waypoint_positions(const TableReader& root, sim::WaypointScenario& sc) {
  std::vector<TableReader> wps = root.array_of_tables("waypoints");
  for (const TableReader& w : wps) {
    declare(w, {"position"});
    sc.waypoints_i.push_back(bounded_position(w, "position"));
  }
  return wps;
}

/// The craft's limits from which the craft profile derives its defaults
/// (guidance/craft_defaults.hpp; docs/waypoint.md, "Tuning").
guidance::CraftLimits waypoint_craft_limits(const sim::WaypointScenario& sc) {
  guidance::CraftLimits limits;
  limits.mass = sc.mission.mass;
  limits.T_max = sc.mission.T_max;
  limits.f_max = sc.mission.f_max;
  const lie::Vec3 moments = lie::symmetric_eigenvalues(sc.J);
  limits.J_max = moments(2);
  limits.J_min = moments(0);
  limits.J = sc.J;
  limits.max_wheel_torque = sc.max_wheel_torque;
  limits.control_period = sc.control_period;
  return limits;
}

/// [attitude_control]: required by the paper profile (Table I); derived otherwise.
void read_waypoint_attitude_control(const TableReader& root, bool paper,
                                    const guidance::CraftLimits& limits, sim::WaypointScenario& sc) {
  const control::QuaternionPidGains craft_gains = guidance::craft_attitude_gains(limits);
  const auto att = paper ? std::optional<TableReader>(root.table("attitude_control"))
                         : root.optional_table("attitude_control");
  if (!att) {
    sc.gains = craft_gains;
    return;
  }
  declare(*att, {"kp", "ki", "kd", "integral_zone"});
  // Derived gains keep their shaping, which no key expresses: their kp and kd are not read as
  // defaults (the resolved scenario would turn the shaping off by writing them).
  const bool shaped = !paper && !att->has("kp") && !att->has("kd");
  sc.gains.kp = paper    ? att->number("kp", NumberRule::positive())
                : shaped ? craft_gains.kp
                         : att->number_or("kp", DerivedDefault{craft_gains.kp}, NumberRule::positive());
  sc.gains.ki = att->number_or("ki", 0.0, NumberRule::non_negative());
  sc.gains.kd = paper    ? att->number("kd", NumberRule::positive())
                : shaped ? craft_gains.kd
                         : att->number_or("kd", DerivedDefault{craft_gains.kd}, NumberRule::positive());
  sc.gains.integral_zone = att->number_or("integral_zone", 0.0, NumberRule::non_negative());
  if (shaped) {  // derived gains keep their shaping
    sc.gains.shaped = craft_gains.shaped;
    sc.gains.shaping = craft_gains.shaping;
    sc.gains.shaping_scale = craft_gains.shaping_scale;
  }
}

/// [guidance]: declares its keys and reads the required ones (cruise speed and accuracies).
void read_waypoint_guidance_required(const TableReader& g, guidance::MissionParams& mp) {
  declare(g, {"profile", "cruise_speed", "acceleration_fraction", "pointing_tolerance", "pointing_error", "arrival_radius",
              "position_accuracy", "speed_accuracy", "braking_margin", "braking_distance", "lateral_rct",
              "rct_transfer",
              "main_cutoff_speed", "replan_distance", "brake_speed",
              "velocity_projection", "projection_blend_speed", "projection_full_angle_deg",
              "flip_timing", "flip_lead_time"});
  mp.cruise_speed = g.number("cruise_speed", NumberRule::positive());
  mp.arrival_radius = g.number("arrival_radius", NumberRule::positive());
  mp.position_accuracy = g.number("position_accuracy", NumberRule::positive());
  mp.speed_accuracy = g.number("speed_accuracy", NumberRule::positive());
}

/// [fine_position]: required by the paper profile (κ_d of Table I); derived otherwise. Returns
/// the table when given, which the dead-band checks name.
std::optional<TableReader> read_waypoint_fine_position(const TableReader& root, bool paper,
                                                       const guidance::CraftLimits& limits,
                                                       guidance::MissionParams& mp) {
  const control::RctPositionGains craft_rct =
      guidance::craft_rct_gains(limits, mp.speed_accuracy, mp.position_accuracy);
  mp.rct = craft_rct;
  const double craft_braking = paper ? 0.0 : guidance::craft_rct_braking_acceleration(limits);
  mp.rct.braking_acceleration = craft_braking;
  std::optional<TableReader> fine = paper ? std::optional<TableReader>(root.table("fine_position"))
                                          : root.optional_table("fine_position");
  if (!fine) return fine;
  declare(*fine, {"kappa_p", "kappa_d", "on_threshold", "braking_acceleration"});
  mp.rct.braking_acceleration =
      fine->number_or("braking_acceleration", DerivedDefault{craft_braking}, NumberRule::non_negative());
  mp.rct.kappa_d = paper ? fine->number("kappa_d", NumberRule::positive())
                         : fine->number_or("kappa_d", DerivedDefault{craft_rct.kappa_d}, NumberRule::positive());
  // Craft profile: the derived κ_p with the κ_d in force (position control on).
  mp.rct.kappa_p = fine->number_or(
      "kappa_p", DerivedDefault{paper ? 0.0 : guidance::craft_kappa_p(limits, mp.rct.kappa_d, mp.position_accuracy)},
      NumberRule::non_negative());
  mp.rct_threshold = fine->number_or("on_threshold", 0.5, {0.0, 1.0, true, false});
  return fine;
}

/// [guidance]: the optional keys, with the paper's values or the craft-derived defaults.
void read_waypoint_guidance_options(const TableReader& g, bool paper, const guidance::CraftLimits& limits,
                                    sim::WaypointScenario& sc) {
  guidance::MissionParams& mp = sc.mission;
  mp.acceleration_fraction =
      g.number_or("acceleration_fraction", 0.2, {0.0, 0.5, true, false});
  mp.pointing_thrust_axis = enum_or(g, "pointing_error", sim::kPointingErrorNames, !paper);
  mp.pointing_tolerance = g.number_or(
      "pointing_tolerance", DerivedDefault{paper ? 1e-6 : guidance::craft_pointing_tolerance(limits)}, {0.0, 1.0, true, true});
  mp.braking_margin = g.number_or(
      "braking_margin", DerivedDefault{paper ? 1.0 : guidance::craft_braking_margin(limits, mp.cruise_speed)},
      {0.0, 1.0, true, false});
  mp.brake_along_velocity = enum_or(g, "braking_distance", sim::kBrakingDistanceNames, true);
  mp.main_cutoff_speed = g.number_or(
      "main_cutoff_speed", DerivedDefault{paper ? 0.02 : guidance::craft_main_cutoff_speed(limits, mp.cruise_speed)},
      NumberRule::non_negative());
  mp.replan_distance = g.number_or(
      "replan_distance",
      DerivedDefault{paper ? 50.0
            : guidance::craft_replan_distance(limits, mp.main_cutoff_speed, mp.position_accuracy,
                                              mp.arrival_radius,
                                              guidance::craft_slew_time(limits, sc.gains))},
      NumberRule::positive());
  mp.brake_speed =
      g.number_or("brake_speed", DerivedDefault{guidance::default_brake_speed(mp)}, NumberRule::non_negative());
  mp.velocity_projection = g.boolean_or("velocity_projection", true);
  mp.lateral_rct = g.boolean_or("lateral_rct", !paper);
  mp.rct_transfer = g.boolean_or("rct_transfer", !paper);
  mp.projection.blend_speed = g.number_or(
      "projection_blend_speed", DerivedDefault{paper ? 0.05 : guidance::craft_projection_blend_speed(limits)},
      NumberRule::positive());
  const double full_deg =
      g.number_or("projection_full_angle_deg", 89.0, {0.0, 90.0, false, true});
  mp.projection.cos_full = std::cos(full_deg * kPi / 180.0);
  mp.flip_timing = enum_or(g, "flip_timing", sim::kFlipTimingNames,
                           paper ? guidance::FlipTiming::immediate : guidance::FlipTiming::braking_point);
  mp.flip_lead_time = g.number_or(
      "flip_lead_time", DerivedDefault{paper ? 60.0 : 1.5 * guidance::craft_slew_time(limits, sc.gains)},
      NumberRule::non_negative());
}

/// The order of the guidance distances and speeds: arrival radius < replan distance, position
/// accuracy < replan distance (position control on), main cut-off speed < cruise speed.
void check_waypoint_guidance_order(const TableReader& g, const guidance::MissionParams& mp) {
  if (mp.replan_distance <= mp.arrival_radius) {
    g.fail(g.has("replan_distance") ? "replan_distance" : "arrival_radius",
           "replan_distance (" + detail::format_number(mp.replan_distance) + ") must exceed arrival_radius (" +
               detail::format_number(mp.arrival_radius) + ")");
  }
  if (mp.rct.kappa_p > 0.0 && mp.position_accuracy >= mp.replan_distance) {
    g.fail("position_accuracy", "must be < replan_distance (" + detail::format_number(mp.replan_distance) + ")");
  }
  if (mp.main_cutoff_speed >= mp.cruise_speed) {
    g.fail("main_cutoff_speed", "must be < cruise_speed (" + detail::format_number(mp.cruise_speed) + ")");
  }
}

/// [simulation]: duration, output interval and integrator; control_period was read before
/// (the craft defaults need it) and is checked here against the others.
void read_waypoint_simulation(const TableReader& root, const TableReader& sim, sim::WaypointScenario& sc) {
  declare(sim, {"duration", "control_period", "output_interval", "integrator", "step", "abs_tol",
                "rel_tol", "max_step"});
  const SimulationTimes times = read_simulation_times(root, sim, 1.0);
  sc.duration = times.duration;
  sc.output_interval = times.output_interval;
  sc.integrator = times.integrator;
  if (sc.control_period > sc.duration) {
    sim.fail("control_period", "must be <= duration (" + detail::format_number(sc.duration) + ")");
  }
  if (sc.output_interval < sc.control_period) {
    sim.fail("output_interval",
             "must be >= control_period (" + detail::format_number(sc.control_period) + "): rows are logged at "
             "control samples");
  }
  require_countable(sim, "control_period", sc.control_period, sc.duration, kMaxRunSteps,
                    "control samples");
  require_step_budget(sim, sc.integrator, sc.duration);
  require_countable(sim, "output_interval", sc.output_interval, sc.duration, kMaxOutputRows,
                    "output rows");
}

/// What the craft cannot fly (docs/waypoint.md, "Tuning"): accuracies inside the RCT dead bands
/// or below one RCT pulse, and an RCT stopping distance beyond the replan distance; rejected
/// with the reason and the numbers, before flying.
void check_waypoint_rct_authority(const TableReader& craft, const TableReader& g,
                                  const std::optional<TableReader>& fine_table,
                                  const guidance::CraftLimits& limits, const guidance::MissionParams& mp) {
  auto fail_fine = [&](const char* fine_key, const char* guidance_key, const std::string& why) {
    if (fine_table && fine_table->has(fine_key)) fine_table->fail(fine_key, why);
    g.fail(guidance_key, why);
  };
  const double band_p = guidance::rct_position_dead_band(limits, mp.rct, mp.rct_threshold);
  if (mp.rct.kappa_p > 0.0 && band_p > mp.position_accuracy) {
    fail_fine("kappa_p", "position_accuracy",
              "position_accuracy " + four_digits(mp.position_accuracy) + " m is unreachable: the RCT (" +
                  four_digits(limits.a_rct()) + " m/s^2) stop firing within " + four_digits(band_p) +
                  " m of the waypoint with kappa_p = " + four_digits(mp.rct.kappa_p));
  }
  const double band_v = guidance::rct_speed_dead_band(limits, mp.rct, mp.rct_threshold);
  // At the band itself the position term of [Waypoint eq. (28)] still fires (waypoint_fine.toml flies at
  // band = δ_v); twice the accuracy is out of reach.
  if (band_v > 2.0 * mp.speed_accuracy) {
    fail_fine("kappa_d", "speed_accuracy",
              "speed_accuracy " + four_digits(mp.speed_accuracy) + " m/s is unreachable: the RCT (" +
                  four_digits(limits.a_rct()) + " m/s^2) stop firing below " + four_digits(band_v) +
                  " m/s with kappa_d = " + four_digits(mp.rct.kappa_d) + " (more than twice the accuracy)");
  }
  const double quantum = guidance::rct_speed_quantum(limits);
  if (quantum > mp.speed_accuracy) {
    g.fail("speed_accuracy", "speed_accuracy " + four_digits(mp.speed_accuracy) +
                                 " m/s is unreachable: one control period of one RCT changes the "
                                 "speed by " + four_digits(quantum) + " m/s (more than the accuracy)");
  }
  const double v_left = guidance::main_speed_left(limits, mp.main_cutoff_speed);
  const double s_rct = guidance::rct_stopping_distance(limits, v_left);
  if (s_rct > mp.replan_distance) {
    craft.fail("rct_thrust", "thruster authority too small: the RCT (" + four_digits(limits.a_rct()) +
                                 " m/s^2) need " + four_digits(s_rct) + " m to stop the " + four_digits(v_left) +
                                 " m/s the main engine leaves at cut-off, more than "
                                 "guidance.replan_distance (" + four_digits(mp.replan_distance) + " m)");
  }
}

/// Reachability: every waypoint needs at least the bang-bang time of its leg, and one half-turn
/// (the flip) at the wheels' torque limit per leg longer than the arrival radius that the main
/// engine flies (not the legs inside half the re-plan distance, which the RCT fly).
void check_waypoints_reachable(const std::vector<TableReader>& wps, const guidance::CraftLimits& limits,
                               const sim::WaypointScenario& sc) {
  const guidance::MissionParams& mp = sc.mission;
  const double a_max = mp.T_max / mp.mass;
  const double t_flip = guidance::wheel_half_turn_time(limits);
  double t_min = 0.0;
  double t_flips = 0.0;
  lie::Vec3 from = sc.p0_i;
  for (std::size_t k = 0; k < sc.waypoints_i.size(); ++k) {
    const double leg = (sc.waypoints_i[k] - from).norm();
    t_min += 2.0 * std::sqrt(leg / a_max);
    // A leg inside half the re-plan distance is flown by the RCT alone (no flip; start_leg).
    const bool rct_leg = mp.rct.kappa_p > 0.0 && leg <= 0.5 * mp.replan_distance;
    if (leg > mp.arrival_radius && !rct_leg) t_flips += t_flip;
    from = sc.waypoints_i[k];
    if (t_min + t_flips > sc.duration) {
      wps[k].fail("position",
                  "waypoint " + std::to_string(k) + " is unreachable within simulation.duration (" +
                      detail::format_number(sc.duration) + " s): even bang-bang at T_max/m = " + detail::format_number(a_max) +
                      " m/s^2 needs " + detail::format_number(t_min) + " s to get there" +
                      (t_flips > 0.0 ? " plus " + four_digits(t_flips) + " s of flips at max_wheel_torque " +
                                           four_digits(sc.max_wheel_torque) + " N m"
                                     : std::string()));
    }
  }
}

}  // namespace

sim::WaypointScenario parse_waypoint(const Document& doc) { return parse_waypoint_part(doc, "waypoint", {}); }

sim::WaypointScenario parse_waypoint_part(const Document& doc, std::string_view kind,
                                          std::initializer_list<std::string_view> other_keys) {
  sim::WaypointScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "spacecraft", "initial", "waypoints",
                 "attitude_control", "fine_position", "guidance", "simulation"});
  declare(root, other_keys);
  sc.name = read_header(root, doc, kind);
  check_ephemeris_table(root);  // AEM export metadata (docs/interop.md)
  const TableReader craft = read_waypoint_spacecraft(root, sc);
  read_waypoint_initial(root, sc);
  const std::vector<TableReader> wps = read_waypoint_positions(root, sc);

  // [guidance] profile first: it decides the defaults of the other tables.
  const TableReader g = root.table("guidance");
  sc.profile = enum_or(g, "profile", sim::kGuidanceProfileNames, sim::GuidanceProfile::craft);
  const bool paper = sc.profile == sim::GuidanceProfile::paper;
  // The control period is needed by the craft defaults; [simulation] is read in full below.
  const TableReader sim = root.table("simulation");
  sc.control_period = sim.number_or("control_period", 0.1, NumberRule::positive());
  const guidance::CraftLimits limits = waypoint_craft_limits(sc);

  read_waypoint_attitude_control(root, paper, limits, sc);
  read_waypoint_guidance_required(g, sc.mission);
  const std::optional<TableReader> fine_table = read_waypoint_fine_position(root, paper, limits, sc.mission);
  read_waypoint_guidance_options(g, paper, limits, sc);
  check_waypoint_guidance_order(g, sc.mission);
  read_waypoint_simulation(root, sim, sc);
  root.finish();

  check_waypoint_rct_authority(craft, g, fine_table, limits, sc.mission);
  check_waypoints_reachable(wps, limits, sc);
  return sc;
}

}  // namespace attiguard::scenario
