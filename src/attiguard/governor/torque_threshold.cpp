#include "attiguard/governor/torque_threshold.hpp"

#include "attiguard/core/errors.hpp"
#include "attiguard/core/finite.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace attiguard::governor {

namespace {

/// c = λ_min / (2 k_d²), the weight of the kinetic term in f.
double kinetic_weight(const TorqueThresholdInputs& in) noexcept {
  return in.lambda_min / (2.0 * in.kd * in.kd);
}

/// f′(θ) = k_p sin θ − 2 c k_p cos θ · max(0, τ_max − k_p sin θ).
double objective_derivative(const TorqueThresholdInputs& in, double theta) noexcept {
  const double s = std::sin(theta);
  const double g = std::max(0.0, in.tau_max - in.kp * s);
  return in.kp * s - 2.0 * kinetic_weight(in) * in.kp * std::cos(theta) * g;
}

/// A number in messages: %.6g.
std::string format_value(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

double torque_threshold_objective(const TorqueThresholdInputs& in, double theta) noexcept {
  const double g = std::max(0.0, in.tau_max - in.kp * std::sin(theta));
  // 1 − cos θ = 2 sin²(θ/2) without cancellation.
  const double half = std::sin(0.5 * theta);
  return in.kp * 2.0 * half * half + kinetic_weight(in) * g * g;
}

TorqueThreshold compute_torque_threshold(const TorqueThresholdInputs& in, double tol) {
  if (!positive_finite(in.kp) || !positive_finite(in.kd) || !positive_finite(in.lambda_min) ||
      !positive_finite(in.tau_max) || !positive_finite(tol)) {
    throw SetupError(
        "torque threshold: kp, kd, lambda_min, tau_max and tol must be positive and finite");
  }
  // Every term of f and f′ must be a normal double: k_p, k_d², c = λ_min/(2k_d²), c·τ_max²
  // and c·k_p·τ_max. Outside that range (e.g. τ_max ≥ 1e155 or k_d = 1e300) f over/underflows
  // and the bisection returns Γ_d = 0: a governor that never moves the reference while the run
  // looks successful (docs/pet-erg.md, "Torque threshold Γ_d", range check).
  const double c = kinetic_weight(in);
  for (const double term : {in.kd * in.kd, c, c * in.tau_max * in.tau_max, c * in.kp * in.tau_max,
                            in.kp * in.kp}) {
    if (!std::isnormal(term)) {
      throw SetupError("torque threshold: kp = " + format_value(in.kp) + ", kd = " +
                       format_value(in.kd) + ", tau_max = " + format_value(in.tau_max) +
                       " and lambda_min(J) = " + format_value(in.lambda_min) +
                       " over/underflow Gamma_d in double precision; rescale the gains and the "
                       "torque limit");
    }
  }
  // f is convex on [0, π/2] (f″ = k_p cos θ + 2c (k_p cos θ)² 1[g>0] + 2c g₊ k_p sin θ ≥ 0),
  // f′(0) = −2c k_p τ_max < 0 and f′(π/2) = k_p > 0: bisection on the sign of f′ brackets the
  // unique minimiser; on [lo, hi] the tangents at lo and hi bound f from below.
  double lo = 0.0;
  double hi = 0.5 * std::numbers::pi;
  double f_lo = torque_threshold_objective(in, lo);
  double f_hi = torque_threshold_objective(in, hi);
  double d_lo = objective_derivative(in, lo);
  double d_hi = objective_derivative(in, hi);
  TorqueThreshold out;
  for (int it = 0; it < 200; ++it) {
    out.iterations = it;
    // Lower bound: the two tangent lines meet at θ_x; convexity gives f ≥ max of the tangents.
    double lower = std::min(f_lo, f_hi);
    if (d_hi - d_lo > 0.0) {
      const double theta_x =
          std::clamp((f_lo - f_hi + d_hi * hi - d_lo * lo) / (d_hi - d_lo), lo, hi);
      lower = std::min(lower, f_lo + d_lo * (theta_x - lo));
    }
    const double upper = std::min(f_lo, f_hi);
    out.gamma_d = lower;
    out.upper_bound = upper;
    out.theta_star = f_lo <= f_hi ? lo : hi;
    if (upper - lower <= tol || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon()) {
      break;
    }
    const double mid = 0.5 * (lo + hi);
    const double d_mid = objective_derivative(in, mid);
    const double f_mid = torque_threshold_objective(in, mid);
    if (d_mid > 0.0) {
      hi = mid;
      f_hi = f_mid;
      d_hi = d_mid;
    } else {
      lo = mid;
      f_lo = f_mid;
      d_lo = d_mid;
    }
  }
  // Rounding of f (a handful of operations on values ≤ k_p + c τ_max²) cannot lift the bound
  // above the exact minimum by more than a few units in the last place of that scale.
  const double scale = in.kp + kinetic_weight(in) * in.tau_max * in.tau_max;
  const double allowance = 16.0 * std::numeric_limits<double>::epsilon() * scale;
  out.gamma_d = std::max(0.0, out.gamma_d - allowance);
  // Γ_d must be resolved: a bound of which the rounding allowance is more than 0.1 %, or that is
  // not a normal number, is noise, not a threshold.
  if (!std::isnormal(out.gamma_d) || out.gamma_d <= 1e3 * allowance) {
    throw SetupError("torque threshold: Gamma_d = " + format_value(out.gamma_d) +
                     " is not resolved in double precision (scale k_p + lambda_min tau_max^2/(2 "
                     "k_d^2) = " + format_value(scale) + ") for kp = " + format_value(in.kp) +
                     ", kd = " + format_value(in.kd) + ", tau_max = " + format_value(in.tau_max) +
                     "; rescale the gains and the torque limit");
  }
  return out;
}

double torque_threshold_loose(const TorqueThresholdInputs& in) noexcept {
  return in.tau_max * in.tau_max / (2.0 * in.kp + 2.0 * in.kd * in.kd / in.lambda_min);
}

}  // namespace attiguard::governor
