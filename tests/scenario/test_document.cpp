#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "attiguard/scenario/document.hpp"
#include "scenario/scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;
using test::input_error;
using test::starts_with;

TEST(Document, ParsesTextAndKeepsThePathForMessages) {
  const Document doc = parse_document("kind = \"rigid_body\"\n", "dir/my.toml");
  EXPECT_EQ(doc.path, std::filesystem::path("dir/my.toml"));
  EXPECT_EQ(scenario_kind(doc), "rigid_body");
}

TEST(Document, SyntaxErrorsAreOneLineWithFileLineAndColumn) {
  const std::string m = input_error(
      [] { (void)parse_document("kind = \"rigid_body\"\n[control]\nkp = 5.0.0\n", "bad.toml"); });
  EXPECT_TRUE(starts_with(m, "bad.toml:3:")) << m;
  EXPECT_TRUE(contains(m, ": TOML syntax error: "));
  const std::string dup = input_error([] { (void)parse_document("a = 1\na = 2\n", "bad.toml"); });
  EXPECT_TRUE(starts_with(dup, "bad.toml:2:")) << dup;
  EXPECT_TRUE(contains(dup, "TOML syntax error:"));
  const std::string eof = input_error([] { (void)parse_document("v = [1,\n", "bad.toml"); });
  EXPECT_TRUE(contains(eof, "TOML syntax error:"));
}

TEST(Document, ScenarioKindIsARequiredString) {
  EXPECT_EQ(input_error([] { (void)scenario_kind(parse_document("name = \"x\"\n", "k.toml")); }),
            "k.toml:1:1: kind: missing required key: every scenario file names its kind, e.g. "
            "kind = \"rigid_body\"");
  EXPECT_TRUE(
      starts_with(input_error([] { (void)scenario_kind(parse_document("kind = 3\n", "k.toml")); }),
                  "k.toml:1:8: kind: expected a string, got an integer"));
}

TEST(Document, LoadReadsFilesAndReportsUnreadableOnes) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "attiguard_scenario_document_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "ok.toml";
  {
    std::ofstream out(file);
    out << "kind = \"rigid_body\"\n";
  }
  EXPECT_EQ(scenario_kind(load_document(file)), "rigid_body");
  const std::filesystem::path none = dir / "missing.toml";
  EXPECT_TRUE(starts_with(input_error([&] { (void)load_document(none); }),
                          none.string() + ": cannot read scenario file ("));
  EXPECT_EQ(input_error([&] { (void)load_document(dir); }),
            dir.string() + ": cannot read scenario file (it is a directory)");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::scenario
