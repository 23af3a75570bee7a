#include "attiguard/sim/planned_run.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <Eigen/Eigenvalues>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/four_digits.hpp"
#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/sim/pet_erg_loop.hpp"
#include "attiguard/sim/pet_erg_slew_problem.hpp"
#include "attiguard/sim/planned_robust_design.hpp"

namespace attiguard::sim {

namespace {

using governor::GovernorMode;
using governor::GovernorOutput;
using governor::PlannedOutput;
using lie::Mat3;
using lie::Vec3;
using namespace pet_erg_loop;  // NOLINT: the loop's parts (sim/pet_erg_loop.hpp)

/// The derivation's dimensionless constants (docs/pet-erg.md, section 16.2, "Defaults").
constexpr double kBandwidthRatio = 3.0;     ///< ω_n = kBandwidthRatio · 2π / T_bb
constexpr double kDampingRatio = 0.8;       ///< k_Ω = 2 ζ J_max ω_n
constexpr double kBandwidthPeriod = 0.3;    ///< cap on √(k_R/J_min) h
constexpr double kDampingPeriod = 0.6;      ///< cap on k_Ω h / J_min
constexpr double kMarginFloor = 0.5 * std::numbers::pi / 180.0;  ///< smallest derived margin
constexpr double kMarginCap = 5.0 * std::numbers::pi / 180.0;    ///< largest derived margin
constexpr double kEpsilon = 0.05;           ///< ε of the thresholds
constexpr double kSamplesPerPlan = 200.0;   ///< T_s = T_p / 200 in the continuous loop
constexpr double kMinControlInstants = 10.0;  ///< control instants over the plan, at least
constexpr int kPlannedIntervals = 64;       ///< N of the plan when [plan] intervals is left out
constexpr double kStepsPerPeriod = 20.0;    ///< derived step ≤ 1 / (20 ω_fast)
constexpr double kNoiseShare = 0.1;         ///< k_Ω e_ω + k_R e_θ ≤ kNoiseShare τ_plan
constexpr double kHeadroomBase = 0.05;      ///< the derived headroom without sensor errors
constexpr double kHeadroomNoise = 3.0;      ///< … plus this many times the sensors' torque share
constexpr double kHeadroomCap = 0.5;
constexpr double kStartShare = 0.5;         ///< k_Ω ‖ω_0‖ ≤ kStartShare τ_plan

/// The sensors' attitude and rate errors the derivation assumes [rad], [rad/s]: the declared
/// bias bounds of section 13 when larger than the biases, plus the noises.
double attitude_error(const PetErgScenario& sc) {
  return sc.imperfections.attitude_bias_max() + sc.imperfections.sensor.attitude_noise;
}
/// The attitude error that costs the law torque: with robust margins the bias is geometric (the
/// analysis frame R B, docs/pet-erg.md section 16.3) and only the noise counts.
double torque_attitude_error(const PetErgScenario& sc) {
  return sc.margins == governor::Margins::robust ? sc.imperfections.sensor.attitude_noise : attitude_error(sc);
}
double rate_error(const PetErgScenario& sc) { return sc.imperfections.rate_error_max(); }

/// The torque the tracking law spends on the sensors' errors and the quantisation at the gains
/// (k_Ω e_ω + k_R e_θ + q√3/2) [N·m] (docs/pet-erg.md, section 16.2, "Defaults").
double sensor_torque(const PetErgScenario& sc, const control::TrackingGains& g) {
  const PetErgImperfections& im = sc.imperfections;
  return g.k_Omega * rate_error(sc) + g.k_R * torque_attitude_error(sc) + 0.5 * std::sqrt(3.0) * im.torque_quantum;
}

/// The largest ω_n with J_max(1.6 ω_n e_ω + ω_n² e_θ) ≤ kNoiseShare τ_plan (+∞ without errors).
double noise_bandwidth(const PetErgScenario& sc, double J_max, double plan_torque) {
  const double A = J_max * torque_attitude_error(sc);
  const double B = 2.0 * kDampingRatio * J_max * rate_error(sc);
  const double C = kNoiseShare * plan_torque;
  if (A <= 0.0 && B <= 0.0) return std::numeric_limits<double>::infinity();
  if (A <= 0.0) return C / B;
  return (-B + std::sqrt(B * B + 4.0 * A * C)) / (2.0 * A);
}

/// The tracking gains: the scenario's kp, kd when given, else derived from J and the slew's
/// eigenaxis bang-bang time, capped by the loop period h (0: none) and by the sensors' errors.
void derive_gains(const PetErgScenario& sc, double T_bb, double h, double plan_torque, PlannedFigures& f) {
  if (!sc.derived.kp_derived && !sc.derived.kd_derived) {
    f.gains = control::TrackingGains{sc.params.gains.kp, sc.params.gains.kd};
    return;
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(sc.params.J);
  const double J_min = eig.eigenvalues().minCoeff();
  const double J_max = eig.eigenvalues().maxCoeff();
  double omega_n = kBandwidthRatio * 2.0 * std::numbers::pi / T_bb;
  if (h > 0.0) {
    const double cap = std::min(kBandwidthPeriod / h * std::sqrt(J_min / J_max),
                                kDampingPeriod * J_min / (2.0 * kDampingRatio * J_max * h));
    f.limited_by_loop_period = cap < omega_n;
    omega_n = std::min(omega_n, cap);
  }
  const double noise_cap = noise_bandwidth(sc, J_max, plan_torque);
  f.limited_by_sensors = noise_cap < omega_n;
  omega_n = std::min(omega_n, noise_cap);
  // A start turning at ω_0 (off the plan, which starts at rest): the damping torque k_Ω ‖ω_0‖ at
  // most half the plan's torque, so that the hold brakes it without saturating.
  const double w0 = sc.omega0_b.norm();
  if (w0 > 0.0) {
    const double start_cap = kStartShare * plan_torque / (2.0 * kDampingRatio * J_max * w0);
    f.limited_by_initial_rate = start_cap < omega_n;
    omega_n = std::min(omega_n, start_cap);
  }
  f.natural_frequency = omega_n;
  f.gains_derived = true;
  f.gains.k_R = sc.derived.kp_derived ? J_max * omega_n * omega_n : sc.params.gains.kp;
  f.gains.k_Omega = sc.derived.kd_derived ? 2.0 * kDampingRatio * J_max * omega_n : sc.params.gains.kd;
}

/// The plan's cone margin: the scenario's, else the attitude error the torque headroom lets the
/// tracking law correct (2 h τ / k_R) plus the attitude sensor's error, within [0.5°, 5°].
double derived_cone_margin(const PetErgScenario& sc, const plan::SlewProblem& p,
                           const control::TrackingGains& g) {
  const double m = 2.0 * p.torque_headroom * p.tau_max / g.k_R + attitude_error(sc);
  return std::clamp(m, kMarginFloor, kMarginCap);
}

/// The integration step of the run when derived: resolves the tracking loop's fastest rate.
void set_integration_step(const PlannedFigures& f, const Mat3& J, PetErgScenario& run) {
  if (!run.derived.integrator_step_derived) return;
  const double J_min = Eigen::SelfAdjointEigenSolver<Mat3>(J).eigenvalues().minCoeff();
  const double fastest = std::max(std::sqrt(f.gains.k_R / J_min), f.gains.k_Omega / J_min);
  run.integrator.step = std::min(run.integrator.step, 1.0 / (kStepsPerPeriod * fastest));
  if (run.control_period > 0.0) run.integrator.step = std::min(run.integrator.step, run.control_period);
}

constexpr int kRobustPlans = 4;              ///< plans the robust design makes at most
constexpr double kRobustMarginSlack = 1.02;  ///< a replanned cone margin: 2 % above the need
constexpr int kRateBisections = 14;          ///< bisections of the clock's rate ṡ
constexpr double kSlowestRate = 0.02;        ///< the slowest ṡ the design tries
/// Multiples of the derived natural frequency the robust design tries (softer gains: a smaller
/// hold error, a larger attitude error).
constexpr std::array<double, 7> kRobustBandwidths{1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125};

/// The design at ṡ, or nothing when the margin is refused there.
std::optional<PlannedRobustDesign> design_at(const PetErgScenario& sc, const governor::ProgressGovernor& progress,
                                             const PlannedRobustBasis& basis, double rate) {
  try {
    return planned_robust_design(sc, progress, basis, rate);
  } catch (const SetupError&) {
    return std::nullopt;
  }
}

/// The fastest ṡ ∈ [kSlowestRate, 1] whose design keeps the torque (bisection: the need grows
/// with ṡ), with its design; nothing when even the slowest does not.
std::optional<PlannedRobustDesign> fastest_rate(const PetErgScenario& sc, const governor::ProgressGovernor& progress) {
  const auto torque_ok = [](const std::optional<PlannedRobustDesign>& d) { return d && d->torque_holds(); };
  PlannedRobustBasis basis;
  try {
    basis = planned_robust_basis(sc, progress);
  } catch (const SetupError&) {
    return std::nullopt;
  }
  std::optional<PlannedRobustDesign> best = design_at(sc, progress, basis, 1.0);
  if (torque_ok(best)) return best;
  best = design_at(sc, progress, basis, kSlowestRate);
  if (!torque_ok(best)) return std::nullopt;
  double lo = kSlowestRate, hi = 1.0;
  for (int i = 0; i < kRateBisections; ++i) {
    const double mid = std::sqrt(lo * hi);
    std::optional<PlannedRobustDesign> d = design_at(sc, progress, basis, mid);
    if (torque_ok(d)) {
      lo = mid;
      best = std::move(d);
    } else {
      hi = mid;
    }
  }
  return best;
}

/// Why the derived gains fail at the slowest clock rate, for a refusal: the proof's own refusal,
/// or the torque the proved errors need against the limit, with the torque error's parts.
std::string slowest_design_summary(const PetErgScenario& sc, const governor::SlewPlan& plan, const PlannedFigures& f) {
  try {
    const governor::ProgressGovernor progress(plan, sc.cones, f.tau_max, f.gains, sc.control_period, 0.0);
    const PlannedRobustDesign d = planned_robust_design(sc, progress, kSlowestRate);
    const governor::RobustTrackingMargin& m = d.margin;
    return "torque needed " + four_digits(d.torque_needed) + " N m (torque error " + four_digits(m.torque_error) +
           " N m: hold " + four_digits(m.hold_error) + ", state " + four_digits(m.state_error) + ", disturbance " +
           four_digits(m.disturbance) + ")";
  } catch (const SetupError& e) {
    return e.what();
  }
}

/// The tracking gains at ω_n (docs/pet-erg.md, section 16.2): k_R = J_max ω_n², k_Ω = 2ζ J_max ω_n.
control::TrackingGains gains_at(const PetErgScenario& sc, double omega_n) {
  const double J_max = Eigen::SelfAdjointEigenSolver<Mat3>(sc.params.J).eigenvalues().maxCoeff();
  return {J_max * omega_n * omega_n, 2.0 * kDampingRatio * J_max * omega_n};
}

/// Robust margins (docs/pet-erg.md, section 16.3, "Design"): the plan is flown at a constant
/// clock rate ṡ (a time-scaled plan: rates ×ṡ, torque ×ṡ²). Over softer multiples of the derived
/// gains, the fastest ṡ whose proved errors keep the command within the torque limit is found by
/// bisection, and the fastest of all is taken; when the plan does not keep the cones by the
/// proved attitude error θ* plus the bias β it is made again with that cone margin. A given cone margin or pair of gains is kept, its
/// shortfall refused at its key.
void plan_robust(const PetErgScenario& sc, const plan::PlannerOptions& options, PlannedSetup& s) {
  PlannedFigures& f = s.figures;
  const bool gains_free = f.gains_derived && sc.derived.kp_derived && sc.derived.kd_derived;
  const double base_omega_n = f.natural_frequency;
  for (int round = 0; round < kRobustPlans; ++round) {
    s.planned = plan::plan_slew(s.problem, options);
    std::optional<PlannedRobustDesign> best;
    control::TrackingGains best_gains = f.gains;
    double best_omega_n = f.natural_frequency;
    for (const double m : kRobustBandwidths) {
      const control::TrackingGains g = gains_free ? gains_at(sc, m * base_omega_n) : f.gains;
      const governor::ProgressGovernor progress(s.planned.plan, sc.cones, f.tau_max, g, sc.control_period, 0.0);
      std::optional<PlannedRobustDesign> d = fastest_rate(sc, progress);
      if (d && (!best || d->rate > best->rate)) {
        best = std::move(d);
        best_gains = g;
        best_omega_n = m * base_omega_n;
      }
      if (!gains_free) break;
    }
    if (!best) {
      throw PlannedSetupRefusal("control", "margins", "robust margins of the planned mode: the imperfections' "
                                "bounds leave no clock rate down to " + four_digits(kSlowestRate) +
                                " whose proved errors keep the torque within " +
                                (sc.wheels.empty() ? four_digits(f.tau_max) + " N m" : std::string("the wheels' limits")) +
                                ", at any of the tried gains (docs/pet-erg.md, section 16.3); at the "
                                "derived gains: " + slowest_design_summary(sc, s.planned.plan, f));
    }
    f.robust = best;
    if (gains_free) {
      f.natural_frequency = best_omega_n;
      f.gains = best_gains;
    }
    if (best->plan_cone_margin >= best->cone_margin_needed) return;
    const std::string need = four_digits(best->cone_margin_needed * 180.0 / std::numbers::pi);
    if (sc.plan.cone_margin_given) {
      throw PlannedSetupRefusal("plan", "cone_margin_deg", "robust margins of the planned mode need a cone margin of " +
                                need + " deg; the plan keeps " +
                                four_digits(best->plan_cone_margin * 180.0 / std::numbers::pi) + " deg");
    }
    s.problem.cone_margin = std::max(s.problem.cone_margin, 0.0) +
                            kRobustMarginSlack * (best->cone_margin_needed - best->plan_cone_margin) + 1e-4;
  }
  throw PlannedSetupRefusal("control", "margins", "robust margins of the planned mode: no plan keeps the cones by "
                            "the proved attitude error and the bias within " + std::to_string(kRobustPlans) +
                            " plans (the cone margin needed grows with the plan)");
}

}  // namespace

PlannedSetup planned_setup(const PetErgScenario& sc) {
  PlannedSetup s;
  s.run = sc;
  s.problem = slew_problem(sc, SlewStart::any_rate);
  // With robust margins the plan starts where the flight software sees the craft: the attitude
  // its sensor reports at t = 0, R_0 exp(b) (the bias included; its noise is the design's initial
  // error). The analysis runs in that frame, R B (docs/pet-erg.md, section 16.3, "The wait").
  if (sc.margins == governor::Margins::robust) {
    s.problem.R_start = sc.R0_ib * lie::exp(sc.imperfections.sensor.attitude_bias_b);
  }
  PlannedFigures& f = s.figures;
  f.plan_torque_limit = s.problem.tau_max;
  governor::CraftScales craft = craft_scales(sc);
  craft.disturbance_bound = 0.0;  // the law's own torque: the disturbance acts on the plant
  f.tau_max = governor::effective_torque(craft);
  const double T_bb = dynamics::eigenaxis_bang_bang_time(sc.params.J, s.problem.R_start,
                                                         s.problem.R_target, s.problem.tau_max);
  const double h = sc.control_period > 0.0 ? sc.control_period
                   : sc.derived.integrator_step_derived ? 0.0
                                                        : sc.integrator.step;
  derive_gains(sc, T_bb, h, s.problem.tau_max, f);
  if (!sc.plan.torque_headroom_given) {
    s.problem.torque_headroom =
        std::clamp(kHeadroomBase + kHeadroomNoise * sensor_torque(sc, f.gains) / s.problem.tau_max,
                   kHeadroomBase, kHeadroomCap);
  }
  f.torque_headroom = s.problem.torque_headroom;
  f.torque_headroom_derived = !sc.plan.torque_headroom_given;
  f.cone_margin_derived = !sc.plan.cone_margin_given;
  if (f.cone_margin_derived) s.problem.cone_margin = derived_cone_margin(sc, s.problem, f.gains);
  f.cone_margin = s.problem.cone_margin;
  plan::PlannerOptions options = planner_options(sc);
  // A finer mesh than `attiguard plan` derives: between collocation points the cubic reference
  // needs up to 25 % more than the linear torque where the torque switches, for a quarter of an
  // interval; shorter intervals leave the tracking loop less to correct there.
  if (options.intervals == 0) options.intervals = kPlannedIntervals;
  if (sc.margins == governor::Margins::robust) {
    plan_robust(sc, options, s);
    f.cone_margin = s.problem.cone_margin;
  } else {
    s.planned = plan::plan_slew(s.problem, options);
  }
  f.plan = s.planned.report;
  const double T_p = s.planned.plan.duration();
  if (sc.control_period > T_p / kMinControlInstants) {
    throw PlannedSetupRefusal("control", "control_period", four_digits(sc.control_period) + " s leaves " +
                     std::to_string(static_cast<long>(T_p / sc.control_period)) +
                     " control instants over the plan's " + four_digits(T_p) + " s; the planned mode "
                     "needs at least " + std::to_string(static_cast<int>(kMinControlInstants)) +
                     " (a control period of at most " + four_digits(T_p / kMinControlInstants) + " s)");
  }
  f.sample_period = sc.control_period > 0.0 ? sc.control_period : T_p / kSamplesPerPlan;
  f.epsilon = kEpsilon;
  s.params = governor::PlannedGovernorParams{f.gains, f.tau_max, f.sample_period, f.epsilon,
                                             sc.control_period, sc.imperfections.delay_periods, std::nullopt};
  if (f.robust) s.params.robust = f.robust->params;
  // With robust margins and wheels the command is saturated to the wheels' slabs, which the
  // design keeps it within (docs/pet-erg.md, section 16.3, "Wheels").
  if (f.robust && !sc.wheels.empty()) {
    s.params.slabs = wheel_slabs(sc);
  }
  s.run.params.Ts = f.sample_period;  // the continuous loop stops at every choice of ṡ
  set_integration_step(f, sc.params.J, s.run);
  return s;
}

namespace {

/// `check`'s lines of the robust margins (docs/pet-erg.md, section 16.3).
std::string robust_report(const PlannedRobustDesign& d, const PlannedFigures& f) {
  constexpr double kDeg = 180.0 / std::numbers::pi;
  const governor::RobustTrackingMargin& m = d.margin;
  const double flown = f.plan.duration / d.rate;
  std::string out = "robust margins of the planned mode (docs/pet-erg.md, section 16.3):\n";
  out += "  clock rate " + four_digits(d.rate) + ": the plan flown in " + four_digits(flown) + " s = " +
         four_digits(flown / f.plan.bang_bang_time) + "x the eigenaxis bang-bang time\n";
  out += "  torque error w = " + four_digits(m.torque_error) + " N m (disturbance " + four_digits(m.disturbance) +
         ", hold " + four_digits(m.hold_error) + ", state " + four_digits(m.state_error) + ", quantisation " +
         four_digits(m.quantisation_error) + ", wheels " + four_digits(m.wheel_error) + ", bias " +
         four_digits(m.bias_error) + ")\n";
  out += "  proved errors: attitude " + four_digits(std::max(m.attitude_error_max, d.rest.attitude_error_max) * kDeg) +
         " deg, rate " + four_digits(std::max(m.rate_error_max, d.rest.rate_error_max)) +
         " rad/s; cone margin needed " + four_digits(d.cone_margin_needed * kDeg) + " deg (with the bias), the plan keeps " +
         four_digits(d.plan_cone_margin * kDeg) + " deg\n";
  out += d.wheel_slabs ? "  torque needed " + four_digits(d.torque_ratio) + " of the wheels' limits (the largest over the "
                             "wheels and tau_max; as a norm " + four_digits(d.torque_needed) + " N m)"
                       : "  torque needed " + four_digits(d.torque_needed) + " of " + four_digits(d.torque_limit) + " N m";
  out += "; the clock starts once the measured errors are within " + four_digits(d.gate_attitude) + " rad and " +
         four_digits(d.gate_rate) + " rad/s\n";
  return out;
}

}  // namespace

std::string planned_report(const PlannedSetup& setup) {
  const PlannedFigures& f = setup.figures;
  const auto mark = [](bool derived) { return derived ? " (derived)\n" : " (given)\n"; };
  constexpr double kDeg = 180.0 / std::numbers::pi;
  std::string out = "planned slew (docs/pet-erg.md, section 16.2):\n";
  out += "  plan: " + four_digits(f.plan.duration) + " s = " + four_digits(f.plan.ratio) +
         "x the eigenaxis bang-bang time " + four_digits(f.plan.bang_bang_time) + " s, " +
         std::to_string(f.plan.intervals) + " intervals, " + std::to_string(f.plan.path_waypoints) +
         (f.plan.path_waypoints == 1 ? " waypoint" : " waypoints") + " around the cones, planned in " + four_digits(f.plan.planning_seconds) + " s\n";
  out += "  control.kp = k_R = " + four_digits(f.gains.k_R) + " N m" + mark(f.gains_derived);
  out += "  control.kd = k_Omega = " + four_digits(f.gains.k_Omega) + " N m s" + mark(f.gains_derived);
  if (f.gains_derived) {
    out += "  natural frequency " + four_digits(f.natural_frequency) + " rad/s" +
           (f.limited_by_loop_period ? ", lowered to the loop period's caps" : "") +
           (f.limited_by_sensors ? ", lowered for the sensors' errors" : "") +
           (f.limited_by_initial_rate ? ", lowered for the initial rate" : "") + "\n";
  }
  out += "  plan.torque_headroom = " + four_digits(f.torque_headroom) + " of " +
         four_digits(f.plan_torque_limit) + " N m" + mark(f.torque_headroom_derived);
  out += "  plan.cone_margin_deg = " + four_digits(f.cone_margin * kDeg) + mark(f.cone_margin_derived);
  out += "  sampling period of the rate " + four_digits(f.sample_period) + " s, epsilon " +
         four_digits(f.epsilon) + ", torque bound " + four_digits(f.tau_max) + " N m\n";
  if (f.robust) out += robust_report(*f.robust, f);
  return out;
}

namespace {

/// The figures of one run of the planned mode and its view of an instant.
class PlannedFlight {
 public:
  PlannedFlight(const PlannedSetup& setup, governor::GovernorDesign design)
      : sc_(setup.run),
        gov_(setup.planned.plan, setup.run.cones, setup.params),
        hold_(design.params, design.cones),
        r_(initial_result(sc_, std::move(design), hold_)),
        bias_frame_(lie::exp(setup.run.imperfections.sensor.attitude_bias_b)) {
    r_.planned = setup.figures;
  }

