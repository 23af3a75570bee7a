// The robust margin of the planned mode (docs/pet-erg.md, section 16.3): the L1 norms of the
// error dynamics against an independent integration, the proved peaks against a closed loop
// driven by a torque error at its bound on a CubeSat, the paper's scale and a station, and the
// refusal when the torque error overwhelms the gains.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/governor/robust_tracking_margin.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor::robust_tracking_test {
namespace {

using lie::Mat3;
using lie::Vec3;

/// ∫|c·x(t)| dt of ẋ = A x, x(0) = b, by RK4 with a step of 1/2000 of the slowest time constant
/// and the trapezoid rule (an independent estimate, not a bound).
double l1_by_rk4(double lambda, double kR, double kO, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  Eigen::Matrix2d A;
  A << 0.0, 1.0, -kR / lambda, -kO / lambda;
  const double disc = kO * kO - 4.0 * lambda * kR;
  const double sigma = disc < 0.0 ? kO / (2.0 * lambda) : (kO - std::sqrt(disc)) / (2.0 * lambda);
  const double fast = std::max(kO / lambda, std::sqrt(kR / lambda));
  const double dt = std::min(1.0 / (2000.0 * sigma), 0.01 / fast);
  const int steps = static_cast<int>(60.0 / sigma / dt);
  Eigen::Vector2d x = b;
  double sum = 0.0, prev = std::abs(c.dot(x));
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector2d k1 = A * x, k2 = A * (x + 0.5 * dt * k1), k3 = A * (x + 0.5 * dt * k2), k4 = A * (x + dt * k3);
    x += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    const double now = std::abs(c.dot(x));
    sum += 0.5 * dt * (prev + now);
    prev = now;
  }
  return sum;
}

TEST(RobustTrackingMargin, TheL1NormsBoundAnIndependentIntegrationTightly) {
  // λ from a CubeSat to a station; ζ from 0.3 to 2; ω_n from slow to fast for the craft.
  for (const double lambda : {0.02, 1.0, 4e6}) {
    for (const double zeta : {0.3, 0.8, 2.0}) {
      for (const double omega_n : {0.05, 0.5}) {
        const control::TrackingGains g{lambda * omega_n * omega_n, 2.0 * zeta * lambda * omega_n};
        const TrackingGainsL1 l1 = tracking_l1_gains(lambda * Mat3::Identity(), g);
        const Eigen::Vector2d bw(0.0, 1.0 / lambda), bv(1.0, 0.0);
        const Eigen::Vector2d ce(1.0, 0.0), cz(0.0, 1.0), cu(g.k_R, g.k_Omega);
        const std::pair<double, double> pairs[] = {
            {l1.e_R_w, l1_by_rk4(lambda, g.k_R, g.k_Omega, bw, ce)},
            {l1.e_Omega_w, l1_by_rk4(lambda, g.k_R, g.k_Omega, bw, cz)},
            {l1.u_w, l1_by_rk4(lambda, g.k_R, g.k_Omega, bw, cu)},
            {l1.e_R_v, l1_by_rk4(lambda, g.k_R, g.k_Omega, bv, ce)},
            {l1.e_Omega_v, l1_by_rk4(lambda, g.k_R, g.k_Omega, bv, cz)},
            {l1.u_v, l1_by_rk4(lambda, g.k_R, g.k_Omega, bv, cu)}};
        for (const auto& [bound, estimate] : pairs) {
          EXPECT_GE(bound, estimate * (1.0 - 1e-6)) << lambda << " " << zeta << " " << omega_n;
          EXPECT_LE(bound, estimate * 1.03) << lambda << " " << zeta << " " << omega_n;
        }
        // A constant unit torque error settles the attitude error at 1/k_R: the L1 norm is at least that.
        EXPECT_GE(l1.e_R_w, 1.0 / g.k_R * (1.0 - 1e-9));
      }
    }
  }
}

/// The closed loop under the tracking law with a torque error of size w̄ that turns the error
/// outwards, about a reference turning at a constant rate; returns the peaks of ‖e_R‖, ‖e_Ω‖
/// and ‖k_R e_R + k_Ω e_Ω‖ over `duration`.
struct Peaks {
  double e_R{0.0}, e_Omega{0.0}, u{0.0};
};
Peaks fly_with_torque_error(const Mat3& J, const control::TrackingGains& g, const Vec3& omega_d, double wbar,
                            double duration) {
  Mat3 R = Mat3::Identity();
  Vec3 w = omega_d;
  Mat3 R_d = Mat3::Identity();
  const Mat3 J_inv = J.inverse();
  const double fast = std::max(g.k_Omega / J.diagonal().minCoeff(), std::sqrt(g.k_R / J.diagonal().minCoeff()));
  const double dt = std::min(0.02 / fast, duration / 2e5);
  Peaks p;
  for (double t = 0.0; t < duration; t += dt) {
    const control::TrackingReference ref{R_d, omega_d, Vec3::Zero()};
    const control::TrackingError e = control::tracking_error(R, w, ref);
    p.e_R = std::max(p.e_R, e.e_R.norm());
    p.e_Omega = std::max(p.e_Omega, e.e_Omega.norm());
    p.u = std::max(p.u, (g.k_R * e.e_R + g.k_Omega * e.e_Omega).norm());
    // The torque error pushes along the slowest axis, switching with the rate error's sign
    // (the resonant worst case of a second-order loop).
    const Vec3 axis = Vec3::UnitZ();
    const double s = e.e_Omega.dot(axis) >= 0.0 ? 1.0 : -1.0;
    const Vec3 tau = control::tracking_torque(J, R, w, ref, g) + wbar * s * axis;
    // One semi-implicit step of the rigid body (small dt).
    w += dt * (J_inv * (tau - w.cross(J * w)));
    R = R * lie::exp(dt * w);
    R_d = R_d * lie::exp(dt * omega_d);
  }
  return p;
}

