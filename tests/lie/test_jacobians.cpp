#include "attiguard/lie/jacobians.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "test_support.hpp"

namespace attiguard::lie {
namespace {

using test::numerical_jacobian;
using test::random_vector_in_ball;

// J_r(w) is the derivative of δ ↦ log(exp(w)ᵀ exp(w + δ)) at δ = 0; J_l of log(exp(w+δ) exp(w)ᵀ).
TEST(Jacobians, RightJacobianMatchesFiniteDifferences) {
  for (double r : {1e-6, 1e-3, 0.5, 1.5, 2.5, 3.0}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = random_vector_in_ball(r);
      const Mat3 R0t = exp(w).transpose();
      auto f = [&](const Vec3& d) -> Vec3 { return log(R0t * exp(w + d)); };
      const Eigen::MatrixXd num = numerical_jacobian(f, Vec3::Zero().eval(), 1e-6);
      EXPECT_LT((right_jacobian(w) - num).norm(), 1e-8) << "w=" << w.transpose();
    }
  }
}

TEST(Jacobians, LeftJacobianMatchesFiniteDifferences) {
  for (double r : {1e-6, 1e-3, 0.5, 1.5, 2.5, 3.0}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = random_vector_in_ball(r);
      const Mat3 R0t = exp(w).transpose();
      auto f = [&](const Vec3& d) -> Vec3 { return log(exp(w + d) * R0t); };
      const Eigen::MatrixXd num = numerical_jacobian(f, Vec3::Zero().eval(), 1e-6);
      EXPECT_LT((left_jacobian(w) - num).norm(), 1e-8) << "w=" << w.transpose();
    }
  }
}

TEST(Jacobians, InversesAreInverses) {
  for (double r : {0.0, 1e-9, 1e-5, 1e-4, 0.3, 2.0, 3.1}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = random_vector_in_ball(r);
      EXPECT_LT((left_jacobian(w) * left_jacobian_inverse(w) - Mat3::Identity()).norm(), 1e-12);
      EXPECT_LT((right_jacobian(w) * right_jacobian_inverse(w) - Mat3::Identity()).norm(), 1e-12);
      EXPECT_LT((right_jacobian(w) - left_jacobian(w).transpose()).norm(), 1e-15);
    }
  }
}

TEST(Jacobians, SeriesBranchIsContinuous) {
  const Vec3 k = Vec3(0.2, -0.9, 0.4).normalized();
  const Vec3 below = (1e-4 * (1 - 1e-12)) * k;
  const Vec3 above = (1e-4 * (1 + 1e-12)) * k;
  EXPECT_LT((left_jacobian(below) - left_jacobian(above)).norm(), 1e-12);
  EXPECT_LT((left_jacobian_inverse(below) - left_jacobian_inverse(above)).norm(), 1e-12);
}

TEST(Jacobians, DexpIsTheDerivativeOfExpAlongACurve) {
  // d/dt exp(Ω(t)) = (dexp_Ω Ω̇)^ exp(Ω) (Iserles et al. 2000, Lemma 2.1).
  const Vec3 Omega(0.4, -1.1, 0.7);
  const Vec3 Omega_dot(0.3, 0.2, -0.5);
  const double h = 1e-6;
  const Mat3 dR = (exp(Omega + h * Omega_dot) - exp(Omega - h * Omega_dot)) / (2 * h);
  const Vec3 xi = vee(dR * exp(Omega).transpose());
  EXPECT_LT((xi - dexp(Omega, Omega_dot)).norm(), 1e-9);
  EXPECT_LT((dexpinv(Omega, xi) - Omega_dot).norm(), 1e-9);
}

}  // namespace
}  // namespace attiguard::lie
