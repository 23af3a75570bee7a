// app/campaign_identity: the identity file of a campaign and the --resume check against it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "attiguard/app/campaign_identity.hpp"
#include "attiguard/core/errors.hpp"

namespace attiguard::app {
namespace {

std::filesystem::path identity_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("attiguard_identity_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string identity_file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string identity_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const CampaignIdentity kIdentity{"0123456789abcdef0123", 7, "1.2.3", "pet_erg"};

TEST(CampaignIdentity, IsWrittenAsIndentedJsonThroughAPartialFile) {
  const auto dir = identity_dir("write");
  write_identity(dir / "campaign_identity.json", kIdentity);
  EXPECT_EQ(identity_file_text(dir / "campaign_identity.json"),
            "{\n  \"attiguard_version\": \"1.2.3\",\n  \"kind\": \"pet_erg\",\n"
            "  \"scenario_sha256\": \"0123456789abcdef0123\",\n  \"seed\": 7\n}\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "campaign_identity.json.partial"));
  std::filesystem::remove_all(dir);
}

TEST(CampaignIdentity, ResumeAcceptsTheSameIdentityAndNamesTheFirstDifference) {
  const auto dir = identity_dir("resume");
  const auto file = dir / "campaign_identity.json";
  write_identity(file, kIdentity);
  EXPECT_EQ(identity_error_of([&] { check_resume_identity(file, kIdentity, 5); }), "");
  CampaignIdentity other = kIdentity;
  other.seed = 8;
  other.kind = "waypoint";
  const std::string seed = identity_error_of([&] { check_resume_identity(file, other, 5); });
  EXPECT_EQ(seed, file.string() + ": --resume: the seed differs: the campaign in this folder has 7, "
                                  "this invocation 8; resume with the same one or start a new "
                                  "campaign in another --out");
  other.seed = kIdentity.seed;
  EXPECT_NE(identity_error_of([&] { check_resume_identity(file, other, 5); })
                .find("the scenario kind differs: the campaign in this folder has pet_erg"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(CampaignIdentity, AMissingOrUnreadableFileIsRefusedOnlyWhenRowsExist) {
  const auto dir = identity_dir("missing");
  const auto file = dir / "campaign_identity.json";
  EXPECT_EQ(identity_error_of([&] { check_resume_identity(file, kIdentity, 0); }), "");
  EXPECT_NE(identity_error_of([&] { check_resume_identity(file, kIdentity, 3); })
                .find("--resume: missing, so the 3 rows of runs.csv"),
            std::string::npos);
  std::ofstream(file) << "{ not json";
  EXPECT_NE(identity_error_of([&] { check_resume_identity(file, kIdentity, 3); })
                .find("not a campaign identity (unreadable JSON)"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::app
