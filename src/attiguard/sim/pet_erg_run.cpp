#include "attiguard/sim/pet_erg_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "attiguard/core/four_digits.hpp"
#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/adversarial_disturbance.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/sim/cone_json.hpp"
#include "attiguard/sim/derived_values_json.hpp"
#include "attiguard/sim/held_actuation.hpp"
#include "attiguard/sim/pet_erg_loop.hpp"
#include "attiguard/sim/planned_run.hpp"
#include "attiguard/sim/time_grid.hpp"

namespace attiguard::sim {

namespace {

using governor::GovernorMode;
using governor::GovernorOutput;
using lie::Mat3;
using lie::Vec3;
using namespace pet_erg_loop;  // NOLINT: the loop's parts (sim/pet_erg_loop.hpp)

/// control_period = 0: (R, R_g, ω) integrated as one ODE, R_g by [PET-ERG eq. (4)] or (6) (PET-ERG paper).
PetErgResult simulate_continuous_time(const PetErgScenario& sc, const PetErgRowObserver& on_output) {
  governor::GovernorDesign design = design_governor(sc);
  const governor::AttitudeGovernor gov(design.params, sc.cones);
  const dynamics::RigidBody body(sc.params.J);
  PetErgResult r = initial_result(sc, std::move(design), gov);
  PetErgState y = pet_erg_initial_state(sc);
  bool flag = sc.params.mode == GovernorMode::continuous;
  // The saddle tie-break, sampled with the flag and held with it (docs/pet-erg.md, section 4).
  governor::TieBreak tie;
  // Γ_g, the cone cosines, τ and V of the monitor's state for the next step's first stage, and Γ_g
  // of a reference held over the stages (docs/performance.md, "Shared cone cosines").
  governor::GovernorMemo memo;

  auto field = [&](double t, const PetErgState& s) -> PetErgState::Tangent {
    const governor::GovernorRates out = gov.rates(s.R[0], s.x, s.R[1], sc.desired.at(t), flag, tie, memo);
    PetErgState::Tangent d;
    d.segment<3>(0) = s.x;
    d.segment<3>(3) = out.xi_g;
    d.segment<3>(6) = body.angular_acceleration(s.x, out.tau_b);  // [PET-ERG eq. (1)]
    return d;
  };
  // ρ_n and ξ only where a row is written; the figures folded at every step read neither.
  auto monitor = [&](double t, const PetErgState& s, bool row) -> GovernorOutput {
    const Mat3 R_d = sc.desired.at(t);
    const GovernorOutput out = row ? gov.evaluate(s.R[0], s.x, s.R[1], R_d, flag, tie)
                                   : gov.figures(s.R[0], s.x, s.R[1], R_d, flag, tie, memo);
    record(sc, r, t, R_d, s.R[0], out);
    return out;
  };
  auto sample = [&](double t, const PetErgState& s) {
    if (sc.params.mode == GovernorMode::pet) {
      flag = gov.trigger_condition(s.R[0], s.x, s.R[1]);
      ++r.samples;
      r.samples_updating += flag ? 1 : 0;
    }
    const governor::TieBreakUpdate u = gov.tie_break_update(tie, s.R[1], sc.desired.at(t));
    tie = u.state;
    if (u.started) note_tie_break(r, t, tie.cone);
  };

  // t = 0 is the first sampling instant t_0.
  sample(0.0, y);
  auto at_stop = [&](const Stop& stop, double t, PetErgState& s) {
    if (stop.sample) {
      sample(t, s);
    }
  };
  const integrate::IntegrationStats stats = integrate_over_stops(sc, field, y, monitor, at_stop, on_output);
  finish(sc, y, stats, r);
  return r;
}



/// control_period > 0: the flight loop. AttitudeGovernor::step runs at t_k = k·h with the state
/// of that instant and its torque is held until t_{k+1} (zero-order hold, HeldActuation); between
/// the instants only (R, ω) evolve under [PET-ERG eq. (1)], R_g is the governor's (docs/pet-erg.md, "Flight
/// loop", sections 11-13).
class PetErgFlightLoop {
 public:
  explicit PetErgFlightLoop(const PetErgScenario& sc) : PetErgFlightLoop(sc, design_governor(sc)) {}
  PetErgFlightLoop(const PetErgScenario& sc, governor::GovernorDesign design)
      : sc_(sc),
        // The governor of the flight loop (docs/pet-erg.md, sections 10 and 13): the bounded
        // reference step and, with robust margins, the reduced limits and tightened cones.
        gov_(design.params, design.cones),
        body_(sc.params.J),
        r_(initial_result(sc, std::move(design), gov_)),
        actuation_(sc.imperfections, sc.wheels),
        disturbance_(sc),
        // With robust margins the level W is that of the attitude seen through the bias, R B
        // (docs/pet-erg.md, section 13): the invariant the margins guarantee.
        bias_frame_(gov_.params().robust ? lie::exp(sc.imperfections.sensor.attitude_bias_b)
                                         : Mat3::Identity()) {}

