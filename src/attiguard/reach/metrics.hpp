#pragma once
/// @file metrics.hpp
/// The metrics of ConReach [ConReach Sec. 3.1]: the P-metric on R³, the
/// left-invariant metric G_Q on SO(3) (Def. 1), the product metric G_Q × G_P (Def. 2), and
/// computable bounds on the left-invariant distance d_Q, which has no closed form:
///
///   upper (inclusion fact 1): the curve R1 exp(s ŵ), w = log(R1ᵀR2)^∨, s ∈ [0,1], joins R1 to R2
///         with constant body velocity w, so its G_Q-length is √(wᵀQw) ≥ d_Q(R1, R2);
///   lower (inclusion fact 2): every curve has G_Q-speed ≥ √λ_min(Q)·(bi-invariant speed), so
///         d_Q(R1, R2) ≥ √λ_min(Q)·d(R1, R2); hence B_Q(R0, r) ⊆ bi-invariant ball r/√λ_min(Q).
/// Proofs: docs/reach.md, "Inclusion facts".

#include <string>

#include "attiguard/lie/symmetric_eigen.hpp"
#include "attiguard/reach/interval.hpp"

namespace attiguard::reach {

/// Q (on SO(3)) and P (on R³) of the product metric G_Q × G_P (Def. 2).
struct ProductMetric {
  Mat3 Q{Mat3::Identity()};
  Mat3 P{Mat3::Identity()};
};

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// The coupled left-invariant metric M = [[Q, S], [Sᵀ, P]] on SO(3) × R³ (docs/reach.md,
/// "Coupled metrics"): ⟨(α, β), (α, β)⟩ = zᵀMz for the body-trivialised tangent z = (α, β),
/// α = (RᵀṘ)^∨, β = ω̇. S = 0 is the product metric G_Q × G_P (Def. 2).
struct StateMetric {
  Mat3 Q{Mat3::Identity()};
  Mat3 S{Mat3::Zero()};
  Mat3 P{Mat3::Identity()};
};

/// M = [[Q, S], [Sᵀ, P]].
[[nodiscard]] Mat6 metric_matrix(const StateMetric& m);
/// Q − S P⁻¹ Sᵀ: B_M((R, ω), r) projects into B_{Q−SP⁻¹Sᵀ}(R, r) (docs/reach.md, coupled fact 3).
[[nodiscard]] Mat3 attitude_schur(const StateMetric& m);
/// P − Sᵀ Q⁻¹ S: B_M((R, ω), r) projects into {ω' : ‖ω' − ω‖_{P−SᵀQ⁻¹S} ≤ r} (coupled fact 2).
[[nodiscard]] Mat3 omega_schur(const StateMetric& m);
/// Upper bound √(zᵀMz), z = (log(R1ᵀR2)^∨, ω2 − ω1), on d_M (coupled fact 1).
[[nodiscard]] double metric_distance_upper(const StateMetric& m, const Mat3& R1, const Vec3& w1,
                                           const Mat3& R2, const Vec3& w2);
/// Bound on sup √(zᵀMz) over ‖z_R‖ ≤ a, ‖z_ω‖ ≤ b: the smaller of √(λ_max(Q)a² + 2‖S‖₂ab +
/// λ_max(P)b²) and (S ≠ 0) min over θ = k/40 of √λ_max(D_θ M D_θ), D_θ = diag(a/√θ, b/√(1−θ))
/// (the radius of an M-ball around (R0, ω0) covering B_I(R0, a) × B(ω0, b), coupled fact 1).
[[nodiscard]] double metric_cover_radius(const StateMetric& m, double a, double b);

/// Smallest / largest eigenvalue of the symmetric part of M (lie/symmetric_eigen.hpp).
using lie::lambda_max;
using lie::lambda_min;
/// True when M is finite, symmetric (to 1e-12 relative) and λ_min > 0.
[[nodiscard]] bool is_spd(const Mat3& M);
/// Throws InputError "`what`: … (must be symmetric positive definite)" unless is_spd(M).
void require_spd(const Mat3& M, const std::string& what);

/// ⟨u, v⟩ of G_Q at any R for body vectors u = (RᵀK1)^∨, v = (RᵀK2)^∨ ([ConReach eq. (8)]).
[[nodiscard]] inline double q_inner(const Mat3& Q, const Vec3& u, const Vec3& v) { return u.dot(Q * v); }
/// d_P(x1, x2) = ‖x1 − x2‖_P (Sec. 3.1.1).
[[nodiscard]] double p_distance(const Mat3& P, const Vec3& x1, const Vec3& x2);
/// Upper bound √(wᵀQw), w = log(R1ᵀR2)^∨, on d_Q(R1, R2).
[[nodiscard]] double dq_upper(const Mat3& Q, const Mat3& R1, const Mat3& R2);
/// Lower bound √λ_min(Q)·‖log(R1ᵀR2)‖ on d_Q(R1, R2).
[[nodiscard]] double dq_lower(const Mat3& Q, const Mat3& R1, const Mat3& R2);
/// Bounds on the product distance √(d_Q² + d_P²) (Sec. 3.1.3).
[[nodiscard]] double product_distance_upper(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                                            const Mat3& R2, const Vec3& w2);
[[nodiscard]] double product_distance_lower(const ProductMetric& m, const Mat3& R1, const Vec3& w1,
                                            const Mat3& R2, const Vec3& w2);

/// Radius of the bi-invariant ball containing B_Q(R0, r): r/√λ_min(Q) (inclusion fact 2).
[[nodiscard]] double attitude_enclosure_radius(const Mat3& Q, double r);
/// Half-widths of the box containing the P-ball {x : ‖x − x0‖_P ≤ r}: r √((P⁻¹)_kk).
[[nodiscard]] Vec3 p_ball_half_widths(const Mat3& P, double r);

}  // namespace attiguard::reach
