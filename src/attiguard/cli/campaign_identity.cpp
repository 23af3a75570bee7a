/// @file campaign_identity.cpp
/// The SHA-256 of a scenario file and the identity of a campaign (cli/campaign_identity.hpp).

#include "attiguard/cli/campaign_identity.hpp"

#include <openssl/evp.h>

#include <array>
#include <fstream>
#include <memory>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/version.hpp"

namespace attiguard::cli {

std::string sha256_hex(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot read the scenario file to hash it");
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw NumericalError("SHA-256: OpenSSL digest initialisation failed");
  }
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize n = in.gcount();
    if (n > 0 && EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<std::size_t>(n)) != 1) {
      throw NumericalError("SHA-256: OpenSSL digest update failed");
    }
  }
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest.data(), &length) != 1) {
    throw NumericalError("SHA-256: OpenSSL digest finalisation failed");
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    hex += kHex[digest[i] >> 4];
    hex += kHex[digest[i] & 0xF];
  }
  return hex;
}

app::CampaignIdentity campaign_identity(const std::filesystem::path& scenario, std::uint64_t seed,
                                        const std::string& kind) {
  return {sha256_hex(scenario), seed, version_string, kind};
}

}  // namespace attiguard::cli
