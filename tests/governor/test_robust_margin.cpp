// Robust margins (governor/robust_margin.hpp, docs/pet-erg.md section 13): the certified bound
// Γ_min of the region where Ẇ may be ≥ 0, the inequality Ẇ ≤ −a‖ω‖² − b‖s‖² + c‖s‖‖ω‖ +
// w̄(‖ω‖ + ε‖s‖) on sampled states of SO(3) × R³ (bias, wheel momentum and torque error drawn
// within their bounds, Ẇ by a central difference along the dynamics), invariance of {W ≤ L} for
// L > Γ_min, |W − V| ≤ δV and the measurement margin e_W.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/robust_margin.hpp"
#include "attiguard/governor/torque_threshold.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

struct Sampler {
  std::mt19937_64 gen;
  std::uniform_real_distribution<double> u{0.0, 1.0};
  std::normal_distribution<double> n{0.0, 1.0};
  explicit Sampler(std::uint64_t seed) : gen(seed) {}
  double uniform() { return u(gen); }
  Vec3 unit() { return Vec3(n(gen), n(gen), n(gen)).normalized(); }
  Vec3 in_ball(double r) { return r * std::cbrt(uniform()) * unit(); }
};

/// A random problem: non-diagonal J (triangle inequality), gains, bounds of every imperfection.
struct Problem {
  RobustMarginInputs in;
  RobustMargin m;
};

