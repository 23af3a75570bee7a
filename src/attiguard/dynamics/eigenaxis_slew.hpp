#pragma once
/// @file eigenaxis_slew.hpp
/// The time-optimal reference for a slew (docs/pet-erg.md, "Outcomes"): a rest-to-rest
/// eigenaxis rotation by θ about the fixed body axis k with bang-bang torque at the limit. With
/// τ = α J k (the gyroscopic term ω × Jω neglected: exact for a principal axis, where it
/// vanishes) the largest angular acceleration is α = τ_max / ‖J k‖, and accelerating over half
/// the angle then decelerating takes T = 2 √(θ / α) = 2 √(θ ‖J k‖ / τ_max).

#include <cmath>

#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

/// T = 2 √(θ ‖J k‖ / τ_max) of the rest-to-rest eigenaxis bang-bang slew from R_from to R_to
/// (k, θ from log(R_fromᵀ R_to); docs/pet-erg.md, "Outcomes"). 0 when R_from = R_to.
[[nodiscard]] inline double eigenaxis_bang_bang_time(const lie::Mat3& J, const lie::Mat3& R_from,
                                                     const lie::Mat3& R_to,
                                                     double tau_max) noexcept {
  const lie::Vec3 rotation_b = lie::log(R_from.transpose() * R_to);
  const double theta = rotation_b.norm();
  if (!(theta > 0.0)) return 0.0;
  const double inertia_along_axis = (J * (rotation_b / theta)).norm();
  return 2.0 * std::sqrt(theta * inertia_along_axis / tau_max);
}

}  // namespace attiguard::dynamics
