#include "attiguard/io/csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <system_error>

#include "attiguard/core/errors.hpp"

namespace attiguard::io {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                      : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

/// At most 40 characters of a field for a message.
std::string shown(std::string_view field) {
  return field.size() <= 40 ? std::string(field) : std::string(field.substr(0, 40)) + "...";
}

/// Reads the next non-empty line (without "\r"); false at the end.
bool next_line(std::ifstream& in, std::string& text, long& line_no) {
  while (std::getline(in, text)) {
    ++line_no;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (!text.empty()) return true;
  }
  return false;
}

}  // namespace

void check_file_size(const std::filesystem::path& path, std::uintmax_t limit,
                     std::string_view hint) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec || bytes <= limit) return;  // not a regular file: opening it says why
  char text[160];
  std::snprintf(text, sizeof text, "%ju bytes (%.0f MiB) is more than the limit %.0f MiB of a result file that attiguard reads",
                bytes, static_cast<double>(bytes) / 1048576.0, static_cast<double>(limit) / 1048576.0);
  throw InputError(path.string() + ": " + text + " (" + std::string(hint) + ")");
}

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  return std::nullopt;
}

CsvStream::CsvStream(const std::filesystem::path& path) : path_(path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": cannot read (not a regular file)");
  check_file_size(path, kMaxResultFileBytes,
                  "a trajectory that long: write fewer rows with a larger output_interval");
  in_.open(path, std::ios::binary);
  if (!in_) throw InputError("cannot read " + path.string());
  if (!next_line(in_, text_, line_)) fail("empty file (no header row)");
  for (std::string_view name : split(text_)) {
    if (name.empty()) fail("the header has an empty column name");
    for (const std::string& c : columns_) {
      if (c == name) fail("the header names column '" + shown(name) + "' twice");
    }
    columns_.emplace_back(name);
  }
}

void CsvStream::fail(const std::string& what) const {
  throw InputError(path_.string() + ":" + std::to_string(line_) + ": " + what);
}

bool CsvStream::next(std::vector<double>& row) {
  if (!next_line(in_, text_, line_)) return false;
  const auto f = split(text_);
  if (f.size() != columns_.size()) {
    fail(std::to_string(f.size()) + " fields, the header has " + std::to_string(columns_.size()));
  }
  row.assign(f.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].empty()) continue;
    const auto r = std::from_chars(f[i].data(), f[i].data() + f[i].size(), row[i]);
    if (r.ec != std::errc{} || r.ptr != f[i].data() + f[i].size()) {
      fail("column " + columns_[i] + ": '" + shown(f[i]) + "' is not a number");
    }
    if (!std::isfinite(row[i])) fail("column " + columns_[i] + ": '" + shown(f[i]) + "' is not a finite number");
  }
  return true;
}

CsvTable read_csv(const std::filesystem::path& path) {
  CsvStream stream(path);
  CsvTable table;
  table.columns = stream.columns();
  std::vector<double> row;
  while (stream.next(row)) table.rows.push_back(row);
  return table;
}

}  // namespace attiguard::io
