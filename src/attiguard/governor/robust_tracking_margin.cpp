#include "attiguard/governor/robust_tracking_margin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Core>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/finite.hpp"
#include "attiguard/core/four_digits.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::governor {

namespace {

using Mat2 = Eigen::Matrix2d;
using Vec2 = Eigen::Vector2d;

/// Throws SetupError("robust planned margins: what") unless ok.
void require_tracking(bool ok, const std::string& what) {
  if (!ok) throw SetupError("robust planned margins: " + what);
}

constexpr double kTimeConstants = 40.0;   ///< horizon of the L1 integrals, in slowest time constants
constexpr int kMinCells = 8000;           ///< cells of the L1 integrals, at least
constexpr int kMaxCells = 400000;
constexpr double kCellStiffness = 0.005;  ///< the fastest pole's rate times Δ at most this (if kMaxCells allows)
constexpr int kFixedPointIterations = 400;
constexpr double kSuperSolution = 1e-3;   ///< the fixed point is inflated by this and checked strict
constexpr double kThetaCap = std::numbers::pi / 3.0;  ///< 60°: ‖C − I‖ = sin(θ/2) holds below it

/// exp(M) of a 2×2 matrix by scaling and squaring of its Taylor series (‖M‖ ≤ 1/2 after scaling,
/// 20 terms: below rounding).
Mat2 exp2(const Mat2& M) {
  int squarings = 0;
  double norm = M.cwiseAbs().rowwise().sum().maxCoeff();
  while (norm > 0.5) {
    norm *= 0.5;
    ++squarings;
  }
  const Mat2 A = M / std::ldexp(1.0, squarings);
  Mat2 term = Mat2::Identity();
  Mat2 sum = Mat2::Identity();
  for (int k = 1; k <= 20; ++k) {
    term = term * A / k;
    sum += term;
  }
  for (int i = 0; i < squarings; ++i) sum = sum * sum;
  return sum;
}

/// The slowest decay rate of λ s² + k_Ω s + k_R [1/s].
double slowest_decay(double lambda, const control::TrackingGains& g) {
  const double disc = g.k_Omega * g.k_Omega - 4.0 * lambda * g.k_R;
  if (disc < 0.0) return g.k_Omega / (2.0 * lambda);
  return (g.k_Omega - std::sqrt(disc)) / (2.0 * lambda);
}

/// The L1 norms and peaks from the integrals and peaks [input: w, v, z][output: e, z, u]
/// (docs/pet-erg.md, section 16.3); a free response's peak includes t = 0.
TrackingGainsL1 l1_from(const std::array<std::array<double, 3>, 3>& integral,
                        const std::array<std::array<double, 3>, 3>& peak, const control::TrackingGains& gains) {
  TrackingGainsL1 g;
  g.e_R_w = integral[0][0];
  g.e_Omega_w = integral[0][1];
  g.u_w = integral[0][2];
  g.e_R_v = integral[1][0];
  g.e_Omega_v = integral[1][1];
  g.u_v = integral[1][2];
  g.e_R_w_peak = peak[0][0];
  g.e_Omega_w_peak = peak[0][1];
  g.u_w_peak = peak[0][2];
  g.e_R_from_e = std::max(1.0, peak[1][0]);
  g.e_Omega_from_e = peak[1][1];
  g.u_from_e = std::max(gains.k_R, peak[1][2]);
  g.e_R_from_z = peak[2][0];
  g.e_Omega_from_z = std::max(1.0, peak[2][1]);
  g.u_from_z = std::max(gains.k_Omega, peak[2][2]);
  return g;
}

}  // namespace

