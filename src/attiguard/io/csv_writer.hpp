#pragma once
/// @file csv_writer.hpp
/// Streaming CSV writer for time series: a header row, then rows of numbers written in the
/// shortest form that reads back to the same double (std::to_chars), so outputs are exact and
/// byte-reproducible.

#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "attiguard/io/partial_file.hpp"

namespace attiguard::io {

/// Writes `path` with the given column names (docs/conventions.md, "Outputs"): into
/// PATH.partial, renamed to PATH by close(), so that an interrupted or failed run never leaves a
/// truncated PATH that looks complete.
class CsvWriter {
 public:
  /// Removes an existing PATH and creates PATH.partial; throws InputError "cannot write FILE:
  /// reason" on failure.
  CsvWriter(const std::filesystem::path& path, std::vector<std::string> columns);

  /// Appends one row; values.size() must equal the number of columns (else std::logic_error).
  void row(std::span<const double> values);

  /// Number of data rows written so far.
  [[nodiscard]] long rows() const noexcept { return rows_; }
  [[nodiscard]] const std::vector<std::string>& columns() const noexcept { return columns_; }

  /// Flushes, closes and renames PATH.partial to PATH (once; later calls do nothing); throws
  /// InputError if the data could not be written.
  void close();

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  std::string line_;
  long rows_{0};
};

}  // namespace attiguard::io
