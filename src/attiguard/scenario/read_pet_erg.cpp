// Scenario kind `pet_erg` (docs/scenario-format.md, section "pet_erg").

#include "attiguard/scenario/read_pet_erg.hpp"

#include "attiguard/sim/pet_erg_slew_problem.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/scenario/robust_margin_setup.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/ephemeris_check.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

using governor::ConeConstraint;
using governor::GovernorMode;
using lie::Mat3;
using lie::Vec3;



/// Rejects a desired attitude that violates a cone or lies in a cone's repulsive band.
void check_desired(const TableReader& t, std::string_view key, const Mat3& R_d,
                   std::span<const ConeConstraint> cones) {
  for (std::size_t i = 0; i < cones.size(); ++i) {
    const ConeConstraint& cone = cones[i];
    const double c = governor::cone_cosine(cone, R_d);
    const std::string which = "cones[" + std::to_string(i) + "]";
    if (c < cone.cos_theta_c) {
      t.fail(key, "desired attitude violates the pointing constraint " + which +
                      " (a_c^T R_d a_b = " + detail::format_number(c) + " < cos(theta_c) = " + detail::format_number(cone.cos_theta_c) +
                      ")");
    }
    if (c < cone.zeta) {
      t.fail(key, "desired attitude lies in the repulsive band of " + which + " (a_c^T R_d a_b = " +
                      detail::format_number(c) + " < zeta = " + detail::format_number(cone.zeta) +
                      "): the governed reference cannot converge to it; move R_d or reduce "
                      "delta_offset/zeta_offset");
    }
  }
}

/// [desired]: a constant R_d, or a schedule whose R_d is the initial attitude R0_ib before the
/// first entry's t (docs/scenario-format.md, "pet_erg").
governor::ReferenceSchedule parse_desired(const TableReader& t,
                                          std::span<const ConeConstraint> cones,
                                          const Mat3& R0_ib) {
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
      e.fail("t", "schedule times must increase strictly (previous t = " + detail::format_number(waypoints.back().t) +
                      ")");
    }
    w.R_d = e.rotation("attitude");
    check_desired(e, "attitude", w.R_d, cones);
    waypoints.push_back(w);
  }
  return governor::ReferenceSchedule(waypoints, interp, R0_ib);
}

/// Γ_d must be computable: gains and torque limit whose Γ_d over/underflows are refused at
/// control.tau_max (docs/pet-erg.md, "Torque threshold Γ_d", range check).
void check_torque_threshold(const TableReader& control, const governor::GovernorParams& params) {
  const double lambda_min =
      lie::lambda_min(params.J);
  if (!(lambda_min > 0.0)) return;  // the inertia reader has refused it already
  try {
    (void)governor::compute_torque_threshold(
        {params.gains.kp, params.gains.kd, lambda_min, params.tau_max});
  } catch (const SetupError& e) {
    control.fail("tau_max", e.what());
  }
}

/// The keys of the adversarial disturbance, and the keys it does not use refused with it
/// (docs/pet-erg.md, section 11, "Adversarial disturbance"; docs/scenario-format.md, "pet_erg").
void parse_adversary(const TableReader& t, dynamics::DisturbanceKind kind,
                     sim::AdversarySettings& adversary) {
  const bool adversarial = kind == dynamics::DisturbanceKind::adversarial;
  for (const std::string_view key : {"disturbance_axis_b", "disturbance_period"}) {
    t.used_only_if(key, !adversarial,
                   "not used by disturbance = \"adversarial\" (its direction is chosen from the "
                   "state at every update): remove it");
  }
  for (const std::string_view key : {"disturbance_update", "adversary_weight"}) {
    t.used_only_if(key, adversarial, "only used by disturbance = \"adversarial\"");
  }
  adversary.update = enum_or(t, "disturbance_update", sim::kDisturbanceUpdateNames,
                             sim::DisturbanceUpdate::control);
  adversary.weight = t.number_or("adversary_weight", 0.5, NumberRule::range(0.0, 1.0));
}

