// Scenario kind `waypoint`: the paper scenario and the fine-position scenario end to end, outputs,
// and input errors (docs/waypoint.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>
#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "sanitizer_build.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"
#include "cli_runner.hpp"

namespace attiguard::sim {
namespace {

sim::WaypointScenario load(const std::string& file) {
  return scenario::parse_waypoint(scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/" + file));
}

TEST(WaypointRun, PaperScenarioVisitsTheWaypointsInOrder) {
  const sim::WaypointScenario sc = load("examples/waypoint_paper.toml");
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.completed);
  ASSERT_TRUE(res.finite);
  std::vector<int> arrivals;
  double t_prev = 0.0;
  for (const TransitionRecord& r : res.transitions) {
    if (r.reason == guidance::TransitionReason::accuracy_met) arrivals.push_back(r.waypoint);
  }
  EXPECT_EQ(arrivals, (std::vector<int>{0, 1, 2}));
  for (const WaypointResult& w : res.waypoints) {
    EXPECT_TRUE(w.reached);
    EXPECT_GT(w.arrival_time, t_prev);
    t_prev = w.arrival_time;
    EXPECT_LT(w.final_speed, sc.mission.speed_accuracy);  // κ_p = 0: only the speed is nulled
    std::printf("paper WP-%d: t = %.1f s, |e| = %.3f m, |v| = %.4f m/s, dv = %.3f m/s\n", w.index + 1,
                w.arrival_time, w.final_position_error, w.final_speed, w.delta_v());
  }
}

TEST(WaypointRun, FinePositionControlReachesEveryWaypoint) {
  const sim::WaypointScenario sc = load("examples/waypoint_fine.toml");
  ASSERT_GT(sc.mission.rct.kappa_p, 0.0);
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.completed);
  for (const WaypointResult& w : res.waypoints) {
    EXPECT_TRUE(w.reached);
    EXPECT_LT(w.final_position_error, 1.0);
    EXPECT_LT(w.final_speed, 0.01);
    std::printf("fine WP-%d: t = %.1f s, |e| = %.3f m, |v| = %.4f m/s, dv = %.3f m/s\n", w.index + 1,
                w.arrival_time, w.final_position_error, w.final_speed, w.delta_v());
  }
  EXPECT_LE(res.max_torque_norm, 5.0 * std::sqrt(3.0) + 1e-9);  // wheel limit 5 N·m per axis
}

std::string doc_with(const std::string& from, const std::string& to);

/// examples/<file> as text with each `from` replaced once by its `to`.
std::string example_with(const std::string& file,
                         const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/" + file);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  for (const auto& [from, to] : edits) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
  }
  return text;
}

std::string fine_doc_with(const std::vector<std::pair<std::string, std::string>>& edits) {
  return example_with("waypoint_fine.toml", edits);
}

// Beyond the paper: the main engine misaligned by 1 deg (unknown to the guidance). Without the
// brake mode and the flip-due end of acceleration the lateral miss sends the mission into
// endless re-plans (docs/waypoint.md, "Main-engine misalignment"); with them every waypoint is
// reached to fine-control accuracy, at a cost in time and delta-v.
TEST(WaypointRun, OneDegreeEngineMisalignmentStillReachesEveryWaypoint) {
  const double tilt = 1.0 * M_PI / 180.0;
  std::ostringstream axis;
  axis.precision(17);
  axis << "main_thrust_axis_b = [" << std::cos(tilt) << ", " << 0.6 * std::sin(tilt) << ", "
       << 0.8 * std::sin(tilt) << "]\nmax_wheel_torque = 5.0";
  const std::string text = fine_doc_with(
      {{"max_wheel_torque = 5.0", axis.str()}, {"duration = 6000.0", "duration = 15000.0"}});
  const sim::WaypointScenario sc =
      scenario::parse_waypoint(scenario::parse_document(text, "tilted.toml"));
  ASSERT_GT(sc.mission.brake_speed, 0.0);
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.completed);
  for (const WaypointResult& w : res.waypoints) {
    EXPECT_LT(w.final_position_error, 1.0);
    EXPECT_LT(w.final_speed, 0.01);
  }
  bool braked = false;
  for (const auto& tr : res.transitions) braked = braked || tr.to == guidance::Mode::brake;
  EXPECT_TRUE(braked);
  double delta_v = 0.0;
  for (const WaypointResult& w : res.waypoints) delta_v += w.delta_v();
  std::printf("[ measured ] 1 deg misalignment: %.1f s, delta-v %.2f m/s, %zu transitions\n",
              res.total_time, delta_v, res.transitions.size());

  // The same engine with the brake mode and the lateral RCT off (Algorithm 1 as printed): the
  // mission fails.
  const sim::WaypointScenario printed = scenario::parse_waypoint(scenario::parse_document(
      fine_doc_with({{"max_wheel_torque = 5.0", axis.str()},
                     {"duration = 6000.0", "duration = 15000.0"},
                     {"replan_distance = 50.0", "replan_distance = 50.0\nbrake_speed = 0.0\nlateral_rct = false"}}),
      "printed.toml"));
  EXPECT_FALSE(simulate_waypoint(printed).completed);
}

