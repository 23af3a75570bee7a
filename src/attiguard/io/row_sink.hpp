#pragma once
/// @file row_sink.hpp
/// Where a simulator's time series go (docs/architecture.md, "Data flow"): a simulator announces
/// its column names once, then emits one row of numbers per output instant. The CLI writes them
/// to DIR/trajectory.csv (CsvRowSink), campaign runs drop them (NullRowSink), the Python bindings
/// fill numpy arrays (python/src/bind_run.cpp).

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "attiguard/io/csv_writer.hpp"

namespace attiguard::io {

/// Receives a time series: begin() once with the column names, then row() per output instant,
/// then end(). rows() counts the rows received.
class RowSink {
 public:
  RowSink() = default;
  RowSink(const RowSink&) = delete;
  RowSink& operator=(const RowSink&) = delete;
  virtual ~RowSink() = default;

  /// The column names (called once, before any row).
  virtual void begin(const std::vector<std::string>& columns) = 0;
  /// One row, values.size() equal to the number of columns.
  virtual void row(std::span<const double> values) = 0;
  /// After the last row (flushes files; throws InputError when they could not be written).
  virtual void end() {}

  /// False for a sink that drops rows: a simulator may then skip computing them.
  [[nodiscard]] virtual bool wants_rows() const noexcept { return true; }
};

/// Drops every row (campaign runs need the summary only).
class NullRowSink final : public RowSink {
 public:
  void begin(const std::vector<std::string>&) override {}
  void row(std::span<const double>) override {}
  [[nodiscard]] bool wants_rows() const noexcept override { return false; }
};

/// Writes the rows to a CSV file (io::CsvWriter: shortest round-trip numbers).
class CsvRowSink final : public RowSink {
 public:
  /// The file is created by begin(); throws InputError there when it cannot be.
  explicit CsvRowSink(std::filesystem::path path) : path_(std::move(path)) {}
  void begin(const std::vector<std::string>& columns) override { csv_.emplace(path_, columns); }
  void row(std::span<const double> values) override { csv_->row(values); }
  void end() override {
    if (csv_) csv_->close();
  }
  /// Data rows written.
  [[nodiscard]] long rows() const noexcept { return csv_ ? csv_->rows() : 0; }

 private:
  std::filesystem::path path_;
  std::optional<CsvWriter> csv_;
};

/// Sends each call to two sinks (Python's run() with an output directory: CSV and numpy).
class TeeRowSink final : public RowSink {
 public:
  TeeRowSink(RowSink& a, RowSink& b) : a_(a), b_(b) {}
  void begin(const std::vector<std::string>& columns) override {
    a_.begin(columns);
    b_.begin(columns);
  }
  void row(std::span<const double> values) override {
    a_.row(values);
    b_.row(values);
  }
  void end() override {
    a_.end();
    b_.end();
  }

 private:
  RowSink& a_;
  RowSink& b_;
};

}  // namespace attiguard::io