/// The disturbance keys of [imperfections] (docs/pet-erg.md, section 11): kind, bound (its rate
/// build-up over the duration, bound·T/λ_min(J), below the flight loop's Nyquist rate π/T_c:
/// docs/scenario-format.md, "Bounds of [imperfections]"), axis, period, and the adversary.
void parse_disturbance(const TableReader& t, double control_period, double duration, const Mat3& J,
                       std::uint64_t seed, sim::PetErgImperfections& im) {
  dynamics::DisturbanceTorque& d = im.disturbance;
  d.kind = enum_or(t, "disturbance", dynamics::kDisturbanceKindNames, dynamics::DisturbanceKind::none);
  d.bound = t.number_or("disturbance_bound", 0.0, NumberRule::non_negative());
  if (d.kind != dynamics::DisturbanceKind::none && !(d.bound > 0.0)) {
    t.fail(t.has("disturbance_bound") ? "disturbance_bound" : "disturbance",
           "a disturbance needs disturbance_bound > 0 [N m]");
  }
  const double nyquist = std::numbers::pi / control_period;
  const double lambda_min = lie::lambda_min(J);
  if (const double most = nyquist * lambda_min / duration; !(d.bound <= most)) {
    t.fail("disturbance_bound",
           "at most " + detail::format_number(most) + " N m, got " + detail::format_number(d.bound) +
               ": the rate it builds over the duration, disturbance_bound x duration / "
               "lambda_min(J), must stay below the flight loop's Nyquist rate pi/control_period = " +
               detail::format_number(nyquist) + " rad/s");
  }
  if (t.has("disturbance_axis_b")) d.axis_b = t.direction("disturbance_axis_b");
  d.period = t.number_or("disturbance_period", 100.0, NumberRule::positive());
  // A sinusoid the flight loop can resolve: at least two control periods (its Nyquist period;
  // a subnormal period made 2 pi t / P overflow to a NaN torque at the first step).
  if (const double least = 2.0 * control_period; !(d.period >= least)) {
    t.fail("disturbance_period", "at least 2 x control_period = " + detail::format_number(least) +
                                     " s (the shortest period the flight loop resolves, its Nyquist "
                                     "period), got " + detail::format_number(d.period));
  }
  d.hold = control_period;
  d.seed = seed;
  parse_adversary(t, d.kind, im.adversary);
}

/// Refuses at `key` an error of bias + noise that is not below `most` (docs/scenario-format.md,
/// "Bounds of [imperfections]"); `why` names the limit, with a parenthesised reason after it.
void refuse_error_bound(const TableReader& t, std::string_view key, double bias, double noise, double most,
                        std::string_view unit, std::string_view why) {
  if (bias + noise < most) return;
  const std::string_view what = key.ends_with("bound") ? "the bias bound + noise"
                                : key.ends_with("noise") ? "bias + noise" : "the bias";
  const std::size_t note = why.find(" (");
  t.fail(key, std::string(what) + " must stay below " + std::string(why.substr(0, note)) + " = " +
                  detail::format_number(most) + " " + std::string(unit) +
                  (note == std::string_view::npos ? "" : std::string(why.substr(note))) + ", got " +
                  detail::format_number(bias + noise));
}

constexpr double kMaxAttitudeError = 0.5 * std::numbers::pi;
constexpr std::string_view kAttitudeWhy = "pi/2 (beyond it the measured attitude may lie in the "
                                          "other hemisphere)";
constexpr std::string_view kRateWhy = "the flight loop's Nyquist rate pi/control_period";

