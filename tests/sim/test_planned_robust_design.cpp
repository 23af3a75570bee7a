// Robust margins of the planned mode (docs/pet-erg.md, section 16.3): the robust slew170
// example converges near the eigenaxis bang-bang time with every constraint kept and the true
// errors within the proved peaks; the design from plain values; the refusals located at their keys.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/planned_robust_design.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::sim::planned_robust_test {
namespace {

std::string example_text(const std::string& name) {
  std::ifstream in(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples" / name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

PetErgScenario scenario_of(const std::string& text) {
  return scenario::parse_pet_erg(scenario::parse_document(text, "robust_planned.toml"));
}

/// The error of reading and setting up `text` ("" when accepted).
std::string refusal_of(const std::string& text) {
  try {
    (void)planned_setup(scenario_of(text));
  } catch (const PlannedSetupRefusal& e) {
    return e.table() + "." + e.key() + ": " + e.message();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

const std::string kExample = "pet_erg_slew170_planned_robust.toml";

TEST(PlannedRobust, TheSlew170ExampleConvergesNearTheBangBangTimeWithTheErrorsWithinTheProvedPeaks) {
  const PetErgScenario sc = scenario_of(example_text(kExample));
  const PetErgResult r = simulate_planned(sc);
  ASSERT_TRUE(r.planned && r.planned->robust);
  const PlannedRobustDesign& d = *r.planned->robust;
  EXPECT_LT(r.first_pointing_violation_time, 0.0);
  EXPECT_GT(r.min_pointing_margin, 0.0);
  EXPECT_LE(r.max_torque_norm, sc.params.tau_max);
  ASSERT_GE(r.convergence_time, 0.0);
  EXPECT_LE(r.convergence_time / r.eigenaxis_bang_bang_time, 1.3);
  // The guarantee: the true errors (seen through the bias) stay within the proved peaks.
  EXPECT_LE(r.max_V_minus_Gamma, 0.0);
  EXPECT_LE(r.planned->max_W_minus_level, 0.0);
  // The design: the plan keeps the cones by what the peaks and the bias need, and the command's
  // proved bound is within τ_max; the clock runs at the design's rate.
  EXPECT_GE(d.plan_cone_margin, d.cone_margin_needed);
  EXPECT_LE(d.torque_needed, d.torque_limit);
  EXPECT_GT(d.rate, 0.5);
  EXPECT_LE(d.rate, 1.0);
  EXPECT_EQ(r.planned->inadmissible_samples, 0);
  EXPECT_EQ(r.planned->saturated_commands, 0);
}

TEST(PlannedRobust, TheDesignFromPlainValuesMatchesTheRun) {
  const PlannedSetup s = planned_setup(scenario_of(example_text(kExample)));
  ASSERT_TRUE(s.figures.robust);
  const governor::ProgressGovernor progress(s.planned.plan, s.run.cones, s.figures.tau_max, s.figures.gains,
                                            s.run.control_period, 0.0);
  const PlannedRobustDesign d = planned_robust_design(s.run, progress, s.figures.robust->rate);
  EXPECT_DOUBLE_EQ(d.torque_needed, s.figures.robust->torque_needed);
  EXPECT_DOUBLE_EQ(d.cone_margin_needed, s.figures.robust->cone_margin_needed);
  // A faster clock needs more torque.
  const PlannedRobustDesign faster = planned_robust_design(s.run, progress, 1.0);
  EXPECT_GE(faster.torque_needed, d.torque_needed);
}

TEST(PlannedRobust, RefusalsAreLocatedAtTheirKeys) {
  const std::string text = example_text(kExample);
  // Robust margins need the flight loop.
  EXPECT_NE(refusal_of(replaced(text, "control_period = 0.02                  # s: the 50 Hz flight loop\n", ""))
                .find("control.margins: robust margins of the planned mode need the flight loop"),
            std::string::npos);
  // The PET-ERG's reference step cap has no use in the planned mode.
  EXPECT_NE(refusal_of(replaced(text, "margins = \"robust\"", "margins = \"robust\"\nrobust_reference_step = 0.002"))
                .find("control.robust_reference_step"),
            std::string::npos);
  // A given cone margin below what the proved errors and the bias need.
  const std::string small_margin = replaced(text, "[simulation]", "[plan]\ncone_margin_deg = 0.05\n\n[simulation]");
  EXPECT_NE(refusal_of(small_margin).find("plan.cone_margin_deg: robust margins of the planned mode need a cone margin of"),
            std::string::npos)
      << refusal_of(small_margin);
  // A disturbance the torque cannot overcome at any clock rate or gains.
  const std::string strong = replaced(text, "disturbance_bound = 0.001", "disturbance_bound = 0.3");
  EXPECT_NE(refusal_of(strong).find("control.margins: robust margins of the planned mode"), std::string::npos)
      << refusal_of(strong);
  // … with why, at the derived gains: the torque error's parts.
  EXPECT_NE(refusal_of(strong).find("at the derived gains: "), std::string::npos) << refusal_of(strong);
  EXPECT_NE(refusal_of(strong).find("disturbance 0.3"), std::string::npos) << refusal_of(strong);
}

}  // namespace
}  // namespace attiguard::sim::planned_robust_test
