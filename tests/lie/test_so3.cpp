#include "attiguard/lie/so3.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_support.hpp"

namespace attiguard::lie {
namespace {

using test::random_rotation;
using test::random_vector_in_ball;
using std::numbers::pi;

TEST(So3, HatIsCrossProductAndVeeInvertsIt) {
  for (int i = 0; i < 100; ++i) {
    const Vec3 x = random_vector_in_ball(3.0);
    const Vec3 y = random_vector_in_ball(3.0);
    EXPECT_LT((hat(x) * y - x.cross(y)).norm(), 1e-14);
    EXPECT_EQ(vee(hat(x)), x);
    EXPECT_LT((hat(x) + hat(x).transpose()).norm(), 1e-15);
  }
}

TEST(So3, SkIsTheSkewPart) {
  Mat3 A;
  A << 1, 2, 3, 4, 5, 6, 7, 8, 10;
  const Mat3 S = sk(A);
  EXPECT_LT((S + S.transpose()).norm(), 1e-15);
  EXPECT_LT((S - 0.5 * (A - A.transpose())).norm(), 1e-15);
}

TEST(So3, ExpIsARotationAndMatchesAxisAngle) {
  for (int i = 0; i < 200; ++i) {
    const Vec3 w = random_vector_in_ball(2.0 * pi);
    const Mat3 R = exp(w);
    EXPECT_LT(orthonormality_error(R), 1e-14);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-14);
    if (w.norm() > 0) {
      const Eigen::AngleAxisd aa(w.norm(), w.normalized());
      EXPECT_LT((R - aa.toRotationMatrix()).norm(), 1e-14);
    }
  }
}

TEST(So3, ExpSeriesAgreesWithClosedFormAcrossTheSwitch) {
  // Either side of the θ = 1e-4 series switch the map is continuous to rounding.
  const Vec3 k = Vec3(1, 2, 3).normalized();
  const Mat3 below = exp((1e-4 * (1 - 1e-12)) * k);
  const Mat3 above = exp((1e-4 * (1 + 1e-12)) * k);
  EXPECT_LT((below - above).norm(), 1e-15);
}

TEST(So3, ExpLogRoundTripForRandomRotations) {
  for (int i = 0; i < 1000; ++i) {
    const Mat3 R = random_rotation();
    const Vec3 w = log(R);
    EXPECT_LE(w.norm(), pi + 1e-15);
    EXPECT_LT((exp(w) - R).norm(), 1e-13);
  }
}

class So3SpecialAngle : public ::testing::TestWithParam<double> {};

TEST_P(So3SpecialAngle, ExpLogRoundTrip) {
  const double theta = GetParam();
  for (int i = 0; i < 50; ++i) {
    const Vec3 k = random_vector_in_ball(1.0).normalized();
    const Mat3 R = exp(theta * k);
    const Vec3 w = log(R);
    EXPECT_LT((exp(w) - R).norm(), 1e-13) << "theta=" << theta;
    EXPECT_NEAR(w.norm(), theta, 1e-12 + 1e-9 * theta);
  }
}

INSTANTIATE_TEST_SUITE_P(NearZeroAndNearPi, So3SpecialAngle,
                         ::testing::Values(0.0, 1e-12, 1e-8, 1e-4, 0.5, 2.0, pi - 1e-4,
                                           pi - 1e-9, pi));

TEST(So3, LogAtExactlyPiFromSymmetricMatrix) {
  // R = 2kkᵀ − I is a rotation by exactly π; built without any trigonometry.
  for (int i = 0; i < 50; ++i) {
    const Vec3 k = random_vector_in_ball(1.0).normalized();
    const Mat3 R = 2.0 * k * k.transpose() - Mat3::Identity();
    const Vec3 w = log(R);
    EXPECT_NEAR(w.norm(), pi, 1e-12);
    EXPECT_NEAR(std::abs(w.normalized().dot(k)), 1.0, 1e-12);
    EXPECT_LT((exp(w) - R).norm(), 1e-13);
  }
  // The three coordinate half-turns, where two diagonal entries tie.
  for (int j = 0; j < 3; ++j) {
    const Vec3 k = Vec3::Unit(j);
    const Mat3 R = 2.0 * k * k.transpose() - Mat3::Identity();
    EXPECT_LT((exp(log(R)) - R).norm(), 1e-15);
  }
}

TEST(So3, LogExpRoundTripInsideTheInjectivityRadius) {
  for (int i = 0; i < 1000; ++i) {
    const Vec3 w = random_vector_in_ball(pi - 1e-6);
    EXPECT_LT((log(exp(w)) - w).norm(), 1e-12) << w.transpose();
  }
  // Tiny angles keep full relative accuracy.
  const Vec3 tiny(1e-12, -2e-12, 3e-13);
  EXPECT_LT((log(exp(tiny)) - tiny).norm(), 1e-27);
  // Just below π the sign of the axis is still resolved from the skew part.
  const Vec3 k = Vec3(-0.3, 0.5, 0.81).normalized();
  const Vec3 near_pi = (pi - 1e-9) * k;
  EXPECT_LT((log(exp(near_pi)) - near_pi).norm(), 1e-12);
}

TEST(So3, DistanceIsBiInvariantAndSymmetric) {
  for (int i = 0; i < 100; ++i) {
    const Mat3 A = random_rotation();
    const Mat3 B = random_rotation();
    const Mat3 C = random_rotation();
    const double d = distance(A, B);
    EXPECT_GE(d, 0.0);
    EXPECT_LE(d, pi + 1e-15);
    EXPECT_NEAR(d, distance(B, A), 1e-12);
    EXPECT_NEAR(d, distance(C * A, C * B), 1e-12);
    EXPECT_NEAR(d, distance(A * C, B * C), 1e-12);
  }
}

TEST(So3, PhiIsOneMinusCosine) {
  for (int i = 0; i < 100; ++i) {
    const Vec3 w = random_vector_in_ball(pi);
    EXPECT_NEAR(phi(exp(w)), 1.0 - std::cos(w.norm()), 1e-14);
  }
  EXPECT_EQ(phi(Mat3::Identity()), 0.0);
}

TEST(So3, ProjectionRecoversANearRotation) {
  for (int i = 0; i < 100; ++i) {
    const Mat3 R = random_rotation();
    Mat3 noise = Mat3::Random() * 1e-6;
    const Mat3 P = project_to_so3(R + noise);
    EXPECT_TRUE(is_rotation(P, 1e-13));
    EXPECT_LT((P - R).norm(), 1e-5);
  }
  // A reflection is mapped to a proper rotation.
  const Mat3 reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
  EXPECT_GT(project_to_so3(reflection).determinant(), 0.0);
}

TEST(So3, IsRotationRejectsBadMatrices) {
  EXPECT_TRUE(is_rotation(Mat3::Identity()));
  EXPECT_FALSE(is_rotation(Mat3(Eigen::Vector3d(1, 1, -1).asDiagonal())));
  EXPECT_FALSE(is_rotation(1.001 * Mat3::Identity()));
  Mat3 nan = Mat3::Identity();
  nan(1, 2) = std::nan("");
  EXPECT_FALSE(is_rotation(nan));
}

}  // namespace
}  // namespace attiguard::lie
