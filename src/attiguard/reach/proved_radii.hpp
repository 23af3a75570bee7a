#pragma once
/// @file proved_radii.hpp
/// The radii ConReach derives from a metric ball B_M(x, r), M = [[Q, S], [Sᵀ, P]] (metrics.hpp),
/// as bounds proved for the floating-point numbers computed with (docs/reach.md, "Rounding
/// sites"). Each starts from the double-precision value, widens it slightly and proves the
/// matrix inequality behind it with lmi_proof.hpp's interval congruence (prove_less); the
/// scalar arithmetic after the proof is rounded outward (scalar_interval.hpp).
///
///  - projection radii (coupled facts 2, 3): λ_lo ≤ λ_min(Q − SP⁻¹Sᵀ) from M − λ_lo·diag(I, 0) ≻ 0
///    (the Schur complement of a positive definite matrix), and likewise for P − SᵀQ⁻¹S; the
///    radius r/√λ_lo;
///  - ω half-widths: h_k ≥ r √((M⁻¹)_{3+k,3+k}) from M − (r/h_k)² e e ᵀ ≻ 0, e = e_{3+k};
///  - cover radius (coupled fact 1): every z with ‖z_R‖ ≤ a, ‖z_ω‖ ≤ b has zᵀMz ≤ λ when
///    M ⪯ λ·diag(w_R I, w_ω I) with w_R a² + w_ω b² ≤ 1;
///  - the ball's growth r e^{cΔt} + allowance.

#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

/// Which block of the state a projection is onto.
enum class StateBlock { attitude, omega };

/// up(r/√x) for x > 0 (√ is correctly rounded, so √x ≥ down(fl(√x))): the radius r/√λ of a
/// metric ball's projection when λ bounds the metric from below.
[[nodiscard]] double radius_over_sqrt_up(double r, double x);

/// A proved λ_lo ≤ λ_min of the block's Schur complement (attitude: Q − SP⁻¹Sᵀ, omega:
/// P − SᵀQ⁻¹S); 0 when no positive bound can be proved.
[[nodiscard]] double proved_schur_lower(const StateMetric& m, StateBlock block);

/// r/√λ_lo rounded up: the radius of the bi-invariant attitude ball (attitude) or the Euclidean
/// ω ball (omega) that contains B_M(x, r)'s projection; +∞ when λ_lo = 0.
[[nodiscard]] double proved_projection_radius(const StateMetric& m, double r, StateBlock block);

/// Proved half-widths h_k ≥ r √((P − SᵀQ⁻¹S)⁻¹_kk) of the box containing the ω projection.
[[nodiscard]] Vec3 proved_omega_half_widths(const StateMetric& m, double r);

/// A proved upper bound on sup √(zᵀMz) over ‖z_R‖ ≤ a, ‖z_ω‖ ≤ b (metric_cover_radius's value
/// or slightly above).
[[nodiscard]] double proved_cover_radius(const StateMetric& m, double a, double b);

/// r e^{cΔt} + allowance rounded up (exp assumed within 1 ulp, widened by 2).
[[nodiscard]] double proved_ball_growth(double r, double c, double dt, double allowance);

}  // namespace attiguard::reach
