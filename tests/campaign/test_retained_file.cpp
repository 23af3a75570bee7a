// campaign/retained_file: DIR/retained.h5 written and read back, and `attiguard campaign`
// writing it (docs/campaigns.md, "Retained time series").

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "attiguard/campaign/retained_file.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_reader.hpp"
#include "cli_runner.hpp"

namespace attiguard::campaign {
namespace {

namespace fs = std::filesystem;

TEST(RetainedFile, WritesRowsAsRunsFinishAndReadsThemBackWithNaNForMissingRuns) {
  const fs::path dir = test::fresh_dir("retained_file");
  const fs::path path = dir / "retained.h5";
  const std::vector<double> t{0.0, 1.0, 2.0};
  {
    RetainedFile f(path, {"x", "y"}, t, 4, 1.0, false);
    const std::vector<double> run2{1, 2, 3, 10, 20, 30};  // x then y
    f.write_run(2, run2, 3);
    const std::vector<double> run0{4, 5, 40, 50};  // a run with only 2 samples
    f.write_run(0, run0, 2);
  }
  const RetainedSeries r = read_retained(path);
  EXPECT_EQ(r.columns, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(r.t, t);
  ASSERT_EQ(r.runs, 4u);
  EXPECT_EQ(r.values[1][2 * 3 + 1], 20.0);
  EXPECT_EQ(r.values[0][0 * 3 + 1], 5.0);
  EXPECT_TRUE(std::isnan(r.values[0][0 * 3 + 2]));  // run 0 ended before t = 2
  EXPECT_TRUE(std::isnan(r.values[0][1 * 3 + 0]));  // run 1 never written
  // --resume reopens a matching file and refuses another shape.
  EXPECT_NO_THROW(RetainedFile(path, {"x", "y"}, t, 4, 1.0, true));
  EXPECT_THROW(RetainedFile(path, {"x"}, t, 4, 1.0, true), InputError);
  // A larger --runs on --resume keeps the rows written so far.
  { RetainedFile extended(path, {"x", "y"}, t, 6, 1.0, true); }
  const RetainedSeries e = read_retained(path);
  EXPECT_EQ(e.runs, 6u);
  EXPECT_EQ(e.values[1][2 * 3 + 1], 20.0);
  EXPECT_TRUE(std::isnan(e.values[1][5 * 3 + 1]));
  fs::remove_all(dir);
}

#ifdef ATTIGUARD_CLI_PATH
TEST(RetainedFile, CampaignRetainsEachRunsColumnsAsItsReplayedTrajectoryHasThem) {
  const fs::path dir = test::fresh_dir("retain_cli");
  const std::string scenario = std::string("'") + ATTIGUARD_SOURCE_DIR + "/examples/pet_erg_campaign_retained.toml'";
  const auto r = test::run_cli("campaign " + scenario + " --runs 6 --seed 3 --out '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("retained.h5"), std::string::npos) << r.out;
  const RetainedSeries s = read_retained(dir / "retained.h5");
  EXPECT_EQ(s.runs, 6u);
  EXPECT_EQ(s.columns, (std::vector<std::string>{"margin_0", "tau_norm", "V"}));
  ASSERT_EQ(s.t.size(), 121u);  // 60 s every 0.5 s
  const auto p = test::run_cli("campaign " + scenario + " --seed 3 --out '" + dir.string() + "' --replay 4");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const io::CsvTable csv = io::read_csv(dir / "run_4" / "trajectory.csv");
  const std::size_t it = *csv.column("t"), im = *csv.column("margin_0"), iv = *csv.column("V");
  std::size_t row = 0, checked = 0;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    while (row < csv.rows.size() && csv.rows[row][it] < s.t[k] - 1e-9) ++row;
    ASSERT_LT(row, csv.rows.size());
    EXPECT_EQ(s.values[0][4 * s.t.size() + k], csv.rows[row][im]) << "t = " << s.t[k];
    EXPECT_EQ(s.values[2][4 * s.t.size() + k], csv.rows[row][iv]) << "t = " << s.t[k];
    ++checked;
  }
  EXPECT_EQ(checked, 121u);

  // An unknown retained column is invalid input naming the key and the columns.
  std::ofstream(dir / "bad.toml") << test::read_file(fs::path(ATTIGUARD_SOURCE_DIR) / "examples/pet_erg_campaign_retained.toml")
                                  << "\n";
  std::string text = test::read_file(dir / "bad.toml");
  text.replace(text.find("\"margin_0\", "), 12, "\"margin_9\", ");
  std::ofstream(dir / "bad.toml") << text;
  const auto b = test::run_cli("campaign '" + (dir / "bad.toml").string() + "' --runs 2 --out '" + (dir / "bad").string() + "'");
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("[campaign] retain: no column 'margin_9'"), std::string::npos) << b.err;
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace attiguard::campaign
