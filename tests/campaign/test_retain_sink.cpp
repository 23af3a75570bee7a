// campaign/retain_sink: the samples a campaign keeps of one run (docs/campaigns.md,
// "Retained time series").

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "attiguard/campaign/retain_sink.hpp"
#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {
namespace {

TEST(RetainSink, KeepsTheFirstRowAtOrAfterEachMultipleOfTheInterval) {
  RetainSink sink({{"b"}, 0.5});
  sink.begin({"t", "a", "b"});
  for (int i = 0; i <= 20; ++i) {
    const double t = 0.1 * i;
    const std::array<double, 3> row{t, -1.0, 10.0 * t};
    sink.row(row);
  }
  ASSERT_EQ(sink.samples(), 5u);  // t = 0, 0.5, 1, 1.5, 2
  const auto v = sink.values();
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_DOUBLE_EQ(sink.times()[k], 0.5 * static_cast<double>(k));
    EXPECT_NEAR(v[k], 5.0 * static_cast<double>(k), 1e-12);
  }
  RetainSink missing({{"nope"}, 1.0});
  EXPECT_THROW(missing.begin({"t", "a"}), InputError);
}

TEST(RetainSink, RowsThatSkipARetainedTimeAreRefusedNotStampedWithIt) {
  // Rows every 1 s, retain_interval 0.2 s: sample 1 would be the row at t = 1 stamped 0.2 s.
  RetainSink sink({{"a"}, 0.2});
  sink.begin({"t", "a"});
  sink.row(std::array<double, 2>{0.0, 1.0});
  try {
    sink.row(std::array<double, 2>{1.0, 2.0});
    FAIL() << "a row at t = 1 s was kept as the sample of t = 0.2 s";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("[campaign] retain_interval: no trajectory row at the retained time t = 0.2 s", 0), 0u) << m;
    EXPECT_NE(m.find("rows around it are at t = 0 s and 1 s"), std::string::npos) << m;
  }
  // Not a multiple: rows every 0.5 s, interval 0.75 s.
  RetainSink odd({{"a"}, 0.75});
  odd.begin({"t", "a"});
  odd.row(std::array<double, 2>{0.0, 0.0});
  odd.row(std::array<double, 2>{0.5, 0.0});
  EXPECT_THROW(odd.row(std::array<double, 2>{1.0, 0.0}), InputError);
  // A multiple: rows every 0.5 s, interval 1 s keeps t = 0, 1, 2 at their own rows.
  RetainSink twice({{"a"}, 1.0});
  twice.begin({"t", "a"});
  for (int i = 0; i <= 4; ++i) twice.row(std::array<double, 2>{0.5 * i, 10.0 * i});
  ASSERT_EQ(twice.samples(), 3u);
  EXPECT_EQ(twice.values(), (std::vector<double>{0.0, 20.0, 40.0}));
}

}  // namespace
}  // namespace attiguard::campaign
