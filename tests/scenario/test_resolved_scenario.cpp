// The resolved scenario's rules (scenario/resolved_scenario.hpp; docs/conventions.md,
// "Outputs"): a default is written only when the reader would accept it given the other
// settings, derived defaults are left out of a campaign's resolved scenario, and the defaults of
// a table left out are written as that table.

#include <gtest/gtest.h>

#include <string>

#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;

constexpr const char* kFlightLoop = R"(kind = "pet_erg"
[body]
inertia = [1.0, 2.0, 3.0]
[control]
kp = 5.0
kd = 1.0
tau_max = 2.5
control_period = 0.1
[desired]
attitude = { axis = [0.0, 1.0, 0.0], angle_deg = 30.0 }
[simulation]
duration = 5.0
[imperfections]
disturbance = "random"
disturbance_bound = 0.01
rate_bias = [0.001, 0.0, 0.0]
)";

void check_pet_erg(const Document& doc) { (void)parse_pet_erg(doc); }

TEST(ResolvedScenario, LeavesOutTheKeysTheOtherSettingsLeaveUnused) {
  const Document doc = parse_document(kFlightLoop, "loop.toml");
  const std::string resolved = resolve_scenario(doc, &check_pet_erg);
  EXPECT_TRUE(contains(resolved, "disturbance_period = 100.0"));  // used by "random"
  EXPECT_FALSE(contains(resolved, "disturbance_update"));  // only with "adversarial"
  EXPECT_FALSE(contains(resolved, "adversary_weight"));
  EXPECT_FALSE(contains(resolved, "robust_reference_step"));  // only with margins = "robust"
  // ... and the reader accepts what was written.
  EXPECT_NO_THROW(check_pet_erg(parse_document(resolved, "loop.resolved.toml")));
}

TEST(ResolvedScenario, WritesTheDefaultsOfATableLeftOut) {
  const Document doc = parse_document(kFlightLoop, "loop.toml");
  const std::string resolved = resolve_scenario(doc, &check_pet_erg);
  EXPECT_TRUE(contains(resolved, "[erg]"));
  EXPECT_TRUE(contains(resolved, "epsilon_gamma = 0.1"));  // a constant default
  // the values derived from the craft (docs/pet-erg.md, section 8), as the run used them
  const sim::PetErgScenario sc = parse_pet_erg(doc);
  EXPECT_TRUE(sc.derived.Ts_derived && sc.derived.kappa_derived && sc.derived.c_gamma_derived);
  EXPECT_TRUE(contains(resolved, "c_gamma = 1.2"));
  EXPECT_TRUE(contains(resolved, "sampling_period = "));
  const sim::PetErgScenario again = parse_pet_erg(parse_document(resolved, "loop.resolved.toml"));
  EXPECT_EQ(again.params.Ts, sc.params.Ts);
  EXPECT_EQ(again.params.kappa, sc.params.kappa);
  EXPECT_EQ(again.params.epsilon, sc.params.epsilon);
  EXPECT_EQ(again.integrator.step, sc.integrator.step);
}

TEST(ResolvedScenario, DerivedDefaultsAreLeftOutOfACampaignOnly) {
  const std::string campaign = std::string(kFlightLoop) +
                               "[dispersions]\n\"imperfections.rate_bias\" = { type = \"vector\", "
                               "distribution = \"uniform\", delta = 0.0005 }\n"
                               "\"control.kp\" = { distribution = \"uniform\", delta = 0.5 }\n";
  const Document doc = parse_document(campaign, "mc.toml");
  // rate_bias_bound defaults to the norm of rate_bias: a dispersed run derives its own.
  EXPECT_TRUE(contains(resolve_scenario(nominal_document(doc), &check_pet_erg), "rate_bias_bound = 0.001"));
  const std::string resolved = resolve_campaign(doc, &check_pet_erg);
  EXPECT_FALSE(contains(resolved, "rate_bias_bound"));
  EXPECT_TRUE(contains(resolved, "torque_quantum = 0.0"));  // a constant default
  EXPECT_FALSE(contains(resolved, "kappa"));  // derived from the craft: each run derives its own
  EXPECT_TRUE(contains(resolved, "[dispersions]"));
  // The defaults of the quoted [dispersions] entries (`type`) are not written: the campaign
  // file still reads (before, `dispersions."control.kp".type` made a table named '"control').
  const Document again = parse_document(resolved, "mc.resolved.toml");
  EXPECT_EQ(read_dispersions(again).items.size(), 2u);
  EXPECT_NO_THROW(check_pet_erg(nominal_document(again)));
}

}  // namespace
}  // namespace attiguard::scenario
