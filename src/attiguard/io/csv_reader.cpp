#include "attiguard/io/csv_reader.hpp"

#include <charconv>
#include <fstream>
#include <limits>

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

}  // namespace

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  return std::nullopt;
}

CsvTable read_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + path.string());
  CsvTable table;
  std::string line;
  long line_no = 0;
  auto fail = [&](const std::string& what) {
    throw InputError(path.string() + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto f = split(line);
    if (table.columns.empty()) {
      for (auto name : f) table.columns.emplace_back(name);
      continue;
    }
    if (f.size() != table.columns.size()) {
      fail(std::to_string(f.size()) + " fields, the header has " +
           std::to_string(table.columns.size()));
    }
    std::vector<double> row(f.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f[i].empty()) continue;
      const auto r = std::from_chars(f[i].data(), f[i].data() + f[i].size(), row[i]);
      if (r.ec != std::errc{} || r.ptr != f[i].data() + f[i].size()) {
        fail("column " + table.columns[i] + ": '" + std::string(f[i]) + "' is not a number");
      }
    }
    table.rows.push_back(std::move(row));
  }
  if (table.columns.empty()) fail("empty file (no header row)");
  return table;
}

}  // namespace attiguard::io
