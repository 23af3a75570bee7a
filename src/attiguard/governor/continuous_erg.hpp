#pragma once
/// @file continuous_erg.hpp
/// The continuous-time explicit reference governor on SO(3) [PET-ERG eq. (4)]:
///   Ṙ_g = R_g ξ̂,  ξ = κ max{Γ(R_g) − V, 0} ρ_n / max{‖ρ_n‖, ε}.
/// (The paper prints κ(Γ − V); with the DSM of Sec. III-B.1 the factor is κ max{Γ − V, 0}, which
/// is the same along solutions by Theorem 1 (i) and keeps Ṙ_g = 0 whenever V ≥ Γ.)

#include <algorithm>

#include "attiguard/governor/pointing_threshold.hpp"

namespace attiguard::governor {

/// Body rate ξ of the auxiliary reference, Ṙ_g = R_g ξ̂, of the continuous ERG (PET-ERG paper,
/// [PET-ERG eq. (4)]): ξ = κ max{Γ − V, 0} ρ / max{‖ρ‖, ε}. Allocation-free.
[[nodiscard]] inline Vec3 erg_reference_rate(double kappa, double gamma, double V, const Vec3& rho,
                                             double epsilon) noexcept {
  const double margin = dynamic_safety_margin(kappa, gamma, V);
  if (margin <= 0.0) {
    return Vec3::Zero();
  }
  return (margin / std::max(rho.norm(), epsilon)) * rho;
}

}  // namespace attiguard::governor
