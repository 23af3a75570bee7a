#pragma once
/// @file reaction_wheel_array.hpp
/// N reaction wheels with arbitrary spin axes (docs/pet-erg.md, section 12): wheel i, spin axis
/// a_i (body, unit), exerts the torque u_i a_i on the body (|u_i| ≤ u_max,i) and its spin
/// momentum h_i changes by ḣ_i = −u_i (|h_i| ≤ h_max,i). The body obeys
/// J ω̇ = (Jω + A h) × ω + A u + d, A = [a_1 … a_N]. Fixed capacity, allocation-free.

#include <array>
#include <span>

#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

/// Most wheels of one array.
inline constexpr int kMaxWheels = 8;

/// One wheel (docs/pet-erg.md, section 12).
struct ReactionWheel {
  lie::Vec3 axis_b{lie::Vec3::UnitX()};  ///< unit spin axis a_i in the body frame
  double torque_max{0.1};                ///< u_max,i [N·m]
  double momentum_max{1.0};              ///< h_max,i [N·m·s]
  double momentum0{0.0};                 ///< h_i(0) [N·m·s]
};

/// Per-wheel quantities (first count() entries used).
using WheelVector = std::array<double, kMaxWheels>;

/// The array A, its pseudo-inverse A⁺ = Aᵀ(AAᵀ)⁻¹ and the limits (docs/pet-erg.md, section 12).
class ReactionWheelArray {
 public:
  ReactionWheelArray() = default;
  /// 3 to kMaxWheels wheels whose axes span R³. Throws SetupError otherwise (set-up code only).
  explicit ReactionWheelArray(std::span<const ReactionWheel> wheels);

  [[nodiscard]] int count() const noexcept { return count_; }
  [[nodiscard]] const ReactionWheel& wheel(int i) const noexcept {
    return wheels_[static_cast<std::size_t>(i)];
  }
  /// Row i of A⁺: u = A⁺ τ is the minimum-norm allocation of τ (docs/pet-erg.md, section 12).
  [[nodiscard]] const lie::Vec3& allocation_row(int i) const noexcept {
    return rows_[static_cast<std::size_t>(i)];
  }
  /// Body torque A u of wheel torques u.
  [[nodiscard]] lie::Vec3 body_torque(const WheelVector& u) const noexcept;
  /// Wheel momentum seen by the body, A h.
  [[nodiscard]] lie::Vec3 body_momentum(const WheelVector& h) const noexcept;
  /// u = A⁺ τ, each u_i clipped to ±u_max,i (the actuators' saturation; with the governor's
  /// polytope Γ_d the clip is inactive whenever V ≤ Γ; docs/pet-erg.md, section 12).
  [[nodiscard]] WheelVector allocate(const lie::Vec3& tau_b) const noexcept;

 private:
  std::array<ReactionWheel, kMaxWheels> wheels_{};
  std::array<lie::Vec3, kMaxWheels> rows_{};
  int count_{0};
};

/// A 4-wheel pyramid: axes at elevation `elevation` [rad] above the body x-y plane, azimuths
/// 45°, 135°, 225°, 315° (docs/pet-erg.md, section 12).
[[nodiscard]] std::array<ReactionWheel, 4> pyramid_wheels(double elevation, double torque_max,
                                                          double momentum_max) noexcept;

}  // namespace attiguard::dynamics
