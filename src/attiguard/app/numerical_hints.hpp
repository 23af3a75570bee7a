#pragma once
/// @file numerical_hints.hpp
/// The key most likely responsible for a numerical failure (a diverging run) of a scenario, per
/// kind (docs/errors.md, "Numerical failures"): the kind registry (app/kinds.hpp) holds each
/// kind's hint, app::numerical_failure_hint (app/failure.hpp) looks it up.

#include <string>

#include "attiguard/scenario/document.hpp"

namespace attiguard::app {

/// Kind rigid_body: a fixed rkmk4 step above the stability limit ≈ 2/λ_max of the body under the
/// PD law [PET-ERG eq. (3)] (λ_max: the fastest root of J_i s² + k_d s + k_p over the principal
/// moments J_i, and the gyroscopic rate |ω0| |J_j − J_k|/J_i; no gains for the other laws),
/// located at simulation.step; "" when the step is below it. Throws what parse_rigid_body throws.
[[nodiscard]] std::string rigid_body_numerical_hint(const scenario::Document& doc);

/// Kind pet_erg: an erg.kappa that turns the reference by more than 1 rad per integrator step
/// (κ Γ_d h > 1, the reference dynamics [PET-ERG eq. (6)]), located at erg.kappa; else the step
/// hint of rigid_body_numerical_hint with the PD gains [PET-ERG eq. (3)]; "" when neither.
/// Throws what parse_pet_erg throws.
[[nodiscard]] std::string pet_erg_numerical_hint(const scenario::Document& doc);

}  // namespace attiguard::app
