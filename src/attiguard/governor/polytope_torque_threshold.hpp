#pragma once
/// @file polytope_torque_threshold.hpp
/// Γ_d for a torque polytope P = {τ : |r_iᵀ τ| ≤ u_i, i = 1..m} instead of the 2-norm ball of the
/// PET-ERG paper's (2a) (docs/pet-erg.md, section 12), e.g. the body torques a reaction-wheel
/// array reaches with pseudo-inverse allocation (r_i the rows of A⁺, u_i the wheel limits).
///
/// Exact reduction: the saturating states are the union over i of the slab exits
/// |r_iᵀ(k_p s − k_d ω)| ≥ u_i, so Γ_d(P) = min_i Γ_d,i. For one slab with n = r_i/‖r_i‖ and
/// τ_i = u_i/‖r_i‖: max over the axis k of |nᵀ(k_p sin θ k − k_d ω)| = k_p sin θ + k_d |nᵀω|
/// (k = ±n), and min ½ωᵀJω subject to |nᵀω| ≥ ρ is ½ρ²/(nᵀJ⁻¹n) (Cauchy–Schwarz in the J⁻¹
/// metric, attained at ω ∝ J⁻¹n). Γ_d,i is therefore the ball threshold of torque_threshold.hpp
/// with λ_min(J) replaced by 1/(nᵀJ⁻¹n) and τ_max by τ_i: the same certified lower bound.

#include <span>

#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// Γ_d of the polytope {|r_iᵀτ| ≤ u_i} (docs/pet-erg.md, section 12): the minimum over the slabs
/// of compute_torque_threshold with λ = 1/(n_iᵀJ⁻¹n_i), τ = u_i/‖r_i‖; `slab` receives the index
/// of the binding slab. Throws SetupError for empty or mismatched inputs, a zero row or a
/// non-positive limit (set-up code only).
[[nodiscard]] TorqueThreshold compute_polytope_torque_threshold(double kp, double kd,
                                                                const lie::Mat3& J,
                                                                std::span<const lie::Vec3> rows,
                                                                std::span<const double> limits,
                                                                int* slab = nullptr);

}  // namespace attiguard::governor
