// The shared parts of the scenario schema (docs/scenario-format.md, sections "Common rules",
// "Integrator keys", "pet_erg" [control]/[erg]/[[cones]], "reach" [safety]).

#include "attiguard/scenario/common_tables.hpp"

#include <cmath>

#include <numbers>
#include <optional>

#include "attiguard/core/errors.hpp"
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

governor::ConeConstraint parse_cone(const TableReader& t) {
  declare(t, {"delta_offset", "zeta_offset", "repulsive_gain"});
  const ConeGeometry g = read_cone_geometry(t);
  const double delta_offset = t.number_or("delta_offset", 0.05, NumberRule::positive());
  const double zeta_offset = t.number_or("zeta_offset", 0.05, NumberRule::positive());
  const double gain = t.number_or("repulsive_gain", 1.0, NumberRule::positive());
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
  const auto erg = root.optional_table("erg");
  if (!erg) return;
  declare(*erg, {"kappa", "c_gamma", "sampling_period", "epsilon", "epsilon_gamma"});
  params.kappa = erg->number_or("kappa", params.kappa, NumberRule::positive());
  params.c_gamma = erg->number_or("c_gamma", params.c_gamma, NumberRule{1.0, std::nullopt, true, false});
  params.Ts = erg->number_or("sampling_period", params.Ts, NumberRule::positive());
  params.epsilon = erg->number_or("epsilon", params.epsilon, NumberRule::positive());
  params.epsilon_gamma =
      erg->number_or("epsilon_gamma", params.epsilon_gamma, NumberRule{0.0, 2.0, true, true});
  erg->finish();
}

TableReader parse_governor_block(const TableReader& root, governor::GovernorParams& params,
                                 std::initializer_list<std::string_view> control_extra) {
  params.mode = enum_or(root, "governor", governor::kGovernorModeNames, governor::GovernorMode::pet);
  const TableReader control = root.table("control");
  declare(control, {"kp", "kd", "tau_max"});
  declare(control, control_extra);
  params.gains.kp = control.number("kp", NumberRule::positive());
  params.gains.kd = control.number("kd", NumberRule::positive());
  params.tau_max = control.number("tau_max", NumberRule::positive());
  parse_erg_table(root, params);
  return control;
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

void require_countable(const TableReader& t, std::string_view key, double value, double duration,
                       double limit, std::string_view what) {
  const double count = duration / value;
  if (count <= limit) return;
  const std::string message = "needs " + detail::format_number(std::ceil(count)) + " " +
                              std::string(what) + " over the duration " +
                              detail::format_number(duration) + " s (" + std::string(key) + " = " +
                              detail::format_number(value) + " s; at most " +
                              detail::format_number(limit) + "): a run that size does not finish " +
                              "in reasonable time; use a larger " + std::string(key);
  if (t.has(key)) t.fail(key, message);
  t.fail(key, "the default " + message + " (set " + std::string(key) + ")");
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
