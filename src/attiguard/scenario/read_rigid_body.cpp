// Scenario kind `rigid_body` (docs/scenario-format.md, section "Kind rigid_body").

#include "attiguard/scenario/read_rigid_body.hpp"

#include <array>
#include <initializer_list>

#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/ephemeris_check.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

sim::RigidBodyScenario parse_rigid_body(const Document& doc) {
  using sim::TorqueLaw;
  sim::RigidBodyScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "body", "initial", "control", "simulation"});

  sc.name = read_header(root, doc, "rigid_body");
  check_ephemeris_table(root);  // AEM export metadata (docs/interop.md)

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
  const TableReader control = root.table("control");
  sc.law = enum_required(control, "law", sim::kTorqueLawNames);
  if (sc.law == TorqueLaw::pd) {
    declare(control, {"kp", "kd", "reference"});
    sc.kp = control.number("kp", NumberRule::positive());
    sc.kd = control.number("kd", NumberRule::positive());
    sc.R_ref_ib = control.rotation("reference");
  } else if (sc.law == TorqueLaw::constant_torque) {
    sc.torque_b = control.vector3("torque_b");
  }

  const TableReader simulation = root.table("simulation");
  declare(simulation,
          {"duration", "output_interval", "integrator", "step", "abs_tol", "rel_tol", "max_step"});
  const SimulationTimes times = read_simulation_times(root, simulation, 0.01);
  sc.duration = times.duration;
  sc.output_interval = times.output_interval;
  sc.integrator = times.integrator;
  require_at_most_duration(simulation, "output_interval", sc.output_interval, sc.duration);
  require_step_budget(simulation, sc.integrator, sc.duration);
  require_countable(simulation, "output_interval", sc.output_interval, sc.duration, kMaxOutputRows,
                    "output rows");
  require_at_most_duration(simulation, "step", sc.integrator.step, sc.duration);

  root.finish();
  return sc;
}

}  // namespace attiguard::scenario
