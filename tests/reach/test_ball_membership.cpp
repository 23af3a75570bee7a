// The soundness check's cheap attitude-ball test (reach/ball_membership.hpp): where it proves a
// rotation inside, the distance lie::distance computes is within the limit, so the check's
// excess max(distance − limit, 0) is the same with and without it; it proves most interior
// points and nothing outside.

#include <gtest/gtest.h>

#include <random>

#include "attiguard/lie/so3.hpp"
#include "attiguard/reach/ball_membership.hpp"

namespace ar = attiguard::reach;
namespace lie = attiguard::lie;

namespace {
lie::Vec3 random_unit(std::mt19937_64& g) {
  std::normal_distribution<double> n(0.0, 1.0);
  return lie::Vec3(n(g), n(g), n(g)).normalized();
}
}  // namespace

// Rotations at distances from 0 to 1.5 limits of a ball, most within 10⁻⁵ relative of the
// limit (where the margin decides): a proof is never wrong, and the clamped excess is the exact
// one bit for bit.
TEST(ReachBallMembership, ProvedInsideImpliesTheComputedDistanceIsWithinTheLimit) {
  std::mt19937_64 g(48);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long proved = 0;
  long inside = 0;
  for (const double limit : {1e-3, 0.01, 0.2, 0.7, 1.0}) {
    const lie::Mat3 C = lie::exp(random_unit(g) * 2.0);
    const ar::AttitudeBallTest test(C, limit);
    for (int k = 0; k < 20000; ++k) {
      const double f = k % 4 == 0 ? 1.5 * u(g) : 1.0 + 1e-5 * (2.0 * u(g) - 1.0);
      const lie::Mat3 R = C * lie::exp(random_unit(g) * (f * limit));
      const double d = lie::distance(C, R);
      if (test.proves_inside(R)) {
        ++proved;
        ASSERT_LE(d, limit) << "limit " << limit << ", f " << f;
      }
      if (d <= limit) ++inside;
      ASSERT_EQ(std::max(test.excess_or_zero(R), 0.0), std::max(d - limit, 0.0));
    }
  }
  EXPECT_GT(proved, inside / 2);  // the interior samples, not those within 10⁻⁶ of the limit
}

// Outside the limits where the margin argument holds (limit < 10⁻³ or > 1) and for non-finite
// rotations the test proves nothing.
TEST(ReachBallMembership, NoProofForTinyOrLargeBallsOrNonFiniteRotations) {
  const lie::Mat3 C = lie::Mat3::Identity();
  EXPECT_FALSE(ar::AttitudeBallTest(C, 5e-4).proves_inside(C));
  EXPECT_FALSE(ar::AttitudeBallTest(C, 1.2).proves_inside(C));
  const ar::AttitudeBallTest test(C, 0.1);
  EXPECT_TRUE(test.proves_inside(lie::exp(lie::Vec3(0.05, 0.0, 0.0))));
  lie::Mat3 bad = C;
  bad(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(test.proves_inside(bad));
  bad(0, 1) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(test.proves_inside(bad));
  EXPECT_FALSE(test.proves_inside(2.0 * C));  // c = 2.5: not a rotation
}
