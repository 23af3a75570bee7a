#pragma once
/// @file jacobians.hpp
/// Jacobians of the SO(3) exponential (dexp) and their inverses (dexpinv).
///
/// Left Jacobian  J_l(w): exp(w + δ) = exp(J_l(w) δ) exp(w) + O(δ²)   (dexp_w of Iserles et al.)
/// Right Jacobian J_r(w): exp(w + δ) = exp(w) exp(J_r(w) δ) + O(δ²),  J_r(w) = J_l(−w) = J_l(w)ᵀ.
/// J_l(w) = I + ((1 − cos θ)/θ²) ŵ + ((θ − sin θ)/θ³) ŵ², and
/// J_l⁻¹(w) = I − ½ ŵ + (1/θ² − (1 + cos θ)/(2θ sin θ)) ŵ², valid for ‖w‖ < 2π.
/// The Runge–Kutta–Munthe-Kaas integrators (integrate/) use J_r⁻¹ for Ṙ = R ω̂ with
/// R = R₀ exp(Ω̂): Ω̇ = J_r⁻¹(Ω) ω. ConReach's exp-atlas dynamics [ConReach eq. (26)] use the same maps.

#include "attiguard/lie/so3.hpp"

namespace attiguard::lie {

/// Left Jacobian of exp, J_l(w) = dexp_w (series for θ < 1e-4).
[[nodiscard]] Mat3 left_jacobian(const Vec3& w) noexcept;
/// Inverse left Jacobian J_l⁻¹(w) = dexpinv_w, for ‖w‖ < 2π (series for θ < 1e-4).
[[nodiscard]] Mat3 left_jacobian_inverse(const Vec3& w) noexcept;
/// Right Jacobian J_r(w) = J_l(−w).
[[nodiscard]] Mat3 right_jacobian(const Vec3& w) noexcept;
/// Inverse right Jacobian J_r⁻¹(w) = J_l⁻¹(−w).
[[nodiscard]] Mat3 right_jacobian_inverse(const Vec3& w) noexcept;

/// J_r⁻¹(w) = I + ½ ŵ + c ŵ² with c of exp_coefficients(w), written out entry by entry: the
/// operations Eigen performs for right_jacobian_inverse's I − ½·hat(−w) + c·(hat(−w)·hat(−w))
/// (evaluated as (c·hat(−w))·hat(−w)) without the products by the zeros, so the result is
/// bit-for-bit right_jacobian_inverse(w) (Munthe-Kaas 1998, BIT 38; docs/performance.md, "Lean core").
[[nodiscard]] inline Mat3 right_jacobian_inverse_of(const Vec3& w, double c) noexcept {
  const double x = w.x();
  const double y = w.y();
  const double z = w.z();
  const double cx = c * x;
  const double cy = c * y;
  const double cz = c * z;
  Mat3 J;
  J(0, 0) = 1.0 + (-(cz * z) - cy * y);
  J(1, 1) = 1.0 + (-(cz * z) - cx * x);
  J(2, 2) = 1.0 + (-(cy * y) - cx * x);
  J(0, 1) = -(0.5 * z) + cy * x;
  J(1, 0) = 0.5 * z + cx * y;
  J(0, 2) = 0.5 * y + cz * x;
  J(2, 0) = -(0.5 * y) + cx * z;
  J(1, 2) = -(0.5 * x) + cz * y;
  J(2, 1) = 0.5 * x + cy * z;
  return J;
}

/// dexp_w(v) = J_l(w) v (Iserles, Munthe-Kaas, Nørsett, Zanna 2000, "Lie-group methods", §2).
[[nodiscard]] inline Vec3 dexp(const Vec3& w, const Vec3& v) noexcept { return left_jacobian(w) * v; }
/// dexpinv_w(v) = J_l⁻¹(w) v.
[[nodiscard]] inline Vec3 dexpinv(const Vec3& w, const Vec3& v) noexcept {
  return left_jacobian_inverse(w) * v;
}

}  // namespace attiguard::lie
