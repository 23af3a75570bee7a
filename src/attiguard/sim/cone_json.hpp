#pragma once
/// @file cone_json.hpp
/// A pointing cone as the summaries of kinds pet_erg and mission report it (docs/pet-erg.md,
/// docs/mission.md): the one definition of the keys axis_b, direction_i and theta_c_deg.

#include <nlohmann/json.hpp>

#include "attiguard/governor/cone_constraint.hpp"

namespace attiguard::sim {

/// The cone c_i(R) = a_cᵀ R a_b ≥ cos θ_c [PET-ERG eq. (2b)] as a JSON object: `axis_b` (a_b),
/// `direction_i` (a_c) and `theta_c_deg` (θ_c in degrees).
[[nodiscard]] nlohmann::json cone_json(const governor::ConeConstraint& c);

}  // namespace attiguard::sim
