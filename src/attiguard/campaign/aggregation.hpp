#pragma once
/// @file aggregation.hpp
/// campaign.json from the rows of runs.csv: counts, violations, failures, the count of each
/// `outcome` value (kinds whose summary has one), and percentiles of every summary figure over
/// the runs that completed (status ok) and have it, with the count they are over.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace attiguard::campaign {

/// Context written at the top of campaign.json.
struct CampaignInfo {
  std::string scenario;
  std::string kind;
  unsigned long long seed{0};
  long runs{0};          ///< runs requested
  long max_attempts{1};
  std::vector<std::string> dispersed;  ///< dispersion key paths
};

/// Nearest-rank percentile (p in [0, 100]) of sorted values.
[[nodiscard]] double percentile(const std::vector<double>& sorted, double p);

/// Aggregates runs.csv rows (`header` its first line split, `rows` keyed by run index).
/// Deterministic: the same rows give the same JSON text whatever the order they ran in.
[[nodiscard]] nlohmann::json aggregate(const CampaignInfo& info,
                                       const std::vector<std::string>& header,
                                       const std::map<long, std::string>& rows);

/// "2 converged, 38 stalled" from campaign.json's `outcomes` object (name → count), in its
/// (sorted) order; "none" when empty.
[[nodiscard]] std::string outcome_counts_text(const nlohmann::json& outcomes);

}  // namespace attiguard::campaign
