// Scenario kind `pet_erg` (docs/scenario-format.md, section "pet_erg").

#include "attiguard/scenario/pet_erg_scenario.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/rigid_body_scenario.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

using governor::ConeConstraint;
using governor::GovernorMode;
using lie::Mat3;
using lie::Vec3;

void declare(const TableReader& table, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) {
    (void)table.has(key);
  }
}

std::string num(double x) { return detail::format_number(x); }

constexpr double kDegree = std::numbers::pi / 180.0;

/// An angle given as `<key>_deg` (degrees) or `<key>` (radians), exactly one of them.
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


/// Rejects a desired attitude that violates a cone or lies in a cone's repulsive band.
void check_desired(const TableReader& t, std::string_view key, const Mat3& R_d,
                   std::span<const ConeConstraint> cones) {
  for (std::size_t i = 0; i < cones.size(); ++i) {
    const ConeConstraint& cone = cones[i];
    const double c = governor::cone_cosine(cone, R_d);
    const std::string which = "cones[" + std::to_string(i) + "]";
    if (c < cone.cos_theta_c) {
      t.fail(key, "desired attitude violates the pointing constraint " + which +
                      " (a_c^T R_d a_b = " + num(c) + " < cos(theta_c) = " + num(cone.cos_theta_c) +
                      ")");
    }
    if (c < cone.zeta) {
      t.fail(key, "desired attitude lies in the repulsive band of " + which + " (a_c^T R_d a_b = " +
                      num(c) + " < zeta = " + num(cone.zeta) +
                      "): the governed reference cannot converge to it; move R_d or reduce "
                      "delta_offset/zeta_offset");
    }
  }
}

governor::ReferenceSchedule parse_desired(const TableReader& t,
                                          std::span<const ConeConstraint> cones) {
  declare(t, {"attitude", "schedule", "interpolation"});
  const bool has_attitude = t.has("attitude");
  const bool has_schedule = t.has("schedule");
  if (has_attitude == has_schedule) {
    t.fail_here("give exactly one of 'attitude' (constant R_d) or 'schedule' (R_d(t))");
  }
  if (has_attitude) {
    const Mat3 R_d = t.rotation("attitude");
    check_desired(t, "attitude", R_d, cones);
    return governor::ReferenceSchedule(R_d);
  }
  static constexpr std::array<std::string_view, 2> modes{"hold", "geodesic"};
  const std::string interp = t.string_or("interpolation", "hold", modes);
  const std::vector<TableReader> entries = t.array_of_tables("schedule");
  if (entries.size() > static_cast<std::size_t>(governor::kMaxWaypoints)) {
    t.fail("schedule", "at most " + std::to_string(governor::kMaxWaypoints) + " waypoints");
  }
  std::vector<governor::Waypoint> waypoints;
  for (const TableReader& e : entries) {
    declare(e, {"t", "attitude"});
    governor::Waypoint w;
    w.t = e.number("t", NumberRule::non_negative());
    if (!waypoints.empty() && !(w.t > waypoints.back().t)) {
      e.fail("t", "schedule times must increase strictly (previous t = " + num(waypoints.back().t) +
                      ")");
    }
    w.R_d = e.rotation("attitude");
    check_desired(e, "attitude", w.R_d, cones);
    waypoints.push_back(w);
  }
  return governor::ReferenceSchedule(waypoints, interp == "geodesic"
                                                    ? governor::Interpolation::geodesic
                                                    : governor::Interpolation::hold);
}

}  // namespace

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

ConeConstraint parse_cone(const TableReader& t) {
  declare(t, {"type", "axis_b", "direction_i", "half_angle", "half_angle_deg", "delta_offset",
              "zeta_offset", "repulsive_gain"});
  static constexpr std::array<std::string_view, 2> types{"keep_in", "keep_out"};
  const std::string type = t.string_or("type", "keep_in", types);
  const Vec3 axis_b = t.direction("axis_b");
  const Vec3 direction_i = t.direction("direction_i");
  const bool keep_in = type == "keep_in";
  // keep_in: θ_c ∈ (0, π]; keep_out: α ∈ [0, π).
  const NumberRule rule = keep_in ? NumberRule{0.0, std::numbers::pi, true, false}
                                  : NumberRule{0.0, std::numbers::pi, false, true};
  const double half_angle = angle(t, "half_angle", rule);
  const double delta_offset = t.number_or("delta_offset", 0.05, NumberRule::positive());
  const double zeta_offset = t.number_or("zeta_offset", 0.05, NumberRule::positive());
  const double gain = t.number_or("repulsive_gain", 1.0, NumberRule::positive());
  const ConeConstraint cone =
      keep_in ? governor::keep_in_cone(axis_b, direction_i, half_angle, delta_offset, zeta_offset, gain)
              : governor::keep_out_cone(axis_b, direction_i, half_angle, delta_offset, zeta_offset,
                                        gain);
  if (const auto err = governor::cone_error(cone)) {
    t.fail(t.has("half_angle_deg") ? "half_angle_deg" : "half_angle", *err);
  }
  return cone;
}

const char* governor_mode_name(GovernorMode mode) noexcept {
  switch (mode) {
    case GovernorMode::pet:
      return "pet";
    case GovernorMode::continuous:
      return "continuous";
    case GovernorMode::none:
      return "none";
  }
  return "?";
}