  /// The instant's view: the torque applied, R_g = R_p(σ), V, Γ_g and the true cones' margins.
  GovernorOutput view(const PetErgState& s, const PlannedOutput& p, const Vec3& tau_applied_b) const {
    GovernorOutput out;
    out.tau_b = tau_applied_b;
    out.R_g = p.reference.R_ib;
    out.V = out.W = p.V;
    out.gamma_g = out.gamma = p.choice.gamma_g;
    if (const auto& robust = gov_.params().robust) {
      // The true errors seen through the bias against the reference, as a ratio to the peaks
      // the design proved (section 16.3): at most 1 by the guarantee.
      out.W = governor::tracking_error_ratio(control::tracking_error(s.R[0] * bias_frame_, s.x, p.reference),
                                             robust->attitude_error, robust->rate_error);
      out.gamma = 1.0;
    }
    out.gamma_d = p.choice.torque_bound;
    out.trigger = p.choice.admissible;
    out.cone_count = static_cast<int>(sc_.cones.size());
    for (std::size_t i = 0; i < sc_.cones.size(); ++i) {
      out.margins[i] = governor::pointing_margin(sc_.cones[i], s.R[0]);
    }
    return out;
  }

  /// Folds an instant into the figures.
  void observe(double t, const PetErgState& s, const GovernorOutput& out, const PlannedOutput& p) {
    record(sc_, r_, t, sc_.desired.at(t), s.R[0], out);
    PlannedFigures& f = *r_.planned;
    if (f.robust) f.max_W_minus_level = std::max(f.max_W_minus_level, out.W - out.gamma);
    if (sc_.control_period == 0.0) demanded(p);
    if (p.sigma >= gov_.progress().plan().duration() && f.progress_end_time < 0.0) f.progress_end_time = t;
    f.final_progress = p.sigma;
    f.final_rate = p.rate;
  }

