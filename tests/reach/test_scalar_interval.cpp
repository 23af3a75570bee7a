// next_up / next_down of scalar_interval.hpp (docs/reach.md, "Rounding sites"; issue 48): bit for
// bit std::nextafter(x, ±∞) on the special values and on random bit patterns of every exponent.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "attiguard/reach/scalar_interval.hpp"

namespace ar = attiguard::reach;

namespace scalar_interval_test {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b) ||
         (std::isnan(a) && std::isnan(b));
}

void expect_nextafter(double x) {
  EXPECT_TRUE(same_bits(ar::next_up(x), std::nextafter(x, HUGE_VAL))) << x;
  EXPECT_TRUE(same_bits(ar::next_down(x), std::nextafter(x, -HUGE_VAL))) << x;
}

}  // namespace scalar_interval_test

TEST(RoundingNextUp, IsNextafterOnSpecialValues) {
  using L = std::numeric_limits<double>;
  for (double x : {0.0, -0.0, L::denorm_min(), -L::denorm_min(), L::min(), -L::min(), L::max(),
                   -L::max(), L::infinity(), -L::infinity(), L::quiet_NaN(), 1.0, -1.0,
                   L::epsilon(), 0.1, -0.1}) {
    scalar_interval_test::expect_nextafter(x);
  }
}

TEST(RoundingNextUp, IsNextafterOnRandomBitPatterns) {
  std::mt19937_64 rng(48);
  for (int i = 0; i < 200000; ++i) {
    scalar_interval_test::expect_nextafter(std::bit_cast<double>(rng()));
  }
}

TEST(RoundingNextUp, IntervalOperationsEncloseTheExactResult) {
  // 0.1 + 0.2 in round-to-nearest is 0.30000000000000004 > 3/10; the interval sum must contain
  // the exact sum of the two doubles (long double has 64 mantissa bits: exact here).
  const ar::Interval s = ar::Interval(0.1) + ar::Interval(0.2);
  const long double exact = static_cast<long double>(0.1) + static_cast<long double>(0.2);
  EXPECT_LE(static_cast<long double>(s.lo), exact);
  EXPECT_GE(static_cast<long double>(s.hi), exact);
  EXPECT_LT(s.lo, s.hi);
}