  /// t = 0: the governor starts from R_g(0) and the first control instant acts.
  void start(PetErgState& y) {
    gov_.reset(0.0, sc_.R_g0);
    control(0.0, y);
  }

  /// From t = 0 to the end over the stop plan, the control instants at their stops.
  integrate::IntegrationStats fly(PetErgState& y, const PetErgRowObserver& on_output) {
    auto field = [this](double t, const PetErgState& s) { return this->field(t, s); };
    auto monitor = [this](double t, const PetErgState& s, bool row) { return this->monitor(t, s, row); };
    auto at_stop = [this](const Stop& stop, double t, PetErgState& s) {
      if (stop.control) {
        control(t, s);
      }
    };
    return integrate_over_stops(sc_, field, y, monitor, at_stop, on_output);
  }

  /// The figures of the run ending in y.
  PetErgResult figures(const PetErgState& y, const integrate::IntegrationStats& stats) {
    finish(sc_, y, stats, r_);
    finish_wheels(sc_, actuation_, r_);
    return std::move(r_);
  }

 private:
  /// Between control instants: (R, ω) under [PET-ERG eq. (1)] with the held torque, the disturbance d
  /// (docs/pet-erg.md, section 11) and the wheels' gyroscopic torque (A h) × ω (section 12).
  PetErgState::Tangent field(double t, const PetErgState& s) const {
    PetErgState::Tangent d;
    d.segment<3>(0) = s.x;
    d.segment<3>(3).setZero();  // R_g changes only at the control instants
    Vec3 tau = actuation_.torque_b() + disturbance_.at(t, s);
    if (actuation_.has_wheels()) tau += actuation_.momentum_b(t).cross(s.x);
    d.segment<3>(6) = body_.angular_acceleration(s.x, tau);
    return d;
  }

  /// The governor's view of the true state with the torque actually applied, the margins of the
  /// true constraints (with robust margins the governor enforces tightened cones); ρ_n and ξ only
  /// for a row.
  GovernorOutput view(const PetErgState& s, const Mat3& R_d, bool row) const {
    const Mat3 R_seen = s.R[0] * bias_frame_;
    GovernorOutput out = row ? gov_.evaluate(R_seen, s.x, s.R[1], R_d, gov_.trigger_flag(), gov_.tie_break())
                             : gov_.figures(R_seen, s.x, s.R[1], R_d, gov_.trigger_flag(), gov_.tie_break());
    out.tau_b = actuation_.torque_b();
    for (std::size_t i = 0; i < sc_.cones.size(); ++i) {
      out.margins[i] = governor::pointing_margin(sc_.cones[i], s.R[0]);
    }
    return out;
  }

  /// t = 0, every integrator step and every stop: the figures and the wheels' momenta (`row`:
  /// the output goes into a row).
  GovernorOutput monitor(double t, const PetErgState& s, bool row) {
    const Mat3 R_d = sc_.desired.at(t);
    const GovernorOutput out = view(s, R_d, row);
    record(sc_, r_, t, R_d, s.R[0], out);
    actuation_.observe_momenta(t);
    return out;
  }

  /// Control instant t: what the flight software computes and commands (HeldActuation), the
  /// governor's R_g into the state, the disturbance held, the sampling counted.
  void control(double t, PetErgState& s) {
    const GovernorOutput& out = actuation_.control(gov_, t, s.R[0], s.x, sc_.desired.at(t));
    s.R[1] = gov_.params().mode == GovernorMode::none ? sc_.desired.at(t) : gov_.reference();
    disturbance_.hold(s);
    if (out.sampled) {
      ++r_.samples;
      r_.samples_updating += out.trigger ? 1 : 0;
    }
    if (out.tie_break_started) note_tie_break(r_, t, out.tie_break.cone);
  }

