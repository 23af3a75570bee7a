#pragma once
/// @file read_reach.hpp
/// Scenario kind `reach` → reach::ReachScenario (reach/reach_scenario.hpp), analysed with
/// `attiguard reach SCENARIO --out DIR`. Keys: docs/scenario-format.md, section "reach".

#include "attiguard/reach/reach_scenario.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Parses and validates a `reach` document (ConReach paper, Algorithm 1 inputs); rejects unknown
/// keys. Throws InputError.
[[nodiscard]] reach::ReachScenario parse_reach(const Document& doc);

}  // namespace attiguard::scenario
