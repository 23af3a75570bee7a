#pragma once
/// @file retain_plan.hpp
/// Which time series a campaign keeps of every run (docs/campaigns.md, "Retained time series"):
/// `[campaign] retain = ["min_margin", "tau_norm", …]` names trajectory.csv columns of the kind,
/// `retain_interval` the spacing [s] of the kept samples t_k = k · interval.

#include <string>
#include <vector>

namespace attiguard::campaign {

/// The retained columns and their sampling interval; empty columns: nothing retained.
struct RetainPlan {
  std::vector<std::string> columns;
  double interval{1.0};  ///< [s], > 0
  [[nodiscard]] bool enabled() const noexcept { return !columns.empty(); }
};

}  // namespace attiguard::campaign
