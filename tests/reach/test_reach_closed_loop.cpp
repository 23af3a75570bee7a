// Analytic A, B of Theorem 4 against finite differences, and soundness of the enclosures.

#include <gtest/gtest.h>

#include <Eigen/SVD>

#include <memory>
#include <vector>

#include "attiguard/reach/closed_loop.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::lie::exp;
using attiguard::test::random_rotation;
using attiguard::test::random_vector_in_ball;

namespace {
std::vector<std::shared_ptr<ar::ClosedLoop>> loops() {
  const ar::Mat3 J = ar::Vec3(1.0, 2.0, 3.0).asDiagonal();
  return {std::make_shared<ar::LinearOmegaLoop>(ar::Vec3(-2, -1, -3).asDiagonal()),
          std::make_shared<ar::RigidBodyLoop>(J, ar::Vec3::Zero()),
          std::make_shared<ar::RigidBodyLoop>(J, ar::Vec3(0.1, -0.2, 0.05)),
          std::make_shared<ar::PdLoop>(J, 2.0, 3.0, exp(ar::Vec3(0.1, 0.2, 0.3)))};
}
}  // namespace

TEST(ReachClosedLoop, AnalyticABMatchFiniteDifferences) {
  const double h = 1e-6;
  for (const auto& loop : loops()) {
    for (int k = 0; k < 50; ++k) {
      const ar::Mat3 R = random_rotation();
      const ar::Vec3 w = random_vector_in_ball(2.0);
      ar::Mat3 Afd, Bfd;
      for (int j = 0; j < 3; ++j) {
        const ar::Vec3 e = ar::Vec3::Unit(j);
        Afd.col(j) = (loop->omega_dot(R * exp(h * e), w) - loop->omega_dot(R * exp(-h * e), w)) / (2 * h);
        Bfd.col(j) = (loop->omega_dot(R, w + h * e) - loop->omega_dot(R, w - h * e)) / (2 * h);
      }
      EXPECT_LT((loop->A(R, w) - Afd).norm(), 1e-7) << loop->name();
      EXPECT_LT((loop->B(R, w) - Bfd).norm(), 1e-7) << loop->name();
    }
  }
}

TEST(ReachClosedLoop, EnclosuresContainSampledValues) {
  for (const auto& loop : loops()) {
    for (int k = 0; k < 20; ++k) {
      const ar::AttitudeBall att{random_rotation(), 0.3 * (k % 4)};
      const ar::Vec3 c = random_vector_in_ball(1.0);
      const ar::Box3 box = ar::Box3::around(c, ar::Vec3(0.1, 0.2, 0.05));
      const ar::IntervalMat3 A = loop->A_enclosure(att, box);
      const ar::IntervalMat3 B = loop->B_enclosure(att, box);
      const ar::Box3 F = loop->omega_dot_enclosure(att, box);
      const ar::LmiEnclosure lmi = loop->lmi_enclosure(att, box);
      for (int s = 0; s < 200; ++s) {
        const ar::Mat3 R = att.center * exp(random_vector_in_ball(att.radius));
        ar::Vec3 w;
        for (int j = 0; j < 3; ++j) {
          w(j) = box.lo(j) + (box.hi(j) - box.lo(j)) * (0.5 + 0.5 * ar::Vec3::Random()(0));
        }
        ASSERT_TRUE(A.contains(loop->A(R, w), 1e-12)) << loop->name();
        ASSERT_TRUE(B.contains(loop->B(R, w), 1e-12)) << loop->name();
        ASSERT_TRUE(F.contains(loop->omega_dot(R, w), 1e-12)) << loop->name();
        // ‖A − A_v‖ ≤ ρ with the vertices' A (all equal to the centre for every built-in loop).
        Eigen::JacobiSVD<ar::Mat3> svd(loop->A(R, w) - lmi.vertices.front().A);
        EXPECT_LE(svd.singularValues()(0), lmi.rho + 1e-12) << loop->name();
      }
    }
  }
}
