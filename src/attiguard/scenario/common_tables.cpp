// The shared parts of the scenario schema (docs/scenario-format.md, sections "Common rules",
// "Integrator keys", "pet_erg" [control]/[erg]/[[cones]], "reach" [safety]).

#include "attiguard/scenario/common_tables.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>

#include <numbers>
#include <optional>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/ephemeris_check.hpp"
#include "attiguard/scenario/messages.hpp"

namespace attiguard::scenario {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;

/// Names of the cone types (keep_in is the default).
enum class ConeType { keep_in, keep_out };
constexpr NameTable<ConeType, 2> kConeTypeNames{
    {{{ConeType::keep_in, "keep_in"}, {ConeType::keep_out, "keep_out"}}}};
}  // namespace

void declare(const TableReader& table, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) {
    (void)table.has(key);
  }
}

std::string read_header(const TableReader& root, const Document& doc,
                        std::string_view expected_kind, std::string_view default_name) {
  const std::string kind = root.string("kind");
  if (kind != expected_kind) {
    root.fail("kind", "expected \"" + std::string(expected_kind) + "\", got " +
                          detail::quoted(kind, '"'));
  }
  const std::string stem = doc.path.stem().string();
  std::string name = root.string_or("name", stem.empty() ? default_name : std::string_view(stem));
  if (name.empty()) {
    root.fail("name", "must not be empty");
  }
  (void)root.string_or("description", "");
  return name;
}

double angle(const TableReader& t, const std::string& key, const NumberRule& rule_rad) {
  const std::string key_deg = key + "_deg";
  const bool has_rad = t.has(key);
  const bool has_deg = t.has(key_deg);
  if (has_rad && has_deg) {
    t.fail(key_deg, "give either " + key + " (rad) or " + key_deg + " (degrees), not both");
  }
  if (has_rad && !has_deg) {
    // A value that only makes sense in degrees (half_angle = 40): say which key takes degrees.
    const double x = t.number(key);
    const bool below = rule_rad.min && (rule_rad.min_exclusive ? x <= *rule_rad.min : x < *rule_rad.min);
    const bool above = rule_rad.max && (rule_rad.max_exclusive ? x >= *rule_rad.max : x > *rule_rad.max);
    if (!below && above && x <= 360.0) {
      t.fail(key, "must be " + std::string(rule_rad.min_exclusive ? "> " : ">= ") +
                      detail::format_number(rule_rad.min.value_or(0.0)) + " and " +
                      (rule_rad.max_exclusive ? "< " : "<= ") + detail::format_number(*rule_rad.max) +
                      " rad, got " + detail::format_number(x) + ": " + key + " is in radians; for " +
                      detail::format_number(x) + " degrees write " + key_deg + " = " +
                      detail::format_number(x));
    }
  }
  if (has_deg) {
    NumberRule rule_deg = rule_rad;
    if (rule_deg.min) {
      *rule_deg.min /= kDegree;
    }
    if (rule_deg.max) {
      *rule_deg.max /= kDegree;
    }
    return t.number(key_deg, rule_deg) * kDegree;
  }
  return t.number(key, rule_rad);  // reports "missing required key" when neither is present
}

ConeGeometry read_cone_geometry(const TableReader& t) {
  declare(t, {"type", "axis_b", "direction_i", "half_angle", "half_angle_deg"});
  ConeGeometry g;
  g.keep_out = enum_or(t, "type", kConeTypeNames, ConeType::keep_in) == ConeType::keep_out;
  g.axis_b = t.direction("axis_b");
  g.direction_i = t.direction("direction_i");
  // keep_in: θ_c ∈ (0, π]; keep_out: α ∈ [0, π).
  const NumberRule rule = g.keep_out ? NumberRule{0.0, std::numbers::pi, false, true}
                                     : NumberRule{0.0, std::numbers::pi, true, false};
  g.half_angle = angle(t, "half_angle", rule);
  g.half_angle_key = t.has("half_angle_deg") ? "half_angle_deg" : "half_angle";
  return g;
}

