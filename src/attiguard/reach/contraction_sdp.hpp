#pragma once
/// @file contraction_sdp.hpp
/// The contraction LMI (10) of Theorem 4 and the per-step SDP (20) of ConReach:
///
///   M(Q, P; A, B, ω, c) = [ ω̂Q − Qω̂ − 2cQ    Q + AᵀP         ]
///                         [ Q + PA            BᵀP + PB − 2cP ]  ⪯ 0   on U_i,
///
/// imposed at the vertices of an LmiEnclosure; when the enclosure carries a norm bound
/// ‖[ΔA ΔB]‖₂ ≤ ρ, robustly through the sufficient condition (one multiplier μ_v > 0 per vertex)
///
///   [ M_v + μ_v ρ² I₆   U ]
///   [ Uᵀ             −μ_v I₃ ] ⪯ 0,   U = [0; P],
///
/// which follows from Sym(UΔ) ⪯ μ⁻¹UUᵀ + μΔᵀΔ and a Schur complement (docs/reach.md).
/// Constraints of (20): Q_floor I ⪯ Q ⪯ Q_i, ε I ⪯ P ⪯ P_i. Every returned (Q, P, c) is
/// certified a posteriori in double precision: Q ⪯ Q_i and P ⪯ P_i are enforced by scaling
/// (Q, P) down (the LMI is homogeneous in (Q, P, μ)), and any residual positive eigenvalue e of
/// the LMI is absorbed by raising c by e/(2 λ_min(diag(Q, P))) (M decreases by 2Δc·diag(Q, P)).
/// Then Q, P ≻ 0, Q ≺ Q_i, P ≺ P_i and the LMI at every vertex are proved in outward-rounded
/// interval arithmetic (lmi_proof.hpp); a solution that cannot be proved is not returned as ok.

#include <string>
#include <vector>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/sdp_solver.hpp"

namespace attiguard::reach {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// M(Q, P; A, B, ω, c) of (10).
[[nodiscard]] Mat6 contraction_lmi(const Mat3& Q, const Mat3& P, const Mat3& A, const Mat3& B,
                                   const Vec3& omega, double c);

/// Largest eigenvalue of the (robust, Schur-complemented) LMI over the enclosure:
/// max_v λ_max(M_v + μ_v ρ² I + UUᵀ/μ_v) (μ ignored when ρ = 0). +inf when some μ_v ≤ 0.
[[nodiscard]] double lmi_worst_eigenvalue(const LmiEnclosure& enc, const Mat3& Q, const Mat3& P,
                                          double c, const std::vector<double>& mu);

/// Smallest c for which Q = P = I satisfies the (robust) LMI: max_v ½λ_max(M_v(I, I, 0)) + ρ.
/// Algorithm 1 starts its line search here (0.2071 = (√2 − 1)/2 for the paper's example).
[[nodiscard]] double identity_metric_rate(const LmiEnclosure& enc);

/// Objective of the per-step SDP.
enum class MetricObjective {
  max_trace_q,       ///< the paper's (20): minimise −tr(Q)
  max_min_eigenvalue ///< maximise t with tI ⪯ Q, tI ⪯ P (bi-invariant enclosure of the ball)
};

struct MetricSdpSettings {
  double q_floor{1e-6};     ///< Q ⪰ q_floor I (the attitude enclosure of geodesics needs it)
  double p_floor{1e-6};     ///< P ⪰ p_floor I
  double strictness{1e-7};  ///< LMI imposed as ⪯ −strictness·I in the SDP
  SdpSettings sdp;
};

/// Outcome of one SDP at a fixed rate.
struct MetricSolution {
  bool ok{false};
  double c_requested{0.0};
  double c{0.0};            ///< certified rate (≥ c_requested; larger only after a repair)
  Mat3 Q{Mat3::Identity()};
  Mat3 P{Mat3::Identity()};
  double worst_eigenvalue{0.0};  ///< of the LMI at (Q, P, c) after certification (≤ 0)
  bool scaled{false};       ///< (Q, P) were scaled down to keep Q ⪯ Q_i, P ⪯ P_i exactly
  SdpStatus status{SdpStatus::failed};
  std::string message;
};

/// Solves (20) at rate c over the enclosure with Q ⪯ Q_prev, P ⪯ P_prev, then certifies.
[[nodiscard]] MetricSolution solve_metric(const LmiEnclosure& enc, const Mat3& Q_prev,
                                          const Mat3& P_prev, double c, MetricObjective objective,
                                          const MetricSdpSettings& settings);

/// The always-feasible fallback: Q = P = s I with s = min(λ_min(Q_prev), λ_min(P_prev)) at
/// c = identity_metric_rate(enc) (plus a certification margin).
[[nodiscard]] MetricSolution fallback_metric(const LmiEnclosure& enc, const Mat3& Q_prev,
                                             const Mat3& P_prev);

}  // namespace attiguard::reach
