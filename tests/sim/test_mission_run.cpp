// Scenario kind `mission` (docs/mission.md): waypoint guidance through the PET-ERG. Acceptance of
// the kind: the constrained example completes every waypoint with min pointing margin >= 0 and
// ||tau|| <= tau_max at every sample, while its unconstrained twin violates the cone.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_mission.hpp"
#include "attiguard/sim/mission_run.hpp"
#include "cli_runner.hpp"

namespace {

attiguard::sim::MissionScenario load_mission_example() {
  return attiguard::scenario::parse_mission(attiguard::scenario::load_document(
      std::string(ATTIGUARD_SOURCE_DIR) + "/examples/mission_sun_constrained.toml"));
}

}  // namespace

// Issue 49: a set stop flag (the interruption flag of a run that writes files) ends a flight at
// its first control step with io::Interrupted, which is not recorded as the flight's numerical
// failure (the twin was then flown to its end, 15-30 s after SIGTERM); record_mission passes it
// to both flights; unset, the flights are as without it.
TEST(MissionRun, ASetStopFlagEndsEitherFlightWithInterruptedNotAFailure) {
  using namespace attiguard;
  const sim::MissionScenario sc = load_mission_example();
  std::atomic<bool> stop{true};
  EXPECT_THROW((void)sim::simulate_mission(sc, governor::GovernorMode::none, {}, &stop), io::Interrupted);
  io::NullRowSink rows;
  EXPECT_THROW((void)sim::record_mission(sc, rows, &stop), io::Interrupted);
  stop = false;
  const sim::MissionResult flown = sim::simulate_mission(sc, governor::GovernorMode::pet, {}, &stop);
  EXPECT_TRUE(flown.failure.empty()) << flown.failure;
  EXPECT_TRUE(flown.flight.completed);
}

// Issue 13: the cost of the constraints is reported only when both flights completed (it was
// −3.17 m/s for an incomplete constrained flight), and a numerical failure of one flight keeps
// the other's results, with the failure named.
TEST(MissionRun, CostsOnlyWhenBothFlightsCompletedAndAFailedTwinKeepsTheOwnResults) {
  using namespace attiguard;
  const sim::MissionScenario sc = load_mission_example();
  sim::MissionFlights f;
  f.own = sim::simulate_mission(sc, governor::GovernorMode::pet);
  f.twin = sim::simulate_mission(sc, governor::GovernorMode::none);
  ASSERT_TRUE(f.own.flight.completed && f.twin.flight.completed);
  const nlohmann::json ok = sim::mission_summary(sc, f);
  EXPECT_EQ(ok["outcome"], "completed");
  EXPECT_TRUE(ok["time_cost"].is_number());
  EXPECT_FALSE(ok.contains("outcome_reason"));

  // The unconstrained twin cut short: incomplete, with a reason; no cost.
  sim::MissionScenario short_sc = sc;
  short_sc.waypoint.duration = 200.0;
  sim::MissionFlights partial = f;
  partial.twin = sim::simulate_mission(short_sc, governor::GovernorMode::none);
  ASSERT_FALSE(partial.twin.flight.completed);
  const nlohmann::json inc = sim::mission_summary(sc, partial);
  EXPECT_EQ(inc["outcome"], "completed");
  EXPECT_EQ(inc["unconstrained"]["outcome"], "incomplete");
  EXPECT_NE(inc["unconstrained"]["outcome_reason"].get<std::string>().find("time out at 200.0 s"),
            std::string::npos)
      << inc["unconstrained"]["outcome_reason"];
  EXPECT_TRUE(inc["time_cost"].is_null());
  EXPECT_TRUE(inc["delta_v_cost"].is_null());

  // The twin failed numerically: the own flight's figures are all there, the failure named.
  sim::MissionFlights failed = f;
  failed.twin = sim::MissionResult{};
  failed.twin.flight.finite = false;
  failed.twin.failure = "integrator: non-finite state at t = 1.5 s (divergence)";
  const nlohmann::json fj = sim::mission_summary(sc, failed);
  EXPECT_EQ(fj["outcome"], "completed");
  EXPECT_EQ(fj["constrained"]["waypoints_reached"].get<long>(), 2);
  EXPECT_EQ(fj["unconstrained"]["outcome"], "incomplete");
  EXPECT_NE(fj["unconstrained"]["outcome_reason"].get<std::string>().find("numerical failure: integrator"),
            std::string::npos);
  EXPECT_NE(fj["twin_failure"].get<std::string>().find("divergence"), std::string::npos);
  EXPECT_TRUE(fj["time_cost"].is_null());
}

