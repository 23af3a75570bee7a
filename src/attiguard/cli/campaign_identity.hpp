#pragma once
/// @file campaign_identity.hpp
/// What makes two campaign invocations the same campaign (docs/campaigns.md, "Interruption and
/// resume"): the SHA-256 of the scenario file's bytes, the seed, the attiguard version and the
/// kind. Written to DIR/campaign_identity.json when a campaign starts; `--resume` refuses to add
/// rows to a folder whose identity differs, naming the difference.

#include <cstdint>
#include <filesystem>
#include <string>

namespace attiguard::cli {

struct CampaignIdentity {
  std::string scenario_sha256;  ///< hex digest of the scenario file
  std::uint64_t seed{0};
  std::string version;          ///< attiguard version that ran it
  std::string kind;             ///< scenario kind
};

/// Hex SHA-256 of a file's bytes (OpenSSL EVP); InputError when it cannot be read.
[[nodiscard]] std::string sha256_hex(const std::filesystem::path& file);

/// The identity of a campaign of `scenario` with `seed` run by this program.
[[nodiscard]] CampaignIdentity campaign_identity(const std::filesystem::path& scenario,
                                                 std::uint64_t seed, const std::string& kind);

/// Writes it as JSON to `file` (through a temporary name, renamed).
void write_identity(const std::filesystem::path& file, const CampaignIdentity& id);

/// For `--resume` into a folder holding `completed_rows` finished runs: throws InputError naming
/// the first field of `file` that differs from `now` (or that `file` is missing or unreadable
/// while rows exist). Nothing to check when there are no rows.
void check_resume_identity(const std::filesystem::path& file, const CampaignIdentity& now,
                           std::size_t completed_rows);

}  // namespace attiguard::cli
