#include <gtest/gtest.h>

#include "attiguard/scenario/key_path.hpp"

namespace attiguard::scenario {
namespace {

TEST(CampaignKeyPath, SplitsKeysAndIndices) {
  const auto steps = split_key_path("cones[1].direction_i");
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].key, "cones");
  ASSERT_TRUE(steps[0].index.has_value());
  EXPECT_EQ(*steps[0].index, 1u);
  EXPECT_EQ(steps[1].key, "direction_i");
  EXPECT_FALSE(steps[1].index.has_value());
  EXPECT_TRUE(split_key_path("a..b").empty());
  EXPECT_TRUE(split_key_path("a[x]").empty());
  EXPECT_TRUE(split_key_path("[0]").empty());
  EXPECT_TRUE(split_key_path("").empty());
}

TEST(CampaignKeyPath, ResolvesAndAssigns) {
  toml::table root = toml::parse(R"(
    [control]
    kp = 5
    [[cones]]
    direction_i = [1.0, 0.0, 0.0]
    [[cones]]
    direction_i = [0.0, 1.0, 0.0]
  )");
  ASSERT_NE(resolve_key_path(root, "control.kp"), nullptr);
  EXPECT_EQ(resolve_key_path(root, "control.kd"), nullptr);
  EXPECT_EQ(resolve_key_path(root, "cones[2].direction_i"), nullptr);
  assign_key_path(root, "control.kp", toml::value<double>(7.5));
  EXPECT_DOUBLE_EQ(*resolve_key_path(root, "control.kp")->value<double>(), 7.5);
  assign_key_path(root, "cones[1].direction_i", toml::array{0.0, 0.0, 1.0});
  const toml::array* a = resolve_key_path(root, "cones[1].direction_i")->as_array();
  ASSERT_NE(a, nullptr);
  EXPECT_DOUBLE_EQ(*a->get(2)->value<double>(), 1.0);
  assign_key_path(root, "initial.omega_b[1]", toml::value<double>(1.0));  // absent: no-op
  EXPECT_EQ(resolve_key_path(root, "initial"), nullptr);
}

}  // namespace
}  // namespace attiguard::scenario