  const PetErgScenario& sc_;
  governor::AttitudeGovernor gov_;
  const dynamics::RigidBody body_;
  PetErgResult r_;
  HeldActuation actuation_;
  PetErgPlantDisturbance disturbance_;
  const Mat3 bias_frame_;
};

/// control_period > 0: the flight loop of PetErgFlightLoop (docs/pet-erg.md, "Flight loop").
PetErgResult simulate_flight_loop(const PetErgScenario& sc, const PetErgRowObserver& on_output) {
  PetErgFlightLoop loop(sc);
  PetErgState y = pet_erg_initial_state(sc);
  loop.start(y);
  const integrate::IntegrationStats stats = loop.fly(y, on_output);
  return loop.figures(y, stats);
}

}  // namespace

PetErgResult simulate_pet_erg(const PetErgScenario& sc, const PetErgRowObserver& on_output) {
  if (sc.params.mode == GovernorMode::planned) return simulate_planned(sc, on_output);
  return sc.control_period > 0.0 ? simulate_flight_loop(sc, on_output)
                                 : simulate_continuous_time(sc, on_output);
}

namespace {

nlohmann::json finite_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

/// The [imperfections] of the run, echoed in summary.json (docs/pet-erg.md, section 11).
nlohmann::json imperfections_json(const PetErgImperfections& im) {
  nlohmann::json j = {{"disturbance", std::string(dynamics::kDisturbanceKindNames.name(im.disturbance.kind))},
                      {"disturbance_bound", im.disturbance.bound},
                      {"attitude_error_bound", im.sensor.attitude_error_bound()},
                      {"rate_error_bound", im.sensor.rate_error_bound()},
                      {"attitude_bias_bound", im.attitude_bias_bound},
                      {"rate_bias_bound", im.rate_bias_bound},
                      {"delay_periods", im.delay_periods},
                      {"torque_quantum", im.torque_quantum}};
  if (im.disturbance.kind == dynamics::DisturbanceKind::adversarial) {
    j["disturbance_update"] = std::string(kDisturbanceUpdateNames.name(im.adversary.update));
    j["adversary_weight"] = im.adversary.weight;
  }
  return j;
}

/// The robust margin of the run (docs/pet-erg.md, section 13), echoed in summary.json.
nlohmann::json robust_json(const PetErgScenario& sc, const PetErgResult& r) {
  const governor::GovernorDesign& design = r.design;
  const governor::RobustMargin& m = *design.params.robust;
  // The guarantee assumes the wheels' momenta within their limits (checked, not governed).
  const bool momentum_held = sc.wheels.empty() || r.max_wheel_momentum_ratio <= 1.0;
  return {{"assumption_wheel_momentum_within_limits", momentum_held},
          {"epsilon", m.epsilon},
          {"delta", m.delta},
          {"omega_max", m.omega_max},
          {"torque_error", m.torque_error},
          {"torque_error_parts",
           {{"disturbance", m.disturbance},
            {"sensors", m.sensor_error},
            {"quantisation", m.quantisation_error},
            {"hold", m.hold_error},
            {"reference_lag", m.reference_lag_error}}},
          {"command_error", m.command_error},
          {"tau_max_reduced", design.tau_max_reduced},
          {"wheel_gamma_d_reduced", sc.wheels.empty() ? nlohmann::json(nullptr) : nlohmann::json(design.wheel_gamma_d_reduced)},
          {"gamma_min", m.gamma_min},
          {"measurement_margin", m.measurement_margin},
          {"max_reference_step", std::isfinite(m.max_reference_step) ? nlohmann::json(m.max_reference_step) : nlohmann::json(nullptr)},
          {"start_allowance", m.start_allowance}};
}

/// Why a planned run did not converge (docs/pet-erg.md, section 16.2): the clock held short of
/// the plan's end, with the level and thresholds of the last choice, or the plan flown to its
/// end and the attitude not settled.
std::string planned_reason(const PlannedFigures& f, const std::string& error) {
  if (f.final_progress < f.plan.duration && f.final_rate > 0.0) {
    return "the run ended with the plan's clock still running (sigma = " + four_digits(f.final_progress) +
           " of " + four_digits(f.plan.duration) + " s, s_dot = " + four_digits(f.final_rate) +
           "): [simulation] duration is shorter than the plan; " + error;
  }
  if (f.final_progress < f.plan.duration) {
    return "the plan's clock stopped at sigma = " + four_digits(f.final_progress) + " of " +
           four_digits(f.plan.duration) + " s (held " + four_digits(f.time_held) +
           " s): the tracking error's level V = " + four_digits(f.last_V) +
           " leaves no rate within the thresholds (Gamma_g = " + four_digits(f.last_gamma_g) +
           ", torque bound " + four_digits(f.last_torque_bound) + " N m against tau_max " +
           four_digits(f.tau_max) + " N m); " + error;
  }
  return "the plan is flown to its end but the attitude has not settled within the tolerance "
         "(a disturbance, a sensor bias or slow damping); " + error;
}

/// One sentence with the numbers of a run that did not converge (docs/pet-erg.md, "Outcomes").
std::string outcome_reason(const PetErgScenario& sc, const PetErgResult& r) {
  const double left_deg = r.reference_distance_left * 180.0 / std::numbers::pi;
  const std::string error = "attitude error phi = " + four_digits(r.final_attitude_error) +
                            " > tolerance " + four_digits(sc.convergence_tolerance) + " at t = " +
                            four_digits(sc.duration) + " s";
  std::string cones;
  for (int i : r.active_cones) cones += (cones.empty() ? "" : ", ") + std::to_string(i);
  const std::string active =
      cones.empty() ? "no cone's repulsive band active" : "repulsive band of cones [" + cones + "] active";
  if (r.planned && r.outcome != PetErgOutcome::converged) return planned_reason(*r.planned, error);
  switch (r.outcome) {
    case PetErgOutcome::stalled:
      return "reference stopped " + four_digits(left_deg) + " deg short of R_d (moved " +
             four_digits(r.reference_motion.displacement() * 180.0 / std::numbers::pi) +
             " deg over the last half of the run, " + active + "); " + error;
    case PetErgOutcome::chattering:
      return "reference chatters: over the last half of the run it travelled " +
             four_digits(r.reference_motion.path_length() * 180.0 / std::numbers::pi) + " deg for a net " +
             four_digits(r.reference_motion.displacement() * 180.0 / std::numbers::pi) +
             " deg, reversing its direction " + std::to_string(r.reference_motion.reversals()) +
             " times (largest step " +
             four_digits(r.reference_motion.largest_move() * 180.0 / std::numbers::pi) +
             " deg); reduce kappa or the integrator step, or set control_period; " + error;
    case PetErgOutcome::not_converged_by_end:
      if (r.reference_distance_left <= std::acos(std::max(-1.0, 1.0 - sc.convergence_tolerance))) {
        return "reference at R_d (" + four_digits(left_deg) +
               " deg left) but the attitude has not settled within the tolerance (slow damping, "
               "a disturbance or a sensor bias); " + error;
      }
      return "still " + four_digits(left_deg) + " deg between reference and R_d (" + active + "); " + error;
    case PetErgOutcome::converged:
      break;
  }
  return {};
}

/// The run's settings: kind, name, governor, integrator, times, imperfections (docs/pet-erg.md,
/// section 11) and the kind of margins (section 13).
void add_run_settings(nlohmann::json& j, const PetErgScenario& sc) {
  j["kind"] = "pet_erg";
  j["name"] = sc.name;
  j["governor"] = std::string(governor::kGovernorModeNames.name(sc.params.mode));
  j["integrator"] = std::string(integrate::kMethodNames.name(sc.integrator.method));
  j["duration"] = sc.duration;
  j["control_period"] = sc.control_period;
  j["imperfections"] = imperfections_json(sc.imperfections);
  j["margins"] = std::string(governor::kMarginsNames.name(sc.margins));
}

/// The reaction wheels' figures (docs/pet-erg.md, section 12), with wheels only.
void add_wheels(nlohmann::json& j, const PetErgScenario& sc, const PetErgResult& r) {
  if (sc.wheels.empty()) return;
  j["wheels"] = static_cast<long>(sc.wheels.size());
  j["wheel_gamma_d"] = r.design.wheels.gamma_d;
  j["wheel_binding"] = r.design.wheels.binding;
  j["max_wheel_torque_ratio"] = r.max_wheel_torque_ratio;
  j["wheel_torque_limit_satisfied"] = r.max_wheel_torque_ratio <= 1.0;
  j["max_wheel_momentum_ratio"] = r.max_wheel_momentum_ratio;
  j["wheel_momentum_satisfied"] = r.max_wheel_momentum_ratio <= 1.0;
  j["final_wheel_momentum"] = r.final_wheel_momentum;
}

/// The gains and the governor's parameters [PET-ERG eqs. (3)-(6)] and the thresholds of the run
/// (docs/pet-erg.md, sections 2-3).
void add_governor_figures(nlohmann::json& j, const PetErgScenario& sc, const PetErgResult& r) {
  j["kp"] = sc.params.gains.kp;
  j["kd"] = sc.params.gains.kd;
  j["tau_max"] = sc.params.tau_max;
  j["kappa"] = sc.params.kappa;
  j["c_gamma"] = sc.params.c_gamma;
  j["sampling_period"] = sc.params.Ts;
  j["epsilon"] = sc.params.epsilon;
  j["epsilon_gamma"] = sc.params.epsilon_gamma;
  j["gamma_d"] = r.gamma_d;
  j["gamma_d_upper_bound"] = r.gamma_d_upper;
  j["gamma_d_loose"] = r.gamma_d_loose;
  j["gamma_cap"] = r.gamma_cap;
  j["gamma_g_initial"] = finite_or_null(r.gamma_g_initial);
  j["gamma_initial"] = r.gamma_initial;
  j["V_initial"] = r.V_initial;
  try {
    j["derived_defaults"] = derived_values_json(governor_values(sc));
  } catch (const SetupError&) {  // a scenario built in code with no torque left over its disturbance
    j["derived_defaults"] = nullptr;
  }
}

/// The constraints [PET-ERG eqs. (2a), (2b)], the wheels' limits and the level V − Γ.
void add_constraints(nlohmann::json& j, const PetErgScenario& sc, const PetErgResult& r) {
  j["max_torque_norm"] = r.max_torque_norm;
  const bool torque_ok = r.max_torque_norm <= sc.params.tau_max;
  j["torque_limit_satisfied"] = torque_ok;
  j["min_pointing_margin"] = finite_or_null(r.min_pointing_margin);
  nlohmann::json per_cone = nlohmann::json::array();
  for (double m : r.min_margin_per_cone) {
    per_cone.push_back(finite_or_null(m));
  }
  j["min_pointing_margin_per_cone"] = per_cone;
  const bool pointing_ok = !(r.min_pointing_margin < 0.0);
  j["pointing_constraints_satisfied"] = pointing_ok;
  j["first_pointing_violation_time"] =
      r.first_pointing_violation_time >= 0.0 ? nlohmann::json(r.first_pointing_violation_time)
                                             : nlohmann::json(nullptr);
  const bool wheels_ok = sc.wheels.empty() || (r.max_wheel_torque_ratio <= 1.0 &&
                                                r.max_wheel_momentum_ratio <= 1.0);
  j["constraints_satisfied"] = torque_ok && pointing_ok && wheels_ok;
  // With robust margins the level is W (docs/pet-erg.md, section 13), of the true state.
  // Planned mode with robust margins: the true errors' ratio to the proved peaks (section 16.3).
  j["lyapunov_level"] = sc.margins != governor::Margins::robust          ? "V"
                        : sc.params.mode == governor::GovernorMode::planned ? "error_ratio"
                                                                            : "W";
  j["max_V_minus_Gamma"] = r.max_V_minus_Gamma;
  j["V_below_Gamma"] = r.max_V_minus_Gamma <= 0.0;
}

/// The end of the run: final errors, convergence and the outcome (docs/pet-erg.md, "Outcomes").
void add_outcome(nlohmann::json& j, const PetErgScenario& sc, const PetErgResult& r) {
  j["final_attitude_error"] = r.final_attitude_error;
  j["final_reference_error"] = r.final_reference_error;
  j["final_omega_norm"] = r.final_omega_norm;
  j["convergence_tolerance"] = sc.convergence_tolerance;
  j["convergence_time"] =
      r.convergence_time >= 0.0 ? nlohmann::json(r.convergence_time) : nlohmann::json(nullptr);
  j["outcome"] = std::string(kPetErgOutcomeNames.name(r.outcome));
  if (r.outcome != PetErgOutcome::converged) j["outcome_reason"] = outcome_reason(sc, r);
  j["reference_distance_left"] = r.reference_distance_left;
  j["reference_moves_last_half"] = r.reference_motion.moves();
  j["reference_reversals_last_half"] = r.reference_motion.reversals();
  j["reference_path_last_half"] = r.reference_motion.path_length();
  j["active_cones"] = r.active_cones;
  // The saddle tie-breaks of the navigation field (docs/pet-erg.md, section 4).
  j["saddle_tie_breaks"] = r.saddle_tie_breaks;
  j["first_tie_break_time"] =
      r.first_tie_break_time >= 0.0 ? nlohmann::json(r.first_tie_break_time) : nlohmann::json(nullptr);
  j["tie_break_cones"] = r.tie_break_cones;
  j["slew_angle_deg"] = r.slew_angle * 180.0 / std::numbers::pi;
  j["eigenaxis_bang_bang_time"] = r.eigenaxis_bang_bang_time;
  j["convergence_time_over_bang_bang"] =
      r.convergence_time >= 0.0 && r.eigenaxis_bang_bang_time > 0.0
          ? nlohmann::json(r.convergence_time / r.eigenaxis_bang_bang_time)
          : nlohmann::json(nullptr);
  const bool wheels = r.wheel_bang_bang_time > 0.0;
  j["eigenaxis_bang_bang_time_wheels"] = wheels ? nlohmann::json(r.wheel_bang_bang_time) : nlohmann::json(nullptr);
  j["convergence_time_over_wheels_bang_bang"] = wheels && r.convergence_time >= 0.0
                                                    ? nlohmann::json(r.convergence_time / r.wheel_bang_bang_time)
                                                    : nlohmann::json(nullptr);
}

/// The sampling of [PET-ERG eq. (5)] and the integrator's counters.
void add_counters(nlohmann::json& j, const PetErgResult& r) {
  j["samples"] = r.samples;
  j["samples_updating"] = r.samples_updating;
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejected_steps;
  j["evaluations"] = r.evaluations;
}

/// governor = "planned": the plan, the tracking gains and margins, the progress
/// (docs/pet-erg.md, section 16.2; docs/scenario-format.md, "pet_erg", "Outputs").
nlohmann::json planned_json(const PetErgResult& r) {
  return planned_figures_json(*r.planned, r.convergence_time);
}

}  // namespace

namespace {

/// The robust margins of a planned run (docs/pet-erg.md, section 16.3), summary.json's
/// planned.robust.
nlohmann::json planned_robust_json(const PlannedRobustDesign& d, const PlannedFigures& f, double convergence_time) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const auto budget = [](const governor::RobustTrackingMargin& m) {
    return nlohmann::json{{"torque_error", m.torque_error},
                          {"disturbance", m.disturbance},
                          {"state", m.state_error},
                          {"quantisation", m.quantisation_error},
                          {"hold", m.hold_error},
                          {"wheels", m.wheel_error},
                          {"bias", m.bias_error},
                          {"kinematic_error", m.kinematic_error},
                          {"attitude_error_max_deg", m.attitude_error_max * kDeg},
                          {"rate_error_max", m.rate_error_max},
                          {"feedback_torque_max", m.feedback_torque_max}};
  };
  const double flown = f.plan.duration / d.rate;
  return {{"rate", d.rate},
          {"flown_duration", flown},
          {"flown_ratio", flown / f.plan.bang_bang_time},
          {"flight", budget(d.margin)},
          {"wait", budget(d.rest)},
          {"gate_attitude", d.gate_attitude},
          {"gate_rate", d.gate_rate},
          {"cone_margin_needed_deg", d.cone_margin_needed * kDeg},
          {"plan_cone_margin_deg", d.plan_cone_margin * kDeg},
          {"torque_needed", d.torque_needed},
          {"torque_limit", d.torque_limit},
          {"wheel_torque_ratio", d.wheel_slabs ? nlohmann::json(d.torque_ratio) : nlohmann::json(nullptr)},
          {"max_error_ratio", f.max_W_minus_level + 1.0},
          {"errors_within_bounds", f.max_W_minus_level <= 0.0},
          {"convergence_time_over_flown_plan",
           convergence_time >= 0.0 ? nlohmann::json(convergence_time / flown) : nlohmann::json(nullptr)}};
}

}  // namespace

