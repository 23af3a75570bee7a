#include "attiguard/campaign/runs_file.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <system_error>

#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_reader.hpp"

namespace attiguard::campaign {

namespace {

/// Digits only, as a non-negative whole number of type T; nullopt otherwise.
template <class T>
std::optional<T> whole_number(std::string_view text) {
  T value{};
  if (text.empty() || text.size() > 20) return std::nullopt;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || text.front() == '-') return std::nullopt;
  return value;
}

/// At most 40 characters of a field for a message.
std::string shown(std::string_view field) {
  return field.size() <= 40 ? std::string(field) : std::string(field.substr(0, 40)) + "...";
}

/// Why `f` (the fields of one row) is not a row attiguard writes under `columns`, "" when it is.
std::string row_problem(const std::vector<std::string>& columns, const std::vector<std::string>& f) {
  if (f.size() != columns.size()) {
    return std::to_string(f.size()) + " fields, the header has " + std::to_string(columns.size());
  }
  const auto at = [&](std::size_t i, const std::string& what) {
    return "column " + columns[i] + ": '" + shown(f[i]) + "' " + what;
  };
  std::string status;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == "status") status = f[i];
  }
  if (status != "ok" && status != "rejected" && status != "failed") {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == "status") return at(i, "is not a status (ok, rejected or failed)");
    }
    return "no status column";
  }
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const std::string& name = columns[i];
    const std::string& v = f[i];
    if (name == "status" || name == "reason" || name == "outcome") continue;
    if (name == "run") {
      if (!whole_number<long>(v)) return at(i, "is not a run index (a whole number >= 0)");
    } else if (name == "seed") {
      if (!whole_number<std::uint64_t>(v)) return at(i, "is not a seed (a whole number from 0 to 2^64 - 1)");
    } else if (name == "attempts") {
      const auto n = whole_number<long>(v);
      if (!n || *n < 1) return at(i, "is not a number of attempts (a whole number >= 1)");
    } else if (name == "violation") {
      if (status == "ok" ? v != "0" && v != "1" : !v.empty()) {
        return at(i, status == "ok" ? "is not 0 or 1" : "must be empty in a row of status " + status);
      }
    } else if (!v.empty()) {
      double x = 0.0;
      const auto r = std::from_chars(v.data(), v.data() + v.size(), x);
      if (r.ec != std::errc{} || r.ptr != v.data() + v.size()) return at(i, "is not a number");
      if (!std::isfinite(x)) return at(i, "is not a finite number");
    }
  }
  return "";
}

}  // namespace

RunsTable read_runs_table(const std::filesystem::path& path) {
  RunsTable table;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return table;
  io::check_file_size(path, io::kMaxResultFileBytes, "a campaign that large is not read back");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::map<long, long> line_of;  // run index → line number
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (in.eof()) break;  // torn last line (interrupted write): no newline after it
    const auto fail = [&](const std::string& what) {
      throw InputError(path.string() + ":" + std::to_string(line_no) + ": " + what +
                       " (not a row attiguard writes: delete the line, and --resume runs that run again)");
    };
    if (line_no == 1) {
      table.columns = csv_split(line);
      if (table.columns.empty() || table.columns.front() != "run") {
        throw InputError(path.string() + ":1: not the header of a runs.csv (its first column is 'run')");
      }
      continue;
    }
    const std::vector<std::string> f = csv_split(line);
    if (const std::string why = row_problem(table.columns, f); !why.empty()) fail(why);
    const long index = *whole_number<long>(f.front());
    if (const auto [it, fresh] = line_of.emplace(index, line_no); !fresh) {
      fail("run " + std::to_string(index) + " again (its row is line " + std::to_string(it->second) + ")");
    }
    table.rows.emplace(index, std::move(line));
  }
  return table;
}

std::map<long, std::string> read_runs(const std::filesystem::path& path, const std::string& header) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {};
  // The header first: another campaign's runs.csv is refused as such, not row by row.
  {
    std::ifstream in(path, std::ios::binary);
    std::string first;
    if (std::getline(in, first) && !in.eof() && first != header) {
      throw InputError(path.string() + ": --resume: the header of this runs.csv differs from "
                                       "the campaign's (different scenario or dispersions)");
    }
  }
  return read_runs_table(path).rows;
}

RunsAppender::RunsAppender(const std::filesystem::path& path, const std::string& header) {
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
  out_.open(path, std::ios::binary | std::ios::app);
  if (!out_) throw InputError(path.string() + ": cannot write runs.csv");
  if (fresh) {
    out_ << header << '\n';
    out_.flush();
  }
}

void RunsAppender::append(const std::string& line) {
  out_ << line << '\n';
  out_.flush();
}

void write_sorted(const std::filesystem::path& path, const std::string& header,
                  const std::map<long, std::string>& rows) {
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(tmp.string() + ": cannot write");
    out << header << '\n';
    for (const auto& [index, line] : rows) out << line << '\n';
    if (!out) throw InputError(tmp.string() + ": write failed");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace attiguard::campaign
