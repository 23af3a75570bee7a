#pragma once
/// @file polynomial_field.hpp
/// The ω-dynamics of a ConReach closed loop written as the polynomial it is (docs/reach.md,
/// "Nominal error bound"): every built-in loop ([ConReach eq. (6)] with the
/// loops of Sec. 6 and [PET-ERG eq. (3)]) has
///   X_ω(R, ω) = c + B ω + (ωᵀ Q_a ω)_{a=1..3} + L vec(R),
/// with vec(R) the 9 entries of R row by row (vec(R)_{3r+s} = R_rs). This exact form is what the
/// Taylor-model bound of the nominal's integration error (nominal_error.hpp) differentiates.

#include <array>
#include <cmath>
#include <optional>
#include <utility>

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

/// The coefficients of a vector field f(R, ω) of the form above, read off by evaluating it:
/// c = f(0, 0); B e_b and Q_b,b from f(0, ±e_b); Q_b,c + Q_c,b from f(0, e_b + e_c); L e_m from
/// f(E_m, 0) with E_m the unit matrix of entry m (f is evaluated as the polynomial it is, also
/// at matrices that are not rotations). Exact for such an f up to rounding; checked at two
/// further points, returning nullopt when f is not of this form.
template <class F>
[[nodiscard]] std::optional<PolynomialField> probe_polynomial_field(const F& f) {
  using lie::Mat3;
  using lie::Vec3;
  PolynomialField p;
  const Mat3 zero = Mat3::Zero();
  p.constant = f(zero, Vec3::Zero());
  std::array<Vec3, 3> plus, minus;
  for (int b = 0; b < 3; ++b) {
    plus[static_cast<std::size_t>(b)] = f(zero, Vec3::Unit(b));
    minus[static_cast<std::size_t>(b)] = f(zero, -Vec3::Unit(b));
    p.linear.col(b) = 0.5 * (plus[static_cast<std::size_t>(b)] - minus[static_cast<std::size_t>(b)]);
    const Vec3 diag = 0.5 * (plus[static_cast<std::size_t>(b)] + minus[static_cast<std::size_t>(b)]) - p.constant;
    for (int a = 0; a < 3; ++a) p.quadratic[static_cast<std::size_t>(a)](b, b) = diag(a);
  }
  for (int b = 0; b < 3; ++b) {
    for (int c = b + 1; c < 3; ++c) {
      // f(e_b + e_c) = c + B(e_b + e_c) + Q_bb + Q_cc + (Q_bc + Q_cb): split evenly.
      const Vec3 both = f(zero, Vec3::Unit(b) + Vec3::Unit(c)) - p.constant - p.linear.col(b) -
                        p.linear.col(c);
      for (int a = 0; a < 3; ++a) {
        const lie::Mat3& Q = p.quadratic[static_cast<std::size_t>(a)];
        const double cross = both(a) - Q(b, b) - Q(c, c);
        p.quadratic[static_cast<std::size_t>(a)](b, c) = 0.5 * cross;
        p.quadratic[static_cast<std::size_t>(a)](c, b) = 0.5 * cross;
      }
    }
  }
  for (int m = 0; m < 9; ++m) {
    Mat3 unit = Mat3::Zero();
    unit(m / 3, m % 3) = 1.0;
    p.linear_R.col(m) = f(unit, Vec3::Zero()) - p.constant;
  }
  // Two checks away from the probe points (a rotation by 1 rad about (2, −1, 3)/√14, ω ≠ 0).
  const Mat3 R1 = lie::exp(Vec3(2.0, -1.0, 3.0) / std::sqrt(14.0));
  for (const auto& [R, w] : {std::pair<Mat3, Vec3>{R1, Vec3(0.3, -0.7, 1.1)},
                             std::pair<Mat3, Vec3>{R1.transpose(), Vec3(-1.9, 0.4, -0.2)}}) {
    const Vec3 want = f(R, w);
    const Vec3 got = p.evaluate(R, w);
    const double scale = 1.0 + want.norm() + p.constant.norm() + p.linear.norm() + p.linear_R.norm() +
                         p.quadratic[0].norm() + p.quadratic[1].norm() + p.quadratic[2].norm();
    if (!want.allFinite() || !((want - got).norm() <= 1e-12 * scale)) return std::nullopt;
  }
  return p;
}

}  // namespace attiguard::reach
