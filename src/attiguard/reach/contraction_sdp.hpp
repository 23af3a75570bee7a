#pragma once
/// @file contraction_sdp.hpp
/// The contraction LMI [ConReach eq. (10)] of Theorem 4, its coupled-metric generalisation, and the per-step
/// SDP [ConReach eq. (20)]. For the metric M = [[Q, S], [Sᵀ, P]] (metrics.hpp) and the linearised
/// closed loop F = [[−ω̂, I], [A, B]] of z = (δθ_b, δω) (docs/reach.md, "Coupled metrics"):
///
///   L(M; A, B, ω, c) = MF + FᵀM − 2cM ⪯ 0   on U_i;
///
/// with S = 0 this is (10): [[ω̂Q − Qω̂ − 2cQ, Q + AᵀP], [Q + PA, BᵀP + PB − 2cP]]. It is imposed
/// at the vertices of an LmiEnclosure; when the enclosure carries a norm bound
/// ‖[ΔA ΔB]‖₂ ≤ ρ, robustly through the sufficient condition (one multiplier μ_v > 0 per vertex)
///
///   [ L_v + μ_v ρ² I₆   U ]
///   [ Uᵀ             −μ_v I₃ ] ⪯ 0,   U = M[0; I] = [S; P],
///
/// which follows from Sym(UΔ) ⪯ μ⁻¹UUᵀ + μΔᵀΔ and a Schur complement (docs/reach.md).
/// Constraints of [ConReach eq. (20)]: Q_floor I ⪯ Q ⪯ Q_i, ε I ⪯ P ⪯ P_i (product), or
/// diag(Q_floor I, ε I) ⪯ M ⪯ M_i (coupled). Every returned (Q, P, c) is
/// certified a posteriori in double precision: Q ⪯ Q_i and P ⪯ P_i are enforced by scaling
/// (Q, P) down (the LMI is homogeneous in (Q, P, μ)), and any residual positive eigenvalue e of
/// the LMI is absorbed by raising c by e/(2 λ_min(diag(Q, P))) (M decreases by 2Δc·diag(Q, P)).
/// Then Q, P ≻ 0, Q ≺ Q_i, P ≺ P_i and the LMI at every vertex are proved in outward-rounded
/// interval arithmetic (lmi_proof.hpp); a solution that cannot be proved is not returned as ok.

#include <string>
#include <vector>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/sdp_solver.hpp"

namespace attiguard::reach {

/// L(M; A, B, ω, c) = MF + FᵀM − 2cM, F = [[−ω̂, I], [A, B]] (docs/reach.md, "Coupled metrics").
[[nodiscard]] Mat6 contraction_lmi(const Mat6& M, const Mat3& A, const Mat3& B, const Vec3& omega,
                                   double c);
/// M(Q, P; A, B, ω, c) of [ConReach eq. (10)] (the product metric, S = 0).
[[nodiscard]] Mat6 contraction_lmi(const Mat3& Q, const Mat3& P, const Mat3& A, const Mat3& B,
                                   const Vec3& omega, double c);

/// Largest eigenvalue of the (robust, Schur-complemented) LMI over the enclosure:
/// max_v λ_max(M_v + μ_v ρ² I + UUᵀ/μ_v) (μ ignored when ρ = 0). +inf when some μ_v ≤ 0.
[[nodiscard]] double lmi_worst_eigenvalue(const LmiEnclosure& enc, const StateMetric& m, double c,
                                          const std::vector<double>& mu);
/// The same for the product metric (S = 0).
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
  bool coupled{false};      ///< optimise S too (M = [[Q, S], [Sᵀ, P]]); false: S = 0
  /// true: a solution is accepted only with the interval proof (lmi_proof.hpp); false ("float"):
  /// the double-precision eigenvalue certification alone (docs/reach.md, "Rigour").
  bool rigorous{true};
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
  Mat3 S{Mat3::Zero()};     ///< the coupling block (0 for the product metric)
  std::vector<double> mu;   ///< robust multipliers μ_v (empty when ρ = 0)
  double worst_eigenvalue{0.0};  ///< of the LMI at (Q, P, c) after certification (≤ 0)
  bool scaled{false};       ///< (Q, P) were scaled down to keep Q ⪯ Q_i, P ⪯ P_i exactly
  bool proved{false};       ///< proved in outward-rounded interval arithmetic (lmi_proof.hpp)
  SdpStatus status{SdpStatus::failed};
  std::string message;
};

/// Solves (20) at rate c over the enclosure with M ⪯ M_prev (S free when settings.coupled,
/// else S = 0 and prev.S must be 0), then certifies. Objectives for the coupled metric:
/// max_trace_q maximises tr(Q); max_min_eigenvalue maximises t with tI ⪯ Q − SP⁻¹Sᵀ and
/// tI ⪯ P − SᵀQ⁻¹S (the Schur complements that bound the ball's projections, metrics.hpp).
[[nodiscard]] MetricSolution solve_metric(const LmiEnclosure& enc, const StateMetric& prev, double c,
                                          MetricObjective objective,
                                          const MetricSdpSettings& settings);
/// The product-metric form with Q ⪯ Q_prev, P ⪯ P_prev.
[[nodiscard]] MetricSolution solve_metric(const LmiEnclosure& enc, const Mat3& Q_prev,
                                          const Mat3& P_prev, double c, MetricObjective objective,
                                          const MetricSdpSettings& settings);

/// The SDP [ConReach eq. (20)] that solve_metric hands to solve_sdp, uncertified (for benchmarks
/// and tests of the SDP solvers alone; docs/reach.md, "Dense SDP solver").
[[nodiscard]] LmiProblem metric_problem(const LmiEnclosure& enc, const StateMetric& prev, double c,
                                        MetricObjective objective,
                                        const MetricSdpSettings& settings);

/// The always-feasible fallback: Q = P = s I, S = 0, with s = λ_min(M_prev) at
/// c = identity_metric_rate(enc) (plus a certification margin); proved in interval arithmetic
/// when `rigorous` (the product-metric overload always proves).
[[nodiscard]] MetricSolution fallback_metric(const LmiEnclosure& enc, const StateMetric& prev,
                                             bool rigorous);
[[nodiscard]] MetricSolution fallback_metric(const LmiEnclosure& enc, const Mat3& Q_prev,
                                             const Mat3& P_prev);

}  // namespace attiguard::reach
