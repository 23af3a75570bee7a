// The comparison-system state (reach/deviation.hpp): its vector layout z = (d_1, d_2, d_3, e_ω,
// e_R) (docs/reach.md, "Enclosure U_i", step 2), which the tube's 5×5 comparison matrix indexes,
// and the componentwise operations the tube and ConReach use.

#include <gtest/gtest.h>

#include <limits>

#include "attiguard/reach/deviation.hpp"

namespace ar = attiguard::reach;

TEST(ReachDeviation, VectorIsDOmegaThenEOmegaThenER) {
  const ar::Deviation d{attiguard::lie::Vec3(1.0, 2.0, 3.0), 4.0, 5.0};
  const ar::Deviation::Vector z = d.vector();
  for (int k = 0; k < 5; ++k) EXPECT_EQ(z(k), k + 1.0) << k;
  const ar::Deviation back = ar::Deviation::from_vector(z);
  EXPECT_EQ(back.d_omega_b, d.d_omega_b);
  EXPECT_EQ(back.e_omega_b, 4.0);
  EXPECT_EQ(back.e_R, 5.0);
  EXPECT_TRUE(back == d);
}

TEST(ReachDeviation, DefaultIsZero) {
  const ar::Deviation d;
  EXPECT_TRUE(d.vector().isZero(0.0));
}

TEST(ReachDeviation, BallsBoundEveryAxisByTheOmegaRadius) {
  const ar::Deviation d = ar::Deviation::of_balls(0.3, 0.1);
  ar::Deviation::Vector expected;
  expected << 0.1, 0.1, 0.1, 0.1, 0.3;
  EXPECT_EQ(d.vector(), expected);
}

TEST(ReachDeviation, OmegaHalfWidthsAreCappedByTheNormBound) {
  const ar::Deviation d{attiguard::lie::Vec3(0.5, 2.0, 1.0), 1.5, 0.0};
  EXPECT_EQ(d.omega_half_widths(), attiguard::lie::Vec3(0.5, 1.5, 1.0));
}

TEST(ReachDeviation, MinIsComponentwise) {
  const ar::Deviation a{attiguard::lie::Vec3(1.0, 5.0, 3.0), 2.0, 7.0};
  const ar::Deviation b{attiguard::lie::Vec3(4.0, 2.0, 3.0), 6.0, 1.0};
  const ar::Deviation m = a.min(b);
  EXPECT_EQ(m.d_omega_b, attiguard::lie::Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(m.e_omega_b, 2.0);
  EXPECT_EQ(m.e_R, 1.0);
  EXPECT_TRUE(b.min(a) == m);
}

TEST(ReachDeviation, EqualityAndFinitenessSeeEveryComponent) {
  const ar::Deviation a{attiguard::lie::Vec3(1.0, 2.0, 3.0), 4.0, 5.0};
  EXPECT_TRUE(a.all_finite());
  for (int k = 0; k < 5; ++k) {
    ar::Deviation::Vector z = a.vector();
    z(k) += 1.0;
    EXPECT_FALSE(ar::Deviation::from_vector(z) == a) << k;
    z(k) = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(ar::Deviation::from_vector(z).all_finite()) << k;
  }
}