TEST(RobustTrackingMargin, TheProvedPeaksHoldAgainstATorqueErrorAtItsBound) {
  struct Craft {
    Mat3 J;
    double wbar;
  };
  const Craft crafts[] = {{Vec3(0.042, 0.041, 0.0072).asDiagonal(), 2e-5},
                          {Vec3(1.0, 2.0, 3.0).asDiagonal(), 0.01},
                          {Vec3(3e6, 4e6, 5e6).asDiagonal(), 5.0}};
  for (const Craft& c : crafts) {
    const double lmax = c.J.diagonal().maxCoeff();
    const double omega_n = 0.2;
    const control::TrackingGains g{lmax * omega_n * omega_n, 1.6 * lmax * omega_n};
    RobustTrackingInputs in;
    in.gains = g;
    in.J = c.J;
    in.control_period = 1e-6;  // the continuous loop: no hold to speak of
    in.disturbance = c.wbar;
    in.applied_torque_max = 10.0 * lmax * omega_n * omega_n;
    in.reference_rate_max = 0.01;
    const RobustTrackingMargin m = compute_robust_tracking_margin(in);
    const Peaks p = fly_with_torque_error(c.J, g, Vec3(0.0, 0.0, in.reference_rate_max), c.wbar, 30.0 / omega_n);
    EXPECT_LE(p.e_R, m.e_R_max) << lmax;
    EXPECT_LE(p.e_Omega, m.rate_error_max) << lmax;
    EXPECT_LE(p.u, m.feedback_torque_max) << lmax;
    // Not vacuous: the worst case reaches a fair share of the proved peaks.
    EXPECT_GT(p.e_R, 0.3 * m.e_R_max) << lmax;
    EXPECT_GT(p.u, 0.3 * m.feedback_torque_max) << lmax;
  }
}

TEST(RobustTrackingMargin, NoErrorAtAllProvesZeroPeaks) {
  RobustTrackingInputs in;
  in.gains = {1.0, 2.0};
  in.control_period = 0.1;
  const RobustTrackingMargin m = compute_robust_tracking_margin(in);
  EXPECT_EQ(m.e_R_max, 0.0);
  EXPECT_EQ(m.rate_error_max, 0.0);
  EXPECT_EQ(m.feedback_torque_max, 0.0);
}

TEST(RobustTrackingMargin, ATorqueErrorBeyondTheGainsIsRefusedWithItsNumbers) {
  RobustTrackingInputs in;
  in.gains = {0.01, 0.1};
  in.J = Mat3::Identity();
  in.control_period = 0.1;
  in.disturbance = 0.05;  // 5 k_R: the attitude error would settle beyond 60°... and the loop saturates
  in.reference_rate_max = 0.5;
  try {
    (void)compute_robust_tracking_margin(in);
    FAIL() << "accepted";
  } catch (const SetupError& e) {
    EXPECT_NE(std::string(e.what()).find("leaves no bounded tracking error"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("disturbance 0.05"), std::string::npos) << e.what();
  }
}

// With a delay, a run's first period has no torque (a start pulse); a clock started while the
// loop already runs has none (docs/pet-erg.md, section 16.3, "The wait"): its peaks lose the
// pulse's share and nothing else; without a delay the two are the same.
TEST(RobustTrackingMargin, AClockStartedWhileTheLoopRunsHasNoStartPulse) {
  RobustTrackingInputs in;
  in.gains = {0.2, 1.6};
  in.J = Vec3(3.0, 4.0, 5.0).asDiagonal();
  in.control_period = 0.05;
  in.delay_periods = 1;
  in.disturbance = 0.002;
  in.applied_torque_max = 0.1;
  in.reference_rate_max = 0.02;
  in.initial_attitude_error = 0.01;
  in.initial_rate_error = 0.002;
  const RobustTrackingMargin at_start = compute_robust_tracking_margin(in);
  in.torque_from_start = true;
  const RobustTrackingMargin running = compute_robust_tracking_margin(in);
  EXPECT_GT(at_start.start_error, 0.0);
  EXPECT_EQ(running.start_error, 0.0);
  EXPECT_LT(running.e_R_max, at_start.e_R_max);
  EXPECT_LT(running.feedback_torque_max, at_start.feedback_torque_max);
  in.delay_periods = 0;
  const RobustTrackingMargin no_delay_running = compute_robust_tracking_margin(in);
  in.torque_from_start = false;
  const RobustTrackingMargin no_delay = compute_robust_tracking_margin(in);
  EXPECT_EQ(no_delay.e_R_max, no_delay_running.e_R_max);
  EXPECT_EQ(no_delay.feedback_torque_max, no_delay_running.feedback_torque_max);
}

}  // namespace
}  // namespace attiguard::governor::robust_tracking_test
