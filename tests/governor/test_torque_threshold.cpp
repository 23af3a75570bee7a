// Γ_d of the PET-ERG paper (Sec. III-B.1): the exact 1-D reduction, its certified computation,
// brute-force sampling of SO(3) × R³, and the loose closed-form bound.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <tuple>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "test_support.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

/// A random symmetric positive-definite inertia R diag(J) Rᵀ satisfying the triangle inequality.
Mat3 random_inertia(std::mt19937_64& gen) {
  std::uniform_real_distribution<double> u(0.5, 5.0);
  Vec3 d(u(gen), u(gen), u(gen));
  std::sort(d.data(), d.data() + 3);
  if (d(2) > d(0) + d(1)) {
    d(2) = d(0) + d(1);
  }
  const Mat3 R = test::random_rotation();
  return R * d.asDiagonal() * R.transpose();
}

double lambda_min(const Mat3& J) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(J, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
}

/// V and ‖τ‖ of the PD law (3) at the error R_e = RᵀR_g (take R_g = I, R = R_eᵀ) and ω.
struct VTau {
  double V;
  double tau;
};
VTau v_tau(const Mat3& J, const control::PdGains& g, const Mat3& R_e, const Vec3& omega) {
  const Mat3 R = R_e.transpose();
  const Mat3 R_g = Mat3::Identity();
  return {control::pd_lyapunov(J, R, omega, R_g, g), control::pd_torque(R, omega, R_g, g).norm()};
}

TEST(TorqueThreshold, PaperScenarioValueBracketsAndBeatsLooseBound) {
  const TorqueThresholdInputs in{5.0, 1.0, 1.0, 2.5};
  const TorqueThreshold th = compute_torque_threshold(in);
  EXPECT_LE(th.gamma_d, th.upper_bound);
  EXPECT_LE(th.upper_bound - th.gamma_d, 1e-9);
  EXPECT_NEAR(th.gamma_d, 0.54082229701, 1e-9);
  EXPECT_GT(th.gamma_d, torque_threshold_loose(in));
  EXPECT_NEAR(torque_threshold_loose(in), 2.5 * 2.5 / 12.0, 1e-15);
  // The initial state of the paper's Sec. V (V(0) = 0.35) lies below Γ_d.
  EXPECT_GT(th.gamma_d, 0.35);
}

TEST(TorqueThreshold, OneDimensionalReductionMatchesDenseGrid) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(0.1, 10.0);
  for (int trial = 0; trial < 200; ++trial) {
    const TorqueThresholdInputs in{u(gen), u(gen), u(gen), u(gen)};
    const TorqueThreshold th = compute_torque_threshold(in);
    double grid_min = std::numeric_limits<double>::infinity();
    double grid_arg = 0.0;
    const int n = 20000;
    const double h = 0.5 * std::numbers::pi / n;
    for (int i = 0; i <= n; ++i) {
      const double f = torque_threshold_objective(in, i * h);
      if (f < grid_min) {
        grid_min = f;
        grid_arg = i * h;
      }
    }
    // Refine around the best grid point with a second dense grid.
    for (int i = -10000; i <= 10000; ++i) {
      const double theta = std::clamp(grid_arg + i * h / 10000.0, 0.0, 0.5 * std::numbers::pi);
      grid_min = std::min(grid_min, torque_threshold_objective(in, theta));
    }
    // Also the branch θ ∈ (π/2, π] can never be lower.
    for (int i = 0; i <= 2000; ++i) {
      const double theta = 0.5 * std::numbers::pi * (1.0 + static_cast<double>(i) / 2000);
      EXPECT_GE(torque_threshold_objective(in, theta), th.gamma_d);
    }
    EXPECT_LE(th.gamma_d, grid_min) << "trial " << trial;  // never overestimates
    EXPECT_LE(th.upper_bound - th.gamma_d, 1e-9) << "trial " << trial;  // accurate to 1e-9
    EXPECT_LE(grid_min - th.gamma_d, 1e-9) << "trial " << trial;
    EXPECT_GE(th.gamma_d, torque_threshold_loose(in) - 1e-15) << "trial " << trial;
  }
}

