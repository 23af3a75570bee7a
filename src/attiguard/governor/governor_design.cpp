// The governor's design (docs/pet-erg.md, sections 12-13): wheel polytope, robust margin,
// reduced torque limits and tightened cones, computed once, offline.

#include "attiguard/governor/governor_design.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/shortest_number.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::governor {

namespace {

using lie::Vec3;

std::string num(double x) { return shortest_number(x); }

/// x [rad] in degrees, for the messages.
double degrees(double x) { return x * 180.0 / std::numbers::pi; }

/// Throws SetupError("no admissible set with robust margins: why") (docs/pet-erg.md, section 13).
[[noreturn]] void no_admissible_set(const std::string& why) {
  throw SetupError("no admissible set with robust margins: " + why);
}

/// "torque error bound w = … N m (disturbance …, sensors …, quantisation …, hold …, reference
/// lag …)".
std::string budget(const RobustMargin& m) {
  return "torque error bound w = " + num(m.torque_error) + " N m (disturbance " + num(m.disturbance) +
         ", sensors " + num(m.sensor_error) + ", quantisation " + num(m.quantisation_error) + ", hold " +
         num(m.hold_error) + ", reference lag " + num(m.reference_lag_error) + ")";
}


/// Γ_d of the wheel polytope with each limit reduced to u_max,i − ‖r_i‖ e_cmd (section 13).
double reduced_wheel_gamma_d(const GovernorDesignInputs& in, double e_cmd) {
  const dynamics::ReactionWheelArray array(in.wheels);
  std::vector<Vec3> rows;
  std::vector<double> limits;
  for (int i = 0; i < array.count(); ++i) {
    rows.push_back(array.allocation_row(i));
    limits.push_back(array.wheel(i).torque_max - array.allocation_row(i).norm() * e_cmd);
    if (!(limits.back() > 0.0)) {
      no_admissible_set("the command error bound " + num(e_cmd) + " N m reaches wheel " + std::to_string(i) +
                        "'s torque limit " + num(array.wheel(i).torque_max) + " N m");
    }
  }
  return compute_polytope_torque_threshold(in.params.gains.kp, in.params.gains.kd, in.params.J, rows, limits)
      .gamma_d;
}

/// One cone tightened by the attitude bias bound β, its repulsive level δ moved to at least
/// `gap` inside the new boundary and ζ with it (section 13). `i` names the cone in the messages.
ConeConstraint robust_cone(ConeConstraint cone, std::size_t i, double bias, double gap, double gamma_min) {
  const double theta_c = cone.theta_c - bias;
  if (!(gap < theta_c)) {
    no_admissible_set("cones[" + std::to_string(i) + "] (theta_c = " + num(degrees(cone.theta_c)) +
                      " deg, less the attitude bias bound " + num(degrees(bias)) + " deg) leaves no attitude " +
                      num(degrees(gap)) + " deg inside it, as Gamma_min = " + num(gamma_min) + " needs");
  }
  const double delta_offset = cone.delta - cone.cos_theta_c;
  const double band = cone.zeta - cone.delta;
  cone.theta_c = theta_c;
  cone.cos_theta_c = std::cos(theta_c);
  cone.sin_theta_c = std::abs(std::sin(theta_c));
  cone.delta = std::max(cone.cos_theta_c + delta_offset, std::cos(theta_c - gap));
  cone.zeta = cone.delta + band;
  if (!(cone.zeta < 1.0)) {
    no_admissible_set("the repulsive band of cones[" + std::to_string(i) + "] moved inwards by the robust gap " +
                      num(degrees(gap)) + " deg leaves no attitude outside it");
  }
  return cone;
}

/// The cones the governor enforces with robust margins (section 13): each θ_c tightened by the
/// attitude bias bound β (the true axis lies within β of the axis seen through the bias), the
/// repulsive levels kept at the same offsets from the new boundary; then, as R_g may only stand
/// where Γ_W > Γ_min, i.e. more than gap = arccos(1 − Γ_min/((1 − δ) k_p)) inside each cone, the
/// level δ where the repulsive potential diverges is moved to that angle (plus 5 %) when it lies
/// closer to the boundary, and ζ with it, so that the navigation field itself keeps R_g where its
/// moves are admissible.
std::vector<ConeConstraint> robust_cones(const GovernorDesignInputs& in, const RobustMargin& m) {
  const double kp = in.params.gains.kp;
  const double ratio = 1.05 * m.gamma_min / ((1.0 - m.delta) * kp);
  if (!(ratio < 2.0)) {
    no_admissible_set("Gamma_min = " + num(m.gamma_min) + " leaves no attitude inside any cone (kp = " + num(kp) +
                      ")");
  }
  const double gap = std::acos(1.0 - ratio);
  std::vector<ConeConstraint> cones;
  for (std::size_t i = 0; i < in.cones.size(); ++i) {
    cones.push_back(robust_cone(in.cones[i], i, in.bounds.attitude_bias, gap, m.gamma_min));
  }
  return cones;
}

/// The robust part of the design (section 13): e_cmd, the reduced torque limits, the robust
/// margin for them, its admissibility, and the tightened cones, into `d`.
void design_robust(const GovernorDesignInputs& in, GovernorDesign& d) {
  if (!(in.control_period > 0.0)) {
    throw SetupError("robust margins are for the flight loop: set control_period > 0");
  }
  if (in.params.mode == GovernorMode::none) {
    throw SetupError("robust margins are margins of the governor: governor = \"none\" has none");
  }
  RobustMarginInputs r = margin_inputs(in);
  const double e_cmd = command_error_bound(r);
  // The torque limits reduced by the command error: the true state's PD torque must stay within
  // them for the command (sensors, quantisation) to stay within the real ones.
  d.tau_max_reduced = in.params.tau_max - e_cmd;
  if (!(d.tau_max_reduced > 0.0)) {
    no_admissible_set("the command error bound " + num(e_cmd) +
                      " N m (kp sigma_R + kd sigma_omega + quantisation) is not below tau_max = " +
                      num(in.params.tau_max));
  }
  const double lambda_min = lie::lambda_min(in.params.J);
  double gamma_d = compute_torque_threshold({r.kp, r.kd, lambda_min, d.tau_max_reduced}).gamma_d;
  if (!in.wheels.empty()) {
    d.wheel_gamma_d_reduced = reduced_wheel_gamma_d(in, e_cmd);
    gamma_d = std::min(gamma_d, d.wheel_gamma_d_reduced);
  }
  r.gamma_top = std::min(gamma_d, r.kp * (2.0 - r.epsilon_gamma));
  const RobustMargin m = compute_robust_margin(r);
  if (!((1.0 - m.delta) * r.gamma_top > m.gamma_min)) {
    no_admissible_set("Gamma_min = " + num(m.gamma_min) + " of the " + budget(m) +
                      " is not below (1 - delta) Gamma_d' = " + num((1.0 - m.delta) * r.gamma_top) +
                      " (Gamma_d' = " + num(r.gamma_top) +
                      " with the reduced torque limits): reduce the imperfections, the control period or "
                      "raise kp, kd");
  }
  d.cones = robust_cones(in, m);
  d.params.tau_max = d.tau_max_reduced;
  if (!in.wheels.empty()) d.params.polytope_gamma_d = d.wheel_gamma_d_reduced;
  d.params.robust = m;
}

}  // namespace