  /// A choice of ṡ at t at plan time σ, after the previous one at t_prev; `held`: the clock
  /// stood still since then.
  void chose(double t, double t_prev, bool held, double sigma, const governor::RateChoice& c) {
    PlannedFigures& f = *r_.planned;
    const bool before_end = sigma < gov_.progress().plan().duration();
    if (before_end && held) f.time_held += t - t_prev;
    if (before_end) f.min_rate = std::min(f.min_rate, c.rate);
    if (c.rule == governor::RateRule::brake) ++f.brakes;
    ++f.samples;
    ++r_.samples;
    if (c.admissible) ++r_.samples_updating; else ++f.inadmissible_samples;
    const governor::PlannedGovernorParams& gp = gov_.params();
    const double bound_ratio = gp.slabs.count > 0 && gp.robust ? gp.robust->torque_ratio : c.torque_bound / gp.tau_max;
    f.max_torque_bound_ratio = std::max(f.max_torque_bound_ratio, bound_ratio);
    f.last_V = c.V;
    f.last_gamma_g = c.gamma_g;
    f.last_torque_bound = c.torque_bound;
  }

  /// The law's demand at an instant (the continuous loop's instants, the flight loop's commands).
  void demanded(const PlannedOutput& p) {
    PlannedFigures& f = *r_.planned;
    f.max_demand_ratio = std::max(f.max_demand_ratio, p.demand_ratio);
    if (p.demand_ratio > 1.0) ++f.saturated_commands;
  }