PetErgScenario parse_pet_erg(const Document& doc) {
  PetErgScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "governor", "body", "initial", "desired",
                 "control", "erg", "cones", "simulation"});
  const std::string kind = root.string("kind");
  if (kind != "pet_erg") {
    root.fail("kind", "expected \"pet_erg\", got " + detail::quoted(kind, '"'));
  }
  const std::string stem = doc.path.stem().string();
  sc.name = root.string_or("name", stem.empty() ? "scenario" : stem);
  if (sc.name.empty()) {
    root.fail("name", "must not be empty");
  }
  (void)root.string_or("description", "");

  static constexpr std::array<std::string_view, 3> modes{"pet", "continuous", "none"};
  const std::string mode = root.string_or("governor", "pet", modes);
  sc.params.mode = mode == "pet"          ? GovernorMode::pet
                   : mode == "continuous" ? GovernorMode::continuous
                                          : GovernorMode::none;

  const TableReader body = root.table("body");
  declare(body, {"inertia"});
  sc.params.J = body.inertia("inertia");

  const TableReader control = root.table("control");
  declare(control, {"kp", "kd", "tau_max"});
  sc.params.gains.kp = control.number("kp", NumberRule::positive());
  sc.params.gains.kd = control.number("kd", NumberRule::positive());
  sc.params.tau_max = control.number("tau_max", NumberRule::positive());

  parse_erg_table(root, sc.params);

  if (root.has("cones")) {
    const std::vector<TableReader> cones = root.array_of_tables("cones");
    if (cones.size() > static_cast<std::size_t>(governor::kMaxCones)) {
      root.fail("cones", "at most " + std::to_string(governor::kMaxCones) +
                             " cone constraints (got " + std::to_string(cones.size()) + ")");
    }
    for (const TableReader& c : cones) {
      sc.cones.push_back(parse_cone(c));
    }
  }

  const TableReader desired = root.table("desired");
  sc.desired = parse_desired(desired, sc.cones);

  std::optional<TableReader> initial = root.optional_table("initial");
  if (initial) {
    declare(*initial, {"attitude", "omega_b", "reference"});
    if (initial->has("attitude")) {
      sc.R0_ib = initial->rotation("attitude");
    }
    if (initial->has("omega_b")) {
      sc.omega0_b = initial->vector3("omega_b");
    }
    sc.R_g0 = initial->has("reference") ? initial->rotation("reference") : sc.R0_ib;
  } else {
    sc.R_g0 = sc.R0_ib;
  }

  const TableReader simulation = root.table("simulation");
  declare(simulation, {"duration", "output_interval", "integrator", "step", "abs_tol", "rel_tol",
                       "max_step", "convergence_tolerance"});
  sc.duration = simulation.number("duration", NumberRule::positive());
  sc.output_interval = simulation.number_or("output_interval", 0.01, NumberRule::positive());
  sc.integrator = parse_integrator_settings(simulation);
  sc.convergence_tolerance =
      simulation.number_or("convergence_tolerance", 1e-4, NumberRule::positive());
  for (const auto& [key, value] : {std::pair<std::string_view, double>{"output_interval",
                                                                         sc.output_interval},
                                    {"step", sc.integrator.step}}) {
    if (value > sc.duration) {
      simulation.fail(key, std::string(simulation.has(key) ? "" : "the default ") +
                               "must be <= duration (" + num(sc.duration) + "), got " + num(value));
    }
  }
  root.finish();

  // Admissibility (PET-ERG paper, Theorem 1): R_g(0) inside every cone's field domain and
  // V(R_0, ω_0, R_g(0)) ≤ Γ(R_g(0)).
  std::optional<governor::AttitudeGovernor> gov;
  try {
    gov.emplace(sc.params, sc.cones);
  } catch (const std::invalid_argument& e) {
    root.fail_here(e.what());
  }
  const auto fail_initial = [&](std::string_view preferred, const std::string& message) {
    if (initial && initial->has(preferred)) {
      initial->fail(preferred, message);
    }
    if (initial && initial->has("attitude")) {
      initial->fail("attitude", message);
    }
    if (initial) {
      initial->fail_here(message);
    }
    root.fail_here(message + " ([initial] defaults to the identity attitude at rest)");
  };
  // The same checks for every mode: `governor = "none"` runs the very scenario the governor
  // would run, to show what the governor prevents.
  for (std::size_t i = 0; i < sc.cones.size(); ++i) {
    const double c = governor::cone_cosine(sc.cones[i], sc.R_g0);
    if (!(c > sc.cones[i].delta)) {
      fail_initial("reference", "initial reference R_g(0) is outside the navigation field's "
                                "domain of cones[" + std::to_string(i) + "] (a_c^T R_g a_b = " +
                                    num(c) + " <= delta = " + num(sc.cones[i].delta) + ")");
    }
  }
  const double V0 = gov->lyapunov(sc.R0_ib, sc.omega0_b, sc.R_g0);
  const double G0 = gov->gamma(sc.R_g0);
  if (V0 > G0) {
    fail_initial("omega_b", "initial state not admissible: V(0) = " + num(V0) +
                                " > Gamma(R_g(0)) = " + num(G0) + " (Gamma_d = " +
                                num(gov->gamma_d()) + ", Gamma_g = " + num(gov->gamma_g(sc.R_g0)) +
                                ")");
  }
  return sc;
}

}  // namespace attiguard::scenario
