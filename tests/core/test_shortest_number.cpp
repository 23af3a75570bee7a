// core/shortest_number.hpp: the user's values echoed in messages read back exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "attiguard/core/shortest_number.hpp"

namespace attiguard {
namespace {

TEST(ShortestNumber, WritesTheShortestTextThatReadsBack) {
  EXPECT_EQ(shortest_number(-1.0), "-1");
  EXPECT_EQ(shortest_number(0.05), "0.05");
  EXPECT_EQ(shortest_number(1e-9), "1e-09");
  EXPECT_EQ(shortest_number(150.3), "150.3");
  for (const double x : {0.1 + 0.2, std::sqrt(2.0), 6.02214076e23, -2.5e-300}) {
    EXPECT_EQ(std::stod(shortest_number(x)), x) << shortest_number(x);
  }
}

TEST(ShortestNumber, NamesTheNonFiniteValues) {
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(shortest_number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(shortest_number(-std::numeric_limits<double>::infinity()), "-inf");
}

}  // namespace
}  // namespace attiguard
