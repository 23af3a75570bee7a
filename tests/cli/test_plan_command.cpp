// `attiguard plan` (docs/slew-planner.md, "Outputs", "Failures"): the files, the outcome line,
// exit 4 with the reason when no path is admissible, refusals located at their keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace attiguard::test::plan_command_test {
namespace {

namespace fs = std::filesystem;

/// A 3U CubeSat slewing 120 deg about body/inertial y, with `cones` appended (TOML text).
std::string cubesat_scenario(const std::string& cones, const std::string& extra = "") {
  return R"(kind = "pet_erg"
name = "plan_cli_cubesat"
[body]
inertia = [[0.042, 0.001, 0.0], [0.001, 0.042, 0.0], [0.0, 0.0, 0.007]]
[desired]
attitude = { axis = [0.0, 1.0, 0.0], angle_deg = 120.0 }
[control]
tau_max = 0.001
[simulation]
duration = 600.0
)" + extra + cones;
}

fs::path write_scenario(const fs::path& dir, const std::string& text) {
  const fs::path path = dir / "scenario.toml";
  std::ofstream(path) << text;
  return path;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(PlanCommand, PlansTheSlew170ExampleNearTheBangBangTime) {
  const fs::path out = fresh_dir("plan_slew170");
  const CliResult r = run_cli("plan examples/pet_erg_slew170.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("outcome: planned (", 0), 0u) << r.out;
  const nlohmann::json j = read_json(out / "plan.json");
  EXPECT_EQ(j["kind"], "plan");
  EXPECT_LE(j["ratio_to_bang_bang"].get<double>(), 1.05);
  EXPECT_GE(j["smallest_cone_margin_deg"].get<double>(), 0.0);
  EXPECT_LE(j["largest_torque_ratio"].get<double>(), 1.0);
  EXPECT_EQ(j["solver"]["name"], "ipopt");
  // plan.csv: trajectory.csv's column names, a margin per cone, ending at t = duration.
  const std::string csv = read_file(out / "plan.csv");
  EXPECT_EQ(csv.rfind("t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z,tau_x,tau_y,tau_z,tau_norm,"
                      "margin_0,margin_1,margin_2\n", 0),
            0u);
  EXPECT_GT(count_lines(csv), 100);
  // The cones as summary.json writes them: what `view` draws.
  ASSERT_EQ(j["cones"].size(), 3u);
  EXPECT_EQ(j["cones"][0]["axis_b"].size(), 3u);
  EXPECT_TRUE(j["cones"][0]["theta_c_deg"].is_number());
  fs::remove_all(out);
}

TEST(PlanCommand, ViewDrawsThePlanWithItsCones) {
  const fs::path out = fresh_dir("plan_view");
  const CliResult r =
      run_cli("plan examples/pet_erg_slew170.toml --view --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find((out / "view.html").string()), std::string::npos) << r.out;
  const std::string html = read_file(out / "view.html");
  EXPECT_NE(html.find("\"kind\":\"plan\""), std::string::npos);
  EXPECT_NE(html.find("\"theta_c_deg\""), std::string::npos);
  EXPECT_NE(html.find("\"margin_2\""), std::string::npos);  // plan.csv is the page's trajectory
  // `attiguard view DIR` on the same folder writes the same page.
  fs::remove(out / "view.html");
  const CliResult v = run_cli("view '" + out.string() + "'");
  ASSERT_EQ(v.exit_code, 0) << v.err;
  EXPECT_EQ(read_file(out / "view.html"), html);
  fs::remove_all(out);
}

TEST(PlanCommand, ATargetInsideAKeepOutConeIsExit4WithTheReason) {
  const fs::path dir = fresh_dir("plan_target_in_cone");
  // The target attitude points body +z along R_d e_z = (sin 120°, 0, cos 120°).
  const fs::path scenario = write_scenario(dir, cubesat_scenario(R"([[cones]]
type = "keep_out"
axis_b = [0.0, 0.0, 1.0]
direction_i = [0.8660254, 0.0, -0.5]
half_angle_deg = 10.0
)"));
  const CliResult r = run_cli("plan '" + scenario.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no admissible path: the target attitude does not keep cones[0]"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.rfind("outcome: no_admissible_path", 0), 0u) << r.out;
  const nlohmann::json j = read_json(dir / "out" / "plan.json");
  EXPECT_EQ(j["outcome"], "no_admissible_path");
  EXPECT_FALSE(fs::exists(dir / "out" / "plan.csv"));
  fs::remove_all(dir);
}

TEST(PlanCommand, AKeepInConeThatExcludesTheTargetIsExit4) {
  const fs::path dir = fresh_dir("plan_keep_in");
  const fs::path scenario = write_scenario(dir, cubesat_scenario(R"([[cones]]
type = "keep_in"
axis_b = [0.0, 0.0, 1.0]
direction_i = [0.0, 0.0, 1.0]
half_angle_deg = 60.0
)"));
  const CliResult r = run_cli("plan '" + scenario.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("target attitude does not keep cones[0]"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(PlanCommand, ConesThatCloseEveryWayAreExit4WithTheReason) {
  const fs::path dir = fresh_dir("plan_closed_ring");
  // Twelve 12-deg keep-out cones on body +z in a ring 30 deg around inertial +z, where body +z
  // starts: start and target keep them, no path leaves the ring.
  std::string cones;
  for (int k = 0; k < 12; ++k) {
    const double a = 30.0 * k * std::numbers::pi / 180.0;
    cones += "[[cones]]\ntype = \"keep_out\"\naxis_b = [0.0, 0.0, 1.0]\ndirection_i = [" +
             std::to_string(0.5 * std::cos(a)) + ", " + std::to_string(0.5 * std::sin(a)) +
             ", 0.8660254]\nhalf_angle_deg = 12.0\n";
  }
  const fs::path scenario = write_scenario(dir, cubesat_scenario(cones));
  const CliResult r = run_cli("plan '" + scenario.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no admissible path: the cones close every way"), std::string::npos) << r.err;
  EXPECT_EQ(read_json(dir / "out" / "plan.json")["outcome"], "no_admissible_path");
  EXPECT_FALSE(fs::exists(dir / "out" / "plan.csv"));
  // Nothing to view: said so, at plan.csv.
  const CliResult v = run_cli("view '" + (dir / "out").string() + "'");
  EXPECT_EQ(v.exit_code, 2) << v.err;
  EXPECT_NE(v.err.find("plan.csv: not found"), std::string::npos) << v.err;
  fs::remove_all(dir);
}

TEST(PlanCommand, AScenarioOfAnotherKindIsRefusedAtKind) {
  const CliResult r = run_cli("plan examples/conreach_paper.toml --out /tmp/attiguard_plan_kind_refused");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("kind"), std::string::npos) << r.err;
  fs::remove_all("/tmp/attiguard_plan_kind_refused");
}

TEST(PlanCommand, BadPlanValuesAndNonSlewsAreRefusedAtTheirKeys) {
  const fs::path dir = fresh_dir("plan_bad_values");
  const fs::path out = dir / "out";
  const fs::path headroom =
      write_scenario(dir, cubesat_scenario("", "[plan]\ntorque_headroom = 1.5\n"));
  CliResult r = run_cli("plan '" + headroom.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("plan.torque_headroom"), std::string::npos) << r.err;
  const fs::path typo = write_scenario(dir, cubesat_scenario("", "[plan]\ncone_margin = 2.0\n"));
  r = run_cli("plan '" + typo.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cone_margin"), std::string::npos) << r.err;
  const fs::path spinning = write_scenario(
      dir, cubesat_scenario("", "[initial]\nattitude = { axis = [1.0, 0.0, 0.0], angle = 0.0 }\n"
                                "omega_b = [0.0, 0.0, 0.001]\n"));
  r = run_cli("plan '" + spinning.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("initial.omega_b"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(PlanCommand, ACubeSatWithASunConeOnThePathPlansAroundIt) {
  const fs::path dir = fresh_dir("plan_cubesat_sun");
  // Body +z sweeps the x-z plane; the Sun sits on that sweep, 60 deg along.
  const fs::path scenario = write_scenario(dir, cubesat_scenario(R"([[cones]]
type = "keep_out"
axis_b = [0.0, 0.0, 1.0]
direction_i = [0.8660254, 0.0, 0.5]
half_angle_deg = 25.0
)", "[plan]\ncone_margin_deg = 2.0\n"));
  const CliResult r = run_cli("plan '" + scenario.string() + "' --out '" + (dir / "out").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = read_json(dir / "out" / "plan.json");
  EXPECT_GE(j["smallest_cone_margin_deg"].get<double>(), 2.0);
  EXPECT_GE(j["path_waypoints"].get<int>(), 1);
  EXPECT_LT(j["ratio_to_bang_bang"].get<double>(), 2.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::test::plan_command_test
