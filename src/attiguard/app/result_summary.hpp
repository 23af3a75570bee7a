#pragma once
/// @file result_summary.hpp
/// The one reader of a run's DIR/summary.json for `attiguard view` and `export-aem`
/// (docs/errors.md, "Strict readers"): the strict JSON reader (io/json_reader.hpp), then the
/// keys both rely on.

#include <filesystem>

#include <nlohmann/json.hpp>

namespace attiguard::app {

/// DIR/summary.json of `attiguard run` (or `campaign --replay K`): a JSON object whose "kind" is
/// the name of a kind that `attiguard run` runs (kinds() but reach) and whose "name", when
/// present, is a string. Throws InputError "FILE: …" naming the key otherwise (and for every
/// refusal of io::read_json_object).
[[nodiscard]] nlohmann::json read_run_summary(const std::filesystem::path& path);

}  // namespace attiguard::app
