#include "attiguard/sim/planned_robust_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::sim {

double plan_feedforward_rate(const governor::SlewPlan& plan, double omega_max) {
  const lie::Vec3 moments = lie::symmetric_eigenvalues(plan.inertia());
  const double lmin = moments(0);
  const double lmax = moments(2);
  const auto nodes = plan.nodes();
  const auto mid = plan.midpoint_torques();
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double dt = nodes[k + 1].t - nodes[k].t;
    if (!(dt > 0.0)) continue;
    const double tau_rate = std::max((mid[k] - nodes[k].tau_b).norm(), (nodes[k + 1].tau_b - mid[k]).norm()) / (0.5 * dt);
    const lie::Vec3 D = (nodes[k + 1].omega_b - nodes[k].omega_b) / dt;
    const lie::Vec3& m0 = nodes[k].omega_dot_b;
    const lie::Vec3& m1 = nodes[k + 1].omega_dot_b;
    const double omega_rate = std::max(m0.norm(), m1.norm()) + 1.5 * (D - 0.5 * (m0 + m1)).norm();
    // d/dt J⁻¹(τ − ω × Jω): ‖J⁻¹‖ (‖τ̇‖ + 2 λ_max ‖ω‖ ‖ω̇‖)
    worst = std::max(worst, (tau_rate + 2.0 * lmax * omega_max * omega_rate) / lmin);
  }
  return worst;
}

namespace {

/// The gate over the errors the torque error keeps at rest: any factor > 1 ends the wait (the free
/// response decays below the margin), a smaller one later but with smaller errors at the clock's
/// start (docs/pet-erg.md, section 16.3, "The wait and the flight": 1.1 against 1.25, 1.6, 2.2).
constexpr double kGateFactor = 1.1;

/// The robust margin's inputs with the plan flown at ṡ = 1 (docs/pet-erg.md, section 16.3,
/// "Assumptions"): the declared bounds of the scenario (section 13's), the plan's extremes and the
/// start. Everything here but the reference's extremes is independent of the clock rate.
governor::RobustTrackingInputs tracking_inputs(const PetErgScenario& sc, const governor::SlewPlan& plan,
                                               const governor::PlanWindow& w, const control::TrackingGains& g) {
  const governor::RobustMarginInputs b = governor::margin_inputs(design_inputs(sc));
  governor::RobustTrackingInputs in;
  in.gains = g;
  in.J = sc.params.J;
  in.control_period = sc.control_period;
  in.delay_periods = b.delay_periods;
  in.attitude_bias = sc.imperfections.attitude_bias_max();
  in.attitude_noise = b.attitude_noise;
  in.rate_error = sc.imperfections.rate_error_max();
  in.quantisation_error = b.quantisation_error;
  in.disturbance = b.disturbance;
  in.wheel_momentum_max = b.wheel_momentum_max;
  in.applied_torque_max = b.applied_torque_max;
  // The total momentum over the run: its initial value plus what the disturbance can add.
  lie::Vec3 H0 = sc.params.J * sc.omega0_b;
  for (const dynamics::ReactionWheel& wheel : sc.wheels) H0 += wheel.axis_b.normalized() * wheel.momentum0;
  in.total_momentum_max = H0.norm() + b.disturbance * sc.duration;
  in.reference_rate_max = w.omega_max;
  in.reference_accel_max = w.omega_dot_max;
  in.reference_jerk_max = plan_feedforward_rate(plan, w.omega_max);
  in.reference_end_accel = plan.evaluate(plan.duration()).omega_dot_b.norm();
  // The start: the plan's first attitude is the one the sensor reports at t = 0 without its
  // noise, R_0 B: in the frame R B the error is the noise's; at rest but for ω₀.
  in.initial_attitude_error = in.attitude_noise;
  in.initial_rate_error = sc.omega0_b.norm();
  return in;
}

/// `in` (the plan at ṡ = 1) flown at the constant clock rate ṡ: the reference's rate,
/// acceleration and its change scale by ṡ, ṡ², ṡ³ (docs/pet-erg.md, section 16.3).
governor::RobustTrackingInputs at_rate(governor::RobustTrackingInputs in, double rate) {
  in.reference_rate_max *= rate;
  in.reference_accel_max *= rate * rate;
  in.reference_jerk_max *= rate * rate * rate;
  in.reference_end_accel *= rate * rate;
  return in;
}

}  // namespace

