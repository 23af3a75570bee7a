#include "attiguard/campaign/runs_file.hpp"

#include <charconv>
#include <sstream>

#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {

std::map<long, std::string> read_runs(const std::filesystem::path& path, const std::string& header) {
  std::map<long, std::string> rows;
  std::ifstream in(path, std::ios::binary);
  if (!in) return rows;
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (text.empty()) return rows;
  std::size_t pos = 0;
  bool first = true;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // torn last line (interrupted write)
    const std::string line = text.substr(pos, nl - pos);
    pos = nl + 1;
    if (first) {
      if (line != header) {
        throw InputError(path.string() + ": --resume: the header of this runs.csv differs from "
                                         "the campaign's (different scenario or dispersions)");
      }
      first = false;
      continue;
    }
    long index = -1;
    const auto r = std::from_chars(line.data(), line.data() + line.size(), index);
    if (r.ec != std::errc{} || index < 0) continue;
    rows[index] = line;
  }
  return rows;
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
