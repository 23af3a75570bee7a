#pragma once
/// @file torque_quantizer.hpp
/// Torque quantisation of the actuator command (docs/pet-erg.md, section 11): each body
/// component rounded to the nearest multiple of the quantum q (q = 0: no quantisation). The
/// error is at most q/2 per component, ‖τ_q − τ‖ ≤ (√3/2) q. Allocation-free and noexcept.

#include <cmath>

#include "attiguard/lie/so3.hpp"

namespace attiguard::control {

/// τ rounded componentwise to multiples of `quantum` (docs/pet-erg.md, section 11).
[[nodiscard]] inline lie::Vec3 quantize_torque(const lie::Vec3& tau_b, double quantum) noexcept {
  if (!(quantum > 0.0)) return tau_b;
  return lie::Vec3(quantum * std::nearbyint(tau_b(0) / quantum),
                   quantum * std::nearbyint(tau_b(1) / quantum),
                   quantum * std::nearbyint(tau_b(2) / quantum));
}

}  // namespace attiguard::control
