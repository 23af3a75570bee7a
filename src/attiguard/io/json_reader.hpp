#pragma once
/// @file json_reader.hpp
/// Reads a result JSON file back (summary.json, reach.json, campaign.json, tune.json; docs/errors.md,
/// "Strict readers"): at most kMaxResultJsonBytes, valid JSON, a JSON object.

#include <cstdint>
#include <filesystem>

#include <nlohmann/json.hpp>

namespace attiguard::io {

/// The largest result JSON file attiguard reads back: 64 MiB (summaries are kilobytes).
inline constexpr std::uintmax_t kMaxResultJsonBytes = std::uintmax_t{64} << 20;

/// The JSON object in `path`; throws InputError "FILE: …" when it cannot be read, is larger than
/// kMaxResultJsonBytes, is not valid JSON (with the byte of the parse error) or is not an object
/// ("expected a JSON object, got an array").
[[nodiscard]] nlohmann::json read_json_object(const std::filesystem::path& path);

}  // namespace attiguard::io
