#pragma once
/// @file reach_scenario.hpp
/// Scenario kind `reach`: ConReach reachability and safety verification
/// (`attiguard reach SCENARIO.toml --out DIR`). Keys: docs/scenario-format.md, section "reach".

#include <memory>
#include <string>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/soundness.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Everything a `reach` run needs, validated.
struct ReachScenario {
  std::string name;
  std::shared_ptr<const reach::ClosedLoop> loop;  ///< [system]
  std::string model;                              ///< [system] model
  reach::InitialSet initial;                      ///< [initial]
  reach::ConReachSettings settings;               ///< [reach]
  int attitude_cells{1};                          ///< [partition] attitude_cells (per axis)
  int omega_cells{1};                             ///< [partition] omega_cells (per axis)
  int threads{0};                                 ///< [partition] threads (0: all cores)
  reach::SoundnessSettings soundness;             ///< [soundness]
  reach::SafetySpec safety;                       ///< [safety]
  int boundary_points{200};                       ///< [output] boundary_points
};

/// Parses and validates a `reach` document; rejects unknown keys. Throws InputError.
[[nodiscard]] ReachScenario parse_reach(const Document& doc);

}  // namespace attiguard::scenario
