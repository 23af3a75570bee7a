#pragma once
/// @file document.hpp
/// A parsed scenario file: its path (for error messages) and its TOML table.

#include <filesystem>
#include <string>

#include <toml++/toml.h>

namespace attiguard::scenario {

/// A scenario file parsed with toml++ (docs/scenario-format.md).
struct Document {
  std::filesystem::path path;  ///< as given by the user; quoted in every error message
  toml::table root;
};

/// Reads and parses a TOML scenario file.
/// Throws InputError "FILE:LINE:COL: TOML syntax error: …" on a parse error and
/// "FILE: cannot read scenario file (…)" when the file cannot be opened.
[[nodiscard]] Document load_document(const std::filesystem::path& path);

/// Parses TOML text held in memory (tests, Python bindings); `path` is used in messages only.
[[nodiscard]] Document parse_document(std::string_view text, const std::filesystem::path& path);

/// The scenario kind: the required top-level string `kind` (e.g. "rigid_body").
[[nodiscard]] std::string scenario_kind(const Document& doc);

}  // namespace attiguard::scenario
