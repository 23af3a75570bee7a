// cli/campaign_command and cli/tune_command: the flags are bounded and a resume reads runs.csv
// strictly; no thread failure ends in an abort (docs/errors.md, "No abort", "Strict readers").
#ifdef ATTIGUARD_CLI_PATH
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "attiguard/parallel/thread_limit.hpp"
#include "cli_runner.hpp"
#include "sanitizer_build.hpp"


namespace attiguard {
namespace {

namespace fs = std::filesystem;

const std::string kCampaign = "examples/pet_erg_campaign.toml";
const std::string kTune = "examples/pet_erg_slew170.toml";

/// One error line starting "attiguard: error: " and containing every one of `parts`.
void expect_one_line(const test::CliResult& r, const std::vector<std::string>& parts) {
  EXPECT_EQ(r.err.rfind("attiguard: error: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  for (const std::string& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << p << " in " << r.err;
}

TEST(CampaignCommand, ThreadsBeyondTheLimitAreRefusedNamingTheFlagAndTheLimit) {
  const fs::path dir = test::fresh_dir("cmd_threads");
  const std::string limit = std::to_string(parallel::thread_limit());
  const std::string more = std::to_string(parallel::thread_limit() + 1);
  for (const std::string& cmd : {"campaign " + kCampaign + " --runs 2", "tune " + kTune + " --budget 4 --no-plot"}) {
    const auto r = test::run_cli(cmd + " --threads " + more + " --out '" + dir.string() + "'");
    EXPECT_EQ(r.exit_code, 2) << cmd;
    expect_one_line(r, {"--threads: " + more + " is more than the limit " + limit, "use --threads " + limit});
    const auto big = test::run_cli(cmd + " --threads 200 --out '" + dir.string() + "'");
    EXPECT_EQ(big.exit_code, 2) << cmd << big.err;  // was SIGABRT when 200 threads could not start
  }
  fs::remove_all(dir);
}

TEST(CampaignCommand, ThreadsTheSystemRefusesEndWithExitTwoNamingTheFlag) {
#ifdef ATTIGUARD_TEST_ASAN
  GTEST_SKIP() << "ASan reserves its shadow memory: an address-space limit is not a thread limit";
#else
  // 1 GB thread stacks (ulimit -s) in a 3 GB address space (ulimit -v): a thread soon fails.
  const fs::path dir = test::fresh_dir("cmd_thread_start");
  for (const std::string& cmd : {"campaign " + kCampaign + " --runs 8", "tune " + kTune + " --budget 8 --no-plot"}) {
    const auto r = test::run_cli("--version >/dev/null; (ulimit -s 1000000 && ulimit -v 3000000 && exec '" +
                                 std::string(ATTIGUARD_CLI_PATH) + "' " + cmd + " --threads 8 --out '" +
                                 dir.string() + "')");
    EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
    expect_one_line(r, {"--threads: cannot start worker thread ", "use --threads "});
  }
  fs::remove_all(dir);
#endif
}

TEST(CampaignCommand, TuneBudgetBeyondTheLimitNamesTheFlagOrTheKey) {
  const fs::path dir = test::fresh_dir("cmd_budget");
  const auto flag = test::run_cli("tune " + kTune + " --budget 1000000 --out '" + dir.string() + "'");
  EXPECT_EQ(flag.exit_code, 2);
  expect_one_line(flag, {"--budget: 1000000 runs are more than the limit 100000"});
  std::stringstream text;
  text << std::ifstream(fs::path(ATTIGUARD_SOURCE_DIR) / kTune).rdbuf() << "\n[tune]\nbudget = 1000000000\n";
  std::ofstream(dir / "s.toml") << text.str();
  const auto key = test::run_cli("tune '" + (dir / "s.toml").string() + "' --out '" + (dir / "o").string() + "'");
  EXPECT_EQ(key.exit_code, 2);
  expect_one_line(key, {"s.toml:", "tune.budget: 1000000000 runs are more than the limit 100000"});
  fs::remove_all(dir);
}

TEST(CampaignCommand, ResumeRefusesARowThatDoesNotParseWithItsLine) {
  const fs::path dir = test::fresh_dir("cmd_resume");
  const std::string out = " --out '" + dir.string() + "'";
  ASSERT_EQ(test::run_cli("campaign " + kCampaign + " --runs 3" + out).exit_code, 0);
  const std::string good = test::read_file(dir / "runs.csv");
  std::vector<std::string> lines;
  std::stringstream in(good);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 4u);
  const auto with_line3 = [&](const std::string& row) {
    std::ofstream f(dir / "runs.csv", std::ios::binary | std::ios::trunc);
    for (std::size_t i = 0; i < lines.size(); ++i) f << (i == 2 ? row : lines[i]) << '\n';
  };
  const std::string last_field_cut = lines[2].substr(0, lines[2].rfind(','));
  for (const auto& [row, what] : std::vector<std::pair<std::string, std::string>>{
           {last_field_cut + ",nan", "is not a finite number"},
           {last_field_cut + ",abc", "'abc' is not a number"},
           {lines[2] + ",1", "fields, the header has"}}) {
    with_line3(row);
    const auto r = test::run_cli("campaign " + kCampaign + " --runs 5 --resume" + out);
    EXPECT_EQ(r.exit_code, 2) << row;
    expect_one_line(r, {"runs.csv:3: ", what});
  }
  fs::remove_all(dir);
}

TEST(CampaignCommand, RetainIntervalBelowTheRowSpacingIsRefusedAtItsKey) {
  const fs::path dir = test::fresh_dir("cmd_retain");
  std::stringstream text;
  text << std::ifstream(fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_campaign_retained.toml").rdbuf();
  std::string s = text.str();
  const std::size_t at = s.find("retain_interval = 0.5");
  ASSERT_NE(at, std::string::npos);
  s.replace(at, 21, "retain_interval = 0.2");
  std::ofstream(dir / "s.toml") << s;
  const auto r = test::run_cli("campaign '" + (dir / "s.toml").string() + "' --runs 2 --out '" +
                               (dir / "o").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_line(r, {"s.toml:", "campaign.retain_interval: no trajectory row at the retained time t = 0.2 s"});
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard
#endif
