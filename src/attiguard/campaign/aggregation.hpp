#pragma once
/// @file aggregation.hpp
/// campaign.json from the rows of runs.csv: counts, violations, failures and percentiles of
/// every summary figure over the runs that completed (status ok).

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

}  // namespace attiguard::campaign
