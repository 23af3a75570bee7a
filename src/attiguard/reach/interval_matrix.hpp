#pragma once
/// @file interval_matrix.hpp
/// Small interval matrices over the outward-rounded Interval of scalar_interval.hpp, and the
/// upward-rounded norms ConReach's rounding sites bound with (docs/reach.md, "Rounding sites").
/// Every result contains the exact result of the operation on any reals in the operands.

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>

#include "attiguard/reach/interval.hpp"
#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

template <int N>
using IMat = std::array<std::array<Interval, N>, N>;
using IMat3 = IMat<3>;
using IVec3 = std::array<Interval, 3>;

/// The point interval matrix of a floating-point matrix (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] IMat<N> point(const Eigen::Matrix<double, N, N>& M) {
  IMat<N> out;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) out[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = M(i, j);
  }
  return out;
}

/// Enclosure of A·B (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] IMat<N> product(const IMat<N>& A, const IMat<N>& B) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) {
      Interval s(0.0);
      for (std::size_t k = 0; k < N; ++k) s += A[i][k] * B[k][j];
      out[i][j] = s;
    }
  }
  return out;
}

/// Aᵀ (exact; docs/reach.md, "Rounding sites")
template <int N>
[[nodiscard]] IMat<N> transposed(const IMat<N>& A) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = A[j][i];
  }
  return out;
}

/// Enclosure of A + sign·B, sign = ±1 (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] IMat<N> add(const IMat<N>& A, const IMat<N>& B, double sign = 1.0) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = sign > 0 ? A[i][j] + B[i][j] : A[i][j] - B[i][j];
  }
  return out;
}

/// Enclosure of s·A (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] IMat<N> scaled(const Interval& s, const IMat<N>& A) {
  IMat<N> out;
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) out[i][j] = s * A[i][j];
  }
  return out;
}

/// An upper bound of √x for x ≥ 0 (sqrt is correctly rounded, IEEE 754; docs/reach.md, "Rounding sites").
[[nodiscard]] inline double sqrt_up(double x) { return Interval::up(std::sqrt(x)); }
/// A lower bound of √x for x ≥ 0 (docs/reach.md, "Rounding sites").
[[nodiscard]] inline double sqrt_down(double x) { return x > 0.0 ? Interval::down(std::sqrt(x)) : 0.0; }

/// Upper bound of the Frobenius norm of every matrix in A (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] double frobenius_up(const IMat<N>& A) {
  Interval s(0.0);
  for (const auto& row : A) {
    for (const Interval& x : row) s += Interval(x.mag()) * Interval(x.mag());
  }
  return sqrt_up(s.hi);
}

/// Upper bound of the induced ∞-norm (max row sum of |·|) of every matrix in A (docs/reach.md, "Rounding sites").
template <int N>
[[nodiscard]] double inf_norm_up(const IMat<N>& A) {
  double worst = 0.0;
  for (const auto& row : A) {
    Interval s(0.0);
    for (const Interval& x : row) s += Interval(x.mag());
    worst = std::max(worst, s.hi);
  }
  return worst;
}

/// Entrywise max |x| over the interval matrix (exact; docs/reach.md, "Rounding sites").
[[nodiscard]] inline Mat3 magnitudes(const IMat3& A) {
  Mat3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) out(static_cast<int>(i), static_cast<int>(j)) = A[i][j].mag();
  }
  return out;
}

/// Entrywise upper bound of |x − c| over x ∈ A: the radius of A about the point matrix c
/// (docs/reach.md, "Rounding sites").
[[nodiscard]] inline Mat3 radius_about(const IMat3& A, const Mat3& c) {
  Mat3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      const double cij = c(static_cast<int>(i), static_cast<int>(j));
      out(static_cast<int>(i), static_cast<int>(j)) = (A[i][j] - Interval(cij)).mag();
    }
  }
  return out;
}

/// IntervalMat3 ↔ IMat3 (exact; docs/reach.md, "Rounding sites").
[[nodiscard]] inline IMat3 to_imat(const IntervalMat3& M) {
  IMat3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      out[i][j] = Interval(M.lo(static_cast<int>(i), static_cast<int>(j)), M.hi(static_cast<int>(i), static_cast<int>(j)));
    }
  }
  return out;
}
[[nodiscard]] inline IntervalMat3 to_interval_mat(const IMat3& M) {
  IntervalMat3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      out.lo(static_cast<int>(i), static_cast<int>(j)) = M[i][j].lo;
      out.hi(static_cast<int>(i), static_cast<int>(j)) = M[i][j].hi;
    }
  }
  return out;
}

/// The hat matrix of an interval vector (exact: entries are ±v_k; docs/reach.md, "Rounding sites").
[[nodiscard]] inline IMat3 hat(const IVec3& v) {
  const Interval z(0.0);
  return {{{z, -v[2], v[1]}, {v[2], z, -v[0]}, {-v[1], v[0], z}}};
}

/// Enclosure of A·v (docs/reach.md, "Rounding sites").
[[nodiscard]] inline IVec3 mat_vec(const IMat3& A, const IVec3& v) {
  IVec3 out;
  for (std::size_t i = 0; i < 3; ++i) {
    Interval s(0.0);
    for (std::size_t k = 0; k < 3; ++k) s += A[i][k] * v[k];
    out[i] = s;
  }
  return out;
}

/// Enclosure of u·v (docs/reach.md, "Rounding sites").
[[nodiscard]] inline Interval dot(const IVec3& u, const IVec3& v) {
  Interval s(0.0);
  for (std::size_t k = 0; k < 3; ++k) s += u[k] * v[k];
  return s;
}

/// The point interval vector of a floating-point vector (docs/reach.md, "Rounding sites").
[[nodiscard]] inline IVec3 point(const Vec3& v) { return {Interval(v(0)), Interval(v(1)), Interval(v(2))}; }

/// Upper bound of ‖AᵀA − I‖_F over A: the orthogonality defect of a matrix meant to be a rotation
/// (docs/reach.md, "Rounding sites"). A's polar factor U satisfies ‖A − U‖_F ≤ this and
/// ‖A‖₂ ≤ 1 + this.
[[nodiscard]] inline double orthogonality_defect_up(const IMat3& A) {
  IMat3 G = product<3>(transposed<3>(A), A);
  for (std::size_t i = 0; i < 3; ++i) G[i][i] = G[i][i] - Interval(1.0);
  return frobenius_up<3>(G);
}

}  // namespace attiguard::reach
