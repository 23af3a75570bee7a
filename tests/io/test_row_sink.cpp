// io/row_sink: where a simulator's rows go (CSV file, nowhere, two sinks at once).

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "attiguard/io/row_sink.hpp"

namespace attiguard::io {
namespace {

/// Records what it receives.
class RecordingSink final : public RowSink {
 public:
  void begin(const std::vector<std::string>& c) override { columns = c; }
  void row(std::span<const double> v) override { rows.emplace_back(v.begin(), v.end()); }
  void end() override { ended = true; }
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  bool ended{false};
};

TEST(RowSink, CsvSinkWritesHeaderAndExactRows) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("attiguard_row_sink_" + std::to_string(::getpid()) + ".csv");
  {
    CsvRowSink csv(path);
    EXPECT_EQ(csv.rows(), 0);
    csv.begin({"t", "x"});
    const std::array<double, 2> r0{0.0, 0.1};
    const std::array<double, 2> r1{0.5, 1.0 / 3.0};
    csv.row(r0);
    csv.row(r1);
    csv.end();
    EXPECT_EQ(csv.rows(), 2);
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "t,x\n0,0.1\n0.5,0.3333333333333333\n");
  std::filesystem::remove(path);
}

TEST(RowSink, NullSinkWantsNoRowsAndTeeFeedsBoth) {
  NullRowSink none;
  EXPECT_FALSE(none.wants_rows());
  RecordingSink a;
  RecordingSink b;
  EXPECT_TRUE(a.wants_rows());
  TeeRowSink tee(a, b);
  tee.begin({"t"});
  const std::array<double, 1> r{2.0};
  tee.row(r);
  tee.end();
  for (const RecordingSink* s : {&a, &b}) {
    EXPECT_EQ(s->columns, std::vector<std::string>{"t"});
    ASSERT_EQ(s->rows.size(), 1U);
    EXPECT_EQ(s->rows[0][0], 2.0);
    EXPECT_TRUE(s->ended);
  }
}

}  // namespace
}  // namespace attiguard::io
