#pragma once
/// @file point_dynamics.hpp
/// The slew's dynamics at one transcription point, with exact first and second derivatives
/// (docs/slew-planner.md, "Derivatives"). The point's variables are z = [q (4), ω (3), u (3)]
/// and f(z) = [½ q ⊗ [0, ω]; J⁻¹(u − ω × Jω)] ([Waypoint eqs. (4)-(5)]; [PET-ERG eq. (1)]),
/// in the planner's scaled units (docs/slew-planner.md, "Scaling"). f is quadratic in z, so its
/// Hessians are constant in z.

#include <Eigen/Core>

#include "attiguard/lie/so3.hpp"

namespace attiguard::plan {

/// z = [q, ω, u] of one point.
using PointVector = Eigen::Matrix<double, 10, 1>;
/// x = [q, ω]: the state part of z, and f(z).
using StateVector = Eigen::Matrix<double, 7, 1>;
/// ∂f/∂z.
using PointJacobian = Eigen::Matrix<double, 7, 10>;
/// ∂²(λᵀf)/∂z² (symmetric).
using PointHessian = Eigen::Matrix<double, 10, 10>;

/// The rigid body's f(z), ∂f/∂z and ∂²(λᵀf)/∂z² for a fixed inertia J (docs/slew-planner.md,
/// "Derivatives").
class PointDynamics {
 public:
  /// J symmetric positive definite (scaled units).
  explicit PointDynamics(const lie::Mat3& J);
  /// f(z) = [½ q ⊗ [0, ω]; J⁻¹(u − ω × Jω)].
  [[nodiscard]] StateVector f(const PointVector& z) const noexcept;
  /// ∂f/∂z, exact.
  [[nodiscard]] PointJacobian jacobian(const PointVector& z) const noexcept;
  /// ∂²(λᵀf)/∂z², exact (independent of z: f is quadratic).
  [[nodiscard]] PointHessian hessian(const StateVector& lambda) const noexcept;

 private:
  lie::Mat3 J_;
  lie::Mat3 J_inv_;
};

}  // namespace attiguard::plan