// Issue 13: a 500 kg craft (inertia about 100 kg m^2, 22 N engine, 0.5 N m wheels), a Sun
// keep-out cone and three waypoints complete with the governor on; the unconstrained twin
// violates the cone. No [attitude_control] (unused by kind mission) and every guidance key
// derived from the craft.
TEST(MissionRun, FiveHundredKilogramCraftCompletesGovernedAndItsTwinViolatesTheCone) {
  using namespace attiguard;
  const sim::MissionScenario sc = scenario::parse_mission(scenario::load_document(
      std::string(ATTIGUARD_SOURCE_DIR) + "/examples/mission_500kg_sun.toml"));
  EXPECT_EQ(sc.waypoint.profile, sim::GuidanceProfile::craft);
  const sim::MissionResult con = sim::simulate_mission(sc, governor::GovernorMode::pet);
  const sim::MissionResult unc = sim::simulate_mission(sc, governor::GovernorMode::none);
  const sim::WaypointOutcome out = sim::mission_outcome(sc, con);
  EXPECT_TRUE(out.completed) << out.reason;
  for (const sim::WaypointResult& w : con.flight.waypoints) {
    EXPECT_TRUE(w.reached);
    EXPECT_LT(w.final_position_error, sc.waypoint.mission.position_accuracy);
  }
  EXPECT_GE(con.min_pointing_margin, 0.0);
  EXPECT_EQ(con.torque_violations, 0);
  EXPECT_LT(unc.min_pointing_margin, 0.0);
  EXPECT_TRUE(unc.flight.completed);
  std::printf("[ measured ] 500 kg mission: governed %.1f s, %.4f m/s, margin %+.4f; twin %.1f s, "
              "margin %+.4f (violation from t = %.1f s)\n",
              con.flight.total_time, con.delta_v(), con.min_pointing_margin, unc.flight.total_time,
              unc.min_pointing_margin, unc.first_pointing_violation_time);
}

// Issue 13: a leg whose steady desired attitude lies in a cone's repulsive band is rejected
// before flying (kind pet_erg rejects such an R_d): here the star tracker (+y_b) ends the first
// align slew pointing along -x, where the Sun is.
TEST(MissionRun, DesiredAttitudeInARepulsiveBandIsRejectedBeforeFlying) {
  using namespace attiguard;
  std::string text = attiguard::test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) /
                                                "examples/mission_500kg_sun.toml");
  const std::string from = "direction_i = [-1.0, 1.0, 0.3]";
  text.replace(text.find(from), from.size(), "direction_i = [-1.0, 0.1, 0.0]");
  try {
    (void)scenario::parse_mission(scenario::parse_document(text, "sun_on_leg.toml"));
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("waypoints[0].position: the desired attitude of leg 0 (x_b towards the "
                        "waypoint) lies inside cones[0]"),
              std::string::npos)
        << what;
  }
}

#ifdef ATTIGUARD_CLI_PATH

