// Γ_d of a torque polytope {|r_iᵀτ| ≤ u_i} (governor/polytope_torque_threshold.hpp,
// docs/pet-erg.md section 12): never above the V of a state whose PD torque leaves the polytope,
// and attained by the constructed minimiser.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

struct Polytope {
  std::vector<Vec3> rows;
  std::vector<double> limits;
};

Polytope wheel_polytope(std::span<const dynamics::ReactionWheel> wheels) {
  const dynamics::ReactionWheelArray array(wheels);
  Polytope p;
  for (int i = 0; i < array.count(); ++i) {
    p.rows.push_back(array.allocation_row(i));
    p.limits.push_back(array.wheel(i).torque_max);
  }
  return p;
}

/// max_i |r_iᵀτ| / u_i: ≥ 1 outside the polytope.
double exit_ratio(const Polytope& p, const Vec3& tau) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.rows.size(); ++i) m = std::max(m, std::abs(p.rows[i].dot(tau)) / p.limits[i]);
  return m;
}

TEST(PolytopeTorqueThreshold, NoStateOutsideThePolytopeLiesBelowGammaDAndTheMinimiserAttainsIt) {
  std::mt19937_64 gen(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n(0.0, 1.0);
  auto unit = [&] { return Vec3(n(gen), n(gen), n(gen)).normalized(); };
  for (int trial = 0; trial < 30; ++trial) {
    Vec3 d(50.0 + 100.0 * u(gen), 50.0 + 100.0 * u(gen), 50.0 + 100.0 * u(gen));
    const Mat3 Q = lie::exp(3.0 * unit());
    const Mat3 J = Q * d.asDiagonal() * Q.transpose();
    const control::PdGains gains{0.5 + 5.0 * u(gen), 5.0 + 30.0 * u(gen)};
    std::vector<dynamics::ReactionWheel> wheels;
    const int count = 3 + static_cast<int>(3 * u(gen));
    for (int i = 0; i < count; ++i) wheels.push_back({unit(), 0.05 + 0.3 * u(gen), 10.0, 0.0});
    Polytope p;
    try {
      p = wheel_polytope(wheels);
    } catch (const SetupError&) {
      continue;  // axes (nearly) coplanar
    }
    int slab = -1;
    const TorqueThreshold t = compute_polytope_torque_threshold(gains.kp, gains.kd, J, p.rows, p.limits, &slab);
    ASSERT_GT(t.gamma_d, 0.0);
    ASSERT_LE(t.gamma_d, t.upper_bound);
    // The minimiser of the binding slab: R_e = exp(θ* n̂), ω = −ρ J⁻¹n / (nᵀJ⁻¹n).
    const Vec3 nv = p.rows[static_cast<std::size_t>(slab)].normalized();
    const double tau_i = p.limits[static_cast<std::size_t>(slab)] / p.rows[static_cast<std::size_t>(slab)].norm();
    const double rho = std::max(0.0, tau_i - gains.kp * std::sin(t.theta_star)) / gains.kd;
    const Vec3 Jn = J.inverse() * nv;
    const Vec3 omega = -rho * Jn / nv.dot(Jn);
    const Mat3 R = lie::exp(-t.theta_star * nv);  // R_g = I: R_e = Rᵀ = exp(θ* n̂)
    const Vec3 tau = control::pd_torque(R, omega, Mat3::Identity(), gains);
    EXPECT_NEAR(std::abs(nv.dot(tau)), tau_i, 1e-9 * tau_i);
    EXPECT_NEAR(control::pd_lyapunov(J, R, omega, Mat3::Identity(), gains), t.upper_bound,
                1e-8 * t.upper_bound);
    // Random states scaled onto the polytope's boundary never have V < Γ_d.
    for (int k = 0; k < 3000; ++k) {
      const Mat3 Rk = lie::exp((std::numbers::pi * std::cbrt(u(gen))) * unit());
      const Vec3 w = (0.01 * n(gen)) * unit();
      const Vec3 tk = control::pd_torque(Rk, w, Mat3::Identity(), gains);
      const double ratio = exit_ratio(p, tk);
      if (ratio < 1.0) {
        // Scale ω up along itself until the torque leaves the polytope (if it can).
        bool out = false;
        Vec3 ws = w;
        for (int g = 0; g < 60 && !out; ++g) {
          ws *= 1.25;
          out = exit_ratio(p, control::pd_torque(Rk, ws, Mat3::Identity(), gains)) >= 1.0;
        }
        if (!out) continue;
        EXPECT_GE(control::pd_lyapunov(J, Rk, ws, Mat3::Identity(), gains), t.gamma_d);
      } else {
        EXPECT_GE(control::pd_lyapunov(J, Rk, w, Mat3::Identity(), gains), t.gamma_d);
      }
    }
  }
}

TEST(PolytopeTorqueThreshold, OneSlabPerAxisOfADiagonalBodyIsTheBallThresholdPerAxis) {
  // Rows e_x, e_y, e_z with limit τ and J = diag(1, 2, 3): slab x has λ = 1/(e_xᵀJ⁻¹e_x) = 1,
  // the smallest, so Γ_d is the ball threshold of (k_p, k_d, λ_min = 1, τ).
  const Mat3 J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  const std::vector<Vec3> rows{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  const std::vector<double> limits{2.5, 2.5, 2.5};
  int slab = -1;
  const TorqueThreshold t = compute_polytope_torque_threshold(5.0, 1.0, J, rows, limits, &slab);
  EXPECT_EQ(slab, 0);
  EXPECT_EQ(t.gamma_d, compute_torque_threshold({5.0, 1.0, 1.0, 2.5}).gamma_d);
  EXPECT_THROW((void)compute_polytope_torque_threshold(5.0, 1.0, J, rows, std::vector<double>{1.0}),
               SetupError);
}

}  // namespace
}  // namespace attiguard::governor