TrackingGainsL1 tracking_l1_gains(const lie::Mat3& J, const control::TrackingGains& gains) {
  const lie::Vec3 moments = lie::symmetric_eigenvalues(J);
  require_tracking(positive_finite(moments(0)), "the inertia must be positive definite");
  double sigma = std::numeric_limits<double>::infinity();
  double rate = 0.0;    // the fastest pole's magnitude
  double A_norm = 0.0;
  std::array<Mat2, 3> A;
  for (int i = 0; i < 3; ++i) {
    const double lambda = moments(i);
    A[static_cast<std::size_t>(i)] << 0.0, 1.0, -gains.k_R / lambda, -gains.k_Omega / lambda;
    sigma = std::min(sigma, slowest_decay(lambda, gains));
    rate = std::max({rate, gains.k_Omega / lambda, std::sqrt(gains.k_R / lambda)});
    A_norm = std::max(A_norm, A[static_cast<std::size_t>(i)].norm());
  }
  require_tracking(positive_finite(sigma), "the tracking gains must make the error dynamics stable");
  const double T = kTimeConstants / sigma;
  const int cells = std::clamp(static_cast<int>(std::ceil(T * rate / kCellStiffness)), kMinCells, kMaxCells);
  const double dt = T / cells;
  // On a cell |h(t)| ≤ the linear interpolant of |h| at its ends + Δ²/8 sup|h''|, and
  // sup|h''| ≤ ‖c A²‖ ‖x_j‖ e^{‖A‖Δ}: the trapezoid of |h| plus Δ³/8 of that bounds ∫|h|.
  const double curvature = dt * dt / 8.0 * std::exp(A_norm * dt);
  const Vec2 c_e(1.0, 0.0), c_z(0.0, 1.0), c_u(gains.k_R, gains.k_Omega);
  const std::array<Vec2, 3> outputs{c_e, c_z, c_u};
  // Nine responses per mode: outputs e, z, u of the impulses from w (b = (0, 1/λ)) and from v
  // (b = (1, 0), also the free response from a unit e_R) and of the free response from a unit e_Ω.
  std::array<Mat2, 3> Phi;
  std::array<std::array<Vec2, 3>, 3> x;  // [mode][input: w, v, z]
  std::array<std::array<double, 3>, 3> cA2{};  // [mode][output] ‖c A²‖
  for (std::size_t i = 0; i < 3; ++i) {
    Phi[i] = exp2(A[i] * dt);
    x[i] = {Vec2(0.0, 1.0 / moments(static_cast<int>(i))), Vec2(1.0, 0.0), Vec2(0.0, 1.0)};
    for (std::size_t o = 0; o < 3; ++o) cA2[i][o] = (outputs[o].transpose() * A[i] * A[i]).norm();
  }
  std::array<std::array<double, 3>, 3> integral{}, peak{}, previous{};  // [input][output]
  const auto sample = [&](std::array<std::array<double, 3>, 3>& now, std::array<std::array<double, 3>, 3>& slack) {
    for (std::size_t in = 0; in < 3; ++in) {
      for (std::size_t o = 0; o < 3; ++o) {
        now[in][o] = 0.0;
        slack[in][o] = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
          now[in][o] = std::max(now[in][o], std::abs(outputs[o].dot(x[i][in])));
          slack[in][o] = std::max(slack[in][o], curvature * cA2[i][o] * x[i][in].norm());
        }
      }
    }
  };
  std::array<std::array<double, 3>, 3> slack{};
  sample(previous, slack);
  for (int j = 0; j < cells; ++j) {
    std::array<std::array<double, 3>, 3> before_slack = slack;
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t in = 0; in < 3; ++in) x[i][in] = Phi[i] * x[i][in];
    }
    std::array<std::array<double, 3>, 3> now{};
    sample(now, slack);
    for (std::size_t in = 0; in < 3; ++in) {
      for (std::size_t o = 0; o < 3; ++o) {
        integral[in][o] += dt * (0.5 * (previous[in][o] + now[in][o]) + before_slack[in][o]);
        peak[in][o] = std::max(peak[in][o], std::max(previous[in][o], now[in][o]) + before_slack[in][o]);
      }
    }
    previous = now;
  }
  // The tail beyond 40 time constants: the states have decayed by e^-40; each integral gains
  // at most the last state's size times the horizon (a generous allowance).
  for (std::size_t in = 0; in < 3; ++in) {
    for (std::size_t o = 0; o < 3; ++o) {
      double last = 0.0;
      for (std::size_t i = 0; i < 3; ++i) last = std::max(last, outputs[o].norm() * x[i][in].norm());
      integral[in][o] += last * T;
    }
  }
  return l1_from(integral, peak, gains);
}

