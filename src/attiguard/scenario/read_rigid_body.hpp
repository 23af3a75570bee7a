#pragma once
/// @file read_rigid_body.hpp
/// Scenario kind `rigid_body` → sim::RigidBodyScenario (sim/rigid_body_scenario.hpp). Keys:
/// docs/scenario-format.md, section "rigid_body".

#include "attiguard/scenario/document.hpp"
#include "attiguard/sim/rigid_body_scenario.hpp"

namespace attiguard::scenario {

/// Parses and validates a `rigid_body` document ([PET-ERG eq. (1)] and PD law [PET-ERG eq. (3)]);
/// rejects unknown keys. Throws InputError.
[[nodiscard]] sim::RigidBodyScenario parse_rigid_body(const Document& doc);

}  // namespace attiguard::scenario
