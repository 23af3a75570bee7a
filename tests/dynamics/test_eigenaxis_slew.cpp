// The eigenaxis bang-bang slew time (dynamics/eigenaxis_slew.hpp, docs/pet-erg.md "Outcomes").

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/dynamics/eigenaxis_slew.hpp"

namespace attiguard::dynamics {
namespace {

using lie::Mat3;
using lie::Vec3;

TEST(EigenaxisSlew, PrincipalAxisMatchesTheDoubleIntegratorBangBang) {
  const Mat3 J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  const double theta = 0.5 * std::numbers::pi;
  const double tau_max = 2.5;
  const double T = eigenaxis_bang_bang_time(J, Mat3::Identity(), lie::exp(Vec3(0, theta, 0)), tau_max);
  // Double integrator with acceleration ±α = τ_max / J_yy: θ = α (T/2)².
  const double alpha = tau_max / 2.0;
  EXPECT_NEAR(alpha * (0.5 * T) * (0.5 * T), theta, 1e-12);
}

TEST(EigenaxisSlew, ZeroForNoSlewAndGrowsWithInertiaAlongTheAxis) {
  const Mat3 J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  const Mat3 R = lie::exp(Vec3(0.3, -0.2, 0.1));
  EXPECT_EQ(eigenaxis_bang_bang_time(J, R, R, 1.0), 0.0);
  const double about_x = eigenaxis_bang_bang_time(J, Mat3::Identity(), lie::exp(Vec3(1, 0, 0)), 1.0);
  const double about_z = eigenaxis_bang_bang_time(J, Mat3::Identity(), lie::exp(Vec3(0, 0, 1)), 1.0);
  EXPECT_NEAR(about_z / about_x, std::sqrt(3.0), 1e-12);
}

}  // namespace
}  // namespace attiguard::dynamics
