#pragma once
/// @file retained_file.hpp
/// DIR/retained.h5, the retained time series of a campaign (docs/campaigns.md, "Retained time
/// series"), in HDF5 (libhdf5-dev; read with python3-h5py):
///   /t                 float64 [S]       the sample times t_k = k · retain_interval [s]
///   /series/NAME       float64 [N, S]    column NAME of run k in row k (NaN: not run, or the
///                                        run ended before t_k); chunks of one run, deflated
///   attributes of /: retain_interval, runs, samples, columns (comma-separated)
/// Rows are written as runs finish, so an interrupted campaign keeps the rows of its runs.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace attiguard::campaign {

/// An open retained.h5 for writing.
class RetainedFile {
 public:
  /// Creates `path` (replacing it) for `runs` runs of `times.size()` samples of `columns`, or,
  /// with `keep_existing` (--resume), opens it when its columns and times match (a different
  /// run count: rewritten with the rows of the runs below both counts kept); throws InputError
  /// when they differ or when HDF5 fails.
  RetainedFile(const std::filesystem::path& path, const std::vector<std::string>& columns,
               const std::vector<double>& times, std::size_t runs, double interval,
               bool keep_existing);
  RetainedFile(const RetainedFile&) = delete;
  RetainedFile& operator=(const RetainedFile&) = delete;
  ~RetainedFile();

  /// Writes run k's values (column-major, `samples` per column, at most the file's samples;
  /// fewer leave NaN). Throws InputError on an HDF5 failure.
  void write_run(std::size_t k, std::span<const double> values, std::size_t samples);

 private:
  std::int64_t file_{-1};  ///< hid_t of HDF5 1.10 (int64_t)
  std::vector<std::int64_t> datasets_;
  std::size_t samples_{0};
  std::size_t runs_{0};
  std::filesystem::path path_;
};

/// The contents of a retained.h5 (the viewer and the tests).
struct RetainedSeries {
  std::vector<double> t;
  std::vector<std::string> columns;
  std::size_t runs{0};
  /// values[c][k * t.size() + s]: column c, run k, sample s.
  std::vector<std::vector<double>> values;
};

/// Reads `path`; throws InputError when it is not a retained.h5.
[[nodiscard]] RetainedSeries read_retained(const std::filesystem::path& path);

}  // namespace attiguard::campaign
