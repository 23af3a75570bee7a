#include "attiguard/dynamics/rigid_body.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/core/errors.hpp"
#include "test_support.hpp"

namespace attiguard::dynamics {
namespace {

Mat3 diag(double a, double b, double c) { return Vec3(a, b, c).asDiagonal(); }

TEST(Inertia, AcceptsPhysicalBodiesInAnyOrientation) {
  EXPECT_FALSE(inertia_error(diag(1, 2, 3)));
  EXPECT_FALSE(inertia_error(diag(1, 1, 2)));  // thin disc: J1 + J2 = J3 exactly
  for (int i = 0; i < 50; ++i) {
    const Mat3 R = test::random_rotation();
    EXPECT_FALSE(inertia_error(R * diag(2, 3, 4) * R.transpose()));
  }
}

TEST(Inertia, RejectsNonPhysicalMatrices) {
  EXPECT_TRUE(inertia_error(diag(1, 2, -3)));          // indefinite
  EXPECT_TRUE(inertia_error(diag(-2, -1, -3)));        // negative definite
  EXPECT_TRUE(inertia_error(diag(1, 1, 3)));           // triangle inequality
  EXPECT_TRUE(inertia_error(Mat3::Zero()));
  Mat3 asym = diag(1, 2, 3);
  asym(0, 1) = 0.5;
  EXPECT_TRUE(inertia_error(asym));
  Mat3 nan = diag(1, 2, 3);
  nan(2, 2) = std::nan("");
  EXPECT_TRUE(inertia_error(nan));
  EXPECT_NE(inertia_error(diag(1, 1, 3))->find("triangle"), std::string::npos);
  EXPECT_THROW(RigidBody{diag(1, 2, -3)}, InputError);
}

TEST(RigidBody, EulerEquationsMatchTheFormula) {
  const RigidBody body(diag(1, 2, 3));
  const Vec3 w(0.2, 0.3, 0.4);
  const Vec3 tau(0.1, -0.2, 0.05);
  // J ω̇ = (J ω) × ω + τ (PET-ERG paper, eq. (1)), component-wise Euler equations.
  const Vec3 wd = body.angular_acceleration(w, tau);
  EXPECT_NEAR(wd(0), ((2 - 3) * w(1) * w(2) + tau(0)) / 1.0, 1e-15);
  EXPECT_NEAR(wd(1), ((3 - 1) * w(2) * w(0) + tau(1)) / 2.0, 1e-15);
  EXPECT_NEAR(wd(2), ((1 - 2) * w(0) * w(1) + tau(2)) / 3.0, 1e-15);
  EXPECT_NEAR(body.min_principal_moment(), 1.0, 1e-14);
  EXPECT_NEAR(body.max_principal_moment(), 3.0, 1e-14);
}

}  // namespace
}  // namespace attiguard::dynamics
