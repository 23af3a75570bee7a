// cli/tune_command: `attiguard tune` writes tune.json and best.toml, whose run reproduces the
// best point; a search without a converged point exits 4 (docs/pet-erg.md, section "Tuning").
#ifdef ATTIGUARD_CLI_PATH
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace attiguard {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& p) { return nlohmann::json::parse(test::read_file(p)); }

TEST(TuneCli, WritesTheBestGainsAndBestTomlRunsToTheSameConvergenceTime) {
  const fs::path dir = test::fresh_dir("tune_best");
  const auto r = test::run_cli("tune examples/pet_erg_slew170.toml --budget 12 --threads 2 --no-plot --out '" +
                               dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = read_json(dir / "tune.json");
  EXPECT_EQ(j["outcome"], "found");
  EXPECT_EQ(j["evaluated"], 12);
  ASSERT_TRUE(j["best"].is_object());
  EXPECT_NE(r.out.find("convergence_time: "), std::string::npos);
  // best.toml is a valid scenario whose run converges at the best point's time.
  const auto run = test::run_cli("run '" + (dir / "best.toml").string() + "' --out '" + (dir / "run").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json s = read_json(dir / "run" / "summary.json");
  EXPECT_EQ(s["outcome"], "converged");
  EXPECT_EQ(s["kp"].get<double>(), j["best"]["values"]["control.kp"].get<double>());
  EXPECT_DOUBLE_EQ(s["convergence_time"].get<double>(), j["convergence_time"].get<double>());
  EXPECT_DOUBLE_EQ(s["convergence_time_over_bang_bang"].get<double>(),
                   j["convergence_time_over_bang_bang"].get<double>());
  fs::remove_all(dir);
}

TEST(TuneCli, NoConvergedPointExitsFourAndSaysSo) {
  const fs::path dir = test::fresh_dir("tune_none");
  const auto r = test::run_cli(
      "tune tests/data/campaign/pet_erg_stalling.toml --budget 4 --no-plot --range control.kp=4:6 "
      "--range control.kd=0.8:1.2 --out '" + dir.string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("attiguard tune: none of the 4 evaluated points converged with every constraint kept"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_json(dir / "tune.json")["outcome"], "none_converged");
  EXPECT_FALSE(fs::exists(dir / "best.toml"));
  fs::remove_all(dir);
}

TEST(TuneCli, BadRangeBudgetOrKindIsInvalidInput) {
  const fs::path dir = test::fresh_dir("tune_bad");
  const std::string out = " --out '" + dir.string() + "'";
  const auto range = test::run_cli("tune examples/pet_erg_slew170.toml --range control.kp=3:2" + out);
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_NE(range.err.find("--range 'control.kp=3:2'"), std::string::npos) << range.err;
  EXPECT_EQ(test::run_cli("tune examples/pet_erg_slew170.toml --budget 2" + out).exit_code, 2);
  EXPECT_EQ(test::run_cli("tune examples/pet_erg_slew170.toml --threads 0" + out).exit_code, 2);
  const auto kind = test::run_cli("tune examples/rigid_body_pd.toml" + out);
  EXPECT_EQ(kind.exit_code, 2);
  EXPECT_NE(kind.err.find("pet_erg"), std::string::npos) << kind.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard
#endif
