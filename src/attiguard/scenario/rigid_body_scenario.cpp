// Scenario kind `rigid_body` (docs/scenario-format.md, section "Kind rigid_body") and the
// integrator keys shared by every kind (section "Integrator keys").

#include "attiguard/scenario/rigid_body_scenario.hpp"

#include <array>
#include <initializer_list>

#include "attiguard/scenario/messages.hpp"

namespace attiguard::scenario {

namespace {

/// Declares the keys a table may hold before any is read (TableReader::has), so that a typo of a
/// required key is reported as that typo rather than as a different key missing.
void declare(const TableReader& table, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) {
    (void)table.has(key);
  }
}

/// Rejects `key` (present or defaulted) when its value exceeds the duration.
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

}  // namespace

integrate::IntegratorSettings parse_integrator_settings(const TableReader& simulation) {
  static constexpr std::array<std::string_view, 2> methods{"rkmk4", "rkmk_dp54"};
  integrate::IntegratorSettings settings;
  const std::string method = simulation.string_or("integrator", "rkmk4", methods);
  settings.method = method == "rkmk_dp54" ? integrate::Method::rkmk_dp54 : integrate::Method::rkmk4;
  settings.step = simulation.number_or("step", settings.step, NumberRule::positive());
  settings.abs_tol = simulation.number_or("abs_tol", settings.abs_tol, NumberRule::positive());
  settings.rel_tol = simulation.number_or("rel_tol", settings.rel_tol, NumberRule::positive());
  settings.max_step =
      simulation.number_or("max_step", settings.max_step, NumberRule::non_negative());
  return settings;
}

RigidBodyScenario parse_rigid_body(const Document& doc) {
  RigidBodyScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "body", "initial", "control", "simulation"});

  const std::string kind = root.string("kind");
  if (kind != "rigid_body") {
    root.fail("kind", "expected \"rigid_body\", got " + detail::quoted(kind, '"'));
  }
  std::string stem = doc.path.stem().string();
  sc.name = root.string_or("name", stem.empty() ? "scenario" : stem);
  if (sc.name.empty()) {
    root.fail("name", "must not be empty");
  }
  (void)root.string_or("description", "");

  const TableReader body = root.table("body");
  declare(body, {"inertia"});
  sc.J = body.inertia("inertia");

  if (const auto initial = root.optional_table("initial")) {
    declare(*initial, {"attitude", "omega_b"});
    if (initial->has("attitude")) {
      sc.R0_ib = initial->rotation("attitude");
    }
    if (initial->has("omega_b")) {
      sc.omega0_b = initial->vector3("omega_b");
    }
  }

  // Only the keys of the chosen law are read: the others are rejected as unknown by finish().
  static constexpr std::array<std::string_view, 3> laws{"free", "constant_torque", "pd"};
  const TableReader control = root.table("control");
  const std::string law = control.string("law", laws);
  if (law == "pd") {
    sc.law = TorqueLaw::pd;
    declare(control, {"kp", "kd", "reference"});
    sc.kp = control.number("kp", NumberRule::positive());
    sc.kd = control.number("kd", NumberRule::positive());
    sc.R_ref_ib = control.rotation("reference");
  } else if (law == "constant_torque") {
    sc.law = TorqueLaw::constant_torque;
    sc.torque_b = control.vector3("torque_b");
  } else {
    sc.law = TorqueLaw::free;
  }

  const TableReader simulation = root.table("simulation");
  declare(simulation,
          {"duration", "output_interval", "integrator", "step", "abs_tol", "rel_tol", "max_step"});
  sc.duration = simulation.number("duration", NumberRule::positive());
  sc.output_interval = simulation.number_or("output_interval", 0.01, NumberRule::positive());
  sc.integrator = parse_integrator_settings(simulation);
  require_at_most_duration(simulation, "output_interval", sc.output_interval, sc.duration);
  require_at_most_duration(simulation, "step", sc.integrator.step, sc.duration);

  root.finish();
  return sc;
}

}  // namespace attiguard::scenario