namespace {

/// A derived figure for a message: 6 significant digits.
std::string approx(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

/// `angle` [rad] in the unit of the key the cone's half angle was given as.
std::string in_unit_of(const ConeGeometry& g, double angle) {
  return g.half_angle_key == "half_angle_deg" ? approx(angle / kDegree) + " deg"
                                              : approx(angle) + " rad";
}

/// The navigation field of a cone (docs/pet-erg.md, "Repulsive potential") needs
/// cos θ_c < δ < ζ < 1 with δ = cos θ_c + delta_offset, ζ = δ + zeta_offset: the body axis must
/// have a cap of angle φ = θ_c (keep-in) or π − α (keep-out) around the allowed direction, with
/// cos φ + delta_offset + zeta_offset < 1, or the repulsive band covers every attitude. Refused
/// in the user's terms (the cone as given, its half angle in its own unit): at the half angle
/// when even the default offsets (0.05 + 0.05) leave no room, else at the larger offset given.
void require_room_for_field(const TableReader& t, const ConeGeometry& g, double delta_offset,
                            double zeta_offset) {
  constexpr double kDefaultOffsets = 0.05 + 0.05;
  const double phi = g.keep_out ? std::numbers::pi - g.half_angle : g.half_angle;
  const double offsets = delta_offset + zeta_offset;
  const double zeta = std::cos(phi) + offsets;
  if (zeta < 1.0) return;
  const std::string cone = std::string(g.keep_out ? "a keep-out" : "a keep-in") +
                           " cone of half angle " + in_unit_of(g, g.half_angle);
  const std::string why =
      cone + " leaves the body axis a cap of " + in_unit_of(g, phi) + " around " +
      (g.keep_out ? "the opposite of direction_i" : "direction_i") +
      "; its navigation field needs cos(" + in_unit_of(g, phi) + ") + delta_offset + zeta_offset"
      " < 1, got " + approx(std::cos(phi)) + " + " + detail::format_number(delta_offset) + " + " +
      detail::format_number(zeta_offset) + " = " + approx(zeta) +
      " (the repulsive band would cover every attitude): ";
  const bool offsets_given = t.has("delta_offset") || t.has("zeta_offset");
  if (offsets_given && std::cos(phi) + kDefaultOffsets < 1.0) {
    const bool at_zeta = t.has("zeta_offset") && (!t.has("delta_offset") || zeta_offset >= delta_offset);
    t.fail(at_zeta ? "zeta_offset" : "delta_offset",
           why + "use delta_offset + zeta_offset < 1 - cos(" + in_unit_of(g, phi) + ") = " +
               approx(1.0 - std::cos(phi)));
  }
  const double room = std::acos(std::max(-1.0, 1.0 - std::min(offsets, 2.0)));  // smallest cap
  t.fail(g.half_angle_key,
         why + (g.keep_out ? "use a half angle below " + in_unit_of(g, std::numbers::pi - room)
                           : "use a half angle above " + in_unit_of(g, room)) +
             (offsets_given ? " with these offsets" : ""));
}

}  // namespace

governor::ConeConstraint parse_cone(const TableReader& t) {
  declare(t, {"delta_offset", "zeta_offset", "repulsive_gain"});
  const ConeGeometry g = read_cone_geometry(t);
  const double delta_offset = t.number_or("delta_offset", 0.05, NumberRule::positive());
  const double zeta_offset = t.number_or("zeta_offset", 0.05, NumberRule::positive());
  const double gain = t.number_or("repulsive_gain", 1.0, NumberRule::positive());
  require_room_for_field(t, g, delta_offset, zeta_offset);
  const governor::ConeConstraint cone =
      g.keep_out ? governor::keep_out_cone(g.axis_b, g.direction_i, g.half_angle, delta_offset,
                                           zeta_offset, gain)
                 : governor::keep_in_cone(g.axis_b, g.direction_i, g.half_angle, delta_offset,
                                          zeta_offset, gain);
  if (const auto err = governor::cone_error(cone)) {
    t.fail(g.half_angle_key, *err);
  }
  return cone;
}

std::string cone_domain_message(const TableReader& root, std::size_t index,
                                const governor::ConeConstraint& cone, double c,
                                bool reference_given) {
  const ConeGeometry g = read_cone_geometry(root.array_of_tables("cones").at(index));
  const std::string who = reference_given ? "the initial reference R_g(0)" : "the initial attitude";
  const std::string name = "cones[" + std::to_string(index) + "]";
  // Angles of the body axis from direction_i as the user gave it (a keep-out cone stores −s).
  const double angle = std::acos(std::clamp(g.keep_out ? -c : c, -1.0, 1.0));
  const double edge = std::acos(std::clamp(g.keep_out ? -cone.delta : cone.delta, -1.0, 1.0));
  const bool violated = g.keep_out ? angle < g.half_angle : angle > g.half_angle;
  std::string m = who + " puts the body axis axis_b " + in_unit_of(g, angle) + " from direction_i of " +
                  name + ", " + (g.keep_out ? "a keep-out" : "a keep-in") + " cone of half angle " +
                  in_unit_of(g, g.half_angle);
  if (violated) {
    m += g.keep_out ? ": it starts inside the cone it must avoid" : ": it starts outside the cone it must stay in";
  } else {
    m += std::string(": it starts within the navigation field's margin (delta_offset = ") +
         approx(cone.delta - cone.cos_theta_c) + " needs " +
         (g.keep_out ? "more than " : "less than ") + in_unit_of(g, edge) + ")";
  }
  return m + "; start " + (reference_given ? "the reference" : "the attitude") +
         (g.keep_out ? " farther from direction_i" : " closer to direction_i");
}

std::vector<governor::ConeConstraint> parse_cones(const TableReader& root) {
  std::vector<governor::ConeConstraint> out;
  if (!root.has("cones")) return out;
  const std::vector<TableReader> cones = root.array_of_tables("cones");
  if (cones.size() > static_cast<std::size_t>(governor::kMaxCones)) {
    root.fail("cones", "at most " + std::to_string(governor::kMaxCones) +
                           " cone constraints (got " + std::to_string(cones.size()) + ")");
  }
  for (const TableReader& c : cones) {
    out.push_back(parse_cone(c));
    c.finish();
  }
  return out;
}

void parse_erg_table(const TableReader& root, governor::GovernorParams& params) {
  const TableReader erg = root.table_or_empty("erg");  // left out: its defaults, read the same way
  declare(erg, {"kappa", "c_gamma", "sampling_period", "epsilon", "epsilon_gamma", "saddle_tie_break"});
  params.kappa = erg.number_or("kappa", params.kappa, NumberRule::positive());
  params.c_gamma = erg.number_or("c_gamma", params.c_gamma, NumberRule{1.0, std::nullopt, true, false});
  params.Ts = erg.number_or("sampling_period", params.Ts, NumberRule::positive());
  params.epsilon = erg.number_or("epsilon", params.epsilon, NumberRule::positive());
  params.epsilon_gamma =
      erg.number_or("epsilon_gamma", params.epsilon_gamma, NumberRule{0.0, 2.0, true, true});
  // The saddle tie-break of the navigation field (docs/pet-erg.md, section 4).
  params.saddle_tie_break = erg.boolean_or("saddle_tie_break", params.saddle_tie_break);
  erg.finish();
}

TableReader parse_governor_block(const TableReader& root, governor::GovernorParams& params,
                                 std::initializer_list<std::string_view> control_extra,
                                 Gains gains) {
  params.mode = enum_or(root, "governor", governor::kGovernorModeNames, governor::GovernorMode::pet);
  const TableReader control = root.table("control");
  declare(control, {"kp", "kd", "tau_max"});
  declare(control, control_extra);
  if (gains == Gains::required || control.has("kp")) {
    params.gains.kp = control.number("kp", NumberRule::positive());
  }
  if (gains == Gains::required || control.has("kd")) {
    params.gains.kd = control.number("kd", NumberRule::positive());
  }
  params.tau_max = control.number("tau_max", NumberRule::positive());
  // [erg] is the PET-ERG's; the planned mode refuses it (read_pet_erg.cpp) and reads none of it.
  if (params.mode != governor::GovernorMode::planned) parse_erg_table(root, params);
  return control;
}

governor::GivenGovernorValues given_governor_values(const TableReader& root,
                                                   const governor::GovernorParams& params) {
  const TableReader control = root.table("control");
  const TableReader erg = root.table_or_empty("erg");
  governor::GivenGovernorValues given;
  if (control.has("kp")) given.kp = params.gains.kp;
  if (control.has("kd")) given.kd = params.gains.kd;
  if (erg.has("kappa")) given.kappa = params.kappa;
  if (erg.has("sampling_period")) given.Ts = params.Ts;
  if (erg.has("c_gamma")) given.c_gamma = params.c_gamma;
  if (erg.has("epsilon")) given.epsilon = params.epsilon;
  return given;
}

void apply_governor_values(const governor::DerivedGovernorValues& values,
                           governor::GovernorParams& params) {
  params.gains.kp = values.kp;
  params.gains.kd = values.kd;
  params.kappa = values.kappa;
  params.Ts = values.Ts;
  params.c_gamma = values.c_gamma;
  params.epsilon = values.epsilon;
}

governor::AttitudeGovernor make_governor(const TableReader& t, std::string_view where,
                                         const governor::GovernorParams& params,
                                         const std::vector<governor::ConeConstraint>& cones) {
  try {
    return governor::AttitudeGovernor(params, cones);
  } catch (const SetupError& e) {
    if (where.empty()) t.fail_here(e.what());
    t.fail(where, e.what());
  }
}

void require_at_most_duration(const TableReader& simulation, std::string_view key, double value,
                              double duration) {
  if (value <= duration) {
    return;
  }
  const std::string numbers =
      "duration (" + detail::format_number(duration) + "), got " + detail::format_number(value);
  if (simulation.has(key)) {
    simulation.fail(key, "must be <= " + numbers);
  }
  simulation.fail(
      key, "the default must be <= " + numbers + "; set " + std::string(key) + " explicitly");
}


SimulationTimes read_simulation_times(const TableReader& root, const TableReader& simulation,
                                      double output_interval_default) {
  SimulationTimes times;
  times.duration = simulation.number("duration", NumberRule::positive());
  check_ephemeris_end(root, times.duration);  // the AEM's last date (docs/interop.md)
  times.output_interval =
      simulation.number_or("output_interval", output_interval_default, NumberRule::positive());
  times.integrator = parse_integrator_settings(simulation);
  return times;
}

integrate::IntegratorSettings parse_integrator_settings(const TableReader& simulation) {
  integrate::IntegratorSettings settings;
  settings.method =
      enum_or(simulation, "integrator", integrate::kMethodNames, integrate::Method::rkmk4);
  settings.step = simulation.number_or("step", settings.step, NumberRule::positive());
  settings.abs_tol = simulation.number_or("abs_tol", settings.abs_tol, NumberRule::positive());
  settings.rel_tol = simulation.number_or("rel_tol", settings.rel_tol, NumberRule::positive());
  settings.max_step =
      simulation.number_or("max_step", settings.max_step, NumberRule::non_negative());
  return settings;
}

namespace {
/// " (at most L; raise the limit with --flag N)".
std::string limit_clause(WorkLimit limit) {
  return "at most " + detail::format_number(limit_value(limit)) + ", or raise the limit with " +
         std::string(limit_flag(limit)) + " N";
}
}  // namespace

void require_countable(const TableReader& t, std::string_view key, double value, double duration,
                       WorkLimit limit, std::string_view what) {
  const double count = duration / value;
  if (count <= limit_value(limit)) return;
  const std::string message = "needs " + detail::format_number(std::ceil(count)) + " " +
                              std::string(what) + " over the duration " +
                              detail::format_number(duration) + " s (" + std::string(key) + " = " +
                              detail::format_number(value) + " s; " + limit_clause(limit) +
                              "): a run that size does not finish in reasonable time; use a "
                              "larger " + std::string(key);
  if (t.has(key)) t.fail(key, message);
  t.fail(key, "the default " + message + " (set " + std::string(key) + ")");
}

void require_cell_budget(const TableReader& partition, std::string_view key, int attitude_cells,
                         int omega_cells, int steps) {
  const double cells = std::pow(static_cast<double>(attitude_cells), 3) *
                       std::pow(static_cast<double>(omega_cells), 3);
  const double work = cells * steps;
  if (work <= limit_value(WorkLimit::reach_cells)) return;
  partition.fail(key, "attitude_cells = " + std::to_string(attitude_cells) + " and omega_cells = " +
                          std::to_string(omega_cells) + " make up to " +
                          detail::format_number(cells) + " cells (attitude_cells^3 x omega_cells^3)"
                          ", " + detail::format_number(work) + " cell-steps with reach.steps = " +
                          std::to_string(steps) + " (" + limit_clause(WorkLimit::reach_cells) +
                          "): an analysis that size does not finish in reasonable time; use fewer "
                          "cells");
}

void require_step_budget(const TableReader& simulation, const integrate::IntegratorSettings& s,
                         double duration) {
  if (s.method == integrate::Method::rkmk_dp54) {
    if (s.max_step > 0.0) {
      require_countable(simulation, "max_step", s.max_step, duration, kMaxRunSteps, "integrator steps");
    }
    return;
  }
  require_countable(simulation, "step", s.step, duration, kMaxRunSteps, "integrator steps");
}

}  // namespace attiguard::scenario
