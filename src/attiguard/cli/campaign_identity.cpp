#include "attiguard/cli/campaign_identity.hpp"

#include <openssl/evp.h>

#include <array>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

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

CampaignIdentity campaign_identity(const std::filesystem::path& scenario, std::uint64_t seed,
                                   const std::string& kind) {
  return {sha256_hex(scenario), seed, version_string, kind};
}

void write_identity(const std::filesystem::path& file, const CampaignIdentity& id) {
  const nlohmann::json j = {{"scenario_sha256", id.scenario_sha256},
                            {"seed", id.seed},
                            {"attiguard_version", id.version},
                            {"kind", id.kind}};
  const std::filesystem::path tmp = file.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << j.dump(2) << '\n';
    if (!out) throw InputError(tmp.string() + ": cannot write");
  }
  std::filesystem::rename(tmp, file);
}

void check_resume_identity(const std::filesystem::path& file, const CampaignIdentity& now,
                           std::size_t completed_rows) {
  if (completed_rows == 0) return;
  const std::string where = file.string() + ": --resume: ";
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(where + "missing, so the " + std::to_string(completed_rows) +
                     " rows of runs.csv beside it cannot be matched to this scenario and seed; "
                     "start a new campaign (without --resume) or use another --out");
  }
  nlohmann::json j;
  try {
    std::stringstream text;
    text << in.rdbuf();
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + "not a campaign identity (unreadable JSON)");
  }
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

}  // namespace attiguard::cli