PlannedRobustBasis planned_robust_basis(const PetErgScenario& sc, const governor::ProgressGovernor& progress) {
  PlannedRobustBasis b;
  b.window = progress.ahead(0.0);
  b.flight = tracking_inputs(sc, progress.plan(), b.window, progress.gains());
  b.l1 = governor::tracking_l1_gains(b.flight.J, b.flight.gains);
  // The wait: the clock held at σ = 0 (the reference at rest) from the scenario's start until
  // the measured errors pass the gate; the gate is 1.1 times the errors the torque error alone
  // keeps at rest, plus the sensors' errors, so that the wait ends.
  governor::RobustTrackingInputs at_rest = at_rate(b.flight, 0.0);
  b.rest = governor::compute_robust_tracking_margin(at_rest, b.l1);
  at_rest.initial_attitude_error = 0.0;
  at_rest.initial_rate_error = 0.0;
  const governor::RobustTrackingMargin forced = governor::compute_robust_tracking_margin(at_rest, b.l1);
  b.gate_attitude = kGateFactor * forced.e_R_max + at_rest.attitude_noise;
  b.gate_rate = kGateFactor * forced.rate_error_max + at_rest.rate_error;
  // The flight starts when the clock does, d periods after the measured errors passed the gate
  // (the torque computed then acts from there): from the true errors within the gate plus the
  // sensors' errors, plus what the wait's errors change over those periods (θ̇ ≤ ‖e_Ω‖,
  // J ė_Ω = −u + w). The loop runs throughout: no period without torque at the clock's start.
  const double lead = b.flight.delay_periods * b.flight.control_period;
  const double J_min = lie::symmetric_eigenvalues(b.flight.J)(0);
  b.flight.initial_attitude_error = std::asin(std::min(1.0, b.gate_attitude + b.flight.attitude_noise)) +
                                    lead * b.rest.rate_error_max;
  b.flight.initial_rate_error = b.gate_rate + b.flight.rate_error +
                                lead * (b.rest.feedback_torque_max + b.rest.torque_error) / J_min;
  b.flight.torque_from_start = true;
  // With wheels the command is judged against what they apply unclipped (section 16.3, "Wheels").
  b.slabs = wheel_slabs(sc);
  return b;
}

PlannedRobustDesign planned_robust_design(const PetErgScenario& sc, const governor::ProgressGovernor& progress,
                                          const PlannedRobustBasis& basis, double rate) {
  const governor::PlanWindow& w = basis.window;
  PlannedRobustDesign d;
  d.rate = rate;
  d.rest = basis.rest;
  d.gate_attitude = basis.gate_attitude;
  d.gate_rate = basis.gate_rate;
  const governor::RobustTrackingInputs in = at_rate(basis.flight, rate);
  d.margin = governor::compute_robust_tracking_margin(in, basis.l1);
  const governor::RobustTrackingMargin& m = d.margin;
  const double theta = std::max(m.attitude_error_max, d.rest.attitude_error_max);
  d.cone_margin_needed = theta + in.attitude_bias;
  d.plan_cone_margin = sc.cones.empty() ? std::numeric_limits<double>::infinity() : w.cone_margin_min;
  // The command: the reference's torque, the feedback's peak, the feedforward's errors at the
  // peaks, the command error (section 16.3, "Torque"); in the flight and in the wait.
  // The command is the reference's torque ṡ² τ_p(σ) plus an error of norm at most E.
  const double flight_error = m.feedback_torque_max +
                              progress.feedforward_error(m.attitude_error_max, m.rate_error_max, rate, w) +
                              m.command_error;
  const double flight = progress.reference_torque(rate, w) + flight_error;
  const double wait = d.rest.feedback_torque_max +
                      progress.feedforward_error(d.rest.attitude_error_max, d.rest.rate_error_max, 0.0, w) +
                      d.rest.command_error;
  d.torque_needed = std::max(flight, wait);
  d.torque_limit = progress.tau_max();
  if (basis.slabs.count > 0) {
    // Wheels: per slab, the reference's torque along the row plus the error's support (exact at
    // the plan's nodes and midpoints, between which the torque is linear).
    d.wheel_slabs = true;
    d.torque_ratio = std::max(basis.slabs.plan_gauge(progress.plan(), rate * rate, flight_error),
                              basis.slabs.inflated_gauge(lie::Vec3::Zero(), wait));
  }
  d.params.rate = rate;
  d.params.attitude_error = std::max(m.e_R_max, d.rest.e_R_max);
  d.params.rate_error = std::max(m.rate_error_max, d.rest.rate_error_max);
  d.params.attitude_allowance = in.attitude_noise;
  d.params.rate_allowance = in.rate_error + in.attitude_noise * in.reference_rate_max;
  d.params.torque_bound = d.torque_needed;
  d.params.torque_ratio = d.torque_ratio;
  d.params.gate_attitude = d.gate_attitude;
  d.params.gate_rate = d.gate_rate;
  return d;
}

PlannedRobustDesign planned_robust_design(const PetErgScenario& sc, const governor::ProgressGovernor& progress,
                                          double rate) {
  return planned_robust_design(sc, progress, planned_robust_basis(sc, progress), rate);
}

}  // namespace attiguard::sim
