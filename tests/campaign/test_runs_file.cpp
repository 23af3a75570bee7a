// campaign/runs_file: runs.csv read back strictly for --resume, --replay and view
// (docs/campaigns.md, "Interruption and resume"; docs/errors.md, "Strict readers").

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "attiguard/campaign/runs_file.hpp"
#include "attiguard/core/errors.hpp"
#include "cli_runner.hpp"

namespace attiguard::campaign {
namespace {

namespace fs = std::filesystem;

const std::string kHeader = "run,seed,attempts,status,reason,control.kp,outcome,violation,t_conv";
const std::string kRow0 = "0,123,1,ok,,5.5,converged,0,3.25";
const std::string kRow1 = "1,18446744073709551615,3,rejected,\"kp: must be > 0, got -1\",-1,,,";

fs::path runs_with(const std::string& name, const std::string& body) {
  const fs::path p = test::fresh_dir("runs_file_" + name) / "runs.csv";
  std::ofstream(p, std::ios::binary) << kHeader << '\n' << body;
  return p;
}

/// The message of read_runs on a runs.csv of `body`, "" when it is accepted.
std::string refusal(const std::string& name, const std::string& body) {
  try {
    (void)read_runs(runs_with(name, body), kHeader);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RunsFile, ReadsTheRowsAttiguardWritesAndDropsATornLastLine) {
  const auto rows = read_runs(runs_with("ok", kRow0 + "\n" + kRow1 + "\n2,77,1,ok,,4"), kHeader);
  ASSERT_EQ(rows.size(), 2u);  // the torn "2,77,…" (no newline) is an interrupted append
  EXPECT_EQ(rows.at(0), kRow0);
  EXPECT_EQ(rows.at(1), kRow1);
  const RunsTable t = read_runs_table(runs_with("table", kRow0 + "\n"));
  EXPECT_EQ(t.columns.size(), 9u);
  EXPECT_TRUE(read_runs_table(fs::path("/nonexistent/runs.csv")).rows.empty());
}

TEST(RunsFile, RefusesEveryRowAttiguardDoesNotWriteWithItsLineAndColumn) {
  const std::string ok = kRow0 + "\n";
  const auto expect = [&](const std::string& name, const std::string& row, const std::string& part) {
    const std::string m = refusal(name, ok + row + "\n");
    EXPECT_NE(m.find("runs.csv:3: "), std::string::npos) << name << ": " << m;
    EXPECT_NE(m.find(part), std::string::npos) << name << ": " << m;
  };
  expect("nan", "1,5,1,ok,,nan,converged,0,3", "column control.kp: 'nan' is not a finite number");
  expect("inf", "1,5,1,ok,,1,converged,0,-inf", "column t_conv: '-inf' is not a finite number");
  expect("abc", "1,5,1,ok,,abc,converged,0,3", "column control.kp: 'abc' is not a number");
  expect("extra", "1,5,1,ok,,1,converged,0,3,9", "10 fields, the header has 9");
  expect("short", "1,5,1,ok,,1,converged,0", "8 fields, the header has 9");
  expect("index", "-1,5,1,ok,,1,converged,0,3", "column run: '-1' is not a run index");
  expect("seed", "1,18446744073709551616,1,ok,,1,converged,0,3", "column seed:");
  expect("attempts", "1,5,0,ok,,1,converged,0,3", "column attempts: '0'");
  expect("status", "1,5,1,fine,,1,converged,0,3", "column status: 'fine' is not a status");
  expect("violation", "1,5,1,ok,,1,converged,2,3", "column violation: '2' is not 0 or 1");
  expect("again", "0,5,1,ok,,1,converged,0,3", "run 0 again (its row is line 2)");
}

TEST(RunsFile, AnotherCampaignsHeaderIsRefusedAsSuch) {
  const fs::path p = runs_with("header", kRow0 + "\n");
  try {
    (void)read_runs(p, "run,seed,attempts,status,reason,violation");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the header of this runs.csv differs"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace attiguard::campaign
