// The prediction of kind `mission` (docs/mission.md, "Prediction"; issue 42, item 3): the legs as
// the waypoint kind predicts them, the turns flown at the pace of the mission's own attitude loop
// (the governed slew), `check` printing it and summary.json giving actual / predicted per leg;
// the guidance's flip lead time derived from the governed flip when the file leaves it out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/io/row_sink.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_mission.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/mission_kind_prediction.hpp"
#include "attiguard/sim/mission_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"
#include "cli_runner.hpp"

namespace attiguard::sim::mission_prediction_test {
namespace {

MissionScenario example(const std::string& name) {
  return scenario::parse_mission(
      scenario::load_document(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples" / (name + ".toml")));
}

// Acceptance of issue 42: the mission examples predict their time within 20 %, and every leg
// within 1.5 (the waypoint kind's p95 bound).
TEST(MissionKindPrediction, TheMissionExamplesPredictTheirTimeWithinTwentyPercent) {
  for (const char* name : {"mission_sun_constrained", "mission_500kg_sun", "mission_sun_constrained_planned"}) {
    const MissionScenario sc = example(name);
    io::NullRowSink rows;
    const nlohmann::json s = mission_summary(sc, record_mission(sc, rows));
    ASSERT_TRUE(s.at("completed").get<bool>()) << name;
    const double ratio = s.at("time_over_predicted").get<double>();
    EXPECT_GE(ratio, 0.8) << name;
    EXPECT_LE(ratio, 1.2) << name;
    EXPECT_TRUE(s.at("prediction").at("turns_converged").get<bool>()) << name;
    for (const nlohmann::json& w : s.at("waypoints")) {
      const double leg = w.at("time_over_predicted").get<double>();
      EXPECT_GE(leg, 1.0 / 1.5) << name;
      EXPECT_LE(leg, 1.5) << name;
    }
    std::printf("[ figures  ] %s: %.1f s flown, %.1f s predicted, ratio %.3f\n", name,
                s.at("total_time").get<double>(), s.at("predicted_time").get<double>(), ratio);
  }
}

// The turns are the mission's own loop: the governed PET-ERG turn is slower than the waypoint
// kind's PID model on the 500 kg example (its [attitude_control] PID is not flown by kind mission),
// and the planned mode's turn is near its eigenaxis bang-bang time.
TEST(MissionKindPrediction, TurnsAreFlownByTheMissionsOwnAttitudeLoop) {
  const MissionScenario sc = example("mission_500kg_sun");
  const guidance::MissionPrediction pid = predict_waypoint_mission(sc.waypoint);
  const MissionKindPrediction governed = predict_mission_kind(sc, governor::GovernorMode::pet);
  ASSERT_EQ(pid.legs.size(), governed.prediction.legs.size());
  EXPECT_GT(governed.prediction.legs[0].turn_time, pid.legs[0].turn_time);
  const lie::Mat3 R0 = lie::Mat3::Identity();
  const lie::Mat3 R1 = lie::exp(lie::Vec3(0.0, 0.0, 0.5 * std::numbers::pi));
  const PredictedTurn pet = predicted_governed_turn(sc, governor::GovernorMode::pet, R0, R1);
  const PredictedTurn none = predicted_governed_turn(sc, governor::GovernorMode::none, R0, R1);
  EXPECT_TRUE(pet.converged && none.converged);
  EXPECT_GT(pet.time, none.time);  // the governor's DSM slows the reference
  // within the pointing tolerance already: no turn
  const double tol = sc.waypoint.mission.pointing_tolerance;
  EXPECT_EQ(predicted_governed_turn(sc, governor::GovernorMode::pet, R0, lie::exp(lie::Vec3(0.5 * tol, 0.0, 0.0))).time,
            0.0);
}

// The guidance's flip lead time comes from the governed flip when the file leaves it out, and a
// given one is kept.
TEST(MissionKindPrediction, TheFlipLeadTimeIsTheGovernedFlipsUnlessGiven) {
  const MissionScenario sc = example("mission_500kg_sun");
  const MissionKindPrediction kp = predict_mission_kind(sc, sc.params.mode);
  const lie::Mat3 R_acc = lie::exp(lie::Vec3(0.0, 0.0, 0.5 * std::numbers::pi));  // x_b along +y: the first leg
  lie::Mat3 R_dec = R_acc;
  R_dec.col(0) = -R_acc.col(0);
  R_dec.col(1) = -R_acc.col(1);
  const PredictedTurn flip = predicted_governed_turn(sc, sc.params.mode, R_acc, R_dec);
  ASSERT_TRUE(flip.converged && kp.all_turns_converged);
  EXPECT_GE(sc.waypoint.mission.flip_lead_time, 1.5 * flip.time - 1e-9);
  EXPECT_GT(sc.waypoint.mission.flip_lead_time, 100.0);

  std::string text = test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples/mission_500kg_sun.toml");
  text.replace(text.find("[guidance]\n"), 11, "[guidance]\nflip_lead_time = 42.0\n");
  const MissionScenario given = scenario::parse_mission(scenario::parse_document(text, "given.toml"));
  EXPECT_EQ(given.waypoint.mission.flip_lead_time, 42.0);
}

TEST(MissionKindPrediction, CheckPrintsTheLegsAndTheMission) {
  const test::CliResult r = test::run_cli("check examples/mission_sun_constrained.toml");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("predicted leg 0: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("predicted leg 1: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("predicted mission (governor pet): "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("warning"), std::string::npos) << r.out;
}

// A governor so slow (κ = 10⁻⁴) that a turn cannot finish within the duration: check warns that
// the mission would stall in a turn.
TEST(MissionKindPrediction, CheckWarnsWhenATurnCannotFinishWithinTheDuration) {
  std::string text =
      test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples/mission_500kg_sun.toml");
  const std::size_t at = text.find("kappa = 1.0");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 11, "kappa = 1e-4");
  const MissionScenario sc = scenario::parse_mission(scenario::parse_document(text, "short.toml"));
  const std::string report = mission_prediction_report(sc);
  EXPECT_NE(report.find("warning: a governed turn does not reach the pointing tolerance"), std::string::npos)
      << report;
}

}  // namespace
}  // namespace attiguard::sim::mission_prediction_test
