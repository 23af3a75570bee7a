// campaign/retain_sink: the samples a campaign keeps of one run (docs/campaigns.md,
// "Retained time series").

#include <gtest/gtest.h>

#include <array>

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

}  // namespace
}  // namespace attiguard::campaign
