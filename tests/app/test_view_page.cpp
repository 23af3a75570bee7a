// app/view_page: the data and HTML of DIR/view.html (docs/viewer.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

}  // namespace
}  // namespace attiguard::app
