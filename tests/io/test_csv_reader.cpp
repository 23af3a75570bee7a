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

TEST(CsvReader, RefusesNonFiniteFieldsTornRowsAndBadHeaders) {
  const auto message = [](const std::string& name, const std::string& text) {
    const auto p = write(name, text);
    std::string m;
    try {
      (void)read_csv(p);
    } catch (const InputError& e) {
      m = e.what();
    }
    std::filesystem::remove(p);
    return m;
  };
  EXPECT_NE(message("nan", "t,x\n0,1\n1,nan\n").find(":3: column x: 'nan' is not a finite number"), std::string::npos);
  EXPECT_NE(message("inf", "t,x\n-inf,1\n").find(":2: column t: '-inf' is not a finite number"), std::string::npos);
  EXPECT_NE(message("big", "t,x\n0,1e999\n").find(":2: column x: '1e999' is not a number"), std::string::npos);
  EXPECT_NE(message("torn", "t,x\n0,1\n1,2,3\n").find(":3: 3 fields, the header has 2"), std::string::npos);
  EXPECT_NE(message("dup", "t,x,t\n0,1,2\n").find(":1: the header names column 't' twice"), std::string::npos);
  EXPECT_NE(message("emptyname", "t,,x\n").find(":1: the header has an empty column name"), std::string::npos);
  EXPECT_NE(message("empty", "").find("empty file (no header row)"), std::string::npos);
  EXPECT_EQ(message("subnormal", "t,x\n0,5e-324\n"), "");  // csv_writer writes subnormals
}

TEST(CsvReader, AFileBeyondTheSizeLimitIsRefusedNamingTheFileAndTheLimit) {
  const auto p = write("huge", "t,x\n0,1\n");
  std::filesystem::resize_file(p, kMaxResultFileBytes + 1);  // sparse: no disk used
  try {
    (void)read_csv(p);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(p.string() + ": 536870913 bytes (512 MiB) is more than the limit 512 MiB", 0), 0u) << m;
  }
  std::filesystem::remove(p);
}

TEST(CsvReader, StreamReadsRowByRowWithTheSameChecks) {
  const auto p = write("stream", "t,x\n0,1\n\n1,2\n2,x\n");
  CsvStream s(p);
  EXPECT_EQ(s.columns(), (std::vector<std::string>{"t", "x"}));
  std::vector<double> row;
  ASSERT_TRUE(s.next(row));
  EXPECT_EQ(row, (std::vector<double>{0.0, 1.0}));
  ASSERT_TRUE(s.next(row));  // the blank line is skipped
  EXPECT_EQ(s.line(), 4);
  EXPECT_THROW((void)s.next(row), InputError);
  std::filesystem::remove(p);
}

}  // namespace
}  // namespace attiguard::io
