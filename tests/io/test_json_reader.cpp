// io/json_reader: result JSON files read back as objects (docs/errors.md, "Strict readers").

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/json_reader.hpp"

namespace attiguard::io {
namespace {

std::string refusal(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() /
                 ("attiguard_json_reader_" + name + "_" + std::to_string(::getpid()) + ".json");
  std::ofstream(p, std::ios::binary) << text;
  std::string m;
  try {
    (void)read_json_object(p);
  } catch (const InputError& e) {
    m = e.what();
  }
  std::filesystem::remove(p);
  return m;
}

TEST(JsonReader, ReadsObjectsAndRefusesEverythingElseNamingTheFile) {
  EXPECT_EQ(refusal("ok", R"({"kind": "pet_erg", "x": [1, 2]})"), "");
  EXPECT_NE(refusal("array", "[]").find(".json: expected a JSON object (as attiguard writes), got an array"), std::string::npos);
  EXPECT_NE(refusal("number", "3").find("got a number"), std::string::npos);
  EXPECT_NE(refusal("torn", R"({"kind": "pet)").find(": not valid JSON (at byte "), std::string::npos);
  EXPECT_NE(refusal("nan", R"({"x": NaN})").find("not valid JSON"), std::string::npos);
  EXPECT_NE(refusal("empty", "").find("not valid JSON"), std::string::npos);
  // Found by fuzz/output_reader_fuzz.cpp: nlohmann-json throws out_of_range, not parse_error.
  EXPECT_NE(refusal("overflow", R"({"x": 45601e0326245489})").find(": not valid JSON (number overflow parsing '45601e0326245489')"),
            std::string::npos)
      << refusal("overflow", R"({"x": 45601e0326245489})");
  try {
    (void)read_json_object("/nonexistent/summary.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/summary.json: cannot read (not a regular file)");
  }
}

}  // namespace
}  // namespace attiguard::io