/// The sensor keys of [imperfections] and the bias bounds the robust margins assume (docs/pet-erg.md,
/// sections 11 and 13): attitude errors below π/2, rate errors below the Nyquist rate, each
/// bound at least its bias's norm (norms without overflow, stableNorm, each compared with its
/// limit before any is combined).
void parse_sensor(const TableReader& t, double nyquist, std::uint64_t seed, sim::PetErgImperfections& im) {
  dynamics::AttitudeSensor& s = im.sensor;
  if (t.has("attitude_bias")) s.attitude_bias_b = t.vector3("attitude_bias");
  s.attitude_noise = t.number_or("attitude_noise", 0.0, NumberRule::non_negative());
  if (t.has("rate_bias")) s.rate_bias_b = t.vector3("rate_bias");
  s.rate_noise = t.number_or("rate_noise", 0.0, NumberRule::non_negative());
  s.seed = seed;
  const double attitude_bias = s.attitude_bias_b.stableNorm();
  const double rate_bias = s.rate_bias_b.stableNorm();
  refuse_error_bound(t, t.has("attitude_bias") || !t.has("attitude_noise") ? "attitude_bias" : "attitude_noise",
                     attitude_bias, 0.0, kMaxAttitudeError, "rad", kAttitudeWhy);
  if (t.has("attitude_noise")) {
    refuse_error_bound(t, "attitude_noise", attitude_bias, s.attitude_noise, kMaxAttitudeError, "rad", kAttitudeWhy);
  }
  refuse_error_bound(t, "rate_bias", rate_bias, 0.0, nyquist, "rad/s", kRateWhy);
  refuse_error_bound(t, "rate_noise", rate_bias, s.rate_noise, nyquist, "rad/s", kRateWhy);
  im.attitude_bias_bound = t.number_or("attitude_bias_bound", DerivedDefault{attitude_bias}, NumberRule::non_negative());
  if (im.attitude_bias_bound < attitude_bias) {
    t.fail("attitude_bias_bound", "below the norm of attitude_bias, " + detail::format_number(attitude_bias) + " rad");
  }
  if (t.has("attitude_bias_bound")) {
    refuse_error_bound(t, "attitude_bias_bound", im.attitude_bias_bound, s.attitude_noise, kMaxAttitudeError, "rad",
                       kAttitudeWhy);
  }
  im.rate_bias_bound = t.number_or("rate_bias_bound", DerivedDefault{rate_bias}, NumberRule::non_negative());
  if (im.rate_bias_bound < rate_bias) {
    t.fail("rate_bias_bound", "below the norm of rate_bias, " + detail::format_number(rate_bias) + " rad/s");
  }
  if (t.has("rate_bias_bound")) {
    refuse_error_bound(t, "rate_bias_bound", im.rate_bias_bound, s.rate_noise, nyquist, "rad/s", kRateWhy);
  }
}

/// [imperfections] (docs/pet-erg.md, section 11; docs/scenario-format.md, "pet_erg"): only for
/// the flight loop (control_period > 0). Every magnitude is bounded where it enters
/// (docs/scenario-format.md, "pet_erg", "Bounds of [imperfections]"): rate errors below the
/// flight loop's Nyquist rate pi/control_period, attitude errors below pi/2, the disturbance's
/// rate build-up over the duration below the Nyquist rate, the sinusoid's period at least
/// 2 control_period, the torque quantum at least tau_max 2^-52 (tau/q an exact integer).
sim::PetErgImperfections parse_imperfections(const TableReader& t, double control_period,
                                             double duration, const Mat3& J, double tau_max) {
  declare(t, {"disturbance", "disturbance_bound", "disturbance_axis_b", "disturbance_period",
              "disturbance_update", "adversary_weight", "attitude_bias", "attitude_noise",
              "rate_bias", "rate_noise", "delay_periods", "torque_quantum", "seed",
              "attitude_bias_bound", "rate_bias_bound"});
  if (!(control_period > 0.0)) {
    t.fail_here("imperfections act on the flight loop: set [control] control_period > 0");
  }
  sim::PetErgImperfections im;
  const auto seed = static_cast<std::uint64_t>(t.integer_or("seed", 0, 0, 1L << 62));
  parse_disturbance(t, control_period, duration, J, seed, im);
  parse_sensor(t, std::numbers::pi / control_period, seed, im);
  im.delay_periods = static_cast<int>(t.integer_or("delay_periods", 0, 0, 1));
  im.torque_quantum = t.number_or("torque_quantum", 0.0, NumberRule::non_negative());
  // τ/q must be an exact integer of double precision for |τ| ≤ τ_max: q ≥ τ_max 2^-52.
  if (const double least = std::ldexp(tau_max, -52);
      im.torque_quantum > 0.0 && im.torque_quantum < least) {
    t.fail("torque_quantum", "0 (no quantisation) or at least tau_max x 2^-52 = " +
                                 detail::format_number(least) + " N m (tau/torque_quantum must be "
                                 "an exact integer in double precision), got " +
                                 detail::format_number(im.torque_quantum));
  }
  return im;
}

