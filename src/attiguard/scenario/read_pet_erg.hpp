#pragma once
/// @file read_pet_erg.hpp
/// Scenario kind `pet_erg` → sim::PetErgScenario (sim/pet_erg_scenario.hpp). Keys:
/// docs/scenario-format.md, section "pet_erg".

#include "attiguard/scenario/document.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::scenario {


/// Parses and validates a `pet_erg` document (PET-ERG paper, Sec. V and Theorem 1); rejects
/// unknown keys. Besides the types and ranges
/// of every key it rejects, with InputError naming file:line:col and key:
///   - a desired attitude (or schedule waypoint) that violates a cone, or that lies where the
///     repulsive potential is active (a_cᵀR_d a_b < ζ: the reference could not converge to it);
///   - an initial reference outside the field's domain (a_cᵀR_g(0)a_b ≤ δ);
///   - an initial state that is not admissible, V(R_0, ω_0, R_g(0)) > Γ(R_g(0)) (Theorem 1).
[[nodiscard]] sim::PetErgScenario parse_pet_erg(const Document& doc);

/// parse_pet_erg without the three admissibility checks listed above, for `attiguard plan`: the
/// slew planner decides whether the slew is admissible and says why not with exit 4
/// (docs/slew-planner.md, "Failures"); a target near a cone's edge, in the PET-ERG's repulsive
/// band, is one it plans.
[[nodiscard]] sim::PetErgScenario parse_pet_erg_slew(const Document& doc);

}  // namespace attiguard::scenario
