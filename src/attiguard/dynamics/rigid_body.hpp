#pragma once
/// @file rigid_body.hpp
/// Rigid-body attitude plant Ṙ = R ω̂, J ω̇ = (J ω) × ω + τ [PET-ERG eq. (1)].

#include <optional>
#include <string>

#include "attiguard/lie/so3.hpp"

namespace attiguard::dynamics {

using lie::Mat3;
using lie::Vec3;

/// Why J is not a physically valid inertia matrix (not finite, not symmetric to 1e-9 relative,
/// not positive definite, or principal moments violating the triangle inequality
/// J_i + J_j ≥ J_k with a 1e-9 relative tolerance), or nullopt when it is valid.
[[nodiscard]] std::optional<std::string> inertia_error(const Mat3& J);

/// A rigid body with a validated inertia matrix (body frame, about the centre of mass) [kg·m²].
class RigidBody {
 public:
  /// Throws SetupError (an InputError) with inertia_error's message when J is not valid.
  explicit RigidBody(const Mat3& J);

  [[nodiscard]] const Mat3& inertia() const noexcept { return J_; }
  [[nodiscard]] const Mat3& inertia_inverse() const noexcept { return J_inv_; }
  /// Smallest principal moment λ_min(J).
  [[nodiscard]] double min_principal_moment() const noexcept { return lambda_min_; }
  /// Largest principal moment λ_max(J).
  [[nodiscard]] double max_principal_moment() const noexcept { return lambda_max_; }

  /// ω̇ = J⁻¹((J ω) × ω + τ) [PET-ERG eq. (1)]; allocation-free. With J diagonal (principal axes)
  /// the products by its zeros are left out: for finite arguments the same result as the dense
  /// products (docs/performance.md, "Lean core (issue 48, item 2)").
  [[nodiscard]] Vec3 angular_acceleration(const Vec3& omega_b, const Vec3& tau_b) const noexcept {
    if (diagonal_) {
      const Vec3 Jw = J_.diagonal().cwiseProduct(omega_b);
      return J_inv_.diagonal().cwiseProduct(Jw.cross(omega_b) + tau_b);
    }
    return J_inv_ * ((J_ * omega_b).cross(omega_b) + tau_b);
  }
  /// Rotational kinetic energy ½ ωᵀ J ω.
  [[nodiscard]] double kinetic_energy(const Vec3& omega_b) const noexcept {
    return 0.5 * omega_b.dot(J_ * omega_b);
  }
  /// Angular momentum in inertial coordinates, R J ω (conserved when τ = 0).
  [[nodiscard]] Vec3 angular_momentum_i(const Mat3& R_ib, const Vec3& omega_b) const noexcept {
    return R_ib * (J_ * omega_b);
  }

 private:
  Mat3 J_;
  Mat3 J_inv_;
  double lambda_min_{0.0};
  double lambda_max_{0.0};
  bool diagonal_{false};  ///< J and J⁻¹ have exactly zero off-diagonal entries
};

}  // namespace attiguard::dynamics
