#pragma once
/// @file csv_reader.hpp
/// Reads a numeric CSV file as written by csv_writer.hpp (a header row of column names, then
/// rows of numbers; an empty field is NaN): DIR/trajectory.csv for the AEM export and the
/// viewer, the CSV files of reach (docs/interop.md, docs/viewer.md). One strict reader for all
/// of them (docs/errors.md, "Strict readers"): a row with another number of fields than the
/// header, a field that is not a finite number ("nan", "inf", "abc", "1e999"), a header with an
/// empty or repeated name, or a file larger than kMaxResultFileBytes is an InputError naming
/// the file and the line.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace attiguard::io {

/// The largest result file (CSV) attiguard reads back: 512 MiB. Longer trajectories are
/// written (--max-output-rows) but not read back by view, export-aem or --resume.
inline constexpr std::uintmax_t kMaxResultFileBytes = std::uintmax_t{512} << 20;

/// Throws InputError "FILE: N bytes (M MiB) is more than the limit L MiB of a result file that
/// attiguard reads (…)" when `path` is larger than `limit` bytes; `hint` ends the message.
void check_file_size(const std::filesystem::path& path, std::uintmax_t limit,
                     std::string_view hint);

/// The columns and rows of a CSV file.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of the column `name`, nullopt when absent.
  [[nodiscard]] std::optional<std::size_t> column(std::string_view name) const;
};

/// Reads a numeric CSV file row by row in constant memory, with the checks of the file
/// comment. The constructor reads the header.
class CsvStream {
 public:
  /// Opens `path` and reads its header; throws InputError "FILE: …" when it is missing, too
  /// large, empty or its header is bad.
  explicit CsvStream(const std::filesystem::path& path);
  [[nodiscard]] const std::vector<std::string>& columns() const noexcept { return columns_; }
  /// Reads the next data row into `row` (NaN for an empty field); false at the end of the
  /// file. Throws InputError "FILE:LINE: …" for a bad row.
  bool next(std::vector<double>& row);
  /// The line number of the row last read (1: the header).
  [[nodiscard]] long line() const noexcept { return line_; }

 private:
  [[noreturn]] void fail(const std::string& what) const;
  std::filesystem::path path_;
  std::ifstream in_;
  std::string text_;
  std::vector<std::string> columns_;
  long line_{0};
};

/// Reads `path` whole (CsvStream); throws InputError "FILE:LINE: what" when it cannot be read,
/// is too large, a row has another number of fields than the header or a field is not a finite
/// number.
[[nodiscard]] CsvTable read_csv(const std::filesystem::path& path);

}  // namespace attiguard::io
