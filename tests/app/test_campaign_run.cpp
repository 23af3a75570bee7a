// app/campaign_run: one campaign of a loaded scenario — its files, its report, and --resume
// running only the runs DIR/runs.csv does not hold.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "attiguard/app/campaign_run.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"

namespace attiguard::app {
namespace {

namespace fs = std::filesystem;

fs::path run_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() /
                   ("attiguard_campaign_run_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string run_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

long run_line_count(const std::string& text) {
  long n = 0;
  for (char c : text) n += c == '\n' ? 1 : 0;
  return n;
}

const fs::path kCampaignScenario = fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_campaign.toml";

CampaignRequest campaign_request_of(const fs::path& out, long runs, bool resume) {
  CampaignRequest r;
  r.scenario = kCampaignScenario;
  r.out_dir = out;
  r.runs = runs;
  r.seed = 5;
  r.resume = resume;
  r.identity = {"00ff", 5, "test", "pet_erg"};
  return r;
}

TEST(CampaignRun, WritesRunsCsvCampaignJsonAndReportsThem) {
  const fs::path out = run_dir("fresh");
  const parallel::World world;
  const Campaign c = load_campaign(kCampaignScenario, 5, campaign_scratch(out, world.rank));
  OutputFolder folder(out, OutputCommand::campaign, true, {kCampaignScenario});
  folder.claim();
  CampaignRequest request = campaign_request_of(out, 3, false);
  CampaignStart started{99, 99};
  request.on_start = [&](const CampaignStart& s) { started = s; };
  const std::optional<CampaignReport> report = run_campaign(c, request, world, folder);
  ASSERT_TRUE(report.has_value());
  EXPECT_EQ(started.done, 0u);
  EXPECT_EQ(started.todo, 3u);
  EXPECT_EQ(report->rows, 3u);
  EXPECT_EQ(report->runs_path, out / "runs.csv");
  EXPECT_EQ(run_line_count(run_file_text(report->runs_path)), 4);
  EXPECT_EQ(run_file_text(report->runs_path).substr(0, csv_header(c).size() + 1), csv_header(c) + "\n");
  EXPECT_EQ(run_file_text(report->summary_path), report->summary.dump(2) + "\n");
  EXPECT_EQ(report->summary["runs_completed"], 3);
  EXPECT_EQ(report->summary["scenario_sha256"], "00ff");
  EXPECT_EQ(report->summary["attiguard_version"], "test");
  EXPECT_TRUE(fs::exists(report->resolved_path));
  EXPECT_EQ(nlohmann::json::parse(run_file_text(out / "campaign_identity.json"))["seed"], 5);
  EXPECT_FALSE(report->retained_path.has_value());
  EXPECT_FALSE(fs::exists(out / ".scratch"));

  // --replay 1: the same row as in runs.csv, with the run's own files beside it.
  fs::create_directories(out / "run_1");
  OutputFolder replay_folder(out / "run_1", OutputCommand::replay, true, {kCampaignScenario});
  replay_folder.claim();
  const ReplayReport replayed = replay_campaign_run(c, 1, kCampaignScenario, out / "runs.csv", replay_folder);
  EXPECT_EQ(replayed.run.index, 1);
  ASSERT_TRUE(replayed.matches_runs_csv.has_value());
  EXPECT_TRUE(*replayed.matches_runs_csv);
  EXPECT_EQ(run_file_text(out / "run_1/run.csv"), csv_header(c) + "\n" + replayed.row + "\n");
  EXPECT_TRUE(fs::exists(out / "run_1/summary.json"));
  EXPECT_TRUE(fs::exists(out / "run_1/trajectory.csv"));
  EXPECT_TRUE(fs::exists(out / "run_1" / scenario::kResolvedScenarioFile));
  // Run 7 is not in runs.csv: nothing to compare with.
  EXPECT_FALSE(replay_campaign_run(c, 7, kCampaignScenario, out / "runs.csv", replay_folder).matches_runs_csv);
  fs::remove_all(out);
}

TEST(CampaignRun, ResumeRunsOnlyTheMissingRunsAndGivesTheBytesOfOneCampaign) {
  const fs::path whole = run_dir("whole");
  const fs::path cut = run_dir("cut");
  const parallel::World world;
  const Campaign c = load_campaign(kCampaignScenario, 5, campaign_scratch(whole, world.rank));
  {
    OutputFolder folder(whole, OutputCommand::campaign, true, {kCampaignScenario});
    folder.claim();
    ASSERT_TRUE(run_campaign(c, campaign_request_of(whole, 4, false), world, folder));
  }
  {
    OutputFolder folder(cut, OutputCommand::campaign, true, {kCampaignScenario});
    folder.claim();
    ASSERT_TRUE(run_campaign(c, campaign_request_of(cut, 2, false), world, folder));
  }
  OutputFolder folder(cut, OutputCommand::campaign, true, {kCampaignScenario});
  CampaignRequest resume = campaign_request_of(cut, 4, true);
  CampaignStart started;
  resume.on_start = [&](const CampaignStart& s) { started = s; };
  const std::optional<CampaignReport> report = run_campaign(c, resume, world, folder);
  ASSERT_TRUE(report.has_value());
  EXPECT_EQ(started.done, 2u);
  EXPECT_EQ(started.todo, 2u);
  EXPECT_EQ(run_file_text(cut / "runs.csv"), run_file_text(whole / "runs.csv"));
  EXPECT_EQ(run_file_text(cut / "campaign.json"), run_file_text(whole / "campaign.json"));
  // Another seed is another campaign: refused, the folder unchanged.
  CampaignRequest other = campaign_request_of(cut, 4, true);
  other.identity.seed = 6;
  const std::string before = run_file_text(cut / "runs.csv");
  EXPECT_THROW((void)run_campaign(c, other, world, folder), InputError);
  EXPECT_EQ(run_file_text(cut / "runs.csv"), before);
  fs::remove_all(whole);
  fs::remove_all(cut);
}

TEST(CampaignRun, RunStatusesHaveTheirRunsCsvNames) {
  EXPECT_STREQ(status_name(RunStatus::ok), "ok");
  EXPECT_STREQ(status_name(RunStatus::rejected), "rejected");
  EXPECT_STREQ(status_name(RunStatus::failed), "failed");
  EXPECT_EQ(kRunStatusNames.find("rejected"), RunStatus::rejected);
}

TEST(CampaignRun, TheScratchFolderOfARankIsBelowDir) {
  EXPECT_EQ(campaign_scratch("out", 3), fs::path("out") / ".scratch" / "rank3");
}

}  // namespace
}  // namespace attiguard::app
