#include "attiguard/lie/quaternion.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "attiguard/lie/axis_angle.hpp"
#include "attiguard/lie/shortest_arc.hpp"
#include "test_support.hpp"

namespace attiguard::lie {
namespace {

using test::random_rotation;
using test::random_vector_in_ball;
using std::numbers::pi;

Quat random_quat() {
  Quat q = rotation_to_quat(random_rotation());
  return q;
}

TEST(Quaternion, ConventionIsScalarFirstRotatingByTheta) {
  // q = [cos(θ/2), k sin(θ/2)] rotates by θ about k: a quarter turn about z maps x to y.
  const Quat q = quat_from_axis_angle(Vec3::UnitZ(), pi / 2);
  EXPECT_NEAR(q(0), std::cos(pi / 4), 1e-15);
  EXPECT_LT((quat_to_rotation(q) * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);
}

TEST(Quaternion, ProductMatrixIsTheHamiltonProduct) {
  for (int i = 0; i < 100; ++i) {
    const Quat p = random_quat();
    const Quat q = random_quat();
    EXPECT_LT((quat_product_matrix(p) * q - quat_multiply(p, q)).norm(), 1e-15);
    // Agrees with Eigen's Hamilton product through the named conversions.
    EXPECT_LT((from_eigen(to_eigen(p) * to_eigen(q)) - quat_multiply(p, q)).norm(), 1e-15);
  }
}

TEST(Quaternion, QuaternionAndMatrixProductsAgree) {
  for (int i = 0; i < 200; ++i) {
    const Quat p = random_quat();
    const Quat q = random_quat();
    const Mat3 Rpq = quat_to_rotation(quat_multiply(p, q));
    EXPECT_LT((Rpq - quat_to_rotation(p) * quat_to_rotation(q)).norm(), 1e-14);
    EXPECT_LT((quat_to_rotation(quat_conjugate(p)) - quat_to_rotation(p).transpose()).norm(),
              1e-14);
  }
}

TEST(Quaternion, MatrixRoundTripForEveryBranchOfShepperd) {
  for (int i = 0; i < 500; ++i) {
    const Mat3 R = random_rotation();
    const Quat q = rotation_to_quat(R);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_GE(q(0), 0.0);
    EXPECT_LT((quat_to_rotation(q) - R).norm(), 1e-14);
  }
  for (int j = 0; j < 3; ++j) {  // half-turns exercise the ε-dominant branches
    const Mat3 R = exp(pi * Vec3::Unit(j));
    EXPECT_LT((quat_to_rotation(rotation_to_quat(R)) - R).norm(), 1e-14);
  }
}

TEST(Quaternion, RotationVectorRoundTrip) {
  for (double r : {0.0, 1e-12, 1e-6, 1.0, pi - 1e-6}) {
    for (int i = 0; i < 20; ++i) {
      const Vec3 w = random_vector_in_ball(r);
      const Quat q = quat_from_rotation_vector(w);
      EXPECT_NEAR(q.norm(), 1.0, 1e-15);
      EXPECT_LT((rotation_vector_from_quat(q) - w).norm(), 1e-12);
      EXPECT_LT((rotation_vector_from_quat(-q) - w).norm(), 1e-12);  // double cover
      EXPECT_LT((quat_to_rotation(q) - exp(w)).norm(), 1e-14);
    }
  }
}

TEST(AxisAngle, ConversionsAgreeWithExpAndLog) {
  for (int i = 0; i < 100; ++i) {
    const Mat3 R = random_rotation();
    const AxisAngle aa = axis_angle_from_rotation(R);
    EXPECT_NEAR(aa.axis.norm(), 1.0, 1e-14);
    EXPECT_LT((rotation_from_axis_angle(aa) - R).norm(), 1e-13);
    EXPECT_LT((rotation_vector(aa) - log(R)).norm(), 1e-15);
  }
  EXPECT_EQ(axis_angle_from_rotation(Mat3::Identity()).angle, 0.0);
}

TEST(ShortestArc, MapsAOntoBInEveryConfiguration) {
  for (int i = 0; i < 500; ++i) {
    const Vec3 a = random_vector_in_ball(5.0);
    const Vec3 b = random_vector_in_ball(5.0);
    const Mat3 R = shortest_arc(a, b);
    EXPECT_LT((R * a.normalized() - b.normalized()).norm(), 1e-13);
    // Shortest: the rotation angle is the angle between the vectors.
    EXPECT_NEAR(log(R).norm(), std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)),
                1e-7);
  }
}

TEST(ShortestArc, ParallelAndAntiParallelStayDefined) {
  for (int i = 0; i < 100; ++i) {
    const Vec3 a = random_vector_in_ball(1.0).normalized();
    EXPECT_LT((shortest_arc(a, 3.0 * a) - Mat3::Identity()).norm(), 1e-15);
    const Mat3 flip = shortest_arc(a, -a);
    EXPECT_TRUE(is_rotation(flip, 1e-13));
    EXPECT_LT((flip * a + a).norm(), 1e-14);
    // Nearly anti-parallel: still a rotation mapping a onto b.
    const Vec3 b = (-a + 1e-10 * any_orthogonal(a)).normalized();
    const Mat3 near = shortest_arc(a, b);
    EXPECT_TRUE(is_rotation(near, 1e-12));
    EXPECT_LT((near * a - b).norm(), 1e-9);
  }
  EXPECT_EQ(shortest_arc(Vec3::Zero(), Vec3::UnitX()), Mat3::Identity());
}

}  // namespace
}  // namespace attiguard::lie
