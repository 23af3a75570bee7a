// Scenario kind `mission` (docs/mission.md): waypoint guidance through the PET-ERG. Acceptance of
// the kind: the constrained example completes every waypoint with min pointing margin >= 0 and
// ||tau|| <= tau_max at every sample, while its unconstrained twin violates the cone.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

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

#endif
