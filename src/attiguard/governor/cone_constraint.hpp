#pragma once
/// @file cone_constraint.hpp
/// Geometric pointing constraint a_cᵀ R a_b ≥ cos θ_c [PET-ERG eq. (2b)], keep-in and
/// keep-out forms, and the fixed-capacity set of them the governor holds.
///
/// Everything here is allocation-free and noexcept except the validation helper.

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

using lie::Mat3;
using lie::Vec3;

/// Most cone constraints one governor holds (storage is a std::array, never the heap).
inline constexpr int kMaxCones = 16;

/// One pointing constraint [PET-ERG eq. (2b)]: the body axis a_b (unit, body frame) must
/// stay within the angle θ_c of the inertial direction a_c (unit, inertial frame), i.e.
/// c(R) := a_cᵀ R a_b ≥ cos θ_c. A keep-out cone of half-angle α around s is a_c = −s,
/// θ_c = π − α (beyond the paper: docs/pet-erg.md, "Beyond the paper").
///
/// The repulsive part of the navigation field (docs/pet-erg.md, "Repulsive potential") is active
/// for δ < c < ζ and diverges as c → δ⁺, with cos θ_c < δ < ζ (paper Sec. V:
/// δ = cos θ_c + 0.05, ζ = δ + 0.05).
struct ConeConstraint {
  Vec3 axis_b{0.0, 0.0, 1.0};       ///< a_b, unit body axis
  Vec3 direction_i{0.0, 0.0, 1.0};  ///< a_c, unit inertial direction
  double theta_c{std::numbers::pi};  ///< θ_c ∈ (0, π] [rad]
  double cos_theta_c{-1.0};          ///< cos θ_c
  double sin_theta_c{0.0};           ///< sin θ_c ≥ 0
  double delta{-0.95};               ///< δ: the repulsive potential diverges as c → δ⁺
  double zeta{-0.9};                 ///< ζ: the repulsive potential vanishes for c ≥ ζ
  double repulsive_gain{1.0};        ///< k_r of P_r = k_r (ζ − c)²/(c − δ)
};

/// Keep-in cone of half-angle θ_c around a_c, constraint [PET-ERG eq. (2b)], with the
/// repulsive levels δ = cos θ_c + delta_offset and ζ = δ + zeta_offset (paper Sec. V uses 0.05
/// for both). Axes are normalised here.
[[nodiscard]] inline ConeConstraint keep_in_cone(const Vec3& axis_b, const Vec3& direction_i,
                                                 double theta_c, double delta_offset = 0.05,
                                                 double zeta_offset = 0.05,
                                                 double repulsive_gain = 1.0) noexcept {
  ConeConstraint c;
  c.axis_b = axis_b.normalized();
  c.direction_i = direction_i.normalized();
  c.theta_c = theta_c;
  c.cos_theta_c = std::cos(theta_c);
  c.sin_theta_c = std::abs(std::sin(theta_c));
  c.delta = c.cos_theta_c + delta_offset;
  c.zeta = c.delta + zeta_offset;
  c.repulsive_gain = repulsive_gain;
  return c;
}

/// Keep-out cone of half-angle α around the inertial direction s: [PET-ERG eq. (2b)] with
/// a_c = −s and θ_c = π − α (docs/pet-erg.md, "Beyond the paper").
[[nodiscard]] inline ConeConstraint keep_out_cone(const Vec3& axis_b, const Vec3& avoid_i,
                                                  double alpha, double delta_offset = 0.05,
                                                  double zeta_offset = 0.05,
                                                  double repulsive_gain = 1.0) noexcept {
  return keep_in_cone(axis_b, -avoid_i, std::numbers::pi - alpha, delta_offset, zeta_offset,
                      repulsive_gain);
}

/// c(R) = a_cᵀ R a_b, the cosine of the angle between the body axis in inertial coordinates and
/// a_c ([PET-ERG eq. (2b)]; docs/errata.md, PET-ERG 1a).
[[nodiscard]] inline double cone_cosine(const ConeConstraint& cone, const Mat3& R_ib) noexcept {
  return cone.direction_i.dot(R_ib * cone.axis_b);
}