  PetErgResult figures(PetErgState& y, const integrate::IntegrationStats& stats, double sigma_end) {
    y.R[1] = gov_.progress().reference(sigma_end, 0.0).R_ib;
    finish(sc_, y, stats, r_);
    return std::move(r_);
  }

  const PetErgScenario& scenario() const noexcept { return sc_; }
  governor::PlannedGovernor& governor() noexcept { return gov_; }
  const governor::PlannedGovernor& governor() const noexcept { return gov_; }
  PetErgResult& result() noexcept { return r_; }

 private:
  const PetErgScenario& sc_;
  governor::PlannedGovernor gov_;
  governor::AttitudeGovernor hold_;  ///< the PD hold's figures (Γ_d of the hold)
  PetErgResult r_;
  Mat3 bias_frame_;  ///< B = exp(b̂_R): the analysis frame R B of the robust margins
};

/// The design of the PD hold the plan ends with (its thresholds are the summary's Γ figures).
governor::GovernorDesign hold_design(const PetErgScenario& run) {
  PetErgScenario hold = run;
  hold.params.mode = GovernorMode::none;
  hold.margins = governor::Margins::nominal;  // the planned mode's robust margins are section 16.3's
  return design_governor(hold);
}

/// Both observers' view of an instant.
struct PlannedView {
  GovernorOutput out;
  PlannedOutput planned;
};

/// control_period = 0: (R, ω) integrated as one ODE under the tracking law; the clock
/// (σ, ṡ, s̈) set at the choices at t_k = k T_s and run in closed form between them
/// (docs/pet-erg.md, section 16.2).
PetErgResult fly_continuous(const PlannedSetup& setup, const PlannedRowObserver& on_output) {
  PlannedFlight flight(setup, hold_design(setup.run));
  const PetErgScenario& sc = flight.scenario();
  const governor::PlannedGovernor& gov = flight.governor();
  const dynamics::RigidBody body(sc.params.J);
  governor::ProgressClock clock{0.0, 0.0, 0.0, 0.0, gov.progress().plan().duration()};
  governor::RateChoice choice;
  const auto planned_at = [&](double t, const PetErgState& s) {
    PlannedOutput p = gov.evaluate(clock.sigma_at(t), clock.rate_at(t), clock.accel_at(t), s.R[0], s.x);
    p.choice = choice;
    return p;
  };
  auto field = [&](double t, const PetErgState& s) -> PetErgState::Tangent {
    const PlannedOutput p = planned_at(t, s);
    PetErgState::Tangent d;
    d.segment<3>(0) = s.x;
    d.segment<3>(3).setZero();  // R[1] holds R_p(σ), set at the stops
    d.segment<3>(6) = body.angular_acceleration(s.x, p.tau_b);
    return d;
  };
  auto monitor = [&](double t, const PetErgState& s) -> PlannedView {
    const PlannedOutput p = planned_at(t, s);
    PlannedView v{flight.view(s, p, p.tau_b), p};
    flight.observe(t, s, v.out, p);
    return v;
  };
  auto sample = [&](double t, PetErgState& s) {
    const double sigma = clock.sigma_at(t);
    const double rate = clock.rate_at(t);
    choice = gov.progress().choose(sigma, s.R[0], s.x, rate);
    flight.chose(t, clock.t_k, clock.rate_k == 0.0 && clock.accel_k == 0.0, sigma, choice);
    clock = governor::ProgressClock{t, sigma, choice.rate, choice.accel, clock.duration};
    s.R[1] = gov.progress().reference(sigma, choice.rate).R_ib;
  };
  PetErgState y = pet_erg_initial_state(sc);
  sample(0.0, y);
  auto at_stop = [&](const Stop& stop, double t, PetErgState& s) {
    if (stop.sample) sample(t, s);
  };
  using Observer = std::function<void(double, const PetErgState&, const Mat3&, const PlannedView&)>;
  const Observer observer =
      on_output ? Observer([&](double t, const PetErgState& s, const Mat3& R_d, const PlannedView& v) {
                    on_output(t, s, R_d, v.out, v.planned);
                  })
                : nullptr;
  const integrate::IntegrationStats stats = integrate_over_stops(sc, field, y, monitor, at_stop, observer);
  return flight.figures(y, stats, clock.sigma_at(sc.duration));
}

}  // namespace

namespace {

/// control_period > 0: the flight loop. PlannedGovernor::step runs at t_k = k h with the
/// sensors' view of the state, its torque held to t_{k+1} (HeldActuation: quantum, delay,
/// wheels); the plant between the instants as in the PET-ERG's flight loop (docs/pet-erg.md,
/// sections 10-12 and 16.2).
class PlannedFlightLoop {
 public:
  explicit PlannedFlightLoop(const PlannedSetup& setup)
      : flight_(setup, hold_design(setup.run)),
        sc_(flight_.scenario()),
        body_(sc_.params.J),
        actuation_(sc_.imperfections, sc_.wheels),
        disturbance_(sc_),
        T_(flight_.governor().progress().plan().duration()) {}

