// `attiguard check` and `run` on a scenario with no governor or gain key (docs/pet-erg.md,
// section 8): check prints every value as derived or given with its scales, summary.json records
// them under `derived_defaults`, the outcome line gives the ratio to the eigenaxis bang-bang time.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace attiguard::test::defaults_cli {
namespace {

TEST(DefaultsCli, CheckPrintsTheDerivedValuesAndTheirScales) {
  const CliResult r = run_cli("check tests/data/defaults/cubesat_3u.toml");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("control.kp = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(derived)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(given)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("erg.kappa = "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("time sqrt(J_max theta/tau)"), std::string::npos) << r.out;
  // the paper scenario gives every value
  const CliResult paper = run_cli("check examples/pet_erg_paper.toml");
  ASSERT_EQ(paper.exit_code, 0) << paper.err;
  EXPECT_NE(paper.out.find("control.kp = 5 (given)"), std::string::npos) << paper.out;
  EXPECT_NE(paper.out.find("erg.kappa = 1 (given)"), std::string::npos) << paper.out;
}

TEST(DefaultsCli, SummaryRecordsTheDerivedValuesAndTheOutcomeLineTheRatio) {
  const auto dir = fresh_dir("defaults_run");
  const CliResult r = run_cli("run tests/data/defaults/station_wheels.toml --out '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("outcome: converged", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("x the eigenaxis bang-bang time"), std::string::npos) << r.out;
  const nlohmann::json s = nlohmann::json::parse(read_file(dir / "summary.json"));
  ASSERT_TRUE(s.contains("derived_defaults"));
  const nlohmann::json& d = s["derived_defaults"];
  EXPECT_EQ(d["derived"], nlohmann::json({"kp", "kd", "kappa", "sampling_period", "c_gamma", "epsilon", "step"}));
  const double kp = 8.0 * d["torque_scale"].get<double>() /
                    (d["reference_angle_deg"].get<double>() * 3.141592653589793 / 180.0);
  EXPECT_NEAR(s["kp"].get<double>(), kp, 1e-12 * kp);
  EXPECT_GT(d["time_scale"].get<double>(), 0.0);
  EXPECT_LE(s["convergence_time_over_bang_bang"].get<double>(), 10.0);
  // the sampling period is a whole number of the 1 s control period
  EXPECT_DOUBLE_EQ(s["sampling_period"].get<double>(), std::round(s["sampling_period"].get<double>()));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::test::defaults_cli