/// Margin of constraint [PET-ERG eq. (2b)]: a_cᵀ R a_b − cos θ_c (≥ 0 when satisfied).
[[nodiscard]] inline double pointing_margin(const ConeConstraint& cone, const Mat3& R_ib) noexcept {
  return cone_cosine(cone, R_ib) - cone.cos_theta_c;
}

/// Why a cone is not usable by the governor (axes not unit/finite, θ_c ∉ (0, π],
/// not cos θ_c < δ < ζ, δ ≥ 1, k_r ≤ 0), or nullopt. Set-up code only (allocates).
[[nodiscard]] inline std::optional<std::string> cone_error(const ConeConstraint& cone) {
  if (!cone.axis_b.allFinite() || std::abs(cone.axis_b.norm() - 1.0) > 1e-9) {
    return "the body axis a_b must be a finite unit vector";
  }
  if (!cone.direction_i.allFinite() || std::abs(cone.direction_i.norm() - 1.0) > 1e-9) {
    return "the inertial direction a_c must be a finite unit vector";
  }
  if (!(cone.theta_c > 0.0 && cone.theta_c <= std::numbers::pi)) {
    return "the cone angle theta_c must lie in (0, pi]";
  }
  if (!(cone.delta > cone.cos_theta_c)) {
    return "delta must exceed cos(theta_c) (delta_offset > 0)";
  }
  if (!(cone.zeta > cone.delta)) {
    return "zeta must exceed delta (zeta_offset > 0)";
  }
  if (!(cone.delta < 1.0)) {
    return "delta = cos(theta_c) + delta_offset must be < 1 (the cone leaves no room for the "
           "reference)";
  }
  if (!(cone.repulsive_gain > 0.0) || !std::isfinite(cone.repulsive_gain)) {
    return "the repulsive gain must be positive and finite";
  }
  return std::nullopt;
}

/// A fixed-capacity list of cone constraints (no heap; at most kMaxCones). Used by the flight
/// governor ([PET-ERG eq. (2b)], several constraints: docs/pet-erg.md, "Beyond the paper").
class ConeSet {
 public:
  ConeSet() = default;

  /// Appends a cone; returns false (and changes nothing) when kMaxCones are already held.
  bool push_back(const ConeConstraint& cone) noexcept {
    if (count_ >= kMaxCones) {
      return false;
    }
    cones_[static_cast<std::size_t>(count_++)] = cone;
    return true;
  }
  /// Removes every cone.
  void clear() noexcept { count_ = 0; }
  /// Number of cones [PET-ERG eq. (2b)] held.
  [[nodiscard]] int size() const noexcept { return count_; }
  /// True when no cone [PET-ERG eq. (2b)] is held.
  [[nodiscard]] bool empty() const noexcept { return count_ == 0; }
  /// Cone i (0 ≤ i < size()), constraint [PET-ERG eq. (2b)].
  [[nodiscard]] const ConeConstraint& operator[](int i) const noexcept {
    return cones_[static_cast<std::size_t>(i)];
  }
  /// The held cones [PET-ERG eq. (2b)] as a span (for Γ_g and ρ_n of the PET-ERG paper, Sec. III-B).
  [[nodiscard]] std::span<const ConeConstraint> span() const noexcept {
    return {cones_.data(), static_cast<std::size_t>(count_)};
  }
  /// Iteration over the held cones [PET-ERG eq. (2b)].
  [[nodiscard]] auto begin() const noexcept { return cones_.begin(); }
  /// End of the held cones [PET-ERG eq. (2b)].
  [[nodiscard]] auto end() const noexcept { return cones_.begin() + count_; }

 private:
  std::array<ConeConstraint, kMaxCones> cones_{};
  int count_{0};
};

}  // namespace attiguard::governor
