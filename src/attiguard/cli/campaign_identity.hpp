#pragma once
/// @file campaign_identity.hpp
/// The identity of a campaign run by this program (app/campaign_identity.hpp, docs/campaigns.md
/// "Interruption and resume"): the SHA-256 of the scenario file's bytes is taken here, with
/// OpenSSL, which only the program links.

#include <cstdint>
#include <filesystem>
#include <string>

#include "attiguard/app/campaign_identity.hpp"

namespace attiguard::cli {

/// Hex SHA-256 of a file's bytes (OpenSSL EVP); InputError when it cannot be read.
[[nodiscard]] std::string sha256_hex(const std::filesystem::path& file);

/// The identity of a campaign of `scenario` with `seed` run by this program.
[[nodiscard]] app::CampaignIdentity campaign_identity(const std::filesystem::path& scenario,
                                                      std::uint64_t seed, const std::string& kind);

}  // namespace attiguard::cli
