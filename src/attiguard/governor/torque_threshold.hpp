#pragma once
/// @file torque_threshold.hpp
/// The input-saturation threshold Γ_d of the PET-ERG paper (Sec. III-B.1, the set C_d of [PET-ERG eq. (2a)]):
/// the largest level of V(R, ω, R_g) = ½ ωᵀJω + k_p φ(RᵀR_g) whose sublevel set keeps the PD
/// torque [PET-ERG eq. (3)] within ‖τ‖ ≤ τ_max.
///
/// Γ_d = min { V : ‖k_p sk(R_e)^∨ − k_d ω‖ ≥ τ_max } over SO(3) × R³ reduces exactly to
///   Γ_d = min_{θ ∈ [0, π/2]} f(θ),
///   f(θ) = k_p (1 − cos θ) + (λ_min(J) / (2 k_d²)) · max(0, τ_max − k_p sin θ)²
/// (derivation: docs/pet-erg.md, "Torque threshold Γ_d"). f is convex on [0, π/2], so the
/// minimum is bracketed by bisection on f′ with a certified lower bound from the tangent lines.

namespace attiguard::governor {

/// Parameters Γ_d depends on ([PET-ERG eqs. (2a), (3)] and V of Sec. III-A).
struct TorqueThresholdInputs {
  double kp{1.0};          ///< k_p of [PET-ERG eq. (3)] [N·m]
  double kd{1.0};          ///< k_d of [PET-ERG eq. (3)] [N·m·s]
  double lambda_min{1.0};  ///< smallest principal moment of J [kg·m²]
  double tau_max{1.0};     ///< τ_max of [PET-ERG eq. (2a)] [N·m]
};

/// The reduced objective f(θ) above (PET-ERG paper, Γ_d of Sec. III-B.1; docs/pet-erg.md):
/// the smallest V among the states whose attitude error has rotation angle θ and whose PD torque
/// (3) has norm ≥ τ_max. Exposed for tests and documentation.
[[nodiscard]] double torque_threshold_objective(const TorqueThresholdInputs& in,
                                                double theta) noexcept;

/// Result of the offline computation of Γ_d.
struct TorqueThreshold {
  double gamma_d{0.0};      ///< certified lower bound of the exact minimum (never above it)
  double upper_bound{0.0};  ///< f at the best point found (an attained value, ≥ the minimum)
  double theta_star{0.0};   ///< minimiser θ* of f [rad]
  int iterations{0};        ///< bisection iterations used
};

/// Γ_d of the PET-ERG paper (Sec. III-B.1, "solving the associated offline optimization problem
/// directly on SO(3)×R³"), computed once offline to the absolute accuracy `tol` (default 1e-12,
/// well inside the required 1e-9, docs/errata.md, PET-ERG 1b). The returned gamma_d is a certified lower bound of
/// the true minimum (tangent-line bound of the convex f, minus a few rounding units): it never
/// overestimates, so {V ≤ Γ_d} never allows torque saturation.
/// Throws SetupError (core/errors.hpp) when an input is not positive and finite, when a term of
/// f over/underflows (e.g. τ_max ≥ 1e155, k_d = 1e300), or when the resulting Γ_d is not resolved
/// in double precision (docs/pet-erg.md, "Torque threshold Γ_d"; set-up code only).
[[nodiscard]] TorqueThreshold compute_torque_threshold(const TorqueThresholdInputs& in,
                                                       double tol = 1e-12);

/// The loose closed-form bound Γ_d^loose = τ_max² / (2 k_p + 2 k_d² / λ_min(J)) ≤ Γ_d, from
/// ‖τ‖ ≤ k_p ‖sk(R_e)^∨‖ + k_d ‖ω‖, ‖sk(R_e)^∨‖² = sin²θ ≤ 2φ, ½λ_min‖ω‖² ≤ ½ωᵀJω and
/// Cauchy–Schwarz (docs/pet-erg.md). Kept for comparison with the exact Γ_d of the PET-ERG paper
/// (Sec. III-B.1) and its predecessor's conservatism.
[[nodiscard]] double torque_threshold_loose(const TorqueThresholdInputs& in) noexcept;

}  // namespace attiguard::governor