Problem random_problem(Sampler& s) {
  Problem p;
  Vec3 d(20.0 + 200.0 * s.uniform(), 20.0 + 200.0 * s.uniform(), 20.0 + 200.0 * s.uniform());
  std::sort(d.data(), d.data() + 3);
  d(2) = std::min(d(2), d(0) + d(1));
  const Mat3 Q = lie::exp(3.0 * s.unit());
  p.in.J = Q * d.asDiagonal() * Q.transpose();
  p.in.kp = 0.2 + 3.0 * s.uniform();
  p.in.kd = 2.0 + 15.0 * s.uniform();
  p.in.control_period = 0.01 + 0.2 * s.uniform();
  p.in.delay_periods = s.uniform() < 0.5 ? 0 : 1;
  p.in.attitude_bias = 0.03 * s.uniform();
  p.in.attitude_noise = 1e-3 * s.uniform();
  p.in.rate_error = 1e-4 * s.uniform();
  p.in.quantisation_error = 1e-3 * s.uniform();
  p.in.disturbance = 0.01 * s.uniform();
  p.in.applied_torque_max = 0.1 + s.uniform();
  p.in.wheel_momentum_max = s.uniform() < 0.5 ? 0.0 : 20.0 * s.uniform();
  const double lambda_min =
      Eigen::SelfAdjointEigenSolver<Mat3>(p.in.J, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
  const double tau = 0.05 + 0.5 * s.uniform();
  p.in.gamma_top = std::min(compute_torque_threshold({p.in.kp, p.in.kd, lambda_min, tau}).gamma_d,
                            p.in.kp * (2.0 - p.in.epsilon_gamma));
  p.m = compute_robust_margin(p.in);
  return p;
}

/// A state (R, ω) whose attitude seen through the bias, R B, and rate have V' = ½ωᵀJω +
/// k_p φ((RB)ᵀR_g) ≤ Γ_top, with R_g given.
struct State {
  Mat3 R;
  Vec3 omega;
};

State random_state(Sampler& s, const Problem& p, const Mat3& R_g, const Mat3& B) {
  const double budget = p.in.gamma_top * s.uniform();
  const double split = s.uniform();
  // attitude error: k_p (1 − cos θ) = split · budget
  const double theta = std::acos(std::clamp(1.0 - split * budget / p.in.kp, -1.0, 1.0));
  const Mat3 R_seen = R_g * lie::exp(-theta * s.unit());  // (R_seen)ᵀ R_g = exp(θ k)
  const Vec3 dir = s.unit();
  const Vec3 omega = std::sqrt(2.0 * (1.0 - split) * budget / dir.dot(p.in.J * dir)) * dir;
  return {R_seen * B.transpose(), omega};
}

TEST(UltimateLevelBound, IsAnUpperBoundOfTheRegionAndTightToOneInTenThousand) {
  Sampler s(5);
  for (int trial = 0; trial < 200; ++trial) {
    const double a = 0.1 + 10.0 * s.uniform();
    const double b = 1e-4 + s.uniform();
    const double c = 1.9 * std::sqrt(a * b) * s.uniform();  // 4ab > c²
    const double eps = 1e-4 + 0.1 * s.uniform();
    const double uyy = 100.0 * s.uniform();
    const double uxx = s.uniform();
    const double uxy = s.uniform();
    const double bound = ultimate_level_bound(a, b, c, eps, uyy, uxx, uxy);
    // Dense sampling of the boundary of {Q ≤ y + εx} (every ray's farthest point).
    double sampled = 0.0;
    constexpr int kRays = 200000;
    for (int i = 0; i <= kRays; ++i) {
      const double t = 0.5 * std::numbers::pi * i / kRays;
      const double x = std::cos(t);
      const double y = std::sin(t);
      const double q = a * y * y + b * x * x - c * x * y;
      const double r = (y + eps * x) / q;
      sampled = std::max(sampled, r * r * (uyy * y * y + uxx * x * x + uxy * x * y));
    }
    EXPECT_GE(bound, sampled) << trial;
    EXPECT_LE(bound, sampled * (1.0 + 1e-4)) << trial;
  }
  EXPECT_EQ(ultimate_level_bound(1.0, 1.0, 2.0, 0.1, 1.0, 1.0, 1.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(ultimate_level_bound(1.0, 1.0, 2.5, 0.1, 1.0, 1.0, 1.0), std::numeric_limits<double>::infinity());
}

// The inequality of section 13 on sampled states, with the torque error, the bias and the
// wheels' momentum drawn within their bounds; and the invariance it implies: Ẇ < 0 wherever
// W > Γ_min. Ẇ is a central difference along J ω̇ = (Jω + A h) × ω + k_p s' − k_d ω + w.
TEST(RobustMargin, StrictLyapunovDerivativeObeysItsBoundAndDecreasesAboveGammaMin) {
  Sampler s(2024);
  int above = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Problem p = random_problem(s);
    const RobustMargin& m = p.m;
    ASSERT_GT(m.epsilon, 0.0);
    const Mat3 R_g = lie::exp(3.0 * s.unit());
    for (int k = 0; k < 400; ++k) {
      const Mat3 B = lie::exp(s.in_ball(p.in.attitude_bias));
      const State x = random_state(s, p, R_g, B);
      const Vec3 Ah = s.in_ball(p.in.wheel_momentum_max);
      // the error w: at its bound in a random direction, or exactly along ω
      const Vec3 w = m.torque_error * (k % 3 == 0 && x.omega.norm() > 0 ? x.omega.normalized() : s.unit());
      auto W_of = [&](const Mat3& R, const Vec3& omega) {
        return strict_lyapunov(p.in.J, R * B, omega, R_g, p.in.kp, m.epsilon);
      };
      const Vec3 s_seen = lie::vee(lie::sk((x.R * B).transpose() * R_g));
      const Vec3 tau = p.in.kp * s_seen - p.in.kd * x.omega;
      const Vec3 omega_dot =
          p.in.J.ldlt().solve((p.in.J * x.omega + Ah).cross(x.omega) + tau + w);
      const double h = 1e-6;
      const double W_dot = (W_of(x.R * lie::exp(h * x.omega), x.omega + h * omega_dot) -
                            W_of(x.R * lie::exp(-h * x.omega), x.omega - h * omega_dot)) /
                           (2.0 * h);
      const double xs = s_seen.norm();
      const double y = x.omega.norm();
      const double bound = -m.a * y * y - m.b * xs * xs + m.c * xs * y + w.norm() * (y + m.epsilon * xs);
      const double scale = p.in.gamma_top * 1e-6 + 1e-12;
      EXPECT_LE(W_dot, bound + scale) << "trial " << trial << " state " << k;
      if (W_of(x.R, x.omega) > m.gamma_min * (1.0 + 1e-6)) {
        ++above;
        EXPECT_LT(W_dot, scale) << "trial " << trial << " state " << k;
      }
    }
  }
  EXPECT_GT(above, 1000);  // the invariance claim was exercised
}

TEST(RobustMargin, WIsWithinDeltaOfVAndTheMeasurementMarginBoundsTheComputedLevel) {
  Sampler s(99);
  for (int trial = 0; trial < 60; ++trial) {
    const Problem p = random_problem(s);
    const RobustMargin& m = p.m;
    EXPECT_GT(m.delta, 0.0);
    EXPECT_LT(m.delta, 1.0);
    const Mat3 R_g = lie::exp(3.0 * s.unit());
    for (int k = 0; k < 500; ++k) {
      const State x = random_state(s, p, R_g, Mat3::Identity());
      const double V = control::pd_lyapunov(p.in.J, x.R, x.omega, R_g, {p.in.kp, p.in.kd});
      const double W = strict_lyapunov(p.in.J, x.R, x.omega, R_g, p.in.kp, m.epsilon);
      EXPECT_GE(W, (1.0 - m.delta) * V - 1e-15) << trial;
      EXPECT_LE(W, (1.0 + m.delta) * V + 1e-15) << trial;
      // measured: attitude noise within σ_n, rate error within σ_ω
      const Mat3 R_meas = x.R * lie::exp(s.in_ball(p.in.attitude_noise));
      const Vec3 omega_meas = x.omega + s.in_ball(p.in.rate_error);
      const double W_meas = strict_lyapunov(p.in.J, R_meas, omega_meas, R_g, p.in.kp, m.epsilon);
      EXPECT_LE(std::abs(W_meas - W), m.measurement_margin + 1e-15) << trial;
    }
  }
}

TEST(RobustMargin, TheErrorBudgetAddsUpAndWithoutImperfectionsOnlyTheHoldRemains) {
  Sampler s(7);
  const Problem p = random_problem(s);
  const RobustMargin& m = p.m;
  EXPECT_DOUBLE_EQ(m.torque_error,
                   m.disturbance + m.sensor_error + m.quantisation_error + m.hold_error + m.reference_lag_error);
  EXPECT_DOUBLE_EQ(m.command_error, command_error_bound(p.in));
  RobustMarginInputs clean = p.in;
  clean.attitude_bias = clean.attitude_noise = clean.rate_error = clean.quantisation_error = 0.0;
  clean.disturbance = 0.0;
  clean.delay_periods = 0;
  const RobustMargin c = compute_robust_margin(clean);
  EXPECT_EQ(c.command_error, 0.0);
  EXPECT_EQ(c.reference_lag_error, 0.0);
  EXPECT_EQ(c.max_reference_step, std::numeric_limits<double>::infinity());
  EXPECT_GT(c.hold_error, 0.0);
  EXPECT_DOUBLE_EQ(c.torque_error, c.hold_error);
  // Halving the control period halves the hold error and quarters Γ_min (w̄ is all hold).
  clean.control_period *= 0.5;
  const RobustMargin half = compute_robust_margin(clean);
  EXPECT_NEAR(half.hold_error, 0.5 * c.hold_error, 1e-12 * c.hold_error);
  EXPECT_NEAR(half.gamma_min, 0.25 * c.gamma_min, 1e-9 * c.gamma_min);
}

TEST(RobustMargin, RefusesInputsItCannotUse) {
  RobustMarginInputs in;
  in.control_period = 0.0;
  EXPECT_THROW((void)compute_robust_margin(in), SetupError);
  in.control_period = 0.1;
  in.disturbance = -1.0;
  EXPECT_THROW((void)compute_robust_margin(in), SetupError);
  in.disturbance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW((void)compute_robust_margin(in), SetupError);
  in.disturbance = 0.0;
  in.delay_periods = 2;
  EXPECT_THROW((void)compute_robust_margin(in), SetupError);
  in.delay_periods = 0;
  in.gamma_top = 10.0;  // above k_p (2 − ε_Γ) = 1.9
  EXPECT_THROW((void)compute_robust_margin(in), SetupError);
  in.gamma_top = 0.5;
  EXPECT_NO_THROW((void)compute_robust_margin(in));
}

// The governor with robust margins: Γ_W = (1 − δ)Γ, the level is W, and a move to a reference
// where Γ_W ≤ Γ_min is not taken.
TEST(RobustMargin, TheGovernorComparesWWithTheReducedThresholdAndKeepsRgWhereGammaExceedsGammaMin) {
  GovernorParams params;
  params.gains = {1.0, 4.0};
  params.J = Vec3(10.0, 12.0, 15.0).asDiagonal();
  params.tau_max = 0.5;
  params.kappa = 50.0;
  params.bounded_step = true;
  const std::vector<ConeConstraint> cones{keep_out_cone(Vec3::UnitX(), Vec3(0.0, 1.0, 0.0), 0.5)};
  const AttitudeGovernor nominal(params, cones);
  RobustMarginInputs in;
  in.kp = params.gains.kp;
  in.kd = params.gains.kd;
  in.J = params.J;
  in.control_period = 0.1;
  in.disturbance = 1e-3;
  in.gamma_top = nominal.gamma_d();
  params.robust = compute_robust_margin(in);
  const AttitudeGovernor robust(params, cones);
  const Mat3 R_g = lie::exp(Vec3(0.0, 0.0, 0.3));
  EXPECT_DOUBLE_EQ(robust.gamma(R_g), (1.0 - params.robust->delta) * nominal.gamma(R_g));
  const Vec3 omega(0.01, -0.02, 0.005);
  const Mat3 R = lie::exp(Vec3(0.02, 0.0, 0.28));
  EXPECT_DOUBLE_EQ(robust.level(R, omega, R_g),
                   strict_lyapunov(params.J, R, omega, R_g, 1.0, params.robust->epsilon));
  // Drive the reference towards R_d behind the cone: it stops where Γ_W(R_g) > Γ_min still holds.
  AttitudeGovernor gov(params, cones);
  gov.reset(0.0, Mat3::Identity());
  const Mat3 R_d = lie::exp(Vec3(0.0, 0.0, 2.6));  // +x swept past +y: through the keep-out cone
  for (int k = 0; k < 20000; ++k) {
    (void)gov.step(0.1 * k, gov.reference(), Vec3::Zero(), R_d);
    EXPECT_GT(gov.gamma(gov.reference()), params.robust->gamma_min) << k;
  }
}

}  // namespace
}  // namespace attiguard::governor
