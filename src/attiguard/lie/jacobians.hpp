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

/// J_r⁻¹(w) v = v + ½ w × v + c w × (w × v) with c of chart_coefficients(w) (lie/so3.hpp): the
/// dexpinv of the RKMK stages as two cross products, no 3×3 matrix (Munthe-Kaas 1998, BIT 38;
/// docs/performance.md, "Lean core (issue 48, item 2)").
[[nodiscard]] inline Vec3 apply_right_jacobian_inverse(const Vec3& w, double c, const Vec3& v) noexcept {
  const Vec3 u = w.cross(v);
  return v + (0.5 * u + c * w.cross(u));
}

/// dexp_w(v) = J_l(w) v (Iserles, Munthe-Kaas, Nørsett, Zanna 2000, "Lie-group methods", §2).
[[nodiscard]] inline Vec3 dexp(const Vec3& w, const Vec3& v) noexcept { return left_jacobian(w) * v; }
/// dexpinv_w(v) = J_l⁻¹(w) v.
[[nodiscard]] inline Vec3 dexpinv(const Vec3& w, const Vec3& v) noexcept {
  return left_jacobian_inverse(w) * v;
}

}  // namespace attiguard::lie
