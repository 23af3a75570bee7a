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

// A diagonal J takes the path without the products by its zeros: the same bits as the dense
// products J⁻¹((J ω) × ω + τ) (docs/performance.md, "Lean core (issue 48, item 2)"); a rotated J
// takes the dense path.
TEST(RigidBody, DiagonalInertiaGivesTheDenseProductsBitForBit) {
  const Mat3 Q = test::random_rotation();
  const Mat3 rotated = Q * diag(1, 2, 3) * Q.transpose();
  for (const Mat3& J : {diag(1, 2, 3), diag(0.02, 0.03, 0.025), Mat3(0.5 * (rotated + rotated.transpose()))}) {
    const RigidBody body(J);
    for (int i = 0; i < 200; ++i) {
      const Vec3 w = test::random_vector_in_ball(i % 2 == 0 ? 3.0 : 1e-3);
      const Vec3 tau = test::random_vector_in_ball(1.0);
      const Vec3 dense =
          body.inertia_inverse() * ((body.inertia() * w).cross(w) + tau);
      const Vec3 got = body.angular_acceleration(w, tau);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(got(k), dense(k));
    }
  }
}

}  // namespace
}  // namespace attiguard::dynamics