// Issue 13, first bullet: flying straight through the waypoint diverged (exit 3, "integrator:
// non-finite state at t = 102.51 s"): the reversed error direction of the flip became exactly
// antiparallel to its chart (n = 0 in error_frame()). Now the crossing is an overshoot that
// brakes and re-plans, and the run completes within its accuracy.
// Issue 25's typical heavy craft (6.2 t, J ≈ 8·10⁴ kg·m², 1.85 N·m wheels): its 3.2 km first
// leg is inside half the derived re-plan distance and flown by the RCT. Along the switching line
// alone (v = λe, far beyond what 10.5 N can brake) it was still 256 m short after 20 000 s; with
// the braking curve of the RCT law it completes, and within 20 % of the predicted time.
TEST(WaypointRun, HeavyCraftsRctLegFollowsTheBrakingCurveAndMeetsThePrediction) {
  const sim::WaypointScenario sc = load("tests/data/waypoint/heavy_short_first_leg.toml");
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.finite);
  ASSERT_TRUE(res.completed) << waypoint_outcome(sc, res).reason;
  const nlohmann::json s = waypoint_summary(sc, res);
  const double ratio = s["time_over_predicted"].get<double>();
  EXPECT_GT(ratio, 0.8);
  EXPECT_LT(ratio, 1.2);
  EXPECT_TRUE(s["prediction"]["legs"][0]["rct_only"].get<bool>());
  EXPECT_FALSE(s["prediction"]["legs"][1]["rct_only"].get<bool>());
  for (const auto& leg : s["legs"]) EXPECT_GT(leg["time_over_predicted"].get<double>(), 0.5);
  std::printf("[ measured ] heavy craft: %.1f s, predicted %.1f s (ratio %.3f)\n", res.total_time,
              s["predicted_time"].get<double>(), ratio);
}

// `attiguard check` prints the prediction of every leg and of the mission (docs/waypoint.md,
// "Prediction"), and warns, exit 0, when simulation.duration is shorter than the prediction.
TEST(WaypointCli, CheckPrintsThePredictionAndWarnsOfAShortDuration) {
  const test::CliResult ok = test::run_cli("check tests/data/waypoint/heavy_short_first_leg.toml");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("predicted leg 0: "), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("RCT only"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("predicted leg 1: "), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("predicted mission: "), std::string::npos) << ok.out;
  EXPECT_EQ(ok.out.find("warning"), std::string::npos) << ok.out;
  const auto dir = test::fresh_dir("waypoint_short_duration");
  std::string text = test::read_file(std::string(ATTIGUARD_SOURCE_DIR) + "/tests/data/waypoint/heavy_short_first_leg.toml");
  text.replace(text.find("duration = 20000.0"), 18, "duration = 9000.0");
  { std::ofstream(dir / "short.toml") << text; }
  const test::CliResult warned = test::run_cli("check '" + (dir / "short.toml").string() + "'");
  EXPECT_EQ(warned.exit_code, 0) << warned.err;
  EXPECT_NE(warned.out.find("warning: simulation.duration 9000.0 s is shorter than the predicted mission time"),
            std::string::npos) << warned.out;
  std::filesystem::remove_all(dir);
}

