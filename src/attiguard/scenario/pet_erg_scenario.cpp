// Scenario kind `pet_erg` (docs/scenario-format.md, section "pet_erg").

#include "attiguard/scenario/pet_erg_scenario.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <utility>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

using governor::ConeConstraint;
using governor::GovernorMode;
using lie::Mat3;
using lie::Vec3;

std::string num(double x) { return detail::format_number(x); }


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
  const governor::Interpolation interp =
      enum_or(t, "interpolation", governor::kInterpolationNames, governor::Interpolation::hold);
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
  return governor::ReferenceSchedule(waypoints, interp);
}

}  // namespace

sim::PetErgScenario parse_pet_erg(const Document& doc) {
  sim::PetErgScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "governor", "body", "initial", "desired",
                 "control", "erg", "cones", "simulation"});
  sc.name = read_header(root, doc, "pet_erg");
  (void)parse_governor_block(root, sc.params);

  const TableReader body = root.table("body");
  declare(body, {"inertia"});
  sc.params.J = body.inertia("inertia");

  sc.cones = parse_cones(root);

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
  require_at_most_duration(simulation, "output_interval", sc.output_interval, sc.duration);
  require_at_most_duration(simulation, "step", sc.integrator.step, sc.duration);
  require_step_budget(simulation, sc.integrator, sc.duration);
  require_countable(simulation, "output_interval", sc.output_interval, sc.duration, kMaxOutputRows,
                    "output rows");
  if (const std::optional<TableReader> erg = root.optional_table("erg");
      erg && sc.params.mode == GovernorMode::pet) {
    require_countable(*erg, "sampling_period", sc.params.Ts, sc.duration, kMaxRunSteps,
                      "governor samples");
  }
  root.finish();

  // Admissibility (PET-ERG paper, Theorem 1): R_g(0) inside every cone's field domain and
  // V(R_0, ω_0, R_g(0)) ≤ Γ(R_g(0)).
  const governor::AttitudeGovernor gov = make_governor(root, "", sc.params, sc.cones);
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
      fail_initial("reference", cone_domain_message(root, i, sc.cones[i], c, initial && initial->has("reference")));
    }
  }
  const double V0 = gov.lyapunov(sc.R0_ib, sc.omega0_b, sc.R_g0);
  const double G0 = gov.gamma(sc.R_g0);
  if (V0 > G0) {
    fail_initial("omega_b", "initial state not admissible: V(0) = " + num(V0) +
                                " > Gamma(R_g(0)) = " + num(G0) + " (Gamma_d = " +
                                num(gov.gamma_d()) + ", Gamma_g = " + num(gov.gamma_g(sc.R_g0)) +
                                ")");
  }
  return sc;
}

}  // namespace attiguard::scenario
