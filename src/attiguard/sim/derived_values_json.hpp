#pragma once
/// @file derived_values_json.hpp
/// The PET-ERG's parameters derived from the craft (docs/pet-erg.md, section 8) as summary.json
/// records them (`derived_defaults`) and as `attiguard check` prints them: the one definition of
/// their keys and their text.

#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/governor/default_gains.hpp"

namespace attiguard::sim {

/// `derived_defaults` of summary.json (docs/pet-erg.md, section 8): which of kp, kd, kappa,
/// sampling_period, c_gamma were derived, and the scales they come from (torque_scale,
/// reference_angle_deg, time_scale, rate_scale, natural_frequency, damping_ratio,
/// gamma_d_estimate, bandwidth_period, damping_period, limited_by_control_period).
[[nodiscard]] nlohmann::json derived_values_json(const governor::DerivedGovernorValues& d);

/// The lines `attiguard check` prints for a pet_erg scenario (docs/pet-erg.md, section 8): each
/// value with "(derived)" or "(given)", then the scales.
[[nodiscard]] std::string derived_values_report(const governor::DerivedGovernorValues& d);

}  // namespace attiguard::sim