// The paper example (Tables I-II): predicted within 10 % of the flown 3240.4 s.
TEST(WaypointRun, PaperExampleIsPredictedWithinTenPerCent) {
  const sim::WaypointScenario sc = load("examples/waypoint_paper.toml");
  const nlohmann::json p = prediction_entry(predict_waypoint_mission(sc));
  EXPECT_NEAR(p["time"].get<double>(), 3240.4, 324.0);
  EXPECT_NEAR(p["delta_v"].get<double>(), 339.48, 5.0);
  EXPECT_EQ(p["legs"].size(), 3u);
}

TEST(WaypointRun, StraightCrossingOfTheWaypointCompletesWithoutNan) {
  const sim::WaypointScenario sc = load("tests/data/waypoint/straight_crossing.toml");
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.finite);
  ASSERT_TRUE(res.completed) << res.total_time;
  EXPECT_LT(res.waypoints[0].final_position_error, sc.mission.position_accuracy);
  EXPECT_LT(res.waypoints[0].final_speed, sc.mission.speed_accuracy);
  std::printf("[ measured ] straight crossing: %.1f s, delta-v %.3f m/s\n", res.total_time,
              res.waypoints[0].delta_v());
}

// Issue 13, second bullet: starting with a velocity away from the waypoint, (13) tested ‖v‖ and
// the craft coasted away for 3000 s (850 m off, Δv 0, exit 0). Decisions now use the closing
// speed: the craft turns back and arrives.
TEST(WaypointRun, StartingAwayFromTheWaypointTurnsBackInsteadOfCoastingAway) {
  const sim::WaypointScenario sc = load("tests/data/waypoint/coasting_away.toml");
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.finite);
  ASSERT_TRUE(res.completed) << res.total_time;
  EXPECT_LT(res.waypoints[0].final_position_error, sc.mission.position_accuracy);
  EXPECT_GT(res.waypoints[0].delta_v(), 0.45);  // at least the 0.25 m/s away + 0.2 m/s towards
  std::printf("[ measured ] receding start: %.1f s, delta-v %.3f m/s\n", res.total_time,
              res.waypoints[0].delta_v());
}

// Issue 13, third bullet: a 5 m arrival radius handed over to the RCT at 0.66 m/s, which they
// could not stop (3000 s of oscillation). Now fine control is entered only below brake_speed.
TEST(WaypointRun, LargeArrivalRadiusHandsOverOnlyAtASpeedTheRctCanStop) {
  sim::WaypointScenario sc = load("tests/data/waypoint/straight_crossing.toml");
  sc.mission.arrival_radius = 5.0;
  double worst_entry = 0.0;
  const WaypointSimResult res =
      simulate_waypoint(sc, [&](double, const dynamics::SpacecraftState& y, const guidance::MissionCommand& c) {
        if (c.transition && c.mode == guidance::Mode::fine) {
          worst_entry = std::max(worst_entry, dynamics::v_i_of(y).norm());
        }
      });
  EXPECT_TRUE(res.completed) << res.total_time;
  EXPECT_GT(worst_entry, 0.0);
  EXPECT_LE(worst_entry, sc.mission.brake_speed);
}

// After an overshoot the re-planned leg used to coast away for ever as well (4350 s to 12000 s,
// 2170 m away): coasting with a closing speed <= 0 is now an overshoot that re-plans.
TEST(WaypointRun, CoastingAwayIsAnOvershootThatReplans) {
  sim::WaypointScenario sc = load("tests/data/waypoint/coasting_away.toml");
  sc.R0_ib = lie::quat_to_rotation(lie::Quat(0.0, 0.0, 0.0, 1.0));  // x_b away from the waypoint
  sc.v0_i = lie::Vec3(-0.5, 0.0, 0.0);
  bool coasted_away = false;
  const WaypointSimResult res =
      simulate_waypoint(sc, [&](double, const dynamics::SpacecraftState& y, const guidance::MissionCommand& c) {
        const lie::Vec3 e = sc.waypoints_i[0] - dynamics::p_i_of(y);
        if (c.mode == guidance::Mode::coast && guidance::closing_speed(e, dynamics::v_i_of(y)) < -1e-3) {
          coasted_away = true;
        }
      });
  EXPECT_FALSE(coasted_away);
  EXPECT_TRUE(res.completed) << res.total_time;
}

