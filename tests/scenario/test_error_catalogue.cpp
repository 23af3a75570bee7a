// docs/errors.md is the catalogue of bad inputs: every case is a file of tests/data/bad_inputs/
// and its exact error message. This test reads the catalogue, loads each file the way
// `attiguard check` (or `attiguard campaign`, for files with [dispersions]) does, and compares.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/tune_table.hpp"
#include "attiguard/app/kinds.hpp"

namespace attiguard::scenario {
namespace {

struct Case {
  std::string name;
  std::string message;
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<Case> catalogue() {
  std::istringstream in(slurp(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "docs/errors.md"));
  std::vector<Case> cases;
  std::string line;
  bool in_block = false;
  while (std::getline(in, line)) {
    if (line.starts_with("## ")) {
      cases.push_back({line.substr(3), ""});
    } else if (line == "```" && !cases.empty()) {
      in_block = !in_block;
    } else if (in_block) {
      cases.back().message += line;
    }
  }
  return cases;
}

/// The message of the InputError the file produces ("" when it is accepted).
std::string error_of(const std::string& relative) {
  const std::string text = slurp(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / relative);
  try {
    const Document doc = parse_document(text, relative);
    if (doc.has_top_level("tune")) (void)read_tune_table(doc);  // as attiguard tune (cli/tune_command.cpp)
    if (doc.has_top_level("dispersions")) {  // as attiguard campaign (app/campaign_runner.cpp)
      const Document nominal = nominal_document(doc);
      const app::KindHandler& h = app::handler_for(nominal);
      const DispersionPlan plan = read_dispersions(doc);
      h.check(nominal);
      check_dispersion_bounds(plan, doc, h.check);
    } else {  // as attiguard check
      app::handler_for(doc).check(doc);
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ErrorCatalogue, EveryCaseGivesItsExactMessage) {
  const std::vector<Case> cases = catalogue();
  ASSERT_GE(cases.size(), 20u);
  for (const Case& c : cases) {
    EXPECT_EQ(error_of("tests/data/bad_inputs/" + c.name + ".toml"), c.message) << c.name;
  }
}

TEST(ErrorCatalogue, EveryBadInputFileIsCatalogued) {
  std::set<std::string> names;
  for (const Case& c : catalogue()) names.insert(c.name);
  const auto dir = std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "tests/data/bad_inputs";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_TRUE(names.contains(entry.path().stem().string())) << entry.path();
  }
}

}  // namespace
}  // namespace attiguard::scenario
