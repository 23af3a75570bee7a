#pragma once
/// @file product_state.hpp
/// States on the product manifold SO(3)ᴷ × Rᴺ, with the retraction and local coordinates the
/// Runge–Kutta–Munthe-Kaas integrators work in.
///
/// Tangent vectors are stacked [ξ_1; …; ξ_K; ẋ] with ξ_j the *body* velocity of factor j
/// (Ṙ_j = R_j ξ̂_j, as in [PET-ERG eq. (1)]). The retraction is the group exponential
/// acting on the right: y ⊕ δ = (R_j exp(δ̂_j), x + δ_x); local(y1, y2) = (log(R1ᵀR2), x2 − x1).

#include <Eigen/Core>
#include <array>

#include "attiguard/lie/jacobians.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::integrate {

/// A point of SO(3)ᴷ × Rᴺ (K rotation factors, N Euclidean coordinates).
template <int K, int N>
struct ProductState {
  static_assert(K >= 0 && N >= 0, "ProductState needs non-negative factor counts");
  static constexpr int num_rotations = K;
  static constexpr int num_euclidean = N;
  static constexpr int tangent_dim = 3 * K + N;
  using Tangent = Eigen::Matrix<double, tangent_dim, 1>;
  using Euclidean = Eigen::Matrix<double, N, 1>;

  std::array<lie::Mat3, K> R;  ///< rotation factors (each body → inertial, R_j ∈ SO(3))
  Euclidean x;                 ///< Euclidean factor

  ProductState() {
    R.fill(lie::Mat3::Identity());
    x.setZero();
  }

  /// Rotation block j of a tangent vector.
  static auto rot_block(Tangent& v, int j) { return v.template segment<3>(3 * j); }
  static auto rot_block(const Tangent& v, int j) { return v.template segment<3>(3 * j); }
  /// Euclidean block of a tangent vector.
  static auto euclidean_block(Tangent& v) { return v.template tail<N>(); }
  static auto euclidean_block(const Tangent& v) { return v.template tail<N>(); }

  /// True when every entry of every factor is finite.
  [[nodiscard]] bool all_finite() const noexcept {
    for (const auto& Rj : R) {
      if (!Rj.allFinite()) {
        return false;
      }
    }
    return x.allFinite();
  }
};

/// y ⊕ δ = (R_j exp(δ_j), x + δ_x): the retraction the RKMK methods move along.
template <int K, int N>
[[nodiscard]] ProductState<K, N> retract(const ProductState<K, N>& y,
                                         const typename ProductState<K, N>::Tangent& delta) noexcept {
  using S = ProductState<K, N>;
  S out;
  for (int j = 0; j < K; ++j) {
    out.R[j] = y.R[j] * lie::exp(S::rot_block(delta, j));
  }
  out.x = y.x + S::euclidean_block(delta);
  return out;
}

/// local(y1, y2) = (log(R1ᵀ R2), x2 − x1), the inverse of retract within the injectivity radius.
template <int K, int N>
[[nodiscard]] typename ProductState<K, N>::Tangent local(const ProductState<K, N>& y1,
                                                         const ProductState<K, N>& y2) noexcept {
  using S = ProductState<K, N>;
  typename S::Tangent d;
  for (int j = 0; j < K; ++j) {
    S::rot_block(d, j) = lie::log(y1.R[j].transpose() * y2.R[j]);
  }
  S::euclidean_block(d) = y2.x - y1.x;
  return d;
}

/// Ω̇ = J_r⁻¹(Ω_j) ξ_j on each rotation block and the identity on the Euclidean block: the
/// "dexpinv" of the RKMK method for y(t) = y0 ⊕ Ω(t) (Munthe-Kaas 1998, BIT 38; right
/// trivialisation because our velocities are body velocities).
template <int K, int N>
[[nodiscard]] typename ProductState<K, N>::Tangent dexpinv_body(
    const typename ProductState<K, N>::Tangent& Omega,
    const typename ProductState<K, N>::Tangent& xi) noexcept {
  using S = ProductState<K, N>;
  typename S::Tangent out;
  for (int j = 0; j < K; ++j) {
    S::rot_block(out, j) = lie::right_jacobian_inverse(S::rot_block(Omega, j)) * S::rot_block(xi, j);
  }
  S::euclidean_block(out) = S::euclidean_block(xi);
  return out;
}

/// One RKMK stage's chart at Ω: the point y ⊕ Ω and the rotation blocks' J_r⁻¹(Ω_j) of
/// dexpinv_body, from one sin and one cos per factor (exp and J_r⁻¹ share θ = ‖Ω_j‖). Bit-for-bit
/// retract(y, Ω) and dexpinv_body(Ω, ·) (Munthe-Kaas 1998, BIT 38; docs/performance.md, "Lean core").
template <int K, int N>
struct StageChart {
  ProductState<K, N> point;            ///< y ⊕ Ω
  std::array<lie::Mat3, K> jr_inverse;  ///< J_r⁻¹(Ω_j)

  /// dexpinv_body(Ω, ξ): J_r⁻¹(Ω_j) ξ_j on the rotation blocks, ξ_x on the Euclidean one.
  [[nodiscard]] typename ProductState<K, N>::Tangent dexpinv(
      const typename ProductState<K, N>::Tangent& xi) const noexcept {
    using S = ProductState<K, N>;
    typename S::Tangent out;
    for (int j = 0; j < K; ++j) {
      S::rot_block(out, j) = jr_inverse[static_cast<std::size_t>(j)] * S::rot_block(xi, j);
    }
    S::euclidean_block(out) = S::euclidean_block(xi);
    return out;
  }
};

/// The chart of an RKMK stage at Ω from y (StageChart; Munthe-Kaas 1998, BIT 38).
template <int K, int N>
[[nodiscard]] StageChart<K, N> stage_chart(const ProductState<K, N>& y,
                                           const typename ProductState<K, N>::Tangent& Omega) noexcept {
  using S = ProductState<K, N>;
  StageChart<K, N> chart;
  for (int j = 0; j < K; ++j) {
    const auto Omega_j = S::rot_block(Omega, j);
    const lie::Vec3 w = Omega_j;
    const lie::ExpCoefficients k = lie::exp_coefficients(w);
    const auto jj = static_cast<std::size_t>(j);
    chart.point.R[jj] = y.R[jj] * lie::rodrigues(w, k.a, k.b);
    chart.jr_inverse[jj] = lie::right_jacobian_inverse_of(w, k.c);
  }
  chart.point.x = y.x + S::euclidean_block(Omega);
  return chart;
}

}  // namespace attiguard::integrate