nlohmann::json planned_figures_json(const PlannedFigures& f, double convergence_time) {
  const plan::PlanReport& p = f.plan;
  const double T_p = p.duration;
  nlohmann::json plan = {{"duration", T_p},
                         {"bang_bang_time", p.bang_bang_time},
                         {"ratio", p.ratio},
                         {"intervals", p.intervals},
                         {"path_waypoints", p.path_waypoints},
                         {"smallest_cone_margin_deg", p.check.smallest_cone_margin * 180.0 / std::numbers::pi},
                         {"largest_torque_ratio", p.check.largest_torque_ratio},
                         {"wall_time_s", p.planning_seconds},
                         {"torque_limit", f.plan_torque_limit},
                         {"torque_headroom", f.torque_headroom},
                         {"torque_headroom_derived", f.torque_headroom_derived},
                         {"cone_margin_deg", f.cone_margin * 180.0 / std::numbers::pi},
                         {"cone_margin_derived", f.cone_margin_derived}};
  nlohmann::json j = {{"plan", plan},
          {"k_R", f.gains.k_R},
          {"k_Omega", f.gains.k_Omega},
          {"gains_derived", f.gains_derived},
          {"natural_frequency", f.natural_frequency},
          {"limited_by_loop_period", f.limited_by_loop_period},
          {"limited_by_sensors", f.limited_by_sensors},
          {"limited_by_initial_rate", f.limited_by_initial_rate},
          {"tau_max", f.tau_max},
          {"sampling_period", f.sample_period},
          {"epsilon", f.epsilon},
          {"samples", f.samples},
          {"inadmissible_samples", f.inadmissible_samples},
          {"brakes", f.brakes},
          {"min_rate", f.min_rate},
          {"time_held", f.time_held},
          {"progress_end_time", finite_or_null(f.progress_end_time >= 0.0 ? f.progress_end_time : NAN)},
          {"final_progress", f.final_progress},
          {"final_rate", f.final_rate},
          {"max_torque_bound_ratio", f.max_torque_bound_ratio},
          {"max_demand_ratio", f.max_demand_ratio},
          {"saturated_commands", f.saturated_commands},
          {"convergence_time_over_plan",
           convergence_time >= 0.0 && T_p > 0.0 ? nlohmann::json(convergence_time / T_p)
                                                : nlohmann::json(nullptr)}};
  if (f.robust) j["robust"] = planned_robust_json(*f.robust, f, convergence_time);
  return j;
}

