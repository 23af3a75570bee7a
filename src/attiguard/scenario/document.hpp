#pragma once
/// @file document.hpp
/// A parsed scenario file: its path (for error messages) and its TOML table.

#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>
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

/// A scenario given as a JSON-like value (the Python bindings' dicts, docs/python.md) with the
/// structure of a scenario file: objects are tables, arrays of objects arrays of tables, other
/// arrays arrays, and numbers, booleans and strings values. `path` is used in messages only
/// ("<dict>"); the values are then validated by the same readers as a file's. Throws InputError
/// naming the key path of a null value.
[[nodiscard]] Document document_from_json(const nlohmann::json& value,
                                          const std::filesystem::path& path);

/// The scenario kind: the required top-level string `kind` (e.g. "rigid_body").
[[nodiscard]] std::string scenario_kind(const Document& doc);

}  // namespace attiguard::scenario