  void start(PetErgState& y) {
    flight_.governor().reset(0.0);
    control(0.0, y);
  }

  integrate::IntegrationStats fly(PetErgState& y, const PlannedRowObserver& on_output) {
    auto field = [this](double t, const PetErgState& s) { return this->field(t, s); };
    auto monitor = [this](double t, const PetErgState& s) { return this->monitor(t, s); };
    auto at_stop = [this](const Stop& stop, double t, PetErgState& s) {
      if (stop.control) control(t, s);
    };
    const auto rows = [&](double t, const PetErgState& s, const Mat3& R_d, const PlannedView& v) {
      on_output(t, s, R_d, v.out, v.planned);
    };
    using Observer = std::function<void(double, const PetErgState&, const Mat3&, const PlannedView&)>;
    const Observer observer = on_output ? Observer(rows) : nullptr;
    return integrate_over_stops(sc_, field, y, monitor, at_stop, observer);
  }

  PetErgResult figures(PetErgState& y, const integrate::IntegrationStats& stats) {
    finish_wheels(sc_, actuation_, flight_.result());
    return flight_.figures(y, stats, sigma_at(sc_.duration));
  }

 private:
  [[nodiscard]] double sigma_at(double t) const noexcept {
    return flight_.governor().clock().sigma_at(t);
  }

