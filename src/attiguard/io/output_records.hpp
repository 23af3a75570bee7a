#pragma once
/// @file output_records.hpp
/// What an output folder records about the run that wrote it (docs/conventions.md, "Outputs"):
/// the plots it made (DIR/plots.txt, so that the next run in the folder removes them instead of
/// leaving another kind's figures beside its results) and, when it failed, a status file saying
/// that the outputs beside it are partial.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace attiguard::io {

/// Records the PNG files of `written` (their file names) in DIR/plots.txt.
void record_plots(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& written);

/// Removes the plots DIR/plots.txt lists (plain file names only) and the list itself: the figures
/// of an earlier run, before a new run writes its results into DIR.
void remove_recorded_plots(const std::filesystem::path& dir);

/// Writes DIR/NAME.partial, a JSON object {"status": "partial", "kind", "scenario",
/// "exit_code", "error"[, "result"]}: the run that was writing DIR/NAME failed with `error`, and
/// the other NAME.partial files beside it hold what it wrote up to the failure; `kind` "" is
/// written as null (an input refused before its kind was known); `result`, when not null, is the
/// NAME the command had completed before it failed (app/output_folder.hpp). Never throws (a
/// failure is being reported already).
void write_failure_status(const std::filesystem::path& dir, const std::string& name,
                          const std::string& kind, const std::string& scenario, int exit_code,
                          const std::string& error,
                          const nlohmann::json& result = nullptr) noexcept;

/// Writes `text` to DIR/NAME (through NAME.partial, renamed when complete); throws InputError
/// "cannot write FILE: reason" on failure.
void write_text(const std::filesystem::path& dir, const std::string& name, const std::string& text);

}  // namespace attiguard::io
