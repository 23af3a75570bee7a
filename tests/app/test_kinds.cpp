// app/kinds: the kind registry runs a kind with its rows in the sink the caller chooses.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "attiguard/app/kinds.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {
namespace {

/// Counts rows and remembers the columns.
class CountingSink final : public io::RowSink {
 public:
  void begin(const std::vector<std::string>& c) override { columns = c; }
  void row(std::span<const double>) override { ++rows; }
  std::vector<std::string> columns;
  long rows{0};
};

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("attiguard_kinds_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(Kinds, RowsGoToTheCallersSinkAndNoFileIsWrittenWithoutWriteFiles) {
  const scenario::Document doc =
      scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/rigid_body_pd.toml");
  for (const char* name : {"rigid_body"}) {
    const KindHandler& h = handler_for(doc);
    EXPECT_EQ(h.name, name);
    CountingSink rows;
    RunOptions options;
    options.out_dir = scratch("memory");
    options.write_files = false;
    options.rows = &rows;
    const nlohmann::json summary = h.run(doc, options);
    EXPECT_FALSE(std::filesystem::exists(options.out_dir));
    EXPECT_EQ(rows.columns.front(), "t");
    EXPECT_GT(rows.rows, 1);
    EXPECT_EQ(summary["output_rows"].get<long>(), rows.rows);
    EXPECT_TRUE(summary.contains("wall_time_s"));
  }
}

TEST(Kinds, WithWriteFilesTheCsvHasTheSameRowsAsTheSink) {
  const scenario::Document doc =
      scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/waypoint_paper.toml");
  CountingSink rows;
  RunOptions options;
  options.out_dir = scratch("files");
  options.rows = &rows;
  (void)handler_for(doc).run(doc, options);
  ASSERT_TRUE(std::filesystem::is_regular_file(options.out_dir / "summary.json"));
  long lines = 0;
  std::ifstream csv(options.out_dir / "trajectory.csv");
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, rows.rows + 1);  // header + rows
  std::filesystem::remove_all(options.out_dir);
}

}  // namespace
}  // namespace attiguard::app
