#pragma once
/// @file navigation_field.hpp
/// The navigation field ρ_n(R_d, R_g) = −grad P(R_g, R_d), P = P_a + Σ P_r (PET-ERG paper,
/// Sec. III-B.2), as body vectors of T_{R_g}SO(3): a function f has gradient g at R_g when
/// f(R_g exp(εη̂)) = f(R_g) + ε gᵀη + O(ε²) (docs/errata.md, PET-ERG 1c).
///
/// Repulsive potential (our choice, the paper does not state it; docs/pet-erg.md):
///   P_r(c) = k_r (ζ − c)² / (c − δ) for δ < c < ζ, 0 for c ≥ ζ, c = a_cᵀR_g a_b.
/// It is C¹ (dP_r/dc = 0 at c = ζ), diverges as c → δ⁺, and its gradient is
///   grad P_r = (dP_r/dc) g_c,  dP_r/dc = −k_r (ζ − c)(ζ + c − 2δ)/(c − δ)².
/// All functions are allocation-free and noexcept; for c ≤ δ (outside the field's domain, which
/// the governor never reaches) they return large finite values instead of ±∞.

#include <algorithm>
#include <span>

#include "attiguard/governor/cone_constraint.hpp"

namespace attiguard::governor {

/// Smallest distance c − δ used in the repulsive formulas (keeps them finite).
inline constexpr double kRepulsiveFloor = 1e-12;

/// Attractive potential P_a = ½ tr(I − R_dᵀR_g) = φ(R_dᵀR_g) (PET-ERG paper, Sec. III-B.2;
/// docs/errata.md, PET-ERG 1c).
[[nodiscard]] inline double attractive_potential(const Mat3& R_g, const Mat3& R_d) noexcept {
  return lie::phi(R_d.transpose() * R_g);
}

/// Attractive field ρ_a = −grad P_a = sk(R_gᵀR_d)^∨ (PET-ERG paper, Sec. III-B.2;
/// docs/errata.md, PET-ERG 1c).
[[nodiscard]] inline Vec3 attractive_field(const Mat3& R_g, const Mat3& R_d) noexcept {
  return lie::vee(lie::sk(R_g.transpose() * R_d));
}

/// The attractive field the governor follows (docs/pet-erg.md, section 4, "Half-turns"): ρ_a of
/// attractive_field, except beyond a quarter turn (θ = d(R_g, R_d) > π/2) where ‖ρ_a‖ = sin θ is
/// below `floor`: there max(sin θ, floor) n̂ with n̂ the axis of log(R_gᵀR_d). At θ = π every
/// direction is a critical point of P_a (its maximum) and ρ_a = 0 would hold R_g there for ever;
/// log's axis (well defined up to its sign, which log fixes) is a descent direction, and the field is
/// continuous where sin θ = floor. Only the direction of ξ changes: its magnitude is the DSM's
/// [PET-ERG eqs. (4)-(6)], on which safety rests. floor ≤ 0 gives attractive_field.
[[nodiscard]] inline Vec3 governed_attractive_field(const Mat3& R_g, const Mat3& R_d, double floor) noexcept {
  const Mat3 E = R_g.transpose() * R_d;
  const Vec3 rho = lie::vee(lie::sk(E));
  if (!(floor > 0.0) || E.trace() >= 1.0 || rho.norm() >= floor) return rho;  // tr E = 1 + 2 cos θ
  const Vec3 w = lie::log(E);
  const double theta = w.norm();
  if (!(theta > 0.0)) return rho;
  return (floor / theta) * w;
}

/// Gradient of c(R_g) = a_cᵀR_g a_b: g_c = a_b × (R_gᵀa_c), ‖g_c‖ = sin β_g (constraint [PET-ERG eq. (2b)] of
/// the PET-ERG paper; docs/errata.md, PET-ERG 1d).
[[nodiscard]] inline Vec3 constraint_gradient(const ConeConstraint& cone, const Mat3& R_g) noexcept {
  return cone.axis_b.cross(R_g.transpose() * cone.direction_i);
}

/// P_r(c) = k_r (ζ − c)²/(c − δ) on δ < c < ζ, 0 for c ≥ ζ (repulsive term of P, PET-ERG paper
/// Sec. III-B.2; the form is ours, docs/pet-erg.md).
[[nodiscard]] inline double repulsive_potential_of_cosine(const ConeConstraint& cone,
                                                          double c) noexcept {
  if (c >= cone.zeta) {
    return 0.0;
  }
  const double gap = std::max(c - cone.delta, kRepulsiveFloor);
  const double d = cone.zeta - c;
  return cone.repulsive_gain * d * d / gap;
}

/// dP_r/dc = −k_r (ζ − c)(ζ + c − 2δ)/(c − δ)² (≤ 0; zero for c ≥ ζ) (PET-ERG paper
/// Sec. III-B.2; docs/pet-erg.md).
[[nodiscard]] inline double repulsive_potential_slope(const ConeConstraint& cone, double c) noexcept {
  if (c >= cone.zeta) {
    return 0.0;
  }
  const double gap = std::max(c - cone.delta, kRepulsiveFloor);
  return -cone.repulsive_gain * (cone.zeta - c) * (cone.zeta + c - 2.0 * cone.delta) / (gap * gap);
}

/// P_r(R_g) of one cone [PET-ERG Sec. III-B.2].
[[nodiscard]] inline double repulsive_potential(const ConeConstraint& cone, const Mat3& R_g) noexcept {
  return repulsive_potential_of_cosine(cone, cone_cosine(cone, R_g));
}

/// Repulsive field of one cone from its cosine c = a_cᵀR_g a_b already computed (cone_cosine):
/// ρ_r = −(dP_r/dc) g_c [PET-ERG Sec. III-B.2] (docs/performance.md, "Shared cone cosines").
[[nodiscard]] inline Vec3 repulsive_field_of_cosine(const ConeConstraint& cone, double c,
                                                    const Mat3& R_g) noexcept {
  if (c >= cone.zeta) {
    return Vec3::Zero();
  }
  return -repulsive_potential_slope(cone, c) * constraint_gradient(cone, R_g);
}

/// Repulsive field of one cone ρ_r = −grad P_r = −(dP_r/dc) g_c [PET-ERG Sec. III-B.2].
[[nodiscard]] inline Vec3 repulsive_field(const ConeConstraint& cone, const Mat3& R_g) noexcept {
  return repulsive_field_of_cosine(cone, cone_cosine(cone, R_g), R_g);
}

/// Total potential P = P_a + Σ_i P_r,i (PET-ERG paper Sec. III-B.2; sum over cones: docs/pet-erg.md, "Beyond the paper").
[[nodiscard]] inline double navigation_potential(std::span<const ConeConstraint> cones,
                                                 const Mat3& R_g, const Mat3& R_d) noexcept {
  double p = attractive_potential(R_g, R_d);
  for (const ConeConstraint& cone : cones) {
    p += repulsive_potential(cone, R_g);
  }
  return p;
}

/// Navigation field ρ_n(R_d, R_g) = −grad P = ρ_a + Σ_i ρ_r,i [PET-ERG Sec. III-B.2]; with
/// `attraction_floor` > 0 the attractive part is governed_attractive_field's (docs/pet-erg.md,
/// section 4, "Half-turns").
[[nodiscard]] inline Vec3 navigation_field(std::span<const ConeConstraint> cones, const Mat3& R_g,
                                           const Mat3& R_d, double attraction_floor = 0.0) noexcept {
  Vec3 rho = governed_attractive_field(R_g, R_d, attraction_floor);
  for (const ConeConstraint& cone : cones) {
    rho += repulsive_field(cone, R_g);
  }
  return rho;
}

/// navigation_field with each cone's cosine a_cᵀR_g a_b already computed (`cosines`, one per
/// cone, e.g. by the pointing_threshold overload that writes them): bit for bit the same field
/// [PET-ERG Sec. III-B.2] (docs/performance.md, "Shared cone cosines").
[[nodiscard]] inline Vec3 navigation_field(std::span<const ConeConstraint> cones, const Mat3& R_g,
                                           const Mat3& R_d, double attraction_floor,
                                           std::span<const double> cosines) noexcept {
  Vec3 rho = governed_attractive_field(R_g, R_d, attraction_floor);
  for (std::size_t i = 0; i < cones.size(); ++i) {
    rho += repulsive_field_of_cosine(cones[i], cosines[i], R_g);
  }
  return rho;
}

}  // namespace attiguard::governor
