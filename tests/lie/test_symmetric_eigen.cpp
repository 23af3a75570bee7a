#include "attiguard/lie/symmetric_eigen.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace attiguard::lie {
namespace {

using test::random_rotation;

TEST(SymmetricEigen, RotatedDiagonalGivesItsEntriesAscending) {
  for (int i = 0; i < 50; ++i) {
    const Mat3 R = random_rotation();
    const Vec3 d(3.0e6, 1.0e-2, 42.0);  // station, CubeSat and in between
    const Mat3 J = R * d.asDiagonal() * R.transpose();
    const Vec3 e = symmetric_eigenvalues(J);
    EXPECT_NEAR(e(0), 1.0e-2, 1e-9 * 3.0e6);
    EXPECT_NEAR(e(1), 42.0, 1e-9 * 3.0e6);
    EXPECT_NEAR(e(2), 3.0e6, 1e-9 * 3.0e6);
    EXPECT_EQ(lambda_min(J), e(0));
    EXPECT_EQ(lambda_max(J), e(2));
  }
}

TEST(SymmetricEigen, OnlyTheSymmetricPartCounts) {
  Mat3 M = Vec3(1.0, 2.0, 5.0).asDiagonal();
  M(0, 1) = 4.0;  // symmetric part has 2 in both off-diagonal places
  M(1, 0) = 0.0;
  Mat3 S = M;
  S(0, 1) = S(1, 0) = 2.0;
  EXPECT_EQ(symmetric_eigenvalues(M), symmetric_eigenvalues(S));
  // A skew matrix has a zero symmetric part.
  EXPECT_EQ(symmetric_eigenvalues(hat(Vec3(1.0, -2.0, 3.0))), Vec3::Zero());
}

}  // namespace
}  // namespace attiguard::lie
