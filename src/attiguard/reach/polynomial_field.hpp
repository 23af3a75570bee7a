#pragma once
/// @file polynomial_field.hpp
/// The ω-dynamics of a ConReach closed loop written as the polynomial it is (docs/reach.md,
/// "Nominal error bound"): every built-in loop (contraction-reachability paper, eq. (6) with the
/// loops of Sec. 6 and PET-ERG eq. (3)) has
///   X_ω(R, ω) = c + B ω + (ωᵀ Q_a ω)_{a=1..3} + L vec(R),
/// with vec(R) the 9 entries of R row by row (vec(R)_{3r+s} = R_rs). This exact form is what the
/// Taylor-model bound of the nominal's integration error (nominal_error.hpp) differentiates.

#include <array>

#include <Eigen/Core>

#include "attiguard/lie/so3.hpp"

namespace attiguard::reach {

/// X_ω(R, ω) = constant + linear ω + quadratic ω + linear_R vec(R) (see file comment).
struct PolynomialField {
  lie::Vec3 constant{lie::Vec3::Zero()};
  lie::Mat3 linear{lie::Mat3::Zero()};               ///< B: coefficient of ω
  std::array<lie::Mat3, 3> quadratic{lie::Mat3::Zero(), lie::Mat3::Zero(), lie::Mat3::Zero()};
  Eigen::Matrix<double, 3, 9> linear_R{Eigen::Matrix<double, 3, 9>::Zero()};

  /// X_ω(R, ω) from the coefficients (for checks against the loop's own omega_dot).
  [[nodiscard]] lie::Vec3 evaluate(const lie::Mat3& R, const lie::Vec3& omega) const {
    lie::Vec3 out = constant + linear * omega;
    for (int a = 0; a < 3; ++a) out(a) += omega.dot(quadratic[static_cast<std::size_t>(a)] * omega);
    Eigen::Matrix<double, 9, 1> v;
    for (int r = 0; r < 3; ++r) {
      for (int s = 0; s < 3; ++s) v(3 * r + s) = R(r, s);
    }
    return out + linear_R * v;
  }
};

/// The quadratic part −J⁻¹(ω × Jω) of Euler's equation as coefficients Q_a (Q_a(b, c) is the
/// coefficient of ω_b ω_c in component a).
[[nodiscard]] inline std::array<lie::Mat3, 3> gyroscopic_quadratic(const lie::Mat3& J, const lie::Mat3& Jinv) {
  std::array<lie::Mat3, 3> Q{lie::Mat3::Zero(), lie::Mat3::Zero(), lie::Mat3::Zero()};
  for (int b = 0; b < 3; ++b) {
    for (int c = 0; c < 3; ++c) {
      const lie::Vec3 v = -Jinv * lie::Vec3::Unit(b).cross(J * lie::Vec3::Unit(c));
      for (int a = 0; a < 3; ++a) Q[static_cast<std::size_t>(a)](b, c) = v(a);
    }
  }
  return Q;
}

}  // namespace attiguard::reach