/// [[wheels]] (docs/pet-erg.md, section 12): the array; the refusals of its polytope
/// (governor::wheel_polytope: the flight loop it needs, an array that does not span, a Γ_d that
/// cannot be computed) located at the first [[wheels]] table.
void parse_wheels(const TableReader& root, sim::PetErgScenario& sc) {
  if (!root.has("wheels")) return;
  const std::vector<TableReader> entries = root.array_of_tables("wheels");
  for (const TableReader& e : entries) {
    declare(e, {"axis_b", "torque_max", "momentum_max", "momentum"});
    dynamics::ReactionWheel w;
    w.axis_b = e.direction("axis_b");
    w.torque_max = e.number("torque_max", NumberRule::positive());
    w.momentum_max = e.number("momentum_max", NumberRule::positive());
    w.momentum0 = e.number_or("momentum", 0.0, NumberRule{});
    if (std::abs(w.momentum0) > w.momentum_max) {
      e.fail("momentum", "initial wheel momentum exceeds momentum_max = " + detail::format_number(w.momentum_max));
    }
    sc.wheels.push_back(w);
  }
}

/// The refusals of the wheel polytope (governor::wheel_polytope: the flight loop it needs, an
/// array that does not span, a Γ_d that cannot be computed) located at the first [[wheels]]
/// table; after the gains are known.
void check_wheel_polytope(const TableReader& root, const sim::PetErgScenario& sc) {
  if (sc.wheels.empty()) return;
  try {
    (void)governor::wheel_polytope(sim::design_inputs(sc));
  } catch (const SetupError& e) {
    root.array_of_tables("wheels").front().fail_here(e.what());
  }
}

/// The derived values in the resolved scenario (docs/conventions.md, "Outputs"), replacing the
/// constants [erg]'s reader recorded for its absent keys.
void record_derived_values(const governor::DerivedGovernorValues& d) {
  const std::pair<const char*, std::pair<bool, double>> values[] = {
      {"control.kp", {d.kp_derived, d.kp}},         {"control.kd", {d.kd_derived, d.kd}},
      {"erg.kappa", {d.kappa_derived, d.kappa}},    {"erg.sampling_period", {d.Ts_derived, d.Ts}},
      {"erg.c_gamma", {d.c_gamma_derived, d.c_gamma}}, {"erg.epsilon", {d.epsilon_derived, d.epsilon}}};
  for (const auto& [path, value] : values) {
    if (value.first) DefaultsRecorder::replace_derived(path, value.second);
  }
}

/// With robust margins: Γ_min/((1 − δ)Γ_d') of the design of `sc` (docs/pet-erg.md, section 8,
/// "Robust margins"); +∞ when the design refuses the values, 0 without robust margins.
double robust_margin_ratio(const sim::PetErgScenario& sc) {
  try {
    const governor::GovernorDesign design = sim::design_governor(sc);
    if (!design.params.robust) return 0.0;
    const governor::AttitudeGovernor gov(design.params, design.cones);
    const governor::RobustMargin& m = *design.params.robust;
    const double ratio = m.gamma_min / ((1.0 - m.delta) * gov.gamma_d());
    return std::isfinite(ratio) ? ratio : std::numeric_limits<double>::infinity();
  } catch (const SetupError&) {
    return std::numeric_limits<double>::infinity();
  }
}

/// The softenings of θ_ref tried for the robust margins, in order: softer first (a smaller k_p
/// lowers the hold error k_d h ω̇), then stiffer (a larger k_d dominates the wheels' and the
/// body's gyroscopic coupling in the strict Lyapunov function).
/// (1, the unscaled loop, is tried first by the caller.)
constexpr std::array<double, 12> kSoftenings{2.0, 4.0, 8.0, 16.0, 64.0, 256.0,
                                             0.5, 0.25, 0.125, 1.0 / 16.0, 1.0 / 64.0, 1.0 / 256.0};

