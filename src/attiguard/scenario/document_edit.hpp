#pragma once
/// @file document_edit.hpp
/// Reading and replacing one number of a scenario Document by key path, and the document as TOML
/// text (gain search, docs/pet-erg.md section "Tuning": candidates and DIR/best.toml).

#include <optional>
#include <string>
#include <string_view>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// The number at key path `path` ("control.kp"), nullopt when absent or not a number.
[[nodiscard]] std::optional<double> number_at(const Document& doc, std::string_view path);

/// Sets the number at `path`: replaces it, or inserts it when its table exists and the key is
/// absent (e.g. `[control] control_period`), creating a missing top-level table (`[erg]`). Throws InputError naming the path when the table
/// is missing or the key holds a value that is not a number.
void set_number(Document& doc, std::string_view path, double value);

/// The document's tables as scenario-file text (comments and key order of the file are not kept).
[[nodiscard]] std::string document_text(const Document& doc);

/// The file name of a scenario called `stem` ("best" -> "best.toml"): the format's extension is
/// scenario/'s concern (docs/architecture.md, "Layers").
[[nodiscard]] std::string scenario_file_name(std::string_view stem);

}  // namespace attiguard::scenario
