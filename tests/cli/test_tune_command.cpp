// cli/tune_command: `attiguard tune` writes tune.json and best.toml, whose run reproduces the
// best point; a search without a converged point exits 4 (docs/pet-erg.md, section "Tuning").
#ifdef ATTIGUARD_CLI_PATH
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/core/four_digits.hpp"

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
  EXPECT_NE(r.out.find("\noutcome: found ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" points admissible); "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; best " + four_digits(j["convergence_time"].get<double>()) + " s = "),
            std::string::npos)
      << r.out;
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
  const auto batch = test::run_cli("tune examples/pet_erg_slew170.toml --batch 0" + out);
  EXPECT_EQ(batch.exit_code, 2);
  EXPECT_NE(batch.err.find("--batch: must be at least 1"), std::string::npos) << batch.err;
  const auto kind = test::run_cli("tune examples/rigid_body_pd.toml" + out);
  EXPECT_EQ(kind.exit_code, 2);
  EXPECT_NE(kind.err.find("pet_erg"), std::string::npos) << kind.err;
  fs::remove_all(dir);
}


/// examples/pet_erg_slew170.toml with `tune` appended, written into `dir`.
fs::path slew_with(const fs::path& dir, const std::string& tune) {
  const fs::path path = dir / "slew.toml";
  std::ofstream(path) << test::read_file(fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_slew170.toml") << '\n'
                      << tune;
  return path;
}

// The [tune] table gives budget, seed, ranges and plot; flags given override its keys.
TEST(TuneCli, TuneTableGivesTheSettingsAndFlagsOverrideThem) {
  const fs::path dir = test::fresh_dir("tune_table");
  const fs::path file = slew_with(dir, "[tune]\nbudget = 6\nseed = 3\nbatch = 2\nplot = false\n[tune.ranges]\n"
                                       "\"control.kp\" = [1.0, 5.0]\n\"control.kd\" = [5.0, 20.0]\n");
  const auto r = test::run_cli("tune '" + file.string() + "' --out '" + (dir / "table").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = read_json(dir / "table" / "tune.json");
  EXPECT_EQ(j["evaluated"], 6);
  EXPECT_EQ(j["seed"], 3);
  EXPECT_EQ(j["batch"], 2);
  ASSERT_EQ(j["parameters"].size(), 2u);
  EXPECT_EQ(j["parameters"][0]["key"], "control.kd");  // in key order
  EXPECT_EQ(j["parameters"][0]["max"], 20.0);
  EXPECT_EQ(j["parameters"][1]["key"], "control.kp");
  EXPECT_EQ(j["parameters"][1]["min"], 1.0);
  EXPECT_FALSE(fs::exists(dir / "table" / "tune_tradeoff.png"));  // plot = false
  const auto o = test::run_cli("tune '" + file.string() + "' --budget 8 --seed 4 --batch 3 --range erg.kappa=1:10 --no-plot --out '" +
                               (dir / "flags").string() + "'");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const nlohmann::json k = read_json(dir / "flags" / "tune.json");
  EXPECT_EQ(k["evaluated"], 8);
  EXPECT_EQ(k["seed"], 4);
  EXPECT_EQ(k["batch"], 3);
  ASSERT_EQ(k["parameters"].size(), 1u);
  EXPECT_EQ(k["parameters"][0]["key"], "erg.kappa");
  // best.toml keeps the [tune] table: `attiguard run` and `check` ignore it.
  EXPECT_EQ(test::run_cli("check '" + (dir / "flags" / "best.toml").string() + "'").exit_code, 0);
  fs::remove_all(dir);
}

TEST(TuneCli, BadTuneTableIsInvalidInputNamingTheKey) {
  const fs::path dir = test::fresh_dir("tune_table_bad");
  const fs::path file = slew_with(dir, "[tune]\nbudget = 2\n");
  const auto r = test::run_cli("tune '" + file.string() + "' --no-plot --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("slew.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": tune.budget: must be in [4, "), std::string::npos) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  // `attiguard check` ignores the table (it is tune's).
  EXPECT_EQ(test::run_cli("check '" + file.string() + "'").exit_code, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard
#endif