RobustMarginInputs margin_inputs(const GovernorDesignInputs& in) {
  const ImperfectionBounds& b = in.bounds;
  RobustMarginInputs r;
  r.kp = in.params.gains.kp;
  r.kd = in.params.gains.kd;
  r.J = in.params.J;
  r.control_period = in.control_period;
  r.delay_periods = b.delay_periods;
  r.attitude_bias = b.attitude_bias;
  r.attitude_noise = b.attitude_noise;
  r.rate_error = b.rate_bias + b.rate_noise;
  r.quantisation_error = 0.5 * std::sqrt(3.0) * b.torque_quantum;  // ‖Q(τ) − τ‖ ≤ (√3/2) q
  r.disturbance = b.disturbance;
  r.epsilon_gamma = in.params.epsilon_gamma;
  r.max_reference_step = in.max_reference_step;
  r.applied_torque_max = in.params.tau_max;
  if (!in.wheels.empty()) {
    // ‖A u‖ ≤ σ_max(A) ‖u‖ and ‖A h‖ ≤ σ_max(A) ‖h‖ with |u_i| ≤ u_max,i, |h_i| ≤ h_max,i (the
    // momentum limit is assumed to hold: it is checked, not governed).
    Eigen::Matrix<double, 3, Eigen::Dynamic> A(3, static_cast<Eigen::Index>(in.wheels.size()));
    double u2 = 0.0;
    double h2 = 0.0;
    for (std::size_t i = 0; i < in.wheels.size(); ++i) {
      A.col(static_cast<Eigen::Index>(i)) = in.wheels[i].axis_b.normalized();
      u2 += in.wheels[i].torque_max * in.wheels[i].torque_max;
      h2 += in.wheels[i].momentum_max * in.wheels[i].momentum_max;
    }
    const double sigma_max = std::sqrt(lie::lambda_max(A * A.transpose()));
    r.applied_torque_max = std::min(r.applied_torque_max, sigma_max * std::sqrt(u2));
    r.wheel_momentum_max = sigma_max * std::sqrt(h2);
  }
  return r;
}

WheelPolytope wheel_polytope(const GovernorDesignInputs& in) {
  if (in.wheels.empty()) return {};
  if (!(in.control_period > 0.0)) {
    throw SetupError("reaction wheels act in the flight loop: set [control] control_period > 0");
  }
  const dynamics::ReactionWheelArray array(in.wheels);
  std::vector<Vec3> rows;
  std::vector<double> limits;
  for (int i = 0; i < array.count(); ++i) {
    rows.push_back(array.allocation_row(i));
    limits.push_back(array.wheel(i).torque_max);
  }
  WheelPolytope p;
  const TorqueThreshold t = compute_polytope_torque_threshold(in.params.gains.kp, in.params.gains.kd, in.params.J,
                                                              rows, limits, &p.binding);
  p.gamma_d = t.gamma_d;
  p.gamma_d_upper = t.upper_bound;
  return p;
}

GovernorDesign design(const GovernorDesignInputs& in) {
  GovernorDesign d;
  d.params = in.params;
  d.params.robust.reset();
  d.params.bounded_step = in.control_period > 0.0;
  d.wheels = wheel_polytope(in);
  d.params.polytope_gamma_d = d.wheels.gamma_d;
  d.cones = in.cones;
  if (in.margins == Margins::robust) design_robust(in, d);
  return d;
}

}  // namespace attiguard::governor