/// k_p, k_d, κ, T_s, c_Γ, ε: the file's, or derived from the craft (docs/pet-erg.md, section 8).
/// With robust margins and k_p derived, the first softening of θ_ref whose design leaves room
/// (Γ_min ≤ robust_share·(1 − δ)Γ_d') is taken, else the one with the most room, else none (the
/// design's refusal then names the bound at fault). A derivation that fails is located at
/// control.tau_max. `planned`: governor = "planned", whose values are derived again at set-up
/// (docs/pet-erg.md, section 16.2), so none is recorded for the resolved scenario.
void derive_governor_values(const TableReader& root, const TableReader& control,
                            sim::PetErgScenario& sc, bool planned) {
  const governor::GivenGovernorValues given = given_governor_values(root, sc.params);
  governor::CraftScales craft = sim::craft_scales(sc);
  const auto derive = [&](double softening) {
    craft.softening = softening;
    try {
      sc.derived = governor::derive_governor_values(craft, given);
    } catch (const SetupError& e) {
      control.fail("tau_max", e.what());
    }
    apply_governor_values(sc.derived, sc.params);
  };
  derive(1.0);
  if (sc.margins == governor::Margins::robust && !given.kp) {
    double best = 1.0;
    double best_ratio = robust_margin_ratio(sc);
    for (const double softening : kSoftenings) {
      if (best_ratio <= governor::DefaultGainConstants{}.robust_share) break;
      derive(softening);
      const double ratio = robust_margin_ratio(sc);
      if (ratio < best_ratio) {
        best = softening;
        best_ratio = ratio;
      }
    }
    if (!(best_ratio < 1.0)) best = 1.0;
    if (best != craft.softening) derive(best);
  }
  // The planned mode derives its gains and step again at set-up from the plan (docs/pet-erg.md,
  // section 16.2): the PD hold's values are not written into a resolved scenario.
  if (!planned) record_derived_values(sc.derived);
  const TableReader simulation = root.table("simulation");
  if (!simulation.has("step")) {
    sc.derived.integrator_step_derived = true;
    sc.derived.integrator_step = std::min(sc.derived.integrator_step, 0.1 * sc.duration);
    sc.integrator.step = sc.derived.integrator_step;
    if (planned) {
      DefaultsRecorder::record_unused("simulation.step");  // derived again at set-up
    } else {
      DefaultsRecorder::replace_derived("simulation.step", sc.integrator.step);
    }
    require_step_budget(simulation, sc.integrator, sc.duration);
  }
}

/// The governor block, `margins`, `control_period` of [control] (docs/scenario-format.md,
/// "pet_erg"); returns the [control] reader.
TableReader parse_control(const TableReader& root, sim::PetErgScenario& sc) {
  const TableReader control = parse_governor_block(
      root, sc.params, {"control_period", "margins", "robust_reference_step"}, Gains::derived_when_absent);
  sc.margins = enum_or(control, "margins", governor::kMarginsNames, governor::Margins::nominal);
  control.used_only_if("robust_reference_step", sc.margins == governor::Margins::robust,
                       "only with margins = \"robust\"");
  sc.control_period = control.number_or("control_period", 0.0, NumberRule::non_negative());
  if (sc.params.mode == GovernorMode::planned && sc.margins == governor::Margins::robust) {
    if (!(sc.control_period > 0.0)) {
      control.fail("margins", "robust margins of the planned mode need the flight loop: set "
                              "[control] control_period > 0 (docs/pet-erg.md, section 16.3)");
    }
    control.used_only_if("robust_reference_step", false,
                         "the planned mode has no reference steps: its robust margins size the plan "
                         "(docs/pet-erg.md, section 16.3)");
  }
  return control;
}

/// governor = "planned" (docs/pet-erg.md, section 16.2): one rest-to-rest slew, refused at its
/// key otherwise; the [erg] table is the PET-ERG's and is not used.
void check_planned(const TableReader& root, const sim::PetErgScenario& sc) {
  if (sc.params.mode != GovernorMode::planned) return;
  if (root.has("erg")) {
    root.fail("erg", "[erg] sets the PET-ERG's reference governor; governor = \"planned\" does not "
                     "use it (remove it, or set governor = \"pet\")");
  }
  if (const auto refusal = sim::slew_refusal(sc, sim::SlewStart::any_rate)) {
    const TableReader table = root.table(refusal->table);
    if (table.has(refusal->key)) table.fail(refusal->key, "governor = \"planned\": " + refusal->message);
    table.fail_here("governor = \"planned\": " + refusal->message);
  }
}

/// [initial] (docs/scenario-format.md, "pet_erg"): attitude, omega_b, reference (default the
/// attitude). Returns its reader when the table is there.
std::optional<TableReader> parse_initial(const TableReader& root, sim::PetErgScenario& sc) {
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
  return initial;
}