namespace {

/// The cones [PET-ERG eq. (2b)] (the true constraints), with δ, ζ of their bands.
nlohmann::json pet_erg_cones_json(const PetErgScenario& sc) {
  nlohmann::json j = nlohmann::json::array();
  for (const governor::ConeConstraint& c : sc.cones) {
    nlohmann::json cone = cone_json(c);
    cone["cos_theta_c"] = c.cos_theta_c;
    cone["delta"] = c.delta;
    cone["zeta"] = c.zeta;
    cone["repulsive_gain"] = c.repulsive_gain;
    j.push_back(std::move(cone));
  }
  return j;
}

}  // namespace

nlohmann::json pet_erg_summary(const PetErgScenario& sc, const PetErgResult& r) {
  nlohmann::json j;
  add_run_settings(j, sc);
  if (r.design.params.robust) j["robust"] = robust_json(sc, r);
  add_wheels(j, sc, r);
  add_governor_figures(j, sc, r);
  add_constraints(j, sc, r);
  add_outcome(j, sc, r);
  add_counters(j, r);
  j["cones"] = pet_erg_cones_json(sc);
  if (r.planned) j["planned"] = planned_json(r);
  if (r.output_rows > 0) j["output_rows"] = r.output_rows;
  return j;
}

namespace {

/// The first columns of every pet_erg trajectory (docs/scenario-format.md, "Outputs"): t, R,
/// ω, the torque applied, R_g (the plan's R_p(σ) in the planned mode) and R_d.
std::vector<std::string> state_columns() {
  return {"t",     "q_w",   "q_x",   "q_y",      "q_z",  "omega_x", "omega_y", "omega_z", "tau_x", "tau_y",
          "tau_z", "tau_norm", "qg_w", "qg_x", "qg_y", "qg_z",    "qd_w",    "qd_x",    "qd_y",  "qd_z"};
}

/// Writes the cells of state_columns() from `cell` on; returns the next cell.
std::vector<double>::iterator write_state_cells(std::vector<double>::iterator cell, double t,
                                                const PetErgState& y, const Mat3& R_d,
                                                const GovernorOutput& out) {
  const lie::Quat q = lie::rotation_to_quat(y.R[0]);
  const lie::Quat qg = lie::rotation_to_quat(out.R_g);
  const lie::Quat qd = lie::rotation_to_quat(R_d);
  for (const double v : {t, q(0), q(1), q(2), q(3), y.x(0), y.x(1), y.x(2), out.tau_b(0), out.tau_b(1),
                         out.tau_b(2), out.tau_b.norm(), qg(0), qg(1), qg(2), qg(3), qd(0), qd(1), qd(2),
                         qd(3)}) {
    *cell++ = v;
  }
  return cell;
}

/// The rows of a planned run (docs/scenario-format.md, "pet_erg", "Outputs"): qg is the plan's
/// attitude R_p(σ), s and s_dot the clock σ and its rate ṡ, gamma_g the cone threshold ahead,
/// torque_bound the bound on ‖τ‖ of the level set at the last choice, admissible whether that
/// choice met the thresholds (docs/pet-erg.md, section 16.2).
PetErgResult record_planned(const PetErgScenario& sc, io::RowSink& rows) {
  const bool has_cones = !sc.cones.empty();
  std::vector<std::string> columns = state_columns();
  for (const char* name : {"s", "s_dot", "V"}) columns.push_back(name);
  if (has_cones) columns.push_back("gamma_g");
  for (const char* name : {"torque_bound", "admissible", "attitude_error", "reference_error"}) {
    columns.push_back(name);
  }
  for (std::size_t i = 0; i < sc.cones.size(); ++i) columns.push_back("margin_" + std::to_string(i));
  rows.begin(columns);
  std::vector<double> row(columns.size());
  long emitted = 0;
  const PlannedRowObserver write_row = [&](double t, const PetErgState& y, const Mat3& R_d,
                                           const GovernorOutput& out, const governor::PlannedOutput& p) {
    auto cell = write_state_cells(row.begin(), t, y, R_d, out);
    for (const double v : {p.sigma, p.rate, out.V}) *cell++ = v;
    if (has_cones) *cell++ = out.gamma_g;
    for (const double v : {p.choice.torque_bound, p.choice.admissible ? 1.0 : 0.0,
                           lie::phi(R_d.transpose() * y.R[0]), lie::phi(R_d.transpose() * out.R_g)}) {
      *cell++ = v;
    }
    for (int i = 0; i < out.cone_count; ++i) *cell++ = out.margins[static_cast<std::size_t>(i)];
    rows.row(row);
    ++emitted;
  };
  PetErgResult result = simulate_planned(sc, rows.wants_rows() ? write_row : PlannedRowObserver{});
  result.output_rows = emitted;
  return result;
}

}  // namespace

