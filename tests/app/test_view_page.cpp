// app/view_page: the data and HTML of DIR/view.html (docs/viewer.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "attiguard/app/aem_export.hpp"
#include "attiguard/app/result_summary.hpp"
#include "attiguard/app/view_page.hpp"
#include "attiguard/core/errors.hpp"
#include "cli_runner.hpp"

namespace attiguard::app {
namespace {

namespace fs = std::filesystem;

/// A pet_erg-like folder with `rows` trajectory rows t = 0.01 k.
fs::path flight_dir(const std::string& name, int rows) {
  const fs::path dir = test::fresh_dir(name);
  std::ofstream(dir / "summary.json") << R"({"kind": "pet_erg", "name": "demo</script><b>", "cones": []})";
  std::ofstream csv(dir / "trajectory.csv");
  csv.precision(17);
  csv << "t,q_w,q_x,q_y,q_z\n";
  for (int k = 0; k < rows; ++k) csv << 0.01 * k << ",1,0,0," << 1.0 / 3.0 << "\n";
  return dir;
}

TEST(ViewPage, DecimatesLongTrajectoriesSayingSoAndKeepsTheLastRow) {
  const fs::path dir = flight_dir("view_decimate", 4500);
  const nlohmann::json d = view_data(dir);
  EXPECT_EQ(d["kind"], "pet_erg");
  const auto& s = d["series"]["trajectory"];
  EXPECT_EQ(s["rows_total"], 4500);
  EXPECT_EQ(s["stride"], 3);            // ceil(4500 / kViewMaxRows)
  EXPECT_EQ(s["rows_shown"], 1501);     // every 3rd row and the last one
  EXPECT_DOUBLE_EQ(s["data"]["t"].back().get<double>(), 44.99);
  EXPECT_DOUBLE_EQ(s["data"]["q_z"][0].get<double>(), 0.333333333);  // 9 significant digits
  fs::remove_all(dir);
}

TEST(ViewPage, ShortTrajectoriesAreShownWhole) {
  const fs::path dir = flight_dir("view_whole", 300);
  const nlohmann::json d = view_data(dir);
  EXPECT_EQ(d["series"]["trajectory"]["stride"], 1);
  EXPECT_EQ(d["series"]["trajectory"]["rows_shown"], 300);
  fs::remove_all(dir);
}

TEST(ViewPage, TheHtmlCannotBeClosedByTheDataAndInlinesTheBundle) {
  const fs::path dir = flight_dir("view_html", 10);
  const std::string html = view_html(view_data(dir), "console.log('</script>');");
  EXPECT_EQ(html.find("demo</script>"), std::string::npos);
  EXPECT_NE(html.find("demo<\\/script>"), std::string::npos);
  EXPECT_NE(html.find("console.log('<\\/script>');"), std::string::npos);
  EXPECT_NE(html.find("Content-Security-Policy"), std::string::npos);
  fs::remove_all(dir);
}

TEST(ViewPage, AFolderWithoutResultsOrTrajectoryIsInvalidInput) {
  const fs::path empty = test::fresh_dir("view_empty");
  EXPECT_THROW((void)view_data(empty), InputError);
  std::ofstream(empty / "summary.json") << R"({"kind": "pet_erg"})";
  EXPECT_THROW((void)view_data(empty), InputError);
  EXPECT_THROW((void)write_view(empty, "console.log(1);"), InputError);
  EXPECT_THROW((void)read_viewer_bundle(empty / "no_bundle.js"), InputError);
  fs::remove_all(empty);
}

/// The message of `f()`'s InputError, "" when it does not throw one.
template <class F>
std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ViewPage, RefusesWhatExportAemRefusesWithTheSameMessage) {
  // Each fault of a run folder: the view's message is the AEM export's (one reader for both).
  const std::vector<std::pair<std::string, std::string>> trajectory_faults{
      {"nan", "t,q_w,q_x,q_y,q_z\n0,1,0,0,0\n0.1,nan,0,0,0\n"},
      {"torn", "t,q_w,q_x,q_y,q_z\n0,1,0,0,0\n0.1,1,0\n"},
      {"extra", "t,q_w,q_x,q_y,q_z\n0,1,0,0,0,7\n"},
      {"text", "t,q_w,q_x,q_y,q_z\n0,1,0,abc,0\n"}};
  for (const auto& [name, text] : trajectory_faults) {
    const fs::path dir = flight_dir("view_fault_" + name, 3);
    std::ofstream(dir / "trajectory.csv", std::ios::trunc) << text;
    const std::string view = refusal([&] { (void)view_data(dir); });
    EXPECT_NE(view.find("trajectory.csv:"), std::string::npos) << name << ": " << view;
    EXPECT_EQ(view, refusal([&] { (void)export_aem(dir, io::AemMetadata{}); })) << name;
    fs::remove_all(dir);
  }
  const std::vector<std::pair<std::string, std::string>> summary_faults{
      {"array", "[]"}, {"kind", R"({"kind": "warp_drive"})"}, {"nokind", R"({"name": "x"})"},
      {"torn", R"({"kind": "pet_)"}, {"name", R"({"kind": "pet_erg", "name": 3})"}};
  for (const auto& [name, text] : summary_faults) {
    const fs::path dir = flight_dir("view_summary_" + name, 3);
    std::ofstream(dir / "summary.json", std::ios::trunc) << text;
    const std::string view = refusal([&] { (void)view_data(dir); });
    EXPECT_NE(view.find("summary.json: "), std::string::npos) << name << ": " << view;
    EXPECT_EQ(view, refusal([&] { (void)read_run_summary(dir / "summary.json"); })) << name;
    fs::remove_all(dir);
  }
}

TEST(ViewPage, CampaignRunsAreReadByTheResumeReader) {
  const fs::path dir = test::fresh_dir("view_runs");
  std::ofstream(dir / "campaign.json") << R"({"runs_requested": 2})";
  std::ofstream(dir / "runs.csv") << "run,seed,attempts,status,reason,violation,x\n0,18446744073709551615,1,ok,,0,1.5\n"
                                     "1,2,1,failed,\"diverged, at t = 3\",,\n";
  const nlohmann::json d = view_data(dir);
  EXPECT_EQ(d["series"]["runs"]["rows_total"], 2);
  EXPECT_EQ(d["series"]["runs"]["data"]["seed"][0], "18446744073709551615");
  EXPECT_EQ(d["series"]["runs"]["data"]["reason"][1], "diverged, at t = 3");
  EXPECT_TRUE(d["series"]["runs"]["data"]["x"][1].is_null());
  std::ofstream(dir / "runs.csv", std::ios::app) << "2,3,1,ok,,0,nan\n";
  const std::string m = refusal([&] { (void)view_data(dir); });
  EXPECT_NE(m.find("runs.csv:4: column x: 'nan' is not a finite number"), std::string::npos) << m;
  std::ofstream(dir / "campaign.json", std::ios::trunc) << "[]";
  EXPECT_NE(refusal([&] { (void)view_data(dir); }).find("campaign.json: expected a JSON object"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::app