/// [simulation] (docs/scenario-format.md, "pet_erg"): duration, outputs, integrator, tolerance,
/// and the budgets of steps and rows.
void parse_simulation(const TableReader& root, sim::PetErgScenario& sc) {
  const TableReader simulation = root.table("simulation");
  declare(simulation, {"duration", "output_interval", "integrator", "step", "abs_tol", "rel_tol",
                       "max_step", "convergence_tolerance"});
  const SimulationTimes times = read_simulation_times(root, simulation, 0.01);
  sc.duration = times.duration;
  sc.output_interval = times.output_interval;
  sc.integrator = times.integrator;
  sc.convergence_tolerance =
      simulation.number_or("convergence_tolerance", 1e-4, NumberRule::positive());
  require_at_most_duration(simulation, "output_interval", sc.output_interval, sc.duration);
  if (simulation.has("step")) {  // else derived from the craft (derive_governor_values)
    require_at_most_duration(simulation, "step", sc.integrator.step, sc.duration);
    require_step_budget(simulation, sc.integrator, sc.duration);
  }
  require_countable(simulation, "output_interval", sc.output_interval, sc.duration, kMaxOutputRows,
                    "output rows");
}

/// The control steps and governor samples of the run within the step budget.
void check_step_counts(const TableReader& root, const TableReader& control, const sim::PetErgScenario& sc) {
  if (sc.control_period > 0.0) {
    require_at_most_duration(control, "control_period", sc.control_period, sc.duration);
    require_countable(control, "control_period", sc.control_period, sc.duration, kMaxRunSteps,
                      "control steps");
  }
  if (sc.params.mode == GovernorMode::pet) {  // [erg] given or left out (its default T_s)
    require_countable(root.table_or_empty("erg"), "sampling_period", sc.params.Ts, sc.duration,
                      kMaxRunSteps, "governor samples");
  }
}

/// The tables the admissibility checks locate their refusals at.
struct AdmissibilityTables {
  const TableReader& root;
  const std::optional<TableReader>& initial;
  const TableReader& desired;
};

/// Admissibility [PET-ERG Thm. 1]: R_g(0) inside every cone's field domain and
/// V(R_0, ω_0, R_g(0)) ≤ Γ(R_g(0)); with robust margins the targets and the start of
/// docs/pet-erg.md, section 13. The same checks for every mode: `governor = "none"` runs the very
/// scenario the governor would run, to show what the governor prevents.
void check_admissible(const AdmissibilityTables& t, const sim::PetErgScenario& sc,
                      const governor::GovernorDesign& design) {
  const TableReader& root = t.root;
  const std::optional<TableReader>& initial = t.initial;
  const governor::AttitudeGovernor gov = make_governor(root, "", design.params, design.cones);
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
  for (std::size_t i = 0; i < sc.cones.size(); ++i) {
    const double c = governor::cone_cosine(sc.cones[i], sc.R_g0);
    if (!(c > sc.cones[i].delta)) {
      fail_initial("reference", cone_domain_message(root, i, sc.cones[i], c, initial && initial->has("reference")));
    }
  }
  if (design.params.robust) {
    check_robust_desired(t.desired, gov, sc, design);
    if (const std::string problem = robust_initial_problem(gov, sc, *design.params.robust); !problem.empty()) {
      fail_initial("omega_b", problem);
    }
    return;
  }
  const double V0 = gov.lyapunov(sc.R0_ib, sc.omega0_b, sc.R_g0);
  const double G0 = gov.gamma(sc.R_g0);
  if (V0 > G0) {
    fail_initial("omega_b", "initial state not admissible: V(0) = " + detail::format_number(V0) +
                                " > Gamma(R_g(0)) = " + detail::format_number(G0) + " (Gamma_d = " +
                                detail::format_number(gov.gamma_d()) + ", Gamma_g = " + detail::format_number(gov.gamma_g(sc.R_g0)) +
                                ")");
  }
}

