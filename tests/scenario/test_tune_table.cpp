// scenario/tune_table: the `[tune]` table of a pet_erg scenario (docs/scenario-format.md, "[tune]").

#include <gtest/gtest.h>

#include <string>

#include "attiguard/app/kinds.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/tune_table.hpp"

namespace attiguard::scenario {
namespace {

// A small pet_erg scenario (no [erg] table: erg.* keys are inserted when tuned).
const std::string kTuneBase = R"(kind = "pet_erg"
[body]
inertia = [1.0, 2.0, 3.0]
[initial]
attitude = { matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] }
omega_b = [0.0, 0.0, 0.0]
[desired]
attitude = { axis = [0.0, 1.0, 0.0], angle_deg = 90.0 }
[control]
kp = 5.0
kd = 1.0
tau_max = 2.5
[simulation]
duration = 10.0
output_interval = 0.5
integrator = "rkmk4"
step = 0.01
)";

/// The InputError message of read_tune_table on kTuneBase + `tune` ("" when accepted).
std::string tune_error_of(const std::string& tune) {
  try {
    (void)read_tune_table(parse_document(kTuneBase + tune, "t.toml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TuneTable, AbsentTableGivesNothing) {
  const TuneTable t = read_tune_table(parse_document(kTuneBase, "t.toml"));
  EXPECT_FALSE(t.budget.has_value());
  EXPECT_FALSE(t.seed.has_value());
  EXPECT_FALSE(t.batch.has_value());
  EXPECT_FALSE(t.plot.has_value());
  EXPECT_TRUE(t.ranges.empty());
}

TEST(TuneTable, ReadsEveryKeyAndTheRangesInKeyOrder) {
  const TuneTable t = read_tune_table(parse_document(
      kTuneBase + "[tune]\nbudget = 40\nseed = 7\nbatch = 6\nplot = false\n[tune.ranges]\n"
              "\"erg.kappa\" = [0.5, 50]\n\"control.kp\" = [0.1, 10]\n",
      "t.toml"));
  EXPECT_EQ(t.budget, 40);
  EXPECT_EQ(t.seed, 7u);
  EXPECT_EQ(t.batch, 6);
  EXPECT_EQ(t.plot, false);
  ASSERT_EQ(t.ranges.size(), 2u);
  EXPECT_EQ(t.ranges[0].key, "control.kp");
  EXPECT_DOUBLE_EQ(t.ranges[0].min, 0.1);
  EXPECT_DOUBLE_EQ(t.ranges[0].max, 10.0);
  EXPECT_EQ(t.ranges[1].key, "erg.kappa");  // absent key of an absent table: inserted when tuned
  EXPECT_DOUBLE_EQ(t.ranges[1].min, 0.5);
  EXPECT_DOUBLE_EQ(t.ranges[1].max, 50.0);
}

TEST(TuneTable, BadValuesAreLocatedOneLineErrors) {
  EXPECT_EQ(tune_error_of("[tune]\nbudget = 3\n"), "t.toml:19:10: tune.budget: must be in [4, 9223372036854775807], got 3");
  EXPECT_EQ(tune_error_of("[tune]\nseed = -1\n"), "t.toml:19:8: tune.seed: must be in [0, 9223372036854775807], got -1");
  EXPECT_EQ(tune_error_of("[tune]\nbatch = 0\n"), "t.toml:19:9: tune.batch: must be in [1, 9223372036854775807], got 0");
  EXPECT_EQ(tune_error_of("[tune]\nplot = 1\n"), "t.toml:19:8: tune.plot: expected a boolean (true or false), got an integer");
  EXPECT_EQ(tune_error_of("[tune]\nbudgett = 40\n"),
            "t.toml:19:1: tune.budgett: unknown key 'budgett' (expected one of: batch, budget, plot, ranges, seed); "
            "did you mean 'budget'?");
  EXPECT_EQ(tune_error_of("[tune]\nranges = {}\n"),
            "t.toml:19:10: tune.ranges: [tune] ranges must list at least one KEY = [MIN, MAX]");
  EXPECT_EQ(tune_error_of("[tune.ranges]\n\"control.kp\" = [10.0, 0.1]\n"),
            "t.toml:19:16: tune.ranges.\"control.kp\": MIN 10 is above MAX 0.1 (expected 0 < MIN <= MAX)");
  EXPECT_EQ(tune_error_of("[tune.ranges]\n\"control.kp\" = [1, 2, 3]\n"),
            "t.toml:19:16: tune.ranges.\"control.kp\": expected [MIN, MAX] (2 numbers, 0 < MIN <= MAX), got 3 numbers");
  EXPECT_EQ(tune_error_of("[tune.ranges]\n\"control.kp\" = [0, 2]\n"),
            "t.toml:19:17: tune.ranges.\"control.kp\"[0]: must be > 0, got 0");
  EXPECT_EQ(tune_error_of("[tune.ranges]\n\"body.inertia\" = [1, 2]\n"),
            "t.toml:19:18: tune.ranges.\"body.inertia\": cannot be tuned: the scenario's value at this key "
            "path is not a number");
  EXPECT_EQ(tune_error_of("[tune.ranges]\n\"initial.attitude.matrix.x\" = [1, 2]\n"),
            "t.toml:19:31: tune.ranges.\"initial.attitude.matrix.x\": cannot be tuned: the scenario has no "
            "table to hold this key");
}

// The kind's parser accepts the table and ignores it (run, check); its other tables stay strict.
TEST(TuneTable, PetErgParserAcceptsAndIgnoresTheTable) {
  const Document doc = parse_document(kTuneBase + "[tune]\nbudget = 3\nwhatever = \"x\"\n", "t.toml");
  EXPECT_NO_THROW(app::handler_for(doc).check(doc));
  const Document other = parse_document(kTuneBase + "[tuning]\nbudget = 3\n", "t.toml");
  EXPECT_THROW(app::handler_for(other).check(other), InputError);
}

}  // namespace
}  // namespace attiguard::scenario
