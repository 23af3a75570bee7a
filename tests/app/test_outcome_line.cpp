// app/outcome_line: the one line of figures each command prints (docs/conventions.md, "Outcome
// line"), from the result files' JSON.

#include "attiguard/app/outcome_line.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace attiguard::app {
namespace {

using nlohmann::json;

bool has(const std::string& line, const std::string& piece) {
  return line.find(piece) != std::string::npos;
}

/// Every line: one line, starting with "outcome: ".
void expect_one_line(const std::string& line) {
  EXPECT_EQ(line.rfind("outcome: ", 0), 0U) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
}

TEST(OutcomeLine, PetErgConvergedShowsTimeRatioMarginAndTorque) {
  const json s = {{"outcome", "converged"},
                  {"convergence_time", 41.25},
                  {"eigenaxis_bang_bang_time", 12.5},
                  {"convergence_time_over_bang_bang", 3.3},
                  {"min_pointing_margin", 0.0123},
                  {"max_torque_norm", 0.75},
                  {"tau_max", 1.0},
                  {"constraints_satisfied", true},
                  {"duration", 100.0}};
  const std::string line = pet_erg_outcome_line(s);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: converged; at 41.25 s = 3.3x the eigenaxis bang-bang time 12.5 s"))
      << line;
  EXPECT_TRUE(has(line, "min pointing margin 0.0123")) << line;
  EXPECT_TRUE(has(line, "max |tau|/tau_max 0.75")) << line;
  EXPECT_TRUE(has(line, "constraints kept")) << line;
  EXPECT_FALSE(has(line, "not converged")) << line;
}

TEST(OutcomeLine, PetErgStalledSaysWhyAndLeavesOutMissingFigures) {
  const json s = {{"outcome", "stalled"},
                  {"outcome_reason", "reference stopped 62 deg short of R_d"},
                  {"convergence_time", nullptr},
                  {"convergence_time_over_bang_bang", nullptr},
                  {"min_pointing_margin", nullptr},  // no cone
                  {"max_torque_norm", 2.0},
                  {"tau_max", 1.0},
                  {"constraints_satisfied", false},
                  {"duration", 300.0}};
  const std::string line = pet_erg_outcome_line(s);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: stalled; not converged by 300 s")) << line;
  EXPECT_FALSE(has(line, "pointing margin")) << line;
  EXPECT_TRUE(has(line, "max |tau|/tau_max 2")) << line;
  EXPECT_TRUE(has(line, "constraint VIOLATED")) << line;
  EXPECT_TRUE(has(line, "reference stopped 62 deg short of R_d")) << line;
}

TEST(OutcomeLine, NonFiniteAndWrongTypedFiguresAreLeftOut) {
  const json s = {{"outcome", "diverged"},
                  {"convergence_time", "soon"},
                  {"min_pointing_margin", std::numeric_limits<double>::infinity()},
                  {"max_torque_norm", 1.0},
                  {"tau_max", 0.0}};
  const std::string line = pet_erg_outcome_line(s);
  expect_one_line(line);
  EXPECT_FALSE(has(line, "inf")) << line;
  EXPECT_FALSE(has(line, "tau_max")) << line;  // no ratio to a zero limit
  EXPECT_FALSE(has(line, "soon")) << line;
  expect_one_line(pet_erg_outcome_line(json::array()));
  // A reason with a line break stays on the line; an absent reason adds nothing.
  expect_one_line(pet_erg_outcome_line({{"outcome", "stalled"}, {"outcome_reason", "a\nb"}}));
  EXPECT_EQ(pet_erg_outcome_line({{"outcome", "stalled"}}), "outcome: stalled");
  EXPECT_EQ(pet_erg_outcome_line(json()).rfind("outcome: unknown", 0), 0U);
}

TEST(OutcomeLine, WaypointShowsTimeDeltaVAndWorstArrivalError) {
  const json s = {{"outcome", "completed"},
                  {"total_time", 812.5},
                  {"total_delta_v", 3.25},
                  {"max_final_position_error", 0.0421},
                  {"max_torque_norm", 0.1}};
  const std::string line = waypoint_outcome_line(s);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: completed; time 812.5 s; delta-v 3.25 m/s; worst arrival error 0.0421 m"))
      << line;
}

TEST(OutcomeLine, MissionTakesTheWorstWaypointAndTheCostOfTheConstraints) {
  const json s = {{"outcome", "completed"},
                  {"governor", "pet_erg"},
                  {"total_time", 100.0},
                  {"total_delta_v", 2.0},
                  {"waypoints", json::array({{{"final_position_error", 0.5}},
                                             {{"final_position_error", 0.75}}})},
                  {"min_pointing_margin", 0.08},
                  {"max_torque_norm", 0.5},
                  {"tau_max", 1.0},
                  {"constraints_satisfied", true},
                  {"time_cost", 12.0},
                  {"delta_v_cost", 0.25}};
  const std::string line = mission_outcome_line(s);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: completed (governor pet_erg)")) << line;
  EXPECT_TRUE(has(line, "worst arrival error 0.75 m")) << line;
  EXPECT_TRUE(has(line, "the constraints cost 12 s and 0.25 m/s against the unconstrained twin"))
      << line;
}

TEST(OutcomeLine, ReachNamesTheFirstUnprovedInterval) {
  const json r = {{"verdict", "cannot_prove"},
                  {"first_failure_time", 0.625},
                  {"safety_reason", "the ball leaves the keep-in cone"},
                  {"cells", 27},
                  {"steps", json::array({{{"t", 0.0}, {"t_end", 0.5}, {"safe", true}, {"r", 0.1}},
                                         {{"t", 0.5}, {"t_end", 1.0}, {"safe", false}, {"r", 0.2}},
                                         {{"t", 1.0}, {"t_end", 1.5}, {"safe", false}, {"r", 0.3},
                                          {"attitude_radius", 0.05}}})},
                  {"adversarial", {{"attitude_tightness", 1.91}}},
                  {"soundness", {{"samples", 2000}, {"inside", 2000}}}};
  const std::string line = reach_outcome_line(r);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: cannot_prove (first unproved at t = 0.625 s, in step [0.5, 1] s)")) << line;
  EXPECT_TRUE(has(line, "final ball r 0.3; attitude within 0.05 rad")) << line;
  EXPECT_TRUE(has(line, "tightness (claimed/seen attitude spread) 1.91")) << line;
  EXPECT_TRUE(has(line, "27 cells")) << line;
  EXPECT_TRUE(has(line, "2000/2000 sampled trajectories inside")) << line;
  EXPECT_TRUE(has(line, "the ball leaves the keep-in cone")) << line;

  // Several cells: the first cell's unsafe step is named only when it holds the first instant.
  json split = r;
  split["first_failure_time"] = 0.25;
  split["n_steps"] = 3;
  split["step_mode"] = "adaptive";
  split["partition"] = {{"cells_split", 1}};
  const std::string ls = reach_outcome_line(split);
  EXPECT_TRUE(has(ls, "outcome: cannot_prove (first unproved at t = 0.25 s)")) << ls;
  EXPECT_TRUE(has(ls, "3 adaptive steps; 27 cells (1 cell split)")) << ls;

  const json safe = {{"verdict", "safe"}, {"steps", json::array({{{"t", 0.0}, {"t_end", 1.0}, {"safe", true}, {"r", 0.1}}})}};
  EXPECT_FALSE(has(reach_outcome_line(safe), "unproved")) << reach_outcome_line(safe);
}

TEST(OutcomeLine, CampaignCountsStatusesOutcomesAndViolations) {
  const json c = {{"runs_requested", 10000},
                  {"runs_completed", 10000},
                  {"ok", 9998},
                  {"rejected", 1},
                  {"failures", 1},
                  {"violations", 0},
                  {"outcomes", {{"converged", 9990}, {"stalled", 8}}},
                  {"figures", {{"convergence_time", {{"count", 9990}, {"min", 10.0}, {"p50", 12.5}, {"max", 20.0}}}}}};
  const std::string line = campaign_outcome_line(c);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: done (10000 of 10000 runs); 9998 ok, 1 rejected, 1 failed")) << line;
  EXPECT_TRUE(has(line, "outcomes: 9990 converged, 8 stalled")) << line;
  EXPECT_TRUE(has(line, "0 runs with a constraint violation")) << line;
  EXPECT_TRUE(has(line, "convergence_time over 9990 runs: min 10, median 12.5, max 20 s")) << line;

  json partial = c;
  partial["runs_completed"] = 12;
  EXPECT_EQ(campaign_outcome_line(partial).rfind("outcome: partial (12 of 10000 runs)", 0), 0U);
  json violating = c;
  violating["violations"] = 1;
  EXPECT_TRUE(has(campaign_outcome_line(violating), "outcome: violations")) << campaign_outcome_line(violating);
  EXPECT_TRUE(has(campaign_outcome_line(violating), "1 run with a constraint violation"));
}

TEST(OutcomeLine, TuneCountsPointsAndShowsTheBest) {
  const json t = {
      {"outcome", "found"},
      {"evaluated", 3},
      {"admissible", 1},
      {"points", json::array({{{"status", "ok"}, {"outcome", "converged"}, {"violations", 0}},
                              {{"status", "ok"}, {"outcome", "converged"}, {"violations", 1}},
                              {{"status", "rejected"}, {"outcome", nullptr}, {"violations", 0}}})},
      {"best", {{"convergence_time", 30.0}, {"convergence_time_over_bang_bang", 3.85},
                {"values", {{"kappa", 2.5}, {"kp", 1.0}}}}},
      {"nominal", {{"convergence_time", 60.0}, {"convergence_time_over_bang_bang", 7.7}}}};
  const std::string line = tune_outcome_line(t);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "outcome: found (1 of 3 points admissible); 2 ok, 1 rejected")) << line;
  EXPECT_TRUE(has(line, "outcomes: 2 converged")) << line;
  EXPECT_TRUE(has(line, "1 point with a constraint violation")) << line;
  EXPECT_TRUE(has(line, "best 30 s = 3.85x bang-bang at kappa = 2.5, kp = 1")) << line;
  EXPECT_TRUE(has(line, "scenario's own values 60 s = 7.7x")) << line;

  const json none = {{"outcome", "none_converged"}, {"outcome_reason", "none of the 3 evaluated points converged"},
                     {"best", nullptr}, {"points", json::array()}};
  EXPECT_TRUE(has(tune_outcome_line(none), "none of the 3 evaluated points converged"));
  EXPECT_FALSE(has(tune_outcome_line(none), "best")) << tune_outcome_line(none);
}

TEST(OutcomeLine, RigidBodyShowsTheFinalErrors) {
  const json s = {{"duration", 20.0}, {"final_attitude_error_rad", 1e-6}, {"final_omega_norm", 2e-7},
                  {"max_energy_drift_rel", 3e-12}};
  const std::string line = rigid_body_outcome_line(s);
  expect_one_line(line);
  EXPECT_TRUE(has(line, "final attitude error 1e-06 rad")) << line;
  EXPECT_TRUE(has(line, "max relative energy drift 3e-12")) << line;
}

}  // namespace
}  // namespace attiguard::app