// Issue 13: an honest outcome. A run cut short says `incomplete` and why, with the distance and
// speed left; a completed one says `completed` and no reason.
TEST(WaypointRun, OutcomeIsCompletedOrIncompleteWithTheReasonAndWhatIsLeft) {
  sim::WaypointScenario sc = load("tests/data/waypoint/coasting_away.toml");
  const nlohmann::json done = waypoint_summary(sc, simulate_waypoint(sc));
  EXPECT_EQ(done["outcome"], "completed");
  EXPECT_FALSE(done.contains("outcome_reason"));
  sc.duration = 300.0;
  const WaypointSimResult cut = simulate_waypoint(sc);
  const nlohmann::json j = waypoint_summary(sc, cut);
  EXPECT_EQ(j["outcome"], "incomplete");
  const std::string why = j["outcome_reason"].get<std::string>();
  EXPECT_NE(why.find("time out at 300.0 s"), std::string::npos) << why;
  char left[64];
  std::snprintf(left, sizeof left, "%.3f m away", cut.final_distance);
  EXPECT_NE(why.find(left), std::string::npos) << why;
  EXPECT_GT(cut.final_distance, 1.0);

  // Moving away at the end is named as such.
  sc.v0_i = lie::Vec3(-0.25, 0.0, 0.0);
  sc.duration = 0.5;  // still receding: 0.5 s of thrust take 0.1 of the 0.25 m/s
  const WaypointSimResult away = simulate_waypoint(sc);
  EXPECT_NE(waypoint_outcome(sc, away).reason.find("moving away"), std::string::npos)
      << waypoint_outcome(sc, away).reason;
}

/// Time from the last hand-over to fine control until the end of the run [s].
double last_fine_phase(const WaypointSimResult& res) {
  double start = res.total_time;
  for (const auto& tr : res.transitions) {
    if (tr.to == guidance::Mode::fine) start = tr.t;
  }
  return res.total_time - start;
}

// Issue 42, item 1: braking against v stops the craft on the line it flies, which misses the
// waypoint by the speed across the line of sight left from the start's drift (here 0.4 m/s on an
// 11 km leg: a 200 m miss). With the RCT nulling that speed while the main engine flies the leg
// (docs/waypoint.md, "Lateral RCT") the last fine phase is short; without them it is long.
TEST(WaypointRun, LateralRctPutTheBrakingOnTheWaypoint) {
  const sim::WaypointScenario sc = load("tests/data/waypoint/lateral_drift_large_craft.toml");
  ASSERT_TRUE(sc.mission.lateral_rct);
  const WaypointSimResult res = simulate_waypoint(sc);
  ASSERT_TRUE(res.completed) << waypoint_outcome(sc, res).reason;
  sim::WaypointScenario off = sc;
  off.mission.lateral_rct = false;
  const WaypointSimResult res_off = simulate_waypoint(off);
  ASSERT_TRUE(res_off.completed) << waypoint_outcome(off, res_off).reason;
  std::printf("[ measured ] last fine phase %.1f s of %.1f s (lateral RCT), %.1f s of %.1f s (without)\n",
              last_fine_phase(res), res.total_time, last_fine_phase(res_off), res_off.total_time);
  EXPECT_LT(last_fine_phase(res), 0.05 * res.total_time);
  EXPECT_GT(last_fine_phase(res_off), 4.0 * last_fine_phase(res));
  EXPECT_LT(res.total_time, res_off.total_time);
}

