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

/// y ⊕ δ = (R_j exp(δ_j), x + δ_x): the retraction the RKMK methods move along, R_j exp(δ_j) as
/// lie::times_exp with lie::chart_coefficients (docs/performance.md, "Lean core (issue 48, item 2)").
template <int K, int N>
[[nodiscard]] ProductState<K, N> retract(const ProductState<K, N>& y,
                                         const typename ProductState<K, N>::Tangent& delta) noexcept {
  using S = ProductState<K, N>;
  S out;
  for (int j = 0; j < K; ++j) {
    const lie::Vec3 w = S::rot_block(delta, j);
    const auto jj = static_cast<std::size_t>(j);
    if (w.isZero(0.0)) {  // a factor at rest (e.g. a held reference): exp(0) = I
      out.R[jj] = y.R[jj];
      continue;
    }
    const lie::ExpCoefficients k = lie::chart_coefficients(w);
    out.R[jj] = lie::times_exp(y.R[jj], w, k.a, k.b);
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

/// One RKMK stage's chart at Ω: the point y ⊕ Ω (retract) and what dexpinv_body(Ω, ·) needs,
/// Ω_j and the coefficient c of J_r⁻¹(Ω_j); exp and J_r⁻¹ share lie::chart_coefficients
/// (Munthe-Kaas 1998, BIT 38; docs/performance.md, "Lean core (issue 48, item 2)").
template <int K, int N>
struct StageChart {
  ProductState<K, N> point;        ///< y ⊕ Ω
  std::array<lie::Vec3, K> omega;  ///< Ω_j
  std::array<double, K> c;         ///< c(‖Ω_j‖) of J_r⁻¹(Ω_j) = I + ½ Ω̂_j + c Ω̂_j²

  /// dexpinv_body(Ω, ξ): J_r⁻¹(Ω_j) ξ_j on the rotation blocks (lie::apply_right_jacobian_inverse,
  /// two cross products), ξ_x on the Euclidean one (Munthe-Kaas 1998, BIT 38).
  [[nodiscard]] typename ProductState<K, N>::Tangent dexpinv(
      const typename ProductState<K, N>::Tangent& xi) const noexcept {
    using S = ProductState<K, N>;
    typename S::Tangent out;
    for (int j = 0; j < K; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      S::rot_block(out, j) = lie::apply_right_jacobian_inverse(omega[jj], c[jj], S::rot_block(xi, j));
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
    const lie::Vec3 w = S::rot_block(Omega, j);
    const auto jj = static_cast<std::size_t>(j);
    chart.omega[jj] = w;
    if (w.isZero(0.0)) {  // a factor at rest (e.g. a held reference): exp(0) = I, J_r⁻¹(0) = I
      chart.point.R[jj] = y.R[jj];
      chart.c[jj] = 1.0 / 12.0;
      continue;
    }
    const lie::ExpCoefficients k = lie::chart_coefficients(w);
    chart.point.R[jj] = lie::times_exp(y.R[jj], w, k.a, k.b);
    chart.c[jj] = k.c;
  }
  chart.point.x = y.x + S::euclidean_block(Omega);
  return chart;
}

}  // namespace attiguard::integrate
