#include "attiguard/plan/point_dynamics.hpp"

#include <Eigen/LU>

namespace attiguard::plan {

using lie::hat;
using lie::Mat3;
using lie::Vec3;

PointDynamics::PointDynamics(const Mat3& J) : J_(J), J_inv_(J.inverse()) {}

StateVector PointDynamics::f(const PointVector& z) const noexcept {
  const double eta = z(0);
  const Vec3 eps = z.segment<3>(1);
  const Vec3 omega = z.segment<3>(4);
  const Vec3 u = z.segment<3>(7);
  StateVector out;
  out(0) = -0.5 * eps.dot(omega);
  out.segment<3>(1) = 0.5 * (eta * omega + eps.cross(omega));
  out.segment<3>(4) = J_inv_ * (u - omega.cross(J_ * omega));
  return out;
}

PointJacobian PointDynamics::jacobian(const PointVector& z) const noexcept {
  const double eta = z(0);
  const Vec3 eps = z.segment<3>(1);
  const Vec3 omega = z.segment<3>(4);
  PointJacobian F = PointJacobian::Zero();
  // q̇ = ½ [−εᵀω; ηω + ε × ω]
  F.block<3, 1>(1, 0) = 0.5 * omega;                      // ∂/∂η
  F.block<1, 3>(0, 1) = -0.5 * omega.transpose();         // ∂q̇₀/∂ε
  F.block<3, 3>(1, 1) = -0.5 * hat(omega);                // ∂(ε × ω)/∂ε = −[ω]×
  F.block<1, 3>(0, 4) = -0.5 * eps.transpose();           // ∂q̇₀/∂ω
  F.block<3, 3>(1, 4) = 0.5 * (eta * Mat3::Identity() + hat(eps));
  // ω̇ = J⁻¹(u − ω × Jω): ∂/∂ω = J⁻¹([Jω]× − [ω]× J), ∂/∂u = J⁻¹
  F.block<3, 3>(4, 4) = J_inv_ * (hat(J_ * omega) - hat(omega) * J_);
  F.block<3, 3>(4, 7) = J_inv_;
  return F;
}

PointHessian PointDynamics::hessian(const StateVector& lambda) const noexcept {
  PointHessian H = PointHessian::Zero();
  const double l0 = lambda(0);
  const Vec3 lv = lambda.segment<3>(1);
  // λ_qᵀq̇ is bilinear in (q, ω): ∂²/∂η∂ω = ½ λ_v, ∂²/∂ε∂ω = −½(λ₀ I + [λ_v]×).
  Eigen::Matrix<double, 4, 3> q_omega;
  q_omega.row(0) = 0.5 * lv.transpose();
  q_omega.bottomRows<3>() = -0.5 * (l0 * Mat3::Identity() + hat(lv));
  H.block<4, 3>(0, 4) = q_omega;
  H.block<3, 4>(4, 0) = q_omega.transpose();
  // λ_ωᵀJ⁻¹(−ω × Jω) = −ωᵀ J [ν]× ω with ν = J⁻¹λ_ω: Hessian −(J[ν]× − [ν]× J).
  const Vec3 nu = J_inv_ * lambda.segment<3>(4);
  H.block<3, 3>(4, 4) = -(J_ * hat(nu) - hat(nu) * J_);
  return H;
}

}  // namespace attiguard::plan
