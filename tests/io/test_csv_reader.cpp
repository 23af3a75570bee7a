// io/csv_reader: numeric CSV files as csv_writer writes them.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_reader.hpp"

namespace attiguard::io {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() /
                 ("attiguard_csv_reader_" + name + "_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(p) << text;
  return p;
}

TEST(CsvReader, ReadsColumnsAndExactNumbersWithEmptyFieldsAsNaN) {
  const auto p = write("ok", "t,x\n0,0.1\n0.5,\n1,0.3333333333333333\n");
  const CsvTable t = read_csv(p);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "x"}));
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(*t.column("x"), 1u);
  EXPECT_FALSE(t.column("y").has_value());
  EXPECT_EQ(t.rows[0][1], 0.1);
  EXPECT_TRUE(std::isnan(t.rows[1][1]));
  EXPECT_EQ(t.rows[2][1], 1.0 / 3.0);
  std::filesystem::remove(p);
}

TEST(CsvReader, NamesTheLineOfABadRow) {
  const auto p = write("bad", "t,x\n0,1\n1,abc\n");
  try {
    (void)read_csv(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":3: column x: 'abc' is not a number"), std::string::npos) << e.what();
  }
  const auto q = write("short", "t,x\n0\n");
  EXPECT_THROW((void)read_csv(q), InputError);
  EXPECT_THROW((void)read_csv(p.string() + ".missing"), InputError);
  std::filesystem::remove(p);
  std::filesystem::remove(q);
}

}  // namespace
}  // namespace attiguard::io
