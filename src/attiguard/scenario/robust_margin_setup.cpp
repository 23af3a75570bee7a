// `[control] margins = "robust"` (docs/pet-erg.md, section 13).

#include "attiguard/scenario/robust_margin_setup.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"
#include "attiguard/governor/robust_margin.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/scenario/messages.hpp"

namespace attiguard::scenario {

namespace {


/// "w = … N m (disturbance …, sensors …, quantisation …, hold …, reference lag …)".
std::string budget(const governor::RobustMargin& m) {
  return "torque error bound w = " + detail::format_number(m.torque_error) + " N m (disturbance " + detail::format_number(m.disturbance) +
         ", sensors " + detail::format_number(m.sensor_error) + ", quantisation " + detail::format_number(m.quantisation_error) +
         ", hold " + detail::format_number(m.hold_error) + ", reference lag " + detail::format_number(m.reference_lag_error) + ")";
}

/// The bounds of the flight loop, [imperfections] and [[wheels]] (section 13, "Assumptions").
governor::RobustMarginInputs margin_inputs(const TableReader& control, const sim::PetErgScenario& sc) {
  const sim::PetErgImperfections& im = sc.imperfections;
  governor::RobustMarginInputs in;
  in.kp = sc.params.gains.kp;
  in.kd = sc.params.gains.kd;
  in.J = sc.params.J;
  in.control_period = sc.control_period;
  in.delay_periods = im.delay_periods;
  in.attitude_bias = im.attitude_bias_bound;
  in.attitude_noise = im.sensor.attitude_noise;
  in.rate_error = im.rate_bias_bound + im.sensor.rate_noise;
  in.quantisation_error = 0.5 * std::sqrt(3.0) * im.torque_quantum;  // ‖Q(τ) − τ‖ ≤ (√3/2) q
  in.disturbance = im.disturbance.bound;
  in.epsilon_gamma = sc.params.epsilon_gamma;
  in.max_reference_step = control.number_or("robust_reference_step", 0.0, NumberRule::positive());
  in.applied_torque_max = sc.params.tau_max;
  if (!sc.wheels.empty()) {
    // ‖A u‖ ≤ σ_max(A) ‖u‖ and ‖A h‖ ≤ σ_max(A) ‖h‖ with |u_i| ≤ u_max,i, |h_i| ≤ h_max,i (the
    // momentum limit is assumed to hold: it is checked, not governed).
    Eigen::Matrix<double, 3, Eigen::Dynamic> A(3, static_cast<Eigen::Index>(sc.wheels.size()));
    double u2 = 0.0;
    double h2 = 0.0;
    for (std::size_t i = 0; i < sc.wheels.size(); ++i) {
      A.col(static_cast<Eigen::Index>(i)) = sc.wheels[i].axis_b.normalized();
      u2 += sc.wheels[i].torque_max * sc.wheels[i].torque_max;
      h2 += sc.wheels[i].momentum_max * sc.wheels[i].momentum_max;
    }
    const double sigma_max = std::sqrt(
        lie::lambda_max(A * A.transpose()));
    in.applied_torque_max = std::min(in.applied_torque_max, sigma_max * std::sqrt(u2));
    in.wheel_momentum_max = sigma_max * std::sqrt(h2);
  }
  return in;
}

/// The cones the governor enforces with robust margins (docs/pet-erg.md, section 13): each θ_c
/// tightened by the attitude bias bound β (the true axis lies within β of the axis seen through
/// the bias), the repulsive levels kept at the same offsets from the new boundary; then, as R_g
/// may only stand where Γ_W > Γ_min, i.e. more than gap = arccos(1 − Γ_min/((1 − δ) k_p)) inside
/// each cone, the level δ where the repulsive potential diverges is moved to that angle (plus
/// 5 %) when it lies closer to the boundary, and ζ with it, so that the navigation field itself
/// keeps R_g where its moves are admissible.
std::vector<governor::ConeConstraint> robust_cones(const TableReader& control, const governor::RobustMargin& m,
                                                   double bias, const sim::PetErgScenario& sc) {
  const double ratio = 1.05 * m.gamma_min / ((1.0 - m.delta) * sc.params.gains.kp);
  if (!(ratio < 2.0)) {
    control.fail("margins", "no admissible set with robust margins: Gamma_min = " + detail::format_number(m.gamma_min) +
                                " leaves no attitude inside any cone (kp = " + detail::format_number(sc.params.gains.kp) + ")");
  }
  const double gap = std::acos(1.0 - ratio);
  std::vector<governor::ConeConstraint> cones = sc.cones;
  for (std::size_t i = 0; i < cones.size(); ++i) {
    governor::ConeConstraint& cone = cones[i];
    const double theta_c = cone.theta_c - bias;
    if (!(gap < theta_c)) {
      control.fail("margins", "no admissible set with robust margins: cones[" + std::to_string(i) +
                                  "] (theta_c = " + detail::format_number(cone.theta_c * 180.0 / std::numbers::pi) +
                                  " deg, less the attitude bias bound " + detail::format_number(bias * 180.0 / std::numbers::pi) +
                                  " deg) leaves no attitude " + detail::format_number(gap * 180.0 / std::numbers::pi) +
                                  " deg inside it, as Gamma_min = " + detail::format_number(m.gamma_min) + " needs");
    }
    const double delta_offset = cone.delta - cone.cos_theta_c;
    const double band = cone.zeta - cone.delta;
    cone.theta_c = theta_c;
    cone.cos_theta_c = std::cos(theta_c);
    cone.sin_theta_c = std::abs(std::sin(theta_c));
    cone.delta = std::max(cone.cos_theta_c + delta_offset, std::cos(theta_c - gap));
    cone.zeta = cone.delta + band;
    if (!(cone.zeta < 1.0)) {
      control.fail("margins", "no admissible set with robust margins: the repulsive band of cones[" +
                                  std::to_string(i) + "] moved inwards by the robust gap " +
                                  detail::format_number(gap * 180.0 / std::numbers::pi) + " deg leaves no attitude outside it");
    }
  }
  return cones;
}

}  // namespace

void set_robust_margins(const TableReader& control, sim::PetErgScenario& sc) {
  if (!(sc.control_period > 0.0)) {
    control.fail("margins", "robust margins are for the flight loop: set control_period > 0");
  }
  if (sc.params.mode == governor::GovernorMode::none) {
    control.fail("margins", "robust margins are margins of the governor: governor = \"none\" has none");
  }
  governor::RobustMarginInputs in = margin_inputs(control, sc);
  const double e_cmd = governor::command_error_bound(in);
  const auto no_set = [&](const std::string& why) {
    control.fail("margins", "no admissible set with robust margins: " + why);
  };
  // The torque limits reduced by the command error: the true state's PD torque must stay within
  // them for the command (sensors, quantisation) to stay within the real ones.
  sc.robust_tau_max = sc.params.tau_max - e_cmd;
  if (!(sc.robust_tau_max > 0.0)) {
    no_set("the command error bound " + detail::format_number(e_cmd) + " N m (kp sigma_R + kd sigma_omega + quantisation) is not below tau_max = " +
           detail::format_number(sc.params.tau_max));
  }
  const double lambda_min =
      lie::lambda_min(sc.params.J);
  double gamma_d = 0.0;
  try {
    gamma_d = governor::compute_torque_threshold({in.kp, in.kd, lambda_min, sc.robust_tau_max}).gamma_d;
    if (!sc.wheels.empty()) {
      const dynamics::ReactionWheelArray array(sc.wheels);
      std::vector<lie::Vec3> rows;
      std::vector<double> limits;
      for (int i = 0; i < array.count(); ++i) {
        rows.push_back(array.allocation_row(i));
        limits.push_back(array.wheel(i).torque_max - array.allocation_row(i).norm() * e_cmd);
        if (!(limits.back() > 0.0)) {
          no_set("the command error bound " + detail::format_number(e_cmd) + " N m reaches wheel " + std::to_string(i) +
                 "'s torque limit " + detail::format_number(array.wheel(i).torque_max) + " N m");
        }
      }
      sc.robust_polytope_gamma_d =
          governor::compute_polytope_torque_threshold(in.kp, in.kd, sc.params.J, rows, limits).gamma_d;
      gamma_d = std::min(gamma_d, sc.robust_polytope_gamma_d);
    }
  } catch (const SetupError& e) {
    control.fail("margins", e.what());
  }
  in.gamma_top = std::min(gamma_d, in.kp * (2.0 - in.epsilon_gamma));
  governor::RobustMargin m;
  try {
    m = governor::compute_robust_margin(in);
  } catch (const SetupError& e) {
    control.fail("margins", e.what());
  }
  if (!((1.0 - m.delta) * in.gamma_top > m.gamma_min)) {
    no_set("Gamma_min = " + detail::format_number(m.gamma_min) + " of the " + budget(m) +
           " is not below (1 - delta) Gamma_d' = " + detail::format_number((1.0 - m.delta) * in.gamma_top) +
           " (Gamma_d' = " + detail::format_number(in.gamma_top) +
           " with the reduced torque limits): reduce the imperfections, the control period or "
           "raise kp, kd");
  }
  sc.robust_cones = robust_cones(control, m, in.attitude_bias, sc);
  sc.params.robust = m;
}

void check_robust_desired(const TableReader& desired, const governor::AttitudeGovernor& gov,
                          const sim::PetErgScenario& sc) {
  const governor::RobustMargin& m = *sc.params.robust;
  const std::string key = desired.has("attitude") ? "attitude" : "schedule";
  for (int i = 0; i < sc.desired.size(); ++i) {
    const lie::Mat3& R_d = sc.desired[i].R_d;
    for (std::size_t c = 0; c < sc.robust_cones.size(); ++c) {
      const double cosine = governor::cone_cosine(sc.robust_cones[c], R_d);
      if (cosine < sc.robust_cones[c].zeta) {
        desired.fail(key, "with robust margins this desired attitude lies in the widened repulsive band of cones[" +
                              std::to_string(c) + "] (a_c^T R_d a_b = " + detail::format_number(cosine) + " < zeta = " +
                              detail::format_number(sc.robust_cones[c].zeta) + ", Gamma_min = " + detail::format_number(m.gamma_min) +
                              "): move R_d away from the cone or reduce the imperfections");
      }
    }
    const double G = gov.gamma(R_d);
    if (!(G > m.gamma_min)) {
      desired.fail(key, "with robust margins the reference can never reach this desired attitude: "
                        "Gamma_W(R_d) = " + detail::format_number(G) + " (Gamma_g = " + detail::format_number(gov.gamma_g(R_d)) +
                        ") is not above Gamma_min = " + detail::format_number(m.gamma_min) +
                        ": move R_d away from the cones or reduce the imperfections");
    }
  }
}

std::string robust_initial_problem(const governor::AttitudeGovernor& gov, const sim::PetErgScenario& sc) {
  const governor::RobustMargin& m = *sc.params.robust;
  const double G0 = gov.gamma(sc.R_g0);
  // The analysis runs in the frame seen through the attitude bias B (section 13).
  const lie::Mat3 R0_seen = sc.R0_ib * lie::exp(sc.imperfections.sensor.attitude_bias_b);
  const double W0 = gov.level(R0_seen, sc.omega0_b, sc.R_g0) + m.start_allowance;
  if (G0 > m.gamma_min && W0 <= G0) return {};
  return "initial state not admissible with robust margins: W(0) + start allowance = " + detail::format_number(W0) +
         ", Gamma_W(R_g(0)) = " + detail::format_number(G0) + ", Gamma_min = " + detail::format_number(m.gamma_min) +
         " (needs Gamma_min < Gamma_W(R_g(0)) and W(0) + allowance <= Gamma_W(R_g(0)))";
}

}  // namespace attiguard::scenario
