// campaign/envelopes: percentile envelopes and worst runs of retained time series
// (docs/campaigns.md, "Retained time series").

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "attiguard/campaign/envelopes.hpp"

namespace attiguard::campaign {
namespace {

TEST(Envelopes, PercentilesPerSampleOverTheRunsThatHaveAValueAndTheWorstRuns) {
  RetainedSeries s;
  s.t = {0.0, 1.0};
  s.columns = {"min_margin"};
  s.runs = 101;
  s.values.assign(1, std::vector<double>(202, 0.0));
  for (std::size_t k = 0; k < 101; ++k) {
    s.values[0][k * 2 + 0] = static_cast<double>(k);        // 0 … 100
    s.values[0][k * 2 + 1] = k == 7 ? NAN : 100.0 - static_cast<double>(k);
  }
  const Envelope e = envelope(s, 0, 2);
  EXPECT_EQ(e.min[0], 0.0);
  EXPECT_EQ(e.max[0], 100.0);
  EXPECT_EQ(e.p50[0], 50.0);
  EXPECT_EQ(e.p1[0], 1.0);
  EXPECT_EQ(e.p99[0], 99.0);
  EXPECT_EQ(e.count[0], 101.0);
  EXPECT_EQ(e.count[1], 100.0);  // run 7 has no value at t = 1
  // Margins: the worst runs have the lowest minimum over time (run 100 reaches 0 at t = 1).
  ASSERT_EQ(e.worst.size(), 2u);
  EXPECT_EQ(e.worst[0], 0u);
  EXPECT_EQ(e.worst[1], 100u);
}

}  // namespace
}  // namespace attiguard::campaign