  PetErgState::Tangent field(double t, const PetErgState& s) const {
    PetErgState::Tangent d;
    d.segment<3>(0) = s.x;
    d.segment<3>(3).setZero();  // R[1] holds R_p(σ), set at the control instants
    Vec3 tau = actuation_.torque_b() + disturbance_.at(t, s);
    if (actuation_.has_wheels()) tau += actuation_.momentum_b(t).cross(s.x);
    d.segment<3>(6) = body_.angular_acceleration(s.x, tau);
    return d;
  }

  /// The true state against the governor's clock, with the torque actually applied.
  PlannedView monitor(double t, const PetErgState& s) {
    const governor::PlannedGovernor& gov = flight_.governor();
    const governor::ProgressClock& clock = gov.clock();
    // With a delay the clock was set for t_k + h at t_k; with robust margins (a clock that coasts)
    // the reference at t < t_k + h is σ_k − ṡ (t_k + h − t), at rest before the start.
    double sigma = clock.sigma_at(t);
    if (gov.params().robust && t < clock.t_k) sigma = std::max(0.0, clock.sigma_k - clock.rate_k * (clock.t_k - t));
    PlannedOutput p = gov.evaluate(sigma, clock.rate_at(t), clock.accel_at(t), s.R[0], s.x);
    p.choice = gov.output().choice;
    PlannedView v{flight_.view(s, p, actuation_.torque_b()), p};
    flight_.observe(t, s, v.out, p);
    actuation_.observe_momenta(t);
    return v;
  }

