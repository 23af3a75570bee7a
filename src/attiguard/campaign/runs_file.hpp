#pragma once
/// @file runs_file.hpp
/// runs.csv on disk: rows appended (and flushed) as runs finish, read back by --resume, and
/// rewritten sorted by run index when the campaign ends.

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace attiguard::campaign {

/// Complete rows of an existing runs.csv keyed by run index (a torn last line is dropped).
/// Throws InputError when its header differs from `header`. Empty map when there is no file.
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