PetErgResult record_pet_erg(const PetErgScenario& sc, io::RowSink& rows) {
  if (sc.params.mode == GovernorMode::planned) return record_planned(sc, rows);
  // Γ_g only with cones: without one it is +∞ (pointing_threshold.hpp), which no output file
  // holds (docs/scenario-format.md, "Outputs"); one margin column per cone.
  const bool has_cones = !sc.cones.empty();
  std::vector<std::string> columns = state_columns();
  for (const char* name : {"V", "gamma_d"}) columns.push_back(name);
  if (has_cones) columns.push_back("gamma_g");
  for (const char* name : {"gamma", "trigger", "attitude_error", "reference_error"}) columns.push_back(name);
  for (std::size_t i = 0; i < sc.cones.size(); ++i) {
    columns.push_back("margin_" + std::to_string(i));
  }
  rows.begin(columns);
  std::vector<double> row(columns.size());
  long emitted = 0;
  const PetErgRowObserver write_row = [&](double t, const PetErgState& y, const Mat3& R_d,
                                          const GovernorOutput& out) {
    auto cell = write_state_cells(row.begin(), t, y, R_d, out);
    for (const double v : {out.V, out.gamma_d}) *cell++ = v;
    if (has_cones) *cell++ = out.gamma_g;
    for (const double v : {out.gamma, out.trigger ? 1.0 : 0.0, lie::phi(R_d.transpose() * y.R[0]),
                           lie::phi(R_d.transpose() * out.R_g)}) {
      *cell++ = v;
    }
    for (int i = 0; i < out.cone_count; ++i) *cell++ = out.margins[static_cast<std::size_t>(i)];
    rows.row(row);
    ++emitted;
  };
  PetErgResult result = simulate_pet_erg(sc, rows.wants_rows() ? write_row : PetErgRowObserver{});
  result.output_rows = emitted;
  return result;
}

}  // namespace attiguard::sim