/// `[plan]` (docs/slew-planner.md, "Options"; docs/scenario-format.md, "pet_erg"): read only when
/// present, so that a scenario without it resolves as before.
void parse_plan(const TableReader& root, sim::PetErgScenario& sc) {
  const std::optional<TableReader> plan = root.optional_table("plan");
  if (!plan) return;
  declare(*plan, {"torque_headroom", "cone_margin_deg", "intervals"});
  // Read only when given (no recorded default): the planned mode derives the two when left out
  // (docs/pet-erg.md, section 16.2), and a resolved scenario must derive them again.
  sc.plan.torque_headroom_given = plan->has("torque_headroom");
  if (sc.plan.torque_headroom_given) {
    sc.plan.torque_headroom = plan->number("torque_headroom", {0.0, 1.0, false, true});
  }
  sc.plan.cone_margin_given = plan->has("cone_margin_deg");
  if (sc.plan.cone_margin_given) {
    sc.plan.cone_margin =
        plan->number("cone_margin_deg", {0.0, 90.0, false, true}) * std::numbers::pi / 180.0;
  }
  sc.plan.intervals = static_cast<int>(plan->integer_or("intervals", 0, 0, 2000));
  if (sc.plan.intervals != 0 && sc.plan.intervals < 4) {
    plan->fail("intervals", "must be 0 (derived) or at least 4");
  }
}

/// Which checks of the governor's admissibility a pet_erg document gets.
enum class PetErgChecks { run, plan };

sim::PetErgScenario parse_pet_erg_with(const Document& doc, PetErgChecks checks) {
  sim::PetErgScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "governor", "body", "initial", "desired",
                 "control", "erg", "cones", "simulation", "imperfections", "wheels", "tune",
                 "plan"});
  sc.name = read_header(root, doc, "pet_erg");
  check_ephemeris_table(root);  // AEM export metadata (docs/interop.md)
  const TableReader control = parse_control(root, sc);

  const TableReader body = root.table("body");
  declare(body, {"inertia"});
  sc.params.J = body.inertia("inertia");

  sc.cones = parse_cones(root);
  const std::optional<TableReader> initial = parse_initial(root, sc);
  const TableReader desired = root.table("desired");
  sc.desired = parse_desired(desired,
                             checks == PetErgChecks::run ? std::span<const ConeConstraint>(sc.cones)
                                                         : std::span<const ConeConstraint>(),
                             sc.R0_ib);
  parse_simulation(root, sc);
  if (const std::optional<TableReader> im = root.optional_table("imperfections")) {
    sc.imperfections =
        parse_imperfections(*im, sc.control_period, sc.duration, sc.params.J, sc.params.tau_max);
  }
  parse_wheels(root, sc);
  // The reference step cap bounds the lag of a delayed command only (docs/pet-erg.md, section 13).
  control.used_only_if("robust_reference_step", sc.imperfections.delay_periods > 0,
                       "only used with [imperfections] delay_periods = 1 (it caps the reference "
                       "lag of a delayed command; without the delay there is none)");
  if (sc.margins == governor::Margins::robust && sc.imperfections.delay_periods > 0) {
    sc.robust_reference_step = control.number_or("robust_reference_step", 0.0, NumberRule::positive());
  }
  parse_plan(root, sc);
  check_planned(root, sc);
  // The planned mode ends in the PD hold: its thresholds and admissibility are those of mode
  // none (the start at rest outside every cone); the mode is set back below.
  const bool planned = sc.params.mode == GovernorMode::planned;
  // Its robust margins are those of section 16.3 (sim/planned_robust_design), computed with the
  // plan; the PD hold's design stays nominal.
  const governor::Margins margins = sc.margins;
  if (planned) {
    sc.params.mode = GovernorMode::none;
    sc.margins = governor::Margins::nominal;
  }
  derive_governor_values(root, control, sc, planned);
  check_torque_threshold(control, sc.params);
  check_wheel_polytope(root, sc);
  const governor::GovernorDesign design = located_design(control, sc);
  check_step_counts(root, control, sc);
  root.finish();
  if (checks == PetErgChecks::run) check_admissible({root, initial, desired}, sc, design);
  if (planned) {
    sc.params.mode = GovernorMode::planned;
    sc.margins = margins;
  }
  return sc;
}

}  // namespace

sim::PetErgScenario parse_pet_erg(const Document& doc) {
  return parse_pet_erg_with(doc, PetErgChecks::run);
}

sim::PetErgScenario parse_pet_erg_slew(const Document& doc) {
  return parse_pet_erg_with(doc, PetErgChecks::plan);
}

}  // namespace attiguard::scenario