// Issue 42: crafts beyond the class generator, each given 1.5 x the tool's own prediction (a
// 100 t tug, a 1 kg and a 6U CubeSat with a reversal and a zero-length leg, a 400 t station on
// two opposite collinear legs). The sanitized build flies the two CubeSats only (the stations'
// missions of 10⁴–10⁵ s took 100 s there, sanitizer_build.hpp); Release flies all four.
TEST(WaypointRun, AStationClassTugAndAOneKilogramCubeSatCompleteWithinOneAndAHalfPredictions) {
  std::vector<const char*> files{"tests/data/waypoint/cubesat_1kg.toml", "tests/data/waypoint/cubesat_6u_reversal.toml"};
  if (attiguard::test::kSanitizedWorkDivisor == 1) {
    files.push_back("tests/data/waypoint/station_tug_100t.toml");
    files.push_back("tests/data/waypoint/station_400t_collinear.toml");
  }
  for (const char* file : files) {
    sim::WaypointScenario sc = load(file);
    const double predicted = predict_waypoint_mission(sc).time;
    sc.duration = 1.5 * predicted;
    const WaypointSimResult res = simulate_waypoint(sc);
    ASSERT_TRUE(res.finite) << file;
    EXPECT_TRUE(res.completed) << file << ": " << waypoint_outcome(sc, res).reason;
    std::printf("[ measured ] %s: %.1f s, predicted %.1f s (%.3f)\n", file, res.total_time, predicted,
                res.total_time / predicted);
  }
}

TEST(WaypointRun, BrakingAlongTheVelocityBeatsTheNormOfTheError) {
  // (14) holds along a line: braking on ‖e‖ with a lateral offset passes the closest point with
  // speed left, which κ_p = 0 cannot take back (Algorithm 1 as printed: no brake mode).
  const auto norm = scenario::parse_waypoint(scenario::parse_document(
      doc_with("braking_distance = \"along_velocity\"",
               "braking_distance = \"norm\"\nbrake_speed = 0.0"),
      "norm.toml"));
  const WaypointSimResult r_norm = simulate_waypoint(norm);
  const WaypointSimResult r_along = simulate_waypoint(load("examples/waypoint_paper.toml"));
  EXPECT_GT(r_norm.waypoints[2].final_position_error, 5.0);
  EXPECT_LT(r_along.waypoints[2].final_position_error, 1.0);
  // The brake mode (beyond the paper) takes that speed back with the main engine.
  const auto norm_brake = scenario::parse_waypoint(scenario::parse_document(
      doc_with("braking_distance = \"along_velocity\"", "braking_distance = \"norm\""),
      "norm_brake.toml"));
  EXPECT_LT(simulate_waypoint(norm_brake).waypoints[2].final_position_error, 2.0);
}

std::string doc_with(const std::string& from, const std::string& to) {
  return example_with("waypoint_paper.toml", {{from, to}});
}

