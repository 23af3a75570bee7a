/// @file campaign_identity.cpp
/// The campaign identity file and the --resume check (app/campaign_identity.hpp).

#include "attiguard/app/campaign_identity.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/json_file.hpp"

namespace attiguard::app {

namespace {

/// The identity file `file` as JSON; InputError (with `where`) when it is missing or unreadable.
nlohmann::json read_identity_file(const std::filesystem::path& file, const std::string& where,
                                  std::size_t completed_rows) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(where + "missing, so the " + std::to_string(completed_rows) +
                     " rows of runs.csv beside it cannot be matched to this scenario and seed; "
                     "start a new campaign (without --resume) or use another --out");
  }
  try {
    std::stringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + "not a campaign identity (unreadable JSON)");
  }
}

}  // namespace

void write_identity(const std::filesystem::path& file, const CampaignIdentity& id) {
  const nlohmann::json j = {{"scenario_sha256", id.scenario_sha256},
                            {"seed", id.seed},
                            {"attiguard_version", id.version},
                            {"kind", id.kind}};
  io::write_json(file, j);
}

void check_resume_identity(const std::filesystem::path& file, const CampaignIdentity& now,
                           std::size_t completed_rows) {
  if (completed_rows == 0) return;
  const std::string where = file.string() + ": --resume: ";
  const nlohmann::json j = read_identity_file(file, where, completed_rows);
  const auto field = [&](const char* key) -> std::string {
    if (!j.contains(key)) throw InputError(where + "has no '" + key + "'");
    return j[key].is_string() ? j[key].get<std::string>() : j[key].dump();
  };
  const auto differ = [&](const std::string& what, const std::string& then, const std::string& here) {
    throw InputError(where + what + " differs: the campaign in this folder has " + then +
                     ", this invocation " + here +
                     "; resume with the same one or start a new campaign in another --out");
  };
  if (const std::string s = field("seed"); s != std::to_string(now.seed)) {
    differ("the seed", s, std::to_string(now.seed));
  }
  if (const std::string s = field("scenario_sha256"); s != now.scenario_sha256) {
    differ("the scenario file (SHA-256)", s.substr(0, 12) + "…", now.scenario_sha256.substr(0, 12) + "…");
  }
  if (const std::string s = field("kind"); s != now.kind) differ("the scenario kind", s, now.kind);
  if (const std::string s = field("attiguard_version"); s != now.version) {
    differ("the attiguard version", s, now.version);
  }
}

}  // namespace attiguard::app
