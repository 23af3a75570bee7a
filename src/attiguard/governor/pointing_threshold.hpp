#pragma once
/// @file pointing_threshold.hpp
/// The pointing threshold Γ_g(R_g) of the PET-ERG paper (Sec. III-B.1, the set C_g of [PET-ERG eq. (2b)]) and
/// the aggregate threshold Γ(R_g) = min{Γ_d, Γ_g(R_g), k_p(2 − ε_Γ)}.
///
/// Geometry (docs/pet-erg.md, "Pointing threshold Γ_g"): on {V ≤ Γ} the rotation angle θ of
/// R_e = RᵀR_g satisfies k_p(1 − cos θ) ≤ Γ, and R a_b lies in the spherical cap of radius θ
/// around R_g a_b. With β_g = arccos(a_cᵀR_g a_b) the constraint holds on the whole cap iff
/// β_g + θ ≤ θ_c, hence Γ_g = k_p(1 − cos(θ_c − β_g)) for β_g < θ_c and 0 otherwise. All
/// functions are allocation-free and noexcept.

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "attiguard/governor/cone_constraint.hpp"

namespace attiguard::governor {

/// pointing_threshold of one cone from its cosine c = a_cᵀR_g a_b already computed (cone_cosine),
/// the same operations (PET-ERG paper, Sec. III-B.1; docs/performance.md, "Shared cone cosines").
[[nodiscard]] inline double pointing_threshold_of_cosine(const ConeConstraint& cone, double cosine,
                                                         double kp) noexcept {
  const double c = std::clamp(cosine, -1.0, 1.0);
  if (!(c > cone.cos_theta_c)) {
    return 0.0;
  }
  const double sin_beta = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double cos_gap = cone.cos_theta_c * c + cone.sin_theta_c * sin_beta;
  return kp * std::max(0.0, 1.0 - cos_gap);
}

/// Γ_g of one cone: k_p(1 − cos(θ_c − β_g)) with β_g = arccos(a_cᵀR_g a_b) when β_g < θ_c, else 0
/// (PET-ERG paper, Sec. III-B.1, "Γ_g(R_g) handles C_g"; docs/errata.md, PET-ERG 1a).
/// cos(θ_c − β_g) = cos θ_c · c + sin θ_c · sin β_g with c = cos β_g: no inverse trigonometry.
[[nodiscard]] inline double pointing_threshold(const ConeConstraint& cone, const Mat3& R_g,
                                               double kp) noexcept {
  return pointing_threshold_of_cosine(cone, cone_cosine(cone, R_g), kp);
}

/// Γ_g for several cones: the minimum over them (beyond the paper, docs/pet-erg.md: "any number of cone constraints";
/// PET-ERG paper Sec. III-B.1 for one). +∞ when there is no cone.
[[nodiscard]] inline double pointing_threshold(std::span<const ConeConstraint> cones,
                                               const Mat3& R_g, double kp) noexcept {
  double g = std::numeric_limits<double>::infinity();
  for (const ConeConstraint& cone : cones) {
    g = std::min(g, pointing_threshold(cone, R_g, kp));
  }
  return g;
}

/// Γ_g for several cones as pointing_threshold(cones, R_g, kp), bit for bit, also writing each
/// cone's cosine a_cᵀR_g a_b into `cosines` (at least cones.size() entries) for the repulsive
/// terms of ρ_n at the same R_g (PET-ERG paper Sec. III-B; docs/performance.md, "Shared cone
/// cosines").
[[nodiscard]] inline double pointing_threshold(std::span<const ConeConstraint> cones, const Mat3& R_g,
                                               double kp, std::span<double> cosines) noexcept {
  double g = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cones.size(); ++i) {
    cosines[i] = cone_cosine(cones[i], R_g);
    g = std::min(g, pointing_threshold_of_cosine(cones[i], cosines[i], kp));
  }
  return g;
}

/// Aggregate threshold Γ = min{Γ_d, Γ_g, k_p(2 − ε_Γ)} [PET-ERG Sec. III-B.1].
[[nodiscard]] inline double aggregate_threshold(double gamma_d, double gamma_g, double kp,
                                                double epsilon_gamma) noexcept {
  return std::min({gamma_d, gamma_g, kp * (2.0 - epsilon_gamma)});
}

/// Dynamic safety margin Δ = κ max{Γ − V, 0} [PET-ERG Sec. III-B.1].
[[nodiscard]] inline double dynamic_safety_margin(double kappa, double gamma, double V) noexcept {
  return kappa * std::max(gamma - V, 0.0);
}

}  // namespace attiguard::governor
