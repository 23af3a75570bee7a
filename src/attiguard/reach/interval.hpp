#pragma once
/// @file interval.hpp
/// The small set types ConReach encloses states and matrices with: boxes in R³, interval 3×3
/// matrices and bi-invariant balls on SO(3). Header-only, allocation-free.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "attiguard/lie/so3.hpp"

namespace attiguard::reach {

using lie::Mat3;
using lie::Vec3;

/// Axis-aligned box [lo, hi] ⊂ R³.
struct Box3 {
  Vec3 lo{Vec3::Zero()};
  Vec3 hi{Vec3::Zero()};

  [[nodiscard]] static Box3 around(const Vec3& c, const Vec3& radius) { return {c - radius, c + radius}; }
  [[nodiscard]] Vec3 center() const { return 0.5 * (lo + hi); }
  [[nodiscard]] Vec3 radius() const { return 0.5 * (hi - lo); }
  /// Vertex k ∈ {0..7}: bit j of k selects hi (1) or lo (0) in coordinate j.
  [[nodiscard]] Vec3 vertex(int k) const {
    Vec3 v;
    for (int j = 0; j < 3; ++j) v(j) = ((k >> j) & 1) ? hi(j) : lo(j);
    return v;
  }
  /// max over the box of |ω_j|, per coordinate.
  [[nodiscard]] Vec3 abs_max() const { return lo.cwiseAbs().cwiseMax(hi.cwiseAbs()); }
  /// max over the box of ‖ω‖₂.
  [[nodiscard]] double norm_max() const { return abs_max().norm(); }
  [[nodiscard]] bool contains(const Vec3& x, double tol = 0.0) const {
    return (x.array() >= lo.array() - tol).all() && (x.array() <= hi.array() + tol).all();
  }
  [[nodiscard]] bool contains(const Box3& b, double tol = 0.0) const {
    return contains(b.lo, tol) && contains(b.hi, tol);
  }
  [[nodiscard]] Box3 hull(const Box3& b) const { return {lo.cwiseMin(b.lo), hi.cwiseMax(b.hi)}; }
  [[nodiscard]] Box3 intersect(const Box3& b) const { return {lo.cwiseMax(b.lo), hi.cwiseMin(b.hi)}; }
  [[nodiscard]] Box3 inflated(const Vec3& by) const { return {lo - by, hi + by}; }
  [[nodiscard]] bool finite() const { return lo.allFinite() && hi.allFinite(); }
};

/// Interval 3×3 matrix [lo, hi] (entrywise).
struct IntervalMat3 {
  Mat3 lo{Mat3::Zero()};
  Mat3 hi{Mat3::Zero()};

  [[nodiscard]] static IntervalMat3 point(const Mat3& M) { return {M, M}; }
  [[nodiscard]] static IntervalMat3 around(const Mat3& c, const Mat3& radius) { return {c - radius, c + radius}; }
  [[nodiscard]] Mat3 center() const { return 0.5 * (lo + hi); }
  [[nodiscard]] Mat3 radius() const { return 0.5 * (hi - lo); }
  /// Entrywise max |M_jk| over the interval.
  [[nodiscard]] Mat3 abs_max() const { return lo.cwiseAbs().cwiseMax(hi.cwiseAbs()); }
  [[nodiscard]] bool contains(const Mat3& M, double tol = 0.0) const {
    return (M.array() >= lo.array() - tol).all() && (M.array() <= hi.array() + tol).all();
  }
};

/// Bi-invariant ball {R : d(R, center) ≤ radius} on SO(3), d(R1, R2) = ‖log(R1ᵀR2)‖.
struct AttitudeBall {
  Mat3 center{Mat3::Identity()};
  double radius{0.0};
};

/// ‖I − exp(η̂)‖₂ = 2 sin(‖η‖/2) bound for ‖η‖ ≤ rho (≤ 2 for any rho).
[[nodiscard]] inline double chord(double rho) noexcept {
  return rho >= std::numbers::pi ? 2.0 : 2.0 * std::sin(0.5 * rho);
}

/// An upper bound of 2 sin(ρ/2) for ρ ≥ 0, valid for the real number ρ: sin of the C library is
/// taken as accurate to 1 ulp and widened by 2 ulps, and 2 sin(ρ/2) ≤ ρ is used where it is
/// smaller (docs/reach.md, "Rounding sites").
[[nodiscard]] inline double chord_up(double rho) noexcept {
  // rounding site: chord
  if (rho >= std::numbers::pi) return 2.0;
  const double s = std::nextafter(std::nextafter(std::sin(0.5 * rho), HUGE_VAL), HUGE_VAL);
  return std::min(rho, 2.0 * s);
}

}  // namespace attiguard::reach