  /// Control instant t: the sensors' view to the governor, its torque commanded and held.
  void control(double t, PetErgState& s) {
    const dynamics::Measurement m = actuation_.measure(s.R[0], s.x);
    const governor::ProgressClock before = flight_.governor().clock();
    // With robust margins the law cancels the wheels' momentum coupling (section 16.3).
    const bool robust = flight_.governor().params().robust.has_value();
    const Vec3 wheel_momentum_b = robust && actuation_.has_wheels() ? actuation_.momentum_b(t) : Vec3::Zero();
    const PlannedOutput& p = flight_.governor().step(t, m.R_ib, m.omega_b, wheel_momentum_b);
    actuation_.command(t, p.tau_b);
    flight_.demanded(p);
    if (p.sampled) {
      flight_.chose(t, before.t_k, before.rate_k == 0.0 && before.accel_k == 0.0, p.sigma, p.choice);
    }
    s.R[1] = p.reference.R_ib;
    disturbance_.hold(s);
  }

  PlannedFlight flight_;
  const PetErgScenario& sc_;
  const dynamics::RigidBody body_;
  HeldActuation actuation_;
  PetErgPlantDisturbance disturbance_;
  double T_;
};

}  // namespace

PetErgResult simulate_planned(const PetErgScenario& sc, const PlannedRowObserver& on_output) {
  const PlannedSetup setup = planned_setup(sc);
  if (setup.run.control_period > 0.0) {
    PlannedFlightLoop loop(setup);
    PetErgState y = pet_erg_initial_state(setup.run);
    loop.start(y);
    const integrate::IntegrationStats stats = loop.fly(y, on_output);
    return loop.figures(y, stats);
  }
  return fly_continuous(setup, on_output);
}

PetErgResult simulate_planned(const PetErgScenario& sc, const PetErgRowObserver& on_output) {
  if (!on_output) return simulate_planned(sc, PlannedRowObserver{});
  return simulate_planned(sc, PlannedRowObserver([&](double t, const PetErgState& y, const Mat3& R_d,
                                                     const GovernorOutput& out, const PlannedOutput&) {
                            on_output(t, y, R_d, out);
                          }));
}

}  // namespace attiguard::sim
