#pragma once
/// @file envelopes.hpp
/// Percentile envelopes of a campaign's retained time series (docs/campaigns.md, "Retained time
/// series"): at each sample time t_k, the min, 1 %, 50 %, 99 % percentiles and max over the
/// runs that have a finite value there (nearest-rank percentiles, campaign::percentile), the
/// count of those runs, and the worst runs.

#include <cstddef>
#include <string>
#include <vector>

#include "attiguard/campaign/retained_file.hpp"

namespace attiguard::campaign {

/// The envelope of one retained column.
struct Envelope {
  std::string column;
  std::vector<double> min, p1, p50, p99, max;  ///< per sample; NaN where no run has a value
  std::vector<double> count;                   ///< runs with a finite value at each sample
  /// The worst runs, worst first: for a column whose name contains "margin" the lowest
  /// minimum over time, otherwise the highest maximum.
  std::vector<std::size_t> worst;
};

/// The envelope of column `c` of `series` with the `worst_count` worst runs.
[[nodiscard]] Envelope envelope(const RetainedSeries& series, std::size_t c, std::size_t worst_count = 3);

/// Writes /envelopes/NAME (float64 [6, S]: min, p1, p50, p99, max, count) and /worst/NAME
/// (int64 run indices) of every column into the retained file `path`; throws InputError.
void write_envelopes(const std::filesystem::path& path, const std::vector<Envelope>& envelopes);

}  // namespace attiguard::campaign