namespace {

void require_valid(const RobustTrackingInputs& in) {
  require_tracking(positive_finite(in.gains.k_R) && positive_finite(in.gains.k_Omega),
                   "the tracking gains must be positive and finite");
  require_tracking(positive_finite(in.control_period), "needs the flight loop: control_period > 0");
  require_tracking(in.delay_periods == 0 || in.delay_periods == 1, "delay_periods must be 0 or 1");
  for (const double x : {in.attitude_bias, in.attitude_noise, in.rate_error, in.quantisation_error,
                         in.disturbance, in.wheel_momentum_max, in.reference_rate_max, in.reference_accel_max,
                         in.reference_jerk_max, in.reference_end_accel, in.initial_attitude_error,
                         in.initial_rate_error, in.total_momentum_max}) {
    require_tracking(non_negative_finite(x), "error bounds and reference extremes must be finite and non-negative");
  }
  require_tracking(positive_finite(in.applied_torque_max), "the applied torque bound must be positive");
}

/// The peaks the budget is evaluated at: θ, ‖e_R‖ ≤ x, ‖e_Ω‖ ≤ y, ‖k_R e_R + k_Ω e_Ω‖ ≤ u.
struct Peaks {
  double x{0.0}, y{0.0}, u{0.0};
  double W{0.0};  ///< ‖w‖ ≤ W, the torque error
};

/// Constants of the craft used by the budget.
struct Craft {
  double lmin{0.0}, lmax{0.0};
  double bias{0.0};  ///< 2 sin(β/2) = ‖Bᵀ − I‖
};

/// Δθ, Δω: the error of the state the torque is computed for (measured; with d = 1 predicted
/// one period ahead by a midpoint step under the acting torque and the wheels' momentum)
/// (docs/pet-erg.md, section 16.3, "Error budget").
void state_errors(const RobustTrackingInputs& in, const Craft& k, const Peaks& p, double w, double Hb,
                  double& d_theta, double& d_omega) {
  const double h = in.control_period;
  d_theta = in.attitude_noise;
  d_omega = in.rate_error;
  if (in.delay_periods == 0) return;
  // ‖ω̇‖ ≤ ‖ė_Ω‖ + ‖d/dt(R_e ω_d)‖ ≤ (‖u‖ + ‖w‖)/λ_min + ‖ω‖‖ω_d‖ + ‖ω̇_d‖ along the tracked flight.
  const double ad = (p.u + p.W) / k.lmin + w * in.reference_rate_max + in.reference_accel_max;
  d_omega += h * (h * in.applied_torque_max * w + in.disturbance + in.quantisation_error) / k.lmin +
             h * ((Hb + k.lmax * (w + in.rate_error + h * ad)) / k.lmin) * (in.rate_error + 2.0 * h * ad);
  // R: exp is 1-Lipschitz; ∫Bᵀω against h ω̃_m, and the first Magnus term (generously).
  d_theta += h * (in.rate_error + k.bias * w + 2.0 * h * ad) + h * h * h * w * ad;
}

/// The torque-error budget at the peaks p into m; returns ‖w‖'s bound (docs/pet-erg.md, section
/// 16.3, "Error budget").
double torque_error_at(const RobustTrackingInputs& in, const Craft& k, const Peaks& p, RobustTrackingMargin& m) {
  const double kR = in.gains.k_R;
  const double kO = in.gains.k_Omega;
  const double h = in.control_period;
  const double wd = in.reference_rate_max;
  const double wdd = in.reference_accel_max;
  const double w = wd + p.y;  // ≥ ‖ω‖
  const double rigid = k.lmax * w + in.wheel_momentum_max;
  const double Hb = in.total_momentum_max > 0.0 ? std::min(rigid, in.total_momentum_max) : rigid;
  double d_theta = 0.0, d_omega = 0.0;
  state_errors(in, k, p, w, Hb, d_theta, d_omega);
  const double L_omega = kO + Hb + k.lmax * (w + d_omega + wd);
  const double L_R = kR + (kO + k.lmax * (w + d_omega)) * wd + k.lmax * wdd;
  m.state_error = L_R * d_theta + L_omega * d_omega;
  m.quantisation_error = in.quantisation_error;
  m.command_error = m.state_error + m.quantisation_error;
  // The held command's staleness over h: d/dt of F = −k_R e_R − k_Ω e_Ω + ω × H_b − J ω̂ R_e ω_d
  // (J R_e ω̇_d is taken at the hold's middle): ‖ė_R‖ ≤ ‖e_Ω‖ + ‖v‖, ‖ė_Ω‖ ≤ (‖u‖ + ‖w‖)/λ_min,
  // ‖ω̇‖ ≤ ‖ė_Ω‖ + ‖ω‖‖ω_d‖ + ‖ω̇_d‖, d/dt(ω × H_b) ≤ ‖ω̇‖‖H_b‖ + ‖ω‖(‖ω‖‖H_b‖ + d̄ + τ_ext).
  const double G = Hb + k.lmax * wd;
  const double tau_ext = in.wheel_momentum_max > 0.0 ? 0.0 : in.applied_torque_max;
  const double v = m.kinematic_error;
  const double stale = kR * (p.y + v) + (kO + G) * p.u / k.lmin + G * (w * wd + wdd) +
                       w * (w * Hb + in.disturbance + tau_ext) + k.lmax * w * (w * wd + wdd) +
                       k.lmax * (w + wd) * wdd;
  const double hold = h * stale + 0.5 * h * k.lmax * in.reference_jerk_max;
  m.wheel_error = in.wheel_momentum_max > 0.0 ? (1.0 + in.delay_periods) * h * in.applied_torque_max * w : 0.0;
  m.bias_error = k.lmax * k.bias * w * wd;
  m.disturbance = in.disturbance;
  const double gain = h * (kO + G) / k.lmin;  // the staleness driven by ‖w‖ itself
  const double rest = m.disturbance + m.command_error + hold + m.wheel_error + m.bias_error;
  const double total = gain < 1.0 ? rest / (1.0 - gain) : std::numeric_limits<double>::infinity();
  m.hold_error = hold + (total - rest);
  m.torque_error = total;
  return total;
}

/// One application of the bounds: the peaks that the budget at p implies (docs/pet-erg.md,
/// section 16.3, "Fixed point").
Peaks bound_peaks(const RobustTrackingInputs& in, const Craft& k, const Peaks& p, RobustTrackingMargin& m) {
  const TrackingGainsL1& g = m.l1;
  const double theta = std::asin(std::min(1.0, p.x));
  m.kinematic_error = std::sin(0.5 * theta) * p.y + k.bias * (in.reference_rate_max + p.y);
  const double W = torque_error_at(in, k, p, m);
  // The free response of the initial error: in the eigenbasis of J each mode's response to its
  // share of e_R(0) and e_Ω(0), so ‖e(t)‖ ≤ max_i |φ_i(t)| ‖e(0)‖ and likewise from e_Ω(0).
  const double x0 = std::sin(std::min(in.initial_attitude_error, 0.5 * std::numbers::pi));
  const double y0 = in.initial_rate_error;
  const double x_free = g.e_R_from_e * x0 + g.e_R_from_z * y0;
  const double y_free = g.e_Omega_from_e * x0 + g.e_Omega_from_z * y0;
  const double u_free = g.u_from_e * x0 + g.u_from_z * y0;
  // Pulses: zero torque over the first d periods (the law's torque missing), and the
  // feedforward's drop over at most one period at the plan's end.
  const double w0 = in.reference_rate_max + y_free;
  const double start_pulse = in.torque_from_start ? 0.0 : in.delay_periods * in.control_period *
                             (u_free + (k.lmax * w0 + in.wheel_momentum_max) * w0 + W);
  const double end_pulse = in.control_period * k.lmax * in.reference_end_accel;
  m.start_error = start_pulse * g.e_R_w_peak;
  m.end_error = end_pulse * g.e_R_w_peak;
  const double pulses = start_pulse + end_pulse;
  Peaks q;
  q.x = x_free + g.e_R_w * W + g.e_R_v * m.kinematic_error + pulses * g.e_R_w_peak;
  q.y = y_free + g.e_Omega_w * W + g.e_Omega_v * m.kinematic_error + pulses * g.e_Omega_w_peak;
  q.u = u_free + g.u_w * W + g.u_v * m.kinematic_error + pulses * g.u_w_peak;
  q.W = W;
  return q;
}

}  // namespace

