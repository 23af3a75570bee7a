#pragma once
/// @file torque_slabs.hpp
/// The torques a reaction-wheel array applies without clipping, within a declared norm bound
/// (docs/pet-erg.md, section 16.3, "Wheels"): P = {τ : ‖τ‖ ≤ τ_max, |r_iᵀ τ| ≤ u_i}, r_i the rows
/// of the pseudo-inverse allocation A⁺ and u_i the wheel torque limits (the set that
/// dynamics::ReactionWheelArray::allocate leaves unclipped). Its gauge measures a torque against
/// P; the inflated gauge a torque plus any error of a given norm. Fixed capacity, allocation-free
/// (the flight loop saturates with it).

#include <array>

#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/slew_plan.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// P = {‖τ‖ ≤ ball, |r_iᵀ τ| ≤ u_i, i < count} (docs/pet-erg.md, section 16.3, "Wheels"); with
/// count = 0 the ball alone.
struct TorqueSlabs {
  double ball{1.0};                                   ///< τ_max [N·m], > 0
  int count{0};                                       ///< slabs used (≤ dynamics::kMaxWheels)
  std::array<lie::Vec3, dynamics::kMaxWheels> rows{};  ///< r_i: wheel torque per body torque (rows of A⁺)
  std::array<double, dynamics::kMaxWheels> limits{};   ///< u_i [N·m], > 0

  /// The gauge max(‖τ‖/τ_max, max_i |r_iᵀτ|/u_i): τ ∈ P iff ≤ 1, and τ/gauge lies on P's boundary.
  [[nodiscard]] double gauge(const lie::Vec3& tau_b) const noexcept;

  /// The largest gauge of τ + δ over ‖δ‖ ≤ e: max((‖τ‖ + e)/τ_max, max_i (|r_iᵀτ| + ‖r_i‖ e)/u_i)
  /// (exact: each term is the support of the ball in the row's direction).
  [[nodiscard]] double inflated_gauge(const lie::Vec3& tau_b, double e) const noexcept;

  /// The largest torque of P along d: 1/gauge(d/‖d‖) [N·m] (d ≠ 0).
  [[nodiscard]] double torque_along(const lie::Vec3& d_b) const noexcept { return 1.0 / gauge(d_b.normalized()); }

  /// The largest inflated gauge of ṡ² τ_p(σ) + δ over the plan and ‖δ‖ ≤ e: the plan's torque is
  /// linear between a node, its midpoint and the next node and the gauge is convex, so its
  /// largest value is at one of those points, exactly (docs/pet-erg.md, section 16.3, "Wheels").
  [[nodiscard]] double plan_gauge(const SlewPlan& plan, double rate_squared, double e) const noexcept;
};

/// The slabs of `array` within the ball τ_max (docs/pet-erg.md, section 16.3, "Wheels").
[[nodiscard]] TorqueSlabs wheel_torque_slabs(const dynamics::ReactionWheelArray& array, double tau_max) noexcept;

}  // namespace attiguard::governor
