#pragma once
/// @file campaign_identity.hpp
/// What makes two campaign invocations the same campaign (docs/campaigns.md, "Interruption and
/// resume"): the SHA-256 of the scenario file's bytes, the seed, the attiguard version and the
/// kind. Written to DIR/campaign_identity.json when a campaign starts; `--resume` refuses to add
/// rows to a folder whose identity differs, naming the difference. The digest itself is taken by
/// the program (cli/campaign_identity.hpp: only it links OpenSSL).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace attiguard::app {

/// The identity of one campaign (docs/campaigns.md, "Interruption and resume").
struct CampaignIdentity {
  std::string scenario_sha256;  ///< hex digest of the scenario file
  std::uint64_t seed{0};
  std::string version;          ///< attiguard version that ran it
  std::string kind;             ///< scenario kind
};

/// Writes it as JSON to `file` (io::write_json: through FILE.partial, renamed; docs/campaigns.md,
/// "Interruption and resume").
void write_identity(const std::filesystem::path& file, const CampaignIdentity& id);

/// For `--resume` into a folder holding `completed_rows` finished runs: throws InputError naming
/// the first field of `file` that differs from `now` (or that `file` is missing or unreadable
/// while rows exist). Nothing to check when there are no rows (docs/campaigns.md, "Interruption
/// and resume").
void check_resume_identity(const std::filesystem::path& file, const CampaignIdentity& now,
                           std::size_t completed_rows);

}  // namespace attiguard::app