RobustTrackingMargin compute_robust_tracking_margin(const RobustTrackingInputs& in) {
  require_valid(in);
  return compute_robust_tracking_margin(in, tracking_l1_gains(in.J, in.gains));
}

RobustTrackingMargin compute_robust_tracking_margin(const RobustTrackingInputs& in, const TrackingGainsL1& l1) {
  require_valid(in);
  const lie::Vec3 moments = lie::symmetric_eigenvalues(in.J);
  Craft k;
  k.lmin = moments(0);
  k.lmax = moments(2);
  require_tracking(positive_finite(k.lmin) && positive_finite(k.lmax), "the inertia must be positive definite");
  k.bias = 2.0 * std::sin(0.5 * std::min(in.attitude_bias, std::numbers::pi));
  RobustTrackingMargin m;
  m.l1 = l1;
  const double x_cap = std::sin(kThetaCap);
  // The least fixed point, from below (every bound is monotone in the peaks).
  Peaks p;
  bool converged = false;
  for (m.iterations = 1; m.iterations <= kFixedPointIterations; ++m.iterations) {
    const Peaks q = bound_peaks(in, k, p, m);
    if (!(q.x <= x_cap) || !std::isfinite(q.y) || !std::isfinite(q.u)) break;
    const bool settled = q.x <= p.x * (1.0 + 1e-12) && q.y <= p.y * (1.0 + 1e-12) && q.u <= p.u * (1.0 + 1e-12) &&
                         q.W <= p.W * (1.0 + 1e-12);
    p = q;
    if (settled) {
      converged = true;
      break;
    }
  }
  // Certified: at the inflated point the bounds are strictly below it, so the peaks, continuous
  // from below it at t = 0, can never reach it.
  const double up = 1.0 + kSuperSolution;
  const Peaks top{p.x * up, p.y * up, p.u * up, p.W * up};
  RobustTrackingMargin at_top = m;
  const Peaks check = converged ? bound_peaks(in, k, top, at_top) : Peaks{};
  // (A component that the bounds leave at zero is zero: no error drives it.)
  const auto below = [](double bound, double at) { return bound < at || (bound == 0.0 && at == 0.0); };
  const bool strict = converged && top.x <= x_cap && below(check.x, top.x) && below(check.y, top.y) &&
                      below(check.u, top.u) && check.W <= top.W;
  require_tracking(strict, "the imperfections' torque error w = " + four_digits(m.torque_error) + " N m (hold " +
                               four_digits(m.hold_error) + ", state " + four_digits(m.state_error) +
                               ", disturbance " + four_digits(m.disturbance) + ") leaves no bounded tracking "
                               "error below 60 deg for k_R = " + four_digits(in.gains.k_R) + " N m, k_Omega = " +
                               four_digits(in.gains.k_Omega) + " N m s");
  at_top.e_R_max = top.x;
  at_top.attitude_error_max = std::asin(top.x);
  at_top.rate_error_max = top.y;
  at_top.feedback_torque_max = top.u;
  return at_top;
}

}  // namespace attiguard::governor
