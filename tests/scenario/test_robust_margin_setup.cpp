// `[control] margins = "robust"` (scenario/robust_margin_setup.hpp, docs/pet-erg.md section 13):
// the design of the parsed scenario (sim::design_governor) with the reduced torque limits, the
// cones tightened by the bias bound with their repulsive band moved inwards as Γ_min needs, and
// the refusals located at the file's keys.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"

namespace attiguard::scenario {
namespace {

std::string robust_example(const std::string& from = "", const std::string& to = "") {
  std::ifstream in(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples" / "pet_erg_robust_campaign.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  text = text.substr(0, text.find("[dispersions]"));
  if (!from.empty()) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  return text;
}

sim::PetErgScenario parse(const std::string& text) {
  return parse_pet_erg(parse_document(text, "robust.toml"));
}

std::string robust_error_of(const std::string& text) {
  try {
    (void)parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RobustMarginSetup, TheExampleGetsReducedLimitsAndTightenedCones) {
  const sim::PetErgScenario sc = parse(robust_example());
  ASSERT_EQ(sc.margins, governor::Margins::robust);
  EXPECT_DOUBLE_EQ(sc.robust_reference_step, 0.002);
  const governor::GovernorDesign design = sim::design_governor(sc);
  ASSERT_TRUE(design.params.robust.has_value());
  const governor::RobustMargin& m = *design.params.robust;
  EXPECT_NEAR(design.tau_max_reduced, sc.params.tau_max - m.command_error, 1e-15);
  EXPECT_EQ(design.params.tau_max, design.tau_max_reduced);
  EXPECT_EQ(design.params.polytope_gamma_d, design.wheel_gamma_d_reduced);
  EXPECT_LT(design.wheel_gamma_d_reduced, design.wheels.gamma_d);
  EXPECT_GT(m.gamma_min, 0.0);
  EXPECT_LT(m.gamma_min, (1.0 - m.delta) * design.wheel_gamma_d_reduced);
  EXPECT_DOUBLE_EQ(m.max_reference_step, 0.002);
  // the scenario holds the user's inputs only: the derived values are the design's
  EXPECT_FALSE(sc.params.robust.has_value());
  EXPECT_EQ(sc.params.polytope_gamma_d, 0.0);
  EXPECT_EQ(sc.margins, governor::Margins::robust);
  const std::vector<governor::ConeConstraint>& robust_cones = design.cones;
  ASSERT_EQ(robust_cones.size(), sc.cones.size());
  const double bias = sc.imperfections.attitude_bias_bound;
  EXPECT_DOUBLE_EQ(bias, 0.0215);
  const double gap = std::acos(1.0 - 1.05 * m.gamma_min / ((1.0 - m.delta) * sc.params.gains.kp));
  for (std::size_t i = 0; i < sc.cones.size(); ++i) {
    const governor::ConeConstraint& c = sc.cones[i];
    const governor::ConeConstraint& r = robust_cones[i];
    EXPECT_NEAR(r.theta_c, c.theta_c - bias, 1e-15) << i;
    // the repulsive potential diverges at least `gap` inside the tightened cone
    EXPECT_GE(r.delta, std::cos(r.theta_c - gap) - 1e-15) << i;
    EXPECT_GE(r.delta - r.cos_theta_c, c.delta - c.cos_theta_c - 1e-15) << i;
    EXPECT_NEAR(r.zeta - r.delta, c.zeta - c.delta, 1e-12) << i;
  }
  // At δ of a tightened cone, Γ_W exceeds Γ_min: the field keeps R_g where moves are admissible.
  const governor::AttitudeGovernor gov(design.params, design.cones);
  const governor::ConeConstraint& sun = robust_cones[0];
  const double beta = std::acos(sun.delta);  // an attitude with a_cᵀR a_b = δ
  EXPECT_GT((1.0 - m.delta) * sc.params.gains.kp * (1.0 - std::cos(sun.theta_c - beta)), m.gamma_min);
  // the true constraints stay the file's: the Sun keep-out cone of 40° is θ_c = 140°
  EXPECT_NEAR(sc.cones[0].theta_c, 140.0 * std::numbers::pi / 180.0, 1e-12);
}

TEST(RobustMarginSetup, RefusesScenariosWhoseBoundsLeaveNoAdmissibleSet) {
  EXPECT_NE(robust_error_of(robust_example("disturbance_bound = 0.003", "disturbance_bound = 0.03"))
                .find("control.margins: no admissible set with robust margins: Gamma_min = "),
            std::string::npos);
  // a command error (here rate noise × k_d) that reaches the wheels' torque limits
  EXPECT_NE(robust_error_of(robust_example("rate_noise = 0.00002", "rate_noise = 0.05"))
                .find("no admissible set with robust margins: the command error bound"),
            std::string::npos);
  // a bias bound whose coupling k_p 2 sin(β/2) leaves no strict Lyapunov function
  EXPECT_NE(robust_error_of(robust_example("attitude_bias_bound = 0.0215", "attitude_bias_bound = 1.1"))
                .find("control.margins: robust margins: no strict Lyapunov function W = V - eps w^T J s for kp = 0.5, "
                      "kd = 6 and the inertia's lambda_max = 150.3 with the attitude bias coupling"),
            std::string::npos);
}

TEST(RobustMarginSetup, RefusesTargetsAndStartsOutsideTheRobustSet) {
  EXPECT_NE(robust_error_of(robust_example("angle_deg = 120.0", "angle_deg = 105.0"))
                .find("desired.attitude: with robust margins this desired attitude lies in the widened repulsive band"),
            std::string::npos);
  EXPECT_NE(robust_error_of(robust_example("omega_b = [0.001, -0.001, 0.0005]", "omega_b = [0.02, -0.02, 0.01]"))
                .find("initial.omega_b: initial state not admissible with robust margins: W(0) + start allowance"),
            std::string::npos);
}

TEST(RobustMarginSetup, KeysOnlyWhereTheyMeanSomething) {
  EXPECT_NE(robust_error_of(robust_example("margins = \"robust\"", "margins = \"nominal\""))
                .find("control.robust_reference_step: only with margins = \"robust\""),
            std::string::npos);
  // (robust margins without the flight loop: docs/errors.md, robust_without_flight_loop)
  EXPECT_NE(robust_error_of(robust_example("attitude_bias_bound = 0.0215", "attitude_bias_bound = 0.0001"))
                .find("imperfections.attitude_bias_bound: below the norm of attitude_bias"),
            std::string::npos);
  EXPECT_NE(robust_error_of(robust_example("margins = \"robust\"", "margins = \"robustly\"")).find("control.margins"),
            std::string::npos);
  EXPECT_NE(robust_error_of(robust_example("governor = \"pet\"", "governor = \"none\""))
                .find("robust margins are margins of the governor"),
            std::string::npos);
}

// examples/pet_erg_robust_campaign.toml and its nominal twin are the same campaign but for the
// margins (docs/pet-erg.md, section 14): every line equal outside the header comment, the name,
// the description and the [control] margins lines.
TEST(Examples, RobustCampaignPairDiffersOnlyInTheMargins) {
  auto lines = [](const std::string& name) {
    std::ifstream in(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples" / name);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("#", 0) == 0 || line.rfind("name =", 0) == 0 || line.rfind("description =", 0) == 0 ||
          line.rfind("margins =", 0) == 0 || line.rfind("robust_reference_step =", 0) == 0) {
        continue;
      }
      out.push_back(line);
    }
    return out;
  };
  const std::vector<std::string> robust = lines("pet_erg_robust_campaign.toml");
  const std::vector<std::string> nominal = lines("pet_erg_robust_campaign_nominal.toml");
  EXPECT_GT(robust.size(), 80U);
  EXPECT_EQ(robust, nominal);
  EXPECT_EQ(parse(robust_example()).margins, governor::Margins::robust);
}

}  // namespace
}  // namespace attiguard::scenario
