#pragma once
/// @file lmi_proof.hpp
/// A proof, valid for the floating-point numbers computed with, that a certified solution of
/// the contraction SDP satisfies the LMI [ConReach eq. (10)] [ConReach Thm. 4] at every
/// vertex of an LmiEnclosure, and that the metric stays positive definite and monotone
/// (Q ≻ 0, P ≻ 0, Q ⪯ Q_prev, P ⪯ P_prev; paper Lemma 5). docs/reach.md, "Rigorous LMI check":
///  1. every matrix is evaluated in outward-rounded interval arithmetic (scalar_interval.hpp);
///  2. an interval symmetric matrix S is proved negative definite by a congruence with the
///     floating-point eigenvectors V of its midpoint: D = VᵀSV (in intervals) has every row
///     satisfying D_ii + Σ_{j≠i}|D_ij| < 0 (Gershgorin), and VᵀV is strictly diagonally dominant
///     with a positive diagonal (so V is nonsingular); by Sylvester's law of inertia every
///     symmetric matrix in S is then negative definite.

#include <vector>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

/// Outcome of a proof: `proved`, and the largest Gershgorin row bound found (< 0 when proved).
struct NegativeDefiniteProof {
  bool proved{false};
  double margin{0.0};
};

/// Proves λ_max(MF_v + F_vᵀM − 2cM + μ_v ρ² I + UUᵀ/μ_v) < 0 at every vertex, U = M[0; I] (the
/// robust form of contraction_sdp.hpp for the coupled metric M = [[Q, S], [Sᵀ, P]]; μ ignored
/// when ρ = 0), with M, c and μ taken as the exact values of their floating-point numbers and
/// F over the vertex's interval data [A_v ± A_rad], [B_v ± B_rad] (closed_loop.hpp; docs/reach.md,
/// "Rounding sites"). `margin` is the worst vertex's.
[[nodiscard]] NegativeDefiniteProof prove_contraction_lmi(const LmiEnclosure& enc,
                                                          const StateMetric& metric, double c,
                                                          const std::vector<double>& mu);
/// The product-metric case S = 0 (LMI [ConReach eq. (10)]).
[[nodiscard]] NegativeDefiniteProof prove_contraction_lmi(const LmiEnclosure& enc, const Mat3& Q,
                                                          const Mat3& P, double c,
                                                          const std::vector<double>& mu);

/// Proves A − B ≺ 0 for symmetric 3×3 A, B (B = 0: A ≺ 0).
[[nodiscard]] NegativeDefiniteProof prove_less(const Mat3& A, const Mat3& B);
/// Proves A − B ≺ 0 for symmetric 6×6 A, B (the coupled metric: M ≻ 0, M ≺ M_prev).
[[nodiscard]] NegativeDefiniteProof prove_less(const Mat6& A, const Mat6& B);

}  // namespace attiguard::reach
