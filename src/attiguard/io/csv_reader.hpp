#pragma once
/// @file csv_reader.hpp
/// Reads a numeric CSV file as written by csv_writer.hpp (a header row of column names, then
/// rows of numbers; an empty field is NaN): DIR/trajectory.csv for the AEM export and the
/// viewer (docs/interop.md, docs/viewer.md).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace attiguard::io {

/// The columns and rows of a CSV file.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of the column `name`, nullopt when absent.
  [[nodiscard]] std::optional<std::size_t> column(std::string_view name) const;
};

/// Reads `path`; throws InputError "FILE:LINE: what" when it cannot be read, a row has another
/// number of fields than the header or a field is not a number.
[[nodiscard]] CsvTable read_csv(const std::filesystem::path& path);

}  // namespace attiguard::io
