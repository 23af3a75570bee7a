#pragma once
/// @file json_file.hpp
/// Writing run summaries (docs/conventions.md, "Outputs").

#include <filesystem>

#include <nlohmann/json.hpp>

namespace attiguard::io {

/// Writes `value` as pretty-printed JSON (2-space indent, trailing newline).
/// Non-finite numbers are written as null by nlohmann-json; callers keep summaries finite.
/// Throws InputError "cannot write FILE: reason" on failure.
void write_json(const std::filesystem::path& path, const nlohmann::json& value);

/// Creates `dir` (and parents) if missing; throws InputError naming it on failure.
void ensure_directory(const std::filesystem::path& dir);

}  // namespace attiguard::io
