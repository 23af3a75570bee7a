#include "attiguard/io/csv_writer.hpp"

#include <cstring>
#include <stdexcept>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/shortest_number.hpp"

namespace attiguard::io {

CsvWriter::CsvWriter(const std::filesystem::path& path, std::vector<std::string> columns)
    : path_(path), columns_(std::move(columns)) {
  // An earlier complete file of that name goes first, so that a run that stops before close()
  // leaves only PATH.partial, never an old PATH that looks like its result.
  std::error_code ec;
  std::filesystem::remove(path, ec);
  out_.open(partial_path(path), std::ios::binary | std::ios::trunc);
  if (!out_) {
    throw InputError("cannot write " + path.string() + ": " + std::strerror(errno));
  }
  line_.reserve(32 * columns_.size());
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    out_ << (i ? "," : "") << columns_[i];
  }
  out_ << '\n';
}

void CsvWriter::row(std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::logic_error("CsvWriter::row: " + std::to_string(values.size()) + " values for " +
                           std::to_string(columns_.size()) + " columns in " + path_.string());
  }
  line_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) {
      line_.push_back(',');
    }
    append_shortest(line_, values[i]);
  }
  line_.push_back('\n');
  out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
  ++rows_;
}

void CsvWriter::close() {
  if (!out_.is_open()) return;
  out_.flush();
  if (!out_) {
    throw InputError("cannot write " + path_.string() + ": write failed (disk full?)");
  }
  out_.close();
  commit_partial(path_);
}

}  // namespace attiguard::io
