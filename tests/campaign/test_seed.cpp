#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "attiguard/campaign/seed.hpp"

namespace attiguard::campaign {
namespace {

TEST(CampaignSeed, SplitMix64KnownValue) {
  // First output of the SplitMix64 stream seeded with 0 (reference value of the generator).
  Rng rng(0);
  EXPECT_EQ(rng.next(), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(splitmix64(0), 0xE220A8397B1DCDAFULL);
}

TEST(CampaignSeed, RunSeedsAreDistinctAndDeterministic) {
  std::set<std::uint64_t> seen;
  for (std::uint64_t k = 0; k < 10000; ++k) seen.insert(run_seed(42, k));
  EXPECT_EQ(seen.size(), 10000u);
  EXPECT_EQ(run_seed(42, 7), run_seed(42, 7));
  EXPECT_NE(run_seed(42, 7), run_seed(43, 7));
}

TEST(CampaignSeed, UniformAndNormalMoments) {
  Rng rng(5);
  double su = 0.0, sn = 0.0, sn2 = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double u = rng.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    su += u;
    const double g = rng.normal();
    ASSERT_TRUE(std::isfinite(g));
    sn += g;
    sn2 += g * g;
  }
  EXPECT_NEAR(su / n, 0.5, 0.005);
  EXPECT_NEAR(sn / n, 0.0, 0.01);
  EXPECT_NEAR(sn2 / n, 1.0, 0.02);
}

}  // namespace
}  // namespace attiguard::campaign