TEST(MissionRun, SunConstrainedExampleKeepsConeAndTorqueTwinViolatesCone) {
  const auto out = attiguard::test::fresh_dir("mission_sun_out");
  const auto r = attiguard::test::run_cli("run examples/mission_sun_constrained.toml --out '" +
                                          out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "summary.json"));
  const double tau_max = j["tau_max"].get<double>();
  const auto& con = j["constrained"];
  EXPECT_EQ(con["governor"], "pet");
  EXPECT_TRUE(con["completed"].get<bool>());
  EXPECT_EQ(con["waypoints_reached"].get<long>(), 2);
  EXPECT_GE(con["min_pointing_margin"].get<double>(), 0.0);
  EXPECT_LE(con["max_torque_norm"].get<double>(), tau_max * (1.0 + 1e-9));
  EXPECT_EQ(con["torque_violations"].get<long>(), 0);
  const auto& unc = j["unconstrained"];
  EXPECT_EQ(unc["governor"], "none");
  EXPECT_LT(unc["min_pointing_margin"].get<double>(), 0.0);
  EXPECT_FALSE(unc["pointing_constraints_satisfied"].get<bool>());
  EXPECT_FALSE(unc["constraints_satisfied"].get<bool>());
  // Top level = the constrained flight; `*_satisfied` names, as campaigns count violations by them.
  EXPECT_TRUE(j["pointing_constraints_satisfied"].get<bool>());
  EXPECT_TRUE(j["torque_limit_satisfied"].get<bool>());
  EXPECT_TRUE(j["constraints_satisfied"].get<bool>());
  for (const char* key : {"min_pointing_margin", "max_torque_norm", "waypoints", "time_cost",
                          "delta_v_cost", "wall_time_s"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  ASSERT_EQ(j["waypoints"].size(), 2u);
  for (const auto& w : j["waypoints"]) EXPECT_TRUE(w["reached"].get<bool>());
  // Every logged sample of the constrained flight: margin >= 0 and ||tau|| <= tau_max.
  std::istringstream csv(attiguard::test::read_file(out / "trajectory.csv"));
  std::string line;
  std::getline(csv, line);
  long rows = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 31u);
    EXPECT_GE(v[30], 0.0) << "t = " << v[0];
    EXPECT_LE(v[17], tau_max * (1.0 + 1e-9)) << "t = " << v[0];
    ++rows;
  }
  EXPECT_GT(rows, 100);
  std::filesystem::remove_all(out);
}

TEST(MissionRun, UnknownGovernorKeyIsInvalidInput) {
  const auto dir = attiguard::test::fresh_dir("mission_bad");
  std::string text = attiguard::test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) /
                                                "examples/mission_sun_constrained.toml");
  text.replace(text.find("tau_max = 5.0"), 13, "tau_maxx = 5.0");
  std::ofstream(dir / "bad.toml") << text;
  const auto r = attiguard::test::run_cli("check '" + (dir / "bad.toml").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("tau_maxx"), std::string::npos) << r.err;
}

// Issue 27: the messages of the waypoint part of a mission carry FILE:LINE:COL like the
// governor's (the waypoint part was read from a copy of the document, which has no positions).
TEST(MissionRun, ErrorsOfTheWaypointPartAndOfTheGovernorAreLocated) {
  const std::string text = attiguard::test::read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) /
                                                      "examples/mission_sun_constrained.toml");
  const auto located_error = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto pos = t.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    t.replace(pos, from.size(), to);
    try {
      (void)attiguard::scenario::parse_mission(attiguard::scenario::parse_document(t, "m.toml"));
    } catch (const attiguard::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(located_error("mass = 100.0", "mass = -1.0").rfind("m.toml:16:8: spacecraft.mass:", 0), 0u)
      << located_error("mass = 100.0", "mass = -1.0");
  EXPECT_EQ(located_error("[guidance]", "[guidance]\nbogus = 1").rfind("m.toml:44:1: guidance.bogus:", 0), 0u)
      << located_error("[guidance]", "[guidance]\nbogus = 1");
  EXPECT_EQ(located_error("kappa = 1.0", "kappa = -1.0").rfind("m.toml:64:9: erg.kappa:", 0), 0u)
      << located_error("kappa = 1.0", "kappa = -1.0");
}

#endif
