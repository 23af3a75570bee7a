// Γ_g of the PET-ERG paper (Sec. III-B.1) and the cone constraint (2b): the closed form is the
// exact geometric bound (safe and tight), keep-out cones, several cones.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "test_support.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;


TEST(ConeConstraint, KeepOutConeIsTheComplementOfAKeepInCone) {
  std::uniform_real_distribution<double> u(0.05, 1.5);
  for (int i = 0; i < 500; ++i) {
    const Vec3 axis_b = test::random_unit();
    const Vec3 sun_i = test::random_unit();
    const double alpha = u(test::rng());
    const ConeConstraint cone = keep_out_cone(axis_b, sun_i, alpha);
    const Mat3 R = test::random_rotation();
    const double angle_to_sun = std::acos(std::clamp(sun_i.dot(R * axis_b), -1.0, 1.0));
    EXPECT_EQ(pointing_margin(cone, R) >= 0.0, angle_to_sun >= alpha - 1e-12 ? true : false)
        << angle_to_sun << " " << alpha;
    EXPECT_NEAR(pointing_margin(cone, R), std::cos(alpha) - std::cos(angle_to_sun), 1e-12);
  }
}

TEST(PointingThreshold, PaperValueAtIdentity) {
  const ConeConstraint cone =
      keep_in_cone(Vec3(0, 0, 1), Vec3(-0.791, 0.061, -0.609), 160.0 * std::numbers::pi / 180.0);
  const double beta = std::acos(Vec3(-0.791, 0.061, -0.609).normalized()(2));
  EXPECT_NEAR(pointing_threshold(cone, Mat3::Identity(), 5.0),
              5.0 * (1.0 - std::cos(160.0 * std::numbers::pi / 180.0 - beta)), 1e-12);
  EXPECT_NEAR(cone.delta, std::cos(160.0 * std::numbers::pi / 180.0) + 0.05, 1e-15);
  EXPECT_NEAR(cone.zeta, cone.delta + 0.05, 1e-15);
}

// The geometry decides: on {k_p φ(RᵀR_g) ≤ Γ_g(R_g)} the constraint holds (safe), and the worst
// attitude of that set touches the cone (tight). A threshold that used β_g in place of θ_c − β_g,
// or the angle instead of 1 − cos, would fail one of the two checks.
TEST(PointingThreshold, IsTheExactGeometricBound) {
  std::uniform_real_distribution<double> angle(0.3, std::numbers::pi);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double kp = 3.0;
  int tested = 0;
  for (int i = 0; i < 400; ++i) {
    const ConeConstraint cone = keep_in_cone(test::random_unit(), test::random_unit(), angle(test::rng()));
    const Mat3 R_g = test::random_rotation();
    const double gamma_g = pointing_threshold(cone, R_g, kp);
    if (pointing_margin(cone, R_g) <= 0.0) {
      EXPECT_EQ(gamma_g, 0.0);
      continue;
    }
    ++tested;
    ASSERT_GT(gamma_g, 0.0);
    // Largest rotation angle allowed by V ≤ Γ_g (V ≥ k_p φ): 1 − cos θ_max = Γ_g / k_p.
    const double theta_max = std::acos(std::clamp(1.0 - gamma_g / kp, -1.0, 1.0));
    for (int s = 0; s < 200; ++s) {
      const Vec3 axis = test::random_unit();
      const double theta = theta_max * std::cbrt(unit(test::rng()));
      const Mat3 R = R_g * lie::exp(theta * axis);
      EXPECT_GE(pointing_margin(cone, R), -1e-12);
    }
    // Tightness: rotating R_g a_b away from a_c by θ_max in their common plane reaches the cone.
    const Vec3 b_i = R_g * cone.axis_b;
    const Vec3 n = cone.direction_i.cross(b_i);
    if (n.norm() > 1e-6) {
      const Mat3 R_worst = lie::exp(theta_max * n.normalized()) * R_g;
      EXPECT_NEAR(lie::phi(R_worst.transpose() * R_g), gamma_g / kp, 1e-12);
      EXPECT_NEAR(pointing_margin(cone, R_worst), 0.0, 1e-9);
    }
  }
  EXPECT_GT(tested, 100);
}

TEST(PointingThreshold, SeveralConesTakeTheMinimumAndNoConeIsInfinite) {
  const Mat3 R_g = lie::exp(Vec3(0.2, -0.4, 0.1));
  ConeSet set;
  const ConeConstraint a = keep_out_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 0.3);
  const ConeConstraint b = keep_out_cone(Vec3(1, 0, 0), Vec3(0, 1, 0), 0.5);
  const ConeConstraint c = keep_in_cone(Vec3(0, 1, 0), Vec3(0, 1, 0), 1.2);
  ASSERT_TRUE(set.push_back(a));
  ASSERT_TRUE(set.push_back(b));
  ASSERT_TRUE(set.push_back(c));
  const double expected = std::min({pointing_threshold(a, R_g, 2.0), pointing_threshold(b, R_g, 2.0),
                                    pointing_threshold(c, R_g, 2.0)});
  EXPECT_DOUBLE_EQ(pointing_threshold(set.span(), R_g, 2.0), expected);
  EXPECT_TRUE(std::isinf(pointing_threshold(std::span<const ConeConstraint>{}, R_g, 2.0)));
  EXPECT_DOUBLE_EQ(aggregate_threshold(0.5, 0.7, 5.0, 0.1), 0.5);
  EXPECT_DOUBLE_EQ(aggregate_threshold(20.0, 30.0, 5.0, 0.1), 9.5);
  for (int i = 3; i < kMaxCones; ++i) {
    EXPECT_TRUE(set.push_back(a));
  }
  EXPECT_FALSE(set.push_back(a));
  EXPECT_EQ(set.size(), kMaxCones);
}

TEST(ConeConstraint, ValidationRejectsBadLevels) {
  EXPECT_FALSE(cone_error(keep_in_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 2.0)).has_value());
  // A keep-in cone so narrow that δ ≥ 1.
  EXPECT_TRUE(cone_error(keep_in_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 0.1)).has_value());
  EXPECT_TRUE(cone_error(keep_in_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 2.0, -0.1)).has_value());
}

}  // namespace
}  // namespace attiguard::governor
