// The saddle tie-break end to end (docs/pet-erg.md, section 4, "Saddles: the tie-break"; issue
// 41): the Sun exactly on the eigenaxis path of the star tracker stalls the reference without it
// and converges with it, in the continuous-time loop (PET-ERG and continuous ERG), in the flight
// loop with robust margins and imperfections, on a principal and an off-principal slew axis;
// overlapping bands (a minimum of P) stay stalled.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "attiguard/app/outcome_line.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_run.hpp"

namespace attiguard::sim {
namespace {

std::string tie_break_file_text(const std::string& relative) {
  std::ifstream in(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// examples/pet_erg_symmetric_sun.toml with each `from` replaced by its `to` (first occurrence).
std::string symmetric_sun_text(const std::vector<std::pair<std::string, std::string>>& edits = {}) {
  std::string text = tie_break_file_text("examples/pet_erg_symmetric_sun.toml");
  for (const auto& [from, to] : edits) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
  }
  return text;
}

/// The same saddle with the slew axis z off the principal axes: J with products of inertia. The
/// body leaves the slew plane (gyroscopic coupling), R_g does not (its field does not depend on J).
const std::vector<std::pair<std::string, std::string>> kOffPrincipalAxis{
    {"inertia = [1.0, 2.0, 3.0]", "inertia = [[1.5, 0.1, -0.2], [0.1, 2.0, 0.15], [-0.2, 0.15, 3.0]]"}};

/// The saddle on the tilted slew axis k = (0, 1, 1)/√2 (J = diag(1, 2, 3)): R_d = 120° about k, the
/// Sun where it takes the tracker at mid-slew, Rot(k, 60°) x = (½, √6/4, −√6/4). Not exactly
/// symmetric in floating point: rounding alone moves R_g off the saddle.
const std::vector<std::pair<std::string, std::string>> kTiltedAxis{
    {"axis = [0.0, 0.0, 1.0], angle_deg = 120.0", "axis = [0.0, 1.0, 1.0], angle_deg = 120.0"},
    {"direction_i = [0.5, 0.8660254037844386, 0.0]", "direction_i = [0.5, 0.6123724356957945, -0.6123724356957945]"}};

/// The flight loop at 20 Hz with robust margins and every imperfection within its bound (gains
/// slow enough for the robust design to be admissible: docs/pet-erg.md, section 13).
std::vector<std::pair<std::string, std::string>> robust_flight_loop_edits() {
  return {{"kp = 5.0", "kp = 0.5"},
          {"kd = 1.0", "kd = 1.5"},
          {"tau_max = 2.5", "tau_max = 0.5\ncontrol_period = 0.05\nmargins = \"robust\""},
          {"duration = 60.0", "duration = 150.0"},
          {"step = 0.01", "step = 0.01\nconvergence_tolerance = 1e-3\n\n[imperfections]\n"
                          "disturbance = \"random\"\ndisturbance_bound = 0.002\n"
                          "attitude_bias = [0.0005, -0.0005, 0.0002]\nattitude_bias_bound = 0.001\n"
                          "attitude_noise = 0.0002\nrate_bias = [0.0001, 0.0, -0.0001]\nrate_noise = 0.0001\n"
                          "torque_quantum = 0.0001"}};
}

struct TieBreakRun {
  PetErgResult result;
  nlohmann::json summary;
};

TieBreakRun run_tie_break_scenario(const std::string& text, bool tie_break) {
  PetErgScenario sc = scenario::parse_pet_erg(scenario::parse_document(text, "symmetric_sun.toml"));
  sc.params.saddle_tie_break = tie_break;
  TieBreakRun run{simulate_pet_erg(sc), {}};
  run.summary = pet_erg_summary(sc, run.result);
  return run;
}

/// Without the tie-break: stalled far short of R_d in the band of cone 0, safe.
void expect_stalled_at_the_saddle(const TieBreakRun& run) {
  const nlohmann::json& s = run.summary;
  EXPECT_EQ(s["outcome"], "stalled") << s.dump(1);
  EXPECT_TRUE(s["constraints_satisfied"].get<bool>());
  EXPECT_GT(run.result.reference_distance_left, 80.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(s["active_cones"], nlohmann::json::array({0}));
  EXPECT_EQ(s["saddle_tie_breaks"], 0);
  EXPECT_TRUE(s["first_tie_break_time"].is_null());
  EXPECT_EQ(s["tie_break_cones"], nlohmann::json::array());
}

/// With it: converged, every constraint kept, V ≤ Γ, one tie-break around cone 0, named by the
/// summary and the outcome line.
void expect_converged_after_one_tie_break(const TieBreakRun& run) {
  const nlohmann::json& s = run.summary;
  EXPECT_EQ(s["outcome"], "converged") << s.dump(1);
  EXPECT_TRUE(s["constraints_satisfied"].get<bool>());
  EXPECT_TRUE(s["V_below_Gamma"].get<bool>());
  EXPECT_GE(s["min_pointing_margin"].get<double>(), 0.0);
  EXPECT_EQ(s["saddle_tie_breaks"], 1);
  ASSERT_TRUE(s["first_tie_break_time"].is_number());
  EXPECT_LT(s["first_tie_break_time"].get<double>(), s["convergence_time"].get<double>());
  EXPECT_EQ(s["tie_break_cones"], nlohmann::json::array({0}));
  const std::string line = app::pet_erg_outcome_line(s);
  EXPECT_EQ(line.rfind("outcome: converged (saddle tie-break around cone 0 at t = ", 0), 0U) << line;
}

TEST(PetErgTieBreak, SymmetricSunStallsWithoutTheTieBreakAndConvergesWithIt) {
  const std::string text = symmetric_sun_text();
  expect_stalled_at_the_saddle(run_tie_break_scenario(text, false));
  const TieBreakRun run = run_tie_break_scenario(text, true);
  expect_converged_after_one_tie_break(run);
  // Measured (docs/pet-erg.md, section 4): the tie-break at the sample t = 7.5 s.
  EXPECT_NEAR(run.summary["first_tie_break_time"].get<double>(), 7.5, 1e-9);
  EXPECT_NE(app::pet_erg_outcome_line(run.summary).find("(saddle tie-break around cone 0 at t = 7.5 s)"),
            std::string::npos);
}

TEST(PetErgTieBreak, OffPrincipalSlewAxisStallsWithoutTheTieBreakAndConvergesWithIt) {
  const std::string text = symmetric_sun_text(kOffPrincipalAxis);
  expect_stalled_at_the_saddle(run_tie_break_scenario(text, false));
  expect_converged_after_one_tie_break(run_tie_break_scenario(text, true));
}

TEST(PetErgTieBreak, TiltedSlewAxisConvergesWithTheTieBreak) {
  // Rounding breaks this symmetry by itself (the reference escapes the saddle without the
  // tie-break too); the tie-break fires at the saddle and the run converges as well.
  const TieBreakRun run = run_tie_break_scenario(symmetric_sun_text(kTiltedAxis), true);
  expect_converged_after_one_tie_break(run);
  EXPECT_EQ(run_tie_break_scenario(symmetric_sun_text(kTiltedAxis), false).summary["outcome"], "converged");
}

TEST(PetErgTieBreak, ContinuousErgBreaksTheSaddleAtTheSamplingInstants) {
  const std::string text = symmetric_sun_text({{"governor = \"pet\"", "governor = \"continuous\""}});
  expect_stalled_at_the_saddle(run_tie_break_scenario(text, false));
  const TieBreakRun run = run_tie_break_scenario(text, true);
  expect_converged_after_one_tie_break(run);
  // Sampled at the instants k T_s like the PET-ERG's trigger.
  const double t = run.summary["first_tie_break_time"].get<double>();
  EXPECT_NEAR(t / 0.5, std::round(t / 0.5), 1e-9);
}

TEST(PetErgTieBreak, RobustFlightLoopBreaksTheSaddleOnBothSlewAxes) {
  for (const bool off_principal : {false, true}) {
    std::vector<std::pair<std::string, std::string>> edits = robust_flight_loop_edits();
    if (off_principal) edits.insert(edits.end(), kOffPrincipalAxis.begin(), kOffPrincipalAxis.end());
    const std::string text = symmetric_sun_text(edits);
    SCOPED_TRACE(off_principal ? "off-principal axis" : "principal axis z");
    const TieBreakRun without = run_tie_break_scenario(text, false);
    EXPECT_EQ(without.summary["margins"], "robust");
    EXPECT_EQ(without.summary["control_period"], 0.05);
    expect_stalled_at_the_saddle(without);
    expect_converged_after_one_tie_break(run_tie_break_scenario(text, true));
  }
}

TEST(PetErgTieBreak, FlightLoopAtTenHertzBreaksTheSaddle) {
  const std::string text = symmetric_sun_text({{"tau_max = 2.5", "tau_max = 2.5\ncontrol_period = 0.1"}});
  expect_stalled_at_the_saddle(run_tie_break_scenario(text, false));
  expect_converged_after_one_tie_break(run_tie_break_scenario(text, true));
}

TEST(PetErgTieBreak, AConeOnOneSideSendsTheDetourToTheOther) {
  // A second keep-out cone (15°) 50° above the Sun, at Rz(60°)(cos 50°, 0, sin 50°): its band
  // overlaps the Sun's above the Sun, so the side σ = +1 of the exact saddle (up) leads into a
  // minimum of P between the two bands. The look-ahead around the Sun's cone sees it and the
  // detour goes below (docs/pet-erg.md, section 4, "The side").
  const std::string moon =
      "[[cones]]\ntype = \"keep_out\"\naxis_b = [1.0, 0.0, 0.0]\n"
      "direction_i = [0.32139380484326974, 0.5566703992264194, 0.766044443118978]\nhalf_angle_deg = 15.0\n\n"
      "[simulation]";
  const TieBreakRun run = run_tie_break_scenario(symmetric_sun_text({{"[simulation]", moon}}), true);
  expect_converged_after_one_tie_break(run);
  // The mirror image of the run without the Moon: the same convergence time, far from the Moon.
  const TieBreakRun alone = run_tie_break_scenario(symmetric_sun_text(), true);
  EXPECT_NEAR(run.summary["convergence_time"].get<double>(), alone.summary["convergence_time"].get<double>(), 1e-9);
  EXPECT_GT(run.summary["min_pointing_margin_per_cone"][1].get<double>(), 0.3);
}

TEST(PetErgTieBreak, OverlappingBandsAreAMinimumOfPAndStayStalled) {
  // tests/data/campaign/pet_erg_stalling.toml without its [dispersions] (docs/pet-erg.md,
  // "Outcomes"): two bands hold R_g between them, P rises on both sides of the detour direction.
  std::string text = tie_break_file_text("tests/data/campaign/pet_erg_stalling.toml");
  text.erase(text.find("[dispersions]"));
  const TieBreakRun run = run_tie_break_scenario(text, true);
  EXPECT_EQ(run.summary["outcome"], "stalled") << run.summary.dump(1);
  EXPECT_EQ(run.summary["saddle_tie_breaks"], 0);
  EXPECT_EQ(run.summary["active_cones"], nlohmann::json::array({0, 1}));
  EXPECT_TRUE(run.summary["constraints_satisfied"].get<bool>());
  const TieBreakRun without = run_tie_break_scenario(text, false);
  EXPECT_EQ(run.result.reference_motion.reversals(), without.result.reference_motion.reversals());
  EXPECT_EQ(run.summary["reference_distance_left"], without.summary["reference_distance_left"]);
}

}  // namespace
}  // namespace attiguard::sim