TEST(TorqueThreshold, NoSampledBoundaryStateOfSO3xR3LiesBelowGammaD) {
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(0.2, 8.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const Mat3 J = random_inertia(gen);
    const control::PdGains g{u(gen), u(gen)};
    const double tau_max = u(gen);
    const TorqueThresholdInputs in{g.kp, g.kd, lambda_min(J), tau_max};
    const double gamma_d = compute_torque_threshold(in).gamma_d;
    Eigen::SelfAdjointEigenSolver<Mat3> eig(J);
    const Vec3 e_min = eig.eigenvectors().col(0);
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s < 5000; ++s) {
      // Attitude error: uniform, or concentrated at small angles where the minimum lies.
      const Mat3 R_e = s % 2 == 0 ? test::random_rotation()
                                  : lie::exp(test::random_vector_in_ball(1.6 * unit(gen)));
      // ω direction: uniform, or close to the least-inertia axis (where the minimum lies).
      Vec3 dir = test::random_vector_in_ball(1.0).normalized();
      if (s % 3 == 0) {
        dir = (e_min * (unit(gen) < 0.5 ? 1.0 : -1.0) + 0.05 * dir).normalized();
      }
      // Smallest |ω| along dir with ‖k_p s − k_d |ω| dir‖ = τ_max (or ω = 0 if already there).
      const Vec3 sv = g.kp * lie::vee(lie::sk(R_e));
      double r = 0.0;
      if (sv.norm() < tau_max) {
        const double b = -2.0 * g.kd * sv.dot(dir);
        const double c = sv.squaredNorm() - tau_max * tau_max;
        r = (-b + std::sqrt(b * b - 4.0 * g.kd * g.kd * c)) / (2.0 * g.kd * g.kd);
      }
      const VTau vt = v_tau(J, g, R_e, r * dir);
      EXPECT_GE(vt.tau, tau_max * (1.0 - 1e-9));
      EXPECT_GE(vt.V, gamma_d) << "trial " << trial << " sample " << s;
      best = std::min(best, vt.V);
      // Any state beyond the boundary along the same ray has a larger V as well.
      const VTau beyond = v_tau(J, g, R_e, (r + unit(gen)) * dir);
      if (beyond.tau >= tau_max) {
        EXPECT_GE(beyond.V, gamma_d);
      }
    }
    // The bound is tight: the optimal state of the reduction sits on the boundary at V ≈ Γ_d.
    const TorqueThreshold th = compute_torque_threshold(in);
    const double theta = th.theta_star;
    const double r_opt = std::max(0.0, tau_max - g.kp * std::sin(theta)) / g.kd;
    const Mat3 R_e = lie::exp(-theta * e_min);  // axis k = −ω/‖ω‖
    const VTau opt = v_tau(J, g, R_e, r_opt * e_min);
    EXPECT_NEAR(opt.tau, tau_max, 1e-9 * tau_max);
    EXPECT_NEAR(opt.V, gamma_d, 1e-8);
    EXPECT_GE(best, gamma_d);
  }
}

TEST(TorqueThreshold, RejectsInvalidInputs) {
  EXPECT_THROW((void)compute_torque_threshold({0.0, 1.0, 1.0, 1.0}), SetupError);
  EXPECT_THROW((void)compute_torque_threshold({1.0, 1.0, -1.0, 1.0}), SetupError);
  EXPECT_THROW((void)compute_torque_threshold({1.0, 1.0, 1.0, std::nan("")}), SetupError);
}

// Issue 14: τ_max ≥ 1e155 (τ_max² overflows) or k_p, k_d = 1e300 gave Γ_d = 0 and a run that
// never moved but reported success; such inputs are refused. Large but representable values
// still work.
TEST(TorqueThreshold, RejectsParametersWhoseGammaDOverOrUnderflows) {
  const TorqueThresholdInputs paper{5.0, 1.0, 1.0, 2.5};
  for (const auto& [kp, kd, tau_max] : {std::tuple{5.0, 1.0, 1e155}, std::tuple{1e300, 1.0, 2.5},
                                        std::tuple{5.0, 1e300, 2.5}, std::tuple{1e300, 1e300, 2.5},
                                        std::tuple{5.0, 1.0, 1e-170}, std::tuple{5.0, 1e-170, 2.5}}) {
    TorqueThresholdInputs in = paper;
    in.kp = kp;
    in.kd = kd;
    in.tau_max = tau_max;
    EXPECT_THROW((void)compute_torque_threshold(in), SetupError) << kp << " " << kd << " " << tau_max;
  }
  for (const double tau_max : {1e-3, 1e3, 1e6}) {
    TorqueThresholdInputs in = paper;
    in.tau_max = tau_max;
    const TorqueThreshold t = compute_torque_threshold(in);
    EXPECT_GT(t.gamma_d, 0.0);
    EXPECT_LE(t.gamma_d, t.upper_bound);
  }
}

}  // namespace
}  // namespace attiguard::governor