void expect_input_error(const std::string& text, const std::string& needle) {
  try {
    (void)scenario::parse_waypoint(scenario::parse_document(text, "bad.toml"));
    ADD_FAILURE() << "no InputError for " << needle;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(WaypointScenario, RejectsUnreachableWaypointsAndBadParameters) {
  expect_input_error(doc_with("duration = 6000.0", "duration = 1000.0"), "unreachable");
  expect_input_error(doc_with("main_thrust = 20.0", "main_thrust = -20.0"), "main_thrust");
  expect_input_error(doc_with("acceleration_fraction = 0.2", "acceleration_fraction = 0.7"),
                     "acceleration_fraction");
  expect_input_error(doc_with("replan_distance = 50.0", "replan_distance = 0.001"), "replan_distance");
  expect_input_error(doc_with("kappa_d = 5.0", "kappa_d = 0.0"), "kappa_d");
  expect_input_error(doc_with("output_interval = 1.0", "output_interval = 0.01"), "output_interval");
  expect_input_error(doc_with("cruise_speed = 100.0", "cruise_sped = 100.0"), "cruise_sped");
  expect_input_error(doc_with("cruise_speed = 100.0", "cruise_speed = 100.0\nlateral_rct = 1"), "lateral_rct");
  // A main engine more than 10 deg from body x (here 26 deg).
  expect_input_error(doc_with("main_thrust = 20.0", "main_thrust = 20.0\nmain_thrust_axis_b = [0.9, 0.44, 0.0]"),
                     "main_thrust_axis_b");
}

TEST(WaypointScenario, AnExplicitBodyXEngineAxisIsThePaperPlant) {
  const sim::WaypointScenario sc = scenario::parse_waypoint(scenario::parse_document(
      doc_with("main_thrust = 20.0", "main_thrust = 20.0\nmain_thrust_axis_b = [2.0, 0.0, 0.0]"),
      "axis.toml"));
  EXPECT_EQ(sc.main_thrust_axis_b, lie::Vec3::UnitX());  // normalised
  const WaypointSimResult explicit_axis = simulate_waypoint(sc);
  const WaypointSimResult paper = simulate_waypoint(load("examples/waypoint_paper.toml"));
  ASSERT_EQ(explicit_axis.waypoints.size(), paper.waypoints.size());
  EXPECT_EQ(explicit_axis.waypoints[2].final_position_error, paper.waypoints[2].final_position_error);
}

#ifdef ATTIGUARD_CLI_PATH
TEST(WaypointCli, RunWritesTheListedOutputs) {
  const auto out = test::fresh_dir("waypoint_run");
  const test::CliResult r = test::run_cli("run examples/waypoint_paper.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = test::read_file(out / "trajectory.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "t,p_x,p_y,p_z,v_x,v_y,v_z,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z,tau_x,tau_y,tau_z,"
            "thrust,rct_1,rct_2,rct_3,rct_4,rct_5,rct_6,mode,waypoint");
  const auto s = nlohmann::json::parse(test::read_file(out / "summary.json"));
  for (const char* key : {"waypoints", "total_time", "total_delta_v", "max_torque_norm", "steps",
                          "wall_time_s"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  ASSERT_EQ(s.at("waypoints").size(), 3u);
  for (const auto& w : s.at("waypoints")) {
    for (const char* key : {"index", "arrival_time", "final_position_error", "final_speed", "delta_v"}) {
      EXPECT_TRUE(w.contains(key)) << key;
    }
  }
  std::filesystem::remove_all(out);
}

TEST(WaypointCli, BadScenarioExitsWithCode2) {
  const auto dir = test::fresh_dir("waypoint_bad");
  {
    std::ofstream f(dir / "bad.toml");
    f << doc_with("duration = 6000.0", "duration = 100.0");
  }
  const test::CliResult r = test::run_cli("run '" + (dir / "bad.toml").string() + "' --out '" +
                                          (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unreachable"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}
#endif

// Issue 13: `check` refuses what the craft cannot fly, with the reason and the number.
TEST(WaypointScenario, RejectsMissionsTheCraftCannotFly) {
  // κ_p so small that the RCT stop firing 2.5 m from the waypoint: δ_p = 0.2 m is out of reach.
  expect_input_error(example_with("waypoint_fine.toml", {{"kappa_p = 0.02", "kappa_p = 0.001"}}),
                     "fine_position.kappa_p: position_accuracy 0.2 m is unreachable: the RCT (0.005 m/s^2) "
                     "stop firing within 2.5 m of the waypoint");
  // Wheels too weak to flip: a half turn at 2e-4 N m takes 2√(π·20/2e-4) = 1121 s per leg.
  expect_input_error(example_with("waypoint_fine.toml", {{"max_wheel_torque = 5.0", "max_wheel_torque = 0.0002"}}),
                     "plus 3363 s of flips at max_wheel_torque 0.0002 N m");
  // The paper profile keeps the paper's defaults: the same file without the keys it sets.
  const sim::WaypointScenario paper = scenario::parse_waypoint(scenario::parse_document(
      example_with("waypoint_paper.toml", {{"pointing_tolerance = 1e-6", ""}, {"braking_margin = 0.95", ""}}),
      "paper.toml"));
  EXPECT_EQ(paper.mission.pointing_tolerance, 1e-6);
  EXPECT_EQ(paper.mission.braking_margin, 1.0);  // (16) as printed
  EXPECT_FALSE(paper.mission.pointing_thrust_axis);
  EXPECT_EQ(paper.mission.flip_timing, guidance::FlipTiming::immediate);
}

}  // namespace
}  // namespace attiguard::sim
