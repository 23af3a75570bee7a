#pragma once
/// @file retain_keys.hpp
/// The `[campaign]` keys `retain` (array of trajectory column names) and `retain_interval` [s]
/// (docs/campaigns.md, "Retained time series"). Includes the table reader: scenario/ only.

#include "attiguard/campaign/retain_plan.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

/// Reads `retain` and `retain_interval` of the `[campaign]` table `campaign` of `doc` (both
/// optional; retain must be a non-empty array of distinct non-empty strings, the interval
/// positive). Throws InputError located at the key.
[[nodiscard]] campaign::RetainPlan read_retain(const TableReader& campaign, const Document& doc);

}  // namespace attiguard::scenario
