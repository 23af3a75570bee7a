// app/output_folder: run_in_folder, the claim / run / fail protocol every command runs in.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "attiguard/app/output_folder.hpp"
#include "attiguard/core/errors.hpp"

namespace attiguard::app {
namespace {

namespace fs = std::filesystem;

fs::path folder_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() /
                   ("attiguard_output_folder_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string folder_file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(OutputFolderRun, ClaimsTheFolderThenRunsTheBody) {
  const fs::path dir = folder_dir("claim");
  std::ofstream(dir / "reach.json") << "{}";
  OutputFolder folder(dir, OutputCommand::run);
  bool ran = false;
  run_in_folder(folder, "", dir / "s.toml", [&] {
    ran = true;
    EXPECT_FALSE(fs::exists(dir / "reach.json"));  // another command's output: removed first
  });
  EXPECT_TRUE(ran);
  fs::remove_all(dir);
}

TEST(OutputFolderRun, AFailureOfTheBodyLeavesTheStatusFileAndIsRethrown) {
  const fs::path dir = folder_dir("fail");
  OutputFolder folder(dir, OutputCommand::tune);
  EXPECT_THROW(run_in_folder(folder, "pet_erg", "s.toml",
                             [&] {
                               std::ofstream(dir / "tune.json") << "{\"outcome\": \"found\"}\n";
                               throw InputError("s.toml: bad");
                             }),
               InputError);
  EXPECT_FALSE(fs::exists(dir / "tune.json"));
  const auto status = nlohmann::json::parse(folder_file_text(dir / "tune.json.partial"));
  EXPECT_EQ(status["status"], "partial");
  EXPECT_EQ(status["kind"], "pet_erg");
  EXPECT_EQ(status["scenario"], "s.toml");
  EXPECT_EQ(status["error"], "s.toml: bad");
  EXPECT_EQ(status["result"]["outcome"], "found");
  fs::remove_all(dir);
}

TEST(OutputFolderRun, WithoutTheClaimTheFolderIsLeftAsItWasOnFailure) {
  const fs::path dir = folder_dir("unclaimed");
  std::ofstream(dir / "runs.csv") << "run\n";
  std::ofstream(dir / "reach.json") << "{}";
  OutputFolder folder(dir, OutputCommand::campaign);
  EXPECT_THROW(run_in_folder(folder, "", "s.toml", [] { throw InputError("refused"); }, false),
               InputError);
  EXPECT_TRUE(fs::exists(dir / "reach.json"));
  EXPECT_TRUE(fs::exists(dir / "runs.csv"));
  EXPECT_FALSE(fs::exists(dir / "campaign.json.partial"));
  fs::remove_all(dir);
}

TEST(OutputFolderRun, StatusNamesAndOutputNamesComeFromTheTables) {
  EXPECT_EQ(status_name(OutputCommand::run), "summary.json");
  EXPECT_EQ(status_name(OutputCommand::replay), "summary.json");
  EXPECT_EQ(status_name(OutputCommand::campaign), "campaign.json");
  EXPECT_EQ(status_name(OutputCommand::view), "");
  EXPECT_EQ(status_name(OutputCommand::export_aem), "");
  ASSERT_EQ(output_names(OutputCommand::view).size(), 1u);
  EXPECT_EQ(output_names(OutputCommand::view).front(), "view.html");
  EXPECT_EQ(output_names(OutputCommand::tune).front(), "tune.json");
}

}  // namespace
}  // namespace attiguard::app
