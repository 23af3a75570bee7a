// The planner's exact derivatives against finite differences (docs/slew-planner.md,
// "Derivatives"), and the cone's quaternion form against the rotation matrix.
#include <gtest/gtest.h>

#include <random>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/plan/cone_quadratic.hpp"
#include "attiguard/plan/point_dynamics.hpp"

namespace attiguard::plan::point_dynamics_test {
namespace {

lie::Mat3 asymmetric_inertia() {
  lie::Mat3 J;
  J << 2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 0.8;
  return J;
}

PointVector random_point(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  PointVector z;
  for (int i = 0; i < 10; ++i) z(i) = n(rng);
  return z;
}

TEST(PointDynamics, JacobianMatchesFiniteDifferences) {
  const PointDynamics dyn(asymmetric_inertia());
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const PointVector z = random_point(rng);
    const PointJacobian F = dyn.jacobian(z);
    const double h = 1e-6;
    for (int j = 0; j < 10; ++j) {
      PointVector zp = z, zm = z;
      zp(j) += h;
      zm(j) -= h;
      const StateVector fd = (dyn.f(zp) - dyn.f(zm)) / (2.0 * h);
      for (int i = 0; i < 7; ++i) EXPECT_NEAR(F(i, j), fd(i), 1e-7) << i << "," << j;
    }
  }
}

TEST(PointDynamics, HessianMatchesFiniteDifferencesOfTheJacobian) {
  const PointDynamics dyn(asymmetric_inertia());
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const PointVector z = random_point(rng);
    StateVector lambda;
    for (int i = 0; i < 7; ++i) lambda(i) = std::normal_distribution<double>(0.0, 1.0)(rng);
    const PointHessian H = dyn.hessian(lambda);
    EXPECT_LT((H - H.transpose()).norm(), 1e-14);
    const double h = 1e-6;
    for (int j = 0; j < 10; ++j) {
      PointVector zp = z, zm = z;
      zp(j) += h;
      zm(j) -= h;
      const Eigen::Matrix<double, 1, 10> fd =
          lambda.transpose() * (dyn.jacobian(zp) - dyn.jacobian(zm)) / (2.0 * h);
      for (int i = 0; i < 10; ++i) EXPECT_NEAR(H(j, i), fd(i), 1e-7) << j << "," << i;
    }
  }
}

TEST(ConeQuadratic, EqualsTheCosineOfTheRotatedAxisForUnitQuaternions) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const lie::Vec3 a_b = lie::Vec3(n(rng), n(rng), n(rng)).normalized();
    const lie::Vec3 a_c = lie::Vec3(n(rng), n(rng), n(rng)).normalized();
    const lie::Quat q = lie::Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
    const Eigen::Matrix4d M = cone_quadratic(a_b, a_c);
    EXPECT_NEAR(q.dot(M * q), a_c.dot(lie::quat_to_rotation(q) * a_b), 1e-14);
    // Homogeneous: a scaled quaternion scales the form by its squared norm.
    const lie::Quat q3 = 3.0 * q;
    EXPECT_NEAR(q3.dot(M * q3), 9.0 * a_c.dot(lie::quat_to_rotation(q) * a_b), 1e-12);
  }
}

}  // namespace
}  // namespace attiguard::plan::point_dynamics_test
