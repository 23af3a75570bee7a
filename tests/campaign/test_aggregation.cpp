#include <gtest/gtest.h>

#include "attiguard/campaign/aggregation.hpp"
#include "attiguard/campaign/csv_format.hpp"

namespace attiguard::campaign {
namespace {

TEST(CampaignAggregation, NearestRankPercentiles) {
  const std::vector<double> v{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  EXPECT_EQ(percentile(v, 0), 1);
  EXPECT_EQ(percentile(v, 50), 5);
  EXPECT_EQ(percentile(v, 95), 10);
  EXPECT_EQ(percentile(v, 100), 10);
}

TEST(CampaignAggregation, CountsAndFiguresIndependentOfInsertionOrder) {
  const std::vector<std::string> header{"run", "seed", "attempts", "status", "reason",
                                        "x",   "violation", "margin"};
  std::map<long, std::string> rows;
  rows[2] = "2,9,1,failed,\"integrator: NaN, at t = 1\",0.5,,";
  rows[0] = "0,7,1,ok,,0.1,0,0.25";
  rows[1] = "1,8,2,ok,,0.2,1,-0.5";
  rows[3] = "3,10,5,rejected,not admissible,0.3,,";
  CampaignInfo info;
  info.runs = 4;
  const auto j = aggregate(info, header, rows);
  EXPECT_EQ(j["ok"], 2);
  EXPECT_EQ(j["failures"], 1);
  EXPECT_EQ(j["rejected"], 1);
  EXPECT_EQ(j["violations"], 1);
  EXPECT_EQ(j["failed_or_rejected_runs"][0]["reason"], "integrator: NaN, at t = 1");
  EXPECT_DOUBLE_EQ(j["figures"]["margin"]["min"].get<double>(), -0.5);
  EXPECT_FALSE(j["figures"].contains("x"));  // dispersed values are inputs, not figures
}

// Issue 14: a campaign of which most runs stall must say so: each outcome is counted, and a
// figure's statistics state the number of runs they are over (a null convergence time is not
// among them).
TEST(CampaignAggregation, CountsOutcomesAndStatesTheCountOfEveryStatistic) {
  const std::vector<std::string> header{"run",     "seed",      "attempts",        "status",
                                        "reason",  "outcome",   "violation",       "convergence_time",
                                        "min_pointing_margin"};
  std::map<long, std::string> rows;
  rows[0] = "0,1,1,ok,,converged,0,31.5,0.07";
  rows[1] = "1,2,1,ok,,stalled,0,,0.05";
  rows[2] = "2,3,1,ok,,stalled,0,,0.06";
  rows[3] = "3,4,1,ok,,converged,0,29.0,0.08";
  rows[4] = "4,5,1,failed,integrator: NaN,,,,";
  rows[5] = "5,6,1,ok,,chattering,0,,0.04";
  CampaignInfo info;
  info.runs = 6;
  const auto j = aggregate(info, header, rows);
  EXPECT_EQ(j["ok"], 5);
  EXPECT_EQ(j["outcomes"]["converged"], 2);
  EXPECT_EQ(j["outcomes"]["stalled"], 2);
  EXPECT_EQ(j["outcomes"]["chattering"], 1);
  EXPECT_FALSE(j["outcomes"].contains(""));
  EXPECT_EQ(j["figures"]["convergence_time"]["count"], 2);
  EXPECT_EQ(j["figures"]["min_pointing_margin"]["count"], 5);
  EXPECT_EQ(outcome_counts_text(j["outcomes"]), "1 chattering, 2 converged, 2 stalled");
  // A kind without outcomes gets no `outcomes` object.
  const std::vector<std::string> plain{"run", "seed", "attempts", "status", "reason", "violation", "x"};
  EXPECT_FALSE(aggregate(info, plain, {{0, "0,1,1,ok,,0,1.5"}}).contains("outcomes"));
}

TEST(CampaignCsv, QuoteSplitRoundTrip) {
  const std::string field = "a, \"b\"\nc";
  const auto f = csv_split("1," + csv_quote(field) + ",x");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[1], "a, \"b\" c");
  EXPECT_EQ(format_number(0.1), "0.10000000000000001");
}

}  // namespace
}  // namespace attiguard::campaign
