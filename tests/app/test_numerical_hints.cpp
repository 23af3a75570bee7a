// app/numerical_hints: the key most likely responsible for a diverging run, per kind, and the
// registry entries that hold them.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "attiguard/app/failure.hpp"
#include "attiguard/app/kinds.hpp"
#include "attiguard/app/numerical_hints.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {
namespace {

std::string hint_example_text(const std::string& name) {
  std::ifstream in(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/" + name, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with its first `from` replaced by `to` (which must be there).
std::string hint_with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(NumericalHints, AFixedStepAboveTheStabilityLimitIsLocatedAtTheStep) {
  const std::string stiff = hint_with(hint_with(hint_example_text("rigid_body_pd.toml"), "inertia = [1.0, 2.0, 3.0]",
                                      "inertia = [1e-3, 1e3, 1e3]"),
                                 "step = 0.01", "step = 0.05");
  const scenario::Document doc = scenario::parse_document(stiff, "stiff.toml");
  const std::string hint = rigid_body_numerical_hint(doc);
  EXPECT_NE(hint.find("stiff.toml:"), std::string::npos) << hint;
  EXPECT_NE(hint.find("simulation.step: 0.05 s is above the stability limit ~ 2/lambda_max = "
                      "0.00201 s"),
            std::string::npos)
      << hint;
  EXPECT_EQ(rigid_body_numerical_hint(scenario::parse_document(hint_example_text("rigid_body_pd.toml"),
                                                               "pd.toml")),
            "");
}

TEST(NumericalHints, AKappaTurningTheReferenceTooFastIsLocatedAtKappa) {
  const std::string text = hint_with(hint_example_text("pet_erg_paper.toml"), "kappa = 1.0", "kappa = 1e300");
  const std::string hint = pet_erg_numerical_hint(scenario::parse_document(text, "kappa.toml"));
  EXPECT_NE(hint.find("erg.kappa: 1e+300 turns the reference at up to kappa Gamma_d"),
            std::string::npos)
      << hint;
}

TEST(NumericalHints, TheRegistryHoldsEachKindsHintAndTheFailureHintUsesIt) {
  for (const KindHandler& k : kinds()) {
    EXPECT_EQ(k.numerical_hint != nullptr, k.name == "rigid_body" || k.name == "pet_erg") << k.name;
  }
  const std::string text = hint_with(hint_example_text("pet_erg_paper.toml"), "kappa = 1.0", "kappa = 1e300");
  const scenario::Document doc = scenario::parse_document(text, "kappa.toml");
  EXPECT_EQ(numerical_failure_hint(doc), pet_erg_numerical_hint(doc));
  EXPECT_EQ(numerical_failure_hint(scenario::parse_document("kind = \"nonsense\"\n", "n.toml")), "");
}

}  // namespace
}  // namespace attiguard::app
