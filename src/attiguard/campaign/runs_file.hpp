#pragma once
/// @file runs_file.hpp
/// runs.csv on disk: rows appended (and flushed) as runs finish, read back by --resume, and
/// rewritten sorted by run index when the campaign ends.

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace attiguard::campaign {

/// A runs.csv as read back: its header's column names and its rows keyed by run index.
struct RunsTable {
  std::vector<std::string> columns;
  std::map<long, std::string> rows;  ///< run index → its line (no newline)
};

/// Reads an existing runs.csv strictly (docs/campaigns.md, "Interruption and resume";
/// docs/errors.md, "Strict readers"), for --resume, --replay and `attiguard view`: every
/// complete line after the header must be a row attiguard writes (the header's number of
/// fields; run and attempts whole numbers, run >= 0, attempts >= 1; seed a whole number below
/// 2^64; status ok, rejected or failed; violation 0 or 1 in an ok row, empty otherwise; reason
/// and outcome text; every other field empty or a finite number; no run index twice), else
/// InputError "PATH:LINE: …" naming the column. A torn last line (no newline: an interrupted
/// append) is dropped. A file larger than io::kMaxResultFileBytes is an InputError. An absent
/// or empty file: no columns, no rows.
[[nodiscard]] RunsTable read_runs_table(const std::filesystem::path& path);

/// read_runs_table(path).rows; throws InputError when the file's header differs from
/// `header` (another scenario or other dispersions).
[[nodiscard]] std::map<long, std::string> read_runs(const std::filesystem::path& path,
                                                    const std::string& header);

/// Appends rows to runs.csv, writing the header first when the file is new or empty.
class RunsAppender {
 public:
  RunsAppender(const std::filesystem::path& path, const std::string& header);
  /// Appends one line and flushes it to the OS.
  void append(const std::string& line);

 private:
  std::ofstream out_;
};

/// Writes header + rows (in index order) to `path` atomically (temporary file and rename).
void write_sorted(const std::filesystem::path& path, const std::string& header,
                  const std::map<long, std::string>& rows);

}  // namespace attiguard::campaign
