#pragma once
/// @file output_records.hpp
/// What an output folder records about the run that wrote it (docs/conventions.md, "Outputs"):
/// the plots it made (DIR/plots.txt, so that the next run in the folder removes them instead of
/// leaving another kind's figures beside its results) and, when it failed, a status file saying
/// that the outputs beside it are partial.

#include <filesystem>
#include <string>
#include <vector>

namespace attiguard::io {

/// Records the PNG files of `written` (their file names) in DIR/plots.txt.
void record_plots(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& written);

/// Removes the plots DIR/plots.txt lists (plain file names only) and the list itself: the figures
/// of an earlier run, before a new run writes its results into DIR.
void remove_recorded_plots(const std::filesystem::path& dir);

/// Writes DIR/NAME.partial, a JSON object {"status": "partial", "kind", "scenario",
/// "exit_code", "error"}: the run that was writing DIR/NAME failed with `error`, and the other
/// NAME.partial files beside it hold what it wrote up to the failure. Never throws (a failure
/// is being reported already).
void write_failure_status(const std::filesystem::path& dir, const std::string& name,
                          const std::string& kind, const std::string& scenario, int exit_code,
                          const std::string& error) noexcept;

/// Writes `text` to DIR/NAME (through NAME.partial, renamed when complete); throws InputError
/// "cannot write FILE: reason" on failure.
void write_text(const std::filesystem::path& dir, const std::string& name, const std::string& text);

}  // namespace attiguard::io
