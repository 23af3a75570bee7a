// scenario/retain_keys: [campaign] retain and retain_interval (docs/campaigns.md, "Retained
// time series"), read through read_dispersions as attiguard campaign reads them.

#include <gtest/gtest.h>

#include <string>

#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

std::string scenario(const std::string& campaign) {
  return "kind = \"rigid_body\"\n[control]\nkp = 1.0\n[campaign]\n" + campaign +
         "[dispersions]\n\"control.kp\" = { distribution = \"uniform\", min = 1.0, max = 2.0 }\n";
}

TEST(RetainKeys, ReadsTheColumnsAndTheInterval) {
  const DispersionPlan p = read_dispersions(
      parse_document(scenario("retain = [\"tau_norm\", \"V\"]\nretain_interval = 0.25\n"), "c.toml"));
  EXPECT_EQ(p.retain.columns, (std::vector<std::string>{"tau_norm", "V"}));
  EXPECT_EQ(p.retain.interval, 0.25);
  EXPECT_TRUE(p.retain.enabled());
  const DispersionPlan none = read_dispersions(parse_document(scenario(""), "c.toml"));
  EXPECT_FALSE(none.retain.enabled());
  EXPECT_EQ(none.retain.interval, 1.0);
}

TEST(RetainKeys, BadValuesAreLocatedAtTheirKey) {
  auto error_of = [](const std::string& campaign) {
    return test::input_error([&] { (void)read_dispersions(parse_document(scenario(campaign), "c.toml")); });
  };
  EXPECT_TRUE(test::starts_with(error_of("retain = []\n"), "c.toml:5:10: campaign.retain: must be a non-empty array"));
  EXPECT_TRUE(test::contains(error_of("retain = [1]\n"), "every entry must be a non-empty string"));
  EXPECT_TRUE(test::contains(error_of("retain = [\"V\", \"V\"]\n"), "'V' is listed twice"));
  EXPECT_TRUE(test::contains(error_of("retain = [\"V\"]\nretain_interval = 0\n"), "campaign.retain_interval"));
  EXPECT_TRUE(test::contains(error_of("retains = [\"V\"]\n"), "unknown key 'retains'"));
}

}  // namespace
}  // namespace attiguard::scenario
