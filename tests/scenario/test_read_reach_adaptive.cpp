// The keys of ConReach's adaptive steps and automatic splitting (docs/scenario-format.md,
// "reach"; docs/reach.md "Adaptive steps", "Automatic splitting"): defaults, and bad values
// refused at their key in one line.

#include <gtest/gtest.h>

#include <string>

#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_reach.hpp"
#include "scenario/scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;
using test::input_error;

/// A free-body reach scenario with `reach_keys` under [reach] and `tail` appended.
std::string adaptive_reach(const std::string& reach_keys, const std::string& tail = "") {
  return "kind = \"reach\"\n[system]\nmodel = \"free\"\ninertia = [1.0, 2.0, 3.0]\n"
         "[initial]\nattitude_radius = 0.05\nomega_b = [0.1, 0.0, 0.0]\nomega_radius = 0.01\n"
         "[reach]\nhorizon = 1.0\n" + reach_keys + tail;
}

TEST(ReadReachAdaptive, WithoutStepsTheAnalysisChoosesItsStepsAndSplitsByDefault) {
  const reach::ReachScenario sc = parse_reach(parse_document(adaptive_reach(""), "f.toml"));
  EXPECT_TRUE(sc.settings.adaptive);
  EXPECT_EQ(sc.settings.integrator_step, 0.0);  // derived from the loop
  EXPECT_EQ(sc.settings.substeps, 10);
  EXPECT_EQ(sc.settings.max_bisections, 6);
  EXPECT_TRUE(sc.split.enabled);
  EXPECT_EQ(sc.split.max_cell_steps, 10000);
  EXPECT_EQ(sc.split.max_seconds, 60.0);
  const reach::ReachScenario fixed = parse_reach(parse_document(adaptive_reach("steps = 10\n"), "f.toml"));
  EXPECT_FALSE(fixed.settings.adaptive);
  EXPECT_EQ(fixed.settings.integrator_step, 1e-3);
  const reach::ReachScenario own = parse_reach(parse_document(
      adaptive_reach("integrator_step = 0.002\n", "[partition]\nsplit = false\nmax_cell_steps = 50\nmax_seconds = 2.5\n"),
      "f.toml"));
  EXPECT_EQ(own.settings.integrator_step, 0.002);
  EXPECT_FALSE(own.split.enabled);
  EXPECT_EQ(own.split.max_cell_steps, 50);
  EXPECT_EQ(own.split.max_seconds, 2.5);
}

TEST(ReadReachAdaptive, BadValuesAreRefusedAtTheirKey) {
  auto refused = [](const std::string& text) { return input_error([&] { (void)parse_reach(parse_document(text, "f.toml")); }); };
  const std::string b = refused(adaptive_reach("max_bisections = 31\n"));
  EXPECT_TRUE(contains(b, "f.toml:")) << b;
  EXPECT_TRUE(contains(b, "max_bisections")) << b;
  const std::string s = refused(adaptive_reach("", "[partition]\nsplit = 3\n"));
  EXPECT_TRUE(contains(s, "partition.split")) << s;
  const std::string m = refused(adaptive_reach("", "[partition]\nmax_seconds = -1.0\n"));
  EXPECT_TRUE(contains(m, "partition.max_seconds")) << m;
  const std::string c = refused(adaptive_reach("", "[partition]\nmax_cell_steps = 0\n"));
  EXPECT_TRUE(contains(c, "partition.max_cell_steps")) << c;
  const std::string h = refused(adaptive_reach("integrator_step = 2.0\n"));
  EXPECT_TRUE(contains(h, "integrator_step")) << h;
  const std::string n = refused(adaptive_reach("integrator_step = nan\n"));
  EXPECT_TRUE(contains(n, "integrator_step")) << n;
}

}  // namespace
}  // namespace attiguard::scenario
